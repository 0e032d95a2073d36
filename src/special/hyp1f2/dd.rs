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
//! (`bessel_f64.rs`) from `s = 17`. For the model family the caller now tries
//! [`family_series_dd`] (below) first, the same series at a third of the cost.
//!
//! **Tail** (as in the f64 series): once `a+N, b1+N, b2+N > 0`,
//! `|t_{n+1}/t_n| <= rho_N = |z| max(1, (a+N)/(b1+N)) / ((b2+N)(N+1))` for all
//! `n >= N` (each factor is monotone in `n`), so `sum_{n>=N} |t_n| <= |t_N|/(1 - rho_N)`;
//! the sum stops when that is at most `2^-70 |sum|` (with `rho_N <= 1/2`).
//!
//! **The model family** `F_k = 1F2(1/2; k+1, k+3/2; z)` ([`family_series_dd`]):
//! the same series with the bound proven once, a priori, instead of carried per
//! operation, and the term ratio formed off the dependency chain. With
//! `t_{n+1} = t_n rho_n`, `rho_n = z (2n+1)/den_n`, `den_n = (k+1+n)(2k+3+2n)(n+1)`
//! (an exact integer while below `2^53`, checked), each step is
//!
//! * `rho~_n = div_f64(z (2n+1), den_n)`: the product of two f64 exact (two_prod),
//!   the division charged `C_DIV = 16 u^2` of `|rho~_n|` (the error model of
//!   `src/ball/dd_bounded.rs`, which uses the same double-word algorithms);
//! * `t~_{n+1} = t~_n rho~_n`: charged `C_MUL = 8 u^2 |t~_n| |rho~_n|`;
//! * `s~ = s~ + t~` (the double-word addition): charged `C_ADD = 8 u^2 (|s~| + |t~|)`;
//!
//! with `|d|` the magnitude `|d.hi| + |d.lo|`. **Terms.** Let `E_n = |t~_n - t_n|`.
//! Then `E_{n+1} <= |t~_n| |rho~_n - rho_n| + |rho_n| E_n + C_MUL |t~_n| |rho~_n|
//! <= 24 u^2 |t~_n| |rho~_n| + |rho_n| E_n`, and `|t~_n| |rho~_n| <= (1 + 7u) |t~_{n+1}|`
//! (the product's high part is `fl(p + e)`, `|e| <= 3u |p|`), `|rho_n| <= (1 + 16 u^2) |rho~_n|`.
//! By induction `E_n <= n kappa |t~_n|` with `kappa = 25 u^2`: the step from `n` to
//! `n + 1` needs `24 (1 + 7u) + 200 n u <= 25`, true for `n <= 2^44` (the loop stops
//! at [`MAX_TERMS`]). **Sum.** The additions add at most
//! `C_ADD (B + A)` with `A = sum_n |t~_n|`, `B = sum_n |s~_{n-1}|` (both summed in
//! the loop, in f64), so after the terms `0..N-1`
//! `|s~ - sum_{n<N} t_n| <= kappa (N - 1) A + C_ADD (A + B)`. **Tail** as above, with
//! `|t_N| <= (1 + N kappa) |t~_N|` and `rho_N = |z|/((k+3/2+N)(N+1))` (here
//! `(a+N)/(b1+N) < 1`). The bound is evaluated in f64 (a few hundred roundings,
//! and `A`, `B` summed with relative error `<= N u`: covered by
//! `BOUND_INFLATION = 1 + 2^-30` in `BoundedDd::finish`, which also adds the final
//! rounding to f64). Cost: one double-word product and one addition on the chain
//! a term, against three products and a division with running bounds in
//! [`hyp1f2_series_dd`].
//!
//! References: DLMF 16.2.1 (the series); Joldes, Muller, Popescu, ACM TOMS 44
//! (2017) for the double-word operations.

use crate::ball::cpu_dispatch;
use crate::ball::{div_f64_p, mag, two_sum, BoundedDd, Dd, ExactProduct, C_ADD, U2};

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

cpu_dispatch! {
    /// `F_k(z) = 1F2(1/2; k+1, k+3/2; z)` for `z < 0` by its series in
    /// double-double with the a-priori bound of the module docs (`None`: `z` not
    /// negative and finite, a denominator above `2^53`, no convergence within
    /// the cap). The bound is absolute; the caller decides whether it is
    /// relative enough (the cancellation is about `e^{2 sqrt(-z)}`).
    pub(crate) fn family_series_dd(k: u32, z: f64) -> Option<BoundedDd> => family_series_with
}

/// [`family_series_dd`] with Dekker's products (tests compare the two).
#[cfg(test)]
pub(crate) fn family_series_dd_portable(k: u32, z: f64) -> Option<BoundedDd> {
    family_series_with::<crate::ball::Dekker>(k, z)
}

#[inline(always)]
fn family_series_with<P: ExactProduct>(k: u32, z: f64) -> Option<BoundedDd> {
    if !(z < 0.0 && z.is_finite()) {
        return None;
    }
    const KAPPA: f64 = 25.0 * U2;
    // 2^53: the integer denominators are exact below it
    const EXACT_INT: f64 = 9_007_199_254_740_992.0;
    let u = crate::ball::U;
    let kf = k as f64;
    let (mut t, mut s) = (Dd::ONE, Dd::ONE);
    // A = sum |t~_n| over the terms summed, B = sum |s~_{n-1}| over the additions
    let (mut a_sum, mut b_sum) = (1.0f64, 0.0f64);
    let mut n: u64 = 0;
    loop {
        let nf = n as f64;
        let den = (kf + 1.0 + nf) * (2.0 * kf + 3.0 + 2.0 * nf) * (nf + 1.0);
        if !(den < EXACT_INT) || n >= MAX_TERMS {
            return None;
        }
        let rho = div_f64_p::<P>(Dd::prod_p::<P>(z, 2.0 * nf + 1.0), den);
        t = t.mul_p::<P>(rho);
        n += 1;
        let (mt, ms) = (mag(t), mag(s));
        if !mt.is_finite() {
            return None;
        }
        if mt <= TAIL_REL * ms {
            let nf = n as f64;
            let rho_n = -z / ((kf + 1.5 + nf) * (nf + 1.0)) * (1.0 + 8.0 * u);
            if rho_n <= 0.5 {
                let tail = mt * (1.0 + nf * KAPPA) * (1.0 + 4.0 * u) / (1.0 - rho_n);
                if tail <= TAIL_REL * ms {
                    let e = KAPPA * (nf - 1.0) * a_sum + C_ADD * (a_sum + b_sum) + tail;
                    return Some(BoundedDd { v: s, e });
                }
            }
        }
        a_sum += mt;
        b_sum += ms;
        s = s + t;
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
    fn family_series_encloses_and_is_relative_where_the_route_is_taken() {
        // the route of hyp1f2_bounded for the family at k < s - 2 and s below the
        // Bessel route (s < 17.5): every k it serves there, s on a grid through
        // the range plus the largest s it can be asked at; the bound must enclose
        // the 200-bit value and be 1e-14 relative (the acceptance of the caller)
        let mut worst = 0.0f64;
        for k in [0u32, 1, 2, 3, 5, 8, 10, 14] {
            for i in 0..=24 {
                let s = 2.5 + 15.0 * i as f64 / 24.0 + 0.013;
                if (k as f64) >= s - 2.0 {
                    continue;
                }
                let z = -s * s;
                let kf = k as f64;
                let reference = hyp1f2_mp_f64(0.5, kf + 1.0, kf + 1.5, z, 200).unwrap();
                let b = family_series_dd(k, z).expect("family series converges").finish().unwrap();
                let d = Float::with_val(300, reference.mid() - b.value).abs();
                assert!(d <= b.err, "k={k} s={s}: {b} vs {reference:?}");
                let p = family_series_dd_portable(k, z).unwrap().finish().unwrap();
                assert_eq!((p.value, p.err), (b.value, b.err), "fused and portable differ");
                worst = worst.max(b.err / b.value.abs());
            }
        }
        // measured 1.2e-15 (the bound, dominated at s = 17.5 by kappa N A)
        assert!(worst <= 1e-14, "worst relative bound {worst:e}");
        // beyond its range (k = 0 at s = 35: cancellation e^70) the bound still holds
        let b = family_series_dd(0, -1225.0).unwrap().finish().unwrap();
        let reference = hyp1f2_mp_f64(0.5, 1.0, 1.5, -1225.0, 200).unwrap();
        assert!(Float::with_val(300, reference.mid() - b.value).abs() <= b.err);
        assert!(family_series_dd(3, 0.5).is_none() && family_series_dd(3, f64::NAN).is_none());
    }

    #[test]
    fn bounded_encloses_on_a_dense_grid_across_the_route_switches() {
        // hyp1f2_bounded for the family at small k, where it switches between the
        // f64 series, the double-word family series (first where its cancellation
        // estimate allows) and the Bessel route: every point encloses the 200-bit
        // value with a bound of at most 1e-14 relative, and none falls back to MP
        for k in 0u32..=12 {
            for i in 0..=95 {
                let s = 0.5 + 34.5 * i as f64 / 95.0;
                let (kf, z) = (k as f64, -s * s);
                let reference = hyp1f2_mp_f64(0.5, kf + 1.0, kf + 1.5, z, 200).unwrap();
                // the native paths alone (the global fallback counter is shared with
                // the tests running beside this one): Some = no MP fallback
                let native = crate::special::hyp1f2::hyp1f2_native_bounded(0.5, kf + 1.0, kf + 1.5, z, super::super::NATIVE_REL_TOL);
                let b = native.unwrap().unwrap_or_else(|| panic!("k={k} s={s}: MP fallback"));
                let d = Float::with_val(300, reference.mid() - b.value).abs();
                assert!(d <= b.err && b.err <= 1e-14 * b.value.abs(), "k={k} s={s}: {b} vs {reference:?}");
            }
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
