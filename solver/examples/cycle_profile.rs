//! Profiling driver: one loading-unloading cycle, with the time per solve and
//! the CG iterations and Dugdale-zone updates per state.
//!
//! `cargo run --release -p maugis-solver --example cycle_profile -- LAMBDA ALPHA BETA CELLS STEPS AMAX`

use std::time::Instant;

use maugis::contact::model::Params;
use maugis_solver::contact::{ContactSolver, SolveOptions};
use maugis_solver::grid::Grid;
use maugis_solver::path::{compare_with_model, cycle, suggested_half_width, CycleOptions};
use maugis_solver::profile::{Adhesion, Profile};

fn main() {
    let a: Vec<f64> = std::env::args().skip(1).map(|s| s.parse().expect("numbers")).collect();
    let (lambda, alpha, beta, cells, steps, amax) = (a[0], a[1], a[2], a[3] as usize, a[4] as usize, a[5]);
    let params = Params::new(lambda, alpha, beta).unwrap();
    let grid = Grid::new(cells, suggested_half_width(params, amax).unwrap()).unwrap();
    let profile = Profile::wavy_cylinder(alpha, beta).unwrap();
    let mut s = ContactSolver::new(grid, None, &profile, Adhesion::dugdale(lambda).unwrap(), SolveOptions::default()).unwrap();
    let t = Instant::now();
    let c = cycle(&mut s, CycleOptions { amax, steps_per_leg: steps }, &mut |_, _| {}).unwrap();
    let secs = t.elapsed().as_secs_f64();
    let all: Vec<_> = c.loading.iter().chain(&c.unloading).collect();
    let cg: usize = all.iter().map(|s| s.cg_iterations).sum();
    let zu: usize = all.iter().map(|s| s.zone_updates).sum();
    let maxcg = all.iter().map(|s| s.cg_iterations).max().unwrap();
    let maxzu = all.iter().map(|s| s.zone_updates).max().unwrap();
    let prods: usize = all.iter().map(|s| s.products).sum();
    println!(
        "cells {cells} dx {:.3e} states {} time {secs:.2} s ({:.1} ms/solve) cg {cg} ({:.0}/solve, max {maxcg}) zone updates {zu} (max {maxzu}) products {prods} ({:.0}/solve)",
        grid.dx(),
        all.len(),
        1e3 * secs / all.len() as f64,
        cg as f64 / all.len() as f64,
        prods as f64 / all.len() as f64
    );
    let mut worst: f64 = 0.0;
    for leg in [&c.loading, &c.unloading] {
        for r in compare_with_model(params, s.datum(), leg) {
            if r.model_valid && r.contact_intervals == 1 && r.abar > 0.2 {
                worst = worst.max((r.load - r.model_load).abs());
            }
        }
    }
    println!("max |L - L_model| on valid single-interval states: {worst:.4e}; stiff-cycle work {:.5}", c.stiff_work);
    let datum = s.datum();
    if std::env::var("VERBOSE").is_ok() {
        for s in &all {
            let m = compare_with_model(params, datum, std::slice::from_ref(*s)).first().map(|r| (r.model_load, r.model_valid));
            println!("{:.5} {:.5} {:.5} {} {} {} {} {:?}", s.approach, s.abar, s.load, s.contact_intervals(), s.zone_cells, s.cg_iterations, s.zone_updates, m);
        }
    }
}
