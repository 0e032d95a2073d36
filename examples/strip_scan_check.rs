//! Does `ContactSize::solve_m` return the *first* root of the strip residual?
//! Draws random model parameters (`lambda` log-uniform in [0.1, 10], `alpha` in
//! [0, 2], `beta` in [0.3, 2.3], `abar` in [0.3, 4.3]; with `short`: `lambda` in
//! [0.1, 100], `alpha` in [0, 3], `beta` in [0.05, 0.3], `abar` in [0.2, 3.2], where
//! the excursions crowd the contact edge; xorshift from a seed), solves
//! the strip, and scans the residual `F` on `(0, c - a)` in steps of `beta/2048`
//! (128 times finer than the solver's scan): a sample with `F >= 0` before the
//! solver's root is a missed first root. Prints each miss, the count and the CPU
//! time spent in `solve_m`.
//!
//!     cargo run --release --features maugis/gmp-no-check --example strip_scan_check [draws] [seed] [short]

use maugis::contact::model::{ContactSize, Params};
use std::time::Instant;

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let draws: usize = args.get(1).and_then(|v| v.parse().ok()).unwrap_or(4000);
    let mut seed: u64 = args.get(2).and_then(|v| v.parse().ok()).unwrap_or(12345);
    let short = args.get(3).is_some_and(|v| v == "short");
    let mut rnd = || {
        seed ^= seed << 13;
        seed ^= seed >> 7;
        seed ^= seed << 17;
        (seed >> 11) as f64 / (1u64 << 53) as f64
    };
    let (mut solved, mut missed, mut solve_s) = (0usize, 0usize, 0.0f64);
    for _ in 0..draws {
        let (lambda, alpha, beta, abar) = if short {
            (10f64.powf(-1.0 + 3.0 * rnd()), 3.0 * rnd(), 0.05 + 0.25 * rnd(), 0.2 + 3.0 * rnd())
        } else {
            (10f64.powf(-1.0 + 2.0 * rnd()), 2.0 * rnd(), 0.3 + 2.0 * rnd(), 0.3 + 4.0 * rnd())
        };
        let Ok(c) = Params::new(lambda, alpha, beta).and_then(|p| ContactSize::new(p, abar)) else { continue };
        let t = Instant::now();
        let Ok(m) = c.solve_m() else { continue };
        solve_s += t.elapsed().as_secs_f64();
        solved += 1;
        let (step, s_end) = (beta / 2048.0, (m - 1.0) * abar);
        let mut s = step;
        while s < s_end - step {
            let f = c.strip_residual_m_minus_1(s / abar).expect("residual");
            if f >= 0.0 {
                missed += 1;
                println!("miss: lambda {lambda} alpha {alpha} beta {beta} abar {abar}: solve_m {m}, F = {f:e} at m = {}", 1.0 + s / abar);
                break;
            }
            s += step;
        }
    }
    println!("{solved} solved, {missed} first roots missed; solve_m {:.1} us per call on average", 1e6 * solve_s / solved.max(1) as f64);
}
