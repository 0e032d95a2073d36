//! The output schema of a run: one object that `summary.json` and
//! `maugis curve --format json` both print (serde behind the `serde` feature).
//!
//! A [`RunSummary`] holds the run's parameters and one [`CurveSummary`] per
//! Maugis parameter: the grid states, turning points, the paths, jumps, loops
//! and dissipation under load and displacement control, pull-off and the
//! invalid stretches. Field names are the JSON keys.

use crate::contact::curve::{Curve, CurveOptions, CurvePoint, PullOff, TurningPoint};
use crate::contact::paths::{ControlPaths, HysteresisLoop, Jump, PathNode};
use crate::contact::units::{Material, Scales};

/// The energy one loading-unloading cycle dissipates (units of `dgamma l_h`).
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct DissipationSummary {
    /// Under load control.
    pub load_control: f64,
    /// Under displacement control (datum in [`RunParams::datum`]).
    pub displacement_control: f64,
    /// Load control, valid loops only.
    pub load_control_valid: f64,
    /// Load control, loops through invalid states.
    pub load_control_invalid: f64,
    /// Displacement control, valid loops only.
    pub displacement_control_valid: f64,
    /// Displacement control, loops through invalid states.
    pub displacement_control_invalid: f64,
}

/// A run of consecutive invalid grid states.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Stretch {
    /// First invalid grid point.
    pub from_abar: f64,
    /// Last invalid grid point.
    pub to_abar: f64,
    /// Number of grid points.
    pub points: usize,
    /// Some state has `pbar > 1` inside the contact.
    pub cavitation: bool,
    /// Some state has a negative gap in the adhesive strip.
    pub interpenetration: bool,
}

/// The parameters shared by the curves of a run.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct RunParams {
    /// Wave amplitude.
    pub alpha: f64,
    /// Wavelength.
    pub beta: f64,
    /// Largest contact.
    pub amax: f64,
    /// Grid points per curve.
    pub points: usize,
    /// Datum of displacement control (units of `l_h`).
    pub datum: f64,
}

/// Everything about one curve.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct CurveSummary {
    /// Maugis parameter.
    pub lambda: f64,
    /// Wave amplitude.
    pub alpha: f64,
    /// Wavelength.
    pub beta: f64,
    /// The CSV file of the grid states, when files are written.
    pub csv: Option<String>,
    /// Number of invalid grid states.
    pub invalid_points: usize,
    /// Runs of invalid grid states.
    pub invalid_stretches: Vec<Stretch>,
    /// Refined turning points of the load.
    pub turning_points: Vec<TurningPoint>,
    /// Jumps under load control (only those met).
    pub jumps: Vec<Jump>,
    /// Loops under load control.
    pub loops: Vec<HysteresisLoop>,
    /// Pull-off: the end of unloading under load control, with its own validity.
    pub pull_off: Option<PullOff>,
    /// The most tensile valid state on the unloading path.
    pub valid_pull_off: Option<PathNode>,
    /// Dissipation of one cycle.
    pub dissipation: DissipationSummary,
    /// Paths under load control.
    pub load_control: ControlPaths,
    /// Paths under displacement control.
    pub displacement_control: ControlPaths,
    /// The grid states.
    pub points: Vec<CurvePoint>,
}

/// The whole run.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct RunSummary {
    /// Shared parameters.
    pub params: RunParams,
    /// The `lambda` of the M-DMT limit drawn in the load-area plot.
    pub mdmt_limit_lambda: f64,
    /// One entry per curve, by increasing `lambda`.
    pub curves: Vec<CurveSummary>,
}

/// The invalid stretches of a curve.
pub fn invalid_stretches(points: &[CurvePoint]) -> Vec<Stretch> {
    let mut out: Vec<Stretch> = Vec::new();
    let mut open = false;
    for p in points {
        let v = &p.validity;
        if v.valid {
            open = false;
            continue;
        }
        match out.last_mut() {
            Some(s) if open => {
                s.to_abar = p.abar;
                s.points += 1;
                s.cavitation |= v.cavitation;
                s.interpenetration |= v.interpenetration;
            }
            _ => out.push(Stretch {
                from_abar: p.abar,
                to_abar: p.abar,
                points: 1,
                cavitation: v.cavitation,
                interpenetration: v.interpenetration,
            }),
        }
        open = true;
    }
    out
}

impl DissipationSummary {
    /// From the two controls.
    pub fn new(load: &ControlPaths, displacement: &ControlPaths) -> DissipationSummary {
        DissipationSummary {
            load_control: load.dissipation.total,
            displacement_control: displacement.dissipation.total,
            load_control_valid: load.dissipation.valid,
            load_control_invalid: load.dissipation.invalid,
            displacement_control_valid: displacement.dissipation.valid,
            displacement_control_invalid: displacement.dissipation.invalid,
        }
    }
}

impl CurveSummary {
    /// Summarises a curve (`csv`: the file its grid states go to, if any).
    pub fn new(curve: &Curve, csv: Option<String>) -> CurveSummary {
        CurveSummary {
            lambda: curve.params.lambda,
            alpha: curve.params.alpha,
            beta: curve.params.beta,
            csv,
            invalid_points: curve.points.iter().filter(|p| !p.validity.valid).count(),
            invalid_stretches: invalid_stretches(&curve.points),
            turning_points: curve.turning_points.clone(),
            jumps: curve.jumps.clone(),
            loops: curve.loops.clone(),
            pull_off: curve.pull_off,
            valid_pull_off: curve.valid_pull_off,
            dissipation: DissipationSummary::new(&curve.load_control, &curve.displacement_control),
            load_control: curve.load_control.clone(),
            displacement_control: curve.displacement_control.clone(),
            points: curve.points.clone(),
        }
    }
}

impl RunParams {
    /// From the shared roughness and the grid options.
    pub fn new(alpha: f64, beta: f64, opts: CurveOptions) -> RunParams {
        RunParams { alpha, beta, amax: opts.amax, points: opts.points, datum: opts.datum }
    }
}

/// One curve's headline numbers in SI units.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct SiCurve {
    /// Maugis parameter.
    pub lambda: f64,
    /// Adhesive (Dugdale) stress `sigma_0` (Pa).
    pub sigma_pa: f64,
    /// Interaction range `delta_c = dgamma/sigma_0` (m).
    pub delta_c_m: f64,
    /// Pull-off load per unit length (N/m).
    pub pull_off_load_n_per_m: Option<f64>,
    /// Contact half-width at pull-off (m).
    pub pull_off_half_width_m: Option<f64>,
    /// Dissipation of one closed cycle under load control (J/m).
    pub dissipation_load_control_j_per_m: f64,
    /// The same under displacement control (J/m).
    pub dissipation_displacement_control_j_per_m: f64,
}

/// A run in SI units: the material, the scales and each curve's headline
/// numbers (the grid states stay normalised; multiply by the scales).
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct SiSummary {
    /// Material and geometry.
    pub material: Material,
    /// Wave amplitude `A` (m).
    pub amplitude_m: f64,
    /// Wavelength `zeta` (m).
    pub wavelength_m: f64,
    /// The scales: `l_h`, `l_v` (m), load (N/m), stress (Pa), energy (J/m).
    pub scales: Scales,
    /// Datum of displacement control (m).
    pub datum_m: f64,
    /// One entry per curve.
    pub curves: Vec<SiCurve>,
}

impl SiSummary {
    /// The SI view of a run.
    pub fn new(run: &RunSummary, material: Material) -> crate::error::Result<SiSummary> {
        let s = Scales::new(material)?;
        Ok(SiSummary {
            material,
            amplitude_m: s.to_vertical(run.params.alpha),
            wavelength_m: s.to_horizontal(run.params.beta),
            scales: s,
            datum_m: s.to_horizontal(run.params.datum),
            curves: run
                .curves
                .iter()
                .map(|c| SiCurve {
                    lambda: c.lambda,
                    sigma_pa: s.sigma(c.lambda),
                    delta_c_m: s.delta_c(c.lambda),
                    pull_off_load_n_per_m: c.pull_off.map(|p| s.to_load(p.load)),
                    pull_off_half_width_m: c.pull_off.map(|p| s.to_horizontal(p.abar)),
                    dissipation_load_control_j_per_m: s.to_energy(c.dissipation.load_control),
                    dissipation_displacement_control_j_per_m: s.to_energy(c.dissipation.displacement_control),
                })
                .collect(),
        })
    }
}
