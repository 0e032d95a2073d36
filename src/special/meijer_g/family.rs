//! `G(k, y)` for every `k = 0..=kmax` at one `y`, in f64 with proven bounds
//! ([`meijer_g_k_family_f64`]): the sums over `k` of Eq. 12 in a solver's sweep.
//!
//! # Method
//!
//! The recurrences of [`super::direct_sums_sweep`], run in double words
//! ([`BoundedDd`], whose running bound is the error analysis: every operation
//! is charged `8-16 u^2` of its operands, `u = 2^-53`, see
//! `src/ball/dd_bounded.rs`). With `H_k = 2F1(1, k+1/2; k+3; y)`:
//!
//! ```text
//! H_k     = 1 + ((2k+1)/(2k+6)) y H_{k+1}            (downward; contracts by y (2k+1)/(2k+6) < 1)
//! S_{k+1} = S_k + 3 y H_{k+1} / ((2k+6)(k+2))        (upward; positive increments)
//! G(k, y) = C_k (-ln y - S_k + P_k)/2
//! ```
//!
//! (the increment is `3 (H_k - 1)/((2k+1)(k+2))` with `H_k - 1` replaced by its
//! exact value, so nothing cancels). Both directions are stable: the downward
//! one damps the error of `H_kmax` by the contraction factor, the upward one
//! adds positive terms, so the relative error of `S_k` grows by at most a few
//! `u^2` per step. The start values dominate the bound: `~1e-30` for
//! `y <= 0.97`; near one the connection formula for `H_kmax` cancels by about
//! `e^{kmax w}` (bounds up to `~1e-22` at `w = 0.02`, `kmax = 1000`). The start values:
//!
//! * `0 < y <= Y_NATIVE_MAX` (`y >= Y_DD_MIN`): `S_0` by the double-word direct
//!   series, `H_kmax` by its series (positive terms, ratio `<= y`, tail
//!   `t_N y/(1-y)`), both stopped at `2^-104` relative.
//! * `Y_NATIVE_MAX < y < 1`: `S_0 = -ln y + P_0 - 2 G(0, y)/C_0` from the
//!   double-word near-one expansion of `G(0, .)`; `H_kmax` by the `1-z`
//!   connection formula [DLMF 15.8.4] as in [`super::near_one_sums_sweep`]:
//!   `H_K = (2(K+2)/3) 2F1(1, K+1/2; -1/2; w) + (4 sqrt(pi)/3) ((K+2)/C_K) w^{3/2} y^{-K-2}`
//!   (with `2 sqrt(pi)` from the table: `(8 sqrt(pi)/3) = (4/3) (2 sqrt(pi))`); the
//!   series has ratio `w (2K+1+2n)/(2n-1)`, decreasing for `n >= 1`, so its tail
//!   is `|t_N|/(1 - ratio_N)` once that ratio is below 1; `y^{K+2}` by binary
//!   powering of the exact `y`.
//! * `y = 1`: `G(k, 1) = C_k B_k(1)` from the table.
//!
//! Each value is rounded to f64 with its bound; where that bound is not
//! `1e-14` relative (the f64 `y` next to a zero of `G(k, .)`, `y < Y_DD_MIN`,
//! `k > 1000`) the per-`k` [`super::meijer_g_k_bounded`] takes over
//! for that `k` (its own native paths, then MP), so every returned bound is
//! `1e-14` relative and proven.
//!
//! Cost: `~8` double-word operations per `k` (`~0.1 us`) plus the two start
//! series (`~ 75/(-ln y)` terms each, or `~k w + 40` near one).

use crate::ball::cpu_dispatch;
use crate::ball::{BoundedDd, Bounded, ExactProduct};
use crate::error::{Error, Interval, Result};
use super::dd::{ln_dd, near_one_dd, s_dd, DdConstants, Y_DD_MIN};
use super::native::{dd_constants, TABLE_K_MAX};
use super::{meijer_g_k_bounded, MAX_K, NATIVE_REL_TOL, Y_NATIVE_MAX};

/// Tail bound of the start series relative to their sums (`2^-104`).
const TAIL_REL: f64 = 4.930380657631324e-32;

/// Cap on the terms of a start series.
const MAX_TERMS: u64 = 20_000;

/// `G(k, y)` for `k = 0..=kmax`, each in f64 with a proven bound
/// `|G(k, y) - value| <= err <= 1e-14 |value|` (see the module docs for the
/// method). `0 < y <= 1`, `kmax <= MAX_K` of [`super`].
///
/// # Errors
/// [`Error::NonFinite`] for a NaN or infinite `y`; [`Error::OutOfRange`] for `y`
/// outside `(0, 1]`; [`Error::IntegerOutOfRange`] for `kmax` above the supported maximum.
pub fn meijer_g_k_family_f64(kmax: u32, y: f64) -> Result<Vec<Bounded>> {
    crate::error::finite(y, "y")?;
    if !(y > 0.0 && y <= 1.0) {
        return Err(Error::OutOfRange { arg: "y (= (a/x)^2 with x >= a)", value: y, allowed: Interval::left_open(0.0, 1.0) });
    }
    if kmax > MAX_K {
        let max = MAX_K as i64;
        return Err(Error::IntegerOutOfRange { arg: "kmax", value: kmax as i64, min: 0, max });
    }
    let top = kmax.min(TABLE_K_MAX);
    let swept = family_dd(top, y);
    let mut out = Vec::with_capacity(kmax as usize + 1);
    for k in 0..=kmax {
        let native = swept.as_ref().and_then(|v| v.get(k as usize)).and_then(|g| g.finish());
        match native {
            // G(1, 1) = 0 exactly
            _ if k == 1 && y == 1.0 => out.push(Bounded { value: 0.0, err: 0.0 }),
            Some(b) if b.value.is_finite() && b.err <= NATIVE_REL_TOL * b.value.abs() => out.push(b),
            _ => out.push(meijer_g_k_bounded(k, y)?),
        }
    }
    Ok(out)
}

cpu_dispatch! {
    /// The swept family in double words for `k = 0..=top` (`top <= TABLE_K_MAX`), or
    /// `None` where the start values are not available (`y < Y_DD_MIN`).
    pub(crate) fn family_dd(top: u32, y: f64) -> Option<Vec<BoundedDd>> => family_with
}

#[inline(always)]
fn family_with<P: ExactProduct>(top: u32, y: f64) -> Option<Vec<BoundedDd>> {
    if top > TABLE_K_MAX {
        return None;
    }
    let consts: Vec<DdConstants> = (0..=top).map(dd_constants).collect::<Option<_>>()?;
    if y == 1.0 {
        return Some(consts.iter().map(|c| c.c.mul_p::<P>(c.b1)).collect());
    }
    if !(y >= Y_DD_MIN && y < 1.0) {
        return None;
    }
    let l = ln_dd::<P>(y, consts[0].ln2)?;
    let (s0, h_top) = if y <= Y_NATIVE_MAX {
        (s_dd::<P>(0, y)?, h_series::<P>(top, y)?)
    } else {
        let w = 1.0 - y; // exact (Sterbenz)
        let c0 = &consts[0];
        let b0 = near_one_dd::<P>(0, w, c0)?.div(c0.c)?;
        let s0 = l.neg().add(c0.p).sub(b0.mul_f64_p::<P>(2.0));
        (s0, h_connection::<P>(top, y, w, &consts[top as usize])?)
    };
    // H downward
    let n = top as usize;
    let mut h = vec![BoundedDd::ZERO; n + 1];
    h[n] = h_top;
    for k in (0..n).rev() {
        let kf = k as f64;
        h[k] = h[k + 1].mul_f64_p::<P>(y).mul_f64_p::<P>(2.0 * kf + 1.0).div_f64_p::<P>(2.0 * kf + 6.0).add(BoundedDd::ONE);
    }
    // S upward and G
    let mut out = Vec::with_capacity(n + 1);
    let mut s = s0;
    for k in 0..=n {
        let c = &consts[k];
        let b = l.neg().sub(s).add(c.p).mul_f64_p::<P>(0.5);
        out.push(c.c.mul_p::<P>(b));
        if k < n {
            let kf = k as f64;
            let inc = h[k + 1].mul_f64_p::<P>(y).mul_f64_p::<P>(3.0).div_f64_p::<P>((2.0 * kf + 6.0) * (kf + 2.0));
            s = s.add(inc);
        }
    }
    Some(out)
}

/// `H_K = 2F1(1, K+1/2; K+3; y)` by its series (`y <= Y_NATIVE_MAX`): terms
/// `t_{n+1} = t_n y (2K+1+2n)/(2K+6+2n)`, positive with ratio `<= y`.
#[inline(always)]
fn h_series<P: ExactProduct>(top: u32, y: f64) -> Option<BoundedDd> {
    let kf = top as f64;
    let one_minus_y = 1.0 - y; // y >= 1/2: exact; y < 1/2: at least 1/2, rounding covered below
    let mut t = BoundedDd::ONE;
    let mut s = BoundedDd::ONE;
    let mut n = 0u64;
    loop {
        let nf = n as f64;
        t = t.mul_f64_p::<P>(y).mul_f64_p::<P>(2.0 * kf + 1.0 + 2.0 * nf).div_f64_p::<P>(2.0 * kf + 6.0 + 2.0 * nf);
        n += 1;
        // tail from this term on: t_n/(1-y)
        let tail = (t.mag() + t.e) / one_minus_y * (1.0 + 8.0 * crate::ball::U);
        if tail <= TAIL_REL * s.mag() {
            s.e += tail;
            return Some(s);
        }
        s = s.add(t);
        if n > MAX_TERMS {
            return None;
        }
    }
}

/// `H_K` near `y = 1` by the connection formula (module docs), `w = 1 - y` exact.
#[inline(always)]
fn h_connection<P: ExactProduct>(top: u32, y: f64, w: f64, c: &DdConstants) -> Option<BoundedDd> {
    let kf = top as f64;
    let up = 1.0 + 8.0 * crate::ball::U;
    // F = 2F1(1, K+1/2; -1/2; w) = sum_n t_n, t_{n+1} = t_n w (2K+1+2n)/(2n-1)
    let mut t = BoundedDd::ONE;
    let mut f = BoundedDd::ONE;
    let mut n = 0u64;
    loop {
        let nf = n as f64;
        t = t.mul_f64_p::<P>(w).mul_f64_p::<P>(2.0 * kf + 1.0 + 2.0 * nf).div_f64_p::<P>(2.0 * nf - 1.0);
        n += 1;
        let nf = n as f64;
        let ratio = w * (2.0 * kf + 1.0 + 2.0 * nf) / (2.0 * nf - 1.0) * up;
        if ratio < 1.0 {
            let tail = (t.mag() + t.e) / (1.0 - ratio) * up;
            if tail <= TAIL_REL * f.mag() {
                f.e += tail;
                break;
            }
        }
        f = f.add(t);
        if n > MAX_TERMS {
            return None;
        }
    }
    // y^{K+2} by binary powering of the exact y
    let mut e = top as u64 + 2;
    let mut base = BoundedDd::exact(y);
    let mut pow = BoundedDd::ONE;
    while e > 0 {
        if e & 1 == 1 {
            pow = pow.mul_p::<P>(base);
        }
        e >>= 1;
        if e > 0 {
            base = base.mul_p::<P>(base);
        }
    }
    let w32 = BoundedDd::exact(w).sqrt_p::<P>()?.mul_f64_p::<P>(w);
    let second = c.two_sqrt_pi.mul_f64_p::<P>(4.0 * (kf + 2.0)).mul_p::<P>(w32).div(c.c.mul_p::<P>(pow).mul_f64_p::<P>(3.0))?;
    Some(f.mul_f64_p::<P>(2.0 * (kf + 2.0)).div_f64_p::<P>(3.0).add(second))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::special::exact;
    use crate::special::meijer_g::meijer_g_k_mp;
    use rug::Float;

    #[test]
    fn family_matches_the_certified_values() {
        let eps = f64::EPSILON;
        for &y in &[1e-300, 1e-4, 0.03125, 0.25, 0.5, 0.5007496256836826, 0.75, 0.9, 0.97, 0.975, 0.99, 0.999, 1.0 - 1e-9, 1.0 - eps, 1.0] {
            let fam = meijer_g_k_family_f64(1000, y).unwrap();
            assert_eq!(fam.len(), 1001);
            for k in (0..=1000u32).filter(|k| k % 37 == 0 || *k <= 3 || *k >= 998) {
                let b = fam[k as usize];
                let reference = meijer_g_k_mp(k, &exact(y), 200).unwrap();
                let d = Float::with_val(300, reference.mid() - b.value).abs();
                assert!(d <= b.err, "y={y} k={k}: {b} vs {reference:?}");
                assert!(b.err <= 1e-14 * b.value.abs() || b.value == 0.0, "y={y} k={k}: {b}");
            }
        }
    }

    #[test]
    fn swept_values_agree_with_the_per_k_dd_paths() {
        // the recurrence loses nothing measurable: the swept double words agree with
        // the per-k double-word values (both bounds hold); the bound stays far below
        // f64 resolution (near one the connection formula for H_kmax cancels by ~e^{k w})
        for &y in &[0.25, 0.6377620640075394, 0.9, 0.98, 1.0 - 1e-6] {
            let fam = family_dd(1000, y).unwrap();
            for k in [0u32, 1, 2, 5, 100, 999, 1000] {
                let c = dd_constants(k).unwrap();
                let per_k = crate::special::meijer_g::dd::meijer_g_k_dd(k, y, &c).unwrap();
                let a = fam[k as usize];
                let diff = ((a.v.hi - per_k.v.hi) + (a.v.lo - per_k.v.lo)).abs();
                assert!(diff <= a.e + per_k.e, "y={y} k={k}: {a:?} vs {per_k:?}");
                assert!(a.e <= 1e-20 * (1.0 + a.mag()), "y={y} k={k}: bound {}", a.e);
            }
        }
    }

    #[test]
    fn bad_input_and_large_kmax() {
        assert!(meijer_g_k_family_f64(5, 0.0).is_err());
        assert!(meijer_g_k_family_f64(5, 1.5).is_err());
        assert!(meijer_g_k_family_f64(5, f64::NAN).is_err());
        assert!(meijer_g_k_family_f64(5, f64::INFINITY).is_err());
        assert!(meijer_g_k_family_f64(MAX_K + 1, 0.5).is_err());
        let fam = meijer_g_k_family_f64(1003, 0.5).unwrap();
        let b = fam[1003];
        let reference = meijer_g_k_mp(1003, &exact(0.5), 200).unwrap();
        assert!(Float::with_val(300, reference.mid() - b.value).abs() <= b.err);
    }
}
