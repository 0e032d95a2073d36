//! The output schema of a run: one object that `summary.json` and
//! `maugis curve --format json` both print (serde behind the `serde` feature).
//!
//! A [`RunSummary`] holds the run's parameters and one [`CurveSummary`] per
//! Maugis parameter: the grid states, turning points, the paths, jumps, loops
//! and dissipation under load and displacement control, pull-off and the
//! invalid stretches. Field names are the JSON keys.
//!
//! [`load_area_curves`] solves a run's curves and [`RunSummary::new`]
//! assembles the summary from them: `maugis curve` and the Python
//! `run_summary`/`curve` both call these two, and only present the result.

#[cfg(feature = "parallel")]
use rayon::prelude::*;

use crate::contact::located::{At, LocatedError};
use crate::contact::curve::{load_area_curve, Curve, CurveOptions, CurvePoint, PullOff, TurningPoint};
use crate::contact::model::Params;
use crate::contact::profile::WavyProfile;
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
    /// Wave amplitude (the first wave's, for a profile of many waves: see `waves`).
    pub alpha: f64,
    /// Wavelength (the first wave's, for a profile of many waves: see `waves`).
    pub beta: f64,
    /// Every wave of the profile, when it has other than exactly one (absent from the
    /// JSON for the seed paper's one-wave profile).
    #[cfg_attr(feature = "serde", serde(default, skip_serializing_if = "Option::is_none"))]
    pub waves: Option<WavyProfile>,
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
    /// Wave amplitude (the first wave's, for a profile of many waves: see `waves`).
    pub alpha: f64,
    /// Wavelength (the first wave's, for a profile of many waves: see `waves`).
    pub beta: f64,
    /// Every wave of the profile, when it has other than exactly one.
    #[cfg_attr(feature = "serde", serde(default, skip_serializing_if = "Option::is_none"))]
    pub waves: Option<WavyProfile>,
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
            alpha: curve.params.alpha(),
            beta: curve.params.beta(),
            waves: many_waves(curve.params.profile()),
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

/// The profile when it has other than exactly one wave (the summaries' `waves`).
fn many_waves(profile: &WavyProfile) -> Option<WavyProfile> {
    (profile.len() != 1).then_some(*profile)
}

/// Solves the load-area curve ([`load_area_curve`]) of each `lambda` at the
/// shared roughness, in the given order (in parallel over `lambda` with the
/// `parallel` feature). `on_curve` is called once as each curve is done (a
/// progress bar's tick). Errors: a `lambda`, `alpha` or `beta` that
/// [`Params::new`] refuses ([`At::Input`], checked for every curve before any
/// is solved), or the curve that failed ([`At::Curve`]).
pub fn load_area_curves(
    lambdas: &[f64],
    alpha: f64,
    beta: f64,
    opts: CurveOptions,
    on_curve: impl Fn() + Sync + Send,
) -> Result<Vec<Curve>, LocatedError> {
    let params = lambdas.iter().map(|&l| Params::new(l, alpha, beta)).collect::<crate::error::Result<Vec<_>>>().map_err(|e| At::Input.wrap(e))?;
    curves_of(&params, opts, on_curve)
}

/// [`load_area_curves`] for a profile of any number of waves.
pub fn load_area_curves_profile(
    lambdas: &[f64],
    profile: &WavyProfile,
    opts: CurveOptions,
    on_curve: impl Fn() + Sync + Send,
) -> Result<Vec<Curve>, LocatedError> {
    let params = lambdas
        .iter()
        .map(|&l| Params::with_profile(l, *profile))
        .collect::<crate::error::Result<Vec<_>>>()
        .map_err(|e| At::Input.wrap(e))?;
    curves_of(&params, opts, on_curve)
}

/// The curves of `params`, in their order.
fn curves_of(params: &[Params], opts: CurveOptions, on_curve: impl Fn() + Sync + Send) -> Result<Vec<Curve>, LocatedError> {
    let one = |p: &Params| {
        let c = load_area_curve(*p, opts).map_err(|e| At::Curve { lambda: p.lambda }.wrap(e))?;
        on_curve();
        Ok(c)
    };
    #[cfg(feature = "parallel")]
    let out = params.par_iter().map(one).collect();
    #[cfg(not(feature = "parallel"))]
    let out = params.iter().map(one).collect();
    out
}

impl RunSummary {
    /// The summary of a run's curves (as [`load_area_curves`] returns them, at
    /// the shared `alpha`, `beta` and grid `opts`): one [`CurveSummary`] per
    /// curve in their order, `csv` naming each curve's file (if any), and the
    /// first curve's `lambda` as the M-DMT limit's (NaN without curves).
    pub fn new<'c>(
        alpha: f64,
        beta: f64,
        opts: CurveOptions,
        curves: impl IntoIterator<Item = &'c Curve>,
        csv: impl Fn(&Curve) -> Option<String>,
    ) -> RunSummary {
        RunSummary::with_run_params(RunParams::new(alpha, beta, opts), curves, csv)
    }

    /// [`RunSummary::new`] for a profile of any number of waves.
    pub fn for_profile<'c>(
        profile: &WavyProfile,
        opts: CurveOptions,
        curves: impl IntoIterator<Item = &'c Curve>,
        csv: impl Fn(&Curve) -> Option<String>,
    ) -> RunSummary {
        RunSummary::with_run_params(RunParams::for_profile(profile, opts), curves, csv)
    }

    fn with_run_params<'c>(
        params: RunParams,
        curves: impl IntoIterator<Item = &'c Curve>,
        csv: impl Fn(&Curve) -> Option<String>,
    ) -> RunSummary {
        let curves: Vec<CurveSummary> = curves.into_iter().map(|c| CurveSummary::new(c, csv(c))).collect();
        RunSummary {
            params,
            mdmt_limit_lambda: curves.first().map_or(f64::NAN, |c| c.lambda),
            curves,
        }
    }
}

impl RunParams {
    /// From the shared roughness and the grid options.
    pub fn new(alpha: f64, beta: f64, opts: CurveOptions) -> RunParams {
        RunParams { alpha, beta, waves: None, amax: opts.amax, points: opts.points, datum: opts.datum }
    }

    /// From a profile of any number of waves and the grid options.
    pub fn for_profile(profile: &WavyProfile, opts: CurveOptions) -> RunParams {
        let first = profile.waves().first();
        RunParams {
            alpha: first.map_or(0.0, |w| w.alpha()),
            beta: first.map_or(f64::INFINITY, |w| w.beta()),
            waves: many_waves(profile),
            amax: opts.amax,
            points: opts.points,
            datum: opts.datum,
        }
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
    /// Every wave `(A_j, zeta_j)` in metres, when the profile has other than exactly one.
    #[cfg_attr(feature = "serde", serde(default, skip_serializing_if = "Option::is_none"))]
    pub waves_m: Option<Vec<(f64, f64)>>,
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
            waves_m: run.params.waves.as_ref().map(|p| s.profile_to_si(p)),
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

#[cfg(test)]
mod tests {
    use super::*;
    use std::sync::atomic::{AtomicUsize, Ordering};

    #[test]
    fn a_run_keeps_the_given_order_and_names_its_files() {
        let opts = CurveOptions { amax: 3.0, points: 40, datum: 100.0 };
        let (alpha, beta) = (std::f64::consts::SQRT_2 / 4.0, 1.125);
        let done = AtomicUsize::new(0);
        let curves = load_area_curves(&[3.0, 0.5], alpha, beta, opts, || {
            done.fetch_add(1, Ordering::Relaxed);
        })
        .unwrap();
        assert_eq!(done.load(Ordering::Relaxed), 2);
        let run = RunSummary::new(alpha, beta, opts, &curves, |c| Some(format!("{}.csv", c.params.lambda)));
        assert_eq!(run.mdmt_limit_lambda, 3.0);
        assert_eq!(run.params, RunParams { alpha, beta, waves: None, amax: 3.0, points: 40, datum: 100.0 });
        assert_eq!(run.curves.iter().map(|c| c.lambda).collect::<Vec<_>>(), [3.0, 0.5]);
        assert_eq!(run.curves[1].csv.as_deref(), Some("0.5.csv"));
        assert_eq!(run.curves[0], CurveSummary::new(&curves[0], Some("3.csv".into())));
        assert!(RunSummary::new(alpha, beta, opts, &[], |_| None).mdmt_limit_lambda.is_nan());
    }

    #[test]
    fn a_run_names_what_failed() {
        let opts = CurveOptions { amax: 3.0, points: 40, datum: 100.0 };
        assert!(matches!(load_area_curves(&[1.0, -1.0], 0.1, 1.0, opts, || ()), Err(LocatedError { at: At::Input, .. })));
        let bad = CurveOptions { points: 1, ..opts };
        match load_area_curves(&[2.0], 0.1, 1.0, bad, || ()) {
            Err(e @ LocatedError { at: At::Curve { lambda }, .. }) => {
                assert_eq!(lambda, 2.0);
                assert!(e.to_string().starts_with("lambda = 2: "), "{e}");
            }
            other => panic!("{other:?}"),
        }
    }
}
