//! Grid convergence of the solver map's W (issue 24, item 2): W, W_d, the loops
//! and the cavitated fraction of representative points of the
//! `maugis sweep --solver` map (beta = 9/8, amax = 6) on a ladder of
//! resolutions, each against the finest run of its point.
//!
//! `cargo run --release -p maugis-solver --example map_convergence -- OUT.csv [CELLS,..] [STEPS,..]`
//!
//! Defaults: cells 2048,4096,8192 and steps per leg 200,400,800. Prints a row
//! per run and writes the CSV (`docs/solver-map-convergence.csv`).

use std::time::Instant;

use maugis_solver::map::{measure_cycle, Resolution, ResolutionRule};

/// `(lambda, alpha)`: smooth, cavitating, dissipative and borderline points of the map.
const POINTS: [(f64, f64); 9] = [
    (0.1, 0.5),
    (0.3, 0.3),
    (1.0, 0.0),
    (1.0, 0.25),
    (1.0, 0.5),
    (3.0, 0.353_553_390_593_273_7),
    (10.0, 0.0),
    (10.0, 0.1),
    (10.0, 0.5),
];

fn list(arg: Option<String>, default: &[usize]) -> Vec<usize> {
    arg.map_or_else(|| default.to_vec(), |s| s.split(',').map(|t| t.trim().parse().expect("a comma-separated list of whole numbers")).collect())
}

fn main() {
    let mut args = std::env::args().skip(1);
    let out = args.next().expect("usage: map_convergence OUT.csv [CELLS,..] [STEPS,..]");
    let cells = list(args.next(), &[2048, 4096, 8192]);
    let steps = list(args.next(), &[200, 400, 800]);
    let (beta, amax) = (1.125, 6.0);
    let mut csv = String::from("lambda,alpha,cells,steps_per_leg,auto,seconds,w,w_d,loops,cavitated_fraction,w_ref,w_d_ref,w_error,w_d_error\n");
    for (lambda, alpha) in POINTS {
        let auto = ResolutionRule::Auto.at(lambda);
        let mut rows = Vec::new();
        for &c in &cells {
            for &s in &steps {
                let r = Resolution { cells: c, steps_per_leg: s };
                let t = Instant::now();
                let m = measure_cycle(lambda, alpha, beta, amax, r);
                rows.push((r, t.elapsed().as_secs_f64(), m));
            }
        }
        // the finest run is the reference
        let reference = rows.last().and_then(|r| r.2.as_ref().ok()).copied();
        for (r, secs, m) in rows {
            match (m, reference) {
                (Ok(m), Some(f)) => {
                    let line = format!(
                        "{lambda},{alpha},{},{},{},{secs:.2},{},{},{},{},{},{},{},{}",
                        r.cells,
                        r.steps_per_leg,
                        r == auto,
                        m.w,
                        m.w_d,
                        m.loops,
                        m.cavitated_fraction,
                        f.w,
                        f.w_d,
                        m.w - f.w,
                        m.w_d - f.w_d
                    );
                    println!("{line}");
                    csv.push_str(&line);
                    csv.push('\n');
                }
                (m, _) => println!("{lambda},{alpha},{},{}: {:?} (reference {:?})", r.cells, r.steps_per_leg, m.err(), reference.is_some()),
            }
        }
    }
    std::fs::write(&out, csv).expect("write the CSV");
}
