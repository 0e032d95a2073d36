//! The real-ball functions of [`Ball`]'s public API: `sqrt`, `exp`, `ln`, `acosh`,
//! `sin_cos`, `cos`, `ln_1p`, `asinh`, `pow`, `pow_u64`, and `gamma`, `rgamma`,
//! `digamma` at exact points.
//!
//! # Method and error bounds
//!
//! * Monotone functions (`sqrt`, `exp`, `ln`, `acosh`, `ln_1p`, `asinh`): MPFR at
//!   both ends of the ball, rounded outward (`Ball::monotone`), so the interval
//!   image is enclosed exactly as MPFR's directed rounding allows.
//! * `sin_cos`: 1-Lipschitz (DLMF 4.14), with the second-order radius
//!   `r |cos m| + r^2/2` for wide balls (Taylor), and `[-1, 1]` as a cap.
//! * `pow`: `exp(e ln self)`, `self > 0`; `pow_u64`: binary powering in ball arithmetic.
//! * `gamma`, `rgamma`, `digamma`: MPFR's correctly rounded values at an exact point
//!   (at most one ulp), `rgamma` the reciprocal of the `gamma` ball.
//!
//! Domain errors are [`Error::BallOutOfRange`] (the ball reaches outside the
//! function's domain) and [`Error::Pole`].

use rug::float::Round;
use rug::ops::AssignRound;
use rug::Float;

use std::cmp::Ordering;

use super::{binary_power, elementary, fixed, is_nonpositive_integer, rounded, rounding_error, Ball, Mag};
use crate::error::{Error, Invariant, Result};

impl Ball {
    /// `sqrt(self)`; an error if the ball reaches below zero.
    pub fn sqrt(&self) -> Result<Ball> {
        if self.lower() < 0 {
            return Err(self.out_of_range("sqrt argument", crate::error::Interval::at_least(0.0)));
        }
        Ok(self.monotone(true, |x, r| {
            let mut y = Float::new(x.prec());
            y.assign_round(x.sqrt_ref(), r);
            y
        }))
    }

    /// `exp(self)`.
    pub fn exp(&self) -> Result<Ball> {
        let b = self.monotone(true, |x, r| {
            let mut y = Float::new(x.prec());
            y.assign_round(x.exp_ref(), r);
            y
        });
        if !b.is_finite() {
            return Err(Error::Overflow { what: "exp".into() });
        }
        Ok(b)
    }

    /// `ln(self)`; an error unless the ball is positive.
    pub fn ln(&self) -> Result<Ball> {
        if !self.is_positive() {
            return Err(self.out_of_range("ln argument", crate::error::Interval::above(0.0)));
        }
        Ok(self.monotone(true, |x, r| {
            let mut y = Float::new(x.prec());
            y.assign_round(x.ln_ref(), r);
            y
        }))
    }

    /// `acosh(self)` for `self >= 1`.
    pub fn acosh(&self) -> Result<Ball> {
        if self.lower() < 1 {
            return Err(self.out_of_range("acosh argument", crate::error::Interval::at_least(1.0)));
        }
        Ok(self.monotone(true, |x, r| {
            let mut y = Float::new(x.prec());
            y.assign_round(x.acosh_ref(), r);
            y
        }))
    }

    /// `(sin(self), cos(self))`. Both are 1-Lipschitz, so the input radius `r`
    /// carries over; MPFR's correctly rounded values add one ulp each. A wide ball
    /// (`r > 2^-12`) gets the second-order radius where it is smaller: by Taylor,
    /// `|sin(m + t) - sin m| <= r |cos m| + r^2/2` for `|t| <= r` (and the same with sin
    /// and cos exchanged), with `|cos m| <= |c| + err(c)` from the computed cosine: on
    /// the boxes around Bernstein ellipses the rectangle of `e^(x + iy)` is then the
    /// sector's, not a square around it. A wide result (radius above 1/2) is
    /// intersected with `[-1, 1]`.
    pub fn sin_cos(&self) -> (Ball, Ball) {
        let p = self.prec();
        // a wide ball's midpoint values at WIDE_EVAL_PREC bits (its result is wide:
        // `sin_cos_spread` is at least r^2/2 > 2^-17), then exactly at p
        let q = elementary::mid_eval_prec(self);
        let ((s, es), (c, ec)) = match self.is_finite().then(|| fixed::sin_cos(&self.mid, q)).flatten() {
            Some(v) => v,
            None => {
                let mut s = Float::with_val(q, &self.mid);
                let mut c = Float::new(q);
                // s holds mid rounded to q bits: sin_cos_round of the rounded value,
                // so the rounding of mid (1-Lipschitz) is added to both errors
                let (_, om) = Float::with_val_round(q, &self.mid, Round::Nearest);
                let em = rounding_error(&s, om);
                let (os, oc) = s.sin_cos_round(&mut c, Round::Nearest);
                let (es, ec) = (rounding_error(&s, os).add(em), rounding_error(&c, oc).add(em));
                ((s, es), (c, ec))
            }
        };
        let (s, c) = (Float::with_val(p, s), Float::with_val(p, c));
        let (rs, rc) = (self.sin_cos_spread(&c, ec), self.sin_cos_spread(&s, es));
        (elementary::within_unit(Ball { mid: s, rad: rs.add(es) }), elementary::within_unit(Ball { mid: c, rad: rc.add(ec) }))
    }

    /// How far sin (or cos) moves over the ball: `min(r, r (|o| + eo) + r^2/2)` for a
    /// wide ball, where `o` (error `eo`) is the computed cos (or sin) of the midpoint;
    /// `r` otherwise (see [`Ball::sin_cos`]).
    fn sin_cos_spread(&self, o: &Float, eo: Mag) -> Mag {
        let r = self.rad;
        if r.le(&Mag::pow2_const(-12)) || !r.is_finite() {
            return r;
        }
        let t = r.mul(Mag::from_float_up(o).add(eo)).add(r.mul(r).mul_2exp(-1));
        if t.le(&r) {
            t
        } else {
            r
        }
    }

    /// `ln(1 + self)` for `self > -1` (accurate for small arguments).
    pub fn ln_1p(&self) -> Result<Ball> {
        if self.lower() <= -1 {
            return Err(self.out_of_range("ln_1p argument", crate::error::Interval::above(-1.0)));
        }
        Ok(self.monotone(true, |x, r| {
            let mut y = Float::new(x.prec());
            y.assign_round(x.ln_1p_ref(), r);
            y
        }))
    }

    /// `asinh(self)` (monotone, any real argument).
    pub fn asinh(&self) -> Ball {
        self.monotone(true, |x, r| {
            let mut y = Float::new(x.prec());
            y.assign_round(x.asinh_ref(), r);
            y
        })
    }

    /// `cos(self)`.
    pub fn cos(&self) -> Ball {
        self.sin_cos().1
    }

    /// `self^e` for a real exponent, `self > 0`: `exp(e ln self)`, at the base's
    /// precision: `ln self` errs by about `2^-prec` relatively, so a longer
    /// exponent is rounded into its ball at that precision first (a decimal
    /// exponent tightened to 54 000 bits made `exp` run at that length).
    pub fn pow(&self, e: &Ball) -> Result<Ball> {
        if self.is_exact() && self.mid == 1 {
            return Ok(Ball::one(self.prec()));
        }
        self.ln()?.mul(&e.at_most_prec(self.prec().max(2))).exp()
    }

    /// `self^n` for an integer `n >= 0` (binary powering).
    pub fn pow_u64(&self, n: u64) -> Ball {
        binary_power(Ball::one(self.prec()), self.clone(), n, Ball::mul, Ball::sqr)
    }

    /// Requires an exact point, or returns an error naming the function.
    fn exact_point(&self, what: &'static str) -> Result<()> {
        if !self.is_exact() {
            return Err(Error::Invariant(Invariant::InexactArgument { function: what }));
        }
        Ok(())
    }

    /// Applies a correctly rounded MPFR function at an exact point: the result is
    /// off by at most one ulp.
    fn correctly_rounded<F>(&self, f: F) -> Ball
    where
        F: Fn(&Float, &mut Float) -> Ordering,
    {
        let mut y = Float::new(self.prec());
        let ord = f(&self.mid, &mut y);
        rounded(y, ord)
    }

    /// `Gamma(x)` at an exact point that is not a pole.
    pub fn gamma(&self) -> Result<Ball> {
        self.exact_point("gamma")?;
        if is_nonpositive_integer(&self.mid) {
            return Err(Error::Pole { function: "Gamma", at: self.mid.to_f64() });
        }
        let b = self.correctly_rounded(|x, y| y.assign_round(x.gamma_ref(), Round::Nearest));
        if !b.is_finite() {
            return Err(Error::Overflow { what: "gamma".into() });
        }
        Ok(b)
    }

    /// `1/Gamma(x)` at an exact point (zero at the poles).
    pub fn rgamma(&self) -> Result<Ball> {
        self.exact_point("rgamma")?;
        if is_nonpositive_integer(&self.mid) {
            return Ok(Ball::zero(self.prec()));
        }
        self.gamma()?.recip()
    }

    /// `psi(x)` (digamma) at an exact point that is not a pole.
    pub fn digamma(&self) -> Result<Ball> {
        self.exact_point("digamma")?;
        if is_nonpositive_integer(&self.mid) {
            return Err(Error::Pole { function: "digamma", at: self.mid.to_f64() });
        }
        Ok(self.correctly_rounded(|x, y| y.assign_round(x.digamma_ref(), Round::Nearest)))
    }
}
