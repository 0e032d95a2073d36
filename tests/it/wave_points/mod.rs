//! The cross-check points of the wave displacement, shared by
//! tests/it/wave_crosscheck.rs and tests/it/wave_certified.rs.

/// The test points `(a, zeta, x)`.
pub fn points() -> Vec<(f64, f64, f64)> {
    let a_values = [0.25, 0.75, 1.5, 2.0, 3.0, 4.5, 6.0];
    let zeta_values = [0.5, 1.125, 2.0, 5.0];
    let mut pts = Vec::new();
    // x/a = 1 + 10^-j, j = 2..10, over a rotating choice of (a, zeta)
    for j in 2..=10 {
        let a = a_values[j % a_values.len()];
        let zeta = zeta_values[j % zeta_values.len()];
        pts.push((a, zeta, a * (1.0 + 10f64.powi(-(j as i32)))));
    }
    // a grid over (a, zeta) with x/a spread over (1, 5]
    let ratios = [1.03125, 1.5, 2.25, 3.5, 5.0];
    let mut r = 0;
    for &a in &a_values {
        for &zeta in &zeta_values {
            pts.push((a, zeta, a * ratios[r % ratios.len()]));
            r += 1;
        }
    }
    // the extremes: D = 2 pi 6 / 0.5 ~ 75 near the edge and far away
    pts.push((6.0, 0.5, 6.0 * (1.0 + 1e-6)));
    pts.push((6.0, 0.5, 30.0));
    pts.push((5.5, 1.125, 5.6));
    pts.push((2.0, 1.125, 2.6));
    pts.push((0.7, 2.0, 0.75));
    pts.push((3.0, 2.0, 9.0));
    pts.push((0.125, 5.0, 0.625));
    pts.push((1.0, 1.0, 1.0625));
    pts.push((1.25, 3.0, 4.0));
    pts.push((2.5, 4.0, 2.5 * 1.0001));
    pts.push((0.5, 0.75, 2.0));
    pts.push((3.5, 5.0, 10.5));
    pts.push((1.75, 0.625, 1.75 * 1.001));
    pts.push((0.375, 1.5, 1.5));
    pts
}

/// The points a cross-check runs in this tier: every point under `./dev test
/// --long`, every fourth one in the default tier (13 of the 51: x/a = 1 + 10^-j
/// for j = 2, 6, 10, one grid point at each of the seven a, three far points).
pub fn tier_points() -> Vec<(f64, f64, f64)> {
    let all = points();
    if crate::tier::long() {
        all
    } else {
        all.into_iter().step_by(4).collect()
    }
}
