//! The model domain of the f64 wave functions (issue 8, issue 23 item 5):
//! `a in [0.5, 6]`, `zeta = 9/8`, `x/a in [1, 3]`. The 64 points are those of
//! the criterion group `wave_f64_domain` (benches/displacement.rs) and of
//! `reference/bench_scipy.py --wave`; examples/f64_targets.rs adds the edges.

/// The wavelength of the domain (`beta = 9/8` in the paper's units).
pub const ZETA: f64 = 1.125;

/// `a = 0.5 + 5.5 u`, `x = a (1 + 2 v)`, `u`, `v` the fractional parts of
/// `i phi` and `i 0.7548776662466927`, `i < 64`.
pub fn wave_points() -> Vec<(f64, f64)> {
    (0..64)
        .map(|i| {
            let u = (i as f64 * 0.618_033_988_749_895).fract();
            let v = (i as f64 * 0.754_877_666_246_693).fract();
            let a = 0.5 + 5.5 * u;
            (a, a * (1.0 + 2.0 * v))
        })
        .collect()
}

/// [`wave_points`] and, for `a` in {0.5, 1, 2, 3, 4.5, 6}, the edges `x = a`,
/// one ulp above, `x = a (1 + 1e-15)` and `x = 3a`.
#[allow(dead_code)]
pub fn wave_points_with_edges() -> Vec<(f64, f64)> {
    let mut pts = wave_points();
    for a in [0.5f64, 1.0, 2.0, 3.0, 4.5, 6.0] {
        let up = f64::from_bits(a.to_bits() + 1);
        pts.extend([(a, a), (a, up), (a, a * (1.0 + 1e-15)), (a, 3.0 * a)]);
    }
    pts
}
