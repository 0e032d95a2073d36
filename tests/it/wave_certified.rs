//! Eq. 11a as a certified double integral against the certified Eq. 12 / Eq. 11b
//! series: two independent balls of the same number must overlap, and each must
//! carry digits (issue 22 item 6).
//!
//! The certified double integral costs about 0.2 s (du) to 13 s (u) a point at
//! 64 bits in release, growing with D = 2 pi a/zeta and as x -> a. The test takes
//! the cross-check points of tests/it/wave_crosscheck.rs: every fourth in the
//! default test tier, all 51 under `./dev test --long` (100 s on two cores in
//! release, measured 2026-11-25).

use maugis::contact::displacement::{du_wave_series_mp, u_wave_series_mp};
use maugis::contact::displacement::quadrature_ball::{du_wave_quad_ball, traction_integral_ball, u_wave_quad_ball};
use maugis::special::exact;
use maugis::Ball;
use rayon::prelude::*;
use rug::Float;

/// Precision of the certified double integral.
const PREC: u32 = 64;

use crate::wave_points;
use wave_points::tier_points;

fn ball(v: f64) -> Ball {
    Ball::from_f64(v, 53).unwrap()
}

/// Both quantities at one point: overlap with the series, and digits.
fn check_point(a: f64, zeta: f64, x: f64) {
    let (ae, ze, me, xe) = (exact(a), exact(zeta), exact(1.0), exact(x));
    let series = u_wave_series_mp(&ae, &ze, &me, &xe, 1000, 100).unwrap().full();
    let dseries = du_wave_series_mp(&ae, &ze, &me, &xe, 1000, 100).unwrap().full();
    let t = std::time::Instant::now();
    let quad = u_wave_quad_ball(&ball(a), &ball(zeta), &ball(1.0), &ball(x), PREC).expect("certified Eq. 11a u");
    let tu = t.elapsed();
    let t = std::time::Instant::now();
    let dquad = du_wave_quad_ball(&ball(a), &ball(zeta), &ball(1.0), &ball(x), PREC).expect("certified Eq. 11a du");
    let tdu = t.elapsed();
    eprintln!("({a}, {zeta}, {x}): u {quad:?} in {tu:.2?}, du {dquad:?} in {tdu:.2?}");
    assert!(quad.overlaps(&series), "u at ({a},{zeta},{x}): Eq. 11a {quad:?} vs Eq. 12 {series:?}");
    assert!(dquad.overlaps(&dseries), "du at ({a},{zeta},{x}): Eq. 11a {dquad:?} vs Eq. 11b {dseries:?}");
    // digits: rad <= 2^-56 of the natural scale (max(|u|, A), max(|du|, 6 A/zeta)),
    // and the series ball far tighter still
    let scale = Float::with_val(53, series.abs_upper().max(&Float::with_val(53, 1)));
    let dscale = Float::with_val(53, dseries.abs_upper().max(&Float::with_val(53, 6.0 / zeta)));
    assert!(quad.meets_abs(PREC - 8, &scale), "u at ({a},{zeta},{x}): {quad:?} too wide");
    assert!(dquad.meets_abs(PREC - 8, &dscale), "du at ({a},{zeta},{x}): {dquad:?} too wide");
    assert!(series.meets_abs(90, &scale) && dseries.meets_abs(90, &dscale));
}

#[test]
fn eq11a_certified_overlaps_series_every_point() {
    tier_points().par_iter().for_each(|&(a, zeta, x)| check_point(a, zeta, x));
}

/// The edge: `u_w(a) = A (1 - cos D)` exactly, and `du_w/dx` at `x = a` (the
/// limit from `x > a`) against the series there.
#[test]
fn eq11a_certified_at_the_edge() {
    let (a, zeta) = (1.5, 2.0);
    let (ae, ze, me) = (exact(a), exact(zeta), exact(1.0));
    let dseries = du_wave_series_mp(&ae, &ze, &me, &ae, 1000, 100).unwrap().full();
    let dquad = du_wave_quad_ball(&ball(a), &ball(zeta), &ball(1.0), &ball(a), PREC).unwrap();
    assert!(dquad.overlaps(&dseries), "{dquad:?} vs {dseries:?}");
    assert!(dquad.rad_mag().to_f64_up() < 1e-16);
    let u = u_wave_quad_ball(&ball(a), &ball(zeta), &ball(1.0), &ball(a), PREC).unwrap();
    let d = 2.0 * std::f64::consts::PI * a / zeta;
    assert!((u.to_f64() - (1.0 - d.cos())).abs() < 1e-15 && u.rad_mag().to_f64_up() < 1e-18);
}

/// The traction integral `K(c) = int_0^D J0(t) cos((t - D) c) dt`, certified: at
/// `c = 1` the convolution `int_0^D J0(t) cos(D - t) dt = D J0(D)` (Laplace:
/// `s/(s^2+1)^(3/2) = -d/ds (s^2+1)^(-1/2)`) must lie in the ball; at other `c`
/// the f64 Bessel-series value of the model (an estimate) agrees to 1e-13.
#[test]
fn traction_integral_certified() {
    use maugis::contact::displacement::WaveBessel;
    use maugis::special::bessel_j::bessel_j_mp;
    for &(a, zeta) in &[(1.0, 1.0), (6.0, 0.5), (0.25, 2.0), (3.0, 1.125)] {
        let wb = WaveBessel::new(a, zeta, 1.0).unwrap();
        let d = Ball::pi(160).mul(&ball(a)).mul_pow2(1).div(&ball(zeta)).unwrap();
        let exact_k1 = bessel_j_mp(0, d.mid(), 140).unwrap().mul(&d);
        for &c in &[0.0, 0.25, 0.5, 0.9, 1.0] {
            let k = traction_integral_ball(&d, &ball(c), 96).unwrap();
            let f = wb.traction_integral(c);
            assert!(k.rad_mag().to_f64_up() < 1e-26 * f.abs().max(1.0), "K({c}) at ({a},{zeta}): {k:?}");
            assert!((k.to_f64() - f).abs() <= 1e-13 * f.abs().max(1.0), "K({c}) at ({a},{zeta}): {k:?} vs f64 {f}");
            if c == 1.0 {
                assert!(k.overlaps(&exact_k1), "K(1) at ({a},{zeta}): {k:?} vs D J0(D) = {exact_k1:?}");
            }
        }
    }
}
