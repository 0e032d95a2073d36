//! Issue 37: the model at tiny contact sizes, `abar` from `1e-7` down to `1e-400`
//! (below the f64 range), where `m - 1 = s/abar` reaches `1e399` while the strip
//! width `s = c - a` stays moderate. The slow-input scan met these inputs ending in
//! `Error::Invariant(StripResidualNotFinite)`: the f64 root scan that starts the MP
//! root formed `sqrt(z (2 + z))` (overflow) times `abar^2` (underflow), and the f64
//! Bessel sequence of the wave term was NaN at `D = 2 pi abar/beta < 1e-90`.
//!
//! * `strip_ratio` and `load` (one wave and the `_waves` form) answer at 8, 53 and
//!   256 bits with the digits asked for, and contain the mpmath values at the
//!   decimals as typed (`reference/data/model_tiny_contact.csv`,
//!   `reference/model_tiny_contact.py`: the root searched in the strip width at 700
//!   and 900 bits, 100 digits);
//! * the f64 model answers wherever `m` is a finite f64 (`abar >= 1e-300` here),
//!   within `1e-11` relative of the same references, and refuses with
//!   `NotRepresentable` where `m - 1` is not (`abar = 5e-324`).

use crate::common;

use maugis::ball::Decimal;
use maugis::contact::model::{solve_load, ContactSize, Params};
use maugis::contact::model_mp::{load_at_decimals, load_waves_at_decimals, strip_ratio_at_decimals, strip_ratio_waves_at_decimals};
use maugis::Error;
use rug::Float;

fn reference(text: &str) -> Float {
    Float::with_val(common::DECIMAL_REF_BITS, Float::parse(text).expect("reference parses"))
}

fn d(s: &str) -> Decimal {
    Decimal::parse(s).expect("decimal parses")
}

#[test]
fn tiny_contact_m_and_load_contain_the_references() {
    let rows = common::load("model_tiny_contact");
    assert!(rows.len() >= 7, "{} rows", rows.len());
    let mut failures = Vec::new();
    for row in &rows {
        let typed = [&row["lambda"], &row["alpha"], &row["beta"], &row["abar"]];
        let args = typed.map(|s| d(s));
        let (m_ref, load_ref) = (reference(&row["m"]), reference(&row["load"]));
        let abar = Float::with_val(64, args[3].as_rational());
        let hertz = Float::with_val(64, &abar * &abar) * Float::with_val(64, rug::float::Constant::Pi) / 4u32;
        let one_wave = [(args[1].clone(), args[2].clone())];
        for prec in [8u32, 53, 256] {
            let at = format!("{typed:?} at {prec} bits");
            for (form, m) in [
                ("strip_ratio", strip_ratio_at_decimals(&args, prec)),
                ("strip_ratio_waves", strip_ratio_waves_at_decimals(&args[0], &args[3], &one_wave, prec)),
            ] {
                match m {
                    Ok(m) if m.meets_rel(prec) && common::contains_decimal_ref(&m, &m_ref, None) => {}
                    other => failures.push(format!("{form} {at}: {other:?} vs {}", m_ref.to_string_radix(10, Some(30)))),
                }
            }
            for (form, l) in [
                ("load", load_at_decimals(&args, prec)),
                ("load_waves", load_waves_at_decimals(&args[0], &args[3], &one_wave, prec)),
            ] {
                match l {
                    // the load's contract: rad <= 2^-prec max(|L|, pi abar^2/4)
                    Ok(l) if (l.meets_rel(prec) || l.meets_abs(prec, &hertz)) && common::contains_decimal_ref(&l, &load_ref, Some(&hertz)) => {}
                    other => failures.push(format!("{form} {at}: {other:?} vs {}", load_ref.to_string_radix(10, Some(30)))),
                }
            }
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

#[test]
fn tiny_contact_f64_model_answers_where_m_is_a_double() {
    let rows = common::load("model_tiny_contact");
    let mut checked = 0;
    for row in &rows {
        let v = [&row["lambda"], &row["alpha"], &row["beta"], &row["abar"]].map(|s| s.parse::<f64>().expect("f64 parses"));
        let params = Params::new(v[0], v[1], v[2]).expect("parameters in range");
        let (m_ref, load_ref) = (reference(&row["m"]).to_f64(), reference(&row["load"]).to_f64());
        if v[3] < 1e-300 {
            // m - 1 = s/abar past f64::MAX (abar = 5e-324), or abar below the f64 range (read as 0)
            match ContactSize::new(params, v[3]).and_then(|cs| cs.solve_m()) {
                Err(Error::NotRepresentable { .. } | Error::OutOfRange { .. } | Error::NonFiniteResult { .. }) => {}
                other => panic!("{v:?}: {other:?}, expected a typed refusal (m - 1 = {m_ref:e} is not a double)"),
            }
            continue;
        }
        let m = ContactSize::new(params, v[3]).and_then(|cs| cs.solve_m()).unwrap_or_else(|e| panic!("{v:?}: {e:?}"));
        let load = solve_load(params, v[3]).unwrap_or_else(|e| panic!("{v:?}: {e:?}"));
        assert!(((m - m_ref) / m_ref).abs() < 1e-11, "{v:?}: m = {m:e}, reference {m_ref:e}");
        assert!(((load - load_ref) / load_ref).abs() < 1e-11, "{v:?}: load = {load:e}, reference {load_ref:e}");
        checked += 1;
    }
    assert!(checked >= 4, "{checked} rows checked in f64");
}
