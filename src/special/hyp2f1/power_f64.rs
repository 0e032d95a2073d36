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
//! * **`ln x`** ([`ln_f64`]), `x = hi + lo > 0`, table-driven: `hi = m 2^e`
//!   exactly with `m in [1, 2)`; `ln(1 + lo/hi)` is `t = fl(lo/hi)` with error
//!   `<= u |t| + t^2`. The top 7 bits of `m` pick `c = 1 + (j + 1/2)/128`
//!   (exact, `|m - c| <= 2^-8`) and `ln c = L_hi + L_lo` (MPFR, to `~2^-106`);
//!   `ln m = ln c + 2 atanh s`, `s = (m - c)/(m + c)` [DLMF 4.37.24] in f64
//!   (`m - c` exact by Sterbenz, two roundings: `|s~ - s| <= 2.01 u |s|`,
//!   `|s| <= 2^-9`, which moves `2 atanh s` by `<= 4.03 u |s| ~ 2^-60`).
//!   `2 atanh s = 2 s + 2 s^3 (1/3 + s^2/5) + R`, `|R| <= 2 |s|^7/(7 (1 - s^2)) < 2^-65`,
//!   the cubic part (`<= 5 10^-9`) in f64. Then
//!   `ln x = ((e C1 + L_hi) + 2 s) + (L_lo + e C2 + cubic + t) + e C3` with
//!   `ln 2 = C1 + C2 + C3` (`e C1` exact: `C1` has 42 bits, `|e| < 2^11`),
//!   returned as a double word: the first sums exact (`two_sum`), the small
//!   parts rounded, `|e C3| < 2^11 * 2^-102`. The absolute error is about
//!   `2^-60`, so `p ln x` carries `|p|` times that.
//! * **`e^y`** ([`exp_f64`]), `y = y_hi + y_lo`, `|y_hi| <= 700`, known to
//!   `dy` (absolute), table-driven (Tang's method): `ln 2/64 = D1 + D2 + D3`
//!   (`D1` with 32 significant bits, `D2` the next 53, `|D3|` bounded; from
//!   MPFR), `k = round(64 y_hi/ln 2)`, `r1 = y_hi - k D1` exact (`k D1` exact
//!   for `|k| < 2^17`; Sterbenz, `|r1| <= D1/2 + ...`),
//!   (`r1` is a multiple of `2^-60` below `2^-7`),
//!   `r~ = fl(fl(r1 - fl(k D2)) + y_lo)`: `r~` errs by those three roundings and
//!   `|k D3|`, `|r~| <= 0.0055`. `e^r - 1 = r + r^2 P(r)` with `P` of degree 4
//!   (truncation `<= |r|^7/7! e^|r| < 2^-66`), `r^2 P` in f64 (charged
//!   thirteen roundings on a term `<= 1.6 10^-5`). With `k = 64 n + j`,
//!   `e^y = 2^n T_j (1 + q)`, `T_j = 2^(j/64)` a double word `t_h + t_l`
//!   (MPFR, within `2^-104` relative): `v = t_h + fl(fl(t_h q) + t_l)`, three
//!   roundings and the dropped `t_l q`; then the exact scaling by `2^n`. An
//!   error `d` in the exponent multiplies the result by `e^d`:
//!   `|e^d - 1| <= 1.01 |d|` for `|d| < 10^-3`.
//! * **`x^p = e^{p ln x}`** ([`pow_f64`]): `p l_hi` exactly as a double
//!   word (`two_prod`) plus `p l_lo`; the exponent errs by `|p| E_ln` plus
//!   roundings of the low parts, passed to [`exp_f64`] as `dy`.
//!
//! Everything is refused (`None`) outside these ranges (subnormal or
//! non-finite input, `|y| > 700`); the caller then takes the double-word or
//! MP path.

use super::power::{round_small, LN2_C1, LN2_C2, U};
use crate::ball::{two_prod, two_sum, Dd};

/// `|C3|` of the split `ln 2 = C1 + C2 + C3` of [`super::power`], rounded up.
const LN2_C3_BOUND: f64 = 1.97e-31;

/// `ln(hi + lo)` for `hi > 0` normal and `|lo| <= ulp(hi)`: `(v_hi, v_lo, err)`
/// with `|ln(hi + lo) - (v_hi + v_lo)| <= err`, an absolute error far below
/// `u` (about `2^-60` plus `2^-80 |e|`). Table-driven (module docs).
pub(super) fn ln_f64(hi: f64, lo: f64) -> Option<(f64, f64, f64)> {
    if !(hi.is_normal() && hi > 0.0 && lo.is_finite() && lo.abs() <= hi * 2.3e-16) {
        return None;
    }
    // hi = m 2^e, m in [1, 2): exact scaling by a power of two
    let bits = hi.to_bits();
    let e = ((bits >> 52) & 0x7ff) as i64 - 1023;
    let m = f64::from_bits((bits & 0x000f_ffff_ffff_ffff) | 0x3ff0_0000_0000_0000);
    let j = ((bits >> (52 - LN_TABLE_BITS)) & ((1 << LN_TABLE_BITS) - 1)) as usize;
    let table = ln_table();
    let c = 1.0 + (j as f64 + 0.5) / LN_TABLE_SIZE as f64; // exact
    let (l_hi, l_lo) = table.ln_c[j];
    let t = lo / hi;
    let err_t = U * t.abs() + t * t;
    // s = (m - c)/(m + c): m - c exact (Sterbenz), two roundings; |s| <= 2^-9
    let s = (m - c) / (m + c);
    let s2 = s * s;
    // 2 atanh s = 2 s + 2 s^3 (1/3 + s^2/5) + R, |R| <= 2 |s|^7 / (7 (1 - s^2))
    let small = 2.0 * s * s2 * (LN_THIRD + s2 * LN_FIFTH);
    // e ln 2 + ln c + 2 s + small + t: the first three summed exactly (e C1 exact)
    let ef = e as f64;
    let (a, a_err) = two_sum(ef * LN2_C1, l_hi);
    let (b, b_err) = two_sum(a, 2.0 * s);
    let low1 = ef * LN2_C2 + l_lo;
    let low2 = low1 + (small + t);
    let low = (a_err + b_err) + low2;
    let (v_hi, v_lo) = two_sum(b, low);
    // |s~ - s| <= 2.01 u |s| moves 2 atanh by <= 2 (2.01 u |s|)/(1 - s^2); the
    // small part has eight roundings on |small| <= 5e-9; the rest one each
    let err_s = 4.03 * U * s.abs() + 2.0 * s2 * s2 * s2 * s.abs() / 7.0 * 1.0001 + 8.0 * U * small.abs();
    let err_low = U * ((ef * LN2_C2).abs() + low1.abs() + (small + t).abs() + low2.abs() + (a_err + b_err).abs() + low.abs() + v_lo.abs());
    let err = (err_s + err_low * 1.0001 + err_t + ef.abs() * LN2_C3_BOUND + table.ln_c_err) * 1.0001;
    Some((v_hi, v_lo, err))
}

/// Bits of the mantissa that pick the table entry of [`ln_f64`].
const LN_TABLE_BITS: u32 = 7;
const LN_TABLE_SIZE: usize = 1 << LN_TABLE_BITS;
const LN_THIRD: f64 = 1.0 / 3.0;
const LN_FIFTH: f64 = 1.0 / 5.0;

/// `ln(1 + (j + 1/2)/128) = hi + lo`, within `ln_c_err` (absolute).
struct LnTable {
    ln_c: [(f64, f64); LN_TABLE_SIZE],
    ln_c_err: f64,
}

/// The table from MPFR at 256 bits, built on first use.
fn ln_table() -> &'static LnTable {
    static TABLE: std::sync::OnceLock<LnTable> = std::sync::OnceLock::new();
    TABLE.get_or_init(|| {
        use rug::Float;
        let p = 256;
        let mut ln_c = [(0.0, 0.0); LN_TABLE_SIZE];
        let mut ln_c_err = 0.0f64;
        for (j, slot) in ln_c.iter_mut().enumerate() {
            let c = 1.0 + (j as f64 + 0.5) / LN_TABLE_SIZE as f64;
            let (hi, lo, err) = split_double_word(&Float::with_val(p, c).ln());
            ln_c_err = ln_c_err.max(err * 1.0001 + f64::MIN_POSITIVE);
            *slot = (hi, lo);
        }
        LnTable { ln_c, ln_c_err }
    })
}

/// `e^y` for `y = y_hi + y_lo` known to within `dy` (absolute), `|y_lo|`
/// far below 1: `(value, rel)` with `|e^{y*} - value| <= rel |value|` for
/// every `|y* - y| <= dy`. Table-driven (module docs).
pub(super) fn exp_f64(y_hi: f64, y_lo: f64, dy: f64) -> Option<(f64, f64)> {
    if !(y_hi.abs() <= 700.0 && y_lo.abs() <= 1e-10 && dy >= 0.0 && dy < 1e-6) {
        return None;
    }
    let t = exp_table();
    let k = round_small(y_hi * t.inv_d);
    // y_hi - k D1 exact (k D1 exact: k < 2^17, D1 has 32 bits; Sterbenz)
    let r1 = y_hi - k * t.d1;
    let kd2 = k * t.d2;
    let r2 = r1 - kd2;
    let r = r2 + y_lo;
    if !(r.abs() <= 0.0055) {
        return None;
    }
    // exponent error: roundings of k D2, r2, r; |k D3|; the caller's dy
    let d = U * (kd2.abs() + r2.abs() + r.abs()) * 1.0001 + k.abs() * t.d3_bound + dy;
    // e^r - 1 = r + r^2 P(r), P(r) = 1/2 + r/6 + r^2/24 + r^3/120 + r^4/720
    let r_sq = r * r;
    let poly = EXP_P[0] + r * (EXP_P[1] + r * (EXP_P[2] + r * (EXP_P[3] + r * EXP_P[4])));
    let q2 = r_sq * poly;
    let q = r + q2;
    // |q~ - (e^r - 1)| <= |r|^7/5040 e^|r| + 12 u |r^2 P| + u |q| (roundings of
    // r^2, P (8), the coefficients (1 each), r^2 P, and q)
    let q_err = r_sq * r_sq * r_sq * r.abs() / 5040.0 * 1.006 + 13.0 * U * q2.abs() + U * q.abs();
    let k_int = k as i64;
    let j = k_int.rem_euclid(EXP_TABLE_SIZE as i64) as usize;
    let n = (k_int - j as i64) / EXP_TABLE_SIZE as i64;
    let (th, tl) = t.two_pow[j];
    let m = th * q;
    let sm = m + tl;
    let v = th + sm;
    // |v - T (1 + Q)| with T = 2^(j/64) exactly, Q = e^r - 1
    let abs = U * (m.abs() + sm.abs() + v.abs()) + (tl * q).abs() + t.table_rel * th * 1.01 + th * q_err * 1.0001;
    let rel = (abs / v.abs() * (1.0 + 4.0 * U) + 1.01 * d) * 1.0001;
    let scale = f64::from_bits(((n + 1023) as u64) << 52); // n in [-1011, 1010]
    let value = v * scale;
    value.is_normal().then_some((value, rel))
}

/// `P(r)` of [`exp_f64`]: `1/2, 1/6, 1/24, 1/120, 1/720`, each a correctly
/// rounded quotient of exact integers (relative error `u`, counted in the
/// twelve roundings of its bound).
const EXP_P: [f64; 5] = [1.0 / 2.0, 1.0 / 6.0, 1.0 / 24.0, 1.0 / 120.0, 1.0 / 720.0];

/// Entries of the `2^(j/64)` table.
const EXP_TABLE_SIZE: usize = 64;

/// `2^(j/64) = hi + lo` (within `table_rel`), and `ln 2/64 = D1 + D2 + D3`.
struct ExpTable {
    two_pow: [(f64, f64); EXP_TABLE_SIZE],
    table_rel: f64,
    inv_d: f64,
    d1: f64,
    d2: f64,
    d3_bound: f64,
}

/// The table from MPFR at 256 bits, built on first use.
fn exp_table() -> &'static ExpTable {
    static TABLE: std::sync::OnceLock<ExpTable> = std::sync::OnceLock::new();
    TABLE.get_or_init(|| {
        use rug::float::Constant;
        use rug::Float;
        let p = 256;
        let mut two_pow = [(0.0, 0.0); EXP_TABLE_SIZE];
        let mut table_rel = 0.0f64;
        for (j, slot) in two_pow.iter_mut().enumerate() {
            let exact = Float::with_val(p, Float::with_val(p, j) / EXP_TABLE_SIZE as u32).exp2();
            let (hi, lo, err) = split_double_word(&exact);
            table_rel = table_rel.max(err / exact.to_f64() * 1.0001 + f64::MIN_POSITIVE);
            *slot = (hi, lo);
        }
        let d = Float::with_val(p, Constant::Log2) / EXP_TABLE_SIZE as u32;
        let d1 = Float::with_val(32, &d).to_f64();
        let r = Float::with_val(p, &d - d1);
        let d2 = r.to_f64();
        let d3 = Float::with_val(p, &r - d2).abs().to_f64() * 1.0001 + f64::MIN_POSITIVE;
        let inv_d = Float::with_val(p, EXP_TABLE_SIZE as u32) / Float::with_val(p, Constant::Log2);
        ExpTable { two_pow, table_rel, inv_d: inv_d.to_f64(), d1, d2, d3_bound: d3 }
    })
}

/// An MPFR value as a double word `hi + lo` and the bound `|x - hi - lo|`
/// (rounded up), for the tables.
fn split_double_word(x: &rug::Float) -> (f64, f64, f64) {
    let hi = x.to_f64();
    let rest = rug::Float::with_val(x.prec(), x - hi);
    let lo = rest.to_f64();
    let err = rug::Float::with_val(x.prec(), &rest - lo).abs().to_f64_round(rug::float::Round::Up);
    (hi, lo, err)
}

/// `floor(x)` for `|x| < 2^51`, without a libm call.
#[inline]
pub(super) fn floor_small(x: f64) -> f64 {
    let r = round_small(x);
    if r > x {
        r - 1.0
    } else {
        r
    }
}

/// `floor(x)` for every finite `x` (NaN stays NaN), without a libm call:
/// below `2^52` in magnitude through the exact conversion to `i64` and back
/// (truncation, then one step down for a negative non-integer); from `2^52`
/// on every f64 is an integer.
#[inline]
pub(crate) fn floor_any(x: f64) -> f64 {
    if x.abs() < 4503599627370496.0 {
        let t = (x as i64) as f64;
        if t > x {
            t - 1.0
        } else {
            t
        }
    } else {
        x
    }
}

/// `x^p` for `x = hi + lo > 0` (a double word) and an f64 `p`:
/// `(value, rel)` with `|x^p - value| <= rel |value|`. The exponent `p ln x`
/// is carried as `y_hi + y_lo` (`two_prod`), so its error is `|p|` times that
/// of [`ln_f64`] plus roundings far below `u`. (The native `2F1` computes
/// `ln x` once and calls [`pow_from_ln`]; this form is the one tested.)
#[cfg(test)]
pub(super) fn pow_f64(x: Dd, p: f64) -> Option<(f64, f64)> {
    pow_from_ln(ln_f64(x.hi, x.lo)?, p)
}

/// `x^p` from `ln x = l_hi + l_lo` (within `l_err`, as [`ln_f64`] returns it):
/// the second half of [`pow_f64`], for several powers of one `x`.
pub(super) fn pow_from_ln(ln_x: (f64, f64, f64), p: f64) -> Option<(f64, f64)> {
    pow_dw_exponent(ln_x, Dd::from_f64(p))
}

/// `x^p` from `ln x` (as [`pow_from_ln`]) for an exponent given as a double
/// word `p = p_hi + p_lo` (`|p_lo| <= u |p_hi|`, e.g. `c - a - b`): the exponent
/// `p ln x = two_prod(p_hi, l_hi) + (p_hi l_lo + p_lo l_hi)`, whose dropped and
/// rounded parts (`|p| l_err`, `|p_lo l_lo|`, three roundings) go to `dy`.
pub(super) fn pow_dw_exponent((l_hi, l_lo, l_err): (f64, f64, f64), p: Dd) -> Option<(f64, f64)> {
    let (y_hi, y_err) = two_prod(p.hi, l_hi);
    let cross = p.hi * l_lo + p.lo * l_hi;
    let y_lo = y_err + cross;
    let dy = ((p.hi.abs() + p.lo.abs()) * l_err
        + (p.lo * l_lo).abs()
        + U * ((p.hi * l_lo).abs() + (p.lo * l_hi).abs() + cross.abs() + y_lo.abs()))
        * 1.0001;
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
    fn floor_any_is_floor() {
        let xs = [0.0, -0.0, 0.5, -0.5, 1.0, -1.0, 2.5, -2.5, 1e-300, -1e-300, 4503599627370495.5, -4503599627370495.5];
        let big = [4503599627370496.0, -4503599627370497.0, 1e300, -1e300, f64::MAX, f64::MIN];
        for x in xs.iter().chain(&big).copied().chain((0..2000).map(|i| (i as f64 - 1000.0) * 0.0137)) {
            assert_eq!(floor_any(x), x.floor(), "{x}");
            let y = f64::from_bits(x.to_bits() + 1);
            assert_eq!(floor_any(y), y.floor(), "{y}");
        }
        assert!(floor_any(f64::NAN).is_nan());
    }

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
            // small exponents with a low word (k = 0 and the first table steps)
            let y = (f - 0.5) * 0.05;
            let y_lo = y * (g - 0.5) * 2.2e-16;
            let (v, rel) = exp_f64(y, y_lo, 0.0).unwrap();
            let r = rel_to(v, &(Float::with_val(200, y) + y_lo).exp());
            assert!(r <= rel, "exp({y} + {y_lo}) = {v}: rel error {r:e} > bound {rel:e}");
            worst_exp = worst_exp.max(rel);
            // pow on the Pfaff domain: x = 1 - z in (1.5, 11] and up to 1e6, p in [-10, 10]
            let z = if i % 4 == 0 { -(10f64.powf(6.0 * f)) - 0.5 } else { -10.0 * f - 0.5 };
            let omz = Dd::diff(1.0, z);
            let p = 20.0 * g - 10.0;
            let (v, rel) = pow_f64(omz, p).unwrap();
            let want = Float::with_val(200, Float::with_val(200, omz.hi) + omz.lo).pow(Float::with_val(200, p));
            let r = rel_to(v, &want);
            assert!(r <= rel, "({z})^{p}: rel error {r:e} > bound {rel:e}");
            // the exponent carries |p| times ln's absolute error (far below u), exp ~6u
            worst_pow = worst_pow.max(rel / (6.0 + 0.1 * p.abs()));
        }
        assert!(worst_ln < 0.05 * U, "{worst_ln:e} (absolute)");
        assert!(worst_exp < 4.0 * U, "{worst_exp:e}");
        assert!(worst_pow < U, "{worst_pow:e} (per (6 + |p|/10) u)");
        assert!(ln_f64(0.0, 0.0).is_none() && ln_f64(-1.0, 0.0).is_none() && ln_f64(f64::NAN, 0.0).is_none());
        assert!(exp_f64(701.0, 0.0, 0.0).is_none() && exp_f64(f64::NAN, 0.0, 0.0).is_none());
    }
}
