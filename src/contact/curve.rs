//! The load-area response `Lbar(abar)` and its stability under load control.
//!
//! * [`load_area_curve`] solves the model on a grid of contact sizes (default
//!   `abar in (0, 6]`, 600 points), with the validity flags of every state.
//! * Turning points (`dLbar/dabar = 0`) are located on the grid and refined with
//!   Brent's method on the derivative (central differences of the solved load,
//!   step `1e-6`), to about `1e-9` in `abar`.
//! * Jumps under load control: **loading** goes from each local maximum to the
//!   next larger `abar` with the same load; **unloading** goes from each local
//!   minimum to the next smaller `abar` with the same load, or out of contact
//!   (pull-off) when there is none. Jump targets are refined with Brent's method
//!   on `Lbar(abar) - L_turn`.
//! * The pull-off point is the first local minimum met when unloading from the
//!   largest contact that has no unloading target; if the curve has no such
//!   minimum (M-DMT-like monotone curves), it is the smallest computed contact.

#[cfg(feature = "parallel")]
use rayon::prelude::*;

use crate::contact::model::{brent, ContactSize, Params, Validity};
use crate::error::{Error, Result};

/// One solved state.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CurvePoint {
    /// Contact half-width.
    pub abar: f64,
    /// Strip ratio `c/a`.
    pub m: f64,
    /// Load, Eq. 14.
    pub load: f64,
    /// Validity diagnostics.
    pub validity: Validity,
}

/// Maximum or minimum of the load.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum TurningKind {
    /// Local maximum of `Lbar(abar)`.
    Max,
    /// Local minimum.
    Min,
}

/// A turning point `dLbar/dabar = 0`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TurningPoint {
    /// Where.
    pub abar: f64,
    /// The load there.
    pub load: f64,
    /// Max or min.
    pub kind: TurningKind,
}

/// Direction of a jump.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum JumpDirection {
    /// Increasing load: from a maximum to a larger contact.
    Loading,
    /// Decreasing load: from a minimum to a smaller contact.
    Unloading,
}

/// A jump at constant load.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Jump {
    /// Direction.
    pub direction: JumpDirection,
    /// From this contact size (a turning point).
    pub from_abar: f64,
    /// To this one (on the curve, same load).
    pub to_abar: f64,
    /// The load.
    pub load: f64,
}

/// A hysteresis loop under load control: a loading jump (from a load maximum
/// to a larger contact) and the unloading jump that returns past it (from a
/// load minimum to a smaller contact). Following the loop, the contact climbs
/// the curve from `unloading.to_abar` to `loading.from_abar`, jumps out to
/// `loading.to_abar`, descends the curve back to `unloading.from_abar` and jumps
/// in to `unloading.to_abar`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct HysteresisLoop {
    /// The loading jump.
    pub loading: Jump,
    /// The unloading jump.
    pub unloading: Jump,
    /// Area enclosed in the `(abar, Lbar)` plane (shoelace formula over the
    /// grid states on both stable branches and the two jumps). A measure of the
    /// loop's size, not the dissipated energy (that needs the approach `delta`).
    pub area: f64,
}

/// A whole load-area response.
#[derive(Debug, Clone)]
pub struct Curve {
    /// The parameters.
    pub params: Params,
    /// The grid states.
    pub points: Vec<CurvePoint>,
    /// Refined turning points, by increasing `abar`.
    pub turning_points: Vec<TurningPoint>,
    /// Jumps under load control.
    pub jumps: Vec<Jump>,
    /// The pull-off state `(abar, load)`.
    pub pull_off: Option<(f64, f64)>,
    /// Hysteresis loops formed by pairs of loading and unloading jumps.
    pub loops: Vec<HysteresisLoop>,
}

/// Grid options.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CurveOptions {
    /// Largest contact size.
    pub amax: f64,
    /// Number of grid points, `abar_i = amax i / points`, `i = 1..=points`.
    pub points: usize,
}

impl Default for CurveOptions {
    fn default() -> Self {
        CurveOptions { amax: 6.0, points: 600 }
    }
}

/// Solves and checks one state.
pub fn state(params: Params, abar: f64) -> Result<CurvePoint> {
    let cs = ContactSize::new(params, abar)?;
    let m = cs.solve_m()?;
    Ok(CurvePoint { abar, m, load: cs.load(m), validity: cs.validity(m)? })
}

/// The load at `abar` (solving for `m`).
pub fn load_at(params: Params, abar: f64) -> Result<f64> {
    let cs = ContactSize::new(params, abar)?;
    Ok(cs.load(cs.solve_m()?))
}

/// `dLbar/dabar` by a central difference of solved loads.
fn load_slope(params: Params, abar: f64) -> Result<f64> {
    let h = 1e-6 * abar.max(1.0);
    Ok((load_at(params, abar + h)? - load_at(params, abar - h)?) / (2.0 * h))
}

/// Solves the model on the grid and analyses stability.
pub fn load_area_curve(params: Params, opts: CurveOptions) -> Result<Curve> {
    if !(opts.amax.is_finite() && opts.amax > 0.0) {
        return Err(Error::Domain { what: format!("amax must be > 0 (got {})", opts.amax) });
    }
    if opts.points < 2 {
        return Err(Error::Domain { what: format!("points must be >= 2 (got {})", opts.points) });
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
    let (jumps, pull_off) = jumps(params, &points, &turning_points)?;
    let loops = hysteresis_loops(&points, &jumps);
    Ok(Curve { params, points, turning_points, jumps, pull_off, loops })
}

/// Pairs each unloading jump with the loading jump whose maximum lies inside
/// it and whose target lies beyond it.
fn hysteresis_loops(pts: &[CurvePoint], jumps: &[Jump]) -> Vec<HysteresisLoop> {
    let mut out = Vec::new();
    for u in jumps.iter().filter(|j| j.direction == JumpDirection::Unloading) {
        let partner = jumps.iter().find(|l| {
            l.direction == JumpDirection::Loading
                && l.from_abar > u.to_abar
                && l.from_abar < u.from_abar
                && l.to_abar > u.from_abar
        });
        if let Some(l) = partner {
            // polygon: lower branch u.to -> l.from, jump to l.to, upper branch l.to -> u.from, jump back
            let mut poly: Vec<(f64, f64)> = vec![(u.to_abar, u.load)];
            poly.extend(pts.iter().filter(|p| p.abar > u.to_abar && p.abar < l.from_abar).map(|p| (p.abar, p.load)));
            poly.push((l.from_abar, l.load));
            poly.push((l.to_abar, l.load));
            poly.extend(pts.iter().rev().filter(|p| p.abar < l.to_abar && p.abar > u.from_abar).map(|p| (p.abar, p.load)));
            poly.push((u.from_abar, u.load));
            let twice: f64 = poly
                .iter()
                .zip(poly.iter().cycle().skip(1))
                .map(|(p, q)| p.0 * q.1 - q.0 * p.1)
                .sum();
            out.push(HysteresisLoop { loading: *l, unloading: *u, area: 0.5 * twice.abs() });
        }
    }
    out
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

/// Jumps and pull-off.
fn jumps(params: Params, pts: &[CurvePoint], tps: &[TurningPoint]) -> Result<(Vec<Jump>, Option<(f64, f64)>)> {
    let mut jumps = Vec::new();
    let mut pull_off = None;
    let target = |lo: f64, hi: f64, level: f64| -> Result<f64> {
        let f = |a: f64| load_at(params, a).map(|l| l - level).unwrap_or(f64::NAN);
        let (flo, fhi) = (f(lo), f(hi));
        if flo < 0.0 {
            brent(f, lo, hi, flo, fhi)
        } else {
            brent(|a| -f(a), lo, hi, -flo, -fhi)
        }
    };
    for tp in tps {
        match tp.kind {
            TurningKind::Max => {
                // first grid point beyond the max where the load is back at L_max
                let start = pts.iter().position(|p| p.abar > tp.abar).unwrap_or(pts.len());
                let mut dipped = false;
                for j in start..pts.len() {
                    if pts[j].load < tp.load {
                        dipped = true;
                    } else if dipped {
                        let lo = if j > 0 { pts[j - 1].abar } else { tp.abar };
                        let to = target(lo, pts[j].abar, tp.load)?;
                        jumps.push(Jump { direction: JumpDirection::Loading, from_abar: tp.abar, to_abar: to, load: tp.load });
                        break;
                    }
                }
            }
            TurningKind::Min => {
                let end = pts.iter().rposition(|p| p.abar < tp.abar);
                let mut found = false;
                if let Some(end) = end {
                    let mut rose = false;
                    for j in (0..=end).rev() {
                        if pts[j].load > tp.load {
                            rose = true;
                        } else if rose {
                            let hi = if j + 1 < pts.len() { pts[j + 1].abar } else { tp.abar };
                            let to = target(pts[j].abar, hi, tp.load)?;
                            jumps.push(Jump {
                                direction: JumpDirection::Unloading,
                                from_abar: tp.abar,
                                to_abar: to,
                                load: tp.load,
                            });
                            found = true;
                            break;
                        }
                    }
                }
                if !found {
                    // unloading from the large-contact end meets the rightmost such minimum first
                    pull_off = Some((tp.abar, tp.load));
                }
            }
        }
    }
    if pull_off.is_none() {
        if let Some(p) = pts.first() {
            pull_off = Some((p.abar, p.load));
        }
    }
    Ok((jumps, pull_off))
}
