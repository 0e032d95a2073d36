//! Issue 37 item 3: no refusal that more precision would fix. Each registry
//! function is called through its MP path (what `maugis eval` and Python run) at
//! 2, 8, 12, 16 and 24 bits at decimals typed next to each of its edges, on the
//! inside: it must answer, and its ball must overlap the same function's ball at
//! 256 bits (a low precision may not move the enclosure). Before issue 37 the
//! inputs were rounded to the working precision first, which can put the edge
//! inside the ball: `meijer_g_k(0, 0.999999999999999)` and
//! `meijer_g_k(2000, 0.999999999999)` at 12 bits were refused with "sqrt argument
//! must lie in [0, inf) over its whole input ball". Edges that lie inside the
//! typed input are errors at every precision (`edges_inside_the_ball_are_errors_at_every_precision`
//! in src/special/hyp2f1/ball_input.rs and the domain tests).

use maugis::ball::Decimal;
use maugis::registry::{function, Answer, Arg, ParamKind};
use maugis::Ball;

fn call(name: &str, texts: &[&str], prec: u32) -> Result<Ball, String> {
    let f = function(name).unwrap();
    let args: Vec<Arg<Decimal>> = f
        .params
        .iter()
        .zip(texts)
        .map(|(p, s)| match p.kind {
            ParamKind::Integer => Arg::Int(s.parse().unwrap()),
            ParamKind::Real => Arg::Real(Decimal::parse(s).unwrap()),
        })
        .collect();
    match f.eval_mp(&args, prec) {
        Ok(Answer::Ball(b)) => Ok(b),
        Ok(Answer::SeriesBall { value, .. }) => Ok(value),
        Ok(other) => Err(format!("not a ball: {other:?}")),
        Err(e) => Err(format!("{e}")),
    }
}

/// Points next to an edge, on the domain's side (name, arguments, the edge).
const NEXT_TO_EDGES: &[(&str, &[&str], &str)] = &[
    ("meijer_g_k", &["0", "0.999999999999999"], "y = 1"),
    ("meijer_g_k", &["2000", "0.999999999999"], "y = 1"),
    ("meijer_g_k", &["2", "0.000000000001"], "y = 0"),
    ("meijer_g_k", &["7", "0.99999999999999999999"], "y = 1"),
    ("hyp2f1", &["0.5", "0.25", "-2.0000000001", "0.25"], "c = -2 (pole)"),
    ("hyp2f1", &["0.5", "0.25", "1.5", "0.999999999999999"], "z = 1"),
    ("hyp2f1", &["0.5", "0.25", "0.7500000001", "1"], "c - a - b = 0 at z = 1"),
    ("hyp2f1", &["1.5", "1000001", "24.741135219007653", "-0.5"], "a parameter of 10^6"),
    ("hyp1f2", &["0.5", "-3.0000000001", "1.5", "-2"], "b1 = -3 (pole)"),
    ("hyp1f2", &["0.5", "1", "0.0000000001", "-2"], "b2 = 0 (pole)"),
    ("bessel_j", &["3", "0.000000000001"], "x = 0"),
    ("u_wave", &["1", "0.7", "0.1", "1.000000000001"], "x = a"),
    ("du_wave", &["1", "0.7", "0.1", "1.000000000001"], "x = a"),
];

#[test]
fn next_to_each_edge_every_precision_answers() {
    let mut bad = Vec::new();
    for (name, texts, edge) in NEXT_TO_EDGES {
        let reference = match call(name, texts, 256) {
            Ok(b) => b,
            Err(e) => {
                bad.push(format!("{name}{texts:?} (next to {edge}) at 256 bits: {e}"));
                continue;
            }
        };
        for prec in [2u32, 8, 12, 16, 24] {
            match call(name, texts, prec) {
                Ok(b) if b.overlaps(&reference) => {}
                Ok(b) => bad.push(format!("{name}{texts:?} at {prec} bits: {b:?} misses the 256-bit {reference:?}")),
                Err(e) => bad.push(format!("{name}{texts:?} (next to {edge}) at {prec} bits: {e}")),
            }
        }
    }
    assert!(bad.is_empty(), "{} refusals or misses:\n{}", bad.len(), bad.join("\n"));
}
