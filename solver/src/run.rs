//! One simulation from the model's parameters: the setup that a user of the
//! solver (the `maugis simulate` command, the Python package) needs, in one
//! place.
//!
//! [`simulate`] takes `(lambda, alpha, beta)` and the run's extent, sizes the
//! domain with [`suggested_half_width`], builds the wavy-cylinder profile and
//! the Dugdale law, runs a displacement-controlled loading-unloading
//! [`cycle`], and compares every state with the semi-analytical load at the
//! same contact half-width ([`compare_with_model`]).

use maugis::contact::curve::DEFAULT_DATUM;
use maugis::contact::model::Params;

use crate::contact::{ContactSolver, SolveOptions, State};
use crate::dissipation::{cycle_dissipation, CycleDissipation};
use crate::error::{Result, SolverError};
use crate::grid::Grid;
use crate::path::{
    compare_with_model, cycle, load_controlled, suggested_half_width, Cycle, CycleOptions, LoadControlled, LoadDirection, ModelComparison,
};
use crate::profile::{Adhesion, Profile};

/// What to simulate.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SimulationSpec {
    /// Maugis parameter `lambda > 0`.
    pub lambda: f64,
    /// Normalised wave amplitude `alpha >= 0`.
    pub alpha: f64,
    /// Normalised wavelength `beta > 0`.
    pub beta: f64,
    /// Loading stops once the contact half-width reaches `amax`.
    pub amax: f64,
    /// Grid cells (a power of two).
    pub cells: usize,
    /// Approach steps per leg (`2 ..= 100000`).
    pub steps_per_leg: usize,
}

/// A simulated cycle with its setup and the model at the same half-widths.
#[derive(Debug, Clone)]
pub struct Simulation {
    /// The parameters.
    pub spec: SimulationSpec,
    /// Half-width `X` of the domain `[-X, X]`.
    pub half_width: f64,
    /// The datum of the approach (see [`ContactSolver::datum`]).
    pub datum: f64,
    /// The cycle.
    pub cycle: Cycle,
    /// The model at the loading states' half-widths.
    pub model_loading: Vec<ModelComparison>,
    /// The model at the unloading states' half-widths.
    pub model_unloading: Vec<ModelComparison>,
}

impl Simulation {
    /// The model comparison of `state` (of leg `unloading` or not), when the
    /// model has a state at its half-width.
    pub fn model_at(&self, state: &State, unloading: bool) -> Option<&ModelComparison> {
        let list = if unloading { &self.model_unloading } else { &self.model_loading };
        list.iter().find(|r| r.abar == state.abar && state.abar > 0.0)
    }

    /// The load-controlled paths ([`load_controlled`]) of the loading leg and
    /// of the unloading leg. The unloading leg starts at the last loading
    /// state, so its indices are shifted by one: index `k >= 1` is
    /// `cycle.unloading[k - 1]`, index 0 the last loading state.
    pub fn load_controlled(&self) -> (LoadControlled, LoadControlled) {
        let loading = load_controlled(&self.cycle.loading, LoadDirection::Increasing);
        let mut back = Vec::with_capacity(self.cycle.unloading.len() + 1);
        back.extend(self.cycle.loading.last().cloned());
        back.extend(self.cycle.unloading.iter().cloned());
        (loading, load_controlled(&back, LoadDirection::Decreasing))
    }

    /// W of the closed in-contact cycle under load control and under
    /// displacement control at the model's default datum
    /// ([`DEFAULT_DATUM`], 100 `l_h`), measured as the library measures it on
    /// the model ([`crate::dissipation`]), so the two compare point by point.
    /// Errors when the cycle has fewer than two states in contact.
    pub fn dissipation(&self) -> Result<CycleDissipation> {
        cycle_dissipation(&self.cycle, self.datum, DEFAULT_DATUM)
    }

    /// The run as a flat report: the object `maugis simulate --format json`
    /// prints and the Python package returns.
    pub fn report(&self) -> SimulationReport {
        let (lc_loading, lc_unloading) = self.load_controlled();
        let on_path = [
            (0..self.cycle.loading.len()).map(|i| lc_loading.states.contains(&i)).collect::<Vec<bool>>(),
            (0..self.cycle.unloading.len()).map(|i| lc_unloading.states.contains(&(i + 1))).collect::<Vec<bool>>(),
        ];
        let mut states = Vec::with_capacity(self.cycle.loading.len() + self.cycle.unloading.len());
        for (unloading, leg, list) in [(false, "loading", &self.cycle.loading), (true, "unloading", &self.cycle.unloading)] {
            for (i, s) in list.iter().enumerate() {
                let m = self.model_at(s, unloading);
                states.push(StateRecord {
                    leg,
                    approach: s.approach,
                    abar: s.abar,
                    load: s.load,
                    contact_intervals: s.contact_intervals(),
                    zone_cells: s.zone_cells,
                    model_load: m.map(|r| r.model_load),
                    model_valid: m.map(|r| r.model_valid),
                    load_controlled: on_path[usize::from(unloading)][i],
                    zone_ends_placed: s.zone_ends_placed,
                });
            }
        }
        SimulationReport {
            lambda: self.spec.lambda,
            alpha: self.spec.alpha,
            beta: self.spec.beta,
            cells: self.spec.cells,
            half_width: self.half_width,
            datum: self.datum,
            stiff_cycle_work: self.cycle.stiff_work,
            dissipation: self.dissipation().ok().map(|d| DissipationRecord {
                load_control: d.load_control.dissipation.total,
                displacement_control: d.displacement_control.dissipation.total,
                datum: d.displacement_control.datum,
                load_control_cavitated: d.load_control.dissipation.invalid,
                displacement_control_cavitated: d.displacement_control.dissipation.invalid,
                single_interval: d.load_control.single_interval,
            }),
            pull_off: lc_unloading.pull_off.map(|(_, load)| load),
            states,
        }
    }
}

/// One state of a [`SimulationReport`].
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct StateRecord {
    /// `"loading"` or `"unloading"`.
    pub leg: &'static str,
    /// The approach `Delta-bar` (from the solver's datum).
    pub approach: f64,
    /// Contact half-width `abar` (outermost contact edges).
    pub abar: f64,
    /// Load `Lbar`.
    pub load: f64,
    /// Number of contact intervals (more than one: cavitation).
    pub contact_intervals: usize,
    /// Cells across the Dugdale zone.
    pub zone_cells: usize,
    /// The semi-analytical load at the same `abar`, where the model has a state.
    pub model_load: Option<f64>,
    /// Whether that model state is valid.
    pub model_valid: Option<bool>,
    /// Whether the state is on the load-controlled path of its leg
    /// ([`crate::path::load_controlled`]): a soft machine (prescribed load)
    /// visits it; between two such states of a leg with others in between, it
    /// jumps.
    pub load_controlled: bool,
    /// Whether the Dugdale-zone ends were placed inside their cells
    /// ([`crate::contact::State::zone_ends_placed`]); `false`: the zone ends on
    /// cell edges and the state carries the grid-pinning error.
    pub zone_ends_placed: bool,
}

/// W of a simulated cycle ([`Simulation::dissipation`]), in units of
/// `dgamma l_h` per unit length.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct DissipationRecord {
    /// W under load control.
    pub load_control: f64,
    /// W_d under displacement control at `datum`.
    pub displacement_control: f64,
    /// The datum of displacement control (model convention, units of `l_h`).
    pub datum: f64,
    /// The part of `load_control` from loops through cavitated states.
    pub load_control_cavitated: f64,
    /// The part of `displacement_control` from loops through cavitated states.
    pub displacement_control_cavitated: f64,
    /// Every state had at most one contact interval; otherwise W is an
    /// estimate (states of different branches ordered by `abar` together).
    pub single_interval: bool,
}

/// A simulated cycle as a flat report.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct SimulationReport {
    /// Maugis parameter.
    pub lambda: f64,
    /// Wave amplitude.
    pub alpha: f64,
    /// Wavelength.
    pub beta: f64,
    /// Grid cells.
    pub cells: usize,
    /// Half-width of the domain.
    pub half_width: f64,
    /// Datum of the approach.
    pub datum: f64,
    /// `oint Lbar dDelta` over the simulated stiff-machine cycle, from out of
    /// contact back to out of contact ([`Cycle::stiff_work`]); not W.
    pub stiff_cycle_work: f64,
    /// W of the closed in-contact cycle ([`Simulation::dissipation`]), with the
    /// keys of the model's curve; `None` when fewer than two states are in contact.
    pub dissipation: Option<DissipationRecord>,
    /// The pull-off load under load control (the most tensile load of the
    /// unloading leg), if the unloading leg carries tension.
    pub pull_off: Option<f64>,
    /// The states, loading then unloading.
    pub states: Vec<StateRecord>,
}

/// Runs the simulation; `progress(done, estimated_total)` is called after every state.
pub fn simulate(spec: SimulationSpec, progress: &mut dyn FnMut(usize, usize)) -> Result<Simulation> {
    if !(2..=100_000).contains(&spec.steps_per_leg) {
        return Err(SolverError::Domain { what: format!("steps per leg must lie in [2, 100000] (got {})", spec.steps_per_leg) });
    }
    let params = Params::new(spec.lambda, spec.alpha, spec.beta)?;
    let half_width = suggested_half_width(params, spec.amax)?;
    let grid = Grid::new(spec.cells, half_width)?;
    let profile = Profile::wavy_cylinder(spec.alpha, spec.beta)?;
    let adhesion = Adhesion::dugdale(spec.lambda)?;
    let mut solver = ContactSolver::new(grid, None, &profile, adhesion, SolveOptions::default())?;
    let cycle = cycle(&mut solver, CycleOptions { amax: spec.amax, steps_per_leg: spec.steps_per_leg }, progress)?;
    Ok(Simulation {
        spec,
        half_width,
        datum: solver.datum(),
        model_loading: compare_with_model(params, solver.datum(), &cycle.loading),
        model_unloading: compare_with_model(params, solver.datum(), &cycle.unloading),
        cycle,
    })
}
