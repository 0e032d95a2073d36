//! The traction of Eq. 16 (with the wave integral of Eq. 7) as a certified ball.
//!
//! Inside the contact (`|x| < abar`)
//!
//! ```text
//! pbar(x) = (2/pi) atan(abar sqrt(m^2 - 1)/w) - w/(2 lambda) (1 + 2 pi alpha/(beta abar) K(|x|/abar)),
//! w = sqrt(abar^2 - x^2),   K(c) = int_0^D J0(t) cos((t - D) c) dt,   D = 2 pi abar/beta,
//! ```
//!
//! `pbar = 1` in the adhesive strip `abar <= |x| <= m abar` and `0` beyond (as
//! [`ContactSize::traction_at`](crate::contact::model::ContactSize::traction_at)).
//! `K` is the certified integral
//! [`traction_integral_ball`]; the rest is ball arithmetic on the input balls
//! ([`ModelBalls`]) and a ball of `m` (e.g. from
//! [`solve_m_ball_mp`](crate::contact::model_mp::solve_m_ball_mp)), so the
//! result contains the traction at every point of the balls.

use crate::ball::Ball;
use crate::contact::model::Params;
use crate::contact::model_mp::ModelBalls;
use crate::contact::displacement::quadrature_ball::traction_integral_ball;
use crate::error::{check_prec, Error, Result};

/// Certified `pbar(x)` (Eq. 16) over the input balls, for a ball of the strip
/// ratio `m >= 1` and a ball of `x`. A ball of `x` that straddles the contact
/// edge `|x| = abar` (an exact `x` equal to an exact `abar` is on the strip side,
/// as in f64) is a typed error; one that straddles the strip end gives `[0, 1]`.
pub fn traction_ball_mp(inputs: &ModelBalls, m: &Ball, x: &Ball, prec: u32) -> Result<Ball> {
    check_prec(prec)?;
    for (v, what) in [(m, "m"), (x, "x")] {
        if !v.is_finite() {
            return Err(Error::NonFinite { what });
        }
    }
    m.check_within("the strip ratio m", crate::error::Interval::at_least(1.0))?;
    let wp = prec + 20;
    let [lam, a] = [&inputs.lambda, &inputs.abar].map(|v| v.set_prec(wp.max(v.prec())));
    let (m, x) = (m.set_prec(wp.max(m.prec())), x.set_prec(wp.max(x.prec())));
    // |x| (the traction is even)
    let ax = if x.lower() >= 0 {
        x
    } else if x.upper() <= 0 {
        x.neg()
    } else {
        Ball::hull(&rug::Float::new(wp), &x.abs_upper(), wp)
    };
    let edge = ax.sub(&a);
    if edge.lower() >= 0 {
        // strip or beyond: 1 for |x| - abar <= abar (m - 1), else 0
        let room = a.mul(&m.add_i64(-1)).sub(&edge);
        return Ok(if room.lower() >= 0 {
            Ball::one(prec)
        } else if room.upper() < 0 {
            Ball::zero(prec)
        } else {
            Ball::hull(&rug::Float::new(prec), &rug::Float::with_val(prec, 1), prec)
        });
    }
    if edge.upper() >= 0 {
        // The contact edge |x| = abar inside the ball of x: the traction is
        // singular in slope there.
        return Err(Error::BallOutOfRange {
            arg: "|x| - abar (the contact edge lies inside the ball of x)",
            lower: edge.lower().to_f64(),
            upper: edge.upper().to_f64(),
            allowed: crate::error::Interval { lo: f64::NEG_INFINITY, hi: 0.0, lo_closed: false, hi_closed: false },
        });
    }
    let w = a.sub(&ax).mul(&a.add(&ax)).sqrt()?;
    let e = m.add_i64(-1);
    let s = e.mul(&e.add_i64(2)).sqrt()?;
    let pi = Ball::pi(wp);
    let adhesive = a.mul(&s).div(&w)?.atan().mul_pow2(1).div(&pi)?;
    // sum_j (2 pi alpha_j/(beta_j abar)) K_j(x/abar)
    let mut wave: Option<Ball> = None;
    for w in &inputs.waves {
        let [alpha, beta] = [&w.alpha, &w.beta].map(|v| v.set_prec(wp.max(v.prec())));
        if alpha.is_exact() && alpha.mid().is_zero() {
            continue;
        }
        let d = pi.mul(&a).mul_pow2(1).div(&beta)?;
        let k = traction_integral_ball(&d, &ax.div(&a)?, wp)?;
        let term = pi.mul(&alpha).mul_pow2(1).div(&beta.mul(&a))?.mul(&k);
        wave = Some(match wave {
            None => term,
            Some(sum) => sum.add(&term),
        });
    }
    let elastic = w.div(&lam.mul_pow2(1))?.mul(&wave.unwrap_or_else(|| Ball::zero(wp)).add_i64(1));
    Ok(adhesive.sub(&elastic))
}

/// [`traction_ball_mp`] with the parameters and `abar` read as exact binary
/// numbers and `x` an exact f64.
pub fn traction_mp(params: Params, abar: f64, m: &Ball, x: f64, prec: u32) -> Result<Ball> {
    traction_ball_mp(&ModelBalls::exact(params, abar)?, m, &Ball::from_f64(x, 53)?, prec)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::contact::model::ContactSize;
    use crate::contact::model_mp::solve_m_mp;

    #[test]
    fn matches_f64_traction_and_checks_input() {
        let params = Params::new(0.5, 0.1, 1.125).unwrap();
        let abar = 1.3;
        let cs = ContactSize::new(params, abar).unwrap();
        let strip = cs.solve_strip().unwrap();
        let m = solve_m_mp(params, abar, 80).unwrap();
        for &x in &[0.0, 0.4, 1.0, 1.29, 1.3, 1.3 * strip.m() * 0.999, 5.0] {
            let p = traction_mp(params, abar, &m, x, 64).unwrap();
            let f = cs.traction_at(strip, x);
            assert!(p.rad_mag().to_f64_up() < 1e-15, "x = {x}: {p:?}");
            assert!((p.to_f64() - f).abs() < 1e-9, "x = {x}: {p:?} vs f64 {f}");
        }
        assert!(traction_mp(params, abar, &Ball::from_f64(0.5, 53).unwrap(), 0.1, 64).is_err());
        let x = Ball::with_mag(rug::Float::with_val(53, 1.3), crate::ball::Mag::from_f64(1e-3));
        assert!(matches!(traction_ball_mp(&ModelBalls::exact(params, abar).unwrap(), &m, &x, 64), Err(Error::BallOutOfRange { .. })));
    }
}
