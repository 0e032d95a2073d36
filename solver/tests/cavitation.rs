//! Fig. 4c roughness (alpha = 2 sqrt(2)/8, beta = 9/8) at lambda = 1/4: the
//! simulated contact cavitates (more than one contact interval) where the
//! semi-analytical model flags its states invalid, and agrees with the model
//! where the model is valid.

use maugis::contact::model::Params;
use maugis_solver::contact::{ContactSolver, SolveOptions};
use maugis_solver::grid::Grid;
use maugis_solver::path::{compare_with_model, cycle, suggested_half_width, CycleOptions};
use maugis_solver::profile::{Adhesion, Profile};

#[test]
fn lambda_quarter_cavitates_where_the_model_is_invalid() {
    let (lambda, alpha, beta, amax) = (0.25, std::f64::consts::SQRT_2 / 4.0, 1.125, 4.2);
    let params = Params::new(lambda, alpha, beta).unwrap();
    let grid = Grid::new(2048, suggested_half_width(params, amax).unwrap()).unwrap();
    let profile = Profile::wavy_cylinder(alpha, beta).unwrap();
    let mut solver = ContactSolver::new(grid, None, &profile, Adhesion::dugdale(lambda).unwrap(), SolveOptions::default()).unwrap();
    let c = cycle(&mut solver, CycleOptions { amax, steps_per_leg: 40 }, &mut |_, _| {}).unwrap();
    let cmp = compare_with_model(params, &c.loading);
    let cavitated_in = |lo: f64, hi: f64| cmp.iter().any(|r| r.contact_intervals > 1 && (lo..hi).contains(&r.abar));
    assert!(cavitated_in(2.1, 2.5), "no cavitation near abar = 2.2");
    assert!(cavitated_in(3.2, 3.5), "no cavitation near abar = 3.3");
    for r in &cmp {
        if r.contact_intervals > 1 {
            assert!(!r.model_valid, "cavitated at abar {} where the model is valid", r.abar);
        } else if r.model_valid && r.abar > 0.2 {
            assert!((r.load - r.model_load).abs() <= 0.015, "abar {}: {} vs {}", r.abar, r.load, r.model_load);
        }
    }
    // Somewhere after a jump the true load differs from the invalid model load by > 0.1.
    assert!(cmp.iter().any(|r| r.contact_intervals > 1 && (r.load - r.model_load).abs() > 0.1));
}
