//! [`HoloBall`]: the integrand's argument, a complex ball that can only be
//! transformed by functions that are holomorphic wherever they return a finite ball.
//!
//! # Why a type and not a flag
//!
//! A Gauss-Legendre error bound holds only where the integrand is holomorphic. Arb
//! asks the user's integrand to check that itself, through an `analytic` flag it must
//! remember to test before every function with a branch cut: forget it, and
//! `sqrt(x)` on `[1, 4]` returns a wrong ball with no warning. Here the integrand
//! receives a `HoloBall`, and the only functions it offers with a branch cut
//! (`sqrt`, `log`, `pow`, `atan`) consult the evaluation mode the integrator set:
//!
//! * at the quadrature nodes and on real segments (*point* mode) they take the
//!   principal branch, which is what the integral of a real function means;
//! * on the complex box that encloses a Bernstein ellipse (*analytic* mode) they
//!   return the indeterminate ball when the box touches their cut, so the piece is
//!   bisected instead of bounded by a value of the wrong branch.
//!
//! The mode is private: an integrand cannot read or change it, and `HoloBall` does
//! not hand out its inner [`CBall`], so a principal-branch `CBall` function cannot be
//! applied by mistake. The one way to apply another function is
//! [`HoloBall::map_holomorphic`], whose name states the caller's promise.

use std::ops::{Add, Div, Mul, Neg, Sub};

use rug::Rational;

use crate::ball::{Ball, CBall, Decimal};

/// Where the integrand is being evaluated (set by the integrator only).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Mode {
    /// Real points and real segments: principal branches.
    Point,
    /// A complex box around a Bernstein ellipse: branch cuts give indeterminate balls.
    Analytic,
}

/// A complex ball seen by an integrand; see the module docs.
#[derive(Clone, Debug)]
pub struct HoloBall {
    z: CBall,
    mode: Mode,
    /// Set by the integrator on the argument of a piece mapped at an end
    /// (`singular.rs`); every operation drops it.
    end: Option<Box<MappedEnd>>,
}

/// The argument of a piece mapped at an end `e`: `x = e + sign t` with `t = exp(log_t)`,
/// both computed from the integrator's variable `s` without cancellation (`t = d e^{-s}`,
/// `log_t = log d - s`), holomorphic in `s`, and on the real axis `t > 0` and `log_t`
/// the real logarithm of `t`. The expression evaluator reads it (`quad/expr/mapped.rs`)
/// so that `log(x - e)`, `(x - e)^r` and the like are evaluated from `log_t`, entire in
/// `s`, instead of from `x`, whose box turns around `e` when `Im s` is large.
#[derive(Clone, Debug)]
pub(crate) struct MappedEnd {
    /// `e`, when it is an exact rational (otherwise the evaluator evaluates as usual).
    pub(crate) e: Option<Rational>,
    /// `+1` or `-1`.
    pub(crate) sign: i64,
    pub(crate) t: CBall,
    pub(crate) log_t: CBall,
}

macro_rules! cut_function {
    ($(#[$doc:meta])* $name:ident, $analytic:ident) => {
        $(#[$doc])*
        pub fn $name(&self) -> HoloBall {
            let z = match self.mode {
                Mode::Point => self.z.$name(),
                Mode::Analytic => self.z.$analytic(),
            };
            self.with(z)
        }
    };
}

macro_rules! entire_function {
    ($(#[$doc:meta])* $name:ident) => {
        $(#[$doc])*
        pub fn $name(&self) -> HoloBall {
            self.with(self.z.$name())
        }
    };
}

impl HoloBall {
    pub(crate) fn new(z: CBall, mode: Mode) -> HoloBall {
        HoloBall { z, mode, end: None }
    }

    /// `self`, marked as the argument of a piece mapped at an end ([`MappedEnd`]).
    pub(crate) fn with_end(mut self, end: MappedEnd) -> HoloBall {
        self.end = Some(Box::new(end));
        self
    }

    /// The end this argument was mapped at, if any.
    pub(crate) fn mapped_end(&self) -> Option<&MappedEnd> {
        self.end.as_deref()
    }

    pub(crate) fn into_inner(self) -> CBall {
        self.z
    }

    pub(crate) fn inner(&self) -> &CBall {
        &self.z
    }

    /// The ball itself, for the integrator to move a point in place.
    pub(crate) fn inner_mut(&mut self) -> &mut CBall {
        &mut self.z
    }

    fn with(&self, z: CBall) -> HoloBall {
        HoloBall { z, mode: self.mode, end: None }
    }

    /// Working precision of the evaluation (bits): make constants at this precision.
    pub fn prec(&self) -> u32 {
        self.z.prec()
    }

    /// A constant (a constant is holomorphic).
    pub fn constant(&self, c: CBall) -> HoloBall {
        self.with(c)
    }

    /// A real constant.
    pub fn real(&self, c: Ball) -> HoloBall {
        self.with(CBall::from_real(c))
    }

    /// An integer constant.
    pub fn int(&self, n: i64) -> HoloBall {
        self.with(CBall::from_i64(n, self.prec()))
    }

    /// A decimal constant, as the ball that contains it at this precision.
    pub fn decimal(&self, d: &Decimal) -> HoloBall {
        self.real(d.to_ball(self.prec()))
    }

    /// pi.
    pub fn pi(&self) -> HoloBall {
        self.real(Ball::pi(self.prec()))
    }

    /// Applies `f`, which the caller promises is holomorphic wherever it returns a
    /// finite ball, and which encloses its values on every input rectangle. Use it
    /// for special functions of this crate with no `HoloBall` method.
    pub fn map_holomorphic<F: FnOnce(&CBall) -> CBall>(&self, f: F) -> HoloBall {
        self.with(f(&self.z))
    }

    /// The ball itself, to inspect (read only: functions are applied through the
    /// methods, so the evaluation mode cannot be bypassed).
    pub fn inner_ref(&self) -> &CBall {
        &self.z
    }

    /// Whether the ball is finite (a non-finite ball marks a pole or a cut).
    pub fn is_finite(&self) -> bool {
        self.z.is_finite()
    }

    /// `self^n` for an integer `n` (no branch cut; a pole at 0 for `n < 0`).
    pub fn powi(&self, n: i64) -> HoloBall {
        self.with(self.z.pow_i64(n))
    }

    /// `self^2`.
    pub fn sqr(&self) -> HoloBall {
        self.with(self.z.sqr())
    }

    /// `1/self` (a pole where `self` reaches 0).
    pub fn recip(&self) -> HoloBall {
        self.with(self.z.recip())
    }

    /// `self^w = exp(w log self)`, principal branch, cut along `(-inf, 0]`.
    pub fn pow(&self, w: &HoloBall) -> HoloBall {
        let z = match self.mode {
            Mode::Point => self.z.pow(&w.z),
            Mode::Analytic => self.z.pow_analytic(&w.z),
        };
        self.with(z)
    }

    cut_function!(
        /// Square root, principal branch, cut along `(-inf, 0]`.
        sqrt, sqrt_analytic
    );
    cut_function!(
        /// Natural logarithm, principal branch, cut along `(-inf, 0]`.
        log, log_analytic
    );
    cut_function!(
        /// Arc tangent, principal branch, cuts along `i(-inf, -1]` and `i[1, inf)`.
        atan, atan_analytic
    );
    entire_function!(
        /// `e^self`.
        exp
    );
    entire_function!(
        /// Sine.
        sin
    );
    entire_function!(
        /// Cosine.
        cos
    );
    entire_function!(
        /// Tangent (poles where `cos` vanishes).
        tan
    );
    entire_function!(
        /// Hyperbolic sine.
        sinh
    );
    entire_function!(
        /// Hyperbolic cosine.
        cosh
    );
    entire_function!(
        /// Hyperbolic tangent (poles where `cosh` vanishes).
        tanh
    );
    entire_function!(
        /// Hyperbolic secant `1/cosh` (poles where `cosh` vanishes), enclosed
        /// tightly on rectangles far from the imaginary axis.
        sech
    );

    /// The Bessel function `J_n(self)`, entire for integer `n`.
    pub fn besselj(&self, n: i64) -> HoloBall {
        self.with(self.z.bessel_j(n))
    }
}

macro_rules! binary_op {
    ($trait:ident, $method:ident, $call:ident) => {
        impl $trait<&HoloBall> for &HoloBall {
            type Output = HoloBall;
            fn $method(self, rhs: &HoloBall) -> HoloBall {
                self.with(self.z.$call(&rhs.z))
            }
        }
        impl $trait<HoloBall> for HoloBall {
            type Output = HoloBall;
            fn $method(self, rhs: HoloBall) -> HoloBall {
                (&self).$method(&rhs)
            }
        }
        impl $trait<&HoloBall> for HoloBall {
            type Output = HoloBall;
            fn $method(self, rhs: &HoloBall) -> HoloBall {
                (&self).$method(rhs)
            }
        }
        impl $trait<HoloBall> for &HoloBall {
            type Output = HoloBall;
            fn $method(self, rhs: HoloBall) -> HoloBall {
                self.$method(&rhs)
            }
        }
    };
}

binary_op!(Add, add, add);
binary_op!(Sub, sub, sub);
binary_op!(Mul, mul, mul);
binary_op!(Div, div, div);

impl Neg for &HoloBall {
    type Output = HoloBall;
    fn neg(self) -> HoloBall {
        self.with(self.z.neg())
    }
}

impl Neg for HoloBall {
    type Output = HoloBall;
    fn neg(self) -> HoloBall {
        -&self
    }
}
