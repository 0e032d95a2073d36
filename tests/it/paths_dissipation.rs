//! Load-control paths, the jumps they meet, loops and dissipation (issue 9,
//! items 1-2), at the paper's Fig. 4c roughness (alpha = 2 sqrt(2)/8, beta = 9/8).
//!
//! * The jumps are recomputed independently from the grid states alone (running
//!   maximum/minimum of the load, no refinement) and must match in number and
//!   place (within a grid step).
//! * The dissipation is recomputed from u_H, u_w and u_a (the displacement
//!   module, not the closed-form approach) at finite data x_d = 40, 80, 160,
//!   extrapolated to infinity (error ~ 1/x_d^2), and must match to 0.2 %.
//! * Shifting the approach by k L (another datum) leaves it unchanged.
//! * Brute force: the closed cycle walked over the grid states alone (running
//!   minimum down, running maximum back up, no refinement) on a 4x finer grid,
//!   its enclosed area taken by the shoelace formula in the (Delta, L) plane,
//!   under both controls; and W_d <= W, with W_d -> W as the datum recedes.

use maugis::contact::curve::{load_area_curve, Curve, CurveOptions, JumpDirection};
use maugis::contact::displacement::{u_adhesive, u_hertz, u_wave};
use maugis::contact::model::{ContactSize, Params};
use maugis::contact::paths::{loops_and_dissipation, Control, Driver, PathNode};

const FIG4C_ALPHA: f64 = 0.353_553_390_593_273_8; // 2 sqrt(2)/8
const FIG4C_BETA: f64 = 1.125;

fn fig4c(lambda: f64) -> Curve {
    load_area_curve(Params::new(lambda, FIG4C_ALPHA, FIG4C_BETA).unwrap(), CurveOptions::default()).unwrap()
}

/// Drop events of a running extremum over the grid loads: (index of the last
/// state before the drop, index of the first state back at that level or None).
fn grid_jumps(loads: &[f64], forward: bool) -> Vec<(usize, Option<usize>)> {
    let n = loads.len();
    let idx: Vec<usize> = if forward { (0..n).collect() } else { (0..n).rev().collect() };
    let better = |a: f64, b: f64| if forward { a >= b } else { a <= b };
    let mut out = Vec::new();
    let mut k = 0;
    let mut level = loads[idx[0]];
    while k + 1 < n {
        let next = loads[idx[k + 1]];
        if better(next, level) {
            level = next;
            k += 1;
            continue;
        }
        let from = k;
        match (k + 1..n).find(|&j| better(loads[idx[j]], level)) {
            Some(j) => {
                out.push((idx[from], Some(idx[j])));
                level = loads[idx[j]];
                k = j;
            }
            None => {
                out.push((idx[from], None));
                break;
            }
        }
    }
    out
}

#[test]
fn jumps_are_those_the_paths_meet() {
    for lambda in [0.25, 0.5, 1.0, 1.5, 3.0, 6.0] {
        let c = fig4c(lambda);
        let loads: Vec<f64> = c.points.iter().map(|p| p.load).collect();
        let h = c.points[1].abar - c.points[0].abar;
        let near = |a: f64, b: f64| (a - b).abs() <= 2.0 * h;
        let lc = &c.load_control;
        // loading
        let grid: Vec<_> = grid_jumps(&loads, true);
        let ours: Vec<_> = lc.jumps.iter().filter(|j| j.direction == JumpDirection::Loading).collect();
        let grid_ok: Vec<_> = grid.iter().filter(|g| g.1.is_some()).collect();
        assert_eq!(ours.len(), grid_ok.len(), "lambda = {lambda}: loading jumps {ours:?} vs grid {grid:?}");
        for (j, g) in ours.iter().zip(&grid_ok) {
            assert!(near(j.from.abar, c.points[g.0].abar), "lambda = {lambda}: {j:?} vs grid from {}", c.points[g.0].abar);
            assert!(near(j.to.abar, c.points[g.1.unwrap()].abar), "lambda = {lambda}: {j:?} vs grid to");
        }
        // unloading: the last drop without a target is pull-off
        let grid: Vec<_> = grid_jumps(&loads, false);
        let ours: Vec<_> = lc.jumps.iter().filter(|j| j.direction == JumpDirection::Unloading).collect();
        let grid_ok: Vec<_> = grid.iter().filter(|g| g.1.is_some()).collect();
        assert_eq!(ours.len(), grid_ok.len(), "lambda = {lambda}: unloading jumps {ours:?} vs grid {grid:?}");
        for (j, g) in ours.iter().zip(&grid_ok) {
            assert!(near(j.from.abar, c.points[g.0].abar) && near(j.to.abar, c.points[g.1.unwrap()].abar), "lambda = {lambda}: {j:?}");
        }
        let po = c.pull_off.unwrap();
        match grid.last() {
            Some((i, None)) => assert!(near(po.abar, c.points[*i].abar), "lambda = {lambda}: pull-off {po:?}"),
            _ => assert!(po.at_grid_edge, "lambda = {lambda}: {po:?}"),
        }
        // every jump starts on its path and loops are counted once
        for w in c.loops.windows(2) {
            assert!(w[0].control_high <= w[1].control_low, "lambda = {lambda}: overlapping loops");
        }
    }
}

/// The example: at lambda = 6 loading meets the maxima at 1.57, 2.73,
/// 3.87 and 5.02, not the one at 0.33.
#[test]
fn lambda_6_loading_maxima() {
    let c = fig4c(6.0);
    let from: Vec<f64> = c
        .jumps
        .iter()
        .filter(|j| j.direction == JumpDirection::Loading && j.from_turning_point)
        .map(|j| j.from.abar)
        .collect();
    let want = [1.57, 2.73, 3.87, 5.02];
    assert_eq!(from.len(), want.len(), "{from:?}");
    for (a, w) in from.iter().zip(want) {
        assert!((a - w).abs() < 0.01, "{from:?}");
    }
}

/// `u(x_d)` of a state: Hertz + wave + adhesive, from the displacement module.
fn u_at_datum(p: Params, abar: f64, xd: f64) -> f64 {
    let cs = ContactSize::new(p, abar).unwrap();
    let m = cs.solve_m().unwrap();
    u_hertz(abar, 1.0, xd).unwrap()
        + u_wave(abar, p.beta(), p.alpha(), xd).unwrap()
        + u_adhesive(abar, m * abar, p.lambda(), 1.0, xd).unwrap()
}

/// `int u dL` along a path between loads `lo` and `hi` (path given by increasing load).
fn integral(path: &[(f64, f64)], lo: f64, hi: f64) -> f64 {
    let mut s = 0.0;
    for w in path.windows(2) {
        let ((la, ua), (lb, ub)) = (w[0], w[1]);
        if lb <= la {
            continue;
        }
        let (a, b) = (la.max(lo), lb.min(hi));
        if b > a {
            let at = |l: f64| ua + (ub - ua) * (l - la) / (lb - la);
            s += 0.5 * (at(a) + at(b)) * (b - a);
        }
    }
    s
}

fn w_at_datum(p: Params, loading: &[PathNode], unloading: &[PathNode], xd: f64) -> f64 {
    let l: Vec<(f64, f64)> = loading.iter().map(|n| (n.load, u_at_datum(p, n.abar, xd))).collect();
    let u: Vec<(f64, f64)> = unloading.iter().rev().map(|n| (n.load, u_at_datum(p, n.abar, xd))).collect();
    let lo = l[0].0.max(u[0].0);
    let hi = l[l.len() - 1].0.min(u[u.len() - 1].0);
    integral(&u, lo, hi) - integral(&l, lo, hi)
}

#[test]
fn dissipation_matches_finite_datum_extrapolation() {
    for lambda in [3.0, 6.0] {
        let c = fig4c(lambda);
        let p = c.params;
        let lc = &c.load_control;
        let ws: Vec<f64> = [40.0, 80.0, 160.0].iter().map(|&xd| w_at_datum(p, &lc.reloading, &lc.unloading, xd)).collect();
        let extrapolated = (4.0 * ws[2] - ws[1]) / 3.0;
        let w = lc.dissipation.total;
        let rel = (w - extrapolated).abs() / extrapolated.abs();
        eprintln!("lambda = {lambda}: W = {w}, finite data {ws:?} -> {extrapolated} (rel {rel:e})");
        assert!(w > 0.0);
        assert!(rel < 2e-3, "lambda = {lambda}: W = {w} vs {extrapolated}");
        // the finite-datum values converge (the datum matters only at O(1/x_d^2))
        assert!((ws[2] - ws[1]).abs() < (ws[1] - ws[0]).abs() + 1e-12);
    }
}

#[test]
fn dissipation_does_not_depend_on_the_datum() {
    let c = fig4c(3.0);
    let lc = &c.load_control;
    let levels: Vec<f64> = lc.jumps.iter().chain(&lc.reloading_jumps).map(|j| j.from.load).collect();
    for k in [-3.0, 0.7, 5.0] {
        let shift = |v: &[PathNode]| -> Vec<PathNode> { v.iter().map(|n| PathNode { approach: n.approach + k * n.load, ..*n }).collect() };
        let (loops, d) = loops_and_dissipation(Driver::load(), &shift(&lc.reloading), &shift(&lc.unloading), &levels, false);
        assert_eq!(loops.len(), lc.loops.len());
        let w = lc.dissipation.total;
        assert!((d.total - w).abs() < 1e-10 * w, "k = {k}: {} vs {w}", d.total);
    }
}

#[test]
fn displacement_control_paths_are_consistent() {
    let c = fig4c(6.0);
    let dc = &c.displacement_control;
    assert_eq!(dc.control, Control::Displacement);
    let drv = Driver::displacement(dc.datum).unwrap();
    for j in &dc.jumps {
        // a jump under displacement control keeps the approach at the datum
        let (a, b) = (drv.value((j.from.load, j.from.approach)), drv.value((j.to.load, j.to.approach)));
        assert!((a - b).abs() < 1e-8 * (1.0 + a.abs()), "{j:?}");
    }
    // each path is monotone in its control variable
    let v: Vec<f64> = dc.loading.iter().map(|n| drv.value((n.load, n.approach))).collect();
    assert!(v.windows(2).all(|w| w[1] >= w[0] - 1e-9), "loading not monotone");
    let v: Vec<f64> = dc.unloading.iter().map(|n| drv.value((n.load, n.approach))).collect();
    assert!(v.windows(2).all(|w| w[1] <= w[0] + 1e-9), "unloading not monotone");
    assert!(dc.dissipation.total >= 0.0);
    assert!(Driver::displacement(0.0).is_err() && Driver::displacement(f64::NAN).is_err());
}

/// The closed cycle walked over grid states alone, in the (Delta, L) plane:
/// unloading follows the running minimum of `y` from the largest contact down
/// to the first minimum without a target, reloading the running maximum back
/// up; a jump leaves from the extreme grid state and lands where the chord
/// between the two grid states around the level crosses it (linear
/// interpolation, no solve). Returns the area of the polygon (shoelace formula).
fn brute_force_cycle_area(pts: &[(f64, f64, f64)]) -> f64 {
    // pts: (y, Delta, L) by increasing abar
    let n = pts.len();
    let lerp = |i: usize, j: usize, level: f64| -> (f64, f64) {
        let (a, b) = (pts[i], pts[j]);
        let t = if b.0 == a.0 { 0.0 } else { (level - a.0) / (b.0 - a.0) };
        (a.1 + t * (b.1 - a.1), a.2 + t * (b.2 - a.2))
    };
    let mut unload: Vec<(f64, f64)> = vec![(pts[n - 1].1, pts[n - 1].2)];
    let (mut k, mut level) = (n - 1, pts[n - 1].0);
    while k > 0 {
        if pts[k - 1].0 <= level {
            k -= 1;
            level = pts[k].0;
            unload.push((pts[k].1, pts[k].2));
            continue;
        }
        match (0..k).rev().find(|&j| pts[j].0 <= level) {
            Some(j) => {
                unload.push(lerp(j, j + 1, level));
                unload.push((pts[j].1, pts[j].2));
                k = j;
                level = pts[j].0;
            }
            None => break,
        }
    }
    let end = k;
    let mut reload: Vec<(f64, f64)> = vec![(pts[end].1, pts[end].2)];
    let mut level = pts[end].0;
    while k + 1 < n {
        if pts[k + 1].0 >= level {
            k += 1;
            level = pts[k].0;
            reload.push((pts[k].1, pts[k].2));
            continue;
        }
        let j = (k + 1..n).find(|&j| pts[j].0 >= level).expect("reloading reaches the largest contact");
        reload.push(lerp(j - 1, j, level));
        reload.push((pts[j].1, pts[j].2));
        k = j;
        level = pts[j].0;
    }
    // polygon: reload (end -> n-1), then unload back (n-1 -> end)
    let ring: Vec<(f64, f64)> = reload.iter().chain(unload.iter().skip(1)).copied().collect();
    let mut s = 0.0;
    for w in 0..ring.len() {
        let (a, b) = (ring[w], ring[(w + 1) % ring.len()]);
        s += a.0 * b.1 - b.0 * a.1;
    }
    0.5 * s.abs()
}

#[test]
fn dissipation_is_the_area_of_the_closed_cycle() {
    for lambda in [1.5, 3.0, 6.0] {
        let c = fig4c(lambda);
        let p = c.params;
        let fine = load_area_curve(p, CurveOptions { points: 2400, ..CurveOptions::default() }).unwrap();
        for (paths, drv) in [(&c.load_control, Driver::load()), (&c.displacement_control, Driver::displacement(c.displacement_control.datum).unwrap())] {
            let pts: Vec<(f64, f64, f64)> = fine.points.iter().map(|q| (drv.value((q.load, q.approach)), q.approach, q.load)).collect();
            let area = brute_force_cycle_area(&pts);
            let w = paths.dissipation.total;
            let rel = (w - area).abs() / area;
            eprintln!("lambda = {lambda}, {:?}: W = {w}, brute-force polygon area {area} (rel {rel:e})", paths.control);
            assert!(rel < 5e-3, "lambda = {lambda}, {:?}: W = {w} vs polygon {area}", paths.control);
        }
    }
}

/// A stiffer machine jumps later and less on every fold: W_d <= W, growing
/// towards W as the datum recedes (a machine gripping at x_d has compliance
/// (2/pi) ln x_d, and infinite compliance is load control). The exception is
/// near pull-off: at lambda = 1/2 displacement control at x_d = 100 keeps the
/// contact past the load-control pull-off (its unloading drops to a small
/// contact that is stable under the stiffer machine), and reloading from there
/// adds folds that the load-control cycle never visits.
#[test]
fn displacement_control_dissipates_less() {
    for lambda in [0.5, 1.0, 1.5, 3.0, 6.0] {
        let p = Params::new(lambda, FIG4C_ALPHA, FIG4C_BETA).unwrap();
        let run = |datum: f64| load_area_curve(p, CurveOptions { datum, ..CurveOptions::default() }).unwrap();
        let c = run(100.0);
        let w = c.load_control.dissipation.total;
        let pull_off = c.load_control.end.unwrap().state.abar;
        let dcs: Vec<_> = [1e4, 1e40].iter().map(|&d| run(d).displacement_control).collect();
        let dcs = [&c.displacement_control, &dcs[0], &dcs[1]];
        let wd: Vec<f64> = dcs.iter().map(|d| d.dissipation.total).collect();
        eprintln!("lambda = {lambda}: W = {w}, W_d at data 1e2, 1e4, 1e40: {wd:?}");
        let tol = 1e-9 * (1.0 + w);
        assert!(w > 0.0 && (w - wd[2]) <= 0.05 * w + tol && wd[2] <= w + tol, "lambda = {lambda}: W_d(1e40) = {} vs W = {w}", wd[2]);
        if lambda == 0.5 {
            let end = dcs[0].end.unwrap().state.abar;
            assert!(end < 0.5 * pull_off && wd[0] > w, "lambda = 1/2: end {end} vs pull-off {pull_off}, W_d {wd:?} vs W {w}");
        } else {
            assert!(wd[0] <= wd[1] + tol && wd[1] <= wd[2] + tol, "lambda = {lambda}: W = {w}, W_d = {wd:?}");
        }
    }
}

/// Issue 9, lambda = 1/4: the load-controlled pull-off (-1.52 at abar = 0.935)
/// lies in a cavitating stretch. The valid pull-off is the most tensile valid
/// state unloading can reach, here on the small-contact branch below that
/// stretch: L -> -1.2533 as abar -> 0+ (an independent boundary-element
/// solution with cavitation: -1.233 to -1.244), not a state above it.
#[test]
fn lambda_quarter_valid_pull_off_is_on_the_small_contact_branch() {
    let c = fig4c(0.25);
    let po = c.pull_off.unwrap();
    assert!(!po.validity.valid && (po.load + 1.5203).abs() < 1e-3, "{po:?}");
    let v = c.valid_pull_off.unwrap();
    assert!(v.valid && v.abar < 0.2, "{v:?}");
    // it is the most tensile valid grid state, and the branch limit is near
    let most = c.points.iter().filter(|p| p.validity.valid).map(|p| p.load).fold(f64::INFINITY, f64::min);
    assert_eq!(v.load, most);
    assert!((v.load + 1.2533).abs() < 1e-3, "{v:?}");
    assert!(v.load < -1.233 && v.load > -1.27, "{v:?} vs the BEM's -1.233..-1.244");
    // at lambda = 6 the pull-off itself is valid and is the valid pull-off
    let c6 = fig4c(6.0);
    let (po6, v6) = (c6.pull_off.unwrap(), c6.valid_pull_off.unwrap());
    assert!(po6.validity.valid && (v6.load - po6.load).abs() < 1e-12, "{po6:?} {v6:?}");
}

/// The largest contact on a falling branch (6 Weierstrass scales at lambda = 30, the
/// finest wave folding at abar = 6): the closed cycle runs up to the grid's largest
/// load instead of reporting no loop and W = 0, under both controls; the cycle's
/// paths meet at both ends; on a curve whose last state is the largest (one wave) no
/// cycle is re-based.
#[test]
fn a_cycle_whose_largest_contact_is_on_a_falling_branch_still_closes() {
    use maugis::contact::profile::WavyProfile;
    let profile = WavyProfile::weierstrass(2.0 * std::f64::consts::SQRT_2 / 8.0, 9.0 / 8.0, 6, 2.0, 0.5).unwrap();
    let params = maugis::contact::model::Params::with_profile(30.0, profile).unwrap();
    let curve = maugis::contact::curve::load_area_curve(params, maugis::contact::curve::CurveOptions { amax: 6.0, points: 2730, ..Default::default() }).unwrap();
    let last = curve.points.last().unwrap();
    let top = curve.points.iter().map(|p| p.load).fold(f64::NEG_INFINITY, f64::max);
    assert!(last.load < top, "the grid ends on a falling branch ({} < {top})", last.load);
    for cp in [&curve.load_control, &curve.displacement_control] {
        assert!(!cp.cycle_unloading.is_empty(), "{:?}: the cycle is re-based", cp.control);
        assert!(!cp.reloading_truncated, "{:?}: the re-based cycle closes", cp.control);
        assert!(cp.dissipation.total > 0.0 && !cp.loops.is_empty(), "{:?}: W = {}", cp.control, cp.dissipation.total);
        // the cycle's two paths start and end at the same states
        let (u, r) = (&cp.cycle_unloading, &cp.reloading);
        assert_eq!(u.first().unwrap().abar, r.last().unwrap().abar, "{:?}: top", cp.control);
        assert_eq!(u.last().unwrap().abar, r.first().unwrap().abar, "{:?}: bottom", cp.control);
    }
    // W is at most the sum of the loops' areas and they are all positive
    assert!(curve.load_control.loops.iter().all(|l| l.dissipation > 0.0));
    let one = maugis::contact::curve::load_area_curve(maugis::contact::model::Params::new(3.0, 2.0 * std::f64::consts::SQRT_2 / 8.0, 9.0 / 8.0).unwrap(), Default::default()).unwrap();
    assert!(one.load_control.cycle_unloading.is_empty() && one.displacement_control.cycle_unloading.is_empty());
}

/// A closed cycle whose reloading stops at a maximum finer than the grid (between
/// two grid states, above every later one) closes below that maximum, instead of
/// being reported open with W = 0: the three-scale Weierstrass profile (H = 0.8)
/// at lambda = 1, reported open under load control before at 300 and at the
/// default 600 points (its reloading stopped at abar = 5.926, between two grid
/// states, above the grid's largest load). The cycle now runs up to the grid state
/// before that maximum (default tier: 300 points); under `--long`, W at 600 points
/// agrees with the same curve's at 1200 points (which closed before too) to 2 %.
/// An open cycle reports no loops and W = 0.
#[test]
fn a_cycle_whose_top_maximum_is_finer_than_the_grid_closes_below_it() {
    use maugis::contact::profile::WavyProfile;
    let profile = WavyProfile::weierstrass(2.0 * std::f64::consts::SQRT_2 / 8.0, 9.0 / 8.0, 3, 2.0, 0.8).unwrap();
    let params = Params::with_profile(1.0, profile).unwrap();
    let curve = |points: usize| load_area_curve(params, CurveOptions { amax: 6.0, points, ..Default::default() }).unwrap();
    let coarse = curve(crate::tier::pick(300, 600));
    for cp in [&coarse.load_control, &coarse.displacement_control] {
        assert!(!cp.reloading_truncated && !cp.loops.is_empty() && cp.dissipation.total > 0.0, "{:?}: the cycle closes", cp.control);
    }
    if crate::tier::long() {
        let fine = curve(1200);
        for (c, f) in [(&coarse.load_control, &fine.load_control), (&coarse.displacement_control, &fine.displacement_control)] {
            let (wc, wf) = (c.dissipation.total, f.dissipation.total);
            assert!(!f.reloading_truncated && (wc / wf - 1.0).abs() < 0.02, "{:?}: W = {wc} at 600 points, {wf} at 1200", c.control);
        }
    }
    // under load control the cycle's top is the grid state before the maximum
    let lc = &coarse.load_control;
    let top = lc.cycle_unloading.first().expect("the cycle runs below the largest contact");
    let peak = lc.loading.iter().map(|n| n.load).fold(f64::NEG_INFINITY, f64::max);
    assert!(top.abar < 6.0 && top.load < peak, "top {top:?}, the loading path's largest load {peak}");
    assert_eq!(lc.reloading.last().map(|n| n.abar), Some(top.abar));
    // an open cycle measures nothing
    let (loops, d) = loops_and_dissipation(Driver::load(), &lc.reloading, &lc.cycle_unloading, &[], true);
    assert!(loops.is_empty() && d.total == 0.0);
}
