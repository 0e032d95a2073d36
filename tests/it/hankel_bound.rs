//! Hankel's expansion of `H^(1)_n` and its error bound (DLMF 10.17.13-15, as
//! `src/ball/complex/hankel.rs` implements them) against the true remainder.
//!
//! The reference values of `H^(1)_n(z)` (120 digits) come from
//! `reference/generate_hankel.py` (mpmath). For each point and each `l = 1..24` the test
//! forms the true remainder `R_l = H (pi z/2)^(1/2) e^{-i omega} - sum_{k<l} i^k a_k
//! z^-k` in ball arithmetic at 600 bits and checks `|R_l| <= CBall::hankel_remainder_bound`.
//! The points run from `|z| = 1/2` (far outside the range where the expansion is useful,
//! where the bound is large but must still hold) to 45, and from `ph z` near `-pi/2`
//! (where DLMF 10.17.15 has the factor `chi(l)` and the exponent `chi(1) = pi/2`) to near
//! `pi/2`. The test has teeth: it also asserts that somewhere the true remainder is
//! within a factor 2.2 of the bound (on the real axis, where `R_l` is about the first
//! neglected term and the bound twice that), so a bound too small by that factor fails.

use maugis::ball::{CBall, Decimal, Mag};
use maugis::Ball;

const CSV: &str = include_str!("../../reference/data/hankel1.csv");
const P: u32 = 600;

struct Row {
    n: i64,
    z: CBall,
    h: CBall,
    label: String,
}

fn dec(s: &str) -> Ball {
    Decimal::parse(s).unwrap_or_else(|e| panic!("{s}: {e}")).to_ball(P)
}

fn rows() -> Vec<Row> {
    CSV.lines()
        .skip(1)
        .map(|line| {
            let f: Vec<&str> = line.split(',').collect();
            assert_eq!(f.len(), 5, "{line}");
            let n: i64 = f[0].parse().unwrap();
            let z = CBall::new(dec(f[1]), dec(f[2]));
            assert!(z.is_exact(), "{line}: the points are dyadic");
            Row { n, z, h: CBall::new(dec(f[3]), dec(f[4])), label: format!("n {n} z {}{:+}i", f[1], f[2].parse::<f64>().unwrap()) }
        })
        .collect()
}

/// `(pi z/2)^(1/2) e^{-i omega} H`, `omega = z - n pi/2 - pi/4`: the full sum
/// `sum_{k<l} i^k a_k z^-k + R_l`.
fn scaled(row: &Row) -> CBall {
    let pi = Ball::pi(P);
    let root = row.z.mul_real(&pi).mul_real(&Ball::from_ratio(1, 2, P)).sqrt();
    let omega = row.z.sub(&CBall::from_real(pi.mul(&Ball::from_ratio(2 * row.n + 1, 4, P))));
    root.mul(&omega.mul_i().neg().exp()).mul(&row.h)
}

fn mag_f64(m: &Mag) -> f64 {
    m.to_f64_up()
}

#[test]
fn true_remainder_never_exceeds_the_bound() {
    let mut worst = 0.0f64;
    let mut worst_below = 0.0f64;
    let mut checked = 0;
    for row in rows() {
        let full = scaled(&row);
        assert!(full.rad_mag().le(&Mag::pow2(-300)), "{}: reference too wide {:?}", row.label, full);
        let inv = row.z.recip();
        let mu = 4 * row.n * row.n;
        let mut partial = CBall::zero(P);
        let mut term = CBall::one(P);
        for l in 1..=24u64 {
            // partial = sum_{k < l}
            partial = partial.add(&term);
            let k = l as i64;
            term = term.mul(&inv).mul_i().mul_real(&Ball::from_ratio(mu - (2 * k - 1) * (2 * k - 1), 8 * k, P));
            let r = full.sub(&partial);
            let bound = CBall::hankel_remainder_bound(row.n, l, &row.z);
            assert!(bound.is_finite(), "{} l {l}: no bound", row.label);
            assert!(
                r.abs_upper_mag().le(&bound),
                "{} l {l}: |R_l| = {:e} exceeds the bound {:e}",
                row.label,
                mag_f64(&r.abs_upper_mag()),
                mag_f64(&bound)
            );
            let ratio = mag_f64(&r.abs_lower_mag()) / mag_f64(&bound);
            worst = worst.max(ratio);
            if row.z.im().is_negative() {
                worst_below = worst_below.max(ratio);
            }
            checked += 1;
        }
    }
    eprintln!("hankel_bound: {checked} remainders, largest |R_l| / bound {worst:.3} (below the axis {worst_below:.3})");
    assert_eq!(checked, 378 * 24);
    assert!(worst > 1.0 / 2.2, "no point comes within 2.2x of the bound ({worst}): the test would not catch a bound that small");
    assert!(worst_below > 0.3, "below the axis no point comes within 3.3x of the bound ({worst_below})");
}

/// The expansion's ball contains `H^(1)_n(z)` (and, through the symmetries, `H^(2)_n`
/// and negative orders) wherever it is used (`Re z > 0`), and is narrow where `|z|` is
/// large enough for the goal.
#[test]
fn expansion_contains_the_reference() {
    for row in rows() {
        for p in [64u32, 256] {
            let z = row.z.set_prec(p);
            let h = z.hankel1_large(row.n);
            assert!(h.overlaps(&row.h), "{} at {p} bits: {h:?}", row.label);
            let h2 = z.conj().hankel2_large(row.n);
            assert!(h2.overlaps(&row.h.conj()), "{} at {p} bits, H^(2) at conj z: {h2:?}", row.label);
            let sign = if row.n % 2 == 1 { -1 } else { 1 };
            let hm = z.hankel1_large(-row.n);
            assert!(hm.overlaps(&row.h.mul_i64(sign)), "{} at {p} bits, order -n: {hm:?}", row.label);
            let r = z.abs_lower_mag().to_f64_up();
            if r >= 0.35 * (p as f64 + 60.0) {
                let rel = h.rad_mag().to_f64_up() / row.h.abs_lower_mag().to_f64_up();
                assert!(rel < 2f64.powi(-(p as i32) + 8), "{} at {p} bits: relative radius {rel:e}", row.label);
            }
        }
    }
}

/// `hankel_sum_bound(n, rho)` bounds `|(pi z/2)^(1/2) e^{-i omega} H^(1)_n(z)|` for
/// every `|z| >= rho`, `-pi/2 <= ph z <= pi`: the factor `K` of the Hankel-type tails.
#[test]
fn sum_bound_holds_at_every_reference_point() {
    for row in rows() {
        let full = scaled(&row);
        let rho = row.z.abs_lower_mag();
        let k = CBall::hankel_sum_bound(row.n, rho);
        assert!(full.abs_upper_mag().le(&k), "{}: |sum| = {:e} > {:e}", row.label, mag_f64(&full.abs_upper_mag()), mag_f64(&k));
    }
    // and the bound is not vacuous where the integrator uses it (|w| T >= 0.35 (64 + 60))
    let k = CBall::hankel_sum_bound(0, Mag::from_f64(44.0));
    assert!(k.le(&Mag::from_f64(1.05)), "{:e}", mag_f64(&k));
}
