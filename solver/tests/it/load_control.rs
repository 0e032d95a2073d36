//! Load control read off a displacement-controlled cycle
//! (`path::load_controlled`): smooth Dugdale-Maugis cylinder at lambda = 1.
//! Along the load-controlled path the load is monotone, the loading path snaps
//! into contact at zero load, and the pull-off load agrees with the most
//! tensile load of the semi-analytical curve.

use maugis::contact::curve::state as model_state;
use maugis::contact::model::Params;
use maugis_solver::contact::{ContactSolver, SolveOptions};
use maugis_solver::grid::Grid;
use maugis_solver::path::{cycle, load_controlled, suggested_half_width, CycleOptions, LoadDirection};
use maugis_solver::profile::{Adhesion, Profile};

#[test]
fn smooth_lambda_1_load_control_snaps_in_at_zero_load_and_pulls_off_at_the_model_minimum() {
    let (lambda, amax) = (1.0, 2.0);
    let params = Params::new(lambda, 0.0, 1.0).unwrap();
    let grid = Grid::new(4096, suggested_half_width(params, amax).unwrap()).unwrap();
    let profile = Profile::wavy_cylinder(0.0, 1.0).unwrap();
    let mut solver = ContactSolver::new(grid, None, &profile, Adhesion::dugdale(lambda).unwrap(), SolveOptions::default()).unwrap();
    let c = cycle(&mut solver, CycleOptions { amax, steps_per_leg: 60 }, &mut |_, _| {}).unwrap();

    let up = load_controlled(&c.loading, LoadDirection::Increasing);
    let loads: Vec<f64> = up.states.iter().map(|&i| c.loading[i].load).collect();
    assert!(loads.windows(2).all(|w| w[1] > w[0]), "loading under load control is not monotone: {loads:?}");
    assert!(up.pull_off.is_none());
    // Snap-in: the displacement path goes tensile on contact; under load control
    // the first contact state on the path carries a non-negative load.
    let first_contact = up.states.iter().map(|&i| &c.loading[i]).find(|s| s.contact_intervals() > 0).unwrap();
    assert!(first_contact.load >= 0.0);
    assert!(c.loading.iter().any(|s| s.contact_intervals() > 0 && s.load < 0.0), "no tensile contact state on the stiff path");
    assert!(!up.jumps.is_empty(), "no snap-in jump");

    let mut leg = vec![c.loading.last().unwrap().clone()];
    leg.extend(c.unloading.iter().cloned());
    let down = load_controlled(&leg, LoadDirection::Decreasing);
    let loads: Vec<f64> = down.states.iter().map(|&i| leg[i].load).collect();
    assert!(loads.windows(2).all(|w| w[1] < w[0]), "unloading under load control is not monotone");
    let (at, pull_off) = down.pull_off.expect("pull-off");
    assert_eq!(*down.states.last().unwrap(), at);
    // The model's most tensile load over abar in (0, amax].
    let model_min = (1..=400)
        .filter_map(|k| model_state(params, amax * k as f64 / 400.0).ok())
        .map(|m| m.load)
        .fold(f64::INFINITY, f64::min);
    eprintln!("pull-off {pull_off} (model {model_min}), load-control jumps on loading {:?}", up.jumps);
    assert!((pull_off - model_min).abs() <= 0.02, "pull-off {pull_off} vs model {model_min}");
}

