//! `Mag`: a non-negative upper bound `man * 2^exp` with an f64 mantissa and a
//! wide exponent, the radius type of [`Ball`](super::Ball).
//!
//! Every operation rounds upward (or, for [`Mag::sub_lower`], downward): f64
//! arithmetic is correctly rounded, so moving the rounded result one ulp in the
//! safe direction (`next_up`/`next_down`) gives a rigorous bound. Mantissas stay
//! in `[0.5, 1)`, so no f64 operation here can overflow or underflow; the `i64`
//! exponent never does in practice. This is Arb's `mag_t` with a 53-bit mantissa.

use rug::Float;

/// Non-negative magnitude bound `man * 2^exp`; `man` in `[0.5, 1)`, or zero, or infinity.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Mag {
    man: f64,
    exp: i64,
}

/// `(m, e)` with `x = m 2^e`, `m` in `[0.5, 1)`, for finite `x > 0`.
fn frexp(x: f64) -> (f64, i64) {
    let bits = x.to_bits();
    let biased = ((bits >> 52) & 0x7ff) as i64;
    if biased == 0 {
        // subnormal: scale into the normal range first
        let (m, e) = frexp(x * 2f64.powi(64));
        return (m, e - 64);
    }
    let m = f64::from_bits((bits & !(0x7ffu64 << 52)) | (1022u64 << 52));
    (m, biased - 1022)
}

/// The significand limbs `D` and exponent `e` of a finite nonzero float:
/// `|x| = D 2^(e - 64 len(D))`, the top limb with its high bit set.
pub(crate) fn raw_parts(x: &Float) -> (&[u64], i64) {
    const _: () = assert!(std::mem::size_of::<gmp_mpfr_sys::gmp::limb_t>() == 8 || cfg!(not(target_pointer_width = "64")));
    // SAFETY: `x` is a valid, finite, nonzero MPFR number; its significand has
    // `ceil(prec / bits_per_limb)` limbs at `d`, borrowed for the lifetime of `x`.
    unsafe {
        let r = &*x.as_raw();
        let k = (r.prec as usize).div_ceil(64);
        (std::slice::from_raw_parts(r.d.as_ptr() as *const u64, k), r.exp as i64)
    }
}

/// The top limb of a finite nonzero float's significand and its exponent:
/// `|x| = 0.top... 2^e`.
fn top_limb(x: &Float) -> (u64, i64) {
    let (d, e) = raw_parts(x);
    (d[d.len() - 1], e)
}

/// `2^-d` for `0 <= d <= 60`, exact, built from its bits (`powi` is a libcall).
#[inline]
fn pow2_neg(d: i64) -> f64 {
    debug_assert!((0..=60).contains(&d));
    f64::from_bits(((1023 - d) as u64) << 52)
}

impl Mag {
    /// Zero.
    pub const ZERO: Mag = Mag { man: 0.0, exp: 0 };

    /// Infinity (an unbounded radius).
    pub fn inf() -> Mag {
        Mag { man: f64::INFINITY, exp: 0 }
    }

    fn norm(man: f64, exp: i64) -> Mag {
        if man == 0.0 {
            Mag::ZERO
        } else if !man.is_finite() {
            Mag::inf()
        } else {
            let (m, e) = frexp(man);
            Mag { man: m, exp: exp + e }
        }
    }

    /// `2^e`, in constant context.
    pub const fn pow2_const(e: i64) -> Mag {
        Mag { man: 0.5, exp: e + 1 }
    }

    /// `2^e`.
    pub fn pow2(e: i64) -> Mag {
        Mag { man: 0.5, exp: e + 1 }
    }

    /// Upper bound of `|x|` for an f64 (exact).
    pub fn from_f64(x: f64) -> Mag {
        Mag::norm(x.abs(), 0)
    }

    /// Upper bound of `|x|`: the top 53 bits of the significand plus one unit of the
    /// 53rd, read from the limbs (no MPFR call; at most `2^-52` relative above `|x|`).
    pub fn from_float_up(x: &Float) -> Mag {
        if x.is_zero() {
            return Mag::ZERO;
        }
        if !x.is_finite() {
            return Mag::inf();
        }
        let (top, e) = top_limb(x);
        // |x| = 0.top... 2^e < (floor(top / 2^11) + 1) 2^(e - 53); the sum is <= 2^53 (exact)
        let m = ((top >> 11) + 1) as f64 * pow2_neg(53);
        if m == 1.0 {
            Mag { man: 0.5, exp: e + 1 }
        } else {
            Mag { man: m, exp: e }
        }
    }

    /// Lower bound of `|x|`: the top 53 bits of the significand, truncated.
    pub fn from_float_down(x: &Float) -> Mag {
        if x.is_zero() || x.is_nan() {
            return Mag::ZERO;
        }
        if x.is_infinite() {
            return Mag::inf();
        }
        let (top, e) = top_limb(x);
        Mag { man: (top >> 11) as f64 * pow2_neg(53), exp: e }
    }

    /// `self` as an f64, exactly, when its exponent is in the normal range of f64
    /// (`None` otherwise, and for infinity).
    pub fn to_f64_exact(&self) -> Option<f64> {
        if self.man == 0.0 {
            return Some(0.0);
        }
        if !self.man.is_finite() || !(-1000..=1000).contains(&self.exp) {
            return None;
        }
        Some(self.man * f64::from_bits(((1023 + self.exp) as u64) << 52))
    }

    /// The exact value as a 53-bit float (infinite for [`Mag::inf`]).
    pub fn to_float(&self) -> Float {
        if !self.man.is_finite() {
            return Float::with_val(53, rug::float::Special::Infinity);
        }
        let mut f = Float::with_val(53, self.man);
        let e = self.exp.clamp(i32::MIN as i64 / 2, i32::MAX as i64 / 2) as i32;
        f <<= e;
        f
    }

    /// An f64 `>= self` (infinity on overflow).
    pub fn to_f64_up(&self) -> f64 {
        if self.man == 0.0 {
            return 0.0;
        }
        if !self.man.is_finite() || self.exp > 1024 {
            return f64::INFINITY;
        }
        if self.exp < -1000 {
            return f64::MIN_POSITIVE;
        }
        (self.man * 2f64.powi(self.exp as i32)).next_up()
    }

    /// `log2(self)` (approximate; `-inf` for zero).
    pub fn log2(&self) -> f64 {
        if self.man == 0.0 {
            f64::NEG_INFINITY
        } else if !self.man.is_finite() {
            f64::INFINITY
        } else {
            self.man.log2() + self.exp as f64
        }
    }

    /// Whether zero.
    pub fn is_zero(&self) -> bool {
        self.man == 0.0
    }

    /// Whether finite.
    pub fn is_finite(&self) -> bool {
        self.man.is_finite()
    }

    /// `self + o`, rounded up.
    pub fn add(self, o: Mag) -> Mag {
        if self.is_zero() {
            return o;
        }
        if o.is_zero() {
            return self;
        }
        if !self.is_finite() || !o.is_finite() {
            return Mag::inf();
        }
        let (big, small) = if self.exp >= o.exp { (self, o) } else { (o, self) };
        let d = big.exp - small.exp;
        if d > 60 {
            return Mag::norm(big.man.next_up(), big.exp);
        }
        // both mantissas in [0.5, 1): the sum is in [0.5, 2), so one halving (exact)
        // normalises it, without the general frexp
        let sum = (big.man + small.man * pow2_neg(d)).next_up();
        if sum < 1.0 {
            Mag { man: sum, exp: big.exp }
        } else {
            Mag { man: sum * 0.5, exp: big.exp + 1 }
        }
    }

    /// `self * o`, rounded up.
    pub fn mul(self, o: Mag) -> Mag {
        if self.is_zero() || o.is_zero() {
            return Mag::ZERO;
        }
        if !self.is_finite() || !o.is_finite() {
            return Mag::inf();
        }
        // the product of two mantissas in [0.5, 1) is in [0.25, 1): one doubling (exact)
        let prod = (self.man * o.man).next_up();
        if prod >= 1.0 {
            Mag { man: prod * 0.5, exp: self.exp + o.exp + 1 }
        } else if prod >= 0.5 {
            Mag { man: prod, exp: self.exp + o.exp }
        } else {
            Mag { man: prod * 2.0, exp: self.exp + o.exp - 1 }
        }
    }

    /// `self * o`, rounded down (for lower bounds).
    pub fn mul_lower(self, o: Mag) -> Mag {
        if self.is_zero() || o.is_zero() {
            return Mag::ZERO;
        }
        if !self.is_finite() || !o.is_finite() {
            return Mag::inf();
        }
        Mag::norm((self.man * o.man).next_down(), self.exp + o.exp)
    }

    /// `self / o` rounded up, `o` a (positive) lower bound of the divisor.
    pub fn div(self, o: Mag) -> Mag {
        if self.is_zero() {
            return Mag::ZERO;
        }
        if o.is_zero() || !self.is_finite() {
            return Mag::inf();
        }
        if !o.is_finite() {
            return Mag::ZERO;
        }
        Mag::norm((self.man / o.man).next_up(), self.exp - o.exp)
    }

    /// `max(self - o, 0)`, rounded down (for lower bounds).
    pub fn sub_lower(self, o: Mag) -> Mag {
        if o.is_zero() {
            return self;
        }
        if self.le(&o) {
            return Mag::ZERO;
        }
        if !self.is_finite() {
            return self;
        }
        let d = self.exp - o.exp;
        if d > 60 {
            return Mag::norm(self.man.next_down(), self.exp);
        }
        let diff = self.man - o.man * pow2_neg(d);
        if diff <= 0.0 {
            return Mag::ZERO;
        }
        Mag::norm(diff.next_down().max(0.0), self.exp)
    }

    /// `sqrt(self^2 + o^2)`, rounded up when `up`, down otherwise (f64 arithmetic on
    /// the mantissas: each operation is correctly rounded, and stepping its result one
    /// ulp in the safe direction bounds it).
    pub fn hypot(self, o: Mag, up: bool) -> Mag {
        if !self.is_finite() || !o.is_finite() {
            return Mag::inf();
        }
        let (big, small) = if o.le(&self) { (self, o) } else { (o, self) };
        if small.is_zero() {
            return big;
        }
        let d = big.exp - small.exp;
        if d > 60 {
            // big <= hypot <= big + small
            return if up { big.add(small) } else { big };
        }
        // big.man in [0.5, 1), small scaled by 2^-d exactly: the sum of squares is in
        // [0.25, 2), its root in [0.5, 1.5)
        let (x, y) = (big.man, small.man * pow2_neg(d));
        let step = |v: f64| if up { v.next_up() } else { v.next_down() };
        let h = step(step(step(x * x) + step(y * y)).sqrt());
        Mag::norm(h, big.exp)
    }

    /// `self * 2^e` (exact).
    pub fn mul_2exp(self, e: i64) -> Mag {
        if self.is_zero() || !self.is_finite() {
            self
        } else {
            Mag { man: self.man, exp: self.exp + e }
        }
    }

    /// `self <= o`.
    pub fn le(&self, o: &Mag) -> bool {
        if self.is_zero() {
            return true;
        }
        if o.is_zero() {
            return false;
        }
        if !o.is_finite() {
            return true;
        }
        if !self.is_finite() {
            return false;
        }
        if self.exp != o.exp {
            self.exp < o.exp
        } else {
            self.man <= o.man
        }
    }

    /// The larger of two bounds.
    pub fn max(self, o: Mag) -> Mag {
        if self.le(&o) {
            o
        } else {
            self
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn operations_bound_exact_results() {
        let a = Mag::from_f64(0.1);
        let b = Mag::from_f64(3.0e-20);
        let exact_sum = Float::with_val(200, 0.1) + Float::with_val(200, 3.0e-20);
        assert!(a.add(b).to_float() >= exact_sum);
        let exact_prod = Float::with_val(200, 0.1) * Float::with_val(200, 3.0e-20);
        assert!(a.mul(b).to_float() >= exact_prod);
        let exact_q = Float::with_val(200, 0.1) / Float::with_val(200, 3.0e-20);
        assert!(a.div(b).to_float() >= exact_q);
        let exact_d = Float::with_val(200, 0.1) - Float::with_val(200, 3.0e-20);
        assert!(a.sub_lower(b).to_float() <= exact_d);
        assert!(b.sub_lower(a).is_zero());
        let big = Mag::pow2(100000);
        assert!(big.mul(big).log2() > 199_999.0);
        let f = Float::with_val(300, 1) / 3u32;
        assert!(Mag::from_float_up(&f).to_float() >= f);
        assert!(Mag::from_float_down(&f).to_float() <= f);
    }

    #[test]
    fn hypot_brackets_the_exact_value() {
        let cases = [(0.75, 0.6), (3.0, 4.0), (1.0e-30, 2.5), (7.0, 1.0e-25), (0.1, 0.1), (1.0, 0.0), (0.0, 0.3)];
        for (x, y) in cases {
            let (a, b) = (Mag::from_f64(x), Mag::from_f64(y));
            let exact = Float::with_val(300, Float::with_val(300, x).hypot(&Float::with_val(300, y)));
            let (up, down) = (a.hypot(b, true), a.hypot(b, false));
            assert!(up.to_float() >= exact && down.to_float() <= exact, "{x} {y}");
            assert!(up.log2() - down.log2() < 1e-12, "{x} {y}: tight");
        }
        assert!(!Mag::inf().hypot(Mag::from_f64(1.0), true).is_finite());
    }
}
