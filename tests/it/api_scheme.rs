//! The API scheme of `special` (issue 26 item 4), one function family at a time:
//! `f_native_bounded(args, rel_tol) -> Result<Option<Bounded>>` means the same for
//! 1F2, 2F1 and G: a typed error for a bad argument or tolerance, `Some` only with
//! a proven bound within `rel_tol`, and that bound encloses the certified value.

use maugis::special::{hyp1f2, hyp2f1, meijer_g};
use maugis::{Bounded, Error};

/// `b` encloses the 64-bit ball `exact` and meets `rel_tol`.
fn check(what: &str, b: Option<Bounded>, exact: maugis::Ball, rel_tol: f64) {
    let b = b.unwrap_or_else(|| panic!("{what}: the native path should certify this point"));
    assert!(b.err <= rel_tol * b.value.abs(), "{what}: {b:?} misses {rel_tol}");
    let (lo, hi) = (exact.lower().to_f64(), exact.upper().to_f64());
    assert!(b.value - b.err <= hi && lo <= b.value + b.err, "{what}: {b:?} misses [{lo}, {hi}]");
}

fn f(x: f64) -> rug::Float {
    rug::Float::with_val(64, x)
}

#[test]
fn native_bounded_encloses_and_meets_the_tolerance() {
    for rel_tol in [1e-14, 1e-10] {
        let b = hyp1f2::hyp1f2_native_bounded(0.5, 3.0, 3.5, -20.0, rel_tol).unwrap();
        check("1F2", b, hyp1f2::hyp1f2_mp(&f(0.5), &f(3.0), &f(3.5), &f(-20.0), 64).unwrap(), rel_tol);
        let b = hyp2f1::hyp2f1_native_bounded(0.5, 0.25, 1.5, 0.3, rel_tol).unwrap();
        check("2F1", b, hyp2f1::hyp2f1_mp(&f(0.5), &f(0.25), &f(1.5), &f(0.3), 64).unwrap(), rel_tol);
        let b = meijer_g::meijer_g_k_native_bounded(5, 0.5, rel_tol).unwrap();
        check("G", b, meijer_g::meijer_g_k_mp(5, &f(0.5), 64).unwrap(), rel_tol);
    }
}

#[test]
fn native_bounded_refuses_bad_arguments_and_tolerances_alike() {
    for rel_tol in [0.0, -1e-14, f64::NAN, f64::INFINITY] {
        for (what, r) in [
            ("1F2", hyp1f2::hyp1f2_native_bounded(0.5, 3.0, 3.5, -20.0, rel_tol)),
            ("2F1", hyp2f1::hyp2f1_native_bounded(0.5, 0.25, 1.5, 0.3, rel_tol)),
            ("G", meijer_g::meijer_g_k_native_bounded(5, 0.5, rel_tol)),
        ] {
            assert!(matches!(r, Err(Error::OutOfRange { arg, .. }) if arg.starts_with("rel_tol")), "{what} at rel_tol {rel_tol}: {r:?}");
        }
    }
    assert!(matches!(hyp1f2::hyp1f2_native_bounded(f64::NAN, 3.0, 3.5, -20.0, 1e-14), Err(Error::NonFinite { what: "a" })));
    assert!(matches!(hyp2f1::hyp2f1_native_bounded(0.5, 0.25, 1.5, f64::NAN, 1e-14), Err(Error::NonFinite { what: "z" })));
    assert!(matches!(meijer_g::meijer_g_k_native_bounded(5, f64::NAN, 1e-14), Err(Error::NonFinite { what: "y" })));
    assert!(matches!(meijer_g::meijer_g_k_native_bounded(5, 1.5, 1e-14), Err(Error::OutOfRange { .. })));
    assert!(matches!(hyp2f1::hyp2f1_native_bounded(0.5, 0.25, 1.5, 1.5, 1e-14), Err(_)));
}
