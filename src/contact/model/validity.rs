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

/// The rescan of [`ContactSize::validity_at`] samples the finest wavelength this many times.
pub const SAMPLES_PER_WAVELENGTH: f64 = 16.0;

/// The rescan refines a sampled local extremum whose value lies within this fraction
/// of the samples' spread of the best sample.
pub const RESCAN_MARGIN: f64 = 0.1;

/// The rescan refines this many sampled local extrema, those whose parabolic vertex
/// (through the sample and its neighbours) is the most extreme.
const RESCAN_REFINE: usize = 3;

/// Most samples of one rescan: 256 finest wavelengths at 16 samples each (a contact
/// of more wavelengths is sampled more coarsely; each sample costs a sum over the waves'
/// Bessel terms, so the rescan's work stays bounded however small `beta_min` is).
const RESCAN_MAX_SAMPLES: usize = 4096;

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
    ///
    /// Both searches then scan again at [`SAMPLES_PER_WAVELENGTH`] samples per finest
    /// wavelength `beta_min` wherever that is finer than the first sampling, and
    /// refine the sampled local extrema near the best (`rescan_extremum`): the traction's and the gap's features are as narrow as the
    /// finest wave (two waves `(0.354, 1.125) + (0.177, 0.375)` at lambda = 3,
    /// abar = 2.2112: an interior traction peak of 1.0035 at x = 1.691 lay between
    /// the first search's 48 samples, which reported 0.9998 at the edge; the solver
    /// cavitates there). Where the rescan finds nothing more extreme, the result is
    /// the first search's, bit for bit. Like the root scan, this samples; it does not
    /// bound the functions between samples.
    pub fn validity_at(&self, strip: StripEnd) -> Result<Validity> {
        let a = self.abar;
        let z = strip.m_minus_1();
        let spacing = self.params.profile.finest_wavelength().map(|b| b / SAMPLES_PER_WAVELENGTH);
        let gap = |t: f64| self.strip_gap(strip, t);
        let (gt, gv) = refine_extremum(gap, 1e-6, 1.0, true);
        // the strip in t: a width a z in x
        let (gt, gv) = match spacing.and_then(|h| rescan_extremum(gap, gap, 1e-6, 1.0, h / (a * z), true)) {
            Some((t, v)) if v < gv => (t, v),
            _ => (gt, gv),
        };
        let trac = |x: f64| self.traction_at(strip, x);
        let (tx, tv) = refine_extremum(trac, 0.0, a * (1.0 - 1e-9), false);
        let trac_fast = |x: f64| self.traction_fast_at(strip, x);
        let (tx, tv) = match spacing.and_then(|h| rescan_extremum(trac_fast, trac, 0.0, a * (1.0 - 1e-9), h, false)) {
            Some((x, v)) if v > tv => (x, v),
            _ => (tx, tv),
        };
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

/// The rescan of [`ContactSize::validity_at`]: `sample` (a cheaper approximation of `f`
/// that only ranks the candidates) on `[lo, hi]` at spacing `h` (when
/// that is finer than [`refine_extremum`]'s); of the sampled local extrema within
/// [`RESCAN_MARGIN`] of the samples' spread of the best, the [`RESCAN_REFINE`] whose
/// parabolic vertex is the most extreme are refined by golden-section search between
/// their neighbours in `f`; the most extreme result (values of `f`), or `None` when the first search's
/// sampling was as fine.
fn rescan_extremum<S: Fn(f64) -> f64, F: Fn(f64) -> f64>(sample: S, f: F, lo: f64, hi: f64, h: f64, minimize: bool) -> Option<(f64, f64)> {
    let width = hi - lo;
    if !(width > 0.0) || !(h > 0.0) || width / h <= VALIDITY_SAMPLES as f64 {
        return None;
    }
    let n = ((width / h).ceil() as usize).min(RESCAN_MAX_SAMPLES);
    let step = width / n as f64;
    let sign = if minimize { 1.0 } else { -1.0 };
    let g = |x: f64| sign * f(x);
    let values: Vec<f64> = (0..=n).map(|i| sign * sample(lo + step * i as f64)).collect();
    let (vmin, vmax) = values.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &v| (a.min(v), b.max(v)));
    if !(vmin.is_finite() && vmax.is_finite()) {
        return None;
    }
    let cutoff = vmin + RESCAN_MARGIN * (vmax - vmin);
    // the sampled local extrema near the best, ranked by the vertex of the parabola
    // through each and its neighbours; the RESCAN_REFINE best are refined
    let mut candidates: Vec<(f64, usize)> = (0..=n)
        .filter(|&i| {
            let v = values[i];
            let left = if i > 0 { values[i - 1] } else { f64::INFINITY };
            let right = if i < n { values[i + 1] } else { f64::INFINITY };
            v <= cutoff && v <= left && v <= right
        })
        .map(|i| {
            let v = values[i];
            let vertex = if i > 0 && i < n {
                let (l, r) = (values[i - 1], values[i + 1]);
                let curv = l - 2.0 * v + r;
                if curv > 0.0 { v - (r - l) * (r - l) / (8.0 * curv) } else { v }
            } else {
                v
            };
            (vertex, i)
        })
        .collect();
    candidates.sort_by(|a, b| a.0.total_cmp(&b.0));
    let mut best: Option<(f64, f64)> = None;
    for &(_, i) in candidates.iter().take(RESCAN_REFINE) {
        let x = lo + step * i as f64;
        let v = g(x);
        let (a, b) = ((x - step).max(lo), (x + step).min(hi));
        let (xr, vr) = match golden_section_min(|x| Ok::<f64, ()>(g(x)), a, b, 1e-12, 60) {
            Ok((xr, vr)) if vr < v => (xr, vr),
            _ => (x, v),
        };
        if best.map_or(true, |(_, bv)| vr < bv) {
            best = Some((xr, vr));
        }
    }
    best.map(|(x, v)| (x, sign * v))
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