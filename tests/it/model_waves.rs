//! Profiles of many waves (issue 35): superposition, one wave as the seed paper's
//! model, and the certified route on two waves.
//!
//! * two waves of equal wavelength give the state of one wave with the summed
//!   amplitude (to the solver's tolerance: the two sums round differently);
//! * a wave of amplitude 0 changes nothing, bit for bit;
//! * the order of the waves changes nothing, to rounding;
//! * `Params::with_profile` with one wave is `Params::new`, bit for bit;
//! * the certified balls of a two-wave state (strip ratio, load, traction) enclose
//!   the f64 values, up to the f64 route's own error;
//! * the N-wave limits: adhesionless load and envelope are the sums of the waves'.

use maugis::contact::curve::{load_area_curve, state, CurveOptions, CurvePoint};
use maugis::contact::limits::{adhesionless_load, adhesionless_load_profile, envelope_halfwidth, envelope_halfwidth_profile, mdmt_strip_end};
use maugis::contact::model::{ContactSize, Params};
use maugis::contact::model_mp::{load_mp, solve_m_mp};
use maugis::contact::profile::WavyProfile;
use maugis::contact::traction_mp::traction_mp;
use maugis::error::{ProfileError, WaveField};
use maugis::Error;
use proptest::prelude::*;
use rug::Float;

fn with_waves(lambda: f64, pairs: &[(f64, f64)]) -> Params {
    Params::with_profile(lambda, WavyProfile::from_pairs(pairs).unwrap()).unwrap()
}

/// `|a - b| <= tol (1 + |b|)` on the state's numbers.
fn close(a: &CurvePoint, b: &CurvePoint, tol: f64) -> Result<(), String> {
    let rel = |x: f64, y: f64| (x - y).abs() <= tol * (1.0 + y.abs());
    if rel(a.m_minus_1, b.m_minus_1) && rel(a.load, b.load) && rel(a.approach, b.approach) && a.validity.valid == b.validity.valid {
        Ok(())
    } else {
        Err(format!("{a:?}\n vs {b:?}"))
    }
}

/// Two solves of the same state agree ([`close`] at `1e-9`), or both fail; validity
/// may differ only next to a tolerance's edge (`pbar` or the strip gap within `1e-6` of it).
fn agree(a: &maugis::Result<CurvePoint>, b: &maugis::Result<CurvePoint>) -> Result<(), String> {
    match (a, b) {
        (Ok(x), Ok(y)) => match close(x, y, 1e-9) {
            Err(e) if x.validity.valid != y.validity.valid => {
                let margin = (x.validity.max_traction - 1.0).abs().min(x.validity.min_strip_gap.abs());
                if margin < 1e-6 { Ok(()) } else { Err(format!("validity flips away from an edge: {e}")) }
            }
            r => r,
        },
        (Err(_), Err(_)) => Ok(()),
        (x, y) => Err(format!("one solves, the other not: {x:?} vs {y:?}")),
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 32, .. ProptestConfig::default() })]

    #[test]
    fn equal_wavelengths_add_their_amplitudes(
        lambda in 0.2f64..8.0, a1 in 0.0f64..0.6, a2 in 0.0f64..0.6, beta in 0.4f64..3.0, abar in 0.3f64..4.0,
    ) {
        let two = state(with_waves(lambda, &[(a1, beta), (a2, beta)]), abar);
        let one = state(Params::new(lambda, a1 + a2, beta).unwrap(), abar);
        // equal up to the root's tolerance (1e-13 relative in m - 1) and the sums' rounding
        let r = agree(&two, &one);
        prop_assert!(r.is_ok(), "{r:?}");
    }

    #[test]
    fn a_wave_of_amplitude_zero_changes_nothing(
        lambda in 0.2f64..8.0, alpha in 0.0f64..0.6, beta in 0.4f64..3.0, beta0 in 0.05f64..5.0, abar in 0.3f64..4.0,
    ) {
        let plain = state(Params::new(lambda, alpha, beta).unwrap(), abar);
        let padded = state(with_waves(lambda, &[(alpha, beta), (0.0, beta0)]), abar);
        let front = state(with_waves(lambda, &[(0.0, beta0), (alpha, beta)]), abar);
        if alpha > 0.0 {
            prop_assert_eq!(&padded, &plain);
            prop_assert_eq!(&front, &plain);
        } else {
            // the smooth cylinder: the scan resolves the finest wavelength given
            prop_assert!(padded.is_ok() == plain.is_ok());
        }
    }

    #[test]
    fn the_order_of_the_waves_changes_nothing(
        lambda in 0.2f64..8.0, a1 in 0.0f64..0.5, b1 in 0.5f64..3.0, a2 in 0.0f64..0.3, b2 in 0.2f64..1.5,
        a3 in 0.0f64..0.2, b3 in 0.1f64..0.8, abar in 0.3f64..3.0,
    ) {
        let w = [(a1, b1), (a2, b2), (a3, b3)];
        let base = state(with_waves(lambda, &w), abar);
        for perm in [[2, 0, 1], [1, 2, 0], [2, 1, 0]] {
            let r = agree(&base, &state(with_waves(lambda, &perm.map(|i| w[i])), abar));
            prop_assert!(r.is_ok(), "{perm:?}: {r:?}");
        }
    }
}

#[test]
fn one_wave_profile_is_params_new_bit_for_bit() {
    let opts = CurveOptions { amax: 4.0, points: 80, ..CurveOptions::default() };
    for (lambda, alpha, beta) in [(0.5, std::f64::consts::SQRT_2 / 4.0, 1.125), (3.0, 0.0, 1.125), (6.0, 0.2, 0.3)] {
        let a = Params::new(lambda, alpha, beta).unwrap();
        let b = Params::with_profile(lambda, WavyProfile::one_wave(alpha, beta).unwrap()).unwrap();
        assert_eq!(a, b);
        let (ca, cb) = (load_area_curve(a, opts).unwrap(), load_area_curve(b, opts).unwrap());
        assert_eq!(ca.points, cb.points);
        assert_eq!((ca.pull_off, ca.turning_points.len(), ca.jumps.len()), (cb.pull_off, cb.turning_points.len(), cb.jumps.len()));
    }
}

/// The certified route on two waves: the ball of `m` at 40 bits contains the f64
/// root (its error is 1e-13 relative in `m - 1`), the load ball at that `m` ball
/// the f64 load, and the traction balls the f64 traction, each up to the f64 route's
/// error (`1e-12` of the load scale, `1e-11` for the traction).
#[test]
fn certified_two_wave_balls_enclose_the_f64_state() {
    let p = with_waves(3.0, &[(std::f64::consts::SQRT_2 / 4.0, 1.125), (std::f64::consts::SQRT_2 / 8.0, 0.375)]);
    for abar in [0.6, 1.5, 2.2, 3.1] {
        let cs = ContactSize::new(p, abar).unwrap();
        let strip = cs.solve_strip().unwrap();
        let m_ball = solve_m_mp(p, abar, 40).unwrap();
        let near = |ball: &maugis::Ball, v: f64, slack: f64| {
            let d = Float::with_val(128, ball.mid() - v).abs();
            d <= Float::with_val(128, ball.rad() + slack)
        };
        assert!(near(&m_ball, strip.m(), 1e-13 * strip.m_minus_1()), "abar {abar}: m {} vs {m_ball:?}", strip.m());
        assert!(m_ball.rad() < 1e-9, "abar {abar}: m ball {m_ball:?} too wide");
        let load = load_mp(p, abar, &m_ball, 40).unwrap();
        let scale = std::f64::consts::PI * abar * abar / 4.0;
        assert!(near(&load, cs.load_at(strip), 1e-12 * scale), "abar {abar}: load {} vs {load:?}", cs.load_at(strip));
        for x in [0.0, 0.3 * abar, 0.77 * abar, 0.95 * abar] {
            let t = traction_mp(p, abar, &m_ball, x, 40).unwrap();
            let f = cs.traction_at(strip, x);
            assert!(near(&t, f, 1e-11), "abar {abar}, x {x}: traction {f} vs {t:?}");
        }
    }
}

#[test]
fn limits_of_many_waves_are_sums() {
    let pairs = [(0.35, 1.125), (0.2, 0.375), (0.1, 0.125)];
    let p = WavyProfile::from_pairs(&pairs).unwrap();
    for abar in [0.5, 2.0, 5.0] {
        let sum: f64 = pairs.iter().map(|&(a, b)| adhesionless_load(a, b, abar) - std::f64::consts::PI * abar * abar / 4.0).sum();
        let l = adhesionless_load_profile(&p, abar);
        assert!((l - std::f64::consts::PI * abar * abar / 4.0 - sum).abs() < 1e-12 * (1.0 + sum.abs()));
        let h: f64 = pairs.iter().map(|&(a, b)| envelope_halfwidth(a, b, abar)).sum();
        assert!((envelope_halfwidth_profile(&p, abar) - h).abs() < 1e-13 * h);
    }
    // E.43b for many waves: the first root, below the cylinder's sqrt(2/lambda)
    for lambda in [0.05, 0.3, 2.0] {
        let c = mdmt_strip_end(Params::with_profile(lambda, p).unwrap()).unwrap();
        let f = |c: f64| lambda * c * c / 2.0 + 2.0 * lambda * pairs.iter().map(|&(a, b)| a * (std::f64::consts::PI * c / b).sin().powi(2)).sum::<f64>() - 1.0;
        assert!(f(c).abs() < 1e-9, "lambda {lambda}: f({c}) = {}", f(c));
        assert!(c <= (2.0 / lambda).sqrt() * (1.0 + 1e-12));
        let n = 20_000;
        assert!((1..n).all(|i| f(c * i as f64 / n as f64) < 0.0), "lambda {lambda}: a root below {c}");
    }
}

#[test]
fn bad_profiles_are_typed_errors_naming_the_wave() {
    let cases: [(&[(f64, f64)], usize, WaveField); 4] = [
        (&[(0.3, 1.0), (f64::NAN, 0.5)], 2, WaveField::Amplitude),
        (&[(-0.1, 1.0)], 1, WaveField::Amplitude),
        (&[(0.3, 1.0), (0.1, 0.0)], 2, WaveField::Wavelength),
        (&[(0.3, 1.0), (0.1, 0.5), (0.1, f64::INFINITY)], 3, WaveField::Wavelength),
    ];
    for (pairs, wave, field) in cases {
        match WavyProfile::from_pairs(pairs) {
            Err(Error::Profile(ProfileError::Wave { wave: w, field: f, .. })) => assert_eq!((w, f), (wave, field), "{pairs:?}"),
            other => panic!("{pairs:?}: {other:?}"),
        }
    }
    assert!(matches!(WavyProfile::from_pairs(&[(0.1, 1.0); 65]), Err(Error::Profile(ProfileError::TooManyWaves { count: 65, .. }))));
    assert!(Params::with_profile(f64::NAN, WavyProfile::smooth()).is_err());
}

#[cfg(feature = "serde")]
#[test]
fn params_of_many_waves_round_trip_through_json() {
    let p = with_waves(2.0, &[(0.3, 1.125), (0.1, 0.375)]);
    let json = serde_json::to_string(&p).unwrap();
    assert_eq!(json, r#"{"lambda":2.0,"waves":[{"alpha":0.3,"beta":1.125},{"alpha":0.1,"beta":0.375}]}"#);
    assert_eq!(serde_json::from_str::<Params>(&json).unwrap(), p);
    let one = Params::new(2.0, 0.3, 1.125).unwrap();
    assert_eq!(serde_json::to_string(&one).unwrap(), r#"{"lambda":2.0,"alpha":0.3,"beta":1.125}"#);
    assert!(serde_json::from_str::<Params>(r#"{"lambda":2.0,"waves":[{"alpha":-0.3,"beta":1.0}]}"#).unwrap_err().to_string().contains("wave 1"));
}
