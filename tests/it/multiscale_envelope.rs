//! Issue 39, item 1: the envelope of the load-area response of many-wave profiles
//! (`contact::multiscale`). The constants: one wave gives the paper's envelope, equal
//! wavelengths add, incommensurate ones fall back to the triangle sum, odd ratios are
//! symmetric, even ones lopsided, and the sampling bound encloses a 16 times finer
//! search. The model: over Weierstrass profiles and lambda (the issue's whole grid
//! under `./dev test --long`, a corner of it by default), the wave part stays inside
//! the phase-locked envelope up to the JKR limit's own finite-`D` excess.

use std::f64::consts::{PI, SQRT_2};

use maugis::contact::multiscale::{envelope_constants, EnvelopeConstants, EnvelopeStudy};
use maugis::contact::profile::WavyProfile;

use crate::tier;

const A1: f64 = 2.0 * SQRT_2 / 8.0;
const B1: f64 = 9.0 / 8.0;

/// `g(a) = sum_j c_j cos(2 pi a/beta_j - 3 pi/4)`, sampled `n` times over `[0, p)`:
/// `(max, -min)`.
fn brute(profile: &WavyProfile, p: f64, n: usize) -> (f64, f64) {
    let (mut hi, mut lo) = (f64::NEG_INFINITY, f64::INFINITY);
    for i in 0..n {
        let a = p * i as f64 / n as f64;
        let g: f64 = profile.waves().iter().map(|w| PI * w.alpha() / w.beta().sqrt() * (2.0 * PI * a / w.beta() - 0.75 * PI).cos()).sum();
        hi = hi.max(g);
        lo = lo.min(g);
    }
    (hi, -lo)
}

#[test]
fn one_wave_is_the_papers_envelope() {
    let c = envelope_constants(&WavyProfile::one_wave(A1, B1).unwrap());
    let c1 = PI * A1 / B1.sqrt();
    assert_eq!((c.triangle, c.upper, c.lower), (c1, c1, c1));
    // the scaled Johnson parameter sqrt(beta/alpha^2) of the Fig. 4c wave is 3
    assert!((EnvelopeConstants::johnson(c.upper) - 3.0).abs() < 1e-14);
    let smooth = envelope_constants(&WavyProfile::smooth());
    assert_eq!((smooth.triangle, smooth.upper, smooth.lower), (0.0, 0.0, 0.0));
}

#[test]
fn equal_wavelengths_add_and_incommensurate_ones_take_the_triangle_sum() {
    let same = envelope_constants(&WavyProfile::from_pairs(&[(A1, B1), (A1 / 2.0, B1)]).unwrap());
    assert_eq!(same.period, Some(B1));
    assert!(same.upper >= same.triangle - same.sampling_error && same.upper <= same.triangle, "{same:?}");
    assert!(same.lower >= same.triangle - same.sampling_error, "{same:?}");
    let free = envelope_constants(&WavyProfile::from_pairs(&[(A1, B1), (A1 / 2.0, B1 / SQRT_2)]).unwrap());
    assert_eq!(free.period, None);
    assert_eq!((free.upper, free.lower), (free.triangle, free.triangle));
}

#[test]
fn odd_ratios_are_symmetric_even_ones_lopsided_and_the_sampling_bound_encloses() {
    for n in [2, 3, 4] {
        for gamma in [2.0, 3.0, 4.0, 5.0] {
            for hurst in [0.0, 0.5, 1.0] {
                let profile = WavyProfile::weierstrass(A1, B1, n, gamma, hurst).unwrap();
                let c = envelope_constants(&profile);
                let p = c.period.expect("integer ratios have a period");
                assert!((p - B1).abs() <= 1e-15 * B1, "period {p}");
                // a 16 times finer search lies inside [upper - error, upper]
                let samples = ((16.0 * 256.0 * p / profile.finest_wavelength().unwrap()).ceil() as usize).min(1_000_000);
                let (hi, lo) = brute(&profile, p, samples);
                // where the finer search is capped it carries a sampling error of its own
                let coarse = (256.0 * p / profile.finest_wavelength().unwrap()).ceil();
                let tol = 1e-13 * c.triangle + c.sampling_error * (coarse / samples as f64).powi(2) * 1.01;
                for (name, m, fine) in [("M+", c.upper, hi), ("M-", c.lower, lo)] {
                    assert!(fine <= m + tol && fine >= m - c.sampling_error - tol, "N {n} gamma {gamma} H {hurst}: {name} {m} (error {}) vs finer {fine}", c.sampling_error);
                }
                assert!(c.upper <= c.triangle && c.lower <= c.triangle);
                if gamma % 2.0 == 1.0 {
                    assert!((c.upper - c.lower).abs() <= c.sampling_error + tol, "odd gamma {gamma}: {c:?}");
                } else {
                    // g(a + P/2) is not -g(a): lopsided (with gamma = 2 the lower side
                    // is the wider one, with gamma = 4 the upper)
                    assert!((c.lower - c.upper).abs() > 0.01 * c.triangle, "even gamma {gamma}, N {n}, H {hurst}: {c:?}");
                    if gamma == 2.0 {
                        assert!(c.lower > c.upper, "gamma 2, N {n}, H {hurst}: {c:?}");
                    }
                }
            }
        }
    }
    // the triangle sum is loose: with N = 3, gamma = 2, H = 0.3 by 43 % above
    let c = envelope_constants(&WavyProfile::weierstrass(A1, B1, 3, 2.0, 0.3).unwrap());
    assert!(c.upper / c.triangle < 0.6, "{c:?}");
}

/// The model's wave part against the phase-locked envelope: it reaches it (within
/// the grid's 0.5 %) and does not exceed it by more than the JKR limit's own excess at
/// finite `D` (plus 1 %), locally (Eq. 17) and globally (adhesionless above, JKR below).
#[test]
fn the_model_stays_inside_the_phase_locked_envelope() {
    let grid = EnvelopeStudy::issue_grid();
    let study = tier::pick(
        EnvelopeStudy { scales: vec![2], gammas: vec![2.0, 3.0], hursts: vec![0.5], lambdas: vec![0.3, 3.0, 100.0], ..grid.clone() },
        grid,
    );
    for case in study.cases() {
        let row = study.row(case).unwrap();
        let (c, all) = (row.constants, row.excursion.all);
        let up = c.upper.max(row.jkr.0) * 1.01;
        let down = c.lower.max(row.jkr.1) * 1.01;
        assert!(all.local_up <= up && all.global_up <= up, "{case:?}: up {} / {} vs {up}", all.local_up, all.global_up);
        assert!(all.local_down <= down && all.global_down <= down, "{case:?}: down {} / {} vs {down}", all.local_down, all.global_down);
        // the JKR limit itself is outside by at most 2.5 % (at D_1 near 2 pi)
        assert!(row.jkr.0 <= 1.025 * c.upper && row.jkr.1 <= 1.025 * c.lower, "{case:?}: {:?} vs {c:?}", row.jkr);
        if case.3 >= 100.0 {
            // and the envelope is reached, not just respected
            assert!(all.local_up >= 0.99 * c.upper && all.local_down >= 0.99 * c.lower, "{case:?}: {all:?} vs {c:?}");
        }
    }
}
