//! Six significant digits of a positive normal f64, exactly as Rust's `{:.5e}`
//! prints them (`2.53774e-22`), without the general formatter.
//!
//! Printing a radius was a third of the cost of an answer's text in `maugis eval`:
//! `{:.5e}` takes about 1 500 instructions where its Grisu step decides, and 4 000 where
//! it falls back to Dragon4's big integers, which it did for the radii of both 64-bit
//! requests measured and does for about one random value in six near `1e-22`
//! (docs/quadrature.md, "`eval`'s own cost per request"); this takes about 850.
//!
//! # Method
//!
//! With `w = m 2^e` (`m < 2^53`) and `k = floor(log10 w)`, the digits are
//! `D = round(s)`, `s = w 10^(5-k)` in `[10^5, 10^6)`, and the text `D[0].D[1..6]e{k}`
//! (`D = 10^6` after rounding is `10^5` with `k + 1`). `10^q` is
//! [`super::float_digits`]'s 128-bit power (relative error below `2^-112`) cut to its
//! top 64 bits `M` (below `2^-63` more), so it errs by less than `2^-62` relative. The
//! product `s' = m M 2^(e + E)` is exact in 128 bits, so `|s' - s| < s 2^-62 < 2^-41`
//! for `s < 2^21`.
//!
//! Rounding to nearest is decided by `s'` unless its fraction lies within `2^-26` of
//! `1/2`; there (and for anything outside the range above) the answer is `None`, and
//! the caller prints with `{:.5e}`. A test compares the two on random values over the
//! whole normal range and on values next to the ties.

use super::float_digits::pow10;

/// `{:.5e}` of `w`, or `None` where the caller must use `format!("{:.5e}", w)`
/// (`w` not positive normal, or the rounding too close to call; see the module docs).
pub(super) fn six_digits(w: f64) -> Option<String> {
    if !(w.is_normal() && w > 0.0) {
        return None;
    }
    let bits = w.to_bits();
    let m = (bits & ((1 << 52) - 1)) | (1 << 52);
    let e = ((bits >> 52) & 0x7ff) as i32 - 1075;
    let mut k = w.log10().floor() as i32;
    for _ in 0..3 {
        let (mant, exp) = pow10_64(5 - k)?;
        let prod = u128::from(m) * u128::from(mant);
        let sh = -(e + exp);
        if !(30..128).contains(&sh) {
            return None;
        }
        let (whole, frac) = (prod >> sh, prod & ((1u128 << sh) - 1));
        if whole < 100_000 {
            k -= 1;
            continue;
        }
        if whole >= 1_000_000 {
            k += 1;
            continue;
        }
        let half = 1u128 << (sh - 1);
        if frac.abs_diff(half) <= 1u128 << (sh - 26) {
            return None;
        }
        let mut d = whole as u32 + u32::from(frac > half);
        if d == 1_000_000 {
            d = 100_000;
            k += 1;
        }
        let mut text = String::with_capacity(14);
        let mut unit = 100_000;
        while unit > 0 {
            text.push(char::from(b'0' + (d / unit % 10) as u8));
            if unit == 100_000 {
                text.push('.');
            }
            unit /= 10;
        }
        text.push('e');
        if k < 0 {
            text.push('-');
        }
        let k = k.unsigned_abs();
        for unit in [100, 10, 1] {
            if k >= unit || unit == 1 {
                text.push(char::from(b'0' + (k / unit % 10) as u8));
            }
        }
        return Some(text);
    }
    None
}

/// `10^q` from below in a 64-bit mantissa: [`pow10`]'s top 64 bits (relative error
/// below `2^-112 + 2^-63 < 2^-62`); `None` for `|q| > 1023`.
fn pow10_64(q: i32) -> Option<(u64, i32)> {
    let p = pow10(q)?;
    Some(((p.mant >> 64) as u64, p.exp + 64))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The same text as `{:.5e}` wherever it answers, and an answer for nearly all
    /// values: random ones over the whole normal range, powers of ten and the range's
    /// ends. Next to the ties between two six-digit decimals it declines (or answers
    /// the same text).
    #[test]
    fn prints_what_std_prints() {
        let mut x: u64 = 0x9E37_79B9_7F4A_7C15;
        let mut next = || {
            x ^= x << 13;
            x ^= x >> 7;
            x ^= x << 17;
            x
        };
        let mut values = vec![f64::MIN_POSITIVE, f64::MAX, 1.0, 9.999995, 9.9999949999, 0.5, 2.53774e-22];
        values.extend((-307..=308).map(|k| 10f64.powi(k)));
        for _ in 0..100_000 {
            // a random normal f64: random mantissa and biased exponent 1..=2046
            let bits = (next() >> 12) | ((1 + next() % 2046) << 52);
            values.push(f64::from_bits(bits));
        }
        let mut declined = 0;
        for &w in &values {
            match six_digits(w) {
                Some(s) => assert_eq!(s, format!("{w:.5e}"), "{w:e}"),
                None => declined += 1,
            }
        }
        assert!(declined * 1000 < values.len(), "declined {declined} of {}", values.len());
        let mut answered = 0;
        for _ in 0..20_000 {
            // next to a tie: (D + 1/2) 10^(k-5) rounded to f64, and its neighbours
            let d = 100_000 + next() % 900_000;
            let k = (next() % 600) as i32 - 300;
            let t = (d as f64 + 0.5) * 10f64.powi(k - 5);
            for w in [t, t.next_up(), t.next_down()].into_iter().filter(|w| w.is_normal()) {
                if let Some(s) = six_digits(w) {
                    assert_eq!(s, format!("{w:.5e}"), "{w:e}");
                    answered += 1;
                }
            }
        }
        assert!(answered < 3 * 20_000, "some values next to a tie are declined");
        assert_eq!(six_digits(0.0), None);
        assert_eq!(six_digits(-1.0), None);
        assert_eq!(six_digits(f64::INFINITY), None);
        assert_eq!(six_digits(f64::MIN_POSITIVE / 2.0), None);
    }
}
