//! Criterion benchmarks of the special-function core.
//!
//! * `meijer_g_k` at the singular point `y = 1` and at `y = 1 - 1e-12`, 128 bits,
//!   for k across 0..=1000 (the target: under a millisecond each);
//! * `hyp1f2(1/2; k+1, k+3/2; -300)` at 128 bits (the Eq. 12 factor at abar = 6,
//!   beta = 9/8 is about -280);
//! * `hyp1f2_large_grid`: `hyp1f2_mp` at 128 bits on the issue-23 grid of large
//!   parameters and `1F2(1/2; 1, 3/2; z)` down to `z = -10^6` at 53, 128, 400 bits;
//! * `hyp2f1(1, k+1/2; k+2; y)` at 128 bits near and at y = 1;
//! * `hyp2f1_large_param`: MP `2F1` with one large parameter (`b` in {1e4, 1e5, 1e6})
//!   on the 76 points of `reference/data/hyp2f1_large_param.csv` at 64 and 256 bits,
//!   through the decimal path `maugis eval` takes (target: 50 ms a call; Arb and
//!   mpmath beside it: `reference/bench_hyp2f1_large_param.py`);
//! * `bessel_j` MP at fixed points; f64 over the issue-8 domain (`bessel_j_f64`);
//! * `bessel_j_large`: `bessel_j_mp` over the issue-13 grid (n in {0, 1, 7, 60,
//!   500, 2000, 10000} x x in {0.001, ..., 1000000.5}) and J_500(30000),
//!   J_-1200(50000.25), at 53, 128 and 512 bits, one id per point (targets:
//!   2 ms at 53 and 128 bits, 10 ms at 512).

use criterion::{black_box, criterion_group, criterion_main, BenchmarkId, Criterion};
use maugis::special::{bessel_j, exact, hyp1f2, hyp2f1, meijer_g};

#[path = "common/meijer_domain.rs"]
mod meijer_domain;

#[path = "common/hyp1f2_large_grid.rs"]
mod hyp1f2_large_grid;

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

/// `hyp1f2_mp` at 128 bits over the issue-23 grid (`a`, `b1`, `b2`, `z` in
/// `[-500, 500]`, `benches/common/hyp1f2_large_grid.rs`; target 50 ms a point), and
/// `1F2(1/2; 1, 3/2; z)` for `z` down to `-10^6` at 53, 128 and 400 bits (target
/// 10 ms). Arb beside it on the same points: `reference/bench_arb_hyp1f2_grid.py`.
fn bench_hyp1f2_large(c: &mut Criterion) {
    let mut g = c.benchmark_group("hyp1f2_large_grid");
    g.sample_size(10).warm_up_time(std::time::Duration::from_millis(100)).measurement_time(std::time::Duration::from_millis(400));
    let ex = |p: (f64, f64, f64, f64)| (exact(p.0), exact(p.1), exact(p.2), exact(p.3));
    for (i, p) in hyp1f2_large_grid::large_grid().into_iter().enumerate() {
        let (a, b1, b2, z) = ex(p);
        g.bench_function(BenchmarkId::new("prec=128", format!("{i}:a={},b1={},b2={},z={}", p.0, p.1, p.2, p.3)), |b| {
            b.iter(|| hyp1f2::hyp1f2_mp(&a, &b1, &b2, black_box(&z), 128).unwrap())
        });
    }
    for prec in [53u32, 128, 400] {
        for &zf in &hyp1f2_large_grid::MODEL_Z {
            let (a, b1, b2, z) = ex((0.5, 1.0, 1.5, zf));
            g.bench_function(BenchmarkId::new(format!("model,prec={prec}"), format!("z={zf}")), |b| {
                b.iter(|| hyp1f2::hyp1f2_mp(&a, &b1, &b2, black_box(&z), prec).unwrap())
            });
        }
    }
    g.finish();
}

/// `hyp1f2_bounded(1/2; k+1, k+3/2; -s^2)` over the issue-8 domain k <= 1000,
/// s <= 35 (64 fixed low-discrepancy points; elements per second), with the number
/// of MP fallbacks printed (large negative z against small k cancels: those fall back).
fn bench_hyp1f2_domain(c: &mut Criterion) {
    let pts: Vec<(f64, f64)> = (0..64)
        .map(|i| {
            let u = (i as f64 * 0.618_033_988_749_895).fract();
            let v = (i as f64 * 0.754_877_666_246_693).fract();
            ((1000.0 * u).floor(), 35.0 * v)
        })
        .collect();
    let before = maugis::special::fallback_counts().hyp1f2;
    let mut g = c.benchmark_group("hyp1f2_f64_domain");
    g.throughput(criterion::Throughput::Elements(pts.len() as u64));
    g.bench_function("hyp1f2_bounded", |b| {
        b.iter(|| pts.iter().map(|&(k, s)| hyp1f2::hyp1f2_bounded(0.5, k + 1.0, k + 1.5, black_box(-s * s)).unwrap().value).sum::<f64>())
    });
    let native: Vec<(f64, f64)> = pts
        .iter()
        .copied()
        .filter(|&(k, s)| hyp1f2::hyp1f2_native_bounded(0.5, k + 1.0, k + 1.5, -s * s, 1e-14).is_ok_and(|b| b.is_some()))
        .collect();
    g.throughput(criterion::Throughput::Elements(native.len().max(1) as u64));
    g.bench_function("hyp1f2_native_bounded/accepted_points", |b| {
        b.iter(|| native.iter().map(|&(k, s)| hyp1f2::hyp1f2_native_bounded(0.5, k + 1.0, k + 1.5, black_box(-s * s), 1e-14).unwrap().unwrap().value).sum::<f64>())
    });
    g.finish();
    eprintln!(
        "hyp1f2_f64_domain: {} of {} points native; MP fallbacks counted during the run: {}",
        native.len(),
        pts.len(),
        maugis::special::fallback_counts().hyp1f2 - before
    );
    // Issue 23's table: k in {0, 1, 2, 5, 10, 50, 200, 1000}, 64 s per k in (0, 35]
    let before = maugis::special::fallback_counts().hyp1f2;
    let mut g = c.benchmark_group("hyp1f2_f64_per_k");
    g.throughput(criterion::Throughput::Elements(64));
    for k in [0.0f64, 1.0, 2.0, 5.0, 10.0, 50.0, 200.0, 1000.0] {
        let ss: Vec<f64> = (1..=64).map(|i| 35.0 * ((i as f64 * 0.618_033_988_749_895).fract()).max(1.0 / 64.0)).collect();
        g.bench_with_input(BenchmarkId::new("hyp1f2_bounded,k", k), &k, |b, &k| {
            b.iter(|| ss.iter().map(|&s| hyp1f2::hyp1f2_bounded(0.5, k + 1.0, k + 1.5, black_box(-s * s)).unwrap().value).sum::<f64>())
        });
    }
    g.finish();
    eprintln!("hyp1f2_f64_per_k: MP fallbacks during the run: {}", maugis::special::fallback_counts().hyp1f2 - before);
    // The whole family k = 0..=1000 at one z = -s^2 (elements: 1001 values per call).
    let before = maugis::special::fallback_counts().hyp1f2;
    let mut g = c.benchmark_group("hyp1f2_model_family_f64");
    g.throughput(criterion::Throughput::Elements(1001));
    for &s in &[0.5f64, 3.0, 10.0, 20.0, 35.0] {
        g.bench_with_input(BenchmarkId::new("kmax=1000,s", s), &s, |b, &s| {
            b.iter(|| hyp1f2::hyp1f2_model_family_f64(1000, black_box(-s * s)).unwrap().iter().map(|v| v.value).sum::<f64>())
        });
    }
    g.finish();
    eprintln!("hyp1f2_model_family_f64: MP fallbacks during the run: {}", maugis::special::fallback_counts().hyp1f2 - before);
}

/// A criterion group of `meijer_g_k_bounded` over named point sets (elements per
/// second), with the MP fallbacks of the run printed.
fn bench_meijer_point_sets(c: &mut Criterion, group: &str, sets: &[(&str, &Vec<(u32, f64)>)]) {
    let before = maugis::special::fallback_counts().meijer_g_k;
    let mut g = c.benchmark_group(group);
    for &(name, pts) in sets {
        g.throughput(criterion::Throughput::Elements(pts.len() as u64));
        g.bench_function(name, |b| b.iter(|| pts.iter().map(|&(k, y)| meijer_g::meijer_g_k_bounded(k, black_box(y)).unwrap().value).sum::<f64>()));
    }
    g.finish();
    eprintln!("{group}: MP fallbacks during the run: {}", maugis::special::fallback_counts().meijer_g_k - before);
}

/// `meijer_g_k_bounded(k, y)` over the issue-8 domain k <= 1000, y in (0, 1]
/// (64 fixed points; elements per second), with the MP fallbacks printed.
fn bench_meijer_domain(c: &mut Criterion) {
    let pts = meijer_domain::meijer_domain_points();
    let before = maugis::special::fallback_counts().meijer_g_k;
    let mut g = c.benchmark_group("meijer_g_k_f64_domain");
    g.throughput(criterion::Throughput::Elements(pts.len() as u64));
    g.bench_function("meijer_g_k_bounded", |b| {
        b.iter(|| pts.iter().map(|&(k, y)| meijer_g::meijer_g_k_bounded(k, black_box(y)).unwrap().value).sum::<f64>())
    });
    g.finish();
    eprintln!("meijer_g_k_f64_domain: MP fallbacks during the run: {}", maugis::special::fallback_counts().meijer_g_k - before);
    // The paths next to y = 1 and the zeros: y > 0.97 (near-one expansion: f64 where
    // k (1 - y) <= 1.25, else plain double-double with four AVX lanes), 1e-9 next to the
    // zero of G(k, .) (direct formula in double words), and the f64 near-one expansion
    // at 0.9 <= y < 0.97.
    let near_one: Vec<(u32, f64)> = [0u32, 2, 100, 472, 1000].iter().flat_map(|&k| [(k, 0.9705), (k, 0.99), (k, 1.0 - 1e-9)]).collect();
    let near_one_f64: Vec<(u32, f64)> = [0u32, 1, 2, 5, 10].iter().flat_map(|&k| [(k, 0.9), (k, 0.93), (k, 0.95), (k, 0.96)]).collect();
    let near_zero: Vec<(u32, f64)> = vec![(2, 0.807_135_927_66), (5, 0.637_762_065), (10, 0.571_703_529_38), (100, 0.507_463_152_53), (1000, 0.500_749_626_68)];
    bench_meijer_point_sets(c, "meijer_g_k_f64_dd_paths", &[("near_one", &near_one), ("next_to_zero", &near_zero), ("near_one_f64_below_0.97", &near_one_f64)]);
    // The routes of issue 23 item 4 (meijer_g/beta_series.rs, meijer_g/near_one_fast.rs):
    // the Beta series (k w >= 14.5-30 by k, and the cells at y = 1/2 for large k), the
    // plain double-double near-one expansion at growth -k ln y from 3 to 32 (and next to the
    // zeros of G(2, .), G(3, .)), and its slowest cells (k w ~ 20-30 at large k).
    let beta: Vec<(u32, f64)> = vec![(100, 0.5), (1000, 0.5), (300, 0.85), (1000, 0.9), (1000, 0.95), (1000, 0.97)];
    let fast: Vec<(u32, f64)> = vec![(30, 0.9), (100, 0.93), (300, 0.98), (100, 0.97), (2, 0.8), (3, 0.7)];
    let slowest: Vec<(u32, f64)> = vec![(1000, 0.9705), (1000, 0.98), (300, 0.93), (100, 0.85)];
    bench_meijer_point_sets(c, "meijer_g_k_f64_routes", &[("beta_series", &beta), ("near_one_fast", &fast), ("near_one_fast_slowest", &slowest)]);
    // The whole family k = 0..=1000 at one y (elements: 1001 values per call).
    let before = maugis::special::fallback_counts().meijer_g_k;
    let mut g = c.benchmark_group("meijer_g_k_family_f64");
    g.throughput(criterion::Throughput::Elements(1001));
    for &y in &[0.25, 0.5, 0.9, 0.99, 1.0 - 1e-9, 1.0] {
        g.bench_with_input(BenchmarkId::new("kmax=1000", y), &y, |b, &y| {
            b.iter(|| meijer_g::meijer_g_k_family_f64(1000, black_box(y)).unwrap().iter().map(|v| v.value).sum::<f64>())
        });
    }
    g.finish();
    eprintln!("meijer_g_k_family_f64: MP fallbacks during the run: {}", maugis::special::fallback_counts().meijer_g_k - before);
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

/// MP `2F1` with one large parameter over the grid of
/// `reference/data/hyp2f1_large_param.csv` (issue 37), at 64 and 256 bits, through
/// `eval_at_decimals` + `hyp2f1_ball_mp` as `maugis eval` runs it; one id per point
/// (`prec=P/i:a,b,c,z`). Arb and mpmath on the same points:
/// `python3 reference/bench_hyp2f1_large_param.py 64 256`.
fn bench_hyp2f1_large_param(c: &mut Criterion) {
    use maugis::ball::{eval_at_decimals, Decimal};
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/reference/data/hyp2f1_large_param.csv");
    let mut rdr = csv::ReaderBuilder::new().comment(Some(b'#')).from_path(path).expect("reference/data/hyp2f1_large_param.csv");
    let rows: Vec<Vec<String>> = rdr.records().map(|r| r.expect("csv row").iter().take(4).map(str::to_string).collect()).collect();
    let mut g = c.benchmark_group("hyp2f1_large_param");
    g.sample_size(10).warm_up_time(std::time::Duration::from_millis(100)).measurement_time(std::time::Duration::from_millis(400));
    for prec in [64u32, 256] {
        for (i, r) in rows.iter().enumerate() {
            let d: Vec<Decimal> = r.iter().map(|s| Decimal::parse(s).expect("decimal")).collect();
            g.bench_function(BenchmarkId::new(format!("prec={prec}"), format!("{i}:{}", r.join(","))), |b| {
                b.iter(|| eval_at_decimals(black_box(&d), prec, |x| hyp2f1::hyp2f1_ball_mp(&x[0], &x[1], &x[2], &x[3], prec)).unwrap())
            });
        }
    }
    g.finish();
}

/// The issue-8 domain for the f64 comparison with SciPy: a, b in [-3, 3],
/// c in [0.5, 6], z in [-5, 0.9], from the 64-bit LCG that
/// reference/bench_scipy.py reproduces (same seed, same points).
fn hyp2f1_bench_points(n: usize) -> Vec<[f64; 4]> {
    let mut state: u64 = 0x2f1_5c1;
    let mut uniform = |lo: f64, hi: f64| {
        state = state.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
        lo + (hi - lo) * ((state >> 11) as f64 / (1u64 << 53) as f64)
    };
    (0..n).map(|_| [uniform(-3.0, 3.0), uniform(-3.0, 3.0), uniform(0.5, 6.0), uniform(-5.0, 0.9)]).collect()
}

/// f64 2F1 over 1000 random points of the SciPy domain (time per 1000 values),
/// with the native-path fallback count and the worst error against the
/// certified 120-bit value printed once.
fn bench_hyp2f1_f64(c: &mut Criterion) {
    let pts = hyp2f1_bench_points(1000);
    let mut fallbacks = 0;
    let (mut worst, mut worst_bound) = (0.0f64, 0.0f64);
    for p in &pts {
        let native = hyp2f1::hyp2f1_native_bounded(p[0], p[1], p[2], p[3], hyp2f1::NATIVE_ACCEPT_REL).unwrap();
        if native.is_none() {
            fallbacks += 1;
        }
        let v = hyp2f1::hyp2f1_bounded(p[0], p[1], p[2], p[3]).unwrap();
        let m = hyp2f1::hyp2f1_mp(&exact(p[0]), &exact(p[1]), &exact(p[2]), &exact(p[3]), 120).unwrap().to_f64();
        worst = worst.max(((v.value - m) / m).abs());
        worst_bound = worst_bound.max(v.err / v.value.abs());
    }
    eprintln!(
        "hyp2f1_f64 points: {} MP fallbacks of {}, worst rel error {worst:.2e}, worst rel bound {worst_bound:.2e}",
        fallbacks,
        pts.len()
    );
    let mut g = c.benchmark_group("hyp2f1_f64");
    g.bench_function("hyp2f1/1000 random points", |b| {
        b.iter(|| pts.iter().map(|p| hyp2f1::hyp2f1(p[0], p[1], p[2], black_box(p[3])).unwrap()).sum::<f64>())
    });
    g.bench_function("hyp2f1_bounded/1000 random points", |b| {
        b.iter(|| pts.iter().map(|p| hyp2f1::hyp2f1_bounded(p[0], p[1], p[2], black_box(p[3])).unwrap().err).sum::<f64>())
    });
    g.finish();
}

fn bench_bessel(c: &mut Criterion) {
    let mut g = c.benchmark_group("bessel_j");
    for &(n, x) in &[(0i64, 2.5f64), (10, 37.699), (100, 120.0), (0, 1000.0)] {
        let xe = exact(x);
        g.bench_with_input(BenchmarkId::new("mp128", format!("n={n},x={x}")), &(n, x), |b, _| {
            b.iter(|| bessel_j::bessel_j_mp(black_box(n), &xe, 128).unwrap())
        });
    }
    g.finish();
}

/// The issue-8 J_n domain, integer n <= 60, x <= 150, uniform: the points of
/// examples/bessel_f64.rs and `reference/bench_scipy.py --bessel` (same LCG,
/// same seed), so the three compare side by side.
fn bessel_bench_points(count: usize) -> Vec<(i64, f64)> {
    let mut state: u64 = 0xB355E1;
    let mut uniform = || {
        state = state.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
        (state >> 11) as f64 / (1u64 << 53) as f64
    };
    (0..count).map(|_| (((uniform() * 61.0) as i64).min(60), uniform() * 150.0)).collect()
}

/// f64 J_n over 1000 points of the domain (time per 1000 values), and each
/// native method on its own share of them; the MP-fallback count and the
/// worst error against the certified value are printed once.
fn bench_bessel_f64(c: &mut Criterion) {
    let pts = bessel_bench_points(1000);
    let (mut fallbacks, mut worst) = (0, 0.0f64);
    for &(n, x) in &pts {
        let (m, ax) = (n.unsigned_abs(), x.abs());
        let native = bessel_j::bessel_j_native(bessel_j::choose_native(m, ax), m, ax);
        if !native.is_some_and(|b| b.err <= b.value.abs() / (1u64 << 47) as f64) {
            fallbacks += 1;
        }
        let v = bessel_j::bessel_j(n, x).unwrap();
        let e = bessel_j::bessel_j_mp(n, &exact(x), 128).unwrap().to_f64();
        if e != 0.0 {
            worst = worst.max(((v - e) / e).abs());
        }
    }
    eprintln!("bessel_j_f64 points: {fallbacks} MP fallbacks (bounded) of {}, worst rel error {worst:.2e}", pts.len());
    let mut g = c.benchmark_group("bessel_j_f64");
    g.bench_function("bessel_j/1000 random points", |b| {
        b.iter(|| pts.iter().map(|&(n, x)| bessel_j::bessel_j(n, black_box(x)).unwrap()).sum::<f64>())
    });
    g.bench_function("bessel_j_bounded/1000 random points", |b| {
        b.iter(|| pts.iter().map(|&(n, x)| bessel_j::bessel_j_bounded(n, black_box(x)).unwrap().err).sum::<f64>())
    });
    for m in [bessel_j::NativeMethod::Recurrence, bessel_j::NativeMethod::Series] {
        let sel: Vec<(u64, f64)> =
            pts.iter().map(|&(n, x)| (n as u64, x)).filter(|&(n, x)| bessel_j::choose_native(n, x) == m).collect();
        g.bench_function(format!("{m:?}/{} of the points", sel.len()), |b| {
            b.iter(|| sel.iter().map(|&(n, x)| bessel_j::bessel_j_native(m, n, black_box(x)).map_or(0.0, |v| v.value)).sum::<f64>())
        });
    }
    g.finish();
}

/// The issue-13 grid (the same points as `examples/bessel_grid.rs`).
const GRID_ORDERS: [i64; 7] = [0, 1, 7, 60, 500, 2000, 10000];
const GRID_ARGS: [f64; 9] = [0.001, 1.5, 30.25, 150.5, 999.5, 5000.25, 20000.5, 99999.5, 1000000.5];
const GRID_EXTRA: [(i64, f64); 2] = [(500, 30000.0), (-1200, 50000.25)];

fn bench_bessel_large(c: &mut Criterion) {
    let mut g = c.benchmark_group("bessel_j_large");
    g.sample_size(10).warm_up_time(std::time::Duration::from_millis(100)).measurement_time(std::time::Duration::from_millis(400));
    for prec in [53u32, 128, 512] {
        let points = GRID_ORDERS.iter().flat_map(|&n| GRID_ARGS.iter().map(move |&x| (n, x))).chain(GRID_EXTRA);
        for (n, x) in points {
            let xe = exact(x);
            g.bench_with_input(BenchmarkId::new(format!("prec={prec}"), format!("n={n},x={x}")), &(n, x), |b, _| {
                b.iter(|| bessel_j::bessel_j_mp(black_box(n), &xe, prec).unwrap())
            });
        }
    }
    g.finish();
}

criterion_group! {
    name = benches;
    config = Criterion::default().sample_size(20).warm_up_time(std::time::Duration::from_millis(300)).measurement_time(std::time::Duration::from_secs(1));
    targets = bench_meijer, bench_hyp1f2, bench_hyp1f2_large, bench_hyp1f2_domain, bench_meijer_domain, bench_hyp2f1, bench_hyp2f1_large_param, bench_hyp2f1_f64, bench_bessel, bench_bessel_large, bench_bessel_f64
}
criterion_main!(benches);
