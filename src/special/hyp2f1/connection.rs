//! The 1-z connection formula (non-degenerate), its use after Pfaff for `z < -1`,
//! and Gauss's sum at `z = 1`.
//!
//! # Method
//!
//! * **1-z formula** (`s = c - a - b` not an integer) [DLMF 15.8.4, 15.10.21]:
//!   `2F1 = G1 2F1(a, b; 1-s; 1-z) + (1-z)^s G2 2F1(c-a, c-b; 1+s; 1-z)`,
//!   `G1 = Gamma(c) Gamma(s) / (Gamma(c-a) Gamma(c-b))`,
//!   `G2 = Gamma(c) Gamma(-s) / (Gamma(a) Gamma(b))`. All parameter combinations
//!   (`c-a`, `c-a-b`, `1-s`, ...) are formed *exactly* (binary sums with enough
//!   bits), so the Gamma values are taken at exact points; `1/Gamma` at a pole
//!   is the exact zero, which switches the corresponding piece off. Gamma ratios
//!   whose arguments differ by a small integer are Pochhammer products
//!   (`Gamma(x+k)/Gamma(x) = (x)_k`), which is exact in the limit and cheap.
//!   A series `2F1(p, q; p; x)` is the power `(1-x)^{-q}` [DLMF 15.4.6]; this is
//!   what makes the paper's model case `2F1(1, k+1/2; k+2; y)` cheap near 1
//!   (the second piece is `y^{-k-1}`).
//! * **`z < -1`**: Pfaff gives `(1-z)^{-a} 2F1(a, c-b; c; w)` with
//!   `w = z/(z-1) in (1/2, 1)`; that function is then evaluated by the 1-w
//!   formula above (parameters `a, c-b, c`; `s' = b - a`, degenerate when `b - a`
//!   is an integer), with the series argument `1 - w = 1/(1-z)`. If `c - b` (or
//!   `c - a`, then Pfaff on `b`) is a non-positive integer the transformed
//!   function is a polynomial in `w` (summed exactly in rationals).
//! * **`z = 1`**: Gauss's sum `Gamma(c) Gamma(c-a-b) / (Gamma(c-a) Gamma(c-b))`
//!   when `c - a - b > 0` [DLMF 15.4.20].
//!
//! # Error bound
//!
//! Ball arithmetic throughout: the Gamma ratios from [`gamma_ratio_scaled`] (exact
//! points, MPFR's correctly rounded values), the powers with directed rounding,
//! and the series engine's rigorous radius for the two `1-z` series.

use rug::Float;

use super::log_case::log_core;
use super::series::{pow_exact_exponent_scaled, rounded_inside_unit, series_or_power};
use super::transform::hyp2f1_pfaff;
use super::one;
use crate::ball::{Ball, Scaled};
use crate::error::{Error, Result};
use crate::special::gamma::{gamma_ratio_scaled, xball};
use crate::special::{exact_add, exact_sub, is_nonpositive_integer};

/// [`Algorithm::Connection`]: the 1-z formula for exact `0 < z < 1`, `c - a - b`
/// not an integer.
pub(crate) fn hyp2f1_connection(a: &Float, b: &Float, c: &Float, z: &Float, wp: u32) -> Result<Ball> {
    if !(*z > 0 && *z < 1) {
        return Err(Error::precondition("1-z formula needs 0 < z < 1"));
    }
    let u = xball(&exact_sub(&one(), z), wp);
    connection_core(a, b, c, &xball(z, wp), &u, wp)
}

/// The 1-x formula at balls `x` and `u = 1 - x` (`0 < u < 1`), `c - a - b` not an integer.
pub(super) fn connection_core(a: &Float, b: &Float, c: &Float, x: &Ball, u: &Ball, wp: u32) -> Result<Ball> {
    let ca = exact_sub(c, a);
    let cb = exact_sub(c, b);
    let s = exact_sub(&ca, b);
    if s.is_integer() {
        return Err(Error::precondition("1-z formula needs c - a - b not an integer"));
    }
    let neg_s = Float::with_val(s.prec(), -&s);
    let one_minus_s = exact_sub(&one(), &s);
    let one_plus_s = exact_add(&one(), &s);
    // each term's Gamma ratio and power in logarithms where they pass the
    // exponent range (`Scaled`), the term formed once
    let g1 = gamma_ratio_scaled(&[c, &s], &[&ca, &cb], wp)?;
    let t1 = if g1.is_exact_zero() { g1 } else { g1.mul_ball(&series_or_power(a, b, &one_minus_s, u, x, wp)?) };
    let g2 = gamma_ratio_scaled(&[c, &neg_s], &[a, b], wp)?;
    let t2 = if g2.is_exact_zero() {
        g2
    } else {
        let us = pow_exact_exponent_scaled(u, &s, wp)?;
        g2.mul(&us).mul_ball(&series_or_power(&ca, &cb, &one_plus_s, u, x, wp)?)
    };
    Scaled::sum_to_ball(&[t1, t2], wp)
}

/// [`Algorithm::PfaffConnection`] and [`Algorithm::PfaffConnectionLog`]: for
/// `z < 0`, `(1-z)^{-a} 2F1(a, c-b; c; w)`, `w = z/(z-1)`, with the inner function
/// by the 1-w formula (logarithmic when `b - a` is an integer) at `1 - w = 1/(1-z)`.
/// Falls back to [`hyp2f1_pfaff`] when the transformed function is a polynomial
/// (times a power).
pub(crate) fn hyp2f1_pfaff_connection(a: &Float, b: &Float, c: &Float, z: &Float, wp: u32) -> Result<Ball> {
    if *z >= 0 {
        return Err(Error::precondition("Pfaff + 1-w formula needs z < 0"));
    }
    let ca = exact_sub(c, a);
    let cb = exact_sub(c, b);
    if [a, b, &ca, &cb].iter().any(|x| is_nonpositive_integer(x)) {
        return hyp2f1_pfaff(a, b, c, z, wp);
    }
    let omz_b = xball(&exact_sub(&one(), z), wp);
    let pre = pow_exact_exponent_scaled(&omz_b, &Float::with_val(a.prec(), -a), wp)?;
    // `1 - z` and `z` rounded into their balls at `wp` bits: a decimal `z`
    // tightened to 58 000 bits made `u`, `ln u` and every term of the series in
    // `u` cost that length (`2F1(-245.25, -162.25; 112.5; -181.625e25051)` at 150
    // bits: 150 ms of CPU, of which 50 ms in one step before the budget's next
    // check, issue 37's scan). Kept as given when the rounded `u` would reach 1.
    let (u, zb) = match rounded_inside_unit(&omz_b.at_most_prec(wp).recip()?, wp) {
        Some(u) => (u, xball(z, wp).at_most_prec(wp)),
        None => (omz_b.recip()?, xball(z, wp)),
    };
    let w = zb.mul(&u).neg();
    let s = exact_sub(b, a);
    let inner = if s.is_integer() { log_core(a, &cb, c, &u, wp)? } else { connection_core(a, &cb, c, &w, &u, wp)? };
    pre.mul_ball(&inner).to_value(wp)
}

/// [`Algorithm::Gauss`]: `2F1(a, b; c; 1) = Gamma(c) Gamma(c-a-b) / (Gamma(c-a) Gamma(c-b))`, `c - a - b > 0`.
pub(crate) fn hyp2f1_gauss(a: &Float, b: &Float, c: &Float, wp: u32) -> Result<Ball> {
    let ca = exact_sub(c, a);
    let cb = exact_sub(c, b);
    let s = exact_sub(&ca, b);
    if s <= 0 {
        return Err(Error::precondition("Gauss's sum needs c - a - b > 0"));
    }
    gamma_ratio_scaled(&[c, &s], &[&ca, &cb], wp)?.to_value(wp)
}
