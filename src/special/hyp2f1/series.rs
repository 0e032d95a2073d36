//! The `2F1` power-series engine: exact parameters, a ball argument, summed in
//! place with an a-priori rounding bound and a rigorous tail.
//!
//! # Method and error bound
//!
//! * **Series engine** ([`series_2f1`]): terms and partial sums are computed in
//!   place at `p = max(wp, 64)` bits with round-to-nearest (`u = 2^-p`). Each
//!   step `t_{n+1} = t_n (a+n)(b+n) z / ((c+n)(n+1))` performs at most 8
//!   roundings (3 when `2^k a`, `2^k b`, `2^k c` are small integers: the ratio is
//!   then a quotient of two exact machine integers), so
//!   `|t~_n - t_n| <= gamma_{8n} |t_n| <= 10 n u |t~_n|`, and each addition errs
//!   by at most `2 u |s~_k|`. The radius is
//!   `10 N u sum|t~_n| + 2 N u max|s~_k|` (zero when MPFR reports every
//!   operation exact) plus the tail: for `n >= N0` past every negative parameter,
//!   `|t_{n+1}/t_n| <= rho = |z|^+ min over the two pairings of
//!   max(1, (a+N0)/(c+N0)) max(1, (b+N0)/(1+N0))` (each factor is monotone in `n`,
//!   so `rho` stays valid for every later stopping index `N`), and
//!   `sum_{n>=N} |t_n| <= |t_N| / (1 - rho)`. When `rho` at the term limit
//!   (`MAX_SERIES_TERMS`) is still `>= 1`, no stopping index exists below it and
//!   the series is refused before summing ([`Error::TooExpensive`], also when
//!   it passes what is left of the call's time budget, [`crate::budget`]). `rho` is rounded upward at `wp + 16`
//!   bits (not with the 53-bit radius arithmetic: `|z|` may be within `2^-40` of
//!   1, where the direct series can still be the cheap choice when `c - a - b` is
//!   large), and summation stops once `|t_N| / (1 - rho)` is below `2^-wp |s|`
//!   (the bound of `pfq`, with the better pairing). When `z` is a ball
//!   `[z~ +/- r]` (after Pfaff) the sum is taken at `z~` and
//!   `|t_n(z) - t_n(z~)| <= ((1 + r/|z~|)^n - 1) |t_n(z~)|` is added, with
//!   `(1+d)^N - 1 <= expm1(N d)`.
//!
//! `2F1(p, q; p; x) = (1-x)^{-q}` [DLMF 15.4.6] is used instead of a series when
//! a numerator equals the denominator ([`series_or_power`]).

use std::cmp::Ordering;

use rug::float::Round;
use rug::ops::{AddAssignRound, AssignRound, DivAssignRound, MulAssignRound, SubAssignRound};
use rug::Float;

use super::{nonpos_degree, one, pole_error, terminating_degree, MIN_SERIES_PREC};
use crate::ball::{Ball, Scaled, MAG_PREC};
use crate::error::{Error, Result};
use crate::special::gamma::{
    expm1_up, mag_abs, mag_abs_down, mag_add, mag_div, mag_geometric, mag_inf, mag_min, mag_mul, mag_pow2, mag_u64,
    mag_zero, xball,
};
use crate::special::pfq::{pfq_series, MAX_SERIES_TERMS};

/// Smallest `N` with `p + N > 0` for every parameter `p`.
pub(super) fn first_positive_index(params: &[&Float]) -> Result<u64> {
    let mut n = 0u64;
    for p in params {
        if **p <= 0 {
            let v = -p.to_f64();
            if v.is_nan() || v >= 1e15 {
                return Err(crate::special::pfq::series_past_negative_parameter("2F1(a, b; c; z) by its series (a parameter below -1e15)", v));
            }
            n = n.max(v.floor() as u64 + 1);
        }
    }
    Ok(n)
}

/// Upper bound of `max(1, (p+n)/(q+n))` at `prec` bits (infinite when `q + n <= 0`).
pub(super) fn pair_factor(p: &Float, q: &Float, n: u64, prec: u32) -> Float {
    let num = Float::with_val_round(prec, p + n, Round::Up).0;
    let den = Float::with_val_round(prec, q + n, Round::Down).0;
    if den <= 0 || num < 0 {
        return mag_inf();
    }
    let f = Float::with_val_round(prec, &num / &den, Round::Up).0;
    if f < 1 {
        Float::with_val(prec, 1)
    } else {
        f
    }
}

/// Upper bound of `|x|` over a ball at `prec` bits (full accuracy, unlike the
/// 32-bit radius arithmetic: `|x|` may be within `2^-40` of 1).
pub(super) fn abs_upper_precise(x: &Ball, prec: u32) -> Float {
    let hi = Float::with_val_round(prec, x.upper().abs_ref(), Round::Up).0;
    let lo = Float::with_val_round(prec, x.lower().abs_ref(), Round::Up).0;
    if hi >= lo {
        hi
    } else {
        lo
    }
}

/// `rho_N`: bound on `|t_{n+1}/t_n|` for all `n >= N` of a series with term
/// ratio `(p1+n)(p2+n) x / ((q1+n)(q2+n))`, the better of the two pairings, at
/// `prec` bits (rounded upward). Each factor is non-increasing in `N`, so
/// `rho_N` also bounds the ratios beyond any later `N`.
pub(super) fn ratio_bound(p1: &Float, p2: &Float, q1: &Float, q2: &Float, x_abs_up: &Float, n: u64, prec: u32) -> Float {
    let mul = |a: &Float, b: &Float| Float::with_val_round(prec, a * b, Round::Up).0;
    let f1 = mul(&pair_factor(p1, q1, n, prec), &pair_factor(p2, q2, n, prec));
    let f2 = mul(&pair_factor(p2, q1, n, prec), &pair_factor(p1, q2, n, prec));
    mul(x_abs_up, &mag_min(f1, f2))
}

/// `1 / (1 - rho_N)` (upward) once `rho_N < 1`, tried at most every 8 terms.
pub(super) struct TailFactor {
    factor: Option<Float>,
    next_try: u64,
}

impl TailFactor {
    pub(super) fn new() -> TailFactor {
        TailFactor { factor: None, next_try: 0 }
    }

    pub(super) fn get(&mut self, n: u64, rho: impl FnOnce() -> Float) -> Option<&Float> {
        if self.factor.is_none() && n >= self.next_try {
            let r = rho();
            if r < 1 {
                self.factor = Some(mag_geometric(&r));
            } else {
                self.next_try = n + 8;
            }
        }
        self.factor.as_ref()
    }
}

/// `|t| * f` (by exponents, `f >= 1`) is at most `2^-(wp+1) max(|s|, 2^-wp sum|t|)`.
pub(super) fn negligible_scaled(t: &Float, f: &Float, s: &Float, abs_sum: &Float, wp: u32) -> bool {
    match (t.get_exp(), f.get_exp()) {
        (None, _) => true,
        (Some(et), Some(ef)) => {
            let e = (et as i64 + ef as i64).clamp(i32::MIN as i64 / 2, i32::MAX as i64 / 2) as i32;
            let shifted = Float::with_val(2, 1) << e;
            negligible(&shifted, s, abs_sum, wp)
        }
        (Some(_), None) => false,
    }
}

/// Whether `|t| <= 2^-(wp+1) max(|s|, 2^-wp sum|t|)` (by exponents).
pub(super) fn negligible(t: &Float, s: &Float, abs_sum: &Float, wp: u32) -> bool {
    let Some(et) = t.get_exp() else { return true };
    let (et, wp) = (et as i64, wp as i64);
    match s.get_exp() {
        Some(es) => et + wp + 2 <= es as i64,
        None => match abs_sum.get_exp() {
            Some(ea) => et + 2 * wp + 2 <= ea as i64,
            None => false,
        },
    }
}

/// `(2^k a, 2^k b, 2^k c, k)` when these are integers below `2^31` in magnitude
/// for some `k <= 16`.
pub(super) fn scaled_integers(a: &Float, b: &Float, c: &Float) -> Option<(i64, i64, i64, u32)> {
    let conv = |x: &Float, k: u32| -> Option<i64> {
        let y = Float::with_val(x.prec(), x << k);
        if !y.is_integer() || y.clone().abs() >= (1u64 << 31) {
            return None;
        }
        Some(y.to_f64() as i64)
    };
    (0..=16u32).find_map(|k| Some((conv(a, k)?, conv(b, k)?, conv(c, k)?, k)))
}

/// The series `2F1(a, b; c; z)` (exact parameters, `z` a ball with `|z| < 1`,
/// or any `z` when the series terminates) summed in place at `wp` bits, with the
/// a-priori rounding bound, the perturbation bound for the radius of `z` and the
/// rigorous tail bound of the module docs.
/// The refusal of a 2F1 series of at least `terms` terms past `limit` seconds.
fn too_expensive(terms: u64, per_term: f64, limit: f64) -> Error {
    Error::TooExpensive {
        function: "2F1(a, b; c; z) by its series",
        seconds: (terms as f64 * per_term).max(limit.next_up()),
        limit_seconds: limit,
    }
}

pub(crate) fn series_2f1(a: &Float, b: &Float, c: &Float, z: &Ball, wp: u32) -> Result<Ball> {
    let wp = wp.max(MIN_SERIES_PREC);
    let deg = terminating_degree(a, b);
    // `z` rounded into its ball at `wp` bits: every term multiplies by its
    // midpoint, and a decimal `z` tightened to 54 000 bits cost that length a
    // term (the radius is carried by the perturbation bound below); kept as
    // given when the rounded ball would reach `|z| = 1` (`w = 1 - 10^-6020`
    // after Pfaff: the series' own refusal then names its term count)
    let rounded = if deg.is_some() { Some(z.at_most_prec(wp)) } else { rounded_inside_unit(z, wp) };
    let z = rounded.as_ref().unwrap_or(z);
    if let Some(m) = nonpos_degree(c) {
        if deg.map_or(true, |d| d > m) {
            return Err(pole_error(c));
        }
    }
    if deg.is_none() && !(z.upper() < 1 && z.lower() > -1) {
        return Err(Error::precondition("2F1 series needs |z| < 1 (transform the argument first)"));
    }
    // The series' cost: its cap of MAX_SERIES_TERMS terms, shortened by what
    // is left of the call's time budget (crate::budget).
    let per_term = crate::special::pfq::seconds_per_term(wp);
    let limit = crate::budget::limit_seconds(MAX_SERIES_TERMS as f64 * per_term);
    let max_terms = ((limit / per_term) as u64).min(MAX_SERIES_TERMS);
    if let Some(d) = deg {
        if d > max_terms {
            return Err(too_expensive(d, per_term, limit));
        }
    }
    let zm = z.mid();
    if zm.is_zero() {
        if z.is_exact() {
            return Ok(Ball::one(wp));
        }
        // A ball around zero: the ball-arithmetic core needs no division by |z~|.
        let sum = pfq_series(&[xball(a, wp), xball(b, wp)], &[xball(c, wp)], z, wp)?;
        return Ok(sum.sum);
    }
    let n_pos = if deg.is_some() { 0 } else { first_positive_index(&[a, b, c])? };
    let delta = if z.is_exact() { None } else { Some(mag_div(&z.rad(), &mag_abs_down(zm))) };
    let rho_prec = wp + 16;
    let z_abs_up = abs_upper_precise(z, rho_prec);
    let mut tail_factor = TailFactor::new();
    let runs_past = |n: u64| n < n_pos || !(ratio_bound(a, b, c, &one(), &z_abs_up, n + 1, rho_prec) < 1);
    if deg.is_none() && runs_past(max_terms) {
        // The loop stops only at some n >= n_pos with rho_n < 1, and rho_n is
        // non-increasing in n: rho just past the term limit >= 1 means it would
        // run past the limit, so refuse now, naming a lower bound of the terms
        // (a doubling search: within a factor 2).
        let mut n = max_terms.max(1);
        while n < 1 << 62 && runs_past(n) {
            n *= 2;
        }
        return Err(too_expensive((n / 2).max(max_terms), per_term, limit));
    }

    let scaled = scaled_integers(a, b, c);
    let mut t = Float::with_val(wp, 1);
    let mut s = Float::with_val(wp, 1);
    let mut an = Float::new(wp);
    let mut bn = Float::new(wp);
    let mut cn = Float::new(wp);
    let mut abs_sum = Float::with_val(MAG_PREC, 1);
    let mut max_exp_s: i64 = 1; // |s~_k| < 2^max_exp_s for all k
    let mut all_exact = true;
    let mut tail = mag_zero();
    let mut n: u64 = 0;
    loop {
        if deg == Some(n) {
            break;
        }
        // Small dyadic parameters: the ratio (a+n)(b+n) / ((c+n)(n+1)) as a quotient
        // of two machine integers (3 roundings per step instead of 8).
        let int_step = scaled.and_then(|(ai, bi, ci, k)| {
            let nk = (n as i128) << k;
            let num = (ai as i128 + nk) * (bi as i128 + nk);
            let den = ((ci as i128 + nk) * (n as i128 + 1)) << k;
            Some((i64::try_from(num).ok()?, i64::try_from(den).ok()?))
        });
        let inexact = match int_step {
            Some((_, 0)) => return Err(pole_error(c)),
            Some((num, den)) => {
                let mut inexact = t.mul_assign_round(num, Round::Nearest) != Ordering::Equal;
                inexact |= t.mul_assign_round(zm, Round::Nearest) != Ordering::Equal;
                inexact |= t.div_assign_round(den, Round::Nearest) != Ordering::Equal;
                inexact
            }
            None => {
                let mut inexact = an.assign_round(a + n, Round::Nearest) != Ordering::Equal;
                inexact |= bn.assign_round(b + n, Round::Nearest) != Ordering::Equal;
                inexact |= cn.assign_round(c + n, Round::Nearest) != Ordering::Equal;
                if cn.is_zero() {
                    return Err(pole_error(c));
                }
                inexact |= t.mul_assign_round(&an, Round::Nearest) != Ordering::Equal;
                inexact |= t.mul_assign_round(&bn, Round::Nearest) != Ordering::Equal;
                inexact |= t.mul_assign_round(zm, Round::Nearest) != Ordering::Equal;
                inexact |= t.div_assign_round(&cn, Round::Nearest) != Ordering::Equal;
                inexact |= t.div_assign_round(n + 1, Round::Nearest) != Ordering::Equal;
                inexact
            }
        };
        all_exact &= !inexact;
        n += 1;
        if !t.is_finite() {
            return Err(Error::Overflow { what: "hyp2f1 series term".into() });
        }
        if deg.is_none() && n >= n_pos && negligible(&t, &s, &abs_sum, wp) {
            let factor = tail_factor.get(n, || ratio_bound(a, b, c, &one(), &z_abs_up, n, rho_prec));
            if let Some(factor) = factor {
                if negligible_scaled(&t, factor, &s, &abs_sum, wp) {
                    // sum_{k>=N} |t_k(z)| <= |t_N(z)| / (1 - rho), with
                    // |t_N(z)| <= |t~_N| (1 + 10 N u) (1 + delta)^N.
                    let mut tn = mag_mul(
                        &mag_abs(&t),
                        &mag_add(&Float::with_val(MAG_PREC, 1), &mag_mul(&mag_u64(10 * n), &mag_pow2(-(wp as i64)))),
                    );
                    if let Some(d) = &delta {
                        let e = expm1_up(&mag_mul(d, &mag_u64(n)));
                        tn = mag_mul(&tn, &mag_add(&Float::with_val(MAG_PREC, 1), &e));
                    }
                    tail = mag_mul(&tn, factor);
                    break;
                }
            }
        }
        all_exact &= s.add_assign_round(&t, Round::Nearest) == Ordering::Equal;
        if t.is_sign_negative() {
            abs_sum.sub_assign_round(&t, Round::Up);
        } else {
            abs_sum.add_assign_round(&t, Round::Up);
        }
        if let Some(e) = s.get_exp() {
            max_exp_s = max_exp_s.max(e as i64);
        }
        if n > MAX_SERIES_TERMS {
            return Err(Error::NoConvergence { function: "hyp2f1", terms: n });
        }
        if n % crate::budget::TERMS_BETWEEN_CHECKS == 0 {
            // the installed time budget (crate::budget): the term count above is a
            // lower bound of the work, not its length (2F1(24.1, -34.875; 1000001; 0.5)
            // planned 65 560 guard bits and summed 5000 terms at 65 742 bits: 2 s)
            crate::budget::check_elapsed("2F1 series, term by term", 0.0, crate::error::Reached::Terms { count: n })?;
        }
    }
    let u = mag_pow2(-(wp as i64));
    let mut rad = tail;
    if !all_exact {
        let nn = mag_u64(n.max(1));
        let term_err = mag_mul(&mag_mul(&abs_sum, &mag_mul(&nn, &mag_u64(10))), &u);
        let sum_err = mag_mul(&mag_mul(&mag_pow2(max_exp_s + 1), &nn), &u);
        rad = mag_add(&rad, &mag_add(&term_err, &sum_err));
    }
    if let Some(d) = &delta {
        // sum_{n<N} |t_n(z) - t_n(z~)| <= expm1(N delta) (1 + 10 N u) sum |t~_n|
        let e = expm1_up(&mag_mul(d, &mag_u64(n.max(1))));
        let grow = mag_add(&Float::with_val(MAG_PREC, 1), &mag_mul(&mag_u64(10 * n.max(1)), &u));
        rad = mag_add(&rad, &mag_mul(&mag_mul(&e, &grow), &abs_sum));
    }
    Ok(Ball::with_radius(s, &rad))
}


/// `2F1(p, q; r; x)`, using `2F1(p, q; p; x) = (1-x)^{-q}` [DLMF 15.4.6] when a
/// numerator equals the denominator; `one_minus_x` must enclose `1 - x`.
pub(super) fn series_or_power(p: &Float, q: &Float, r: &Float, x: &Ball, one_minus_x: &Ball, wp: u32) -> Result<Ball> {
    if p == r {
        return pow_exact_exponent(one_minus_x, &Float::with_val(q.prec(), -q), wp);
    }
    if q == r {
        return pow_exact_exponent(one_minus_x, &Float::with_val(p.prec(), -p), wp);
    }
    series_2f1(p, q, r, x, wp)
}

/// `x` rounded into its ball at `wp` bits, when that ball still lies in
/// `(-1, 1)` and, for a positive `x`, in `(0, 1)` (the series' and the logarithm's
/// domains); `None` otherwise: then `x` is kept at its own length. A decimal
/// argument tightened to 58 000 bits by the decimal retries otherwise makes every
/// term, `ln` and `1/x` cost that length (issue 37's scan).
pub(super) fn rounded_inside_unit(x: &Ball, wp: u32) -> Option<Ball> {
    let r = x.at_most_prec(wp);
    let inside = r.upper() < 1 && r.lower() > -1 && (x.lower() <= 0 || r.lower() > 0);
    inside.then_some(r)
}

/// `base^e` for `base > 0` and an exact exponent (binary powering for integers):
/// [`pow_exact_exponent_scaled`] as a ball ([`Error::ValueOutOfRange`] when the
/// power itself is outside the exponent range).
pub(super) fn pow_exact_exponent(base: &Ball, e: &Float, wp: u32) -> Result<Ball> {
    pow_exact_exponent_scaled(base, e, wp)?.to_ball(wp)
}

/// `base^e` for `base > 0` and an exact exponent as a [`Scaled`]: binary powering
/// for an integer `|e| <= 2^20` while the power stays in the exponent range, else
/// `e^(e ln base)` ([`Scaled::pow`], in logarithms when `|e ln base|` is large:
/// the Pfaff prefactor `(1 - z)^(-a)` at `a = 7.4e17` passes `2^(2^30)` while its
/// product with the inner sum need not).
pub(super) fn pow_exact_exponent_scaled(base: &Ball, e: &Float, wp: u32) -> Result<Scaled> {
    if e.is_zero() {
        return Ok(Scaled::one(wp));
    }
    if e.is_integer() && e.clone().abs() <= (1u64 << 20) {
        let n = e.to_f64().abs() as u64;
        let p = base.pow_u64(n);
        // past MPFR's exponent range (2^(2^30)): `(1 - z)^100001` at `1 - z =
        // 1.3e14333` (issue 37's scan): in logarithms below
        if p.is_finite() && !p.contains_zero() {
            return Ok(Scaled::from_ball(if e.is_sign_negative() { p.recip()? } else { p }));
        }
    }
    // A base longer than the working precision (`1 - z` exact at `z = 3e-29731`
    // holds about 98 000 bits) is rounded into its ball by `Scaled::pow`: at `wp`
    // bits when `|e ln base|` is small (`ln` at the base's own length took 0.5 s,
    // issue 37's scan), else at the bits its size needs.
    // Likewise the exponent (`c - a - b` exact at `a = -1e-23409` holds 78 000
    // bits, and `exp` ran at 175 060 bits: 0.1 s a call, issue 37's scan): `ln`
    // of the base carries a relative error of `2^-wp` already, so `e` rounded to
    // `wp` bits widens `e ln(base)` by as much again, which the Ziv loop sees.
    // (`Ball::pow` rounds `e` to the base's precision; `Scaled::pow`, for a large
    // `e ln(base)`, to the length its absolute accuracy needs.)
    Scaled::pow(base, &Ball::from_float(e, e.prec()), wp)
}
