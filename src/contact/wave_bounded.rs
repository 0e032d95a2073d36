//! The wave displacement `u_w(x)` and its gradient `du_w/dx` in f64 with a
//! **proven** error bound: the Bessel form of [`super::displacement`] evaluated
//! in double-double with a running error analysis.
//!
//! # Method
//!
//! With `D = 2 pi a/zeta`, `r = x/a >= 1` and `t = sqrt((r-1)/(r+1))` in `[0, 1)`
//! (notes/model.md sec. 3; the module docs of [`super::displacement`]):
//!
//! ```text
//! q = (1 - t)/(1 + t) = r - sqrt(r^2 - 1),        acosh(r) = 2 atanh(t),
//! u_w     = A [1 - J0(D) + D J1(D) acosh(r) + 2 sum_{n=1}^{N} (-1)^{n+1} J_{2n}(D) q^{2n}],
//! du_w/dx = (4A/a) (1 - t) sum_{n=1}^{N} (-1)^{n+1} n J_{2n}(D) geo_n,   geo_n = sum_{j<2n} q^j,
//! ```
//!
//! (`(1 - q)/sqrt(r^2-1) = 1 - t`). Everything is a function of `t`, which is
//! computed from the exact difference `x - a`, so nothing cancels at the contact
//! edge. `atanh(t) = t + t^3/3 + t^5 P(t^2)`, `P(s) = sum_j s^j/(2j+5)`: the
//! first two terms in double-double, `P` by Horner in f64 (its contribution is
//! below `t^5/(5(1-t^2))`, so an f64 relative error there is ~1e-17 of the total).
//!
//! **Per contact** ([`CertifiedBessel`]): `D` and `J_0(D), ..., J_{2N+1}(D)` as
//! certified balls at [`CERT_PREC`] bits ([`bessel_j_sequence_mp`] at the midpoint
//! of the ball `D`, widened by `rad(D)` since `|J_n'| <= 1` [DLMF 10.14.1]),
//! each converted to a double-double with its conversion error added. `N` is
//! chosen by the truncation bounds below.
//!
//! # Error bound
//!
//! Every quantity is a [`BoundedDd`]: a double-double value and an f64 bound
//! `e >= |exact - v|`, propagated through `+ - * / sqrt` by the error model
//! written out in `crate::ball::dd_bounded` (`8 u^2` per addition and
//! product, `16 u^2` per quotient and square root, `u = 2^-53`). On top of it:
//!
//! * Horner in f64 for `P(s)` over `J` terms: Higham's running error bound
//!   `u (2 mu - |p|)` [Higham, *Accuracy and Stability*, Alg. 5.1] (times 1.01 for
//!   its second-order terms), plus `u P(|s|)` for the rounded coefficients, plus the truncation
//!   `s^J/((2J+5)(1-s))`, plus `e_s / (2 (1 - s)^2)` for the input error of `s`
//!   (`P'(s) <= 1/(2(1-s)^2)`);
//! * the truncated Bessel sums: `|J_{2n}(D)| <= (D/2)^{2n}/(2n)!` [DLMF 10.14.4],
//!   `0 <= q <= 1`, `0 <= geo_n <= 2n`, so the neglected terms are at most
//!   `tail0 = sum_{n>N} (D/2)^{2n}/(2n)!` and `2 tail2`, `tail2 = sum_{n>N} n^2 (D/2)^{2n}/(2n)!`
//!   (computed rigorously in MP once per contact).
//!
//! The bound itself is evaluated in f64 and inflated by `1 + 2^-30` to cover
//! its own roundings; the final rounding of `hi + lo` to f64 adds `u |value|`
//! ([`BoundedDd::finish`]).
//!
//! # Regions and fallback
//!
//! The native path certifies for `t <= T_MAX = 3/4`, i.e. `x/a <= 25/7 ~ 3.57`,
//! which covers the model's range `x/a in [1, 3]`. Beyond it (and if a division
//! or square root cannot be certified, which does not happen for valid inputs)
//! the `*_bounded` entry points fall back to the certified MP Bessel form at 64
//! bits; [`wave_bounded_fallbacks`] counts those calls (the benches report it).
//!
//! References: seed paper Eq. 12 and Appendix B.11; notes/model.md sec. 3;
//! DLMF 10.6.1, 10.12.4, 10.14.1, 10.14.4; Dekker (1971); Hida, Li, Bailey (2007);
//! Joldes, Muller, Popescu, "Tight and rigorous error bounds for basic building
//! blocks of double-word arithmetic", ACM TOMS 44 (2017).

use std::sync::atomic::{AtomicU64, Ordering};

use rug::float::Round;
use rug::Float;

use crate::ball::{Ball, Bounded, BoundedDd, Dd, U};
use crate::error::Result;
use crate::special::bessel_j::bessel_j_sequence_mp;
use crate::special::exact_sub;

/// Precision (bits) of the per-contact certified Bessel data.
pub const CERT_PREC: u32 = 128;

/// Largest `t = sqrt((x/a - 1)/(x/a + 1))` of the native path (`x/a <= 25/7`).
pub const T_MAX: f64 = 0.75;

static FALLBACKS: AtomicU64 = AtomicU64::new(0);

/// How many `u_wave_bounded` / `du_wave_bounded` / `WaveBessel::eval_bounded`
/// calls (per x) fell back to the MP path since the process started.
pub fn wave_bounded_fallbacks() -> u64 {
    FALLBACKS.load(Ordering::Relaxed)
}

pub(crate) fn count_fallback() {
    FALLBACKS.fetch_add(1, Ordering::Relaxed);
}

/// A certified ball as a double-double with its conversion error.
fn tr_from_ball(b: &Ball) -> BoundedDd {
    let mid = b.mid();
    let hi = mid.to_f64();
    let rest = exact_sub(mid, &Float::with_val(53, hi));
    let lo = rest.to_f64();
    let rem = exact_sub(&rest, &Float::with_val(53, lo)).abs().to_f64_round(Round::Up);
    let e = (rem + b.rad_mag().to_f64_up()).next_up();
    BoundedDd { v: Dd { hi, lo }, e }
}

/// `2 atanh(t) = acosh(r)` for `0 <= t <= T_MAX`: `t + t^3/3` in double-double,
/// `t^5 P(t^2)` with `P` by Horner in f64 (module docs).
fn two_atanh(t: BoundedDd) -> Option<BoundedDd> {
    if !(t.mag() + t.e <= T_MAX) {
        return None;
    }
    let t2 = t.mul(t);
    let t3 = t2.mul(t);
    let lead = t.add(t3.div(BoundedDd::exact(3.0))?);
    let s = t2.v.to_f64();
    let s_up = t2.mag() + t2.e + U; // upper bound of t^2 (covers the rounding of s)
    if !(s_up < 1.0) {
        return None;
    }
    // Terms until s^J/((2J+5)(1-s)) <= 2^-64 (relative to P(0) = 1/5).
    let mut j_terms = 1usize;
    let mut sp = s_up;
    while sp / ((2 * j_terms + 5) as f64 * (1.0 - s_up)) > 1.0 / (1u64 << 63) as f64 / 8.0 {
        sp *= s_up;
        j_terms += 1;
        if j_terms > 4000 {
            return None;
        }
    }
    // Horner with Higham's running error bound (Algorithm 5.1): u (2 mu - |p|).
    let mut p = 1.0 / (2 * (j_terms - 1) + 5) as f64;
    let mut mu = p / 2.0;
    for j in (0..j_terms - 1).rev() {
        p = p * s + 1.0 / (2 * j + 5) as f64;
        mu = s * mu + p.abs();
    }
    let p_abs = 1.0 / (5.0 * (1.0 - s_up)) * 1.25; // >= P(|s|) (P(s) <= 1/(5(1-s)))
    let trunc = sp / ((2 * j_terms + 5) as f64 * (1.0 - s_up));
    // running bound (with 1% for its own second-order terms) plus the
    // rounding of the coefficients 1/(2j+5) (at most u P(|s|))
    let horner = U * (2.0 * mu - p.abs()) * 1.01 + U * p_abs;
    // P'(s) = sum_j j s^{j-1}/(2j+5) <= 1/(2 (1-s)^2)
    let input = (t2.e + U * s_up) / ((1.0 - s_up) * (1.0 - s_up)) * 0.5;
    let p_tr = BoundedDd { v: Dd::from_f64(p), e: horner + trunc + input };
    let t5 = t3.mul(t2);
    Some(lead.add(t5.mul(p_tr)).mul_f64(2.0))
}

/// The certified per-contact data of the Bessel form.
#[derive(Debug, Clone)]
pub(crate) struct CertifiedBessel {
    d: BoundedDd,
    /// `J_0(D), J_1(D)`.
    j01: [BoundedDd; 2],
    /// `(-1)^{m+1} J_{2m}(D)`, `m = 0..=N` (index 0 unused): the `u` sum in `q^2`.
    u_coef: Vec<BoundedDd>,
    /// `T_m = sum_{n=m+1}^{N} (-1)^{n+1} n J_{2n}(D)`, `m = 0..N`: the gradient sum
    /// `sum_n (-1)^{n+1} n J_{2n} geo_n = (1 + q) sum_m T_m q^{2m}` (collecting the
    /// powers `q^{2m}` and `q^{2m+1}` of `geo_n = sum_{j<2n} q^j`).
    du_coef: Vec<BoundedDd>,
    n_terms: usize,
    /// `sum_{n>N} (D/2)^{2n}/(2n)!`, rounded up.
    tail0: f64,
    /// `sum_{n>N} n^2 (D/2)^{2n}/(2n)!`, rounded up.
    tail2: f64,
}

impl CertifiedBessel {
    /// Certified `D` and `J_n(D)` for `a > 0`, `zeta > 0` (validated by the caller).
    pub(crate) fn new(a: f64, zeta: f64) -> Result<CertifiedBessel> {
        let wp = CERT_PREC;
        let d = Ball::pi(wp).mul_pow2(1).mul(&Ball::from_f64(a, wp)?).div(&Ball::from_f64(zeta, wp)?)?;
        // N with both tails below 2^-110 (the double-double level).
        let (n_terms, tail0, tail2) = super::displacement::bessel_terms(&d.upper(), 110)?;
        let nmax = 2 * n_terms + 1;
        let mid = d.mid().clone();
        let mut j = bessel_j_sequence_mp(nmax, &mid, wp)?;
        for v in j.iter_mut() {
            v.add_error_mag(d.rad_mag());
        }
        let n_terms = n_terms as usize;
        let jt: Vec<BoundedDd> = j.iter().map(tr_from_ball).collect();
        let sign = |n: usize| if n % 2 == 1 { 1.0 } else { -1.0 };
        let u_coef: Vec<BoundedDd> = (0..=n_terms).map(|m| jt[2 * m].mul_f64(sign(m))).collect();
        let mut du_coef = vec![BoundedDd::ZERO; n_terms];
        let mut acc = BoundedDd::ZERO;
        for m in (0..n_terms).rev() {
            acc = acc.add(jt[2 * (m + 1)].mul_f64(sign(m + 1) * (m + 1) as f64));
            du_coef[m] = acc;
        }
        Ok(CertifiedBessel {
            d: tr_from_ball(&d),
            j01: [jt[0], jt[1]],
            u_coef,
            du_coef,
            n_terms,
            tail0: tail0.to_f64_round(Round::Up),
            tail2: tail2.to_f64_round(Round::Up),
        })
    }

    /// `(u_w(x), du_w/dx)` with proven bounds, or `None` where the native path
    /// does not certify (`x/a > 25/7`). `a <= x` and finiteness are the caller's.
    pub(crate) fn eval_bounded(&self, a: f64, amp: f64, x: f64) -> Option<(Bounded, Bounded)> {
        let ad = BoundedDd::exact(a);
        let rm1 = BoundedDd { v: Dd::diff(x, a), e: 0.0 }.div(ad)?; // x/a - 1 (x - a exact)
        let rp1 = BoundedDd { v: Dd::diff(x, -a), e: 0.0 }.div(ad)?; // x/a + 1 (x + a exact)
        let t = rm1.div(rp1)?.sqrt()?;
        let acosh_r = two_atanh(t)?;
        let q = BoundedDd::ONE.sub(t).div(BoundedDd::ONE.add(t))?;
        let one_minus_t = BoundedDd::ONE.sub(t);
        let q2 = q.mul(q);
        // Horner in q^2 for both sums (coefficients precomputed per contact).
        let n = self.n_terms;
        let (mut su, mut sdu) = (self.u_coef[n], self.du_coef[n - 1]);
        for m in (0..n - 1).rev() {
            su = su.mul(q2).add(self.u_coef[m + 1]);
            sdu = sdu.mul(q2).add(self.du_coef[m]);
        }
        let mut su = su.mul(q2);
        let mut sdu = sdu.mul(BoundedDd::ONE.add(q));
        su.e += self.tail0;
        sdu.e += 2.0 * self.tail2;
        let inner = BoundedDd::ONE.sub(self.j01[0]).add(self.d.mul(self.j01[1]).mul(acosh_r)).add(su.mul_f64(2.0));
        let u = inner.mul_f64(amp);
        let du = one_minus_t.mul(sdu).mul_f64(4.0 * amp).div(ad)?;
        Some((u.finish()?, du.finish()?))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn two_atanh_encloses_acosh() {
        for &r in &[1.0, 1.0 + 1e-12, 1.001, 1.35, 2.0, 3.0, 3.5] {
            let rm1 = BoundedDd { v: Dd::diff(r, 1.0), e: 0.0 };
            let rp1 = BoundedDd { v: Dd::diff(r, -1.0), e: 0.0 };
            let t = rm1.div(rp1).unwrap().sqrt().unwrap();
            let v = two_atanh(t).unwrap().finish().unwrap();
            let exact = Float::with_val(200, r).acosh();
            let diff = Float::with_val(200, &exact - v.value).abs().to_f64();
            assert!(diff <= v.err, "r={r}: {v} vs {exact}");
            assert!(v.err <= 4e-16 * v.value.abs().max(1e-300) || v.value == 0.0, "r={r}: {v}");
        }
    }

    #[test]
    fn refuses_beyond_t_max() {
        let t = BoundedDd::exact(0.8);
        assert!(two_atanh(t).is_none());
    }
}
