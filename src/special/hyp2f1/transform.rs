//! Series in `z` or in `w = z/(z-1)`: the direct series and the Euler and Pfaff
//! transformations.
//!
//! # Method
//!
//! * Direct: `sum_n (a)_n (b)_n / ((c)_n n!) z^n` [DLMF 15.2.1], `|z| < 1`.
//! * Pfaff [DLMF 15.8.1]: `(1-z)^{-a} 2F1(a, c-b; c; w)`, `w = z/(z-1)`; for
//!   `-1 <= z < -1/2`, `|w| <= 1/2`. `w` is a ball (`z` times the enclosure of
//!   `1/(1-z)`); the series engine adds the perturbation bound of its radius. If
//!   the transformed series terminates it is summed exactly at the rational `w`.
//! * Euler [DLMF 15.8.1]: `(1-z)^{c-a-b} 2F1(c-a, c-b; c; z)`; a polynomial times
//!   a power when `c - a` or `c - b` is a non-positive integer (any `z < 1`).
//!
//! Every prefactor is a ball power of the exact `1 - z`; the error bound is the
//! series engine's ([`series_2f1`]) times ball arithmetic.

use rug::{Float, Rational};

use super::polynomial::{hyp2f1_polynomial, polynomial_at, to_rational};
use super::series::{pow_exact_exponent_scaled, series_2f1};
use super::{one, terminating_degree};
use crate::ball::Ball;
use crate::error::{Error, Result};
use crate::special::gamma::xball;
use crate::special::{exact_sub, is_nonpositive_integer};

/// [`Algorithm::Direct`]: the power series, `|z| < 1`.
pub(crate) fn hyp2f1_direct(a: &Float, b: &Float, c: &Float, z: &Float, wp: u32) -> Result<Ball> {
    series_2f1(a, b, c, &xball(z, wp), wp)
}

/// [`Algorithm::Pfaff`]: `(1-z)^{-a} 2F1(a, c-b; c; z/(z-1))` (or the same with
/// `a`, `b` swapped when that makes the transformed series terminate); needs
/// `z < 1/2` unless the transformed series terminates (then any `z < 1`).
pub(crate) fn hyp2f1_pfaff(a: &Float, b: &Float, c: &Float, z: &Float, wp: u32) -> Result<Ball> {
    if *z >= 1 {
        return Err(Error::precondition("Pfaff transformation needs z < 1"));
    }
    let ca = exact_sub(c, a);
    let cb = exact_sub(c, b);
    // (1-z)^{-p} 2F1(p, q; c; w)
    let (p, q) = if is_nonpositive_integer(&ca) && !is_nonpositive_integer(&cb) { (b, ca) } else { (a, cb) };
    let omz = exact_sub(&one(), z);
    let omz_b = xball(&omz, wp);
    let pre = pow_exact_exponent_scaled(&omz_b, &Float::with_val(p.prec(), -p), wp)?;
    let u = omz_b.recip()?;
    let w = xball(z, wp).mul(&u).neg();
    let inner = if terminating_degree(p, &q).is_some() {
        let zq = to_rational(z)?;
        let wq = &zq / Rational::from(&zq - 1u32);
        polynomial_at(p, &q, c, &wq, &w, wp)?
    } else {
        series_2f1(p, &q, c, &w, wp)?
    };
    // the prefactor in logarithms where it passes the exponent range
    pre.mul_ball(&inner).to_value(wp)
}

/// [`Algorithm::Euler`]: `(1-z)^{c-a-b} 2F1(c-a, c-b; c; z)` [DLMF 15.8.1]; any
/// `z < 1` when `c - a` or `c - b` is a non-positive integer (polynomial), else `|z| < 1`.
pub(crate) fn hyp2f1_euler(a: &Float, b: &Float, c: &Float, z: &Float, wp: u32) -> Result<Ball> {
    if *z >= 1 {
        return Err(Error::precondition("Euler transformation needs z < 1"));
    }
    let ca = exact_sub(c, a);
    let cb = exact_sub(c, b);
    let s = exact_sub(&ca, b);
    let u = xball(&exact_sub(&one(), z), wp);
    let inner = if terminating_degree(&ca, &cb).is_some() {
        hyp2f1_polynomial(&ca, &cb, c, z, wp)?
    } else {
        series_2f1(&ca, &cb, c, &xball(z, wp), wp)?
    };
    pow_exact_exponent_scaled(&u, &s, wp)?.mul_ball(&inner).to_value(wp)
}
