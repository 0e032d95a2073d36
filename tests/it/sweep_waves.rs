//! Sweeps over profiles of many waves (issue 35): the `amplitude` axis scales every
//! amplitude of a base profile the grid carries.
//!
//! * one wave on the amplitude axis is the `alpha` axis at `alpha = s alpha_1`, point
//!   for point and bit for bit (every field but the axis' value and the index);
//! * a two-wave sweep in two shards merges into the unsharded sweep;
//! * shards of different profiles, and of a profile and a one-wave axis, are a typed
//!   `DifferentProfiles`; the amplitude axis without a profile, a profile on a one-wave
//!   axis and a scale that takes an amplitude out of its range are typed errors;
//! * the JSON records the base profile, and a sweep written without one (before the
//!   amplitude axis existed) still reads back.

use maugis::contact::profile::WavyProfile;
use maugis::contact::sweep::{merge, run_sweep, sweep_point, Regime, SweepAxis, SweepGrid};
use maugis::error::{ProfileError, SweepError};
use maugis::Error;

/// The Fig. 4c wave and a second of a third of its wavelength and half its amplitude.
fn two_waves() -> WavyProfile {
    WavyProfile::from_pairs(&[(0.35, 1.125), (0.175, 0.375)]).unwrap()
}

fn amplitude_grid(profile: WavyProfile) -> SweepGrid {
    SweepGrid {
        lambda_min: 1.0,
        lambda_max: 6.0,
        lambda_n: 2,
        axis: SweepAxis::Amplitude,
        min: 0.0,
        max: 1.0,
        n: 3,
        fixed: 0.0,
        profile: Some(profile),
        amax: 6.0,
        points: 40,
    }
}

#[test]
fn one_wave_on_the_amplitude_axis_is_the_alpha_axis() {
    let (alpha_1, beta) = (0.35, 1.125);
    let g = SweepGrid { min: 0.2, max: 1.3, n: 4, ..amplitude_grid(WavyProfile::one_wave(alpha_1, beta).unwrap()) };
    let sweep = run_sweep(g, None, || ()).unwrap();
    assert_eq!(sweep.points.len(), 8);
    for p in &sweep.points {
        let s = g.value(p.index % g.n);
        assert_eq!(p.value, s);
        assert_eq!((p.alpha, p.beta), (s * alpha_1, beta));
        // the existing path: the alpha axis at the one value alpha = s alpha_1
        let one = SweepGrid {
            lambda_min: p.lambda,
            lambda_max: p.lambda,
            lambda_n: 1,
            axis: SweepAxis::Alpha,
            min: s * alpha_1,
            max: s * alpha_1,
            n: 1,
            fixed: beta,
            profile: None,
            amax: g.amax,
            points: g.points,
        };
        let q = sweep_point(&one, 0).unwrap();
        assert_eq!(q.value, s * alpha_1);
        assert_eq!({ let mut q = q; q.index = p.index; q.value = p.value; q }, *p, "point {}", p.index);
    }
    // the map is not trivial: the rough lambda = 6 row holds a loop
    assert!(sweep.points.iter().any(|p| p.regime == Regime::Dissipative), "{:?}", sweep.points);
}

#[test]
fn a_two_wave_sweep_in_shards_merges_into_the_whole() {
    let g = amplitude_grid(two_waves());
    let whole = run_sweep(g, None, || ()).unwrap();
    let a = run_sweep(g, Some((1, 2)), || ()).unwrap();
    let b = run_sweep(g, Some((2, 2)), || ()).unwrap();
    assert_eq!((a.points.len(), b.points.len()), (3, 3));
    assert_eq!(merge(&[b, a]).unwrap(), whole);
    // scale 0 is the smooth cylinder; the points carry the first wave, scaled
    for p in &whole.points {
        let s = g.value(p.index % g.n);
        assert_eq!((p.alpha, p.beta), (s * 0.35, 1.125));
        if s == 0.0 {
            assert_eq!(p.regime, Regime::SmoothLike, "{p:?}");
        }
    }
    let scaled = g.profile_at(1).unwrap();
    assert_eq!(scaled, WavyProfile::from_pairs(&[(0.5 * 0.35, 1.125), (0.5 * 0.175, 0.375)]).unwrap());
    // the second wave changes the map: not the one wave's sweep
    let one = run_sweep(amplitude_grid(WavyProfile::one_wave(0.35, 1.125).unwrap()), None, || ()).unwrap();
    assert_ne!(one.points[2].dissipation, whole.points[2].dissipation);
}

#[test]
fn shards_of_different_profiles_do_not_merge() {
    let g = amplitude_grid(two_waves());
    let a = run_sweep(g, Some((1, 2)), || ()).unwrap();
    let other = WavyProfile::from_pairs(&[(0.35, 1.125), (0.175, 0.25)]).unwrap();
    let b = run_sweep(amplitude_grid(other), Some((2, 2)), || ()).unwrap();
    match merge(&[a.clone(), b]) {
        Err(Error::Sweep(SweepError::DifferentProfiles { first, other })) => {
            assert_eq!(first, two_waves().describe());
            assert!(other.contains("0.25"), "{other}");
        }
        r => panic!("expected DifferentProfiles, got {r:?}"),
    }
    // a one-wave axis' shard (no profile) with a profile's
    let alpha = SweepGrid { axis: SweepAxis::Alpha, max: 0.35, fixed: 1.125, profile: None, ..g };
    let c = run_sweep(alpha, Some((2, 2)), || ()).unwrap();
    assert!(matches!(merge(&[a, c]), Err(Error::Sweep(SweepError::DifferentProfiles { .. }))));
}

#[test]
fn bad_amplitude_grids_are_typed_errors() {
    let g = amplitude_grid(two_waves());
    assert_eq!(SweepGrid { profile: None, ..g }.check(), Err(Error::Sweep(SweepError::NoBaseProfile)));
    assert_eq!(SweepGrid { profile: Some(WavyProfile::smooth()), ..g }.check(), Err(Error::Sweep(SweepError::NoBaseProfile)));
    assert_eq!(
        SweepGrid { axis: SweepAxis::Alpha, fixed: 1.125, ..g }.check(),
        Err(Error::Sweep(SweepError::ProfileOnOneWaveAxis { axis: "alpha", waves: 2 }))
    );
    assert_eq!(
        SweepGrid { min: -0.5, ..g }.check(),
        Err(Error::Sweep(SweepError::AxisStart { axis: "amplitude", min: -0.5, zero_allowed: true }))
    );
    // a scale that takes the first wave over the largest amplitude names it
    assert!(matches!(
        SweepGrid { max: 1e7, ..g }.check(),
        Err(Error::Profile(ProfileError::Wave { wave: 1, .. }))
    ));
    assert!(matches!(run_sweep(SweepGrid { max: f64::NAN, ..g }, None, || ()), Err(Error::NonFinite { .. })));
}

#[cfg(feature = "serde")]
#[test]
fn the_json_records_the_profile_and_old_sweeps_still_read() {
    let g = amplitude_grid(two_waves());
    let part = run_sweep(SweepGrid { lambda_n: 1, n: 2, ..g }, Some((1, 2)), || ()).unwrap();
    let text = serde_json::to_string(&part).unwrap();
    let v: serde_json::Value = serde_json::from_str(&text).unwrap();
    assert_eq!(v["grid"]["axis"], "amplitude");
    assert_eq!(v["grid"]["profile"][1]["beta"].to_string(), "0.375");
    let back: maugis::contact::sweep::Sweep = serde_json::from_str(&text).unwrap();
    assert_eq!(back, part);
    // a one-wave axis writes no profile, as sweeps did before it: such JSON reads back
    let alpha = SweepGrid { lambda_n: 1, n: 2, axis: SweepAxis::Alpha, max: 0.35, fixed: 1.125, profile: None, ..g };
    let old = run_sweep(alpha, Some((2, 2)), || ()).unwrap();
    let text = serde_json::to_string(&old).unwrap();
    assert!(!text.contains("profile"), "{text}");
    assert_eq!(serde_json::from_str::<maugis::contact::sweep::Sweep>(&text).unwrap(), old);
}
