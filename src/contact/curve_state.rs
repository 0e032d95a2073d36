//! One solved state of the load-area response: the contact size `abar`, the
//! strip ratio `m = c/a`, the load (Eq. 14), the approach and the validity
//! diagnostics, each from one solve of the strip equation
//! ([`ContactSize::solve_strip`]).
//!
//! Both the grid solver ([`crate::contact::curve`]) and the path builder
//! ([`crate::contact::paths`]) read these states; they live here, apart from
//! both, so neither file imports the other's types (issue 26: no file cycles).
//!
//! No numerics of its own: a load or approach that is not a finite f64 is the
//! typed error [`Error::NotRepresentable`]; every other error is the solver's.
//! Re-exported from [`crate::contact::curve`], the public path.

use crate::contact::model::{ContactSize, Params, Validity};
use crate::error::{Error, Result};

/// One solved state.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct CurvePoint {
    /// Contact half-width.
    pub abar: f64,
    /// Strip ratio `c/a` (rounded; see `m_minus_1`).
    pub m: f64,
    /// `m - 1` to full relative accuracy.
    pub m_minus_1: f64,
    /// Load, Eq. 14.
    pub load: f64,
    /// Approach from a datum at infinity ([`ContactSize::approach_at`]).
    pub approach: f64,
    /// Validity diagnostics.
    pub validity: Validity,
}

/// Solves and checks one state.
pub fn state(params: Params, abar: f64) -> Result<CurvePoint> {
    let cs = ContactSize::new(params, abar)?;
    let strip = cs.solve_strip()?;
    Ok(CurvePoint {
        abar,
        m: strip.m(),
        m_minus_1: strip.m_minus_1(),
        load: representable("load", abar, cs.load_at(strip))?,
        approach: representable("approach", abar, cs.approach_at(strip))?,
        validity: cs.validity_at(strip)?,
    })
}

/// `value`, or [`Error::NotRepresentable`] when it is not finite.
fn representable(quantity: &'static str, abar: f64, value: f64) -> Result<f64> {
    if value.is_finite() {
        Ok(value)
    } else {
        Err(Error::NotRepresentable { quantity, abar })
    }
}

/// The load at `abar` (solving for `m`).
pub fn load_at(params: Params, abar: f64) -> Result<f64> {
    let cs = ContactSize::new(params, abar)?;
    representable("load", abar, cs.load_at(cs.solve_strip()?))
}

