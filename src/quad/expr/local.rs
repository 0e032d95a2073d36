//! Local behaviour of an expression next to a finite point, from the tree: the
//! counterpart at a point of the decay classes at infinity (`decay.rs`).
//!
//! # Method
//!
//! Next to a point `p`, on one side (`x = p + sigma t`, `sigma = +-1`, `0 < t <= delta`,
//! `delta <= 1/2`), every node `g` gets a class valid for all such `t`:
//!
//! ```text
//! g(p + sigma t) / t^q  lies in the real ball C,        q rational
//! ```
//!
//! The rules, each a short proof (`t^d` is in `(0, delta^d]` for `d >= 0`):
//!
//! * a subtree affine in `x` with rational coefficients, `c0 + c1 x`: exactly `(c0 + c1 p)
//!   + c1 sigma t`; when `c0 + c1 p = 0` the class is `q = 1, C = c1 sigma` (an exact
//!   zero at `p`), otherwise `q = 0` and `C = (c0 + c1 p) + c1 sigma [0, delta]`. A
//!   constant: its ball.
//! * `-g`, `g h`, `1/h` (`C_h` off 0), `g^n`: as for classes at infinity.
//! * `g + h` with `q_g <= q_h`: `h = t^{q_g} C_h t^{q_h - q_g}`, so `C = C_g + C_h [0,
//!   delta^{q_h - q_g}]` (the lower power dominates next to `p`).
//! * `g^r` (rational constant `r`, `sqrt`: `r = 1/2`): `C_g > 0`, then `C_g^r t^{q r}`.
//! * Bounded `g` (`q >= 0`): `g` lies in `C [0, delta^q]` (in `C` when `q = 0`); `exp`,
//!   `cos`, `cosh`, `sech` of `g` lie in that function of the ball.
//! * `g -> 0` (`q > 0`, `|g| <= G`): `f(g) = g (f(w)/w)` with `f(w)/w` in `[1 - G^2/6,
//!   1]` (sin), `[1 - G^2/3, 1]` (tanh, atan), `[1, sinh G/G]` (sinh), `[1, tan G/G]`
//!   (tan, `G < pi/2`), from their alternating or positive Taylor series; `e^g - 1 = g
//!   (e^w - 1)/w` with `(e^w - 1)/w` in `[(1 - e^-G)/G, (e^G - 1)/G]` (it increases),
//!   and `1 - e^g` its negative; `cos g - 1 = -g^2 (1 - cos w)/w^2` with `(1 - cos
//!   w)/w^2` in `[1/2 - G^2/24, 1/2]` (`G^2 <= 12`: alternating series with decreasing
//!   terms), and `1 - cos g` its negative;
//!   `J_n(g) = g^n h(w)`, `|h(w) 2^n n! - 1| <= e^{G^2/4} - 1` (DLMF 10.2.2: the ratio of
//!   the series' terms to its first is at most `(G^2/4)^k/k!`).
//! * `sin, cos, tanh, atan, besselj` of any real `g`: `[-1, 1]` (`[-pi/2, pi/2]`).
//! * `log g` with `C_g > 0`: `log g = log(g t^-q) + q log t`, and `-log t` is in `[0,
//!   1/(e eps)] t^-eps` for `t <= 1` (`eps = 1/8`): the class `q = -eps`, `C = log C_g
//!   [0, delta^eps] - q [0, 1/(e eps)]`.
//!
//! The class of the integrand gives `|f(p + sigma t)| <= |C| t^q` next to `p`: integrable
//! when `q > -1` (the integrator then maps the end exponentially and bounds the piece
//! cut off by `|C| delta'^{q+1}/(q+1)`), a pole or worse when `q <= -1`.

use rug::{Float, Rational};

use super::decay::const_rational;
use super::tree::{Expr, Function};
use crate::ball::{Ball, CBall, Decimal};

/// Precision of the class balls.
const P: u32 = 128;

/// `g(p + sigma t) / t^q` lies in `coef` for `0 < t <= delta`.
#[derive(Clone, Debug)]
pub(crate) struct Local {
    pub coef: Ball,
    pub power: Rational,
}

struct Ctx {
    p: Rational,
    sigma: i64,
    delta: Ball,
}

fn rat(q: &Rational) -> Ball {
    Decimal::from_rational(q.clone()).to_ball(P)
}

fn hull(lo: &Ball, hi: &Ball) -> Ball {
    let (l, h) = (lo.lower(), hi.upper());
    if l <= h {
        Ball::hull(&l, &h, P)
    } else {
        Ball::hull(&h, &l, P)
    }
}

fn hull0(b: &Ball) -> Ball {
    let z = Float::new(P);
    let (lo, hi) = (b.lower(), b.upper());
    Ball::hull(if lo < z { &lo } else { &z }, if hi > z { &hi } else { &z }, P)
}

fn constant(coef: Ball) -> Local {
    Local { coef, power: Rational::new() }
}

fn unit() -> Ball {
    Ball::hull(&Float::with_val(P, -1), &Float::with_val(P, 1), P)
}

/// `c0 + c1 x` with rational `c0, c1`, if the subtree is that.
pub(crate) fn affine(e: &Expr) -> Option<(Rational, Rational)> {
    Some(match e {
        Expr::X => (Rational::new(), Rational::from(1)),
        Expr::Number(d) => (d.as_rational().clone(), Rational::new()),
        Expr::Neg(a) => {
            let (c0, c1) = affine(a)?;
            (Rational::from(-c0), Rational::from(-c1))
        }
        Expr::Add(a, b) | Expr::Sub(a, b) => {
            let ((a0, a1), (b0, b1)) = (affine(a)?, affine(b)?);
            if matches!(e, Expr::Add(..)) {
                (Rational::from(a0 + b0), Rational::from(a1 + b1))
            } else {
                (Rational::from(a0 - b0), Rational::from(a1 - b1))
            }
        }
        Expr::Mul(a, b) => {
            let ((a0, a1), (b0, b1)) = (affine(a)?, affine(b)?);
            if a1 != 0 && b1 != 0 {
                return None;
            }
            (Rational::from(&a0 * &b0), Rational::from(&a0 * &b1) + Rational::from(&a1 * &b0))
        }
        Expr::Div(a, b) => {
            let (a0, a1) = affine(a)?;
            let d = const_rational(b)?;
            if d == 0 {
                return None;
            }
            (Rational::from(&a0 / &d), Rational::from(&a1 / &d))
        }
        _ => return None,
    })
}

impl Ctx {
    fn delta_pow(&self, e: &Rational) -> Option<Ball> {
        if *e == 0 {
            return Some(Ball::one(P));
        }
        self.delta.pow(&rat(e)).ok()
    }

    /// The range of `g` next to `p` when bounded.
    fn range(&self, g: &Local) -> Option<Ball> {
        if g.power == 0 {
            Some(g.coef.clone())
        } else if g.power > 0 {
            Some(g.coef.mul(&hull0(&self.delta_pow(&g.power)?)))
        } else {
            None
        }
    }

    fn add(&self, f: Local, g: Local) -> Option<Local> {
        let (dom, sub) = if f.power <= g.power { (f, g) } else { (g, f) };
        let shrink = self.delta_pow(&Rational::from(&sub.power - &dom.power))?;
        Some(Local { coef: dom.coef.add(&sub.coef.mul(&hull0(&shrink))), power: dom.power })
    }

    fn mul(&self, f: Local, g: Local) -> Local {
        Local { coef: f.coef.mul(&g.coef), power: Rational::from(&f.power + &g.power) }
    }

    fn recip(&self, g: Local) -> Option<Local> {
        if g.coef.contains_zero() {
            return None;
        }
        Some(Local { coef: g.coef.recip().ok()?, power: Rational::from(-&g.power) })
    }

    fn pow_rational(&self, g: Local, r: &Rational) -> Option<Local> {
        if !g.coef.is_positive() {
            return None;
        }
        Some(Local { coef: g.coef.pow(&rat(r)).ok()?, power: Rational::from(&g.power * r) })
    }

    /// `f(g) = g (f(w)/w)` for `g -> 0`, with the factor's range over `|w| <= G`.
    fn near_zero(&self, f: Function, g: &Local) -> Option<Local> {
        if g.power <= 0 {
            return None;
        }
        let big_g = Ball::from_float(&self.range(g)?.abs_upper(), P);
        let one = Ball::one(P);
        let g2 = big_g.sqr();
        let factor = match f {
            Function::Sin => hull(&one.sub(&g2.div_i64(6).ok()?), &one),
            Function::Tanh | Function::Atan => hull(&one.sub(&g2.div_i64(3).ok()?), &one),
            Function::Sinh => hull(&one, &big_g.sinh().div(&big_g).ok()?),
            Function::Tan => {
                if !(big_g.upper() < Ball::pi(P).mul_pow2(-1).lower()) {
                    return None;
                }
                hull(&one, &big_g.tan().div(&big_g).ok()?)
            }
            _ => return None,
        };
        Some(Local { coef: g.coef.mul(&factor), power: g.power.clone() })
    }

    fn function(&self, f: Function, g: Local) -> Option<Local> {
        match f {
            Function::Sqrt => return self.pow_rational(g, &Rational::from((1, 2))),
            Function::Log => {
                if !g.coef.is_positive() {
                    return None;
                }
                let ln_c = g.coef.ln().ok()?;
                if g.power == 0 {
                    return Some(constant(ln_c));
                }
                let eps = Rational::from((1, 8));
                let e = Ball::one(P).exp().ok()?;
                let neg_log_over = hull0(&e.mul(&rat(&eps)).recip().ok()?);
                let coef = ln_c.mul(&hull0(&self.delta_pow(&eps)?)).sub(&rat(&g.power).mul(&neg_log_over));
                return Some(Local { coef, power: Rational::from(-eps) });
            }
            _ => {}
        }
        if let Some(l) = self.near_zero(f, &g) {
            return Some(l);
        }
        if let Some(r) = self.range(&g) {
            let v = match f {
                Function::Exp => r.exp().ok()?,
                Function::Sin => r.sin(),
                Function::Cos => r.cos(),
                Function::Tan => r.tan(),
                Function::Sinh => r.sinh(),
                Function::Cosh => r.cosh(),
                Function::Tanh => r.tanh(),
                Function::Sech => r.cosh().recip().ok()?,
                Function::Atan => r.atan(),
                _ => return None,
            };
            return v.is_finite().then(|| constant(v));
        }
        match f {
            Function::Sin | Function::Cos | Function::Tanh => Some(constant(unit())),
            Function::Atan => Some(constant(Ball::pi(P).mul_pow2(-1).mul(&unit()))),
            _ => None,
        }
    }

    /// `e^g - 1 = g (e^w - 1)/w` with `(e^w - 1)/w` in `[(1 - e^-G)/G, (e^G - 1)/G]`, and
    /// `cos g - 1 = -g^2 (1 - cos w)/w^2` with `(1 - cos w)/w^2` in `[1/2 - G^2/24, 1/2]`
    /// (alternating series with decreasing terms for `G^2 <= 12`), for `g -> 0` (`q >
    /// 0`, `|g| <= G`; module docs). `None` otherwise.
    fn minus_one(&self, fun: Function, g: &Expr) -> Option<Local> {
        let g = self.class(g)?;
        if g.power <= 0 {
            return None;
        }
        let big_g = Ball::from_float(&self.range(&g)?.abs_upper(), P);
        match fun {
            Function::Exp => {
                let lo = Ball::one(P).sub(&big_g.neg().exp().ok()?).div(&big_g).ok()?;
                let hi = big_g.exp().ok()?.sub(&Ball::one(P)).div(&big_g).ok()?;
                Some(Local { coef: g.coef.mul(&hull(&lo, &hi)), power: g.power })
            }
            Function::Cos => {
                let g2 = big_g.sqr();
                if !(g2.upper() <= 12) {
                    return None;
                }
                let half = Ball::one(P).mul_pow2(-1);
                let lo = half.sub(&g2.div_i64(24).ok()?);
                let ratio = hull(&lo, &half);
                Some(Local { coef: g.coef.mul(&g.coef).mul(&ratio).neg(), power: Rational::from(&g.power * 2u32) })
            }
            _ => None,
        }
    }

    fn class(&self, e: &Expr) -> Option<Local> {
        if let Some((c0, c1)) = affine(e) {
            let at_p = Rational::from(&c0 + Rational::from(&c1 * &self.p));
            let slope = Rational::from(&c1 * self.sigma);
            if at_p == 0 {
                if slope == 0 {
                    return Some(constant(Ball::zero(P)));
                }
                return Some(Local { coef: rat(&slope), power: Rational::from(1) });
            }
            return Some(constant(rat(&at_p).add(&rat(&slope).mul(&hull0(&self.delta)))));
        }
        if !e.depends_on_x() {
            let v = e.eval(&CBall::zero(P));
            if !(v.is_finite() && v.im().is_exact() && v.im().mid().is_zero()) {
                return None;
            }
            return Some(constant(v.re().clone()));
        }
        match e {
            Expr::Neg(a) => {
                let c = self.class(a)?;
                Some(Local { coef: c.coef.neg(), ..c })
            }
            Expr::Add(a, b) => self.add(self.class(a)?, self.class(b)?),
            Expr::Sub(a, b) => {
                // e^g - 1, cos g - 1 with g -> 0, and 1 - e^g, 1 - cos g (negated)
                let (call, one, sign) = match (const_rational(a), const_rational(b)) {
                    (_, Some(c)) if c == 1 => (&**a, true, 1),
                    (Some(c), _) if c == 1 => (&**b, true, -1),
                    _ => (&**a, false, 1),
                };
                if let (Expr::Call(fun @ (Function::Exp | Function::Cos), g), true) = (call, one) {
                    if let Some(c) = self.minus_one(*fun, g) {
                        return Some(if sign < 0 { Local { coef: c.coef.neg(), ..c } } else { c });
                    }
                }
                let h = self.class(b)?;
                self.add(self.class(a)?, Local { coef: h.coef.neg(), ..h })
            }
            Expr::Mul(a, b) => Some(self.mul(self.class(a)?, self.class(b)?)),
            Expr::Div(a, b) => {
                let num = self.class(a)?;
                Some(self.mul(num, self.recip(self.class(b)?)?))
            }
            Expr::PowInt(a, n) => {
                let g = self.class(a)?;
                if *n < 0 && g.coef.contains_zero() {
                    return None;
                }
                let coef = if *n >= 0 { g.coef.pow_u64(*n as u64) } else { g.coef.pow_u64(n.unsigned_abs()).recip().ok()? };
                Some(Local { coef, power: Rational::from(&g.power * *n) })
            }
            Expr::Pow(a, b) => {
                if let Some(r) = const_rational(b) {
                    return self.pow_rational(self.class(a)?, &r);
                }
                // a^b = exp(b log a), b bounded
                let log_a = self.function(Function::Log, self.class(a)?)?;
                let arg = self.mul(self.class(b)?, log_a);
                self.function(Function::Exp, arg)
            }
            Expr::Call(f, a) => self.function(*f, self.class(a)?),
            Expr::BesselJ(n, a) => {
                let g = self.class(a)?;
                if g.power > 0 {
                    let m = n.unsigned_abs();
                    let big_g = Ball::from_float(&self.range(&g)?.abs_upper(), P);
                    let spread = big_g.sqr().mul_pow2(-2).exp().ok()?.sub(&Ball::one(P));
                    let lead = Ball::from_i64(2, P).pow_u64(m).mul(&Ball::factorial(m as u32, P)).recip().ok()?;
                    let h = lead.mul(&hull(&Ball::one(P).sub(&spread), &Ball::one(P).add(&spread)));
                    let sign = if *n < 0 && m % 2 == 1 { -1 } else { 1 };
                    return Some(Local { coef: g.coef.pow_u64(m).mul(&h).mul_i64(sign), power: Rational::from(&g.power * m) });
                }
                Some(constant(unit()))
            }
            _ => None,
        }
    }
}

/// The factors of a product: `e = (-1)^negative prod num / prod den`.
pub(crate) fn factors(e: &Expr, inverted: bool, num: &mut Vec<Expr>, den: &mut Vec<Expr>, negative: &mut bool) {
    match e {
        Expr::Mul(a, b) => {
            factors(a, inverted, num, den, negative);
            factors(b, inverted, num, den, negative);
        }
        Expr::Div(a, b) => {
            factors(a, inverted, num, den, negative);
            factors(b, !inverted, num, den, negative);
        }
        Expr::Neg(a) => {
            *negative = !*negative;
            factors(a, inverted, num, den, negative);
        }
        other => {
            if inverted {
                den.push(other.clone())
            } else {
                num.push(other.clone())
            }
        }
    }
}

/// The class of `f` next to `p` on the side `sigma` (`+1`: `x > p`), for `t <= delta`.
pub(crate) fn local_class(f: &Expr, p: &Rational, sigma: i64, delta: &Rational) -> Option<Local> {
    let ctx = Ctx { p: p.clone(), sigma, delta: rat(delta) };
    ctx.class(f)
}

/// Points where the expression may be singular: the zeros of affine subtrees with
/// rational coefficients that are divided by, raised to a negative or fractional
/// power, or the argument of `log` / `sqrt`.
pub(crate) fn singular_candidates(f: &Expr, out: &mut Vec<Rational>) {
    let mut push = |e: &Expr| {
        if let Some((c0, c1)) = affine(e) {
            if c1 != 0 {
                let root = Rational::from(-c0 / c1);
                if !out.contains(&root) {
                    out.push(root);
                }
            }
        }
    };
    match f {
        Expr::Div(a, b) => {
            push(b);
            // a positive power of an affine subtree divided by: its zero
            if let Expr::PowInt(base, n) = &**b {
                if *n > 0 {
                    push(base);
                }
            }
            singular_candidates(a, out);
            singular_candidates(b, out);
        }
        Expr::PowInt(a, n) => {
            if *n < 0 {
                push(a);
            }
            singular_candidates(a, out);
        }
        Expr::Pow(a, b) => {
            push(a);
            singular_candidates(a, out);
            singular_candidates(b, out);
        }
        Expr::Call(Function::Log | Function::Sqrt, a) => {
            push(a);
            singular_candidates(a, out);
        }
        Expr::Neg(a) | Expr::Call(_, a) | Expr::BesselJ(_, a) => singular_candidates(a, out),
        Expr::Add(a, b) | Expr::Sub(a, b) | Expr::Mul(a, b) => {
            singular_candidates(a, out);
            singular_candidates(b, out);
        }
        Expr::X | Expr::Pi | Expr::Number(_) => {}
    }
}

impl Expr {
    /// `f(p + sigma t)` as an expression in `t` (written `x`), every maximal affine
    /// subtree with rational coefficients folded exactly to `(c0 + c1 p) + c1 sigma t`:
    /// next to `p` the local variable is exact, so nothing cancels however small `t` is.
    pub(crate) fn shifted(&self, p: &Rational, sigma: i64) -> Expr {
        let number = |q: Rational| Expr::Number(Decimal::from_rational(q));
        if let Some((c0, c1)) = affine(self) {
            let at = Rational::from(&c0 + Rational::from(&c1 * p));
            let slope = Rational::from(&c1 * sigma);
            let lin = || Expr::Mul(Box::new(number(slope.clone())), Box::new(Expr::X));
            return match (at == 0, slope == 0) {
                (_, true) => number(at),
                (true, false) => lin(),
                (false, false) => Expr::Add(Box::new(number(at.clone())), Box::new(lin())),
            };
        }
        let b = |e: &Expr| Box::new(e.shifted(p, sigma));
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
}
