//! The wave displacement `u_w(x)` and its gradient `du_w/dx` in f64 with a
//! **proven** error bound: the Bessel form of [`super::displacement`] evaluated
//! in double-double with a running error analysis, without MP on the model's
//! domain.
//!
//! # Method
//!
//! With `D = 2 pi a/zeta`, `r = x/a >= 1` and `t = sqrt((x-a)/(x+a))` in `[0, 1)`
//! (docs/displacement.md, Route 2; the module docs of [`super::displacement`]):
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
//! [`CERT_PREC`] bits ([`wave_bounded_mp_contacts`] counts it). The sums become
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
//! [`wave_bounded_fallbacks`] counts those calls (the benches report both counters).
//! Exact products are fused multiply-adds where the CPU has them (detected at
//! run time, as in `native.rs`), else Dekker's; both are exact.
//!
//! # The value path (estimate)
//!
//! `u_wave` / `du_wave` from scratch do not build these certified data: the
//! submodule `value` runs one compensated f64 Miller recurrence with both sums
//! in the same loop (about 5x fewer instructions than the per-contact data
//! here). Its error is an estimate, enforced by tests/wave_value.rs (method
//! block in `value.rs`).
//!
//! References: seed paper Eq. 12 and Appendix B.11; docs/displacement.md, Route 2;
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
pub(crate) use value::wave_value;

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

/// The reduction table of [`neg_ln`] has the points `c_j = 1 + j/LN_TABLE_STEPS`, `j = 0..=64`.
const LN_TABLE_STEPS: usize = 64;

/// Binades of `q` that [`neg_ln`] takes: `q in [2^-3, 2)` (`q >= 1/7` for `t <= T_MAX`).
const LN_BINADES: usize = 4;

/// Largest `|f| = |m r_j - 1|` [`neg_ln`] takes: `|m - c_j| <= 1/128`, `c_j >= 1`
/// give `|m/c_j - 1| <= 1/128 = 0.0078125`, and `r_j = fl(1/c_j)` adds `< 2u`.
const LN_F_MAX: f64 = 0.0079;

/// `ln(1 + f) = f + f^2 P(f)`, `P(f) = sum_{k=2}^{10} (-1)^{k+1} f^{k-2}/k`: the
/// coefficients `-1/2, 1/3, ..., -1/10`, each correctly rounded (relative error `<= u`).
const LN_COEF: [f64; 9] =
    [-1.0 / 2.0, 1.0 / 3.0, -1.0 / 4.0, 1.0 / 5.0, -1.0 / 6.0, 1.0 / 7.0, -1.0 / 8.0, 1.0 / 9.0, -1.0 / 10.0];

/// Truncation of [`LN_COEF`] at `|f| <= LN_F_MAX`: `|f|^11/(11 (1 - |f|)) < 6.9e-25`
/// (a unit test recomputes it).
const LN_TRUNC: f64 = 7.0e-25;

/// The reduction table of [`neg_ln`]: `r_j = fl(1/c_j)` and, for each binade
/// `q in [2^-b, 2^{1-b})`, `L_{b,j} = ln(2^-b / r_j)` as a double-double with
/// its error (MPFR at 192 bits, every operation correctly rounded, so the
/// 192-bit value is within `2^-185` of the exact one; then split: error
/// `<= |rest| + 2^-180`).
struct LnTable {
    r: [f64; LN_TABLE_STEPS + 1],
    l: [[BoundedDd; LN_TABLE_STEPS + 1]; LN_BINADES],
}

fn ln_table() -> &'static LnTable {
    static TABLE: std::sync::OnceLock<LnTable> = std::sync::OnceLock::new();
    TABLE.get_or_init(|| {
        let r: [f64; LN_TABLE_STEPS + 1] =
            std::array::from_fn(|j| 1.0 / (1.0 + j as f64 / LN_TABLE_STEPS as f64)); // c_j exact
        let ln2 = Float::with_val(192, rug::float::Constant::Log2);
        let l = std::array::from_fn(|b| {
            std::array::from_fn(|j| {
                let mut v = Float::with_val(192, r[j]).ln(); // ln r_j
                v += Float::with_val(192, &ln2 * b as u32); // + b ln 2
                let v = -v; // ln(2^-b / r_j)
                let hi = v.to_f64();
                let rest = Float::with_val(192, &v - hi);
                let lo = rest.to_f64();
                let rem = Float::with_val(192, &rest - lo).abs().to_f64_round(Round::Up);
                BoundedDd { v: Dd { hi, lo }, e: (rem + 6.5e-55).next_up() } // 2^-180 < 6.5e-55
            })
        });
        LnTable { r, l }
    })
}

/// `-ln(q) = acosh(x/a)` for `q in [1/8, 2)` with a proven bound (module docs,
/// "acosh"): `q = 2^-b m`, `m in [1, 2)`, `c_j` the table point nearest to `m`,
/// `f = m r_j - 1` as a double-double from one exact product (no division:
/// `p + pe = m.hi r_j`, `p - 1` exact by Sterbenz, `fl(m.lo r_j + pe)` off by
/// `<= 2.01 u (2u + 1.01u) < 6.1 u^2`), and
/// `ln q = L_{b,j} + f + f^2 P(f)`, the last term in f64 at `y = f.hi`: Horner
/// over 9 coefficients, two roundings a step (`gamma_16`, on `sum |c_k| |y|^k <= 0.5027`),
/// the coefficients' rounding (`u 0.5027`), `fl(fl(y^2) P~)` (`2.0001 u`):
/// together `<= 10 u y^2`; plus [`LN_TRUNC`]; plus the move from `y` to the exact
/// `f` (`|d/df (ln(1+f) - f)| = |f/(1+f)| <= 0.008`). `None` outside the table.
#[inline(always)]
fn neg_ln<P: ExactProduct>(q: BoundedDd) -> Option<BoundedDd> {
    let (qh, ql) = (q.v.hi, q.v.lo);
    let bits = qh.to_bits();
    let b = 1023 - ((bits >> 52) & 0x7ff) as i64; // q.hi in [2^-b, 2^{1-b})
    if !(0..LN_BINADES as i64).contains(&b) || qh <= 0.0 {
        return None;
    }
    let scale = f64::from_bits(((1023 + b) as u64) << 52); // 2^b, exact scaling
    let (mh, ml) = (qh * scale, ql * scale);
    let j = ((mh - 1.0) * LN_TABLE_STEPS as f64).round() as usize; // 0..=64
    let table = ln_table();
    let r = table.r[j];
    let (p, pe) = P::two_prod(mh, r);
    let (fh, fl) = two_sum(p - 1.0, ml * r + pe);
    if !(fh.abs() <= LN_F_MAX) {
        return None;
    }
    let e_f = r * scale * q.e + 6.1 * U * U;
    let mut pv = LN_COEF[8];
    for &c in LN_COEF[..8].iter().rev() {
        pv = pv * fh + c;
    }
    let y2 = fh * fh;
    let g = y2 * pv;
    let e_g = 10.0 * U * y2 + LN_TRUNC + 0.008 * (fl.abs() + e_f);
    let f = BoundedDd { v: Dd { hi: fh, lo: fl }, e: e_f };
    let ln_q = table.l[b as usize][j].add(f.add(BoundedDd { v: Dd::from_f64(g), e: e_g }));
    Some(ln_q.neg())
}

/// The per-`x` constants of a compensated Horner step: the argument
/// `X = xh + xl` (a double-double) with its error `ex`, and the multipliers of
/// the rounding bound.
#[derive(Clone, Copy)]
pub(crate) struct CompArg {
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

/// Both compensated Horner sums over `coef` (rows `[u.hi, T.hi, u.lo, T.lo, e_u, e_T]`,
/// highest power last) at the argument `x`, in one loop (module docs,
/// "Compensated Horner"). One step of an accumulator `h + l` forms
/// `p + pi = h xh` (exact product), `h' + sigma = p + c.hi` (exact sum) and
/// `l' = fl((pi + sigma) + (h xl + (l xh + c.lo)))`. Its error obeys
/// `eps' <= eps xa + |h| kh + |l| kl + e_c`; unrolled over the `top` steps,
/// `eps <= E + (H kh + L kl) G`, where `E` is the Horner sum of the `e_c` at `xa`
/// (run alongside, one multiply-add per step), `H`, `L` the largest `|h|`, `|l|`
/// over both sums and all steps (running maxima), and `G = sum_{k<top} xa^k
/// <= top max(1, xa)^top`. (`kh ~ u^2`, `kl ~ u`, `L ~ u H`: that second part is
/// `~ top u^2 H`, far below `E`.)
#[inline(always)]
fn comp_horner2<P: ExactProduct>(x: CompArg, coef: &[[f64; 6]]) -> (BoundedDd, BoundedDd) {
    let Some((last, rest)) = coef.split_last() else {
        return (BoundedDd::exact(0.0), BoundedDd::exact(0.0)); // the empty sums
    };
    let (mut uh, mut ul, mut ue) = (last[0], last[2], last[4]);
    let (mut dh, mut dl, mut de) = (last[1], last[3], last[5]);
    let (mut hmax, mut lmax) = (0.0f64, 0.0f64);
    let big = |a: f64, b: f64| if a > b { a } else { b };
    for c in rest.iter().rev() {
        hmax = big(big(hmax, uh.abs()), dh.abs());
        lmax = big(big(lmax, ul.abs()), dl.abs());
        let (p, pi) = P::two_prod(uh, x.xh);
        let (h, sigma) = two_sum(p, c[0]);
        ul = ul * x.xh + ((pi + sigma) + (uh * x.xl + c[2]));
        uh = h;
        ue = ue * x.xa + c[4];
        let (p, pi) = P::two_prod(dh, x.xh);
        let (h, sigma) = two_sum(p, c[1]);
        dl = dl * x.xh + ((pi + sigma) + (dh * x.xl + c[3]));
        dh = h;
        de = de * x.xa + c[5];
    }
    horner2_finish(x, rest.len() as u32, hmax, lmax, [uh, ul, ue], [dh, dl, de])
}

/// The end of [`comp_horner2`]: both accumulators as bounded double-doubles,
/// with the `(H kh + L kl) G` part of the bound.
#[inline(always)]
fn horner2_finish(x: CompArg, steps: u32, hmax: f64, lmax: f64, u: [f64; 3], du: [f64; 3]) -> (BoundedDd, BoundedDd) {
    let g = steps as f64 * if x.xa <= 1.0 { 1.0 } else { pow_int(x.xa, steps) * (1.0 + 1.0 / (1u64 << 40) as f64) };
    let extra = (hmax * x.kh + lmax * x.kl) * g;
    let fin = |[h, l, e]: [f64; 3]| {
        let (hi, lo) = two_sum(h, l);
        BoundedDd { v: Dd { hi, lo }, e: e + extra }
    };
    (fin(u), fin(du))
}

/// [`comp_horner2`] with both sums in the two lanes of one SSE register
/// (`[u, T]`), fused multiply-adds for the exact products and the low parts
/// (`l' = fl(l xh + fl(fl(pi + sigma) + fl(h xl + c.lo)))`: every term passes at
/// most three roundings, within the `gamma_4` of the bound). Same bound.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "fma")]
#[inline]
fn comp_horner2_fma(x: CompArg, coef: &[[f64; 6]]) -> (BoundedDd, BoundedDd) {
    use std::arch::x86_64::*;
    let Some((last, rest)) = coef.split_last() else {
        return (BoundedDd::exact(0.0), BoundedDd::exact(0.0)); // the empty sums
    };
    // SAFETY: each row has 6 f64; the unaligned loads read rows [0..2], [2..4], [4..6].
    let load = |row: &[f64; 6], k: usize| unsafe { _mm_loadu_pd(row.as_ptr().add(k)) };
    let (mut h, mut l, mut e) = (load(last, 0), load(last, 2), load(last, 4));
    let (xh, xl, xa) = (_mm_set1_pd(x.xh), _mm_set1_pd(x.xl), _mm_set1_pd(x.xa));
    let sign = _mm_set1_pd(-0.0);
    let (mut hmax, mut lmax) = (_mm_setzero_pd(), _mm_setzero_pd());
    for c in rest.iter().rev() {
        hmax = _mm_max_pd(hmax, _mm_andnot_pd(sign, h));
        lmax = _mm_max_pd(lmax, _mm_andnot_pd(sign, l));
        let (ch, cl, ce) = (load(c, 0), load(c, 2), load(c, 4));
        let p = _mm_mul_pd(h, xh);
        let pi = _mm_fmsub_pd(h, xh, p);
        let s = _mm_add_pd(p, ch);
        let bb = _mm_sub_pd(s, p);
        let sigma = _mm_add_pd(_mm_sub_pd(p, _mm_sub_pd(s, bb)), _mm_sub_pd(ch, bb));
        l = _mm_fmadd_pd(l, xh, _mm_add_pd(_mm_add_pd(pi, sigma), _mm_fmadd_pd(h, xl, cl)));
        h = s;
        e = _mm_fmadd_pd(e, xa, ce);
    }
    let mut out = [[0.0f64; 2]; 5];
    // SAFETY: five 2-lane stores into arrays of two f64.
    unsafe {
        _mm_storeu_pd(out[0].as_mut_ptr(), h);
        _mm_storeu_pd(out[1].as_mut_ptr(), l);
        _mm_storeu_pd(out[2].as_mut_ptr(), e);
        _mm_storeu_pd(out[3].as_mut_ptr(), hmax);
        _mm_storeu_pd(out[4].as_mut_ptr(), lmax);
    }
    let hm = out[3][0].max(out[3][1]);
    let lm = out[4][0].max(out[4][1]);
    horner2_finish(x, rest.len() as u32, hm, lm, [out[0][0], out[1][0], out[2][0]], [out[0][1], out[1][1], out[2][1]])
}

/// The product strategy of the per-`x` path and its Horner kernel: scalar
/// for Dekker's products, the two-lane SSE kernel with fused multiply-adds.
pub(crate) trait WaveKernel: ExactProduct + Sized {
    fn horner2(x: CompArg, coef: &[[f64; 6]]) -> (BoundedDd, BoundedDd) {
        comp_horner2::<Self>(x, coef)
    }
}

impl WaveKernel for Dekker {}

impl WaveKernel for crate::ball::Fused {
    #[inline(always)]
    fn horner2(x: CompArg, coef: &[[f64; 6]]) -> (BoundedDd, BoundedDd) {
        #[cfg(target_arch = "x86_64")]
        if has_fma() {
            // SAFETY: the CPU supports FMA (checked just above).
            return unsafe { comp_horner2_fma(x, coef) };
        }
        comp_horner2::<Self>(x, coef)
    }
}

/// `v = 2^e m`, `m in [1, 2)`, for a positive normal `v`.
#[inline(always)]
fn exponent_mantissa(v: f64) -> (f64, f64) {
    let bits = v.to_bits();
    let exp = ((bits >> 52) & 0x7ff) as f64 - 1023.0;
    (exp, f64::from_bits((bits & ((1u64 << 52) - 1)) | (1023u64 << 52)))
}

/// Slack on the cheap logarithm bounds below: covers their own f64 roundings
/// (`|e| <= 1100` times `ln 2`'s rounding, a few `u` on values below 800).
const LN_BOUND_SLACK: f64 = 1e-9;

/// A lower bound of `ln(v)` for a positive normal `v` (`log2(m) >= m - 1` on
/// `[1, 2)`, concavity; within 0.06 of the true value).
#[inline(always)]
fn ln_lower(v: f64) -> f64 {
    let (exp, m) = exponent_mantissa(v);
    (exp + m - 1.0) * std::f64::consts::LN_2 - LN_BOUND_SLACK
}

/// An upper bound of `ln(v)` for a positive normal `v`: `ln m` lies below its
/// tangent at `3/2`, `ln(3/2) + (m - 3/2)/(3/2)` (within 0.072 on `[1, 2)`).
#[inline(always)]
fn ln_upper(v: f64) -> f64 {
    let (exp, m) = exponent_mantissa(v);
    exp * std::f64::consts::LN_2 + 0.405_465_108_108_164_4 + (m - 1.5) * (2.0 / 3.0) + LN_BOUND_SLACK
}

/// The certified per-contact data of the Bessel form.
#[derive(Debug, Clone)]
pub(crate) struct CertifiedBessel {
    /// `1 - J_0(D)`.
    one_minus_j0: BoundedDd,
    /// `D J_1(D)`.
    d_j1: BoundedDd,
    /// `1/a` (one double-double quotient, with its bound).
    inv_a: BoundedDd,
    /// The Horner coefficients of both sums, interleaved (one load stream):
    /// `[u.hi, T.hi, u.lo, T.lo, e_u, e_T]` for `i = 0..N`, where
    /// `u_{i+1} = (-1)^i J_{2i+2}(D)` (the `u` sum is `X sum_i u_{i+1} X^i`, `X = q^2`),
    /// `T_i = sum_{n=i+1}^{N} (-1)^{n+1} n J_{2n}(D)` (the gradient sum
    /// `sum_n (-1)^{n+1} n J_{2n} geo_n = (1 + q) sum_i T_i q^{2i}`, collecting the
    /// powers `q^{2i}` and `q^{2i+1}` of `geo_n = sum_{j<2n} q^j`), and `e_*` the
    /// coefficient's error bound plus `gamma_4 (|lo| + 1.0001 u |hi|)` (the Horner step's share).
    coef: Vec<[f64; 6]>,
    /// `lambda_i <= ln(horner_tol / (suffix_{i+1} (1 + 2^-40)))`, `i = 0..N`, where
    /// `suffix_i` bounds (rounded up) `sum_{i' >= i} (|c_i'| + err_i')` over both
    /// sums (`+inf` for `i = N - 1`, where nothing is left): the Horner sums may stop
    /// after power `i` once `(i + 1) ln|X| <= lambda_i` ([`CertifiedBessel::horner_top`]).
    lambda: Vec<f64>,
    /// Tolerance of the Horner truncation, `2^-62 min(1, D)`.
    horner_tol: f64,
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
        // the factor 2k/D off the recurrence's dependency chain
        let c = inv.mul_f64_p::<P>((2 * k) as f64);
        y[k - 1] = y[k].mul_sub_p::<P>(c, y[k + 1]);
    }
    if nf > 0 {
        let (j0, j1) = bessel_j01::<P>(x)?;
        let mut fw = vec![BoundedDd::ZERO; nf + 1];
        forward_sequence::<P>(nf as u64, x, j0, j1, &mut fw)?;
        // D = x + delta + eps, delta = d.lo (an f64), |eps| <= e_D. The Taylor
        // term is tiny (|delta| <= ulp(x)/2), so it is formed in f64:
        // g = fl(fl(b.hi - c.hi) 0.5) with b = J_{k-1}(x) (J_{-1} = -J_1), c = J_{k+1}(x)
        // errs from J_k'(x) = (b - c)/2 by E_g = (e_b + e_c + |b.lo| + |c.lo| + u |b.hi - c.hi|)/2,
        // and corr = fl(delta g) from (delta + eps) J_k' by |delta| E_g + e_D + u |corr|
        // (|J_k'| <= 1); the remainder adds (|delta| + e_D)^2/2.
        let delta = d.v.lo;
        let delta_up = delta.abs() + d.e;
        let rem = 0.5 * delta_up * delta_up * (1.0 + 4.0 * U) + d.e;
        for k in 0..nf {
            let below = if k == 0 { fw[1].neg() } else { fw[k - 1] };
            let (b, c) = (below, fw[k + 1]);
            let diff = b.v.hi - c.v.hi;
            let g = diff * 0.5;
            let e_g = (b.e + c.e + b.v.lo.abs() + c.v.lo.abs() + U * diff.abs()) * 0.5;
            let corr = delta * g;
            let e_corr = (delta.abs() * e_g + U * corr.abs() + rem) * (1.0 + 4.0 * U);
            y[k] = fw[k].add(BoundedDd { v: Dd::from_f64(corr), e: e_corr });
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
        Some(Self::from_sequence::<P>(a, d, &j, n_terms, tail0, tail2))
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
        Ok(Self::from_sequence::<Dekker>(
            a,
            tr_from_ball(&d),
            &jt,
            n_terms as usize,
            tail0.to_f64_round(Round::Up),
            tail2.to_f64_round(Round::Up),
        ))
    }

    /// The Horner coefficients and their bounds from `J_0, ..., J_{2N+1}`, in
    /// one pass from the top: `u_{i+1} = (-1)^i J_{2i+2}` (a sign flip, exact),
    /// `T_i = T_{i+1} + (i + 1) u_{i+1}`, the suffix sums of `|c| + e` over both
    /// sums, and from them the truncation table `lambda`.
    #[inline(always)]
    fn from_sequence<P: ExactProduct>(
        a: f64,
        d: BoundedDd,
        jt: &[BoundedDd],
        n_terms: usize,
        tail0: f64,
        tail2: f64,
    ) -> CertifiedBessel {
        let err = |c: BoundedDd| (c.e + GAMMA4 * (c.v.lo.abs() + 1.0001 * U * c.v.hi.abs())) * (1.0 + 4.0 * U);
        let d_lo = d.v.hi.abs() - d.v.lo.abs() - d.e;
        let horner_tol = HORNER_TAIL_REL * d_lo.clamp(0.0, 1.0);
        let ln_tol = ln_lower(horner_tol);
        let mut coef = vec![[0.0f64; 6]; n_terms];
        let mut lambda = vec![f64::INFINITY; n_terms];
        let mut t_acc = BoundedDd::ZERO;
        // suffix_{i+1} = max over both sums of sum_{i' > i} (|c_i'| + e_i'), rounded up
        let (mut su, mut sd) = (0.0f64, 0.0f64);
        for i in (0..n_terms).rev() {
            let suffix = su.max(sd) * (1.0 + 1.0 / (1u64 << 40) as f64);
            if suffix > 0.0 {
                lambda[i] = ln_tol - ln_upper(suffix);
            }
            let c = if i % 2 == 0 { jt[2 * i + 2] } else { jt[2 * i + 2].neg() };
            t_acc = t_acc.add(c.mul_f64_p::<P>((i + 1) as f64));
            let (eu, et) = (err(c), err(t_acc));
            coef[i] = [c.v.hi, t_acc.v.hi, c.v.lo, t_acc.v.lo, eu, et];
            su = (su + c.mag() + eu) * (1.0 + 4.0 * U);
            sd = (sd + t_acc.mag() + et) * (1.0 + 4.0 * U);
        }
        CertifiedBessel {
            one_minus_j0: BoundedDd::ONE.sub(jt[0]),
            d_j1: d.mul_p::<P>(jt[1]),
            inv_a: BoundedDd::ONE.div_f64_p::<P>(a),
            coef,
            lambda,
            horner_tol,
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

    /// [`CertifiedBessel::eval_bounded`] at every `x` of `xs` (each `>= a`, finite:
    /// the caller's) into `out[i]`, in one loop compiled for the CPU's fused
    /// multiply-add (no per-point dispatch). The indices where the native path
    /// does not certify (`x/a > 25/7`) are pushed to `refused` (their `out`
    /// entries are left as they were). `out.len() == xs.len()`.
    pub(crate) fn eval_bounded_batch(&self, a: f64, amp: f64, xs: &[f64], out: &mut [(Bounded, Bounded)], refused: &mut Vec<usize>) {
        #[cfg(target_arch = "x86_64")]
        if has_fma() {
            // SAFETY: the CPU supports FMA (checked just above).
            return unsafe { eval_batch_fused(self, a, amp, xs, out, refused) };
        }
        self.eval_batch_with::<Dekker>(a, amp, xs, out, refused)
    }

    #[inline(always)]
    fn eval_batch_with<P: WaveKernel>(&self, a: f64, amp: f64, xs: &[f64], out: &mut [(Bounded, Bounded)], refused: &mut Vec<usize>) {
        for (i, (&x, o)) in xs.iter().zip(out.iter_mut()).enumerate() {
            match self.eval_with::<P>(a, amp, x) {
                Some(r) => *o = r,
                None => refused.push(i),
            }
        }
    }

    #[inline(always)]
    fn eval_with<P: WaveKernel>(&self, a: f64, amp: f64, x: f64) -> Option<(Bounded, Bounded)> {
        let rm1 = BoundedDd { v: Dd::diff(x, a), e: 0.0 }; // x - a, exact
        let rp1 = BoundedDd { v: Dd::diff(x, -a), e: 0.0 }; // x + a, exact
        // off the critical path: (x + a)/(2a) and the gradient's factor 8A/a
        let half_ratio = rp1.mul_p::<P>(self.inv_a).mul_f64_p::<P>(0.5);
        let du_scale = self.inv_a.mul_f64_p::<P>(8.0 * amp);
        let t = div_p::<P>(rm1, rp1)?.sqrt_p::<P>()?;
        if !(t.mag() + t.e <= T_MAX) {
            return None;
        }
        let one_minus_t = BoundedDd::ONE.sub(t);
        // q = (1 - t)/(1 + t) = (1 - t)^2/(1 - t^2) = (1 - t)^2 (x + a)/(2a)
        let q = one_minus_t.mul_p::<P>(one_minus_t).mul_p::<P>(half_ratio);
        let q2 = q.mul_p::<P>(q);
        let arg = CompArg::new(q2);
        let acosh_r = neg_ln::<P>(q)?; // acosh(x/a) = -ln q
        let (top, rem) = self.horner_top(arg.xa);
        let (mut su, mut sdu) = P::horner2(arg, &self.coef[..=top]);
        su.e += rem + self.tail0;
        sdu.e += rem + 2.0 * self.tail2;
        let inner = self.one_minus_j0.add(self.d_j1.mul_p::<P>(acosh_r)).add(su.mul_p::<P>(q2).mul_f64_p::<P>(2.0));
        let u = inner.mul_f64_p::<P>(amp);
        // (1 - t)(1 + q) = 2q: du/dx = (4A/a)(1 - t)(1 + q) S = (8A/a) q S
        let du = sdu.mul_p::<P>(q).mul_p::<P>(du_scale);
        Some((u.finish()?, du.finish()?))
    }

    /// Where the Horner sums in `X = q^2` stop for `|X| <= xa`: the first power `i`
    /// with `(i + 1) ln_upper(xa) <= lambda_i`, which implies
    /// `xa^{i+1} suffix_{i+1} <= horner_tol` (the remainder bound, returned with `i`;
    /// the product `(i + 1) L`, `L < 0`, is shrunk by `2^-50` against its rounding),
    /// else all `N` terms (remainder 0).
    #[inline(always)]
    fn horner_top(&self, xa: f64) -> (usize, f64) {
        let n = self.n_terms;
        if !(xa < 1.0 && xa > f64::MIN_POSITIVE) {
            return if xa == 0.0 { (0, 0.0) } else { (n - 1, 0.0) };
        }
        let l = ln_upper(xa) * (1.0 - 1.0 / (1u64 << 50) as f64);
        for (i, &lam) in self.lambda.iter().enumerate() {
            if (i + 1) as f64 * l <= lam {
                return (i, if i + 1 < n { self.horner_tol } else { 0.0 });
            }
        }
        (n - 1, 0.0)
    }
}

/// `x^n` by binary powering (`n <= 127`: at most 14 roundings).
#[inline(always)]
fn pow_int(x: f64, mut n: u32) -> f64 {
    let (mut acc, mut base) = (1.0f64, x);
    while n > 0 {
        if n & 1 == 1 {
            acc *= base;
        }
        n >>= 1;
        base *= base;
    }
    acc
}

/// [`CertifiedBessel::native`] compiled with the `fma` target feature.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "fma")]
unsafe fn native_fused(a: f64, zeta: f64) -> Option<CertifiedBessel> {
    CertifiedBessel::native::<crate::ball::Fused>(a, zeta)
}

/// [`CertifiedBessel::eval_bounded_batch`] compiled with the `fma` target feature.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "fma")]
unsafe fn eval_batch_fused(c: &CertifiedBessel, a: f64, amp: f64, xs: &[f64], out: &mut [(Bounded, Bounded)], refused: &mut Vec<usize>) {
    c.eval_batch_with::<crate::ball::Fused>(a, amp, xs, out, refused)
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
/// `cargo test --release --lib wave_bounded::profile -- --ignored` lists
/// their inclusive instruction counts (reported per call in the docs).
#[cfg(test)]
mod profile {
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
