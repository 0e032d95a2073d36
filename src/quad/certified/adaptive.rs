//! Adaptive Gauss-Legendre on a work stack of subintervals, each piece bounded by
//! the integrand's magnitude on a Bernstein ellipse.
//!
//! # Method
//!
//! For a piece `[lo, hi]` with midpoint `m` and half-width `h`:
//!
//! 1. **Crude enclosure.** The integral lies in `(hi - lo) f([lo, hi])`, `f` evaluated
//!    once on the real segment as a ball (the mean value lies in the convex hull of
//!    the values, and a rectangle is convex). Accepted when its radius is below the
//!    piece's tolerance: this settles small pieces next to singularities, and pieces
//!    where `f` is tiny, with one evaluation.
//! 2. **Gauss-Legendre with an ellipse bound.** If `g(t) = f(m + h t)` is holomorphic
//!    inside the Bernstein ellipse `E_rho` (foci -1, 1, semi-axes `(rho + 1/rho)/2`
//!    and `(rho - 1/rho)/2`) with `|g| <= M` there, the `n`-point rule errs by at most
//!    `64 M / (15 (rho - 1) rho^(2n - 1))` (Trefethen, "Is Gauss quadrature better than
//!    Clenshaw-Curtis?", SIAM Review 2008, Thm. 4.5; as in Arb's
//!    `acb_calc_integrate_gl_auto_deg`). The ellipse is enclosed by the box
//!    `m + h ([-X, X] + i [-Y, Y])`, `X = (rho + 1/rho)/2`, `Y = sqrt(X^2 - 1)`; one
//!    evaluation of `f` on that box in *analytic* mode gives `M`, and a finite answer
//!    proves holomorphy there (every branch cut is checked by [`super::HoloBall`]).
//!    `X` runs over `2, 4, 8, 32, 512, ...` (Arb's ladder); for each the smallest
//!    degree from [`DEGREES`] (Arb's ladder with a rung between each two) whose bound
//!    is [`DEGREE_MARGIN_BITS`] below the tolerance is a candidate, and the smallest
//!    candidate wins (the cost is the number of evaluations). The choice only sets the
//!    cost: the bound of the degree taken is the one added.
//!    We bound `(rho - 1) rho^(2n-1) >= 0.7 rho^(2n)` (valid for `rho >= 3.7`, i.e.
//!    `X >= 2`), so the bound added is `6.1 M / rho^(2n)` with `rho` rounded down.
//!    Where the box's evaluation is not finite and high degrees are at stake, `M`
//!    comes from a cover of the box by sub-boxes (`cover.rs`, which proves holomorphy
//!    the same way).
//! 3. **Bisection** where no degree up to the limit meets the tolerance. A run whose
//!    rate of progress projects it past four times its evaluation limit stops early,
//!    flagged [`Limit::Projected`] (`Progress`).
//!
//! The rule's nodes and weights are balls ([`super::legendre`]), the sum is formed in
//! ball arithmetic, and the truncation bound is added to both radii, so the result
//! encloses the integral over every piece. Pieces share exact dyadic endpoints.

use rug::Float;

use super::cover::{cover_bound, CoverLimits, Covered};
use super::legendre;
use super::{HoloBall, IntegrationError, Limit, Mode};
use crate::ball::{Ball, CBall, Mag};
use crate::error::{Error, Reached, Result};

/// The degree ladder: Arb's (steps of about `2^(1/2)`: 1, 2, 4, 6, 8, 12, 16, 22, 32,
/// ..., 2048) with a rung between each two (steps of about `2^(1/4)`), so that the
/// degree taken exceeds the one the bound asks for by 9% on average instead of 19%.
/// Every rung is a rule to enclose and cache once per precision: the rungs stay few.
pub(crate) const DEGREES: [usize; 40] = [
    1, 2, 3, 4, 5, 6, 7, 8, 10, 12, 14, 16, 19, 22, 26, 32, 38, 46, 54, 64, 76, 90, 108, 128, 152, 182, 216, 256, 304, 362, 430,
    512, 608, 724, 862, 1024, 1218, 1448, 1722, 2048,
];

/// The bits by which the degree taken must beat the piece's tolerance. The rungs of
/// [`DEGREES`] are close, so the bound often lands just below the tolerance; summed
/// over many pieces such bounds can miss the goal by a fraction of a bit and force a
/// second attempt (I15 and I2 of the golden set at 64 bits: 1907 and 4547
/// evaluations without a margin, 952 and 2323 with one bit; two bits and more cost
/// more than they save).
const DEGREE_MARGIN_BITS: f64 = 1.0;

/// The evaluations a cover of one ellipse's box may spend, in multiples of the
/// degree limit: a cover that costs more than a few rules of the largest degree is
/// worse than bisection.
const COVER_BUDGET: usize = 16;

/// The degree on the smallest ellipse from which covers are tried (see
/// `gauss_legendre_piece`). Their cost, about 9 evaluations per unit area of the box in
/// `s` for `int_1^inf dx/(1+x^2)` mapped by `x = e^s`, falls below the rules' at about
/// 100; from 96, `int_0^10000 x^1000 e^-x` at 64 bits took 9% more evaluations (1531
/// against 1399), so covers wait until single boxes would need twice that.
const COVER_MIN_DEGREE: f64 = 192.0;

/// Counters of one integration.
#[derive(Debug, Default, Clone, Copy)]
pub(crate) struct Stats {
    pub evaluations: u64,
    pub subintervals: u64,
    pub max_depth: u32,
    /// Evaluations spent by successful covers (cover.rs), and the area they covered:
    /// their ratio predicts the cost of the next.
    pub cover_evaluations: u64,
    pub cover_area: f64,
}

/// Limits of one run.
#[derive(Debug, Clone, Copy)]
pub(crate) struct RunLimits {
    pub max_evaluations: u64,
    pub max_depth: u32,
    pub max_degree: usize,
}

/// The outcome of [`adaptive`]: the enclosure and the part of its radius that is
/// quadrature truncation (the rest is rounding and input radii).
pub(crate) struct Outcome {
    pub value: CBall,
    pub truncation: Mag,
    /// A limit was reached; the pieces left were enclosed crudely.
    pub limit: Option<Limit>,
    /// Where the integrand was last found unbounded (a piece that could not be enclosed).
    pub unbounded_near: Option<f64>,
    /// An upper bound of `int |f|` over `[a, b]`: the sum over the pieces of the
    /// magnitude of their crude enclosures, `|(hi - lo) f([lo, hi])| >= int_lo^hi |f|`
    /// (certified; infinite when a piece has none).
    pub l1: Mag,
}

/// `rho` (rounded down) and `Y` (rounded up) for `X = 2^xexp`, `xexp >= 1`.
fn ellipse(xexp: u32) -> (Mag, Mag) {
    if xexp <= 20 {
        let x = (1u64 << xexp) as f64;
        // x^2 - 1 is exact in f64 for x <= 2^20; sqrt is correctly rounded.
        let s = (x * x - 1.0).sqrt();
        let rho = (x + s.next_down()).next_down();
        (Mag::from_f64(rho), Mag::from_f64(s.next_up()))
    } else {
        // rho = X + sqrt(X^2 - 1) >= 2X - 1 >= 2X (1 - 2^-21); Y <= X.
        let rho = Mag::pow2(xexp as i64 + 1).mul_lower(Mag::from_f64(1.0 - f64::powi(2.0, -21)));
        (rho, Mag::pow2(xexp as i64))
    }
}

/// `m^k` rounded down.
fn pow_lower(m: Mag, k: u64) -> Mag {
    crate::ball::binary_power(Mag::from_f64(1.0), m, k, |a, b| a.mul_lower(*b), |a| a.mul_lower(*a))
}

/// The bound `6.1 M / rho^(2n)` (see the module docs), rounded up.
fn gl_bound(m: Mag, rho: Mag, n: usize) -> Mag {
    m.mul(Mag::from_f64(6.1)).div(pow_lower(rho, 2 * n as u64))
}

/// `log2` of the bound, for choosing the degree (f64, approximate).
fn gl_bound_log2(m: Mag, rho: Mag, n: usize) -> f64 {
    m.log2() + 6.1f64.log2() - 2.0 * n as f64 * rho.log2()
}

/// The integrand evaluated through the caller's closure, counted.
pub(crate) struct Counted<'f, F> {
    pub f: &'f mut F,
    pub stats: Stats,
}

impl<F: FnMut(&HoloBall) -> CBall> Counted<'_, F> {
    fn eval(&mut self, z: CBall, mode: Mode) -> CBall {
        self.eval_at(&HoloBall::new(z, mode))
    }

    fn eval_at(&mut self, z: &HoloBall) -> CBall {
        self.stats.evaluations += 1;
        (self.f)(z)
    }
}

/// Exact midpoint of two floats (precision raised by one bit).
fn midpoint(lo: &Float, hi: &Float) -> Float {
    let p = lo.prec().max(hi.prec()) + 1;
    let mut m = Float::with_val(p, lo + hi);
    m >>= 1;
    m
}

/// Exact difference `hi - lo` (enough precision for it to be exact).
pub(crate) fn exact_diff(lo: &Float, hi: &Float) -> Float {
    let elo = lo.get_exp().unwrap_or(0) as i64;
    let ehi = hi.get_exp().unwrap_or(0) as i64;
    let spread = (elo - ehi).unsigned_abs() as u32;
    let p = lo.prec().max(hi.prec()) + spread + 2;
    Float::with_val(p.min(crate::MAX_WORKING_PREC * 2), hi - lo)
}

/// The crude enclosure `(hi - lo) f([lo, hi])` of a piece (`None` where `f` is
/// unbounded on the segment).
pub(crate) fn crude<F>(f: &mut Counted<'_, F>, lo: &Float, hi: &Float, wp: u32) -> Option<CBall>
where
    F: FnMut(&HoloBall) -> CBall,
{
    let width = exact_diff(lo, hi);
    let seg = CBall::from_real(Ball::hull(lo, hi, wp));
    let fv = f.eval(seg, Mode::Point);
    fv.is_finite().then(|| fv.mul_real(&Ball::from_float(&width, width.prec())))
}

/// Whether the segment is wider than `2^(16 - wp)` relative to its ends: below that
/// its ball at `wp` bits is mostly rounding, and halves would not enclose better.
fn resolvable(lo: &Float, hi: &Float, wp: u32) -> bool {
    let w = exact_diff(lo, hi);
    let scale = lo.get_exp().max(hi.get_exp()).unwrap_or(i32::MIN) as i64;
    w.get_exp().is_some_and(|e| e as i64 > scale + 16 - wp as i64)
}

/// A piece on the work stack, with its crude enclosure.
struct Piece {
    lo: Float,
    hi: Float,
    depth: u32,
    crude: Option<CBall>,
}

impl Piece {
    /// The radius of the crude enclosure (infinite without one): the work left.
    fn open(&self) -> Mag {
        self.crude.as_ref().map_or(Mag::inf(), |c| c.rad_mag())
    }
}

/// Integrates over `[a, b]` (exact floats, `a < b`) at working precision `wp`.
///
/// The tolerance of every piece is `tol`, raised as the work goes to `2^-goal` times
/// the largest magnitude (lower bound) of a piece's enclosure (Arb's rule: a piece
/// never needs to be known better than the goal relative to the integral, and the
/// integral is at least as large as... its pieces' sum, which the largest piece
/// approximates). Of two halves, the one with more work left is done first, so large
/// pieces raise the tolerance early. The sum of the pieces' errors can exceed one
/// piece's tolerance; the driver checks the goal and retries with a smaller one.
///
/// `first` is the crude enclosure of the whole `[a, b]` at `wp` when the caller has it
/// already (it is then not evaluated again).
#[allow(clippy::too_many_arguments)]
pub(crate) fn adaptive<F>(f: &mut Counted<'_, F>, a: &Float, b: &Float, wp: u32, tol: Mag, goal: i64, lim: RunLimits, first: Option<CBall>, periodic: bool) -> Result<Outcome>
where
    F: FnMut(&HoloBall) -> CBall,
{
    let mut dyn_tol = tol;
    let raise = |t: &mut Mag, v: &CBall| {
        let m = v.abs_lower_mag().mul_2exp(-goal);
        if t.le(&m) {
            *t = m;
        }
    };
    let first = match first {
        Some(c) => c.is_finite().then_some(c),
        None => crude(f, a, b, wp),
    };
    if let Some(c) = &first {
        raise(&mut dyn_tol, c);
    }
    let mut stack = vec![Piece { lo: a.clone(), hi: b.clone(), depth: 0, crude: first }];
    let mut sum = CBall::zero(wp);
    let mut truncation = Mag::ZERO;
    let mut limit = None;
    let mut unbounded_near = None;
    let mut l1 = Mag::ZERO;
    let mut progress = Progress::new(f.stats.evaluations, lim.max_evaluations, a, b);
    let overdraft = lim.max_evaluations.saturating_add(lim.max_evaluations / 4 + 64);
    while let Some(piece) = stack.pop() {
        // the installed time budget (crate::budget), between pieces: no model bounds
        // the number of pieces in advance
        crate::budget::check_elapsed("certified quadrature (adaptive bisection)", 0.0, Reached::Evaluations { count: f.stats.evaluations })?;
        f.stats.subintervals += 1;
        f.stats.max_depth = f.stats.max_depth.max(piece.depth);
        let reached = if f.stats.evaluations >= lim.max_evaluations {
            Some(Limit::Evaluations)
        } else if piece.depth >= lim.max_depth {
            Some(Limit::Depth)
        } else if progress.hopeless(f.stats.evaluations) {
            Some(Limit::Projected)
        } else {
            None
        };
        // 1. the crude enclosure, when it is good enough (or a limit is reached)
        match &piece.crude {
            Some(c) if c.rad_mag().le(&dyn_tol) || reached.is_some() => {
                progress.settled(&piece.lo, &piece.hi);
                sum = sum.add(c);
                l1 = l1.add(c.abs_upper_mag());
                if reached.is_some() {
                    limit = reached;
                }
                continue;
            }
            None if piece.lo == piece.hi || (reached.is_some() && !(piece.depth < lim.max_depth && resolvable(&piece.lo, &piece.hi, wp) && f.stats.evaluations < overdraft)) => {
                // Nothing bounds this piece: the integrand is unbounded (or not defined) on it.
                limit = reached;
                unbounded_near = Some(midpoint(&piece.lo, &piece.hi).to_f64());
                sum = CBall::indeterminate(wp);
                l1 = Mag::inf();
                continue;
            }
            // A limit, and no enclosure yet (the segment's ball was too wide, as
            // sin(x)/x^2 on x = e^[0, 32], whose ball reaches 0): bisect on, without
            // rules, until the halves have crude enclosures, within an overdraft of a
            // quarter of the evaluation limit (an integrand that is not finite anywhere
            // would otherwise bisect into every piece down to the depth limit).
            None if reached.is_some() => limit = reached,
            _ => {}
        }
        // 2. Gauss-Legendre, where the integrand is bounded on the segment
        if let (Some(c), None) = (&piece.crude, reached) {
            if let Some((v, err)) = gauss_legendre_piece(f, &piece.lo, &piece.hi, wp, dyn_tol, lim, periodic, c.abs_upper_mag())? {
                raise(&mut dyn_tol, &v);
                progress.settled(&piece.lo, &piece.hi);
                sum = sum.add(&v);
                l1 = l1.add(c.abs_upper_mag());
                truncation = truncation.add(err);
                continue;
            }
        }
        // 3. bisect, the half with more work left on top
        let mid = midpoint(&piece.lo, &piece.hi);
        let (cl, cr) = (crude(f, &piece.lo, &mid, wp), crude(f, &mid, &piece.hi, wp));
        for c in [&cl, &cr].into_iter().flatten() {
            raise(&mut dyn_tol, c);
        }
        let left = Piece { lo: piece.lo, hi: mid.clone(), depth: piece.depth + 1, crude: cl };
        let right = Piece { lo: mid, hi: piece.hi, depth: piece.depth + 1, crude: cr };
        if left.open().le(&right.open()) {
            stack.push(left);
            stack.push(right);
        } else {
            stack.push(right);
            stack.push(left);
        }
    }
    Ok(Outcome { value: sum, truncation, limit, unbounded_near, l1 })
}

/// The share of an interval settled against the evaluations spent, to stop early a
/// run that will not finish within its evaluation limit (a heuristic: it decides only
/// when the run stops, never what the result encloses). At checkpoints every
/// `chunk` evaluations (a 64th of the budget, at least 20000), the width settled since
/// the last checkpoint is the rate; from the second checkpoint on, the run is hopeless
/// when the width left at that rate would take more than four times the evaluations
/// left. A rate and not the share done: pieces where the integrand is negligible
/// settle early and fast, and would hide a rate of almost nothing elsewhere.
struct Progress {
    start: u64,
    budget: u64,
    chunk: u64,
    width: f64,
    done: f64,
    /// (evaluations, width done) at the last checkpoint
    mark: (u64, f64),
    checkpoints: u32,
    /// Once hopeless, the run stays stopped.
    stopped: bool,
}

impl Progress {
    fn new(start: u64, max_evaluations: u64, a: &Float, b: &Float) -> Progress {
        let budget = max_evaluations.saturating_sub(start);
        let width = exact_diff(a, b).to_f64();
        Progress { start, budget, chunk: (budget / 64).max(20_000), width, done: 0.0, mark: (0, 0.0), checkpoints: 0, stopped: false }
    }

    fn settled(&mut self, lo: &Float, hi: &Float) {
        self.done += exact_diff(lo, hi).to_f64();
    }

    fn hopeless(&mut self, evaluations: u64) -> bool {
        let spent = evaluations.saturating_sub(self.start);
        if self.stopped {
            return true;
        }
        if spent < self.mark.0 + self.chunk || !(self.width > 0.0 && self.width.is_finite()) {
            return false;
        }
        let rate = (self.done - self.mark.1) / (spent - self.mark.0) as f64;
        self.mark = (spent, self.done);
        self.checkpoints += 1;
        if self.checkpoints < 2 {
            return false;
        }
        let left = (self.width - self.done).max(0.0);
        self.stopped = left > rate * 4.0 * self.budget.saturating_sub(spent) as f64;
        self.stopped
    }
}

/// One Gauss-Legendre step on `[lo, hi]`: `Some((enclosure, truncation bound))` when
/// some degree up to `max_degree` meets `tol`, `None` otherwise.
#[allow(clippy::too_many_arguments)]
fn gauss_legendre_piece<F>(f: &mut Counted<'_, F>, lo: &Float, hi: &Float, wp: u32, tol: Mag, lim: RunLimits, periodic: bool, crude_abs: Mag) -> Result<Option<(CBall, Mag)>>
where
    F: FnMut(&HoloBall) -> CBall,
{
    let m = midpoint(lo, hi);
    let mut h = exact_diff(lo, hi);
    h >>= 1;
    let h_mag = Mag::from_float_up(&h);
    let tol_log2 = tol.log2();
    let max_degree = lim.max_degree;
    // Covers of boxes (cover.rs) cost far more evaluations than one box; they pay where
    // the single boxes force small ellipses and high degrees: where a rule on the
    // smallest ellipse (rho = 3.7) would need COVER_MIN_DEGREE or more, from the
    // crude enclosure's size.
    let cover_pays = (crude_abs.log2() - tol_log2) / (2.0 * 3.7f64.log2()) >= COVER_MIN_DEGREE;
    let mut best: Option<(usize, Mag, Mag)> = None; // (n, rho, M)
    // the degree the bound asks for at the last ellipse, unrounded (f64, a heuristic)
    let mut last_need = f64::INFINITY;
    let mut xexp: u32 = 1;
    while xexp < wp.max(2) {
        let (rho, y) = ellipse(xexp);
        let xr = Mag::pow2(xexp as i64);
        let (rx, ry) = (h_mag.mul(xr), h_mag.mul(y));
        let wide = CBall::new(Ball::with_mag(m.clone(), rx).set_prec(wp), Ball::with_mag(Float::new(wp), ry));
        let v = f.eval(wide, Mode::Analytic);
        let mut covered = 0;
        let sup = if v.is_finite() {
            v.abs_upper_mag()
        } else {
            // One box is not finite: cover it by sub-boxes (cover.rs), within a budget
            // of COVER_BUDGET degrees' worth of evaluations, and give up once the bound
            // is too large for every degree up to the limit.
            if !cover_pays {
                break;
            }
            let remaining = lim.max_evaluations.saturating_sub(f.stats.evaluations);
            let budget = remaining.min((COVER_BUDGET * max_degree) as u64);
            // its area in the variable (one period at most when periodic), and the cost
            // the covers so far predict for it
            let height = if periodic { ry.to_f64_up().min(std::f64::consts::PI) } else { ry.to_f64_up() };
            let area = 4.0 * rx.to_f64_up() * height;
            if f.stats.cover_area > 0.0 && f.stats.cover_evaluations as f64 / f.stats.cover_area * area > budget as f64 {
                break;
            }
            let useful = tol_log2 + 2.0 * max_degree as f64 * rho.log2() - 6.1f64.log2() - h_mag.log2();
            let cover = CoverLimits { budget, cutoff: Mag::pow2(useful.clamp(-1e15, 1e15) as i64 + 1), periodic };
            let (sup, spent) = cover_bound(&mut |z| f.eval(z, Mode::Analytic), &m, rx, ry, wp, &cover);
            covered = spent as usize;
            match sup {
                Covered::Bound(sup) => {
                    f.stats.cover_evaluations += spent;
                    f.stats.cover_area += area;
                    sup
                }
                // too large for this ellipse's rho: a larger one may do
                Covered::TooLarge => {
                    xexp += (xexp - 1).max(1);
                    continue;
                }
                Covered::Failed => break,
            }
        };
        let big_m = sup.mul(h_mag);
        // Larger ellipses stop paying once the degree they need grows again (M grows
        // faster than rho^(2n) falls): stop there instead of evaluating the rest of the
        // ladder. Only the choice of degree depends on this; every bound is checked.
        let need = (gl_bound_log2(big_m, rho, 0) - tol_log2) / (2.0 * rho.log2());
        if best.is_some() && need >= last_need {
            break;
        }
        last_need = need;
        for &n in DEGREES.iter().take_while(|&&n| n <= max_degree) {
            if gl_bound_log2(big_m, rho, n) < tol_log2 - DEGREE_MARGIN_BITS {
                if best.is_none_or(|(bn, _, _)| n < bn) {
                    best = Some((n, rho, big_m));
                }
                break;
            }
        }
        // A cover of the next, at least twice as large, box costs more than the degree
        // it could save.
        if matches!(best, Some((1, _, _))) || best.is_some_and(|(bn, _, _)| covered >= bn) {
            break;
        }
        xexp += (xexp - 1).max(1);
    }
    let Some((n, rho, big_m)) = best else {
        return Ok(None);
    };
    let err = gl_bound(big_m, rho, n);
    let rule = legendre::rule(n, wp)?;
    // The nodes at the working precision: m and h carry the endpoints' precision (the
    // caller's, plus a bit per bisection), which would otherwise pass to every
    // operation of the integrand; rounded to wp they are balls that contain them.
    let mb = Ball::from_float(&m, m.prec()).set_prec(wp);
    let hb = Ball::from_float(&h, h.prec()).set_prec(wp);
    // sum_k w_k f(x_k), accumulated in place (real and imaginary parts apart; an
    // imaginary part that is exactly zero, as at real nodes of a real integrand, adds
    // nothing)
    // nothing is allocated per node but the integrand's own values: the node
    // m +- h x_k is formed in place in one point
    let (mut s_re, mut s_im, mut tmp) = (Ball::zero(wp), Ball::zero(wp), Float::new(wp));
    let (mut hx, mut point) = (Ball::zero(wp), HoloBall::new(CBall::zero(wp), Mode::Point));
    for (k, (x, w)) in rule.nodes.iter().zip(&rule.weights).enumerate() {
        hx.assign_mul(&hb, x);
        let last_odd = n % 2 == 1 && k == rule.nodes.len() - 1;
        for minus in [false, true] {
            if minus && last_odd {
                break;
            }
            let t = point.inner_mut().re_mut();
            if minus {
                t.assign_sub(&mb, &hx);
            } else {
                t.assign_add(&mb, &hx);
            }
            let v = f.eval_at(&point);
            s_re.add_mul_assign(v.re(), w, &mut tmp);
            if !v.is_real() {
                s_im.add_mul_assign(v.im(), w, &mut tmp);
            }
        }
    }
    let mut v = CBall::new(s_re, s_im).mul_real(&hb);
    v.add_error_mag(err);
    Ok(Some((v, err)))
}

/// The error for a result that could not be bounded.
pub(crate) fn unbounded_error(near: Option<f64>, stats: &Stats) -> Error {
    Error::Integration(IntegrationError::NotIntegrable { near: near.unwrap_or(f64::NAN), evaluations: stats.evaluations })
}
