//! `1F2(a; b1, b2; z)` summed in double-double with a proven bound: the native
//! path where the f64 series of `super::native_series_bounded` loses
//! too much to cancellation (large negative `z` against small parameters).
//!
//! # Method
//!
//! The series `sum_n t_n`, `t_{n+1} = t_n z (a+n)/((n+1)(b1+n)(b2+n))`, in
//! [`BoundedDd`] arithmetic (error model in `src/ball/dd_bounded.rs`: every
//! operation charged `8-16 u^2` of its operands, `u = 2^-53`). The shifted
//! parameters `a+n`, `b1+n`, `b2+n` are exact double words (TwoSum of two f64),
//! `n+1` is an exact f64. The rounding errors, running with the terms, cost
//! about `16 u^2 sum |t_n|`; for `z < 0`, `sum |t_n| = 1F2(|a|; b1, b2; |z|)`,
//! in the model family `1F2(1/2; k+1, k+3/2; -s^2)` about `e^{2s} s^{-2k-3/2}`
//! times the value (`~1e30` at `k = 0`, `s = 35`). Measured (unit tests): double
//! words certify `1e-14` for `k >= 7` at `s = 35`, `k >= 5` at 30, `k >= 3` at
//! 25, `k >= 1` at 20 and every `k` at `s <= 15`; the f64 series needs about
//! `k >= s`. Below that (`k <= 6`, `s > 15`) the caller takes the Bessel route
//! (`bessel_f64.rs`) from `s = 17`.
//!
//! **Tail** (as in the f64 series): once `a+N, b1+N, b2+N > 0`,
//! `|t_{n+1}/t_n| <= rho_N = |z| max(1, (a+N)/(b1+N)) / ((b2+N)(N+1))` for all
//! `n >= N` (each factor is monotone in `n`), so `sum_{n>=N} |t_n| <= |t_N|/(1 - rho_N)`;
//! the sum stops when that is at most `2^-70 |sum|` (with `rho_N <= 1/2`).
//!
//! References: DLMF 16.2.1 (the series); Joldes, Muller, Popescu, ACM TOMS 44
//! (2017) for the double-word operations.

use crate::ball::cpu_dispatch;
use crate::ball::{two_sum, BoundedDd, Dd, ExactProduct};

/// Stop when the tail is at most this fraction of the sum (`2^-70`).
const TAIL_REL: f64 = 8.470329472543003e-22;

/// Cap on the terms.
const MAX_TERMS: u64 = 20_000;

/// `x + n` as an exact double word.
#[inline(always)]
fn shifted(x: f64, n: f64) -> BoundedDd {
    let (hi, lo) = two_sum(x, n);
    BoundedDd { v: Dd { hi, lo }, e: 0.0 }
}

/// `(a+n, (b1+n)(b2+n)(n+1))` as two f64 when both are exact (`num` is the exact
/// double word `a+n`; the sums' and products' rounding errors are all zero), else
/// `None`. Then the term update is `t z (a+n) / den` with exact operands, the
/// operations charged as in the general case ([`BoundedDd::mul_f64_p`],
/// [`BoundedDd::div_f64_p`]). Holds in the model family (`b1 = k+1`,
/// `b2 = k+3/2`) while the product stays below `2^53`.
#[inline(always)]
fn exact_ratio<P: ExactProduct>(num: BoundedDd, b1: f64, b2: f64, n: f64) -> Option<(f64, f64)> {
    let (d1, e1) = two_sum(b1, n);
    let (d2, e2) = two_sum(b2, n);
    let (p1, f1) = P::two_prod(d1, d2);
    let (p2, f2) = P::two_prod(p1, n + 1.0);
    (num.v.lo == 0.0 && e1 == 0.0 && e2 == 0.0 && f1 == 0.0 && f2 == 0.0 && p2 != 0.0).then_some((num.v.hi, p2))
}

cpu_dispatch! {
    /// The series of `1F2(a; b1, b2; z)` in double-double with its proven bound
    /// (`None`: `b1, b2 <= 0`, no convergence within the cap, or overflow). Exact
    /// products by fused multiply-add where the CPU has it (detected at run time;
    /// bit-identical to Dekker's splitting).
    pub(crate) fn hyp1f2_series_dd(a: f64, b1: f64, b2: f64, z: f64) -> Option<BoundedDd> => series_with
}

/// [`hyp1f2_series_dd`] with Dekker's products (tests compare the two).
#[cfg(test)]
pub(crate) fn hyp1f2_series_dd_portable(a: f64, b1: f64, b2: f64, z: f64) -> Option<BoundedDd> {
    series_with::<crate::ball::Dekker>(a, b1, b2, z)
}

#[inline(always)]
fn series_with<P: ExactProduct>(a: f64, b1: f64, b2: f64, z: f64) -> Option<BoundedDd> {
    if !(b1 > 0.0 && b2 > 0.0 && a.is_finite() && z.is_finite() && b1.is_finite() && b2.is_finite()) {
        return None;
    }
    let u = crate::ball::U;
    // first index with a + n > 0 (the tail bound needs it)
    let n_pos = if a > 0.0 { 0.0 } else { (-a).floor() + 1.0 };
    let mut t = BoundedDd::ONE;
    let mut s = BoundedDd::ONE;
    let mut n: u64 = 0;
    loop {
        let nf = n as f64;
        let num = shifted(a, nf);
        if num.v.hi == 0.0 && num.v.lo == 0.0 {
            // a = -n: the series terminates, and every term so far was exact in its bound
            return Some(s);
        }
        t = match exact_ratio::<P>(num, b1, b2, nf) {
            // a+n exact, (b1+n)(b2+n)(n+1) an exact f64: two products and one
            // division by an f64 instead of a double-word division
            Some((num, den)) => t.mul_f64_p::<P>(z).mul_f64_p::<P>(num).div_f64_p::<P>(den),
            None => {
                let den = shifted(b1, nf).mul_p::<P>(shifted(b2, nf)).mul_f64_p::<P>(nf + 1.0);
                t.mul_f64_p::<P>(z).mul_p::<P>(num).div(den)?
            }
        };
        n += 1;
        if !(t.v.hi.is_finite() && t.e.is_finite()) || n > MAX_TERMS {
            return None;
        }
        let nf = n as f64;
        // (the tail test needs |t_N| <= 2^-70 |s| at least: checked first, without divisions)
        if nf >= n_pos && t.mag() <= TAIL_REL * s.mag() {
            let rho = z.abs() * ((a + nf) / (b1 + nf)).max(1.0) / ((b2 + nf) * (nf + 1.0)) * (1.0 + 8.0 * u);
            if rho <= 0.5 {
                let tail = (t.mag() + t.e) * (1.0 + 4.0 * u) / (1.0 - rho);
                if tail <= TAIL_REL * s.mag() {
                    s.e += tail;
                    return Some(s);
                }
            }
        }
        s = s.add(t);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::special::hyp1f2::hyp1f2_mp_f64;
    use rug::Float;

    fn check(a: f64, b1: f64, b2: f64, z: f64) -> Option<crate::ball::Bounded> {
        let reference = hyp1f2_mp_f64(a, b1, b2, z, 200).unwrap();
        let b = hyp1f2_series_dd(a, b1, b2, z)?.finish()?;
        let d = Float::with_val(300, reference.mid() - b.value).abs();
        assert!(d <= b.err, "1F2({a}; {b1}, {b2}; {z}): {b} vs {reference:?}");
        let p = hyp1f2_series_dd_portable(a, b1, b2, z).unwrap().finish().unwrap();
        assert_eq!((p.value, p.err), (b.value, b.err), "fused and portable differ");
        Some(b)
    }

    #[test]
    fn model_family_at_large_s_is_certified_for_k_at_least_2() {
        // s = 35 (z = -1225) and other large s (two are the bench points that fell
        // back to MP before); k from 7 (the smallest k certified at s = 35) to 1000
        let mut cases: Vec<(u32, f64)> = Vec::new();
        for &k in &[7u32, 8, 13, 34, 100, 1000] {
            for &s in &[35.0f64, 28.469_338_142_245_26, 23.304_422_833_564_544, 10.0, 1.0, 1e-3] {
                cases.push((k, s));
            }
        }
        // the measured edge of the double-word region at smaller s
        cases.extend([(5, 30.0), (3, 25.0), (1, 20.0), (0, 15.0), (0, 10.0)]);
        for (k, s) in cases {
            let kf = k as f64;
            let b = check(0.5, kf + 1.0, kf + 1.5, -s * s).expect("dd series returns a bound");
            assert!(b.err <= 1e-14 * b.value.abs(), "k={k} s={s}: {b}");
        }
    }

    #[test]
    fn bound_holds_where_it_is_not_relative() {
        // k = 0, 1 at s = 35: the cancellation e^70 is beyond double words; the
        // bound still holds (then the caller falls back to MP).
        for &(k, s) in &[(0u32, 35.0f64), (1, 35.0), (0, 20.0), (1, 25.0)] {
            let kf = k as f64;
            if let Some(b) = check(0.5, kf + 1.0, kf + 1.5, -s * s) {
                eprintln!("k={k} s={s}: rel bound {:e}", b.err / b.value.abs());
            }
        }
        // general parameters, non-exact shifts, and a terminating series
        check(0.3, 1.7, 2.9, -400.0).unwrap();
        check(-3.0, 0.25, 1.5, -50.0).unwrap();
        check(1.0 / 3.0, 0.1, 7.0 / 3.0, 30.0).unwrap();
        assert!(hyp1f2_series_dd(0.5, -1.0, 1.5, -1.0).is_none());
    }

    proptest::proptest! {
        #![proptest_config(proptest::test_runner::Config::with_cases(256))]
        /// Over the issue-8 domain of the model family (`k <= 1000`, `s <= 35`,
        /// small `k` oversampled): `hyp1f2_bounded`'s bound holds (f64, double-word
        /// or MP) and is within `1e-14`.
        #[test]
        fn bounded_holds_over_the_model_domain(k in 0u32..=1000, small_k in 0u32..40, pick in 0u32..2, s in 0.0f64..35.0) {
            let k = if pick == 0 { k } else { small_k };
            let (b1, b2, z) = (k as f64 + 1.0, k as f64 + 1.5, -s * s);
            let reference = hyp1f2_mp_f64(0.5, b1, b2, z, 200).unwrap();
            let b = crate::special::hyp1f2::hyp1f2_bounded(0.5, b1, b2, z).unwrap();
            let d = Float::with_val(300, reference.mid() - b.value).abs();
            proptest::prop_assert!(d <= b.err, "k={} s={}: {} vs {:?}", k, s, b, reference);
            proptest::prop_assert!(d.to_f64() <= 1e-14 * b.value.abs(), "k={} s={}", k, s);
            if let Some(dd) = hyp1f2_series_dd(0.5, b1, b2, z).and_then(|v| v.finish()) {
                let d = Float::with_val(300, reference.mid() - dd.value).abs();
                proptest::prop_assert!(d <= dd.err, "dd k={} s={}: {} vs {:?}", k, s, dd, reference);
            }
        }
    }
}
