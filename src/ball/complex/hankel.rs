//! The Hankel functions `H_n^(1)(w)`, `H_n^(2)(w)` of integer order for complex balls
//! with `Re w > 0` and `|w|` large, by Hankel's expansion with its error bound.
//!
//! # Method
//!
//! DLMF 10.17.1, 10.17.2 and 10.17.13: with `a_0 = 1`, `a_k(n) = (4n^2 - 1^2)(4n^2 -
//! 3^2) ... (4n^2 - (2k-1)^2) / (k! 8^k)` and `omega = w - n pi/2 - pi/4`,
//!
//! ```text
//! H_n^(1)(w) = (2/(pi w))^(1/2) e^{i omega} (sum_{k<l} i^k a_k(n) w^-k + R_l^+(n, w)),
//! |R_l^+(n, w)| <= 2 |a_l(n)| V(t^-l) exp(|n^2 - 1/4| V(t^-1))          (DLMF 10.17.14)
//! ```
//!
//! where `V(t^-l)` is the variation of `t^-l` along a path from `w` to `+i inf` on which
//! `|Im t|` changes monotonically, bounded by (DLMF 10.17.15)
//!
//! ```text
//! V(t^-l) <= |w|^-l            for 0 <= ph w <= pi,
//! V(t^-l) <= chi(l) |w|^-l     for -pi/2 <= ph w <= 0,
//! chi(l) = pi^(1/2) Gamma(l/2 + 1) / Gamma(l/2 + 1/2)       (DLMF 9.7(i)),
//! ```
//!
//! so that below the real axis the exponent carries `chi(1) = pi/2` too (`V(t^-1) <=
//! (pi/2) |w|^-1`), and `chi(l) <= (pi (l/2 + 1))^(1/2)` (Gautschi's inequality
//! `Gamma(x + 1)/Gamma(x + 1/2) < (x + 1)^(1/2)`). The statement holds for every `l >=
//! 1`. It was checked word for word against the text of DLMF section 10.17(iv) (version
//! of the DLMF-markdown mirror, equations 10.17.13-15; an earlier version of this file
//! cited them as 10.17.15-16 and left out the factor `chi(1)` in the exponent below the
//! axis, which made the bound up to `e^{(pi/2 - 1) |n^2 - 1/4| / |w|}` too small there).
//! The test `tests/it/hankel_bound.rs` compares the bound with the true remainder,
//! formed from `H^(1)_n` at 120 digits (`reference/generate_hankel.py`), for `n <= 10`,
//! `l <= 24` and `|w|` from 1/2 to 45 at phases from near `-pi/2` to near `pi/2`.
//!
//! The bound is evaluated with `|w|` replaced by a lower bound over the rectangle, and
//! with `chi(l)` wherever the rectangle reaches below the axis, so it holds for every
//! point of it; the sum itself is computed in complex ball arithmetic. The expansion
//! stops at the first `l >= max(|n|, 1)` whose bound is below `2^-(prec+10)`, or where
//! the terms stop decreasing (the error is then about `e^{-2|w|}`, and the radius says
//! so). The square root is the principal one (10.17.7, `|ph w| < pi/2` here).
//! `H^(2)_n(w) = conj(H^(1)_n(conj w))` for real order (DLMF 10.11.9), and `H_{-n} =
//! (-1)^n H_n` (10.4.6).
//!
//! Used by the certified integrator for Hankel-type integrals `int g(x) J_n(w x) dx` to
//! infinity, whose tails it integrates along rays in the upper and lower half-planes
//! (`quad::expr::oscillatory`).

use rug::Float;

use super::CBall;
use crate::ball::{Ball, Mag};

/// A rectangle whose radius exceeds `2^-WIDE_BOX_LOG2 min |w|` gets the magnitude
/// bound of the sum instead of the sum in ball arithmetic ([`CBall::hankel1_wide`]).
const WIDE_BOX_LOG2: i64 = 16;

/// Most terms of the expansion.
const MAX_TERMS: u64 = 100_000;

impl CBall {
    /// `H_n^(1)(w)` by Hankel's expansion (module docs); the indeterminate ball when
    /// the rectangle reaches `Re w <= 0`.
    pub fn hankel1_large(&self, n: i64) -> CBall {
        let p = self.prec();
        if !self.is_finite() || !self.re().is_positive() {
            return CBall::indeterminate(p);
        }
        let m = n.unsigned_abs();
        let rho = self.abs_lower_mag();
        if rho.is_zero() {
            return CBall::indeterminate(p);
        }
        let rho_f = rho.to_float();
        let below_axis = !self.im().lower().is_sign_positive() && !self.im().lower().is_zero();
        if !self.rad_mag().le(&rho.mul_2exp(-WIDE_BOX_LOG2)) {
            return self.hankel1_wide(n, m, rho, below_axis);
        }
        let inv = self.recip();
        // 4 n^2 (n <= 2^20 in any use; checked)
        let Some(mu) = (m as i64).checked_mul(4 * m as i64) else { return CBall::indeterminate(p) };
        let mut sum = CBall::one(p);
        let mut term = CBall::one(p);
        // the term k is about |a_k| rho^-k <= 2^-drop below the sum (about 1), so it is
        // formed at p - drop + 16 bits: the absolute error of the sum stays about 2^-p
        // (every rounding is in the term's radius), at a fraction of the cost
        let mut inv_k = inv.clone();
        let mut prec_k = p;
        // |a_k| rho^-k, as a rigorous upper bound in a 64-bit ball
        let mut a_abs = Ball::one(64);
        let rho_b = Ball::from_float(&rho_f, 64);
        let target = Mag::pow2(-(p as i64) - 10);
        let mut last = Mag::inf();
        let mut k: u64 = 1;
        let bound = loop {
            // a_k = a_{k-1} (4 n^2 - (2k-1)^2) / (8k)
            let Some(num) = (2 * k as i64 - 1).checked_mul(2 * k as i64 - 1).map(|o| mu - o) else { return CBall::indeterminate(p) };
            let den = 8 * k as i64;
            let factor64 = Ball::from_i64(num, 64).div_i64(den).unwrap_or_else(|_| Ball::zero(64));
            a_abs = a_abs.mul(&factor64).div(&rho_b).unwrap_or_else(|_| Ball::from_float(&Float::with_val(64, rug::float::Special::Infinity), 64));
            let a_up = a_abs.abs_upper_mag();
            // bound after the terms 0..k-1: l = k
            if k >= m.max(1) && (a_up.le(&target) || !a_up.le(&last) || k >= MAX_TERMS) {
                let b = remainder_bound(m, k, a_up, rho, below_axis);
                break b;
            }
            last = a_up;
            let drop = (-a_up.log2()).floor();
            let want = if drop.is_finite() && drop > 0.0 { (p as f64 - drop + 16.0).max(64.0) as u32 } else { p };
            if want + 32 <= prec_k {
                prec_k = want;
                inv_k = inv.set_prec(prec_k);
            }
            let t = term.set_prec(prec_k).mul(&inv_k).mul_i().mul_i64(num);
            term = div_int(&t, den);
            sum = sum.add(&term);
            k += 1;
        };
        sum.add_error_mag(bound);
        self.hankel1_from_sum(n, m, &sum)
    }

    /// `(2/(pi w))^(1/2) e^{i omega} sum` (`omega = w - n pi/2 - pi/4`), `m = |n|`.
    fn hankel1_from_sum(&self, n: i64, m: u64, sum: &CBall) -> CBall {
        let p = self.prec();
        let pi = Ball::pi(p);
        let pref = CBall::from_real(Ball::from_i64(2, p)).div(&self.mul_real(&pi)).sqrt();
        let shift = pi.mul(&Ball::from_ratio(2 * m as i64 + 1, 4, p));
        let phase = self.sub(&CBall::from_real(shift)).mul_i().exp();
        let v = pref.mul(&phase).mul(sum);
        if n < 0 && m % 2 == 1 {
            v.neg()
        } else {
            v
        }
    }

    /// [`CBall::hankel1_large`] on a wide rectangle (radius above `2^-WIDE_BOX_LOG2`
    /// times `rho = min |w|`): the sum is enclosed by `1 + disc(sum_{1 <= k < l} |a_k|
    /// rho^-k + |R_l|)`, `l = max(|n|, 1)`, the bound of DLMF 10.17.14-15 (module docs)
    /// for every `w` of the rectangle. Its relative width is about `|4n^2 - 1| / (8
    /// rho)`, where ball arithmetic over the rectangle would multiply the rectangle's
    /// relative width by about `1 + sqrt 2 |rad/w|` at each of ~`2 rho` terms: the
    /// integrator's ellipse bounds need the magnitude, not digits.
    fn hankel1_wide(&self, n: i64, m: u64, rho: Mag, below_axis: bool) -> CBall {
        let p = self.prec();
        let l = m.max(1);
        let rho_b = Ball::from_float(&rho.to_float(), 64);
        let mu = Ball::from_i64(4, 64).mul(&Ball::from_i64(m as i64, 64).sqr());
        let mut a_abs = Ball::one(64);
        let mut rest = Mag::ZERO;
        for k in 1..=l {
            let odd = Ball::from_i64((2 * k - 1) as i64, 64).sqr();
            let Ok(f) = mu.sub(&odd).div(&Ball::from_i64(8 * k as i64, 64)) else { return CBall::indeterminate(p) };
            let Ok(next) = a_abs.mul(&f).div(&rho_b) else { return CBall::indeterminate(p) };
            a_abs = next;
            if k < l {
                rest = rest.add(a_abs.abs_upper_mag());
            }
        }
        rest = rest.add(remainder_bound(m, l, a_abs.abs_upper_mag(), rho, below_axis));
        if !rest.is_finite() {
            return CBall::indeterminate(p);
        }
        let mut sum = CBall::one(p);
        sum.add_error_mag(rest);
        self.hankel1_from_sum(n, m, &sum)
    }

    /// An upper bound of `|sum_{k<l} i^k a_k(n) w^-k + R_l(w)| = |(pi w/2)^(1/2) e^{-i
    /// omega} H_n^(1)(w)|` for every `w` with `|w| >= rho` and `-pi/2 <= ph w <= pi`
    /// (module docs, with `l = max(|n|, 1)`): the factor `K` of the tail bounds of
    /// Hankel-type integrals.
    pub fn hankel_sum_bound(n: i64, rho: Mag) -> Mag {
        let p = 64;
        if rho.is_zero() || !rho.is_finite() {
            return Mag::inf();
        }
        let m = n.unsigned_abs();
        let l = m.max(1);
        let rho_b = Ball::from_float(&rho.to_float(), p);
        let mu = Ball::from_i64(4, p).mul(&Ball::from_i64(m as i64, p).sqr());
        let mut a_abs = Ball::one(p);
        let mut total = Mag::from_f64(1.0);
        for k in 1..=l {
            let odd = Ball::from_i64((2 * k - 1) as i64, p).sqr();
            let Ok(f) = mu.sub(&odd).div(&Ball::from_i64(8 * k as i64, p)) else { return Mag::inf() };
            let Ok(next) = a_abs.mul(&f).div(&rho_b) else { return Mag::inf() };
            a_abs = next;
            if k < l {
                total = total.add(a_abs.abs_upper_mag());
            }
        }
        total.add(remainder_bound(m, l, a_abs.abs_upper_mag(), rho, true))
    }

    /// The bound of DLMF 10.17.14-15 (module docs) of the remainder `R_l^+(n, w)` of
    /// Hankel's expansion of `H_n^(1)` after the terms `k < l`, for every `w` in the
    /// rectangle; infinite unless the rectangle lies in `0 <= ph w <= pi` or in `Re w >
    /// 0` (then `-pi/2 < ph w < pi/2`), or when `l = 0`. For `H_n^(2)` (`R_l^-`) apply
    /// it to `conj w` (DLMF: the bounds hold in the conjugate sectors).
    pub fn hankel_remainder_bound(n: i64, l: u64, w: &CBall) -> Mag {
        if l == 0 || !w.is_finite() {
            return Mag::inf();
        }
        let rho = w.abs_lower_mag();
        if rho.is_zero() {
            return Mag::inf();
        }
        let below_axis = if !w.im().lower().is_sign_negative() || w.im().lower().is_zero() {
            false
        } else if w.re().is_positive() {
            true
        } else {
            return Mag::inf();
        };
        let m = n.unsigned_abs();
        let p = 64;
        let rho_b = Ball::from_float(&rho.to_float(), p);
        let mu = Ball::from_i64(4, p).mul(&Ball::from_i64(m as i64, p).sqr());
        let mut a_abs = Ball::one(p);
        for k in 1..=l {
            let odd = Ball::from_i64((2 * k - 1) as i64, p).sqr();
            let Ok(f) = mu.sub(&odd).div(&Ball::from_i64(8 * k as i64, p)) else { return Mag::inf() };
            let Ok(next) = a_abs.mul(&f).div(&rho_b) else { return Mag::inf() };
            a_abs = next;
        }
        remainder_bound(m, l, a_abs.abs_upper_mag(), rho, below_axis)
    }

    /// `H_n^(2)(w) = conj(H_n^(1)(conj w))` (module docs).
    pub fn hankel2_large(&self, n: i64) -> CBall {
        self.conj().hankel1_large(n).conj()
    }
}

/// `z / n` for a nonzero integer `n`.
fn div_int(z: &CBall, n: i64) -> CBall {
    match (z.re().div_i64(n), z.im().div_i64(n)) {
        (Ok(a), Ok(b)) => CBall::new(a, b),
        _ => CBall::indeterminate(z.prec()),
    }
}

/// `2 |a_l| V(t^-l) exp(|n^2 - 1/4| V(t^-1))` (DLMF 10.17.14) from `a_rho = |a_l(n)|
/// rho^-l` (an upper bound), with the variations of DLMF 10.17.15: `rho^-l` and
/// `rho^-1` for `0 <= ph w <= pi`, `chi(l) rho^-l` and `chi(1) rho^-1 = (pi/2) rho^-1`
/// when `below_axis` (`-pi/2 <= ph w <= 0`), `rho <= |w|`.
fn remainder_bound(m: u64, l: u64, a_rho: Mag, rho: Mag, below_axis: bool) -> Mag {
    let p = 64;
    let nu = Ball::from_i64(m as i64, p).sqr().sub(&Ball::from_ratio(1, 4, p));
    let mut v1 = nu.abs_upper_mag().div(rho);
    if below_axis {
        // chi(1) = pi^(1/2) Gamma(3/2) / Gamma(1) = pi/2 < 1.5707963267949
        // (an upper bound of pi/2 by 3.4e-15, not pi/2 itself).
        #[allow(clippy::approx_constant)]
        let half_pi_above = 1.5707963267949;
        v1 = v1.mul(Mag::from_f64(half_pi_above));
    }
    let e = Ball::from_float(&v1.to_float(), p).exp().map(|x| x.abs_upper_mag()).unwrap_or(Mag::inf());
    let mut b = a_rho.mul_2exp(1).mul(e);
    if below_axis {
        // chi(l) < (pi (l/2 + 1))^(1/2) (Gautschi); the f64 square root errs by far
        // less than the factor 1 + 1e-12
        b = b.mul(Mag::from_f64((std::f64::consts::PI * (l as f64 + 2.0) / 2.0).sqrt() * (1.0 + 1e-12)));
    }
    b
}

#[cfg(test)]
mod tests {
    use super::*;

    /// On the real axis `Re H^(1)_n(x) = J_n(x)`: the expansion's ball must contain the
    /// crate's certified `J_n`, and be narrow.
    #[test]
    fn real_part_on_the_axis_contains_j_n() {
        for n in [0i64, 1, -1, 2, 5] {
            for x in [30i64, 60, 200, 1000] {
                for p in [64u32, 200] {
                    let w = CBall::from_i64(x, p);
                    let h = w.hankel1_large(n);
                    let j = w.bessel_j(n);
                    assert!(h.re().overlaps(j.re()), "n {n} x {x} p {p}: {:?} vs {:?}", h.re(), j.re());
                    if x as f64 > 0.35 * (p as f64 + 40.0) {
                        assert!(h.re().rad_mag().le(&Mag::pow2(-(p as i64) + 8)), "n {n} x {x} p {p}: {:?}", h.re());
                    }
                }
            }
        }
    }

    /// On a wide rectangle (the magnitude bound of the sum) the enclosure contains the
    /// narrow evaluations at points of the rectangle, corners included.
    #[test]
    fn wide_rectangle_contains_its_points() {
        let p = 128;
        for n in [0i64, 1, -2, 5] {
            for (re, im, r) in [(100.0, 20.0, 5.0), (60.0, -3.0, 2.0), (300.0, 0.0, 40.0)] {
                let b = CBall::new(Ball::with_mag(Float::with_val(p, re), Mag::from_f64(r)), Ball::with_mag(Float::with_val(p, im), Mag::from_f64(r)));
                let h = b.hankel1_large(n);
                assert!(h.is_finite(), "n {n} {re}+{im}i +- {r}");
                for (dx, dy) in [(0.0, 0.0), (r, r), (-r, r), (r, -r), (-r, -r), (0.3 * r, -0.7 * r)] {
                    let w = CBall::from_f64s(re + dx, im + dy, p);
                    let v = w.hankel1_large(n);
                    assert!(h.re().contains(v.re().mid()) && h.im().contains(v.im().mid()), "n {n} at {}+{}i: {v:?} not in {h:?}", re + dx, im + dy);
                }
            }
        }
    }

    /// Off the axis `H^(1) + H^(2) = 2 J_n` (the series path of `bessel_j`).
    #[test]
    fn sum_of_both_kinds_is_twice_j_n_off_the_axis() {
        let p = 128;
        for n in [0i64, 1, 3] {
            for (re, im) in [(40.0, 3.0), (50.0, -2.0), (60.0, 0.5)] {
                let w = CBall::from_f64s(re, im, p);
                let s = w.hankel1_large(n).add(&w.hankel2_large(n));
                let j = w.bessel_j(n).mul_i64(2);
                assert!(s.overlaps(&j), "n {n} w {re}+{im}i: {s:?} vs {j:?}");
            }
        }
    }
}
