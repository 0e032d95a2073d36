//! Times `hyp1f2_mp` on the points of `reference/bench_arb_hyp1f2.py` and prints
//! bits and time per call (CSV on stdout).
//!
//! `cargo run --release --example hyp1f2_grid [prec ...]` (default 64 128 512).
//! Each point is called until 20 ms have passed (at least once); the figure is
//! the mean time per call within one process.

use maugis::special::exact;
use maugis::special::hyp1f2::hyp1f2_mp;

#[path = "../benches/common/per_call.rs"]
mod per_call;

/// `(a, b1, b2, z)`: the model family `1F2(1/2; k+1, k+3/2; -s)` (Eq. 12) at
/// `abar = 1, 3, 6` (`s = (pi abar/beta)^2` ~ 7.8, 70, 281), issue 8's point
/// `(1/2; 1, 3/2; -300)`, stronger cancellation and two generic points.
pub const POINTS: [(f64, f64, f64, f64); 14] = [
    (0.5, 1.0, 1.5, -300.0),
    (0.5, 1.5, 2.0, -300.0),
    (0.5, 1.0, 1.5, -7.796),
    (0.5, 1.0, 1.5, -70.17),
    (0.5, 1.0, 1.5, -280.7),
    (0.5, 11.0, 11.5, -280.7),
    (0.5, 101.0, 101.5, -280.7),
    (0.5, 1001.0, 1001.5, -280.7),
    (0.5, 1.0, 1.5, -3000.0),
    (0.5, 1.0, 1.5, -10000.0),
    (0.5, 1.0, 1.5, -1.5),
    (1.25, 2.5, 3.75, 40.0),
    (-2.5, 0.75, 3.25, -60.5),
    (0.5, 1.0, 1.0, -289.0),
];

fn main() {
    let precs: Vec<u32> = std::env::args().skip(1).filter_map(|a| a.parse().ok()).collect();
    let precs = if precs.is_empty() { vec![64, 128, 512] } else { precs };
    println!("prec,a,b1,b2,z,bits,us_per_call");
    for &prec in &precs {
        for &(a, b1, b2, z) in &POINTS {
            let (ae, b1e, b2e, ze) = (exact(a), exact(b1), exact(b2), exact(z));
            let (res, us) = per_call::per_call(|| hyp1f2_mp(&ae, &b1e, &b2e, &ze, prec));
            match res {
                Ok(b) => println!("{prec},{a},{b1},{b2},{z},{:.1},{us:.2}", b.rel_accuracy_bits().min(99999.0)),
                Err(e) => println!("{prec},{a},{b1},{b2},{z},error: {e},{us:.2}"),
            }
        }
    }
}
