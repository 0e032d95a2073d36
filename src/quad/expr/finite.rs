//! Finite ranges whose singular points are found from the expression (issue 40): the
//! range is split at candidate points, and each singular end is integrated in its local
//! variable with the bound of its local class (`local.rs`), or, for fractional powers
//! of affine factors, as a weight.

use rug::{Float, Rational};

use super::decay::const_rational;
use super::local::{affine, factors, local_class, singular_candidates};
use super::removable::{atan_reciprocals_rewritten, removable_point};
use super::tree::{Expr, Function};
use crate::ball::{CBall, Decimal};
use crate::error::{Error, IntegrationError, Result};
use crate::quad::certified::{integrate, integrate_segments, integrate_weighted, EndBound, Integral, Options, Weight};

/// `int_a^b f` for rational ends, with the singular points of `f` in `[a, b]` found from
/// the expression (`local.rs`): a candidate point (a zero of an affine subtree that is
/// divided by, raised to a fractional or negative power, or under `log` / `sqrt`) splits
/// the range, and each end where the integrand is singular gets its local class: an
/// integrable one (`|f| <= C t^q`, `q > -1`) is mapped exponentially with the class as
/// its tail bound; a pole or worse (`q <= -1`) is [`IntegrationError::NotIntegrable`]
/// naming the point.
pub(crate) fn integrate_finite(f: &Expr, a: &Rational, b: &Rational, ip: u32, prec: u32, opts: &Options) -> Result<Integral> {
    let to_ball = |q: &Rational| Decimal::from_rational(q.clone()).to_ball(ip);
    let g = |x: &_| f.eval(x);
    if a == b {
        return integrate(g, &to_ball(a), &to_ball(b), prec, opts);
    }
    let (lo, hi, flip) = if a < b { (a, b, false) } else { (b, a, true) };
    if let Some(g) = atan_reciprocals_rewritten(f, lo, hi) {
        let mut r = integrate_finite(&g, lo, hi, ip, prec, opts)?;
        if flip {
            r.value = r.value.neg();
        }
        return Ok(r);
    }
    let mut candidates = Vec::new();
    singular_candidates(f, &mut candidates);
    let finite_at = |p: &Rational| f.eval(&CBall::from_real(to_ball(p))).is_finite();
    let singular = |p: &Rational| candidates.contains(p) || !finite_at(p);
    // a quotient whose only candidate point is removable (`sin(x)/x`): enclosed on
    // every box, the point's included, and integrated in one piece (`removable.rs`)
    let inside: Vec<&Rational> = candidates.iter().filter(|p| *p >= lo && *p <= hi).collect();
    if inside.len() == 1 {
        if let Some(rem) = removable_point(f, lo, hi).filter(|r| r.point() == inside[0]) {
            if let Ok(mut r) = integrate(|x: &_| rem.eval(x), &to_ball(lo), &to_ball(hi), prec, opts) {
                if r.goal_met {
                    if flip {
                        r.value = r.value.neg();
                    }
                    return Ok(r);
                }
            }
        }
    }
    let mut points = vec![lo.clone()];
    let mut interior: Vec<Rational> = candidates.iter().filter(|p| *p > lo && *p < hi).cloned().collect();
    interior.sort();
    points.extend(interior);
    points.push(hi.clone());
    let mut ends = Vec::new();
    let mut any = false;
    for w in points.windows(2) {
        let half = Rational::from(&w[1] - &w[0]) / 2u32;
        // delta: a power of 2 at most min(1/2, half the segment)
        let mut delta = Rational::from((1, 2));
        while delta > half {
            delta /= 2u32;
        }
        let mut pair = [None, None];
        for (k, (p, sigma)) in [(&w[0], 1i64), (&w[1], -1i64)].into_iter().enumerate() {
            if !singular(p) {
                continue;
            }
            if let Some(c) = local_class(f, p, sigma, &delta) {
                if c.power <= -1 {
                    return Err(Error::Integration(IntegrationError::NotIntegrable { near: p.to_f64(), evaluations: 0 }));
                }
                let delta_f = Float::with_val(64, delta.to_f64());
                pair[k] = Some(EndBound { power: to_ball(&c.power), bound: c.coef.abs_upper_mag(), delta: delta_f });
                any = true;
            }
        }
        let [l, r] = pair;
        ends.push((l, r));
    }
    if any && points.len() == 2 {
        // fractional powers of affine factors vanishing at an end, and `log(x - a)`: a
        // declared weight in all but name (faster: the rest is analytic there)
        if let Some((g_rest, alpha, beta, logs)) = weight_split(f, lo, hi) {
            let w = Weight::new(to_ball(&alpha), to_ball(&beta), logs)?;
            let r = integrate_weighted(|x: &_| g_rest.eval(x), &to_ball(lo), &to_ball(hi), &w, prec, opts);
            if let Ok(mut r) = r {
                if flip {
                    r.value = r.value.neg();
                }
                return Ok(r);
            }
        }
    }
    let mut result = if !any && points.len() == 2 {
        integrate(g, &to_ball(lo), &to_ball(hi), prec, opts)?
    } else {
        singular_pieces(f, &points, &ends, ip, prec, opts)?
    };
    if flip {
        result.value = result.value.neg();
    }
    Ok(result)
}

/// The pieces of a range split at singular points, summed: next to each singular end
/// `p` (side `sigma`) the piece `int_0^{delta/2} f(p + sigma t) dt`, with `f(p + sigma t)`
/// written in `t` and its affine subtrees folded exactly ([`Expr::shifted`]: `1 - x` at
/// `x = 1 - t` is `t`, with no cancellation however small `t`), as a weight at `t = 0`
/// when [`weight_split`] finds one (`log(x) log(1 - x)` on `[0, 1]` becomes `log t` times
/// an analytic rest at each end), else mapped at `t = 0`; the regular middles as they
/// are. The sum is checked against the goal and the pieces
/// redone with more bits when it misses.
fn singular_pieces(f: &Expr, points: &[Rational], ends: &[(Option<EndBound>, Option<EndBound>)], ip: u32, prec: u32, opts: &Options) -> Result<Integral> {
    let to_ball = |q: &Rational| Decimal::from_rational(q.clone()).to_ball(ip);
    // (expression, lo, hi, singular left end, the weight form of that end)
    let mut pieces: Vec<(Expr, Rational, Rational, Option<EndBound>, Option<(Expr, Weight)>)> = Vec::new();
    for (w, (left, right)) in points.windows(2).zip(ends) {
        let mut lo = w[0].clone();
        let mut hi = w[1].clone();
        for (end, p, sigma) in [(left, &w[0], 1i64), (right, &w[1], -1i64)] {
            if let Some(eb) = end {
                let half = Rational::from(eb.delta.to_rational().unwrap_or_default() / 2u32);
                let e = f.shifted(p, sigma);
                let weighted = weight_split(&e, &Rational::new(), &half).and_then(|(g, alpha, beta, logs)| {
                    Weight::new(to_ball(&alpha), to_ball(&beta), logs).ok().map(|w| (g, w))
                });
                pieces.push((e, Rational::new(), half.clone(), Some(eb.clone()), weighted));
                if sigma > 0 {
                    lo = Rational::from(&lo + &half);
                } else {
                    hi = Rational::from(&hi - &half);
                }
            }
        }
        if lo < hi {
            pieces.push((f.clone(), lo, hi, None, None));
        }
    }
    sum_to_goal(prec, opts, |goal, o| {
        let mut out = Vec::new();
        for (e, lo, hi, end, weighted) in &pieces {
            let g = |x: &_| e.eval(x);
            let by_weight = weighted.as_ref().and_then(|(rest, w)| integrate_weighted(|x: &_| rest.eval(x), &to_ball(lo), &to_ball(hi), w, goal, o).ok());
            out.push(match (by_weight, end) {
                (Some(r), _) => r,
                (None, Some(eb)) => integrate_segments(g, vec![to_ball(lo), to_ball(hi)], vec![(Some(eb.clone()), None)], goal, o)?,
                (None, None) => integrate(g, &to_ball(lo), &to_ball(hi), goal, o)?,
            });
        }
        Ok(out)
    })
}

/// Pieces whose sum is the integral, each certified for a goal: the goal starts 8 bits
/// above `prec` and is raised by the bits the sum misses (cancellation between pieces),
/// at most four attempts; a piece stopped by a limit stops the run, flagged.
pub(crate) fn sum_to_goal<P>(prec: u32, opts: &Options, mut pieces: P) -> Result<Integral>
where
    P: FnMut(u32, &Options) -> Result<Vec<Integral>>,
{
    let mut extra = 8u32;
    let mut last = None;
    for _ in 0..4 {
        let goal = (prec + extra).min(crate::MAX_PREC);
        let o = opts.clone().goal_bits(goal)?;
        let parts = pieces(goal, &o)?;
        let (mut evaluations, mut limit, mut wp, mut l1) = (0, None, 0, crate::ball::Mag::ZERO);
        let mut total = crate::ball::CBall::zero(prec);
        for r in &parts {
            evaluations += r.evaluations;
            limit = limit.or(r.limit);
            wp = wp.max(r.working_prec);
            total = total.add(&r.value);
            l1 = l1.add(r.abs_scale);
        }
        let rad = total.rad_mag();
        let wanted = total.abs_lower_mag().mul_2exp(-(prec as i64));
        let (met, abs_tol) = crate::quad::certified::meets(&total, prec, opts, l1);
        let result = Integral { value: total, goal_met: met, limit: if met { None } else { limit }, evaluations, subintervals: 0, working_prec: wp, abs_scale: l1, abs_tol };
        if met || limit.is_some() {
            return Ok(result);
        }
        let missing = if wanted.is_zero() { 32.0 } else { (rad.log2() - wanted.log2()).clamp(1.0, 1e4) };
        extra += missing.ceil() as u32 + 4;
        last = Some(result);
    }
    last.ok_or(Error::Internal { what: "no attempt at the pieces of an integral".into() })
}

/// `f = (x-a)^alpha (b-x)^beta log^k(x-a) g`, from the factors of `f` that are
/// fractional powers (`u^r`, `sqrt(u)`) of an affine `u` vanishing at `a` (`u = c (x -
/// a)`, `c > 0`) or at `b` (`u = c (b - x)`, `c > 0`), and `log(u)` with `u = x - a`
/// exactly (in the numerator; `log(c (x - a))` for `c != 1` is a sum, left to the mapped
/// route): `c^r` stays in `g`. `None` when there is no such factor, an exponent is not
/// `> -1`, or there are more logs than a weight takes.
fn weight_split(f: &Expr, a: &Rational, b: &Rational) -> Option<(Expr, Rational, Rational, u32)> {
    let (mut num, mut den, mut negative) = (Vec::new(), Vec::new(), false);
    factors(f, false, &mut num, &mut den, &mut negative);
    let (mut alpha, mut beta) = (Rational::new(), Rational::new());
    let number = |q: Rational| Expr::Number(Decimal::from_rational(q));
    let mut rest: Vec<Expr> = Vec::new();
    let mut found = false;
    let mut logs = 0u32;
    for (e, sign) in num.iter().map(|e| (e, 1i32)).chain(den.iter().map(|e| (e, -1i32))) {
        let power = match e {
            Expr::Pow(u, r) => const_rational(r).filter(|r| *r.denom() != 1).map(|r| (u, r)),
            Expr::Call(Function::Sqrt, u) => Some((u, Rational::from((1, 2)))),
            _ => None,
        };
        let mut taken = false;
        if let (Expr::Call(Function::Log, u), 1) = (e, sign) {
            if let Some((c0, c1)) = affine(u) {
                if c1 == 1 && Rational::from(&c0 + a) == 0 {
                    logs += 1;
                    taken = true;
                }
            }
        }
        if let Some((u, r)) = power {
            if let Some((c0, c1)) = affine(u) {
                let r = Rational::from(&r * sign);
                let at = |p: &Rational| Rational::from(&c0 + Rational::from(&c1 * p)) == 0;
                if c1 > 0 && at(a) {
                    alpha += &r;
                    rest.push(Expr::Pow(Box::new(number(c1.clone())), Box::new(number(r))));
                    taken = true;
                } else if c1 < 0 && at(b) {
                    beta += &r;
                    rest.push(Expr::Pow(Box::new(number(Rational::from(-&c1))), Box::new(number(r))));
                    taken = true;
                }
            }
        }
        found |= taken;
        if !taken {
            rest.push(if sign > 0 { e.clone() } else { Expr::Div(Box::new(number(Rational::from(1))), Box::new(e.clone())) });
        }
    }
    if !found || alpha <= -1 || beta <= -1 || logs > Weight::MAX_LOG_POWER {
        return None;
    }
    let g = rest.into_iter().fold(number(Rational::from(1)), |acc, e| Expr::Mul(Box::new(acc), Box::new(e)));
    // the rest must be regular at both ends (`log(x) log(1 - x)` on `[0, 1]` is not a
    // weight at 0 times a regular rest: it is split at its singular points instead)
    let mut candidates = Vec::new();
    singular_candidates(&g, &mut candidates);
    if candidates.iter().any(|p| p == a || p == b) {
        return None;
    }
    let mut g = g;
    if negative {
        g = Expr::Neg(Box::new(g));
    }
    Some((g, alpha, beta, logs))
}

