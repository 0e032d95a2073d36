//! The normalised wavy Maugis model at one contact size (docs/model.md), for a
//! cylinder carrying any number of cosine waves ([`crate::contact::profile`]).
//!
//! The files: [`params`] (the parameters and their ranges), [`strip`] (the strip end
//! `m` and the strip functions), `waves` (the waves' terms, summed over the profile),
//! [`state`] ([`ContactSize`]: residual, load, approach, traction, displacement, gap),
//! [`solve`] (the first root), [`validity`], and [`solved`] (a contact size solved whole
//! in one call, [`SolvedState`]: what the load-area response reads). Data flows one way:
//! the parameters and the strip functions feed the waves' terms, the state, then the
//! root and the checks, then the solved state; the callers only assemble it.
//!
//! # Normalisation (two length scales, docs/model.md)
//!
//! Horizontal lengths by `l_h = (dgamma R^2/E*)^(1/3)`: `a = abar l_h`,
//! `c = m abar l_h`, `x = xbar l_h`, `zeta = beta l_h`. Vertical lengths by
//! `l_v = l_h^2/R`: `A = alpha l_v`, `u`, `g`, `delta = l_v/lambda`. Load by
//! `(E* dgamma^2 R)^(1/3)`, traction by `sigma`. In these units
//! `hbar(x) = x^2/2 + sum_j 2 alpha_j sin^2(pi x/beta_j)`, `ubar_H = u_H(a = abar, R = 1)`,
//! `ubar_w = sum_j u_w(a = abar, zeta = beta_j, A = alpha_j)` and
//! `ubar_a = u_a(a = abar, c = m abar, sigma = lambda, E* = 1)` (the functions of
//! [`super::displacement`] with these arguments).
//!
//! # The adhesive-strip equation (Eq. 15b, corrected, docs/model.md)
//!
//! `lambda gbar(c) = 1`, i.e. `F(m) = 0` with
//!
//! ```text
//! F(m) = (4/pi) lambda^2 abar (sqrt(m^2-1) acosh(m) - m ln m)
//!      + (1/2) lambda abar^2 (m sqrt(m^2-1) - acosh(m))          <- abar squared
//!      + lambda sum_j [2 alpha_j sin^2(pi m abar/beta_j) - ubar_w,j(m abar)]   <- this sign
//!      - 1.
//! ```
//!
//! `F(1) = -1` because every gap term vanishes at the contact edge. The strip
//! ends where the gap *first* reaches `delta` (docs/model.md, "Root m"), so `m` is the
//! smallest root: [`ContactSize::solve_strip`] scans outward from `c = a` (steps of
//! at most `beta_min/16` (the finest wavelength) so no wave period is skipped, shrinking towards the edge when
//! the root is closer than one step) for the first sign change and refines it with
//! Brent's method to `1e-13` relative **in `m - 1`** ([`StripEnd`]): as
//! `lambda -> inf`, `m - 1 ~ pi/(4 lambda^2 abar)`, and `m` itself would carry
//! only `1e-16/(m-1)` relative accuracy of it. The strip functions
//! ([`hertz_gap_fn`], [`adhesive_gap_fn`], [`adhesive_approach_fn`]) take `m - 1`
//! and switch to their Taylor series below `1e-3`, so the JKR limit is reached
//! with full relative accuracy. A root where `F` touches zero without changing sign is not
//! detected (it is not a crossing). No root below `c - a = `[`MAX_STRIP`] is an
//! [`crate::Error::NoStripEnd`].
//!
//! # Load (Eq. 14) and traction (Eq. 16)
//!
//! `Lbar = pi abar^2/4 - 2 lambda abar sqrt(m^2-1) + sum_j (pi^2 alpha_j abar/beta_j) J1(2 pi abar/beta_j)`.
//! Inside the contact
//! `pbar = (2/pi) atan(abar sqrt((m^2-1)/(abar^2-x^2))) - (sqrt(abar^2-x^2)/(2 lambda)) (1 + sum_j (2 pi alpha_j/(beta_j abar)) K_j(x/abar))`
//! with `K_j(c) = int_0^D_j J0(t) cos((t-D_j) c) dt`, `D_j = 2 pi abar/beta_j` (the printed
//! Eq. 16 has `2 pi abar` as the upper limit; Eq. 7 and the normalisation give `D`);
//! `pbar = 1` in the strip and 0 outside.
//!
//! # Validity (docs/model.md)
//!
//! A state is physical only if the gap is non-negative in the strip
//! `abar < x < m abar` (no interpenetration at crests) and `pbar <= 1` inside the
//! contact (no cavitation). [`ContactSize::validity`] samples both and refines
//! the extrema with golden-section search. The strip gap is computed in the
//! relative coordinate `t = (x - a)/(c - a)` by [`ContactSize::strip_gap`], whose
//! differences do not cancel as the strip closes, and is compared with a
//! tolerance relative to its own scale `delta = 1/lambda`
//! ([`ContactSize::gap_tolerance`]), so the test means the same from
//! `lambda = 1e-2` to `1e6`.
//!
//! # Approach (datum at infinity)
//!
//! [`ContactSize::approach_at`]: `Delta = lim (ubar(x) - (2 Lbar/pi) ln x)`, in
//! closed form from the large-`x` expansions of the three displacements.

pub mod params;
pub mod solve;
pub mod solved;
pub mod state;
pub mod strip;
pub mod validity;
mod waves;
pub(crate) use waves::check_bessel_lengths;

pub use params::{Params, ABAR_MAX, ABAR_RANGE, ALPHA_MAX, ALPHA_RANGE, BETA_RANGE, LAMBDA_RANGE};
pub use solve::{MAX_STRIP, M_REL_TOL};
pub use solved::{solve_load, solve_load_and_approach, solve_state, solve_validity, SolvedState};
pub use state::ContactSize;
pub use strip::{adhesive_approach_fn, adhesive_gap_fn, hertz_gap_fn, StripEnd};
pub use validity::{Validity, GAP_REL_TOL, RESCAN_MARGIN, SAMPLES_PER_WAVELENGTH, TRACTION_TOL};
/// Brent's method lives in [`crate::roots`]; re-exported here, its former path.
pub use crate::roots::brent;

#[cfg(test)]
mod tests;
