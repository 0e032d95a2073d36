//! f64 J_n over issue 8's domain (n <= 60, x <= 150, uniform, fixed seed):
//! time per value of `bessel_j` and `bessel_j_bounded`, the share that fell
//! back to MP, and the worst relative error against the certified value.
//! `cargo run --release --example bessel_f64 [points]`

use std::time::Instant;

use maugis::special::bessel_j::{bessel_j, bessel_j_bounded, bessel_j_fallbacks, bessel_j_mp};
use rug::Float;

fn main() {
    let count: usize = std::env::args().nth(1).and_then(|a| a.parse().ok()).unwrap_or(20000);
    // xorshift, fixed seed
    let mut state = 0x9E37_79B9_7F4A_7C15u64;
    let mut next = || {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        (state >> 11) as f64 / (1u64 << 53) as f64
    };
    let pts: Vec<(i64, f64)> = (0..count).map(|_| ((next() * 61.0) as i64, next() * 150.0)).collect();
    for (name, limit) in [("n<=60, x<=150", 150.0), ("n<=60, x<=30", 30.0)] {
        let sel: Vec<(i64, f64)> = pts.iter().map(|&(n, x)| (n, x * limit / 150.0)).collect();
        let f0 = bessel_j_fallbacks();
        let t0 = Instant::now();
        let mut acc = 0.0;
        for &(n, x) in &sel {
            acc += bessel_j(n, x).unwrap();
        }
        let plain_us = t0.elapsed().as_secs_f64() * 1e6 / sel.len() as f64;
        let f1 = bessel_j_fallbacks();
        let t0 = Instant::now();
        for &(n, x) in &sel {
            acc += bessel_j_bounded(n, x).unwrap().err;
        }
        let bounded_us = t0.elapsed().as_secs_f64() * 1e6 / sel.len() as f64;
        let f2 = bessel_j_fallbacks();
        let mut worst = 0.0f64;
        for &(n, x) in sel.iter().take(2000) {
            let v = bessel_j(n, x).unwrap();
            let e = bessel_j_mp(n, &Float::with_val(53, x), 128).unwrap().to_f64();
            if e != 0.0 {
                worst = worst.max(((v - e) / e).abs());
            }
        }
        println!(
            "{name}: bessel_j {plain_us:.2} us/value ({} of {} fell back), bessel_j_bounded {bounded_us:.2} us/value ({} fell back), worst rel err {worst:.2e} (first 2000 points) [{acc:.1}]",
            f1 - f0,
            sel.len(),
            f2 - f1
        );
    }
}
