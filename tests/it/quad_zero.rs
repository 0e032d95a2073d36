//! Zero and tiny integrals (issue 40, item 3): the default absolute tolerance
//! `2^-goal L`, `L` a certified upper bound of `int |f|`, for balls that contain 0
//! (`quad::certified::Options::abs_tol`). References are closed forms: the integrals of
//! odd integrands over symmetric ranges are 0, `int_{-1}^1 |sin x| = 2 (1 - cos 1)`,
//! `int_{-3}^3 |atan(tanh(tanh x))| <= 6 pi/4`. 2 to 333 bits, and 1000 in the long tier.

use maugis::ball::{Ball, Mag};
use maugis::quad::certified::{integrate, Options};
use maugis::quad::expr::{abs_tol_text, integrate_range, End, Expr};
use maugis::rug::Float;

fn expr(f: &str, a: &str, b: &str, prec: u32, opts: &Options) -> maugis::quad::certified::Integral {
    integrate_range(&Expr::parse(f).unwrap(), &End::parse(a).unwrap(), &End::parse(b).unwrap(), None, None, prec, opts)
        .unwrap_or_else(|e| panic!("{f} on [{a}, {b}] at {prec} bits: {e}"))
}

/// `(int |f|)` upper bounds from closed forms, and the integrals (both 0).
const ZERO: [(&str, &str, &str, f64); 3] = [
    ("sin(x)", "-1", "1", 0.9194), // 2 (1 - cos 1) = 0.91939...
    ("atan(tanh(tanh(x)))", "-3", "3", 4.7124), // < 6 pi/4
    // 2 int_0^inf x^3 e^-x^2 = 1; the range is folded, int_0^inf (f(x) + f(-x)) dx,
    // and the folded integrand of an odd f is 0 up to rounding: its tolerance is
    // that of the folded integrand (tiny), so only the upper check applies
    ("x^3*exp(-x^2)", "-inf", "inf", 1.0001),
];

#[test]
fn zero_integrals_meet_the_default_absolute_tolerance() {
    for (f, a, b, l1) in ZERO {
        // 1000 bits (seconds for the folded infinite range) in the long tier
        let precs: &[u32] = crate::tier::pick(&[2, 8, 53, 64, 333], &[2, 8, 53, 64, 333, 1000]);
        for &prec in precs {
            let r = expr(f, a, b, prec, &Options::new());
            let label = format!("{f} on [{a}, {b}] at {prec} bits");
            assert!(r.goal_met, "{label}: {:?}", r.value);
            assert!(r.value.contains_zero(), "{label}: {:?} does not contain 0", r.value);
            let t = r.abs_tol.unwrap_or_else(|| panic!("{label}: no absolute tolerance reported"));
            assert!(r.value.rad_mag().le(&t), "{label}: radius above the tolerance");
            // the tolerance is 2^-prec L, L the smaller of a certified bound of int |f| and
            // four times an estimate: within a factor 4 of int |f|
            let lower = Mag::from_f64(l1 * 0.5).mul_2exp(-(prec as i64));
            let upper = Mag::from_f64(l1 * 4.0).mul_2exp(-(prec as i64));
            let folded = a == "-inf";
            assert!((folded || lower.le(&t)) && t.le(&upper), "{label}: tolerance {:e} against int |f| = {l1}", t.to_f64_up());
            assert!(abs_tol_text(&r).is_some(), "{label}");
        }
    }
}

/// A tiny integral (`2e-30`) below `2^-64 int |f|` is answered the same way, and the
/// ball contains it; at 200 bits it is far above the tolerance and the relative goal
/// holds (no tolerance reported).
#[test]
fn tiny_integral_is_enclosed_at_every_precision() {
    let exact = Float::with_val(300, Float::parse("2e-30").unwrap());
    for prec in [64u32, 200] {
        let r = expr("sin(x) + 1e-30", "-1", "1", prec, &Options::new());
        assert!(r.goal_met && r.real().contains(&exact), "{prec}: {:?}", r.value);
        if prec == 64 {
            assert!(r.abs_tol.is_some(), "{:?}", r.value);
        } else {
            assert!(r.abs_tol.is_none() && r.real().meets_rel(prec), "{:?}", r.value);
        }
    }
}

/// A ball that keeps off 0 meets the relative goal: the default tolerance does not
/// weaken an integral with cancellation (`int_0^10 sin x = 1 - cos 10`, `int |f| = 6.2`).
#[test]
fn cancellation_keeps_the_relative_goal() {
    for prec in [64u32, 333] {
        let r = integrate(|x| x.sin(), &Ball::zero(prec), &Ball::from_i64(10, prec), prec, &Options::new()).unwrap();
        assert!(r.goal_met && r.abs_tol.is_none() && r.real().meets_rel(prec), "{prec}: {:?}", r.value);
    }
}

/// The caller's tolerance replaces the default and is reported; `relative_only`
/// turns the default off, and a zero integral then comes back flagged, still enclosing 0.
#[test]
fn caller_tolerance_and_relative_only() {
    let (a, b) = (Ball::from_i64(-1, 64), Ball::from_i64(1, 64));
    let o = Options::new().abs_tol(1e-10).unwrap();
    let r = integrate(|x| x.sin(), &a, &b, 64, &o).unwrap();
    assert!(r.goal_met && r.value.contains_zero(), "{:?}", r.value);
    assert!(r.abs_tol.is_some_and(|t| t.le(&Mag::from_f64(1e-10))));
    let r = integrate(|x| x.sin(), &a, &b, 64, &Options::new().relative_only().max_evaluations(20_000).unwrap()).unwrap();
    assert!(!r.goal_met && r.limit.is_some() && r.value.contains_zero() && r.abs_tol.is_none(), "{:?}", r);
}
