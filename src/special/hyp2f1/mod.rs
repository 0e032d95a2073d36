//! Gauss hypergeometric function `2F1(a, b; c; z)`, real parameters, real `z <= 1`.
//!
//! # Method
//!
//! `2F1(a, b; c; z) = sum_n (a)_n (b)_n / ((c)_n n!) z^n` [DLMF 15.2.1] for
//! `|z| < 1`, continued to `z < -1` and to `z = 1` as below. Every formula is
//! evaluated in ball arithmetic (or in place with an a-priori rounding bound,
//! see *Error argument*), so the returned ball contains the exact value at the
//! given binary inputs. `choose_algorithm` picks one `Algorithm`; each is a
//! public function callable on its own at a working precision `wp`.
//!
//! ## Special cases first
//!
//! * **Terminating** (`Algorithm::Polynomial`): `a` or `b` a non-positive
//!   integer `-d`. `2F1` is a polynomial of degree `d`, summed for any `z <= 1`.
//!   For `d <= 300` it is summed *exactly* in rationals (`rug::Rational`) and
//!   rounded once, so exact zeros (e.g. Chu-Vandermonde zeros at `z = 1`) come
//!   back as `[0 +/- 0]`; longer polynomials use the series engine below.
//! * **`c` a non-positive integer** `-m`: a pole of every term with `n > m`;
//!   allowed only when the series terminates first (`d <= m`, the usual
//!   convention, as in mpmath), otherwise [`Error::ParameterPole`].
//! * **`z = 1`** (`Algorithm::Gauss`): Gauss's sum
//!   `Gamma(c) Gamma(c-a-b) / (Gamma(c-a) Gamma(c-b))` when `c - a - b > 0`
//!   [DLMF 15.4.20]; a terminating series uses the polynomial (Chu-Vandermonde,
//!   DLMF 15.4.24, for any `c - a - b`); otherwise the series diverges and the
//!   result is [`Error::Divergent`].
//! * `z = 0` gives exactly 1.
//!
//! ## Regions (non-terminating)
//!
//! | region | algorithm | series argument |
//! |---|---|---|
//! | `|z| <= 1/2` | `Algorithm::Direct`: DLMF 15.2.1 | `z`, `|z| <= 1/2` |
//! | `-1 <= z < -1/2` | `Algorithm::Pfaff`: `(1-z)^{-a} 2F1(a, c-b; c; z/(z-1))` [DLMF 15.8.1] | `w in (1/3, 1/2]` |
//! | `1/2 < z < 1` | `Algorithm::Connection` / `Algorithm::ConnectionLog` (1-z formula) | `1 - z in (0, 1/2)` |
//! | `z < -1` | `Algorithm::PfaffConnection` / `Algorithm::PfaffConnectionLog`: Pfaff to `w = z/(z-1) in (1/2, 1)`, then the 1-w formula with `1 - w = 1/(1-z)` | `1/(1-z) in (0, 1/2)` |
//!
//! **One large parameter** (`Algorithm::LargeParam`, `large_param.rs`):
//! `max(|a|, |b|) >= 1000` and 16 times the others, `z < 0` or `0 < z < 1`: the
//! connection formula in `1/(1-z)` or `1-z`, whose series length does not grow
//! with the parameter (about 1 ms for `2F1(1.5, 1000001; 24.74; -0.5)`, where every
//! series in `z` runs to `10^6` terms); taken before the regions below when its
//! estimated terms are fewer than `2 max(|a|, |b|) |z|`.
//!
//! **One tiny positive parameter** (`small_parameter.rs`, over balls): `0 < b <= 1`
//! (or `a`), the other parameter `>= 0` of any size, `c >= b + 1` and `z < 0`:
//! `[1 - w, 1]` from Euler's integral, `w ~ b ln(a |z|)`, taken first where `w`
//! meets the precision (`2F1(1.5e31874, 1.1e-29974; 2.2e-167 + ...; -1)`-like inputs,
//! where every other route passes the exponent range or meets poles).
//!
//! Within `-1 <= z <= 1/2` the same function is also
//! `(1-z)^{c-a-b} 2F1(c-a, c-b; c; z)` (`Algorithm::Euler`, DLMF 15.8.1) and
//! `(1-z)^{-b} 2F1(c-a, b; c; w)` (`Algorithm::PfaffSwapped`); for `z < 0`
//! also `(1-z)^{-a} 2F1(a, c-b; c; w)` with `|w| < |z|`. `choose_algorithm`
//! simulates the term magnitudes of these series in f64 and takes the cheapest
//! (terms times precision plus cancellation, the direct series on ties). This
//! matters for large negative parameters: `2F1(-N+1/2, 2; 3; 1/2)` loses about
//! `0.6 N` bits to cancellation in the direct series, while the Euler transform
//! has positive terms (`N = 10^6` takes 0.2 s instead of minutes).
//!
//!
//! # Branch cut
//!
//! The principal branch of `2F1` has its cut on `[1, inf)` [DLMF 15.2(i)]; on
//! the cut the value depends on the side of approach and is complex. Only real
//! `z <= 1` is supported; `z > 1` is [`Error::OutOfRange`].
//!
//! # Performance
//!
//! The paper's model case `2F1(1, k+1/2; k+2; y)`, `k <= 1000`, 128 bits
//! (release build, best of 5): 6-30 us for `y <= 1/2`, 20-100 us on
//! `(1/2, 1)` (direct series up to about `y = 0.9` at `k = 1000`, the 1-z
//! formula above; about 40 us at `y = 1 - 10^-12`), about 1 us at `y = 1`.
//! `model_case_timing` (ignored test) prints the table.
//!
//! # Accuracy
//!
//! * MP: certified, `rad <= 2^-prec |mid|`.
//! * f64 (`native.rs`, `power_f64.rs`, `rgamma_f64.rs`): the direct series for
//!   `-1/2 <= z <= 9/10` (and every terminating case), Pfaff for `z < -1/2`, the
//!   connection formula in `1/(1-z)` for `z <= -4` (before Pfaff), summed
//!   in f64 with a proven a-priori bound (two lanes at a time), with a
//!   double-word head where the first terms cancel, in double words
//!   throughout where that cannot certify, with certified f64 (table-driven)
//!   or double-word `(1-z)^{-a}` and
//!   certified f64 reciprocal Gammas. The arguments are checked in f64; MPFR is
//!   touched only on the fallback. [`hyp2f1_bounded`] returns that proven
//!   bound when it is at most [`NATIVE_ACCEPT_REL`] relative, otherwise the
//!   certified 64-bit MP value rounded with `err = |mid - value| + rad`. Over the
//!   benchmark domain (`a, b in [-3, 3]`, `c in [0.5, 6]`, `z in [-5, 0.9]`) the
//!   native path certifies every one of 10000 random points (unit test
//!   `bound_holds_on_the_benchmark_domain`); MP remains for `9/10 < z <= 1`,
//!   `z < -1/2` beyond 3000 terms, and cancellation beyond double words.
//!
//! Domain: finite real `a, b, c`, real `z <= 1`; `|c - a - b| <= 10^5` when it is
//! an integer and `z > 1/2` or `z < -1`. Tested: `|a|, |b| <= 10`,
//! `0.25 <= c <= 15`, `-10^6 <= z <= 1`, and the model case up to `k = 1000`.
//! Larger parameters work but cost grows with them (`2F1(-10^6+1/2, 2; 3; 1/2)`
//! takes 0.2 s); a series that would need more than 5 * 10^6 terms, or more
//! than what is left of the call's time budget ([`crate::budget`]) allows, is
//! [`Error::TooExpensive`] at once (the ratio bound proves the term count). The
//! Gamma-based formulas (connection, Gauss) are [`Error::TooExpensive`] when the
//! planned cancellation passes [`MAX_GAMMA_LOSS`] bits (MPFR's Gamma at tens of
//! thousands of bits takes minutes to hours), and Gamma arguments longer than
//! the working precision needs are rounded with a proven bound
//! (`special::gamma::gamma_of_ball`). When `c - a - b` is within `eps` of an integer
//! without being one, the 1-z formula cancels about `log2(1/eps)` bits, which
//! the Ziv loop supplies.
//!
//! # Files
//!
//! One file per method, as in Arb's `acb_hypgeom/2f1_*.c`; each opens with its
//! formula and error bound: `series` (the power-series engine), `polynomial`
//! (terminating series, exact rationals), `transform` (direct, Euler, Pfaff),
//! `connection` (1-z formula, Pfaff + 1-w, Gauss's sum), `log_case` (the
//! degenerate 1-z formula, also over balls), `large_param` (one large parameter, over balls), `small_parameter`
//! (one tiny positive parameter, `z < 0`, over balls), `dominant_param` (`a |z|`
//! far past `c` and `b |z|`, `z < 0`, over balls), `out_of_range` (a proof that
//! the value lies above the exponent range),
//! `choose` (the cost model and dispatcher).
//! Gamma ratios, connection terms and the Pfaff/Euler prefactors are formed
//! through [`Scaled`](crate::ball::Scaled) (`m e^l`): a Gamma or a power past
//! MPFR's exponent range (`Gamma(4.2e18)`, `(1 - z)^(-7.4e17)`) is carried in
//! logarithms and the term exponentiated once (the enclosure is proved in
//! `src/ball/scaled.rs`; `ln Gamma` in `special/gamma.rs`). Only a value itself
//! outside the range is refused ([`crate::Error::ValueOutOfRange`]).
//! Gamma, Pochhammer and the magnitude helpers live in `special/gamma.rs`.

mod ball_input;
mod choose;
mod connection;
mod dominant_param;
mod large_param;
mod log_case;
mod native;
mod out_of_range;
mod native_connection;
mod native_dw;
mod native_series;
mod polynomial;
mod power;
mod power_f64;
mod rgamma_f64;
mod series;
mod small_parameter;
mod transform;

#[cfg(test)]
mod tests;

use rug::Float;

pub use ball_input::hyp2f1_ball_mp;
use choose::{evaluate, plan, plan_regions, Algorithm};

use crate::ball::{Ball, Bounded};
use crate::error::{check_prec, finite, Error, Interval, Result};
use crate::special::{
    check_finite, exact, exact_sub, f64_from_mp, is_nonpositive_integer, ziv, ziv_up_to, DEFAULT_GUARD_BITS,
    F64_FALLBACK_PREC,
};
use crate::special::gamma::gamma_seconds;

/// Up to `|z| = 1/2` (and down to `z = -1`) only series in `z` or `w = z/(z-1)`
/// are used (direct, Euler, Pfaff); beyond, the 1-z formulas are candidates.
pub(crate) const DIRECT_RADIUS: f64 = 0.5;

/// Polynomials up to this degree are summed exactly in rationals.
pub(crate) const EXACT_POLY_MAX_DEGREE: u64 = 300;

/// Largest `|c - a - b|` for the logarithmic formula (its finite sum has that many terms).
pub(crate) const MAX_LOG_M: u64 = 100_000;

/// Minimum precision of the series engine (its error bound assumes `8 N 2^-p` tiny).
const MIN_SERIES_PREC: u32 = 64;

// ----- small exact helpers ------------------------------------------------

/// `d` when `x = -d` is a non-positive integer.
fn nonpos_degree(x: &Float) -> Option<u64> {
    if is_nonpositive_integer(x) {
        Some((-x.to_f64()) as u64)
    } else {
        None
    }
}

/// Degree of the polynomial when `a` or `b` is a non-positive integer.
fn terminating_degree(a: &Float, b: &Float) -> Option<u64> {
    match (nonpos_degree(a), nonpos_degree(b)) {
        (Some(x), Some(y)) => Some(x.min(y)),
        (x, y) => x.or(y),
    }
}

fn one() -> Float {
    Float::with_val(2, 1)
}

fn pole_error(c: &Float) -> Error {
    let c = c.to_f64();
    Error::ParameterPole { function: "2F1", arg: "c", pole: c, lower: c, upper: c }
}

/// `z > 1`: the branch cut `[1, inf)` of the principal branch (complex values);
/// only real `z <= 1` is supported.
fn branch_cut_error(z: f64) -> Error {
    Error::OutOfRange { arg: "z", value: z, allowed: Interval::at_most(1.0) }
}

// ----- public entry points ---------------------------------------------------------

/// Checks the arguments: finite, `z <= 1`, `c` not a pole, `z = 1` convergent.
fn validate(a: &Float, b: &Float, c: &Float, z: &Float) -> Result<()> {
    check_finite(a, "a")?;
    check_finite(b, "b")?;
    check_finite(c, "c")?;
    check_finite(z, "z")?;
    if *z > 1 {
        return Err(branch_cut_error(z.to_f64()));
    }
    let deg = terminating_degree(a, b);
    if let Some(m) = nonpos_degree(c) {
        if deg.map_or(true, |d| d > m) {
            return Err(pole_error(c));
        }
    }
    if *z == 1 && deg.is_none() {
        let s = exact_sub(&exact_sub(c, a), b);
        if s <= 0 {
            return Err(Error::Divergent { function: "2F1(a, b; c; 1)", needs: "c - a - b > 0", value: s.to_f64() });
        }
    }
    Ok(())
}

/// Certified `2F1(a, b; c; z)` for real `z <= 1`, with `rad <= 2^-prec |mid|`.
pub fn hyp2f1_mp(a: &Float, b: &Float, c: &Float, z: &Float, prec: u32) -> Result<Ball> {
    check_prec(prec)?;
    validate(a, b, c, z)?;
    if z.is_zero() {
        return Ok(Ball::one(prec));
    }
    // `a |z|` far past `c` and `b |z|` (`dominant_param.rs`): every series and
    // connection formula runs to `~a` terms or meets Gamma at `c - a`
    // (`2F1(2^130, 1.5; 3; -2)`: TooExpensive otherwise)
    if z.is_sign_negative() {
        let wp = prec + DEFAULT_GUARD_BITS;
        let ball = |x: &Float| Ball::from_float(x, x.prec());
        if let Some(Ok(r)) = dominant_param::hyp2f1_dominant_param(&ball(a), &ball(b), &ball(c), &ball(z), wp) {
            if r.meets_rel(prec) {
                return Ok(r);
            }
        }
    }
    let (mut alg, mut lost) = plan(a, b, c, z, prec + DEFAULT_GUARD_BITS);
    if alg == Algorithm::LargeParam {
        let max_wp = prec.saturating_add(DEFAULT_GUARD_BITS + lost).saturating_add(MAX_GAMMA_LOSS);
        match ziv_up_to("hyp2f1", prec, DEFAULT_GUARD_BITS + lost, None, max_wp, |wp| evaluate(alg, a, b, c, z, wp)) {
            Ok(r) => return Ok(r),
            // a Gamma argument or series denominator too close to a pole at the
            // working precision: the region's own methods
            // (a refusal for time ends the call: the budget is spent either way)
            Err(e) if e.is_time_limit() => return Err(e),
            Err(_) => (alg, lost) = plan_regions(a, b, c, z, prec + DEFAULT_GUARD_BITS),
        }
    }
    if alg.uses_gamma() {
        // The Gamma-based formulas: refused when the planned cancellation passes
        // MAX_GAMMA_LOSS, and their Ziv loop stops MAX_GAMMA_LOSS bits past the plan.
        let first = prec.saturating_add(DEFAULT_GUARD_BITS + lost);
        const GAMMA_FORMULA: &str = "2F1 by a connection formula (Gamma values at the working precision its cancellation needs)";
        if lost > MAX_GAMMA_LOSS {
            return Err(Error::TooExpensive {
                function: GAMMA_FORMULA,
                seconds: gamma_seconds(first),
                limit_seconds: crate::budget::limit_seconds(gamma_seconds(MAX_GAMMA_LOSS)),
            });
        }
        // under a short time budget, the first Gamma's estimate against what is left
        crate::budget::check_estimate(GAMMA_FORMULA, gamma_seconds(first), f64::INFINITY)?;
        let max_wp = first.saturating_add(MAX_GAMMA_LOSS);
        return ziv_up_to("hyp2f1", prec, DEFAULT_GUARD_BITS + lost, None, max_wp, |wp| evaluate(alg, a, b, c, z, wp));
    }
    ziv("hyp2f1", prec, DEFAULT_GUARD_BITS + lost, |wp| evaluate(alg, a, b, c, z, wp))
}

/// Most bits of planned cancellation (`plan`'s loss estimate) for which
/// [`hyp2f1_mp`] runs a Gamma-based formula (the 1-z and 1-w connection formulas,
/// Gauss's sum); past it [`Error::TooExpensive`]. The pieces of a connection
/// formula can cancel by tens of thousands of bits at parameters like `4.3e18`
/// (`2F1(4311539713351952334, 27.59; 18.875; -15.375)` planned 65 536 bits), and
/// MPFR's first Gamma at `wp` bits takes about `0.7 (wp/8000)^3` s (measured,
/// `special::gamma`'s cost estimate): 0.7 s at 8000 bits, hours at 65 000. The loss is the cost model's estimate (the certified
/// bound never depends on it): the refusal is a cost decision about this method.
pub const MAX_GAMMA_LOSS: u32 = 8192;

/// Relative bound under which [`hyp2f1_bounded`] accepts the native result
/// (about 45 ulp: a looser bound is of little use in f64 work); above it the
/// double-word series, then MP.
pub const NATIVE_ACCEPT_REL: f64 = 1.0e-14;

/// Relative bound under which [`hyp2f1`] accepts the native f64 value. The
/// bound is a worst case over every rounding; the measured error of the values
/// it accepts stays below `1e-14` relative: worst `7.2e-15` over 100000 random
/// points of the benchmark domain (`docs/special-functions.md`). At `1e-13` the
/// worst measured was `1.1e-14`, at `5e-14` `9.9e-15` (too close), at `3e-14`
/// `4.2e-15` at 7% more time.
pub const NATIVE_VALUE_REL: f64 = 4.0e-14;

/// `2F1(a, b; c; z)` in f64 with a proven error bound for the f64 inputs as given:
/// the native f64 series with its running error bound (`native.rs`) where that
/// bound is at most [`NATIVE_ACCEPT_REL`] relative, otherwise the certified MP
/// value rounded, with `err = |mid - value| + rad`.
pub fn hyp2f1_bounded(a: f64, b: f64, c: f64, z: f64) -> Result<Bounded> {
    validate_f64(a, b, c, z)?;
    if z == 0.0 {
        return Ok(Bounded { value: 1.0, err: 0.0 });
    }
    if let Some(r) = native::hyp2f1_native(a, b, c, z, NATIVE_ACCEPT_REL) {
        return Ok(r);
    }
    mp_fallback(a, b, c, z, |name, guard, eval| crate::special::bounded_from_mp(name, guard, eval))
}

/// The MP fallback of the f64 functions ([`hyp2f1`], [`hyp2f1_bounded`]), counted
/// in [`crate::special::fallback_counts`]: the parameter cap
/// ([`F64_FALLBACK_MAX_PARAM`]), the plan at 64 bits, and `finish` (the f64
/// driver, whose Ziv loop stops at `F64_FALLBACK_MAX_WP`) on the chosen method.
fn mp_fallback<T>(
    a: f64,
    b: f64,
    c: f64,
    z: f64,
    finish: impl FnOnce(&'static str, u32, &dyn Fn(u32) -> Result<Ball>) -> Result<T>,
) -> Result<T> {
    check_fallback_params(a, b, c)?;
    crate::special::fallback::count(crate::special::F64Route::Hyp2f1);
    let (ae, be, ce, ze) = (exact(a), exact(b), exact(c), exact(z));
    let (alg, lost) = plan(&ae, &be, &ce, &ze, F64_FALLBACK_PREC + DEFAULT_GUARD_BITS);
    finish("hyp2f1", DEFAULT_GUARD_BITS + lost, &|wp| evaluate(alg, &ae, &be, &ce, &ze, wp))
}

/// The native f64 path alone: `Some` with a proven bound where it certifies
/// `err <= rel_tol |value|`, `None` where [`hyp2f1_bounded`] would fall back to MP
/// (for solvers that count or avoid the slow path). Errors as [`hyp2f1`].
pub fn hyp2f1_native_bounded(a: f64, b: f64, c: f64, z: f64, rel_tol: f64) -> Result<Option<Bounded>> {
    validate_f64(a, b, c, z)?;
    crate::special::check_rel_tol(rel_tol)?;
    if z == 0.0 {
        return Ok(Some(Bounded { value: 1.0, err: 0.0 }));
    }
    Ok(native::hyp2f1_native(a, b, c, z, rel_tol))
}

/// Checks f64 arguments as [`hyp2f1_mp`] does, in f64 arithmetic (no MPFR on
/// the native path): finite, `z <= 1`, `c` not a pole, and at `z = 1` (rare)
/// the exact sign of `c - a - b` through [`validate`].
fn validate_f64(a: f64, b: f64, c: f64, z: f64) -> Result<()> {
    finite(a, "a")?;
    finite(b, "b")?;
    finite(c, "c")?;
    finite(z, "z")?;
    if z == 1.0 {
        return validate(&exact(a), &exact(b), &exact(c), &exact(z));
    }
    if z > 1.0 {
        return Err(branch_cut_error(z));
    }
    let degree = |x: f64| (x <= 0.0 && x == power_f64::floor_any(x)).then(|| (-x) as u64);
    let deg = match (degree(a), degree(b)) {
        (Some(x), Some(y)) => Some(x.min(y)),
        (x, y) => x.or(y),
    };
    if let Some(m) = degree(c) {
        if deg.map_or(true, |d| d > m) {
            return Err(pole_error(&exact(c)));
        }
    }
    Ok(())
}

/// Largest `max(|a|, |b|, |c|)` that the f64 functions ([`hyp2f1`],
/// [`hyp2f1_bounded`]) hand to the MP fallback where the native path does not
/// certify. Beyond it that fallback took from 0.5 s (a series whose terms overflow
/// the exponent range) to minutes (65 536 bits and more, or 5 million terms) at
/// parameters like `1e10` or `1e300`, mostly to end in an error, and up to 6 s
/// at `1e5` (`examples/slow_corners.rs`; at `1e4` at most 0.8 s seen); the f64
/// functions refuse such arguments at once ([`Error::OutOfRange`]) and
/// [`hyp2f1_mp`] remains for them. (The native path answers any parameters it
/// certifies, e.g. `2F1(1.5, 1e300; 1e300; 0.5)`.)
pub const F64_FALLBACK_MAX_PARAM: f64 = 1.0e4;

/// [`F64_FALLBACK_MAX_PARAM`] for the MP fallback of the f64 functions.
fn check_fallback_params(a: f64, b: f64, c: f64) -> Result<()> {
    let m = a.abs().max(b.abs()).max(c.abs());
    if m > F64_FALLBACK_MAX_PARAM {
        return Err(Error::OutOfRange {
            arg: "max(|a|, |b|, |c|) of an f64 2F1 the native path does not certify (hyp2f1_mp takes larger ones)",
            value: m,
            allowed: crate::error::Interval::closed(0.0, F64_FALLBACK_MAX_PARAM),
        });
    }
    Ok(())
}

/// `2F1(a, b; c; z)` in f64 for real `z <= 1`: the value of [`hyp2f1_bounded`]
/// with the acceptance threshold [`NATIVE_VALUE_REL`] (proven bound at most
/// `4e-14` relative, measured error below `1e-14` over the benchmark domain, see
/// `docs/special-functions.md`); otherwise the certified 64-bit MP value rounded.
pub fn hyp2f1(a: f64, b: f64, c: f64, z: f64) -> Result<f64> {
    validate_f64(a, b, c, z)?;
    if z == 0.0 {
        return Ok(1.0);
    }
    if let Some(r) = native::hyp2f1_native(a, b, c, z, NATIVE_VALUE_REL) {
        return Ok(r.value);
    }
    mp_fallback(a, b, c, z, |name, guard, eval| f64_from_mp(name, guard, eval))
}
