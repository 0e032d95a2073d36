//! The native f64 layer of `J_n(x)`: which double-double method runs where,
//! each with a **proven** error bound.
//!
//! # Regions (`n >= 0`, `x > 0`; [`choose_native`])
//!
//! * **Forward recurrence** (`native_recurrence.rs`) for `n + 1 <= x` and
//!   `x >= 25`, from `J_0`, `J_1` by Hankel's expansion (`native_hankel.rs`).
//!   Absolute error about `1e-24 sqrt(x/(x - n))`; the relative bound is
//!   large only next to a zero of `J_n`.
//! * **Power series** (`native_series.rs`) elsewhere: `x < 25` (at most
//!   ~36 bits cancel) or `n + 1 > x` (the terms barely cancel: about
//!   `0.77 n` bits at `n = x`, 46 bits at `n = 60`). It is tried where the
//!   estimated cancellation is at most `MAX_NATIVE_LOSS_BITS`.
//!
//! Every exact product (Dekker's `two_prod`) is a fused multiply-add where the
//! CPU has one (x86-64 `fma`, detected once at run time; the methods are then
//! compiled with that target feature): both are exact, so values and bounds are
//! bit-identical (tests/bessel_f64.rs checks this), only about 1.3x faster.
//!
//! The callers ([`super::bessel_j`], [`super::bessel_j_bounded`]) accept the
//! result when its proven relative bound meets their tolerance and otherwise
//! fall back to the certified MP value, counted by [`super::bessel_j_fallbacks`]:
//! next to zeros of `J_n`, past the orders and arguments above
//! (`n > 10^4` on the recurrence, `x > 2^40`), and where the series' prefactor
//! underflows.

use crate::ball::cpu_dispatch;
use crate::ball::{Bounded, Dekker, ExactProduct};

use super::native_hankel::{bessel_j01, HANKEL_MAX_X, HANKEL_MIN_X};
use super::native_recurrence::{forward, MAX_RECURRENCE_ORDER};
use super::native_series::{series_bounded, MAX_NATIVE_LOSS_BITS};

/// The native methods.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[non_exhaustive]
pub enum NativeMethod {
    /// Forward recurrence from Hankel's `J_0`, `J_1`.
    Recurrence,
    /// Power series.
    Series,
    /// Neither certifies here: the MP path.
    Mp,
}

/// Picks the native method for `n >= 0`, `x > 0` (module docs).
pub fn choose_native(n: u64, x: f64) -> NativeMethod {
    if (HANKEL_MIN_X..=HANKEL_MAX_X).contains(&x) && (n + 1) as f64 <= x && n <= MAX_RECURRENCE_ORDER {
        NativeMethod::Recurrence
    } else if super::series_loss_bits(n, x) <= MAX_NATIVE_LOSS_BITS {
        NativeMethod::Series
    } else {
        NativeMethod::Mp
    }
}

cpu_dispatch! {
    /// `J_n(x)` by one native method, with its proven bound (`None` where it
    /// cannot run; tests call each method on its own). Exact products use the
    /// CPU's fused multiply-add where it has one (detected once at run time),
    /// else Dekker's splitting; both are exact, so the results are bit-identical.
    pub fn bessel_j_native(method: NativeMethod, n: u64, x: f64) -> Option<Bounded> => native_with
}

/// [`bessel_j_native`] with Dekker's exact products on every CPU (tests
/// compare it with the fused path bit for bit).
pub fn bessel_j_native_portable(method: NativeMethod, n: u64, x: f64) -> Option<Bounded> {
    native_with::<Dekker>(method, n, x)
}

#[inline(always)]
fn native_with<P: ExactProduct>(method: NativeMethod, n: u64, x: f64) -> Option<Bounded> {
    match method {
        NativeMethod::Recurrence => {
            let (j0, j1) = bessel_j01::<P>(x)?;
            forward::<P>(n, x, j0, j1)?.finish()
        }
        NativeMethod::Series => series_bounded::<P>(n, x),
        NativeMethod::Mp => None,
    }
}
