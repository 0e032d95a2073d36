//! Certified integrals of parsed expressions: the one entry point behind
//! `maugis integrate`, the `integrate` request of `maugis eval` and Python's
//! `maugis.integrate`.

use super::decay::{tail_class, TailClass};
use super::finite::{integrate_finite, sum_to_goal};
use super::local::singular_candidates;
use super::oscillatory::{integrate_inverted, integrate_oscillatory};
use super::oscillatory_sum::integrate_oscillatory_sum;
use super::substitute::sqrt_substituted;
use super::Expr;
use crate::ball::{Ball, Decimal};
use crate::error::{Error, IntegrationError, Result};
use crate::quad::certified::{integrate_to_infinity, integrate_to_infinity_from, integrate_weighted, Decay, Integral, Options, Weight};

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
/// (decay classes, `docs/quadrature.md`); a declared `decay` (for `b = inf`)
/// is used instead when given. `-inf` ends are reflected (`int_{-inf}^b f(x) dx =
/// int_{-b}^inf f(-x) dx`, and `int_{-inf}^inf f = int_0^inf (f(x) + f(-x)) dx`).
///
/// Decimal inputs become balls that contain them, so the result contains the
/// integral for the numbers as typed. Reversed ranges change the sign, except with a
/// (non-trivial) weight, which needs `a < b`.
///
/// Bounded in time: the whole call (all its pieces) runs under the installed budget,
/// or under [`Budget::DEFAULT`](crate::budget::Budget::DEFAULT) counted from the call
/// when none is installed, and refuses past it with
/// [`Error::BudgetSpent`](crate::Error::BudgetSpent)
/// ([time budget](crate::quad::certified#time-budget)).
pub fn integrate_range(
    f: &Expr,
    a: &End,
    b: &End,
    weight: Option<&WeightSpec>,
    decay: Option<&DecaySpec>,
    prec: u32,
    opts: &Options,
) -> Result<Integral> {
    crate::budget::ensure(|| range(f, a, b, weight, decay, prec, opts))
}

/// [`integrate_range`] inside its budget.
fn range(f: &Expr, a: &End, b: &End, weight: Option<&WeightSpec>, decay: Option<&DecaySpec>, prec: u32, opts: &Options) -> Result<Integral> {
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
        let mut r = range(f, b, a, None, None, prec, opts)?;
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
            // square roots vanishing at a: x = a + t^2 (`substitute.rs`)
            if decay.is_none() && weight.is_none() {
                if let Some(g) = sqrt_substituted(f, a.as_rational()) {
                    if let Ok(r) = to_infinity(&g, &crate::Ball::zero(ip), None, prec, opts, 1.0) {
                        if r.goal_met {
                            return Ok(r);
                        }
                    }
                }
            }
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
        // a sum with oscillatory terms, `(1 - cos x)/x^2`: split at T, the rest's tail
        // by this function (`oscillatory_sum.rs`); a point none of the terms' routes
        // could bound leaves the integrand to the routes below
        let rest_tail = |g: &Expr, t: &crate::Ball, p: u32, o: &Options| to_infinity(g, t, None, p, o, side);
        match integrate_oscillatory_sum(f, a, prec, opts, &rest_tail) {
            Some(Err(Error::Integration(IntegrationError::NotIntegrable { .. }))) | None => {}
            Some(r) => return r,
        }
    }
    match class {
        TailClass::Decays { decay, from } => {
            // a singular candidate in [a, from] (`exp(-x) sin(x)/x` from 0): [a, from]
            // by the finite route, which finds removable and endpoint singularities
            if weight.is_none() && a.is_exact() && from.is_exact() && from.upper() > a.upper() {
                if let (Some(ar), Some(fr)) = (a.mid().to_rational(), from.mid().to_rational()) {
                    let mut candidates = Vec::new();
                    singular_candidates(f, &mut candidates);
                    if candidates.iter().any(|p| *p >= ar && *p <= fr) {
                        return sum_to_goal(prec, opts, |goal, o| {
                            let finite = integrate_finite(f, &ar, &fr, goal + 64, goal, o)?;
                            let tail = integrate_to_infinity(|x: &_| f.eval(x), &from, None, &decay, goal, o)?;
                            Ok(vec![finite, tail])
                        });
                    }
                }
            }
            let g = |x: &_| f.eval(x);
            // x's logarithm from the map of an algebraic tail (`mapped.rs`)
            let opts = opts.clone().end_log(super::mapped::reads_end_log(f));
            integrate_to_infinity_from(g, a, weight, &decay, &from, prec, &opts)
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

/// The absolute tolerance the result met, as a short decimal (4 digits, rounded up),
/// when the goal was met by it and not by the relative goal (the ball contains 0):
/// `2^-prec` times a certified bound of `int |f|` by default
/// ([`crate::quad::certified::Options::abs_tol`]). `None` otherwise.
pub fn abs_tol_text(r: &Integral) -> Option<String> {
    let t = r.abs_tol?;
    let up = rug::Float::with_val_round(24, t.to_float(), rug::float::Round::Up).0;
    Some(up.to_string_radix_round(10, Some(4), rug::float::Round::Up))
}
