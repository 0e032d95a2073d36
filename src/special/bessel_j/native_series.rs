//! `J_n(x)` in f64 with a **proven** error bound: the power series in
//! double-double with a running error analysis.
//!
//! # Method
//!
//! `J_n(x) = p_n S`, `p_n = (x/2)^n / n!`, `S = sum_k t_k`, `t_0 = 1`,
//! `t_{k+1} = t_k (z / ((k+1)(n+k+1)))`, `z = -x^2/4` [DLMF 10.2.2] (the ratio in
//! brackets is independent of `t_k`, so its division stays off the dependency chain).
//! `z` is exact in double-double (`x^2` by Dekker's exact product, `/4` exact),
//! the divisors are exact integers below `2^53`.
//!
//! # Error bound
//!
//! With `u = 2^-53` and the double-double error model of
//! `crate::ball::dd_bounded` (Joldes, Muller, Popescu, ACM TOMS 44, 2017,
//! with slack: `+`: `8 u^2 (|a| + |b|)`, `*`: `8 u^2 |a||b|`, `/`: `16 u^2 |a/b|`):
//!
//! * each term carries a relative error `eta_k` with
//!   `eta_{k+1} = eta_k (1 + 25 u^2) + 25 u^2`, which covers
//!   `(1 + eta_k)(1 + 8u^2)(1 + 16u^2) - 1`; `p_n = (x/2)^n * (1/n!)` by binary
//!   powering (each `*` composes `(1+a)(1+b)(1+8u^2) - 1 <= s(1+s)`, `s = a+b+8u^2`)
//!   and a table of `1/k!` rounded from 256-bit MPFR values (`<= 2u^2`), or for
//!   `n > 170` the running product of `(x/2)/j`;
//! * each addition adds `8 u^2 (|s_k| + |t_{k+1}|)`;
//! * the sum stops at the first `K` with `rho = |z| / ((K+1)(n+K+1)) <= 1/2` and
//!   `|t_K| (1 + eta_K) <= 2^-70 |S~|`: the tail is at most `2 |t_K| (1 + eta_K)`;
//! * the product `p S` adds `|p| e_S + |S| e_p + e_p e_S + 8 u^2 |p||S|`, and the
//!   final rounding of `hi + lo` to f64 adds `u |value|`.
//!
//! The bound is evaluated in f64 in fewer than `2^20` operations of relative
//! error `<= u` each, so multiplying it by `1 + 2^-30` and stepping one ulp up
//! covers its own rounding.
//!
//! # Region
//!
//! The terms alternate; about `log2(I_n(x)/|J_n(x)|)` bits cancel, and the
//! summation error is `~8 u^2 2^loss |S|`. The native path is tried where the
//! estimated loss is at most [`MAX_NATIVE_LOSS_BITS`] (for `n = 0` up to
//! `x ~ 36`, for `n = 60` up to `x ~ 65`) and accepted when the proven bound
//! meets the caller's tolerance; elsewhere (larger `x`, close to a zero of
//! `J_n`, underflow of `p_n`) the callers fall back to the certified MP path
//! and count it ([`super::bessel_j_fallbacks`]). Hankel's expansion in
//! double-double (for larger `x`) is not implemented yet.

use crate::ball::{div_f64_p, mag, Bounded, Dd, ExactProduct, BOUND_INFLATION, C_ADD, U, U2};

/// Per `*` then `/` step: covers `(1 + 8u^2)(1 + 16u^2) - 1` with room.
const C_STEP: f64 = 25.0 * U2;
/// Stop when the next term is below `2^-70` of the sum (the callers accept
/// at most `2^-47` relative; the summation error alone is `~2^-100 2^loss`).
const TAIL_REL: f64 = 8.470329472543003e-22; // 2^-70

/// Largest estimated cancellation (bits) for which the native series is tried.
pub const MAX_NATIVE_LOSS_BITS: f64 = 52.0;
/// Orders above this go to the MP path (the prefactor's running error grows like `n u^2`).
const MAX_NATIVE_ORDER: u64 = 5000;

/// `(1 + a)(1 + b)(1 + c) - 1 <= s (1 + s)`, `s = a + b + c <= 1`.
#[inline]
fn compose(a: f64, b: f64, c: f64) -> f64 {
    let s = a + b + c;
    s * (1.0 + s)
}

/// `1/k!` for `k <= MAX_TABLE_FACTORIAL` as double-doubles, rounded from 256-bit
/// MPFR values (`hi` nearest, `lo` nearest to the rest: relative error `<= 2 u^2`).
pub(crate) const MAX_TABLE_FACTORIAL: u64 = 170;
/// Relative error of a table entry.
pub(crate) const TABLE_ETA: f64 = 2.0 * U2;

pub(crate) fn inv_factorials() -> &'static [Dd] {
    static TABLE: std::sync::OnceLock<Vec<Dd>> = std::sync::OnceLock::new();
    TABLE.get_or_init(|| {
        (0..=MAX_TABLE_FACTORIAL as u32)
            .map(|k| {
                let f = rug::Float::with_val(256, rug::Float::factorial(k)).recip();
                let hi = f.to_f64();
                let lo = rug::Float::with_val(256, &f - hi).to_f64();
                Dd { hi, lo }
            })
            .collect()
    })
}

/// `(x/2)^n / n!` and its relative error bound: binary powering and the
/// table for `n <= 170`, else the running product `prod (x/2)/j`.
#[inline(always)]
fn prefactor<P: ExactProduct>(n: u64, half: f64) -> Option<(Dd, f64)> {
    if n <= MAX_TABLE_FACTORIAL {
        let (mut acc, mut eta_acc) = (Dd::ONE, 0.0f64);
        let (mut base, mut eta_base) = (Dd::from_f64(half), 0.0f64);
        let mut e = n;
        while e > 0 {
            if e & 1 == 1 {
                acc = acc.mul_p::<P>(base);
                eta_acc = compose(eta_acc, eta_base, 8.0 * U2);
            }
            e >>= 1;
            if e > 0 {
                base = base.mul_p::<P>(base);
                eta_base = compose(eta_base, eta_base, 8.0 * U2);
            }
        }
        if !acc.hi.is_finite() || acc.hi == 0.0 {
            return None;
        }
        let p = acc.mul_p::<P>(inv_factorials()[n as usize]);
        return Some((p, compose(eta_acc, TABLE_ETA, 8.0 * U2)));
    }
    let mut p = Dd::ONE;
    let mut eta_p = 0.0f64;
    for j in 1..=n {
        p = div_f64_p::<P>(p.mul_f64_p::<P>(half), j as f64);
        eta_p = eta_p * (1.0 + C_STEP) + C_STEP;
    }
    Some((p, eta_p))
}

/// The series in double-double with its proven bound, `x > 0`; `None` where it
/// cannot run (prefactor underflow, terms out of range) — the caller then
/// falls back to MP.
#[inline(always)]
pub(crate) fn series_bounded<P: ExactProduct>(n: u64, x: f64) -> Option<Bounded> {
    if !(x > 0.0) || n > MAX_NATIVE_ORDER {
        return None;
    }
    let (p, eta_p) = prefactor::<P>(n, x / 2.0)?;
    if !(p.hi.abs() > 1e-280) || !p.hi.is_finite() {
        return None;
    }
    let xx = Dd::prod_p::<P>(x, x); // exact
    let z = Dd { hi: -xx.hi / 4.0, lo: -xx.lo / 4.0 };
    let z_abs = mag(z);
    let mut t = Dd::ONE;
    let mut s = Dd::ONE;
    let mut eta = 0.0f64;
    let mut err = 0.0f64;
    let mut k: u64 = 0;
    let tail = loop {
        let d = ((k + 1) * (n + k + 1)) as f64; // exact below 2^53
        // the ratio z/d does not depend on t: off the dependency chain
        t = t.mul_p::<P>(div_f64_p::<P>(z, d));
        eta = eta * (1.0 + C_STEP) + C_STEP;
        k += 1;
        let t_abs = mag(t);
        if !t_abs.is_finite() {
            return None;
        }
        let t_up = t_abs * (1.0 + eta);
        let next_d = ((k + 1) * (n + k + 1)) as f64;
        if z_abs <= 0.5 * next_d && t_up <= TAIL_REL * mag(s) {
            break 2.0 * t_up;
        }
        let s_prev = mag(s);
        s = s + t;
        err += eta * t_abs + C_ADD * (s_prev + t_abs);
        if k > 100_000 {
            return None;
        }
    };
    let e_s = err + tail;
    let s_abs = mag(s);
    let p_abs = mag(p);
    let e_p = eta_p * p_abs;
    let v = p.mul_p::<P>(s);
    let value = v.hi + v.lo;
    if !value.is_finite() || value == 0.0 {
        return None;
    }
    let e = p_abs * e_s + s_abs * e_p + e_p * e_s + 8.0 * U2 * p_abs * s_abs + U * value.abs();
    let e = (e * BOUND_INFLATION).next_up();
    Some(Bounded { value, err: e })
}
