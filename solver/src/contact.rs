//! One equilibrium state at a prescribed approach: Polonsky-Keer constrained
//! conjugate gradients inside a Dugdale-zone fixed point.
//!
//! # Problem
//!
//! On the grid, with `u = K p` ([`crate::elastic`]), compressive traction `p`
//! positive, approach `Delta` (relative to the datum) and gap
//! `g = h - Delta + u`, find `p` with
//!
//! * contact: `g_i = 0` and `p_i >= -sigma0`;
//! * Dugdale zone: `0 < g_i < delta_c` and `p_i = -sigma0`;
//! * outside: `g_i >= delta_c` and `p_i = 0`.
//!
//! # Method
//!
//! * **Dugdale zone.** With the zone `S` (contact plus cohesive cells) fixed,
//!   the unknown is the shifted traction `q = p + sigma0 1_S >= 0`, non-zero
//!   only in contact: `g = K q + b`, `b = h - Delta - sigma0 K 1_S`, `q >= 0`,
//!   `g >= 0`, `q g = 0`, a convex bound-constrained quadratic program (`K` is
//!   symmetric positive definite, see the datum condition in
//!   [`crate::elastic`]). `S` is replaced by `{q > 0} u {g < delta_c}` inside
//!   the same iteration, as soon as the contact residual has fallen by
//!   [`ZONE_RATIO`] since the last zone change (an inexact fixed point: the
//!   cohesive zone is updated from the current gap during the constrained CG,
//!   as in the adhesive Polonsky-Keer of Rey, Anciaux and Molinari, Comput.
//!   Mech. 60, 2017, 69; also Bazrafshan, de Rooij, Valefi and Schipper,
//!   Tribol. Int. 112, 2017, 117). A zone change costs one product (the
//!   cohesive traction's displacement is updated, not recomputed), keeps the
//!   traction of contact cells, and resets the conjugacy. Successive changes
//!   in the same direction are extrapolated (Aitken, see `update_zone`).
//! * **Contact.** Polonsky and Keer (Wear 231, 1999, 206), displacement
//!   controlled, preconditioned as in Vollebregt's BCCG-FP (J. Comput. Phys.
//!   257, 2014, 333): the free set is the cells in contact plus the cells that
//!   penetrate; the residual (the gap) on it is preconditioned by the inverse
//!   circulant `C ~ K^-1` ([`HalfPlane::precondition`]), restricted to the
//!   free set, and conjugated (Fletcher-Reeves with `r.z`) while the free set
//!   is unchanged and no cell was projected; the step is exact along the
//!   direction, then `q` is projected onto `q >= 0`. The preconditioner makes
//!   the iteration count nearly independent of the grid (about 25 to 50 per
//!   state along a path, against 1000 to 3000 without it at 4096 cells). The
//!   gap is updated by `g -= tau K d` and recomputed from scratch after a
//!   projection, every [`REFRESH_EVERY`] steps and before convergence is declared.
//! * **Stopping criterion.** The natural complementarity residual
//!   `r = max_i |min(q_i, g_i / K_0)|` (`K_0` the self-influence, so that
//!   `g/K_0` is a traction) must fall below `tol * max(max q, sigma0, 1e-300)`
//!   on a freshly computed gap, and every cell must obey the Dugdale law
//!   (the zone is consistent with the gap).
//! * **Cost.** Two products (four real FFTs of length `2n`) per CG step, one
//!   per zone change; [`State::products`] counts them.
//!
//! Under displacement control a state can have several equilibria (before a
//! snap-in or pull-off); warm starts keep the solver on the branch it is
//! following, as in an experiment with a stiff machine.

use crate::elastic::HalfPlane;
use crate::error::{Result, SolverError};
use crate::grid::Grid;
use crate::profile::{Adhesion, Profile};

/// Tunables of one solve.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SolveOptions {
    /// Relative complementarity tolerance of the inner solve.
    pub tol: f64,
    /// Cap on conjugate-gradient iterations per inner solve.
    pub max_cg: usize,
    /// Cap on Dugdale-zone updates per state.
    pub max_zone_updates: usize,
}

impl Default for SolveOptions {
    fn default() -> Self {
        SolveOptions { tol: 1e-9, max_cg: 20_000, max_zone_updates: 2_000 }
    }
}

/// Relative contact residual at which an inconsistent Dugdale zone is always updated.
const LOOSE_TOL: f64 = 1e-5;
/// Otherwise the zone is updated once the contact residual has fallen by this
/// factor since the last update.
pub const ZONE_RATIO: f64 = 0.3;
/// Gap recomputed from scratch at least this often (the update `g -= tau K d`
/// accumulates rounding).
pub const REFRESH_EVERY: usize = 25;
/// Cap on the Aitken extrapolation factor of a zone update (`rho <= 0.8`).
const MAX_ZONE_EXTRAPOLATION: f64 = 4.0;

/// Summary of one converged state, in the normalised units of the
/// semi-analytical model.
#[derive(Debug, Clone, PartialEq)]
pub struct State {
    /// Approach `Delta` (units `l_v`), relative to the datum.
    pub approach: f64,
    /// Load per unit length `Lbar = sum p dx` (compressive positive).
    pub load: f64,
    /// Half-width of the outermost contact edges, `(right - left)/2`; 0 without contact.
    pub abar: f64,
    /// Contact intervals `(left edge, right edge)`, cell edges.
    pub contact: Vec<(f64, f64)>,
    /// Dugdale-zone intervals (contact plus cohesive cells), cell edges: the
    /// outermost ends are the strip ends `-c, c`.
    pub zone: Vec<(f64, f64)>,
    /// Cohesive cells between the rightmost contact edge and the right strip
    /// end (the resolution of the Dugdale zone); all zone cells without contact.
    pub zone_cells: usize,
    /// Elastic energy `(1/2) sum p u dx` (datum-dependent, units `dgamma l_h`).
    pub elastic_energy: f64,
    /// Adhesion energy `sum phi(g) dx`, `phi = -(1 - lambda g)` in the zone.
    pub adhesion_energy: f64,
    /// Conjugate-gradient iterations (all inner solves).
    pub cg_iterations: usize,
    /// Dugdale-zone updates.
    pub zone_updates: usize,
    /// FFT products (operator and preconditioner, two real FFTs each).
    pub products: usize,
    /// Final relative complementarity residual.
    pub residual: f64,
}

impl State {
    /// Number of contact intervals (more than one: cavitation).
    pub fn contact_intervals(&self) -> usize {
        self.contact.len()
    }

    /// Total potential energy `elastic + adhesion` (its derivative in the approach is the load).
    pub fn energy(&self) -> f64 {
        self.elastic_energy + self.adhesion_energy
    }
}

/// The solver: the operator, the profile, the law and the warm-start state.
pub struct ContactSolver {
    op: HalfPlane,
    h: Vec<f64>,
    adhesion: Adhesion,
    opts: SolveOptions,
    /// Shifted traction `q = p + sigma0 1_S` (warm start).
    q: Vec<f64>,
    /// Dugdale zone `S` (warm start).
    zone: Vec<bool>,
    gap: Vec<f64>,
    traction: Vec<f64>,
    /// `sigma0 K 1_S`, the displacement of the cohesive traction.
    kz: Vec<f64>,
    /// Free set of the last CG step (contact or penetrating cells).
    free: Vec<bool>,
    r: Vec<f64>,
    z: Vec<f64>,
    u: Vec<f64>,
    dir: Vec<f64>,
    kdir: Vec<f64>,
    /// Changed cells per Dugdale-zone update: the last update's direction
    /// (+1 growth, -1 shrinkage, 0 mixed) and count.
    last_zone_change: (i8, usize),
}

/// Runs of `true` in `mask` as `(first, last)` index pairs.
fn runs(mask: impl Iterator<Item = bool>) -> Vec<(usize, usize)> {
    let mut out = Vec::new();
    let mut start = None;
    let mut last = 0;
    for (i, m) in mask.enumerate() {
        match (m, start) {
            (true, None) => start = Some(i),
            (false, Some(s)) => {
                out.push((s, i - 1));
                start = None;
            }
            _ => {}
        }
        last = i;
    }
    if let Some(s) = start {
        out.push((s, last));
    }
    out
}

impl ContactSolver {
    /// A solver for `profile` on `grid`, datum `datum` (`None`: the domain width).
    pub fn new(grid: Grid, datum: Option<f64>, profile: &Profile, adhesion: Adhesion, opts: SolveOptions) -> Result<Self> {
        if !(opts.tol > 0.0 && opts.tol < 1.0) || opts.max_cg == 0 || opts.max_zone_updates == 0 {
            return Err(SolverError::Domain {
                what: "solve options: tol must lie in (0, 1) and the iteration caps must be positive".into(),
            });
        }
        let h = profile.sample(&grid)?;
        let op = HalfPlane::new(grid, datum)?;
        let n = grid.cells();
        Ok(ContactSolver {
            op,
            h,
            adhesion,
            opts,
            q: vec![0.0; n],
            zone: vec![false; n],
            gap: vec![0.0; n],
            traction: vec![0.0; n],
            kz: vec![0.0; n],
            free: vec![false; n],
            r: vec![0.0; n],
            z: vec![0.0; n],
            u: vec![0.0; n],
            dir: vec![0.0; n],
            kdir: vec![0.0; n],
            last_zone_change: (0, 0),
        })
    }

    /// The grid.
    pub fn grid(&self) -> Grid {
        self.op.grid()
    }

    /// The datum distance.
    pub fn datum(&self) -> f64 {
        self.op.datum()
    }

    /// The interface law.
    pub fn adhesion(&self) -> Adhesion {
        self.adhesion
    }

    /// The profile depth at the cell centres.
    pub fn profile(&self) -> &[f64] {
        &self.h
    }

    /// Gap at the cell centres of the last solved state.
    pub fn gap(&self) -> &[f64] {
        &self.gap
    }

    /// Traction (compressive positive) on the cells of the last solved state.
    pub fn traction(&self) -> &[f64] {
        &self.traction
    }

    /// Forgets the warm start (no contact, empty zone).
    pub fn reset(&mut self) {
        self.q.iter_mut().for_each(|v| *v = 0.0);
        self.zone.iter_mut().for_each(|v| *v = false);
    }

    /// Solves for the equilibrium at approach `approach`, warm-started from the
    /// previous state.
    pub fn solve(&mut self, approach: f64) -> Result<State> {
        crate::error::finite(approach, "the approach")?;
        let (sigma0, delta_c) = self.adhesion.strength_and_range();
        let n = self.h.len();
        let k0 = self.op.coefficient(0);
        let products0 = self.op.products();
        // kz = sigma0 K 1_S, then g = K q + h - Delta - kz.
        for i in 0..n {
            self.r[i] = if self.zone[i] { sigma0 } else { 0.0 };
        }
        self.op.apply(&self.r, &mut self.kz);
        self.refresh_gap(approach);
        self.last_zone_change = (0, 0);
        let mut fresh = true;
        let mut since_refresh = 0;
        let mut conjugate = false;
        let mut rz_old = 1.0;
        let mut zone_updates = 0;
        // The zone is updated once the contact residual has fallen by ZONE_RATIO
        // since the last update (or to the loose tolerance).
        let mut zone_target = f64::INFINITY;
        let mut residual;
        let mut it = 0;
        loop {
            let mut qmax: f64 = 0.0;
            let mut res: f64 = 0.0;
            let mut inconsistent = 0;
            for i in 0..n {
                let (q, g) = (self.q[i], self.gap[i]);
                qmax = qmax.max(q);
                res = res.max(q.min(g / k0).abs());
                let inside = q > 0.0 || g < delta_c;
                inconsistent += usize::from(inside != self.zone[i]);
            }
            let scale = qmax.max(sigma0).max(1e-300);
            if !res.is_finite() {
                return Err(SolverError::NoConvergence { what: "contact CG", iterations: it, residual: res });
            }
            residual = res / scale;
            if residual <= self.opts.tol && inconsistent == 0 {
                if fresh {
                    break;
                }
                // Confirm on a gap computed from scratch, not updated.
                self.refresh_gap(approach);
                fresh = true;
                since_refresh = 0;
                continue;
            }
            if it >= self.opts.max_cg {
                return Err(SolverError::NoConvergence { what: "contact CG", iterations: it, residual });
            }
            if inconsistent > 0 && (residual <= zone_target || residual <= LOOSE_TOL.max(self.opts.tol)) {
                self.update_zone(sigma0, delta_c);
                zone_updates += 1;
                if zone_updates >= self.opts.max_zone_updates {
                    return Err(SolverError::NoConvergence { what: "Dugdale-zone update", iterations: zone_updates, residual });
                }
                zone_target = residual * ZONE_RATIO;
                conjugate = false;
                fresh = false;
                continue;
            }
            it += 1;
            // Free set: cells in contact and cells that penetrate.
            let mut same_free_set = true;
            for i in 0..n {
                let free = self.q[i] > 0.0 || self.gap[i] < 0.0;
                same_free_set &= free == self.free[i];
                self.free[i] = free;
                self.r[i] = if free { self.gap[i] } else { 0.0 };
            }
            self.op.precondition(&self.r, &mut self.z);
            let mut rz = 0.0;
            for i in 0..n {
                if self.free[i] {
                    rz += self.r[i] * self.z[i];
                } else {
                    self.z[i] = 0.0;
                }
            }
            let beta = if conjugate && same_free_set { rz / rz_old } else { 0.0 };
            rz_old = rz;
            for i in 0..n {
                self.dir[i] = self.z[i] + beta * self.dir[i];
            }
            self.op.apply(&self.dir, &mut self.kdir);
            let (mut num, mut den) = (0.0, 0.0);
            for i in 0..n {
                if self.free[i] {
                    num += self.r[i] * self.dir[i];
                    den += self.kdir[i] * self.dir[i];
                }
            }
            if !(den > 0.0 && num > 0.0) {
                if conjugate {
                    // Lost descent through rounding: restart from the gradient.
                    conjugate = false;
                    continue;
                }
                return Err(SolverError::NoConvergence { what: "contact CG (lost positivity)", iterations: it, residual });
            }
            let tau = num / den;
            let mut projected = false;
            for i in 0..n {
                if self.free[i] {
                    let v = self.q[i] - tau * self.dir[i];
                    if v < 0.0 {
                        projected = true;
                        self.q[i] = 0.0;
                    } else {
                        self.q[i] = v;
                    }
                }
            }
            since_refresh += 1;
            if projected || since_refresh >= REFRESH_EVERY {
                self.refresh_gap(approach);
                since_refresh = 0;
                fresh = true;
            } else {
                for i in 0..n {
                    self.gap[i] -= tau * self.kdir[i];
                }
                fresh = false;
            }
            conjugate = !projected;
        }
        let products = self.op.products() - products0;
        Ok(self.summarise(approach, sigma0, it, zone_updates, residual, products))
    }

    /// `g = K q + h - Delta - kz` from scratch (one product).
    fn refresh_gap(&mut self, approach: f64) {
        self.op.apply(&self.q, &mut self.u);
        for i in 0..self.h.len() {
            self.gap[i] = self.u[i] + self.h[i] - approach - self.kz[i];
        }
    }

    /// Replaces the zone by `{q > 0} u {g < delta_c}`, keeping the traction of
    /// the contact cells (their shifted traction `q` moves by `sigma0`) and
    /// updating `kz` and the gap by the change of the cohesive traction (one
    /// product).
    ///
    /// **Acceleration.** The gap meets `delta_c` tangentially at a strip end,
    /// so the plain update moves an edge by a geometric sequence of steps
    /// (ratio `rho` about 0.6-0.7: 480, 260, 160, 100, ... cells). When two
    /// successive updates change the zone in the same direction, with
    /// `rho = count_k / count_(k-1) < 1`, every changed run that grows (or
    /// shrinks) an existing zone interval at one end is extended further in
    /// that direction by `rho/(1 - rho)` times its length, the sum of the rest
    /// of the sequence (Aitken). An overshoot is undone by the next plain
    /// update; convergence is still declared only when every cell obeys the
    /// law, so the acceleration changes the cost, not the answer.
    fn update_zone(&mut self, sigma0: f64, delta_c: f64) {
        let n = self.h.len();
        // r: +1 cell joins, -1 cell leaves, 0 unchanged (cohesive cells only;
        // contact cells only change representation).
        let (mut added, mut removed) = (0usize, 0usize);
        for i in 0..n {
            let inside = self.q[i] > 0.0 || self.gap[i] < delta_c;
            self.r[i] = 0.0;
            if inside != self.zone[i] && self.q[i] <= 0.0 {
                self.r[i] = if inside { 1.0 } else { -1.0 };
                if inside {
                    added += 1;
                } else {
                    removed += 1;
                }
            }
        }
        let direction: i8 = match (added > 0, removed > 0) {
            (true, false) => 1,
            (false, true) => -1,
            _ => 0,
        };
        let count = added + removed;
        let (last_direction, last_count) = self.last_zone_change;
        self.last_zone_change = (direction, count);
        if direction != 0 && direction == last_direction && count < last_count {
            let rho = count as f64 / last_count as f64;
            let omega = (rho / (1.0 - rho)).min(MAX_ZONE_EXTRAPOLATION);
            self.extend_zone_runs(direction, omega);
        }
        for i in 0..n {
            if self.q[i] > 0.0 {
                if !self.zone[i] {
                    // A contact cell joins: its representation changes, not its traction.
                    self.zone[i] = true;
                    self.q[i] += sigma0;
                }
            } else if self.r[i] != 0.0 {
                self.zone[i] = self.r[i] > 0.0;
                self.r[i] *= sigma0;
            }
        }
        self.op.apply(&self.r, &mut self.u);
        for i in 0..n {
            self.kz[i] += self.u[i];
            self.gap[i] -= self.u[i];
        }
    }

    /// Extends the runs of changes marked in `r` (`direction` +1: joining
    /// cells, -1: leaving cells) outward from the zone interval they grow or
    /// shrink, by `omega` times their length, over cohesive cells only.
    fn extend_zone_runs(&mut self, direction: i8, omega: f64) {
        let n = self.h.len();
        let mark = f64::from(direction);
        let changed: Vec<(usize, usize)> = runs(self.r.iter().map(|&v| v == mark));
        for (a, b) in changed {
            let extra = (omega * (b - a + 1) as f64).ceil() as usize;
            // Growth: the run is attached to the old zone on one side and
            // extends away from it. Shrinkage: the run is attached to the
            // remaining zone on one side and eats into it.
            let attached = |j: usize| -> bool {
                if direction > 0 {
                    self.zone[j]
                } else {
                    self.zone[j] && self.r[j] == 0.0
                }
            };
            let left_attached = a > 0 && attached(a - 1);
            let right_attached = b + 1 < n && attached(b + 1);
            let eligible = |j: usize, zone: &[bool], q: &[f64]| q[j] <= 0.0 && zone[j] == (direction < 0);
            let step: isize = match (left_attached, right_attached, direction > 0) {
                (true, false, true) | (false, true, false) => 1,
                (false, true, true) | (true, false, false) => -1,
                _ => continue,
            };
            let mut j = if step > 0 { b as isize + 1 } else { a as isize - 1 };
            for _ in 0..extra {
                if j < 0 || j >= n as isize || !eligible(j as usize, &self.zone, &self.q) || self.r[j as usize] != 0.0 {
                    break;
                }
                self.r[j as usize] = mark;
                j += step;
            }
        }
    }

    fn summarise(&mut self, approach: f64, sigma0: f64, cg: usize, updates: usize, residual: f64, products: usize) -> State {
        let grid = self.op.grid();
        let n = grid.cells();
        let dx = grid.dx();
        let lambda = sigma0;
        for i in 0..n {
            self.traction[i] = self.q[i] - if self.zone[i] { sigma0 } else { 0.0 };
        }
        let p = std::mem::take(&mut self.traction);
        self.op.apply(&p, &mut self.u);
        self.traction = p;
        let mut load = 0.0;
        let mut elastic = 0.0;
        let mut adhesive = 0.0;
        for i in 0..n {
            load += self.traction[i] * dx;
            elastic += 0.5 * self.traction[i] * self.u[i] * dx;
            if self.zone[i] {
                let g = if self.q[i] > 0.0 { 0.0 } else { self.gap[i] };
                adhesive -= (1.0 - lambda * g) * dx;
            }
        }
        let edge = |(a, b): (usize, usize)| (grid.x(a) - 0.5 * dx, grid.x(b) + 0.5 * dx);
        let q = &self.q;
        // Contact edges: q = p + sigma0 vanishes like sqrt(distance) at a
        // Dugdale-Maugis (and Hertz) edge, so q^2 is extrapolated linearly from
        // the two outermost contact cells to its zero (clamped to one cell).
        let contact_edge = |(a, b): (usize, usize)| {
            let sub = |inner: usize, outer: usize| {
                let (qo, qi) = (q[outer] * q[outer], q[inner] * q[inner]);
                if qi > qo { (qo / (qi - qo)).min(1.0) * dx } else { 0.5 * dx }
            };
            let left = if b > a { grid.x(a) - sub(a + 1, a) } else { grid.x(a) - 0.5 * dx };
            let right = if b > a { grid.x(b) + sub(b - 1, b) } else { grid.x(b) + 0.5 * dx };
            (left, right)
        };
        let contact_runs = runs(self.q.iter().map(|&v| v > 0.0));
        let zone_runs = runs(self.zone.iter().copied());
        let abar = match (contact_runs.first(), contact_runs.last()) {
            (Some(&(l, lb)), Some(&(ra, r))) => 0.5 * (contact_edge((ra, r)).1 - contact_edge((l, lb)).0),
            _ => 0.0,
        };
        let zone_cells = match (contact_runs.last(), zone_runs.last()) {
            (Some(&(_, cr)), Some(&(_, zr))) => zr.saturating_sub(cr),
            (None, _) => self.zone.iter().filter(|&&z| z).count(),
            _ => 0,
        };
        State {
            approach,
            load,
            abar,
            contact: contact_runs.into_iter().map(contact_edge).collect(),
            zone: zone_runs.into_iter().map(edge).collect(),
            zone_cells,
            elastic_energy: elastic,
            adhesion_energy: adhesive,
            cg_iterations: cg,
            zone_updates: updates,
            products,
            residual,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::runs;

    #[test]
    fn runs_of_a_mask() {
        let m = [false, true, true, false, true, false, false, true];
        assert_eq!(runs(m.iter().copied()), vec![(1, 2), (4, 4), (7, 7)]);
        assert!(runs([false, false].iter().copied()).is_empty());
    }
}
