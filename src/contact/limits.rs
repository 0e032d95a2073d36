//! The limits and envelopes of Appendix E and Eq. 17 (normalised units).
//!
//! * JKR (`lambda -> inf`), E.42a: `L = pi a^2/4 + (pi^2 alpha a/beta) J1(2 pi a/beta) - sqrt(2 pi a)`;
//!   its envelope E.42b: `pi a^2/4 +/- pi sqrt(alpha^2/beta) sqrt(a) - sqrt(2 pi a)`
//!   (Kesari et al. 2010, from the large-argument form of `J1`).
//! * M-DMT (`lambda -> 0`), E.43a: `L = pi a^2/4 + (pi^2 alpha a/beta) J1(2 pi a/beta) - L'_p`,
//!   `L'_p = 2 lambda cbar` (E.43c), where `cbar = m abar` is the first root of E.43b,
//!   `1 = lambda cbar^2/2 + 2 alpha lambda sin^2(pi cbar/beta)` (the rigid profile
//!   reaches the interaction range); envelope E.43d with `- L'_p`.
//! * Smooth M-DMT, E.44: `pi a^2/4 - 2 sqrt(2 lambda)` (pull-off `2 sqrt(2 lambda)`).
//! * Local envelope, Eq. 17: the smooth Maugis load at the same `lambda`
//!   `+/- pi sqrt(alpha^2/beta) sqrt(a)`.
//!
//! For a profile of many waves (docs/model.md, "Many waves") each wave term becomes a
//! sum over the waves, the same way as in the model:
//!
//! * the adhesionless load `pi a^2/4 + sum_j (pi^2 alpha_j a/beta_j) J1(2 pi a/beta_j)`
//!   ([`adhesionless_load_profile`]);
//! * the envelope half-width `sum_j pi alpha_j sqrt(a/beta_j)` ([`envelope_halfwidth_profile`]):
//!   each wave's term is bounded by its large-argument amplitude
//!   `(pi^2 alpha_j a/beta_j) sqrt(2/(pi D_j)) = pi alpha_j sqrt(a/beta_j)`, and the
//!   amplitudes add (the triangle inequality; sharp only where the waves' phases align);
//! * E.43b `1 = lambda cbar^2/2 + 2 lambda sum_j alpha_j sin^2(pi cbar/beta_j)`, whose
//!   first root lies in `[c_lo, sqrt(2/lambda)]`, `c_lo = sqrt(2 (1 - 2 lambda sum_j alpha_j)/lambda)`
//!   (below `c_lo` every `sin^2 <= 1` keeps `f < 0`; at `sqrt(2/lambda)` the cylinder alone
//!   gives `f >= 0`).
//!
//! Tabulated: [`appendix_e`] gives E.42a/b and E.43a/d at one contact size and
//! [`appendix_e_rows`] on the grid `abar_i = amax i/points` (what the load-area
//! plot draws); [`LimitRow`] adds E.44 and Eq. 17, and [`limit_rows`] is the
//! table of `maugis limits` (its CSV columns [`LimitRow::COLUMNS`], its JSON rows).

use std::f64::consts::PI;

#[cfg(feature = "parallel")]
use rayon::prelude::*;

use crate::contact::curve::load_at;
use crate::contact::located::{At, LocatedError};
use crate::contact::model::Params;
use crate::contact::profile::WavyProfile;
use crate::roots::{brent, first_crossing};
use crate::error::{finite, Error, Interval, Result};
use crate::special::bessel_j::bessel_j_sequence;

fn check_abar(abar: f64) -> Result<()> {
    finite(abar, "abar")?;
    Interval::above(0.0).check("abar", abar)?;
    Ok(())
}

/// One wave's adhesionless load term `(pi^2 alpha a/beta) J1(2 pi a/beta)`.
fn wave_load_term(alpha: f64, beta: f64, abar: f64) -> f64 {
    let d = 2.0 * PI * abar / beta;
    let j1 = bessel_j_sequence(1, d).get(1).copied().unwrap_or(0.0);
    PI * PI * alpha * abar / beta * j1
}

/// The adhesionless wavy load `pi a^2/4 + (pi^2 alpha a/beta) J1(2 pi a/beta)`.
pub fn adhesionless_load(alpha: f64, beta: f64, abar: f64) -> f64 {
    PI * abar * abar / 4.0 + wave_load_term(alpha, beta, abar)
}

/// The adhesionless load of a profile of many waves,
/// `pi a^2/4 + sum_j (pi^2 alpha_j a/beta_j) J1(2 pi a/beta_j)` (one wave: [`adhesionless_load`]).
pub fn adhesionless_load_profile(profile: &WavyProfile, abar: f64) -> f64 {
    let waves = profile.waves().iter().fold(0.0, |s, w| s + wave_load_term(w.alpha(), w.beta(), abar));
    PI * abar * abar / 4.0 + waves
}

/// The envelope half-width `pi sqrt(alpha^2/beta) sqrt(a)`.
pub fn envelope_halfwidth(alpha: f64, beta: f64, abar: f64) -> f64 {
    PI * (alpha * alpha / beta).sqrt() * abar.sqrt()
}

/// The envelope half-width of a profile of many waves, `sum_j pi sqrt(alpha_j^2/beta_j) sqrt(a)`
/// (one wave: [`envelope_halfwidth`]).
pub fn envelope_halfwidth_profile(profile: &WavyProfile, abar: f64) -> f64 {
    profile.waves().iter().fold(0.0, |s, w| s + envelope_halfwidth(w.alpha(), w.beta(), abar))
}

/// E.42a.
pub fn jkr_load(alpha: f64, beta: f64, abar: f64) -> Result<f64> {
    check_abar(abar)?;
    Ok(adhesionless_load(alpha, beta, abar) - (2.0 * PI * abar).sqrt())
}

/// E.42b: `(lower, upper)`.
pub fn jkr_envelope(alpha: f64, beta: f64, abar: f64) -> Result<(f64, f64)> {
    check_abar(abar)?;
    Ok(jkr_envelope_of(envelope_halfwidth(alpha, beta, abar), abar))
}

/// E.42b around the smooth JKR load with half-width `h`.
fn jkr_envelope_of(h: f64, abar: f64) -> (f64, f64) {
    let base = PI * abar * abar / 4.0 - (2.0 * PI * abar).sqrt();
    (base - h, base + h)
}

/// E.42a for a profile of many waves.
pub fn jkr_load_profile(profile: &WavyProfile, abar: f64) -> Result<f64> {
    check_abar(abar)?;
    Ok(adhesionless_load_profile(profile, abar) - (2.0 * PI * abar).sqrt())
}

/// E.42b for a profile of many waves: `(lower, upper)`.
pub fn jkr_envelope_profile(profile: &WavyProfile, abar: f64) -> Result<(f64, f64)> {
    check_abar(abar)?;
    Ok(jkr_envelope_of(envelope_halfwidth_profile(profile, abar), abar))
}

/// The M-DMT strip end `cbar`: the first root of E.43b,
/// `f(c) = lambda c^2/2 + 2 lambda sum_j alpha_j sin^2(pi c/beta_j) - 1`. Below
/// `c_lo = sqrt(2 (1 - 2 lambda sum_j alpha_j)/lambda)` (0 when `2 lambda sum_j alpha_j >= 1`)
/// `f < 0` (`sin^2 <= 1`). For one wave, at the first crest `beta (k + 1/2) >= c_lo`
/// `f >= 0`: the root lies within one wave period after `c_lo`; for any profile it lies
/// below `sqrt(2/lambda)`, where the cylinder alone gives `f >= 0`. Scanned from `c_lo`
/// in steps of `beta_min/16` (the finest wavelength), every sampled local maximum
/// refined (`roots::first_crossing`), then Brent.
pub fn mdmt_strip_end(params: Params) -> Result<f64> {
    let lambda = params.lambda;
    let waves = params.profile.waves();
    let f = |c: f64| {
        let w = waves.iter().fold(0.0, |acc, w| {
            let s = (PI * c / w.beta()).sin();
            acc + 2.0 * w.alpha() * lambda * s * s
        });
        lambda * c * c / 2.0 + w - 1.0
    };
    let total_alpha: f64 = waves.iter().map(|w| w.alpha()).sum();
    let rest = 1.0 - 2.0 * total_alpha * lambda;
    // a little below c_lo, where f < 0 with room for the rounding of f and of c_lo
    let mut lo = if rest > 0.0 { (2.0 * rest / lambda).sqrt() * (1.0 - 1e-9) } else { 0.0 };
    let mut flo = f(lo);
    while !(flo < 0.0) && lo > 0.0 {
        lo = if lo > 1e-300 { lo * 0.5 } else { 0.0 };
        flo = f(lo);
    }
    let beta_min = params.profile.scan_wavelength();
    let beta_max = params.profile.coarsest_wavelength().unwrap_or(if beta_min.is_finite() { beta_min } else { 0.0 });
    let cylinder_root = (2.0 / lambda).sqrt();
    let step = if beta_min.is_finite() { beta_min / 16.0 } else { cylinder_root / 16.0 };
    // one wave: the crest after c_lo plus a step, f >= 0 there, up to rounding; any
    // profile: the cylinder's root sqrt(2/lambda) plus a step
    let limit = (lo + 2.0 * beta_max).max(cylinder_root) + step;
    let never = |c: f64| Ok::<f64, std::convert::Infallible>(f(c));
    match first_crossing(never, None, (lo, flo), |c| c + step, limit, 1e-12) {
        Ok(Some((a, b, fa, fb))) => brent(f, a, b, fa, fb),
        _ => Err(Error::NoStripEnd { model: "M-DMT, E.43b, c", limit }),
    }
}

/// E.43c: the rigid pull-off load `L'_p = 2 lambda cbar`.
pub fn mdmt_pull_off(params: Params) -> Result<f64> {
    Ok(2.0 * params.lambda * mdmt_strip_end(params)?)
}

/// E.43a.
pub fn mdmt_load(params: Params, abar: f64) -> Result<f64> {
    check_abar(abar)?;
    Ok(adhesionless_load_profile(&params.profile, abar) - mdmt_pull_off(params)?)
}

/// E.43d: `(lower, upper)`.
pub fn mdmt_envelope(params: Params, abar: f64) -> Result<(f64, f64)> {
    check_abar(abar)?;
    let base = PI * abar * abar / 4.0 - mdmt_pull_off(params)?;
    let h = envelope_halfwidth_profile(&params.profile, abar);
    Ok((base - h, base + h))
}

/// E.44: smooth M-DMT load `pi a^2/4 - 2 sqrt(2 lambda)`.
pub fn smooth_mdmt_load(lambda: f64, abar: f64) -> Result<f64> {
    check_abar(abar)?;
    finite(lambda, "lambda")?;
    Interval::above(0.0).check("lambda", lambda)?;
    Ok(PI * abar * abar / 4.0 - 2.0 * (2.0 * lambda).sqrt())
}

/// Eq. 17: the smooth Maugis load at the same `lambda` `+/-` the envelope
/// half-width: `(lower, upper)`.
pub fn local_envelope(params: Params, abar: f64) -> Result<(f64, f64)> {
    check_abar(abar)?;
    let l = load_at(params.smooth(), abar)?;
    let h = envelope_halfwidth_profile(&params.profile, abar);
    Ok((l - h, l + h))
}

/// The Appendix E limits at one contact size: JKR (E.42a) and its envelope
/// (E.42b) at the roughness, M-DMT (E.43a) and its envelope (E.43d) at the
/// parameters' `lambda`. Envelopes are `(lower, upper)`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AppendixE {
    /// E.42a.
    pub jkr: f64,
    /// E.42b.
    pub jkr_envelope: (f64, f64),
    /// E.43a.
    pub mdmt: f64,
    /// E.43d.
    pub mdmt_envelope: (f64, f64),
}

/// [`AppendixE`] at `abar > 0`.
pub fn appendix_e(params: Params, abar: f64) -> Result<AppendixE> {
    Ok(AppendixE {
        jkr: jkr_load_profile(&params.profile, abar)?,
        jkr_envelope: jkr_envelope_profile(&params.profile, abar)?,
        mdmt: mdmt_load(params, abar)?,
        mdmt_envelope: mdmt_envelope(params, abar)?,
    })
}

/// One row of the limits table at `abar`: [`AppendixE`], the smooth M-DMT
/// load (E.44) and the local envelope (Eq. 17, a smooth-model solve). Field
/// names are the JSON keys and, in this order, the CSV columns.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct LimitRow {
    /// Contact half-width.
    pub abar: f64,
    /// E.42a.
    pub jkr: f64,
    /// E.42b, lower.
    pub jkr_env_lower: f64,
    /// E.42b, upper.
    pub jkr_env_upper: f64,
    /// E.43a.
    pub mdmt: f64,
    /// E.43d, lower.
    pub mdmt_env_lower: f64,
    /// E.43d, upper.
    pub mdmt_env_upper: f64,
    /// E.44.
    pub smooth_mdmt: f64,
    /// Eq. 17, lower.
    pub local_env_lower: f64,
    /// Eq. 17, upper.
    pub local_env_upper: f64,
}

impl LimitRow {
    /// The column names, in the order of [`LimitRow::values`].
    pub const COLUMNS: [&'static str; 10] = [
        "abar",
        "jkr",
        "jkr_env_lower",
        "jkr_env_upper",
        "mdmt",
        "mdmt_env_lower",
        "mdmt_env_upper",
        "smooth_mdmt",
        "local_env_lower",
        "local_env_upper",
    ];

    /// The row at `abar > 0`.
    pub fn new(params: Params, abar: f64) -> Result<LimitRow> {
        let e = appendix_e(params, abar)?;
        let (local_env_lower, local_env_upper) = local_envelope(params, abar)?;
        Ok(LimitRow {
            abar,
            jkr: e.jkr,
            jkr_env_lower: e.jkr_envelope.0,
            jkr_env_upper: e.jkr_envelope.1,
            mdmt: e.mdmt,
            mdmt_env_lower: e.mdmt_envelope.0,
            mdmt_env_upper: e.mdmt_envelope.1,
            smooth_mdmt: smooth_mdmt_load(params.lambda, abar)?,
            local_env_lower,
            local_env_upper,
        })
    }

    /// The values in the order of [`LimitRow::COLUMNS`].
    pub fn values(&self) -> [f64; 10] {
        [
            self.abar,
            self.jkr,
            self.jkr_env_lower,
            self.jkr_env_upper,
            self.mdmt,
            self.mdmt_env_lower,
            self.mdmt_env_upper,
            self.smooth_mdmt,
            self.local_env_lower,
            self.local_env_upper,
        ]
    }
}

/// Largest grid of [`limit_rows`] and [`appendix_e_rows`].
pub const MAX_LIMIT_POINTS: usize = 10_000_000;

/// `f` at `abar_i = amax i/points`, `i = 1..=points` (in parallel with the
/// `parallel` feature). Errors: `points` outside `[1, MAX_LIMIT_POINTS]`
/// ([`At::Input`]), or the first failure met with its `abar` ([`At::Limits`]).
fn on_grid<T: Send>(amax: f64, points: usize, f: impl Fn(f64) -> Result<T> + Sync + Send) -> std::result::Result<Vec<T>, LocatedError> {
    if !(1..=MAX_LIMIT_POINTS).contains(&points) {
        let value = i64::try_from(points).unwrap_or(i64::MAX);
        return Err(At::Input.wrap(Error::IntegerOutOfRange { arg: "points", value, min: 1, max: MAX_LIMIT_POINTS as i64 }));
    }
    let at = |i: usize| {
        let abar = amax * i as f64 / points as f64;
        f(abar).map_err(|e| At::Limits { abar }.wrap(e))
    };
    #[cfg(feature = "parallel")]
    let out = (1..=points).into_par_iter().map(at).collect();
    #[cfg(not(feature = "parallel"))]
    let out = (1..=points).map(at).collect();
    out
}

/// The table of `maugis limits`: a [`LimitRow`] at each `abar_i = amax i/points`.
pub fn limit_rows(params: Params, amax: f64, points: usize) -> std::result::Result<Vec<LimitRow>, LocatedError> {
    on_grid(amax, points, |abar| LimitRow::new(params, abar))
}

/// [`AppendixE`] at each `abar_i = amax i/points`, with its `abar`.
pub fn appendix_e_rows(params: Params, amax: f64, points: usize) -> std::result::Result<Vec<(f64, AppendixE)>, LocatedError> {
    on_grid(amax, points, |abar| Ok((abar, appendix_e(params, abar)?)))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The M-DMT strip end is the first root of E.43b: `f(c) = 0` to rounding and
    /// `f < 0` on a grid of `beta/1024` before it, over lambda from 1e-3 to 1e4,
    /// alpha from 0 to 3 and beta from 1e-3 to 10 (the scan starts at `c_lo`, within a
    /// wave period of the root, so tiny beta costs no more steps).
    #[test]
    fn mdmt_strip_end_is_the_first_root() {
        let mut checked = 0;
        for &lambda in &[1e-3, 0.05, 0.3, 1.0, 4.0, 30.0, 1e4] {
            for &alpha in &[0.0, 0.01, 0.2, 0.7, 1.5, 3.0] {
                for &beta in &[1e-3, 0.05, 0.4, 1.125, 3.0, 10.0] {
                    let p = Params::new(lambda, alpha, beta).unwrap();
                    let c = mdmt_strip_end(p).unwrap();
                    let f = |c: f64| {
                        let s = (PI * c / beta).sin();
                        lambda * c * c / 2.0 + 2.0 * alpha * lambda * s * s - 1.0
                    };
                    assert!(f(c).abs() < 1e-9 * (1.0 + lambda * c * c + alpha * lambda), "lambda {lambda} alpha {alpha} beta {beta}: f({c}) = {:e}", f(c));
                    let step = beta / 1024.0;
                    let samples = ((c / step) as usize).min(2_000_000);
                    for i in 1..samples.saturating_sub(1) {
                        let t = c * i as f64 / samples as f64;
                        assert!(f(t) < 0.0, "lambda {lambda} alpha {alpha} beta {beta}: f({t}) = {:e} >= 0 before the root {c}", f(t));
                    }
                    checked += 1;
                }
            }
        }
        assert_eq!(checked, 7 * 6 * 6);
    }

    #[test]
    fn smooth_mdmt_pull_off_is_2_sqrt_2_lambda() {
        for lambda in [0.02, 0.1, 1.0] {
            let p = Params::new(lambda, 0.0, 1.0).unwrap();
            let lp = mdmt_pull_off(p).unwrap();
            assert!((lp - 2.0 * (2.0 * lambda).sqrt()).abs() < 1e-12, "{lp}");
            let a = 1.7;
            assert!((mdmt_load(p, a).unwrap() - smooth_mdmt_load(lambda, a).unwrap()).abs() < 1e-12);
        }
    }

    #[test]
    fn envelopes_bracket_the_limits_for_large_a() {
        let (alpha, beta) = (2f64.sqrt() / 4.0, 1.125);
        for a in [3.0, 4.5, 6.0] {
            let l = jkr_load(alpha, beta, a).unwrap();
            let (lo, hi) = jkr_envelope(alpha, beta, a).unwrap();
            assert!(l >= lo - 0.5 && l <= hi + 0.5, "a={a}: {lo} <= {l} <= {hi}");
        }
    }

    #[test]
    fn rows_hold_the_single_limits_on_the_grid() {
        let p = Params::new(0.5, 2f64.sqrt() / 4.0, 1.125).unwrap();
        let rows = limit_rows(p, 3.0, 7).unwrap();
        let e = appendix_e_rows(p, 3.0, 7).unwrap();
        assert_eq!(rows.len(), 7);
        for (r, (abar, a)) in rows.iter().zip(&e) {
            assert_eq!(r.abar, *abar);
            assert_eq!(r.jkr, jkr_load(p.alpha(), p.beta(), r.abar).unwrap());
            assert_eq!((r.mdmt_env_lower, r.mdmt_env_upper), mdmt_envelope(p, r.abar).unwrap());
            assert_eq!((r.local_env_lower, r.local_env_upper), local_envelope(p, r.abar).unwrap());
            assert_eq!((a.jkr, a.jkr_envelope, a.mdmt, a.mdmt_envelope), (r.jkr, (r.jkr_env_lower, r.jkr_env_upper), r.mdmt, (r.mdmt_env_lower, r.mdmt_env_upper)));
            assert_eq!(r.values()[0], r.abar);
        }
        assert_eq!(rows[6].abar, 3.0);
        assert!(matches!(limit_rows(p, 3.0, 0), Err(LocatedError { at: At::Input, .. })));
        match limit_rows(p, f64::NAN, 3) {
            Err(e @ LocatedError { at: At::Limits { .. }, .. }) => assert!(e.to_string().starts_with("limits at abar = NaN: "), "{e}"),
            other => panic!("{other:?}"),
        }
    }
}
