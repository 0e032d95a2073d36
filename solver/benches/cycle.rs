//! Criterion benches of the numerical solver.
//!
//! * `solver_warm_solve`: the time of one warm-started solve against the grid
//!   (smooth Dugdale-Maugis cylinder, lambda = 1, alternating between two
//!   neighbouring approaches as in a continuation step).
//! * `solver_cycle_2p15`: the target, one loading-unloading cycle on
//!   2^15 cells with 400 approach steps (200 per leg). Each iteration is the
//!   next solve along the cycle (the approach schedule of the same cycle on a
//!   coarse grid), so criterion's time per iteration is the time per solve
//!   along the path; the cycle time is that times the number of states
//!   (printed). Two cases: the smooth cylinder at lambda = 1 (amax 2.5) and the
//!   Fig. 4c roughness at lambda = 1/4 (amax 4.2, cavitating).
//!
//! With `MAUGIS_SOLVER_FULL_CYCLE=1` the bench also runs each full 2^15-cell
//! cycle once through `path::cycle` and prints its wall time, the time per
//! solve, the CG iterations and the FFT products.
//!
//! Measured numbers go to docs/solver.md (with the load average: the machine
//! is shared).

use std::time::{Duration, Instant};

use criterion::{BenchmarkId, Criterion};
use maugis::contact::model::Params;
use maugis_solver::contact::{ContactSolver, SolveOptions};
use maugis_solver::grid::Grid;
use maugis_solver::path::{cycle, suggested_half_width, CycleOptions};
use maugis_solver::profile::{Adhesion, Profile};

/// (name, lambda, alpha, beta, amax) of the benched cases.
const CASES: [(&str, f64, f64, f64, f64); 2] = [
    ("smooth_lambda_1", 1.0, 0.0, 1.0, 2.5),
    ("fig4c_lambda_quarter", 0.25, std::f64::consts::SQRT_2 / 4.0, 1.125, 4.2),
];
/// The target: 2^15 cells, 400 steps (200 per leg).
const TARGET_CELLS: usize = 1 << 15;
const TARGET_STEPS_PER_LEG: usize = 200;

fn solver(lambda: f64, alpha: f64, beta: f64, cells: usize, amax: f64) -> ContactSolver {
    let params = Params::new(lambda, alpha, beta).expect("valid bench parameters");
    let grid = Grid::new(cells, suggested_half_width(params, amax).expect("half width")).expect("grid");
    let profile = Profile::wavy_cylinder(alpha, beta).expect("profile");
    ContactSolver::new(grid, None, &profile, Adhesion::dugdale(lambda).expect("adhesion"), SolveOptions::default())
        .expect("solver")
}

fn solve_per_grid(c: &mut Criterion) {
    let mut group = c.benchmark_group("solver_warm_solve");
    group.sample_size(10);
    for cells in [4096usize, 32768] {
        group.bench_with_input(BenchmarkId::new("smooth_lambda_1", cells), &cells, |b, &cells| {
            let mut s = solver(1.0, 0.0, 1.0, cells, 2.5);
            let mut d = 1.5;
            s.solve(d).expect("first solve");
            b.iter(|| {
                d = if d == 1.5 { 1.52 } else { 1.5 };
                s.solve(d).expect("solve")
            });
        });
    }
    group.finish();
}

/// The approaches of the target cycle, from the same cycle on a coarse grid.
fn schedule(lambda: f64, alpha: f64, beta: f64, amax: f64) -> Vec<f64> {
    let mut coarse = solver(lambda, alpha, beta, 2048, amax);
    let c = cycle(&mut coarse, CycleOptions { amax, steps_per_leg: TARGET_STEPS_PER_LEG }, &mut |_, _| {})
        .expect("coarse cycle");
    c.loading.iter().chain(&c.unloading).map(|s| s.approach).collect()
}

fn cycle_2p15(c: &mut Criterion) {
    let mut group = c.benchmark_group("solver_cycle_2p15");
    group.sample_size(10).warm_up_time(Duration::from_secs(1));
    for (name, lambda, alpha, beta, amax) in CASES {
        let approaches = schedule(lambda, alpha, beta, amax);
        let mut s = solver(lambda, alpha, beta, TARGET_CELLS, amax);
        let mut next = 0;
        let (mut solves, mut spent) = (0usize, Duration::ZERO);
        group.bench_function(BenchmarkId::new("per_solve", name), |b| {
            b.iter_custom(|iters| {
                let t = Instant::now();
                for _ in 0..iters {
                    if next == approaches.len() {
                        next = 0;
                        s.reset();
                    }
                    s.solve(approaches[next]).expect("solve along the cycle");
                    next += 1;
                }
                let e = t.elapsed();
                solves += iters as usize;
                spent += e;
                e
            });
        });
        let per = spent.as_secs_f64() / solves.max(1) as f64;
        println!(
            "solver_cycle_2p15/{name}: {} states per cycle x {:.1} ms per solve = {:.1} s per cycle (load average {})",
            approaches.len(),
            1e3 * per,
            per * approaches.len() as f64,
            load_average()
        );
    }
    group.finish();
}

fn full_cycles() {
    for (name, lambda, alpha, beta, amax) in CASES {
        let mut s = solver(lambda, alpha, beta, TARGET_CELLS, amax);
        let t = Instant::now();
        let c = cycle(&mut s, CycleOptions { amax, steps_per_leg: TARGET_STEPS_PER_LEG }, &mut |_, _| {})
            .expect("cycle");
        let secs = t.elapsed().as_secs_f64();
        let states: Vec<_> = c.loading.iter().chain(&c.unloading).collect();
        let cg: usize = states.iter().map(|s| s.cg_iterations).sum();
        let products: usize = states.iter().map(|s| s.products).sum();
        println!(
            "full cycle {name}, 2^15 cells, {} states: {secs:.1} s wall, {:.1} ms per solve, {:.0} CG steps and {:.0} FFT products per solve (load average {})",
            states.len(),
            1e3 * secs / states.len() as f64,
            cg as f64 / states.len() as f64,
            products as f64 / states.len() as f64,
            load_average()
        );
    }
}

fn load_average() -> String {
    std::fs::read_to_string("/proc/loadavg").map(|s| s.split_whitespace().take(3).collect::<Vec<_>>().join(" ")).unwrap_or_default()
}

fn main() {
    let mut c = Criterion::default().configure_from_args();
    solve_per_grid(&mut c);
    cycle_2p15(&mut c);
    if std::env::var_os("MAUGIS_SOLVER_FULL_CYCLE").is_some() {
        full_cycles();
    }
    c.final_summary();
}
