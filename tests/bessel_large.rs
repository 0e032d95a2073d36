//! J_n on the large (n, x) plane: Hankel's expansion with the DLMF 10.17(iv)
//! remainder against the power series where both run (two algorithms, two
//! precisions, balls must overlap), and grid points that used to be refused.

use maugis::special::bessel_j::{bessel_j_hankel, bessel_j_mp, bessel_j_series, choose_algorithm, Algorithm};
use rug::Float;

#[test]
fn hankel_and_series_overlap_where_n_squared_exceeds_x() {
    // n^2/x from 0.4 to 80: the old rule (x >= n^2/8) refused Hankel at most of these.
    for &(n, x, wp) in &[(60u64, 150.5, 160u32), (100, 400.25, 200), (200, 1000.5, 140), (500, 5000.25, 128), (40, 20.5, 256)] {
        let xf = Float::with_val(53, x);
        let Some(h) = bessel_j_hankel(n, &xf, wp + 200).unwrap() else {
            assert!(n == 40, "Hankel must reach the target at n={n} x={x}");
            continue;
        };
        let series_wp = wp + 200 + (1.45 * x) as u32;
        let s = bessel_j_series(n, &xf, series_wp).unwrap();
        assert!(h.overlaps(&s), "n={n} x={x}: {h:?} vs {s:?}");
        assert!(h.meets_rel(wp), "n={n} x={x}: {:.1} bits", h.rel_accuracy_bits());
    }
}

#[test]
fn former_refusals_answer_with_full_precision() {
    // Refused on main at 4add25a ("would need ~144293 guard bits in the power series").
    for &(n, x) in &[(2000i64, 99999.5), (10000, 1000000.5), (-1200, 50000.25), (500, 30000.0)] {
        let xf = Float::with_val(53, x);
        assert_eq!(choose_algorithm(n.unsigned_abs(), x, 160), Algorithm::Hankel);
        let lo = bessel_j_mp(n, &xf, 128).unwrap();
        let hi = bessel_j_mp(n, &xf, 256).unwrap();
        assert!(lo.meets_rel(128) && hi.meets_rel(256), "n={n} x={x}");
        assert!(lo.overlaps(&hi), "n={n} x={x}: {lo:?} vs {hi:?}");
    }
}

#[test]
fn recurrence_holds_across_methods() {
    // J_{n-1} + J_{n+1} = (2n/x) J_n [DLMF 10.6.1] where the chooser switches
    // method between neighbouring orders.
    let x = Float::with_val(53, 20000.5);
    for n in [400i64, 2000] {
        let p = 200;
        let a = bessel_j_mp(n - 1, &x, p).unwrap();
        let b = bessel_j_mp(n, &x, p).unwrap();
        let c = bessel_j_mp(n + 1, &x, p).unwrap();
        let xb = maugis::Ball::from_float(&x, p);
        let lhs = a.add(&c);
        let rhs = b.mul_i64(2 * n).div(&xb).unwrap();
        assert!(lhs.overlaps(&rhs), "n={n}: {lhs:?} vs {rhs:?}");
    }
}
