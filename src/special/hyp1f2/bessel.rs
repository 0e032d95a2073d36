//! The model family `F_k(-x^2) = 1F2(1/2; k+1, k+3/2; -x^2)` at large `x` through
//! `J_0`, `J_1` and the Struve-type functions `H_nu - Y_nu` (certified, MP).
//!
//! # Method
//!
//! With `(1/2)_n/((k+1)_n (k+3/2)_n n!) = C(2n, n) (2k+1)!/(4^n (2k+1+2n)!)` and
//! `(2k)!/(2k+1+2n)! = int_0^1 (1-t)^{2k} t^{2n}/(2n)! dt`, summing under the
//! integral gives `sum_n (-x^2 t^2)^n/(n!)^2 = J_0(2 x t)` [DLMF 10.2.2], so
//!
//! ```text
//! F_k(-x^2) = (2k+1) int_0^1 (1-t)^{2k} J_0(y t) dt,   y = 2x,
//!           = (2k+1) sum_{j=0}^{2k} C(2k, j) (-1)^j m_j,   m_j = y^{-j-1} int_0^y u^j J_0(u) du.
//! ```
//!
//! The moments obey (integrate `d/du[u^j J_1] = (j-1) u^{j-1} J_1 + u^j J_0` and
//! `d/du[u^{j-1} J_0] = (j-1) u^{j-2} J_0 - u^{j-1} J_1`, DLMF 10.6.2)
//!
//! ```text
//! m_0 = Lambda(y)/y,  m_1 = J_1(y)/y,
//! m_j = J_1(y)/y + (j-1) J_0(y)/y^2 - (j-1)^2 m_{j-2}/y^2   (j >= 2),
//! ```
//!
//! where `Lambda(y) = int_0^y J_0`. By DLMF 10.22.2 (`int_0^y J_0 = y J_0 +
//! (pi y/2)(J_1 H_0 - J_0 H_1)`), `H_nu = Y_nu + K_nu` [DLMF 11.2.5, `K_nu` the
//! Struve function `H_nu - Y_nu`] and the Wronskian `J_1 Y_0 - J_0 Y_1 = 2/(pi y)`
//! [DLMF 10.5.2],
//!
//! ```text
//! Lambda(y) = 1 + J_1(y) U(y) - y J_0(y) V(y),
//! U = (pi y/2) K_0(y) = sum_{k>=0} u_k,  u_0 = 1, u_{k+1} = -u_k (2k+1)^2/y^2,
//! V = (pi/2) K_1(y) - 1 = sum_{k>=1} v_k,  v_0 = 1, v_{k+1} = v_k (1-2k)(2k+1)/y^2.
//! ```
//!
//! `U` and `V` are the asymptotic expansions of DLMF 11.6.1;
//! splitting off `v_0 = 1` removes the cancellation between `y J_0` and
//! `(pi y/2) J_0 K_1` (both about `y^{1/2}`, their difference `y^{-3/2}`).
//!
//! # Remainder bound (proof)
//!
//! DLMF 11.5.2: `K_nu(y) = 2 (y/2)^nu/(sqrt(pi) Gamma(nu+1/2)) int_0^inf e^{-y t} (1+t^2)^{nu-1/2} dt`
//! for `y > 0`. Taylor's theorem with the Lagrange remainder for `(1+w)^alpha`,
//! `alpha = nu - 1/2`, `w = t^2 >= 0`, after `p` terms:
//! `R_p(w) = C(alpha, p) w^p (1 + theta w)^{alpha - p}` for some `theta` in `(0, 1)`.
//! For `p >= alpha` (here `p >= 1` for `nu = 0, 1`) the last factor lies in
//! `(0, 1]`, so `R_p(w)` has the sign of the next term and at most its size.
//! Integrating against `e^{-y t} > 0` (`int_0^inf e^{-yt} t^{2p} dt = (2p)!/y^{2p+1}`):
//! the remainder of `U` after `p >= 1` terms is at most `|u_p|` and that of
//! `sum v_k` after its terms `1..p-1` at most `|v_p|` (DLMF 11.6(i) states the
//! same). Every term and both remainders are evaluated in ball arithmetic over the
//! ball of `y = 2 sqrt(-z)`, so the bound holds at every point of the ball.
//! The series is stopped at the first `p >= 1` with `y |u_p| <= 2^-(wp+4)`
//! (`|v_p| <= |u_p|` term by term, since `(2k-1)(2k+1) < (2k+1)^2`); if the terms
//! start growing (`2p + 1 >= y`) first, the route does not apply at this
//! precision (about `y < 0.7 wp`) and the caller sums the `1F2` series instead.
//!
//! `J_0(y)`, `J_1(y)` are certified over the ball of `y`
//! ([`crate::special::bessel_j`]'s ball-input path, Hankel's expansion at large `y`).
//!
//! # Cancellation and cost
//!
//! `Lambda -> 1` and `F_k ~ (k+1/2)/x`: `Lambda` loses no bits beyond the
//! `log2 y` of the input ball; the binomial sum loses up to about `2k` bits
//! (`sum_j C(2k, j) = 4^k`) and the moment recurrence grows by `(j-1)^2/y^2` per
//! step, so the route is offered for `4k <= y` only. The Ziv loop of the caller
//! raises the working precision if the ball falls short. Cost: two Bessel
//! values plus about `min(wp, y)` terms of `U`, `V`, against the series' roughly
//! `e x` terms at `wp + 2.9 x` bits (its cancellation `e^{2x}`): at
//! `z = -10^6` (`x = 1000`), 4200 bits of guard for the series.

use rug::Float;

use crate::ball::{Ball, Mag};
use crate::error::Result;
use crate::special::bessel_j::bessel_j_ball_input;

/// Whether the asymptotic series of `U`, `V` reaches `y |u_p| <= 2^-(wp+4)`
/// before its terms grow, for `y = 2 x` (an f64 estimate with 8 bits of margin;
/// the ball evaluation checks again and returns `None` when it does not).
pub(crate) fn applies(k: u64, y: f64, wp: u32) -> bool {
    if !(y.is_finite() && y > 0.0) || (4 * k) as f64 > y {
        return false;
    }
    let target = -(wp as f64) - 12.0 - y.log2();
    let mut log_u = 0.0f64;
    let mut j = 0.0f64;
    while 2.0 * j + 1.0 < y {
        log_u += 2.0 * ((2.0 * j + 1.0) / y).log2();
        j += 1.0;
        if log_u <= target {
            return true;
        }
    }
    false
}

/// `F_k(z) = 1F2(1/2; k+1, k+3/2; z)` for `z < 0` at working precision `wp` by the
/// module's Bessel route: a ball that encloses the value, or `None` where the
/// asymptotic series of `U`, `V` does not reach `2^-(wp+4)` (the caller then
/// uses the series). The ball's radius carries every rounding and both remainders.
pub(crate) fn model_family_bessel(k: u64, z: &Float, wp: u32) -> Result<Option<Ball>> {
    let y = Ball::from_float(z, wp).neg().sqrt()?.mul_pow2(1);
    if !applies(k, y.to_f64(), wp) {
        return Ok(None);
    }
    let j0 = bessel_j_ball_input(0, &y, wp)?;
    let j1 = bessel_j_ball_input(1, &y, wp)?;
    let inv_y = y.recip()?;
    let inv_y2 = inv_y.sqr();
    // U = sum_{k>=0} u_k, V = sum_{k>=1} v_k
    let mut u = Ball::one(wp);
    let mut v = Ball::one(wp);
    let mut sum_u = Ball::one(wp);
    let mut sum_v = Ball::zero(wp);
    let target = Mag::pow2(-(wp as i64) - 4);
    let y_up = y.abs_upper_mag();
    let mut p: i64 = 0;
    loop {
        // u_{p+1} = -u_p (2p+1)^2 / y^2, v_{p+1} = v_p (1-2p)(2p+1) / y^2
        u = u.mul(&inv_y2).mul_i64(-(2 * p + 1) * (2 * p + 1));
        v = v.mul(&inv_y2).mul_i64((1 - 2 * p) * (2 * p + 1));
        p += 1;
        let u_up = u.abs_upper_mag();
        if y_up.mul(u_up).le(&target) {
            // remainders after p >= 1 terms: |R_U| <= |u_p|, |R_V| <= |v_p|
            sum_u.add_error_mag(u_up);
            sum_v.add_error_mag(v.abs_upper_mag());
            break;
        }
        if y.lower() <= Float::with_val(64, 2 * p + 1) {
            return Ok(None);
        }
        sum_u = sum_u.add(&u);
        sum_v = sum_v.add(&v);
    }
    // Lambda = 1 + J1 U - y J0 V
    let lambda = j1.mul(&sum_u).sub(&y.mul(&j0).mul(&sum_v)).add_i64(1);
    let m0 = lambda.mul(&inv_y);
    if k == 0 {
        return Ok(Some(m0));
    }
    // moments m_j, j = 0..=2k, and the alternating binomial sum
    let j1_y = j1.mul(&inv_y);
    let j0_y2 = j0.mul(&inv_y2);
    let two_k = 2 * k as i64;
    let mut prev2 = m0.clone(); // m_{j-2}
    let mut prev1 = j1_y.clone(); // m_{j-1}
    let mut binom = Ball::one(wp);
    let mut total = m0;
    for j in 1..=two_k {
        let mj = if j == 1 {
            j1_y.clone()
        } else {
            let m = j1_y.add(&j0_y2.mul_i64(j - 1)).sub(&prev2.mul(&inv_y2).mul_i64((j - 1) * (j - 1)));
            prev2 = std::mem::replace(&mut prev1, m.clone());
            m
        };
        binom = binom.mul_i64(two_k - j + 1).div_i64(j)?;
        let term = binom.mul(&mj);
        total = if j % 2 == 1 { total.sub(&term) } else { total.add(&term) };
    }
    Ok(Some(total.mul_i64(two_k + 1)))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::special::exact;
    use crate::special::pfq::pfq_series;

    #[test]
    fn overlaps_the_series_where_both_apply() {
        let wp = 160;
        for &x in &[130.0f64, 200.25, 517.0] {
            let z = exact(-x * x);
            for k in [0u64, 1, 2, 5, 17] {
                let b = model_family_bessel(k, &z, wp).unwrap().unwrap_or_else(|| panic!("k={k} x={x}: route did not apply"));
                let kb = Ball::from_i64(k as i64, 2000);
                let half = Ball::from_ratio(1, 2, 2000);
                let s = pfq_series(&[half.clone()], &[kb.add_i64(1), kb.add(&half).add_i64(1)], &Ball::from_float(&z, 2000), 2000).unwrap().sum;
                assert!(b.overlaps(&s), "k={k} x={x}: {b:?} vs {s:?}");
                assert!(b.rel_accuracy_bits() >= (wp - 2 * k as u32 - 16) as f64, "k={k} x={x}: {b:?}");
            }
        }
    }

    #[test]
    fn declines_where_the_asymptotic_series_is_short() {
        // y = 20: the minimal term of U is about e^-20, far above 2^-128
        assert!(model_family_bessel(0, &exact(-100.0), 128).unwrap().is_none());
        // 4k > y
        assert!(model_family_bessel(200, &exact(-1e6), 128).unwrap().is_some());
        assert!(model_family_bessel(600, &exact(-1e6), 128).unwrap().is_none());
    }
}

#[cfg(test)]
mod edge_tests {
    use crate::special::exact;
    use crate::special::hyp1f2::{hyp1f2_bounded, hyp1f2_mp};

    #[test]
    fn huge_negative_z_answers_or_refuses_without_panic() {
        for &z in &[-1e12, -1e30, -1e300, -f64::MAX] {
            for prec in [53u32, 128] {
                match hyp1f2_mp(&exact(0.5), &exact(1.0), &exact(1.5), &exact(z), prec) {
                    Ok(b) => {
                        assert!(b.meets_rel(prec), "z={z}: {b:?}");
                        // leading term (k+1/2)/x with k = 0
                        let lead = 0.5 / (-z).sqrt();
                        assert!((b.to_f64() / lead - 1.0).abs() < 1e-3, "z={z}: {b:?}");
                    }
                    Err(e) => eprintln!("z={z} prec={prec}: {e}"),
                }
            }
            let _ = hyp1f2_bounded(0.5, 1.0, 1.5, z);
        }
    }
}
