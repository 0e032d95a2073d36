//! `G(k, y)` next to the singular point `y = 1` by the expansion in `w = 1 - y`
//! (module docs of [`super`], region **NearOne**), its value at `y = 1`, and the
//! sweep over `k` near one.
//!
//! Error bound: the `I1` and `I2` term ratios decrease in the index, so once
//! they are below one the tails are geometric and are added to the radius.
//! The two sums cancel by about `1.45 k w` bits, which the caller's Ziv loop adds.
//!
//! References: DLMF 15.8.4 (the `1-z` connection formula); seed paper D.41a.

use rug::Float;

use crate::ball::{Ball, Mag};
use crate::error::{Error, Interval, Result};
use crate::special::exact_sub;

use super::constants::MeijerConstants;
use super::direct::sums_by_recurrence;

/// [`direct_sums_sweep`](super::direct_sums_sweep) near `y = 1` (`w = 1 - y` small, `kmax w` moderate):
/// `S_0 = -ln y + psi(2) - psi(1/2) - 2 B_0(y)` from the near-one expansion of
/// `G(0, y)`, and `H_kmax` from the 1-z connection formula [DLMF 15.8.4]
/// (`c - a - b = 3/2`; the second piece collapses to a power):
/// `2F1(1, b; k+3; y) = (2(k+2)/3) 2F1(1, b; -1/2; w) + (8 sqrt(pi)/3) ((k+2)/C_k) w^{3/2} y^{-k-2}`,
/// `b = k+1/2`, with `Gamma(k+3)/Gamma(k+1/2) = 2(k+2)/C_k`. The series
/// `2F1(1, b; -1/2; w)` has term ratio `w (b+n)/(n-1/2)`, decreasing for `n >= 1`,
/// so its tail is geometric once that ratio is below 1.
pub fn near_one_sums_sweep(kmax: u32, w: &Ball, wp: u32) -> Result<Vec<Ball>> {
    crate::error::check_working_prec(wp)?;
    let w = if w.lower() < 0 { Ball::hull(&Float::new(wp), &w.upper(), wp) } else { w.clone() };
    if w.upper() > 0.5 {
        return Err(Error::OutOfRange { arg: "w = 1 - y (the near-one sweep)", value: w.upper().to_f64(), allowed: Interval::closed(0.0, 0.5) });
    }
    let yb = Ball::one(wp).sub(&w);
    let c0 = MeijerConstants::new(0, wp)?;
    // S_0 from B_0 = G_0 / C_0
    let b0 = meijer_g_k_near_one_ball(&c0, &w, wp)?.div(&c0.c_k)?;
    let s0 = yb.ln()?.neg().add(&c0.psi_diff).sub(&b0.mul_pow2(1));
    // H_top by the connection formula
    let top = kmax as i64;
    let ct = MeijerConstants::new(kmax, wp)?;
    let w_up = w.abs_upper_mag();
    let one = Mag::from_f64(1.0);
    let mut t = Ball::one(wp);
    let mut f = Ball::one(wp);
    let mut n: i64 = 0;
    loop {
        // t_{n+1} = t_n w (b+n)/(n-1/2) = t_n w (2k+1+2n)/(2n-1)
        t = t.mul(&w).mul_i64(2 * top + 1 + 2 * n).div_i64(2 * n - 1)?;
        n += 1;
        let rho = w_up
            .mul(Mag::from_f64(((2 * top + 1 + 2 * n) as f64).next_up()))
            .div(Mag::from_f64(((2 * n - 1) as f64).next_down()));
        let one_minus = one.sub_lower(rho);
        if !one_minus.is_zero() {
            let tail = t.abs_upper_mag().div(one_minus);
            if tail.le(&f.abs_lower_mag().mul_2exp(-(wp as i64) - 4)) {
                f.add_error_mag(tail);
                break;
            }
        }
        f = f.add(&t);
        if n > 100_000_000 {
            return Err(Error::NoConvergence { function: "meijer_g_k (near-one sweep)", terms: n as u64 });
        }
    }
    let first = f.mul_i64(2 * (top + 2)).div_i64(3)?;
    let power = w.sqrt()?.mul(&w).div(&yb.pow_u64(kmax as u64 + 2))?;
    let second = Ball::pi(wp).sqrt()?.mul_i64(8 * (top + 2)).div_i64(3)?.div(&ct.c_k)?.mul(&power);
    let h_top = first.add(&second);
    sums_by_recurrence(s0, h_top, kmax, &yb)
}

/// `G(k, y)` by the expansion in `w = 1 - y` at working precision `wp` (`y >= 1/2`).
pub fn meijer_g_k_near_one(k: u32, y: &Float, wp: u32) -> Result<Ball> {
    crate::error::check_working_prec(wp)?;
    if *y < 0.5 {
        return Err(Error::OutOfRange { arg: "y (the near-one expansion)", value: y.to_f64(), allowed: Interval::closed(0.5, 1.0) });
    }
    // w = 1 - y exactly.
    let w_exact = exact_sub(&Float::with_val(2, 1), y);
    meijer_g_k_near_one_ball(&MeijerConstants::cached(k, wp)?, &Ball::from_float(&w_exact, wp), wp)
}

/// [`meijer_g_k_near_one`] for `w = 1 - y` known only as a ball with
/// `0 <= w <= 1/2` (a lower end below zero is clipped: the true `w` is `>= 0`).
pub fn meijer_g_k_near_one_ball(consts: &MeijerConstants, w: &Ball, wp: u32) -> Result<Ball> {
    crate::error::check_working_prec(wp)?;
    let k = consts.k;
    let w = if w.lower() < 0 { Ball::hull(&Float::new(wp), &w.upper(), wp) } else { w.clone() };
    if w.upper() > 0.5 {
        return Err(Error::OutOfRange { arg: "w = 1 - y (the near-one expansion)", value: w.upper().to_f64(), allowed: Interval::closed(0.0, 0.5) });
    }
    let kw = (k as f64) * w.upper().to_f64();
    let kk = k as i64;
    let w_up = w.abs_upper_mag();
    let one = Mag::from_f64(1.0);
    // Integer ratios as Mag bounds (the integers are exact doubles).
    let ratio = |num: i64, den: i64| Mag::from_f64(num as f64).div(Mag::from_f64(den as f64));
    // I1 = sum_j h_j w^{j+1}/(j+1), r_{j+1} = r_j (2k+1+2j)/(1+2j)
    let mut r = Ball::one(wp); // r_j
    let mut h = Ball::one(wp); // h_j
    let mut wpow = w.clone(); // w^{j+1}
    let mut i1 = Ball::zero(wp);
    let mut j: i64 = 0;
    loop {
        i1 = i1.add(&h.mul(&wpow).div_i64(j + 1)?);
        r = r.mul_i64(2 * kk + 1 + 2 * j).div_i64(1 + 2 * j)?;
        h = h.add(&r);
        wpow = wpow.mul(&w);
        j += 1;
        // tail from index j <= r_j w^{j+1} / (1 - rho), rho = w (2k+1+2j)/(1+2j)
        if (j as f64) > kw {
            let rho = w_up.mul(ratio(2 * kk + 1 + 2 * j, 1 + 2 * j));
            let one_minus = one.sub_lower(rho);
            if !one_minus.is_zero() {
                let tail = r.abs_upper_mag().mul(wpow.abs_upper_mag()).div(one_minus);
                if tail.le(&i1.abs_upper_mag().mul_2exp(-(wp as i64) - 4)) {
                    i1.add_error_mag(tail);
                    break;
                }
            }
        }
        if j > 50_000_000 {
            return Err(Error::NoConvergence { function: "meijer_g_k (near one, I1)", terms: j as u64 });
        }
    }
    // I2 = w^{3/2} sum_j c_j w^j / (j + 3/2), c_{j+1} = c_j (k+2+j)/(j+1)
    let mut cj = Ball::one(wp);
    let mut wj = Ball::one(wp);
    let mut sum2 = Ball::zero(wp);
    let mut j: i64 = 0;
    loop {
        sum2 = sum2.add(&cj.mul(&wj).mul_pow2(1).div_i64(2 * j + 3)?);
        cj = cj.mul_i64(kk + 2 + j).div_i64(j + 1)?;
        wj = wj.mul(&w);
        j += 1;
        if (j as f64) > kw {
            // term ratio <= w (k+2+j)/(j+1), decreasing in j
            let rho = w_up.mul(ratio(kk + 2 + j, j + 1));
            let one_minus = one.sub_lower(rho);
            if !one_minus.is_zero() {
                let next = cj.abs_upper_mag().mul(wj.abs_upper_mag()).mul(ratio(2, 2 * j + 3));
                let tail = next.div(one_minus);
                if tail.le(&sum2.abs_upper_mag().mul_2exp(-(wp as i64) - 4)) {
                    sum2.add_error_mag(tail);
                    break;
                }
            }
        }
        if j > 50_000_000 {
            return Err(Error::NoConvergence { function: "meijer_g_k (near one, I2)", terms: j as u64 });
        }
    }
    let i2 = w.sqrt()?.mul(&w).mul(&sum2);
    let ck = &consts.c_k;
    let two_sqrt_pi = Ball::pi(wp).sqrt()?.mul_pow2(1);
    let at_one = ck.mul(&consts.bracket_at_one);
    Ok(at_one.add(&ck.mul_i64(kk + 1).mul(&i1)).sub(&two_sqrt_pi.mul(&i2)))
}

/// `G(k, 1) = C_k B(1)`.
pub fn meijer_g_k_at_one(k: u32, wp: u32) -> Result<Ball> {
    crate::error::check_working_prec(wp)?;
    Ok(meijer_g_k_at_one_with(&MeijerConstants::cached(k, wp)?))
}

/// `G(k, 1) = C_k B(1)` from precomputed constants.
pub fn meijer_g_k_at_one_with(consts: &MeijerConstants) -> Ball {
    consts.c_k.mul(&consts.bracket_at_one)
}

