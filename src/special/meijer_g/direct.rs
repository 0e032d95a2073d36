//! `G(k, y)` by the direct series `S(y) = sum_{n>=1} (k+1/2)_n y^n / ((k+2)_n n)`
//! (module docs of [`super`], region **Direct**), one `k` at a time or for every
//! `k <= kmax` at once by two recurrences in `k`.
//!
//! Error bound: the term ratio is at most `y`, so the tail from term `N` is at
//! most `(r_N/N)/(1-y)`, added to the ball's radius; every operation is a ball
//! operation, so the result encloses `G` over a ball argument.
//!
//! References: seed paper Eq. 12 and D.41a; DLMF 15.5.11 (contiguity).

use rug::Float;

use crate::ball::{Ball, Mag, MAG_PREC};
use crate::error::{Error, Interval, Result};

use super::constants::MeijerConstants;

/// The arguments of the direct series, `0 < y < 1` (its tail bound needs `y < 1`).
const Y_DIRECT: Interval = Interval { lo: 0.0, hi: 1.0, lo_closed: false, hi_closed: false };

/// `G(k, y)` by the direct series at working precision `wp`.
pub fn meijer_g_k_direct(k: u32, y: &Float, wp: u32) -> Result<Ball> {
    crate::error::check_working_prec(wp)?;
    meijer_g_k_direct_ball(&MeijerConstants::cached(k, wp)?, &Ball::from_float(y, wp), wp)
}

/// `S(y) = sum_{n>=1} (b)_n y^n / ((c)_n n)`, `b = k+1/2`, `c = k+2`, with the tail
/// bound `sum_{n>=N} v_n <= (r_N/N) / (1 - y)`: `r_n = (b)_n y^n/(c)_n` has ratio
/// `y (b+n)/(c+n) <= y`.
pub(super) fn direct_sum(k: u32, yb: &Ball, wp: u32) -> Result<Ball> {
    let y_up = yb.upper();
    if y_up >= 1 {
        return Err(Error::OutOfRange { arg: "y (the direct series)", value: y_up.to_f64(), allowed: Y_DIRECT });
    }
    let b2 = 2 * k as i64 + 1; // 2b
    let c2 = 2 * k as i64 + 4; // 2c
    let mut r = Ball::one(wp);
    let mut sum = Ball::zero(wp);
    let one_minus_y = Mag::from_float_down(&Float::with_val(MAG_PREC, 1 - &y_up));
    let mut n: i64 = 0;
    loop {
        // r_{n+1} = r_n y (2b + 2n)/(2c + 2n)
        r = r.mul(yb).mul_i64(b2 + 2 * n).div_i64(c2 + 2 * n)?;
        n += 1;
        let v = r.div_i64(n)?;
        // tail from n on: (r_n/n)/(1-y)
        let tail = v.abs_upper_mag().div(one_minus_y);
        if tail.le(&sum.abs_lower_mag().mul_2exp(-(wp as i64) - 4)) {
            sum.add_error_mag(tail);
            return Ok(sum);
        }
        sum = sum.add(&v);
        if n > 100_000_000 {
            return Err(Error::NoConvergence { function: "meijer_g_k (direct)", terms: n as u64 });
        }
    }
}

/// `S_k(y)` for every `k = 0..=kmax` at once (`0 < y < 1`), for sums over `k`
/// such as Eq. 12.
///
/// With `b = k+1/2`, `c = k+2`, the Pochhammer ratios of consecutive `k` differ by
/// `u_n^(k) - u_n^(k+1) = -(3/2) n u_n^(k) / (b (c+n))`, which sums to
/// `S_{k+1} = S_k + (3/((2k+1)(k+2))) (H_k - 1)`, `H_k = 2F1(1, k+1/2; k+3; y)`, and
/// `H_k = 1 + ((2k+1)/(2k+6)) y H_{k+1}` [DLMF 15.5.11-type contiguity for `a = 1`].
/// `H` is run downward from its series at `kmax` (the recurrence contracts by `y`),
/// `S` upward from the direct `S_0` (positive increments): two series instead of
/// `kmax + 1`. All in balls; the tails are those of `direct_sum` and of the `H`
/// series (ratio `<= y`).
pub fn direct_sums_sweep(kmax: u32, yb: &Ball, wp: u32) -> Result<Vec<Ball>> {
    crate::error::check_working_prec(wp)?;
    let y_up = yb.upper();
    if y_up >= 1 {
        return Err(Error::OutOfRange { arg: "y (the direct series)", value: y_up.to_f64(), allowed: Y_DIRECT });
    }
    let top = kmax as i64;
    // H_top = sum_n (b)_n/(c')_n y^n, b = top + 1/2, c' = top + 3: ratio y (2b + 2n)/(2c' + 2n)
    let one_minus_y = Mag::from_float_down(&Float::with_val(MAG_PREC, 1 - &y_up));
    let mut t = Ball::one(wp);
    let mut h_top = Ball::one(wp);
    let mut n: i64 = 0;
    loop {
        t = t.mul(yb).mul_i64(2 * top + 1 + 2 * n).div_i64(2 * top + 6 + 2 * n)?;
        n += 1;
        let tail = t.abs_upper_mag().div(one_minus_y);
        if tail.le(&h_top.abs_lower_mag().mul_2exp(-(wp as i64) - 4)) {
            h_top.add_error_mag(tail);
            break;
        }
        h_top = h_top.add(&t);
        if n > 100_000_000 {
            return Err(Error::NoConvergence { function: "meijer_g_k (sweep)", terms: n as u64 });
        }
    }
    sums_by_recurrence(direct_sum(0, yb, wp)?, h_top, kmax, yb)
}

/// The two recurrences of [`direct_sums_sweep`] from `S_0` and `H_kmax`.
pub(super) fn sums_by_recurrence(s0: Ball, h_top: Ball, kmax: u32, yb: &Ball) -> Result<Vec<Ball>> {
    let top = kmax as i64;
    let wp = s0.prec();
    let mut h = vec![Ball::zero(wp); kmax as usize + 1];
    h[kmax as usize] = h_top;
    for k in (0..top).rev() {
        let next = h[k as usize + 1].mul(yb).mul_i64(2 * k + 1).div_i64(2 * k + 6)?;
        h[k as usize] = next.add_i64(1);
    }
    let mut out = Vec::with_capacity(kmax as usize + 1);
    out.push(s0);
    for k in 0..top {
        let inc = h[k as usize].add_i64(-1).mul_i64(3).div_i64((2 * k + 1) * (k + 2))?;
        let next = out[k as usize].add(&inc);
        out.push(next);
    }
    Ok(out)
}

/// `G(k, y)` from `S_k(y)` (e.g. from [`direct_sums_sweep`]) and the constants.
pub fn meijer_g_k_from_sum(consts: &MeijerConstants, ln_y: &Ball, s: &Ball) -> Ball {
    let bracket = ln_y.neg().sub(s).add(&consts.psi_diff).mul_pow2(-1);
    consts.c_k.mul(&bracket)
}

/// [`meijer_g_k_direct`] for an argument known only as a ball (`0 < y < 1`
/// over the whole ball): every operation is a ball operation, so the result
/// encloses `G(k, y)` for every `y` in the ball.
pub fn meijer_g_k_direct_ball(consts: &MeijerConstants, yb: &Ball, wp: u32) -> Result<Ball> {
    crate::error::check_working_prec(wp)?;
    let s = direct_sum(consts.k, yb, wp)?;
    let bracket = yb.ln()?.neg().sub(&s).add(&consts.psi_diff).mul_pow2(-1);
    Ok(consts.c_k.mul(&bracket))
}

