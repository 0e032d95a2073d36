//! Identities as properties (proptest), each checked on certified balls: an
//! identity holds when the ball of `lhs - rhs` contains zero (or, for the
//! non-rigorous finite-difference and perturbation checks, is within a stated
//! tolerance).

use maugis::special::{bessel_j, exact, hyp2f1, meijer_g};
use maugis::Ball;
use proptest::prelude::*;
use rug::Float;

const P: u32 = 128;

fn j(n: i64, x: f64) -> Ball {
    bessel_j::bessel_j_mp(n, &exact(x), P).expect("J_n")
}

fn f21(a: f64, b: f64, c: f64, z: f64) -> Ball {
    hyp2f1::hyp2f1_mp(&exact(a), &exact(b), &exact(c), &exact(z), P).expect("2F1")
}

/// A dyadic number m / 2^e (exactly representable).
fn dyadic(m: i64, e: i32) -> f64 {
    m as f64 * 2f64.powi(-e)
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 64, .. ProptestConfig::default() })]

    /// DLMF 10.6.1: J_{n-1}(x) + J_{n+1}(x) = (2n/x) J_n(x).
    #[test]
    fn bessel_three_term_recurrence(n in -60i64..60, m in 1i64..(200 << 8)) {
        let x = dyadic(m, 8);
        let lhs = j(n - 1, x).add(&j(n + 1, x));
        let rhs = j(n, x).mul_i64(2 * n).div(&Ball::from_f64(x, P).unwrap()).unwrap();
        prop_assert!(lhs.overlaps(&rhs), "n={} x={}: {:?} vs {:?}", n, x, lhs, rhs);
    }

    /// DLMF 15.5.11 (Gauss contiguous relation):
    /// (c - a) F(a-1) + (2a - c + (b - a) z) F(a) + a (z - 1) F(a+1) = 0,
    /// across all regions of z (direct, Pfaff, 1-z, z < -1).
    #[test]
    fn hyp2f1_contiguous_relation(
        am in -40i64..40, bm in -40i64..40, cm in 1i64..60, zm in -4000i64..1000
    ) {
        let a = dyadic(am, 3) + 0.0625;
        let b = dyadic(bm, 3) + 0.1875;
        let c = dyadic(cm, 2) + 0.125;
        let z = dyadic(zm, 10);
        prop_assume!(z < 1.0);
        let p = |v: f64| Ball::from_f64(v, P).unwrap();
        let f_m = f21(a - 1.0, b, c, z);
        let f_0 = f21(a, b, c, z);
        let f_p = f21(a + 1.0, b, c, z);
        let t1 = p(c - a).mul(&f_m);
        let t2 = p(2.0 * a - c).add(&p(b - a).mul(&p(z))).mul(&f_0);
        let t3 = p(a).mul(&p(z).sub(&Ball::one(P))).mul(&f_p);
        let sum = t1.add(&t2).add(&t3);
        prop_assert!(sum.contains(&Float::new(P)), "a={} b={} c={} z={}: {:?}", a, b, c, z, sum);
    }

    /// D.41a of the seed: the Meijer-G bracket B(y) = G(k,y)/C_k has
    /// dB/dy = -2F1(1, k+1/2; k+2; y)/(2y). Central difference with h = 2^-24 at
    /// 128 bits: the O(h^2) truncation is far below the 1e-9 relative tolerance.
    #[test]
    fn meijer_bracket_derivative_is_2f1(k in 0u32..300, ym in 16i64..1000) {
        let y = dyadic(ym, 10);
        let h = 2f64.powi(-24);
        let g = |yy: f64| meijer_g::meijer_g_k_mp(k, &exact(yy), P).unwrap();
        let c_k = {
            let kf = Float::with_val(64, k);
            let g1 = Ball::from_float(&Float::with_val(64, &kf + 0.5), P).gamma().unwrap();
            let g2 = Ball::from_float(&Float::with_val(64, &kf + 2u32), P).gamma().unwrap();
            g1.div(&g2).unwrap().mul_pow2(1)
        };
        let diff = g(y + h).sub(&g(y - h)).div(&Ball::from_f64(2.0 * h, P).unwrap()).unwrap().div(&c_k).unwrap();
        let expect = f21(1.0, k as f64 + 0.5, k as f64 + 2.0, y).div(&Ball::from_f64(-2.0 * y, P).unwrap()).unwrap();
        let rel = diff.sub(&expect).abs_upper().to_f64() / expect.abs_lower().to_f64();
        prop_assert!(rel < 1e-9, "k={} y={}: rel {}", k, y, rel);
    }
}

/// Slater's theorem at slightly perturbed parameters (b2 = eps instead of 0)
/// against the closed form of the degenerate family. The perturbation moves the
/// value by O(eps |ln eps|), so the tolerance is 1e-6 relative at eps = 2^-32.
#[test]
fn slater_perturbed_matches_family() {
    let eps = 2f64.powi(-32);
    for k in [0u32, 1, 2, 5, 12] {
        for &y in &[0.125, 0.375, 0.5, 0.8125, 0.96875] {
            let a = [0.0, 0.5 - k as f64, 1.0];
            let b = [0.0, eps, -(k as f64) - 1.0];
            let (re, _im) = meijer_g::meijer_g33_slater_mp(a, b, -y, 256).expect("slater");
            let fam = meijer_g::meijer_g_k_mp(k, &exact(y), 128).expect("family");
            let d = re.sub(&fam).abs_upper().to_f64();
            let scale = fam.abs_upper().to_f64().max(1e-3);
            assert!(d <= 1e-6 * scale, "k={k} y={y}: slater {re:?} vs family {fam:?}");
        }
    }
}

/// Two precisions, one algorithm: balls at 100 and 300 bits must overlap
/// (Arb's standard consistency test), for every function.
#[test]
fn two_precisions_overlap() {
    let pts = [0.03125, 0.5, 0.9375, 0.999_999_999_999, 1.0];
    for k in [0u32, 1, 3, 40, 1000] {
        for &y in &pts {
            let lo = meijer_g::meijer_g_k_mp(k, &exact(y), 100).unwrap();
            let hi = meijer_g::meijer_g_k_mp(k, &exact(y), 300).unwrap();
            assert!(lo.overlaps(&hi), "G({k},{y})");
        }
    }
    for &(n, x) in &[(0i64, 0.5), (7, 33.25), (-4, 1234.5), (300, 299.0)] {
        let lo = bessel_j::bessel_j_mp(n, &exact(x), 100).unwrap();
        let hi = bessel_j::bessel_j_mp(n, &exact(x), 300).unwrap();
        assert!(lo.overlaps(&hi), "J_{n}({x})");
    }
    for &z in &[-1e5, -3.0, -0.75, 0.25, 0.75, 0.999_999, 1.0] {
        let lo = hyp2f1::hyp2f1_mp(&exact(1.0), &exact(10.5), &exact(12.0), &exact(z), 100).unwrap();
        let hi = hyp2f1::hyp2f1_mp(&exact(1.0), &exact(10.5), &exact(12.0), &exact(z), 300).unwrap();
        assert!(lo.overlaps(&hi), "2F1 at {z}");
    }
}
