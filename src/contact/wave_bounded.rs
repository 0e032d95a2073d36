//! The wave displacement `u_w(x)` and its gradient `du_w/dx` in f64 with a
//! **proven** error bound: the Bessel form of [`super::displacement`] evaluated
//! in double-double with a running error analysis, without MP on the model's
//! domain.
//!
//! # Method
//!
//! With `D = 2 pi a/zeta`, `r = x/a >= 1` and `t = sqrt((x-a)/(x+a))` in `[0, 1)`
//! (notes/model.md sec. 3; the module docs of [`super::displacement`]):
//!
//! ```text
//! q = (1 - t)/(1 + t) = (1 - t)^2 (x + a)/(2a),      acosh(r) = 2 atanh(t),
//! u_w     = A [1 - J0(D) + D J1(D) acosh(r) + 2 sum_{n=1}^{N} (-1)^{n+1} J_{2n}(D) q^{2n}],
//! du_w/dx = (4A/a) (1 - t) sum_{n=1}^{N} (-1)^{n+1} n J_{2n}(D) geo_n,   geo_n = sum_{j<2n} q^j,
//! ```
//!
//! (`(1 - q)/sqrt(r^2-1) = 1 - t`). Everything is a function of `t`, computed
//! from the exact `x - a` and `x + a`, so nothing cancels at the contact edge.
//!
//! **Per contact** (`CertifiedBessel`, about 3-6 us): `D` as a bounded
//! double-double (`Dd::TWO_PI`, error `< 3e-32`, times `a`, over `zeta`), `N`
//! from the tail bounds below (`2^-64`; `N = 41` at `D = 33.5`), and
//! `J_0(D), ..., J_{2N+1}(D)`:
//!
//! * `J_{2N}`, `J_{2N+1}` by the power series [DLMF 10.2.2] (`(D/2)^n` by binary
//!   powering, `1/n!` from the table of `native_series.rs`, terms until
//!   `2^-108` of the sum with ratio `<= 1/2`, tail `2 |t_K|`);
//! * the orders down to the turning point by the recurrence
//!   `J_{k-1} = (2k/D) J_k - J_{k+1}` [DLMF 10.6.1] run downward (where `J_k`
//!   grows downward; the running triangle-inequality bound grows like
//!   `e^{0.55 D}` over this stretch, `2^27` at `D = 33.5`);
//! * below the turning point, for `D >= 25`, the forward recurrence of
//!   `native_recurrence.rs` from Hankel's `J_0`, `J_1` at `x = fl(D)`, whose
//!   energy-norm bound does not grow like the triangle inequality (which would
//!   add `e^{0.47 D}`), moved to `D = x + delta` by Taylor:
//!   `J_k(D) = J_k(x) + delta (J_{k-1}(x) - J_{k+1}(x))/2 + R`, `|R| <= delta^2/2`
//!   (`|J_k''| <= 1` [DLMF 10.14.1]); for `D < 25` the downward recurrence runs to 0.
//!
//! Every step is a `BoundedDd` operation (the error model of
//! `crate::ball::dd_bounded`); the data are accepted when every `J_k` is known
//! to `2^-60` (over `a in [0.5, 6]`, `zeta = 9/8` the bounds are below `1e-19`;
//! a unit test checks them against 300-bit values). Where not (`D` beyond
//! about 60, where `2N+1` passes the `1/n!` table), the data come from MP at
//! [`CERT_PREC`] bits ([`wave_bounded_mp_contacts`] counts it). The sums become
//! polynomials in `X = q^2` (`u`: coefficients `(-1)^{m+1} J_{2m}`; gradient:
//! `(1 + q) sum_m T_m X^m`, `T_m = sum_{n>m} (-1)^{n+1} n J_{2n}`), with the
//! coefficients' bounds.
//!
//! **Per x** (about 0.4-0.5 us): `t^2 = (x-a)/(x+a)` (`div_p`: one division
//! by the leading part and the double-double `1 - eps`, no long division),
//! `t` by the double-double square root, `acosh(r) = 2 (atanh(t0) + atanh(w))`
//! with `t0 = i/16` the nearest table point (`atanh(t0)` from 256-bit MPFR),
//! `w = (t - t0)/(1 - t t0)`, `|w| <= 0.08`, and `atanh(w) = w + w^3/3 + w^5 P(w^2)`,
//! `P(s) = sum_j s^j/(2j+5)`: the first two terms in double-double, `P` by
//! Horner in f64 (about 9 terms). Then both sums by one compensated Horner
//! loop, truncated at the first power `i` with `|X|^{i+1} sum_{i'>i} (|c_i'| + e_i') <= 2^-72 min(1, D)`
//! (the remainder is added to the bound; at `x/a = 3` about 15 of 41 terms).
//!
//! # Error bound
//!
//! Every quantity is a `BoundedDd`: a double-double value and an f64 bound
//! `e >= |exact - v|`, propagated through `+ - * / sqrt` by the error model
//! written out in `crate::ball::dd_bounded` (`8 u^2` per addition and
//! product, `16 u^2` per quotient and square root, `u = 2^-53`). On top of it:
//!
//! * **Compensated Horner** (`CompAcc`; Graillat, Langlois, Louvet, 2009, in
//!   the unnormalised form of `native_recurrence.rs`): the accumulator is
//!   `h + l`, the argument the double-double `X~ = xh + xl` with `|X~ - X| <= ex`,
//!   the coefficient `c = c.hi + c.lo` with error `e_c`. One step forms
//!   `p + pi = h xh` (exact product), `h' + sigma = p + c.hi` (exact sum), and
//!   `l' = fl((pi + sigma) + (h xl + (l xh + c.lo)))`, which drops `l xl` and
//!   rounds a sum in which each term passes at most four roundings, so
//!   `|h' + l' - ((h + l) X~ + c)| <= gamma_4 (|pi| + |sigma| + |h xl| + |l xh| + |c.lo|) + |l xl|`
//!   [Higham, *Accuracy and Stability*, Lemma 3.1], `gamma_4 = 4u/(1-4u) <= 4.0001 u`,
//!   `|pi| <= u |p|`, `|sigma| <= u |h'|`. With `eps` the accumulator's error,
//!   `eps' <= eps (|X~| + ex) + (|h| + |l|) ex + that rounding + e_c`
//!   (the `|S| ex` term from `X~ - X`); this runs alongside in f64
//!   (`xa = |xh| + |xl| + ex`, `kh = ex + gamma_4 (|xl| + 2.0001 u |xh|)`,
//!   `kl = ex + gamma_4 |xh| + |xl|`, `gamma_4 (|c.lo| + 1.0001 u |c.hi|)` folded into
//!   the stored `e_c`, from `|pi| + |sigma| <= u (|p| + |h'|)` and
//!   `|p| + |h'| <= 2.0001 |h xh| + 1.0001 |c.hi|`).
//! * `div_p`: `num/(H + L) = (num/H)(1 - eps) + r`, `eps = fl(L/H)`,
//!   `|r| <= 2.01 u^2 |num/H|` (charged `3 u^2`), plus `|num/den| e_den/(|den| - e_den)`.
//! * Horner in f64 for `P(s)` over `J` terms: Higham's running error bound
//!   `u (2 mu - |p|)` [Higham, Alg. 5.1] (times 1.01 for its second-order
//!   terms), plus `u P(|s|)` for the rounded coefficients, plus the truncation
//!   `s^J/((2J+5)(1-s))`, plus `e_s / (2 (1 - s)^2)` for the input error of `s`
//!   (`P'(s) <= 1/(2(1-s)^2)`).
//! * The truncated Bessel sums: `|J_{2n}(D)| <= (D/2)^{2n}/(2n)!` [DLMF 10.14.4],
//!   `0 <= q <= 1`, `0 <= geo_n <= 2n`, so the neglected terms are at most
//!   `tail0 = sum_{n>N} (D/2)^{2n}/(2n)!` and `2 tail2`, `tail2 = sum_{n>N} n^2 (D/2)^{2n}/(2n)!`
//!   (f64 with each step's three roundings covered by `1 + 4u`, and the geometric
//!   tail once the ratio is below 1/2; `bessel_tails`).
//!
//! The bound itself is evaluated in f64 and inflated by `1 + 2^-30` to cover
//! its own roundings; the final rounding of `hi + lo` to f64 adds `u |value|`
//! (`BoundedDd::finish`).
//!
//! # Regions and fallback
//!
//! The native per-x path certifies for `t <= T_MAX = 3/4`, i.e. `x/a <= 25/7 ~ 3.57`,
//! which covers the model's range `x/a in [1, 3]`. Beyond it the `*_bounded`
//! entry points fall back to the certified MP Bessel form at 64 bits;
//! [`wave_bounded_fallbacks`] counts those calls (the benches report both counters).
//! Exact products are fused multiply-adds where the CPU has them (detected at
//! run time, as in `native.rs`), else Dekker's; both are exact.
//!
//! References: seed paper Eq. 12 and Appendix B.11; notes/model.md sec. 3;
//! DLMF 10.2.2, 10.6.1, 10.12.4, 10.14.1, 10.14.4; Dekker (1971); Hida, Li, Bailey (2007);
//! Joldes, Muller, Popescu, "Tight and rigorous error bounds for basic building
//! blocks of double-word arithmetic", ACM TOMS 44 (2017); Graillat, Langlois,
//! Louvet, "Algorithms for accurate, validated and fast polynomial
//! evaluation", Japan J. Indust. Appl. Math. 26 (2009); Higham, *Accuracy and
//! Stability of Numerical Algorithms*, 2nd ed. (2002).

use std::sync::atomic::{AtomicU64, Ordering};

use rug::float::Round;
use rug::Float;

use crate::ball::{two_sum, Ball, Bounded, BoundedDd, Dd, Dekker, ExactProduct, U};
use crate::error::Result;
use crate::special::bessel_j::{
    bessel_j01, bessel_j_sequence_mp, forward_sequence, inv_factorials, HANKEL_MAX_X, HANKEL_MIN_X, MAX_TABLE_FACTORIAL, TABLE_ETA,
};
use crate::special::exact_sub;

/// Precision (bits) of the per-contact certified Bessel data on the MP route.
pub const CERT_PREC: u32 = 128;

/// Largest `t = sqrt((x/a - 1)/(x/a + 1))` of the native path (`x/a <= 25/7`).
pub const T_MAX: f64 = 0.75;

/// The Bessel sums are cut where both tails (`tail0`, `tail2`) are below this
/// (`2^-64`; relative to the scales `|A|` and `2 pi |A|/zeta` of the results
/// they weigh at most `2^-61`, far below the final rounding).
const BESSEL_TAIL_TARGET: f64 = 5.421_010_862_427_522e-20;

/// The Horner sums in `q^2` stop at the first power whose rigorous remainder
/// bound is below `2^-72 min(1, D)` (the remainder is added to the bound).
const HORNER_TAIL_REL: f64 = 2.117_582_368_135_750_6e-22;

/// The top series stop when the next term is below `2^-108` of the sum.
const TAIL_REL_SERIES: f64 = 3.081_487_911_019_577e-33;

/// `gamma_4 = 4u/(1 - 4u)`, rounded up (a four-deep f64 sum, Higham Lemma 3.1).
const GAMMA4: f64 = 4.0001 * U;

/// A certified native sequence is accepted when every `J_n(D)` is known to
/// this absolute accuracy, `2^-60` (otherwise the MP route builds the data;
/// over the model domain, `D <= 33.5`, the bound is below `3e-20`).
const NATIVE_J_ERR_MAX: f64 = 8.673_617_379_884_035e-19; // 2^-60

/// `|2 pi - Dd::TWO_PI|` is below `u |lo| < 2.8e-32`.
const TWO_PI_ERR: f64 = 3.0e-32;

static FALLBACKS: AtomicU64 = AtomicU64::new(0);

/// How many `u_wave_bounded` / `du_wave_bounded` / `WaveBessel::eval_bounded`
/// calls (per x) fell back to the MP path since the process started.
pub fn wave_bounded_fallbacks() -> u64 {
    FALLBACKS.load(Ordering::Relaxed)
}

static MP_CONTACTS: AtomicU64 = AtomicU64::new(0);

/// How many times the per-contact Bessel data of the bounded path were built
/// in MP (where the native double-double sequence does not certify: `D`
/// beyond about 60) since the process started.
pub fn wave_bounded_mp_contacts() -> u64 {
    MP_CONTACTS.load(Ordering::Relaxed)
}

pub(crate) fn count_fallback() {
    FALLBACKS.fetch_add(1, Ordering::Relaxed);
}

/// Whether the CPU has a fused multiply-add (checked once; `std` caches it).
#[inline]
fn has_fma() -> bool {
    #[cfg(target_arch = "x86_64")]
    {
        std::arch::is_x86_feature_detected!("fma")
    }
    #[cfg(not(target_arch = "x86_64"))]
    {
        false
    }
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

/// `num / den` in [`BoundedDd`] without the long division: with `den = H + L`
/// (a normalised double-double, `|L| <= u |H|`) and `eps = fl(L/H)`,
/// `num/den = (num/H) (1 - eps) + r`, `|r| <= (u^2 + eps^2/(1 + eps)) |num/H| <= 2.01 u^2 |num/H|`
/// (`|L/H - eps| <= u |eps| <= u^2`), so `num/H` ([`BoundedDd::div_f64_p`]) times
/// the double-double `1 - eps` carrying `3 u^2` gives `num/den~`; the error
/// `e_den` of the denominator adds `|num/den~| e_den/(|den~| - e_den)`.
/// Falls back to [`BoundedDd::div`] if `den` is not normalised.
#[inline(always)]
fn div_p<P: ExactProduct>(num: BoundedDd, den: BoundedDd) -> Option<BoundedDd> {
    let (h, l) = (den.v.hi, den.v.lo);
    let eps = l / h;
    if !(eps.abs() <= U) || h == 0.0 {
        return num.div(den);
    }
    let low = den.mag() - den.e;
    if !(low > 0.0) {
        return None;
    }
    let corr = BoundedDd { v: Dd { hi: 1.0, lo: -eps }, e: 3.0 * U * U };
    let mut r = num.div_f64_p::<P>(h).mul_p::<P>(corr);
    if den.e > 0.0 {
        r.e += (r.mag() + r.e) * den.e / low;
    }
    Some(r)
}

/// Spacing of the table of `atanh(t0)`, `t0 = i/16`, `i = 0..=12` (up to `T_MAX`).
const ATANH_TABLE_STEP: f64 = 0.0625;

/// `atanh(i/16)` for `i = 0..=12` as double-doubles with their errors (MPFR at
/// 256 bits, correctly rounded, then split: error `<= |rest| + 2^-250 |v|`).
fn atanh_table() -> &'static [BoundedDd] {
    static TABLE: std::sync::OnceLock<Vec<BoundedDd>> = std::sync::OnceLock::new();
    TABLE.get_or_init(|| {
        (0..=12)
            .map(|i| {
                let f = Float::with_val(256, i as f64 * ATANH_TABLE_STEP).atanh();
                let hi = f.to_f64();
                let rest = Float::with_val(256, &f - hi);
                let lo = rest.to_f64();
                let rem = Float::with_val(256, &rest - lo).abs().to_f64_round(Round::Up);
                BoundedDd { v: Dd { hi, lo }, e: (rem + hi.abs() * 5.5e-76).next_up() }
            })
            .collect()
    })
}

/// `2 atanh(t) = acosh(r)` for `0 <= t <= T_MAX`: with `t0 = i/16` the table
/// point nearest to `t`, `atanh(t) = atanh(t0) + atanh(w)`,
/// `w = (t - t0)/(1 - t t0)`, `|w| <= 0.08`, and `atanh(w)` by [`atanh_series`].
#[inline(always)]
fn two_atanh<P: ExactProduct>(t: BoundedDd) -> Option<BoundedDd> {
    if !(t.mag() + t.e <= T_MAX) {
        return None;
    }
    let i = (t.v.hi / ATANH_TABLE_STEP).round().clamp(0.0, 12.0) as usize;
    if i == 0 {
        return Some(atanh_series::<P>(t)?.mul_f64_p::<P>(2.0));
    }
    let t0 = i as f64 * ATANH_TABLE_STEP; // exact
    let w = div_p::<P>(t.sub(BoundedDd::exact(t0)), BoundedDd::ONE.sub(t.mul_f64_p::<P>(t0)))?;
    Some(atanh_table()[i].add(atanh_series::<P>(w)?).mul_f64_p::<P>(2.0))
}

/// `atanh(t) = t + t^3/3 + t^5 P(t^2)` for `|t| <= T_MAX`: the first two terms in
/// double-double, `P` by Horner in f64 (module docs).
#[inline(always)]
fn atanh_series<P: ExactProduct>(t: BoundedDd) -> Option<BoundedDd> {
    if !(t.mag() + t.e <= T_MAX) {
        return None;
    }
    let t2 = t.mul_p::<P>(t);
    let t3 = t2.mul_p::<P>(t);
    let lead = t.add(t3.div_f64_p::<P>(3.0));
    let s = t2.v.to_f64();
    let s_up = t2.mag() + t2.e + U; // upper bound of t^2 (covers the rounding of s)
    if !(s_up < 1.0) {
        return None;
    }
    // Terms until s^J/((2J+5)(1-s)) <= 2^-66 (relative to P(0) = 1/5): J from
    // an f64 estimate, then the truncation bound below is computed for that J.
    // (after the table reduction s <= 0.0065, where J = 9 suffices: no logarithm)
    let j_terms = if s_up <= 1e-300 {
        1
    } else if s_up <= 0.0065 {
        9
    } else {
        ((-45.75 / s_up.ln()).ceil().max(1.0) as usize).min(4000)
    };
    let sp = s_up.powi(j_terms as i32) * (1.0 + 1e-12); // powi: < 2 j_terms roundings
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
    let t5 = t3.mul_p::<P>(t2);
    Some(lead.add(t5.mul_p::<P>(p_tr)))
}

/// One accumulator of the compensated Horner scheme: the value `h + l`
/// (not renormalised) and the bound `e` on its distance to the exact
/// polynomial at the exact argument (module docs, "Compensated Horner").
#[derive(Clone, Copy)]
struct CompAcc {
    h: f64,
    l: f64,
    e: f64,
}

/// The per-`x` constants of a compensated Horner step: the argument
/// `X = xh + xl` (a double-double) with its error `ex`, and the multipliers of
/// the running bound.
#[derive(Clone, Copy)]
struct CompArg {
    xh: f64,
    xl: f64,
    /// `|xh| + |xl| + ex`, which bounds `|X~|` and `|X|`.
    xa: f64,
    /// `ex + gamma_4 (|xl| + 2.0001 u |xh|)`: multiplies `|h|` (the last term is
    /// the `u |p| + u |h'|` of the step, with `|p| + |h'| <= 2.0001 |h xh| + 1.0001 |c.hi|`;
    /// the `|c.hi|` part is folded into the stored coefficient error).
    kh: f64,
    /// `ex + gamma_4 |xh| + |xl|`: multiplies `|l|`.
    kl: f64,
}

impl CompArg {
    #[inline(always)]
    fn new(x: BoundedDd) -> CompArg {
        let (xh, xl, ex) = (x.v.hi, x.v.lo, x.e);
        let kh = ex + GAMMA4 * (xl.abs() + 2.0001 * U * xh.abs());
        CompArg { xh, xl, xa: xh.abs() + xl.abs() + ex, kh, kl: ex + GAMMA4 * xh.abs() + xl.abs() }
    }
}

impl CompAcc {
    #[inline(always)]
    fn start(c: Dd, ec: f64) -> CompAcc {
        CompAcc { h: c.hi, l: c.lo, e: ec }
    }

    /// `S X + C`: `h' + sigma = fl(h xh) + pi + c.hi` exactly (two_prod, two_sum),
    /// `l' = fl((pi + sigma) + (h xl + (l xh + c.lo)))`; `ec` is the coefficient's
    /// own error plus `gamma_4 (|c.lo| + 1.0001 u |c.hi|)` (precomputed).
    #[inline(always)]
    fn step<P: ExactProduct>(self, x: CompArg, c: Dd, ec: f64) -> CompAcc {
        let (p, pi) = P::two_prod(self.h, x.xh);
        let (h, sigma) = two_sum(p, c.hi);
        let l = (pi + sigma) + (self.h * x.xl + (self.l * x.xh + c.lo));
        let e = self.e * x.xa + self.h.abs() * x.kh + self.l.abs() * x.kl + ec;
        CompAcc { h, l, e }
    }

    #[inline(always)]
    fn finish(self) -> BoundedDd {
        let (hi, lo) = two_sum(self.h, self.l);
        BoundedDd { v: Dd { hi, lo }, e: self.e }
    }
}

/// A cheap estimate of `ln(v)` for `0 < v < 1`, at most the true value
/// (`log2(m) >= m - 1` on `[1, 2)`); it only picks where the checked truncation
/// search starts, so its accuracy affects the speed, not the bound.
#[inline(always)]
fn ln_lower(v: f64) -> f64 {
    let bits = v.to_bits();
    let exp = ((bits >> 52) & 0x7ff) as f64 - 1023.0;
    let mant = f64::from_bits((bits & ((1u64 << 52) - 1)) | (1023u64 << 52));
    (exp + mant - 1.0) * std::f64::consts::LN_2
}

/// The certified per-contact data of the Bessel form.
#[derive(Debug, Clone)]
pub(crate) struct CertifiedBessel {
    d: BoundedDd,
    /// `J_0(D), J_1(D)`.
    j01: [BoundedDd; 2],
    /// `u_{i+1} = (-1)^i J_{2i+2}(D)`, `i = 0..N`: the `u` sum is `X sum_i u_{i+1} X^i`, `X = q^2`.
    u_coef: Vec<Dd>,
    /// `T_i = sum_{n=i+1}^{N} (-1)^{n+1} n J_{2n}(D)`, `i = 0..N`: the gradient sum
    /// `sum_n (-1)^{n+1} n J_{2n} geo_n = (1 + q) sum_i T_i q^{2i}` (collecting the
    /// powers `q^{2i}` and `q^{2i+1}` of `geo_n = sum_{j<2n} q^j`).
    du_coef: Vec<Dd>,
    /// Error bounds of the coefficients plus `gamma_4 |lo|` (the Horner step's share).
    u_err: Vec<f64>,
    du_err: Vec<f64>,
    /// `max` over both sums of `sum_{i' >= i} (|c_i'| + err_i')`, rounded up; entry `N` is 0.
    suffix: Vec<f64>,
    /// Tolerance of the Horner truncation, `2^-72 min(1, D)`.
    horner_tol: f64,
    /// `ln(horner_tol / suffix[0])` (where the truncation search starts).
    ln_tol_over_suffix: f64,
    n_terms: usize,
    /// `sum_{n>N} (D/2)^{2n}/(2n)!`, rounded up.
    tail0: f64,
    /// `sum_{n>N} n^2 (D/2)^{2n}/(2n)!`, rounded up.
    tail2: f64,
}

/// `N` and the tails `sum_{n>N} (D/2)^{2n}/(2n)!`, `sum_{n>N} n^2 (D/2)^{2n}/(2n)!`
/// in f64, rounded up: the terms `t_m = (D/2)^{2m}/(2m)!` by their ratio
/// `h^2/((2m-1) 2m)` (three roundings per step, covered by `1 + 4u`), and once the
/// ratio of the weighted terms `rho = h^2 ((m+1)/m)^2/((2m+1)(2m+2))` is below
/// 1/2, the tails from `m` are at most `t_m m^p/(1 - rho)` (decreasing ratios).
/// `half_d_up >= D/2`. `None` if `N` passes `max_n`.
fn bessel_tails(half_d_up: f64, max_n: usize) -> Option<(usize, f64, f64)> {
    let h2 = half_d_up * half_d_up * (1.0 + 2.0 * U);
    let mut t = 1.0f64; // t_0
    for m in 1..=max_n + 1 {
        let mf = m as f64;
        t = t * h2 / ((2.0 * mf - 1.0) * (2.0 * mf)) * (1.0 + 4.0 * U);
        let rho = h2 / ((2.0 * mf + 1.0) * (2.0 * mf + 2.0)) * ((mf + 1.0) / mf).powi(2) * (1.0 + 8.0 * U);
        if rho < 0.5 {
            let tail0 = t / (1.0 - rho) * (1.0 + 4.0 * U);
            let tail2 = t * mf * mf / (1.0 - rho) * (1.0 + 8.0 * U);
            if tail0 <= BESSEL_TAIL_TARGET && tail2 <= BESSEL_TAIL_TARGET {
                return Some((m - 1, tail0, tail2));
            }
        }
    }
    None
}

/// `J_n(D) = (D/2)^n/n! sum_k t_k`, `t_{k+1} = t_k z/((k+1)(n+k+1))`, `z = -(D/2)^2`
/// [DLMF 10.2.2] in [`BoundedDd`]: `pre` is `(D/2)^n/n!`. The sum stops at the
/// first `K` with ratio bound `|z|/((K+1)(n+K+1)) <= 1/2` and
/// `|t_K| <= 2^-108 |S|`; the tail is then at most `2 |t_K|` (the downward
/// recurrence amplifies the top errors by up to `~2^100` at `D = 33.5`, but in
/// absolute terms to `~1e-20`).
#[inline(always)]
fn j_series<P: ExactProduct>(pre: BoundedDd, z: BoundedDd, n: usize) -> Option<BoundedDd> {
    let z_up = z.mag() + z.e;
    let mut t = BoundedDd::ONE;
    let mut s = BoundedDd::ONE;
    let mut k = 0usize;
    let tail = loop {
        let div = ((k + 1) * (n + k + 1)) as f64; // exact
        t = t.mul_p::<P>(z.div_f64_p::<P>(div));
        k += 1;
        let t_up = t.mag() + t.e;
        if z_up <= 0.5 * ((k + 1) * (n + k + 1)) as f64 && t_up <= TAIL_REL_SERIES * s.mag() {
            break 2.0 * t_up;
        }
        s = s.add(t);
        if k > 10_000 || !t_up.is_finite() {
            return None;
        }
    };
    s.e += tail;
    Some(pre.mul_p::<P>(s))
}

/// `J_0(D), ..., J_top(D)` with proven bounds, natively: `J_{top-1}`, `J_top` by
/// the power series, the rest by the recurrence `J_{k-1} = (2k/D) J_k - J_{k+1}`
/// [DLMF 10.6.1] run downward, everything in [`BoundedDd`] (module docs).
#[inline(always)]
fn native_sequence<P: ExactProduct>(d: BoundedDd, top: usize) -> Option<Vec<BoundedDd>> {
    if top < 2 || top as u64 > MAX_TABLE_FACTORIAL {
        return None;
    }
    let h = d.mul_f64_p::<P>(0.5);
    let z = h.mul_p::<P>(h).neg();
    // (D/2)^m by binary powering, then 1/m! from the table (relative error <= TABLE_ETA).
    let m = top - 1;
    let (mut acc, mut base, mut e) = (BoundedDd::ONE, h, m);
    while e > 0 {
        if e & 1 == 1 {
            acc = acc.mul_p::<P>(base);
        }
        e >>= 1;
        if e > 0 {
            base = base.mul_p::<P>(base);
        }
    }
    let f = inv_factorials()[m];
    let inv_fact = BoundedDd { v: f, e: TABLE_ETA * crate::ball::mag(f) };
    let pre_m = acc.mul_p::<P>(inv_fact);
    let pre_top = pre_m.mul_p::<P>(h).div_f64_p::<P>(top as f64);
    let mut y = vec![BoundedDd::ZERO; top + 1];
    y[m] = j_series::<P>(pre_m, z, m)?;
    y[top] = j_series::<P>(pre_top, z, top)?;
    // Below the turning point (`k < D`) the downward recurrence's running bound
    // grows like `e^{0.47 D}` on top of the `e^{0.55 D}` above it; from
    // `D = 25` on, the orders below `nf = floor(x) - 1` come instead from the
    // forward recurrence of `native_recurrence.rs` at `x = D.hi` (Hankel's
    // `J_0`, `J_1`; energy-norm bound, no such growth), moved to `D = x + delta`
    // by Taylor: `J_k(D) = J_k(x) + delta (J_{k-1}(x) - J_{k+1}(x))/2 + R`,
    // `|R| <= delta^2/2` (`|J_k''| <= 1`, DLMF 10.6.1, 10.14.1).
    let x = d.v.hi;
    let nf = if (HANKEL_MIN_X..=HANKEL_MAX_X).contains(&x) { x.floor() as usize - 1 } else { 0 };
    if nf >= m {
        return None;
    }
    let inv = BoundedDd::ONE.div(d)?;
    for k in (nf + 1..=m).rev() {
        y[k - 1] = y[k].mul_p::<P>(inv).mul_f64_p::<P>((2 * k) as f64).sub(y[k + 1]);
    }
    if nf > 0 {
        let (j0, j1) = bessel_j01::<P>(x)?;
        let mut fw = vec![BoundedDd::ZERO; nf + 1];
        forward_sequence::<P>(nf as u64, x, j0, j1, &mut fw)?;
        let delta = BoundedDd { v: Dd::from_f64(d.v.lo), e: d.e };
        let delta_up = delta.mag() + delta.e;
        let rem = 0.5 * delta_up * delta_up * (1.0 + 4.0 * U);
        for k in 0..nf {
            let below = if k == 0 { fw[1].neg() } else { fw[k - 1] };
            let deriv = below.sub(fw[k + 1]).mul_f64_p::<P>(0.5);
            let mut v = fw[k].add(delta.mul_p::<P>(deriv));
            v.e += rem;
            y[k] = v;
        }
    }
    Some(y)
}

impl CertifiedBessel {
    /// Certified `D` and `J_n(D)` for `a > 0`, `zeta > 0` (validated by the
    /// caller): natively in double-double where that certifies (`D` up to about
    /// 60), else at [`CERT_PREC`] bits in MP.
    pub(crate) fn new(a: f64, zeta: f64) -> Result<CertifiedBessel> {
        match Self::native_only(a, zeta) {
            Some(c) => Ok(c),
            None => Self::new_mp_counted(a, zeta),
        }
    }

    /// [`CertifiedBessel::new_mp`], counted by [`wave_bounded_mp_contacts`].
    pub(crate) fn new_mp_counted(a: f64, zeta: f64) -> Result<CertifiedBessel> {
        MP_CONTACTS.fetch_add(1, Ordering::Relaxed);
        Self::new_mp(a, zeta)
    }

    /// The native per-contact data only (`None` where it does not certify;
    /// the estimate paths then use the double-double Miller data instead).
    pub(crate) fn native_only(a: f64, zeta: f64) -> Option<CertifiedBessel> {
        #[cfg(target_arch = "x86_64")]
        if has_fma() {
            // SAFETY: the CPU supports FMA (checked just above).
            return unsafe { native_fused(a, zeta) };
        }
        Self::native::<Dekker>(a, zeta)
    }

    /// The native per-contact data (`None` where it does not certify).
    #[inline(always)]
    fn native<P: ExactProduct>(a: f64, zeta: f64) -> Option<CertifiedBessel> {
        let two_pi = BoundedDd { v: Dd::TWO_PI, e: TWO_PI_ERR };
        let d = two_pi.mul_f64_p::<P>(a).div_f64_p::<P>(zeta);
        let half_up = (d.mag() + d.e) * 0.5 * (1.0 + 2.0 * U);
        let (n_terms, tail0, tail2) = bessel_tails(half_up, (MAX_TABLE_FACTORIAL as usize - 2) / 2)?;
        let n_terms = n_terms.max(1);
        let j = native_sequence::<P>(d, 2 * n_terms + 1)?;
        if !j.iter().all(|v| v.e <= NATIVE_J_ERR_MAX) {
            return None;
        }
        Some(Self::from_sequence(d, &j, n_terms, tail0, tail2))
    }

    /// The MP route: `J_n(D)` as balls at [`CERT_PREC`] bits
    /// ([`bessel_j_sequence_mp`] at the midpoint of the ball `D`, widened by
    /// `rad(D)` since `|J_n'| <= 1` [DLMF 10.14.1]).
    pub(crate) fn new_mp(a: f64, zeta: f64) -> Result<CertifiedBessel> {
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
        let jt: Vec<BoundedDd> = j.iter().map(tr_from_ball).collect();
        Ok(Self::from_sequence(
            tr_from_ball(&d),
            &jt,
            n_terms as usize,
            tail0.to_f64_round(Round::Up),
            tail2.to_f64_round(Round::Up),
        ))
    }

    /// The Horner coefficients and their bounds from `J_0, ..., J_{2N+1}`.
    fn from_sequence(d: BoundedDd, jt: &[BoundedDd], n_terms: usize, tail0: f64, tail2: f64) -> CertifiedBessel {
        let sign = |n: usize| if n % 2 == 1 { 1.0 } else { -1.0 };
        let u: Vec<BoundedDd> = (0..n_terms).map(|i| jt[2 * i + 2].mul_f64(sign(i + 1))).collect();
        let mut du = vec![BoundedDd::ZERO; n_terms];
        let mut acc = BoundedDd::ZERO;
        for i in (0..n_terms).rev() {
            acc = acc.add(jt[2 * (i + 1)].mul_f64(sign(i + 1) * (i + 1) as f64));
            du[i] = acc;
        }
        let err = |c: &BoundedDd| (c.e + GAMMA4 * (c.v.lo.abs() + 1.0001 * U * c.v.hi.abs())) * (1.0 + 4.0 * U);
        let mut suffix = vec![0.0f64; n_terms + 1];
        let (mut su, mut sd) = (0.0f64, 0.0f64);
        for i in (0..n_terms).rev() {
            su = (su + u[i].mag() + err(&u[i])) * (1.0 + 4.0 * U);
            sd = (sd + du[i].mag() + err(&du[i])) * (1.0 + 4.0 * U);
            suffix[i] = su.max(sd);
        }
        let d_lo = d.v.hi.abs() - d.v.lo.abs() - d.e;
        let horner_tol = HORNER_TAIL_REL * d_lo.clamp(0.0, 1.0);
        let ln_tol_over_suffix = (horner_tol / suffix[0]).ln();
        CertifiedBessel {
            d,
            j01: [jt[0], jt[1]],
            u_coef: u.iter().map(|c| c.v).collect(),
            du_coef: du.iter().map(|c| c.v).collect(),
            u_err: u.iter().map(err).collect(),
            du_err: du.iter().map(err).collect(),
            suffix,
            horner_tol,
            ln_tol_over_suffix,
            n_terms,
            tail0,
            tail2,
        }
    }

    /// `(u_w(x), du_w/dx)` with proven bounds, or `None` where the native path
    /// does not certify (`x/a > 25/7`). `a <= x` and finiteness are the caller's.
    pub(crate) fn eval_bounded(&self, a: f64, amp: f64, x: f64) -> Option<(Bounded, Bounded)> {
        #[cfg(target_arch = "x86_64")]
        if has_fma() {
            // SAFETY: the CPU supports FMA (checked just above).
            return unsafe { eval_fused(self, a, amp, x) };
        }
        self.eval_with::<Dekker>(a, amp, x)
    }

    #[inline(always)]
    fn eval_with<P: ExactProduct>(&self, a: f64, amp: f64, x: f64) -> Option<(Bounded, Bounded)> {
        let rm1 = BoundedDd { v: Dd::diff(x, a), e: 0.0 }; // x - a, exact
        let rp1 = BoundedDd { v: Dd::diff(x, -a), e: 0.0 }; // x + a, exact
        let t = div_p::<P>(rm1, rp1)?.sqrt_p::<P>()?;
        let acosh_r = two_atanh::<P>(t)?;
        let one_minus_t = BoundedDd::ONE.sub(t);
        // q = (1 - t)/(1 + t) = (1 - t)^2/(1 - t^2) = (1 - t)^2 (x + a)/(2a)
        let q = one_minus_t.mul_p::<P>(one_minus_t).mul_p::<P>(rp1).div_f64_p::<P>(2.0 * a);
        let q2 = q.mul_p::<P>(q);
        let arg = CompArg::new(q2);
        // Truncate the Horner sums where the remainder is negligible (|X| <= xa).
        let n = self.n_terms;
        let mut top = n - 1;
        let mut rem = 0.0f64;
        if arg.xa < 1.0 {
            // first candidate from logarithms (xa^{i+1} suffix[0] <= tol), then checked
            let guess = (self.ln_tol_over_suffix / ln_lower(arg.xa)).floor() - 1.0;
            let start = if guess.is_finite() && guess > 0.0 { (guess as usize).min(n - 1) } else { 0 };
            let mut pw = arg.xa.powi(start as i32 + 1); // < 2^-40 relative error (covered below)
            for i in start..n - 1 {
                let r = pw * self.suffix[i + 1] * (1.0 + 1.0 / (1u64 << 40) as f64);
                if r <= self.horner_tol {
                    top = i;
                    rem = r;
                    break;
                }
                pw *= arg.xa;
            }
        }
        // Compensated Horner in q^2, the two sums interleaved.
        let (mut su, mut sdu) =
            (CompAcc::start(self.u_coef[top], self.u_err[top]), CompAcc::start(self.du_coef[top], self.du_err[top]));
        for i in (0..top).rev() {
            su = su.step::<P>(arg, self.u_coef[i], self.u_err[i]);
            sdu = sdu.step::<P>(arg, self.du_coef[i], self.du_err[i]);
        }
        let (mut su, mut sdu) = (su.finish(), sdu.finish());
        su.e += rem;
        sdu.e += rem;
        let mut su = su.mul_p::<P>(q2);
        let mut sdu = sdu.mul_p::<P>(BoundedDd::ONE.add(q));
        su.e += self.tail0;
        sdu.e += 2.0 * self.tail2;
        let inner = BoundedDd::ONE
            .sub(self.j01[0])
            .add(self.d.mul_p::<P>(self.j01[1]).mul_p::<P>(acosh_r))
            .add(su.mul_f64_p::<P>(2.0));
        let u = inner.mul_f64_p::<P>(amp);
        let du = one_minus_t.mul_p::<P>(sdu).mul_f64_p::<P>(4.0 * amp).div_f64_p::<P>(a);
        Some((u.finish()?, du.finish()?))
    }
}

/// [`CertifiedBessel::native`] compiled with the `fma` target feature.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "fma")]
unsafe fn native_fused(a: f64, zeta: f64) -> Option<CertifiedBessel> {
    CertifiedBessel::native::<crate::ball::Fused>(a, zeta)
}

/// [`CertifiedBessel::eval_with`] compiled with the `fma` target feature.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "fma")]
unsafe fn eval_fused(c: &CertifiedBessel, a: f64, amp: f64, x: f64) -> Option<(Bounded, Bounded)> {
    c.eval_with::<crate::ball::Fused>(a, amp, x)
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
            let v = two_atanh::<Dekker>(t).unwrap().finish().unwrap();
            let exact = Float::with_val(200, r).acosh();
            let diff = Float::with_val(200, &exact - v.value).abs().to_f64();
            assert!(diff <= v.err, "r={r}: {v} vs {exact}");
            assert!(v.err <= 4e-16 * v.value.abs().max(1e-300) || v.value == 0.0, "r={r}: {v}");
        }
    }

    /// The native per-contact `J_n(D)` lie within their bounds of the 300-bit
    /// values, on both sides of the switch to the forward recurrence (`D = 25`)
    /// and across the model domain (`D` up to 33.5), and they certify there.
    #[test]
    fn native_sequence_encloses_the_mp_values() {
        let cases = [(0.5, 1.125), (3.0, 1.125), (4.4, 1.125), (4.5, 1.125), (6.0, 1.125), (3.0, 0.5), (0.1, 2.0)];
        for &(a, zeta) in &cases {
            let two_pi = BoundedDd { v: Dd::TWO_PI, e: TWO_PI_ERR };
            let d = two_pi.mul_f64(a).div_f64_p::<Dekker>(zeta);
            let half_up = (d.mag() + d.e) * 0.5 * (1.0 + 2.0 * U);
            let (n, _, _) = bessel_tails(half_up, 84).unwrap();
            let top = 2 * n.max(1) + 1;
            let j = native_sequence::<Dekker>(d, top).unwrap();
            let dm = Float::with_val(300, crate::special::exact(2.0 * a)) * Float::with_val(300, rug::float::Constant::Pi)
                / Float::with_val(300, zeta);
            let reference = bessel_j_sequence_mp(top as u64, &dm, 300).unwrap();
            for (k, (v, r)) in j.iter().zip(reference.iter()).enumerate() {
                let got = Float::with_val(300, v.v.hi) + v.v.lo;
                let diff = Float::with_val(300, got - r.mid()).abs().to_f64();
                assert!(diff <= v.e, "a={a} zeta={zeta}: J_{k}: diff {diff:e} > bound {:e}", v.e);
                assert!(v.e <= NATIVE_J_ERR_MAX, "a={a} zeta={zeta}: J_{k}: bound {:e}", v.e);
            }
            assert!(CertifiedBessel::native::<Dekker>(a, zeta).is_some(), "a={a} zeta={zeta}");
        }
        // the whole model domain a in [0.5, 6], zeta = 9/8 is native (no MP contact data)
        for i in 0..=44 {
            let a = 0.5 + 0.125 * i as f64;
            assert!(CertifiedBessel::native::<Dekker>(a, 1.125).is_some(), "a={a}");
            assert!(CertifiedBessel::native_only(a, 1.125).is_some(), "a={a}");
        }
    }

    #[test]
    fn refuses_beyond_t_max() {
        let t = BoundedDd::exact(0.8);
        assert!(two_atanh::<Dekker>(t).is_none());
    }
}
