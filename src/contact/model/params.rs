//! The model's parameters: the Maugis parameter `lambda` and the profile (a cylinder
//! carrying any number of cosine waves, [`WavyProfile`]), with their supported ranges.
//!
//! [`Params::new`]`(lambda, alpha, beta)` is the seed paper's one-wave case and keeps its
//! errors ([`crate::Error::NonFinite`], [`crate::Error::OutOfRange`] naming `alpha` or `beta`);
//! [`Params::with_profile`] takes any profile, checked by [`WavyProfile`]'s constructors.

use crate::contact::profile::{WavyProfile, AMPLITUDE_RANGE, WAVELENGTH_RANGE};
use crate::error::{finite, Interval, Result};
#[cfg(feature = "serde")]
use crate::error::Error;
#[cfg(feature = "serde")]
use crate::error::ProfileError;

/// Supported Maugis parameters: beyond these the strip equation over- or
/// underflows in f64 (`lambda^2 abar` terms) or the strip leaves `MAX_STRIP`.
pub const LAMBDA_RANGE: Interval = Interval::closed(1e-6, 1e6);
/// Largest supported `alpha` (of each wave).
pub const ALPHA_MAX: f64 = 1e6;
/// Supported `alpha` of each wave (0 is no wave): [`AMPLITUDE_RANGE`].
pub const ALPHA_RANGE: Interval = AMPLITUDE_RANGE;
/// Supported `beta` of each wave: [`WAVELENGTH_RANGE`].
pub const BETA_RANGE: Interval = WAVELENGTH_RANGE;
/// Largest supported contact size.
pub const ABAR_MAX: f64 = 1e4;
/// Supported contact sizes `abar`.
pub const ABAR_RANGE: Interval = Interval::left_open(0.0, ABAR_MAX);

/// The model parameters: Maugis parameter `lambda` and the profile's waves
/// (amplitudes `alpha_j`, wavelengths `beta_j`).
///
/// The fields are private: a `Params` exists only through [`Params::new`],
/// [`Params::with_profile`] (or deserialization, which runs the same checks), so every
/// `Params` a function receives is inside [`LAMBDA_RANGE`] with every wave inside
/// [`ALPHA_RANGE`] and [`BETA_RANGE`].
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(try_from = "ParamsFields", into = "ParamsFields"))]
pub struct Params {
    pub(crate) lambda: f64,
    pub(crate) profile: WavyProfile,
}

impl Params {
    /// Validated one-wave parameters (the seed paper's profile): each finite and inside
    /// its range, else [`crate::Error::NonFinite`] or [`crate::Error::OutOfRange`] naming it.
    pub fn new(lambda: f64, alpha: f64, beta: f64) -> Result<Params> {
        finite(lambda, "lambda")?;
        finite(alpha, "alpha")?;
        finite(beta, "beta")?;
        LAMBDA_RANGE.check("lambda", lambda)?;
        ALPHA_RANGE.check("alpha", alpha)?;
        BETA_RANGE.check("beta", beta)?;
        Ok(Params { lambda, profile: WavyProfile::one_wave(alpha, beta)? })
    }

    /// `lambda` (finite, in [`LAMBDA_RANGE`]) with any profile.
    pub fn with_profile(lambda: f64, profile: WavyProfile) -> Result<Params> {
        finite(lambda, "lambda")?;
        LAMBDA_RANGE.check("lambda", lambda)?;
        Ok(Params { lambda, profile })
    }

    /// Maugis parameter, `> 0`.
    pub fn lambda(&self) -> f64 {
        self.lambda
    }

    /// The profile: the cylinder and its waves.
    pub fn profile(&self) -> &WavyProfile {
        &self.profile
    }

    /// The first wave's normalised amplitude, `>= 0` (0 for the smooth cylinder).
    /// For a profile of many waves see [`Params::profile`].
    pub fn alpha(&self) -> f64 {
        self.profile.waves().first().map_or(0.0, |w| w.alpha())
    }

    /// The first wave's normalised wavelength, `> 0` (infinite for a profile without a
    /// wave). For a profile of many waves see [`Params::profile`].
    pub fn beta(&self) -> f64 {
        self.profile.waves().first().map_or(f64::INFINITY, |w| w.beta())
    }

    /// The one wave `(alpha, beta)` when the profile has exactly one, else `None`.
    pub fn single_wave(&self) -> Option<(f64, f64)> {
        match self.profile.waves() {
            [w] => Some((w.alpha(), w.beta())),
            _ => None,
        }
    }

    /// The same profile at another Maugis parameter (checked as [`Params::new`]).
    pub fn with_lambda(&self, lambda: f64) -> Result<Params> {
        Params::with_profile(lambda, self.profile)
    }

    /// The smooth cylinder at the same `lambda`: the waves' amplitudes set to 0, their
    /// wavelengths kept (the root scan then samples as finely as for the rough profile;
    /// one wave: `Params::new(lambda, 0, beta)`).
    pub fn smooth(&self) -> Params {
        Params { lambda: self.lambda, profile: self.profile.without_amplitudes() }
    }
}

/// The serialized form of [`Params`]: `{"lambda", "alpha", "beta"}` for one wave (the
/// seed paper's form), `{"lambda", "waves": [{"alpha", "beta"}, ..]}` otherwise; checked
/// by [`Params::new`] or [`Params::with_profile`] on the way in.
#[cfg(feature = "serde")]
#[derive(serde::Serialize, serde::Deserialize)]
struct ParamsFields {
    lambda: f64,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    alpha: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    beta: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    waves: Option<WavyProfile>,
}

#[cfg(feature = "serde")]
impl TryFrom<ParamsFields> for Params {
    type Error = Error;
    fn try_from(f: ParamsFields) -> Result<Params> {
        match (f.alpha, f.beta, f.waves) {
            (Some(alpha), Some(beta), None) => Params::new(f.lambda, alpha, beta),
            (None, None, Some(waves)) => Params::with_profile(f.lambda, waves),
            _ => Err(Error::Profile(ProfileError::ParamsFields)),
        }
    }
}

#[cfg(feature = "serde")]
impl From<Params> for ParamsFields {
    fn from(p: Params) -> ParamsFields {
        match p.single_wave() {
            Some((alpha, beta)) => ParamsFields { lambda: p.lambda, alpha: Some(alpha), beta: Some(beta), waves: None },
            None => ParamsFields { lambda: p.lambda, alpha: None, beta: None, waves: Some(p.profile) },
        }
    }
}
