//! `2F1(a, b; c; z)` with one parameter tiny and positive, for `z < 0`: the
//! enclosure `[1 - w, 1]` from Euler's integral, at any size of the other
//! parameter.
//!
//! # Why
//!
//! At `a` of `10^17` to `10^31874`, `b` of `10^-20` and less, moderate or huge
//! `c` and `z < -1` (issue 37's scan: about 50 inputs a seed) the value is
//! `1 - O(b ln(a |z|))`, while every other route meets a quantity past the
//! exponent range or a pole: Pfaff's prefactor `(1-z)^(-a)` and its inner
//! function, the connection formula's `Gamma(b - a)` with `b - a` within `b` of
//! the integer `-a` (a ball at the working precision holds it), and for a decimal
//! `a` like `1.5e31874` (74 000 bits of mantissa) an input ball that holds
//! thousands of the connection formula's poles. They were refused as `Overflow`.
//!
//! # Method and bound
//!
//! For `c > b > 0` and `z < 1` [DLMF 15.6.1],
//! `F = N int_0^1 t^(b-1) (1-t)^(c-b-1) (1-zt)^(-a) dt`, `N = Gamma(c)/(Gamma(b) Gamma(c-b))`,
//! a positive weight of integral 1. With `a >= 0` and `z < 0`, `1 - zt >= 1`, so
//! `0 <= 1 - (1-zt)^(-a) <= min(1, a ln(1 + |z| t)) <= min(1, a |z| t)`, and
//! `0 <= 1 - F`. With `c - b >= 1` also `(1-t)^(c-b-1) <= 1`; with `A >= a`,
//! `Z >= |z|`, `L = ln max(1, A Z)` and `eps = e^-L`:
//!
//! `1 - F <= N (A Z int_0^eps t^b dt + int_eps^1 t^(b-1) dt)
//!        = N (eps^b / (b+1) + (1 - eps^b) / b)
//!        <= Gamma(c) / (Gamma(1+b) Gamma(c-b)) (b + b L)`
//!
//! (`N = b Gamma(c)/(Gamma(1+b) Gamma(c-b))`, `1 - e^(-bL) <= bL`). Finally
//! `ln Gamma(c) - ln Gamma(c-b) = int_(c-b)^c psi <= b psi(c) < b ln c` for `c > b > 0`
//! (`psi` increases, and `psi(x) < ln x - 1/(2x)` for `x > 0` [Alzer, Math. Comp. 66
//! (1997), 373-389, the case `n = 0`]), and `Gamma(1+b) >= 0.8856` on `0 < b <= 1`
//! (the minimum of `Gamma` on `[1, 2]`, `0.885603...` at `1.4616...`). So over all
//! the input balls
//!
//! `F in [1 - w, 1]`, `w = B (1 + L) max(1, C)^B / 0.8856`,
//!
//! with `B`, `C` the upper ends of the balls of `b` and `c`; `a` and `b` are
//! exchanged when `a` is the tiny one (`2F1` is symmetric in them). Every
//! quantity is rounded upward (MPFR, 64 bits). The route is taken only where
//! `w <= 2^-(prec+1)`, so that the ball meets the requested precision; elsewhere
//! the other routes run as before.

use rug::float::Round;
use rug::Float;

use crate::ball::Ball;

/// Precision of the bound's arithmetic (every step rounded upward).
const BOUND_PREC: u32 = 64;

/// A lower bound of `min Gamma(x)` over `1 <= x <= 2` (`0.8856031944...`).
const GAMMA_MIN_ON_ONE_TWO: f64 = 0.8856;

fn up(x: Float) -> Float {
    Float::with_val_round(BOUND_PREC, &x, Round::Up).0
}

/// `ln max(1, x)` rounded up, for `x >= 0`.
fn ln_at_least_one_up(x: &Float) -> Float {
    if *x <= 1 {
        return Float::new(BOUND_PREC);
    }
    Float::with_val_round(BOUND_PREC, x.ln_ref(), Round::Up).0
}

/// The width `w` of the module docs when `small` is the tiny parameter, `large`
/// the other one, and the balls meet the conditions (`small` in `(0, 1]`, `large
/// >= 0`, `c - small >= 1`, `z < 0`); `None` otherwise.
fn width(large: &Ball, small: &Ball, c: &Ball, z: &Ball) -> Option<Float> {
    if !(small.lower() > 0 && small.upper() <= 1 && large.lower() >= 0 && z.upper() < 0) {
        return None;
    }
    let c_minus = Float::with_val_round(BOUND_PREC, c.lower() - small.upper(), Round::Down).0;
    if !(c_minus >= 1) {
        return None;
    }
    let b_up = up(small.upper());
    let az = Float::with_val_round(BOUND_PREC, large.upper() * Float::with_val(BOUND_PREC, -z.lower()), Round::Up).0;
    let l = ln_at_least_one_up(&az);
    let c_pow = {
        let e = Float::with_val_round(BOUND_PREC, &b_up * ln_at_least_one_up(&up(c.upper())), Round::Up).0;
        Float::with_val_round(BOUND_PREC, e.exp_ref(), Round::Up).0
    };
    let one_plus_l = Float::with_val_round(BOUND_PREC, &l + 1u32, Round::Up).0;
    let w = Float::with_val_round(BOUND_PREC, &b_up * &one_plus_l, Round::Up).0;
    let w = Float::with_val_round(BOUND_PREC, &w * &c_pow, Round::Up).0;
    let w = Float::with_val_round(BOUND_PREC, &w / GAMMA_MIN_ON_ONE_TWO, Round::Up).0;
    w.is_finite().then_some(w)
}

/// The enclosure `[1 - w, 1]` of the module docs at `prec` bits, when one of `a`,
/// `b` is tiny and positive over its ball, the other non-negative, `c` at least
/// one above the tiny one and `z < 0`, and `w <= 2^-(prec+1)`; `None` otherwise.
pub(crate) fn hyp2f1_small_parameter(a: &Ball, b: &Ball, c: &Ball, z: &Ball, prec: u32) -> Option<Ball> {
    let w = [width(a, b, c, z), width(b, a, c, z)].into_iter().flatten().min_by(|x, y| x.partial_cmp(y).unwrap_or(std::cmp::Ordering::Equal))?;
    let limit = Float::with_val(BOUND_PREC, 1) >> (prec + 1);
    if w > limit {
        return None;
    }
    // [1 - w, 1]: `1 - w` rounded down at `prec + 64` bits
    let lo = Float::with_val_round(prec + 64, 1 - &w, Round::Down).0;
    Some(Ball::hull(&lo, &Float::with_val(prec + 64, 1), prec + 64))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::special::hyp2f1::hyp2f1_mp;

    fn exact(x: f64) -> Ball {
        Ball::from_float(&Float::with_val(64, x), 64)
    }

    /// Where the route is taken, its ball holds the certified value of the other
    /// routes at the same binary inputs (at moderate `a`, where they answer), and
    /// its lower end is not loose by more than the bound's factor: the value's
    /// distance to 1 is at least a third of `w` (unless the ball is one ulp of its
    /// midpoint at `prec + 64` bits, wider than `w`).
    #[test]
    fn encloses_the_other_routes_value() {
        let tiny = |e: i32| Float::with_val(64, 1) >> e;
        for (a, b, c, z, prec) in [
            (100.0, tiny(20), 2.5, -20.0, 8),
            (100.0, tiny(80), 2.5, -20.0, 53),
            (3.0, tiny(40), 1.5 + tiny(40).to_f64(), -0.5, 16),
            (1000.0, tiny(200), 30.0, -3.0, 128),
            (12.5, tiny(30), 1e6, -300.0, 8),
        ] {
            let (ab, bb, cb, zb) = (exact(a), Ball::from_float(&b, 64), exact(c), exact(z));
            let r = hyp2f1_small_parameter(&ab, &bb, &cb, &zb, prec).unwrap_or_else(|| panic!("2F1({a}, {b}; {c}; {z}) at {prec}: not taken"));
            let other = hyp2f1_mp(&Float::with_val(64, a), &b, &Float::with_val(64, c), &Float::with_val(64, z), prec + 64).unwrap();
            assert!(r.overlaps(&other) && r.contains(other.mid()), "2F1({a}, {b}; {c}; {z}) at {prec}: {r:?} against {other:?}");
            assert!(r.meets_rel(prec), "{r:?}");
            // symmetric in a and b
            let s = hyp2f1_small_parameter(&bb, &ab, &cb, &zb, prec).unwrap();
            assert_eq!((s.mid(), s.rad()), (r.mid(), r.rad()));
            let gap = Float::with_val(64, 1 - other.upper());
            let ulp_bound = r.rad() <= (Float::with_val(64, 1) >> (prec + 62));
            assert!(gap * 3u32 >= Float::with_val(64, r.rad() * 2u32) || c > 1e5 || ulp_bound, "2F1({a}, {b}; {c}; {z}): the bound {r:?} is loose against {other:?}");
        }
    }

    /// Outside its conditions (a negative or not tiny parameter, `z >= 0`,
    /// `c < b + 1`, `a < 0`) or where `w` does not meet the precision, no answer.
    #[test]
    fn not_taken_outside_its_conditions() {
        let t = Ball::from_float(&(Float::with_val(64, 1) >> 100), 64);
        let neg = t.neg();
        for (a, b, c, z) in [
            (exact(1e18), neg.clone(), exact(2.5), exact(-20.0)),
            (exact(1e18), t.clone(), exact(2.5), exact(0.5)),
            (exact(1e18), t.clone(), exact(0.5), exact(-20.0)),
            (exact(-1e18), t.clone(), exact(2.5), exact(-20.0)),
            (exact(1e18), exact(0.5), exact(2.5), exact(-20.0)),
        ] {
            assert!(hyp2f1_small_parameter(&a, &b, &c, &z, 53).is_none(), "{a:?} {b:?} {c:?} {z:?}");
        }
        // 2^-100 (1 + ln(2e19)) / 0.8856 is about 2^-94.4: at 90 bits, not at 100
        assert!(hyp2f1_small_parameter(&exact(1e18), &t, &exact(2.5), &exact(-20.0), 90).is_some());
        assert!(hyp2f1_small_parameter(&exact(1e18), &t, &exact(2.5), &exact(-20.0), 100).is_none());
    }
}
