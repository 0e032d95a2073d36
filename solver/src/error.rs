//! The solver's error type: every public entry point that can fail on user input
//! returns [`Result`]; nothing panics on bad input.
//!
//! Each variant carries the values it reports (the limits too, as fields), and
//! its message is made from them: this file imports no other module of the
//! solver, and no message names a front end's flag (a library user has none).

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
        /// Fewest cells accepted ([`crate::grid::MIN_CELLS`]).
        min: usize,
        /// Most cells accepted ([`crate::grid::MAX_CELLS`]).
        max: usize,
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
    /// A profile table (`x,h` CSV text, [`crate::profile_file`]) has a bad
    /// line.
    ProfileTable {
        /// The 1-based line of the text.
        line: usize,
        /// What is wrong with it.
        fault: TableFault,
    },
    /// A profile table does not cover the domain `[-half_width, half_width]`.
    ProfileCoverage {
        /// The table's first `x`.
        first: f64,
        /// The table's last `x`.
        last: f64,
        /// The domain half-width it must cover.
        half_width: f64,
    },
    /// An adhesion law's name that the solver does not know
    /// ([`crate::profile::AdhesionLaw::from_name`]).
    UnknownLaw {
        /// The name given.
        name: String,
        /// The names it knows.
        known: Vec<&'static str>,
    },
    /// An error from the `maugis` library (the semi-analytical model).
    Model(maugis::Error),
}

/// What is wrong with a line of a profile table.
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub enum TableFault {
    /// The first line is not the header `x,h`.
    Header {
        /// The line found.
        found: String,
    },
    /// A row does not have two fields.
    Fields {
        /// Fields found.
        found: usize,
    },
    /// A field is not a number.
    Number {
        /// `"x"` or `"h"`.
        column: &'static str,
        /// The field's text.
        text: String,
    },
    /// A field is NaN or infinite.
    NotFinite {
        /// `"x"` or `"h"`.
        column: &'static str,
    },
    /// `x` does not increase strictly.
    NotIncreasing {
        /// This row's `x`.
        x: f64,
        /// The previous row's `x`.
        previous: f64,
    },
    /// The interpolant's slope at this row is not a finite f64: the rows
    /// around it are too close for the rise of `h` between them.
    SlopeNotFinite {
        /// This row's `x`.
        x: f64,
    },
    /// Fewer rows than [`crate::profile_file::MIN_ROWS`] (`line`: the last line read).
    TooFewRows {
        /// Rows found.
        rows: usize,
        /// Fewest rows accepted ([`crate::profile_file::MIN_ROWS`]).
        min: usize,
    },
}

impl fmt::Display for TableFault {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            TableFault::Header { found } => write!(f, "the header must be `x,h` (found `{found}`)"),
            TableFault::Fields { found } => write!(f, "a row must have two fields, x and h (found {found})"),
            TableFault::Number { column, text } => write!(f, "{column} is not a number (`{text}`)"),
            TableFault::NotFinite { column } => write!(f, "{column} must be a finite number"),
            TableFault::NotIncreasing { x, previous } => {
                write!(f, "x must increase strictly from row to row (x = {x} after {previous})")
            }
            TableFault::SlopeNotFinite { x } => {
                write!(f, "the slope at x = {x} is not a finite number: the rows around it are too close for their rise")
            }
            TableFault::TooFewRows { rows, min } => write!(f, "the table needs at least {min} rows (found {rows})"),
        }
    }
}

impl fmt::Display for SolverError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            SolverError::Domain { what } => write!(f, "{what}"),
            SolverError::Grid { cells, min, max } => {
                write!(f, "grid must be a power of two between {min} and {max} cells (got {cells})")
            }
            SolverError::DomainTooSmall { half_width } => write!(
                f,
                "the contact or Dugdale zone reached the end of the domain (half-width {half_width}); \
                 enlarge the domain or lower the largest contact half-width (amax)"
            ),
            SolverError::NeverTouches => {
                write!(f, "the profile never comes within the adhesion range of the surface; nothing to simulate")
            }
            SolverError::NoConvergence { what, iterations, residual } => {
                write!(f, "{what} did not converge in {iterations} iterations (residual {residual:e})")
            }
            SolverError::ProfileTable { line, fault } => write!(f, "profile table, line {line}: {fault}"),
            SolverError::ProfileCoverage { first, last, half_width } => write!(
                f,
                "the profile table covers x in [{first}, {last}], but the domain is [-{half_width}, {half_width}]: \
                 extend the table or narrow the domain"
            ),
            SolverError::UnknownLaw { name, known } => {
                write!(f, "unknown adhesion law {name:?}; known: {}", known.join(", "))
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
