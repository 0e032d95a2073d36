//! Issue 23's f64 speed targets measured in one run, each value with its proven
//! bound: `hyp1f2_bounded(1/2; k+1, k+3/2; -s^2)` over the issue's `k` set,
//! `meijer_g_k_bounded` on the 10 x 18 `(k, y)` grid, and `u_wave_bounded` /
//! `du_wave_bounded` from scratch over the model domain (the 64 points of the
//! criterion group `wave_f64_domain` plus, per contact size, `x = a`, one ulp
//! above, `x = a (1 + 1e-15)` and `x = 3a`).
//!
//! Every point is timed by the calling thread's CPU time
//! (`CLOCK_THREAD_CPUTIME_ID`, exact to the nanosecond, unlike
//! `/proc/thread-self/schedstat`, which moves only at scheduler ticks): the
//! fastest of 40 batches of `calls` calls, so a batch that the scheduler or a
//! cache-cold start disturbed does not count. Output is CSV on stdout, one row
//! per measured point, for `reference/bench_f64_targets.py`, which writes the
//! tables in `docs/performance.md`:
//!
//! ```text
//! hyp1f2,<k>,<s>,<us>,<rel bound>,<mp fallback 0/1>
//! meijer,<k>,<y>,<us>,<rel bound>,<mp fallback 0/1>
//! wave,<u|du>,<a>,<x>,<us>,<bound relative to the scale>,<mp fallback 0/1>
//! load,<1 min>,<5 min>,<15 min>
//! ```
//!
//! `cargo run --release --example f64_targets --features maugis/gmp-no-check`

use maugis::budget::thread_cpu_seconds;
use maugis::contact::displacement::{du_wave_bounded, u_wave_bounded};
use maugis::special::hyp1f2::hyp1f2_bounded;
use maugis::special::{fallback_counts, meijer_g};
use maugis::Bounded;
use std::hint::black_box;

#[path = "../benches/common/meijer_domain.rs"]
mod meijer_domain;
#[path = "../benches/common/wave_domain.rs"]
mod wave_domain;

/// CPU time per call of `f` in us: the fastest of 40 batches of `calls`.
fn per_call(calls: usize, mut f: impl FnMut() -> f64) -> f64 {
    let mut best = f64::INFINITY;
    for _ in 0..40 {
        let t = thread_cpu_seconds() * 1e9;
        let mut s = 0.0;
        for _ in 0..calls {
            s += f();
        }
        black_box(s);
        best = best.min(((thread_cpu_seconds() * 1e9) - t) * 1e-3 / calls as f64);
    }
    best
}

/// The bound relative to the value (0 for an exact zero, as `G(1, 1)`).
fn rel(b: &Bounded) -> f64 {
    if b.err == 0.0 {
        0.0
    } else {
        b.err / b.value.abs()
    }
}

fn main() {
    // 1F2 of the model family: the points of examples/hyp1f2_f64_cpu.rs.
    let ss: Vec<f64> = (1..=64).map(|i| 35.0 * ((i as f64 * 0.618_033_988_749_895).fract()).max(1.0 / 64.0)).collect();
    for k in [0.0f64, 1.0, 2.0, 5.0, 10.0, 50.0, 200.0, 1000.0] {
        for &s in &ss {
            let before = fallback_counts().hyp1f2;
            let b = hyp1f2_bounded(0.5, k + 1.0, k + 1.5, -s * s).expect("hyp1f2 in the model domain");
            let fb = (fallback_counts().hyp1f2 > before) as u8;
            let us = per_call(40, || hyp1f2_bounded(0.5, k + 1.0, k + 1.5, black_box(-s * s)).map_or(f64::NAN, |b| b.value));
            println!("hyp1f2,{k},{s},{us:.4},{:.3e},{fb}", rel(&b));
        }
    }
    // G on the grid of examples/meijer_g_grid.rs, and the 64 domain points.
    meijer_g::meijer_g_k_bounded(0, 0.5).expect("G(0, 0.5)"); // constants built once, outside the timing
    let ks = [0u32, 1, 2, 3, 5, 10, 30, 100, 300, 1000];
    let ys = [1e-10, 0.1, 0.5, 0.7, 0.8, 0.85, 0.9, 0.93, 0.95, 0.96, 0.97, 0.9705, 0.98, 0.99, 0.999, 1.0 - 1e-6, 1.0 - 1e-12, 1.0];
    let grid = ks.iter().flat_map(|&k| ys.iter().map(move |&y| (k, y, "grid")));
    let domain = meijer_domain::meijer_domain_points().into_iter().map(|(k, y)| (k, y, "domain"));
    for (k, y, set) in grid.chain(domain) {
        let before = fallback_counts().meijer_g_k;
        let b = meijer_g::meijer_g_k_bounded(k, y).expect("G in its domain");
        let fb = (fallback_counts().meijer_g_k > before) as u8;
        let us = per_call(40, || meijer_g::meijer_g_k_bounded(k, black_box(y)).map_or(f64::NAN, |b| b.value));
        println!("meijer,{k},{y:e},{us:.4},{:.3e},{fb},{set}", rel(&b));
    }
    // u_w, du_w/dx from scratch: scale max(|u|, A) and max(|u'|, 2 pi A/zeta), A = 1.
    let zeta = wave_domain::ZETA;
    for (a, x) in wave_domain::wave_points_with_edges() {
        for (name, f, scale) in [
            ("u", u_wave_bounded as fn(f64, f64, f64, f64) -> maugis::Result<Bounded>, 1.0),
            ("du", du_wave_bounded, 2.0 * std::f64::consts::PI / zeta),
        ] {
            let before = fallback_counts().wave_bounded;
            let b = f(a, zeta, 1.0, x).expect("u_w in the model domain");
            let fb = (fallback_counts().wave_bounded > before) as u8;
            let us = per_call(40, || f(a, zeta, 1.0, black_box(x)).map_or(f64::NAN, |b| b.value));
            println!("wave,{name},{a},{x:e},{us:.4},{:.3e},{fb}", b.err / b.value.abs().max(scale));
        }
    }
    let load = std::fs::read_to_string("/proc/loadavg").unwrap_or_default();
    println!("load,{}", load.split_whitespace().take(3).collect::<Vec<_>>().join(","));
}
