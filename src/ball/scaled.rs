//! [`Scaled`]: a real number enclosed as `m e^l`, for products whose factors pass
//! MPFR's exponent range while the product does not.
//!
//! MPFR's exponent range is `2^-(2^30) .. 2^(2^30)` (rug's default, which this
//! crate never changes: the process is shared). `Gamma(4.2e18)` or `(1 - z)^(-a)`
//! at `a = 7.4e17`, `1 - z = 178.9` lie past it, while the value they make with
//! their neighbours (`Gamma(c) / Gamma(c - a)`, about `c^a`; the Pfaff prefactor
//! times an inner sum near its reciprocal) is an ordinary number. Such factors are
//! carried as a pair of balls and the product is formed in logarithms, exponentiated
//! once at the end.
//!
//! # Method and error bound
//!
//! A `Scaled { m, l }` stands for every `mu e^lambda` with `mu` in the ball `m`
//! and `lambda` in the ball `l` (`m` carries the sign and a zero, `l` the size).
//!
//! * Product and quotient: `(m1 m2, l1 + l2)` and `(m1 / m2, l1 - l2)`, since
//!   `mu1 e^lambda1 mu2 e^lambda2 = (mu1 mu2) e^(lambda1 + lambda2)`; ball
//!   arithmetic encloses each part, so the pair encloses every product.
//! * Power ([`Scaled::pow`]): `base^e = e^(e ln base)` for `base > 0`, with `ln
//!   base = ln_1p(base - 1)` next to 1 (`base - 1` formed at the base's own
//!   length, then rounded into its ball; `ln base` at `p` bits elsewhere) and the product at `p = wp + 16 + log2 |e ln base|` bits, so
//!   that the absolute error of `l`, which becomes the relative error of the
//!   value, is about `2^-(wp+16)` however large `l` is.
//! * Back to a ball ([`Scaled::to_ball`]): for any integer `k`, `mu e^lambda =
//!   2^k mu e^(lambda - k ln 2)`. With `k` the integer nearest `mid(l) / ln 2`
//!   and `f = l - k ln 2` in balls (`ln 2` at a precision where `|k| 2^-p` is
//!   below `2^-(wp+16)`), every `lambda - k ln 2` lies in `f`, so every value
//!   lies in `2^k m e^f`. `e^f` is MPFR's `exp` at the ends of `f`, rounded
//!   outward (`Ball::exp`); the shift by `2^k` is exact when the result is in
//!   the exponent range.
//! * Sums ([`Scaled::sum_to_ball`]): each term formed as above; a term whose
//!   magnitude lies below the exponent range is bounded by `|m|_hi 2^ceil(l_hi /
//!   ln 2)` (`l_hi / ln 2` rounded up with `ln 2` rounded the way that enlarges
//!   it, a [`Mag`] with its 64-bit exponent) and added to the radius of the
//!   others: `(1 - z)^(-7.4e17)` times its Gamma ratio in the connection formula
//!   in `1/(1-z)`, about `2^(-5.5e18)`, next to a term of size 1.
//! * Out of range: when every value of `2^k m e^f` has magnitude at least
//!   `2^emax`, or at most `2^(emin - 1)`, no precision represents the value:
//!   [`Error::ValueOutOfRange`] (an honest refusal, with the value's `log2`
//!   magnitude). When the ball only straddles a limit it is [`Error::Overflow`]:
//!   a tighter ball (more precision) may settle it.

use rug::Float;

use super::{Ball, Mag};
use crate::error::{Error, Log2Magnitude, Log2Relation, Result};

/// A real number in `m e^l` (see the module docs).
#[derive(Clone, Debug)]
pub struct Scaled {
    m: Ball,
    l: Ball,
}

/// Estimated seconds of MPFR's `ln` at `p` bits, for the budget (an estimate,
/// never in a bound): measured (test profile, load 9 on 2 cores) 2.7 ms at
/// 20 000 bits, 19 ms at 50 000, 41 ms at 100 000; this is `0.045 (p/10^5)^1.5`
/// (4, 16, 45 ms there). A logarithm carried at `wp + log2|l|` bits costs that
/// much at a parameter of `10^30000` (`|l|` about `2^100000`).
pub(crate) fn ln_seconds(p: u32) -> f64 {
    0.045 * (f64::from(p) / 1e5).powf(1.5)
}

/// [`Error::ValueOutOfRange`] of an intermediate as [`Error::Overflow`]: only
/// the function's own value may be called out of range.
pub(crate) fn intermediate(e: Error) -> Error {
    match e {
        Error::ValueOutOfRange { .. } => Error::Overflow { what: "an intermediate product taken in logarithms (past the exponent range)".into() },
        e => e,
    }
}

/// `q + extra` as a [`Log2Magnitude`] estimate: `q` (a float of any exponent
/// in MPFR's range) is past f64's range when the value is `2^(2^1024)` or
/// less than its reciprocal, so it is read as a decimal through `log10` at 64
/// bits (the significand to about 10 digits: the printed 5 are right).
pub(crate) fn log2_magnitude(q: &Float, extra: i64) -> Log2Magnitude {
    let v = Float::with_val(64, q + extra);
    if v.is_zero() || !v.is_finite() {
        return Log2Magnitude::about(v.to_f64());
    }
    let l = Float::with_val(64, v.abs_ref()).log10();
    let e = Float::with_val(64, l.floor_ref());
    let frac = Float::with_val(64, &l - &e).to_f64();
    let m = 10f64.powf(frac);
    let m = if v.is_sign_negative() { -m } else { m };
    Log2Magnitude::new(m, e.to_f64() as i64, Log2Relation::About)
}

/// `floor(log2 |x|) + 1` of a finite nonzero float, 0 otherwise.
fn exponent(x: &Float) -> i64 {
    x.get_exp().map_or(0, i64::from)
}

impl Scaled {
    /// The ball `m` itself (`l = 0`).
    pub fn from_ball(m: Ball) -> Scaled {
        Scaled { m, l: Ball::zero(2) }
    }

    /// `1` at `prec` bits.
    pub fn one(prec: u32) -> Scaled {
        Scaled::from_ball(Ball::one(prec))
    }

    /// `sign e^l` for `sign` a ball (typically `+-1`, or `pi / sin(pi d)`).
    pub fn with_log(m: Ball, l: Ball) -> Scaled {
        Scaled { m, l }
    }

    /// Whether `l` is the exact zero (the value is the ball `m`).
    fn plain(&self) -> bool {
        self.l.is_exact() && self.l.mid().is_zero()
    }

    /// Whether the value is the exact zero.
    pub fn is_exact_zero(&self) -> bool {
        self.m.is_exact() && self.m.mid().is_zero()
    }

    fn add_logs(a: &Ball, b: &Ball) -> Ball {
        if a.is_exact() && a.mid().is_zero() {
            b.clone()
        } else if b.is_exact() && b.mid().is_zero() {
            a.clone()
        } else {
            a.add(b)
        }
    }

    /// `self * other`.
    pub fn mul(&self, other: &Scaled) -> Scaled {
        Scaled { m: self.m.mul(&other.m), l: Scaled::add_logs(&self.l, &other.l) }
    }

    /// `self * b`.
    pub fn mul_ball(&self, b: &Ball) -> Scaled {
        Scaled { m: self.m.mul(b), l: self.l.clone() }
    }

    /// `-self`.
    pub fn neg(&self) -> Scaled {
        Scaled { m: self.m.neg(), l: self.l.clone() }
    }

    /// `self / other`; an error when `other`'s `m` contains zero.
    pub fn div(&self, other: &Scaled) -> Result<Scaled> {
        Ok(Scaled { m: self.m.div(&other.m)?, l: Scaled::add_logs(&self.l, &other.l.neg()) })
    }

    /// `self / b`; an error when `b` contains zero.
    pub fn div_ball(&self, b: &Ball) -> Result<Scaled> {
        Ok(Scaled { m: self.m.div(b)?, l: self.l.clone() })
    }

    /// `base^e` for a positive ball `base` (an error otherwise), carried in
    /// logarithms at the precision the module docs give, whatever the size of
    /// `e ln base`. Pass `base` unrounded: it is rounded here to the bits its
    /// logarithm needs (`wp` rounded first, `(1 - 3.9e-62)^(2.7e24977)` lost
    /// all of `ln base` to the rounding).
    pub fn pow(base: &Ball, e: &Ball, wp: u32) -> Result<Scaled> {
        if (base.is_exact() && *base.mid() == 1) || (e.is_exact() && e.mid().is_zero()) {
            return Ok(Scaled::one(wp));
        }
        if !base.is_positive() {
            return Err(base.out_of_range("pow base", crate::error::Interval::above(0.0)));
        }
        // ln base = ln_1p(base - 1), with base - 1 formed at the base's own
        // length (exact for a long `1 - z` at a tiny `z`: rounding `1 - 3.9e-62`
        // to `wp` bits first gave ln base = 0 +- 2^-wp, and with it nothing)
        let t = base.sub(&Ball::one(2));
        // log2 |e ln base| from the exponents (an estimate that only sets the precision):
        // |ln base| is about |t| for |t| < 1/2, and below log2(e) |ln(1+t)| otherwise
        let ln_exp = if t.mid().get_exp().is_some_and(|x| x < 0) {
            exponent(t.mid())
        } else {
            let lb = base.at_most_prec(64).ln()?;
            exponent(lb.mid()) + 1
        };
        let size = (exponent(e.mid()) + ln_exp).max(0);
        let p = (i64::from(wp) + 16 + size).min(i64::from(crate::MAX_WORKING_PREC) * 4) as u32;
        if p > 4096 {
            crate::budget::check_estimate("a power taken in logarithms (ln at the bits its size needs)", ln_seconds(p), f64::INFINITY)?;
        }
        // ln_1p only next to 1 (|t| < 1/2): next to 0, `1 + t` rounded at p bits
        // would lose `base` itself (`1 - z` at `z = 1 - 10^-30`)
        let ln_base = if t.mid().get_exp().is_some_and(|x| x < 0) { t.set_prec(p).ln_1p()? } else { base.set_prec(p).ln()? };
        let l = ln_base.mul(&e.at_most_prec(p));
        Ok(Scaled { m: Ball::one(wp), l })
    }

    /// An upper bound of `|value|` as a [`Mag`] (module docs, "Sums"); infinite
    /// when `l` is unbounded.
    pub fn abs_upper_mag(&self) -> Mag {
        let m = self.m.abs_upper_mag();
        if self.plain() || m.is_zero() {
            return m;
        }
        let t = self.l.upper();
        if !t.is_finite() {
            return Mag::inf();
        }
        let ln2_lo = Float::with_val_round(64, rug::float::Constant::Log2, rug::float::Round::Down).0;
        let ln2_hi = Float::with_val_round(64, rug::float::Constant::Log2, rug::float::Round::Up).0;
        let den = if t.is_sign_negative() { ln2_hi } else { ln2_lo };
        let x = Float::with_val_round(64, &t / &den, rug::float::Round::Up).0.ceil();
        // below 2^-(2^61) the bound 2^-(2^61) (larger, so still a bound) keeps
        // the Mag's exponent far from its i64 limits
        let xf = x.to_f64().max(-(2f64.powi(61)));
        if xf < 2f64.powi(61) {
            m.mul_2exp(xf as i64)
        } else {
            Mag::inf()
        }
    }

    /// `sum terms` as the function's value (module docs, "Sums"): terms below
    /// the exponent range go into the radius; [`Error::ValueOutOfRange`] when
    /// every term lies below it (the sum then does too), [`Error::Overflow`] when
    /// a term lies above it (the terms may cancel: a cap of this method).
    pub fn sum_to_value(terms: &[Scaled], wp: u32) -> Result<Ball> {
        let mut out: Option<Ball> = None;
        let mut tiny = Mag::ZERO;
        let mut tiny_log2: Option<Log2Magnitude> = None;
        for t in terms {
            match t.form(wp) {
                Ok(b) => out = Some(out.map_or_else(|| b.clone(), |o| o.add(&b))),
                Err(Error::ValueOutOfRange { log2_magnitude }) if log2_magnitude.is_negative() => {
                    tiny = tiny.add(t.abs_upper_mag());
                    tiny_log2 = Some(match tiny_log2 {
                        Some(m) if m.cmp_number(&log2_magnitude).is_ge() => m,
                        _ => log2_magnitude,
                    });
                }
                Err(Error::ValueOutOfRange { .. }) => {
                    return Err(Error::Overflow { what: "a sum taken in logarithms (a term past the exponent range)".into() })
                }
                Err(e) => return Err(e),
            }
        }
        match out {
            Some(mut b) => {
                b.add_error_mag(tiny);
                Ok(b)
            }
            None => Err(Error::ValueOutOfRange { log2_magnitude: tiny_log2.unwrap_or(Log2Magnitude::about(f64::NEG_INFINITY)) }),
        }
    }

    /// [`Scaled::sum_to_value`] for an intermediate sum (an inner function that
    /// a prefactor multiplies later): out of range is [`Error::Overflow`].
    pub fn sum_to_ball(terms: &[Scaled], wp: u32) -> Result<Ball> {
        Scaled::sum_to_value(terms, wp).map_err(intermediate)
    }

    /// The enclosing ball at about `wp` bits (module docs) of a value that is
    /// the function's own: [`Error::ValueOutOfRange`] when it lies outside MPFR's
    /// exponent range (an honest refusal: no precision represents it), or
    /// [`Error::Overflow`] when the enclosure straddles a limit of that range.
    pub fn to_value(&self, wp: u32) -> Result<Ball> {
        self.form(wp)
    }

    /// [`Scaled::to_value`] for an intermediate (a factor or an inner function
    /// that later factors may bring back into range): out of range is
    /// [`Error::Overflow`], a cap of the method, never a statement about the
    /// function's value.
    pub fn to_ball(&self, wp: u32) -> Result<Ball> {
        self.form(wp).map_err(intermediate)
    }

    fn form(&self, wp: u32) -> Result<Ball> {
        if self.plain() || self.is_exact_zero() {
            if !self.m.is_finite() {
                return Err(Error::Overflow { what: "a product taken in logarithms (its ball)".into() });
            }
            return Ok(self.m.clone());
        }
        if !self.l.is_finite() || !self.m.is_finite() {
            return Err(Error::Overflow { what: "a product taken in logarithms (its logarithm)".into() });
        }
        let (emin, emax) = (i64::from(rug::float::exp_min()), i64::from(rug::float::exp_max()));
        let size = exponent(self.l.mid()).max(0);
        let p = self.l.prec().max((i64::from(wp) + 16 + size).min(u32::MAX as i64 / 2) as u32);
        let ln2 = Ball::ln2(p);
        let q = Float::with_val(64, self.l.mid() / ln2.mid()).round();
        let log2_estimate = log2_magnitude(&q, exponent(self.m.mid()));
        // |k| past 2^62: the value is 2^(+-2^62) times m. Out of range when the
        // whole of `l` is past 2^61 (in either direction, with `m` excluding zero
        // for the upper side) and `|m|` within 2^(+-2^40): however wide `l` is
        if q.clone().abs() > (1u64 << 62) {
            let edge = Float::with_val(64, 1u64 << 61);
            let m_ok = self.m.abs_upper_mag().is_finite() && exponent(self.m.mid()).abs() < (1 << 40);
            let above = self.l.lower() > edge && !self.m.contains_zero() && exponent(&self.m.abs_lower()) > -(1 << 40);
            let below = self.l.upper() < -edge;
            if m_ok && (above || below) {
                return Err(Error::ValueOutOfRange { log2_magnitude: log2_estimate });
            }
            return Err(Error::Overflow { what: "a product taken in logarithms (a wide logarithm)".into() });
        }
        let k = q.to_f64() as i64;
        let f = self.l.sub(&ln2.mul(&Ball::from_float(&Float::with_val(64, k), 64)));
        let t = self.m.mul(&f.at_most_prec(wp + 16).exp()?);
        if !t.is_finite() {
            return Err(Error::Overflow { what: "a product taken in logarithms (its ball)".into() });
        }
        if t.is_exact() && t.mid().is_zero() {
            return Ok(t);
        }
        // |t| <= 2^e_hi; |t| >= 2^(e_lo - 1) when t excludes zero
        let e_hi = exponent(&t.abs_upper());
        let above_all = !t.contains_zero() && k + exponent(&t.abs_lower()) > emax;
        let below_all = k + e_hi < emin;
        if above_all || below_all {
            return Err(Error::ValueOutOfRange { log2_magnitude: log2_estimate });
        }
        if k + e_hi > emax || (!t.contains_zero() && k + exponent(&t.abs_lower()) - 1 < emin) {
            return Err(Error::Overflow { what: "a product taken in logarithms (its ball straddles the exponent range's limit)".into() });
        }
        let shift = i32::try_from(k).ok().filter(|_| t.mid().is_zero() || k + exponent(t.mid()) > emin);
        match shift {
            Some(s) => Ok(t.mul_pow2(s)),
            None => Err(Error::Overflow { what: "a product taken in logarithms (its midpoint below the exponent range)".into() }),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn product_past_the_exponent_range_is_representable() {
        // 3^(2^40) * 3^(-2^40 + 5) = 243, with both factors far past 2^(2^30)
        let three = Ball::from_i64(3, 64);
        let big = Ball::from_float(&Float::with_val(64, 1u64 << 40), 64);
        let back = big.neg().add_i64(5);
        let v = Scaled::pow(&three, &big, 64).unwrap().mul(&Scaled::pow(&three, &back, 64).unwrap()).to_value(64).unwrap();
        assert!(v.contains(&Float::with_val(64, 243)), "{v:?}");
        assert!(v.rel_accuracy_bits() > 50.0, "{v:?}");
        // the factor alone is refused as out of range, with its size
        match Scaled::pow(&three, &big, 64).unwrap().to_value(64) {
            Err(Error::ValueOutOfRange { log2_magnitude }) => {
                assert!((log2_magnitude.to_f64() / (1u64 << 40) as f64 - 3f64.log2()).abs() < 1e-9, "{log2_magnitude}")
            }
            other => panic!("{other:?}"),
        }
        match Scaled::pow(&three, &big.neg(), 64).unwrap().to_value(64) {
            Err(Error::ValueOutOfRange { log2_magnitude }) => assert!(log2_magnitude.to_f64() < -1e12),
            other => panic!("{other:?}"),
        }
    }
}

