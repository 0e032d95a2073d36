//! W of the closed in-contact cycle measured on a simulated cycle
//! (`maugis_solver::dissipation`) against the semi-analytical model's W
//! (`maugis::contact::paths`, the same definition) where the model is valid
//! along the whole cycle: the Fig. 4c roughness (alpha = 2 sqrt(2)/8,
//! beta = 9/8) at lambda = 3 and 6, and the smooth cylinder at lambda = 1,
//! amax = 6; and alpha = 1/6 at lambda = 4, where the closed cycle's first
//! loop needs the reloading leg of the simulated cycle. Tolerance (issue 24):
//! 2 % of the model's W, or 0.02 where W is near 0 (below 1: the smooth
//! cylinder, W = 0, and alpha = 1/6, W = 0.37).
//!
//! Resolution: 4096 cells and 400 approach steps per leg. The steps, not the
//! cells, set the error: W is made by the turning points of the load (and of
//! `Delta_d`), which the stiff machine samples once per step. At 400 steps
//! the measured differences are -0.04 % (W) and -0.64 % (W_d) at lambda = 3,
//! -0.16 % and -0.80 % at lambda = 6; at 100 steps W_d misses by 7.6 % at
//! lambda = 3 (checked below, so the tolerance bites). The smooth cylinder has
//! no fold to resolve: 100 steps.

use maugis::contact::curve::{load_area_curve, CurveOptions};
use maugis::contact::model::Params;
use maugis::contact::paths::Driver;
use maugis_solver::dissipation::{closed_cycle, cycle_dissipation_along_legs};
use maugis_solver::run::{simulate, Simulation, SimulationSpec};

const FIG4C_ALPHA: f64 = std::f64::consts::SQRT_2 / 4.0;
const FIG4C_BETA: f64 = 1.125;
const AMAX: f64 = 6.0;
/// Relative tolerance on W where W is not near 0.
const REL_TOL: f64 = 0.02;
/// Absolute tolerance where W is near 0.
const ABS_TOL: f64 = 0.02;

/// (solver W, solver W_d, model W, model W_d).
fn both(lambda: f64, alpha: f64, steps: usize) -> (f64, f64, f64, f64) {
    let (w, _) = with_simulation(lambda, alpha, steps);
    w
}

/// [`both`] and the simulation.
fn with_simulation(lambda: f64, alpha: f64, steps: usize) -> ((f64, f64, f64, f64), Simulation) {
    let spec = SimulationSpec {
        lambda,
        alpha,
        beta: FIG4C_BETA,
        amax: AMAX,
        cells: 4096,
        steps_per_leg: steps,
    };
    let sim = simulate(spec, &mut |_, _| {}).unwrap();
    let d = sim.dissipation().unwrap();
    assert!(
        d.load_control.single_interval,
        "lambda {lambda}: a cavitated state"
    );
    assert!(!d.load_control.reloading_truncated && !d.displacement_control.reloading_truncated);
    let curve = load_area_curve(
        Params::new(lambda, alpha, FIG4C_BETA).unwrap(),
        CurveOptions {
            amax: AMAX,
            ..CurveOptions::default()
        },
    )
    .unwrap();
    // The model is valid along the whole cycle: every loop it counts is valid.
    for c in [&curve.load_control, &curve.displacement_control] {
        assert_eq!(
            c.dissipation.invalid, 0.0,
            "lambda {lambda}: the model has invalid loops"
        );
    }
    // The reading along the legs (for cavitated cycles) agrees with the
    // reading by contact size, and so with the model, on these cycles of one
    // contact interval (at 400 steps; at 100 both miss turning points, see
    // `coarse_steps_miss_the_tolerance_and_w_is_not_the_stiff_work`).
    let (legs_w, legs_wd) = cycle_dissipation_along_legs(&sim.cycle, sim.datum, maugis::contact::curve::DEFAULT_DATUM).unwrap();
    for (name, legs, model) in [("W", &legs_w, &curve.load_control), ("W_d", &legs_wd, &curve.displacement_control)].into_iter().filter(|_| steps >= 400) {
        eprintln!("lambda {lambda} alpha {alpha}: {name} along the legs {} (model {})", legs.work, model.dissipation.total);
        assert!(!legs.reloading_truncated && legs.cavitated_fraction == 0.0);
        assert!(
            agrees(legs.work, model.dissipation.total),
            "lambda {lambda} alpha {alpha}: {name} along the legs {} against the model's {}",
            legs.work,
            model.dissipation.total
        );
    }
    (
        (
            d.load_control.dissipation.total,
            d.displacement_control.dissipation.total,
            curve.load_control.dissipation.total,
            curve.displacement_control.dissipation.total,
        ),
        sim,
    )
}

fn agrees(solver: f64, model: f64) -> bool {
    if model.abs() < 1.0 {
        (solver - model).abs() <= ABS_TOL
    } else {
        (solver - model).abs() <= REL_TOL * model.abs()
    }
}

fn check(lambda: f64, alpha: f64, steps: usize) {
    let (w, wd, mw, mwd) = both(lambda, alpha, steps);
    eprintln!("lambda {lambda} alpha {alpha}: W {w} (model {mw}), W_d {wd} (model {mwd})");
    assert!(
        agrees(w, mw),
        "lambda {lambda}: W {w} against the model's {mw}"
    );
    assert!(
        agrees(wd, mwd),
        "lambda {lambda}: W_d {wd} against the model's {mwd}"
    );
}

#[test]
fn fig4c_lambda_3_dissipation_matches_the_model() {
    check(3.0, FIG4C_ALPHA, 400);
}

#[test]
fn fig4c_lambda_6_dissipation_matches_the_model() {
    check(6.0, FIG4C_ALPHA, 400);
}

/// alpha = 1/6, lambda = 4: the model is valid along the whole cycle, and
/// the upper end of its first loop, the load maximum of the small-contact
/// branch, lies on a stretch that neither the loading nor the unloading leg
/// visits (the unloading leg jumps over it, the loading leg snaps in beyond
/// it). The reloading leg visits it; without it W is 22 % low.
#[test]
fn alpha_sixth_lambda_4_needs_the_reloading_leg() {
    let ((w, wd, mw, mwd), sim) = with_simulation(4.0, 1.0 / 6.0, 400);
    eprintln!("alpha 1/6 lambda 4: W {w} (model {mw}), W_d {wd} (model {mwd})");
    assert!(agrees(w, mw), "W {w} against the model's {mw}");
    assert!(agrees(wd, mwd), "W_d {wd} against the model's {mwd}");
    assert!(!sim.cycle.reloading.is_empty());
    let mut two_legs = sim.cycle.clone();
    two_legs.reloading.clear();
    let w2 = closed_cycle(&two_legs, sim.datum, Driver::load()).unwrap().dissipation.total;
    assert!(!agrees(w2, mw), "without the reloading leg W {w2} against {mw}");
}

#[test]
fn smooth_lambda_1_dissipates_nothing() {
    let (w, wd, mw, mwd) = both(1.0, 0.0, 100);
    assert!(
        mw.abs() < 1e-12 && mwd.abs() < 1e-12,
        "model W {mw}, W_d {mwd}"
    );
    assert!(agrees(w, mw) && agrees(wd, mwd), "W {w}, W_d {wd}");
}

/// W is not the stiff-machine work (12.0 at lambda = 6), and with 100 steps
/// per leg W_d at lambda = 3 misses the tolerance: the test above can fail.
#[test]
fn coarse_steps_miss_the_tolerance_and_w_is_not_the_stiff_work() {
    let (_, wd, _, mwd) = both(3.0, FIG4C_ALPHA, 100);
    assert!(!agrees(wd, mwd), "W_d {wd} against {mwd} at 100 steps");
    let spec = SimulationSpec {
        lambda: 6.0,
        alpha: FIG4C_ALPHA,
        beta: FIG4C_BETA,
        amax: AMAX,
        cells: 4096,
        steps_per_leg: 100,
    };
    let sim = simulate(spec, &mut |_, _| {}).unwrap();
    let w = sim.dissipation().unwrap().load_control.dissipation.total;
    assert!(
        sim.cycle.stiff_work > 2.0 * w,
        "stiff work {} against W {w}",
        sim.cycle.stiff_work
    );
}
