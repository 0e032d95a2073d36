//! `2F1(a, b; c; z)` next to 1, one parameter tiny or `c` huge: the enclosure
//! `[1 - w, 1]` for `z < 0` (`[1, 1 + w]` for a tiny negative parameter, and for
//! `0 <= z <= 1`) from Euler's integral, at any size of the other parameter.
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
//! with `B`, `C` the upper ends of the balls of `b` and `c`.
//!
//! For `b < c < b + 1` (a tiny `c` too) the integral is split at `t = 1/2`:
//! on `[0, 1/2]`, `(1-t)^(c-b-1) <= 2^(1+b-c) <= 4`, and the part is at most
//! `4 b (1 + L) Gamma(c) / (Gamma(1+b) Gamma(c-b))`; on `[1/2, 1]`,
//! `t^(b-1) <= 2^(1-b)`, the bracket at most 1 and `int (1-t)^(c-b-1) = 2^(b-c)/(c-b)`,
//! so the part is at most `2^(1-c) b Gamma(c) / (Gamma(1+b) Gamma(c-b+1))`; with
//! `Gamma(c)/Gamma(c-b) <= max(1, c)^b` and `Gamma(c)/Gamma(c-b+1) = Gamma(c+1) /
//! (c Gamma(c+1-b)) <= (c+1)^b / c` (the same `psi` bound):
//! `w = B (C + 1)^B (4 (1 + L) + 2 / c_lo) / 0.8856`.
//!
//! Without the tiny parameter, for any `c > b > 0` (the mean of `t` under the
//! weight is `b/c`): `1 - F <= a |z| N int t^b (1-t)^(c-b-1) dt = a |z| b / c`,
//! `w = A Z B / c_lo` (a huge `c`: `2F1(4.7e16, 28.7; 5.9e4397; -96)`).
//!
//! A tiny negative parameter, `-1/2 <= b < 0`, with `c >= 1`: from
//! `F' = (ab/c) 2F1(a+1, b+1; c+1; z)` [DLMF 15.5.1], Euler's integral of that
//! function (`c + 1 > b + 1 > 0`) and `int_0^|z| (1 + s t)^(-a-1) ds =
//! (1 - (1 + |z| t)^(-a)) / (a t)`:
//! `F - 1 = (|b| Gamma(c) / (Gamma(1+b) Gamma(c-b))) int t^(b-1) (1-t)^(c-b-1) (1 - (1-zt)^(-a)) dt >= 0`,
//! and with `beta = |b|`, `(1-t)^(c-b-1) <= 1`, the bracket at most `min(1, A Z t)`,
//! `int_0^1 t^(-beta-1) min(1, A Z t) dt = e^(beta L) / (1 - beta) + (e^(beta L) - 1) / beta`,
//! `1/Gamma(1 - beta) <= 1` and `Gamma(c)/Gamma(c + beta) <= e^(-beta psi(1)) <= e^beta`
//! (`c >= 1`): `F in [1, 1 + w]`, `w = beta e^(beta (1 + L)) (1/(1 - beta) + L)`.
//! For `0 < c < 1` (`2F1(4.2e10967, -2e-5876; 9.4e-105; -1)`, issue 37's scan:
//! `Overflow`) the integral is split at `t = 1/2`: on `[0, 1/2]`,
//! `(1-t)^(c-b-1) <= 2^(1-c-beta) <= 2`, so that part is at most twice the one
//! above; on `[1/2, 1]`, `t^(-beta-1) <= 2^(beta+1)`, the bracket at most 1 and
//! `int (1-t)^(c+beta-1) = 2^(-c-beta)/(c+beta)`, at most `2/(c+beta)`; and
//! `Gamma(c)/Gamma(c+beta) = ((c+beta)/c) Gamma(c+1)/Gamma(c+1+beta) <=
//! (1 + beta/c) e^beta` (the same `psi` bound at `c + 1 >= 1`):
//! `w = beta [2 (1 + beta/c_lo) e^(beta (1 + L)) (1/(1 - beta) + L) + 2 e^beta / c_lo]`.
//!
//! For `0 <= z <= 1`, `a >= 0`, `b > 0`, `c > a + b + 1`: `1 <= (1-zt)^(-a) <=
//! (1-t)^(-a)`, so `1 <= F <= F(a, b; c; 1)`, and since `g(t) = (1-t)^(-a)` has
//! an increasing derivative, `g(t) - 1 <= t g'(t) = a t (1-t)^(-a-1)`:
//! `F(1) - 1 <= a N B(b+1, c-a-b-1) = (a b / (c-a-b-1)) F(1)` [DLMF 15.4.20 for the
//! ratio], so `F in [1, 1/(1-q)]`, `q = A B / (c_lo - A - B - 1) < 1`,
//! `w = q / (1 - q)` (`2F1(7.3e14049, 2.5e-175; 2.7e14537; 1)`).
//!
//! The smallest `w` that applies is taken; `a` and `b` are exchanged when `a` is
//! the small one (`2F1` is symmetric in them). Every quantity is rounded upward
//! (MPFR, 64 bits). The route is taken only where `w <= 2^-(prec+1)`, so that
//! the ball meets the requested precision; elsewhere the other routes run as
//! before.

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

/// `x * y` rounded up.
fn mul_up(x: &Float, y: &Float) -> Float {
    Float::with_val_round(BOUND_PREC, x * y, Round::Up).0
}

/// The width `w` of the module docs when `small` is the parameter `b` of the
/// bound, `large` the other one, and the balls meet its conditions (`b > 0`,
/// `a >= 0`, `c > b`, `z < 0`); the smallest of the bounds that apply, or `None`.
fn width(large: &Ball, small: &Ball, c: &Ball, z: &Ball) -> Option<Float> {
    if !(small.lower() > 0 && large.lower() >= 0 && z.upper() < 0) {
        return None;
    }
    let b_up = up(small.upper());
    let c_lo = Float::with_val_round(BOUND_PREC, c.lower(), Round::Down).0;
    let c_minus = Float::with_val_round(BOUND_PREC, c.lower() - small.upper(), Round::Down).0;
    if !(c_minus > 0) {
        return None;
    }
    let az = mul_up(&up(large.upper()), &up(Float::with_val(BOUND_PREC, -z.lower())));
    // the mean: A Z B / c
    let mean = Float::with_val_round(BOUND_PREC, &mul_up(&az, &b_up) / &c_lo, Round::Up).0;
    if !(b_up <= 1) {
        return mean.is_finite().then_some(mean);
    }
    let one_plus_l = Float::with_val_round(BOUND_PREC, ln_at_least_one_up(&az) + 1u32, Round::Up).0;
    let log = if c_minus >= 1 {
        // B (1 + L) max(1, C)^B / Gamma_min
        let e = mul_up(&b_up, &ln_at_least_one_up(&up(c.upper())));
        let c_pow = Float::with_val_round(BOUND_PREC, e.exp_ref(), Round::Up).0;
        mul_up(&mul_up(&b_up, &one_plus_l), &c_pow)
    } else {
        // B (C + 1)^B (4 (1 + L) + 2 / c_lo) / Gamma_min
        let c1 = Float::with_val_round(BOUND_PREC, c.upper() + 1u32, Round::Up).0;
        let e = mul_up(&b_up, &ln_at_least_one_up(&c1));
        let c_pow = Float::with_val_round(BOUND_PREC, e.exp_ref(), Round::Up).0;
        let inner = Float::with_val_round(BOUND_PREC, &one_plus_l * 4u32, Round::Up).0;
        let pole = Float::with_val_round(BOUND_PREC, 2u32 / &c_lo, Round::Up).0;
        let inner = Float::with_val_round(BOUND_PREC, &inner + &pole, Round::Up).0;
        mul_up(&mul_up(&b_up, &c_pow), &inner)
    };
    let log = Float::with_val_round(BOUND_PREC, &log / GAMMA_MIN_ON_ONE_TWO, Round::Up).0;
    let w = if mean < log { mean } else { log };
    w.is_finite().then_some(w)
}

/// The width `w` of the module docs' `[1, 1 + w]` for a tiny negative `small`
/// (`-1/2 <= b < 0`, `a >= 0`, `c > 0`, `z < 0`), or `None`.
fn width_negative(large: &Ball, small: &Ball, c: &Ball, z: &Ball) -> Option<Float> {
    if !(small.upper() < 0 && small.lower() >= -0.5 && large.lower() >= 0 && c.lower() > 0 && z.upper() < 0) {
        return None;
    }
    let beta = up(Float::with_val(BOUND_PREC, -small.lower()));
    let az = mul_up(&up(large.upper()), &up(Float::with_val(BOUND_PREC, -z.lower())));
    let l = ln_at_least_one_up(&az);
    // beta e^(beta (1 + L)) (1/(1 - beta) + L)
    let e = mul_up(&beta, &Float::with_val_round(BOUND_PREC, &l + 1u32, Round::Up).0);
    let e = Float::with_val_round(BOUND_PREC, e.exp_ref(), Round::Up).0;
    let one_minus = Float::with_val_round(BOUND_PREC, 1u32 - &beta, Round::Down).0;
    let inv = Float::with_val_round(BOUND_PREC, 1u32 / &one_minus, Round::Up).0;
    let w = mul_up(&mul_up(&beta, &e), &Float::with_val_round(BOUND_PREC, &inv + &l, Round::Up).0);
    if c.lower() >= 1 {
        return w.is_finite().then_some(w);
    }
    // 0 < c < 1 (module docs): beta [2 (1 + beta/c_lo) e^(beta(1+L)) (1/(1-beta) + L) + 2 e^beta / c_lo]
    let c_lo = Float::with_val_round(BOUND_PREC, c.lower(), Round::Down).0;
    let ratio = Float::with_val_round(BOUND_PREC, &beta / &c_lo, Round::Up).0;
    let near = mul_up(&Float::with_val_round(BOUND_PREC, &ratio + 1u32, Round::Up).0, &Float::with_val_round(BOUND_PREC, &w * 2u32, Round::Up).0);
    let e_beta = Float::with_val_round(BOUND_PREC, beta.exp_ref(), Round::Up).0;
    let far = mul_up(&mul_up(&beta, &e_beta), &Float::with_val_round(BOUND_PREC, 2u32 / &c_lo, Round::Up).0);
    let w = Float::with_val_round(BOUND_PREC, &near + &far, Round::Up).0;
    w.is_finite().then_some(w)
}

/// The width `w = q / (1 - q)`, `q = A B / (c_lo - A - B - 1)`, of the module
/// docs' `[1, 1 + w]` for `0 <= z <= 1` (`a >= 0`, `b > 0`, `c > a + b + 1` over
/// the balls, `q < 1`), or `None`.
fn width_unit(a: &Ball, b: &Ball, c: &Ball, z: &Ball) -> Option<Float> {
    if !(a.lower() >= 0 && b.lower() > 0 && z.lower() >= 0 && z.upper() <= 1) {
        return None;
    }
    let (a_up, b_up) = (up(a.upper()), up(b.upper()));
    let sum = Float::with_val_round(BOUND_PREC, &a_up + &b_up, Round::Up).0;
    let sum = Float::with_val_round(BOUND_PREC, &sum + 1u32, Round::Up).0;
    let room = Float::with_val_round(BOUND_PREC, c.lower() - &sum, Round::Down).0;
    if !(room > 0) {
        return None;
    }
    let q = Float::with_val_round(BOUND_PREC, &mul_up(&a_up, &b_up) / &room, Round::Up).0;
    let one_minus = Float::with_val_round(BOUND_PREC, 1u32 - &q, Round::Down).0;
    if !(one_minus > 0) {
        return None;
    }
    let w = Float::with_val_round(BOUND_PREC, &q / &one_minus, Round::Up).0;
    w.is_finite().then_some(w)
}

/// The enclosure `[1 - w, 1]` (or `[1, 1 + w]` for a tiny negative parameter) of
/// the module docs at `prec + 64` bits, when its conditions hold over the balls
/// and `w <= 2^-(prec+1)`; `None` otherwise.
pub(crate) fn hyp2f1_small_parameter(a: &Ball, b: &Ball, c: &Ball, z: &Ball, prec: u32) -> Option<Ball> {
    let smallest = |ws: [Option<Float>; 2]| ws.into_iter().flatten().min_by(|x, y| x.partial_cmp(y).unwrap_or(std::cmp::Ordering::Equal));
    let limit = Float::with_val(BOUND_PREC, 1) >> (prec + 1);
    let one = Float::with_val(prec + 64, 1);
    if let Some(w) = smallest([width(a, b, c, z), width(b, a, c, z)]).filter(|w| *w <= limit) {
        // [1 - w, 1]: `1 - w` rounded down at `prec + 64` bits
        let lo = Float::with_val_round(prec + 64, 1 - &w, Round::Down).0;
        return Some(Ball::hull(&lo, &one, prec + 64));
    }
    let w = smallest([width_negative(a, b, c, z), width_negative(b, a, c, z)])
        .or_else(|| width_unit(a, b, c, z))
        .filter(|w| *w <= limit)?;
    let hi = Float::with_val_round(prec + 64, 1 + &w, Round::Up).0;
    Some(Ball::hull(&one, &hi, prec + 64))
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
        // (a, b, c, z, prec, whether w is within a factor 3/2 of 1 - F)
        for (a, b, c, z, prec, tight) in [
            (100.0, tiny(20), 2.5, -20.0, 8, true),
            (100.0, tiny(80), 2.5, -20.0, 53, true),
            (3.0, tiny(40), 1.5 + tiny(40).to_f64(), -0.5, 16, true),
            (1000.0, tiny(200), 30.0, -3.0, 128, true),
            (12.5, tiny(30), 1e6, -300.0, 8, false),
            // b < c < b + 1: the split integral (w about 4.7 times 1 - F)
            (100.0, tiny(60), 0.5, -20.0, 16, false),
            (100.0, tiny(300), tiny(200).to_f64(), -20.0, 53, false),
            // c huge, b moderate: the mean bound A Z B / c
            (100.0, Float::with_val(64, 2.5), 1e30, -20.0, 53, true),
            // 0 <= z <= 1: [1, 1/(1 - q)], q = a b / (c - a - b - 1)
            (3.0, tiny(40), 10.0, 0.75, 16, false),
            (100.0, Float::with_val(64, 2.5), 1e30, 1.0, 53, true),
            // a tiny negative b: [1, 1 + w]
            (100.0, -tiny(40), 2.5, -20.0, 16, false),
            (1000.0, -tiny(200), 1.0, -3.0, 128, false),
            // a tiny negative b with 0 < c < 1: the split integral
            (1000.0, -tiny(200), 0.5, -3.0, 128, false),
            (50.0, -tiny(300), tiny(150).to_f64(), -1.0, 53, false),
        ] {
            let (ab, bb, cb, zb) = (exact(a), Ball::from_float(&b, 64), exact(c), exact(z));
            let r = hyp2f1_small_parameter(&ab, &bb, &cb, &zb, prec).unwrap_or_else(|| panic!("2F1({a}, {b}; {c}; {z}) at {prec}: not taken"));
            let other = hyp2f1_mp(&Float::with_val(64, a), &b, &Float::with_val(64, c), &Float::with_val(64, z), prec + 64).unwrap();
            assert!(r.overlaps(&other) && r.contains(other.mid()), "2F1({a}, {b}; {c}; {z}) at {prec}: {r:?} against {other:?}");
            assert!(r.meets_rel(prec), "{r:?}");
            // symmetric in a and b
            let s = hyp2f1_small_parameter(&bb, &ab, &cb, &zb, prec).unwrap();
            assert_eq!((s.mid(), s.rad()), (r.mid(), r.rad()));
            let gap = if b < 0 || z >= 0.0 { Float::with_val(64, other.lower() - 1u32) } else { Float::with_val(64, 1 - other.upper()) };
            let ulp_bound = r.rad() <= (Float::with_val(64, 1) >> (prec + 62));
            assert!(!tight || gap * 3u32 >= Float::with_val(64, r.rad() * 2u32) || ulp_bound, "2F1({a}, {b}; {c}; {z}): the bound {r:?} is loose against {other:?}");
        }
    }

    /// Outside its conditions (a negative parameter, `z >= 0`, `c <= b`, `a < 0`)
    /// or where `w` does not meet the precision, no answer.
    #[test]
    fn not_taken_outside_its_conditions() {
        let t = Ball::from_float(&(Float::with_val(64, 1) >> 100), 64);
        let neg = t.neg();
        for (a, b, c, z) in [
            // a tiny negative b with c <= 0
            (exact(1e18), neg.clone(), exact(-0.5), exact(-20.0)),
            // a negative b not tiny
            (exact(1e18), exact(-0.75), exact(2.5), exact(-20.0)),
            (exact(1e18), t.clone(), exact(2.5), exact(0.5)),
            (exact(-1e18), t.clone(), exact(2.5), exact(-20.0)),
            (exact(1e18), exact(0.5), exact(2.5), exact(-20.0)),
            // c below b
            (exact(1e18), t.clone(), Ball::from_float(&(Float::with_val(64, 1) >> 101), 64), exact(-20.0)),
        ] {
            assert!(hyp2f1_small_parameter(&a, &b, &c, &z, 53).is_none(), "{a:?} {b:?} {c:?} {z:?}");
        }
        // 2^-100 (1 + ln(2e19)) / 0.8856 is about 2^-94.4: at 90 bits, not at 100
        assert!(hyp2f1_small_parameter(&exact(1e18), &t, &exact(2.5), &exact(-20.0), 90).is_some());
        assert!(hyp2f1_small_parameter(&exact(1e18), &t, &exact(2.5), &exact(-20.0), 100).is_none());
    }
}
