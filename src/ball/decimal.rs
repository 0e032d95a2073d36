//! Decimal text as a ball that contains it (Arb's convention for typed inputs).
//!
//! # Contract
//!
//! A [`Decimal`] is the exact rational number the text denotes
//! (`[+-]digits[.digits][e[+-]digits]`). [`Decimal::to_ball`] turns it into a
//! [`Ball`] that **contains** that rational:
//!
//! * if the decimal is a binary fraction (its reduced denominator is a power of
//!   two, e.g. `2.5`, `0.375`, `1e3`), the ball is exact: radius zero, with as
//!   many midpoint bits as the number needs (at least the requested precision);
//! * otherwise the midpoint is the rational rounded to nearest at the requested
//!   precision and the radius is one ulp of it (round to nearest errs by at most
//!   half an ulp, so the ball contains the decimal).
//!
//! A function evaluated on the ball therefore encloses the function **at the
//! decimal typed**, not at some nearby binary number. Where the function is
//! steep or vanishes near the decimal, the input radius may dominate; then
//! [`eval_at_decimals`] re-rounds the decimals at more bits (they are known
//! exactly) until the answer meets the requested relative precision or a cap.
//!
//! Rejected with a typed [`Error`]: empty text, anything that is not a plain
//! decimal (`nan`, `inf`, hexadecimal, embedded spaces), and exponents beyond
//! `±MAX_DECIMAL_EXPONENT`.

use rug::float::Round;
use rug::{Float, Integer, Rational};

use super::six_digits::six_digits;
use super::{rounded, Ball, Mag};
use crate::error::{Error, Result};

/// Largest |decimal exponent| accepted (after folding in the digits' position).
/// `1e100000` is far beyond any quantity the crate's functions take; the cap
/// keeps the exact rational (and its memory) bounded.
pub const MAX_DECIMAL_EXPONENT: i64 = 100_000;

/// Largest number of mantissa digits accepted (the exact rational's size).
pub const MAX_DECIMAL_DIGITS: usize = 100_000;

/// A decimal number, held exactly.
#[derive(Clone, Debug, PartialEq)]
pub struct Decimal {
    value: Rational,
    /// Bits of the odd part of the numerator when the value is a binary fraction.
    binary_bits: Option<u32>,
}

impl Decimal {
    /// Parses `[+-]digits[.digits][(e|E)[+-]digits]` (surrounding whitespace allowed).
    pub fn parse(text: &str) -> Result<Decimal> {
        let t = text.trim();
        let bad = || Error::NotADecimal { text: t.to_string() };
        let (neg, rest) = match t.as_bytes().first() {
            Some(b'-') => (true, &t[1..]),
            Some(b'+') => (false, &t[1..]),
            _ => (false, t),
        };
        let (mantissa, exp_text) = match rest.find(['e', 'E']) {
            Some(i) => (&rest[..i], Some(&rest[i + 1..])),
            None => (rest, None),
        };
        let (int_part, frac_part) = match mantissa.find('.') {
            Some(i) => (&mantissa[..i], &mantissa[i + 1..]),
            None => (mantissa, ""),
        };
        let all_digits = |s: &str| s.bytes().all(|b| b.is_ascii_digit());
        if (int_part.is_empty() && frac_part.is_empty()) || !all_digits(int_part) || !all_digits(frac_part) {
            return Err(bad());
        }
        if int_part.len() + frac_part.len() > MAX_DECIMAL_DIGITS {
            return Err(Error::DecimalTooLarge {
                text: t.chars().take(24).collect(),
                max_digits: MAX_DECIMAL_DIGITS,
                max_exponent: MAX_DECIMAL_EXPONENT,
            });
        }
        let exp: i64 = match exp_text {
            None => 0,
            Some(e) => {
                let digits = e.strip_prefix(['+', '-']).unwrap_or(e);
                if digits.is_empty() || !all_digits(digits) {
                    return Err(bad());
                }
                // Saturate absurdly long exponents; the range check below rejects them.
                e.parse::<i64>().unwrap_or(if e.starts_with('-') { i64::MIN / 2 } else { i64::MAX / 2 })
            }
        };
        // value = digits * 10^(exp - len(frac)); leading zeros dropped, trailing zeros
        // folded into the exponent, so "1000e-3" and "1" are the same number.
        let all: String = [int_part, frac_part].concat();
        let significant = all.trim_start_matches('0');
        if significant.is_empty() {
            return Ok(Decimal { value: Rational::new(), binary_bits: Some(0) });
        }
        let trimmed = significant.trim_end_matches('0');
        let trailing = (significant.len() - trimmed.len()) as i64;
        let scale = exp.saturating_sub(frac_part.len() as i64).saturating_add(trailing);
        let magnitude = scale.saturating_add(trimmed.len() as i64);
        if !(-MAX_DECIMAL_EXPONENT..=MAX_DECIMAL_EXPONENT).contains(&magnitude) {
            return Err(Error::DecimalTooLarge {
                text: t.chars().take(24).collect(),
                max_digits: MAX_DECIMAL_DIGITS,
                max_exponent: MAX_DECIMAL_EXPONENT,
            });
        }
        let mut num = Integer::from_str_radix(trimmed, 10).map_err(|_| bad())?;
        if neg {
            num = -num;
        }
        let pow10 = Integer::from(Integer::u_pow_u(10, scale.unsigned_abs() as u32));
        let value = if scale >= 0 { Rational::from(num * pow10) } else { Rational::from((num, pow10)) };
        let binary_bits = binary_fraction_bits(&value);
        Ok(Decimal { value, binary_bits })
    }

    /// An exact rational number (for example a binary float `m 2^e` handed over
    /// exactly), under the same contract as a parsed decimal.
    pub fn from_rational(value: Rational) -> Decimal {
        let binary_bits = binary_fraction_bits(&value);
        Decimal { value, binary_bits }
    }

    /// The exact value.
    pub fn as_rational(&self) -> &Rational {
        &self.value
    }

    /// Whether the decimal is a binary fraction (exactly representable in binary).
    pub fn is_binary_fraction(&self) -> bool {
        self.binary_bits.is_some()
    }

    /// A ball at `prec` bits that contains the decimal; exact (radius zero) when
    /// the decimal is a binary fraction, with as many midpoint bits as it needs.
    pub fn to_ball(&self, prec: u32) -> Ball {
        let prec = prec.clamp(2, rug::float::prec_max());
        if let Some(bits) = self.binary_bits {
            let p = prec.max(bits).max(2);
            // an integer (the constants of most expressions) without the rational's
            // conversion: exact in p >= bits bits
            if *self.value.denom() == 1 {
                if let Some(i) = self.value.numer().to_i64() {
                    return Ball::from_i64(i, p);
                }
            }
            let mid = Float::with_val(p, &self.value);
            return Ball::from_float(&mid, p);
        }
        let (mid, ord) = Float::with_val_round(prec, &self.value, Round::Nearest);
        rounded(mid, ord)
    }

    /// The nearest f64 (round to nearest, ties to even).
    pub fn to_f64(&self) -> f64 {
        self.value.to_f64()
    }
}

/// For a binary fraction `m 2^e` (m odd), the bits of `m`; `None` otherwise.
fn binary_fraction_bits(q: &Rational) -> Option<u32> {
    let den = q.denom();
    if !den.is_power_of_two() {
        return None;
    }
    let num = q.numer().clone().abs();
    let tz = num.find_one(0).unwrap_or(0);
    let bits = num.significant_bits() - tz;
    // A binary fraction with more bits than MPFR allows is treated as a general decimal.
    (bits <= rug::float::prec_max()).then_some(bits.max(1))
}

impl Ball {
    /// The ball at `prec` bits that contains the decimal `text` (see [`Decimal`]).
    pub fn from_decimal(text: &str, prec: u32) -> Result<Ball> {
        Ok(Decimal::parse(text)?.to_ball(prec))
    }
}

/// An upper bound of half a unit in the last digit of the decimal text `s`
/// (`[-]digits[.digits][e[-]exp]`, rug's format), or `None` if `s` is not such
/// a decimal (`inf`, `NaN`).
pub(super) fn half_unit_of_last_digit(s: &str) -> Option<Mag> {
    let body = s.strip_prefix('-').unwrap_or(s);
    let (mant, exp) = match body.find('e') {
        Some(i) => (&body[..i], body[i + 1..].parse::<i64>().ok()?),
        None => (body, 0),
    };
    if mant.is_empty() || !mant.bytes().all(|b| b.is_ascii_digit() || b == b'.') {
        return None;
    }
    let frac_digits = mant.find('.').map_or(0, |i| mant.len() - i - 1) as i64;
    Some(pow10_upper(exp.checked_sub(frac_digits)?).mul_2exp(-1))
}

/// An upper bound of `10^m`: `2^s` with `s >= m log2(10)`. The f64 product
/// `t = m LOG2_10` errs by at most `2.5e-16 |t|` (the constant and one rounding;
/// `m` is exact below `2^52`), covered by the slack `2e-15 |t| + 1e-9`, which
/// also covers the rounding of `t + slack`; `s = e + f` with `e = floor(s)` and
/// `f = s - e` exact, and `2^f` from `exp2` (within a few ulps) raised by `1e-12`.
fn pow10_upper(m: i64) -> Mag {
    if m.unsigned_abs() > 1 << 52 {
        return if m < 0 { Mag::pow2(-(1 << 60)) } else { Mag::inf() };
    }
    let t = m as f64 * std::f64::consts::LOG2_10;
    let s = t + (t.abs() * 2e-15 + 1e-9);
    let e = s.floor();
    Mag::from_f64((s - e).exp2() * (1.0 + 1e-12)).mul_2exp(e as i64)
}

/// A short decimal string `>= m` ([`super::decimal_upper`] of a [`Mag`]): through
/// f64 where the bound is a normal f64 (Rust prints an f64 exactly rounded to
/// nearest, so printing `v (1 + 2^-16)` with six significant digits, relative
/// error `<= 5e-6`, gives a decimal `>= v`; [`six_digits`] prints the same text as
/// `{:.5e}` at a fraction of its cost), else through MPFR.
pub(super) fn mag_decimal_upper(m: Mag) -> String {
    if m.is_zero() {
        return "0".to_string();
    }
    let l = m.log2();
    if l.is_finite() && l.abs() < 1000.0 {
        let v = m.to_f64_up();
        if v.is_normal() {
            let w = v * (1.0 + 1.0 / 65536.0);
            return six_digits(w).unwrap_or_else(|| format!("{w:.5e}"));
        }
    }
    super::decimal_upper(&m.to_float())
}

/// Largest midpoint precision [`eval_at_decimals`] rounds decimals to.
pub const MAX_DECIMAL_INPUT_PREC: u32 = 1 << 16;

/// Evaluates `f` on balls that contain the decimals `args`, so that the result
/// contains the function at the decimals as typed.
///
/// The decimals are rounded at `max(prec, 53) + 64` bits first. When the
/// result misses `rad <= 2^-prec |mid|` and some input is not exact, the input
/// precision is raised by the bits missing plus a margin (at least doubled) and
/// `f` runs again, up to [`MAX_DECIMAL_INPUT_PREC`] bits; past that the answer is
/// [`crate::Error::PrecisionExhausted`] (an enclosing ball wider than `prec` is not
/// returned as if it met it). Binary-fraction inputs are exact from
/// the start, so for them `f` runs once. A domain error of `f` (an edge inside
/// an input ball) is retried with tighter balls while an input is inexact, and
/// returned once the balls are exact or at the cap; other errors return at once.
pub fn eval_at_decimals<F>(args: &[Decimal], prec: u32, f: F) -> Result<Ball>
where
    F: FnMut(&[Ball]) -> Result<Ball>,
{
    eval_at_decimals_with_floor(args, prec, None, f)
}

/// [`eval_at_decimals`] for a function with a natural scale `floor` that may
/// vanish at the decimals (for example `u_w(a) = A (1 - cos(2 pi a/zeta))`,
/// zero when `a/zeta` is an integer): the answer is accepted once
/// `rad <= 2^-prec max(|mid|, floor)`.
pub fn eval_at_decimals_with_floor<F>(args: &[Decimal], prec: u32, floor: Option<&Float>, f: F) -> Result<Ball>
where
    F: FnMut(&[Ball]) -> Result<Ball>,
{
    crate::budget::ensure(|| eval_at_decimals_loop(args, prec, floor, f))
}

/// The loop of [`eval_at_decimals_with_floor`], under the call's time budget.
fn eval_at_decimals_loop<F>(args: &[Decimal], prec: u32, floor: Option<&Float>, mut f: F) -> Result<Ball>
where
    F: FnMut(&[Ball]) -> Result<Ball>,
{
    let all_exact = args.iter().all(Decimal::is_binary_fraction);
    let mut input_prec = prec.max(53) + 64;
    let mut round_start = std::time::Instant::now();
    loop {
        if input_prec > prec.max(53) + 64 {
            // a retry: its time is at least about the last round's
            let reached = crate::error::Reached::InputPrecision { bits: input_prec };
            crate::budget::check_elapsed("eval_at_decimals (retries at tighter input balls)", crate::budget::since(round_start), reached)?;
            round_start = std::time::Instant::now();
        }
        let balls: Vec<Ball> = args.iter().map(|d| d.to_ball(input_prec)).collect();
        let out = match f(&balls) {
            Ok(out) => out,
            // An edge (pole, branch point, divergence) inside an input ball that
            // is not exact may leave it when the ball shrinks, as for z typed as
            // 1 - 10^-40 next to the branch point z = 1: retry tighter. A decimal
            // that lies on the edge keeps failing and the error is returned at the cap.
            Err(e) if e.is_domain() && !all_exact && input_prec < MAX_DECIMAL_INPUT_PREC => {
                input_prec = input_prec.saturating_mul(2).min(MAX_DECIMAL_INPUT_PREC);
                continue;
            }
            Err(e) => return Err(e),
        };
        let meets_floor = floor.is_some_and(|fl| !fl.is_zero() && out.meets_abs(prec, fl));
        if all_exact || out.meets_rel(prec) || meets_floor {
            return Ok(out);
        }
        if input_prec >= MAX_DECIMAL_INPUT_PREC {
            // an enclosing ball wider than asked is not returned as if it met `prec`
            return Err(crate::error::Error::PrecisionExhausted { function: "eval_at_decimals", working_prec: input_prec });
        }
        let achieved = out.rel_accuracy_bits();
        let missing = if achieved.is_finite() { (prec as f64 - achieved).max(0.0) } else { input_prec as f64 };
        let next = (input_prec as f64 + missing + 32.0).max(2.0 * input_prec as f64);
        input_prec = next.min(MAX_DECIMAL_INPUT_PREC as f64) as u32;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn q(s: &str) -> Rational {
        Decimal::parse(s).unwrap().as_rational().clone()
    }

    #[test]
    fn parses_exactly() {
        assert_eq!(q("2.5"), Rational::from((5, 2)));
        assert_eq!(q("-0.125e1"), Rational::from((-5, 4)));
        assert_eq!(q(".1"), Rational::from((1, 10)));
        assert_eq!(q("1000E-3"), Rational::from(1));
        assert_eq!(q("+7."), Rational::from(7));
        assert_eq!(q("-0"), Rational::new());
        assert_eq!(q("  3.83170597020751231561  "), Rational::from((383170597020751231561u128, 10u128.pow(20))));
        for bad in ["", ".", "e5", "1e", "1e+", "nan", "inf", "0x10", "1.2.3", "1 2", "--1", "1e99999999999999999999"] {
            assert!(Decimal::parse(bad).is_err(), "{bad:?} accepted");
        }
        assert!(Decimal::parse("1e100001").is_err());
        assert!(Decimal::parse("1e-100002").is_err());
        assert!(Decimal::parse("1e-100000").is_ok());
    }

    #[test]
    fn binary_fractions_are_exact() {
        for (s, bits) in [("2.5", 3), ("0.375", 2), ("1e3", 7), ("-1048576", 1), ("0", 1)] {
            let d = Decimal::parse(s).unwrap();
            assert!(d.is_binary_fraction(), "{s}");
            let b = d.to_ball(2);
            assert!(b.is_exact(), "{s}: {b:?}");
            assert!(b.prec() >= bits);
            assert_eq!(Rational::from(b.mid().to_rational().unwrap()), *d.as_rational());
        }
        // 2^-200 + 1, typed in full: exact with 201 midpoint bits at any requested precision.
        // 2^-200 = 5^200 / 10^200.
        let five = Integer::from(Integer::u_pow_u(5, 200)).to_string_radix(10);
        let text = format!("1.{five:0>200}");
        let d = Decimal::parse(&text).unwrap();
        let b = d.to_ball(53);
        assert!(b.is_exact() && b.prec() == 201, "{b:?}");
    }

    #[test]
    fn other_decimals_are_contained() {
        for s in ["0.1", "3.83170597020751231561", "-1e-30", "123456789.123456789123456789", "7e-100000"] {
            let d = Decimal::parse(s).unwrap();
            assert!(!d.is_binary_fraction(), "{s}");
            for prec in [2, 53, 64, 300] {
                let b = d.to_ball(prec);
                assert!(!b.is_exact());
                // |mid - q| <= rad, checked in exact rational arithmetic.
                let mid = b.mid().to_rational().unwrap();
                let rad = b.rad().to_rational().unwrap();
                let diff = Rational::from(&mid - d.as_rational()).abs();
                assert!(diff <= rad, "{s} at {prec}: {b:?}");
                assert!(b.meets_rel(prec.saturating_sub(2)));
            }
        }
    }

    #[test]
    fn refinement_reaches_the_target() {
        // f(x) = x - 0.1 at the decimal 0.1000000000000000000000001: needs input bits ~ 80 + prec.
        let d = Decimal::parse("0.1000000000000000000000001").unwrap();
        let tenth = Decimal::parse("0.1").unwrap();
        let mut calls = 0;
        let out = eval_at_decimals(&[d, tenth], 53, |b| {
            calls += 1;
            Ok(b[0].sub(&b[1]))
        })
        .unwrap();
        assert!(out.meets_rel(53), "{out:?}");
        assert!(out.contains(&Float::with_val(200, Float::parse("1e-25").unwrap())));
        assert!(calls >= 2);
        // Exact inputs: one call.
        let mut calls = 0;
        let two = Decimal::parse("2").unwrap();
        eval_at_decimals(&[two], 53, |b| {
            calls += 1;
            Ok(b[0].clone())
        })
        .unwrap();
        assert_eq!(calls, 1);
    }

    #[test]
    fn a_ball_that_never_meets_prec_is_an_error_at_the_cap() {
        // f ignores how tight its inputs are (a radius of 2^-20 whatever the input
        // precision): the loop raises the input precision to the cap and then says
        // so, instead of returning the wide ball as if it met 53 bits
        let tenth = Decimal::parse("0.1").unwrap();
        let mut calls = 0;
        let r = eval_at_decimals(&[tenth], 53, |b| {
            calls += 1;
            let mut out = b[0].clone();
            out.add_error(&Float::with_val(53, 2f64.powi(-20)));
            Ok(out)
        });
        assert!(matches!(r, Err(crate::error::Error::PrecisionExhausted { working_prec, .. }) if working_prec == MAX_DECIMAL_INPUT_PREC), "{r:?}");
        assert!(calls > 1 && calls < 20, "{calls} calls");
    }

    #[test]
    fn decimal_output_encloses_in_every_format() {
        // rug prints "123456.75", "1.5e-3", "1.0e300", "-7.0e-5000": the half unit of the
        // last digit is read from each form; radii outside the f64 range go through MPFR.
        let texts = ["2.5", "123456.75", "0.001", "1e300", "-7e-5000", "9.99999999999999999999999999999999999999999999e9", "1e-320", "3e100000"];
        for (i, t) in texts.iter().enumerate() {
            for (digits, rad) in [(1usize, 0.0), (7, 1e-30), (42, 0.0), (42, 3.5e-44)] {
                let x = Float::with_val(180, Float::parse(t).unwrap()) / 3u32;
                let mut b = Ball::from_float(&x, 180);
                b.add_error(&Float::with_val(53, rad));
                let (m, r) = b.to_decimal(digits);
                let mid = Float::with_val(400, Float::parse(&m).unwrap());
                let rr = Float::with_val(400, Float::parse(&r).unwrap());
                // encloses the exact midpoint with room for the input radius
                let d = Float::with_val(400, &x - &mid).abs() + rad;
                assert!(d <= rr, "{i} {t} digits={digits}: {m} +/- {r} vs {x}");
                // and is no wider than the radius plus one unit of the last digit (and 3e-5 for the rounding up)
                let unit = Float::with_val(400, x.abs_ref()) * Float::with_val(400, Float::i_pow_u(10, digits as u32 - 1)).recip() * 10u32;
                let limit = (Float::with_val(400, rad) + unit) * 1.00003f64;
                assert!(rr <= limit, "{i} {t} digits={digits}: {r} > {limit}");
            }
        }
        let mut z = Ball::from_float(&Float::new(53), 53);
        z.add_error(&Float::with_val(53, 1e-10));
        let (m, r) = z.to_decimal(10);
        assert_eq!(m, "0");
        assert!(Float::with_val(100, Float::parse(&r).unwrap()) >= 1e-10);
    }
}
