//! The normalised wavy Maugis model at one contact size (docs/model.md).
//!
//! # Normalisation (two length scales, docs/model.md)
//!
//! Horizontal lengths by `l_h = (dgamma R^2/E*)^(1/3)`: `a = abar l_h`,
//! `c = m abar l_h`, `x = xbar l_h`, `zeta = beta l_h`. Vertical lengths by
//! `l_v = l_h^2/R`: `A = alpha l_v`, `u`, `g`, `delta = l_v/lambda`. Load by
//! `(E* dgamma^2 R)^(1/3)`, traction by `sigma`. In these units
//! `hbar(x) = x^2/2 + 2 alpha sin^2(pi x/beta)`, `ubar_H = u_H(a = abar, R = 1)`,
//! `ubar_w = u_w(a = abar, zeta = beta, A = alpha)` and
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
//!      + lambda [2 alpha sin^2(pi m abar/beta) - ubar_w(m abar)]   <- this sign
//!      - 1.
//! ```
//!
//! `F(1) = -1` because every gap term vanishes at the contact edge. The strip
//! ends where the gap *first* reaches `delta` (docs/model.md, "Root m"), so `m` is the
//! smallest root: [`ContactSize::solve_strip`] scans outward from `c = a` (steps of
//! at most `beta/16` so no wave period is skipped, shrinking towards the edge when
//! the root is closer than one step) for the first sign change and refines it with
//! Brent's method to `1e-13` relative **in `m - 1`** ([`StripEnd`]): as
//! `lambda -> inf`, `m - 1 ~ pi/(4 lambda^2 abar)`, and `m` itself would carry
//! only `1e-16/(m-1)` relative accuracy of it. The strip functions
//! ([`hertz_gap_fn`], [`adhesive_gap_fn`], [`adhesive_approach_fn`]) take `m - 1`
//! and switch to their Taylor series below `1e-3`, so the JKR limit is reached
//! with full relative accuracy. A root where `F` touches zero without changing sign is not
//! detected (it is not a crossing). No root below `c - a = `[`MAX_STRIP`] is an
//! [`Error::NoConvergence`].
//!
//! # Load (Eq. 14) and traction (Eq. 16)
//!
//! `Lbar = pi abar^2/4 - 2 lambda abar sqrt(m^2-1) + (pi^2 alpha abar/beta) J1(2 pi abar/beta)`.
//! Inside the contact
//! `pbar = (2/pi) atan(abar sqrt((m^2-1)/(abar^2-x^2))) - (sqrt(abar^2-x^2)/(2 lambda)) (1 + (2 pi alpha/(beta abar)) K(x/abar))`
//! with `K(c) = int_0^D J0(t) cos((t-D) c) dt`, `D = 2 pi abar/beta` (the printed
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

use std::f64::consts::PI;

use crate::contact::displacement::{profile_depth, u_adhesive, u_hertz, WaveBessel};
use crate::error::{finite, Error, Interval, Invariant, Result};
/// Brent's method lives in [`crate::roots`]; re-exported here, its former path.
pub use crate::roots::brent;
use crate::roots::{first_crossing, golden_section_min, BRENT_REL_TOL};

/// Largest strip width `c - a` (in `l_h`) the root scan explores.
pub const MAX_STRIP: f64 = 1.0e4;

/// Relative tolerance of the root `m - 1` (the solver's variable).
pub const M_REL_TOL: f64 = BRENT_REL_TOL;

/// The golden-section search that refines a sampled local maximum of the strip
/// residual stops at this width in `c - a` (relative to `1 + (c - a)`).
const PEAK_REL_TOL: f64 = 1e-10;

/// The strip scan starts this many octaves below its first step (`first/4096`) and
/// doubles up to it ([`ContactSize::solve_strip`]).
const EDGE_OCTAVES: i32 = 12;

/// Relative slack of the gap test: a state interpenetrates when its strip gap is
/// below `-GAP_REL_TOL delta` (`delta = 1/lambda`, the gap scale of the strip)
/// minus the rounding allowance of [`ContactSize::gap_tolerance`].
pub const GAP_REL_TOL: f64 = 1e-9;
/// Slack of the traction test: cavitation when `pbar > 1 + TRACTION_TOL`
/// (plus the rounding allowance of the Hertz term, see [`ContactSize::traction_tolerance`]).
pub const TRACTION_TOL: f64 = 1e-9;

/// Below this `z = m - 1` the strip functions use their Taylor series
/// (six terms: truncation below `z^6 < 1e-18` relative).
const SERIES_Z: f64 = 1e-3;

/// Supported Maugis parameters: beyond these the strip equation over- or
/// underflows in f64 (`lambda^2 abar` terms) or the strip leaves [`MAX_STRIP`].
pub const LAMBDA_RANGE: Interval = Interval::closed(1e-6, 1e6);
/// Largest supported `alpha`.
pub const ALPHA_MAX: f64 = 1e6;
/// Supported `alpha` (0 is the smooth cylinder).
pub const ALPHA_RANGE: Interval = Interval::closed(0.0, ALPHA_MAX);
/// Supported `beta`.
pub const BETA_RANGE: Interval = Interval::closed(1e-6, 1e6);
/// Largest supported contact size.
pub const ABAR_MAX: f64 = 1e4;
/// Supported contact sizes `abar`.
pub const ABAR_RANGE: Interval = Interval::left_open(0.0, ABAR_MAX);

/// Samples per extremum search in [`ContactSize::validity`].
const VALIDITY_SAMPLES: usize = 48;

/// The model parameters: Maugis parameter `lambda`, roughness `alpha` (amplitude)
/// and `beta` (wavelength).
///
/// The fields are private: a `Params` exists only through [`Params::new`] (or
/// deserialization, which runs the same checks), so every `Params` a function
/// receives is inside [`LAMBDA_RANGE`], [`ALPHA_RANGE`] and [`BETA_RANGE`].
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(try_from = "ParamsFields", into = "ParamsFields"))]
pub struct Params {
    pub(crate) lambda: f64,
    pub(crate) alpha: f64,
    pub(crate) beta: f64,
}

impl Params {
    /// Validated parameters: each finite and inside its range, else
    /// [`Error::NonFinite`] or [`Error::OutOfRange`] naming it.
    pub fn new(lambda: f64, alpha: f64, beta: f64) -> Result<Params> {
        finite(lambda, "lambda")?;
        finite(alpha, "alpha")?;
        finite(beta, "beta")?;
        LAMBDA_RANGE.check("lambda", lambda)?;
        ALPHA_RANGE.check("alpha", alpha)?;
        BETA_RANGE.check("beta", beta)?;
        Ok(Params { lambda, alpha, beta })
    }

    /// Maugis parameter, `> 0`.
    pub fn lambda(&self) -> f64 {
        self.lambda
    }

    /// Normalised wave amplitude, `>= 0` (0 is the smooth cylinder).
    pub fn alpha(&self) -> f64 {
        self.alpha
    }

    /// Normalised wavelength, `> 0`.
    pub fn beta(&self) -> f64 {
        self.beta
    }

    /// The same roughness at another Maugis parameter (checked as [`Params::new`]).
    pub fn with_lambda(&self, lambda: f64) -> Result<Params> {
        Params::new(lambda, self.alpha, self.beta)
    }
}

/// The serialized form of [`Params`]: `{"lambda", "alpha", "beta"}`, checked
/// by [`Params::new`] on the way in.
#[cfg(feature = "serde")]
#[derive(serde::Serialize, serde::Deserialize)]
struct ParamsFields {
    lambda: f64,
    alpha: f64,
    beta: f64,
}

#[cfg(feature = "serde")]
impl TryFrom<ParamsFields> for Params {
    type Error = Error;
    fn try_from(f: ParamsFields) -> Result<Params> {
        Params::new(f.lambda, f.alpha, f.beta)
    }
}

#[cfg(feature = "serde")]
impl From<Params> for ParamsFields {
    fn from(p: Params) -> ParamsFields {
        ParamsFields { lambda: p.lambda, alpha: p.alpha, beta: p.beta }
    }
}

/// Validity diagnostics of a state.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Validity {
    /// Smallest gap in the strip `abar < x <= m abar` (units of `l_v`).
    pub min_strip_gap: f64,
    /// Where it occurs.
    pub min_strip_gap_at: f64,
    /// Largest traction `pbar` inside the contact.
    pub max_traction: f64,
    /// Where it occurs.
    pub max_traction_at: f64,
    /// The gap is below minus its tolerance somewhere in the strip.
    pub interpenetration: bool,
    /// The traction exceeds `1 +` its tolerance somewhere inside the contact.
    pub cavitation: bool,
    /// Neither.
    pub valid: bool,
}

/// The end of the adhesive strip, `m = c/a > 1`, stored as `m - 1`.
///
/// As `lambda -> inf` the strip closes like `m - 1 ~ pi/(4 lambda^2 abar)`
/// (docs/model.md, the `smooth_jkr_limit` erratum row): at `lambda = 1e6` that is `1e-12`, and `m` itself would carry
/// only four significant digits of it. The solver works in `m - 1`, and every
/// quantity of a state (load, traction, gap, approach) is computed from it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StripEnd {
    m_minus_1: f64,
}

impl StripEnd {
    /// From `m - 1 > 0` (finite).
    pub fn from_m_minus_1(m_minus_1: f64) -> Result<StripEnd> {
        finite(m_minus_1, "m - 1")?;
        Interval::above(0.0).check("m - 1", m_minus_1)?;
        Ok(StripEnd { m_minus_1 })
    }

    /// From `m > 1` (finite). Loses the relative accuracy of `m - 1` when `m`
    /// is close to 1; prefer [`StripEnd::from_m_minus_1`].
    pub fn from_m(m: f64) -> Result<StripEnd> {
        finite(m, "m")?;
        Interval::above(1.0).check("the strip ratio m = c/a", m)?;
        Ok(StripEnd { m_minus_1: m - 1.0 })
    }

    /// `m = c/a` (rounded).
    pub fn m(self) -> f64 {
        1.0 + self.m_minus_1
    }

    /// `m - 1`, to full relative accuracy.
    pub fn m_minus_1(self) -> f64 {
        self.m_minus_1
    }

    /// `sqrt(m^2 - 1)`.
    pub fn sqrt_m2_minus_1(self) -> f64 {
        sqrt_z2z(self.m_minus_1)
    }
}

/// `sqrt(z (2 + z)) = sqrt((1+z)^2 - 1)`.
fn sqrt_z2z(z: f64) -> f64 {
    (z * (2.0 + z)).sqrt()
}

/// `acosh(1 + z)` for `z >= 0`, accurate for small `z`.
fn acosh_1p(z: f64) -> f64 {
    (z + sqrt_z2z(z)).ln_1p()
}

/// The Hertz gap function `(1+z) sqrt(z(2+z)) - acosh(1+z)`, `z >= 0`
/// (`= 2 int_1^{1+z} sqrt(t^2-1) dt`; the Hertz gap at `x = (1+z) a` is
/// `a^2/2` times it). Series below `SERIES_Z`:
/// `sqrt(2z) z (4/3 + z/5 - z^2/56 + z^3/288 - 5 z^4/5632 + 7 z^5/26624)`.
pub fn hertz_gap_fn(z: f64) -> f64 {
    if z < SERIES_Z {
        let p = 4.0 / 3.0 + z * (1.0 / 5.0 + z * (-1.0 / 56.0 + z * (1.0 / 288.0 + z * (-5.0 / 5632.0 + z * 7.0 / 26624.0))));
        (2.0 * z).sqrt() * z * p
    } else {
        (1.0 + z) * sqrt_z2z(z) - acosh_1p(z)
    }
}

/// The adhesive strip-gap function `sqrt(z(2+z)) acosh(1+z) - (1+z) ln(1+z)`,
/// `z >= 0` (leading term `z`; the two products differ by a factor 2, so the
/// direct form loses at most one bit).
pub fn adhesive_gap_fn(z: f64) -> f64 {
    sqrt_z2z(z) * acosh_1p(z) - (1.0 + z) * z.ln_1p()
}

/// The adhesive approach function `(1+z) acosh(1+z) - sqrt(z(2+z))`, `z >= 0`.
/// Series below `SERIES_Z`:
/// `sqrt(2z) z (2/3 - z/30 + 3 z^2/560 - 5 z^3/4032 + 35 z^4/101376 - 63 z^5/585728)`.
pub fn adhesive_approach_fn(z: f64) -> f64 {
    if z < SERIES_Z {
        let p = 2.0 / 3.0 + z * (-1.0 / 30.0 + z * (3.0 / 560.0 + z * (-5.0 / 4032.0 + z * (35.0 / 101376.0 - z * 63.0 / 585728.0))));
        (2.0 * z).sqrt() * z * p
    } else {
        (1.0 + z) * acosh_1p(z) - sqrt_z2z(z)
    }
}

/// The model at one contact size `abar` (the Bessel data of the wave term are
/// computed once here).
#[derive(Debug, Clone)]
pub struct ContactSize {
    params: Params,
    abar: f64,
    wave: Option<WaveBessel>,
    j0: f64,
    j1: f64,
}

fn check_m(m: f64) -> Result<StripEnd> {
    StripEnd::from_m(m)
}

fn check_x(x: f64) -> Result<f64> {
    finite(x, "x")
}

impl ContactSize {
    /// Prepares contact size `abar > 0`.
    pub fn new(params: Params, abar: f64) -> Result<ContactSize> {
        finite(abar, "abar")?;
        ABAR_RANGE.check("abar", abar)?;
        let wave = if params.alpha > 0.0 { Some(WaveBessel::new(abar, params.beta, params.alpha)?) } else { None };
        let js = crate::special::bessel_j::bessel_j_sequence(1, 2.0 * PI * abar / params.beta);
        let j0 = js.first().copied().unwrap_or(1.0);
        let j1 = js.get(1).copied().unwrap_or(0.0);
        Ok(ContactSize { params, abar, wave, j0, j1 })
    }

    /// The contact size.
    pub fn abar(&self) -> f64 {
        self.abar
    }

    /// The parameters.
    pub fn params(&self) -> Params {
        self.params
    }

    /// `ubar_w(x)` for `x >= abar` (`x` below `abar` is read as `abar`).
    pub fn wave_displacement(&self, x: f64) -> Result<f64> {
        check_x(x)?;
        Ok(self.wave_displacement_unchecked(x))
    }

    fn wave_displacement_unchecked(&self, x: f64) -> f64 {
        match &self.wave {
            Some(w) => w.u_fast(x.max(self.abar)),
            None => 0.0,
        }
    }

    /// The wave part of the gap, `2 alpha sin^2(pi x/beta) - ubar_w(x)`, `x >= abar`.
    fn wave_gap(&self, x: f64) -> f64 {
        let Params { alpha, beta, .. } = self.params;
        if alpha > 0.0 {
            let sn = (PI * x / beta).sin();
            2.0 * alpha * sn * sn - self.wave_displacement_unchecked(x)
        } else {
            0.0
        }
    }

    /// The three gap contributions at `c = m abar`, `m = 1 + z` with `z >= 0`:
    /// (Hertz, adhesive, wave), units of `l_v`.
    fn strip_terms(&self, z: f64) -> (f64, f64, f64) {
        let (a, lambda) = (self.abar, self.params.lambda);
        let hertz = 0.5 * a * a * hertz_gap_fn(z);
        let adhesive = 4.0 / PI * lambda * a * adhesive_gap_fn(z);
        let c = a + a * z;
        (hertz, adhesive, self.wave_gap(c))
    }

    /// The three gap contributions at `c = m abar` (`m >= 1`): (Hertz, adhesive, wave).
    pub fn strip_gap_terms(&self, m: f64) -> Result<(f64, f64, f64)> {
        finite(m, "m")?;
        Interval::at_least(1.0).check("the strip ratio m = c/a", m)?;
        Ok(self.strip_terms(m - 1.0))
    }

    fn residual_z(&self, z: f64) -> f64 {
        let (h, ad, w) = self.strip_terms(z);
        self.params.lambda * (h + ad + w) - 1.0
    }

    /// `F(m) = lambda gbar(m abar) - 1` (Eq. 15b, corrected), `m >= 1`.
    pub fn strip_residual(&self, m: f64) -> Result<f64> {
        finite(m, "m")?;
        Interval::at_least(1.0).check("the strip ratio m = c/a", m)?;
        Ok(self.residual_z(m - 1.0))
    }

    /// `F` as a function of `z = m - 1 >= 0` (full relative accuracy in `z`).
    pub fn strip_residual_m_minus_1(&self, z: f64) -> Result<f64> {
        finite(z, "m - 1")?;
        Interval::at_least(0.0).check("m - 1", z)?;
        Ok(self.residual_z(z))
    }

    /// The first root `m > 1` of [`Self::strip_residual`] (see [`Self::solve_strip`]).
    pub fn solve_m(&self) -> Result<f64> {
        Ok(self.solve_strip()?.m())
    }

    /// The first root of the strip equation, solved for `z = m - 1`.
    ///
    /// Scan in the strip width `s = c - a = z abar` with steps of
    /// `max(min(beta/16, 1/4), min(s/20, beta/16))`: never more than a sixteenth
    /// of a wave period, so no period and no wide excursion within one is skipped;
    /// every sampled local maximum below zero is refined by golden-section search
    /// (the residual's excursions above zero narrower than a step rise between
    /// samples), and a refined maximum at or above zero brackets the first
    /// crossing. This samples the residual, it does not bound it between samples:
    /// an excursion that leaves no sampled local maximum (two maxima within one
    /// step) can still be missed; `examples/strip_scan_check` counts the misses
    /// against a scan 128 times finer. The scan starts at `s_1/4096` (`s_1` the
    /// first step) and doubles up to `s_1`: next to the edge the residual rises
    /// like a square root and can cross zero and fall back within the first step.
    /// When that first sample is already past the root, the crossing is
    /// bracketed by halving `s` towards the edge (`F(0) = -1` ends the halving
    /// below `z = 1e-300`). Brent's method then refines `z` to [`M_REL_TOL`] relative.
    pub fn solve_strip(&self) -> Result<StripEnd> {
        let a = self.abar;
        let f = |z: f64| self.residual_z(z);
        let max_step = (self.params.beta / 16.0).min(0.25).max(1e-6);
        let eval = |s: f64| -> Result<f64> {
            let v = f(s / a);
            if v.is_finite() {
                Ok(v)
            } else {
                Err(Error::Invariant(Invariant::StripResidualNotFinite { m_minus_1: s / a }))
            }
        };
        let done = |z: Result<f64>| -> Result<StripEnd> {
            let z = z?;
            StripEnd::from_m_minus_1(z).map_err(|_| Error::Invariant(Invariant::StripRootNotPositive { m_minus_1: z }))
        };
        // The scan starts EDGE_OCTAVES octaves below the first step and doubles up to
        // it: next to the edge F rises like a square root and can cross zero and fall
        // back within the first step (lambda 24.5, alpha 2.97, beta 0.228, abar 3.09:
        // F > 0 at m = 1.00072, the first step ends at m = 1.0046).
        let first = max_step;
        let start = first * 0.5f64.powi(EDGE_OCTAVES);
        let f_start = eval(start)?;
        if f_start >= 0.0 {
            // Bracket towards the edge: F(0) = -1.
            let (mut hi, mut f_hi) = (start, f_start);
            let mut lo = 0.5 * start;
            loop {
                let f_lo = eval(lo)?;
                if f_lo < 0.0 {
                    return done(brent(f, lo / a, hi / a, f_lo, f_hi));
                }
                hi = lo;
                f_hi = f_lo;
                lo *= 0.25;
                if lo < 1e-300 * a {
                    return done(brent(f, 0.0, hi / a, -1.0, f_hi));
                }
            }
        }
        // then never more than a sixteenth of a wave period (the step grew with s
        // before, 5 % of s, and skipped a positive excursion of width 0.09 in s:
        // abar 2.54, lambda 0.107, alpha 1.23, beta 0.79 gave m = 2.51 for the
        // first root 2.34); every sampled local maximum is refined (narrow
        // excursions above zero between samples: 4 of 4000 random parameter sets,
        // e.g. lambda 4.36, alpha 0.561, beta 0.393, abar 0.928 gave m = 1.345 for
        // the first root 1.065; F(0) = -1 is the first sample's left neighbour)
        let next = |s: f64| if s < first { 2.0 * s } else { s + max_step.max((s * 0.05).min(self.params.beta / 16.0)) };
        match first_crossing(eval, Some((0.0, -1.0)), (start, f_start), next, MAX_STRIP, PEAK_REL_TOL)? {
            Some((lo, hi, f_lo, f_hi)) => done(brent(f, lo / a, hi / a, f_lo, f_hi)),
            None => Err(Error::NoStripEnd { model: "Eq. 15b, c - a", limit: MAX_STRIP }),
        }
    }

    /// Eq. 14 at the strip end `m` (`m > 1`).
    pub fn load(&self, m: f64) -> Result<f64> {
        let load = self.load_at(check_m(m)?);
        if load.is_finite() {
            Ok(load)
        } else {
            Err(Error::NotRepresentable { quantity: "load", abar: self.abar })
        }
    }

    /// Eq. 14: `pi abar^2/4 - 2 lambda abar sqrt(m^2-1) + (pi^2 alpha abar/beta) J1(2 pi abar/beta)`.
    pub fn load_at(&self, strip: StripEnd) -> f64 {
        let (a, Params { lambda, alpha, beta }) = (self.abar, self.params);
        PI * a * a / 4.0 - 2.0 * lambda * a * strip.sqrt_m2_minus_1() + PI * PI * alpha * a / beta * self.j1
    }

    /// The approach `Delta-bar` (units of `l_v`) measured from a datum at
    /// infinity with the logarithmic term removed:
    /// `Delta = lim_{x -> inf} [ubar(x) - (2 Lbar/pi) ln x]`.
    ///
    /// In plane strain the surface displacement grows like `(2 Lbar/pi) ln x`, so
    /// an approach exists only relative to a datum; any other datum shifts
    /// `Delta` by `k Lbar` and leaves `int Delta dLbar` over a closed cycle
    /// unchanged. From the large-`x` forms of Eq. 10, the Bessel form of `u_w`
    /// (docs/displacement.md, Route 2, `acosh(x/a) -> ln(2x/a)`, `q -> 0`) and A.5b:
    ///
    /// ```text
    /// Delta = (2 Lbar/pi) ln(2/abar) + abar^2/4 + alpha (1 - J0(D))
    ///       + (4 lambda abar/pi) (m acosh(m) - sqrt(m^2-1)),   D = 2 pi abar/beta.
    /// ```
    pub fn approach_at(&self, strip: StripEnd) -> f64 {
        let (a, Params { lambda, alpha, .. }) = (self.abar, self.params);
        let load = self.load_at(strip);
        2.0 * load / PI * (2.0 / a).ln()
            + a * a / 4.0
            + alpha * (1.0 - self.j0)
            + 4.0 * lambda * a / PI * adhesive_approach_fn(strip.m_minus_1())
    }

    /// [`Self::approach_at`] for `m > 1`.
    pub fn approach(&self, m: f64) -> Result<f64> {
        Ok(self.approach_at(check_m(m)?))
    }

    /// `pbar(x)`: Eq. 16 inside the contact, 1 in the strip, 0 outside (`m > 1`).
    pub fn traction(&self, m: f64, x: f64) -> Result<f64> {
        Ok(self.traction_at(check_m(m)?, check_x(x)?))
    }

    /// [`Self::traction`] at a solved strip end.
    pub fn traction_at(&self, strip: StripEnd, x: f64) -> f64 {
        let (a, Params { lambda, alpha, beta }) = (self.abar, self.params);
        let ax = x.abs();
        if ax >= a {
            let z = strip.m_minus_1();
            return if ax - a <= a * z { 1.0 } else { 0.0 };
        }
        let w = ((a - ax) * (a + ax)).sqrt();
        let adhesive = 2.0 / PI * (a * strip.sqrt_m2_minus_1() / w).atan();
        let k = match &self.wave {
            Some(wb) => wb.traction_integral(ax / a),
            None => 0.0,
        };
        adhesive - w / (2.0 * lambda) * (1.0 + 2.0 * PI * alpha / (beta * a) * k)
    }

    /// The total displacement `ubar(x)`: the profile inside the contact, the sum
    /// of the Hertz, wave and adhesive displacements outside (`m > 1`).
    pub fn displacement(&self, m: f64, x: f64) -> Result<f64> {
        self.displacement_at(check_m(m)?, check_x(x)?)
    }

    /// [`Self::displacement`] at a solved strip end.
    pub fn displacement_at(&self, strip: StripEnd, x: f64) -> Result<f64> {
        let ax = check_x(x)?.abs();
        let Params { lambda, alpha, beta } = self.params;
        if ax <= self.abar {
            return profile_depth(1.0, alpha, beta, ax);
        }
        let uh = u_hertz(self.abar, 1.0, ax)?;
        let c = self.abar + self.abar * strip.m_minus_1();
        let ua = u_adhesive(self.abar, c, lambda, 1.0, ax)?;
        Ok(uh + self.wave_displacement_unchecked(ax) + ua)
    }

    /// The gap `gbar(x) = hbar - ubar` (zero inside the contact, `m > 1`).
    pub fn gap(&self, m: f64, x: f64) -> Result<f64> {
        self.gap_at(check_m(m)?, check_x(x)?)
    }

    /// [`Self::gap`] at a solved strip end. Inside the strip it is
    /// [`Self::strip_gap`] (well conditioned as the strip closes).
    pub fn gap_at(&self, strip: StripEnd, x: f64) -> Result<f64> {
        let ax = check_x(x)?.abs();
        let a = self.abar;
        if ax <= a {
            return Ok(0.0);
        }
        let z = strip.m_minus_1();
        let t = (ax - a) / (a * z);
        if t <= 1.0 {
            return Ok(self.strip_gap(strip, t));
        }
        let Params { alpha, beta, .. } = self.params;
        Ok(profile_depth(1.0, alpha, beta, ax)? - self.displacement_at(strip, ax)?)
    }

    /// The gap inside the strip at `x = abar (1 + t (m - 1))`, `t in [0, 1]`
    /// (clamped), from differences that never cancel as `m -> 1`:
    ///
    /// * Hertz: `hbar - ubar_H = (abar^2/2) H(t z)` with [`hertz_gap_fn`]
    ///   (`xi^2 - xi/(xi + sqrt(xi^2-1)) = xi sqrt(xi^2-1)`);
    /// * adhesive (A.5a with `xi = x/a`, `mu = m`, `S = sqrt(mu^2-1)`,
    ///   `W = sqrt(mu^2-xi^2)`, `q = S/W`, `p = xi q`):
    ///   `ubar_a = (4 lambda abar/pi) [mu (acosh p - acosh q) + (mu - xi) acosh q - S acosh xi]`,
    ///   where `q - 1 = (xi^2-1)/((S+W) W)`, `p - q = (xi - 1) q` and
    ///   `acosh p - acosh q = ln1p((p - q)(1 + (p+q)/(P+Q))/(q + Q))`,
    ///   `P, Q = sqrt(p^2-1), sqrt(q^2-1)`; at `t = 1`, `-(4 lambda abar/pi)` [`adhesive_gap_fn`];
    /// * wave: `2 alpha sin^2(pi x/beta) - ubar_w(x)` (absolute error `~1e-15 alpha D`).
    pub fn strip_gap(&self, strip: StripEnd, t: f64) -> f64 {
        let t = if t.is_nan() { 1.0 } else { t.clamp(0.0, 1.0) };
        let (a, lambda) = (self.abar, self.params.lambda);
        let z = strip.m_minus_1();
        let zt = z * t;
        let x = a + a * zt;
        let hertz = 0.5 * a * a * hertz_gap_fn(zt);
        let kfac = 4.0 * lambda * a / PI;
        let u_a = if t >= 1.0 {
            -kfac * adhesive_gap_fn(z)
        } else if t <= 0.0 {
            0.0
        } else {
            let mu = 1.0 + z;
            let s = sqrt_z2z(z);
            let xi2m1 = zt * (2.0 + zt);
            let w = (z * (1.0 - t) * (2.0 + z + zt)).sqrt();
            let q = s / w;
            let qm1 = xi2m1 / ((s + w) * w);
            let p_minus_q = zt * q;
            let p = q + p_minus_q;
            let big_q = (qm1 * (q + 1.0)).sqrt();
            let pm1 = qm1 + p_minus_q;
            let big_p = (pm1 * (p + 1.0)).sqrt();
            let acosh_q = (qm1 + big_q).ln_1p();
            let acosh_p_minus_q = (p_minus_q * (1.0 + (p + q) / (big_p + big_q)) / (q + big_q)).ln_1p();
            kfac * (mu * acosh_p_minus_q + z * (1.0 - t) * acosh_q - s * acosh_1p(zt))
        };
        hertz + self.wave_gap(x) - u_a
    }

    /// Tolerance of the gap test: `GAP_REL_TOL / lambda` plus a rounding
    /// allowance for the wave term (`1e-13 alpha (1 + D)`, ~100 times its
    /// measured error) and for the Hertz term at large `abar` (`1e-14 abar^2`).
    pub fn gap_tolerance(&self) -> f64 {
        let Params { lambda, alpha, beta } = self.params;
        let d = 2.0 * PI * self.abar / beta;
        GAP_REL_TOL / lambda + 1e-13 * alpha * (1.0 + d) + 1e-14 * self.abar * self.abar
    }

    /// Tolerance of the traction test: [`TRACTION_TOL`] plus the rounding of the
    /// Hertz/wave term `sqrt(abar^2-x^2)/(2 lambda) (1 + ...)` (`1e-14 abar/lambda (1 + 2 pi alpha D/beta)`).
    pub fn traction_tolerance(&self) -> f64 {
        let Params { lambda, alpha, beta } = self.params;
        let d = 2.0 * PI * self.abar / beta;
        TRACTION_TOL + 1e-14 * self.abar / lambda * (1.0 + 2.0 * PI * alpha * d / (beta * self.abar))
    }

    /// Minimum strip gap and maximum inner traction, located by sampling and
    /// golden-section refinement (`m > 1`).
    pub fn validity(&self, m: f64) -> Result<Validity> {
        self.validity_at(check_m(m)?)
    }

    /// [`Self::validity`] at a solved strip end. The strip is sampled in the
    /// relative coordinate `t` of [`Self::strip_gap`], so the search resolves it
    /// however narrow it is.
    pub fn validity_at(&self, strip: StripEnd) -> Result<Validity> {
        let a = self.abar;
        let z = strip.m_minus_1();
        let (gt, gv) = refine_extremum(|t| self.strip_gap(strip, t), 1e-6, 1.0, true);
        let trac = |x: f64| self.traction_at(strip, x);
        let (tx, tv) = refine_extremum(trac, 0.0, a * (1.0 - 1e-9), false);
        if !gv.is_finite() || !tv.is_finite() {
            return Err(Error::Internal { what: "validity check produced a non-finite value".into() });
        }
        let interpenetration = gv < -self.gap_tolerance();
        let cavitation = tv > 1.0 + self.traction_tolerance();
        Ok(Validity {
            min_strip_gap: gv,
            min_strip_gap_at: a + a * z * gt,
            max_traction: tv,
            max_traction_at: tx,
            interpenetration,
            cavitation,
            valid: !interpenetration && !cavitation,
        })
    }
}

/// Extremum (minimum if `minimize`, else maximum) of `f` on `[lo, hi]`: the best
/// of [`VALIDITY_SAMPLES`] samples, refined by golden-section search between its
/// neighbours. Returns `(argument, value)`.
fn refine_extremum<F: Fn(f64) -> f64>(f: F, lo: f64, hi: f64, minimize: bool) -> (f64, f64) {
    let sign = if minimize { 1.0 } else { -1.0 };
    let g = |x: f64| sign * f(x);
    if !(hi > lo) {
        return (lo, f(lo));
    }
    let n = VALIDITY_SAMPLES;
    let h = (hi - lo) / n as f64;
    let mut best = (lo, g(lo));
    for i in 1..=n {
        let x = lo + h * i as f64;
        let v = g(x);
        if v < best.1 || best.1.is_nan() {
            best = (x, v);
        }
    }
    // golden section on [best - h, best + h] ∩ [lo, hi]
    let refined = golden_section_min(|x| Ok::<f64, ()>(g(x)), (best.0 - h).max(lo), (best.0 + h).min(hi), 1e-12, 60);
    let (x, v) = match refined {
        Ok((x, v)) if v < best.1 => (x, v),
        _ => best,
    };
    (x, sign * v)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[cfg(feature = "serde")]
    #[test]
    fn params_deserialize_through_the_checks() {
        let p = Params::new(0.5, 0.25, 1.125).unwrap();
        let json = serde_json::to_string(&p).unwrap();
        assert_eq!(json, r#"{"lambda":0.5,"alpha":0.25,"beta":1.125}"#);
        assert_eq!(serde_json::from_str::<Params>(&json).unwrap(), p);
        // out of range or missing: refused with the constructor's message, not built
        for bad in [r#"{"lambda":-1.0,"alpha":0.25,"beta":1.125}"#, r#"{"lambda":0.5,"alpha":0.25,"beta":0.0}"#, r#"{"lambda":0.5,"alpha":0.25}"#] {
            let e = serde_json::from_str::<Params>(bad).unwrap_err().to_string();
            assert!(e.contains("lambda") || e.contains("beta"), "{bad}: {e}");
        }
    }

    #[test]
    fn params_accessors_and_with_lambda() {
        let p = Params::new(0.5, 0.25, 1.125).unwrap();
        assert_eq!((p.lambda(), p.alpha(), p.beta()), (0.5, 0.25, 1.125));
        assert_eq!(p.with_lambda(3.0).unwrap(), Params::new(3.0, 0.25, 1.125).unwrap());
        assert!(matches!(p.with_lambda(f64::NAN), Err(Error::NonFinite { what: "lambda" })));
        assert!(matches!(p.with_lambda(-1.0), Err(Error::OutOfRange { .. })));
    }

    #[test]
    fn smooth_case_is_johnson_greenwood() {
        // alpha = 0: F(m) has no wave term; the root satisfies the JG equation.
        let p = Params::new(1.0, 0.0, 1.0).unwrap();
        let cs = ContactSize::new(p, 2.0).unwrap();
        let m = cs.solve_m().unwrap();
        assert!(cs.strip_residual(m).unwrap().abs() < 1e-12);
        assert!(m > 1.0);
    }

    #[test]
    fn residual_is_minus_one_at_the_edge() {
        let p = Params::new(1.5, 2f64.sqrt() / 4.0, 1.125).unwrap();
        for abar in [0.5, 2.0, 5.5] {
            let cs = ContactSize::new(p, abar).unwrap();
            assert!((cs.strip_residual(1.0).unwrap() + 1.0).abs() < 1e-12);
        }
    }

    /// The well-conditioned strip gap equals `h - u_H - u_w - u_a` from the
    /// displacement module where that is accurate (a wide strip).
    #[test]
    fn strip_gap_matches_the_displacement_sum() {
        let p = Params::new(0.7, 0.3, 1.3).unwrap();
        let cs = ContactSize::new(p, 1.9).unwrap();
        let strip = StripEnd::from_m_minus_1(0.4).unwrap();
        for t in [0.01, 0.2, 0.5, 0.9, 0.999, 1.0] {
            let x = 1.9 * (1.0 + 0.4 * t);
            let direct = profile_depth(1.0, 0.3, 1.3, x).unwrap()
                - u_hertz(1.9, 1.0, x).unwrap()
                - cs.wave_displacement(x).unwrap()
                - u_adhesive(1.9, 1.9 * 1.4, 0.7, 1.0, x).unwrap();
            let g = cs.strip_gap(strip, t);
            assert!((g - direct).abs() < 1e-12 * (1.0 + direct.abs()), "t = {t}: {g} vs {direct}");
        }
    }

    /// The series branches of the strip functions join their closed forms.
    #[test]
    fn strip_function_series_join_closed_forms() {
        let z = SERIES_Z;
        let below = z * (1.0 - 1e-12);
        for (f, name) in [(hertz_gap_fn as fn(f64) -> f64, "H"), (adhesive_approach_fn, "P")] {
            let (a, b) = (f(below), f(z));
            assert!((a - b).abs() < 1e-10 * b.abs(), "{name}: {a} vs {b}");
        }
    }

    #[test]
    fn state_functions_reject_bad_m_and_x() {
        let p = Params::new(1.0, 0.2, 1.0).unwrap();
        let cs = ContactSize::new(p, 1.0).unwrap();
        for m in [f64::NAN, f64::INFINITY, 1.0, 0.5, -2.0] {
            assert!(cs.load(m).is_err(), "load({m})");
            assert!(cs.traction(m, 0.3).is_err(), "traction({m})");
            assert!(cs.displacement(m, 2.0).is_err());
            assert!(cs.gap(m, 2.0).is_err());
            assert!(cs.validity(m).is_err());
            assert!(cs.approach(m).is_err());
        }
        for m in [f64::NAN, 0.99, f64::NEG_INFINITY] {
            assert!(cs.strip_residual(m).is_err(), "strip_residual({m})");
            assert!(cs.strip_gap_terms(m).is_err());
        }
        assert!(cs.strip_residual_m_minus_1(-1e-3).is_err());
        assert!(cs.traction(1.2, f64::NAN).is_err());
        assert!(cs.wave_displacement(f64::NAN).is_err());
        assert!(StripEnd::from_m_minus_1(0.0).is_err());
        assert!(StripEnd::from_m_minus_1(f64::NAN).is_err());
    }

    #[test]
    fn bad_parameters() {
        assert!(Params::new(0.0, 0.1, 1.0).is_err());
        assert!(Params::new(1.0, -0.1, 1.0).is_err());
        assert!(Params::new(1.0, 0.1, 0.0).is_err());
        assert!(Params::new(f64::NAN, 0.1, 1.0).is_err());
        let p = Params::new(1.0, 0.1, 1.0).unwrap();
        assert!(ContactSize::new(p, 0.0).is_err());
    }
}
