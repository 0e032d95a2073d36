//! The seed paper's named parameter sets, defined once for every front end.
//!
//! The paper draws three roughnesses (normalised amplitude `alpha` and
//! wavelength `beta`, docs/model.md) and the smooth cylinder:
//!
//! | name | `{alpha, beta}` | where |
//! |---|---|---|
//! | [`FIG_4A`] | `{2 sqrt(2)/8, 2}` | Fig. 4a (and the text of Fig. 4d) |
//! | [`FIG_4B`] | `{sqrt(2)/3, 2}` | Figs. 2, 4b and 11-14 |
//! | [`FIG_4C`] | `{2 sqrt(2)/8, 9/8}` | Figs. 4c and 5-10, 13-14; the main job (`maugis curve`) |
//! | [`SMOOTH`] | `{0, -}` | Fig. 3 (`beta` plays no role when `alpha = 0`) |
//!
//! [`MAIN_LAMBDAS`] are the Maugis parameters of the main job.

use super::model::Params;
use crate::error::Result;

/// A roughness: the normalised wave amplitude and wavelength, with the paper's name for it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Roughness {
    /// Normalised amplitude `alpha`.
    pub alpha: f64,
    /// Normalised wavelength `beta`.
    pub beta: f64,
    /// How the paper writes it, e.g. `"{2√2/8, 9/8}"`.
    pub label: &'static str,
}

impl Roughness {
    /// The model parameters at Maugis parameter `lambda` (checked by [`Params::new`]).
    pub fn params(&self, lambda: f64) -> Result<Params> {
        Params::new(lambda, self.alpha, self.beta)
    }

    /// `(alpha, beta)`.
    pub fn pair(&self) -> (f64, f64) {
        (self.alpha, self.beta)
    }
}

/// Fig. 4a: `{2 sqrt(2)/8, 2}`.
pub const FIG_4A: Roughness = Roughness { alpha: std::f64::consts::SQRT_2 / 4.0, beta: 2.0, label: "{2√2/8, 2}" };
/// Fig. 4b (and Figs. 2, 11-14): `{sqrt(2)/3, 2}`.
pub const FIG_4B: Roughness = Roughness { alpha: std::f64::consts::SQRT_2 / 3.0, beta: 2.0, label: "{√2/3, 2}" };
/// Fig. 4c (and Figs. 5-10, 13-14, the main job): `{2 sqrt(2)/8, 9/8}`.
pub const FIG_4C: Roughness = Roughness { alpha: std::f64::consts::SQRT_2 / 4.0, beta: 1.125, label: "{2√2/8, 9/8}" };
/// Fig. 3: the smooth cylinder.
pub const SMOOTH: Roughness = Roughness { alpha: 0.0, beta: 1.0, label: "{0, −}" };

/// The paper's named roughnesses, in figure order.
pub const ROUGHNESSES: [Roughness; 4] = [SMOOTH, FIG_4A, FIG_4B, FIG_4C];

/// The Maugis parameters of the main job (`maugis curve`, Fig. 4c roughness).
pub const MAIN_LAMBDAS: [f64; 7] = [0.1, 0.25, 0.5, 1.0, 1.5, 3.0, 6.0];

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_named_sets_are_the_papers_and_valid() {
        // 2 sqrt(2)/8 and sqrt(2)/3 as the paper writes them, to the last bit
        assert_eq!(FIG_4C.alpha, 2.0 * 2f64.sqrt() / 8.0);
        assert_eq!(FIG_4B.alpha, 2f64.sqrt() / 3.0);
        assert_eq!(FIG_4C.beta, 9.0 / 8.0);
        for r in ROUGHNESSES {
            for l in MAIN_LAMBDAS {
                assert!(r.params(l).is_ok(), "{r:?} at lambda = {l}");
            }
        }
    }
}
