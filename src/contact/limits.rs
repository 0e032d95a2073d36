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

use std::f64::consts::PI;

use crate::contact::curve::load_at;
use crate::contact::model::{brent, Params};
use crate::error::{finite, Error, Result};
use crate::special::bessel_j::bessel_j_sequence;

fn check_abar(abar: f64) -> Result<()> {
    finite(abar, "abar")?;
    if abar <= 0.0 {
        return Err(Error::Domain { what: format!("abar must be > 0 (got {abar})") });
    }
    Ok(())
}

/// The adhesionless wavy load `pi a^2/4 + (pi^2 alpha a/beta) J1(2 pi a/beta)`.
pub fn adhesionless_load(alpha: f64, beta: f64, abar: f64) -> f64 {
    let d = 2.0 * PI * abar / beta;
    let j1 = bessel_j_sequence(1, d).get(1).copied().unwrap_or(0.0);
    PI * abar * abar / 4.0 + PI * PI * alpha * abar / beta * j1
}

/// The envelope half-width `pi sqrt(alpha^2/beta) sqrt(a)`.
pub fn envelope_halfwidth(alpha: f64, beta: f64, abar: f64) -> f64 {
    PI * (alpha * alpha / beta).sqrt() * abar.sqrt()
}

/// E.42a.
pub fn jkr_load(alpha: f64, beta: f64, abar: f64) -> Result<f64> {
    check_abar(abar)?;
    Ok(adhesionless_load(alpha, beta, abar) - (2.0 * PI * abar).sqrt())
}

/// E.42b: `(lower, upper)`.
pub fn jkr_envelope(alpha: f64, beta: f64, abar: f64) -> Result<(f64, f64)> {
    check_abar(abar)?;
    let base = PI * abar * abar / 4.0 - (2.0 * PI * abar).sqrt();
    let h = envelope_halfwidth(alpha, beta, abar);
    Ok((base - h, base + h))
}

/// The M-DMT strip end `cbar`: the first root of E.43b, found by scanning
/// outward from 0 in steps of at most `beta/16` and refining with Brent.
pub fn mdmt_strip_end(params: Params) -> Result<f64> {
    let Params { lambda, alpha, beta } = params;
    let f = |c: f64| {
        let s = (PI * c / beta).sin();
        lambda * c * c / 2.0 + 2.0 * alpha * lambda * s * s - 1.0
    };
    let step = (beta / 16.0).min(0.05);
    let (mut lo, mut flo) = (0.0, -1.0);
    let mut c = step;
    while c < 1e6 {
        let fc = f(c);
        if fc >= 0.0 {
            return brent(f, lo, c, flo, fc);
        }
        lo = c;
        flo = fc;
        c += step.max(c * 1e-3);
    }
    Err(Error::Domain { what: "no M-DMT strip end (E.43b) below c = 1e6: lambda too small".into() })
}

/// E.43c: the rigid pull-off load `L'_p = 2 lambda cbar`.
pub fn mdmt_pull_off(params: Params) -> Result<f64> {
    Ok(2.0 * params.lambda * mdmt_strip_end(params)?)
}

/// E.43a.
pub fn mdmt_load(params: Params, abar: f64) -> Result<f64> {
    check_abar(abar)?;
    Ok(adhesionless_load(params.alpha, params.beta, abar) - mdmt_pull_off(params)?)
}

/// E.43d: `(lower, upper)`.
pub fn mdmt_envelope(params: Params, abar: f64) -> Result<(f64, f64)> {
    check_abar(abar)?;
    let base = PI * abar * abar / 4.0 - mdmt_pull_off(params)?;
    let h = envelope_halfwidth(params.alpha, params.beta, abar);
    Ok((base - h, base + h))
}

/// E.44: smooth M-DMT load `pi a^2/4 - 2 sqrt(2 lambda)`.
pub fn smooth_mdmt_load(lambda: f64, abar: f64) -> Result<f64> {
    check_abar(abar)?;
    finite(lambda, "lambda")?;
    if lambda <= 0.0 {
        return Err(Error::Domain { what: "lambda must be > 0".into() });
    }
    Ok(PI * abar * abar / 4.0 - 2.0 * (2.0 * lambda).sqrt())
}

/// Eq. 17: the smooth Maugis load at the same `lambda` `+/-` the envelope
/// half-width: `(lower, upper)`.
pub fn local_envelope(params: Params, abar: f64) -> Result<(f64, f64)> {
    check_abar(abar)?;
    let smooth = Params::new(params.lambda, 0.0, params.beta)?;
    let l = load_at(smooth, abar)?;
    let h = envelope_halfwidth(params.alpha, params.beta, abar);
    Ok((l - h, l + h))
}

#[cfg(test)]
mod tests {
    use super::*;

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
}
