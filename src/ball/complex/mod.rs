//! Complex balls: a rectangle `[re ± r_re] + i [im ± r_im]` of two real [`Ball`]s.
//!
//! # Method
//!
//! [`CBall`] is Arb's `acb_t`: a real ball for the real part and one for the
//! imaginary part, each an MPFR midpoint with a radius rounded upward. Every
//! operation returns a rectangle that contains the exact result for *every* pair of
//! points of its operands (the inclusion property), because each is written in
//! real-ball operations that have it:
//!
//! * `+`, `-`: componentwise;
//! * `*`: `(a + ib)(c + id) = (ac - bd) + i(ad + bc)`, with a real fast path when an
//!   operand's imaginary part is exactly zero (the integrator's nodes);
//! * `/`: `z / w = z conj(w) / |w|^2`, the denominator `c^2 + d^2` a real ball; a
//!   divisor rectangle that reaches zero gives the *indeterminate* ball (below).
//!
//! # Non-finite balls
//!
//! Arithmetic never fails. Where a result is not bounded (a division by a ball that
//! contains zero, an overflow, a function evaluated on its branch cut in its analytic
//! form) the result is [`CBall::indeterminate`]: NaN midpoints and infinite radii,
//! which every later operation propagates and [`CBall::is_finite`] reports. This is
//! what lets the certified integrator ([`crate::quad::certified`]) detect a
//! non-holomorphic integrand: it evaluates the integrand on a complex box, and a
//! non-finite answer means "not analytic (or not bounded) there".
//!
//! f64 complex arithmetic elsewhere in the crate uses `num-complex` where it needs
//! any; this type is for certified arbitrary-precision work only.

use std::fmt;

use rug::float::Special;
use rug::Float;

use super::{Ball, Mag};

mod bessel;
mod hankel;
mod elementary;

/// A complex rectangle `re + i im` of two real balls.
#[derive(Clone, PartialEq)]
pub struct CBall {
    re: Ball,
    im: Ball,
}

impl fmt::Debug for CBall {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{:?} + i{:?}", self.re, self.im)
    }
}

impl fmt::Display for CBall {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        fmt::Debug::fmt(self, f)
    }
}

/// The real ball "some unknown number or none": NaN midpoint, infinite radius.
fn indeterminate_real(prec: u32) -> Ball {
    Ball::with_mag(Float::with_val(prec, Special::Nan), Mag::inf())
}

impl CBall {
    // ----- construction -------------------------------------------------

    /// `re + i im`.
    pub fn new(re: Ball, im: Ball) -> CBall {
        CBall { re, im }
    }

    /// The real ball `re` as a complex ball (imaginary part exactly zero).
    pub fn from_real(re: Ball) -> CBall {
        let p = re.prec();
        CBall { re, im: Ball::zero(p) }
    }

    /// The real part, to be overwritten in place (the integrator's quadrature nodes).
    pub(crate) fn re_mut(&mut self) -> &mut Ball {
        &mut self.re
    }

    /// Exact zero.
    pub fn zero(prec: u32) -> CBall {
        CBall { re: Ball::zero(prec), im: Ball::zero(prec) }
    }

    /// Exact one.
    pub fn one(prec: u32) -> CBall {
        CBall { re: Ball::one(prec), im: Ball::zero(prec) }
    }

    /// The imaginary unit, exactly.
    pub fn i(prec: u32) -> CBall {
        CBall { re: Ball::zero(prec), im: Ball::one(prec) }
    }

    /// The integer `n`, exactly when it fits `prec` bits.
    pub fn from_i64(n: i64, prec: u32) -> CBall {
        CBall::from_real(Ball::from_i64(n, prec))
    }

    /// The indeterminate ball: not a number, infinite radius in both parts. Every
    /// operation on it gives it back; [`CBall::is_finite`] is false.
    pub fn indeterminate(prec: u32) -> CBall {
        CBall { re: indeterminate_real(prec), im: indeterminate_real(prec) }
    }

    // ----- inspection ---------------------------------------------------

    /// The real part.
    pub fn re(&self) -> &Ball {
        &self.re
    }

    /// The imaginary part.
    pub fn im(&self) -> &Ball {
        &self.im
    }

    /// Splits into `(re, im)`.
    pub fn into_parts(self) -> (Ball, Ball) {
        (self.re, self.im)
    }

    /// Working precision: the larger of the two midpoints' precisions.
    pub fn prec(&self) -> u32 {
        self.re.prec().max(self.im.prec())
    }

    /// Both parts have finite midpoints and radii.
    pub fn is_finite(&self) -> bool {
        self.re.is_finite() && self.im.is_finite()
    }

    /// The imaginary part is exactly zero (a real point or real interval).
    pub fn is_real(&self) -> bool {
        self.im.is_exact() && self.im.mid().is_zero()
    }

    /// Both radii are zero.
    pub fn is_exact(&self) -> bool {
        self.re.is_exact() && self.im.is_exact()
    }

    /// Whether the rectangle contains `x + i y`.
    pub fn contains(&self, x: &Float, y: &Float) -> bool {
        self.re.contains(x) && self.im.contains(y)
    }

    /// Whether the two rectangles share a point.
    pub fn overlaps(&self, other: &CBall) -> bool {
        self.re.overlaps(&other.re) && self.im.overlaps(&other.im)
    }

    /// Whether the rectangle contains zero.
    pub fn contains_zero(&self) -> bool {
        self.re.contains_zero() && self.im.contains_zero()
    }

    /// Upper bound of `|z|` over the rectangle (`sqrt(|re|^2 + |im|^2)`, rounded up).
    pub fn abs_upper_mag(&self) -> Mag {
        self.re.abs_upper_mag().hypot(self.im.abs_upper_mag(), true)
    }

    /// Lower bound of `|z|` over the rectangle (zero when it contains zero).
    pub fn abs_lower_mag(&self) -> Mag {
        self.re.abs_lower_mag().hypot(self.im.abs_lower_mag(), false)
    }

    /// The larger of the two radii.
    pub fn rad_mag(&self) -> Mag {
        self.re.rad_mag().max(self.im.rad_mag())
    }

    /// The same rectangle with both midpoints rounded to `prec` bits.
    pub fn set_prec(&self, prec: u32) -> CBall {
        CBall { re: self.re.set_prec(prec), im: self.im.set_prec(prec) }
    }

    /// Widens both radii by `e`.
    pub fn add_error_mag(&mut self, e: Mag) {
        self.re.add_error_mag(e);
        self.im.add_error_mag(e);
    }

    // ----- arithmetic ---------------------------------------------------

    /// `self + other`.
    pub fn add(&self, other: &CBall) -> CBall {
        CBall { re: self.re.add(&other.re), im: self.im.add(&other.im) }
    }

    /// `self - other`.
    pub fn sub(&self, other: &CBall) -> CBall {
        CBall { re: self.re.sub(&other.re), im: self.im.sub(&other.im) }
    }

    /// `-self` (exact).
    pub fn neg(&self) -> CBall {
        CBall { re: self.re.neg(), im: self.im.neg() }
    }

    /// The complex conjugate (exact).
    pub fn conj(&self) -> CBall {
        CBall { re: self.re.clone(), im: self.im.neg() }
    }

    /// `self + x` for a real ball.
    pub fn add_real(&self, x: &Ball) -> CBall {
        CBall { re: self.re.add(x), im: self.im.clone() }
    }

    /// `self * x` for a real ball.
    pub fn mul_real(&self, x: &Ball) -> CBall {
        if self.is_real() {
            return CBall { re: self.re.mul(x), im: Ball::zero(self.im.prec()) };
        }
        CBall { re: self.re.mul(x), im: self.im.mul(x) }
    }

    /// `self * n` for an integer.
    pub fn mul_i64(&self, n: i64) -> CBall {
        CBall { re: self.re.mul_i64(n), im: self.im.mul_i64(n) }
    }

    /// `self * 2^e` (exact).
    pub fn mul_pow2(&self, e: i32) -> CBall {
        CBall { re: self.re.mul_pow2(e), im: self.im.mul_pow2(e) }
    }

    /// `self * i` (exact).
    pub fn mul_i(&self) -> CBall {
        CBall { re: self.im.neg(), im: self.re.clone() }
    }

    /// `self * other`.
    pub fn mul(&self, other: &CBall) -> CBall {
        if other.is_real() {
            return self.mul_real(&other.re);
        }
        if self.is_real() {
            return other.mul_real(&self.re);
        }
        let (a, b, c, d) = (&self.re, &self.im, &other.re, &other.im);
        CBall { re: a.mul(c).sub(&b.mul(d)), im: a.mul(d).add(&b.mul(c)) }
    }

    /// `self^2`.
    pub fn sqr(&self) -> CBall {
        if self.is_real() {
            return CBall { re: self.re.sqr(), im: Ball::zero(self.im.prec()) };
        }
        let (a, b) = (&self.re, &self.im);
        // (a + ib)^2 = (a - b)(a + b) + 2iab for points: one product fewer, and no
        // cancellation between a^2 and b^2 beyond what the exact value has. For wide
        // rectangles a^2 - b^2 is tighter (each square sees its own dependency).
        let re = if self.is_exact() { a.sub(b).mul(&a.add(b)) } else { a.sqr().sub(&b.sqr()) };
        CBall { re, im: a.mul(b).mul_pow2(1) }
    }

    /// `|self|^2 = re^2 + im^2` as a real ball.
    pub fn norm_sqr(&self) -> Ball {
        if self.is_real() {
            return self.re.sqr();
        }
        self.re.sqr().add(&self.im.sqr())
    }

    /// `1 / self`; the indeterminate ball when `self` reaches zero.
    pub fn recip(&self) -> CBall {
        let p = self.prec();
        if self.is_real() {
            return match self.re.recip() {
                Ok(r) => CBall::from_real(r),
                Err(_) => CBall::indeterminate(p),
            };
        }
        let den = self.norm_sqr();
        match (self.re.div(&den), self.im.div(&den)) {
            (Ok(re), Ok(im)) => CBall { re, im: im.neg() },
            _ => CBall::indeterminate(p),
        }
    }

    /// `self / other`; the indeterminate ball when `other` reaches zero.
    pub fn div(&self, other: &CBall) -> CBall {
        let p = self.prec().max(other.prec());
        if other.is_real() {
            return match (self.re.div(&other.re), self.im.div(&other.re)) {
                (Ok(re), Ok(im)) => CBall { re, im },
                _ => CBall::indeterminate(p),
            };
        }
        let den = other.norm_sqr();
        let num = self.mul(&other.conj());
        match (num.re.div(&den), num.im.div(&den)) {
            (Ok(re), Ok(im)) => CBall { re, im },
            _ => CBall::indeterminate(p),
        }
    }

    /// `self^n` for an integer `n >= 0` (binary powering).
    pub fn pow_u64(&self, n: u64) -> CBall {
        super::binary_power(CBall::one(self.prec()), self.clone(), n, CBall::mul, CBall::sqr)
    }

    /// `self^n` for any integer `n` (a negative power through [`CBall::recip`]).
    pub fn pow_i64(&self, n: i64) -> CBall {
        let p = self.pow_u64(n.unsigned_abs());
        if n < 0 {
            p.recip()
        } else {
            p
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn c(re: f64, im: f64) -> CBall {
        CBall::new(Ball::from_f64(re, 64).unwrap(), Ball::from_f64(im, 64).unwrap())
    }

    #[test]
    fn product_and_quotient_enclose_exact_values() {
        let z = c(1.5, -2.25);
        let w = c(0.75, 3.0);
        // (1.5 - 2.25i)(0.75 + 3i) = 1.125 + 6.75 + i(4.5 - 1.6875) = 7.875 + 2.8125i
        let p = z.mul(&w);
        assert!(p.contains(&Float::with_val(64, 7.875), &Float::with_val(64, 2.8125)));
        assert!(p.is_exact());
        // (p / w) must contain z again
        let q = p.div(&w);
        assert!(q.contains(&Float::with_val(64, 1.5), &Float::with_val(64, -2.25)));
        assert!(q.rad_mag().le(&Mag::pow2(-58)));
        let s = z.sqr();
        // (1.5 - 2.25i)^2 = 2.25 - 5.0625 - 6.75i
        assert!(s.contains(&Float::with_val(64, -2.8125), &Float::with_val(64, -6.75)));
    }

    #[test]
    fn division_by_a_ball_around_zero_is_indeterminate_and_propagates() {
        let mut zero_ish = c(0.0, 0.0);
        zero_ish.add_error_mag(Mag::pow2(-10));
        let q = c(1.0, 1.0).div(&zero_ish);
        assert!(!q.is_finite());
        assert!(!q.add(&c(1.0, 0.0)).is_finite());
        assert!(!q.mul(&c(2.0, 0.5)).is_finite());
        assert!(!zero_ish.recip().is_finite());
        // a rectangle that excludes zero is fine
        assert!(c(0.0, 1.0).recip().is_finite());
    }

    #[test]
    fn magnitude_bounds_bracket_the_modulus() {
        let z = c(3.0, 4.0);
        assert!(z.abs_lower_mag().le(&Mag::from_f64(5.0)));
        assert!(Mag::from_f64(5.0).le(&z.abs_upper_mag()));
        assert!(z.abs_upper_mag().le(&Mag::from_f64(5.0 * (1.0 + 1e-15))));
    }

    #[test]
    fn integer_powers() {
        let z = c(0.0, 1.0);
        let p = z.pow_i64(-3); // i^-3 = i
        assert!(p.contains(&Float::with_val(64, 0), &Float::with_val(64, 1)));
        let q = c(1.0, 1.0).pow_u64(8); // (1+i)^8 = 16
        assert!(q.contains(&Float::with_val(64, 16), &Float::with_val(64, 0)));
    }
}
