//! The first call of a certified integral in a fresh process (the Gauss-Legendre
//! rules are built then) against the warm call, for the integrals of issue 36's
//! table, through the expression integrator (`quad::expr::integrate_range`, as
//! `maugis integrate` calls it).
//!
//! `cargo run --release --example first_call -- ID PREC` prints `id prec first_ms
//! warm_ms evaluations`; without arguments it runs every (id, prec) of the table, each
//! in a fresh process of itself (the first call must not find rules of an earlier one).
//! `first_call rule N PREC` prints the wall milliseconds of building one Gauss-Legendre
//! rule (degree `N`, `PREC`-bit balls) in a fresh process (under load, count its CPU
//! time with `perf stat -e task-clock`).
//! `first_call ID PREC CALLS` runs a warm-up call and then `CALLS` more, untimed, and
//! prints `id prec evaluations goal_met`: for instruction counts of warm calls under
//! callgrind (`reference/instructions_warm_calls.sh`: the difference of two runs with
//! different `CALLS`). `MAUGIS_MAX_DEGREE=n` sets the largest degree (for the degree
//! cap's trade, `quad/certified/mod.rs`).

use std::process::Command;
use std::time::Instant;

use maugis::quad::certified::Options;
use maugis::quad::expr::{integrate_range, End, Expr};

const TABLE: [(&str, &str, &str, &str, &[u32]); 6] = [
    ("atanderiv", "1/(1+x^2)", "0", "1", &[64, 333, 3333]),
    ("rump", "sin(x + exp(x))", "0", "8", &[64, 333]),
    ("gauss", "exp(-x^2)", "0", "2", &[333, 3333]),
    ("sqrt", "sqrt(x)", "1", "4", &[3333]),
    ("xJ0", "x*besselj(0, x)", "0", "10", &[3333]),
    ("sin_zero", "sin(x)", "-1", "1", &[64, 333]),
];

fn one(id: &str, prec: u32, warm_calls: Option<u32>) {
    let (_, f, a, b, _) = TABLE.iter().find(|t| t.0 == id).expect("unknown id");
    let (f, a, b) = (Expr::parse(f).unwrap(), End::parse(a).unwrap(), End::parse(b).unwrap());
    let opts = match std::env::var("MAUGIS_MAX_DEGREE").ok().and_then(|v| v.parse().ok()) {
        Some(n) => Options::new().max_degree(n).expect("MAUGIS_MAX_DEGREE in 1..=2048"),
        None => Options::new(),
    };
    let run = || integrate_range(&f, &a, &b, None, None, prec, &opts).expect("integrate");
    if let Some(calls) = warm_calls {
        let r = run();
        for _ in 0..calls {
            run();
        }
        println!("{id}\t{prec}\t{}\t{}", r.evaluations, r.goal_met);
        return;
    }
    let t = Instant::now();
    let r = run();
    let first = t.elapsed().as_secs_f64() * 1e3;
    if std::env::var_os("FIRST_CALL_ONLY").is_some() {
        println!("{id}\t{prec}\t{first:.2}");
        return;
    }
    let t = Instant::now();
    let mut calls = 0u32;
    while calls < 3 || t.elapsed().as_secs_f64() < 0.3 {
        run();
        calls += 1;
    }
    let warm = t.elapsed().as_secs_f64() * 1e3 / calls as f64;
    println!("{id}\t{prec}\t{first:.2}\t{warm:.3}\t{}\t{}", r.evaluations, r.goal_met);
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    if args.len() == 3 && args[0] == "rule" {
        let (n, prec) = (args[1].parse().expect("degree"), args[2].parse().expect("prec"));
        let t = Instant::now();
        maugis::quad::certified::build_gauss_legendre_rule(n, prec).expect("rule");
        println!("rule\t{n}\t{prec}\t{:.2}", t.elapsed().as_secs_f64() * 1e3);
        return;
    }
    if args.len() == 2 || args.len() == 3 {
        let calls = args.get(2).map(|c| c.parse().expect("CALLS"));
        one(&args[0], args[1].parse().expect("prec"), calls);
        return;
    }
    let me = std::env::current_exe().expect("current_exe");
    println!("id\tprec\tfirst_ms\twarm_ms\tevaluations\tgoal_met");
    for (id, _, _, _, precs) in TABLE {
        for &p in precs {
            let out = Command::new(&me).args([id, &p.to_string()]).output().expect("run");
            print!("{}", String::from_utf8_lossy(&out.stdout));
        }
    }
}
