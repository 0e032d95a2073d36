//! Profiles that do not touch: a solve out of the adhesion range returns an
//! empty state (no contact, no Dugdale zone, zero load), and a cycle whose
//! approach range cannot reach `amax` returns a typed error instead of a
//! number (docs/solver.md, "Profiles that do not touch").

use maugis_solver::contact::{ContactSolver, SolveOptions};
use maugis_solver::error::SolverError;
use maugis_solver::grid::Grid;
use maugis_solver::path::{cycle, CycleOptions};
use maugis_solver::profile::{Adhesion, Profile};

fn solver(profile: &Profile, cells: usize, half_width: f64, lambda: f64) -> ContactSolver {
    let grid = Grid::new(cells, half_width).unwrap();
    ContactSolver::new(grid, None, profile, Adhesion::dugdale(lambda).unwrap(), SolveOptions::default()).unwrap()
}

#[test]
fn out_of_range_state_is_empty() {
    let lambda = 1.0;
    let delta_c = 1.0 / lambda;
    let mut s = solver(&Profile::wavy_cylinder(0.0, 1.0).unwrap(), 512, 4.0, lambda);
    let hmin = s.profile().iter().copied().fold(f64::INFINITY, f64::min);
    // The lowest point stays 1.5 delta_c (and then 0.01 delta_c) beyond the range.
    for gap in [1.5 * delta_c, 1.01 * delta_c] {
        let st = s.solve(hmin - gap).unwrap();
        assert!(st.contact.is_empty() && st.zone.is_empty(), "gap {gap}: {:?} {:?}", st.contact, st.zone);
        assert_eq!((st.abar, st.load, st.contact_intervals(), st.zone_cells), (0.0, 0.0, 0, 0));
        assert!(s.traction().iter().all(|&p| p == 0.0));
        assert!(s.gap().iter().all(|&g| g >= delta_c));
    }
    // Just inside the range the zone appears (and the load is tensile).
    let st = s.solve(hmin - 0.9 * delta_c).unwrap();
    assert!(!st.zone.is_empty() && st.load < 0.0);
}

#[test]
fn sampled_profile_far_out_of_reach_is_a_typed_error() {
    // A profile 400 times steeper than the cylinder: the approach range sized
    // for the cylinder never brings the contact out to amax.
    let grid = Grid::new(512, 4.0).unwrap();
    let h: Vec<f64> = (0..grid.cells()).map(|i| 200.0 * grid.x(i) * grid.x(i)).collect();
    let mut s = solver(&Profile::Sampled(h), 512, 4.0, 1.0);
    let e = cycle(&mut s, CycleOptions { amax: 2.0, steps_per_leg: 4 }, &mut |_, _| {}).unwrap_err();
    match &e {
        SolverError::AmaxNotReached { reached, amax, steps } => assert!(*reached < 2.0 && *amax == 2.0 && *steps > 4, "{e}"),
        other => panic!("expected AmaxNotReached, got {other:?}"),
    }
    assert!(e.to_string().contains("short of amax"), "{e}");
    // A sampled profile of the wrong length or with a NaN is refused up front.
    let bad = Profile::Sampled(vec![0.0; 100]);
    assert!(matches!(ContactSolver::new(grid, None, &bad, Adhesion::dugdale(1.0).unwrap(), SolveOptions::default()), Err(SolverError::LengthMismatch { found: 100, expected: 512, .. })));
    let mut nan = vec![0.0; 512];
    nan[7] = f64::NAN;
    assert!(matches!(ContactSolver::new(grid, None, &Profile::Sampled(nan), Adhesion::dugdale(1.0).unwrap(), SolveOptions::default()), Err(SolverError::NonFinite { .. })));
}
