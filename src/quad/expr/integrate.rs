//! Certified integrals of parsed expressions: the one entry point behind
//! `maugis integrate`, the `integrate` request of `maugis eval` and Python's
//! `maugis.integrate`.

use super::decay::{tail_class, TailClass};
use super::decay::const_rational;
use super::local::{affine, local_class, singular_candidates};
use super::oscillatory::factors;
use super::tree::Function;
use super::oscillatory::{integrate_inverted, integrate_oscillatory};
use rug::{Float, Rational};
use crate::ball::CBall;
use super::Expr;
use crate::ball::{Ball, Decimal};
use crate::error::{Error, IntegrationError, Result};
use crate::quad::certified::{integrate, integrate_segments, integrate_to_infinity, integrate_to_infinity_from, integrate_weighted, Decay, EndBound, Integral, Options, Weight};

/// Guard bits of the balls made from decimal inputs (endpoints, exponents, decay
/// constants) over the requested precision: their radii then cost the result
/// about `2^-64` of its tolerance.
const INPUT_GUARD_BITS: u32 = 64;

/// An end of an integral: a decimal, `+inf` or `-inf`.
#[derive(Clone, Debug, PartialEq)]
pub enum End {
    /// A finite end, a decimal (the ball that contains it).
    Finite(Decimal),
    /// `+inf`.
    Infinity,
    /// `-inf`.
    MinusInfinity,
}

/// The former name of [`End`] (an upper end may now be any end).
pub type UpperLimit = End;

impl End {
    /// A decimal, or `inf` / `+inf` / `infinity` / `-inf` / `-infinity` (any case).
    pub fn parse(text: &str) -> Result<End> {
        let t = text.trim();
        let lower = t.to_ascii_lowercase();
        match lower.as_str() {
            "inf" | "+inf" | "infinity" | "+infinity" => Ok(End::Infinity),
            "-inf" | "-infinity" => Ok(End::MinusInfinity),
            _ => Decimal::parse(t).map(End::Finite).map_err(|e| match e {
                Error::NotADecimal { text } => Error::Integration(IntegrationError::UpperEnd { text }),
                other => other,
            }),
        }
    }

    fn rank(&self) -> i8 {
        match self {
            End::MinusInfinity => -1,
            End::Finite(_) => 0,
            End::Infinity => 1,
        }
    }
}

impl From<Decimal> for End {
    fn from(d: Decimal) -> End {
        End::Finite(d)
    }
}

/// The endpoint weight `(x-a)^alpha (b-x)^beta log^log(x-a)` as typed; each part
/// defaults to 0 (no weight).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct WeightSpec {
    /// `alpha > -1`, or `None` for 0.
    pub alpha: Option<Decimal>,
    /// `beta > -1`, or `None` for 0 (must be 0 on a semi-infinite range).
    pub beta: Option<Decimal>,
    /// The power of `log(x-a)`.
    pub log: u32,
}

impl WeightSpec {
    fn is_trivial(&self) -> bool {
        let zero = |d: &Option<Decimal>| d.as_ref().is_none_or(|d| *d.as_rational() == 0);
        zero(&self.alpha) && zero(&self.beta) && self.log == 0
    }

    fn to_weight(&self, prec: u32) -> Result<Weight> {
        let ball = |d: &Option<Decimal>| d.as_ref().map_or_else(|| crate::Ball::zero(prec), |d| d.to_ball(prec));
        Weight::new(ball(&self.alpha), ball(&self.beta), self.log)
    }
}

/// A declared bound on the whole integrand for `x >= a`, for `b = inf`.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub enum DecaySpec {
    /// `|f(x)| <= bound e^(-rate x)`.
    Exponential {
        /// `rate > 0`.
        rate: Decimal,
        /// `bound >= 0`.
        bound: Decimal,
    },
    /// `|f(x)| <= bound x^(-power)`.
    Algebraic {
        /// `power > 1`.
        power: Decimal,
        /// `bound >= 0`.
        bound: Decimal,
    },
}

/// `int_a^b w(x) f(x) dx` as a certified [`Integral`], `f` the expression,
/// `w` the optional endpoint weight (at a finite `a`).
///
/// An infinite end needs no declaration: the tail bound is derived from the expression
/// ([`decay`](self) rules, `docs/quadrature.md`); a declared `decay` (for `b = inf`)
/// is used instead when given. `-inf` ends are reflected (`int_{-inf}^b f(x) dx =
/// int_{-b}^inf f(-x) dx`, and `int_{-inf}^inf f = int_0^inf (f(x) + f(-x)) dx`).
///
/// Decimal inputs become balls that contain them, so the result contains the
/// integral for the numbers as typed. Reversed ranges change the sign, except with a
/// (non-trivial) weight, which needs `a < b`.
pub fn integrate_range(
    f: &Expr,
    a: &End,
    b: &End,
    weight: Option<&WeightSpec>,
    decay: Option<&DecaySpec>,
    prec: u32,
    opts: &Options,
) -> Result<Integral> {
    crate::error::check_prec(prec)?;
    let canonical = f.canonical();
    let f = &canonical;
    let ip = prec.saturating_add(INPUT_GUARD_BITS);
    let weight = weight.filter(|w| !w.is_trivial()).map(|w| w.to_weight(ip)).transpose()?;
    if decay.is_some() && !matches!(b, End::Infinity) {
        return Err(Error::Integration(IntegrationError::DecayWithFiniteEnd));
    }
    if a.rank() > b.rank() || (a.rank() != 0 && a == b) {
        if weight.is_some() || a == b {
            return Err(Error::Integration(IntegrationError::Endpoints { a: end_f64(a), b: end_f64(b) }));
        }
        let mut r = integrate_range(f, b, a, None, None, prec, opts)?;
        r.value = r.value.neg();
        return Ok(r);
    }
    if weight.is_some() && matches!(a, End::MinusInfinity) {
        return Err(Error::Integration(IntegrationError::Endpoints { a: f64::NEG_INFINITY, b: end_f64(b) }));
    }
    let g = |x: &_| f.eval(x);
    match (a, b) {
        (End::Finite(a), End::Finite(b)) => match &weight {
            None => integrate_finite(f, a.as_rational(), b.as_rational(), ip, prec, opts),
            Some(w) => integrate_weighted(g, &a.to_ball(ip), &b.to_ball(ip), w, prec, opts),
        },
        (End::Finite(a), End::Infinity) => {
            let a = a.to_ball(ip);
            match decay {
                Some(d) => {
                    let decay = match d {
                        DecaySpec::Exponential { rate, bound } => Decay::exponential(rate.to_ball(ip), bound.to_ball(ip))?,
                        DecaySpec::Algebraic { power, bound } => Decay::algebraic(power.to_ball(ip), bound.to_ball(ip))?,
                    };
                    integrate_to_infinity(g, &a, weight.as_ref(), &decay, prec, opts)
                }
                None => to_infinity(f, &a, weight.as_ref(), prec, opts, 1.0),
            }
        }
        (End::MinusInfinity, End::Finite(b)) => {
            let minus_b = Decimal::from_rational(rug::Rational::from(-b.as_rational()));
            to_infinity(&f.reflected(), &minus_b.to_ball(ip), None, prec, opts, -1.0)
        }
        (End::MinusInfinity, End::Infinity) => {
            let both = Expr::Add(Box::new(f.clone()), Box::new(f.reflected()));
            to_infinity(&both, &crate::Ball::zero(ip), None, prec, opts, 1.0)
        }
        _ => Err(Error::Integration(IntegrationError::Endpoints { a: end_f64(a), b: end_f64(b) })),
    }
}

/// [`integrate_range`] from a finite `a`.
pub fn integrate_expr(
    f: &Expr,
    a: &Decimal,
    b: &End,
    weight: Option<&WeightSpec>,
    decay: Option<&DecaySpec>,
    prec: u32,
    opts: &Options,
) -> Result<Integral> {
    integrate_range(f, &End::Finite(a.clone()), b, weight, decay, prec, opts)
}

/// `int_a^b f` for rational ends, with the singular points of `f` in `[a, b]` found from
/// the expression (`local.rs`): a candidate point (a zero of an affine subtree that is
/// divided by, raised to a fractional or negative power, or under `log` / `sqrt`) splits
/// the range, and each end where the integrand is singular gets its local class: an
/// integrable one (`|f| <= C t^q`, `q > -1`) is mapped exponentially with the class as
/// its tail bound; a pole or worse (`q <= -1`) is [`IntegrationError::NotIntegrable`]
/// naming the point.
pub(crate) fn integrate_finite(f: &Expr, a: &Rational, b: &Rational, ip: u32, prec: u32, opts: &Options) -> Result<Integral> {
    let to_ball = |q: &Rational| Decimal::from_rational(q.clone()).to_ball(ip);
    let g = |x: &_| f.eval(x);
    if a == b {
        return integrate(g, &to_ball(a), &to_ball(b), prec, opts);
    }
    let (lo, hi, flip) = if a < b { (a, b, false) } else { (b, a, true) };
    let mut candidates = Vec::new();
    singular_candidates(f, &mut candidates);
    let finite_at = |p: &Rational| f.eval(&CBall::from_real(to_ball(p))).is_finite();
    let singular = |p: &Rational| candidates.contains(p) || !finite_at(p);
    let mut points = vec![lo.clone()];
    let mut interior: Vec<Rational> = candidates.iter().filter(|p| *p > lo && *p < hi).cloned().collect();
    interior.sort();
    points.extend(interior);
    points.push(hi.clone());
    let mut ends = Vec::new();
    let mut any = false;
    for w in points.windows(2) {
        let half = Rational::from(&w[1] - &w[0]) / 2u32;
        // delta: a power of 2 at most min(1/2, half the segment)
        let mut delta = Rational::from((1, 2));
        while delta > half {
            delta /= 2u32;
        }
        let mut pair = [None, None];
        for (k, (p, sigma)) in [(&w[0], 1i64), (&w[1], -1i64)].into_iter().enumerate() {
            if !singular(p) {
                continue;
            }
            if let Some(c) = local_class(f, p, sigma, &delta) {
                if c.power <= -1 {
                    return Err(Error::Integration(IntegrationError::NotIntegrable { near: p.to_f64(), evaluations: 0 }));
                }
                let delta_f = Float::with_val(64, delta.to_f64());
                pair[k] = Some(EndBound { power: to_ball(&c.power), bound: c.coef.abs_upper_mag(), delta: delta_f });
                any = true;
            }
        }
        let [l, r] = pair;
        ends.push((l, r));
    }
    if any && points.len() == 2 {
        // fractional powers of affine factors vanishing at an end: a declared weight in
        // all but name (faster: the rest is analytic there)
        if let Some((g_rest, alpha, beta)) = weight_split(f, lo, hi) {
            let w = Weight::new(to_ball(&alpha), to_ball(&beta), 0)?;
            let r = integrate_weighted(|x: &_| g_rest.eval(x), &to_ball(lo), &to_ball(hi), &w, prec, opts);
            if let Ok(mut r) = r {
                if flip {
                    r.value = r.value.neg();
                }
                return Ok(r);
            }
        }
    }
    let mut result = if !any && points.len() == 2 {
        integrate(g, &to_ball(lo), &to_ball(hi), prec, opts)?
    } else {
        singular_pieces(f, &points, &ends, ip, prec, opts)?
    };
    if flip {
        result.value = result.value.neg();
    }
    Ok(result)
}

/// The pieces of a range split at singular points, summed: next to each singular end
/// `p` (side `sigma`) the piece `int_0^{delta/2} f(p + sigma t) dt`, with `f(p + sigma t)`
/// written in `t` and its affine subtrees folded exactly ([`Expr::shifted`]: `1 - x` at
/// `x = 1 - t` is `t`, with no cancellation however small `t`), mapped at `t = 0`; the
/// regular middles as they are. The sum is checked against the goal and the pieces
/// redone with more bits when it misses.
fn singular_pieces(f: &Expr, points: &[Rational], ends: &[(Option<EndBound>, Option<EndBound>)], ip: u32, prec: u32, opts: &Options) -> Result<Integral> {
    let to_ball = |q: &Rational| Decimal::from_rational(q.clone()).to_ball(ip);
    // (expression, lo, hi, singular left end)
    let mut pieces: Vec<(Expr, Rational, Rational, Option<EndBound>)> = Vec::new();
    for (w, (left, right)) in points.windows(2).zip(ends) {
        let mut lo = w[0].clone();
        let mut hi = w[1].clone();
        for (end, p, sigma) in [(left, &w[0], 1i64), (right, &w[1], -1i64)] {
            if let Some(eb) = end {
                let half = Rational::from(eb.delta.to_rational().unwrap_or_default() / 2u32);
                pieces.push((f.shifted(p, sigma), Rational::new(), half.clone(), Some(eb.clone())));
                if sigma > 0 {
                    lo = Rational::from(&lo + &half);
                } else {
                    hi = Rational::from(&hi - &half);
                }
            }
        }
        if lo < hi {
            pieces.push((f.clone(), lo, hi, None));
        }
    }
    let mut extra = 8u32;
    let mut last = None;
    for _ in 0..4 {
        let goal = (prec + extra).min(crate::MAX_PREC);
        let o = opts.clone().goal_bits(goal)?;
        let mut total: Option<crate::ball::CBall> = None;
        let (mut evaluations, mut limit, mut wp) = (0, None, 0);
        for (e, lo, hi, end) in &pieces {
            let g = |x: &_| e.eval(x);
            let r = match end {
                Some(eb) => integrate_segments(g, vec![to_ball(lo), to_ball(hi)], vec![(Some(eb.clone()), None)], goal, &o)?,
                None => integrate(g, &to_ball(lo), &to_ball(hi), goal, &o)?,
            };
            evaluations += r.evaluations;
            limit = limit.or(r.limit);
            wp = wp.max(r.working_prec);
            total = Some(match total {
                None => r.value,
                Some(t) => t.add(&r.value),
            });
        }
        let total = total.unwrap_or_else(|| crate::ball::CBall::zero(prec));
        let rad = total.rad_mag();
        let wanted = total.abs_lower_mag().mul_2exp(-(prec as i64));
        let met = rad.le(&wanted);
        let result = Integral { value: total, goal_met: met, limit: if met { None } else { limit }, evaluations, subintervals: 0, working_prec: wp };
        if met || limit.is_some() {
            return Ok(result);
        }
        let missing = if wanted.is_zero() { 32.0 } else { (rad.log2() - wanted.log2()).clamp(1.0, 1e4) };
        extra += missing.ceil() as u32 + 4;
        last = Some(result);
    }
    last.ok_or(Error::Internal { what: "no attempt at the singular pieces".into() })
}

/// `f = (x-a)^alpha (b-x)^beta g`, from the factors of `f` that are fractional powers
/// (`u^r`, `sqrt(u)`) of an affine `u` vanishing at `a` (`u = c (x - a)`, `c > 0`) or at
/// `b` (`u = c (b - x)`, `c > 0`): `c^r` stays in `g`. `None` when there is no such
/// factor or an exponent is not `> -1`.
fn weight_split(f: &Expr, a: &Rational, b: &Rational) -> Option<(Expr, Rational, Rational)> {
    let (mut num, mut den, mut negative) = (Vec::new(), Vec::new(), false);
    factors(f, false, &mut num, &mut den, &mut negative);
    let (mut alpha, mut beta) = (Rational::new(), Rational::new());
    let number = |q: Rational| Expr::Number(Decimal::from_rational(q));
    let mut rest: Vec<Expr> = Vec::new();
    let mut found = false;
    for (e, sign) in num.iter().map(|e| (e, 1i32)).chain(den.iter().map(|e| (e, -1i32))) {
        let power = match e {
            Expr::Pow(u, r) => const_rational(r).filter(|r| *r.denom() != 1).map(|r| (u, r)),
            Expr::Call(Function::Sqrt, u) => Some((u, Rational::from((1, 2)))),
            _ => None,
        };
        let mut taken = false;
        if let Some((u, r)) = power {
            if let Some((c0, c1)) = affine(u) {
                let r = Rational::from(&r * sign);
                let at = |p: &Rational| Rational::from(&c0 + Rational::from(&c1 * p)) == 0;
                if c1 > 0 && at(a) {
                    alpha += &r;
                    rest.push(Expr::Pow(Box::new(number(c1.clone())), Box::new(number(r))));
                    taken = true;
                } else if c1 < 0 && at(b) {
                    beta += &r;
                    rest.push(Expr::Pow(Box::new(number(Rational::from(-&c1))), Box::new(number(r))));
                    taken = true;
                }
            }
        }
        found |= taken;
        if !taken {
            rest.push(if sign > 0 { e.clone() } else { Expr::Div(Box::new(number(Rational::from(1))), Box::new(e.clone())) });
        }
    }
    if !found || alpha <= -1 || beta <= -1 {
        return None;
    }
    let mut g = rest.into_iter().fold(number(Rational::from(1)), |acc, e| Expr::Mul(Box::new(acc), Box::new(e)));
    if negative {
        g = Expr::Neg(Box::new(g));
    }
    Some((g, alpha, beta))
}

fn end_f64(e: &End) -> f64 {
    match e {
        End::Finite(d) => d.to_f64(),
        End::Infinity => f64::INFINITY,
        End::MinusInfinity => f64::NEG_INFINITY,
    }
}

/// `int_a^inf w f` with the tail bound derived from the expression; `side` (+1 or -1)
/// names the infinite end in errors.
fn to_infinity(f: &Expr, a: &crate::Ball, weight: Option<&Weight>, prec: u32, opts: &Options, side: f64) -> Result<Integral> {
    let class = tail_class(f);
    // An algebraic tail of an oscillatory integrand: the rotated contour converges
    // exponentially where the real axis would need a cut at 2^(goal/(p-1)).
    if weight.is_none() && !matches!(class, TailClass::Decays { decay: Decay::Exponential { .. }, .. }) {
        if let Some(r) = integrate_oscillatory(f, a, prec, opts) {
            return r;
        }
        // an algebraic tail analytic at infinity: u = 1/x
        if let Some(r) = integrate_inverted(f, a, prec, opts) {
            return r;
        }
    }
    match class {
        TailClass::Decays { decay, from } => {
            let g = |x: &_| f.eval(x);
            integrate_to_infinity_from(g, a, weight, &decay, &from, prec, opts)
        }
        TailClass::Slow { power } => Err(Error::Integration(IntegrationError::NotAbsolutelyIntegrable { power, end: side })),
        TailClass::Unknown => Err(Error::Integration(IntegrationError::MissingDecay)),
    }
}

/// The imaginary part of an integral when the front ends must show it: `None` when
/// it is a ball around 0 no wider than the real part's radius (as for a real
/// integrand, whose integral's imaginary part is 0), so that what is left out is
/// never larger than the radius shown.
pub fn significant_imaginary(r: &Integral) -> Option<&Ball> {
    let (re, im) = (r.value.re(), r.value.im());
    (!(im.contains_zero() && im.rad_mag().le(&re.rad_mag()))).then_some(im)
}

/// Why a result is flagged, for a warning: the limit that stopped it before its
/// goal; `None` when the goal was met.
pub fn shortfall(r: &Integral) -> Option<String> {
    if r.goal_met {
        return None;
    }
    let by = r.limit.map_or_else(|| "a limit".to_string(), |l| l.to_string());
    Some(format!(
        "the goal was not met: stopped by {by} after {} evaluations; the ball still encloses the integral",
        r.evaluations
    ))
}
