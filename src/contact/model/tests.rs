//! Unit tests of the model at one contact size (moved with the split of `model.rs`).

use super::*;
use super::strip::SERIES_Z;
use crate::contact::displacement::{profile_depth, u_adhesive, u_hertz};
use crate::error::Error;

#[cfg(feature = "serde")]
#[test]
fn params_deserialize_through_the_checks() {
    let p = Params::new(0.5, 0.25, 1.125).unwrap();
    let json = serde_json::to_string(&p).unwrap();
    assert_eq!(json, r#"{"lambda":0.5,"alpha":0.25,"beta":1.125}"#);
    assert_eq!(serde_json::from_str::<Params>(&json).unwrap(), p);
    // out of range or missing: refused with the constructor's message, not built
    for bad in [r#"{"lambda":-1.0,"alpha":0.25,"beta":1.125}"#, r#"{"lambda":0.5,"alpha":0.25,"beta":0.0}"#, r#"{"lambda":0.5,"alpha":0.25}"#] {
        let e = serde_json::from_str::<Params>(bad).unwrap_err().to_string();
        assert!(e.contains("lambda") || e.contains("beta"), "{bad}: {e}");
    }
}

#[test]
fn params_accessors_and_with_lambda() {
    let p = Params::new(0.5, 0.25, 1.125).unwrap();
    assert_eq!((p.lambda(), p.alpha(), p.beta()), (0.5, 0.25, 1.125));
    assert_eq!(p.with_lambda(3.0).unwrap(), Params::new(3.0, 0.25, 1.125).unwrap());
    assert!(matches!(p.with_lambda(f64::NAN), Err(Error::NonFinite { what: "lambda" })));
    assert!(matches!(p.with_lambda(-1.0), Err(Error::OutOfRange { .. })));
}

#[test]
fn smooth_case_is_johnson_greenwood() {
    // alpha = 0: F(m) has no wave term; the root satisfies the JG equation.
    let p = Params::new(1.0, 0.0, 1.0).unwrap();
    let cs = ContactSize::new(p, 2.0).unwrap();
    let m = cs.solve_m().unwrap();
    assert!(cs.strip_residual(m).unwrap().abs() < 1e-12);
    assert!(m > 1.0);
}

#[test]
fn residual_is_minus_one_at_the_edge() {
    let p = Params::new(1.5, 2f64.sqrt() / 4.0, 1.125).unwrap();
    for abar in [0.5, 2.0, 5.5] {
        let cs = ContactSize::new(p, abar).unwrap();
        assert!((cs.strip_residual(1.0).unwrap() + 1.0).abs() < 1e-12);
    }
}

/// The well-conditioned strip gap equals `h - u_H - u_w - u_a` from the
/// displacement module where that is accurate (a wide strip).
#[test]
fn strip_gap_matches_the_displacement_sum() {
    let p = Params::new(0.7, 0.3, 1.3).unwrap();
    let cs = ContactSize::new(p, 1.9).unwrap();
    let strip = StripEnd::from_m_minus_1(0.4).unwrap();
    for t in [0.01, 0.2, 0.5, 0.9, 0.999, 1.0] {
        let x = 1.9 * (1.0 + 0.4 * t);
        let direct = profile_depth(1.0, 0.3, 1.3, x).unwrap()
            - u_hertz(1.9, 1.0, x).unwrap()
            - cs.wave_displacement(x).unwrap()
            - u_adhesive(1.9, 1.9 * 1.4, 0.7, 1.0, x).unwrap();
        let g = cs.strip_gap(strip, t);
        assert!((g - direct).abs() < 1e-12 * (1.0 + direct.abs()), "t = {t}: {g} vs {direct}");
    }
}

/// The series branches of the strip functions join their closed forms.
#[test]
fn strip_function_series_join_closed_forms() {
    let z = SERIES_Z;
    let below = z * (1.0 - 1e-12);
    for (f, name) in [(hertz_gap_fn as fn(f64) -> f64, "H"), (adhesive_approach_fn, "P")] {
        let (a, b) = (f(below), f(z));
        assert!((a - b).abs() < 1e-10 * b.abs(), "{name}: {a} vs {b}");
    }
}

#[test]
fn state_functions_reject_bad_m_and_x() {
    let p = Params::new(1.0, 0.2, 1.0).unwrap();
    let cs = ContactSize::new(p, 1.0).unwrap();
    for m in [f64::NAN, f64::INFINITY, 1.0, 0.5, -2.0] {
        assert!(cs.load(m).is_err(), "load({m})");
        assert!(cs.traction(m, 0.3).is_err(), "traction({m})");
        assert!(cs.displacement(m, 2.0).is_err());
        assert!(cs.gap(m, 2.0).is_err());
        assert!(cs.validity(m).is_err());
        assert!(cs.approach(m).is_err());
    }
    for m in [f64::NAN, 0.99, f64::NEG_INFINITY] {
        assert!(cs.strip_residual(m).is_err(), "strip_residual({m})");
        assert!(cs.strip_gap_terms(m).is_err());
    }
    assert!(cs.strip_residual_m_minus_1(-1e-3).is_err());
    assert!(cs.traction(1.2, f64::NAN).is_err());
    assert!(cs.wave_displacement(f64::NAN).is_err());
    assert!(StripEnd::from_m_minus_1(0.0).is_err());
    assert!(StripEnd::from_m_minus_1(f64::NAN).is_err());
}

#[test]
fn bad_parameters() {
    assert!(Params::new(0.0, 0.1, 1.0).is_err());
    assert!(Params::new(1.0, -0.1, 1.0).is_err());
    assert!(Params::new(1.0, 0.1, 0.0).is_err());
    assert!(Params::new(f64::NAN, 0.1, 1.0).is_err());
    let p = Params::new(1.0, 0.1, 1.0).unwrap();
    assert!(ContactSize::new(p, 0.0).is_err());
}
