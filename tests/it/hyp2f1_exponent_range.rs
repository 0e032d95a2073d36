//! Issue 37: MP `2F1` where a Gamma or the Pfaff prefactor passes MPFR's exponent
//! range (`2^(2^30)`) while the value does not. Gauss's sum at `z = 1` with
//! `Gamma(4.2e18)`, and `(1 - z)^(-7.4e17)` times the inner series, were refused
//! `Overflow` (about 215 of issue 37's scan's 20 000 `hyp2f1` inputs a seed); they
//! are formed in logarithms now (`maugis::ball::Scaled`) and answer certified.
//! Only a value that is itself outside the range is refused, as
//! `Error::ValueOutOfRange`. One tiny positive parameter with `z < 0` at a huge
//! other one (`2F1(7.4e17, 2.4e-200; 23.4; -177.9)`, `a = 2.2e14124`: refused
//! `Overflow` before) answers by the enclosure `[1 - w, 1]` of
//! `src/special/hyp2f1/small_parameter.rs`; the row `2F1(1e18, 2e-41; 2.5; -20)`
//! has `1 - F = 8.7e-40` against `w = 1.03e-39` at 128 bits.
//!
//! References: `reference/data/hyp2f1_exponent_range.csv`
//! (`reference/hyp2f1_exponent_range.py`: mpmath at 600 and 900 bits).

use crate::common;

use maugis::Error;
use rug::Float;

#[test]
fn exponent_range_inputs_enclose_the_reference() {
    let rows = common::load("hyp2f1_exponent_range");
    assert!(rows.len() >= 2, "{} rows", rows.len());
    for row in &rows {
        let (a, b, c, z) = (&row["a"], &row["b"], &row["c"], &row["z"]);
        let r = Float::with_val(400, Float::parse(&row["value"]).unwrap());
        for prec in [2, 8, 53, 128] {
            let ball = common::hyp2f1_at_decimals(a, b, c, z, prec).unwrap_or_else(|e| panic!("({a}, {b}; {c}; {z}) at {prec}: {e}"));
            assert!(common::contains_40_digit_ref(&ball, &r), "({a}, {b}; {c}; {z}) at {prec}: {ball:?} vs {}", row["value"]);
            assert!(ball.meets_rel(prec), "({a}, {b}; {c}; {z}) at {prec}: {ball:?}");
        }
    }
}

/// `2F1(a, b; b; z) = (1 - z)^(-a)` (closed form): at `a = 10^18`, `z = -177.9`
/// the value is `2^(-10^18 log2(178.9))`, below every exponent range: refused as
/// the value itself, with its size, at every precision.
#[test]
fn a_value_outside_the_exponent_range_is_refused_as_such() {
    let want = -1e18 * 178.9f64.log2();
    for (a, sign) in [("1e18", 1.0), ("-1e18", -1.0)] {
        for prec in [8, 64] {
            match common::hyp2f1_at_decimals(a, "2.5", "2.5", "-177.9", prec) {
                Err(Error::ValueOutOfRange { log2_magnitude }) => {
                    assert!((log2_magnitude - sign * want).abs() <= 1e-9 * want.abs(), "{a} at {prec}: {log2_magnitude} vs {}", sign * want)
                }
                other => panic!("{a} at {prec}: {other:?}"),
            }
        }
    }
}
