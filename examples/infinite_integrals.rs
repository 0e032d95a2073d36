//! Issue 36's integrals to infinity (`reference/data/integrals_infinite.csv`, written by
//! `reference/generate_infinite_integrals.py`) through the expression integrator with no
//! declaration. Prints id, prec, first-call CPU ms, warm CPU ms (mean over 0.3 s of
//! CPU time, at least one call), evaluations, goal met, reference enclosed. CPU time
//! of the calling thread ([`maugis::budget::thread_cpu_seconds`]): the machine is shared.
//!
//! `cargo run --release --example infinite_integrals [-- PREC... [--only ID]]`

use maugis::budget::thread_cpu_seconds as cpu;
use maugis::quad::certified::{Integral, Options};
use maugis::quad::expr::{integrate_range, End, Expr};
use maugis::rug::Float;

const CSV: &str = include_str!("../reference/data/integrals_infinite.csv");

/// Warm mean in CPU ms over 0.3 s (at least one call).
fn warm(run: &dyn Fn() -> Integral) -> f64 {
    let t = cpu();
    let mut calls = 0u32;
    while calls < 1 || cpu() - t < 0.3 {
        run();
        calls += 1;
    }
    (cpu() - t) * 1e3 / calls as f64
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let only = args.iter().position(|a| a == "--only").map(|i| args[i + 1].clone());
    let precs: Vec<u32> = args.iter().take_while(|a| !a.starts_with("--")).map(|p| p.parse().expect("prec")).collect();
    let precs = if precs.is_empty() { vec![64, 333] } else { precs };
    // --expr EXPR A B: one integral given on the command line (no reference)
    let extra = args.iter().position(|a| a == "--expr").map(|i| format!("expr,,\"{}\",{},{},0", args[i + 1], args[i + 2], args[i + 3]));
    // the reference table's rows (or the one from --expr), read by the csv crate
    let table = match &extra {
        Some(line) => format!("id,description,expression,a,b,value\n{line}\n"),
        None => CSV.to_string(),
    };
    let rows: Vec<csv::StringRecord> = csv::Reader::from_reader(table.as_bytes()).records().map(|r| r.expect("a row of the table")).collect();
    println!("id\tprec\tfirst_cpu_ms\twarm_cpu_ms\tevaluations\tgoal_met\tencloses");
    for &prec in &precs {
        for f in &rows {
            let (id, expr, a, b, value) = (&f[0], &f[2], &f[3], &f[4], &f[5]);
            if only.as_ref().is_some_and(|o| !id.starts_with(o.as_str())) {
                continue;
            }
            let (e, a, b) = (Expr::parse(expr).unwrap(), End::parse(a).unwrap(), End::parse(b).unwrap());
            let want = Float::with_val(1400, Float::parse(value).unwrap());
            let run = || integrate_range(&e, &a, &b, None, None, prec, &Options::new()).expect("integrate");
            let t = cpu();
            let r = run();
            let first = (cpu() - t) * 1e3;
            let warm_ms = if first < 5000.0 { format!("{:.3}", warm(&run)) } else { "-".into() };
            println!("{id}\t{prec}\t{first:.2}\t{warm_ms}\t{}\t{}\t{}", r.evaluations, r.goal_met, r.real().contains(&want));
        }
    }
}
