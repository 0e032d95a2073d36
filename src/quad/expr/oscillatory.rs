//! Oscillatory integrals to infinity, certified: `int_a^inf g(x) sin(w x + phi) dx`,
//! `cos`, and `int_a^inf g(x) J_n(w x) dx`, recognised in the expression.
//!
//! # Method
//!
//! *Recognition.* The integrand is flattened into factors (`*`, `/`, unary minus); one
//! factor of the numerator must be `sin(u)`, `cos(u)` or `besselj(n, u)` with `u = w x +
//! phi` affine in `x` (`w` an exact rational, `w != 0`; `phi` any real constant). The
//! other factors form `g`.
//!
//! *The class of `g` in a sector.* On `Omega = {z : Re z >= T, |ph z| <= theta}` (`T`
//! an exact integer, `theta <= pi/2` below), `g` gets a class `g(z) = z^q u(z)`, `u(z)`
//! in a complex ball `D`, by rules that also prove `g` holomorphic on `Omega` (every
//! point of `Omega` has `|z| >= T` and `|ph z| <= theta`): `z` (`q = 1, D = 1`); a
//! constant; `-g`, `g h` (`z^a z^b = z^{a+b}` for the principal powers), `1/h` (`D_h`
//! off 0: `h` has no zero), integer powers; `g + h` with `q_g >= q_h`: `D = D_g + D_h
//! disc(0, T^{q_h - q_g})`; `g^r` for a real constant `r` (`sqrt` is `r = 1/2`) when
//! `|q| theta + sup |ph D| < pi`: then `Log g = q Log z + Log u` (the right side has
//! imaginary part in `(-pi, pi)`), `g` never meets the cut, and `g^r = z^{q r} u^r`; any
//! function of a `g` with `q <= 0` (bounded: `g` in `D disc(0, T^q)`, or in `D` when `q
//! = 0`): that function of the ball, when finite.
//!
//! *Contour rotation.* Split at `T`: `int_a^T f` is an ordinary certified integral. For
//! the tail, `sin(w x + phi) = (e^{i phi} e^{i w x} - e^{-i phi} e^{-i w x})/(2i)` (and
//! `cos` alike), and `J_n(w x) = (H_n^(1)(w x) + H_n^(2)(w x))/2`. Each term
//! `int_T^inf g(x) E(x) dx` with `|E(z)| <= K |z|^e e^{-s Im z}` (`s = +-w`: `E = e^{i w
//! z}`, `e = 0`; `E = H^(1)(w z)`, `e = -1/2`) is moved to the ray `z = T + r d`, `d = c
//! + i`, `r >= 0` (or `d = c - i` for the terms that decay below the axis), inside
//! `Omega` with `theta = atan(1/c)` (`pi/2` for `c = 0`):
//!
//! ```text
//! int_T^inf g(x) E(x) dx = d int_0^inf g(T + r d) E(T + r d) dr.
//! ```
//!
//! The slope `c` is the least of `0, 1/64, 1/8, 1/2, 1` for which `g` has a class on
//! that sector (fractional powers of `z^q` need `|q| theta < pi`): on the ray `E` turns
//! `c |w|` radians while it decays by `e^{-|w|}`, so the vertical ray (`c = 0`) carries no
//! oscillation at all and takes the fewest evaluations.
//!
//! Proof: Cauchy's theorem on the parallelogram `T, X, X + R d, T + R d` (all in
//! `Omega`, where `g E` is holomorphic: `Re z >= T` and `0 <= ph z <= theta` there). On
//! the far side (`Im z = R`) `|g E| <= |D| K |z|^{q+e} e^{-|s| R}` over a length `X - T`:
//! `-> 0` as `R -> inf`. On the side from `X`, `|z| >= Re z >= X` and `|g E| <= |D| K
//! X^{q+e} e^{-|s| r}`, whose integral `<= |d| |D| K X^{q+e}/|s| -> 0` as `X -> inf`
//! because `q + e < 0` (checked: the integral is then at most conditionally convergent
//! on the real axis, and converges). On the ray, `|integrand| <= |d| |D| K T^{q+e}
//! e^{-|s| r}`: an exponential decay, which the certified integrator cuts with its
//! closed-form tail ([`Decay::exponential`]). For the Hankel terms `K = (2/(pi
//! |w|))^(1/2)` times a bound of Hankel's sum with its remainder
//! ([`CBall::hankel_sum_bound`], valid for `-pi/2 <= ph(w z) <= pi`, which contains
//! the sector), and `T` is taken with `|w| T >= 3 * 0.35 (goal + 60)`, three times where
//! the expansion first reaches the goal (`T_OVER_HANKEL`). `H^(1)` is evaluated on the
//! ray by Hankel's expansion with its error bound (`ball/complex/hankel.rs`).
//!
//! The pieces are certified balls; their sum is checked against the goal and the pieces
//! redone with more bits when it misses.

use rug::{Float, Rational};

use super::decay::const_rational;
use super::tree::{Expr, Function};
use crate::ball::{Ball, CBall, Decimal, Mag};
use crate::error::Result;
use super::finite::{integrate_finite, sum_to_goal};
use super::local::factors;
use crate::quad::certified::{integrate, integrate_to_infinity, Decay, HoloBall, Integral, Options};

/// The oscillatory factor of an integrand.
#[derive(Clone, Debug)]
enum Kernel {
    /// `sin(w x + phi)` (`cos` when `cos` is true).
    Trig { cos: bool, w: Rational, phi: Expr },
    /// `J_n(w x)`.
    Bessel { n: i64, w: Rational },
}

/// `f = g * kernel`.
struct Split {
    g: Expr,
    kernel: Kernel,
}

/// The coefficient of `x` in an expression affine in `x` (exact), if it is one.
fn linear_coefficient(e: &Expr) -> Option<Rational> {
    if !e.depends_on_x() {
        return Some(Rational::new());
    }
    Some(match e {
        Expr::X => Rational::from(1),
        Expr::Neg(a) => Rational::from(-linear_coefficient(a)?),
        Expr::Add(a, b) => Rational::from(linear_coefficient(a)? + linear_coefficient(b)?),
        Expr::Sub(a, b) => Rational::from(linear_coefficient(a)? - linear_coefficient(b)?),
        Expr::Mul(a, b) if !a.depends_on_x() => Rational::from(const_rational(a)? * linear_coefficient(b)?),
        Expr::Mul(a, b) if !b.depends_on_x() => Rational::from(linear_coefficient(a)? * const_rational(b)?),
        Expr::Div(a, b) if !b.depends_on_x() => {
            let d = const_rational(b)?;
            if d == 0 {
                return None;
            }
            Rational::from(linear_coefficient(a)? / d)
        }
        _ => return None,
    })
}

/// `e` with `x = 0`: the constant part of an affine expression.
fn at_zero(e: &Expr) -> Expr {
    match e {
        Expr::X => Expr::Number(Decimal::from_rational(Rational::new())),
        Expr::Pi | Expr::Number(_) => e.clone(),
        Expr::Neg(a) => Expr::Neg(Box::new(at_zero(a))),
        Expr::Add(a, b) => Expr::Add(Box::new(at_zero(a)), Box::new(at_zero(b))),
        Expr::Sub(a, b) => Expr::Sub(Box::new(at_zero(a)), Box::new(at_zero(b))),
        Expr::Mul(a, b) => Expr::Mul(Box::new(at_zero(a)), Box::new(at_zero(b))),
        Expr::Div(a, b) => Expr::Div(Box::new(at_zero(a)), Box::new(at_zero(b))),
        other => other.clone(),
    }
}

fn kernel_of(e: &Expr) -> Option<Kernel> {
    match e {
        Expr::Call(f @ (Function::Sin | Function::Cos), u) if u.depends_on_x() => {
            let w = linear_coefficient(u)?;
            (w != 0).then(|| Kernel::Trig { cos: *f == Function::Cos, w, phi: at_zero(u) })
        }
        Expr::BesselJ(n, u) if u.depends_on_x() => {
            let w = linear_coefficient(u)?;
            // J_n(w x + c) with c != 0 is not handled
            let c = const_rational(&at_zero(u))?;
            (w != 0 && c == 0).then(|| Kernel::Bessel { n: *n, w })
        }
        _ => None,
    }
}

fn split(f: &Expr) -> Option<Split> {
    let (mut num, mut den, mut negative) = (Vec::new(), Vec::new(), false);
    factors(f, false, &mut num, &mut den, &mut negative);
    let i = num.iter().position(|e| kernel_of(e).is_some())?;
    let kernel = kernel_of(&num.remove(i))?;
    let one = || Expr::Number(Decimal::from_rational(Rational::from(1)));
    let mut g = num.into_iter().fold(one(), |acc, e| Expr::Mul(Box::new(acc), Box::new(e)));
    if !den.is_empty() {
        let d = den.into_iter().fold(one(), |acc, e| Expr::Mul(Box::new(acc), Box::new(e)));
        g = Expr::Div(Box::new(g), Box::new(d));
    }
    if negative {
        g = Expr::Neg(Box::new(g));
    }
    Some(Split { g, kernel })
}

/// Precision of the class balls.
const P: u32 = 128;

/// `g(z) = z^q u(z)`, `u` in `d`, on `Omega_T` (module docs).
#[derive(Clone, Debug)]
struct ZClass {
    q: Rational,
    d: CBall,
}

struct ZCtx {
    t: Ball,
    /// An upper bound of the sector's half-angle `theta` (`|ph z| <= theta`).
    angle: Ball,
    /// The class must hold on all of `|z| >= T` (every argument): no fractional powers.
    full: bool,
}

fn rat(q: &Rational) -> Ball {
    Decimal::from_rational(q.clone()).to_ball(P)
}

/// The disc `|z| <= m` as a complex ball.
fn disc(m: Mag) -> CBall {
    let b = Ball::with_mag(Float::new(P), m);
    CBall::new(b.clone(), b)
}

impl ZCtx {
    fn t_pow(&self, e: &Rational) -> Option<Ball> {
        if *e == 0 {
            return Some(Ball::one(P));
        }
        self.t.pow(&rat(e)).ok()
    }

    /// The values of `g` on `Omega_T` when `q <= 0`.
    fn bounded(&self, g: &ZClass) -> Option<CBall> {
        if g.q == 0 {
            return Some(g.d.clone());
        }
        if g.q < 0 {
            return Some(g.d.mul(&disc(self.t_pow(&g.q)?.abs_upper_mag())));
        }
        None
    }

    fn class(&self, e: &Expr) -> Option<ZClass> {
        if !e.depends_on_x() {
            let v = e.eval(&CBall::zero(P));
            return v.is_finite().then(|| ZClass { q: Rational::new(), d: v });
        }
        match e {
            Expr::X => Some(ZClass { q: Rational::from(1), d: CBall::one(P) }),
            Expr::Neg(a) => {
                let c = self.class(a)?;
                Some(ZClass { d: c.d.neg(), ..c })
            }
            Expr::Add(a, b) => self.add(self.class(a)?, self.class(b)?),
            Expr::Sub(a, b) => {
                let h = self.class(b)?;
                self.add(self.class(a)?, ZClass { d: h.d.neg(), ..h })
            }
            Expr::Mul(a, b) => {
                let (g, h) = (self.class(a)?, self.class(b)?);
                Some(ZClass { q: Rational::from(&g.q + &h.q), d: g.d.mul(&h.d) })
            }
            Expr::Div(a, b) => {
                let (g, h) = (self.class(a)?, self.class(b)?);
                if h.d.contains_zero() {
                    return None;
                }
                let d = g.d.div(&h.d);
                d.is_finite().then(|| ZClass { q: Rational::from(&g.q - &h.q), d })
            }
            Expr::PowInt(a, n) => {
                let g = self.class(a)?;
                if *n < 0 && g.d.contains_zero() {
                    return None;
                }
                let d = g.d.pow_i64(*n);
                d.is_finite().then(|| ZClass { q: Rational::from(&g.q * *n), d })
            }
            Expr::Pow(a, b) if !b.depends_on_x() => {
                let r = const_rational(b)?;
                self.pow(self.class(a)?, &r)
            }
            Expr::Call(Function::Sqrt, a) => self.pow(self.class(a)?, &Rational::from((1, 2))),
            Expr::Call(f, a) => {
                let g = self.class(a)?;
                let v = self.bounded(&g)?;
                let y = match f {
                    Function::Exp => v.exp(),
                    Function::Log => v.log_analytic(),
                    Function::Sin => v.sin(),
                    Function::Cos => v.cos(),
                    Function::Tan => v.tan(),
                    Function::Sinh => v.sinh(),
                    Function::Cosh => v.cosh(),
                    Function::Tanh => v.tanh(),
                    Function::Sech => v.sech(),
                    Function::Atan => v.atan_analytic(),
                    _ => return None,
                };
                y.is_finite().then(|| ZClass { q: Rational::new(), d: y })
            }
            _ => None,
        }
    }

    fn add(&self, g: ZClass, h: ZClass) -> Option<ZClass> {
        let (big, small) = if g.q >= h.q { (g, h) } else { (h, g) };
        let shrink = self.t_pow(&Rational::from(&small.q - &big.q))?;
        let d = big.d.add(&small.d.mul(&disc(shrink.abs_upper_mag())));
        Some(ZClass { q: big.q, d })
    }

    /// `g^r` on `Omega_T` (module docs).
    fn pow(&self, g: ZClass, r: &Rational) -> Option<ZClass> {
        if self.full {
            return None;
        }
        let log_u = g.d.log_analytic();
        if !log_u.is_finite() {
            return None;
        }
        // |q| theta + sup |ph u| < pi
        let arg = Ball::from_float(&log_u.im().abs_upper(), P);
        let spread = self.angle.mul(&rat(&Rational::from(g.q.clone().abs()))).add(&arg);
        if !(spread.upper() < Ball::pi(P).lower()) {
            return None;
        }
        let d = log_u.mul_real(&rat(r)).exp();
        d.is_finite().then(|| ZClass { q: Rational::from(&g.q * r), d })
    }
}

/// One tail term: `coef int_T^inf g(x) E(x) dx`.
struct Term {
    coef: CBall,
    /// `+1`: the ray `T + r(1+i)`; `-1`: `T + r(1-i)`.
    side: i64,
}

/// `T` is taken this many times beyond the least `|w| T = 0.35 (goal + 60)` at which
/// Hankel's expansion reaches the goal: there the expansion needs about `2 |w| T`
/// terms and the rays most of the time; at three times, about a fifth of the terms
/// (`x J_0(k x)/(x^2+1)^(3/2)`, `k = 1/2, 1, 5`, at 333 bits: 0.37-0.54 s at factor 1,
/// 0.26-0.29 s at 3, 0.24-0.27 s at 4, 0.24-0.27 s at 6, where `int J_0` and `int J_1
/// / sqrt x` take longer; CPU time, 2026-11-29).
const T_OVER_HANKEL: f64 = 3.0;

/// Largest `j` tried for `T = 2^j`.
const MAX_LOG2_T: u32 = 40;

/// What the contour rotation of one oscillatory integrand needs: `f = g * kernel`, the
/// split point `T`, the slope of the rays and the certified decay along them.
pub(crate) struct Plan {
    g: Expr,
    kernel: Kernel,
    t: Ball,
    slope: Rational,
    j: u32,
    decay: Decay,
}

/// `int_a^inf f(x) dx` for a recognised oscillatory `f` (module docs): `None` when `f`
/// is not of that form or `g` gets no class.
pub(crate) fn integrate_oscillatory(f: &Expr, a: &Ball, prec: u32, opts: &Options) -> Option<Result<Integral>> {
    Some(match plan(f, a, prec)? {
        Ok(p) => run(f, &p.g, &p.kernel, a, &p.t, &p.slope, p.j, &p.decay, prec, opts),
        Err(e) => Err(e),
    })
}

/// The recognition of [`integrate_oscillatory`] without the integration: `None` when
/// `f` is not of the form or `g` gets no class (cheap: class balls at 128 bits).
pub(crate) fn plan(f: &Expr, a: &Ball, prec: u32) -> Option<Result<Plan>> {
    let Split { g, kernel } = split(f)?;
    let (w, hankel_n) = match &kernel {
        Kernel::Trig { w, .. } => (w.clone(), None),
        Kernel::Bessel { n, w } => (w.clone(), Some(*n)),
    };
    let w_abs = Rational::from(w.clone().abs());
    let w_ball = rat(&w_abs);
    // T: past a, and for Hankel's expansion |w| T >= 3 * 0.35 (goal + 60): the least
    // t 2^(j-3) >= need with 2^(j-1) < need <= 2^j, t in 5..=8 (not just a power of 2:
    // the finite part [a, T] is up to 37% shorter)
    let mut j = 1u32;
    let a_up = a.upper().to_f64();
    let need = if hankel_n.is_some() { T_OVER_HANKEL * 0.35 * (prec as f64 + 60.0) / w_abs.to_f64() } else { 0.0 };
    let need = (a_up + 1.0).max(need);
    while j < MAX_LOG2_T && ((1u64 << j) as f64) < need {
        j += 1;
    }
    let t0 = if j >= 3 { (5u64..=8).map(|t| t << (j - 3)).find(|&t| t as f64 >= need).unwrap_or(1 << j) } else { 1 << j };
    let mut found = None;
    'search: for jj in 0..=12u32 {
        let t = Float::with_val(P, t0) << jj;
        for slope in RAY_SLOPES {
            let c = Rational::from(slope);
            let ctx = ZCtx { t: Ball::from_float(&t, P), angle: sector_angle(&c), full: false };
            if let Some(class) = ctx.class(&g) {
                found = Some((j + jj, ctx, class, c));
                break 'search;
            }
        }
    }
    let (j, ctx, class, slope) = found?;
    let e = if hankel_n.is_some() { Rational::from((-1, 2)) } else { Rational::new() };
    let qe = Rational::from(&class.q + &e);
    if qe >= 0 {
        return None;
    }
    let t = ctx.t.clone();
    // the bound of |g E| on the ray: |c + i| |D| K T^{q+e}
    let k_factor = match hankel_n {
        None => Ball::one(P),
        Some(n) => {
            let rho = w_ball.mul(&t);
            let sum = CBall::hankel_sum_bound(n, rho.abs_lower_mag());
            Ball::from_i64(2, P).div(&Ball::pi(P).mul(&w_ball)).ok()?.sqrt().ok()?.mul(&Ball::from_float(&sum.to_float(), P))
        }
    };
    let dir_abs = rat(&Rational::from(&slope * &slope)).add(&Ball::one(P)).sqrt().ok()?;
    let bound = dir_abs.mul(&Ball::from_float(&class.d.abs_upper_mag().to_float(), P)).mul(&k_factor).mul(&ctx.t_pow(&qe)?);
    let bound = Ball::from_float(&bound.upper(), P);
    let rate = Ball::from_float(&w_ball.lower(), P);
    Some(Decay::exponential(rate, bound).map(|decay| Plan { g, kernel, t, slope, j, decay }))
}

/// The slopes `c` of the rays `T + r (c +- i)` tried, steepest first: on a steeper ray
/// the kernel oscillates less per unit of decay (`e^{i w z}` turns `c w` radians while
/// it decays by `e^{-w}`; on the vertical ray it does not turn at all), and the ray
/// integral takes fewer evaluations. A steeper ray needs the class of `g` on a wider
/// sector (`theta = atan(1/c)`), which fractional powers may not allow.
const RAY_SLOPES: [(i64, i64); 5] = [(0, 1), (1, 64), (1, 8), (1, 2), (1, 1)];

/// An upper bound of `theta = atan(1/c)`, the half-angle of the sector that contains
/// every ray `T + r (c +- i)` and the region between it and the real axis (`pi/2` for
/// `c = 0`).
fn sector_angle(c: &Rational) -> Ball {
    let half_pi = Ball::pi(P).mul_pow2(-1);
    if *c == 0 {
        return half_pi;
    }
    // atan(1/c) = pi/2 - atan(c)
    let at = rat(c).atan();
    Ball::from_float(&half_pi.sub(&at).upper(), P)
}

#[allow(clippy::too_many_arguments)]
fn run(f: &Expr, g: &Expr, kernel: &Kernel, a: &Ball, t: &Ball, slope: &Rational, _j: u32, decay: &Decay, prec: u32, opts: &Options) -> Result<Integral> {
    let wp = prec + 30;
    // the tail terms and their coefficients
    let half = CBall::from_real(Ball::one(wp).mul_pow2(-1));
    let terms: Vec<Term> = match kernel {
        Kernel::Trig { cos, w, phi } => {
            let phi = phi.eval(&CBall::zero(wp));
            let ep = phi.mul_i().exp();
            let em = phi.neg().mul_i().exp();
            let s = if *w > 0 { 1 } else { -1 };
            // sin: (e^{i phi} e^{i w x} - e^{-i phi} e^{-i w x}) / (2i); cos: (..+..)/2
            let (cp, cm) = if *cos { (ep.mul(&half), em.mul(&half)) } else { (ep.mul(&half).mul_i().neg(), em.mul(&half).mul_i()) };
            vec![Term { coef: cp, side: s }, Term { coef: cm, side: -s }]
        }
        Kernel::Bessel { n, w } => {
            // J_n(w x) = (-1)^n J_n(|w| x) for w < 0
            let sign = if *w < 0 && n % 2 != 0 { half.neg() } else { half.clone() };
            vec![Term { coef: sign.clone(), side: 1 }, Term { coef: sign, side: -1 }]
        }
    };
    sum_to_goal(prec, opts, |goal, o| {
        let finite = match (a.mid().to_rational(), t.mid().to_rational()) {
            (Some(ar), Some(tr)) if a.is_exact() => integrate_finite(f, &ar, &tr, goal + 64, goal, o)?,
            _ => integrate(|x: &HoloBall| f.eval(x), a, t, goal, o)?,
        };
        let mut out = vec![finite];
        for term in &terms {
            let side = term.side;
            let tt = t.clone();
            let kern = kernel.clone();
            let slope = Decimal::from_rational(slope.clone());
            let ray = move |s: &HoloBall| -> HoloBall {
                let p = s.prec();
                let dir = s.constant(CBall::new(slope.to_ball(p), Ball::from_i64(side, p)));
                let z = s * &dir + s.real(tt.set_prec(p));
                let gz = g.eval(&z);
                let ez = match &kern {
                    Kernel::Trig { w, .. } => {
                        let sw = Decimal::from_rational(Rational::from(w.clone().abs() * side)).to_ball(p);
                        (&z * &s.constant(CBall::new(Ball::zero(p), sw))).exp()
                    }
                    Kernel::Bessel { n, w } => {
                        let wb = Decimal::from_rational(Rational::from(w.clone().abs())).to_ball(p);
                        let n = *n;
                        z.map_holomorphic(|zz| {
                            let arg = zz.mul_real(&wb);
                            if side > 0 {
                                arg.hankel1_large(n)
                            } else {
                                arg.hankel2_large(n)
                            }
                        })
                    }
                };
                gz * ez * dir
            };
            let mut r = integrate_to_infinity(ray, &Ball::zero(wp), None, decay, goal, o)?;
            r.value = r.value.mul(&term.coef.set_prec(wp));
            out.push(r);
        }
        Ok(out)
    })
}

/// `int_a^inf f` for an `f` with a class `z^q D`, `q <= -2` an integer, on the whole
/// neighbourhood `|z| >= T` of infinity (integer powers, sums, products, quotients and
/// functions of bounded subexpressions only). Then `F(u) = f(1/u)/u^2 = u^{-q-2} D(1/u)`
/// is holomorphic on `0 < |u| <= 1/T` and bounded, so (Riemann) holomorphic on the disc:
/// `int_T^inf f = int_0^{1/T} F(u) du` is an ordinary certified integral of an analytic
/// function, whose value on a box that contains `u = 0` (and lies in the disc) is
/// enclosed by `box^{-q-2} D`. `int_a^T f` is integrated as a finite range. `None` when
/// there is no such class.
pub(crate) fn integrate_inverted(f: &Expr, a: &Ball, prec: u32, opts: &Options) -> Option<Result<Integral>> {
    let a_up = a.upper().to_f64();
    let mut found = None;
    for j in 1u32..24 {
        if ((1u64 << j) as f64) < a_up + 1.0 {
            continue;
        }
        let ctx = ZCtx { t: Ball::from_float(&(Float::with_val(P, 1) << j), P), angle: Ball::pi(P), full: true };
        if let Some(c) = ctx.class(f) {
            found = Some((j, c));
            break;
        }
        if found.is_none() && j > 12 {
            break;
        }
    }
    let (j, class) = found?;
    if *class.q.denom() != 1 || class.q > -2 {
        return None;
    }
    let k = (Rational::from(-&class.q) - 2u32).numer().to_i64()?;
    let t = Ball::from_float(&(Float::with_val(P, 1) << j), P);
    let u_max = Ball::from_float(&(Float::with_val(P, 1) >> j), P);
    let d = class.d;
    let inner = move |u: &HoloBall| -> HoloBall {
        let ub = u.inner_ref();
        if ub.contains_zero() {
            if !ub.abs_upper_mag().le(&Mag::pow2(-(j as i64))) {
                return u.map_holomorphic(|z| CBall::indeterminate(z.prec()));
            }
            let dd = d.clone();
            return u.map_holomorphic(|z| z.pow_i64(k).mul(&dd.set_prec(z.prec())));
        }
        let x = u.recip();
        f.eval(&x) * x.sqr()
    };
    Some(sum_to_goal(prec, opts, |goal, o| {
        let finite = match (a.mid().to_rational(), t.mid().to_rational()) {
            (Some(ar), Some(tr)) if a.is_exact() => integrate_finite(f, &ar, &tr, goal + 64, goal, o)?,
            _ => integrate(|x: &HoloBall| f.eval(x), a, &t, goal, o)?,
        };
        let tail = integrate(&inner, &Ball::zero(P), &u_max, goal, o)?;
        Ok(vec![finite, tail])
    }))
}
