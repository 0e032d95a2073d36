//! Arbitrary-precision versions of the model's core quantities, on request:
//! the strip residual `F(m)` (Eq. 15b, corrected), a certified enclosure of the
//! strip end `m`, and the load (Eq. 14).
//!
//! **Two entry points per quantity.** The `*_ball_mp` functions take the model's
//! inputs `lambda, (alpha_j, beta_j)_j, abar` as balls (any number of waves; the
//! wave terms are summed over them, docs/model.md "Many waves") ([`ModelBalls`], Arb's
//! convention): the result encloses the quantity at *every* point of the input
//! balls, which is how a decimal typed by a user is certified
//! (`maugis eval`'s `strip_ratio` and `load`, and for many waves
//! `strip_ratio_waves` and `load_waves`: [`strip_ratio_waves_at_decimals`],
//! [`load_waves_at_decimals`]). The f64 entry points
//! ([`strip_residual_mp`], [`solve_m_mp`], [`load_mp`]) read their inputs as
//! exact binary numbers and run the ball code on exact balls.
//!
//! **Method.** `F` is evaluated in ball arithmetic in the variable `e = m - 1`
//! (no cancellation as `m -> 1`): `sqrt(m^2 - 1) = sqrt(e (e + 2))`,
//! `acosh m = ln1p(e + sqrt(e (e + 2)))`, `ln m = ln1p(e)`, and the wave term by
//! the certified Bessel form of [`crate::contact::displacement`] at `x/a = m`,
//! with `J_n` at a ball `D = 2 pi abar / beta` taken at its midpoint and widened
//! by `rad(D)` (`|J_n'| <= 1`, DLMF 10.14.1). Every operation is a ball
//! operation on the input balls, so the sign of `F` is proven for all inputs in
//! the balls when its ball excludes zero.
//!
//! [`solve_m_ball_mp`] starts from the f64 first root of
//! [`ContactSize::solve_strip`] at the midpoints (solved in `m - 1`, so the
//! bracket is tight even as `m -> 1`), proves a sign change of `F` across a
//! small bracket **over the whole input balls** (raising the working precision
//! by the measured deficit where the balls, not the sign, are the obstacle),
//! then tries to finish
//! at once: a secant on ball midpoints estimates the root and two ball
//! evaluations prove the sign change across a bracket of the target width (the
//! estimate carries no claim; only those evaluations do). Otherwise it bisects
//! the bracket. A bisection
//! point where `F`'s ball straddles zero is re-evaluated at the input
//! midpoints: if that straddles too the working precision is raised (Ziv);
//! otherwise the width of the inputs is what keeps the root from being located
//! more tightly, and the current bracket is returned. So the returned ball
//! contains, for every input in the balls, a root of `F`; for exact inputs its
//! relative width is `2^-prec`. That it is the *first* root rests on the f64
//! scan at the midpoints (see `model.rs`).
//!
//! The load (Eq. 14) is ball arithmetic on the inputs and the ball of `m`; the
//! pair (inputs, `m(inputs)`) lies inside the balls, so the load ball encloses
//! the load at every input in the balls. Its working precision covers the wave
//! term's prefactor `pi^2 alpha abar/beta` times `D` against the Hertz load
//! (`wave_load_guard`: 28 bits at beta = 0.001).

use rug::Float;

use crate::ball::{eval_at_decimals, eval_at_decimals_with_floor, Ball, Decimal};
use crate::contact::displacement::u_wave_at_ratio_balls;
use crate::contact::model::{ContactSize, Params, ABAR_RANGE, ALPHA_RANGE, BETA_RANGE, LAMBDA_RANGE};
use crate::contact::profile::{WavyProfile, MAX_WAVES};
use crate::error::{check_prec, Error, Interval, ProfileError, Result, WaveField};
use crate::special::bessel_j::bessel_j_mp;
use crate::special::exact_sub;
use crate::MAX_WORKING_PREC;

/// One wave of the profile as balls: amplitude `alpha` and wavelength `beta`
/// (normalised, `docs/model.md`).
#[derive(Debug, Clone)]
pub struct WaveBalls {
    /// Wave amplitude, within `[0, ALPHA_MAX]` over the whole ball.
    pub alpha: Ball,
    /// Wavelength, within [`BETA_RANGE`] over the whole ball.
    pub beta: Ball,
}

impl WaveBalls {
    /// An amplitude known to be exactly 0: the wave adds nothing.
    fn is_absent(&self) -> bool {
        self.alpha.is_exact() && self.alpha.mid().is_zero()
    }
}

/// The model's inputs as balls: the Maugis parameter `lambda`, the profile's waves
/// (each an amplitude `alpha_j` and a wavelength `beta_j`) and the contact
/// half-width `abar`. Every result computed from them encloses its value at every
/// point of the balls.
#[derive(Debug, Clone)]
pub struct ModelBalls {
    /// Maugis parameter, within [`LAMBDA_RANGE`] over the whole ball.
    pub lambda: Ball,
    /// The waves, at most [`MAX_WAVES`], in the profile's order.
    pub waves: Vec<WaveBalls>,
    /// Contact half-width, within `(0, ABAR_MAX]` over the whole ball.
    pub abar: Ball,
}

/// `v` at no fewer than `wp` bits (raising the precision is exact; a ball
/// already finer than `wp`, such as a decimal input, is kept as it is).
fn at_least(v: &Ball, wp: u32) -> Ball {
    if v.prec() >= wp {
        v.clone()
    } else {
        v.set_prec(wp)
    }
}


impl ModelBalls {
    /// Checked inputs: each ball must be finite and lie inside the model's
    /// domain over its whole width (an edge inside a ball is a typed error that
    /// names it).
    pub fn new(lambda: Ball, alpha: Ball, beta: Ball, abar: Ball) -> Result<ModelBalls> {
        for (v, what) in [(&alpha, "alpha"), (&beta, "beta")] {
            if !v.is_finite() {
                return Err(Error::NonFinite { what });
            }
        }
        alpha.check_within("alpha", ALPHA_RANGE)?;
        beta.check_within("beta", BETA_RANGE)?;
        ModelBalls::with_waves(lambda, vec![WaveBalls { alpha, beta }], abar)
    }

    /// Checked inputs for any number of waves (`0..=`[`MAX_WAVES`]): a wave whose ball
    /// reaches outside its range is [`ProfileError::Wave`] naming the wave (1-based)
    /// and the field.
    pub fn with_waves(lambda: Ball, waves: Vec<WaveBalls>, abar: Ball) -> Result<ModelBalls> {
        for (v, what) in [(&lambda, "lambda"), (&abar, "abar")] {
            if !v.is_finite() {
                return Err(Error::NonFinite { what });
            }
        }
        lambda.check_within("lambda", LAMBDA_RANGE)?;
        abar.check_within("abar", ABAR_RANGE)?;
        if waves.len() > MAX_WAVES {
            return Err(Error::Profile(ProfileError::TooManyWaves { count: waves.len(), max: MAX_WAVES }));
        }
        for (i, w) in waves.iter().enumerate() {
            for (v, field, allowed) in [(&w.alpha, WaveField::Amplitude, ALPHA_RANGE), (&w.beta, WaveField::Wavelength, BETA_RANGE)] {
                if !v.is_finite() || v.check_within("wave", allowed).is_err() {
                    let value = if v.is_finite() { v.mid().to_f64() } else { f64::NAN };
                    return Err(Error::Profile(ProfileError::Wave { wave: i + 1, field, value, allowed }));
                }
            }
        }
        Ok(ModelBalls { lambda, waves, abar })
    }

    /// Exact balls of validated f64 parameters and `abar`.
    pub fn exact(params: Params, abar: f64) -> Result<ModelBalls> {
        let b = |v: f64| Ball::from_f64(v, 53);
        let waves = params
            .profile
            .waves()
            .iter()
            .map(|w| Ok(WaveBalls { alpha: b(w.alpha())?, beta: b(w.beta())? }))
            .collect::<Result<Vec<_>>>()?;
        ModelBalls::with_waves(b(params.lambda)?, waves, b(abar)?)
    }

    /// Whether every input is an exact number.
    pub fn is_exact(&self) -> bool {
        self.lambda.is_exact() && self.abar.is_exact() && self.waves.iter().all(|w| w.alpha.is_exact() && w.beta.is_exact())
    }

    /// The midpoints, as exact balls.
    fn midpoints(&self) -> ModelBalls {
        let m = |v: &Ball| Ball::from_float(v.mid(), v.prec());
        let waves = self.waves.iter().map(|w| WaveBalls { alpha: m(&w.alpha), beta: m(&w.beta) }).collect();
        ModelBalls { lambda: m(&self.lambda), waves, abar: m(&self.abar) }
    }

    /// The midpoints rounded to f64, for the f64 root scan that starts
    /// [`solve_m_ball_mp`], and the start `e0 = m - 1` at working precision `wp`
    /// that the scan gives.
    ///
    /// A contact size below [`START_ABAR_MIN`] (down to the MP range, `1e-400` as
    /// typed) is scanned at `START_ABAR_MIN`: the root's strip width `s = abar (m - 1)`
    /// depends on `abar` there only through terms of relative size `abar ln(1/abar)`
    /// (its limit solves `lambda (s^2/2 + (4 ln 2/pi) lambda s + 2 alpha sin^2(pi s/beta)) = 1`),
    /// far below the f64 scan's own tolerance, so `e0 = s/abar` is computed in MP at
    /// the midpoint. Only the start comes from here: the sign changes that enclose
    /// the root are proven in ball arithmetic at the inputs as given.
    fn f64_start(&self, wp: u32) -> Result<Float> {
        let f = |v: &Ball| v.mid().to_f64();
        let pairs: Vec<(f64, f64)> = self.waves.iter().map(|w| (f(&w.alpha), f(&w.beta))).collect();
        let params = match pairs.as_slice() {
            [(alpha, beta)] => Params::new(f(&self.lambda), *alpha, *beta)?,
            _ => Params::with_profile(f(&self.lambda), WavyProfile::from_pairs(&pairs)?)?,
        };
        let abar = f(&self.abar);
        if abar >= START_ABAR_MIN {
            return Ok(Float::with_val(wp, ContactSize::new(params, abar)?.solve_strip()?.m_minus_1()));
        }
        let width = ContactSize::new(params, START_ABAR_MIN)?.solve_strip()?.m_minus_1() * START_ABAR_MIN;
        Ok(Float::with_val(wp, width) / self.abar.mid())
    }
}

/// The smallest contact size the f64 scan that starts [`bracket_root`] runs at
/// (see `ModelBalls::f64_start`; below it the Bessel data of the f64 wave terms
/// reach subnormal numbers).
const START_ABAR_MIN: f64 = 1e-300;

/// `F(m) = lambda gbar(m abar) - 1` over the input balls, at working precision
/// `wp`, for a ball of `e = m - 1 >= 0`.
pub fn strip_residual_ball_mp(inputs: &ModelBalls, m_minus_1: &Ball, wp: u32) -> Result<Ball> {
    crate::error::check_working_prec(wp)?;
    if m_minus_1.upper() < 0 {
        return Err(m_minus_1.out_of_range("m - 1", Interval::at_least(0.0)));
    }
    // m - 1 >= 0 by definition: clip a ball that reaches below zero.
    let e = if m_minus_1.lower() < 0 { Ball::hull(&Float::new(wp), &m_minus_1.upper(), wp) } else { at_least(m_minus_1, wp) };
    let [lam, a] = [&inputs.lambda, &inputs.abar].map(|v| at_least(v, wp));
    let mb = e.add_i64(1);
    let s = e.mul(&e.add_i64(2)).sqrt()?; // sqrt(m^2 - 1)
    let acosh_m = e.add(&s).ln_1p()?;
    let ln_m = e.ln_1p()?;
    let hertz = a.sqr().mul(&mb.mul(&s).sub(&acosh_m)).mul_pow2(-1);
    let adhesive = Ball::pi(wp).recip()?.mul_pow2(2).mul(&lam).mul(&a).mul(&s.mul(&acosh_m).sub(&mb.mul(&ln_m)));
    // sum_j [2 alpha_j sin^2(pi c / beta_j) - u_w,j(c)], c = m abar
    let mut wave: Option<Ball> = None;
    for w in inputs.waves.iter().filter(|w| !w.is_absent()) {
        let [alpha, beta] = [&w.alpha, &w.beta].map(|v| at_least(v, wp));
        let uw = u_wave_at_ratio_balls(&a, &beta, &alpha, &e, wp)?;
        let arg = Ball::pi(wp).mul(&a).mul(&mb).div(&beta)?;
        let sn = arg.sin_cos().0;
        let term = sn.sqr().mul(&alpha).mul_pow2(1).sub(&uw);
        wave = Some(match wave {
            None => term,
            Some(sum) => sum.add(&term),
        });
    }
    Ok(lam.mul(&hertz.add(&adhesive).add(&wave.unwrap_or_else(|| Ball::zero(wp)))).add_i64(-1))
}

/// `F(m) = lambda gbar(m abar) - 1` in ball arithmetic at working precision `wp`
/// (`m >= 1` and the parameters exact binary numbers).
pub fn strip_residual_mp(params: Params, abar: f64, m: &Float, wp: u32) -> Result<Ball> {
    crate::error::check_working_prec(wp)?;
    if *m < 1 {
        return Err(Error::OutOfRange { arg: "m (the strip ratio)", value: m.to_f64(), allowed: Interval::at_least(1.0) });
    }
    let e = Ball::from_float(&exact_sub(m, &Float::with_val(2, 1)), wp); // m - 1, exact
    strip_residual_ball_mp(&ModelBalls::exact(params, abar)?, &e, wp)
}

/// What the bisection's width is relative to.
#[derive(Clone, Copy, PartialEq, Eq)]
enum RootScale {
    /// `m`: the ball of `m` has relative width `2^-prec`.
    StripRatio,
    /// `m - 1`: the ball of `m - 1` has relative width `2^-prec` (for the
    /// load, whose `sqrt(m^2 - 1)` magnifies errors in `m` as `m -> 1`).
    StripRatioMinusOne,
}

/// A ball of `e = m - 1` that contains, for every input in the balls, a root
/// of `F`; see the module doc and [`solve_m_ball_mp`].
fn bracket_root(inputs: &ModelBalls, prec: u32, scale: RootScale) -> Result<Ball> {
    check_prec(prec)?;
    let mut wp = prec + 32;
    let e0 = inputs.f64_start(wp)?;
    let mids = inputs.midpoints();
    let exact = inputs.is_exact();
    // Bracket [lo, hi] of m - 1 around the f64 root with a proven sign change
    // over the whole input balls: e0 (1 -+ 1e-9 16^tries), in f64 where that is
    // finite (the f64 root as it was always used), else in MP (m - 1 past 1e290:
    // a contact size below about 1e-290).
    let e0_f64 = e0.to_f64();
    let around = |spread: f64, wp: u32| -> (Float, Float) {
        if e0_f64 < 1e290 {
            let delta = e0_f64 * spread;
            (Float::with_val(wp, (e0_f64 - delta).max(0.0)), Float::with_val(wp, e0_f64 + delta))
        } else {
            let delta = Float::with_val(wp, &e0 * spread);
            (Float::with_val(wp, &e0 - &delta), Float::with_val(wp, &e0 + &delta))
        }
    };
    let mut spread = 1e-9;
    let (mut lo, mut hi);
    let mut tries = 0;
    let mut raises = 0;
    loop {
        (lo, hi) = around(spread, wp);
        let flo = strip_residual_ball_mp(inputs, &Ball::from_float(&lo, wp), wp)?;
        let fhi = strip_residual_ball_mp(inputs, &Ball::from_float(&hi, wp), wp)?;
        if flo.is_negative() && fhi.is_positive() {
            break;
        }
        // The midpoints have the expected signs but a ball straddles zero. If it
        // does so at the midpoint inputs too, the working precision is what
        // limits. (On rough profiles, D = 2 pi abar/beta in the thousands, the
        // ball recurrence of the J_n once widened the wave's radius by ~0.68 D
        // bits; the midpoint recurrence now loses about 2 log2 D.) Raise wp by
        // the measured deficit (a few times at most, by 15 % more than
        // measured) instead of widening the bracket around a root that is
        // already there.
        let signs_right = flo.mid().is_sign_negative() && fhi.mid().is_sign_positive() && !flo.mid().is_zero() && !fhi.mid().is_zero();
        if signs_right && raises < MAX_DEFICIT_RAISES {
            let at_mids = |x: &Float| strip_residual_ball_mp(&mids, &Ball::from_float(x, wp), wp);
            let (glo, ghi) = if exact { (flo.clone(), fhi.clone()) } else { (at_mids(&lo)?, at_mids(&hi)?) };
            let deficit = [&glo, &ghi].iter().map(|f| 48.0 - f.rel_accuracy_bits()).fold(0.0f64, f64::max);
            if !(glo.is_negative() && ghi.is_positive()) && deficit.is_finite() && deficit > 0.0 {
                raises += 1;
                wp = (wp as f64 + (1.15 * deficit).ceil() + 32.0).min(MAX_WORKING_PREC as f64) as u32;
                continue;
            }
        }
        spread *= 16.0;
        tries += 1;
        if tries > 12 {
            // No proven sign change at this working precision: the residual's
            // balls are too wide (strong cancellation on rough profiles, found by
            // the eval fuzz target at alpha/beta = 2500). Raise the precision
            // once before giving up with a typed error; for decimal inputs,
            // eval_at_decimals then retries with tighter balls (the input balls'
            // width, not the working precision, is then what limits).
            if wp < 2 * (prec + 32) {
                wp = (2 * wp).min(crate::MAX_WORKING_PREC);
                spread = 1e-9;
                tries = 0;
                continue;
            }
            return Err(Error::RootNotCertified { quantity: "m - 1 (the strip ratio, Eq. 15b)", near: e0_f64, input_balls: !exact });
        }
    }
    let target_width = match scale {
        RootScale::StripRatio => Float::with_val(wp, &hi + 1u32),
        RootScale::StripRatioMinusOne => hi.clone(),
    } >> prec as i32;
    // Estimate, then verify: a secant iteration on the (uncertified) midpoints
    // of F at the midpoint inputs and a cheap precision locates the root; two
    // ball evaluations at `wp` over the input balls then prove the sign change
    // across a bracket of the target width (or a wider one, when the input
    // balls' width is what keeps it from being that narrow). Only those two
    // evaluations carry the proof; when they fail, the bisection below runs on
    // whatever they proved.
    if let Some((vlo, vhi, done)) = verified_bracket(inputs, &mids, &lo, &hi, &target_width, prec, &mut wp, &mut raises)? {
        if done {
            return Ok(Ball::hull(&vlo, &vhi, wp));
        }
        (lo, hi) = (Float::with_val(wp, &vlo), Float::with_val(wp, &vhi));
    }
    // Bisection until the bracket is 2^-prec m (or 2^-prec (m - 1)) wide.
    loop {
        let width = Float::with_val(wp, &hi - &lo);
        let size = match scale {
            RootScale::StripRatio => Float::with_val(wp, &hi + 1u32),
            RootScale::StripRatioMinusOne => hi.clone(),
        };
        if width <= size >> prec as i32 {
            return Ok(Ball::hull(&lo, &hi, wp));
        }
        let mid = Float::with_val(wp + 1, &lo + &hi) / 2u32;
        let f = strip_residual_ball_mp(inputs, &Ball::from_float(&mid, wp + 1), wp)?;
        if f.is_negative() {
            lo = mid;
        } else if f.is_positive() {
            hi = mid;
        } else if !exact && !strip_residual_ball_mp(&mids, &Ball::from_float(&mid, wp + 1), wp)?.contains_zero() {
            // At the midpoint inputs the sign is proven: the input width is
            // what straddles, and the roots over the balls fill a range
            // around `mid`. Locate its two ends separately.
            let fine = Float::with_val(wp, &hi - &lo) >> 5u32;
            let lower = one_sided_end(inputs, &lo, &mid, true, &fine, wp)?;
            let upper = one_sided_end(inputs, &mid, &hi, false, &fine, wp)?;
            return Ok(Ball::hull(&lower, &upper, wp));
        } else {
            // F's ball straddles zero at this precision: raise it (Ziv).
            wp += 32;
            if wp > MAX_WORKING_PREC {
                return Err(Error::PrecisionExhausted { function: "solve_m_mp", working_prec: wp });
            }
            lo = Float::with_val(wp, &lo);
            hi = Float::with_val(wp, &hi);
        }
    }
}

/// Raises of the working precision by a measured deficit in [`bracket_root`]'s
/// search for a sign change.
const MAX_DEFICIT_RAISES: u32 = 6;

/// Widening factors (powers of two of the target width) tried when the input
/// balls keep the verified bracket from being as narrow as asked.
const WIDENINGS: [u32; 4] = [0, 8, 16, 32];

/// The estimate-then-verify step of [`bracket_root`]. `F` is proven negative at
/// `lo` and positive at `hi` over the input balls. Returns
/// `Some((lo', hi', true))` with `[lo', hi'] ⊂ [lo, hi]`, `F(lo') < 0` and
/// `F(hi') > 0` proven over the input balls and `hi' - lo'` the target `width`
/// times `2^k` for the first `k` of [`WIDENINGS`] that verifies (`k > 0` only
/// when the midpoint inputs verify at the target width: the input balls are
/// what is wide); `Some((lo', hi', false))` with the tightest proven ends when
/// no width verifies; `None` when the secant gives no estimate.
#[allow(clippy::too_many_arguments)]
fn verified_bracket(
    inputs: &ModelBalls, mids: &ModelBalls, lo: &Float, hi: &Float, width: &Float, prec: u32, wp: &mut u32, raises: &mut u32,
) -> Result<Option<(Float, Float, bool)>> {
    // Secant on midpoint values at a cheap precision, then (if that does not
    // verify) once more at `wp`.
    let mut estimate_wp = (prec + 96).min(*wp);
    loop {
        let Some(r) = secant_estimate(mids, lo, hi, width, estimate_wp)? else { return Ok(None) };
        let (mut best_lo, mut best_hi) = (lo.clone(), hi.clone());
        let w = *wp;
        for (i, &k) in WIDENINGS.iter().enumerate() {
            let half = Float::with_val(w, width << k) >> 1u32;
            let a = Float::with_val(w, &r - &half).max(lo);
            let b = Float::with_val(w, &r + &half).min(hi);
            let f = |x: &Float, on: &ModelBalls| strip_residual_ball_mp(on, &Ball::from_float(x, w), w);
            let (fa, fb) = (f(&a, inputs)?, f(&b, inputs)?);
            if fa.is_negative() && a > best_lo {
                best_lo = a.clone();
            }
            if fb.is_positive() && b < best_hi {
                best_hi = b.clone();
            }
            if fa.is_negative() && fb.is_positive() {
                return Ok(Some((a, b, true)));
            }
            if i > 0 {
                continue;
            }
            let (ga, gb) = if inputs.is_exact() { (fa, fb) } else { (f(&a, mids)?, f(&b, mids)?) };
            if !(ga.is_negative() && gb.is_positive()) {
                // Not even at the midpoint inputs: the working precision limits
                // (or the estimate is off). Raise it by the measured deficit while
                // the midpoints have the expected signs, then check again.
                let signs_right = ga.mid().is_sign_negative() && gb.mid().is_sign_positive() && !ga.mid().is_zero() && !gb.mid().is_zero();
                let deficit = [&ga, &gb].iter().map(|g| 8.0 - g.rel_accuracy_bits()).fold(0.0f64, f64::max);
                if signs_right && deficit.is_finite() && deficit > 0.0 && *raises < MAX_DEFICIT_RAISES && *wp < MAX_WORKING_PREC {
                    *raises += 1;
                    *wp = (*wp as f64 + (1.15 * deficit).ceil() + 32.0).min(MAX_WORKING_PREC as f64) as u32;
                    return verified_bracket(inputs, mids, lo, hi, width, prec, wp, raises);
                }
                // Widen only when the midpoint inputs verify at the target width.
                break;
            }
        }
        if estimate_wp >= *wp {
            return Ok(Some((best_lo, best_hi, false)));
        }
        estimate_wp = *wp;
    }
}

/// A root estimate of `F` at the midpoint inputs in `[lo, hi]` (where the
/// midpoints of `F` change sign) by the secant method on ball midpoints at
/// `wp`: no claim, only a guess for [`verified_bracket`] to check.
fn secant_estimate(mids: &ModelBalls, lo: &Float, hi: &Float, tol: &Float, wp: u32) -> Result<Option<Float>> {
    let f = |x: &Float| -> Result<Float> { Ok(strip_residual_ball_mp(mids, &Ball::from_float(x, wp), wp)?.mid().clone()) };
    let (mut x0, mut x1) = (Float::with_val(wp, lo), Float::with_val(wp, hi));
    let (mut f0, mut f1) = (f(&x0)?, f(&x1)?);
    for _ in 0..40 {
        if f1.is_zero() {
            break;
        }
        let den = Float::with_val(wp, &f1 - &f0);
        if den.is_zero() || !den.is_finite() {
            return Ok(None);
        }
        let step = Float::with_val(wp, &x1 - &x0) * &f1 / &den;
        let x2 = Float::with_val(wp, &x1 - &step).max(lo).min(hi);
        let moved = Float::with_val(wp, &x2 - &x1).abs();
        (x0, f0) = (x1, f1);
        x1 = x2;
        f1 = f(&x1)?;
        if moved <= Float::with_val(wp, tol >> 4u32) {
            break;
        }
    }
    Ok(x1.is_finite().then_some(x1))
}

/// One end of the range of roots over wide input balls: within `[lo, hi]`,
/// where `F` is proven negative at `lo` and straddles zero at `hi` (`lower`)
/// or straddles at `lo` and is proven positive at `hi` (upper end), bisect
/// until the interval is `fine` wide, keeping the side whose sign is proven.
/// Returns the proven end (`lo` for the lower end, `hi` for the upper).
fn one_sided_end(inputs: &ModelBalls, lo: &Float, hi: &Float, lower: bool, fine: &Float, wp: u32) -> Result<Float> {
    let (mut lo, mut hi) = (lo.clone(), hi.clone());
    while Float::with_val(wp, &hi - &lo) > *fine {
        let mid = Float::with_val(wp + 1, &lo + &hi) / 2u32;
        let f = strip_residual_ball_mp(inputs, &Ball::from_float(&mid, wp + 1), wp)?;
        let proven_outside = if lower { f.is_negative() } else { f.is_positive() };
        match (lower, proven_outside) {
            (true, true) | (false, false) => lo = mid,
            (true, false) | (false, true) => hi = mid,
        }
    }
    Ok(if lower { lo } else { hi })
}

/// A ball that contains, for every input in the balls, a root of `F` (the f64
/// solver's first root at the midpoints); of relative width `2^-prec` when the
/// inputs are tight enough, wider (and still enclosing) when their width keeps
/// the root from being located more tightly. See the module doc.
pub fn solve_m_ball_mp(inputs: &ModelBalls, prec: u32) -> Result<Ball> {
    Ok(bracket_root(inputs, prec, RootScale::StripRatio)?.add_i64(1))
}

/// A ball that provably contains a root of `F` (the f64 solver's first root),
/// of relative width `2^-prec`; the parameters are exact binary numbers.
pub fn solve_m_mp(params: Params, abar: f64, prec: u32) -> Result<Ball> {
    solve_m_ball_mp(&ModelBalls::exact(params, abar)?, prec)
}

/// Eq. 14 over the input balls, for a strip ratio known as a ball:
/// `pi abar^2/4 - 2 lambda abar sqrt(m^2-1) + (pi^2 alpha abar/beta) J1(2 pi abar/beta)`.
pub fn load_ball_mp(inputs: &ModelBalls, m: &Ball, prec: u32) -> Result<Ball> {
    check_prec(prec)?;
    if !m.is_finite() {
        return Err(Error::NonFinite { what: "m" });
    }
    load_from_m_minus_1(inputs, &m.add_i64(-1), prec)
}

/// Eq. 14 for a ball of `e = m - 1`, with `sqrt(m^2 - 1) = sqrt(e (e + 2))`.
fn load_from_m_minus_1(inputs: &ModelBalls, e: &Ball, prec: u32) -> Result<Ball> {
    check_prec(prec)?;
    let wp = prec + LOAD_GUARD_BITS + wave_load_guard(inputs);
    if e.upper() < 0 {
        return Err(e.out_of_range("m - 1", Interval::at_least(0.0)));
    }
    // m - 1 >= 0 by definition: clip a ball that reaches below zero.
    let e = if e.lower() < 0 { Ball::hull(&Float::new(wp), &e.upper(), wp) } else { at_least(e, wp) };
    let [lam, a] = [&inputs.lambda, &inputs.abar].map(|v| at_least(v, wp));
    let pi = Ball::pi(wp);
    let s = e.mul(&e.add_i64(2)).sqrt()?;
    let hertz = pi.mul(&a.sqr()).mul_pow2(-2);
    let adhesive = lam.mul(&a).mul(&s).mul_pow2(1);
    let mut wave: Option<Ball> = None;
    for w in inputs.waves.iter().filter(|w| !w.is_absent()) {
        let [alpha, beta] = [&w.alpha, &w.beta].map(|v| at_least(v, wp));
        // J1 at D = 2 pi abar/beta (a ball): |J1'| <= 1, evaluate at the midpoint and widen
        let d = pi.mul(&a).mul_pow2(1).div(&beta)?;
        let mut j1 = bessel_j_mp(1, d.mid(), wp)?;
        j1.add_error_mag(d.rad_mag());
        let term = pi.sqr().mul(&alpha).mul(&a).div(&beta)?.mul(&j1);
        wave = Some(match wave {
            None => term,
            Some(sum) => sum.add(&term),
        });
    }
    Ok(hertz.sub(&adhesive).add(&wave.unwrap_or_else(|| Ball::zero(wp))))
}

/// Guard bits of [`load_from_m_minus_1`] beyond its wave term.
const LOAD_GUARD_BITS: u32 = 16;

/// Extra guard bits for the wave term of Eq. 14, `(pi^2 alpha abar/beta) J1(D)`,
/// `D = 2 pi abar/beta`: the roundings in `D` (relative `2^-wp`) reach the load
/// as `|J1'| D 2^-wp <= D 2^-wp` times the prefactor, and those of the
/// prefactor as `|J1| <= min(1, D/2)` [DLMF 10.14.1, 10.14.4] times it, against
/// the Hertz load `pi abar^2/4` that the accuracy is measured on. So about
/// `log2(pi^2 |alpha| abar/beta (D + min(1, D/2)) / (pi abar^2/4))` bits, from the
/// midpoints in f64 (an estimate that only sets the working precision; the
/// ball arithmetic carries the proof). At beta = 0.001 that is 28 bits; before,
/// the load at 53 bits never met its tolerance and `eval_at_decimals` raised
/// the input precision to its cap (over 60 s).
///
/// For many waves, the largest of the waves' guards plus `log2` of the number of waves.
fn wave_load_guard(inputs: &ModelBalls) -> u32 {
    let a = inputs.abar.mid().to_f64().abs();
    let pi = std::f64::consts::PI;
    let per_wave = inputs.waves.iter().map(|w| {
        let [alpha, beta] = [&w.alpha, &w.beta].map(|v| v.mid().to_f64().abs());
        let d = 2.0 * pi * a / beta;
        let ratio = pi * pi * alpha * a / beta * (d + (d / 2.0).min(1.0)) / (pi * a * a / 4.0);
        if ratio.is_finite() && ratio > 1.0 {
            ratio.log2().ceil().min(4096.0) as u32
        } else {
            0
        }
    });
    let count_bits = usize::BITS - inputs.waves.len().saturating_sub(1).leading_zeros();
    per_wave.max().unwrap_or(0) + if inputs.waves.len() > 1 { count_bits } else { 0 }
}

/// Eq. 14 in ball arithmetic for a strip ratio known as a ball; the parameters
/// are exact binary numbers.
pub fn load_mp(params: Params, abar: f64, m: &Ball, prec: u32) -> Result<Ball> {
    load_ball_mp(&ModelBalls::exact(params, abar)?, m, prec)
}

/// How the model's decimal inputs are laid out, and how their balls become [`ModelBalls`].
#[derive(Clone, Copy)]
enum Layout {
    /// `[lambda, alpha, beta, abar]` (the seed paper's one wave; errors name `alpha`, `beta`).
    OneWave,
    /// `[lambda, abar, alpha_1, beta_1, alpha_2, beta_2, ...]` (errors name the wave and the field).
    Waves,
}

impl Layout {
    /// The inputs' balls as [`ModelBalls`].
    fn balls(self, b: &[Ball]) -> Result<ModelBalls> {
        match (self, b) {
            (Layout::OneWave, [lambda, alpha, beta, abar]) => ModelBalls::new(lambda.clone(), alpha.clone(), beta.clone(), abar.clone()),
            (Layout::Waves, [lambda, abar, waves @ ..]) if waves.len() % 2 == 0 => {
                let waves = waves.chunks(2).map(|w| WaveBalls { alpha: w[0].clone(), beta: w[1].clone() }).collect();
                ModelBalls::with_waves(lambda.clone(), waves, abar.clone())
            }
            (Layout::OneWave, _) => Err(Error::Arity { function: "the model", expected: 4, got: b.len() }),
            (Layout::Waves, _) => Err(Error::IncompleteGroup { function: "the model", group: "wave", names: &["alpha", "beta"], fixed: 2, got: b.len() }),
        }
    }

    /// Where `abar` is.
    fn abar(self) -> usize {
        match self {
            Layout::OneWave => 3,
            Layout::Waves => 1,
        }
    }
}

/// `[lambda, abar, alpha_1, beta_1, ...]` as one list; at most [`MAX_WAVES`] waves
/// ([`ProfileError::TooManyWaves`] at once, before any evaluation).
fn wave_args(lambda: &Decimal, abar: &Decimal, waves: &[(Decimal, Decimal)]) -> Result<Vec<Decimal>> {
    if waves.len() > MAX_WAVES {
        return Err(Error::Profile(ProfileError::TooManyWaves { count: waves.len(), max: MAX_WAVES }));
    }
    let mut args = vec![lambda.clone(), abar.clone()];
    for (alpha, beta) in waves {
        args.extend([alpha.clone(), beta.clone()]);
    }
    Ok(args)
}

fn strip_ratio_in(layout: Layout, args: &[Decimal], prec: u32) -> Result<Ball> {
    eval_at_decimals(args, prec, |b| solve_m_ball_mp(&layout.balls(b)?, prec))
}

fn load_in(layout: Layout, args: &[Decimal], prec: u32) -> Result<Ball> {
    let abar = Float::with_val(64, args[layout.abar()].as_rational());
    let hertz = Float::with_val(64, &abar * &abar) * Float::with_val(64, rug::float::Constant::Pi) / 4u32;
    eval_at_decimals_with_floor(args, prec, Some(&hertz), |b| {
        let inputs = layout.balls(b)?;
        let e = bracket_root(&inputs, prec + 32, RootScale::StripRatioMinusOne)?;
        load_from_m_minus_1(&inputs, &e, prec)
    })
}

/// The strip ratio `m` at decimal inputs `[lambda, alpha, beta, abar]` on the
/// ball contract of [`crate::ball::eval_at_decimals`] (what `maugis eval` runs
/// for `strip_ratio`): the ball contains the (first) root of Eq. 15b at the
/// decimals as typed, with `rad <= 2^-prec m`.
pub fn strip_ratio_at_decimals(args: &[Decimal; 4], prec: u32) -> Result<Ball> {
    strip_ratio_in(Layout::OneWave, args, prec)
}

/// The load (Eq. 14) at the strip ratio of Eq. 15b, at decimal inputs
/// `[lambda, alpha, beta, abar]` (what `maugis eval` runs for `load`). The load
/// vanishes along every load-area curve, so the accuracy promise is absolute,
/// on the Hertz load of the same contact: `rad <= 2^-prec max(|L|, pi abar^2/4)`.
pub fn load_at_decimals(args: &[Decimal; 4], prec: u32) -> Result<Ball> {
    load_in(Layout::OneWave, args, prec)
}

/// [`strip_ratio_at_decimals`] for a profile of any number of waves
/// (`0..=`[`MAX_WAVES`], each `(alpha_j, beta_j)` as typed; what `maugis eval` runs
/// for `strip_ratio_waves`). Every decimal is a ball that contains it; the
/// answer contains the first root of Eq. 15b (the waves' terms summed, docs/model.md
/// "Many waves") at the decimals, with `rad <= 2^-prec m`. One wave gives the ball of
/// [`strip_ratio_at_decimals`] bit for bit. A bad wave is [`ProfileError::Wave`]
/// naming the wave (from 1) and the field.
pub fn strip_ratio_waves_at_decimals(lambda: &Decimal, abar: &Decimal, waves: &[(Decimal, Decimal)], prec: u32) -> Result<Ball> {
    strip_ratio_in(Layout::Waves, &wave_args(lambda, abar, waves)?, prec)
}

/// [`load_at_decimals`] for a profile of any number of waves (what `maugis eval`
/// runs for `load_waves`), on the same contract:
/// `rad <= 2^-prec max(|L|, pi abar^2/4)`. One wave gives the ball of
/// [`load_at_decimals`] bit for bit.
pub fn load_waves_at_decimals(lambda: &Decimal, abar: &Decimal, waves: &[(Decimal, Decimal)], prec: u32) -> Result<Ball> {
    load_in(Layout::Waves, &wave_args(lambda, abar, waves)?, prec)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn certified_root_agrees_with_f64_solver() {
        for &(lambda, abar) in &[(1.0, 0.7), (6.0, 3.16), (0.25, 2.2)] {
            let p = Params::new(lambda, 2f64.sqrt() / 4.0, 1.125).unwrap();
            let cs = ContactSize::new(p, abar).unwrap();
            let m0 = cs.solve_m().unwrap();
            let l0 = cs.load(m0).unwrap();
            let m = solve_m_mp(p, abar, 128).unwrap();
            assert!(m.meets_rel(120), "{m:?}");
            assert!((m.to_f64() - m0).abs() <= 1e-12 * m0, "f64 {m0} vs MP {m:?}");
            let l = load_mp(p, abar, &m, 128).unwrap();
            assert!((l.to_f64() - l0).abs() < 1e-10, "load {l:?} vs {l0}");
            // the residual changes sign across the returned ball
            assert!(strip_residual_mp(p, abar, &m.lower(), 192).unwrap().is_negative());
            assert!(strip_residual_mp(p, abar, &m.upper(), 192).unwrap().is_positive());
        }
    }

    #[test]
    fn rough_profile_root_is_certified() {
        // Was 6 min at load 22, then 3.5 s (53 bits) and 5.3 s (128 bits): the
        // wave's J_n came from the ball recurrence, whose radius grows by ~0.68 D
        // bits (D = 2 pi/beta ~ 6300), and bracket_root raised the working
        // precision to ~6800 bits. With the midpoint recurrence
        // (bessel_j_sequence_three_term) it answers at prec + 32: 0.10 s and
        // 0.09 s (examples/corners_23b, test profile, load average 3-4).
        // cli/src/eval.rs's fuzz target: strip_ratio at lambda = 2.5, alpha = 2.5,
        // beta = "0.001", abar = 1 (prec 53) once answered "internal error: no
        // certified sign change of F around the f64 root m - 1 = 6.5e-5".
        let d = |t: &str| Decimal::parse(t).unwrap();
        for prec in [53, 128] {
            let m = strip_ratio_at_decimals(&[d("2.5"), d("2.5"), d("0.001"), d("1")], prec).unwrap();
            assert!(m.meets_rel(prec), "{prec}: {m:?}");
            let m1 = m.to_f64() - 1.0;
            assert!((m1 - 6.532499002676018e-5).abs() < 1e-3 * m1, "{prec}: {m:?}");
        }
    }

    #[test]
    fn rough_profile_load_is_certified() {
        // Issue 23: load(2.5, 2.5, "0.001", 1) took over 60 s at 53 and 128 bits
        // and, at 53 bits, returned a ball 17x wider than its tolerance (the
        // wave term of Eq. 14 at prec + 16 bits; eval_at_decimals raised the
        // input precision to its cap without reaching it). Now 0.09 s / 0.12 s
        // (examples/corners_23b load, test profile, load average 3-4).
        let d = |t: &str| Decimal::parse(t).unwrap();
        let p = Params::new(2.5, 2.5, 0.001).unwrap();
        let cs = ContactSize::new(p, 1.0).unwrap();
        let l64 = cs.load(cs.solve_m().unwrap()).unwrap();
        let hertz = Float::with_val(64, rug::float::Constant::Pi) / 4u32;
        let mut prev: Option<Ball> = None;
        for prec in [53, 128, 512] {
            let l = load_at_decimals(&[d("2.5"), d("2.5"), d("0.001"), d("1")], prec).unwrap();
            // the contract: rad <= 2^-prec max(|L|, pi abar^2/4)
            assert!(l.meets_rel(prec) || l.meets_abs(prec, &hertz), "{prec}: {l:?}");
            assert!((l.to_f64() - l64).abs() <= 1e-6 * l64.abs(), "{prec}: {l:?} against the f64 model's {l64}");
            if let Some(q) = &prev {
                assert!(q.overlaps(&l), "{prec}: {l:?} against {q:?}");
            }
            prev = Some(l);
        }
    }
}
