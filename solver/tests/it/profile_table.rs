//! A profile table (`x,h` rows, `maugis_solver::profile_file`) sampled from
//! the built-in Fig. 4c profile reproduces the built-in run (issue 24, item
//! 5): every state's load within 1e-3 of the load scale (the load unit
//! `(E* dgamma^2 R)^(1/3)`), at lambda = 1/4 (cavitating) and 6, on the same
//! grid. The rows are 0.01 apart over `[-X - 0.5, X + 0.5]`; the cubic
//! interpolant is then within about 1e-6 of the profile (third order,
//! `profile_file` unit test).

use maugis_solver::profile_file::ProfileTable;
use maugis_solver::run::{simulate, simulate_with, SimulationOptions, SimulationSpec};
use maugis_solver::SolverError;

const ALPHA: f64 = std::f64::consts::SQRT_2 / 4.0;
const BETA: f64 = 1.125;

fn fig4c(x: f64) -> f64 {
    0.5 * x * x + ALPHA * (1.0 - (2.0 * std::f64::consts::PI * x / BETA).cos())
}

fn table_text(half_width: f64, dx: f64) -> String {
    let n = ((2.0 * half_width + 1.0) / dx).ceil() as usize;
    let mut text = String::from("x,h\n");
    for k in 0..=n {
        let x = -half_width - 0.5 + k as f64 * dx;
        text.push_str(&format!("{x},{}\n", fig4c(x)));
    }
    text
}

fn worst_load_difference(lambda: f64) -> (f64, usize) {
    let spec = SimulationSpec { lambda, alpha: ALPHA, beta: BETA, amax: 4.0, cells: 4096, steps_per_leg: 40 };
    let built_in = simulate(spec, &mut |_, _| {}).unwrap();
    let table = ProfileTable::parse(&table_text(built_in.half_width, 0.01)).unwrap();
    let options = SimulationOptions { profile: Some(table), ..SimulationOptions::default() };
    let from_table = simulate_with(spec, options, &mut |_, _| {}).unwrap();
    assert_eq!(from_table.half_width, built_in.half_width);
    let (a, b) = (built_in.report().states, from_table.report().states);
    assert_eq!(a.len(), b.len(), "lambda {lambda}: the runs visit different numbers of states");
    let worst = a.iter().zip(&b).map(|(p, q)| (p.load - q.load).abs()).fold(0.0, f64::max);
    (worst, a.len())
}

#[test]
fn a_table_of_the_fig4c_profile_reproduces_the_built_in_loads() {
    for lambda in [0.25, 6.0] {
        let (worst, states) = worst_load_difference(lambda);
        eprintln!("lambda {lambda}: {states} states, largest load difference {worst:e}");
        assert!(worst <= 1e-3, "lambda {lambda}: {worst}");
    }
}

#[test]
fn a_table_that_does_not_cover_the_domain_is_refused() {
    let spec = SimulationSpec { lambda: 1.0, alpha: ALPHA, beta: BETA, amax: 2.0, cells: 512, steps_per_leg: 10 };
    let table = ProfileTable::parse(&table_text(1.0, 0.05)).unwrap();
    let options = SimulationOptions { profile: Some(table), ..SimulationOptions::default() };
    match simulate_with(spec, options, &mut |_, _| {}) {
        Err(SolverError::ProfileCoverage { first, last, half_width }) => {
            assert!(first > -half_width && last < half_width, "{first} {last} {half_width}")
        }
        other => panic!("{:?}", other.map(|s| s.half_width)),
    }
}
