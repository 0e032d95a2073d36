//! `sup |f|` on a box by a cover of sub-boxes, where one evaluation on the whole box
//! is not finite.
//!
//! # Method
//!
//! The ellipse bound of `adaptive.rs` needs `M >= |f|` on the box `B` enclosing a
//! Bernstein ellipse, and a proof that `f` is holomorphic there. One evaluation of `f`
//! on `B` in analytic mode gives both when it is finite. It is not finite when
//! rectangle arithmetic loses too much on `B` even though `f` is holomorphic and small
//! there: with `x = c e^s` (the map of an algebraic decay), the rectangle of `e^B`
//! contains every angle once `B` is wider than about 1 in `s`, so `1 + x^2` reaches 0
//! although the poles of `1/(1 + x^2)` lie at `Re s = -log c` only.
//!
//! Here `B` is covered by closed sub-boxes `B_1, ..., B_k`: each box whose evaluation
//! is not finite is cut in two across its longer side (at a float between its edges,
//! the same for both halves, so the halves cover it), depth first. When every `B_j`
//! has a finite analytic-mode value `v_j`, then `f` is holomorphic on each `B_j` (every
//! operation was, [`super::HoloBall`]), hence on their union `B` (holomorphy is local
//! and the closed boxes cover `B`), and `|f| <= max_j |v_j|^+` on `B`: the same two
//! facts one finite evaluation on `B` gives.
//!
//! **Periodic integrands.** When the part declares its integrand `2 pi i`-periodic in
//! `s` (the map `x = c e^s`: `e^{s + 2 pi i} = e^s` exactly, so `g(s) = F(c e^s) c e^s`
//! takes the same values, and is holomorphic at the same points, on `s` and
//! `s + 2 pi i`), a box taller than a period is cut to the window `|Im s| <= P`,
//! `P >= pi` (rounded up): every point of the tall box is a translate by a multiple of
//! `2 pi i` of a point of the window, so the window's bound and holomorphy hold on the
//! tall box.
//!
//! **Cost and failure.** A box that contains a true singularity never becomes finite;
//! the cover gives up when a sub-box would be smaller than `1/64` of the (windowed)
//! box's shorter side, when the evaluation budget is spent, or when the maximum so far
//! already exceeds `cutoff` (no degree can use the bound). The evaluations count as
//! integrand evaluations in the statistics. Depth first, a box next to a singularity
//! reaches the smallest size after about `2 log2 64 = 12` cuts.

use rug::Float;

use crate::ball::{Ball, CBall, Mag};

/// A closed box `[re_lo, re_hi] x [im_lo, im_hi]`.
struct Cell {
    re: (Float, Float),
    im: (Float, Float),
}

impl Cell {
    fn ball(&self, wp: u32) -> CBall {
        CBall::new(Ball::hull(&self.re.0, &self.re.1, wp), Ball::hull(&self.im.0, &self.im.1, wp))
    }

    fn widths(&self) -> (f64, f64) {
        (Float::with_val(53, &self.re.1 - &self.re.0).to_f64(), Float::with_val(53, &self.im.1 - &self.im.0).to_f64())
    }
}

/// A float strictly between `lo` and `hi`, or `None` when there is none at `wp` bits.
fn split_point(lo: &Float, hi: &Float, wp: u32) -> Option<Float> {
    let mut t = Float::with_val(wp.max(lo.prec()).max(hi.prec()), lo + hi);
    t >>= 1;
    (lo < &t && &t < hi).then_some(t)
}

/// What a cover may spend.
pub(crate) struct CoverLimits {
    /// Evaluations at most.
    pub budget: u64,
    /// Give up once the maximum reaches this (the bound would be of no use).
    pub cutoff: Mag,
    /// The integrand is `2 pi i`-periodic in its variable.
    pub periodic: bool,
}

/// The outcome of a cover.
pub(crate) enum Covered {
    /// `sup |f|` on the box (rounded up).
    Bound(Mag),
    /// The maximum reached the cutoff: a larger ellipse may still do.
    TooLarge,
    /// A sub-box too small or the budget spent: `f` may be singular in the box.
    Failed,
}

/// `sup |f|` on the box `m + [-rx, rx] + i [-ry, ry]` from a cover of sub-boxes (module
/// docs), with the number of evaluations spent.
///
/// The sub-boxes are evaluated at a low precision, 64 bits plus the bits that tell
/// the box's centre from its edges: a bound needs a few correct bits, and ball
/// arithmetic encloses at any precision.
///
/// `f` evaluates the integrand on a box in analytic mode (and counts it).
pub(crate) fn cover_bound<F>(f: &mut F, m: &Float, rx: Mag, ry: Mag, wp: u32, lim: &CoverLimits) -> (Covered, u64)
where
    F: FnMut(CBall) -> CBall,
{
    let scale = m.get_exp().map_or(0, |e| e as i64) - rx.log2().floor() as i64;
    let wp = (64 + scale.clamp(0, 1 << 20) as u32).min(wp);
    let re = Ball::with_mag(m.clone(), rx);
    let (ry_whole, mut ry) = (ry, ry);
    if lim.periodic {
        let p = Mag::from_float_up(&Ball::pi(64).upper());
        if p.le(&ry) {
            ry = p;
        }
    }
    let im = Ball::with_mag(Float::new(wp), ry);
    let root = Cell { re: (re.lower(), re.upper()), im: (im.lower(), im.upper()) };
    let (w0, h0) = root.widths();
    let min_side = w0.min(h0) / 64.0;
    // The caller evaluated the whole box already (not finite): unless the window made
    // it smaller, the root is cut without a second evaluation.
    let mut known_open = ry == ry_whole;
    let mut stack = vec![root];
    let mut spent = 0u64;
    let mut max = Mag::ZERO;
    while let Some(cell) = stack.pop() {
        if !std::mem::take(&mut known_open) {
            if spent >= lim.budget {
                return (Covered::Failed, spent);
            }
            spent += 1;
            let v = f(cell.ball(wp));
            if v.is_finite() {
                max = max.max(v.abs_upper_mag());
                if lim.cutoff.le(&max) {
                    return (Covered::TooLarge, spent);
                }
                continue;
            }
        }
        let (w, h) = cell.widths();
        let (side, wide) = if w >= h { (w, true) } else { (h, false) };
        if side / 2.0 < min_side {
            return (Covered::Failed, spent);
        }
        let (lo, hi) = if wide { &cell.re } else { &cell.im };
        let Some(t) = split_point(lo, hi, wp) else {
            return (Covered::Failed, spent);
        };
        let Cell { re, im } = cell;
        if wide {
            stack.push(Cell { re: (t.clone(), re.1), im: im.clone() });
            stack.push(Cell { re: (re.0, t), im });
        } else {
            stack.push(Cell { re: re.clone(), im: (t.clone(), im.1) });
            stack.push(Cell { re, im: (im.0, t) });
        }
    }
    (Covered::Bound(max), spent)
}
