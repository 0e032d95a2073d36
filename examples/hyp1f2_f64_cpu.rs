//! Thread CPU time per value of `hyp1f2_bounded(1/2; k+1, k+3/2; -s^2)` over
//! issue 23's table: `k` in {0, 1, 2, 5, 10, 50, 200, 1000}, 64 values of `s` in
//! `(0, 35]` per `k` (the same points as the criterion group `hyp1f2_f64_per_k`),
//! with the MP fallbacks counted. CPU time (`maugis::budget::thread_cpu_seconds`)
//! rather than wall time, since the machine is shared.
//!
//! `cargo run --release --example hyp1f2_f64_cpu`

use maugis::budget::thread_cpu_seconds;
use maugis::special::hyp1f2::hyp1f2_bounded;

fn main() {
    let ss: Vec<f64> = (1..=64).map(|i| 35.0 * ((i as f64 * 0.618_033_988_749_895).fract()).max(1.0 / 64.0)).collect();
    let reps = 2000;
    let mut total = 0.0;
    let before = maugis::special::fallback_counts().hyp1f2;
    println!("k,us_per_value_cpu,worst_rel_bound");
    for k in [0.0f64, 1.0, 2.0, 5.0, 10.0, 50.0, 200.0, 1000.0] {
        let mut worst = 0.0f64;
        for &s in &ss {
            let b = hyp1f2_bounded(0.5, k + 1.0, k + 1.5, -s * s).unwrap();
            worst = worst.max(b.err / b.value.abs());
        }
        let t0 = thread_cpu_seconds() * 1e9;
        let mut acc = 0.0;
        for _ in 0..reps {
            for &s in &ss {
                acc += hyp1f2_bounded(0.5, k + 1.0, k + 1.5, std::hint::black_box(-s * s)).unwrap().value;
            }
        }
        let us = ((thread_cpu_seconds() * 1e9) - t0) / (reps * ss.len()) as f64 * 1e-3;
        total += us;
        println!("{k},{us:.3},{worst:.2e}{}", if acc.is_nan() { " nan" } else { "" });
    }
    println!("mean over k: {:.3} us per value; MP fallbacks: {}", total / 8.0, maugis::special::fallback_counts().hyp1f2 - before);
}
