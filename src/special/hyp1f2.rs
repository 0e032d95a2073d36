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

use crate::ball::Ball;
use crate::error::Result;
use crate::special::exact;
use crate::special::pfq::{hyp_pfq, hyp_pfq_mp};

/// Certified `1F2(a; b1, b2; z)` with `rad <= 2^-prec |mid|`.
pub fn hyp1f2_mp(a: &Float, b1: &Float, b2: &Float, z: &Float, prec: u32) -> Result<Ball> {
    hyp_pfq_mp(std::slice::from_ref(a), &[b1.clone(), b2.clone()], z, prec)
}

/// `1F2(a; b1, b2; z)` in f64, within `1e-14` relative.
pub fn hyp1f2(a: f64, b1: f64, b2: f64, z: f64) -> Result<f64> {
    hyp_pfq(&[a], &[b1, b2], z)
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
    fn bad_input() {
        assert!(hyp1f2(0.5, -1.0, 2.0, 1.0).is_err());
        assert!(hyp1f2(0.5, 1.0, 2.0, f64::INFINITY).is_err());
    }
}
