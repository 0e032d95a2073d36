//! Warm calls of issue 36's integrals (the table of `examples/first_call.rs`) through
//! the expression integrator (`quad::expr::integrate_range`, as `maugis integrate` calls
//! it), a fixed number of them, for instruction counts under callgrind
//! (`reference/instructions_warm_calls.sh`): one warm-up call (the Gauss-Legendre rules
//! and the elementary functions' tables are built), then `CALLS` calls; the difference
//! of two runs with different `CALLS` is the cost of warm calls alone.
//!
//! `cargo run --release --example warm_calls -- ID PREC CALLS` prints `id prec
//! evaluations goal_met`; `MAUGIS_MAX_DEGREE=n` sets the largest degree (for the
//! degree cap's trade, `quad/certified/mod.rs`).

use maugis::quad::certified::Options;
use maugis::quad::expr::{integrate_range, End, Expr};

/// (id, integrand, a, b): the ids of `reference/arb_warm_calls.c`.
const TABLE: [(&str, &str, &str, &str); 6] = [
    ("atanderiv", "1/(1+x^2)", "0", "1"),
    ("rump", "sin(x + exp(x))", "0", "8"),
    ("gauss", "exp(-x^2)", "0", "2"),
    ("sqrt", "sqrt(x)", "1", "4"),
    ("xJ0", "x*besselj(0, x)", "0", "10"),
    ("sin_zero", "sin(x)", "-1", "1"),
];

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let [id, prec, calls] = &args[..] else {
        eprintln!("usage: warm_calls ID PREC CALLS");
        std::process::exit(2);
    };
    let (prec, calls): (u32, u32) = (prec.parse().expect("PREC"), calls.parse().expect("CALLS"));
    let (_, f, a, b) = TABLE.iter().find(|t| t.0 == id).expect("unknown id");
    let (f, a, b) = (Expr::parse(f).unwrap(), End::parse(a).unwrap(), End::parse(b).unwrap());
    let opts = match std::env::var("MAUGIS_MAX_DEGREE").ok().and_then(|v| v.parse().ok()) {
        Some(n) => Options::new().max_degree(n).expect("MAUGIS_MAX_DEGREE in 1..=2048"),
        None => Options::new(),
    };
    let run = || integrate_range(&f, &a, &b, None, None, prec, &opts).expect("integrate");
    let r = run();
    for _ in 0..calls {
        run();
    }
    println!("{id}\t{prec}\t{}\t{}", r.evaluations, r.goal_met);
}
