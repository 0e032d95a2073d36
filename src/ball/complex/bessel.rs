//! `J_n(z)` for a complex ball `z` and any integer order `n`.
//!
//! # Method
//!
//! * `n < 0`: `J_{-n} = (-1)^n J_n` (DLMF 10.4.1).
//! * Real `z` (imaginary part exactly zero): the crate's certified real-argument
//!   [`crate::special::bessel_j::bessel_j_mp`] machinery at the midpoint `m` (Hankel,
//!   recurrence or series by cost), widened by the input radius `r` as in
//!   [`crate::special::bessel_j::bessel_j_ball_mp`]: relative (`~ n r / m`) before the
//!   first zeros, else `r` times a bound of `|J_n'|` over the ball (DLMF 10.6.1, 10.14.1, 10.14.4).
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

/// Rectangles with a radius above this get the disc bound instead of the series.
const WIDE_BOX: Mag = Mag::pow2_const(-2);

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
            return match crate::special::bessel_j::bessel_j_ball_input(n, self.re(), p) {
                Ok(b) => CBall::from_real(b),
                Err(_) => CBall::indeterminate(p),
            };
        }
        let m = n.unsigned_abs();
        if m > MAX_ORDER {
            return CBall::indeterminate(p);
        }
        let j = if self.rad_mag().le(&WIDE_BOX) { self.bessel_j_series(m) } else { self.bessel_j_disc(m) };
        if n < 0 && m % 2 == 1 {
            j.neg()
        } else {
            j
        }
    }

    /// The disc `|J_m(z)| <= |z/2|^m e^{|Im z|} / m!` over the rectangle (DLMF 10.14.4,
    /// `m >= 0`), as both parts' radii around 0. For wide rectangles (the integrator's
    /// ellipse boxes) it is about as tight as the series would be, at a fraction of
    /// its cost (the series would run at `|z| log2(e)` extra bits).
    fn bessel_j_disc(&self, m: u64) -> CBall {
        let p = self.prec();
        let q = 64;
        // upper bounds: |z/2|^m from the ball [0 +- |z|/2]^m, e^y from the ball [0 +- y]
        let zhalf = Ball::with_mag(rug::Float::new(q), self.abs_upper_mag().mul_2exp(-1));
        let y = Ball::with_mag(rug::Float::new(q), self.im().abs_upper_mag());
        let pow = zhalf.pow_u64(m).abs_upper_mag();
        let e = y.exp_ball().abs_upper_mag();
        let fact = if m <= u32::MAX as u64 { Ball::factorial(m as u32, q).abs_lower_mag() } else { Mag::ZERO };
        let bound = pow.mul(e).div(fact);
        if !bound.is_finite() {
            return CBall::indeterminate(p);
        }
        CBall::new(Ball::with_mag(rug::Float::new(p), bound), Ball::with_mag(rug::Float::new(p), bound))
    }

    /// The power series of `J_m(z)`, `m >= 0`, at a raised working precision.
    fn bessel_j_series(&self, m: u64) -> CBall {
        let p = self.prec();
        let zmax = self.abs_upper_mag();
        let zf = zmax.to_f64_up();
        let yf = self.im().abs_lower_mag().to_f64_up().min(zf);
        let loss = ((zf - yf) * std::f64::consts::LOG2_E).ceil();
        if loss.is_nan() || loss >= 1.0e7 {
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
            // |t| <= |Re t| + |Im t| (Mag arithmetic, no MPFR call)
            let tk = t.re().abs_upper_mag().add(t.im().abs_upper_mag());
            let sk = sum.re().abs_upper_mag().max(sum.im().abs_upper_mag());
            if q_ok && (tk.le(&eps.mul(sk)) || k > max_terms) {
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

#[cfg(test)]
mod tests {
    use super::*;
    use rug::Float;

    const RP: u32 = 1024;

    /// I_n(y) by its positive series at RP bits.
    fn bessel_i(n: u64, y: f64) -> Float {
        let h = Float::with_val(RP, y) / 2u32;
        let h2 = Float::with_val(RP, &h * &h);
        let mut t = Float::with_val(RP, rug::ops::Pow::pow(&h, n as u32)) / Float::with_val(RP, Float::factorial(n as u32));
        let mut s = t.clone();
        for k in 1..10_000u64 {
            t *= &h2;
            t /= k * (k + n);
            s += &t;
            if t.is_zero() || t.get_exp().unwrap() < s.get_exp().unwrap() - RP as i32 - 8 {
                break;
            }
        }
        s
    }

    #[test]
    fn real_argument_matches_the_real_function() {
        let p = 128;
        for n in [0i64, 1, 5, -3, 40] {
            for x in [2.5f64, -7.25, 30.0, 1e-3] {
                let z = CBall::from_f64s(x, 0.0, p);
                let j = z.bessel_j(n);
                let r = crate::special::bessel_j::bessel_j_mp(n, &Float::with_val(p, x), p).unwrap();
                assert!(j.is_real() && j.re().overlaps(&r), "J_{n}({x}) {j:?} {r:?}");
                assert!(j.re().meets_rel(120), "J_{n}({x}) {j:?}");
                // the complex series at a point just off the axis agrees
                let zc = CBall::from_f64s(x, 1e-40, p);
                let jc = zc.bessel_j(n);
                assert!(jc.re().overlaps(&r), "series J_{n}({x}) {jc:?} {r:?}");
                assert!(jc.re().meets_rel(110), "series J_{n}({x}) {jc:?}");
            }
        }
        // a real ball with a radius: |J_n'| <= 1
        let mut z = CBall::from_f64s(3.0, 0.0, p);
        z.add_error_mag(Mag::from_f64(1e-3));
        let (re, _) = z.clone().into_parts();
        let j = CBall::from_real(re).bessel_j(2);
        for t in [2.999f64, 3.0005, 3.001] {
            let r = crate::special::bessel_j::bessel_j_mp(2, &Float::with_val(p, t), p).unwrap();
            assert!(j.re().contains(r.mid()));
        }
    }

    #[test]
    fn imaginary_argument_is_i_to_the_n_times_i_n() {
        let p = 128;
        for n in [0u64, 1, 2, 3, 7] {
            for y in [0.5f64, 4.0, 25.0, -3.0] {
                let j = CBall::from_f64s(0.0, y, p).bessel_j(n as i64);
                // J_n(iy) = i^n I_n(y)
                let iv = bessel_i(n, y.abs());
                let iv = if y < 0.0 && n % 2 == 1 { -iv } else { iv };
                let (want_re, want_im) = match n % 4 {
                    0 => (iv, Float::new(RP)),
                    1 => (Float::new(RP), iv),
                    2 => (-iv, Float::new(RP)),
                    _ => (Float::new(RP), -iv),
                };
                assert!(j.contains(&want_re, &want_im), "J_{n}({y}i) {j:?}");
                let m = Float::with_val(RP, want_re.hypot_ref(&want_im));
                assert!(j.rad_mag().le(&Mag::from_float_down(&m).mul_2exp(-120)), "J_{n}({y}i) {j:?}");
            }
        }
    }

    #[test]
    fn recurrence_and_reflection_on_complex_arguments() {
        let p = 160;
        for &(x, y) in &[(3.0, 2.0), (20.0, -5.0), (0.1, 0.01), (-7.5, 0.25), (45.0, 1.0), (2.0, 60.0)] {
            let z = CBall::from_f64s(x, y, p);
            for n in [1i64, 2, 6] {
                let (a, b, c) = (z.bessel_j(n - 1), z.bessel_j(n), z.bessel_j(n + 1));
                assert!(b.is_finite());
                // J_{n-1} + J_{n+1} = (2n / z) J_n
                let lhs = a.add(&c);
                let rhs = b.mul_i64(2 * n).div(&z);
                assert!(lhs.overlaps(&rhs), "({x},{y}) n={n}: {lhs:?} {rhs:?}");
                let m = b.abs_upper_mag();
                assert!(b.rad_mag().le(&m.mul_2exp(-150)), "({x},{y}) n={n}: {b:?}");
            }
            let j3 = z.bessel_j(3);
            assert_eq!(z.bessel_j(-3), j3.neg());
            assert_eq!(z.bessel_j(-2), z.bessel_j(2));
        }
    }

    #[test]
    fn rectangles_and_odd_inputs() {
        let p = 64;
        let mut z = CBall::from_f64s(2.0, 1.0, p);
        z.add_error_mag(Mag::from_f64(0.05));
        let j = z.bessel_j(1);
        assert!(j.is_finite());
        let mut s: u64 = 0x1234_5678_9abc_def1;
        for _ in 0..20 {
            s ^= s << 13;
            s ^= s >> 7;
            s ^= s << 17;
            let u = (s >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0;
            let v = ((s >> 3) % 1_000_000) as f64 / 1e6 * 2.0 - 1.0;
            let pt = CBall::from_f64s(2.0 + 0.05 * u, 1.0 + 0.05 * v, 256).bessel_j(1);
            assert!(pt.rad_mag().le(&Mag::pow2(-200)));
            assert!(j.contains(pt.re().mid(), pt.im().mid()), "{j:?} misses {pt:?}");
        }
        assert!(!CBall::indeterminate(p).bessel_j(0).is_finite());
        assert!(!CBall::from_f64s(1.0, 1.0, p).bessel_j(i64::MIN).is_finite());
        let z0 = CBall::zero(p);
        assert_eq!(z0.bessel_j(0), CBall::one(p));
        assert!(CBall::i(p).mul_i64(0).bessel_j(3).contains(&Float::new(p), &Float::new(p)));
    }

    #[test]
    #[ignore = "timing; run with --ignored --nocapture"]
    fn timing() {
        for p in [64u32, 333] {
            for &(x, y) in &[(0.7, -0.3), (5.0, 2.0), (40.0, 3.0)] {
                let z = CBall::from_f64s(x, y, p);
                let n = 2000;
                let t0 = std::time::Instant::now();
                for _ in 0..n {
                    std::hint::black_box(std::hint::black_box(&z).bessel_j(1));
                }
                let dt = t0.elapsed().as_nanos() as f64 / n as f64;
                println!("{p:4} bits J_1({x}+{y}i): {dt:8.0} ns");
            }
        }
    }
}
