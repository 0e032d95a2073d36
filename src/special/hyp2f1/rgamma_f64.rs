//! Certified `1/Gamma(x)` in f64, for the Gamma ratios of the native f64 `2F1`
//! connection formulas: a table of Taylor polynomials built once from a
//! certified series, then a short Horner sum with a proven error bound.
//!
//! # Method
//!
//! **The series.** `1/Gamma(z) = sum_{k>=1} a_k z^k` is entire [DLMF 5.7.1];
//! `a_1 = 1`, `a_2 = gamma`, and from `ln Gamma(1+z) = -gamma z + sum_{k>=2}
//! (-1)^k zeta(k) z^k / k` [DLMF 5.7.3]
//! `(k-1) a_k = gamma a_{k-1} + sum_{j=2}^{k-1} (-1)^{j+1} zeta(j) a_{k-j}`.
//! The `a_k`, `k <= SERIES_TERMS`, are computed once in ball arithmetic at
//! [`TABLE_PREC`] bits from MPFR's `gamma` and `zeta(j)`.
//!
//! **A bound for the rest** (Cauchy on `|z| = 8`): from the Weierstrass product
//! `1/Gamma(z) = z e^{gamma z} prod_{n>=1} (1 + z/n) e^{-z/n}` [DLMF 5.8.2], with
//! `|(1+w) e^{-w}| <= (1+|w|) e^{|w|}` for `n <= 16` and `<= e^{|w|^2}` for
//! `|w| <= 1/2`, `ln max_{|z|=8} |1/Gamma| <= ln 8 + 8 gamma + ln C(24, 8) +
//! 8 H_16 + 64/16 < 51.3`, so `M = max_{|z|<=8} |1/Gamma(z)| < 2 10^22` and
//! `|a_k| <= M 8^-k`.
//!
//! **The table.** At the centres `c = i/16`, `i = -8..=24` (covering
//! `[-1/2, 3/2]`), the Taylor coefficients `d_j = sum_{k>=j} a_k C(k,j) c^{k-j}`,
//! `j < ORDERS`, of the polynomial truncated at `k <= SERIES_TERMS`, by repeated
//! synthetic division (a Taylor shift) in balls; the rest of the sum is
//! at most `M sum_{k>SERIES_TERMS} ((1+|c|)/8)^k` (`C(k,j) |c|^{k-j} <=
//! (1+|c|)^k`), added to each radius. Each `d_j` is rounded to f64 (`d~_j`, error
//! `e_j` = rounding + radius). Beyond the computed orders, Cauchy on the circle
//! of radius `6.5` about `c` (inside `|z| <= 8`): `|d_j| <= M 6.5^-j`.
//!
//! **Evaluation** at an exact f64 `x0 in [-1/2, 3/2]`: `c` the nearest centre,
//! `delta = x0 - c` is exact (`|delta| <= 1/32 <= |x0|` or `c = 0`, and `delta`
//! is a multiple of `ulp(x0)`), Horner `p = sum_{j<=K} d~_j delta^j` in f64
//! (`K <= 16`; the rows are zero-padded to 16, and a zero top keeps `p = 0`
//! exactly until the row's own degree). By
//! [Higham, *Accuracy and Stability*, 2nd ed., eq. 5.3] the computed value is
//! `sum d~_j delta^j (1 + theta_{2j+1})`, `|theta_n| <= gamma_n = nu/(1-nu)`
//! (with a fused multiply-add per step, `theta_{j+1}`: fewer roundings, the
//! same bound), so
//! `|p~ - 1/Gamma(x0)| <= sum_j beta_j |delta|^j + 32 |delta| T`, with
//! `beta_j = gamma_{2j+1} |d~_j| + e_j` and the truncation
//! `T = sum_{j>K} max|d_j| 32^-j` (every `|delta|^j <= 32 |delta| 32^-j`), so
//! `<= beta_0 + 32 |delta| B1`, `B1 = sum_{1<=j<=K} beta_j 32^-j + T`: two
//! constants per centre (summed once, inflated by `1.001`), and the runtime
//! bound is one product and one sum (inflated by `1 + 2^-40`). At the centre
//! `c = 0`, `d_0 = 0 = beta_0` and the bound is relative to `|delta| ~ |x0|`,
//! so `1/Gamma` keeps its relative accuracy next to its zero.
//!
//! **Shift** [DLMF 5.5.1]. For `x >= 3/2`, `x0 = x - m in [1/2, 3/2)` and
//! `1/Gamma(x) = (1/Gamma(x0)) / prod_{j=1}^{m} (x - j)`; for `x < -1/2`,
//! `x0 = x + m in (-1/2, 1/2]` and `1/Gamma(x) = (1/Gamma(x0)) prod_{j<m} (x + j)`.
//! Every factor and `x0` are exact in f64 (integers added to `x` with a result
//! no larger than `|x|`, on `ulp(x)`'s grid), so the product has `m - 1`
//! roundings and the final product or quotient one:
//! `|v - 1/Gamma(x)| <= 1.02 (k u + gamma_{m-1}) |v| + err_p |P~|^{+-1} (1 + 1.01 gamma_{m-1})`,
//! `k = 1` for the product and `k = 2` for the quotient, formed as
//! `p fl(1/P~)` (one division a value); `gamma_{m-1} <= 1.0002 (m-1) u` for `m <= 60`.
//!
//! **A double-word argument** `x = hi + lo` (e.g. the exact `c - a`,
//! `|lo| <= 2^-40`). The reduced argument is `x0 + lo`: Horner runs at
//! `delta~ = fl(delta + lo)`, `|eta| = |delta~ - (x0 + lo - c)| <= u |delta~|`, and
//! moving the argument by `eta` changes `1/Gamma` by at most
//! `(e^{|eta| Psi0} - 1) |1/Gamma| <= 1.01 |eta| Psi0 |1/Gamma|` (if `<= 1/100`),
//! `Psi0 = 1/t_min + 1.97` (`psi(t) = psi(t+1) - 1/t`, `|psi| <= 1.97` on
//! `[1/2, 5/2]`; `1/Gamma` keeps its sign on the segment, `|t| >= t_min > 0`).
//! This keeps the relative accuracy next to a pole, where `lo` is not small
//! next to `x0`. The shift factors are `x + j`, not `hi + j`: a relative change
//! of at most `1.01 |lo| S`, `S = sum 1/|x + j|`, with `S <= 2.01 m` for `x < -1/2`
//! and `S = psi(x) - psi(x0) < (E + 1) ln 2 + 1.97` for `x >= 3/2` (`psi(t) < ln t`,
//! `t < 2^(E+1)`) [DLMF 5.5.2, 5.15.1].
//!
//! **Batches.** The connection formulas need six or seven reciprocal Gammas
//! at once; [`rgamma_batch`] runs their Horner sums interleaved, so the
//! latency of one dependency chain (16 steps) hides behind the others, and
//! with fused multiply-adds where the CPU has them (run-time detection).
//!
//! Outside `|x| < MAX_ABS_ARG`, or where a product leaves the normal range,
//! the function returns `None` and the caller takes another path.
//!
//! Tested against MPFR's `gamma` at 20000 points, next to the poles, and on
//! double-word arguments (`tests` below).

use std::sync::OnceLock;

use super::power::{round_small, U};
use super::power_f64::floor_small;
use crate::ball::{Ball, Dd, Dekker, ExactProduct};
#[cfg(target_arch = "x86_64")]
use crate::ball::Fused;

/// Largest `|x|` accepted (the shift products stay far from overflow).
const MAX_ABS_ARG: f64 = 60.0;

/// Terms `a_1..a_SERIES_TERMS` of the series of `1/Gamma` used for the table.
const SERIES_TERMS: usize = 100;

/// Taylor orders computed per centre; the Horner degree `K` is chosen below it.
const ORDERS: usize = 24;

/// Precision of the table computation (the sums for `d_j` lose at most about
/// 5 bits to cancellation at `|c| <= 3/2`).
const TABLE_PREC: u32 = 128;

/// `M`: `|1/Gamma(z)| < M` for `|z| <= 8` (module docs).
const CAUCHY_M: f64 = 2e22;

/// Largest Horner degree (a row whose truncation would need more carries the
/// dropped terms in its bound); rows are zero-padded to it.
const MAX_DEGREE: usize = 16;

/// Centres `i/16`, `i = CENTRE_MIN..=CENTRE_MAX`.
const CENTRE_MIN: i32 = -8;
const CENTRE_MAX: i32 = 24;

/// One centre: `d~_j`, the Horner degree, and the bound's two constants:
/// `beta_0` and `B1 = sum_{1<=j<=K} beta_j 32^-j + T` (module docs).
#[derive(Clone, Debug)]
struct Row {
    horner: [f64; MAX_DEGREE + 1],
    degree: usize,
    beta0: f64,
    b1: f64,
}

/// The table, built on first use.
fn table() -> &'static [Row] {
    static TABLE: OnceLock<Vec<Row>> = OnceLock::new();
    TABLE.get_or_init(build_table)
}

/// `a_1..=a_SERIES_TERMS` (index `k`; `a_0 = 0`) in balls.
fn series_coefficients() -> Vec<Ball> {
    let p = TABLE_PREC;
    let euler = Ball::euler_gamma(p);
    let zeta: Vec<Ball> = (0..SERIES_TERMS as u32).map(|j| if j >= 2 { Ball::zeta_u(j, p) } else { Ball::zero(p) }).collect();
    let mut a = vec![Ball::zero(p), Ball::one(p), euler.clone()];
    for k in 3..=SERIES_TERMS {
        let mut s = euler.mul(&a[k - 1]);
        for j in 2..k {
            let t = zeta[j].mul(&a[k - j]);
            s = if j % 2 == 1 { s.add(&t) } else { s.sub(&t) };
        }
        // division by an exact small integer: the ball covers its rounding
        a.push(s.div_i64(k as i64 - 1).unwrap_or_else(|_| Ball::zero(p)));
    }
    a
}

/// Upper bound of `sum_{k>n} M r^k` for `r < 1`.
fn geometric_tail(r: f64, n: usize) -> f64 {
    CAUCHY_M * r.powi(n as i32 + 1) / (1.0 - r) * 1.001
}

fn gamma_n(n: usize) -> f64 {
    let nu = n as f64 * U;
    nu / (1.0 - nu) * 1.0001
}

/// Rounds a ball to f64: `(value, bound on |exact - value|)`.
fn round_ball(b: &Ball) -> (f64, f64) {
    let v = b.to_f64();
    let diff = rug::Float::with_val(b.prec() + 64, b.mid() - v).abs().to_f64();
    (v, (diff + b.rad_mag().to_f64_up()) * 1.0001)
}

fn build_table() -> Vec<Row> {
    let p = TABLE_PREC;
    let a = series_coefficients();
    let mut rows = Vec::new();
    for i in CENTRE_MIN..=CENTRE_MAX {
        let c = Ball::from_ratio(i as i64, 16, p);
        let c_abs = (i as f64 / 16.0).abs();
        // at c = 0, d_j = a_j exactly: no truncation
        let truncation = if i == 0 { 0.0 } else { geometric_tail((1.0 + c_abs) / 8.0, SERIES_TERMS) };
        let mut coeff = [0.0; ORDERS];
        let mut err = [0.0; ORDERS];
        // Taylor shift by repeated synthetic division: dividing sum b_k z^k by
        // (z - c) leaves the remainder d_j and the quotient for d_{j+1}
        let mut b: Vec<Ball> = a.clone();
        for j in 0..ORDERS {
            for k in (j..SERIES_TERMS).rev() {
                let t = b[k + 1].mul(&c);
                b[k] = b[k].add(&t);
            }
            let (v, e) = round_ball(&b[j]);
            coeff[j] = v;
            err[j] = e + truncation;
        }
        // Horner degree: the smallest K whose truncation is below 2^-66 of the
        // smallest |1/Gamma| near the centre (bounded below by |d_0| - 1/16 sum),
        // at most MAX_DEGREE; the truncation T covers every order above K.
        let cauchy = geometric_tail(1.0 / (32.0 * 6.5), ORDERS - 1);
        let tail_above = |k: usize| cauchy + (k + 1..ORDERS).map(|j| (coeff[j].abs() + err[j]) * (1.0f64 / 32.0).powi(j as i32)).sum::<f64>();
        let floor = if i == 0 { 1.0 / 32.0 } else { coeff[0].abs() * 0.5 };
        let degree = (0..ORDERS).find(|&k| tail_above(k) <= floor * 2f64.powi(-66)).unwrap_or(ORDERS - 1).min(MAX_DEGREE);
        let tail = tail_above(degree);
        let beta = |j: usize| gamma_n(2 * j + 1) * coeff[j].abs() + err[j];
        let b1 = (1..=degree).map(|j| beta(j) * (1.0f64 / 32.0).powi(j as i32)).sum::<f64>() * 1.001 + tail * 1.001;
        let mut horner = [0.0; MAX_DEGREE + 1];
        horner[..=degree].copy_from_slice(&coeff[..=degree]);
        rows.push(Row { horner, degree, beta0: beta(0) * 1.001, b1 });
    }
    rows
}

/// The shift of `hi` into the table's range: `x0 = hi -+ m` and the product
/// `P` of the exact factors (`1/Gamma(hi) = (1/Gamma(x0)) / P` when `divide`,
/// `(1/Gamma(x0)) P` otherwise).
#[derive(Clone, Copy, Debug)]
struct Shift {
    x0: f64,
    m: f64,
    prod: f64,
    divide: bool,
}

impl Shift {
    const NONE: Shift = Shift { x0: 0.0, m: 0.0, prod: 1.0, divide: false };

    /// The shifts of `N` arguments at once, without data-dependent branches
    /// (the factors `hi - j`, or `hi + j`, run to the largest `m` of the
    /// batch, a factor 1 exactly where an argument needs fewer).
    #[inline(always)]
    fn of_batch<const N: usize>(his: [f64; N]) -> [Shift; N] {
        let mut out = [Shift::NONE; N];
        let mut m_max = 0.0f64;
        for (sh, &hi) in out.iter_mut().zip(&his) {
            // arguments out of range (refused by the caller) take no shift
            let in_range = hi.abs() < MAX_ABS_ARG;
            let up = in_range && hi >= 1.5;
            let down = in_range && hi < -0.5;
            let m = if up {
                floor_small(hi - 0.5)
            } else if down {
                floor_small(0.5 - hi)
            } else {
                0.0
            };
            // up: x0 = hi - m in [1/2, 3/2); down: x0 = hi + m in (-1/2, 1/2]
            *sh = Shift { x0: if up { hi - m } else { hi + m }, m, prod: 1.0, divide: up };
            m_max = m_max.max(m);
        }
        let mut j = 0.0;
        while j < m_max {
            for (sh, &hi) in out.iter_mut().zip(&his) {
                // up: factors hi - 1, ..., hi - m; down: hi, hi + 1, ..., hi + m - 1
                let factor = if sh.divide { hi - (j + 1.0) } else { hi + j };
                sh.prod *= if j < sh.m { factor } else { 1.0 };
            }
            j += 1.0;
        }
        out
    }
}

/// The bound of the Horner value `p ~ 1/Gamma(x0 + lo)` at `delta~` (module
/// docs), then of the shifted value: `Some((value, err))`, or `None` next to
/// the pole at 0 or where the argument's low word moves too much. Written
/// without data-dependent branches (the sign of the argument and whether its
/// low word is zero vary from call to call): both sides are computed, the
/// right one selected, and the validity tested once at the end.
#[inline(always)]
fn finish(x: Dd, sh: &Shift, row: &Row, delta: f64, p: f64) -> Option<(f64, f64)> {
    let (x0, lo) = (sh.x0, x.lo);
    let (ad, lo_abs) = (delta.abs(), lo.abs());
    let has_lo = lo != 0.0;
    // sum_j beta_j |delta|^j + 32 |delta| T <= beta_0 + 32 |delta| B1 (|delta| <= 1/32)
    let mut err_p = (row.beta0 + 32.0 * ad * row.b1) * (1.0 + 2f64.powi(-40));
    // With lo: moving the argument by eta changes 1/Gamma by <= 1.01 |eta| Psi0
    // |1/Gamma|, |psi(t)| <= 1/|t| + 1.97 on the segment (|t| >= |x0| - |lo| - |eta|).
    let eta = U * ad;
    let t_min = (x0.abs() - lo_abs - eta) * (1.0 - 4.0 * U);
    let h_arg = eta * (1.0 / t_min + 1.97) * (1.0 + 4.0 * U);
    let arg_ok = !has_lo | ((t_min > 0.0) & (h_arg <= 0.01));
    err_p += if has_lo { 1.01 * h_arg * (p.abs() + err_p) } else { 0.0 };
    // gamma_{m-1} <= 1.0002 (m - 1) u for m <= 60
    let m = sh.m;
    let g = (m - 1.0).max(0.0) * U * 1.0002;
    // the quotient as p fl(1/P~): two roundings (|fl(1/P~)| >= |1/P~| (1 - u))
    let inv = 1.0 / sh.prod;
    let (factor, factor_bound, roundings) =
        if sh.divide { (inv, inv.abs() * (1.0 + 2.0 * U), 2.0 * U) } else { (sh.prod, sh.prod.abs(), U) };
    let v = p * factor;
    let mut err = 1.02 * (roundings + g) * v.abs() + err_p * factor_bound * (1.0 + 1.01 * g);
    // The shift factors are x + j, not hi + j: relative change <= 1.01 |lo| S,
    // S = sum 1/|x + j| over the factors (0 without lo or without factors):
    // up, sum_{i<m} 1/(x0 + i) = psi(x) - psi(x0) < ln x + 1.97 < (E + 1) ln 2 + 1.97;
    // down, every |x + j| >= 1/2 - |lo|, S <= 2.01 m.
    let top = (x.hi + 2.0 * lo_abs) * (1.0 + 4.0 * U);
    let e = ((top.to_bits() >> 52) & 0x7ff) as f64 - 1022.0;
    let s_up = e * std::f64::consts::LN_2 + 1.97;
    let h_shift = lo_abs * if sh.divide { s_up } else { 2.01 * m } * (1.0 + 4.0 * U);
    let shift_ok = h_shift <= 0.01;
    err += 1.01 * h_shift * (v.abs() + err);
    (arg_ok & shift_ok).then_some((v, err * (1.0 + 8.0 * U)))
}

/// Certified `1/Gamma(x)` for a double word `x = hi + lo`, `|hi| < 60`:
/// `Some((value, err))` with `|1/Gamma(x) - value| <= err`, or `None` (module docs).
#[cfg(test)]
pub(super) fn rgamma_dw(x: Dd) -> Option<(f64, f64)> {
    rgamma_batch([x])[0]
}

/// [`rgamma_dw`] at `N` arguments at once: the `N` Horner sums run
/// interleaved (independent dependency chains, so the latency of one chain
/// hides behind the others), with fused multiply-adds where the CPU has them.
pub(super) fn rgamma_batch<const N: usize>(xs: [Dd; N]) -> [Option<(f64, f64)>; N] {
    #[cfg(target_arch = "x86_64")]
    if std::arch::is_x86_feature_detected!("fma") {
        // SAFETY: the CPU supports FMA (checked just above).
        return unsafe { rgamma_batch_fused(xs) };
    }
    rgamma_batch_with::<Dekker, N>(xs)
}

/// [`rgamma_batch`] compiled with fused multiply-add.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "fma")]
unsafe fn rgamma_batch_fused<const N: usize>(xs: [Dd; N]) -> [Option<(f64, f64)>; N] {
    rgamma_batch_with::<Fused, N>(xs)
}

/// [`rgamma_batch`] with the Horner step `P::mul_add` (one rounding where
/// fused, two otherwise; the bound counts two).
#[inline(always)]
fn rgamma_batch_with<P: ExactProduct, const N: usize>(xs: [Dd; N]) -> [Option<(f64, f64)>; N] {
    let table = table();
    let mut rows: [&Row; N] = [&table[0]; N];
    let shifts = Shift::of_batch(xs.map(|x| x.hi));
    let mut delta = [0.0f64; N];
    let mut ok = [false; N];
    let mut degree = 0;
    for i in 0..N {
        let x = xs[i];
        if !(x.hi.abs() < MAX_ABS_ARG) || !(x.lo.abs() <= 2f64.powi(-40)) {
            continue;
        }
        let sh = shifts[i];
        if !(sh.prod.abs() > 1e-280 && sh.prod.abs() < 1e280) {
            continue;
        }
        // x0 in [-1/2, 3/2]: c = i/16 the nearest centre, delta = x0 - c exactly;
        // with lo, delta~ = fl(delta + lo), |eta| <= u |delta~|
        let c = round_small(sh.x0 * 16.0);
        let d = (sh.x0 - c / 16.0) + x.lo;
        if !(d.abs() <= (1.0 / 32.0) * (1.0 + 1e-10)) {
            continue;
        }
        rows[i] = &table[(c as i32 - CENTRE_MIN) as usize];
        degree = degree.max(rows[i].degree);
        delta[i] = d;
        ok[i] = true;
    }
    // Horner over the zero-padded rows: p stays exactly 0 above a row's degree
    let mut p = [0.0f64; N];
    for j in (0..=degree).rev() {
        for i in 0..N {
            p[i] = P::mul_add(p[i], delta[i], rows[i].horner[j]);
        }
    }
    let mut out = [None; N];
    for i in 0..N {
        if ok[i] {
            out[i] = finish(xs[i], &shifts[i], rows[i], delta[i], p[i]);
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::special::exact;
    use rug::Float;

    /// `|1/Gamma(x) - value| <= err` against MPFR at 200 bits, relative error
    /// of the bound itself small; the portable (two roundings per Horner step)
    /// variant is checked too.
    fn check(x: Dd) -> Option<f64> {
        let portable = rgamma_batch_with::<Dekker, 1>([x])[0];
        if let Some((v, err)) = portable {
            check_against_mpfr(x, v, err);
        }
        let (v, err) = rgamma_dw(x)?;
        assert!(portable.is_some(), "1/Gamma({} + {}): the portable variant refused", x.hi, x.lo);
        check_against_mpfr(x, v, err);
        Some(if v == 0.0 { 0.0 } else { err / v.abs() })
    }

    fn check_against_mpfr(x: Dd, v: f64, err: f64) {
        // (&a + &b evaluates at 200 bits; owned a + b would round to a's 53 bits)
        let xf = Float::with_val(200, &exact(x.hi) + &exact(x.lo));
        let exact_v = if xf.is_integer() && xf <= 0 { Float::new(200) } else { Float::with_val(200, xf.gamma_ref()).recip() };
        let diff = Float::with_val(200, &exact_v - v).abs().to_f64();
        assert!(diff <= err, "1/Gamma({} + {}): |error| {diff:e} > bound {err:e} (value {v:e})", x.hi, x.lo);
    }

    /// A batch answers as its elements one by one (the same Horner steps, only
    /// interleaved), refusals included, for a batch mixing every shift.
    #[test]
    fn batch_equals_one_by_one() {
        let mut rng = Lcg(0xba7c);
        for _ in 0..2000 {
            let c = rng.uniform(0.5, 6.0);
            let (a, b) = (rng.uniform(-3.0, 3.0), rng.uniform(-3.0, 3.0));
            let xs = [Dd::from_f64(c), Dd::from_f64(a), Dd::from_f64(b), Dd::diff(c, a), Dd::diff(c, b), Dd::diff(a, b), Dd::from_f64(-(b.round())), Dd::from_f64(70.0)];
            let batch = rgamma_batch(xs);
            for (x, got) in xs.iter().zip(batch) {
                assert_eq!(got, rgamma_dw(*x), "1/Gamma({} + {})", x.hi, x.lo);
            }
            let portable = rgamma_batch_with::<Dekker, 8>(xs);
            for (x, got) in xs.iter().zip(portable) {
                assert_eq!(got, rgamma_batch_with::<Dekker, 1>([*x])[0], "portable 1/Gamma({} + {})", x.hi, x.lo);
            }
        }
    }

    use super::super::tests::Lcg;

    #[test]
    fn table_degrees_are_short() {
        let t = table();
        let max = t.iter().map(|r| r.degree).max().unwrap();
        eprintln!("degrees {:?}", t.iter().map(|r| r.degree).collect::<Vec<_>>());
        assert!(max <= 16, "Horner degree {max}");
    }

    #[test]
    fn bound_holds_on_random_points() {
        let mut rng = Lcg(0x6a3a);
        let mut worst = 0.0f64;
        for i in 0..20000 {
            let x = if i % 2 == 0 { rng.uniform(-12.0, 12.0) } else { rng.uniform(-0.6, 1.6) };
            let rel = check(Dd::from_f64(x)).unwrap();
            // relative bound a few ulp away from the poles (|1/Gamma| tiny there)
            let pole_dist = (x - x.round()).abs();
            if x > 0.5 || pole_dist > 1e-3 {
                worst = worst.max(rel);
            }
        }
        eprintln!("worst relative bound {worst:e}");
        assert!(worst < 30.0 * U, "{worst:e}");
    }

    #[test]
    fn near_poles_and_zero() {
        for n in 0..12 {
            for d in [1e-300, 1e-17, 1e-9, 1e-3, 0.49] {
                for s in [-1.0, 1.0] {
                    let x = -(n as f64) + s * d;
                    let rel = check(Dd::from_f64(x)).unwrap();
                    assert!(rel < 40.0 * U, "1/Gamma({x}): relative bound {rel:e}");
                }
            }
            // exactly at a pole: 1/Gamma = 0 exactly
            let (v, err) = rgamma_dw(Dd::from_f64(-(n as f64))).unwrap();
            assert_eq!(v, 0.0);
            assert!(err == 0.0 || err < 1e-300, "{err:e}");
        }
    }

    #[test]
    fn double_word_arguments() {
        let mut rng = Lcg(0xd00d);
        let mut answered = 0;
        for _ in 0..5000 {
            let (c, a) = (rng.uniform(0.5, 6.0), rng.uniform(-3.0, 3.0));
            if let Some(rel) = check(Dd::diff(c, a)) {
                answered += 1;
                let d = Dd::diff(c, a);
                if (d.hi - d.hi.round()).abs() > 1e-3 || d.hi > 0.5 {
                    assert!(rel < 64.0 * U, "1/Gamma({c} - {a}): relative bound {rel:e}");
                }
            }
        }
        assert!(answered >= 4990, "{answered}");
    }

    #[test]
    fn out_of_range_is_none() {
        assert!(rgamma_dw(Dd::from_f64(60.5)).is_none());
        assert!(rgamma_dw(Dd::from_f64(-61.0)).is_none());
        assert!(rgamma_dw(Dd::from_f64(f64::NAN)).is_none());
    }
}
