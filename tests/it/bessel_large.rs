//! J_n on the large (n, x) plane (issue 13): the grid n in {0, 1, 7, 60, 500,
//! 2000, 10000} x x in {0.001, ..., 1000000.5} and the edges of the
//! recurrence's regions against `reference/data/bessel_j_grid.csv` (mpmath,
//! 170 digits) at 53, 128 and 512 bits; the methods against each other where
//! their regions meet (two algorithms, two precisions, balls must overlap);
//! and no refusal over |n| <= 1e5, |x| <= 1e7, prec <= 4096.

use crate::common;

use maugis::special::bessel_j::{
    bessel_j_hankel, bessel_j_mp, bessel_j_series, bessel_j_three_term, choose_algorithm, Algorithm,
};
use maugis::Ball;
use rug::Float;

/// Relative uncertainty of a 170-digit reference (last digit, and the
/// 190-digit agreement of the generator's two runs).
const GRID_REF_SLACK: &str = "1e-168";

fn grid_reference(row: &common::Row) -> Float {
    Float::with_val(700, Float::parse(&row["value"]).expect("reference value parses"))
}

fn exact_x(row: &common::Row) -> Float {
    // The reference is at the binary64 number nearest the x text (as the bench and
    // the grid use it: exact except for 0.001).
    Float::with_val(53, common::col_f64(row, "x"))
}

fn encloses(ball: &Ball, reference: &Float) -> bool {
    let d = Float::with_val(800, ball.mid() - reference).abs();
    let slack = Float::with_val(800, reference.clone().abs() * Float::with_val(64, Float::parse(GRID_REF_SLACK).unwrap()));
    d <= Float::with_val(800, ball.rad() + &slack)
}

#[test]
fn grid_and_region_edges_against_mpmath() {
    let rows = common::load("bessel_j_grid");
    assert!(rows.len() >= 90, "bessel_j_grid has {} rows", rows.len());
    let mut failures = Vec::new();
    for prec in [53u32, 128, 512] {
        for row in &rows {
            let n = common::col_i64(row, "n");
            let x = exact_x(row);
            let r = grid_reference(row);
            match bessel_j_mp(n, &x, prec) {
                Ok(b) => {
                    if !encloses(&b, &r) {
                        failures.push(format!("prec {prec} n={n} x={}: {b:?} misses {}", row["x"], r.to_string_radix(10, Some(30))));
                    } else if !b.meets_rel(prec) {
                        failures.push(format!("prec {prec} n={n} x={}: {:.1} bits", row["x"], b.rel_accuracy_bits()));
                    }
                }
                Err(e) => failures.push(format!("prec {prec} n={n} x={}: error {e}", row["x"])),
            }
        }
    }
    assert!(failures.is_empty(), "{} failures:\n{}", failures.len(), failures.join("\n"));
}

#[test]
fn recurrence_meets_hankel_and_series() {
    // Where the recurrence's region meets Hankel's (x large against n) and the
    // power series' (x moderate): two algorithms, balls must overlap.
    for &(n, x, wp) in &[
        (60u64, 150.5, 200u32),
        (500, 999.5, 160),
        (500, 5000.25, 128),
        (2000, 20000.5, 300),
        (30, 30.25, 200),
        (31, 30.25, 200),
        (40, 30.25, 200),
        (150, 150.5, 140),
        (152, 150.5, 600),
    ] {
        let xf = Float::with_val(53, x);
        let j0 = bessel_j_mp(0, &xf, wp + 64).unwrap();
        let j1 = bessel_j_mp(1, &xf, wp + 64).unwrap();
        let r = bessel_j_three_term(n, &xf, &j0, &j1, wp + 64).unwrap();
        assert!(r.meets_rel(wp), "n={n} x={x}: recurrence gives {:.1} bits", r.rel_accuracy_bits());
        let other = match bessel_j_hankel(n, &xf, wp + 200).unwrap() {
            Some(h) if x >= 1000.0 => h,
            _ => bessel_j_series(n, &xf, wp + 200 + (1.45 * x) as u32).unwrap(),
        };
        assert!(r.overlaps(&other), "n={n} x={x}: {r:?} vs {other:?}");
    }
}

#[test]
fn chooser_uses_the_recurrence_where_n_and_x_are_both_large() {
    for &(n, x) in &[(10000u64, 20000.5), (2000, 5000.25), (10000, 99999.5)] {
        assert_eq!(choose_algorithm(n, x, 160), Algorithm::Recurrence, "n={n} x={x}");
    }
    // The old methods keep their regions.
    assert_eq!(choose_algorithm(0, 1000000.5, 160), Algorithm::Hankel);
    assert_eq!(choose_algorithm(7, 1.5, 160), Algorithm::PowerSeries);
    assert_eq!(choose_algorithm(10000, 150.5, 160), Algorithm::PowerSeries);
}

#[test]
fn no_refusal_on_the_documented_domain() {
    // |n| <= 1e5, |x| <= 1e7: corners, the turning point, and both signs.
    let points: &[(i64, f64, u32)] = &[
        (100_000, 1.0e7, 128),
        (-100_000, 100_000.5, 128),
        (100_000, 100_000.0, 128),
        (100_000, 50_000.25, 64),
        (100_000, 0.75, 128),
        (99_999, -1.0e7, 64),
        (2000, 5000.25, 4096),
        (60, 9_999_999.5, 4096),
    ];
    for &(n, x, prec) in points {
        let xf = Float::with_val(53, x);
        let b = bessel_j_mp(n, &xf, prec).unwrap_or_else(|e| panic!("n={n} x={x} prec={prec}: {e}"));
        assert!(b.meets_rel(prec), "n={n} x={x}: {:.1} bits", b.rel_accuracy_bits());
        let hi = bessel_j_mp(n, &xf, prec + 64).unwrap();
        assert!(b.overlaps(&hi), "n={n} x={x}: {b:?} vs {hi:?}");
    }
}

#[test]
fn recurrence_identity_across_methods() {
    // J_{n-1} + J_{n+1} = (2n/x) J_n [DLMF 10.6.1] where neighbouring orders may
    // take different methods (the turning point x = 20000.5 lies between 20000 and 20001).
    let x = Float::with_val(53, 20000.5);
    for n in [400i64, 2000, 20000, 20001, 20002] {
        let p = 200;
        let a = bessel_j_mp(n - 1, &x, p).unwrap();
        let b = bessel_j_mp(n, &x, p).unwrap();
        let c = bessel_j_mp(n + 1, &x, p).unwrap();
        let xb = Ball::from_float(&x, p);
        let lhs = a.add(&c);
        let rhs = b.mul_i64(2 * n).div(&xb).unwrap();
        assert!(lhs.overlaps(&rhs), "n={n}: {lhs:?} vs {rhs:?}");
    }
}

#[test]
fn hankel_and_series_overlap_where_n_squared_exceeds_x() {
    // n^2/x from 0.4 to 80: Hankel with the DLMF 10.17(iv) remainder and its
    // exp(n^2/x) factor against the power series.
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
