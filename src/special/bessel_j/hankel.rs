//! `J_n(x)` by Hankel's asymptotic expansion for large `x`, with a remainder
//! bound valid for every truncation index.
//!
//! # Method
//!
//! [DLMF 10.17.3, 10.17.13]: for real `x > 0` and integer `n >= 0`,
//! `J_n(x) = Re H^(1)_n(x)` and
//! `H^(1)_n(x) = sqrt(2/(pi x)) e^{i w} (sum_{k<l} i^k a_k(n) x^{-k} + R_l)`,
//! `w = x - n pi/2 - pi/4`, with
//! `a_k(n) = prod_{j=1..k} (4n^2 - (2j-1)^2) / (k! 8^k)` [DLMF 10.17.1]. So
//!
//! `J_n(x) = sqrt(2/(pi x)) (cos(w) P - sin(w) Q + Re(e^{i w} R_l))`,
//! `P = sum_{2k<l} (-1)^k a_{2k} x^{-2k}`, `Q = sum_{2k+1<l} (-1)^k a_{2k+1} x^{-2k-1}`.
//!
//! **Remainder** [DLMF 10.17.14 with 10.17.15, Olver (1997) ch. 7 §13]:
//! `|R_l| <= 2 |a_l(n)| V(t^{-l}) exp(|n^2 - 1/4| V(t^{-1}))`, and on the real
//! axis (`ph x = 0`) the variations are `V(t^{-l}) <= x^{-l}`, so
//!
//! `|R_l| <= 2 |a_l(n) x^{-l}| exp(|n^2 - 1/4| / x)` for every `l >= 0`.
//!
//! (The same bound follows from DLMF 10.40.10-11 for `K_n(-ix)`, `|ph| = pi/2`,
//! through `H^(1)_n(x) = (2/(pi i)) e^{-n pi i/2} K_n(-ix)` [DLMF 10.27.8], and
//! from DLMF 13.7.4 for `U(n+1/2, 2n+1, -2ix)` in region R1 with `sigma = 0`,
//! `rho = |n^2 - 1/4|`.) Unlike the real-axis bound
//! of 10.17(iii) it needs no `l >= n/2`, so the sum can stop as soon as the
//! term is small: at `x ~ n^2/10` that is a few hundred terms instead of `n`.
//! The price is the factor `exp(n^2/x)`, paid in guard bits.
//!
//! The terms grow while `4n^2 - (2k+1)^2 > 8 (k+1) x` (about `k < n^2/(2x)`),
//! then fall, and diverge again once `(2k+1)^2 - 4n^2 > 8 (k+1) x`. [`plan`]
//! follows `log2 |a_k x^-k|` in f64 to find the first `l` whose bound is below
//! the target, the peak term (bits lost to cancellation in `P`, `Q`) and the
//! cost; the chooser in [`super`] compares it with the power series.

use rug::float::Round;
use rug::Float;

use crate::ball::{Ball, Mag};
use crate::error::{Error, Result};

/// Most terms the expansion is allowed (beyond that the series or another method is cheaper).
pub(crate) const MAX_HANKEL_TERMS: u64 = 200_000;

/// What the expansion costs at `(n, x, wp)`, from f64 estimates.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct HankelPlan {
    /// Terms to sum.
    pub terms: u64,
    /// `log2` of the largest term (bits lost to cancellation).
    pub peak_bits: f64,
    /// `log2 exp(|n^2 - 1/4| / x)`: bits the remainder factor costs.
    pub remainder_bits: f64,
}

/// `log2 exp(|n^2 - 1/4| / x)`, rounded up (a few ulps of margin).
fn remainder_log2(n: u64, x: f64) -> f64 {
    let nf = n as f64;
    let v = (nf * nf - 0.25).abs() / x * std::f64::consts::LOG2_E;
    v * (1.0 + 1e-12) + 1e-300
}

/// The f64 plan: only for `x >= n` (below, the remainder factor `exp(n^2/x)`
/// costs more than `1.44 n` bits and the power series is cheaper; without this
/// cut the f64 walk would follow up to `n` terms to find them diverging):
/// first `l` with `log2|a_l x^-l| + 1 + remainder_bits <= -wp`, or
/// `None` when the terms diverge first (or the count passes [`MAX_HANKEL_TERMS`]).
pub(crate) fn plan(n: u64, x: f64, wp: u32) -> Option<HankelPlan> {
    if !(x > 0.0) {
        return None;
    }
    let four_n2 = 4.0 * (n as f64) * (n as f64);
    let remainder_bits = remainder_log2(n, x);
    if x < n as f64 {
        return None;
    }
    let target = -(wp as f64) - 1.0 - remainder_bits - 2.0; // 2 bits of f64 slack
    // The term is m 2^e (f64 mantissa product, renormalised by log2 only when it
    // leaves [2^-400, 2^400]): one multiplication per term instead of a log2.
    let mut m = 1.0f64;
    let mut e = 0.0f64;
    let mut peak_m = 1.0f64;
    let mut peak = 0.0f64;
    let mut threshold = target.exp2();
    for k in 0..MAX_HANKEL_TERMS {
        if k >= 1 && m <= threshold {
            return Some(HankelPlan { terms: k, peak_bits: peak.max(peak_m.log2() + e), remainder_bits });
        }
        let odd = (2 * k + 1) as f64;
        let ratio = (four_n2 - odd * odd).abs() / (8.0 * (k + 1) as f64 * x);
        if (k as f64) > n as f64 && ratio >= 1.0 {
            return None;
        }
        m *= ratio;
        peak_m = peak_m.max(m);
        if !(RENORM_LOW..=RENORM_HIGH).contains(&m) {
            if m == 0.0 {
                return None; // a zero term: 4n^2 = (2k+1)^2 cannot happen for integer n; defensive
            }
            peak = peak.max(peak_m.log2() + e);
            let l = m.log2().floor();
            e += l;
            m = (m.log2() - l).exp2();
            peak_m = m;
            threshold = (target - e).exp2();
        }
    }
    None
}

/// Renormalisation range of the plan's f64 mantissa.
const RENORM_LOW: f64 = 1.0 / (1u128 << 100) as f64 / (1u128 << 100) as f64 / (1u128 << 100) as f64 / (1u128 << 100) as f64;
const RENORM_HIGH: f64 = 1.0 / RENORM_LOW;

/// `J_n(x)` by Hankel's expansion at working precision `wp` (`x > 0`), summed
/// until the remainder bound is below `2^-wp`; `None` if the terms diverge first.
pub fn bessel_j_hankel(n: u64, x: &Float, wp: u32) -> Result<Option<Ball>> {
    crate::error::check_working_prec(wp)?;
    let xb = Ball::from_float(x, wp);
    let n_i = i64::try_from(n).map_err(|_| Error::IntegerOutOfRange { arg: "n", value: i64::MAX, min: 0, max: i64::MAX })?;
    let four_n2 = 4i128 * (n_i as i128) * (n_i as i128);
    let inv_8x = xb.mul_i64(8).recip()?;
    // exp(|n^2 - 1/4| / x) <= 2^e with e from the lower end of x (x is exact here,
    // its f64 rounding downward is a lower bound).
    let x_lo = x.to_f64_round(Round::Down);
    let e_bits = remainder_log2(n, x_lo).ceil();
    if !e_bits.is_finite() || e_bits > 1e9 {
        return Ok(None);
    }
    let remainder_factor = Mag::pow2(e_bits as i64 + 1); // 2 exp(|n^2-1/4|/x)
    let target = Mag::pow2(-(wp as i64));
    let mut term = Ball::one(wp); // (-1)^{floor(k/2)} a_k x^-k, signs folded in below
    let mut p = Ball::zero(wp);
    let mut q = Ball::zero(wp);
    let mut prev = term.abs_upper_mag();
    let remainder: Mag;
    let mut k: u64 = 0;
    loop {
        let t_abs = term.abs_upper_mag();
        if k >= 1 && t_abs.mul(remainder_factor).le(&target) {
            remainder = t_abs.mul(remainder_factor);
            break;
        }
        if k > n && prev.le(&t_abs) && k >= 2 {
            return Ok(None);
        }
        if k >= MAX_HANKEL_TERMS {
            return Ok(None);
        }
        prev = t_abs;
        let signed = if (k / 2) % 2 == 1 { term.neg() } else { term.clone() };
        if k % 2 == 0 {
            p = p.add(&signed);
        } else {
            q = q.add(&signed);
        }
        // a_{k+1} x^{-k-1} = a_k x^-k (4n^2 - (2k+1)^2) / (8 (k+1) x)
        let odd = (2 * k as i128 + 1) * (2 * k as i128 + 1);
        let num = four_n2 - odd;
        term = match i64::try_from(num) {
            Ok(v) => term.mul_i64(v),
            Err(_) => term.mul(&Ball::from_float(&Float::with_val(128, rug::Integer::from(num)), wp)),
        };
        term = term.mul(&inv_8x).div_i64(k as i64 + 1)?;
        k += 1;
    }
    // w = x - (2n+1) pi / 4
    let pi = Ball::pi(wp);
    let w = xb.sub(&pi.mul_i64(2 * n_i + 1).mul_pow2(-2));
    let (s, c) = w.sin_cos();
    let amp = Ball::from_i64(2, wp).div(&pi.mul(&xb))?.sqrt()?;
    let mut inner = c.mul(&p).sub(&s.mul(&q));
    // |Re(e^{iw} R_l)| <= |R_l| <= 2 |a_l x^-l| exp(|n^2-1/4|/x), whatever the phase.
    inner.add_error_mag(remainder);
    Ok(Some(amp.mul(&inner)))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn plan_matches_the_term_sizes() {
        // x >> n^2: few terms, no peak.
        let p = plan(0, 1000.0, 128).unwrap();
        assert!(p.terms < 30 && p.peak_bits == 0.0, "{p:?}");
        // n^2/(2x) = 50: a peak of ~e^50, exp(100) in the remainder, a few hundred terms.
        let p = plan(10_000, 1_000_000.5, 128).unwrap();
        assert!(p.peak_bits > 60.0 && p.peak_bits < 80.0 && p.terms < 500, "{p:?}");
        // x small against n: the terms diverge before reaching the target.
        assert!(plan(60, 30.25, 128).is_none());
    }
}
