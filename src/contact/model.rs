//! The normalised wavy Maugis model at one contact size (notes/model.md sec. 4-7).
//!
//! # Normalisation (two length scales, notes sec. 4)
//!
//! Horizontal lengths by `l_h = (dgamma R^2/E*)^(1/3)`: `a = abar l_h`,
//! `c = m abar l_h`, `x = xbar l_h`, `zeta = beta l_h`. Vertical lengths by
//! `l_v = l_h^2/R`: `A = alpha l_v`, `u`, `g`, `delta = l_v/lambda`. Load by
//! `(E* dgamma^2 R)^(1/3)`, traction by `sigma`. In these units
//! `hbar(x) = x^2/2 + 2 alpha sin^2(pi x/beta)`, `ubar_H = u_H(a = abar, R = 1)`,
//! `ubar_w = u_w(a = abar, zeta = beta, A = alpha)` and
//! `ubar_a = u_a(a = abar, c = m abar, sigma = lambda, E* = 1)` (the functions of
//! [`super::displacement`] with these arguments).
//!
//! # The adhesive-strip equation (Eq. 15b, corrected, notes sec. 5)
//!
//! `lambda gbar(c) = 1`, i.e. `F(m) = 0` with
//!
//! ```text
//! F(m) = (4/pi) lambda^2 abar (sqrt(m^2-1) acosh(m) - m ln m)
//!      + (1/2) lambda abar^2 (m sqrt(m^2-1) - acosh(m))          <- abar squared
//!      + lambda [2 alpha sin^2(pi m abar/beta) - ubar_w(m abar)]   <- this sign
//!      - 1.
//! ```
//!
//! `F(1) = -1` because every gap term vanishes at the contact edge. The strip
//! ends where the gap *first* reaches `delta` (notes sec. 6), so `m` is the
//! smallest root: [`ContactSize::solve_m`] scans outward from `c = a` (steps of
//! at most `beta/16` so no wave period is skipped, halving towards the edge when
//! the root is closer than one step) for the first sign change and refines it with Brent's method to
//! `1e-13` relative. A root where `F` touches zero without changing sign is not
//! detected (it is not a crossing). No root below `c - a = `[`MAX_STRIP`] is an
//! [`Error::NoConvergence`].
//!
//! # Load (Eq. 14) and traction (Eq. 16)
//!
//! `Lbar = pi abar^2/4 - 2 lambda abar sqrt(m^2-1) + (pi^2 alpha abar/beta) J1(2 pi abar/beta)`.
//! Inside the contact
//! `pbar = (2/pi) atan(abar sqrt((m^2-1)/(abar^2-x^2))) - (sqrt(abar^2-x^2)/(2 lambda)) (1 + (2 pi alpha/(beta abar)) K(x/abar))`
//! with `K(c) = int_0^D J0(t) cos((t-D) c) dt`, `D = 2 pi abar/beta` (the printed
//! Eq. 16 has `2 pi abar` as the upper limit; Eq. 7 and the normalisation give `D`);
//! `pbar = 1` in the strip and 0 outside.
//!
//! # Validity (notes sec. 7)
//!
//! A state is physical only if the gap is non-negative in the strip
//! `abar < x < m abar` (no interpenetration at crests) and `pbar <= 1` inside the
//! contact (no cavitation). [`ContactSize::validity`] samples both and refines
//! the extrema with golden-section search.

use std::f64::consts::PI;

use crate::contact::displacement::{profile_depth, u_adhesive, u_hertz, WaveBessel};
use crate::error::{finite, Error, Result};

/// Largest strip width `c - a` (in `l_h`) the root scan explores.
pub const MAX_STRIP: f64 = 1.0e4;

/// Relative tolerance of the root `m`.
pub const M_REL_TOL: f64 = 1e-13;

/// Slack of the validity tests (gap `>= -GAP_TOL`, traction `<= 1 + TRACTION_TOL`).
pub const GAP_TOL: f64 = 1e-10;
/// See [`GAP_TOL`].
pub const TRACTION_TOL: f64 = 1e-10;

/// Supported Maugis parameters: beyond these the strip equation over- or
/// underflows in f64 (`lambda^2 abar` terms) or the strip leaves [`MAX_STRIP`].
pub const LAMBDA_RANGE: (f64, f64) = (1e-6, 1e6);
/// Largest supported `alpha`.
pub const ALPHA_MAX: f64 = 1e6;
/// Supported `beta`.
pub const BETA_RANGE: (f64, f64) = (1e-6, 1e6);
/// Largest supported contact size.
pub const ABAR_MAX: f64 = 1e4;

/// Samples per extremum search in [`ContactSize::validity`].
const VALIDITY_SAMPLES: usize = 48;

/// The model parameters: Maugis parameter `lambda`, roughness `alpha` (amplitude)
/// and `beta` (wavelength).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Params {
    /// Maugis parameter, `> 0`.
    pub lambda: f64,
    /// Normalised wave amplitude, `>= 0` (0 is the smooth cylinder).
    pub alpha: f64,
    /// Normalised wavelength, `> 0`.
    pub beta: f64,
}

impl Params {
    /// Validated parameters.
    pub fn new(lambda: f64, alpha: f64, beta: f64) -> Result<Params> {
        finite(lambda, "lambda")?;
        finite(alpha, "alpha")?;
        finite(beta, "beta")?;
        if !(LAMBDA_RANGE.0..=LAMBDA_RANGE.1).contains(&lambda) {
            return Err(Error::Domain {
                what: format!("lambda must lie in [{:e}, {:e}] (got {lambda:?})", LAMBDA_RANGE.0, LAMBDA_RANGE.1),
            });
        }
        if !(0.0..=ALPHA_MAX).contains(&alpha) {
            return Err(Error::Domain { what: format!("alpha must lie in [0, {ALPHA_MAX:e}] (got {alpha:?})") });
        }
        if !(BETA_RANGE.0..=BETA_RANGE.1).contains(&beta) {
            return Err(Error::Domain {
                what: format!("beta must lie in [{:e}, {:e}] (got {beta:?})", BETA_RANGE.0, BETA_RANGE.1),
            });
        }
        Ok(Params { lambda, alpha, beta })
    }
}

/// Validity diagnostics of a state.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Validity {
    /// Smallest gap in the strip `abar < x <= m abar` (units of `l_v`).
    pub min_strip_gap: f64,
    /// Where it occurs.
    pub min_strip_gap_at: f64,
    /// Largest traction `pbar` inside the contact.
    pub max_traction: f64,
    /// Where it occurs.
    pub max_traction_at: f64,
    /// `min_strip_gap >= -GAP_TOL && max_traction <= 1 + TRACTION_TOL`.
    pub valid: bool,
}

/// The model at one contact size `abar` (the Bessel data of the wave term are
/// computed once here).
#[derive(Debug, Clone)]
pub struct ContactSize {
    params: Params,
    abar: f64,
    wave: Option<WaveBessel>,
    j1: f64,
}

impl ContactSize {
    /// Prepares contact size `abar > 0`.
    pub fn new(params: Params, abar: f64) -> Result<ContactSize> {
        finite(abar, "abar")?;
        if !(abar > 0.0 && abar <= ABAR_MAX) {
            return Err(Error::Domain { what: format!("abar must lie in (0, {ABAR_MAX:e}] (got {abar:?})") });
        }
        let wave = if params.alpha > 0.0 { Some(WaveBessel::new(abar, params.beta, params.alpha)?) } else { None };
        let j1 = crate::special::bessel_j::bessel_j_sequence(1, 2.0 * PI * abar / params.beta).get(1).copied().unwrap_or(0.0);
        Ok(ContactSize { params, abar, wave, j1 })
    }

    /// The contact size.
    pub fn abar(&self) -> f64 {
        self.abar
    }

    /// The parameters.
    pub fn params(&self) -> Params {
        self.params
    }

    /// `ubar_w(x)` for `x >= abar`.
    pub fn wave_displacement(&self, x: f64) -> f64 {
        match &self.wave {
            Some(w) => w.u_fast(x.max(self.abar)),
            None => 0.0,
        }
    }

    /// The three gap contributions at `c = m abar`: (Hertz, adhesive, wave), units of `l_v`.
    pub fn strip_gap_terms(&self, m: f64) -> (f64, f64, f64) {
        let (a, Params { lambda, alpha, beta }) = (self.abar, self.params);
        let e = (m - 1.0).max(0.0);
        let s = (e * (2.0 + e)).sqrt(); // sqrt(m^2 - 1)
        let acosh_m = (e + s).ln_1p();
        let hertz = 0.5 * a * a * (m * s - acosh_m);
        let adhesive = 4.0 / PI * lambda * a * (s * acosh_m - m * e.ln_1p());
        let c = m * a;
        let sn = (PI * c / beta).sin();
        let wave = if alpha > 0.0 { 2.0 * alpha * sn * sn - self.wave_displacement(c) } else { 0.0 };
        (hertz, adhesive, wave)
    }

    /// `F(m) = lambda gbar(m abar) - 1` (Eq. 15b, corrected).
    pub fn strip_residual(&self, m: f64) -> f64 {
        let (h, ad, w) = self.strip_gap_terms(m);
        self.params.lambda * (h + ad + w) - 1.0
    }

    /// The first root `m > 1` of [`Self::strip_residual`].
    ///
    /// Scan in the strip width `s = c - a` with steps of at most
    /// `min(beta/16, 1/4)` (so no wave period is skipped); when the first
    /// sampled point is already past the root, the crossing lies in
    /// `(0, s_1]`, where the wave term changes little, and is bracketed by
    /// halving `s` towards the edge (down to `s = 1e-14 a`).
    pub fn solve_m(&self) -> Result<f64> {
        let a = self.abar;
        let f = |m: f64| self.strip_residual(m);
        let max_step = (self.params.beta / 16.0).min(0.25).max(1e-6);
        let eval = |s: f64| -> Result<f64> {
            let v = f(1.0 + s / a);
            if v.is_finite() {
                Ok(v)
            } else {
                Err(Error::Internal { what: format!("strip residual not finite at m = {}", 1.0 + s / a) })
            }
        };
        let first = max_step;
        let f_first = eval(first)?;
        if f_first >= 0.0 {
            // Bracket towards the edge: F(0) = -1.
            let (mut hi, mut f_hi) = (first, f_first);
            let mut lo = 0.5 * first;
            loop {
                let f_lo = eval(lo)?;
                if f_lo < 0.0 {
                    return brent(f, 1.0 + lo / a, 1.0 + hi / a, f_lo, f_hi);
                }
                hi = lo;
                f_hi = f_lo;
                lo *= 0.5;
                if lo < 1e-14 * a {
                    return brent(f, 1.0, 1.0 + hi / a, -1.0, f_hi);
                }
            }
        }
        let (mut s_prev, mut f_prev) = (first, f_first);
        loop {
            let s = s_prev + max_step.max(s_prev * 0.05);
            let fs = eval(s)?;
            if fs >= 0.0 {
                return brent(f, 1.0 + s_prev / a, 1.0 + s / a, f_prev, fs);
            }
            if s > MAX_STRIP {
                return Err(Error::Domain {
                    what: format!("no end of the adhesive strip within c - a <= {MAX_STRIP:e} (abar = {a}): parameters too extreme"),
                });
            }
            s_prev = s;
            f_prev = fs;
        }
    }

    /// Eq. 14.
    pub fn load(&self, m: f64) -> f64 {
        let (a, Params { lambda, alpha, beta }) = (self.abar, self.params);
        let e = (m - 1.0).max(0.0);
        PI * a * a / 4.0 - 2.0 * lambda * a * (e * (2.0 + e)).sqrt() + PI * PI * alpha * a / beta * self.j1
    }

    /// `pbar(x)`: Eq. 16 inside the contact, 1 in the strip, 0 outside.
    pub fn traction(&self, m: f64, x: f64) -> f64 {
        let (a, Params { lambda, alpha, beta }) = (self.abar, self.params);
        let ax = x.abs();
        if ax >= a {
            return if ax <= m * a { 1.0 } else { 0.0 };
        }
        let w = ((a - ax) * (a + ax)).sqrt();
        let e = m - 1.0;
        let adhesive = 2.0 / PI * (a * (e * (2.0 + e)).sqrt() / w).atan();
        let k = match &self.wave {
            Some(wb) => wb.traction_integral(ax / a),
            None => 0.0,
        };
        adhesive - w / (2.0 * lambda) * (1.0 + 2.0 * PI * alpha / (beta * a) * k)
    }

    /// The total displacement `ubar(x)`: the profile inside the contact, the sum
    /// of the Hertz, wave and adhesive displacements outside.
    pub fn displacement(&self, m: f64, x: f64) -> Result<f64> {
        let ax = x.abs();
        let Params { lambda, alpha, beta } = self.params;
        if ax <= self.abar {
            return profile_depth(1.0, alpha, beta, ax);
        }
        let uh = u_hertz(self.abar, 1.0, ax)?;
        let ua = u_adhesive(self.abar, m * self.abar, lambda, 1.0, ax)?;
        Ok(uh + self.wave_displacement(ax) + ua)
    }

    /// The gap `gbar(x) = hbar - ubar` (zero inside the contact).
    pub fn gap(&self, m: f64, x: f64) -> Result<f64> {
        let ax = x.abs();
        if ax <= self.abar {
            return Ok(0.0);
        }
        let Params { alpha, beta, .. } = self.params;
        Ok(profile_depth(1.0, alpha, beta, ax)? - self.displacement(m, ax)?)
    }

    /// Minimum strip gap and maximum inner traction, located by sampling and
    /// golden-section refinement.
    pub fn validity(&self, m: f64) -> Result<Validity> {
        let a = self.abar;
        let c = m * a;
        // Strip: the gap vanishes at x = a; sample (a, c] from just off the edge.
        let gap = |x: f64| self.gap(m, x).unwrap_or(f64::NAN);
        let (gx, gv) = refine_extremum(|x| gap(x), a + (c - a) * 1e-6, c, true);
        // Traction: symmetric in x; sample [0, a).
        let trac = |x: f64| self.traction(m, x);
        let (tx, tv) = refine_extremum(trac, 0.0, a * (1.0 - 1e-9), false);
        if !gv.is_finite() || !tv.is_finite() {
            return Err(Error::Internal { what: "validity check produced a non-finite value".into() });
        }
        Ok(Validity {
            min_strip_gap: gv,
            min_strip_gap_at: gx,
            max_traction: tv,
            max_traction_at: tx,
            valid: gv >= -GAP_TOL && tv <= 1.0 + TRACTION_TOL,
        })
    }
}

/// Extremum (minimum if `minimize`, else maximum) of `f` on `[lo, hi]`: the best
/// of [`VALIDITY_SAMPLES`] samples, refined by golden-section search between its
/// neighbours. Returns `(argument, value)`.
fn refine_extremum<F: Fn(f64) -> f64>(f: F, lo: f64, hi: f64, minimize: bool) -> (f64, f64) {
    let sign = if minimize { 1.0 } else { -1.0 };
    let g = |x: f64| sign * f(x);
    if !(hi > lo) {
        return (lo, f(lo));
    }
    let n = VALIDITY_SAMPLES;
    let h = (hi - lo) / n as f64;
    let mut best = (lo, g(lo));
    for i in 1..=n {
        let x = lo + h * i as f64;
        let v = g(x);
        if v < best.1 || best.1.is_nan() {
            best = (x, v);
        }
    }
    // golden section on [best - h, best + h] ∩ [lo, hi]
    let (mut a, mut b) = ((best.0 - h).max(lo), (best.0 + h).min(hi));
    let gr = 0.5 * (5f64.sqrt() - 1.0);
    let mut x1 = b - gr * (b - a);
    let mut x2 = a + gr * (b - a);
    let (mut f1, mut f2) = (g(x1), g(x2));
    for _ in 0..60 {
        if (b - a) <= 1e-12 * (1.0 + a.abs()) {
            break;
        }
        if f1 < f2 {
            b = x2;
            x2 = x1;
            f2 = f1;
            x1 = b - gr * (b - a);
            f1 = g(x1);
        } else {
            a = x1;
            x1 = x2;
            f1 = f2;
            x2 = a + gr * (b - a);
            f2 = g(x2);
        }
    }
    let (x, v) = if f1 < f2 { (x1, f1) } else { (x2, f2) };
    let (x, v) = if v < best.1 { (x, v) } else { best };
    (x, sign * v)
}

/// Brent's root finder on a bracket `[a, b]` with `f(a) < 0 <= f(b)`
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
        let tol = 2.0 * f64::EPSILON * b.abs() + 0.5 * M_REL_TOL * b.abs();
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn smooth_case_is_johnson_greenwood() {
        // alpha = 0: F(m) has no wave term; the root satisfies the JG equation.
        let p = Params::new(1.0, 0.0, 1.0).unwrap();
        let cs = ContactSize::new(p, 2.0).unwrap();
        let m = cs.solve_m().unwrap();
        assert!(cs.strip_residual(m).abs() < 1e-12);
        assert!(m > 1.0);
    }

    #[test]
    fn residual_is_minus_one_at_the_edge() {
        let p = Params::new(1.5, 2f64.sqrt() / 4.0, 1.125).unwrap();
        for abar in [0.5, 2.0, 5.5] {
            let cs = ContactSize::new(p, abar).unwrap();
            assert!((cs.strip_residual(1.0) + 1.0).abs() < 1e-12);
        }
    }

    #[test]
    fn bad_parameters() {
        assert!(Params::new(0.0, 0.1, 1.0).is_err());
        assert!(Params::new(1.0, -0.1, 1.0).is_err());
        assert!(Params::new(1.0, 0.1, 0.0).is_err());
        assert!(Params::new(f64::NAN, 0.1, 1.0).is_err());
        let p = Params::new(1.0, 0.1, 1.0).unwrap();
        assert!(ContactSize::new(p, 0.0).is_err());
    }
}
