//! The transitional Maugis parameter `lambda*` (issue 24, item 3): for a
//! roughness `(alpha, beta)`, the `lambda` below which the roughness-induced
//! dissipation measured by the solver vanishes.
//!
//! # Definition
//!
//! The roughness-induced dissipation at `lambda` is the excess
//! `E(lambda) = W(lambda, alpha, beta) - W(lambda, 0, beta)` of the solver's W
//! (closed in-contact cycle, load control, [`crate::dissipation`]) over the
//! smooth cylinder's at the same resolution, as in the solver map
//! ([`crate::map`]). It *vanishes* below the threshold
//! `t = fraction * W_JKR`, with `W_JKR` the model's W (load control) at
//! [`JKR_LAMBDA`] (`lambda = 1000`, the JKR limit for these roughnesses: the
//! model is valid along the whole cycle there).
//!
//! `lambda*` is the lower end of the dissipative range: `E` is evaluated on a
//! log-spaced scan of `lambda` over `[lambda_min, lambda_max]`; the first scan
//! point with `E > t` and the one before it bracket `lambda*`, and the
//! bracket is bisected in `ln lambda` until its ratio is below
//! `1 + rel_tol`. `lambda*` is the bracket's geometric mean.
//!
//! # Uncertainty
//!
//! * bisection: half the final bracket in `ln lambda`;
//! * grid: the search repeated at the refined resolution (twice the cells
//!   and twice the steps per leg), from the two scan points around the first
//!   bracket (the whole scan again if they do not bracket it),
//!   `|ln lambda*_fine - ln lambda*|`;
//! * the reported relative uncertainty is their sum.
//!
//! `E` need not be monotone in `lambda` (the closed cycle's W can switch
//! between branches where two unloading minima are nearly level), so a
//! scan with a later return below `t` is reported ([`Search::non_monotone`]).

use maugis::contact::curve::{load_area_curve, CurveOptions};
use maugis::contact::model::Params;

use crate::error::{count_in_range, finite, in_range, Interval, Result};
use crate::map::{measure_cycle_under, Resolution, ResolutionRule};
use crate::profile::AdhesionLaw;

/// The `lambda` whose model W stands for the JKR limit.
pub const JKR_LAMBDA: f64 = 1000.0;

/// What to search.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct TransitionSpec {
    /// Amplitude (`> 0`).
    pub alpha: f64,
    /// Wavelength.
    pub beta: f64,
    /// Largest contact half-width of every cycle.
    pub amax: f64,
    /// Scan range of `lambda`.
    pub lambda_min: f64,
    /// Scan range of `lambda`.
    pub lambda_max: f64,
    /// Scan points (log-spaced, `>= 2`).
    pub scan: usize,
    /// Threshold as a fraction of `W_JKR` (`> 0`).
    pub fraction: f64,
    /// Bisect until the bracket's ratio is below `1 + rel_tol` (`> 0`).
    pub rel_tol: f64,
    /// The resolution (the refined search doubles cells and steps).
    pub resolution: ResolutionRule,
    /// The adhesion law of every cycle (`W_JKR` is the model's, law-free in the JKR limit).
    #[cfg_attr(feature = "serde", serde(default))]
    pub law: AdhesionLaw,
}

/// One evaluation of the excess.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Evaluation {
    /// Maugis parameter.
    pub lambda: f64,
    /// W of the rough cylinder.
    pub w: f64,
    /// W of the smooth cylinder at the same resolution.
    pub w_smooth: f64,
    /// The resolution.
    pub resolution: Resolution,
}

impl Evaluation {
    /// `w - w_smooth`.
    pub fn excess(&self) -> f64 {
        self.w - self.w_smooth
    }
}

/// Where `lambda*` lies when the scan does not bracket it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
pub enum Outside {
    /// Below the scan (dissipation at its lowest lambda).
    Below,
    /// Above the scan (no dissipation up to its largest lambda).
    Above,
}

impl Outside {
    /// `"below the scan"` or `"above the scan"`.
    pub fn name(self) -> &'static str {
        match self {
            Outside::Below => "below the scan",
            Outside::Above => "above the scan",
        }
    }
}

/// One search at one resolution.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Search {
    /// `lambda*` (geometric mean of the bracket); `None` when the scan never
    /// crosses the threshold.
    pub lambda_star: Option<f64>,
    /// The two scan points around the crossing (where bisection started).
    pub scan_bracket: Option<(f64, f64)>,
    /// The final bracket.
    pub bracket: Option<(f64, f64)>,
    /// `lambda*` lies outside the scan: `E` at the lowest scan point already
    /// exceeds the threshold, or no scan point exceeds it.
    pub outside: Option<Outside>,
    /// After the first crossing, a later scan point returns below the threshold.
    pub non_monotone: bool,
    /// Every evaluation, in order.
    pub evaluations: Vec<Evaluation>,
}

/// The result: the search at the spec's resolution and at the refined one.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Transition {
    /// The spec.
    pub spec: TransitionSpec,
    /// The model's W at [`JKR_LAMBDA`].
    pub w_jkr: f64,
    /// The threshold `fraction * w_jkr`.
    pub threshold: f64,
    /// At the spec's resolution.
    pub search: Search,
    /// At twice the cells and steps (`None`: not run, see [`transitions`]).
    pub refined: Option<Search>,
}

impl Transition {
    /// `lambda*` of the refined search (the better estimate), or of the
    /// search when there is no refined one.
    pub fn lambda_star(&self) -> Option<f64> {
        self.refined.as_ref().map_or(self.search.lambda_star, |r| r.lambda_star)
    }

    /// Relative uncertainty of `lambda*` (module docs): half the final
    /// bracket in `ln lambda`, plus the shift between the two resolutions when
    /// the refined search ran (without it, the bisection part only).
    pub fn relative_uncertainty(&self) -> Option<f64> {
        relative_uncertainty(&self.search, self.refined.as_ref())
    }
}

/// The relative uncertainty of `lambda*` from a search and its refined
/// repetition (module docs): half the final bracket in `ln lambda`, plus the
/// shift between the two resolutions when the refined search ran.
pub fn relative_uncertainty(search: &Search, refined: Option<&Search>) -> Option<f64> {
    let best = refined.unwrap_or(search);
    let (lo, hi) = best.bracket?;
    let shift = match refined {
        Some(r) => (r.lambda_star?.ln() - search.lambda_star?.ln()).abs(),
        None => 0.0,
    };
    Some(0.5 * (hi / lo).ln() + shift)
}

/// The model's W (load control) at [`JKR_LAMBDA`].
pub fn w_jkr(alpha: f64, beta: f64, amax: f64) -> Result<f64> {
    let c = load_area_curve(Params::new(JKR_LAMBDA, alpha, beta)?, CurveOptions { amax, ..CurveOptions::default() })?;
    Ok(c.load_control.dissipation.total)
}

impl TransitionSpec {
    /// Checks the spec.
    pub fn check(&self) -> Result<()> {
        for (v, w) in [(self.alpha, "alpha"), (self.beta, "beta"), (self.amax, "amax"), (self.lambda_min, "lambda_min"), (self.lambda_max, "lambda_max"), (self.fraction, "fraction"), (self.rel_tol, "rel_tol")] {
            finite(v, w)?;
        }
        in_range(self.alpha, "alpha (lambda* needs a rough cylinder)", Interval::above(0.0))?;
        in_range(self.lambda_min, "lambda_min", Interval::above(0.0))?;
        in_range(self.lambda_max, "lambda_max (above lambda_min)", Interval::above(self.lambda_min))?;
        count_in_range(self.scan, "scan points", 2, usize::MAX)?;
        in_range(self.fraction, "fraction", Interval::above(0.0))?;
        in_range(self.rel_tol, "rel_tol", Interval::above(0.0))?;
        Params::new(self.lambda_min, self.alpha, self.beta)?;
        Params::new(self.lambda_max, self.alpha, self.beta)?;
        Ok(())
    }
}

/// Evaluations already made, by `(lambda, resolution)`: searches for several
/// thresholds share their scan.
pub type Cache = std::collections::HashMap<(u64, usize, usize), Evaluation>;

/// `E(lambda)` at `resolution`.
pub fn evaluate(spec: &TransitionSpec, lambda: f64, resolution: Resolution) -> Result<Evaluation> {
    let w = measure_cycle_under(spec.law, lambda, spec.alpha, spec.beta, spec.amax, resolution)?.w;
    let w_smooth = measure_cycle_under(spec.law, lambda, 0.0, spec.beta, spec.amax, resolution)?.w;
    Ok(Evaluation { lambda, w, w_smooth, resolution })
}

/// One search with `resolution_at` giving the resolution at each `lambda`:
/// the spec's scan, or only the two ends of `range` when given; `progress`
/// is called after each evaluation.
pub fn search(
    spec: &TransitionSpec,
    threshold: f64,
    resolution_at: &dyn Fn(f64) -> Resolution,
    range: Option<(f64, f64)>,
    cache: &mut Cache,
    progress: &mut dyn FnMut(&Evaluation),
) -> Result<Search> {
    spec.check()?;
    let mut eval = |lambda: f64| -> Result<Evaluation> {
        let r = resolution_at(lambda);
        let key = (lambda.to_bits(), r.cells, r.steps_per_leg);
        Ok(match cache.get(&key) {
            Some(e) => *e,
            None => {
                let e = evaluate(spec, lambda, r)?;
                progress(&e);
                cache.insert(key, e);
                e
            }
        })
    };
    let lambdas = match range {
        Some((lo, hi)) => vec![lo, hi],
        None => scan_lambdas(spec.lambda_min, spec.lambda_max, spec.scan),
    };
    search_with(&lambdas, spec.rel_tol, threshold, &mut eval)
}

/// `n` log-spaced values from `lo` to `hi`.
pub fn scan_lambdas(lo: f64, hi: f64, n: usize) -> Vec<f64> {
    let (l0, l1) = (lo.ln(), hi.ln());
    (0..n).map(|i| (l0 + (l1 - l0) * i as f64 / (n.max(2) - 1) as f64).exp()).collect()
}

/// The search of [`search`] over the scan `lambdas` (increasing) with any
/// evaluation of the excess: the first scan point above `threshold` and the
/// one before it bracket `lambda*`, bisected in `ln lambda` until the
/// bracket's ratio is below `1 + rel_tol` (module docs). The profiles of many
/// scales (`crate::scales`) search with their own cycles through it.
pub fn search_with(lambdas: &[f64], rel_tol: f64, threshold: f64, eval: &mut dyn FnMut(f64) -> Result<Evaluation>) -> Result<Search> {
    finite(rel_tol, "rel_tol")?;
    in_range(rel_tol, "rel_tol", Interval::above(0.0))?;
    count_in_range(lambdas.len(), "scan points", 2, usize::MAX)?;
    let mut evaluations = Vec::new();
    let mut first_above = None;
    let mut non_monotone = false;
    for (i, &lambda) in lambdas.iter().enumerate() {
        let e = eval(lambda)?;
        evaluations.push(e);
        let above = e.excess() > threshold;
        match (first_above, above) {
            (None, true) => first_above = Some(i),
            (Some(_), false) => non_monotone = true,
            _ => {}
        }
    }
    let i = match first_above {
        None => return Ok(Search { lambda_star: None, scan_bracket: None, bracket: None, outside: Some(Outside::Above), non_monotone, evaluations }),
        Some(0) => return Ok(Search { lambda_star: None, scan_bracket: None, bracket: None, outside: Some(Outside::Below), non_monotone, evaluations }),
        Some(i) => i,
    };
    let (mut lo, mut hi) = (lambdas[i - 1], lambdas[i]);
    while hi / lo > 1.0 + rel_tol {
        let mid = (lo * hi).sqrt();
        let e = eval(mid)?;
        evaluations.push(e);
        if e.excess() > threshold {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    Ok(Search { lambda_star: Some((lo * hi).sqrt()), scan_bracket: Some((lambdas[i - 1], lambdas[i])), bracket: Some((lo, hi)), outside: None, non_monotone, evaluations })
}

/// `lambda*` with its uncertainty (module docs) for one threshold
/// (`spec.fraction`): the model's `W_JKR`, then the search at the spec's
/// resolution and at twice its cells and steps.
pub fn transition(spec: TransitionSpec, progress: &mut dyn FnMut(&Evaluation)) -> Result<Transition> {
    Ok(transitions(spec, &[spec.fraction], progress)?.remove(0))
}

/// [`transition`] for several thresholds sharing one scan: the first of
/// `fractions` gets the refined search too, the others the spec's resolution
/// only (`refined: None`). `progress` is called once per new evaluation.
pub fn transitions(spec: TransitionSpec, fractions: &[f64], progress: &mut dyn FnMut(&Evaluation)) -> Result<Vec<Transition>> {
    transitions_refined(spec, fractions, true, progress)
}

/// [`transitions`], with the refined search of the first fraction only when
/// `refine` (otherwise every `refined` is `None`: the bisection part of the
/// uncertainty only).
pub fn transitions_refined(spec: TransitionSpec, fractions: &[f64], refine: bool, progress: &mut dyn FnMut(&Evaluation)) -> Result<Vec<Transition>> {
    spec.check()?;
    for &f in fractions {
        TransitionSpec { fraction: f, ..spec }.check()?;
    }
    let w_jkr = w_jkr(spec.alpha, spec.beta, spec.amax)?;
    let rule = spec.resolution;
    let fine = |l: f64| {
        let r = rule.at(l);
        Resolution { cells: 2 * r.cells, steps_per_leg: 2 * r.steps_per_leg }
    };
    let mut cache = Cache::new();
    let mut out = Vec::with_capacity(fractions.len());
    for (k, &fraction) in fractions.iter().enumerate() {
        let spec = TransitionSpec { fraction, ..spec };
        let threshold = fraction * w_jkr;
        let coarse = search(&spec, threshold, &|l| rule.at(l), None, &mut cache, progress)?;
        let refined = if k == 0 && refine {
            // From the scan points around the coarse bracket; the whole scan
            // again when they do not bracket it.
            let mut r = search(&spec, threshold, &fine, coarse.scan_bracket, &mut cache, progress)?;
            if r.outside.is_some() && coarse.scan_bracket.is_some() {
                let mut whole = search(&spec, threshold, &fine, None, &mut cache, progress)?;
                r.evaluations.append(&mut whole.evaluations);
                whole.evaluations = r.evaluations;
                r = whole;
            }
            Some(r)
        } else {
            None
        };
        out.push(Transition { spec, w_jkr, threshold, search: coarse, refined });
    }
    Ok(out)
}

/// One Johnson parameter of [`johnson_sweep`].
#[derive(Debug, Clone)]
pub struct JohnsonRow {
    /// `chi = sqrt(beta/alpha^2)`.
    pub chi: f64,
    /// The spec searched (`alpha = sqrt(beta)/chi`).
    pub spec: TransitionSpec,
    /// [`transitions_refined`]: one [`Transition`] per fraction.
    pub result: Result<Vec<Transition>>,
    /// Wall time of this parameter's searches (s).
    pub seconds: f64,
}

/// `lambda*` for several Johnson parameters `chi = sqrt(beta/alpha^2)` at the
/// wavelength of `template` (whose `alpha` is replaced by `sqrt(beta)/chi`),
/// one thread per parameter: [`transitions_refined`] with `fractions`, the
/// refined search where `refine(chi)`. Rows in the order of `chis`.
pub fn johnson_sweep(template: TransitionSpec, chis: &[f64], fractions: &[f64], refine: &(dyn Fn(f64) -> bool + Sync)) -> Vec<JohnsonRow> {
    std::thread::scope(|sc| {
        let handles: Vec<_> = chis
            .iter()
            .map(|&chi| {
                sc.spawn(move || {
                    let t = std::time::Instant::now();
                    let spec = TransitionSpec { alpha: template.beta.sqrt() / chi, ..template };
                    let result = transitions_refined(spec, fractions, refine(chi), &mut |_| {});
                    JohnsonRow { chi, spec, result, seconds: t.elapsed().as_secs_f64() }
                })
            })
            .collect();
        // A search thread panics only on a bug: pass it on.
        handles.into_iter().map(|h| h.join().unwrap_or_else(|p| std::panic::resume_unwind(p))).collect()
    })
}
