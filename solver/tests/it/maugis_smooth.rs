//! Smooth Dugdale-Maugis cylinder (alpha = 0) against the semi-analytical model
//! of the `maugis` crate (Johnson and Greenwood 2008) at the same contact
//! half-width, on loading and unloading, load and approach (on the model's
//! datum), at lambda = 0.1, 1 and 10, on the default grid (4096 cells); and
//! the energy identity `dPi/dDelta = Lbar` of the discrete solution. lambda =
//! 10 (a Dugdale zone of about 5 cells) needs the zone ends placed within
//! their cells (`SolveOptions::sub_cell_ends`, docs/solver.md).

use maugis::contact::model::Params;
use maugis_solver::contact::{ContactSolver, SolveOptions};
use maugis_solver::grid::Grid;
use maugis_solver::path::{compare_with_model, cycle, suggested_half_width, CycleOptions};
use maugis_solver::profile::{Adhesion, Profile};

/// 1 % of the load scale: the normalised load unit `(E* dgamma^2 R)^(1/3)`.
const LOAD_TOL: f64 = 0.01;

/// Approach tolerance on the model's datum (`path::approach_on_model_datum`),
/// units `l_v`: the measured error at 4096 cells is below 3e-3 for lambda in
/// {0.1, 1, 10} (docs/solver.md, mesh convergence).
const APPROACH_TOL: f64 = 5e-3;

/// One cycle at 4096 cells: every contact state is valid in the model, has one
/// contact interval, and matches the model's load and approach at its `abar`.
fn smooth_cycle_matches_the_model(lambda: f64, amax: f64, steps: usize) {
    let params = Params::new(lambda, 0.0, 1.0).unwrap();
    let grid = Grid::new(4096, suggested_half_width(params, amax).unwrap()).unwrap();
    let profile = Profile::wavy_cylinder(0.0, 1.0).unwrap();
    let mut solver = ContactSolver::new(grid, None, &profile, Adhesion::dugdale(lambda).unwrap(), SolveOptions::default()).unwrap();
    let c = cycle(&mut solver, CycleOptions { amax, steps_per_leg: steps }, &mut |_, _| {}).unwrap();
    let mut compared = 0;
    for leg in [&c.loading, &c.unloading] {
        for r in compare_with_model(params, solver.datum(), leg) {
            assert!(r.model_valid, "lambda {lambda}: smooth states are valid (abar {})", r.abar);
            assert!(r.abar > 0.0);
            assert_eq!(r.contact_intervals, 1);
            assert!((r.load - r.model_load).abs() <= LOAD_TOL, "lambda {lambda}, abar {}: load {} vs model {}", r.abar, r.load, r.model_load);
            assert!(
                (r.approach - r.model_approach).abs() <= APPROACH_TOL,
                "lambda {lambda}, abar {}: approach {} vs model {}",
                r.abar,
                r.approach,
                r.model_approach
            );
            compared += 1;
        }
    }
    assert!(compared >= steps / 2, "lambda {lambda}: only {compared} states in contact");
    // Every state with a Dugdale zone has its ends placed within their cells.
    for s in c.loading.iter().chain(&c.unloading).filter(|s| !s.zone.is_empty()) {
        assert!(s.zone_ends_placed, "lambda {lambda}: zone ends on cell edges at approach {}", s.approach);
    }
    // The cycle ends out of contact and dissipates work (snap-in and pull-off).
    assert_eq!(c.unloading.last().unwrap().contact_intervals(), 0);
    assert!(c.stiff_work > 0.0);
}

#[test]
fn smooth_maugis_lambda_1_matches_the_model_on_both_legs() {
    smooth_cycle_matches_the_model(1.0, 2.5, 20);
}

#[test]
fn smooth_maugis_lambda_10_matches_the_model_on_both_legs() {
    smooth_cycle_matches_the_model(10.0, 2.5, 20);
}

#[test]
fn smooth_maugis_lambda_tenth_matches_the_model_on_both_legs() {
    smooth_cycle_matches_the_model(0.1, 2.5, 20);
}

#[test]
fn energy_derivative_is_the_load() {
    let lambda = 1.0;
    let grid = Grid::new(1024, 4.0).unwrap();
    let profile = Profile::wavy_cylinder(0.0, 1.0).unwrap();
    let mut solver = ContactSolver::new(grid, None, &profile, Adhesion::dugdale(lambda).unwrap(), SolveOptions::default()).unwrap();
    let d = 2.0;
    let h = 1e-3;
    let _ = solver.solve(d - h).unwrap();
    let lo = solver.solve(d - h).unwrap();
    let mid = solver.solve(d).unwrap();
    let hi = solver.solve(d + h).unwrap();
    let slope = (hi.energy() - lo.energy()) / (2.0 * h);
    assert!(mid.abar > 0.5);
    assert!((slope - mid.load).abs() <= 1e-2 * (1.0 + mid.load.abs()), "dPi/dDelta {slope} vs load {}", mid.load);
}
