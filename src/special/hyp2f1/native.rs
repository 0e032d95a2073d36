//! Native f64 `2F1` with a proven error bound (running error analysis).
//!
//! # Method
//!
//! * `-1/2 <= z <= 9/10`, or `a`/`b` a non-positive integer (any `z <= 1`): the
//!   direct series `sum_n t_n z^n` [DLMF 15.2.1] in f64.
//! * `z < -1/2`: Pfaff [DLMF 15.8.1], `(1-z)^{-a} 2F1(a, c-b; c; w)` or
//!   `(1-z)^{-b} 2F1(c-a, b; c; w)`, `w = z/(z-1) in (1/3, 1)`; the candidate
//!   with fewer negative numerators first, the other if the first cannot certify.
//!   `c - b` is a double word (exact); the prefactor is
//!   [`pow_from_ln`](super::power_f64) for the f64 sums (a bound of a few `u`) and
//!   [`pow_dw`](super::power::pow_dw) for the double-word sums.
//! * `z <= -4`: the connection formula in `x = 1/(1-z)` [DLMF 15.8.3], two f64
//!   series in `x <= 1/5` and seven reciprocal Gammas
//!   ([`rgamma_batch`](super::rgamma_f64)), first (Pfaff's `w >= 4/5` needs
//!   more than 150 terms); not where `a - b` is within `0.05` of an integer
//!   (its two terms blow up). Its bound is derived at
//!   [`connection_inv_one_minus_z`]. Between `-4` and `-1/2`, Pfaff goes first
//!   (measured crossover, `hyp2f1_regions`), and below `-4` too when `a, b > 0`
//!   (the connection formula's two terms cancel at a third of those points,
//!   Pfaff's f64 sum certifies 98.6%); the connection formula is its fallback there.
//!
//! * `9/10 < z < 1`: the connection formula in `x = 1 - z` [DLMF 15.8.4], two
//!   f64 series in `x < 1/10` and six reciprocal Gammas (the direct series
//!   does not converge usefully beyond `9/10`; below, it costs less); not
//!   where `c - a - b` is within `0.05` of an integer (the log case). Its
//!   bound is derived at [`connection_one_minus_z`].
//!
//! When no f64 sum certifies (cancellation), the same series are summed in
//! double words. Anything else (`z = 1`, `z` in `(9/10, 1)` where the
//! connection formula does not apply, more than
//! [`MAX_NATIVE_TERMS`] terms, a bound above the caller's tolerance, values
//! near the f64 range ends) returns `None`, and the callers fall back to the
//! certified MP path.
//!
//! # Error bound (proven)
//!
//! Let `u = 2^-53`. Parameters are `p = p_hi + p_lo` (`p_lo = 0` for f64 inputs;
//! for `c - b` the exact double word). Every step computes the term ratio
//! `r_n = fl(fl(N_n x) / D_n)`, `N_n = fl(fl(p1_hi+n) fl(p2_hi+n))`,
//! `D_n = fl(fl(q_hi+n)(n+1))`: 5 roundings on the numerator's side and 2 on
//! the denominator's, each a factor `(1 + d)^{+-1}`, `|d| <= u`. The terms
//! follow from the ratios with one or two more roundings a term (the method
//! of each loop, [`series`] and [`series_two`], counts them: 9 a term with the
//! pairing of [`series`], 8 in [`series_two`]). Dropping `p_lo` multiplies the
//! factor `p + n` by `1 + e`, `|e| <= |p_lo| / min_n |p + n|` (a lower bound of
//! the distance is computed once). The series argument `x~` is `x (1 + theta)`
//! (`theta = 0` for the direct series, `|theta| <= 2.01 u` for `w`), so
//! `t_n(x)` and `t_n(x~)` differ by the factor `(1 + theta)^n`. With
//! `E = k u + sum |p_lo| / dist + theta` per term (`k = 10` in [`series`],
//! `9` in [`series_two`], one unit above the count for the second-order
//! terms) and `N E <= 1/100`, `|t~_n - t_n| <= 1.01 n E |t~_n|`. Summation in
//! f64 adds at most `u |s~_k|` per addition [Higham, *Accuracy and
//! Stability*, 2nd ed., Sec. 4.2]. The tail after `N >= n_pos` terms (every
//! shifted parameter positive) is at most `|t_N| rho / (1 - rho)` with
//! `rho = |x| max(1, (p1+m)/(q+m)) max(1, (p2+m)/(1+m))` at `m = N` (each
//! factor non-increasing in `m`; the two pairings share one denominator,
//! [`ratio_bound`]; computed with an upward margin). So
//! `|S - s~| <= 1.01 (E sum n |t~_n| + u sum |s~_k|) + |t~_N| (1 + 1.01 N E) rho/(1 - rho)`,
//! and every sum of non-negative f64 terms here is inflated by `1.001`
//! (covers `gamma_N` for `N <= 10^6`). The prefactor has the relative bound of
//! `pow_f64` (or `pow_dw`); the product `P S` adds one rounding.
//!
//! # Speed
//!
//! The f64 loops run two lanes (`ball::F64x2`: SSE2, compiled for AVX where
//! the CPU has it, bit-identical): the two terms of a pair ([`series`]), or
//! the two series of a connection formula ([`series_two`]). The seven
//! reciprocal Gammas of a connection formula run as one batch with
//! interleaved Horner sums ([`rgamma_batch`]). Where the first terms of a sum
//! cancel, [`series_hybrid`] sums a double-word head and continues in f64,
//! instead of the double-word sum throughout.

use super::power::{pow_dw, round_small, U};
use super::power_f64::{floor_any, ln_f64, pow_dw_exponent, pow_from_ln};
use super::rgamma_f64::rgamma_batch;
use crate::ball::{cpu_dispatch, two_sum, Bounded, Dd, ExactProduct, F64x2};

/// Cap on the terms of a native series (beyond it, MP).
pub(super) const MAX_NATIVE_TERMS: u64 = 3000;

/// Largest `z` for the native direct series (beyond it the terms decay too slowly).
pub(super) const NATIVE_Z_MAX: f64 = 0.9;

/// Where the direct series hands over to Pfaff.
const PFAFF_BELOW: f64 = -0.5;

/// Below this `z` the connection formula in `1/(1-z)` goes first: its two
/// series (argument at most `1/(1-z)`) and seven reciprocal Gammas cost less
/// than Pfaff's one series at `w = z/(z-1) = 1 - 1/(1-z)` (measured over the
/// benchmark domain: `-4` beats `-3` and `-4.5`).
const CONNECTION_FIRST_BELOW: f64 = -4.0;

/// The connection formulas need `a - b` (or `c - a - b`) this far from an
/// integer (closer, their two terms blow up and cancel; Pfaff or the direct
/// series takes over).
const CONNECTION_MIN_FRAC: f64 = 0.05;

/// Above this `z` the connection formula in `1 - z` goes first: there it is
/// the only f64 path ([`NATIVE_Z_MAX`]). Below, the direct series costs less
/// (measured with the two-lane loops over the benchmark domain: at
/// `0.75 <= z < 0.9`, 0.22 us a value against 0.30 us with the connection
/// formula first from `z = 0.7`).
const CONNECTION_ONE_MINUS_Z_ABOVE: f64 = 0.9;

/// Above this `z` the connection formula in `1 - z` is the fallback when the
/// direct series cannot certify (before the double-word head): at
/// `hyp2f1_bounded`'s `1e-14` that happens often near `z = 0.9`.
const CONNECTION_ONE_MINUS_Z_FALLBACK_ABOVE: f64 = 0.7;

/// A series parameter `hi + lo` (`lo = 0` when it is an exact f64).
#[derive(Clone, Copy, Debug)]
struct Param {
    hi: f64,
    lo: f64,
}

impl Param {
    fn exact(x: f64) -> Param {
        Param { hi: x, lo: 0.0 }
    }

    fn from_dw(d: Dd) -> Param {
        Param { hi: d.hi, lo: d.lo }
    }

    /// `d` when the parameter is exactly `-d`, a non-positive integer.
    fn nonpos_degree(&self) -> Option<u64> {
        (self.lo == 0.0 && self.hi <= 0.0 && self.hi == floor_any(self.hi) && self.hi > -1e15).then(|| (-self.hi) as u64)
    }

    /// Upper bound of `|lo| / min_{n >= 0} |p + n|` (0 for exact parameters);
    /// `None` when the distance cannot be bounded away from zero.
    fn perturbation(&self) -> Option<f64> {
        if self.lo == 0.0 {
            return Some(0.0);
        }
        let p = self.hi;
        let dist = if p > 0.0 {
            p
        } else {
            let f = p - floor_any(p);
            f.min(1.0 - f)
        };
        let dist_lo = dist - 4.0 * U * (p.abs() + 1.0) - self.lo.abs();
        (dist_lo > 0.0).then(|| self.lo.abs() / dist_lo * 1.0001)
    }

    /// Upper bound of `p + n` (exact `p`), for the tail ratio.
    fn upper_plus(&self, n: f64) -> f64 {
        (self.hi + self.lo.abs() + n) * (1.0 + 2.0 * U) + f64::MIN_POSITIVE
    }

    /// Lower bound of `p + n`.
    fn lower_plus(&self, n: f64) -> f64 {
        let v = self.hi - self.lo.abs() + n;
        v - 2.0 * U * v.abs() - f64::MIN_POSITIVE
    }
}

/// First index with every shifted parameter positive (where the tail bound is
/// valid); `None` beyond [`MAX_NATIVE_TERMS`]. Parameters within `1e-9` of a
/// non-positive integer from above are pushed one step further (their
/// neglected low words cannot flip the sign after that).
fn first_positive_index(params: [f64; 3]) -> Option<f64> {
    let mut n_pos = 0.0f64;
    for p in params {
        if p <= 1e-9 {
            n_pos = n_pos.max(floor_any(-p) + 2.0);
        }
    }
    (n_pos <= MAX_NATIVE_TERMS as f64).then_some(n_pos)
}

/// Upper bound `rho` of every ratio `|t_{m+1}/t_m| = |x| |(p1+m)(p2+m)| /
/// ((q+m)(m+1))` for `m >= n` (every shifted parameter positive there), with
/// `x_abs` an upper bound of `|x|`; infinity where it cannot be bounded.
/// Each factor `max(1, (p+m)/(q+m))` is non-increasing in `m`, and pairing
/// `p1` or `p2` with `q` gives two bounds with one denominator:
/// `rho = x_abs min(max(q+n, p1+n) max(1+n, p2+n), max(q+n, p2+n) max(1+n, p1+n)) / ((q+n)(1+n))`,
/// numerators from upper bounds of the sums, the denominator from a lower
/// bound (one division).
fn ratio_bound(p1: &Param, p2: &Param, q: &Param, x_abs: f64, n: f64) -> f64 {
    let (xnum, den) = ratio_parts(p1, p2, q, x_abs, n);
    xnum / den * (1.0 + 2.0 * U)
}

/// [`ratio_bound`], tightened where a parameter is large (for the hybrid
/// sum's switch, tested once every 8 double-word terms): with
/// `A = p1 + p2 - q - 1` and `B = p1 p2 - q`, the factor of the ratio is
/// `r(m) = 1 + (A m + B) / ((m+q)(m+1))`, and for `m >= n >= 1`
/// `(m+q)(m+1) >= m (m+1) k`, `k = 1` for `q >= 0` and `k = (n+q)/n` otherwise
/// (`(m+q)/m` grows with `m`), so `r(m) <= 1 + (A+ + B+/n) / ((n+1) k)`
/// (`A+ = max(A, 0)`; the right side decreases in `m`). Every operation is
/// bounded upward (`up`, `dn`: one rounding's worth).
fn ratio_bound_tight(p1: &Param, p2: &Param, q: &Param, x_abs: f64, n: f64) -> f64 {
    let by_pairs = ratio_bound(p1, p2, q, x_abs, n);
    if !(n >= 1.0) {
        return by_pairs;
    }
    let up = |v: f64| v + (2.0 * U * v.abs() + f64::MIN_POSITIVE);
    let dn = |v: f64| v - (2.0 * U * v.abs() + f64::MIN_POSITIVE);
    let hi = |p: &Param| up(p.hi + p.lo.abs());
    let lo = |p: &Param| dn(p.hi - p.lo.abs());
    let q_dn = lo(q);
    let a_up = up(up(up(hi(p1) + hi(p2)) - q_dn) - 1.0).max(0.0);
    let corners = [lo(p1) * lo(p2), lo(p1) * hi(p2), hi(p1) * lo(p2), hi(p1) * hi(p2)];
    let b_up = up(up(corners.iter().fold(f64::NEG_INFINITY, |m, &c| m.max(c))) - q_dn).max(0.0);
    let k = if q_dn >= 0.0 { 1.0 } else { dn(dn(n + q_dn) / n) };
    if !(k > 0.0 && b_up.is_finite()) {
        return by_pairs;
    }
    let excess = up(up(up(a_up + up(b_up / n)) / (1.0 + n)) / k);
    by_pairs.min(up(x_abs * up(1.0 + excess)))
}

/// An upper bound of `x_abs num` and a lower bound of `den` (positive, or
/// `xnum` infinite), `rho = x_abs num / den` as in [`ratio_bound`].
#[inline(always)]
fn ratio_parts(p1: &Param, p2: &Param, q: &Param, x_abs: f64, n: f64) -> (f64, f64) {
    let (u1, u2, uq) = (p1.upper_plus(n), p2.upper_plus(n), q.upper_plus(n));
    let den = q.lower_plus(n) * (1.0 + n) * (1.0 - 2.0 * U);
    if !(den > 0.0) || !(u1 >= 0.0 && u2 >= 0.0) {
        return (f64::INFINITY, 1.0);
    }
    let one_n = 1.0 + n; // exact
    let num = (u1.max(uq) * u2.max(one_n)).min(u2.max(uq) * u1.max(one_n)) * (1.0 + 2.0 * U);
    (x_abs * num * (1.0 + 2.0 * U), den)
}

/// The series `2F1(p1, p2; q; x~)` with `x~ = x (1 + theta)`, `|theta| <= x_rel`,
/// summed in f64: `(value, err)` with `|2F1(p1, p2; q; x) - value| <= err`.
///
/// Two terms a step, in two lanes: with `N_n = fl(fl(p1+n) fl(p2+n))` and
/// `D_n = fl(fl(q+n) (n+1))`, the ratios `r_n = fl(fl(N_n x) / D_n)` and
/// `r_{n+1}` (one lane-wise division) carry 5 roundings on the numerator's
/// side and 2 on the denominator's: 7 each; `t_{n+1} = fl(t_n r_n)` and
/// `t_{n+2} = fl(t_n fl(r_n r_{n+1}))` add one and two: 8 a term. The pair is
/// added as `s += fl(t_{n+1} + t_{n+2})`, whose inner rounding
/// (`<= u (|t_{n+1}| + |t_{n+2}|)`) is charged to the terms: `E = 10 u` a term
/// covers all of it with the second-order terms (module docs). The tail after
/// the pair ending at `N >= n_pos` is `sum_{n>N} |t_n| <= |t_N| rho / (1 - rho)`.
fn series(p1: Param, p2: Param, q: Param, x: f64, x_rel: f64, stop: f64) -> Option<(f64, f64)> {
    series_from(p1, p2, q, x, x_rel, stop, Start { n: 0, t: 1.0, s: 1.0 })
}

/// Where [`series_from`] starts: the term `t` of index `n` (already summed)
/// and the partial sum `s` up to it.
#[derive(Clone, Copy, Debug)]
struct Start {
    n: u64,
    t: f64,
    s: f64,
}

/// [`series`] from the term of index `start.n` on: the terms `t_{n+1}, ...`
/// from `start.t`, added to `start.s`. The bound covers the terms' errors
/// relative to an exact `start.t` (weights `n E` with the absolute index, so a
/// relative error up to `n E` of `start.t` is covered too) and the additions;
/// the error of `start.s` is the caller's.
fn series_from(p1: Param, p2: Param, q: Param, x: f64, x_rel: f64, stop: f64, start: Start) -> Option<(f64, f64)> {
    let deg = match (p1.nonpos_degree(), p2.nonpos_degree()) {
        (Some(d1), Some(d2)) => Some(d1.min(d2)),
        (d1, d2) => d1.or(d2),
    };
    if let Some(m) = q.nonpos_degree() {
        if deg.map_or(true, |d| d > m) {
            return None;
        }
    }
    if deg.is_none() && !(x.abs() < 1.0) {
        return None;
    }
    if deg.is_some_and(|d| d > MAX_NATIVE_TERMS) {
        return None;
    }
    let e_step = 10.0 * U + p1.perturbation()? + p2.perturbation()? + q.perturbation()? + x_rel;
    let n_pos = first_positive_index([p1.hi, p2.hi, q.hi])?;
    // Every denominator (q+n)(n+1) and product of two stays far inside the
    // normal range: |q + n| >= dist(q, {0, -1, -2, ...}) > 1e-60 (no rounding
    // takes a nonzero sum to zero), |q| < 1e30, n <= MAX_NATIVE_TERMS + 2.
    if !denominators_safe(&q) {
        return None;
    }
    // Pairs while n + 2 <= limit; a polynomial's odd last term after the loop.
    let limit = deg.unwrap_or(MAX_NATIVE_TERMS + 2);
    // The tail test runs when |t~| tail_mult <= |s~|: first from first_trigger
    // (never for a polynomial); once rho < 1 is known, tail_mult bounds the tail
    // factor over every later index, and the test succeeds at its first call.
    let quarter_over_stop = quarter_over(stop);
    let mut tail_mult = if deg.is_some() { f64::INFINITY } else { first_trigger(x, quarter_over_stop) };
    let mut tail_factor = f64::INFINITY; // rho/(1 - rho) with margins, once known
    let mut tail = None;
    if start.n > limit {
        return None;
    }
    let mut st = PairState {
        t: start.t,
        s: start.s,
        sum_nt2: F64x2::splat(0.0),
        idx: F64x2::new(start.n as f64, start.n as f64 + 1.0),
        n: start.n,
    };
    let params = [F64x2::splat(p1.hi), F64x2::splat(p2.hi), F64x2::splat(q.hi)];
    while sum_pairs(&mut st, params, x, limit, tail_mult) {
        match series_tail(&p1, &p2, &q, x, x_rel, e_step, n_pos, st.idx.lo(), st.t, st.s, stop, quarter_over_stop, &mut tail_factor) {
            TailTest::Done(b) => {
                tail = Some(b);
                break;
            }
            TailTest::Later(mult) => tail_mult = mult,
        }
    }
    let PairState { mut t, mut s, sum_nt2, idx, mut n } = st;
    let nf = idx.lo();
    let mut sum_nt = sum_nt2.lo() + sum_nt2.hi();
    let mut additions = (n - start.n) / 2;
    if deg.is_some() {
        if n + 1 == limit {
            // the last term of a polynomial, alone (8 roundings; with the
            // addition, 9, within e_step)
            let n1 = nf + 1.0;
            t *= (p1.hi + nf) * (p2.hi + nf) * x / ((q.hi + nf) * n1);
            s += t;
            sum_nt += n1 * t.abs();
            n += 1;
            additions += 1;
        }
        tail = Some(0.0);
    }
    let tail = tail?;
    if !(s.is_finite() && sum_nt.is_finite()) || (n as f64) * e_step > 0.01 {
        return None;
    }
    // The additions' rounding, u sum_k |s~_k| over the K additions, without
    // summing |s~_k| in the loop: s~_k = s~_K - (the later pairs) - (their
    // roundings), a pair term of index n is in at most n/2 of them, so
    // (1 - u K) sum_k |s~_k| <= K |s~_K| + (1 + u)/2 sum_n n |t~_n|, and u K <= 1/2000
    // (n E <= 1/100, E >= 10 u): sum_k |s~_k| <= 1.001 (K |s~_K| + 0.5001 sum_n n |t~_n|).
    let sum_abs_s = 1.001 * (additions as f64 * s.abs() + 0.5001 * sum_nt);
    Some((s, f64_sum_error(e_step, sum_nt, sum_abs_s, tail)))
}

/// The largest power of two at most `x` (a positive normal `x`).
fn pow2_floor(x: f64) -> f64 {
    f64::from_bits(x.to_bits() & 0x7ff0_0000_0000_0000)
}

/// Where the f64 series of [`hyp2f1_native`] stop: once their tail bound is
/// below `rel_tol/256` of the sum (it is part of the returned bound), rounded
/// down to a power of two (so the sums form `1/stop` exactly, without a
/// division): `2^-53` for `hyp2f1`, `2^-55` for `hyp2f1_bounded`, never above
/// `2^-46` or below `2^-56`.
fn stop_for(rel_tol: f64) -> f64 {
    pow2_floor((rel_tol / 256.0).clamp(1.3877787807814457e-17, 1.4210854715202004e-14))
}

/// `1/(4 stop)`: exact, without a division, for `stop` a power of two in the
/// normal range (as [`hyp2f1_native`] makes it); a division otherwise.
#[inline]
fn quarter_over(stop: f64) -> f64 {
    let bits = stop.to_bits();
    if bits & 0x000f_ffff_ffff_ffff == 0 && stop > 1e-300 && stop < 1.0 {
        // 2^e -> 2^(-e-2): exponent field 1023 + e -> 1023 - e - 2
        f64::from_bits((2044 - (bits >> 52)) << 52)
    } else {
        0.25 / stop
    }
}

/// The first value of the loops' trigger `|t~| mult <= |s~|` for the tail
/// test: `rho >= |x|`, so the test cannot succeed before `|t~| |x| / (1 - |x|)
/// <= stop |s~|`; the first call waits for that, at least for `|t~| <= 4 stop
/// |s~|`. A trigger only (any positive value is sound); `4|x|/(1 - |x|) <=
/// 4|x|(1 + 2|x|)` for `|x| <= 1/2`, without a division.
fn first_trigger(x: f64, quarter_over_stop: f64) -> f64 {
    let ax = x.abs();
    let asymptotic = if ax <= 0.5 { 4.0 * ax * (1.0 + 2.0 * ax) } else { 4.0 * ax / (1.0 - ax) };
    quarter_over_stop * asymptotic.max(1.0)
}

/// The bound of an f64 sum (module docs): `1.01 (E sum n |t~_n| + u sum |s~_k|)`
/// inflated by `1.001` for the rounding of those sums, plus the tail, plus
/// `8u` for the rounding of this expression.
fn f64_sum_error(e_step: f64, sum_nt: f64, sum_abs_s: f64, tail: f64) -> f64 {
    ((1.01 * (e_step * sum_nt + U * sum_abs_s)) * 1.001 + tail) * (1.0 + 8.0 * U)
}

/// Whether every denominator `(q+n)(n+1)` of a series, and a product of two,
/// stays far inside the normal range: `|q + n| >= dist(q, {0, -1, -2, ...})
/// > 1e-60` (no rounding takes a nonzero sum to zero), `|q| < 1e30`,
/// `n <= MAX_NATIVE_TERMS + 2`.
fn denominators_safe(q: &Param) -> bool {
    let q_dist = if q.hi > 0.0 { q.hi } else { (q.hi - floor_any(q.hi)).min(floor_any(q.hi) + 1.0 - q.hi) };
    q_dist > 1e-60 && q.hi.abs() < 1e30
}

/// Two series `2F1(p1, p2; q; x~)` with one argument (those of a connection
/// formula), one in each lane: `[(value, err); 2]` with the bound of
/// [`series`] each, or `None` where either is a polynomial, has a pole, or does
/// not converge here (the caller then sums them one by one).
///
/// One term a step in each lane: `r_n = fl(fl(N_n x) / D_n)` with
/// `N_n = fl(fl(p1+n) fl(p2+n))`, `D_n = fl(fl(q+n) (n+1))`, and
/// `t_{n+1} = fl(t_n r_n)`: six roundings on the numerator's side, two on the
/// denominator's, so `E = 9 u` a term (for the `10 u` of [`series`]), and the
/// sum `s += t` adds `u |s~_k|` a term (bounded at the end, as in [`series_from`]). Each lane stops at its own tail test
/// ([`series_tail`]); the other runs on.
fn series_two(lanes: [[Param; 3]; 2], x: f64, x_rel: f64, stop: f64) -> Option<[(f64, f64); 2]> {
    if !(x.abs() < 1.0) {
        return None;
    }
    let mut e_step = [0.0; 2];
    let mut n_pos = [0.0; 2];
    for (l, [p1, p2, q]) in lanes.iter().enumerate() {
        if p1.nonpos_degree().is_some() || p2.nonpos_degree().is_some() || q.nonpos_degree().is_some() || !denominators_safe(q) {
            return None;
        }
        e_step[l] = 9.0 * U + p1.perturbation()? + p2.perturbation()? + q.perturbation()? + x_rel;
        n_pos[l] = first_positive_index([p1.hi, p2.hi, q.hi])?;
    }
    let quarter_over_stop = quarter_over(stop);
    let mut mult = [first_trigger(x, quarter_over_stop); 2];
    let mut factor = [f64::INFINITY; 2];
    // per lane when done: (sum, sum n |t~_n|, last index, tail)
    let mut done: [Option<(f64, f64, f64, f64)>; 2] = [None; 2];
    let mut st = TwoState { t: F64x2::splat(1.0), s: F64x2::splat(1.0), sum_nt: F64x2::splat(0.0), idx: F64x2::splat(0.0) };
    let params = [0, 1, 2].map(|k| F64x2::new(lanes[0][k].hi, lanes[1][k].hi));
    let n_max = MAX_NATIVE_TERMS as f64;
    while done.iter().any(Option::is_none) {
        let lanes_hit = sum_two(&mut st, params, x, n_max, F64x2::new(mult[0], mult[1]));
        if lanes_hit == 0 {
            return None; // n_max reached
        }
        let nf = st.idx.lo();
        for l in 0..2 {
            if lanes_hit & (1 << l) == 0 || done[l].is_some() {
                continue;
            }
            let pick = |v: F64x2| if l == 0 { v.lo() } else { v.hi() };
            let [p1, p2, q] = &lanes[l];
            let (t, s) = (pick(st.t), pick(st.s));
            match series_tail(p1, p2, q, x, x_rel, e_step[l], n_pos[l], nf, t, s, stop, quarter_over_stop, &mut factor[l]) {
                TailTest::Done(b) => {
                    done[l] = Some((s, pick(st.sum_nt), nf, b));
                    mult[l] = f64::INFINITY;
                }
                TailTest::Later(m) => mult[l] = m,
            }
        }
    }
    let mut out = [(0.0, 0.0); 2];
    for l in 0..2 {
        let (s, sum_nt, nf, tail) = done[l]?;
        if !(s.is_finite() && sum_nt.is_finite()) || nf * e_step[l] > 0.01 {
            return None;
        }
        // the additions' rounding as in series_from, with one addition a term
        // (a term of index n is in at most n - 1 later partial sums):
        // sum_k |s~_k| <= 1.001 (N |s~_N| + 1.0001 sum_n n |t~_n|)
        let sum_abs_s = 1.001 * (nf * s.abs() + 1.0001 * sum_nt);
        out[l] = (s, f64_sum_error(e_step[l], sum_nt, sum_abs_s, tail));
    }
    Some(out)
}

/// The running state of [`series_two`]'s loop (lane `l` is series `l`).
#[derive(Clone, Copy, Debug)]
struct TwoState {
    t: F64x2,
    s: F64x2,
    sum_nt: F64x2,    // sum_n n |t~_n|
    idx: F64x2,       // (n, n): the index of the last term added
}

cpu_dispatch! {
    /// [`series_two`]'s loop: one term a lane a step until a lane's term passes
    /// its trigger (`|t~| mult <= |s~|`: the mask of those lanes) or the index
    /// reaches `n_max` (0). On its own, as [`sum_pairs`].
    #[inline(never)]
    fn sum_two(st: &mut TwoState, params: [F64x2; 3], x: f64, n_max: f64, mult: F64x2) -> u32 => avx sum_two_with
}

#[inline(always)]
fn sum_two_with(st: &mut TwoState, [v1, v2, vq]: [F64x2; 3], x: f64, n_max: f64, mult: F64x2) -> u32 {
    let TwoState { mut t, mut s, mut sum_nt, mut idx } = *st;
    let (one, vx) = (F64x2::splat(1.0), F64x2::splat(x));
    let mut hit = 0;
    while idx.lo() < n_max {
        let idx1 = idx.add(one);
        let num = v1.add(idx).mul(v2.add(idx));
        let den = vq.add(idx).mul(idx1);
        t = t.mul(num.mul(vx).div(den));
        s = s.add(t);
        sum_nt = sum_nt.add(idx1.mul(t.abs()));
        idx = idx1;
        hit = t.abs().mul(mult).le_mask(s.abs());
        if hit != 0 {
            break;
        }
    }
    *st = TwoState { t, s, sum_nt, idx };
    hit
}

/// The running state of [`series_from`]'s two-lane loop.
#[derive(Clone, Copy, Debug)]
struct PairState {
    t: f64,
    s: f64,
    sum_nt2: F64x2,       // sum_n n |t~_n|, odd and even n in two lanes
    idx: F64x2,           // (n, n + 1)
    n: u64,
}

cpu_dispatch! {
    /// [`series_from`]'s loop: pairs of terms while `n + 2 <= limit`, each lane
    /// rounding as the scalar formula of [`series`]; `true` when it stopped for
    /// the tail test (`|t~| tail_mult <= |s~|`). On its own (no call inside, and
    /// few live values), so that the state stays in registers.
    #[inline(never)]
    fn sum_pairs(st: &mut PairState, params: [F64x2; 3], x: f64, limit: u64, tail_mult: f64) -> bool => avx sum_pairs_with
}

#[inline(always)]
fn sum_pairs_with(st: &mut PairState, [v1, v2, vq]: [F64x2; 3], x: f64, limit: u64, tail_mult: f64) -> bool {
    let PairState { mut t, mut s, mut sum_nt2, mut idx, mut n } = *st;
    let (one, two, vx) = (F64x2::splat(1.0), F64x2::splat(2.0), F64x2::splat(x));
    // one pair: the terms n + 1 and n + 2
    let pair = |t: &mut f64, s: &mut f64, sum_nt2: &mut F64x2, idx: &mut F64x2| {
        let idx1 = idx.add(one); // (n + 1, n + 2)
        let num = v1.add(*idx).mul(v2.add(*idx)); // (N_n, N_{n+1})
        let den = vq.add(*idx).mul(idx1); // (D_n, D_{n+1})
        let r = num.mul(vx).div(den); // (r_n, r_{n+1})
        let (r0, r1) = (r.lo(), r.hi());
        let t1 = *t * r0;
        *t *= r0 * r1;
        *s += t1 + *t;
        *sum_nt2 = sum_nt2.add(idx1.mul(F64x2::new(t1, *t).abs()));
        *idx = idx.add(two);
    };
    let mut test = false;
    // two pairs a step, the trigger tested once
    while n + 4 <= limit {
        pair(&mut t, &mut s, &mut sum_nt2, &mut idx);
        pair(&mut t, &mut s, &mut sum_nt2, &mut idx);
        n += 4;
        if t.abs() * tail_mult <= s.abs() {
            test = true;
            break;
        }
    }
    if !test && n + 2 <= limit {
        pair(&mut t, &mut s, &mut sum_nt2, &mut idx);
        n += 2;
        test = t.abs() * tail_mult <= s.abs();
    }
    *st = PairState { t, s, sum_nt2, idx, n };
    test
}

/// What [`series_tail`] found.
enum TailTest {
    /// The tail bound, at most `stop |s~|`: the sum ends here.
    Done(f64),
    /// Not yet: test again when `|t~| mult <= |s~|` (`Done` for sure then,
    /// once `rho < 1` is known; before, `mult` grows 16-fold a call).
    Later(f64),
}

/// The tail test of [`series`] after the term `t~_N` (`N = nf >= n_pos`): the
/// tail is at most `|t~_N| (1 + 1.01 N E) rho / (1 - rho)`, with
/// `rho` bounding every ratio `|t_{n+1}/t_n|` from `N` on (so it stays valid at
/// every later index, where `1 + 1.01 N E <= 1.0101`: the sum is refused
/// when `N E > 1/100`). The factor `rho / (1 - rho)` (with margins) is kept
/// in `factor` (infinite until known) for the later calls.
#[inline]
#[allow(clippy::too_many_arguments)]
fn series_tail(
    p1: &Param, p2: &Param, q: &Param, x: f64, x_rel: f64, e_step: f64, n_pos: f64, nf: f64, t: f64, s: f64, stop: f64,
    quarter_over_stop: f64, factor: &mut f64,
) -> TailTest {
    // 1/stop = 4 fl(1/(4 stop)) within u: covered by the 6u margin of the multiplier
    let inv_stop = 4.0 * quarter_over_stop;
    if !(*factor < f64::INFINITY) {
        // not yet valid (a shifted parameter still negative) or rho >= 1:
        // test again once the term is 16 times smaller next to the sum
        let retry = || TailTest::Later(16.0 * (s.abs() / t.abs()).min(1e300));
        if nf < n_pos {
            return retry();
        }
        let (xnum, den) = ratio_parts(p1, p2, q, x.abs() * (1.0 + x_rel) * (1.0 + 2.0 * U), nf);
        let gap = (den - xnum) * (1.0 - 2.0 * U); // lower bound of den - x num
        if !(gap > 0.0) {
            return retry();
        }
        // The common case without a division: the tail |t_N| (1 + 1.01 N E)
        // x num / (den - x num) is at most stop |s~| when the products (upward
        // and downward margins) say so; the tail is then bounded by stop |s~|.
        let lhs = t.abs() * (1.0 + 1.01 * nf * e_step) * xnum * (1.0 + 16.0 * U);
        let rhs = stop * s.abs() * gap * (1.0 - 4.0 * U);
        if lhs <= rhs {
            return TailTest::Done(stop * s.abs() * (1.0 + 2.0 * U));
        }
        *factor = xnum / gap * (1.0 + 2.0 * U) * (1.0 + 4.0 * U);
    }
    let tail_factor = *factor;
    let bound = t.abs() * (1.0 + 1.01 * nf * e_step) * tail_factor;
    if bound <= stop * s.abs() {
        return TailTest::Done(bound);
    }
    TailTest::Later(tail_factor * 1.0102 * inv_stop * (1.0 + 6.0 * U))
}

/// `t_{n+1} = t_n x (p1+n)(p2+n) / ((q+n)(n+1))` in double words (the step
/// of [`series_dw`], `49 u^2` relative, charged `128 u^2`); `None` at a zero
/// denominator.
#[inline(always)]
fn dw_next_term<P: ExactProduct>(p1: Dd, p2: Dd, q: Dd, x: Dd, t: Dd, n: u64) -> Option<Dd> {
    let nf = n as f64;
    let num = p1.add_accurate(Dd::from_f64(nf)).mul_accurate_p::<P>(p2.add_accurate(Dd::from_f64(nf)));
    let den = q.add_accurate(Dd::from_f64(nf)).mul_accurate_p::<P>(Dd::from_f64(nf + 1.0));
    if den.hi == 0.0 {
        return None;
    }
    Some(t.mul_accurate_p::<P>(num.mul_accurate_p::<P>(x).div_accurate_p::<P>(den)))
}

cpu_dispatch! {
    /// The series `2F1(p1, p2; q; x)` summed in double-word arithmetic, for the
    /// cases where the f64 sum cannot certify (cancellation, many terms). Same
    /// argument as [`series`] with the per-step relative error
    /// `E = 128 u^2 + theta` (three DW additions `3u^2`, two DW products `7u^2`, the
    /// product by `x` `7u^2`, one DW division `15u^2 + 56u^3`, the update `7u^2`:
    /// `49 u^2`, charged `128 u^2`) and `3u^2 |s~_k|` per addition; parameters are
    /// exact double words (`theta` bounds the relative error of `x`).
    fn series_dw(p1: Dd, p2: Dd, q: Dd, x: Dd, x_rel: f64) -> Option<(Dd, f64)> => series_dw_with
}

/// [`series_dw`] with the exact product `P` (the result is bit-identical for
/// every `P`: both products are exact).
#[inline(always)]
fn series_dw_with<P: ExactProduct>(p1: Dd, p2: Dd, q: Dd, x: Dd, x_rel: f64) -> Option<(Dd, f64)> {
    let pa = Param::from_dw(p1);
    let pb = Param::from_dw(p2);
    let pq = Param::from_dw(q);
    let exact_int = |p: &Dd| p.lo == 0.0 && p.hi <= 0.0 && p.hi == floor_any(p.hi);
    let deg = [p1, p2].iter().filter(|p| exact_int(p)).map(|p| (-p.hi) as u64).min();
    if exact_int(&q) && deg.map_or(true, |d| d > (-q.hi) as u64) {
        return None;
    }
    if deg.is_none() && !(x.hi.abs() < 1.0) || deg.is_some_and(|d| d > MAX_NATIVE_TERMS) {
        return None;
    }
    let e_step = 128.0 * U * U + x_rel;
    let n_pos = first_positive_index([p1.hi, p2.hi, q.hi])?;
    // The tail only needs to be far below the rounding bound (u |s|): 2^-60.
    const STOP: f64 = 8.673617379884035e-19; // 2^-60
    let mut t = Dd::from_f64(1.0);
    let mut s = Dd::from_f64(1.0);
    let (mut sum_abs_s, mut sum_nt, mut tail) = (0.0f64, 0.0f64, 0.0f64);
    let mut n = 0u64;
    loop {
        if deg == Some(n) {
            break;
        }
        t = dw_next_term::<P>(p1, p2, q, x, t, n)?;
        n += 1;
        let nf = n as f64;
        if deg.is_none() && nf >= n_pos && t.hi.abs() <= STOP * s.hi.abs() {
            let rho = ratio_bound(&pa, &pb, &pq, x.hi.abs() * (1.0 + 2.0 * U) * (1.0 + x_rel) * (1.0 + 2.0 * U), nf);
            if rho < 1.0 {
                let bound = t.hi.abs() * (1.0 + 2.0 * U) * (1.0 + 1.01 * nf * e_step) / ((1.0 - rho) * (1.0 - 2.0 * U))
                    * (1.0 + 4.0 * U);
                if bound <= STOP * s.hi.abs() {
                    tail = bound;
                    break;
                }
            }
        }
        s = s.add_accurate(t);
        sum_abs_s += s.hi.abs();
        sum_nt += nf * t.hi.abs();
        if n > MAX_NATIVE_TERMS || !s.hi.is_finite() || !t.hi.is_finite() {
            return None;
        }
    }
    if (n as f64) * e_step > 0.01 {
        return None;
    }
    // |t~| <= |t~.hi| (1 + 2u): folded into the 1.01 and 1.001 margins below.
    let err = (1.01 * (e_step * sum_nt * (1.0 + 2.0 * U) + 3.1 * U * U * sum_abs_s * (1.0 + 2.0 * U))) * 1.001 + tail;
    Some((s, err * (1.0 + 8.0 * U)))
}

cpu_dispatch! {
    /// The series `2F1(p1, p2; q; x)` with its head in double words and the rest
    /// in f64, for a sum whose first terms cancel (where the f64 sum cannot
    /// certify) but whose later terms are small: [`series_dw`]'s loop until the
    /// term `t_K` (`K >= n_pos`) is small enough that the f64 rest's rounding
    /// bound, about `E |t_K| (K + 1) / (1 - rho)^2` (`E` = 10 u and the
    /// parameters' perturbations), is below an eighth of the target
    /// `rel_tol |s| >= 256 stop |s|` (or `K = 96`), then
    /// [`series_from`] with `t~_K = fl(t_K.hi + t_K.lo)` and the partial sum's
    /// high word, and the low word added at the end.
    ///
    /// Error: the head as in [`series_dw`] (per step `E_dw = 128 u^2 + x_rel`,
    /// `3.1 u^2 |s_k|` per addition); `t~_K` errs by at most `1.01 K E_dw + 1.01 u`
    /// relative, below the `K E` that [`series_from`]'s absolute-index weights
    /// already charge (`E >= 10 u`, `K >= 1`); the f64 argument `x.hi` errs by
    /// `theta = 1.01 (|x.lo| + x_rel |x|) / |x.hi|` relative, passed as its
    /// `x_rel`; the final `fl(s_f + s_K.lo)` adds `u |v|`.
    fn series_hybrid(p1: Dd, p2: Dd, q: Dd, x: Dd, x_rel: f64, stop: f64) -> Option<(f64, f64)> => series_hybrid_with
}

#[inline(always)]
fn series_hybrid_with<P: ExactProduct>(p1: Dd, p2: Dd, q: Dd, x: Dd, x_rel: f64, stop: f64) -> Option<(f64, f64)> {
    const MAX_HEAD: u64 = 96;
    let exact_int = |p: &Dd| p.lo == 0.0 && p.hi <= 0.0 && p.hi == floor_any(p.hi);
    if [p1, p2, q].iter().any(exact_int) || !(x.hi.abs() < 1.0) {
        return None; // polynomials and poles: the other paths
    }
    let e_dw = 128.0 * U * U + x_rel;
    let n_pos = first_positive_index([p1.hi, p2.hi, q.hi])?;
    let (pa, pb, pq) = (Param::from_dw(p1), Param::from_dw(p2), Param::from_dw(q));
    // The switch (a cost decision only; the bound is the final one): once
    // every later ratio is below rho < 1, the f64 rest charges about
    // E sum_{n>K} n |t_n| <= E |t_K| (K + 1) / (1 - rho)^2, E ~ 10 u to 16 u;
    // the head ends when that is below 1/8 of the target 256 stop |s|
    // (|t_K| (K + 1) w <= |s| with w = 16 u / (32 stop (1 - rho)^2)).
    let mut w_switch = f64::INFINITY;
    let mut rho_tried_at = -1.0f64;
    let mut t = Dd::from_f64(1.0);
    let mut s = Dd::from_f64(1.0);
    let (mut sum_abs_s, mut sum_nt) = (0.0f64, 0.0f64);
    let mut n = 0u64;
    loop {
        t = dw_next_term::<P>(p1, p2, q, x, t, n)?;
        n += 1;
        let nf = n as f64;
        s = s.add_accurate(t);
        sum_abs_s += s.hi.abs();
        sum_nt += nf * t.hi.abs();
        if !s.hi.is_finite() || !t.hi.is_finite() {
            return None;
        }
        if n >= MAX_HEAD {
            break;
        }
        let weighted = t.hi.abs() * (nf + 1.0);
        if nf >= n_pos && weighted <= s.hi.abs() {
            if w_switch == f64::INFINITY && nf >= rho_tried_at + 8.0 {
                // rho once (it bounds every later ratio); again 8 terms on if >= 1
                rho_tried_at = nf;
                let rho = ratio_bound_tight(&pa, &pb, &pq, x.hi.abs() * (1.0 + 2.0 * U) * (1.0 + x_rel) * (1.0 + 2.0 * U), nf);
                if rho < 1.0 {
                    w_switch = 16.0 * U / (32.0 * stop * (1.0 - rho) * (1.0 - rho));
                }
            }
            if weighted * w_switch <= s.hi.abs() {
                break;
            }
        }
    }
    let head_err = (1.01 * (e_dw * sum_nt * (1.0 + 2.0 * U) + 3.1 * U * U * sum_abs_s * (1.0 + 2.0 * U))) * 1.001;
    let theta = 1.01 * (x.lo.abs() + x_rel * x.hi.abs() * (1.0 + 2.0 * U)) / x.hi.abs();
    let start = Start { n, t: t.hi + t.lo, s: s.hi };
    let (sf, err_f) = series_from(Param::from_dw(p1), Param::from_dw(p2), Param::from_dw(q), x.hi, theta, stop, start)?;
    let v = sf + s.lo;
    Some((v, (head_err + err_f + U * v.abs()) * (1.0 + 4.0 * U)))
}

/// `p + 1` for a double word `p`, as a series parameter. The low word is
/// rounded once (`<= u |lo|`); [`series`] uses it only through `|lo|` (the
/// perturbation bound), so it is stored enlarged by `4u` to cover that.
fn plus_one(p: Dd) -> Param {
    let (hi, e) = two_sum(p.hi, 1.0);
    let lo = e + p.lo;
    Param { hi, lo: lo * (1.0 + 4.0 * U) }
}

/// A reciprocal Gamma (as [`rgamma_batch`] returns it) with its relative
/// bound: `Some(None)` for an exact zero.
fn rgamma_rel(r: Option<(f64, f64)>) -> Option<Option<(f64, f64)>> {
    let (v, e) = r?;
    if v == 0.0 {
        return (e == 0.0).then_some(None);
    }
    Some(Some((v, e / v.abs())))
}

/// `(1/G(n1)) (1/G(n2)) / ((1/G(d1)) (1/G(d2)))`, a connection coefficient, with
/// its relative bound, from the four reciprocal Gammas; `Some(None)` when a
/// numerator vanishes exactly (the term is zero). Three roundings: with `r_*`
/// the relative bounds of the four reciprocal Gammas, `|C~ - C| <= rho |C~|`,
/// `rho = s (1 + s)`, `s = r_n1 + r_n2 + 1.01 (r_d1 + r_d2) + 3.01 u`
/// (`e^s - 1 <= s (1 + s)`, `1/(1 - r) <= 1 + 1.01 r` for `r <= 1/100`).
fn gamma_coefficient(num: [Option<(f64, f64)>; 2], den: [Option<(f64, f64)>; 2]) -> Option<Option<(f64, f64)>> {
    let Some((n1, r1)) = rgamma_rel(num[0])? else { return Some(None) };
    let Some((n2, r2)) = rgamma_rel(num[1])? else { return Some(None) };
    let (d1, q1) = rgamma_rel(den[0])??;
    let (d2, q2) = rgamma_rel(den[1])??;
    let s = r1 + r2 + 1.01 * (q1 + q2) + 3.01 * U;
    if !(s <= 0.01 && q1 <= 0.01 && q2 <= 0.01) {
        return None;
    }
    Some(Some((n1 * n2 / (d1 * d2), s * (1.0 + s) * 1.0001)))
}

/// Adds the term `coef pw sum` of a connection formula to `(value, err)`:
/// relative bounds `coef_rel`, `pw_rel`, the series' absolute `err_s`, two
/// roundings for the products and one for the sum.
fn add_connection_term(acc: (f64, f64), (coef, coef_rel): (f64, f64), (pw, pw_rel): (f64, f64), (sum, err_s): (f64, f64)) -> (f64, f64) {
    let (value, err) = acc;
    let pre = coef * pw;
    // |pre~ - pre| <= pr |pre~|: the two relative bounds and one rounding
    let pr = (coef_rel + pw_rel + coef_rel * pw_rel + U) * 1.0001;
    let t = pre * sum;
    let total = value + t;
    let err = err + (pre.abs() * err_s * (1.0 + 2.0 * pr) + (1.01 * pr + U) * t.abs()) * (1.0 + 4.0 * U) + U * total.abs();
    (total, err)
}

/// `2F1(a, b; c; z)` for `z <= -1` by the connection formula in `x = 1/(1-z)`
/// [DLMF 15.8.3], for `a - b` at least [`CONNECTION_MIN_FRAC`] from an integer:
///
/// ```text
/// 2F1(a, b; c; z) = sum over (p, q) in {(a, b), (b, a)} of
///     Gamma(c) Gamma(q-p) / (Gamma(q) Gamma(c-p)) (1-z)^{-p} 2F1(p, c-q; p-q+1; x)
/// ```
///
/// `(value, err)` with a proven bound, or `None`. The coefficients from
/// [`gamma_coefficient`], both powers from one [`ln_f64`] of the exact double
/// word `1 - z`; `x = fl(1/(1-z)_hi)` is within `2.01 u` relative.
fn connection_inv_one_minus_z(a: f64, b: f64, c: f64, z: f64, stop: f64) -> Option<(f64, f64)> {
    let amb = Dd::diff(a, b);
    if !(z <= -1.0) || (amb.hi - round_small(amb.hi)).abs() < CONNECTION_MIN_FRAC {
        return None;
    }
    let omz = Dd::diff(1.0, z);
    let x = 1.0 / omz.hi; // |x - 1/(1-z)| <= 2.01 u x
    let ln_omz = ln_f64(omz.hi, omz.lo)?;
    // the seven reciprocal Gammas at once (interleaved Horner sums)
    let [g_c, g_a, g_b, g_ca, g_cb, g_amb, g_bma] =
        rgamma_batch([Dd::from_f64(c), Dd::from_f64(a), Dd::from_f64(b), Dd::diff(c, a), Dd::diff(c, b), amb, Dd::diff(b, a)]);
    let lanes = [(a, b), (b, a)].map(|(p, q)| [Param::exact(p), Param::from_dw(Dd::diff(c, q)), plus_one(Dd::diff(p, q))]);
    // both series in one two-lane loop where it applies, else one by one
    let both = series_two(lanes, x, 2.01 * U, stop);
    let mut acc = (0.0f64, 0.0f64);
    for (i, (p, num, den)) in [(a, [g_b, g_ca], [g_c, g_bma]), (b, [g_a, g_cb], [g_c, g_amb])].into_iter().enumerate() {
        let Some(coef) = gamma_coefficient(num, den)? else { continue };
        let pw = pow_from_ln(ln_omz, -p)?;
        let [p1, p2, q] = lanes[i];
        let sum = match both {
            Some(sums) => sums[i],
            None => series(p1, p2, q, x, 2.01 * U, stop)?,
        };
        acc = add_connection_term(acc, coef, pw, sum);
    }
    Some((acc.0, acc.1 * (1.0 + 4.0 * U)))
}

/// `2F1(a, b; c; z)` for `1/2 < z < 1` by the connection formula in `x = 1 - z`
/// [DLMF 15.8.4, 15.10.21], for `s = c - a - b` at least [`CONNECTION_MIN_FRAC`]
/// from an integer (closer, the log case):
///
/// ```text
/// 2F1(a, b; c; z) = Gamma(c) Gamma(s) / (Gamma(c-a) Gamma(c-b)) 2F1(a, b; 1-s; x)
///                 + x^s Gamma(c) Gamma(-s) / (Gamma(a) Gamma(b)) 2F1(c-a, c-b; 1+s; x)
/// ```
///
/// `x = 1 - z` is exact (Sterbenz). `s` is the double word
/// `two_sum(two_sum(c, -a).hi, -b)` with the low parts added once: it errs by
/// at most `u |lo|`, below `2^-100 |s|`; that moves `1/Gamma(+-s)` by a relative
/// `|psi| 2^-100 < 2^-90` (`|s + n| >= 0.05`) and the power by `|ln x| 2^-100`,
/// both covered by the `2^-80` relative added to the coefficients. The series'
/// parameters `1 -+ s` carry `|lo|` enlarged by `4u` (the perturbation bound of
/// [`series`]).
fn connection_one_minus_z(a: f64, b: f64, c: f64, z: f64, stop: f64) -> Option<(f64, f64)> {
    if !(z > 0.5 && z < 1.0) {
        return None;
    }
    let (h1, l1) = two_sum(c, -a);
    let (h2, l2) = two_sum(h1, -b);
    let s = Dd { hi: h2, lo: l1 + l2 };
    if (s.hi - round_small(s.hi)).abs() < CONNECTION_MIN_FRAC {
        return None;
    }
    const S_SLACK: f64 = 8.271806125530277e-25; // 2^-80
    let neg_s = Dd { hi: -s.hi, lo: -s.lo };
    let x = 1.0 - z;
    let mut acc = (0.0f64, 0.0f64);
    let widen = |p: Param| Param { hi: p.hi, lo: p.lo.abs() * (1.0 + 4.0 * U) + 2.0 * U * s.lo.abs() };
    // the seven reciprocal Gammas at once (interleaved Horner sums)
    let [g_ca, g_cb, g_c, g_s, g_a, g_b, g_neg_s] =
        rgamma_batch([Dd::diff(c, a), Dd::diff(c, b), Dd::from_f64(c), s, Dd::from_f64(a), Dd::from_f64(b), neg_s]);
    let lanes = [
        [Param::exact(a), Param::exact(b), widen(plus_one(neg_s))],
        [Param::from_dw(Dd::diff(c, a)), Param::from_dw(Dd::diff(c, b)), widen(plus_one(s))],
    ];
    // both series in one two-lane loop where it applies, else one by one
    let both = series_two(lanes, x, 0.0, stop);
    let sum = |i: usize| match both {
        Some(sums) => Some(sums[i]),
        None => series(lanes[i][0], lanes[i][1], lanes[i][2], x, 0.0, stop),
    };
    if let Some((coef, rel)) = gamma_coefficient([g_ca, g_cb], [g_c, g_s])? {
        acc = add_connection_term(acc, (coef, rel + S_SLACK), (1.0, 0.0), sum(0)?);
    }
    if let Some((coef, rel)) = gamma_coefficient([g_a, g_b], [g_c, g_neg_s])? {
        let pw = pow_dw_exponent(ln_f64(x, 0.0)?, s)?;
        acc = add_connection_term(acc, (coef, rel + S_SLACK), (pw.0, pw.1 + S_SLACK), sum(1)?);
    }
    Some((acc.0, acc.1 * (1.0 + 4.0 * U)))
}

/// `2F1(a, b; c; z)` natively with a proven bound, accepted only when
/// `err <= rel_tol |value|`; `None` where the native path cannot certify that
/// (the caller then uses MP). Arguments are validated by the caller.
pub(super) fn hyp2f1_native(a: f64, b: f64, c: f64, z: f64, rel_tol: f64) -> Option<Bounded> {
    let accept = |v: f64, err: f64| -> Option<Bounded> {
        (v.is_finite() && v.abs() > 1e-290 && v.abs() < 1e290 && err <= rel_tol * v.abs()).then_some(Bounded { value: v, err })
    };
    let stop = stop_for(rel_tol);
    let terminating = Param::exact(a).nonpos_degree().is_some() || Param::exact(b).nonpos_degree().is_some();
    if !terminating && z > CONNECTION_ONE_MINUS_Z_ABOVE {
        if let Some(r) = connection_one_minus_z(a, b, c, z, stop).and_then(|(v, err)| accept(v, err)) {
            return Some(r);
        }
    }
    if terminating || (PFAFF_BELOW..=NATIVE_Z_MAX).contains(&z) {
        let (pa, pb, pc) = (Param::exact(a), Param::exact(b), Param::exact(c));
        if let Some(r) = series(pa, pb, pc, z, 0.0, stop).and_then(|(v, err)| accept(v, err)) {
            return Some(r);
        }
        // Above 0.7 the connection formula in 1 - z (its series in 1 - z < 0.3
        // are short, and its cancellation a different one) ...
        if !terminating && z > CONNECTION_ONE_MINUS_Z_FALLBACK_ABOVE {
            if let Some(r) = connection_one_minus_z(a, b, c, z, stop).and_then(|(v, err)| accept(v, err)) {
                return Some(r);
            }
        }
        // ... a double-word head where the first terms cancel, then f64 ...
        if let Some(r) = series_hybrid(Dd::from_f64(a), Dd::from_f64(b), Dd::from_f64(c), Dd::from_f64(z), 0.0, stop).and_then(|(v, err)| accept(v, err)) {
            return Some(r);
        }
        // ... then double words throughout (cancellation, many terms).
        let (s, err) = series_dw(Dd::from_f64(a), Dd::from_f64(b), Dd::from_f64(c), Dd::from_f64(z), 0.0)?;
        let v = s.hi + s.lo;
        return accept(v, (err + U * v.abs()) * (1.0 + 2.0 * U));
    }
    if z >= PFAFF_BELOW {
        return None;
    }
    // Below -4 the connection formula goes first, except for a, b > 0: there
    // it fails to certify a third of the points (its two terms cancel), and
    // Pfaff's f64 sum certifies 98.6% (measured over z in [-5, -4)); it is
    // Pfaff's fallback then.
    let connection_first = z <= CONNECTION_FIRST_BELOW && !(a > 0.0 && b > 0.0);
    if connection_first {
        if let Some(r) = connection_inv_one_minus_z(a, b, c, z, stop).and_then(|(v, err)| accept(v, err)) {
            return Some(r);
        }
    }
    // Pfaff: w = z/(z-1) = -z / (1 - z); 1 - z exact as a double word.
    let omz = Dd::diff(1.0, z);
    let ca = Dd::diff(c, a);
    let cb = Dd::diff(c, b);
    let neg = |x: f64| (x < 0.0) as u8;
    let first_a = neg(a) + neg(cb.hi) <= neg(b) + neg(ca.hi);
    let candidates = if first_a { [(a, cb), (b, ca)] } else { [(b, ca), (a, cb)] };
    // f64 sums first (w rounded twice: relative error <= 2.01 u) ...
    let w = -z / omz.hi;
    // |P - P~| <= pre_rel |P~| (power_f64); one more rounding for the product.
    let pfaff = |(pre, pre_rel): (f64, f64), (s, err_s): (f64, f64)| -> Option<Bounded> {
        let v = pre * s;
        let pr = pre_rel * 1.0001;
        accept(v, (pre.abs() * err_s * (1.0 + 2.0 * pr) + (1.01 * pr + U) * v.abs()) * (1.0 + 4.0 * U))
    };
    // ln(1 - z) once; each power before its sum (independent work the CPU
    // overlaps with the sum's start)
    let ln_omz = ln_f64(omz.hi, omz.lo);
    for (p, q) in candidates {
        let pre = ln_omz.and_then(|l| pow_from_ln(l, -p));
        let sum = series(Param::exact(p), Param::from_dw(q), Param::exact(c), w, 2.01 * U, stop);
        if let Some(r) = pre.zip(sum).and_then(|(pre, sum)| pfaff(pre, sum)) {
            return Some(r);
        }
    }
    if z <= CONNECTION_FIRST_BELOW && !connection_first {
        if let Some(r) = connection_inv_one_minus_z(a, b, c, z, stop).and_then(|(v, err)| accept(v, err)) {
            return Some(r);
        }
    }
    // ... then a double-word head (w to 32 u^2) where the first terms cancel
    // (not the connection formula where it did not go first: over random
    // points where the first f64 sum fails, it certifies only 23% of those the
    // second one does not, at the cost of two series and seven Gammas) ...
    let w = Dd::from_f64(-z).div_accurate(omz);
    for (p, q) in candidates {
        let pre = ln_omz.and_then(|l| pow_from_ln(l, -p));
        if let Some(r) = pre.zip(series_hybrid(Dd::from_f64(p), q, Dd::from_f64(c), w, 32.0 * U * U, stop)).and_then(|(pre, sum)| pfaff(pre, sum)) {
            return Some(r);
        }
    }
    // ... then double words throughout.
    let (p, q) = candidates[0];
    let (s, err_s) = series_dw(Dd::from_f64(p), q, Dd::from_f64(c), w, 32.0 * U * U)?;
    let (pre, pre_rel) = pow_dw(omz, Dd::from_f64(-p), 0.0)?;
    let prod = pre.mul_accurate(s);
    let v = prod.hi + prod.lo;
    let s_abs = s.hi.abs() * (1.0 + 2.0 * U);
    let pre_abs = pre.hi.abs() * (1.0 + 2.0 * U);
    // |P S - v| <= |P| err_s + |P~ - P| |s~| + 7u^2 |P~ s~| + u |v|
    let err = (pre_abs * (1.0 + 1.01 * pre_rel) * err_s + 1.01 * pre_rel * pre_abs * s_abs + 8.0 * U * U * pre_abs * s_abs)
        * 1.0001
        + U * v.abs();
    accept(v, err * (1.0 + 4.0 * U))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ball::Dekker;
    use crate::special::exact;
    use crate::special::hyp2f1::hyp2f1_mp;
    use rug::Float;

    use super::super::tests::Lcg;

    /// Over the benchmark domain (a, b in [-3, 3], c in [0.5, 6], z in [-5, 0.9]):
    /// the bound holds at every point against the certified 120-bit ball, the
    /// accepted values are within 1e-14, and the MP fallback stays rare.
    #[test]
    fn bound_holds_on_the_benchmark_domain() {
        let mut rng = Lcg(0x2f1);
        let (mut accepted, mut total) = (0u32, 0u32);
        let (mut worst, mut worst_bound) = (0.0f64, 0.0f64);
        for _ in 0..10000 {
            let (a, b, c, z) = (rng.uniform(-3.0, 3.0), rng.uniform(-3.0, 3.0), rng.uniform(0.5, 6.0), rng.uniform(-5.0, 0.9));
            total += 1;
            let Some(r) = hyp2f1_native(a, b, c, z, super::super::NATIVE_VALUE_REL) else { continue };
            let m = hyp2f1_mp(&exact(a), &exact(b), &exact(c), &exact(z), 120).unwrap();
            let diff = Float::with_val(200, m.mid() - r.value).abs();
            let diff_up = diff.to_f64() + m.rad().to_f64();
            assert!(diff_up <= r.err, "2F1({a}, {b}; {c}; {z}): |error| {diff_up:e} > bound {:e}", r.err);
            if r.err <= super::super::NATIVE_VALUE_REL * r.value.abs() {
                accepted += 1;
                worst = worst.max(diff_up / r.value.abs());
                worst_bound = worst_bound.max(r.err / r.value.abs());
            }
        }
        eprintln!("native accepted {accepted}/{total}, worst rel error {worst:e}, worst rel bound {worst_bound:e}");
        assert!(worst <= 1e-14, "{worst:e}");
        assert!(accepted as f64 >= 0.97 * total as f64, "{accepted}/{total}");
    }

    /// A connection formula on its own over 3000 random points (a, b in [-3, 3],
    /// c in [0.5, 6], z from `z_of`): its bound holds at every point against
    /// the certified 120-bit ball, and it answers at least 85% of them.
    fn check_connection(form: fn(f64, f64, f64, f64, f64) -> Option<(f64, f64)>, seed: u64, z_of: fn(&mut Lcg, u32) -> f64) {
        let mut rng = Lcg(seed);
        let (mut answered, mut total, mut worst_bound) = (0u32, 0u32, 0.0f64);
        for i in 0..3000 {
            let (a, b, c) = (rng.uniform(-3.0, 3.0), rng.uniform(-3.0, 3.0), rng.uniform(0.5, 6.0));
            let z = z_of(&mut rng, i);
            total += 1;
            let stop = if i % 2 == 0 { 1.3877787807814457e-17 } else { 1.4210854715202004e-14 };
            let Some((v, err)) = form(a, b, c, z, stop) else { continue };
            answered += 1;
            let m = hyp2f1_mp(&exact(a), &exact(b), &exact(c), &exact(z), 120).unwrap();
            let diff_up = Float::with_val(200, m.mid() - v).abs().to_f64() + m.rad().to_f64();
            assert!(diff_up <= err, "connection form of 2F1({a}, {b}; {c}; {z}): |error| {diff_up:e} > bound {err:e}");
            if v != 0.0 {
                worst_bound = worst_bound.max(err / v.abs());
            }
        }
        eprintln!("connection answered {answered}/{total}, worst rel bound {worst_bound:e}");
        assert!(answered as f64 >= 0.85 * total as f64, "{answered}/{total}");
    }

    /// The stops are powers of two, and `1/(4 stop)` is exact without a division.
    #[test]
    fn stops_are_powers_of_two() {
        for e in -60..-1 {
            let s = 2f64.powi(e);
            assert_eq!(quarter_over(s), 0.25 / s);
            assert_eq!(pow2_floor(s * 1.7), s);
        }
        assert_eq!(quarter_over(3e-17), 0.25 / 3e-17);
        for rel in [super::super::NATIVE_ACCEPT_REL, super::super::NATIVE_VALUE_REL, 1e-20, 1.0] {
            let stop = stop_for(rel);
            assert_eq!(pow2_floor(stop), stop);
            assert!(stop <= (rel / 256.0).max(1.3877787807814457e-17), "{rel:e}: {stop:e}");
        }
    }

    /// The double-word series with fused products (where the CPU has them) is
    /// bit-identical to the portable one.
    #[test]
    fn double_word_series_fused_equals_portable() {
        let mut rng = Lcg(0xf0a);
        for _ in 0..500 {
            let (a, b, c, x) = (rng.uniform(-3.0, 3.0), rng.uniform(-3.0, 3.0), rng.uniform(0.5, 6.0), rng.uniform(-0.9, 0.9));
            let args = (Dd::from_f64(a), Dd::diff(c, b), Dd::from_f64(c), Dd::from_f64(x));
            let fast = series_dw(args.0, args.1, args.2, args.3, 0.0);
            let portable = series_dw_with::<Dekker>(args.0, args.1, args.2, args.3, 0.0);
            assert_eq!(fast, portable, "2F1({a}, {c} - {b}; {c}; {x})");
        }
    }

    /// The hybrid sum (double-word head, f64 rest) where the f64 sum cannot
    /// certify 1e-13: Pfaff forms `2F1(a, c-b; c; w)` and direct series with
    /// exact f64 parameters and argument, `w in [1/3, 0.85]`. Its bound holds
    /// at every point against the certified 120-bit ball, at the stops of
    /// both entry points; it certifies most of them, within 1e-14.
    #[test]
    fn hybrid_series_bound_holds_where_f64_cancels() {
        let mut rng = Lcg(0x4b1d);
        let (mut cancelling, mut certified, mut worst) = (0u32, 0u32, 0.0f64);
        for i in 0..20000 {
            let (a, b, c) = (rng.uniform(-3.0, 3.0), rng.uniform(-3.0, 3.0), rng.uniform(0.5, 6.0));
            let x = if i % 2 == 0 { rng.uniform(1.0 / 3.0, 0.85) } else { rng.uniform(-0.5, 0.85) };
            let p2 = if i % 2 == 0 { c - b } else { b };
            // the stops of hyp2f1_bounded and hyp2f1
            let stop = stop_for(if i % 4 < 2 { super::super::NATIVE_ACCEPT_REL } else { super::super::NATIVE_VALUE_REL });
            let f64_sum = series(Param::exact(a), Param::exact(p2), Param::exact(c), x, 0.0, stop);
            if f64_sum.is_some_and(|(v, err)| err <= 1e-13 * v.abs()) {
                continue;
            }
            cancelling += 1;
            let Some((v, err)) = series_hybrid(Dd::from_f64(a), Dd::from_f64(p2), Dd::from_f64(c), Dd::from_f64(x), 0.0, stop) else { continue };
            let m = hyp2f1_mp(&exact(a), &exact(p2), &exact(c), &exact(x), 120).unwrap();
            let diff_up = Float::with_val(200, m.mid() - v).abs().to_f64() + m.rad().to_f64();
            assert!(diff_up <= err, "hybrid 2F1({a}, {p2}; {c}; {x}): |error| {diff_up:e} > bound {err:e}");
            if err <= 1e-13 * v.abs() {
                certified += 1;
                worst = worst.max(diff_up / v.abs());
            }
        }
        eprintln!("hybrid certified {certified} of {cancelling} points where f64 did not, worst rel error {worst:e}");
        assert!(cancelling >= 100, "{cancelling}");
        assert!(worst <= 1e-14, "{worst:e}");
        assert!(certified as f64 >= 0.9 * cancelling as f64, "{certified}/{cancelling}");
    }

    /// DLMF 15.8.3, z in [-1000, -1].
    #[test]
    fn connection_bound_holds() {
        check_connection(connection_inv_one_minus_z, 0x1f2, |rng, i| {
            if i % 3 == 0 {
                -10f64.powf(rng.uniform(0.0, 3.0))
            } else {
                rng.uniform(-5.0, -1.0)
            }
        });
    }

    /// DLMF 15.8.4, z in (1/2, 1), up to `1 - 10^-12`.
    #[test]
    fn connection_one_minus_z_bound_holds() {
        check_connection(connection_one_minus_z, 0x1a2, |rng, i| {
            if i % 3 == 0 {
                1.0 - 10f64.powf(-rng.uniform(0.31, 12.0))
            } else {
                rng.uniform(0.5, 1.0)
            }
        });
    }

    #[test]
    fn terminating_and_edges() {
        // 2F1(-2, b; c; z) = 1 - 2 b z / c + b (b+1) z^2 / (c (c+1)), also for z < -1.
        for &(b, c, z) in &[(0.7, 2.5, -30.0), (1.5, 0.25, 1.0), (-1.5, 3.0, -4.5)] {
            let r = hyp2f1_native(-2.0, b, c, z, 1e-13).unwrap();
            let want = 1.0 - 2.0 * b * z / c + b * (b + 1.0) * z * z / (c * (c + 1.0));
            assert!((r.value - want).abs() <= r.err + 4.0 * f64::EPSILON * want.abs(), "{r:?} vs {want}");
        }
        // Beyond 9/10 only the connection formula: native unless c - a - b is
        // (near) an integer (the log case); z = 1 is Gauss's sum in MP.
        assert!(hyp2f1_native(0.3, 0.4, 1.5, 0.95, 1e-13).is_some());
        assert!(hyp2f1_native(0.3, 0.7, 2.0, 0.95, 1e-13).is_none());
        assert!(hyp2f1_native(0.3, 0.4, 1.5, 1.0, 1e-13).is_none());
    }
}




