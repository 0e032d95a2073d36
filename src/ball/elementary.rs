//! Real-ball elementary functions that the complex ones ([`super::CBall`]) are built on.
//!
//! # Method
//!
//! Each function evaluates MPFR once at the midpoint `m`, rounded to nearest at the
//! ball's precision (error at most one ulp, zero when MPFR reports the result exact),
//! and adds a bound for the effect of the input radius `r` from the derivative. `exp`,
//! `sin` and `cos` take the midpoint value and its error bound from the fixed-point
//! kernels of [`super::fixed`] instead, where those serve the precision and argument:
//!
//! * `exp`: `|e^(m+t) - e^m| <= e^m (e^r - 1)`;
//! * `sinh`, `cosh`: `|sinh(m+t) - sinh m|, |cosh(m+t) - cosh m| <= cosh(m) (e^r - 1)`
//!   (from the addition theorems and `|sinh m| <= cosh m`, DLMF 4.35.19-20), both from
//!   one MPFR `sinh_cosh` call;
//! * `sin`, `tanh`, `atan`: 1-Lipschitz (DLMF 4.14, 4.28); `atan` with `1/(1 + x^2)`;
//! * `ln`, `ln_1p`: `r / lower(x)`, `r / lower(1 + x)` (the ball must be positive);
//! * `sqrt`: `|sqrt(m+t) - sqrt(m)| <= r / sqrt(m)`;
//! * `atan2(y, x)` (the argument of `x + iy`): `d/dy = x / |z|^2`, `d/dx = -y / |z|^2`, so
//!   the radius is `(r_y upper|x| + r_x upper|y|) / lower|z|^2` while the rectangle keeps
//!   off the cut `x <= 0, y = 0`. On
//!   the cut MPFR's principal convention `atan2(+0, x < 0) = pi` is kept: a rectangle in
//!   the closed upper half plane uses the derivative bound (the argument is continuous
//!   there), one that reaches below the cut gets `[0 +/- pi]`, the whole range.
//!
//! `e^r - 1` is bounded by `r + r^2` for `r <= 1` (the Taylor tail is at most
//! `(e - 2) r^2`) and by MPFR's upward-rounded `expm1` at 53 bits above that.
//!
//! # Non-finite results
//!
//! The `*_ball` helpers never fail: where the result is unbounded or undefined
//! (overflow of MPFR's exponent range, a logarithm of a ball reaching zero) they return
//! a NaN midpoint with an infinite radius, which [`Ball::is_finite`] reports. An
//! underflowing `exp` gives `[0 +/- 2^emin]`.

use rug::float::{Round, Special};
use rug::ops::AssignRound;
use rug::Float;

use super::{rounding_error, Ball, Mag};

/// The real ball "no information": NaN midpoint, infinite radius.
/// Radius above which the monotone functions use their end values instead of a
/// derivative bound at the midpoint (tighter, and sign-preserving, for wide balls).
const WIDE: Mag = Mag::pow2_const(-8);

/// Precision of the end (or midpoint) values of a wide ball (radius above [`WIDE`]):
/// its result is at least `2^-17` wide relative to its size (the radius, or the
/// second-order term of `sin`/`cos`, see [`Ball::sin_cos`]), so values rounded
/// outward at 64 bits widen it by a relative `2^-47` of its width at most, and cost a
/// fraction of the full precision's (the boxes around Bernstein ellipses of the
/// integrator are such balls: at 3333 bits their `exp`, `sinh`, `cosh` at full
/// precision were most of a box's evaluation).
pub(crate) const WIDE_EVAL_PREC: u32 = 64;

/// The precision of a wide ball's values ([`WIDE_EVAL_PREC`] where that saves limbs).
pub(crate) fn wide_eval_prec(p: u32) -> u32 {
    if p > 2 * WIDE_EVAL_PREC { WIDE_EVAL_PREC } else { p }
}

/// The precision of a ball's midpoint values: [`wide_eval_prec`] for a wide ball
/// (radius above [`WIDE`]), its own otherwise.
pub(crate) fn mid_eval_prec(b: &Ball) -> u32 {
    if b.rad.le(&WIDE) { b.prec() } else { wide_eval_prec(b.prec()) }
}

pub(crate) fn nan_ball(prec: u32) -> Ball {
    Ball { mid: Float::with_val(prec, Special::Nan), rad: Mag::inf() }
}

/// An upper bound of `e^r - 1`.
pub(crate) fn expm1_up(r: Mag) -> Mag {
    if r.is_zero() {
        return Mag::ZERO;
    }
    if !r.is_finite() {
        return Mag::inf();
    }
    if r.le(&Mag::pow2(0)) {
        return r.add(r.mul(r));
    }
    let mut y = Float::new(53);
    y.assign_round(r.to_float().exp_m1_ref(), Round::Up);
    Mag::from_float_up(&y)
}

/// `mid +/- (err + scale * expm1(r))` with `scale = |mid| + err`; non-finite
/// midpoints become the NaN ball.
fn with_lipschitz(mid: Float, err: Mag, scale_mid: &Float, r: Mag) -> Ball {
    if !mid.is_finite() || !scale_mid.is_finite() || !err.is_finite() {
        return nan_ball(mid.prec());
    }
    let mut rad = err;
    if !r.is_zero() {
        rad = rad.add(Mag::from_float_up(scale_mid).add(err).mul(expm1_up(r)));
    }
    Ball { mid, rad }
}

/// Radius above which a sine or cosine ball is intersected with `[-1, 1]`.
const UNIT_CLAMP: Mag = Mag::pow2_const(-1);

/// A sine or cosine ball of a real argument intersected with `[-1, 1]`, which holds
/// every value: the 1-Lipschitz bound `mid +/- r` alone grows without limit with `r`
/// (on the Bernstein-ellipse boxes of the integrator, `cos [0 +/- 256]` would be
/// `[1 +/- 256]` instead of `[-1, 1]`). Only wide balls (radius above 1/2) are looked
/// at; a NaN ball stays as it is.
pub(crate) fn within_unit(b: Ball) -> Ball {
    if b.rad.le(&UNIT_CLAMP) || !b.is_finite() {
        return b;
    }
    if Mag::pow2(0).le(&b.rad) {
        // radius >= 1: [mid - r, mid + r] reaches past -1 or 1 on at least one side;
        // [0 +/- 1] holds every value, without the ends' arithmetic
        return Ball { mid: Float::with_val(b.prec(), 0), rad: Mag::pow2(0) };
    }
    let (lo, hi) = (b.lower(), b.upper());
    if lo >= -1 && hi <= 1 {
        return b;
    }
    let p = b.prec();
    let lo = if lo < -1 { Float::with_val(p, -1) } else { lo };
    let hi = if hi > 1 { Float::with_val(p, 1) } else { hi };
    Ball::hull(&lo, &hi, p)
}

/// The rounding error of an MPFR result, where an underflow to zero is bounded by
/// the smallest positive float instead of an infinite radius.
fn mpfr_error(y: &Float, ord: std::cmp::Ordering) -> Mag {
    if y.is_zero() && ord != std::cmp::Ordering::Equal {
        return Mag::pow2(rug::float::exp_min() as i64);
    }
    rounding_error(y, ord)
}

/// `(sinh, cosh)` of the wide ball `[0 +- y]` (the imaginary part of the boxes around
/// Bernstein ellipses): `sinh` is odd and increasing, `cosh` even and increasing in
/// `|x|`, so they are `[0 +- sinh y]` and `[1, cosh y]`, from one enclosure
/// `[e_lo, e_hi]` of `e^y` at [`WIDE_EVAL_PREC`] bits: `sinh y <= (e_hi - 1/e_hi) / 2`,
/// `cosh y <= (e_hi + 1/e_lo) / 2`, each operation rounded up (`1/e_hi` rounded down
/// where it is subtracted).
fn sinh_cosh_centred(y: Mag, p: u32) -> (Ball, Ball) {
    let q = WIDE_EVAL_PREC;
    // y <= 2^31 keeps e^y within MPFR's exponent range (2^(2^30)); beyond, the NaN balls
    if !y.le(&Mag::pow2(31)) {
        return (nan_ball(p), nan_ball(p));
    }
    let yf = y.to_float();
    let (e_lo, e_hi) = match super::fixed::exp(&yf, q) {
        Some((e, err)) => {
            let b = Ball { mid: e, rad: err };
            (b.clone().into_end(false), b.into_end(true))
        }
        None => (Float::with_val_round(q, yf.exp_ref(), Round::Down).0, Float::with_val_round(q, yf.exp_ref(), Round::Up).0),
    };
    if !e_hi.is_finite() || !e_lo.is_sign_positive() || e_lo.is_zero() {
        return (nan_ball(p), nan_ball(p));
    }
    let inv_down = Float::with_val_round(q, e_hi.recip_ref(), Round::Down).0;
    let inv_up = Float::with_val_round(q, e_lo.recip_ref(), Round::Up).0;
    let mut sh = Float::with_val_round(q, &e_hi - &inv_down, Round::Up).0;
    sh >>= 1;
    let mut ch = Float::with_val_round(q, &e_hi + &inv_up, Round::Up).0;
    ch >>= 1;
    (Ball { mid: Float::new(p), rad: Mag::from_float_up(&sh) }, Ball::hull(&Float::with_val(q, 1), &ch, p))
}

impl Ball {
    /// `e^self`, never failing: the NaN ball on overflow (see the module docs).
    pub(crate) fn exp_ball(&self) -> Ball {
        let p = self.prec();
        if !self.is_finite() {
            return nan_ball(p);
        }
        if !self.rad.le(&WIDE) {
            // A wide ball: exp is increasing, so the hull of the directed-rounded
            // values at the ends (it stays positive, unlike mid +- |exp'| r).
            let (lo, hi) = (self.lower(), self.upper());
            // an end of the fixed-point ball when the kernel serves it, else MPFR rounded outward
            let q = wide_eval_prec(p);
            let end = |x: &Float, round: Round| match super::fixed::exp(x, q) {
                Some((y, rad)) => Ball { mid: y, rad }.into_end(round == Round::Up),
                None => Float::with_val_round(q, x.exp_ref(), round).0,
            };
            let (a, b) = (end(&lo, Round::Down), end(&hi, Round::Up));
            if !b.is_finite() {
                return nan_ball(p);
            }
            return Ball::hull(&a, &b, p);
        }
        let (y, err) = super::fixed::exp(&self.mid, p).unwrap_or_else(|| {
            let (y, ord) = Float::with_val_round(p, self.mid.exp_ref(), Round::Nearest);
            let err = mpfr_error(&y, ord);
            (y, err)
        });
        with_lipschitz(y.clone(), err, &y, self.rad)
    }

    /// `(sinh self, cosh self)` from one MPFR call; the NaN balls on overflow.
    pub fn sinh_cosh(&self) -> (Ball, Ball) {
        let p = self.prec();
        if !self.is_finite() {
            return (nan_ball(p), nan_ball(p));
        }
        if !self.rad.le(&WIDE) && self.mid.is_zero() {
            return sinh_cosh_centred(self.rad, p);
        }
        if !self.rad.le(&WIDE) {
            // A wide ball: sinh is increasing and cosh increasing in |x|, so the hulls of
            // directed-rounded end values (cosh stays >= 1 instead of dipping below 0).
            let (lo, hi) = (self.lower(), self.upper());
            // beyond 2^31 both overflow MPFR's exponent range (2^(2^30)): say so at once
            // (MPFR's sinh takes long to find out)
            if lo.clone().abs() > (1u64 << 31) || hi.clone().abs() > (1u64 << 31) {
                return (nan_ball(p), nan_ball(p));
            }
            // (sinh x, cosh x) at an end as balls, from the fixed-point exp where it serves,
            // at WIDE_EVAL_PREC bits (the ends themselves exact)
            let q = wide_eval_prec(p);
            let at = |x: &Float| -> Option<(Ball, Ball)> {
                let (ep, ee) = super::fixed::exp(x, q)?;
                let (mp, me) = super::fixed::exp(&Float::with_val(x.prec(), -x), q)?;
                let (e, einv) = (Ball { mid: ep, rad: ee }, Ball { mid: mp, rad: me });
                Some((e.sub(&einv).mul_pow2(-1), e.add(&einv).mul_pow2(-1)))
            };
            let (s_lo, s_hi, c_hi, c_lo) = match (at(&lo), at(&hi)) {
                (Some((sl, cl)), Some((sh, ch))) => {
                    // cosh is even: its largest value is at the end farther from 0
                    let (cl_up, ch_up) = (cl.upper(), ch.upper());
                    let c_hi = if cl_up > ch_up { cl_up } else { ch_up };
                    let c_lo = if lo.is_sign_positive() {
                        cl.lower()
                    } else if hi.is_sign_negative() {
                        ch.lower()
                    } else {
                        Float::with_val(p, 1)
                    };
                    (sl.lower(), sh.upper(), c_hi, c_lo)
                }
                _ => {
                    let far = if lo.clone().abs() > hi.clone().abs() { lo.clone().abs() } else { hi.clone().abs() };
                    let c_lo = if lo.is_sign_positive() {
                        Float::with_val_round(q, lo.cosh_ref(), Round::Down).0
                    } else if hi.is_sign_negative() {
                        Float::with_val_round(q, hi.cosh_ref(), Round::Down).0
                    } else {
                        Float::with_val(q, 1)
                    };
                    (
                        Float::with_val_round(q, lo.sinh_ref(), Round::Down).0,
                        Float::with_val_round(q, hi.sinh_ref(), Round::Up).0,
                        Float::with_val_round(q, far.cosh_ref(), Round::Up).0,
                        c_lo,
                    )
                }
            };
            if !s_lo.is_finite() || !s_hi.is_finite() || !c_hi.is_finite() {
                return (nan_ball(p), nan_ball(p));
            }
            return (Ball::hull(&s_lo, &s_hi, p), Ball::hull(&c_lo, &c_hi, p));
        }
        let mut s = self.mid.clone();
        let mut c = Float::new(p);
        let (os, oc) = s.sinh_cosh_round(&mut c, Round::Nearest);
        if !c.is_finite() {
            return (nan_ball(p), nan_ball(p));
        }
        let (es, ec) = (rounding_error(&s, os), rounding_error(&c, oc));
        // both radii: err + (|cosh m| + err_c) (e^r - 1)
        let prop = if self.rad.is_zero() {
            Mag::ZERO
        } else {
            Mag::from_float_up(&c).add(ec).mul(expm1_up(self.rad))
        };
        let bs = Ball { mid: s, rad: es.add(prop) };
        let bc = Ball { mid: c, rad: ec.add(prop) };
        (bs, bc)
    }

    /// `sinh(self)`.
    pub fn sinh(&self) -> Ball {
        self.sinh_cosh().0
    }

    /// `cosh(self)`.
    pub fn cosh(&self) -> Ball {
        self.sinh_cosh().1
    }

    /// Applies a 1-Lipschitz MPFR function at the midpoint: radius `r + ulp`.
    fn lipschitz1<F>(&self, f: F) -> Ball
    where
        F: FnOnce(&Float, u32) -> (Float, std::cmp::Ordering),
    {
        let p = self.prec();
        if !self.is_finite() {
            return nan_ball(p);
        }
        let (y, ord) = f(&self.mid, p);
        if !y.is_finite() {
            return nan_ball(p);
        }
        let rad = self.rad.add(rounding_error(&y, ord));
        Ball { mid: y, rad }
    }

    /// `sin(self)`.
    pub fn sin(&self) -> Ball {
        let p = self.prec();
        // a wide ball's midpoint value at WIDE_EVAL_PREC bits, then exactly at p
        let q = mid_eval_prec(self);
        if let Some((y, err)) = self.is_finite().then(|| super::fixed::sin(&self.mid, q)).flatten() {
            return within_unit(Ball { mid: Float::with_val(p, y), rad: self.rad.add(err) });
        }
        within_unit(self.lipschitz1(|m, _| {
            let (y, ord) = Float::with_val_round(q, m.sin_ref(), Round::Nearest);
            (Float::with_val(p, y), ord)
        }))
    }

    /// `tanh(self)` (`|tanh'| = sech^2 <= 1`).
    pub fn tanh(&self) -> Ball {
        self.lipschitz1(|m, p| Float::with_val_round(p, m.tanh_ref(), Round::Nearest))
    }

    /// `tan(self) = sin / cos`; the NaN ball when the ball reaches a pole.
    pub fn tan(&self) -> Ball {
        let (s, c) = self.sin_cos();
        s.div(&c).unwrap_or_else(|_| nan_ball(self.prec()))
    }

    /// `atan(self)`: radius `r / (1 + lower(x)^2)`.
    pub fn atan(&self) -> Ball {
        let p = self.prec();
        if !self.is_finite() {
            return nan_ball(p);
        }
        let (y, ord) = Float::with_val_round(p, self.mid.atan_ref(), Round::Nearest);
        let mut rad = rounding_error(&y, ord);
        if !self.rad.is_zero() {
            let l = self.abs_lower_mag();
            let den = Mag::pow2(0).max(l.mul_lower(l));
            rad = rad.add(self.rad.div(den));
        }
        Ball { mid: y, rad }
    }

    /// `atan2(self, x)`: the principal argument of `x + i self`, in `[-pi, pi]`
    /// (MPFR's convention: `pi` on the negative real axis). Never fails; a rectangle
    /// that contains the origin or reaches across the cut gets `[0 +/- pi]`.
    pub fn atan2(&self, x: &Ball) -> Ball {
        let y = self;
        let p = y.prec().max(x.prec());
        if !y.is_finite() || !x.is_finite() {
            return nan_ball(p);
        }
        let whole = || {
            let pi = Ball::pi(p);
            Ball { mid: Float::new(p), rad: Mag::from_float_up(&pi.mid).add(pi.rad) }
        };
        let x_pos = x.is_positive();
        if y.is_exact() && y.mid.is_zero() {
            if x_pos {
                return Ball::zero(p);
            }
            if x.is_negative() {
                return Ball::pi(p);
            }
            return whole();
        }
        if y.contains_zero() && !x_pos {
            // touches the cut, or contains the origin
            if x.contains_zero() || y.lower() < 0 {
                return whole();
            }
            // in the closed upper half plane: continuous, the derivative bound holds
        }
        let (a, ord) = Float::with_val_round(p, y.mid.atan2_ref(&x.mid), Round::Nearest);
        let mut rad = rounding_error(&a, ord);
        if !x.rad.is_zero() || !y.rad.is_zero() {
            // |d/dy| = |x| / |z|^2, |d/dx| = |y| / |z|^2, bounded over the rectangle
            let lo = x.abs_lower_mag().max(y.abs_lower_mag());
            let num = y.rad.mul(x.abs_upper_mag()).add(x.rad.mul(y.abs_upper_mag()));
            rad = rad.add(num.div(lo.mul_lower(lo)));
        }
        Ball { mid: a, rad }
    }

    /// `ln(self)`, never failing: the NaN ball unless the ball is positive.
    pub(crate) fn ln_ball(&self) -> Ball {
        let p = self.prec();
        if !self.is_finite() || !self.mid.is_sign_positive() || self.mid.is_zero() {
            return nan_ball(p);
        }
        let lo = Mag::from_float_down(&self.mid).sub_lower(self.rad);
        if lo.is_zero() {
            return nan_ball(p);
        }
        let (y, ord) = Float::with_val_round(p, self.mid.ln_ref(), Round::Nearest);
        let mut rad = rounding_error(&y, ord);
        if !self.rad.is_zero() {
            rad = rad.add(self.rad.div(lo));
        }
        Ball { mid: y, rad }
    }

    /// `ln(1 + self)`, never failing: the NaN ball unless `self > -1`.
    pub(crate) fn ln_1p_ball(&self) -> Ball {
        let p = self.prec();
        if !self.is_finite() {
            return nan_ball(p);
        }
        let mut lo = Float::new(64);
        lo.assign_round(&self.lower() + 1u32, Round::Down);
        if lo <= 0 {
            return nan_ball(p);
        }
        let (y, ord) = Float::with_val_round(p, self.mid.ln_1p_ref(), Round::Nearest);
        let mut rad = rounding_error(&y, ord);
        if !self.rad.is_zero() {
            rad = rad.add(self.rad.div(Mag::from_float_down(&lo)));
        }
        Ball { mid: y, rad }
    }

    /// `sqrt(self)`, never failing: the NaN ball unless the ball is positive.
    pub(crate) fn sqrt_ball(&self) -> Ball {
        let p = self.prec();
        if !self.is_finite() {
            return nan_ball(p);
        }
        if self.rad.is_zero() && self.mid.is_zero() {
            return Ball::zero(p);
        }
        if !self.is_positive() {
            return nan_ball(p);
        }
        let (y, ord) = Float::with_val_round(p, self.mid.sqrt_ref(), Round::Nearest);
        let err = rounding_error(&y, ord);
        let mut rad = err;
        if !self.rad.is_zero() {
            let lo = Mag::from_float_down(&y).sub_lower(err);
            rad = rad.add(self.rad.div(lo));
        }
        Ball { mid: y, rad }
    }

    /// `sqrt` over the non-negative part of the ball: `[0, sqrt(upper)]` when the ball
    /// reaches zero. For quantities known to be `>= 0` whose enclosure dips below.
    pub(crate) fn sqrt_nonneg(&self) -> Ball {
        let p = self.prec();
        if !self.is_finite() {
            return nan_ball(p);
        }
        if self.is_positive() || (self.is_exact() && self.mid.is_zero()) {
            return self.sqrt_ball();
        }
        let up = self.upper();
        if up < 0 {
            return nan_ball(p);
        }
        let mut s = Float::new(p);
        s.assign_round(up.sqrt_ref(), Round::Up);
        Ball::hull(&Float::new(p), &s, p)
    }

    /// `self^2`, never reaching below zero: for a wide ball (radius above `2^-20 |mid|`)
    /// the exact range `[lower|x|^2, upper|x|^2]` from the 53-bit magnitude bounds, which
    /// is tighter than the product rule; the ordinary square otherwise.
    pub(crate) fn sqr_nonneg(&self) -> Ball {
        if self.rad.le(&Mag::from_float_down(&self.mid).mul_2exp(-20)) {
            return self.sqr();
        }
        let (l, u) = (self.abs_lower_mag(), self.abs_upper_mag());
        if !u.is_finite() {
            return nan_ball(self.prec());
        }
        Ball::hull(&l.mul_lower(l).to_float(), &u.mul(u).to_float(), self.prec())
    }

    /// `|self|` as a ball.
    pub(crate) fn abs_ball(&self) -> Ball {
        if self.mid.is_sign_negative() {
            self.neg()
        } else {
            self.clone()
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn hp(x: f64) -> Float {
        Float::with_val(512, x)
    }

    #[test]
    fn real_helpers_enclose() {
        let p = 128;
        for &(m, r) in &[(0.3, 0.0), (-2.5, 1e-10), (40.0, 0.5), (-0.001, 0.01), (700.0, 2.0)] {
            let mut b = Ball::from_f64(m, p).unwrap();
            b.add_error_mag(Mag::from_f64(r));
            let (s, c) = b.sinh_cosh();
            let e = b.exp_ball();
            let t = b.tanh();
            let a = b.atan();
            for k in 0..=10 {
                let x = hp(m) + hp(r) * (2.0 * k as f64 / 10.0 - 1.0);
                assert!(s.contains(&Float::with_val(512, x.sinh_ref())), "sinh {m} {r}");
                assert!(c.contains(&Float::with_val(512, x.cosh_ref())), "cosh {m} {r}");
                assert!(e.contains(&Float::with_val(512, x.exp_ref())), "exp {m} {r}");
                assert!(t.contains(&Float::with_val(512, x.tanh_ref())), "tanh {m} {r}");
                assert!(a.contains(&Float::with_val(512, x.atan_ref())), "atan {m} {r}");
            }
        }
        // overflow: not finite, no panic
        assert!(!Ball::from_f64(1e300, 64).unwrap().exp_ball().is_finite());
        assert!(!Ball::from_f64(1e300, 64).unwrap().sinh_cosh().1.is_finite());
        let u = Ball::from_f64(-1e300, 64).unwrap().exp_ball();
        assert!(u.is_finite() && u.contains(&Float::new(64)));
    }

    #[test]
    fn atan2_conventions() {
        let p = 64;
        let b = |x: f64| Ball::from_f64(x, p).unwrap();
        let pi = Float::with_val(256, rug::float::Constant::Pi);
        assert!(b(0.0).atan2(&b(-1.0)).contains(&pi));
        let mut y = b(0.5);
        y.add_error_mag(Mag::from_f64(0.5)); // [0, 1]: upper half plane
        let a = y.atan2(&b(-2.0));
        assert!(a.contains(&pi));
        assert!(a.contains(&Float::with_val(256, Float::with_val(256, 1).atan2_ref(&hp(-2.0)))));
        let mut y2 = b(0.0);
        y2.add_error_mag(Mag::from_f64(0.5)); // crosses the cut
        let w = y2.atan2(&b(-2.0));
        assert!(w.contains(&pi) && w.contains(&Float::with_val(256, -&pi)));
    }
}
