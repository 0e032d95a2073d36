//! Criterion benchmarks of the wave displacement (issue: Eq. 12 at k_max = 1000).
//!
//! * Eq. 12 summed to k_max = 1000, certified, for abar in {1, 3, 6}, beta = 9/8
//!   (lengths in units of l_h, A = 1): at 128 bits over the grid x/a in [1, 3]
//!   of issue 8 (the former slow band x/a ~ 1.1-1.4 included), at 256 bits at
//!   x/a in {1, 1.001, 2};
//! * the Bessel form in f64 (double-double) and MP (128 bits);
//! * the Eq. 11a quadrature in f64.
//!
//! `reference/bench_mpmath.py` times mpmath on the same cases; the side-by-side
//! table is in docs/performance.md.

#[path = "common/wave_domain.rs"]
mod wave_domain;

use criterion::{black_box, criterion_group, criterion_main, BenchmarkId, Criterion, Throughput};
use maugis::contact::displacement::{du_wave, du_wave_bounded, u_wave, u_wave_bounded, u_wave_mp, u_wave_series_mp, WaveBessel};
use maugis::contact::displacement::bounded::wave_scratch_misses;
use maugis::contact::displacement::quadrature::u_wave_quad;
use maugis::special::exact;

const ABARS: [f64; 3] = [1.0, 3.0, 6.0];
const RATIOS: [f64; 3] = [1.0, 1.001, 2.0];
const BETA: f64 = wave_domain::ZETA;

/// The issue-8 grid of x/a for the Eq. 12 slow band (a in {1, 3, 6}, x/a in [1, 3]).
const GRID_RATIOS: [f64; 13] = [1.0, 1.0005, 1.001, 1.01, 1.05, 1.1, 1.2, 1.35, 1.5, 1.75, 2.0, 2.5, 3.0];

fn bench_eq12(c: &mut Criterion) {
    let mut g = c.benchmark_group("eq12_kmax1000");
    for &prec in &[128u32, 256] {
        for &abar in &ABARS {
            let ratios: &[f64] = if prec == 128 { &GRID_RATIOS } else { &RATIOS };
            for &r in ratios {
                let (a, z, m, x) = (exact(abar), exact(BETA), exact(1.0), exact(abar * r));
                g.bench_with_input(BenchmarkId::new(format!("{prec}bit"), format!("abar={abar},x/a={r}")), &prec, |b, &p| {
                    b.iter(|| u_wave_series_mp(&a, &z, &m, black_box(&x), 1000, p).unwrap())
                });
            }
        }
    }
    g.finish();
}

fn bench_bessel_form(c: &mut Criterion) {
    let mut g = c.benchmark_group("bessel_form");
    for &abar in &ABARS {
        for &r in &RATIOS {
            let x = abar * r;
            g.bench_with_input(BenchmarkId::new("f64", format!("abar={abar},x/a={r}")), &x, |b, &x| {
                b.iter(|| u_wave(abar, BETA, 1.0, black_box(x)).unwrap())
            });
            // With the Bessel data of one contact size precomputed (the solver's case).
            let wb = WaveBessel::new(abar, BETA, 1.0).unwrap();
            g.bench_with_input(BenchmarkId::new("f64_precomputed", format!("abar={abar},x/a={r}")), &x, |b, &x| {
                b.iter(|| wb.eval(black_box(x)).unwrap())
            });
            let (a, z, m, xe) = (exact(abar), exact(BETA), exact(1.0), exact(x));
            g.bench_with_input(BenchmarkId::new("mp128", format!("abar={abar},x/a={r}")), &x, |b, _| {
                b.iter(|| u_wave_mp(&a, &z, &m, black_box(&xe), 128).unwrap())
            });
        }
    }
    g.finish();
}

/// The f64 wave functions per value over the domain, from scratch and with the
/// contact precomputed (the solver's case), estimate and proven-bound paths.
/// Criterion reports elements per second: 64 values per iteration.
fn bench_wave_f64_domain(c: &mut Criterion) {
    let pts = wave_domain::wave_points();
    let (before, before_contacts) = (maugis::special::fallback_counts().wave_bounded, maugis::special::fallback_counts().wave_bounded_mp_contacts);
    let mut g = c.benchmark_group("wave_f64_domain");
    g.throughput(Throughput::Elements(pts.len() as u64));
    g.bench_function("u_wave/scratch", |b| {
        b.iter(|| pts.iter().map(|&(a, x)| u_wave(a, BETA, 1.0, black_box(x)).unwrap()).sum::<f64>())
    });
    g.bench_function("du_wave/scratch", |b| {
        b.iter(|| pts.iter().map(|&(a, x)| du_wave(a, BETA, 1.0, black_box(x)).unwrap()).sum::<f64>())
    });
    g.bench_function("u_wave_bounded/scratch", |b| {
        b.iter(|| pts.iter().map(|&(a, x)| u_wave_bounded(a, BETA, 1.0, black_box(x)).unwrap().value).sum::<f64>())
    });
    g.bench_function("du_wave_bounded/scratch", |b| {
        b.iter(|| pts.iter().map(|&(a, x)| du_wave_bounded(a, BETA, 1.0, black_box(x)).unwrap().value).sum::<f64>())
    });
    // one contact per a in {1, 3, 6}, 64 x in [a, 3a]
    for &abar in &ABARS {
        let wb = WaveBessel::new(abar, BETA, 1.0).unwrap();
        let xs: Vec<f64> = pts.iter().map(|&(a, x)| abar * x / a).collect();
        wb.eval_bounded(xs[0]).unwrap(); // certified data built once, outside the timing
        g.bench_function(format!("eval/precomputed/abar={abar}"), |b| b.iter(|| wb.eval_many(black_box(&xs)).unwrap()));
        g.bench_function(format!("eval_bounded/precomputed/abar={abar}"), |b| {
            b.iter(|| wb.eval_bounded_many(black_box(&xs)).unwrap())
        });
    }
    g.finish();
    eprintln!(
        "wave_f64_domain: MP fallbacks of the bounded path: {} (per x), contact data built in MP: {}",
        maugis::special::fallback_counts().wave_bounded - before,
        maugis::special::fallback_counts().wave_bounded_mp_contacts - before_contacts
    );
}

/// `u_wave_bounded` from scratch (the one-pass bounded route: both values and
/// their bounds per call) point by point over a grid of the model domain,
/// `a in {0.5, 1.5, 3, 4.5, 6}` x `x/a in {1, 2, 3}`, `zeta = 9/8`: the
/// per-value time at each point (report min / median / max over the grid),
/// and the calls the route handed on (must be 0).
fn bench_wave_bounded_grid(c: &mut Criterion) {
    let before = wave_scratch_misses();
    let mut g = c.benchmark_group("wave_bounded_grid");
    for &a in &[0.5, 1.5, 3.0, 4.5, 6.0] {
        for &r in &[1.0, 2.0, 3.0] {
            let x = a * r;
            g.bench_function(format!("u_wave_bounded/a={a}/x_over_a={r}"), |b| {
                b.iter(|| u_wave_bounded(black_box(a), BETA, 1.0, black_box(x)).unwrap())
            });
        }
    }
    g.finish();
    eprintln!("wave_bounded_grid: calls handed on by the one-pass route: {}", wave_scratch_misses() - before);
}

fn bench_quadrature(c: &mut Criterion) {
    let mut g = c.benchmark_group("eq11a_quadrature_f64");
    for &abar in &ABARS {
        let x = abar * 2.0;
        g.bench_with_input(BenchmarkId::new("u_wave_quad", format!("abar={abar},x/a=2")), &x, |b, &x| {
            b.iter(|| u_wave_quad(abar, BETA, 1.0, black_box(x)).unwrap())
        });
    }
    g.finish();
}

criterion_group! {
    name = benches;
    config = Criterion::default().sample_size(10).warm_up_time(std::time::Duration::from_millis(300)).measurement_time(std::time::Duration::from_secs(1));
    targets = bench_eq12, bench_bessel_form, bench_wave_f64_domain, bench_wave_bounded_grid, bench_quadrature
}
criterion_main!(benches);
