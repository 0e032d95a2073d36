//! Three independent routes to the wave displacement must agree
//! (issue: "Eq. 12 series = Bessel form = u_w(a) + integral of the Eq. 11a quadrature"):
//!
//! * Eq. 12 / Eq. 11b series (certified balls, kmax = 1000, with truncation bound),
//! * the Bessel form (certified balls; f64 double-double),
//! * the Eq. 11a double quadrature (tanh-sinh in MP, Gauss–Legendre in f64).
//!
//! At 51 points (every fourth, 13, in the default test tier, all under `./dev test
//! --long`: `wave_points::tier_points`) spanning a in (0, 6], zeta in [1/2, 5], A = 1 (D = 2 pi a/zeta up
//! to 75) and x/a in (1, 5], including x/a = 1 + 10^-j for j = 2..10. Also the
//! truncation bounds at several kmax, the edge identity, and one test per
//! erratum of the printed paper (docs/displacement.md, "Errata pinned by tests").

use maugis::contact::displacement::*;
use maugis::contact::displacement::quadrature::*;
use maugis::special::exact;
use maugis::Ball;
use rayon::prelude::*;
use rug::Float;

/// MP quadrature precision: 84 bits = 25 digits.
const QUAD_PREC: u32 = 84;

use crate::wave_points;
use wave_points::{points, tier_points};

fn ball_of(v: &Float) -> Ball {
    Ball::from_float(v, v.prec())
}

#[test]
fn enough_points() {
    let pts = points();
    assert!(pts.len() >= 50, "{} points", pts.len());
    for j in 2..=10 {
        assert!(pts.iter().any(|&(a, _, x)| ((x / a - 1.0) / 10f64.powi(-j) - 1.0).abs() < 1e-3));
    }
}

/// Eq. 12 (kmax = 1000, truncation bound included) and the Bessel form are
/// certified balls of the same number: they must overlap, and both are tight.
#[test]
fn series_and_bessel_form_agree_mp() {
    tier_points().par_iter().for_each(|&(a, zeta, x)| {
        let (ae, ze, me, xe) = (exact(a), exact(zeta), exact(1.0), exact(x));
        let bessel = u_wave_mp(&ae, &ze, &me, &xe, 100).expect("bessel u");
        let series = u_wave_series_mp(&ae, &ze, &me, &xe, 1000, 100).expect("series u");
        assert!(series.full().overlaps(&bessel), "u at ({a},{zeta},{x}): {:?} vs {bessel:?}", series.partial);
        let dbessel = du_wave_mp(&ae, &ze, &me, &xe, 100).expect("bessel du");
        let dseries = du_wave_series_mp(&ae, &ze, &me, &xe, 1000, 100).expect("series du");
        assert!(dseries.full().overlaps(&dbessel), "du at ({a},{zeta},{x}): {:?} vs {dbessel:?}", dseries.partial);
        // 25+ digits certified: rad <= 2^-84 max(|u|, A)
        let scale = Float::with_val(53, bessel.mid().clone().abs().max(&Float::with_val(53, 1)));
        assert!(bessel.meets_abs(QUAD_PREC, &scale) && series.full().meets_abs(QUAD_PREC, &scale));
    });
}

/// The Eq. 11a quadrature (an estimate) agrees with the certified Bessel form
/// to 25 digits relative to max(|u_w|, A) (and max(|u_w'|, 2 pi A/zeta)).
#[test]
fn quadrature_agrees_mp() {
    tier_points().par_iter().for_each(|&(a, zeta, x)| {
        let (ae, ze, me, xe) = (exact(a), exact(zeta), exact(1.0), exact(x));
        let bessel = u_wave_mp(&ae, &ze, &me, &xe, 100).unwrap();
        // an explicit budget: the default (30 s of wall time) ran out for du on a
        // machine loaded 8-fold (3 s of CPU time in 30 s)
        let roomy = maugis::Budget::from_secs_f64(900.0).expect("budget");
        let quad = roomy.run(|| u_wave_quad_mp(&ae, &ze, &me, &xe, QUAD_PREC)).expect("quad u");
        let scale = bessel.abs_upper().to_f64().max(1.0);
        let diff = bessel.sub(&ball_of(&quad.value)).abs_upper().to_f64();
        assert!(diff <= 1e-25 * scale, "u at ({a},{zeta},{x}): quad {} vs {bessel:?}", quad.value);
        let dbessel = du_wave_mp(&ae, &ze, &me, &xe, 100).unwrap();
        let dquad = roomy.run(|| du_wave_quad_mp(&ae, &ze, &me, &xe, QUAD_PREC)).expect("quad du");
        let dscale = dbessel.abs_upper().to_f64().max(2.0 * std::f64::consts::PI / zeta);
        let ddiff = dbessel.sub(&ball_of(&dquad.value)).abs_upper().to_f64();
        assert!(ddiff <= 1e-25 * dscale, "du at ({a},{zeta},{x}): quad {} vs {dbessel:?}", dquad.value);
    });
}

/// f64: the Bessel form to 1e-14 and the quadrature to 1e-12 of the certified value.
#[test]
fn f64_routes_agree() {
    let mut worst_bessel = 0.0f64;
    let mut worst_quad = 0.0f64;
    for (a, zeta, x) in tier_points() {
        let (ae, ze, me, xe) = (exact(a), exact(zeta), exact(1.0), exact(x));
        let u = u_wave_mp(&ae, &ze, &me, &xe, 80).unwrap().to_f64();
        let du = du_wave_mp(&ae, &ze, &me, &xe, 80).unwrap().to_f64();
        let scale = u.abs().max(1.0);
        let dscale = du.abs().max(2.0 * std::f64::consts::PI / zeta);
        let eb = (u_wave(a, zeta, 1.0, x).unwrap() - u).abs() / scale;
        let edb = (du_wave(a, zeta, 1.0, x).unwrap() - du).abs() / dscale;
        let eq = (u_wave_quad(a, zeta, 1.0, x).unwrap().value - u).abs() / scale;
        let edq = (du_wave_quad(a, zeta, 1.0, x).unwrap().value - du).abs() / dscale;
        assert!(eb <= 1e-14 && edb <= 1e-14, "Bessel f64 at ({a},{zeta},{x}): {eb:e} {edb:e}");
        assert!(eq <= 1e-12 && edq <= 1e-12, "quadrature f64 at ({a},{zeta},{x}): {eq:e} {edq:e}");
        worst_bessel = worst_bessel.max(eb).max(edb);
        worst_quad = worst_quad.max(eq).max(edq);
    }
    eprintln!("f64 Bessel form worst error {worst_bessel:e}; f64 quadrature worst {worst_quad:e} (relative to max(|u|, A))");
}

/// The truncation bound of the paper's sum is correct: for several kmax the
/// exact value (Bessel ball) lies within `trunc` of the certified partial sum.
#[test]
fn truncation_bounds_hold() {
    let kmaxes = [0u64, 3, 10, 25, 60, 1000];
    tier_points().par_iter().for_each(|&(a, zeta, x)| {
        let (ae, ze, me, xe) = (exact(a), exact(zeta), exact(1.0), exact(x));
        let exact_u = u_wave_mp(&ae, &ze, &me, &xe, 100).unwrap();
        let exact_du = du_wave_mp(&ae, &ze, &me, &xe, 100).unwrap();
        for &k in &kmaxes {
            let s = u_wave_series_mp(&ae, &ze, &me, &xe, k, 100).unwrap();
            assert!(s.full().overlaps(&exact_u), "u kmax={k} at ({a},{zeta},{x}): trunc {} partial {:?}", s.trunc, s.partial);
            let ds = du_wave_series_mp(&ae, &ze, &me, &xe, k, 100).unwrap();
            assert!(ds.full().overlaps(&exact_du), "du kmax={k} at ({a},{zeta},{x})");
        }
    });
}

// ------------------------------------------------------------------ errata

/// Erratum (docs/displacement.md): with C = 0 and the corrected prefactor, Eq. 12 meets the
/// profile at the edge, u_w(a) = A (1 - cos(2 pi a/zeta)), and the printed
/// prefactor (pi a/lambda)^2 (lambda the Maugis parameter, here 1.5) does not.
#[test]
fn erratum_eq12_prefactor_and_integration_constant() {
    for &(a, zeta) in &[(2.0, 1.125), (0.7, 2.0), (4.5, 5.0)] {
        let s = u_wave_series_mp(&exact(a), &exact(zeta), &exact(1.0), &exact(a), 1000, 100).unwrap().full();
        let d = Ball::pi(120).mul_pow2(1).mul(&Ball::from_f64(a, 120).unwrap()).div(&Ball::from_f64(zeta, 120).unwrap()).unwrap();
        let edge = Ball::one(120).sub(&d.cos());
        assert!(s.overlaps(&edge), "corrected Eq. 12 at x = a");
        let lambda = 1.5;
        let printed = s.mul(&Ball::from_f64((zeta / lambda).powi(2), 120).unwrap());
        assert!(!printed.overlaps(&edge), "the printed (pi a/lambda)^2 must fail");
    }
}

/// Erratum (docs/displacement.md): the sign is (-1)^k (the printed (-1)^{3k} is the same for
/// integer k): the Eq. 12 terms alternate. Dropping the alternation breaks the
/// agreement with the Bessel form.
#[test]
fn erratum_eq12_sign_alternates() {
    let (a, zeta, x) = (2.0, 1.125, 2.6);
    let (ae, ze, me, xe) = (exact(a), exact(zeta), exact(1.0), exact(x));
    let bessel = u_wave_mp(&ae, &ze, &me, &xe, 100).unwrap();
    let series = u_wave_series_mp(&ae, &ze, &me, &xe, 1000, 100).unwrap();
    assert!(series.full().overlaps(&bessel));
    // Partial sums through kmax = 0 and 1 differ by T_1; the alternating sign
    // makes T_1 < 0 here (all factors of T_1 other than (-1)^1 are positive: 1F2 at
    // -(pi a/zeta)^2 is checked positive, G(1, y) > 0 for y < 1).
    let s0 = u_wave_series_mp(&ae, &ze, &me, &xe, 0, 100).unwrap().partial;
    let s1 = u_wave_series_mp(&ae, &ze, &me, &xe, 1, 100).unwrap().partial;
    let g1 = maugis::special::meijer_g::meijer_g_k_mp(1, &exact((a / x) * (a / x)), 80).unwrap();
    let f1 = maugis::special::hyp1f2::hyp1f2_mp_f64(0.5, 2.0, 2.5, -(std::f64::consts::PI * a / zeta).powi(2), 80).unwrap();
    let t1 = s1.sub(&s0);
    assert_eq!(t1.is_negative(), g1.is_positive() == f1.is_positive(), "T_1 carries the sign (-1)^1");
}

/// Erratum (docs/displacement.md): printed Eq. 11a (outer integral over [0, 2 pi], factor
/// 2 pi a/zeta inside) does not give du_w/dx; the corrected one (outer over
/// [0, D], prefactor A/zeta) matches the Bessel form and Eq. 11b.
#[test]
fn erratum_eq11a_limits_and_prefactor() {
    for &(a, zeta, x) in &[(2.0, 1.125, 2.6), (0.7, 2.0, 0.75), (3.0, 2.0, 9.0)] {
        let du = du_wave_mp(&exact(a), &exact(zeta), &exact(1.0), &exact(x), 80).unwrap().to_f64();
        let corrected = du_wave_quad(a, zeta, 1.0, x).unwrap().value;
        let printed = du_wave_quad_as_printed(a, zeta, 1.0, x).unwrap();
        assert!((corrected - du).abs() <= 1e-12 * du.abs().max(1.0));
        assert!((printed - du).abs() > 1e-3 * du.abs().max(1.0), "printed Eq. 11a unexpectedly agrees at ({a},{zeta},{x})");
    }
}

/// Erratum (docs/displacement.md): sign convention. With u positive downward, u_w' from Eq. 11b
/// is the derivative of u_w (central difference of the certified Bessel form),
/// not its negative (printed Eq. 2 has the opposite sign).
#[test]
fn erratum_sign_convention_gradient_is_derivative() {
    for &(a, zeta, x) in &[(2.0, 1.125, 2.6), (4.5, 5.0, 7.0), (0.75, 0.5, 1.0)] {
        let h = 2f64.powi(-20);
        let up = u_wave_mp(&exact(a), &exact(zeta), &exact(1.0), &exact(x + h), 100).unwrap();
        let dn = u_wave_mp(&exact(a), &exact(zeta), &exact(1.0), &exact(x - h), 100).unwrap();
        let fd = up.sub(&dn).to_f64() / (2.0 * h);
        let s = du_wave_series_mp(&exact(a), &exact(zeta), &exact(1.0), &exact(x), 1000, 80).unwrap().full().to_f64();
        assert!((fd - s).abs() <= 1e-8 * s.abs().max(1.0), "({a},{zeta},{x}): fd {fd} vs Eq. 11b {s}");
    }
}
