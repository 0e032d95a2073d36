//! CPU time per value of the f64 wave functions over the issue-8 domain
//! (zeta = 9/8, x/a in [1, 3], 64 points per contact, a in {1, 3, 6}): from
//! scratch (`u_wave_bounded`) and with the contact precomputed
//! (`WaveBessel::eval_bounded`, `WaveBessel::eval`, and the batch
//! `WaveBessel::eval_bounded_into` over the 64 points). Thread CPU time from
//! /proc/thread-self/schedstat (Linux), so that a loaded machine inflates it
//! less than wall time; criterion's `wave_f64_domain` group gives wall times.
//!
//!     cargo run --release --example wave_f64_cpu [s|p|v<a>]    (s: scratch only, p: precomputed only,
//!     v<a> / b<a>: 64 REPS calls of u_wave / u_wave_bounded at contact size a, for callgrind)

use maugis::contact::displacement::{du_wave, u_wave, u_wave_bounded, WaveBessel};
fn cpu_ns() -> f64 {
    std::fs::read_to_string("/proc/thread-self/schedstat").unwrap().split_whitespace().next().unwrap().parse().unwrap()
}
fn main() {
    let mode = std::env::args().nth(1).unwrap_or_default();
    // `v<a>` / `b<a>`: u_wave / u_wave_bounded only, 64 points x REPS (default 100)
    // at one a (for callgrind: the difference of two REPS is the cost per call)
    let bounded = mode.starts_with('b');
    if let Some(a) = mode.strip_prefix(['v', 'b']).and_then(|a| a.parse::<f64>().ok()) {
        let reps: usize = std::env::var("REPS").ok().and_then(|v| v.parse().ok()).unwrap_or(100);
        let mut s = 0.0;
        let xs: Vec<f64> = (0..64).map(|i| a * (1.0 + 2.0 * (i as f64 * 0.754877666246693).fract())).collect();
        for _ in 0..reps {
            for &x in &xs {
                s += if bounded { u_wave_bounded(a, 1.125, 1.0, x).unwrap().value } else { u_wave(a, 1.125, 1.0, x).unwrap() };
            }
        }
        println!("{s}");
        return;
    }
    let mut s = 0.0;
    for &a in &[1.0, 3.0, 6.0] {
        let xs: Vec<f64> = (0..64).map(|i| a * (1.0 + 2.0 * (i as f64 * 0.754877666246693).fract())).collect();
        if mode != "p" {
            let t0 = cpu_ns();
            for _ in 0..15000 { for &x in &xs { s += u_wave(a, 1.125, 1.0, x).unwrap(); } }
            println!("a={a} scratch u_wave {:.3} us/value (CPU)", (cpu_ns() - t0) / 960000.0 * 1e-3);
            let t0 = cpu_ns();
            for _ in 0..15000 { for &x in &xs { s += du_wave(a, 1.125, 1.0, x).unwrap(); } }
            println!("a={a} scratch du_wave {:.3} us/value (CPU)", (cpu_ns() - t0) / 960000.0 * 1e-3);
            let t0 = cpu_ns();
            for _ in 0..1500 { for &x in &xs { s += u_wave_bounded(a, 1.125, 1.0, x).unwrap().value; } }
            println!("a={a} scratch bounded {:.3} us/value (CPU)", (cpu_ns() - t0) / 96000.0 * 1e-3);
        }
        if mode != "s" {
            let wb = WaveBessel::new(a, 1.125, 1.0).unwrap();
            wb.eval_bounded(a).unwrap();
            let t0 = cpu_ns();
            for _ in 0..20000 { for &x in &xs { let r = wb.eval_bounded(x).unwrap(); s += r.0.value + r.0.err; } }
            println!("a={a} precomp bounded {:.3} us/value (CPU)", (cpu_ns() - t0) / 1280000.0 * 1e-3);
            let t0 = cpu_ns();
            for _ in 0..20000 { for &x in &xs { let r = wb.eval(x).unwrap(); s += r.0; } }
            println!("a={a} precomp estimate {:.3} us/value (CPU)", (cpu_ns() - t0) / 1280000.0 * 1e-3);
            let mut out = wb.eval_bounded_many(&xs).unwrap();
            let t0 = cpu_ns();
            for _ in 0..20000 { wb.eval_bounded_into(&xs, &mut out).unwrap(); s += out[7].0.value; }
            println!("a={a} precomp bounded, batch of 64 {:.3} us/value (CPU)", (cpu_ns() - t0) / 1280000.0 * 1e-3);
        }
    }
    if s == 0.1 { println!("{s}"); }
}
