//! `G(k, 1 - w)` by the near-one expansion in plain double-double with an
//! a-priori rounding bound (issue 23, item 4): the expansion of [`super::dd::near_one_dd`]
//! with its first sum in closed form but one, so that each of the two remaining sums
//! is a single hypergeometric recurrence, and no running bound per operation.
//!
//! # Method
//!
//! `G = C_k B_k(1) + C_k (k+1) I1(w) - 2 sqrt(pi) w^{3/2} I2'(w)`, `w = 1 - y` exact
//! (module docs of [`super`], region NearOne), `I1 = sum_j h_j w^{j+1}/(j+1)`,
//! `h_j = sum_{i<=j} r_i`, `r_i = (k+1/2)_i/(1/2)_i`. The partial sums of a ratio of
//! Pochhammer symbols telescope: `sum_{i=0}^j (a)_i/(b)_i = ((a)_{j+1}/(b)_j - (b-1))/(a-b+1)`
//! (induction on `j`), so with `a = k+1/2`, `b = 1/2`:
//! `h_j = (r_j (k+1/2+j) + 1/2)/(k+1)` and, as `sum_j w^{j+1}/(j+1) = -ln(1-w)`,
//!
//! `(k+1) I1 = T1 - ln(y)/2`, `T1 = sum_{m>=1} tau_m`, `tau_m = r_m w^m (2m-1)/(2m)`,
//!
//! `G = C_k (B_k(1) - ln(y)/2 + T1) - 2 sqrt(pi) w^{3/2} T2`, `T2 = I2' = sum_{j>=0} sigma_j`,
//! `sigma_j = 2 (k+2)_j w^j/(j! (2j+3))`. Both are single recurrences:
//! `tau_1 = w (2k+1)/2`, `tau_m = tau_{m-1} R_m`, `R_m = w N_m/D_m`,
//! `N_m = (2k+2m-1)(m-1)`, `D_m = m (2m-3)`; `sigma_0 = 2/3`,
//! `sigma_j = sigma_{j-1} R'_j`, `R'_j = w N'_j/D'_j`, `N'_j = (k+1+j)(2j+1)`,
//! `D'_j = j (2j+3)` (exact integers below `2^53`). Every quantity is positive.
//!
//! **Tails.** `tau_m <= rho_m = r_m w^m`, whose ratio `w (2k+2m+1)/(2m+1)` decreases, so
//! after `M` terms `sum_{m>M} tau_m <= rho_{M+1}/(1 - ratio_{M+1})`,
//! `rho_{M+1} = tau_M (2M/(2M-1)) w (2k+2M+1)/(2M+1)`, once that ratio is below one. The
//! ratio of `sigma` is `<= w (k+1+j)/j`, decreasing, so after `J` terms the tail is
//! `<= sigma_J r/(1 - r)`, `r = w (k+2+J)/(J+1)`, once `r < 1`. The tails are evaluated
//! in f64 from the computed terms inflated by their error bounds, with `8u` for their
//! own roundings.
//!
//! **Rounding, a priori.** With `eps = u^2 = 2^-106` and the per-operation charges of
//! the house double-double model (`src/ball/dd_bounded.rs`; Joldes, Muller, Popescu,
//! ACM TOMS 44 (2017)): a double-double product `<= 8 eps`, the sum of two positive
//! double-doubles `<= 8 eps` of the result, a quotient by an f64 `<= 16 eps` (`sigma_0`),
//! all relative here (every operand is positive).
//!
//! *The ratios* (`ratio`): `d d'` (the two denominators of a step) is an exact integer
//! below `2^53`, `inv = fl(fl(1/(d d')) d') = (1/d)(1 + alpha)`, `|alpha| <= gamma_2`, one
//! quotient for both lanes. `a + ae = w n` exactly (`two_prod`); `rh = fl(a inv) =
//! (a/d)(1 + beta)`, `|beta| <= gamma_3`; `p + pe = rh d` exactly, `a - p` exact (Sterbenz:
//! `p` is within `gamma_4` of `a`); `X = a - rh d + ae = d (R - rh)` has `|X| <= 4.01 u |a|`,
//! and `r = fl(fl((a - p) - pe) + ae)` is within `u 3.01 u |a| + u 4.02 u |a| <= 7.1 u^2 |a|`
//! of it; `rl = fl(r inv)` is within `7.2 u^2 |a/d| + 4.01 u (gamma_2 + u) |a/d| <= 19.4 u^2 R`
//! of `X/d = R - rh`. So `R~ = rh + rl` (Fast2Sum, exact since `|rl| <= 4.1 u rh`) has
//! relative error `<= 20 eps`.
//!
//! *The recurrences* advance two steps an iteration: `x_{m+1} = x_m R_{m+1}` (off the
//! dependency chain) and `x_{m+2} = x_m (R_{m+1} R_{m+2})`, so a step adds at most
//! `20 + 8 = 28 eps` and two `20 + 20 + 8 + 8 = 56 eps`: `eta(tau_m) <= 28 (m-1) eps`
//! (`tau_1` is exact: an exact product halved), `eta(sigma_j) <= (16 + 28 j) eps`
//! (`sigma_0 = 2/3` one quotient), charged `32 (m-1)` and `16 + 32 j`, to first order (the
//! second-order terms are below `(32 * 6000 eps)^2` relative, covered by the factor
//! `1 + 2^-20`).
//!
//! *The sums* (two accumulators each, even and odd `m`, added at the end): the computed
//! `s~_M = sum_m (s~_{m-1} + t~_m)(1 + delta_m)` differs from `sum_m t~_m` by at most
//! `8 eps sum_m s~_m`, and `sum_m t~_m` from the exact partial sum by
//! `sum_m eta_m t_m`. Both weighted sums are accumulated in f64 as the terms are formed
//! (off the dependency chains), so the bound is what this evaluation incurred, not a
//! worst case over the longest sum.
//!
//! The sums stop (checked every 4 terms) when both tails are below `2^-56 (1-w)^k` of
//! their sums (the parts grow like `(1-w)^{-k}` before they cancel, so that is about
//! `2^-56 |G|`, up to the factor by which the parts exceed `(1-w)^{-k} |G|`, ~5 measured), or `2^-104`, whichever is larger: the stopping rule only sets the cost,
//! the tail added is the proven one. `ln y` is the f64 [`super::elementary::ln_bounded`]
//! where the whole bound, its error `C_k u |ln y|/2` included, meets the caller's
//! `rel_tol`, else the double-double
//! [`super::dd::ln_dd`] (next to the zeros of `G(2, .)`, `G(3, .)`); the assembly (six
//! operations, where the parts cancel) runs in the bounded double-doubles of
//! `dd_bounded.rs`.
//!
//! **Lanes.** `x = (tau_m, sigma_{m-1})` sits in the two lanes of one SSE2 register, and
//! where the CPU has AVX and FMA the two steps of an iteration run side by side in four
//! lanes, `(tau_{m+1}, sigma_m, tau_{m+2}, sigma_{m+1})`. Every lane rounds as the scalar
//! operation would and the exact products are exact either way (FMA, or Dekker's
//! splitting lane by lane), so all builds give the same bits (tested). About 45
//! instructions a term of both sums (callgrind: 5.5k a call at `k = 100`, `y = 0.85`,
//! 96 terms; 13.2k for the scalar double-double version, and 25 ns a term of each sum
//! for [`super::dd::near_one_dd`]'s running bound).
//!
//! Accuracy: the result's error is about `50 M eps (1-w)^{-k} |G|`, so its bound is
//! `1e-14` relative while `-k ln(1 - w) <= ~30` (tested: every point of the list
//! with growth `<= 30`, worst `2.1e-15`; `3.4e-15` at `k = 1000`, `y = 0.97`, growth 30.5);
//! the caller tries it while `k w <= 31 y`.
//!
//! References: DLMF 15.8.4 (the `1-z` connection formula behind the expansion),
//! 5.2.5 (Pochhammer symbols).

use crate::ball::{cpu_dispatch, BoundedDd, Dd, ExactProduct, U};
use super::dd::{ln_dd, DdConstants};
use super::elementary::ln_bounded;

/// Cap on the terms of a sum.
const MAX_TERMS: u64 = 6000;

/// Slack over the first-order rounding bounds (second-order terms, and the
/// f64 evaluation of the bounds themselves).
const SLACK: f64 = 1.0 + 1.0 / (1u64 << 20) as f64;

/// `G(k, 1 - w)` by the near-one expansion in plain double-double, `0 < w <= 1/2`
/// exact, with its proven bound (module docs): on four AVX lanes with FMA products where
/// the CPU has both, else on two lanes with FMA or Dekker's products (all bit-identical).
pub(crate) fn near_one_fast(k: u32, w: f64, c: &DdConstants, rel_tol: f64) -> Option<BoundedDd> {
    #[cfg(target_arch = "x86_64")]
    {
        if std::arch::is_x86_feature_detected!("avx") && std::arch::is_x86_feature_detected!("fma") {
            // SAFETY: the CPU has AVX and FMA (checked just above).
            return unsafe { near_one_fast_avx(k, w, c, rel_tol) };
        }
    }
    near_one_fast_2lane(k, w, c, rel_tol)
}

cpu_dispatch! {
    /// [`near_one_fast`] on two lanes: FMA products where the CPU has them, else Dekker's.
    fn near_one_fast_2lane(k: u32, w: f64, c: &DdConstants, rel_tol: f64) -> Option<BoundedDd> => near_one_fast_with
}

/// [`near_one_fast`] with Dekker's products (tests compare the two).
#[cfg(test)]
pub(crate) fn near_one_fast_portable(k: u32, w: f64, c: &DdConstants, rel_tol: f64) -> Option<BoundedDd> {
    near_one_fast_with::<crate::ball::Dekker>(k, w, c, rel_tol)
}

/// Two lanes, `a` for the recurrence of `T1` and `b` for that of `T2`: the same
/// operations on both, in one SSE2 register on x86-64 (each lane rounds as the scalar
/// operation would, so the analysis holds lane by lane and every build gives the same
/// bits), two f64 elsewhere.
#[cfg(target_arch = "x86_64")]
mod lanes {
    use std::arch::x86_64::{__m128d, _mm_add_pd, _mm_cvtsd_f64, _mm_div_pd, _mm_mul_pd, _mm_set_pd, _mm_shuffle_pd, _mm_sub_pd, _mm_unpackhi_pd};

    #[derive(Clone, Copy)]
    pub(super) struct L2(pub(super) __m128d);

    // SAFETY (every `unsafe` block): SSE2 is part of the x86-64 baseline, and the
    // intrinsics only read and write their register operands.
    impl L2 {
        #[inline(always)]
        pub(super) fn new(a: f64, b: f64) -> L2 {
            L2(unsafe { _mm_set_pd(b, a) })
        }
        #[inline(always)]
        pub(super) fn a(self) -> f64 {
            unsafe { _mm_cvtsd_f64(self.0) }
        }
        #[inline(always)]
        pub(super) fn b(self) -> f64 {
            unsafe { _mm_cvtsd_f64(_mm_unpackhi_pd(self.0, self.0)) }
        }
        #[inline(always)]
        pub(super) fn add(self, o: L2) -> L2 {
            L2(unsafe { _mm_add_pd(self.0, o.0) })
        }
        #[inline(always)]
        pub(super) fn sub(self, o: L2) -> L2 {
            L2(unsafe { _mm_sub_pd(self.0, o.0) })
        }
        #[inline(always)]
        pub(super) fn mul(self, o: L2) -> L2 {
            L2(unsafe { _mm_mul_pd(self.0, o.0) })
        }
        #[inline(always)]
        pub(super) fn div(self, o: L2) -> L2 {
            L2(unsafe { _mm_div_pd(self.0, o.0) })
        }
        /// `(b, a)`.
        #[inline(always)]
        pub(super) fn swap(self) -> L2 {
            L2(unsafe { _mm_shuffle_pd::<1>(self.0, self.0) })
        }
    }
}

/// Two lanes as two f64 (targets other than x86-64).
#[cfg(not(target_arch = "x86_64"))]
mod lanes {
    #[derive(Clone, Copy)]
    pub(super) struct L2(f64, f64);

    impl L2 {
        #[inline(always)]
        pub(super) fn new(a: f64, b: f64) -> L2 {
            L2(a, b)
        }
        #[inline(always)]
        pub(super) fn a(self) -> f64 {
            self.0
        }
        #[inline(always)]
        pub(super) fn b(self) -> f64 {
            self.1
        }
        #[inline(always)]
        pub(super) fn add(self, o: L2) -> L2 {
            L2(self.0 + o.0, self.1 + o.1)
        }
        #[inline(always)]
        pub(super) fn sub(self, o: L2) -> L2 {
            L2(self.0 - o.0, self.1 - o.1)
        }
        #[inline(always)]
        pub(super) fn mul(self, o: L2) -> L2 {
            L2(self.0 * o.0, self.1 * o.1)
        }
        #[inline(always)]
        pub(super) fn div(self, o: L2) -> L2 {
            L2(self.0 / o.0, self.1 / o.1)
        }
        /// `(b, a)`.
        #[inline(always)]
        pub(super) fn swap(self) -> L2 {
            L2(self.1, self.0)
        }
    }
}

use lanes::L2;

/// The exact products lane by lane, `a b = p + e` ([`ExactProduct`] on two lanes):
/// one fused multiply-add per lane pair (Fused), or Dekker's splitting in the same
/// order as the scalar `two_prod` (Dekker); both exact, so bit-identical.
trait TwoProd2: ExactProduct {
    fn two_prod2(a: L2, b: L2) -> (L2, L2);
}

impl TwoProd2 for crate::ball::Dekker {
    #[inline(always)]
    fn two_prod2(a: L2, b: L2) -> (L2, L2) {
        let p = a.mul(b);
        let splitter = L2::new(134_217_729.0, 134_217_729.0); // 2^27 + 1
        let split = |x: L2| {
            let t = splitter.mul(x);
            let hi = t.sub(t.sub(x));
            (hi, x.sub(hi))
        };
        let (ah, al) = split(a);
        let (bh, bl) = split(b);
        let e = ah.mul(bh).sub(p).add(ah.mul(bl)).add(al.mul(bh)).add(al.mul(bl));
        (p, e)
    }
}

impl TwoProd2 for crate::ball::Fused {
    #[inline(always)]
    fn two_prod2(a: L2, b: L2) -> (L2, L2) {
        #[cfg(target_arch = "x86_64")]
        {
            let p = a.mul(b);
            // SAFETY: `Fused` runs only inside the function compiled with `fma`, after the
            // run-time check (`cpu_dispatch`).
            (p, L2(unsafe { std::arch::x86_64::_mm_fmsub_pd(a.0, b.0, p.0) }))
        }
        #[cfg(not(target_arch = "x86_64"))]
        {
            let (pa, ea) = <Self as ExactProduct>::two_prod(a.a(), b.a());
            let (pb, eb) = <Self as ExactProduct>::two_prod(a.b(), b.b());
            (L2::new(pa, pb), L2::new(ea, eb))
        }
    }
}

/// A double-double per lane.
#[derive(Clone, Copy)]
struct Dd2 {
    hi: L2,
    lo: L2,
}

impl Dd2 {
    /// Fast2Sum `s + t` (exact for `|s| >= |t|`).
    #[inline(always)]
    fn quick(s: L2, t: L2) -> Dd2 {
        let hi = s.add(t);
        Dd2 { hi, lo: t.sub(hi.sub(s)) }
    }
    /// The house product ([`Dd::mul_p`], lane by lane): `<= 8 eps` relative.
    #[inline(always)]
    fn mul<P: TwoProd2>(self, o: Dd2) -> Dd2 {
        let (p, e) = P::two_prod2(self.hi, o.hi);
        Dd2::quick(p, e.add(self.hi.mul(o.lo).add(self.lo.mul(o.hi))))
    }
    /// The house sum (`Dd + Dd`, lane by lane): `<= 8 eps` of the result for positive operands.
    #[inline(always)]
    fn add(self, o: Dd2) -> Dd2 {
        let s = self.hi.add(o.hi);
        let bb = s.sub(self.hi);
        let e = self.hi.sub(s.sub(bb)).add(o.hi.sub(bb));
        Dd2::quick(s, e.add(self.lo).add(o.lo))
    }
}

/// `R = w n/d` lane by lane for exact integers `n`, `d`, given `inv` (`1/d` within
/// `gamma_2`; module docs: relative error `<= 20 eps`), as a normalized double-double.
#[inline(always)]
fn ratio<P: TwoProd2>(w: L2, n: L2, d: L2, inv: L2) -> Dd2 {
    let (a, ae) = P::two_prod2(w, n); // a + ae = w n exactly
    let rh = a.mul(inv);
    let (p, pe) = P::two_prod2(rh, d); // rh d = p + pe exactly; a - p exact (Sterbenz)
    let rl = a.sub(p).sub(pe).add(ae).mul(inv);
    Dd2::quick(rh, rl) // |rl| <= 4.1 u rh: exact
}

/// The ratios of step `m` (`mm = (m, m)`): `tau_m/tau_{m-1}` (lane a) and
/// `sigma_{m-1}/sigma_{m-2}` (lane b), `j = m - 1`:
/// `w (2k-1+2m)(m-1)/(m(2m-3))` and `w (k+m)(2m-1)/((m-1)(2m+1))`, numerators
/// `(alpha + 2m)(gamma + m)` and denominators `(delta + m)(zeta + 2m)` lane by lane
/// (exact integers), with one quotient for both (`1/d_a = d_b/(d_a d_b)`,
/// `d_a d_b < 2^53` exact).
#[inline(always)]
fn ratios<P: TwoProd2>(mm: L2, k: &RatioConsts, w: L2) -> Dd2 {
    let m2 = mm.add(mm);
    let n = k.alpha.add(m2).mul(k.gamma.add(mm));
    let d = k.delta.add(mm).mul(k.zeta.add(m2));
    let ds = d.swap();
    let q = k.one.div(d.mul(ds)); // 1/(d_a d_b) in both lanes
    ratio::<P>(w, n, d, q.mul(ds))
}

/// The lane constants of [`ratios`].
struct RatioConsts {
    alpha: L2,
    gamma: L2,
    delta: L2,
    zeta: L2,
    one: L2,
}

/// The start of both recurrences: `x = (tau_1, sigma_0)` (`tau_1 = w (2k+1)/2` exact,
/// `sigma_0 = 2/3` one quotient), the weighted error sums of the first terms (units of
/// `eps`; `eta(sigma_0) = 16`), and the stopping threshold: a sum stops when its tail is
/// below `2^-56 (1-w)^k` of it (an estimate of `|G|` over the parts; only the cost
/// depends on it), at least `2^-104`.
#[inline(always)]
fn start<P: TwoProd2>(kf: f64, w: f64) -> (Dd2, L2, f64) {
    let tau1 = Dd::prod_p::<P>(w, 2.0 * kf + 1.0);
    let sigma0 = crate::ball::div_f64_p::<P>(Dd::from_f64(2.0), 3.0);
    let x = Dd2 { hi: L2::new(0.5 * tau1.hi, sigma0.hi), lo: L2::new(0.5 * tau1.lo, sigma0.lo) };
    let we = L2::new(8.0 * x.hi.a(), 24.0 * x.hi.b());
    // 2^-56 (1-w)^k from an estimate of k ln(1-w) (the first four terms of its series,
    // which only underestimate |ln(1-w)|), as a power of two built from its bits
    let lam = kf * w * (1.0 + w * (0.5 + w * (1.0 / 3.0 + 0.25 * w)));
    let e2 = (56.0 + lam * std::f64::consts::LOG2_E).min(104.0);
    let rel_stop = f64::from_bits(((1023.0 - e2.ceil()) as u64) << 52);
    (x, we, rel_stop)
}

/// The lane constants of [`ratios`] for `k`.
#[inline(always)]
fn ratio_consts(kf: f64) -> RatioConsts {
    RatioConsts {
        alpha: L2::new(2.0 * kf - 1.0, -1.0),
        gamma: L2::new(-1.0, kf),
        delta: L2::new(0.0, -1.0),
        zeta: L2::new(-3.0, 1.0),
        one: L2::new(1.0, 1.0),
    }
}

/// The stopping test after the step to `x = (tau_m, sigma_{m-1})`, `m = 1 (mod 4)`: the
/// tails of both sums (module docs) and, once both are below `rel_stop` of their sums,
/// the two sums (the even and odd accumulators added) with their bounds.
#[inline(always)]
#[allow(clippy::too_many_arguments)]
fn stop(m: u64, kf: f64, w: f64, x: Dd2, acc_e: Dd2, acc_o: Dd2, we: L2, wo: L2, rel_stop: f64) -> Option<(Dd2, f64, f64)> {
    let mf = m as f64;
    let jf = mf - 1.0;
    let (tau, sigma) = (x.hi.a(), x.hi.b());
    let (s1, s2) = (acc_e.hi.a() + acc_o.hi.a(), acc_e.hi.b() + acc_o.hi.b());
    // A test without quotients first (it only decides the cost: the tails added below are
    // the proven ones): ratio_{m+1} = n1/d1 < 1 and tail1 = rho_{m+1}/(1 - n1/d1) below
    // rel_stop s1 (rho_{m+1} ~ tau w (2k+2m+1)/(2m+1), the factor 2m/(2m-1) and the
    // roundings covered by 1.1), and the same for T2 with n2/d2 = w (k+2+j)/(j+1)
    let (n1, d1) = (w * (2.0 * kf + 2.0 * mf + 3.0), 2.0 * mf + 3.0);
    let (n2, d2) = (w * (kf + 2.0 + jf), jf + 1.0);
    if !(n1 < d1 && n2 < d2) {
        return None;
    }
    let rho = tau * w * (2.0 * kf + 2.0 * mf + 1.0);
    if !(1.1 * rho * d1 <= rel_stop * s1 * (2.0 * mf + 1.0) * (d1 - n1) && 1.1 * sigma * n2 <= rel_stop * s2 * (d2 - n2)) {
        return None;
    }
    let up = 1.0 + 8.0 * U;
    let eps = U * U;
    // T1: rho_{m+1} = tau_m (2m/(2m-1)) w (2k+2m+1)/(2m+1); ratio_{m+1} = w (2k+2m+3)/(2m+3)
    let r1 = w * (2.0 * kf + 2.0 * mf + 3.0) / (2.0 * mf + 3.0) * up;
    // T2: ratio bound w (k+2+j)/(j+1)
    let r2 = w * (kf + 2.0 + jf) / (jf + 1.0) * up;
    if !(r1 < 1.0 && r2 < 1.0) {
        return None;
    }
    let tau_up = tau * (1.0 + 2.0 * U + 32.0 * mf * eps);
    let rho_next = tau_up * (2.0 * mf / (2.0 * mf - 1.0)) * w * (2.0 * kf + 2.0 * mf + 1.0) / (2.0 * mf + 1.0) * up;
    let tail1 = rho_next / (1.0 - r1) * up;
    let tail2 = sigma * (1.0 + 2.0 * U + (16.0 + 32.0 * jf) * eps) * r2 / (1.0 - r2) * up;
    let total = acc_e.add(acc_o);
    let wt = we.add(wo).add(L2::new(8.0, 8.0).mul(total.hi));
    Some((total, tail1 + eps * wt.a() * (1.0 + 2.0 * U) * SLACK, tail2 + eps * wt.b() * (1.0 + 2.0 * U) * SLACK))
}

/// Both sums, two lanes at a time (module docs): `(T1, T2)` and their bounds.
#[inline(always)]
fn sums_2lane<P: TwoProd2>(kf: f64, w: f64) -> Option<(Dd2, f64, f64)> {
    let (mut x, mut we, rel_stop) = start::<P>(kf, w);
    // two accumulators per sum (even and odd m), so that the additions form two chains
    let mut acc_e = x;
    let mut acc_o = Dd2 { hi: L2::new(0.0, 0.0), lo: L2::new(0.0, 0.0) };
    let mut wo = L2::new(0.0, 0.0);
    let rc = ratio_consts(kf);
    let (ww, one, eight) = (L2::new(w, w), L2::new(1.0, 1.0), L2::new(8.0, 8.0));
    let mut mm = L2::new(1.0, 1.0); // (m, m)
    let mut m = 1u64; // x holds tau_m, sigma_{m-1}
    loop {
        // two steps, m+1 (off the chain) and m+2 = x R_{m+1} R_{m+2} (on it)
        let mf = m as f64;
        mm = mm.add(one);
        let r1 = ratios::<P>(mm, &rc, ww);
        mm = mm.add(one);
        let r2 = ratios::<P>(mm, &rc, ww);
        let x1 = x.mul::<P>(r1);
        x = x.mul::<P>(r1.mul::<P>(r2));
        acc_e = acc_e.add(x1);
        acc_o = acc_o.add(x);
        // eta(tau_m) <= 32 (m-1) eps, eta(sigma_j) <= (16 + 32 j) eps, j = m - 1
        we = we.add(L2::new(32.0 * mf, 32.0 * mf + 16.0).mul(x1.hi)).add(eight.mul(acc_e.hi));
        wo = wo.add(L2::new(32.0 * mf + 32.0, 32.0 * mf + 48.0).mul(x.hi)).add(eight.mul(acc_o.hi));
        m += 2;
        if m % 4 == 1 {
            if let Some(done) = stop(m, kf, w, x, acc_e, acc_o, we, wo, rel_stop) {
                return Some(done);
            }
        }
        if m > MAX_TERMS {
            return None;
        }
    }
}

/// The assembly: `G = C_k (B_k(1) - ln(y)/2 + T1) - 2 sqrt(pi) w^{3/2} T2` in bounded
/// double-doubles.
#[inline(always)]
fn assemble<P: TwoProd2>(w: f64, c: &DdConstants, sums: (Dd2, f64, f64), rel_tol: f64) -> Option<BoundedDd> {
    let (total, e1, e2) = sums;
    let t1 = BoundedDd { v: Dd { hi: total.hi.a(), lo: total.lo.a() }, e: e1 };
    let t2 = BoundedDd { v: Dd { hi: total.hi.b(), lo: total.lo.b() }, e: e2 };
    let w32 = BoundedDd::exact(w).sqrt_p::<P>()?.mul_f64_p::<P>(w);
    let part2 = c.two_sqrt_pi.mul_p::<P>(w32).mul_p::<P>(t2);
    let base = c.b1.add(t1);
    // ln y in f64 (about 30 ns) where the whole bound, its error C_k |ln y| u/2 included,
    // meets rel_tol (with the final rounding and inflation of `finish`); else in
    // double-double (ln_dd, about 0.2-0.3 us: next to the zeros of G(2, .), G(3, .))
    let y = 1.0 - w;
    if let Some(l) = ln_bounded(y) {
        let half_ln_y = BoundedDd { v: Dd::from_f64(0.5 * l.v), e: 0.5 * l.e };
        let g = c.c.mul_p::<P>(base.sub(half_ln_y)).sub(part2);
        if (g.e + 2.0 * U * g.v.hi.abs()) * (1.0 + 1e-9) <= rel_tol * g.v.hi.abs() {
            return Some(g);
        }
    }
    let half_ln_y = ln_dd::<P>(y, c.ln2)?.mul_f64_p::<P>(0.5);
    Some(c.c.mul_p::<P>(base.sub(half_ln_y)).sub(part2))
}

#[inline(always)]
fn near_one_fast_with<P: TwoProd2>(k: u32, w: f64, c: &DdConstants, rel_tol: f64) -> Option<BoundedDd> {
    if !(w > 0.0 && w <= 0.5) {
        return None;
    }
    assemble::<P>(w, c, sums_2lane::<P>(k as f64, w)?, rel_tol)
}

/// Four lanes (AVX): the two steps of both recurrences of one iteration of
/// [`sums_2lane`] side by side, `(tau_{m+1}, sigma_m, tau_{m+2}, sigma_{m+1})`, the same
/// operations lane by lane (so the same bits).
#[cfg(target_arch = "x86_64")]
mod avx {
    use super::{lanes::L2, ratio_consts, start, stop, Dd2, MAX_TERMS};
    use crate::ball::Fused;
    use std::arch::x86_64::*;

    #[derive(Clone, Copy)]
    struct L4(__m256d);

    // SAFETY (every `unsafe` block): these functions are inlined only into
    // `near_one_fast_avx`, which runs after the run-time check for AVX and FMA.
    impl L4 {
        #[inline(always)]
        fn new(a: f64, b: f64, c: f64, d: f64) -> L4 {
            L4(unsafe { _mm256_set_pd(d, c, b, a) })
        }
        #[inline(always)]
        fn join(lo: L2, hi: L2) -> L4 {
            L4(unsafe { _mm256_insertf128_pd::<1>(_mm256_castpd128_pd256(lo.0), hi.0) })
        }
        #[inline(always)]
        fn low(self) -> L2 {
            L2(unsafe { _mm256_castpd256_pd128(self.0) })
        }
        #[inline(always)]
        fn high(self) -> L2 {
            L2(unsafe { _mm256_extractf128_pd::<1>(self.0) })
        }
        #[inline(always)]
        fn add(self, o: L4) -> L4 {
            L4(unsafe { _mm256_add_pd(self.0, o.0) })
        }
        #[inline(always)]
        fn sub(self, o: L4) -> L4 {
            L4(unsafe { _mm256_sub_pd(self.0, o.0) })
        }
        #[inline(always)]
        fn mul(self, o: L4) -> L4 {
            L4(unsafe { _mm256_mul_pd(self.0, o.0) })
        }
        #[inline(always)]
        fn div(self, o: L4) -> L4 {
            L4(unsafe { _mm256_div_pd(self.0, o.0) })
        }
        /// The lanes of each half swapped.
        #[inline(always)]
        fn swap(self) -> L4 {
            L4(unsafe { _mm256_permute_pd::<0b0101>(self.0) })
        }
        #[inline(always)]
        fn two_prod(self, o: L4) -> (L4, L4) {
            let p = self.mul(o);
            (p, L4(unsafe { _mm256_fmsub_pd(self.0, o.0, p.0) }))
        }
    }

    #[derive(Clone, Copy)]
    struct Dd4 {
        hi: L4,
        lo: L4,
    }

    impl Dd4 {
        #[inline(always)]
        fn join(lo: Dd2, hi: Dd2) -> Dd4 {
            Dd4 { hi: L4::join(lo.hi, hi.hi), lo: L4::join(lo.lo, hi.lo) }
        }
        #[inline(always)]
        fn low(self) -> Dd2 {
            Dd2 { hi: self.hi.low(), lo: self.lo.low() }
        }
        #[inline(always)]
        fn high(self) -> Dd2 {
            Dd2 { hi: self.hi.high(), lo: self.lo.high() }
        }
        #[inline(always)]
        fn quick(s: L4, t: L4) -> Dd4 {
            let hi = s.add(t);
            Dd4 { hi, lo: t.sub(hi.sub(s)) }
        }
        /// [`Dd2::mul`] on four lanes.
        #[inline(always)]
        fn mul(self, o: Dd4) -> Dd4 {
            let (p, e) = self.hi.two_prod(o.hi);
            Dd4::quick(p, e.add(self.hi.mul(o.lo).add(self.lo.mul(o.hi))))
        }
        /// [`Dd2::add`] on four lanes.
        #[inline(always)]
        fn add(self, o: Dd4) -> Dd4 {
            let s = self.hi.add(o.hi);
            let bb = s.sub(self.hi);
            let e = self.hi.sub(s.sub(bb)).add(o.hi.sub(bb));
            Dd4::quick(s, e.add(self.lo).add(o.lo))
        }
    }

    /// [`super::ratios`] for `m` in the low half and `m + 1` in the high half (`mm`).
    #[inline(always)]
    fn ratios4(mm: L4, alpha: L4, gamma: L4, delta: L4, zeta: L4, one: L4, w: L4) -> Dd4 {
        let m2 = mm.add(mm);
        let n = alpha.add(m2).mul(gamma.add(mm));
        let d = delta.add(mm).mul(zeta.add(m2));
        let ds = d.swap();
        let inv = one.div(d.mul(ds)).mul(ds);
        let (a, ae) = w.two_prod(n);
        let rh = a.mul(inv);
        let (p, pe) = rh.two_prod(d);
        let rl = a.sub(p).sub(pe).add(ae).mul(inv);
        Dd4::quick(rh, rl)
    }

    /// [`super::sums_2lane`] on four lanes, with FMA products (the same bits).
    #[inline(always)]
    pub(super) fn sums_4lane(kf: f64, w: f64) -> Option<(Dd2, f64, f64)> {
        let (mut x, we0, rel_stop) = start::<Fused>(kf, w);
        let zero = L2::new(0.0, 0.0);
        let mut acc = Dd4::join(x, Dd2 { hi: zero, lo: zero });
        let mut wt = L4::join(we0, zero);
        let rc = ratio_consts(kf);
        let dup = |v: L2| L4::join(v, v);
        let (alpha, gamma, delta, zeta, one) = (dup(rc.alpha), dup(rc.gamma), dup(rc.delta), dup(rc.zeta), dup(rc.one));
        let ww = L4::new(w, w, w, w);
        let eight = L4::new(8.0, 8.0, 8.0, 8.0);
        let (two, sixty_four) = (L4::new(2.0, 2.0, 2.0, 2.0), L4::new(64.0, 64.0, 64.0, 64.0));
        let mut mm = L4::new(2.0, 2.0, 3.0, 3.0); // (m+1, m+1, m+2, m+2)
        let mut coef = L4::new(32.0, 48.0, 64.0, 80.0); // (32 m, 32 m + 16, 32 m + 32, 32 m + 48)
        let mut m = 1u64;
        loop {
            let rv = ratios4(mm, alpha, gamma, delta, zeta, one, ww);
            let (r1, r2) = (rv.low(), rv.high());
            let r12 = r1.mul::<Fused>(r2);
            let y = Dd4::join(x, x).mul(Dd4::join(r1, r12));
            acc = acc.add(y);
            wt = wt.add(coef.mul(y.hi)).add(eight.mul(acc.hi));
            x = y.high();
            mm = mm.add(two);
            coef = coef.add(sixty_four);
            m += 2;
            if m % 4 == 1 {
                if let Some(done) = stop(m, kf, w, x, acc.low(), acc.high(), wt.low(), wt.high(), rel_stop) {
                    return Some(done);
                }
            }
            if m > MAX_TERMS {
                return None;
            }
        }
    }
}

/// [`near_one_fast_with`] on four AVX lanes with FMA products.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx,fma")]
fn near_one_fast_avx(k: u32, w: f64, c: &DdConstants, rel_tol: f64) -> Option<BoundedDd> {
    if !(w > 0.0 && w <= 0.5) {
        return None;
    }
    assemble::<crate::ball::Fused>(w, c, avx::sums_4lane(k as f64, w)?, rel_tol)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::special::exact;
    use crate::special::meijer_g::meijer_g_k_mp;
    use crate::special::meijer_g::native::dd_constants;
    use rug::Float;

    #[test]
    fn bound_holds_and_is_relative_up_to_growth_30() {
        // every (k, y) of the list with -k ln y <= 40: the bound encloses the
        // certified 200-bit value; the four-lane (AVX), two-lane and Dekker builds agree bit
        // for bit; where the
        // parts grow by at most e^30 the bound is 1e-14 relative (the caller's condition)
        let eps = f64::EPSILON;
        let ys = [0.5f64.next_up(), 0.6, 0.7, 0.78, 0.8, 0.807, 0.85, 0.875, 0.9, 0.93, 0.95, 0.96, 0.97, 0.9705, 0.98, 0.99, 0.999];
        let ys: Vec<f64> = ys.into_iter().chain([1.0 - 1e-6, 1.0 - 1e-12, 1.0 - eps, 1.0 - eps / 2.0]).collect();
        let (mut relative, mut within30, mut total) = (0, 0, 0);
        let mut worst = 0.0f64;
        for &k in &[0u32, 1, 2, 3, 10, 30, 100, 300, 1000] {
            for &y in &ys {
                let w = 1.0 - y;
                let growth = -(k as f64) * y.ln();
                if growth > 40.0 {
                    continue;
                }
                let c = dd_constants(k).unwrap();
                let raw = near_one_fast(k, w, &c, 1e-14).expect("a bound for 0 < w <= 1/2");
                let portable = near_one_fast_portable(k, w, &c, 1e-14).unwrap();
                assert_eq!((raw.v.hi, raw.v.lo, raw.e), (portable.v.hi, portable.v.lo, portable.e), "k={k} y={y}");
                // the two-lane build (FMA where the CPU has it) gives the same bits too
                let two = near_one_fast_2lane(k, w, &c, 1e-14).unwrap();
                assert_eq!((raw.v.hi, raw.v.lo, raw.e), (two.v.hi, two.v.lo, two.e), "k={k} y={y}");
                let b = raw.finish().unwrap();
                let reference = meijer_g_k_mp(k, &exact(y), 200).unwrap();
                let d = Float::with_val(300, reference.mid() - b.value).abs();
                assert!(d <= b.err, "k={k} y={y}: {b} vs {reference:?}");
                total += 1;
                if growth <= 30.0 {
                    within30 += 1;
                    let rel = b.err / b.value.abs();
                    worst = worst.max(rel);
                    relative += (rel <= 1e-14) as u32;
                }
            }
        }
        eprintln!("near_one_fast: {relative} of {within30} (growth <= 30) within 1e-14, worst {worst:.2e}; {total} points");
        // Measured: all 164 points with growth <= 30 (worst 2.1e-15); k = 1000, y = 0.97
        // (growth 30.5) gives 3.4e-15
        assert_eq!(relative, within30, "worst {worst:.2e}");
    }

    #[test]
    fn refuses_outside_its_range() {
        let c = dd_constants(5).unwrap();
        for w in [0.0, -0.1, 0.5f64.next_up(), f64::NAN] {
            assert!(near_one_fast(5, w, &c, 1e-14).is_none(), "w={w}");
        }
    }
}
