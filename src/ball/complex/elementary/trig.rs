//! `exp` and the trigonometric and hyperbolic functions of a complex ball: `exp`,
//! `sin`, `cos`, `sinh`, `cosh`, `tan`, `tanh`, `sech`, entire or meromorphic, with no
//! branch cut.
//!
//! # Method
//!
//! `exp(x + iy) = e^x (cos y + i sin y)` (DLMF 4.5.11); `sin`, `cos`, `sinh`, `cosh` from
//! one `sin_cos` of one part and one `sinh_cosh` of the other (DLMF 4.21.37-38,
//! 4.35.34-35); `tan` by DLMF 4.21.39 in the two forms of the module docs of
//! `elementary/mod.rs` (no cancellation near a pole, no overflow for large `|Im z|`);
//! `tanh z = -i tan(iz)` (DLMF 4.28.9); `sech z = 2t/(1 + t^2)`, `t = e^{-z}` or `e^z`
//! (bounded on wide rectangles, as Arb's `acb_sech`).
//!
//! # Error bound
//!
//! Each real operation adds its rounding error and the propagated input radius (see
//! `elementary/mod.rs`); a pole or an overflow gives the indeterminate ball.

use super::finish;
use crate::ball::{Ball, CBall};

impl CBall {

    /// `e^z`.
    pub fn exp(&self) -> CBall {
        let p = self.prec();
        if !self.is_finite() {
            return CBall::indeterminate(p);
        }
        if self.is_real() {
            return finish(CBall::from_real(self.re.exp_ball()), p);
        }
        let (s, c) = self.im.sin_cos();
        if self.is_imaginary() {
            return finish(CBall::new(c, s), p);
        }
        let e = self.re.exp_ball();
        finish(CBall::new(e.mul(&c), e.mul(&s)), p)
    }

    /// `sin z = sin x cosh y + i cos x sinh y`.
    pub fn sin(&self) -> CBall {
        let p = self.prec();
        if !self.is_finite() {
            return CBall::indeterminate(p);
        }
        if self.is_real() {
            return finish(CBall::from_real(self.re.sin()), p);
        }
        let (sh, ch) = self.im.sinh_cosh();
        if self.is_imaginary() {
            return finish(CBall::new(Ball::zero(p), sh), p);
        }
        let (s, c) = self.re.sin_cos();
        finish(CBall::new(s.mul(&ch), c.mul(&sh)), p)
    }

    /// `cos z = cos x cosh y - i sin x sinh y`.
    pub fn cos(&self) -> CBall {
        let p = self.prec();
        if !self.is_finite() {
            return CBall::indeterminate(p);
        }
        if self.is_real() {
            return finish(CBall::from_real(self.re.cos()), p);
        }
        let (sh, ch) = self.im.sinh_cosh();
        if self.is_imaginary() {
            return finish(CBall::from_real(ch), p);
        }
        let (s, c) = self.re.sin_cos();
        finish(CBall::new(c.mul(&ch), s.mul(&sh).neg()), p)
    }

    /// `sinh z = sinh x cos y + i cosh x sin y`.
    pub fn sinh(&self) -> CBall {
        let p = self.prec();
        if !self.is_finite() {
            return CBall::indeterminate(p);
        }
        if self.is_real() {
            return finish(CBall::from_real(self.re.sinh()), p);
        }
        if self.is_imaginary() {
            return finish(CBall::new(Ball::zero(p), self.im.sin()), p);
        }
        let (sh, ch) = self.re.sinh_cosh();
        let (s, c) = self.im.sin_cos();
        finish(CBall::new(sh.mul(&c), ch.mul(&s)), p)
    }

    /// `cosh z = cosh x cos y + i sinh x sin y`.
    pub fn cosh(&self) -> CBall {
        let p = self.prec();
        if !self.is_finite() {
            return CBall::indeterminate(p);
        }
        if self.is_real() {
            return finish(CBall::from_real(self.re.cosh()), p);
        }
        if self.is_imaginary() {
            return finish(CBall::from_real(self.im.cos()), p);
        }
        let (sh, ch) = self.re.sinh_cosh();
        let (s, c) = self.im.sin_cos();
        finish(CBall::new(ch.mul(&c), sh.mul(&s)), p)
    }

    /// `tan z`; indeterminate where the rectangle reaches a pole `pi/2 + k pi`.
    pub fn tan(&self) -> CBall {
        let p = self.prec();
        if !self.is_finite() {
            return CBall::indeterminate(p);
        }
        if self.is_real() {
            return finish(CBall::from_real(self.re.tan()), p);
        }
        let (x, y) = (&self.re, &self.im);
        let one = Ball::one(p);
        let far_up = y.lower() > 1;
        if far_up || y.upper() < -1 {
            // tan z = i (1 - w) / (1 + w), w = e^(2iz) for y > 0; conjugate for y < 0.
            let ay = if far_up { y.clone() } else { y.neg() };
            let e = ay.mul_pow2(1).neg().exp_ball(); // |w| = e^(-2|y|)
            let (s2, c2) = x.mul_pow2(1).sin_cos();
            // |1 + w|^2 = 1 + 2 e cos 2x + e^2
            let den = one.add(&e.mul(&c2).mul_pow2(1)).add(&e.sqr());
            let re = e.mul(&s2).mul_pow2(1).div(&den);
            let im = one.sub(&e.sqr()).div(&den);
            return match (re, im) {
                (Ok(re), Ok(im)) => finish(CBall::new(re, if far_up { im } else { im.neg() }), p),
                _ => CBall::indeterminate(p),
            };
        }
        // cos 2x + cosh 2y = 2 (cos^2 x + sinh^2 y): no cancellation near the poles
        let (s, c) = x.sin_cos();
        let (sh, ch) = y.sinh_cosh();
        let den = c.sqr_nonneg().add(&sh.sqr_nonneg());
        match (s.mul(&c).div(&den), sh.mul(&ch).div(&den)) {
            (Ok(re), Ok(im)) => finish(CBall::new(re, im), p),
            _ => CBall::indeterminate(p),
        }
    }

    /// `tanh z = -i tan(iz)`; indeterminate where the rectangle reaches a pole.
    pub fn tanh(&self) -> CBall {
        let p = self.prec();
        if !self.is_finite() {
            return CBall::indeterminate(p);
        }
        if self.is_real() {
            return finish(CBall::from_real(self.re.tanh()), p);
        }
        // iz = -y + ix; tan(iz) = a + ib; -i(a + ib) = b - ia
        let t = CBall::new(self.im.neg(), self.re.clone()).tan();
        if !t.is_finite() {
            return CBall::indeterminate(p);
        }
        let (a, b) = t.into_parts();
        CBall::new(b, a.neg())
    }

    /// `sech z = 1/cosh z`; indeterminate where the rectangle reaches a pole.
    ///
    /// Where the real part keeps one sign, `sech z = 2 t / (1 + t^2)` with
    /// `t = e^{-|Re| ...}`, i.e. `t = e^{-z}` for `Re z > 0` and `t = e^{z}` for
    /// `Re z < 0` (DLMF 4.28.1, multiplied through): `|t| < 1` there, so the
    /// denominator stays away from 0 even on rectangles whose imaginary side spans
    /// several periods, where the rectangle of `cosh z` itself contains 0 (this is
    /// what lets the integrator bound `sech` on wide ellipse boxes, as Arb's
    /// `acb_sech` does).
    pub fn sech(&self) -> CBall {
        let p = self.prec();
        if !self.is_finite() {
            return CBall::indeterminate(p);
        }
        if self.is_real() {
            let (_, c) = self.re.sinh_cosh();
            return match c.recip() {
                Ok(r) => finish(CBall::from_real(r), p),
                Err(_) => CBall::indeterminate(p),
            };
        }
        let t = if self.re.is_positive() {
            self.neg().exp()
        } else if self.re.is_negative() {
            self.exp()
        } else {
            return self.cosh().recip();
        };
        finish(t.mul_pow2(1).div(&t.sqr().add(&CBall::one(p))), p)
    }
}
