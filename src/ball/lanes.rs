//! Two f64 lanes for the native f64 kernels: SSE2 on x86-64 (part of the
//! baseline target, so no run-time detection), two plain f64 elsewhere.
//!
//! Every operation rounds each lane exactly as the scalar operation would
//! (IEEE 754, round to nearest), so an error analysis written for the scalar
//! code holds lane by lane, and both builds give bit-identical results.

#[cfg(target_arch = "x86_64")]
use std::arch::x86_64::{
    __m128d, _mm_add_pd, _mm_andnot_pd, _mm_cmple_pd, _mm_cvtsd_f64, _mm_div_pd, _mm_movemask_pd, _mm_mul_pd, _mm_set1_pd,
    _mm_set_pd, _mm_unpackhi_pd,
};

/// Lanes `(lo, hi)`.
#[cfg(target_arch = "x86_64")]
#[derive(Clone, Copy, Debug)]
pub(crate) struct F64x2(__m128d);

/// The portable lanes on other targets (`portable::F64x2`).
#[cfg(not(target_arch = "x86_64"))]
pub(crate) use portable::F64x2;

// SAFETY (every `unsafe` block below): SSE2 is part of the x86-64 baseline,
// and the intrinsics only read and write their register operands.
#[cfg(target_arch = "x86_64")]
impl F64x2 {
    #[inline(always)]
    pub(crate) fn new(lo: f64, hi: f64) -> F64x2 {
        F64x2(unsafe { _mm_set_pd(hi, lo) })
    }

    #[inline(always)]
    pub(crate) fn splat(x: f64) -> F64x2 {
        F64x2(unsafe { _mm_set1_pd(x) })
    }

    #[inline(always)]
    pub(crate) fn add(self, o: F64x2) -> F64x2 {
        F64x2(unsafe { _mm_add_pd(self.0, o.0) })
    }

    #[inline(always)]
    pub(crate) fn mul(self, o: F64x2) -> F64x2 {
        F64x2(unsafe { _mm_mul_pd(self.0, o.0) })
    }

    #[inline(always)]
    pub(crate) fn div(self, o: F64x2) -> F64x2 {
        F64x2(unsafe { _mm_div_pd(self.0, o.0) })
    }

    /// Bit 0 set when `lo <= o.lo`, bit 1 when `hi <= o.hi` (false with a NaN).
    #[inline(always)]
    pub(crate) fn le_mask(self, o: F64x2) -> u32 {
        unsafe { _mm_movemask_pd(_mm_cmple_pd(self.0, o.0)) as u32 }
    }

    #[inline(always)]
    pub(crate) fn abs(self) -> F64x2 {
        F64x2(unsafe { _mm_andnot_pd(_mm_set1_pd(-0.0), self.0) })
    }

    #[inline(always)]
    pub(crate) fn lo(self) -> f64 {
        unsafe { _mm_cvtsd_f64(self.0) }
    }

    #[inline(always)]
    pub(crate) fn hi(self) -> f64 {
        unsafe { _mm_cvtsd_f64(_mm_unpackhi_pd(self.0, self.0)) }
    }
}

/// Two plain f64: the lanes on targets without SSE2, compiled (and tested
/// against the SSE2 lanes) on every target.
#[cfg_attr(target_arch = "x86_64", allow(dead_code))]
pub(crate) mod portable {
    /// Lanes `(lo, hi)`.
    #[derive(Clone, Copy, Debug)]
    pub(crate) struct F64x2([f64; 2]);

    impl F64x2 {
        #[inline(always)]
        pub(crate) fn new(lo: f64, hi: f64) -> F64x2 {
            F64x2([lo, hi])
        }

        #[inline(always)]
        pub(crate) fn splat(x: f64) -> F64x2 {
            F64x2([x, x])
        }

        #[inline(always)]
        pub(crate) fn add(self, o: F64x2) -> F64x2 {
            F64x2([self.0[0] + o.0[0], self.0[1] + o.0[1]])
        }

        #[inline(always)]
        pub(crate) fn mul(self, o: F64x2) -> F64x2 {
            F64x2([self.0[0] * o.0[0], self.0[1] * o.0[1]])
        }

        #[inline(always)]
        pub(crate) fn div(self, o: F64x2) -> F64x2 {
            F64x2([self.0[0] / o.0[0], self.0[1] / o.0[1]])
        }

        /// Bit 0 set when `lo <= o.lo`, bit 1 when `hi <= o.hi` (false with a NaN).
        #[inline(always)]
        pub(crate) fn le_mask(self, o: F64x2) -> u32 {
            (self.0[0] <= o.0[0]) as u32 | ((self.0[1] <= o.0[1]) as u32) << 1
        }

        #[inline(always)]
        pub(crate) fn abs(self) -> F64x2 {
            F64x2([self.0[0].abs(), self.0[1].abs()])
        }

        #[inline(always)]
        pub(crate) fn lo(self) -> f64 {
            self.0[0]
        }

        #[inline(always)]
        pub(crate) fn hi(self) -> f64 {
            self.0[1]
        }
    }
}

#[cfg(test)]
mod tests {
    use super::F64x2;

    /// The portable lanes give the same bits as these (on x86-64: SSE2).
    #[test]
    fn portable_lanes_equal_these() {
        use super::portable::F64x2 as P;
        let xs = [0.1, -3.7, 1e300, -1e-300, 7.0 / 3.0, -0.0, 2.5e-310, f64::NAN, f64::INFINITY];
        for &a in &xs {
            for &b in &xs {
                let (v, w, pv, pw) = (F64x2::new(a, b), F64x2::new(b, 1.5), P::new(a, b), P::new(b, 1.5));
                let same = |x: F64x2, y: P| x.lo().to_bits() == y.lo().to_bits() && x.hi().to_bits() == y.hi().to_bits();
                assert!(same(v.add(w), pv.add(pw)) && same(v.mul(w), pv.mul(pw)) && same(v.div(w), pv.div(pw)), "{a} {b}");
                assert!(same(v.abs(), pv.abs()) && same(F64x2::splat(a), P::splat(a)), "{a} {b}");
                assert_eq!(v.le_mask(w), pv.le_mask(pw), "{a} {b}");
            }
        }
    }

    /// Each lane rounds as the scalar operation does (bit for bit).
    #[test]
    fn lanes_round_as_scalars() {
        let xs = [0.1, -3.7, 1e300, -1e-300, 7.0 / 3.0, -0.0, 2.5e-310, f64::NAN];
        for &a in &xs {
            for &b in &xs {
                let (va, vb) = (F64x2::new(a, b), F64x2::new(b, a));
                if a.is_nan() || b.is_nan() {
                    assert_eq!(va.le_mask(vb), 0);
                    continue;
                }
                assert_eq!(va.add(vb).lo().to_bits(), (a + b).to_bits());
                assert_eq!(va.add(vb).hi().to_bits(), (b + a).to_bits());
                assert_eq!(va.mul(vb).lo().to_bits(), (a * b).to_bits());
                assert_eq!(va.div(vb).lo().to_bits(), (a / b).to_bits());
                assert_eq!(va.div(vb).hi().to_bits(), (b / a).to_bits());
                assert_eq!(va.le_mask(vb), (a <= b) as u32 | ((b <= a) as u32) << 1);
                assert_eq!(va.mul(F64x2::splat(a)).hi().to_bits(), (b * a).to_bits());
                assert_eq!(va.abs().lo().to_bits(), a.abs().to_bits());
                assert_eq!(va.abs().hi().to_bits(), b.abs().to_bits());
            }
        }
    }
}
