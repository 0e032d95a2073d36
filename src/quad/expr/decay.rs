//! Decay classes at `+inf`, derived from the expression tree: a certified tail bound
//! for `int_a^inf f` that the user does not have to find by hand.
//!
//! # Method
//!
//! For a radius `R = 2^j` (tried for `j = 1, 3, 6, 10, 16, 32`), every node `g` of the
//! tree gets a *class* valid for all real `x >= R`:
//!
//! ```text
//! g(x) / (x^q e^{-c x^k})  lies in the real ball C,        q, c, k rational, k >= 0
//! ```
//!
//! (`c = 0` means no exponential factor; then `k = 0`). The statement is two-sided, so
//! a class whose `C` excludes 0 proves `g` has no zero beyond `R` and may divide. The
//! rules, each a short proof (all for `x >= R >= 2`, and every ball evaluated in ball
//! arithmetic, so the bounds are rigorous):
//!
//! * `x`: `C = 1, q = 1`; a constant (a subtree without `x`): its ball, `q = 0` (a
//!   constant whose ball is not real gives no class).
//! * `-g`, `g h`, `1/h`, `g^n` (integer `n`): `C` negated, multiplied, inverted (`C_h`
//!   must exclude 0), powered; `q` and the exponent add, negate, multiply. Two
//!   exponential factors of different orders `k_L > k_O` are merged by
//!   `-c_L x^{k_L} - c_O x^{k_O} <= -(c_L - max(0, -c_O) R^{k_O - k_L}) x^{k_L}` (as
//!   `x^{k_O - k_L} <= R^{k_O - k_L}`); the factor left over is in `(0, 1]`, so `C`
//!   becomes its hull with 0 (the class then bounds `|g|` only).
//! * `g + h`: one term dominates. With `rho(x) = x^{q_h - q_g} e^{E_h(x) - E_g(x)}`,
//!   `h = x^{q_g} e^{E_g} C_h rho(x)`. If `x rho'/rho = (q_h - q_g) + c_g k_g x^{k_g}
//!   - c_h k_h x^{k_h} <= 0` on `[R, inf)` (checked below), `rho` decreases and
//!   `0 < rho(x) <= rho(R)`, so `g + h` has the class of `g` with `C = C_g + C_h [0,
//!   rho(R)]`. Otherwise the roles are swapped; otherwise there is no class.
//! * *A sum of powers is `<= 0` on `[R, inf)`*: `sum a_i x^{e_i}` with leading exponent
//!   `e_0` is at most `x^{e_0} (a_0 + sum_{i>0} max(0, a_i) R^{e_i - e_0})`, since
//!   `x^{e_i - e_0} <= R^{e_i - e_0}`; the check is that this bracket's upper bound is
//!   `<= 0`.
//! * `g^r` for a constant rational `r` (`sqrt` is `r = 1/2`): `C_g > 0` is required;
//!   then `g^r = C'^r x^{q r} e^{r E}` with `C' = g/(x^q e^E)` in `C_g`. Any other
//!   power `g^h` is `exp(h log g)`.
//! * `exp(g)`: when `g` is bounded on `[R, inf)` (below), `exp` of its range. When
//!   `c_g = 0` and `q_g > 0`: `C_lo x^q <= g <= C_hi x^q`, so `e^g = e^{C_hi x^q} t`
//!   with `t` in `(0, 1]` (`t = 1` when `C_g` is a point): `c = -C_hi`, `k = q_g`.
//! * *Bounded* `g`: if `c_g = 0, q_g <= 0`, or `c_g > 0` and `x^q e^{-c x^k}` decreases
//!   on `[R, inf)` (`q - c k x^k <= 0`, a sum of powers), then `g` lies in `C_g [0,
//!   R^q e^{-c R^k}]` (in `C_g` itself when `q = c = 0`), and any function of `g` lies
//!   in that function of the ball.
//! * `sin g`, `atan g`, `tanh g` with `g` bounded by `G` and tending to 0: `f(t)/t` is
//!   in `[0, 1]` for `|t| <= pi` (sin) and for all real `t` (atan, tanh), so `f(g)`
//!   has the class of `g` with `C_g [0, 1]`.
//! * `sin, cos, tanh, atan, besselj` of any real `g`: `[-1, 1]` (`[-pi/2, pi/2]`);
//!   `|J_n(t)| <= 1` for real `t` and integer `n` (DLMF 10.14.1 and `J_{-n} = (-1)^n
//!   J_n`).
//! * `cosh, sinh, sech` of `g = C x^q` unbounded (`c_g = 0, q > 0`, `C` off 0; `m =
//!   |C|`): `cosh g = e^{|g|} (1 + e^{-2|g|})/2`, `sinh g = sign(C) e^{|g|} (1 -
//!   e^{-2|g|})/2`, `sech g = 2 e^{-|g|}/(1 + e^{-2|g|})`, with `e^{-2|g|}` in `(0,
//!   eps]`, `eps = e^{-2 m_lo R^q}`.
//! * `log g` for `C_g > 0`: `log g = log C' + q log x - c x^k`. With `log x / x^d` in
//!   `(0, 1/(e d)]` for `x >= 1`, `d > 0`: the class is `x^d` with `d = 1/8` when `c =
//!   0`, and `x^k` with leading coefficient `-c` otherwise.
//!
//! From the class of the whole integrand, `|f(x)| <= |C| x^q e^{-c x^k}` for `x >= R`:
//!
//! * `c > 0, k >= 1`: `x^k >= R^{k-1} x`, so with `lambda = c R^{k-1}`, `|f| <= |C| R^q
//!   e^{-lambda x}` when `q <= 0`; when `q > 0`, `R` is raised to `R' >= 8 q/lambda`,
//!   where `x^q e^{-lambda x/8}` decreases, and `|f| <= |C| R'^q e^{-lambda R'/8}
//!   e^{-7 lambda x/8}`: an exponential [`Decay`] from `R`.
//! * `c > 0, 0 < k < 1`: `x^{q+3} e^{-c x^k} <= (s/(c k))^{s/k} e^{-s/k}` (`s = q + 3 >
//!   0`, the maximum over `x > 0`), an algebraic decay `x^-3`.
//! * `c = 0, q < -1`: the algebraic decay `|C| x^q`.
//! * `c = 0, q >= -1` or `c < 0`: not absolutely integrable ([`TailClass::Slow`]).
//!
//! The integrator then integrates `[a, R]` as a finite range and uses the decay beyond
//! its cut `T >= R` (`singular.rs`). The derivation is on the real axis only: the tail
//! bounds of the integrator are real-axis bounds.

use rug::{Float, Rational};

use super::tree::{Expr, Function};
use crate::ball::{Ball, CBall, Decimal};
use crate::quad::certified::Decay;

/// Precision of the class balls.
const P: u32 = 128;

/// Radii tried, as powers of 2.
const RADII_LOG2: [u32; 6] = [1, 3, 6, 10, 16, 32];

/// `g(x) / (x^power e^{-rate x^order})` lies in `coef` for every real `x >= R`.
#[derive(Clone, Debug)]
pub(crate) struct Class {
    pub coef: Ball,
    pub power: Rational,
    pub rate: Rational,
    pub order: Rational,
}

/// What the expression says about its tail at `+inf`.
#[derive(Clone, Debug)]
pub(crate) enum TailClass {
    /// A certified bound `|f(x)| <= ...` for `x >= from` (an exact ball).
    Decays { decay: Decay, from: Ball },
    /// `|f(x)| <= |C| x^power` with `power >= -1` and no exponential decay (or a
    /// growth): not absolutely integrable as far as the expression shows.
    Slow { power: f64 },
    /// No class follows from the rules.
    Unknown,
}

struct Ctx {
    r: Ball,
}

fn rat(q: &Rational) -> Ball {
    Decimal::from_rational(q.clone()).to_ball(P)
}

fn zero_q() -> Rational {
    Rational::new()
}

/// The ball `[min(0, lo), max(0, hi)]`.
fn hull0(b: &Ball) -> Ball {
    let zero = Float::new(P);
    let lo = b.lower();
    let hi = b.upper();
    let lo = if lo < zero { lo } else { zero.clone() };
    let hi = if hi > zero { hi } else { zero };
    Ball::hull(&lo, &hi, P)
}

fn constant(coef: Ball) -> Class {
    Class { coef, power: zero_q(), rate: zero_q(), order: zero_q() }
}

impl Ctx {
    /// `R^e`.
    fn r_pow(&self, e: &Rational) -> Option<Ball> {
        if *e == 0 {
            return Some(Ball::one(P));
        }
        self.r.pow(&rat(e)).ok()
    }

    /// Whether `sum a_i x^{e_i} <= 0` for every `x >= R` (module docs).
    fn nonpositive_beyond(&self, terms: &[(Ball, Rational)]) -> bool {
        let mut merged: Vec<(Ball, Rational)> = Vec::new();
        for (a, e) in terms {
            if a.is_exact() && a.mid().is_zero() {
                continue;
            }
            match merged.iter_mut().find(|(_, f)| f == e) {
                Some(t) => t.0 = t.0.add(a),
                None => merged.push((a.clone(), e.clone())),
            }
        }
        let Some(lead) = merged.iter().map(|(_, e)| e.clone()).max() else {
            return true;
        };
        let mut s = Ball::zero(P);
        for (a, e) in &merged {
            if *e == lead {
                s = s.add(a);
            } else {
                let up = a.upper();
                if up > 0 {
                    let Some(rp) = self.r_pow(&Rational::from(e - &lead)) else { return false };
                    s = s.add(&Ball::from_float(&up, P).mul(&rp));
                }
            }
        }
        s.upper() <= 0
    }

    /// `e^{-c R^k}` for an exponential factor.
    fn exp_factor_at_r(&self, c: &Rational, k: &Rational) -> Option<Ball> {
        if *c == 0 {
            return Some(Ball::one(P));
        }
        rat(c).mul(&self.r_pow(k)?).neg().exp().ok()
    }

    /// The range of `g` over `[R, inf)` when it is bounded there.
    fn bounded_range(&self, g: &Class) -> Option<Ball> {
        if g.rate == 0 {
            if g.power == 0 {
                return Some(g.coef.clone());
            }
            if g.power < 0 {
                return Some(g.coef.mul(&hull0(&self.r_pow(&g.power)?)));
            }
            return None;
        }
        if g.rate < 0 {
            return None;
        }
        // x^q e^{-c x^k} decreasing: q - c k x^k <= 0
        let ck = Rational::from(&g.rate * &g.order);
        if !self.nonpositive_beyond(&[(rat(&g.power), zero_q()), (rat(&ck).neg(), g.order.clone())]) {
            return None;
        }
        let s = self.r_pow(&g.power)?.mul(&self.exp_factor_at_r(&g.rate, &g.order)?);
        Some(g.coef.mul(&hull0(&s)))
    }

    /// Whether `g` tends to 0 (bounded, and not a nonzero constant).
    fn tends_to_zero(g: &Class) -> bool {
        g.rate > 0 || (g.rate == 0 && g.power < 0)
    }

    /// The product of two exponential factors as one factor and whether the
    /// coefficient must be hulled with 0.
    fn merge_exp(&self, a: (&Rational, &Rational), b: (&Rational, &Rational)) -> Option<(Rational, Rational, bool)> {
        let (ca, ka) = a;
        let (cb, kb) = b;
        if *cb == 0 {
            return Some((ca.clone(), ka.clone(), false));
        }
        if *ca == 0 {
            return Some((cb.clone(), kb.clone(), false));
        }
        if ka == kb {
            let c = Rational::from(ca + cb);
            let k = if c == 0 { zero_q() } else { ka.clone() };
            return Some((c, k, false));
        }
        let ((cl, kl), (co, ko)) = if ka > kb { ((ca, ka), (cb, kb)) } else { ((cb, kb), (ca, ka)) };
        if *co >= 0 {
            return Some((cl.clone(), kl.clone(), true));
        }
        let loss = rat(&Rational::from(-co)).mul(&self.r_pow(&Rational::from(ko - kl))?);
        let c = rat(cl).sub(&loss).lower().to_rational()?;
        let k = if c == 0 { zero_q() } else { kl.clone() };
        Some((c, k, true))
    }

    /// `g` in the class of `f`, when `f` dominates (module docs).
    fn absorb(&self, f: &Class, g: &Class) -> Option<Ball> {
        let d = Rational::from(&g.power - &f.power);
        let terms = [
            (rat(&d), zero_q()),
            (rat(&Rational::from(&f.rate * &f.order)), f.order.clone()),
            (rat(&Rational::from(&g.rate * &g.order)).neg(), g.order.clone()),
        ];
        if !self.nonpositive_beyond(&terms) {
            return None;
        }
        // rho(R) = R^d e^{c_f R^{k_f} - c_g R^{k_g}}
        let ef = self.exp_factor_at_r(&f.rate, &f.order)?;
        let eg = self.exp_factor_at_r(&g.rate, &g.order)?;
        let rho = self.r_pow(&d)?.mul(&eg).div(&ef).ok()?;
        Some(g.coef.mul(&hull0(&rho)))
    }

    fn add(&self, f: Class, g: Class) -> Option<Class> {
        if let Some(extra) = self.absorb(&f, &g) {
            return Some(Class { coef: f.coef.add(&extra), ..f });
        }
        let extra = self.absorb(&g, &f)?;
        Some(Class { coef: g.coef.add(&extra), ..g })
    }

    fn mul(&self, f: Class, g: Class) -> Option<Class> {
        let (rate, order, lossy) = self.merge_exp((&f.rate, &f.order), (&g.rate, &g.order))?;
        let coef = f.coef.mul(&g.coef);
        Some(Class { coef: if lossy { hull0(&coef) } else { coef }, power: Rational::from(&f.power + &g.power), rate, order })
    }

    fn recip(&self, g: Class) -> Option<Class> {
        if g.coef.contains_zero() {
            return None;
        }
        Some(Class { coef: g.coef.recip().ok()?, power: Rational::from(-&g.power), rate: Rational::from(-&g.rate), order: g.order })
    }

    /// `g^r`, `r` rational, `g > 0` beyond `R`.
    fn pow_rational(&self, g: Class, r: &Rational) -> Option<Class> {
        if !g.coef.is_positive() {
            return None;
        }
        let coef = g.coef.pow(&rat(r)).ok()?;
        let rate = Rational::from(&g.rate * r);
        let order = if rate == 0 { zero_q() } else { g.order };
        Some(Class { coef, power: Rational::from(&g.power * r), rate, order })
    }

    fn exp(&self, g: Class) -> Option<Class> {
        if let Some(range) = self.bounded_range(&g) {
            return Some(constant(range.exp().ok()?));
        }
        if g.rate == 0 && g.power > 0 {
            let c = Rational::from(-g.coef.upper().to_rational()?);
            let coef = if g.coef.is_exact() { Ball::one(P) } else { hull0(&Ball::one(P)) };
            let order = if c == 0 { zero_q() } else { g.power };
            return Some(Class { coef, power: zero_q(), rate: c, order });
        }
        None
    }

    fn log(&self, g: Class) -> Option<Class> {
        if !g.coef.is_positive() {
            return None;
        }
        let ln_c = g.coef.ln().ok()?;
        if g.rate == 0 && g.power == 0 {
            return Some(constant(ln_c));
        }
        // log g = log C' + q log x - c x^k, over x^d (d = 1/8, or k when c != 0)
        let d = if g.rate == 0 { Rational::from((1, 8)) } else { g.order.clone() };
        let e = Ball::one(P).exp().ok()?;
        let log_over = hull0(&e.mul(&rat(&d)).recip().ok()?); // log x / x^d in (0, 1/(e d)]
        let r_d = hull0(&self.r_pow(&Rational::from(-&d))?); // x^-d in (0, R^-d]
        let mut coef = ln_c.mul(&r_d).add(&rat(&g.power).mul(&log_over));
        if g.rate != 0 {
            coef = coef.sub(&rat(&g.rate));
        }
        Some(Class { coef, power: d, rate: zero_q(), order: zero_q() })
    }

    fn function(&self, f: Function, g: Class) -> Option<Class> {
        match f {
            Function::Exp => return self.exp(g),
            Function::Log => return self.log(g),
            Function::Sqrt => return self.pow_rational(g, &Rational::from((1, 2))),
            _ => {}
        }
        let range = self.bounded_range(&g);
        if let Some(range) = &range {
            let small = Self::tends_to_zero(&g);
            let pi = Ball::pi(P);
            let near_zero_rule = match f {
                Function::Sin => range.abs_upper() <= pi.lower(),
                Function::Atan | Function::Tanh => true,
                _ => false,
            };
            if small && near_zero_rule {
                return Some(Class { coef: g.coef.mul(&hull0(&Ball::one(P))), ..g });
            }
            let v = match f {
                Function::Sin => range.sin(),
                Function::Cos => range.cos(),
                Function::Tan => range.tan(),
                Function::Sinh => range.sinh(),
                Function::Cosh => range.cosh(),
                Function::Tanh => range.tanh(),
                Function::Sech => range.cosh().recip().ok()?,
                Function::Atan => range.atan(),
                _ => return None,
            };
            return v.is_finite().then(|| constant(v));
        }
        let unit = Ball::hull(&Float::with_val(P, -1), &Float::with_val(P, 1), P);
        match f {
            Function::Sin | Function::Cos | Function::Tanh => Some(constant(unit)),
            Function::Atan => Some(constant(Ball::pi(P).mul_pow2(-1).mul(&unit))),
            Function::Cosh | Function::Sinh | Function::Sech => {
                if g.rate != 0 || g.power <= 0 || g.coef.contains_zero() {
                    return None;
                }
                let sign = if g.coef.is_positive() { 1 } else { -1 };
                let m = g.coef.mul_i64(sign);
                let (m_lo, m_hi) = (m.lower().to_rational()?, m.upper().to_rational()?);
                let eps = rat(&m_lo).mul(&self.r_pow(&g.power)?).mul_i64(-2).exp().ok()?;
                let one = Ball::one(P);
                let exact = m.is_exact();
                let (coef, rate) = match f {
                    Function::Cosh => (Ball::hull(&one.lower(), &one.add(&eps).upper(), P).mul_pow2(-1), Rational::from(-&m_hi)),
                    Function::Sinh => (Ball::hull(&one.sub(&eps).lower(), &one.upper(), P).mul_pow2(-1).mul_i64(sign), Rational::from(-&m_hi)),
                    _ => (Ball::hull(&one.add(&eps).recip().ok()?.lower(), &one.upper(), P).mul_pow2(1), m_lo.clone()),
                };
                let coef = if exact { coef } else { hull0(&coef) };
                Some(Class { coef, power: zero_q(), rate, order: g.power })
            }
            _ => None,
        }
    }

    fn class(&self, e: &Expr) -> Option<Class> {
        if !e.depends_on_x() {
            let v = e.eval(&CBall::zero(P));
            if !(v.is_finite() && v.im().is_exact() && v.im().mid().is_zero()) {
                return None;
            }
            return Some(constant(v.re().clone()));
        }
        match e {
            Expr::X => Some(Class { coef: Ball::one(P), power: Rational::from(1), rate: zero_q(), order: zero_q() }),
            Expr::Neg(a) => {
                let c = self.class(a)?;
                Some(Class { coef: c.coef.neg(), ..c })
            }
            Expr::Add(a, b) => self.add(self.class(a)?, self.class(b)?),
            Expr::Sub(a, b) => {
                let g = self.class(b)?;
                self.add(self.class(a)?, Class { coef: g.coef.neg(), ..g })
            }
            Expr::Mul(a, b) => self.mul(self.class(a)?, self.class(b)?),
            Expr::Div(a, b) => {
                let num = self.class(a)?;
                self.mul(num, self.recip(self.class(b)?)?)
            }
            Expr::PowInt(a, n) => {
                let g = self.class(a)?;
                if *n < 0 && g.coef.contains_zero() {
                    return None;
                }
                let coef = if *n >= 0 { g.coef.pow_u64(*n as u64) } else { g.coef.pow_u64(n.unsigned_abs()).recip().ok()? };
                let rate = Rational::from(&g.rate * *n);
                let order = if rate == 0 { zero_q() } else { g.order };
                Some(Class { coef, power: Rational::from(&g.power * *n), rate, order })
            }
            Expr::Pow(a, b) => {
                if !b.depends_on_x() {
                    if let Some(r) = const_rational(b) {
                        return self.pow_rational(self.class(a)?, &r);
                    }
                    let g = self.class(a)?;
                    let r = self.class(b)?.coef;
                    if g.power == 0 && g.rate == 0 && g.coef.is_positive() {
                        return Some(constant(g.coef.pow(&r).ok()?));
                    }
                    return None;
                }
                // a^b = exp(b log a)
                let log_a = self.log(self.class(a)?)?;
                self.exp(self.mul(self.class(b)?, log_a)?)
            }
            Expr::Call(f, a) => self.function(*f, self.class(a)?),
            Expr::BesselJ(_, a) => {
                self.class(a)?;
                Some(constant(Ball::hull(&Float::with_val(P, -1), &Float::with_val(P, 1), P)))
            }
            Expr::Pi | Expr::Number(_) => None,
        }
    }
}

pub(crate) use super::tree::const_rational;

/// The class of `f` at `+inf` for the radius `2^log2_r`.
pub(crate) fn class_at(f: &Expr, log2_r: u32) -> Option<Class> {
    let ctx = Ctx { r: Ball::from_float(&(Float::with_val(P, 1) << log2_r), P) };
    ctx.class(f)
}

/// The tail of `int^inf f`: a certified decay from the expression (module docs).
pub(crate) fn tail_class(f: &Expr) -> TailClass {
    let mut slow = None;
    for j in RADII_LOG2 {
        let Some(c) = class_at(f, j) else { continue };
        match decay_of(&c, j) {
            Some(t) => return t,
            None => slow = Some(c.power.to_f64()),
        }
    }
    match slow {
        Some(power) => TailClass::Slow { power },
        None => TailClass::Unknown,
    }
}

/// The [`Decay`] of a class found at `R = 2^j`, `None` when it is not integrable.
fn decay_of(c: &Class, j: u32) -> Option<TailClass> {
    let r_of = |j: u32| Ball::from_float(&(Float::with_val(P, 1) << j), P);
    let m = Ball::from_float(&c.coef.abs_upper(), P);
    if c.rate > 0 && c.order >= 1 {
        let mut j = j;
        let ctx = |j: u32| Ctx { r: r_of(j) };
        let lambda = |j: u32| rat(&c.rate).mul(&ctx(j).r_pow(&Rational::from(&c.order - 1u32)).unwrap_or_else(|| Ball::one(P)));
        if c.power > 0 {
            // R' >= 8 q / lambda
            while j < 1000 && rat(&c.power).mul_i64(8).div(&lambda(j)).ok()?.upper() > *r_of(j).mid() {
                j += 1;
            }
            let l = lambda(j);
            let r = r_of(j);
            let bound = m.mul(&ctx(j).r_pow(&c.power)?).mul(&l.mul(&r).mul_pow2(-3).neg().exp().ok()?);
            let rate = l.mul_i64(7).mul_pow2(-3);
            let rate = Ball::from_float(&rate.lower(), P);
            return Some(TailClass::Decays { decay: Decay::exponential(rate, bound).ok()?, from: r });
        }
        let rate = Ball::from_float(&lambda(j).lower(), P);
        let bound = m.mul(&ctx(j).r_pow(&c.power)?);
        return Some(TailClass::Decays { decay: Decay::exponential(rate, bound).ok()?, from: r_of(j) });
    }
    if c.rate > 0 && c.order > 0 {
        // x^{q+3} e^{-c x^k} <= (s/(c k))^{s/k} e^{-s/k}, s = q + 3
        let s = Rational::from(&c.power + 3u32);
        if s <= 0 {
            return None;
        }
        let ck = rat(&Rational::from(&c.rate * &c.order));
        let s_over_k = rat(&Rational::from(&s / &c.order));
        let peak = rat(&s).div(&ck).ok()?.pow(&s_over_k).ok()?.mul(&s_over_k.neg().exp().ok()?);
        return Some(TailClass::Decays { decay: Decay::algebraic(Ball::from_i64(3, P), m.mul(&peak)).ok()?, from: r_of(j) });
    }
    if c.rate == 0 && c.power < -1 {
        let power = rat(&Rational::from(-&c.power));
        return Some(TailClass::Decays { decay: Decay::algebraic(power, m).ok()?, from: r_of(j) });
    }
    None
}

impl Expr {
    /// `f(-x)`: the tree with `x` replaced by `-x`.
    pub fn reflected(&self) -> Expr {
        let b = |e: &Expr| Box::new(e.reflected());
        match self {
            Expr::X => Expr::Neg(Box::new(Expr::X)),
            Expr::Pi | Expr::Number(_) => self.clone(),
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
