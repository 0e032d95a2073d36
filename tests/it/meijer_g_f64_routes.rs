//! Every f64 route of `meijer_g_k_bounded` (issue 23, item 4), through the public API:
//! on a grid of `k` and `y` that crosses every route switch (the Beta-expectation series
//! from `k (1-y) = 14`, first from 14.5-29.4 by `k`, the plain double-double near-one expansion
//! at `k w = 32 y` and `y = 0.78, 0.875`, the f64 near-one expansion at `y = 0.85`, `k w = 1.25`, the direct
//! series at `y = 0.97`), next to `y = 1`, next to each zero of `G(k, .)` and at tiny `y`,
//! the returned bound encloses the certified 200-bit value, it is `1e-14` relative
//! (the tolerance table below, enforced), and no point falls back to MP, the f64 `y`
//! around each zero included (the Taylor route about the zero, `meijer_g/zero_taylor.rs`).

use maugis::special::{exact, fallback_counts, meijer_g};
use rug::Float;

/// `y` with `G(k, y)` changing sign between `y` and its f64 neighbour above.
fn f64_next_to_zero(k: u32, lo: f64, hi: f64) -> f64 {
    let sign = |y: f64| meijer_g::meijer_g_k_mp(k, &exact(y), 64).unwrap().mid().is_sign_positive();
    let (mut lo, mut hi) = (lo, hi);
    assert!(sign(lo) && !sign(hi), "k={k}: no sign change in [{lo}, {hi}]");
    loop {
        let mid = 0.5 * (lo + hi);
        if mid <= lo || mid >= hi {
            return lo;
        }
        if sign(mid) {
            lo = mid;
        } else {
            hi = mid;
        }
    }
}

#[derive(Default)]
struct Region {
    points: u32,
    fallbacks: u32,
    worst_bound: f64,
    worst_error: f64,
}

#[test]
fn every_route_encloses_and_is_relative() {
    let eps = f64::EPSILON;
    let ks = [0u32, 1, 2, 3, 10, 30, 100, 300, 1000];
    let base = [
        1e-300, 1e-10, 1.0 / 1024.0, 0.1, 0.25, 0.5, 0.5 + 1.0 / 1048576.0, 0.6, 0.7, 0.78, 0.8, 0.85, 0.875, 0.9, 0.93, 0.95, 0.96, 0.97, 0.9705, 0.98, 0.99,
        0.999, 1.0 - 1e-6, 1.0 - 1e-12, 1.0 - eps, 1.0 - eps / 2.0, 1.0,
    ];
    let mut regions: std::collections::BTreeMap<&str, Region> = Default::default();
    let mut check = |k: u32, y: f64, region: &'static str, may_fall_back: bool| {
        let before = fallback_counts().meijer_g_k;
        let b = meijer_g::meijer_g_k_bounded(k, y).unwrap();
        let fell_back = fallback_counts().meijer_g_k > before;
        let reference = meijer_g::meijer_g_k_mp(k, &exact(y), 200).unwrap();
        let d = Float::with_val(300, reference.mid() - b.value).abs();
        assert!(d <= b.err, "k={k} y={y}: {b} vs {reference:?}");
        assert!(!fell_back || may_fall_back, "k={k} y={y}: MP fallback");
        let r = regions.entry(region).or_default();
        r.points += 1;
        r.fallbacks += fell_back as u32;
        if b.value != 0.0 {
            r.worst_bound = r.worst_bound.max(b.err / b.value.abs());
            r.worst_error = r.worst_error.max(d.to_f64() / reference.mid().to_f64().abs());
        }
    };
    for &k in &ks {
        let kf = k as f64;
        let mut ys: Vec<(f64, &str)> = Vec::new();
        for &y in &base {
            let region = if y < 1.0 / 1024.0 {
                "tiny y"
            } else if y == 1.0 {
                "y = 1"
            } else if kf * (1.0 - y) >= 28.0 && y >= 0.5 {
                "k w >= 28"
            } else if y > 0.97 {
                "0.97 < y < 1"
            } else {
                "y <= 0.97"
            };
            ys.push((y, region));
        }
        // the f64 neighbours of every switch
        let mut switches = vec![0.65, 0.78, 0.84, 0.85, 0.875, 0.97];
        if k > 0 {
            switches.extend([1.0 - 1.25 / kf, kf / (kf + 32.0)]);
        }
        if k >= 28 {
            switches.push(1.0 - 14.0 / kf);
        }
        // where the Beta series goes first (meijer_g/native.rs, beta_series_kw)
        let beta_kw = match k {
            30 => 14.5,
            100 => 21.2,
            300 => 26.9,
            1000 => 29.4,
            _ => 0.0,
        };
        if beta_kw > 0.0 {
            switches.push(1.0 - beta_kw / kf);
        }
        for s in switches {
            if s > 0.5 && s < 1.0 {
                ys.extend([(s.next_down(), "route switches"), (s, "route switches"), (s.next_up(), "route switches")]);
            }
        }
        for (y, region) in ys {
            check(k, y, region, false);
        }
    }
    // next to the zeros: G(2, .) at 0.807, G(3, .) at 0.70, G(k, .) at 1/2 + O(1/k): every
    // k >= 2 has exactly one (meijer_g/zero_taylor.rs). The two f64 y around each zero, the
    // next four f64 either side, and offsets up to 1e-2 (the window of the Taylor route about
    // the zero is min(y_0, 1 - y_0)/10 >= 1.9e-2; beyond it the double-double routes answer)
    let mut zero_ks: Vec<u32> = (2..25).collect();
    zero_ks.extend([30, 100, 300, 519, 1000]);
    for &k in &zero_ks {
        let y0 = f64_next_to_zero(k, 0.5, 0.85);
        let mut next_to = vec![y0, y0.next_up()];
        let (mut below, mut above) = (y0, y0.next_up());
        for _ in 0..4 {
            below = below.next_down();
            above = above.next_up();
            next_to.extend([below, above]);
        }
        for y in next_to {
            check(k, y, "the ten f64 y around a zero", false);
        }
        for &d in &[1e-15, 1e-14, 1e-13, 1e-12] {
            check(k, y0 - d, "next to a zero (1e-15 to 1e-12)", false);
            check(k, y0 + d, "next to a zero (1e-15 to 1e-12)", false);
        }
        // and 16 quasi-random offsets in (-1e-12, 1e-12), log-spread from 1e-16
        for i in 0..16u32 {
            let f = (i as f64 * 0.618_033_988_749_895 + k as f64 * 0.1).fract();
            let d = 1e-16 * 1e4f64.powf(f) * if i % 2 == 0 { 1.0 } else { -1.0 };
            check(k, y0 + d, "next to a zero (1e-15 to 1e-12)", false);
        }
        for &d in &[1e-9, 1e-6, 1e-3, 5e-3, 1e-2] {
            check(k, y0 - d, "near a zero (1e-9 to 1e-2)", false);
            check(k, y0 + d, "near a zero (1e-9 to 1e-2)", false);
        }
        check(k, y0 - 3e-2, "3e-2 from a zero", false);
        check(k, y0 + 3e-2, "3e-2 from a zero", false);
    }
    // the tolerance table: the bound is 1e-14 relative everywhere, natively, and the value
    // within it
    let tolerance = meijer_g::NATIVE_REL_TOL;
    eprintln!("| region | points | MP fallbacks | max bound/|G| | max error/|G| | tolerance |");
    eprintln!("|---|---:|---:|---:|---:|---:|");
    for (name, r) in &regions {
        eprintln!("| {name} | {} | {} | {:.2e} | {:.2e} | {tolerance:.0e} |", r.points, r.fallbacks, r.worst_bound, r.worst_error);
        assert!(r.worst_bound <= tolerance && r.worst_error <= tolerance, "{name}: over {tolerance}");
    }
}
