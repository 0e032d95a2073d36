//! Certified `ln |Gamma(x)|` and its sign in f64/double-word arithmetic, for the
//! Gamma ratios of the native f64 `2F1` transformations.
//!
//! # Method
//!
//! `x = x_hi + x_lo` a double word, `-30 < x <= 10^6`, not a non-positive
//! integer; `u = 2^-53`.
//!
//! * **Shift.** With `K = max(0, ceil(10 - x_hi))`, `Gamma(x) = Gamma(y) / P`,
//!   `y = x + K >= 10`, `P = prod_{j<K} (x + j)` [DLMF 5.5.1]. Each factor
//!   `x + j` is exact as a double word (`two_sum`, plus `x_lo` with one
//!   rounding far below `u |x + j|`), the product in double words (DWTimesDW1,
//!   `7 u^2` each, charged `8 u^2`), so `|P~ - P| <= (8K + 1) u^2 |P~|`; its
//!   logarithm by [`ln_f64`] (a double word, absolute error `~2^-60`). The sign
//!   of `Gamma(x)` is the sign of `P`.
//! * **Stirling** [DLMF 5.11.1]: `ln Gamma(y) = (y - 1/2) ln y - y + ln(2 pi)/2
//!   + sum_{k=1}^{8} B_{2k} / (2k (2k-1) y^{2k-1}) + R`, and for real `y > 0` the
//!   remainder is bounded by the first neglected term and has its sign
//!   [DLMF 5.11(ii)]: `|R| <= (43867/244188) / y^17 < 1.8 10^-18` at `y >= 10`.
//!   `(y - 1/2) ln y` as a double word (`y_hi - 1/2` exact, `two_prod`, the
//!   cross terms rounded); its error is `|y - 1/2|` times that of `ln y`.
//!   The correction sum `D = (1/y) S(1/y^2)` (`|D| <= 1/120`) in f64 by
//!   [`horner`] on the rational coefficients `fl(B_{2k}/(2k(2k-1)))`
//!   (one division of exact integers each: `c_rel = u`), with `1/y`, `1/y^2`
//!   rounded (a relative error of `3u` in `1/y^2` moves `D` by `<= 3 u |D|`).
//!   `ln(2 pi)/2` is a double word to `2^-106` (tested against MPFR).
//!
//! Everything outside these ranges (a pole, `x <= -30`, a shift product that
//! over- or underflows) returns `None`: the caller takes another path.

use super::power::{dw_mul, Dw, U};
use super::power_f64::{horner, ln_f64};
use crate::ball::{two_prod, two_sum};

/// `ln(2 pi)/2 = HALF_LN_2PI_HI + HALF_LN_2PI_LO` to about `2^-106`.
const HALF_LN_2PI_HI: f64 = 0.9189385332046728;
const HALF_LN_2PI_LO: f64 = -3.8782941580672414e-17;

/// `ln |Gamma(x)|` as a double word with an absolute error bound, and the sign
/// of `Gamma(x)`.
#[derive(Clone, Copy, Debug)]
pub(super) struct LnGamma {
    pub hi: f64,
    pub lo: f64,
    pub err: f64,
    pub negative: bool,
}

/// `B_{2k}/(2k(2k-1))`, `k = 1..=8`, as `(numerator, denominator)`.
const STIRLING: [(f64, f64); 8] =
    [(1.0, 12.0), (-1.0, 360.0), (1.0, 1260.0), (-1.0, 1680.0), (1.0, 1188.0), (-691.0, 360360.0), (1.0, 156.0), (-3617.0, 122400.0)];

/// The Stirling coefficients, each one correctly rounded division of exact
/// integers (evaluated at compile time): `c_rel = u`.
const STIRLING_COEFFICIENTS: [f64; 8] = {
    let mut c = [0.0; 8];
    let mut i = 0;
    while i < 8 {
        c[i] = STIRLING[i].0 / STIRLING[i].1;
        i += 1;
    }
    c
};

/// Bound of the first neglected Stirling term at `y = 10`, scaled: `|R| <= R10 (10/y)^17`.
const R10: f64 = 1.8e-18;

/// `ln |Gamma(x)|` for a double word `x` (see the module doc); `None` at a
/// pole, for `x <= -30` or `x > 10^6`.
pub(super) fn ln_gamma_f64(x: Dw) -> Option<LnGamma> {
    if !(x.hi > -30.0 && x.hi <= 1e6 && x.lo.is_finite()) {
        return None;
    }
    let k = if x.hi < 10.0 { (10.0 - x.hi).ceil() } else { 0.0 };
    // P = prod_{j<K} (x + j) in double words
    let mut p = Dw::new(1.0);
    let mut factor_rel = 0.0f64; // sum of the relative roundings of the factors
    for j in 0..k as i64 {
        let (h, e) = two_sum(x.hi, j as f64);
        let lo = e + x.lo; // one rounding, <= u |lo|
        let (fh, fl) = two_sum(h, lo);
        if fh == 0.0 {
            return None; // a pole
        }
        factor_rel += U * lo.abs() / fh.abs() * 1.01;
        p = dw_mul(p, Dw { hi: fh, lo: fl });
    }
    let negative = p.hi < 0.0;
    let (ph, pl) = if negative { (-p.hi, -p.lo) } else { (p.hi, p.lo) };
    // y = x + K
    let (yh, ye) = two_sum(x.hi, k);
    let y = {
        let (h, l) = two_sum(yh, ye + x.lo);
        Dw { hi: h, lo: l }
    };
    // (y - 1/2) ln y
    let (l_hi, l_lo, l_err) = ln_f64(y.hi, y.lo)?;
    let hm = y.hi - 0.5; // exact: y_hi >= 10 < 2^52
    let (a_hi, a_e) = two_prod(hm, l_hi);
    let cross = hm * l_lo + y.lo * l_hi;
    let a_lo = a_e + cross;
    let err_a = (hm + y.lo).abs() * l_err * 1.0001
        + U * ((hm * l_lo).abs() + (y.lo * l_hi).abs() + cross.abs() + a_lo.abs()) * 1.01
        + (y.lo * l_lo).abs() * 1.01;
    // D = (1/y) S(1/y^2)
    let inv = 1.0 / y.hi;
    let inv2 = inv * inv;
    let (sv, s_err, s_abs) = horner(&STIRLING_COEFFICIENTS, inv2, U);
    let d = inv * sv;
    // 1/y_hi vs 1/y: |y_lo|/y^2; rounding of inv (u), inv2 (3u on S's argument: |S'| x <= |S|... bounded by s_abs)
    let err_d = (inv * (s_err + 3.01 * U * s_abs) + 2.01 * U * d.abs() + y.lo.abs() * inv2 * 0.1) * 1.0001 + R10 * (10.0 * inv).powi(17) * 1.0001;
    // ln Gamma(y) = a - y + ln(2 pi)/2 + D, as a double word
    let (s1, e1) = two_sum(a_hi, -y.hi);
    let (s2, e2) = two_sum(s1, HALF_LN_2PI_HI);
    let partial = (a_lo - y.lo) + (HALF_LN_2PI_LO + d);
    let small = partial + (e1 + e2);
    let err_sum =
        U * ((a_lo - y.lo).abs() + (HALF_LN_2PI_LO + d).abs() + (e1 + e2).abs() + partial.abs() + small.abs()) * 1.01;
    // minus ln |P|
    let (lp_hi, lp_lo, lp_err) = if k > 0.0 { ln_f64(ph, pl)? } else { (0.0, 0.0, 0.0) };
    // |P~ - P| / |P~|: the products and the factors' roundings; ln moves by <= 1.01 p_rel
    let p_rel = ((8.0 * k + 1.0) * U * U + factor_rel) * 1.01;
    let (g_hi, g_e) = two_sum(s2, -lp_hi);
    let g_lo = g_e + (small - lp_lo);
    let err = (err_a + err_d + err_sum + lp_err + 1.01 * p_rel + U * (g_lo.abs() + (small - lp_lo).abs())) * 1.0001;
    let (hi, lo) = two_sum(g_hi, g_lo); // normalised (exact)
    Some(LnGamma { hi, lo, err, negative })
}

#[cfg(test)]
mod tests {
    use super::*;
    use rug::Float;

    #[test]
    fn half_ln_2pi_split() {
        let pi = Float::with_val(300, rug::float::Constant::Pi);
        let want = Float::with_val(300, pi * 2u32).ln() / 2u32;
        let got = Float::with_val(300, HALF_LN_2PI_HI) + HALF_LN_2PI_LO;
        assert!(Float::with_val(300, got - &want).abs().to_f64() < 2f64.powi(-104));
    }

    /// The bound holds against MPFR's `lgamma` at 200 bits over `(-30, 1e6)`,
    /// next to the poles and at small arguments, and stays within a few u.
    #[test]
    fn ln_gamma_meets_its_bound() {
        let mut worst = 0.0f64;
        for i in 0..20000 {
            let f = (i as f64 * 0.618_033_988_749_895).fract();
            let g = (i as f64 * 0.754_877_666_246_693).fract();
            let xh = match i % 4 {
                0 => -29.5 + 39.0 * f,                          // the shifted range, negative included
                1 => 10f64.powf(6.0 * f - 3.0),                 // 1e-3 .. 1e3
                2 => -((i % 29) as f64) + (g - 0.5) * 1e-6,     // next to the poles
                _ => 10.0 + 1e6 * f,                            // Stirling directly
            };
            if xh == xh.round() && xh <= 0.0 {
                continue;
            }
            let x = {
                let (h, l) = two_sum(xh, xh * (g - 0.5) * 2.2e-16);
                Dw { hi: h, lo: l }
            };
            let r = ln_gamma_f64(x).unwrap_or_else(|| panic!("ln_gamma_f64({x:?}) refused"));
            let xf = Float::with_val(200, x.hi) + x.lo;
            let (want, ord) = xf.clone().ln_abs_gamma();
            let abs = Float::with_val(200, Float::with_val(200, r.hi) + r.lo - &want).abs().to_f64();
            assert!(abs <= r.err, "ln|Gamma({x:?})| = {} + {}: |error| {abs:e} > bound {:e}", r.hi, r.lo, r.err);
            assert_eq!(r.negative, ord == std::cmp::Ordering::Less, "sign of Gamma({x:?})");
            worst = worst.max(r.err / (1.0 + want.to_f64().abs()));
        }
        assert!(worst < 4.0 * U, "{worst:e}");
        assert!(ln_gamma_f64(Dw::new(-3.0)).is_none());
        assert!(ln_gamma_f64(Dw::new(-31.0)).is_none());
    }
}
