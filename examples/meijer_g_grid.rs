//! Time per value of the f64 `meijer_g_k_bounded(k, y)` on a grid over `k <= 1000`,
//! `y in (0, 1]` (issue 23, item 4: at most 1 us everywhere), with the MP fallbacks
//! marked. Each cell is the wall time of the fastest of 40 batches of 40 calls (the
//! machine is shared: batches of 10-300 us are shorter than a scheduler slice, so the
//! fastest is the one least disturbed by other load); a `*` marks a cell that fell back
//! to MP. Prints a markdown table, a summary line, and the mean over the 64 points
//! of the criterion group `meijer_g_k_f64_domain` (same points, same measure).
//!
//! `cargo run --release --example meijer_g_grid`

use maugis::special::meijer_g;

#[path = "../benches/common/meijer_domain.rs"]
mod meijer_domain;
use std::hint::black_box;
use std::time::Instant;

/// Wall time per call of `f` in us, fastest of 40 batches of `calls`.
fn per_call(calls: usize, mut f: impl FnMut() -> f64) -> f64 {
    let mut best = f64::INFINITY;
    for _ in 0..40 {
        let t = Instant::now();
        let mut s = 0.0;
        for _ in 0..calls {
            s += f();
        }
        black_box(s);
        best = best.min(t.elapsed().as_secs_f64() * 1e6 / calls as f64);
    }
    best
}

fn main() {
    let ks = [0u32, 1, 2, 3, 5, 10, 30, 100, 300, 1000];
    let ys = [1e-10, 0.1, 0.5, 0.7, 0.8, 0.85, 0.9, 0.93, 0.95, 0.96, 0.97, 0.9705, 0.98, 0.99, 0.999, 1.0 - 1e-6, 1.0 - 1e-12, 1.0];
    meijer_g::meijer_g_k_bounded(0, 0.5).unwrap(); // the constants table, built once
    let mut header = String::from("| k \\ y |");
    let mut rule = String::from("|---:|");
    for y in ys {
        header.push_str(&format!(" {} |", if y < 1.0 - 1e-4 { format!("{y}") } else { format!("1-{:.0e}", 1.0 - y) }));
        rule.push_str("---:|");
    }
    println!("{}\n{}", header.replace("1-0e0", "1"), rule);
    let (mut worst, mut worst_at, mut fallbacks, mut over) = (0.0f64, (0, 0.0), 0u64, 0);
    for &k in &ks {
        let mut row = format!("| {k} |");
        for &y in &ys {
            let before = maugis::special::fallback_counts().meijer_g_k;
            let best = per_call(40, || meijer_g::meijer_g_k_bounded(k, black_box(y)).unwrap().value);
            let fb = maugis::special::fallback_counts().meijer_g_k - before;
            fallbacks += (fb > 0) as u64;
            over += (best > 1.0) as u32;
            if best > worst {
                worst = best;
                worst_at = (k, y);
            }
            row.push_str(&format!(" {best:.2}{} |", if fb > 0 { "*" } else { "" }));
        }
        println!("{row}");
    }
    // the 64 points of benches/special.rs, bench_meijer_domain
    let pts = meijer_domain::meijer_domain_points();
    let before = maugis::special::fallback_counts().meijer_g_k;
    let domain = per_call(2, || pts.iter().map(|&(k, y)| meijer_g::meijer_g_k_bounded(k, black_box(y)).unwrap().value).sum::<f64>()) / 64.0;
    println!("\nthe 64 domain points of meijer_g_k_f64_domain: {domain:.3} us per value, {} MP fallbacks", maugis::special::fallback_counts().meijer_g_k - before);
    let load = std::fs::read_to_string("/proc/loadavg").unwrap_or_default();
    println!(
        "{} cells: worst {worst:.2} us at k = {}, y = {}; {over} cells above 1 us; {fallbacks} cells with an MP fallback; load average {}",
        ks.len() * ys.len(),
        worst_at.0,
        worst_at.1,
        load.split_whitespace().take(3).collect::<Vec<_>>().join(" ")
    );
}
