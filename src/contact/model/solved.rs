//! A contact size solved whole, in one call: the strip end, the load and approach
//! computed from it once, and (for [`solve_state`]) the validity checks. This is what
//! the load-area response reads ([`crate::contact::curve_state`] assembles its
//! `CurvePoint` from a [`SolvedState`], [`crate::contact::paths`] refines its extrema
//! with [`solve_load_and_approach`]): the model computes, the callers assemble, and no
//! data goes back into the model between the steps.

use super::params::Params;
use super::state::ContactSize;
use super::strip::StripEnd;
use super::validity::Validity;
use crate::error::{Error, Result};

/// One solved state: the contact size, its strip end, the load (Eq. 14) and the
/// approach ([`ContactSize::approach_at`]), both finite, and the validity diagnostics.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SolvedState {
    /// Contact half-width.
    pub abar: f64,
    /// The strip end (`m - 1` to full relative accuracy).
    pub strip: StripEnd,
    /// Load, Eq. 14.
    pub load: f64,
    /// Approach from a datum at infinity.
    pub approach: f64,
    /// Validity diagnostics.
    pub validity: Validity,
}

/// `value`, or [`Error::NotRepresentable`] when it is not finite.
fn representable(quantity: &'static str, abar: f64, value: f64) -> Result<f64> {
    if value.is_finite() {
        Ok(value)
    } else {
        Err(Error::NotRepresentable { quantity, abar })
    }
}

/// Solves and checks the state at `abar`: the first root of the strip equation, the
/// load and the approach ([`Error::NotRepresentable`] when one is not a finite f64,
/// the load checked first), then the validity.
pub fn solve_state(params: Params, abar: f64) -> Result<SolvedState> {
    let cs = ContactSize::new(params, abar)?;
    let strip = cs.solve_strip()?;
    let (load, approach) = cs.load_and_approach_at(strip);
    let load = representable("load", abar, load)?;
    let approach = representable("approach", abar, approach)?;
    let validity = cs.validity_at(strip)?;
    Ok(SolvedState { abar, strip, load, approach, validity })
}

/// The load at `abar` (solving for the strip end; [`Error::NotRepresentable`] when it
/// is not a finite f64).
pub fn solve_load(params: Params, abar: f64) -> Result<f64> {
    let cs = ContactSize::new(params, abar)?;
    representable("load", abar, cs.load_at(cs.solve_strip()?))
}

/// The load and the approach at `abar` (solving for the strip end), as computed.
pub fn solve_load_and_approach(params: Params, abar: f64) -> Result<(f64, f64)> {
    let cs = ContactSize::new(params, abar)?;
    Ok(cs.load_and_approach_at(cs.solve_strip()?))
}

/// The validity diagnostics of the state at `abar` (solving for the strip end).
pub fn solve_validity(params: Params, abar: f64) -> Result<Validity> {
    let cs = ContactSize::new(params, abar)?;
    cs.validity_at(cs.solve_strip()?)
}
