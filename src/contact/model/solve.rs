//! The first root of the strip equation (corrected Eq. 15b) at one contact size:
//! [`ContactSize::solve_strip`] scans outward from the contact edge in steps of at most a
//! sixteenth of the finest wavelength, refines every sampled local maximum, and
//! brackets the first sign change for Brent's method (docs/model.md, "Root m").

use super::state::ContactSize;
use super::strip::StripEnd;
use crate::error::{Error, Invariant, Reached, Result};
use crate::roots::{brent, first_crossing, BRENT_REL_TOL};

/// Largest strip width `c - a` (in `l_h`) the root scan explores.
pub const MAX_STRIP: f64 = 1.0e4;

/// Relative tolerance of the root `m - 1` (the solver's variable).
pub const M_REL_TOL: f64 = BRENT_REL_TOL;

/// The golden-section search that refines a sampled local maximum of the strip
/// residual stops at this width in `c - a` (relative to `1 + (c - a)`).
const PEAK_REL_TOL: f64 = 1e-10;

/// The strip scan starts this many octaves below its first step (`first/4096`) and
/// doubles up to it ([`ContactSize::solve_strip`]).
const EDGE_OCTAVES: i32 = 12;

impl ContactSize {
    /// The first root `m > 1` of [`Self::strip_residual`] (see [`Self::solve_strip`]).
    pub fn solve_m(&self) -> Result<f64> {
        Ok(self.solve_strip()?.m())
    }

    /// The first root of the strip equation, solved for `z = m - 1`.
    ///
    /// Scan in the strip width `s = c - a = z abar` with steps of
    /// `max(min(beta/16, 1/4), min(s/20, beta/16))`, `beta` the shortest wavelength of
    /// the profile's waves (infinite without a wave): never more than a sixteenth
    /// of a wave period, so no period and no wide excursion within one is skipped;
    /// every sampled local maximum below zero is refined by golden-section search
    /// (the residual's excursions above zero narrower than a step rise between
    /// samples), and a refined maximum at or above zero brackets the first
    /// crossing. This samples the residual, it does not bound it between samples:
    /// an excursion that leaves no sampled local maximum (two maxima within one
    /// step) can still be missed; `examples/strip_scan_check` counts the misses
    /// against a scan 128 times finer. The scan starts at `s_1/4096` (`s_1` the
    /// first step) and doubles up to `s_1`: next to the edge the residual rises
    /// like a square root and can cross zero and fall back within the first step.
    /// When that first sample is already past the root, the crossing is
    /// bracketed by halving `s` towards the edge (`F(0) = -1` ends the halving
    /// below `z = 1e-300`). Brent's method then refines `z` to [`M_REL_TOL`] relative.
    pub fn solve_strip(&self) -> Result<StripEnd> {
        let a = self.abar;
        let f = |z: f64| self.residual_z(z);
        // the shortest wavelength of the waves with an amplitude (a wave of amplitude 0
        // changes nothing); a profile without one keeps its waves' shortest wavelength
        // (the one-wave smooth case Params::new(lambda, 0, beta) scans as before)
        let beta = self.params.profile.scan_wavelength();
        let max_step = (beta / 16.0).min(0.25).max(1e-6);
        let evaluations = std::cell::Cell::new(0u64);
        let eval = |s: f64| -> Result<f64> {
            // the installed time budget (crate::budget; none on the f64 path unless
            // the caller installs one), every 64 samples: the scan's length is
            // the root over the step (lambda = 1e-6, beta = 6.5e-3: 3.5e6 samples
            // of a wave sum with D = 2e4 terms, minutes, under an MP strip_ratio)
            let count = evaluations.get() + 1;
            evaluations.set(count);
            if count % 64 == 0 {
                crate::budget::check_elapsed("the strip root scan (Eq. 15b, f64)", 0.0, Reached::Evaluations { count })?;
            }
            let z = s / a;
            if !z.is_finite() {
                // a strip width over f64::MAX times a subnormal contact size
                return Err(Error::NotRepresentable { quantity: "m - 1 (the strip end)", abar: a });
            }
            let v = f(z);
            if v.is_finite() {
                Ok(v)
            } else {
                Err(Error::Invariant(Invariant::StripResidualNotFinite { m_minus_1: s / a }))
            }
        };
        let done = |z: Result<f64>| -> Result<StripEnd> {
            let z = z?;
            StripEnd::from_m_minus_1(z).map_err(|_| Error::Invariant(Invariant::StripRootNotPositive { m_minus_1: z }))
        };
        // The scan starts EDGE_OCTAVES octaves below the first step and doubles up to
        // it: next to the edge F rises like a square root and can cross zero and fall
        // back within the first step (lambda 24.5, alpha 2.97, beta 0.228, abar 3.09:
        // F > 0 at m = 1.00072, the first step ends at m = 1.0046).
        let first = max_step;
        let start = first * 0.5f64.powi(EDGE_OCTAVES);
        let f_start = eval(start)?;
        if f_start >= 0.0 {
            // Bracket towards the edge: F(0) = -1.
            let (mut hi, mut f_hi) = (start, f_start);
            let mut lo = 0.5 * start;
            loop {
                let f_lo = eval(lo)?;
                if f_lo < 0.0 {
                    return done(brent(f, lo / a, hi / a, f_lo, f_hi));
                }
                hi = lo;
                f_hi = f_lo;
                lo *= 0.25;
                if lo < 1e-300 * a {
                    return done(brent(f, 0.0, hi / a, -1.0, f_hi));
                }
            }
        }
        // then never more than a sixteenth of a wave period (the step grew with s
        // before, 5 % of s, and skipped a positive excursion of width 0.09 in s:
        // abar 2.54, lambda 0.107, alpha 1.23, beta 0.79 gave m = 2.51 for the
        // first root 2.34); every sampled local maximum is refined (narrow
        // excursions above zero between samples: 4 of 4000 random parameter sets,
        // e.g. lambda 4.36, alpha 0.561, beta 0.393, abar 0.928 gave m = 1.345 for
        // the first root 1.065; F(0) = -1 is the first sample's left neighbour)
        let next = |s: f64| if s < first { 2.0 * s } else { s + max_step.max((s * 0.05).min(beta / 16.0)) };
        match first_crossing(eval, Some((0.0, -1.0)), (start, f_start), next, MAX_STRIP, PEAK_REL_TOL)? {
            Some((lo, hi, f_lo, f_hi)) => done(brent(f, lo / a, hi / a, f_lo, f_hi)),
            None => Err(Error::NoStripEnd { model: "Eq. 15b, c - a", limit: MAX_STRIP }),
        }
    }
}
