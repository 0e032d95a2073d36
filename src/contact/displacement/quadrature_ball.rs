//! The wave displacement from Eq. 11a as a **certified** double integral: a ball
//! that provably contains `u_w(x)` (or `du_w/dx`), computed by the certified
//! integrator [`crate::quad::certified`] and nothing else, so it is a check of the
//! Eq. 11b / Eq. 12 series and the Bessel form that shares none of their code.
//!
//! # The integrals
//!
//! Eq. 11a as corrected in docs/displacement.md, Route 3 (outer range `[0, D]`,
//! `D = 2 pi a/zeta`, prefactor `A/zeta`, `x = a/cos(phi)`), and its integral in `x`
//! from `a` (see [`crate::contact::displacement::quadrature`], docs/model.md and
//! docs/displacement.md for the derivation):
//!
//! ```text
//! du_w/dx          = (A/zeta)   int_0^D J0(t) 2 int_0^pi cos(phi) sin^2(th) / (1 - cos th cos phi) C dth dt,
//! u_w(x) - u_w(a)  = (A a/zeta) int_0^D J0(t) 2 int_0^pi sin^2(th) ln((r - cos th)/(1 - cos th)) C dth dt,
//! C = cos((t - D) cos th),  r = x/a,  u_w(a) = A (1 - cos D) = 2 A sin^2(D/2).
//! ```
//!
//! # The split of the singular kernel
//!
//! The substitution `s = sin(th/2)` (`th = 2 asin s`, `s in [0, 1]`) makes every
//! trigonometric factor a polynomial: `1 - cos th = 2 s^2`, `cos th = 1 - 2 s^2`,
//! `sin^2(th) dth = 8 s^2 sqrt(1 - s^2) ds`. The logarithm becomes
//!
//! ```text
//! ln((r - cos th)/(1 - cos th)) = ln(rho + 2 s^2) - ln 2 - 2 ln s,   rho = r - 1 = (x - a)/a,
//! ```
//!
//! The range is split at `s = 3/4`; beyond it (`th` towards `pi`) the variable
//! `v = cos(th/2)` (`cos th = 2 v^2 - 1`, `sin^2(th) dth = 8 v^2 sqrt(1 - v^2) dv`,
//! `v in [0, sqrt(7)/4]`) keeps `sqrt(1 - v^2)` away from its branch point, so
//!
//! ```text
//! 2 int_0^pi ... dth = 16 [ int_0^{3/4} s^2 ln(s) g1(s) ds + int_0^{3/4} g0(s) ds + int_0^{sqrt 7/4} h(v) dv ],
//! g1 = -2 sqrt(1-s^2) C,   g0 = s^2 sqrt(1-s^2) C (ln(rho + 2 s^2) - ln 2),
//! h  = v^2 sqrt(1-v^2) C ln((rho + 2 - 2 v^2)/(2 - 2 v^2)),
//! ```
//!
//! `g1`, `g0`, `h` analytic on neighbourhoods of their ranges for `x > a`: the
//! logarithmic singularity at `th = 0` is the weight `s^2 ln s` (`alpha = 2`,
//! `k = 1`) of [`integrate_weighted`], certified without truncation; the `v` piece
//! is mapped onto `[0, 3/4]` (`v = s sqrt(7)/3`) and shares one integral with `g0`.
//! The gradient kernel, in the same two variables, is
//!
//! ```text
//! 16 [ int_0^{3/4} cos(phi) s^2 sqrt(1-s^2) C / (eps + 2 s^2 cos(phi)) ds
//!    + int_0^{sqrt 7/4} cos(phi) v^2 sqrt(1-v^2) C / (1 + cos(phi) - 2 v^2 cos(phi)) dv ],
//! eps = 1 - cos(phi) = (x - a)/x,
//! ```
//!
//! analytic for `x > a` (poles at `s = +-i sqrt(eps/(2 cos phi))`, resolved by
//! bisection); at `x = a` exactly `s^2/(2 s^2) = 1/2`.
//!
//! # Rigour of the outer integral
//!
//! The outer integrand `J0(t) I(t)` is entire in `t` (`I` is an integral of an entire
//! function of `t` over a compact range). The outer Gauss-Legendre bound needs
//! `|J0 I|` on complex boxes around Bernstein ellipses: the inner integral is run
//! with `t` the complex ball itself (a constant of the inner integrand), and since
//! every inner evaluation encloses the integrand for every `t` in the box, the
//! inner certified integral encloses `I(t)` for every `t` in the box. That is how
//! the nodes (balls of radius about `2^-wp`) are evaluated. On the wide boxes of
//! the Bernstein ellipses the integrand is bounded instead, without the complex
//! Bessel function or the inner integral (both costly on a huge box): every kernel
//! above is `>= 0`, `|c| <= 1` for the `cos((t - D) c)` factor, so
//! `|J0(t) I(t)| <= e^|Im t| M cosh(|Im t|) <= M e^(2 |Im t|)` (DLMF 10.14.4) with
//! `M` the inner integral at `t = D` (`C = 1`), itself a certified ball. An inner failure becomes the indeterminate ball,
//! which the outer integrator treats as a point to bisect around (or reports).
//! Inputs are balls (Arb's convention): `D`, `rho`, `cos(phi)` and `eps` are ball
//! functions of them, and the endpoint `D` is a ball the integrator accounts for.
//!
//! Cost (64 bits, release): 0.05-1 s for `du_w/dx` and 0.5-10 s for `u_w` a point
//! (`D` up to 75, `x/a` down to `1 + 1e-6`), so this route is for checking, not for
//! production (`D <=` [`MAX_CERTIFIED_D`], `prec <=`
//! [`MAX_CERTIFIED_PREC`]).
//!
//! References: the paper's Eq. 11a (and Eq. 11b / Eq. 12, which the tests
//! cross-check against); docs/displacement.md, Route 3 (the corrected Eq. 11a);
//! docs/quadrature.md (the certified integrator).

use rug::float::Round;

use crate::ball::{Ball, CBall, Mag};
use crate::error::{check_prec, Error, Interval, Result};
use crate::quad::certified::{integrate, integrate_weighted, HoloBall, Options, Weight};

/// Largest `D = 2 pi a/zeta` the certified route accepts (its cost grows like `D^2`).
pub const MAX_CERTIFIED_D: f64 = 200.0;

/// Largest precision (bits) the certified route accepts: a double integral at
/// more bits costs minutes.
pub const MAX_CERTIFIED_PREC: u32 = 1024;

/// Which quantity.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Quantity {
    /// `du_w/dx`
    Gradient,
    /// `u_w(x)`
    Displacement,
}

/// The ball functions of the inputs the integrands need, at working precision.
struct Geometry {
    /// `D = 2 pi a/zeta`
    d: Ball,
    /// `rho = (x - a)/a`
    rho: Ball,
    /// `cos(phi) = a/x`
    cos_phi: Ball,
    /// `eps = 1 - cos(phi) = (x - a)/x`
    eps: Ball,
    /// `x = a` exactly.
    at_edge: bool,
}

/// Checks the inputs and builds the geometry at `wp` bits.
fn geometry(a: &Ball, zeta: &Ball, amp: &Ball, x: &Ball, prec: u32, wp: u32) -> Result<Geometry> {
    check_prec(prec)?;
    if prec > MAX_CERTIFIED_PREC {
        return Err(Error::RoutePrecision { route: "the certified Eq. 11a route (a double integral)", requested: prec, max: MAX_CERTIFIED_PREC });
    }
    for (v, what) in [(a, "a"), (zeta, "zeta"), (amp, "amp"), (x, "x")] {
        if !v.is_finite() {
            return Err(Error::NonFinite { what });
        }
    }
    a.check_within("the contact half-width a", Interval::above(0.0))?;
    zeta.check_within("the wavelength zeta", Interval::above(0.0))?;
    let [a, zeta, x] = [a, zeta, x].map(|v| v.set_prec(wp));
    let d = Ball::pi(wp).mul(&a).mul_pow2(1).div(&zeta)?;
    // the certified double integral costs D^2
    d.check_within("2 pi a/zeta", Interval::left_open(0.0, MAX_CERTIFIED_D))?;
    let xma = x.sub(&a);
    let at_edge = xma.is_exact() && xma.mid().is_zero();
    if !at_edge && !(xma.lower() > 0) {
        let (lower, upper) = (xma.lower().to_f64_round(Round::Down), xma.upper().to_f64_round(Round::Up));
        return Err(Error::ContactEdgeInBall { function: "the Eq. 11a route (u_wave_quad_ball, du_wave_quad_ball)", lower, upper });
    }
    Ok(Geometry { rho: xma.div(&a)?, cos_phi: a.div(&x)?, eps: xma.div(&x)?, d, at_edge })
}

/// Inner options at working precision `p`: the goal `p` bits, and an absolute
/// tolerance at the natural scale of `I(t)` (`int |kernel| <= 8` here): `I(t)`
/// oscillates in `t` and may vanish, where a relative goal alone would chase a zero.
fn inner_options(p: u32) -> Result<Options> {
    Options::new().goal_bits(p)?.abs_tol((8.0 * (-(p as f64)).exp2()).max(f64::MIN_POSITIVE))
}

/// Whether a `t` ball is a box (a Bernstein-ellipse box or a real segment) rather
/// than a quadrature node (a point up to rounding).
fn is_box(t: &CBall) -> bool {
    let p = t.prec() as i64;
    !t.rad_mag().le(&Mag::pow2(-p / 2))
}

/// The ball centred at 0 of radius `scale e^(rate |Im t|)` (upper bounds), for a
/// box `t`: what an integrand whose modulus grows at most like that gives on the
/// boxes of the Bernstein ellipses, without evaluating the complex Bessel function
/// (or an inner integral) on a box that may be huge (the integrator tries wide
/// ellipses), at the price of the cancellation in the integrand.
fn box_bound(scale: &Ball, rate: &Ball, t: &CBall) -> CBall {
    let p = t.prec();
    let im = Ball::from_float(&t.im().abs_upper(), p).mul(rate);
    match im.exp() {
        Ok(e) if e.is_finite() => {
            let mut z = CBall::zero(p);
            z.add_error_mag(scale.mul(&e).abs_upper_mag());
            z
        }
        _ => CBall::indeterminate(p),
    }
}

/// `2 int_0^pi kernel dth` (the inner integral of Eq. 11a, or of its
/// `x`-integral) at every `t` in the complex ball `t`, as a complex ball: the
/// `s` piece `[0, 3/4]` and the `v` piece `[0, sqrt(7)/4]` (module docs), the
/// latter as `v = lambda s`, `lambda = sqrt(7)/3`, so both share one integral.
fn inner(kind: Quantity, g: &Geometry, t: &CBall) -> Result<CBall> {
    // An exact t is the integrator's rough magnitude pass (nodes are balls):
    // it only sets a tolerance, so a cheaper enclosure does.
    let p = if t.is_exact() { t.prec().min(32) } else { t.prec() };
    let opts = inner_options(p)?;
    let t_minus_d = t.set_prec(p).sub(&CBall::from_real(g.d.set_prec(p)));
    let zero = Ball::zero(p);
    let s_end = Ball::from_ratio(3, 4, p);
    let lambda = Ball::from_i64(7, p).sqrt()?.div_i64(3)?;
    // (w^2, sqrt(1 - w^2) cos((t - D) c)) with c = 1 - 2 w^2 (s piece, sign 1) or
    // c = 2 w^2 - 1 (v piece, sign -1): the factors every kernel shares.
    let common = |w: &HoloBall, sign: i64| -> (HoloBall, HoloBall) {
        let w2 = w.sqr();
        let c = (w.constant(t_minus_d.clone()) * (w.int(sign) - &w2 * w.int(2 * sign))).cos();
        let root = (w.int(1) - &w2).sqrt();
        (w2, root * c)
    };
    let (rho, cos_phi, eps) = (g.rho.set_prec(p), g.cos_phi.set_prec(p), g.eps.set_prec(p));
    let sum = match kind {
        Quantity::Displacement => {
            let ln2 = Ball::ln2(p);
            // s^2 ln(s) (-2 sqrt(1-s^2) C): the weight s^2 ln s, which decays
            // like e^(-3y) in the integrator's map s = d e^(-y)
            let log_part = integrate_weighted(
                |s| common(s, 1).1 * s.int(-2),
                &zero,
                &s_end,
                &Weight::new(Ball::from_i64(2, p), zero.clone(), 1)?,
                p,
                &opts,
            )?;
            // s^2 sqrt(1-s^2) C (ln(rho + 2 s^2) - ln 2)
            //   + lambda v^2 sqrt(1-v^2) C ln((rho + 2 - 2 v^2)/(2 - 2 v^2)) at v = lambda s
            let analytic_part = integrate(
                |s| {
                    let (s2, k) = common(s, 1);
                    let near = &s2 * k * ((s.real(rho.clone()) + &s2 * s.int(2)).log() - s.real(ln2.clone()));
                    let v = s * s.real(lambda.clone());
                    let (v2, k) = common(&v, -1);
                    let two_u = (v.int(1) - &v2) * v.int(2);
                    let far = v2 * k * ((v.real(rho.clone()) + &two_u) / two_u).log() * v.real(lambda.clone());
                    near + far
                },
                &zero,
                &s_end,
                p,
                &opts,
            )?;
            log_part.value.add(&analytic_part.value)
        }
        Quantity::Gradient => {
            let at_edge = g.at_edge;
            // cos(phi) s^2 sqrt(1-s^2) C / (eps + 2 s^2 cos(phi)) (= sqrt(1-s^2) C/2 at x = a)
            //   + lambda cos(phi) v^2 sqrt(1-v^2) C / (1 + cos(phi) - 2 v^2 cos(phi)) at v = lambda s
            integrate(
                |s| {
                    let (s2, k) = common(s, 1);
                    let cp = s.real(cos_phi.clone());
                    let near = if at_edge {
                        k * s.real(Ball::from_ratio(1, 2, s.prec()))
                    } else {
                        s2 * k * &cp / (s.real(eps.clone()) + s.sqr() * &cp * s.int(2))
                    };
                    let v = s * s.real(lambda.clone());
                    let (v2, k) = common(&v, -1);
                    let far = &v2 * k * &cp / (v.int(1) + &cp - v2 * &cp * v.int(2)) * v.real(lambda.clone());
                    near + far
                },
                &zero,
                &s_end,
                p,
                &opts,
            )?
            .value
        }
    };
    Ok(sum.mul_i64(16))
}

/// `int_0^D J0(t) I(t) dt`, certified, with an absolute tolerance `abs_tol` next
/// to the relative goal `prec`.
fn outer(kind: Quantity, g: &Geometry, prec: u32, abs_tol: f64) -> Result<Ball> {
    let mut failure: Option<Error> = None;
    let opts = Options::new().abs_tol(abs_tol.max(f64::MIN_POSITIVE))?;
    let zero = Ball::zero(g.d.prec());
    // On a box, |J0(t) I(t)| <= M e^(2 |Im t|): |J0(t)| <= e^|Im t| (DLMF 10.14.4),
    // and every kernel is >= 0 on the range (ln((rho + 2 s^2)/(2 s^2)) > 0,
    // cos(phi) s^2/(eps + 2 s^2 cos(phi)) >= 0, likewise in v) with
    // |C| = |cos((t - D) c)| <= cosh(|Im t|), |c| <= 1, so |I(t)| <= M cosh(|Im t|)
    // where M is I at C = 1, i.e. the inner integral at t = D.
    let m = inner(kind, g, &CBall::from_real(g.d.clone()))?;
    let m_upper = Ball::from_float(&m.re().abs_upper(), g.d.prec());
    let two = Ball::from_i64(2, g.d.prec());
    let r = integrate(
        |t: &HoloBall| {
            let t_ball = t.inner();
            if is_box(t_ball) {
                return t.constant(box_bound(&m_upper, &two, t_ball));
            }
            match inner(kind, g, t_ball) {
                Ok(v) => t.besselj(0) * t.constant(v),
            Err(e) => {
                    failure = Some(e);
                    t.constant(CBall::indeterminate(t.prec()))
                }
            }
        },
        &zero,
        &g.d,
        prec,
        &opts,
    );
    match r {
        Ok(r) if r.value.is_finite() => Ok(r.value.re().clone()),
        Ok(_) => Err(failure.unwrap_or(Error::Internal { what: "the Eq. 11a double integral is not finite".into() })),
        Err(e) => Err(failure.unwrap_or(e)),
    }
}

fn wave_quad_ball(kind: Quantity, a: &Ball, zeta: &Ball, amp: &Ball, x: &Ball, prec: u32) -> Result<Ball> {
    let wp = prec.saturating_add(30);
    let g = geometry(a, zeta, amp, x, prec, wp)?;
    let [a, zeta, amp] = [a, zeta, amp].map(|v| v.set_prec(wp));
    if amp.is_exact() && amp.mid().is_zero() {
        return Ok(Ball::zero(prec));
    }
    let two_pow = |bits: u32| (-(bits as f64)).exp2();
    match kind {
        Quantity::Displacement => {
            // u_w(a) = 2 A sin^2(D/2)
            let edge = g.d.mul_pow2(-1).sin().sqr().mul(&amp).mul_pow2(1);
            if g.at_edge {
                return Ok(edge);
            }
            // goal: rad <= 2^-prec |A| for the increment, i.e. 2^-prec zeta/a = 2^-prec 2 pi/D on the integral
            let tol = two_pow(prec) * 2.0 * std::f64::consts::PI / g.d.upper().to_f64();
            let integral = outer(kind, &g, prec, tol)?;
            Ok(amp.mul(&a).div(&zeta)?.mul(&integral).add(&edge))
        }
        Quantity::Gradient => {
            // goal: rad <= 2^-prec 6 |A|/zeta (the natural scale of du_w/dx)
            let integral = outer(kind, &g, prec, 6.0 * two_pow(prec))?;
            amp.div(&zeta).map(|f| f.mul(&integral))
        }
    }
}

/// Certified `u_w(x)` from the Eq. 11a double integral (module docs): a ball that
/// contains `u_w` at every point of the input balls, with `rad` about
/// `2^-prec max(|u_w|, |A|)`. `x = a` exactly is the edge value `A (1 - cos D)`.
///
/// Errors: non-finite inputs, `a <= 0` or `zeta <= 0` in a ball, `x < a` or the
/// edge `x = a` inside the balls, `2 pi a/zeta >` [`MAX_CERTIFIED_D`],
/// `prec >` [`MAX_CERTIFIED_PREC`] (typed, no panic).
pub fn u_wave_quad_ball(a: &Ball, zeta: &Ball, amp: &Ball, x: &Ball, prec: u32) -> Result<Ball> {
    wave_quad_ball(Quantity::Displacement, a, zeta, amp, x, prec)
}

/// Certified `du_w/dx` from the Eq. 11a double integral, with `rad` about
/// `2^-prec max(|du_w/dx|, 6 |A|/zeta)`; as [`u_wave_quad_ball`] (at `x = a`
/// exactly, the limit from `x > a`).
pub fn du_wave_quad_ball(a: &Ball, zeta: &Ball, amp: &Ball, x: &Ball, prec: u32) -> Result<Ball> {
    wave_quad_ball(Quantity::Gradient, a, zeta, amp, x, prec)
}

/// The wave-traction integral of Eqs. 7 and 16,
/// `K(c) = int_0^D J0(t) cos((t - D) c) dt`, certified, for balls `D > 0` and `c`:
/// the ball contains `K` at every point of the balls, with
/// `rad` about `2^-prec max(|K|, 1)`. An entire integrand: plain certified
/// Gauss-Legendre, no kernel split.
pub fn traction_integral_ball(d: &Ball, c: &Ball, prec: u32) -> Result<Ball> {
    check_prec(prec)?;
    if prec > MAX_CERTIFIED_PREC {
        return Err(Error::RoutePrecision { route: "the certified traction integral", requested: prec, max: MAX_CERTIFIED_PREC });
    }
    for (v, what) in [(d, "D"), (c, "c")] {
        if !v.is_finite() {
            return Err(Error::NonFinite { what });
        }
    }
    d.check_within("D (the traction integral)", Interval::closed(0.0, MAX_CERTIFIED_D))?;
    let wp = prec.saturating_add(20);
    let (d, c) = (d.set_prec(wp), c.set_prec(wp));
    let opts = Options::new().abs_tol((-(prec as f64)).exp2().max(f64::MIN_POSITIVE))?;
    // on a box: |J0(t)| <= e^|Im t| (DLMF 10.14.4), |cos((t - D) c)| <= e^(|c| |Im t|)
    let rate = Ball::from_float(&c.abs_upper(), wp).add_i64(1);
    let one = Ball::one(wp);
    let r = integrate(
        |t: &HoloBall| {
            if is_box(t.inner()) {
                return t.constant(box_bound(&one, &rate, t.inner()));
            }
            t.besselj(0) * ((t - t.real(d.clone())) * t.real(c.clone())).cos()
        },
        &Ball::zero(wp),
        &d,
        prec,
        &opts,
    )?;
    if !r.value.is_finite() {
        return Err(Error::Internal { what: "the traction integral is not finite".into() });
    }
    Ok(r.value.re().clone())
}

#[cfg(test)]
mod tests {
    use super::*;
    use rug::Float;

    #[test]
    fn bad_inputs_are_typed_errors() {
        let b = |v: f64| Ball::from_f64(v, 64).unwrap();
        let (a, z, m) = (b(1.0), b(1.0), b(1.0));
        assert!(matches!(u_wave_quad_ball(&a, &z, &m, &b(0.5), 64), Err(Error::ContactEdgeInBall { .. })));
        assert!(matches!(du_wave_quad_ball(&b(-1.0), &z, &m, &b(2.0), 64), Err(Error::BallOutOfRange { .. })));
        assert!(matches!(u_wave_quad_ball(&a, &b(0.0), &m, &b(2.0), 64), Err(Error::BallOutOfRange { .. })));
        assert!(matches!(u_wave_quad_ball(&a, &b(1e-3), &m, &b(2.0), 64), Err(Error::BallOutOfRange { .. })));
        assert!(matches!(u_wave_quad_ball(&a, &z, &m, &b(2.0), 5000), Err(Error::RoutePrecision { .. })));
        assert!(matches!(u_wave_quad_ball(&a, &z, &m, &b(2.0), 1), Err(_)));
        let nan = Ball::with_mag(Float::with_val(64, rug::float::Special::Nan), Mag::ZERO);
        assert!(matches!(u_wave_quad_ball(&a, &z, &m, &nan, 64), Err(Error::NonFinite { .. })));
        // the edge inside the balls
        let x = Ball::with_mag(Float::with_val(64, 1), Mag::from_f64(1e-3));
        assert!(matches!(du_wave_quad_ball(&a, &z, &m, &x, 64), Err(Error::ContactEdgeInBall { .. })));
        assert!(matches!(traction_integral_ball(&b(-1.0), &b(0.5), 64), Err(Error::BallOutOfRange { .. })));
    }
}
