//! The model family `F_k(-x^2) = 1F2(1/2; k+1, k+3/2; -x^2)` at large `x` in
//! double words with a proven bound: the route of `bessel.rs` (same formulas,
//! same remainder proof) run in [`BoundedDd`], whose running bound is the
//! error analysis (`src/ball/dd_bounded.rs`).
//!
//! # Method
//!
//! `y = 2 sqrt(-z)` in double words (`y~`, bound `e_y`); `J_0`, `J_1` at the f64
//! `y0 = hi(y~)` by the native Hankel path (`bessel_j01`, proven bound, `y0 >= 25`)
//! and moved to `y` by one Taylor step: with `D = y - y0` (`|D - lo(y~)| <= e_y`),
//! `J_0(y) = J_0(y0) - J_1(y0) D + R_0`, `J_1(y) = J_1(y0) + (J_0(y0) - J_1(y0)/y0) D + R_1`,
//! `|R_i| <= D^2/2`, since every derivative of `J_n` is at most 1 in modulus on
//! the real axis (`J_n^(m) = 2^-m sum_j (-1)^j C(m, j) J_{n-m+2j}` [DLMF 10.6.7]
//! and `|J_nu| <= 1` [DLMF 10.14.1]). Then `U`, `V` (asymptotic series of the
//! Struve differences, remainder at most the first omitted term: `bessel.rs`),
//! `Lambda = 1 + J_1 U - y J_0 V`, the moments `m_j` and the binomial sum, all in
//! [`BoundedDd`]. The series `U`, `V` stop at the first `p >= 1` with
//! `y |u_p| <= 2^-64`, or at their smallest term (`2p + 1 >= y`; the remainder
//! bound holds for every `p >= 1`): below about `y = 40` that term is too large
//! for `1e-14` and the caller, which accepts only a bound of `1e-14` relative,
//! goes on to the series.
//!
//! Used by [`super::hyp1f2_bounded`] for the family at `k <= x/2`, where the
//! series cancel (`e^{2x}` against `x^{-2k}`) and the double-word series needs
//! `k >= 7` at `x = 35`; the MP fallback took about 100 us there.

use crate::ball::cpu_dispatch;
use crate::ball::{Bounded, BoundedDd, Dd, ExactProduct};
use crate::special::bessel_j::{bessel_j01, HANKEL_MAX_X, HANKEL_MIN_X};

/// `2^-64`: the stopping target of `y |u_p|`.
const TARGET: f64 = 5.421010862427522e-20;

cpu_dispatch! {
    /// `F_k(z)` for `z < 0` with a proven bound, or `None` where the route does not
    /// apply (`y = 2 sqrt(-z)` outside the Hankel range, `4k > y`, `C(2k, j)`
    /// above `2^53`). The bound may be wide where `y < 40` (see the module docs).
    pub(crate) fn model_family_bessel_f64(k: u32, z: f64) -> Option<Bounded> => family_with
}

#[inline(always)]
fn family_with<P: ExactProduct>(k: u32, z: f64) -> Option<Bounded> {
    if !(z < 0.0) {
        return None;
    }
    let y = BoundedDd::exact(-z).sqrt_p::<P>()?.mul_f64_p::<P>(2.0);
    let y0 = y.v.hi;
    if !(HANKEL_MIN_X..=HANKEL_MAX_X).contains(&y0) || 4.0 * k as f64 > y0 {
        return None;
    }
    // J_0, J_1 at y0, moved to y by one Taylor step
    let (j0_0, j1_0) = bessel_j01::<P>(y0)?;
    let d = BoundedDd { v: Dd::from_f64(y.v.lo), e: y.e };
    let d_up = y.v.lo.abs() + y.e;
    let taylor = 0.5 * d_up * d_up;
    let j0 = j0_0.sub(j1_0.mul_p::<P>(d));
    let j0 = BoundedDd { v: j0.v, e: j0.e + taylor };
    let j1_slope = j0_0.sub(j1_0.div_f64_p::<P>(y0));
    let j1 = j1_0.add(j1_slope.mul_p::<P>(d));
    let j1 = BoundedDd { v: j1.v, e: j1.e + taylor };
    let inv_y = BoundedDd::ONE.div(y)?;
    let inv_y2 = inv_y.mul_p::<P>(inv_y);
    let (sum_u, sum_v) = struve_tails(y0, d_up)?;
    let lambda = BoundedDd::ONE.add(j1.mul_p::<P>(sum_u)).sub(y.mul_p::<P>(j0).mul_p::<P>(sum_v));
    let m0 = lambda.mul_p::<P>(inv_y);
    if k == 0 {
        return m0.finish();
    }
    let j1_y = j1.mul_p::<P>(inv_y);
    let j0_y2 = j0.mul_p::<P>(inv_y2);
    let two_k = 2.0 * k as f64;
    let (mut prev2, mut prev1) = (m0, j1_y);
    let mut binom = 1.0f64; // C(2k, j), exact while below 2^53
    let mut total = m0;
    let mut j = 1.0f64;
    while j <= two_k {
        let mj = if j == 1.0 {
            j1_y
        } else {
            let m = j1_y.add(j0_y2.mul_f64_p::<P>(j - 1.0)).sub(prev2.mul_p::<P>(inv_y2).mul_f64_p::<P>((j - 1.0) * (j - 1.0)));
            prev2 = prev1;
            prev1 = m;
            m
        };
        // C(2k, j) = C(2k, j-1) (2k-j+1) / j: exact while the product is below 2^53
        let prod = binom * (two_k - j + 1.0);
        if !(prod < 9.0e15) {
            return None;
        }
        binom = prod / j;
        let term = mj.mul_f64_p::<P>(binom);
        total = if j % 2.0 == 1.0 { total.sub(term) } else { total.add(term) };
        j += 1.0;
    }
    total.mul_f64_p::<P>(two_k + 1.0).finish()
}

/// `U = sum_{p>=0} u_p` and `V = sum_{p>=1} v_p` (module docs; `u_0 = v_0 = 1`,
/// `u_{p+1} = -u_p (2p+1)^2/y^2`, `v_{p+1} = v_p (1-2p)(2p+1)/y^2`) as double words
/// `1 + T_u` and `T_v` with bounds, for `y = y0 + D`, `|D| <= d_up`.
///
/// The tails `T_u = sum_{p>=1} u_p`, `T_v` are at most `1/y^2` in size, so they
/// are summed in f64: `r = fl(1/fl(y0 y0))` has relative error at most
/// `eps_r = 2.01 u + 2.01 d_up/y0` against `1/y^2` (two roundings, and
/// `(y0/y)^2` within `1 +- 2.01 |D|/y0`), and `u~_p = fl(fl(u~_{p-1} r) c_p)` with
/// the exact integer `c_p` has relative error at most `p (eps_r + 2u) 1.01`
/// while that is below `0.01` (induction on `(1 + eps)^p <= 1 + 1.01 p eps`).
/// The recursive sum adds at most `u |partial sum|` per addition. The remainder
/// after the last term `p >= 1` is at most `|u_p|` (resp. `|v_p|`): see
/// `bessel.rs`. The loop stops at `y |u_p| <= 2^-64` or at the smallest term
/// (`2p + 1 >= y`).
#[inline(always)]
fn struve_tails(y0: f64, d_up: f64) -> Option<(BoundedDd, BoundedDd)> {
    let u = crate::ball::U;
    let r = 1.0 / (y0 * y0);
    let eps = 2.01 * u + 2.01 * d_up / y0 + 2.0 * u;
    let (mut tu, mut tv) = (1.0f64, 1.0f64);
    let (mut su, mut sv) = (0.0f64, 0.0f64);
    let (mut err_u, mut err_v) = (0.0f64, 0.0f64);
    let mut p = 0.0f64;
    loop {
        let q = 2.0 * p + 1.0;
        tu = tu * r * (-q * q);
        tv = tv * r * ((1.0 - 2.0 * p) * q);
        p += 1.0;
        let rel = 1.01 * p * eps;
        if !(rel < 0.01) {
            return None;
        }
        let (au, av) = (tu.abs() * (1.0 + rel) / (1.0 - rel), tv.abs() * (1.0 + rel) / (1.0 - rel));
        if y0 * 1.000_001 * au <= TARGET || 2.0 * p + 1.0 >= y0 {
            // remainders |u_p|, |v_p| (the first omitted terms)
            err_u += au;
            err_v += av;
            break;
        }
        su += tu;
        sv += tv;
        err_u += rel * au + u * su.abs();
        err_v += rel * av + u * sv.abs();
    }
    let (hi, lo) = crate::ball::two_sum(1.0, su);
    let bu = BoundedDd { v: Dd { hi, lo }, e: err_u * crate::ball::BOUND_INFLATION };
    let bv = BoundedDd { v: Dd::from_f64(sv), e: err_v * crate::ball::BOUND_INFLATION };
    Some((bu, bv))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::special::hyp1f2::hyp1f2_mp_f64;
    use rug::Float;

    #[test]
    fn bound_holds_and_is_tight() {
        let mut accepted = 0;
        for &s in &[18.0f64, 19.0, 20.0, 22.0, 23.5, 27.25, 30.0, 34.999, 35.0, 60.0, 400.0] {
            for k in [0u32, 1, 2, 3, 5, 6, 10, 17] {
                let z = -s * s;
                let Some(b) = model_family_bessel_f64(k, z) else { continue };
                let exact = hyp1f2_mp_f64(0.5, k as f64 + 1.0, k as f64 + 1.5, z, 200).unwrap();
                let diff = Float::with_val(300, exact.mid() - b.value).abs();
                assert!(diff <= b.err, "k={k} s={s}: {b} vs {exact:?}");
                if b.err <= 1e-14 * b.value.abs() {
                    accepted += 1;
                }
            }
        }
        assert!(accepted >= 50, "{accepted}");
    }

    #[test]
    fn declines_outside_its_range() {
        assert!(model_family_bessel_f64(0, -100.0).is_none()); // y = 20 < 25
        let wide = model_family_bessel_f64(0, -160.0).unwrap(); // y = 25.3: e^-24 remainder
        assert!(wide.err > 1e-14 * wide.value.abs(), "{wide}");
        assert!(model_family_bessel_f64(20, -35.0 * 35.0).is_none()); // 4k > y
        assert!(model_family_bessel_f64(0, 4.0).is_none());
    }
}
