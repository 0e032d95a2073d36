//! Endpoint weights `(x-a)^alpha (b-x)^beta log^k(x-a)` and semi-infinite ranges.
//!
//! # Method
//!
//! `[a, b]` is split at `c = (a + b)/2`. On `[a, c]`, when `alpha != 0` or `k > 0`,
//! the substitution `x = a + d e^{-s}`, `d = c - a`, gives (exactly)
//!
//! ```text
//! int_a^c (x-a)^alpha log^k(x-a) h(x) dx
//!     = int_0^inf e^{mu (log d - s)} (log d - s)^k h(a + d e^{-s}) ds,   mu = alpha + 1,
//! ```
//!
//! with `h(x) = (b-x)^beta g(x)` analytic next to `[a, c]`. The new integrand is
//! analytic in `s` and decays like `e^{-mu s}`. The range is cut at `S`; with
//! `A = |log d|` and `H = sup |h|` over `[a, a + d e^{-S}]` (one ball evaluation),
//!
//! ```text
//! |int_S^inf ...| <= H e^{mu (log d - S)} (A + S)^k / (mu (1 - k/(mu (A + S)))),
//! ```
//!
//! valid for `mu (A + S) > k`, from `Gamma(k+1, y) <= y^k e^{-y} / (1 - k/y)` for
//! `y > k` (DLMF 8.10.1 and the alternating expansion 8.11.2). `S` is chosen so that
//! this is at most a quarter of the tolerance, and the bound is added to the radius.
//! The right end is the mirror image (`x = b - d e^{-s}`, `nu = beta + 1`, no log).
//! Where an end is regular, the piece is integrated as it is. Exponents that are
//! balls (decimals such as `-1/3`) are used as balls throughout, so the result holds
//! for every exponent in the ball.
//!
//! A semi-infinite range `[a, inf)` with a declared exponential decay
//! `|w f| <= m e^{-cx}` is cut at `T` where the declared tail `m e^{-cT}/c` is at most a
//! quarter of the tolerance, and `[a, T]` is integrated as above.
//!
//! An algebraic decay `|w f| <= m x^{-p}` (`p > 1`, `x >= a > 0`) is cut in `x` only
//! when the cut is moderate: a cut needs `T ~ 2^(goal/(p-1))` and about `log2 T`
//! bisections (`2^3335` at 3333 bits, beyond f64), so `T` is used (with the tail
//! `m T^{1-p}/(p-1)`, valid for `T >= a`) while `log2 T <= 128`. Otherwise `[c, inf)` is
//! mapped by `x = c e^s` (`c = a`, or `c = 2a` when the weight is singular at `a` and
//! `[a, 2a]` is integrated as above):
//!
//! ```text
//! int_c^inf F(x) dx = int_0^inf F(c e^s) c e^s ds        (exact, c > 0)
//! ```
//!
//! This is `x = c/u` followed by the exponential map `u = e^{-s}` of the endpoint `u = 0`.
//! The mapped integrand is evaluated in ball arithmetic like any other: its ellipse
//! bounds need `F` only on boxes around `c e^{[0, S]}`, never at infinity, so `F` need
//! not be analytic at infinity (`sin(x)/x^2` is fine). The range in `s` is cut at `S`,
//! and the tail is bounded from the declaration alone, on the real axis:
//!
//! ```text
//! |int_S^inf F(c e^s) c e^s ds| = |int_{c e^S}^inf F(x) dx| <= int_{c e^S}^inf m x^{-p} dx
//!                                = m (c e^S)^{1-p} / (p - 1),
//! ```
//!
//! valid because `c e^S >= c >= a` (for every `a` in its ball; the bound is evaluated in
//! ball arithmetic with `c`, `m` and `p` as balls and rounded up). `S ~ goal ln 2/(p-1)`
//! grows linearly with the goal: about 2310 at 3333 bits for `p = 2`, where the mapped
//! integrand decays like `e^{-(p-1)s}`.

use rug::Float;

use super::{HoloBall, IntegrationError, MappedEnd, Mode, Part, PartsBuilder, XMap};
use crate::ball::{Ball, CBall, Mag};
use crate::error::{Error, Result};

/// The endpoint weight `(x-a)^alpha (b-x)^beta log^k(x-a)`.
#[derive(Debug, Clone)]
pub struct Weight {
    alpha: Ball,
    beta: Ball,
    log_power: u32,
}

impl Weight {
    /// Largest power of the logarithm.
    pub const MAX_LOG_POWER: u32 = 8;

    /// A weight; `alpha` and `beta` must be `> -1` on the whole ball, `log_power <=`
    /// [`Weight::MAX_LOG_POWER`].
    pub fn new(alpha: Ball, beta: Ball, log_power: u32) -> Result<Weight> {
        for (which, e) in [("alpha", &alpha), ("beta", &beta)] {
            if !e.is_finite() || e.lower() <= -1 {
                return Err(Error::Integration(IntegrationError::WeightExponent { which, value: e.to_f64() }));
            }
        }
        if log_power > Weight::MAX_LOG_POWER {
            return Err(Error::Integration(IntegrationError::LogPower { value: log_power, max: Weight::MAX_LOG_POWER }));
        }
        Ok(Weight { alpha, beta, log_power })
    }

    /// `(x-a)^alpha`, no log, no right weight.
    pub fn left(alpha: Ball) -> Result<Weight> {
        let p = alpha.prec();
        Weight::new(alpha, Ball::zero(p), 0)
    }

    fn left_singular(&self) -> bool {
        !is_zero(&self.alpha) || self.log_power > 0
    }

    fn right_singular(&self) -> bool {
        !is_zero(&self.beta)
    }
}

fn is_zero(b: &Ball) -> bool {
    b.is_exact() && b.mid().is_zero()
}

/// A declared bound on the whole integrand for `x >= a`.
#[derive(Debug, Clone)]
#[non_exhaustive]
pub enum Decay {
    /// `|f(x)| <= bound e^{-rate x}`, `rate > 0`.
    Exponential {
        /// `c > 0`.
        rate: Ball,
        /// `m >= 0`.
        bound: Ball,
    },
    /// `|f(x)| <= bound x^{-power}`, `power > 1`, for `x >= a > 0`.
    Algebraic {
        /// `p > 1`.
        power: Ball,
        /// `m >= 0`.
        bound: Ball,
    },
}

impl Decay {
    /// `|f(x)| <= bound e^{-rate x}`.
    pub fn exponential(rate: Ball, bound: Ball) -> Result<Decay> {
        if !rate.is_finite() || !rate.is_positive() {
            return Err(decay_error("rate must be > 0", &rate));
        }
        if !bound.is_finite() || bound.is_negative() {
            return Err(decay_error("bound must be >= 0", &bound));
        }
        Ok(Decay::Exponential { rate, bound })
    }

    /// `|f(x)| <= bound x^{-power}`.
    pub fn algebraic(power: Ball, bound: Ball) -> Result<Decay> {
        if !power.is_finite() || power.lower() <= 1 {
            return Err(decay_error("power must be > 1", &power));
        }
        if !bound.is_finite() || bound.is_negative() {
            return Err(decay_error("bound must be >= 0", &bound));
        }
        Ok(Decay::Algebraic { power, bound })
    }
}

fn decay_error(what: &'static str, v: &Ball) -> Error {
    Error::Integration(IntegrationError::Decay { what, value: v.to_f64() })
}

type Wrap<'w> = Box<dyn Fn(&HoloBall, &mut dyn FnMut(&HoloBall) -> HoloBall) -> HoloBall + 'w>;

/// The weight factors that are analytic on a piece: `(b-x)^beta` next to `a`, and
/// `(x-a)^alpha log^k(x-a)` next to `b`, times `g`.
fn left_factor(b: Ball, beta: Ball) -> impl Fn(&HoloBall, &mut dyn FnMut(&HoloBall) -> HoloBall) -> HoloBall {
    move |x, g| {
        let gx = g(x);
        if is_zero(&beta) {
            return gx;
        }
        let bx = x.real(b.clone()) - x;
        bx.pow(&x.real(beta.clone())) * gx
    }
}

fn right_factor(a: Ball, alpha: Ball, k: u32) -> impl Fn(&HoloBall, &mut dyn FnMut(&HoloBall) -> HoloBall) -> HoloBall {
    move |x, g| {
        let mut v = g(x);
        if is_zero(&alpha) && k == 0 {
            return v;
        }
        let xa = x - x.real(a.clone());
        if !is_zero(&alpha) {
            v = xa.pow(&x.real(alpha.clone())) * v;
        }
        if k > 0 {
            v = xa.log().powi(k as i64) * v;
        }
        v
    }
}

/// The exponentially mapped piece next to an endpoint `e` (`sign` +1 for `x = e + d e^{-s}`,
/// -1 for `x = e - d e^{-s}`), and its tail bound for the target `target`.
struct Mapped {
    e: Ball,
    /// `e` as a rational, when exact (for [`MappedEnd`]).
    e_exact: Option<rug::Rational>,
    sign: i64,
    d: Ball,
    mu: Ball,
    log_d: Ball,
    k: u32,
}

impl Mapped {
    fn new(e: &Ball, other: &Float, sign: i64, exponent: &Ball, k: u32, wp: u32) -> Result<Mapped> {
        let other = Ball::from_float(other, other.prec());
        let d = if sign > 0 { other.sub(e) } else { e.sub(&other) };
        let log_d = d.set_prec(wp).ln()?;
        let e_exact = if e.is_exact() { e.mid().to_rational() } else { None };
        Ok(Mapped { e: e.set_prec(wp), e_exact, sign, d: d.set_prec(wp), mu: exponent.set_prec(wp).add_i64(1), log_d, k })
    }

    /// `x(s)` in f64, for errors.
    fn map(&self) -> XMap {
        XMap::Endpoint { e: self.e.to_f64(), d: self.d.to_f64(), sign: self.sign as f64 }
    }

    /// `x(s)`, from `t = d e^{-s}` and `log_t = log d - s`, carrying both
    /// ([`MappedEnd`]).
    fn x(&self, s: &HoloBall, log_t: &HoloBall) -> HoloBall {
        let t = s.real(self.d.clone()) * (-s).exp();
        let x = if self.sign > 0 { s.real(self.e.clone()) + &t } else { s.real(self.e.clone()) - &t };
        let end = MappedEnd { e: self.e_exact.clone(), sign: self.sign, t: t.into_inner(), log_t: log_t.inner().clone() };
        x.with_end(end)
    }

    /// The integrand in `s`, around the analytic factor `h`.
    fn wrap<'w, H>(self, h: H) -> Wrap<'w>
    where
        H: Fn(&HoloBall, &mut dyn FnMut(&HoloBall) -> HoloBall) -> HoloBall + 'w,
    {
        Box::new(move |s, g| {
            let ld = s.real(self.log_d.clone()) - s;
            let mut v = (s.real(self.mu.clone()) * &ld).exp();
            if self.k > 0 {
                v = v * ld.powi(self.k as i64);
            }
            v * h(&self.x(s, &ld), g)
        })
    }

    /// The cut `S` (an exact float) and the rigorous tail bound beyond it.
    fn cut<H>(&self, h: &H, target: Mag, g: &mut dyn FnMut(&HoloBall) -> HoloBall) -> Result<(Float, Mag)>
    where
        H: Fn(&HoloBall, &mut dyn FnMut(&HoloBall) -> HoloBall) -> HoloBall,
    {
        let p = 64;
        let mu_f = self.mu.lower().to_f64().max(1e-300);
        let a_f = self.log_d.abs_upper().to_f64();
        let k = self.k as f64;
        // A first S from the bound with H = 1, then refined with the true H.
        let ln_target = target.log2() * std::f64::consts::LN_2;
        let mut ln_h = 0.0f64;
        let mut s = 1.0f64;
        for round in 0..40 {
            for _ in 0..4 {
                let est = mu_f * self.log_d.to_f64() + k * (a_f + s).ln() - mu_f.ln() + ln_h - ln_target;
                s = (est / mu_f).max(1.0).max((k + 1.0) / mu_f);
            }
            let s_float = Float::with_val(53, s);
            // H over x in [e, e +- d e^{-S}]
            let near = self.d.mul(&Ball::from_float(&s_float, p).neg().exp()?);
            let seg = Ball::hull(&Float::with_val(p, 0), &near.upper(), p);
            let xs = if self.sign > 0 { self.e.add(&seg) } else { self.e.sub(&seg) };
            let hv = h(&HoloBall::new(CBall::from_real(xs), Mode::Point), g);
            let big_h = hv.inner().abs_upper_mag();
            if !big_h.is_finite() {
                return Ok((s_float, Mag::inf()));
            }
            let tail = self.tail_bound(&s_float, a_f, big_h)?;
            if tail.le(&target) {
                return Ok((s_float, tail));
            }
            ln_h = big_h.log2() * std::f64::consts::LN_2 + 0.5 * round as f64;
        }
        Err(Error::Integration(IntegrationError::NotIntegrable { near: self.e.to_f64(), evaluations: 0 }))
    }

    /// `H e^{mu (log d - S)} (A + S)^k / (mu (1 - k/(mu (A + S))))`, rounded up.
    fn tail_bound(&self, s: &Float, a_f: f64, big_h: Mag) -> Result<Mag> {
        let p = 64;
        let sb = Ball::from_float(s, p);
        let mu = self.mu.set_prec(p);
        let e = mu.mul(&self.log_d.set_prec(p).sub(&sb)).exp()?;
        let a_up = Ball::from_f64(a_f.next_up(), p)?; // >= |log d|
        let u = a_up.add(&sb);
        let mut t = e.mul(&u.pow_u64(self.k as u64)).div(&mu)?;
        if self.k > 0 {
            let y = mu.mul(&u);
            let factor = Ball::one(p).sub(&Ball::from_i64(self.k as i64, p).div(&y)?);
            if !factor.is_positive() {
                return Ok(Mag::inf());
            }
            t = t.div(&factor)?;
        }
        Ok(t.abs_upper_mag().mul(big_h))
    }
}

/// The parts of `int_a^b (x-a)^alpha (b-x)^beta log^k(x-a) g(x) dx`, `a < b`.
pub(crate) fn finite_parts<'w, F>(a: &Ball, b: &Ball, weight: &Weight, prec: u32) -> Result<Box<PartsBuilder<'w, F>>>
where
    F: FnMut(&HoloBall) -> HoloBall + 'w,
{
    if !(a.upper() < b.lower()) {
        return Err(Error::Integration(IntegrationError::Endpoints { a: a.to_f64(), b: b.to_f64() }));
    }
    let (a, b, w) = (a.clone(), b.clone(), weight.clone());
    Ok(Box::new(move |tol: Mag, wp: u32, g: &mut F| parts_on(&a, &b, &w, tol, wp.max(prec.min(64)), g, Mag::ZERO)))
}

/// The parts of `int_a^inf w(x) f(x) dx` under a declared decay.
///
/// With `from = Some(R)`, the decay holds only for `x >= R`: every cut is then at least
/// `R`, and the map of an algebraic decay starts at `max(a, R)` with `[a, R]` a finite
/// piece.
///
/// With `end_log`, the map `x = c e^s` of an algebraic decay hands the integrand `x`
/// with its logarithm `log c + s` ([`MappedEnd`] at `e = 0`), and its part is not
/// declared periodic (the integrand so evaluated need not be).
pub(crate) fn infinite_parts<'w, F>(a: &Ball, weight: Option<&Weight>, decay: &Decay, from: Option<&Ball>, end_log: bool) -> Result<Box<PartsBuilder<'w, F>>>
where
    F: FnMut(&HoloBall) -> HoloBall + 'w,
{
    let p = a.prec().max(64);
    let w = match weight {
        Some(w) => {
            if w.right_singular() {
                return Err(Error::Integration(IntegrationError::WeightExponent { which: "beta (must be 0 on [a, inf))", value: w.beta.to_f64() }));
            }
            w.clone()
        }
        None => Weight::new(Ball::zero(p), Ball::zero(p), 0)?,
    };
    // the decay holds beyond r >= a
    let r = match from {
        Some(r) if r.lower() > a.upper() => Some(r.clone()),
        _ => None,
    };
    if let Decay::Algebraic { .. } = decay {
        if r.is_none() && !a.is_positive() {
            return Err(Error::Integration(IntegrationError::Decay { what: "an algebraic decay x^-p needs a > 0", value: a.to_f64() }));
        }
    }
    let (a, decay) = (a.clone(), decay.clone());
    let start = r.clone().unwrap_or_else(|| a.clone());
    Ok(Box::new(move |tol: Mag, wp: u32, g: &mut F| match &decay {
        Decay::Exponential { rate, bound } => {
            let (t, tail) = cut_exponential(&start, rate, bound, tol.mul_2exp(-2))?;
            parts_on(&a, &Ball::from_float(&t, t.prec()), &w, tol.mul_2exp(-1), wp, g, tail)
        }
        Decay::Algebraic { power, bound } => match cut_algebraic_in_x(&start, power, bound, tol.mul_2exp(-2))? {
            // a moderate cut: [a, T] as a finite range (fewer evaluations at low goals)
            Some((t, tail)) => parts_on(&a, &Ball::from_float(&t, t.prec()), &w, tol.mul_2exp(-1), wp, g, tail),
            None => algebraic_parts(&a, r.as_ref(), &w, power, bound, tol, wp, g, end_log),
        },
    }))
}

/// The parts of `int_a^inf w f` under `|w f| <= m x^{-p}`: `[a, 2a]` as a finite piece
/// when `w` is singular at `a`, then `[c, inf)` in the variable `s` of `x = c e^s`, cut at
/// `S` with the declared tail (module docs).
#[allow(clippy::too_many_arguments)]
fn algebraic_parts<'w, F>(a: &Ball, from: Option<&Ball>, w: &Weight, power: &Ball, bound: &Ball, tol: Mag, wp: u32, g: &mut F, end_log: bool) -> Result<Vec<Part<'w>>>
where
    F: FnMut(&HoloBall) -> HoloBall,
{
    let (mut parts, c, map_tol) = if let Some(r) = from {
        // the decay holds beyond R > a: [a, R] as a finite piece
        (parts_on(a, r, w, tol.mul_2exp(-1), wp, g, Mag::ZERO)?, r.clone(), tol.mul_2exp(-1))
    } else if w.left_singular() {
        // a > 0, so mid(a) > rad(a) and c = 2 mid(a) (exact) lies above the ball a.
        let c = Float::with_val(a.mid().prec() + 1, a.mid() * 2u32);
        let c = Ball::from_float(&c, c.prec());
        (parts_on(a, &c, w, tol.mul_2exp(-1), wp, g, Mag::ZERO)?, c, tol.mul_2exp(-1))
    } else {
        (Vec::new(), a.clone(), tol)
    };
    let (s, tail) = cut_algebraic(&c, power, bound, map_tol.mul_2exp(-2))?;
    let factor = right_factor(a.set_prec(wp), w.alpha.set_prec(wp), w.log_power);
    let c = c.set_prec(wp);
    let log_c = if end_log { Some(c.ln()?) } else { None };
    parts.push(Part {
        lo: Float::with_val(wp, 0),
        hi: s,
        tail,
        // e^{s + 2 pi i} = e^s: the map is periodic (cover.rs), and so is the integrand
        // unless it reads log x = log c + s, which is not
        periodic: !end_log,
        map: XMap::Exponential { c: c.to_f64() },
        wrap: Box::new(move |s: &HoloBall, g: &mut dyn FnMut(&HoloBall) -> HoloBall| {
            let x = s.real(c.clone()) * s.exp();
            let fx = match &log_c {
                // x = 0 + t, t = c e^s = exp(log c + s)
                Some(log_c) => {
                    let end = MappedEnd { e: Some(rug::Rational::new()), sign: 1, t: x.inner().clone(), log_t: (s.real(log_c.clone()) + s).into_inner() };
                    factor(&x.clone().with_end(end), g)
                }
                None => factor(&x, g),
            };
            fx * x
        }),
    });
    Ok(parts)
}

/// `S >= 1` (exact) where the declared tail `m (c e^S)^{1-p} / (p-1)` is at most
/// `target`, and that tail (rounded up). Computed in log space: `S` stays moderate
/// (`~ goal ln 2 / (p-1)`) at any goal.
fn cut_algebraic(c: &Ball, power: &Ball, bound: &Ball, target: Mag) -> Result<(Float, Mag)> {
    let p = 64;
    let q = power.lower().to_f64() - 1.0;
    let m = bound.abs_upper().to_f64().max(1e-300);
    let s = ((((m / q).ln() - ln_mag(target)) / q) - c.lower().to_f64().ln()).max(1.0);
    let (pm1, bound, ln_c) = (power.set_prec(p).add_i64(-1), bound.set_prec(p), c.set_prec(p).ln()?);
    // m exp(-(p-1)(ln c + S)) / (p-1)
    search_cut(s, target, |sb| bound.mul(&ln_c.add(sb).mul(&pm1).neg().exp()?).div(&pm1))
}

/// Below this `log2 T`, an algebraic decay is cut in `x` at `T` (`[a, T]` then costs
/// about `log2 T` bisections) instead of mapped by `x = c e^s`: at 64 bits (`T ~ 2^66`
/// for `int_1^inf dx/(1+x^2)`) the cut takes 2438 evaluations against the map's 6657;
/// at 333 bits (`T ~ 2^335`) the map takes 59400 against the cut's 79493.
const ALGEBRAIC_CUT_MAX_LOG2: f64 = 128.0;

/// `Some((T, tail))` with `T >= a + 1` (exact) where the declared tail
/// `m T^{1-p}/(p-1)` is at most `target` (rounded up; valid since `T >= a`), when
/// `log2 T <= ALGEBRAIC_CUT_MAX_LOG2`; `None` otherwise (the map is used).
fn cut_algebraic_in_x(a: &Ball, power: &Ball, bound: &Ball, target: Mag) -> Result<Option<(Float, Mag)>> {
    let q = power.lower().to_f64() - 1.0;
    let m = bound.abs_upper().to_f64().max(1e-300);
    let ln_t = ((m / q).ln() - ln_mag(target)) / q;
    if !(ln_t / std::f64::consts::LN_2 <= ALGEBRAIC_CUT_MAX_LOG2) {
        return Ok(None);
    }
    let t = ln_t.exp().max(a.upper().to_f64() + 1.0);
    let p = 64;
    let (pm1, bound) = (power.set_prec(p).add_i64(-1), bound.set_prec(p));
    search_cut(t, target, |tb| bound.mul(&tb.ln()?.mul(&pm1).neg().exp()?).div(&pm1)).map(Some)
}

/// `T >= a + 1` (exact) where the declared tail `m e^{-cT}/c` is at most `target`, and
/// that tail (rounded up).
fn cut_exponential(a: &Ball, rate: &Ball, bound: &Ball, target: Mag) -> Result<(Float, Mag)> {
    let p = 64;
    let c = rate.lower().to_f64();
    let m = bound.abs_upper().to_f64().max(1e-300);
    let t = ((m.ln() - c.ln() - ln_mag(target)) / c).max(a.upper().to_f64() + 1.0);
    let (rate, bound) = (rate.set_prec(p), bound.set_prec(p));
    search_cut(t, target, |tb| bound.mul(&rate.mul(tb).neg().exp()?).div(&rate))
}

fn ln_mag(m: Mag) -> f64 {
    m.log2() * std::f64::consts::LN_2
}

/// From the f64 estimate `t`, the first cut (an exact float, raised by 25% a step) whose
/// rigorous tail bound `tail_at(t)` is at most `target`, and that bound.
fn search_cut(mut t: f64, target: Mag, tail_at: impl Fn(&Ball) -> Result<Ball>) -> Result<(Float, Mag)> {
    for _ in 0..60 {
        if !t.is_finite() || t > 1e300 {
            break;
        }
        let tf = Float::with_val(53, t);
        let tail = tail_at(&Ball::from_float(&tf, 64))?.abs_upper_mag();
        if tail.le(&target) {
            return Ok((tf, tail));
        }
        t = t * 1.25 + 1.0;
    }
    Err(Error::Integration(IntegrationError::Decay { what: "the declared decay does not reach the tolerance at any finite cut", value: t }))
}

fn parts_on<'w, F>(a: &Ball, b: &Ball, w: &Weight, tol: Mag, wp: u32, g: &mut F, extra_tail: Mag) -> Result<Vec<Part<'w>>>
where
    F: FnMut(&HoloBall) -> HoloBall,
{
    let p = wp;
    let c = {
        let m = Float::with_val(a.mid().prec().max(b.mid().prec()) + 1, a.mid() + b.mid());
        m / 2u32
    };
    let target = tol.mul_2exp(-3);
    let mut parts = Vec::new();
    let mut endpoint_error = extra_tail;
    // left piece [a, c]
    let lf = left_factor(b.set_prec(p), w.beta.set_prec(p));
    if w.left_singular() {
        let mapped = Mapped::new(a, &c, 1, &w.alpha, w.log_power, p)?;
        let (s, tail) = mapped.cut(&lf, target, g)?;
        parts.push(Part { lo: Float::with_val(p, 0), hi: s, tail, periodic: false, map: mapped.map(), wrap: mapped.wrap(lf) });
    } else {
        endpoint_error = endpoint_error.add(end_error(a, &lf, p, g));
        parts.push(Part { lo: a.mid().clone(), hi: c.clone(), tail: Mag::ZERO, periodic: false, map: XMap::Identity, wrap: Box::new(lf) });
    }
    // right piece [c, b]
    let rf = right_factor(a.set_prec(p), w.alpha.set_prec(p), w.log_power);
    if w.right_singular() {
        let mapped = Mapped::new(b, &c, -1, &w.beta, 0, p)?;
        let (s, tail) = mapped.cut(&rf, target, g)?;
        parts.push(Part { lo: Float::with_val(p, 0), hi: s, tail, periodic: false, map: mapped.map(), wrap: mapped.wrap(rf) });
    } else {
        endpoint_error = endpoint_error.add(end_error(b, &rf, p, g));
        parts.push(Part { lo: c, hi: b.mid().clone(), tail: Mag::ZERO, periodic: false, map: XMap::Identity, wrap: Box::new(rf) });
    }
    if !endpoint_error.is_zero() {
        parts.push(Part { lo: Float::new(p), hi: Float::new(p), tail: endpoint_error, periodic: false, map: XMap::Identity, wrap: Box::new(|s, g| g(s)) });
    }
    Ok(parts)
}

/// `rad(e) sup |f|` over the endpoint's ball (zero for an exact endpoint).
fn end_error<H>(e: &Ball, h: &H, p: u32, g: &mut dyn FnMut(&HoloBall) -> HoloBall) -> Mag
where
    H: Fn(&HoloBall, &mut dyn FnMut(&HoloBall) -> HoloBall) -> HoloBall,
{
    if e.is_exact() {
        return Mag::ZERO;
    }
    let v = h(&HoloBall::new(CBall::from_real(e.set_prec(p)), Mode::Point), g);
    v.inner().abs_upper_mag().mul(e.rad_mag())
}

/// A singular end found from the integrand's expression: `|f(e + sigma t)| <= bound
/// t^power` for `0 < t <= delta` (`power > -1`, `delta` an exact power of 2).
#[derive(Clone, Debug)]
pub struct EndBound {
    /// `q > -1` (a ball that contains it).
    pub power: Ball,
    /// `|C|`.
    pub bound: Mag,
    /// `delta`, an exact power of 2.
    pub delta: Float,
}

/// The parts of `int_{points[0]}^{points[last]} f` over consecutive segments, each
/// end of a segment regular (`None`) or singular with an [`EndBound`]. Next to a
/// singular end `e` the piece `[e, e +- delta/2]` is mapped by `x = e +- d e^{-s}` (`d`
/// the piece's length, `mu = 1`: the integrand `d e^{-s} f(x)`), and cut at `S` with the
/// tail `int_0^{d e^{-S}} bound t^q dt = bound (d e^{-S})^{q+1}/(q+1)` (`d e^{-S} <=
/// delta`).
pub(crate) fn segment_parts<'w, F>(points: Vec<Ball>, ends: Vec<(Option<EndBound>, Option<EndBound>)>) -> Result<Box<PartsBuilder<'w, F>>>
where
    F: FnMut(&HoloBall) -> HoloBall + 'w,
{
    for w in points.windows(2) {
        if !(w[0].upper() < w[1].lower()) {
            return Err(Error::Integration(IntegrationError::Endpoints { a: w[0].to_f64(), b: w[1].to_f64() }));
        }
    }
    Ok(Box::new(move |tol: Mag, wp: u32, g: &mut F| {
        let n_seg = (points.len() - 1).max(1) as f64;
        let target = tol.mul_2exp(-3).div(Mag::from_f64(2.0 * n_seg));
        let mut parts = Vec::new();
        let mut endpoint_error = Mag::ZERO;
        let id = |s: &HoloBall, g: &mut dyn FnMut(&HoloBall) -> HoloBall| g(s);
        for (i, w) in points.windows(2).enumerate() {
            let (a, b) = (&w[0], &w[1]);
            let (left, right) = &ends[i];
            let prec = a.mid().prec().max(b.mid().prec()) + 64;
            let lo = match left {
                Some(eb) => {
                    let c = Float::with_val(prec, a.mid() + Float::with_val(prec, &eb.delta >> 1u32));
                    parts.push(mapped_piece(a, &c, 1, eb, target, wp)?);
                    c
                }
                None => {
                    endpoint_error = endpoint_error.add(end_error(a, &id, wp, g));
                    a.mid().clone()
                }
            };
            let hi = match right {
                Some(eb) => {
                    let c = Float::with_val(prec, b.mid() - Float::with_val(prec, &eb.delta >> 1u32));
                    parts.push(mapped_piece(b, &c, -1, eb, target, wp)?);
                    c
                }
                None => {
                    endpoint_error = endpoint_error.add(end_error(b, &id, wp, g));
                    b.mid().clone()
                }
            };
            if lo < hi {
                parts.push(Part { lo, hi, tail: Mag::ZERO, periodic: false, map: XMap::Identity, wrap: Box::new(id) });
            }
        }
        if !endpoint_error.is_zero() {
            parts.push(Part { lo: Float::new(wp), hi: Float::new(wp), tail: endpoint_error, periodic: false, map: XMap::Identity, wrap: Box::new(id) });
        }
        Ok(parts)
    }))
}

/// The mapped piece between the singular end `e` and `c` (module docs of
/// [`segment_parts`]).
fn mapped_piece<'w>(e: &Ball, c: &Float, sign: i64, eb: &EndBound, target: Mag, wp: u32) -> Result<Part<'w>> {
    let mapped = Mapped::new(e, c, sign, &Ball::zero(wp), 0, wp)?;
    let p = 64;
    let q1 = eb.power.set_prec(p).add_i64(1);
    if !q1.is_positive() {
        return Err(Error::Integration(IntegrationError::NotIntegrable { near: e.to_f64(), evaluations: 0 }));
    }
    let d_up = Ball::from_float(&mapped.d.abs_upper(), p);
    let bound = Ball::from_float(&eb.bound.to_float(), p);
    let tail_at = |s: &Ball| -> Result<Ball> {
        let small = d_up.mul(&s.neg().exp()?);
        bound.mul(&small.pow(&q1)?).div(&q1)
    };
    let q1_f = q1.lower().to_f64().max(1e-6);
    let est = ((bound.to_f64().max(1e-300) * d_up.to_f64().powf(q1_f) / q1_f).ln() - ln_mag(target)) / q1_f;
    let (s, tail) = search_cut(est.max(1.0), target, tail_at)?;
    let map = mapped.map();
    Ok(Part { lo: Float::with_val(wp, 0), hi: s, tail, periodic: false, map, wrap: mapped.wrap(|x: &HoloBall, g: &mut dyn FnMut(&HoloBall) -> HoloBall| g(x)) })
}
