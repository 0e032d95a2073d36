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
fn pow_lower(m: Mag, mut k: u64) -> Mag {
    let mut result = Mag::from_f64(1.0);
    let mut base = m;
    while k > 0 {
        if k & 1 == 1 {
            result = result.mul_lower(base);
        }
        k >>= 1;
        if k > 0 {
            base = base.mul_lower(base);
        }
    }
    result
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

impl<F: FnMut(&CBall, Mode) -> CBall> Counted<'_, F> {
    fn eval(&mut self, z: &CBall, mode: Mode) -> CBall {
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
fn exact_diff(lo: &Float, hi: &Float) -> Float {
    let elo = lo.get_exp().unwrap_or(0) as i64;
    let ehi = hi.get_exp().unwrap_or(0) as i64;
    let spread = (elo - ehi).unsigned_abs() as u32;
    let p = lo.prec().max(hi.prec()) + spread + 2;
    Float::with_val(p.min(crate::MAX_WORKING_PREC * 2), hi - lo)
}

/// Integrates over `[a, b]` (exact floats, `a < b`) to an absolute tolerance `tol`,
/// at working precision `wp`.
pub(crate) fn adaptive<F>(f: &mut Counted<'_, F>, a: &Float, b: &Float, wp: u32, tol: Mag, lim: RunLimits) -> Result<Outcome>
where
    F: FnMut(&CBall, Mode) -> CBall,
{
    let total = Mag::from_float_down(&exact_diff(a, b));
    let mut stack: Vec<(Float, Float, u32)> = vec![(a.clone(), b.clone(), 0)];
    let mut sum = CBall::zero(wp);
    let mut truncation = Mag::ZERO;
    let mut limit = None;
    let mut unbounded_near = None;
    while let Some((lo, hi, depth)) = stack.pop() {
        f.stats.subintervals += 1;
        f.stats.max_depth = f.stats.max_depth.max(depth);
        let width = exact_diff(&lo, &hi);
        // The piece's share of the tolerance: proportional to its width, but never
        // below 2^-10 of the whole, so that a long range whose integral lives in a
        // small part (a cut-off tail) is not asked for absurd accuracy far out. More
        // than 2^10 pieces at the floor can exceed `tol`; the driver then retries
        // with a smaller one.
        let share = Mag::from_float_down(&width).div(total.add(Mag::pow2(-100_000))).max(Mag::pow2(-10));
        let piece_tol = tol.mul_lower(share);
        let reached = if f.stats.evaluations >= lim.max_evaluations {
            Some(Limit::Evaluations)
        } else if depth >= lim.max_depth {
            Some(Limit::Depth)
        } else {
            None
        };
        // 1. crude enclosure
        let seg = CBall::from_real(Ball::hull(&lo, &hi, wp));
        let fv = f.eval(&seg, Mode::Point);
        if fv.is_finite() {
            let crude = fv.mul_real(&Ball::from_float(&width, width.prec()));
            if crude.rad_mag().le(&piece_tol) || reached.is_some() {
                sum = sum.add(&crude);
                if reached.is_some() {
                    limit = reached;
                }
                continue;
            }
        } else if reached.is_some() || width.is_zero() {
            // Nothing bounds this piece: the integrand is unbounded (or not defined) on it.
            limit = reached;
            unbounded_near = Some(midpoint(&lo, &hi).to_f64());
            sum = CBall::indeterminate(wp);
            continue;
        }
        if reached.is_none() {
            // 2. Gauss-Legendre
            if let Some((v, err)) = gauss_legendre_piece(f, &lo, &hi, wp, piece_tol, lim.max_degree)? {
                sum = sum.add(&v);
                truncation = truncation.add(err);
                continue;
            }
        }
        // 3. bisect
        let mid = midpoint(&lo, &hi);
        stack.push((mid.clone(), hi, depth + 1));
        stack.push((lo, mid, depth + 1));
    }
    Ok(Outcome { value: sum, truncation, limit, unbounded_near })
}

/// One Gauss-Legendre step on `[lo, hi]`: `Some((enclosure, truncation bound))` when
/// some degree up to `max_degree` meets `tol`, `None` otherwise.
fn gauss_legendre_piece<F>(f: &mut Counted<'_, F>, lo: &Float, hi: &Float, wp: u32, tol: Mag, max_degree: usize) -> Result<Option<(CBall, Mag)>>
where
    F: FnMut(&CBall, Mode) -> CBall,
{
    let m = midpoint(lo, hi);
    let mut h = exact_diff(lo, hi);
    h >>= 1;
    let h_mag = Mag::from_float_up(&h);
    let tol_log2 = tol.log2();
    let mut best: Option<(usize, Mag, Mag)> = None; // (n, rho, M)
    let mut xexp: u32 = 1;
    while xexp < wp.max(2) {
        let (rho, y) = ellipse(xexp);
        let xr = Mag::pow2(xexp as i64);
        let wide = CBall::new(
            Ball::with_mag(m.clone(), h_mag.mul(xr)),
            Ball::with_mag(Float::new(m.prec()), h_mag.mul(y)),
        );
        let v = f.eval(&wide, Mode::Analytic);
        if !v.is_finite() {
            break;
        }
        let big_m = v.abs_upper_mag().mul(h_mag);
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
    let mb = Ball::from_float(&m, m.prec());
    let hb = Ball::from_float(&h, h.prec());
    let mut s = CBall::zero(wp);
    for (k, (x, w)) in rule.nodes.iter().zip(&rule.weights).enumerate() {
        let hx = hb.mul(x);
        let right = f.eval(&CBall::from_real(mb.add(&hx)), Mode::Point);
        let pair = if n % 2 == 1 && k == rule.nodes.len() - 1 {
            right
        } else {
            right.add(&f.eval(&CBall::from_real(mb.sub(&hx)), Mode::Point))
        };
        s = s.add(&pair.mul_real(w));
    }
    let mut v = s.mul_real(&hb);
    v.add_error_mag(err);
    Ok(Some((v, err)))
}

/// The error for a result that could not be bounded.
pub(crate) fn unbounded_error(near: Option<f64>, stats: &Stats) -> Error {
    Error::Integration(IntegrationError::NotIntegrable { near: near.unwrap_or(f64::NAN), evaluations: stats.evaluations })
}
