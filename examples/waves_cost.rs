//! The cost of a 600-state load-area curve of a profile of many waves against the sum
//! of its waves' one-wave curves (issue 35's target: at most 1.3 times), in thread CPU
//! time (CLOCK_THREAD_CPUTIME_ID: less sensitive to other processes than wall time,
//! on this shared 2-core machine), one thread, the median of `REPS` runs.
//!
//!     cargo run --release --example waves_cost [REPS]
//!
//! The criterion group `waves` of `benches/solver.rs` times the same curves in wall time.

use maugis::budget::thread_cpu_seconds;
use maugis::contact::curve::{load_area_curve, CurveOptions};
use maugis::contact::model::Params;
use maugis::contact::profile::WavyProfile;

/// Median thread CPU time of one 600-state curve, computed on this thread.
fn median_curve_seconds(p: Params, reps: usize) -> f64 {
    let pool = rayon::ThreadPoolBuilder::new().num_threads(1).build().expect("a one-thread pool");
    let mut t: Vec<f64> = (0..reps)
        .map(|_| {
            pool.install(|| {
                let t0 = thread_cpu_seconds();
                let c = load_area_curve(p, CurveOptions::default()).expect("curve");
                assert_eq!(c.points.len(), 600);
                thread_cpu_seconds() - t0
            })
        })
        .collect();
    t.sort_by(f64::total_cmp);
    t[reps / 2]
}

fn main() {
    let reps: usize = std::env::args().nth(1).and_then(|s| s.parse().ok()).unwrap_or(5);
    let (alpha, beta, lambda) = (2f64.sqrt() / 4.0, 1.125, 3.0);
    let profiles = [
        ("Fig. 4c wave + (alpha/2, beta/3)", WavyProfile::from_pairs(&[(alpha, beta), (alpha / 2.0, beta / 3.0)]).unwrap()),
        ("Weierstrass, 4 scales, gamma 2, H 1/2", WavyProfile::weierstrass(alpha, beta, 4, 2.0, 0.5).unwrap()),
    ];
    println!("| profile (lambda = 3, 600 states, 1 thread) | N-wave curve (s) | one-wave curves (s) | sum (s) | ratio |");
    println!("|---|---|---|---|---|");
    for (name, profile) in profiles {
        let all = median_curve_seconds(Params::with_profile(lambda, profile).unwrap(), reps);
        let singles: Vec<f64> =
            profile.waves().iter().map(|w| median_curve_seconds(Params::new(lambda, w.alpha(), w.beta()).unwrap(), reps)).collect();
        let sum: f64 = singles.iter().sum();
        let list: Vec<String> = singles.iter().map(|s| format!("{s:.3}")).collect();
        println!("| {name} | {all:.3} | {} | {sum:.3} | {:.2} |", list.join(" + "), all / sum);
    }
}
