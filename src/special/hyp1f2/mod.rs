//! The hypergeometric function `1F2(a; b1, b2; z)`, real parameters, real `z`.
//!
//! # Method
//!
//! `1F2` is entire in `z` [DLMF 16.2]. Its series
//! `sum_n (a)_n z^n / ((b1)_n (b2)_n n!)` is summed by the pFq core
//! ([`crate::special::pfq`]) in ball arithmetic, with the core's rigorous tail
//! bound: for `n >= N` the term ratio is at most
//! `|z| max(1, (a^+ + N)/(b^- + N)) / (b'^- + N)` (numerator paired with the larger
//! lower parameter), so the tail is geometric once `N` passes `|z|/b'`.
//!
//! # Cancellation and why the Ziv loop matters
//!
//! For `z < 0` the terms alternate and grow to about
//! `sum |t_n| = 1F2(|a|; b1, b2; |z|) ~ exp(3 |z|^{1/3})` (for `a`, `b` of order
//! one) before they decay, while the value stays of order `|z|^{-a}` or smaller.
//! At the model's `z = -(pi abar / beta)^2 ~ -300`, `b1 = 1`, `b2 = 3/2` this
//! loses about 50 bits; at `z = -10^4` about 93. Arb's `arb_hypgeom_pfq`
//! at 103 bits returns `1F2(1/2; 3/2, 2; -300)` with 42 bits lost and nothing
//! correct at `-3000`, because it does not raise its working precision. Here a
//! cheap f64 pass measures `log2(sum |t_n| / |sum|)` and the Ziv loop adds it as
//! guard bits, raising further until `rad <= 2^-prec |mid|` is certified.
//!
//! # Model case
//!
//! Eq. 12 of the seed paper uses `1F2(1/2; k+1, k+3/2; -(pi a/zeta)^2)` with
//! `k <= 1000`; there the parameters grow with `k` and the cancellation shrinks
//! (`sum |t_n|/|F| ~ e^{2s} s^{-2k-3/2}` at `z = -s^2`), so large `k` is cheap: the
//! f64 series certifies `1e-14` for about `k >= s`, the double-word series
//! (`dd.rs`) from `k >= 7` at `s = 35` (every `k` at `s <= 15`), and the Bessel
//! route in double words (`bessel_f64.rs`) the small `k` at `s >= 17`.
//!
//! # Model family at large `|z|` (`bessel.rs`)
//!
//! `1F2(1/2; k+1, k+3/2; -x^2) = (2k+1) int_0^1 (1-t)^{2k} J_0(2xt) dt`, which
//! reduces to `J_0(2x)`, `J_1(2x)` and the two asymptotic series of the Struve
//! differences `H_0 - Y_0`, `H_1 - Y_1` (DLMF 10.22.2, 11.6.1), whose remainder is
//! bounded by the first omitted term (proof in `bessel.rs`). [`hyp1f2_mp`] takes it
//! for the model family (`a = 1/2`, `{b1, b2} = {k+1, k+3/2}`, `0 <= k <= 10^6`,
//! `4k <= 2x`) when that asymptotic series reaches the working precision
//! (about `2x >= 0.7 wp`): there the series would carry `2.9 x` guard bits
//! (`x = 1000`: 2900) and `e x` terms. `1F2(1/2; 1, 3/2; z)` at 53, 128 and 400
//! bits: 40 us to 2.4 ms for `z` from `-300` to `-10^6` (the series at `-10^4`, 400
//! bits, is the slowest), where the series was refused from `z = -5 10^4` at 128
//! bits.
//!
//! # Large parameters
//!
//! With `a`, `b1`, `b2` of a few hundred and either sign the terms fall below
//! `2^-1022` before the series may stop (it must pass `-a`), so the bound of the
//! exact-parameter series (`pfq.rs`) sums subnormal f64 magnitudes; that bound is
//! proven for them (issue 23: a bug there made the bound useless and the Ziv loop
//! climbed to 1200 bits, 3.5 s a call). On the issue-23 grid (`a`, `b1`, `b2`, `z`
//! in `[-500, 500]`, 64 points, `benches/common/hyp1f2_large_grid.rs`) every point
//! now takes under 0.2 ms at 128 bits.
//!
//! # Accuracy
//!
//! * MP: certified, `rad <= 2^-prec |mid|`.
//! * f64: the f64 series is returned when its error estimate is below
//!   [`F64_TRUST`](crate::special::pfq::F64_TRUST) relative (no significant
//!   cancellation); otherwise the certified 64-bit value, rounded. Tolerance
//!   `1e-14` relative.
//!
//! * Ball inputs ([`hyp1f2_ball_mp`]): the same series in ball arithmetic over
//!   the input balls, tail bounded over the balls; a pole inside a `b` ball is
//!   a typed error.
//!
//! Domain: finite real parameters with `b1, b2` not non-positive integers
//! (unless the series terminates first), finite real `z`; tested: `|z| <= 10^4`
//! (golden table), parameters and `z` in `[-500, 500]` (the issue-23 grid, against
//! Arb), and the model family down to `z = -10^6`.

mod bessel;
mod bessel_f64;
mod dd;
mod family;

pub use family::{hyp1f2_model_family_f64, FAMILY_MAX_K};

use rug::Float;

use crate::ball::{Ball, Bounded};
use crate::error::Result;
use crate::special::exact;
use crate::special::pfq::{hyp_pfq, hyp_pfq_mp};

/// The seed's family `1F2(1/2; k+1, k+3/2; -s)` (Eq. 11b, 12, C.39) at working
/// precision `wp`, for `s >= 0` given as a ball.
///
/// It is `Phi(2k+1)` of `model_phi_series`: the term ratio is the rational
/// `-s (2n+1)/((k+1+n)(2k+3+2n)(n+1))`, so each term costs one ball
/// multiplication and two exact-integer scalings instead of the generic core's
/// parameter arithmetic. **Tail bound**: the ratio's modulus decreases in `n`,
/// so once its value `rho_N < 1`, `sum_{n>=N} |t_n| <= |t_N|/(1 - rho_N)`.
/// Compared with the generic pFq core in the tests.
pub fn hyp1f2_model_ball(k: u32, s: &Ball, wp: u32) -> Result<Ball> {
    crate::error::check_working_prec(wp)?;
    // F_k = Phi(2k + 1): the same series, with the same ratio and tail bound.
    model_phi_series(2 * u64::from(k) + 1, s, wp)
}

/// Bits of relative accuracy the downward recurrence of [`hyp1f2_model_family`]
/// may lose before the per-k series takes over (the Eq. 12 sum's guard bits cover it).
pub const FAMILY_RECURRENCE_MAX_LOSS: u32 = 16;

/// Extra working bits of [`hyp1f2_model_family`]'s recurrence per unit of
/// `D = 2 sqrt(s)`: the radius growth measured down to `k = 0` at `D = 33.5`
/// was about 110 bits.
const FAMILY_EXTRA_BITS_PER_D: f64 = 3.3;

/// `Phi(m) = 1F2(1/2; (m+1)/2, (m+2)/2; -s) = sum_n C(2n, n) (-s)^n m!/(m+2n)!`
/// for an integer `m >= 0` (the model family is `F_k = Phi(2k+1)`), summed
/// directly in balls. Term ratio `-s 2(2n+1)/((n+1)(m+2n+1)(m+2n+2))`, whose
/// modulus decreases in `n`: the tail is geometric as in [`hyp1f2_model_ball`].
fn model_phi_series(m: u64, s: &Ball, wp: u32) -> Result<Ball> {
    use crate::ball::Mag;
    use crate::error::Error;
    let neg_s = s.neg();
    let s_up = s.abs_upper_mag();
    let mm = i64::try_from(m).map_err(|_| Error::IntegerOutOfRange { arg: "k", value: i64::MAX, min: 0, max: i64::MAX })?;
    let mut t = Ball::one(wp);
    let mut sum = Ball::one(wp);
    let mut n: i64 = 0;
    loop {
        let den = (n + 1)
            .checked_mul(mm + 2 * n + 1)
            .and_then(|v| v.checked_mul(mm + 2 * n + 2))
            .ok_or_else(|| Error::IntegerOutOfRange { arg: "k", value: mm, min: 0, max: i64::MAX / 2 })?;
        t = t.mul(&neg_s).mul_i64(2 * (2 * n + 1)).div_i64(den)?;
        n += 1;
        let t_up = t.abs_upper_mag();
        let next_den = (n + 1) as f64 * (mm + 2 * n + 1) as f64 * (mm + 2 * n + 2) as f64;
        let rho = s_up.mul(Mag::from_f64((2 * (2 * n + 1)) as f64)).div(Mag::from_f64(next_den.next_down()));
        let one_minus = Mag::from_f64(1.0).sub_lower(rho);
        if !one_minus.is_zero() {
            let tail = t_up.div(one_minus);
            if tail.le(&sum.abs_lower_mag().mul_2exp(-(wp as i64) - 2)) {
                sum.add_error_mag(tail);
                return Ok(sum);
            }
        }
        sum = sum.add(&t);
        if n > 100_000_000 {
            return Err(Error::NoConvergence { function: "1F2 model family", terms: n as u64 });
        }
        if n as u64 % crate::budget::TERMS_BETWEEN_CHECKS == 0 {
            // the installed time budget (crate::budget): at large s the terms grow
            // until n ~ sqrt(s) at a precision covering their cancellation (the wave
            // series at x = 2.8e32010 spent 17 s in its first family, issue 37's scan)
            crate::budget::check_elapsed("1F2 model family series, term by term", 0.0, crate::error::Reached::Terms { count: n as u64 })?;
        }
    }
}

/// The whole model family `F_k = 1F2(1/2; k+1, k+3/2; -s)`, `k = 0..=kmax`, in balls
/// at working precision `wp` (`s >= 0`), for sums over `k` such as Eq. 11b and Eq. 12.
///
/// **Recurrence.** With `Phi(m)` as in `model_phi_series` (so `F_k = Phi(2k+1)`),
/// `m!/(m+2n)! - (m+1)!/(m+2n+1)! = 2n m!/(m+2n+1)!`, the coefficient identity
/// `2n C(2n,n) (-s)^n = -4 s (2n-1) C(2n-2,n-1) (-s)^{n-1}` and
/// `2n+1 = (m+2n+3) - (m+2)` give the four-term relation
///
/// ```text
/// Phi(m) = Phi(m+1) - (4 s/(m+1)) [Phi(m+2)/(m+2) - Phi(m+3)/(m+3)].
/// ```
///
/// It is run downward from four series values at the top (short series: the
/// term ratio there is about `4 s/m^2`). Downward it is stable while `m` is
/// large against `D = 2 sqrt(s)`; below that the other solutions grow. It runs
/// with `3.3 D + 16` extra bits. Every
/// step is a ball operation, so the radius shows the growth: the recurrence
/// stops as soon as a value has lost more than [`FAMILY_RECURRENCE_MAX_LOSS`]
/// bits, and the remaining
/// small `k` are summed one by one ([`hyp1f2_model_ball`]). All results are
/// enclosures whichever route produced them.
pub fn hyp1f2_model_family(kmax: u32, s: &Ball, wp: u32) -> Result<Vec<Ball>> {
    crate::error::check_working_prec(wp)?;
    let top = 2 * kmax as u64 + 1;
    let mut phi: Vec<Option<Ball>> = vec![None; top as usize + 4];
    // The ball radius of the recurrence grows by up to ~3.3 D bits on the way down
    // to m = 0 (measured: ~110 bits at D = 33.5); carry that much more precision.
    let d = 2.0 * s.upper().to_f64().max(0.0).sqrt();
    let hp = wp + (FAMILY_EXTRA_BITS_PER_D * d).ceil().min(4096.0) as u32 + 16;
    let s_hp = s.set_prec(hp);
    for m in top..top + 4 {
        phi[m as usize] = Some(model_phi_series(m, &s_hp, hp)?);
    }
    // Switch to the per-k series once a value keeps fewer than `keep` bits.
    let keep = wp.saturating_sub(FAMILY_RECURRENCE_MAX_LOSS) as f64;
    let four_s = s_hp.mul_pow2(2);
    let mut m = top;
    while m > 0 {
        m -= 1;
        let mi = m as i64;
        let (p1, p2, p3) = match (&phi[m as usize + 1], &phi[m as usize + 2], &phi[m as usize + 3]) {
            (Some(a), Some(b), Some(c)) => (a, b, c),
            _ => break,
        };
        let bracket = p2.div_i64(mi + 2)?.sub(&p3.div_i64(mi + 3)?);
        let v = p1.sub(&four_s.mul(&bracket).div_i64(mi + 1)?);
        if !(v.rel_accuracy_bits() >= keep) {
            break;
        }
        phi[m as usize] = Some(v);
    }
    (0..=kmax)
        .map(|k| match phi[2 * k as usize + 1].take() {
            Some(v) => Ok(v.set_prec(wp)),
            None => hyp1f2_model_ball(k, s, wp),
        })
        .collect()
}

/// Certified `1F2(a; b1, b2; z)` with `rad <= 2^-prec |mid|`.
///
/// The model family `1F2(1/2; k+1, k+3/2; z)` (either order of the `b`) at
/// large negative `z` goes through `J_0`, `J_1` and the Struve asymptotics
/// (`bessel.rs`) where that series reaches the working precision; everything
/// else sums the series (`pfq`).
pub fn hyp1f2_mp(a: &Float, b1: &Float, b2: &Float, z: &Float, prec: u32) -> Result<Ball> {
    if let Some(k) = model_family_index(a, b1, b2) {
        crate::error::check_prec(prec)?;
        crate::special::check_finite(z, "hypergeometric argument")?;
        let y = 2.0 * (-z.to_f64()).sqrt();
        let guard = crate::special::DEFAULT_GUARD_BITS + 2 * k as u32 + y.log2().max(0.0) as u32;
        if *z < 0 && bessel::applies(k, y, prec + guard) {
            let mut declined = false;
            // any failure of the route (it declines at a raised precision, or a
            // Bessel value is refused) hands the point to the series
            let b = crate::special::ziv("hyp1f2", prec, guard, |wp| match bessel::model_family_bessel(k, z, wp) {
                Ok(Some(b)) => Ok(b),
                other => {
                    declined = true;
                    other.and(Err(crate::error::Error::PrecisionExhausted { function: "hyp1f2 (Bessel route)", working_prec: wp }))
                }
            });
            if !declined {
                return b;
            }
        }
    }
    hyp_pfq_mp(std::slice::from_ref(a), &[b1.clone(), b2.clone()], z, prec)
}

/// `x^2` above which the f64 Bessel route is tried for the model family (`y = 2x >= 34`:
/// below, the smallest term of its asymptotic series is above `1e-14`).
const BESSEL_F64_MIN_X2: f64 = 289.0;

/// [`model_family_index`] for f64 parameters.
fn model_family_index_f64(a: f64, b1: f64, b2: f64) -> Option<u32> {
    let (lo, hi) = if b1 < b2 { (b1, b2) } else { (b2, b1) };
    let k = lo - 1.0;
    (a == 0.5 && (0.0..=1e6).contains(&k) && k == k.floor() && hi - k == 1.5).then_some(k as u32)
}

/// `Some(k)` when `(a; b1, b2) = (1/2; k+1, k+3/2)` (either order) with an integer
/// `0 <= k <= 10^6`: the seed's model family.
fn model_family_index(a: &Float, b1: &Float, b2: &Float) -> Option<u64> {
    if *a != 0.5 {
        return None;
    }
    let (lo, hi) = if b1 < b2 { (b1, b2) } else { (b2, b1) };
    let k = crate::special::exact_sub(lo, &Float::with_val(2, 1));
    let ok = k.is_integer() && k >= 0 && k <= 1e6 && crate::special::exact_sub(hi, &k) == 1.5;
    ok.then(|| k.to_f64() as u64)
}

/// Certified `1F2(a; b1, b2; z)` over balls of inputs (Arb's convention): the
/// result contains the function at every point of the balls, and a pole
/// (`b1` or `b2` a non-positive integer inside its ball) is a typed error.
/// The series runs in ball arithmetic with a tail bound valid over the whole
/// balls ([`crate::special::pfq::hyp_pfq_ball_mp`] has the argument). Exact
/// inputs give [`hyp1f2_mp`]'s answer.
pub fn hyp1f2_ball_mp(a: &Ball, b1: &Ball, b2: &Ball, z: &Ball, prec: u32) -> Result<Ball> {
    if [a, b1, b2, z].iter().all(|x| x.is_exact() && x.is_finite()) {
        return hyp1f2_mp(a.mid(), b1.mid(), b2.mid(), z.mid(), prec);
    }
    crate::special::pfq::hyp_pfq_ball_mp(std::slice::from_ref(a), &[b1.clone(), b2.clone()], z, prec)
}

/// Largest relative bound the native f64 series may return (beyond it: MP).
pub const NATIVE_REL_TOL: f64 = 1e-14;

/// Cap on the terms of the native f64 series.
const NATIVE_MAX_TERMS: u64 = 20_000;


/// How many [`hyp1f2_bounded`] / [`hyp1f2`] calls fell back to MP since the process started.
#[deprecated(note = "use `maugis::special::fallback_counts().hyp1f2`: one snapshot of every counter")]
pub fn hyp1f2_fallbacks() -> u64 {
    crate::special::fallback_counts().hyp1f2
}

/// The series of `1F2(a; b1, b2; z)` summed in f64 with a running error analysis:
/// `Some((value, err))` with `|1F2 - value| <= err` (proven), `None` where it
/// cannot be applied (`b1, b2 <= 0`, no convergence within the cap, overflow).
///
/// **Argument.** With `u = 2^-53`, the computed term ratio
/// `fl(z (a+n) / ((n+1)(b1+n)(b2+n)))` has at most 6 roundings (three shifted
/// parameters, two products, one quotient) and the update `t <- t r` one more, so
/// the computed `t~_n = t_n (1 + theta_n)`, `|theta_n| <= gamma_{7n}`
/// [Higham, *Accuracy and Stability*, Lemma 3.1]. Each addition `s <- s + t~` adds
/// at most `u |s_new|`. Hence `|sum_{n<N} t_n - s~| <= sum gamma_{7n} |t~_n|/(1-gamma_{7n}) + u sum |s~_k|`.
/// **Tail**: once `a+N, b1+N, b2+N > 0`, `|t_{n+1}/t_n| <= rho_N = |z| max(1, (a+N)/(b1+N)) / ((b2+N)(N+1))`
/// for all `n >= N` (each factor is monotone in `n`), so `sum_{n>=N} |t_n| <= |t_N|/(1 - rho_N)`
/// when `rho_N < 1`. The bound is evaluated in f64 and inflated by `1 + 2^-30`
/// for its own roundings (fewer than `2^20` operations).
pub(crate) fn native_series_bounded(a: f64, b1: f64, b2: f64, z: f64) -> Option<Bounded> {
    if !(b1 > 0.0 && b2 > 0.0 && a.is_finite() && z.is_finite()) {
        return None;
    }
    let u = f64::EPSILON / 2.0;
    // first index with a + n > 0 (the tail bound needs it), unless the series terminates
    let n_pos = if a > 0.0 { 0.0 } else { (-a).floor() + 1.0 };
    let mut t = 1.0f64;
    let mut s = 1.0f64;
    let mut err = 0.0f64; // accumulated rounding bound
    let mut n: u64 = 0;
    loop {
        let nf = n as f64;
        let r = z * (a + nf) / ((nf + 1.0) * (b1 + nf) * (b2 + nf));
        t *= r;
        n += 1;
        let g = 7.0 * n as f64 * u;
        if !(g < 0.5) || !t.is_finite() || n > NATIVE_MAX_TERMS {
            return None;
        }
        let gamma = g / (1.0 - g);
        if t == 0.0 {
            if !(a <= 0.0 && a == a.floor() && nf + 1.0 > -a) {
                return None; // underflow, not termination
            }
            // terminating series (a a non-positive integer): exact beyond this term
            let b = Bounded { value: s, err: (err * (1.0 + 1.0 / (1u64 << 30) as f64)).next_up() };
            return Some(b);
        }
        let nf = n as f64;
        if nf >= n_pos {
            let rho = z.abs() * ((a + nf) / (b1 + nf)).max(1.0) / ((b2 + nf) * (nf + 1.0)) * (1.0 + 8.0 * u);
            if rho < 0.5 {
                let t_up = t.abs() * (1.0 + gamma) / (1.0 - gamma);
                let tail = t_up / (1.0 - rho);
                if tail <= 1e-3 * u * s.abs() {
                    let total = (err + tail) * (1.0 + 1.0 / (1u64 << 30) as f64);
                    return Some(Bounded { value: s, err: total.next_up() });
                }
            }
        }
        s += t;
        err += gamma / (1.0 - gamma) * t.abs() + u * s.abs();
    }
}

/// `1F2(a; b1, b2; z)` in f64, within `1e-14` relative: the native series where its
/// proven bound is at most [`NATIVE_REL_TOL`] relative, else the pFq path.
pub fn hyp1f2(a: f64, b1: f64, b2: f64, z: f64) -> Result<f64> {
    if let Some(b) = hyp1f2_native_or_dd(a, b1, b2, z, NATIVE_REL_TOL) {
        return Ok(b.value);
    }
    hyp_pfq(&[a], &[b1, b2], z)
}

/// `L`, about `ln(sum_n |t_n| / |F_k(-x^2)|)` for the model family's series at
/// `z = -x^2` (`sum |t_n| = 1F2(1/2; k+1, k+3/2; x^2) ~ Gamma(k+1) Gamma(k+3/2)
/// e^{2x}/(2 sqrt(pi) x^{2k+3/2})` [DLMF 16.11.7], `F_k ~ (2k+1)/(2x)`), with
/// Stirling's `ln Gamma(k+1) + ln Gamma(k+3/2) ~ 2 ((k+1) ln(k+1) - (k+1)) + ln(2 pi)`.
/// It only chooses a route (a wrong guess costs time, never a bound).
fn family_cancellation_ln(k: u32, x: f64) -> f64 {
    let k1 = k as f64 + 1.0;
    2.0 * x - (2.0 * k1 - 0.5) * x.ln() + 2.0 * (k1 * k1.ln() - k1) + 1.84 + (x / (k1 - 0.5)).ln() - 1.27
}

/// The f64 series, else the double-double series (`dd.rs`), if
/// either bound is at most [`NATIVE_REL_TOL`] relative.
fn hyp1f2_native_or_dd(a: f64, b1: f64, b2: f64, z: f64, rel_tol: f64) -> Option<Bounded> {
    let accept = |b: Bounded| (b.value.is_finite() && b.err <= rel_tol * b.value.abs()).then_some(b);
    // the model family where its series cancel (k <= x/2 at z = -x^2): the Bessel
    // route; below its range, the f64 series only where it can certify (about
    // k >= x - 2: the cancellation is e^{2x} x^{-2k-3/2}), else straight to double words
    let family = model_family_index_f64(a, b1, b2);
    if let (Some(k), true) = (family, z < 0.0) {
        let x = (-z).sqrt();
        // the double-word series first where its bound (about 25 u^2 N e^L of the
        // value, N ~ 100 terms) stays near 1e-15: it is the cheaper route there
        if (k as f64) < x - 2.0 && family_cancellation_ln(k, x) <= 31.0 {
            if let Some(b) = dd::family_series_dd(k, z).and_then(|v| v.finish()).and_then(accept) {
                return Some(b);
            }
        }
        if (4 * k as u64) as f64 <= 2.0 * x && z < -BESSEL_F64_MIN_X2 {
            if let Some(b) = bessel_f64::model_family_bessel_f64(k, z).and_then(accept) {
                return Some(b);
            }
        }
        if (k as f64) < x - 2.0 {
            return dd::family_series_dd(k, z)?.finish().and_then(accept);
        }
    }
    native_series_bounded(a, b1, b2, z)
        .and_then(accept)
        .or_else(|| dd::hyp1f2_series_dd(a, b1, b2, z)?.finish().and_then(accept))
}

/// The native f64 paths of [`hyp1f2_bounded`] alone (the Bessel route, the f64
/// series, double-double; no MP): `Some` with a proven bound where it certifies
/// `err <= rel_tol |value|`, `None` where [`hyp1f2_bounded`] would fall back to
/// MP (for solvers that count or avoid the slow path), and for parameters at a
/// pole, which [`hyp1f2_bounded`] reports as a typed error. Errors:
/// [`crate::Error::NonFinite`] for an argument, [`crate::Error::OutOfRange`] for a `rel_tol`
/// that is not positive and finite.
pub fn hyp1f2_native_bounded(a: f64, b1: f64, b2: f64, z: f64, rel_tol: f64) -> Result<Option<Bounded>> {
    for (v, what) in [(a, "a"), (b1, "b1"), (b2, "b2"), (z, "z")] {
        crate::error::finite(v, what)?;
    }
    crate::special::check_rel_tol(rel_tol)?;
    Ok(hyp1f2_native_or_dd(a, b1, b2, z, rel_tol))
}

/// `1F2(a; b1, b2; z)` in f64 with a proven error bound for the f64 inputs as given:
/// for the model family `1F2(1/2; k+1, k+3/2; -s^2)` at `k < s - 2` where the
/// series' cancellation allows it, the double-word series with an a-priori bound
/// (`dd.rs`, `family_series_dd`); then at `s >= 17`, `k <= s/2`, the
/// Bessel route in double words (`bessel_f64.rs`); else the native series
/// (`native_series_bounded`) when its bound is at most [`NATIVE_REL_TOL`]
/// relative (skipped for the family at `k < s - 2`, where it cannot be), else
/// the same series in double-double (cancellation: large negative `z` against the
/// parameters); otherwise the certified MP value at 64 bits, counted by
/// [`crate::special::fallback_counts`] (none over the family at `k <= 1000`, `s <= 35`:
/// `reference/bench_f64_targets.py`: at most 0.89 us at any of the 512 points of
/// issue 23's table, `k` in {0, 1, 2, 5, 10, 50, 200, 1000}, CPU time at load 6.5;
/// it was 28 us per value on average with MP fallbacks).
pub fn hyp1f2_bounded(a: f64, b1: f64, b2: f64, z: f64) -> Result<Bounded> {
    for (v, what) in [(a, "a"), (b1, "b1"), (b2, "b2"), (z, "z")] {
        crate::error::finite(v, what)?;
    }
    if let Some(b) = hyp1f2_native_or_dd(a, b1, b2, z, NATIVE_REL_TOL) {
        return Ok(b);
    }
    crate::special::fallback::count(crate::special::F64Route::Hyp1f2);
    crate::special::bounded_from_ball("hyp1f2", &hyp1f2_mp_f64(a, b1, b2, z, crate::special::F64_FALLBACK_PREC)?)
}

/// Certified `1F2` at f64 arguments (convenience wrapper).
pub fn hyp1f2_mp_f64(a: f64, b1: f64, b2: f64, z: f64, prec: u32) -> Result<Ball> {
    crate::error::finite(a, "a")?;
    crate::error::finite(b1, "b1")?;
    crate::error::finite(b2, "b2")?;
    crate::error::finite(z, "z")?;
    hyp1f2_mp(&exact(a), &exact(b1), &exact(b2), &exact(z), prec)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::special::bessel_j::bessel_j_mp;
    use crate::error::Error;

    #[test]
    fn reduces_to_bessel_squared() {
        // 1F2(1/2; 1, 1; -x^2) = J_0(x)^2 [DLMF 10.8.3 with nu = mu = 0]
        for &x in &[0.5, 3.0, 17.25] {
            let f = hyp1f2_mp_f64(0.5, 1.0, 1.0, -x * x, 150).unwrap();
            let j = bessel_j_mp(0, &exact(x), 150).unwrap();
            assert!(f.overlaps(&j.sqr()), "x={x}");
        }
    }

    #[test]
    fn model_case_certified_at_minus_300() {
        // Issue acceptance: certified to full precision for every k = 0..=1000.
        for k in 0u32..=1000 {
            let kf = k as f64;
            let b = hyp1f2_mp_f64(0.5, kf + 1.0, kf + 1.5, -300.0, 128).unwrap();
            assert!(b.meets_rel(128), "k={k}");
        }
    }

    #[test]
    fn f64_close_to_mp() {
        for &(a, b1, b2, z) in &[(0.5, 1.0, 1.5, -300.0), (0.5, 11.0, 11.5, -300.0), (1.25, 2.5, 3.75, 40.0)] {
            let v = hyp1f2(a, b1, b2, z).unwrap();
            let m = hyp1f2_mp_f64(a, b1, b2, z, 80).unwrap().to_f64();
            assert!((v - m).abs() <= 1e-14 * m.abs(), "{a} {b1} {b2} {z}: {v} vs {m}");
        }
    }

    #[test]
    fn model_family_routine_matches_the_pfq_core() {
        use crate::special::pfq::pfq_series;
        let wp = 200;
        for &s in &[0.0, 0.75, 30.0, 280.5, 2000.0] {
            for k in [0u32, 1, 7, 60, 999] {
                let sb = Ball::from_f64(s, wp).unwrap();
                let fast = hyp1f2_model_ball(k, &sb, wp).unwrap();
                let kb = Ball::from_i64(k as i64, wp);
                let half = Ball::from_ratio(1, 2, wp);
                let generic = pfq_series(&[half.clone()], &[kb.add_i64(1), kb.add(&half).add_i64(1)], &sb.neg(), wp).unwrap().sum;
                assert!(fast.overlaps(&generic), "k={k} s={s}: {fast:?} vs {generic:?}");
            }
        }
    }

    #[test]
    fn family_recurrence_matches_the_per_k_series() {
        let wp = 200;
        for &s in &[0.0, 0.75, 30.0, 280.5, 1225.0] {
            let sb = Ball::from_f64(s, wp).unwrap();
            let fam = hyp1f2_model_family(300, &sb, wp).unwrap();
            for k in [0u32, 1, 2, 7, 17, 18, 60, 299, 300] {
                let one = hyp1f2_model_ball(k, &sb, wp).unwrap();
                assert!(fam[k as usize].overlaps(&one), "k={k} s={s}: {:?} vs {one:?}", fam[k as usize]);
                // (small k at large s come from the per-k series, which loses its own cancellation)
                if k as f64 > 2.0 * s.sqrt() {
                    assert!(fam[k as usize].meets_rel(wp - FAMILY_RECURRENCE_MAX_LOSS - 4), "k={k} s={s}: {:?}", fam[k as usize]);
                }
            }
        }
    }

    #[test]
    fn native_bound_holds_and_is_tight_where_accepted() {
        let mut accepted = 0;
        for &(a, b1, b2, z) in &[
            (0.5, 1.0, 1.5, -3.0),
            (0.5, 11.0, 11.5, -300.0),
            (0.5, 101.0, 101.5, -1225.0),
            (0.5, 1001.0, 1001.5, -1225.0),
            (1.25, 2.5, 3.75, 40.0),
            (-3.0, 2.5, 0.75, 7.5),
            (0.5, 1.0, 1.5, -1e-9),
            (2.0, 0.25, 0.125, -0.5),
        ] {
            let exact = hyp1f2_mp_f64(a, b1, b2, z, 200).unwrap();
            if let Some(b) = native_series_bounded(a, b1, b2, z) {
                let diff = Float::with_val(264, exact.mid() - b.value).abs();
                assert!(diff <= b.err, "{a} {b1} {b2} {z}: {b} vs {exact:?}");
                if b.err <= NATIVE_REL_TOL * b.value.abs() {
                    accepted += 1;
                }
            }
            let fb = hyp1f2_bounded(a, b1, b2, z).unwrap();
            let diff = Float::with_val(264, exact.mid() - fb.value).abs();
            assert!(diff <= fb.err && fb.err <= 1e-14 * fb.value.abs(), "{a} {b1} {b2} {z}: {fb}");
        }
        assert!(accepted >= 6, "{accepted}");
    }

    #[test]
    fn huge_parameter_series_is_refused_at_once_or_answers() {
        // Fuzz finding (docs/fuzzing.md): a = 3.7e18 makes the terms grow until
        // n^3 ~ a z, n ~ 4.4e6, so the series (the only method here) needs millions
        // of terms: 5.4 s at 98 bits. It is refused before summing, with the estimate.
        let e = |v: f64| Float::with_val(53, v);
        match hyp1f2_mp(&e(3.7e18), &e(20.03), &e(-179.875), &e(23.7), 98) {
            Err(Error::TooExpensive { seconds, limit_seconds, .. }) => {
                assert!(seconds > limit_seconds && limit_seconds == crate::special::pfq::MAX_SERIES_SECONDS, "{seconds}")
            }
            other => panic!("expected TooExpensive, got {other:?}"),
        }
        let ball = |v: f64| Ball::from_f64(v, 53).unwrap();
        let refused = hyp1f2_ball_mp(&ball(3.7e18), &ball(20.03), &ball(-179.875), &Ball::from_decimal("23.7", 98).unwrap(), 98);
        assert!(matches!(refused, Err(Error::TooExpensive { .. })), "{refused:?}");
        // a = 1e12: about 3e4 terms, within the budget; the exact-parameter series
        // and the ball series (a separate loop) agree.
        let v = hyp1f2_mp(&e(1e12), &e(20.03), &e(-179.875), &e(23.7), 98).unwrap();
        assert!(v.meets_rel(98), "{v:?}");
        let w = crate::special::pfq::pfq_series(&[ball(1e12).set_prec(160)], &[ball(20.03).set_prec(160), ball(-179.875).set_prec(160)], &ball(23.7).set_prec(160), 160).unwrap().sum;
        assert!(v.overlaps(&w), "{v:?} vs {w:?}");
    }

    #[test]
    fn bad_input() {
        assert!(hyp1f2(0.5, -1.0, 2.0, 1.0).is_err());
        assert!(hyp1f2(0.5, 1.0, 2.0, f64::INFINITY).is_err());
    }
}
