//! Times one MP registry evaluation at decimal arguments as typed (issue 23h: the
//! slow `hyp2f1` corner at decimal parameters outside `1e-30..1e4`).
//! `cargo run --profile test --example hyp2f1_decimal_corner --features maugis/gmp-no-check -- FN PREC ARG...`
//! e.g. `-- hyp2f1 32 2.3241413192607027e1 22.787377894353547e-10537 -0.5 -1.235e2`.
use maugis::ball::Decimal;
use maugis::registry::{self, Arg, ParamKind};
use std::time::Instant;

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let f = registry::function(&args[0]).expect("a registry function name");
    let prec: u32 = args[1].parse().expect("a precision");
    let vals: Vec<Arg<Decimal>> = f
        .params
        .iter()
        .zip(&args[2..])
        .map(|(p, t)| match p.kind {
            ParamKind::Integer => Arg::Int(t.parse().expect("an integer")),
            ParamKind::Real => Arg::Real(Decimal::parse(t).expect("a decimal")),
        })
        .collect();
    let t = Instant::now();
    let r = f.eval_mp(&vals, prec);
    let took = t.elapsed().as_secs_f64();
    match r {
        Ok(a) => println!("{}({}) at {prec} bits = {a:?}  [{took:.3} s]", f.name, args[2..].join(", ")),
        Err(e) => println!("{}({}) at {prec} bits: error {e}  [{took:.3} s]", f.name, args[2..].join(", ")),
    }
}
