//! The f64 series of the native `2F1` path ([`super::native`]): the running
//! error analysis and the two-lane loops.
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
//! interleaved Horner sums ([`rgamma_batch`](super::rgamma_f64::rgamma_batch)). Where the first terms of a sum
//! cancel, [`series_hybrid`](super::native_dw::series_hybrid) sums a double-word head and continues in f64,
//! instead of the double-word sum throughout.

use super::power::U;
use super::power_f64::floor_any;
use crate::ball::{cpu_dispatch, Dd, F64x2};

/// Cap on the terms of a native series (beyond it, MP).
pub(super) const MAX_NATIVE_TERMS: u64 = 3000;

/// A series parameter `hi + lo` (`lo = 0` when it is an exact f64).
#[derive(Clone, Copy, Debug)]
pub(super) struct Param {
    pub(super) hi: f64,
    pub(super) lo: f64,
}

impl Param {
    pub(super) fn exact(x: f64) -> Param {
        Param { hi: x, lo: 0.0 }
    }

    pub(super) fn from_dw(d: Dd) -> Param {
        Param { hi: d.hi, lo: d.lo }
    }

    /// `d` when the parameter is exactly `-d`, a non-positive integer.
    pub(super) fn nonpos_degree(&self) -> Option<u64> {
        (self.lo == 0.0 && self.hi <= 0.0 && self.hi == floor_any(self.hi) && self.hi > -1e15).then(|| (-self.hi) as u64)
    }

    /// Upper bound of `|lo| / min_{n >= 0} |p + n|` (0 for exact parameters);
    /// `None` when the distance cannot be bounded away from zero.
    pub(super) fn perturbation(&self) -> Option<f64> {
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
    pub(super) fn upper_plus(&self, n: f64) -> f64 {
        (self.hi + self.lo.abs() + n) * (1.0 + 2.0 * U) + f64::MIN_POSITIVE
    }

    /// Lower bound of `p + n`.
    pub(super) fn lower_plus(&self, n: f64) -> f64 {
        let v = self.hi - self.lo.abs() + n;
        v - 2.0 * U * v.abs() - f64::MIN_POSITIVE
    }
}

/// First index with every shifted parameter positive (where the tail bound is
/// valid); `None` beyond [`MAX_NATIVE_TERMS`]. Parameters within `1e-9` of a
/// non-positive integer from above are pushed one step further (their
/// neglected low words cannot flip the sign after that).
pub(super) fn first_positive_index(params: [f64; 3]) -> Option<f64> {
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
pub(super) fn ratio_bound(p1: &Param, p2: &Param, q: &Param, x_abs: f64, n: f64) -> f64 {
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
pub(super) fn ratio_bound_tight(p1: &Param, p2: &Param, q: &Param, x_abs: f64, n: f64) -> f64 {
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
pub(super) fn ratio_parts(p1: &Param, p2: &Param, q: &Param, x_abs: f64, n: f64) -> (f64, f64) {
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
pub(super) fn series(p1: Param, p2: Param, q: Param, x: f64, x_rel: f64, stop: f64) -> Option<(f64, f64)> {
    series_from(p1, p2, q, x, x_rel, stop, Start { n: 0, t: 1.0, s: 1.0 })
}

/// Where [`series_from`] starts: the term `t` of index `n` (already summed)
/// and the partial sum `s` up to it.
#[derive(Clone, Copy, Debug)]
pub(super) struct Start {
    pub(super) n: u64,
    pub(super) t: f64,
    pub(super) s: f64,
}

/// [`series`] from the term of index `start.n` on: the terms `t_{n+1}, ...`
/// from `start.t`, added to `start.s`. The bound covers the terms' errors
/// relative to an exact `start.t` (weights `n E` with the absolute index, so a
/// relative error up to `n E` of `start.t` is covered too) and the additions;
/// the error of `start.s` is the caller's.
pub(super) fn series_from(p1: Param, p2: Param, q: Param, x: f64, x_rel: f64, stop: f64, start: Start) -> Option<(f64, f64)> {
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
pub(super) fn pow2_floor(x: f64) -> f64 {
    f64::from_bits(x.to_bits() & 0x7ff0_0000_0000_0000)
}

/// Where the f64 series of [`hyp2f1_native`](super::native::hyp2f1_native) stop: once their tail bound is
/// below `rel_tol/256` of the sum (it is part of the returned bound), rounded
/// down to a power of two (so the sums form `1/stop` exactly, without a
/// division): `2^-53` for `hyp2f1`, `2^-55` for `hyp2f1_bounded`, never above
/// `2^-46` or below `2^-56`.
pub(super) fn stop_for(rel_tol: f64) -> f64 {
    pow2_floor((rel_tol / 256.0).clamp(1.3877787807814457e-17, 1.4210854715202004e-14))
}

/// `1/(4 stop)`: exact, without a division, for `stop` a power of two in the
/// normal range (as [`hyp2f1_native`](super::native::hyp2f1_native) makes it); a division otherwise.
#[inline]
pub(super) fn quarter_over(stop: f64) -> f64 {
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
pub(super) fn first_trigger(x: f64, quarter_over_stop: f64) -> f64 {
    let ax = x.abs();
    let asymptotic = if ax <= 0.5 { 4.0 * ax * (1.0 + 2.0 * ax) } else { 4.0 * ax / (1.0 - ax) };
    quarter_over_stop * asymptotic.max(1.0)
}

/// The bound of an f64 sum (module docs): `1.01 (E sum n |t~_n| + u sum |s~_k|)`
/// inflated by `1.001` for the rounding of those sums, plus the tail, plus
/// `8u` for the rounding of this expression.
pub(super) fn f64_sum_error(e_step: f64, sum_nt: f64, sum_abs_s: f64, tail: f64) -> f64 {
    ((1.01 * (e_step * sum_nt + U * sum_abs_s)) * 1.001 + tail) * (1.0 + 8.0 * U)
}

/// Whether every denominator `(q+n)(n+1)` of a series, and a product of two,
/// stays far inside the normal range: `|q + n| >= dist(q, {0, -1, -2, ...})
/// > 1e-60` (no rounding takes a nonzero sum to zero), `|q| < 1e30`,
/// `n <= MAX_NATIVE_TERMS + 2`.
pub(super) fn denominators_safe(q: &Param) -> bool {
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
pub(super) fn series_two(lanes: [[Param; 3]; 2], x: f64, x_rel: f64, stop: f64) -> Option<[(f64, f64); 2]> {
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
pub(super) struct TwoState {
    pub(super) t: F64x2,
    pub(super) s: F64x2,
    pub(super) sum_nt: F64x2,    // sum_n n |t~_n|
    pub(super) idx: F64x2,       // (n, n): the index of the last term added
}

cpu_dispatch! {
    /// [`series_two`]'s loop: one term a lane a step until a lane's term passes
    /// its trigger (`|t~| mult <= |s~|`: the mask of those lanes) or the index
    /// reaches `n_max` (0). On its own, as [`sum_pairs`].
    #[inline(never)]
    pub(super) fn sum_two(st: &mut TwoState, params: [F64x2; 3], x: f64, n_max: f64, mult: F64x2) -> u32 => avx sum_two_with
}

#[inline(always)]
pub(super) fn sum_two_with(st: &mut TwoState, [v1, v2, vq]: [F64x2; 3], x: f64, n_max: f64, mult: F64x2) -> u32 {
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
pub(super) struct PairState {
    pub(super) t: f64,
    pub(super) s: f64,
    pub(super) sum_nt2: F64x2,       // sum_n n |t~_n|, odd and even n in two lanes
    pub(super) idx: F64x2,           // (n, n + 1)
    pub(super) n: u64,
}

cpu_dispatch! {
    /// [`series_from`]'s loop: pairs of terms while `n + 2 <= limit`, each lane
    /// rounding as the scalar formula of [`series`]; `true` when it stopped for
    /// the tail test (`|t~| tail_mult <= |s~|`). On its own (no call inside, and
    /// few live values), so that the state stays in registers.
    #[inline(never)]
    pub(super) fn sum_pairs(st: &mut PairState, params: [F64x2; 3], x: f64, limit: u64, tail_mult: f64) -> bool => avx sum_pairs_with
}

#[inline(always)]
pub(super) fn sum_pairs_with(st: &mut PairState, [v1, v2, vq]: [F64x2; 3], x: f64, limit: u64, tail_mult: f64) -> bool {
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
pub(super) enum TailTest {
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
pub(super) fn series_tail(
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
