//! Smooth Dugdale-Maugis cylinder (alpha = 0) against the semi-analytical model
//! of the `maugis` crate (Johnson and Greenwood 2008) at the same contact
//! half-width, on loading and unloading; and the energy identity
//! `dPi/dDelta = Lbar` of the discrete solution.

use maugis::contact::model::Params;
use maugis_solver::contact::{ContactSolver, SolveOptions};
use maugis_solver::grid::Grid;
use maugis_solver::path::{compare_with_model, cycle, suggested_half_width, CycleOptions};
use maugis_solver::profile::{Adhesion, Profile};

/// 1 % of the load scale: the normalised load unit `(E* dgamma^2 R)^(1/3)`.
const LOAD_TOL: f64 = 0.01;

#[test]
fn smooth_maugis_lambda_1_matches_the_model_on_both_legs() {
    let lambda = 1.0;
    let amax = 2.5;
    let params = Params::new(lambda, 0.0, 1.0).unwrap();
    let grid = Grid::new(4096, suggested_half_width(params, amax).unwrap()).unwrap();
    let profile = Profile::wavy_cylinder(0.0, 1.0).unwrap();
    let mut solver = ContactSolver::new(grid, None, &profile, Adhesion::dugdale(lambda).unwrap(), SolveOptions::default()).unwrap();
    let c = cycle(&mut solver, CycleOptions { amax, steps_per_leg: 10 }, &mut |_, _| {}).unwrap();
    let mut compared = 0;
    for leg in [&c.loading, &c.unloading] {
        for r in compare_with_model(params, leg) {
            assert!(r.model_valid, "smooth lambda = 1 states are valid (abar {})", r.abar);
            assert_eq!(r.contact_intervals, 1);
            assert!((r.load - r.model_load).abs() <= LOAD_TOL, "abar {}: {} vs model {}", r.abar, r.load, r.model_load);
            compared += 1;
        }
    }
    assert!(compared >= 10, "only {compared} states in contact");
    // The cycle ends out of contact and dissipates work (snap-in and pull-off).
    assert_eq!(c.unloading.last().unwrap().contact_intervals(), 0);
    assert!(c.dissipated > 0.0);
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
