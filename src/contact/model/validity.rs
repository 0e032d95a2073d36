//! Whether a state is physical (docs/model.md, "Validity"): the gap is non-negative in
//! the strip `abar < x < m abar` (no interpenetration at crests) and `pbar <= 1` inside
//! the contact (no cavitation). [`ContactSize::validity`] samples both and refines the
//! extrema with golden-section search; the tolerances are relative to the gap scale
//! `delta = 1/lambda` plus the rounding allowances of every wave's term.

use super::state::{check_m, ContactSize};
use super::strip::StripEnd;
use crate::error::{Error, Result};
use crate::roots::golden_section_min;

/// Relative slack of the gap test: a state interpenetrates when its strip gap is
/// below `-GAP_REL_TOL delta` (`delta = 1/lambda`, the gap scale of the strip)
/// minus the rounding allowance of [`ContactSize::gap_tolerance`].
pub const GAP_REL_TOL: f64 = 1e-9;
/// Slack of the traction test: cavitation when `pbar > 1 + TRACTION_TOL`
/// (plus the rounding allowance of the Hertz term, see [`ContactSize::traction_tolerance`]).
pub const TRACTION_TOL: f64 = 1e-9;

/// Samples per extremum search in [`ContactSize::validity`].
const VALIDITY_SAMPLES: usize = 48;

/// Validity diagnostics of a state.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Validity {
    /// Smallest gap in the strip `abar < x <= m abar` (units of `l_v`).
    pub min_strip_gap: f64,
    /// Where it occurs.
    pub min_strip_gap_at: f64,
    /// Largest traction `pbar` inside the contact.
    pub max_traction: f64,
    /// Where it occurs.
    pub max_traction_at: f64,
    /// The gap is below minus its tolerance somewhere in the strip.
    pub interpenetration: bool,
    /// The traction exceeds `1 +` its tolerance somewhere inside the contact.
    pub cavitation: bool,
    /// Neither.
    pub valid: bool,
}

impl ContactSize {
    /// Tolerance of the gap test: `GAP_REL_TOL / lambda` plus a rounding
    /// allowance for each wave term (`1e-13 alpha_j (1 + D_j)`, ~100 times its
    /// measured error) and for the Hertz term at large `abar` (`1e-14 abar^2`).
    pub fn gap_tolerance(&self) -> f64 {
        GAP_REL_TOL / self.params.lambda + self.waves.gap_allowance() + 1e-14 * self.abar * self.abar
    }

    /// Tolerance of the traction test: [`TRACTION_TOL`] plus the rounding of the
    /// Hertz/wave term `sqrt(abar^2-x^2)/(2 lambda) (1 + ...)`
    /// (`1e-14 abar/lambda (1 + sum_j 2 pi alpha_j D_j/(beta_j abar))`).
    pub fn traction_tolerance(&self) -> f64 {
        TRACTION_TOL + 1e-14 * self.abar / self.params.lambda * (1.0 + self.waves.traction_allowance())
    }

    /// Minimum strip gap and maximum inner traction, located by sampling and
    /// golden-section refinement (`m > 1`).
    pub fn validity(&self, m: f64) -> Result<Validity> {
        self.validity_at(check_m(m)?)
    }

    /// [`Self::validity`] at a solved strip end. The strip is sampled in the
    /// relative coordinate `t` of [`Self::strip_gap`], so the search resolves it
    /// however narrow it is.
    pub fn validity_at(&self, strip: StripEnd) -> Result<Validity> {
        let a = self.abar;
        let z = strip.m_minus_1();
        let (gt, gv) = refine_extremum(|t| self.strip_gap(strip, t), 1e-6, 1.0, true);
        let trac = |x: f64| self.traction_at(strip, x);
        let (tx, tv) = refine_extremum(trac, 0.0, a * (1.0 - 1e-9), false);
        if !gv.is_finite() || !tv.is_finite() {
            return Err(Error::Internal { what: "validity check produced a non-finite value".into() });
        }
        let interpenetration = gv < -self.gap_tolerance();
        let cavitation = tv > 1.0 + self.traction_tolerance();
        Ok(Validity {
            min_strip_gap: gv,
            min_strip_gap_at: a + a * z * gt,
            max_traction: tv,
            max_traction_at: tx,
            interpenetration,
            cavitation,
            valid: !interpenetration && !cavitation,
        })
    }
}

/// Extremum (minimum if `minimize`, else maximum) of `f` on `[lo, hi]`: the best
/// of [`VALIDITY_SAMPLES`] samples, refined by golden-section search between its
/// neighbours. Returns `(argument, value)`.
fn refine_extremum<F: Fn(f64) -> f64>(f: F, lo: f64, hi: f64, minimize: bool) -> (f64, f64) {
    let sign = if minimize { 1.0 } else { -1.0 };
    let g = |x: f64| sign * f(x);
    if !(hi > lo) {
        return (lo, f(lo));
    }
    let n = VALIDITY_SAMPLES;
    let h = (hi - lo) / n as f64;
    let mut best = (lo, g(lo));
    for i in 1..=n {
        let x = lo + h * i as f64;
        let v = g(x);
        if v < best.1 || best.1.is_nan() {
            best = (x, v);
        }
    }
    // golden section on [best - h, best + h] ∩ [lo, hi]
    let refined = golden_section_min(|x| Ok::<f64, ()>(g(x)), (best.0 - h).max(lo), (best.0 + h).min(hi), 1e-12, 60);
    let (x, v) = match refined {
        Ok((x, v)) if v < best.1 => (x, v),
        _ => best,
    };
    (x, sign * v)
}