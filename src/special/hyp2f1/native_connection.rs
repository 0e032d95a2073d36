//! The connection formulas of the native `2F1` path ([`super::native`]):
//! `2F1` at `z <= -4` from two series in `x = 1/(1-z)` [DLMF 15.8.3], and at
//! `9/10 < z < 1` from two series in `x = 1 - z` [DLMF 15.8.4], each with
//! reciprocal Gammas from [`super::rgamma_f64`] and the f64 series of
//! [`super::native_series`]. The bounds are derived at
//! [`connection_inv_one_minus_z`] and [`connection_one_minus_z`]; `None` where
//! they cannot certify (`a - b` or `c - a - b` within [`CONNECTION_MIN_FRAC`]
//! of an integer, a Gamma that cannot be bounded).

use super::native_series::{series, series_two, Param};
use super::power::{round_small, U};
use super::power_f64::{ln_f64, pow_dw_exponent, pow_from_ln};
use super::rgamma_f64::rgamma_batch;
use crate::ball::{two_sum, Dd};

/// The connection formulas need `a - b` (or `c - a - b`) this far from an
/// integer (closer, their two terms blow up and cancel; Pfaff or the direct
/// series takes over).
pub(super) const CONNECTION_MIN_FRAC: f64 = 0.05;

/// `p + 1` for a double word `p`, as a series parameter. The low word is
/// rounded once (`<= u |lo|`); [`series`] uses it only through `|lo|` (the
/// perturbation bound), so it is stored enlarged by `4u` to cover that.
pub(super) fn plus_one(p: Dd) -> Param {
    let (hi, e) = two_sum(p.hi, 1.0);
    let lo = e + p.lo;
    Param { hi, lo: lo * (1.0 + 4.0 * U) }
}

/// A reciprocal Gamma (as [`rgamma_batch`] returns it) with its relative
/// bound: `Some(None)` for an exact zero.
pub(super) fn rgamma_rel(r: Option<(f64, f64)>) -> Option<Option<(f64, f64)>> {
    let (v, e) = r?;
    if v == 0.0 {
        return (e == 0.0).then_some(None);
    }
    Some(Some((v, e / v.abs())))
}

/// `(1/G(n1)) (1/G(n2)) / ((1/G(d1)) (1/G(d2)))`, a connection coefficient, with
/// its relative bound, from the four reciprocal Gammas; `Some(None)` when a
/// numerator vanishes exactly (the term is zero). Three roundings: with `r_*`
/// the relative bounds of the four reciprocal Gammas, `|C~ - C| <= rho |C~|`,
/// `rho = s (1 + s)`, `s = r_n1 + r_n2 + 1.01 (r_d1 + r_d2) + 3.01 u`
/// (`e^s - 1 <= s (1 + s)`, `1/(1 - r) <= 1 + 1.01 r` for `r <= 1/100`).
pub(super) fn gamma_coefficient(num: [Option<(f64, f64)>; 2], den: [Option<(f64, f64)>; 2]) -> Option<Option<(f64, f64)>> {
    let Some((n1, r1)) = rgamma_rel(num[0])? else { return Some(None) };
    let Some((n2, r2)) = rgamma_rel(num[1])? else { return Some(None) };
    let (d1, q1) = rgamma_rel(den[0])??;
    let (d2, q2) = rgamma_rel(den[1])??;
    let s = r1 + r2 + 1.01 * (q1 + q2) + 3.01 * U;
    if !(s <= 0.01 && q1 <= 0.01 && q2 <= 0.01) {
        return None;
    }
    Some(Some((n1 * n2 / (d1 * d2), s * (1.0 + s) * 1.0001)))
}

/// Adds the term `coef pw sum` of a connection formula to `(value, err)`:
/// relative bounds `coef_rel`, `pw_rel`, the series' absolute `err_s`, two
/// roundings for the products and one for the sum.
pub(super) fn add_connection_term(acc: (f64, f64), (coef, coef_rel): (f64, f64), (pw, pw_rel): (f64, f64), (sum, err_s): (f64, f64)) -> (f64, f64) {
    let (value, err) = acc;
    let pre = coef * pw;
    // |pre~ - pre| <= pr |pre~|: the two relative bounds and one rounding
    let pr = (coef_rel + pw_rel + coef_rel * pw_rel + U) * 1.0001;
    let t = pre * sum;
    let total = value + t;
    let err = err + (pre.abs() * err_s * (1.0 + 2.0 * pr) + (1.01 * pr + U) * t.abs()) * (1.0 + 4.0 * U) + U * total.abs();
    (total, err)
}

/// `2F1(a, b; c; z)` for `z <= -1` by the connection formula in `x = 1/(1-z)`
/// [DLMF 15.8.3], for `a - b` at least [`CONNECTION_MIN_FRAC`] from an integer:
///
/// ```text
/// 2F1(a, b; c; z) = sum over (p, q) in {(a, b), (b, a)} of
///     Gamma(c) Gamma(q-p) / (Gamma(q) Gamma(c-p)) (1-z)^{-p} 2F1(p, c-q; p-q+1; x)
/// ```
///
/// `(value, err)` with a proven bound, or `None`. The coefficients from
/// [`gamma_coefficient`], both powers from one [`ln_f64`] of the exact double
/// word `1 - z`; `x = fl(1/(1-z)_hi)` is within `2.01 u` relative.
pub(super) fn connection_inv_one_minus_z(a: f64, b: f64, c: f64, z: f64, stop: f64) -> Option<(f64, f64)> {
    let amb = Dd::diff(a, b);
    if !(z <= -1.0) || (amb.hi - round_small(amb.hi)).abs() < CONNECTION_MIN_FRAC {
        return None;
    }
    let omz = Dd::diff(1.0, z);
    let x = 1.0 / omz.hi; // |x - 1/(1-z)| <= 2.01 u x
    let ln_omz = ln_f64(omz.hi, omz.lo)?;
    // the seven reciprocal Gammas at once (interleaved Horner sums)
    let [g_c, g_a, g_b, g_ca, g_cb, g_amb, g_bma] =
        rgamma_batch([Dd::from_f64(c), Dd::from_f64(a), Dd::from_f64(b), Dd::diff(c, a), Dd::diff(c, b), amb, Dd::diff(b, a)]);
    let lanes = [(a, b), (b, a)].map(|(p, q)| [Param::exact(p), Param::from_dw(Dd::diff(c, q)), plus_one(Dd::diff(p, q))]);
    // both series in one two-lane loop where it applies, else one by one
    let both = series_two(lanes, x, 2.01 * U, stop);
    let mut acc = (0.0f64, 0.0f64);
    for (i, (p, num, den)) in [(a, [g_b, g_ca], [g_c, g_bma]), (b, [g_a, g_cb], [g_c, g_amb])].into_iter().enumerate() {
        let Some(coef) = gamma_coefficient(num, den)? else { continue };
        let pw = pow_from_ln(ln_omz, -p)?;
        let [p1, p2, q] = lanes[i];
        let sum = match both {
            Some(sums) => sums[i],
            None => series(p1, p2, q, x, 2.01 * U, stop)?,
        };
        acc = add_connection_term(acc, coef, pw, sum);
    }
    Some((acc.0, acc.1 * (1.0 + 4.0 * U)))
}

/// `2F1(a, b; c; z)` for `1/2 < z < 1` by the connection formula in `x = 1 - z`
/// [DLMF 15.8.4, 15.10.21], for `s = c - a - b` at least [`CONNECTION_MIN_FRAC`]
/// from an integer (closer, the log case):
///
/// ```text
/// 2F1(a, b; c; z) = Gamma(c) Gamma(s) / (Gamma(c-a) Gamma(c-b)) 2F1(a, b; 1-s; x)
///                 + x^s Gamma(c) Gamma(-s) / (Gamma(a) Gamma(b)) 2F1(c-a, c-b; 1+s; x)
/// ```
///
/// `x = 1 - z` is exact (Sterbenz). `s` is the double word
/// `two_sum(two_sum(c, -a).hi, -b)` with the low parts added once: it errs by
/// at most `u |lo|`, below `2^-100 |s|`; that moves `1/Gamma(+-s)` by a relative
/// `|psi| 2^-100 < 2^-90` (`|s + n| >= 0.05`) and the power by `|ln x| 2^-100`,
/// both covered by the `2^-80` relative added to the coefficients. The series'
/// parameters `1 -+ s` carry `|lo|` enlarged by `4u` (the perturbation bound of
/// [`series`]).
pub(super) fn connection_one_minus_z(a: f64, b: f64, c: f64, z: f64, stop: f64) -> Option<(f64, f64)> {
    if !(z > 0.5 && z < 1.0) {
        return None;
    }
    let (h1, l1) = two_sum(c, -a);
    let (h2, l2) = two_sum(h1, -b);
    let s = Dd { hi: h2, lo: l1 + l2 };
    if (s.hi - round_small(s.hi)).abs() < CONNECTION_MIN_FRAC {
        return None;
    }
    const S_SLACK: f64 = 8.271806125530277e-25; // 2^-80
    let neg_s = Dd { hi: -s.hi, lo: -s.lo };
    let x = 1.0 - z;
    let mut acc = (0.0f64, 0.0f64);
    let widen = |p: Param| Param { hi: p.hi, lo: p.lo.abs() * (1.0 + 4.0 * U) + 2.0 * U * s.lo.abs() };
    // the seven reciprocal Gammas at once (interleaved Horner sums)
    let [g_ca, g_cb, g_c, g_s, g_a, g_b, g_neg_s] =
        rgamma_batch([Dd::diff(c, a), Dd::diff(c, b), Dd::from_f64(c), s, Dd::from_f64(a), Dd::from_f64(b), neg_s]);
    let lanes = [
        [Param::exact(a), Param::exact(b), widen(plus_one(neg_s))],
        [Param::from_dw(Dd::diff(c, a)), Param::from_dw(Dd::diff(c, b)), widen(plus_one(s))],
    ];
    // both series in one two-lane loop where it applies, else one by one
    let both = series_two(lanes, x, 0.0, stop);
    let sum = |i: usize| match both {
        Some(sums) => Some(sums[i]),
        None => series(lanes[i][0], lanes[i][1], lanes[i][2], x, 0.0, stop),
    };
    if let Some((coef, rel)) = gamma_coefficient([g_ca, g_cb], [g_c, g_s])? {
        acc = add_connection_term(acc, (coef, rel + S_SLACK), (1.0, 0.0), sum(0)?);
    }
    if let Some((coef, rel)) = gamma_coefficient([g_a, g_b], [g_c, g_neg_s])? {
        let pw = pow_dw_exponent(ln_f64(x, 0.0)?, s)?;
        acc = add_connection_term(acc, (coef, rel + S_SLACK), (pw.0, pw.1 + S_SLACK), sum(1)?);
    }
    Some((acc.0, acc.1 * (1.0 + 4.0 * U)))
}
