//! The functions of a complex ball with a branch cut: `log`, `sqrt`, `pow`, `atan`,
//! each in a principal form and an `_analytic` form that returns the indeterminate ball
//! when the rectangle touches the cut.
//!
//! # Method
//!
//! `log z = ln|z| + i Arg z` (DLMF 4.2.3), `ln|z|` through `ln_1p` near `|z| = 1`;
//! `sqrt z` by DLMF 4.2(iv) without cancellation in either half plane; `pow(z, w) =
//! exp(w log z)` (DLMF 4.2.26), exact integer exponents by binary powering and `w = 1/2`
//! by `sqrt`; `atan z = (i/2)(log(1 - iz) - log(1 + iz))` (DLMF 4.23.26) written with
//! `atan2` and `ln_1p`. Details, cuts and the values taken on them: `elementary/mod.rs`.
//!
//! # Error bound
//!
//! As for every function of `elementary/mod.rs`: the rounding of each real operation
//! plus the propagated input radius; a rectangle that contains the origin (log) or a
//! singular point (atan at `+-i`) gives the indeterminate ball or the enclosing disc
//! stated at each function.

use rug::float::Round;
use rug::ops::AssignRound;
use rug::Float;

use super::{disc, finish, signed_like, touches_negative_axis};
use crate::ball::elementary::nan_ball;
use crate::ball::{Ball, CBall, Mag};

impl CBall {

    /// `ln|z|` as a real ball (the rectangle must exclude 0).
    fn ln_abs(&self) -> Ball {
        let p = self.prec();
        let (x, y) = (&self.re, &self.im);
        let n = x.sqr_nonneg().add(&y.sqr_nonneg());
        let nf = n.mid().to_f64();
        if (0.5..2.0).contains(&nf) {
            // ln|z| = ln_1p((x - 1)(x + 1) + y^2) / 2: a small result stays accurate
            let d = x.sub(&Ball::one(p)).mul(&x.add(&Ball::one(p))).add(&y.sqr_nonneg());
            let l = d.ln_1p_ball();
            if l.is_finite() {
                return l.mul_pow2(-1);
            }
        }
        let l = n.ln_ball();
        if l.is_finite() {
            return l.mul_pow2(-1);
        }
        // a wide rectangle whose squared modulus came out reaching 0: the modulus bounds
        let (lo, hi) = (self.abs_lower_mag(), self.abs_upper_mag());
        if lo.is_zero() || !hi.is_finite() {
            return nan_ball(p);
        }
        let mut a = Float::new(p);
        a.assign_round(lo.to_float().ln_ref(), Round::Down);
        let mut b = Float::new(p);
        b.assign_round(hi.to_float().ln_ref(), Round::Up);
        Ball::hull(&a, &b, p)
    }

    fn log_impl(&self, analytic: bool) -> CBall {
        let p = self.prec();
        if !self.is_finite() || self.contains_zero() {
            return CBall::indeterminate(p);
        }
        if self.is_real() {
            if self.re.is_positive() {
                return finish(CBall::from_real(self.re.ln_ball()), p);
            }
            if analytic {
                return CBall::indeterminate(p);
            }
            // on the cut, from above: ln|x| + i pi
            return finish(CBall::new(self.re.neg().ln_ball(), Ball::pi(p)), p);
        }
        if analytic && touches_negative_axis(self) {
            return CBall::indeterminate(p);
        }
        finish(CBall::new(self.ln_abs(), self.im.atan2(&self.re)), p)
    }

    /// Principal logarithm `ln|z| + i Arg z`, `Arg` in `(-pi, pi]` (DLMF 4.2.1-3).
    /// Indeterminate when the rectangle contains 0; on a rectangle that straddles the
    /// cut the imaginary part covers `[-pi, pi]`.
    pub fn log(&self) -> CBall {
        self.log_impl(false)
    }

    /// [`CBall::log`], but indeterminate as soon as the rectangle touches `(-inf, 0]`.
    pub fn log_analytic(&self) -> CBall {
        self.log_impl(true)
    }

    fn sqrt_impl(&self, analytic: bool) -> CBall {
        let p = self.prec();
        if !self.is_finite() {
            return CBall::indeterminate(p);
        }
        let (x, y) = (&self.re, &self.im);
        if analytic && touches_negative_axis(self) {
            return CBall::indeterminate(p);
        }
        if self.is_real() {
            if x.is_positive() {
                return finish(CBall::from_real(x.sqrt_ball()), p);
            }
            // principal: sqrt(x) for x >= 0, i sqrt(-x) for x < 0
            if x.is_negative() {
                return finish(CBall::new(Ball::zero(p), x.neg().sqrt_ball()), p);
            }
            return finish(CBall::new(x.sqrt_nonneg(), x.neg().sqrt_nonneg()), p);
        }
        let n = x.sqr_nonneg().add(&y.sqr_nonneg());
        if self.contains_zero() || !n.is_positive() {
            // |sqrt z| <= sqrt(max |z|): Re in [0, B], Im in [-B, B]
            let hi = self.abs_upper_mag();
            if !hi.is_finite() {
                return CBall::indeterminate(p);
            }
            let mut b = Float::new(53);
            b.assign_round(hi.to_float().sqrt_ref(), Round::Up);
            let bm = Mag::from_float_up(&b);
            return finish(CBall::new(disc(bm, p), disc(bm, p)), p);
        }
        let a = n.sqrt_ball();
        let re_of = || a.add(x).mul_pow2(-1).sqrt_nonneg();
        let im_abs = || a.sub(x).mul_pow2(-1).sqrt_nonneg();
        if !x.mid().is_sign_negative() {
            let re = re_of();
            if re.is_positive() {
                if let Ok(im) = y.div(&re.mul_pow2(1)) {
                    return finish(CBall::new(re, im), p);
                }
            }
            return finish(CBall::new(re, signed_like(im_abs(), y)), p);
        }
        let t = im_abs();
        if t.is_positive() && !y.contains_zero() {
            if let Ok(re) = y.abs_ball().div(&t.mul_pow2(1)) {
                return finish(CBall::new(re, signed_like(t, y)), p);
            }
        }
        finish(CBall::new(re_of(), signed_like(t, y)), p)
    }

    /// Principal square root (`Re >= 0`; on the cut `sqrt(-x) = i sqrt x`, DLMF 4.2(iv)).
    pub fn sqrt(&self) -> CBall {
        self.sqrt_impl(false)
    }

    /// [`CBall::sqrt`], but indeterminate as soon as the rectangle touches `(-inf, 0]`.
    pub fn sqrt_analytic(&self) -> CBall {
        self.sqrt_impl(true)
    }

    /// The exponent as an exact integer, if it is one (and fits comfortably in i64).
    fn as_exact_integer(&self) -> Option<i64> {
        if !self.is_real() || !self.re.is_exact() {
            return None;
        }
        let m = self.re.mid();
        if !m.is_integer() || m.clone().abs() >= (1u64 << 62) {
            return None;
        }
        m.to_integer()?.to_i64()
    }

    fn pow_impl(&self, w: &CBall, analytic: bool) -> CBall {
        let p = self.prec().max(w.prec());
        if !self.is_finite() || !w.is_finite() {
            return CBall::indeterminate(p);
        }
        if let Some(n) = w.as_exact_integer() {
            return finish(self.pow_i64(n), p);
        }
        if w.is_real() && w.re.is_exact() && *w.re.mid() == 0.5 {
            return self.sqrt_impl(analytic);
        }
        if self.is_real() && self.re.is_positive() && w.is_real() {
            let l = self.re.ln_ball();
            return finish(CBall::from_real(l.mul(&w.re).exp_ball()), p);
        }
        if self.contains_zero() {
            if analytic || !w.re.is_positive() {
                return CBall::indeterminate(p);
            }
            // |z^w| = |z|^Re w e^(-Im w Arg z) <= U^a e^(pi |Im w|), a = lower or upper Re w
            let u = self.abs_upper_mag();
            let mut lu = Float::new(53);
            lu.assign_round(u.to_float().ln_ref(), Round::Up);
            let a = if lu.is_sign_negative() { w.re.lower() } else { w.re.upper() };
            let mut t = Float::new(64);
            t.assign_round(&lu * &a, Round::Up);
            let mut pim = Float::new(64);
            let (wi, piu) = (w.im.abs_upper_mag().to_float(), Ball::pi(53).upper());
            pim.assign_round(&wi * &piu, Round::Up);
            let mut s = Float::new(64);
            s.assign_round(&t + &pim, Round::Up);
            let mut b = Float::new(64);
            b.assign_round(s.exp_ref(), Round::Up);
            let bm = Mag::from_float_up(&b);
            return finish(CBall::new(disc(bm, p), disc(bm, p)), p);
        }
        let l = self.log_impl(analytic);
        if !l.is_finite() {
            return CBall::indeterminate(p);
        }
        w.mul(&l).exp()
    }

    /// Principal power `z^w = exp(w log z)` (DLMF 4.2.26). An exact integer `w` uses
    /// binary powering (no cut; indeterminate at a pole `0^-n`).
    pub fn pow(&self, w: &CBall) -> CBall {
        self.pow_impl(w, false)
    }

    /// [`CBall::pow`], but indeterminate when the rectangle touches `(-inf, 0]`
    /// (unless `w` is an exact integer).
    pub fn pow_analytic(&self, w: &CBall) -> CBall {
        self.pow_impl(w, true)
    }

    // ----- inverse tangent ------------------------------------------------

    fn atan_impl(&self, analytic: bool) -> CBall {
        let p = self.prec();
        if !self.is_finite() {
            return CBall::indeterminate(p);
        }
        if self.is_real() {
            return finish(CBall::from_real(self.re.atan()), p);
        }
        let (x, y) = (&self.re, &self.im);
        let one = Ball::one(p);
        if analytic && x.contains_zero() && (y.upper() >= 1 || y.lower() <= -1) {
            return CBall::indeterminate(p);
        }
        // Re = (Arg(1 + iz) - Arg(1 - iz)) / 2; 1 + iz = (1 - y) + ix, 1 - iz = (1 + y) - ix
        let re = x.atan2(&one.sub(y)).sub(&x.neg().atan2(&one.add(y))).mul_pow2(-1);
        // Im = ln_1p(4y / (x^2 + (1 - y)^2)) / 4, odd in y
        let neg = y.mid().is_sign_negative();
        let ya = if neg { y.neg() } else { y.clone() };
        let den = x.sqr_nonneg().add(&one.sub(&ya).sqr_nonneg());
        let mut im = match ya.mul_pow2(2).div(&den) {
            Ok(q) => q.ln_1p_ball().mul_pow2(-2),
            Err(_) => return CBall::indeterminate(p),
        };
        if !im.is_finite() {
            // a wide rectangle: (ln(x^2 + (1 + y)^2) - ln(x^2 + (1 - y)^2)) / 4
            let num = x.sqr_nonneg().add(&one.add(&ya).sqr_nonneg());
            im = num.ln_ball().sub(&den.ln_ball()).mul_pow2(-2);
        }
        finish(CBall::new(re, if neg { im.neg() } else { im }), p)
    }

    /// Principal inverse tangent, cuts `i(-inf, -1]` and `i[1, inf)` (DLMF 4.23.26);
    /// indeterminate where the rectangle reaches `+-i`.
    pub fn atan(&self) -> CBall {
        self.atan_impl(false)
    }

    /// [`CBall::atan`], but indeterminate as soon as the rectangle touches a cut.
    pub fn atan_analytic(&self) -> CBall {
        self.atan_impl(true)
    }
}
