//! The degenerate (logarithmic) 1-z formula: `c - a - b` an integer.
//!
//! # Method
//!
//! * **Degenerate 1-z formula** (`s = m` an integer): the Gamma poles of the two
//!   pieces cancel and the limit has logarithms [DLMF 15.8.10, A&S 15.3.10-11].
//!   For `m >= 0`, with `u = 1 - z`,
//!   `2F1(a, b; a+b+m; z) = Gamma(m) Gamma(c) / (Gamma(a+m) Gamma(b+m)) sum_{n<m} (a)_n (b)_n / (n! (1-m)_n) u^n`
//!   `  - (-u)^m Gamma(c) / (Gamma(a) Gamma(b)) sum_n (a+m)_n (b+m)_n / (n! (n+m)!) u^n`
//!   `    * [ln u - psi(n+1) - psi(n+m+1) + psi(a+m+n) + psi(b+m+n)]`
//!   (the first sum is absent for `m = 0`). For `m < 0` Euler's transformation
//!   `2F1(a, b; c; z) = u^{c-a-b} 2F1(c-a, c-b; c; z)` [DLMF 15.8.1] maps to
//!   `-m > 0` (this is A&S 15.3.12). The digamma values start from MPFR's
//!   correctly rounded `psi` at exact points and are advanced with
//!   `psi(x+1) = psi(x) + 1/x` in balls. If `c - a` or `c - b` is a non-positive
//!   integer, Euler's transformation makes the function `u^s` times a polynomial
//!   ([`Algorithm::Euler`]); together with the terminating case this
//!   removes every sub-case in which the digamma arguments could hit a pole.
//!
//! # Error bound
//!
//! * **Logarithmic series**: summed in ball arithmetic. Tail: the coefficient
//!   ratio is bounded as above (pairs `(a+m, m+1)`, `(b+m, 1)` or swapped), and for
//!   `n >= N` the bracket is at most `|ln u| + |A-1| psi'(x1) + |B-m-1| psi'(x2)`
//!   by the mean value theorem, with `psi'(x) <= 1/x + 1/x^2` and `x1, x2` the
//!   smallest arguments at `n = N`.

use rug::float::Round;
use rug::Float;

use super::series::{abs_upper_precise, first_positive_index, negligible, negligible_scaled, ratio_bound, rounded_inside_unit, TailFactor};
use super::{one, MAX_LOG_M, MIN_SERIES_PREC};
use crate::ball::{Ball, Scaled, MAG_PREC};
use crate::error::{Error, Interval, Result};
use crate::special::gamma::{gamma_ratio_scaled, int_float, mag_abs, mag_add, mag_div, mag_inf, mag_min, mag_mul, xball};
use crate::special::pfq::MAX_SERIES_TERMS;
use crate::special::{exact_add, exact_sub, is_nonpositive_integer};

/// [`Algorithm::ConnectionLog`]: the logarithmic 1-z formula for exact
/// `0 < z < 1`, `c - a - b` an integer (none of `a, b, c-a, c-b` a non-positive integer).
pub(crate) fn hyp2f1_connection_log(a: &Float, b: &Float, c: &Float, z: &Float, wp: u32) -> Result<Ball> {
    if !(*z > 0 && *z < 1) {
        return Err(Error::precondition("logarithmic 1-z formula needs 0 < z < 1"));
    }
    let u = xball(&exact_sub(&one(), z), wp);
    log_core(a, b, c, &u, wp)
}

/// The logarithmic 1-x formula at the ball `u = 1 - x`, `0 < u < 1`.
pub(super) fn log_core(a: &Float, b: &Float, c: &Float, u: &Ball, wp: u32) -> Result<Ball> {
    // `u` at `wp` bits where it stays in (0, 1): `ln u` and every term multiply
    // by it (a decimal `z` tightened to 58 000 bits, issue 37's scan)
    let rounded = rounded_inside_unit(u, wp);
    let u = rounded.as_ref().unwrap_or(u);
    let ca = exact_sub(c, a);
    let cb = exact_sub(c, b);
    let s = exact_sub(&ca, b);
    if !s.is_integer() {
        return Err(Error::precondition("logarithmic 1-z formula needs c - a - b an integer"));
    }
    if [a, b, &ca, &cb].iter().any(|x| is_nonpositive_integer(x)) {
        return Err(Error::precondition("logarithmic 1-z formula needs none of a, b, c-a, c-b a non-positive integer"));
    }
    let mf = s.to_f64();
    if mf.abs() > MAX_LOG_M as f64 {
        return Err(Error::OutOfRange { arg: "|c - a - b| (2F1)", value: mf.abs(), allowed: Interval::closed(0.0, MAX_LOG_M as f64) });
    }
    let m = mf.abs() as u64;
    if mf >= 0.0 {
        log_formula(a, b, c, &ca, &cb, m, u, wp)
    } else {
        // Euler: 2F1(a,b;c;z) = u^{-m} 2F1(c-a, c-b; c; z), with c - (c-a) - (c-b) = m.
        let f = log_formula(&ca, &cb, c, a, b, m, u, wp)?;
        Ok(f.div(&u.pow_u64(m))?)
    }
}

/// `2F1(a, b; a+b+m; 1-u)` for an integer `m >= 0` [A&S 15.3.10-11]; `ca = c-a`, `cb = c-b`.
#[allow(clippy::too_many_arguments)]
pub(super) fn log_formula(a: &Float, b: &Float, c: &Float, ca: &Float, cb: &Float, m: u64, u: &Ball, wp: u32) -> Result<Ball> {
    // the Gamma ratios in logarithms where they pass the exponent range, each
    // term formed once (`Scaled`)
    let mut terms = Vec::with_capacity(2);
    if m >= 1 {
        let g = gamma_ratio_scaled(&[c], &[ca, cb], wp)?;
        if !g.is_exact_zero() {
            let gm = Ball::factorial((m - 1) as u32, wp); // Gamma(m)
            terms.push(g.mul_ball(&gm).mul_ball(&finite_sum(a, b, m, u, wp)?));
        }
    }
    let g2 = gamma_ratio_scaled(&[c], &[a, b], wp)?;
    if !g2.is_exact_zero() {
        let am = exact_add(a, &int_float(m));
        let bm = exact_add(b, &int_float(m));
        let part = g2.mul_ball(&u.pow_u64(m)).mul_ball(&log_series(&am, &bm, m, u, wp)?);
        // -(-u)^m = (-1)^{m+1} u^m
        terms.push(if m % 2 == 0 { part.neg() } else { part });
    }
    if terms.is_empty() {
        return Ok(Ball::zero(wp));
    }
    Scaled::sum_to_ball(&terms, wp)
}

/// `sum_{n<m} (a)_n (b)_n / (n! (1-m)_n) u^n`.
pub(super) fn finite_sum(a: &Float, b: &Float, m: u64, u: &Ball, wp: u32) -> Result<Ball> {
    let (ab, bb) = (xball(a, wp), xball(b, wp));
    let mut t = Ball::one(wp);
    let mut s = Ball::one(wp);
    for n in 0..m.saturating_sub(1) {
        let ni = n as i64;
        let den = Ball::from_i64((ni + 1) * (ni + 1 - m as i64), wp);
        t = t.mul(&ab.add_i64(ni)).mul(&bb.add_i64(ni)).mul(u).div(&den)?;
        s = s.add(&t);
        if (n + 1) % crate::budget::TERMS_BETWEEN_CHECKS == 0 {
            // `m` up to MAX_LOG_M terms: `2F1(100000, 1; 23.07; -4.75e7327)` at 6
            // bits ran 1.5 s of CPU here before the next check (issue 37's scan, seed 2)
            crate::budget::check_elapsed("2F1 logarithmic case, finite sum", 0.0, crate::error::Reached::Terms { count: n + 1 })?;
        }
    }
    Ok(s)
}

/// Upper bound of `psi'(x) <= 1/x + 1/x^2` at a lower bound `x > 0`.
pub(super) fn trigamma_up(x_lo: &Float) -> Float {
    if *x_lo <= 0 {
        return mag_inf();
    }
    let inv = mag_div(&Float::with_val(MAG_PREC, 1), x_lo);
    mag_add(&inv, &mag_mul(&inv, &inv))
}

/// For `n >= N`: bound on `|ln u - psi(n+1) - psi(n+m+1) + psi(A+n) + psi(B+n)|`.
pub(super) fn log_bracket_bound(aa: &Float, bb: &Float, m: u64, n: u64, lnu_abs: &Float) -> Float {
    let lo = |p: &Float| Float::with_val_round(MAG_PREC, p + n, Round::Down).0;
    let n1 = Float::with_val_round(MAG_PREC, n + 1, Round::Down).0;
    let nm1 = Float::with_val_round(MAG_PREC, n + m + 1, Round::Down).0;
    let dist = |p: &Float, q: u64| mag_abs(&exact_sub(p, &int_float(q)));
    let term = |p: &Float, q: u64, qn: &Float| {
        let x = mag_min(lo(p), qn.clone());
        mag_mul(&dist(p, q), &trigamma_up(&x))
    };
    let opt1 = mag_add(&term(aa, 1, &n1), &term(bb, m + 1, &nm1));
    let opt2 = mag_add(&term(bb, 1, &n1), &term(aa, m + 1, &nm1));
    mag_add(lnu_abs, &mag_min(opt1, opt2))
}

/// `L = sum_n (A)_n (B)_n / (n! (n+m)!) u^n [ln u - psi(n+1) - psi(n+m+1) + psi(A+n) + psi(B+n)]`
/// in ball arithmetic with the tail bound of the module docs (`A`, `B` not
/// non-positive integers, `0 < u < 1`).
pub(super) fn log_series(aa: &Float, bb: &Float, m: u64, u: &Ball, wp: u32) -> Result<Ball> {
    let wp = wp.max(MIN_SERIES_PREC);
    let lnu = u.ln()?;
    let m32 = u32::try_from(m).map_err(|_| Error::IntegerOutOfRange { arg: "c - a - b", value: i64::try_from(m).unwrap_or(i64::MAX), min: 0, max: u32::MAX as i64 })?;
    let mut tau = Ball::factorial(m32, wp).recip()?;
    let mut psi1 = Ball::from_i64(1, wp).digamma()?;
    let mut psim = Ball::from_i64(m as i64 + 1, wp).digamma()?;
    let (ab, bbb) = (xball(aa, wp), xball(bb, wp));
    // MPFR's digamma at the parameters' own length (an exact difference of a decimal
    // tightened to 65 536 bits and z = -2e7765: 49 s, issue 37's scan) computes
    // Bernoulli numbers as Gamma does: refused at once when that estimate passes the
    // installed budget (not yet rounded into a ball: psi over a ball needs a bound)
    let psi_bits = ab.prec().max(bbb.prec());
    crate::budget::check_estimate("2F1 logarithmic case (digamma at the parameters' length)", crate::special::gamma::gamma_seconds(psi_bits), f64::INFINITY)?;
    let mut psia = ab.digamma()?;
    let mut psib = bbb.digamma()?;
    let mut sum = tau.mul(&lnu.sub(&psi1).sub(&psim).add(&psia).add(&psib));
    let mut abs_sum = sum.abs_upper();
    let n_pos = first_positive_index(&[aa, bb])?;
    let lnu_abs = lnu.abs_upper();
    let proxy = mag_add(&lnu_abs, &Float::with_val(MAG_PREC, 1));
    let rho_prec = wp + 16;
    let u_abs = abs_upper_precise(u, rho_prec);
    let q1 = int_float(m + 1);
    let mut tail_factor = TailFactor::new();
    let mut n: u64 = 0;
    loop {
        let ni = n as i64;
        let an = ab.add_i64(ni);
        let bn = bbb.add_i64(ni);
        let den = Ball::from_i64((ni + 1) * (ni + m as i64 + 1), wp);
        tau = tau.mul(&an).mul(&bn).mul(u).div(&den)?;
        psi1 = psi1.add(&Ball::from_ratio(1, ni + 1, wp));
        psim = psim.add(&Ball::from_ratio(1, ni + m as i64 + 1, wp));
        psia = psia.add(&an.recip()?);
        psib = psib.add(&bn.recip()?);
        n += 1;
        if n >= n_pos {
            let tau_up = tau.abs_upper();
            let proxy_term = mag_mul(&tau_up, &proxy);
            if negligible(&proxy_term, sum.mid(), &abs_sum, wp) {
                let factor = tail_factor.get(n, || ratio_bound(aa, bb, &q1, &one(), &u_abs, n, rho_prec));
                if let Some(factor) = factor {
                    if negligible_scaled(&proxy_term, factor, sum.mid(), &abs_sum, wp) {
                        let h = log_bracket_bound(aa, bb, m, n, &lnu_abs);
                        let tail = mag_mul(&mag_mul(&tau_up, &h), factor);
                        if tail.is_finite() {
                            sum.add_error(&tail);
                            return Ok(sum);
                        }
                    }
                }
            }
        }
        let term = tau.mul(&lnu.sub(&psi1).sub(&psim).add(&psia).add(&psib));
        abs_sum = mag_add(&abs_sum, &term.abs_upper());
        sum = sum.add(&term);
        if !sum.is_finite() {
            return Err(Error::Overflow { what: "hyp2f1 logarithmic series".into() });
        }
        if n > MAX_SERIES_TERMS {
            return Err(Error::NoConvergence { function: "hyp2f1 (logarithmic series)", terms: n });
        }
        if n % crate::budget::TERMS_BETWEEN_CHECKS == 0 {
            // the installed time budget (crate::budget): with c = 2e32632 the terms
            // grew for 13 s before the sum overflowed (issue 37's scan)
            crate::budget::check_elapsed("2F1 logarithmic series, term by term", 0.0, crate::error::Reached::Terms { count: n })?;
        }
    }
}
