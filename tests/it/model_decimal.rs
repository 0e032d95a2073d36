//! The model's MP quantities at decimal inputs (issue 13): the strip ratio `m`
//! (first root of Eq. 15b, corrected) and the load (Eq. 14), with
//! `lambda, alpha, beta, abar` typed as decimals that become balls containing
//! them. The answer must contain the value at the decimals as typed; wide input
//! balls give wider balls that still contain every point; edges of the model's
//! domain inside an input ball are typed errors.
//!
//! References: `reference/data/model_decimal.csv` (mpmath from the decimal
//! strings at 700 and 900 bits, 100 digits; `model_decimal_rows` in
//! reference/generate.py).

use crate::common;

use maugis::ball::Decimal;
use maugis::contact::model::Params;
use maugis::contact::model_mp::{load_at_decimals, solve_m_ball_mp, solve_m_mp, strip_ratio_at_decimals, ModelBalls};
use maugis::Ball;
use rug::Float;

const REF_BITS: u32 = common::DECIMAL_REF_BITS;

fn decimals(args: [&str; 4]) -> [Decimal; 4] {
    args.map(|s| Decimal::parse(s).expect("decimal parses"))
}

fn reference(text: &str) -> Float {
    Float::with_val(REF_BITS, Float::parse(text).expect("reference parses"))
}

#[test]
fn decimal_probes_contain_m_and_the_load() {
    let rows = common::load("model_decimal");
    assert!(rows.len() >= 18, "{} rows", rows.len());
    let mut failures = Vec::new();
    let mut probes = 0;
    for row in &rows {
        let args = [&row["lambda"], &row["alpha"], &row["beta"], &row["abar"]].map(|s| s.as_str());
        let d = decimals(args);
        let (m_ref, load_ref) = (reference(&row["m"]), reference(&row["load"]));
        let abar = Float::with_val(64, d[3].as_rational());
        let hertz = Float::with_val(64, &abar * &abar) * Float::with_val(64, rug::float::Constant::Pi) / 4u32;
        for prec in [53, 128, 256] {
            probes += 2;
            match strip_ratio_at_decimals(&d, prec) {
                Ok(m) => {
                    if !common::contains_decimal_ref(&m, &m_ref, None) {
                        failures.push(format!("m{args:?} prec {prec}: {m:?} vs {}", m_ref.to_string_radix(10, Some(30))));
                    }
                    if !m.meets_rel(prec) {
                        failures.push(format!("m{args:?} prec {prec}: only {:.1} bits", m.rel_accuracy_bits()));
                    }
                }
                Err(e) => failures.push(format!("m{args:?} prec {prec}: {e}")),
            }
            match load_at_decimals(&d, prec) {
                Ok(l) => {
                    if !common::contains_decimal_ref(&l, &load_ref, Some(&hertz)) {
                        failures.push(format!("load{args:?} prec {prec}: {l:?} vs {}", load_ref.to_string_radix(10, Some(30))));
                    }
                    if !(l.meets_rel(prec) || l.meets_abs(prec, &hertz)) {
                        failures.push(format!("load{args:?} prec {prec}: only {:.1} bits", l.rel_accuracy_bits()));
                    }
                }
                Err(e) => failures.push(format!("load{args:?} prec {prec}: {e}")),
            }
        }
    }
    assert!(failures.is_empty(), "{} of {probes} probes failed:\n{}", failures.len(), failures[..failures.len().min(20)].join("\n"));
    eprintln!("{probes} model probes at typed decimals, 0 failures");
}

/// A ball `[m +- r]` from f64 (exact midpoint and radius).
fn ball(m: f64, r: f64) -> Ball {
    Ball::with_radius(Float::with_val(64, m), &Float::with_val(64, r))
}

#[test]
fn a_wide_input_ball_encloses_the_root_at_its_ends() {
    // Fig. 4c roughness, lambda = 1 +- 2^-20 at abar = 2.2: the ball of m must
    // contain the certified roots at both ends of the lambda ball, and be as
    // wide as the spread of m over the ball, not 2^-128.
    let (alpha, beta, abar) = (2f64.sqrt() / 4.0, 1.125, 2.2);
    let r = 2f64.powi(-20);
    let inputs = ModelBalls::new(ball(1.0, r), ball(alpha, 0.0), ball(beta, 0.0), ball(abar, 0.0)).unwrap();
    let m = solve_m_ball_mp(&inputs, 128).unwrap();
    let mut spread = Float::with_val(128, 0);
    let m_mid = solve_m_mp(Params::new(1.0, alpha, beta).unwrap(), abar, 128).unwrap();
    for lambda in [1.0 - r, 1.0 + r] {
        let end = solve_m_mp(Params::new(lambda, alpha, beta).unwrap(), abar, 128).unwrap();
        assert!(m.contains(&end.lower()) && m.contains(&end.upper()), "lambda {lambda}: {end:?} not in {m:?}");
        spread = spread.max(&Float::with_val(128, end.mid() - m_mid.mid()).abs());
    }
    assert!(spread > 0, "m does not depend on lambda?");
    // as tight as the inputs allow: within 4x of the spread of m over the ball
    assert!(m.rad() <= spread * 4u32, "{m:?} is much wider than the spread of m");
}

#[test]
fn edges_inside_the_input_balls_are_errors() {
    let (lam, alpha, beta, abar) = (ball(1.0, 0.0), ball(0.3, 0.0), ball(1.125, 0.0), ball(2.0, 0.0));
    let e = ModelBalls::new(lam.clone(), ball(0.0, 1e-30), beta.clone(), abar.clone()).unwrap_err().to_string();
    assert!(e.contains("alpha") && e.contains("input ball"), "{e}");
    let e = ModelBalls::new(lam.clone(), alpha.clone(), beta.clone(), ball(0.0, 1e-3)).unwrap_err().to_string();
    assert!(e.contains("abar"), "{e}");
    let e = ModelBalls::new(ball(1e6, 1e-3), alpha.clone(), beta.clone(), abar.clone()).unwrap_err().to_string();
    assert!(e.contains("lambda"), "{e}");
    let e = ModelBalls::new(lam.clone(), alpha.clone(), ball(0.0, 0.0), abar.clone()).unwrap_err().to_string();
    assert!(e.contains("beta"), "{e}");
    let nan = Ball::with_radius(Float::with_val(53, f64::NAN), &Float::new(53));
    assert!(ModelBalls::new(nan, alpha.clone(), beta.clone(), abar.clone()).is_err());
    // decimals typed at an edge
    for args in [["1", "0", "1.125", "0"], ["0", "0.3", "1.125", "2"], ["1", "-0.1", "1.125", "2"]] {
        let d = decimals(args);
        assert!(strip_ratio_at_decimals(&d, 64).is_err(), "{args:?}");
        assert!(load_at_decimals(&d, 64).is_err(), "{args:?}");
    }
}
