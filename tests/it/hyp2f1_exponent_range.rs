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
                    assert!((log2_magnitude.to_f64() - sign * want).abs() <= 1e-9 * want.abs(), "{a} at {prec}: {log2_magnitude} vs {}", sign * want)
                }
                other => panic!("{a} at {prec}: {other:?}"),
            }
        }
    }
}

/// Issue 37's scan: values past `2^(2^30)` with positive parameters and `0 < z <
/// 1`, refused as `Overflow` (a cap) before. `src/special/hyp2f1/out_of_range.rs`
/// proves `F >= t_n >= 2^emax` from one term; the refusal carries that lower
/// bound (`Log2Relation::AtLeast`). Where `b` and `c` are the same decimal the
/// value is `(1 - z)^(-a)` (closed form, DLMF 15.4.6), whose `log2` must lie
/// above the bound.
#[test]
fn values_proven_past_the_exponent_range_are_refused_as_such() {
    use maugis::Log2Relation;
    let long_zeros = |digits: &str, zeros: usize, exp: &str| format!("0.{}{digits}{exp}", "0".repeat(zeros));
    let cases = [
        ("26.77829953180948e24976".to_string(), "1.0000000000000002e0".to_string(), "1.0000000000000002".to_string(), "3.892980940400477e-62".to_string()),
        ("1".into(), long_zeros("35533216026122666", 22, "e17786"), long_zeros("2186915842541662", 233, "e-19396"), "0.9999999999999998".into()),
        (long_zeros("6698428018039019", 305, "e1645"), "2".into(), "1".into(), long_zeros("2747567575366148", 193, "")),
        (long_zeros("3506261068948738", 133, "e14716"), "27".into(), "26".into(), long_zeros("18759989576251596", 222, "e-6733")),
        (long_zeros("6638121085517171", 46, "e22593"), "32".into(), "30".into(), long_zeros("969346177432491", 78, "")),
    ];
    let emax = f64::from(rug::float::exp_max());
    for (i, (a, b, c, z)) in cases.iter().enumerate() {
        for prec in [2, 53, 128] {
            match common::hyp2f1_at_decimals(a, b, c, z, prec) {
                Err(Error::ValueOutOfRange { log2_magnitude }) => {
                    assert_eq!(log2_magnitude.relation, Log2Relation::AtLeast, "case {i} at {prec}");
                    let bound = log2_magnitude.to_f64();
                    assert!(bound >= emax, "case {i} at {prec}: {log2_magnitude}");
                    if i == 0 {
                        // (1 - z)^(-a): log2 = -a log2(1 - z), about a z / ln 2
                        let want = Float::with_val(128, Float::parse(a).unwrap())
                            * -Float::with_val(400, 1 - Float::with_val(400, Float::parse(z).unwrap())).log2();
                        assert!(Float::with_val(128, bound) <= want, "case {i}: {bound} vs {want}");
                    }
                }
                other => panic!("case {i} ({a}, {b}; {c}; {z}) at {prec}: {other:?}"),
            }
        }
    }
}

/// A `log2` magnitude past f64's range prints as a decimal, not `2^-inf`:
/// `2F1(1, -9.5e14123; 1; 4.26e-273) = (1 - z)^(9.5e14123)` (DLMF 15.4.6), whose
/// `log2` is `9.5e14123 log2(1 - 4.26e-273) = -5.8386...e13851` (closed form,
/// from `rug` at 128 bits).
#[test]
fn a_log2_magnitude_past_f64_prints_its_digits() {
    let e = common::hyp2f1_at_decimals("1", "-9.5e14123", "1", "4.26e-273", 53).expect_err("out of range");
    let Error::ValueOutOfRange { log2_magnitude } = &e else { panic!("{e:?}") };
    let z = Float::with_val(1024, Float::parse("4.26e-273").unwrap());
    let want = Float::with_val(128, Float::parse("9.5e14123").unwrap()) * Float::with_val(1024, 1 - &z).log2();
    let digits = Float::with_val(128, want.clone().abs().log10());
    let exp10 = digits.clone().floor().to_f64() as i64;
    let mantissa = -10f64.powf((digits - exp10).to_f64());
    assert_eq!(log2_magnitude.exp10, exp10, "{log2_magnitude:?} vs {want}");
    assert!((log2_magnitude.mantissa - mantissa).abs() < 1e-6, "{log2_magnitude:?} vs {want}");
    let text = e.to_string();
    assert!(!text.contains("inf"), "{text}");
    assert!(text.contains(&format!("2^({mantissa:.4}e{exp10})")), "{text}");
}
