//! Sums with oscillatory terms to infinity: `int_a^inf (1 - cos x)/x^2 dx`, where the
//! oscillatory factor is not a factor of the whole integrand but of a term of it.
//!
//! # Method
//!
//! *Terms.* The integrand is written as a sum of signed terms by the identities `(u +-
//! v)/d = u/d +- v/d`, `(u +- v) m = u m +- v m` (and `m (u +- v)`), `-(u +- v) = -u -+
//! v`, and `sin(u)^2 = 1/2 - cos(2u)/2`, `cos(u)^2 = 1/2 + cos(2u)/2` (identities on
//! the whole complex plane), applied while the count stays at most [`MAX_TERMS`]:
//! `(1 - cos x)/x^2 = 1/x^2 - cos(x)/x^2`, `sin(x)^2/x^2 = (1/2)/x^2 - (1/2)
//! cos(2x)/x^2`. A term that `oscillatory.rs` recognises (a factor `sin(w x + phi)`,
//! `cos(w x + phi)` or `besselj(n, w x)` and a sector class of the rest with `q + e <
//! 0`) is an *oscillatory term* `t_i`; the others, summed, are the *rest* `r`, which must
//! have a decay class (`decay.rs`: an absolutely integrable tail). At least one term
//! must be oscillatory, and there must be at least two terms; otherwise the rule does
//! not apply and the integrand takes the other routes.
//!
//! *Split.* `T` is the least power of two `>= a + 1` and `>= p + 1` for every singular
//! candidate `p` of every term (`local.rs`: zeros of affine subtrees under `/`, negative
//! or fractional powers, `log`, `sqrt`). Then
//!
//! ```text
//! int_a^inf f = int_a^T f + int_T^inf r + sum_i int_T^inf t_i.
//! ```
//!
//! `int_a^T f` is integrated term by term when every term's finite part is certified
//! (`sin(x)/x + 1/(1+x^2)`: the removable point of `sin(x)/x` is then found by
//! `removable.rs`, which sees quotients only), else summand by summand as typed (the
//! folded `(1 - cos x)/x^2 + (1 - cos(-x))/(-x)^2` of a range `(-inf, inf)`), and
//! otherwise as the whole integrand, by
//! the finite route: a singularity the terms have and the sum has not (`1/x^2` and
//! `cos(x)/x^2` at 0, where `(1 - cos x)/x^2 -> 1/2`) is the sum's removable point there
//! (`removable.rs`), never a term's pole; a term's pole is refused by its local class
//! before any evaluation. `int_T^inf r` takes the routes of a non-oscillatory tail
//! (`integrate.rs`: decay class, or `u = 1/x`), and each `int_T^inf t_i` the contour
//! rotation of `oscillatory.rs` from `T`.
//!
//! *Proof.* For `X > T`, `int_T^X f = int_T^X r + sum_i int_T^X t_i` (a finite sum of
//! integrals of functions continuous on `[T, X]`: no term has a singular candidate
//! there, and a singular point that is no candidate is one the certified integrator
//! cannot bound, an error and never a ball). As `X -> inf` each term on the right converges: `r`
//! absolutely, by its class; each `t_i` by the rotation's proof, which shows the
//! far sides of the contour vanish and the ray integral converge. So the left side
//! converges to the sum of the limits. Each piece is a certified ball; the sum is
//! checked against the goal and the pieces redone with more bits when cancellation
//! between them misses it (`finite.rs`, `sum_to_goal`).

use rug::{Float, Rational};

use super::decay::{tail_class, TailClass};
use super::finite::{integrate_finite, sum_to_goal};
use super::local::{local_class, singular_candidates};
use super::oscillatory::{integrate_oscillatory, plan};
use super::tree::{Expr, Function};
use crate::ball::{Ball, Decimal};
use crate::error::{Error, IntegrationError, Result};
use crate::quad::certified::{integrate, HoloBall, Integral, Options};

/// Most terms a sum is expanded into (the expansion multiplies them out: beyond this
/// the rule does not apply).
const MAX_TERMS: usize = 16;

/// Largest `j` tried for `T = 2^j`.
const MAX_LOG2_T: u32 = 40;

/// Precision of `T` (a power of two: exact at any precision).
const P: u32 = 64;

/// The signed terms of `e` (`true`: negated), or `None` past [`MAX_TERMS`]: sums and
/// differences flattened, quotients and products with a sum multiplied out, and
/// `sin(u)^2 = 1/2 - cos(2u)/2`, `cos(u)^2 = 1/2 + cos(2u)/2`.
fn terms(e: &Expr, negated: bool, out: &mut Vec<(Expr, bool)>) -> Option<()> {
    let half = || Expr::Number(Decimal::from_rational(Rational::from((1, 2))));
    match e {
        Expr::Add(a, b) => {
            terms(a, negated, out)?;
            terms(b, negated, out)?;
        }
        Expr::Sub(a, b) => {
            terms(a, negated, out)?;
            terms(b, !negated, out)?;
        }
        Expr::Neg(a) => terms(a, !negated, out)?,
        Expr::Div(n, d) => {
            let mut inner = Vec::new();
            terms(n, negated, &mut inner)?;
            if inner.len() == 1 {
                out.push((e.clone(), negated));
            } else {
                out.extend(inner.into_iter().map(|(t, s)| (Expr::Div(Box::new(t), d.clone()), s)));
            }
        }
        Expr::Mul(a, b) => {
            let (mut ta, mut tb) = (Vec::new(), Vec::new());
            terms(a, negated, &mut ta)?;
            terms(b, false, &mut tb)?;
            if ta.len() * tb.len() == 1 {
                out.push((e.clone(), negated));
            } else {
                if out.len() + ta.len() * tb.len() > MAX_TERMS {
                    return None;
                }
                for (u, su) in &ta {
                    for (v, sv) in &tb {
                        out.push((Expr::Mul(Box::new(u.clone()), Box::new(v.clone())), su ^ sv));
                    }
                }
            }
        }
        Expr::PowInt(base, 2) => match &**base {
            Expr::Call(f @ (Function::Sin | Function::Cos), u) => {
                let two_u = Expr::Mul(Box::new(Expr::Number(Decimal::from_rational(Rational::from(2)))), u.clone());
                let cos_2u = Expr::Mul(Box::new(half()), Box::new(Expr::Call(Function::Cos, Box::new(two_u))));
                out.push((half(), negated));
                out.push((cos_2u, negated ^ (*f == Function::Sin)));
            }
            _ => out.push((e.clone(), negated)),
        },
        other => out.push((other.clone(), negated)),
    }
    (out.len() <= MAX_TERMS).then_some(())
}

/// The summands of `e` as typed: sums, differences and signs flattened, nothing
/// multiplied out.
fn summands(e: &Expr, negated: bool, out: &mut Vec<Expr>) {
    match e {
        Expr::Add(a, b) => {
            summands(a, negated, out);
            summands(b, negated, out);
        }
        Expr::Sub(a, b) => {
            summands(a, negated, out);
            summands(b, !negated, out);
        }
        Expr::Neg(a) => summands(a, !negated, out),
        other => out.push(signed(other.clone(), negated)),
    }
}

/// Whether `e` is a sum or a difference (under signs).
fn is_sum(e: &Expr) -> bool {
    match e {
        Expr::Add(..) | Expr::Sub(..) => true,
        Expr::Neg(a) => is_sum(a),
        _ => false,
    }
}

fn signed(t: Expr, negated: bool) -> Expr {
    if negated {
        Expr::Neg(Box::new(t))
    } else {
        t
    }
}

/// The tail route of a non-oscillatory integrand from `T` (`integrate.rs`'s
/// `to_infinity`, passed in: this file sits below it).
pub(crate) type RestTail<'a> = dyn Fn(&Expr, &Ball, u32, &Options) -> Result<Integral> + 'a;

/// `int_a^inf f` for a sum with oscillatory terms (module docs): `None` when the rule
/// does not apply.
pub(crate) fn integrate_oscillatory_sum(f: &Expr, a: &Ball, prec: u32, opts: &Options, rest_tail: &RestTail<'_>) -> Option<Result<Integral>> {
    if !is_sum(f) && !matches!(f, Expr::Div(..) | Expr::Mul(..)) {
        return None;
    }
    let mut all = Vec::new();
    terms(f, false, &mut all)?;
    if all.len() < 2 {
        return None;
    }
    // T: a power of two past a and every term's singular candidates
    let mut candidates = Vec::new();
    for (t, _) in &all {
        singular_candidates(t, &mut candidates);
    }
    let beyond = candidates.iter().map(Rational::to_f64).fold(a.upper().to_f64(), f64::max) + 1.0;
    if !beyond.is_finite() {
        return None;
    }
    let j = (0..=MAX_LOG2_T).find(|&j| (1u64 << j) as f64 >= beyond)?;
    let t = Ball::from_float(&(Float::with_val(P, 1) << j), P);
    let (mut oscillatory, mut rest) = (Vec::new(), None::<Expr>);
    for (term, negated) in all {
        let term = signed(term, negated);
        if matches!(plan(&term, &t, prec), Some(Ok(_))) {
            oscillatory.push(term);
        } else {
            rest = Some(match rest {
                None => term,
                Some(r) => Expr::Add(Box::new(r), Box::new(term)),
            });
        }
    }
    if oscillatory.is_empty() {
        return None;
    }
    if let Some(r) = &rest {
        if !matches!(tail_class(r), TailClass::Decays { .. }) {
            return None;
        }
    }
    let t_rational = Rational::from(1u64 << j);
    let each: Vec<Expr> = oscillatory.iter().cloned().chain(rest.clone()).collect();
    let mut typed = Vec::new();
    summands(f, false, &mut typed);
    Some(sum_to_goal(prec, opts, |goal, o| {
        let mut out = match a.mid().to_rational() {
            Some(ar) if a.is_exact() => match finite_by_terms(&each, &ar, &t_rational, goal, o)? {
                Some(parts) => parts,
                None => match typed.len() > 1 {
                    true => finite_by_terms(&typed, &ar, &t_rational, goal, o)?,
                    false => None,
                }
                .map_or_else(|| integrate_finite(f, &ar, &t_rational, goal + 64, goal, o).map(|r| vec![r]), Ok)?,
            },
            _ => vec![integrate(|x: &HoloBall| f.eval(x), a, &t, goal, o)?],
        };
        if let Some(r) = &rest {
            out.push(rest_tail(r, &t, goal, o)?);
        }
        for term in &oscillatory {
            let r = integrate_oscillatory(term, &t, goal, o)
                .unwrap_or(Err(Error::Internal { what: "an oscillatory term recognised once was not the second time".into() }))?;
            out.push(r);
        }
        Ok(out)
    }))
}

/// `int_a^T` term by term, when every term's finite part meets its goal: a removable
/// point of a term that is a quotient (`sin(x)/x` in `sin(x)/x + 1/(1+x^2)`) is then
/// found by `removable.rs`, which sees only quotients, and not mapped as a singular end
/// of the sum. `None` (the sum is integrated whole) when a term is not integrable on
/// `[a, T]` (`1/x^2` in `(1 - cos x)/x^2`: its local class at 0 is `q = -2`, found
/// before any evaluation), has a singular candidate without a local class there, or
/// misses its goal.
fn finite_by_terms(terms: &[Expr], a: &Rational, t: &Rational, goal: u32, o: &Options) -> Result<Option<Vec<Integral>>> {
    // Before any work: every singular candidate of every term in [a, T] must have an
    // integrable local class (`q > -1`) on the sides the range extends to, or a term
    // could spend its evaluation limit before it fails.
    let delta = Rational::from((1, 2));
    for term in terms {
        let mut candidates = Vec::new();
        singular_candidates(term, &mut candidates);
        for p in candidates.iter().filter(|p| *p >= a && *p <= t) {
            for sigma in [1i64, -1] {
                if (sigma > 0 && p == t) || (sigma < 0 && p == a) {
                    continue;
                }
                if !local_class(term, p, sigma, &delta).is_some_and(|c| c.power > -1) {
                    return Ok(None);
                }
            }
        }
    }
    let mut out = Vec::new();
    for term in terms {
        match integrate_finite(term, a, t, goal + 64, goal, o) {
            Ok(r) if r.goal_met => out.push(r),
            Ok(_) | Err(Error::Integration(IntegrationError::NotIntegrable { .. })) => return Ok(None),
            Err(e) => return Err(e),
        }
    }
    Ok(Some(out))
}
