//! Ball arithmetic: a `rug::Float` midpoint and a radius rounded upward.
//!
//! # Method
//!
//! A [`Ball`] `[m ± r]` stands for every real `x` with `|x - m| <= r`. Every
//! operation returns a ball that contains the exact result of the operation
//! applied to *every* pair of points of its operands (the inclusion property).
//! The midpoint is rounded to nearest at the ball's precision; the radius is a
//! [`Mag`] (f64 mantissa, 64-bit exponent) to which every bound is added with
//! rounding toward `+inf`:
//!
//! * `+`, `-`:   `r = ra + rb + err(m)`
//! * `*`:        `r = |ma| rb + |mb| ra + ra rb + err(m)`
//! * `/`:        `r = (|ma| rb + |mb| ra) / (|mb| (|mb| - rb)) + err(m)` (requires `|mb| > rb`)
//! * monotone functions (`exp`, `ln`, `sqrt`, `acosh`): evaluate at both endpoints with
//!   directed rounding (MPFR rounds correctly in every direction) and take the hull.
//! * `gamma`, `digamma` on an *exact* point: MPFR is correctly rounded, so
//!   the error is at most one ulp (`rgamma` is the reciprocal of the `gamma` ball).
//!
//! `err(m)` is the rounding error of the midpoint: zero when MPFR reports the
//! operation exact (ternary value `Equal`), otherwise one ulp of the rounded
//! midpoint, `2^(e - p)` for `|m| in [2^(e-1), 2^e)` (round-to-nearest errs by at
//! most half of that).
//!
//! This is the same discipline as Arb's `arb_t` (midpoint `arf_t`, radius `mag_t`),
//! reduced to what the special functions of this crate need.

use std::cmp::Ordering;
use std::fmt;

use rug::float::{Constant, Round};
use rug::ops::AssignRound;
use rug::Float;

use crate::error::{Error, Result};

mod bounded;
mod complex;
pub use complex::CBall;
mod decimal;
mod dd_bounded;
mod double_double;
mod elementary;
mod float_digits;
pub(crate) mod fixed;
mod functions;
pub(crate) use double_double::{two_prod, two_sum};
mod lanes;
pub(crate) use lanes::F64x2;
mod mag;
mod scaled;
mod six_digits;
pub use bounded::Bounded;
pub use decimal::{eval_at_decimals, eval_at_decimals_with_floor, Decimal, MAX_DECIMAL_DIGITS, MAX_DECIMAL_EXPONENT, MAX_DECIMAL_INPUT_PREC};
pub use double_double::Dd;
pub(crate) use dd_bounded::{div_f64_p, mag, BoundedDd, BOUND_INFLATION, C_ADD, U, U2};
pub(crate) use double_double::{cpu_dispatch, Dekker, ExactProduct, Fused};
pub use mag::Mag;
pub use scaled::Scaled;
pub(crate) use scaled::log2_magnitude;
pub(crate) use scaled::{intermediate, ln_seconds};

/// `base^n` by square-and-multiply (`one` is the unit of `mul`); shared by the ball,
/// complex-ball and magnitude powers.
pub(crate) fn binary_power<T: Clone>(one: T, base: T, mut n: u64, mul: impl Fn(&T, &T) -> T, sqr: impl Fn(&T) -> T) -> T {
    // the first factor is taken as it is (a product by the exact one only costs)
    let mut result: Option<T> = None;
    let mut base = base;
    while n > 0 {
        if n & 1 == 1 {
            result = Some(match result {
                Some(r) => mul(&r, &base),
                None => base.clone(),
            });
        }
        n >>= 1;
        if n > 0 {
            base = sqr(&base);
        }
    }
    result.unwrap_or(one)
}

/// Precision (bits) of the radius-sized `Float` values handed out by
/// [`Ball::rad`], [`Ball::abs_upper`] and friends (the radius itself is a [`Mag`]
/// with a 53-bit mantissa). Radii are upper bounds, so a short mantissa only
/// makes them slightly larger, never wrong.
pub const MAG_PREC: u32 = 53;

/// A real interval `[mid - rad, mid + rad]` with an arbitrary-precision midpoint.
#[derive(Clone, PartialEq)]
pub struct Ball {
    mid: Float,
    rad: Mag,
}

impl fmt::Debug for Ball {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "[{} +/- {}]", self.mid.to_string_radix(10, Some(20)), self.rad.to_float().to_string_radix(10, Some(4)))
    }
}

impl fmt::Display for Ball {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        fmt::Debug::fmt(self, f)
    }
}

/// One ulp of `m` at its precision (an upper bound for the round-to-nearest error
/// that produced it), or zero when the operation was exact.
fn rounding_error(m: &Float, ord: Ordering) -> Mag {
    if ord == Ordering::Equal {
        return Mag::ZERO;
    }
    match m.get_exp() {
        Some(e) => Mag::pow2(e as i64 - m.prec() as i64),
        // A zero or non-finite midpoint after an inexact operation: MPFR only
        // produces this on underflow/overflow; the radius becomes unbounded.
        None => Mag::inf(),
    }
}

/// A ball from a rounded midpoint and its ternary value.
pub(crate) fn rounded(mid: Float, ord: Ordering) -> Ball {
    let rad = rounding_error(&mid, ord);
    Ball { mid, rad }
}

impl Ball {
    // ----- construction -------------------------------------------------

    /// The exact ball `[x ± 0]`, `x` rounded to `prec` bits (exact when `prec >= 53`);
    /// if rounding happened the radius covers it.
    pub fn from_f64(x: f64, prec: u32) -> Result<Ball> {
        if !x.is_finite() {
            return Err(Error::NonFinite { what: "ball midpoint" });
        }
        let (mid, ord) = Float::with_val_round(prec, x, Round::Nearest);
        Ok(rounded(mid, ord))
    }

    /// The ball `[x ± 0]` for an integer.
    pub fn from_i64(x: i64, prec: u32) -> Ball {
        let (mid, ord) = Float::with_val_round(prec, x, Round::Nearest);
        rounded(mid, ord)
    }

    /// The ball containing the rational `num/den` (`den != 0`).
    pub fn from_ratio(num: i64, den: i64, prec: u32) -> Ball {
        let q = rug::Rational::from((num, den));
        let (mid, ord) = Float::with_val_round(prec, &q, Round::Nearest);
        rounded(mid, ord)
    }

    /// The ball containing the exact value of `x`, rounded to `prec` bits.
    pub fn from_float(x: &Float, prec: u32) -> Ball {
        let (mid, ord) = Float::with_val_round(prec, x, Round::Nearest);
        rounded(mid, ord)
    }

    /// A ball from a midpoint and a radius (the radius is rounded upward).
    pub fn with_radius(mid: Float, rad: &Float) -> Ball {
        Ball { mid, rad: Mag::from_float_up(rad) }
    }

    /// A ball from a midpoint and a [`Mag`] radius.
    pub fn with_mag(mid: Float, rad: Mag) -> Ball {
        Ball { mid, rad }
    }

    /// Exact zero.
    pub fn zero(prec: u32) -> Ball {
        Ball { mid: Float::new(prec), rad: Mag::ZERO }
    }

    /// Exact one.
    pub fn one(prec: u32) -> Ball {
        Ball::from_i64(1, prec)
    }

    /// A ball containing pi.
    pub fn pi(prec: u32) -> Ball {
        let (mid, ord) = Float::with_val_round(prec, Constant::Pi, Round::Nearest);
        rounded(mid, ord)
    }

    /// A ball containing `n!` (MPFR's correctly rounded factorial).
    pub fn factorial(n: u32, prec: u32) -> Ball {
        let (mid, ord) = Float::with_val_round(prec, Float::factorial(n), Round::Nearest);
        rounded(mid, ord)
    }

    /// A ball containing Euler's constant `gamma`.
    pub(crate) fn euler_gamma(prec: u32) -> Ball {
        let (mid, ord) = Float::with_val_round(prec, Constant::Euler, Round::Nearest);
        rounded(mid, ord)
    }

    /// A ball containing `zeta(n)` (MPFR's correctly rounded Riemann zeta), `n >= 2`.
    pub(crate) fn zeta_u(n: u32, prec: u32) -> Ball {
        let (mid, ord) = Float::with_val_round(prec, Float::zeta_u(n), Round::Nearest);
        rounded(mid, ord)
    }

    /// A ball containing ln 2.
    pub fn ln2(prec: u32) -> Ball {
        let (mid, ord) = Float::with_val_round(prec, Constant::Log2, Round::Nearest);
        rounded(mid, ord)
    }

    // ----- inspection ---------------------------------------------------

    /// The midpoint.
    pub fn mid(&self) -> &Float {
        &self.mid
    }

    /// The radius (an upper bound on the distance from the midpoint to any
    /// enclosed value), as a float.
    pub fn rad(&self) -> Float {
        self.rad.to_float()
    }

    /// The radius as a [`Mag`].
    pub fn rad_mag(&self) -> Mag {
        self.rad
    }

    /// Precision of the midpoint in bits.
    pub fn prec(&self) -> u32 {
        self.mid.prec()
    }

    /// True when the radius is zero (the ball is one exactly known number).
    pub fn is_exact(&self) -> bool {
        self.rad.is_zero()
    }

    /// True when midpoint and radius are finite.
    pub fn is_finite(&self) -> bool {
        self.mid.is_finite() && self.rad.is_finite()
    }

    /// Whether the ball contains the number `x`.
    pub fn contains(&self, x: &Float) -> bool {
        if !self.rad.is_finite() {
            return true;
        }
        // |mid - x| bounded above through both directed roundings.
        let p = self.prec().max(x.prec()) + 8;
        let mut hi = Float::new(p);
        hi.assign_round(&self.mid - x, Round::Up);
        let mut lo = Float::new(p);
        lo.assign_round(&self.mid - x, Round::Down);
        let d = Mag::from_float_up(&hi).max(Mag::from_float_up(&lo));
        d.le(&self.rad)
    }

    /// Whether the two balls share a point.
    pub fn overlaps(&self, other: &Ball) -> bool {
        if !self.rad.is_finite() || !other.rad.is_finite() {
            return true;
        }
        let p = self.prec().max(other.prec()) + 8;
        let mut lo = Float::new(p);
        lo.assign_round(&self.mid - &other.mid, Round::Down);
        let mut hi = Float::new(p);
        hi.assign_round(&self.mid - &other.mid, Round::Up);
        // The exact difference lies in [lo, hi]; a lower bound of its magnitude:
        let lhs = if lo.is_sign_negative() != hi.is_sign_negative() || lo.is_zero() || hi.is_zero() {
            Mag::ZERO
        } else {
            let a = Mag::from_float_down(&lo);
            let b = Mag::from_float_down(&hi);
            if a.le(&b) { a } else { b }
        };
        lhs.le(&self.rad.add(other.rad))
    }

    /// Upper bound of `|x|` over the ball, as a [`Mag`].
    pub fn abs_upper_mag(&self) -> Mag {
        Mag::from_float_up(&self.mid).add(self.rad)
    }

    /// Lower bound of `|x|` over the ball, as a [`Mag`] (zero when the ball contains zero).
    pub fn abs_lower_mag(&self) -> Mag {
        Mag::from_float_down(&self.mid).sub_lower(self.rad)
    }

    /// Upper bound of `|x|` over the ball.
    pub fn abs_upper(&self) -> Float {
        self.abs_upper_mag().to_float()
    }

    /// Lower bound of `|x|` over the ball (zero when the ball contains zero).
    pub fn abs_lower(&self) -> Float {
        self.abs_lower_mag().to_float()
    }

    /// Lower end of the ball, rounded down, at the midpoint's precision.
    pub fn lower(&self) -> Float {
        if let Some(r) = self.rad.to_f64_exact() {
            return Float::with_val_round(self.prec(), &self.mid - r, Round::Down).0;
        }
        let mut r = Float::new(self.prec());
        r.assign_round(&self.mid - &self.rad.to_float(), Round::Down);
        r
    }

    /// Upper end of the ball, rounded up, at the midpoint's precision.
    pub fn upper(&self) -> Float {
        if let Some(r) = self.rad.to_f64_exact() {
            return Float::with_val_round(self.prec(), &self.mid + r, Round::Up).0;
        }
        let mut r = Float::new(self.prec());
        r.assign_round(&self.mid + &self.rad.to_float(), Round::Up);
        r
    }

    /// [`Ball::lower`] or [`Ball::upper`], reusing the midpoint's storage.
    pub(crate) fn into_end(mut self, upper: bool) -> Float {
        match self.rad.to_f64_exact() {
            Some(r) if upper => {
                rug::ops::AddAssignRound::add_assign_round(&mut self.mid, r, Round::Up);
                self.mid
            }
            Some(r) => {
                rug::ops::SubAssignRound::sub_assign_round(&mut self.mid, r, Round::Down);
                self.mid
            }
            None if upper => self.upper(),
            None => self.lower(),
        }
    }

    /// True when every point of the ball is `> 0`.
    pub fn is_positive(&self) -> bool {
        if self.mid.is_sign_positive() && self.mid.is_normal() && self.rad_below_mid() {
            return true;
        }
        self.lower() > 0
    }

    /// True when every point of the ball is `< 0`.
    pub fn is_negative(&self) -> bool {
        if self.mid.is_sign_negative() && self.mid.is_normal() && self.rad_below_mid() {
            return true;
        }
        self.upper() < 0
    }

    /// `rad < |mid|`, decided without allocating through a lower bound of `|mid|` (a
    /// sufficient test for the sign checks above; they decide exactly otherwise).
    fn rad_below_mid(&self) -> bool {
        !Mag::from_float_down(&self.mid).le(&self.rad)
    }

    /// True when the ball contains zero (`|mid| <= rad`, decided conservatively:
    /// a ball that merely touches zero after rounding also counts).
    pub fn contains_zero(&self) -> bool {
        self.abs_lower_mag().is_zero()
    }

    /// `log2(|mid| / rad)`: the number of bits the ball certifies
    /// (`+inf` for an exact ball, `-inf` for a zero midpoint with a nonzero radius).
    pub fn rel_accuracy_bits(&self) -> f64 {
        if self.rad.is_zero() {
            return f64::INFINITY;
        }
        if self.mid.is_zero() {
            return f64::NEG_INFINITY;
        }
        Mag::from_float_down(&self.mid).log2() - self.rad.log2()
    }

    /// Whether `rad <= 2^-prec |mid|`: the ball pins the value to `prec` bits
    /// relative (exact zero included).
    pub fn meets_rel(&self, prec: u32) -> bool {
        if self.rad.is_zero() {
            return true;
        }
        self.rad.le(&Mag::from_float_down(&self.mid).mul_2exp(-(prec as i64)))
    }

    /// Whether `rad <= 2^-prec * scale`.
    pub fn meets_abs(&self, prec: u32, scale: &Float) -> bool {
        self.rad.le(&Mag::from_float_down(scale).mul_2exp(-(prec as i64)))
    }

    /// The midpoint as an f64 (round to nearest).
    pub fn to_f64(&self) -> f64 {
        self.mid.to_f64()
    }

    /// The same ball with its midpoint rounded to `prec` bits.
    pub fn set_prec(&self, prec: u32) -> Ball {
        let mut mid = self.mid.clone();
        let ord = mid.set_prec_round(prec, Round::Nearest);
        let rad = self.rad.add(rounding_error(&mid, ord));
        Ball { mid, rad }
    }

    /// The same ball with its midpoint rounded to `prec` bits when it is longer
    /// (an exact input of 54 000 bits holding a short value, or a decimal ball
    /// tightened that far, costs its whole length in every product: issue 37).
    pub fn at_most_prec(&self, prec: u32) -> Ball {
        if self.mid.prec() > prec {
            self.set_prec(prec)
        } else {
            self.clone()
        }
    }

    /// [`Error::BallOutOfRange`] for this ball as the argument `arg`.
    pub fn out_of_range(&self, arg: &'static str, allowed: crate::error::Interval) -> crate::Error {
        crate::Error::BallOutOfRange {
            arg,
            lower: self.lower().to_f64_round(Round::Down),
            upper: self.upper().to_f64_round(Round::Up),
            allowed,
        }
    }

    /// `Ok` when the whole ball lies in `allowed`, else
    /// [`Error::BallOutOfRange`] naming `arg`.
    pub fn check_within(&self, arg: &'static str, allowed: crate::error::Interval) -> crate::Result<()> {
        let low_ok = if allowed.lo_closed { self.lower() >= allowed.lo } else { self.lower() > allowed.lo };
        let high_ok = if allowed.hi_closed { self.upper() <= allowed.hi } else { self.upper() < allowed.hi };
        if low_ok && high_ok {
            Ok(())
        } else {
            Err(self.out_of_range(arg, allowed))
        }
    }

    /// Widen the radius by `|extra|` (rounded up).
    pub fn add_error(&mut self, extra: &Float) {
        self.rad = self.rad.add(Mag::from_float_up(extra));
    }

    /// Widen the radius by a [`Mag`].
    pub fn add_error_mag(&mut self, extra: Mag) {
        self.rad = self.rad.add(extra);
    }

    // ----- arithmetic ---------------------------------------------------

    fn out_prec(&self, other: &Ball) -> u32 {
        self.prec().max(other.prec())
    }

    /// `self + other`.
    pub fn add(&self, other: &Ball) -> Ball {
        let (mid, ord) = Float::with_val_round(self.out_prec(other), &self.mid + &other.mid, Round::Nearest);
        let rad = self.rad.add(other.rad).add(rounding_error(&mid, ord));
        Ball { mid, rad }
    }

    /// `self - other`.
    pub fn sub(&self, other: &Ball) -> Ball {
        let (mid, ord) = Float::with_val_round(self.out_prec(other), &self.mid - &other.mid, Round::Nearest);
        let rad = self.rad.add(other.rad).add(rounding_error(&mid, ord));
        Ball { mid, rad }
    }

    /// `-self` (exact).
    pub fn neg(&self) -> Ball {
        Ball { mid: Float::with_val(self.prec(), -&self.mid), rad: self.rad }
    }

    #[inline]
    /// `|mid_a| r_b + |mid_b| r_a + r_a r_b`: how far `a b` strays from
    /// `mid_a mid_b` over the two balls (rounding not included).
    fn product_spread(&self, other: &Ball) -> Mag {
        let mut rad = Mag::ZERO;
        if !other.rad.is_zero() {
            rad = Mag::from_float_up(&self.mid).mul(other.rad);
        }
        if !self.rad.is_zero() {
            rad = rad.add(Mag::from_float_up(&other.mid).mul(self.rad));
            if !other.rad.is_zero() {
                rad = rad.add(self.rad.mul(other.rad));
            }
        }
        rad
    }

    /// `self * other`.
    pub fn mul(&self, other: &Ball) -> Ball {
        let (mid, ord) = Float::with_val_round(self.out_prec(other), &self.mid * &other.mid, Round::Nearest);
        let rad = rounding_error(&mid, ord).add(self.product_spread(other));
        Ball { mid, rad }
    }

    /// `self * self`. For a wide ball (radius above `|mid|/16`) the square of the
    /// interval itself: `[0, max|x|^2]` when it reaches zero, `[min|x|^2, max|x|^2]`
    /// otherwise (the product rule `2|m|r + r^2` would reach below zero).
    pub fn sqr(&self) -> Ball {
        if self.rad.is_zero() || !self.is_finite() || self.rad.le(&Mag::from_float_down(&self.mid).mul_2exp(-4)) {
            return self.mul(self);
        }
        let p = self.prec();
        let hi_abs = self.abs_upper_mag();
        let hi = hi_abs.mul(hi_abs).to_float();
        if self.contains_zero() {
            return Ball::hull(&Float::with_val(MAG_PREC, 0), &hi, p);
        }
        let lo_abs = self.abs_lower_mag();
        let lo = lo_abs.mul_lower(lo_abs).to_float();
        Ball::hull(&lo, &hi, p)
    }

    /// `self * n` for an integer `n`.
    pub fn mul_i64(&self, n: i64) -> Ball {
        let (mid, ord) = Float::with_val_round(self.prec(), &self.mid * n, Round::Nearest);
        // |n| as an upper bound: the f64 conversion rounds to nearest, step up once.
        let n_up = Mag::from_f64((n.unsigned_abs() as f64).next_up());
        let rad = self.rad.mul(n_up).add(rounding_error(&mid, ord));
        Ball { mid, rad }
    }

    /// `self / n` for a nonzero integer `n`.
    pub fn div_i64(&self, n: i64) -> Result<Ball> {
        if n == 0 {
            return Err(Error::DivisionByZero);
        }
        let (mid, ord) = Float::with_val_round(self.prec(), &self.mid / n, Round::Nearest);
        // |n| as a lower bound: the f64 conversion rounds to nearest, step down once.
        let n_lo = Mag::from_f64((n.unsigned_abs() as f64).next_down());
        let rad = self.rad.div(n_lo).add(rounding_error(&mid, ord));
        Ok(Ball { mid, rad })
    }

    /// `self + n` for an integer `n`.
    pub fn add_i64(&self, n: i64) -> Ball {
        let (mid, ord) = Float::with_val_round(self.prec(), &self.mid + n, Round::Nearest);
        let rad = self.rad.add(rounding_error(&mid, ord));
        Ball { mid, rad }
    }

    /// `self = a + b` in place (the result of [`Ball::add`], in `self`'s storage).
    pub(crate) fn assign_add(&mut self, a: &Ball, b: &Ball) {
        let ord = self.assign_mid(a.out_prec(b), &a.mid + &b.mid);
        self.rad = a.rad.add(b.rad).add(rounding_error(&self.mid, ord));
    }

    /// `self = a - b` in place (the result of [`Ball::sub`]).
    pub(crate) fn assign_sub(&mut self, a: &Ball, b: &Ball) {
        let ord = self.assign_mid(a.out_prec(b), &a.mid - &b.mid);
        self.rad = a.rad.add(b.rad).add(rounding_error(&self.mid, ord));
    }

    /// `self = a * b` in place (the result of [`Ball::mul`]).
    pub(crate) fn assign_mul(&mut self, a: &Ball, b: &Ball) {
        let ord = self.assign_mid(a.out_prec(b), &a.mid * &b.mid);
        self.rad = rounding_error(&self.mid, ord).add(a.product_spread(b));
    }

    /// The midpoint set to `value` rounded to nearest at `prec` bits.
    fn assign_mid<T>(&mut self, prec: u32, value: T) -> Ordering
    where
        Float: AssignRound<T, Round = Round, Ordering = Ordering>,
    {
        if self.mid.prec() != prec {
            self.mid.set_prec(prec);
        }
        self.mid.assign_round(value, Round::Nearest)
    }

    /// `self += a * b` in place, with `tmp` as scratch for the product (no
    /// allocation once `tmp` and `self` have their storage): the radius covers both
    /// roundings and the input radii, as `self.add(&a.mul(b))` would.
    pub(crate) fn add_mul_assign(&mut self, a: &Ball, b: &Ball, tmp: &mut Float) {
        let p = self.prec().max(a.prec()).max(b.prec());
        if tmp.prec() != p {
            tmp.set_prec(p);
        }
        let ord = tmp.assign_round(&a.mid * &b.mid, Round::Nearest);
        let rad = self.rad.add(rounding_error(tmp, ord)).add(a.product_spread(b));
        if self.mid.prec() < p {
            self.mid.set_prec(p); // exact: more bits
        }
        let ord = rug::ops::AddAssignRound::add_assign_round(&mut self.mid, &*tmp, Round::Nearest);
        self.rad = rad.add(rounding_error(&self.mid, ord));
    }

    /// `self * 2^e` (exact).
    pub fn mul_pow2(&self, e: i32) -> Ball {
        let mut mid = self.mid.clone();
        mid <<= e;
        Ball { mid, rad: self.rad.mul_2exp(e as i64) }
    }

    /// `self / other`; an error if `other` contains zero.
    pub fn div(&self, other: &Ball) -> Result<Ball> {
        let den_lo = other.abs_lower_mag();
        if den_lo.is_zero() {
            return Err(Error::DivisionByZero);
        }
        let (mid, ord) = Float::with_val_round(self.out_prec(other), &self.mid / &other.mid, Round::Nearest);
        let mut rad = rounding_error(&mid, ord);
        if !self.rad.is_zero() || !other.rad.is_zero() {
            // |a/b - ma/mb| <= (|ma| rb + |mb| ra) / (|mb| (|mb| - rb))
            let num = Mag::from_float_up(&self.mid)
                .mul(other.rad)
                .add(Mag::from_float_up(&other.mid).mul(self.rad));
            let den = Mag::from_float_down(&other.mid).mul_lower(den_lo);
            if den.is_zero() {
                return Err(Error::DivisionByZero);
            }
            rad = rad.add(num.div(den));
        }
        Ok(Ball { mid, rad })
    }

    /// `1 / self`.
    pub fn recip(&self) -> Result<Ball> {
        Ball::one(self.prec()).div(self)
    }

    /// Applies a monotone function through its endpoints. `f` must round in the
    /// given direction; `increasing` says which endpoint maps to which.
    fn monotone<F>(&self, increasing: bool, f: F) -> Ball
    where
        F: Fn(&Float, Round) -> Float,
    {
        let p = self.prec();
        if self.rad.is_zero() {
            let lo = f(&self.mid, Round::Down);
            let hi = f(&self.mid, Round::Up);
            return Ball::hull(&lo, &hi, p);
        }
        let (a, b) = (self.lower(), self.upper());
        let (lo, hi) = if increasing {
            (f(&a, Round::Down), f(&b, Round::Up))
        } else {
            (f(&b, Round::Down), f(&a, Round::Up))
        };
        Ball::hull(&lo, &hi, p)
    }

    /// The smallest ball (at `prec` bits) containing `[lo, hi]`.
    pub fn hull(lo: &Float, hi: &Float, prec: u32) -> Ball {
        // mid = round(lo + hi) / 2 (the halving is exact), off (lo + hi)/2 by at most
        // half an ulp of mid; rad = (hi - lo)/2 rounded up, plus one ulp of mid.
        let (mut mid, ord) = Float::with_val_round(prec, lo + hi, Round::Nearest);
        mid >>= 1;
        let mut w = Float::new(MAG_PREC);
        w.assign_round(hi - lo, Round::Up);
        let half_width = if w.is_sign_negative() { Mag::ZERO } else { Mag::from_float_up(&w).mul_2exp(-1) };
        Ball { rad: half_width.add(rounding_error(&mid, ord)), mid }
    }

    /// Whether the ball is exactly a non-positive integer.
    pub fn is_exact_nonpositive_integer(&self) -> bool {
        self.is_exact() && is_nonpositive_integer(&self.mid)
    }

    /// Decimal midpoint with `digits` significant digits and a decimal radius
    /// that bounds the true radius plus the decimal conversion error of the
    /// midpoint, so the printed ball still encloses.
    ///
    /// The midpoint is printed by MPFR's `mpfr_get_str` rounding to nearest
    /// (rug's `to_string_radix`; a midpoint of at most 128 bits to at most 25
    /// digits by `float_digits`, the same text at a quarter of the cost), so it is
    /// within half a unit of its last printed digit of the binary midpoint; that half unit, bounded above
    /// (`decimal::half_unit_of_last_digit`), is the conversion error. (Until issue
    /// 23, item 6, the printed text was parsed back at `prec + 64` bits and
    /// subtracted: 1.5 us against 0.5 us at 128 bits, for a radius at most half a
    /// unit of the last digit smaller.) The radius is printed through f64 where it
    /// is a normal f64 (`decimal::mag_decimal_upper`).
    pub fn to_decimal(&self, digits: usize) -> (String, String) {
        let n = digits.max(1);
        let mid_s = float_digits::float_digits(&self.mid, n).unwrap_or_else(|| self.mid.to_string_radix(10, Some(n)));
        let conv = if self.mid.is_zero() { Mag::ZERO } else { decimal::half_unit_of_last_digit(&mid_s).unwrap_or_else(Mag::inf) };
        (mid_s, decimal::mag_decimal_upper(self.rad.add(conv)))
    }
}

/// A short decimal string that is `>= x` (x >= 0).
pub fn decimal_upper(x: &Float) -> String {
    if x.is_zero() {
        return "0".to_string();
    }
    let s = x.to_string_radix_round(10, Some(6), Round::Up);
    s
}

/// Whether an exact float is an integer `<= 0`.
pub fn is_nonpositive_integer(x: &Float) -> bool {
    x.is_integer() && *x <= 0
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn add_mul_enclose() {
        let p = 64;
        let a = Ball::from_ratio(1, 3, p);
        let b = Ball::from_ratio(2, 7, p);
        let s = a.add(&b).mul(&a).sub(&b);
        // (1/3 + 2/7) * 1/3 - 2/7 = 13/63 - 18/63 = -5/63
        let exact = Float::with_val(256, rug::Rational::from((-5, 63)));
        assert!(s.contains(&exact), "{s:?}");
        assert!(s.meets_rel(p - 8));
    }

    #[test]
    fn div_and_functions_enclose() {
        let p = 80;
        let x = Ball::from_ratio(5, 4, p);
        let y = x.ln().unwrap().exp().unwrap();
        assert!(y.contains(&Float::with_val(200, 1.25)));
        let z = x.sqrt().unwrap().sqr();
        assert!(z.contains(&Float::with_val(200, 1.25)));
        let q = Ball::one(p).div(&Ball::from_i64(3, p)).unwrap().mul_i64(3);
        assert!(q.contains(&Float::with_val(200, 1)));
        assert!(Ball::zero(p).recip().is_err());
    }

    #[test]
    fn gamma_digamma_enclose() {
        let p = 100;
        let g = Ball::from_ratio(1, 2, p).gamma().unwrap();
        let sqrt_pi = Float::with_val(300, Constant::Pi).sqrt();
        assert!(g.contains(&sqrt_pi));
        let d = Ball::from_i64(1, p).digamma().unwrap();
        let euler = -Float::with_val(300, Constant::Euler);
        assert!(d.contains(&euler));
        assert!(Ball::from_i64(-2, p).gamma().is_err());
        assert!(Ball::from_i64(-2, p).rgamma().unwrap().mid().is_zero());
    }

    #[test]
    fn decimal_output_encloses() {
        let b = Ball::pi(200);
        let (m, r) = b.to_decimal(20);
        let mid = Float::with_val(300, Float::parse(&m).unwrap());
        let rad = Float::with_val(300, Float::parse(&r).unwrap());
        let pi = Float::with_val(300, Constant::Pi);
        assert!(Float::with_val(300, &pi - &mid).abs() <= rad);
    }
}
