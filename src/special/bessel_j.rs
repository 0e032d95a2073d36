//! Bessel function of the first kind `J_n(x)`, integer order, real argument.
//!
//! # Method
//!
//! Symmetries first: `J_{-n}(x) = (-1)^n J_n(x)` and `J_n(-x) = (-1)^n J_n(x)`
//! [DLMF 10.4.1, 10.11.1], so the algorithms see `n >= 0`, `x > 0`.
//! `J_0(0) = 1`, `J_n(0) = 0` for `n != 0` (exact).
//!
//! Two algorithms, chosen by [`choose_algorithm`]:
//!
//! * **Power series** [DLMF 10.2.2]:
//!   `J_n(x) = (x/2)^n / n! * 0F1(; n+1; -x^2/4)`, summed by the pFq core with its
//!   rigorous tail bound. The terms alternate and their magnitudes sum to
//!   `I_n(x) n! (2/x)^n`, so about `log2(I_n(x)/|J_n(x)|)` bits cancel (roughly
//!   `1.44 x` for `x > n`); the Ziv loop adds them as guard bits.
//! * **Hankel asymptotic expansion** for large `x` [DLMF 10.17.3]:
//!   `J_n(x) = sqrt(2/(pi x)) (cos(w) P - sin(w) Q)`, `w = x - n pi/2 - pi/4`,
//!   `P = sum_k (-1)^k a_{2k}(n) x^{-2k}`, `Q = sum_k (-1)^k a_{2k+1}(n) x^{-2k-1}`,
//!   `a_k(n) = prod_{j=1..k} (4n^2 - (2j-1)^2) / (k! 8^k)` [DLMF 10.17.1].
//!   **Error bound** [DLMF 10.17(iii)]: for `n >= 0`, `x > 0`, the remainder of
//!   `P` after `l` terms is at most the first neglected term in absolute value
//!   when `l >= max(n/2 - 1/4, 1)`, and that of `Q` when `l >= max(n/2 - 3/4, 1)`.
//!   We stop at an even index `K >= max(n, 2)` with `|a_K x^-K|` and
//!   `|a_{K+1} x^{-K-1}|` below the target and add those two terms to the radii
//!   of `P` and `Q`. The expansion is tried when
//!   `x >= n^2/8 + 0.4 wp + 20` (its smallest term is about `e^{-2x}`); if its
//!   terms stop decreasing before reaching the target, the power series is used.
//!
//! # Accuracy
//!
//! * MP: certified, `rad <= 2^-prec |mid|` (relative, also near zeros: the Ziv
//!   loop raises the working precision there).
//! * f64: the certified value at 64 bits rounded to nearest, so within one ulp
//!   (tolerance 2 ulp; absolute `2^-53` near zeros is therefore also met).
//!   This path costs a few microseconds; a double-double fast path is future work.
//!
//! Domain: `|n| <= 10^4` and `|x| <= 10^4` are tested; larger values work but are slow.

use rug::Float;

use crate::ball::{Ball, Bounded, Dd};
use crate::error::{Error, Result};
use crate::special::pfq::pfq_series;
use crate::special::{check_finite, exact, f64_from_mp, ziv};

/// Largest |n| accepted (the documented domain is |n| <= 1e4; this is the hard cap).
pub const MAX_ORDER: i64 = 1_000_000;

/// Minimum x for the Hankel expansion, beyond the precision-dependent bound.
const HANKEL_X_MIN: f64 = 20.0;

/// The two algorithms.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Algorithm {
    /// Power series through 0F1.
    PowerSeries,
    /// Hankel's asymptotic expansion with DLMF 10.17(iii) bounds.
    Hankel,
}

/// Picks the algorithm for `n >= 0`, `x > 0` at working precision `wp`.
pub fn choose_algorithm(n: u64, x: f64, wp: u32) -> Algorithm {
    let nf = n as f64;
    if x >= HANKEL_X_MIN && x >= nf * nf / 8.0 + 0.4 * wp as f64 + 20.0 {
        Algorithm::Hankel
    } else {
        Algorithm::PowerSeries
    }
}

/// Initial guard bits at output precision `prec`: for the Hankel expansion the
/// bits lost to `cos(w) P - sin(w) Q` (about `log2 x`), for the power series an
/// estimate of `log2(I_n(x)/|J_n(x)|)`.
fn initial_guard(n: u64, x: f64, prec: u32) -> u32 {
    if choose_algorithm(n, x, prec + 32) == Algorithm::Hankel {
        return 32 + x.log2().max(0.0) as u32;
    }
    let nf = n as f64;
    let est = 1.4427 * x.min(x * x / (nf + 1.0));
    (est + 24.0).min(4.0e6) as u32
}

fn validate(n: i64, x: &Float) -> Result<()> {
    check_finite(x, "x")?;
    if n.abs() > MAX_ORDER {
        return Err(Error::Domain { what: format!("|n| = {} exceeds the supported order {MAX_ORDER}", n.abs()) });
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

/// `J_n(x)` by the power series at working precision `wp` (`x > 0`).
pub fn bessel_j_series(n: u64, x: &Float, wp: u32) -> Result<Ball> {
    let xb = Ball::from_float(x, wp);
    let half_x = xb.mul_pow2(-1);
    let z = half_x.sqr().neg();
    let b = [Ball::from_i64(n as i64 + 1, wp)];
    let sum = pfq_series(&[], &b, &z, wp)?.sum;
    // (x/2)^n / n!, n! correctly rounded by MPFR.
    let order = u32::try_from(n).map_err(|_| Error::Domain { what: "Bessel order too large".into() })?;
    let fact = Ball::factorial(order, wp);
    let pre = half_x.pow_u64(n).div(&fact)?;
    Ok(pre.mul(&sum))
}

/// `J_n(x)` by Hankel's expansion at working precision `wp` (`x > 0`);
/// `None` if the expansion cannot reach `2^-wp` (terms stop decreasing).
pub fn bessel_j_hankel(n: u64, x: &Float, wp: u32) -> Result<Option<Ball>> {
    let xb = Ball::from_float(x, wp);
    let four_n2 = Ball::from_i64(4, wp).mul(&Ball::from_i64(n as i64, wp).sqr());
    let eight_x = xb.mul_i64(8);
    let mut term = Ball::one(wp); // a_k x^-k
    let mut p = Ball::one(wp);
    let mut q = Ball::zero(wp);
    let mut prev_abs = term.abs_upper();
    let min_k = (n as u64).max(2);
    let mut k: u64 = 0;
    loop {
        // term_{k+1} = term_k (4n^2 - (2k+1)^2) / (8 (k+1) x)
        let odd = Ball::from_i64(2 * k as i64 + 1, wp).sqr();
        let factor = four_n2.sub(&odd).div(&eight_x.mul_i64(k as i64 + 1))?;
        term = term.mul(&factor);
        k += 1;
        let t_abs = term.abs_upper();
        if k >= min_k && k % 2 == 0 {
            // Candidate stop at K = k: the remainders are bounded by |u_K| (for P)
            // and |u_{K+1}| (for Q).
            let next = term.mul(&four_n2.sub(&Ball::from_i64(2 * k as i64 + 1, wp).sqr()).div(&eight_x.mul_i64(k as i64 + 1))?);
            let n_abs = next.abs_upper();
            let mut target = Float::with_val(crate::ball::MAG_PREC, 1);
            target >>= wp as i32;
            if t_abs <= target && n_abs <= target {
                p.add_error(&t_abs);
                q.add_error(&n_abs);
                break;
            }
        }
        if k > min_k && t_abs > prev_abs {
            return Ok(None);
        }
        prev_abs = t_abs;
        // (-1)^j a_{2j} x^{-2j} into P (k = 2j), (-1)^j a_{2j+1} x^{-2j-1} into Q (k = 2j+1).
        let j = k / 2;
        let signed = if j % 2 == 1 { term.neg() } else { term.clone() };
        if k % 2 == 0 {
            p = p.add(&signed);
        } else {
            q = q.add(&signed);
        }
        if k > 10_000_000 {
            return Err(Error::NoConvergence { function: "bessel_j (Hankel)", terms: k });
        }
    }
    // w = x - (2n+1) pi / 4
    let pi = Ball::pi(wp);
    let w = xb.sub(&pi.mul_i64(2 * n as i64 + 1).mul_pow2(-2));
    let (s, c) = w.sin_cos();
    let amp = Ball::from_i64(2, wp).div(&pi.mul(&xb))?.sqrt()?;
    Ok(Some(amp.mul(&c.mul(&p).sub(&s.mul(&q)))))
}

/// `J_n(x)` at working precision `wp` (`n >= 0`, `x > 0`), algorithm by [`choose_algorithm`].
fn bessel_j_positive(n: u64, x: &Float, wp: u32) -> Result<Ball> {
    if choose_algorithm(n, x.to_f64(), wp) == Algorithm::Hankel {
        if let Some(b) = bessel_j_hankel(n, x, wp)? {
            return Ok(b);
        }
    }
    bessel_j_series(n, x, wp)
}

/// Certified `J_n(x)` with `rad <= 2^-prec |mid|`.
pub fn bessel_j_mp(n: i64, x: &Float, prec: u32) -> Result<Ball> {
    crate::error::check_prec(prec)?;
    bessel_j_ball(n, x, prec)
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

/// Guard bits past which the power series is refused instead of run: it would
/// need about `guard` bits and as many terms (at `n ~ x ~ 1e5`, hours of work).
pub const MAX_SERIES_GUARD: u32 = 1 << 17;

/// The initial guard, or an error when the power series would be out of
/// proportion (outside the documented domain |n|, |x| <= 1e4 this can happen).
fn check_cost(m: u64, x: f64, prec: u32) -> Result<u32> {
    let guard = initial_guard(m, x, prec);
    if guard > MAX_SERIES_GUARD {
        return Err(Error::Domain {
            what: format!(
                "J_n(x) with n = {m}, x = {x:e} would need ~{guard} guard bits in the power series; \
                 the supported domain is |n|, |x| <= 1e4 (and Hankel's expansion for larger x)"
            ),
        });
    }
    Ok(guard)
}

/// `J_n(x)` in f64, within 1 ulp (see the module docs).
pub fn bessel_j(n: i64, x: f64) -> Result<f64> {
    crate::error::finite(x, "x")?;
    let xe = exact(x);
    validate(n, &xe)?;
    if x == 0.0 {
        return Ok(if n == 0 { 1.0 } else { 0.0 });
    }
    let (m, ax, negate) = reduce(n, &xe);
    let guard = check_cost(m, ax.to_f64(), crate::special::F64_FALLBACK_PREC)?;
    let v = f64_from_mp("bessel_j", guard, |wp| bessel_j_positive(m, &ax, wp))?;
    Ok(if negate { -v } else { v })
}

/// `J_n(x)` in f64 with a proven error bound for the f64 `x` as given.
pub fn bessel_j_bounded(n: i64, x: f64) -> Result<Bounded> {
    crate::error::finite(x, "x")?;
    let xe = exact(x);
    validate(n, &xe)?;
    if x == 0.0 {
        return Ok(Bounded { value: if n == 0 { 1.0 } else { 0.0 }, err: 0.0 });
    }
    let (m, ax, negate) = reduce(n, &xe);
    let guard = check_cost(m, ax.to_f64(), crate::special::F64_FALLBACK_PREC)?;
    let b = crate::special::bounded_from_mp("bessel_j", guard, |wp| bessel_j_positive(m, &ax, wp))?;
    Ok(if negate { Bounded { value: -b.value, err: b.err } } else { b })
}

/// Certified `J_0(x), ..., J_nmax(x)` at working precision `wp` (`x > 0`).
///
/// `J_nmax` and `J_{nmax+1}` are certified by [`bessel_j_mp`]; the rest follows
/// from the three-term recurrence run downward, `J_{n-1} = (2n/x) J_n - J_{n+1}`
/// [DLMF 10.6.1], in ball arithmetic, so every entry is certified. Downward is the
/// stable direction for `n > x` (J_n is the minimal solution there); below `x`
/// the recurrence is neutral and the radii grow only mildly.
pub fn bessel_j_sequence_mp(nmax: u64, x: &Float, wp: u32) -> Result<Vec<Ball>> {
    check_finite(x, "x")?;
    if *x <= 0 {
        return Err(Error::Domain { what: "bessel_j_sequence_mp needs x > 0".into() });
    }
    let top = i64::try_from(nmax).map_err(|_| Error::Domain { what: "order too large".into() })?;
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
/// tests measure it). Returns an empty vector for non-finite `x`.
pub fn bessel_j_sequence_dd(nmax: usize, x: Dd) -> Vec<Dd> {
    if !x.hi.is_finite() {
        return Vec::new();
    }
    let mut out = vec![Dd::ZERO; nmax + 1];
    if x.hi == 0.0 {
        out[0] = Dd::ONE;
        return out;
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

/// `J_0(x), ..., J_nmax(x)` in f64 (the double-double sequence, rounded).
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn small_values() {
        // J_0(1) = 0.7651976865579666, J_1(1) = 0.44005058574493355
        assert!((bessel_j(0, 1.0).unwrap() - 0.765_197_686_557_966_6).abs() < 2e-16);
        assert!((bessel_j(1, 1.0).unwrap() - 0.440_050_585_744_933_55).abs() < 2e-16);
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
