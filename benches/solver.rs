//! Criterion benchmarks of the Maugis solver (Fig. 4c roughness):
//! the first-root solve for m, one validity check, and one 600-point curve
//! (rayon over grid points; run with RAYON_NUM_THREADS=1 for the one-core figure).
//!
//! Group `waves` (issue 35): a 600-state curve of a profile of many waves against
//! each of its waves alone on the cylinder, at lambda = 3, for the Fig. 4c wave plus
//! a wave of a third of its wavelength and half its amplitude, and for the 4-scale
//! Weierstrass profile (gamma = 2, H = 1/2) below the Fig. 4c wave. The target: the
//! N-wave curve costs at most 1.3 times the sum of the one-wave curves
//! (docs/performance.md).

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

fn bench_waves(c: &mut Criterion) {
    use maugis::contact::profile::WavyProfile;
    let (alpha, beta) = (2f64.sqrt() / 4.0, 1.125);
    let profiles = [
        ("two_waves", WavyProfile::from_pairs(&[(alpha, beta), (alpha / 2.0, beta / 3.0)]).unwrap()),
        ("weierstrass_4", WavyProfile::weierstrass(alpha, beta, 4, 2.0, 0.5).unwrap()),
    ];
    let lambda = 3.0;
    for (name, profile) in profiles {
        let p = Params::with_profile(lambda, profile).unwrap();
        c.bench_function(&format!("waves/curve_600/{name}/all"), |b| b.iter(|| load_area_curve(p, CurveOptions::default()).unwrap()));
        for (j, w) in profile.waves().iter().enumerate() {
            let one = Params::new(lambda, w.alpha(), w.beta()).unwrap();
            c.bench_function(&format!("waves/curve_600/{name}/wave_{}", j + 1), |b| {
                b.iter(|| load_area_curve(one, CurveOptions::default()).unwrap())
            });
        }
    }
}

criterion_group! {
    name = benches;
    config = Criterion::default().sample_size(10).warm_up_time(std::time::Duration::from_millis(300)).measurement_time(std::time::Duration::from_secs(2));
    targets = bench_solver, bench_waves
}
criterion_main!(benches);
