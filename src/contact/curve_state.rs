//! One solved state of the load-area response: the contact size `abar`, the
//! strip ratio `m = c/a`, the load (Eq. 14), the approach and the validity
//! diagnostics, each from one solve of the strip equation. The model computes the
//! state in one call ([`solve_state`]); this file only assembles the record the
//! curve, the paths and the outputs read (no call back into the model).
//!
//! Both the grid solver ([`crate::contact::curve`]) and the path builder
//! ([`crate::contact::paths`]) read these states; they live here, apart from
//! both, so neither file imports the other's types (issue 26: no file cycles).
//!
//! No numerics of its own: a load or approach that is not a finite f64 is the
//! model's typed error [`crate::Error::NotRepresentable`].
//! Re-exported from [`crate::contact::curve`], the public path.

use crate::contact::model::{solve_state, SolvedState, Validity};
use crate::error::Result;

pub use crate::contact::model::solve_load as load_at;

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
    /// Approach from a datum at infinity ([`crate::contact::model::ContactSize::approach_at`]).
    pub approach: f64,
    /// Validity diagnostics.
    pub validity: Validity,
}

impl From<SolvedState> for CurvePoint {
    fn from(s: SolvedState) -> CurvePoint {
        CurvePoint { abar: s.abar, m: s.strip.m(), m_minus_1: s.strip.m_minus_1(), load: s.load, approach: s.approach, validity: s.validity }
    }
}

/// Solves and checks one state ([`solve_state`]).
pub fn state(params: crate::contact::model::Params, abar: f64) -> Result<CurvePoint> {
    solve_state(params, abar).map(CurvePoint::from)
}
