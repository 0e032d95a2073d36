//! Time per value of the f64 `hyp2f1` and `hyp2f1_bounded` by band of `z` over
//! the issue-8 domain (a, b in [-3, 3], c in [0.5, 6], z in [-5, 0.9]; the
//! LCG of `benches/special.rs`), to see where the time goes, and over all the
//! points in the drawn order (as a vectorised call sees them). Best of 5 passes
//! over 20000 points (`MAUGIS_REGIONS_REPS` sets the passes). Run: `cargo run --release --example hyp2f1_regions`.

use maugis::special::hyp2f1;
use std::hint::black_box;
use std::time::Instant;

/// Best times (seconds) of `reps` passes of `hyp2f1` and `hyp2f1_bounded`
/// over `pts` (the second infinite when `value_only`).
fn best_of(pts: &[[f64; 4]], reps: usize, value_only: bool) -> [f64; 2] {
    let mut best = [f64::INFINITY; 2];
    for _ in 0..reps {
        let t = Instant::now();
        let s: f64 = pts.iter().map(|p| hyp2f1::hyp2f1(p[0], p[1], p[2], black_box(p[3])).unwrap_or(0.0)).sum();
        black_box(s);
        best[0] = best[0].min(t.elapsed().as_secs_f64());
        if value_only {
            continue;
        }
        let t = Instant::now();
        let s: f64 = pts.iter().map(|p| hyp2f1::hyp2f1_bounded(p[0], p[1], p[2], black_box(p[3])).map_or(0.0, |b| b.err)).sum();
        black_box(s);
        best[1] = best[1].min(t.elapsed().as_secs_f64());
    }
    best
}

fn main() {
    let mut state: u64 = 0x2f1_5c1;
    let mut uniform = |lo: f64, hi: f64| {
        state = state.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
        lo + (hi - lo) * ((state >> 11) as f64 / (1u64 << 53) as f64)
    };
    let pts: Vec<[f64; 4]> =
        (0..20000).map(|_| [uniform(-3.0, 3.0), uniform(-3.0, 3.0), uniform(0.5, 6.0), uniform(-5.0, 0.9)]).collect();
    // passes per band (best of); MAUGIS_REGIONS_REPS=1 for an instruction count under valgrind
    let reps: usize = std::env::var("MAUGIS_REGIONS_REPS").ok().and_then(|v| v.parse().ok()).unwrap_or(5);
    // MAUGIS_REGIONS_VALUE_ONLY=1 skips hyp2f1_bounded (for profiling the value path)
    let value_only = std::env::var("MAUGIS_REGIONS_VALUE_ONLY").is_ok_and(|v| v == "1");
    let bands = [(-5.0, -4.0), (-4.0, -3.0), (-3.0, -2.0), (-2.0, -1.0), (-1.0, -0.5), (-0.5, 0.0), (0.0, 0.5), (0.5, 0.75), (0.75, 0.9)];
    println!("| z band | points | hyp2f1 us | hyp2f1_bounded us |");
    println!("|---|---|---|---|");
    let mut total = [0.0f64; 2];
    for (lo, hi) in bands {
        let sel: Vec<[f64; 4]> = pts.iter().copied().filter(|p| p[3] >= lo && p[3] < hi).collect();
        let best = best_of(&sel, reps, value_only);
        total[0] += best[0];
        total[1] += best[1];
        let n = sel.len() as f64;
        println!("| [{lo}, {hi}) | {} | {:.3} | {:.3} |", sel.len(), best[0] / n * 1e6, best[1] / n * 1e6);
    }
    let n = pts.len() as f64;
    println!("| all (sum of the bands) | {} | {:.3} | {:.3} |", pts.len(), total[0] / n * 1e6, total[1] / n * 1e6);
    // all points in the drawn order (z bands mixed, as a vectorised call sees them)
    let best = best_of(&pts, reps, value_only);
    println!("| all, drawn order | {} | {:.3} | {:.3} |", pts.len(), best[0] / n * 1e6, best[1] / n * 1e6);
}
