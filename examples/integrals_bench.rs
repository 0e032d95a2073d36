//! The maugis side of the speed comparison against C Arb (issue 22, item 7), run by
//! `reference/bench_integrals.sh` next to `reference/arb_integrals.c`: the same
//! analytic integrals at 64 and 333 bits, one warm-up call (Gauss-Legendre nodes
//! cached), then calls repeated until 0.2 s have passed. Prints one tab-separated line
//! per (integral, prec): id, prec, mean ms per call, evaluations of one call, calls,
//! goal met, and the real part.
//!
//! `cargo run --release --example integrals_bench [id]`; with `MAUGIS_BENCH_CALLS=n`,
//! exactly `n` timed calls (for instruction counts under callgrind, which a loaded
//! machine does not disturb).

use std::time::Instant;

use maugis::ball::Ball;
use maugis::quad::certified::{integrate, HoloBall, Integral, Options};

type F = fn(&HoloBall) -> HoloBall;

/// (id, integrand, a, b); the ids match reference/arb_integrals.c.
pub const INTEGRALS: [(&str, F, i64, i64); 6] = [
    ("atanderiv", |x| (x.sqr() + x.int(1)).recip(), 0, 1),
    ("rump", |x| (x.exp() + x).sin(), 0, 8),
    ("exp", |x| x.exp(), 0, 1),
    ("sqrt", |x| x.sqrt(), 1, 4),
    ("xJ0", |x| x * x.besselj(0), 0, 1),
    ("sin100", |x| x.sin(), 0, 100),
];

fn once(f: F, a: i64, b: i64, prec: u32) -> Integral {
    integrate(f, &Ball::from_i64(a, prec), &Ball::from_i64(b, prec), prec, &Options::new()).expect("integrate")
}

fn main() {
    let only: Option<String> = std::env::args().nth(1);
    // A fixed number of calls instead of 0.2 s (for instruction counts under callgrind).
    let fixed_calls: Option<u64> = std::env::var("MAUGIS_BENCH_CALLS").ok().and_then(|v| v.parse().ok());
    let precs: Vec<u32> = match std::env::var("MAUGIS_BENCH_PREC").ok().and_then(|v| v.parse().ok()) {
        Some(p) => vec![p],
        None => vec![64, 333],
    };
    for prec in precs {
        for (id, f, a, b) in INTEGRALS {
            if only.as_deref().is_some_and(|o| o != id) {
                continue;
            }
            let warm = once(f, a, b, prec);
            let t0 = Instant::now();
            let mut calls = 0u64;
            let mut last;
            loop {
                last = once(f, a, b, prec);
                calls += 1;
                if fixed_calls.map_or(t0.elapsed().as_secs_f64() >= 0.2, |n| calls >= n) {
                    break;
                }
            }
            let ms = t0.elapsed().as_secs_f64() * 1e3 / calls as f64;
            println!("{id}\t{prec}\t{ms:.6}\t{}\t{calls}\t{}\t{:?}", warm.evaluations, last.goal_met, last.real());
        }
    }
}
