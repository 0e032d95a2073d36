//! A proof that `2F1(a, b; c; z)` lies above MPFR's exponent range, for
//! positive parameters and `0 < z < 1`, over balls.
//!
//! # Why
//!
//! `2F1(2.7e24977, 1.0000000000000002; 1.0000000000000002; 3.9e-62)` is about
//! `e^(a z) = e^(1e24916)`, and `2F1(1, 3.6e17763; 2.2e-19396; 1 - 2^-52)` about
//! `(b / c) (1 - z)^(c - a - b)`: both far past `2^(2^30)`, the largest value MPFR
//! represents. Every route met that size as an intermediate (Pfaff's prefactor,
//! a term of a connection formula) and was refused as [`Error::Overflow`], a cap
//! of the method (issue 37's scan, 5 of 40 000 inputs). No precision can answer
//! them; the refusal that says so is [`Error::ValueOutOfRange`], and it needs a
//! proof that the value itself is that large.
//!
//! # Method and proof
//!
//! For `a, b, c > 0` and `0 < z < 1` every term of DLMF 15.2.1 is positive, so
//! for every `n`
//!
//! `2F1(a, b; c; z) >= t_n = prod_{k=0}^{n-1} [(a + k) / (c + k)] [(b + k) / (1 + k)] z`
//!
//! (also with `a` and `b` exchanged in the pairing). For `x, y > 0` the map
//! `k -> (x + k) / (y + k)` is monotone, so on `0 <= k < n` it is at least
//! `min(x / y, (x + n - 1) / (y + n - 1))`; over the balls `x >= x_lo`, `y <=
//! y_hi`, and `(x + k) / (y + k) >= (x_lo + k) / (y_hi + k)`. Hence
//!
//! `log2 2F1 >= n (log2 z_lo + log2 m1 + log2 m2)`,
//!
//! `m1`, `m2` those minima. Each quantity is rounded downward (MPFR, 64 bits), so
//! the right side is a lower bound. It is tried at `n = 2^31, 2^32, ..., 2^62`
//! and the best bound kept; when it reaches MPFR's `emax` (`|F| >= 2^emax` is not
//! representable) the function's value is out of range at every point of the
//! balls, and the refusal carries the bound (`Log2Relation::AtLeast`).
//!
//! Cost: about 200 operations on 64-bit floats; nothing is tried unless all four
//! balls satisfy the signs.

use rug::float::Round;
use rug::Float;

use crate::ball::Ball;
use crate::error::{Error, Log2Magnitude, Log2Relation};

const PREC: u32 = 64;

fn down(x: Float) -> Float {
    Float::with_val_round(PREC, &x, Round::Down).0
}

/// `log2` of the lower bound of `(x + k) / (y + k)` over `0 <= k < n` (module
/// docs), rounded down.
fn log2_ratio_floor(x_lo: &Float, y_hi: &Float, n: &Float) -> Float {
    let first = Float::with_val_round(PREC, x_lo / y_hi, Round::Down).0;
    let nm1 = Float::with_val(PREC, n - 1u32);
    let num = Float::with_val_round(PREC, x_lo + &nm1, Round::Down).0;
    let den = Float::with_val_round(PREC, y_hi + &nm1, Round::Up).0;
    let last = Float::with_val_round(PREC, &num / &den, Round::Down).0;
    let m = if first < last { first } else { last };
    Float::with_val_round(PREC, m.log2_ref(), Round::Down).0
}

/// [`Error::ValueOutOfRange`] when the module's bound proves `2F1(a, b; c; z)
/// >= 2^emax` over the balls; `None` when it does not apply or does not prove it.
pub(crate) fn proven_above_range(a: &Ball, b: &Ball, c: &Ball, z: &Ball) -> Option<Error> {
    if !(a.lower() > 0 && b.lower() > 0 && c.lower() > 0 && z.lower() > 0 && z.upper() < 1) {
        return None;
    }
    let (a_lo, b_lo, c_hi, z_lo) = (down(a.lower()), down(b.lower()), Float::with_val_round(PREC, c.upper(), Round::Up).0, down(z.lower()));
    let one = Float::with_val(PREC, 1);
    let log_z = Float::with_val_round(PREC, z_lo.log2_ref(), Round::Down).0;
    let emax = Float::with_val(PREC, rug::float::exp_max());
    let mut best: Option<Float> = None;
    for k in 31..=62u32 {
        let n = Float::with_val(PREC, 1u64 << k);
        for (p, q) in [(&a_lo, &b_lo), (&b_lo, &a_lo)] {
            // (p + k)/(c + k) and (q + k)/(1 + k)
            let l1 = log2_ratio_floor(p, &c_hi, &n);
            let l2 = log2_ratio_floor(q, &one, &n);
            let per = down(Float::with_val_round(PREC, &l1 + &l2, Round::Down).0 + &log_z);
            let bound = Float::with_val_round(PREC, &per * &n, Round::Down).0;
            if bound.is_finite() && best.as_ref().map_or(true, |b| bound > *b) {
                best = Some(bound);
            }
        }
    }
    let best = best?;
    (best >= emax).then(|| {
        let m = crate::ball::log2_magnitude(&best, 0);
        Error::ValueOutOfRange { log2_magnitude: Log2Magnitude { relation: Log2Relation::AtLeast, ..m } }
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ball::Ball;

    fn ball(x: f64) -> Ball {
        Ball::from_f64(x, 64).unwrap()
    }

    #[test]
    fn e_to_the_a_z_past_the_range_is_proven_out_of_range() {
        // 2F1(a, 1; 1; z) = (1 - z)^(-a) = 2^(-a log2(1 - z)): at a = 2^40, z = 1/2
        // that is 2^(2^40), past 2^(2^30); the bound must prove it
        let e = proven_above_range(&ball(2f64.powi(40)), &ball(1.0), &ball(1.0), &ball(0.5)).expect("proven");
        match e {
            Error::ValueOutOfRange { log2_magnitude } => {
                assert_eq!(log2_magnitude.relation, Log2Relation::AtLeast);
                let l = log2_magnitude.to_f64();
                assert!(l >= f64::from(rug::float::exp_max()) && l <= 2f64.powi(40), "{l}");
            }
            other => panic!("{other:?}"),
        }
    }

    #[test]
    fn a_representable_value_is_not_claimed_out_of_range() {
        // (1 - z)^(-a) at a = 2^29, z = 1/2: 2^(2^29), inside the range
        assert!(proven_above_range(&ball(2f64.powi(29)), &ball(1.0), &ball(1.0), &ball(0.5)).is_none());
        // negative z, negative parameter, z = 1: not this module's
        assert!(proven_above_range(&ball(2f64.powi(40)), &ball(1.0), &ball(1.0), &ball(-0.5)).is_none());
        assert!(proven_above_range(&ball(-2f64.powi(40)), &ball(1.0), &ball(1.0), &ball(0.5)).is_none());
    }
}
