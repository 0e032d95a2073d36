//! The decimal text of an MPFR number of at most 128 bits to at most 25 significant
//! digits, exactly as rug's `to_string_radix(10, Some(n))` prints it (round to
//! nearest), without MPFR's `mpfr_get_str`.
//!
//! A ball's midpoint is most of the cost of an answer's text at 53 and 64 bits: at 64
//! bits a midpoint has 84 bits and 23 digits are printed, about 4 500 instructions
//! through MPFR (docs/quadrature.md, "`eval`'s own cost per request"); this takes about
//! 1 600.
//!
//! # Method
//!
//! With `|x| = m 2^e`, `m` normalised to 128 bits, `k = floor(log10 |x|)` and `n`
//! digits, the digits are `D = round(s)`, `s = |x| 10^(n-1-k)` in `[10^(n-1), 10^n)`
//! (`D = 10^n` after rounding is `10^(n-1)` with `k + 1`), as in [`super::six_digits`]
//! with 128-bit mantissas: `10^q` by binary powering from 10 (exact) or from `0.1`
//! rounded down to 128 bits (relative error below `2^-127`), each product cut to its top
//! 128 bits (below `2^-127` each), so for `|q| <= 1023` and at most 20 products the
//! error is below `1023 * 21 * 2^-127 < 2^-112`. The product `m M` is exact in 256
//! bits, so `|s' - s| < s 2^-112 < 2^-28` for `s < 10^25 < 2^84`. Rounding to nearest
//! is decided by `s'` unless its fraction lies within `2^-26` of `1/2` (MPFR breaks an
//! exact tie to even: those all fall there); there, and outside the ranges above, the
//! answer is `None` and the caller asks MPFR. The text follows rug: the sign, then the
//! digits with the point after the `k + 1`-th when `0 <= k < n` (no point when `k =
//! n - 1`) and no exponent, else the point after the first digit and `e{k}`. A test
//! compares the two on random numbers and next to ties.

use rug::Float;

/// `x.to_string_radix(10, Some(n))`, or `None` where the caller must ask MPFR (`x`
/// zero, not finite, of more than 128 bits or far from 1, `n` above 25, or the rounding
/// too close to call; see the module docs).
pub(super) fn float_digits(x: &Float, n: usize) -> Option<String> {
    if !(1..=25).contains(&n) {
        return None;
    }
    let sig = x.get_significand()?;
    let exp = i64::from(x.get_exp()?);
    if sig.significant_bits() > 128 || exp.abs() > 3000 {
        return None;
    }
    // |x| = m 2^e with m's top bit at 127
    let mut m = sig.to_u128()?;
    let mut e = exp - i64::from(sig.significant_bits());
    let lead = m.leading_zeros();
    m <<= lead;
    e -= i64::from(lead);
    let ten_n = 10u128.pow(n as u32);
    let mut k = ((e as f64 + (m as f64).log2()) * std::f64::consts::LOG10_2).floor() as i64;
    for _ in 0..3 {
        let p = pow10((n as i64 - 1 - k) as i32)?;
        let (hi, _) = mul_wide(m, p.mant);
        // s' = (hi 2^128 + lo) 2^(e + p.exp); its fraction is decided by hi alone
        let sh = -(e + i64::from(p.exp)) - 128;
        if !(30..128).contains(&sh) {
            return None;
        }
        let (whole, frac) = (hi >> sh, hi & ((1u128 << sh) - 1));
        if whole < ten_n / 10 {
            k -= 1;
            continue;
        }
        if whole >= ten_n {
            k += 1;
            continue;
        }
        let half = 1u128 << (sh - 1);
        if frac.abs_diff(half) <= 1u128 << (sh - 26) {
            return None;
        }
        let mut d = whole + u128::from(frac > half);
        if d == ten_n {
            d = ten_n / 10;
            k += 1;
        }
        return Some(text(x.is_sign_negative(), d, n, k));
    }
    None
}

/// rug's layout of the `n` digits `d` of a number `0.d 10^(k+1)` (see the module docs).
fn text(negative: bool, d: u128, n: usize, k: i64) -> String {
    // the digits from two u64 halves (one u128 division instead of one a digit)
    const E19: u128 = 10_000_000_000_000_000_000;
    let mut digits = [b'0'; 25];
    let (mut hi, mut lo) = ((d / E19) as u64, (d % E19) as u64);
    for (i, slot) in digits[..n].iter_mut().rev().enumerate() {
        let v = if i < 19 { &mut lo } else { &mut hi };
        *slot = b'0' + (*v % 10) as u8;
        *v /= 10;
    }
    let mut s = Vec::with_capacity(n + 8);
    if negative {
        s.push(b'-');
    }
    let positional = (0..n as i64).contains(&k);
    let point = if positional { k as usize + 1 } else { 1 };
    s.extend_from_slice(&digits[..point]);
    if point < n {
        s.push(b'.');
        s.extend_from_slice(&digits[point..n]);
    }
    if !positional {
        s.push(b'e');
        if k < 0 {
            s.push(b'-');
        }
        let mut e = [0u8; 20];
        let mut at = e.len();
        let mut u = k.unsigned_abs();
        loop {
            at -= 1;
            e[at] = b'0' + (u % 10) as u8;
            u /= 10;
            if u == 0 {
                break;
            }
        }
        s.extend_from_slice(&e[at..]);
    }
    String::from_utf8(s).unwrap_or_default()
}

/// `mant 2^exp`, `mant` with its top bit set.
#[derive(Clone, Copy)]
pub(super) struct Fp {
    pub(super) mant: u128,
    pub(super) exp: i32,
}

/// The 256-bit product `a b` as (high, low) halves.
fn mul_wide(a: u128, b: u128) -> (u128, u128) {
    const LOW: u128 = (1 << 64) - 1;
    let (a1, a0, b1, b0) = (a >> 64, a & LOW, b >> 64, b & LOW);
    let (p00, p01, p10, p11) = (a0 * b0, a0 * b1, a1 * b0, a1 * b1);
    let mid = (p00 >> 64) + (p01 & LOW) + (p10 & LOW);
    ((p11 + (p01 >> 64) + (p10 >> 64) + (mid >> 64)), (p00 & LOW) | (mid << 64))
}

/// `a b` cut to its top 128 bits (relative error below `2^-127`).
fn mul(a: Fp, b: Fp) -> Fp {
    let (hi, lo) = mul_wide(a.mant, b.mant);
    if hi >> 127 == 1 {
        Fp { mant: hi, exp: a.exp + b.exp + 128 }
    } else {
        Fp { mant: (hi << 1) | (lo >> 127), exp: a.exp + b.exp + 127 }
    }
}

/// `10^q` from below, relative error below `2^-112` (module docs); `None` for `|q| > 1023`.
pub(super) fn pow10(q: i32) -> Option<Fp> {
    let mut n = q.unsigned_abs();
    if n > 1023 {
        return None;
    }
    let mut base = if q >= 0 { Fp { mant: 10 << 124, exp: -124 } } else { Fp { mant: u128::MAX / 5 * 4, exp: -131 } };
    let mut r = Fp { mant: 1 << 127, exp: -127 };
    while n > 0 {
        if n & 1 == 1 {
            r = mul(r, base);
        }
        n >>= 1;
        if n > 0 {
            base = mul(base, base);
        }
    }
    Some(r)
}

#[cfg(test)]
mod tests {
    use super::*;
    use rug::ops::Pow;

    /// The same text as rug's `to_string_radix(10, Some(n))` wherever it answers, and an
    /// answer for nearly all numbers: random ones of 24 to 128 bits over `2^-2900 ..
    /// 2^2900` for each digit count 1 to 25, both signs, small integers and powers of
    /// ten; next to the ties between two `n`-digit decimals it declines or agrees.
    #[test]
    fn prints_what_mpfr_prints() {
        let mut x: u64 = 0x2545_F491_4F6C_DD1D;
        let mut next = || {
            x ^= x << 13;
            x ^= x >> 7;
            x ^= x << 17;
            x
        };
        let mut answered = 0;
        let mut tried = 0;
        let check = |f: &Float, n: usize, answered: &mut usize| {
            if let Some(s) = float_digits(f, n) {
                assert_eq!(s, f.to_string_radix(10, Some(n)), "{f:e} at {n} digits");
                *answered += 1;
            }
        };
        for i in 0..40_000u64 {
            let prec = 24 + (next() % 105) as u32;
            let bits = rug::Integer::from(next()) << 64 | next();
            let mut f = Float::with_val(prec, bits);
            f >>= (next() % 5800) as i32 - 2900 + 128;
            if i % 2 == 1 {
                f = -f;
            }
            let n = 1 + (i % 25) as usize;
            tried += 1;
            check(&f, n, &mut answered);
        }
        assert!(answered * 1000 > tried * 999, "answered {answered} of {tried}");
        for v in [1.0, -1.0, 10.0, 12.5, 99.5, 0.1, 1e24, 1e25, 1e23f64.next_down(), 123456.0] {
            for n in 1..=25 {
                check(&Float::with_val(84, v), n, &mut answered);
            }
        }
        for k in -300..=300 {
            check(&Float::with_val(84, Float::with_val(200, 10).pow(k)), 23, &mut answered);
        }
        let before = answered;
        for _ in 0..5_000 {
            // next to a tie: (D + 1/2) 10^k at 84 bits, D of n digits
            let n = 1 + (next() % 25) as usize;
            let d = rug::Integer::from(next()) % rug::Integer::from(10).pow(n as u32);
            let k = (next() % 200) as i32 - 100;
            let tie = (Float::with_val(300, d) + 0.5f64) * Float::with_val(300, 10).pow(k);
            let f = Float::with_val(84, &tie);
            check(&f, n, &mut answered);
            let mut up = f.clone();
            up.next_up();
            check(&up, n, &mut answered);
        }
        assert!(answered - before < 10_000, "some values next to a tie are declined");
        assert_eq!(float_digits(&Float::new(84), 23), None);
        assert_eq!(float_digits(&Float::with_val(84, f64::INFINITY), 23), None);
        assert_eq!(float_digits(&Float::with_val(200, 1.5), 23), None, "more than 128 bits");
        assert_eq!(float_digits(&Float::with_val(84, 1.5), 26), None);
    }
}
