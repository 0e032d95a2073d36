//! `J_n(x)` by the power series [DLMF 10.2.2]:
//! `J_n(x) = (x/2)^n / n! * S`, `S = sum_k t_k`, `t_0 = 1`,
//! `t_{k+1} = t_k z / ((k+1)(n+k+1))`, `z = -x^2/4`.
//!
//! # Method and error bound
//!
//! The sum runs on bare MPFR midpoints (no ball per operation) with a running
//! error analysis in [`Mag`] (upper bounds, rounded up). With `u = 2^(1-wp)`
//! (at least the relative error of one round-to-nearest operation at `wp` bits)
//! and `eta_z` the relative radius of `z`:
//!
//! * term: `t~_{k+1} = fl(fl(t~_k z~) / d_k)`, `d_k = (k+1)(n+k+1)` an exact
//!   integer, so `|t_{k+1} - t~_{k+1}| <= eta_{k+1} |t~_{k+1}|` with
//!   `1 + eta_{k+1} <= (1 + eta_k)(1 + eta_z)(1 + u)^2 <= e^A`,
//!   `A = eta_k + eta_z + 2u`, and `e^A - 1 <= A (1 + A)` for `A <= 1`;
//! * sum: each `fl(s~ + t~)` errs by at most `u |fl(s~ + t~)|`;
//! * tail: the sum stops at the first `K` with `|t_K| <= 2^-wp max(|S~|, 2^-wp sum|t~|)`
//!   and `rho = |z| / ((K+1)(n+K+1)) <= 1/2`; the ratios `|t_{k+1}/t_k|` decrease
//!   from there on, so the tail is at most `|t_K| / (1 - rho) <= 2 |t_K|`. (The test
//!   is evaluated only once `|t~| < 2^(e_s - wp + 2)`, `|s~| < 2^e_s`, where it can
//!   first pass: a cheap filter on binary exponents. Skipping it sums more terms,
//!   which the bound covers, so `K` may be a term later; the terms tend to zero.)
//!
//! The bound is `sum_k eta_k |t~_k| + u sum_k |s~_k| + 2 |t_K|`, added to the
//! radius of `S`; the prefactor `(x/2)^n / n!` is a ball product. The terms
//! alternate and their magnitudes sum to `I_n(x) n! (2/x)^n`, so about
//! `log2(I_n(x)/|J_n(x)|)` bits cancel; the Ziv loop of [`super`] adds them.
//!
//! # Rectangular splitting (from [`RECTANGULAR_MIN_PREC`] bits)
//!
//! At high precision a full multiplication costs `O(wp^2)` and a division by a
//! one-limb integer or an addition `O(wp)`, so [`bessel_j_series`] sums
//! `S_K = sum_{k<K} t_k` by Smith's rectangular splitting, as Arb's hypergeometric
//! sums do: with the powers `p_j = z~^j`, `j <= m = ceil(sqrt K)`, and the block sums
//! `R_i = sum_{k >= i m} z^(k - i m) D_(i m) / D_k` (`D_k = prod_(l<=k) d_l`,
//! `d_l = l (n + l)`, so `S_K = R_0`), Horner's rule over the block reads
//!
//! ```text
//! R_i = p_0 + (p_1 + (p_2 + ... (p_(m-1) + p_m R_(i+1) / d_(im+m)) ... / d_(im+3)) / d_(im+2)) / d_(im+1),
//! ```
//!
//! `m` powers and one multiplication by `p_m` a block: about `2 sqrt K` full products
//! instead of `K`; the rest are divisions by `d_l` (one limb) and additions.
//!
//! *Error bound.* Every operation (`fl(a b)`, `fl(a / d)`, `fl(a + b)`) multiplies
//! its exact result by `1 + delta`, `|delta| <= u`, so the computed sum is exactly
//! `sum_k t_k(z~) prod_(i in path_k) (1 + delta_i)`, the product over the operations
//! that term `k = i m + j` passes through: `p_j`'s `j - 1` products, one addition,
//! `j` divisions and `j` additions in its own block, and for each of the `i` blocks
//! before it the product by `p_m` (`m` roundings with `p_m`'s own) and `m` divisions
//! and `m` additions: at most `3 k + 1` roundings. With `z`'s relative radius
//! `eta_z`, `|t_k(z) - t_k(z~)| <= ((1 + eta_z)^k - 1) |t_k(z~)|`, so
//!
//! ```text
//! |S~ - S_K(z)| <= sum_k |t_k| (e^(A_k) - 1) <= (1 + A_(K-1)) sum_k A_k |t_k|,
//! A_k = (3 k + 1) u + k eta_z = u + k (3 u + eta_z),   A_(K-1) <= 1,
//! ```
//!
//! `|t_k| <= T_k`, the upper bounds `T_0 = 1`, `T_(k+1) = T_k |z| / d_(k+1)` rounded up
//! ([`Mag`]), so the bound is `(1 + A_(K-1)) (u sum T_k + (3 u + eta_z) sum k T_k)`.
//! `K` is fixed before the sum, from the same bounds: the first `K` with
//! `rho = |z| / ((K+1)(n+K+1)) <= 1/2` and `T_K <= 2^-(wp+1) sum_(k<K) T_k`; the tail is
//! at most `2 T_K` as above. (The bound is relative to `sum |t_k|`, as the
//! cancellation's rounding errors are in any order of summation: the Ziv loop's guard
//! of `log2(I_n/|J_n|) + 24` bits covers both.)
//!
//! [`bessel_j_series_pfq`] is the same series through the generic pFq core
//! (balls at every step): slower, kept as the cross-check.

use rug::Float;

use crate::ball::{Ball, Mag};
use crate::error::{Error, Result};
use crate::special::pfq::pfq_series;

/// Cap on the number of series terms (`x` up to ~1e7 needs about `1.4 x`).
const MAX_SERIES_TERMS: u64 = 50_000_000;

/// Orders from which the prefactor goes through `exp(n ln(x/2) - ln n!)`
/// instead of a power and an exact factorial (MPFR's `n!` is slow for large n).
const LOG_PREFACTOR_MIN_ORDER: u64 = 128;

/// `(x/2)^n / n!` as a ball. For large `n`, `exp(n ln(x/2) - ln Gamma(n+1))`
/// with `ln Gamma` correctly rounded by MPFR (radius one ulp) at
/// `wp + log2(|exponent|) + 16` bits, so the exponent's absolute error stays
/// below `2^-(wp+16)`.
fn prefactor(n: u64, half_x: &Ball, wp: u32) -> Result<Ball> {
    if n < LOG_PREFACTOR_MIN_ORDER {
        let order = u32::try_from(n).map_err(|_| Error::IntegerOutOfRange { arg: "n", value: i64::try_from(n).unwrap_or(i64::MAX), min: 0, max: u32::MAX as i64 })?;
        let fact = Ball::factorial(order, wp);
        return half_x.pow_u64(n).div(&fact);
    }
    let nf = n as f64;
    // |ln(x/2)| from the binary exponent (to_f64 would under- or overflow for MP inputs)
    let ln_half_x = half_x.mid().get_exp().map_or(0.0, |e| (e as f64).abs() * std::f64::consts::LN_2);
    let magnitude = nf * (nf.ln().abs() + ln_half_x + 1.0);
    // |ln(x/2)| is finite for the nonzero x that reach here; the sum saturates
    // instead of overflowing, and the precision check below refuses it
    let p = wp.saturating_add(magnitude.log2().max(0.0) as u32).saturating_add(16);
    crate::error::check_working_prec(p)?;
    let n_i = i64::try_from(n).map_err(|_| Error::IntegerOutOfRange { arg: "n", value: i64::MAX, min: 0, max: i64::MAX })?;
    let lnfact_mid = Float::with_val(p, n_i + 1).ln_gamma();
    let ulp = match lnfact_mid.get_exp() {
        Some(e) => Mag::pow2(e as i64 - p as i64),
        None => Mag::ZERO,
    };
    let lnfact = Ball::with_mag(lnfact_mid, ulp);
    let exponent = half_x.set_prec(p).ln()?.mul_i64(n_i).sub(&lnfact);
    exponent.exp()
}

/// From this working precision on, [`bessel_j_series`] sums by rectangular splitting
/// (module docs); below it, term by term with the running error analysis.
pub const RECTANGULAR_MIN_PREC: u32 = 256;

/// `J_n(x)` by the power series at working precision `wp` (`x > 0`).
pub fn bessel_j_series(n: u64, x: &Float, wp: u32) -> Result<Ball> {
    crate::error::check_working_prec(wp)?;
    let xb = Ball::from_float(x, wp);
    let half_x = xb.mul_pow2(-1);
    let z = half_x.sqr().neg();
    let sum = if wp >= RECTANGULAR_MIN_PREC { sum_rectangular(n, &z, wp)? } else { sum_term_by_term(n, &z, wp)? };
    Ok(prefactor(n, &half_x, wp)?.mul(&sum))
}

/// The most bits the powers of the rectangular sum may hold (128 MiB); beyond, the
/// term-by-term sum, which keeps two numbers.
const RECTANGULAR_MAX_POWER_BITS: u64 = 1 << 30;

/// A lower bound of the integer `d` as a [`Mag`] (exact below `2^53`).
fn mag_of_integer_down(d: u64) -> Mag {
    let f = d as f64;
    Mag::from_f64(if d < (1u64 << 53) { f } else { f.next_down() })
}

/// `d_k = k (n + k)`, the divisor of the step from `t_(k-1)` to `t_k`.
fn divisor(n: u64, k: u64) -> Result<u64> {
    k.checked_mul(n + k).ok_or_else(|| Error::precondition("Bessel series index within u64"))
}

/// The number of terms `K` and the error bound of the rectangular sum (module docs):
/// `(K, rounding bound, tail bound)`.
fn rectangular_plan(n: u64, z: &Ball, wp: u32) -> Result<(u64, Mag, Mag)> {
    let z_abs = z.abs_upper_mag();
    let eta_z = z.rad_mag().div(Mag::from_float_down(z.mid()));
    let u = Mag::pow2(1 - wp as i64);
    let slope = u.mul(Mag::from_f64(3.0)).add(eta_z); // A_k = u + k slope
    let mut t = Mag::from_f64(1.0); // T_k
    let mut sum_t = Mag::ZERO; // sum_(k<K) T_k
    let mut sum_kt = Mag::ZERO; // sum_(k<K) k T_k
    let mut ratio_ok = false;
    let mut k: u64 = 0;
    loop {
        if k > 0 {
            // T_k = T_(k-1) |z| / d_k
            t = t.mul(z_abs).div(mag_of_integer_down(divisor(n, k)?));
            if !t.is_finite() {
                return Err(Error::Overflow { what: "Bessel series term".into() });
            }
            if !ratio_ok {
                // rho = |z| / d_(k+1) <= 1/2, and so for every later k (d grows)
                ratio_ok = z_abs.le(&mag_of_integer_down(divisor(n, k + 1)?).mul_2exp(-1));
            }
            if ratio_ok && t.le(&sum_t.mul_2exp(-(wp as i64) - 1)) {
                break;
            }
        }
        sum_t = sum_t.add(t);
        sum_kt = sum_kt.add(t.mul(Mag::from_f64(k as f64)));
        k += 1;
        if k > MAX_SERIES_TERMS {
            return Err(Error::NoConvergence { function: "bessel_j (power series)", terms: k });
        }
    }
    // A_(K-1) <= 1 (checked), e^A - 1 <= A (1 + A)
    let a_max = u.add(slope.mul(Mag::from_f64((k - 1) as f64)));
    if !a_max.le(&Mag::from_f64(1.0)) {
        return Err(Error::precondition("Bessel series rounding bound below 1"));
    }
    let rounding = u.mul(sum_t).add(slope.mul(sum_kt)).mul(a_max.add(Mag::from_f64(1.0)));
    Ok((k, rounding, t.mul_2exp(1)))
}

/// `0F1(; n+1; z) = sum_k t_k` by rectangular splitting (module docs), as a ball.
fn sum_rectangular(n: u64, z: &Ball, wp: u32) -> Result<Ball> {
    let (terms, rounding, tail) = rectangular_plan(n, z, wp)?;
    // m = ceil(sqrt K), powers p_1 .. p_m of z~ (p_1 exact)
    let m = (terms as f64).sqrt().ceil().max(1.0) as u64;
    if m.saturating_mul(wp as u64) > RECTANGULAR_MAX_POWER_BITS {
        // the powers would hold too much memory (huge x at huge precision)
        return sum_term_by_term(n, z, wp);
    }
    let mut powers: Vec<Float> = Vec::with_capacity(m as usize + 1);
    powers.push(Float::with_val(wp, 1));
    powers.push(z.mid().clone());
    for j in 2..=m as usize {
        let p = Float::with_val(wp, &powers[j - 1] * z.mid());
        powers.push(p);
    }
    let blocks = terms.div_ceil(m);
    let mut w = Float::new(wp);
    for i in (0..blocks).rev() {
        let lo = i * m;
        let len = m.min(terms - lo);
        if i + 1 < blocks {
            // w = p_m R_(i+1) (only the last block can be shorter than m)
            w *= &powers[m as usize];
        }
        for j in (1..=len).rev() {
            // w = w / d_(lo+j) + p_(j-1)
            if !w.is_zero() {
                w /= divisor(n, lo + j)?;
            }
            if j == 1 {
                w += 1u32;
            } else {
                w += &powers[j as usize - 1];
            }
        }
    }
    Ok(Ball::with_mag(w, rounding.add(tail)))
}

/// `0F1(; n+1; z) = sum_k t_k` term by term with the running error analysis (module
/// docs), as a ball.
fn sum_term_by_term(n: u64, z: &Ball, wp: u32) -> Result<Ball> {
    let z_mid = z.mid().clone();
    let z_abs = z.abs_upper_mag();
    let eta_z = z.rad_mag().div(Mag::from_float_down(&z_mid));
    let u = Mag::pow2(1 - wp as i64);
    let two_u = u.mul_2exp(1);
    let target_shift = -(wp as i64);

    let mut t = Float::with_val(wp, 1);
    let mut s = Float::with_val(wp, 1);
    let mut eta = Mag::ZERO; // |t_k - t~_k| <= eta |t~_k|
    let mut err = Mag::ZERO; // sum_k eta_k |t~_k|
    let mut s_abs = Mag::ZERO; // sum_k |s~_k| (times u at the end: the additions' roundings)
    let mut abs_sum = Mag::from_f64(1.0);
    // rho = |z| / ((k+1)(n+k+1)) <= 1/2 holds from here on once it holds (the
    // denominator grows with k)
    let mut ratio_ok = false;
    let mut k: u64 = 0;
    let tail = loop {
        // t_{k+1} = t_k z / ((k+1)(n+k+1))
        let d = (k + 1)
            .checked_mul(n + k + 1)
            .ok_or_else(|| Error::precondition("Bessel series index within i64"))?;
        t *= &z_mid;
        t /= d;
        let a = eta.add(eta_z).add(two_u);
        eta = a.add(a.mul(a));
        k += 1;
        let t_abs = Mag::from_float_up(&t);
        if !t_abs.is_finite() {
            return Err(Error::Overflow { what: "Bessel series term".into() });
        }
        if !ratio_ok {
            // (the f64 product rounded to nearest, stepped down: a lower bound below 2^53)
            let next_d = Mag::from_f64((((k + 1) as f64) * ((n + k + 1) as f64)).next_down()).mul_2exp(-1);
            ratio_ok = z_abs.le(&next_d);
        }
        // The stopping test costs about ten Mag operations; it is run only once
        // |t~| < 2^(e_s - wp + 2) (binary exponents, `|s~| < 2^e_s`), below which the
        // test |t| <= 2^-wp max(|S~|, ...) can first pass. Skipping it only sums more
        // terms, which the bound covers; the terms tend to zero, so it is reached.
        let may_stop = match (t.get_exp(), s.get_exp()) {
            (Some(et), Some(es)) => (et as i64) + (wp as i64) <= (es as i64) + 2,
            _ => true,
        };
        if ratio_ok && may_stop {
            let t_exact = t_abs.add(t_abs.mul(eta));
            let target = Mag::from_float_down(&s).max(abs_sum.mul_2exp(target_shift)).mul_2exp(target_shift);
            if t_exact.le(&target) {
                break t_exact.mul_2exp(1);
            }
        }
        s += &t;
        err = err.add(eta.mul(t_abs));
        s_abs = s_abs.add(Mag::from_float_up(&s));
        abs_sum = abs_sum.add(t_abs);
        if k > MAX_SERIES_TERMS {
            return Err(Error::NoConvergence { function: "bessel_j (power series)", terms: k });
        }
    };
    let err = err.add(u.mul(s_abs));
    Ok(Ball::with_mag(s, err.add(tail)))
}

/// The same series through the generic pFq core (balls at every step): the
/// cross-check for [`bessel_j_series`].
pub fn bessel_j_series_pfq(n: u64, x: &Float, wp: u32) -> Result<Ball> {
    crate::error::check_working_prec(wp)?;
    let xb = Ball::from_float(x, wp);
    let half_x = xb.mul_pow2(-1);
    let z = half_x.sqr().neg();
    let b = [Ball::from_i64(n as i64 + 1, wp)];
    let sum = pfq_series(&[], &b, &z, wp)?.sum;
    Ok(prefactor(n, &half_x, wp)?.mul(&sum))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The rectangular sum and the term-by-term one at the same working precision:
    /// both balls enclose `0F1`, so they overlap, and the rectangular radius is within
    /// a few bits of the term-by-term one (the a-priori bound of the module docs
    /// against the running one), from tiny to cancelling arguments, orders 0 to 500.
    #[test]
    fn rectangular_and_term_by_term_sums_agree() {
        for &(n, x) in &[(0u64, 1e-3), (0, 0.37), (0, 2.404825557695773), (0, 10.0), (1, 7.015586669815619), (3, 25.5), (40, 30.25), (500, 999.5), (7, 0.75)] {
            let xf = Float::with_val(53, x);
            for wp in [64u32, 256, 333, 1000, 3353] {
                let wp = wp + (1.45 * x) as u32;
                let z = Ball::from_float(&xf, wp).mul_pow2(-1).sqr().neg();
                let a = sum_rectangular(n, &z, wp).unwrap();
                let b = sum_term_by_term(n, &z, wp).unwrap();
                assert!(a.overlaps(&b), "n={n} x={x} wp={wp}: {a:?} vs {b:?}");
                let (ra, rb) = (a.rad_mag().log2(), b.rad_mag().log2());
                assert!(ra <= rb + 4.0, "n={n} x={x} wp={wp}: radius 2^{ra:.1} against 2^{rb:.1}");
            }
        }
    }

    /// At a zero of `J_0` (the cancelling case) the certified value at 3333 bits meets
    /// its goal, and the one at 3353 bits lies inside it: the rectangular sum through
    /// the Ziv loop, and its radius checked against the midpoint.
    #[test]
    fn rectangular_sum_encloses_near_a_zero() {
        // x near j_(0,1) = 2.4048..., given to 53 bits: J_0(x) ~ 1e-17
        let xf = Float::with_val(53, 2.404825557695773);
        let a = crate::special::bessel_j::bessel_j_mp(0, &xf, 3333).unwrap();
        let b = crate::special::bessel_j::bessel_j_mp(0, &xf, 3353).unwrap();
        assert!(a.meets_rel(3333), "{:.1} bits", a.rel_accuracy_bits());
        assert!(a.overlaps(&b));
        let c = bessel_j_series_pfq(0, &xf, 3400).unwrap();
        assert!(a.overlaps(&c));
    }

    #[test]
    fn fast_and_pfq_series_overlap() {
        for &(n, x) in &[(0u64, 2.5), (5, 30.25), (40, 150.5), (1, 1e-3), (500, 999.5), (7, 0.75), (2000, 1e-3), (200, 30.5)] {
            let xf = Float::with_val(53, x);
            for wp in [64u32, 200, 400] {
                let extra = (1.45 * x) as u32;
                let a = bessel_j_series(n, &xf, wp + extra).unwrap();
                let b = bessel_j_series_pfq(n, &xf, wp + extra + 30).unwrap();
                assert!(a.overlaps(&b), "n={n} x={x} wp={wp}: {a:?} vs {b:?}");
                assert!(a.meets_rel(wp - 8), "n={n} x={x} wp={wp}: {:.1} bits", a.rel_accuracy_bits());
            }
        }
    }
}
