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
//! ACM TOMS 44 (2017)): a double-double product `<= 8 eps`, a quotient by an f64
//! `<= 16 eps`, the sum of two positive double-doubles `<= 8 eps` of the result, all
//! relative here (every operand is positive). `w N_m` is exact (`two_prod`), so
//! `R~_m = R_m (1 + theta)`, `|theta| <= 16 eps`, and each step of a recurrence adds
//! `16 + 8 = 24 eps`: `eta(tau_m) <= 24 (m-1) eps` (`tau_1` is exact: an exact product
//! halved), `eta(sigma_j) <= (16 + 24 j) eps` (`sigma_0 = 2/3` one quotient), to first
//! order (the second-order terms are below `(24 * 6000 eps)^2` relative, covered by the
//! factor `1 + 2^-20`). The computed sum `s~_M = sum_m (s~_{m-1} + t~_m)(1 + delta_m)`
//! differs from `sum_m t~_m` by at most `8 eps sum_m s~_m`, and `sum_m t~_m` from the
//! exact partial sum by `sum_m eta_m t_m`. Both weighted sums are accumulated in f64
//! as the terms are formed (off the recurrences' dependency chains), so the bound is
//! what this evaluation incurred, not a worst case over the longest sum.
//!
//! The sums stop (checked every 4 terms) when the tail is below `2^-64 (1-w)^k` of the
//! sum (the parts grow like `(1-w)^{-k}` before they cancel, so that is about
//! `2^-64 |G|`), or `2^-104` of it, whichever is larger: the stopping rule only sets the
//! cost, the tail added is the proven one. `ln y` is the double-double
//! [`super::dd::ln_dd`] (running bound); the assembly (six operations, where the parts
//! cancel) runs in the bounded double-doubles of `dd_bounded.rs`. The two recurrences
//! are interleaved in one loop, so that their dependency chains overlap.
//!
//! Accuracy: the result's error is about `50 M eps (1-w)^{-k} |G|`, so its bound is
//! `1e-14` relative while `-k ln(1 - w) <= ~30`; the caller accepts it only then.
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

cpu_dispatch! {
    /// `G(k, 1 - w)` by the near-one expansion in plain double-double, `0 < w <= 1/2`
    /// exact, with its proven bound (module docs). FMA products where the CPU has them
    /// (bit-identical to Dekker's).
    pub(crate) fn near_one_fast(k: u32, w: f64, c: &DdConstants) -> Option<BoundedDd> => near_one_fast_with
}

/// [`near_one_fast`] with Dekker's products (tests compare the two).
#[cfg(test)]
pub(crate) fn near_one_fast_portable(k: u32, w: f64, c: &DdConstants) -> Option<BoundedDd> {
    near_one_fast_with::<crate::ball::Dekker>(k, w, c)
}

/// `R = w n/d` for exact integers `n`, `d` as a normalized double-double, given
/// `inv = fl(fl(1/(d d')) d')`, `1/d` within `gamma_2` (module docs: relative error
/// `<= 20 eps`).
#[inline(always)]
fn ratio<P: ExactProduct>(w: f64, n: f64, d: f64, inv: f64) -> Dd {
    let (a, ae) = P::two_prod(w, n); // a + ae = w n exactly
    let rh = a * inv;
    let (p, pe) = P::two_prod(rh, d); // rh d = p + pe exactly; a - p exact (Sterbenz)
    let rl = (((a - p) - pe) + ae) * inv;
    let hi = rh + rl; // quick_two_sum (|rl| <= 4.1 u rh): exact
    Dd { hi, lo: rl - (hi - rh) }
}

/// One step of both recurrences: `tau_m` and `sigma_{m-1}` (module docs), added to
/// the accumulators `t1`, `t2`; `w1`, `w2` collect the weighted error sums (units of `eps`).
#[inline(always)]
#[allow(clippy::too_many_arguments)]
fn step<P: ExactProduct>(m: u64, kf: f64, w: f64, tau: &mut Dd, sigma: &mut Dd, t1: &mut Dd, t2: &mut Dd, w1: &mut f64, w2: &mut f64) {
    let mf = m as f64;
    let jf = mf - 1.0; // sigma's index
    let d1 = mf * (2.0 * mf - 3.0);
    let d2 = jf * (2.0 * jf + 3.0);
    // one quotient for both ratios: 1/d1 = d2/(d1 d2) (d1 d2 < 2^53, exact)
    let q = 1.0 / (d1 * d2);
    // tau_m = tau_{m-1} w (2k+2m-1)(m-1)/(m(2m-3))
    *tau = tau.mul_p::<P>(ratio::<P>(w, (2.0 * kf + 2.0 * mf - 1.0) * (mf - 1.0), d1, q * d2));
    *t1 = *t1 + *tau;
    *w1 += 32.0 * (mf - 1.0) * tau.hi + 8.0 * t1.hi;
    // sigma_j = sigma_{j-1} w (k+1+j)(2j+1)/(j(2j+3)), j = m - 1
    *sigma = sigma.mul_p::<P>(ratio::<P>(w, (kf + 1.0 + jf) * (2.0 * jf + 1.0), d2, q * d1));
    *t2 = *t2 + *sigma;
    *w2 += (16.0 + 32.0 * jf) * sigma.hi + 8.0 * t2.hi;
}

#[inline(always)]
fn near_one_fast_with<P: ExactProduct>(k: u32, w: f64, c: &DdConstants) -> Option<BoundedDd> {
    if !(w > 0.0 && w <= 0.5) {
        return None;
    }
    let kf = k as f64;
    let up = 1.0 + 8.0 * U;
    let eps = U * U;
    // stop a sum when its tail is below rel_stop of it: 2^-64 (1-w)^k (an estimate of
    // |G| over the parts; only the cost depends on it), at least 2^-104
    let rel_stop = (5.421010862427522e-20 * (kf * (-w).ln_1p()).exp()).max(4.930380657631324e-32);
    // T1: tau_1 = w (2k+1)/2 (exact), T2: sigma_0 = 2/3
    let mut tau = Dd::prod_p::<P>(w, 2.0 * kf + 1.0);
    tau = Dd { hi: 0.5 * tau.hi, lo: 0.5 * tau.lo };
    let mut t1 = tau;
    let mut w1 = 8.0 * t1.hi; // sum eta_m t~_m + 8 s~_m, in units of eps
    let mut sigma = crate::ball::div_f64_p::<P>(Dd::from_f64(2.0), 3.0);
    let mut t2 = sigma;
    let mut w2 = 16.0 * sigma.hi + 8.0 * t2.hi;
    // second accumulators (odd m), so that the additions form two chains each; the two
    // recurrences run the same number of steps (their counts differ by a few at most)
    let (mut t1b, mut t2b) = (Dd::ZERO, Dd::ZERO);
    let mut m = 1u64; // index of the last tau (and of the last sigma plus one)
    let (e1, e2) = loop {
        step::<P>(m + 1, kf, w, &mut tau, &mut sigma, &mut t1, &mut t2, &mut w1, &mut w2);
        step::<P>(m + 2, kf, w, &mut tau, &mut sigma, &mut t1b, &mut t2b, &mut w1, &mut w2);
        m += 2;
        if m % 4 != 1 {
            continue;
        }
        let mf = m as f64;
        let jf = mf - 1.0;
        // T1: rho_{m+1} = tau_m (2m/(2m-1)) w (2k+2m+1)/(2m+1); ratio_{m+1} = w (2k+2m+3)/(2m+3)
        let r1 = w * (2.0 * kf + 2.0 * mf + 3.0) / (2.0 * mf + 3.0) * up;
        // T2: ratio bound w (k+2+j)/(j+1)
        let r2 = w * (kf + 2.0 + jf) / (jf + 1.0) * up;
        if r1 < 1.0 && r2 < 1.0 {
            let tau_up = tau.hi * (1.0 + 2.0 * U + 32.0 * mf * eps);
            let rho_next = tau_up * (2.0 * mf / (2.0 * mf - 1.0)) * w * (2.0 * kf + 2.0 * mf + 1.0) / (2.0 * mf + 1.0) * up;
            let tail1 = rho_next / (1.0 - r1) * up;
            let tail2 = sigma.hi * (1.0 + 2.0 * U + (16.0 + 32.0 * jf) * eps) * r2 / (1.0 - r2) * up;
            if tail1 <= rel_stop * (t1.hi + t1b.hi) && tail2 <= rel_stop * (t2.hi + t2b.hi) {
                t1 = t1 + t1b;
                t2 = t2 + t2b;
                w1 += 8.0 * t1.hi;
                w2 += 8.0 * t2.hi;
                break (tail1 + eps * w1 * (1.0 + 2.0 * U) * SLACK, tail2 + eps * w2 * (1.0 + 2.0 * U) * SLACK);
            }
        }
        if m > MAX_TERMS {
            return None;
        }
    };
    let t1 = BoundedDd { v: t1, e: e1 };
    let t2 = BoundedDd { v: t2, e: e2 };
    let w32 = BoundedDd::exact(w).sqrt_p::<P>()?.mul_f64_p::<P>(w);
    let part2 = c.two_sqrt_pi.mul_p::<P>(w32).mul_p::<P>(t2);
    let base = c.b1.add(t1);
    // ln y in f64 (about 30 ns) where its error, C_k |ln y| u/2, is below 1/8 of the
    // 1e-14 |G| the caller asks; else in double-double (ln_dd, about 0.2-0.3 us)
    let y = 1.0 - w;
    if let Some(l) = ln_bounded(y) {
        let half_ln_y = BoundedDd { v: Dd::from_f64(0.5 * l.v), e: 0.5 * l.e };
        let g = c.c.mul_p::<P>(base.sub(half_ln_y)).sub(part2);
        if c.c.v.hi * half_ln_y.e <= 1.25e-15 * g.v.hi.abs() {
            return Some(g);
        }
    }
    let half_ln_y = ln_dd::<P>(y, c.ln2)?.mul_f64_p::<P>(0.5);
    Some(c.c.mul_p::<P>(base.sub(half_ln_y)).sub(part2))
}
