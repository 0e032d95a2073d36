//! The 64 points of the issue-8 `meijer_g_k` domain, `k <= 1000`, `y in (0, 1]`
//! (shared by benches/special.rs, group `meijer_g_k_f64_domain`, and
//! examples/meijer_g_grid.rs, so that both time the same points).

/// `k = floor(1000 frac(i phi))`, `y = 1 - frac(i 0.7548776662466927)`, `i < 64`.
pub fn meijer_domain_points() -> Vec<(u32, f64)> {
    (0..64)
        .map(|i| {
            let u = (i as f64 * 0.618_033_988_749_895).fract();
            let v = (i as f64 * 0.754_877_666_246_693).fract();
            ((1000.0 * u).floor() as u32, 1.0 - v)
        })
        .collect()
}
