//! The waves' terms of the model at one contact size, summed over the profile's waves
//! (docs/model.md, "Many waves").
//!
//! With continuous intimate contact on `|x| < abar` the adhesionless traction and
//! displacement are linear in the profile, so each wave term of the one-wave model is
//! a sum over waves `j`, each with its own Bessel length `D_j = 2 pi abar/beta_j`:
//!
//! | quantity | term | method |
//! |---|---|---|
//! | strip gap (Eq. 15b) | `sum_j [2 alpha_j sin^2(pi x/beta_j) - ubar_w(x; alpha_j, beta_j)]` | [`WaveBessel::u_fast`] |
//! | load (Eq. 14) | `sum_j (pi^2 alpha_j abar/beta_j) J1(D_j)` | `bessel_j_sequence` |
//! | approach | `sum_j alpha_j (1 - J0(D_j))` | the same |
//! | traction (Eq. 16) | `sum_j (2 pi alpha_j/(beta_j abar)) K_j(x/abar)` | [`WaveBessel::traction_integral`] |
//!
//! Waves of amplitude 0 contribute exactly 0 and are skipped (no Bessel data is built
//! for them). The sums run in the profile's order from `0.0`, so for one wave every
//! value is bit for bit the one-wave model's (`0 + t = t`). The cost of a state is the
//! sum of the waves' costs: each wave's Bessel data has about `D_j/2 + 30` terms.
//!
//! Rounding: each wave term carries the one-wave allowance (`~1e-15 alpha_j D_j` in the
//! gap); [`WaveTerms::gap_allowance`] and [`WaveTerms::traction_allowance`] sum them.

use std::f64::consts::PI;

use crate::contact::displacement::{WaveBessel, MAX_WAVE_D};
use crate::contact::profile::{CosineWave, WavyProfile};
use crate::error::{Error, ProfileError, Result};
use crate::special::bessel_j::bessel_j_sequence;

/// One wave with a nonzero amplitude at one contact size: its Bessel data.
#[derive(Debug, Clone)]
struct WaveAtSize {
    wave: CosineWave,
    bessel: WaveBessel,
    j0: f64,
    j1: f64,
}

/// The waves' terms at contact size `abar`.
/// Every wave with an amplitude resolvable at `abar`: a Bessel length over
/// [`MAX_WAVE_D`] is [`ProfileError::WaveTooFine`] naming the wave.
pub(crate) fn check_bessel_lengths(profile: &WavyProfile, abar: f64) -> Result<()> {
    for (i, wave) in profile.waves().iter().enumerate().filter(|(_, w)| w.alpha() > 0.0) {
        if !(wave.bessel_length(abar) <= MAX_WAVE_D) {
            return Err(Error::Profile(ProfileError::WaveTooFine { wave: i + 1, beta: wave.beta(), abar, max: MAX_WAVE_D }));
        }
    }
    Ok(())
}

#[derive(Debug, Clone)]
pub(crate) struct WaveTerms {
    abar: f64,
    waves: Vec<WaveAtSize>,
}

impl WaveTerms {
    /// Builds each nonzero wave's Bessel data at `abar`. A wave whose Bessel length
    /// exceeds [`MAX_WAVE_D`] is [`ProfileError::WaveTooFine`] naming it, before any
    /// wave's data is built.
    pub(crate) fn new(profile: &WavyProfile, abar: f64) -> Result<WaveTerms> {
        check_bessel_lengths(profile, abar)?;
        let waves = profile
            .active_waves()
            .map(|&wave| {
                let bessel = WaveBessel::new(abar, wave.beta(), wave.alpha())?;
                let js = bessel_j_sequence(1, wave.bessel_length(abar));
                let j0 = js.first().copied().unwrap_or(1.0);
                let j1 = js.get(1).copied().unwrap_or(0.0);
                Ok(WaveAtSize { wave, bessel, j0, j1 })
            })
            .collect::<Result<Vec<_>>>()?;
        Ok(WaveTerms { abar, waves })
    }

    /// `sum_j ubar_w,j(x)`, `x >= abar` (below it read as `abar`).
    pub(crate) fn displacement(&self, x: f64) -> f64 {
        let x = x.max(self.abar);
        self.waves.iter().fold(0.0, |s, w| s + w.bessel.u_fast(x))
    }

    /// The waves' part of the gap, `sum_j [2 alpha_j sin^2(pi x/beta_j) - ubar_w,j(x)]`, `x >= abar`.
    pub(crate) fn gap(&self, x: f64) -> f64 {
        let xa = x.max(self.abar);
        self.waves.iter().fold(0.0, |s, w| s + (w.wave.depth(x) - w.bessel.u_fast(xa)))
    }

    /// The waves' part of the load (Eq. 14), `sum_j (pi^2 alpha_j abar/beta_j) J1(D_j)`.
    pub(crate) fn load(&self) -> f64 {
        let a = self.abar;
        self.waves.iter().fold(0.0, |s, w| s + PI * PI * w.wave.alpha() * a / w.wave.beta() * w.j1)
    }

    /// The waves' part of the approach, `sum_j alpha_j (1 - J0(D_j))`.
    pub(crate) fn approach(&self) -> f64 {
        self.waves.iter().fold(0.0, |s, w| s + w.wave.alpha() * (1.0 - w.j0))
    }

    /// The waves' factor of the traction (Eq. 16) at `c = x/abar`:
    /// `sum_j (2 pi alpha_j/(beta_j abar)) K_j(c)`.
    pub(crate) fn traction(&self, c: f64) -> f64 {
        let a = self.abar;
        self.waves
            .iter()
            .fold(0.0, |s, w| s + 2.0 * PI * w.wave.alpha() / (w.wave.beta() * a) * w.bessel.traction_integral(c))
    }

    /// [`Self::traction`] from the waves' f64 traction sums
    /// ([`WaveBessel::traction_integral_fast`]), for candidate scans.
    pub(crate) fn traction_fast(&self, c: f64) -> f64 {
        let a = self.abar;
        self.waves
            .iter()
            .fold(0.0, |s, w| s + 2.0 * PI * w.wave.alpha() / (w.wave.beta() * a) * w.bessel.traction_integral_fast(c))
    }

    /// Rounding allowance of [`Self::gap`]: `sum_j 1e-13 alpha_j (1 + D_j)`, about 100
    /// times each wave's measured error.
    pub(crate) fn gap_allowance(&self) -> f64 {
        self.waves.iter().fold(0.0, |s, w| s + 1e-13 * w.wave.alpha() * (1.0 + w.wave.bessel_length(self.abar)))
    }

    /// The waves' part of the traction test's rounding allowance:
    /// `sum_j 2 pi alpha_j D_j/(beta_j abar)`.
    pub(crate) fn traction_allowance(&self) -> f64 {
        let a = self.abar;
        self.waves
            .iter()
            .fold(0.0, |s, w| s + 2.0 * PI * w.wave.alpha() * w.wave.bessel_length(a) / (w.wave.beta() * a))
    }
}
