//! The seed's series: Eq. 12 for `u_w` and Eq. 11b for `du_w/dx`, truncated
//! at `kmax`, as certified balls of the partial sum with a rigorous bound on the
//! rest (module docs of [`super`], "the truncation bound").
//!
//! The Meijer-G factors come from [`crate::special::meijer_g`] (one series per
//! `k`, or the sweeps over `k`), the 1F2 factors from
//! [`crate::special::hyp1f2`]'s model family. The terms grow to about
//! `e^D/sqrt(D)` before they cancel; the Ziv loop adds those bits.

use rug::Float;

use crate::ball::{Ball, MAG_PREC};
use crate::error::{Error, Reached, Result};
use crate::special::hyp1f2::{hyp1f2_model_ball, hyp1f2_model_family};
use crate::special::meijer_g::{
    self, direct_sums_sweep, meijer_g_k_at_one_with, meijer_g_k_direct_ball, meijer_g_k_from_sum, meijer_g_k_near_one_ball, near_one_sums_sweep,
    MeijerConstants,
};
use crate::special::pfq::pfq_series;
use crate::special::{exact, ziv_with_floor, DEFAULT_GUARD_BITS};

use super::geometry::{check_kmax, check_wave_f64, check_wave_mp, gradient_scale, wave_geometry, WaveGeometry};

/// Largest `k_top (1 - y)` for the near-one sweep of the Meijer sums in Eq. 12
/// (it then runs with `1.45 k_top w <= 58` extra bits).
const NEAR_ONE_SWEEP_MAX_KW: f64 = 40.0;

/// `1 + 2 ln 2`, rounded up: the largest value of `psi(k+2) - psi(k+1/2)` (at `k = 0`).
const PSI_DIFF_MAX: f64 = 2.39;

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

/// A term index beyond `u32` (unreachable after [`check_kmax`], which caps `kmax`
/// at [`super::MAX_KMAX`]).
fn kmax_error(k: u64) -> Error {
    Error::IntegerOutOfRange { arg: "kmax", value: i64::try_from(k).unwrap_or(i64::MAX), min: 0, max: super::MAX_KMAX as i64 }
}

/// Which series.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum SeriesKind {
    /// Eq. 12, `u_w`.
    Displacement,
    /// Eq. 11b, `du_w/dx`.
    Gradient,
}

/// The bound on `beta_{k+1}/beta_k` for every `k >= k0` (module docs), when it is
/// below 1/2 (the tail from `k0` on is then geometric), else `None`.
fn tail_ratio(kind: SeriesKind, g: &WaveGeometry, k0: u64) -> Option<f64> {
    let k0f = k0 as f64;
    let s_up = g.s.upper().to_f64();
    let ratio = match kind {
        // D^2/((2k+2)(2k+3)) (1 + 1/(2.39 (k+2))) for k >= k0 (ratio beta_{k+1}/beta_k)
        SeriesKind::Displacement => {
            4.0 * s_up / ((2.0 * k0f + 2.0) * (2.0 * k0f + 3.0)) * (1.0 + 1.0 / (PSI_DIFF_MAX * (k0f + 2.0)))
        }
        // s/((k+1)(k+2)) (2k+1)/(2k+3) (k+2)/(k+1) <= s/(k+1)^2
        SeriesKind::Gradient => s_up / ((k0f + 1.0) * (k0f + 1.0)),
    } * (1.0 + 1e-12);
    (ratio < 0.5).then_some(ratio)
}

/// `sum_{k>=k0} |T_k|` bounded by the geometric tail `beta_{k0} / (1 - ratio)`,
/// `ratio` from [`tail_ratio`].
fn geometric_tail(first: &Float, ratio: f64) -> Float {
    let mut tail = Float::with_val(MAG_PREC, first / (1.0 - ratio));
    tail.next_up();
    tail
}

/// Upper bound of `|T_k|` for `k >= k0` as a geometric tail: returns
/// `(bound on sum_{k>=k0} |T_k|)` if the bound ratio from `k0` on is `< 1/2`, else `None`.
fn series_tail(kind: SeriesKind, g: &WaveGeometry, k0: u64) -> Result<Option<Float>> {
    let Some(ratio) = tail_ratio(kind, g, k0) else { return Ok(None) };
    let first = single_term_bound(kind, g, k0)?;
    Ok(Some(geometric_tail(&first, ratio)))
}

/// Rigorous bound on `sum_{k > kmax} |T_k|`.
///
/// Sums the single-term bounds until the geometric tail applies, at
/// `k ~ sqrt(2 s)`; their `k`-dependent coefficient by its recurrence
/// ([`next_term_coeff`]), one factorial at `kmax + 1` only. (With a factorial per
/// `k`, at `s ~ 10^6` the 1500 bounds cost 0.1 s of MPFR's `fac_ui` after the
/// series itself, with no budget check: `u_wave_series(10000, 29.38, 23.4,
/// 2.9e15998, 1)` took 0.15 s of a 0.1 s budget, issue 37's scan.) The call's
/// budget is checked every [`crate::budget::TERMS_BETWEEN_CHECKS`] bounds.
fn truncation_bound(kind: SeriesKind, g: &WaveGeometry, kmax: u64) -> Result<Float> {
    let p = MAG_PREC + 32;
    let s = Ball::from_float(&g.s.upper(), p);
    let mut total = Float::with_val(MAG_PREC, 0);
    let mut k = kmax + 1;
    let mut coeff = term_coeff(kind, &s, k, p)?;
    loop {
        let single = single_term_bound_with(kind, g, k, &coeff)?;
        if let Some(ratio) = tail_ratio(kind, g, k) {
            let mut sum = Float::with_val(MAG_PREC, &total + &geometric_tail(&single, ratio));
            sum.next_up();
            return Ok(sum);
        }
        // Not yet geometric: add the bound of the single term T_k.
        let mut sum = Float::with_val(MAG_PREC, &total + &single);
        sum.next_up();
        total = sum;
        coeff = next_term_coeff(kind, &s, &coeff, k)?;
        k += 1;
        if (k - kmax) % crate::budget::TERMS_BETWEEN_CHECKS == 0 {
            crate::budget::check_elapsed("the wave series' truncation bound", 0.0, Reached::Terms { count: k - kmax })?;
        }
        if k > kmax + 10_000_000 {
            return Err(Error::NoConvergence { function: "wave series truncation bound", terms: k });
        }
    }
}

/// The `k`-dependent coefficient of the single-term bound `beta_k`:
/// `(4s)^k/(2k+1)!` (Eq. 12) or `s^k/(k! (k+1)! (2k+1))` (Eq. 11b), `s` a ball at `p` bits.
fn term_coeff(kind: SeriesKind, s: &Ball, k: u64, p: u32) -> Result<Ball> {
    let kk = u32::try_from(k).map_err(|_| kmax_error(k))?;
    match kind {
        SeriesKind::Displacement => s.mul_pow2(2).pow_u64(k).div(&Ball::factorial(2 * kk + 1, p)),
        SeriesKind::Gradient => {
            s.pow_u64(k).div(&Ball::factorial(kk, p).mul(&Ball::factorial(kk + 1, p)).mul_i64(2 * k as i64 + 1))
        }
    }
}

/// [`term_coeff`] at `k + 1` from its value at `k` (exact ratios, ball arithmetic):
/// `4s/((2k+2)(2k+3))`, or `s (2k+1)/((k+1)(k+2)(2k+3))`.
fn next_term_coeff(kind: SeriesKind, s: &Ball, coeff: &Ball, k: u64) -> Result<Ball> {
    let k = i64::try_from(k).map_err(|_| kmax_error(k))?;
    match kind {
        SeriesKind::Displacement => coeff.mul(&s.mul_pow2(2)).div_i64(2 * k + 2)?.div_i64(2 * k + 3),
        SeriesKind::Gradient => coeff.mul(s).mul_i64(2 * k + 1).div_i64(k + 1)?.div_i64(k + 2)?.div_i64(2 * k + 3),
    }
}

/// The single-term bound `beta_k` (see the module docs).
fn single_term_bound(kind: SeriesKind, g: &WaveGeometry, k: u64) -> Result<Float> {
    let p = MAG_PREC + 32;
    let s = Ball::from_float(&g.s.upper(), p);
    single_term_bound_with(kind, g, k, &term_coeff(kind, &s, k, p)?)
}

/// [`single_term_bound`] with its coefficient [`term_coeff`] given.
fn single_term_bound_with(kind: SeriesKind, g: &WaveGeometry, k: u64, coeff: &Ball) -> Result<Float> {
    let p = MAG_PREC + 32;
    let s = Ball::from_float(&g.s.upper(), p);
    let exp_factor = s.div(&Ball::from_i64(k as i64 + 1, p))?.exp()?;
    let amp = Ball::from_float(&g.amp.abs_upper(), p);
    let b = match kind {
        SeriesKind::Displacement => {
            let ln_y = Ball::from_float(&g.y.lower(), p).ln()?.neg();
            let l = ln_y.add(&Ball::from_f64(PSI_DIFF_MAX, p)?).add(&Ball::from_i64(k as i64 + 2, p).ln()?);
            amp.mul(&s).mul(coeff).mul(&exp_factor).mul(&l)
        }
        SeriesKind::Gradient => {
            let x_lo = Ball::from_float(&g.x.lower(), p);
            amp.mul(&s).mul_pow2(1).div(&x_lo)?.mul(coeff).mul(&exp_factor).mul_i64(2 * (k as i64 + 1))
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
    let k_top = u32::try_from(k_top).map_err(|_| kmax_error(k_top))?;
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
        let term_start = std::time::Instant::now();
        let kk = u32::try_from(k).map_err(|_| kmax_error(k))?;
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
        // the terms past the family's reach cost a Meijer and a 1F2 series each:
        // the call's time budget, every term (one term took 0.2 s at x = 2.8e32010,
        // issue 37's scan; the check costs a clock read), with this term's time as
        // the next one's estimate (at zero, a 60 ms term began at 0.1 s under load)
        crate::budget::check_elapsed("the wave series (Eq. 11b/12) term by term", crate::budget::since(term_start), Reached::Terms { count: k + 1 })?;
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
    // Cost, against the call's time budget, at the planned working precision
    // (the cancellation guard is ~1.44 D bits: 31 000 bits at D = 21 700):
    // * the terms: the loop ends at `kmax` or at its early stop, which needs the
    //   tail ratio below 1/2, `(2k+4)(2k+5) > 2 D^2` (Eq. 12; `(k+2)^2 > 2s` for
    //   Eq. 11b): at least `min(kmax + 1, 0.7 D - 3)` terms of a few ball products
    //   at that precision each (pFq's time per term). Without it, `D = 4.4e6`
    //   (`a/zeta = 7e5`) started a round at 6.4e6 bits (0.2-0.3 s before a check);
    // * Eq. 11b's 2F1 factors near `y = 1` need Gamma values at that precision
    //   (MPFR's first Gamma at 31 000 bits takes about 40 s). Eq. 12 needs none
    //   (its Meijer constants come from closed forms and recurrences).
    let first_wp = prec.saturating_add(guard);
    let min_terms = ((kmax as f64) + 1.0).min((0.7 * d - 3.0).max(1.0));
    let mut seconds = min_terms * crate::special::pfq::seconds_per_term(first_wp);
    if kind == SeriesKind::Gradient {
        seconds = seconds.max(crate::special::gamma::gamma_seconds(first_wp));
    }
    crate::budget::check_estimate("the wave series (its terms, or Gamma values, at the working precision its cancellation needs)", seconds, f64::INFINITY)?;
    let partial = ziv_with_floor(name, prec, guard, Some(&floor), |wp| {
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


#[cfg(test)]
mod tests {
    use super::*;

    fn e(v: f64) -> Float {
        exact(v)
    }

    /// The truncation bound with its coefficient by recurrence equals, within
    /// the balls' rounding, the sum of the single-term bounds each from its
    /// factorial (the way it was summed before), and stops at the call's budget.
    #[test]
    fn truncation_bound_by_recurrence_matches_the_factorials_and_checks_the_budget() {
        for kind in [SeriesKind::Displacement, SeriesKind::Gradient] {
            for (abar, r) in [(3.0, 1.2), (6.0, 2.0), (20.0, 1.5)] {
                let g = wave_geometry(&e(abar), &e(1.125), &e(1.0), &e(abar * r), 128).unwrap();
                for kmax in [0u64, 5, 40] {
                    let fast = truncation_bound(kind, &g, kmax).unwrap();
                    let mut direct = Float::with_val(MAG_PREC, 0);
                    let mut k = kmax + 1;
                    let tail = loop {
                        if let Some(t) = series_tail(kind, &g, k).unwrap() {
                            break t;
                        }
                        direct += single_term_bound(kind, &g, k).unwrap();
                        k += 1;
                    };
                    direct += tail;
                    let rel = (Float::with_val(64, &fast / &direct) - 1u32).abs().to_f64();
                    assert!(rel < 1e-9, "{kind:?} abar = {abar}, x/a = {r}, kmax = {kmax}: {fast} against {direct}");
                }
            }
        }
        // issue 37's scan: u_wave_series(10000, 29.38, 23.4, 2.9e15998, 1) sums about
        // 1500 single-term bounds (s ~ 10^6); under a microsecond it stops at a check
        let x = Float::with_val(64, Float::parse("2.9100642042897952e15998").unwrap());
        let g = wave_geometry(&e(10000.0), &e(29.379548012748188), &e(23.445022485831416), &x, 128).unwrap();
        let r = crate::budget::Budget::from_secs_f64(1e-6).unwrap().run(|| truncation_bound(SeriesKind::Displacement, &g, 1));
        assert!(matches!(r, Err(Error::BudgetSpent { reached: Reached::Terms { .. }, .. })), "{r:?}");
        assert!(truncation_bound(SeriesKind::Displacement, &g, 1).unwrap().is_finite());
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
}
