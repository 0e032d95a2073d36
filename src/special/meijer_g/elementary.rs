//! `ln y` and `ln((1-y)/y)` in f64 with proven bounds, for the f64 paths of
//! `G(k, y)` ([`super::native`], [`super::beta_series`]).
//!
//! # Method
//!
//! * `2 atanh(v)` for `|v| <= 0.18` given `|v~ - v| <= e_v` ([`two_atanh_bounded`]):
//!   `atanh(v) = v P(v^2)`, `P(s) = sum_j s^j/(2j+1)` [DLMF 4.6.1 with 4.37.24] by
//!   Horner with Higham's running bound (*Accuracy and Stability*, Alg. 5.1), the
//!   coefficients' roundings `u P(|s|)`, the truncation `s^J/((2J+1)(1-s))` and the
//!   input error through `P'(s) <= 1/(2(1-s)^2)`.
//! * `ln y` ([`ln_bounded`]): `y = m 2^e`, `m in [1/sqrt2, sqrt2)`,
//!   `ln y = e ln2 + 2 atanh(v)`, `v = (m-1)/(m+1)` (`m - 1` exact by Sterbenz; two
//!   roundings: `|v~ - v| <= gamma_2 |v|`), `|v| <= 0.1716`; `|ln2 - fl(ln2)| <= 2.4e-17`.
//! * `ln(w/y)`, `w = 1 - y`, `1/2 <= y < 1` ([`ln_w_over_y_bounded`]): `w/y = 1 + d`,
//!   `d = (1 - 2y)/y` (`1 - 2y` exact by Sterbenz, `d` one rounding); for
//!   `d >= -0.3`, `ln(1 + d) = 2 atanh(d/(2 + d))` (three roundings after `d`'s:
//!   `|v~ - v| <= 3.3 u |v~|`), so the result is relative also where it vanishes
//!   (`y -> 1/2`, next to the zeros of `G(k, .)` for large `k`); below,
//!   `ln(fl(w/y))` (`|ln(w/y)| >= 0.35`, the quotient's rounding adds `u/(1-u)`).

/// An f64 and a bound on its error.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Val {
    pub v: f64,
    pub e: f64,
}

const U: f64 = f64::EPSILON / 2.0;

/// `2 atanh(v)` for `|v| <= 0.18`, where the exact argument `v*` satisfies
/// `|v - v*| <= ev` (module docs).
pub(crate) fn two_atanh_bounded(v: f64, ev: f64) -> Option<Val> {
    if !(v.abs() + ev <= 0.18) {
        return None;
    }
    let s = v * v;
    let s_up = (v.abs() + ev) * (v.abs() + ev) * (1.0 + 4.0 * U);
    let es = s_up - s + U * s; // |s~ - v*^2| (covers the rounding of s and the error of v)
    // Horner over J terms, J with s^J/((2J+1)(1-s)) <= 2^-64
    let mut j_terms = 1usize;
    let mut sp = s_up;
    while sp / ((2 * j_terms + 1) as f64 * (1.0 - s_up)) > 1.0 / (1u64 << 63) as f64 / 2.0 {
        sp *= s_up;
        j_terms += 1;
    }
    let mut p = 1.0 / (2 * (j_terms - 1) + 1) as f64;
    let mut mu = p / 2.0;
    for j in (0..j_terms - 1).rev() {
        p = p * s + 1.0 / (2 * j + 1) as f64;
        mu = s * mu + p.abs();
    }
    let p_abs = 1.0 / (1.0 - s_up);
    let trunc = sp / ((2 * j_terms + 1) as f64 * (1.0 - s_up));
    let ep = U * (2.0 * mu - p.abs()) * 1.01 + U * p_abs + trunc + es / (2.0 * (1.0 - s_up) * (1.0 - s_up));
    let at = v * p; // atanh(v)
    let e_at = v.abs() * ep + p.abs() * ev + ep * ev + U * at.abs();
    Some(Val { v: 2.0 * at, e: 2.0 * e_at })
}

/// `ln y` for `0 < y <= 1` with a proven bound.
pub(crate) fn ln_bounded(y: f64) -> Option<Val> {
    if !(y > 0.0 && y <= 1.0) || y < f64::MIN_POSITIVE {
        return None;
    }
    let bits = y.to_bits();
    let mut e = ((bits >> 52) & 0x7ff) as i64 - 1022;
    let mut m = f64::from_bits((bits & !(0x7ffu64 << 52)) | (1022u64 << 52)); // [0.5, 1)
    if m < std::f64::consts::FRAC_1_SQRT_2 {
        m *= 2.0;
        e -= 1;
    }
    let v = (m - 1.0) / (m + 1.0);
    let g2 = 2.0 * U / (1.0 - 2.0 * U);
    let at2 = two_atanh_bounded(v, g2 * v.abs())?;
    let l1 = e as f64 * std::f64::consts::LN_2;
    let e_l1 = (e as f64).abs() * 2.4e-17 + U * l1.abs();
    let l = l1 + at2.v;
    Some(Val { v: l, e: e_l1 + at2.e + U * l.abs() })
}

/// `ln((1 - y)/y)` for `1/2 <= y < 1` with a proven bound, relative where it
/// vanishes at `y = 1/2` (module docs).
pub(crate) fn ln_w_over_y_bounded(y: f64) -> Option<Val> {
    if !(0.5..1.0).contains(&y) {
        return None;
    }
    let d = (1.0 - 2.0 * y) / y; // 1 - 2y exact (Sterbenz), one rounding
    if d >= -0.3 {
        let v = d / (2.0 + d);
        two_atanh_bounded(v, 3.3 * U * v.abs())
    } else {
        let l = ln_bounded((1.0 - y) / y)?; // 1 - y exact; the quotient's rounding: u/(1-u) in ln
        Some(Val { v: l.v, e: l.e + 1.0001 * U })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rug::Float;

    #[test]
    fn ln_bound_holds() {
        for &y in &[1.0, 0.5, std::f64::consts::FRAC_1_SQRT_2, 0.75, 1e-300, 0.999999, 0.1, 3.0e-5] {
            let l = ln_bounded(y).unwrap();
            let exact = Float::with_val(200, y).ln();
            let d = Float::with_val(200, &exact - l.v).abs().to_f64();
            assert!(d <= l.e, "y={y}: {} +/- {} vs {exact}", l.v, l.e);
            assert!(l.e <= 4e-16 * l.v.abs().max(1.0), "y={y}: {}", l.e);
        }
    }

    #[test]
    fn ln_w_over_y_bound_holds_and_is_relative_next_to_one_half() {
        let mut ys = vec![0.5, 0.5f64.next_up(), 0.5 + 1e-12, 0.5 + 1e-6, 0.5007, 0.5075, 0.55, 0.588, 0.5883, 0.6, 0.75, 0.9, 0.97, 0.999, 1.0 - 1e-12];
        ys.push(1.0 / 1.7);
        ys.push((1.0f64 / 1.7).next_up());
        for &y in &ys {
            let l = ln_w_over_y_bounded(y).unwrap();
            let yf = Float::with_val(300, y);
            let exact = (Float::with_val(300, 1 - &yf) / &yf).ln();
            let d = Float::with_val(300, &exact - l.v).abs().to_f64();
            assert!(d <= l.e, "y={y}: {} +/- {} vs {exact}", l.v, l.e);
            // relative near 1/2, and at most a few u absolute elsewhere
            assert!(l.e <= 8.0 * U * l.v.abs() || l.e <= 6.0 * U, "y={y}: {} +/- {}", l.v, l.e);
        }
        assert!(ln_w_over_y_bounded(0.4).is_none() && ln_w_over_y_bounded(1.0).is_none());
    }
}
