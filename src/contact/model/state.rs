//! The model at one contact size `abar` ([`ContactSize`]): the strip residual of the
//! corrected Eq. 15b, the load (Eq. 14), the approach, the traction (Eq. 16), the
//! displacement and the gap, for a profile of any number of waves (the waves' sums in
//! `model/waves.rs`). The formulas are in the module docs of [`crate::contact::model`];
//! the first root of the strip equation is in [`super::solve`], the validity checks in
//! [`super::validity`].

use std::f64::consts::PI;

use super::params::{Params, ABAR_RANGE};
use super::strip::{acosh_1p, adhesive_approach_fn, adhesive_gap_fn, hertz_gap_fn, sqrt_z2z, ScaledStrip, StripEnd, SCALED_Z};
use super::waves::WaveTerms;
use crate::contact::displacement::{u_adhesive, u_hertz};
use crate::error::{finite, Error, Interval, Result};

/// The model at one contact size `abar` (the Bessel data of the wave term are
/// computed once here).
#[derive(Debug, Clone)]
pub struct ContactSize {
    pub(super) params: Params,
    pub(super) abar: f64,
    pub(super) waves: WaveTerms,
}

pub(super) fn check_m(m: f64) -> Result<StripEnd> {
    StripEnd::from_m(m)
}

fn check_x(x: f64) -> Result<f64> {
    finite(x, "x")
}

impl ContactSize {
    /// Prepares contact size `abar > 0`.
    pub fn new(params: Params, abar: f64) -> Result<ContactSize> {
        finite(abar, "abar")?;
        ABAR_RANGE.check("abar", abar)?;
        let waves = WaveTerms::new(&params.profile, abar)?;
        Ok(ContactSize { params, abar, waves })
    }

    /// The contact size.
    pub fn abar(&self) -> f64 {
        self.abar
    }

    /// The parameters.
    pub fn params(&self) -> Params {
        self.params
    }

    /// `ubar_w(x)` for `x >= abar` (`x` below `abar` is read as `abar`).
    pub fn wave_displacement(&self, x: f64) -> Result<f64> {
        check_x(x)?;
        Ok(self.wave_displacement_unchecked(x))
    }

    fn wave_displacement_unchecked(&self, x: f64) -> f64 {
        self.waves.displacement(x)
    }

    /// The waves' part of the gap, `sum_j [2 alpha_j sin^2(pi x/beta_j) - ubar_w,j(x)]`, `x >= abar`.
    fn wave_gap(&self, x: f64) -> f64 {
        self.waves.gap(x)
    }

    /// The three gap contributions at `c = m abar`, `m = 1 + z` with `z >= 0`:
    /// (Hertz, adhesive, wave), units of `l_v`. From `z = `[`SCALED_Z`] on in the strip
    /// width ([`ScaledStrip`]: finite wherever the strip width is).
    fn strip_terms(&self, z: f64) -> (f64, f64, f64) {
        let (a, lambda) = (self.abar, self.params.lambda);
        let c = a + a * z;
        if z >= SCALED_Z {
            let scaled = ScaledStrip::new(a, z);
            return (0.5 * scaled.hertz_gap(), 4.0 / PI * lambda * scaled.adhesive_gap(), self.wave_gap(c));
        }
        let hertz = 0.5 * a * a * hertz_gap_fn(z);
        let adhesive = 4.0 / PI * lambda * a * adhesive_gap_fn(z);
        (hertz, adhesive, self.wave_gap(c))
    }

    /// `abar sqrt(m^2 - 1)` at the strip end (finite wherever the strip width is).
    fn a_sqrt_m2_minus_1(&self, strip: StripEnd) -> f64 {
        let z = strip.m_minus_1();
        if z >= SCALED_Z {
            ScaledStrip::new(self.abar, z).a_sqrt_m2_minus_1()
        } else {
            self.abar * strip.sqrt_m2_minus_1()
        }
    }

    /// The three gap contributions at `c = m abar` (`m >= 1`): (Hertz, adhesive, wave).
    pub fn strip_gap_terms(&self, m: f64) -> Result<(f64, f64, f64)> {
        finite(m, "m")?;
        Interval::at_least(1.0).check("the strip ratio m = c/a", m)?;
        Ok(self.strip_terms(m - 1.0))
    }

    pub(super) fn residual_z(&self, z: f64) -> f64 {
        let (h, ad, w) = self.strip_terms(z);
        self.params.lambda * (h + ad + w) - 1.0
    }

    /// `F(m) = lambda gbar(m abar) - 1` (Eq. 15b, corrected), `m >= 1`.
    pub fn strip_residual(&self, m: f64) -> Result<f64> {
        finite(m, "m")?;
        Interval::at_least(1.0).check("the strip ratio m = c/a", m)?;
        Ok(self.residual_z(m - 1.0))
    }

    /// `F` as a function of `z = m - 1 >= 0` (full relative accuracy in `z`).
    pub fn strip_residual_m_minus_1(&self, z: f64) -> Result<f64> {
        finite(z, "m - 1")?;
        Interval::at_least(0.0).check("m - 1", z)?;
        Ok(self.residual_z(z))
    }

    /// Eq. 14 at the strip end `m` (`m > 1`).
    pub fn load(&self, m: f64) -> Result<f64> {
        let load = self.load_at(check_m(m)?);
        if load.is_finite() {
            Ok(load)
        } else {
            Err(Error::NotRepresentable { quantity: "load", abar: self.abar })
        }
    }

    /// Eq. 14: `pi abar^2/4 - 2 lambda abar sqrt(m^2-1) + sum_j (pi^2 alpha_j abar/beta_j) J1(2 pi abar/beta_j)`.
    pub fn load_at(&self, strip: StripEnd) -> f64 {
        let (a, lambda) = (self.abar, self.params.lambda);
        let adhesive = if strip.m_minus_1() >= SCALED_Z {
            2.0 * lambda * self.a_sqrt_m2_minus_1(strip)
        } else {
            2.0 * lambda * a * strip.sqrt_m2_minus_1()
        };
        PI * a * a / 4.0 - adhesive + self.waves.load()
    }

    /// The approach `Delta-bar` (units of `l_v`) measured from a datum at
    /// infinity with the logarithmic term removed:
    /// `Delta = lim_{x -> inf} [ubar(x) - (2 Lbar/pi) ln x]`.
    ///
    /// In plane strain the surface displacement grows like `(2 Lbar/pi) ln x`, so
    /// an approach exists only relative to a datum; any other datum shifts
    /// `Delta` by `k Lbar` and leaves `int Delta dLbar` over a closed cycle
    /// unchanged. From the large-`x` forms of Eq. 10, the Bessel form of `u_w`
    /// (docs/displacement.md, Route 2, `acosh(x/a) -> ln(2x/a)`, `q -> 0`) and A.5b:
    ///
    /// ```text
    /// Delta = (2 Lbar/pi) ln(2/abar) + abar^2/4 + sum_j alpha_j (1 - J0(D_j))
    ///       + (4 lambda abar/pi) (m acosh(m) - sqrt(m^2-1)),   D_j = 2 pi abar/beta_j.
    /// ```
    pub fn approach_at(&self, strip: StripEnd) -> f64 {
        self.approach_from_load(strip, self.load_at(strip))
    }

    /// The load ([`Self::load_at`]) and the approach ([`Self::approach_at`]) at a solved
    /// strip end, the load computed once.
    pub fn load_and_approach_at(&self, strip: StripEnd) -> (f64, f64) {
        let load = self.load_at(strip);
        (load, self.approach_from_load(strip, load))
    }

    /// [`Self::approach_at`] given the load there.
    fn approach_from_load(&self, strip: StripEnd, load: f64) -> f64 {
        let (a, lambda) = (self.abar, self.params.lambda);
        let z = strip.m_minus_1();
        let adhesive = if z >= SCALED_Z {
            4.0 * lambda / PI * ScaledStrip::new(a, z).adhesive_approach()
        } else {
            4.0 * lambda * a / PI * adhesive_approach_fn(z)
        };
        2.0 * load / PI * (2.0 / a).ln() + a * a / 4.0 + self.waves.approach() + adhesive
    }

    /// [`Self::approach_at`] for `m > 1`.
    pub fn approach(&self, m: f64) -> Result<f64> {
        Ok(self.approach_at(check_m(m)?))
    }

    /// `pbar(x)`: Eq. 16 inside the contact, 1 in the strip, 0 outside (`m > 1`).
    pub fn traction(&self, m: f64, x: f64) -> Result<f64> {
        Ok(self.traction_at(check_m(m)?, check_x(x)?))
    }

    /// [`Self::traction`] at a solved strip end.
    pub fn traction_at(&self, strip: StripEnd, x: f64) -> f64 {
        let (a, lambda) = (self.abar, self.params.lambda);
        let ax = x.abs();
        if ax >= a {
            let z = strip.m_minus_1();
            return if ax - a <= a * z { 1.0 } else { 0.0 };
        }
        let w = ((a - ax) * (a + ax)).sqrt();
        let adhesive = 2.0 / PI * (self.a_sqrt_m2_minus_1(strip) / w).atan();
        adhesive - w / (2.0 * lambda) * (1.0 + self.waves.traction(ax / a))
    }

    /// [`Self::traction_at`] with the waves' f64 traction sums (a few ulps of the
    /// largest term instead of one rounding each), for the validity rescan's samples.
    pub(super) fn traction_fast_at(&self, strip: StripEnd, x: f64) -> f64 {
        let (a, lambda) = (self.abar, self.params.lambda);
        let ax = x.abs();
        if ax >= a {
            return self.traction_at(strip, x);
        }
        let w = ((a - ax) * (a + ax)).sqrt();
        let adhesive = 2.0 / PI * (self.a_sqrt_m2_minus_1(strip) / w).atan();
        adhesive - w / (2.0 * lambda) * (1.0 + self.waves.traction_fast(ax / a))
    }

    /// The total displacement `ubar(x)`: the profile inside the contact, the sum
    /// of the Hertz, wave and adhesive displacements outside (`m > 1`).
    pub fn displacement(&self, m: f64, x: f64) -> Result<f64> {
        self.displacement_at(check_m(m)?, check_x(x)?)
    }

    /// [`Self::displacement`] at a solved strip end.
    pub fn displacement_at(&self, strip: StripEnd, x: f64) -> Result<f64> {
        let ax = check_x(x)?.abs();
        let lambda = self.params.lambda;
        if ax <= self.abar {
            return Ok(self.params.profile.depth(ax));
        }
        let uh = u_hertz(self.abar, 1.0, ax)?;
        let c = self.abar + self.abar * strip.m_minus_1();
        let ua = u_adhesive(self.abar, c, lambda, 1.0, ax)?;
        Ok(uh + self.wave_displacement_unchecked(ax) + ua)
    }

    /// The gap `gbar(x) = hbar - ubar` (zero inside the contact, `m > 1`).
    pub fn gap(&self, m: f64, x: f64) -> Result<f64> {
        self.gap_at(check_m(m)?, check_x(x)?)
    }

    /// [`Self::gap`] at a solved strip end. Inside the strip it is
    /// [`Self::strip_gap`] (well conditioned as the strip closes).
    pub fn gap_at(&self, strip: StripEnd, x: f64) -> Result<f64> {
        let ax = check_x(x)?.abs();
        let a = self.abar;
        if ax <= a {
            return Ok(0.0);
        }
        let z = strip.m_minus_1();
        let t = (ax - a) / (a * z);
        if t <= 1.0 {
            return Ok(self.strip_gap(strip, t));
        }
        Ok(self.params.profile.depth(ax) - self.displacement_at(strip, ax)?)
    }

    /// The gap inside the strip at `x = abar (1 + t (m - 1))`, `t in [0, 1]`
    /// (clamped), from differences that never cancel as `m -> 1`:
    ///
    /// * Hertz: `hbar - ubar_H = (abar^2/2) H(t z)` with [`hertz_gap_fn`]
    ///   (`xi^2 - xi/(xi + sqrt(xi^2-1)) = xi sqrt(xi^2-1)`);
    /// * adhesive (A.5a with `xi = x/a`, `mu = m`, `S = sqrt(mu^2-1)`,
    ///   `W = sqrt(mu^2-xi^2)`, `q = S/W`, `p = xi q`):
    ///   `ubar_a = (4 lambda abar/pi) [mu (acosh p - acosh q) + (mu - xi) acosh q - S acosh xi]`,
    ///   where `q - 1 = (xi^2-1)/((S+W) W)`, `p - q = (xi - 1) q` and
    ///   `acosh p - acosh q = ln1p((p - q)(1 + (p+q)/(P+Q))/(q + Q))`,
    ///   `P, Q = sqrt(p^2-1), sqrt(q^2-1)`; at `t = 1`, `-(4 lambda abar/pi)` [`adhesive_gap_fn`];
    /// * waves: `sum_j [2 alpha_j sin^2(pi x/beta_j) - ubar_w,j(x)]` (absolute error `~1e-15 alpha_j D_j` each).
    pub fn strip_gap(&self, strip: StripEnd, t: f64) -> f64 {
        let t = if t.is_nan() { 1.0 } else { t.clamp(0.0, 1.0) };
        let (a, lambda) = (self.abar, self.params.lambda);
        let z = strip.m_minus_1();
        let zt = z * t;
        let x = a + a * zt;
        let hertz = 0.5 * a * a * hertz_gap_fn(zt);
        let kfac = 4.0 * lambda * a / PI;
        let u_a = if t >= 1.0 {
            -kfac * adhesive_gap_fn(z)
        } else if t <= 0.0 {
            0.0
        } else {
            let mu = 1.0 + z;
            let s = sqrt_z2z(z);
            let xi2m1 = zt * (2.0 + zt);
            let w = (z * (1.0 - t) * (2.0 + z + zt)).sqrt();
            let q = s / w;
            let qm1 = xi2m1 / ((s + w) * w);
            let p_minus_q = zt * q;
            let p = q + p_minus_q;
            let big_q = (qm1 * (q + 1.0)).sqrt();
            let pm1 = qm1 + p_minus_q;
            let big_p = (pm1 * (p + 1.0)).sqrt();
            let acosh_q = (qm1 + big_q).ln_1p();
            let acosh_p_minus_q = (p_minus_q * (1.0 + (p + q) / (big_p + big_q)) / (q + big_q)).ln_1p();
            kfac * (mu * acosh_p_minus_q + z * (1.0 - t) * acosh_q - s * acosh_1p(zt))
        };
        hertz + self.wave_gap(x) - u_a
    }
}
