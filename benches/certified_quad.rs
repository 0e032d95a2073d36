//! Criterion benchmarks of the certified integrator on the analytic integrals of the
//! speed comparison against C Arb (reference/arb_integrals.c,
//! reference/bench_integrals.sh, docs/quadrature.md "Speed against Arb"), at 64 and
//! 333 bits. Nodes are cached by the warm-up iterations, as in the comparison.
//! x J_0(x) is left out: it takes seconds per call (see docs/quadrature.md).

use criterion::{black_box, criterion_group, criterion_main, BenchmarkId, Criterion};
use maugis::ball::Ball;
use maugis::quad::certified::{integrate, HoloBall, Options};

type F = fn(&HoloBall) -> HoloBall;

const INTEGRALS: [(&str, F, i64, i64); 5] = [
    ("atanderiv", |x| (x.sqr() + x.int(1)).recip(), 0, 1),
    ("rump", |x| (x.exp() + x).sin(), 0, 8),
    ("exp", |x| x.exp(), 0, 1),
    ("sqrt", |x| x.sqrt(), 1, 4),
    ("sin100", |x| x.sin(), 0, 100),
];

fn bench_certified(c: &mut Criterion) {
    let mut g = c.benchmark_group("certified_quad");
    g.sample_size(10);
    for prec in [64u32, 333] {
        for (id, f, a, b) in INTEGRALS {
            let (a, b) = (Ball::from_i64(a, prec), Ball::from_i64(b, prec));
            let o = Options::new();
            g.bench_with_input(BenchmarkId::new(id, prec), &prec, |bench, &p| {
                bench.iter(|| integrate(f, black_box(&a), black_box(&b), p, &o).unwrap())
            });
        }
    }
    g.finish();
}

/// Integrals that need no declaration (issue 36): infinite ranges with the tail bound
/// from the expression, oscillatory tails on rotated rays, singular ends found from the
/// expression. Warm calls, 64 and 333 bits; docs/quadrature.md has the table.
fn bench_undeclared(c: &mut Criterion) {
    use maugis::quad::expr::{integrate_range, End, Expr};
    let mut g = c.benchmark_group("certified_quad_undeclared");
    g.sample_size(10);
    let cases = [
        ("exp_over_1px", "exp(-x)/(1+x)", "0", "inf"),
        ("x2_gauss", "x^2*exp(-x^2)", "-inf", "inf"),
        ("lorentz", "1/(1+x^2)", "0", "inf"),
        ("sinc", "sin(x)/x", "0", "inf"),
        ("j0", "besselj(0, x)", "0", "inf"),
        ("cos_lorentz", "cos(x)/(1+x^2)", "0", "inf"),
        ("rsqrt_cos", "x^(-1/2)*cos(x)", "0", "1"),
        ("log", "log(x)", "0", "1"),
    ];
    for prec in [64u32, 333] {
        for (id, text, a, b) in cases {
            let f = Expr::parse(text).unwrap();
            let (a, b) = (End::parse(a).unwrap(), End::parse(b).unwrap());
            let o = Options::new();
            g.bench_with_input(BenchmarkId::new(id, prec), &prec, |bench, &p| {
                bench.iter(|| integrate_range(black_box(&f), &a, &b, None, None, p, &o).unwrap())
            });
        }
    }
    g.finish();
}

criterion_group!(benches, bench_certified, bench_undeclared);
criterion_main!(benches);
