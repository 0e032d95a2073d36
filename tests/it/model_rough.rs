//! Issue 23: the model's MP quantities on a rough profile, beta typed as
//! "0.001" (D = 2 pi abar/beta ~ 6283 and 9425): the strip ratio `m` and the
//! load at the decimals as typed, at 53, 128 and 512 bits, against
//! `reference/data/model_rough.csv` (`reference/model_rough.py`: mpmath with
//! Miller's recurrence at 450 and 600 bits, 100 digits). The load there took
//! over 60 s and the strip ratio 3.5 to 5.3 s before the midpoint recurrence
//! for the J_n; the times are in docs/bessel.md (no time assertion here).

use crate::common;

use maugis::ball::Decimal;
use maugis::contact::model_mp::{load_at_decimals, strip_ratio_at_decimals};
use rug::Float;

fn reference(text: &str) -> Float {
    Float::with_val(common::DECIMAL_REF_BITS, Float::parse(text).expect("reference parses"))
}

#[test]
fn rough_profile_m_and_load_contain_the_references() {
    let rows = common::load("model_rough");
    assert!(rows.len() >= 2, "{} rows", rows.len());
    let mut failures = Vec::new();
    for row in &rows {
        let args = [&row["lambda"], &row["alpha"], &row["beta"], &row["abar"]].map(|s| Decimal::parse(s).expect("decimal parses"));
        let (m_ref, load_ref) = (reference(&row["m"]), reference(&row["load"]));
        let abar = Float::with_val(64, args[3].as_rational());
        let hertz = Float::with_val(64, &abar * &abar) * Float::with_val(64, rug::float::Constant::Pi) / 4u32;
        for prec in [53u32, 128, 512] {
            let at = format!("{:?} at {prec} bits", [&row["lambda"], &row["alpha"], &row["beta"], &row["abar"]]);
            match strip_ratio_at_decimals(&args, prec) {
                Ok(m) if m.meets_rel(prec) && common::contains_decimal_ref(&m, &m_ref, None) => {}
                other => failures.push(format!("m {at}: {other:?} vs {}", m_ref.to_string_radix(10, Some(30)))),
            }
            match load_at_decimals(&args, prec) {
                // the load's contract: rad <= 2^-prec max(|L|, pi abar^2/4)
                Ok(l) if (l.meets_rel(prec) || l.meets_abs(prec, &hertz)) && common::contains_decimal_ref(&l, &load_ref, Some(&hertz)) => {}
                other => failures.push(format!("load {at}: {other:?} vs {}", load_ref.to_string_radix(10, Some(30)))),
            }
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}
