//! The rigid profile `h(x)` (depth below its lowest point, normalised by `l_v`)
//! and the adhesion law.

use std::f64::consts::PI;

use maugis::contact::model::{ALPHA_RANGE, BETA_RANGE};

use crate::error::{finite, in_range, Interval, Result, SolverError};
use crate::grid::Grid;
use crate::profile_file::ProfileTable;

/// The indenter's profile.
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub enum Profile {
    /// The paper's wavy cylinder (Eq. 1, normalised):
    /// `h(x) = x^2/2 + alpha (1 - cos(2 pi x/beta))`; `alpha = 0` is the smooth cylinder.
    WavyCylinder {
        /// Wave amplitude `alpha = A/l_v >= 0`.
        alpha: f64,
        /// Wavelength `beta = zeta/l_h > 0`.
        beta: f64,
    },
    /// The wave alone, `h(x) = alpha (1 - cos(2 pi x/beta))`: one period of a
    /// sinusoidal surface (for the periodic domain).
    Sinusoid {
        /// Wave amplitude `alpha > 0`.
        alpha: f64,
        /// Wavelength `beta > 0`.
        beta: f64,
    },
    /// Any profile, sampled at the cell centres of the grid it is used with.
    Sampled(Vec<f64>),
    /// A profile table (`x,h` rows, [`crate::profile_file`]), interpolated by
    /// cubic Hermite pieces; it must cover the grid's domain.
    Table(ProfileTable),
}

impl Profile {
    /// The wavy cylinder, checked.
    pub fn wavy_cylinder(alpha: f64, beta: f64) -> Result<Profile> {
        finite(alpha, "alpha")?;
        finite(beta, "beta")?;
        // The model's ranges: a subnormal beta made 2 pi x/beta overflow and the
        // sampled profile NaN (found by tests/it/fuzz.rs).
        in_range(alpha, "alpha", ALPHA_RANGE)?;
        in_range(beta, "beta", BETA_RANGE)?;
        Ok(Profile::WavyCylinder { alpha, beta })
    }

    /// The sinusoid, checked (`alpha > 0`: a flat surface has no contact to
    /// follow).
    pub fn sinusoid(alpha: f64, beta: f64) -> Result<Profile> {
        match Profile::wavy_cylinder(alpha, beta)? {
            _ if alpha == 0.0 => Err(SolverError::OutOfRange { arg: "alpha (the sinusoid needs a wave)", value: alpha, allowed: Interval::above(0.0) }),
            _ => Ok(Profile::Sinusoid { alpha, beta }),
        }
    }

    /// The depth at any `x` of the grid's domain: exact for the wavy cylinder,
    /// linear between the cell centres for a sampled profile (`samples` is
    /// [`Profile::sample`] on the same grid).
    pub fn depth_at(&self, x: f64, grid: &Grid, samples: &[f64]) -> f64 {
        match self {
            Profile::WavyCylinder { alpha, beta } => 0.5 * x * x + alpha * (1.0 - (2.0 * PI * x / beta).cos()),
            Profile::Sinusoid { alpha, beta } => alpha * (1.0 - (2.0 * PI * x / beta).cos()),
            Profile::Table(t) => t.depth_at(x),
            Profile::Sampled(_) => {
                let n = samples.len();
                let u = ((x - grid.x(0)) / grid.dx()).clamp(0.0, (n - 1) as f64);
                let j = (u.floor() as usize).min(n - 2);
                let t = u - j as f64;
                samples[j] * (1.0 - t) + samples[j + 1] * t
            }
        }
    }

    /// The depth at every cell centre of `grid`. Errors: a sampled profile
    /// of another length or with a non-finite value, a table that does not
    /// cover the grid's domain.
    pub fn sample(&self, grid: &Grid) -> Result<Vec<f64>> {
        match self {
            Profile::WavyCylinder { alpha, beta } => Ok(grid
                .centres()
                .into_iter()
                .map(|x| 0.5 * x * x + alpha * (1.0 - (2.0 * PI * x / beta).cos()))
                .collect()),
            Profile::Sampled(h) => {
                if h.len() != grid.cells() {
                    return Err(SolverError::LengthMismatch { arg: "the sampled profile", found: h.len(), expected: grid.cells() });
                }
                for &v in h {
                    finite(v, "every profile value")?;
                }
                Ok(h.clone())
            }
            Profile::Sinusoid { .. } => Ok(grid.centres().into_iter().map(|x| self.depth_at(x, grid, &[])).collect()),
            Profile::Table(t) => {
                t.check_covers(grid.half_width())?;
                Ok(grid.centres().into_iter().map(|x| t.depth_at(x)).collect())
            }
        }
    }
}

/// The interface law: none (Hertz), or an [`AdhesionLaw`] at a Maugis parameter
/// `lambda` in [`LAMBDA_RANGE`]. The fields are private: an `Adhesion` exists only
/// through [`Adhesion::NONE`], [`Adhesion::dugdale`], [`Adhesion::exponential`]
/// or [`AdhesionLaw::at`], which check `lambda`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Adhesion {
    /// `None`: frictionless, non-adhesive contact (Hertz).
    law: Option<AdhesionLaw>,
    /// The Maugis parameter (`0` without adhesion).
    lambda: f64,
}

/// The adhesion law's name, as the front ends select it.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Hash)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
#[non_exhaustive]
pub enum AdhesionLaw {
    /// Dugdale-Maugis: tensile traction `sigma0 = lambda` (units
    /// `(E*^2 dgamma/R)^(1/3)`) where `0 < g < delta_c = 1/lambda` (units `l_v`),
    /// zero beyond; work of adhesion `sigma0 delta_c = 1` (units `dgamma`). The
    /// paper's law; the default.
    #[default]
    Dugdale,
    /// A smooth law: a hard wall (`g >= 0`) and the tensile traction
    /// `sigma(g) = sigma0 exp(-g/rho)` for `g >= 0`, with `sigma0 = lambda`
    /// and `rho = 1/lambda`. Matched to Dugdale of the same `lambda` as
    /// Maugis (1992) and Johnson and Greenwood (1997) match the Lennard-Jones
    /// law: the same peak stress `sigma0` and the same work of adhesion
    /// `int sigma dg = sigma0 rho = 1`, hence the same range
    /// `w/sigma0 = delta_c`; its equivalent Maugis parameter is `lambda`
    /// itself (`docs/solver.md`).
    Exponential,
}

impl AdhesionLaw {
    /// Every law, in the order the front ends list them.
    pub const ALL: [AdhesionLaw; 2] = [AdhesionLaw::Dugdale, AdhesionLaw::Exponential];

    /// `"dugdale"` or `"exp"`.
    pub fn name(self) -> &'static str {
        match self {
            AdhesionLaw::Dugdale => "dugdale",
            AdhesionLaw::Exponential => "exp",
        }
    }

    /// The law named `name` (`"dugdale"`, `"exp"`); errors:
    /// [`SolverError::UnknownLaw`].
    pub fn from_name(name: &str) -> Result<AdhesionLaw> {
        AdhesionLaw::ALL.into_iter().find(|l| l.name() == name).ok_or_else(|| SolverError::UnknownLaw {
            name: name.to_string(),
            known: AdhesionLaw::ALL.map(AdhesionLaw::name).to_vec(),
        })
    }

    /// The law at Maugis parameter `lambda`, checked.
    pub fn at(self, lambda: f64) -> Result<Adhesion> {
        match self {
            AdhesionLaw::Dugdale => Adhesion::dugdale(lambda),
            AdhesionLaw::Exponential => Adhesion::exponential(lambda),
        }
    }
}

/// The Maugis parameters the solver's adhesion laws accept (narrower than the
/// model's [`maugis::contact::model::LAMBDA_RANGE`]: beyond it the zone or the
/// decay length is not resolved by any supported grid).
pub const LAMBDA_RANGE: Interval = Interval::closed(1e-4, 1e4);

impl Adhesion {
    /// Frictionless, non-adhesive contact (Hertz).
    pub const NONE: Adhesion = Adhesion { law: None, lambda: 0.0 };

    /// `law` at Maugis parameter `lambda`, checked: finite and in [`LAMBDA_RANGE`].
    fn checked(law: AdhesionLaw, lambda: f64) -> Result<Adhesion> {
        finite(lambda, "lambda")?;
        in_range(lambda, "lambda", LAMBDA_RANGE)?;
        Ok(Adhesion { law: Some(law), lambda })
    }

    /// Dugdale-Maugis ([`AdhesionLaw::Dugdale`]) with Maugis parameter `lambda`, checked.
    pub fn dugdale(lambda: f64) -> Result<Adhesion> {
        Adhesion::checked(AdhesionLaw::Dugdale, lambda)
    }

    /// The exponential law ([`AdhesionLaw::Exponential`]) with Maugis parameter
    /// `lambda`, checked (the range of [`Adhesion::dugdale`]).
    pub fn exponential(lambda: f64) -> Result<Adhesion> {
        Adhesion::checked(AdhesionLaw::Exponential, lambda)
    }

    /// The law; `None` without adhesion.
    pub fn law(&self) -> Option<AdhesionLaw> {
        self.law
    }

    /// The Maugis parameter; `None` without adhesion.
    pub fn lambda(&self) -> Option<f64> {
        self.law.map(|_| self.lambda)
    }

    /// How far out of contact a cycle starts, in `l_v`: the range `delta_c`
    /// for Dugdale (no traction beyond it); `4 rho` for the exponential law
    /// (traction below `e^-4 = 1.8 %` of its peak).
    pub fn start_distance(&self) -> f64 {
        match self.law {
            None => 0.0,
            Some(AdhesionLaw::Dugdale) => 1.0 / self.lambda,
            Some(AdhesionLaw::Exponential) => 4.0 / self.lambda,
        }
    }

    /// `(sigma0, delta_c)`; `(0, 0)` without adhesion.
    pub fn strength_and_range(&self) -> (f64, f64) {
        match self.law {
            None => (0.0, 0.0),
            Some(_) => (self.lambda, 1.0 / self.lambda),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn adhesion_is_built_only_checked() {
        assert_eq!((Adhesion::NONE.law(), Adhesion::NONE.lambda()), (None, None));
        assert_eq!(Adhesion::NONE.strength_and_range(), (0.0, 0.0));
        let d = Adhesion::dugdale(2.0).unwrap();
        assert_eq!((d.law(), d.lambda()), (Some(AdhesionLaw::Dugdale), Some(2.0)));
        assert_eq!((d.start_distance(), d.strength_and_range()), (0.5, (2.0, 0.5)));
        let e = AdhesionLaw::Exponential.at(2.0).unwrap();
        assert_eq!((e.law(), e.lambda(), e.start_distance()), (Some(AdhesionLaw::Exponential), Some(2.0), 2.0));
        for law in AdhesionLaw::ALL {
            assert!(matches!(law.at(f64::NAN), Err(SolverError::NonFinite { arg: "lambda", .. })));
            for bad in [0.0, -1.0, 2e4] {
                assert!(matches!(law.at(bad), Err(SolverError::OutOfRange { arg: "lambda", allowed, .. }) if allowed == LAMBDA_RANGE));
            }
        }
    }
}
