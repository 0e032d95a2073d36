//! Criterion benches of the numerical solver: the time per solve against the
//! grid size (warm-started, as in a continuation), and one short
//! loading-unloading cycle. Smooth Dugdale-Maugis cylinder at lambda = 1 and the
//! Fig. 4c roughness at lambda = 1/4 (cavitating).
//!
//! Measured numbers go to docs/solver.md; the target (2^15 cells,
//! 400 steps, <= 60 s) is recorded there with the state of the solver.

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion};
use maugis::contact::model::Params;
use maugis_solver::contact::{ContactSolver, SolveOptions};
use maugis_solver::grid::Grid;
use maugis_solver::path::{cycle, suggested_half_width, CycleOptions};
use maugis_solver::profile::{Adhesion, Profile};

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
    for cells in [1024usize, 2048, 4096] {
        group.bench_with_input(BenchmarkId::new("smooth_lambda_1", cells), &cells, |b, &cells| {
            let mut s = solver(1.0, 0.0, 1.0, cells, 2.5);
            let mut d = 1.5;
            s.solve(d).expect("first solve");
            // Alternate between two nearby approaches: each solve is warm-started
            // from its neighbour, as in a continuation step.
            b.iter(|| {
                d = if d == 1.5 { 1.52 } else { 1.5 };
                s.solve(d).expect("solve")
            });
        });
    }
    group.finish();
}

fn short_cycle(c: &mut Criterion) {
    let mut group = c.benchmark_group("solver_cycle");
    group.sample_size(10);
    group.bench_function("fig4c_lambda_quarter_2048_cells_2x20_steps", |b| {
        b.iter(|| {
            let mut s = solver(0.25, 2f64.sqrt() / 4.0, 1.125, 2048, 4.2);
            cycle(&mut s, CycleOptions { amax: 4.2, steps_per_leg: 20 }, &mut |_, _| {}).expect("cycle")
        });
    });
    group.finish();
}

criterion_group!(benches, solve_per_grid, short_cycle);
criterion_main!(benches);
