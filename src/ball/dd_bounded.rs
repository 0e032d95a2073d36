//! A double-double value with a proven absolute error bound: the running error
//! analysis shared by the native f64 paths (`J_n`, `u_w`).
//!
//! # Error model
//!
//! A [`BoundedDd`] is a pair `(v, e)`: a double-double value `v` and an f64
//! `e >= |exact - v|`. With `u = 2^-53`, `|a|` standing for `|a.hi| + |a.lo|`,
//! and the double-double algorithms of [`Dd`] (two_sum and Dekker's two_prod
//! are exact; the correction terms are two or three f64 operations on
//! quantities of size `<= u |a|`, so each costs an error of order `u^2`;
//! quick_two_sum is exact or off by `u` times its `u`-sized correction), each
//! operation adds (with slack over the derivations of Joldes, Muller, Popescu,
//! "Tight and rigorous error bounds for basic building blocks of double-word
//! arithmetic", ACM TOMS 44, 2017):
//!
//! * `a + b`, `a - b`: `e = e_a + e_b + 8 u^2 (|a| + |b|)`   (derivation: `6 u^2`);
//! * `a b`: `e = |a| e_b + |b| e_a + e_a e_b + 8 u^2 |a| |b|`   (derivation: `4 u^2`);
//! * `a b` for an exact f64 `b`: `e = |b| e_a + 8 u^2 |a| |b|`;
//! * `a / d` for an exact f64 `d` ([`div_f64_p`]): `e = e_a / |d| + 16 u^2 |a/d|`;
//! * `a / b`: `e = (e_a + |a/b| e_b)/(|b| - e_b) + 16 u^2 |a/b|`   (three-quotient
//!   long division, derivation `~6 u^2`), refused unless `|b| > e_b`;
//! * `sqrt(a)`: `e = e_a/sqrt(|a| - e_a) + 16 u^2 sqrt|a|`   (one Newton step from
//!   the f64 root, `~3 u^2`), refused unless `|a| > e_a`; `sqrt(0) = 0` exactly.
//!
//! The bounds themselves are evaluated in f64. Each of those operations has
//! relative error `<= u`, and no chain in the callers is longer than `2^20`
//! operations, so multiplying a final bound by [`BOUND_INFLATION`] `= 1 + 2^-30`
//! (and stepping one ulp up) covers them. [`BoundedDd::finish`] does that and
//! adds the final rounding of `hi + lo` to f64, `u |value|`.

use super::double_double::{Dekker, ExactProduct};
use super::{Bounded, Dd};

/// Unit roundoff of f64, `2^-53`.
pub(crate) const U: f64 = f64::EPSILON / 2.0;
/// `u^2 = 2^-106`.
pub(crate) const U2: f64 = U * U;
/// Relative error charged to a double-double addition (of `|a| + |b|`).
pub(crate) const C_ADD: f64 = 8.0 * U2;
/// Relative error charged to a double-double product.
pub(crate) const C_MUL: f64 = 8.0 * U2;
/// Relative error charged to a double-double quotient.
pub(crate) const C_DIV: f64 = 16.0 * U2;
/// Relative error charged to a double-double square root.
pub(crate) const C_SQRT: f64 = 16.0 * U2;
/// Inflation of an f64-evaluated bound (covers its own roundings, see above).
pub(crate) const BOUND_INFLATION: f64 = 1.0 + 1.0 / (1u64 << 30) as f64;

/// `a / d` for an f64 `d`: one quotient, the exact remainder by an exact
/// product (strategy `P`), a second quotient (the "double-word by float" division; error a
/// few `u^2`, charged [`C_DIV`]).
#[inline(always)]
pub(crate) fn div_f64_p<P: ExactProduct>(a: Dd, d: f64) -> Dd {
    let q1 = a.hi / d;
    let pr = Dd::prod_p::<P>(q1, d);
    let r = (a.hi - pr.hi) - pr.lo + a.lo;
    let q2 = r / d;
    let s = q1 + q2;
    Dd { hi: s, lo: q2 - (s - q1) }
}

/// `|a.hi| + |a.lo|`, the magnitude the error model charges against.
#[inline]
pub(crate) fn mag(a: Dd) -> f64 {
    a.hi.abs() + a.lo.abs()
}

/// A double-double value `v` with an error bound `e >= |exact - v|`.
#[derive(Debug, Clone, Copy)]
pub(crate) struct BoundedDd {
    pub v: Dd,
    pub e: f64,
}

impl BoundedDd {
    pub(crate) const ZERO: BoundedDd = BoundedDd { v: Dd::ZERO, e: 0.0 };
    pub(crate) const ONE: BoundedDd = BoundedDd { v: Dd::ONE, e: 0.0 };

    /// An exact f64.
    #[inline]
    pub(crate) fn exact(x: f64) -> BoundedDd {
        BoundedDd { v: Dd::from_f64(x), e: 0.0 }
    }

    /// `|v.hi| + |v.lo|`.
    #[inline]
    pub(crate) fn mag(self) -> f64 {
        mag(self.v)
    }

    #[inline]
    pub(crate) fn neg(self) -> BoundedDd {
        BoundedDd { v: -self.v, e: self.e }
    }

    #[inline]
    pub(crate) fn add(self, o: BoundedDd) -> BoundedDd {
        BoundedDd { v: self.v + o.v, e: self.e + o.e + C_ADD * (self.mag() + o.mag()) }
    }

    #[inline]
    pub(crate) fn sub(self, o: BoundedDd) -> BoundedDd {
        BoundedDd { v: self.v - o.v, e: self.e + o.e + C_ADD * (self.mag() + o.mag()) }
    }

    #[inline]
    #[allow(dead_code)] // the native paths call mul_p; kept for tests and callers
    pub(crate) fn mul(self, o: BoundedDd) -> BoundedDd {
        self.mul_p::<Dekker>(o)
    }

    /// [`BoundedDd::mul`] with the product strategy `P` (same value, same bound).
    #[inline(always)]
    pub(crate) fn mul_p<P: ExactProduct>(self, o: BoundedDd) -> BoundedDd {
        let (ma, mb) = (self.mag(), o.mag());
        BoundedDd { v: self.v.mul_p::<P>(o.v), e: ma * o.e + mb * self.e + self.e * o.e + C_MUL * ma * mb }
    }

    /// `self * c - z` in one step (a three-term recurrence's update), with the
    /// product strategy `P`: `p + pe = c.hi y.hi` exactly, `s + se = p - z.hi`
    /// exactly, then the low parts `se + (pe + (c.hi y.lo + c.lo y.hi) - z.lo)`
    /// summed in f64 and one quick_two_sum. Error, with `|c| = |c.hi| + |c.lo|`:
    /// the dropped `c.lo y.lo` (`<= u^2 |c| |y|`), the two low products'
    /// roundings (`<= 2 u^2 |c| |y|`), at most four additions on the five low
    /// terms (`|se| <= u (|p| + |z.hi|)`, `|pe| <= u |p|`, the two products, `|z.lo|`:
    /// in all `<= 1.0001 u (4 |c| |y| + 2 |z|)`, so `gamma_4` of that), and the final
    /// quick_two_sum (`<= u^2 (|c| |y| + |z|)` when it is not exact): under
    /// `20 u^2 |c| |y| + 9 u^2 |z|`, charged `24 u^2 |c| |y| + 16 u^2 |z|`; plus the propagated
    /// `|c| e_y + |y| e_c + e_c e_y + e_z`.
    #[inline(always)]
    pub(crate) fn mul_sub_p<P: ExactProduct>(self, c: BoundedDd, z: BoundedDd) -> BoundedDd {
        let (y, cv, zv) = (self.v, c.v, z.v);
        let (p, pe) = P::two_prod(cv.hi, y.hi);
        let (s, se) = super::double_double::two_sum(p, -zv.hi);
        let lo = se + ((pe + (cv.hi * y.lo + cv.lo * y.hi)) - zv.lo);
        let (hi, lo) = super::double_double::quick_two_sum(s, lo);
        let (my, mc, mz) = (self.mag(), c.mag(), z.mag());
        let e = mc * self.e + my * c.e + c.e * self.e + z.e + U2 * (24.0 * mc * my + 16.0 * mz);
        BoundedDd { v: Dd { hi, lo }, e }
    }

    /// `self * b` for an exact f64 `b` (Dekker's product; the tests' shorthand).
    #[cfg(test)]
    #[inline]
    pub(crate) fn mul_f64(self, b: f64) -> BoundedDd {
        self.mul_f64_p::<Dekker>(b)
    }

    /// [`BoundedDd::mul_f64`] with the product strategy `P`.
    #[inline(always)]
    pub(crate) fn mul_f64_p<P: ExactProduct>(self, b: f64) -> BoundedDd {
        let ab = b.abs();
        BoundedDd { v: self.v.mul_f64_p::<P>(b), e: ab * self.e + C_MUL * self.mag() * ab }
    }

    /// `self / d` for an exact nonzero f64 `d`, with the product strategy `P`.
    #[inline(always)]
    pub(crate) fn div_f64_p<P: ExactProduct>(self, d: f64) -> BoundedDd {
        let v = div_f64_p::<P>(self.v, d);
        BoundedDd { v, e: self.e / d.abs() + C_DIV * mag(v) }
    }

    pub(crate) fn div(self, o: BoundedDd) -> Option<BoundedDd> {
        let den = o.mag() - o.e;
        if !(den > 0.0) {
            return None;
        }
        let v = self.v / o.v;
        let q = mag(v);
        Some(BoundedDd { v, e: (self.e + q * o.e) / den + C_DIV * q })
    }

    #[allow(dead_code)] // the native paths call sqrt_p; kept for tests and callers
    pub(crate) fn sqrt(self) -> Option<BoundedDd> {
        self.sqrt_p::<Dekker>()
    }

    /// [`BoundedDd::sqrt`] with the product strategy `P`.
    #[inline(always)]
    pub(crate) fn sqrt_p<P: ExactProduct>(self) -> Option<BoundedDd> {
        if self.v.hi == 0.0 && self.v.lo == 0.0 && self.e == 0.0 {
            return Some(BoundedDd::ZERO);
        }
        let low = self.mag() - self.e;
        if !(self.v.hi > 0.0 && low > 0.0) {
            return None;
        }
        let v = self.v.sqrt_p::<P>();
        Some(BoundedDd { v, e: self.e / low.sqrt() + C_SQRT * mag(v) })
    }

    /// The f64 value and its proven bound (final rounding and bound inflation included).
    pub(crate) fn finish(self) -> Option<Bounded> {
        let value = self.v.to_f64();
        let err = ((self.e + U * value.abs()) * BOUND_INFLATION).next_up();
        (value.is_finite() && err.is_finite()).then_some(Bounded { value, err })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rug::Float;

    fn exact_of(d: Dd) -> Float {
        Float::with_val(300, d.hi) + Float::with_val(300, d.lo)
    }

    fn holds(b: BoundedDd, exact: &Float) -> bool {
        let diff = Float::with_val(300, exact_of(b.v) - exact).abs();
        diff <= b.e
    }

    #[test]
    fn operations_enclose() {
        // x^2 - y^2 with cancellation, a quotient, a square root, f64 scalings.
        let (x, y) = (BoundedDd::exact(1.0 + 2f64.powi(-40)), BoundedDd::exact(1.0 - 2f64.powi(-41)));
        let xf = Float::with_val(300, x.v.hi);
        let yf = Float::with_val(300, y.v.hi);
        let d = x.mul(x).sub(y.mul(y));
        let df = Float::with_val(300, &xf * &xf) - Float::with_val(300, &yf * &yf);
        assert!(holds(d, &df));
        let q = d.div(BoundedDd::exact(3.0)).unwrap();
        let qf = Float::with_val(300, &df / 3u32);
        assert!(holds(q, &qf));
        let r = q.sqrt().unwrap();
        assert!(holds(r, &Float::with_val(300, qf.sqrt_ref())));
        let s = r.div_f64_p::<Dekker>(7.0).mul_f64(-3.0).neg();
        let sf = Float::with_val(300, exact_of(r.v) * 3u32) / 7u32;
        assert!(holds(s, &sf));
        // c y - z with and without cancellation
        for &(cy, zz) in &[(1.0 / 3.0, 0.2), (0.1, 0.1 * (1.0 + 2f64.powi(-50)))] {
            let c = BoundedDd::exact(cy).div_f64_p::<Dekker>(7.0);
            let y = BoundedDd::exact(7.0 + 2f64.powi(-45)).div_f64_p::<Dekker>(3.0);
            let z = BoundedDd::exact(zz).div_f64_p::<Dekker>(3.0);
            let r = y.mul_sub_p::<Dekker>(c, z);
            let exact = exact_of(c.v) * exact_of(y.v) - exact_of(z.v);
            let slack = c.mag() * y.e + y.mag() * c.e + c.e * y.e + z.e;
            let diff = Float::with_val(300, exact_of(r.v) - &exact).abs();
            assert!(diff <= r.e && r.e <= slack + 1e-30, "{r:?}");
        }
        let b = BoundedDd::exact(0.1).div_f64_p::<Dekker>(3.0).finish().unwrap();
        let e = Float::with_val(300, 0.1f64) / 3u32;
        assert!(Float::with_val(300, &e - b.value).abs() <= b.err);
    }
}
