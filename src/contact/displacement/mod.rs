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
//!    [`crate::contact::displacement::quadrature`].
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

use rug::Float;

use crate::ball::Ball;
use crate::error::{finite, Error, Interval, Result};
use crate::special::{check_finite, exact_add, exact_sub, ziv, DEFAULT_GUARD_BITS};

pub(crate) mod bessel_mp;
pub mod bounded;
pub mod quadrature;
pub mod quadrature_ball;
mod wave;
mod geometry;
mod series;
mod wave_f64;

pub(crate) use bessel_mp::u_wave_at_ratio_balls;
pub use bessel_mp::{
    du_wave_at_edge_ball_mp, du_wave_ball_mp, du_wave_mp, u_wave_at_edge_ball_mp, u_wave_ball_mp, u_wave_mp, wave_at_decimals,
};
pub use series::{du_wave_series_mp, u_wave_series, u_wave_series_mp, TruncatedSeries};
pub use wave::Wave;
pub use wave_f64::{du_wave, du_wave_bounded, u_wave, u_wave_bounded, WaveBessel};

/// Largest `D = 2 pi a/zeta` (contact width in wavelengths times `pi`) accepted.
pub const MAX_WAVE_D: f64 = 1.0e5;

/// Largest `kmax` accepted by the truncated series.
pub const MAX_KMAX: u64 = 100_000;

// ---------------------------------------------------------------- Hertz, profile, adhesive

fn check_positive(v: f64, what: &'static str) -> Result<()> {
    finite(v, what)?;
    if v <= 0.0 {
        return Err(Error::OutOfRange { arg: what, value: v, allowed: Interval::above(0.0) });
    }
    Ok(())
}

fn check_positive_mp(v: &Float, what: &'static str) -> Result<()> {
    if *v <= 0 {
        return Err(Error::OutOfRange { arg: what, value: v.to_f64(), allowed: Interval::above(0.0) });
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
    check_positive_mp(a, "a")?;
    check_positive_mp(r, "r")?;
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

/// Profile depth `h(x) = x^2/(2R) + A (1 - cos(2 pi x/zeta))` (Eq. 1). Note the
/// order `amp, zeta`, the reverse of [`u_wave`]'s: [`Wave::depth`] cannot swap them.
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
        return Err(Error::OutOfRange { arg: "the strip end c", value: c, allowed: Interval::at_least(a) });
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
    check_positive_mp(a, "a")?;
    check_positive_mp(sigma, "sigma")?;
    check_positive_mp(e_star, "e_star")?;
    if *c < *a {
        return Err(Error::OutOfRange { arg: "the strip end c", value: c.to_f64(), allowed: Interval::at_least(a.to_f64()) });
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
    use crate::special::exact;

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
    fn bad_input() {
        assert!(u_wave(0.0, 1.0, 1.0, 1.0).is_err());
        assert!(u_wave(1.0, 0.0, 1.0, 1.0).is_err());
        assert!(u_wave(1.0, 1.0, 1.0, 0.5).is_err());
        assert!(u_wave(1.0, 1.0, f64::NAN, 1.5).is_err());
        assert!(u_wave_series(1.0, 1.0, 1.0, 1.5, u64::MAX).is_err());
        assert!(u_hertz(1.0, -1.0, 2.0).is_err());
        assert!(u_adhesive(1.0, 0.5, 1.0, 1.0, 2.0).is_err());
    }

    #[test]
    fn f64_fallback_refuses_what_needs_too_many_bits() {
        // tests/fuzz.rs (registry_f64_paths): x/a ~ 3e297 sent the f64 fallback's
        // Ziv loop to 58 335 bits (minutes). Capped at F64_FALLBACK_MAX_WP now: a
        // typed error naming the cap, or a value, never a hang; the MP function remains.
        let (a, zeta, amp, x) = (1.0245220703013299e-296, 1e-300, 245.625, 29.594286029034663);
        for r in [du_wave(a, zeta, amp, x), u_wave(a, zeta, amp, x)] {
            match r {
                Ok(v) => assert!(v.is_finite(), "{v}"),
                Err(e) => assert!(
                    matches!(e, Error::PrecisionExhausted { working_prec, .. } if working_prec <= crate::special::F64_FALLBACK_MAX_WP),
                    "{e:?}"
                ),
            }
        }
    }

    #[test]
    fn far_field_agrees_between_mp_and_f64_routes() {
        // x >> a, where 1 - sqrt((r-1)/(r+1)) is formed as (2/(r+1))/(1 + sqrt t) in
        // the MP geometry: the certified balls against the f64 routes' own geometry.
        for &r in &[10.0, 1e3, 1e6, 1e12] {
            let (a, zeta, amp) = (2.0, 1.125, 0.75);
            let x = a * r;
            let u = u_wave_mp(&e(a), &e(zeta), &e(amp), &e(x), 128).unwrap();
            let du = du_wave_mp(&e(a), &e(zeta), &e(amp), &e(x), 128).unwrap();
            let (uf, duf) = (u_wave(a, zeta, amp, x).unwrap(), du_wave(a, zeta, amp, x).unwrap());
            assert!(u.meets_rel(120) && du.meets_rel(100), "r={r}: {u:?} {du:?}");
            assert!((u.to_f64() - uf).abs() <= 1e-14 * u.to_f64().abs().max(amp), "r={r}: {u:?} vs {uf}");
            let scale = 2.0 * std::f64::consts::PI * amp / zeta;
            assert!((du.to_f64() - duf).abs() <= 1e-14 * scale, "r={r}: {du:?} vs {duf}");
        }
    }
}

