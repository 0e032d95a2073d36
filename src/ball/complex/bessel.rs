//! `J_n(z)` for a complex ball `z` and any integer order `n`.
//!
//! # Method
//!
//! * `n < 0`: `J_{-n} = (-1)^n J_n` (DLMF 10.4.1).
//! * Real `z` (imaginary part exactly zero): the crate's certified real-argument
//!   [`crate::special::bessel_j::bessel_j_mp`] machinery at the midpoint `m` (Hankel,
//!   recurrence or series by cost), widened by the input radius `r`: `|J_n'(x)| <= 1`
//!   on the real line (DLMF 10.6.1 with 10.14.1), so `J_n([m +/- r]) ⊂ [J_n(m) +/- (rad + r)]`.
//! * Complex `z`: the power series (DLMF 10.2.2)
//!   `J_n(z) = sum_k (-1)^k (z/2)^(2k+n) / (k! (k+n)!)`
//!   in complex ball arithmetic, `t_{k+1} = t_k * (-(z/2)^2) / ((k+1)(k+n+1))`. The sum
//!   stops at the first `K` with `q_K = |z|^2 / (4 (K+1)(K+n+1)) <= 1/2` (so every later
//!   ratio is `<= 1/2` too) and `|t_K| <= 2^-wp |sum|`; the tail is then at most
//!   `|t_K| / (1 - 1/2) = 2 |t_K|` (`|t_K|` bounded over the whole rectangle), added to both
//!   radii.
//!
//! # Precision and cost
//!
//! The terms grow to about `e^|z|` (their sum of moduli is `I_n(|z|)`) while
//! `|J_n(z)| ~ e^|Im z| / sqrt|z|` (DLMF 10.7.8), so the series cancels about
//! `(|z| - |Im z|) log2 e` bits. The sum runs at `wp = prec + (|z| - |Im z|) log2 e + 20`
//! bits over about `e|z|/2 + wp / log2(...)` terms: cost grows like `|z|` times an MPFR
//! multiplication at `wp` bits, i.e. roughly quadratically in `|z|` once `|z|` dominates
//! `prec` (`|z| = 1000` near the real axis means ~1500 extra bits and ~1500 terms).
//! That is correct but slow for large `|z|` off the real axis; an asymptotic (Hankel)
//! expansion for complex `z` is not implemented. Orders `n > 2^20` give the
//! indeterminate ball.
//!
//! `|J_n(x)| <= 1` for real `x` (DLMF 10.14.1) is used only for the real path's
//! derivative bound; the complex path needs no a-priori bound.

use super::CBall;
use crate::ball::{Ball, Mag};

/// Largest order handled by the series.
const MAX_ORDER: u64 = 1 << 20;

impl CBall {
    /// `J_n(z)` for every `z` in the rectangle; indeterminate for non-finite input or
    /// when the cost guard of the real path refuses.
    pub fn bessel_j(&self, n: i64) -> CBall {
        let p = self.prec();
        if !self.is_finite() {
            return CBall::indeterminate(p);
        }
        if self.is_real() {
            return match crate::special::bessel_j::bessel_j_ball(n, self.re().mid(), p) {
                Ok(mut b) => {
                    b.add_error_mag(self.re().rad_mag());
                    CBall::from_real(b)
                }
                Err(_) => CBall::indeterminate(p),
            };
        }
        let m = n.unsigned_abs();
        if m > MAX_ORDER {
            return CBall::indeterminate(p);
        }
        let j = self.bessel_j_series(m);
        if n < 0 && m % 2 == 1 {
            j.neg()
        } else {
            j
        }
    }

    /// The power series of `J_m(z)`, `m >= 0`, at a raised working precision.
    fn bessel_j_series(&self, m: u64) -> CBall {
        let p = self.prec();
        let zmax = self.abs_upper_mag();
        let zf = zmax.to_f64_up();
        let yf = self.im().abs_lower_mag().to_f64_up().min(zf);
        let loss = ((zf - yf) * std::f64::consts::LOG2_E).ceil();
        if !(loss < 1.0e7) {
            return CBall::indeterminate(p);
        }
        let wp = p + loss as u32 + 20 + (64 - m.leading_zeros());
        let z = self.set_prec(wp);
        let h = z.mul_pow2(-1);
        let w = h.sqr().neg();
        // t_0 = (z/2)^m / m!
        let mut t = h.pow_u64(m);
        if m > 1 {
            let f = Ball::factorial(m as u32, wp);
            t = t.div(&CBall::from_real(f));
        }
        let mut sum = t.clone();
        // |z|^2 / 4, rounded up
        let z2_4 = zmax.mul(zmax).mul_2exp(-2);
        let max_terms = 4 * (zf as u64 + wp as u64) + 100;
        let eps = Mag::pow2(-(wp as i64));
        let mut k: u64 = 0;
        loop {
            // t <- t_{k+1}
            let (a, b) = (k + 1, k + m + 1);
            t = t.mul(&w);
            t = match (a as i64).checked_mul(b as i64) {
                Some(ab) if ab < (1i64 << 53) => div_int(&t, ab),
                _ => div_int(&div_int(&t, a as i64), b as i64),
            };
            k += 1;
            if !t.is_finite() {
                return CBall::indeterminate(p);
            }
            // q_k = |z|^2 / (4 (k+1)(k+m+1)) <= 1/2 ?
            let d = Mag::from_f64((((k + 1) as f64) * ((k + m + 1) as f64)).next_down());
            let q_ok = z2_4.div(d).le(&Mag::pow2(-1));
            let tk = t.abs_upper_mag();
            if q_ok && (tk.le(&eps.mul(sum.abs_upper_mag())) || k > max_terms) {
                sum.add_error_mag(tk.mul_2exp(1));
                break;
            }
            if k > 4 * max_terms {
                return CBall::indeterminate(p);
            }
            sum = sum.add(&t);
        }
        let r = sum.set_prec(p);
        if r.is_finite() {
            r
        } else {
            CBall::indeterminate(p)
        }
    }
}

/// `z / n` for a positive integer `n`.
fn div_int(z: &CBall, n: i64) -> CBall {
    match (z.re().div_i64(n), z.im().div_i64(n)) {
        (Ok(a), Ok(b)) => CBall::new(a, b),
        _ => CBall::indeterminate(z.prec()),
    }
}
