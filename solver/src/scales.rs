//! Dissipation and cavitation against the number of scales (issue 39, items 2
//! and 3): the solver's closed cycle for Weierstrass profiles of `N = 1, 2, ...`
//! scales, next to the single scales alone and the model where it holds.
//!
//! # The study
//!
//! Wave `j = 0..N-1` of the profile has wavelength `beta gamma^-j` and amplitude
//! `alpha gamma^(-H j)` (`WavyProfile::weierstrass`). For each Hurst exponent
//! `H`, each `lambda` and each `N <= max_scales` [`ScalesSpec::cycles`] lists
//! three kinds of cycle:
//!
//! * the profile of `N` scales;
//! * each of its waves alone on the cylinder (the single scales, whose W's
//!   the profile's is compared with);
//! * the smooth cylinder (`alpha = 0`), the base of the excess.
//!
//! Equal cycles (the first wave alone is the one-scale profile, for every `H`)
//! run once ([`ScalesSpec::cycles`]); they are numbered, and shard `s` of `n`
//! runs the cycles `k` with `k % n == s - 1`, so a cluster can split the study
//! and [`merge`] reassembles it exactly.
//!
//! # Per cycle ([`ScaleCycle`])
//!
//! One displacement-controlled cycle ([`crate::run::simulate_with`], free
//! domain sized by the model), read along the legs
//! ([`crate::dissipation::closed_cycle_along_legs`]: the contact splits into
//! up to two dozen intervals, and the reading by contact size fails there)
//! under load control (W) and displacement control at the model's datum
//! (W_d); the fraction of in-contact states with more than one contact
//! interval (cavitation) and the most intervals held; the model's W and W_d
//! on its load-area curve and whether its whole closed cycle is valid (the
//! model's W counts only then).
//!
//! # Resolution ([`ScaleResolution`])
//!
//! Chosen for the cycle's finest wavelength `beta_min`: cells
//! `cells_per_wavelength * 2X/beta_min` rounded up to a power of two,
//! approach steps per leg `steps_per_wavelength * amax/beta_min`, at least the
//! one-wave map's rule ([`ResolutionRule::Auto`]: 2048 cells for
//! `lambda <= 1`, 4096 above, 400 steps). [`ScaleResolution::refined`] doubles both: the grid
//! study of `docs/multiscale.md` runs the largest `N` at both and reports the
//! change.

//!
//! # lambda* ([`lambda_star`])
//!
//! The transitional Maugis parameter of `crate::transition` for a profile of
//! the study: the lower end of the lambda range where the excess of the
//! solver's W over the smooth cylinder's exceeds a fraction of the model's W
//! in the JKR limit on the same profile, by a log scan and bisection, repeated
//! at the refined resolution for the grid part of its uncertainty
//! ([`crate::transition::search_with`]).

use maugis::contact::curve::{load_area_curve, CurveOptions, DEFAULT_DATUM};
use maugis::contact::model::Params;
use maugis::contact::profile::WavyProfile;

use crate::dissipation::cycle_dissipation_along_legs;
use crate::transition::{relative_uncertainty, scan_lambdas, search_with, Evaluation, Search, JKR_LAMBDA};
use crate::error::{count_in_range, finite, in_range, Interval, MergeFault, Result, SolverError};
use crate::path::suggested_half_width;
use crate::map::{Resolution, ResolutionRule};
use crate::profile::AdhesionLaw;
use crate::run::{simulate_with, SimulationOptions, SimulationSpec};

/// How each cycle's resolution follows its finest wavelength (module docs).
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct ScaleResolution {
    /// Cells per finest wavelength.
    pub cells_per_wavelength: f64,
    /// Approach steps per leg per finest wavelength of contact half-width.
    pub steps_per_wavelength: f64,
    /// Cells and steps are multiplied by `2^refinement` (the grid study).
    pub refinement: u32,
}

impl Default for ScaleResolution {
    /// 16 cells and 16 steps per finest wavelength.
    fn default() -> Self {
        ScaleResolution { cells_per_wavelength: 16.0, steps_per_wavelength: 16.0, refinement: 0 }
    }
}

impl ScaleResolution {
    /// Twice the cells and twice the steps.
    pub fn refined(&self) -> ScaleResolution {
        ScaleResolution { refinement: self.refinement + 1, ..*self }
    }

    /// `(cells, steps per leg)` at `lambda` on a domain of half-width
    /// `half_width`, for a finest wavelength `beta_min` up to contact
    /// half-width `amax`: `cells_per_wavelength * 2X/beta_min` cells rounded up
    /// to a power of two and `steps_per_wavelength * amax/beta_min` steps, at
    /// least the one-wave map's rule at `lambda` ([`ResolutionRule::Auto`]),
    /// times `2^refinement`.
    pub fn at(&self, lambda: f64, half_width: f64, beta_min: f64, amax: f64) -> Resolution {
        let auto = ResolutionRule::Auto.at(lambda);
        let cells = (self.cells_per_wavelength * 2.0 * half_width / beta_min).ceil().max(auto.cells as f64) as usize;
        let steps = (self.steps_per_wavelength * amax / beta_min).ceil().max(auto.steps_per_leg as f64) as usize;
        Resolution { cells: cells.next_power_of_two() << self.refinement, steps_per_leg: steps << self.refinement }
    }

    fn check(&self) -> Result<()> {
        for (v, what) in [(self.cells_per_wavelength, "cells per wavelength"), (self.steps_per_wavelength, "steps per wavelength")] {
            finite(v, what)?;
            in_range(v, what, Interval::closed(1.0, 1e4))?;
        }
        count_in_range(self.refinement as usize, "the refinement", 0, 4)?;
        Ok(())
    }
}

/// What to compute (module docs).
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct ScalesSpec {
    /// Amplitude of the first (coarsest) wave.
    pub alpha: f64,
    /// Wavelength of the first wave.
    pub beta: f64,
    /// Wavelength ratio of neighbouring scales (`> 1`).
    pub gamma: f64,
    /// Hurst exponents.
    pub hursts: Vec<f64>,
    /// Maugis parameters.
    pub lambdas: Vec<f64>,
    /// Profiles of `1..=max_scales` scales.
    pub max_scales: usize,
    /// Largest contact half-width of every cycle.
    pub amax: f64,
    /// The resolution rule.
    pub resolution: ScaleResolution,
    /// Model curve points (`abar` spacing `amax/points`), at least 32 per
    /// finest wavelength ([`model_points`]).
    pub model_points: usize,
    /// The adhesion law.
    #[cfg_attr(feature = "serde", serde(default))]
    pub law: AdhesionLaw,
}

/// What a cycle is in the study.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
pub enum CycleRole {
    /// The profile of `scales` scales at Hurst exponent `hurst`.
    Profile { hurst: f64, scales: usize },
    /// Wave `wave` of the profiles at `hurst`, alone.
    Single { hurst: f64, wave: usize },
    /// The smooth cylinder.
    Smooth,
}

/// One cycle to run: `lambda`, the waves (empty: the smooth cylinder) and
/// every role it plays.
#[derive(Debug, Clone, PartialEq)]
pub struct CycleCase {
    /// Index in [`ScalesSpec::cycles`].
    pub index: usize,
    /// Maugis parameter.
    pub lambda: f64,
    /// The waves `(alpha_j, beta_j)`; empty for the smooth cylinder.
    pub waves: Vec<(f64, f64)>,
    /// The roles.
    pub roles: Vec<CycleRole>,
}

impl ScalesSpec {
    /// Checks the spec.
    pub fn check(&self) -> Result<()> {
        for (v, what) in [(self.alpha, "alpha"), (self.beta, "beta"), (self.gamma, "gamma"), (self.amax, "amax")] {
            finite(v, what)?;
        }
        in_range(self.alpha, "alpha", Interval::above(0.0))?;
        count_in_range(self.max_scales, "the number of scales", 1, 12)?;
        count_in_range(self.hursts.len(), "Hurst exponents", 1, 16)?;
        count_in_range(self.lambdas.len(), "lambdas", 1, 64)?;
        count_in_range(self.model_points, "model curve points", 2, 200_000)?;
        for &h in &self.hursts {
            finite(h, "a Hurst exponent")?;
            WavyProfile::weierstrass(self.alpha, self.beta, self.max_scales, self.gamma, h)?;
        }
        for &l in &self.lambdas {
            finite(l, "lambda")?;
            Params::new(l, self.alpha, self.beta)?;
        }
        self.resolution.check()
    }

    /// The waves of the profile of `scales` scales at `hurst`.
    pub fn waves(&self, hurst: f64, scales: usize) -> Result<Vec<(f64, f64)>> {
        let p = WavyProfile::weierstrass(self.alpha, self.beta, scales, self.gamma, hurst)?;
        Ok(p.waves().iter().map(|w| (w.alpha(), w.beta())).collect())
    }

    /// Every cycle of the study, without repeats, in a fixed order: by
    /// `lambda`, then the smooth cylinder, then by Hurst exponent the
    /// profiles of `1..=max_scales` scales and the single waves.
    pub fn cycles(&self) -> Result<Vec<CycleCase>> {
        self.check()?;
        let mut out: Vec<CycleCase> = Vec::new();
        let mut add = |lambda: f64, waves: Vec<(f64, f64)>, role: CycleRole| {
            match out.iter_mut().find(|c| c.lambda.to_bits() == lambda.to_bits() && c.waves == waves) {
                Some(c) => c.roles.push(role),
                None => out.push(CycleCase { index: out.len(), lambda, waves, roles: vec![role] }),
            }
        };
        for &lambda in &self.lambdas {
            add(lambda, Vec::new(), CycleRole::Smooth);
            for &hurst in &self.hursts {
                let all = self.waves(hurst, self.max_scales)?;
                for scales in 1..=self.max_scales {
                    add(lambda, all[..scales].to_vec(), CycleRole::Profile { hurst, scales });
                }
                for (wave, &w) in all.iter().enumerate() {
                    add(lambda, vec![w], CycleRole::Single { hurst, wave });
                }
            }
        }
        Ok(out)
    }
}

/// The model's closed cycle on the same profile.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct ModelCycle {
    /// W under load control.
    pub w: f64,
    /// W_d under displacement control at the model's datum.
    pub w_d: f64,
    /// Every node of both closed cycles is a valid state (no cavitation, no
    /// interpenetration): only then is the model's W the physical one.
    pub valid: bool,
    /// Fraction of the curve's states that are valid.
    pub valid_fraction: f64,
}

/// What one cycle measured (module docs).
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct ScaleCycle {
    /// Index in [`ScalesSpec::cycles`].
    pub index: usize,
    /// Maugis parameter.
    pub lambda: f64,
    /// The waves (empty: smooth).
    pub waves: Vec<(f64, f64)>,
    /// The roles.
    pub roles: Vec<CycleRole>,
    /// Grid cells.
    pub cells: usize,
    /// Approach steps per leg.
    pub steps_per_leg: usize,
    /// Domain half-width.
    pub half_width: f64,
    /// W under load control, read along the legs (`None`: the cycle failed or
    /// did not close, see `error`).
    pub w: Option<f64>,
    /// W_d under displacement control at the model's datum.
    pub w_d: Option<f64>,
    /// Fraction of the in-contact states of the three legs with more than one
    /// contact interval.
    pub cavitated_fraction: f64,
    /// The most contact intervals of any state.
    pub max_intervals: usize,
    /// The load-controlled pull-off (the end of unloading).
    pub pull_off: Option<f64>,
    /// The model on the same profile (`None`: the model failed, see `error`).
    pub model: Option<ModelCycle>,
    /// `alpha_min/(lambda beta_min)` of the finest wave: the traction estimate
    /// of Eq. 16 (0 for the smooth cylinder).
    pub traction_estimate: f64,
    /// What failed before the model, if anything: the parameters or the
    /// solver (prefixed `parameters: ` or `solver: `).
    pub error: Option<String>,
    /// Why the model has no W on this profile, if it has none (`model` is
    /// then `None`). Studies written before this field held the model's error
    /// in `error`, after `"; model: "`; [`with_model`] moves it here.
    #[cfg_attr(feature = "serde", serde(default))]
    pub model_error: Option<String>,
    /// Wall time (s).
    pub seconds: f64,
}

/// The model's parameters and the profile (`None`: the smooth cylinder) of
/// `waves` at `lambda`.
fn case_params(spec: &ScalesSpec, lambda: f64, waves: &[(f64, f64)]) -> Result<(Params, Option<WavyProfile>)> {
    if waves.is_empty() {
        return Ok((Params::new(lambda, 0.0, spec.beta)?, None));
    }
    let p = WavyProfile::from_pairs(waves)?;
    Ok((Params::with_profile(lambda, p)?, Some(p)))
}

/// The finest wavelength of `waves` (the first wave's for the smooth cylinder).
fn finest_wavelength(spec: &ScalesSpec, waves: &[(f64, f64)]) -> f64 {
    waves.iter().map(|w| w.1).fold(spec.beta, f64::min)
}

/// Model curve points for a finest wavelength `beta_min`: `spec.model_points`,
/// and at least 32 per finest wavelength (the envelope study's rule; with
/// fewer the model's W misses loops of the finest wave: 25.6 at 100 points
/// against 38.6 at 600 for 4 scales at lambda = 10, docs/model.md).
pub fn model_points(spec: &ScalesSpec, beta_min: f64) -> usize {
    spec.model_points.max((32.0 * spec.amax / beta_min).ceil() as usize)
}

/// Runs one cycle of the study and measures it, the model beside it. A
/// failed simulation or model is recorded in `error`, not returned: the rest
/// of the study goes on.
pub fn run_cycle(spec: &ScalesSpec, case: &CycleCase, resolution: ScaleResolution) -> ScaleCycle {
    with_model(spec, solver_cycle(spec, case, resolution))
}

/// A cycle's record before anything is measured.
fn blank_cycle(case: &CycleCase) -> ScaleCycle {
    ScaleCycle {
        index: case.index,
        lambda: case.lambda,
        waves: case.waves.clone(),
        roles: case.roles.clone(),
        cells: 0,
        steps_per_leg: 0,
        half_width: 0.0,
        w: None,
        w_d: None,
        cavitated_fraction: 0.0,
        max_intervals: 0,
        pull_off: None,
        model: None,
        traction_estimate: case.waves.iter().min_by(|a, b| a.1.total_cmp(&b.1)).map_or(0.0, |&(a, b)| a / (case.lambda * b)),
        error: None,
        model_error: None,
        seconds: 0.0,
    }
}

/// The solver's part of [`run_cycle`] (no model).
fn solver_cycle(spec: &ScalesSpec, case: &CycleCase, resolution: ScaleResolution) -> ScaleCycle {
    let t = std::time::Instant::now();
    let mut out = blank_cycle(case);
    match case_params(spec, case.lambda, &case.waves) {
        Err(e) => out.error = Some(format!("parameters: {e}")),
        Ok((params, profile)) => {
            if let Err(e) = simulate_case(spec, case, params, profile, finest_wavelength(spec, &case.waves), resolution, &mut out) {
                out.error = Some(format!("solver: {e}"));
            }
        }
    }
    out.seconds = t.elapsed().as_secs_f64();
    out
}

/// `cycle` with the model's closed cycle on its profile (re)computed
/// ([`model_points`]); a model that fails sets `model_error`.
pub fn with_model(spec: &ScalesSpec, mut cycle: ScaleCycle) -> ScaleCycle {
    let model = case_params(spec, cycle.lambda, &cycle.waves).and_then(|(params, _)| model_cycle(params, spec, finest_wavelength(spec, &cycle.waves)));
    // An earlier model's error goes; the solver's stays (a study written
    // before `model_error` existed held it at the end of `error`).
    cycle.error = cycle.error.as_deref().map(without_legacy_model_error).filter(|e| !e.is_empty()).map(str::to_string);
    (cycle.model, cycle.model_error) = match model {
        Ok(m) => (Some(m), None),
        Err(e) => (None, Some(e.to_string())),
    };
    cycle
}

/// `error` of a study written before [`ScaleCycle::model_error`] existed,
/// without the model's part: that was appended last, as `model: ...` after
/// `"; "` (or alone), and its own text may hold `"; "`.
fn without_legacy_model_error(error: &str) -> &str {
    const MODEL: &str = "model: ";
    if error.starts_with(MODEL) {
        return "";
    }
    error.find(&format!("; {MODEL}")).map_or(error, |k| &error[..k])
}

/// The model's W, W_d and validity on `params`' profile.
fn model_cycle(params: Params, spec: &ScalesSpec, beta_min: f64) -> Result<ModelCycle> {
    let c = load_area_curve(params, CurveOptions { amax: spec.amax, points: model_points(spec, beta_min), ..CurveOptions::default() })?;
    // A cycle that does not close has no W (its zero is no measurement).
    let (load_open, disp_open) = (c.load_control.reloading_truncated, c.displacement_control.reloading_truncated);
    if load_open || disp_open {
        return Err(SolverError::ModelCycleOpen { load_control: load_open, displacement_control: disp_open });
    }
    let closed_valid = |p: &maugis::contact::paths::ControlPaths| {
        p.reloading.iter().chain(&p.unloading).chain(&p.cycle_unloading).all(|n| n.valid) && p.dissipation.invalid == 0.0
    };
    Ok(ModelCycle {
        w: c.load_control.dissipation.total,
        w_d: c.displacement_control.dissipation.total,
        valid: closed_valid(&c.load_control) && closed_valid(&c.displacement_control),
        valid_fraction: c.points.iter().filter(|p| p.validity.valid).count() as f64 / c.points.len() as f64,
    })
}

/// The solver's cycle of `case` into `out`.
fn simulate_case(
    spec: &ScalesSpec,
    case: &CycleCase,
    params: Params,
    profile: Option<WavyProfile>,
    finest: f64,
    resolution: ScaleResolution,
    out: &mut ScaleCycle,
) -> Result<()> {
    let half_width = suggested_half_width(params, spec.amax)?;
    let Resolution { cells, steps_per_leg: steps } = resolution.at(case.lambda, half_width, finest, spec.amax);
    out.cells = cells;
    out.steps_per_leg = steps;
    out.half_width = half_width;
    let (alpha, beta) = case.waves.first().copied().unwrap_or((0.0, spec.beta));
    let sim = simulate_with(
        SimulationSpec { lambda: case.lambda, alpha, beta, amax: spec.amax, cells, steps_per_leg: steps },
        SimulationOptions { law: spec.law, waves: profile, half_width: Some(half_width), without_model: true, ..SimulationOptions::default() },
        &mut |_, _| {},
    )?;
    let c = &sim.cycle;
    let in_contact: Vec<_> = c.loading.iter().chain(&c.unloading).chain(&c.reloading).filter(|s| s.abar > 0.0).collect();
    out.max_intervals = in_contact.iter().map(|s| s.contact_intervals()).max().unwrap_or(0);
    out.cavitated_fraction =
        in_contact.iter().filter(|s| s.contact_intervals() > 1).count() as f64 / in_contact.len().max(1) as f64;
    let (load, disp) = cycle_dissipation_along_legs(c, sim.datum, DEFAULT_DATUM)?;
    if !load.reloading_truncated {
        out.w = Some(load.work);
        out.pull_off = Some(load.end.load);
    }
    if !disp.reloading_truncated {
        out.w_d = Some(disp.work);
    }
    if load.reloading_truncated || disp.reloading_truncated {
        return Err(SolverError::CycleOpen { load_control: load.reloading_truncated, displacement_control: disp.reloading_truncated });
    }
    Ok(())
}

/// The study (or one shard of it).
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct ScalesStudy {
    /// The spec.
    pub spec: ScalesSpec,
    /// `(s, n)` when this is shard `s` of `n`.
    pub shard: Option<(usize, usize)>,
    /// The cycles run, by index.
    pub cycles: Vec<ScaleCycle>,
}

/// The cycles of shard `shard` (1-based `(s, n)`; `None`: all).
pub fn shard_cases(spec: &ScalesSpec, shard: Option<(usize, usize)>) -> Result<Vec<CycleCase>> {
    if let Some((s, n)) = shard {
        if n == 0 || s == 0 || s > n {
            return Err(SolverError::BadShard { shard: s, of: n });
        }
    }
    Ok(spec.cycles()?.into_iter().filter(|c| shard.map_or(true, |(s, n)| c.index % n == s - 1)).collect())
}

/// Runs shard `shard` of the study; the cycles run in parallel with the
/// `parallel` feature; `progress` is called once per finished cycle.
pub fn run_study<P: Fn(&ScaleCycle) + Sync>(spec: ScalesSpec, shard: Option<(usize, usize)>, progress: P) -> Result<ScalesStudy> {
    run_study_reusing(spec, shard, &[], progress)
}

/// Whether a cycle of `earlier` was run as `spec` would run it: the same
/// first wavelength (it sets the smooth cylinder's resolution), amax,
/// resolution rule, model points and law (the wavelength ratio, Hurst
/// exponents and lambdas may differ: the cycle is keyed by its own `lambda`
/// and waves).
fn same_setup(spec: &ScalesSpec, earlier: &ScalesSpec) -> bool {
    // The first wavelength too: the smooth cylinder's resolution follows it.
    spec.beta == earlier.beta
        && spec.amax == earlier.amax
        && spec.resolution == earlier.resolution
        && spec.model_points == earlier.model_points
        && spec.law == earlier.law
}

/// [`run_study`], taking each solver cycle that one of `earlier` studies
/// already ran with the same setup (the same `lambda` and waves; the same first
/// wavelength, amax, resolution rule, model points and law)
/// from it instead of running it again (its index and roles renumbered for
/// this study, the model recomputed, which is cheap beside the solver): a
/// study of more scales extends one of fewer.
pub fn run_study_reusing<P: Fn(&ScaleCycle) + Sync>(
    spec: ScalesSpec,
    shard: Option<(usize, usize)>,
    earlier: &[ScalesStudy],
    progress: P,
) -> Result<ScalesStudy> {
    let cases = shard_cases(&spec, shard)?;
    let known = |case: &CycleCase| {
        earlier.iter().filter(|e| same_setup(&spec, &e.spec)).flat_map(|e| &e.cycles).find(|c| {
            c.lambda.to_bits() == case.lambda.to_bits() && c.waves == case.waves
        })
    };
    let run = |case: &CycleCase| {
        let r = match known(case) {
            Some(c) => with_model(&spec, ScaleCycle { index: case.index, roles: case.roles.clone(), ..c.clone() }),
            None => run_cycle(&spec, case, spec.resolution),
        };
        progress(&r);
        r
    };
    #[cfg(feature = "parallel")]
    let cycles: Vec<ScaleCycle> = {
        use rayon::prelude::*;
        cases.par_iter().map(run).collect()
    };
    #[cfg(not(feature = "parallel"))]
    let cycles: Vec<ScaleCycle> = cases.iter().map(run).collect();
    Ok(ScalesStudy { spec, shard, cycles })
}

/// Reassembles shards of one study (in any order; together they must cover
/// every cycle exactly once, with one spec).
pub fn merge(parts: &[ScalesStudy]) -> Result<ScalesStudy> {
    let fault = |f| SolverError::Merge { fault: f };
    let first = parts.first().ok_or(fault(MergeFault::Empty))?;
    let total = first.spec.cycles()?.len();
    let mut slots: Vec<Option<ScaleCycle>> = vec![None; total];
    for p in parts {
        if p.spec != first.spec {
            return Err(fault(MergeFault::DifferentMaps));
        }
        for c in &p.cycles {
            let slot = slots.get_mut(c.index).ok_or(fault(MergeFault::OutsideGrid { index: c.index }))?;
            if slot.replace(c.clone()).is_some() {
                return Err(fault(MergeFault::Duplicate { index: c.index }));
            }
        }
    }
    let missing = slots.iter().filter(|s| s.is_none()).count();
    if missing > 0 {
        return Err(fault(MergeFault::Missing { missing, total }));
    }
    Ok(ScalesStudy { spec: first.spec.clone(), shard: None, cycles: slots.into_iter().flatten().collect() })
}

/// One row of the table of W against the number of scales.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct ScalesRow {
    /// Hurst exponent.
    pub hurst: f64,
    /// Maugis parameter.
    pub lambda: f64,
    /// Number of scales.
    pub scales: usize,
    /// The profile's cycle.
    pub profile: ScaleCycle,
    /// The smooth cylinder's W at this `lambda`.
    pub w_smooth: Option<f64>,
    /// `sum_j (W_j - W_smooth)` over the profile's waves alone, plus `W_smooth`:
    /// what the profile's W would be if the scales' excess dissipations added.
    pub w_sum_of_singles: Option<f64>,
    /// The same sum for W_d.
    pub w_d_sum_of_singles: Option<f64>,
}

impl ScalesStudy {
    /// The table: one row per Hurst exponent, `lambda` and number of scales.
    pub fn rows(&self) -> Vec<ScalesRow> {
        let find = |lambda: f64, role: CycleRole| {
            self.cycles.iter().find(|c| c.lambda.to_bits() == lambda.to_bits() && c.roles.contains(&role))
        };
        let mut rows = Vec::new();
        for &hurst in &self.spec.hursts {
            for &lambda in &self.spec.lambdas {
                let smooth = find(lambda, CycleRole::Smooth);
                for scales in 1..=self.spec.max_scales {
                    let Some(profile) = find(lambda, CycleRole::Profile { hurst, scales }) else { continue };
                    let sum = |get: &dyn Fn(&ScaleCycle) -> Option<f64>| -> Option<f64> {
                        let base = get(smooth?)?;
                        let mut s = base;
                        for wave in 0..scales {
                            s += get(find(lambda, CycleRole::Single { hurst, wave })?)? - base;
                        }
                        Some(s)
                    };
                    rows.push(ScalesRow {
                        hurst,
                        lambda,
                        scales,
                        profile: profile.clone(),
                        w_smooth: smooth.and_then(|s| s.w),
                        w_sum_of_singles: sum(&|c| c.w),
                        w_d_sum_of_singles: sum(&|c| c.w_d),
                    });
                }
            }
        }
        rows
    }
}

/// The search of `lambda*` for one profile of a study ([`lambda_star`]).
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct StarScan {
    /// Scan range of `lambda`.
    pub lambda_min: f64,
    /// Scan range of `lambda`.
    pub lambda_max: f64,
    /// Scan points (log-spaced, `>= 2`).
    pub scan: usize,
    /// Threshold as a fraction of `W_JKR` (`> 0`).
    pub fraction: f64,
    /// Bisect until the bracket's ratio is below `1 + rel_tol`.
    pub rel_tol: f64,
    /// Repeat the search at the refined resolution (the grid uncertainty).
    pub refine: bool,
}

/// `lambda*` of one profile of a study.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct ScaleTransition {
    /// Hurst exponent.
    pub hurst: f64,
    /// Number of scales.
    pub scales: usize,
    /// The search's settings.
    pub scan: StarScan,
    /// The model's W (load control) of the profile at [`JKR_LAMBDA`].
    pub w_jkr: f64,
    /// `fraction * w_jkr`.
    pub threshold: f64,
    /// At the study's resolution.
    pub search: Search,
    /// At the refined resolution (`None`: not run).
    pub refined: Option<Search>,
}

impl ScaleTransition {
    /// `lambda*` of the refined search, or of the search without one.
    pub fn lambda_star(&self) -> Option<f64> {
        self.refined.as_ref().map_or(self.search.lambda_star, |r| r.lambda_star)
    }

    /// Relative uncertainty (`crate::transition` module docs).
    pub fn relative_uncertainty(&self) -> Option<f64> {
        relative_uncertainty(&self.search, self.refined.as_ref())
    }
}

/// `lambda*` of the profile of `scales` scales at `hurst` (issue 39 item 3),
/// with `crate::transition`'s definition: the lower end of the range where the
/// excess `W - W_smooth` of the solver's closed cycle exceeds `fraction` times
/// the model's W in the JKR limit ([`JKR_LAMBDA`]) on the same profile, by a
/// log scan and bisection, repeated at the refined resolution for the grid
/// uncertainty. The cycles are the study's ([`run_cycle`]'s resolution rule),
/// read along the legs; `progress` is called after each cycle pair.
pub fn lambda_star(spec: &ScalesSpec, hurst: f64, scales: usize, scan: StarScan, progress: &(dyn Fn(&Evaluation) + Sync)) -> Result<ScaleTransition> {
    spec.check()?;
    count_in_range(scales, "the number of scales", 1, spec.max_scales)?;
    for (v, what) in [(scan.lambda_min, "lambda_min"), (scan.lambda_max, "lambda_max"), (scan.fraction, "fraction")] {
        finite(v, what)?;
        in_range(v, what, Interval::above(0.0))?;
    }
    in_range(scan.lambda_max, "lambda_max (above lambda_min)", Interval::above(scan.lambda_min))?;
    let waves = spec.waves(hurst, scales)?;
    let (jkr, _) = case_params(spec, JKR_LAMBDA, &waves)?;
    let w_jkr = model_cycle(jkr, spec, finest_wavelength(spec, &waves))?.w;
    let threshold = scan.fraction * w_jkr;
    let mut cache: std::collections::HashMap<(u64, u32), Evaluation> = std::collections::HashMap::new();
    let mut run = |resolution: ScaleResolution, lambdas: &[f64]| -> Result<Search> {
        let mut eval = |lambda: f64| -> Result<Evaluation> {
            if let Some(e) = cache.get(&(lambda.to_bits(), resolution.refinement)) {
                return Ok(*e);
            }
            let w = |waves: &[(f64, f64)]| -> Result<(f64, Resolution)> {
                let case = CycleCase { index: 0, lambda, waves: waves.to_vec(), roles: Vec::new() };
                let (params, profile) = case_params(spec, lambda, waves)?;
                let mut c = blank_cycle(&case);
                simulate_case(spec, &case, params, profile, finest_wavelength(spec, waves), resolution, &mut c)?;
                Ok((c.w.unwrap_or(f64::NAN), Resolution { cells: c.cells, steps_per_leg: c.steps_per_leg }))
            };
            let (w_rough, r) = w(&waves)?;
            let (w_smooth, _) = w(&[])?;
            let e = Evaluation { lambda, w: w_rough, w_smooth, resolution: r };
            progress(&e);
            cache.insert((lambda.to_bits(), resolution.refinement), e);
            Ok(e)
        };
        search_with(lambdas, scan.rel_tol, threshold, &mut eval)
    };
    let lambdas = scan_lambdas(scan.lambda_min, scan.lambda_max, scan.scan);
    let search = run(spec.resolution, &lambdas)?;
    let refined = if scan.refine {
        let fine = spec.resolution.refined();
        let mut r = match search.scan_bracket {
            Some((lo, hi)) => run(fine, &[lo, hi])?,
            None => run(fine, &lambdas)?,
        };
        if r.outside.is_some() && search.scan_bracket.is_some() {
            r = run(fine, &lambdas)?;
        }
        Some(r)
    } else {
        None
    };
    Ok(ScaleTransition { hurst, scales, scan, w_jkr, threshold, search, refined })
}
