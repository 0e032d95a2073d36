//! Validity and accuracy of the model from lambda = 1e-2 to 1e6 (issue 9, item 3):
//! the strip equation solved for m - 1 converges to the JKR limit with full
//! relative accuracy, no smooth state is flagged invalid, and the refined
//! pull-off matches a 40-digit reference (reference/pull_off_smooth.py).

use maugis::contact::curve::{load_area_curve, CurveOptions};
use maugis::contact::limits::jkr_load;
use maugis::contact::model::{ContactSize, Params};
use maugis::contact::model_mp::solve_m_mp;

/// `(lambda, abar, load)` rows of reference/data/pull_off_smooth.csv.
fn reference() -> Vec<(f64, f64, f64)> {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/reference/data/pull_off_smooth.csv");
    let mut r = csv::Reader::from_path(path).expect("reference/data/pull_off_smooth.csv (run reference/pull_off_smooth.py)");
    r.records()
        .map(|rec| {
            let rec = rec.unwrap();
            let f = |i: usize| rec[i].parse::<f64>().unwrap();
            (f(0), f(1), f(2))
        })
        .collect()
}

#[test]
fn smooth_large_lambda_all_valid_and_pull_off_to_1e_9() {
    let rows = reference();
    assert_eq!(rows.len(), 3);
    for (lambda, abar_ref, load_ref) in rows {
        let c = load_area_curve(Params::new(lambda, 0.0, 1.0).unwrap(), CurveOptions::default()).unwrap();
        let invalid: Vec<f64> = c.points.iter().filter(|p| !p.validity.valid).map(|p| p.abar).collect();
        assert!(invalid.is_empty(), "lambda = {lambda}: {} invalid states, first at {:?}", invalid.len(), invalid.first());
        let po = c.pull_off.expect("pull-off");
        assert!(!po.at_grid_edge && po.validity.valid, "lambda = {lambda}: {po:?}");
        let rel = (po.load - load_ref).abs() / load_ref.abs();
        assert!(rel < 1e-9, "lambda = {lambda}: pull-off {} vs reference {load_ref} (rel {rel:e})", po.load);
        assert!((po.abar - abar_ref).abs() < 1e-4, "lambda = {lambda}: pull-off at {} vs {abar_ref}", po.abar);
    }
}

/// Small lambda (M-DMT side): the relative tolerances still flag nothing in the smooth case.
#[test]
fn smooth_small_lambda_all_valid() {
    for lambda in [0.01, 0.1] {
        let c = load_area_curve(Params::new(lambda, 0.0, 1.0).unwrap(), CurveOptions::default()).unwrap();
        let n = c.points.iter().filter(|p| !p.validity.valid).count();
        assert_eq!(n, 0, "lambda = {lambda}: {n} invalid states");
    }
}

/// lambda -> inf: the load tends to E.42a (about like 1/lambda^2) down to the
/// rounding level of the load, with no floor from rounding m (at lambda = 1e6,
/// m - 1 ~ 1e-12; computed as m, then minus 1, the load was off by 2e-5).
#[test]
fn jkr_limit_with_full_relative_accuracy() {
    for abar in [0.3, 0.86, 2.0, 5.0] {
        let jkr = jkr_load(0.0, 1.0, abar).unwrap();
        let mut errs = Vec::new();
        for lambda in [1e4, 1e5, 1e6] {
            let cs = ContactSize::new(Params::new(lambda, 0.0, 1.0).unwrap(), abar).unwrap();
            let strip = cs.solve_strip().unwrap();
            let ratio = strip.m_minus_1() * 4.0 * lambda * lambda * abar / std::f64::consts::PI;
            assert!((ratio - 1.0).abs() < 3.0 / lambda, "abar = {abar}, lambda = {lambda}: ratio {ratio}");
            errs.push((cs.load_at(strip) - jkr).abs());
        }
        for w in errs.windows(2) {
            assert!(w[1] < 0.2 * w[0] + 1e-13, "abar = {abar}: errors {errs:?}");
        }
        assert!(errs[2] < 1e-12 * (1.0 + jkr.abs()), "abar = {abar}: {errs:?}");
    }
}

/// The f64 root in m - 1 agrees with the certified MP enclosure to 1e-12
/// relative even at lambda = 1e6, where m itself has four correct digits of m - 1.
#[test]
fn m_minus_1_agrees_with_certified_root() {
    for (lambda, abar) in [(1e6, 0.86), (1e4, 3.0)] {
        let p = Params::new(lambda, 0.0, 1.0).unwrap();
        let e = ContactSize::new(p, abar).unwrap().solve_strip().unwrap().m_minus_1();
        let m = solve_m_mp(p, abar, 128).unwrap();
        let e_mp = (rug::Float::with_val(400, m.mid()) - 1u32).to_f64();
        assert!((e - e_mp).abs() < 1e-12 * e_mp, "lambda = {lambda}: {e} vs {e_mp}");
    }
}
