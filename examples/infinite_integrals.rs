//! Issue 36's integrals to infinity (`reference/data/integrals_infinite.csv`, written by
//! `reference/generate_infinite_integrals.py`) through the expression integrator with no
//! declaration. Prints id, prec, first-call CPU ms, warm CPU ms (mean over 0.3 s of
//! CPU time, at least one call), evaluations, goal met, reference enclosed. CPU time
//! of the process (`CLOCK_PROCESS_CPUTIME_ID`): the machine is shared.
//!
//! `cargo run --release --example infinite_integrals [-- PREC... [--only ID]]`

use maugis::quad::certified::{Integral, Options};
use maugis::quad::expr::{integrate_range, End, Expr};
use maugis::rug::Float;

const CSV: &str = include_str!("../reference/data/integrals_infinite.csv");

/// CPU seconds of this process.
fn cpu() -> f64 {
    let mut ts = libc::timespec { tv_sec: 0, tv_nsec: 0 };
    // SAFETY: a valid pointer to a timespec owned by this frame.
    unsafe { libc::clock_gettime(libc::CLOCK_PROCESS_CPUTIME_ID, &mut ts) };
    ts.tv_sec as f64 + ts.tv_nsec as f64 * 1e-9
}

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

fn fields(line: &str) -> Vec<String> {
    let (mut out, mut cur, mut quoted) = (Vec::new(), String::new(), false);
    for c in line.chars() {
        match c {
            '"' => quoted = !quoted,
            ',' if !quoted => out.push(std::mem::take(&mut cur)),
            c => cur.push(c),
        }
    }
    out.push(cur);
    out
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let only = args.iter().position(|a| a == "--only").map(|i| args[i + 1].clone());
    let precs: Vec<u32> = args.iter().take_while(|a| !a.starts_with("--")).map(|p| p.parse().expect("prec")).collect();
    let precs = if precs.is_empty() { vec![64, 333] } else { precs };
    // --expr EXPR A B: one integral given on the command line (no reference)
    let extra = args.iter().position(|a| a == "--expr").map(|i| format!("expr,,\"{}\",{},{},0", args[i + 1], args[i + 2], args[i + 3]));
    let csv: Vec<&str> = match &extra {
        Some(line) => vec![line.as_str()],
        None => CSV.lines().skip(1).collect(),
    };
    println!("id\tprec\tfirst_cpu_ms\twarm_cpu_ms\tevaluations\tgoal_met\tencloses");
    for &prec in &precs {
        for line in &csv {
            let f = fields(line);
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
