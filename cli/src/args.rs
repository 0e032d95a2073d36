//! Value parsers shared by the `curve`, `profile` and `limits` subcommands.
//!
//! Every numeric flag is checked while the command line is parsed, so a bad value
//! is a clap usage error (exit code 2, one line on stderr) raised before anything
//! is computed or written. Numbers are arithmetic expressions, parsed by the
//! `meval` crate: decimals (`0.125`, `1e-1`), fractions (`1/10`, `9/8`), `pi`,
//! `e`, `sqrt(2)/3`, `2*sqrt(2)/8`, powers (`2^-3`) and the usual functions.

/// The paper's Fig. 4c amplitude `alpha = 2 sqrt(2)/8`.
pub const FIG4C_ALPHA: f64 = std::f64::consts::SQRT_2 / 4.0;
/// The paper's Fig. 4c wavelength `beta = 9/8`.
pub const FIG4C_BETA: f64 = 1.125;
/// Upper bound on `--points` (keeps a typo from running for hours).
pub const MAX_POINTS: usize = 1_000_000;

/// Largest contact half-width `abar` / `amax` accepted (the solver's cost grows
/// linearly with it; the paper's range is `abar <= 6`).
pub const MAX_ABAR: f64 = 1.0e4;
/// Largest wave argument `2 pi abar/beta` accepted when `alpha > 0` (the wave
/// term's Bessel series needs about that many terms per state).
pub const MAX_WAVE_ARG: f64 = 1.0e5;

/// Checks the size of the problem before any work: `abar <= MAX_ABAR`
/// and, with waviness, `2 pi abar/beta <= MAX_WAVE_ARG`. `flag` names the option.
pub fn check_size(flag: &str, abar: f64, alpha: f64, beta: f64) -> Result<(), String> {
    if abar > MAX_ABAR {
        return Err(format!("{flag} must be <= {} (got {})", num(MAX_ABAR), num(abar)));
    }
    let d = 2.0 * std::f64::consts::PI * abar / beta;
    if alpha > 0.0 && d > MAX_WAVE_ARG {
        let name = flag.trim_start_matches('-');
        return Err(format!(
            "2 pi {name}/beta = {} exceeds {}: the wave series would take too long; reduce {flag} or increase --beta",
            num(d),
            num(MAX_WAVE_ARG)
        ));
    }
    Ok(())
}

/// Checks the model parameters against the library's ranges, naming the flag.
pub fn check_params(lambdas: &[f64], alpha: f64, beta: f64) -> Result<(), String> {
    use maugis::contact::model::{ALPHA_MAX, BETA_RANGE, LAMBDA_RANGE};
    for &l in lambdas {
        if !(LAMBDA_RANGE.0..=LAMBDA_RANGE.1).contains(&l) {
            return Err(format!("--lambda must lie in [{}, {}] (got {})", num(LAMBDA_RANGE.0), num(LAMBDA_RANGE.1), num(l)));
        }
    }
    if !(0.0..=ALPHA_MAX).contains(&alpha) {
        return Err(format!("--alpha must lie in [0, {}] (got {})", num(ALPHA_MAX), num(alpha)));
    }
    if !(BETA_RANGE.0..=BETA_RANGE.1).contains(&beta) {
        return Err(format!("--beta must lie in [{}, {}] (got {})", num(BETA_RANGE.0), num(BETA_RANGE.1), num(beta)));
    }
    Ok(())
}

/// `x` for messages: plain for ordinary magnitudes, scientific otherwise.
pub fn num(x: f64) -> String {
    if x != 0.0 && x.is_finite() && (x.abs() >= 1e6 || x.abs() < 1e-4) {
        format!("{x:e}")
    } else {
        format!("{x}")
    }
}

/// A finite number given as an arithmetic expression (`sqrt(2)/3`, `9/8`, `pi/4`).
pub fn number(s: &str) -> Result<f64, String> {
    let t = s.trim();
    if t.is_empty() {
        return Err("empty value: give a number or an expression like sqrt(2)/3".into());
    }
    let v = meval::eval_str(t).map_err(|e| format!("'{s}' is not a number or an arithmetic expression ({e})"))?;
    if !v.is_finite() {
        return Err(format!("'{s}' must be a finite number (not NaN or infinity)"));
    }
    Ok(v)
}

/// Any finite number.
pub fn finite(s: &str) -> Result<f64, String> {
    number(s)
}

/// A finite number `> 0`.
pub fn positive(s: &str) -> Result<f64, String> {
    let v = number(s)?;
    if v > 0.0 {
        Ok(v)
    } else {
        Err(format!("must be > 0 (got {})", num(v)))
    }
}

/// A finite number `>= 0`.
pub fn non_negative(s: &str) -> Result<f64, String> {
    let v = number(s)?;
    if v >= 0.0 {
        Ok(v)
    } else {
        Err(format!("must be >= 0 (got {})", num(v)))
    }
}

/// A grid size in `2..=MAX_POINTS`.
pub fn grid_points(s: &str) -> Result<usize, String> {
    let n: usize = s.trim().parse().map_err(|_| format!("'{s}' is not a whole number"))?;
    if n < 2 {
        return Err(format!("must be >= 2 (got {n})"));
    }
    if n > MAX_POINTS {
        return Err(format!("must be <= {MAX_POINTS} (got {n})"));
    }
    Ok(n)
}

/// `x` with a few significant digits, trimmed (`0.353553`, `1.125`, `6`).
pub fn short(x: f64) -> String {
    let s = format!("{x:.6}");
    let s = s.trim_end_matches('0').trim_end_matches('.');
    if s == "-0" {
        "0".into()
    } else {
        s.to_string()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn parsers() {
        assert_eq!(positive("1/10"), Ok(0.1));
        assert_eq!(positive("9/8"), Ok(1.125));
        assert!(positive("0").is_err());
        assert!(positive("NaN").is_err());
        assert!(positive("inf").is_err());
        assert!(positive("1/0").is_err());
        assert!((positive("sqrt(2)/3").unwrap() - 2f64.sqrt() / 3.0).abs() < 1e-16);
        assert_eq!(positive("2*sqrt(2)/8"), Ok(FIG4C_ALPHA));
        assert_eq!(positive("pi/4"), Ok(std::f64::consts::FRAC_PI_4));
        assert_eq!(positive("1e-1"), Ok(0.1));
        assert!(positive("sqrt(-1)").is_err());
        assert!(positive("2 +").is_err());
        assert!(positive("").is_err());
        assert!(non_negative("-1").is_err());
        assert_eq!(non_negative("0"), Ok(0.0));
        assert!(grid_points("1").is_err());
        assert_eq!(grid_points("2"), Ok(2));
        assert_eq!(short(0.1), "0.1");
        assert_eq!(short(6.0), "6");
        assert_eq!(short(FIG4C_ALPHA), "0.353553");
        assert_eq!(num(1e300), "1e300");
        assert_eq!(num(0.25), "0.25");
        assert!(check_size("--amax", 6.0, FIG4C_ALPHA, FIG4C_BETA).is_ok());
        assert!(check_size("--amax", 1e5, 0.0, 1.0).is_err());
        assert!(check_size("--amax", 6.0, 0.3, 1e-5).is_err());
        assert!(check_size("--amax", 6.0, 0.0, 1e-5).is_ok());
    }
}
