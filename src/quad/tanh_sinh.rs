//! Arbitrary-precision tanh-sinh (double-exponential) quadrature on `[a, b]`.
//!
//! # Method
//!
//! The substitution `x = c + r g(t)`, `g(t) = tanh(π/2 sinh t)`, `c = (a+b)/2`,
//! `r = (b-a)/2` [Takahasi & Mori 1974] turns `∫_a^b f` into
//! `r ∫_{-∞}^{∞} f(x(t)) g'(t) dt`, `g'(t) = (π/2) cosh t / cosh^2(π/2 sinh t)`,
//! whose integrand decays double-exponentially; the trapezoidal rule with step
//! `h` then converges like `exp(-C/h)` (about doubling the correct digits
//! every time `h` is halved) for integrands analytic in the open interval,
//! including integrable algebraic or logarithmic endpoint singularities.
//!
//! **Levels.** Level `k` uses `h = 2^-k` and sums `T_k = r h Σ_j w_j f(x_j)`
//! over `t_j = j h`; level `k >= 1` only evaluates the new odd `j` and reuses
//! the sum of level `k - 1` [Bailey, Jeyabalan & Li 2005].
//!
//! **Nodes without cancellation.** With `u = π/2 sinh t` and `e = exp(-2u)`,
//! the distance of `g(t)` from `±1` is `δ = 1 - tanh u = 2e/(1+e)` and the
//! weight is `g' = (π/2) cosh t · 4e/(1+e)^2`, both computed from `e` without
//! subtraction. The node near `b` has `b - x = r δ` and `x - a = (b-a) - r δ`,
//! the node near `a` the mirror image, so the distance to the nearer end
//! keeps full relative precision even when `x` itself rounds to the endpoint.
//! `δ` and the weights are computed with [`NODE_GUARD_BITS`] extra bits
//! (`e` amplifies the rounding of `u` by `2u`).
//! [`integrate_with_complements`] passes these distances to the integrand
//! (write `(1-x)^{-3/4}` as `bx^{-3/4}`, `ln x` on `[0, 1]` as `ln xa`).
//! [`integrate`] passes only `x` and never evaluates at a node whose `x` rounds
//! onto an endpoint (that part of the tail then enters the error estimate).
//!
//! **Truncation of `Σ_j`.** Walking outwards on each side separately, a side
//! stops after [`TAIL_RUN`] consecutive nodes where both the weight has
//! underflowed, `g'(t_j) <= 2^-wp`, and the term is negligible,
//! `|w_j f(x_j)| <= 2^-wp Σ|w f|`. The first condition alone (weights below
//! `2^-wp`) is right for bounded integrands but would cut `(1-x)^{-3/4}`,
//! whose terms behave like `δ^{1/4}`, at `2^{-wp/4}`; the second condition
//! lets the sum run on until singular terms have decayed. A hard stop at
//! `δ < 2^{-TAIL_DEPTH_FACTOR · wp}` bounds the work; reaching it (or an
//! endpoint-rounded node in [`integrate`]) adds `r h |last term|` to the error
//! estimate.
//!
//! **Error estimate** [Bailey, Jeyabalan & Li 2005, Sec. 3]. With
//! `e1 = |T_k - T_{k-1}|`, `e2 = |T_k - T_{k-2}|`, measured relative to
//! `|T_k|` in `log2` as `l1`, `l2 < 0`: when the levels converge (`l1 < l2`)
//! the quadratic-convergence heuristic predicts the error of `T_k` as
//! `2^(θ max(l1^2/l2, 2 l1))` relative (digits double per level), damped by
//! `θ = CONVERGENCE_DAMPING = 15/16` because the observed gain per level can
//! fall a little short of 2; otherwise the estimate is `e1`. It is raised to
//! at least the rounding level `2^-wp √N ∫|f|` (`N` evaluations, random-walk
//! accumulation) and to the truncation estimate. **This is an estimate, not a
//! bound.**
//!
//! **Stopping.** At level `k >= MIN_LEVEL`, stop when the estimate is
//! `<= max(2^-prec |T_k|, abs_tol)`. Past `max_level`:
//! [`Error::NoConvergence`] (`terms` = evaluations). If the rounding level
//! alone exceeds the target (the integral is much smaller than `∫|f|`,
//! cancellation beyond `guard_bits`), more levels cannot help:
//! [`Error::PrecisionExhausted`], raise `guard_bits`.
//!
//! Working precision `wp = prec + guard_bits`. The returned value is `T_k`
//! rounded to `prec` bits; that rounding is added to the error estimate.
//! The integrand should return values accurate to about the precision of the
//! `x` it receives (`wp` bits): noise at `2^-prec` in `f` shows up as
//! non-convergence of the levels.
//!
//! **Targets.** The default is purely relative (`abs_tol = 0`); an integral
//! that is exactly zero (odd integrand on a symmetric interval) then cannot
//! meet it: set `abs_tol` when the value may vanish.
//!
//! # References
//!
//! * H. Takahasi, M. Mori, "Double exponential formulas for numerical
//!   integration", Publ. RIMS Kyoto Univ. 9 (1974) 721–741.
//! * D. H. Bailey, K. Jeyabalan, X. S. Li, "A comparison of three
//!   high-precision quadrature schemes", Experimental Math. 14 (2005) 317–329.

use rug::float::{Constant, Round};
use rug::ops::AssignRound;
use rug::Float;

use crate::error::{check_prec, Error, Result};
use crate::quad::QuadEstimateMp;
use crate::special::check_finite;
use crate::MAX_WORKING_PREC;

/// Default target precision (bits).
pub const DEFAULT_PREC: u32 = 128;
/// Default guard bits (working precision = `prec + guard_bits`): covers the
/// rounding of a sum of a few thousand terms and moderate cancellation.
pub const DEFAULT_GUARD_BITS: u32 = 32;
/// Default level cap: `h = 2^-12`, about `2^12 · 2 · t_max ≈ 40 000` nodes,
/// enough for several thousand bits on analytic integrands.
pub const DEFAULT_MAX_LEVEL: u32 = 12;
/// Largest level accepted (`h = 2^-20`, millions of evaluations).
pub const MAX_LEVEL_CAP: u32 = 20;
/// Smallest level at which convergence may be declared: the heuristic needs
/// three levels in the asymptotic regime, and levels 0–2 (`h >= 1/4`) are
/// too coarse to be in it. Levels 0–3 cost about 80 evaluations.
pub const MIN_LEVEL: u32 = 3;
/// Consecutive negligible terms that end one side of the trapezoidal sum.
pub const TAIL_RUN: u32 = 2;
/// Hard stop of the node walk at `δ < 2^{-TAIL_DEPTH_FACTOR · wp}`: resolves
/// endpoint singularities `|x - a|^α` down to `α >= -1 + 1/TAIL_DEPTH_FACTOR`
/// (the term then behaves like `δ^{1+α}`), at about
/// `log(TAIL_DEPTH_FACTOR)/h` extra nodes per side where needed.
pub const TAIL_DEPTH_FACTOR: u32 = 64;
/// Largest `guard_bits` accepted.
pub const MAX_GUARD_BITS: u32 = 1 << 16;

/// Extra bits for the nodes and weights. The weight `~ exp(-2u)` amplifies the
/// rounding of `u = π/2 sinh t` by `2u` (up to ~50 where weights still
/// matter), which at `wp` bits put the sum ~10 bits above `2^-wp` in tests;
/// 16 extra bits make node errors negligible next to the sum's own rounding.
pub const NODE_GUARD_BITS: u32 = 16;
/// Damping of the predicted error exponent. The heuristic assumes the correct
/// bits double per level; on the test integrals the gain factor at the last
/// level was between 1.93 and 2.3, so the prediction is scaled by 15/16
/// (covers a factor down to 1.875) before it is compared with the target.
pub const CONVERGENCE_DAMPING: f64 = 15.0 / 16.0;

/// Precision of the error bookkeeping (`L1`, estimates): a double's worth.
const EST_PREC: u32 = 53;

/// Targets and limits of [`integrate`] / [`integrate_with_complements`].
#[derive(Debug, Clone, PartialEq)]
pub struct TanhSinhOptions {
    /// Target relative precision in bits, and the precision of the result.
    pub prec: u32,
    /// Extra working bits.
    pub guard_bits: u32,
    /// Absolute target (`>= 0`; zero means relative only). It cannot go below
    /// the rounding level `2^-wp √N ∫|f|` (see the module docs).
    pub abs_tol: Float,
    /// Largest level `k` (`h = 2^-k`), in `MIN_LEVEL ..= MAX_LEVEL_CAP`.
    pub max_level: u32,
}

impl Default for TanhSinhOptions {
    fn default() -> Self {
        TanhSinhOptions::with_prec(DEFAULT_PREC)
    }
}

impl TanhSinhOptions {
    /// Defaults with target precision `prec` bits.
    pub fn with_prec(prec: u32) -> Self {
        TanhSinhOptions {
            prec,
            guard_bits: DEFAULT_GUARD_BITS,
            abs_tol: Float::new(EST_PREC),
            max_level: DEFAULT_MAX_LEVEL,
        }
    }

    /// Working precision, after validation.
    fn validate(&self) -> Result<u32> {
        check_prec(self.prec)?;
        if self.guard_bits > MAX_GUARD_BITS {
            return Err(Error::IntegerOutOfRange { arg: "guard_bits", value: self.guard_bits as i64, min: 0, max: MAX_GUARD_BITS as i64 });
        }
        let wp = self.prec.saturating_add(self.guard_bits);
        if wp > MAX_WORKING_PREC {
            return Err(Error::Precision { requested: wp as u64 });
        }
        if !(MIN_LEVEL..=MAX_LEVEL_CAP).contains(&self.max_level) {
            return Err(Error::IntegerOutOfRange {
                arg: "max_level",
                value: self.max_level as i64,
                min: MIN_LEVEL as i64,
                max: MAX_LEVEL_CAP as i64,
            });
        }
        check_finite(&self.abs_tol, "abs_tol")?;
        if self.abs_tol.is_sign_negative() && !self.abs_tol.is_zero() {
            return Err(Error::OutOfRange { arg: "abs_tol", value: self.abs_tol.to_f64(), allowed: crate::error::Interval::at_least(0.0) });
        }
        Ok(wp)
    }
}

/// `∫_a^b f(x) dx` for an integrand of `x` alone (see the module docs; for
/// endpoint singularities prefer [`integrate_with_complements`]).
pub fn integrate<F>(mut f: F, a: &Float, b: &Float, opts: &TanhSinhOptions) -> Result<QuadEstimateMp>
where
    F: FnMut(&Float) -> Result<Float>,
{
    run(&mut |x: &Float, _: &Float, _: &Float| f(x), a, b, opts, true)
}

/// `∫_a^b f dx` where the integrand is called as `f(x, x - lo, hi - x)` with
/// `lo = min(a, b)`, `hi = max(a, b)`; the smaller of the two distances is
/// accurate to full relative precision (the other to full absolute precision).
pub fn integrate_with_complements<F>(mut f: F, a: &Float, b: &Float, opts: &TanhSinhOptions) -> Result<QuadEstimateMp>
where
    F: FnMut(&Float, &Float, &Float) -> Result<Float>,
{
    run(&mut f, a, b, opts, false)
}

/// One abscissa-weight pair for `t = j 2^-k >= 0` on `[-1, 1]`.
struct Node {
    /// `1 - g(t)`, in `(0, 1]`.
    delta: Float,
    /// `g'(t)`.
    weight: Float,
}

/// The node at precision `np`.
fn node(j: u64, k: u32, half_pi: &Float, np: u32) -> Node {
    if j == 0 {
        return Node { delta: Float::with_val(np, 1), weight: half_pi.clone() };
    }
    let mut t = Float::with_val(np, j);
    t >>= k;
    let (sinh, cosh) = t.sinh_cosh(Float::new(np));
    let u = Float::with_val(np, &sinh * half_pi);
    let e = Float::with_val(np, -(u * 2u32)).exp();
    let one_plus_e = Float::with_val(np, &e + 1u32);
    let delta = Float::with_val(np, &e * 2u32) / &one_plus_e;
    let mut weight = Float::with_val(np, &cosh * half_pi) * (e * 4u32);
    weight /= one_plus_e.square();
    Node { delta, weight }
}

/// `log2 |x|` as f64 (`-inf` for zero).
fn log2_abs(x: &Float) -> f64 {
    if x.is_zero() {
        return f64::NEG_INFINITY;
    }
    let (m, e) = x.to_f64_exp();
    m.abs().log2() + e as f64
}

/// Rounds `x` upward to [`EST_PREC`] bits, absolute value.
fn est_abs(x: &Float) -> Float {
    let mut r = Float::new(EST_PREC);
    r.assign_round(x.abs_ref(), Round::Up);
    r
}

/// Which end of the interval a node lies near.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Side {
    Upper = 0,
    Lower = 1,
}

/// Walk state of one side within one level.
struct SideWalk {
    side: Side,
    active: bool,
    small_run: u32,
    last_term: Float,
}

/// The interval and its precomputed lengths.
struct Interval<'a> {
    lo: &'a Float,
    hi: &'a Float,
    len: Float,
    r: Float,
}

/// Evaluates the node of `side` at distance `δ`; `None` when skipping
/// endpoint-rounded nodes and `x` rounds onto the endpoint.
fn eval_side<F>(f: &mut F, iv: &Interval, side: Side, nd: &Node, wp: u32, skip_endpoints: bool) -> Result<Option<Float>>
where
    F: FnMut(&Float, &Float, &Float) -> Result<Float>,
{
    let near = Float::with_val(wp, &iv.r * &nd.delta);
    let far = Float::with_val(wp, &iv.len - &near);
    let (x, xa, bx) = match side {
        Side::Upper => (Float::with_val(wp, iv.hi - &near), far, near),
        Side::Lower => (Float::with_val(wp, iv.lo + &near), near, far),
    };
    if skip_endpoints && (x == *iv.lo || x == *iv.hi) {
        return Ok(None);
    }
    let y = f(&x, &xa, &bx)?;
    if !y.is_finite() {
        return Err(Error::NonFinite { what: "integrand value" });
    }
    Ok(Some(Float::with_val(wp, &y * &nd.weight)))
}

fn run<F>(f: &mut F, a: &Float, b: &Float, opts: &TanhSinhOptions, skip_endpoints: bool) -> Result<QuadEstimateMp>
where
    F: FnMut(&Float, &Float, &Float) -> Result<Float>,
{
    let wp = opts.validate()?;
    check_finite(a, "lower bound a")?;
    check_finite(b, "upper bound b")?;
    let prec = opts.prec;
    if a == b {
        return Ok(QuadEstimateMp { value: Float::new(prec), error_estimate: Float::new(EST_PREC), evaluations: 0 });
    }
    let negate = a > b;
    let (lo, hi) = if negate { (b, a) } else { (a, b) };
    let len = Float::with_val(wp, hi - lo);
    if !len.is_finite() {
        return Err(Error::Overflow { what: "tanh-sinh interval length".into() });
    }
    let r = Float::with_val(wp, &len / 2u32);
    let iv = Interval { lo, hi, len, r };
    let node_prec = wp + NODE_GUARD_BITS;
    let half_pi = Float::with_val(node_prec, Constant::Pi) / 2u32;

    // 2^-wp, the negligible-term / underflowed-weight threshold.
    let mut eps_wp = Float::with_val(EST_PREC, 1);
    eps_wp >>= wp as i32;
    // Hard stop of the walk: δ < 2^{-TAIL_DEPTH_FACTOR wp}.
    let mut delta_min = Float::with_val(EST_PREC, 1);
    delta_min >>= (TAIL_DEPTH_FACTOR as u64 * wp as u64).min(i32::MAX as u64 / 2) as i32;
    // The same stop in t (plus one step), as a loop bound independent of rounding:
    // δ ≈ 2 exp(-π sinh t).
    let depth_bits = TAIL_DEPTH_FACTOR as f64 * wp as f64;
    let t_stop = (depth_bits * std::f64::consts::LN_2 / std::f64::consts::PI).asinh() + 1.0;

    let mut sum = Float::new(wp); // Σ_j w_j f(x_j) over all levels
    let mut l1 = Float::new(EST_PREC); // Σ_j |w_j f(x_j)|
    let mut evaluations: u64 = 0;
    let mut history: Vec<Float> = Vec::new(); // T_0, T_1, ...
    // |w f| at the outermost node evaluated so far on each side (upper, lower),
    // carried across levels: the truncation estimate when a walk is cut short.
    let mut edge_terms = [Float::new(EST_PREC), Float::new(EST_PREC)];

    for k in 0..=opts.max_level {
        let (j0, step) = if k == 0 { (1u64, 1u64) } else { (1u64, 2u64) };
        if k == 0 {
            let nd = node(0, 0, &half_pi, node_prec);
            let Some(tau) = eval_side(f, &iv, Side::Upper, &nd, wp, skip_endpoints)? else {
                return Err(Error::IntervalTooNarrow { prec: wp });
            };
            evaluations += 1;
            let tau_abs = est_abs(&tau);
            edge_terms = [tau_abs.clone(), tau_abs.clone()];
            l1 += &tau_abs;
            sum += &tau;
        }
        let mut sides = [Side::Upper, Side::Lower].map(|side| SideWalk {
            side,
            active: true,
            small_run: 0,
            last_term: edge_terms[side as usize].clone(),
        });
        let mut truncation_terms = Float::new(EST_PREC);
        let j_max = (t_stop * (1u64 << k) as f64).ceil() as u64 + 1;
        let mut j = j0;
        while sides.iter().any(|s| s.active) {
            if j > j_max {
                // Unreachable in exact arithmetic (δ < delta_min first); a guard.
                for s in sides.iter_mut().filter(|s| s.active) {
                    truncation_terms = truncation_terms.max(&s.last_term);
                    s.active = false;
                }
                break;
            }
            let nd = node(j, k, &half_pi, node_prec);
            if nd.delta.is_zero() || nd.delta < delta_min {
                for s in sides.iter_mut().filter(|s| s.active) {
                    truncation_terms = truncation_terms.max(&s.last_term);
                    s.active = false;
                }
                break;
            }
            let weight_small = nd.weight <= eps_wp;
            for s in sides.iter_mut().filter(|s| s.active) {
                let Some(tau) = eval_side(f, &iv, s.side, &nd, wp, skip_endpoints)? else {
                    truncation_terms = truncation_terms.max(&s.last_term);
                    s.active = false;
                    continue;
                };
                evaluations += 1;
                let tau_abs = est_abs(&tau);
                l1 += &tau_abs;
                sum += &tau;
                let negligible = weight_small && tau_abs <= Float::with_val(EST_PREC, &l1 * &eps_wp);
                s.small_run = if negligible { s.small_run + 1 } else { 0 };
                if s.small_run >= TAIL_RUN {
                    s.active = false;
                }
                s.last_term = tau_abs;
            }
            j += step;
        }
        for s in &sides {
            edge_terms[s.side as usize] = s.last_term.clone();
        }

        // T_k = r h Σ, h = 2^-k.
        let mut t_k = Float::with_val(wp, &sum * &iv.r);
        t_k >>= k as i32;
        let mut l1_k = Float::with_val(EST_PREC, &l1 * &iv.r);
        l1_k >>= k as i32;
        let mut trunc = Float::with_val(EST_PREC, &truncation_terms * &iv.r);
        trunc >>= k as i32;
        history.push(t_k.clone());
        if k < MIN_LEVEL {
            continue;
        }

        let estimate = level_estimate(&history, &l1_k, &trunc, evaluations, wp);
        let mut target = est_abs(&t_k);
        target >>= prec as i32;
        if opts.abs_tol > target {
            target = est_abs(&opts.abs_tol);
        }
        if !t_k.is_finite() || !estimate.total.is_finite() {
            return Err(Error::Overflow { what: "tanh-sinh sum".into() });
        }
        if estimate.total <= target {
            let mut value = Float::with_val(prec, &t_k);
            // The final rounding to `prec` bits is part of the returned error.
            let rounding = est_abs(&Float::with_val(wp, &value - &t_k));
            let mut error_estimate = Float::new(EST_PREC);
            error_estimate.assign_round(&estimate.total + &rounding, Round::Up);
            if negate {
                value = -value;
            }
            return Ok(QuadEstimateMp { value, error_estimate, evaluations });
        }
        if estimate.rounding > target {
            return Err(Error::PrecisionExhausted { function: "tanh_sinh", working_prec: wp });
        }
    }
    Err(Error::NoConvergence { function: "tanh_sinh", terms: evaluations })
}

/// The parts of the error estimate of the last level in `history`.
struct LevelEstimate {
    /// `max(convergence, rounding, truncation)`.
    total: Float,
    /// `2^-wp √N ∫|f|`.
    rounding: Float,
}

/// The error estimate of the module docs for `T_k = history[k]` (`k >= 2`).
fn level_estimate(history: &[Float], l1_k: &Float, trunc: &Float, evaluations: u64, wp: u32) -> LevelEstimate {
    let k = history.len() - 1;
    let t_k = &history[k];
    let e1 = est_abs(&Float::with_val(t_k.prec(), t_k - &history[k - 1]));
    let e2 = est_abs(&Float::with_val(t_k.prec(), t_k - &history[k - 2]));
    let scale = if t_k.is_zero() { l1_k.clone() } else { est_abs(t_k) };
    let convergence = if e1.is_zero() {
        Float::new(EST_PREC)
    } else {
        let l1 = log2_abs(&e1) - log2_abs(&scale);
        let l2 = log2_abs(&e2) - log2_abs(&scale);
        if l2 < 0.0 && l1 < l2 && scale.is_finite() && !scale.is_zero() {
            let l = CONVERGENCE_DAMPING * (l1 * l1 / l2).max(2.0 * l1);
            Float::with_val(EST_PREC, l).exp2() * &scale
        } else {
            e1
        }
    };
    let mut rounding = Float::with_val(EST_PREC, l1_k * (evaluations as f64).sqrt());
    rounding >>= wp as i32;
    let total = convergence.max(&rounding).max(trunc);
    LevelEstimate { total, rounding }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn fl(x: f64) -> Float {
        Float::with_val(53, x)
    }

    fn rel_err(v: &Float, exact: &Float) -> f64 {
        let d = Float::with_val(exact.prec() + 64, v - exact);
        (d / exact).to_f64().abs()
    }

    #[test]
    fn exp_on_unit_interval() {
        for prec in [53u32, 128, 300] {
            let opts = TanhSinhOptions::with_prec(prec);
            let r = integrate(|x| Ok(Float::with_val(x.prec(), x.exp_ref())), &fl(0.0), &fl(1.0), &opts).unwrap();
            let exact = Float::with_val(prec + 64, 1u32).exp() - 1u32;
            let err = rel_err(&r.value, &exact);
            assert!(err <= 2f64.powi(-(prec as i32) + 1), "prec={prec}: err {err:e}, {r:?}");
            assert!(r.evaluations < 2000, "prec={prec}: {} evaluations", r.evaluations);
        }
    }

    #[test]
    fn node_formulas_match_direct_tanh() {
        let wp = 200;
        let half_pi = Float::with_val(wp, Constant::Pi) / 2u32;
        for (j, k) in [(1u64, 0u32), (3, 2), (13, 3), (40, 3)] {
            let nd = node(j, k, &half_pi, wp);
            let t = Float::with_val(wp, j as f64 / (1u64 << k) as f64);
            let u = Float::with_val(wp, t.sinh_ref()) * &half_pi;
            let g = Float::with_val(wp, u.tanh_ref());
            let direct = Float::with_val(wp, 1u32 - g);
            assert!(rel_err(&nd.delta, &direct) < 1e-50 || direct.is_zero(), "j={j} k={k}");
            let cosh_u = Float::with_val(wp, u.cosh_ref());
            let w = Float::with_val(wp, t.cosh_ref()) * &half_pi / cosh_u.square();
            assert!(rel_err(&nd.weight, &w) < 1e-55, "j={j} k={k}");
        }
    }

    #[test]
    fn bad_input_is_an_error() {
        let f = |x: &Float| Ok(x.clone());
        let o = TanhSinhOptions::default();
        let nan = Float::with_val(53, rug::float::Special::Nan);
        assert!(matches!(integrate(f, &nan, &fl(1.0), &o), Err(Error::NonFinite { .. })));
        assert!(matches!(integrate(f, &fl(0.0), &Float::with_val(53, rug::float::Special::Infinity), &o), Err(Error::NonFinite { .. })));
        assert!(matches!(integrate(f, &fl(0.0), &fl(1.0), &TanhSinhOptions::with_prec(1)), Err(Error::Precision { .. })));
        let bad = TanhSinhOptions { max_level: MAX_LEVEL_CAP + 1, ..o.clone() };
        assert!(matches!(integrate(f, &fl(0.0), &fl(1.0), &bad), Err(Error::IntegerOutOfRange { arg: "max_level", .. })));
        let bad = TanhSinhOptions { max_level: 1, ..o.clone() };
        assert!(matches!(integrate(f, &fl(0.0), &fl(1.0), &bad), Err(Error::IntegerOutOfRange { arg: "max_level", .. })));
        let bad = TanhSinhOptions { abs_tol: fl(-1e-30), ..o.clone() };
        assert!(matches!(integrate(f, &fl(0.0), &fl(1.0), &bad), Err(Error::OutOfRange { arg: "abs_tol", .. })));
        let bad = TanhSinhOptions { abs_tol: nan.clone(), ..o.clone() };
        assert!(matches!(integrate(f, &fl(0.0), &fl(1.0), &bad), Err(Error::NonFinite { .. })));
        let bad = TanhSinhOptions { guard_bits: MAX_GUARD_BITS + 1, ..o.clone() };
        assert!(integrate(f, &fl(0.0), &fl(1.0), &bad).is_err());
        // Integrand errors and non-finite values.
        assert_eq!(integrate(|_| Err(Error::DivisionByZero), &fl(0.0), &fl(1.0), &o), Err(Error::DivisionByZero));
        let inf = |_: &Float| Ok(Float::with_val(53, rug::float::Special::Infinity));
        assert!(matches!(integrate(inf, &fl(0.0), &fl(1.0), &o), Err(Error::NonFinite { .. })));
    }

    #[test]
    fn empty_and_reversed() {
        let o = TanhSinhOptions::with_prec(100);
        let f = |x: &Float| Ok(Float::with_val(x.prec(), x * x));
        let z = integrate(f, &fl(0.5), &fl(0.5), &o).unwrap();
        assert!(z.value.is_zero() && z.error_estimate.is_zero() && z.evaluations == 0);
        let fwd = integrate(f, &fl(0.0), &fl(3.0), &o).unwrap();
        let rev = integrate(f, &fl(3.0), &fl(0.0), &o).unwrap();
        assert_eq!(fwd.value, -rev.value);
        assert!(rel_err(&fwd.value, &Float::with_val(200, 9u32)) < 1e-29);
    }

    #[test]
    fn interval_narrower_than_working_precision() {
        // [1, 1 + 2^-200] at 100 + 32 bits: x alone cannot resolve it, the
        // complements can (f = 2 (x - 1) / width^2 integrates to 1).
        let lo = fl(1.0);
        let mut width = Float::with_val(53, 1);
        width >>= 200;
        let hi = Float::with_val(256, &lo + &width);
        let o = TanhSinhOptions::with_prec(100);
        assert!(matches!(integrate(|_| Ok(fl(1.0)), &lo, &hi, &o), Err(Error::IntervalTooNarrow { prec: 132 })));
        let w2 = Float::with_val(53, width.square_ref());
        let r = integrate_with_complements(|_, xa, _| Ok(Float::with_val(xa.prec(), xa * 2u32) / &w2), &lo, &hi, &o).unwrap();
        assert!(rel_err(&r.value, &fl(1.0)) < 1e-30, "{r:?}");
    }

    #[test]
    fn vanishing_integral_needs_abs_tol() {
        // ∫_{-1}^{1} x dx = 0: relative target unreachable, absolute target fine.
        let f = |x: &Float| Ok(x.clone());
        let mut o = TanhSinhOptions::with_prec(64);
        o.max_level = 6;
        assert!(integrate(f, &fl(-1.0), &fl(1.0), &o).is_err());
        o.abs_tol = Float::with_val(53, 1e-20);
        let r = integrate(f, &fl(-1.0), &fl(1.0), &o).unwrap();
        assert!(r.value.to_f64().abs() <= 1e-20);
    }
}
