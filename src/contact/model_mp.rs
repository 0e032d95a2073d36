//! Arbitrary-precision versions of the model's core quantities, on request:
//! the strip residual `F(m)` (Eq. 15b, corrected), a certified enclosure of the
//! strip end `m`, and the load (Eq. 14).
//!
//! `F` is evaluated in ball arithmetic (the wave term by the certified Bessel form
//! of [`crate::contact::displacement`]), so the sign of `F` at a point is proven
//! when its ball excludes zero. [`solve_m_mp`] starts from the f64 first root of
//! [`ContactSize::solve_strip`] (solved in `m - 1`, so the bracket is tight even as `m -> 1`), proves a sign change of `F` across a small bracket and
//! bisects it to the requested width: the returned ball provably contains a root
//! of `F`. That it is the *first* root rests on the f64 scan (see `model.rs`).

use rug::Float;

use crate::ball::Ball;
use crate::contact::displacement::wave_bessel_wp;
use crate::contact::model::{ContactSize, Params};
use crate::error::{check_prec, Error, Result};
use crate::special::bessel_j::bessel_j_mp;
use crate::special::exact_sub;
use crate::MAX_WORKING_PREC;

/// `F(m) = lambda gbar(m abar) - 1` in ball arithmetic at working precision `wp`
/// (`m >= 1` exact).
pub fn strip_residual_mp(params: Params, abar: f64, m: &Float, wp: u32) -> Result<Ball> {
    let Params { lambda, alpha, beta } = params;
    if *m < 1 {
        return Err(Error::Domain { what: "the strip ratio m must be >= 1".into() });
    }
    let a = Ball::from_f64(abar, wp)?;
    let lam = Ball::from_f64(lambda, wp)?;
    let e = Ball::from_float(&exact_sub(m, &Float::with_val(2, 1)), wp); // m - 1, exact
    let mb = e.add_i64(1);
    let s = e.mul(&e.add_i64(2)).sqrt()?; // sqrt(m^2 - 1)
    let acosh_m = e.add(&s).ln_1p()?;
    let ln_m = e.ln_1p()?;
    let hertz = a.sqr().mul(&mb.mul(&s).sub(&acosh_m)).mul_pow2(-1);
    let adhesive = Ball::pi(wp).recip()?.mul_pow2(2).mul(&lam).mul(&a).mul(&s.mul(&acosh_m).sub(&mb.mul(&ln_m)));
    // c = m abar exactly (enough bits for the product of two binary numbers)
    let abar_f = Float::with_val(53, abar);
    let c = Float::with_val(m.prec() + 53, m * &abar_f);
    let wave = if alpha > 0.0 {
        let (beta_f, alpha_f) = (Float::with_val(53, beta), Float::with_val(53, alpha));
        let uw = wave_bessel_wp(&abar_f, &beta_f, &alpha_f, &c, wp)?.0;
        let arg = Ball::pi(wp).mul(&Ball::from_float(&c, wp)).div(&Ball::from_f64(beta, wp)?)?;
        let sn = arg.sin_cos().0;
        sn.sqr().mul(&Ball::from_f64(alpha, wp)?).mul_pow2(1).sub(&uw)
    } else {
        Ball::zero(wp)
    };
    Ok(lam.mul(&hertz.add(&adhesive).add(&wave)).add_i64(-1))
}

/// A ball that provably contains a root of `F` (the f64 solver's first root),
/// of relative width `2^-prec`.
pub fn solve_m_mp(params: Params, abar: f64, prec: u32) -> Result<Ball> {
    check_prec(prec)?;
    let e0 = ContactSize::new(params, abar)?.solve_strip()?.m_minus_1();
    // m = 1 + (m - 1) must be exact: enough bits for the exponent gap of m - 1.
    let gap_bits = (-e0.log2()).max(0.0).min(1100.0) as u32;
    let mut wp = (prec + 32).max(gap_bits + 64);
    // Bracket around the f64 root with a proven sign change.
    let mut delta = e0 * 1e-9;
    let (mut lo, mut hi);
    let mut tries = 0;
    loop {
        lo = Float::with_val(wp, 1) + (e0 - delta).max(0.0);
        hi = Float::with_val(wp, 1) + (e0 + delta);
        let (flo, fhi) = (strip_residual_mp(params, abar, &lo, wp)?, strip_residual_mp(params, abar, &hi, wp)?);
        if flo.is_negative() && fhi.is_positive() {
            break;
        }
        delta *= 16.0;
        tries += 1;
        if tries > 12 {
            return Err(Error::Internal { what: format!("no certified sign change of F around the f64 root m - 1 = {e0}") });
        }
    }
    // Bisection until the bracket is 2^-prec m wide.
    loop {
        let width = Float::with_val(wp, &hi - &lo);
        let scale = Float::with_val(wp, &hi >> prec as i32);
        if width <= scale {
            return Ok(Ball::hull(&lo, &hi, wp));
        }
        let mid = Float::with_val(wp + 1, &lo + &hi) / 2u32;
        let f = strip_residual_mp(params, abar, &mid, wp)?;
        if f.is_negative() {
            lo = mid;
        } else if f.is_positive() {
            hi = mid;
        } else {
            // F's ball straddles zero at this precision: raise it (Ziv).
            wp += 32;
            if wp > MAX_WORKING_PREC {
                return Err(Error::PrecisionExhausted { function: "solve_m_mp", working_prec: wp });
            }
            lo = Float::with_val(wp, &lo);
            hi = Float::with_val(wp, &hi);
        }
    }
}

/// Eq. 14 in ball arithmetic for a strip ratio known as a ball:
/// `pi abar^2/4 - 2 lambda abar sqrt(m^2-1) + (pi^2 alpha abar/beta) J1(2 pi abar/beta)`.
pub fn load_mp(params: Params, abar: f64, m: &Ball, prec: u32) -> Result<Ball> {
    check_prec(prec)?;
    let wp = prec + 16;
    let Params { lambda, alpha, beta } = params;
    let a = Ball::from_f64(abar, wp)?;
    let pi = Ball::pi(wp);
    let s = m.sqr().add_i64(-1);
    let s = if s.lower() < 0 { Ball::hull(&Float::new(wp), &s.upper(), wp) } else { s };
    let hertz = pi.mul(&a.sqr()).mul_pow2(-2);
    let adhesive = Ball::from_f64(lambda, wp)?.mul(&a).mul(&s.sqrt()?).mul_pow2(1);
    let wave = if alpha > 0.0 {
        // J1 at D = 2 pi abar/beta (a ball): |J1'| <= 1, evaluate at the midpoint and widen
        let d = pi.mul(&a).mul_pow2(1).div(&Ball::from_f64(beta, wp)?)?;
        let mut j1 = bessel_j_mp(1, d.mid(), wp)?;
        j1.add_error_mag(d.rad_mag());
        pi.sqr().mul(&Ball::from_f64(alpha, wp)?).mul(&a).div(&Ball::from_f64(beta, wp)?)?.mul(&j1)
    } else {
        Ball::zero(wp)
    };
    Ok(hertz.sub(&adhesive).add(&wave))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn certified_root_agrees_with_f64_solver() {
        for &(lambda, abar) in &[(1.0, 0.7), (6.0, 3.16), (0.25, 2.2)] {
            let p = Params::new(lambda, 2f64.sqrt() / 4.0, 1.125).unwrap();
            let cs = ContactSize::new(p, abar).unwrap();
            let m0 = cs.solve_m().unwrap();
            let l0 = cs.load(m0).unwrap();
            let m = solve_m_mp(p, abar, 128).unwrap();
            assert!(m.meets_rel(120), "{m:?}");
            assert!((m.to_f64() - m0).abs() <= 1e-12 * m0, "f64 {m0} vs MP {m:?}");
            let l = load_mp(p, abar, &m, 128).unwrap();
            assert!((l.to_f64() - l0).abs() < 1e-10, "load {l:?} vs {l0}");
            // the residual changes sign across the returned ball
            assert!(strip_residual_mp(p, abar, &m.lower(), 192).unwrap().is_negative());
            assert!(strip_residual_mp(p, abar, &m.upper(), 192).unwrap().is_positive());
        }
    }
}
