//! The Hankel functions `H_n^(1)(w)`, `H_n^(2)(w)` of integer order for complex balls
//! with `Re w > 0` and `|w|` large, by Hankel's expansion with its error bound.
//!
//! # Method
//!
//! DLMF 10.17.5 and 10.17.13: with `a_0 = 1`, `a_k(n) = (4n^2 - 1^2)(4n^2 - 3^2) ...
//! (4n^2 - (2k-1)^2) / (k! 8^k)` (10.17.1) and `omega = w - n pi/2 - pi/4`,
//!
//! ```text
//! H_n^(1)(w) = (2/(pi w))^(1/2) e^{i omega} (sum_{k<l} i^k a_k(n) w^-k + R_l(w)),
//! |R_l(w)| <= 2 |a_l(n)| V(t^-l) exp(|n^2 - 1/4| V(t^-1))          (DLMF 10.17.15)
//! ```
//!
//! where `V(t^-l)`, the variation of `t^-l` along a path from `w` to `+i inf`, is at most
//! `|w|^-l` for `0 <= ph w <= pi` and at most `chi(l) |w|^-l` for `-pi/2 <= ph w <= 0`
//! (DLMF 10.17.16), `chi(l) = pi^(1/2) Gamma(l/2 + 1)/Gamma(l/2 + 1/2) <= (pi (l/2 +
//! 1))^(1/2)` (Gautschi's inequality). The square root is the principal one (10.17.7,
//! `|ph w| < pi/2` here). The bound is evaluated with `|w|` replaced by a lower bound
//! over the rectangle, so it holds for every point of it; the sum itself is computed in
//! complex ball arithmetic. The expansion stops at the first `l >= max(|n|, 1)` whose
//! bound is below `2^-(prec+10)`, or where the terms stop decreasing (the error is then
//! about `e^{-2|w|}`, and the radius says so). `H^(2)_n(w) = conj(H^(1)_n(conj w))` for
//! real order (DLMF 10.11.9), and `H_{-n} = (-1)^n H_n` (10.4.6).
//!
//! Used by the certified integrator for Hankel-type integrals `int g(x) J_n(w x) dx` to
//! infinity, whose tails it integrates along rays in the upper and lower half-planes
//! (`quad::expr::oscillatory`).

use rug::Float;

use super::CBall;
use crate::ball::{Ball, Mag};

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
        let mu = Ball::from_i64(4, p).mul(&Ball::from_i64(m as i64, p).sqr());
        let inv = self.recip();
        let mut sum = CBall::one(p);
        let mut term = CBall::one(p);
        // |a_k| rho^-k, as a rigorous upper bound in a 64-bit ball
        let mut a_abs = Ball::one(64);
        let rho_b = Ball::from_float(&rho_f, 64);
        let target = Mag::pow2(-(p as i64) - 10);
        let mut last = Mag::inf();
        let mut k: u64 = 1;
        let bound = loop {
            // a_k from a_{k-1}
            let odd = Ball::from_i64((2 * k - 1) as i64, p).sqr();
            let factor = mu.sub(&odd).div(&Ball::from_i64(8 * k as i64, p)).unwrap_or_else(|_| Ball::zero(p));
            let factor64 = factor.set_prec(64);
            a_abs = a_abs.mul(&factor64).div(&rho_b).unwrap_or_else(|_| Ball::from_float(&Float::with_val(64, rug::float::Special::Infinity), 64));
            let a_up = a_abs.abs_upper_mag();
            // bound after the terms 0..k-1: l = k
            if k >= m.max(1) && (a_up.le(&target) || !a_up.le(&last) || k >= MAX_TERMS) {
                let mut b = a_up.mul_2exp(1);
                // exp(|n^2 - 1/4| / rho)
                let nu = Ball::from_i64(m as i64, 64).sqr().sub(&Ball::from_ratio(1, 4, 64));
                let e = nu.abs_upper_mag().div(rho);
                let e = Ball::from_float(&e.to_float(), 64).exp().map(|x| x.abs_upper_mag()).unwrap_or(Mag::inf());
                b = b.mul(e);
                if below_axis {
                    // chi(l) <= (pi (l/2 + 1))^(1/2) <= (2 (l + 2))^(1/2)
                    b = b.mul(Mag::from_f64(((2 * (k + 2)) as f64).sqrt()).mul(Mag::from_f64(1.0 + 1e-9)));
                }
                break b;
            }
            last = a_up;
            term = term.mul(&inv).mul_i().mul_real(&factor);
            sum = sum.add(&term);
            k += 1;
        };
        sum.add_error_mag(bound);
        let pi = Ball::pi(p);
        let pref = CBall::from_real(Ball::from_i64(2, p)).div(&self.mul_real(&pi)).sqrt();
        let shift = pi.mul(&Ball::from_ratio(2 * m as i64 + 1, 4, p));
        let phase = self.sub(&CBall::from_real(shift)).mul_i().exp();
        let v = pref.mul(&phase).mul(&sum);
        if n < 0 && m % 2 == 1 {
            v.neg()
        } else {
            v
        }
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
        let nu = Ball::from_i64(m as i64, p).sqr().sub(&Ball::from_ratio(1, 4, p));
        let e = Ball::from_float(&nu.abs_upper_mag().div(rho).to_float(), p).exp().map(|x| x.abs_upper_mag()).unwrap_or(Mag::inf());
        let chi = Mag::from_f64(((2 * (l + 2)) as f64).sqrt() * (1.0 + 1e-9));
        total.add(a_abs.abs_upper_mag().mul_2exp(1).mul(e).mul(chi))
    }

    /// `H_n^(2)(w) = conj(H_n^(1)(conj w))` (module docs).
    pub fn hankel2_large(&self, n: i64) -> CBall {
        self.conj().hankel1_large(n).conj()
    }
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
