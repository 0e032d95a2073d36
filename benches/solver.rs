//! Criterion benchmarks of the Maugis solver (Fig. 4c roughness):
//! the first-root solve for m, one validity check, and one 600-point curve
//! (rayon over grid points; run with RAYON_NUM_THREADS=1 for the one-core figure).

use criterion::{black_box, criterion_group, criterion_main, Criterion};
use maugis::contact::curve::{load_area_curve, CurveOptions};
use maugis::contact::model::{ContactSize, Params};

fn params(lambda: f64) -> Params {
    Params::new(lambda, 2f64.sqrt() / 4.0, 1.125).unwrap()
}

fn bench_solver(c: &mut Criterion) {
    for &lambda in &[0.1, 1.0, 6.0] {
        let p = params(lambda);
        c.bench_function(&format!("solve_m/lambda={lambda},abar=3"), |b| {
            b.iter(|| ContactSize::new(p, black_box(3.0)).unwrap().solve_m().unwrap())
        });
        let cs = ContactSize::new(p, 3.0).unwrap();
        let m = cs.solve_m().unwrap();
        c.bench_function(&format!("validity/lambda={lambda},abar=3"), |b| b.iter(|| cs.validity(black_box(m)).unwrap()));
        c.bench_function(&format!("curve_600/lambda={lambda}"), |b| {
            b.iter(|| load_area_curve(p, CurveOptions::default()).unwrap())
        });
    }
}

criterion_group! {
    name = benches;
    config = Criterion::default().sample_size(10).warm_up_time(std::time::Duration::from_millis(300)).measurement_time(std::time::Duration::from_secs(2));
    targets = bench_solver
}
criterion_main!(benches);
