//! The model's certified values at decimals for a profile of many waves (issue 35):
//! `strip_ratio_waves_at_decimals` and `load_waves_at_decimals`, and the registry's
//! `strip_ratio_waves` / `load_waves` behind `maugis eval`.
//!
//! * one wave gives the one-wave entries' balls bit for bit;
//! * the balls contain the mpmath values at the decimals as typed
//!   (`reference/data/model_waves_decimal.csv`, `model_waves_decimal_rows` in
//!   reference/generate.py) and carry the digits asked for;
//! * they contain the f64 model's values up to the f64 route's error;
//! * at 12 bits they still answer with 12 bits, or refuse with a typed error;
//! * bad waves are typed errors naming the wave and the field.

use crate::common;

use maugis::ball::Decimal;
use maugis::contact::model::{ContactSize, Params};
use maugis::contact::model_mp::{load_at_decimals, load_waves_at_decimals, strip_ratio_at_decimals, strip_ratio_waves_at_decimals};
use maugis::contact::profile::{WavyProfile, MAX_WAVES};
use maugis::error::{ProfileError, WaveField};
use maugis::registry::{self, Answer, Arg};
use maugis::{Ball, Error};
use rug::Float;

fn d(s: &str) -> Decimal {
    Decimal::parse(s).expect("decimal parses")
}

fn waves(flat: &str) -> Vec<(Decimal, Decimal)> {
    let v: Vec<&str> = flat.split_whitespace().collect();
    assert!(v.len() % 2 == 0, "{flat}");
    v.chunks(2).map(|w| (d(w[0]), d(w[1]))).collect()
}

fn hertz(abar: &Decimal) -> Float {
    let a = Float::with_val(64, abar.as_rational());
    Float::with_val(64, &a * &a) * Float::with_val(64, rug::float::Constant::Pi) / 4u32
}

fn same(a: &Ball, b: &Ball) -> bool {
    a.mid() == b.mid() && a.rad() == b.rad() && a.prec() == b.prec()
}

#[test]
fn one_wave_is_the_one_wave_entry_bit_for_bit() {
    let cases = [["3", "0.3535533905932737622", "1.125", "2.2"], ["1", "0.35", "1.125", "2"], ["0.25", "0", "1.125", "0.7"], ["6", "0.375", "0.5", "1.25"]];
    for [lambda, alpha, beta, abar] in cases {
        let one = [d(lambda), d(alpha), d(beta), d(abar)];
        let w = [(d(alpha), d(beta))];
        for prec in [12, 53, 128] {
            let (a, b) = (strip_ratio_at_decimals(&one, prec).unwrap(), strip_ratio_waves_at_decimals(&d(lambda), &d(abar), &w, prec).unwrap());
            assert!(same(&a, &b), "m {lambda} {alpha} {beta} {abar} prec {prec}: {a:?} vs {b:?}");
            let (a, b) = (load_at_decimals(&one, prec).unwrap(), load_waves_at_decimals(&d(lambda), &d(abar), &w, prec).unwrap());
            assert!(same(&a, &b), "load {lambda} {alpha} {beta} {abar} prec {prec}: {a:?} vs {b:?}");
        }
        // the registry's f64 paths too
        let f = |name: &str, args: &[f64]| match registry::function(name).unwrap().eval_f64(&args.iter().map(|v| Arg::Real(*v)).collect::<Vec<_>>()).unwrap() {
            Answer::F64(v) => v,
            other => panic!("{other:?}"),
        };
        let p: [f64; 4] = [lambda, alpha, beta, abar].map(|t| t.parse().unwrap());
        for (one, many) in [("strip_ratio", "strip_ratio_waves"), ("load", "load_waves")] {
            assert_eq!(f(one, &p).to_bits(), f(many, &[p[0], p[3], p[1], p[2]]).to_bits(), "{one} at {p:?}");
        }
    }
}

#[test]
fn many_wave_balls_contain_the_mpmath_values_at_the_decimals() {
    let rows = common::load("model_waves_decimal");
    assert!(rows.len() >= 7, "{} rows", rows.len());
    let mut failures = Vec::new();
    for row in &rows {
        let (lambda, abar, w) = (d(&row["lambda"]), d(&row["abar"]), waves(&row["waves"]));
        let m_ref = Float::with_val(common::DECIMAL_REF_BITS, Float::parse(&row["m"]).unwrap());
        let load_ref = Float::with_val(common::DECIMAL_REF_BITS, Float::parse(&row["load"]).unwrap());
        let scale = hertz(&abar);
        for prec in [53, 128] {
            let m = strip_ratio_waves_at_decimals(&lambda, &abar, &w, prec).unwrap();
            if !common::contains_decimal_ref(&m, &m_ref, None) || !m.meets_rel(prec) {
                failures.push(format!("m {row:?} prec {prec}: {m:?}"));
            }
            let l = load_waves_at_decimals(&lambda, &abar, &w, prec).unwrap();
            if !common::contains_decimal_ref(&l, &load_ref, Some(&scale)) || !(l.meets_rel(prec) || l.meets_abs(prec, &scale)) {
                failures.push(format!("load {row:?} prec {prec}: {l:?}"));
            }
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

/// The f64 model of the same two waves: the ball of `m` contains the f64 root up to
/// its error (`1e-13` relative in `m - 1`), the load ball the f64 load up to `1e-12`
/// of the load scale; both balls have their digits.
#[test]
fn two_wave_balls_contain_the_f64_model() {
    let pairs = [(std::f64::consts::SQRT_2 / 4.0, 1.125), (std::f64::consts::SQRT_2 / 8.0, 0.375)];
    // the decimals of the f64 numbers, so that both routes see the same inputs
    let text = |v: f64| format!("{v:e}");
    let w: Vec<(Decimal, Decimal)> = pairs.iter().map(|&(a, b)| (d(&text(a)), d(&text(b)))).collect();
    let p = Params::with_profile(3.0, WavyProfile::from_pairs(&pairs).unwrap()).unwrap();
    let near = |ball: &Ball, v: f64, slack: f64| Float::with_val(128, ball.mid() - v).abs() <= Float::with_val(128, ball.rad() + slack);
    for abar in [0.6, 1.5, 2.2, 3.1] {
        let cs = ContactSize::new(p, abar).unwrap();
        let strip = cs.solve_strip().unwrap();
        let (lambda, a) = (d("3"), d(&text(abar)));
        for prec in [53, 100] {
            let m = strip_ratio_waves_at_decimals(&lambda, &a, &w, prec).unwrap();
            assert!(m.meets_rel(prec), "abar {abar} prec {prec}: {m:?}");
            assert!(near(&m, strip.m(), 1e-13 * strip.m_minus_1()), "abar {abar}: m {} vs {m:?}", strip.m());
            let l = load_waves_at_decimals(&lambda, &a, &w, prec).unwrap();
            let scale = std::f64::consts::PI * abar * abar / 4.0;
            assert!(l.meets_rel(prec) || l.meets_abs(prec, &hertz(&a)), "abar {abar} prec {prec}: {l:?}");
            assert!(near(&l, cs.load_at(strip), 1e-12 * scale), "abar {abar}: load {} vs {l:?}", cs.load_at(strip));
        }
    }
}

/// At 12 bits the answer still carries 12 bits and overlaps the 128-bit ball (or is a
/// typed refusal; none is expected at these inputs), through the registry as
/// `maugis eval` calls it.
#[test]
fn low_precision_still_answers() {
    let args = |list: &[&str]| list.iter().map(|t| Arg::Real(d(t))).collect::<Vec<_>>();
    let inputs: [&[&str]; 3] = [
        &["3", "2.2", "0.3535533905932737622", "1.125", "0.1767766952966368811", "0.375"],
        &["1", "1.3", "0.3", "1.2", "0.21", "0.6", "0.15", "0.3"],
        &["0.5", "0.1", "0.35", "1.125", "0.2", "0.01"],
    ];
    for name in ["strip_ratio_waves", "load_waves"] {
        let f = registry::function(name).unwrap();
        for list in inputs {
            let ball = |prec| match f.eval_mp(&args(list), prec) {
                Ok(Answer::Ball(b)) => Ok(b),
                Ok(other) => panic!("{other:?}"),
                Err(e) => Err(e),
            };
            let fine = ball(128).unwrap_or_else(|e| panic!("{name} {list:?} at 128 bits: {e}"));
            match ball(12) {
                Ok(b) => {
                    let abar = d(list[1]);
                    assert!(b.meets_rel(12) || (name == "load_waves" && b.meets_abs(12, &hertz(&abar))), "{name} {list:?}: {b:?}");
                    assert!(b.overlaps(&fine), "{name} {list:?}: {b:?} vs {fine:?}");
                }
                Err(e) => assert!(matches!(e, Error::RootNotCertified { .. } | Error::PrecisionExhausted { .. }), "{name} {list:?}: {e:?}"),
            }
        }
    }
}

#[test]
fn bad_waves_are_typed_errors() {
    let (lambda, abar) = (d("3"), d("2.2"));
    let check = |w: &[(&str, &str)], wave: usize, field: WaveField| {
        let w: Vec<(Decimal, Decimal)> = w.iter().map(|(a, b)| (d(a), d(b))).collect();
        for prec in [12, 64] {
            for e in [strip_ratio_waves_at_decimals(&lambda, &abar, &w, prec).unwrap_err(), load_waves_at_decimals(&lambda, &abar, &w, prec).unwrap_err()] {
                match &e {
                    Error::Profile(ProfileError::Wave { wave: got, field: f, .. }) => {
                        assert_eq!((*got, *f), (wave, field), "{w:?}: {e}");
                        assert!(e.to_string().contains(&format!("wave {wave}")), "{e}");
                    }
                    other => panic!("{w:?} at {prec}: {other:?}"),
                }
            }
        }
    };
    check(&[("0.35", "1.125"), ("-0.1", "0.375")], 2, WaveField::Amplitude);
    check(&[("0.35", "0"), ("0.1", "0.375")], 1, WaveField::Wavelength);
    check(&[("0.35", "1.125"), ("0.1", "0.375"), ("0.1", "-2")], 3, WaveField::Wavelength);
    check(&[("2e6", "1.125")], 1, WaveField::Amplitude);
    let many = vec![(d("0.01"), d("1")); MAX_WAVES + 1];
    assert!(matches!(
        strip_ratio_waves_at_decimals(&lambda, &abar, &many, 64),
        Err(Error::Profile(ProfileError::TooManyWaves { count, max: MAX_WAVES })) if count == MAX_WAVES + 1
    ));
    // a wave too fine for the contact (D = 2 pi abar/beta over 1e5) is named, on the f64
    // and the certified paths, and refused before any wave's terms are computed
    let fine: Vec<(Decimal, Decimal)> = (0..16).map(|j| (d(&format!("{:e}", 0.35 * 2f64.powf(-0.5 * j as f64))), d(&format!("{:e}", 1.125 * 2f64.powi(-j))))).collect();
    for prec in [12, 64] {
        for e in [strip_ratio_waves_at_decimals(&lambda, &abar, &fine, prec).unwrap_err(), load_waves_at_decimals(&lambda, &abar, &fine, prec).unwrap_err()] {
            assert!(matches!(e, Error::Profile(ProfileError::WaveTooFine { wave: 14, .. })), "{e:?}");
            assert!(e.to_string().contains("wave 14"), "{e}");
        }
    }
    let pairs: Vec<(f64, f64)> = (0..16).map(|j| (0.35 * 2f64.powf(-0.5 * j as f64), 1.125 * 2f64.powi(-j))).collect();
    let p = Params::with_profile(3.0, WavyProfile::from_pairs(&pairs).unwrap()).unwrap();
    assert!(matches!(ContactSize::new(p, 2.2), Err(Error::Profile(ProfileError::WaveTooFine { wave: 14, .. }))));
    assert!(ContactSize::new(p, 0.5).is_ok(), "the same waves fit a smaller contact");
    // lambda and abar keep their own names
    let w = waves("0.35 1.125");
    assert!(matches!(strip_ratio_waves_at_decimals(&d("-1"), &abar, &w, 64), Err(Error::BallOutOfRange { arg: "lambda", .. })));
    assert!(matches!(load_waves_at_decimals(&lambda, &d("0"), &w, 64), Err(Error::BallOutOfRange { arg: "abar", .. })));
}
