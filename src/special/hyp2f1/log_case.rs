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
//!
//! # Over balls
//!
//! For `z < -1` with `a`, `b` exact and `b - a = m` an integer, and `c`, `z` balls
//! ([`hyp2f1_log_case_balls`], the ball path's route where the connection formula
//! needs `Gamma(b - a)` at a pole and Pfaff's `w` is next to 1:
//! `2F1(-140.625, 242.375; 27.07; -1e10556)`, issue 37's scan), Pfaff's inner
//! function `2F1(a, c-b; c; w)` has `c - a - (c - b) = m` at every point of the
//! balls, and the formula above is evaluated in ball arithmetic over them
//! (`a`, `b` exchanged so that `m >= 0`; `c - a`, `c - b` with exact midpoints).
//! What is not ball arithmetic is made valid for every point: `psi` over a
//! pole-free ball is the hull of its values at the ends (`psi' > 0` between poles);
//! the tail's ratio bound takes the upper ends (`max(1, (p+n)/(q+n))` increases
//! with `p`), the first index past the negative parameters the lower ends, and
//! the bracket bound `max |p - q|` over the ends with `psi'` at the lower end; a
//! Gamma of a ball is `gamma_of_ball_scaled` (its `psi` bound). A ball
//! parameter enters the series rounded into its ball at `wp + 16` bits (`c + 1/2`
//! at `c = 1e-19401` is exact at 64 000 bits).

use rug::float::Round;
use rug::Float;

use super::large_param::difference;
use super::series::{abs_upper_precise, first_positive_index, negligible, negligible_scaled, ratio_bound, rounded_inside_unit, TailFactor};
use super::{one, MAX_LOG_M, MIN_SERIES_PREC};
use crate::ball::{Ball, Scaled, MAG_PREC};
use crate::error::{Error, Interval, Result};
use crate::special::gamma::{gamma_of_ball_scaled, gamma_ratio_scaled, int_float, mag_abs, mag_add, mag_div, mag_inf, mag_min, mag_mul, xball};
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
    let [a, b, c, ca, cb] = [a, b, c, ca, cb].map(|x| xball(x, wp));
    log_formula_balls(&a, &b, &c, &ca, &cb, m, u, wp)
}

/// `x + n` with the midpoint's sum exact (an exact `a` stays exact: `a + m`).
fn shift(x: &Ball, n: u64) -> Ball {
    Ball::with_mag(exact_add(x.mid(), &int_float(n)), x.rad_mag())
}

/// `2F1(a, b; c; z)` over balls for `z < -1` with `a`, `b` exact and `b - a` an
/// integer (module docs, "Over balls"): Pfaff [DLMF 15.8.1],
/// `(1-z)^(-a) 2F1(a, c-b; c; w)`, whose inner function has `c - a - (c - b) =
/// b - a = m` and `1 - w = u = 1/(1-z)`: the logarithmic formula at `u`
/// ([`log_formula_balls`]; `a` and `b` exchanged so that `m >= 0`).
pub(super) fn hyp2f1_log_case_balls(a: &Ball, b: &Ball, c: &Ball, z: &Ball, wp: u32) -> Result<Ball> {
    if !(a.is_exact() && b.is_exact() && z.upper() < -1) {
        return Err(Error::precondition("logarithmic case over balls needs exact a, b and z < -1"));
    }
    let d = exact_sub(b.mid(), a.mid());
    if !d.is_integer() {
        return Err(Error::precondition("logarithmic case over balls needs b - a an integer"));
    }
    let (a, b) = if d.is_sign_negative() { (b, a) } else { (a, b) };
    let mf = d.to_f64().abs();
    if mf > MAX_LOG_M as f64 {
        return Err(Error::OutOfRange { arg: "|b - a| (2F1)", value: mf, allowed: Interval::closed(0.0, MAX_LOG_M as f64) });
    }
    let m = mf as u64;
    let omz = Ball::one(wp).sub(z);
    let u = omz.recip()?.at_most_prec(wp);
    let (cb, ca) = (difference(c, b), difference(c, a));
    let inner = log_formula_balls(a, &cb, c, &ca, b, m, &u, wp)?;
    Scaled::pow(&omz, &a.neg(), wp)?.mul_ball(&inner).to_value(wp)
}

/// `Gamma(x) / (Gamma(y1) Gamma(y2))` over balls: [`gamma_ratio_scaled`] at exact
/// points (its pairings of integer differences, its zero at a pole of a
/// denominator), else each Gamma over its ball (`gamma_of_ball_scaled`, a pole
/// inside a ball an error).
fn gamma_ratio_balls(x: &Ball, y1: &Ball, y2: &Ball, wp: u32) -> Result<Scaled> {
    if [x, y1, y2].iter().all(|t| t.is_exact()) {
        return gamma_ratio_scaled(&[x.mid()], &[y1.mid(), y2.mid()], wp);
    }
    gamma_of_ball_scaled(x, wp)?.div(&gamma_of_ball_scaled(y1, wp)?.mul(&gamma_of_ball_scaled(y2, wp)?))
}

/// [`log_formula`] over balls of `a, b, c` (with `c - a - b = m` for every
/// point: the caller forms `ca`, `cb` so; module docs, "Over balls").
#[allow(clippy::too_many_arguments)]
pub(super) fn log_formula_balls(a: &Ball, b: &Ball, c: &Ball, ca: &Ball, cb: &Ball, m: u64, u: &Ball, wp: u32) -> Result<Ball> {
    // the Gamma ratios in logarithms where they pass the exponent range, each
    // term formed once (`Scaled`)
    let mut terms = Vec::with_capacity(2);
    if m >= 1 {
        let g = gamma_ratio_balls(c, ca, cb, wp)?;
        if !g.is_exact_zero() {
            let gm = Ball::factorial((m - 1) as u32, wp); // Gamma(m)
            terms.push(g.mul_ball(&gm).mul_ball(&finite_sum(a, b, m, u, wp)?));
        }
    }
    let g2 = gamma_ratio_balls(c, a, b, wp)?;
    if !g2.is_exact_zero() {
        let (am, bm) = (shift(a, m), shift(b, m));
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
pub(super) fn finite_sum(ab: &Ball, bb: &Ball, m: u64, u: &Ball, wp: u32) -> Result<Ball> {
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

/// For `n >= N`: bound on `|ln u - psi(n+1) - psi(n+m+1) + psi(A+n) + psi(B+n)|`
/// for every `A`, `B` of their balls: `|A - q| <= max` over the ball's ends, and
/// `A + n >=` its lower end plus `n` (`psi'` decreases).
pub(super) fn log_bracket_bound(aa: &Ball, bb: &Ball, m: u64, n: u64, lnu_abs: &Float) -> Float {
    let lo = |p: &Ball| Float::with_val_round(MAG_PREC, p.lower() + n, Round::Down).0;
    let n1 = Float::with_val_round(MAG_PREC, n + 1, Round::Down).0;
    let nm1 = Float::with_val_round(MAG_PREC, n + m + 1, Round::Down).0;
    let dist = |p: &Ball, q: u64| {
        let (d1, d2) = (mag_abs(&exact_sub(&p.lower(), &int_float(q))), mag_abs(&exact_sub(&p.upper(), &int_float(q))));
        if d1 > d2 {
            d1
        } else {
            d2
        }
    };
    let term = |p: &Ball, q: u64, qn: &Float| {
        let x = mag_min(lo(p), qn.clone());
        mag_mul(&dist(p, q), &trigamma_up(&x))
    };
    let opt1 = mag_add(&term(aa, 1, &n1), &term(bb, m + 1, &nm1));
    let opt2 = mag_add(&term(bb, 1, &n1), &term(aa, m + 1, &nm1));
    mag_add(lnu_abs, &mag_min(opt1, opt2))
}

/// `psi` over a ball without a pole: MPFR's correctly rounded value at an exact
/// point; else the hull of `psi` at the two ends (`psi` increases between its
/// poles, `psi' = sum 1/(x+k)^2 > 0`).
fn digamma_ball(x: &Ball, wp: u32) -> Result<Ball> {
    if x.is_exact() {
        return x.digamma();
    }
    if crate::special::pfq::contains_pole(x, None).is_some() {
        return Err(Error::Pole { function: "digamma", at: x.mid().to_f64() });
    }
    let ends = [x.lower(), x.upper()].map(|e| Ball::from_float(&e, wp.max(e.prec())).digamma());
    let [lo, hi] = ends;
    let (lo, hi) = (lo?, hi?);
    Ok(Ball::hull(&lo.lower(), &hi.upper(), wp))
}

/// `L = sum_n (A)_n (B)_n / (n! (n+m)!) u^n [ln u - psi(n+1) - psi(n+m+1) + psi(A+n) + psi(B+n)]`
/// in ball arithmetic with the tail bound of the module docs (`A`, `B` not
/// non-positive integers, `0 < u < 1`).
pub(super) fn log_series(ab: &Ball, bbb: &Ball, m: u64, u: &Ball, wp: u32) -> Result<Ball> {
    let wp = wp.max(MIN_SERIES_PREC);
    // a ball parameter at `wp + 16` bits (an exact one, the point path's, as
    // given): `c + 1/2` at `c = 1e-19401` is exact at 64 000 bits, where MPFR's
    // digamma at the ends would run for seconds (the estimate below refuses it)
    let round = |x: &Ball| if x.is_exact() { x.clone() } else { x.at_most_prec(wp + 16) };
    let (ab, bbb) = (&round(ab), &round(bbb));
    let lnu = u.ln()?;
    let m32 = u32::try_from(m).map_err(|_| Error::IntegerOutOfRange { arg: "c - a - b", value: i64::try_from(m).unwrap_or(i64::MAX), min: 0, max: u32::MAX as i64 })?;
    let mut tau = Ball::factorial(m32, wp).recip()?;
    let mut psi1 = Ball::from_i64(1, wp).digamma()?;
    let mut psim = Ball::from_i64(m as i64 + 1, wp).digamma()?;
    // MPFR's digamma at the parameters' own length (an exact difference of a decimal
    // tightened to 65 536 bits and z = -2e7765: 49 s, issue 37's scan) computes
    // Bernoulli numbers as Gamma does: refused at once when that estimate passes the
    // installed budget (not yet rounded into a ball: psi over a ball needs a bound)
    let psi_bits = ab.prec().max(bbb.prec());
    crate::budget::check_estimate("2F1 logarithmic case (digamma at the parameters' length)", crate::special::gamma::gamma_seconds(psi_bits), f64::INFINITY)?;
    let mut psia = digamma_ball(ab, wp)?;
    let mut psib = digamma_ball(bbb, wp)?;
    let mut sum = tau.mul(&lnu.sub(&psi1).sub(&psim).add(&psia).add(&psib));
    let mut abs_sum = sum.abs_upper();
    // the tail's bounds hold for every point of the balls: the lower ends for
    // the first index past the negative parameters, the upper ends in the
    // ratio bound (`max(1, (p+n)/(q+n))` increases with `p`)
    let (lo_a, lo_b, hi_a, hi_b) = (ab.lower(), bbb.lower(), ab.upper(), bbb.upper());
    let n_pos = first_positive_index(&[&lo_a, &lo_b])?;
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
                let factor = tail_factor.get(n, || ratio_bound(&hi_a, &hi_b, &q1, &one(), &u_abs, n, rho_prec));
                if let Some(factor) = factor {
                    if negligible_scaled(&proxy_term, factor, sum.mid(), &abs_sum, wp) {
                        let h = log_bracket_bound(ab, bbb, m, n, &lnu_abs);
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
