//! A profile read from a table: the rows `x,h` of a CSV text, in the
//! normalised units of the built-in profile (`x` in `l_h`, `h` in `l_v`, the
//! depth of the indenter's surface, growing away from the body), and its cubic
//! interpolant onto a grid.
//!
//! # Format
//!
//! The first line is the header `x,h`; every other non-blank line holds two
//! finite numbers, `x` strictly increasing. Blank lines are skipped. Lines may
//! end in `\r\n`. At least 4 rows.
//!
//! # Interpolation
//!
//! Piecewise cubic Hermite: at each row the slope of the parabola through it
//! and its two neighbours (one-sided at the ends), so the interpolant is `C^1`
//! and exact for quadratics; its error is `O(dx_max^3 |h'''|)` on a smooth
//! profile (third order, unit test).
//! The table must cover the domain: its first `x` at most `-X`, its last at
//! least `X` ([`ProfileTable::check_covers`]).
//!
//! # Errors
//!
//! A line that is not a row of two finite numbers in increasing `x`, a header
//! other than `x,h`, fewer than 4 rows, or rows so close for their rise that a
//! slope is not a finite f64 is [`SolverError::ProfileTable`]
//! with the 1-based line and a [`TableFault`]; a table that does not cover the
//! domain is [`SolverError::ProfileCoverage`].

use crate::error::{Result, SolverError, TableFault};

/// Fewest rows a table may have.
pub const MIN_ROWS: usize = 4;

/// A checked profile table: `x` strictly increasing, every value finite.
#[derive(Debug, Clone, PartialEq)]
pub struct ProfileTable {
    x: Vec<f64>,
    h: Vec<f64>,
    /// The Hermite slopes at the rows.
    slope: Vec<f64>,
}

impl ProfileTable {
    /// Parses CSV text (see the module docs).
    pub fn parse(text: &str) -> Result<ProfileTable> {
        let fault = |line: usize, fault: TableFault| SolverError::ProfileTable { line, fault };
        let mut lines = text.lines().enumerate().map(|(i, l)| (i + 1, l.trim()));
        let header = lines.by_ref().find(|(_, l)| !l.is_empty());
        match header {
            Some((_, l)) if l.trim_start_matches('\u{feff}').replace(' ', "") == "x,h" => {}
            Some((i, l)) => return Err(fault(i, TableFault::Header { found: l.to_string() })),
            None => return Err(fault(1, TableFault::TooFewRows { rows: 0, min: MIN_ROWS })),
        }
        let (mut x, mut h) = (Vec::new(), Vec::new());
        let mut last_line = 1;
        for (i, l) in lines {
            if l.is_empty() {
                continue;
            }
            last_line = i;
            let fields: Vec<&str> = l.split(',').map(str::trim).collect();
            if fields.len() != 2 {
                return Err(fault(i, TableFault::Fields { found: fields.len() }));
            }
            let mut row = [0.0; 2];
            for (k, (v, column)) in fields.iter().zip(["x", "h"]).enumerate() {
                let value: f64 = v.parse().map_err(|_| fault(i, TableFault::Number { column, text: v.to_string() }))?;
                if !value.is_finite() {
                    return Err(fault(i, TableFault::NotFinite { column }));
                }
                row[k] = value;
            }
            if let Some(&previous) = x.last() {
                if row[0] <= previous {
                    return Err(fault(i, TableFault::NotIncreasing { x: row[0], previous }));
                }
            }
            x.push(row[0]);
            h.push(row[1]);
        }
        if x.len() < MIN_ROWS {
            return Err(fault(last_line, TableFault::TooFewRows { rows: x.len(), min: MIN_ROWS }));
        }
        ProfileTable::new(x, h)
    }

    /// A table from its columns (`x` strictly increasing, all finite, at least
    /// [`MIN_ROWS`] rows); a fault is reported on the line the row would have
    /// in a CSV text (row `k` on line `k + 2`).
    pub fn new(x: Vec<f64>, h: Vec<f64>) -> Result<ProfileTable> {
        let fault = |row: usize, fault: TableFault| SolverError::ProfileTable { line: row + 2, fault };
        if x.len() != h.len() || x.len() < MIN_ROWS {
            return Err(fault(x.len().min(h.len()), TableFault::TooFewRows { rows: x.len().min(h.len()), min: MIN_ROWS }));
        }
        for k in 0..x.len() {
            for (v, column) in [(x[k], "x"), (h[k], "h")] {
                if !v.is_finite() {
                    return Err(fault(k, TableFault::NotFinite { column }));
                }
            }
            if k > 0 && x[k] <= x[k - 1] {
                return Err(fault(k, TableFault::NotIncreasing { x: x[k], previous: x[k - 1] }));
            }
        }
        let n = x.len();
        let secant = |k: usize| (h[k + 1] - h[k]) / (x[k + 1] - x[k]);
        let mut slope = vec![0.0; n];
        for k in 1..n - 1 {
            let (d0, d1) = (x[k] - x[k - 1], x[k + 1] - x[k]);
            slope[k] = (secant(k - 1) * d1 + secant(k) * d0) / (d0 + d1);
        }
        // One-sided: the parabola through the first (last) three rows.
        let end = |s0: f64, s1: f64, d0: f64, d1: f64| s0 + (s0 - s1) * d0 / (d0 + d1);
        slope[0] = end(secant(0), secant(1), x[1] - x[0], x[2] - x[1]);
        slope[n - 1] = end(secant(n - 2), secant(n - 3), x[n - 1] - x[n - 2], x[n - 2] - x[n - 3]);
        // Rows too close for their rise (a subnormal step, or h differences near
        // f64::MAX) give a slope that is not a number: the interpolant would be NaN.
        if let Some(k) = slope.iter().position(|s| !s.is_finite()) {
            return Err(fault(k, TableFault::SlopeNotFinite { x: x[k] }));
        }
        Ok(ProfileTable { x, h, slope })
    }

    /// The rows' `x`.
    pub fn x(&self) -> &[f64] {
        &self.x
    }

    /// The rows' `h`.
    pub fn h(&self) -> &[f64] {
        &self.h
    }

    /// `Ok` when the table covers `[-half_width, half_width]`.
    pub fn check_covers(&self, half_width: f64) -> Result<()> {
        let (first, last) = (self.x[0], self.x[self.x.len() - 1]);
        if first <= -half_width && last >= half_width {
            Ok(())
        } else {
            Err(SolverError::ProfileCoverage { first, last, half_width })
        }
    }

    /// The interpolated depth at `x` (held at the end rows' values outside the
    /// table; [`Self::check_covers`] keeps a solver's grid inside it).
    /// A NaN `x` gives NaN.
    pub fn depth_at(&self, x: f64) -> f64 {
        let n = self.x.len();
        if x.is_nan() {
            // no row brackets it (partition_point would give 0, and 0 - 1 panics)
            return f64::NAN;
        }
        if x <= self.x[0] {
            return self.h[0];
        }
        if x >= self.x[n - 1] {
            return self.h[n - 1];
        }
        let k = self.x.partition_point(|&v| v <= x) - 1;
        let d = self.x[k + 1] - self.x[k];
        let t = (x - self.x[k]) / d;
        let (t2, t3) = (t * t, t * t * t);
        let (h00, h10, h01, h11) = (2.0 * t3 - 3.0 * t2 + 1.0, t3 - 2.0 * t2 + t, -2.0 * t3 + 3.0 * t2, t3 - t2);
        h00 * self.h[k] + h10 * d * self.slope[k] + h01 * self.h[k + 1] + h11 * d * self.slope[k + 1]
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn line_of(text: &str) -> (usize, TableFault) {
        match ProfileTable::parse(text) {
            Err(SolverError::ProfileTable { line, fault }) => (line, fault),
            other => panic!("{other:?}"),
        }
    }

    #[test]
    fn faults_name_their_line() {
        assert!(matches!(line_of("x,y\n0,1\n"), (1, TableFault::Header { .. })));
        assert!(matches!(line_of("x,h\n0,1\n1,2\n2,oops\n3,4\n"), (4, TableFault::Number { column: "h", .. })));
        assert!(matches!(line_of("x,h\n0,1\n1,2,3\n"), (3, TableFault::Fields { found: 3 })));
        assert!(matches!(line_of("x,h\n0,1\n1,2\n\n1,3\n4,4\n"), (5, TableFault::NotIncreasing { .. })));
        assert!(matches!(line_of("x,h\n0,1\nNaN,2\n"), (3, TableFault::NotFinite { column: "x" })));
        assert!(matches!(line_of("x,h\n0,1\n1,2\n"), (3, TableFault::TooFewRows { rows: 2, .. })));
        assert!(matches!(line_of(""), (1, TableFault::TooFewRows { rows: 0, min: MIN_ROWS })));
    }

    #[test]
    fn quadratics_are_exact_and_the_error_is_third_order() {
        // The Fig. 4c profile on rows 0.1 and 0.05 apart: the largest error
        // between the rows falls by 2^3 (within 25 %).
        let f = |v: f64| 0.5 * v * v + 0.35 * (1.0 - (2.0 * std::f64::consts::PI * v / 1.125).cos());
        let worst = |dx: f64| {
            let x: Vec<f64> = (0..=(8.0 / dx).round() as usize).map(|k| -4.0 + k as f64 * dx).collect();
            let t = ProfileTable::new(x.clone(), x.iter().map(|&v| f(v)).collect()).unwrap();
            (0..4000).map(|k| -3.9 + 7.8 * k as f64 / 3999.0).map(|v| (t.depth_at(v) - f(v)).abs()).fold(0.0, f64::max)
        };
        let (coarse, fine) = (worst(0.1), worst(0.05));
        assert!(coarse < 2e-3 && (6.0..10.0).contains(&(coarse / fine)), "{coarse} {fine}");
        let xs = [-3.0, -2.2, -1.0, 0.1, 0.3, 1.7, 3.0];
        let quad = |v: f64| 0.5 * v * v - 0.25 * v + 2.0;
        let t = ProfileTable::new(xs.to_vec(), xs.iter().map(|&v| quad(v)).collect()).unwrap();
        for k in 0..100 {
            let v = -3.0 + 6.0 * k as f64 / 99.0;
            assert!((t.depth_at(v) - quad(v)).abs() < 1e-12, "{v}");
        }
        assert!(t.check_covers(3.0).is_ok());
        assert!(matches!(t.check_covers(3.1), Err(SolverError::ProfileCoverage { .. })));
    }
}
