//! `2F1` over balls of inputs (Arb's convention): the result contains
//! `2F1(a, b; c; z)` for every point of the input balls.
//!
//! # Edges inside the input balls (typed errors, never a number)
//!
//! * `c` a non-positive integer inside a non-exact `c` ball: a pole.
//! * `z > 1` inside the `z` ball: the branch cut.
//! * `z = 1` in the `z` ball of a non-terminating series: `c - a - b = 0` inside
//!   its ball ("may diverge"), or `c - a - b < 0` (diverges).
//!
//! # Input-radius propagation (proven)
//!
//! First, a value proven past the exponent range (`out_of_range.rs`: positive
//! parameters, `0 < z < 1`, one term of the series at least `2^emax`:
//! [`Error::ValueOutOfRange`] with that lower bound); one tiny parameter or a huge `c` (`small_parameter.rs`: the enclosure
//! `[1 - w, 1]` or `[1, 1 + w]` from Euler's integral, where `w` meets the
//! precision); `a |z|` past `c` and `b |z|` by more than the precision, `z < 0`
//! (`dominant_param.rs`: `Gamma(c)/Gamma(c-b) (a|z|)^(-b)` times a proven bracket
//! `[L, U]` around 1); `c` the same exact number as `b` (or `a`): `(1 - z)^(-a)` (or `^(-b)`).
//! Exact inputs go straight to [`hyp2f1_mp`](super::hyp2f1_mp). Otherwise:
//!
//! * **`-3/4 < z < 1`, `c > 0` on its ball** (majorant bound). With
//!   `A = max |a|`, `B = max |b|`, `C = min c`, `R = max |z|` over the balls,
//!   `|(a)_n| <= (A)_n`, `|(b)_n| <= (B)_n`, `(c)_n >= (C)_n`, so every term and
//!   every partial derivative of a term is dominated by the same object of the
//!   positive series `M(A, B; C; R) = 2F1(A, B; C; R)`. Its coefficients are
//!   polynomials in `A` with non-negative coefficients, so `M` is convex and
//!   increasing in `A`: `sup |d/da 2F1| <= dM/dA (A) <= M(A+1) - M(A) <= M(A+1)`;
//!   likewise for `b`. Where `a > 0` over its ball, `|d/da (a)_n| <= (A)_n n / a_lo`
//!   gives also `sup |d/da 2F1| <= (R / a_lo) dM/dR`, and the smaller is taken
//!   (likewise for `b`): at a parameter of `10^29217` the first is the majorant
//!   itself, the second `10^-29217` times it. A terminating series of degree `d`
//!   (the other parameter an exact `-d`) has only `k < d`, so the same holds
//!   with `-(b_hi + d - 1)` in place of `b_lo` when that is positive. `|d/dc (1/(c)_n)| <= n / ((C)_n C)` gives
//!   `sup |d/dc 2F1| <= (R/C) dM/dR`, and `sup |d/dz 2F1| <= dM/dR =
//!   (A B / C) 2F1(A+1, B+1; C+1; R)` [DLMF 15.5.1]. By the mean value theorem
//!   `|F(x) - F(mid)| <= sum_i sup|d_i F| rad_i`, added to the certified ball at
//!   the midpoints. The majorants are certified MP values at exact upper bounds
//!   (their ball's upper end is used).
//! * **`z < -2`**: the connection formula in `1/(1-z)` over the balls
//!   (`large_param.rs`; Gamma ratios with an integer difference as products,
//!   `c - a`, `c - b`, `a - b` with exact midpoints), then, for exact `a`, `b`
//!   with `b - a` an integer, the logarithmic formula after Pfaff over the balls
//!   (`log_case.rs`, "Over balls"); on an error, Pfaff below.
//! * **`z < -1/2`**: Pfaff [DLMF 15.8.1] in ball arithmetic,
//!   `(1-z)^{-a} 2F1(a, c-b; c; w)`, `w = z/(z-1)` in `(1/3, 1)`, the inner
//!   function by the majorant bound above.
//! * **`z = 1` exactly, `c - a - b > 0` on its ball**: Gauss's sum
//!   `Gamma(c) Gamma(c-a-b) / (Gamma(c-a) Gamma(c-b))` [DLMF 15.4.20] with
//!   `Gamma` over a pole-free ball `[m +/- r]`: `(ln|Gamma|)' = psi` is
//!   increasing between poles, so `|psi| <= M = max(|psi(lo)|, |psi(hi)|)` on the
//!   ball and `Gamma(x) in Gamma(m) [e^{-rM}, e^{rM}]`; a terminating series
//!   (`a = -n` exact) uses Chu-Vandermonde `(c-b)_n / (c)_n` [DLMF 15.4.24].
//!
//! * **`c <= 0` somewhere on a non-exact `c` ball, `|z| <= 1/2`**: the series in
//!   ball arithmetic (`pfq::hyp_pfq_ball_mp`), a pole inside the `c` ball an error.
//!
//! Not covered (a typed error says so): non-exact balls with `c <= 0` somewhere
//! on the ball and `|z| > 1/2` after the transformation (at `w = 0.992` the ball
//! series ran for minutes), `z` balls that straddle `-3/4 .. -1/2` and beyond, `z` balls
//! reaching 1 that are not exactly 1, and at `z = 1` a `c - a` or `c - b` ball
//! containing a non-positive integer.

use rug::float::Round;
use rug::Float;

use super::choose::{evaluate, plan, plan_regions, Algorithm};
use super::dominant_param::hyp2f1_dominant_param;
use super::out_of_range::proven_above_range;
use super::small_parameter::hyp2f1_small_parameter;
use super::log_case::hyp2f1_log_case_balls;
use super::large_param::{hyp2f1_large_param, large_param_cheaper, large_param_loss, large_param_terms};
use super::{hyp2f1_mp, validate};
use crate::ball::{Ball, Mag, Scaled};
use crate::error::{check_prec, Error, Interval, Result};
use crate::special::gamma::gamma_pair_scaled;
use crate::special::{is_nonpositive_integer, ziv_ball_inputs, DEFAULT_GUARD_BITS};

/// Precision of the majorant evaluations (only upper bounds are needed).
const MAJORANT_PREC: u32 = 32;

/// Most bits of planned cancellation a majorant evaluation pays for (beyond, its
/// ball is wider: still an upper bound).
const MAJORANT_MAX_LOST: u32 = 512;

/// Correct bits a majorant evaluation aims at.
const MAJORANT_ACCURACY: u32 = 8;

/// Highest working precision of a majorant evaluation.
const MAJORANT_MAX_WP: u32 = 4096;

/// Extra bits of the ball arithmetic around the midpoint evaluation.
const BALL_GUARD: u32 = 32;

/// Below `z = -FAR_NEGATIVE` the ball path tries the connection formula in
/// `1/(1-z)` (at most 1/3) before Pfaff.
const FAR_NEGATIVE: f64 = 2.0;

/// [`Error::BallOutOfRange`] for the ball `x` named `arg`.
fn ball_outside(arg: &'static str, x: &Ball, allowed: Interval) -> Error {
    Error::BallOutOfRange { arg, lower: x.lower().to_f64(), upper: x.upper().to_f64(), allowed }
}

/// [`Error::BallTooWide`] for the ball `x` named `arg`.
fn too_wide(arg: &'static str, x: &Ball, needs: &'static str) -> Error {
    Error::BallTooWide { arg, lower: x.lower().to_f64(), upper: x.upper().to_f64(), needs }
}

/// Whether the ball contains an integer `<= 0`.
fn contains_nonpositive_integer(x: &Ball) -> bool {
    crate::special::pfq::contains_pole(x, None).is_some()
}

/// `d` when the ball is exactly the non-positive integer `-d`.
fn exact_degree(x: &Ball) -> Option<u64> {
    (x.is_exact() && is_nonpositive_integer(x.mid())).then(|| (-x.mid().to_f64()) as u64)
}

/// Certified `2F1(a, b; c; z)` over balls of inputs (see the module docs): the
/// result contains the function at every point of the balls, or an error names
/// the edge (pole, branch cut, divergence at `z = 1`) that lies inside them.
pub fn hyp2f1_ball_mp(a: &Ball, b: &Ball, c: &Ball, z: &Ball, prec: u32) -> Result<Ball> {
    check_prec(prec)?;
    for (x, what) in [(a, "a"), (b, "b"), (c, "c"), (z, "z")] {
        if !x.is_finite() {
            return Err(Error::NonFinite { what });
        }
    }
    // a value proven past the exponent range (`out_of_range.rs`): positive
    // parameters, `0 < z < 1`, `F >= t_n >= 2^emax` (`c` equal to `b`: the power
    // below, which names the size itself)
    if equal_to_c(a, b, c).is_none() {
        if let Some(e) = proven_above_range(a, b, c, z) {
            return Err(e);
        }
    }
    if let Some(r) = hyp2f1_small_parameter(a, b, c, z, prec) {
        return Ok(r);
    }
    // `a |z|` past `c` and `b |z|` by more than the precision (`dominant_param.rs`):
    // `2F1(2.7e24591, 27.39; 2.9e599; -8)`, where the connection formula's Gammas
    // at `c - a`, `b - a` hold poles
    if let Some(r) = hyp2f1_dominant_param(a, b, c, z, prec + BALL_GUARD) {
        return r;
    }
    if [a, b, c, z].iter().all(|x| x.is_exact()) {
        return hyp2f1_mp(a.mid(), b.mid(), c.mid(), z.mid(), prec);
    }
    let terminating = exact_degree(a).or(exact_degree(b));
    check_edges(a, b, c, z, terminating)?;
    if terminating == Some(0) {
        // 2F1(0, b; c; z) = 1 for every b, c, z (the series' one term)
        return Ok(Ball::one(prec));
    }
    let wp = prec + BALL_GUARD;
    if let Some(e) = equal_to_c(a, b, c) {
        if z.upper() < 1 {
            // 2F1(a, b; b; z) = (1 - z)^(-a) [DLMF 15.4.6], `c` the same exact
            // number as `b` (or `a`): `2F1(9.2e18, 23.5; 9.2e18; -243.875) =
            // 244.875^(-23.5)` went through Pfaff's inner function past the range
            // (issue 37's scan: `Overflow`); a power past the range is the value's
            // (`1 - z` formed exactly: `Scaled::pow` takes `ln` of the base at the
            // bits it needs, and `1 - 1e-1000` rounded to `wp` bits would be 1)
            let bits = z.mid().get_exp().map_or(0, |x| -i64::from(x)).max(0) + i64::from(z.mid().prec()) + 4;
            let omz = Ball::one(bits.min(1 << 20) as u32).sub(z);
            return Scaled::pow(&omz, &e.neg(), wp)?.to_value(prec);
        }
    }
    if z.is_exact() && *z.mid() == 1 {
        return gauss_ball(a, b, c, terminating, wp);
    }
    if let Some(r) = large_param_ball(a, b, c, z, prec) {
        return r;
    }
    if z.lower() > -0.75 && z.upper() < 1 {
        return direct_ball(a, b, c, z, wp);
    }
    if z.upper() < -FAR_NEGATIVE {
        // The connection formula in `u = 1/(1-z)` over the balls (the
        // large-parameter route's formula, `large_param.rs`, valid for any
        // parameters): Pfaff's `w = 1 - u` is next to 1 there, where the
        // majorant's derivative grows like `(1-R)^(C-A-B-1)` and no input
        // precision pins the value: `2F1(26.13, 38; 1.5; -1.0875e16464)` was
        // refused PrecisionExhausted at 65 536 input bits (issue 37's scan, about
        // 20 of 20 000 inputs a seed). On an error (an integer inside `b - a`, a
        // Gamma pole) Pfaff below.
        let loss = large_param_loss(a.mid().to_f64(), b.mid().to_f64(), c.mid().to_f64(), z.mid().to_f64());
        if let Ok(r) = ziv_ball_inputs(prec, DEFAULT_GUARD_BITS + loss, None, |wp| hyp2f1_large_param(a, b, c, z, wp)) {
            return Ok(r);
        }
        // `b - a` an integer with `a`, `b` exact (the formula above needs
        // `Gamma(b - a)`): the logarithmic formula after Pfaff over the balls
        // (`log_case.rs`); `2F1(-140.625, 242.375; 27.07; -1e10556)` was refused
        // PrecisionExhausted (Pfaff's `w` within `1e-10556` of 1)
        if let Ok(r) = ziv_ball_inputs(prec, DEFAULT_GUARD_BITS, None, |wp| hyp2f1_log_case_balls(a, b, c, z, wp)) {
            return Ok(r);
        }
    }
    if z.upper() < -0.5 {
        // Pfaff: (1-z)^{-a} 2F1(a, c-b; c; w), w = z/(z-1) = -z/(1-z).
        // 2F1 is symmetric in a and b: a terminating parameter (the lower
        // degree) is taken as `a`, so that the prefactor is `(1-z)^d` and the
        // inner function a polynomial of degree `d`. Taken the other way, at
        // `2F1(8.3e17, -1; 26.78; -20) = 1 + 6.2e17` the prefactor
        // `21^(-8.3e17)` and the inner function, about its reciprocal, each
        // passed the exponent range (issue 37's scan: `Overflow`).
        let (a, b) = match (exact_degree(a), exact_degree(b)) {
            (None, Some(_)) => (b, a),
            (Some(da), Some(db)) if db < da => (b, a),
            _ => (a, b),
        };
        let omz = Ball::one(wp).sub(z);
        let w = z.div(&omz)?.neg();
        let inner = direct_ball(a, &c.sub(b), c, &w, wp)?;
        // at `wp` bits: `1 - z` of a decimal `z` tightened to 54 000 bits made
        // `ln` and `exp` run at that length (50 ms, issue 37's scan)
        // the prefactor in logarithms where it passes the exponent range
        // (`(1 - z)^(-7.4e17)`), the product formed once (`Scaled`)
        let pre = Scaled::pow(&omz, &a.neg(), wp)?;
        return pre.mul_ball(&inner).to_value(wp);
    }
    Err(too_wide("z", z, "within (-3/4, 1) or below -1/2"))
}

/// The other upper parameter when `c` and `b` (or `a`) are the same exact number.
fn equal_to_c<'a>(a: &'a Ball, b: &'a Ball, c: &Ball) -> Option<&'a Ball> {
    // (at a non-positive integer `c` the terminating convention applies instead:
    // `2F1(a, -3; -3; z)` is the series cut after `n = 3`)
    if !c.is_exact() || is_nonpositive_integer(c.mid()) {
        return None;
    }
    if b.is_exact() && b.mid() == c.mid() {
        Some(a)
    } else if a.is_exact() && a.mid() == c.mid() {
        Some(b)
    } else {
        None
    }
}

/// One large parameter (`large_param.rs`), when the chooser's estimate at the
/// midpoints takes it: its formula runs in ball arithmetic over the input balls,
/// so no majorant is needed (the majorant `2F1(A, B; C; |z|)` at `B = 10^6`,
/// `|z| = 1/2` is about `2^(10^6)` times the value). `None` when it does not
/// apply or fails (an integer inside `b - a` or `c - a - b`, a Gamma argument
/// ball holding a pole): the majorant route then.
fn large_param_ball(a: &Ball, b: &Ball, c: &Ball, z: &Ball, prec: u32) -> Option<Result<Ball>> {
    let (af, bf, cf, zf) = (a.mid().to_f64(), b.mid().to_f64(), c.mid().to_f64(), z.mid().to_f64());
    let terms = large_param_terms(af, bf, cf, zf, f64::from(prec))?;
    if !large_param_cheaper(af, bf, zf, terms) && c.lower() > 0 {
        // the series in `z` with its majorant (`c > 0` over the ball) is short
        // at `big |z|` below the route's term count: `2F1(-47.3, 1e4; 12.9; -0.05)`
        // summed 2 x 7700 terms of ball arithmetic in `u = 0.95` (55 ms at 64
        // bits), where the series in `z` peaks near `n = big |z| = 500` (2 ms).
        // Not for `c < 0`: the ball series that `direct_ball` sums there loses
        // the peak term's size to its radius (`2F1(3.7, 1e4; -33.45; -0.05)`:
        // three tighter input balls, 42 ms)
        return None;
    }
    if z.contains_zero() || !(z.upper() < 1) {
        return None;
    }
    let loss = if af.abs() >= bf.abs() { large_param_loss(bf, af, cf, zf) } else { large_param_loss(af, bf, cf, zf) };
    let guard = DEFAULT_GUARD_BITS + loss;
    // Input balls too wide for `prec` bits after the planned loss (the decimal
    // path's first round holds its decimals at `prec + 64` bits; each term's
    // input perturbation is bounded against the sum of `|t_n|`, which the
    // cancelling series exceeds by the loss): one round, whose ball the decimal
    // loop reads to tighten its inputs. A second round at more working
    // precision would shrink nothing (`2F1(-47.3, 1e6; 12.9; -0.05)` at 256
    // bits ran rounds at 561, 866, then 561 bits on tighter inputs).
    let input_bits = [a, b, c, z].iter().map(|x| x.rel_accuracy_bits()).fold(f64::INFINITY, f64::min);
    let r = if input_bits < f64::from(prec) + f64::from(loss) {
        crate::budget::ensure(|| hyp2f1_large_param(a, b, c, z, prec.saturating_add(guard).min(crate::special::MAX_WORKING_PREC)))
    } else {
        ziv_ball_inputs(prec, guard, None, |wp| hyp2f1_large_param(a, b, c, z, wp))
    };
    r.ok().map(Ok)
}

/// The edges of the module docs; `terminating` is the degree when `a` or `b` is
/// an exact non-positive integer.
fn check_edges(a: &Ball, b: &Ball, c: &Ball, z: &Ball, terminating: Option<u64>) -> Result<()> {
    if z.upper() > 1 {
        // z > 1: the branch cut [1, inf) of the principal branch.
        return Err(ball_outside("z", z, Interval::at_most(1.0)));
    }
    if c.is_exact() {
        if let Some(m) = exact_degree(c) {
            if terminating.map_or(true, |d| d > m) {
                return validate(a.mid(), b.mid(), c.mid(), z.mid());
            }
        }
    } else if contains_nonpositive_integer(c) {
        let pole = Float::with_val(64, c.lower().ceil_ref()).to_f64();
        return Err(Error::ParameterPole {
            function: "2F1",
            arg: "c",
            pole,
            lower: c.lower().to_f64(),
            upper: c.upper().to_f64(),
        });
    }
    if z.upper() == 1 && terminating.is_none() {
        let s = c.sub(a).sub(b);
        if s.lower() <= 0 && s.upper() >= 0 {
            return Err(Error::Divergent {
                function: "2F1(a, b; c; 1) over balls",
                needs: "c - a - b > 0 over the whole ball",
                value: s.lower().to_f64(),
            });
        }
        if s.upper() < 0 {
            return Err(Error::Divergent { function: "2F1(a, b; c; 1)", needs: "c - a - b > 0", value: s.mid().to_f64() });
        }
        if !z.is_exact() {
            // z = 1 within a non-exact ball: give z exactly or below 1.
            return Err(ball_outside("z", z, Interval { lo: f64::NEG_INFINITY, hi: 1.0, lo_closed: false, hi_closed: false }));
        }
    }
    Ok(())
}

/// Upper bound of `|x|` over a ball, as an exact float.
fn abs_max(x: &Ball) -> Float {
    let lo = x.lower().abs();
    let hi = x.upper().abs();
    if lo > hi {
        lo
    } else {
        hi
    }
}

/// Upper end of the certified `2F1(p, q; r; x)` at exact points (a majorant):
/// the planned method at [`MAJORANT_PREC`] bits plus the planned loss (at most
/// [`MAJORANT_MAX_LOST`]), doubled while the ball has fewer than
/// [`MAJORANT_ACCURACY`] correct bits, up to [`MAJORANT_MAX_WP`] (a Ziv loop to 32
/// correct bits climbed to 65 592 bits and took minutes at `2F1(1, 1.35e18; 21.3;
/// 1 - 2^-52)`, whose pieces cancel): a wide ball's upper end is as valid a bound,
/// it only asks more digits of the input balls.
fn majorant(p: &Float, q: &Float, r: &Float, x: &Float) -> Result<Mag> {
    // a majorant past the exponent range is this bound's cap, never the value's
    majorant_value(p, q, r, x).map_err(crate::ball::intermediate)
}

/// [`majorant`] before its errors are read as an intermediate's.
fn majorant_value(p: &Float, q: &Float, r: &Float, x: &Float) -> Result<Mag> {
    validate(p, q, r, x)?;
    if x.is_zero() {
        return Ok(Mag::pow2(0));
    }
    let (mut alg, lost) = plan(p, q, r, x, MAJORANT_PREC);
    let mut wp = MAJORANT_PREC + DEFAULT_GUARD_BITS + lost.min(MAJORANT_MAX_LOST);
    let mut m = match evaluate(alg, p, q, r, x, wp) {
        // the large-parameter route can meet a Gamma argument or a series
        // denominator next to a pole (`2F1(100001, 1.8e-202; 41.375; -38.125)`:
        // Gamma near -100002): the region's own methods, as `hyp2f1_mp` does
        Err(e) if alg == Algorithm::LargeParam && !e.is_time_limit() => {
            let (regional, lost) = plan_regions(p, q, r, x, MAJORANT_PREC);
            alg = regional;
            wp = MAJORANT_PREC + DEFAULT_GUARD_BITS + lost.min(MAJORANT_MAX_LOST);
            evaluate(alg, p, q, r, x, wp)?
        }
        other => other?,
    };
    // a little accuracy keeps the bound tight (a loose one asks the input balls
    // for many more bits, and long parameters slow every later evaluation)
    while !m.meets_rel(MAJORANT_ACCURACY) && wp < MAJORANT_MAX_WP {
        wp = (2 * wp).min(MAJORANT_MAX_WP);
        m = evaluate(alg, p, q, r, x, wp)?;
    }
    let up = m.upper();
    if !up.is_finite() {
        return Err(Error::Overflow { what: "a majorant of the 2F1 input-radius bound".into() });
    }
    Ok(Mag::from_float_up(&up))
}

/// `p + 1`, rounded up.
fn plus_one_up(p: &Float) -> Float {
    Float::with_val_round(p.prec().max(64), p + 1u32, Round::Up).0
}

/// The majorant bound of the module docs for `-3/4 < z < 1`, `c > 0` on its ball.
/// With `a = -d` exact (or `b`), `M = 2F1(-d, B; C; -R)` (terms `|(-d)_n| (B)_n R^n
/// / ((C)_n n!)`, a polynomial) and `dM/dR = (d B / C) 2F1(1-d, B+1; C+1; -R)`
/// replace the non-terminating majorant; `a = 0` or `b = 0` exact is exactly 1.
fn direct_ball(a: &Ball, b: &Ball, c: &Ball, z: &Ball, wp: u32) -> Result<Ball> {
    if [a, b, c, z].iter().all(|x| x.is_exact()) {
        // (an inner function after Pfaff may be out of range where the value is not)
        return hyp2f1_mp(a.mid(), b.mid(), c.mid(), z.mid(), wp).map_err(crate::ball::intermediate);
    }
    let c_lo = c.lower();
    if !(c_lo > 0) {
        // The majorant needs c > 0 over the ball. Otherwise (c < 0 between
        // poles, |z| <= 1/2: a bounded term count) the series itself in ball arithmetic (pFq's ball path:
        // ball terms, a tail bound valid over the balls, a cost check before
        // summing); a pole inside the c ball stays an error. Checked before the
        // midpoint evaluation, which can cost far more than the check.
        if z.abs_upper() <= 0.5 {
            let inputs = [a, b, c, z].map(|x| crate::special::input_ball(x, wp));
            return crate::special::pfq::hyp_pfq_ball_mp(&inputs[..2], &inputs[2..3], &inputs[3], wp);
        }
        return Err(ball_outside("c", c, Interval::above(0.0)));
    }
    let (deg_a, deg_b) = (exact_degree(a), exact_degree(b));
    if deg_a == Some(0) || deg_b == Some(0) {
        return Ok(Ball::one(wp));
    }
    let (aa, bb, rr) = (abs_max(a), abs_max(b), abs_max(z));
    if !(rr < 1) {
        return Err(too_wide("z", z, "|z| < 1 over the ball after the transformation"));
    }
    let mut out = hyp2f1_mp(a.mid(), b.mid(), c.mid(), z.mid(), wp).map_err(crate::ball::intermediate)?;
    // The majorant's parameters: A (or -d, exact, with x = -R) and its shift by one.
    let terminating = deg_a.is_some() || deg_b.is_some();
    let param = |x: &Ball, big: &Float| if exact_degree(x).is_some() { x.mid().clone() } else { big.clone() };
    let shift = |x: &Ball, big: &Float| {
        if exact_degree(x).is_some() {
            Float::with_val(x.mid().prec().max(64), x.mid() + 1u32)
        } else {
            plus_one_up(big)
        }
    };
    let (pa, pb) = (param(a, &aa), param(b, &bb));
    let (pa1, pb1) = (shift(a, &aa), shift(b, &bb));
    let x = if terminating { Float::with_val(rr.prec(), -&rr) } else { rr.clone() };
    let mut err = Mag::ZERO;
    // dM/dR = (A B / C) 2F1(A+1, B+1; C+1; R), when a radius needs it
    let needs_d_r = !c.is_exact() || !z.is_exact() || [a, b].iter().any(|x| !x.is_exact());
    let d_r = if needs_d_r {
        let c1 = Float::with_val_round(c_lo.prec().max(64), &c_lo + 1u32, Round::Down).0;
        Some(majorant(&pa1, &pb1, &c1, &x)?.mul(Mag::from_float_up(&aa)).mul(Mag::from_float_up(&bb)).div(Mag::from_float_down(&c_lo)))
    } else {
        None
    };
    // `d/da`: `M(A+1) - M(A) <= M(A+1)`, or for `a > 0` over its ball, where
    // `|d/da (a)_n| <= (A)_n n / a_lo`, the sharper `(R / a_lo) dM/dR` (as for
    // `c`): at `b` of 97 000 bits held at 65 536 (`c - b` after Pfaff of a
    // decimal `c = 3.4e29217`, radius `2^31464`) the first is `2^31464` times the
    // value, the second `2^-65536` (issue 37's scan: PrecisionExhausted before)
    // With a terminating series of degree `d` (the other parameter an exact `-d`)
    // only `k < d` enter, so `p` with `p + d - 1 < 0` over its ball has
    // `|p + k| >= -(p_hi + d - 1)` there: the same bound with that distance
    // (`2F1(-1, 1.9e22735; 5e-309; -7) = 1 + 7 b / c`: PrecisionExhausted before).
    let degree = deg_a.or(deg_b);
    let distance = |p: &Ball| -> Option<Float> {
        let lo = p.lower();
        if lo > 0 {
            return Some(lo.clone());
        }
        let d = degree?;
        let top = Float::with_val_round(p.upper().prec().max(64), p.upper() + d.saturating_sub(1), Round::Up).0;
        (top < 0).then(|| -top)
    };
    let param_err = |p: &Ball, shifted: Mag| -> Mag {
        match (&d_r, distance(p)) {
            (Some(d), Some(lo)) => {
                let sharp = d.mul(Mag::from_float_up(&rr)).div(Mag::from_float_down(&lo));
                if sharp.le(&shifted) {
                    sharp
                } else {
                    shifted
                }
            }
            _ => shifted,
        }
        .mul(p.rad_mag())
    };
    if !a.is_exact() {
        err = err.add(param_err(a, majorant(&pa1, &pb, &c_lo, &x)?));
    }
    if !b.is_exact() {
        err = err.add(param_err(b, majorant(&pa, &pb1, &c_lo, &x)?));
    }
    if let Some(d_r) = d_r {
        if !z.is_exact() {
            err = err.add(d_r.mul(z.rad_mag()));
        }
        if !c.is_exact() {
            let d_c = d_r.mul(Mag::from_float_up(&rr)).div(Mag::from_float_down(&c_lo));
            err = err.add(d_c.mul(c.rad_mag()));
        }
    }
    out.add_error_mag(err);
    Ok(out)
}

/// A Gamma argument ball of Gauss's sum that holds a pole, named as a parameter
/// pole (an exact pole is the Gamma's own error later).
fn no_parameter_pole(x: &Ball) -> Result<()> {
    if !x.is_exact() && contains_nonpositive_integer(x) {
        return Err(Error::ParameterPole {
            function: "2F1(a, b; c; 1) over balls",
            arg: "a Gamma argument (c, c - a - b, c - a or c - b)",
            pole: Float::with_val(64, x.lower().ceil_ref()).to_f64(),
            lower: x.lower().to_f64(),
            upper: x.upper().to_f64(),
        });
    }
    Ok(())
}

/// Gauss's sum (or Chu-Vandermonde) at `z = 1` over balls of parameters.
fn gauss_ball(a: &Ball, b: &Ball, c: &Ball, terminating: Option<u64>, wp: u32) -> Result<Ball> {
    if let Some(n) = terminating {
        // 2F1(-n, b; c; 1) = (c-b)_n / (c)_n (with a and b swapped when b = -n).
        let other = if exact_degree(a) == Some(n) { b } else { a };
        let cb = c.sub(other);
        let (mut num, mut den) = (Ball::one(wp), Ball::one(wp));
        for k in 0..n as i64 {
            num = num.mul(&cb.add_i64(k));
            den = den.mul(&c.add_i64(k));
        }
        return num.div(&den);
    }
    // Gamma(c) / Gamma(c - a) and Gamma(c - a - b) / Gamma(c - b), each pair by
    // its difference `a` (`gamma_pair_scaled`: at c = 10^20000 the radius of c
    // would otherwise enter both logarithms, and the bits they need are those of
    // `a ln c`, not `c ln c`)
    let (ca, cb) = (c.sub(a), c.sub(b));
    let s = ca.sub(b);
    for x in [c, &s, &ca, &cb] {
        no_parameter_pole(x)?;
    }
    let first = gamma_pair_scaled(c, &ca, a, wp)?;
    let second = gamma_pair_scaled(&s, &cb, &a.neg(), wp)?;
    first.mul(&second).to_value(wp)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ball::{eval_at_decimals, Decimal};

    fn dec(s: &str) -> Decimal {
        Decimal::parse(s).unwrap()
    }

    fn at_decimals(a: &str, b: &str, c: &str, z: &str, prec: u32) -> Result<Ball> {
        eval_at_decimals(&[dec(a), dec(b), dec(c), dec(z)], prec, |x| hyp2f1_ball_mp(&x[0], &x[1], &x[2], &x[3], prec))
    }

    #[test]
    fn edges_inside_the_ball_are_errors_at_every_precision() {
        for prec in [2, 16, 53, 64, 128, 256, 1000] {
            // c - a - b = 0 inside the balls at z = 1.
            let e = at_decimals("0.3", "0.7", "1", "1", prec).unwrap_err();
            assert!(matches!(e, Error::Divergent { needs: "c - a - b > 0 over the whole ball", .. }), "{prec}: {e:?}");
            assert!(e.to_string().contains("diverges"), "{prec}: {e}");
            let e = at_decimals("0.5", "0.25", "-2", "0.5", prec).unwrap_err();
            assert!(matches!(e, Error::ParameterPole { arg: "c", pole: -2.0, .. }), "{prec}: {e:?}");
            assert!(e.to_string().contains("pole"), "{prec}: {e}");
            let e = at_decimals("0.3", "0.9", "1", "1", prec).unwrap_err();
            assert!(matches!(e, Error::Divergent { needs: "c - a - b > 0", .. }), "{prec}: {e:?}");
        }
        let ball = |m: f64, r: f64| Ball::with_radius(Float::with_val(64, m), &Float::with_val(64, r));
        let (one, three) = (Ball::one(64), Ball::from_i64(3, 64));
        // The branch cut z > 1 inside the z ball.
        let e = hyp2f1_ball_mp(&one, &one, &three, &ball(0.9, 0.2), 64).unwrap_err();
        assert!(matches!(e, Error::BallOutOfRange { arg: "z", allowed: Interval { hi: 1.0, .. }, .. }), "{e:?}");
        let e = hyp2f1_ball_mp(&one, &one, &ball(-2.0, 1e-30), &ball(0.5, 0.0), 64).unwrap_err();
        assert!(matches!(e, Error::ParameterPole { arg: "c", pole: -2.0, .. }), "{e:?}");
        assert!(e.to_string().contains("c = -2") && e.to_string().contains("pole"), "{e}");
    }

    #[test]
    fn encloses_the_function_at_the_decimal_typed() {
        // 2F1(1, 2; 2; z) = 1/(1 - z): at z = 0.99999999999999999999 exactly 1e20.
        for prec in [53, 128, 300] {
            let b = at_decimals("1", "2", "2", "0.99999999999999999999", prec).unwrap();
            assert!(b.contains(&Float::with_val(200, 1e20)), "{prec}: {b:?}");
            assert!(b.meets_rel(prec), "{prec}: {b:?}");
        }
        // 2F1(1, 1/2; 2; z) = 2 (1 - sqrt(1 - z)) / z at the same z (issue 8's example).
        let z = dec("0.99999999999999999999");
        let zq = Float::with_val(400, z.as_rational());
        let want = Float::with_val(400, 2 * (1 - Float::with_val(400, 1 - &zq).sqrt()) / &zq);
        let b = at_decimals("1", "0.5", "2", "0.99999999999999999999", 128).unwrap();
        assert!(b.contains(&want), "{b:?} vs {want}");
        // Gauss's sum at z = 1 with decimal parameters: 2F1(0.1, 0.2; 1.3; 1) = G(1.3) G(1) / (G(1.2) G(1.1)).
        let q = |s: &str| Float::with_val(400, dec(s).as_rational());
        let want = Float::with_val(400, q("1.3").gamma() * q("1").gamma() / (q("1.2").gamma() * q("1.1").gamma()));
        let b = at_decimals("0.1", "0.2", "1.3", "1", 100).unwrap();
        assert!(b.contains(&want) && b.meets_rel(100), "{b:?} vs {want}");
        // Pfaff region with decimal inputs vs the exact-input value at a nearby binary point.
        let b = at_decimals("0.3", "-1.7", "2.9", "-3.1", 128).unwrap();
        let q3 = |s: &str| Float::with_val(300, dec(s).as_rational());
        let m = hyp2f1_mp(&q3("0.3"), &q3("-1.7"), &q3("2.9"), &q3("-3.1"), 200).unwrap();
        assert!(b.overlaps(&m) && b.meets_rel(128), "{b:?} vs {m:?}");
    }

    /// `c` the same exact number as `a` (or `b`): `(1 - z)^(-b)`, against the power
    /// of the decimals as typed (issue 37's scan refused the first `Overflow`), and
    /// a power past the exponent range refused as the value's.
    #[test]
    fn c_equal_to_a_is_the_power() {
        let (b, z) = ("23.501833939562957", "-243.875");
        for prec in [2, 8, 53, 128] {
            let r = at_decimals("9223372036854775807", b, "9223372036854775807", z, prec).unwrap();
            let bq = Float::with_val(600, dec(b).as_rational());
            let want = rug::ops::Pow::pow(Float::with_val(600, 244.875f64), -bq);
            assert!(r.contains(&want) && r.meets_rel(prec), "{prec}: {r:?} against {want:.30}");
        }
        // 2F1(2.425e1022, 2.5; 2.5; 1e-1000) = (1 - z)^(-a) = 2^(a z / ln 2 (1 + O(z)))
        let want = 2.425e22 / std::f64::consts::LN_2;
        for prec in [8, 53] {
            let e = at_decimals("242.5e1020", "2.5", "2.5", "1e-1000", prec).unwrap_err();
            assert!(matches!(e, Error::ValueOutOfRange { log2_magnitude } if (log2_magnitude.to_f64() / want - 1.0).abs() < 1e-9), "{e:?}");
        }
    }

    /// `c - a` an exact non-positive integer below `z = -2`: the connection
    /// formula's first term vanishes (`1/Gamma(c - a) = 0`); issue 37's scan refused
    /// `2F1(2, 29.65; 1; -5.4e7163)` PrecisionExhausted. Against Euler's closed form
    /// `(1-z)^(-1-b) (1 + (b-1) z)` [DLMF 15.8.1] from the decimals as typed.
    #[test]
    fn c_minus_a_a_pole_drops_its_term() {
        let (b, z) = ("29.650647073042535", "-53.75e7162");
        let (bq, zq) = (Float::with_val(4000, dec(b).as_rational()), Float::with_val(4000, dec(z).as_rational()));
        let omz = Float::with_val(4000, 1 - &zq);
        let pow = Float::with_val(4000, Float::with_val(4000, -(Float::with_val(4000, &bq + 1u32)) * omz.ln()).exp());
        let want = Float::with_val(4000, &pow * Float::with_val(4000, 1 + Float::with_val(4000, &bq - 1u32) * &zq));
        for prec in [8, 53, 109] {
            let r = at_decimals("2", b, "1", z, prec).unwrap_or_else(|e| panic!("{prec}: {e:?}"));
            assert!(r.contains(&want) && r.meets_rel(prec), "{prec}: {r:?} against {want:.30}");
        }
    }

    /// A terminating `b = -d` with a huge `a` in the Pfaff region (issue 37's
    /// scan refused these as `Overflow`): the value is the polynomial
    /// `sum_k (a)_k (-d)_k / ((c)_k k!) z^k`, summed here in exact rationals
    /// from the decimals as typed.
    #[test]
    fn a_terminating_b_with_a_huge_a_below_minus_one_answers() {
        use rug::Rational;
        for (a, d, c, z) in [
            ("834858075317145057", 1u32, "26.78491247857184", "-20"),
            ("2781327933789835835", 17, "26.540264011134894", "-4"),
            ("3711248345017201267", 1, "2.6229905839978656e1", "-125.5"),
        ] {
            let q = |s: &str| dec(s).as_rational().clone();
            let (aq, cq, zq) = (q(a), q(c), q(z));
            let (mut term, mut sum) = (Rational::from(1), Rational::from(1));
            for k in 0..d {
                term *= Rational::from(&aq + k) * Rational::from(k as i64 - d as i64) * &zq;
                term /= Rational::from(&cq + k) * Rational::from(k + 1);
                sum += &term;
            }
            let want = Float::with_val(4096, &sum);
            for prec in [8, 53, 128] {
                let r = at_decimals(a, &format!("-{d}"), c, z, prec).unwrap_or_else(|e| panic!("2F1({a}, -{d}; {c}; {z}) at {prec}: {e:?}"));
                assert!(r.contains(&want) && r.meets_rel(prec), "2F1({a}, -{d}; {c}; {z}) at {prec}: {r:?} against {want:.20}");
            }
        }
    }
}
