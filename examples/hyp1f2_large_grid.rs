//! Times `hyp1f2_mp` on the issue-23 large-parameter grid
//! (`benches/common/hyp1f2_large_grid.rs`) and prints, per point, the certified
//! bits, the CPU time per call (thread CPU time, `benches/common/per_call.rs`) and the ball (CSV on stdout; the midpoint with
//! `prec/3 + 30` significant digits, the reader adds that rounding to the radius), for
//! `reference/bench_arb_hyp1f2_grid.py`.
//!
//! `cargo run --release --example hyp1f2_large_grid [prec ...]` (default 128).

use maugis::special::exact;
use maugis::special::hyp1f2::hyp1f2_mp;

#[path = "../benches/common/per_call.rs"]
mod per_call;

#[path = "../benches/common/hyp1f2_large_grid.rs"]
mod grid;

fn main() {
    let precs: Vec<u32> = std::env::args().skip(1).filter_map(|a| a.parse().ok()).collect();
    let precs = if precs.is_empty() { vec![128] } else { precs };
    println!("prec,a,b1,b2,z,bits,us_per_call,mid,rad");
    for &prec in &precs {
        for (a, b1, b2, z) in grid::all_points() {
            let (ae, b1e, b2e, ze) = (exact(a), exact(b1), exact(b2), exact(z));
            let (res, us) = per_call::per_call_cpu(|| hyp1f2_mp(&ae, &b1e, &b2e, &ze, prec));
            match res {
                Ok(b) => println!(
                    "{prec},{a},{b1},{b2},{z},{:.1},{us:.2},{},{}",
                    b.rel_accuracy_bits().min(99999.0),
                    b.mid().to_string_radix(10, Some(b.mid().prec() as usize / 3 + 30)),
                    b.rad().to_string_radix(10, Some(6))
                ),
                Err(e) => println!("{prec},{a},{b1},{b2},{z},error: {e},{us:.2},,"),
            }
        }
    }
}
