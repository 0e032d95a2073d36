//! Mesh-convergence study of the numerical solver against the semi-analytical
//! model (docs/solver.md, "Mesh convergence").
//!
//! For each case and grid it runs one displacement-controlled cycle (100 steps
//! per leg) and reports, over the states where the model is valid and the
//! simulation has one contact interval (abar > 0.2):
//!
//! * `load_err`: max |Lbar - Lbar_model| at the simulated abar;
//! * `approach_err`: max |Delta - Delta_model| on the model's datum
//!   (`path::approach_on_model_datum`);
//! * the fewest cohesive cells in the right Dugdale zone;
//! * `unplaced_states`: states with a Dugdale zone whose ends could not be
//!   placed within their cells (`State::zone_ends_placed`);
//!
//! and, for the cavitating case (lambda = 1/4), `cavitated_diff`: the largest
//! load difference to the finest grid over the loading states (same approach)
//! where both grids report more than one contact interval.
//!
//! Writes `OUT/solver_mesh_convergence.csv` and `.svg` (log-log
//! load error against cells). `OUT` is the first argument (default `.`); a
//! second argument caps the grid (default 32768).
//!
//! `cargo run --release -p maugis-solver --example mesh_convergence -- docs`

use std::fmt::Write as _;
use std::time::Instant;

use maugis::contact::model::Params;
use maugis_solver::contact::{ContactSolver, SolveOptions, State};
use maugis_solver::grid::Grid;
use maugis_solver::path::{compare_with_model, cycle, suggested_half_width, CycleOptions};
use maugis_solver::profile::{Adhesion, Profile};

struct Case {
    name: &'static str,
    lambda: f64,
    alpha: f64,
    beta: f64,
    amax: f64,
    max_cells: usize,
}

const STEPS_PER_LEG: usize = 100;

fn run(case: &Case, cells: usize) -> (Vec<State>, Vec<State>, f64, f64, f64, usize, usize) {
    let params = Params::new(case.lambda, case.alpha, case.beta).expect("parameters");
    let grid = Grid::new(cells, suggested_half_width(params, case.amax).expect("half width")).expect("grid");
    let profile = Profile::wavy_cylinder(case.alpha, case.beta).expect("profile");
    let adhesion = Adhesion::dugdale(case.lambda).expect("lambda");
    let mut s = ContactSolver::new(grid, None, &profile, adhesion, SolveOptions::default()).expect("solver");
    let t = Instant::now();
    let c = cycle(&mut s, CycleOptions { amax: case.amax, steps_per_leg: STEPS_PER_LEG }, &mut |_, _| {}).expect("cycle");
    let secs = t.elapsed().as_secs_f64();
    let (mut load_err, mut approach_err, mut min_zone): (f64, f64, usize) = (0.0, 0.0, usize::MAX);
    let unplaced = c.loading.iter().chain(&c.unloading).filter(|st| !st.zone.is_empty() && !st.zone_ends_placed).count();
    for leg in [&c.loading, &c.unloading] {
        let cmp = compare_with_model(params, s.datum(), leg);
        for (r, st) in cmp.iter().zip(leg.iter().filter(|st| st.abar > 0.0)) {
            if r.model_valid && r.contact_intervals == 1 && r.abar > 0.2 {
                load_err = load_err.max((r.load - r.model_load).abs());
                approach_err = approach_err.max((r.approach - r.model_approach).abs());
                min_zone = min_zone.min(st.zone_cells);
            }
        }
    }
    (c.loading, c.unloading, secs, load_err, approach_err, min_zone, unplaced)
}

fn main() {
    let mut args = std::env::args().skip(1);
    let out = std::path::PathBuf::from(args.next().unwrap_or_else(|| ".".into()));
    let cap: usize = args.next().map(|s| s.parse().expect("cells")).unwrap_or(1 << 15);
    let fig4c = (std::f64::consts::SQRT_2 / 4.0, 1.125);
    let cases = [
        Case { name: "smooth lambda=0.1", lambda: 0.1, alpha: 0.0, beta: 1.0, amax: 2.5, max_cells: 1 << 15 },
        Case { name: "smooth lambda=1", lambda: 1.0, alpha: 0.0, beta: 1.0, amax: 2.5, max_cells: 1 << 15 },
        Case { name: "smooth lambda=10", lambda: 10.0, alpha: 0.0, beta: 1.0, amax: 2.5, max_cells: 1 << 15 },
        Case { name: "Fig. 4c lambda=6", lambda: 6.0, alpha: fig4c.0, beta: fig4c.1, amax: 2.5, max_cells: 1 << 15 },
        Case { name: "Fig. 4c lambda=1/4", lambda: 0.25, alpha: fig4c.0, beta: fig4c.1, amax: 4.2, max_cells: 1 << 15 },
    ];
    let mut csv = String::from("case,cells,dx,seconds,load_err,approach_err,min_zone_cells,cavitated_diff,unplaced_states\n");
    let mut series: Vec<(&str, Vec<(usize, f64)>)> = Vec::new();
    for case in &cases {
        let grids: Vec<usize> = (10..=15).map(|k| 1usize << k).filter(|&n| n <= case.max_cells.min(cap)).collect();
        let mut rows = Vec::new();
        for &n in &grids {
            let r = run(case, n);
            eprintln!("{} cells {n}: {:.1} s, load err {:.2e}, approach err {:.2e}, min zone cells {}, unplaced {}", case.name, r.2, r.3, r.4, r.5, r.6);
            rows.push((n, r));
        }
        let finest = &rows.last().expect("one grid").1 .0;
        let mut points = Vec::new();
        for (n, (loading, _, secs, load_err, approach_err, min_zone, unplaced)) in &rows {
            let cav = loading
                .iter()
                .zip(finest)
                .filter(|(a, b)| a.contact_intervals() > 1 && b.contact_intervals() > 1)
                .map(|(a, b)| (a.load - b.load).abs())
                .fold(f64::NAN, f64::max);
            let dx = 2.0 * suggested_half_width(Params::new(case.lambda, case.alpha, case.beta).unwrap(), case.amax).unwrap() / *n as f64;
            let _ = writeln!(csv, "{},{n},{dx:.4e},{secs:.2},{load_err:.4e},{approach_err:.4e},{min_zone},{cav:.4e},{unplaced}", case.name);
            points.push((*n, *load_err));
        }
        series.push((case.name, points));
    }
    std::fs::write(out.join("solver_mesh_convergence.csv"), &csv).expect("write csv");
    std::fs::write(out.join("solver_mesh_convergence.svg"), svg(&series)).expect("write svg");
    print!("{csv}");
}

/// A log-log plot of the load error against cells, one polyline per case.
fn svg(series: &[(&str, Vec<(usize, f64)>)]) -> String {
    let (w, h, left, right, top, bottom) = (720.0, 460.0, 70.0, 190.0, 20.0, 50.0);
    let (x0, x1) = (10.0f64, 15.0f64); // log2 cells
    let (y0, y1) = (-5.0f64, 0.0f64); // log10 error
    let px = |n: usize| left + ((n as f64).log2() - x0) / (x1 - x0) * (w - left - right);
    let py = |e: f64| top + (y1 - e.max(1e-5).log10()) / (y1 - y0) * (h - top - bottom);
    let colours = ["#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e"];
    let mut s = format!(
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{w}\" height=\"{h}\" font-family=\"sans-serif\" font-size=\"12\">\n\
         <rect width=\"{w}\" height=\"{h}\" fill=\"white\"/>\n"
    );
    for k in 10..=15 {
        let x = px(1 << k);
        let _ = writeln!(s, "<line x1=\"{x}\" y1=\"{top}\" x2=\"{x}\" y2=\"{}\" stroke=\"#ddd\"/><text x=\"{x}\" y=\"{}\" text-anchor=\"middle\">2^{k}</text>", h - bottom, h - bottom + 16.0);
    }
    for e in -5..=0 {
        let y = py(10f64.powi(e));
        let _ = writeln!(s, "<line x1=\"{left}\" y1=\"{y}\" x2=\"{}\" y2=\"{y}\" stroke=\"#ddd\"/><text x=\"{}\" y=\"{}\" text-anchor=\"end\">1e{e}</text>", w - right, left - 6.0, y + 4.0);
    }
    let y1pc = py(0.01);
    let _ = writeln!(s, "<line x1=\"{left}\" y1=\"{y1pc}\" x2=\"{}\" y2=\"{y1pc}\" stroke=\"#888\" stroke-dasharray=\"6 4\"/><text x=\"{}\" y=\"{}\" fill=\"#555\">1 % of the load scale</text>", w - right, left + 6.0, y1pc - 5.0);
    let _ = writeln!(s, "<text x=\"{}\" y=\"{}\" text-anchor=\"middle\">cells (uniform grid)</text>", left + 0.5 * (w - left - right), h - 12.0);
    let _ = writeln!(s, "<text transform=\"translate(18 {}) rotate(-90)\" text-anchor=\"middle\">max |L - L_model| on valid states</text>", top + 0.5 * (h - top - bottom));
    for (i, (name, pts)) in series.iter().enumerate() {
        let c = colours[i % colours.len()];
        let pts: Vec<&(usize, f64)> = pts.iter().filter(|(_, e)| *e > 0.0).collect();
        let poly: Vec<String> = pts.iter().map(|&&(n, e)| format!("{:.1},{:.1}", px(n), py(e))).collect();
        let _ = writeln!(s, "<polyline points=\"{}\" fill=\"none\" stroke=\"{c}\" stroke-width=\"2\"/>", poly.join(" "));
        for &&(n, e) in &pts {
            let _ = writeln!(s, "<circle cx=\"{:.1}\" cy=\"{:.1}\" r=\"3.5\" fill=\"{c}\"/>", px(n), py(e));
        }
        let ly = top + 10.0 + 20.0 * i as f64;
        let _ = writeln!(s, "<line x1=\"{}\" y1=\"{ly}\" x2=\"{}\" y2=\"{ly}\" stroke=\"{c}\" stroke-width=\"2\"/><text x=\"{}\" y=\"{}\">{name}</text>", w - right + 10.0, w - right + 30.0, w - right + 36.0, ly + 4.0);
    }
    s.push_str("</svg>\n");
    s
}
