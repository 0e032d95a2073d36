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
//! * **Dugdale zone (outer loop).** The zone `S` (contact plus cohesive cells)
//!   is held fixed; the unknown is the shifted traction `q = p + sigma0 1_S >= 0`,
//!   non-zero only in contact. With `S` fixed this is a frictionless
//!   non-adhesive problem with a known extra load: `g = K q + b`,
//!   `b = h - Delta - sigma0 K 1_S`, `q >= 0`, `g >= 0`, `q g = 0`, a convex
//!   bound-constrained quadratic program (`K` is symmetric positive definite,
//!   see the datum condition in [`crate::elastic`]). Then `S` is replaced by
//!   `{q > 0} u {g < delta_c}` and the program is solved again, warm-started,
//!   until `S` no longer changes. This is the cohesive-zone treatment of
//!   Bazrafshan, de Rooij, Valefi and Schipper (Tribol. Int. 112, 2017, 117) and
//!   of the Dugdale case of Rey, Anciaux and Molinari (Comput. Mech. 60, 2017,
//!   69), who update the adhesive zone from the current gap around a
//!   Polonsky-Keer solve.
//! * **Contact (inner loop).** Polonsky and Keer (Wear 231, 1999, 206),
//!   displacement-controlled form: conjugate directions restricted to the
//!   cells in contact, projection onto `q >= 0`, cells with negative gap
//!   outside the contact added with a steepest-descent step and the conjugacy
//!   reset. Convex problem, so it converges from any start.
//! * **Stopping criterion.** The natural complementarity residual
//!   `r = max_i |min(q_i, g_i / K_0)|` (`K_0` the self-influence, so that
//!   `g/K_0` is a traction) must fall below `tol * max(max q, sigma0, 1e-300)`.
//!   The outer loop stops when the zone is unchanged, i.e. every cell satisfies
//!   the Dugdale law exactly at the converged `q`.
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

/// Inner tolerance while the Dugdale zone is still changing.
const LOOSE_TOL: f64 = 1e-5;

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
    b: Vec<f64>,
    u: Vec<f64>,
    dir: Vec<f64>,
    kdir: Vec<f64>,
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
            b: vec![0.0; n],
            u: vec![0.0; n],
            dir: vec![0.0; n],
            kdir: vec![0.0; n],
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
        let mut cg_total = 0;
        let mut updates = 0;
        let mut residual;
        // Inner solves are loose while the zone still moves, strict once it is settled.
        let loose = self.opts.tol.max(LOOSE_TOL);
        let mut strict = false;
        loop {
            // b = h - Delta - sigma0 K 1_S
            for i in 0..n {
                self.u[i] = if self.zone[i] { sigma0 } else { 0.0 };
            }
            let ones = std::mem::take(&mut self.u);
            let mut ku = std::mem::take(&mut self.kdir);
            self.op.apply(&ones, &mut ku);
            self.u = ones;
            for i in 0..n {
                self.b[i] = self.h[i] - approach - ku[i];
            }
            self.kdir = ku;
            let (iters, res) = self.contact_cg(if strict { self.opts.tol } else { loose })?;
            cg_total += iters;
            residual = res;
            // New zone from the converged gap.
            let mut changed = false;
            for i in 0..n {
                let inside = self.q[i] > 0.0 || (delta_c > 0.0 && self.gap[i] < delta_c);
                if inside != self.zone[i] {
                    self.zone[i] = inside;
                    changed = true;
                }
            }
            if !changed {
                if strict {
                    break;
                }
                strict = true;
                continue;
            }
            strict = false;
            updates += 1;
            if updates >= self.opts.max_zone_updates {
                return Err(SolverError::NoConvergence {
                    what: "Dugdale-zone update",
                    iterations: updates,
                    residual,
                });
            }
        }
        Ok(self.summarise(approach, sigma0, cg_total, updates, residual))
    }

    /// Polonsky-Keer CG on `q >= 0` for `g = K q + b`; leaves `g` in `self.gap`.
    fn contact_cg(&mut self, tol: f64) -> Result<(usize, f64)> {
        let n = self.q.len();
        let k0 = self.op.coefficient(0);
        let (sigma0, _) = self.adhesion.strength_and_range();
        let mut conjugate = false;
        let mut g_old = 1.0;
        self.dir.iter_mut().for_each(|v| *v = 0.0);
        for it in 0..=self.opts.max_cg {
            let q = std::mem::take(&mut self.q);
            self.op.apply(&q, &mut self.u);
            self.q = q;
            let mut qmax: f64 = 0.0;
            let mut res: f64 = 0.0;
            let mut any_contact = false;
            for i in 0..n {
                self.gap[i] = self.u[i] + self.b[i];
                qmax = qmax.max(self.q[i]);
                res = res.max(self.q[i].min(self.gap[i] / k0).abs());
                any_contact |= self.q[i] > 0.0;
            }
            let scale = qmax.max(sigma0).max(1e-300);
            if !res.is_finite() {
                return Err(SolverError::NoConvergence { what: "contact CG", iterations: it, residual: res });
            }
            if res <= tol * scale {
                return Ok((it, res / scale));
            }
            if it == self.opts.max_cg {
                return Err(SolverError::NoConvergence { what: "contact CG", iterations: it, residual: res / scale });
            }
            if !any_contact {
                // Seed: cells that penetrate get the traction that would close them alone.
                for i in 0..n {
                    if self.gap[i] < 0.0 {
                        self.q[i] = -self.gap[i] / k0;
                    }
                }
                conjugate = false;
                continue;
            }
            let big_g: f64 = (0..n).filter(|&i| self.q[i] > 0.0).map(|i| self.gap[i] * self.gap[i]).sum();
            let beta = if conjugate { big_g / g_old } else { 0.0 };
            for i in 0..n {
                self.dir[i] = if self.q[i] > 0.0 { self.gap[i] + beta * self.dir[i] } else { 0.0 };
            }
            g_old = big_g;
            let dir = std::mem::take(&mut self.dir);
            self.op.apply(&dir, &mut self.kdir);
            self.dir = dir;
            let (mut num, mut den) = (0.0, 0.0);
            for i in 0..n {
                if self.q[i] > 0.0 {
                    num += self.gap[i] * self.dir[i];
                    den += self.kdir[i] * self.dir[i];
                }
            }
            if !(den > 0.0) {
                return Err(SolverError::NoConvergence { what: "contact CG (lost positivity)", iterations: it, residual: res / scale });
            }
            let tau = num / den;
            let mut overlap = false;
            for i in 0..n {
                if self.q[i] > 0.0 {
                    self.q[i] = (self.q[i] - tau * self.dir[i]).max(0.0);
                } else if self.gap[i] < 0.0 {
                    self.q[i] = -tau * self.gap[i];
                    overlap = true;
                }
            }
            conjugate = !overlap;
        }
        unreachable!("the loop returns at it == max_cg")
    }

    fn summarise(&mut self, approach: f64, sigma0: f64, cg: usize, updates: usize, residual: f64) -> State {
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
