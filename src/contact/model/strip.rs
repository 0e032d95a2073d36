//! The end of the adhesive strip, `m = c/a`, held as `m - 1` ([`StripEnd`]), and the
//! strip functions of the corrected Eq. 15b that take `z = m - 1` and keep full
//! relative accuracy as the strip closes ([`hertz_gap_fn`], [`adhesive_gap_fn`],
//! [`adhesive_approach_fn`]: closed forms, and six-term Taylor series below `z = 1e-3`,
//! truncation below `z^6 < 1e-18` relative). None of them depends on the profile.

use crate::error::{finite, Interval, Result};

/// Below this `z = m - 1` the strip functions use their Taylor series
/// (six terms: truncation below `z^6 < 1e-18` relative).
pub(crate) const SERIES_Z: f64 = 1e-3;

/// From this `z = m - 1` on, the model's strip terms are computed from `abar` times
/// the strip functions in the strip width `s = abar z` ([`ScaledStrip`]): at tiny
/// contact sizes (`abar = 1e-257`, `m - 1 = 5e252`) `sqrt(z (2 + z))` overflows and
/// `abar^2` underflows, while their product is a moderate number.
pub(crate) const SCALED_Z: f64 = 1e6;

/// `abar` times the strip functions at `z = m - 1 >= `[`SCALED_Z`], in the strip
/// width `s = abar z` and the strip end `c = abar + s`: no product of a huge and a
/// tiny number, no cancellation.
///
/// With `P = abar sqrt(m^2 - 1) = sqrt(s (2 abar + s))`, `L = ln m = ln1p(z)` and
/// `acosh m = L + ln1p(P/c)` (`m + sqrt(m^2-1) = m (1 + P/c)`):
///
/// * `abar^2 H(z) = c P - abar^2 acosh m` ([`hertz_gap_fn`]);
/// * `abar G(z) = P ln1p(P/c) - abar^2 L/(c + P)` ([`adhesive_gap_fn`];
///   `c - P = abar^2/(c + P)`, so the two terms of `G`, each about `z ln z`, never
///   cancel);
/// * `abar A(z) = c acosh m - P` ([`adhesive_approach_fn`]).
#[derive(Debug, Clone, Copy)]
pub(crate) struct ScaledStrip {
    a: f64,
    c: f64,
    p: f64,
    ln_m: f64,
    acosh_m: f64,
}

impl ScaledStrip {
    /// At contact size `a > 0` and `z = m - 1 >= 0` (finite).
    pub(crate) fn new(a: f64, z: f64) -> ScaledStrip {
        let s = a * z;
        let c = a + s;
        let p = s.sqrt() * (2.0 * a + s).sqrt();
        let ln_m = z.ln_1p();
        let acosh_m = ln_m + (p / c).ln_1p();
        ScaledStrip { a, c, p, ln_m, acosh_m }
    }

    /// `abar sqrt(m^2 - 1)`.
    pub(crate) fn a_sqrt_m2_minus_1(&self) -> f64 {
        self.p
    }

    /// `abar^2 H(z)`, `H` the Hertz gap function.
    pub(crate) fn hertz_gap(&self) -> f64 {
        self.c * self.p - self.a * (self.a * self.acosh_m)
    }

    /// `abar G(z)`, `G` the adhesive strip-gap function.
    pub(crate) fn adhesive_gap(&self) -> f64 {
        self.p * (self.p / self.c).ln_1p() - self.a / (self.c + self.p) * self.a * self.ln_m
    }

    /// `abar A(z)`, `A` the adhesive approach function.
    pub(crate) fn adhesive_approach(&self) -> f64 {
        self.c * self.acosh_m - self.p
    }
}

/// The end of the adhesive strip, `m = c/a > 1`, stored as `m - 1`.
///
/// As `lambda -> inf` the strip closes like `m - 1 ~ pi/(4 lambda^2 abar)`
/// (docs/model.md, the `smooth_jkr_limit` erratum row): at `lambda = 1e6` that is `1e-12`, and `m` itself would carry
/// only four significant digits of it. The solver works in `m - 1`, and every
/// quantity of a state (load, traction, gap, approach) is computed from it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StripEnd {
    m_minus_1: f64,
}

impl StripEnd {
    /// From `m - 1 > 0` (finite).
    pub fn from_m_minus_1(m_minus_1: f64) -> Result<StripEnd> {
        finite(m_minus_1, "m - 1")?;
        Interval::above(0.0).check("m - 1", m_minus_1)?;
        Ok(StripEnd { m_minus_1 })
    }

    /// From `m > 1` (finite). Loses the relative accuracy of `m - 1` when `m`
    /// is close to 1; prefer [`StripEnd::from_m_minus_1`].
    pub fn from_m(m: f64) -> Result<StripEnd> {
        finite(m, "m")?;
        Interval::above(1.0).check("the strip ratio m = c/a", m)?;
        Ok(StripEnd { m_minus_1: m - 1.0 })
    }

    /// `m = c/a` (rounded).
    pub fn m(self) -> f64 {
        1.0 + self.m_minus_1
    }

    /// `m - 1`, to full relative accuracy.
    pub fn m_minus_1(self) -> f64 {
        self.m_minus_1
    }

    /// `sqrt(m^2 - 1)`.
    pub fn sqrt_m2_minus_1(self) -> f64 {
        sqrt_z2z(self.m_minus_1)
    }
}


/// `sqrt(z (2 + z)) = sqrt((1+z)^2 - 1)`.
pub(crate) fn sqrt_z2z(z: f64) -> f64 {
    (z * (2.0 + z)).sqrt()
}

/// `acosh(1 + z)` for `z >= 0`, accurate for small `z`.
pub(crate) fn acosh_1p(z: f64) -> f64 {
    (z + sqrt_z2z(z)).ln_1p()
}


/// The Hertz gap function `(1+z) sqrt(z(2+z)) - acosh(1+z)`, `z >= 0`
/// (`= 2 int_1^{1+z} sqrt(t^2-1) dt`; the Hertz gap at `x = (1+z) a` is
/// `a^2/2` times it). Series below `SERIES_Z`:
/// `sqrt(2z) z (4/3 + z/5 - z^2/56 + z^3/288 - 5 z^4/5632 + 7 z^5/26624)`.
pub fn hertz_gap_fn(z: f64) -> f64 {
    if z < SERIES_Z {
        let p = 4.0 / 3.0 + z * (1.0 / 5.0 + z * (-1.0 / 56.0 + z * (1.0 / 288.0 + z * (-5.0 / 5632.0 + z * 7.0 / 26624.0))));
        (2.0 * z).sqrt() * z * p
    } else {
        (1.0 + z) * sqrt_z2z(z) - acosh_1p(z)
    }
}

/// The adhesive strip-gap function `sqrt(z(2+z)) acosh(1+z) - (1+z) ln(1+z)`,
/// `z >= 0` (leading term `z`; the two products differ by a factor 2, so the
/// direct form loses at most one bit).
pub fn adhesive_gap_fn(z: f64) -> f64 {
    sqrt_z2z(z) * acosh_1p(z) - (1.0 + z) * z.ln_1p()
}

/// The adhesive approach function `(1+z) acosh(1+z) - sqrt(z(2+z))`, `z >= 0`.
/// Series below `SERIES_Z`:
/// `sqrt(2z) z (2/3 - z/30 + 3 z^2/560 - 5 z^3/4032 + 35 z^4/101376 - 63 z^5/585728)`.
pub fn adhesive_approach_fn(z: f64) -> f64 {
    if z < SERIES_Z {
        let p = 2.0 / 3.0 + z * (-1.0 / 30.0 + z * (3.0 / 560.0 + z * (-5.0 / 4032.0 + z * (35.0 / 101376.0 - z * 63.0 / 585728.0))));
        (2.0 * z).sqrt() * z * p
    } else {
        (1.0 + z) * acosh_1p(z) - sqrt_z2z(z)
    }
}

