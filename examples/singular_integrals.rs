//! Issue 40's finite integrals (`reference/data/integrals_singular.csv`, written by
//! `reference/generate_finite_singular.py`) through the expression integrator with no
//! declaration, at 53, 64, 333 and 1000 bits, and the same integrals with a declared
//! weight where one applies. Prints id, prec, first-call ms, warm ms (mean over 0.2 s,
//! at least one call; skipped when the first call took over 3 s), evaluations, goal
//! met, reference enclosed, and the declared-weight warm ms.
//!
//! `cargo run --release --example singular_integrals [-- PREC...]`

use std::time::Instant;

use maugis::ball::Decimal;
use maugis::quad::certified::{Integral, Options};
use maugis::quad::expr::{integrate_range, End, Expr, WeightSpec};
use maugis::rug::Float;

const CSV: &str = include_str!("../reference/data/integrals_singular.csv");

/// The declared-weight form of an integral: `(g, alpha, beta, log)`.
fn declared(id: &str) -> Option<(&'static str, Option<&'static str>, Option<&'static str>, u32)> {
    match id {
        "log" => Some(("1", None, None, 1)),
        "rsqrt" => Some(("1", Some("-0.5"), None, 0)),
        "sqrt" => Some(("1", Some("0.5"), None, 0)),
        "rsqrt_cos" => Some(("cos(x)", Some("-0.5"), None, 0)),
        "rsqrt_both" => Some(("1", Some("-0.5"), Some("-0.5"), 0)),
        _ => None,
    }
}

/// Warm mean in ms over 0.2 s (at least one call).
fn warm(run: &dyn Fn() -> Integral) -> f64 {
    let t = Instant::now();
    let mut calls = 0u32;
    while calls < 1 || t.elapsed().as_secs_f64() < 0.2 {
        run();
        calls += 1;
    }
    t.elapsed().as_secs_f64() * 1e3 / calls as f64
}

fn main() {
    let precs: Vec<u32> = std::env::args().skip(1).map(|p| p.parse().expect("prec")).collect();
    let precs = if precs.is_empty() { vec![53, 64, 333, 1000] } else { precs };
    println!("id\tprec\tfirst_ms\twarm_ms\tevaluations\tgoal_met\tencloses\tdeclared_warm_ms");
    for &prec in &precs {
        for line in CSV.lines().skip(1) {
            let f: Vec<&str> = line.split(',').collect();
            let (id, expr, a, b, value) = (f[0], f[f.len() - 4], f[f.len() - 3], f[f.len() - 2], f[f.len() - 1]);
            let (e, a, b) = (Expr::parse(expr).unwrap(), End::parse(a).unwrap(), End::parse(b).unwrap());
            let want = Float::with_val(1400, Float::parse(value).unwrap());
            let run = || integrate_range(&e, &a, &b, None, None, prec, &Options::new()).expect("integrate");
            let t = Instant::now();
            let r = run();
            let first = t.elapsed().as_secs_f64() * 1e3;
            let warm_ms = if first < 3000.0 { format!("{:.3}", warm(&run)) } else { "-".into() };
            let declared_ms = declared(id).map(|(g, alpha, beta, log)| {
                let g = Expr::parse(g).unwrap();
                let w = WeightSpec { alpha: alpha.map(|s| Decimal::parse(s).unwrap()), beta: beta.map(|s| Decimal::parse(s).unwrap()), log };
                let run = || integrate_range(&g, &a, &b, Some(&w), None, prec, &Options::new()).expect("declared");
                run();
                format!("{:.3}", warm(&run))
            });
            println!(
                "{id}\t{prec}\t{first:.2}\t{warm_ms}\t{}\t{}\t{}\t{}",
                r.evaluations,
                r.goal_met,
                r.real().contains(&want),
                declared_ms.unwrap_or_else(|| "-".into())
            );
        }
    }
}
