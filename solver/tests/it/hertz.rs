//! Hertz line contact without adhesion against the exact solution: the load
//! `Lbar = pi a^2/4` and the approach `Delta = (a^2/2) (ln(2 L_d/a) + 1/2)`
//! relative to the datum `L_d` (Johnson 1985, sec. 5.6, with the datum of
//! `maugis_solver::elastic`: `Delta = u(0) = -(2/pi) int p ln(|s|/L_d) ds`).
//! This validates the elasticity operator and the datum of the approach.

use maugis_solver::contact::{ContactSolver, SolveOptions};
use maugis_solver::grid::Grid;
use maugis_solver::profile::{Adhesion, Profile};

/// Exact Hertz approach at half-width `a` for datum `datum`.
fn hertz_approach(a: f64, datum: f64) -> f64 {
    0.5 * a * a * ((2.0 * datum / a).ln() + 0.5)
}

/// Inverse of [`hertz_approach`] by bisection (it increases with `a` for `a < 2 L_d`).
fn hertz_half_width(delta: f64, datum: f64) -> f64 {
    let (mut lo, mut hi) = (0.0, datum);
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if hertz_approach(mid, datum) < delta {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    0.5 * (lo + hi)
}

#[test]
fn hertz_load_and_half_width_match_the_exact_solution() {
    let grid = Grid::new(4096, 4.0).unwrap();
    let profile = Profile::wavy_cylinder(0.0, 1.0).unwrap();
    let mut solver = ContactSolver::new(grid, None, &profile, Adhesion::NONE, SolveOptions::default()).unwrap();
    let datum = solver.datum();
    let dx = grid.dx();
    for a in [0.5, 1.0, 2.0, 3.0] {
        let delta = hertz_approach(a, datum);
        let s = solver.solve(delta).unwrap();
        let a_exact = hertz_half_width(delta, datum);
        assert!((a_exact - a).abs() < 1e-12);
        let l_exact = std::f64::consts::PI * a * a / 4.0;
        assert_eq!(s.contact_intervals(), 1, "a = {a}");
        assert!((s.abar - a).abs() <= dx, "a = {a}: abar {} (dx {dx})", s.abar);
        // Discretisation error of the load: O(dx/a) relative.
        assert!((s.load - l_exact).abs() <= 2.0 * dx / a * l_exact, "a = {a}: load {} vs {l_exact}", s.load);
        assert!(s.residual <= 1e-9);
    }
}

#[test]
fn hertz_load_error_falls_with_the_grid() {
    let profile = Profile::wavy_cylinder(0.0, 1.0).unwrap();
    let a = 1.3;
    let mut errors = Vec::new();
    let mut iterations = Vec::new();
    for cells in [512, 2048, 8192] {
        let grid = Grid::new(cells, 4.0).unwrap();
        let mut solver = ContactSolver::new(grid, Some(8.0), &profile, Adhesion::NONE, SolveOptions::default()).unwrap();
        let s = solver.solve(hertz_approach(a, 8.0)).unwrap();
        errors.push((s.load - std::f64::consts::PI * a * a / 4.0).abs());
        iterations.push(s.cg_iterations);
    }
    assert!(errors[1] < 0.5 * errors[0] && errors[2] < 0.5 * errors[1], "{errors:?}");
    // The FFT preconditioner keeps the cold-start CG count nearly independent
    // of the grid (unpreconditioned it grows like sqrt(n)).
    assert!(iterations[2] <= 2 * iterations[0] + 10, "CG iterations {iterations:?}");
}

#[test]
fn no_contact_before_the_profile_touches() {
    let grid = Grid::new(256, 4.0).unwrap();
    let profile = Profile::wavy_cylinder(0.0, 1.0).unwrap();
    let mut solver = ContactSolver::new(grid, None, &profile, Adhesion::NONE, SolveOptions::default()).unwrap();
    let s = solver.solve(-0.1).unwrap();
    assert_eq!(s.contact_intervals(), 0);
    assert_eq!(s.load, 0.0);
}
