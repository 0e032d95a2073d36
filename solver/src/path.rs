//! Displacement-controlled continuation: loading, then unloading, warm-started
//! state to state, and the comparison with the semi-analytical model.
//!
//! # Stepping
//!
//! The approach starts where the profile's lowest point is `delta_c` away
//! from the surface (no interaction) and grows in equal steps
//! `dDelta = (Delta_H(amax) - Delta_0) / (steps/2)`, `Delta_H` the Hertz
//! approach at `amax` ([`hertz_approach`]), until the outermost contact
//! half-width reaches `amax`. Unloading goes back down in the same steps until
//! the contact and the Dugdale zone are gone. Each state starts from the
//! previous one, so the path follows a branch as a stiff testing machine would:
//! snap-in and pull-off appear as jumps between neighbouring states.
//!
//! A third leg, **reloading**, starts again from the smallest contact the
//! unloading leg held (its warm start, [`crate::contact::WarmStart`]) and
//! raises the approach on the same lattice of approaches until a state is the
//! loading leg's state at that approach, or the contact reaches `amax`. It
//! visits what the loading leg jumped over at snap-in, where the closed cycle of
//! [`crate::dissipation`] reloads from the end of unloading.
//!
//! # Load control
//!
//! [`load_controlled`] reads the path of a soft machine (prescribed load) off a
//! leg of the displacement-controlled cycle: the states with
//! `dLbar/dDelta > 0`, the jumps between them and the pull-off load.
//!
//! # Work of the stiff-machine cycle
//!
//! [`Cycle::stiff_work`] is the work of the displacement-controlled cycle as
//! simulated, `oint Lbar dDelta` (trapezoidal rule over both legs), from out of
//! contact back to out of contact. It is datum-free: the datum shifts `Delta` by
//! a multiple of `Lbar`, which integrates to zero around a closed loop. It is
//! the work lost in the jumps of a stiff machine over the first cycle (snap-in
//! and the separation past pull-off included), not the dissipation W of the
//! model's closed in-contact cycle: that is [`crate::dissipation`].

use maugis::contact::curve::state as model_state;
use maugis::contact::model::{ContactSize, Params};

use crate::contact::{ContactSolver, State};
use crate::error::{count_in_range, finite, in_range, Interval, Result, SolverError};

/// Exact Hertz approach at half-width `a`, relative to datum `datum`:
/// `(a^2/2) (ln(2 datum/a) + 1/2)` (the smooth non-adhesive cylinder).
pub fn hertz_approach(a: f64, datum: f64) -> f64 {
    0.5 * a * a * ((2.0 * datum / a).ln() + 0.5)
}

/// Tunables of a cycle.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CycleOptions {
    /// Loading stops once the contact half-width reaches `amax`.
    pub amax: f64,
    /// Approach steps per leg.
    pub steps_per_leg: usize,
}

/// A loading-unloading cycle.
#[derive(Debug, Clone, PartialEq)]
pub struct Cycle {
    /// States in loading order.
    pub loading: Vec<State>,
    /// States in unloading order.
    pub unloading: Vec<State>,
    /// The reloading leg (see [`cycle`]): from the smallest contact the
    /// unloading leg held, the approach rises again in the same steps until a
    /// state is the loading leg's state at the same approach (the rest would
    /// repeat loading) or the contact reaches `amax`. Empty when the unloading
    /// leg held no contact.
    pub reloading: Vec<State>,
    /// Approach step.
    pub step: f64,
    /// `oint Lbar dDelta` over the simulated stiff-machine cycle, from out of
    /// contact back to out of contact (see the module docs); not the model's W,
    /// which [`crate::dissipation`] measures.
    pub stiff_work: f64,
}

/// Most steps a leg may take, as a multiple of `steps_per_leg` (the Hertz
/// estimate of the approach range can be short with strong adhesion or waves).
const LEG_STEP_FACTOR: usize = 6;

/// Runs a loading-unloading cycle. `progress(done, estimated_total)` is called
/// after every state.
pub fn cycle(solver: &mut ContactSolver, opts: CycleOptions, progress: &mut dyn FnMut(usize, usize)) -> Result<Cycle> {
    finite(opts.amax, "amax")?;
    let grid = solver.grid();
    // amax < 0.9 X, X the domain half-width
    let open = Interval { lo: 0.0, hi: 0.9 * grid.half_width(), lo_closed: false, hi_closed: false };
    in_range(opts.amax, "amax (below 0.9 times the domain half-width)", open)?;
    count_in_range(opts.steps_per_leg, "steps per leg", 2, 1_000_000)?;
    let hmin = solver.profile_min();
    // Just out of range (the zone rule compares the gap with delta_c strictly).
    let start = hmin - solver.adhesion().start_distance() * (1.0 + 1e-9);
    let step = (hmin + hertz_approach(opts.amax, solver.datum()) - start) / opts.steps_per_leg as f64;
    let total = 2 * opts.steps_per_leg;
    solver.reset();
    let mut loading = Vec::new();
    let mut k = 0;
    loop {
        let s = checked(solver, start + k as f64 * step, grid.cells())?;
        let done = s.abar >= opts.amax;
        loading.push(s);
        k += 1;
        progress(k, total.max(k + 1));
        if done {
            break;
        }
        if k > LEG_STEP_FACTOR * opts.steps_per_leg {
            let reached = loading.iter().map(|s| s.abar).fold(0.0, f64::max);
            if loading.iter().all(|s| s.contact.is_empty()) {
                return Err(SolverError::NeverTouches);
            }
            return Err(SolverError::AmaxNotReached { reached, amax: opts.amax, steps: k });
        }
    }
    let mut unloading = Vec::new();
    let top = loading.len() - 1;
    // The warm start of the last unloading state in contact, and its index on
    // the approach lattice `start + m step`.
    let mut held: Option<(i64, crate::contact::WarmStart)> = None;
    for j in 1.. {
        let s = checked(solver, start + (top as f64 - j as f64) * step, grid.cells())?;
        let done = s.contact.is_empty() && s.zone.is_empty();
        if s.abar > 0.0 {
            held = Some((top as i64 - j as i64, solver.warm_start()));
        }
        unloading.push(s);
        progress(k + j, total.max(k + j + 1));
        if done || j > LEG_STEP_FACTOR * opts.steps_per_leg {
            break;
        }
    }
    // Reloading from the smallest contact held: the stiff machine's own
    // stable branch back up. It visits the stretches of small contact that the
    // loading leg jumped over at snap-in (the library's closed cycle reloads
    // from the end of unloading, so its turning points can lie there); once it
    // meets the loading leg's state at the same approach it would repeat it.
    let mut reloading = Vec::new();
    if let Some((m0, warm)) = held {
        solver.resume(&warm);
        for m in m0 + 1.. {
            let s = checked(solver, start + m as f64 * step, grid.cells())?;
            let rejoined = usize::try_from(m).ok().and_then(|m| loading.get(m)).is_some_and(|l| same_state(l, &s));
            let done = rejoined || s.abar >= opts.amax || m > (top + LEG_STEP_FACTOR * opts.steps_per_leg) as i64;
            reloading.push(s);
            progress(k + unloading.len() + reloading.len(), total.max(k + unloading.len() + reloading.len() + 1));
            if done {
                break;
            }
        }
    }
    let work = |states: &[State]| -> f64 {
        states.windows(2).map(|w| 0.5 * (w[0].load + w[1].load) * (w[1].approach - w[0].approach)).sum()
    };
    // Close the loop: unloading starts at the last loading state.
    let mut back = vec![loading[top].clone()];
    back.extend(unloading.iter().cloned());
    let mut stiff_work = work(&loading) + work(&back);
    // Both legs end without load; if unloading stopped below the start, the
    // unloaded stretch carries no load and adds nothing.
    if !stiff_work.is_finite() {
        stiff_work = f64::NAN;
    }
    Ok(Cycle { loading, unloading, reloading, step, stiff_work })
}

/// Relative difference in `abar` and in the load within which two states
/// solved at the same approach are the same equilibrium (both are converged to
/// `tol = 1e-9` and the zone ends to `1e-8 delta_c`).
const SAME_STATE: f64 = 1e-6;

/// Whether `a` and `b` (solved at the same approach) are the same equilibrium.
fn same_state(a: &State, b: &State) -> bool {
    a.contact_intervals() == b.contact_intervals()
        && (a.abar - b.abar).abs() <= SAME_STATE * a.abar.abs().max(1.0)
        && (a.load - b.load).abs() <= SAME_STATE * a.load.abs().max(1.0)
}

/// Direction of the load under load control.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum LoadDirection {
    /// Loading: the load increases.
    Increasing,
    /// Unloading: the load decreases.
    Decreasing,
}

/// The load-controlled path read off one leg of a displacement-controlled
/// cycle (a soft machine: the load is prescribed).
///
/// A state is stable under load control only where `dLbar/dDelta > 0`. With
/// the load increasing, the machine follows the leg while the load rises; where
/// the displacement-controlled load falls back (an unstable stretch under load
/// control: snap-in at zero load, or the stretch before a cavitation jump) it
/// jumps, at the load reached, to the first later state whose load is at least
/// as high. Unloading is the mirror image with the load decreasing, and ends in
/// pull-off at the most tensile load of the leg, where the contact separates
/// under load control.
///
/// The states are those of the stiff-machine path: where that path itself
/// jumped past the state a soft machine lands on, the load-controlled path
/// resumes at the first visited state beyond the jump load (within one
/// displacement step of the landing).
#[derive(Debug, Clone, PartialEq)]
pub struct LoadControlled {
    /// Indices (into the leg) of the states on the load-controlled path, in order.
    pub states: Vec<usize>,
    /// Jumps as `(from, to)` index pairs: consecutive path states with skipped
    /// (load-control unstable) states between them.
    pub jumps: Vec<(usize, usize)>,
    /// Unloading: the pull-off load (the most tensile load of the leg) and the
    /// index of its state; `None` when loading or when no state carries tension.
    pub pull_off: Option<(usize, f64)>,
}

/// The load-controlled path of one leg ([`LoadControlled`]): `Increasing`
/// for the loading leg, `Decreasing` for the unloading leg (which should start
/// at the last loading state, as [`Cycle::unloading`] does after it).
pub fn load_controlled(leg: &[State], direction: LoadDirection) -> LoadControlled {
    let mut states = Vec::new();
    let mut jumps = Vec::new();
    let mut record: Option<f64> = None;
    for (i, s) in leg.iter().enumerate() {
        let beyond = match (record, direction) {
            (None, _) => true,
            (Some(r), LoadDirection::Increasing) => s.load > r,
            (Some(r), LoadDirection::Decreasing) => s.load < r,
        };
        if beyond {
            if let Some(&last) = states.last() {
                if i > last + 1 {
                    jumps.push((last, i));
                }
            }
            states.push(i);
            record = Some(s.load);
        }
    }
    let pull_off = match direction {
        LoadDirection::Increasing => None,
        LoadDirection::Decreasing => states.last().map(|&i| (i, leg[i].load)).filter(|&(_, l)| l < 0.0),
    };
    if let Some((i, _)) = pull_off {
        // Under load control the contact separates at the most tensile load:
        // the states after it on the leg are not reached.
        states.retain(|&j| j <= i);
        jumps.retain(|&(a, _)| a < i);
    }
    LoadControlled { states, jumps, pull_off }
}

/// One solve, then the check that nothing reached the end of the domain.
fn checked(solver: &mut ContactSolver, approach: f64, cells: usize) -> Result<State> {
    let s = solver.solve(approach)?;
    let g = solver.grid();
    let touches_end = |v: &[(f64, f64)]| {
        v.first().is_some_and(|&(l, _)| l <= -g.half_width() + 0.5 * g.dx())
            || v.last().is_some_and(|&(_, r)| r >= g.half_width() - 0.5 * g.dx())
    };
    if touches_end(&s.zone) || touches_end(&s.contact) || cells == 0 {
        return Err(SolverError::DomainTooSmall { half_width: g.half_width() });
    }
    Ok(s)
}

/// The simulated approach on the model's datum: the library's
/// `ContactSize::approach_at` measures `Delta` from a datum at infinity with the
/// logarithmic term removed, `Delta_model = lim [u(x) - (2 Lbar/pi) ln x]`; the
/// solver's datum is at distance `datum`, so
/// `Delta_model = Delta - (2/pi) Lbar ln(datum)` (exact for the log kernel; the
/// Hertz test checks it).
pub fn approach_on_model_datum(approach: f64, load: f64, datum: f64) -> f64 {
    approach - 2.0 / std::f64::consts::PI * load * datum.ln()
}

/// A simulated state next to the semi-analytical model at the same `abar`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ModelComparison {
    /// Simulated outermost half-width.
    pub abar: f64,
    /// Simulated load.
    pub load: f64,
    /// Simulated approach on the model's datum ([`approach_on_model_datum`]).
    pub approach: f64,
    /// Semi-analytical load at `abar` (Eq. 14).
    pub model_load: f64,
    /// Semi-analytical approach at `abar` (`ContactSize::approach_at`).
    pub model_approach: f64,
    /// Whether the semi-analytical state is valid (no interpenetration, no cavitation).
    pub model_valid: bool,
    /// Simulated contact intervals.
    pub contact_intervals: usize,
}

/// The semi-analytical load, approach and validity at each simulated contact
/// state (`abar > 0`); `datum` is the solver's ([`ContactSolver::datum`]).
/// States the model cannot solve are skipped.
pub fn compare_with_model(params: Params, datum: f64, states: &[State]) -> Vec<ModelComparison> {
    states
        .iter()
        .filter(|s| s.abar > 0.0)
        .filter_map(|s| {
            let m = model_state(params, s.abar).ok()?;
            Some(ModelComparison {
                abar: s.abar,
                load: s.load,
                approach: approach_on_model_datum(s.approach, s.load, datum),
                model_load: m.load,
                model_approach: m.approach,
                model_valid: m.validity.valid,
                contact_intervals: s.contact_intervals(),
            })
        })
        .collect()
}

/// A domain half-width that holds the contact and the Dugdale zone up to
/// `amax`: 1.25 times the largest strip end `c = m abar` of the model on 64
/// contact sizes in `(0, amax]`, and at least the zone at first touch,
/// `sqrt(2 delta_c)`, and `1.25 amax`.
pub fn suggested_half_width(params: Params, amax: f64) -> Result<f64> {
    finite(amax, "amax")?;
    in_range(amax, "amax", Interval::left_open(0.0, 1e4))?;
    let mut c_max: f64 = amax.max((2.0 / params.lambda()).sqrt());
    for i in 1..=64 {
        let abar = amax * i as f64 / 64.0;
        if let Ok(m) = ContactSize::new(params, abar).and_then(|cs| cs.solve_m()) {
            c_max = c_max.max(m * abar);
        }
    }
    Ok(1.25 * c_max)
}
