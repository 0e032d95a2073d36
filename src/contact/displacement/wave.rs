//! The wave of the profile, `A (1 - cos(2 pi x/zeta))` (Eq. 1), as one value.
//!
//! The free functions of [`crate::contact::displacement`] take the amplitude and
//! the wavelength as two bare `f64`, in two orders: `u_wave(a, zeta, amp, x)`
//! and `profile_depth(r, amp, zeta, x)`. Both compile when the two are swapped.
//! A [`Wave`] carries them together, checked once: its methods call the same
//! routes with the arguments in the right places. Nothing here computes; the
//! methods, error bounds and references are those of the functions they name.

use super::{check_positive, du_wave, du_wave_bounded, profile_depth, u_wave, u_wave_bounded, WaveBessel};
use crate::ball::Bounded;
use crate::error::{finite, Result};

/// A sinusoidal wave of amplitude `amp` (`A`, any finite value; 0 is the smooth
/// cylinder) and wavelength `zeta` (`> 0`), in the length unit of the call.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Wave {
    amp: f64,
    zeta: f64,
}

impl Wave {
    /// The wave `A (1 - cos(2 pi x/zeta))`; errors: [`crate::Error::NonFinite`]
    /// for a non-finite `amp` or `zeta`, [`crate::Error::OutOfRange`] for `zeta <= 0`.
    pub fn new(amp: f64, zeta: f64) -> Result<Wave> {
        finite(amp, "amp")?;
        check_positive(zeta, "zeta")?;
        Ok(Wave { amp, zeta })
    }

    /// The amplitude `A`.
    pub fn amp(&self) -> f64 {
        self.amp
    }

    /// The wavelength `zeta`.
    pub fn zeta(&self) -> f64 {
        self.zeta
    }

    /// The profile depth `h(x) = x^2/(2R) + A (1 - cos(2 pi x/zeta))` of a
    /// cylinder of radius `r` carrying this wave ([`profile_depth`]).
    pub fn depth(&self, r: f64, x: f64) -> Result<f64> {
        profile_depth(r, self.amp, self.zeta, x)
    }

    /// The wave displacement `u_w(x)` outside a contact of half-width `a` ([`u_wave`], an estimate).
    pub fn u(&self, a: f64, x: f64) -> Result<f64> {
        u_wave(a, self.zeta, self.amp, x)
    }

    /// `du_w/dx` ([`du_wave`], an estimate).
    pub fn du(&self, a: f64, x: f64) -> Result<f64> {
        du_wave(a, self.zeta, self.amp, x)
    }

    /// `u_w(x)` with a proven bound ([`u_wave_bounded`]).
    pub fn u_bounded(&self, a: f64, x: f64) -> Result<Bounded> {
        u_wave_bounded(a, self.zeta, self.amp, x)
    }

    /// `du_w/dx` with a proven bound ([`du_wave_bounded`]).
    pub fn du_bounded(&self, a: f64, x: f64) -> Result<Bounded> {
        du_wave_bounded(a, self.zeta, self.amp, x)
    }

    /// The Bessel data of a contact of half-width `a`, for many `x` ([`WaveBessel::new`]).
    pub fn at_contact(&self, a: f64) -> Result<WaveBessel> {
        WaveBessel::new(a, self.zeta, self.amp)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Error;

    #[test]
    fn methods_put_amp_and_zeta_in_their_places() {
        // an amplitude and a wavelength that differ, so a swap would show
        let (amp, zeta, a, r) = (0.35, 1.125, 2.0, 1.0);
        let w = Wave::new(amp, zeta).unwrap();
        assert_eq!((w.amp(), w.zeta()), (amp, zeta));
        for x in [2.5, 3.0, 7.0] {
            assert_eq!(w.u(a, x).unwrap(), u_wave(a, zeta, amp, x).unwrap());
            assert_eq!(w.du(a, x).unwrap(), du_wave(a, zeta, amp, x).unwrap());
            assert_eq!(w.u_bounded(a, x).unwrap(), u_wave_bounded(a, zeta, amp, x).unwrap());
            assert_eq!(w.du_bounded(a, x).unwrap(), du_wave_bounded(a, zeta, amp, x).unwrap());
            assert_eq!(w.at_contact(a).unwrap().eval(x).unwrap(), (w.u(a, x).unwrap(), w.du(a, x).unwrap()));
            // Eq. 1 by hand: x^2/(2R) + A (1 - cos(2 pi x/zeta))
            let h = x * x / (2.0 * r) + amp * (1.0 - (2.0 * std::f64::consts::PI * x / zeta).cos());
            assert!((w.depth(r, x).unwrap() - h).abs() < 1e-14 * h.abs().max(1.0));
        }
        // at the contact edge u_w(a) = A (1 - cos(2 pi a/zeta)), which a swap breaks
        let edge = amp * (1.0 - (2.0 * std::f64::consts::PI * a / zeta).cos());
        assert!((w.u(a, a).unwrap() - edge).abs() < 1e-13);
    }

    #[test]
    fn bad_waves_are_refused_by_name() {
        assert!(matches!(Wave::new(f64::NAN, 1.0), Err(Error::NonFinite { what: "amp" })));
        assert!(matches!(Wave::new(0.1, 0.0), Err(Error::OutOfRange { arg: "zeta", .. })));
        assert!(matches!(Wave::new(0.1, f64::INFINITY), Err(Error::NonFinite { what: "zeta" })));
        assert!(Wave::new(0.0, 1.0).is_ok());
    }
}
