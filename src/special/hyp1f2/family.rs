//! The model family `F_k = 1F2(1/2; k+1, k+3/2; z)` for every `k = 0..=kmax` at
//! one `z`, in f64 with proven bounds ([`hyp1f2_model_family_f64`]).
//!
//! # Method
//!
//! `F_k = Phi(2k+1)`, `Phi(m) = 1F2(1/2; (m+1)/2, (m+2)/2; z)` (see
//! [`super::hyp1f2::hyp1f2_model_family`]), and the four-term recurrence of the MP
//! family, run downward in double words ([`BoundedDd`], whose running bound is
//! the error analysis; `src/ball/dd_bounded.rs`):
//!
//! ```text
//! Phi(m) = Phi(m+1) + 4 z (Phi(m+2)/(m+2) - Phi(m+3)/(m+3)) / (m+1)
//! ```
//!
//! (`4 z` exact). Start: `Phi(M..M+3)`, `M = 2 kmax + 1`, by the double-word
//! series of [`super::dd`]. The recurrence loses accuracy where the
//! family cancels (small `m` against large `|z|`: about `3.3 * 2 sqrt|z|` bits
//! down to `m = 0`, measured in MP); the running bound shows it, and the
//! recurrence stops as soon as a value's bound exceeds `2^-60` relative (the
//! bound grows by about `1 + 8|z|/m^2` per step, as it credits no cancellation:
//! it reaches `k = 0` for `|z| <= 9`, `k = 21` at `z = -100`, `k = 258` at
//! `z = -1225`). The
//! remaining small `k`, and any value whose rounded bound is not `1e-14`
//! relative, are evaluated per `k` by [`super::hyp1f2::hyp1f2_bounded`] (f64
//! series, double-word series, Bessel route, then MP), so every returned bound is proven and
//! `1e-14` relative.

use crate::ball::cpu_dispatch;
use crate::ball::{Bounded, BoundedDd, ExactProduct};
use crate::error::{Error, Result};
use super::{hyp1f2_bounded, NATIVE_REL_TOL};
use super::dd::hyp1f2_series_dd;

/// Largest relative bound a recurrence value may carry before the recurrence
/// stops (`2^-60`).
const RECURRENCE_MAX_REL: f64 = 8.673617379884035e-19;

/// Largest `kmax` accepted (the recurrence stores `2 kmax + 4` values).
pub const FAMILY_MAX_K: u32 = 1_000_000;

/// `F_k = 1F2(1/2; k+1, k+3/2; z)` for `k = 0..=kmax`, each in f64 with a proven
/// bound `|F_k - value| <= err <= 1e-14 |value|` for the f64 `z` as given (the
/// model's `z = -s^2`; any finite `z` is accepted). Method in the module docs.
///
/// # Errors
/// [`Error::NonFinite`] for a NaN or infinite `z`; [`Error::IntegerOutOfRange`]
/// for `kmax > FAMILY_MAX_K`.
pub fn hyp1f2_model_family_f64(kmax: u32, z: f64) -> Result<Vec<Bounded>> {
    crate::error::finite(z, "z")?;
    if kmax > FAMILY_MAX_K {
        return Err(Error::IntegerOutOfRange { arg: "kmax", value: kmax as i64, min: 0, max: FAMILY_MAX_K as i64 });
    }
    let swept = phi_downward(kmax, z);
    (0..=kmax)
        .map(|k| {
            let m = 2 * k as usize + 1;
            let native = swept.get(m).copied().flatten().and_then(|v| v.finish());
            match native {
                Some(b) if b.value.is_finite() && b.err <= NATIVE_REL_TOL * b.value.abs() => Ok(b),
                _ => {
                    let kf = k as f64;
                    hyp1f2_bounded(0.5, kf + 1.0, kf + 1.5, z)
                }
            }
        })
        .collect()
}

cpu_dispatch! {
    /// `Phi(m)` for `m = 0..=2 kmax + 4` by the downward recurrence; `None` below the
    /// index where the recurrence stopped (or everywhere if a start value failed).
    /// Exact products by fused multiply-add where the CPU has it (bit-identical).
    pub(crate) fn phi_downward(kmax: u32, z: f64) -> Vec<Option<BoundedDd>> => phi_with
}

#[inline(always)]
fn phi_with<P: ExactProduct>(kmax: u32, z: f64) -> Vec<Option<BoundedDd>> {
    let top = 2 * kmax as usize + 1;
    let mut phi: Vec<Option<BoundedDd>> = vec![None; top + 4];
    for m in top..top + 4 {
        let mf = m as f64;
        match hyp1f2_series_dd(0.5, 0.5 * (mf + 1.0), 0.5 * (mf + 2.0), z) {
            Some(v) => phi[m] = Some(v),
            None => return phi,
        }
    }
    let four_z = 4.0 * z;
    for m in (0..top).rev() {
        let (p1, p2, p3) = match (phi[m + 1], phi[m + 2], phi[m + 3]) {
            (Some(a), Some(b), Some(c)) => (a, b, c),
            _ => break,
        };
        let mf = m as f64;
        let bracket = p2.div_f64_p::<P>(mf + 2.0).sub(p3.div_f64_p::<P>(mf + 3.0));
        let v = p1.add(bracket.mul_f64_p::<P>(four_z).div_f64_p::<P>(mf + 1.0));
        if !(v.e <= RECURRENCE_MAX_REL * v.mag()) {
            break;
        }
        phi[m] = Some(v);
    }
    phi
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::special::hyp1f2::hyp1f2_mp_f64;
    use rug::Float;

    #[test]
    fn family_matches_the_certified_values() {
        for &s in &[0.0f64, 1e-3, 0.5, 3.0, 10.0, 23.304_422_833_564_544, 35.0] {
            let z = -s * s;
            let fam = hyp1f2_model_family_f64(1000, z).unwrap();
            assert_eq!(fam.len(), 1001);
            for k in (0..=1000u32).filter(|k| k % 53 == 0 || *k <= 8 || *k >= 998) {
                let kf = k as f64;
                let reference = hyp1f2_mp_f64(0.5, kf + 1.0, kf + 1.5, z, 200).unwrap();
                let b = fam[k as usize];
                let d = Float::with_val(300, reference.mid() - b.value).abs();
                assert!(d <= b.err, "s={s} k={k}: {b} vs {reference:?}");
                assert!(b.err <= 1e-14 * b.value.abs(), "s={s} k={k}: {b}");
            }
        }
    }

    #[test]
    fn recurrence_reaches_down_to_where_the_family_cancels() {
        // The running bound of the recurrence grows by about (1 + 8|z|/m^2) per step
        // (absolute values, no cancellation credited), so at large |z| it stops early:
        // measured m = 0 at s <= 3, m = 42 at s = 10, m = 517 (k = 258) at s = 35; below
        // that the per-k paths take over.
        for &(s, must_reach_zero) in &[(0.5f64, true), (3.0, true), (10.0, false), (35.0, false)] {
            let phi = phi_downward(1000, -s * s);
            let lowest = phi.iter().position(|v| v.is_some()).unwrap();
            eprintln!("s={s}: recurrence reaches m = {lowest}");
            assert!(!must_reach_zero || lowest == 0, "s={s}: stopped at m = {lowest}");
            assert!(lowest <= 600, "s={s}: stopped at m = {lowest}");
        }
    }

    #[test]
    fn bad_input() {
        assert!(hyp1f2_model_family_f64(3, f64::NAN).is_err());
        assert!(hyp1f2_model_family_f64(3, f64::NEG_INFINITY).is_err());
        assert!(hyp1f2_model_family_f64(FAMILY_MAX_K + 1, -1.0).is_err());
        assert_eq!(hyp1f2_model_family_f64(0, -4.0).unwrap().len(), 1);
    }

    #[test]
    fn fused_and_portable_recurrences_agree_bit_for_bit() {
        for &z in &[-0.25f64, -9.0, -100.0, -1225.0] {
            let (a, b) = (phi_downward(300, z), phi_with::<crate::ball::Dekker>(300, z));
            for (x, y) in a.iter().zip(b.iter()) {
                assert_eq!(x.map(|v| (v.v.hi, v.v.lo, v.e)), y.map(|v| (v.v.hi, v.v.lo, v.e)), "z={z}");
            }
        }
    }
}
