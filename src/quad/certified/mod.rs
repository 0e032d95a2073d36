//! Certified integration in complex ball arithmetic.
//!
//! [`integrate`] returns a complex ball that provably contains `int_a^b f(x) dx`:
//! its radius covers the quadrature error, the node and weight errors, every
//! rounding, and the radii of the endpoints as given (a decimal endpoint is the ball
//! that contains it). [`integrate_weighted`] adds algebraic-logarithmic endpoint
//! singularities, certified without truncation by hand, and
//! [`integrate_to_infinity`] semi-infinite ranges with a declared decay. For integrands
//! written as expressions, `quad::expr::integrate_range` finds the decay, the singular
//! ends and oscillatory tails itself and calls these with what it proved.
//!
//! # Method
//!
//! * **Analytic pieces** (`adaptive.rs`): adaptive Gauss-Legendre on a work stack of
//!   subintervals, the degree chosen per piece as the cheapest that meets the piece's
//!   tolerance, bisection where none does; the error bound `64 M / (15 (rho - 1)
//!   rho^(2n-1))` from `M = |f|` on a Bernstein ellipse (Trefethen 2008; Petras;
//!   F. Johansson, "Numerical integration in arbitrary-precision ball arithmetic",
//!   ICMS 2018, the method of Arb's `acb_calc_integrate`). Nodes and weights are balls
//!   (`legendre.rs`), cached per degree and precision.
//! * **Covers** (`cover.rs`): where one evaluation on an ellipse's box is not finite
//!   (rectangle arithmetic on `c e^(box)` for the map of an algebraic decay), the box is
//!   covered by sub-boxes whose finite values prove holomorphy and bound `|f|` on it;
//!   one period high when the integrand is `2 pi i`-periodic in its variable.
//! * **Holomorphy that cannot be forgotten** ([`HoloBall`]): the integrand receives a
//!   value whose branch-cut functions check the cut themselves on the ellipse's box.
//!   There is no flag to forget.
//! * **Endpoint singularities** (`singular.rs`): `(x-a)^alpha (b-x)^beta log^k(x-a) g(x)`
//!   with `g` analytic, `alpha, beta > -1`. The interval is split at its midpoint; next
//!   to a singular endpoint the substitution `x = a + d e^{-s}` turns the piece into
//!   `int_0^inf d^(alpha+1) e^{-(alpha+1)s} (log d - s)^k h(a + d e^{-s}) ds`, whose
//!   integrand is analytic and decays exponentially; the range is cut at `S` with the
//!   tail bounded in closed form by `sup |h|` next to the endpoint, itself a ball
//!   evaluation. No user truncation, no user tail bound.
//! * **Semi-infinite ranges**: `[a, inf)` with a declared bound `|f(x)| <= m e^{-c x}` or
//!   `|f(x)| <= m x^{-p}` (`p > 1`) for `x >= a`. An exponential decay is cut where the
//!   declared tail is below a quarter of the tolerance; an algebraic one the same way
//!   while the cut `T ~ 2^(goal/(p-1))` has `log2 T <= 128`, and otherwise mapped by
//!   `x = c e^s` (`c = a`), which turns `x^{-p}` into `e^{-(p-1)s}`, and cut in `s` at
//!   `S ~ goal ln 2/(p-1)` with the declared tail `m (c e^S)^{1-p}/(p-1)`
//!   (`singular.rs`). The result is certified *given the declaration*, which the caller
//!   vouches for.
//! * **Precision escalation**: the working precision starts at `prec + 20` bits and is
//!   raised when rounding (cancellation), not truncation, keeps the radius above the
//!   goal.
//!
//! # Goals and limits
//!
//! The goal is met when `rad <= 2^-goal |mid|` (relative, `goal` = the requested
//! precision unless [`Options::goal_bits`] says otherwise) or `rad <= abs_tol`. When a
//! limit ([`Options::max_evaluations`], [`Options::max_depth`], the working-precision
//! cap) is reached first, the pieces left are enclosed crudely and the result comes
//! back *flagged*: [`Integral::goal_met`] is false and [`Integral::limit`] names the
//! limit. The ball is still a rigorous enclosure. An integrand that cannot be bounded
//! at all (a pole, a non-integrable singularity, an undeclared endpoint singularity)
//! gives [`IntegrationError::NotIntegrable`], which names the point.
//!
//! # Time budget
//!
//! Every entry point ([`integrate`], [`integrate_weighted`], [`integrate_to_infinity`],
//! [`integrate_to_infinity_from`], [`integrate_segments`]) answers or refuses in bounded
//! time. It runs under the budget installed by [`Budget::run`](crate::budget::Budget::run)
//! when there is one (an outer budget's deadline stands, shorter or longer), and under
//! [`Budget::DEFAULT`](crate::budget::Budget::DEFAULT) (30 s), counted from the call,
//! when there is none: a direct call needs no budget of its own to be bounded. The
//! budget is checked between the driver's attempts and between the adaptive bisection's
//! pieces, so a call overruns it by at most one piece's work (one Gauss-Legendre rule
//! and its ellipse bounds); past it the call returns [`Error::BudgetSpent`] with the
//! evaluations reached. The budget never changes a result that is returned.

pub(crate) mod adaptive;
mod cover;
mod holo;
pub(crate) mod legendre;
mod legendre_series;
mod singular;

use std::fmt;

use rug::Float;

pub use holo::HoloBall;
pub(crate) use holo::{MappedEnd, Mode};
pub use singular::{Decay, EndBound, Weight};

use crate::ball::{Ball, CBall, Mag};
pub use crate::error::IntegrationError;
use crate::error::{check_prec, Error, Result};
use adaptive::{Counted, RunLimits, Stats};

/// The default degree limit is Arb's `prec/2 + 60`, but at most this: a rule of
/// degree `n` costs about `n^2` word-size operations and `n^(3/2)` full products at
/// `prec + 0.85 n` bits on average to enclose above 8 limbs (`legendre.rs`,
/// `legendre_series.rs`), paid once per process, while bisection costs evaluations on
/// every call. At 3333 bits (2026-11-29 14:36 UTC, load 6-9, `1/(1+x^2)` on `[0, 1]`,
/// `sqrt x` on `[1, 4]`, first call / warm, wall time): the cap 512 0.15 s / 14.9 ms,
/// 0.16 s / 17.0 ms; 608 0.26 s / 10.2 ms, 0.40 s / 12.1 ms; 724 the same as 608 (no
/// piece asks more); C Arb 1.64 s / 17.5 ms, 2.28 s / 12.0 ms. `e^(-x^2)` on `[0, 2]`
/// and `x J_0(x)` on `[0, 10]` take degrees below 512 at any of these caps. Before the
/// series evaluation (when a rule of degree 608 cost 1.6 s) the cap was 512, and 362
/// before that.
const DEFAULT_MAX_DEGREE_CAP: usize = 608;

/// Builds the degree-`n` Gauss-Legendre rule with `prec`-bit node and weight balls (and
/// caches it), as the first integration at that degree and precision does: for the
/// side-by-side measurements of the first call (`examples/first_call.rs`, `rule N
/// PREC`). Not part of the API.
#[doc(hidden)]
pub fn build_gauss_legendre_rule(n: usize, prec: u32) -> Result<()> {
    legendre::rule(n, prec).map(|_| ())
}

/// The limit that stopped an integration before its goal.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[non_exhaustive]
pub enum Limit {
    /// [`Options::max_evaluations`].
    Evaluations,
    /// [`Options::max_depth`].
    Depth,
    /// The working precision reached [`Options::max_working_prec`].
    WorkingPrecision,
    /// The run was stopped early: at the rate it settled its range over the last 64th
    /// of [`Options::max_evaluations`] (at least 20000 evaluations), the rest would
    /// have taken more than four times the evaluations left.
    Projected,
}

impl fmt::Display for Limit {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Limit::Evaluations => write!(f, "the evaluation limit"),
            Limit::Depth => write!(f, "the bisection depth limit"),
            Limit::WorkingPrecision => write!(f, "the working-precision cap"),
            Limit::Projected => write!(f, "the evaluation limit (projected from the rate of progress)"),
        }
    }
}

/// Options of a certified integration. Build with [`Options::new`] and the setters.
#[derive(Debug, Clone)]
pub struct Options {
    goal_bits: Option<u32>,
    abs_tol: Option<Mag>,
    relative_only: bool,
    max_evaluations: Option<u64>,
    max_depth: Option<u32>,
    max_degree: Option<usize>,
    max_working_prec: u32,
    /// The integrand reads the logarithm of `x` on the map `x = c e^s` of an algebraic
    /// tail (`quad/expr/mapped.rs`); that map's part is then not `2 pi i`-periodic.
    end_log: bool,
}

impl Default for Options {
    fn default() -> Self {
        Options::new()
    }
}

impl Options {
    /// The defaults: relative goal = the requested precision, the default absolute
    /// tolerance for balls that contain 0 ([`Options::abs_tol`]), Arb's limits with
    /// evaluations and depth sized by the first working precision `w = prec + 20`
    /// (`1000 w + w^2` evaluations, depth `2 w`, degree `prec/2 + 60` but at most 608), working precision up to `8 prec +
    /// 256` bits.
    pub fn new() -> Options {
        Options { goal_bits: None, abs_tol: None, relative_only: false, max_evaluations: None, max_depth: None, max_degree: None, max_working_prec: 0, end_log: false }
    }

    /// For the expression integrator: its integrand evaluates `x`'s logarithm from the
    /// map of an algebraic tail (`quad/expr/mapped.rs`).
    pub(crate) fn end_log(mut self, on: bool) -> Options {
        self.end_log = on;
        self
    }

    /// Relative goal in bits (`rad <= 2^-bits |mid|`), at most [`crate::MAX_PREC`].
    pub fn goal_bits(mut self, bits: u32) -> Result<Options> {
        if bits == 0 || bits > crate::MAX_PREC {
            return Err(Error::Integration(IntegrationError::Option { what: "goal_bits must be in 1 ..= 65536" }));
        }
        self.goal_bits = Some(bits);
        Ok(self)
    }

    /// Absolute tolerance: the goal is also met when `rad <= tol`. Must be finite and `> 0`.
    /// It replaces the default absolute tolerance.
    ///
    /// **The default absolute tolerance.** Without this option, a result whose ball
    /// contains 0 also meets the goal when `rad <= 2^-goal L`, where `L` is a certified
    /// upper bound of `int |f|` along the path integrated (the sum over the final pieces
    /// of `|(hi - lo) f([lo, hi])|`, plus the bounds of the tails cut), or four times an
    /// estimate of `int |f|` where that is smaller ([`Integral::abs_scale`]). A relative goal
    /// cannot be met by an integral that is 0 (`int_{-1}^1 sin x`), and one below
    /// `2^-goal int |f|` is, at this goal, indistinguishable from 0: this is Arb's
    /// `abs_tol`, scaled to the integrand. A ball that keeps off 0 always meets the
    /// relative goal. The tolerance, when it decided, is in [`Integral::abs_tol`].
    /// [`Options::relative_only`] turns it off.
    pub fn abs_tol(mut self, tol: f64) -> Result<Options> {
        if !(tol.is_finite() && tol > 0.0) {
            return Err(Error::Integration(IntegrationError::Option { what: "abs_tol must be a finite number > 0" }));
        }
        self.abs_tol = Some(Mag::from_f64(tol));
        Ok(self)
    }

    /// No default absolute tolerance (see [`Options::abs_tol`]): the relative goal
    /// only, so an integral far below `int |f|` is refined until its ball keeps off 0
    /// (`int_{-10}^{10} sin x + e^{-200-x^2}`, 2.6e-87: 768 working bits at 64 bits).
    /// An integral that is exactly 0 then ends at a limit, flagged.
    pub fn relative_only(mut self) -> Options {
        self.relative_only = true;
        self
    }

    /// Largest number of integrand evaluations (at least 1).
    pub fn max_evaluations(mut self, n: u64) -> Result<Options> {
        if n == 0 {
            return Err(Error::Integration(IntegrationError::Option { what: "max_evaluations must be >= 1" }));
        }
        self.max_evaluations = Some(n);
        Ok(self)
    }

    /// Largest bisection depth (at most 100000).
    pub fn max_depth(mut self, depth: u32) -> Result<Options> {
        if depth > 100_000 {
            return Err(Error::Integration(IntegrationError::Option { what: "max_depth must be <= 100000" }));
        }
        self.max_depth = Some(depth);
        Ok(self)
    }

    /// Largest Gauss-Legendre degree (1 ..= 2048).
    pub fn max_degree(mut self, n: usize) -> Result<Options> {
        if !(1..=2048).contains(&n) {
            return Err(Error::Integration(IntegrationError::Option { what: "max_degree must be in 1 ..= 2048" }));
        }
        self.max_degree = Some(n);
        Ok(self)
    }

    /// Largest working precision (bits) the escalation may reach, at most
    /// [`crate::MAX_WORKING_PREC`].
    pub fn max_working_prec(mut self, bits: u32) -> Result<Options> {
        if !(2..=crate::MAX_WORKING_PREC).contains(&bits) {
            return Err(Error::Integration(IntegrationError::Option { what: "max_working_prec must be in 2 ..= 1048576" }));
        }
        self.max_working_prec = bits;
        Ok(self)
    }

    fn goal(&self, prec: u32) -> u32 {
        self.goal_bits.unwrap_or(prec)
    }

    /// The limits. Evaluations and depth are sized by the first working precision `w =
    /// prec + 20`, not the requested one: at 2 bits a depth of `2 prec = 4` turned a
    /// long range into a "not bounded" error (`1/((x-5)^2 + 0.01)` on `[1, 10^4]`),
    /// which 16 bits answered.
    fn limits(&self, prec: u32) -> RunLimits {
        let w = prec.saturating_add(20);
        let p = w as u64;
        RunLimits {
            max_evaluations: self.max_evaluations.unwrap_or(1000 * p + p * p),
            max_depth: self.max_depth.unwrap_or(2 * w).max(1),
            max_degree: self.max_degree.unwrap_or((prec as usize / 2 + 60).min(DEFAULT_MAX_DEGREE_CAP)),
        }
    }

    fn working_cap(&self, prec: u32) -> u32 {
        if self.max_working_prec > 0 {
            self.max_working_prec
        } else {
            prec.saturating_mul(8).saturating_add(256).min(crate::MAX_WORKING_PREC)
        }
    }
}

/// A certified integral.
#[derive(Debug, Clone)]
pub struct Integral {
    /// A complex ball that contains the integral.
    pub value: CBall,
    /// Whether the radius meets the goal (relative, or the absolute tolerance).
    pub goal_met: bool,
    /// The limit that stopped the integration before its goal, if any.
    pub limit: Option<Limit>,
    /// Integrand evaluations, over all attempts.
    pub evaluations: u64,
    /// Subintervals processed in the final attempt.
    pub subintervals: u64,
    /// The working precision of the final attempt (bits).
    pub working_prec: u32,
    /// The scale `L` of the default absolute tolerance `2^-goal L` ([`Options::abs_tol`]):
    /// the smaller of a certified upper bound of `int |f|` along the path integrated
    /// (the real range, the mapped pieces, the rays of an oscillatory tail, with the
    /// tails cut) and four times an estimate of it (an 8-point rule, or, for a
    /// sign-changing integrand on a plain finite range, the crude enclosure's bound: the
    /// certified bound comes from crude enclosures `|(hi - lo) f([lo, hi])|` and can be
    /// loose on wide pieces; the estimate only ever makes the tolerance smaller).
    pub abs_scale: Mag,
    /// The absolute tolerance the result met, when the goal was met by it and not by
    /// the relative goal (the ball then contains 0): the caller's [`Options::abs_tol`],
    /// or the default `2^-goal abs_scale`. `None` when the relative goal was met or not
    /// met at all.
    pub abs_tol: Option<Mag>,
}

impl Integral {
    /// The real part: the integral of a real integrand over a real range.
    pub fn real(&self) -> &Ball {
        self.value.re()
    }

    /// `log2(|mid| / rad)` of the real part: the bits it certifies.
    pub fn real_accuracy_bits(&self) -> f64 {
        self.value.re().rel_accuracy_bits()
    }
}

/// One piece of an integral in its own variable `s` over `[lo, hi]`: the integrand
/// is `wrap(s, f)`, plus a bound on what was cut away (`tail`).
pub(crate) struct Part<'w> {
    pub lo: Float,
    pub hi: Float,
    pub tail: Mag,
    /// `wrap(s + 2 pi i, f) = wrap(s, f)` (the map `x = c e^s`): covers of ellipse boxes
    /// may then be cut to one period (`cover.rs`).
    pub periodic: bool,
    /// How the part's variable maps to `x` (to name points in errors).
    pub map: XMap,
    #[allow(clippy::type_complexity)]
    pub wrap: Box<dyn Fn(&HoloBall, &mut dyn FnMut(&HoloBall) -> HoloBall) -> HoloBall + 'w>,
}

/// The substitution of a part, `x(s)`, in f64 (approximate: it names points in errors).
#[derive(Debug, Clone, Copy)]
pub(crate) enum XMap {
    /// `x = s`.
    Identity,
    /// `x = e + sign d e^{-s}` (next to a singular endpoint `e`).
    Endpoint { e: f64, d: f64, sign: f64 },
    /// `x = c e^s` (an algebraic decay to infinity).
    Exponential { c: f64 },
}

impl XMap {
    /// `x(s)`.
    pub fn to_x(self, s: f64) -> f64 {
        match self {
            XMap::Identity => s,
            XMap::Endpoint { e, d, sign } => e + sign * d * (-s).exp(),
            XMap::Exponential { c } => c * s.exp(),
        }
    }
}

/// Builds the parts for an absolute tolerance at a working precision.
pub(crate) type PartsBuilder<'w, F> = dyn Fn(Mag, u32, &mut F) -> Result<Vec<Part<'w>>> + 'w;

/// `int_a^b f(x) dx` for `f` holomorphic on a neighbourhood of `[a, b]` (or at least
/// bounded on it: the crude enclosures also settle integrable bounded singular points,
/// slowly), as a certified complex ball. `a > b` is allowed (the integral changes sign).
///
/// ```
/// use maugis::ball::Ball;
/// use maugis::quad::certified::{integrate, Options};
///
/// // int_1^4 sqrt(x) dx = 14/3
/// let (a, b) = (Ball::from_i64(1, 128), Ball::from_i64(4, 128));
/// let r = integrate(|x| x.sqrt(), &a, &b, 128, &Options::new()).unwrap();
/// assert!(r.goal_met);
/// assert!(r.real().contains(&(maugis::rug::Float::with_val(256, 14) / 3u32)));
/// ```
///
/// Bounded in time: runs under the installed budget, or under
/// [`Budget::DEFAULT`](crate::budget::Budget::DEFAULT) when none is installed, and
/// refuses past it with [`Error::BudgetSpent`]
/// ([time budget](crate::quad::certified#time-budget)).
pub fn integrate<F>(mut f: F, a: &Ball, b: &Ball, prec: u32, opts: &Options) -> Result<Integral>
where
    F: FnMut(&HoloBall) -> HoloBall,
{
    check_prec(prec)?;
    finite_ball(a, "a")?;
    finite_ball(b, "b")?;
    let (lo, hi, flip) = if a.mid() <= b.mid() { (a.clone(), b.clone(), false) } else { (b.clone(), a.clone(), true) };
    let builder = move |_tol: Mag, wp: u32, f: &mut F| -> Result<Vec<Part<'static>>> {
        let mut parts = Vec::new();
        if lo.mid() != hi.mid() {
            parts.push(Part {
                lo: lo.mid().clone(),
                hi: hi.mid().clone(),
                tail: Mag::ZERO,
                periodic: false,
                map: XMap::Identity,
                wrap: Box::new(|s: &HoloBall, f: &mut dyn FnMut(&HoloBall) -> HoloBall| f(s)),
            });
        }
        // Inexact endpoints: |int over the endpoint's ball| <= rad sup |f| there.
        let mut extra = Mag::ZERO;
        for end in [&lo, &hi] {
            if !end.is_exact() {
                let v = f(&HoloBall::new(CBall::from_real(end.set_prec(wp)), Mode::Point));
                extra = extra.add(v.inner().abs_upper_mag().mul(end.rad_mag()));
            }
        }
        if !extra.is_zero() {
            parts.push(Part { lo: Float::new(wp), hi: Float::new(wp), tail: extra, periodic: false, map: XMap::Identity, wrap: Box::new(|s, f| f(s)) });
        }
        Ok(parts)
    };
    let mut r = run(&mut f, &builder, prec, opts)?;
    if flip {
        r.value = r.value.neg();
    }
    Ok(r)
}

/// `int_a^b (x-a)^alpha (b-x)^beta log^k(x-a) g(x) dx` with `g` analytic on a
/// neighbourhood of `[a, b]` and the weight's exponents `> -1`; `a < b`. See the
/// module docs for the method: no truncation or tail bound is asked of the caller.
///
/// Bounded in time: runs under the installed budget, or under
/// [`Budget::DEFAULT`](crate::budget::Budget::DEFAULT) when none is installed, and
/// refuses past it with [`Error::BudgetSpent`]
/// ([time budget](crate::quad::certified#time-budget)).
pub fn integrate_weighted<F>(mut g: F, a: &Ball, b: &Ball, weight: &Weight, prec: u32, opts: &Options) -> Result<Integral>
where
    F: FnMut(&HoloBall) -> HoloBall,
{
    check_prec(prec)?;
    finite_ball(a, "a")?;
    finite_ball(b, "b")?;
    let builder = singular::finite_parts(a, b, weight, prec)?;
    run(&mut g, &*builder, prec, opts)
}

/// `int_a^inf w(x) f(x) dx` with an optional endpoint [`Weight`] at `a` (its `beta`
/// must be 0) and a declared [`Decay`] of the whole integrand for `x >= a`.
///
/// Bounded in time: runs under the installed budget, or under
/// [`Budget::DEFAULT`](crate::budget::Budget::DEFAULT) when none is installed, and
/// refuses past it with [`Error::BudgetSpent`]
/// ([time budget](crate::quad::certified#time-budget)).
pub fn integrate_to_infinity<F>(mut f: F, a: &Ball, weight: Option<&Weight>, decay: &Decay, prec: u32, opts: &Options) -> Result<Integral>
where
    F: FnMut(&HoloBall) -> HoloBall,
{
    check_prec(prec)?;
    finite_ball(a, "a")?;
    let builder = singular::infinite_parts(a, weight, decay, None, opts.end_log)?;
    run(&mut f, &*builder, prec, opts)
}

/// `int f` over consecutive segments `points[i] .. points[i+1]` (increasing), each end
/// regular or singular with a bound [`EndBound`] of the integrand next to it, which
/// the caller vouches for: next to a singular end the piece is mapped exponentially
/// and cut with the closed-form tail of the bound (`singular.rs`).
///
/// Bounded in time: runs under the installed budget, or under
/// [`Budget::DEFAULT`](crate::budget::Budget::DEFAULT) when none is installed, and
/// refuses past it with [`Error::BudgetSpent`]
/// ([time budget](crate::quad::certified#time-budget)).
pub fn integrate_segments<F>(mut f: F, points: Vec<Ball>, ends: Vec<(Option<EndBound>, Option<EndBound>)>, prec: u32, opts: &Options) -> Result<Integral>
where
    F: FnMut(&HoloBall) -> HoloBall,
{
    check_prec(prec)?;
    if points.len() < 2 || ends.len() + 1 != points.len() {
        return Err(Error::Integration(IntegrationError::Option { what: "integrate_segments needs n + 1 points and n pairs of ends" }));
    }
    for (i, p) in points.iter().enumerate() {
        finite_ball(p, if i == 0 { "a" } else { "b" })?;
    }
    let builder = singular::segment_parts(points, ends)?;
    run(&mut f, &*builder, prec, opts)
}

/// [`integrate_to_infinity`] with a decay that holds only for `x >= from` (`from >
/// a`): `[a, from]` is integrated as a finite range.
///
/// Bounded in time: runs under the installed budget, or under
/// [`Budget::DEFAULT`](crate::budget::Budget::DEFAULT) when none is installed, and
/// refuses past it with [`Error::BudgetSpent`]
/// ([time budget](crate::quad::certified#time-budget)).
pub fn integrate_to_infinity_from<F>(mut f: F, a: &Ball, weight: Option<&Weight>, decay: &Decay, from: &Ball, prec: u32, opts: &Options) -> Result<Integral>
where
    F: FnMut(&HoloBall) -> HoloBall,
{
    check_prec(prec)?;
    finite_ball(a, "a")?;
    finite_ball(from, "from")?;
    let builder = singular::infinite_parts(a, weight, decay, Some(from), opts.end_log)?;
    run(&mut f, &*builder, prec, opts)
}

fn finite_ball(x: &Ball, what: &'static str) -> Result<()> {
    if x.is_finite() {
        Ok(())
    } else {
        Err(Error::NonFinite { what })
    }
}

/// What one evaluation per part says about the integral's size ([`crude_magnitude`]).
enum Crude {
    /// The sum of the crude enclosures keeps off 0 within a factor 16: its lower and
    /// upper magnitudes.
    Keeps(Mag, Mag),
    /// Every part's enclosure is finite, but their sum reaches 0 (or spreads over more
    /// than a factor 16): the sum of their magnitudes and the tails, a certified upper
    /// bound of `int |f|` along the path.
    Reaches(Mag),
    /// A part's enclosure is not finite.
    Unbounded,
}

/// The magnitude from one evaluation per part: the crude enclosure `(b - a) f([a, b])`
/// of every part at the working precision `wp`, summed with the tails. Where the sum
/// keeps off zero within a factor 16 (`|upper| <= 16 |lower|`), its lower bound is a
/// magnitude of the integral that costs at most four bits of extra work (it is below
/// the integral). The enclosures are rigorous (exact widths) and kept in `crudes`, one
/// per part, for the first attempt.
fn crude_magnitude<F>(f: &mut F, parts: &[Part<'_>], wp: u32, evaluations: &mut u64, crudes: &mut Vec<Option<CBall>>) -> Crude
where
    F: FnMut(&HoloBall) -> HoloBall,
{
    let mut sum = CBall::zero(64);
    let mut l1 = Mag::ZERO;
    for part in parts {
        sum.add_error_mag(part.tail);
        l1 = l1.add(part.tail);
        if part.lo == part.hi {
            crudes.push(None);
            continue;
        }
        let seg = CBall::from_real(Ball::hull(&part.lo, &part.hi, wp));
        let v = (part.wrap)(&HoloBall::new(seg, Mode::Point), f).into_inner();
        *evaluations += 1;
        if !v.is_finite() {
            return Crude::Unbounded;
        }
        let width = adaptive::exact_diff(&part.lo, &part.hi);
        let c = v.mul_real(&Ball::from_float(&width, width.prec()));
        sum = sum.add(&c);
        l1 = l1.add(c.abs_upper_mag());
        crudes.push(Some(c));
    }
    let (lower, upper) = (sum.abs_lower_mag(), sum.abs_upper_mag());
    if !lower.is_zero() && upper.le(&lower.mul_2exp(4)) {
        Crude::Keeps(lower, upper)
    } else if l1.is_finite() {
        Crude::Reaches(l1)
    } else {
        Crude::Unbounded
    }
}

/// A rough magnitude of the integral and of `int |f|`, and whether the first is an
/// estimate of the integral (`false`: 0, its size unknown). From the crude enclosures
/// ([`crude_magnitude`]) when their sum keeps off 0; or 0 and the enclosure's certified
/// bound `L_c = |(b - a) f([a, b])| >= int |f|` when [`sign_changes`] finds the
/// integrand of opposite signs at the ends, each of size `L_c/(b - a)`, and the default absolute
/// tolerance is on ([`Options::abs_tol`]): the first tolerance is then `2^(-goal-3)
/// L_c`, as the 8-point estimate would set it up to the ratio of `L_c` to `int |f|`
/// (1.8 for `sin x` on `[-1, 1]`). Otherwise an 8-point rule on each part at 64 bits
/// (MPFR's exponent range: integrals like `e^-1010` do not underflow). It only sets the
/// tolerance and caps `L` ([`Integral::abs_scale`]); the result is checked.
///
/// The 8-point rule is skipped where the enclosure and the two end values suffice: it
/// was 8 of the 24 evaluations of `sin x` on `[-1, 1]` at 64 bits (`docs/quadrature.md`).
fn rough_magnitude<F>(f: &mut F, parts: &[Part<'_>], wp: u32, opts: &Options, evaluations: &mut u64, crudes: &mut Vec<Option<CBall>>) -> (Mag, Mag, bool)
where
    F: FnMut(&HoloBall) -> HoloBall,
{
    match crude_magnitude(f, parts, wp, evaluations, crudes) {
        Crude::Keeps(lower, upper) => return (lower, upper, true),
        Crude::Reaches(l1) if opts.abs_tol.is_none() && !opts.relative_only && sign_changes(f, parts, wp, l1, evaluations) => return (Mag::ZERO, l1, false),
        _ => {}
    }
    let Ok(rule) = legendre::rule(8, 64) else {
        return (Mag::ZERO, Mag::ZERO, true);
    };
    let (mut sum, mut l1) = (Float::new(64), Float::new(64));
    for part in parts {
        let tail = part.tail.to_float();
        if tail.is_finite() {
            l1 += &tail;
        }
        if part.lo == part.hi {
            continue;
        }
        let m = Float::with_val(64, &part.lo + &part.hi) / 2u32;
        let h = Float::with_val(64, &part.hi - &part.lo) / 2u32;
        for (x, w) in rule.nodes.iter().zip(&rule.weights) {
            for sign in [1i32, -1] {
                let t = Float::with_val(64, &m + Float::with_val(64, x.mid() * &h) * sign);
                let v = (part.wrap)(&HoloBall::new(CBall::from_real(Ball::from_float(&t, 64)), Mode::Point), f);
                *evaluations += 1;
                let z = v.inner();
                let (re, im) = (z.re().mid(), z.im().mid());
                if re.is_finite() && im.is_finite() {
                    let wh = Float::with_val(64, w.mid() * &h);
                    sum += Float::with_val(64, re * &wh);
                    l1 += Float::with_val(64, Float::with_val(64, re.hypot_ref(im)) * &wh);
                }
            }
        }
    }
    (Mag::from_float_up(&sum), Mag::from_float_up(&l1), true)
}

/// Whether a plain finite range (one part, no map, no tail) has an integrand that
/// takes both signs with magnitudes of the order of the enclosure's bound `l1`: its
/// values at the two ends (two evaluations, as points) are real balls of opposite
/// signs, each at least `l1 / (16 (b - a))` in magnitude. Then `l1` is taken to be
/// within a small factor of `int |f|` (a heuristic that only steers the tolerance).
/// A one-signed integrand whose enclosure reaches 0 only through the ball arithmetic
/// (`x^1000 e^-x` on `[0, 10^4]`: a ball around 0 of radius far above `int |f|`),
/// mapped parts and folded ranges take the 8-point estimate.
fn sign_changes<F>(f: &mut F, parts: &[Part<'_>], wp: u32, l1: Mag, evaluations: &mut u64) -> bool
where
    F: FnMut(&HoloBall) -> HoloBall,
{
    let [part] = parts else { return false };
    if !matches!(part.map, XMap::Identity) || !part.tail.is_zero() || l1.is_zero() || part.lo == part.hi {
        return false;
    }
    let width = Mag::from_float_up(&adaptive::exact_diff(&part.lo, &part.hi));
    let least = l1.mul_2exp(-4).div(width).to_float();
    let mut signs = [0i32; 2];
    for (k, end) in [&part.lo, &part.hi].into_iter().enumerate() {
        let v = (part.wrap)(&HoloBall::new(CBall::from_real(Ball::from_float(end, wp)), Mode::Point), f).into_inner();
        *evaluations += 1;
        if !v.is_finite() || !v.is_real() {
            return false;
        }
        let re = v.re();
        signs[k] = if re.upper() <= -least.clone() {
            -1
        } else if re.lower() >= least {
            1
        } else {
            return false;
        };
    }
    signs[0] != signs[1]
}

/// The absolute tolerance for a magnitude estimate: relative to the integral, but
/// never asking for more than 32 bits below `int |f|` (beyond that the goal is met by
/// the retries, on the next attempt's estimate). With the default absolute tolerance
/// ([`Options::abs_tol`]), an estimate below `2^-goal int |f|` asks for that level
/// only: the ball is then expected to contain 0 and to meet `2^-goal L`.
fn tolerance(opts: &Options, goal: u32, mag: Mag, l1: Mag) -> Mag {
    let scale = mag.max(l1.mul_2exp(-32));
    let mut rel = if !scale.is_zero() && scale.is_finite() {
        scale.mul_2exp(-(goal as i64) - 2)
    } else {
        Mag::pow2(-(goal as i64) - 32)
    };
    if opts.abs_tol.is_none() && !opts.relative_only && l1.is_finite() && !l1.is_zero() && mag.le(&l1.mul_2exp(-(goal as i64))) {
        rel = rel.max(l1.mul_2exp(-(goal as i64) - 3));
    }
    match opts.abs_tol {
        Some(t) => rel.max(t),
        None => rel,
    }
}

/// Whether a ball meets the goal, and the absolute tolerance that decided (if one
/// did): relative, the caller's absolute tolerance, or (when the ball contains 0) the
/// default `2^-goal scale` ([`Options::abs_tol`], [`Integral::abs_scale`]).
pub(crate) fn meets(v: &CBall, goal: u32, opts: &Options, scale: Mag) -> (bool, Option<Mag>) {
    let rad = v.rad_mag();
    if rad.le(&v.abs_lower_mag().mul_2exp(-(goal as i64))) {
        return (true, None);
    }
    match (opts.abs_tol, opts.relative_only) {
        (Some(t), _) => (rad.le(&t), rad.le(&t).then_some(t)),
        (None, false) => {
            let t = scale.mul_2exp(-(goal as i64));
            let met = v.contains_zero() && scale.is_finite() && rad.le(&t);
            (met, met.then_some(t))
        }
        (None, true) => (false, None),
    }
}

/// Attempts of the driver before the last enclosure is returned flagged.
const MAX_ATTEMPTS: usize = 8;

/// The driver of every public entry point, under the installed time budget or
/// [`Budget::DEFAULT`](crate::budget::Budget::DEFAULT) from now when none is installed
/// (module docs, "Time budget").
fn run<F>(f: &mut F, builder: &PartsBuilder<'_, F>, prec: u32, opts: &Options) -> Result<Integral>
where
    F: FnMut(&HoloBall) -> HoloBall,
{
    crate::budget::ensure(|| run_in_budget(f, builder, prec, opts))
}

/// The driver: tolerance from a rough estimate, the adaptive integration of every
/// part, and escalation (a new tolerance from the enclosure, or more working
/// precision when rounding dominates) until the goal is met or a limit is reached.
fn run_in_budget<F>(f: &mut F, builder: &PartsBuilder<'_, F>, prec: u32, opts: &Options) -> Result<Integral>
where
    F: FnMut(&HoloBall) -> HoloBall,
{
    let goal = opts.goal(prec);
    let limits = opts.limits(prec);
    let cap = opts.working_cap(prec);
    let mut wp = (prec + 20).min(cap);
    let first_wp = wp;
    let mut evaluations = 0u64;
    // First estimate, with parts built for a provisional tolerance. The crude
    // enclosures of its parts serve the first attempt where its parts are the same.
    let provisional = builder(Mag::pow2(-(goal as i64)), wp, f)?;
    let mut crudes = Vec::new();
    let (mut mag, mut l1, mut estimated) = rough_magnitude(f, &provisional, wp, opts, &mut evaluations, &mut crudes);
    let l1_estimate = l1;
    let mut reusable: Vec<Option<CBall>> =
        provisional.iter().zip(crudes.into_iter().chain(std::iter::repeat(None))).map(|(p, c)| c.filter(|_| p.lo != p.hi)).collect();
    let spans: Vec<(Float, Float)> = provisional.iter().map(|p| (p.lo.clone(), p.hi.clone())).collect();
    drop(provisional);
    let mut last: Option<Integral> = None;
    // log2 of a factor on the tolerance, lowered when truncation kept the goal out of reach
    let mut tol_shift: i64 = 0;
    // the same while the enclosures contain 0 (the integral's size is unknown)
    let mut zero_shift: i64 = 0;
    let mut zero_attempts = 0u32;
    for _attempt in 0..MAX_ATTEMPTS {
        // the installed time budget (crate::budget), between attempts
        crate::budget::check_elapsed("certified quadrature (attempts)", 0.0, crate::error::Reached::Evaluations { count: evaluations })?;
        let tol = tolerance(opts, goal, mag, l1).mul_2exp(tol_shift + zero_shift);
        let parts = builder(tol, wp, f)?;
        let n_parts = parts.iter().filter(|p| p.lo != p.hi).count().max(1) as u64;
        let mut total = CBall::zero(wp);
        let mut truncation = Mag::ZERO;
        let mut l1_bound = Mag::ZERO;
        let mut stats = Stats::default();
        let mut limit = None;
        let same_parts = parts.len() == spans.len() && parts.iter().zip(&spans).all(|(p, (lo, hi))| p.lo == *lo && p.hi == *hi);
        for (i, part) in parts.iter().enumerate() {
            if part.lo != part.hi {
                // the crude enclosure of the estimate, once, at the precision it was made at
                let first = if same_parts && wp == first_wp { reusable.get_mut(i).and_then(Option::take) } else { None };
                let mut g = |z: &HoloBall| (part.wrap)(z, f).into_inner();
                let mut counted = Counted { f: &mut g, stats };
                let part_tol = tol.mul_2exp(-1).div(Mag::from_f64(n_parts as f64));
                let out = adaptive::adaptive(&mut counted, &part.lo, &part.hi, wp, part_tol, goal as i64 + 3 - tol_shift - zero_shift, limits, first, part.periodic)?;
                stats = counted.stats;
                if !out.value.is_finite() {
                    return Err(adaptive::unbounded_error(out.unbounded_near.map(|s| part.map.to_x(s)), &stats));
                }
                if out.limit.is_some() {
                    limit = out.limit;
                }
                total = total.add(&out.value);
                truncation = truncation.add(out.truncation);
                l1_bound = l1_bound.add(out.l1);
            }
            if !part.tail.is_finite() {
                return Err(adaptive::unbounded_error(Some(part.map.to_x(part.lo.to_f64())), &stats));
            }
            total.add_error_mag(part.tail);
            truncation = truncation.add(part.tail);
            l1_bound = l1_bound.add(part.tail);
        }
        evaluations += stats.evaluations;
        let abs_scale = if l1_estimate.is_zero() || !l1_estimate.is_finite() {
            l1_bound
        } else {
            let four = l1_estimate.mul_2exp(2);
            if l1_bound.le(&four) { l1_bound } else { four }
        };
        let (goal_met, abs_tol) = meets(&total, goal, opts, abs_scale);
        let result = Integral { value: total, goal_met, limit, evaluations, subintervals: stats.subintervals, working_prec: wp, abs_scale, abs_tol };
        if goal_met {
            return Ok(result);
        }
        let new_mag = result.value.abs_lower_mag();
        if limit.is_some() {
            // A limit with a tolerance set from a rough estimate far below the
            // integral's size (a long range sampled where the integrand is small):
            // retry once the enclosure tells the size; otherwise stop, flagged.
            // (Not when the first tolerance came from the enclosures' bound of int |f|,
            // which is above the integral's size.)
            if estimated && mag.mul_2exp(10).le(&new_mag) && !new_mag.le(&mag.mul_2exp(10)) && tol_shift == 0 {
                mag = new_mag;
                l1 = l1.max(new_mag);
                last = Some(result);
                continue;
            }
            return Ok(result);
        }
        // Not met: rounding or truncation?
        let rad = result.value.rad_mag();
        let rounding_dominates = truncation.mul_2exp(1).le(&rad);
        if new_mag.is_zero() {
            // The enclosure still contains 0: the integral is small against int |f|
            // (cancellation). Ask for more on both counts, doubling the step.
            let step = (goal / 2).max(32) << zero_attempts.min(8);
            zero_attempts += 1;
            zero_shift -= step as i64;
            if wp >= cap && zero_attempts > 2 {
                return Ok(Integral { limit: Some(Limit::WorkingPrecision), ..result });
            }
            wp = wp.saturating_add(step).min(cap);
        } else {
            if rounding_dominates {
                if wp >= cap {
                    return Ok(Integral { limit: Some(Limit::WorkingPrecision), ..result });
                }
                // Bits lost to cancellation, plus a margin.
                let lost = (rad.log2() + goal as f64 - new_mag.log2()).clamp(16.0, 1e6) as u32;
                wp = wp.saturating_add(lost + 16).min(cap);
            } else {
                // Truncation: many pieces each within their share. Ask each for the
                // bits missing, and two more.
                let wanted = new_mag.mul_2exp(-(goal as i64));
                let missing = (rad.log2() - wanted.log2()).clamp(0.0, 1e6).ceil() as i64;
                tol_shift -= missing + 2;
            }
            mag = new_mag;
            estimated = true;
            l1 = if l1.le(&new_mag.mul_2exp(32)) { l1 } else { new_mag.mul_2exp(32) };
            // The size is known now: the shift that stood in for it goes.
            zero_shift = 0;
        }
        last = Some(result);
    }
    // MAX_ATTEMPTS without meeting the goal: the last enclosure, flagged.
    last.ok_or(Error::Internal { what: "certified integration ran no attempt".into() })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::budget::{installed_limit, Budget};
    use std::time::Duration;

    /// Every entry point, called directly (no [`Budget::run`] around it), runs its
    /// integrand under [`Budget::DEFAULT`]; inside an explicit budget, under that one
    /// (an outer deadline stands, even one later than the default's); and leaves no
    /// budget installed behind it.
    #[test]
    fn a_direct_call_runs_under_the_default_budget() {
        let ball = |n: i64| Ball::from_i64(n, 64);
        let seen = std::cell::Cell::new(None);
        let rec = |x: &HoloBall| {
            seen.set(Some(installed_limit()));
            (-x).exp()
        };
        let decay = || Decay::exponential(ball(1), ball(1)).unwrap();
        let weight = Weight::new(Ball::one(64).mul_pow2(-1).neg(), Ball::zero(64), 0).unwrap();
        let o = Options::new();
        let calls: Vec<(&str, Box<dyn Fn() -> Result<Integral> + '_>)> = vec![
            ("integrate", Box::new(|| integrate(rec, &ball(0), &ball(1), 64, &o))),
            ("integrate_weighted", Box::new(|| integrate_weighted(rec, &ball(0), &ball(1), &weight, 64, &o))),
            ("integrate_to_infinity", Box::new(|| integrate_to_infinity(rec, &ball(0), None, &decay(), 64, &o))),
            ("integrate_to_infinity_from", Box::new(|| integrate_to_infinity_from(rec, &ball(0), None, &decay(), &ball(2), 64, &o))),
            ("integrate_segments", Box::new(|| integrate_segments(rec, vec![ball(0), ball(1), ball(2)], vec![(None, None), (None, None)], 64, &o))),
        ];
        for (name, call) in &calls {
            assert_eq!(installed_limit(), None);
            seen.set(None);
            let r = call().unwrap_or_else(|e| panic!("{name}: {e}"));
            assert!(r.goal_met, "{name}");
            assert_eq!(seen.get(), Some(Some(Duration::from_secs_f64(Budget::DEFAULT.seconds()))), "{name}: the default is installed");
            assert_eq!(installed_limit(), None, "{name}: nothing is left installed");
            // an explicit budget stands, longer than the default as shorter
            for secs in [600.0, 5.0] {
                seen.set(None);
                Budget::from_secs_f64(secs).unwrap().run(|| call().unwrap());
                let limit = seen.get().flatten().unwrap_or_else(|| panic!("{name}: no budget inside"));
                assert!(limit <= Duration::from_secs_f64(secs) && limit > Duration::from_secs_f64(secs - 1.0), "{name}: {limit:?} under {secs} s");
            }
        }
    }
}
