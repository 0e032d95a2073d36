//! The wave displacement `u_w(x)` and its gradient `du_w/dx` in f64 with a
//! **proven** error bound: the Bessel form of [`super`] evaluated
//! in double-double with a running error analysis, without MP on the model's
//! domain.
//!
//! # Method
//!
//! With `D = 2 pi a/zeta`, `r = x/a >= 1` and `t = sqrt((x-a)/(x+a))` in `[0, 1)`
//! (docs/displacement.md, Route 2; the module docs of [`super`]):
//!
//! ```text
//! q = (1 - t)/(1 + t) = (1 - t)^2 (x + a)/(2a),      acosh(r) = -ln q,
//! u_w     = A [1 - J0(D) + D J1(D) acosh(r) + 2 sum_{n=1}^{N} (-1)^{n+1} J_{2n}(D) q^{2n}],
//! du_w/dx = (4A/a) (1 - t) sum_{n=1}^{N} (-1)^{n+1} n J_{2n}(D) geo_n,   geo_n = sum_{j<2n} q^j,
//! ```
//!
//! (`(1 - q)/sqrt(r^2-1) = 1 - t`). Everything is a function of `t`, computed
//! from the exact `x - a` and `x + a`, so nothing cancels at the contact edge.
//! With the gradient sum written as `(1 + q) S`, `(1 - t)(1 + q) = 2q`, so
//! `du_w/dx = (8A/a) q S`.
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
//!   (`|J_k''| <= 1` [DLMF 10.14.1]; the Taylor term, below `ulp(D)`, in f64
//!   with its rounding bounded); for `D < 25` the downward recurrence runs to 0.
//!   The downward step `J_{k-1} = c_k J_k - J_{k+1}`, `c_k = 2k/D`, is one fused
//!   `BoundedDd::mul_sub_p` (error model in `crate::ball::dd_bounded`).
//!
//! Every step is a `BoundedDd` operation (the error model of
//! `crate::ball::dd_bounded`); the data are accepted when every `J_k` is known
//! to `2^-60` (over `a in [0.5, 6]`, `zeta = 9/8` the bounds are below `1e-19`;
//! a unit test checks them against 300-bit values). Where not (`D` beyond
//! about 60, where `2N+1` passes the `1/n!` table), the data come from MP at
//! [`CERT_PREC`] bits (counted in [`crate::special::fallback_counts`]). The sums become
//! polynomials in `X = q^2` (`u`: coefficients `(-1)^{m+1} J_{2m}`; gradient:
//! `(1 + q) sum_m T_m X^m`, `T_m = sum_{n>m} (-1)^{n+1} n J_{2n}`), with the
//! coefficients' bounds.
//!
//! **Per x** (about 0.2 us): `t^2 = (x-a)/(x+a)` (`div_p`: one division
//! by the leading part and the double-double `1 - eps`, no long division),
//! `t` by the double-double square root, `q = (1 - t)^2 ((x + a)/(2a))` (the
//! last factor with the per-contact `1/a`, off the critical path), `X = q^2`.
//! **acosh** (`neg_ln`): `acosh(r) = -ln q`, `q in [1/7, 1]`, without a
//! division: `q = 2^-b m`, `m in [1, 2)`, `c_j = 1 + j/64` the table point
//! nearest to `m`, `r_j = fl(1/c_j)`, `f = m r_j - 1` (`|f| <= 0.0079`) as a
//! double-double from one exact product, and
//! `ln q = L_{b,j} + f + f^2 P(f)`, `L_{b,j} = ln(2^-b/r_j)` from 192-bit MPFR
//! (a 4 x 65 table built on first use), `P(f) = sum_{k=2}^{10} (-1)^{k+1} f^{k-2}/k`
//! by Horner in f64 (its errors enter multiplied by `f^2 <= 6.3e-5`). Then both
//! sums by one compensated Horner loop (the two sums in the two lanes of one
//! SSE register where the CPU has FMA), truncated at the first power `i` with
//! `|X|^{i+1} sum_{i'>i} (|c_i'| + e_i') <= 2^-62 min(1, D)`, decided by cheap
//! logarithm bounds against a per-contact table (the remainder is added to the
//! bound; at `x/a = 3` about 13 of 41 terms).
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
//!   `|p| + |h'| <= 2.0001 |h xh| + 1.0001 |c.hi|`). Unrolled over the `k`
//!   steps, `eps <= E + (H kh + L kl) G`: `E` is the Horner sum of the `e_c`
//!   at `xa` (one multiply-add a step), `H`, `L` the largest `|h|`, `|l|` met
//!   (running maxima over both sums), `G = k max(1, xa)^k`. The `l'` update may
//!   be evaluated as `fl(l xh + fl(fl(pi + sigma) + fl(h xl + c.lo)))` with fused
//!   multiply-adds, or with separate products; either way no term passes more
//!   than four roundings.
//! * `neg_ln`: `f` errs by `<= 6.1 u^2` (the rounding of `m.lo r_j + pe`,
//!   `|m.lo| <= u |m|`, `|pe| <= u |p|`) plus `r_j 2^b e_q`; the f64 part
//!   `g = fl(fl(y^2) P~(y))`, `y = f.hi`, errs by at most `10 u y^2` (Horner
//!   `gamma_16` on `sum |c_k| |y|^k <= 0.5027`, the coefficients' rounding
//!   `u 0.5027`, two final roundings), the truncation `|y|^11/(11 (1 - |y|)) < 7e-25`,
//!   and `0.008 (|f.lo| + e_f)` for `f - y` (`|d/df (ln(1 + f) - f)| <= 0.008`);
//!   the table entries carry `|rest| + 2^-180`.
//! * `div_p`: `num/(H + L) = (num/H)(1 - eps) + r`, `eps = fl(L/H)`,
//!   `|r| <= 2.01 u^2 |num/H|` (charged `3 u^2`), plus `|num/den| e_den/(|den| - e_den)`.
//! * The truncated Bessel sums: `|J_{2n}(D)| <= (D/2)^{2n}/(2n)!` [DLMF 10.14.4],
//!   `0 <= q <= 1`, `0 <= geo_n <= 2n`, so the neglected terms are at most
//!   `tail0 = sum_{n>N} (D/2)^{2n}/(2n)!` and `2 tail2`, `tail2 = sum_{n>N} n^2 (D/2)^{2n}/(2n)!`
//!   (f64 with each step's three roundings covered by `1 + 4u`, and the geometric
//!   tail once the ratio is below 1/2; `bessel_tails`). Both are added to the
//!   Horner sums `S` before the final products: the `u` tail is `X` times a
//!   sum bounded by `tail0` (`X <= 1`), and the gradient tail `T` enters as
//!   `(1 - t) T = 2q (1 + t) T/2`, `(1 + t)/2 <= 1`.
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
//! [`crate::special::fallback_counts`] counts those calls (the benches report both counters).
//! Exact products are fused multiply-adds where the CPU has them (detected at
//! run time, as in `native.rs`), else Dekker's; both are exact.
//!
//! # From scratch: one pass (value, and value with a proven bound)
//!
//! `u_wave` / `du_wave` and `u_wave_bounded` / `du_wave_bounded` from scratch
//! do not build these per-contact data: the submodule `value` runs one
//! compensated f64 Miller recurrence with the sums in the same loop. As a
//! value its error is an estimate (tests/wave_value.rs); with the running
//! error bound of the recurrence alongside (the proof is the method block of
//! `value.rs`: the local error of the compensated step, propagated by the
//! triangle-inequality chain; Miller's start error by Nicholson's formula) it
//! returns a proven bound for one result per call (each entry point forms only
//! the sums its result needs), in 2.6k-5.5k instructions per `u_w` over the
//! model domain (the per-contact route here: 9.8k-31.8k). Where that bound exceeds
//! `2^-50` of the scales (`D` beyond about 40) the `*_bounded` functions use
//! the per-contact data here; [`wave_scratch_misses`] counts those calls.
//!
//! References: seed paper Eq. 12 and Appendix B.11; docs/displacement.md, Route 2;
//! DLMF 10.2.2, 10.6.1, 10.12.4, 10.14.1, 10.14.4; Dekker (1971); Hida, Li, Bailey (2007);
//! Joldes, Muller, Popescu, "Tight and rigorous error bounds for basic building
//! blocks of double-word arithmetic", ACM TOMS 44 (2017); Graillat, Langlois,
//! Louvet, "Algorithms for accurate, validated and fast polynomial
//! evaluation", Japan J. Indust. Appl. Math. 26 (2009); Higham, *Accuracy and
//! Stability of Numerical Algorithms*, 2nd ed. (2002).


use crate::ball::U;

/// Precision (bits) of the per-contact certified Bessel data on the MP route.
pub const CERT_PREC: u32 = 128;

/// Largest `t = sqrt((x/a - 1)/(x/a + 1))` of the native path (`x/a <= 25/7`).
pub const T_MAX: f64 = 0.75;

/// The Bessel sums are cut where both tails (`tail0`, `tail2`) are below this
/// (`2^-64`; relative to the scales `|A|` and `2 pi |A|/zeta` of the results
/// they weigh at most `2^-61`, far below the final rounding).
const BESSEL_TAIL_TARGET: f64 = 5.421_010_862_427_522e-20;

/// The Horner sums in `q^2` stop at the first power whose rigorous remainder
/// bound is below `2^-62 min(1, D)` (the remainder is added to the bound; in
/// `u_w` it weighs `2 |A| 2^-62`, in `du_w/dx` `8 |A| 2^-62 min(1, D)/a`,
/// both far below the final rounding).
const HORNER_TAIL_REL: f64 = 2.168_404_344_971_009e-19;

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

mod value;
pub(crate) use value::{wave_scratch_bounded, wave_value};

/// How many `u_wave_bounded` / `du_wave_bounded` / `WaveBessel::eval_bounded`
/// calls (per x) fell back to the MP path since the process started.
#[deprecated(note = "use `maugis::special::fallback_counts().wave_bounded`: one snapshot of every counter")]
pub fn wave_bounded_fallbacks() -> u64 {
    crate::special::fallback_counts().wave_bounded
}

static SCRATCH_MISSES: std::sync::atomic::AtomicU64 = std::sync::atomic::AtomicU64::new(0);

/// How many `u_wave_bounded` / `du_wave_bounded` calls since the process
/// started did not take the one-pass bounded route from scratch (no FMA,
/// `x/a > 25/7`, `D` beyond the table, or its bound above `2^-50` of the
/// scales) and went to the per-contact certified data (or MP, counted in
/// `maugis::special::fallback_counts().wave_bounded`). Not an MP fallback,
/// so not part of `fallback_counts()`.
pub fn wave_scratch_misses() -> u64 {
    SCRATCH_MISSES.load(std::sync::atomic::Ordering::Relaxed)
}

pub(crate) fn count_scratch_miss() {
    SCRATCH_MISSES.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
}

/// How many times the per-contact Bessel data of the bounded path were built
/// in MP (where the native double-double sequence does not certify: `D`
/// beyond about 60) since the process started.
#[deprecated(note = "use `maugis::special::fallback_counts().wave_bounded_mp_contacts`: one snapshot of every counter")]
pub fn wave_bounded_mp_contacts() -> u64 {
    crate::special::fallback_counts().wave_bounded_mp_contacts
}

pub(crate) fn count_fallback() {
    crate::special::fallback::count(crate::special::F64Route::WaveBounded);
}

mod certified;
mod kernels;
pub(crate) use certified::CertifiedBessel;

#[cfg(test)]
mod tests {
    use rug::Float;
    use crate::ball::{BoundedDd, Dd, Dekker};
    use crate::special::bessel_j::bessel_j_sequence_mp;
    use super::certified::*;
    use super::kernels::*;
    use super::*;

    /// `-ln q` along the per-x path (`q` from `x/a` as in `eval_with`) encloses
    /// `acosh(x/a)`, including `x = a` and `x` one ulp above `a`.
    #[test]
    fn neg_ln_of_q_encloses_acosh() {
        for &r in &[1.0, 1.0 + f64::EPSILON, 1.0 + 1e-12, 1.001, 1.35, 2.0, 3.0, 3.5] {
            let rm1 = BoundedDd { v: Dd::diff(r, 1.0), e: 0.0 };
            let rp1 = BoundedDd { v: Dd::diff(r, -1.0), e: 0.0 };
            let t = rm1.div(rp1).unwrap().sqrt().unwrap();
            let one_minus_t = BoundedDd::ONE.sub(t);
            let q = one_minus_t.mul(one_minus_t).mul(rp1.mul_f64(0.5));
            let v = neg_ln::<Dekker>(q).unwrap();
            let exact = Float::with_val(300, r).acosh();
            let got = Float::with_val(300, v.v.hi) + v.v.lo;
            let diff = Float::with_val(300, &exact - &got).abs().to_f64();
            assert!(diff <= v.e, "r={r}: diff {diff:e} > bound {:e}", v.e);
            assert!(v.e <= 1e-19, "r={r}: bound {:e}", v.e);
        }
    }

    /// `-ln q` on a dense grid over the table's range `[1/8, 1]` (every
    /// table point and binade), against 300-bit MPFR; and the truncation constant.
    #[test]
    fn neg_ln_encloses_on_a_grid() {
        for i in 0..=4000 {
            let qh = 0.125 + 0.875 * (i as f64 / 4000.0);
            let q = BoundedDd { v: Dd { hi: qh, lo: if i % 3 == 0 { 1e-17 * qh } else { 0.0 } }, e: 1e-31 };
            let v = neg_ln::<Dekker>(q).unwrap();
            let exact = -Float::with_val(300, Float::with_val(300, qh) + q.v.lo).ln();
            let got = Float::with_val(300, v.v.hi) + v.v.lo;
            let diff = Float::with_val(300, &exact - &got).abs().to_f64();
            assert!(diff + 1e-31 * 8.01 <= v.e, "q={qh}: diff {diff:e}, bound {:e}", v.e);
            assert!(v.e <= 1e-19, "q={qh}: bound {:e}", v.e);
        }
        assert!(neg_ln::<Dekker>(BoundedDd::exact(0.1)).is_none());
        assert!(neg_ln::<Dekker>(BoundedDd::exact(2.0)).is_none());
        let f = Float::with_val(100, LN_F_MAX);
        let trunc = Float::with_val(100, rug::ops::Pow::pow(&f, 11u32)) / 11u32 / (1.0 - f);
        assert!(trunc < LN_TRUNC, "{trunc}");
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

    /// Both product strategies (Dekker's scalar kernel and, where the CPU has
    /// FMA, the two-lane fused kernel) enclose the 300-bit MP values.
    #[test]
    fn both_kernels_enclose_the_mp_values() {
        use crate::contact::displacement::{du_wave_mp, u_wave_mp};
        use crate::special::exact;
        for &a in &[0.5, 3.0, 6.0] {
            let c = CertifiedBessel::native::<Dekker>(a, 1.125).unwrap();
            for &r in &[1.0, 1.0001, 1.5, 3.0] {
                let x = a * r;
                let (ae, ze, me, xe) = (exact(a), exact(1.125), exact(1.0), exact(x));
                let u_ref = u_wave_mp(&ae, &ze, &me, &xe, 300).unwrap();
                let du_ref = du_wave_mp(&ae, &ze, &me, &xe, 300).unwrap();
                let mut results = vec![c.eval_with::<Dekker>(a, 1.0, x).unwrap()];
                if has_fma() {
                    results.push(c.eval_bounded(a, 1.0, x).unwrap());
                }
                for (u, du) in results {
                    for (b, r) in [(u, &u_ref), (du, &du_ref)] {
                        let diff = Float::with_val(300, r.mid() - b.value).abs().to_f64();
                        assert!(diff <= b.err, "a={a} x={x}: {b} vs {:?}", r);
                        assert!(b.err <= 2e-15, "a={a} x={x}: {b}");
                    }
                }
            }
        }
    }

    #[test]
    fn refuses_beyond_t_max() {
        let c = CertifiedBessel::native::<Dekker>(2.0, 1.125).unwrap();
        assert!(c.eval_with::<Dekker>(2.0, 1.0, 2.0 * 3.5).is_some());
        assert!(c.eval_with::<Dekker>(2.0, 1.0, 2.0 * 3.6).is_none());
    }
}



/// Where the from-scratch time of the bounded path goes: each part behind an
/// `#[inline(never)]` wrapper, so that `valgrind --tool=callgrind` on
/// `cargo test --release --lib displacement::bounded::profile -- --ignored` lists
/// their inclusive instruction counts (reported per call in the docs).
#[cfg(test)]
mod profile {
    use crate::ball::{Bounded, BoundedDd, Dd};
    use crate::special::bessel_j::MAX_TABLE_FACTORIAL;
    use super::certified::*;
    use super::kernels::*;
    use super::*;
    use std::hint::black_box;

    #[inline(never)]
    #[target_feature(enable = "fma")]
    unsafe fn part_d(a: f64, zeta: f64) -> BoundedDd {
        let two_pi = BoundedDd { v: Dd::TWO_PI, e: TWO_PI_ERR };
        two_pi.mul_f64_p::<crate::ball::Fused>(a).div_f64_p::<crate::ball::Fused>(zeta)
    }
    #[inline(never)]
    #[target_feature(enable = "fma")]
    unsafe fn part_tails(d: BoundedDd) -> Option<(usize, f64, f64)> {
        bessel_tails((d.mag() + d.e) * 0.5 * (1.0 + 2.0 * U), (MAX_TABLE_FACTORIAL as usize - 2) / 2)
    }
    #[inline(never)]
    #[target_feature(enable = "fma")]
    unsafe fn part_top_series(d: BoundedDd, top: usize) -> Option<(BoundedDd, BoundedDd)> {
        let h = d.mul_f64_p::<crate::ball::Fused>(0.5);
        let z = h.mul_p::<crate::ball::Fused>(h).neg();
        Some((j_series::<crate::ball::Fused>(BoundedDd::ONE, z, top - 1)?, j_series::<crate::ball::Fused>(BoundedDd::ONE, z, top)?))
    }
    #[inline(never)]
    #[target_feature(enable = "fma")]
    unsafe fn part_sequence(d: BoundedDd, top: usize) -> Option<Vec<BoundedDd>> {
        native_sequence::<crate::ball::Fused>(d, top)
    }
    #[inline(never)]
    #[target_feature(enable = "fma")]
    unsafe fn part_tables(a: f64, d: BoundedDd, j: &[BoundedDd], n: usize, t0: f64, t2: f64) -> CertifiedBessel {
        CertifiedBessel::from_sequence::<crate::ball::Fused>(a, d, j, n, t0, t2)
    }
    #[inline(never)]
    #[target_feature(enable = "fma")]
    unsafe fn part_per_x(c: &CertifiedBessel, a: f64, x: f64) -> Option<(Bounded, Bounded)> {
        c.eval_bounded(a, 1.0, x)
    }
    #[inline(never)]
    #[target_feature(enable = "fma")]
    unsafe fn part_value(a: f64, x: f64) -> Option<(f64, f64)> {
        wave_value(a, 1.125, 1.0, x)
    }

    // Ignored: a profiling harness for callgrind, not a check. It loops over each
    // part of the from-scratch path (PROFILE_N times, at PROFILE_A) so that
    // `valgrind --tool=callgrind` can attribute instructions per part; it
    // asserts nothing about the results, and needs a CPU with FMA. Run by hand:
    // `cargo test --release --lib profile_parts -- --ignored`.
    #[test]
    #[ignore = "profiling harness for callgrind, asserts nothing (see the comment above)"]
    fn profile_parts() {
        let a: f64 = std::env::var("PROFILE_A").ok().and_then(|v| v.parse().ok()).unwrap_or(6.0);
        // SAFETY: the machine that runs this profile has FMA (asserted).
        assert!(has_fma());
        unsafe {
            let x = 2.0 * a;
            let mut acc = 0.0;
            let iters: usize = std::env::var("PROFILE_N").ok().and_then(|v| v.parse().ok()).unwrap_or(1000);
            for _ in 0..iters {
                let d = part_d(black_box(a), 1.125);
                let (n, t0, t2) = part_tails(d).unwrap();
                let top = 2 * n.max(1) + 1;
                acc += part_top_series(d, top).unwrap().0.v.hi;
                let j = part_sequence(d, top).unwrap();
                let c = part_tables(a, d, &j, n.max(1), t0, t2);
                acc += part_per_x(&c, a, black_box(x)).unwrap().0.value;
                acc += part_value(a, black_box(x)).unwrap().0;
            }
            eprintln!("a={a}: {acc}");
        }
    }
}

