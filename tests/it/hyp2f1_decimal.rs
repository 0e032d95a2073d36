//! 2F1 at decimal inputs: each decimal string becomes a ball that contains it,
//! and the answer contains 2F1 at the decimals as typed, next to z = 1 and next
//! to c - a - b = 0; edges inside the input balls are typed errors at every
//! precision.
//!
//! References: `reference/data/hyp2f1_decimal.csv` (mpmath from the decimal
//! strings at 1000 and 1300 bits, 100 digits; `hyp2f1_decimal_rows` in
//! reference/generate.py).

use crate::common;

use maugis::ball::{eval_at_decimals, Decimal};
use maugis::special::hyp2f1::hyp2f1_ball_mp;
use maugis::{Ball, Error, Result};
use rug::Float;

const REF_BITS: u32 = common::DECIMAL_REF_BITS;

/// What `maugis eval` runs for `{"fn": "hyp2f1", ..., "prec": prec}`.
fn at_decimals(a: &str, b: &str, c: &str, z: &str, prec: u32) -> Result<Ball> {
    let d: Vec<Decimal> = [a, b, c, z].iter().map(|s| Decimal::parse(s).expect("decimal parses")).collect();
    eval_at_decimals(&d, prec, |x| hyp2f1_ball_mp(&x[0], &x[1], &x[2], &x[3], prec))
}

#[test]
fn decimal_probes_contain_the_value_at_the_decimals() {
    let rows = common::load("hyp2f1_decimal");
    assert!(rows.len() >= 100, "{} rows", rows.len());
    let mut probes = 0;
    let mut failures = Vec::new();
    for row in &rows {
        let (a, b, c, z) = (&row["a"], &row["b"], &row["c"], &row["z"]);
        let r = Float::with_val(REF_BITS, Float::parse(&row["value"]).unwrap());
        for prec in [53, 128, 256] {
            probes += 1;
            match at_decimals(a, b, c, z, prec) {
                Ok(ball) => {
                    if !common::contains_decimal_ref(&ball, &r, None) {
                        failures.push(format!("({a}, {b}; {c}; {z}) prec {prec}: {ball:?} vs {}", r.to_string_radix(10, Some(30))));
                    }
                    if !ball.meets_rel(prec) {
                        failures.push(format!("({a}, {b}; {c}; {z}) prec {prec}: only {:.1} bits", ball.rel_accuracy_bits()));
                    }
                }
                Err(e) => failures.push(format!("({a}, {b}; {c}; {z}) prec {prec}: {e}")),
            }
        }
    }
    assert!(failures.is_empty(), "{} of {probes} probes failed:\n{}", failures.len(), failures[..failures.len().min(20)].join("\n"));
    eprintln!("{probes} 2F1 probes at typed decimals, 0 failures");
}

#[test]
fn edges_inside_the_input_balls_are_errors() {
    for prec in [2, 24, 53, 64, 113, 128, 256, 512] {
        // c - a - b = 0 at z = 1 (issue 13's request): may diverge.
        let e = at_decimals("0.3", "0.7", "1", "1", prec).unwrap_err();
        assert!(matches!(e, Error::Divergent { needs: "c - a - b > 0 over the whole ball", .. }), "prec {prec}: {e:?}");
        // c - a - b < 0 at z = 1: diverges.
        let e = at_decimals("0.3", "0.7", "0.99999999999999999999", "1", prec).unwrap_err();
        assert!(matches!(e, Error::Divergent { needs: "c - a - b > 0", .. }), "prec {prec}: {e:?}");
        assert!(e.to_string().contains("diverges"), "prec {prec}: {e}");
        // c a pole, typed exactly.
        let e = at_decimals("0.3", "0.7", "-3", "0.5", prec).unwrap_err();
        assert!(matches!(e, Error::ParameterPole { arg: "c", pole: -3.0, .. }), "prec {prec}: {e:?}");
        assert!(e.to_string().contains("pole"), "prec {prec}: {e}");
        // the branch cut
        let e = at_decimals("0.3", "0.7", "1.5", "1.00000000000000000001", prec).unwrap_err();
        assert!(matches!(e, Error::OutOfRange { arg: "z", .. } | Error::BallOutOfRange { arg: "z", .. }), "prec {prec}: {e:?}");
    }
}

#[test]
fn issue_requests_enclose_the_value_at_the_decimal() {
    // {"fn":"hyp2f1","a":"1","b":"2","c":"2","z":"0.99999999999999999999","prec":53}: exactly 1e20.
    let b = at_decimals("1", "2", "2", "0.99999999999999999999", 53).unwrap();
    assert!(b.contains(&Float::with_val(100, 1e20)) && b.meets_rel(53), "{b:?}");
    // Binary-fraction inputs stay exact: the same ball as the exact-input function.
    let exact = maugis::special::hyp2f1::hyp2f1_mp(
        &Float::with_val(53, 0.375),
        &Float::with_val(53, 1.5),
        &Float::with_val(53, 2.25),
        &Float::with_val(53, -0.75),
        128,
    )
    .unwrap();
    let typed = at_decimals("0.375", "1.5", "2.25", "-0.75", 128).unwrap();
    // The ball-input path may take another route than the exact-input one, so the
    // midpoints may differ below 2^-128; the balls must overlap, and the typed
    // answer must lose nothing: full precision, radius within 2x of the exact path.
    assert!(typed.overlaps(&exact), "{typed:?} vs {exact:?}");
    assert!(typed.meets_rel(128), "{typed:?}");
    assert!(typed.rad() <= Float::with_val(53, exact.rad() * 2u32), "{typed:?} vs {exact:?}");
}
