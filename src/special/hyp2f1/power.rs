//! Certified double-double `exp`, `ln` and `x^p` for the prefactors of the
//! native f64 `2F1` path (Pfaff: `(1-z)^{-a}`).
//!
//! # Method
//!
//! Double-double (DW) numbers `hi + lo` ([`Dd`], the crate's one double-word type) with the *accurate* operations of
//! Joldes, Muller and Popescu, "Tight and rigorous error bounds for basic
//! building blocks of double-word arithmetic", ACM TOMS 44 (2017):
//! [`Dd::add_accurate`] (their Alg. 6, AccurateDWPlusDW, relative error `<= 3u^2/(1-4u)`)
//! and [`Dd::mul_accurate`] (Alg. 10, DWTimesDW1, `<= 7u^2`), `u = 2^-53`. Below, every DW
//! operation is charged `8u^2` relative.
//!
//! * `exp(y)`, `|y| <= EXP_MAX_ARG`: `k = round(y / ln 2)`,
//!   `r = y - k ln2` with `ln 2` as three doubles (`k c1` exact: `c1` has 42
//!   bits and `|k| < 2^11`), absolute error `<= 16 u^2 (|y| + 1)`;
//!   `e^{r/256}` by Horner on the Taylor polynomial of degree 10 with DW
//!   coefficients `1/j!` (`|r/256| < 0.00136`: truncation `< 10^-40`; 20 DW
//!   operations whose errors are damped by `|r/256|`: `<= 24 u^2`), then 8
//!   squarings (`e_{i+1} = 2 e_i + 8u^2`: `<= 256 * 25 u^2 + 2040 u^2`), then
//!   the exact scaling by `2^k`. Total relative error
//!   `<= 8500 u^2 + 1.01 * 16 u^2 (|y| + 1) < 2^-90` for `|y| <= 600`; the
//!   declared bound [`EXP_REL_ERR`] is `2^-84`.
//! * `ln(x)`, `x > 0` a DW: `y0 = ln(x.hi)` (libm; only its closeness is used,
//!   and it is checked), `d = x e^{-y0} - 1` in DW (`|d| <= 2^-30` is required),
//!   `ln x = y0 + ln(1 + d*)` with `d*` the exact value of `d`;
//!   `|ln(1+d*) - (d* - d*^2/2)| <= |d*|^3 / (3 (1 - |d*|)) < 2^-89`, and
//!   `|d - d*| <= (1 + |d|)(2^-84 + 8u^2) + 8u^2 |d| < 2^-83`. Declared absolute
//!   error [`ln_abs_err`]: `2^-80 + 2^-100 |ln x|`.
//! * `x^p = exp(p ln x)` for a DW `p` with absolute error `dp`: the exponent
//!   errs by at most `|p| ln_abs_err + |ln x| dp + 8u^2 |p ln x|`, and
//!   `|e^{y+delta} - e^y| <= e^y expm1(|delta|)`; with [`EXP_REL_ERR`] and the
//!   [`pow_dw`] returns the double word and its relative error bound.
//! * Division: [`Dd::div_accurate`], DWDivDW2 (Alg. 17 of the same paper, `<= 15u^2 + 56u^3`).
//!
//! Everything is refused (`None`) outside the ranges above (then the caller
//! falls back to MP): no overflow, underflow or subnormal can occur inside.

use crate::ball::{two_prod, Dd};

/// `u = 2^-53`, the unit roundoff of f64.
pub(super) const U: f64 = f64::EPSILON / 2.0;

/// Largest `|y|` accepted by [`exp_dw`] (keeps `e^y` and its low word normal).
pub(super) const EXP_MAX_ARG: f64 = 600.0;

/// Declared relative error bound of [`exp_dw`] (the method block derives `2^-90`).
pub(super) const EXP_REL_ERR: f64 = 5.169878828456423e-26; // 2^-84

/// `x` rounded to an integer (ties to even) for `|x| < 2^51`, without a libm
/// call (the portable x86-64 target has no `roundsd`).
#[inline]
pub(super) fn round_small(x: f64) -> f64 {
    const MAGIC: f64 = 6755399441055744.0; // 1.5 * 2^52
    (x + MAGIC) - MAGIC
}

/// `ln 2 = LN2_C1 + LN2_C2 + LN2_C3` to about 160 bits; `LN2_C1` has 42 significant bits.
pub(super) const LN2_C1: f64 = 0.6931471805598903;
pub(super) const LN2_C2: f64 = 5.497923018708371e-14;
pub(super) const LN2_C3: f64 = 1.94704509238075e-31;

/// `1/j!` for `j = 2..=10` as double words (from mpmath at 300 bits).
const INV_FACT: [Dd; 9] = [
    Dd { hi: 0.5, lo: 0.0 },
    Dd { hi: 0.16666666666666666, lo: 9.25185853854297e-18 },
    Dd { hi: 0.041666666666666664, lo: 2.3129646346357427e-18 },
    Dd { hi: 0.008333333333333333, lo: 1.1564823173178714e-19 },
    Dd { hi: 0.001388888888888889, lo: -5.300543954373577e-20 },
    Dd { hi: 0.0001984126984126984, lo: 1.7209558293420705e-22 },
    Dd { hi: 2.48015873015873e-05, lo: 2.1511947866775882e-23 },
    Dd { hi: 2.7557319223985893e-06, lo: -1.858393274046472e-22 },
    Dd { hi: 2.755731922398589e-07, lo: 2.3767714622250297e-23 },
];

/// `e^y` with relative error at most [`EXP_REL_ERR`]; `None` for `|y| > EXP_MAX_ARG`.
pub(super) fn exp_dw(y: Dd) -> Option<Dd> {
    if !(y.hi.abs() <= EXP_MAX_ARG) {
        return None;
    }
    let k = round_small(y.hi * std::f64::consts::LOG2_E);
    // r = y - k ln 2: k c1 is exact (|k| < 2^10, c1 has 42 bits), k c2 exact as a DW.
    let r = y.add_accurate(Dd::from_f64(-k * LN2_C1));
    let (p2, e2) = two_prod(k, LN2_C2);
    let r = r.add_accurate(Dd { hi: -p2, lo: -e2 });
    let r = r.add_accurate(Dd::from_f64(-k * LN2_C3));
    let r = Dd { hi: r.hi / 256.0, lo: r.lo / 256.0 };
    // Horner: p = 1 + r (1 + r (1/2 + r (1/6 + ...))).
    let mut p = INV_FACT[8];
    for c in INV_FACT[..8].iter().rev() {
        p = p.mul_accurate(r).add_accurate(*c);
    }
    p = p.mul_accurate(r).add_accurate(Dd::from_f64(1.0));
    p = p.mul_accurate(r).add_accurate(Dd::from_f64(1.0));
    for _ in 0..8 {
        p = p.mul_accurate(p);
    }
    let scale = 2f64.powi(k as i32);
    Some(Dd { hi: p.hi * scale, lo: p.lo * scale })
}

/// Declared absolute error bound of [`ln_dw`] at a result of magnitude `l`.
pub(super) fn ln_abs_err(l: f64) -> f64 {
    8.271806125530277e-25 + 7.888609052210118e-31 * l.abs() // 2^-80 + 2^-100 |l|
}

/// `ln x` for a DW `x > 0` with absolute error at most [`ln_abs_err`].
pub(super) fn ln_dw(x: Dd) -> Option<Dd> {
    if !(x.hi > 0.0 && x.hi.is_finite() && x.hi.is_normal()) {
        return None;
    }
    let y0 = x.hi.ln();
    let e = exp_dw(Dd::from_f64(-y0))?;
    let d = x.mul_accurate(e).add_accurate(Dd::from_f64(-1.0));
    if !(d.hi.abs() <= 9.313225746154785e-10) {
        // |d| > 2^-30: libm's ln is far off; refuse
        return None;
    }
    let half_d2 = 0.5 * d.hi * d.hi;
    Some(Dd::from_f64(y0).add_accurate(d).add_accurate(Dd::from_f64(-half_d2)))
}

/// `x^p` as a double word and a bound on its relative error, for a DW `x > 0`
/// and a DW exponent `p` known to within `dp` (absolute).
pub(super) fn pow_dw(x: Dd, p: Dd, dp: f64) -> Option<(Dd, f64)> {
    let l = ln_dw(x)?;
    let y = p.mul_accurate(l);
    let delta = p.hi.abs() * 1.0001 * ln_abs_err(l.hi) + l.hi.abs() * 1.0001 * dp + 8.0 * U * U * y.hi.abs() * 1.0001;
    if !(delta < 1e-6) {
        return None;
    }
    let e = exp_dw(y)?;
    if !(e.hi.is_normal()) {
        return None;
    }
    // expm1(delta) <= 1.01 delta for delta < 1e-6; (1 + EXP_REL_ERR)(1 + 1.01 delta) - 1.
    let rel = (1.01 * delta + EXP_REL_ERR * 1.01) * 1.0001;
    Some((e, rel))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ball::{two_sum, Dekker};
    use rug::ops::Pow;
    use rug::Float;

    /// |got - want| / |want| with `want` from MPFR at 200 bits.
    fn rel(got: Dd, want: &Float) -> f64 {
        let g = Float::with_val(200, got.hi) + got.lo;
        Float::with_val(200, (g - want) / want).abs().to_f64()
    }

    #[test]
    fn exp_and_ln_meet_their_declared_bounds() {
        let mut worst_exp: f64 = 0.0;
        let mut worst_ln: f64 = 0.0;
        for i in 0..4000 {
            let y = -599.0 + 1198.0 * ((i as f64 * 0.618_033_988_749_895) % 1.0);
            let y = Dd { hi: y, lo: y * 1.1e-17 };
            let want = Float::with_val(200, Float::with_val(200, y.hi) + y.lo).exp();
            let r = rel(exp_dw(y).unwrap(), &want);
            assert!(r <= EXP_REL_ERR, "exp({y:?}): rel {r:e}");
            worst_exp = worst_exp.max(r);
            let x = Dd::from_f64(f64::exp(y.hi / 7.0));
            let want = Float::with_val(200, x.hi).ln();
            let l = ln_dw(x).unwrap();
            let abs = (Float::with_val(200, l.hi) + l.lo - &want).abs().to_f64();
            assert!(abs <= ln_abs_err(l.hi), "ln({x:?}): abs {abs:e}");
            worst_ln = worst_ln.max(abs);
        }
        // The declared bounds leave a wide margin: the observed errors are near u^2.
        assert!(worst_exp < 2f64.powi(-95), "{worst_exp:e}");
        assert!(worst_ln < 2f64.powi(-95), "{worst_ln:e}");
        assert!(exp_dw(Dd::from_f64(601.0)).is_none());
        assert!(ln_dw(Dd::from_f64(0.0)).is_none());
    }

    #[test]
    fn dw_mul_and_div_meet_their_bounds() {
        let u2 = U * U;
        let mut x = 0.7548776662466927f64;
        for i in 0..2000 {
            x = (x * 997.0 + 0.123456789).fract() + 0.01;
            let norm = |hi: f64, rel_lo: f64| {
                let (h, l) = two_sum(hi, hi * rel_lo);
                Dd { hi: h, lo: l }
            };
            let a = norm(x * 3.0 - 1.5, x * 1e-17);
            let b = norm((x * 7.0).fract() + 0.25 + i as f64, -x * 2e-17);
            let fa = Float::with_val(200, a.hi) + a.lo;
            let fb = Float::with_val(200, b.hi) + b.lo;
            let q = Float::with_val(200, &fa / &fb);
            assert!(rel(a.div_accurate(b), &q) <= 16.0 * u2, "{a:?}/{b:?}");
            let m = Float::with_val(200, &fa * &fb);
            assert!(rel(a.mul_accurate(b), &m) <= 7.0 * u2, "{a:?}*{b:?}");
            let m = Float::with_val(200, &fa * b.hi);
            assert!(rel(a.mul_f64_accurate_p::<Dekker>(b.hi), &m) <= 2.0 * u2, "{a:?}*{}", b.hi);
            let s = Float::with_val(200, &fa + &fb);
            assert!(rel(a.add_accurate(b), &s) <= 3.0 * u2 / (1.0 - 4.0 * U), "{a:?}+{b:?}");
        }
    }

    #[test]
    fn pow_bound_holds() {
        for &(x, p) in &[(1.5, -3.0), (6.0, 2.75), (1.0 + 1e-12, -0.3), (3.25, 0.0), (123.5, -2.999)] {
            let (v, r) = pow_dw(Dd::from_f64(x), Dd::from_f64(p), 0.0).unwrap();
            let want = Float::with_val(200, x).pow(Float::with_val(200, p));
            let got = Float::with_val(200, v.hi) + v.lo;
            let err = Float::with_val(200, (got - &want) / &want).abs().to_f64();
            assert!(err <= r, "{x}^{p}: {err:e} > {r:e}");
            assert!(r < 1e-22);
        }
    }
}
