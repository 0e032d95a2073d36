//! The Dugdale-zone ends of a [`ContactSolver`] state, placed off the grid
//! ("Zone ends" in the method block of [`super`]): the gap at every cell edge
//! from the centre gaps and a local traction correction ([`EDGE_STENCIL`]),
//! which decides the cell that holds an end, then a safeguarded secant
//! iteration per end on the exact gap at `c` ([`ContactSolver::gap_at`]) to
//! [`END_TOL`] `delta_c`, at most [`MAX_END_STEPS`] steps.

use super::{runs, ContactSolver};
use crate::error::{Result, SolverError};

/// Half-width (cells) of the local correction that turns the mean of two
/// centre gaps into the gap at the edge between them.
pub const EDGE_STENCIL: usize = 24;
/// Most secant steps per state when placing the zone ends.
pub const MAX_END_STEPS: usize = 100;
/// Tolerance of the zone-end condition `g(c) = delta_c`, relative to `delta_c`.
pub const END_TOL: f64 = 1e-8;
/// Largest move of a zone end in one secant step (cells).
const MAX_END_MOVE: f64 = 16.0;

/// One Dugdale-zone end during [`ContactSolver::place_zone_ends`]: its side
/// (+1: the zone lies to the left), position `c` (cell units), the residual
/// `F(c) = g(c) - delta_c` of the last two positions, and the bracket of a
/// sign change once one is seen.
struct ZoneEnd {
    side: i8,
    c: f64,
    f: Option<(f64, f64)>,
    prev: Option<(f64, f64)>,
    below: Option<f64>,
    above: Option<f64>,
}

impl ZoneEnd {
    fn new(side: i8, c: f64) -> Self {
        ZoneEnd { side, c, f: None, prev: None, below: None, above: None }
    }

    /// Records `F` at the current position.
    fn record(&mut self, f: f64) {
        self.prev = self.f;
        self.f = Some((self.c, f));
        if f < 0.0 {
            self.below = Some(self.c);
        } else {
            self.above = Some(self.c);
        }
    }

    /// The next position: a secant step through the last two residuals (the
    /// first step uses the slope of the interpolated gap), limited to
    /// [`MAX_END_MOVE`] and kept inside a bracket of a sign change by bisection.
    fn next(&self, slope: f64) -> f64 {
        // Called after `record`; without a residual there is nothing to step on.
        let Some((c, f)) = self.f else { return self.c };
        let mut step = match self.prev {
            Some((c0, f0)) if f != f0 && c != c0 => -f * (c - c0) / (f - f0),
            _ if slope != 0.0 => -f / slope,
            _ => 0.0,
        };
        if !step.is_finite() || step == 0.0 {
            step = 1.0;
        }
        if self.below.is_none() || self.above.is_none() {
            // No sign change seen yet: move the way the gap asks for (a gap
            // above delta_c at the end shrinks the zone, below it grows it).
            let shrink = f > 0.0;
            let outward = if self.side > 0 { 1.0 } else { -1.0 };
            let direction = if shrink { -outward } else { outward };
            step = direction * step.abs();
        }
        let mut next = c + step.clamp(-MAX_END_MOVE, MAX_END_MOVE);
        if let (Some(lo), Some(hi)) = (self.below, self.above) {
            let (a, b) = (lo.min(hi), lo.max(hi));
            if !(next > a && next < b) {
                next = 0.5 * (a + b);
            }
        }
        next
    }
}


impl ContactSolver {
    /// Places every Dugdale-zone end within its cell (the module docs, "Zone
    /// ends"): with the zone on whole cells converged, each end position `c`
    /// (cell units: cell `j` covers `[j, j + 1]`) is moved by a safeguarded
    /// secant iteration until the gap, interpolated linearly between cell
    /// centres, equals `delta_c` at `c` to [`END_TOL`]` delta_c`; the end cell
    /// carries the cohesive traction `-sigma0 theta`, `theta` its covered
    /// fraction, and the contact is re-solved with the zone held after each
    /// step. Returns the CG iterations and the final residual.
    pub(super) fn place_zone_ends(&mut self, approach: f64, sigma0: f64, delta_c: f64, start: Option<&[(i8, f64)]>) -> Result<(usize, f64)> {
        let n = self.h.len();
        let mut ends: Vec<ZoneEnd> = start.map(|v| v.iter().map(|&(side, c)| ZoneEnd::new(side, c)).collect()).unwrap_or_default();
        for (a, b) in if start.is_some() { Vec::new() } else { runs(self.zone.iter().copied()) } {
            if a > 0 && b + 1 < n {
                if self.q[a] <= 0.0 {
                    ends.push(ZoneEnd::new(-1, a as f64));
                }
                if self.q[b] <= 0.0 {
                    ends.push(ZoneEnd::new(1, (b + 1) as f64));
                }
            }
        }
        let mut cg = 0;
        let mut residual = 0.0;
        for step in 0..=MAX_END_STEPS {
            let mut converged = true;
            for e in ends.iter_mut() {
                let f = self.gap_at(e.c, approach) - delta_c;
                if f.abs() > END_TOL * delta_c {
                    converged = false;
                }
                e.record(f);
            }
            if converged {
                self.last_ends = ends.iter().map(|e| (e.side, e.c)).collect();
                return Ok((cg, residual));
            }
            if step == MAX_END_STEPS {
                break;
            }
            // New positions, then the fractions of the cells around each end.
            for i in 0..n {
                self.r[i] = 0.0;
            }
            let mut released = false;
            for e in ends.iter_mut() {
                let slope = self.interpolated_slope(e.c);
                let old = e.c;
                e.c = e.next(slope);
                let lo = old.min(e.c).floor() as isize - 1;
                let hi = old.max(e.c).floor() as isize + 1;
                for j in lo.max(0)..=hi.min(n as isize - 1) {
                    let j = j as usize;
                    let t = if e.side > 0 { e.c - j as f64 } else { (j + 1) as f64 - e.c }.clamp(0.0, 1.0);
                    if self.q[j] > 0.0 {
                        if t == 1.0 {
                            continue;
                        }
                        // The zone end moves into the contact: the cell leaves
                        // the contact (the contact re-forms in the next solve if
                        // it must).
                        self.q[j] = 0.0;
                        self.theta[j] = 1.0;
                        released = true;
                    }
                    self.r[j] += t - self.theta[j];
                }
            }
            for i in 0..n {
                if self.r[i] != 0.0 {
                    let t = (self.theta[i] + self.r[i]).clamp(0.0, 1.0);
                    self.r[i] = sigma0 * (t - self.theta[i]);
                    self.theta[i] = t;
                    self.zone[i] = t > 0.0 || self.q[i] > 0.0;
                }
            }
            self.op.apply(&self.r, &mut self.u);
            for i in 0..n {
                self.kz[i] += self.u[i];
                self.gap[i] -= self.u[i];
            }
            if released {
                self.refresh_gap(approach);
            }
            let (it, _, res) = self.relax(approach, false)?;
            cg += it;
            residual = res;
        }
        let worst = ends.iter().map(|e| e.f.map_or(0.0, |(_, f)| f.abs())).fold(0.0, f64::max) / delta_c;
        Err(SolverError::NoConvergence { what: "Dugdale-zone end placement", iterations: MAX_END_STEPS, residual: worst })
    }

    /// The gap at position `c` (cell units) from the traction of every cell,
    /// exact for piecewise-constant traction: `h(x) - Delta + u(x)`,
    /// `u(x) = -(2/pi) sum_j p_j int_cell ln(|x - s|/L_d) ds` (on the periodic
    /// operator its images included, [`HalfPlane::segment_influence`]). A partial
    /// cohesive cell (`0 < theta < 1`, not in contact) carries `-sigma0` on its
    /// covered part (next to the zone) rather than `-sigma0 theta` on the whole
    /// cell: the traction of the zone ends where the zone ends.
    pub(super) fn gap_at(&self, c: f64, approach: f64) -> f64 {
        let grid = self.op.grid();
        let (sigma0, _) = self.adhesion.strength_and_range();
        let n = self.h.len();
        let dx = grid.dx();
        let x0 = -grid.half_width();
        let x = x0 + c * dx;
        let segment = |p: f64, s0: f64, s1: f64| -> f64 { p * self.op.segment_influence(x, s0, s1) };
        let mut u = 0.0;
        for j in 0..n {
            let (q, t) = (self.q[j], self.theta[j]);
            if q == 0.0 && t == 0.0 {
                continue;
            }
            let (s0, s1) = (x0 + j as f64 * dx, x0 + (j + 1) as f64 * dx);
            if q <= 0.0 && t < 1.0 {
                let zone_left = j > 0 && (self.q[j - 1] > 0.0 || self.theta[j - 1] > t);
                if zone_left {
                    u += segment(-sigma0, s0, s0 + t * dx);
                } else {
                    u += segment(-sigma0, s1 - t * dx, s1);
                }
            } else {
                u += segment(q - sigma0 * t, s0, s1);
            }
        }
        self.shape.depth_at(x, &grid, &self.h) - approach + u
    }

    /// The slope (per cell) of [`Self::interpolated_gap`] at `c`.
    pub(super) fn interpolated_slope(&self, c: f64) -> f64 {
        let n = self.h.len();
        let gap = |j: usize| if self.q[j] > 0.0 { 0.0 } else { self.gap[j] };
        let x = (c - 0.5).clamp(0.0, (n - 1) as f64);
        let j = (x.floor() as usize).min(n - 2);
        gap(j + 1) - gap(j)
    }

    /// Whether cell `i` belongs to the Dugdale zone on whole cells: in contact,
    /// or the gap at one of its edges ([`Self::compute_edge_gaps`]) below
    /// `delta_c` (the zone end then lies in the cell). Comparing the gap at
    /// the cell centre instead would misplace the end: the gap rises like
    /// `(x - c) ln|x - c|` beyond a zone end `c`, by a good part of `delta_c`
    /// within half a cell when `lambda^2 dx` is not small.
    pub(super) fn inside(&self, i: usize, delta_c: f64) -> bool {
        let left = if i > 0 { self.edge_gap[i - 1] } else { f64::INFINITY };
        self.q[i] > 0.0 || left.min(self.edge_gap[i]) < delta_c
    }

    /// The gap at the right edge of every cell (`+inf` at the domain end):
    /// the mean of the two neighbouring centre gaps plus the local correction
    /// [`EDGE_STENCIL`] of the traction (exact for piecewise-constant traction
    /// up to the truncated tail of the correction kernel, which falls like
    /// `dx/k^2`: about 1e-3 `delta_c`, unit test), and the profile at the edge.
    /// It only decides which cell holds a zone end; the end's position comes
    /// from the exact gap ([`Self::gap_at`]).
    pub(super) fn compute_edge_gaps(&mut self, sigma0: f64) {
        let n = self.h.len();
        let m = EDGE_STENCIL as isize;
        for i in 0..n {
            self.u[i] = self.q[i] - sigma0 * self.theta[i];
        }
        for i in 0..n - 1 {
            let mut corr = 0.0;
            for (k, d) in (-m - 1..=m).zip(&self.edge_kernel) {
                let j = i as isize - k;
                if j >= 0 && (j as usize) < n {
                    corr += d * self.u[j as usize];
                }
            }
            self.edge_gap[i] = 0.5 * (self.gap[i] + self.gap[i + 1] - self.h[i] - self.h[i + 1]) + self.h_edge[i] + corr;
        }
        self.edge_gap[n - 1] = f64::INFINITY;
    }
}
