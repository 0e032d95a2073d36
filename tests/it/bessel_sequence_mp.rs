//! Issue 23: certified `J_0(x), ..., J_nmax(x)` by the midpoint recurrence
//! (`bessel_j_sequence_three_term`): it encloses the ball recurrence's values
//! (`bessel_j_sequence_mp`, run with enough extra bits to be tighter) and the
//! 170-digit references of `reference/data/bessel_j_grid.csv`, on a grid of
//! `n` and `x` with the turning point `n ~ x`, tiny `x` and `x` up to 1e5, at
//! 53, 128 and 512 bits; and its radii stay within the tolerance table below.
//!
//! Tolerance table, in bits lost against `2^-wp` (module docs of
//! `src/special/bessel_j/three_term.rs`), with `X = max(x, 8)`; measured
//! worst margins (this test's output, at 53/128/512 bits): 2.7 bits below the
//! turning point, 4.2 past it:
//!
//! | region | measure | allowed bits | what dominates |
//! |---|---|---|---|
//! | `n = 0, 1` | relative | 0 | certified `J_0`, `J_1` (Ziv loop to `2^-wp`) |
//! | `2 <= n < x` | absolute | `2 log2 X + 2` | `(n - 1)` local errors times the energy-norm growth, `~x^2` next to the turning point |
//! | `n > x` | relative | `(7/3) log2 X + log2(A) + 2` | `J_{m+1}` (`x^2` against `|J_{m+1}| ~ x^{-1/3}`) and the ratio walk's `28 A 2^-wp`, `A = (nmax - x) + (x/2) ln(nmax - x + 2) + 1` |

use crate::common;

use maugis::special::bessel_j::{bessel_j_sequence_mp, bessel_j_sequence_three_term, MAX_SEQUENCE_ARGUMENT, MAX_SEQUENCE_ORDER};
use maugis::{Ball, Error};
use rug::Float;
use std::collections::BTreeMap;

const PRECS: [u32; 3] = [53, 128, 512];

/// Whether `outer` contains the whole of `inner`.
fn contains_ball(outer: &Ball, inner: &Ball) -> bool {
    outer.lower() <= inner.lower() && inner.upper() <= outer.upper()
}

/// The region of `n` at `x` and the bits the ball lost there against `2^-wp`
/// and its allowance (the module docs' table).
fn bits_lost(n: u64, x: f64, nmax: u64, b: &Ball, wp: u32) -> (&'static str, f64, f64) {
    let big_x = x.max(8.0).log2();
    let log_rad = b.rad_mag().log2();
    let rel = log_rad - b.mid().clone().abs().log2().to_f64();
    if n <= 1 {
        ("n = 0, 1 (relative)", rel + wp as f64, 0.0)
    } else if (n as f64) < x {
        ("2 <= n < x (absolute)", log_rad + wp as f64, 2.0 * big_x + 2.0)
    } else {
        let past = (nmax as f64 - x).max(0.0);
        let a = past + x / 2.0 * (past + 2.0).ln() + 1.0;
        ("n > x (relative)", rel + wp as f64, 7.0 / 3.0 * big_x + a.log2() + 2.0)
    }
}

/// Worst `lost - allowed` per region, with the point where it occurs.
type Worst = BTreeMap<&'static str, (f64, f64, String)>;

fn record(worst: &mut Worst, n: u64, x: f64, nmax: u64, b: &Ball, wp: u32) {
    let (region, lost, allowed) = bits_lost(n, x, nmax, b, wp);
    let e = worst.entry(region).or_insert((f64::NEG_INFINITY, 0.0, String::new()));
    if lost - allowed > e.0 - e.1 || e.2.is_empty() {
        *e = (lost, allowed, format!("n = {n}, x = {x}, wp = {wp}"));
    }
}

fn check_table(worst: &Worst) {
    let mut bad = Vec::new();
    for (region, (lost, allowed, at)) in worst {
        println!("{region}: worst {lost:.1} bits lost (allowed {allowed:.1}) at {at}");
        if lost > allowed {
            bad.push(format!("{region}: {lost:.1} bits lost > {allowed:.1} at {at}"));
        }
    }
    assert!(bad.is_empty(), "{}", bad.join("\n"));
}

#[test]
fn encloses_the_ball_recurrence_with_radii_in_the_table() {
    // x: tiny, below and at 1, small, the model's D = 2 pi / 0.001, 1e4 and 1e5;
    // nmax past the turning point (the wave's use), and below it.
    let cases: [(f64, u64); 17] = [
        (2f64.powi(-30), 40),
        (0.001, 60),
        (0.75, 30),
        (1.0, 30),
        (1.5, 30),
        (2.0, 40),
        (2.5, 40),
        (10.0, 60),
        (30.25, 90),
        (99.75, 160),
        (999.5, 500),
        (999.5, 1100),
        (5000.0, 5100),
        (6283.185307179586, 6400),
        (10000.0, 10150),
        (10000.5, 3000),
        (100000.5, 100300),
    ];
    let mut worst = Worst::new();
    let mut checked = 0usize;
    for &(x, nmax) in &cases {
        let xf = Float::with_val(53, x);
        for wp in PRECS {
            let seq = bessel_j_sequence_three_term(nmax, &xf, wp).unwrap_or_else(|e| panic!("x = {x}, nmax = {nmax}, wp = {wp}: {e:?}"));
            assert_eq!(seq.len(), nmax as usize + 1);
            // The ball recurrence loses ~0.68 x bits: run it with that many more, and 96 to spare.
            // (x = 1e5 would take 68000 bits over 1e5 steps; it is checked against the grid references.)
            if x < 20000.0 {
                let wp_ref = wp + (0.7 * x) as u32 + 96;
                let reference = bessel_j_sequence_mp(nmax, &xf, wp_ref).unwrap();
                for (n, (b, r)) in seq.iter().zip(&reference).enumerate() {
                    assert!(r.rad_mag().le(&b.rad_mag()) || b.rad_mag().is_zero(), "reference not tighter at x = {x}, n = {n}");
                    assert!(contains_ball(b, r), "x = {x}, n = {n}, wp = {wp}: {b:?} does not contain {r:?}");
                    checked += 1;
                }
            }
            for (n, b) in seq.iter().enumerate() {
                // past the turning point J_n > 0 and the ball is relative
                assert!(b.is_finite() && ((n as f64) < x || b.is_positive()), "x = {x}, n = {n}, wp = {wp}: {b:?}");
                record(&mut worst, n as u64, x, nmax, b, wp);
            }
        }
    }
    println!("{checked} values enclose the ball recurrence's");
    check_table(&worst);
}

/// `|b - r| <= rad(b) + 1e-165 |r|` (the references carry 170 digits and agree
/// to 190 between two runs of the generator).
fn encloses_170_digits(b: &Ball, r: &Float) -> bool {
    let d = Float::with_val(800, b.mid() - r).abs();
    let slack = Float::with_val(800, r.clone().abs() * Float::with_val(800, Float::parse("1e-165").unwrap()));
    d <= Float::with_val(800, b.rad() + &slack)
}

#[test]
fn encloses_the_grid_references() {
    let rows = common::load("bessel_j_grid");
    // x -> [(n, reference)]
    let mut by_x: BTreeMap<String, Vec<(u64, Float)>> = BTreeMap::new();
    for row in &rows {
        let n = common::col_i64(row, "n");
        let x = common::col_f64(row, "x");
        if n < 0 || !(x > 0.0) || x > MAX_SEQUENCE_ARGUMENT || n > 110_000 {
            continue;
        }
        let r = Float::with_val(800, Float::parse(&row["value"]).expect("reference parses"));
        by_x.entry(row["x"].clone()).or_default().push((n as u64, r));
    }
    let mut worst = Worst::new();
    let mut checked = 0usize;
    for (text, refs) in &by_x {
        let x = text.parse::<f64>().unwrap();
        let xf = Float::with_val(53, x);
        let nmax = refs.iter().map(|(n, _)| *n).max().unwrap();
        for wp in PRECS {
            let seq = bessel_j_sequence_three_term(nmax, &xf, wp).unwrap_or_else(|e| panic!("x = {x}, nmax = {nmax}, wp = {wp}: {e:?}"));
            for (n, r) in refs {
                let b = &seq[*n as usize];
                assert!(encloses_170_digits(b, r), "x = {text}, n = {n}, wp = {wp}: {b:?} vs {}", r.to_string_radix(10, Some(30)));
                record(&mut worst, *n, x, nmax, b, wp);
                checked += 1;
            }
        }
    }
    assert!(checked >= 250, "only {checked} grid values checked");
    println!("{checked} grid values enclosed");
    check_table(&worst);
}

#[test]
fn bad_arguments_are_typed_errors() {
    let x = Float::with_val(53, 2.5);
    for wp in [0, 1, maugis::MAX_WORKING_PREC + 1] {
        assert!(matches!(bessel_j_sequence_three_term(4, &x, wp), Err(Error::Precision { .. })), "wp = {wp}");
    }
    for bad in [0.0, -1.0, f64::NAN, f64::INFINITY, 2.0 * MAX_SEQUENCE_ARGUMENT] {
        let r = bessel_j_sequence_three_term(4, &Float::with_val(53, bad), 64);
        assert!(matches!(r, Err(Error::OutOfRange { arg: "x", .. }) | Err(Error::NonFinite { .. })), "x = {bad}: {r:?}");
    }
    let r = bessel_j_sequence_three_term(MAX_SEQUENCE_ORDER as u64 + 1, &x, 64);
    assert!(matches!(r, Err(Error::IntegerOutOfRange { arg: "nmax", .. })), "{r:?}");
    // the smallest sequences
    assert_eq!(bessel_j_sequence_three_term(0, &x, 64).unwrap().len(), 1);
    assert_eq!(bessel_j_sequence_three_term(1, &x, 64).unwrap().len(), 2);
}

/// The model's use, end to end: the Bessel form of `u_w` at the contact edge
/// `x = a` sums the whole sequence, `A (1 - J_0(D) - 2 sum (-1)^n J_2n(D))`,
/// and must equal `A (1 - cos D)` [DLMF 10.12.3 at theta = pi/2], computed here
/// by ball sine and cosine, for `D` up to 3e4 (beta = 0.001 is `D = 6283`).
#[test]
fn wave_edge_identity_at_large_d() {
    use maugis::contact::displacement::u_wave_mp;
    let amp = Float::with_val(53, 2.5);
    for (a, zeta) in [(3.0, 0.03), (1.0, 0.001), (1.0, 2.0 * std::f64::consts::PI / 1e4), (0.5, 1e-4)] {
        let (af, zf) = (Float::with_val(53, a), Float::with_val(53, zeta));
        for prec in PRECS {
            let u = u_wave_mp(&af, &zf, &amp, &af, prec).unwrap_or_else(|e| panic!("a = {a}, zeta = {zeta}, prec {prec}: {e:?}"));
            let wp = prec + 64;
            let d = Ball::pi(wp).mul(&Ball::from_float(&af, wp)).mul_pow2(1).div(&Ball::from_float(&zf, wp)).unwrap();
            let edge = Ball::one(wp).sub(&d.sin_cos().1).mul(&Ball::from_float(&amp, wp));
            assert!(u.overlaps(&edge), "a = {a}, zeta = {zeta}, prec {prec}: {u:?} vs A (1 - cos D) = {edge:?}");
            let scale = Float::with_val(53, &amp);
            assert!(u.meets_rel(prec) || u.meets_abs(prec, &scale), "a = {a}, zeta = {zeta}, prec {prec}: {u:?}");
        }
    }
}

/// The ball recurrence's sequence, with its working precision raised (from
/// `wp_ref`) until every ball is tighter than the one of `seq` it is checked
/// against (past the turning point it loses more than `0.7 x` bits).
fn tight_reference(seq: &[Ball], nmax: u64, x: &Float, mut wp_ref: u32) -> Vec<Ball> {
    for _ in 0..4 {
        let reference = bessel_j_sequence_mp(nmax, x, wp_ref).unwrap();
        let short = seq.iter().zip(&reference).map(|(b, r)| r.rad_mag().log2() - b.rad_mag().log2()).fold(f64::NEG_INFINITY, f64::max);
        if short <= 0.0 {
            return reference;
        }
        wp_ref += short.ceil() as u32 + 64;
    }
    panic!("no tight reference at x = {x}, nmax = {nmax}");
}

proptest::proptest! {
    #![proptest_config(proptest::prelude::ProptestConfig::with_cases(64))]
    /// Random binary `x` (log-uniform over 2^-40 .. 2^14), `nmax` from 0 to
    /// `1.5 x + 100`, `wp` from 40 to 700: the sequence contains the ball
    /// recurrence's values run with enough more bits to be tighter, and the
    /// table holds.
    #[test]
    fn random_points_enclose_the_ball_recurrence(log_x in -40.0f64..14.0, frac in 0.0f64..1.5, extra in 0u64..100, wp in 40u32..700) {
        let x = 2f64.powf(log_x);
        let nmax = (frac * x) as u64 + extra;
        let xf = Float::with_val(53, x);
        let seq = bessel_j_sequence_three_term(nmax, &xf, wp).unwrap();
        let reference = tight_reference(&seq, nmax, &xf, wp + (0.7 * x) as u32 + 96);
        let mut worst = Worst::new();
        for (n, (b, r)) in seq.iter().zip(&reference).enumerate() {
            proptest::prop_assert!(contains_ball(b, r), "x = {}, n = {}, wp = {}: {:?} does not contain {:?}", x, n, wp, b, r);
            record(&mut worst, n as u64, x, nmax, b, wp);
        }
        for (region, (lost, allowed, at)) in &worst {
            proptest::prop_assert!(lost <= allowed, "{}: {:.1} bits lost > {:.1} at {}", region, lost, allowed, at);
        }
    }
}

/// Arguments at the ends of the range answer without a panic and overlap the
/// ball recurrence: `x` below f64's range (the ratio walk's bookkeeping is in
/// base-2 logarithms), and `x` at the cap with a short sequence.
#[test]
fn extreme_arguments_answer() {
    for (x, nmax) in [(Float::with_val(53, 1) >> 2000u32, 10u64), (Float::with_val(53, 1) >> 60000u32, 3), (Float::with_val(53, MAX_SEQUENCE_ARGUMENT), 5)] {
        let exp = x.get_exp().unwrap_or(0);
        let seq = std::panic::catch_unwind(|| bessel_j_sequence_three_term(nmax, &x, 64))
            .unwrap_or_else(|_| panic!("panicked at x = 2^{exp}"))
            .unwrap_or_else(|e| panic!("x = 2^{exp}: {e}"));
        assert_eq!(seq.len(), nmax as usize + 1);
        let reference = bessel_j_sequence_mp(nmax, &x, 64 + 96).unwrap();
        for (n, (b, r)) in seq.iter().zip(&reference).enumerate() {
            assert!(b.is_finite() && b.overlaps(r), "x = 2^{exp}, n = {n}: {b:?} vs {r:?}");
            if n > 0 && (x.to_f64() as u64) < n as u64 {
                assert!(b.meets_rel(40), "x = 2^{exp}, n = {n}: {b:?}");
            }
        }
    }
}
