//! Fixed-point numbers of `L` 64-bit limbs, the arithmetic of [`super`]'s kernels.
//!
//! A value is `X 2^-F` with `F = 64 L - 2` fractional bits and `X < 2^(64 L)` an
//! unsigned integer stored little-endian in `[u64; L]`: the range is `[0, 4)` ("Q2").
//! Every operation rounds toward zero (truncates), so [`div_small`] errs by less than
//! one unit of `2^-F` (an *ulp* below) and [`mul`] by less than `1 + 2^-57` ulps, and
//! [`add`] and [`sub`] are exact; the callers keep every value below 4 and never subtract a larger value,
//! and count the ulps in their error bounds.
//!
//! The reduction step needs one more limb for the integer part of the argument:
//! [`Wide`] values are `Y 2^-F` with `Y < 2^(64 (L + 1))`, and the low `L` limbs of a
//! wide value below 1 are its Q2 form.

/// Largest number of limbs (`F = 510` fractional bits).
pub(crate) const MAX_LIMBS: usize = 8;

/// `2^F` (the value 1) in Q2 with `L` limbs.
#[inline]
pub(crate) fn one<const L: usize>() -> [u64; L] {
    let mut x = [0u64; L];
    x[L - 1] = 1 << 62;
    x
}

/// The Q2 product `X Y 2^-F`, truncated: a short product that omits the partial
/// products `x_i y_j` with `i + j <= L - 3` (each below `2^(64 (L - 1))`, at most 32 of
/// them: together below `2^-57` ulp), then the floor. It errs by less than
/// `1 + 2^-57` ulps, never upward. The caller guarantees that the product is below 4.
#[inline(always)]
pub(crate) fn mul<const L: usize>(x: &[u64; L], y: &[u64; L]) -> [u64; L] {
    let mut p = [0u64; 2 * MAX_LIMBS];
    for i in 0..L {
        let mut carry: u64 = 0;
        let xi = x[i] as u128;
        if xi == 0 {
            continue;
        }
        for j in (L.saturating_sub(2 + i))..L {
            let t = xi * y[j] as u128 + p[i + j] as u128 + carry as u128;
            p[i + j] = t as u64;
            carry = (t >> 64) as u64;
        }
        p[i + L] = carry;
    }
    // p >> (64 L - 2) = p >> (64 (L - 1) + 62)
    let mut z = [0u64; L];
    for (i, zi) in z.iter_mut().enumerate() {
        *zi = (p[L - 1 + i] >> 62) | (p[L + i] << 2);
    }
    z
}

/// A divisor `d > 0` prepared for division by multiplication: `d` shifted left until
/// its top bit is set, and the reciprocal `v = floor((2^128 - 1) / dn) - 2^64`
/// (N. Moller and T. Granlund, "Improved division by invariant integers", IEEE Trans.
/// Computers 60, 2011, Algorithm 4): a two-limb by one-limb division then costs two
/// multiplications instead of a hardware (or `__udivti3`) division.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Divisor {
    shift: u32,
    dn: u64,
    v: u64,
}

impl Divisor {
    pub(crate) fn new(d: u64) -> Divisor {
        assert!(d > 0, "division by zero");
        let shift = d.leading_zeros();
        let dn = d << shift;
        let v = (u128::MAX / dn as u128 - (1u128 << 64)) as u64;
        Divisor { shift, dn, v }
    }

    /// `(floor(u / dn), u mod dn)` for `u = u1 2^64 + u0`, `u1 < dn`.
    #[inline(always)]
    fn div_2by1(&self, u1: u64, u0: u64) -> (u64, u64) {
        let p = self.v as u128 * u1 as u128;
        let q = p.wrapping_add(((u1 as u128) << 64) | u0 as u128);
        let (mut q1, q0) = (((q >> 64) as u64).wrapping_add(1), q as u64);
        let mut r = u0.wrapping_sub(q1.wrapping_mul(self.dn));
        if r > q0 {
            q1 = q1.wrapping_sub(1);
            r = r.wrapping_add(self.dn);
        }
        if r >= self.dn {
            q1 += 1;
            r -= self.dn;
        }
        (q1, r)
    }
}

impl Divisor {
    /// `X <- floor(X / d)` for `X` given by a little-endian slice of any length, in
    /// place (each limb is read before it is overwritten: the loop runs downward and
    /// limb `i` needs limbs `i` and `i - 1`).
    pub(crate) fn div_slice_in_place(&self, x: &mut [u64]) {
        let n = x.len();
        if n == 0 {
            return;
        }
        let sh = self.shift;
        let mut rem = if sh == 0 { 0 } else { x[n - 1] >> (64 - sh) };
        for i in (0..n).rev() {
            let limb = if sh == 0 {
                x[i]
            } else if i == 0 {
                x[0] << sh
            } else {
                (x[i] << sh) | (x[i - 1] >> (64 - sh))
            };
            let (q, r) = self.div_2by1(rem, limb);
            x[i] = q;
            rem = r;
        }
    }
}

/// `floor(X / d)` (error below one ulp).
#[inline(always)]
pub(crate) fn div_small<const L: usize>(x: &[u64; L], d: &Divisor) -> [u64; L] {
    let mut z = [0u64; L];
    let sh = d.shift;
    // X 2^sh, limb by limb from the top; the limb above X's top one is below 2^sh <= dn
    let limb = |i: usize| -> u64 {
        if sh == 0 {
            x[i]
        } else if i == 0 {
            x[0] << sh
        } else {
            (x[i] << sh) | (x[i - 1] >> (64 - sh))
        }
    };
    let mut rem = if sh == 0 { 0 } else { x[L - 1] >> (64 - sh) };
    for i in (0..L).rev() {
        let (q, r) = d.div_2by1(rem, limb(i));
        z[i] = q;
        rem = r;
    }
    z
}

/// `X + Y` (exact; the caller keeps the sum below 4).
#[inline]
pub(crate) fn add<const L: usize>(x: &[u64; L], y: &[u64; L]) -> [u64; L] {
    let mut z = [0u64; L];
    let mut carry = false;
    for i in 0..L {
        let (s1, c1) = x[i].overflowing_add(y[i]);
        let (s2, c2) = s1.overflowing_add(carry as u64);
        z[i] = s2;
        carry = c1 || c2;
    }
    debug_assert!(!carry);
    z
}

/// `X - Y` for `X >= Y` (exact).
#[inline]
pub(crate) fn sub<const L: usize>(x: &[u64; L], y: &[u64; L]) -> [u64; L] {
    let mut z = [0u64; L];
    let mut borrow = false;
    for i in 0..L {
        let (d1, b1) = x[i].overflowing_sub(y[i]);
        let (d2, b2) = d1.overflowing_sub(borrow as u64);
        z[i] = d2;
        borrow = b1 || b2;
    }
    debug_assert!(!borrow);
    z
}

/// Whether `X >= Y`.
#[inline]
pub(crate) fn ge(x: &[u64], y: &[u64]) -> bool {
    for i in (0..x.len()).rev() {
        if x[i] != y[i] {
            return x[i] > y[i];
        }
    }
    true
}

/// A signed Q2 value `(-1)^neg X 2^-F`, `X < 2^(64 L)`: the magnitude as above and a
/// sign. [`Signed::mul`] errs by less than `1 + 2^-57` ulps (toward zero), [`Signed::add`]
/// and [`Signed::sub`] are exact; the caller keeps every magnitude below 4.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Signed<const L: usize> {
    pub(crate) mag: [u64; L],
    pub(crate) neg: bool,
}

impl<const L: usize> Signed<L> {
    pub(crate) const ZERO: Signed<L> = Signed { mag: [0; L], neg: false };

    /// The product (a truncated [`mul`] of the magnitudes).
    #[inline]
    pub(crate) fn mul(&self, o: &Signed<L>) -> Signed<L> {
        Signed { mag: mul(&self.mag, &o.mag), neg: self.neg != o.neg }
    }

    /// The exact sum.
    #[inline]
    pub(crate) fn add(&self, o: &Signed<L>) -> Signed<L> {
        if self.neg == o.neg {
            Signed { mag: add(&self.mag, &o.mag), neg: self.neg }
        } else if ge(&self.mag, &o.mag) {
            Signed { mag: sub(&self.mag, &o.mag), neg: self.neg }
        } else {
            Signed { mag: sub(&o.mag, &self.mag), neg: o.neg }
        }
    }

    /// The exact difference.
    #[inline]
    pub(crate) fn sub(&self, o: &Signed<L>) -> Signed<L> {
        self.add(&Signed { mag: o.mag, neg: !o.neg })
    }
}

/// A wide value: `L + 1` limbs of which only the first `L + 1` entries are used.
pub(crate) type Wide = [u64; MAX_LIMBS + 1];

/// `floor(D 2^sh)` into `n` limbs, for the integer `D` given by its little-endian limbs.
/// Returns `None` when the result does not fit in `n` limbs. Bits shifted out below are
/// dropped (truncation).
pub(crate) fn shifted(d: &[u64], sh: i64, n: usize) -> Option<Wide> {
    let mut out: Wide = [0; MAX_LIMBS + 1];
    let q = sh.div_euclid(64);
    let r = sh.rem_euclid(64) as u32;
    // out limb i takes D's bits from 64 i - sh: limbs i - q and i - q - 1
    let limb = |k: i64| -> u64 {
        if k < 0 || k as usize >= d.len() {
            0
        } else {
            d[k as usize]
        }
    };
    // Every bit of D must land below limb n (checked on D's top limb).
    let top_pos = (d.len() as i64 - 1) * 64 + (64 - d[d.len() - 1].leading_zeros() as i64) + sh;
    if top_pos > 64 * n as i64 {
        return None;
    }
    for (i, o) in out.iter_mut().take(n).enumerate() {
        let k = i as i64 - q;
        *o = if r == 0 { limb(k) } else { (limb(k) << r) | (limb(k - 1) >> (64 - r)) };
    }
    Some(out)
}

/// `X * n` for `X` of `len` limbs and a small multiplier; the product must fit in `len + 1`
/// limbs (returned in a [`Wide`]-sized buffer of `len + 1` limbs, plus one spare).
pub(crate) fn mul_small(x: &[u64], n: u64) -> [u64; MAX_LIMBS + 3] {
    let mut z = [0u64; MAX_LIMBS + 3];
    let mut carry: u64 = 0;
    for (i, &xi) in x.iter().enumerate() {
        let t = xi as u128 * n as u128 + carry as u128;
        z[i] = t as u64;
        carry = (t >> 64) as u64;
    }
    z[x.len()] = carry;
    z
}

#[cfg(test)]
mod tests {
    use super::*;
    use rug::Integer;

    fn int(x: &[u64]) -> Integer {
        Integer::from_digits(x, rug::integer::Order::Lsf)
    }

    #[test]
    fn mul_and_div_truncate_within_one_ulp() {
        let mut s: u64 = 0x9e3779b97f4a7c15;
        let mut next = || {
            s ^= s << 13;
            s ^= s >> 7;
            s ^= s << 17;
            s
        };
        for _ in 0..200 {
            let mut x = [0u64; 3];
            let mut y = [0u64; 3];
            for i in 0..3 {
                x[i] = next();
                y[i] = next();
            }
            x[2] >>= 2; // below 1
            y[2] >>= 1; // below 2
            let z = mul(&x, &y);
            let exact: Integer = int(&x) * int(&y);
            let f = 64 * 3 - 2;
            let expect: Integer = exact >> f;
            // the short product is the floor, or one below it
            let gap = expect - int(&z);
            assert!(gap == 0 || gap == 1, "{gap}");
            for d in [next() % 1000 + 1, next() >> (next() % 64), 1, u64::MAX] {
                let d = d.max(1);
                let q = div_small(&x, &Divisor::new(d));
                assert_eq!(int(&q), int(&x) / d, "{d}");
                let full = [next(), next(), next()];
                assert_eq!(int(&div_small(&full, &Divisor::new(d))), int(&full) / d, "{d}");
                let mut long: Vec<u64> = (0..57).map(|_| next()).collect();
                let expect = int(&long) / d;
                Divisor::new(d).div_slice_in_place(&mut long);
                assert_eq!(int(&long), expect, "{d}");
            }
            assert_eq!(int(&sub(&add(&x, &y), &y)), int(&x));
        }
    }

    #[test]
    fn shifts_place_bits_and_refuse_overflow() {
        let d = [0x8000_0000_0000_0001u64, 0x3];
        let v = shifted(&d, 70, 3).unwrap();
        assert_eq!(int(&v[..3]), int(&d) << 70u32);
        let v = shifted(&d, -3, 3).unwrap();
        assert_eq!(int(&v[..3]), int(&d) >> 3u32);
        assert!(shifted(&d, 128, 3).is_none());
    }
}
