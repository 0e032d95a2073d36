//! Quasi-static paths of a load-area response under load control and under
//! displacement control, the jumps they meet, their hysteresis loops and the
//! energy those loops dissipate.
//!
//! # Paths (issue 9, "what to build" 1)
//!
//! A path is driven by a *control variable* `y`: the load `Lbar` under load
//! control, the approach `Delta-bar` ([`crate::contact::model::ContactSize::approach_at`]) under
//! displacement control. Both are functions of the contact size along the
//! solved curve.
//!
//! * **Loading** starts at the smallest computed contact and follows the running
//!   maximum of `y`: where `y` turns down (a local maximum, refined by
//!   golden-section search) the state jumps forward, at constant `y`, to the
//!   first larger contact where `y` is back at that level (refined by Brent's
//!   method). Maxima passed over by a jump are never met and are not listed.
//! * **Unloading** starts at the largest contact and follows the running minimum
//!   of `y` backwards: at a local minimum it jumps back to the first smaller
//!   contact with the same `y`; the first minimum without such a target ends the
//!   path (pull-off under load control). A path that reaches the smallest grid
//!   contact ends there (`at_grid_edge`).
//!
//! A path's `y` is monotone by construction, so each path is a single-valued
//! function of `y`, and the two paths can be compared at equal `y`.
//!
//! # Dissipation: the closed cycle
//!
//! The first loading starts out of contact (`abar -> 0+`) and unloading ends at
//! pull-off, where the body separates: the two paths of the first cycle do not
//! close, and the states out of contact that would close them are not part of
//! the model. The dissipation is therefore that of the **closed cycle** of
//! repeated loading and unloading in contact: unloading from the largest
//! contact to its end (pull-off under load control), then **reloading** from
//! that state back to the largest contact. The two paths meet at both ends, so
//! the energy lost is the area they enclose in the `(Delta, Lbar)` plane.
//! When the largest contact lies on a falling branch (a fine wave's fold at the
//! grid's end, common with many scales), reloading cannot get back to it; the
//! cycle then runs between pull-off and the grid state of the largest control
//! value, the state a machine loading up to that value reaches, and its unloading
//! path is [`ControlPaths::cycle_unloading`] (the first version reported no loop and
//! W = 0 there). The area is
//!
//! ```text
//! W = -oint Delta dL = oint L dDelta = sum over loops of the enclosed area,
//! load control:          W   = int (Delta_unload(L) - Delta_reload(L)) dL
//! displacement control:  W_d = int (L_reload(Delta) - L_unload(Delta)) dDelta
//! ```
//!
//! in units of `dgamma l_h` per unit length of the cylinder (`Lbar Delta-bar`
//! is `(E* dgamma^2 R)^(1/3) l_v = dgamma l_h`). A closed area is unchanged by
//! the shear `Delta -> Delta + k Lbar`, so W does not depend on the datum of
//! the approach, and W and W_d are areas of the same kind: under displacement
//! control the jumps (at constant `Delta_d`) cut each fold of the curve
//! closer to the curve than the jumps at constant load, so `W_d <= W` fold by
//! fold, and `W_d -> W` as the datum recedes; only near pull-off can the
//! stiffer machine keep a contact that load control loses and meet extra folds
//! (docs/model.md, "Dissipation"; tests `displacement_control_dissipates_less`
//! and `dissipation_is_the_area_of_the_closed_cycle`).
//! Each path is a polyline through the grid states and the refined jump ends,
//! integrated exactly (the trapezoid rule in `y`; second order in the grid
//! spacing).
//!
//! (A first version clipped the *first* cycle at the start of loading instead.
//! That region is open at its lower end and its clipping line is horizontal
//! under load control but slanted under displacement control, so the two
//! numbers measured different areas: at lambda = 3, W = 3.08 against W_d =
//! 3.75, where the closed cycle gives W = 4.41 and W_d = 3.78.)
//!
//! A **loop** is a maximal `y` interval where the reloading and unloading paths
//! are at different contact sizes; it is counted once. A loop is *valid* when
//! every state either path visits inside it passes the model's validity test
//! (no cavitation, no interpenetration): the paper finds that cavitation
//! removes the hysteresis, so the dissipation of invalid loops is reported
//! apart.

use crate::contact::curve_state::CurvePoint;
use crate::contact::model::{solve_load_and_approach, Params};
use crate::roots::{brent, golden_section_min};
use crate::error::{Error, Interval, Invariant, Result};

/// Which variable the machine controls.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
pub enum Control {
    /// The load `Lbar` (dead weight).
    Load,
    /// The approach `Delta-bar` (rigid machine).
    Displacement,
}

/// Direction of a jump.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
pub enum JumpDirection {
    /// Increasing control variable: from a maximum to a larger contact.
    Loading,
    /// Decreasing control variable: from a minimum to a smaller contact.
    Unloading,
}

/// A state visited by a path.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct PathNode {
    /// Contact half-width.
    pub abar: f64,
    /// Load, Eq. 14.
    pub load: f64,
    /// Approach from a datum at infinity.
    pub approach: f64,
    /// The state passes the validity test (for refined states: the nearest grid state's flag).
    pub valid: bool,
}

/// A jump at constant control variable.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Jump {
    /// Direction.
    pub direction: JumpDirection,
    /// The turning point it starts from (or the path's first state, see `from_turning_point`).
    pub from: PathNode,
    /// The state it lands on.
    pub to: PathNode,
    /// `false` only for a loading path that starts on a falling branch and
    /// leaves its first state at once.
    pub from_turning_point: bool,
}

/// A hysteresis loop: a maximal interval of the control variable where the
/// loading and unloading paths differ.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct HysteresisLoop {
    /// Lower end of the control variable.
    pub control_low: f64,
    /// Upper end.
    pub control_high: f64,
    /// Smallest contact either path visits inside the loop.
    pub abar_low: f64,
    /// Largest.
    pub abar_high: f64,
    /// Energy dissipated in the loop (units of `dgamma l_h`).
    pub dissipation: f64,
    /// Every visited state inside the loop is valid.
    pub valid: bool,
}

/// Dissipation of one cycle, split by loop validity.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Dissipation {
    /// All loops.
    pub total: f64,
    /// Valid loops only.
    pub valid: f64,
    /// Loops through invalid (cavitating or interpenetrating) states.
    pub invalid: f64,
}

/// The end of the unloading path.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct PathEnd {
    /// The last state in contact (pull-off under load control).
    pub state: PathNode,
    /// The path reached the smallest grid contact instead of a minimum without
    /// target: the true end may lie at a smaller contact.
    pub at_grid_edge: bool,
}

/// The quasi-static cycle under one kind of control.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct ControlPaths {
    /// The controlled variable.
    pub control: Control,
    /// The datum of the approach under displacement control (1 under load control).
    pub datum: f64,
    /// The loading path, by increasing contact.
    pub loading: Vec<PathNode>,
    /// The unloading path, by decreasing contact.
    pub unloading: Vec<PathNode>,
    /// The jumps both paths meet, in the order met (loading first).
    pub jumps: Vec<Jump>,
    /// The end of the unloading path.
    pub end: Option<PathEnd>,
    /// The loading path stopped at a maximum whose target lies beyond the grid.
    pub loading_truncated: bool,
    /// The loading path of the closed cycle: from the end of unloading (the
    /// most tensile state in contact) up to the largest contact. Loops and
    /// dissipation are those of `reloading` and `unloading`.
    pub reloading: Vec<PathNode>,
    /// The jumps `reloading` meets (below the first loading jump they can
    /// differ from `jumps`).
    pub reloading_jumps: Vec<Jump>,
    /// The closed cycle's unloading path when it is not `unloading`: empty, unless
    /// the largest contact lies on a falling branch that reloading cannot reach;
    /// the cycle then runs between pull-off and the grid state of the largest
    /// control value, and this is its unloading path (from that state). When
    /// reloading stops there too, at a maximum between grid states above every
    /// later one (an oscillation finer than the grid), the cycle runs up to the
    /// grid state just before that maximum (up to 16 such cuts, each lower).
    #[cfg_attr(feature = "serde", serde(default))]
    pub cycle_unloading: Vec<PathNode>,
    /// The closed cycle does not close: reloading from the end of unloading
    /// stops at a maximum with no later grid state at its level, both up to the
    /// largest contact, up to the grid's largest control value and up to the
    /// cuts below the maxima it stops at (see `cycle_unloading`). There is then
    /// no cycle: `loops` is empty and `dissipation` is zero because nothing was
    /// measured, not because the contact dissipates nothing (more curve points
    /// or another `amax` may close it).
    #[cfg_attr(feature = "serde", serde(default))]
    pub reloading_truncated: bool,
    /// The hysteresis loops, by increasing control variable.
    pub loops: Vec<HysteresisLoop>,
    /// Their dissipation.
    pub dissipation: Dissipation,
}

/// Cuts of the grid [`control_paths`] tries when the closed cycle does not close
/// (each below the maximum the last reloading walk stopped at); past them the
/// cycle is reported open.
const MAX_CYCLE_CUTS: usize = 16;

/// Relative `abar` tolerance of a refined extremum.
const EXTREMUM_ABAR_TOL: f64 = 1e-9;
/// Relative difference of contact sizes below which two paths coincide.
const SAME_STATE_TOL: f64 = 1e-7;
/// Relative amount by which grid states next to a refined minimum may lie
/// below it (the minimum is refined to `EXTREMUM_ABAR_TOL` in `abar`, so its
/// control value is accurate to rounding).
const START_LEVEL_TOL: f64 = 1e-12;

/// What a path is driven by: the load, or the approach measured at a datum
/// `x_d` (units of `l_h`): `Delta_d = Delta + (2 Lbar/pi) ln x_d`.
///
/// In plane strain the approach from a datum at infinity (log term removed) is
/// the displacement at `x_d = 1`, inside the contact for `abar > 1`: a rigid
/// machine grips the body far away, and the paths under displacement control
/// depend on where (the dissipation under load control does not).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Driver {
    /// The controlled variable.
    pub control: Control,
    /// `ln x_d` (displacement control only).
    pub ln_datum: f64,
}

impl Driver {
    /// Load control.
    pub fn load() -> Driver {
        Driver { control: Control::Load, ln_datum: 0.0 }
    }

    /// Displacement control at datum `x_d > 0` (finite).
    pub fn displacement(datum: f64) -> Result<Driver> {
        crate::error::finite(datum, "datum")?;
        Interval::above(0.0).check("the displacement datum", datum)?;
        Ok(Driver { control: Control::Displacement, ln_datum: datum.ln() })
    }

    /// The controlled value of a state `(load, approach)`.
    pub fn value(&self, la: (f64, f64)) -> f64 {
        match self.control {
            Control::Load => la.0,
            Control::Displacement => la.1 + 2.0 * la.0 / std::f64::consts::PI * self.ln_datum,
        }
    }
}

/// The state at `abar`: `(load, approach)` ([`solve_load_and_approach`]).
pub fn load_and_approach(params: Params, abar: f64) -> Result<(f64, f64)> {
    solve_load_and_approach(params, abar)
}

/// Validity of the grid state nearest to `abar`.
fn valid_near(pts: &[CurvePoint], abar: f64) -> bool {
    let i = pts.partition_point(|p| p.abar < abar);
    let cand = [i.checked_sub(1), Some(i)];
    cand.iter()
        .flatten()
        .filter_map(|&k| pts.get(k))
        .min_by(|p, q| (p.abar - abar).abs().total_cmp(&(q.abar - abar).abs()))
        .map(|p| p.validity.valid)
        .unwrap_or(true)
}

fn node(pts: &[CurvePoint], params: Params, abar: f64) -> Result<PathNode> {
    let (load, approach) = load_and_approach(params, abar)?;
    Ok(PathNode { abar, load, approach, valid: valid_near(pts, abar) })
}

fn grid_node(p: &CurvePoint) -> PathNode {
    PathNode { abar: p.abar, load: p.load, approach: p.approach, valid: p.validity.valid }
}

/// Golden-section search for the extremum of `y` on `[lo, hi]` (`sign = 1`:
/// maximum, `-1`: minimum). Returns the refined node.
fn refine_extremum(pts: &[CurvePoint], params: Params, control: Driver, lo: f64, hi: f64, sign: f64) -> Result<PathNode> {
    let g = |a: f64| -> Result<f64> { Ok(-sign * control.value(load_and_approach(params, a)?)) };
    let (x, _) = golden_section_min(g, lo, hi, EXTREMUM_ABAR_TOL, 100)?;
    node(pts, params, x)
}

/// The contact in `[lo, hi]` where `y` crosses `level` (Brent).
fn refine_crossing(pts: &[CurvePoint], params: Params, control: Driver, lo: f64, hi: f64, level: f64) -> Result<PathNode> {
    let f = |a: f64| load_and_approach(params, a).map(|la| control.value(la) - level).unwrap_or(f64::NAN);
    let (flo, fhi) = (f(lo), f(hi));
    if !(flo.is_finite() && fhi.is_finite()) {
        return Err(Error::Invariant(Invariant::JumpTargetNotComputable { lo, hi }));
    }
    let a = if flo <= 0.0 && fhi >= 0.0 {
        brent(f, lo, hi, flo, fhi)?
    } else if flo >= 0.0 && fhi <= 0.0 {
        brent(|a| -f(a), lo, hi, -flo, -fhi)?
    } else {
        // both on one side (grid-level noise): take the nearer end
        if flo.abs() < fhi.abs() {
            lo
        } else {
            hi
        }
    };
    let mut n = node(pts, params, a)?;
    // a jump is at constant control variable: pin it
    match control.control {
        Control::Load => n.load = level,
        // Delta_d = Delta + (2 L/pi) ln x_d is pinned; the load jumps
        Control::Displacement => n.approach = level - 2.0 * n.load / std::f64::consts::PI * control.ln_datum,
    }
    Ok(n)
}

/// A loading walk: the path from `start` (a state at or before `pts[i0]`) up
/// the running maximum of the control variable; returns its states, its jumps
/// and whether it stopped at a maximum whose target lies beyond the grid.
/// `start_on_curve`: the start is an ordinary state (the smallest grid
/// contact), which the path leaves at once if the control variable falls from
/// it; otherwise the start is a refined minimum (the end of unloading).
fn walk_loading(
    pts: &[CurvePoint],
    params: Params,
    control: Driver,
    start: PathNode,
    i0: usize,
    start_on_curve: bool,
) -> Result<(Vec<PathNode>, Vec<Jump>, bool)> {
    let y = |p: &CurvePoint| control.value((p.load, p.approach));
    let yn = |n: &PathNode| control.value((n.load, n.approach));
    let n = pts.len();
    let mut jumps = Vec::new();
    let mut loading = vec![start];
    let mut truncated = false;
    let mut last_target = if start_on_curve { f64::NEG_INFINITY } else { start.abar };
    let mut i = i0;
    // a refined minimum may sit a rounding error above its neighbours
    while !start_on_curve && i < n && y(&pts[i]) < yn(&start) && yn(&start) - y(&pts[i]) <= START_LEVEL_TOL * (1.0 + y(&pts[i]).abs()) {
        i += 1;
    }
    while i < n {
        let last = *loading.last().unwrap_or(&start);
        if y(&pts[i]) >= yn(&last) {
            loading.push(grid_node(&pts[i]));
            i += 1;
            continue;
        }
        // y turned down between the last visited state and pts[i]
        let (from, at_turn) = if start_on_curve && loading.len() == 1 {
            (last, false)
        } else {
            // the maximum lies after the previous grid state (or the last jump target)
            let lo = pts[i.saturating_sub(2)].abar.max(last_target);
            let tp = refine_extremum(pts, params, control, lo, pts[i].abar, 1.0)?;
            if yn(&tp) >= yn(&last) {
                // states past the refined maximum are not on the path
                while loading.len() > 1 && loading.last().map_or(false, |q| q.abar >= tp.abar) {
                    loading.pop();
                }
                loading.push(tp);
                (tp, true)
            } else {
                (last, true)
            }
        };
        let level = yn(&from);
        match (i..n).find(|&j| y(&pts[j]) >= level) {
            Some(j) => {
                let lo = if j == 0 { from.abar } else { pts[j - 1].abar.max(from.abar) };
                let to = refine_crossing(pts, params, control, lo, pts[j].abar, level)?;
                jumps.push(Jump { direction: JumpDirection::Loading, from, to, from_turning_point: at_turn });
                loading.push(to);
                last_target = to.abar;
                i = j;
                // skip grid states at or before the refined target
                while i < n && pts[i].abar <= to.abar {
                    i += 1;
                }
            }
            None => {
                truncated = true;
                break;
            }
        }
    }
    Ok((loading, jumps, truncated))
}

/// Builds the loading and unloading paths, jumps, loops and dissipation of a
/// solved curve (`pts` by increasing `abar`, at least two).
pub fn control_paths(params: Params, pts: &[CurvePoint], control: Driver) -> Result<ControlPaths> {
    if pts.len() < 2 {
        let value = i64::try_from(pts.len()).unwrap_or(i64::MAX);
        return Err(Error::IntegerOutOfRange { arg: "the states of a path", value, min: 2, max: i64::MAX });
    }
    let y = |p: &CurvePoint| control.value((p.load, p.approach));
    let yn = |n: &PathNode| control.value((n.load, n.approach));
    let n = pts.len();

    // ---------------------------------------------------------- loading
    let (loading, mut jumps, loading_truncated) = walk_loading(pts, params, control, grid_node(&pts[0]), 1, true)?;

    // ---------------------------------------------------------- unloading
    let (unloading, unloading_jumps, end) = walk_unloading(pts, params, control)?;
    jumps.extend(unloading_jumps);

    // ---------------------------------------------------------- reloading
    // The closed cycle: load again from the end of unloading.
    let (mut reloading, mut reloading_jumps, mut reloading_truncated) = reload(pts, params, control, end)?;
    let mut cycle_unloading = Vec::new();
    let mut levels: Vec<f64> = jumps.iter().map(|j| yn(&j.from)).collect();
    if reloading_truncated {
        // The largest contact lies on a falling branch: reloading cannot get back to
        // it. The cycle then runs between pull-off and the grid's largest control
        // value (the state a machine loading to that value reaches), on the grid up
        // to that state.
        // When the refined maximum reloading stopped at lies between grid states and
        // above every one of them (an oscillation finer than the grid), the grid's
        // largest control value lies past it and reloading stops at it again; the
        // cycle then runs up to the grid state just before that maximum, or, when
        // reloading on the grid up to there stops at an earlier such maximum (its
        // jump's target lay past the cut), before that one, and so on down.
        let mut top = (0..n).fold(0, |best, k| if y(&pts[k]) >= y(&pts[best]) { k } else { best });
        let before = |abar: f64| pts.partition_point(|q| q.abar < abar).saturating_sub(1);
        for _ in 0..MAX_CYCLE_CUTS {
            if top < 1 {
                break;
            }
            let grid = &pts[..=top];
            let (u, u_jumps, u_end) = walk_unloading(grid, params, control)?;
            let (r, r_jumps, r_truncated) = reload(grid, params, control, u_end)?;
            if !r_truncated {
                levels.extend(u_jumps.iter().map(|j| yn(&j.from)));
                (cycle_unloading, reloading, reloading_jumps, reloading_truncated) = (u, r, r_jumps, false);
                break;
            }
            // the next cut: before the maximum this walk stopped at (strictly lower)
            top = r.last().map_or(0, |p| before(p.abar)).min(top - 1);
        }
    }
    levels.extend(reloading_jumps.iter().map(|j| yn(&j.from)));
    let cycle = if cycle_unloading.is_empty() { &unloading } else { &cycle_unloading };
    let (loops, dissipation) = loops_and_dissipation(control, &reloading, cycle, &levels, reloading_truncated);
    Ok(ControlPaths {
        control: control.control,
        datum: control.ln_datum.exp(),
        loading,
        unloading,
        jumps,
        end,
        loading_truncated,
        reloading,
        reloading_jumps,
        cycle_unloading,
        reloading_truncated,
        loops,
        dissipation,
    })
}

/// The closed cycle's reloading walk from the end of unloading (from the smallest
/// grid contact when unloading reached the grid's edge).
fn reload(pts: &[CurvePoint], params: Params, control: Driver, end: Option<PathEnd>) -> Result<(Vec<PathNode>, Vec<Jump>, bool)> {
    match end {
        Some(e) if !e.at_grid_edge => {
            let i0 = pts.partition_point(|p| p.abar <= e.state.abar);
            walk_loading(pts, params, control, e.state, i0, false)
        }
        _ => walk_loading(pts, params, control, grid_node(&pts[0]), 1, true),
    }
}

/// An unloading walk from the largest grid contact down the running minimum of the
/// control variable: its states, its jumps and its end (pull-off under load control).
fn walk_unloading(pts: &[CurvePoint], params: Params, control: Driver) -> Result<(Vec<PathNode>, Vec<Jump>, Option<PathEnd>)> {
    let y = |p: &CurvePoint| control.value((p.load, p.approach));
    let yn = |n: &PathNode| control.value((n.load, n.approach));
    let n = pts.len();
    let mut jumps = Vec::new();
    let mut unloading = vec![grid_node(&pts[n - 1])];
    let mut end = None;
    let mut last_target = f64::INFINITY;
    let mut i = n as isize - 2;
    while i >= 0 {
        let k = i as usize;
        let last = *unloading.last().unwrap_or(&grid_node(&pts[n - 1]));
        if y(&pts[k]) <= yn(&last) {
            unloading.push(grid_node(&pts[k]));
            i -= 1;
            continue;
        }
        // y turned up between pts[k] and the last visited state: a minimum
        let hi = pts[(k + 2).min(n - 1)].abar.min(last_target);
        let tp = refine_extremum(pts, params, control, pts[k].abar, hi, -1.0)?;
        let from = if yn(&tp) <= yn(&last) {
            while unloading.len() > 1 && unloading.last().map_or(false, |q| q.abar <= tp.abar) {
                unloading.pop();
            }
            unloading.push(tp);
            tp
        } else {
            last
        };
        let level = yn(&from);
        match (0..=k).rev().find(|&j| y(&pts[j]) <= level) {
            Some(j) => {
                let to = refine_crossing(pts, params, control, pts[j].abar, pts[j + 1].abar.min(from.abar), level)?;
                jumps.push(Jump { direction: JumpDirection::Unloading, from, to, from_turning_point: true });
                unloading.push(to);
                last_target = to.abar;
                i = j as isize;
                while i >= 0 && pts[i as usize].abar >= to.abar {
                    i -= 1;
                }
            }
            None => {
                end = Some(PathEnd { state: from, at_grid_edge: false });
                break;
            }
        }
    }
    if end.is_none() {
        if let Some(&last) = unloading.last() {
            end = Some(PathEnd { state: last, at_grid_edge: true });
        }
    }
    Ok((unloading, jumps, end))
}

/// A path as `(y, x, abar, valid)` by increasing `y` (`x` is the conjugate variable).
fn by_increasing_y(control: Driver, path: &[PathNode], reverse: bool) -> Vec<(f64, f64, f64, bool)> {
    let mut v: Vec<(f64, f64, f64, bool)> = path
        .iter()
        .map(|n| match control.control {
            Control::Load => (n.load, n.approach, n.abar, n.valid),
            Control::Displacement => (control.value((n.load, n.approach)), n.load, n.abar, n.valid),
        })
        .collect();
    if reverse {
        v.reverse();
    }
    v
}

/// `int x dy` along a monotone polyline, clipped to `y in [y1, y2]`.
fn clipped_integral(p: &[(f64, f64, f64, bool)], y1: f64, y2: f64) -> f64 {
    let mut s = 0.0;
    for w in p.windows(2) {
        let ((ya, xa, ..), (yb, xb, ..)) = (w[0], w[1]);
        if yb <= ya {
            continue; // a jump (or a flat step): no dy
        }
        let (lo, hi) = (ya.max(y1), yb.min(y2));
        if hi <= lo {
            continue;
        }
        let at = |y: f64| xa + (xb - xa) * (y - ya) / (yb - ya);
        s += 0.5 * (at(lo) + at(hi)) * (hi - lo);
    }
    s
}

/// The contact size of a monotone path at `y` (the last state with that `y`
/// when the path jumps there, so that a jump's far end counts).
fn abar_at(p: &[(f64, f64, f64, bool)], y: f64) -> Option<f64> {
    let k = p.partition_point(|q| q.0 <= y);
    if k == 0 || k >= p.len() {
        return if k >= 1 && (p[k - 1].0 - y).abs() <= 0.0 { Some(p[k - 1].2) } else { None };
    }
    let (a, b) = (p[k - 1], p[k]);
    if b.0 <= a.0 {
        return Some(a.2);
    }
    Some(a.2 + (b.2 - a.2) * (y - a.0) / (b.0 - a.0))
}

/// Loops and dissipation of a loading and an unloading path (as built by
/// [`control_paths`]); `jump_levels` are the controlled values where either
/// path jumps. Public so that tests can re-evaluate a cycle with another datum.
pub fn loops_and_dissipation(
    control: Driver,
    loading: &[PathNode],
    unloading: &[PathNode],
    jump_levels: &[f64],
    loading_truncated: bool,
) -> (Vec<HysteresisLoop>, Dissipation) {
    let l = by_increasing_y(control, loading, false);
    let u = by_increasing_y(control, unloading, true);
    let (Some(l0), Some(u0), Some(l1), Some(u1)) = (l.first(), u.first(), l.last(), u.last()) else {
        return (Vec::new(), Dissipation::default());
    };
    let y_c = l0.0.max(u0.0);
    let y_h = l1.0.min(u1.0);
    if !(y_h > y_c) || loading_truncated {
        return (Vec::new(), Dissipation::default());
    }
    // Breakpoints: every y where either path jumps, inside (y_c, y_h).
    let mut ys: Vec<f64> = vec![y_c, y_h];
    ys.extend(jump_levels.iter().copied().filter(|&y| y > y_c && y < y_h));
    ys.sort_by(f64::total_cmp);
    ys.dedup();
    let scale = l.iter().chain(u.iter()).map(|q| q.2.abs()).fold(0.0, f64::max);
    let differ = |y: f64| match (abar_at(&l, y), abar_at(&u, y)) {
        (Some(a), Some(b)) => (a - b).abs() > SAME_STATE_TOL * scale,
        _ => false,
    };
    let mut intervals: Vec<(f64, f64)> = Vec::new();
    for w in ys.windows(2) {
        if differ(0.5 * (w[0] + w[1])) {
            match intervals.last_mut() {
                Some(last) if last.1 == w[0] => last.1 = w[1],
                _ => intervals.push((w[0], w[1])),
            }
        }
    }
    // Load control integrates Delta dL (unloading minus loading); displacement
    // control integrates L dDelta (loading minus unloading).
    let sign = match control.control {
        Control::Load => 1.0,
        Control::Displacement => -1.0,
    };
    let mut loops = Vec::new();
    let mut total = Dissipation::default();
    for (lo, hi) in intervals {
        let w = sign * (clipped_integral(&u, lo, hi) - clipped_integral(&l, lo, hi));
        let inside = |q: &&(f64, f64, f64, bool)| q.0 >= lo && q.0 <= hi;
        let visited: Vec<&(f64, f64, f64, bool)> = l.iter().filter(inside).chain(u.iter().filter(inside)).collect();
        let valid = visited.iter().all(|q| q.3);
        let abar_low = visited.iter().map(|q| q.2).fold(f64::INFINITY, f64::min);
        let abar_high = visited.iter().map(|q| q.2).fold(f64::NEG_INFINITY, f64::max);
        loops.push(HysteresisLoop { control_low: lo, control_high: hi, abar_low, abar_high, dissipation: w, valid });
        total.total += w;
        if valid {
            total.valid += w;
        } else {
            total.invalid += w;
        }
    }
    (loops, total)
}
