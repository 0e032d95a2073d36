//! f64 J_n over issue 8's domain (n <= 60, x <= 150, uniform, integer n, fixed
//! seed): time per value of `bessel_j` and `bessel_j_bounded` (wall clock and
//! this thread's CPU time, `maugis::budget::thread_cpu_seconds`), per
//! native method, the share that fell back to MP, and the worst relative
//! error against the certified 128-bit value on every point.
//! `cargo run --release --example bessel_f64 [points]`
//!
//! The points are those of `reference/bench_scipy.py --bessel` (same generator,
//! same seed), so the two outputs compare side by side.

use maugis::budget::thread_cpu_seconds;
use std::time::Instant;

use maugis::special::bessel_j::{bessel_j, bessel_j_bounded, bessel_j_mp, choose_native, NativeMethod};
use rug::Float;

/// The points of `bessel_points` in reference/bench_scipy.py: a 64-bit LCG,
/// `n = floor(61 u)`, `x = 150 u'`.
fn points(count: usize) -> Vec<(i64, f64)> {
    let mut state: u64 = 0xB355E1;
    let mut uniform = || {
        state = state.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
        (state >> 11) as f64 / (1u64 << 53) as f64
    };
    (0..count)
        .map(|_| {
            let n = ((uniform() * 61.0) as i64).min(60);
            (n, uniform() * 150.0)
        })
        .collect()
}

/// Best of `reps` runs: (wall us, cpu us) per value.
fn time_per_value<F: FnMut() -> f64>(count: usize, reps: usize, mut f: F) -> (f64, f64, f64) {
    let (mut wall, mut cpu, mut acc) = (f64::INFINITY, f64::INFINITY, 0.0);
    for _ in 0..reps {
        let (t0, c0) = (Instant::now(), thread_cpu_seconds());
        acc += f();
        wall = wall.min(t0.elapsed().as_secs_f64());
        cpu = cpu.min(thread_cpu_seconds() - c0);
    }
    (wall * 1e6 / count as f64, cpu * 1e6 / count as f64, acc)
}

fn main() {
    let count: usize = std::env::args().nth(1).and_then(|a| a.parse().ok()).unwrap_or(100_000);
    let pts = points(count);
    let method = |&(n, x): &(i64, f64)| choose_native(n.unsigned_abs(), x.abs());
    println!("{count} points, n <= 60, x <= 150 (uniform); best of 5, per value: wall / CPU");
    let f0 = maugis::special::fallback_counts().bessel_j;
    let (w, c, acc) = time_per_value(count, 5, || pts.iter().map(|&(n, x)| bessel_j(n, x).unwrap()).sum());
    let f1 = maugis::special::fallback_counts().bessel_j;
    println!("bessel_j          {w:7.3} us / {c:7.3} us   MP fallbacks {:.4}% [{acc:.3}]", (f1 - f0) as f64 / 5.0 / count as f64 * 100.0);
    let (w, c, acc) = time_per_value(count, 5, || pts.iter().map(|&(n, x)| bessel_j_bounded(n, x).unwrap().err).sum());
    let f2 = maugis::special::fallback_counts().bessel_j;
    println!("bessel_j_bounded  {w:7.3} us / {c:7.3} us   MP fallbacks {:.4}% [{acc:.3e}]", (f2 - f1) as f64 / 5.0 / count as f64 * 100.0);
    for m in [NativeMethod::Recurrence, NativeMethod::Series, NativeMethod::Mp] {
        let sel: Vec<(i64, f64)> = pts.iter().copied().filter(|p| method(p) == m).collect();
        if sel.is_empty() {
            continue;
        }
        let (w, c, _) = time_per_value(sel.len(), 5, || sel.iter().map(|&(n, x)| bessel_j(n, x).unwrap()).sum());
        println!("  {m:?}: {:.1}% of the points, bessel_j {w:.3} us / {c:.3} us", sel.len() as f64 / count as f64 * 100.0);
    }
    // Accuracy on every point: plain value and bound against the certified value.
    let (mut worst_rel, mut worst_rel_bounded, mut worst_bound, mut misses) = (0.0f64, 0.0f64, 0.0f64, 0usize);
    for &(n, x) in &pts {
        let exact = bessel_j_mp(n, &Float::with_val(53, x), 128).unwrap();
        let e = exact.to_f64();
        let v = bessel_j(n, x).unwrap();
        let b = bessel_j_bounded(n, x).unwrap();
        if e != 0.0 {
            worst_rel = worst_rel.max(((v - e) / e).abs());
            worst_rel_bounded = worst_rel_bounded.max(((b.value - e) / e).abs());
            worst_bound = worst_bound.max(b.err / e.abs());
        }
        let diff = Float::with_val(200, exact.mid() - b.value).abs();
        if diff > Float::with_val(200, b.err) - exact.rad() {
            misses += 1;
        }
    }
    println!(
        "worst relative error: bessel_j {worst_rel:.2e}, bessel_j_bounded {worst_rel_bounded:.2e}; largest relative bound {worst_bound:.2e}; bound misses {misses}"
    );
}
