//! The load-area response `Lbar(abar)`, its approach `Delta-bar(abar)` and its
//! stability under load and displacement control.
//!
//! * [`load_area_curve`] solves the model on a grid of contact sizes (default
//!   `abar in (0, 6]`, 600 points), with the approach and the validity flags of
//!   every state.
//! * Turning points of the load (`dLbar/dabar = 0`) are located on the grid and
//!   refined with Brent's method on the derivative (central differences of the
//!   solved load, step `1e-6`), to about `1e-9` in `abar`.
//! * The quasi-static paths, the jumps they meet, the hysteresis loops and the
//!   dissipation are built by [`crate::contact::paths`], under load control
//!   ([`Curve::load_control`]) and under displacement control
//!   ([`Curve::displacement_control`]). [`Curve::jumps`] and [`Curve::loops`]
//!   are those of load control: only the jumps a path meets.
//! * The pull-off state is the end of the unloading path under load control,
//!   refined (golden section on the solved load), with the validity of the
//!   refined state itself; [`Curve::valid_pull_off`] is the most tensile valid
//!   state unloading can reach: on the path, or on the curve below its end.

#[cfg(feature = "parallel")]
use rayon::prelude::*;

pub use crate::contact::curve_state::{load_at, state, CurvePoint};
use crate::contact::model::{solve_validity, Params, Validity};
use crate::roots::brent;
pub use crate::contact::paths::{HysteresisLoop, Jump, JumpDirection};
use crate::contact::paths::{control_paths, ControlPaths, Driver, PathNode};
use crate::error::{Error, Interval, Result};

/// Maximum or minimum of the load.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
pub enum TurningKind {
    /// Local maximum of `Lbar(abar)`.
    Max,
    /// Local minimum.
    Min,
}

/// A turning point `dLbar/dabar = 0`.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct TurningPoint {
    /// Where.
    pub abar: f64,
    /// The load there.
    pub load: f64,
    /// Max or min.
    pub kind: TurningKind,
}

/// The pull-off state: the end of the unloading path under load control.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct PullOff {
    /// Contact half-width.
    pub abar: f64,
    /// The (most tensile) load.
    pub load: f64,
    /// The approach there.
    pub approach: f64,
    /// Validity of this state (computed there, not read off the grid).
    pub validity: Validity,
    /// The unloading path reached the smallest grid contact without meeting a
    /// minimum: the load keeps falling towards smaller contacts.
    pub at_grid_edge: bool,
}

/// A whole load-area response.
#[derive(Debug, Clone)]
pub struct Curve {
    /// The parameters.
    pub params: Params,
    /// The grid states.
    pub points: Vec<CurvePoint>,
    /// Refined turning points of the load, by increasing `abar`.
    pub turning_points: Vec<TurningPoint>,
    /// Jumps under load control (only those the paths meet).
    pub jumps: Vec<Jump>,
    /// The pull-off state.
    pub pull_off: Option<PullOff>,
    /// The most tensile valid state unloading under load control can reach:
    /// a state the path visits, or a grid state below its end (the
    /// small-contact branch past a cavitating stretch).
    pub valid_pull_off: Option<PathNode>,
    /// Hysteresis loops under load control, each counted once.
    pub loops: Vec<HysteresisLoop>,
    /// Paths, jumps, loops and dissipation under load control.
    pub load_control: ControlPaths,
    /// The same under displacement control.
    pub displacement_control: ControlPaths,
}

/// Grid options.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct CurveOptions {
    /// Largest contact size.
    pub amax: f64,
    /// Number of grid points, `abar_i = amax i / points`, `i = 1..=points`.
    pub points: usize,
    /// Where the machine grips the body under displacement control (units of
    /// `l_h`, see [`crate::contact::paths::Driver`]); [`DEFAULT_DATUM`] by default.
    pub datum: f64,
}

/// Default datum of displacement control: 100 `l_h` (far outside the paper's
/// contacts, `abar <= 6`).
pub const DEFAULT_DATUM: f64 = 100.0;

impl Default for CurveOptions {
    fn default() -> Self {
        CurveOptions { amax: 6.0, points: 600, datum: DEFAULT_DATUM }
    }
}

/// `dLbar/dabar` by a central difference of solved loads.
fn load_slope(params: Params, abar: f64) -> Result<f64> {
    let h = 1e-6 * abar.max(1.0);
    Ok((load_at(params, abar + h)? - load_at(params, abar - h)?) / (2.0 * h))
}

/// Solves the model on the grid and analyses stability.
pub fn load_area_curve(params: Params, opts: CurveOptions) -> Result<Curve> {
    Interval::above(0.0).check("amax", opts.amax)?;
    if !opts.amax.is_finite() {
        return Err(Error::NonFinite { what: "amax" });
    }
    if opts.points < 2 {
        let value = i64::try_from(opts.points).unwrap_or(i64::MAX);
        return Err(Error::IntegerOutOfRange { arg: "points", value, min: 2, max: i64::MAX });
    }
    let n = opts.points;
    #[cfg(feature = "parallel")]
    let grid = (1..=n).into_par_iter();
    #[cfg(not(feature = "parallel"))]
    let grid = 1..=n;
    let points: Vec<CurvePoint> = grid
        .map(|i| state(params, opts.amax * i as f64 / n as f64))
        .collect::<Result<Vec<_>>>()?;
    let turning_points = turning_points(params, &points)?;
    let load_control = control_paths(params, &points, Driver::load())?;
    let displacement_control = control_paths(params, &points, Driver::displacement(opts.datum)?)?;
    let pull_off = match load_control.end {
        Some(end) => {
            let validity = solve_validity(params, end.state.abar)?;
            Some(PullOff {
                abar: end.state.abar,
                load: end.state.load,
                approach: end.state.approach,
                validity,
                at_grid_edge: end.at_grid_edge,
            })
        }
        None => None,
    };
    // The most tensile valid state unloading can reach: the valid states the
    // path visits, and the valid states below its end (a path through
    // cavitating states is not described by the model, but its small-contact
    // branch is: a boundary-element solution with cavitation reaches it,
    // docs/model.md "Pull-off").
    let end_abar = load_control.end.map_or(f64::NEG_INFINITY, |e| e.state.abar);
    let valid_pull_off = load_control
        .unloading
        .iter()
        .copied()
        .chain(points.iter().filter(|p| p.abar <= end_abar).map(|p| PathNode { abar: p.abar, load: p.load, approach: p.approach, valid: p.validity.valid }))
        .filter(|n| n.valid)
        .min_by(|p, q| p.load.total_cmp(&q.load));
    Ok(Curve {
        params,
        points,
        turning_points,
        jumps: load_control.jumps.clone(),
        pull_off,
        valid_pull_off,
        loops: load_control.loops.clone(),
        load_control,
        displacement_control,
    })
}

/// Turning points from the grid, refined.
fn turning_points(params: Params, pts: &[CurvePoint]) -> Result<Vec<TurningPoint>> {
    let mut out = Vec::new();
    for i in 1..pts.len().saturating_sub(1) {
        let (l0, l1, l2) = (pts[i - 1].load, pts[i].load, pts[i + 1].load);
        let kind = if l1 > l0 && l1 >= l2 {
            TurningKind::Max
        } else if l1 < l0 && l1 <= l2 {
            TurningKind::Min
        } else {
            continue;
        };
        let (lo, hi) = (pts[i - 1].abar, pts[i + 1].abar);
        let refined = (|| -> Result<f64> {
            let (slo, shi) = (load_slope(params, lo)?, load_slope(params, hi)?);
            if slo * shi > 0.0 {
                return Ok(pts[i].abar);
            }
            let f = |a: f64| load_slope(params, a).unwrap_or(f64::NAN);
            // brent wants f(lo) < 0 <= f(hi): orient the bracket
            if slo < 0.0 {
                brent(f, lo, hi, slo, shi)
            } else {
                brent(|a| -f(a), lo, hi, -slo, -shi)
            }
        })()
        .unwrap_or(pts[i].abar);
        let abar = refined;
        out.push(TurningPoint { abar, load: load_at(params, abar)?, kind });
    }
    Ok(out)
}

