//! The error of the model's multi-step computations: a profile
//! ([`crate::contact::state_profile`]), a run of curves
//! ([`crate::contact::summary::load_area_curves`]) and a table of limits
//! ([`crate::contact::limits`]). It is the library's [`Error`] and where it
//! arose ([`At`]), as fields, so that a front end words the context its own
//! way; [`fmt::Display`] gives a plain wording.

use std::fmt;

use crate::error::Error;

/// Where in a computation an error arose.
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub enum At {
    /// The arguments themselves (a contact size out of range, a grid size, `xmax`,
    /// the parameters of a run).
    Input,
    /// Solving (strip ratio) or checking (validity) the state at `abar`.
    State {
        /// The contact half-width.
        abar: f64,
    },
    /// The certified strip ratio at `abar`.
    CertifiedStripRatio {
        /// The contact half-width.
        abar: f64,
    },
    /// One profile sample at `xbar`.
    Sample {
        /// The position.
        xbar: f64,
    },
    /// The load-area curve at `lambda`.
    Curve {
        /// The Maugis parameter.
        lambda: f64,
    },
    /// The limits at `abar`.
    Limits {
        /// The contact half-width.
        abar: f64,
    },
}

impl At {
    /// `error`, arisen here.
    pub fn wrap(self, error: Error) -> LocatedError {
        LocatedError { at: self, error }
    }
}

/// A library [`Error`] and where it arose.
#[derive(Debug, Clone, PartialEq)]
pub struct LocatedError {
    /// Where.
    pub at: At,
    /// The library's error.
    pub error: Error,
}

impl fmt::Display for LocatedError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let e = &self.error;
        match self.at {
            At::Input => write!(f, "{e}"),
            At::State { abar } => write!(f, "abar = {abar}: {e}"),
            At::CertifiedStripRatio { abar } => write!(f, "abar = {abar}: certified m: {e}"),
            At::Sample { xbar } => write!(f, "at xbar = {xbar}: {e}"),
            At::Curve { lambda } => write!(f, "lambda = {lambda}: {e}"),
            At::Limits { abar } => write!(f, "limits at abar = {abar}: {e}"),
        }
    }
}

impl std::error::Error for LocatedError {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        Some(&self.error)
    }
}
