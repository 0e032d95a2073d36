//! The solver's error type: every public entry point that can fail on user input
//! returns [`Result`]; nothing panics on bad input.

use std::fmt;

/// Everything that can go wrong in `maugis-solver`.
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub enum SolverError {
    /// A parameter is NaN, infinite or out of its domain; the message says what is allowed.
    Domain {
        /// What is wrong and what to change.
        what: String,
    },
    /// The grid size is not a power of two in the supported range.
    Grid {
        /// The requested number of cells.
        cells: usize,
    },
    /// The interaction zone (contact or Dugdale zone) reached the end of the domain:
    /// the free-space solution would be truncated.
    DomainTooSmall {
        /// The domain half-width.
        half_width: f64,
    },
    /// The profile never comes within the interaction range of the surface
    /// over the whole approach range (nothing to simulate).
    NeverTouches,
    /// An iteration (inner CG or outer Dugdale-zone update) hit its cap.
    NoConvergence {
        /// Which iteration.
        what: &'static str,
        /// Iterations done.
        iterations: usize,
        /// Residual reached.
        residual: f64,
    },
    /// An error from the `maugis` library (the semi-analytical model).
    Model(maugis::Error),
}

impl fmt::Display for SolverError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            SolverError::Domain { what } => write!(f, "{what}"),
            SolverError::Grid { cells } => write!(
                f,
                "grid must be a power of two between {} and {} cells (got {cells})",
                crate::grid::MIN_CELLS,
                crate::grid::MAX_CELLS
            ),
            SolverError::DomainTooSmall { half_width } => write!(
                f,
                "the contact or Dugdale zone reached the end of the domain (half-width {half_width}); \
                 enlarge the domain or lower --amax"
            ),
            SolverError::NeverTouches => {
                write!(f, "the profile never comes within the adhesion range of the surface; nothing to simulate")
            }
            SolverError::NoConvergence { what, iterations, residual } => {
                write!(f, "{what} did not converge in {iterations} iterations (residual {residual:e})")
            }
            SolverError::Model(e) => write!(f, "{e}"),
        }
    }
}

impl std::error::Error for SolverError {}

impl From<maugis::Error> for SolverError {
    fn from(e: maugis::Error) -> Self {
        SolverError::Model(e)
    }
}

/// Result with [`SolverError`].
pub type Result<T> = std::result::Result<T, SolverError>;

/// `Ok(x)` if `x` is finite, else a [`SolverError::Domain`] naming it.
pub(crate) fn finite(x: f64, what: &str) -> Result<f64> {
    if x.is_finite() {
        Ok(x)
    } else {
        Err(SolverError::Domain { what: format!("{what} must be a finite number (got {x})") })
    }
}
