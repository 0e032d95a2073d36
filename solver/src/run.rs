//! One simulation from the model's parameters: the setup that a user of the
//! solver (the `maugis simulate` command, the Python package) needs, in one
//! place.
//!
//! [`simulate`] takes `(lambda, alpha, beta)` and the run's extent, sizes the
//! domain with [`suggested_half_width`], builds the wavy-cylinder profile and
//! the adhesion law (Dugdale by default, [`SimulationOptions::law`]), runs a displacement-controlled loading-unloading
//! [`cycle`], and compares every state with the semi-analytical load at the
//! same contact half-width ([`compare_with_model`]).

use maugis::contact::curve::DEFAULT_DATUM;
use maugis::contact::model::Params;

use crate::contact::{ContactSolver, SolveOptions, State};
use crate::dissipation::{cycle_dissipation, CycleDissipation};
use crate::error::Result;
use crate::grid::Grid;
use crate::path::{
    compare_with_model, cycle, load_controlled, suggested_half_width, Cycle, CycleOptions, LoadControlled, LoadDirection, ModelComparison,
};
use crate::profile::{AdhesionLaw, Profile};
use crate::profile_file::ProfileTable;
use crate::error::SolverError;
use maugis::contact::profile::WavyProfile;

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

/// The elastic domain.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
#[non_exhaustive]
pub enum Domain {
    /// A free half-plane (the default): the contact of one indenter.
    #[default]
    Free,
    /// A periodic half-plane of period `2X` ([`crate::elastic`]): one period
    /// of a periodic surface, its images included. The built-in profile is
    /// then the wave alone, `h = alpha (1 - cos(2 pi x/beta))` on one period
    /// `[-beta/2, beta/2]`.
    Periodic,
}

impl Domain {
    /// `"free"` or `"periodic"`.
    pub fn name(self) -> &'static str {
        match self {
            Domain::Free => "free",
            Domain::Periodic => "periodic",
        }
    }
}

/// The options of a simulation beyond [`SimulationSpec`]; the default is the
/// built-in wavy cylinder on a free half-plane, domain sized by
/// [`suggested_half_width`].
#[derive(Debug, Clone, Default, PartialEq)]
pub struct SimulationOptions {
    /// A profile table ([`crate::profile_file`]) in place of the built-in
    /// profile. `alpha` and `beta` of the spec then only name the
    /// semi-analytical model the states are compared with and that sizes the
    /// domain.
    pub profile: Option<ProfileTable>,
    /// The domain half-width `X` (`None`: [`suggested_half_width`] for the
    /// free domain; for the periodic domain `beta/2`, or with a table the
    /// largest `X` it covers).
    pub half_width: Option<f64>,
    /// Free or periodic.
    pub domain: Domain,
    /// The adhesion law at the spec's `lambda` (default Dugdale).
    pub law: AdhesionLaw,
    /// A profile of many waves in place of the spec's one wave `(alpha, beta)`: the
    /// built-in profile is then the cylinder carrying these waves
    /// ([`Profile::RoughCylinder`]), and the model it is compared with is the same
    /// profile's. Free domain only ([`SolverError::PeriodicManyWaves`]).
    pub waves: Option<WavyProfile>,
    /// Compare no state with the model (a profile table that is none of the model's
    /// profiles): the `model_*` lists stay empty. The spec's `alpha`, `beta` (or
    /// `waves`) then only size the free domain.
    pub without_model: bool,
}

/// A simulated cycle with its setup and the model at the same half-widths.
#[derive(Debug, Clone)]
pub struct Simulation {
    /// The parameters.
    pub spec: SimulationSpec,
    /// The options.
    pub options: SimulationOptions,
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
    /// The model at the reloading states' half-widths.
    pub model_reloading: Vec<ModelComparison>,
}

impl Simulation {
    /// The model comparison of `state` of leg `leg` (0 loading, 1 unloading,
    /// 2 reloading), when the model has a state at its half-width.
    pub fn model_at(&self, state: &State, leg: usize) -> Option<&ModelComparison> {
        let list = match leg {
            0 => &self.model_loading,
            1 => &self.model_unloading,
            _ => &self.model_reloading,
        };
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
        let c = &self.cycle;
        let on_path = [
            (0..c.loading.len()).map(|i| lc_loading.states.contains(&i)).collect::<Vec<bool>>(),
            (0..c.unloading.len()).map(|i| lc_unloading.states.contains(&(i + 1))).collect::<Vec<bool>>(),
            vec![false; c.reloading.len()],
        ];
        let mut states = Vec::with_capacity(c.loading.len() + c.unloading.len() + c.reloading.len());
        for (k, (leg, list)) in [("loading", &c.loading), ("unloading", &c.unloading), ("reloading", &c.reloading)].into_iter().enumerate() {
            for (i, s) in list.iter().enumerate() {
                let m = self.model_at(s, k);
                states.push(StateRecord {
                    leg,
                    approach: s.approach,
                    abar: s.abar,
                    load: s.load,
                    contact_intervals: s.contact_intervals(),
                    zone_cells: s.zone_cells,
                    model_load: m.map(|r| r.model_load),
                    model_valid: m.map(|r| r.model_valid),
                    load_controlled: on_path[k][i],
                    zone_ends_placed: s.zone_ends_placed,
                });
            }
        }
        SimulationReport {
            law: self.options.law.name(),
            domain: self.options.domain.name(),
            profile: match (&self.options.profile, self.options.domain, &self.options.waves) {
                (Some(_), _, _) => "table",
                (None, Domain::Free, Some(_)) => "rough_cylinder",
                (None, Domain::Free, None) => "wavy_cylinder",
                (None, Domain::Periodic, _) => "sinusoid",
            },
            waves: self.options.waves,
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
    /// `"loading"`, `"unloading"` or `"reloading"` (the leg from the smallest
    /// contact the unloading leg held back up, [`Cycle::reloading`]).
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
    /// jumps. Always `false` on the reloading leg.
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
    /// The adhesion law, `"dugdale"` or `"exp"` ([`AdhesionLaw::name`]).
    pub law: &'static str,
    /// `"free"` or `"periodic"` ([`Domain`]).
    pub domain: &'static str,
    /// `"wavy_cylinder"` (the built-in profile), `"sinusoid"` (the built-in
    /// profile of the periodic domain) or `"table"` (a profile table).
    pub profile: &'static str,
    /// Maugis parameter.
    pub lambda: f64,
    /// Wave amplitude.
    pub alpha: f64,
    /// Wavelength.
    pub beta: f64,
    /// Every wave, for the profile `"rough_cylinder"` (the spec's `alpha`, `beta`
    /// then do not describe it).
    #[cfg_attr(feature = "serde", serde(skip_serializing_if = "Option::is_none"))]
    pub waves: Option<WavyProfile>,
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
    /// The states, loading, unloading, then reloading.
    pub states: Vec<StateRecord>,
}

/// Runs the simulation of the built-in wavy cylinder on a free half-plane;
/// `progress(done, estimated_total)` is called after every state.
pub fn simulate(spec: SimulationSpec, progress: &mut dyn FnMut(usize, usize)) -> Result<Simulation> {
    simulate_with(spec, SimulationOptions::default(), progress)
}

/// Runs the simulation with `options` (a profile table, the domain).
pub fn simulate_with(spec: SimulationSpec, options: SimulationOptions, progress: &mut dyn FnMut(usize, usize)) -> Result<Simulation> {
    crate::error::count_in_range(spec.steps_per_leg, "steps per leg", 2, 100_000)?;
    let params = match &options.waves {
        None => Params::new(spec.lambda, spec.alpha, spec.beta)?,
        Some(_) if options.domain == Domain::Periodic => {
            return Err(SolverError::PeriodicManyWaves { waves: options.waves.map_or(0, |w| w.len()) })
        }
        Some(w) => Params::with_profile(spec.lambda, *w)?,
    };
    let half_width = match (options.half_width, options.domain, &options.profile) {
        (Some(x), _, _) => crate::error::finite(x, "the domain half-width")?,
        (None, Domain::Free, _) => suggested_half_width(params, spec.amax)?,
        (None, Domain::Periodic, None) => 0.5 * spec.beta,
        (None, Domain::Periodic, Some(t)) => (-t.x()[0]).min(t.x()[t.x().len() - 1]),
    };
    let grid = Grid::new(spec.cells, half_width)?;
    let profile = match (&options.profile, options.domain) {
        (Some(t), _) => Profile::Table(t.clone()),
        (None, Domain::Free) => match options.waves {
            Some(w) => Profile::RoughCylinder(w),
            None => Profile::wavy_cylinder(spec.alpha, spec.beta)?,
        },
        (None, Domain::Periodic) => Profile::sinusoid(spec.alpha, spec.beta)?,
    };
    let adhesion = options.law.at(spec.lambda)?;
    let mut solver = match options.domain {
        Domain::Free => ContactSolver::new(grid, None, &profile, adhesion, SolveOptions::default())?,
        Domain::Periodic => ContactSolver::periodic(grid, None, &profile, adhesion, SolveOptions::default())?,
    };
    let cycle = cycle(&mut solver, CycleOptions { amax: spec.amax, steps_per_leg: spec.steps_per_leg }, progress)?;
    // The model is the wavy cylinder on a free half-plane.
    let compare = |states: &[State]| match options.domain {
        Domain::Free if !options.without_model => compare_with_model(params, solver.datum(), states),
        _ => Vec::new(),
    };
    Ok(Simulation {
        spec,
        half_width,
        datum: solver.datum(),
        model_loading: compare(&cycle.loading),
        model_unloading: compare(&cycle.unloading),
        model_reloading: compare(&cycle.reloading),
        options,
        cycle,
    })
}
