//! 1F2, G(k, y), u_w and du_w/dx at decimal inputs: each decimal string becomes
//! a ball that contains it, and the answer contains the function at the
//! decimals as typed (Arb's convention), near poles of 1F2, next to y = 1 for
//! G, and at the contact edge x = a for u_w with a wavelength that is not a
//! binary fraction. Edges inside the input balls are typed errors.
//!
//! References: `reference/data/ball_inputs_decimal.csv` (mpmath from the
//! decimal strings at 1000 and 1300 bits, 100 digits; `ball_decimal_rows` in
//! reference/generate.py).

use crate::common;

use maugis::ball::{eval_at_decimals, Decimal};
use maugis::contact::displacement::{
    du_wave_at_edge_ball_mp, du_wave_ball_mp, du_wave_mp, u_wave_at_edge_ball_mp, u_wave_ball_mp, u_wave_mp,
    wave_at_decimals,
};
use maugis::special::hyp1f2::{hyp1f2_ball_mp, hyp1f2_mp};
use maugis::special::meijer_g::{meijer_g_k_ball_mp, meijer_g_k_mp};
use maugis::{Ball, Result};
use rug::Float;

const REF_BITS: u32 = common::DECIMAL_REF_BITS;

fn decimals(args: &[&str]) -> Vec<Decimal> {
    args.iter().map(|s| Decimal::parse(s).expect("decimal parses")).collect()
}

/// The wave functions' accuracy floor: |A| for u_w, 6 |A| / zeta for du_w.
fn wave_floor(fname: &str, d: &[Decimal]) -> Float {
    let amp = Float::with_val(64, d[2].as_rational()).abs();
    if fname == "u_wave" {
        amp
    } else {
        amp * 6u32 / Float::with_val(64, d[1].as_rational())
    }
}

/// What `maugis eval` runs for `{"fn": fname, ..., "prec": prec}`, and the
/// scale the accuracy promise refers to (`None`: relative).
fn at_decimals(fname: &str, args: &[&str], prec: u32) -> (Result<Ball>, Option<Float>) {
    let d = decimals(args);
    match fname {
        "hyp1f2" => (eval_at_decimals(&d, prec, |x| hyp1f2_ball_mp(&x[0], &x[1], &x[2], &x[3], prec)), None),
        "meijer_g_k" => {
            let k: u32 = args[0].parse().expect("k");
            (eval_at_decimals(&d[1..], prec, |x| meijer_g_k_ball_mp(k, &x[0], prec)), None)
        }
        "u_wave" | "du_wave" => {
            let d: [Decimal; 4] = d.try_into().expect("four wave arguments");
            (wave_at_decimals(&d, prec, fname == "du_wave"), Some(wave_floor(fname, &d)))
        }
        other => panic!("unknown fn {other}"),
    }
}

#[test]
fn decimal_probes_contain_the_value_at_the_decimals() {
    let rows = common::load("ball_inputs_decimal");
    assert!(rows.len() >= 100, "{} rows", rows.len());
    let mut probes = 0;
    let mut failures = Vec::new();
    let mut per_fn = std::collections::BTreeMap::new();
    for row in &rows {
        let fname = row["fn"].as_str();
        let args: Vec<&str> = row["args"].split_whitespace().collect();
        let r = Float::with_val(REF_BITS, Float::parse(&row["value"]).expect("reference parses"));
        for prec in [53, 128, 256] {
            probes += 1;
            *per_fn.entry(fname.to_string()).or_insert(0) += 1;
            let (out, scale) = at_decimals(fname, &args, prec);
            match out {
                Ok(ball) => {
                    if !common::contains_decimal_ref(&ball, &r, scale.as_ref()) {
                        failures.push(format!("{fname}{args:?} prec {prec}: {ball:?} vs {}", r.to_string_radix(10, Some(30))));
                    }
                    let accurate = ball.meets_rel(prec) || scale.as_ref().is_some_and(|s| ball.meets_abs(prec, s));
                    if !accurate {
                        failures.push(format!("{fname}{args:?} prec {prec}: only {:.1} bits", ball.rel_accuracy_bits()));
                    }
                }
                Err(e) => failures.push(format!("{fname}{args:?} prec {prec}: {e}")),
            }
        }
    }
    assert!(failures.is_empty(), "{} of {probes} probes failed:\n{}", failures.len(), failures[..failures.len().min(20)].join("\n"));
    for f in ["hyp1f2", "meijer_g_k", "u_wave", "du_wave"] {
        assert!(per_fn.get(f).copied().unwrap_or(0) >= 30, "too few {f} probes: {per_fn:?}");
    }
    eprintln!("{probes} probes at typed decimals ({per_fn:?}), 0 failures");
}

/// A ball `[m +- r]` from f64 (exact midpoint and radius).
fn ball(m: f64, r: f64) -> Ball {
    Ball::with_radius(Float::with_val(64, m), &Float::with_val(64, r))
}

#[test]
fn edges_inside_the_input_balls_are_errors() {
    let half = ball(0.5, 0.0);
    let z = ball(-3.0, 0.0);
    // a pole of 1F2: b1 = -2 inside [-2 - 1e-20, -2 + 1e-20]
    let e = hyp1f2_ball_mp(&half, &ball(-2.0, 1e-20), &ball(1.5, 0.0), &z, 64).unwrap_err().to_string();
    assert!(e.contains("pole") && e.contains("b1"), "{e}");
    let e = hyp1f2_ball_mp(&half, &ball(1.5, 0.0), &ball(0.0, 1e-9), &z, 64).unwrap_err().to_string();
    assert!(e.contains("pole") && e.contains("b2"), "{e}");
    // but the series that terminates before the pole is fine: 1F2(-1; -3 +- eps, 1; 3) = 1 - 3/b1 = 2
    let b = hyp1f2_ball_mp(&ball(-1.0, 0.0), &ball(-3.0, 1e-20), &ball(1.0, 0.0), &ball(3.0, 0.0), 64).unwrap();
    assert!(b.contains(&Float::with_val(64, 2)), "{b:?}");
    // G: y = 0 and y > 1 inside the ball
    for y in [ball(0.0, 1e-9), ball(1.0, 1e-20), ball(1.5, 0.1)] {
        assert!(meijer_g_k_ball_mp(3, &y, 64).is_err(), "{y:?}");
    }
    // the contact edge x = a inside the balls: du_w is one-sided there, u_w undefined for x < a
    let (a, zeta, amp) = (ball(1.25, 1e-30), ball(0.25, 1e-30), ball(1.0, 0.0));
    let x = ball(1.25, 2e-30);
    let e = du_wave_ball_mp(&a, &zeta, &amp, &x, 64).unwrap_err().to_string();
    assert!(e.contains("contact edge x = a") && e.contains("one-sided"), "{e}");
    let e = u_wave_ball_mp(&a, &zeta, &amp, &x, 64).unwrap_err().to_string();
    assert!(e.contains("contact edge x = a"), "{e}");
    assert!(u_wave_ball_mp(&a, &zeta, &amp, &ball(1.0, 0.0), 64).unwrap_err().to_string().contains("x >= a"));
    assert!(u_wave_ball_mp(&a, &ball(0.0, 1e-3), &amp, &ball(2.0, 0.0), 64).is_err());
    // at the edge itself (x the same number as a) both answer
    assert!(u_wave_at_edge_ball_mp(&a, &zeta, &amp, 64).is_ok());
    assert!(du_wave_at_edge_ball_mp(&a, &zeta, &amp, 64).is_ok());
}

#[test]
fn issue_request_u_wave_at_the_edge_is_zero() {
    // {"fn":"u_wave","a":"50","zeta":"0.1","amp":"1","x":"50","prec":128}:
    // u_w(a) = 1 - cos(1000 pi) = 0 at the decimal zeta = 0.1 (the binary
    // neighbour of 0.1 gives 7.8e-111, and a ball that excludes 0).
    for prec in [53, 128, 256] {
        let (b, floor) = at_decimals("u_wave", &["50", "0.1", "1", "50"], prec);
        let b = b.unwrap();
        assert!(b.contains(&Float::new(64)), "prec {prec}: {b:?}");
        assert!(b.meets_abs(prec, floor.as_ref().unwrap()), "prec {prec}: {b:?}");
    }
}

#[test]
fn binary_fraction_inputs_lose_nothing() {
    let f = |v: f64| Float::with_val(64, v);
    let e = |v: f64| Ball::from_float(&f(v), 64);
    for prec in [53, 200] {
        let exact = hyp1f2_mp(&f(0.5), &f(1.0), &f(1.5), &f(-300.0), prec).unwrap();
        let via = hyp1f2_ball_mp(&e(0.5), &e(1.0), &e(1.5), &e(-300.0), prec).unwrap();
        assert_eq!(exact.mid(), via.mid());
        assert_eq!(exact.rad(), via.rad());
        let exact = meijer_g_k_mp(7, &f(0.375), prec).unwrap();
        let via = meijer_g_k_ball_mp(7, &e(0.375), prec).unwrap();
        assert_eq!(exact.rad(), via.rad());
        let exact = u_wave_mp(&f(1.5), &f(1.125), &f(0.25), &f(2.5), prec).unwrap();
        let via = u_wave_ball_mp(&e(1.5), &e(1.125), &e(0.25), &e(2.5), prec).unwrap();
        assert_eq!(exact.rad(), via.rad());
        let exact = du_wave_mp(&f(1.5), &f(1.125), &f(0.25), &f(1.5), prec).unwrap();
        let via = du_wave_at_edge_ball_mp(&e(1.5), &e(1.125), &e(0.25), prec).unwrap();
        assert!(exact.overlaps(&via), "{exact:?} vs {via:?}");
    }
}
