//! Times `bessel_j_mp` over the issue-13 grid and prints bits and time per call.
//!
//! `cargo run --release --example bessel_grid [prec ...]` (default 53 128 512).
//! Each point is called until 20 ms have passed (at least once); the figure is
//! the mean time per call within one process.

use std::time::Instant;

use maugis::special::bessel_j::{bessel_j_mp, choose_algorithm};
use rug::Float;

const ORDERS: [i64; 7] = [0, 1, 7, 60, 500, 2000, 10000];
const ARGS: [f64; 9] = [0.001, 1.5, 30.25, 150.5, 999.5, 5000.25, 20000.5, 99999.5, 1000000.5];
const EXTRA: [(i64, f64); 5] = [(500, 30000.0), (-1200, 50000.25), (0, 2.5), (5, 30.25), (40, 150.5)];

fn main() {
    let precs: Vec<u32> = std::env::args().skip(1).filter_map(|a| a.parse().ok()).collect();
    let precs = if precs.is_empty() { vec![53, 128, 512] } else { precs };
    println!("prec,n,x,algorithm,bits,us_per_call");
    for &prec in &precs {
        let points = ORDERS.iter().flat_map(|&n| ARGS.iter().map(move |&x| (n, x))).chain(EXTRA);
        for (n, x) in points {
            let xf = Float::with_val(53, x);
            let alg = choose_algorithm(n.unsigned_abs(), x, prec + 32);
            let t0 = Instant::now();
            let mut calls = 0u32;
            let mut res = bessel_j_mp(n, &xf, prec);
            calls += 1;
            while t0.elapsed().as_secs_f64() < 0.02 {
                res = bessel_j_mp(n, &xf, prec);
                calls += 1;
            }
            let us = t0.elapsed().as_secs_f64() * 1e6 / calls as f64;
            match res {
                Ok(b) => println!("{prec},{n},{x},{alg:?},{:.1},{us:.1}", b.rel_accuracy_bits().min(99999.0)),
                Err(e) => println!("{prec},{n},{x},{alg:?},error: {e},{us:.1}"),
            }
        }
    }
}
