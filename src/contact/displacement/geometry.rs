//! The checks and the geometry of the wave displacement (module docs of
//! [`super`]): validation of `(a, zeta, amp, x)` in f64, MP and balls, and the
//! balls `D`, `s`, `y = (a/x)^2`, `w = 1 - y`, `x - a`, `x + a` both routes sum on.
//!
//! Accuracy: the geometry is computed in ball arithmetic, so every later ball
//! operation encloses the value over the inputs; `x - a` is taken at the inputs'
//! own precision (no merge of `x` and `a` at a low working precision).

use rug::float::Round;
use rug::Float;

use crate::ball::{Ball, Mag, MAG_PREC};
use crate::error::{finite, Error, Interval, Result};
use crate::special::{check_finite, exact_add, exact_sub};

use super::{MAX_KMAX, MAX_WAVE_D};

// ---------------------------------------------------------------- validation

/// Validates `(a, zeta, amp, x)` of the wave displacement.
pub(super) fn check_wave_f64(a: f64, zeta: f64, amp: f64, x: f64) -> Result<()> {
    finite(a, "a")?;
    finite(zeta, "zeta")?;
    finite(amp, "amp")?;
    finite(x, "x")?;
    Interval::above(0.0).check("the contact half-width a", a)?;
    Interval::above(0.0).check("the wavelength zeta", zeta)?;
    if x < a {
        return Err(Error::InsideContact { x, a });
    }
    check_wave_number(2.0 * std::f64::consts::PI * a / zeta)
}

/// The Bessel and Eq. 12 routes sum about `D/2 + 30` terms, `D = 2 pi a/zeta`;
/// past [`MAX_WAVE_D`] the cost and the cancellation are out of proportion.
pub(super) fn check_wave_number(d: f64) -> Result<()> {
    // NaN is refused too (the interval never contains it)
    Interval::closed(0.0, MAX_WAVE_D).check("2 pi a/zeta (the contact width in wavelengths times pi)", d)?;
    Ok(())
}

pub(super) fn check_wave_mp(a: &Float, zeta: &Float, amp: &Float, x: &Float) -> Result<()> {
    check_finite(a, "a")?;
    check_finite(zeta, "zeta")?;
    check_finite(amp, "amp")?;
    check_finite(x, "x")?;
    if *a <= 0 {
        return Err(Error::OutOfRange { arg: "the contact half-width a", value: a.to_f64(), allowed: Interval::above(0.0) });
    }
    if *zeta <= 0 {
        return Err(Error::OutOfRange { arg: "the wavelength zeta", value: zeta.to_f64(), allowed: Interval::above(0.0) });
    }
    if *x < *a {
        return Err(Error::InsideContact { x: x.to_f64(), a: a.to_f64() });
    }
    check_wave_number(2.0 * std::f64::consts::PI * a.to_f64() / zeta.to_f64())
}

pub(super) fn check_kmax(kmax: u64) -> Result<()> {
    if kmax > MAX_KMAX {
        return Err(Error::IntegerOutOfRange { arg: "kmax", value: i64::try_from(kmax).unwrap_or(i64::MAX), min: 0, max: MAX_KMAX as i64 });
    }
    Ok(())
}

// ---------------------------------------------------------------- geometry

/// The derived quantities of the wave problem, as balls at working precision.
pub(super) struct WaveGeometry {
    /// `A`
    pub(super) amp: Ball,
    /// `a`
    pub(super) a: Ball,
    /// `x`
    pub(super) x: Ball,
    /// `D = 2 pi a / zeta`
    pub(super) d: Ball,
    /// `s = D^2/4`
    pub(super) s: Ball,
    /// `y = (a/x)^2`
    pub(super) y: Ball,
    /// `w = 1 - y = (x-a)(x+a)/x^2`
    pub(super) w: Ball,
    /// `q = x/a - sqrt((x/a)^2 - 1) = 1/(x/a + sqrt((x/a)^2 - 1))`
    pub(super) q: Ball,
    /// `acosh(x/a)`
    pub(super) acosh_r: Ball,
    /// `(1 - q)/sqrt(r^2-1) = 1 - sqrt((r-1)/(r+1))`
    pub(super) one_minus_q_over_s: Ball,
    /// `x == a` exactly
    pub(super) at_edge: bool,
}

pub(super) fn wave_geometry(a: &Float, zeta: &Float, amp: &Float, x: &Float, wp: u32) -> Result<WaveGeometry> {
    // x - a and x + a exactly (no cancellation next to the edge).
    let xma = Ball::from_float(&exact_sub(x, a), wp);
    let xpa = Ball::from_float(&exact_add(x, a), wp);
    let inputs = [a, zeta, amp, x].map(|v| Ball::from_float(v, wp));
    geometry_from_balls(&inputs, xma, xpa, x == a, wp)
}

/// The part of a ball at or above zero, for a quantity known to be `>= 0` (the
/// caller has checked `x >= a`): `[max(lower, 0), upper]`. A ball wholly
/// below zero cannot hold such a quantity and is returned as it is (the square
/// root after it then reports the domain error).
pub(super) fn clip_nonnegative(b: &Ball) -> Ball {
    if !(b.lower() < 0) || b.upper() < 0 {
        return b.clone();
    }
    // [0, u] as [u/2 ± u/2] with u rounded up to 53 bits: mid and radius are
    // then the same exact number, so the lower end is exactly 0.
    let (u, _) = Float::with_val_round(53, b.upper(), Round::Up);
    let half = u / 2u32;
    let rad = Mag::from_float_up(&half);
    Ball::with_mag(half, rad)
}

/// The geometry over balls of inputs `[a, zeta, amp, x]`, with `x - a` and
/// `x + a` given as balls (exact for exact inputs).
pub(super) fn geometry_from_balls(inputs: &[Ball; 4], xma: Ball, xpa: Ball, at_edge: bool, wp: u32) -> Result<WaveGeometry> {
    let [ab, zb, amp, xb] = inputs;
    let d = Ball::pi(wp).mul(ab).mul_pow2(1).div(zb)?;
    let s = d.sqr().mul_pow2(-2);
    // r - 1 and r + 1, r = x/a; a lower end of r - 1 below zero (only for
    // balls that touch the edge x = a from above) is clipped: the caller has
    // checked x >= a over the balls.
    let rm1 = clip_nonnegative(&xma.div(ab)?);
    let rp1 = xpa.div(ab)?;
    let r = rm1.add_i64(1);
    // r^2 - 1 and (r-1)/(r+1) are >= 0 wherever x >= a; their balls may still
    // reach below zero by rounding, so the square roots see them clipped.
    let sq = clip_nonnegative(&rm1.mul(&rp1)).sqrt()?; // sqrt(r^2 - 1)
    let q = r.add(&sq).recip()?;
    let acosh_r = rm1.add(&sq).ln_1p()?;
    // 1 - sqrt(t), t = (r-1)/(r+1), as (1 - t)/(1 + sqrt t) with 1 - t = 2/(r+1):
    // no cancellation when r >> 1 (1 - sqrt t ~ 1/r; the direct form lost
    // log2(r) bits, ~1000 at r = 3e297, found by tests/fuzz.rs).
    let sqrt_t = clip_nonnegative(&rm1.div(&rp1)?).sqrt()?;
    let one_minus_q_over_s = rp1.recip()?.mul_pow2(1).div(&sqrt_t.add_i64(1))?;
    let y = ab.div(xb)?.sqr();
    let w = xma.mul(&xpa).div(&xb.sqr())?;
    Ok(WaveGeometry {
        amp: amp.clone(),
        a: ab.clone(),
        x: xb.clone(),
        d,
        s,
        y,
        w,
        q,
        acosh_r,
        one_minus_q_over_s,
        at_edge,
    })
}

/// The natural scale of `du_w/dx`, `2 pi |A| / zeta` (a lower estimate is fine:
/// it only sets the absolute accuracy floor).
pub(super) fn gradient_scale(amp: &Float, zeta: &Float) -> Float {
    let mut f = Float::with_val(MAG_PREC, amp.abs_ref());
    f *= 6u32;
    f /= zeta;
    f
}

