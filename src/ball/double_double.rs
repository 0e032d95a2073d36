//! Double-double arithmetic: an unevaluated sum `hi + lo` of two f64 with
//! `|lo| <= ulp(hi)/2`, about 106 bits, for the f64 paths that must round a
//! cancelling sum correctly (the Bessel form of `u_w`, Miller's recurrence).
//!
//! Error-free transformations: `two_sum` (Knuth), `two_prod` by Veltkamp
//! splitting [Dekker 1971; Hida, Li, Bailey, "Library for double-double and
//! quad-double arithmetic", 2007]. Addition and multiplication are the
//! "sloppy" variants with relative error about `2^-104` (a few units of `u^2`);
//! division uses one Newton correction. These are estimates for fast f64 paths,
//! not certified bounds (those live in [`Ball`](super::Ball)). The *accurate*
//! variants (`add_accurate`, `mul_accurate`, `div_accurate`: Joldes, Muller and
//! Popescu 2017) carry proven relative error bounds, for the certified f64 paths.

use std::ops::{Add, Div, Mul, Neg, Sub};

/// `hi + lo`, non-overlapping.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Dd {
    /// Leading part (the f64 nearest to the value).
    pub hi: f64,
    /// Trailing part.
    pub lo: f64,
}

#[inline]
pub(crate) fn two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    let bb = s - a;
    let e = (a - (s - bb)) + (b - bb);
    (s, e)
}

#[inline]
pub(crate) fn quick_two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    (s, b - (s - a))
}

/// Veltkamp split: `a = hi + lo` with both halves of 26 bits.
#[inline]
fn split(a: f64) -> (f64, f64) {
    const SPLITTER: f64 = 134_217_729.0; // 2^27 + 1
    let t = SPLITTER * a;
    let hi = t - (t - a);
    (hi, a - hi)
}

/// Dekker's exact product `a b = p + e` without a fused multiply-add (the
/// portable x86-64 target has no FMA instruction, and the library call is
/// slower than these 17 flops). Exact unless `a b` over/underflows.
#[inline]
pub(crate) fn two_prod(a: f64, b: f64) -> (f64, f64) {
    let p = a * b;
    let (ah, al) = split(a);
    let (bh, bl) = split(b);
    let e = ((ah * bh - p) + ah * bl + al * bh) + al * bl;
    (p, e)
}

/// How an exact product `a b = p + e` is formed: Dekker's splitting
/// (portable, 17 flops) or one fused multiply-add (2 operations, where the CPU
/// has it; the native f64 special functions pick it at run time). Both are
/// exact, so every result built on them is bit-identical either way.
pub(crate) trait ExactProduct {
    fn two_prod(a: f64, b: f64) -> (f64, f64);

    /// `a b + c` rounded once (fused) or twice (`fl(fl(a b) + c)`): an error
    /// analysis that charges two roundings holds for both. Unlike
    /// [`two_prod`](ExactProduct::two_prod), results differ between the two in
    /// the last bits.
    #[inline(always)]
    fn mul_add(a: f64, b: f64, c: f64) -> f64 {
        a * b + c
    }
}

/// Dekker's splitting, [`two_prod`].
pub(crate) struct Dekker;

/// `p = fl(a b)`, `e = fma(a, b, -p)`; only fast inside a function compiled
/// with the `fma` target feature (elsewhere `mul_add` is a library call).
pub(crate) struct Fused;

impl ExactProduct for Dekker {
    #[inline(always)]
    fn two_prod(a: f64, b: f64) -> (f64, f64) {
        two_prod(a, b)
    }
}

impl ExactProduct for Fused {
    #[inline(always)]
    fn two_prod(a: f64, b: f64) -> (f64, f64) {
        let p = a * b;
        (p, a.mul_add(b, -p))
    }

    #[inline(always)]
    fn mul_add(a: f64, b: f64, c: f64) -> f64 {
        a.mul_add(b, c)
    }
}

/// Defines `fn $name(args) -> ret` that runs `$with` compiled for a CPU
/// feature where the CPU has it (checked at run time; `std` caches the check)
/// and the portable build otherwise:
///
/// * `=> $with` (fused multiply-add): `$with::<Fused>` inside a function
///   compiled with `fma`, else `$with::<Dekker>` (both exact products, so the
///   results are bit-identical);
/// * `=> avx $with`: `$with` inside a function compiled with `avx` (the same
///   operations in three-operand form: bit-identical), else `$with`.
///
/// `$with` must be `#[inline(always)]`, so that the feature reaches its body.
macro_rules! cpu_dispatch {
    ($(#[$attr:meta])* $vis:vis fn $name:ident($($arg:ident: $ty:ty),* $(,)?) -> $ret:ty => $with:ident) => {
        $(#[$attr])*
        $vis fn $name($($arg: $ty),*) -> $ret {
            #[cfg(target_arch = "x86_64")]
            {
                #[target_feature(enable = "fma")]
                unsafe fn fused($($arg: $ty),*) -> $ret {
                    $with::<$crate::ball::Fused>($($arg),*)
                }
                if std::arch::is_x86_feature_detected!("fma") {
                    // SAFETY: the CPU supports FMA (checked just above).
                    return unsafe { fused($($arg),*) };
                }
            }
            $with::<$crate::ball::Dekker>($($arg),*)
        }
    };
    ($(#[$attr:meta])* $vis:vis fn $name:ident($($arg:ident: $ty:ty),* $(,)?) -> $ret:ty => avx $with:ident) => {
        $(#[$attr])*
        $vis fn $name($($arg: $ty),*) -> $ret {
            #[cfg(target_arch = "x86_64")]
            {
                #[target_feature(enable = "avx")]
                unsafe fn with_avx($($arg: $ty),*) -> $ret {
                    $with($($arg),*)
                }
                if std::arch::is_x86_feature_detected!("avx") {
                    // SAFETY: the CPU supports AVX (checked just above).
                    return unsafe { with_avx($($arg),*) };
                }
            }
            $with($($arg),*)
        }
    };
}
pub(crate) use cpu_dispatch;

impl Dd {
    /// Zero.
    pub const ZERO: Dd = Dd { hi: 0.0, lo: 0.0 };
    /// One.
    pub const ONE: Dd = Dd { hi: 1.0, lo: 0.0 };
    /// `2 pi` to ~106 bits.
    pub const TWO_PI: Dd = Dd { hi: std::f64::consts::TAU, lo: 2.4492935982947064e-16 };

    /// An exact f64.
    #[inline]
    pub const fn from_f64(x: f64) -> Dd {
        Dd { hi: x, lo: 0.0 }
    }

    /// Nearest f64.
    #[inline]
    pub fn to_f64(self) -> f64 {
        self.hi + self.lo
    }

    /// The exact difference `a - b` of two doubles.
    #[inline]
    pub fn diff(a: f64, b: f64) -> Dd {
        let (s, e) = two_sum(a, -b);
        Dd { hi: s, lo: e }
    }

    /// The exact product `a * b` of two doubles.
    #[inline]
    pub fn prod(a: f64, b: f64) -> Dd {
        Dd::prod_p::<Dekker>(a, b)
    }

    /// [`Dd::prod`] with the product strategy `P`.
    #[inline(always)]
    pub(crate) fn prod_p<P: ExactProduct>(a: f64, b: f64) -> Dd {
        let (p, e) = P::two_prod(a, b);
        Dd { hi: p, lo: e }
    }

    /// `self * b` for an f64 `b`.
    #[inline]
    pub fn mul_f64(self, b: f64) -> Dd {
        self.mul_f64_p::<Dekker>(b)
    }

    /// [`Dd::mul_f64`] with the product strategy `P`.
    #[inline(always)]
    pub(crate) fn mul_f64_p<P: ExactProduct>(self, b: f64) -> Dd {
        let (p, e) = P::two_prod(self.hi, b);
        let e = e + self.lo * b;
        let (hi, lo) = quick_two_sum(p, e);
        Dd { hi, lo }
    }

    /// `self * b` with the product strategy `P` (the `*` operator is `P = Dekker`).
    #[inline(always)]
    pub(crate) fn mul_p<P: ExactProduct>(self, b: Dd) -> Dd {
        let (p, e) = P::two_prod(self.hi, b.hi);
        let e = e + (self.hi * b.lo + self.lo * b.hi);
        let (hi, lo) = quick_two_sum(p, e);
        Dd { hi, lo }
    }

    /// `|self|`.
    #[inline]
    pub fn abs(self) -> Dd {
        if self.hi < 0.0 {
            -self
        } else {
            self
        }
    }

    /// Square root (one Newton step from the f64 root).
    pub fn sqrt(self) -> Dd {
        self.sqrt_p::<Dekker>()
    }

    /// [`Dd::sqrt`] with the product strategy `P`.
    #[inline(always)]
    pub(crate) fn sqrt_p<P: ExactProduct>(self) -> Dd {
        if self.hi <= 0.0 {
            return Dd::ZERO;
        }
        let r = self.hi.sqrt();
        // r + (self - r^2)/(2r)
        let corr = (self - Dd::prod_p::<P>(r, r)).hi / (2.0 * r);
        let (hi, lo) = quick_two_sum(r, corr);
        Dd { hi, lo }
    }

    /// Reciprocal.
    pub fn recip(self) -> Dd {
        Dd::ONE / self
    }
}

/// The *accurate* double-word operations of Joldes, Muller and Popescu, "Tight
/// and rigorous error bounds for basic building blocks of double-word
/// arithmetic", ACM TOMS 44 (2017), with their proven relative error bounds
/// (`u = 2^-53`). The operators above are the cheaper "sloppy" variants with
/// estimated errors; the certified f64 paths (`hyp2f1`'s power and series
/// prefactors) use these. Each `_p` variant takes the exact product `P` and is
/// bit-identical for every `P`.
impl Dd {
    /// AccurateDWPlusDW [JMP 2017, Alg. 6]: relative error `<= 3u^2/(1-4u)`.
    #[inline]
    pub(crate) fn add_accurate(self, y: Dd) -> Dd {
        let (sh, sl) = two_sum(self.hi, y.hi);
        let (th, tl) = two_sum(self.lo, y.lo);
        let c = sl + th;
        let (vh, vl) = quick_two_sum(sh, c);
        let w = tl + vl;
        let (hi, lo) = quick_two_sum(vh, w);
        Dd { hi, lo }
    }

    /// DWTimesDW1 [JMP 2017, Alg. 10]: relative error `<= 7u^2`.
    #[inline]
    pub(crate) fn mul_accurate(self, y: Dd) -> Dd {
        self.mul_accurate_p::<Dekker>(y)
    }

    /// [`Dd::mul_accurate`] with the exact product `P`.
    #[inline(always)]
    pub(crate) fn mul_accurate_p<P: ExactProduct>(self, y: Dd) -> Dd {
        let (ch, cl1) = P::two_prod(self.hi, y.hi);
        let tl1 = self.hi * y.lo;
        let tl2 = self.lo * y.hi;
        let cl2 = tl1 + tl2;
        let cl3 = cl1 + cl2;
        let (hi, lo) = quick_two_sum(ch, cl3);
        Dd { hi, lo }
    }

    /// DWTimesFP1 [JMP 2017, Alg. 7]: relative error `<= 2u^2`.
    #[inline(always)]
    pub(crate) fn mul_f64_accurate_p<P: ExactProduct>(self, y: f64) -> Dd {
        let (ch, cl1) = P::two_prod(self.hi, y);
        let cl2 = self.lo * y;
        let (th, tl1) = quick_two_sum(ch, cl2);
        let tl2 = tl1 + cl1;
        let (hi, lo) = quick_two_sum(th, tl2);
        Dd { hi, lo }
    }

    /// DWDivDW2 [JMP 2017, Alg. 17]: relative error `<= 15u^2 + 56u^3`.
    #[inline]
    pub(crate) fn div_accurate(self, y: Dd) -> Dd {
        self.div_accurate_p::<Dekker>(y)
    }

    /// [`Dd::div_accurate`] with the exact product `P`.
    #[inline(always)]
    pub(crate) fn div_accurate_p<P: ExactProduct>(self, y: Dd) -> Dd {
        let th = self.hi / y.hi;
        let r = y.mul_f64_accurate_p::<P>(th);
        let pi_h = self.hi - r.hi;
        let dl = self.lo - r.lo;
        let d = pi_h + dl;
        let tl = d / y.hi;
        let (hi, lo) = quick_two_sum(th, tl);
        Dd { hi, lo }
    }
}

impl Add for Dd {
    type Output = Dd;
    #[inline]
    fn add(self, b: Dd) -> Dd {
        let (s, e) = two_sum(self.hi, b.hi);
        let e = e + self.lo + b.lo;
        let (hi, lo) = quick_two_sum(s, e);
        Dd { hi, lo }
    }
}

impl Neg for Dd {
    type Output = Dd;
    #[inline]
    fn neg(self) -> Dd {
        Dd { hi: -self.hi, lo: -self.lo }
    }
}

impl Sub for Dd {
    type Output = Dd;
    #[inline]
    fn sub(self, b: Dd) -> Dd {
        self + (-b)
    }
}

impl Mul for Dd {
    type Output = Dd;
    #[inline]
    fn mul(self, b: Dd) -> Dd {
        self.mul_p::<Dekker>(b)
    }
}

impl Div for Dd {
    type Output = Dd;
    fn div(self, b: Dd) -> Dd {
        let q1 = self.hi / b.hi;
        let r = self - b.mul_f64(q1);
        let q2 = r.hi / b.hi;
        let r = r - b.mul_f64(q2);
        let q3 = r.hi / b.hi;
        let (hi, lo) = quick_two_sum(q1, q2);
        Dd { hi, lo } + Dd::from_f64(q3)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rug::Float;

    fn to_float(d: Dd) -> Float {
        Float::with_val(200, d.hi) + Float::with_val(200, d.lo)
    }

    #[test]
    fn about_106_bits() {
        let third = Dd::ONE / Dd::from_f64(3.0);
        let exact = Float::with_val(200, 1) / 3u32;
        let err = Float::with_val(200, to_float(third) - &exact).abs();
        assert!(err < Float::with_val(53, 1e-31));
        let s = Dd::from_f64(2.0).sqrt();
        let exact = Float::with_val(200, 2).sqrt();
        assert!(Float::with_val(200, to_float(s) - &exact).abs() < Float::with_val(53, 1e-31));
        let tp = to_float(Dd::TWO_PI);
        let exact = Float::with_val(200, rug::float::Constant::Pi) * 2u32;
        assert!(Float::with_val(200, tp - &exact).abs() < Float::with_val(53, 1e-31));
        let p = Dd::from_f64(0.1) * Dd::from_f64(0.3) - Dd::prod(0.1, 0.3);
        assert!(p.to_f64().abs() < 1e-32);
    }
}
