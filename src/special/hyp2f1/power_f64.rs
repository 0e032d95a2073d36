//! Certified f64 `ln`, `exp` and `x^p` with running error bounds, for the
//! Pfaff prefactor `(1-z)^{-a}` of the native f64 `2F1` sums (where the result
//! is an f64 and a relative bound of a few `u` is all the sum needs; the
//! double-word versions in [`super::power`] serve the double-word sums).
//!
//! # Method
//!
//! `u = 2^-53`; no fused multiply-add is assumed (each product and each sum
//! rounds once, to nearest).
//!
//! * **Horner with a running error bound** ([`horner`]), Higham, *Accuracy and
//!   Stability of Numerical Algorithms*, 2nd ed., Sec. 5.1, adapted to separate
//!   roundings of the product and the sum: with `m_i = fl(p_{i+1} x)` and
//!   `p_i = fl(m_i + c_i)`, the error `e_i` of `p_i` against exact Horner on
//!   the same f64 coefficients obeys `|e_i| <= |x| |e_{i+1}| + u |p_{i+1} x| +
//!   u |p_i| / (1 - u)`, so `|e_0| <= u/(1-u) sum_i |x|^i (|m_i| (1 + u) + |p_i|)`.
//!   The sum `mu` is accumulated alongside (its own rounding, at most
//!   `gamma_{3n}` relative for `n <= 20` terms, is covered by the factor
//!   `1 + 2^-40`). Coefficients that are within `c_rel` (relative) of the
//!   exact ones add `c_rel sum |c_i| |x|^i`, also accumulated alongside.
//! * **`ln x`** ([`ln_f64`]), `x = hi + lo > 0`: `hi = m 2^e` exactly with
//!   `m in [1/sqrt 2, sqrt 2)`; `ln(1 + lo/hi)` is `t = fl(lo/hi)` with error
//!   `<= u |t| + t^2`. `ln m = 2 atanh s`, `s = (m-1)/(m+1)`, `|s| <= 0.1716`
//!   [DLMF 4.6.1 with 4.37.24], `s` as a double word (`m - 1` exact by
//!   Sterbenz, `m + 1` exact as a double word, DWDivDW2: `<= 32 u^2` relative).
//!   `2 atanh s = 2 s + 2 s q R(q)`, `q = s^2`, `R(q) = sum_{k>=1} q^{k-1}/(2k+1)`
//!   summed to `k = 11` (tail `<= q^11/(25 (1 - q)) < 10^-18` at `q <= 0.0295`)
//!   by [`horner`] at `q~ = fl(s_hi^2)` with coefficients `fl(1/(2k+1))`
//!   (`c_rel = u`). Only the small part `2 s q R` (`<= 0.0034`) is rounded in
//!   f64, so its errors are `~u/100` absolute; `2 s` is exact as a double word.
//!   Then `ln x = (e C1 + L_hi) + (L_lo + e C2 + t) + e C3` with
//!   `ln 2 = C1 + C2 + C3` (`e C1` exact: `C1` has 42 bits, `|e| < 2^11`),
//!   returned as a double word: the first sum exact (`two_sum`), the small
//!   parts rounded, `|e C3| < 2^11 * 2^-102`. The absolute error is about
//!   `2^-60`, so `p ln x` carries `|p|` times that.
//! * **`e^y`** ([`exp_f64`]), `y = y_hi + y_lo`, `|y_hi| <= 700`, known to
//!   `dy` (absolute): `k = round(y_hi / ln 2)`, `y_hi - k C1` exactly as a
//!   double word `r_hi + r_lo` (`k C1` exact, `two_sum`),
//!   `r~ = fl(r_hi + fl(fl(r_lo + y_lo) - fl(k C2)))`, so `r~` errs by the
//!   roundings of those small terms, `u |r~|` and `|k C3|`. `e^r~` by [`horner`] on the Taylor
//!   polynomial of degree 14 (`|r~| <= 0.35`: truncation
//!   `<= |r|^15/15! e^|r| < 2^-62`) with coefficients `1/j!` rounded from
//!   double words (`c_rel = 1.0001 u`), then the exact scaling by `2^k`. An
//!   error `d` in the exponent multiplies the result by `e^d`:
//!   `|e^d - 1| <= 1.01 |d|` for `|d| < 10^-3`.
//! * **`x^p = e^{p ln x}`** ([`pow_f64`]): `p l_hi` exactly as a double
//!   word (`two_prod`) plus `p l_lo`; the exponent errs by `|p| E_ln` plus
//!   roundings of the low parts, passed to [`exp_f64`] as `dy`.
//!
//! Everything is refused (`None`) outside these ranges (subnormal or
//! non-finite input, `|y| > 700`); the caller then takes the double-word or
//! MP path.

use super::power::{dw_div, Dw, LN2_C1, LN2_C2, U};
use crate::ball::{two_prod, two_sum};

/// Terms of `R(q) = sum_{1<=k<=LN_TERMS} q^{k-1}/(2k+1)` in [`ln_f64`].
const LN_TERMS: usize = 11;

/// Degree of the Taylor polynomial of `e^r` in [`exp_f64`].
const EXP_DEGREE: usize = 14;

/// `|C3|` of the split `ln 2 = C1 + C2 + C3` of [`super::power`], rounded up.
const LN2_C3_BOUND: f64 = 1.97e-31;

/// Margin for the rounding of the running sums themselves (`gamma_{60} < 2^-40`).
const SUM_MARGIN: f64 = 1.0 + 9.1e-13;

/// `sum_i c[i] x^i` (`c[0]` the constant term) by Horner's rule in f64:
/// `(value, err, abs_sum)` with `|value - sum c*_i x^i| <= err` for any exact
/// coefficients `c*_i` within `c_rel |c_i|` of `c[i]` (`c_rel <= 2^-40`), and
/// `abs_sum >= sum |c_i| |x|^i`. At most 20 coefficients.
pub(super) fn horner(c: &[f64], x: f64, c_rel: f64) -> (f64, f64, f64) {
    debug_assert!(!c.is_empty() && c.len() <= 20);
    let ax = x.abs();
    let last = c.len() - 1;
    let mut p = c[last];
    let mut mu = 0.0f64; // sum |x|^i (|m_i| (1 + u) + |p_i|), Horner-accumulated
    let mut nu = c[last].abs(); // sum |c_i| |x|^i
    for &ci in c[..last].iter().rev() {
        let m = p * x;
        p = m + ci;
        mu = mu * ax + (m.abs() * (1.0 + U) + p.abs());
        nu = nu * ax + ci.abs();
    }
    let nu = nu * SUM_MARGIN;
    let err = (U / (1.0 - U) * mu + c_rel / (1.0 - c_rel) * nu) * SUM_MARGIN;
    (p, err, nu)
}

/// `(1/j!)_{j <= EXP_DEGREE}` in f64, each the nearest double to a double word
/// within `32 j u^2` of `1/j!` (so within `1.0001 u` relative).
fn exp_coefficients() -> &'static [f64; EXP_DEGREE + 1] {
    static TABLE: std::sync::OnceLock<[f64; EXP_DEGREE + 1]> = std::sync::OnceLock::new();
    TABLE.get_or_init(|| {
        let mut out = [1.0; EXP_DEGREE + 1];
        let mut f = Dw::new(1.0);
        for (j, slot) in out.iter_mut().enumerate().skip(1) {
            f = dw_div(f, Dw::new(j as f64));
            *slot = f.hi + f.lo;
        }
        out
    })
}

/// `R(q) = sum_{k>=1} q^{k-1}/(2k+1)` coefficients `(1/(2k+3))_{k < LN_TERMS}`,
/// each correctly rounded (IEEE division, evaluated at compile time).
const LN_COEFFICIENTS: [f64; LN_TERMS] = {
    let mut c = [0.0; LN_TERMS];
    let mut k = 0;
    while k < LN_TERMS {
        c[k] = 1.0 / (2 * k + 3) as f64;
        k += 1;
    }
    c
};

/// `ln(hi + lo)` for `hi > 0` normal and `|lo| <= ulp(hi)`: `(v_hi, v_lo, err)`
/// with `|ln(hi + lo) - (v_hi + v_lo)| <= err`, an absolute error far below
/// `u` (about `2^-60` plus `2^-80 |e|`).
pub(super) fn ln_f64(hi: f64, lo: f64) -> Option<(f64, f64, f64)> {
    if !(hi.is_normal() && hi > 0.0 && lo.is_finite() && lo.abs() <= hi * 2.3e-16) {
        return None;
    }
    // hi = m 2^e, m in [1/sqrt 2, sqrt 2): exact scaling by powers of two.
    let bits = hi.to_bits();
    let mut e = ((bits >> 52) & 0x7ff) as i64 - 1023;
    let mut m = f64::from_bits((bits & 0x000f_ffff_ffff_ffff) | 0x3ff0_0000_0000_0000); // [1, 2)
    if m > std::f64::consts::SQRT_2 {
        m *= 0.5;
        e += 1;
    }
    let t = lo / hi;
    let err_t = U * t.abs() + t * t;
    // s = (m - 1)/(m + 1) as a double word: m - 1 exact (Sterbenz), m + 1 exact
    // as a double word, DWDivDW2 (<= 32 u^2 relative, charged).
    let (dh, dl) = two_sum(m, 1.0);
    let s = dw_div(Dw::new(m - 1.0), Dw { hi: dh, lo: dl });
    // ln m = 2 atanh s = 2 s + 2 s q R(q), q = s^2 <= 0.0295; the second part in f64.
    let q = s.hi * s.hi;
    let (r, r_err, _) = horner(&LN_COEFFICIENTS, q, U);
    let tail = q.powi(LN_TERMS as i32) / ((2 * LN_TERMS + 3) as f64 * (1.0 - q)) * 1.01;
    let h = q * r; // q R(q), two roundings
    // |q~ - s^2| <= (u + 70 u^2) s^2 moves qR(q) by at most 1.02 (u + 70u^2) |qR| (d(qR)/dq <= 1.02 R)
    let h_err = (q * (r_err + tail) + 2.05 * U * h.abs()) * 1.0001 + U * h.abs();
    let t3 = 2.0 * s.hi * h; // one rounding
    let (l_hi, l_e) = two_sum(2.0 * s.hi, t3);
    let l_lo = l_e + 2.0 * s.lo;
    // 2 |s| h_err, the rounding of t3 and of l_lo, |s_dw - s| <= 32 u^2 |s| times 2.07
    let err_l = (2.0 * s.hi.abs() * h_err + U * (t3.abs() + l_lo.abs()) + 67.0 * U * U * s.hi.abs()) * 1.0001;
    // e ln 2 + l + t = (e C1 + l_hi) + (l_lo + (e C2 + t)) + e C3: the first sum
    // exact (two_sum, e C1 exact), the small parts rounded (below 2^11 * 2^-44 + 2 u).
    let ef = e as f64;
    let (v_hi, v_err) = two_sum(ef * LN2_C1, l_hi);
    let small = ef * LN2_C2 + t;
    let small2 = l_lo + small;
    let v_lo = v_err + small2;
    let err_small =
        U * ((ef * LN2_C2).abs() + small.abs() + small2.abs() + v_lo.abs()) * 1.0001 + ef.abs() * LN2_C3_BOUND;
    let (v_hi, v_lo) = two_sum(v_hi, v_lo); // normalised (exact)
    Some((v_hi, v_lo, (err_l + err_t + err_small) * 1.0001))
}

/// `e^y` for `y = y_hi + y_lo` known to within `dy` (absolute), `|y_lo|`
/// far below 1: `(value, rel)` with `|e^{y*} - value| <= rel |value|` for
/// every `|y* - y| <= dy`.
pub(super) fn exp_f64(y_hi: f64, y_lo: f64, dy: f64) -> Option<(f64, f64)> {
    if !(y_hi.abs() <= 700.0 && y_lo.abs() <= 1e-10 && dy >= 0.0 && dy < 1e-6) {
        return None;
    }
    let k = (y_hi * std::f64::consts::LOG2_E).round();
    let (r_hi, r_lo) = two_sum(y_hi, -k * LN2_C1);
    let small = (r_lo + y_lo) - k * LN2_C2;
    let r = r_hi + small;
    if !(r.abs() <= 0.35) {
        return None;
    }
    let c = exp_coefficients();
    let (p, p_err, _) = horner(c, r, 1.0001 * U);
    let trunc = r.abs().powi(EXP_DEGREE as i32 + 1) / 1.3e12 * 1.42; // |r|^15/15! e^0.35 (15! > 1.3e12)
    // exponent error: the roundings of `small` and `r`, |k C3|, and the caller's dy
    let d = U * (r.abs() + (r_lo + y_lo).abs() + small.abs()) * 1.0001 + k.abs() * LN2_C3_BOUND + dy;
    let rel = ((p_err + trunc) / p.abs() * (1.0 + 1e-12) + 1.01 * d) * 1.0001;
    let value = p * 2f64.powi(k as i32);
    value.is_normal().then_some((value, rel))
}

/// `x^p` for `x = hi + lo > 0` (a double word) and an f64 `p`:
/// `(value, rel)` with `|x^p - value| <= rel |value|`. The exponent `p ln x`
/// is carried as `y_hi + y_lo` (`two_prod`), so its error is `|p|` times that
/// of [`ln_f64`] plus roundings far below `u`.
pub(super) fn pow_f64(x: Dw, p: f64) -> Option<(f64, f64)> {
    let (l_hi, l_lo, l_err) = ln_f64(x.hi, x.lo)?;
    let (y_hi, y_err) = two_prod(p, l_hi);
    let y_lo = y_err + p * l_lo;
    let dy = (p.abs() * l_err + U * ((p * l_lo).abs() + y_lo.abs())) * 1.0001;
    exp_f64(y_hi, y_lo, dy)
}

#[cfg(test)]
mod tests {
    use super::super::power::LN2_C3;
    use super::*;
    use rug::ops::Pow;
    use rug::Float;

    /// `|got - want| / |got|` (the bounds are relative to the value returned).
    fn rel_to(got: f64, want: &Float) -> f64 {
        let g = Float::with_val(200, got);
        (Float::with_val(200, &g - want) / &g).abs().to_f64()
    }

    /// Deterministic points: the bounds hold against MPFR at 200 bits, and
    /// stay within a few u (the native 2F1 needs them far below 1e-14).
    #[test]
    fn ln2_split_bound() {
        assert!(LN2_C3.abs() <= LN2_C3_BOUND);
    }

    #[test]
    fn ln_exp_pow_meet_their_bounds() {
        let (mut worst_ln, mut worst_exp, mut worst_pow) = (0.0f64, 0.0f64, 0.0f64);
        for i in 0..20000 {
            let f = (i as f64 * 0.618_033_988_749_895).fract();
            let g = (i as f64 * 0.754_877_666_246_693).fract();
            // ln over 1e-300 .. 1e300 and near 1
            let x = if i % 3 == 0 { 1.0 + (f - 0.5) * 1e-6 } else { 10f64.powf(600.0 * f - 300.0) };
            let lo = x * (g - 0.5) * 2.2e-16;
            let (hi, lo) = two_sum(x, lo);
            let (v, v_lo, err) = ln_f64(hi, lo).unwrap();
            let want = (Float::with_val(200, hi) + lo).ln();
            let abs = Float::with_val(200, Float::with_val(200, v) + v_lo - &want).abs().to_f64();
            assert!(abs <= err, "ln({hi} + {lo}) = {v} + {v_lo}: |error| {abs:e} > bound {err:e}");
            worst_ln = worst_ln.max(err);
            // exp over [-700, 700]
            let y = 1400.0 * f - 700.0;
            let dy = if i % 2 == 0 { 0.0 } else { 1e-17 * y.abs() };
            let (v, rel) = exp_f64(y, 0.0, dy).unwrap();
            for ys in [y - dy, y + dy] {
                let r = rel_to(v, &Float::with_val(200, ys).exp());
                assert!(r <= rel, "exp({ys}) = {v}: rel error {r:e} > bound {rel:e}");
            }
            worst_exp = worst_exp.max(rel - 1.0102 * dy); // the caller's dy costs ~dy
            // pow on the Pfaff domain: x = 1 - z in (1.5, 11] and up to 1e6, p in [-10, 10]
            let z = if i % 4 == 0 { -(10f64.powf(6.0 * f)) - 0.5 } else { -10.0 * f - 0.5 };
            let omz = Dw::diff(1.0, z);
            let p = 20.0 * g - 10.0;
            let (v, rel) = pow_f64(omz, p).unwrap();
            let want = Float::with_val(200, Float::with_val(200, omz.hi) + omz.lo).pow(Float::with_val(200, p));
            let r = rel_to(v, &want);
            assert!(r <= rel, "({z})^{p}: rel error {r:e} > bound {rel:e}");
            // the exponent carries |p| times ln's absolute error (far below u), exp ~6u
            worst_pow = worst_pow.max(rel / (6.0 + 0.1 * p.abs()));
        }
        assert!(worst_ln < 0.05 * U, "{worst_ln:e} (absolute)");
        assert!(worst_exp < 8.0 * U, "{worst_exp:e}");
        assert!(worst_pow < U, "{worst_pow:e} (per (6 + |p|/10) u)");
        assert!(ln_f64(0.0, 0.0).is_none() && ln_f64(-1.0, 0.0).is_none() && ln_f64(f64::NAN, 0.0).is_none());
        assert!(exp_f64(701.0, 0.0, 0.0).is_none() && exp_f64(f64::NAN, 0.0, 0.0).is_none());
    }
}
