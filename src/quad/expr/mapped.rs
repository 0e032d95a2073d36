//! Evaluating an expression on a piece mapped at an end, from the end's own logarithm.
//!
//! # Method
//!
//! Next to a singular end `e` the integrator substitutes `x = e + sign t`, `t = d
//! e^{-s}` (`quad/certified/singular.rs`), and hands the integrand `x` together with
//! `t` and `log_t = log d - s`, both computed from `s` without cancellation
//! ([`MappedEnd`]). Evaluated from `x` alone, `x^x = exp(x Log x)` on `[0, 1]` is
//! holomorphic in `s` only where the box of `x` keeps off the cut of `Log`: a box with
//! `|Im s|` near `pi` puts `x = d e^{-s}` around 0, so every Gauss-Legendre ellipse of
//! the mapped piece was the smallest of the ladder, and the cost grew as the square of
//! the precision (`docs/quadrature.md`). In `s`, `Log x = log d - s` exactly, and `x^x =
//! exp(d e^{-s} (log d - s))` is entire.
//!
//! This evaluator carries, next to the value `v` of a subexpression, when it can, a
//! logarithm `L` of it. By induction over the tree, for every node:
//!
//! 1. `v` is a function `G(s)` holomorphic on every box where it is evaluated finite
//!    (compositions of holomorphic functions, the functions with a cut being
//!    [`HoloBall`]'s, which check their cut on the box);
//! 2. on the real `s` axis `G(s)` is the expression's value at `x(s)` with principal
//!    branches, `F(x(s))`;
//! 3. where `L` is given: `e^L = v` on the whole box, and `L` is real on the real axis
//!    (so `v = e^L > 0` there, and `L = ln v`).
//!
//! The rules (`sigma`, `c` exact; every other node takes its usual value from its
//! operands' values and has no `L`):
//!
//! * **affine leaf** `u = c0 + c1 x` (found by `local::affine`) with `c0 + c1 e = 0` and
//!   `sigma = c1 sign > 0`: `u = c1 (x - e) = sigma t`, so `v = sigma t` (no
//!   cancellation however small `t`) and `L = ln sigma + log_t` (`e^{log_t} = d e^{-s} =
//!   t`; real on the real axis). `x` itself is such a leaf when `e = 0`, `sign = +1`.
//! * **products** `a b`: `L = L_a + L_b` (`e^{L_a + L_b} = v_a v_b`); `a / b`: `L_a -
//!   L_b`; `1 / b`: `-L_b`; `c b`, `b c`, `b / c` with a constant `c` real and `> 0`:
//!   `ln c + L_b` (`- ln c` for `/ c`). The value is the product or quotient of the
//!   operands' values, or, for a quotient, `e^L` (the same holomorphic function,
//!   finite where the denominator's box reaches 0).
//! * **integer powers** `a^n`: `L = n L_a`; `v = v_a^n` for `n >= 0`, `e^{n L_a}` for
//!   `n < 0`.
//! * **general powers** `a^b`: the principal `a^b` is `exp(b Log a)`, and on the real
//!   axis `Log a = ln a = L_a` (`a > 0`), so `v = exp(b L_a)` satisfies 1 and 2
//!   (`b`'s value is holomorphic by induction). `L = b L_a` when `b` does not depend on
//!   `x` and is real (its ball has an exact zero imaginary part), so that `L` is real
//!   on the real axis. `sqrt(a)`: `v = exp(L_a / 2)`, `L = L_a / 2`.
//! * **logarithm** `log(a)`: `v = L_a` (principal `Log a = ln a = L_a` on the real axis,
//!   and `L_a` is holomorphic); no `L`.
//!
//! By 1 and 2, the mapped integrand evaluated this way is the analytic continuation off
//! the real axis of the integrand the user wrote, so the Gauss-Legendre error bound
//! from its maximum on an ellipse holds. `e^{x}` gets no `L`: `L = a` would need `a`
//! real on the real axis, which a subtree with a cut need not be.

use rug::Rational;

use super::eval::{apply_function, ExprValue};
use super::local::affine;
use super::tree::{Expr, Function};
use crate::ball::Decimal;
use crate::quad::certified::{HoloBall, MappedEnd};

/// A value and, when known, a logarithm of it (module docs, 3).
type Tracked = (HoloBall, Option<HoloBall>);

/// `f(x)`, `x` the argument of a piece mapped at `end` (module docs).
pub(crate) fn eval_mapped(f: &Expr, x: &HoloBall, end: &MappedEnd) -> HoloBall {
    match &end.e {
        Some(e) => Walk { x, end, e }.node(f).0,
        None => f.eval_plain(x),
    }
}

struct Walk<'a> {
    x: &'a HoloBall,
    end: &'a MappedEnd,
    e: &'a Rational,
}

impl Walk<'_> {
    /// `u = c0 + c1 x` with `c0 + c1 e = 0` and `sigma = c1 sign > 0`: `(sigma t, ln sigma
    /// + log_t)`.
    fn affine_leaf(&self, u: &Expr) -> Option<Tracked> {
        let (c0, c1) = affine(u)?;
        if c1 == 0 || Rational::from(&c0 + Rational::from(&c1 * self.e)) != 0 {
            return None;
        }
        let sigma = Rational::from(&c1 * self.end.sign);
        if sigma <= 0 {
            return None;
        }
        let t = self.x.constant(self.end.t.clone());
        let log_t = self.x.constant(self.end.log_t.clone());
        if sigma == 1 {
            return Some((t, Some(log_t)));
        }
        let s = self.x.decimal(&crate::ball::Decimal::from_rational(sigma));
        let ln_s = s.log();
        Some((s * t, Some(ln_s + log_t)))
    }

    /// The value of a constant subtree and, when it is real and positive, its log.
    fn positive_constant(&self, c: &Expr) -> Option<(HoloBall, HoloBall)> {
        if c.depends_on_x() {
            return None;
        }
        let v = c.eval_plain(self.x);
        let z = v.inner_ref();
        if !(z.im().is_exact() && z.im().mid().is_zero() && z.re().is_positive()) {
            return None;
        }
        let ln = if is_one(c) { self.x.int(0) } else { v.log() };
        Some((v, ln))
    }

    fn node(&self, f: &Expr) -> Tracked {
        if matches!(
            f,
            Expr::X | Expr::Neg(_) | Expr::Add(..) | Expr::Sub(..) | Expr::Mul(..) | Expr::Div(..)
        ) {
            if let Some(leaf) = self.affine_leaf(f) {
                return leaf;
            }
        }
        let plain = |v: HoloBall| (v, None);
        match f {
            Expr::X => plain(self.x.clone()),
            Expr::Pi | Expr::Number(_) => plain(f.eval_plain(self.x)),
            Expr::Neg(a) => plain(-self.node(a).0),
            Expr::Add(a, b) => plain(self.node(a).0 + self.node(b).0),
            Expr::Sub(a, b) => plain(self.node(a).0 - self.node(b).0),
            Expr::Mul(a, b) => {
                for (c, other) in [(a, b), (b, a)] {
                    if let Some((cv, ln_c)) = self.positive_constant(c) {
                        let (v, l) = self.node(other);
                        return (cv * v, l.map(|l| ln_c + l));
                    }
                }
                let ((va, la), (vb, lb)) = (self.node(a), self.node(b));
                let l = la.zip(lb).map(|(la, lb)| la + lb);
                (va * vb, l)
            }
            Expr::Div(a, b) => {
                if let Some((cv, ln_c)) = self.positive_constant(b) {
                    let (v, l) = self.node(a);
                    return (v / cv, l.map(|l| l - ln_c));
                }
                let (vb, lb) = self.node(b);
                if is_one(a) {
                    return match lb {
                        Some(lb) => {
                            let l = -lb;
                            (l.exp(), Some(l))
                        }
                        None => plain(vb.recip()),
                    };
                }
                let (va, la) = self.node(a);
                match la.zip(lb) {
                    Some((la, lb)) => {
                        let l = la - lb;
                        (l.exp(), Some(l))
                    }
                    None => plain(va / vb),
                }
            }
            Expr::PowInt(a, n) => {
                let (va, la) = self.node(a);
                match la {
                    Some(la) => {
                        let l = la * self.x.int(*n);
                        let v = if *n >= 0 { va.powi(*n) } else { l.exp() };
                        (v, Some(l))
                    }
                    None => plain(va.powi(*n)),
                }
            }
            Expr::Pow(a, b) => {
                let (va, la) = self.node(a);
                let (vb, _) = self.node(b);
                match la {
                    Some(la) => {
                        let l = vb.clone() * la;
                        let real_exponent = !b.depends_on_x()
                            && vb.inner_ref().im().is_exact()
                            && vb.inner_ref().im().mid().is_zero();
                        (l.exp(), real_exponent.then_some(l))
                    }
                    None => plain(va.pow(&vb)),
                }
            }
            Expr::Call(Function::Sqrt, a) => match self.node(a) {
                (_, Some(la)) => {
                    let l = la
                        * self
                            .x
                            .decimal(&crate::ball::Decimal::from_rational(Rational::from((1, 2))));
                    (l.exp(), Some(l))
                }
                (va, None) => plain(va.sqrt()),
            },
            Expr::Call(Function::Log, a) => match self.node(a) {
                (_, Some(la)) => plain(la),
                (va, None) => plain(va.log()),
            },
            Expr::Call(g, a) => plain(self.node(a).0.apply(*g)),
            Expr::BesselJ(n, a) => plain(self.node(a).0.besselj(*n)),
        }
    }
}

/// Whether `e` is the literal 1.
fn is_one(e: &Expr) -> bool {
    matches!(e, Expr::Number(d) if *d.as_rational() == 1)
}

/// Whether evaluating `f` with the logarithm of `x` (an end at `e = 0`, `sign = +1`, as
/// on the map `x = c e^s` of an algebraic tail) changes anything: some `log`, `sqrt`,
/// general power, negative integer power or denominator has an operand that carries a
/// logarithm by the rules of the module docs. Where it does not, the map's part keeps
/// its periodicity (`quad/certified/singular.rs`).
pub(crate) fn reads_end_log(f: &Expr) -> bool {
    let zero = Rational::new();
    let carries = |a: &Expr| carries_log(a, &zero);
    let here = match f {
        Expr::Call(Function::Log | Function::Sqrt, a) | Expr::Pow(a, _) => carries(a),
        Expr::PowInt(a, n) => *n < 0 && carries(a),
        Expr::Div(_, b) => carries(b),
        _ => false,
    };
    here || match f {
        Expr::X | Expr::Pi | Expr::Number(_) => false,
        Expr::Neg(a) | Expr::PowInt(a, _) | Expr::Call(_, a) | Expr::BesselJ(_, a) => reads_end_log(a),
        Expr::Add(a, b) | Expr::Sub(a, b) | Expr::Mul(a, b) | Expr::Div(a, b) | Expr::Pow(a, b) => reads_end_log(a) || reads_end_log(b),
    }
}

/// Whether the walk gives `a` a logarithm at an end `e` with `sign = +1` (a static
/// over-approximation of [`Walk::node`]: a constant factor is assumed positive).
fn carries_log(a: &Expr, e: &Rational) -> bool {
    if let Some((c0, c1)) = affine(a) {
        return c1 > 0 && Rational::from(&c0 + Rational::from(&c1 * e)) == 0;
    }
    match a {
        Expr::Mul(x, y) | Expr::Div(x, y) => {
            (carries_log(x, e) || !x.depends_on_x()) && (carries_log(y, e) || !y.depends_on_x())
        }
        Expr::PowInt(x, _) | Expr::Pow(x, _) | Expr::Call(Function::Sqrt, x) => carries_log(x, e),
        _ => false,
    }
}

/// The certified integrator's argument ([`HoloBall`]): the functions with a branch
/// cut take the form the integrator's evaluation mode asks for (principal at the
/// nodes, analytic on the boxes around its ellipses), so an expression evaluated
/// in it is an integrand that cannot integrate across a cut unnoticed.
impl ExprValue for HoloBall {
    fn add(&self, other: &HoloBall) -> HoloBall {
        self + other
    }
    fn sub(&self, other: &HoloBall) -> HoloBall {
        self - other
    }
    fn mul(&self, other: &HoloBall) -> HoloBall {
        self * other
    }
    fn div(&self, other: &HoloBall) -> HoloBall {
        self / other
    }
    fn neg(&self) -> HoloBall {
        -self
    }
    fn recip(&self) -> HoloBall {
        HoloBall::recip(self)
    }
    fn pow_int(&self, n: i64) -> HoloBall {
        self.powi(n)
    }
    fn pow(&self, e: &HoloBall) -> HoloBall {
        HoloBall::pow(self, e)
    }
    fn apply(&self, f: Function) -> HoloBall {
        apply_function!(self, f, sqrt, log, atan)
    }
    fn bessel_j(&self, n: i64) -> HoloBall {
        self.besselj(n)
    }
    fn pi(like: &HoloBall) -> HoloBall {
        like.pi()
    }
    fn from_decimal(d: &Decimal, like: &HoloBall) -> HoloBall {
        like.decimal(d)
    }
    /// On a piece mapped at an end, from the end's logarithm (`mapped.rs`).
    fn eval_expr(e: &Expr, x: &HoloBall) -> HoloBall {
        match x.mapped_end() {
            Some(end) => eval_mapped(e, x, end),
            None => e.eval_plain(x),
        }
    }
}
