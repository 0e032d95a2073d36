//! The inner iteration of a [`ContactSolver`] state ("Method" in [`super`]):
//! Polonsky-Keer constrained conjugate gradients on the contact traction with
//! the Dugdale zone held or updated on whole cells inside the iteration, and
//! the zone's fixed-point update with its Aitken extension of a run that keeps
//! growing or shrinking (the extension changes the cost, not the answer:
//! convergence is declared only when every cell obeys the law).

use super::{runs, ContactSolver, LOOSE_TOL, MAX_ZONE_EXTRAPOLATION, REFRESH_EVERY, ZONE_RATIO};
use crate::error::{Result, SolverError};

impl ContactSolver {
    /// The constrained CG from the current `q`, `theta` and gap; with
    /// `free_zone` the Dugdale zone is updated on whole cells inside the
    /// iteration, otherwise it is held. Returns the CG iterations, the zone
    /// updates and the final relative residual.
    pub(super) fn relax(&mut self, approach: f64, free_zone: bool) -> Result<(usize, usize, f64)> {
        let (sigma0, delta_c) = self.adhesion.strength_and_range();
        let n = self.h.len();
        let k0 = self.op.coefficient(0);
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
            if free_zone {
                self.compute_edge_gaps(sigma0);
            }
            for i in 0..n {
                let (q, g) = (self.q[i], self.gap[i]);
                qmax = qmax.max(q);
                res = res.max(q.min(g / k0).abs());
                if free_zone {
                    inconsistent += usize::from(self.inside(i, delta_c) != self.zone[i]);
                }
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
        Ok((it, zone_updates, residual))
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
    pub(super) fn update_zone(&mut self, sigma0: f64, delta_c: f64) {
        let n = self.h.len();
        // r: +1 cell joins, -1 cell leaves, 0 unchanged (cohesive cells only;
        // contact cells only change representation).
        let (mut added, mut removed) = (0usize, 0usize);
        for i in 0..n {
            let inside = self.inside(i, delta_c);
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
        // `z` (free between CG steps: the next step recomputes it) collects
        // the representation changes of contact cells.
        let mut joined = false;
        for i in 0..n {
            self.z[i] = 0.0;
            if self.q[i] > 0.0 {
                if !self.zone[i] || self.theta[i] < 1.0 {
                    // A contact cell joins: its representation changes, not its
                    // traction. `q` and `kz` both gain `sigma0 (1 - theta)` on it,
                    // so the gap `K q + h - Delta - kz` is unchanged.
                    self.z[i] = sigma0 * (1.0 - self.theta[i]);
                    joined = true;
                    self.zone[i] = true;
                    self.q[i] += self.z[i];
                    self.theta[i] = 1.0;
                }
            } else if self.r[i] != 0.0 {
                let t = if self.r[i] > 0.0 { 1.0 } else { 0.0 };
                self.r[i] = sigma0 * (t - self.theta[i]);
                self.zone[i] = t > 0.0;
                self.theta[i] = t;
            }
        }
        self.op.apply(&self.r, &mut self.u);
        for i in 0..n {
            self.kz[i] += self.u[i];
            self.gap[i] -= self.u[i];
        }
        if joined {
            // `kz = sigma0 K theta` must hold: a gap refreshed from scratch
            // would otherwise overstate the gap by `K z` (the contact would
            // shrink, and at worst vanish, while the incremental gap agrees).
            self.op.apply(&self.z, &mut self.kdir);
            for i in 0..n {
                self.kz[i] += self.kdir[i];
            }
        }
    }

    /// Extends the runs of changes marked in `r` (`direction` +1: joining
    /// cells, -1: leaving cells) outward from the zone interval they grow or
    /// shrink, by `omega` times their length, over cohesive cells only.
    pub(super) fn extend_zone_runs(&mut self, direction: i8, omega: f64) {
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
}
