//! An f64 value with a proven bound on its error.

use std::fmt;

/// An f64 result with a rigorous absolute error bound: the exact value of the
/// function at the f64 inputs as given lies in `[value - err, value + err]`.
///
/// `err` covers truncation and every rounding of the evaluation (it is derived
/// by a running error analysis, or from a certified MP ball where a function
/// falls back to MP). It is an upper bound, not an estimate. `err == 0` means
/// `value` is exact.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Bounded {
    /// The f64 approximation.
    pub value: f64,
    /// Upper bound on `|exact - value|`.
    pub err: f64,
}

impl Bounded {
    /// Whether `x` lies within the bound.
    pub fn contains(&self, x: f64) -> bool {
        (x - self.value).abs() <= self.err
    }

    /// Relative error bound `err / |value|` (infinite at `value == 0` unless `err == 0`).
    pub fn rel_err(&self) -> f64 {
        if self.err == 0.0 {
            0.0
        } else {
            self.err / self.value.abs()
        }
    }
}

impl fmt::Display for Bounded {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{:e} +/- {:e}", self.value, self.err)
    }
}
