//! Zero integrals under the default absolute tolerance (issue 40, item 3): the first
//! call in a fresh process (Gauss-Legendre nodes built then) and the mean of warm
//! calls over 0.2 s, for `int_{-1}^1 sin x` and `int_{-3}^3 atan(tanh(tanh x))`, through
//! the expression integrator, at 64 and 333 bits. Prints id, prec, first ms, warm ms,
//! evaluations, goal met, the absolute tolerance met.
//!
//! `cargo run --release --example zero_integrals`

use std::time::Instant;

use maugis::quad::certified::{Integral, Options};
use maugis::quad::expr::{abs_tol_text, integrate_range, End, Expr};

fn once(f: &Expr, a: &End, b: &End, prec: u32) -> Integral {
    integrate_range(f, a, b, None, None, prec, &Options::new()).expect("integrate")
}

fn main() {
    let cases = [("sin", "sin(x)", "-1", "1"), ("atan_tanh_tanh", "atan(tanh(tanh(x)))", "-3", "3")];
    for prec in [64u32, 333] {
        for (id, f, a, b) in cases {
            let (f, a, b) = (Expr::parse(f).unwrap(), End::parse(a).unwrap(), End::parse(b).unwrap());
            let t = Instant::now();
            let first = once(&f, &a, &b, prec);
            let first_ms = t.elapsed().as_secs_f64() * 1e3;
            let t0 = Instant::now();
            let mut calls = 0u64;
            while t0.elapsed().as_secs_f64() < 0.2 {
                once(&f, &a, &b, prec);
                calls += 1;
            }
            let warm_ms = t0.elapsed().as_secs_f64() * 1e3 / calls as f64;
            println!("{id}\t{prec}\t{first_ms:.3}\t{warm_ms:.3}\t{}\t{}\t{}", first.evaluations, first.goal_met, abs_tol_text(&first).unwrap_or_default());
        }
    }
}
