//! The JKR limit of the line contact for any profile of waves, from the profile
//! itself: the energy-release-rate balance, derived without the Maugis model and
//! without its Bessel closed forms (issue 39, item 5; docs/multiscale.md, "The JKR
//! limit").
//!
//! # Derivation (normalised units of Eq. 13a, `R = E* = 1` scales)
//!
//! A rigid symmetric profile `h(x)` pressed into an elastic half-plane with a
//! contact `|x| < a`: the traction is the bounded (adhesionless) solution for
//! `(a, h)` plus a flat punch of half-width `a`.
//!
//! * **Adhesionless load.** The bounded solution exists for one load,
//!   `L_1(a) = int_0^a x h'(x)/sqrt(a^2 - x^2) dx` (Muskhelishvili's condition for a
//!   bounded edge; Johnson 1985, Eq. 2.46 in our units). For `h = x^2/2`:
//!   `pi a^2/4` (Hertz). For `alpha (1 - cos(2 pi x/beta))` it is
//!   `(pi^2 alpha a/beta) J1(2 pi a/beta)` (DLMF 10.9.1), the wave term of Eq. 14.
//! * **Adhesionless approach.** `Delta_1(a) = (2 L_1/pi) ln(2/a) + I(a)`,
//!   `I(a) = (2/pi) int_0^a h'(x) arccos(x/a) dx`, with the project's datum
//!   (`Delta = lim (u(x) - (2 L/pi) ln x)`, docs/model.md). For `x^2/2`, `I = a^2/4`;
//!   for one wave, by parts and DLMF 10.9.1, `I = alpha (1 - J0(2 pi a/beta))`.
//! * **The punch.** A flat punch of half-width `a` carrying `P` adds
//!   `(2 P/pi) ln(2/a)` to the approach and the edge singularity
//!   `p ~ -P/(pi sqrt(2 a (a - |x|)))`, stress-intensity factor
//!   `K = P/sqrt(pi a)`.
//! * **Griffith.** Equilibrium of the crack-like edge: `G = K^2/(2 E*) = dgamma`,
//!   so `P = -sqrt(2 pi a E* dgamma)`: `-sqrt(2 pi a)` in normalised units (the
//!   JKR load of the smooth cylinder, E.42a).
//!
//! Hence
//!
//! ```text
//! L(a) = L_1(a) - sqrt(2 pi a),      Delta(a) = (2 L/pi) ln(2/a) + I(a).
//! ```
//!
//! Nothing here sums Bessel functions: `L_1` and `I` are integrals of the profile's
//! slope, computed by Gauss-Legendre quadrature after `x = a sin(theta)`, which
//! leaves the entire integrands `a sin(t) h'(a sin t)` and
//! `(pi/2 - t) a cos(t) h'(a sin t)` on `[0, pi/2]`.
//! `h'(a sin t)` holds `sin(D_j sin t)`, `D_j = 2 pi a/beta_j`, whose Chebyshev
//! (and so Gauss-Legendre) coefficients fall like `(e D/(2 k))^k` beyond
//! `k ~ D/2`: [`quadrature_order`] takes `n = ceil(D_max) + 48` nodes, far past
//! that, and a test compares it with `2n`. These values are estimates (f64, no
//! bound): they are a reference for the model, not a certified path.

use std::f64::consts::PI;

use crate::contact::model::check_bessel_lengths;
use crate::contact::profile::WavyProfile;
use crate::error::{finite, Interval, Result};
use crate::quad::gauss_legendre;

/// One JKR state of a profile.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct JkrState {
    /// Contact half-width.
    pub abar: f64,
    /// The adhesionless load `L_1(a)`.
    pub adhesionless_load: f64,
    /// The JKR load `L_1(a) - sqrt(2 pi a)`.
    pub load: f64,
    /// The approach `(2 L/pi) ln(2/a) + I(a)`.
    pub approach: f64,
}

/// Gauss-Legendre nodes for a contact `abar`: `ceil(D_max) + 48`, `D_max` the
/// largest Bessel length `2 pi abar/beta_j` (the cylinder alone: 48).
pub fn quadrature_order(profile: &WavyProfile, abar: f64) -> usize {
    let d_max = profile.active_waves().map(|w| w.bessel_length(abar)).fold(0.0, f64::max);
    // finite and at most MAX_WAVE_D (1e5) once check_bessel_lengths has passed
    d_max.min(1e9).ceil() as usize + 48
}

/// Nodes of one Gauss-Legendre panel beyond which the range is split: `n` nodes
/// become `ceil(n/PANEL_ORDER)` panels of `PANEL_ORDER + 48` nodes each (a panel
/// then holds at most `PANEL_ORDER` radians of the finest wave's phase, resolved
/// as in one rule).
const PANEL_ORDER: usize = 512;

/// `int_0^{pi/2} f` with `n` nodes: one rule, or panels when `n > 2 PANEL_ORDER`.
fn quarter_period(f: impl FnMut(f64) -> f64, n: usize) -> Result<f64> {
    if n <= 2 * PANEL_ORDER {
        gauss_legendre::integrate(f, 0.0, PI / 2.0, n)
    } else {
        gauss_legendre::integrate_composite(f, 0.0, PI / 2.0, PANEL_ORDER + 48, n.div_ceil(PANEL_ORDER))
    }
}

/// The profile's slope `h'(x) = x + sum_j (2 pi alpha_j/beta_j) sin(2 pi x/beta_j)`.
fn slope(profile: &WavyProfile, x: f64) -> f64 {
    profile.active_waves().fold(x, |s, w| {
        let k = 2.0 * PI / w.beta();
        s + w.alpha() * k * (k * x).sin()
    })
}

/// The JKR state at `abar > 0` with `n >= 1` quadrature nodes (split into panels of
/// 560 nodes above 1024). A wave too fine for the contact (`D_j` over 1e5) is
/// [`crate::error::ProfileError::WaveTooFine`], as in the model.
pub fn jkr_state_with_order(profile: &WavyProfile, abar: f64, n: usize) -> Result<JkrState> {
    finite(abar, "abar")?;
    Interval::above(0.0).check("abar", abar)?;
    check_bessel_lengths(profile, abar)?;
    let load_1 = quarter_period(|t| abar * t.sin() * slope(profile, abar * t.sin()), n)?;
    let i = quarter_period(|t| (PI / 2.0 - t) * abar * t.cos() * slope(profile, abar * t.sin()), n)? * 2.0 / PI;
    let load = load_1 - (2.0 * PI * abar).sqrt();
    Ok(JkrState { abar, adhesionless_load: load_1, load, approach: 2.0 * load / PI * (2.0 / abar).ln() + i })
}

/// The JKR state at `abar > 0` ([`quadrature_order`] nodes).
pub fn jkr_state(profile: &WavyProfile, abar: f64) -> Result<JkrState> {
    jkr_state_with_order(profile, abar, quadrature_order(profile, abar))
}
