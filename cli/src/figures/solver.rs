//! The solver's side of `maugis figures`: one displacement-controlled cycle per
//! parameter set (`maugis_solver::run::simulate`, as `maugis simulate` runs it),
//! its states per leg, and the traction, displacement and gap of one state of
//! a leg, got by replaying the leg's approaches on a fresh solver (the cycle
//! keeps the states' summaries, not their fields).

use maugis_solver::contact::{ContactSolver, SolveOptions};
use maugis_solver::grid::Grid;
use maugis_solver::profile::{Adhesion, Profile};
use maugis_solver::run::{simulate, Simulation, SimulationSpec};

/// One simulated state, as drawn.
#[derive(Clone, Copy, Debug)]
pub struct SolverState {
    /// The total intimate contact half-width ([`total_half_width`]), the
    /// paper's abscissa for its numerical results.
    pub abar: f64,
    pub load: f64,
    pub intervals: usize,
}

/// One leg of a simulated cycle.
#[derive(Clone, Debug)]
pub struct SolverLeg {
    pub unloading: bool,
    pub states: Vec<SolverState>,
}

/// The fields of one simulated state over `x >= 0`: rows `[x, pbar, ubar, gbar]`
/// in the model's convention (traction tensile positive over the cohesive
/// stress, `ubar = hbar - gbar`).
#[derive(Clone, Debug)]
pub struct SolverProfile {
    /// Total intimate contact half-width ([`total_half_width`]).
    pub abar: f64,
    /// Outermost contact half-width (`State::abar`).
    pub outer: f64,
    pub intervals: usize,
    pub samples: Vec<[f64; 4]>,
}

/// Half the total length of the contact intervals: the outermost half-width
/// (`State::abar`) while the contact is one interval; less once it has
/// cavitated, where the paper's "total intimate contact area" changes
/// continuously while the outermost edge jumps from crest to crest.
pub fn total_half_width(s: &maugis_solver::contact::State) -> f64 {
    s.contact.iter().map(|(l, r)| r - l).sum::<f64>() / 2.0
}

/// A simulated cycle and its legs.
pub struct SolverRun {
    pub sim: Simulation,
    pub legs: Vec<SolverLeg>,
}

/// Runs the cycle of `spec`; `tick` after every state.
pub fn run(spec: SimulationSpec, tick: &(dyn Fn() + Sync)) -> Result<SolverRun, String> {
    let sim = simulate(spec, &mut |_, _| tick()).map_err(|e| format!("solver at lambda = {}, alpha = {}, beta = {}: {e}", spec.lambda, spec.alpha, spec.beta))?;
    let leg = |unloading: bool, list: &[maugis_solver::contact::State]| SolverLeg {
        unloading,
        states: list.iter().map(|s| SolverState { abar: total_half_width(s), load: s.load, intervals: s.contact_intervals() }).collect(),
    };
    let legs = vec![leg(false, &sim.cycle.loading), leg(true, &sim.cycle.unloading)];
    Ok(SolverRun { sim, legs })
}

/// The state of the leg (`unloading` or loading) whose total contact
/// half-width is nearest `abar`, with its fields: the leg is replayed up to it on a solver
/// set up as [`simulate`] sets it up.
pub fn profile_near(r: &SolverRun, unloading: bool, abar: f64) -> Result<SolverProfile, String> {
    let (cycle, spec) = (&r.sim.cycle, r.sim.spec);
    let leg = if unloading { &cycle.unloading } else { &cycle.loading };
    let k = leg
        .iter()
        .enumerate()
        .filter(|(_, s)| s.abar > 0.0)
        .min_by(|a, b| (total_half_width(a.1) - abar).abs().total_cmp(&(total_half_width(b.1) - abar).abs()))
        .map(|(k, _)| k)
        .ok_or("the solver's leg has no state in contact")?;
    let err = |e: maugis_solver::error::SolverError| e.to_string();
    let grid = Grid::new(spec.cells, r.sim.half_width).map_err(err)?;
    let profile = Profile::wavy_cylinder(spec.alpha, spec.beta).map_err(err)?;
    let mut solver = ContactSolver::new(grid, None, &profile, Adhesion::dugdale(spec.lambda).map_err(err)?, SolveOptions::default()).map_err(err)?;
    let path = if unloading { cycle.loading.iter().chain(&cycle.unloading[..=k]) } else { cycle.loading[..=k].iter().chain(&cycle.unloading[..0]) };
    let mut last = None;
    for s in path {
        last = Some(solver.solve(s.approach).map_err(err)?);
    }
    let state = last.ok_or("empty replay")?;
    let (gap, traction, h) = (solver.gap(), solver.traction(), solver.profile());
    let samples = grid
        .centres()
        .into_iter()
        .enumerate()
        .filter(|(_, x)| *x >= 0.0)
        .map(|(i, x)| [x, -traction[i] / spec.lambda, h[i] - gap[i], gap[i]])
        .collect();
    Ok(SolverProfile { abar: total_half_width(&state), outer: state.abar, intervals: state.contact_intervals(), samples })
}
