//! Sequences `J_0(x), ..., J_nmax(x)` by the three-term recurrence [DLMF 10.6.1]:
//! certified (balls, downward from two certified values) and double-double
//! (Miller's algorithm, an estimate).

use rug::Float;

use super::bessel_j_ball;
use crate::ball::{Ball, Dd};
use crate::error::{Error, Result};
use crate::special::check_finite;

/// Certified `J_0(x), ..., J_nmax(x)` at working precision `wp` (`x > 0`).
///
/// `J_nmax` and `J_{nmax+1}` are certified by [`bessel_j_mp`](super::bessel_j_mp); the rest follows
/// from the three-term recurrence run downward, `J_{n-1} = (2n/x) J_n - J_{n+1}`
/// [DLMF 10.6.1], in ball arithmetic, so every entry is certified. Downward is the
/// stable direction for `n > x` (J_n is the minimal solution there); below `x`
/// the values do not grow, but the radii do: each step adds the radii of
/// `(2n/x) J_n` and `J_{n+1}`, the growth of `|y_{n-1}| = (2n/x)|y_n| + |y_{n+1}|`,
/// about `0.68 x` bits down to `J_0` (measured in `examples/corners_23b seqrad`).
/// For large `x`, [`super::bessel_j_sequence_three_term`] keeps the radii near
/// `2^-wp x^2` at the same working precision.
pub fn bessel_j_sequence_mp(nmax: u64, x: &Float, wp: u32) -> Result<Vec<Ball>> {
    crate::error::check_working_prec(wp)?;
    check_finite(x, "x")?;
    if *x <= 0 {
        return Err(Error::OutOfRange { arg: "x", value: x.to_f64(), allowed: crate::error::Interval::above(0.0) });
    }
    let top = i64::try_from(nmax).map_err(|_| Error::IntegerOutOfRange { arg: "nmax", value: i64::MAX, min: 0, max: i64::MAX })?;
    let upper = bessel_j_ball(top + 1, x, wp)?;
    let lower = bessel_j_ball(top, x, wp)?;
    let xb = Ball::from_float(x, wp);
    let mut seq = vec![Ball::zero(wp); nmax as usize + 1];
    seq[nmax as usize] = lower.clone();
    let mut next = upper;
    let mut cur = lower;
    for n in (1..=nmax).rev() {
        let prev = cur.mul_i64(2 * n as i64).div(&xb)?.sub(&next);
        seq[n as usize - 1] = prev.clone();
        next = cur;
        cur = prev;
    }
    Ok(seq)
}

/// `J_0(x), ..., J_nmax(x)` by Miller's backward recurrence in double-double,
/// normalised with `J_0 + 2 sum_k J_{2k} = 1` [DLMF 10.12.4 at theta = 0].
///
/// The recurrence starts at an even order `M > max(nmax, |x|)` far enough above
/// `|x|` that the neglected dominant solution is negligible at double-double
/// accuracy (see `miller_start`). Absolute error about `1e-30` times
/// `max_n |J_n(x)| <= 1` (an estimate, not a bound; the golden and cross-check
/// tests measure it). Returns an empty vector for non-finite `x`, and outside the
/// range served: `nmax` above [`MAX_SEQUENCE_ORDER`] or `|x|` above
/// [`MAX_SEQUENCE_ARGUMENT`] (the recurrence would run over more than `2^24` orders;
/// [`bessel_j_sequence_mp`] and [`super::bessel_j_mp`] take such orders and arguments).
pub fn bessel_j_sequence_dd(nmax: usize, x: Dd) -> Vec<Dd> {
    if !x.hi.is_finite() || nmax > MAX_SEQUENCE_ORDER || x.hi.abs() > MAX_SEQUENCE_ARGUMENT {
        return Vec::new();
    }
    let mut out = vec![Dd::ZERO; nmax + 1];
    if x.hi == 0.0 {
        out[0] = Dd::ONE;
        return out;
    }
    if x.hi.abs() < TINY_SEQUENCE_ARGUMENT {
        return bessel_j_sequence_tiny(nmax, x);
    }
    let ax = x.abs();
    let inv_x = ax.recip();
    let m = miller_start(nmax, ax.hi);
    let tiny = 2f64.powi(-900);
    let rescale = 2f64.powi(-800);
    let mut j_next = Dd::ZERO; // J_{m+1}
    let mut j_cur = Dd::from_f64(tiny); // J_m (arbitrary scale)
    let mut norm = j_cur.mul_f64(2.0); // m is even
    if m <= nmax {
        out[m] = j_cur;
    }
    for n in (1..=m).rev() {
        let j_prev = (j_cur * inv_x).mul_f64(2.0 * n as f64) - j_next;
        j_next = j_cur;
        j_cur = j_prev;
        let k = n - 1;
        if k <= nmax {
            out[k] = j_cur;
        }
        if k % 2 == 0 {
            norm = norm + if k == 0 { j_cur } else { j_cur.mul_f64(2.0) };
        }
        if j_cur.hi.abs() > 1e200 {
            j_cur = j_cur.mul_f64(rescale);
            j_next = j_next.mul_f64(rescale);
            norm = norm.mul_f64(rescale);
            for v in out.iter_mut().skip(k) {
                *v = v.mul_f64(rescale);
            }
        }
    }
    let inv_norm = norm.recip();
    for (n, v) in out.iter_mut().enumerate() {
        let scaled = *v * inv_norm;
        *v = if x.hi < 0.0 && n % 2 == 1 { -scaled } else { scaled };
    }
    out
}

/// Below this `|x|` [`bessel_j_sequence_dd`] sums three terms of the power series
/// ([`bessel_j_sequence_tiny`]): there Miller's recurrence grows by `2n/|x|` a step,
/// past the f64 range within one step at `|x| = 1e-100` (NaN values), `1/|x|` itself
/// overflows at subnormal `x`, and its `J_0`, with an absolute error near `1e-30`,
/// leaves no digit of `1 - J_0 ~ x^2/4` (the wave displacement's first term) below
/// `|x| = 1e-15`.
const TINY_SEQUENCE_ARGUMENT: f64 = 1e-8;

/// `J_n(x) = (x/2)^n/n! (1 - h/(n+1) + h^2/(2 (n+1)(n+2)) - r)`, `h = (x/2)^2`
/// [DLMF 10.2.2], for `|x| < 1e-8`: the series alternates with falling terms, so
/// `0 <= r <= h^3/(6 (n+1)(n+2)(n+3)) < 2^-166`, under double-double's rounding.
/// Orders whose `(x/2)^n/n!` underflows are 0.
fn bessel_j_sequence_tiny(nmax: usize, x: Dd) -> Vec<Dd> {
    let half = x.mul_f64(0.5);
    let h = half * half;
    let mut out = vec![Dd::ZERO; nmax + 1];
    let mut lead = Dd::ONE; // (x/2)^n/n!
    for (n, v) in out.iter_mut().enumerate() {
        if n > 0 {
            lead = lead * half / Dd::from_f64(n as f64);
        }
        if lead.hi == 0.0 {
            break;
        }
        let (n1, n2) = (Dd::from_f64((n + 1) as f64), Dd::from_f64((n + 2) as f64));
        let second = h / n1;
        let third = second * h / n2.mul_f64(2.0);
        *v = lead - lead * (second - third);
    }
    out
}

/// Largest `nmax` of [`bessel_j_sequence_dd`] and [`bessel_j_sequence`].
pub const MAX_SEQUENCE_ORDER: usize = 1 << 24;
/// Largest `|x|` of [`bessel_j_sequence_dd`] and [`bessel_j_sequence`].
pub const MAX_SEQUENCE_ARGUMENT: f64 = (1u64 << 24) as f64;

/// `J_0(x), ..., J_nmax(x)` in f64 (the double-double sequence, rounded; empty where
/// [`bessel_j_sequence_dd`] is).
pub fn bessel_j_sequence(nmax: usize, x: f64) -> Vec<f64> {
    bessel_j_sequence_dd(nmax, Dd::from_f64(x)).into_iter().map(Dd::to_f64).collect()
}

/// Starting order of Miller's recurrence: even, above `nmax` and `x` by a margin
/// that grows like `sqrt(x)` (the transition-region width) plus a constant for
/// 60 bits of decay [Numerical Recipes 6.5, "IACC" rule, with a wider margin].
/// Up to this `x` the short Miller margin is enough (see [`miller_start`]).
const MILLER_SMALL_X: f64 = 400.0;

fn miller_start(nmax: usize, x: f64) -> usize {
    // Past the turning point n = x the minimal solution decays like
    // exp(-(2/3) (2 t)^{3/2}), t = (n - x)/x^{1/3} (Airy region, DLMF 10.19.8), and
    // then factorially: 24 + 6 x^{1/3} orders beyond max(nmax, x) put the
    // neglected dominant solution below double-double accuracy (checked against
    // the certified sequence in `double_double_sequence_accuracy`).
    // For larger x the accumulated rounding of the long recurrence needs more
    // room; the wider empirical margin `40 + 8 sqrt(base)` is used there.
    let base = (nmax as f64).max(x);
    let m = if x <= MILLER_SMALL_X { base + 24.0 + 6.0 * x.cbrt() } else { base + 40.0 + 8.0 * base.sqrt() };
    let m = m as usize + 2;
    m + (m % 2)
}
