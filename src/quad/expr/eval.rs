//! Evaluating a tree in any number type that has the operations it needs.

use std::borrow::Cow;

use super::tree::{Expr, Function};
use crate::ball::{Ball, CBall, Decimal};

/// The operations an [`Expr`] is evaluated with.
///
/// Implemented for `f64` (ordinary floating point: a quick look, plots, tests)
/// and for [`CBall`](crate::ball::CBall) (certified complex balls, with the
/// branch-cut functions in their analytic forms, for the certified integrator).
/// Arithmetic never fails: a value that is not defined is whatever the type uses
/// for that (NaN for `f64`, the indeterminate ball for `CBall`).
pub trait ExprValue: Clone {
    /// `self + other`.
    fn add(&self, other: &Self) -> Self;
    /// `self - other`.
    fn sub(&self, other: &Self) -> Self;
    /// `self * other`.
    fn mul(&self, other: &Self) -> Self;
    /// `self / other`.
    fn div(&self, other: &Self) -> Self;
    /// `-self`.
    fn neg(&self) -> Self;
    /// `1 / self` (what `1/a` evaluates to: cheaper than a division).
    fn recip(&self) -> Self;
    /// `self^n` by integer powering (defined for every `self` but zero when `n < 0`).
    fn pow_int(&self, n: i64) -> Self;
    /// `self^e`, the general power `exp(e log self)`.
    fn pow(&self, e: &Self) -> Self;
    /// `f(self)` for a one-argument function.
    fn apply(&self, f: Function) -> Self;
    /// `J_n(self)`.
    fn bessel_j(&self, n: i64) -> Self;
    /// The constant pi, in the kind (precision) of `like`.
    fn pi(like: &Self) -> Self;
    /// A value that contains the decimal `d` exactly, in the kind of `like`
    /// (a ball for ball types, the nearest double for `f64`).
    fn from_decimal(d: &Decimal, like: &Self) -> Self;
    /// `e` at `x`: what [`Expr::eval`] computes. The default evaluates the tree node by
    /// node; the integrator's argument overrides it on a piece mapped at an end
    /// (`mapped.rs`).
    #[doc(hidden)]
    fn eval_expr(e: &Expr, x: &Self) -> Self {
        e.eval_plain(x)
    }
}

/// `sech` for f64, so that [`apply_function!`] reads the same for every type.
trait SechF64 {
    fn sech(&self) -> f64;
}

impl SechF64 for f64 {
    fn sech(&self) -> f64 {
        1.0 / self.cosh()
    }
}

/// Whether `e` is the literal 1.
fn is_one(e: &Expr) -> bool {
    matches!(e, Expr::Number(d) if *d.as_rational() == 1)
}

/// `f(x)` through the methods of `x`'s type: `$sqrt`, `$log` and `$atan` name the
/// forms taken for the functions with a branch cut.
macro_rules! apply_function {
    ($x:expr, $f:expr, $sqrt:ident, $log:ident, $atan:ident) => {
        match $f {
            Function::Sqrt => $x.$sqrt(),
            Function::Exp => $x.exp(),
            Function::Log => $x.$log(),
            Function::Sin => $x.sin(),
            Function::Cos => $x.cos(),
            Function::Tan => $x.tan(),
            Function::Sinh => $x.sinh(),
            Function::Cosh => $x.cosh(),
            Function::Tanh => $x.tanh(),
            Function::Sech => $x.sech(),
            Function::Atan => $x.$atan(),
        }
    };
}
pub(crate) use apply_function;

impl Expr {
    /// The value at `x`, computed in the type of `x` (constants take its precision).
    pub fn eval<V: ExprValue>(&self, x: &V) -> V {
        V::eval_expr(self, x)
    }

    /// [`Expr::eval`] node by node, whatever `x` carries.
    pub(crate) fn eval_plain<V: ExprValue>(&self, x: &V) -> V {
        self.eval_cow(x).into_owned()
    }

    /// [`Expr::eval`], with the variable itself borrowed rather than copied (every
    /// operation takes its operands by reference, so `exp(x)` copies nothing).
    fn eval_cow<'x, V: ExprValue>(&self, x: &'x V) -> Cow<'x, V> {
        let go = |e: &Expr| e.eval_cow(x);
        Cow::Owned(match self {
            Expr::X => return Cow::Borrowed(x),
            Expr::Pi => V::pi(x),
            Expr::Number(d) => V::from_decimal(d, x),
            Expr::Neg(a) => go(a).neg(),
            Expr::Add(a, b) => go(a).add(&go(b)),
            Expr::Sub(a, b) => go(a).sub(&go(b)),
            Expr::Mul(a, b) => go(a).mul(&go(b)),
            Expr::Div(a, b) if is_one(a) => go(b).recip(),
            Expr::Div(a, b) => go(a).div(&go(b)),
            Expr::PowInt(a, n) => go(a).pow_int(*n),
            Expr::Pow(a, b) => go(a).pow(&go(b)),
            Expr::Call(f, a) => go(a).apply(*f),
            Expr::BesselJ(n, a) => go(a).bessel_j(*n),
        })
    }

    /// The value at `x` in f64 (no bound: for a quick look and plots).
    pub fn eval_f64(&self, x: f64) -> f64 {
        self.eval(&x)
    }
}

/// Plain floating point: `log` and `sqrt` of negative numbers are NaN, `besselj`
/// is [`bessel_j`](crate::special::bessel_j::bessel_j) (NaN where it returns an error).
impl ExprValue for f64 {
    fn add(&self, other: &f64) -> f64 {
        self + other
    }
    fn sub(&self, other: &f64) -> f64 {
        self - other
    }
    fn mul(&self, other: &f64) -> f64 {
        self * other
    }
    fn div(&self, other: &f64) -> f64 {
        self / other
    }
    fn neg(&self) -> f64 {
        -self
    }
    fn recip(&self) -> f64 {
        1.0 / self
    }
    fn pow_int(&self, n: i64) -> f64 {
        match i32::try_from(n) {
            Ok(n) => self.powi(n),
            Err(_) => self.powf(n as f64),
        }
    }
    fn pow(&self, e: &f64) -> f64 {
        self.powf(*e)
    }
    fn apply(&self, f: Function) -> f64 {
        apply_function!(self, f, sqrt, ln, atan)
    }
    fn bessel_j(&self, n: i64) -> f64 {
        crate::special::bessel_j::bessel_j(n, *self).unwrap_or(f64::NAN)
    }
    fn pi(_: &f64) -> f64 {
        std::f64::consts::PI
    }
    fn from_decimal(d: &Decimal, _: &f64) -> f64 {
        d.to_f64()
    }
}

/// Certified complex balls. The functions with a branch cut are the *analytic*
/// forms (`log_analytic`, `sqrt_analytic`, `pow_analytic`, `atan_analytic`): a
/// rectangle that touches the cut gives the indeterminate ball, so a finite result
/// means the expression is holomorphic on the whole rectangle. Constants take the
/// precision of `x`.
impl ExprValue for CBall {
    fn add(&self, other: &CBall) -> CBall {
        CBall::add(self, other)
    }
    fn sub(&self, other: &CBall) -> CBall {
        CBall::sub(self, other)
    }
    fn mul(&self, other: &CBall) -> CBall {
        CBall::mul(self, other)
    }
    fn div(&self, other: &CBall) -> CBall {
        CBall::div(self, other)
    }
    fn neg(&self) -> CBall {
        CBall::neg(self)
    }
    fn recip(&self) -> CBall {
        CBall::recip(self)
    }
    fn pow_int(&self, n: i64) -> CBall {
        self.pow_i64(n)
    }
    fn pow(&self, e: &CBall) -> CBall {
        self.pow_analytic(e)
    }
    fn apply(&self, f: Function) -> CBall {
        apply_function!(self, f, sqrt_analytic, log_analytic, atan_analytic)
    }
    fn bessel_j(&self, n: i64) -> CBall {
        CBall::bessel_j(self, n)
    }
    fn pi(like: &CBall) -> CBall {
        CBall::from_real(Ball::pi(like.prec()))
    }
    fn from_decimal(d: &Decimal, like: &CBall) -> CBall {
        CBall::from_real(d.to_ball(like.prec()))
    }
}
