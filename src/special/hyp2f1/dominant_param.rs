//! `2F1(a, b; c; z)` for `z < 0` when `a |z|` dwarfs `c` and `b |z|` (two large
//! parameters, `a >> c`), over balls.
//!
//! # Why
//!
//! `2F1(2.7e24591, 27.39; 2.9e599; -8)`: every route of the ball path failed
//! (issue 37's scan, 6 of 40 000 inputs refused as `Overflow`). The connection
//! formula in `1/(1-z)` needs `Gamma(c - a)` and `Gamma(b - a)` at arguments of
//! `-10^24591`, whose balls (a decimal `a` that large is a ball of radius far
//! above 1) hold poles; Pfaff leaves `2F1(b, c - a; c; w)`, whose terms grow
//! like `(a w / c)^n` until `n ~ a`; the one-large-parameter route wants `c`
//! moderate. The value is about `(c / (a |z|))^b`: `2^(-2.2e6)` there, inside the
//! exponent range.
//!
//! # Method and proof
//!
//! With `x = -z > 0`, `a > 0` and `c >= b + 1`, `b > 0`, Euler's integral [DLMF
//! 15.6.1] gives
//!
//! `2F1 = Gamma(c) / (Gamma(b) Gamma(c - b)) I`,
//! `I = int_0^1 t^(b-1) (1-t)^(c-b-1) (1 + x t)^(-a) dt`.
//!
//! Fix `0 < T < 1` (below). On `[0, T]`: `1 >= (1-t)^(c-b-1) >= e^(-(c-b-1) T/(1-T))`
//! (`ln(1-t) >= -t/(1-t)`, `c - b - 1 >= 0`), and
//! `e^(-a x t) <= (1 + x t)^(-a) <= e^(-a x t / (1 + x T))` (`y/(1+y) <= ln(1+y) <= y`).
//! On `[T, 1]` the integrand is at most `(1 + x T)^(-a) t^(b-1)`. With
//! `int_0^inf t^(b-1) e^(-l t) dt = Gamma(b) l^(-b)` and the incomplete
//! `Gamma(b, y) = int_y^inf t^(b-1) e^(-t) dt`:
//!
//! `I <= Gamma(b) (a x)^(-b) [(1 + x T)^b + (1 + x T)^(-a) (a x)^b / (b Gamma(b))]`,
//! `I >= Gamma(b) (a x)^(-b) e^(-(c-b-1) T/(1-T)) [1 - Gamma(b, a x T) / Gamma(b)]`,
//!
//! so `2F1 = [Gamma(c) / Gamma(c - b)] (a x)^(-b) Q` with `Q` in `[L, U]`, the two
//! brackets. For `y > beta = max(b - 1, 0)` and `y >= 1`, `Gamma(b, y) <= y^beta
//! e^(-y) / (1 - beta/y)` (`t^(b-1) <= y^beta e^(beta (t-y)/y)` on `t >= y`), and
//! `Gamma(b) >= 0.885` for `b > 0` (its minimum is 0.8856 at 1.4616).
//!
//! `T = 2^-(wp + 8) / max(c, b x, 1)` (a power of two) makes `(c-b-1) T` and
//! `(1 + x T)^b - 1` at most about `2^-(wp+8)`; the two exponentially small terms
//! (`(1 + x T)^(-a)` against `(a x)^b`, and `Gamma(b, a x T)`) are bounded in
//! logarithms and the route is taken only when each is below `2^-(wp+8)`: when
//! `log2(a x / max(c, b x))` passes `wp` by the `log2` of about `b ln(a x)`.
//! Every quantity of `L` and `U` is formed at 64 bits rounded the way that
//! widens `[L, U]`, from the balls' ends (each is monotone in each input over
//! the ranges above), so `[L, U]` holds `Q` at every point of the balls; the
//! factors `Gamma(c) / Gamma(c - b)` (Stirling's difference where `c` is huge,
//! `gamma_pair_scaled`) and `(a x)^(-b)` are ball arithmetic over the balls, in
//! logarithms ([`Scaled`]), and the product is the function's own value: past
//! the exponent range it is [`Error::ValueOutOfRange`].
//!
//! `b` and `a` may be exchanged (2F1 is symmetric); the larger is taken as `a`.

use rug::float::Round;
use rug::Float;

use crate::ball::{Ball, Scaled};
use crate::error::Result;
use crate::special::gamma::gamma_pair_scaled;

fn mul(x: &Float, y: &Float, r: Round) -> Float {
    Float::with_val_round(x.prec().max(y.prec()), x * y, r).0
}

fn div(x: &Float, y: &Float, r: Round) -> Float {
    Float::with_val_round(x.prec().max(y.prec()), x / y, r).0
}

fn add(x: &Float, y: &Float, r: Round) -> Float {
    Float::with_val_round(x.prec().max(y.prec()), x + y, r).0
}

fn sub(x: &Float, y: &Float, r: Round) -> Float {
    Float::with_val_round(x.prec().max(y.prec()), x - y, r).0
}

fn ln(x: &Float, r: Round) -> Float {
    Float::with_val_round(x.prec(), x.ln_ref(), r).0
}

fn exp(x: &Float, r: Round) -> Float {
    Float::with_val_round(x.prec(), x.exp_ref(), r).0
}

/// `2F1(a, b; c; z)` by the module's bound, when it applies at `wp` bits
/// (`None` otherwise: the caller takes another route).
pub(crate) fn hyp2f1_dominant_param(a: &Ball, b: &Ball, c: &Ball, z: &Ball, wp: u32) -> Option<Result<Ball>> {
    let (d, u) = (Round::Down, Round::Up);
    // the bounds' precision: `[L, U]` is `1 +- 2^-(wp+6)`, held at `wp + 16` bits
    // (each helper rounds at its operands' precision, all `prec`)
    let prec = wp + 16;
    let rnd = |x: &Float, r: Round| Float::with_val_round(prec, x, r).0;
    if !(z.upper() < 0) {
        return None;
    }
    let (a, b) = if a.abs_lower() >= b.abs_upper() { (a, b) } else { (b, a) };
    let one = Float::with_val(prec, 1);
    // a > 0, b > 0, c >= b + 1 over the balls
    let (b_lo, b_hi) = (rnd(&b.lower(), d), rnd(&b.upper(), u));
    if !(a.lower() > 0 && b_lo > 0 && rnd(&c.lower(), d) >= add(&b_hi, &one, u)) {
        return None;
    }
    let (x_lo, x_hi) = (rnd(&-z.upper(), d), rnd(&-z.lower(), u));
    let (a_lo, a_hi) = (rnd(&a.lower(), d), rnd(&a.upper(), u));
    let c_hi = rnd(&c.upper(), u);
    // cheap screen: log2(a x / max(c, b x, 1)) past wp + 24 + log2(b ln(a x))
    let bx = mul(&b_hi, &x_hi, u);
    let scale = if c_hi > bx { c_hi.clone() } else { bx };
    let scale = if scale > 1 { scale } else { one.clone() };
    let ax_lo = mul(&a_lo, &x_lo, d);
    let ln_ax_hi = ln(&mul(&a_hi, &x_hi, u), u);
    let need = f64::from(wp) + 24.0 + (b_hi.to_f64() * ln_ax_hi.to_f64()).max(1.0).log2();
    if !(div(&ax_lo, &scale, d).log2().to_f64() > need) {
        return None;
    }
    // T = 2^-(wp + 8 + e), scale <= 2^e
    let shift = i64::from(wp) + 8 + i64::from(scale.get_exp().unwrap_or(1));
    let t = Float::with_val(prec, Float::with_val(prec, 1) >> (shift.min(1 << 30) as i32));
    let xt_hi = mul(&x_hi, &t, u);
    let xt_lo = mul(&x_lo, &t, d);
    // U = (1 + x T)^b + exp(b ln(a x) - a ln(1 + x T) - ln(b Gamma(b)))
    let first_u = exp(&mul(&ln(&add(&one, &xt_hi, u), u), &b_hi, u), u);
    // ln(1 + y) >= y / (1 + y); Gamma(b) >= 0.885 (its minimum is 0.8856...)
    let ln1p_lo = div(&xt_lo, &add(&one, &xt_lo, u), d);
    let gamma_min = Float::with_val_round(prec, 0.885, d).0;
    let ln_bg = ln(&mul(&b_lo, &gamma_min, d), d);
    let second_ln = sub(&sub(&mul(&b_hi, &ln_ax_hi, u), &mul(&a_lo, &ln1p_lo, d), u), &ln_bg, u);
    let second_u = exp(&second_ln, u);
    let q_hi = add(&first_u, &second_u, u);
    // L = e^(-c T/(1 - T)) [1 - Gamma(b, y)/Gamma(b)], y = a x T
    let c_t = div(&mul(&c_hi, &t, u), &sub(&one, &t, d), u);
    let first_l = exp(&-c_t, d);
    let y = mul(&ax_lo, &t, d);
    let bm1 = sub(&b_hi, &one, u);
    let beta = if bm1 > 0 { bm1 } else { Float::new(prec) };
    if !(y >= 1 && y > beta) {
        return None;
    }
    // ln[Gamma(b, y)/Gamma(b)] <= beta ln y - y - ln(1 - beta/y) - ln 0.885
    let one_minus = sub(&one, &div(&beta, &y, u), d);
    let tail_ln = sub(&sub(&sub(&mul(&ln(&y, u), &beta, u), &y, u), &ln(&one_minus, d), u), &ln(&gamma_min, d), u);
    let tail = exp(&tail_ln, u);
    let q_lo = mul(&first_l, &sub(&one, &tail, d), d);
    let limit = Float::with_val(prec, 1) >> (wp + 6);
    if !(second_u < limit && tail < limit && q_lo > 0) {
        return None;
    }
    let q = Ball::hull(&q_lo, &q_hi, prec);
    let value = || -> Result<Ball> {
        let ratio = gamma_pair_scaled(c, &c.sub(b), b, wp)?;
        let power = Scaled::pow(&a.mul(&z.neg()), &b.neg(), wp)?;
        ratio.mul(&power).mul_ball(&q).to_value(wp)
    };
    Some(value())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::special::hyp2f1::hyp2f1_mp;
    use crate::special::hyp2f1::large_param::hyp2f1_large_param;

    fn exact(x: &Float) -> Ball {
        Ball::from_float(x, x.prec())
    }

    /// Where the route is taken, its ball holds the certified value of the other
    /// routes at the same binary point (the connection formula in `1/(1-z)`,
    /// [`hyp2f1_large_param`] over exact balls), and meets the precision; where `a
    /// |z| / c` is too small for the precision, it declines.
    #[test]
    fn encloses_the_connection_formula_and_declines_when_a_is_not_dominant() {
        for (a, b, c, z, wp) in [(2f64.powi(130), 1.5, 3.0, -2.0, 64), (2f64.powi(200), 2.5, 1e5, -2.75, 96), (1e60, 20.25, 1e6, -8.0, 64)] {
            let fa = Float::with_val(64, a);
            let (fb, fc, fz) = (Float::with_val(64, b), Float::with_val(64, c), Float::with_val(64, z));
            let r = hyp2f1_dominant_param(&exact(&fa), &exact(&fb), &exact(&fc), &exact(&fz), wp).expect("taken").unwrap();
            let other = hyp2f1_large_param(&exact(&fa), &exact(&fb), &exact(&fc), &exact(&fz), wp + 64).unwrap();
            // and the point path takes the route
            assert!(hyp2f1_mp(&fa, &fb, &fc, &fz, wp - 8).unwrap().overlaps(&r));
            assert!(r.overlaps(&other), "2F1({a}, {b}; {c}; {z}): {r:?} against {other:?}");
            assert!(r.meets_rel(wp - 8), "{r:?}");
            // symmetric in a and b
            let s = hyp2f1_dominant_param(&exact(&fb), &exact(&fa), &exact(&fc), &exact(&fz), wp).expect("taken").unwrap();
            assert!(s.overlaps(&r));
        }
        let f = |x: f64| exact(&Float::with_val(64, x));
        // a |z| / c = 2^40: not past wp + 24 bits
        assert!(hyp2f1_dominant_param(&f(2f64.powi(50)), &f(1.5), &f(1024.0), &f(-1.0), 64).is_none());
        // z >= 0, c < b + 1, b < 0: not this route's
        assert!(hyp2f1_dominant_param(&f(2f64.powi(200)), &f(1.5), &f(3.0), &f(0.5), 64).is_none());
        assert!(hyp2f1_dominant_param(&f(2f64.powi(200)), &f(2.5), &f(3.0), &f(-2.0), 64).is_none());
        assert!(hyp2f1_dominant_param(&f(2f64.powi(200)), &f(-2.5), &f(3.0), &f(-2.0), 64).is_none());
    }
}
