//! Terminating `2F1`: `a` or `b` a non-positive integer `-d`.
//!
//! # Method
//!
//! `2F1` is a polynomial of degree `d` [DLMF 15.2.4], summed for any `z <= 1`.
//! For `d <= EXACT_POLY_MAX_DEGREE` (300) it is summed *exactly* in rationals
//! (`rug::Rational`) and rounded once (radius: half an ulp of the rounded value,
//! zero when it is representable), so exact zeros (e.g. Chu-Vandermonde zeros at
//! `z = 1`, DLMF 15.4.24) come back as `[0 +/- 0]`, as long as the degree times
//! the bits of the arguments as reduced rationals stays below `EXACT_POLY_MAX_BITS`
//! (2^16: a parameter like `2.6e18829` is 10^5 bits); longer polynomials use the
//! series engine ([`series_2f1`](super::series::series_2f1)), whose bound covers
//! any `z` for a terminating series. `c = -m` is allowed when `d <= m`.

use std::cmp::Ordering;

use rug::float::Round;
use rug::{Float, Rational};

use super::series::series_2f1;
use super::{nonpos_degree, pole_error, terminating_degree, EXACT_POLY_MAX_DEGREE};
use crate::ball::Ball;
use crate::error::{Error, Result};
use crate::special::gamma::{mag_inf, mag_pow2, mag_zero, xball};

pub(super) fn to_rational(x: &Float) -> Result<Rational> {
    x.to_rational().ok_or(Error::NonFinite { what: "hyp2f1 argument" })
}

/// The terminating sum `sum_{n<=deg} (a)_n (b)_n / ((c)_n n!) z^n`, exactly.
pub(super) fn poly_rational(a: &Float, b: &Float, c: &Float, z: &Rational, deg: u64) -> Result<Rational> {
    let (aq, bq, cq) = (to_rational(a)?, to_rational(b)?, to_rational(c)?);
    let mut t = Rational::from(1);
    let mut s = Rational::from(1);
    for n in 0..deg {
        let nq = Rational::from(n);
        let den = Rational::from(&cq + &nq) * Rational::from(n + 1);
        if den == 0 {
            return Err(pole_error(c));
        }
        t *= Rational::from(&aq + &nq);
        t *= Rational::from(&bq + &nq);
        t *= z;
        t /= den;
        s += &t;
    }
    Ok(s)
}

/// Bound on `degree * (bits of a, b, c and z as reduced rationals)` for the
/// exact sum: each term's numerator and denominator grow by about those bits a
/// step. Arguments such as `z = 3.5e-30834` (about 10^5 bits as a rational) at
/// degree 231 made numbers of 2 * 10^7 bits (minutes), and decimal-ball midpoints
/// of 1000-1600 bits at degree 101 took 0.4 s a sum; past the bound the series
/// engine sums in balls at `wp` bits (exact zeros then come back as tiny balls).
const EXACT_POLY_MAX_BITS: u64 = 1 << 16;

/// Bits of the reduced rationals (numerator plus denominator).
fn rational_bits(qs: &[&Rational]) -> u64 {
    qs.iter().map(|q| u64::from(q.numer().significant_bits()) + u64::from(q.denom().significant_bits())).sum()
}

/// The ball around `q` rounded to `wp` bits (exact when representable).
pub(super) fn ball_from_rational(q: &Rational, wp: u32) -> Ball {
    let (mid, ord) = Float::with_val_round(wp, q, Round::Nearest);
    let rad = match (ord, mid.get_exp()) {
        (Ordering::Equal, _) => mag_zero(),
        (_, Some(e)) => mag_pow2(e as i64 - wp as i64),
        (_, None) => mag_inf(),
    };
    Ball::with_radius(mid, &rad)
}

/// The terminating `2F1(a, b; c; z)` at an exact rational `z` (exact sum when the
/// degree is at most [`EXACT_POLY_MAX_DEGREE`], else the series engine at the ball `zb`).
pub(super) fn polynomial_at(a: &Float, b: &Float, c: &Float, zq: &Rational, zb: &Ball, wp: u32) -> Result<Ball> {
    let Some(deg) = terminating_degree(a, b) else {
        return Err(Error::Internal { what: "hyp2f1 polynomial: no non-positive integer numerator".into() });
    };
    if let Some(m) = nonpos_degree(c) {
        if deg > m {
            return Err(pole_error(c));
        }
    }
    if deg <= EXACT_POLY_MAX_DEGREE {
        let (aq, bq, cq) = (to_rational(a)?, to_rational(b)?, to_rational(c)?);
        if rational_bits(&[&aq, &bq, &cq, zq]).saturating_mul(deg) <= EXACT_POLY_MAX_BITS {
            return Ok(ball_from_rational(&poly_rational(a, b, c, zq, deg)?, wp));
        }
    }
    series_2f1(a, b, c, zb, wp)
}

/// [`Algorithm::Polynomial`]: `a` or `b` a non-positive integer, any `z`.
pub(crate) fn hyp2f1_polynomial(a: &Float, b: &Float, c: &Float, z: &Float, wp: u32) -> Result<Ball> {
    polynomial_at(a, b, c, &to_rational(z)?, &xball(z, wp), wp)
}
