//! Physical units (SI) for the normalised Maugis model, both ways.
//!
//! # Normalisation (seed Eq. 13a with two length scales, docs/model.md)
//!
//! With the plane-strain modulus `E* = E/(1 - nu^2)` (seed, below Eq. 2), the
//! cylinder radius `R`, the work of adhesion `dgamma` and the Dugdale stress
//! `sigma_0` with range `delta_c = dgamma/sigma_0` (Dugdale-Maugis: the
//! traction `sigma_0` acts while the gap is below `delta_c`):
//!
//! | quantity | scale | SI unit |
//! |---|---|---|
//! | horizontal lengths `a`, `c`, `x`, `zeta` | `l_h = (dgamma R^2/E*)^(1/3)` | m |
//! | vertical lengths `A`, `u`, `g`, `Delta`, `delta_c` | `l_v = (dgamma^2 R/E*^2)^(1/3) = l_h^2/R` | m |
//! | load per unit length `L` | `(E* dgamma^2 R)^(1/3)` | N/m |
//! | traction `p` | `sigma_0 = lambda (E*^2 dgamma/R)^(1/3)` | Pa |
//! | energy per unit length `W` | `L-scale x l_v = dgamma l_h` | J/m |
//!
//! so that `lambda = sigma_0 (R/(E*^2 dgamma))^(1/3) = l_v/delta_c`,
//! `alpha = A/l_v`, `beta = zeta/l_h`, and the Johnson-parameter identity of
//! Eq. 13a, `sqrt(2 dgamma zeta/(pi^2 A^2 E*)) = sqrt(2 beta/(pi^2 alpha^2))`,
//! holds (it fails with the printed single scale; test
//! `johnson_parameter_identity_of_eq_13a`).
//!
//! Every input must be finite and positive (`A >= 0`); a bad value is a typed
//! [`Error`] naming the quantity.

use crate::contact::model::Params;
use crate::contact::profile::WavyProfile;
use crate::error::{finite, Error, Interval, Result};

/// Material and geometry of the contact.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Material {
    /// Plane-strain modulus `E* = E/(1 - nu^2)` (Pa).
    pub e_star: f64,
    /// Cylinder radius `R` (m).
    pub radius: f64,
    /// Work of adhesion `dgamma` (J/m^2).
    pub dgamma: f64,
}

/// The strength of the Dugdale interaction, given either way.
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub enum Cohesion {
    /// The adhesive stress `sigma_0` (Pa).
    Stress(f64),
    /// The interaction range `delta_c = dgamma/sigma_0` (m).
    Range(f64),
}

/// The scales that turn normalised quantities into SI ones.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Scales {
    /// `l_h = (dgamma R^2/E*)^(1/3)` (m): contact sizes, positions, wavelength.
    pub horizontal: f64,
    /// `l_v = (dgamma^2 R/E*^2)^(1/3)` (m): amplitude, displacements, gaps, approach.
    pub vertical: f64,
    /// `(E* dgamma^2 R)^(1/3)` (N/m): load per unit length.
    pub load: f64,
    /// `(E*^2 dgamma/R)^(1/3)` (Pa): `sigma_0 / lambda`.
    pub stress: f64,
    /// `dgamma l_h` (J/m): energy per unit length.
    pub energy: f64,
}

/// `x > 0`; `what` names the quantity with its unit, e.g. `"E* (Pa)"`.
fn positive(x: f64, what: &'static str) -> Result<f64> {
    finite(x, what)?;
    Interval::above(0.0).check(what, x)
}

impl Scales {
    /// The scales of a material. Errors: a non-finite or non-positive input.
    pub fn new(m: Material) -> Result<Scales> {
        let e = positive(m.e_star, "E* (Pa)")?;
        let r = positive(m.radius, "R (m)")?;
        let g = positive(m.dgamma, "dgamma (J/m^2)")?;
        let horizontal = (g * r * r / e).cbrt();
        // l_v = l_h^2/R, written out so that it is accurate on its own
        let vertical = (g * g * r / (e * e)).cbrt();
        let load = (e * g * g * r).cbrt();
        let stress = (e * e * g / r).cbrt();
        let s = Scales { horizontal, vertical, load, stress, energy: g * horizontal };
        for (v, what) in [(horizontal, "l_h"), (vertical, "l_v"), (load, "the load scale"), (stress, "the stress scale")] {
            if !(v.is_finite() && v > 0.0) {
                return Err(Error::ScaleNotRepresentable { scale: what, e_star: e, radius: r, dgamma: g });
            }
        }
        Ok(s)
    }

    /// `lambda` of an adhesive stress `sigma_0` (Pa) or range `delta_c` (m).
    pub fn lambda(&self, c: Cohesion) -> Result<f64> {
        match c {
            Cohesion::Stress(s) => Ok(positive(s, "sigma_0 (Pa)")? / self.stress),
            Cohesion::Range(d) => Ok(self.vertical / positive(d, "delta_c (m)")?),
        }
    }

    /// The adhesive stress `sigma_0` (Pa) of a Maugis parameter.
    pub fn sigma(&self, lambda: f64) -> f64 {
        lambda * self.stress
    }

    /// The interaction range `delta_c` (m) of a Maugis parameter.
    pub fn delta_c(&self, lambda: f64) -> f64 {
        self.vertical / lambda
    }

    /// `alpha` of a wave amplitude `A >= 0` (m).
    pub fn alpha(&self, amplitude: f64) -> Result<f64> {
        finite(amplitude, "A")?;
        if amplitude < 0.0 {
            return Err(Error::OutOfRange { arg: "A (m)", value: amplitude, allowed: Interval::at_least(0.0) });
        }
        Ok(amplitude / self.vertical)
    }

    /// `beta` of a wavelength `zeta > 0` (m).
    pub fn beta(&self, wavelength: f64) -> Result<f64> {
        Ok(positive(wavelength, "zeta (m)")? / self.horizontal)
    }

    /// A horizontal length (m) of its normalised value (`a`, `c`, `x`, `zeta`).
    pub fn to_horizontal(&self, bar: f64) -> f64 {
        bar * self.horizontal
    }

    /// A vertical length (m) of its normalised value (`A`, `u`, `g`, `Delta`).
    pub fn to_vertical(&self, bar: f64) -> f64 {
        bar * self.vertical
    }

    /// A load per unit length (N/m) of `Lbar`.
    pub fn to_load(&self, bar: f64) -> f64 {
        bar * self.load
    }

    /// An energy per unit length (J/m) of its normalised value (`W`).
    pub fn to_energy(&self, bar: f64) -> f64 {
        bar * self.energy
    }

    /// A traction (Pa) of `pbar` at Maugis parameter `lambda` (`p = pbar sigma_0`).
    pub fn to_traction(&self, bar: f64, lambda: f64) -> f64 {
        bar * self.sigma(lambda)
    }

    /// `abar` of a contact half-width `a` (m).
    pub fn from_horizontal(&self, a: f64) -> f64 {
        a / self.horizontal
    }

    /// `Lbar` of a load per unit length (N/m).
    pub fn from_load(&self, l: f64) -> f64 {
        l / self.load
    }
}

/// A contact in SI: material, cohesion and wave profile.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Physical {
    /// Material and geometry.
    pub material: Material,
    /// Dugdale stress or range.
    pub cohesion: Cohesion,
    /// Wave amplitude `A >= 0` (m).
    pub amplitude: f64,
    /// Wavelength `zeta > 0` (m).
    pub wavelength: f64,
}

impl Physical {
    /// The scales.
    pub fn scales(&self) -> Result<Scales> {
        Scales::new(self.material)
    }

    /// The model's `(lambda, alpha, beta)`, checked by [`Params::new`].
    pub fn params(&self) -> Result<Params> {
        let s = self.scales()?;
        Params::new(s.lambda(self.cohesion)?, s.alpha(self.amplitude)?, s.beta(self.wavelength)?)
    }
}

impl Scales {
    /// A profile of many waves given in metres: `(A_j, zeta_j)` pairs, each turned into
    /// `(alpha_j, beta_j) = (A_j/l_v, zeta_j/l_h)` and checked by
    /// [`WavyProfile::from_pairs`] (the error names the wave and the field).
    pub fn profile_from_si(&self, waves_m: &[(f64, f64)]) -> Result<WavyProfile> {
        let pairs: Vec<(f64, f64)> = waves_m.iter().map(|&(a, z)| (a / self.vertical, z / self.horizontal)).collect();
        WavyProfile::from_pairs(&pairs)
    }

    /// The waves of a profile in metres, `(A_j, zeta_j)`.
    pub fn profile_to_si(&self, profile: &WavyProfile) -> Vec<(f64, f64)> {
        profile.waves().iter().map(|w| (self.to_vertical(w.alpha()), self.to_horizontal(w.beta()))).collect()
    }
}

/// The SI contact of normalised parameters: `sigma_0` (Pa), `A` (m) and `zeta` (m)
/// (the first wave's, for a profile of many waves: see [`Scales::profile_to_si`]).
pub fn physical_of(params: Params, material: Material) -> Result<Physical> {
    let s = Scales::new(material)?;
    Ok(Physical {
        material,
        cohesion: Cohesion::Stress(s.sigma(params.lambda)),
        amplitude: s.to_vertical(params.alpha()),
        wavelength: s.to_horizontal(params.beta()),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// PDMS-like: E* = 2 MPa, R = 1 mm, dgamma = 0.05 J/m^2.
    const PDMS: Material = Material { e_star: 2e6, radius: 1e-3, dgamma: 0.05 };

    #[test]
    fn scales_follow_the_two_scale_normalisation() {
        let s = Scales::new(PDMS).unwrap();
        let (e, r, g) = (PDMS.e_star, PDMS.radius, PDMS.dgamma);
        assert!((s.horizontal.powi(3) / (g * r * r / e) - 1.0).abs() < 1e-14);
        assert!((s.vertical / (s.horizontal * s.horizontal / r) - 1.0).abs() < 1e-14);
        // load x vertical = energy, sigma_0 delta_c = dgamma
        assert!((s.load * s.vertical / s.energy - 1.0).abs() < 1e-14);
        let lambda = 0.7;
        assert!((s.sigma(lambda) * s.delta_c(lambda) / g - 1.0).abs() < 1e-14);
        // the stress scale is E* l_v/l_h
        assert!((s.stress / (e * s.vertical / s.horizontal) - 1.0).abs() < 1e-14);
    }

    /// The normalised Hertz load `pi abar^2/4` and Dugdale strip load
    /// `-2 lambda abar sqrt(m^2 - 1)` of Eq. 14 are the dimensional
    /// `pi E* a^2/(4 R)` and `-2 sigma_0 sqrt(c^2 - a^2)` (seed A.3b).
    #[test]
    fn dimensional_hertz_and_strip_loads() {
        let s = Scales::new(PDMS).unwrap();
        let (abar, m, lambda) = (2.3, 1.4, 0.8);
        let (a, c) = (s.to_horizontal(abar), s.to_horizontal(m * abar));
        let hertz = std::f64::consts::PI * PDMS.e_star * a * a / (4.0 * PDMS.radius);
        assert!((s.to_load(std::f64::consts::PI * abar * abar / 4.0) / hertz - 1.0).abs() < 1e-14);
        let strip = -2.0 * s.sigma(lambda) * (c * c - a * a).sqrt();
        assert!((s.to_load(-2.0 * lambda * abar * (m * m - 1.0).sqrt()) / strip - 1.0).abs() < 1e-14);
        // the gap at the strip end is delta_c: lambda gbar(c) = 1
        assert!((s.to_vertical(1.0 / lambda) / s.delta_c(lambda) - 1.0).abs() < 1e-14);
    }

    #[test]
    fn johnson_parameter_identity_of_eq_13a() {
        let p = Physical { material: PDMS, cohesion: Cohesion::Stress(1e5), amplitude: 2e-6, wavelength: 5e-5 };
        let q = p.params().unwrap();
        let lhs = (2.0 * PDMS.dgamma * p.wavelength / (std::f64::consts::PI.powi(2) * p.amplitude.powi(2) * PDMS.e_star)).sqrt();
        let rhs = (2.0 * q.beta() / (std::f64::consts::PI.powi(2) * q.alpha().powi(2))).sqrt();
        assert!((lhs / rhs - 1.0).abs() < 1e-13, "{lhs} vs {rhs}");
    }

    #[test]
    fn round_trip_and_both_cohesions() {
        let params = Params::new(1.5, 2f64.sqrt() / 4.0, 1.125).unwrap();
        let p = physical_of(params, PDMS).unwrap();
        let back = p.params().unwrap();
        for (a, b) in [(back.lambda, 1.5), (back.alpha(), 2f64.sqrt() / 4.0), (back.beta(), 1.125)] {
            assert!((a / b - 1.0).abs() < 1e-14, "{a} vs {b}");
        }
        let s = p.scales().unwrap();
        let by_range = Physical { cohesion: Cohesion::Range(s.delta_c(1.5)), ..p }.params().unwrap();
        assert!((by_range.lambda / 1.5 - 1.0).abs() < 1e-14);
        assert!((s.from_horizontal(s.to_horizontal(2.5)) - 2.5).abs() < 1e-15);
        assert!((s.from_load(s.to_load(-1.7)) + 1.7).abs() < 1e-15);
    }

    #[test]
    fn bad_inputs_are_typed_errors_naming_the_quantity() {
        let bad = [
            Material { e_star: 0.0, ..PDMS },
            Material { radius: -1.0, ..PDMS },
            Material { dgamma: f64::NAN, ..PDMS },
            Material { e_star: f64::INFINITY, ..PDMS },
        ];
        for (m, name) in bad.iter().zip(["E*", "R", "dgamma", "E*"]) {
            let e = Scales::new(*m).unwrap_err().to_string();
            assert!(e.contains(name), "{e}");
        }
        let s = Scales::new(PDMS).unwrap();
        assert!(s.lambda(Cohesion::Stress(0.0)).unwrap_err().to_string().contains("sigma_0"));
        assert!(s.lambda(Cohesion::Range(-1e-9)).unwrap_err().to_string().contains("delta_c"));
        assert!(s.alpha(-1e-6).unwrap_err().to_string().contains('A'));
        assert!(s.beta(0.0).unwrap_err().to_string().contains("zeta"));
        // out of the model's range: Params::new refuses
        let huge = Physical { material: PDMS, cohesion: Cohesion::Stress(1e30), amplitude: 0.0, wavelength: 1.0 };
        assert!(huge.params().is_err());
    }
}
