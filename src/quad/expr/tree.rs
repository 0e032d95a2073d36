//! The parsed expression tree and its printed form.

use std::fmt;

use rug::{Integer, Rational};

use crate::ball::Decimal;

pub use super::function::Function;

/// A parsed integrand: a tree in the one variable `x`.
///
/// Built by [`Expr::parse`] (or by hand), evaluated by [`Expr::eval`] in any
/// [`ExprValue`](super::ExprValue) and printed back by `Display` in a form that
/// parses to the same tree.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub enum Expr {
    /// The variable `x`.
    X,
    /// The constant `pi`.
    Pi,
    /// A decimal literal, held exactly (a ball that contains it at any precision).
    Number(Decimal),
    /// `-a`.
    Neg(Box<Expr>),
    /// `a + b`.
    Add(Box<Expr>, Box<Expr>),
    /// `a - b`.
    Sub(Box<Expr>, Box<Expr>),
    /// `a * b`.
    Mul(Box<Expr>, Box<Expr>),
    /// `a / b`.
    Div(Box<Expr>, Box<Expr>),
    /// `a ^ n` with an integer exponent written as a literal (`x^3`, `x^-2`):
    /// integer powering, no branch cut.
    PowInt(Box<Expr>, i64),
    /// `a ^ b` for any other exponent: the general power `exp(b log a)`, analytic
    /// form in complex balls.
    Pow(Box<Expr>, Box<Expr>),
    /// `f(a)` for a one-argument function.
    Call(Function, Box<Expr>),
    /// `besselj(n, a)`: the Bessel function `J_n(a)` of integer order `n`.
    BesselJ(i64, Box<Expr>),
}

impl Expr {
    /// Whether the expression contains the variable `x` (otherwise it is a constant).
    pub fn depends_on_x(&self) -> bool {
        match self {
            Expr::X => true,
            Expr::Pi | Expr::Number(_) => false,
            Expr::Neg(a) | Expr::PowInt(a, _) | Expr::Call(_, a) | Expr::BesselJ(_, a) => a.depends_on_x(),
            Expr::Add(a, b) | Expr::Sub(a, b) | Expr::Mul(a, b) | Expr::Div(a, b) | Expr::Pow(a, b) => {
                a.depends_on_x() || b.depends_on_x()
            }
        }
    }

    /// Number of nodes of the tree.
    pub fn size(&self) -> usize {
        1 + match self {
            Expr::X | Expr::Pi | Expr::Number(_) => 0,
            Expr::Neg(a) | Expr::PowInt(a, _) | Expr::Call(_, a) | Expr::BesselJ(_, a) => a.size(),
            Expr::Add(a, b) | Expr::Sub(a, b) | Expr::Mul(a, b) | Expr::Div(a, b) | Expr::Pow(a, b) => {
                a.size() + b.size()
            }
        }
    }

    /// How tightly the printed form binds: an operand whose level is below what
    /// its parent needs gets parentheses.
    fn level(&self) -> u8 {
        match self {
            Expr::Add(..) | Expr::Sub(..) => 1,
            Expr::Mul(..) | Expr::Div(..) => 2,
            Expr::Neg(_) => 3,
            Expr::Pow(..) | Expr::PowInt(..) => 4,
            Expr::X | Expr::Pi | Expr::Number(_) | Expr::Call(..) | Expr::BesselJ(..) => 5,
        }
    }
}

/// Writes `e`, in parentheses when it binds less tightly than `min`.
fn operand(f: &mut fmt::Formatter<'_>, e: &Expr, min: u8) -> fmt::Result {
    if e.level() < min {
        write!(f, "({e})")
    } else {
        write!(f, "{e}")
    }
}

impl fmt::Display for Expr {
    /// The expression with as few parentheses as parsing it back to the same tree
    /// needs (`-x^2`, `(-x)^2`, `a - (b - c)`, `x^-2`).
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        // Left operands of a left-associative operator may bind as loosely as the
        // operator itself; right operands must bind more tightly. The operand of
        // `^` and of a unary minus is itself a signed power, so a minus there needs
        // no parentheses.
        let binary = |f: &mut fmt::Formatter<'_>, a: &Expr, op: &str, b: &Expr, lvl: u8| {
            operand(f, a, lvl)?;
            f.write_str(op)?;
            operand(f, b, lvl + 1)
        };
        match self {
            Expr::X => f.write_str("x"),
            Expr::Pi => f.write_str("pi"),
            Expr::Number(d) => write_decimal(f, d.as_rational()),
            Expr::Neg(a) => {
                // `-(-x)`: a second sign would fold into the first when parsed
                f.write_str("-")?;
                operand(f, a, 4)
            }
            Expr::Add(a, b) => binary(f, a, " + ", b, 1),
            Expr::Sub(a, b) => binary(f, a, " - ", b, 1),
            Expr::Mul(a, b) => binary(f, a, "*", b, 2),
            Expr::Div(a, b) => binary(f, a, "/", b, 2),
            Expr::PowInt(a, n) => {
                operand(f, a, 5)?;
                write!(f, "^{n}")
            }
            Expr::Pow(a, b) => {
                operand(f, a, 5)?;
                f.write_str("^")?;
                operand(f, b, 3)
            }
            Expr::Call(func, a) => write!(f, "{}({a})", func.name()),
            Expr::BesselJ(n, a) => write!(f, "besselj({n}, {a})"),
        }
    }
}

/// Writes a rational exactly as a decimal (`0.1`, `2500`, `3e-40`) when its
/// denominator is `2^i 5^j`, as `(p/q)` otherwise (not a decimal literal).
fn write_decimal(f: &mut fmt::Formatter<'_>, q: &Rational) -> fmt::Result {
    let den = q.denom();
    let (rest, twos) = den.clone().remove_factor(&Integer::from(2));
    let (rest, fives) = rest.remove_factor(&Integer::from(5));
    if rest != 1 {
        return write!(f, "({q})");
    }
    if *q < 0 {
        f.write_str("(-")?;
    }
    // |q| = m 10^-k with m an integer; then drop m's trailing zeros into exp.
    let k = twos.max(fives);
    let scale = Integer::from(Integer::u_pow_u(10, k));
    let m = Integer::from(q.numer().abs_ref()) * scale / den;
    let (m, zeros) = if m == 0 { (m, 0) } else { m.remove_factor(&Integer::from(10)) };
    let exp = i64::from(zeros) - i64::from(k);
    let digits = m.to_string();
    if (0..=6).contains(&exp) {
        write!(f, "{digits}{}", "0".repeat(exp as usize))?;
    } else if (-30..0).contains(&exp) {
        let point = exp.unsigned_abs() as usize;
        if digits.len() > point {
            let (int, frac) = digits.split_at(digits.len() - point);
            write!(f, "{int}.{frac}")?;
        } else {
            write!(f, "0.{}{digits}", "0".repeat(point - digits.len()))?;
        }
    } else {
        write!(f, "{digits}e{exp}")?;
    }
    if *q < 0 {
        f.write_str(")")?;
    }
    Ok(())
}

impl Expr {
    /// The same node with each child `c` replaced by `f(c)` (a leaf is cloned).
    pub(crate) fn map_children(&self, mut f: impl FnMut(&Expr) -> Expr) -> Expr {
        let mut b = |e: &Expr| Box::new(f(e));
        match self {
            Expr::X | Expr::Pi | Expr::Number(_) => self.clone(),
            Expr::Neg(a) => Expr::Neg(b(a)),
            Expr::Add(x, y) => Expr::Add(b(x), b(y)),
            Expr::Sub(x, y) => Expr::Sub(b(x), b(y)),
            Expr::Mul(x, y) => Expr::Mul(b(x), b(y)),
            Expr::Div(x, y) => Expr::Div(b(x), b(y)),
            Expr::PowInt(a, n) => Expr::PowInt(b(a), *n),
            Expr::Pow(x, y) => Expr::Pow(b(x), b(y)),
            Expr::Call(f, a) => Expr::Call(*f, b(a)),
            Expr::BesselJ(n, a) => Expr::BesselJ(*n, b(a)),
        }
    }

    /// Whether the expression is affine in `x` (`c x + d`, built with `+ - *` and
    /// division by constants). Powers of affine bases keep their form: the endpoint
    /// weights and the exponential maps handle `(x - a)^r` directly (on a map `x = c
    /// e^s`, `e^{r Log x}` is tight and `x sqrt x` is not).
    fn is_affine(&self) -> bool {
        if !self.depends_on_x() {
            return true;
        }
        match self {
            Expr::X => true,
            Expr::Neg(a) => a.is_affine(),
            Expr::Add(a, b) | Expr::Sub(a, b) => a.is_affine() && b.is_affine(),
            Expr::Mul(a, b) => (!a.depends_on_x() && b.is_affine()) || (!b.depends_on_x() && a.is_affine()),
            Expr::Div(a, b) => !b.depends_on_x() && a.is_affine(),
            _ => false,
        }
    }

    /// The same function in a spelling that costs the certified integrator no more
    /// than any other (issue 36, item 5), bottom-up: `1/cosh(u)^k` and `cosh(u)^-k` are
    /// `sech(u)^k` (`sech` is enclosed tightly on wide boxes, `1/cosh` is not),
    /// `exp(a) exp(b)` is `exp(a + b)` (one enclosure instead of a product of two), and
    /// `a*a` is `a^2` (a square, not a product of two independent balls), and `a^(k/2)`
    /// for odd `|k| >= 3` and `a` not affine in `x` is `a^((k-1)/2) sqrt(a)` (its
    /// reciprocal for `k < 0`: both
    /// sides are `e^{(k/2) Log a}`; the square root's enclosure of a wide complex box is
    /// tighter than `e^{(k/2) Log a}`'s, which took the Hankel-type integrals 1.5 times
    /// the evaluations). Each rewrite
    /// is an identity wherever either side is defined, so the integral is the same.
    pub fn canonical(&self) -> Expr {
        if matches!(self, Expr::X | Expr::Pi | Expr::Number(_)) {
            return self.clone();
        }
        let e = self.map_children(Expr::canonical);
        match e {
            Expr::Div(num, den) => match *den {
                Expr::Call(Function::Cosh, u) => Expr::Mul(num, Box::new(Expr::Call(Function::Sech, u))),
                Expr::PowInt(base, k) if k > 0 => match *base {
                    Expr::Call(Function::Cosh, u) => Expr::Mul(num, Box::new(Expr::PowInt(Box::new(Expr::Call(Function::Sech, u)), k))),
                    other => Expr::Div(num, Box::new(Expr::PowInt(Box::new(other), k))),
                },
                other => Expr::Div(num, Box::new(other)),
            },
            Expr::PowInt(base, k) if k < 0 => match *base {
                Expr::Call(Function::Cosh, u) => Expr::PowInt(Box::new(Expr::Call(Function::Sech, u)), -k),
                other => Expr::PowInt(Box::new(other), k),
            },
            // a^(k/2), k odd, |k| >= 3: a^((k-1)/2) sqrt(a) (or its reciprocal), the
            // same principal branch (a^r = e^{r Log a}), enclosed more tightly on wide
            // complex boxes than through e^{r Log a}
            Expr::Pow(base, exp) => match const_rational(&exp) {
                Some(r) if !base.is_affine() && *r.denom() == 2 && r.numer().cmp_abs(&Integer::from(3)) != std::cmp::Ordering::Less && r.numer().cmp_abs(&Integer::from(1 << 20)) == std::cmp::Ordering::Less => {
                    let k = r.numer().to_i64().unwrap_or(1);
                    let whole = Expr::PowInt(base.clone(), (k.abs() - 1) / 2);
                    let prod = Expr::Mul(Box::new(whole), Box::new(Expr::Call(Function::Sqrt, base)));
                    if k > 0 {
                        prod
                    } else {
                        Expr::Div(Box::new(Expr::Number(Decimal::from_rational(Rational::from(1)))), Box::new(prod))
                    }
                }
                _ => Expr::Pow(base, exp),
            },
            Expr::Mul(x, y) => match (*x, *y) {
                (Expr::Call(Function::Exp, p), Expr::Call(Function::Exp, q)) => Expr::Call(Function::Exp, Box::new(Expr::Add(p, q))),
                (x, y) if x == y => Expr::PowInt(Box::new(x), 2),
                (x, y) => Expr::Mul(Box::new(x), Box::new(y)),
            },
            other => other,
        }
    }
}

/// The exact rational value of a constant subtree built from decimals with `+ - * /`
/// and integer powers, if it is one.
pub(crate) fn const_rational(e: &Expr) -> Option<Rational> {
    Some(match e {
        Expr::Number(d) => d.as_rational().clone(),
        Expr::Neg(a) => Rational::from(-const_rational(a)?),
        Expr::Add(a, b) => Rational::from(const_rational(a)? + const_rational(b)?),
        Expr::Sub(a, b) => Rational::from(const_rational(a)? - const_rational(b)?),
        Expr::Mul(a, b) => Rational::from(const_rational(a)? * const_rational(b)?),
        Expr::Div(a, b) => {
            let d = const_rational(b)?;
            if d == 0 {
                return None;
            }
            Rational::from(const_rational(a)? / d)
        }
        Expr::PowInt(a, n) if n.unsigned_abs() <= 64 => {
            let base = const_rational(a)?;
            if base == 0 && *n < 0 {
                return None;
            }
            let p = Rational::from(rug::ops::Pow::pow(&base, n.unsigned_abs() as u32));
            if *n < 0 {
                p.recip()
            } else {
                p
            }
        }
        _ => return None,
    })
}
