//! The energy dissipated per cycle, measured on a simulated cycle with the
//! library's definition for the semi-analytical model (the **closed in-contact
//! cycle** of `maugis::contact::paths`), so that the two are comparable.
//!
//! # Definition
//!
//! The library defines W on the load-area curve: unload from the largest
//! contact to the end of unloading (pull-off under load control), reload from
//! that state back to the largest contact, and take the area the two paths
//! enclose in the `(Delta, Lbar)` plane:
//!
//! ```text
//! load control:          W   = int (Delta_unload(L) - Delta_reload(L)) dL
//! displacement control:  W_d = int (L_reload(Delta_d) - L_unload(Delta_d)) dDelta_d
//! ```
//!
//! with `Delta_d = Delta + (2 Lbar/pi) ln x_d` the approach at the machine's
//! datum `x_d` (the model's default is `maugis::contact::curve::DEFAULT_DATUM`,
//! 100 `l_h`).
//!
//! # On a simulated cycle
//!
//! [`closed_cycle`] takes the in-contact states of the three legs of a
//! displacement-controlled [`Cycle`] (`abar > 0`: loading, unloading, and the
//! reloading leg from the smallest contact the unloading leg held), puts their approach on the
//! model's datum ([`approach_on_model_datum`]), orders them by `abar`, and walks
//! them as the library walks its curve: unloading from the largest contact down
//! the running minimum of the controlled variable, a jump at each local minimum
//! to the first smaller contact at the same level, the end of unloading at the
//! first minimum without such a state; then reloading from that end up the
//! running maximum (one `walk` serves both). Each turning point is refined
//! by the vertex of a parabola through it and the two states before it
//! (`refine_extremum`), and jump targets are interpolated linearly between
//! the two states that bracket the level. The loops and their areas are then
//! computed by the library's own [`loops_and_dissipation`], so the
//! integration is the model's.
//!
//! The stiff machine of the simulation (datum `L_d = 2X`) jumps over the
//! stretches where `Delta` falls with `abar`, and the legs jump over
//! different stretches. A turning point of the soft paths of W (load control,
//! or a datum of 100 `l_h`) can lie on a stretch that both the loading and the
//! unloading leg jump over: at alpha = 1/6, beta = 9/8, lambda >= 4 the load
//! maximum of the small-contact branch, where the closed cycle's reloading
//! turns, lies between the unloading leg's jump (abar 2.01 to 1.50) and the
//! loading leg's snap-in. The reloading leg ([`Cycle::reloading`]) climbs that
//! branch; without it W was 20-27 % low there.
//!
//! A state is *valid* when it has at most one contact interval; loops through
//! cavitated states count in [`Dissipation::invalid`]. With cavitation, states
//! of different branches can share an `abar`, and their order by `abar` mixes
//! the branches: W is then only an estimate ([`ClosedCycle::single_interval`]
//! says whether every state had one contact interval).
//!
//! This is not [`Cycle::stiff_work`], the work `oint Lbar dDelta` of the
//! stiff-machine cycle from out of contact back to out of contact (12.02 against
//! W = 4.51 at lambda = 6, amax = 6, Fig. 4c roughness).
//!
//! # Along the legs, for cavitated cycles
//!
//! Ordering by `abar` fails once the contact splits: a rough profile of many
//! scales holds up to two dozen contact intervals at once, the legs' loads at
//! one `abar` differ by whole units, and the walk by `abar` jumps between
//! branches (W came out 0 for a 4-scale profile at lambda = 3 that dissipates
//! plainly). [`closed_cycle_along_legs`] reads the same closed cycle off the
//! legs in the order the simulation visited them, which is an order along the
//! branches whatever the contact's shape:
//!
//! * unloading: the largest contact (the last loading state), then the
//!   unloading leg's states in contact, from the state of largest controlled
//!   value (the largest contact, unless it lies on a falling branch: the
//!   library re-bases its cycle the same way), walked as above (running minimum of
//!   the controlled variable, a jump at each local minimum to the first later
//!   state at its level), to the end of unloading;
//! * reloading: the reloading leg (then the loading leg above where it
//!   rejoined), from its state of least controlled value (the end of
//!   unloading, met again from below), walked by the running maximum to the
//!   level unloading started at;
//! * W is the work of the machine around that closed polygon in the
//!   `(Delta, Lbar)` plane, `oint Lbar dDelta` (exact on its straight
//!   segments): the energy the cycle dissipates, since the body returns to
//!   the state it left. It needs no single-valued curve.
//!
//! On a cycle with one contact interval throughout, the two readings agree
//! (`solver/tests/it/dissipation.rs`). The jump targets are interpolated
//! between the two leg states around the level, which is accurate to one
//! approach step; the grid study of `docs/multiscale.md` measures what that
//! costs.

use maugis::contact::paths::{
    loops_and_dissipation, Control, Dissipation, Driver, HysteresisLoop, PathNode,
};

use crate::contact::State;
use crate::error::{count_in_range, finite, in_range, Interval, Result};
use crate::path::{approach_on_model_datum, Cycle};

/// Relative difference in `abar` and in the load below which two simulated
/// states are the same state (the legs reach the states a stiff machine
/// visits both ways at approaches equal up to rounding).
const SAME_STATE: f64 = 1e-7;

/// The closed in-contact cycle of a simulated cycle under one kind of control.
#[derive(Debug, Clone, PartialEq)]
pub struct ClosedCycle {
    /// The controlled variable.
    pub control: Control,
    /// The datum `x_d` of displacement control (1 under load control), on the
    /// model's convention (`Delta_d = Delta_model + (2 Lbar/pi) ln x_d`).
    pub datum: f64,
    /// The unloading path, from the largest contact, by decreasing contact
    /// (approach on the model's datum).
    pub unloading: Vec<PathNode>,
    /// The end of unloading (pull-off under load control).
    pub end: PathNode,
    /// The end of unloading is the smallest simulated contact, not a minimum of
    /// the controlled variable: the true end may lie below it.
    pub end_at_edge: bool,
    /// The reloading path, from `end` to the largest contact.
    pub reloading: Vec<PathNode>,
    /// Reloading stopped at a maximum with no larger contact at its level
    /// (the cycle does not close; the library then reports no loops).
    pub reloading_truncated: bool,
    /// The hysteresis loops, by increasing controlled variable.
    pub loops: Vec<HysteresisLoop>,
    /// Their dissipation (units of `dgamma l_h` per unit length); `invalid`:
    /// loops through cavitated states.
    pub dissipation: Dissipation,
    /// Every state of the cycle had at most one contact interval (otherwise
    /// the ordering by `abar` may mix branches, see the module docs).
    pub single_interval: bool,
}

/// W under load control and under displacement control at one datum.
#[derive(Debug, Clone, PartialEq)]
pub struct CycleDissipation {
    /// Load control.
    pub load_control: ClosedCycle,
    /// Displacement control at `displacement_control.datum`.
    pub displacement_control: ClosedCycle,
}

/// The closed in-contact cycle of `cycle` under `driver` (the library's
/// [`Driver`]: `Driver::load()` or `Driver::displacement(x_d)` on the model's
/// datum). `solver_datum` is the datum the cycle was simulated with
/// ([`crate::contact::ContactSolver::datum`], [`crate::run::Simulation::datum`]).
///
/// Errors: a non-finite or non-positive `solver_datum`, fewer than two
/// in-contact states, or a state with a non-finite load or approach
/// ([`crate::SolverError::NonFinite`], [`crate::SolverError::OutOfRange`], [`crate::SolverError::CountOutOfRange`]).
pub fn closed_cycle(cycle: &Cycle, solver_datum: f64, driver: Driver) -> Result<ClosedCycle> {
    finite(solver_datum, "the solver datum")?;
    in_range(solver_datum, "the solver datum", Interval::above(0.0))?;
    let states: Vec<&State> = cycle
        .loading
        .iter()
        .chain(&cycle.unloading)
        .chain(&cycle.reloading)
        .filter(|s| s.abar > 0.0)
        .collect();
    count_in_range(states.len(), "the cycle's states in contact (the dissipation needs 2)", 2, usize::MAX)?;
    let mut pts = Vec::with_capacity(states.len());
    for s in &states {
        pts.push(path_node(s, solver_datum)?);
    }
    pts.sort_by(|p, q| p.abar.total_cmp(&q.abar));
    // Both legs visit the states a stiff machine reaches either way (at
    // approaches equal up to rounding): keep one.
    pts.dedup_by(|q, p| {
        (q.abar - p.abar).abs() <= SAME_STATE * p.abar.abs().max(1.0)
            && (q.load - p.load).abs() <= SAME_STATE * p.load.abs().max(1.0)
    });
    let single_interval = pts.iter().all(|p| p.valid);
    let n = pts.len();
    // Unloading: the running minimum of the controlled variable from the
    // largest contact; its end is the first minimum with no smaller contact at
    // its level (or the smallest contact).
    let unloading = walk(driver, &pts, pts[n - 1], true, n as isize - 2, -1);
    let (end, end_at_edge) = match unloading.stopped {
        Some(e) => (e, false),
        None => (unloading.path[unloading.path.len() - 1], true),
    };
    // Reloading: the running maximum from the end of unloading.
    let from = pts.partition_point(|p| p.abar <= end.abar) as isize;
    let reloading = walk(driver, &pts, end, false, from, 1);
    let truncated = reloading.stopped.is_some();
    let levels: Vec<f64> = unloading.levels.iter().chain(&reloading.levels).copied().collect();
    let (unloading, reloading) = (unloading.path, reloading.path);
    let (loops, dissipation) =
        loops_and_dissipation(driver, &reloading, &unloading, &levels, truncated);
    Ok(ClosedCycle {
        control: driver.control,
        datum: driver.ln_datum.exp(),
        unloading,
        end,
        end_at_edge,
        reloading,
        reloading_truncated: truncated,
        loops,
        dissipation,
        single_interval,
    })
}

/// A simulated state as a node of a model-convention path: its approach moved
/// to the model's datum, `valid` when it has at most one contact interval.
/// Errors: a non-finite half-width, load or approach.
fn path_node(s: &State, solver_datum: f64) -> Result<PathNode> {
    finite(s.abar, "a state's contact half-width")?;
    finite(s.load, "a state's load")?;
    finite(s.approach, "a state's approach")?;
    Ok(PathNode {
        abar: s.abar,
        load: s.load,
        approach: approach_on_model_datum(s.approach, s.load, solver_datum),
        valid: s.contact_intervals() <= 1,
    })
}

/// A walk of the library's along the states ordered by `abar`: its nodes,
/// the levels of its jumps, and the turning point where it stopped for want of
/// a state beyond its level (`None`: it ran off the states).
struct Walk {
    path: Vec<PathNode>,
    levels: Vec<f64>,
    stopped: Option<PathNode>,
}

/// Walks `pts` (ordered by `abar`) from `first`, the next candidate state at
/// index `next`, in the direction `s` of `abar` (`-1`: unloading, the running
/// minimum of the controlled variable; `+1`: reloading, the running maximum).
/// At a turning point (refined by [`refine_extremum`] when the path's last
/// three nodes are consecutive states; `first_is_state`: `first` is one) it
/// jumps at the turning level to the first state beyond it, interpolated; it
/// stops at a turning point with no such state.
fn walk(driver: Driver, pts: &[PathNode], first: PathNode, first_is_state: bool, next: isize, s: isize) -> Walk {
    let y = |p: &PathNode| driver.value((p.load, p.approach));
    let sign = s as f64;
    let in_range = |c: isize| c >= 0 && (c as usize) < pts.len();
    let at = |c: isize| pts[c as usize];
    let mut path = vec![first];
    let mut levels = Vec::new();
    let mut run = usize::from(first_is_state);
    let mut c = next;
    while in_range(c) {
        let last = path[path.len() - 1];
        if sign * (y(&at(c)) - y(&last)) >= 0.0 {
            path.push(at(c));
            run += 1;
            c += s;
            continue;
        }
        // `last` (the state before `c`) turns: refine it, then jump at its
        // level to the first state beyond it.
        let refined = if run >= 3 {
            refine_extremum(driver, [at(c - 3 * s), at(c - 2 * s), at(c - s)], at(c).abar, sign)
        } else {
            None
        };
        let from = match refined {
            Some(r) => {
                path.pop();
                path.push(r);
                r
            }
            None => last,
        };
        let level = y(&from);
        let mut j = c;
        while in_range(j) && sign * (y(&at(j)) - level) < 0.0 {
            j += s;
        }
        if !in_range(j) {
            return Walk { path, levels, stopped: Some(from) };
        }
        levels.push(level);
        path.push(interpolate(driver, at(j - s), at(j), level));
        run = 0;
        c = j;
    }
    Walk { path, levels, stopped: None }
}

/// The state between `a` and `b` where the controlled variable is `level`
/// (linear in the controlled variable; `level` lies between the two values).
fn interpolate(driver: Driver, a: PathNode, b: PathNode, level: f64) -> PathNode {
    let (ya, yb) = (
        driver.value((a.load, a.approach)),
        driver.value((b.load, b.approach)),
    );
    let t = if yb != ya {
        ((level - ya) / (yb - ya)).clamp(0.0, 1.0)
    } else {
        0.0
    };
    let lin = |u: f64, v: f64| u + t * (v - u);
    let mut n = PathNode {
        abar: lin(a.abar, b.abar),
        load: lin(a.load, b.load),
        approach: lin(a.approach, b.approach),
        valid: if t < 0.5 { a.valid } else { b.valid },
    };
    // A jump is at a constant controlled variable: pin it.
    match driver.control {
        Control::Load => n.load = level,
        Control::Displacement => {
            n.approach = level - 2.0 * n.load / std::f64::consts::PI * driver.ln_datum
        }
    }
    n
}

/// The extremum (`sign = 1`: maximum, `-1`: minimum) of the controlled
/// variable at the end of a path's stretch `q = [q0, q1, q2]`: three
/// consecutive simulated states along the path, `q2` the turning state, and
/// `next` the `abar` of the state after it (where the controlled variable has
/// turned back). The load-area curve is smooth in `abar`, but a leg of the
/// stiff machine often stops at or just past the soft machine's turning point
/// (its own fold is near), so the states on the far side can lie across an
/// unvisited stretch: the parabola in `abar` is fitted on the visited side
/// only, and its vertex may lie up to two spacings beyond `q2` (not past
/// `next`). The load and the approach are taken on the same parabola. `None`
/// when the two spacings differ by more than a factor 4, the parabola does not turn the right
/// way, the vertex is out of that range, or it does not improve on `q2`.
fn refine_extremum(driver: Driver, q: [PathNode; 3], next: f64, sign: f64) -> Option<PathNode> {
    let [p0, p1, p2] = q;
    let (x0, x1, x2) = (p0.abar, p1.abar, p2.abar);
    let h = x2 - x1;
    // Spacings of one sign and comparable size (a parabola through two close
    // states and a far one amplifies their noise).
    let h0 = x1 - x0;
    if !(h * h0 > 0.0 && h / h0 <= 4.0 && h0 / h <= 4.0) {
        return None;
    }
    let y = |p: &PathNode| driver.value((p.load, p.approach));
    let (y0, y1, y2) = (y(&p0), y(&p1), y(&p2));
    let d01 = (y1 - y0) / (x1 - x0);
    let d12 = (y2 - y1) / (x2 - x1);
    let c2 = (d12 - d01) / (x2 - x0);
    if !(sign * c2 < 0.0) {
        return None;
    }
    // y(x) = y0 + d01 (x - x0) + c2 (x - x0)(x - x1); y'(xs) = 0.
    let xs = 0.5 * (x0 + x1) - d01 / (2.0 * c2);
    // Between q1 and q2 + 2h, short of `next` (h may be negative: unloading).
    let (lo, hi) = if h > 0.0 {
        (x1, (x2 + 2.0 * h).min(next))
    } else {
        ((x2 + 2.0 * h).max(next), x1)
    };
    if !(xs > lo && xs < hi) {
        return None;
    }
    let quad = |f0: f64, f1: f64, f2: f64| {
        let (e01, e12) = ((f1 - f0) / (x1 - x0), (f2 - f1) / (x2 - x1));
        f0 + e01 * (xs - x0) + (e12 - e01) / (x2 - x0) * (xs - x0) * (xs - x1)
    };
    let r = PathNode {
        abar: xs,
        load: quad(p0.load, p1.load, p2.load),
        approach: quad(p0.approach, p1.approach, p2.approach),
        valid: p0.valid && p1.valid && p2.valid,
    };
    (sign * (y(&r) - y2) >= 0.0 && y(&r).is_finite()).then_some(r)
}

/// W under load control and under displacement control at the datum
/// `displacement_datum` (model convention, `x_d > 0`; the model's curves use
/// `maugis::contact::curve::DEFAULT_DATUM`).
pub fn cycle_dissipation(
    cycle: &Cycle,
    solver_datum: f64,
    displacement_datum: f64,
) -> Result<CycleDissipation> {
    let mut displacement_control = closed_cycle(
        cycle,
        solver_datum,
        Driver::displacement(displacement_datum)?,
    )?;
    // As given, not exp(ln x_d).
    displacement_control.datum = displacement_datum;
    Ok(CycleDissipation {
        load_control: closed_cycle(cycle, solver_datum, Driver::load())?,
        displacement_control,
    })
}

/// The closed in-contact cycle read along the legs (module docs, "Along the
/// legs"), for cycles whose contact splits.
#[derive(Debug, Clone, PartialEq)]
pub struct LegCycle {
    /// The controlled variable.
    pub control: Control,
    /// The datum `x_d` of displacement control (1 under load control).
    pub datum: f64,
    /// The unloading path, from the state of largest controlled value (the
    /// largest contact, unless that lies on a falling branch).
    pub unloading: Vec<PathNode>,
    /// The end of unloading (pull-off under load control).
    pub end: PathNode,
    /// The unloading leg ran out of states in contact before a turning point:
    /// the true end may lie beyond it.
    pub end_at_edge: bool,
    /// The reloading path, from the reloading leg's state of least controlled
    /// value up to the level unloading started at.
    pub reloading: Vec<PathNode>,
    /// Reloading stopped at a maximum with no later state at its level: the
    /// cycle does not close and `work` is not W.
    pub reloading_truncated: bool,
    /// `|Delta|` between the end of unloading and the start of reloading
    /// (the same state, met from both sides; its size shows how well the legs
    /// resolve it).
    pub start_gap: f64,
    /// W: `oint Lbar dDelta` around the closed cycle (units of `dgamma l_h`).
    pub work: f64,
    /// Fraction of the cycle's nodes with more than one contact interval.
    pub cavitated_fraction: f64,
}

/// The closed in-contact cycle of `cycle` under `driver`, read along the legs
/// (module docs). `solver_datum` as for [`closed_cycle`].
///
/// Errors as [`closed_cycle`]; also fewer than two unloading states in contact,
/// or an empty reloading leg (the unloading leg held no contact).
pub fn closed_cycle_along_legs(cycle: &Cycle, solver_datum: f64, driver: Driver) -> Result<LegCycle> {
    finite(solver_datum, "the solver datum")?;
    in_range(solver_datum, "the solver datum", Interval::above(0.0))?;
    let node = |s: &State| path_node(s, solver_datum);
    let y = |p: &PathNode| driver.value((p.load, p.approach));
    // Unloading: the largest contact, then the leg while in contact; walked
    // backwards over the reversed list (the walk's `-1` is the running minimum).
    let mut unload_states: Vec<PathNode> = Vec::new();
    for s in cycle.loading.last().into_iter().chain(cycle.unloading.iter().take_while(|s| s.abar > 0.0)) {
        unload_states.push(node(s)?);
    }
    count_in_range(unload_states.len(), "the unloading leg's states in contact (the cycle needs 2)", 2, usize::MAX)?;
    // The cycle turns at the largest controlled value: the largest contact
    // unless it lies on a falling branch (as the library re-bases its cycle,
    // `ControlPaths::cycle_unloading`).
    let top = (0..unload_states.len()).fold(0, |best, i| if y(&unload_states[i]) > y(&unload_states[best]) { i } else { best });
    unload_states.drain(..top);
    let top_level = y(&unload_states[0]);
    unload_states.reverse();
    let n = unload_states.len();
    let unloading = walk(driver, &unload_states, unload_states[n - 1], true, n as isize - 2, -1);
    let (end, end_at_edge) = match unloading.stopped {
        Some(e) => (e, false),
        None => (unloading.path[unloading.path.len() - 1], true),
    };
    // Reloading: the reloading leg, then the loading leg above its last approach.
    let mut reload_states: Vec<PathNode> = Vec::new();
    for s in cycle.reloading.iter().filter(|s| s.abar > 0.0) {
        reload_states.push(node(s)?);
    }
    let leg_len = reload_states.len();
    count_in_range(leg_len, "the reloading leg's states in contact (the cycle needs 1)", 1, usize::MAX)?;
    let last_approach = cycle.reloading.last().map_or(f64::NEG_INFINITY, |s| s.approach);
    for s in cycle.loading.iter().filter(|s| s.abar > 0.0 && s.approach > last_approach + 0.5 * cycle.step) {
        reload_states.push(node(s)?);
    }
    let i0 = (0..leg_len).min_by(|&i, &j| y(&reload_states[i]).total_cmp(&y(&reload_states[j]))).unwrap_or(0);
    let reloading = walk(driver, &reload_states, reload_states[i0], true, i0 as isize + 1, 1);
    // It closes where it reaches the level the cycle turned at (a stop at a
    // maximum there is the top itself); the loading leg beyond is cut off.
    let closes_at = top_level - 1e-9 * top_level.abs().max(1.0);
    let reloading_truncated = reloading.stopped.is_some_and(|p| y(&p) < closes_at);
    let (unloading, mut reloading) = (unloading.path, reloading.path);
    if let Some(k) = reloading.iter().position(|p| y(p) >= closes_at).filter(|&k| k > 0) {
        let last = interpolate(driver, reloading[k - 1], reloading[k], top_level);
        reloading.truncate(k);
        reloading.push(last);
    }
    let start_gap = (reloading[0].approach - end.approach).abs();
    // oint Lbar dDelta: unloading, then reloading, closed back to the top.
    let polygon: Vec<&PathNode> = unloading.iter().chain(&reloading).chain(unloading.first()).collect();
    let work = polygon.windows(2).map(|w| 0.5 * (w[0].load + w[1].load) * (w[1].approach - w[0].approach)).sum();
    let cavitated = unloading.iter().chain(&reloading).filter(|p| !p.valid).count();
    Ok(LegCycle {
        control: driver.control,
        datum: driver.ln_datum.exp(),
        cavitated_fraction: cavitated as f64 / (unloading.len() + reloading.len()) as f64,
        unloading,
        end,
        end_at_edge,
        reloading,
        reloading_truncated,
        start_gap,
        work,
    })
}

/// [`closed_cycle_along_legs`] under load control and under displacement
/// control at `displacement_datum` (model convention, as
/// [`cycle_dissipation`]): `(load control, displacement control)`.
pub fn cycle_dissipation_along_legs(cycle: &Cycle, solver_datum: f64, displacement_datum: f64) -> Result<(LegCycle, LegCycle)> {
    let mut d = closed_cycle_along_legs(cycle, solver_datum, Driver::displacement(displacement_datum)?)?;
    d.datum = displacement_datum;
    Ok((closed_cycle_along_legs(cycle, solver_datum, Driver::load())?, d))
}
