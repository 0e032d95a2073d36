//! Time per value of the f64 `meijer_g_k_bounded(k, y)` on a grid over `k <= 1000`,
//! `y in (0, 1]` (issue 23, item 4: at most 1 us everywhere), with the MP fallbacks
//! marked. Each cell is the wall time of the fastest of 40 batches of 40 calls (the
//! machine is shared: batches of 10-300 us are shorter than a scheduler slice, so the
//! fastest is the one least disturbed by other load); a `*` marks a cell that fell back
//! to MP. Prints a markdown table, a summary line, and the mean over the 64 points
//! of the criterion group `meijer_g_k_f64_domain` (same points, same measure); then, per `k`
//! in `2..=24, 30, 100, 300, 519, 1000`, the worst of ten points next to the zero of
//! `G(k, .)` (the two f64 `y` around it, offsets `1e-12` to `1e-2`) and the time of the
//! first call at that `k` (which builds the Taylor route's table, `meijer_g/zero_taylor.rs`).
//!
//! `cargo run --release --example meijer_g_grid --features maugis/gmp-no-check`
//! (`MEIJER_G_POINT=k,y MEIJER_G_CALLS=n` times one point only, for callgrind)

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

/// The f64 `y` below the zero of `G(k, .)` (`k >= 2`) whose f64 neighbour above is past it
/// (bisection on the sign of the certified 64-bit MP value in `[0.5, 0.85]`).
fn next_to_zero(k: u32) -> f64 {
    let positive = |y: f64| meijer_g::meijer_g_k_mp(k, &maugis::special::exact(y), 64).unwrap().mid().is_sign_positive();
    let (mut lo, mut hi) = (0.5f64, 0.85f64);
    loop {
        let mid = 0.5 * (lo + hi);
        if mid <= lo || mid >= hi {
            return lo;
        }
        if positive(mid) {
            lo = mid;
        } else {
            hi = mid;
        }
    }
}

fn main() {
    // `MEIJER_G_POINT=k,y MEIJER_G_CALLS=n`: only n calls at one point after a warm-up call
    // (for callgrind: the difference of two counts over the difference of n is one call)
    if let Ok(point) = std::env::var("MEIJER_G_POINT") {
        let (k, y) = point.split_once(',').expect("MEIJER_G_POINT=k,y");
        let (k, y): (u32, f64) = (k.parse().expect("k"), y.parse().expect("y"));
        let calls: usize = std::env::var("MEIJER_G_CALLS").ok().and_then(|c| c.parse().ok()).unwrap_or(1);
        meijer_g::meijer_g_k_bounded(k, y).unwrap();
        let s: f64 = (0..calls).map(|_| meijer_g::meijer_g_k_bounded(k, black_box(y)).unwrap().value).sum();
        println!("{s:e}");
        return;
    }
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
    // next to the zero of G(k, .) (issue 23, item 4): the two f64 y around it and offsets
    // 1e-12 to 1e-2 either side, per k; the first call at each k (outside the timing) builds
    // the Taylor route's table for that k, its time is reported apart
    println!("\n| k | y next to the zero | worst us (10 points) | at offset | MP fallbacks | first call us |\n|---:|---:|---:|---:|---:|---:|");
    let zero_ks: Vec<u32> = (2..25).chain([30, 100, 300, 519, 1000]).collect();
    let (mut z_worst, mut z_worst_at, mut z_fallbacks, mut z_over, mut z_first) = (0.0f64, (0, 0.0), 0u64, 0u32, 0.0f64);
    for &k in &zero_ks {
        let y0 = next_to_zero(k);
        let t = Instant::now();
        meijer_g::meijer_g_k_bounded(k, black_box(y0)).unwrap();
        let first = t.elapsed().as_secs_f64() * 1e6;
        z_first = z_first.max(first);
        let (mut worst, mut at, mut fbs) = (0.0f64, 0.0, 0u64);
        for d in [0.0, f64::NAN, -1e-12, 1e-12, -1e-6, 1e-6, -1e-3, 1e-3, -1e-2, 1e-2] {
            let y = if d.is_nan() { y0.next_up() } else { y0 + d };
            let before = maugis::special::fallback_counts().meijer_g_k;
            let best = per_call(40, || meijer_g::meijer_g_k_bounded(k, black_box(y)).unwrap().value);
            fbs += (maugis::special::fallback_counts().meijer_g_k > before) as u64;
            z_over += (best > 1.0) as u32;
            if best > worst {
                worst = best;
                at = y - y0;
            }
        }
        if worst > z_worst {
            z_worst = worst;
            z_worst_at = (k, y0 + at);
        }
        z_fallbacks += fbs;
        println!("| {k} | {y0} | {worst:.3} | {at:.0e} | {fbs} | {first:.0} |");
    }
    println!(
        "next to the zeros: {} points, worst {z_worst:.3} us at k = {}, y = {}; {z_over} above 1 us; {z_fallbacks} with an MP fallback; first call at a k at most {z_first:.0} us",
        10 * zero_ks.len(),
        z_worst_at.0,
        z_worst_at.1
    );
    let load = std::fs::read_to_string("/proc/loadavg").unwrap_or_default();
    println!(
        "{} cells: worst {worst:.2} us at k = {}, y = {}; {over} cells above 1 us; {fallbacks} cells with an MP fallback; load average {}",
        ks.len() * ys.len(),
        worst_at.0,
        worst_at.1,
        load.split_whitespace().take(3).collect::<Vec<_>>().join(" ")
    );
}
