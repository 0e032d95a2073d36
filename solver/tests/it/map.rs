//! The solver map (`map`): shards merged equal the whole, bad merges and bad
//! options are typed errors, and the labels follow their definition on a small
//! grid (lambda in {1, 6}, alpha in {0, 0.35}, beta = 9/8, 1024 cells, 100 steps:
//! about a second).

use maugis::contact::sweep::{Regime, SweepAxis, SweepGrid};
use maugis_solver::map::{
    map_cycles, merge_maps, run_map, MapOptions, Resolution, ResolutionRule, SolverRegime, DEFAULT_MARGIN,
};
use maugis_solver::{MergeFault, SolverError};

fn grid() -> SweepGrid {
    SweepGrid { lambda_min: 1.0, lambda_max: 6.0, lambda_n: 2, axis: SweepAxis::Alpha, min: 0.0, max: 0.35, n: 2, fixed: 1.125, profile: None, amax: 6.0, points: 60 }
}

fn options() -> MapOptions {
    MapOptions { resolution: ResolutionRule::Fixed(Resolution { cells: 1024, steps_per_leg: 100 }), margin: DEFAULT_MARGIN, ..MapOptions::default() }
}

#[test]
fn shards_merge_to_the_whole_and_labels_follow_the_definition() {
    let (g, o) = (grid(), options());
    // the alpha = 0 points are their rows' smooth references: 4 cycles, not 6
    assert_eq!(map_cycles(&g, None).unwrap().len(), 4);
    let count = std::sync::atomic::AtomicUsize::new(0);
    let whole = run_map(g, o, None, || {
        count.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
    })
    .unwrap();
    assert_eq!(count.into_inner(), 4, "one progress call per cycle");
    let shards: Vec<_> = (1..=3).map(|s| run_map(g, o, Some((s, 3)), || ()).unwrap()).collect();
    assert_eq!(shards.iter().map(|s| s.points.len()).sum::<usize>(), 4);
    // in any order
    let merged = merge_maps(&[shards[2].clone(), shards[0].clone(), shards[1].clone()]).unwrap();
    assert_eq!(merged, whole);

    for p in &whole.points {
        let c = p.solver.expect("every cycle of this grid runs");
        let w_smooth = p.w_smooth.expect("smooth reference");
        let excess = c.w - w_smooth;
        let want = SolverRegime::classify(excess, DEFAULT_MARGIN, c.cavitated_fraction > 0.0);
        assert_eq!(p.regime_solver, want, "{p:?}");
        assert_eq!(p.agree, maugis_solver::map::labels_agree(p.regime_solver, p.model.regime));
        if p.alpha == 0.0 {
            // the smooth reference is this very cycle
            assert_eq!(w_smooth, c.w);
            assert_eq!(p.regime_solver, SolverRegime::SmoothLike, "{p:?}");
            assert_eq!(p.model.regime, Regime::SmoothLike);
        }
    }
    // lambda = 6 with the waves: the solver dissipates far above the margin,
    // with instabilities, and the model agrees
    let rough6 = &whole.points[3];
    assert_eq!((rough6.lambda, rough6.alpha), (6.0, 0.35));
    assert_eq!(rough6.regime_solver, SolverRegime::Dissipative, "{rough6:?}");
    assert!(rough6.solver.unwrap().instabilities > 0 && rough6.solver.unwrap().w > 1.0, "{rough6:?}");
    assert!(rough6.agree);
}

#[test]
fn bad_merges_and_options_are_errors() {
    let (g, o) = (grid(), options());
    let a = run_map(g, o, Some((1, 4)), || ()).unwrap();
    let b = run_map(g, o, Some((2, 4)), || ()).unwrap();
    let merge_fault = |r: Result<_, SolverError>| match r {
        Err(SolverError::Merge { fault }) => fault,
        other => panic!("expected a merge error, got {other:?}"),
    };
    let total = g.len();
    assert!(matches!(merge_fault(merge_maps(&[a.clone(), b.clone()]).map(|_| ())), MergeFault::Missing { missing, total: t } if t == total && missing == total / 2));
    assert!(matches!(merge_fault(merge_maps(&[a.clone(), a.clone()]).map(|_| ())), MergeFault::Duplicate { .. }));
    assert_eq!(merge_fault(merge_maps(&[]).map(|_| ())), MergeFault::Empty);
    let other = MapOptions { margin: 0.5, ..o };
    let c = run_map(g, other, Some((3, 4)), || ()).unwrap();
    assert_eq!(merge_fault(merge_maps(&[a, b, c]).map(|_| ())), MergeFault::DifferentMaps);

    assert!(matches!(run_map(g, MapOptions { margin: -1.0, ..o }, None, || ()), Err(SolverError::OutOfRange { arg: "the margin", value: -1.0, .. })));
    assert!(matches!(run_map(g, MapOptions { margin: f64::NAN, ..o }, None, || ()), Err(SolverError::NonFinite { arg: "margin", .. })));
    let fixed = |cells, steps_per_leg| MapOptions { resolution: ResolutionRule::Fixed(Resolution { cells, steps_per_leg }), ..o };
    assert!(matches!(run_map(g, fixed(1000, 100), None, || ()), Err(SolverError::Grid { cells: 1000, .. })));
    assert!(matches!(run_map(g, fixed(1024, 1), None, || ()), Err(SolverError::CountOutOfRange { arg: "steps per leg", value: 1, min: 2, .. })));
    assert!(matches!(run_map(g, o, Some((0, 2)), || ()), Err(SolverError::BadShard { shard: 0, of: 2 })));
    assert!(matches!(run_map(g, o, Some((3, 2)), || ()), Err(SolverError::BadShard { shard: 3, of: 2 })));
    assert!(matches!(run_map(SweepGrid { lambda_min: 0.0, ..g }, o, None, || ()), Err(SolverError::Model(_))));
}

/// The map runs one wave's cycles: one wave on the amplitude axis (`alpha_1 = 1`, so
/// the scale is the amplitude) runs the alpha axis' cycles; two waves are refused with
/// `MapManyWaves` before any cycle.
#[test]
fn the_amplitude_axis_maps_one_wave_and_refuses_many() {
    use maugis::contact::profile::WavyProfile;
    let g = grid();
    let one = SweepGrid { axis: SweepAxis::Amplitude, fixed: 0.0, profile: Some(WavyProfile::one_wave(1.0, 1.125).unwrap()), ..g };
    assert_eq!(map_cycles(&one, None).unwrap(), map_cycles(&g, None).unwrap());
    let two = SweepGrid { profile: Some(WavyProfile::from_pairs(&[(1.0, 1.125), (0.5, 0.375)]).unwrap()), ..one };
    assert_eq!(map_cycles(&two, None), Err(SolverError::MapManyWaves { waves: 2 }));
    assert!(matches!(run_map(two, options(), None, || ()), Err(SolverError::MapManyWaves { waves: 2 })));
}
