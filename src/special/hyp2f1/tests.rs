//! Unit tests of the 2F1 algorithms against closed forms, contiguous relations
//! and each other.

use rug::float::Round;
use rug::Float;

use super::choose::{choose_algorithm, Algorithm};
use super::connection::{hyp2f1_connection, hyp2f1_gauss, hyp2f1_pfaff_connection};
use super::log_case::hyp2f1_connection_log;
use super::polynomial::{hyp2f1_polynomial, poly_rational, to_rational};
use super::series::series_2f1;
use super::transform::{hyp2f1_direct, hyp2f1_euler, hyp2f1_pfaff};
use super::*;
use crate::special::exact_add;
use crate::special::gamma::xball;
use crate::special::pfq::pfq_series;

/// Deterministic uniform points (64-bit LCG, Knuth's constants), shared by the
/// native-path tests.
pub(super) struct Lcg(pub(super) u64);

impl Lcg {
    pub(super) fn uniform(&mut self, lo: f64, hi: f64) -> f64 {
        self.0 = self.0.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
        lo + (hi - lo) * ((self.0 >> 11) as f64 / (1u64 << 53) as f64)
    }
}

const P: u32 = 128;
/// Precision of the independently computed reference balls.
const REF: u32 = 320;

fn f(x: f64) -> Float {
    exact(x)
}

fn mp(a: f64, b: f64, c: f64, z: f64) -> Ball {
    let r = hyp2f1_mp(&f(a), &f(b), &f(c), &f(z), P);
    match r {
        Ok(v) => {
            assert!(v.meets_rel(P), "2F1({a},{b};{c};{z}) not certified to {P} bits: {v:?}");
            v
        }
        Err(e) => panic!("2F1({a},{b};{c};{z}): {e}"),
    }
}

fn check(name: &str, got: &Ball, want: &Ball) {
    assert!(got.overlaps(want), "{name}: got {got:?}, closed form {want:?}");
}

fn zb(z: f64) -> Ball {
    Ball::from_f64(z, REF).unwrap()
}

/// `-ln(1 - z)` as a ball.
fn ell(z: f64) -> Ball {
    xball(&exact_sub(&one(), &f(z)), REF).ln().unwrap().neg()
}

/// Monotone increasing MPFR function at a ball, through its endpoints.
fn monotone(x: &Ball, g: impl Fn(&Float, Round) -> Float) -> Ball {
    Ball::hull(&g(&x.lower(), Round::Down), &g(&x.upper(), Round::Up), REF)
}

#[test]
fn log_cases_match_elementary_closed_forms() {
    // c - a - b = 0, 1, 2, -1, -2 (DLMF 15.4.2 and partial fractions).
    let zs = [0.3, -0.3, 0.55, 0.6, 0.75, 0.9, 0.999, 1.0 - 2f64.powi(-40), -0.75, -1.0, -1.5, -3.0, -77.25, -1e6];
    for &z in &zs {
        let (zz, l) = (zb(z), ell(z));
        let one_b = Ball::one(REF);
        let l1 = l.div(&zz).unwrap();
        let l2 = l.sub(&zz).div(&zz.sqr()).unwrap();
        let l3 = l.sub(&zz).sub(&zz.sqr().mul_pow2(-1)).div(&zz.sqr().mul(&zz)).unwrap();
        let omz = one_b.sub(&zz);
        check(&format!("2F1(1,1;2;{z})"), &mp(1.0, 1.0, 2.0, z), &l1);
        // 2F1(1,1;3;z) = 2((1-z) ln(1-z) + z)/z^2
        let w = omz.mul(&l.neg()).add(&zz).mul_pow2(1).div(&zz.sqr()).unwrap();
        check(&format!("2F1(1,1;3;{z})"), &mp(1.0, 1.0, 3.0, z), &w);
        // 2F1(1,1;4;z) = 3 (L1 - 2 L2 + L3)
        let w = l1.sub(&l2.mul_pow2(1)).add(&l3).mul_i64(3);
        check(&format!("2F1(1,1;4;{z})"), &mp(1.0, 1.0, 4.0, z), &w);
        // 2F1(2,2;3;z) = 2/(1-z) - 2 L2
        let w = omz.recip().unwrap().sub(&l2).mul_pow2(1);
        check(&format!("2F1(2,2;3;{z})"), &mp(2.0, 2.0, 3.0, z), &w);
        // 2F1(3,3;4;z) = 3/2 (z/(1-z)^2 + 2 L3)
        let w = zz.div(&omz.sqr()).unwrap().add(&l3.mul_pow2(1)).mul_i64(3).mul_pow2(-1);
        check(&format!("2F1(3,3;4;{z})"), &mp(3.0, 3.0, 4.0, z), &w);
    }
}

#[test]
fn complete_elliptic_integral_via_agm() {
    // 2F1(1/2, 1/2; 1; z) = 1 / AGM(1, sqrt(1 - z)): degenerate with m = 0.
    for &z in &[0.3, 0.7, 0.95, 1.0 - 1e-12, -0.4, -0.8, -5.0, -1e4] {
        let r = xball(&exact_sub(&one(), &f(z)), REF).sqrt().unwrap();
        let agm = monotone(&r, |x, rnd| Float::with_val_round(REF, Float::with_val(REF, 1).agm_ref(x), rnd).0);
        check(&format!("K at {z}"), &mp(0.5, 0.5, 1.0, z), &agm.recip().unwrap());
    }
}

#[test]
fn arcsin_and_arsinh_closed_forms() {
    // 2F1(1/2, 1/2; 3/2; x^2) = asin(x)/x, 2F1(1/2, 1/2; 3/2; -x^2) = asinh(x)/x (c-a-b = 1/2).
    for &x in &[0.5, 0.75, 0.875, 0.96875, 1.0 - 2f64.powi(-20), 1.0] {
        let xb = zb(x);
        let w = monotone(&xb, |v, rnd| Float::with_val_round(REF, v.asin_ref(), rnd).0).div(&xb).unwrap();
        check(&format!("asin {x}"), &mp(0.5, 0.5, 1.5, x * x), &w);
    }
    for &x in &[0.5, 0.75, 1.5, 2.0, 100.0] {
        let xb = zb(x);
        let w = monotone(&xb, |v, rnd| Float::with_val_round(REF, v.asinh_ref(), rnd).0).div(&xb).unwrap();
        check(&format!("asinh {x}"), &mp(0.5, 0.5, 1.5, -x * x), &w);
    }
}

#[test]
fn power_closed_form_b_equals_c() {
    // 2F1(a, b; b; z) = (1 - z)^{-a} [DLMF 15.4.6]
    for &(a, b) in &[(0.3, 2.7), (-1.75, 0.5), (4.5, 12.0)] {
        for &z in &[0.3, -0.7, 0.8, 0.999, -5.0, -1e5] {
            let w = xball(&exact_sub(&one(), &f(z)), REF).pow(&zb(-a)).unwrap();
            check(&format!("(1-z)^-a a={a} z={z}"), &mp(a, b, b, z), &w);
            check(&format!("(1-z)^-a a={a} z={z} swapped"), &mp(b, a, b, z), &w);
        }
    }
}

#[test]
fn model_case_closed_forms_and_gauss() {
    // k = 0: 2F1(1, 1/2; 2; y) = 2 (1 - sqrt(1 - y)) / y.
    for &y in &[0.3, 0.7, 1.0 - 1e-12, 1.0] {
        let yy = zb(y);
        let sq = xball(&exact_sub(&one(), &f(y)), REF).sqrt().unwrap();
        let w = Ball::one(REF).sub(&sq).mul_pow2(1).div(&yy).unwrap();
        check(&format!("k=0 y={y}"), &mp(1.0, 0.5, 2.0, y), &w);
    }
    // Gauss: 2F1(1, k+1/2; k+2; 1) = Gamma(k+2) Gamma(1/2) / (Gamma(k+1) Gamma(3/2)) = 2 (k+1).
    for &k in &[0.0, 1.0, 10.0, 1000.0] {
        let g = mp(1.0, k + 0.5, k + 2.0, 1.0);
        assert!(g.contains(&Float::with_val(64, 2.0 * (k + 1.0))), "k={k}: {g:?}");
        assert_eq!(choose_algorithm(&f(1.0), &f(k + 0.5), &f(k + 2.0), &f(1.0), P), Algorithm::Gauss);
    }
    // Certified near 1 and across (0, 1].
    for &k in &[0.0, 3.0, 100.0, 1000.0] {
        for &y in &[0.1, 0.5, 0.6, 0.9, 0.99, 1.0 - 1e-6, 1.0 - 1e-12, 1.0] {
            let _ = mp(1.0, k + 0.5, k + 2.0, y);
        }
    }
}

/// DLMF 15.5.11: (c-a) F(a-1) + (2a - c + (b-a) z) F(a) + a (z-1) F(a+1) = 0
/// (`a - 1`, `a + 1` formed exactly).
fn contiguous_a(a: f64, b: f64, c: f64, z: f64) {
    let (af, bf, cf, zf) = (f(a), f(b), f(c), f(z));
    let run = |x: &Float| -> Ball {
        let v = hyp2f1_mp(x, &bf, &cf, &zf, P).unwrap_or_else(|e| panic!("2F1({x},{b};{c};{z}): {e}"));
        assert!(v.meets_rel(P), "2F1({x},{b};{c};{z}) not certified: {v:?}");
        v
    };
    let fm = run(&exact_sub(&af, &one()));
    let f0 = run(&af);
    let fp = run(&exact_add(&af, &one()));
    let (ab, bb, cb, zz) = (zb(a), zb(b), zb(c), zb(z));
    let coef0 = ab.mul_i64(2).sub(&cb).add(&bb.sub(&ab).mul(&zz));
    let sum = cb.sub(&ab).mul(&fm).add(&coef0.mul(&f0)).add(&ab.mul(&zz.sub(&Ball::one(REF))).mul(&fp));
    assert!(sum.contains(&Float::new(64)), "contiguous relation a={a} b={b} c={c} z={z}: {sum:?}");
    // the relation is not trivially satisfied by wide balls
    let scale = f0.abs_upper();
    assert!(sum.rad() < Float::with_val(64, &scale * 1e-30), "too wide: {sum:?}");
}

#[test]
fn contiguous_relations_across_regions() {
    // c - a - b = 2, 1, 0 for a-1, a, a+1 (logarithmic cases), and generic parameters.
    for &z in &[0.3, -0.4, -0.9, 0.6, 0.7, 0.95, 1.0 - 1e-10, -3.0, -50.0, -1e6] {
        contiguous_a(0.375, 1.4375, 2.8125, z);
        contiguous_a(-2.3, 4.1, 1.7, z);
        contiguous_a(2.5, -7.25, 0.375, z);
        // b - a integer (logarithmic after Pfaff for z < -1)
        contiguous_a(0.75, 2.75, 1.125, z);
    }
    // Model-like large parameters, including c - a - b = 1/2 and -1/2.
    for &z in &[0.3, 0.6, 0.9, 0.999, 1.0 - 1e-12, -0.7, -20.0] {
        contiguous_a(1.0, 1000.5, 1002.0, z);
        contiguous_a(1.0, 10.5, 12.0, z);
    }
}

#[test]
fn algorithms_agree_where_both_apply() {
    let wp = 200;
    let ok = |x: &Ball, y: &Ball, what: &str| {
        assert!(x.overlaps(y), "{what}: {x:?} vs {y:?}");
        assert!(x.meets_rel(wp - 40) && y.meets_rel(wp - 40), "{what}: not accurate {x:?} {y:?}");
    };
    for &(a, b, c) in &[(0.3, 1.7, 2.9), (-2.5, 3.25, 1.5), (1.0, 10.5, 12.0), (4.0, -3.5, 7.25)] {
        let (a, b, c) = (f(a), f(b), f(c));
        for &z in &[0.55, 0.6, 0.7] {
            let d = hyp2f1_direct(&a, &b, &c, &f(z), 2 * wp).unwrap();
            let k = hyp2f1_connection(&a, &b, &c, &f(z), wp).unwrap();
            ok(&d, &k, &format!("direct vs 1-z at {z}"));
        }
        for &z in &[-0.4, -0.6, -0.9] {
            let d = hyp2f1_direct(&a, &b, &c, &f(z), 2 * wp).unwrap();
            let p = hyp2f1_pfaff(&a, &b, &c, &f(z), wp).unwrap();
            ok(&d, &p, &format!("direct vs Pfaff at {z}"));
        }
        for &z in &[-1.25, -1.5, -3.0] {
            let p = hyp2f1_pfaff(&a, &b, &c, &f(z), 2 * wp).unwrap();
            let q = hyp2f1_pfaff_connection(&a, &b, &c, &f(z), wp).unwrap();
            ok(&p, &q, &format!("Pfaff vs Pfaff+1-w at {z}"));
        }
    }
    // Logarithmic cases: m = 2, -1, 0, 3 against the direct series; b - a integer after Pfaff.
    for &(a, b, c) in &[(0.375, 1.625, 4.0), (1.25, 0.5, 0.75), (0.5, 0.5, 1.0), (-0.75, 2.5, 4.75), (2.5, 4.5, 4.0)] {
        let (a, b, c) = (f(a), f(b), f(c));
        for &z in &[0.55, 0.7] {
            let d = hyp2f1_direct(&a, &b, &c, &f(z), 2 * wp).unwrap();
            let k = hyp2f1_connection_log(&a, &b, &c, &f(z), wp).unwrap();
            ok(&d, &k, &format!("direct vs log at {z}"));
        }
    }
    for &(a, b, c) in &[(0.375, 2.375, 1.875), (1.5, 1.5, 0.25), (-1.5, 1.5, 3.5)] {
        let (a, b, c) = (f(a), f(b), f(c));
        for &z in &[-1.5, -2.5] {
            let p = hyp2f1_pfaff(&a, &b, &c, &f(z), 2 * wp).unwrap();
            let q = hyp2f1_pfaff_connection(&a, &b, &c, &f(z), wp).unwrap();
            ok(&p, &q, &format!("Pfaff vs Pfaff+log at {z}"));
        }
    }
    // Gauss's sum vs the terminating series at z = 1 (Chu-Vandermonde).
    let (a, b, c) = (f(-3.0), f(2.25), f(7.5));
    let g = hyp2f1_gauss(&a, &b, &c, wp).unwrap();
    let p = hyp2f1_polynomial(&a, &b, &c, &f(1.0), wp).unwrap();
    ok(&g, &p, "Gauss vs polynomial");
    // Series engine vs the ball-arithmetic pFq core at a ball argument.
    let zball = Ball::from_ratio(-1, 3, wp);
    let e = series_2f1(&f(0.3), &f(-1.7), &f(2.9), &zball, wp).unwrap();
    let q = pfq_series(&[Ball::from_f64(0.3, wp).unwrap(), Ball::from_f64(-1.7, wp).unwrap()], &[Ball::from_f64(2.9, wp).unwrap()], &zball, wp)
        .unwrap()
        .sum;
    ok(&e, &q, "series engine vs pfq core");
}

#[test]
fn terminating_and_euler_polynomials() {
    // Chu-Vandermonde zero: 2F1(-3, 2; 1; 1) = (c-b)_3/(c)_3 = (-1)_3 / 1 = 0, exactly.
    let zero = hyp2f1_mp(&f(-3.0), &f(2.0), &f(1.0), &f(1.0), P).unwrap();
    assert!(zero.is_exact() && zero.mid().is_zero(), "{zero:?}");
    let zero = hyp2f1_mp(&f(-2.0), &f(2.5), &f(1.5), &f(1.0), P).unwrap();
    assert!(zero.is_exact() && zero.mid().is_zero(), "{zero:?}");
    // 2F1(-2, b; c; z) = 1 - 2 b z / c + b (b+1) z^2 / (c (c+1)), also with c = -3 (allowed).
    for &(b, c) in &[(0.7, 2.5), (3.0, -3.0), (-1.5, 0.25)] {
        for &z in &[-1e6, -3.0, -0.75, 0.3, 0.9, 1.0] {
            let (bb, cb, zz) = (zb(b), zb(c), zb(z));
            let w = Ball::one(REF)
                .sub(&bb.mul(&zz).mul_i64(2).div(&cb).unwrap())
                .add(&bb.mul(&bb.add_i64(1)).mul(&zz.sqr()).div(&cb.mul(&cb.add_i64(1))).unwrap());
            check(&format!("poly b={b} c={c} z={z}"), &mp(-2.0, b, c, z), &w);
        }
    }
    // Long polynomial (series engine) vs the exact rational sum.
    let (a, b, c, z) = (f(-400.0), f(0.5), f(1.5), f(-0.25));
    let s = series_2f1(&a, &b, &c, &xball(&z, 300), 300).unwrap();
    let q = poly_rational(&a, &b, &c, &to_rational(&z).unwrap(), 400).unwrap();
    assert!(s.contains(&Float::with_val(600, &q)), "{s:?}");
    // Euler polynomial: c - a = -2, compared with the direct series at z = 0.8.
    let (a, b, c) = (f(2.5), f(0.7), f(0.5));
    assert_eq!(choose_algorithm(&a, &b, &c, &f(0.8), P), Algorithm::Euler);
    let e = hyp2f1_euler(&a, &b, &c, &f(0.8), 200).unwrap();
    let d = hyp2f1_direct(&a, &b, &c, &f(0.8), 400).unwrap();
    assert!(e.overlaps(&d), "{e:?} vs {d:?}");
    // ... and after Pfaff for z < -1 (c - b = -3 makes the transformed series terminate).
    let (a, b, c) = (f(0.3), f(4.25), f(1.25));
    let p = mp(0.3, 4.25, 1.25, -7.5);
    let q = hyp2f1_pfaff_connection(&a, &b, &c, &f(-7.5), 200).unwrap();
    assert!(p.overlaps(&q));
}

#[test]
fn algorithm_choice_by_region() {
    let ch = |a: f64, b: f64, c: f64, z: f64| choose_algorithm(&f(a), &f(b), &f(c), &f(z), P);
    assert_eq!(ch(0.3, 1.7, 2.9, 0.5), Algorithm::Direct);
    assert_eq!(ch(0.3, 1.7, 2.9, -0.2), Algorithm::Direct);
    // |w| = 1/3 < 1/2: Pfaff is cheaper at z = -1/2.
    assert!(matches!(ch(0.3, 1.7, 2.9, -0.5), Algorithm::Pfaff | Algorithm::PfaffSwapped));
    // Large negative a: the direct series cancels. Since issue 37 one parameter of
    // 2000, at least 16 times the others, takes the large-parameter route (its series
    // in u = 1/2 need about 150 terms; Euler's transform thousands of positive ones).
    assert_eq!(ch(-2000.5, 2.0, 3.0, 0.5), Algorithm::LargeParam);
    assert_eq!(ch(0.3, 1.7, 2.9, -0.75), Algorithm::Pfaff);
    assert_eq!(ch(0.3, 1.7, 2.9, 0.9), Algorithm::Connection);
    assert_eq!(ch(1.0, 1.0, 2.0, 0.9), Algorithm::ConnectionLog);
    assert_eq!(ch(0.3, 1.7, 2.9, -5.0), Algorithm::PfaffConnection);
    assert_eq!(ch(1.0, 1.0, 2.0, -50.0), Algorithm::PfaffConnectionLog);
    assert_eq!(ch(0.3, 1.7, 2.9, 1.0), Algorithm::Gauss);
    assert_eq!(ch(-3.0, 1.7, 2.9, -1e6), Algorithm::Polynomial);
    // Model case: direct series where the 1-z pieces would cancel, 1-z formula near 1.
    assert_eq!(ch(1.0, 1000.5, 1002.0, 0.6), Algorithm::Direct);
    assert_eq!(ch(1.0, 1000.5, 1002.0, 1.0 - 1e-12), Algorithm::Connection);
}

#[test]
fn f64_matches_mp_on_a_grid() {
    let zs = [-1e6, -30.0, -2.0, -1.0, -0.7, -0.3, 0.1, 0.45, 0.5, 0.6, 0.9, 1.0 - 1e-9, 1.0];
    let mut n = 0;
    for &a in &[-2.5, -2.0, 0.5, 1.0, 3.7] {
        for &b in &[-1.3, 0.25, 2.0] {
            for &c in &[0.25, 1.5, 5.0] {
                for &z in &zs {
                    let m = hyp2f1_mp(&f(a), &f(b), &f(c), &f(z), 80);
                    let v = hyp2f1(a, b, c, z);
                    match (m, v) {
                        (Ok(m), Ok(v)) => {
                            let w = m.to_f64();
                            assert!((v - w).abs() <= 1e-14 * w.abs(), "2F1({a},{b};{c};{z}): {v} vs {w}");
                            n += 1;
                        }
                        (Err(_), Err(_)) => assert_eq!(z, 1.0, "({a},{b};{c};{z}) failed"),
                        (m, v) => panic!("2F1({a},{b};{c};{z}): mp {m:?} vs f64 {v:?}"),
                    }
                }
            }
        }
    }
    assert!(n > 500);
}

#[test]
fn high_precision() {
    let prec = 1000;
    let z = f(0.9);
    let v = hyp2f1_mp(&f(1.0), &f(1.0), &f(2.0), &z, prec).unwrap();
    assert!(v.meets_rel(prec));
    let l = xball(&exact_sub(&one(), &z), prec + 100).ln().unwrap().neg().div(&xball(&z, prec + 100)).unwrap();
    assert!(v.overlaps(&l), "{v:?} vs {l:?}");
    for &y in &[0.3, 0.9, 1.0 - 1e-12] {
        let m = hyp2f1_mp(&f(1.0), &f(1000.5), &f(1002.0), &f(y), prec).unwrap();
        let lo = hyp2f1_mp(&f(1.0), &f(1000.5), &f(1002.0), &f(y), 100).unwrap();
        assert!(m.meets_rel(prec) && m.overlaps(&lo), "{m:?} vs {lo:?}");
    }
}

#[test]
fn bad_input_is_an_error() {
    let nan = f64::NAN;
    let inf = f64::INFINITY;
    for args in [[nan, 1.0, 1.0, 0.5], [1.0, inf, 1.0, 0.5], [1.0, 1.0, -inf, 0.5], [1.0, 1.0, 1.0, nan]] {
        assert!(matches!(hyp2f1(args[0], args[1], args[2], args[3]), Err(Error::NonFinite { .. })));
    }
    assert!(matches!(hyp2f1(1.0, 1.0, 2.0, 1.5), Err(Error::OutOfRange { arg: "z", value: 1.5, .. })));
    assert!(matches!(hyp2f1(1.0, 1.0, -2.0, 0.5), Err(Error::ParameterPole { arg: "c", pole: -2.0, .. })));
    assert!(matches!(hyp2f1(-5.0, 1.0, -2.0, 0.5), Err(Error::ParameterPole { arg: "c", pole: -2.0, .. })));
    assert!(matches!(hyp2f1(1.0, 1.0, 2.0, 1.0), Err(Error::Divergent { value: 0.0, .. })));
    assert!(matches!(hyp2f1(1.0, 2.0, 2.5, 1.0), Err(Error::Divergent { value: -0.5, .. })));
    assert!(hyp2f1(-2.0, 1.0, -2.0, 0.5).is_ok());
    assert!(hyp2f1_mp(&f(1.0), &f(1.0), &f(2.0), &f(0.5), 0).is_err());
    assert!(hyp2f1_mp(&f(1.0), &f(1.0), &f(2.0), &f(0.5), crate::MAX_PREC + 1).is_err());
    assert!(hyp2f1_mp(&f(1.0), &f(1.0), &Float::with_val(53, rug::float::Special::Nan), &f(0.5), 64).is_err());
    assert!(hyp2f1_direct(&f(1.0), &f(1.0), &f(2.0), &f(1.0), 64).is_err());
    assert!(hyp2f1_connection(&f(1.0), &f(1.0), &f(2.0), &f(0.7), 64).is_err());
    assert!(hyp2f1_connection_log(&f(1.0), &f(1.5), &f(2.0), &f(0.7), 64).is_err());
    assert_eq!(hyp2f1(0.3, 0.4, 0.5, 0.0).unwrap(), 1.0);
}

#[test]
fn f64_fallback_refuses_what_it_cannot_do_in_time() {
    // issue 23 item 5 (docs/fuzzing.md): parameters like 1e300 used to send the
    // f64 functions' MP fallback to 65 536 bits and beyond for minutes
    for (a, b, c, z) in [(1e300, 2.0, 3.0, 0.5), (1e300, -1e300, 3.0, 0.5), (-1e300, 2.5, 3.5, -0.5), (1e10, 1e10, 2.5, 0.3)] {
        for r in [hyp2f1(a, b, c, z).map(|_| ()), hyp2f1_bounded(a, b, c, z).map(|_| ())] {
            assert!(
                matches!(r, Err(Error::OutOfRange { value, allowed, .. }) if value > F64_FALLBACK_MAX_PARAM && allowed.hi == F64_FALLBACK_MAX_PARAM),
                "2F1({a}, {b}; {c}; {z}): {r:?}"
            );
        }
    }
    // what the native path certifies is still answered at any size
    assert!((hyp2f1(1.5, 1e300, 1e300, 0.5).unwrap() - 2f64.powf(1.5)).abs() < 1e-14);
    // within the parameter cap, more than F64_FALLBACK_MAX_WP bits of cancellation is refused at that precision
    let r = hyp2f1_bounded(1e4, 1e4, 2.5, -0.9);
    assert!(
        matches!(r, Err(Error::PrecisionExhausted { working_prec, .. }) if working_prec == crate::special::F64_FALLBACK_MAX_WP),
        "{r:?}"
    );
}

#[test]
fn f64_mp_fallbacks_are_counted() {
    // one fallback counter API for every f64 function (issue 26 item 4): 2F1 counts too.
    // Candidates next to z = 1 and with large parameters, where the native f64 path
    // does not certify; at least one of them must fall back, or the test checks nothing.
    let candidates = [(40.5, -35.25, 2.5, 0.999), (100.5, 90.25, 1.5, -0.99), (-60.5, 70.25, 0.75, 0.9999), (1.0e3, 1.5, 2.25, -0.999)];
    let mut fell_back = 0;
    for (a, b, c, z) in candidates {
        if hyp2f1_native_bounded(a, b, c, z, NATIVE_ACCEPT_REL).unwrap().is_some() {
            continue;
        }
        fell_back += 1;
        let before = crate::special::fallback_counts();
        let r = hyp2f1_bounded(a, b, c, z);
        let d = crate::special::fallback_counts().since(&before);
        assert!(r.is_ok(), "2F1({a}, {b}; {c}; {z}): {r:?}");
        assert!(d.hyp2f1 >= 1, "2F1({a}, {b}; {c}; {z}) fell back uncounted: {d:?}");
        if hyp2f1_native_bounded(a, b, c, z, NATIVE_VALUE_REL).unwrap().is_none() {
            let before = crate::special::fallback_counts();
            hyp2f1(a, b, c, z).unwrap();
            assert!(crate::special::fallback_counts().since(&before).hyp2f1 >= 1);
        }
    }
    assert!(fell_back >= 1, "no candidate reached the MP fallback");
}
