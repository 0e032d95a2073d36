//! The solver's error type: every public entry point that can fail on user input
//! returns [`Result`]; nothing panics on bad input.
//!
//! Each variant carries the values it reports (the limits too, as fields), and
//! its message is made from them: this file imports no other module of the
//! solver, and no message names a front end's flag (a library user has none).

use std::fmt;

pub use maugis::error::Interval;

/// Everything that can go wrong in `maugis-solver`.
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub enum SolverError {
    /// Kept so that code matching on it still compiles: the solver no longer
    /// builds it (every check has a variant with fields below).
    Domain {
        /// What is wrong and what to change.
        what: String,
    },
    /// A profile of many waves on the periodic domain: its waves need not share a
    /// period, so the periodic half-plane takes one sinusoid only.
    PeriodicManyWaves {
        /// How many waves the profile has.
        waves: usize,
    },
    /// A number is NaN or infinite.
    NonFinite {
        /// Which argument.
        arg: &'static str,
        /// The value given.
        value: f64,
    },
    /// A number lies outside the range the solver accepts.
    OutOfRange {
        /// Which argument.
        arg: &'static str,
        /// The value given.
        value: f64,
        /// The values accepted.
        allowed: Interval,
    },
    /// A count (steps, scan points, states) lies outside its range.
    CountOutOfRange {
        /// Which count.
        arg: &'static str,
        /// The count given or found.
        value: usize,
        /// Fewest accepted.
        min: usize,
        /// Most accepted (`usize::MAX`: no upper limit).
        max: usize,
    },
    /// Two lengths that must agree do not.
    LengthMismatch {
        /// What has the wrong length.
        arg: &'static str,
        /// Its length.
        found: usize,
        /// The length it must have.
        expected: usize,
    },
    /// The approach leg ended before the contact half-width reached `amax`.
    AmaxNotReached {
        /// The largest contact half-width reached.
        reached: f64,
        /// The requested largest half-width.
        amax: f64,
        /// Approach steps done.
        steps: usize,
    },
    /// A solver map ([`crate::map`]) over a profile of many waves: the map runs one
    /// wave's cycles (`maugis sweep` maps many waves with the model only).
    MapManyWaves {
        /// The number of waves of the grid's base profile.
        waves: usize,
    },
    /// The closed in-contact cycle read along the legs does not close: reloading
    /// stops at a maximum with no later state at its level
    /// ([`crate::dissipation::LegCycle::reloading_truncated`]).
    CycleOpen {
        /// Under load control.
        load_control: bool,
        /// Under displacement control.
        displacement_control: bool,
    },
    /// The model's closed cycle does not close
    /// ([`maugis::contact::paths::ControlPaths::reloading_truncated`]): its W
    /// is not measured.
    ModelCycleOpen {
        /// Under load control.
        load_control: bool,
        /// Under displacement control.
        displacement_control: bool,
    },
    /// A shard `shard/of` that does not exist (1-based, `1 <= shard <= of`).
    BadShard {
        /// The shard asked for.
        shard: usize,
        /// The number of shards.
        of: usize,
    },
    /// Shards of a map that cannot be merged.
    Merge {
        /// What is wrong with them.
        fault: MergeFault,
    },
    /// A failure that is a bug in the solver, not a fault of the input.
    Internal {
        /// What failed.
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

/// Why shards of a map cannot be merged.
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub enum MergeFault {
    /// No shard was given.
    Empty,
    /// The shards belong to different maps (their grids or options differ).
    DifferentMaps,
    /// A grid point index beyond the grid.
    OutsideGrid {
        /// The index.
        index: usize,
    },
    /// A grid point in two shards.
    Duplicate {
        /// The index.
        index: usize,
    },
    /// Grid points that no shard has.
    Missing {
        /// How many are missing.
        missing: usize,
        /// Grid points in all.
        total: usize,
    },
}

impl fmt::Display for MergeFault {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            MergeFault::Empty => write!(f, "nothing to merge"),
            MergeFault::DifferentMaps => write!(f, "the shards belong to different maps (grid or options differ)"),
            MergeFault::OutsideGrid { index } => write!(f, "grid point {index} lies outside the grid"),
            MergeFault::Duplicate { index } => write!(f, "grid point {index} appears in two shards"),
            MergeFault::Missing { missing, total } => write!(f, "{missing} of {total} grid points are missing: merge every shard"),
        }
    }
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
            SolverError::PeriodicManyWaves { waves } => write!(
                f,
                "the periodic domain takes one sinusoid; a profile of {waves} waves runs on the free half-plane (drop the periodic option)"
            ),
            SolverError::NonFinite { arg, value } => write!(f, "{arg} must be a finite number (got {value})"),
            SolverError::OutOfRange { arg, value, allowed } => write!(f, "{arg} must lie in {allowed} (got {value})"),
            SolverError::CountOutOfRange { arg, value, min, max } if *max == usize::MAX => {
                write!(f, "{arg} must be at least {min} (got {value})")
            }
            SolverError::CountOutOfRange { arg, value, min, max } => write!(f, "{arg} must lie in [{min}, {max}] (got {value})"),
            SolverError::LengthMismatch { arg, found, expected } => write!(f, "{arg} has {found} values, it must have {expected}"),
            SolverError::AmaxNotReached { reached, amax, steps } => write!(
                f,
                "the contact half-width reached only {reached:.4} in {steps} approach steps, short of amax = {amax}; \
                 lower amax or give more steps"
            ),
            SolverError::MapManyWaves { waves } => write!(
                f,
                "the solver map runs one wave's cycles, but the grid's profile has {waves} waves: map it with the model (without --solver), or run maugis simulate per profile"
            ),
            SolverError::CycleOpen { load_control, displacement_control } => write!(
                f,
                "the closed cycle does not close (reloading stops at a maximum with no later state at its level) under {}: raise amax or the steps per leg",
                controls(*load_control, *displacement_control)
            ),
            SolverError::ModelCycleOpen { load_control, displacement_control } => write!(
                f,
                "the model's closed cycle does not close (reloading stops at a maximum with no later curve point at its level) under {}: its W is not measured; change amax or the model's curve points",
                controls(*load_control, *displacement_control)
            ),
            SolverError::BadShard { shard, of } => write!(f, "shard must be s/n with 1 <= s <= n (got {shard}/{of})"),
            SolverError::Merge { fault } => write!(f, "cannot merge the shards: {fault}"),
            SolverError::Internal { what } => write!(f, "internal error (a bug in maugis-solver, please report it): {what}"),
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

/// `Ok(x)` if `x` is finite, else a [`SolverError::NonFinite`] naming it.
pub(crate) fn finite(x: f64, arg: &'static str) -> Result<f64> {
    if x.is_finite() {
        Ok(x)
    } else {
        Err(SolverError::NonFinite { arg, value: x })
    }
}

/// `Ok(x)` if `x` lies in `allowed`, else a [`SolverError::OutOfRange`] naming it.
pub(crate) fn in_range(x: f64, arg: &'static str, allowed: Interval) -> Result<f64> {
    if allowed.contains(x) {
        Ok(x)
    } else {
        Err(SolverError::OutOfRange { arg, value: x, allowed })
    }
}

/// `Ok(n)` if `min <= n <= max`, else a [`SolverError::CountOutOfRange`] naming it.
pub(crate) fn count_in_range(n: usize, arg: &'static str, min: usize, max: usize) -> Result<usize> {
    if (min..=max).contains(&n) {
        Ok(n)
    } else {
        Err(SolverError::CountOutOfRange { arg, value: n, min, max })
    }
}

/// The controls named by a pair of flags (load, displacement).
fn controls(load_control: bool, displacement_control: bool) -> &'static str {
    match (load_control, displacement_control) {
        (true, true) => "load and displacement control",
        (true, false) => "load control",
        _ => "displacement control",
    }
}
