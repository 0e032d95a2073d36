//! The substitution `x = a + t^2` at a finite end `a` where the integrand's only
//! singular behaviour is through square roots of affine factors vanishing there:
//! `exp(-sqrt(x))` on `[0, inf)` becomes `2t exp(-t)`, analytic at `t = 0`, where the
//! exponential map at a singular end needs thousands of evaluations at high precision.
//!
//! # Method
//!
//! For `x = a + t^2`, `t >= 0`, `int_a^inf f(x) dx = int_0^inf 2t f(a + t^2) dt`
//! (substitution, `dx = 2t dt`; the map is a bijection of `[0, inf)` onto `[a, inf)`).
//! The tree of `f(a + t^2)` is written with the square roots resolved: every maximal
//! affine subtree `c0 + c1 x` becomes `(c0 + c1 a) + c1 t^2` (exactly, rational
//! coefficients), and where `c0 + c1 a = 0` and `c1 > 0`, `sqrt(c1 (x - a)) = sqrt(c1)
//! t` and `(c1 (x - a))^r = c1^r t^(2r)` for `r` a half-integer, since `t >= 0` (the
//! principal branch). The result is used only when it has no singular candidate at
//! `t = 0` left (`local.rs`); the integral of the new integrand is then the same number
//! on the same kind of range, and the integrator finds its tail bound from the tree as
//! for any integrand.

use rug::Rational;

use super::decay::const_rational;
use super::local::{affine, singular_candidates};
use super::tree::{Expr, Function};
use crate::ball::Decimal;

fn number(q: Rational) -> Expr {
    Expr::Number(Decimal::from_rational(q))
}

fn bx(e: Expr) -> Box<Expr> {
    Box::new(e)
}

/// `2t f(a + t^2)` with the square roots at `a` resolved (method block), when `f` has a
/// square root of an affine factor vanishing at `a` and the result has no singular
/// candidate at `t = 0`; `None` otherwise.
pub(crate) fn sqrt_substituted(f: &Expr, a: &Rational) -> Option<Expr> {
    let mut resolved = false;
    let g = substitute(f, a, &mut resolved);
    if !resolved {
        return None;
    }
    let mut candidates = Vec::new();
    singular_candidates(&g, &mut candidates);
    if candidates.iter().any(|p| *p == 0) {
        return None;
    }
    Some(Expr::Mul(bx(Expr::Mul(bx(number(Rational::from(2))), bx(Expr::X))), bx(g)))
}

/// `c0 + c1 (a + t^2)`.
fn affine_in_t(c0: &Rational, c1: &Rational, a: &Rational) -> Expr {
    let at = Rational::from(c0 + Rational::from(c1 * a));
    let square = Expr::Mul(bx(number(c1.clone())), bx(Expr::PowInt(bx(Expr::X), 2)));
    if *c1 == 0 {
        number(at)
    } else if at == 0 {
        square
    } else {
        Expr::Add(bx(number(at)), bx(square))
    }
}

/// The slope `c1 > 0` of an affine subtree vanishing at `a`.
fn vanishing_slope(u: &Expr, a: &Rational) -> Option<Rational> {
    let (c0, c1) = affine(u)?;
    (c1 > 0 && Rational::from(&c0 + Rational::from(&c1 * a)) == 0).then_some(c1)
}

fn substitute(e: &Expr, a: &Rational, resolved: &mut bool) -> Expr {
    if let Some((c0, c1)) = affine(e) {
        return affine_in_t(&c0, &c1, a);
    }
    match e {
        Expr::Call(Function::Sqrt, u) => {
            if let Some(c1) = vanishing_slope(u, a) {
                *resolved = true;
                return Expr::Mul(bx(Expr::Call(Function::Sqrt, bx(number(c1)))), bx(Expr::X));
            }
        }
        Expr::Pow(u, p) => {
            if let (Some(c1), Some(q)) = (vanishing_slope(u, a), const_rational(p)) {
                if *q.denom() == 2 {
                    *resolved = true;
                    let k = Rational::from(&q * 2u32).numer().to_i64().unwrap_or(0);
                    return Expr::Mul(bx(Expr::Pow(bx(number(c1)), bx(number(q)))), bx(Expr::PowInt(bx(Expr::X), k)));
                }
            }
        }
        _ => {}
    }
    e.map_children(|x| substitute(x, a, resolved))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `2t f(a + t^2)` against `f` at `x = a + t^2` in f64, and what is left alone.
    #[test]
    fn substituted_integrands_agree_at_the_mapped_points() {
        for (text, a) in [("exp(-sqrt(x))", 0i64), ("exp(-sqrt(2*x - 2))/(1 + x)", 1), ("x^(3/2)*exp(-x)", 0), ("cos(sqrt(x))*exp(-x)", 0)] {
            let f = Expr::parse(text).unwrap();
            let g = sqrt_substituted(&f, &Rational::from(a)).unwrap_or_else(|| panic!("{text}"));
            for t in [0.25, 1.0, 3.5] {
                let x = a as f64 + t * t;
                let want = 2.0 * t * f.eval_f64(x);
                assert!((g.eval_f64(t) - want).abs() <= 1e-13 * want.abs().max(1e-300), "{text} at t = {t}");
            }
        }
        for text in ["exp(-x)", "log(x)*exp(-x)", "sqrt(x+1)*exp(-x)"] {
            assert!(sqrt_substituted(&Expr::parse(text).unwrap(), &Rational::new()).is_none(), "{text}");
        }
    }
}
