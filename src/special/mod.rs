//! Special functions, one file per function, arbitrary precision and f64 side by side.
//!
//! | function | MP (certified ball) | f64 |
//! |---|---|---|
//! | [`bessel_j`](bessel_j::bessel_j) | [`bessel_j_mp`](bessel_j::bessel_j_mp) | power series / MP fallback |
//! | [`hyp_pfq`](pfq::hyp_pfq) | [`hyp_pfq_mp`](pfq::hyp_pfq_mp) | series with a-priori error estimate / MP fallback |
//! | [`hyp1f2`](hyp1f2::hyp1f2) | [`hyp1f2_mp`](hyp1f2::hyp1f2_mp) | pFq core |
//! | [`hyp2f1`](hyp2f1::hyp2f1) | [`hyp2f1_mp`](hyp2f1::hyp2f1_mp) | transformations + pFq core |
//! | [`meijer_g_k`](meijer_g::meijer_g_k) | [`meijer_g_k_mp`](meijer_g::meijer_g_k_mp) | closed form / MP fallback |
//!
//! # Public surface
//!
//! Per function: the f64 value (`f`), the f64 value with a proven bound
//! (`f_bounded`, a [`Bounded`]) and the certified ball (`f_mp`), plus
//! [`hyp_pfq`](pfq::hyp_pfq)/[`hyp_pfq_mp`](pfq::hyp_pfq_mp), [`exact`] (an f64
//! as an exact `Float` argument) and the constants [`F64_FALLBACK_PREC`] and
//! [`F64_TRUST`](pfq::F64_TRUST). Everything else (the Ziv driver, the series
//! engines, the per-method `2F1` entry points, Gamma and magnitude helpers in
//! `gamma.rs`) is crate-internal, so that it can change without breaking users;
//! the unit tests next to each file compare the methods where they overlap.
//!
//! The names mean the same everywhere:
//!
//! | name | inputs | precision argument | returns |
//! |---|---|---|---|
//! | `f` | f64 | none | f64 (an estimate within the documented tolerance) |
//! | `f_bounded` | f64 | none | [`Bounded`]: value and a proven error bound |
//! | `f_native_bounded` | f64 | a relative tolerance | `Result<Option<Bounded>>`: the native f64 path alone, `None` where it does not certify the tolerance |
//! | `f_mp` | exact binary `Float`s | output precision `prec` | a [`Ball`] with `rad <= 2^-prec |mid|` (Ziv loop) |
//! | `f_ball_mp` | [`Ball`]s (a decimal is a ball) | output precision `prec` | a [`Ball`] containing `f` over the input balls |
//! | `f_<method>` (e.g. `bessel_j_series`, `meijer_g_k_direct_ball`) | `Float`s, or `Ball`s where the name ends in `_ball` | working precision `wp` | a [`Ball`] from that one method at `wp`, whatever accuracy it reached (no Ziv loop) |
//!
//! Every function that takes a precision checks it: `prec` against
//! [`crate::MAX_PREC`], `wp` against [`MAX_WORKING_PREC`] (and both `>= 2`),
//! with [`Error::Precision`]; `tests/precision_edges.rs` calls each one at 0, 1
//! and beyond the cap.
//!
//! # Precision policy (Ziv)
//!
//! Every `*_mp` function takes an output precision `prec` (bits) and returns a
//! [`Ball`] that contains the exact value of the function at the given binary
//! inputs, with `rad <= 2^-prec |mid|` (an exact zero is returned as `[0 ± 0]`).
//! It evaluates at a working precision `prec + guard`, checks the achieved
//! relative accuracy, and when it falls short raises the guard by the number of
//! bits the evaluation lost (plus margin), at least doubling it, until
//! [`MAX_WORKING_PREC`] is reached; then it returns
//! [`Error::PrecisionExhausted`]. It never returns a wide ball silently.
//!
//! # f64 policy
//!
//! Every f64 function first runs a fast f64 algorithm that also produces a
//! running error estimate (a-priori rounding analysis plus a tail bound). If
//! the estimate does not meet the function's documented tolerance (for
//! example because a sum of |terms| reveals cancellation), it falls back to the
//! MP path at [`F64_FALLBACK_PREC`] bits and rounds the certified midpoint,
//! which is then within one ulp. The fallback's Ziv loop stops at
//! [`F64_FALLBACK_MAX_WP`] working bits ([`Error::PrecisionExhausted`]): an f64
//! call answers in bounded time or says why not; the `*_mp` functions remain for
//! arguments that need more. Fallbacks are counted per route, in one place:
//! [`fallback_counts`] returns a snapshot of every counter ([`FallbackCounts`]:
//! `bessel_j`, `hyp1f2`, `hyp2f1`, `meijer_g_k`, `wave_bounded`,
//! `wave_bounded_mp_contacts`); subtract two snapshots with
//! [`FallbackCounts::since`]. (The older per-function readers such as
//! `bessel_j_fallbacks` are deprecated aliases of its fields.)
//!
//! # Enums
//!
//! Method and algorithm enums are `#[non_exhaustive]` (methods get added); the
//! closed classifications (`registry::Arg`, `error::ParamKind`, the contact's
//! `Control`, `JumpDirection`, `TurningKind`, `Regime`, `SweepAxis`) are not.

pub mod bessel_j;
pub(crate) mod gamma;
pub mod hyp1f2;
pub mod hyp2f1;
pub mod meijer_g;
pub mod pfq;
pub mod fallback;

pub use fallback::{fallback_counts, F64Route, FallbackCounts};

use rug::float::Round;
use rug::ops::{AddAssignRound, AssignRound};
use rug::Float;

use crate::ball::{Ball, Bounded};
use crate::error::{Error, Reached, Result};
use crate::MAX_WORKING_PREC;

/// Checks the relative tolerance of an `f_native_bounded` call: positive and finite.
pub(crate) fn check_rel_tol(rel_tol: f64) -> Result<()> {
    if rel_tol.is_finite() && rel_tol > 0.0 {
        Ok(())
    } else {
        Err(Error::OutOfRange { arg: "rel_tol (relative tolerance of the native path)", value: rel_tol, allowed: crate::error::Interval::above(0.0) })
    }
}

/// Output precision of the MP fallback used by the f64 functions: 11 bits more
/// than a double, so the rounded midpoint is within `0.5 + 2^-11` ulp.
pub const F64_FALLBACK_PREC: u32 = 64;

/// Largest working precision of the MP fallback behind the f64 functions. An f64
/// answer that cannot be certified below it (more than about 4000 bits of
/// cancellation: parameters like `1e300`, where the fallback used to climb to
/// 65 536 bits and beyond for minutes) is refused with
/// [`Error::PrecisionExhausted`] naming this precision; the `*_mp` functions,
/// which climb to [`MAX_WORKING_PREC`], remain for such arguments.
pub const F64_FALLBACK_MAX_WP: u32 = 4096;

/// Initial guard bits of the Ziv loop when a function gives no better estimate.
pub(crate) const DEFAULT_GUARD_BITS: u32 = 24;

/// Runs `eval(working_prec)` with rising working precision until the ball meets
/// `rad <= 2^-prec |mid|`.
///
/// `guard` is the first guess of the extra bits needed (for example the
/// cancellation estimate of a series). The loop adds at least the bits the
/// previous attempt lost and at least doubles the guard each round.
///
/// This is the internal driver: it accepts any `prec` up to
/// [`MAX_WORKING_PREC`]; public functions check the user's precision with
/// `check_prec` first.
pub(crate) fn ziv<F>(function: &'static str, prec: u32, guard: u32, eval: F) -> Result<Ball>
where
    F: FnMut(u32) -> Result<Ball>,
{
    ziv_with_floor(function, prec, guard, None, eval)
}

/// [`ziv`] with an absolute floor: also accepts `rad <= 2^-prec * floor`.
///
/// Used where the function has a natural scale and may vanish at exact inputs
/// (for example `u_w(a) = A (1 - cos(2 pi a/zeta))` is exactly zero when `a/zeta`
/// is an integer): the accuracy promise there is relative to `max(|value|, floor)`.
pub(crate) fn ziv_with_floor<F>(function: &'static str, prec: u32, guard: u32, floor: Option<&Float>, eval: F) -> Result<Ball>
where
    F: FnMut(u32) -> Result<Ball>,
{
    ziv_up_to(function, prec, guard, floor, MAX_WORKING_PREC, eval)
}

/// [`ziv_with_floor`] with the working precision capped at `max_wp`
/// (`prec <= max_wp <= MAX_WORKING_PREC`): [`Error::PrecisionExhausted`] once an
/// evaluation at `max_wp` does not meet the accuracy.
pub(crate) fn ziv_up_to<F>(function: &'static str, prec: u32, guard: u32, floor: Option<&Float>, max_wp: u32, mut eval: F) -> Result<Ball>
where
    F: FnMut(u32) -> Result<Ball>,
{
    let max_wp = max_wp.min(MAX_WORKING_PREC);
    if !(2..=max_wp).contains(&prec) {
        return Err(Error::Precision { requested: prec as u64 });
    }
    crate::budget::ensure(|| {
        let mut guard = guard.max(8);
        loop {
            let wp = prec.saturating_add(guard).min(max_wp);
            let t = std::time::Instant::now();
            let b = eval(wp)?;
            if b.meets_rel(prec) || floor.is_some_and(|f| !f.is_zero() && b.meets_abs(prec, f)) {
                return Ok(b);
            }
            if wp >= max_wp {
                return Err(Error::PrecisionExhausted { function, working_prec: wp });
            }
            // Bits achieved vs. bits wanted: raise by the shortfall plus margin.
            let achieved = b.rel_accuracy_bits();
            let shortfall = if achieved.is_finite() { (prec as f64 - achieved).max(0.0) } else { wp as f64 };
            let next = (guard as f64 + shortfall + 16.0).max(2.0 * guard as f64);
            guard = next.min((max_wp - prec) as f64) as u32;
            check_next_round(function, t, wp, prec.saturating_add(guard).min(max_wp), achieved)?;
        }
    })
}

/// Between two rounds of a Ziv loop: [`Error::BudgetSpent`] when the time spent
/// plus the next round's estimate passes the call's budget ([`crate::budget`]).
/// The estimate is the last round's time times `(next_wp / wp)^1.5`: MPFR's
/// `ln`, `exp` and Gamma grow about so over 10^3 to 10^5 bits (the rounds of
/// `2F1(2.5, 9e16790; 1.5; -126.375)`'s Ziv loop at 32 240 and 64 496 bits took
/// 15 and 41 ms, release build); scaled linearly, a round estimated at 80 ms
/// took 100 ms and the call ended at 0.16 s under a 0.1 s budget (issue 37's scan).
fn check_next_round(function: &'static str, round_start: std::time::Instant, wp: u32, next_wp: u32, achieved: f64) -> Result<()> {
    let ratio = (f64::from(next_wp) / f64::from(wp.max(1))).max(1.0);
    let next_seconds = crate::budget::since(round_start) * ratio.powf(1.5);
    crate::budget::check_elapsed(function, next_seconds, Reached::WorkingPrecision { bits: wp, accuracy_bits: achieved })
}

/// [`ziv_with_floor`] for inexact (ball) inputs, where raising the working
/// precision cannot shrink the part of the radius that comes from the inputs.
///
/// Every ball `eval` returns must enclose the function over the whole input
/// balls. It stops with the first result that meets `rad <= 2^-prec max(|mid|, floor)`;
/// otherwise it raises the working precision as [`ziv`] does, and stops
/// anyway (returning the wider, still enclosing ball) once a raise no longer
/// halves the radius: the input radius dominates, and only tighter inputs help
/// (see [`crate::ball::eval_at_decimals`]). At the working-precision cap it
/// returns the last ball instead of an error for the same reason.
pub(crate) fn ziv_ball_inputs<F>(prec: u32, guard: u32, floor: Option<&Float>, mut eval: F) -> Result<Ball>
where
    F: FnMut(u32) -> Result<Ball>,
{
    if !(2..=MAX_WORKING_PREC).contains(&prec) {
        return Err(Error::Precision { requested: prec as u64 });
    }
    crate::budget::ensure(|| {
        let mut guard = guard.max(8);
        let mut previous: Option<Float> = None;
        loop {
            let wp = prec.saturating_add(guard).min(MAX_WORKING_PREC);
            let t = std::time::Instant::now();
            let b = eval(wp)?;
            let meets = b.meets_rel(prec) || floor.is_some_and(|f| !f.is_zero() && b.meets_abs(prec, f));
            let rad = b.rad();
            let stalled = previous.as_ref().is_some_and(|p| rad.is_finite() && rad > Float::with_val(p.prec(), p / 2u32));
            if meets || stalled || wp >= MAX_WORKING_PREC {
                return Ok(b);
            }
            previous = Some(rad);
            let achieved = b.rel_accuracy_bits();
            let shortfall = if achieved.is_finite() { (prec as f64 - achieved).max(0.0) } else { wp as f64 };
            let next = (guard as f64 + shortfall + 16.0).max(2.0 * guard as f64);
            guard = next.min((MAX_WORKING_PREC - prec) as f64) as u32;
            check_next_round("a ball-input Ziv loop", t, wp, prec.saturating_add(guard).min(MAX_WORKING_PREC), achieved)?;
        }
    })
}

/// Runs the MP path for an f64 function and rounds the certified midpoint.
pub(crate) fn f64_from_mp<F>(function: &'static str, guard: u32, eval: F) -> Result<f64>
where
    F: FnMut(u32) -> Result<Ball>,
{
    let b = ziv_up_to(function, F64_FALLBACK_PREC, guard, None, F64_FALLBACK_MAX_WP, eval)?;
    let v = b.to_f64();
    finite_result(function, v)
}

/// `v` if it is a finite f64, else [`Error::NonFiniteResult`] naming `function`
/// (a result beyond the f64 range, or an f64 formula that breaks down at
/// extreme scales: the MP path answers there).
pub(crate) fn finite_result(function: &'static str, v: f64) -> Result<f64> {
    if v.is_finite() {
        Ok(v)
    } else {
        Err(Error::NonFiniteResult { function })
    }
}

/// An f64 with a proven error bound from a certified ball: `value` is the
/// midpoint rounded to nearest, and `err = |mid - value| + rad`, each step
/// rounded upward, so the exact value lies within `err` of `value`.
///
/// This is the MP fallback of the `*_bounded` functions: always valid, slower
/// than a native f64 algorithm with its own running error analysis.
pub(crate) fn bounded_from_ball(function: &'static str, b: &Ball) -> Result<Bounded> {
    let value = finite_result(function, b.to_f64())?;
    // mid - value is exact at this precision (both are binary floats).
    let rounding = exact_sub(b.mid(), &exact(value));
    let mut err = Float::with_val(crate::ball::MAG_PREC, 0);
    err.assign_round(rounding.abs_ref(), Round::Up);
    err.add_assign_round(&b.rad(), Round::Up);
    let err = err.to_f64_round(Round::Up);
    Ok(Bounded { value, err })
}

/// Runs a certified MP evaluation at [`F64_FALLBACK_PREC`] bits and returns its
/// f64 rounding with the proven bound ([`bounded_from_ball`]).
pub(crate) fn bounded_from_mp<F>(function: &'static str, guard: u32, eval: F) -> Result<Bounded>
where
    F: FnMut(u32) -> Result<Ball>,
{
    bounded_from_ball(function, &ziv_up_to(function, F64_FALLBACK_PREC, guard, None, F64_FALLBACK_MAX_WP, eval)?)
}

/// An exact binary float from an f64 (53 bits hold every double exactly).
pub fn exact(x: f64) -> Float {
    Float::with_val(53, x)
}

/// Checks a Float argument for finiteness.
/// An input ball for work at `wp` bits, never rounded below its own precision:
/// rounding a ball typed next to an edge (`y = 0.999999999999999` next to
/// `y = 1`, a denominator next to a pole) to a coarse working precision can
/// put the edge inside it, a refusal that more precision would fix. The inputs
/// of `eval_at_decimals` carry `prec + 64` bits at least, and more only when
/// the answer or an edge check needs them.
/// Not kept either: bits the ball does not need. An exact ball is rounded to the
/// bits its value holds (exact: `10^5` at 40 960 bits is a 17-bit number, and
/// Gamma at 40 960 bits takes minutes), an inexact one to the bits that keep the
/// rounding below its radius.
pub(crate) fn input_ball(x: &Ball, wp: u32) -> Ball {
    let needed = if x.is_exact() {
        // SAFETY: mpfr_min_prec reads an initialized MPFR value.
        unsafe { gmp_mpfr_sys::mpfr::min_prec(x.mid().as_raw()) }.max(2) as u32
    } else {
        match (x.mid().get_exp(), x.rad().get_exp()) {
            (Some(em), Some(er)) => (i64::from(em) - i64::from(er) + 2).clamp(2, i64::from(u32::MAX)) as u32,
            _ => wp,
        }
    };
    x.set_prec(wp.max(needed.min(x.prec())))
}

pub(crate) fn check_finite(x: &Float, what: &'static str) -> Result<()> {
    if x.is_finite() {
        Ok(())
    } else {
        Err(Error::NonFinite { what })
    }
}

/// The exact sum `a + b` of two binary floats (enough bits that nothing rounds).
pub(crate) fn exact_add(a: &Float, b: &Float) -> Float {
    Float::with_val(exact_sum_prec(a, b), a + b)
}

/// The exact difference `a - b` of two binary floats.
pub(crate) fn exact_sub(a: &Float, b: &Float) -> Float {
    Float::with_val(exact_sum_prec(a, b), a - b)
}

/// Bits that hold `a ± b` exactly: the span from the lowest set bit to the highest.
fn exact_sum_prec(a: &Float, b: &Float) -> u32 {
    match (a.get_exp(), b.get_exp()) {
        (Some(ea), Some(eb)) => {
            let lo = (ea - a.prec() as i32).min(eb - b.prec() as i32);
            let hi = ea.max(eb) + 1;
            ((hi - lo).max(2) as u32).min(rug::float::prec_max())
        }
        _ => a.prec().max(b.prec()).max(2),
    }
}

/// Whether an exact float is an integer `<= 0`.
pub(crate) fn is_nonpositive_integer(x: &Float) -> bool {
    crate::ball::is_nonpositive_integer(x)
}
