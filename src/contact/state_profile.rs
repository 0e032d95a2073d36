//! The profiles of one state sampled over the symmetric half `xbar >= 0`:
//! traction, substrate displacement, gap and rigid profile depth, as the
//! paper's Figs. 6, 8, 9, 10, 12 and 14 draw them.
//!
//! [`sample_state`] solves the state at contact half-width `abar`
//! ([`ContactSize::solve_strip`]) and samples it on a uniform grid over
//! `[0, xmax]`, with the contact edge `abar` and the strip end `m abar` added
//! when they lie in the range, so that the kinks of the profiles are drawn
//! where they are.

use crate::contact::displacement::profile_depth;
use crate::contact::model::{ContactSize, Params, Validity};
use crate::error::{Error, Result};

/// One sample of a state's profiles (normalised: `x` by `l_h`; `u`, `g`, `h`
/// by `l_v`; the traction by the cohesive stress, tensile positive).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ProfileSample {
    /// Position `xbar >= 0`.
    pub xbar: f64,
    /// Traction `pbar` (Eq. 16 inside the contact, 1 in the strip, 0 beyond).
    pub pbar: f64,
    /// Substrate displacement `ubar` (positive downward, like the profile).
    pub ubar: f64,
    /// Gap `gbar = hbar - ubar` (0 in the contact).
    pub gbar: f64,
    /// Rigid profile depth `hbar` (Eq. 1).
    pub hbar: f64,
}

/// A state and its sampled profiles.
#[derive(Debug, Clone, PartialEq)]
pub struct StateProfile {
    /// The parameters.
    pub params: Params,
    /// Contact half-width.
    pub abar: f64,
    /// Strip ratio `m = c/a`.
    pub m: f64,
    /// Load `Lbar` (Eq. 14).
    pub load: f64,
    /// Validity of the state.
    pub validity: Validity,
    /// The samples, ascending in `xbar`.
    pub samples: Vec<ProfileSample>,
}

impl StateProfile {
    /// The strip end `c = m abar`.
    pub fn strip_end(&self) -> f64 {
        self.m * self.abar
    }
}

/// Solves the state at `abar` and samples its profiles on `points >= 2`
/// uniform positions over `[0, xmax]` (`xmax > 0`; `None`: `1.5 m abar`), plus
/// the contact edge and the strip end where they lie inside. Errors on bad
/// input and where the model has no state.
pub fn sample_state(params: Params, abar: f64, xmax: Option<f64>, points: usize) -> Result<StateProfile> {
    if !(2..=10_000_000).contains(&points) {
        return Err(Error::Domain { what: format!("points must lie in [2, 1e7] (got {points})") });
    }
    let cs = ContactSize::new(params, abar)?;
    let strip = cs.solve_strip()?;
    let m = strip.m();
    let c = m * abar;
    let xmax = xmax.unwrap_or(1.5 * c);
    if !(xmax.is_finite() && xmax > 0.0) {
        return Err(Error::Domain { what: format!("xmax must be finite and > 0 (got {xmax})") });
    }
    let mut xs: Vec<f64> = (0..points).map(|i| xmax * i as f64 / (points - 1) as f64).collect();
    xs.extend([abar, c].into_iter().filter(|&x| x <= xmax));
    xs.sort_by(f64::total_cmp);
    xs.dedup();
    let mut samples = Vec::with_capacity(xs.len());
    for x in xs {
        samples.push(ProfileSample {
            xbar: x,
            pbar: cs.traction_at(strip, x),
            ubar: cs.displacement_at(strip, x)?,
            gbar: cs.gap_at(strip, x)?,
            hbar: profile_depth(1.0, params.alpha, params.beta, x)?,
        });
    }
    Ok(StateProfile { params, abar, m, load: cs.load_at(strip), validity: cs.validity_at(strip)?, samples })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn samples_meet_the_profile_in_the_contact_and_hold_the_edges() {
        let params = Params::new(1.0, std::f64::consts::SQRT_2 / 4.0, 1.125).unwrap();
        let s = sample_state(params, 2.0, None, 50).unwrap();
        assert!(s.samples.iter().any(|p| p.xbar == 2.0));
        assert!(s.samples.iter().any(|p| p.xbar == s.strip_end()));
        assert!(s.samples.windows(2).all(|w| w[0].xbar < w[1].xbar));
        for p in s.samples.iter().filter(|p| p.xbar < 2.0) {
            assert!(p.gbar.abs() < 1e-9 * (1.0 + p.hbar.abs()), "{p:?}");
        }
        for p in s.samples.iter().filter(|p| p.xbar > 2.0 && p.xbar < s.strip_end()) {
            assert_eq!(p.pbar, 1.0);
        }
        assert!(sample_state(params, 2.0, None, 1).is_err());
        assert!(sample_state(params, 2.0, Some(f64::NAN), 10).is_err());
        assert!(sample_state(params, -1.0, None, 10).is_err());
    }
}
