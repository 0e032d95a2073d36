//! No public function panics on any input: arbitrary arguments, including NaN,
//! infinities, signed zeros, subnormals, huge and tiny values, must give `Ok` or
//! a typed `Err`, never a panic. (Arguments are drawn from ranges where the
//! functions answer quickly; how long a valid but extreme request takes is a
//! separate matter, documented per function.)

use std::panic::{catch_unwind, AssertUnwindSafe};

use maugis::contact::curve::state;
use maugis::contact::displacement::{du_wave, u_adhesive, u_hertz, u_wave, u_wave_series_mp};
use maugis::contact::model::Params;
use maugis::special::{bessel_j, exact, hyp1f2, hyp2f1, meijer_g};
use proptest::prelude::*;

/// Special values plus moderate numbers.
fn arg() -> impl Strategy<Value = f64> {
    prop_oneof![
        Just(f64::NAN),
        Just(f64::INFINITY),
        Just(f64::NEG_INFINITY),
        Just(0.0),
        Just(-0.0),
        Just(5e-324),
        Just(f64::MIN_POSITIVE),
        Just(1.0),
        Just(-1.0),
        Just(0.5),
        Just(1e-300),
        (-40i32..40).prop_map(|k| k as f64),
        -30.0f64..30.0,
        -1.0f64..1.0,
    ]
}

fn no_panic<T>(what: &str, f: impl FnOnce() -> T) {
    let r = catch_unwind(AssertUnwindSafe(f));
    assert!(r.is_ok(), "{what} panicked");
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 200, .. ProptestConfig::default() })]

    #[test]
    fn special_functions_never_panic(n in -50i64..50, k in 0u32..60, a in arg(), b in arg(), c in arg(), z in arg()) {
        no_panic("bessel_j", || bessel_j::bessel_j(n, z));
        no_panic("bessel_j_mp", || bessel_j::bessel_j_mp(n, &exact(z), 64));
        no_panic("hyp1f2", || hyp1f2::hyp1f2(a, b, c, z));
        no_panic("hyp1f2_mp", || hyp1f2::hyp1f2_mp(&exact(a), &exact(b), &exact(c), &exact(z), 64));
        no_panic("hyp2f1", || hyp2f1::hyp2f1(a, b, c, z));
        no_panic("hyp2f1_mp", || hyp2f1::hyp2f1_mp(&exact(a), &exact(b), &exact(c), &exact(z), 64));
        no_panic("meijer_g_k", || meijer_g::meijer_g_k(k, z));
        no_panic("meijer_g_k_mp", || meijer_g::meijer_g_k_mp(k, &exact(z.abs()), 64));
    }

    #[test]
    fn contact_functions_never_panic(a in arg(), zeta in arg(), amp in arg(), x in arg(), kmax in 0u64..50) {
        no_panic("u_wave", || u_wave(a, zeta, amp, x));
        no_panic("du_wave", || du_wave(a, zeta, amp, x));
        no_panic("u_wave_series_mp", || u_wave_series_mp(&exact(a), &exact(zeta), &exact(amp), &exact(x), kmax, 64));
        no_panic("u_hertz", || u_hertz(a, zeta, x));
        no_panic("u_adhesive", || u_adhesive(a, zeta, amp, 1.0, x));
        no_panic("model state", || Params::new(amp.abs(), zeta.abs(), x.abs()).and_then(|p| state(p, a)));
    }
}

#[test]
fn nan_and_infinity_are_typed_errors() {
    for v in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
        assert!(bessel_j::bessel_j(1, v).is_err());
        assert!(hyp1f2::hyp1f2(0.5, 1.0, 1.5, v).is_err());
        assert!(hyp2f1::hyp2f1(1.0, 1.0, 2.0, v).is_err());
        assert!(meijer_g::meijer_g_k(1, v).is_err());
        assert!(u_wave(1.0, 1.0, 1.0, v).is_err());
        assert!(Params::new(v, 0.1, 1.0).is_err());
    }
    // past the documented domain (|n| <= 1e5): an answer where the recurrence
    // makes it cheap, and a time-limit error instead of hours of work where not
    assert!(bessel_j::bessel_j(200_000, 200_000.0).is_ok_and(f64::is_finite));
    let x = rug::Float::with_val(53, 999_999.5);
    assert!(bessel_j::bessel_j_mp(1_000_000, &x, 65_536).is_err());
}

/// Issue 26: orders and arguments whose sequence would not fit in memory (or whose
/// start order overflowed `usize`) give the empty sequence of the documented contract.
#[test]
fn huge_sequence_orders_and_arguments_do_not_panic() {
    use maugis::ball::Dd;
    assert!(bessel_j::bessel_j_sequence_dd(usize::MAX, Dd::from_f64(1.0)).is_empty());
    assert!(bessel_j::bessel_j_sequence(usize::MAX, 1.0).is_empty());
    assert!(bessel_j::bessel_j_sequence(2, 1e20).is_empty());
    assert!(bessel_j::bessel_j_sequence(bessel_j::MAX_SEQUENCE_ORDER + 1, 1.0).is_empty());
    assert!(bessel_j::bessel_j_sequence(2, -2.0 * bessel_j::MAX_SEQUENCE_ARGUMENT).is_empty());
    // at the edge of the range an answer
    let s = bessel_j::bessel_j_sequence(3, 2.5);
    assert_eq!(s.len(), 4);
    assert!((s[0] - bessel_j::bessel_j(0, 2.5).unwrap()).abs() < 1e-15);
}
