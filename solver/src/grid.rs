//! The uniform grid of boundary elements on `[-X, X]` (normalised horizontal
//! units `l_h`): `n` cells of width `dx = 2X/n`, cell `i` centred at
//! `x_i = -X + (i + 1/2) dx`. The traction is constant on each cell; gaps and
//! displacements are collocated at the centres.

use crate::error::{finite, in_range, Interval, Result, SolverError};

/// Fewest cells accepted.
pub const MIN_CELLS: usize = 64;
/// Most cells accepted (2^24: the zero-padded FFT then has 2^25 points).
pub const MAX_CELLS: usize = 1 << 24;

/// Smallest domain half-width accepted (`l_h`): far below any contact the
/// model describes, and it keeps the cell width `2X/n` a normal f64 at every
/// grid size (a subnormal half-width made `dx = 0`; found by `tests/it/fuzz.rs`).
pub const MIN_HALF_WIDTH: f64 = 1e-6;
/// Largest domain half-width accepted (`l_h`).
pub const MAX_HALF_WIDTH: f64 = 1e6;

/// A uniform grid of `n` cells (a power of two) on `[-half_width, half_width]`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Grid {
    cells: usize,
    half_width: f64,
}

impl Grid {
    /// `cells` a power of two in `[MIN_CELLS, MAX_CELLS]`, `half_width` in
    /// `[MIN_HALF_WIDTH, MAX_HALF_WIDTH]`.
    pub fn new(cells: usize, half_width: f64) -> Result<Grid> {
        if !cells.is_power_of_two() || !(MIN_CELLS..=MAX_CELLS).contains(&cells) {
            return Err(SolverError::Grid { cells, min: MIN_CELLS, max: MAX_CELLS });
        }
        finite(half_width, "the domain half-width")?;
        in_range(half_width, "the domain half-width", Interval::closed(MIN_HALF_WIDTH, MAX_HALF_WIDTH))?;
        Ok(Grid { cells, half_width })
    }

    /// Number of cells.
    pub fn cells(&self) -> usize {
        self.cells
    }

    /// Half-width `X` of the domain.
    pub fn half_width(&self) -> f64 {
        self.half_width
    }

    /// Cell width `dx = 2X/n`.
    pub fn dx(&self) -> f64 {
        2.0 * self.half_width / self.cells as f64
    }

    /// Centre of cell `i`.
    pub fn x(&self, i: usize) -> f64 {
        -self.half_width + (i as f64 + 0.5) * self.dx()
    }

    /// All cell centres.
    pub fn centres(&self) -> Vec<f64> {
        (0..self.cells).map(|i| self.x(i)).collect()
    }
}
