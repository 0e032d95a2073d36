//! J_n at decimal inputs: a decimal string becomes a ball that contains it, and
//! the answer contains J_n at the decimal as typed (not at a binary rounding).
//!
//! References: `reference/data/bessel_j_decimal.csv` (mpmath from the decimal
//! string at 1100 and 1400 bits, 100 digits), Bessel zeros typed to 17..60
//! digits and the same decimals with the last digit raised by one.

use crate::common;

use maugis::ball::{eval_at_decimals, Decimal};
use maugis::special::bessel_j::{bessel_j_ball_mp, bessel_j_mp};
use maugis::Ball;
use proptest::prelude::*;
use rug::Float;

const REF_BITS: u32 = common::DECIMAL_REF_BITS;

/// Ball at the decimal `x` with the library's refinement driver (what `maugis eval` runs).
fn at_decimal(n: i64, x: &str, prec: u32) -> Ball {
    let d = Decimal::parse(x).expect("decimal parses");
    eval_at_decimals(&[d], prec, |b| bessel_j_ball_mp(n, &b[0], prec)).expect("J_n at a decimal")
}

#[test]
fn decimal_zeros_contain_the_value_at_the_decimal() {
    let rows = common::load("bessel_j_decimal");
    assert!(rows.len() >= 300, "{} rows", rows.len());
    let mut probes = 0;
    let mut failures = Vec::new();
    for row in &rows {
        let n = common::col_i64(row, "n");
        let x = &row["x"];
        let r = Float::with_val(REF_BITS, Float::parse(&row["value"]).unwrap());
        for prec in [53, 128, 256] {
            let b = at_decimal(n, x, prec);
            probes += 1;
            if !common::contains_decimal_ref(&b, &r, None) {
                failures.push(format!("n={n} x={x} prec={prec}: {b:?} vs {}", r.to_string_radix(10, Some(30))));
            }
            // The refinement makes the answer a prec-bit answer at the decimal.
            if !b.meets_rel(prec) {
                failures.push(format!("n={n} x={x} prec={prec}: only {:.1} bits", b.rel_accuracy_bits()));
            }
        }
    }
    assert!(failures.is_empty(), "{} of {probes} probes failed:\n{}", failures.len(), failures[..failures.len().min(20)].join("\n"));
    eprintln!("{probes} probes at typed decimals, 0 failures");
}

#[test]
fn rounded_binary_input_is_not_the_decimal() {
    // The first row: rounding the decimal to 117 bits and certifying there
    // gives a ball that misses J_1 at the decimal; the decimal ball does not.
    let rows = common::load("bessel_j_decimal");
    let row = rows.iter().find(|r| r["n"] == "1" && r["x"].len() > 25).expect("a J_1 row");
    let r = Float::with_val(REF_BITS, Float::parse(&row["value"]).unwrap());
    let rounded = Float::with_val(117, Float::parse(&row["x"]).unwrap());
    let wrong = bessel_j_mp(1, &rounded, 53).unwrap();
    assert!(!common::contains_decimal_ref(&wrong, &r, None), "the binary rounding happened to contain it: {wrong:?}");
    assert!(common::contains_decimal_ref(&at_decimal(1, &row["x"], 53), &r, None));
}

#[test]
fn binary_fraction_inputs_lose_nothing() {
    // `{"fn":"bessel_j","n":5,"x":"2.5","prec":200}`: exact input, same ball as the Float path.
    let a = at_decimal(5, "2.5", 200);
    let b = bessel_j_mp(5, &Float::with_val(53, 2.5), 200).unwrap();
    assert_eq!(a, b);
    assert!(a.rad() <= Float::with_val(53, 3e-66), "{a:?}");
}

#[test]
fn input_radius_is_propagated() {
    // A wide input ball: the result must contain J_n at both ends.
    let x = Ball::with_radius(Float::with_val(64, 10), &Float::with_val(53, 0.25));
    let b = bessel_j_ball_mp(3, &x, 64).unwrap();
    for t in [9.75, 10.0, 10.25] {
        let v = bessel_j_mp(3, &Float::with_val(53, t), 64).unwrap();
        assert!(b.contains(v.mid()), "t={t}: {b:?} vs {v:?}");
    }
    assert!(bessel_j_ball_mp(3, &x, 1).is_err());
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]
    /// Random decimals near J_n zeros typed to 17..60 digits: answers at two
    /// precisions overlap and meet their precision.
    #[test]
    fn two_precisions_overlap(idx in 0usize..392, cut in 17usize..60) {
        let rows = common::load("bessel_j_decimal");
        let row = &rows[idx % rows.len()];
        let n = common::col_i64(row, "n");
        let (mant, exp) = row["x"].split_once('e').unwrap();
        let digits: String = mant.chars().filter(|c| c.is_ascii_digit()).collect();
        let cut = cut.min(digits.len());
        let x = format!("{}.{}e{}", &digits[..1], &digits[1..cut], exp);
        let lo = at_decimal(n, &x, 64);
        let hi = at_decimal(n, &x, 192);
        prop_assert!(lo.overlaps(&hi), "x={} {:?} vs {:?}", x, lo, hi);
        prop_assert!(lo.meets_rel(64) && hi.meets_rel(192));
    }
}
