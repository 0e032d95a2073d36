//! Removable singular points of a quotient, `f = N / U` with `U` affine: `sin(x)/x`,
//! `(exp(x) - 1)/x`, `sin(x - 1/2)/(x - 1/2)`. The integrand is then enclosed on every
//! box, the point's included, and integrated as the analytic function it is, with no
//! split and no map at the point (issue 40). Also `atan(1/u)` at an end of the range
//! where `u` vanishes, replaced by the function equal to it on the segment
//! ([`atan_reciprocals_rewritten`]).
//!
//! # Method
//!
//! Let `U = c0 + c1 x` (`c1 != 0`, rational) vanish at `p` in the range, and let `N`
//! have no singular candidate in the range (`local.rs`: no division by, negative or
//! fractional power of, `log` or `sqrt` of an affine subtree vanishing there).
//!
//! * **`N(p) = 0`.** The local class of `f` at `p` (`local.rs`, from a side where the
//!   range extends) is `|f(p + sigma t)| <= C t^q` with `q >= 0`: `f` is bounded next to
//!   `p`, so `N(p) = lim U(x) f(x) = 0` (`N` is continuous at `p`, `U(p) = 0`). A class
//!   with `q < 0`, or none, leaves the point to the general route.
//! * **The enclosure.** For a box `B` and `H` the smallest box containing `B` and `p`
//!   (convex), every `z` in `B` has the segment `[p, z]` in `H`, and when `N` is
//!   holomorphic on `H`, `f(z) = (N(z) - N(p)) / (c1 (z - p)) = (1/c1) int_0^1 N'(p + s
//!   (z - p)) ds` lies in the closed convex hull of `N'(H) / c1`, so in the ball (a
//!   rectangle, convex) that encloses `N'` on `H`, over `c1`. `N'` is the derivative
//!   of the tree by the rules of calculus ([`derivative`]); `N` evaluated on `H` in the
//!   integrator's holomorphic mode is finite only where `N` is holomorphic (its
//!   branch cuts give non-finite balls), so that evaluation is the check. At `z = p`
//!   the formula gives `N'(p)/c1`, the value of the extension.
//! * **`U^k`** (`k <= 4`, `(1 - cos x)/x^2`). The class `q >= 0` of `f = N/U^k` at `p`
//!   shows `N = O(t^k)`, so `N` (holomorphic at `p`) and its first `k - 1` derivatives
//!   vanish there, and Taylor's formula with integral remainder gives `f(z) = (c1^k
//!   (k-1)!)^-1 int_0^1 (1 - s)^{k-1} N^(k)(p + s (z - p)) ds`: a weighted mean (the
//!   weight's integral is `1/k`) of `N^(k)` on `H`, so `f(z)` lies in the ball of
//!   `N^(k)(H)` times `1/(c1^k k!)`.
//! * **Cancellation of higher order, proven exactly.** The local class sees one order of
//!   cancellation per rule (`e^g - 1 = O(g)`), not two: for `(e^x - 1 - x)/x^2` it finds
//!   `N = O(t)` and the class `q = -1`, which proves nothing. When the class does not
//!   give `q >= 0`, the vanishing of `N, N', ..., N^(k-1)` at `p` is checked instead by
//!   evaluating their trees at the rational `p` exactly ([`exact_at`]), in the ring
//!   `Q[pi]` of polynomials in `pi` with rational coefficients: `x` is `p`, the literals
//!   are the rationals they denote (a decimal is held exactly), `pi` is `pi`, `+ - *`
//!   and integer powers are exact, a division only by a nonzero rational; a function
//!   gives a value only at a rational argument where its value is a known rational:
//!   `exp(0) = cos(0) = cosh(0) = sech(0) = J_0(0) = 1`, `sin(0) = tan(0) = sinh(0) =
//!   tanh(0) = atan(0) = J_n(0) = 0` (`n != 0`), `log(1) = 0`, `sqrt(r^2) = r` (`r > 0`
//!   rational, the principal root), `1^b = 1` (`b` constant, the principal branch);
//!   anything else gives no value and the rule does not apply. As
//!   `pi` is transcendental (Lindemann), an element of `Q[pi]` is 0 exactly when all its
//!   coefficients are. Where an entire function (`exp sin cos sinh cosh J_n`) has an
//!   exact argument with no known rational value (`sin(1)`), its value is kept as an
//!   *atom*, a symbol named by the function and the argument's exact value, and the
//!   values are polynomials in `pi` and the atoms ([`PiPoly`]): one that is 0 as a
//!   polynomial is 0 as a number whatever the atoms are, so `sin(1 + x) - sin(1) - x
//!   cos(1)` at 0 (`sin(1) - sin(1)`, then `cos(1) - cos(1)`) is proven to vanish to
//!   second order; one with terms proves nothing (relations between atoms, as
//!   `sin(1)^2 + cos(1)^2 = 1`, are not used). Each value is then the exact value of `N^(j)(p)`, so `N^(j)(p) =
//!   0` for `j < k` is a proof (`(sin(pi x) - pi x)/x^3`: `N'(0) = pi cos 0 - pi = 0`),
//!   and Taylor's formula above applies with `N` holomorphic on `H`
//!   (checked by the evaluation on `H`, as before). `(e^x - 1 - x)/x^2` (`N(0) = e^0 - 1
//!   = 0`, `N'(0) = e^0 - 1 = 0`, enclosure `e^H / 2`) and `(cos x - 1 + x^2/2)/x^4`
//!   (`N^(j)(0) = 0` for `j <= 3`, enclosure `cos(H)/24`) are found so; `(e^x - 1)/x^2`
//!   (`N'(0) = 1`) is not, and stays a pole (`NotIntegrable` naming the point, from
//!   its local class `q = -1`).
//! * **Which form.** Where `U(B)` excludes 0 the quotient `N(B) / U(B)` is used as it
//!   is; where it contains 0 (next to `p`) the enclosure above. Both enclose `f` on
//!   `B`, so the integrator's ellipse bound holds with either.

use std::collections::BTreeMap;

use rug::Rational;

use super::decay::const_rational;
use super::local::{affine, local_class, singular_candidates};
use super::tree::{Expr, Function};
use super::MAX_BESSEL_ORDER;
use crate::ball::{Ball, CBall, Decimal};
use crate::quad::certified::HoloBall;

/// `f = N / U` with a removable point `p` of `U` in the range (method block).
pub(crate) struct Removable {
    num: Expr,
    den: Expr,
    /// `N^(k)`, `k` the power of `U` in the denominator.
    slope: Expr,
    /// `1 / (c1^k k!)`.
    scale: Rational,
    p: Rational,
}

impl Removable {
    /// The point.
    pub(crate) fn point(&self) -> &Rational {
        &self.p
    }

    /// An enclosure of `f` on the ball `z` (method block).
    pub(crate) fn eval(&self, z: &HoloBall) -> HoloBall {
        let u = self.den.eval(z);
        if !u.inner_ref().contains_zero() {
            return &self.num.eval(z) / &u;
        }
        let prec = z.prec();
        let p = Decimal::from_rational(self.p.clone()).to_ball(prec);
        let inner = z.inner_ref();
        let hull = CBall::new(union(inner.re(), &p), union(inner.im(), &Ball::zero(prec)));
        let h = z.constant(hull);
        if !self.num.eval(&h).is_finite() {
            return z.constant(CBall::indeterminate(prec));
        }
        let recip = Decimal::from_rational(self.scale.clone());
        &self.slope.eval(&h) * &h.decimal(&recip)
    }
}

/// The smallest ball containing both.
fn union(a: &Ball, b: &Ball) -> Ball {
    let (al, bl, au, bu) = (a.lower(), b.lower(), a.upper(), b.upper());
    let lo = if al < bl { al } else { bl };
    let hi = if au > bu { au } else { bu };
    Ball::hull(&lo, &hi, a.prec().max(b.prec()))
}

/// The removable point of `f = N / U` on `[lo, hi]`, when `f` has this form, `U`'s root
/// `p` lies in `[lo, hi]`, `N` has no singular candidate there, `N'` has a tree, and the
/// local class at `p` proves `N(p) = 0` (method block). `None` otherwise.
pub(crate) fn removable_point(f: &Expr, lo: &Rational, hi: &Rational) -> Option<Removable> {
    let Expr::Div(num, den) = f else { return None };
    // U or U^k (1 <= k <= 4)
    let (base, k) = match &**den {
        Expr::PowInt(b, k) if (1..=4).contains(k) => (&**b, *k as u32),
        other => (other, 1),
    };
    let (c0, c1) = affine(base)?;
    if c1 == 0 {
        return None;
    }
    let p = Rational::from(-c0 / &c1);
    if p < *lo || p > *hi {
        return None;
    }
    let mut candidates = Vec::new();
    singular_candidates(num, &mut candidates);
    if candidates.iter().any(|q| q >= lo && q <= hi) {
        return None;
    }
    let sigma = if p < *hi { 1 } else { -1 };
    let delta = Rational::from((1, 1024));
    // N(p) = ... = N^(k-1)(p) = 0: by the local class (q >= 0), or exactly (method block)
    let bounded = local_class(f, &p, sigma, &delta).is_some_and(|c| c.power >= 0);
    let mut slope = (**num).clone();
    for _ in 0..k {
        if !bounded && !exact_at(&slope, &p).is_some_and(|v| v.is_zero()) {
            return None;
        }
        slope = derivative(&slope)?;
    }
    let fact: u32 = (1..=k).product();
    let scale = Rational::from(1) / (Rational::from(rug::ops::Pow::pow(&c1, k)) * fact);
    Some(Removable { num: (**num).clone(), den: (**den).clone(), slope, scale, p })
}

/// A polynomial with rational coefficients in `pi` and in *atoms*, the values of the
/// entire functions `exp sin cos sinh cosh J_n` at exact arguments where no rational
/// value is known (`sin(1)`, `exp(pi/2)`), each atom named by its function and its
/// argument's exact value. A polynomial that is 0 as a polynomial (no terms) is 0 as a
/// number, whatever relations hold between its atoms; one with terms may still be 0
/// (`sin(1)^2 + cos(1)^2 - 1`) and proves nothing. With `pi` alone it is 0 exactly when
/// it has no terms (`pi` is transcendental, Lindemann), and a rational exactly when its
/// only term is the constant one.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct PiPoly(BTreeMap<Vec<(String, u32)>, Rational>);

impl PiPoly {
    fn zero() -> PiPoly {
        PiPoly(BTreeMap::new())
    }

    fn rational(q: Rational) -> PiPoly {
        let mut m = BTreeMap::new();
        if q != 0 {
            m.insert(Vec::new(), q);
        }
        PiPoly(m)
    }

    /// The atom (or `pi`) named `name`.
    fn atom(name: String) -> PiPoly {
        PiPoly(BTreeMap::from([(vec![(name, 1)], Rational::from(1))]))
    }

    /// Whether it is 0 as a polynomial (so 0 as a number).
    pub(crate) fn is_zero(&self) -> bool {
        self.0.is_empty()
    }

    /// The value when the polynomial is a constant.
    fn as_rational(&self) -> Option<Rational> {
        match self.0.len() {
            0 => Some(Rational::new()),
            1 => self.0.get(&Vec::new()).cloned(),
            _ => None,
        }
    }

    fn add(&self, o: &PiPoly, sign: i32) -> PiPoly {
        let mut m = self.0.clone();
        for (k, c) in &o.0 {
            let e = m.entry(k.clone()).or_default();
            *e += Rational::from(c * sign);
            if *e == 0 {
                m.remove(k);
            }
        }
        PiPoly(m)
    }

    fn mul(&self, o: &PiPoly) -> PiPoly {
        let mut m: BTreeMap<Vec<(String, u32)>, Rational> = BTreeMap::new();
        for (ka, a) in &self.0 {
            for (kb, b) in &o.0 {
                // the product of two monomials: exponents of the same atom add
                let mut k = ka.clone();
                for (name, e) in kb {
                    match k.iter_mut().find(|(n, _)| n == name) {
                        Some(entry) => entry.1 += e,
                        None => k.push((name.clone(), *e)),
                    }
                }
                k.sort();
                let e = m.entry(k.clone()).or_default();
                *e += Rational::from(a * b);
                if *e == 0 {
                    m.remove(&k);
                }
            }
        }
        PiPoly(m)
    }

    /// A name for the value, the same for equal polynomials.
    fn key(&self) -> String {
        format!("{:?}", self.0)
    }
}

/// The exact value of `e` at `x = p`, a polynomial in `pi` and atoms with rational
/// coefficients ([`PiPoly`]), when exact arithmetic and the functions' known rational
/// values (`exp(0) = 1`, `sin(0) = 0`, `log(1) = 0`, ...) give it; `None` otherwise, at a
/// division by 0 and at a division by a value that is not a rational (method block).
pub(crate) fn exact_at(e: &Expr, p: &Rational) -> Option<PiPoly> {
    let v = |a: &Expr| exact_at(a, p);
    let q = PiPoly::rational;
    Some(match e {
        Expr::X => q(p.clone()),
        Expr::Number(d) => q(d.as_rational().clone()),
        Expr::Pi => PiPoly::atom("pi".into()),
        // the principal branch: 1^b = e^{b Log 1} = 1
        Expr::Pow(a, b) if !b.depends_on_x() && v(a)?.as_rational()? == 1 => q(Rational::from(1)),
        Expr::Pow(..) => return None,
        Expr::Neg(a) => PiPoly::zero().add(&v(a)?, -1),
        Expr::Add(a, b) => v(a)?.add(&v(b)?, 1),
        Expr::Sub(a, b) => v(a)?.add(&v(b)?, -1),
        Expr::Mul(a, b) => v(a)?.mul(&v(b)?),
        Expr::Div(a, b) => {
            let d = v(b)?.as_rational()?;
            if d == 0 {
                return None;
            }
            v(a)?.mul(&q(d.recip()))
        }
        Expr::PowInt(a, n) => {
            let b = v(a)?;
            if n.unsigned_abs() > 64 {
                return None;
            }
            if *n < 0 {
                let r = b.as_rational()?;
                if r == 0 {
                    return None;
                }
                return Some(q(rug::ops::Pow::pow(r, n.unsigned_abs() as u32).recip()));
            }
            (0..*n).fold(q(Rational::from(1)), |acc, _| acc.mul(&b))
        }
        Expr::Call(f, a) => {
            let arg = v(a)?;
            let Some(u) = arg.as_rational() else {
                return entire_atom(*f, &arg);
            };
            match f {
                Function::Log if u == 1 => q(Rational::new()),
                // the square of a nonzero rational: its positive root (the principal one)
                Function::Sqrt if u > 0 && u.numer().is_perfect_square() && u.denom().is_perfect_square() => {
                    q(Rational::from((u.numer().clone().sqrt(), u.denom().clone().sqrt())))
                }
                Function::Exp | Function::Cos | Function::Cosh | Function::Sech if u == 0 => q(Rational::from(1)),
                Function::Sin | Function::Tan | Function::Sinh | Function::Tanh | Function::Atan if u == 0 => q(Rational::new()),
                _ => return entire_atom(*f, &arg),
            }
        }
        Expr::BesselJ(n, a) => {
            let arg = v(a)?;
            if !arg.is_zero() {
                // J_n is entire for integer n: a finite number at every argument
                return Some(PiPoly::atom(format!("J{n}({})", arg.key())));
            }
            q(Rational::from(i32::from(*n == 0)))
        }
    })
}

/// `f(u)` as an atom, for the entire functions only (a finite, definite number at
/// every `u`: no pole, no branch), else `None`.
fn entire_atom(f: Function, u: &PiPoly) -> Option<PiPoly> {
    match f {
        Function::Exp | Function::Sin | Function::Cos | Function::Sinh | Function::Cosh => Some(PiPoly::atom(format!("{f:?}({})", u.key()))),
        _ => None,
    }
}

fn number(q: i64) -> Expr {
    Expr::Number(Decimal::from_rational(Rational::from(q)))
}

fn bx(e: Expr) -> Box<Expr> {
    Box::new(e)
}

fn is_number(e: &Expr, q: i64) -> bool {
    matches!(e, Expr::Number(d) if *d.as_rational() == q)
}

/// `a b`, folded where a factor is 0 or 1 (exact identities; keeps the trees of
/// repeated derivatives small).
fn mul(a: Expr, b: Expr) -> Expr {
    if is_number(&a, 0) || is_number(&b, 0) {
        number(0)
    } else if is_number(&a, 1) {
        b
    } else if is_number(&b, 1) {
        a
    } else {
        Expr::Mul(bx(a), bx(b))
    }
}

/// `a + b`, folded where a term is 0.
fn add(a: Expr, b: Expr) -> Expr {
    if is_number(&a, 0) {
        b
    } else if is_number(&b, 0) {
        a
    } else {
        Expr::Add(bx(a), bx(b))
    }
}

/// `a - b`, folded where a term is 0.
fn sub(a: Expr, b: Expr) -> Expr {
    if is_number(&b, 0) {
        a
    } else if is_number(&a, 0) {
        neg(b)
    } else {
        Expr::Sub(bx(a), bx(b))
    }
}

/// `-a`, folded where `a` is 0.
fn neg(a: Expr) -> Expr {
    if is_number(&a, 0) { a } else { Expr::Neg(bx(a)) }
}

/// The derivative in `x` of the tree, by the sum, product, quotient, power and chain
/// rules and the derivatives of the functions (DLMF 4.14 and 4.34 for the
/// trigonometric and hyperbolic ones, 10.6(i) for `J_n' = (J_{n-1} - J_{n+1})/2` and
/// `J_0' = -J_1`). `None` for `J_n` of negative order or of the largest order.
pub(crate) fn derivative(e: &Expr) -> Option<Expr> {
    if !e.depends_on_x() {
        return Some(number(0));
    }
    let d = |a: &Expr| derivative(a);
    Some(match e {
        Expr::X => number(1),
        Expr::Pi | Expr::Number(_) => number(0),
        Expr::Neg(a) => neg(d(a)?),
        Expr::Add(a, b) => add(d(a)?, d(b)?),
        Expr::Sub(a, b) => sub(d(a)?, d(b)?),
        Expr::Mul(a, b) => add(mul(d(a)?, (**b).clone()), mul((**a).clone(), d(b)?)),
        // a constant denominator: (a / b)' = a' / b
        Expr::Div(a, b) if !b.depends_on_x() => Expr::Div(bx(d(a)?), b.clone()),
        Expr::Div(a, b) => Expr::Div(bx(sub(mul(d(a)?, (**b).clone()), mul((**a).clone(), d(b)?))), bx(Expr::PowInt(b.clone(), 2))),
        // a^0 = 1 and a^1 = a, so that no a^-1 (a pole where a = 0) enters the derivative
        Expr::PowInt(_, 0) => number(0),
        Expr::PowInt(a, 1) => d(a)?,
        Expr::PowInt(a, n) => mul(mul(number(*n), Expr::PowInt(a.clone(), n - 1)), d(a)?),
        Expr::Pow(a, b) if !b.depends_on_x() => {
            let b_minus_one = match const_rational(b) {
                Some(r) => Expr::Number(Decimal::from_rational(r - 1u32)),
                None => Expr::Sub(b.clone(), bx(number(1))),
            };
            mul(mul((**b).clone(), Expr::Pow(a.clone(), bx(b_minus_one))), d(a)?)
        }
        // a^b = exp(b log a): (a^b)' = a^b (b' log a + b a'/a)
        Expr::Pow(a, b) => mul(
            e.clone(),
            Expr::Add(
                bx(mul(d(b)?, Expr::Call(Function::Log, a.clone()))),
                bx(Expr::Div(bx(mul((**b).clone(), d(a)?)), a.clone())),
            ),
        ),
        Expr::Call(f, a) => {
            let outer = match f {
                Function::Sqrt => Expr::Div(bx(number(1)), bx(mul(number(2), e.clone()))),
                Function::Exp => e.clone(),
                Function::Log => Expr::Div(bx(number(1)), a.clone()),
                Function::Sin => Expr::Call(Function::Cos, a.clone()),
                Function::Cos => Expr::Neg(bx(Expr::Call(Function::Sin, a.clone()))),
                Function::Tan => Expr::Add(bx(number(1)), bx(Expr::PowInt(bx(e.clone()), 2))),
                Function::Sinh => Expr::Call(Function::Cosh, a.clone()),
                Function::Cosh => Expr::Call(Function::Sinh, a.clone()),
                Function::Tanh => Expr::Sub(bx(number(1)), bx(Expr::PowInt(bx(e.clone()), 2))),
                Function::Sech => Expr::Neg(bx(mul(e.clone(), Expr::Call(Function::Tanh, a.clone())))),
                Function::Atan => Expr::Div(bx(number(1)), bx(Expr::Add(bx(number(1)), bx(Expr::PowInt(a.clone(), 2))))),
            };
            mul(outer, d(a)?)
        }
        Expr::BesselJ(n, a) => {
            if *n < 0 || (*n as u64) >= MAX_BESSEL_ORDER {
                return None;
            }
            let outer = if *n == 0 {
                Expr::Neg(bx(Expr::BesselJ(1, a.clone())))
            } else {
                Expr::Div(bx(Expr::Sub(bx(Expr::BesselJ(n - 1, a.clone())), bx(Expr::BesselJ(n + 1, a.clone())))), bx(number(2)))
            };
            mul(outer, d(a)?)
        }
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The derivative's tree against a central difference in f64, at points where every
    /// function is smooth.
    #[test]
    fn derivatives_match_central_differences() {
        for text in [
            "sin(x)", "exp(x) - 1", "x^3 - 2*x", "sqrt(1 + x)", "log(2 + x)", "tan(x)", "tanh(3*x)", "sech(x)^2", "atan(x^2)",
            "besselj(0, x)", "besselj(3, 2*x)", "(1 + x)^(1/3)", "x^x", "sinh(x)*cosh(x)/(2 + x)", "cos(pi*x)", "1/(1+x^2)",
        ] {
            let e = Expr::parse(text).unwrap();
            let de = derivative(&e).unwrap();
            for x in [0.3, 0.7, 1.1] {
                let h = 1e-5;
                let fd = (e.eval_f64(x + h) - e.eval_f64(x - h)) / (2.0 * h);
                let got = de.eval_f64(x);
                assert!((got - fd).abs() <= 1e-7 * (1.0 + fd.abs()), "{text} at {x}: {got} vs {fd}");
            }
        }
    }

    #[test]
    fn quotients_with_a_removable_point_are_recognised_and_others_not() {
        let q = |s: &str| Rational::from(s.parse::<i64>().unwrap());
        for (text, found) in [
            ("sin(x)/x", true),
            ("(exp(x)-1)/x", true),
            ("sin(x-0.5)/(x-0.5)", true),
            ("cos(x)/x", false),
            ("1/x", false),
            ("log(x)/x", false),
            ("sin(x)/(x-3)", false),
            ("(exp(x)-1-x)/x^2", true),
            ("(cos(x)-1+x^2/2)/x^4", true),
            ("(exp(x)-1)/x^2", false),
            ("(exp(x)-1-x)/x^3", false),
            ("(exp(x-1)-x)/(x-1)^2", true),
            ("(sin(pi*x)-pi*x)/x^3", true),
            ("(sin(pi*x)-x)/x^3", false),
            ("(sqrt(4+x)-2-x/4)/x^2", true),
            ("((1+x/2)^(1/3)-1-x/6)/x^2", true),
            ("(sqrt(4+x)-2)/x^2", false),
            ("sin(x)/x^2", false),
            // values with no rational form, cancelling as polynomials in their atoms
            ("(sin(1+x)-sin(1)-x*cos(1))/x^2", true),
            ("(exp(0.5+x)-exp(0.5)*(1+x))/x^2", true),
            ("(besselj(0, 2+x)-besselj(0, 2)+x*besselj(1, 2))/x^2", true),
            ("(sin(1+x)-sin(1))/x^2", false),
            ("(sin(1+x)-sin(1)-x*cos(1.5))/x^2", false),
        ] {
            let e = Expr::parse(text).unwrap().canonical();
            assert_eq!(removable_point(&e, &q("-1"), &q("1")).is_some(), found, "{text}");
        }
    }

    #[test]
    fn a_point_proven_removable_by_atoms_integrates_to_the_sum_of_its_parts() {
        // sin(1 + x) - sin 1 - x cos 1 = sin(1) (cos x - 1) + cos(1) (sin x - x)
        use crate::quad::certified::Options;
        use crate::quad::expr::{integrate_range, End};
        for prec in [64, 333] {
            let int = |t: &str| {
                let (a, b) = (End::parse("0").unwrap(), End::parse("1").unwrap());
                let r = integrate_range(&Expr::parse(t).unwrap(), &a, &b, None, None, prec, &Options::new()).unwrap();
                assert!(r.goal_met, "{t} at {prec} bits");
                r.real().clone()
            };
            let whole = int("(sin(1+x)-sin(1)-x*cos(1))/x^2");
            let one = Ball::one(prec + 20);
            let parts = one.sin().mul(&int("(cos(x)-1)/x^2")).add(&one.cos().mul(&int("(sin(x)-x)/x^2")));
            assert!(whole.overlaps(&parts), "{prec} bits: {whole:?} vs {parts:?}");
        }
    }
}

/// `f` with every `atan(1/u)` (`u` affine, not vanishing inside `(lo, hi)`) replaced by
/// `s pi/2 - atan(u)`, `s` the sign of `u` on `(lo, hi)`: the two agree at every point
/// of the open segment (for real `u > 0` both have the derivative `-1/(1 + u^2)` and
/// tend to 0 as `u -> inf`; `u < 0` is the odd mirror), so the integral is the same,
/// and the new integrand is analytic next to the segment where the old one jumps at
/// `u = 0` (`atan(1/x)` on `[0, 1]`). `None` when there is nothing to replace.
pub(crate) fn atan_reciprocals_rewritten(f: &Expr, lo: &Rational, hi: &Rational) -> Option<Expr> {
    let mut changed = false;
    let e = rewrite(f, lo, hi, &mut changed);
    changed.then_some(e)
}

fn rewrite(e: &Expr, lo: &Rational, hi: &Rational, changed: &mut bool) -> Expr {
    match e {
        Expr::Call(Function::Atan, arg) => {
            let u = match &**arg {
                Expr::Div(one, u) if matches!(&**one, Expr::Number(d) if *d.as_rational() == 1) => Some(u),
                Expr::PowInt(u, -1) => Some(u),
                _ => None,
            };
            if let Some((u, (c0, c1))) = u.and_then(|u| affine(u).map(|c| (u, c))) {
                let at = |x: &Rational| Rational::from(&c0 + Rational::from(&c1 * x));
                let (ulo, uhi) = (at(lo), at(hi));
                let sign = if ulo >= 0 && uhi >= 0 && (ulo > 0 || uhi > 0) {
                    1
                } else if ulo <= 0 && uhi <= 0 && (ulo < 0 || uhi < 0) {
                    -1
                } else {
                    0
                };
                if sign != 0 {
                    *changed = true;
                    let half_pi = Expr::Div(bx(Expr::Pi), bx(number(2)));
                    let half_pi = if sign > 0 { half_pi } else { Expr::Neg(bx(half_pi)) };
                    return Expr::Sub(bx(half_pi), bx(Expr::Call(Function::Atan, u.clone())));
                }
            }
            e.map_children(|a| rewrite(a, lo, hi, changed))
        }
        _ => e.map_children(|a| rewrite(a, lo, hi, changed)),
    }
}
