//! CPU time per value of the f64 wave functions over the issue-8 domain
//! (zeta = 9/8, x/a in [1, 3], 64 points per contact, a in {1, 3, 6}; `g`: the
//! model-domain grid point by point): from
//! scratch (`u_wave_bounded`) and with the contact precomputed
//! (`WaveBessel::eval_bounded`, `WaveBessel::eval`, and the batch
//! `WaveBessel::eval_bounded_into` over the 64 points). Thread CPU time from
//! `maugis::budget::thread_cpu_seconds` (Linux), so that a loaded machine inflates it
//! less than wall time; criterion's `wave_f64_domain` group gives wall times.
//!
//!     cargo run --release --example wave_f64_cpu [s|p|g|v<a>]    (s: scratch only, p: precomputed only,
//!     g: `u_wave_bounded` and `du_wave_bounded` from scratch point by point over the model-domain
//!     grid, min / median / max; v<a> / b<a> / d<a>: 64 REPS calls of u_wave / u_wave_bounded /
//!     du_wave_bounded at contact size a, for callgrind)

use maugis::contact::displacement::bounded::wave_scratch_misses;
use maugis::budget::thread_cpu_seconds;
use maugis::contact::displacement::{du_wave, du_wave_bounded, u_wave, u_wave_bounded, WaveBessel};

/// `g`: thread CPU time per value of `u_wave_bounded` and of `du_wave_bounded`
/// from scratch at each point of the model-domain grid (`zeta = 9/8`, `a` from
/// 0.5 to 6 in steps of 1/4, `x/a` in {1, 1 + ulp, 1.001, 1.01, 1.1, 1.5, 2, 2.5, 3}),
/// `REPS` (default 4000) calls per point after one warm-up call; prints min /
/// median / max over the grid and the calls the one-pass route handed on.
fn grid() {
    let reps: usize = std::env::var("REPS").ok().and_then(|v| v.parse().ok()).unwrap_or(4000);
    let misses = wave_scratch_misses();
    let mut pts = Vec::new();
    for i in 0..=22 {
        let a = 0.5 + 0.25 * i as f64;
        for &r in &[1.0, f64::NAN, 1.001, 1.01, 1.1, 1.5, 2.0, 2.5, 3.0] {
            // NaN marks x one ulp above a
            pts.push((a, if r.is_nan() { f64::from_bits(a.to_bits() + 1) } else { a * r }));
        }
    }
    let mut s = 0.0;
    let mut times = [Vec::new(), Vec::new()];
    for &(a, x) in &pts {
        for (which, t) in times.iter_mut().enumerate() {
            let call = |x: f64| if which == 0 { u_wave_bounded(a, 1.125, 1.0, x) } else { du_wave_bounded(a, 1.125, 1.0, x) };
            s += call(x).unwrap().err;
            let t0 = thread_cpu_seconds() * 1e9;
            for _ in 0..reps {
                s += call(std::hint::black_box(x)).unwrap().value;
            }
            t.push(((thread_cpu_seconds() * 1e9) - t0) / reps as f64 * 1e-3);
        }
    }
    for (name, t) in ["u_wave_bounded", "du_wave_bounded"].iter().zip(times.iter_mut()) {
        t.sort_by(f64::total_cmp);
        println!("{name} from scratch, {} grid points: min {:.3} / median {:.3} / max {:.3} us per value (CPU)", t.len(), t[0], t[t.len() / 2], t[t.len() - 1]);
    }
    println!("calls handed on by the one-pass route: {}", wave_scratch_misses() - misses);
    if s == 0.1 {
        println!("{s}");
    }
}

fn main() {
    let mode = std::env::args().nth(1).unwrap_or_default();
    if mode == "g" {
        grid();
        return;
    }
    // `v<a>` / `b<a>` / `d<a>`: u_wave / u_wave_bounded / du_wave_bounded only, 64 points x REPS (default 100)
    // at one a (for callgrind: the difference of two REPS is the cost per call)
    let (bounded, gradient) = (mode.starts_with('b'), mode.starts_with('d'));
    if let Some(a) = mode.strip_prefix(['v', 'b', 'd']).and_then(|a| a.parse::<f64>().ok()) {
        let reps: usize = std::env::var("REPS").ok().and_then(|v| v.parse().ok()).unwrap_or(100);
        let mut s = 0.0;
        let xs: Vec<f64> = (0..64).map(|i| a * (1.0 + 2.0 * (i as f64 * 0.754877666246693).fract())).collect();
        for _ in 0..reps {
            for &x in &xs {
                s += if bounded {
                    u_wave_bounded(a, 1.125, 1.0, x).unwrap().value
                } else if gradient {
                    du_wave_bounded(a, 1.125, 1.0, x).unwrap().value
                } else {
                    u_wave(a, 1.125, 1.0, x).unwrap()
                };
            }
        }
        println!("{s}");
        return;
    }
    let mut s = 0.0;
    for &a in &[1.0, 3.0, 6.0] {
        let xs: Vec<f64> = (0..64).map(|i| a * (1.0 + 2.0 * (i as f64 * 0.754877666246693).fract())).collect();
        if mode != "p" {
            let t0 = thread_cpu_seconds() * 1e9;
            for _ in 0..15000 { for &x in &xs { s += u_wave(a, 1.125, 1.0, x).unwrap(); } }
            println!("a={a} scratch u_wave {:.3} us/value (CPU)", ((thread_cpu_seconds() * 1e9) - t0) / 960000.0 * 1e-3);
            let t0 = thread_cpu_seconds() * 1e9;
            for _ in 0..15000 { for &x in &xs { s += du_wave(a, 1.125, 1.0, x).unwrap(); } }
            println!("a={a} scratch du_wave {:.3} us/value (CPU)", ((thread_cpu_seconds() * 1e9) - t0) / 960000.0 * 1e-3);
            let t0 = thread_cpu_seconds() * 1e9;
            for _ in 0..1500 { for &x in &xs { s += u_wave_bounded(a, 1.125, 1.0, x).unwrap().value; } }
            println!("a={a} scratch bounded {:.3} us/value (CPU)", ((thread_cpu_seconds() * 1e9) - t0) / 96000.0 * 1e-3);
        }
        if mode != "s" {
            let wb = WaveBessel::new(a, 1.125, 1.0).unwrap();
            wb.eval_bounded(a).unwrap();
            let t0 = thread_cpu_seconds() * 1e9;
            for _ in 0..20000 { for &x in &xs { let r = wb.eval_bounded(x).unwrap(); s += r.0.value + r.0.err; } }
            println!("a={a} precomp bounded {:.3} us/value (CPU)", ((thread_cpu_seconds() * 1e9) - t0) / 1280000.0 * 1e-3);
            let t0 = thread_cpu_seconds() * 1e9;
            for _ in 0..20000 { for &x in &xs { let r = wb.eval(x).unwrap(); s += r.0; } }
            println!("a={a} precomp estimate {:.3} us/value (CPU)", ((thread_cpu_seconds() * 1e9) - t0) / 1280000.0 * 1e-3);
            let mut out = wb.eval_bounded_many(&xs).unwrap();
            let t0 = thread_cpu_seconds() * 1e9;
            for _ in 0..20000 { wb.eval_bounded_into(&xs, &mut out).unwrap(); s += out[7].0.value; }
            println!("a={a} precomp bounded, batch of 64 {:.3} us/value (CPU)", ((thread_cpu_seconds() * 1e9) - t0) / 1280000.0 * 1e-3);
        }
    }
    if s == 0.1 { println!("{s}"); }
}
