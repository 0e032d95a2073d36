//! `u_wave_bounded` / `du_wave_bounded` from scratch by the one-pass bounded
//! Miller route (method block of `src/contact/displacement/bounded/value.rs`):
//! the returned bound must contain the certified MP value (Bessel form in
//! balls at 200 bits) at every point, and both the bound and the error must
//! stay within the tolerance table below, region by region; on the model
//! domain the route must answer every call itself (the miss counter, which
//! counts calls handed to the per-contact data or MP, stays at 0). Alone in
//! its test binary so that no other test moves the process-wide counters.
//!
//! Tolerances, as fractions of the scales `max(|u_w|, |A|)` and
//! `max(|du_w/dx|, 2 pi |A|/zeta)`:
//!
//! | region | points | bound | error |
//! |---|---|---|---|
//! | contact edge: `x = a`, one and two ulps, `1 + 1e-15`, `1 + 2^-40`, `1 + 1e-9` | 45 `a` x 6 | 2e-16 | 1.5e-16 |
//! | near field `x/a` in `(1, 1.2]` | 45 x 6 | 2e-16 | 1.5e-16 |
//! | middle `x/a` in `(1.2, 2]` | 45 x 6 | 2e-16 | 1.5e-16 |
//! | far field `x/a` in `(2, 3]`, and `25/7` (the native limit) | 45 x 7 | 2e-16 | 1.5e-16 |
//! | large `D`: `zeta` from 0.9 down to 0.75 at `a = 6` (`D` to 50) | 4 x 8 | 2^-50 | 1.5e-16 |
//! | tiny `D`: `zeta = 100`, `1e4` (`D` to 3e-4) | 2 x 3 x 8 | 2e-16 | 1.5e-16 |
//!
//! (`a` from 0.5 to 6 in steps of 1/8, `zeta = 9/8` unless stated.)

use maugis::contact::displacement::bounded::wave_scratch_misses;
use maugis::special::fallback_counts;
use maugis::contact::displacement::{du_wave_bounded, du_wave_mp, u_wave_bounded, u_wave_mp};
use maugis::special::exact;
use rug::Float;

const REF_PREC: u32 = 200;

/// The worst (bound, error) of u and du at the points, as fractions of the
/// scales; panics where a bound misses the MP value.
fn worst(points: &[(f64, f64, f64)]) -> [f64; 4] {
    let mut w = [0.0f64; 4];
    for &(a, zeta, x) in points {
        let (ae, ze, me, xe) = (exact(a), exact(zeta), exact(1.0), exact(x));
        let u_ref = u_wave_mp(&ae, &ze, &me, &xe, REF_PREC).unwrap();
        let du_ref = du_wave_mp(&ae, &ze, &me, &xe, REF_PREC).unwrap();
        let u = u_wave_bounded(a, zeta, 1.0, x).unwrap();
        let du = du_wave_bounded(a, zeta, 1.0, x).unwrap();
        let us = u_ref.to_f64().abs().max(1.0);
        let dus = du_ref.to_f64().abs().max(2.0 * std::f64::consts::PI / zeta);
        let eu = Float::with_val(REF_PREC + 64, u_ref.mid() - u.value).abs();
        let edu = Float::with_val(REF_PREC + 64, du_ref.mid() - du.value).abs();
        assert!(eu <= Float::with_val(64, u.err) + u_ref.rad(), "a={a} zeta={zeta} x={x}: u {u} misses {u_ref:?}");
        assert!(edu <= Float::with_val(64, du.err) + du_ref.rad(), "a={a} zeta={zeta} x={x}: du {du} misses {du_ref:?}");
        w = [w[0].max(u.err / us), w[1].max(eu.to_f64() / us), w[2].max(du.err / dus), w[3].max(edu.to_f64() / dus)];
    }
    w
}

/// A named region: its points `(a, zeta, x)` and the bound's tolerance.
type Region = (&'static str, Vec<(f64, f64, f64)>, f64);

fn model_a() -> impl Iterator<Item = f64> {
    (0..=44).map(|i| 0.5 + 0.125 * i as f64)
}

#[test]
fn scratch_route_encloses_the_mp_values_within_the_tolerance_table() {
    let (misses, fallbacks) = (wave_scratch_misses(), fallback_counts().wave_bounded);
    let ulps = |a: f64, k: u64| f64::from_bits(a.to_bits() + k);
    let mut regions: Vec<Region> = Vec::new();
    let grid = |ratios: &[f64]| model_a().flat_map(|a| ratios.iter().map(move |&r| (a, 1.125, a * r))).collect::<Vec<_>>();
    let mut edge: Vec<(f64, f64, f64)> = model_a().flat_map(|a| [(a, 1.125, a), (a, 1.125, ulps(a, 1)), (a, 1.125, ulps(a, 2))]).collect();
    edge.extend(grid(&[1.0 + 1e-15, 1.0 + 2f64.powi(-40), 1.0 + 1e-9]));
    regions.push(("edge", edge, 2e-16));
    regions.push(("near", grid(&[1.001, 1.01, 1.05, 1.1, 1.15, 1.2]), 2e-16));
    regions.push(("middle", grid(&[1.3, 1.45, 1.6, 1.75, 1.9, 2.0]), 2e-16));
    regions.push(("far", grid(&[2.2, 2.4, 2.6, 2.8, 2.95, 3.0, 25.0 / 7.0]), 2e-16));
    let model_points: usize = regions.iter().map(|r| r.1.len()).sum();
    let ratios = [1.0, 1.0 + 1e-12, 1.01, 1.3, 1.9, 2.5, 3.0, 3.5];
    let large_d: Vec<(f64, f64, f64)> = [0.9, 0.85, 0.8, 0.75].iter().flat_map(|&z| ratios.iter().map(move |&r| (6.0, z, 6.0 * r))).collect();
    let tiny_d: Vec<(f64, f64, f64)> = [(0.5, 100.0), (6.0, 100.0), (0.5, 1e4)]
        .iter()
        .flat_map(|&(a, z)| ratios.iter().map(move |&r| (a, z, a * r)))
        .collect();
    let model_misses;
    {
        let mut report = Vec::new();
        for (name, pts, tol) in &regions {
            let w = worst(pts);
            report.push(format!("{name}: {} points, bound u {:.2e} du {:.2e}, error u {:.2e} du {:.2e}", pts.len(), w[0], w[2], w[1], w[3]));
            assert!(w[0] <= *tol && w[2] <= *tol, "{name}: bound above {tol:e}: {w:?}");
            assert!(w[1] <= 1.5e-16 && w[3] <= 1.5e-16, "{name}: error above 1.5e-16: {w:?}");
        }
        model_misses = wave_scratch_misses() - misses;
        for (name, pts, tol) in [("large D", large_d, 2f64.powi(-50)), ("tiny D", tiny_d, 2e-16)] {
            let before = wave_scratch_misses();
            let w = worst(&pts);
            report.push(format!(
                "{name}: {} points, bound u {:.2e} du {:.2e}, error u {:.2e} du {:.2e}, {} handed on",
                pts.len(),
                w[0],
                w[2],
                w[1],
                w[3],
                wave_scratch_misses() - before
            ));
            assert!(w[0] <= tol && w[2] <= tol, "{name}: bound above {tol:e}: {w:?}");
            assert!(w[1] <= 1.5e-16 && w[3] <= 1.5e-16, "{name}: error above 1.5e-16: {w:?}");
        }
        for line in report {
            eprintln!("{line}");
        }
    }
    eprintln!("model domain: {model_points} points, {model_misses} handed to the per-contact data; MP fallbacks in all: {}", fallback_counts().wave_bounded - fallbacks);
    assert_eq!(model_misses, 0, "the one-pass route must answer on the whole model domain");
}
