//! The f64 wave displacement with a proven bound (`u_wave_bounded`,
//! `du_wave_bounded`, `WaveBessel::eval_bounded`): the bound must contain the
//! certified MP value (Bessel form in balls at 200 bits) at every point, and the
//! value must be within the issue-8 accuracy (u_w: 1e-15 of max(|u|, A); du_w:
//! 1e-15 of max(|du|, 2 pi A/zeta)).
//!
//! Points: a grid over a in [0.5, 6], zeta = 9/8 (the model's domain) and other
//! wavelengths, x/a in [1, 3] with the region edges (x = a, x/a = 1 + 2^-40,
//! x/a = 3, the native limit 25/7 and beyond, where the MP fallback answers),
//! and a proptest over random points.

use maugis::contact::displacement::{du_wave_bounded, du_wave_mp, u_wave, u_wave_bounded, u_wave_mp, WaveBessel};
use maugis::special::exact;
use maugis::Bounded;
use proptest::prelude::*;
use rug::Float;

const REF_PREC: u32 = 200;

/// `|exact - value| <= err` against the certified ball (its radius is ~2^-200).
fn check(name: &str, b: Bounded, reference: &maugis::Ball, scale: f64, what: &str) {
    let diff = Float::with_val(REF_PREC + 64, reference.mid() - b.value).abs();
    let mut slack = reference.rad();
    slack += b.err;
    assert!(diff <= slack, "{name} {what}: {b} misses {:?}", reference);
    let rel = diff.to_f64() / scale;
    assert!(rel <= 1e-15, "{name} {what}: error {rel:e} of the scale exceeds 1e-15 ({b} vs {reference:?})");
    // the bound is honest but not loose beyond reason
    assert!(b.err <= 1e-13 * scale, "{name} {what}: bound {:e} is too loose (scale {scale:e})", b.err);
}

fn check_point(a: f64, zeta: f64, amp: f64, x: f64) {
    let (ae, ze, me, xe) = (exact(a), exact(zeta), exact(amp), exact(x));
    let u_ref = u_wave_mp(&ae, &ze, &me, &xe, REF_PREC).unwrap();
    let du_ref = du_wave_mp(&ae, &ze, &me, &xe, REF_PREC).unwrap();
    let what = format!("a={a} zeta={zeta} A={amp} x={x}");
    let u = u_wave_bounded(a, zeta, amp, x).unwrap();
    let du = du_wave_bounded(a, zeta, amp, x).unwrap();
    let u_scale = u_ref.to_f64().abs().max(amp.abs());
    let du_scale = du_ref.to_f64().abs().max(2.0 * std::f64::consts::PI * amp.abs() / zeta);
    check("u_wave_bounded", u, &u_ref, u_scale, &what);
    check("du_wave_bounded", du, &du_ref, du_scale, &what);
    let wb = WaveBessel::new(a, zeta, amp).unwrap();
    let (ub, dub) = wb.eval_bounded(x).unwrap();
    check("eval_bounded u", ub, &u_ref, u_scale, &what);
    check("eval_bounded du", dub, &du_ref, du_scale, &what);
}

#[test]
fn bound_holds_on_the_model_grid_and_region_edges() {
    let ratios = [1.0, 1.0 + 2f64.powi(-40), 1.0 + 2f64.powi(-20), 1.0005, 1.01, 1.2, 1.35, 1.5, 2.0, 2.5, 3.0, 3.5];
    for &a in &[0.5, 1.0, 1.75, 3.0, 4.25, 6.0] {
        for &r in &ratios {
            check_point(a, 1.125, 1.0, a * r);
        }
    }
    // other wavelengths and amplitudes (D from 0.6 to 75)
    for &(a, zeta, amp) in &[(0.5, 5.0, 0.25), (2.0, 0.5, 3.0), (6.0, 0.5, 1.0), (3.0, 2.0, -2.0)] {
        for &r in &[1.0, 1.1, 2.0, 3.0] {
            check_point(a, zeta, amp, a * r);
        }
    }
}

/// The contact edge to the last bit: `x` one ulp above `a` (and two), at both
/// ends of the model's `a` range and in between.
#[test]
fn bound_holds_one_ulp_above_the_edge() {
    for &a in &[0.5f64, 1.0, 2.2, 6.0] {
        let x1 = f64::from_bits(a.to_bits() + 1);
        let x2 = f64::from_bits(a.to_bits() + 2);
        check_point(a, 1.125, 1.0, x1);
        check_point(a, 1.125, -0.75, x2);
    }
}

/// Short wavelengths (`D = 2 pi a/zeta` from 628 to 2513), where the per-contact
/// Bessel data are built in MP: their sequence must carry digits (the ball
/// recurrence it used lost about `0.68 D` bits, and `u_wave_bounded(1, 0.01, 1, x)`
/// came back with a bound of 5.7e136 around a value of -31.6).
#[test]
fn short_wavelengths_keep_a_tight_bound() {
    for &(a, zeta) in &[(1.0, 0.01), (2.0, 0.005)] {
        for &r in &[1.0, 1.5, 3.0] {
            check_point(a, zeta, 1.0, a * r);
        }
    }
}

#[test]
fn beyond_the_native_region_the_mp_fallback_answers_and_is_counted() {
    let before = maugis::special::fallback_counts().wave_bounded;
    check_point(2.0, 1.125, 1.0, 2.0 * 4.0);
    assert!(maugis::special::fallback_counts().wave_bounded >= before + 1);
}

#[test]
fn wave_bessel_rejects_bad_x_with_a_typed_error() {
    let wb = WaveBessel::new(2.0, 1.125, 1.0).unwrap();
    for &x in &[f64::NAN, f64::INFINITY, f64::NEG_INFINITY, 1.999999, -3.0] {
        assert!(wb.eval(x).is_err(), "eval({x})");
        assert!(wb.eval_bounded(x).is_err(), "eval_bounded({x})");
    }
    assert!(wb.eval_many(&[2.5, f64::NAN]).is_err());
    assert!(wb.eval_bounded_many(&[2.5, 1.0]).is_err());
    let msg = wb.eval(1.5).unwrap_err().to_string();
    assert!(msg.contains("x >= a"), "{msg}");
}

#[test]
fn batch_equals_one_by_one() {
    let wb = WaveBessel::new(3.0, 1.125, 1.0).unwrap();
    let xs: Vec<f64> = (0..40).map(|i| 3.0 * (1.0 + i as f64 / 20.0)).collect();
    let many = wb.eval_many(&xs).unwrap();
    let many_b = wb.eval_bounded_many(&xs).unwrap();
    for (i, &x) in xs.iter().enumerate() {
        assert_eq!(many[i], wb.eval(x).unwrap());
        assert_eq!(many_b[i], wb.eval_bounded(x).unwrap());
        // u_wave from scratch (its own fast value path) agrees to the last bits
        let u = u_wave(3.0, 1.125, 1.0, x).unwrap();
        assert!((many[i].0 - u).abs() <= 2.0 * f64::EPSILON * u.abs().max(1.0), "x={x}: {} vs {u}", many[i].0);
        // the estimate path and the bounded path agree within the bound
        assert!(many_b[i].0.contains(many[i].0) || (many_b[i].0.value - many[i].0).abs() <= 4e-16 * 8.0);
    }
}

/// The into-slice batch: same results as one call per point, including a
/// point beyond the native region (the MP fallback) and the contact edge;
/// a length mismatch and a bad `x` are typed errors that write nothing.
#[test]
fn batch_into_a_slice() {
    let wb = WaveBessel::new(6.0, 1.125, 0.5).unwrap();
    let xs = [6.0, f64::from_bits(6.0f64.to_bits() + 1), 7.3, 12.0, 18.0, 6.0 * 4.0];
    let mut out = vec![(Bounded { value: 0.0, err: 0.0 }, Bounded { value: 0.0, err: 0.0 }); xs.len()];
    wb.eval_bounded_into(&xs, &mut out).unwrap();
    for (i, &x) in xs.iter().enumerate() {
        assert_eq!(out[i], wb.eval_bounded(x).unwrap(), "x={x}");
    }
    let mut short = vec![out[0]; 2];
    assert!(wb.eval_bounded_into(&xs, &mut short).is_err());
    let before = out.clone();
    assert!(wb.eval_bounded_into(&[7.0, 5.0, 8.0, 9.0, 10.0, 11.0], &mut out).is_err());
    assert_eq!(out, before);
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    #[test]
    fn bound_holds_at_random_points(a in 0.5f64..6.0, r in 1.0f64..3.0, amp in -3.0f64..3.0) {
        check_point(a, 1.125, amp, a * r);
    }
}
