//! The fast value path of `u_wave` / `du_wave` (an estimate, module docs of
//! `maugis::contact::displacement::bounded`): its accuracy enforced against the 200-bit
//! certified Bessel form (`u_wave_mp`, `du_wave_mp`) on a dense grid of the
//! issue-8 domain `a in [0.5, 6]`, `zeta = 9/8`, `x/a in [1, 3]` plus the edges
//! (`x = a` exactly, one ulp above, `x/a = 3`, `a = 0.5` and `6`): at most
//! `1e-15` of `max(|u_w|, |A|)`, and of `max(|du_w/dx|, 2 pi |A|/zeta)`.

use maugis::contact::displacement::{du_wave, du_wave_mp, u_wave, u_wave_mp};
use maugis::special::exact;
use rug::Float;

const REF_PREC: u32 = 200;

/// The worst errors (relative to the scales) of `u_wave`, `du_wave` at the points.
fn worst(points: &[(f64, f64, f64, f64)]) -> (f64, f64) {
    let (mut wu, mut wdu) = (0.0f64, 0.0f64);
    for &(a, zeta, amp, x) in points {
        let (ae, ze, me, xe) = (exact(a), exact(zeta), exact(amp), exact(x));
        let u_ref = u_wave_mp(&ae, &ze, &me, &xe, REF_PREC).unwrap();
        let du_ref = du_wave_mp(&ae, &ze, &me, &xe, REF_PREC).unwrap();
        let u = u_wave(a, zeta, amp, x).unwrap();
        let du = du_wave(a, zeta, amp, x).unwrap();
        let u_scale = u_ref.to_f64().abs().max(amp.abs());
        let du_scale = du_ref.to_f64().abs().max(2.0 * std::f64::consts::PI * amp.abs() / zeta);
        let eu = Float::with_val(REF_PREC + 64, u_ref.mid() - u).abs().to_f64() / u_scale;
        let edu = Float::with_val(REF_PREC + 64, du_ref.mid() - du).abs().to_f64() / du_scale;
        assert!(eu <= 1e-15, "u_wave a={a} zeta={zeta} A={amp} x={x}: error {eu:e} of the scale (got {u}, ref {u_ref:?})");
        assert!(edu <= 1e-15, "du_wave a={a} zeta={zeta} A={amp} x={x}: error {edu:e} of the scale (got {du}, ref {du_ref:?})");
        wu = wu.max(eu);
        wdu = wdu.max(edu);
    }
    (wu, wdu)
}

/// Dense grid: 45 contact sizes (step 1/8) times 41 ratios with the edges.
#[test]
fn value_path_within_1e15_on_the_dense_domain_grid() {
    let mut pts = Vec::new();
    for i in 0..=44 {
        let a = 0.5 + 0.125 * i as f64;
        let mut ratios: Vec<f64> = (0..=40).map(|j| 1.0 + 2.0 * (j as f64 / 40.0).powi(2)).collect();
        ratios.extend([1.0 + 2f64.powi(-40), 1.0 + 1e-9, 1.0 + 1e-5, 1.001]);
        for r in ratios {
            pts.push((a, 1.125, 1.0, a * r));
        }
        pts.push((a, 1.125, 1.0, f64::from_bits(a.to_bits() + 1)));
    }
    let (wu, wdu) = worst(&pts);
    eprintln!("value path, {} points: worst u error {wu:.3e}, du error {wdu:.3e} of the scale", pts.len());
}

/// Off-grid contact sizes (a at irrational steps), other amplitudes, and
/// other wavelengths (D from 0.6 to 60).
#[test]
fn value_path_within_1e15_off_grid_and_other_wavelengths() {
    let mut pts = Vec::new();
    for i in 0..40 {
        let u = (i as f64 * 0.618_033_988_749_895).fract();
        let v = (i as f64 * 0.754_877_666_246_693).fract();
        let a = 0.5 + 5.5 * u;
        pts.push((a, 1.125, if i % 3 == 0 { -2.5 } else { 0.75 }, a * (1.0 + 2.0 * v)));
    }
    for &(a, zeta) in &[(0.5, 5.0), (2.0, 0.5), (4.0, 0.5), (3.0, 2.0), (0.01, 1.125)] {
        for &r in &[1.0, 1.1, 2.0, 3.0, 3.5] {
            pts.push((a, zeta, 1.0, a * r));
        }
    }
    let (wu, wdu) = worst(&pts);
    eprintln!("value path, {} points: worst u error {wu:.3e}, du error {wdu:.3e} of the scale", pts.len());
}

/// The solver's scan path `WaveBessel::u_fast` (plain f64 from the double-double
/// Bessel values, its sum stopped once the terms left are below `2^-64 |A|`):
/// within `1e-15 |A| max(1, D)` of the 200-bit certified Bessel form, `D = 2 pi a/zeta`
/// from 0.6 to 2000, next to the edge (`x/a - 1` down to `1e-12`) and far from it
/// (`x/a` up to `1e3`), where the stopped sum keeps a few terms of `D/2`.
#[test]
fn fast_scan_path_within_its_documented_error() {
    use maugis::contact::displacement::WaveBessel;
    let mut worst = 0.0f64;
    for &(a, zeta) in &[(0.5, 5.0), (1.0, 1.125), (3.0, 0.3125), (2.0, 0.0625), (6.0, 0.01875)] {
        for &amp in &[1.0, -0.375] {
            let wb = WaveBessel::new(a, zeta, amp).unwrap();
            let d = wb.d();
            for &r in &[1.0 + 1e-12, 1.0 + 1e-6, 1.0 + 1e-3, 1.1, 2.0, 10.0, 1e3] {
                let x = a * r;
                let u_ref = u_wave_mp(&exact(a), &exact(zeta), &exact(amp), &exact(x), REF_PREC).unwrap();
                let e = Float::with_val(REF_PREC + 64, u_ref.mid() - wb.u_fast(x)).abs().to_f64() / (amp.abs() * d.max(1.0).sqrt());
                assert!(e <= 1e-15, "u_fast a={a} zeta={zeta} A={amp} x={x} (D = {d}): error {e:e} of |A| sqrt(max(1, D))");
                worst = worst.max(e);
            }
        }
    }
    eprintln!("u_fast: worst error {worst:.3e} of |A| sqrt(max(1, D))");
}
