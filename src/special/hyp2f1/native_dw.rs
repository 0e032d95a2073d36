//! Double-word sums of the native `2F1` series ([`super::native`]), for the
//! parameters where the f64 sum cancels too much to certify.
//!
//! * [`series_dw`]: every term and partial sum in double words (the accurate
//!   operations of [`Dd`], Joldes-Muller-Popescu 2017); per term a relative
//!   error of `49 u^2` (charged `128 u^2`) and `3u^2 |s~_k|` per addition.
//! * [`series_hybrid`]: a double-word head over the cancelling first terms,
//!   then the f64 loop of [`super::native_series`] with its proven bound.
//!
//! Both return `None` where they cannot certify (the caller falls back to MP).

use super::native_series::{first_positive_index, ratio_bound, ratio_bound_tight, series_from, Param, Start, MAX_NATIVE_TERMS};
use super::power::U;
use super::power_f64::floor_any;
use crate::ball::{cpu_dispatch, Dd, ExactProduct};

/// `t_{n+1} = t_n x (p1+n)(p2+n) / ((q+n)(n+1))` in double words (the step
/// of [`series_dw`], `49 u^2` relative, charged `128 u^2`); `None` at a zero
/// denominator.
#[inline(always)]
pub(super) fn dw_next_term<P: ExactProduct>(p1: Dd, p2: Dd, q: Dd, x: Dd, t: Dd, n: u64) -> Option<Dd> {
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
    /// argument as [`series`](super::native_series::series) with the per-step relative error
    /// `E = 128 u^2 + theta` (three DW additions `3u^2`, two DW products `7u^2`, the
    /// product by `x` `7u^2`, one DW division `15u^2 + 56u^3`, the update `7u^2`:
    /// `49 u^2`, charged `128 u^2`) and `3u^2 |s~_k|` per addition; parameters are
    /// exact double words (`theta` bounds the relative error of `x`).
    pub(super) fn series_dw(p1: Dd, p2: Dd, q: Dd, x: Dd, x_rel: f64) -> Option<(Dd, f64)> => series_dw_with
}

/// [`series_dw`] with the exact product `P` (the result is bit-identical for
/// every `P`: both products are exact).
#[inline(always)]
pub(super) fn series_dw_with<P: ExactProduct>(p1: Dd, p2: Dd, q: Dd, x: Dd, x_rel: f64) -> Option<(Dd, f64)> {
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
    pub(super) fn series_hybrid(p1: Dd, p2: Dd, q: Dd, x: Dd, x_rel: f64, stop: f64) -> Option<(f64, f64)> => series_hybrid_with
}

#[inline(always)]
pub(super) fn series_hybrid_with<P: ExactProduct>(p1: Dd, p2: Dd, q: Dd, x: Dd, x_rel: f64, stop: f64) -> Option<(f64, f64)> {
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
