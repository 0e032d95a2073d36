//! Criterion benchmarks of the special-function core.
//!
//! * `meijer_g_k` at the singular point `y = 1` and at `y = 1 - 1e-12`, 128 bits,
//!   for k across 0..=1000 (the target: under a millisecond each);
//! * `hyp1f2(1/2; k+1, k+3/2; -300)` at 128 bits (the Eq. 12 factor at abar = 6,
//!   beta = 9/8 is about -280);
//! * `hyp2f1(1, k+1/2; k+2; y)` at 128 bits near and at y = 1;
//! * `bessel_j` MP and f64.

use criterion::{black_box, criterion_group, criterion_main, BenchmarkId, Criterion};
use maugis::special::{bessel_j, exact, hyp1f2, hyp2f1, meijer_g};

const KS: [u32; 5] = [0, 1, 10, 100, 1000];

fn bench_meijer(c: &mut Criterion) {
    let mut g = c.benchmark_group("meijer_g_k_128bit");
    for &k in &KS {
        let one = exact(1.0);
        let near = exact(1.0 - 1e-12);
        let mid = exact(0.5);
        g.bench_with_input(BenchmarkId::new("y=1", k), &k, |b, &k| {
            b.iter(|| meijer_g::meijer_g_k_mp(black_box(k), &one, 128).unwrap())
        });
        g.bench_with_input(BenchmarkId::new("y=1-1e-12", k), &k, |b, &k| {
            b.iter(|| meijer_g::meijer_g_k_mp(black_box(k), &near, 128).unwrap())
        });
        g.bench_with_input(BenchmarkId::new("y=0.5", k), &k, |b, &k| {
            b.iter(|| meijer_g::meijer_g_k_mp(black_box(k), &mid, 128).unwrap())
        });
    }
    g.finish();
}

fn bench_hyp1f2(c: &mut Criterion) {
    let mut g = c.benchmark_group("hyp1f2_model_128bit");
    let a = exact(0.5);
    let z = exact(-300.0);
    for &k in &KS {
        let b1 = exact(k as f64 + 1.0);
        let b2 = exact(k as f64 + 1.5);
        g.bench_with_input(BenchmarkId::new("z=-300", k), &k, |b, _| {
            b.iter(|| hyp1f2::hyp1f2_mp(&a, &b1, &b2, black_box(&z), 128).unwrap())
        });
    }
    g.finish();
    c.bench_function("hyp1f2_f64/k=0,z=-300", |b| b.iter(|| hyp1f2::hyp1f2(0.5, 1.0, 1.5, black_box(-300.0)).unwrap()));
    c.bench_function("hyp1f2_f64/k=100,z=-300", |b| {
        b.iter(|| hyp1f2::hyp1f2(0.5, 101.0, 101.5, black_box(-300.0)).unwrap())
    });
}

fn bench_hyp2f1(c: &mut Criterion) {
    let mut g = c.benchmark_group("hyp2f1_model_128bit");
    let one = exact(1.0);
    for &k in &KS {
        let bb = exact(k as f64 + 0.5);
        let cc = exact(k as f64 + 2.0);
        for &y in &[0.25, 0.9, 1.0 - 1e-12, 1.0] {
            let yy = exact(y);
            g.bench_with_input(BenchmarkId::new(format!("y={y}"), k), &k, |b, _| {
                b.iter(|| hyp2f1::hyp2f1_mp(&one, &bb, &cc, black_box(&yy), 128).unwrap())
            });
        }
    }
    g.finish();
}

fn bench_bessel(c: &mut Criterion) {
    let mut g = c.benchmark_group("bessel_j");
    for &(n, x) in &[(0i64, 2.5f64), (10, 37.699), (100, 120.0), (0, 1000.0)] {
        let xe = exact(x);
        g.bench_with_input(BenchmarkId::new("mp128", format!("n={n},x={x}")), &(n, x), |b, _| {
            b.iter(|| bessel_j::bessel_j_mp(black_box(n), &xe, 128).unwrap())
        });
        g.bench_with_input(BenchmarkId::new("f64", format!("n={n},x={x}")), &(n, x), |b, _| {
            b.iter(|| bessel_j::bessel_j(black_box(n), black_box(x)).unwrap())
        });
    }
    g.finish();
}

criterion_group! {
    name = benches;
    config = Criterion::default().sample_size(20).warm_up_time(std::time::Duration::from_millis(300)).measurement_time(std::time::Duration::from_secs(1));
    targets = bench_meijer, bench_hyp1f2, bench_hyp2f1, bench_bessel
}
criterion_main!(benches);
