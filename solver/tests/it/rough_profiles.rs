//! The solver and the model on one profile of many waves, given once (issue 35):
//! the profile goes to `simulate_with` as `SimulationOptions::waves`, which builds the
//! solver's `Profile::RoughCylinder` and compares every state with the model of the
//! same `WavyProfile`.
//!
//! * the Fig. 4c wave plus a second wave of a third of its wavelength and half its
//!   amplitude, at lambda = 1/2, 3 and 6;
//! * a 4-scale Weierstrass profile (gamma = 2, H = 1/2) below the Fig. 4c wave at
//!   lambda = 3.
//!
//! On the default grid (4096 cells), 40 steps per leg:
//! * on every state where the model is valid and the simulation has one contact
//!   interval (`abar > 0.2`), the loads agree to 1 % of the load scale;
//! * wherever the simulation finds more than one contact interval, separated by at
//!   least two cells, the model flags the state invalid. Separations narrower than
//!   two cells are below the grid's resolution: they appear next to the contact
//!   edge, where the traction sits at its limit (lambda = 6, two states before the
//!   unloading jump, holes 0.0008 wide on cells of 0.0034); such states are counted
//!   apart (`unresolved`) and enter neither check.
//!
//! Measured (2026-11-28): two waves at lambda = 1/2 has no valid state with
//! `abar > 0.2` (the model is invalid along the whole path: 63 states with several
//! intervals, every one flagged); lambda = 3 and 6 compare 59 and 79 states (worst
//! 0.0061 and 0.0098);
//! the Weierstrass profile at lambda = 3 likewise has no valid state beyond
//! `abar = 0.2` (101 states with several intervals, every one flagged). This test
//! found the validity check's missed interior traction peaks (the rescan of
//! `ContactSize::validity_at`).

use maugis::contact::profile::WavyProfile;
use maugis_solver::run::{simulate_with, SimulationOptions, SimulationSpec};

/// 1 % of the load scale `(E* dgamma^2 R)^(1/3)`.
const LOAD_TOL: f64 = 0.01;

const FIG4C: (f64, f64) = (std::f64::consts::SQRT_2 / 4.0, 1.125);

struct Outcome {
    worst: f64,
    compared: usize,
    model_valid: usize,
    unresolved: usize,
    multi_interval: usize,
    multi_interval_model_valid: Vec<(f64, usize)>,
}

/// Contact intervals after merging separations narrower than two cells: a gap of less
/// than a cell between two contact pieces is below the grid's resolution (it shows
/// next to the contact edge, where the traction sits at its limit `pbar = 1`: two
/// waves at lambda = 6, abar = 2.2128, a 0.0008-wide hole at x = 2.207 on cells of
/// 0.0034).
fn resolved_intervals(contact: &[(f64, f64)], dx: f64) -> usize {
    let mut n = 0;
    let mut last_right = f64::NEG_INFINITY;
    for &(l, r) in contact {
        if l - last_right >= 2.0 * dx {
            n += 1;
        }
        last_right = r;
    }
    n
}

fn run(lambda: f64, profile: WavyProfile, amax: f64) -> Outcome {
    let first = profile.waves()[0];
    let spec = SimulationSpec { lambda, alpha: first.alpha(), beta: first.beta(), amax, cells: 4096, steps_per_leg: 40 };
    let options = SimulationOptions { waves: Some(profile), ..SimulationOptions::default() };
    let sim = simulate_with(spec, options, &mut |_, _| {}).unwrap();
    let dx = 2.0 * sim.half_width / 4096.0;
    let mut out = Outcome { worst: 0.0, compared: 0, model_valid: 0, unresolved: 0, multi_interval: 0, multi_interval_model_valid: Vec::new() };
    let states = sim.cycle.loading.iter().map(|s| (s, 0)).chain(sim.cycle.unloading.iter().map(|s| (s, 1)));
    for (r, intervals) in states.filter_map(|(s, leg)| sim.model_at(s, leg).map(|r| (r, resolved_intervals(&s.contact, dx)))) {
        out.model_valid += usize::from(r.model_valid);
        if r.contact_intervals > 1 && intervals == 1 {
            // an unresolved separation: neither a clean single-interval state nor a
            // resolved cavity
            out.unresolved += 1;
        } else if intervals > 1 {
            out.multi_interval += 1;
            if r.model_valid {
                out.multi_interval_model_valid.push((r.abar, intervals));
            }
        } else if r.model_valid && r.abar > 0.2 {
            out.worst = out.worst.max((r.load - r.model_load).abs());
            out.compared += 1;
        }
    }
    out
}

fn two_waves() -> WavyProfile {
    WavyProfile::from_pairs(&[FIG4C, (FIG4C.0 / 2.0, FIG4C.1 / 3.0)]).unwrap()
}

/// `min_compared` valid single-interval states and `min_multi` states with several
/// resolved contact intervals, so that each run checks something.
fn check(lambda: f64, profile: WavyProfile, min_compared: usize, min_multi: usize) {
    let o = run(lambda, profile, 2.5);
    eprintln!(
        "lambda {lambda}: {} compared (worst {:.4}), {} model-valid, {} with several intervals, {} unresolved",
        o.compared, o.worst, o.model_valid, o.multi_interval, o.unresolved
    );
    assert!(o.compared >= min_compared, "lambda {lambda}: only {} valid single-interval states", o.compared);
    assert!(o.multi_interval >= min_multi, "lambda {lambda}: only {} states with several contact intervals", o.multi_interval);
    assert!(o.worst <= LOAD_TOL, "lambda {lambda}: largest load error {} on valid stretches", o.worst);
    assert!(
        o.multi_interval_model_valid.is_empty(),
        "lambda {lambda}: {} of {} states with several contact intervals are valid in the model: {:?}",
        o.multi_interval_model_valid.len(),
        o.multi_interval,
        o.multi_interval_model_valid
    );
}

#[test]
fn two_waves_lambda_one_half() {
    check(0.5, two_waves(), 0, 20);
}

#[test]
fn two_waves_lambda_3() {
    check(3.0, two_waves(), 10, 1);
}

#[test]
fn two_waves_lambda_6() {
    check(6.0, two_waves(), 10, 0);
}

#[test]
fn weierstrass_4_scales_lambda_3() {
    let p = WavyProfile::weierstrass(FIG4C.0, FIG4C.1, 4, 2.0, 0.5).unwrap();
    check(3.0, p, 0, 20);
}
