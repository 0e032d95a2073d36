//! The f64 `2F1`: the bound of `hyp2f1_bounded` encloses the exact value for
//! the f64 inputs as given, and `hyp2f1` stays within `1e-14` on the issue-8
//! domain, as properties (proptest) and at the hard places of the native path:
//! its crossovers (`z = -4`, `-1/2`, `0.7`, `0.9`, one ulp either side), `a - b`
//! and `c - a - b` at the connection formulas' `0.05` cut-off and near integers,
//! next to zeros of `2F1` (where the sums cancel and the double-word head
//! takes over), next to `z = 1` and with `c` next to the poles. The reference is
//! the certified 120-bit ball.

use maugis::special::{exact, hyp2f1};
use proptest::prelude::*;
use rug::Float;

/// `|exact - value|` rounded up, from the certified 120-bit ball.
fn error_of(a: f64, b: f64, c: f64, z: f64, value: f64) -> f64 {
    let m = hyp2f1::hyp2f1_mp(&exact(a), &exact(b), &exact(c), &exact(z), 120).expect("2F1 in MP");
    Float::with_val(200, m.mid() - value).abs().to_f64() * (1.0 + 1e-15) + m.rad().to_f64()
}

/// The bound holds (and is finite), and the value path agrees with the
/// bounded one to its own bound.
fn check_bound(a: f64, b: f64, c: f64, z: f64) -> Result<(), TestCaseError> {
    let r = hyp2f1::hyp2f1_bounded(a, b, c, z).expect("2F1 f64");
    prop_assert!(r.err.is_finite() && r.err >= 0.0, "2F1({a}, {b}; {c}; {z}): bound {:e}", r.err);
    let e = error_of(a, b, c, z, r.value);
    prop_assert!(e <= r.err, "2F1({a}, {b}; {c}; {z}) = {:e}: |error| {e:e} > bound {:e}", r.value, r.err);
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 256, .. ProptestConfig::default() })]

    /// The issue-8 domain: the bound holds and the value path is within 1e-14.
    #[test]
    fn bound_and_value_on_the_issue_domain(a in -3.0f64..3.0, b in -3.0f64..3.0, c in 0.5f64..6.0, z in -5.0f64..0.9) {
        check_bound(a, b, c, z)?;
        let v = hyp2f1::hyp2f1(a, b, c, z).expect("2F1 f64");
        let e = error_of(a, b, c, z, v);
        prop_assert!(e <= 1e-14 * v.abs(), "2F1({a}, {b}; {c}; {z}) = {v:e}: relative error {:e}", e / v.abs());
    }

    /// A wider domain (larger parameters, z down to -50 and up to 1): the bound
    /// holds wherever it is returned.
    #[test]
    fn bound_on_a_wider_domain(a in -10.0f64..10.0, b in -10.0f64..10.0, c in 0.25f64..15.0, z in -50.0f64..1.0) {
        check_bound(a, b, c, z)?;
    }
}

/// `x` moved by `k` ulps.
fn ulps(x: f64, k: i64) -> f64 {
    let bits = x.to_bits() as i64;
    f64::from_bits(if x >= 0.0 { bits + k } else { bits - k } as u64)
}

/// A deterministic point generator (the LCG of the benches).
struct Lcg(u64);

impl Lcg {
    fn uniform(&mut self, lo: f64, hi: f64) -> f64 {
        self.0 = self.0.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
        lo + (hi - lo) * ((self.0 >> 11) as f64 / (1u64 << 53) as f64)
    }
}

fn assert_bound(a: f64, b: f64, c: f64, z: f64) {
    if let Err(e) = check_bound(a, b, c, z) {
        panic!("{e}");
    }
}

/// The native path's crossovers, one ulp either side, with random parameters.
#[test]
fn bound_holds_at_the_crossovers() {
    let mut rng = Lcg(0xed6e);
    let (mut native, mut total) = (0, 0);
    for z0 in [-4.0, -3.0, -1.0, -0.5, 0.5, 0.7, 0.9] {
        for k in [-1, 0, 1] {
            let z = ulps(z0, k);
            for _ in 0..40 {
                let (a, b, c) = (rng.uniform(-3.0, 3.0), rng.uniform(-3.0, 3.0), rng.uniform(0.5, 6.0));
                assert_bound(a, b, c, z);
                total += 1;
                let n = hyp2f1::hyp2f1_native_bounded(a, b, c, z, hyp2f1::NATIVE_ACCEPT_REL).unwrap();
                native += n.is_some() as u32;
            }
        }
    }
    // the points test the native path, not only the MP fallback
    assert!(native as f64 >= 0.97 * total as f64, "native {native} of {total}");
}

/// `a - b` at the connection formula's cut-off (0.05 from an integer) and near
/// integers, for `z <= -4`; `c - a - b` likewise for `9/10 < z < 1`.
#[test]
fn bound_holds_next_to_the_log_cases() {
    let mut rng = Lcg(0x10c);
    for d in [0.05, 0.0500001, 0.0499999, 1e-3, 1e-8, 0.0] {
        for _ in 0..25 {
            let (b, c) = (rng.uniform(-3.0, 3.0), rng.uniform(0.5, 6.0));
            let m = rng.uniform(-2.0, 2.0).round();
            let a = b + m + d;
            assert_bound(a, b, c, rng.uniform(-5.0, -4.0));
            let a2 = rng.uniform(-3.0, 3.0);
            let b2 = c - a2 - m - d;
            assert_bound(a2, b2, c, rng.uniform(0.9, 0.999));
        }
    }
}

/// Next to zeros of `2F1` in `z` (the sums cancel): `2F1(-a, b; c; z)` with a
/// zero located by bisection on the MP value, and the f64 points around it.
#[test]
fn bound_holds_next_to_zeros() {
    let cases = [(-2.5, 1.5, 2.0), (-1.7, 2.3, 1.1), (-2.9, -0.4, 3.5), (2.2, -2.6, 1.3)];
    let mut found = 0;
    for (a, b, c) in cases {
        // scan z in [-5, 0.9] for a sign change of the MP value, then bisect in f64
        let f = |z: f64| hyp2f1::hyp2f1_mp(&exact(a), &exact(b), &exact(c), &exact(z), 120).unwrap().mid().to_f64();
        let mut lo = -5.0;
        let mut f_lo = f(lo);
        let mut z = lo;
        while z < 0.9 {
            z = (z + 0.05f64).min(0.9);
            let f_z = f(z);
            if f_lo.signum() != f_z.signum() {
                let (mut x0, mut x1) = (lo, z);
                for _ in 0..60 {
                    let mid = 0.5 * (x0 + x1);
                    if f(mid).signum() == f_lo.signum() {
                        x0 = mid;
                    } else {
                        x1 = mid;
                    }
                }
                found += 1;
                for k in -3..=3 {
                    assert_bound(a, b, c, ulps(x0, k));
                }
                for dz in [1e-12, 1e-9, 1e-6] {
                    assert_bound(a, b, c, x0 - dz);
                    assert_bound(a, b, c, x0 + dz);
                }
            }
            lo = z;
            f_lo = f_z;
        }
    }
    assert!(found >= 3, "zeros found: {found}");
}

/// Next to `z = 1` (the 1-z connection formula above 9/10, one and eight ulps
/// below 1, and `z = 1` itself, Gauss's sum) with `c - a - b > 0`, and `c` next
/// to the poles `0, -1, -2` of the series, from both sides.
#[test]
fn bound_holds_next_to_one_and_the_poles() {
    let mut rng = Lcg(0x1e1);
    for _ in 0..40 {
        let (a, b) = (rng.uniform(-3.0, 3.0), rng.uniform(-3.0, 3.0));
        let c = a + b + rng.uniform(0.1, 3.0);
        if c == c.floor() && c <= 0.0 {
            continue;
        }
        for z in [1.0, ulps(1.0, -1), ulps(1.0, -8), 1.0 - 1e-12, 1.0 - 1e-6, 0.95] {
            assert_bound(a, b, c, z);
        }
    }
    for k in 0..3 {
        for d in [1e-12, 1e-6, 1e-3] {
            for side in [-1.0, 1.0] {
                let c = -(k as f64) + side * d;
                for z in [-4.5, -2.0, -0.7, 0.3, 0.8] {
                    let (a, b) = (rng.uniform(-3.0, 3.0), rng.uniform(-3.0, 3.0));
                    assert_bound(a, b, c, z);
                }
            }
        }
    }
}
