//! The Bessel form of `u_w` and `du_w/dx` (module docs of [`super`], route 2)
//! in arbitrary precision: certified balls for exact and ball inputs, and the
//! term count with its rigorous tails that the f64 bounded path also uses.
//!
//! Error bound: `|J_{2n}(D)| <= (D/2)^{2n}/(2n)!` [DLMF 10.14.4] bounds both
//! tails geometrically once the ratio is below 1/2 (the first neglected term
//! bounded through `k! >= sqrt(2 pi k) (k/e)^k` [DLMF 5.6.1]); the sequence
//! `J_0 .. J_{2N}` comes from the midpoint recurrence
//! ([`bessel_j_sequence_three_term`]: radii near `2^-wp D^2` where the ball
//! recurrence lost about `0.68 D` bits); `J_n` at a ball `D` is
//! widened by `rad(D)` (`|J_n'| <= 1`, DLMF 10.14.1); the Ziv loop raises the
//! working precision until the ball meets the requested relative accuracy (or
//! the absolute floor `2^-prec` times the natural scale).

use rug::float::Round;
use rug::Float;

use crate::ball::{Ball, MAG_PREC};
use crate::error::{Error, Interval, Reached, Result};
use crate::special::bessel_j::{bessel_j_sequence_mp, bessel_j_sequence_three_term, MAX_SEQUENCE_ORDER};
use crate::special::{ziv_up_to, DEFAULT_GUARD_BITS};
use crate::MAX_WORKING_PREC;

use super::geometry::{check_wave_mp, check_wave_number, geometry_from_balls, gradient_scale, wave_geometry, WaveGeometry};

// ---------------------------------------------------------------- Bessel form

/// Upper bound (as f64, rounded up generously) of `sum_{n>N} weight(n) (D/2)^{2n}/(2n)!`
/// with `weight(n) = n^p`, `p in {0, 2}`; `None` if the ratio is not yet below 1.
fn bessel_tail_bound(d_upper: &Float, n_terms: u64, power: i32) -> Option<Float> {
    let p = MAG_PREC + 32;
    let half_d = Ball::from_float(d_upper, p).mul_pow2(-1);
    let m = n_terms + 1;
    // t_m = (D/2)^{2m}/(2m)! <= (e (D/2)/k)^k / sqrt(2 pi k), k = 2m, from
    // k! >= sqrt(2 pi k) (k/e)^k [DLMF 5.6.1]: O(log k) ball operations where
    // (2m)! itself took O(m) (half the time of strip_ratio at beta 0.0001).
    let k = 2 * m;
    let k_ball = Ball::from_i64(i64::try_from(k).ok()?, p);
    let base = half_d.mul(&Ball::one(p).exp().ok()?).div(&k_ball).ok()?;
    let t = base.pow_u64(k).div(&Ball::pi(p).mul(&k_ball).mul_pow2(1).sqrt().ok()?).ok()?;
    let weight = Ball::from_i64((m as i64).pow(power as u32), p);
    let first = t.mul(&weight).abs_upper();
    // ratio for n >= m: (D/2)^2/((2n+1)(2n+2)) ((n+1)/n)^p, decreasing in n.
    let mf = m as f64;
    let ratio_f = (d_upper.to_f64() / 2.0).powi(2) / ((2.0 * mf + 1.0) * (2.0 * mf + 2.0)) * ((mf + 1.0) / mf).powi(power);
    let ratio_f = ratio_f * (1.0 + 1e-12); // cover the rounding of this f64 evaluation
    if !(ratio_f < 0.5) {
        return None;
    }
    let mut tail = Float::with_val(MAG_PREC, &first / (1.0 - ratio_f));
    tail.next_up();
    Some(tail)
}

/// An f64 estimate of the smallest `m` with `(D/2)^{2m}/(2m)! < 2^-wp`
/// (Stirling, `ln k! ~ k ln k - k + ln(2 pi k)/2`), by bisection on `m`; only a
/// starting point for [`bessel_terms`] (0 when it does not apply).
fn stirling_terms_estimate(d: f64, wp: u32) -> u64 {
    if !(d.is_finite() && d > 2.0) {
        return 0;
    }
    let log_term = |m: f64| {
        let k = 2.0 * m;
        k * (d / 2.0).ln() - (k * k.ln() - k + 0.5 * (2.0 * std::f64::consts::PI * k).ln())
    };
    let goal = -(wp as f64) * std::f64::consts::LN_2;
    let (mut lo, mut hi) = (d / 2.0, d * 4.0 + wp as f64);
    if !(log_term(hi) < goal) {
        return 0;
    }
    for _ in 0..80 {
        let mid = 0.5 * (lo + hi);
        if log_term(mid) < goal {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    lo as u64
}

/// Number of Bessel terms `N` with both tails below `2^-wp` (times the weights).
pub(crate) fn bessel_terms(d_upper: &Float, wp: u32) -> Result<(u64, Float, Float)> {
    let mut target = Float::with_val(MAG_PREC, 1);
    target >>= wp as i32;
    let mut n = (d_upper.to_f64() / 2.0).ceil().max(1.0) as u64 + 2;
    // Each bound costs O(n) (the factorial), so a scan from D/2 would cost O(D^2):
    // minutes at D ~ 6e4 (found by tests/fuzz.rs). Start near the f64 (Stirling)
    // estimate of the answer, a few steps below it; the rigorous bounds below
    // still decide, so a rough estimate only costs steps, never soundness.
    n = n.max(stirling_terms_estimate(d_upper.to_f64(), wp).saturating_sub(16));
    loop {
        if let (Some(t0), Some(t2)) = (bessel_tail_bound(d_upper, n, 0), bessel_tail_bound(d_upper, n, 2)) {
            if t2 <= target {
                return Ok((n, t0, t2));
            }
        }
        n += 4;
        if n > 10_000_000 {
            return Err(Error::NoConvergence { function: "u_wave (Bessel form)", terms: n });
        }
    }
}

/// Bessel-form `(u_w, du_w/dx)` as balls at working precision `wp`.
pub(crate) fn wave_bessel_wp(a: &Float, zeta: &Float, amp: &Float, x: &Float, wp: u32) -> Result<(Ball, Ball)> {
    wave_bessel_geometry(&wave_geometry(a, zeta, amp, x, wp)?, wp)
}

/// `u_w` (Bessel form) at `x = r a` over balls of `a`, `zeta`, `amp` and of
/// `r - 1 >= 0` (the model's strip ratio `m = c/a`, Eq. 15b): `x - a = a (r - 1)`
/// and `x + a = a (r + 1)` come from `r - 1`, so there is no cancellation next
/// to the edge. The caller checks the domain (`a, zeta > 0`, `r - 1 >= 0`).
pub(crate) fn u_wave_at_ratio_balls(a: &Ball, zeta: &Ball, amp: &Ball, r_minus_1: &Ball, wp: u32) -> Result<Ball> {
    check_wave_number(2.0 * std::f64::consts::PI * a.upper().to_f64() / zeta.lower().to_f64())?;
    let x = a.mul(&r_minus_1.add_i64(1));
    let xma = a.mul(r_minus_1);
    let xpa = a.mul(&r_minus_1.add_i64(2));
    let at_edge = r_minus_1.is_exact() && r_minus_1.mid().is_zero();
    let g = geometry_from_balls(&[a.clone(), zeta.clone(), amp.clone(), x], xma, xpa, at_edge, wp)?;
    Ok(wave_bessel_geometry(&g, wp)?.0)
}

/// The Bessel form on a geometry (balls): encloses `(u_w, du_w/dx)` over the balls.
fn wave_bessel_geometry(g: &WaveGeometry, wp: u32) -> Result<(Ball, Ball)> {
    let d_mid = g.d.mid().clone();
    let d_upper = g.d.upper();
    let (n_terms, tail0, tail2) = bessel_terms(&d_upper, wp)?;
    // The call's time budget (crate::budget) before the sequence and every 4096
    // terms of the sums: at D = 2 pi 10^4 one evaluation sums 3 * 10^4 terms, and
    // the strip-root search of the model runs dozens of them (0.2 s under a
    // 0.1 s budget, issue 37's scan)
    const CHECK_EVERY: u64 = 4096;
    let check = |n: u64| crate::budget::check_elapsed("the wave's Bessel series (Eq. 11a)", 0.0, Reached::Terms { count: n });
    check(0)?;
    let mut j = if d_mid.is_zero() {
        let mut v = vec![Ball::zero(wp); 2 * n_terms as usize + 1];
        v[0] = Ball::one(wp);
        v
    } else if 2 * n_terms <= MAX_SEQUENCE_ORDER as u64 {
        // Midpoint recurrence with one proven bound: radii near 2^-wp D^2, where the
        // ball recurrence widens by about 0.67 D bits (issue 23).
        bessel_j_sequence_three_term(2 * n_terms, &d_mid, wp)?
    } else {
        bessel_j_sequence_mp(2 * n_terms, &d_mid, wp)?
    };
    // J_n(D) for D in the ball: |J_n'| <= 1.
    for v in j.iter_mut() {
        v.add_error_mag(g.d.rad_mag());
    }
    let q2 = g.q.sqr();
    let mut q_pow = Ball::one(wp); // q^{2n}
    let mut geo = Ball::zero(wp); // sum_{j<2n} q^j
    let mut q_odd = g.q.clone(); // q^{2n-1}
    let mut sum_u = Ball::zero(wp);
    let mut sum_du = Ball::zero(wp);
    check(0)?;
    for n in 1..=n_terms {
        if n % CHECK_EVERY == 0 {
            check(n)?;
        }
        // geo_{2n} = geo_{2n-2} + q^{2n-2} + q^{2n-1}
        geo = geo.add(&q_pow).add(&q_odd);
        q_pow = q_pow.mul(&q2);
        q_odd = q_odd.mul(&q2);
        let jn = &j[2 * n as usize];
        let tu = jn.mul(&q_pow);
        let tdu = jn.mul_i64(n as i64).mul(&geo);
        if n % 2 == 1 {
            sum_u = sum_u.add(&tu);
            sum_du = sum_du.add(&tdu);
        } else {
            sum_u = sum_u.sub(&tu);
            sum_du = sum_du.sub(&tdu);
        }
    }
    sum_u.add_error(&tail0);
    // n |J_2n| geo_n <= 2 n^2 |J_2n|
    sum_du.add_error(&Float::with_val(MAG_PREC, &tail2 * 2u32));
    // u = A [1 - J0 + D J1 acosh(r) + 2 sum]
    let inner = Ball::one(wp).sub(&j[0]).add(&g.d.mul(&j[1]).mul(&g.acosh_r)).add(&sum_u.mul_pow2(1));
    let u = g.amp.mul(&inner);
    // du = (4A/a) (1-q)/s * sum n J_2n geo
    let du = g.amp.mul_pow2(2).div(&g.a)?.mul(&g.one_minus_q_over_s).mul(&sum_du);
    Ok((u, du))
}

/// Certified wave displacement `u_w(x)` (Bessel form) with `rad <= 2^-prec |mid|`.
pub fn u_wave_mp(a: &Float, zeta: &Float, amp: &Float, x: &Float, prec: u32) -> Result<Ball> {
    u_wave_mp_up_to(a, zeta, amp, x, prec, MAX_WORKING_PREC)
}

/// Certified wave-displacement gradient `du_w/dx` (Bessel form).
pub fn du_wave_mp(a: &Float, zeta: &Float, amp: &Float, x: &Float, prec: u32) -> Result<Ball> {
    du_wave_mp_up_to(a, zeta, amp, x, prec, MAX_WORKING_PREC)
}

/// [`u_wave_mp`] with the working precision capped at `max_wp` (the f64
/// fallback's [`F64_FALLBACK_MAX_WP`](crate::special::F64_FALLBACK_MAX_WP)).
pub(crate) fn u_wave_mp_up_to(a: &Float, zeta: &Float, amp: &Float, x: &Float, prec: u32, max_wp: u32) -> Result<Ball> {
    crate::error::check_prec(prec)?;
    check_wave_mp(a, zeta, amp, x)?;
    if amp.is_zero() {
        return Ok(Ball::zero(prec));
    }
    let floor = Float::with_val(MAG_PREC, amp.abs_ref());
    ziv_up_to("u_wave", prec, DEFAULT_GUARD_BITS, Some(&floor), max_wp, |wp| Ok(wave_bessel_wp(a, zeta, amp, x, wp)?.0))
}

/// [`du_wave_mp`] with the working precision capped at `max_wp`.
pub(crate) fn du_wave_mp_up_to(a: &Float, zeta: &Float, amp: &Float, x: &Float, prec: u32, max_wp: u32) -> Result<Ball> {
    crate::error::check_prec(prec)?;
    check_wave_mp(a, zeta, amp, x)?;
    if amp.is_zero() {
        return Ok(Ball::zero(prec));
    }
    let floor = gradient_scale(amp, zeta);
    ziv_up_to("du_wave", prec, DEFAULT_GUARD_BITS, Some(&floor), max_wp, |wp| Ok(wave_bessel_wp(a, zeta, amp, x, wp)?.1))
}

/// The edge a ball of `x` may straddle, per function.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum WaveOutput {
    Displacement,
    Gradient,
}

/// [`u_wave_mp`] / [`du_wave_mp`] over balls of inputs (Arb's convention);
/// `x = None` means `x = a` exactly (the same number, whatever its ball).
fn wave_ball_mp(a: &Ball, zeta: &Ball, amp: &Ball, x: Option<&Ball>, prec: u32, which: WaveOutput) -> Result<Ball> {
    crate::error::check_prec(prec)?;
    let x_is_a = x.is_none();
    let x = x.unwrap_or(a);
    let inputs = [a, zeta, amp, x];
    for (v, what) in [(a, "a"), (zeta, "zeta"), (amp, "amp"), (x, "x")] {
        if !v.is_finite() {
            return Err(Error::NonFinite { what });
        }
    }
    if inputs.iter().all(|v| v.is_exact()) {
        let [a, zeta, amp, x] = inputs.map(|v| v.mid());
        return match which {
            WaveOutput::Displacement => u_wave_mp(a, zeta, amp, x, prec),
            WaveOutput::Gradient => du_wave_mp(a, zeta, amp, x, prec),
        };
    }
    a.check_within("the contact half-width a", Interval::above(0.0))?;
    zeta.check_within("the wavelength zeta", Interval::above(0.0))?;
    check_wave_number(2.0 * std::f64::consts::PI * a.upper().to_f64() / zeta.lower().to_f64())?;
    // x - a over the balls: the edge x = a.
    let xma = if x_is_a { Ball::zero(a.prec()) } else { x.sub(a) };
    if xma.lower() < 0 {
        let function = match which {
            WaveOutput::Displacement => "u_wave",
            WaveOutput::Gradient => "du_wave",
        };
        let (lower, upper) = (xma.lower().to_f64_round(Round::Down), xma.upper().to_f64_round(Round::Up));
        return Err(Error::ContactEdgeInBall { function, lower, upper });
    }
    let floor = match which {
        WaveOutput::Displacement => Float::with_val(MAG_PREC, amp.abs_lower()),
        WaveOutput::Gradient => gradient_scale(&amp.abs_lower(), &zeta.upper()),
    };
    // x - a and x + a at the inputs' own precision (the subtraction above), then
    // rounded to wp relative to themselves: rounding x and a to wp first would
    // merge x = a (1 + 1e-15) with a at low precision and put the edge in the ball.
    let xpa_full = x.add(a);
    crate::special::ziv_ball_inputs(prec, DEFAULT_GUARD_BITS, Some(&floor), |wp| {
        let balls = [a, zeta, amp, x].map(|v| v.set_prec(wp));
        let xma = if x_is_a { Ball::zero(wp) } else { xma.set_prec(wp) };
        let xpa = xpa_full.set_prec(wp);
        let at_edge = xma.is_exact() && xma.mid().is_zero();
        let g = geometry_from_balls(&balls, xma, xpa, at_edge, wp)?;
        let (u, du) = wave_bessel_geometry(&g, wp)?;
        Ok(match which {
            WaveOutput::Displacement => u,
            WaveOutput::Gradient => du,
        })
    })
}

/// Certified `u_w(x)` over balls of inputs (Arb's convention): the result
/// contains `u_w` at every point of the balls.
///
/// **Argument.** The Bessel form runs in ball arithmetic on the balls (`D`,
/// `q`, `acosh(x/a)` are ball functions of the inputs); `J_n` at the ball `D`
/// is its value at the midpoint widened by `rad(D)` (`|J_n'| <= 1`
/// [DLMF 10.14.1]), and the tail bound uses the upper end of `D`, so every
/// piece holds over the balls. **Edges**: `a <= 0` or `zeta <= 0` in a ball,
/// and `x < a` anywhere in the balls (the contact edge `x = a` inside an
/// inexact `x - a`): typed errors. `x = a` exactly (exact equal inputs) is the
/// edge value `A (1 - cos D)`. Accuracy: `rad <= 2^-prec max(|u_w|, |A|)` when
/// the inputs are tight enough (else the wider, enclosing ball).
pub fn u_wave_ball_mp(a: &Ball, zeta: &Ball, amp: &Ball, x: &Ball, prec: u32) -> Result<Ball> {
    wave_ball_mp(a, zeta, amp, Some(x), prec, WaveOutput::Displacement)
}

/// Certified `du_w/dx` over balls of inputs; as [`u_wave_ball_mp`], with the
/// contact edge `x = a` inside the balls a typed error (the gradient is
/// one-sided there; exact `x = a` gives the limit from `x > a`).
/// Accuracy: `rad <= 2^-prec max(|du_w/dx|, 6 |A|/zeta)` when the inputs are tight enough.
pub fn du_wave_ball_mp(a: &Ball, zeta: &Ball, amp: &Ball, x: &Ball, prec: u32) -> Result<Ball> {
    wave_ball_mp(a, zeta, amp, Some(x), prec, WaveOutput::Gradient)
}

/// `u_w` at the contact edge `x = a` over balls of `a`, `zeta`, `amp`: the
/// same number for `x` and `a` (as when both are typed as the same decimal),
/// so the edge is not inside the balls. The value is `A (1 - cos D)`, here
/// from the Bessel form at `x = a` exactly.
pub fn u_wave_at_edge_ball_mp(a: &Ball, zeta: &Ball, amp: &Ball, prec: u32) -> Result<Ball> {
    wave_ball_mp(a, zeta, amp, None, prec, WaveOutput::Displacement)
}

/// `du_w/dx` at the contact edge `x = a` (the limit from `x > a`) over balls
/// of `a`, `zeta`, `amp`, with `x` the same number as `a`.
pub fn du_wave_at_edge_ball_mp(a: &Ball, zeta: &Ball, amp: &Ball, prec: u32) -> Result<Ball> {
    wave_ball_mp(a, zeta, amp, None, prec, WaveOutput::Gradient)
}

/// `u_w` (or `du_w/dx` when `gradient`) at decimal inputs `[a, zeta, amp, x]`
/// on the ball contract of [`crate::ball::eval_at_decimals`] (what `maugis eval`
/// and the Python package run). The accuracy floor is the function's natural
/// scale, `|A|` (or `6 |A| / zeta`), since `u_w` vanishes where `a/zeta` is an
/// integer. `x` given as the same number as `a` is the edge itself
/// ([`u_wave_at_edge_ball_mp`]), not a ball around it.
pub fn wave_at_decimals(args: &[crate::ball::Decimal; 4], prec: u32, gradient: bool) -> Result<Ball> {
    let amp = Float::with_val(64, args[2].as_rational()).abs();
    let zeta = Float::with_val(64, args[1].as_rational());
    let floor = if gradient && zeta > 0 { amp * 6u32 / zeta } else { amp };
    let edge = args[3] == args[0];
    let inputs = if edge { &args[..3] } else { &args[..] };
    crate::ball::eval_at_decimals_with_floor(inputs, prec, Some(&floor), |v| match (gradient, edge) {
        (false, true) => u_wave_at_edge_ball_mp(&v[0], &v[1], &v[2], prec),
        (false, false) => u_wave_ball_mp(&v[0], &v[1], &v[2], &v[3], prec),
        (true, true) => du_wave_at_edge_ball_mp(&v[0], &v[1], &v[2], prec),
        (true, false) => du_wave_ball_mp(&v[0], &v[1], &v[2], &v[3], prec),
    })
}

