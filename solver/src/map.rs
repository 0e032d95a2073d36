//! Regime maps drawn by the solver (issue 24, item 2): one simulated cycle per
//! grid point, labelled from what the solver measures, next to the
//! semi-analytical model's label at the same point.
//!
//! The grid is the model's [`SweepGrid`] (`lambda` log-spaced, a second axis:
//! `alpha`, `beta` or the Johnson parameter), numbered and sharded as
//! `maugis::contact::sweep` numbers and shards it (`k = i_lambda * n + j`; shard
//! `s` of `n` takes `k % n == s - 1`), so [`merge_maps`] reassembles shards
//! exactly.
//!
//! # Per point
//!
//! * one displacement-controlled cycle ([`crate::run::simulate`]) at the
//!   resolution [`ResolutionRule::at`] gives for the point's `lambda`;
//! * W of the closed in-contact cycle under load control and under displacement
//!   control ([`crate::dissipation`]), the part of W from loops through
//!   cavitated states, the number of loops;
//! * the instabilities met: jumps of the load-controlled loading path from a
//!   state in contact ([`crate::path::load_controlled`]);
//! * the fraction of cavitated states: in-contact states of both legs with more
//!   than one contact interval;
//! * the smooth cylinder's W at the same `lambda` and resolution (`alpha = 0`;
//!   one cycle per `lambda` row, shared by the row's points and equal to the
//!   row's `alpha = 0` point when the grid has one);
//! * the model's [`SweepPoint`] (`maugis::contact::sweep::sweep_point`).
//!
//! # The solver's label ([`SolverRegime`])
//!
//! With `excess = W - W_smooth` (load control) and the margin `m`
//! ([`MapOptions::margin`], default [`DEFAULT_MARGIN`]):
//!
//! | label | excess > m | some state cavitated |
//! |---|---|---|
//! | `dissipative` | yes | no |
//! | `both` | yes | yes |
//! | `cavitating` | no | yes |
//! | `smooth_like` | no | no |
//!
//! A point whose cycle fails (a typed [`SolverError`]) is `failed`, with the
//! error's text, and the rest of the map goes on.
//!
//! # Agreement with the model ([`labels_agree`])
//!
//! The model's `dissipative` (some valid loop) agrees with the solver's
//! `dissipative` or `both`; the model's `cavitating` (loops, all through
//! invalid states: the model's claim that cavitation removes them) with the
//! solver's `cavitating`; `smooth_like` with `smooth_like`.

#[cfg(feature = "parallel")]
use rayon::prelude::*;

use maugis::contact::sweep::{sweep_point, Regime, SweepGrid, SweepPoint};

use crate::error::{count_in_range, finite, in_range, Interval, MergeFault, Result, SolverError};
use crate::profile::AdhesionLaw;
use crate::run::{simulate_with, Simulation, SimulationOptions, SimulationSpec};

/// The default label margin over the smooth cylinder's W: 0.02 `dgamma l_h`,
/// the tolerance of W near 0 of the solver's dissipation test
/// (`solver/tests/it/dissipation.rs`).
pub const DEFAULT_MARGIN: f64 = 0.02;

/// Grid cells and approach steps of one cycle.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Resolution {
    /// Cells (a power of two).
    pub cells: usize,
    /// Approach steps per leg.
    pub steps_per_leg: usize,
}

/// How each point's resolution is chosen.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
pub enum ResolutionRule {
    /// The rule of `docs/solver-map.md` ([`ResolutionRule::at`]).
    Auto,
    /// The same resolution everywhere.
    Fixed(Resolution),
}

/// Steps per leg of [`ResolutionRule::Auto`].
pub const AUTO_STEPS: usize = 400;

impl ResolutionRule {
    /// The resolution at `lambda`. `Auto`: [`AUTO_STEPS`] approach steps per
    /// leg, 2048 cells for `lambda <= 1` and 4096 above (the convergence study
    /// in `docs/solver-map.md`: the steps set W's error, the cells matter only
    /// where the Dugdale zone is a few cells wide, at large `lambda`).
    pub fn at(&self, lambda: f64) -> Resolution {
        match *self {
            ResolutionRule::Fixed(r) => r,
            ResolutionRule::Auto => Resolution { cells: if lambda <= 1.0 { 2048 } else { 4096 }, steps_per_leg: AUTO_STEPS },
        }
    }
}

/// Options of a map.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct MapOptions {
    /// The resolution of each cycle.
    pub resolution: ResolutionRule,
    /// The label margin over the smooth cylinder's W (`>= 0`).
    pub margin: f64,
    /// The adhesion law of every cycle (maps written before the law existed read as Dugdale).
    #[cfg_attr(feature = "serde", serde(default))]
    pub law: AdhesionLaw,
}

impl Default for MapOptions {
    fn default() -> Self {
        MapOptions { resolution: ResolutionRule::Auto, margin: DEFAULT_MARGIN, law: AdhesionLaw::Dugdale }
    }
}

/// The solver's regime at one point (module docs).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
pub enum SolverRegime {
    /// W above the smooth cylinder's by more than the margin, no cavitation.
    Dissipative,
    /// Cavitation, W within the margin of the smooth cylinder's.
    Cavitating,
    /// Both.
    Both,
    /// Neither.
    SmoothLike,
    /// The cycle failed (see [`MapPoint::solver_error`]).
    Failed,
}

impl SolverRegime {
    /// The label as written in the CSV and the docs.
    pub fn name(self) -> &'static str {
        match self {
            SolverRegime::Dissipative => "dissipative",
            SolverRegime::Cavitating => "cavitating",
            SolverRegime::Both => "both",
            SolverRegime::SmoothLike => "smooth_like",
            SolverRegime::Failed => "failed",
        }
    }

    /// The label from the excess of W over the smooth cylinder's, the margin
    /// and whether some state cavitated.
    pub fn classify(excess: f64, margin: f64, cavitated: bool) -> SolverRegime {
        match (excess > margin, cavitated) {
            (true, false) => SolverRegime::Dissipative,
            (true, true) => SolverRegime::Both,
            (false, true) => SolverRegime::Cavitating,
            (false, false) => SolverRegime::SmoothLike,
        }
    }
}

/// The model's label as written in the CSV.
pub fn model_regime_name(r: Regime) -> &'static str {
    match r {
        Regime::Dissipative => "dissipative",
        Regime::Cavitating => "cavitating",
        Regime::SmoothLike => "smooth_like",
    }
}

/// Whether the solver's and the model's labels say the same (module docs).
pub fn labels_agree(solver: SolverRegime, model: Regime) -> bool {
    matches!(
        (solver, model),
        (SolverRegime::Dissipative | SolverRegime::Both, Regime::Dissipative)
            | (SolverRegime::Cavitating, Regime::Cavitating)
            | (SolverRegime::SmoothLike, Regime::SmoothLike)
    )
}

/// What one simulated cycle measures.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct CycleMeasure {
    /// The resolution it ran at.
    pub resolution: Resolution,
    /// W under load control (units of `dgamma l_h`).
    pub w: f64,
    /// The part of `w` from loops through cavitated states.
    pub w_cavitated: f64,
    /// W_d under displacement control at the model's datum (100 `l_h`).
    pub w_d: f64,
    /// Loops of the closed cycle under load control.
    pub loops: usize,
    /// Jumps of the load-controlled loading path from a state in contact.
    pub instabilities: usize,
    /// In-contact states of both legs.
    pub states_in_contact: usize,
    /// Fraction of them with more than one contact interval.
    pub cavitated_fraction: f64,
    /// The load-controlled pull-off (most tensile unloading load), if any.
    pub pull_off: Option<f64>,
}

/// Measures one simulated cycle.
pub fn measure(sim: &Simulation) -> Result<CycleMeasure> {
    let d = sim.dissipation()?;
    let (loading, unloading) = sim.load_controlled();
    let legs = || sim.cycle.loading.iter().chain(&sim.cycle.unloading).filter(|s| s.abar > 0.0);
    let in_contact = legs().count();
    let cavitated = legs().filter(|s| s.contact_intervals() > 1).count();
    Ok(CycleMeasure {
        resolution: Resolution { cells: sim.spec.cells, steps_per_leg: sim.spec.steps_per_leg },
        w: d.load_control.dissipation.total,
        w_cavitated: d.load_control.dissipation.invalid,
        w_d: d.displacement_control.dissipation.total,
        loops: d.load_control.loops.len(),
        instabilities: loading.jumps.iter().filter(|&&(from, _)| sim.cycle.loading[from].abar > 0.0).count(),
        states_in_contact: in_contact,
        cavitated_fraction: if in_contact > 0 { cavitated as f64 / in_contact as f64 } else { 0.0 },
        pull_off: unloading.pull_off.map(|(_, l)| l),
    })
}

/// Runs and measures the cycle of `(lambda, alpha, beta)` up to `amax` at
/// `resolution`, under the Dugdale law.
pub fn measure_cycle(lambda: f64, alpha: f64, beta: f64, amax: f64, resolution: Resolution) -> Result<CycleMeasure> {
    measure_cycle_under(AdhesionLaw::Dugdale, lambda, alpha, beta, amax, resolution)
}

/// [`measure_cycle`] under the adhesion law `law`.
pub fn measure_cycle_under(law: AdhesionLaw, lambda: f64, alpha: f64, beta: f64, amax: f64, resolution: Resolution) -> Result<CycleMeasure> {
    let spec = SimulationSpec { lambda, alpha, beta, amax, cells: resolution.cells, steps_per_leg: resolution.steps_per_leg };
    measure(&simulate_with(spec, SimulationOptions { law, ..SimulationOptions::default() }, &mut |_, _| {})?)
}

/// One point of a solver map.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct MapPoint {
    /// Index `k` in the grid.
    pub index: usize,
    /// Maugis parameter.
    pub lambda: f64,
    /// The second axis' value.
    pub value: f64,
    /// Amplitude.
    pub alpha: f64,
    /// Wavelength.
    pub beta: f64,
    /// The solver's cycle (`None`: it failed).
    pub solver: Option<CycleMeasure>,
    /// The smooth cylinder's W at the same `lambda` and resolution.
    pub w_smooth: Option<f64>,
    /// Why the cycle (or the smooth reference) failed.
    pub solver_error: Option<String>,
    /// The solver's label.
    pub regime_solver: SolverRegime,
    /// The model at the same point.
    pub model: SweepPoint,
    /// [`labels_agree`].
    pub agree: bool,
}

/// A solver map (or one shard of it).
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct SolverMap {
    /// The grid (its `amax` is every cycle's, its `points` the model curves').
    pub grid: SweepGrid,
    /// The options.
    pub options: MapOptions,
    /// `(s, n)` when this is shard `s` of `n`.
    pub shard: Option<(usize, usize)>,
    /// The computed points, by index.
    pub points: Vec<MapPoint>,
}

impl MapOptions {
    /// Checks the options: the margin finite and `>= 0`, a fixed resolution
    /// with at least 2 steps (the cells are checked by the grid).
    pub fn check(&self) -> Result<()> {
        finite(self.margin, "margin")?;
        in_range(self.margin, "the margin", Interval::at_least(0.0))?;
        if let ResolutionRule::Fixed(r) = self.resolution {
            crate::grid::Grid::new(r.cells, 1.0)?;
            count_in_range(r.steps_per_leg, "steps per leg", 2, 100_000)?;
        }
        Ok(())
    }
}

/// The grid indices of shard `shard` (1-based `(s, n)`; `None`: all).
pub fn shard_indices(grid: &SweepGrid, shard: Option<(usize, usize)>) -> Result<Vec<usize>> {
    if let Some((s, n)) = shard {
        if n == 0 || s == 0 || s > n {
            return Err(SolverError::BadShard { shard: s, of: n });
        }
    }
    Ok((0..grid.len()).filter(|k| shard.map_or(true, |(s, n)| k % n == s - 1)).collect())
}

/// A cycle to run: `(lambda, alpha, beta)` as bits, so that equal cycles are run once.
type CycleKey = [u64; 3];

fn key(lambda: f64, alpha: f64, beta: f64) -> CycleKey {
    [lambda.to_bits(), alpha.to_bits(), beta.to_bits()]
}

/// The cycles a shard runs: each point's and each of its rows' smooth
/// cylinder, without repeats. Their number is what the progress callback of
/// [`run_map`] counts to. A grid whose base profile has more than one wave (the
/// `amplitude` axis) is [`SolverError::MapManyWaves`]: the cycles are one wave's.
pub fn map_cycles(grid: &SweepGrid, shard: Option<(usize, usize)>) -> Result<Vec<(f64, f64, f64)>> {
    grid.check()?;
    if let Some(p) = grid.profile.filter(|p| p.len() > 1) {
        return Err(SolverError::MapManyWaves { waves: p.len() });
    }
    let mut cycles: Vec<(f64, f64, f64)> = Vec::new();
    let mut seen = std::collections::HashSet::new();
    for k in shard_indices(grid, shard)? {
        let p = grid.params(k / grid.n, k % grid.n)?;
        for c in [(p.lambda(), 0.0, p.beta()), (p.lambda(), p.alpha(), p.beta())] {
            if seen.insert(key(c.0, c.1, c.2)) {
                cycles.push(c);
            }
        }
    }
    Ok(cycles)
}

/// Runs shard `shard` (1-based `(s, n)`; `None`: everything) of a map; the
/// cycles run in parallel with the `parallel` feature; `progress` is called
/// once per finished cycle ([`map_cycles`] counts them). A cycle that fails
/// makes its points `failed`; bad grids, options or shards are errors.
pub fn run_map<P: Fn() + Sync>(grid: SweepGrid, options: MapOptions, shard: Option<(usize, usize)>, progress: P) -> Result<SolverMap> {
    options.check()?;
    let cycles = map_cycles(&grid, shard)?;
    let run = |&(lambda, alpha, beta): &(f64, f64, f64)| {
        let r = measure_cycle_under(options.law, lambda, alpha, beta, grid.amax, options.resolution.at(lambda));
        progress();
        (key(lambda, alpha, beta), r)
    };
    #[cfg(feature = "parallel")]
    let done: Vec<(CycleKey, Result<CycleMeasure>)> = cycles.par_iter().map(run).collect();
    #[cfg(not(feature = "parallel"))]
    let done: Vec<(CycleKey, Result<CycleMeasure>)> = cycles.iter().map(run).collect();
    let done: std::collections::HashMap<CycleKey, Result<CycleMeasure>> = done.into_iter().collect();
    let mut points = Vec::new();
    for k in shard_indices(&grid, shard)? {
        let model = sweep_point(&grid, k)?;
        let cycle = &done[&key(model.lambda, model.alpha, model.beta)];
        let smooth = &done[&key(model.lambda, 0.0, model.beta)];
        points.push(assemble(model, grid.value(k % grid.n), cycle, smooth, options.margin));
    }
    Ok(SolverMap { grid, options, shard, points })
}

/// One point from its model point, its cycle and its row's smooth cycle.
fn assemble(model: SweepPoint, value: f64, cycle: &Result<CycleMeasure>, smooth: &Result<CycleMeasure>, margin: f64) -> MapPoint {
    let (regime_solver, solver_error) = match (cycle, smooth) {
        (Ok(c), Ok(s)) => (SolverRegime::classify(c.w - s.w, margin, c.cavitated_fraction > 0.0), None),
        (Err(e), _) => (SolverRegime::Failed, Some(e.to_string())),
        (Ok(_), Err(e)) => (SolverRegime::Failed, Some(format!("the smooth reference failed: {e}"))),
    };
    MapPoint {
        index: model.index,
        lambda: model.lambda,
        value,
        alpha: model.alpha,
        beta: model.beta,
        solver: cycle.as_ref().ok().copied(),
        w_smooth: smooth.as_ref().ok().map(|s| s.w),
        solver_error,
        regime_solver,
        agree: labels_agree(regime_solver, model.regime),
        model,
    }
}

/// Reassembles shards of one map into the whole (in any order; together they
/// must cover every point exactly once, with one grid and one set of options).
pub fn merge_maps(parts: &[SolverMap]) -> Result<SolverMap> {
    let merge = |fault| SolverError::Merge { fault };
    let first = parts.first().ok_or(merge(MergeFault::Empty))?;
    let mut slots: Vec<Option<MapPoint>> = vec![None; first.grid.len()];
    for part in parts {
        if part.grid != first.grid || part.options != first.options {
            return Err(merge(MergeFault::DifferentMaps));
        }
        for q in &part.points {
            let slot = slots.get_mut(q.index).ok_or(merge(MergeFault::OutsideGrid { index: q.index }))?;
            if slot.replace(q.clone()).is_some() {
                return Err(merge(MergeFault::Duplicate { index: q.index }));
            }
        }
    }
    let missing = slots.iter().filter(|s| s.is_none()).count();
    if missing > 0 {
        return Err(merge(MergeFault::Missing { missing, total: slots.len() }));
    }
    Ok(SolverMap { grid: first.grid, options: first.options, shard: None, points: slots.into_iter().flatten().collect() })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn labels_and_agreement() {
        assert_eq!(SolverRegime::classify(0.5, 0.02, false), SolverRegime::Dissipative);
        assert_eq!(SolverRegime::classify(0.5, 0.02, true), SolverRegime::Both);
        assert_eq!(SolverRegime::classify(0.01, 0.02, true), SolverRegime::Cavitating);
        assert_eq!(SolverRegime::classify(0.02, 0.02, false), SolverRegime::SmoothLike);
        assert!(labels_agree(SolverRegime::Both, Regime::Dissipative));
        assert!(!labels_agree(SolverRegime::Both, Regime::Cavitating));
        assert!(!labels_agree(SolverRegime::Failed, Regime::SmoothLike));
        assert_eq!(ResolutionRule::Auto.at(0.5).cells, 2048);
        assert_eq!(ResolutionRule::Auto.at(3.0).cells, 4096);
    }
}
