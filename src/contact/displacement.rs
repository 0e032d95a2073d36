//! Substrate displacements outside the contact `|x| >= a`, dimensional form.
//!
//! # Hertz (Eq. 10) and the profile (Eq. 1)
//!
//! `u_H(x) = x^2/(2R) - x sqrt(x^2-a^2)/(2R) + a^2 acosh(x/a)/(2R)`, evaluated as
//! `(a^2/(2R)) [x/(x + sqrt(x^2-a^2)) + acosh(x/a)]` (no cancellation for large
//! `x`); inside the contact the substrate follows the punch, `u_H = x^2/(2R)`.
//! `h(x) = x^2/(2R) + 2A sin^2(pi x/zeta)` (= `A (1 - cos(2 pi x/zeta))`).
//!
//! # Wave displacement: three routes
//!
//! With `D = 2 pi a/zeta`, `s = (pi a/zeta)^2 = D^2/4`, `y = (a/x)^2`:
//!
//! 1. **Eq. 12** (seed, with the errata of docs/displacement.md applied:
//!    `(pi a/zeta)^2` for the printed `(pi a/lambda)^2`, `(-1)^k` for `(-1)^{3k}`,
//!    integration constant `C = 0`):
//!    `u_w = (A/sqrt(pi)) s sum_k (-1)^k D^{2k}/(2k+1)! 1F2(1/2; k+1, k+3/2; -s) G(k, y)`,
//!    `G(k, y)` the Meijer-G family of [`crate::special::meijer_g`]. Its terms grow
//!    to about `e^D/sqrt(D)` before they cancel to a result of order `A`: at
//!    `a = 6`, `zeta = 9/8` (`D = 33.5`) that is `6e13`, 46 bits. f64 loses every
//!    digit there; the MP sum adds those bits as guard bits (Ziv).
//!    Its gradient is **Eq. 11b**:
//!    `du_w/dx = (2 A s / x) sum_k (-1)^k s^k / (k! (k+1)! (2k+1)) 1F2(..; -s) 2F1(1, k+1/2; k+2; y)`.
//! 2. **Bessel form** (docs/displacement.md, Route 2; Chebyshev expansion of the traction,
//!    Appendix B.11, integrated term by term), with `q = x/a - sqrt((x/a)^2-1)`:
//!    `u_w = A [1 - J0(D) + D J1(D) acosh(x/a) + 2 sum_{n>=1} (-1)^{n+1} J_{2n}(D) q^{2n}]`,
//!    `du_w/dx = (4A/a) sum_{n>=1} (-1)^{n+1} n J_{2n}(D) g_n`,
//!    `g_n = (1 - q^{2n})/sqrt((x/a)^2-1) = (1 - sqrt((x/a-1)/(x/a+1))) sum_{j<2n} q^j`.
//!    The gradient is the notes' `A/sqrt(x^2-a^2) [D J1(D) - 4 sum (-1)^{n+1} n J_{2n} q^{2n}]`
//!    rewritten with `D J1(D) = 4 sum (-1)^{n+1} n J_{2n}(D)` (telescoping DLMF 10.6.1),
//!    which removes the `0/0` at the contact edge: `du_w/dx` stays finite at `x = a`.
//!    Nothing cancels. **Tail bound**: `|J_{2n}(D)| <= (D/2)^{2n}/(2n)!`
//!    [DLMF 10.14.4], `0 <= q <= 1`, `0 <= g_n <= 2n`, so the tails after `N` terms are
//!    at most `sum_{n>N} (D/2)^{2n}/(2n)!` (times `2A`) and `sum_{n>N} 2n^2 (D/2)^{2n}/(2n)!`
//!    (times `4A/a`), bounded geometrically once the ratio `(D/2)^2/((2n+1)(2n+2)) ((n+1)/n)^2 < 1`.
//!    `J_n` at the ball `D` is evaluated at its midpoint and widened by `rad(D)`
//!    (`|J_n'| <= 1` [DLMF 10.14.1]).
//! 3. **Eq. 11a quadrature** (corrected form, docs/displacement.md, Route 3), in
//!    [`crate::contact::wave_quadrature`].
//!
//! # Eq. 12 and Eq. 11b truncated at `kmax`: the truncation bound
//!
//! `|1F2(1/2; k+1, k+3/2; -s)| <= e^{s/(k+1)}` (termwise: `(1/2)_n <= (k+3/2)_n`,
//! `(k+1)_n >= (k+1)^n`), `|2F1(1, k+1/2; k+2; y)| <= 2(k+1)` (positive
//! coefficients, Gauss's value at `y = 1`), and `|G(k, y)| <= sqrt(pi) (|ln y| + 2.39 + ln(k+2))`
//! (from `G = C_k B`, `C_k <= 2 sqrt(pi)`, `0 <= S(y) <= S(1) = psi(k+2) - psi(3/2) <= ln(k+2)`,
//! `0 < psi(k+2) - psi(k+1/2) <= 1 + 2 ln 2 < 2.39`). Hence
//! `|T_k| <= beta_k = A s D^{2k}/(2k+1)! e^{s/(k+1)} (|ln y| + 2.39 + ln(k+2))` for Eq. 12
//! and `|T_k| <= (2 A s/x) s^k/(k!(k+1)!(2k+1)) e^{s/(k+1)} 2(k+1)` for Eq. 11b; both
//! bound sequences have ratios that decrease in `k`, so the tail from `K+1` is at most
//! `beta_{K+1}/(1 - rho_K)` once `rho_K < 1`. The MP sums stop early when that
//! bound is below `2^-wp` of the partial sum, and then carry it in the radius: the
//! returned ball encloses the partial sum through `kmax` *and* (separately
//! reported) the truncation bound covers the rest.
//!
//! # Adhesive displacement (Box I, A.5a, A.5b)
//!
//! With `K = 4 sigma/(pi E*)`, `X = sqrt((c^2-a^2)/(c^2-x^2))`, `Y = sqrt((c^2-a^2)/(x^2-c^2))`:
//! `u_a = 0` for `|x| <= a`;
//! `K [c acosh(|x| X/a) - |x| acosh(X) - sqrt(c^2-a^2) acosh(|x|/a)]` for `a < |x| < c`;
//! `K [c ln(c/a) - sqrt(c^2-a^2) acosh(c/a)]` at `|x| = c` (A.5b);
//! `K [c asinh(|x| Y/a) - |x| asinh(Y) - sqrt(c^2-a^2) acosh(|x|/a)]` for `|x| > c`.

use rug::float::Round;
use rug::Float;

use crate::ball::{Ball, Bounded, Mag, MAG_PREC};
use crate::error::{finite, Error, Result};
use crate::ball::Dd;
use crate::contact::wave_bounded::{count_fallback, CertifiedBessel};
use std::sync::OnceLock;
use crate::special::bessel_j::{bessel_j_sequence_dd, bessel_j_sequence_mp};
use crate::special::meijer_g::{
    self, direct_sums_sweep, meijer_g_k_at_one_with, near_one_sums_sweep, meijer_g_k_direct_ball, meijer_g_k_from_sum, meijer_g_k_near_one_ball,
    MeijerConstants,
};
use crate::special::hyp1f2::{hyp1f2_model_ball, hyp1f2_model_family};
use crate::special::pfq::pfq_series;
use crate::special::{check_finite, exact, exact_add, exact_sub, ziv, ziv_with_floor, DEFAULT_GUARD_BITS};

/// Largest `D = 2 pi a/zeta` (contact width in wavelengths times `pi`) accepted.
pub const MAX_WAVE_D: f64 = 1.0e5;

/// Largest `kmax` accepted by the truncated series.
pub const MAX_KMAX: u64 = 100_000;

/// Largest `k_top (1 - y)` for the near-one sweep of the Meijer sums in Eq. 12
/// (it then runs with `1.45 k_top w <= 58` extra bits).
const NEAR_ONE_SWEEP_MAX_KW: f64 = 40.0;

/// `1 + 2 ln 2`, rounded up: the largest value of `psi(k+2) - psi(k+1/2)` (at `k = 0`).
const PSI_DIFF_MAX: f64 = 2.39;

// ---------------------------------------------------------------- validation

/// Validates `(a, zeta, amp, x)` of the wave displacement.
fn check_wave_f64(a: f64, zeta: f64, amp: f64, x: f64) -> Result<()> {
    finite(a, "a")?;
    finite(zeta, "zeta")?;
    finite(amp, "amp")?;
    finite(x, "x")?;
    if a <= 0.0 {
        return Err(Error::Domain { what: format!("the contact half-width a must be > 0 (got {a})") });
    }
    if zeta <= 0.0 {
        return Err(Error::Domain { what: format!("the wavelength zeta must be > 0 (got {zeta})") });
    }
    if x < a {
        return Err(Error::Domain { what: format!("the wave displacement is for x >= a (got x = {x} < a = {a})") });
    }
    check_wave_number(2.0 * std::f64::consts::PI * a / zeta)
}

/// The Bessel and Eq. 12 routes sum about `D/2 + 30` terms, `D = 2 pi a/zeta`;
/// past [`MAX_WAVE_D`] the cost and the cancellation are out of proportion.
fn check_wave_number(d: f64) -> Result<()> {
    if !(d <= MAX_WAVE_D) {
        return Err(Error::Domain {
            what: format!("2 pi a/zeta = {d:e} exceeds {MAX_WAVE_D:e}: the contact spans too many wavelengths"),
        });
    }
    Ok(())
}

fn check_wave_mp(a: &Float, zeta: &Float, amp: &Float, x: &Float) -> Result<()> {
    check_finite(a, "a")?;
    check_finite(zeta, "zeta")?;
    check_finite(amp, "amp")?;
    check_finite(x, "x")?;
    if *a <= 0 {
        return Err(Error::Domain { what: "the contact half-width a must be > 0".into() });
    }
    if *zeta <= 0 {
        return Err(Error::Domain { what: "the wavelength zeta must be > 0".into() });
    }
    if *x < *a {
        return Err(Error::Domain { what: "the wave displacement is for x >= a".into() });
    }
    check_wave_number(2.0 * std::f64::consts::PI * a.to_f64() / zeta.to_f64())
}

fn check_kmax(kmax: u64) -> Result<()> {
    if kmax > MAX_KMAX {
        return Err(Error::Domain { what: format!("kmax = {kmax} is too large (at most {MAX_KMAX})") });
    }
    Ok(())
}

// ---------------------------------------------------------------- geometry

/// The derived quantities of the wave problem, as balls at working precision.
struct WaveGeometry {
    /// `A`
    amp: Ball,
    /// `a`
    a: Ball,
    /// `x`
    x: Ball,
    /// `D = 2 pi a / zeta`
    d: Ball,
    /// `s = D^2/4`
    s: Ball,
    /// `y = (a/x)^2`
    y: Ball,
    /// `w = 1 - y = (x-a)(x+a)/x^2`
    w: Ball,
    /// `q = x/a - sqrt((x/a)^2 - 1) = 1/(x/a + sqrt((x/a)^2 - 1))`
    q: Ball,
    /// `acosh(x/a)`
    acosh_r: Ball,
    /// `(1 - q)/sqrt(r^2-1) = 1 - sqrt((r-1)/(r+1))`
    one_minus_q_over_s: Ball,
    /// `x == a` exactly
    at_edge: bool,
}

fn wave_geometry(a: &Float, zeta: &Float, amp: &Float, x: &Float, wp: u32) -> Result<WaveGeometry> {
    // x - a and x + a exactly (no cancellation next to the edge).
    let xma = Ball::from_float(&exact_sub(x, a), wp);
    let xpa = Ball::from_float(&exact_add(x, a), wp);
    let inputs = [a, zeta, amp, x].map(|v| Ball::from_float(v, wp));
    geometry_from_balls(&inputs, xma, xpa, x == a, wp)
}

/// The part of a ball at or above zero, for a quantity known to be `>= 0` (the
/// caller has checked `x >= a`): `[max(lower, 0), upper]`. A ball wholly
/// below zero cannot hold such a quantity and is returned as it is (the square
/// root after it then reports the domain error).
fn clip_nonnegative(b: &Ball) -> Ball {
    if !(b.lower() < 0) || b.upper() < 0 {
        return b.clone();
    }
    // [0, u] as [u/2 ± u/2] with u rounded up to 53 bits: mid and radius are
    // then the same exact number, so the lower end is exactly 0.
    let (u, _) = Float::with_val_round(53, b.upper(), Round::Up);
    let half = u / 2u32;
    let rad = Mag::from_float_up(&half);
    Ball::with_mag(half, rad)
}

/// The geometry over balls of inputs `[a, zeta, amp, x]`, with `x - a` and
/// `x + a` given as balls (exact for exact inputs).
fn geometry_from_balls(inputs: &[Ball; 4], xma: Ball, xpa: Ball, at_edge: bool, wp: u32) -> Result<WaveGeometry> {
    let [ab, zb, amp, xb] = inputs;
    let d = Ball::pi(wp).mul(ab).mul_pow2(1).div(zb)?;
    let s = d.sqr().mul_pow2(-2);
    // r - 1 and r + 1, r = x/a; a lower end of r - 1 below zero (only for
    // balls that touch the edge x = a from above) is clipped: the caller has
    // checked x >= a over the balls.
    let rm1 = clip_nonnegative(&xma.div(ab)?);
    let rp1 = xpa.div(ab)?;
    let r = rm1.add_i64(1);
    // r^2 - 1 and (r-1)/(r+1) are >= 0 wherever x >= a; their balls may still
    // reach below zero by rounding, so the square roots see them clipped.
    let sq = clip_nonnegative(&rm1.mul(&rp1)).sqrt()?; // sqrt(r^2 - 1)
    let q = r.add(&sq).recip()?;
    let acosh_r = rm1.add(&sq).ln_1p()?;
    let one_minus_q_over_s = Ball::one(wp).sub(&clip_nonnegative(&rm1.div(&rp1)?).sqrt()?);
    let y = ab.div(xb)?.sqr();
    let w = xma.mul(&xpa).div(&xb.sqr())?;
    Ok(WaveGeometry {
        amp: amp.clone(),
        a: ab.clone(),
        x: xb.clone(),
        d,
        s,
        y,
        w,
        q,
        acosh_r,
        one_minus_q_over_s,
        at_edge,
    })
}

// ---------------------------------------------------------------- Bessel form

/// Upper bound (as f64, rounded up generously) of `sum_{n>N} weight(n) (D/2)^{2n}/(2n)!`
/// with `weight(n) = n^p`, `p in {0, 2}`; `None` if the ratio is not yet below 1.
fn bessel_tail_bound(d_upper: &Float, n_terms: u64, power: i32) -> Option<Float> {
    let p = MAG_PREC + 32;
    let half_d = Ball::from_float(d_upper, p).mul_pow2(-1);
    let m = n_terms + 1;
    // t_m = (D/2)^{2m}/(2m)!
    let num = half_d.pow_u64(2 * m);
    let fact = Ball::factorial(u32::try_from(2 * m).ok()?, p);
    let t = num.div(&fact).ok()?;
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

/// Number of Bessel terms `N` with both tails below `2^-wp` (times the weights).
pub(crate) fn bessel_terms(d_upper: &Float, wp: u32) -> Result<(u64, Float, Float)> {
    let mut target = Float::with_val(MAG_PREC, 1);
    target >>= wp as i32;
    let mut n = (d_upper.to_f64() / 2.0).ceil().max(1.0) as u64 + 2;
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
    let mut j = if d_mid.is_zero() {
        let mut v = vec![Ball::zero(wp); 2 * n_terms as usize + 1];
        v[0] = Ball::one(wp);
        v
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
    for n in 1..=n_terms {
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
    crate::error::check_prec(prec)?;
    check_wave_mp(a, zeta, amp, x)?;
    if amp.is_zero() {
        return Ok(Ball::zero(prec));
    }
    let floor = Float::with_val(MAG_PREC, amp.abs_ref());
    ziv_with_floor("u_wave", prec, DEFAULT_GUARD_BITS, Some(&floor), |wp| Ok(wave_bessel_wp(a, zeta, amp, x, wp)?.0))
}

/// Certified wave-displacement gradient `du_w/dx` (Bessel form).
pub fn du_wave_mp(a: &Float, zeta: &Float, amp: &Float, x: &Float, prec: u32) -> Result<Ball> {
    crate::error::check_prec(prec)?;
    check_wave_mp(a, zeta, amp, x)?;
    if amp.is_zero() {
        return Ok(Ball::zero(prec));
    }
    let floor = gradient_scale(amp, zeta);
    ziv_with_floor("du_wave", prec, DEFAULT_GUARD_BITS, Some(&floor), |wp| Ok(wave_bessel_wp(a, zeta, amp, x, wp)?.1))
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
    let interval = |v: &Ball| {
        let end = |f: Float| f.to_string_radix(10, Some(4));
        format!("[{}, {}]", end(v.lower()), end(v.upper()))
    };
    if !(a.lower() > 0) {
        return Err(Error::Domain { what: format!("the contact half-width a must be > 0 over its input ball {}", interval(a)) });
    }
    if !(zeta.lower() > 0) {
        return Err(Error::Domain { what: format!("the wavelength zeta must be > 0 over its input ball {}", interval(zeta)) });
    }
    check_wave_number(2.0 * std::f64::consts::PI * a.upper().to_f64() / zeta.lower().to_f64())?;
    // x - a over the balls: the edge x = a.
    let xma = if x_is_a { Ball::zero(a.prec()) } else { x.sub(a) };
    if xma.upper() < 0 {
        return Err(Error::Domain { what: format!("the wave displacement is for x >= a (x - a lies in {})", interval(&xma)) });
    }
    if xma.lower() < 0 {
        return Err(Error::Domain {
            what: match which {
                WaveOutput::Displacement => format!(
                    "the contact edge x = a lies within the input balls (x - a in {}): u_w is defined for x >= a only",
                    interval(&xma)
                ),
                WaveOutput::Gradient => format!(
                    "the contact edge x = a lies within the input balls (x - a in {}): du_w/dx is one-sided there",
                    interval(&xma)
                ),
            },
        });
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

/// The natural scale of `du_w/dx`, `2 pi |A| / zeta` (a lower estimate is fine:
/// it only sets the absolute accuracy floor).
fn gradient_scale(amp: &Float, zeta: &Float) -> Float {
    let mut f = Float::with_val(MAG_PREC, amp.abs_ref());
    f *= 6u32;
    f /= zeta;
    f
}

/// Number of Bessel terms for the f64 path: the tail `sum_{n>N} 2 n^2 (D/2)^{2n}/(2n)!`
/// below `1e-18` (estimate in f64).
fn bessel_terms_f64(d: f64) -> usize {
    let half = d / 2.0;
    let mut n = (half.ceil() as usize).max(1) + 2;
    loop {
        let m = (n + 1) as f64;
        // log of (D/2)^{2m}/(2m)! via lgamma-free Stirling upper bound
        let ln_t = 2.0 * m * half.max(1e-300).ln() - ln_factorial(2.0 * m);
        if ln_t + (2.0 * m * m).ln() < (1e-19f64).ln() {
            return n;
        }
        n += 2;
    }
}

/// `ln(n!)` for real `n >= 1` by Stirling with the 1/(12n) term (a lower bound of
/// the true value is not needed here: this only sizes the f64 sum).
fn ln_factorial(n: f64) -> f64 {
    n * n.ln() - n + 0.5 * (2.0 * std::f64::consts::PI * n).ln() + 1.0 / (12.0 * n)
}

/// Placeholder entries of the batch outputs (every one is overwritten).
const UNSET_PAIR: (Bounded, Bounded) = (Bounded { value: 0.0, err: f64::INFINITY }, Bounded { value: 0.0, err: f64::INFINITY });

/// The Bessel form at one contact size: `D = 2 pi a/zeta` and the sequence
/// `J_n(D)` are computed once (double-double Miller recurrence), after which
/// `u_w(x)`, `du_w/dx` and the wave-traction integral cost one short sum each.
/// This is what the Maugis solver uses: `a` is fixed while the strip end moves.
///
/// Everything is evaluated in double-double (the geometry `q`, `g_n` and the
/// sums) and rounded once; `acosh(x/a)` is the f64 library value, whose
/// half-ulp error enters only through the `D J1(D) acosh(x/a)` term.
#[derive(Debug, Clone)]
pub struct WaveBessel {
    a: f64,
    zeta: f64,
    amp: f64,
    /// Certified Bessel data for the `*_bounded` evaluations, built on first use.
    cert: OnceLock<Option<CertifiedBessel>>,
    /// The native (double-double) certified data, built on first use by either
    /// path; `None` where they do not certify (`D` beyond about 60).
    native: OnceLock<Option<CertifiedBessel>>,
    d: Dd,
    n_terms: usize,
    j: Vec<Dd>,
    /// `S_n = 2 sum_{k>=0} (-1)^k J_{2n+2k+1}(D)`, `n = 0..=n_terms`.
    conv: Vec<Dd>,
    /// `J_{2n}(D)` rounded to f64, for [`WaveBessel::u_fast`].
    j_even_f64: Vec<f64>,
    /// Horner coefficients in `q^2` of the two sums (`horner_coefficients`).
    u_coef: Vec<Dd>,
    du_coef: Vec<Dd>,
}

/// The Bessel-form sums as polynomials in `q^2`:
/// `sum_{n=1}^N (-1)^{n+1} J_{2n} q^{2n} = sum_m u_m q^{2m}`, `u_m = (-1)^{m+1} J_{2m}`, and
/// `sum_n (-1)^{n+1} n J_{2n} geo_n = (1 + q) sum_{m<N} T_m q^{2m}`,
/// `T_m = sum_{n=m+1}^{N} (-1)^{n+1} n J_{2n}` (the powers `q^{2m}`, `q^{2m+1}` of
/// `geo_n = sum_{j<2n} q^j` both occur for every `n > m`). Two Horner passes per `x`.
fn horner_coefficients(j: &[Dd], n_terms: usize) -> (Vec<Dd>, Vec<Dd>) {
    let sign = |n: usize| if n % 2 == 1 { 1.0 } else { -1.0 };
    let u_coef: Vec<Dd> = (0..=n_terms).map(|m| j[2 * m].mul_f64(sign(m))).collect();
    let mut du_coef = vec![Dd::ZERO; n_terms];
    let mut acc = Dd::ZERO;
    for m in (0..n_terms).rev() {
        acc = acc + j[2 * (m + 1)].mul_f64(sign(m + 1) * (m + 1) as f64);
        du_coef[m] = acc;
    }
    (u_coef, du_coef)
}

impl WaveBessel {
    /// Precomputes the Bessel data for contact half-width `a`, wavelength `zeta`,
    /// amplitude `amp`.
    pub fn new(a: f64, zeta: f64, amp: f64) -> Result<WaveBessel> {
        check_wave_f64(a, zeta, amp, a)?;
        let d = Dd::TWO_PI.mul_f64(a) / Dd::from_f64(zeta);
        let n_terms = bessel_terms_f64(d.hi);
        let top = 2 * n_terms + 3;
        let j = bessel_j_sequence_dd(top, d);
        if j.len() <= top {
            // D not finite in double-double at subnormal scales (found by
            // tests/fuzz.rs), or beyond the sequence's range
            return Err(Error::NonFiniteResult { function: "WaveBessel::new (2 pi a/zeta in double-double)" });
        }
        // S_n = J_{2n+1} - J_{2n+3} + ... (times 2): backward partial sums over the odd orders.
        let mut conv = vec![Dd::ZERO; n_terms + 1];
        // Start at the highest odd order available and accumulate downward;
        // the neglected orders are below the sums' truncation level.
        let mut tail = Dd::ZERO;
        let mut k = top as isize - if top % 2 == 1 { 0 } else { 1 };
        while k >= 1 {
            // tail_k = J_k - tail_{k+2}
            tail = j[k as usize] - tail;
            if (k - 1) % 2 == 0 {
                let idx = (k - 1) / 2;
                if idx <= n_terms as isize {
                    conv[idx as usize] = tail.mul_f64(2.0);
                }
            }
            k -= 2;
        }
        let j_even_f64 = (0..=n_terms).map(|n| j[2 * n].to_f64()).collect();
        let (u_coef, du_coef) = horner_coefficients(&j, n_terms);
        Ok(WaveBessel { a, zeta, amp, cert: OnceLock::new(), native: OnceLock::new(), d, n_terms, j, conv, j_even_f64, u_coef, du_coef })
    }

    /// `D = 2 pi a / zeta`.
    pub fn d(&self) -> f64 {
        self.d.to_f64()
    }

    /// `(u_w(x), du_w/dx)` for `x >= a`: the values of [`WaveBessel::eval_bounded`]
    /// (native double-double, rounded once; the certified data are built on the
    /// first call) up to `x/a = 25/7`, beyond it the double-double Miller data.
    /// An estimate: about `1e-16` of `max(|u_w|, |A|)`.
    ///
    /// Errors: `x` NaN or infinite, or `x < a` (the Bessel form is for the
    /// outside of the contact).
    pub fn eval(&self, x: f64) -> Result<(f64, f64)> {
        self.check_x(x)?;
        // The values of the proven-bound path where it runs natively (it is
        // also the faster one); beyond x/a = 25/7 the double-double Miller data.
        if let Some((u, du)) = self.native_data().and_then(|c| c.eval_bounded(self.a, self.amp, x)) {
            return Ok((u.value, du.value));
        }
        Ok(self.eval_unchecked(x))
    }

    /// The native certified Bessel data, built on first use (never MP, so
    /// that the estimate path stays cheap at any `D`).
    fn native_data(&self) -> Option<&CertifiedBessel> {
        self.native.get_or_init(|| CertifiedBessel::native_only(self.a, self.zeta)).as_ref()
    }

    /// The certified Bessel data: native where they certify, else built in MP
    /// on first use.
    fn certified(&self) -> Option<&CertifiedBessel> {
        self.native_data().or_else(|| self.cert.get_or_init(|| CertifiedBessel::new_mp_counted(self.a, self.zeta).ok()).as_ref())
    }

    /// [`WaveBessel::eval`] over a slice of `x` (one contact, many points: the
    /// solver's case), the same values as one call per point, computed in one
    /// loop. Fails on the first invalid `x`, naming it.
    pub fn eval_many(&self, xs: &[f64]) -> Result<Vec<(f64, f64)>> {
        xs.iter().try_for_each(|&x| self.check_x(x))?;
        let Some(c) = self.native_data() else {
            return Ok(xs.iter().map(|&x| self.eval_unchecked(x)).collect());
        };
        let mut out = vec![UNSET_PAIR; xs.len()];
        let mut refused = Vec::new();
        c.eval_bounded_batch(self.a, self.amp, xs, &mut out, &mut refused);
        let mut values: Vec<(f64, f64)> = out.iter().map(|(u, du)| (u.value, du.value)).collect();
        for i in refused {
            values[i] = self.eval_unchecked(xs[i]);
        }
        Ok(values)
    }

    /// `(u_w(x), du_w/dx)` with proven error bounds for the f64 inputs as given
    /// ([`crate::contact::wave_bounded`]). The certified Bessel data are computed
    /// on the first call (MP, once per contact); each later call costs one short
    /// double-double sum. Falls back to the MP Bessel form for `x/a > 25/7`
    /// (counted by [`wave_bounded_fallbacks`](crate::contact::wave_bounded::wave_bounded_fallbacks)).
    pub fn eval_bounded(&self, x: f64) -> Result<(Bounded, Bounded)> {
        self.check_x(x)?;
        if let Some(r) = self.certified().and_then(|c| c.eval_bounded(self.a, self.amp, x)) {
            return Ok(r);
        }
        wave_bounded_fallback(self.a, self.zeta, self.amp, x)
    }

    /// [`WaveBessel::eval_bounded`] over a slice of `x` (one contact, many
    /// points: the solver's case), the same values and bounds as one call per
    /// point, computed in one loop. Fails on the first invalid `x`, naming it.
    pub fn eval_bounded_many(&self, xs: &[f64]) -> Result<Vec<(Bounded, Bounded)>> {
        let mut out = vec![UNSET_PAIR; xs.len()];
        self.eval_bounded_into(xs, &mut out)?;
        Ok(out)
    }

    /// [`WaveBessel::eval_bounded_many`] into the caller's slice, without
    /// allocating (`out.len()` must equal `xs.len()`). Every `x` is checked
    /// before anything is written; an error from the MP fallback (`x/a > 25/7`)
    /// can leave `out` partly written.
    pub fn eval_bounded_into(&self, xs: &[f64], out: &mut [(Bounded, Bounded)]) -> Result<()> {
        if out.len() != xs.len() {
            return Err(Error::Domain {
                what: format!("eval_bounded_into: {} points but room for {} results (make the lengths equal)", xs.len(), out.len()),
            });
        }
        xs.iter().try_for_each(|&x| self.check_x(x))?;
        let Some(c) = self.certified() else {
            for (o, &x) in out.iter_mut().zip(xs) {
                *o = wave_bounded_fallback(self.a, self.zeta, self.amp, x)?;
            }
            return Ok(());
        };
        let mut refused = Vec::new();
        c.eval_bounded_batch(self.a, self.amp, xs, out, &mut refused);
        for i in refused {
            out[i] = wave_bounded_fallback(self.a, self.zeta, self.amp, xs[i])?;
        }
        Ok(())
    }

    fn check_x(&self, x: f64) -> Result<()> {
        finite(x, "x")?;
        if x < self.a {
            return Err(Error::Domain {
                what: format!("the wave displacement is for x >= a (got x = {x} < a = {})", self.a),
            });
        }
        Ok(())
    }

    fn eval_unchecked(&self, x: f64) -> (f64, f64) {
        let (a, amp, d, j) = (self.a, self.amp, self.d, &self.j);
        let ad = Dd::from_f64(a);
        let rm1 = Dd::diff(x, a) / ad; // x/a - 1
        let rp1 = (Dd::from_f64(x) + ad) / ad; // x/a + 1
        let r = Dd::from_f64(x) / ad;
        let sq = (rm1 * rp1).sqrt(); // sqrt((x/a)^2 - 1)
        let q = (r + sq).recip();
        let acosh_r = (rm1 + sq).to_f64().ln_1p();
        let one_minus_q_over_s = Dd::ONE - (rm1 / rp1).sqrt();
        let q2 = q * q;
        // Horner in q^2 (see `horner_coefficients`).
        // One loop, two independent chains (they overlap in the pipeline).
        let n = self.n_terms;
        let (mut su, mut sdu) = (self.u_coef[n], self.du_coef[n - 1]);
        for m in (0..n - 1).rev() {
            su = su * q2 + self.u_coef[m + 1];
            sdu = sdu * q2 + self.du_coef[m];
        }
        let su = su * q2;
        let sdu = sdu * (Dd::ONE + q);
        let inner = (Dd::ONE - j[0]) + (d * j[1]).mul_f64(acosh_r) + su.mul_f64(2.0);
        let u = inner.mul_f64(amp).to_f64();
        let du = (one_minus_q_over_s * sdu).mul_f64(4.0 * amp / a).to_f64();
        (u, du)
    }

    /// `u_w(x)` in plain f64 arithmetic (from the double-double Bessel values):
    /// about 4x faster than [`WaveBessel::eval`], with an error of a few ulps of
    /// the largest term (`~ 1e-15 |A| D`) instead of one rounding. The Maugis
    /// solver uses it in its scans; the public `u_wave` uses [`WaveBessel::eval`].
    pub fn u_fast(&self, x: f64) -> f64 {
        let a = self.a;
        let rm1 = (x - a) / a;
        let sq = (rm1 * (rm1 + 2.0)).sqrt();
        let q = 1.0 / (1.0 + rm1 + sq);
        let acosh_r = (rm1 + sq).ln_1p();
        let q2 = q * q;
        let mut q_pow = 1.0f64;
        let mut su = 0.0f64;
        for n in 1..=self.n_terms {
            q_pow *= q2;
            let t = self.j_even_f64[n] * q_pow;
            su += if n % 2 == 1 { t } else { -t };
        }
        let j1 = self.j[1].to_f64();
        let one_minus_j0 = (Dd::ONE - self.j[0]).to_f64();
        self.amp * (one_minus_j0 + self.d.to_f64() * j1 * acosh_r + 2.0 * su)
    }

    /// The wave-traction integral of Eq. 7 / Eq. 16,
    /// `K(c) = int_0^D J0(t) cos((t - D) c) dt` for `|c| <= 1` (`c = x/a = cos(theta)`).
    ///
    /// Jacobi–Anger, `cos(z c) = J0(z) + 2 sum_n (-1)^n J_{2n}(z) T_{2n}(c)` [DLMF 10.12.3],
    /// and the convolution `int_0^D J0(t) J_{2n}(D-t) dt = 2 sum_k (-1)^k J_{2n+2k+1}(D)`
    /// [DLMF 10.22.31] give `K(c) = sum_n eps_n (-1)^n S_n T_{2n}(c)`; the Chebyshev
    /// polynomials by their recurrence. Same truncation as the displacement sums.
    pub fn traction_integral(&self, c: f64) -> f64 {
        let c = c.clamp(-1.0, 1.0);
        let x2 = 2.0 * c * c - 1.0; // T_2(c)
        // T_{2n}(c) = T_n(T_2(c)); recurrence in n on T_2
        let (mut t_prev, mut t_cur) = (1.0f64, x2); // T_0(x2), T_1(x2)
        let mut sum = self.conv[0];
        for n in 1..=self.n_terms {
            let coeff = self.conv[n].mul_f64(2.0 * t_cur);
            sum = if n % 2 == 1 { sum - coeff } else { sum + coeff };
            let t_next = 2.0 * x2 * t_cur - t_prev;
            t_prev = t_cur;
            t_cur = t_next;
        }
        sum.to_f64()
    }
}

fn wave_bessel_f64(a: f64, zeta: f64, amp: f64, x: f64) -> Result<(f64, f64)> {
    WaveBessel::new(a, zeta, amp)?.eval(x)
}

/// The MP fallback of the bounded f64 wave functions: both Bessel-form balls
/// at [`F64_FALLBACK_PREC`](crate::special::F64_FALLBACK_PREC) bits (counted).
fn wave_bounded_fallback(a: f64, zeta: f64, amp: f64, x: f64) -> Result<(Bounded, Bounded)> {
    count_fallback();
    let (a, zeta, amp, x) = (exact(a), exact(zeta), exact(amp), exact(x));
    let p = crate::special::F64_FALLBACK_PREC;
    let u = crate::special::bounded_from_ball("u_wave", &u_wave_mp(&a, &zeta, &amp, &x, p)?)?;
    let du = crate::special::bounded_from_ball("du_wave", &du_wave_mp(&a, &zeta, &amp, &x, p)?)?;
    Ok((u, du))
}

/// Both bounded values from scratch: certified Bessel data, then the native sum.
fn wave_bounded_pair(a: f64, zeta: f64, amp: f64, x: f64) -> Result<(Bounded, Bounded)> {
    check_wave_f64(a, zeta, amp, x)?;
    match CertifiedBessel::new(a, zeta).ok().and_then(|c| c.eval_bounded(a, amp, x)) {
        Some(r) => Ok(r),
        None => wave_bounded_fallback(a, zeta, amp, x),
    }
}

/// Both f64 values from scratch: the fast value path
/// (`crate::contact::wave_bounded::wave_value`: one compensated Miller
/// recurrence with both sums in the same loop, an estimate enforced by
/// tests/wave_value.rs) where it applies (FMA, `x/a <= 25/7`, `D <= 64`), else
/// the native proven-bound path's values where it runs without MP, else the
/// double-double Miller route of [`WaveBessel`].
fn wave_f64_pair(a: f64, zeta: f64, amp: f64, x: f64) -> Result<(f64, f64)> {
    check_wave_f64(a, zeta, amp, x)?;
    if let Some(r) = crate::contact::wave_bounded::wave_value(a, zeta, amp, x) {
        return Ok(r);
    }
    if let Some((u, du)) = CertifiedBessel::native_only(a, zeta).and_then(|c| c.eval_bounded(a, amp, x)) {
        return Ok((u.value, du.value));
    }
    let (u, du) = wave_bessel_f64(a, zeta, amp, x)?;
    if u.is_finite() && du.is_finite() {
        return Ok((u, du));
    }
    // the double-double route under- or overflows at extreme scales (found by
    // tests/fuzz.rs: a = x = 5e-324, zeta = 3.6e-217): the certified MP values
    let (u, du) = wave_bounded_fallback(a, zeta, amp, x)?;
    Ok((u.value, du.value))
}

/// Wave displacement `u_w(x)` in f64 (Bessel form), from scratch in about
/// 0.2-0.4 us on the model domain (compensated Miller recurrence, module docs
/// of [`crate::contact::wave_bounded`]).
///
/// Accuracy: within `1e-15` of `max(|u_w|, |A|)`, measured worst `1.1e-16` on a
/// dense grid of `a in [0.5, 6]`, `zeta = 9/8`, `x/a in [1, 3]` (tests/wave_value.rs;
/// an estimate: [`u_wave_bounded`] returns a proven bound).
pub fn u_wave(a: f64, zeta: f64, amp: f64, x: f64) -> Result<f64> {
    Ok(wave_f64_pair(a, zeta, amp, x)?.0)
}

/// Wave-displacement gradient `du_w/dx` in f64 (Bessel form), computed with
/// `u_w` by the same path as [`u_wave`]; within `1e-15` of
/// `max(|du_w/dx|, 2 pi |A|/zeta)` on the same grid (an estimate:
/// [`du_wave_bounded`] returns a proven bound).
pub fn du_wave(a: f64, zeta: f64, amp: f64, x: f64) -> Result<f64> {
    Ok(wave_f64_pair(a, zeta, amp, x)?.1)
}

/// `u_w(x)` in f64 with a proven error bound for the f64 inputs as given
/// (native double-double with running error analysis,
/// [`crate::contact::wave_bounded`]; for many `x` at one contact use
/// [`WaveBessel::eval_bounded`], which computes the Bessel data once).
pub fn u_wave_bounded(a: f64, zeta: f64, amp: f64, x: f64) -> Result<Bounded> {
    Ok(wave_bounded_pair(a, zeta, amp, x)?.0)
}

/// `du_w/dx` in f64 with a proven error bound for the f64 inputs as given.
pub fn du_wave_bounded(a: f64, zeta: f64, amp: f64, x: f64) -> Result<Bounded> {
    Ok(wave_bounded_pair(a, zeta, amp, x)?.1)
}

// ---------------------------------------------------------------- Eq. 12 / 11b series

/// A truncated series: the certified enclosure of the partial sum through
/// `kmax`, and a rigorous bound on everything after `kmax`.
#[derive(Debug, Clone)]
pub struct TruncatedSeries {
    /// Ball containing the partial sum `sum_{k=0}^{kmax} T_k`.
    pub partial: Ball,
    /// Upper bound on `|sum_{k>kmax} T_k|` (the truncation error of the paper's sum).
    pub trunc: Float,
}

impl TruncatedSeries {
    /// A ball containing the full (untruncated) value: `partial` widened by `trunc`.
    pub fn full(&self) -> Ball {
        let mut b = self.partial.clone();
        b.add_error(&self.trunc);
        b
    }
}

/// Which series.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum SeriesKind {
    /// Eq. 12, `u_w`.
    Displacement,
    /// Eq. 11b, `du_w/dx`.
    Gradient,
}

/// Upper bound of `|T_k|` for `k >= k0` as a geometric tail: returns
/// `(bound on sum_{k>=k0} |T_k|)` if the bound ratio from `k0` on is `< 1/2`, else `None`.
fn series_tail(kind: SeriesKind, g: &WaveGeometry, k0: u64) -> Result<Option<Float>> {
    let p = MAG_PREC + 32;
    let s = Ball::from_float(&g.s.upper(), p);
    let k0f = k0 as f64;
    let s_up = s.upper().to_f64();
    let ratio = match kind {
        // D^2/((2k+2)(2k+3)) (1 + 1/(2.39 (k+2))) for k >= k0 (ratio beta_{k+1}/beta_k)
        SeriesKind::Displacement => {
            4.0 * s_up / ((2.0 * k0f + 2.0) * (2.0 * k0f + 3.0)) * (1.0 + 1.0 / (PSI_DIFF_MAX * (k0f + 2.0)))
        }
        // s/((k+1)(k+2)) (2k+1)/(2k+3) (k+2)/(k+1) <= s/(k+1)^2
        SeriesKind::Gradient => s_up / ((k0f + 1.0) * (k0f + 1.0)),
    } * (1.0 + 1e-12);
    if !(ratio < 0.5) {
        return Ok(None);
    }
    let first = single_term_bound(kind, g, k0)?;
    let mut tail = Float::with_val(MAG_PREC, &first / (1.0 - ratio));
    tail.next_up();
    Ok(Some(tail))
}

/// Rigorous bound on `sum_{k > kmax} |T_k|`.
fn truncation_bound(kind: SeriesKind, g: &WaveGeometry, kmax: u64) -> Result<Float> {
    // Sum single-term bounds until the geometric tail applies.
    let mut total = Float::with_val(MAG_PREC, 0);
    let mut k = kmax + 1;
    loop {
        if let Some(t) = series_tail(kind, g, k)? {
            let mut sum = Float::with_val(MAG_PREC, &total + &t);
            sum.next_up();
            return Ok(sum);
        }
        // Not yet geometric: bound the single term T_k.
        let single = single_term_bound(kind, g, k)?;
        let mut sum = Float::with_val(MAG_PREC, &total + &single);
        sum.next_up();
        total = sum;
        k += 1;
        if k > kmax + 10_000_000 {
            return Err(Error::NoConvergence { function: "wave series truncation bound", terms: k });
        }
    }
}

/// The single-term bound `beta_k` (see the module docs).
fn single_term_bound(kind: SeriesKind, g: &WaveGeometry, k: u64) -> Result<Float> {
    let p = MAG_PREC + 32;
    let s = Ball::from_float(&g.s.upper(), p);
    let kk = u32::try_from(k).map_err(|_| Error::Domain { what: "kmax too large".into() })?;
    let exp_factor = s.div(&Ball::from_i64(k as i64 + 1, p))?.exp()?;
    let amp = Ball::from_float(&g.amp.abs_upper(), p);
    let b = match kind {
        SeriesKind::Displacement => {
            let coeff = s.mul_pow2(2).pow_u64(k).div(&Ball::factorial(2 * kk + 1, p))?;
            let ln_y = Ball::from_float(&g.y.lower(), p).ln()?.neg();
            let l = ln_y.add(&Ball::from_f64(PSI_DIFF_MAX, p)?).add(&Ball::from_i64(k as i64 + 2, p).ln()?);
            amp.mul(&s).mul(&coeff).mul(&exp_factor).mul(&l)
        }
        SeriesKind::Gradient => {
            let coeff = s
                .pow_u64(k)
                .div(&Ball::factorial(kk, p).mul(&Ball::factorial(kk + 1, p)).mul_i64(2 * k as i64 + 1))?;
            let x_lo = Ball::from_float(&g.x.lower(), p);
            amp.mul(&s).mul_pow2(1).div(&x_lo)?.mul(&coeff).mul(&exp_factor).mul_i64(2 * (k as i64 + 1))
        }
    };
    Ok(b.abs_upper())
}

/// `G(k, y)` at the geometry's `y` (ball), by the meijer module's algorithms.
fn meijer_at(consts: &MeijerConstants, g: &WaveGeometry, wp: u32) -> Result<Ball> {
    if g.at_edge {
        return Ok(meijer_g_k_at_one_with(consts));
    }
    match meijer_g::choose_algorithm(consts.k(), g.y.to_f64().min(1.0)) {
        meijer_g::Algorithm::Direct => meijer_g_k_direct_ball(consts, &g.y, wp),
        _ => meijer_g_k_near_one_ball(consts, &g.w, wp),
    }
}

/// `2F1(1, k+1/2; k+2; y)` at the geometry's `y` (ball): direct series for
/// `y <= 3/4`, else the `1-y` connection formula (see the meijer module docs)
/// `2(k+1) 2F1(1, k+1/2; 1/2; w) - K w^{1/2} y^{-k-1}`, `K = 2 sqrt(pi) Gamma(k+2)/Gamma(k+1/2)`.
fn model_hyp2f1(k: u32, g: &WaveGeometry, wp: u32) -> Result<Ball> {
    let kb = Ball::from_i64(k as i64, wp);
    let half = Ball::from_ratio(1, 2, wp);
    if g.at_edge {
        // Gauss: Gamma(k+2) Gamma(1/2)/(Gamma(k+1) Gamma(3/2)) = 2(k+1)
        return Ok(Ball::from_i64(2 * (k as i64 + 1), wp));
    }
    if g.y.upper() <= 0.75 {
        return Ok(pfq_series(&[Ball::one(wp), kb.add(&half)], &[kb.add_i64(2)], &g.y, wp)?.sum);
    }
    let h = pfq_series(&[Ball::one(wp), kb.add(&half)], std::slice::from_ref(&half), &g.w, wp)?.sum;
    let kf = Float::with_val(64, k);
    let g2 = Ball::from_float(&Float::with_val(64, &kf + 2u32), wp).gamma()?;
    let gh = Ball::from_float(&Float::with_val(64, &kf + 0.5), wp).gamma()?;
    let big_k = Ball::pi(wp).sqrt()?.mul_pow2(1).mul(&g2).div(&gh)?;
    let w_pos = if g.w.lower() < 0 { Ball::hull(&Float::new(wp), &g.w.upper(), wp) } else { g.w.clone() };
    let second = big_k.mul(&w_pos.sqrt()?).div(&g.y.pow_u64(k as u64 + 1))?;
    Ok(h.mul_i64(2 * (k as i64 + 1)).sub(&second))
}

/// Sums Eq. 12 or Eq. 11b through `kmax` at working precision `wp`.
fn wave_series_wp(kind: SeriesKind, g: &WaveGeometry, kmax: u64, wp: u32) -> Result<Ball> {
    let mut coeff = Ball::one(wp); // D^{2k}/(2k+1)!  or  s^k/(k!(k+1)!(2k+1))
    let mut sum = Ball::zero(wp);
    let pre = prefactor(kind, g, wp)?;
    let pre_lower = pre.abs_lower();
    let mut consts = match kind {
        SeriesKind::Displacement => Some(MeijerConstants::new(0, wp)?),
        SeriesKind::Gradient => None,
    };
    // In the direct region (y <= 1/2) all S_k(y) come from one sweep up to a
    // k beyond which the terms are negligible at this precision; later k (if the
    // early stop has not come by then) are evaluated one by one.
    // Near y = 1 the same recurrences start from the near-one expansion, as long
    // as k_top (1 - y) stays small (the connection formula's pieces cancel by
    // about e^{k w}).
    let k_top = sweep_top(g, kmax, wp);
    let k_top = u32::try_from(k_top).map_err(|_| Error::Domain { what: "kmax too large".into() })?;
    let sweep = match choose_meijer_sweep(kind, g, k_top, wp) {
        MeijerSweep::PerK => None,
        MeijerSweep::Direct => Some((direct_sums_sweep(k_top, &g.y, wp)?, g.y.ln()?)),
        MeijerSweep::NearOne { extra_bits } => {
            // The connection formula's two pieces cancel by about e^{k_top w}:
            // run the sweep with that many extra bits, then round back.
            let hp = wp + extra_bits;
            let (x_hp, a_hp) = (g.x.set_prec(hp), g.a.set_prec(hp));
            let w_hp = x_hp.sub(&a_hp).mul(&x_hp.add(&a_hp)).div(&x_hp.sqr())?;
            let sums = near_one_sums_sweep(k_top, &w_hp, hp)?;
            Some((sums.into_iter().map(|b| b.set_prec(wp)).collect(), g.y.ln()?))
        }
    };
    // All 1F2 factors through k_top from one downward recurrence.
    let family = hyp1f2_model_family(k_top, &g.s, wp)?;
    let mut k: u64 = 0;
    loop {
        let kk = u32::try_from(k).map_err(|_| Error::Domain { what: "kmax too large".into() })?;
        let f12 = match family.get(kk as usize) {
            Some(f) => f.clone(),
            None => hyp1f2_model_ball(kk, &g.s, wp)?,
        };
        let other = match kind {
            SeriesKind::Displacement => match (&consts, &sweep) {
                (Some(c), Some((sums, ln_y))) if (kk as usize) < sums.len() => {
                    meijer_g_k_from_sum(c, ln_y, &sums[kk as usize])
                }
                (Some(c), _) => meijer_at(c, g, wp)?,
                (None, _) => return Err(Error::Internal { what: "missing Meijer constants".into() }),
            },
            SeriesKind::Gradient => model_hyp2f1(kk, g, wp)?,
        };
        let term = coeff.mul(&f12).mul(&other);
        sum = if k % 2 == 0 { sum.add(&term) } else { sum.sub(&term) };
        if k == kmax {
            break;
        }
        // Early stop: the rest of the partial sum (k+1..=kmax) is bounded by the tail
        // (checked every 4th term: the bound itself costs a few ball operations).
        let tail = if k % 4 == 3 { series_tail(kind, g, k + 1)? } else { None };
        if let Some(rest) = tail {
            let mut target = sum.abs_lower();
            target >>= wp as i32 + 8;
            // The tail is in units of the final value (prefactors included).
            let mut rest_scaled = Float::with_val(MAG_PREC, &rest / &pre_lower);
            rest_scaled.next_up();
            if pre_lower > 0 && rest_scaled <= target {
                sum.add_error(&rest_scaled);
                break;
            }
        }
        // next coefficient
        let kf = k as i64;
        coeff = match kind {
            SeriesKind::Displacement => coeff.mul(&g.d.sqr()).div_i64((2 * kf + 2) * (2 * kf + 3))?,
            SeriesKind::Gradient => {
                coeff.mul(&g.s).mul_i64(2 * kf + 1).div_i64((kf + 1) * (kf + 2) * (2 * kf + 3))?
            }
        };
        if let Some(c) = consts.as_mut() {
            *c = c.next()?;
        }
        k += 1;
    }
    Ok(pre.mul(&sum))
}

/// Where the sweeps of [`wave_series_wp`] end: an f64 estimate of the `k` at which the
/// early stop fires, plus 8 (the stop is tested every 4th term), capped at `kmax`.
///
/// The stop needs `series_tail(k+1)/prefactor <= 2^-(wp+8) |sum|`; with the single-term
/// bound of the module docs that is `sqrt(pi) e^{s/(k+2)} L_k (4s)^{k+1}/(2k+3)!/(1 - rho)`
/// (Eq. 12; Eq. 11b's terms `s^{k+1}/((k+1)!(k+2)!)` are of the same size, and there only
/// the 1F2 family uses `k_top`). `|sum|` is not known
/// beforehand: it is taken as `2^-16/s` (`|u_w| >= 2^-16 A` roughly). Where the
/// estimate is short (a tiny `u_w`), the terms past the sweep are evaluated one by
/// one (correct, slower). Before this estimate the sweep ended at
/// `1.5 D + wp/8 + 20`, four terms short at `abar = 6`: those four per-k Meijer
/// values near `y = 1` cost 8 ms of the 9 ms at `x/a = 1.2`.
fn sweep_top(g: &WaveGeometry, kmax: u64, wp: u32) -> u64 {
    let s = g.s.upper().to_f64().max(f64::MIN_POSITIVE);
    let ln_inv_y = (1.0 / g.y.lower().to_f64().max(f64::MIN_POSITIVE)).ln();
    let target = -((wp + 8 + 16) as f64) * std::f64::consts::LN_2 - s.ln();
    let ln_4s = (4.0 * s).ln();
    // ln((4s)^(k+1)/(2k+3)!) for k = 0: ln(4s/6)
    let mut ln_term = ln_4s - 6.0f64.ln();
    let mut k: u64 = 0;
    while k < kmax {
        let kf = k as f64;
        let rho = 4.0 * s / ((2.0 * kf + 4.0) * (2.0 * kf + 5.0));
        if rho < 0.5 {
            let ln_tail = 0.5 * std::f64::consts::PI.ln() + s / (kf + 2.0) + (ln_inv_y + PSI_DIFF_MAX + (kf + 3.0).ln()).ln() + ln_term - (1.0 - rho).ln();
            if ln_tail <= target {
                break;
            }
        }
        k += 1;
        let kf = k as f64;
        ln_term += ln_4s - ((2.0 * kf + 2.0) * (2.0 * kf + 3.0)).ln();
    }
    (k + 8).min(kmax)
}

/// How the Meijer sums `S_k(y)`, `k <= k_top`, of one Eq. 12 evaluation are obtained.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum MeijerSweep {
    /// One `G(k, y)` per term (the gradient series, or the edge `x = a`).
    PerK,
    /// [`direct_sums_sweep`]: two series with term ratio `<= y`.
    Direct,
    /// [`near_one_sums_sweep`] with `extra_bits` against the cancellation `~ e^{k_top w}`.
    NearOne { extra_bits: u32 },
}

/// Picks the cheaper sweep by the number of series terms each needs at `wp` bits.
///
/// * direct: the two series have term ratio `<= y`: about `wp ln 2 / (-ln y)` terms each;
/// * near one: the `2F1(1, k_top+1/2; -1/2; w)` series grows while `w (k_top+n)/n > 1`,
///   i.e. for about `k_top w/(1-w)` terms, then decays like `w^n`: about
///   `k_top w/(1-w) + wp ln 2/(-ln w)` terms, and the connection formula loses
///   `1.45 k_top w` bits, paid as extra precision (`NEAR_ONE_SWEEP_MAX_KW` caps it).
///
/// Before this choice, points with `1/2 < y` and `k_top w > 10` (x/a from about 1.1
/// to 1.4 at abar = 3 and 6) fell back to one Meijer series per k: 50-90 ms at 128 bits.
fn choose_meijer_sweep(kind: SeriesKind, g: &WaveGeometry, k_top: u32, wp: u32) -> MeijerSweep {
    if kind != SeriesKind::Displacement || g.at_edge {
        return MeijerSweep::PerK;
    }
    let y = g.y.upper().to_f64();
    let w = g.w.upper().to_f64().max(f64::MIN_POSITIVE);
    if !(y < 1.0) {
        return MeijerSweep::PerK;
    }
    let bits = wp as f64 * std::f64::consts::LN_2;
    let direct_cost = 2.0 * bits / -y.ln();
    let kw = k_top as f64 * w;
    if w <= 0.5 && kw <= NEAR_ONE_SWEEP_MAX_KW {
        let extra = 1.45 * kw;
        let near_cost = (kw / (1.0 - w) + (bits + extra) / -w.ln()) * (1.0 + extra / wp as f64);
        if near_cost < direct_cost {
            return MeijerSweep::NearOne { extra_bits: extra.ceil() as u32 + 8 };
        }
    }
    MeijerSweep::Direct
}

/// `(A/sqrt(pi)) s` for Eq. 12, `2 A s/x` for Eq. 11b.
fn prefactor(kind: SeriesKind, g: &WaveGeometry, wp: u32) -> Result<Ball> {
    match kind {
        SeriesKind::Displacement => g.amp.mul(&g.s).div(&Ball::pi(wp).sqrt()?),
        SeriesKind::Gradient => g.amp.mul(&g.s).mul_pow2(1).div(&g.x),
    }
}

fn wave_series_mp(
    kind: SeriesKind,
    a: &Float,
    zeta: &Float,
    amp: &Float,
    x: &Float,
    kmax: u64,
    prec: u32,
) -> Result<TruncatedSeries> {
    crate::error::check_prec(prec)?;
    check_wave_mp(a, zeta, amp, x)?;
    check_kmax(kmax)?;
    if amp.is_zero() {
        return Ok(TruncatedSeries { partial: Ball::zero(prec), trunc: Float::with_val(MAG_PREC, 0) });
    }
    // The terms reach ~ e^D / sqrt(D): that many bits cancel.
    let d = 2.0 * std::f64::consts::PI * a.to_f64() / zeta.to_f64();
    let guard = DEFAULT_GUARD_BITS + (std::f64::consts::LOG2_E * d).ceil() as u32;
    let name = match kind {
        SeriesKind::Displacement => "u_wave_series",
        SeriesKind::Gradient => "du_wave_series",
    };
    let floor = match kind {
        SeriesKind::Displacement => Float::with_val(MAG_PREC, amp.abs_ref()),
        SeriesKind::Gradient => gradient_scale(amp, zeta),
    };
    let partial = ziv_with_floor(name, prec, guard, Some(&floor), |wp| {
        if std::env::var("MAUGIS_TRACE").is_ok() { eprintln!("{name}: wp = {wp}"); }
        let g = wave_geometry(a, zeta, amp, x, wp)?;
        wave_series_wp(kind, &g, kmax, wp)
    })?;
    let g = wave_geometry(a, zeta, amp, x, MAG_PREC + 32)?;
    let trunc = truncation_bound(kind, &g, kmax)?;
    Ok(TruncatedSeries { partial, trunc })
}

/// Eq. 12 truncated at `kmax`: certified partial sum plus a rigorous truncation bound.
pub fn u_wave_series_mp(a: &Float, zeta: &Float, amp: &Float, x: &Float, kmax: u64, prec: u32) -> Result<TruncatedSeries> {
    wave_series_mp(SeriesKind::Displacement, a, zeta, amp, x, kmax, prec)
}

/// Eq. 11b truncated at `kmax`: certified partial sum plus a rigorous truncation bound.
pub fn du_wave_series_mp(a: &Float, zeta: &Float, amp: &Float, x: &Float, kmax: u64, prec: u32) -> Result<TruncatedSeries> {
    wave_series_mp(SeriesKind::Gradient, a, zeta, amp, x, kmax, prec)
}

/// Eq. 12 truncated at `kmax` in f64: `(partial sum, truncation bound)`.
///
/// Summing Eq. 12 in f64 loses every digit for `D = 2 pi a/zeta` beyond ~25, so
/// the partial sum is computed in certified MP and rounded.
pub fn u_wave_series(a: f64, zeta: f64, amp: f64, x: f64, kmax: u64) -> Result<(f64, f64)> {
    check_wave_f64(a, zeta, amp, x)?;
    let r = u_wave_series_mp(&exact(a), &exact(zeta), &exact(amp), &exact(x), kmax, crate::special::F64_FALLBACK_PREC)?;
    Ok((r.partial.to_f64(), r.trunc.to_f64_round(rug::float::Round::Up)))
}

// ---------------------------------------------------------------- Hertz, profile, adhesive

fn check_positive(v: f64, what: &'static str) -> Result<()> {
    finite(v, what)?;
    if v <= 0.0 {
        return Err(Error::Domain { what: format!("{what} must be > 0 (got {v})") });
    }
    Ok(())
}

/// Hertz displacement `u_H(x)` (Eq. 10) for contact half-width `a`, radius `r`.
pub fn u_hertz(a: f64, r: f64, x: f64) -> Result<f64> {
    check_positive(a, "a")?;
    check_positive(r, "r")?;
    finite(x, "x")?;
    let ax = x.abs();
    if ax <= a {
        return crate::special::finite_result("u_hertz", x * x / (2.0 * r));
    }
    let sq = ((ax - a) * (ax + a)).sqrt();
    let acosh = ((ax - a) / a + sq / a).ln_1p();
    crate::special::finite_result("u_hertz", a * a / (2.0 * r) * (ax / (ax + sq) + acosh))
}

/// Certified Hertz displacement `u_H(x)` (Eq. 10).
pub fn u_hertz_mp(a: &Float, r: &Float, x: &Float, prec: u32) -> Result<Ball> {
    for (v, n) in [(a, "a"), (r, "r"), (x, "x")] {
        check_finite(v, n)?;
    }
    if *a <= 0 || *r <= 0 {
        return Err(Error::Domain { what: "u_hertz needs a > 0 and r > 0".into() });
    }
    crate::error::check_prec(prec)?;
    let ax = Float::with_val(x.prec(), x.abs_ref());
    ziv("u_hertz", prec, DEFAULT_GUARD_BITS, |wp| {
        let rb = Ball::from_float(r, wp);
        let xb = Ball::from_float(&ax, wp);
        if ax <= *a {
            return xb.sqr().div(&rb.mul_pow2(1));
        }
        let ab = Ball::from_float(a, wp);
        let xma = Ball::from_float(&exact_sub(&ax, a), wp);
        let xpa = Ball::from_float(&exact_add(&ax, a), wp);
        let sq = xma.mul(&xpa).sqrt()?;
        let acosh = xma.add(&sq).div(&ab)?.ln_1p()?;
        Ok(ab.sqr().div(&rb.mul_pow2(1))?.mul(&xb.div(&xb.add(&sq))?.add(&acosh)))
    })
}

/// Profile depth `h(x) = x^2/(2R) + A (1 - cos(2 pi x/zeta))` (Eq. 1).
pub fn profile_depth(r: f64, amp: f64, zeta: f64, x: f64) -> Result<f64> {
    check_positive(r, "r")?;
    check_positive(zeta, "zeta")?;
    finite(amp, "amp")?;
    finite(x, "x")?;
    let sn = (std::f64::consts::PI * x / zeta).sin();
    Ok(x * x / (2.0 * r) + 2.0 * amp * sn * sn)
}

/// Adhesive displacement `u_a(x)` (Box I, A.5a/A.5b) for the Dugdale–Maugis strip
/// `a < |x| < c` with cohesive stress `sigma` and plane-strain modulus `e_star`.
pub fn u_adhesive(a: f64, c: f64, sigma: f64, e_star: f64, x: f64) -> Result<f64> {
    check_positive(a, "a")?;
    check_positive(sigma, "sigma")?;
    check_positive(e_star, "e_star")?;
    finite(c, "c")?;
    finite(x, "x")?;
    if c < a {
        return Err(Error::Domain { what: format!("the strip end c must be >= a (got c = {c} < a = {a})") });
    }
    let kfac = 4.0 * sigma / (std::f64::consts::PI * e_star);
    let ax = x.abs();
    if ax <= a || c == a {
        return Ok(0.0);
    }
    let c2a2 = ((c - a) * (c + a)).sqrt();
    let acosh_xa = ((ax - a) / a + ((ax - a) * (ax + a)).sqrt() / a).ln_1p();
    let v = if ax < c {
        let xx = c2a2 / ((c - ax) * (c + ax)).sqrt();
        c * (ax * xx / a).acosh() - ax * xx.acosh() - c2a2 * acosh_xa
    } else if ax == c {
        c * (c / a).ln() - c2a2 * acosh_xa
    } else {
        let yy = c2a2 / ((ax - c) * (ax + c)).sqrt();
        c * (ax * yy / a).asinh() - ax * yy.asinh() - c2a2 * acosh_xa
    };
    crate::special::finite_result("u_adhesive", kfac * v)
}

/// Certified adhesive displacement `u_a(x)` (Box I, A.5a/A.5b).
pub fn u_adhesive_mp(a: &Float, c: &Float, sigma: &Float, e_star: &Float, x: &Float, prec: u32) -> Result<Ball> {
    for (v, n) in [(a, "a"), (c, "c"), (sigma, "sigma"), (e_star, "e_star"), (x, "x")] {
        check_finite(v, n)?;
    }
    if *a <= 0 || *sigma <= 0 || *e_star <= 0 {
        return Err(Error::Domain { what: "u_adhesive needs a > 0, sigma > 0, e_star > 0".into() });
    }
    if *c < *a {
        return Err(Error::Domain { what: "the strip end c must be >= a".into() });
    }
    crate::error::check_prec(prec)?;
    let ax = Float::with_val(x.prec(), x.abs_ref());
    if ax <= *a || c == a {
        return Ok(Ball::zero(prec));
    }
    ziv("u_adhesive", prec, DEFAULT_GUARD_BITS, |wp| {
        let ab = Ball::from_float(a, wp);
        let cb = Ball::from_float(c, wp);
        let xb = Ball::from_float(&ax, wp);
        let kfac = Ball::from_float(sigma, wp).mul_pow2(2).div(&Ball::pi(wp).mul(&Ball::from_float(e_star, wp)))?;
        let cma = Ball::from_float(&exact_sub(c, a), wp);
        let cpa = Ball::from_float(&exact_add(c, a), wp);
        let c2a2 = cma.mul(&cpa).sqrt()?;
        let xma = Ball::from_float(&exact_sub(&ax, a), wp);
        let xpa = Ball::from_float(&exact_add(&ax, a), wp);
        let acosh_xa = xma.add(&xma.mul(&xpa).sqrt()?).div(&ab)?.ln_1p()?;
        let v = match ax.partial_cmp(c) {
            Some(std::cmp::Ordering::Less) => {
                let cmx = Ball::from_float(&exact_sub(c, &ax), wp);
                let cpx = Ball::from_float(&exact_add(c, &ax), wp);
                let xx = c2a2.div(&cmx.mul(&cpx).sqrt()?)?;
                cb.mul(&xb.mul(&xx).div(&ab)?.acosh()?).sub(&xb.mul(&xx.acosh()?)).sub(&c2a2.mul(&acosh_xa))
            }
            Some(std::cmp::Ordering::Equal) => cb.mul(&cb.div(&ab)?.ln()?).sub(&c2a2.mul(&acosh_xa)),
            _ => {
                let xmc = Ball::from_float(&exact_sub(&ax, c), wp);
                let xpc = Ball::from_float(&exact_add(&ax, c), wp);
                let yy = c2a2.div(&xmc.mul(&xpc).sqrt()?)?;
                cb.mul(&xb.mul(&yy).div(&ab)?.asinh()).sub(&xb.mul(&yy.asinh())).sub(&c2a2.mul(&acosh_xa))
            }
        };
        Ok(kfac.mul(&v))
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn e(v: f64) -> Float {
        exact(v)
    }

    #[test]
    fn substrate_meets_profile_at_the_edge() {
        // u_w(a) = A (1 - cos(2 pi a/zeta)) exactly (docs/displacement.md, "Errata pinned by tests").
        for &(a, zeta) in &[(2.0, 1.125), (0.7, 2.0), (6.0, 1.125), (5.5, 0.5)] {
            let u = u_wave_mp(&e(a), &e(zeta), &e(1.0), &e(a), 128).unwrap();
            let d = Ball::pi(200).mul_pow2(1).mul(&Ball::from_f64(a, 200).unwrap()).div(&Ball::from_f64(zeta, 200).unwrap()).unwrap();
            let expect = Ball::one(200).sub(&d.cos());
            assert!(u.overlaps(&expect), "a={a} zeta={zeta}: {u:?} vs {expect:?}");
            let f = u_wave(a, zeta, 1.0, a).unwrap();
            assert!((f - expect.to_f64()).abs() < 1e-14, "f64 {f} vs {}", expect.to_f64());
        }
    }

    #[test]
    fn series_and_bessel_form_agree() {
        for &(a, zeta, x) in &[(2.0, 1.125, 2.6), (0.7, 2.0, 0.75), (3.0, 2.0, 9.0), (5.5, 1.125, 5.6)] {
            let b = u_wave_mp(&e(a), &e(zeta), &e(1.0), &e(x), 100).unwrap();
            let s = u_wave_series_mp(&e(a), &e(zeta), &e(1.0), &e(x), 1000, 100).unwrap();
            assert!(s.full().overlaps(&b), "u: a={a} x={x}: {:?} vs {b:?}", s.partial);
            let db = du_wave_mp(&e(a), &e(zeta), &e(1.0), &e(x), 100).unwrap();
            let ds = du_wave_series_mp(&e(a), &e(zeta), &e(1.0), &e(x), 1000, 100).unwrap();
            assert!(ds.full().overlaps(&db), "du: a={a} x={x}: {:?} vs {db:?}", ds.partial);
        }
    }

    #[test]
    fn traction_integral_matches_quadrature() {
        use crate::quad::gauss_legendre;
        for &(a, zeta) in &[(2.0, 1.125), (6.0, 1.125), (0.3, 2.0)] {
            let wb = WaveBessel::new(a, zeta, 1.0).unwrap();
            let d = wb.d();
            for &c in &[0.0, 0.3, -0.7, 0.999, 1.0] {
                let k = wb.traction_integral(c);
                let q = gauss_legendre::integrate_composite(
                    |t| crate::special::bessel_j::bessel_j_sequence(0, t)[0] * ((t - d) * c).cos(),
                    0.0,
                    d,
                    24,
                    64,
                )
                .unwrap();
                assert!((k - q).abs() < 1e-13, "a={a} zeta={zeta} c={c}: {k} vs {q}");
            }
        }
    }

    #[test]
    fn sweep_reaches_the_early_stop() {
        // The early stop of wave_series_wp (tested at k = 3 mod 4) must fall inside the
        // sweep, else the terms after it cost one Meijer series each (8 ms at abar = 6).
        let wp = 200;
        for &abar in &[1.0, 3.0, 6.0] {
            for &r in &[1.0005, 1.05, 1.2, 1.35, 2.0, 3.0] {
                let g = wave_geometry(&e(abar), &e(1.125), &e(1.0), &e(abar * r), wp).unwrap();
                let sum = wave_series_wp(SeriesKind::Displacement, &g, 1000, wp).unwrap();
                let pre_lower = prefactor(SeriesKind::Displacement, &g, wp).unwrap().abs_lower();
                let mut target = sum.div(&prefactor(SeriesKind::Displacement, &g, wp).unwrap()).unwrap().abs_lower();
                target >>= wp as i32 + 8;
                let stop = (3..1000u64)
                    .step_by(4)
                    .find(|&k| series_tail(SeriesKind::Displacement, &g, k + 1).unwrap().is_some_and(|t| t / &pre_lower <= target))
                    .unwrap();
                let top = sweep_top(&g, 1000, wp);
                assert!(top >= stop && top <= stop + 16, "abar={abar} x/a={r}: sweep to {top}, stop at {stop}");
            }
        }
    }

    #[test]
    fn bad_input() {
        assert!(u_wave(0.0, 1.0, 1.0, 1.0).is_err());
        assert!(u_wave(1.0, 0.0, 1.0, 1.0).is_err());
        assert!(u_wave(1.0, 1.0, 1.0, 0.5).is_err());
        assert!(u_wave(1.0, 1.0, f64::NAN, 1.5).is_err());
        assert!(u_wave_series(1.0, 1.0, 1.0, 1.5, u64::MAX).is_err());
        assert!(u_hertz(1.0, -1.0, 2.0).is_err());
        assert!(u_adhesive(1.0, 0.5, 1.0, 1.0, 2.0).is_err());
    }
}
