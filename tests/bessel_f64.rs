//! The native f64 J_n: its proven bound holds against the certified MP value
//! (random points over n <= 60, x <= 150, edges, near zeros), and the plain
//! f64 value is within 2 ulp.

use maugis::special::bessel_j::{bessel_j, bessel_j_bounded, bessel_j_mp};
use proptest::prelude::*;
use rug::Float;

fn check(n: i64, x: f64) -> Result<(), String> {
    let b = bessel_j_bounded(n, x).map_err(|e| e.to_string())?;
    let exact = bessel_j_mp(n, &Float::with_val(53, x), 160).map_err(|e| e.to_string())?;
    let diff = Float::with_val(200, exact.mid() - b.value).abs();
    let allowed = Float::with_val(200, b.err) - exact.rad();
    if diff > allowed {
        return Err(format!("J_{n}({x}): {b} misses {:?}", exact));
    }
    if b.err > 1e-14 * b.value.abs() && b.err > 1e-300 {
        // A wide bound is only acceptable from the MP fallback near a zero.
        let rel = b.err / b.value.abs();
        if rel > 1e-14 {
            return Err(format!("J_{n}({x}): bound {rel:e} relative"));
        }
    }
    let v = bessel_j(n, x).map_err(|e| e.to_string())?;
    let ulp = f64::EPSILON * exact.to_f64().abs();
    let e = (v - exact.to_f64()).abs();
    if e > 2.0 * ulp {
        return Err(format!("J_{n}({x}) = {v}: error {e:e} > 2 ulp"));
    }
    Ok(())
}

#[test]
fn edges_and_zeros() {
    // Doubles next to zeros j_{0,1}, j_{1,1}, j_{2,1}, j_{0,5}.
    let zeros: [(i64, f64); 4] = [(0, 2.404825557695773), (1, 3.8317059702075125), (2, 5.135622301840683), (0, 14.930917708487787)];
    for &(n, z) in &zeros {
        for x in [z, z.next_up(), z.next_down()] {
            check(n, x).unwrap();
        }
    }
    for &(n, x) in &[(0i64, 1e-300), (60, 1e-3), (60, 150.0), (0, 150.0), (1, 36.0), (0, 35.5), (60, 64.0), (-7, -3.25), (30, 30.0)] {
        check(n, x).unwrap();
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(400))]
    #[test]
    fn bound_holds_over_the_domain(n in 0i64..=60, x in 1e-6f64..150.0) {
        prop_assert!(check(n, x).is_ok(), "{}", check(n, x).unwrap_err());
    }
}
