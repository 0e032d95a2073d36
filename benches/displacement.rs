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

use criterion::{black_box, criterion_group, criterion_main, BenchmarkId, Criterion};
use maugis::contact::displacement::{u_wave, u_wave_mp, u_wave_series_mp, WaveBessel};
use maugis::contact::wave_quadrature::u_wave_quad;
use maugis::special::exact;

const ABARS: [f64; 3] = [1.0, 3.0, 6.0];
const RATIOS: [f64; 3] = [1.0, 1.001, 2.0];
const BETA: f64 = 1.125;

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
                b.iter(|| wb.eval(black_box(x)))
            });
            let (a, z, m, xe) = (exact(abar), exact(BETA), exact(1.0), exact(x));
            g.bench_with_input(BenchmarkId::new("mp128", format!("abar={abar},x/a={r}")), &x, |b, _| {
                b.iter(|| u_wave_mp(&a, &z, &m, black_box(&xe), 128).unwrap())
            });
        }
    }
    g.finish();
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
    targets = bench_eq12, bench_bessel_form, bench_quadrature
}
criterion_main!(benches);
