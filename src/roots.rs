//! Root finding and minimisation in one real variable, for the model's f64
//! solvers ([`crate::contact`]: the strip root `m - 1`, the turning points of
//! the load, the jump ends of the paths, the extrema of the validity tests).
//!
//! # Methods
//!
//! * [`brent`]: Brent's method (R. P. Brent, "Algorithms for Minimization
//!   without Derivatives", 1973, ch. 4): inverse quadratic interpolation or
//!   secant steps, falling back to bisection, on a sign-changing bracket; it
//!   stops when the bracket is below `2 eps |b| + BRENT_REL_TOL |b|` or after
//!   200 steps ([`Error::NoConvergence`]). A bracket without a sign change is
//!   [`Error::Internal`] (callers bracket first).
//! * `golden_section_min` (crate-internal): golden-section search for a minimum of a
//!   unimodal function, until the bracket is below `rel_tol (1 + |a|)`; the
//!   function may fail (its error is passed through).
//!
//! * `first_crossing` (crate-internal): the first upward zero crossing of a
//!   function negative at the start, by an outward scan whose every sampled
//!   local maximum below zero is refined by `golden_section_min` (an excursion
//!   above zero narrower than a step rises between the samples): the bracket
//!   for [`brent`].
//!
//! All are f64 estimates, not certified enclosures: the callers' tolerances
//! (`contact::model`'s gap and traction slacks) absorb their errors.
//!
//! # Layering
//!
//! Below `contact`, beside `quad`: it imports only [`crate::error`], and the
//! contact model is its only user. It is not in `quad` because it is not
//! quadrature, and it is not in `special` because it evaluates no function.

use crate::error::{Error, Result};

/// Relative tolerance of [`brent`]'s root (the model's `m - 1` needs `1e-13`:
/// `contact::model::M_REL_TOL`).
pub const BRENT_REL_TOL: f64 = 1e-13;

/// A bracket `(a, b, f(a), f(b))` with `f(a) < 0 <= f(b)` around the first upward
/// crossing of `f` after `start` (where `f` is `f_start < 0`), scanning at
/// `s_{i+1} = next(s_i)` (increasing) and stopping with `None` past `limit`. A
/// sampled local maximum below zero (`f(s_{i-1}) < f(s_i) > f(s_{i+1})`, the
/// first sample counting `before` as its left neighbour when given) is refined by
/// golden-section search on `[s_{i-1}, s_{i+1}]` to `peak_rel_tol`; a maximum at
/// or above zero closes the bracket there. An estimate: an excursion that leaves
/// no sampled local maximum (two maxima within one step) is not seen.
pub(crate) fn first_crossing<E, F: FnMut(f64) -> std::result::Result<f64, E>>(
    mut f: F,
    before: Option<(f64, f64)>,
    start: (f64, f64),
    next: impl Fn(f64) -> f64,
    limit: f64,
    peak_rel_tol: f64,
) -> std::result::Result<Option<(f64, f64, f64, f64)>, E> {
    let mut prev2 = before;
    let (mut s_prev, mut f_prev) = start;
    while s_prev <= limit {
        let s = next(s_prev);
        let fs = f(s)?;
        if fs >= 0.0 {
            return Ok(Some((s_prev, s, f_prev, fs)));
        }
        if let Some((s2, f2)) = prev2 {
            if f_prev > f2 && f_prev > fs {
                let (s_max, neg_max) = golden_section_min(|t| f(t).map(|v| -v), s2, s, peak_rel_tol, 80)?;
                if -neg_max >= 0.0 {
                    return Ok(Some((s2, s_max, f2, -neg_max)));
                }
            }
        }
        prev2 = Some((s_prev, f_prev));
        (s_prev, f_prev) = (s, fs);
    }
    Ok(None)
}

/// Golden-section search for a minimum of `g` on `[a, b]`, until the bracket is
/// below `rel_tol (1 + |a|)` or after `max_iter` steps. Returns `(x, g(x))`.
pub(crate) fn golden_section_min<E, G: FnMut(f64) -> std::result::Result<f64, E>>(
    mut g: G,
    a: f64,
    b: f64,
    rel_tol: f64,
    max_iter: usize,
) -> std::result::Result<(f64, f64), E> {
    let (mut a, mut b) = (a, b);
    let gr = 0.5 * (5f64.sqrt() - 1.0);
    let mut x1 = b - gr * (b - a);
    let mut x2 = a + gr * (b - a);
    let (mut f1, mut f2) = (g(x1)?, g(x2)?);
    for _ in 0..max_iter {
        if (b - a) <= rel_tol * (1.0 + a.abs()) {
            break;
        }
        if f1 < f2 {
            b = x2;
            x2 = x1;
            f2 = f1;
            x1 = b - gr * (b - a);
            f1 = g(x1)?;
        } else {
            a = x1;
            x1 = x2;
            f1 = f2;
            x2 = a + gr * (b - a);
            f2 = g(x2)?;
        }
    }
    Ok(if f1 < f2 { (x1, f1) } else { (x2, f2) })
}

/// Brent's root finder on a bracket `[a, b]` with `f(a) f(b) <= 0`, to
/// [`BRENT_REL_TOL`] relative (plus `2 eps |b|`)
/// (R. P. Brent, "Algorithms for Minimization without Derivatives", 1973, ch. 4).
pub fn brent<F: Fn(f64) -> f64>(f: F, a: f64, b: f64, fa: f64, fb: f64) -> Result<f64> {
    let (mut a, mut b, mut fa, mut fb) = (a, b, fa, fb);
    if fa * fb > 0.0 {
        return Err(Error::Internal { what: "brent: not a bracket".into() });
    }
    if fb == 0.0 {
        return Ok(b);
    }
    let (mut c, mut fc) = (a, fa);
    let mut d = b - a;
    let mut e = d;
    for _ in 0..200 {
        if fb * fc > 0.0 {
            c = a;
            fc = fa;
            d = b - a;
            e = d;
        }
        if fc.abs() < fb.abs() {
            a = b;
            b = c;
            c = a;
            fa = fb;
            fb = fc;
            fc = fa;
        }
        let tol = 2.0 * f64::EPSILON * b.abs() + 0.5 * BRENT_REL_TOL * b.abs();
        let m = 0.5 * (c - b);
        if m.abs() <= tol || fb == 0.0 {
            return Ok(b);
        }
        if e.abs() >= tol && fa.abs() > fb.abs() {
            let s = fb / fa;
            let (mut p, mut q);
            if a == c {
                p = 2.0 * m * s;
                q = 1.0 - s;
            } else {
                let qq = fa / fc;
                let r = fb / fc;
                p = s * (2.0 * m * qq * (qq - r) - (b - a) * (r - 1.0));
                q = (qq - 1.0) * (r - 1.0) * (s - 1.0);
            }
            if p > 0.0 {
                q = -q;
            } else {
                p = -p;
            }
            if 2.0 * p < (3.0 * m * q - (tol * q).abs()).min((e * q).abs()) {
                e = d;
                d = p / q;
            } else {
                d = m;
                e = m;
            }
        } else {
            d = m;
            e = m;
        }
        a = b;
        fa = fb;
        b += if d.abs() > tol { d } else { tol.copysign(m) };
        fb = f(b);
    }
    Err(Error::NoConvergence { function: "brent", terms: 200 })
}
