//! The hypergeometric function `1F2(a; b1, b2; z)`, real parameters, real `z`.
//!
//! # Method
//!
//! `1F2` is entire in `z` [DLMF 16.2]. Its series
//! `sum_n (a)_n z^n / ((b1)_n (b2)_n n!)` is summed by the pFq core
//! ([`crate::special::pfq`]) in ball arithmetic, with the core's rigorous tail
//! bound: for `n >= N` the term ratio is at most
//! `|z| max(1, (a^+ + N)/(b^- + N)) / (b'^- + N)` (numerator paired with the larger
//! lower parameter), so the tail is geometric once `N` passes `|z|/b'`.
//!
//! # Cancellation and why the Ziv loop matters
//!
//! For `z < 0` the terms alternate and grow to about
//! `sum |t_n| = 1F2(|a|; b1, b2; |z|) ~ exp(3 |z|^{1/3})` (for `a`, `b` of order
//! one) before they decay, while the value stays of order `|z|^{-a}` or smaller.
//! At the model's `z = -(pi abar / beta)^2 ~ -300`, `b1 = 1`, `b2 = 3/2` this
//! loses about 50 bits; at `z = -10^4` about 93. Arb's `arb_hypgeom_pfq`
//! at 103 bits returns `1F2(1/2; 3/2, 2; -300)` with 42 bits lost and nothing
//! correct at `-3000`, because it does not raise its working precision. Here a
//! cheap f64 pass measures `log2(sum |t_n| / |sum|)` and the Ziv loop adds it as
//! guard bits, raising further until `rad <= 2^-prec |mid|` is certified.
//!
//! # Model case
//!
//! Eq. 12 of the seed paper uses `1F2(1/2; k+1, k+3/2; -(pi a/zeta)^2)` with
//! `k <= 1000`; there the parameters grow with `k` and the cancellation shrinks
//! (`~ 2 |z|^{1/2} / (k+1)` nats), so large `k` is cheap.
//!
//! # Accuracy
//!
//! * MP: certified, `rad <= 2^-prec |mid|`.
//! * f64: the f64 series is returned when its error estimate is below
//!   [`F64_TRUST`](crate::special::pfq::F64_TRUST) relative (no significant
//!   cancellation); otherwise the certified 64-bit value, rounded. Tolerance
//!   `1e-14` relative.
//!
//! Domain: finite real parameters with `b1, b2` not non-positive integers
//! (unless the series terminates first), finite real `z`; `|z| <= 10^4` is tested.

use rug::Float;

use crate::ball::{Ball, Bounded};
use crate::error::Result;
use crate::special::exact;
use crate::special::pfq::{hyp_pfq, hyp_pfq_mp};

/// The seed's family `1F2(1/2; k+1, k+3/2; -s)` (Eq. 11b, 12, C.39) at working
/// precision `wp`, for `s >= 0` given as a ball.
///
/// The term ratio is the rational `-s (2n+1)/((k+1+n)(2k+3+2n)(n+1))`, so each
/// term costs one ball multiplication and two exact-integer scalings instead of
/// the generic core's parameter arithmetic. **Tail bound**: the ratio's modulus
/// `s (2n+1)/((k+1+n)(2k+3+2n)(n+1))` decreases in `n`, so once its value
/// `rho_N < 1`, `sum_{n>=N} |t_n| <= |t_N|/(1 - rho_N)`. Compared with the
/// generic pFq core in the tests.
pub fn hyp1f2_model_ball(k: u32, s: &Ball, wp: u32) -> Result<Ball> {
    use crate::ball::Mag;
    use crate::error::Error;
    let neg_s = s.neg();
    let s_up = s.abs_upper_mag();
    let kk = k as i64;
    let mut t = Ball::one(wp);
    let mut sum = Ball::one(wp);
    let mut n: i64 = 0;
    loop {
        let den = (kk + 1 + n)
            .checked_mul(2 * kk + 3 + 2 * n)
            .and_then(|v| v.checked_mul(n + 1))
            .ok_or_else(|| Error::Domain { what: "1F2 model family: k too large".into() })?;
        t = t.mul(&neg_s).mul_i64(2 * n + 1).div_i64(den)?;
        n += 1;
        let t_up = t.abs_upper_mag();
        // rho_n = s (2n+1)/((k+1+n)(2k+3+2n)(n+1)), an upper bound for every later ratio
        let next_den = (kk + 1 + n) as f64 * (2 * kk + 3 + 2 * n) as f64 * (n + 1) as f64;
        let rho = s_up.mul(Mag::from_f64(((2 * n + 1) as f64).next_up())).div(Mag::from_f64(next_den.next_down()));
        let one_minus = Mag::from_f64(1.0).sub_lower(rho);
        if !one_minus.is_zero() {
            let tail = t_up.div(one_minus);
            if tail.le(&sum.abs_lower_mag().mul_2exp(-(wp as i64) - 2)) {
                sum.add_error_mag(tail);
                return Ok(sum);
            }
        }
        sum = sum.add(&t);
        if n > 100_000_000 {
            return Err(Error::NoConvergence { function: "1F2 model family", terms: n as u64 });
        }
    }
}

/// Certified `1F2(a; b1, b2; z)` with `rad <= 2^-prec |mid|`.
pub fn hyp1f2_mp(a: &Float, b1: &Float, b2: &Float, z: &Float, prec: u32) -> Result<Ball> {
    hyp_pfq_mp(std::slice::from_ref(a), &[b1.clone(), b2.clone()], z, prec)
}

/// `1F2(a; b1, b2; z)` in f64, within `1e-14` relative.
pub fn hyp1f2(a: f64, b1: f64, b2: f64, z: f64) -> Result<f64> {
    hyp_pfq(&[a], &[b1, b2], z)
}

/// `1F2(a; b1, b2; z)` in f64 with a proven error bound for the f64 inputs as given.
pub fn hyp1f2_bounded(a: f64, b1: f64, b2: f64, z: f64) -> Result<Bounded> {
    crate::special::bounded_from_ball("hyp1f2", &hyp1f2_mp_f64(a, b1, b2, z, crate::special::F64_FALLBACK_PREC)?)
}

/// Certified `1F2` at f64 arguments (convenience wrapper).
pub fn hyp1f2_mp_f64(a: f64, b1: f64, b2: f64, z: f64, prec: u32) -> Result<Ball> {
    crate::error::finite(a, "a")?;
    crate::error::finite(b1, "b1")?;
    crate::error::finite(b2, "b2")?;
    crate::error::finite(z, "z")?;
    hyp1f2_mp(&exact(a), &exact(b1), &exact(b2), &exact(z), prec)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::special::bessel_j::bessel_j_mp;

    #[test]
    fn reduces_to_bessel_squared() {
        // 1F2(1/2; 1, 1; -x^2) = J_0(x)^2 [DLMF 10.8.3 with nu = mu = 0]
        for &x in &[0.5, 3.0, 17.25] {
            let f = hyp1f2_mp_f64(0.5, 1.0, 1.0, -x * x, 150).unwrap();
            let j = bessel_j_mp(0, &exact(x), 150).unwrap();
            assert!(f.overlaps(&j.sqr()), "x={x}");
        }
    }

    #[test]
    fn model_case_certified_at_minus_300() {
        // Issue acceptance: certified to full precision for every k = 0..=1000.
        for k in 0u32..=1000 {
            let kf = k as f64;
            let b = hyp1f2_mp_f64(0.5, kf + 1.0, kf + 1.5, -300.0, 128).unwrap();
            assert!(b.meets_rel(128), "k={k}");
        }
    }

    #[test]
    fn f64_close_to_mp() {
        for &(a, b1, b2, z) in &[(0.5, 1.0, 1.5, -300.0), (0.5, 11.0, 11.5, -300.0), (1.25, 2.5, 3.75, 40.0)] {
            let v = hyp1f2(a, b1, b2, z).unwrap();
            let m = hyp1f2_mp_f64(a, b1, b2, z, 80).unwrap().to_f64();
            assert!((v - m).abs() <= 1e-14 * m.abs(), "{a} {b1} {b2} {z}: {v} vs {m}");
        }
    }

    #[test]
    fn model_family_routine_matches_the_pfq_core() {
        use crate::special::pfq::pfq_series;
        let wp = 200;
        for &s in &[0.0, 0.75, 30.0, 280.5, 2000.0] {
            for k in [0u32, 1, 7, 60, 999] {
                let sb = Ball::from_f64(s, wp).unwrap();
                let fast = hyp1f2_model_ball(k, &sb, wp).unwrap();
                let kb = Ball::from_i64(k as i64, wp);
                let half = Ball::from_ratio(1, 2, wp);
                let generic = pfq_series(&[half.clone()], &[kb.add_i64(1), kb.add(&half).add_i64(1)], &sb.neg(), wp).unwrap().sum;
                assert!(fast.overlaps(&generic), "k={k} s={s}: {fast:?} vs {generic:?}");
            }
        }
    }

    #[test]
    fn bad_input() {
        assert!(hyp1f2(0.5, -1.0, 2.0, 1.0).is_err());
        assert!(hyp1f2(0.5, 1.0, 2.0, f64::INFINITY).is_err());
    }
}
