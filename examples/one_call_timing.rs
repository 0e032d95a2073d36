//! Times one registry MP call under a budget: `cargo run --example one_call_timing --
//! NAME PREC BUDGET_MS ARG...` (decimals as typed; integers for integer parameters).
//! Prints the answer or the refusal, the wall time and the thread's CPU time
//! (issue 37's slow-input scan; on the shared machine the wall time swings with
//! the other builds' load, the CPU time much less).
use maugis::budget::thread_cpu_seconds;
use maugis::ball::Decimal;
use maugis::registry::{self, Arg, ParamKind};

fn main() {
    let a: Vec<String> = std::env::args().skip(1).collect();
    if a.len() < 3 {
        eprintln!("usage: one_call_timing NAME PREC BUDGET_MS ARG...");
        std::process::exit(2);
    }
    let f = registry::function(&a[0]).unwrap_or_else(|e| panic!("{e}"));
    let prec: u32 = a[1].parse().expect("PREC");
    let budget = maugis::Budget::from_millis(a[2].parse().expect("BUDGET_MS")).expect("budget");
    let args: Vec<Arg<Decimal>> = f
        .params
        .iter()
        .zip(&a[3..])
        .map(|(p, t)| match p.kind {
            ParamKind::Integer => Arg::Int(t.parse().expect("integer")),
            ParamKind::Real => Arg::Real(Decimal::parse(t).expect("decimal")),
        })
        .collect();
    for round in 0..2 {
        let (t0, c0) = (std::time::Instant::now(), thread_cpu_seconds());
        let r = f.eval_mp_with_budget(&args, prec, budget);
        println!("round {round}: {:.4} s (CPU {:.4} s): {r:?}", t0.elapsed().as_secs_f64(), thread_cpu_seconds() - c0);
    }
}

