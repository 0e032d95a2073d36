//! Bessel function of the first kind `J_n(x)`, integer order, real argument.
//!
//! # Method
//!
//! Symmetries first: `J_{-n}(x) = (-1)^n J_n(x)` and `J_n(-x) = (-1)^n J_n(x)`
//! [DLMF 10.4.1, 10.11.1], so the algorithms see `n >= 0`, `x > 0`.
//! `J_0(0) = 1`, `J_n(0) = 0` for `n != 0` (exact).
//!
//! Methods, one file each, picked by [`choose_algorithm`] from f64 cost estimates
//! (estimated CPU time from terms times working bits, per method; the cheapest wins):
//!
//! * **Power series** (`series.rs`) [DLMF 10.2.2]:
//!   `J_n(x) = (x/2)^n / n! * 0F1(; n+1; -x^2/4)`, summed on bare midpoints with a
//!   running error analysis, from 256 bits by rectangular splitting with an a-priori
//!   bound (about `2 sqrt K` full products for `K` terms), and a rigorous tail bound
//!   (the pFq core's sum is the cross-check). The terms alternate and their magnitudes sum to
//!   `I_n(x) n! (2/x)^n`, so about `log2(I_n(x)/|J_n(x)|)` bits cancel (roughly
//!   `1.44 x` for `x > n`); the Ziv loop adds them as guard bits. Cost about
//!   `(2 k_peak + wp/8) (wp + loss)`, `k_peak (n + k_peak) = x^2/4`.
//! * **Hankel's expansion** (`hankel.rs`) [DLMF 10.17.3] with the remainder bound
//!   of DLMF 10.17(iv) on the real axis, `|R_l| <= 2 |a_l(n) x^-l| exp(|n^2-1/4|/x)`,
//!   valid for every `l`: it stops as soon as the bound is below `2^-wp` and
//!   pays `log2 e * n^2/x` bits for the exponential factor. It wins for `x`
//!   beyond about `n^2/(wp + ...)`; see the file's method block.
//! * **Three-term recurrence** (`three_term.rs`) for `n` and `x` both large:
//!   forward from certified `J_0(x)`, `J_1(x)` while `k < x`, with an error
//!   bound for the whole run in the energy norm that the step preserves (as
//!   in `native_recurrence.rs`); past the turning point (`n > x`)
//!   the ratios `J_k/J_{k-1}` from the backward recurrence (their contraction
//!   proves the bound). `max(n, x)` steps of three MPFR operations. It takes
//!   `n ~ x` (J_10000(20000.5): 61 ms by Hankel before, a few ms now) and
//!   `n << x` where `n^2/x` is large (J_10000(99999.5)).
//! * **Sequences**: `J_0..J_nmax` certified by the three-term method's two
//!   runs on midpoints with every value kept (`three_term.rs`,
//!   [`bessel_j_sequence_three_term`]: radii `2^-wp` times about `x^2`); the
//!   older route downward in balls from two certified values
//!   (`recurrence.rs`, [`bessel_j_sequence_mp`]: the radius grows by about
//!   `0.68 x` bits); Miller's algorithm in double-double (an estimate).
//!
//! Not here (issue 13 item 4, issue 8 item 3): the Debye and Airy-type uniform
//! expansions [DLMF 10.19, 10.20] with Olver's bounds, which would make
//! `n ~ x` cost O(prec) instead of O(max(n, x)) steps.
//!
//! # Accuracy
//!
//! * MP: certified, `rad <= 2^-prec |mid|` (relative, also near zeros: the Ziv
//!   loop raises the working precision there).
//! * f64 (`native.rs` picks the method): double-double with a running error
//!   analysis and a **proven** bound: the forward recurrence from Hankel's
//!   `J_0`, `J_1` for `n + 1 <= x`, `x >= 25` (`native_recurrence.rs`,
//!   `native_hankel.rs`), the power series elsewhere (`native_series.rs`).
//!   [`bessel_j`] takes the native value when its bound gives 2 ulp,
//!   [`bessel_j_bounded`] when it gives `2^-47` relative; elsewhere (next to
//!   zeros of `J_n`, `x > 2^40`, series cancellation past 52 bits) both fall back
//!   to the certified MP value at 64 bits and count it ([`crate::special::fallback_counts`]):
//!   over `n <= 60`, `x <= 150` about 0.015% of uniform points for [`bessel_j`],
//!   none seen for [`bessel_j_bounded`] (examples/bessel_f64.rs).
//!
//! Domain: every `|n| <= 10^5`, `|x| <= 10^7`, `prec <= 4096` answers (tested
//! at the corners and the turning point in `tests/bessel_large.rs`; the
//! issue-13 grid against 170-digit mpmath values). A call is refused only when
//! the cheapest method's cost estimate passes [`MAX_COST`] (about a minute).

mod hankel;
mod native;
mod native_hankel;
mod native_recurrence;
mod native_series;
mod recurrence;
mod series;
mod three_term;

pub use hankel::bessel_j_hankel;
pub use native::{bessel_j_native, bessel_j_native_portable, choose_native, NativeMethod};
pub use recurrence::{bessel_j_sequence, bessel_j_sequence_dd, bessel_j_sequence_mp, MAX_SEQUENCE_ARGUMENT, MAX_SEQUENCE_ORDER};
pub(crate) use native_hankel::{bessel_j01, HANKEL_MAX_X, HANKEL_MIN_X};
pub(crate) use native_recurrence::forward_sequence;
pub(crate) use native_series::{inv_factorials, MAX_TABLE_FACTORIAL, TABLE_ETA};
pub use series::{bessel_j_series, bessel_j_series_pfq};
pub use three_term::{bessel_j_sequence_three_term, bessel_j_three_term};


use rug::float::Round;
use rug::ops::AssignRound;
use rug::Float;

use crate::ball::{Ball, Bounded, Mag};
use crate::error::{Error, Result};
use crate::special::{check_finite, exact, f64_from_mp, ziv};

/// Largest |n| accepted: the hard cap. The documented and tested domain is |n| <= 1e5
/// (module docs); orders between 1e5 and this cap are accepted but not tested.
pub const MAX_ORDER: i64 = 1_000_000;

/// The algorithms.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[non_exhaustive]
pub enum Algorithm {
    /// Power series through 0F1.
    PowerSeries,
    /// Hankel's asymptotic expansion with the DLMF 10.17(iv) remainder bound.
    Hankel,
    /// Three-term recurrence from `J_0`, `J_1` (forward below the turning
    /// point, ratios past it) with the modulus bound (`three_term.rs`).
    Recurrence,
}

/// A choice with its f64 cost estimate and the guard bits it needs.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Choice {
    pub algorithm: Algorithm,
    /// Initial guard bits (cancellation and phase reduction).
    pub guard: u32,
    /// Estimated CPU time in ns (see the cost model constants).
    pub cost: f64,
}

// Cost model, in nanoseconds of CPU time on this machine's cores: each
// method's terms (or steps) times its working bits plus a per-term overhead in
// equivalent bits, times a per-method rate. Calibrated on 2026-11-23 from CPU
// times (/proc/self/stat, 0.3 s per point) of all three methods at 36 points
// (n, x from the issue-13 grid, wp 100/180/560); the model is within a factor
// 2 of the measurement wherever two methods compete.

/// Power series: ns per term and bit.
const SERIES_NS_PER_TERM_BIT: f64 = 0.7;
/// Power series: per-term overhead, in equivalent bits.
const SERIES_TERM_OVERHEAD_BITS: f64 = 100.0;
/// Power series: fixed cost (prefactor `(x/2)^n/n!`, Ziv bookkeeping), ns.
const SERIES_FIXED_NS: f64 = 60_000.0;
/// Hankel's expansion: ns per term and bit (six ball operations a term).
const HANKEL_NS_PER_TERM_BIT: f64 = 0.8;
/// Hankel's expansion: per-term overhead, in equivalent bits.
const HANKEL_TERM_OVERHEAD_BITS: f64 = 400.0;
/// Recurrence: ns per step and bit (`three_term::plan` counts 1.5 per step).
const RECURRENCE_NS_PER_STEP_BIT: f64 = 0.23;
/// Recurrence: per-step overhead, in equivalent bits.
const RECURRENCE_STEP_OVERHEAD_BITS: f64 = 150.0;

/// Above this many bits a full MPFR multiplication costs more than linear time
/// (GMP's Toom-Cook range).
const LINEAR_MUL_BITS: f64 = 2048.0;

/// Equivalent bits of one operation at `bits` working bits plus a per-call
/// `overhead`: linear up to [`LINEAR_MUL_BITS`], then `bits^1.6` (the
/// multiplications' Toom-Cook growth; most terms hold one full product).
fn op_bits(bits: f64, overhead: f64) -> f64 {
    let growth = (bits / LINEAR_MUL_BITS).max(1.0).powf(0.6);
    bits * growth + overhead
}

/// Bits the power series loses to cancellation, `log2(I_n(x) / |J_n(x)|)`
/// (the sum of |terms| is `I_n(x)` up to the common prefactor), from the
/// exponential factors of Debye's expansions [DLMF 10.41.3, 10.19.3]:
/// `ln I_n(x) ~ sqrt(n^2+x^2) + n ln(x/(n + sqrt(n^2+x^2)))`, and for `x < n`
/// `ln J_n(x) ~ sqrt(n^2-x^2) + n ln(x/(n + sqrt(n^2-x^2)))` (for `x >= n`, `J_n`
/// is `O(1)` up to algebraic factors). An estimate for the initial guard only:
/// the Ziv loop corrects it.
fn series_loss_bits(n: u64, x: f64) -> f64 {
    let nf = n as f64;
    let r_i = (nf * nf + x * x).sqrt();
    let ln_i = r_i + if n == 0 { 0.0 } else { nf * (x / (nf + r_i)).ln() };
    let ln_j = if x < nf {
        let r_j = (nf * nf - x * x).sqrt();
        r_j + nf * (x / (nf + r_j)).ln()
    } else {
        0.0
    };
    ((ln_i - ln_j) * std::f64::consts::LOG2_E).max(0.0) * 1.02
}

/// The power series' choice: about `2 k_peak + wp/8` terms, `k_peak` the largest
/// term's index (`k (n + k) = x^2/4`), at `wp` plus the cancellation bits.
fn series_choice(n: u64, x: f64, wp: u32) -> Choice {
    let nf = n as f64;
    let k_peak = ((nf * nf + x * x).sqrt() - nf) / 2.0;
    let loss = series_loss_bits(n, x);
    let terms = 2.0 * k_peak + 10.0 + wp as f64 / 8.0;
    Choice { algorithm: Algorithm::PowerSeries, guard: (loss + 24.0).min(4.0e6) as u32, cost: SERIES_FIXED_NS + SERIES_NS_PER_TERM_BIT * terms * op_bits(wp as f64 + loss, SERIES_TERM_OVERHEAD_BITS) }
}

/// Hankel's choice, if its terms reach `2^-wp` before diverging: the peak term
/// and the phase `x - (2n+1) pi/4` (about `log2(x + n)` bits) are the guard.
fn hankel_choice(n: u64, x: f64, wp: u32) -> Option<Choice> {
    let plan = hankel::plan(n, x, wp)?;
    let guard = plan.peak_bits + (x + n as f64).log2().max(0.0) + 16.0;
    let cost = HANKEL_NS_PER_TERM_BIT * plan.terms as f64 * op_bits(wp as f64 + guard, HANKEL_TERM_OVERHEAD_BITS);
    Some(Choice { algorithm: Algorithm::Hankel, guard: guard.min(4.0e6) as u32, cost })
}

/// The recurrence's choice (`n >= 2`, `x > 2`): its steps at `wp` plus its
/// guard, and the two starting values `J_0(x)`, `J_1(x)` by their own choices.
fn recurrence_choice(n: u64, x: f64, wp: u32) -> Option<Choice> {
    if n < 2 || !(x > RECURRENCE_MIN_X) {
        return None;
    }
    let (steps, guard) = three_term::plan(n, x, wp);
    let start_wp = wp.saturating_add(guard.min(4.0e6) as u32);
    let start = choose(0, x, start_wp).cost + choose(1, x, start_wp).cost;
    let cost = RECURRENCE_NS_PER_STEP_BIT * steps * op_bits(wp as f64 + guard, RECURRENCE_STEP_OVERHEAD_BITS) + start;
    Some(Choice { algorithm: Algorithm::Recurrence, guard: guard.min(4.0e6) as u32, cost })
}

/// Below this `x` the power series is always cheaper than the recurrence.
const RECURRENCE_MIN_X: f64 = 2.0;

/// The chooser: the cheapest of the power series, Hankel's expansion and the
/// recurrence (`n >= 0`, `x > 0`, working precision `wp`), by the f64 cost estimates.
pub(crate) fn choose(n: u64, x: f64, wp: u32) -> Choice {
    let mut best = series_choice(n, x, wp);
    for c in [hankel_choice(n, x, wp), recurrence_choice(n, x, wp)].into_iter().flatten() {
        if c.cost < best.cost {
            best = c;
        }
    }
    best
}

/// The chooser's cost estimates at `(n, x, wp)`, one per applicable method
/// (for the benches and docs).
#[doc(hidden)]
pub fn algorithm_costs(n: u64, x: f64, wp: u32) -> Vec<(Algorithm, f64)> {
    [Some(series_choice(n, x, wp)), hankel_choice(n, x, wp), recurrence_choice(n, x, wp)]
        .into_iter()
        .flatten()
        .map(|c| (c.algorithm, c.cost))
        .collect()
}

/// Picks the algorithm for `n >= 0`, `x > 0` at working precision `wp`.
pub fn choose_algorithm(n: u64, x: f64, wp: u32) -> Algorithm {
    choose(n, x, wp).algorithm
}

fn validate(n: i64, x: &Float) -> Result<()> {
    check_finite(x, "x")?;
    if n.unsigned_abs() > MAX_ORDER as u64 {
        return Err(Error::IntegerOutOfRange { arg: "n", value: n, min: -MAX_ORDER, max: MAX_ORDER });
    }
    Ok(())
}

/// Sign from the symmetries: returns (|n|, |x|, negate).
fn reduce(n: i64, x: &Float) -> (u64, Float, bool) {
    let m = n.unsigned_abs();
    let odd = m % 2 == 1;
    let mut negate = false;
    if n < 0 && odd {
        negate = !negate;
    }
    if x.is_sign_negative() && odd {
        negate = !negate;
    }
    (m, Float::with_val(x.prec(), x.abs_ref()), negate)
}


/// `J_n(x)` at working precision `wp` (`n >= 0`, `x > 0`), algorithm by [`choose_algorithm`].
fn bessel_j_positive(n: u64, x: &Float, wp: u32) -> Result<Ball> {
    match choose_algorithm(n, x.to_f64(), wp) {
        Algorithm::Hankel => {
            if let Some(b) = bessel_j_hankel(n, x, wp)? {
                return Ok(b);
            }
        }
        Algorithm::Recurrence => {
            let j0 = bessel_j_positive(0, x, wp)?;
            let j1 = bessel_j_positive(1, x, wp)?;
            return bessel_j_three_term(n, x, &j0, &j1, wp);
        }
        Algorithm::PowerSeries => {}
    }
    bessel_j_series(n, x, wp)
}

/// Certified `J_n(x)` with `rad <= 2^-prec |mid|`.
pub fn bessel_j_mp(n: i64, x: &Float, prec: u32) -> Result<Ball> {
    crate::error::check_prec(prec)?;
    bessel_j_ball(n, x, prec)
}

/// Certified `J_n` over a ball of arguments: the result contains `J_n(t)` for
/// every `t` in `x` (Arb's convention for inputs; see [`crate::ball::Decimal`]
/// for decimal text).
///
/// # Input-radius propagation
///
/// With `m = mid(x)`, `r = rad(x)`, `[c ± rho]` the certified ball of
/// `J_n(m)` at the exact binary number `m`, and `n >= 0`, `m > 0` after the
/// symmetries `J_{-n} = (-1)^n J_n`, `J_n(-t) = (-1)^n J_n(t)` [DLMF 10.4.1, 10.11.1]:
///
/// * **Before the first zeros** (`0 < m - r`, `m + r <= n - 1`, or `<= 2` for
///   `n = 1`): relative propagation. `d/dt (t^-n J_n) = -t^-n J_{n+1}` and
///   `d/dt (t^n J_n) = t^n J_{n-1}` [DLMF 10.6.6]; `J_{n-1}`, `J_n`, `J_{n+1}`
///   are positive on `(0, j_{n-1,1})`, and `j_{nu,1} > nu` [DLMF 10.21.3]
///   (`j_{0,1} = 2.4048...` > 2, DLMF Table 10.21.1). So `t^-n J_n` falls and
///   `t^n J_n` rises across the ball, which pins
///   `J_n(t) / J_n(m)` to `[(lo/m)^n, (m/lo)^n]`, `lo = m - r`, and
///   `(m/lo)^n - 1 <= y e^y` with `y = n r / lo` (`(1+u)^n <= e^(nu)`,
///   `e^y - 1 <= y e^y`). The radius grows by `rho + (|c| + rho) y e^y`: about
///   `n r / m` relative, the true sensitivity `|J_n'/J_n| r ~ n r / m` there,
///   instead of `r` absolute, which at `J_10000(0.001) ~ 1e-68670` carried no digit.
/// * **Elsewhere**: `J_n(t) - J_n(m) = int_m^t J_n'(s) ds` with
///   `J_n' = (J_{n-1} - J_{n+1}) / 2` [DLMF 10.6.1] and, for real `|s| <= T = |m| + r`,
///   `|J_k(s)| <= min(1, (T/2)^k / k!)` [DLMF 10.14.1, 10.14.4], `k! >= (k/e)^k`:
///   `|J_n'| <= min(1, (B_{n-1} + B_{n+1}) / 2)` over the ball (`|J_0'| = |J_1|`), times `r`.
///
/// When the input is inexact the midpoint value is computed 4 bits beyond
/// `prec` so that the input part has room under `2^-prec |mid|`. For an exact
/// `x` the result is [`bessel_j_mp`]'s. Near a zero of `J_n` the input radius
/// dominates: the ball is then honest but wide, and callers that know the
/// input exactly (decimal text) narrow it with [`crate::ball::eval_at_decimals`].
pub fn bessel_j_ball_mp(n: i64, x: &Ball, prec: u32) -> Result<Ball> {
    crate::error::check_prec(prec)?;
    if !x.is_finite() {
        return Err(Error::NonFinite { what: "x" });
    }
    bessel_j_ball_input(n, x, prec)
}

/// Guard bits of the midpoint value when the input ball has a radius.
const INPUT_GUARD_BITS: u32 = 4;

/// [`bessel_j_ball_mp`] without the user-precision cap (also the real-axis path
/// of [`crate::ball::CBall::bessel_j`]).
pub(crate) fn bessel_j_ball_input(n: i64, x: &Ball, prec: u32) -> Result<Ball> {
    let r = x.rad_mag();
    if r.is_zero() {
        return bessel_j_ball(n, x.mid(), prec);
    }
    validate(n, x.mid())?;
    let (m, ax, negate) = reduce(n, x.mid());
    let mut out = bessel_j_ball(m as i64, &ax, prec + INPUT_GUARD_BITS)?;
    let mut lo = Float::new(ax.prec());
    lo.assign_round(&ax - &r.to_float(), Round::Down);
    let lo = if lo.is_sign_positive() && !lo.is_zero() { Mag::from_float_down(&lo) } else { Mag::ZERO };
    let hi = Mag::from_float_up(&ax).add(r);
    let first_zero_bound = match m {
        0 => Mag::ZERO,
        1 => Mag::from_f64(2.0),
        _ => Mag::from_f64((m - 1) as f64),
    };
    if !lo.is_zero() && m >= 1 && hi.le(&first_zero_bound) {
        // J_n(t)/J_n(m) in [(lo/m)^n, (m/lo)^n]; (m/lo)^n - 1 <= y e^y, y = n r / lo.
        let y = r.div(lo).mul(Mag::from_f64(m as f64));
        let ey = exp_upper(y);
        let grow = out.abs_upper_mag().mul(y).mul(ey).add(out.rad_mag());
        out.add_error_mag(grow);
    } else {
        out.add_error_mag(r.mul(derivative_bound(m, hi)));
    }
    Ok(if negate { out.neg() } else { out })
}

/// Upper bound of `e^y` for a [`Mag`] `y` (infinite when it overflows).
fn exp_upper(y: Mag) -> Mag {
    match Ball::with_mag(y.to_float(), Mag::ZERO).exp() {
        Ok(e) => e.abs_upper_mag(),
        Err(_) => Mag::inf(),
    }
}

/// Upper bound of `base^k` by square-and-multiply in [`Mag`] (each step rounds up;
/// no underflow: the exponent is an `i64`).
fn mag_pow(base: Mag, k: u64) -> Mag {
    crate::ball::binary_power(Mag::from_f64(1.0), base, k, |a, b| a.mul(*b), |a| a.mul(*a))
}

/// Upper bound of `|J_k(s)|` for real `|s| <= t`: `min(1, (t/2)^k / k!)`
/// [DLMF 10.14.1, 10.14.4], with `k! >= (k/e)^k` (from `e^k >= k^k / k!`), so
/// `(t/2)^k / k! <= (e t / (2k))^k`.
fn j_abs_bound(k: u64, t: Mag) -> Mag {
    let one = Mag::from_f64(1.0);
    if k == 0 {
        return one;
    }
    // 2.718281828459046 (as an f64) is above e.
    let base = t.mul(Mag::from_f64(2.718_281_828_459_046)).div(Mag::from_f64(2.0 * k as f64));
    if one.le(&base) {
        return one;
    }
    let b = mag_pow(base, k);
    if b.le(&one) { b } else { one }
}

/// Upper bound of `|J_n'(s)|` for real `|s| <= t`, `n >= 0`: `J_0' = -J_1`,
/// `J_n' = (J_{n-1} - J_{n+1}) / 2` [DLMF 10.6.1], with [`j_abs_bound`].
fn derivative_bound(n: u64, t: Mag) -> Mag {
    if n == 0 {
        return j_abs_bound(1, t);
    }
    j_abs_bound(n - 1, t).add(j_abs_bound(n + 1, t)).mul_2exp(-1)
}

/// [`bessel_j_mp`] without the user-precision cap (internal callers run at
/// working precisions up to [`crate::MAX_WORKING_PREC`]).
pub(crate) fn bessel_j_ball(n: i64, x: &Float, prec: u32) -> Result<Ball> {
    validate(n, x)?;
    if x.is_zero() {
        return Ok(if n == 0 { Ball::one(prec) } else { Ball::zero(prec) });
    }
    let (m, ax, negate) = reduce(n, x);
    let guard = check_cost(m, ax.to_f64(), prec)?;
    let b = ziv("bessel_j", prec, guard, |wp| bessel_j_positive(m, &ax, wp))?;
    Ok(if negate { b.neg() } else { b })
}

/// Cost (the chooser's estimate in ns of CPU time)
/// past which a call is refused as a time limit (about a minute of work).
pub const MAX_COST: f64 = 6.0e10;

/// The initial guard, or an error when even the cheapest method would run for
/// more than about a minute ([`MAX_COST`]; nothing in |n| <= 1e5, |x| <= 1e7,
/// prec <= 4096 comes near it).
fn check_cost(m: u64, x: f64, prec: u32) -> Result<u32> {
    let c = choose(m, x, prec + 32);
    // the cap, shortened by what is left of the call's time budget
    crate::budget::check_estimate("J_n(x)", c.cost * 1e-9, MAX_COST * 1e-9)?;
    Ok(c.guard)
}

/// How many f64 calls fell back to the MP path so far (process-wide): the
/// `bessel_j` field of [`crate::special::fallback_counts`].
#[deprecated(note = "use `maugis::special::fallback_counts().bessel_j`: one snapshot of every counter")]
pub fn bessel_j_fallbacks() -> u64 {
    crate::special::fallback_counts().bessel_j
}

/// Relative bound the native path must prove for [`bessel_j`]: with the final
/// rounding included, the value is then within 2 ulp.
const PLAIN_NATIVE_REL: f64 = 1.0 / (1u64 << 52) as f64;
/// Relative bound the native path must prove for [`bessel_j_bounded`] (`2^-47`,
/// about `7e-15`, below the 1e-14 promised for the f64 layer).
const BOUNDED_NATIVE_REL: f64 = 1.0 / (1u64 << 47) as f64;

/// The native path (`n >= 0`, `x > 0`) when its proven bound is within `rel`.
fn native(m: u64, x: f64, rel: f64) -> Option<Bounded> {
    native::bessel_j_native(native::choose_native(m, x), m, x).filter(|b| b.err <= rel * b.value.abs())
}

/// `J_n(x)` in f64, within 2 ulp: the native double-double method (`native.rs`)
/// where its proven bound allows, else the certified MP value rounded.
pub fn bessel_j(n: i64, x: f64) -> Result<f64> {
    let b = f64_entry(n, x, PLAIN_NATIVE_REL, |m, ax| {
        let guard = check_cost(m, ax.to_f64(), crate::special::F64_FALLBACK_PREC)?;
        let v = f64_from_mp("bessel_j", guard, |wp| bessel_j_positive(m, ax, wp))?;
        Ok(Bounded { value: v, err: f64::NAN })
    })?;
    Ok(b.value)
}

/// The shared f64 entry: checks, symmetries, the native path within `rel`,
/// else `fallback(|n|, |x|)` (counted).
fn f64_entry<F>(n: i64, x: f64, rel: f64, fallback: F) -> Result<Bounded>
where
    F: FnOnce(u64, &Float) -> Result<Bounded>,
{
    crate::error::finite(x, "x")?;
    if n.unsigned_abs() > MAX_ORDER as u64 {
        return Err(Error::IntegerOutOfRange { arg: "n", value: n, min: -MAX_ORDER, max: MAX_ORDER });
    }
    if x == 0.0 {
        return Ok(Bounded { value: if n == 0 { 1.0 } else { 0.0 }, err: 0.0 });
    }
    let m = n.unsigned_abs();
    // J_{-n} = (-1)^n J_n, J_n(-x) = (-1)^n J_n [DLMF 10.4.1, 10.11.1]
    let negate = m % 2 == 1 && ((n < 0) != (x < 0.0));
    let b = match native(m, x.abs(), rel) {
        Some(b) => b,
        None => {
            crate::special::fallback::count(crate::special::F64Route::BesselJ);
            fallback(m, &exact(x.abs()))?
        }
    };
    Ok(if negate { Bounded { value: -b.value, err: b.err } } else { b })
}

/// `J_n(x)` in f64 with a proven error bound for the f64 `x` as given: the
/// native double-double method (`native.rs`) with its running error analysis
/// where that proves `err <= 2^-47 |value|`, else the certified MP fallback
/// (counted in [`crate::special::fallback_counts`]).
pub fn bessel_j_bounded(n: i64, x: f64) -> Result<Bounded> {
    f64_entry(n, x, BOUNDED_NATIVE_REL, |m, ax| {
        let guard = check_cost(m, ax.to_f64(), crate::special::F64_FALLBACK_PREC)?;
        crate::special::bounded_from_mp("bessel_j", guard, |wp| bessel_j_positive(m, ax, wp))
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ball::Dd;

    #[test]
    fn small_values() {
        // J_0(1), J_1(1) against the certified MP route (the golden tables in tests/golden.rs
        // check the f64 route against mpmath on the whole domain)
        for n in [0, 1] {
            let exact = bessel_j_mp(n, &rug::Float::with_val(53, 1.0), 128).unwrap();
            let e = rug::Float::with_val(128, exact.mid() - bessel_j(n, 1.0).unwrap()).abs().to_f64();
            assert!(e <= exact.mid().to_f64().abs() * 1.2e-16 && exact.rad().to_f64() < 1e-30, "J_{n}(1): {e:e}");
        }
        assert_eq!(bessel_j(3, 0.0).unwrap(), 0.0);
        assert_eq!(bessel_j(0, 0.0).unwrap(), 1.0);
    }

    #[test]
    fn symmetries() {
        let a = bessel_j(3, 2.0).unwrap();
        assert_eq!(bessel_j(-3, 2.0).unwrap(), -a);
        assert_eq!(bessel_j(3, -2.0).unwrap(), -a);
        assert_eq!(bessel_j(-3, -2.0).unwrap(), a);
    }

    #[test]
    fn hankel_and_series_overlap() {
        for &(n, x) in &[(0u64, 60.0), (3, 75.5), (10, 120.25)] {
            let xf = exact(x);
            let wp = 120;
            let h = bessel_j_hankel(n, &xf, wp).unwrap().expect("hankel applies");
            let s = bessel_j_series(n, &xf, wp + 200).unwrap();
            assert!(h.overlaps(&s), "n={n} x={x}: {h:?} vs {s:?}");
        }
    }

    #[test]
    fn sequences_agree_with_single_values() {
        for &x in &[0.5, 9.75, 42.0, 75.25] {
            let nmax = 60;
            let seq = bessel_j_sequence_mp(nmax, &exact(x), 128).unwrap();
            let f = bessel_j_sequence(nmax as usize, x);
            for n in [0u64, 1, 2, 17, 40, 60] {
                let single = bessel_j_mp(n as i64, &exact(x), 128).unwrap();
                assert!(seq[n as usize].overlaps(&single), "x={x} n={n}");
                let v = single.to_f64();
                assert!((f[n as usize] - v).abs() <= 8.0 * f64::EPSILON, "x={x} n={n}: {} vs {v}", f[n as usize]);
            }
        }
    }

    #[test]
    fn double_double_sequence_accuracy() {
        for &x in &[0.5, 5.0, 20.25, 75.5, 300.0, 1500.0] {
            let nmax = (x as usize) + 60;
            let dd = bessel_j_sequence_dd(nmax, Dd::from_f64(x));
            let mp = bessel_j_sequence_mp(nmax as u64, &exact(x), 160).unwrap();
            for n in 0..=nmax {
                let exact_v = mp[n].mid();
                let err = Float::with_val(200, Float::with_val(200, dd[n].hi) + dd[n].lo - exact_v).abs();
                assert!(err < 1e-29, "x={x} n={n}: error {}", err.to_f64());
            }
        }
    }

    #[test]
    fn bad_input() {
        assert!(bessel_j(1, f64::NAN).is_err());
        assert!(bessel_j_mp(1, &exact(1.0), 1).is_err());
        assert!(bessel_j(MAX_ORDER + 1, 1.0).is_err());
    }
}

