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
//! * **Zone membership on whole cells.** A cell not in contact is cohesive
//!   when the gap at one of its *edges* is below `delta_c`
//!   (`ContactSolver::inside`), not the gap at its centre: beyond a zone end
//!   `c` the gap rises like `(x - c) ln|x - c|` (the traction steps from
//!   `-sigma0` to 0 there), by a good part of `delta_c` within half a cell when
//!   `lambda^2 dx` is not small, so the centre rule misplaces the end by many
//!   cells. The edge gaps are the mean of the two centre gaps plus a local
//!   correction of the traction over [`EDGE_STENCIL`] cells each side (exact
//!   for piecewise-constant traction up to the truncated tail, about 1e-3
//!   `delta_c`).
//! * **Zone ends within their cells** ([`SolveOptions::sub_cell_ends`], on by
//!   default). With the zone on whole cells the ends are pinned to the grid:
//!   a band of end positions is stable, the loading and unloading paths pick
//!   opposite ends of it, and the load at a given `abar` is off by a first-order
//!   amount that is large when the zone spans few cells (0.46 of the load scale
//!   at lambda = 10 on 4096 cells). So each end `c` (cell units) then moves
//!   continuously: the end cell carries `-sigma0 theta`, `theta` its covered
//!   fraction, and a safeguarded secant iteration on `c` (moving the way the
//!   sign of the residual asks until a sign change is bracketed, then secant
//!   and bisection) solves the Dugdale end condition `g(c) = delta_c`, the gap
//!   at the point `c` computed exactly from every cell's traction (the end cell
//!   taken as `-sigma0` on its covered part), to [`END_TOL`]` delta_c`; the
//!   contact is re-solved with the zone held after each step. A state starts
//!   from the previous state's ends (continuation) and keeps them if no cell
//!   more than 1.5 cells from an end changes sides; otherwise the zone is
//!   converged on whole cells first and its ends placed from there. Where no
//!   end position is found (past a jump the whole-cell state is held by the
//!   grid), the whole-cell iteration restarts from where the ends went and the
//!   placement is tried once more; failing that the whole-cell state is
//!   returned with `State::zone_ends_placed = false`. This is the collocation
//!   of the Dugdale-Maugis end condition at the end itself, as in the
//!   semi-analytical model (the strip end `c` where the opening reaches
//!   `delta_c`); the equilibrium at the interior cells is unchanged.
//! * **Stopping criterion.** The natural complementarity residual
//!   `r = max_i |min(q_i, g_i / K_0)|` (`K_0` the self-influence, so that
//!   `g/K_0` is a traction) must fall below `tol * max(max q, sigma0, 1e-300)`
//!   on a freshly computed gap, and every cell must obey the Dugdale law
//!   (the zone is consistent with the gap; with placed ends, every cell away
//!   from the ends, and `|g(c) - delta_c| <= END_TOL delta_c` at the ends).
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
    /// Place every Dugdale-zone end within its cell (secant iteration on the
    /// end position, see the module docs); `false`: zone ends on cell edges.
    pub sub_cell_ends: bool,
}

impl Default for SolveOptions {
    fn default() -> Self {
        SolveOptions { tol: 1e-9, max_cg: 20_000, max_zone_updates: 2_000, sub_cell_ends: true }
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
    /// Whether every Dugdale-zone end was placed within its cell
    /// ([`SolveOptions::sub_cell_ends`]); `false` when that option is off, and
    /// when no placed-end equilibrium was found near the state: its zone then
    /// ends on cell edges and carries the grid-pinning error (docs/solver.md).
    pub zone_ends_placed: bool,
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
    /// The profile (for its depth between cell centres at a zone end).
    shape: Profile,
    /// The profile at the right edge of every cell.
    h_edge: Vec<f64>,
    /// Gap at the right edge of every cell ([`Self::compute_edge_gaps`]).
    edge_gap: Vec<f64>,
    /// `D_k`, `k = -EDGE_STENCIL-1 ..= EDGE_STENCIL`: displacement at the right
    /// edge of cell `i` from unit traction on cell `i - k`, minus the mean of
    /// the displacements at the centres of cells `i` and `i + 1`.
    edge_kernel: Vec<f64>,
    adhesion: Adhesion,
    opts: SolveOptions,
    /// Shifted traction `q = p + sigma0 1_S` (warm start).
    q: Vec<f64>,
    /// Dugdale zone `S`: contact cells and the cells with `theta > 0` (warm start).
    zone: Vec<bool>,
    /// Cohesive fraction of each zone cell, in `[0, 1]`: the cohesive traction
    /// is `-sigma0 theta`. 1 inside the zone, fractional only in the cell that
    /// holds a zone end once the ends are placed within their cells
    /// ([`SolveOptions::sub_cell_ends`]).
    theta: Vec<f64>,
    gap: Vec<f64>,
    traction: Vec<f64>,
    /// `sigma0 K 1_S`, the displacement of the cohesive traction.
    kz: Vec<f64>,
    /// The zone ends placed in the last solved state, `(side, position)`
    /// (empty: the zone ended on cell edges).
    last_ends: Vec<(i8, f64)>,
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

/// The warm-start state saved before a zone-end placement: `q`, `theta`,
/// zone, gap, `kz`.
type Snapshot = (Vec<f64>, Vec<f64>, Vec<bool>, Vec<f64>, Vec<f64>);

/// A solved state's warm start ([`ContactSolver::warm_start`]): the next
/// solve after [`ContactSolver::resume`] continues from it, as it would right
/// after that state (the reloading leg of [`crate::path::cycle`] resumes from an
/// unloading state).
#[derive(Debug, Clone)]
pub struct WarmStart {
    saved: Snapshot,
    last_ends: Vec<(i8, f64)>,
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
    /// A solver for `profile` on `grid` (a free half-plane), datum `datum`
    /// (`None`: the domain width).
    pub fn new(grid: Grid, datum: Option<f64>, profile: &Profile, adhesion: Adhesion, opts: SolveOptions) -> Result<Self> {
        ContactSolver::with_operator(HalfPlane::new(grid, datum)?, profile, adhesion, opts)
    }

    /// A solver on a periodic half-plane of period `2X` ([`HalfPlane::periodic`];
    /// `datum` `None`: the period). The contact and the zone of each period
    /// must stay inside `(-X, X)`: [`crate::path::cycle`] stops with
    /// [`SolverError::DomainTooSmall`] when they reach an end.
    pub fn periodic(grid: Grid, datum: Option<f64>, profile: &Profile, adhesion: Adhesion, opts: SolveOptions) -> Result<Self> {
        ContactSolver::with_operator(HalfPlane::periodic(grid, datum)?, profile, adhesion, opts)
    }

    fn with_operator(op: HalfPlane, profile: &Profile, adhesion: Adhesion, opts: SolveOptions) -> Result<Self> {
        if !(opts.tol > 0.0 && opts.tol < 1.0) || opts.max_cg == 0 || opts.max_zone_updates == 0 {
            return Err(SolverError::Domain {
                what: "solve options: tol must lie in (0, 1) and the iteration caps must be positive".into(),
            });
        }
        let grid = op.grid();
        let h = profile.sample(&grid)?;
        let n = grid.cells();
        let dx = grid.dx();
        let h_edge: Vec<f64> = (0..n).map(|i| profile.depth_at(grid.x(i) + 0.5 * dx, &grid, &h)).collect();
        let m = EDGE_STENCIL as isize;
        let edge_kernel: Vec<f64> = (-m - 1..=m)
            .map(|k| {
                // Unit traction on [-dx/2, dx/2]; the edge at (k + 1/2) dx, the
                // centres at k dx and (k + 1) dx (the datum terms cancel).
                let at = |t: f64| op.segment_influence(t, -0.5 * dx, 0.5 * dx);
                let kf = k as f64;
                at((kf + 0.5) * dx) - 0.5 * (at(kf * dx) + at((kf + 1.0) * dx))
            })
            .collect();
        Ok(ContactSolver {
            op,
            h,
            shape: profile.clone(),
            h_edge,
            edge_gap: vec![f64::INFINITY; n],
            edge_kernel,
            adhesion,
            opts,
            q: vec![0.0; n],
            zone: vec![false; n],
            theta: vec![0.0; n],
            gap: vec![0.0; n],
            traction: vec![0.0; n],
            kz: vec![0.0; n],
            free: vec![false; n],
            last_ends: Vec::new(),
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

    /// The lowest point of the profile over the cell centres and edges.
    pub fn profile_min(&self) -> f64 {
        self.h.iter().chain(&self.h_edge).copied().fold(f64::INFINITY, f64::min)
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
        self.theta.iter_mut().for_each(|v| *v = 0.0);
        self.last_ends.clear();
    }

    /// The warm start the next solve would use (the last solved state's).
    pub fn warm_start(&self) -> WarmStart {
        WarmStart { saved: self.snapshot(), last_ends: self.last_ends.clone() }
    }

    /// Continues from `start` (taken by [`Self::warm_start`] of this solver).
    pub fn resume(&mut self, start: &WarmStart) {
        self.restore(start.saved.clone());
        self.last_ends.clone_from(&start.last_ends);
    }

    /// Solves for the equilibrium at approach `approach`, warm-started from the
    /// previous state.
    pub fn solve(&mut self, approach: f64) -> Result<State> {
        crate::error::finite(approach, "the approach")?;
        let (sigma0, delta_c) = self.adhesion.strength_and_range();
        let products0 = self.op.products();
        let (mut it, mut zone_updates, mut residual) = (0, 0, 0.0);
        let mut placed = false;
        // 1. Continuation: the previous state's zone ends, moved within their
        //    cells, if no cell away from them changes sides.
        if self.opts.sub_cell_ends && !self.last_ends.is_empty() {
            let saved = self.snapshot();
            let start: Vec<(i8, f64)> = self.last_ends.clone();
            self.refresh_gap(approach);
            let attempt = self.relax(approach, false).and_then(|(cg, _, _)| {
                let (cg2, res) = self.place_zone_ends(approach, sigma0, delta_c, Some(&start))?;
                Ok((cg + cg2, res))
            });
            match attempt {
                Ok((cg, res)) if self.consistent_away_from_ends(sigma0, delta_c) => {
                    it += cg;
                    residual = res;
                    placed = true;
                }
                Ok((cg, _)) => {
                    it += cg;
                    self.restore(saved);
                }
                Err(SolverError::NoConvergence { iterations, .. }) => {
                    it += iterations;
                    self.restore(saved);
                }
                Err(e) => return Err(e),
            }
        }
        // 2. The zone on whole cells, then its ends placed within their cells.
        if !placed {
            let (cg, updates, res) = self.relax_on_whole_cells(approach, sigma0)?;
            it += cg;
            zone_updates += updates;
            residual = res;
            let saved_residual = res;
            if self.opts.sub_cell_ends {
                let saved = self.snapshot();
                for attempt in 0..3 {
                    match self.place_zone_ends(approach, sigma0, delta_c, None) {
                        Ok((cg, res)) => {
                            it += cg;
                            residual = res;
                            placed = true;
                            break;
                        }
                        Err(SolverError::NoConvergence { iterations, .. }) => {
                            it += iterations;
                            if attempt < 2 {
                                // No zone end in reach of the whole-cell state (it
                                // is held by the grid past a jump, e.g. beyond
                                // pull-off): the zone on whole cells again, first
                                // from where the ends went, then from no contact
                                // and no zone (the state the jump lands on).
                                if attempt == 1 {
                                    self.reset();
                                }
                                let (cg, updates, res) = self.relax_on_whole_cells(approach, sigma0)?;
                                it += cg;
                                zone_updates += updates;
                                residual = res;
                            } else {
                                // Keep the zone on whole cells (State::zone_ends_placed false).
                                self.restore(saved.clone());
                                residual = saved_residual;
                            }
                        }
                        Err(e) => return Err(e),
                    }
                }
            }
        }
        if !placed {
            self.last_ends.clear();
        }
        let products = self.op.products() - products0;
        let mut state = self.summarise(approach, sigma0, it, zone_updates, residual, products);
        state.zone_ends_placed = placed;
        Ok(state)
    }

    /// Every zone cell whole (`theta` 1), then the constrained CG with the
    /// zone updated on whole cells ([`Self::relax`]).
    fn relax_on_whole_cells(&mut self, approach: f64, sigma0: f64) -> Result<(usize, usize, f64)> {
        for i in 0..self.h.len() {
            self.theta[i] = if self.zone[i] { 1.0 } else { 0.0 };
            self.r[i] = sigma0 * self.theta[i];
        }
        self.op.apply(&self.r, &mut self.kz);
        self.refresh_gap(approach);
        self.relax(approach, true)
    }

    fn snapshot(&self) -> Snapshot {
        (self.q.clone(), self.theta.clone(), self.zone.clone(), self.gap.clone(), self.kz.clone())
    }

    fn restore(&mut self, saved: Snapshot) {
        (self.q, self.theta, self.zone, self.gap, self.kz) = saved;
    }

    /// Whether every cell more than two cells away from a placed zone end
    /// obeys the whole-cell zone rule ([`Self::inside`]): no cohesive cell or
    /// contact appeared or vanished elsewhere.
    fn consistent_away_from_ends(&mut self, sigma0: f64, delta_c: f64) -> bool {
        self.compute_edge_gaps(sigma0);
        let near = |i: usize| self.last_ends.iter().any(|&(_, c)| (i as f64 + 0.5 - c).abs() <= 1.5);
        (0..self.h.len()).all(|i| near(i) || self.inside(i, delta_c) == self.zone[i])
    }

    /// The constrained CG from the current `q`, `theta` and gap; with
    /// `free_zone` the Dugdale zone is updated on whole cells inside the
    /// iteration, otherwise it is held. Returns the CG iterations, the zone
    /// updates and the final relative residual.
    fn relax(&mut self, approach: f64, free_zone: bool) -> Result<(usize, usize, f64)> {
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

    /// Places every Dugdale-zone end within its cell (the module docs, "Zone
    /// ends"): with the zone on whole cells converged, each end position `c`
    /// (cell units: cell `j` covers `[j, j + 1]`) is moved by a safeguarded
    /// secant iteration until the gap, interpolated linearly between cell
    /// centres, equals `delta_c` at `c` to [`END_TOL`]` delta_c`; the end cell
    /// carries the cohesive traction `-sigma0 theta`, `theta` its covered
    /// fraction, and the contact is re-solved with the zone held after each
    /// step. Returns the CG iterations and the final residual.
    fn place_zone_ends(&mut self, approach: f64, sigma0: f64, delta_c: f64, start: Option<&[(i8, f64)]>) -> Result<(usize, f64)> {
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
    fn gap_at(&self, c: f64, approach: f64) -> f64 {
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
    fn interpolated_slope(&self, c: f64) -> f64 {
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
    fn inside(&self, i: usize, delta_c: f64) -> bool {
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
    fn compute_edge_gaps(&mut self, sigma0: f64) {
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
        for i in 0..n {
            if self.q[i] > 0.0 {
                if !self.zone[i] || self.theta[i] < 1.0 {
                    // A contact cell joins: its representation changes, not its traction.
                    self.zone[i] = true;
                    self.q[i] += sigma0 * (1.0 - self.theta[i]);
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
            self.traction[i] = self.q[i] - sigma0 * self.theta[i];
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
                adhesive -= self.theta[i] * (1.0 - lambda * g) * dx;
            }
        }
        // Zone ends: a partial end cell is covered from the zone side.
        let theta = &self.theta;
        let edge = |(a, b): (usize, usize)| (grid.x(a) + (0.5 - theta[a]) * dx, grid.x(b) - (0.5 - theta[b]) * dx);
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
            zone_ends_placed: false,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The edge gaps of the whole-cell zone rule (centre mean plus local
    /// correction) agree with the gap computed exactly at the edge from every
    /// cell's traction to 2e-3 delta_c, in a state with contact and a Dugdale
    /// zone.
    #[test]
    fn edge_gaps_match_the_exact_gap_at_the_edges() {
        let lambda = 4.0;
        let grid = Grid::new(512, 3.0).unwrap();
        let profile = Profile::wavy_cylinder(0.0, 1.0).unwrap();
        let mut s = ContactSolver::new(grid, None, &profile, Adhesion::dugdale(lambda).unwrap(), SolveOptions::default()).unwrap();
        let approach = 1.0;
        let st = s.solve(approach).unwrap();
        assert!(st.abar > 0.5 && st.zone_ends_placed);
        // Whole cells, so that the exact gap sees the same uniform tractions.
        for i in 0..512 {
            s.theta[i] = if s.zone[i] { 1.0 } else { 0.0 };
        }
        let (sigma0, _) = s.adhesion.strength_and_range();
        for i in 0..512 {
            s.r[i] = sigma0 * s.theta[i];
        }
        s.op.apply(&s.r, &mut s.kz);
        s.refresh_gap(approach);
        s.compute_edge_gaps(sigma0);
        let worst = (0..511).map(|i| (s.edge_gap[i] - s.gap_at((i + 1) as f64, approach)).abs()).fold(0.0, f64::max);
        // The truncated tail of the correction leaves about 1e-3 delta_c
        // (measured 7e-4): enough to pick the cell that holds a zone end, whose
        // position is then found from the exact gap.
        assert!(worst < 2e-3 / lambda, "edge gap off by {worst}");
    }

    #[test]
    fn runs_of_a_mask() {
        let m = [false, true, true, false, true, false, false, true];
        assert_eq!(runs(m.iter().copied()), vec![(1, 2), (4, 4), (7, 7)]);
        assert!(runs([false, false].iter().copied()).is_empty());
    }
}
