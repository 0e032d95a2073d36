//! lambda* by bisection (`transition`): on the Fig. 4c roughness at a coarse
//! resolution and the refined one (twice the cells and steps), the bracket
//! holds the crossing of the threshold by the evaluations themselves, the
//! uncertainty covers the two resolutions, and bad specs are typed errors.
//!
//! Default tier: 512 cells and 100 steps (refined 1024 and 200), about a sixth
//! of the long tier's cost; the two brackets are those of the long tier
//! (coarse (0.886, 1.095), refined (0.716, 0.886)), so the shift between the
//! resolutions is not zero and the uncertainty must cover it. Long tier: 1024
//! and 100 (refined 2048 and 200), as before.

use maugis_solver::profile::AdhesionLaw;
use maugis_solver::map::{Resolution, ResolutionRule};
use maugis_solver::transition::{johnson_sweep, transition, Search, TransitionSpec};
use maugis_solver::SolverError;

use crate::tier;

fn spec() -> TransitionSpec {
    TransitionSpec {
        alpha: 2.0 * 2f64.sqrt() / 8.0,
        beta: 1.125,
        amax: 6.0,
        lambda_min: 0.2,
        lambda_max: 6.0,
        scan: 2,
        fraction: 0.1,
        rel_tol: 0.25,
        resolution: ResolutionRule::Fixed(coarse_resolution()),
        law: AdhesionLaw::Dugdale,
    }
}

/// The coarse search's resolution: 512 cells and 100 steps a leg in the default
/// tier, 1024 and 100 in the long tier (module docs).
fn coarse_resolution() -> Resolution {
    Resolution { cells: tier::pick(512, 1024), steps_per_leg: 100 }
}

/// The final bracket `(lo, hi)`: `lo` is the largest evaluated lambda inside
/// the scan bracket at or below the threshold, `hi` the smallest above it.
fn check_bracket(s: &Search, threshold: f64, rel_tol: f64) -> f64 {
    let (lo, hi) = s.bracket.expect("a bracket");
    assert!(hi / lo <= 1.0 + rel_tol && hi > lo, "{lo} {hi}");
    let at = |l: f64| s.evaluations.iter().find(|e| e.lambda == l).unwrap_or_else(|| panic!("no evaluation at {l}")).excess();
    assert!(at(lo) <= threshold && at(hi) > threshold, "E({lo}) = {}, E({hi}) = {}, t = {threshold}", at(lo), at(hi));
    let star = s.lambda_star.unwrap();
    assert!(star > lo && star < hi);
    star
}

#[test]
fn lambda_star_is_bracketed_with_an_uncertainty() {
    let sp = spec();
    let mut seen = 0;
    let t = transition(sp, &mut |_| seen += 1).unwrap();
    assert!(t.w_jkr > 1.0, "W_JKR {}", t.w_jkr);
    assert_eq!(t.threshold, sp.fraction * t.w_jkr);
    let refined = t.refined.as_ref().expect("the refined search runs");
    assert_eq!(seen, t.search.evaluations.len() + refined.evaluations.len());
    let coarse = check_bracket(&t.search, t.threshold, sp.rel_tol);
    let fine = check_bracket(refined, t.threshold, sp.rel_tol);
    assert_eq!(t.lambda_star(), Some(fine));
    let c = coarse_resolution();
    assert!(t.search.evaluations.iter().all(|e| e.resolution == c));
    assert!(refined.evaluations.iter().all(|e| e.resolution == Resolution { cells: 2 * c.cells, steps_per_leg: 2 * c.steps_per_leg }));
    let u = t.relative_uncertainty().unwrap();
    let shift = (fine.ln() - coarse.ln()).abs();
    assert!(shift > 0.0, "the two resolutions' lambda* agree ({fine}): the shift is not exercised");
    assert!(u >= shift && u.is_finite(), "{u}");
    // The same roughness as the Johnson parameter chi = sqrt(beta)/alpha = 3,
    // without the refined search, next to a bad one: rows in order, the
    // coarse search's bracket, a typed error for chi < 0 (alpha < 0).
    // Default tier: the search over the coarse search's final bracket (its two
    // ends, no bisection); long tier: the whole coarse search again.
    let (lo, hi) = t.search.bracket.unwrap();
    let template = tier::pick(TransitionSpec { lambda_min: lo, lambda_max: hi, ..sp }, sp);
    let rows = johnson_sweep(template, &[3.0, -1.0], &[sp.fraction], &|_| false);
    assert_eq!((rows[0].chi, rows[1].chi), (3.0, -1.0));
    assert!((rows[0].spec.alpha / sp.alpha - 1.0).abs() < 1e-15, "{}", rows[0].spec.alpha);
    let r = &rows[0].result.as_ref().unwrap()[0];
    assert!(r.refined.is_none());
    // The same bracket (the scan's ends are exp(ln lambda), within rounding of
    // the coarse search's), from the same W at every lambda it evaluated.
    let (rlo, rhi) = r.search.bracket.expect("the sweep's search brackets lambda*");
    let close = |a: f64, b: f64| (a / b - 1.0).abs() <= 1e-12;
    assert!(close(rlo, lo) && close(rhi, hi), "({rlo}, {rhi}) against ({lo}, {hi})");
    for e in &r.search.evaluations {
        let same = t.search.evaluations.iter().find(|c| close(c.lambda, e.lambda)).unwrap_or_else(|| panic!("the coarse search has no lambda = {}", e.lambda));
        assert!((e.w - same.w).abs() <= 1e-9 * same.w.abs().max(1.0) && (e.w_smooth - same.w_smooth).abs() <= 1e-9, "{e:?} against {same:?}");
    }
    assert!(matches!(rows[1].result, Err(SolverError::OutOfRange { arg, .. }) if arg.starts_with("alpha")), "{:?}", rows[1].result);
}

#[test]
fn bad_specs_are_errors() {
    let sp = spec();
    let err = |s: TransitionSpec| transition(s, &mut |_| ()).unwrap_err();
    assert!(matches!(err(TransitionSpec { alpha: 0.0, ..sp }), SolverError::OutOfRange { arg, value: 0.0, .. } if arg.starts_with("alpha")));
    assert!(matches!(err(TransitionSpec { lambda_max: 0.1, ..sp }), SolverError::OutOfRange { arg, value: 0.1, .. } if arg.starts_with("lambda_max")));
    assert!(matches!(err(TransitionSpec { scan: 1, ..sp }), SolverError::CountOutOfRange { value: 1, min: 2, .. }));
    assert!(matches!(err(TransitionSpec { fraction: 0.0, ..sp }), SolverError::OutOfRange { arg: "fraction", .. }));
    assert!(matches!(err(TransitionSpec { rel_tol: f64::NAN, ..sp }), SolverError::NonFinite { arg: "rel_tol", .. }));
    assert!(matches!(err(TransitionSpec { beta: -1.0, ..sp }), SolverError::Model(maugis::Error::OutOfRange { arg: "beta", .. })));
}
