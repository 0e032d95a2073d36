//! Certified integrals of parsed expressions: the one entry point behind
//! `maugis integrate`, the `integrate` request of `maugis eval` and Python's
//! `maugis.integrate`.

use super::Expr;
use crate::ball::{Ball, Decimal};
use crate::error::{Error, IntegrationError, Result};
use crate::quad::certified::{integrate, integrate_to_infinity, integrate_weighted, Decay, Integral, Options, Weight};

/// Guard bits of the balls made from decimal inputs (endpoints, exponents, decay
/// constants) over the requested precision: their radii then cost the result
/// about `2^-64` of its tolerance.
const INPUT_GUARD_BITS: u32 = 64;

/// The upper end of an integral.
#[derive(Clone, Debug, PartialEq)]
pub enum UpperLimit {
    /// A finite end, a decimal (the ball that contains it).
    Finite(Decimal),
    /// `+inf`: a semi-infinite range, which needs a declared [`DecaySpec`].
    Infinity,
}

impl UpperLimit {
    /// A decimal, or `inf` / `+inf` / `infinity` (any case).
    pub fn parse(text: &str) -> Result<UpperLimit> {
        let t = text.trim();
        let lower = t.to_ascii_lowercase();
        match lower.as_str() {
            "inf" | "+inf" | "infinity" | "+infinity" => Ok(UpperLimit::Infinity),
            "-inf" | "-infinity" => Err(Error::Integration(IntegrationError::NegativeInfinity)),
            _ => Decimal::parse(t).map(UpperLimit::Finite).map_err(|e| match e {
                Error::NotADecimal { text } => Error::Integration(IntegrationError::UpperEnd { text }),
                other => other,
            }),
        }
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
/// `w` the optional endpoint weight; `b = inf` needs `decay`.
///
/// Decimal inputs become balls that contain them, so the result contains the
/// integral for the numbers as typed. Without a (non-trivial) weight and with a
/// finite `b`, `a > b` is allowed; otherwise `a < b`.
pub fn integrate_expr(
    f: &Expr,
    a: &Decimal,
    b: &UpperLimit,
    weight: Option<&WeightSpec>,
    decay: Option<&DecaySpec>,
    prec: u32,
    opts: &Options,
) -> Result<Integral> {
    crate::error::check_prec(prec)?;
    let ip = prec.saturating_add(INPUT_GUARD_BITS);
    let a = a.to_ball(ip);
    let weight = weight.filter(|w| !w.is_trivial()).map(|w| w.to_weight(ip)).transpose()?;
    let g = |x: &_| f.eval(x);
    match (b, decay) {
        (UpperLimit::Finite(_), Some(_)) => Err(Error::Integration(IntegrationError::DecayWithFiniteEnd)),
        (UpperLimit::Finite(b), None) => {
            let b = b.to_ball(ip);
            match &weight {
                None => integrate(g, &a, &b, prec, opts),
                Some(w) => integrate_weighted(g, &a, &b, w, prec, opts),
            }
        }
        (UpperLimit::Infinity, None) => Err(Error::Integration(IntegrationError::MissingDecay)),
        (UpperLimit::Infinity, Some(d)) => {
            let decay = match d {
                DecaySpec::Exponential { rate, bound } => Decay::exponential(rate.to_ball(ip), bound.to_ball(ip))?,
                DecaySpec::Algebraic { power, bound } => Decay::algebraic(power.to_ball(ip), bound.to_ball(ip))?,
            };
            integrate_to_infinity(g, &a, weight.as_ref(), &decay, prec, opts)
        }
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
