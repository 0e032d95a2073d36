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
//!    degree from [`DEGREES`] that meets the tolerance is a candidate, and the
//!    smallest candidate wins (the cost is the number of evaluations).
//!    We bound `(rho - 1) rho^(2n-1) >= 0.7 rho^(2n)` (valid for `rho >= 3.7`, i.e.
//!    `X >= 2`), so the bound added is `6.1 M / rho^(2n)` with `rho` rounded down.
//! 3. **Bisection** where no degree up to the limit meets the tolerance.
//!
//! The rule's nodes and weights are balls ([`super::legendre`]), the sum is formed in
//! ball arithmetic, and the truncation bound is added to both radii, so the result
//! encloses the integral over every piece. Pieces share exact dyadic endpoints.

use rug::Float;

use super::legendre;
use super::{IntegrationError, Limit, Mode};
use crate::ball::{Ball, CBall, Mag};
use crate::error::{Error, Result};

/// Arb's degree ladder (steps of about `2^(1/2)`).
pub(crate) const DEGREES: [usize; 21] =
    [1, 2, 4, 6, 8, 12, 16, 22, 32, 46, 64, 90, 128, 182, 256, 362, 512, 724, 1024, 1448, 2048];

/// Counters of one integration.
#[derive(Debug, Default, Clone, Copy)]
pub(crate) struct Stats {
    pub evaluations: u64,
    pub subintervals: u64,
    pub max_depth: u32,
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

impl<F: FnMut(CBall, Mode) -> CBall> Counted<'_, F> {
    fn eval(&mut self, z: CBall, mode: Mode) -> CBall {
        self.stats.evaluations += 1;
        (self.f)(z, mode)
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
    F: FnMut(CBall, Mode) -> CBall,
{
    let width = exact_diff(lo, hi);
    let seg = CBall::from_real(Ball::hull(lo, hi, wp));
    let fv = f.eval(seg, Mode::Point);
    fv.is_finite().then(|| fv.mul_real(&Ball::from_float(&width, width.prec())))
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
pub(crate) fn adaptive<F>(f: &mut Counted<'_, F>, a: &Float, b: &Float, wp: u32, tol: Mag, goal: i64, lim: RunLimits, first: Option<CBall>) -> Result<Outcome>
where
    F: FnMut(CBall, Mode) -> CBall,
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
    while let Some(piece) = stack.pop() {
        f.stats.subintervals += 1;
        f.stats.max_depth = f.stats.max_depth.max(piece.depth);
        let reached = if f.stats.evaluations >= lim.max_evaluations {
            Some(Limit::Evaluations)
        } else if piece.depth >= lim.max_depth {
            Some(Limit::Depth)
        } else {
            None
        };
        // 1. the crude enclosure, when it is good enough (or a limit is reached)
        match &piece.crude {
            Some(c) if c.rad_mag().le(&dyn_tol) || reached.is_some() => {
                sum = sum.add(c);
                if reached.is_some() {
                    limit = reached;
                }
                continue;
            }
            None if reached.is_some() || piece.lo == piece.hi => {
                // Nothing bounds this piece: the integrand is unbounded (or not defined) on it.
                limit = reached;
                unbounded_near = Some(midpoint(&piece.lo, &piece.hi).to_f64());
                sum = CBall::indeterminate(wp);
                continue;
            }
            _ => {}
        }
        // 2. Gauss-Legendre, where the integrand is bounded on the segment
        if piece.crude.is_some() {
            if let Some((v, err)) = gauss_legendre_piece(f, &piece.lo, &piece.hi, wp, dyn_tol, lim.max_degree)? {
                raise(&mut dyn_tol, &v);
                sum = sum.add(&v);
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
    Ok(Outcome { value: sum, truncation, limit, unbounded_near })
}

/// One Gauss-Legendre step on `[lo, hi]`: `Some((enclosure, truncation bound))` when
/// some degree up to `max_degree` meets `tol`, `None` otherwise.
fn gauss_legendre_piece<F>(f: &mut Counted<'_, F>, lo: &Float, hi: &Float, wp: u32, tol: Mag, max_degree: usize) -> Result<Option<(CBall, Mag)>>
where
    F: FnMut(CBall, Mode) -> CBall,
{
    let m = midpoint(lo, hi);
    let mut h = exact_diff(lo, hi);
    h >>= 1;
    let h_mag = Mag::from_float_up(&h);
    let tol_log2 = tol.log2();
    let mut best: Option<(usize, Mag, Mag)> = None; // (n, rho, M)
    // the degree the bound asks for at the last ellipse, unrounded (f64, a heuristic)
    let mut last_need = f64::INFINITY;
    let mut xexp: u32 = 1;
    while xexp < wp.max(2) {
        let (rho, y) = ellipse(xexp);
        let xr = Mag::pow2(xexp as i64);
        let wide = CBall::new(Ball::with_mag(m.clone(), h_mag.mul(xr)).set_prec(wp), Ball::with_mag(Float::new(wp), h_mag.mul(y)));
        let v = f.eval(wide, Mode::Analytic);
        if !v.is_finite() {
            break;
        }
        let big_m = v.abs_upper_mag().mul(h_mag);
        // Larger ellipses stop paying once the degree they need grows again (M grows
        // faster than rho^(2n) falls): stop there instead of evaluating the rest of the
        // ladder. Only the choice of degree depends on this; every bound is checked.
        let need = (gl_bound_log2(big_m, rho, 0) - tol_log2) / (2.0 * rho.log2());
        if best.is_some() && need >= last_need {
            break;
        }
        last_need = need;
        for &n in DEGREES.iter().take_while(|&&n| n <= max_degree) {
            if gl_bound_log2(big_m, rho, n) < tol_log2 {
                if best.is_none_or(|(bn, _, _)| n < bn) {
                    best = Some((n, rho, big_m));
                }
                break;
            }
        }
        if matches!(best, Some((1, _, _))) {
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
    let (mut s_re, mut s_im, mut tmp) = (Ball::zero(wp), Ball::zero(wp), Float::new(wp));
    for (k, (x, w)) in rule.nodes.iter().zip(&rule.weights).enumerate() {
        let hx = hb.mul(x);
        let last_odd = n % 2 == 1 && k == rule.nodes.len() - 1;
        let points = if last_odd { [Some(mb.add(&hx)), None] } else { [Some(mb.add(&hx)), Some(mb.sub(&hx))] };
        for t in points.into_iter().flatten() {
            let v = f.eval(CBall::from_real(t), Mode::Point);
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
