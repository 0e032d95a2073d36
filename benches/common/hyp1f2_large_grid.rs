//! The issue-23 grid of `1F2(a; b1, b2; z)` at large parameters: `a`, `b1`, `b2`
//! in `[-500, 500]`, `z` in `[-500, 500]`, drawn by a fixed linear congruential
//! generator (so the bench, the example and `reference/bench_arb_hyp1f2_grid.py`
//! see the same points) and rounded to multiples of `2^-13` (exact binary
//! numbers, as typed in the issue). Near-poles are excluded: a lower parameter
//! within `1/16` of a non-positive integer is redrawn.

/// Number of grid points.
pub const GRID_POINTS: usize = 64;

/// The grid's points `(a, b1, b2, z)`; the first is the slow point.
pub fn large_grid() -> Vec<(f64, f64, f64, f64)> {
    let mut state: u64 = 0x2323_2323_2323_2323;
    let mut draw = || {
        state = state.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
        let u = (state >> 11) as f64 / (1u64 << 53) as f64;
        ((u * 1000.0 - 500.0) * 8192.0).round() / 8192.0
    };
    let near_pole = |b: f64| b <= 0.0 && (b - b.round()).abs() < 1.0 / 16.0;
    let mut pts = vec![(-337.8177490234375, 427.4927978515625, 294.2845458984375, -63.8824462890625)];
    while pts.len() < GRID_POINTS {
        let (a, b1, b2, z) = (draw(), draw(), draw(), draw());
        if near_pole(b1) || near_pole(b2) {
            continue;
        }
        pts.push((a, b1, b2, z));
    }
    pts
}

/// The model point `1F2(1/2; 1, 3/2; z)` for `z` down to `-10^6` (issue 23's
/// second criterion: each at 53, 128 and 400 bits in at most 10 ms).
pub const MODEL_Z: [f64; 8] = [-300.0, -3000.0, -10000.0, -22500.0, -50000.0, -100000.0, -500000.0, -1000000.0];

/// The grid and the model points as `(a, b1, b2, z)`.
#[allow(dead_code)]
pub fn all_points() -> Vec<(f64, f64, f64, f64)> {
    let mut pts = large_grid();
    pts.extend(MODEL_Z.iter().map(|&z| (0.5, 1.0, 1.5, z)));
    pts
}
