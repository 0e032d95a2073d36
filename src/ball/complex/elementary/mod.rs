//! Elementary functions of a complex ball: exp, log, sqrt, pow, sin, cos, tan, sinh,
//! cosh, tanh, atan.
//!
//! # Method
//!
//! Every function is written in real-ball operations that have the inclusion property
//! (`Ball`'s ring operations and the real functions of `ball/elementary.rs`, each one
//! MPFR call at the midpoint plus a derivative bound for the radius), so the result
//! contains `f(z)` for every `z` of the input rectangle. The working precision is the
//! input's, [`CBall::prec`]. Where the input's imaginary part is exactly zero the real
//! function is called directly (a real result stays real).
//!
//! * `exp(x + iy) = e^x (cos y + i sin y)` (DLMF 4.5.11 with Euler's formula).
//! * `sin`, `cos`, `sinh`, `cosh` from one `sin_cos` of one part and one `sinh_cosh`
//!   of the other (DLMF 4.21.37-38, 4.35.34-35), e.g.
//!   `sin(x + iy) = sin x cosh y + i cos x sinh y`.
//! * `tan(x + iy) = (sin 2x + i sinh 2y) / (cos 2x + cosh 2y)` (DLMF 4.21.39), computed as
//!   `(sin x cos x + i sinh y cosh y) / (cos^2 x + sinh^2 y)` (no cancellation near a pole) while
//!   `|y| <= 1` or the rectangle reaches `y = 0`; for `|y| > 1` the form
//!   `tan z = i (1 - w) / (1 + w)`, `w = e^(2iz)`, `|w| = e^(-2|y|) < e^-2`, which does not
//!   overflow (so `tan(x + 10^9 i)` is a small ball around `i`). The denominator is a
//!   real ball; it contains zero only at the poles `x = pi/2 + k pi`, `y = 0`, where the
//!   result is indeterminate. `tanh z = -i tan(iz)` (DLMF 4.28.9).
//! * `log z = ln|z| + i Arg z` (DLMF 4.2.3): `ln|z| = ln(x^2 + y^2) / 2`, or
//!   `ln_1p((x - 1)(x + 1) + y^2) / 2` when `|z|` is near 1 (relative accuracy of a small
//!   result); `Arg z = atan2(y, x)` ([`Ball::atan2`]).
//! * `sqrt z` (DLMF 4.2(iv)): with `a = |z|`, `Re = sqrt((a + x)/2)`, `Im = y / (2 Re)`
//!   in the right half plane, and `|Im| = sqrt((a - x)/2)`, `Re = |y| / (2 |Im|)` in the
//!   left: no cancellation in either.
//! * `pow(z, w) = exp(w log z)` (DLMF 4.2.26); an exact integer exponent uses binary
//!   powering (no cut; a negative one through `1/z^n`, indeterminate at 0); an exact
//!   `w = 1/2` is [`CBall::sqrt`]; for a rectangle containing 0 and `Re w > 0` the
//!   principal form returns the disc `|z^w| <= |z|^Re w e^(pi |Im w|)`.
//! * `atan z = (i/2) (log(1 - iz) - log(1 + iz))` (DLMF 4.23.26 with principal
//!   logarithms; C99's and Arb's convention), written out as
//!   `Re = (Arg(1 + iz) - Arg(1 - iz)) / 2 = (atan2(x, 1 - y) - atan2(-x, 1 + y)) / 2`,
//!   `Im = ln_1p(4y / (x^2 + (1 - y)^2)) / 4` (for `y >= 0`; odd in `y`), accurate for
//!   small `z` (on a wide rectangle, where the quotient's ball reaches -1, as the difference
//!   of the two logarithms). Singular at `z = +-i` (indeterminate).
//!
//! # Error bound
//!
//! Each real operation adds its rounding error (one ulp of a correctly rounded MPFR
//! result) and the propagated input radius; for an exact input the result carries
//! about `prec - 4` bits relative to `|f(z)|` (tests check `prec - 8`).
//!
//! # Branch cuts
//!
//! | function | cut | principal value on the cut |
//! |---|---|---|
//! | `log`, `sqrt`, `pow` | `(-inf, 0]` (DLMF 4.2.1, 4.2(iv)) | continuous from above: `Arg = pi` |
//! | `atan` | `i(-inf, -1]`, `i[1, inf)` (DLMF 4.23(ii)) | upper cut continuous from the right (`Re = pi/2`), lower from the left (`Re = -pi/2`) |
//!
//! The principal forms enclose every value taken on the rectangle, also when it
//! straddles the cut (then e.g. `Im log` is `[0 +/- pi]`: wide, but correct). The
//! `_analytic` forms return [`CBall::indeterminate`] as soon as the rectangle touches
//! the cut (decided conservatively: a rectangle that only touches it after rounding
//! counts), so that an integrand built from them is holomorphic wherever it is finite.
//!
//! Any non-finite input, overflow (e.g. `exp` of `Re z > 7e8`, MPFR's exponent range),
//! or pole gives [`CBall::indeterminate`]; nothing panics.

mod branch;
#[cfg(test)]
mod tests;
mod trig;

use rug::Float;

use super::CBall;
use crate::ball::{Ball, Mag};

/// The result, or the indeterminate ball if any part is not finite.
fn finish(z: CBall, p: u32) -> CBall {
    if z.is_finite() {
        z
    } else {
        CBall::indeterminate(p)
    }
}

/// The real ball `[0 +/- b]`.
fn disc(b: Mag, p: u32) -> Ball {
    Ball::with_mag(Float::new(p), b)
}

/// `t` with the sign of `y` (principal convention: `+t` where `y = 0`); the hull of
/// `+-t` when `y` reaches below zero and above or onto zero.
fn signed_like(t: Ball, y: &Ball) -> Ball {
    if y.lower() >= 0 {
        t
    } else if y.upper() < 0 {
        t.neg()
    } else {
        let p = t.prec();
        disc(t.abs_upper_mag(), p)
    }
}

/// Whether the rectangle touches `(-inf, 0]` (conservatively).
fn touches_negative_axis(z: &CBall) -> bool {
    !z.re().is_positive() && z.im().contains_zero()
}

impl CBall {
    /// `re + i im` from two f64 at `prec` bits; indeterminate if either is not finite.
    pub fn from_f64s(re: f64, im: f64, prec: u32) -> CBall {
        match (Ball::from_f64(re, prec), Ball::from_f64(im, prec)) {
            (Ok(a), Ok(b)) => CBall::new(a, b),
            _ => CBall::indeterminate(prec),
        }
    }

    /// Whether the real part is exactly zero.
    pub(super) fn is_imaginary(&self) -> bool {
        self.re.is_exact() && self.re.mid().is_zero()
    }

    // ----- exp and the trigonometric and hyperbolic functions --------------
}
