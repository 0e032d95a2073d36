//! `J_0(x)` and `J_1(x)` in double-double with a **proven** error bound, by
//! Hankel's expansion, for `x >= HANKEL_MIN_X`: the starting pair of the
//! forward recurrence (`native_recurrence.rs`).
//!
//! # Method
//!
//! [DLMF 10.17.3] for `nu = 0, 1`, `w = x - pi/4`, `A = sqrt(2/(pi x))`:
//!
//! ```text
//! J_0(x) = A (P_0 cos w - Q_0 sin w),    J_1(x) = A (P_1 sin w + Q_1 cos w),
//! P_nu = sum_j (-1)^j s_{2j},   Q_nu = sum_j (-1)^j s_{2j+1},   s_k = a_k(nu) x^-k,
//! ```
//!
//! (`J_1`'s phase is `w - pi/2`), `a_k(nu) = prod_{j<=k} (4 nu^2 - (2j-1)^2) / (k! 8^k)`
//! [DLMF 10.17.1]. With `v = 1/(8x)`, `s_k = e_k(nu) v^k`, and `e_k = 8^k a_k` is
//! exact in binary for `k <= 4` (`nu = 0`: 1, -1, 9/2, -75/2, 3675/8;
//! `nu = 1`: 1, 3, -15/2, 105/2, -4725/8).
//!
//! * **Head** `k <= 5` in double-double: `v` by one division, its powers by
//!   products, each `e_k v^k` by an exact-f64 scaling.
//! * **Tail** `k >= 6` in f64: `s_k = s_{k-1} (4nu^2 - (2k-1)^2) fl(v) / k` from
//!   `fl(s_5)`, four roundings a step (`fl(v)` included), so
//!   `|fl(s_k) - s_k| <= (1 + 4.01 (k-5)) u |s_k|` (`k <= 200`), summed smallest
//!   first with `u |partial sum|` per addition. At `x >= 25`, `|s_6| <= 2.4e-9`,
//!   so the tail's f64 error is below `2e-24`.
//! * **Truncation** [DLMF 10.17.14 with 10.17.15, on the real axis, as in
//!   `hankel.rs`]: after `l` terms the remainder of the complex sum is at most
//!   `2 |a_l x^-l| exp(|nu^2 - 1/4|/x) <= 2.07 |s_l|` for `x >= 25`
//!   (`exp(0.75/25) < 1.031`), whatever the phase; `l` is the first index with
//!   `2.07 |s_l| (1 + 4.01 l u) <= 2^-84`, or where the terms start to grow
//!   (the least term is `2.2e-23` at `x = 25`, `9e-28` at `x = 30`).
//! * **Phase**: `w = r + q pi/2` with `q = round((x - pi/4)/(pi/2))` and
//!   `r = x - (2q+1) pi/4`, computed as `x - m * PI_4` in double-double from the
//!   double-double `PI_4` (`|PI_4 - pi/4| <= 7.5e-34`, checked against MPFR in the
//!   tests) with its error carried (`m <= 2^40`). `sin r`, `cos r` at the
//!   double-double value `r~` (`|r~| <= 0.8`) by Taylor series: the powers
//!   `s^j/(2j+1)!`, `s^j/(2j)!` (`s = r~^2`) up to `j = 5` in double-double by
//!   Horner with the `1/k!` table (relative error `2 u^2`), the rest in f64 from
//!   `j = 6` (below `1e-10`; `3.04 j u` relative per term, summed smallest first
//!   with `u |partial sum|` per addition). The series alternate with decreasing terms (`s < 1`), so the
//!   remainder is below the first neglected term, taken below `2^-100`. The
//!   error of `r~` adds `|r - r~|` to both (`|sin'|, |cos'| <= 1`).
//! * `A = sqrt(2/(pi x))` from the double-double `2/pi` (`|error| <= 2.2e-33`).
//!
//! Every double-double step carries its bound by the model of
//! `crate::ball::dd_bounded`; the result errors are about `1e-23` at `x = 25`
//! and below `1e-25` from `x = 30` on.

use crate::ball::{BoundedDd, Dd, U};

use super::native_series::{inv_factorials, TABLE_ETA};

/// Smallest `x` of this path: below it the least term of the expansion (about
/// `e^{-2x}`) stops being small enough, and the power series is used instead.
pub(crate) const HANKEL_MIN_X: f64 = 25.0;
/// Largest `x` (the phase multiple `m` stays exact and the reduction error small).
pub(crate) const HANKEL_MAX_X: f64 = (1u64 << 40) as f64;
/// `2 exp(0.75/x)` for `x >= HANKEL_MIN_X`, rounded up.
const REMAINDER_FACTOR: f64 = 2.07;
/// Truncation target of the expansion, `2^-84`.
const HANKEL_TARGET: f64 = 5.169878828456423e-26;
/// Truncation target of the sine and cosine series, `2^-100`.
const TAYLOR_TARGET: f64 = 7.888609052210118e-31;
/// Most terms before giving up (not reached for `x >= 25`).
const MAX_TERMS: usize = 200;

/// `pi/4` as a double-double with its error bound (MPFR: `7.49e-34`).
const PI_4: BoundedDd = BoundedDd { v: Dd { hi: 0.7853981633974483, lo: 3.061616997868383e-17 }, e: 7.5e-34 };
/// `2/pi` as a double-double with its error bound (MPFR: `2.14e-33`).
const TWO_OVER_PI: BoundedDd = BoundedDd { v: Dd { hi: 0.6366197723675814, lo: -3.935735335036497e-17 }, e: 2.2e-33 };

/// Highest `k` of the double-double head.
const HEAD: usize = 5;
/// `e_k(nu) = 8^k a_k(nu)`, `k = 0..=HEAD`, exact.
const E0: [f64; HEAD + 1] = [1.0, -1.0, 4.5, -37.5, 459.375, -7441.875];
const E1: [f64; HEAD + 1] = [1.0, 3.0, -7.5, 52.5, -590.625, 9095.625];

/// `(J_0(x), J_1(x))` with proven bounds, `HANKEL_MIN_X <= x <= HANKEL_MAX_X`.
pub(crate) fn bessel_j01(x: f64) -> Option<(BoundedDd, BoundedDd)> {
    if !(HANKEL_MIN_X..=HANKEL_MAX_X).contains(&x) {
        return None;
    }
    let (p0, q0) = hankel_pq(x, &E0, 0.0)?;
    let (p1, q1) = hankel_pq(x, &E1, 4.0)?;
    let (sin_w, cos_w) = sin_cos_phase(x)?;
    let amp = TWO_OVER_PI.div_f64(x).sqrt()?;
    let j0 = amp.mul(p0.mul(cos_w).sub(q0.mul(sin_w)));
    let j1 = amp.mul(p1.mul(sin_w).add(q1.mul(cos_w)));
    Some((j0, j1))
}

/// `P_nu`, `Q_nu` with their bounds; the truncation remainder is added to
/// both (it bounds the complex remainder).
fn hankel_pq(x: f64, e: &[f64; 6], four_nu2: f64) -> Option<(BoundedDd, BoundedDd)> {
    let v = BoundedDd::ONE.div_f64(8.0 * x);
    let v2 = v.mul(v);
    let v3 = v2.mul(v);
    let v4 = v2.mul(v2);
    let v5 = v4.mul(v);
    let p = BoundedDd::ONE.add(v2.mul_f64(-e[2])).add(v4.mul_f64(e[4]));
    let s5 = v5.mul_f64(e[5]);
    let q = v.mul_f64(e[1]).add(v3.mul_f64(-e[3])).add(s5);
    // f64 tail from k = HEAD + 1, signed terms stored and summed smallest first.
    let vf = v.v.hi;
    let mut terms = [0.0f64; MAX_TERMS];
    let mut s = s5.v.hi;
    let mut k = HEAD + 1;
    let mut term_err = 0.0f64;
    let remainder = loop {
        let odd = (2 * k - 1) as f64;
        let s_prev = s;
        s = s * (four_nu2 - odd * odd) * vf / k as f64;
        let rel = U + 4.01 * (k - HEAD) as f64 * U;
        let bound = REMAINDER_FACTOR * s.abs() * (1.0 + rel);
        // The bound holds for every l: stop at the target or where the terms
        // turn to grow (the least term, about 2e-23 at x = 25).
        if bound <= HANKEL_TARGET || s.abs() >= s_prev.abs() {
            break bound;
        }
        if k >= MAX_TERMS - 1 || !s.is_finite() {
            return None;
        }
        term_err += rel * s.abs();
        terms[k] = if (k / 2) % 2 == 1 { -s } else { s };
        k += 1;
    };
    let (mut tail_p, mut tail_q, mut sum_err) = (0.0f64, 0.0f64, 0.0f64);
    for j in (HEAD + 1..k).rev() {
        if j % 2 == 0 {
            tail_p += terms[j];
            sum_err += U * tail_p.abs();
        } else {
            tail_q += terms[j];
            sum_err += U * tail_q.abs();
        }
    }
    let err = term_err + sum_err + remainder;
    Some((p.add(BoundedDd { v: Dd::from_f64(tail_p), e: err }), q.add(BoundedDd { v: Dd::from_f64(tail_q), e: err })))
}

/// `(sin w, cos w)`, `w = x - pi/4`, with proven bounds (module docs).
fn sin_cos_phase(x: f64) -> Option<(BoundedDd, BoundedDd)> {
    let quarter_turns = ((x - PI_4.v.hi) / (2.0 * PI_4.v.hi)).round();
    let m = 2.0 * quarter_turns + 1.0; // exact: x <= 2^40
    let r = BoundedDd::exact(x).sub(PI_4.mul_f64(m));
    let (s, c) = sin_cos_reduced(r.v)?;
    let (s, c) = (BoundedDd { v: s.v, e: s.e + r.e }, BoundedDd { v: c.v, e: c.e + r.e });
    Some(match (quarter_turns as i64).rem_euclid(4) {
        0 => (s, c),
        1 => (c, s.neg()),
        2 => (s.neg(), c.neg()),
        _ => (c.neg(), s),
    })
}

/// Highest power of `s = r^2` summed in double-double in the Taylor series.
const TAYLOR_HEAD: usize = 5;

/// `(sin r, cos r)` at an exact double-double `r`, `|r| <= 0.8`.
fn sin_cos_reduced(r: Dd) -> Option<(BoundedDd, BoundedDd)> {
    if !(r.hi.abs() <= 0.8) {
        return None;
    }
    let rb = BoundedDd { v: r, e: 0.0 };
    let s = rb.mul(rb);
    let inv_fact = inv_factorials();
    let coef = |k: usize| {
        let c = inv_fact[k];
        let c = if (k / 2) % 2 == 1 { -c } else { c };
        BoundedDd { v: c, e: TABLE_ETA * (c.hi.abs() + c.lo.abs()) }
    };
    let sin_tail = taylor_tail(s.v.hi, 2 * TAYLOR_HEAD + 3)?;
    let cos_tail = taylor_tail(s.v.hi, 2 * TAYLOR_HEAD + 2)?;
    // Horner: S = c_1 + s (c_3 + ... + s (c_11 + s T_sin)), C likewise.
    let (mut sh, mut ch) = (sin_tail, cos_tail);
    for j in (0..=TAYLOR_HEAD).rev() {
        sh = sh.mul(s).add(coef(2 * j + 1));
        ch = ch.mul(s).add(coef(2 * j));
    }
    Some((rb.mul(sh), ch))
}

/// `T = sum_{i>=0} (-1)^i s^i / (k0 + 2i)!` times the sign `(-1)^{(k0-1)/2}`
/// or `(-1)^{k0/2}` that the Horner scheme above expects at the level past the
/// head (`s^{TAYLOR_HEAD+1}` carries `(-1)^{TAYLOR_HEAD+1}`), in f64 with its
/// bound: the rounding of `s` (`<= u + 8 u^2` relative) and two roundings per
/// step give `3.04 i u` relative per term (plus `u` for `1/k0!`), `u |partial|`
/// per addition, and the first neglected term (alternating, decreasing).
fn taylor_tail(s: f64, k0: usize) -> Option<BoundedDd> {
    let sign = if (TAYLOR_HEAD + 1) % 2 == 1 { -1.0 } else { 1.0 };
    let mut terms = [0.0f64; 16];
    let mut term = sign * inv_factorials()[k0].hi;
    let mut err = 0.0f64;
    for i in 0..terms.len() {
        let rel = U + 3.04 * i as f64 * U;
        if term.abs() * (1.0 + rel) <= TAYLOR_TARGET {
            // smallest first: each addition errs by at most u |partial sum|
            let mut sum = 0.0f64;
            for &t in terms[..i].iter().rev() {
                sum += t;
                err += U * sum.abs();
            }
            return Some(BoundedDd { v: Dd::from_f64(sum), e: err + term.abs() * (1.0 + rel) });
        }
        terms[i] = term;
        err += rel * term.abs();
        let k = (k0 + 2 * i) as f64;
        term = -term * s / ((k + 1.0) * (k + 2.0));
    }
    None
}

#[cfg(test)]
mod tests {
    use super::*;
    use rug::Float;

    fn to_float(d: Dd) -> Float {
        Float::with_val(300, d.hi) + Float::with_val(300, d.lo)
    }

    fn encloses(b: BoundedDd, exact: &Float) -> bool {
        Float::with_val(300, to_float(b.v) - exact).abs() <= b.e
    }

    #[test]
    fn constants_are_within_their_bounds() {
        let pi = Float::with_val(300, rug::float::Constant::Pi);
        assert!(encloses(PI_4, &Float::with_val(300, &pi / 4u32)));
        assert!(encloses(TWO_OVER_PI, &Float::with_val(300, 2u32 / &pi)));
    }

    #[test]
    fn sin_cos_enclose() {
        for &r in &[0.0, 1e-20, -0.3, 0.7853981633974483, -0.8, 0.5] {
            let (s, c) = sin_cos_reduced(Dd { hi: r, lo: r * 1e-17 }).unwrap();
            let rf = to_float(Dd { hi: r, lo: r * 1e-17 });
            assert!(encloses(s, &Float::with_val(300, rf.sin_ref())), "sin {r}");
            assert!(encloses(c, &Float::with_val(300, rf.cos_ref())), "cos {r}");
            assert!(s.e < 5e-26 && c.e < 5e-26, "{r}: {} {}", s.e, c.e);
        }
    }

    #[test]
    fn j01_enclose_the_mp_values() {
        for &x in &[25.0, 25.5, 30.0, 47.123, 100.0, 150.0, 1e4 + 0.25, 7e8] {
            let (j0, j1) = bessel_j01(x).unwrap();
            for (n, b) in [(0i64, j0), (1, j1)] {
                let e = super::super::bessel_j_mp(n, &Float::with_val(53, x), 300).unwrap();
                assert!(encloses(b, e.mid()), "J_{n}({x}): {:?} vs {}", b, e.mid());
                assert!(b.e < if x < 30.0 { 3e-23 } else { 3e-25 }, "J_{n}({x}): bound {:e}", b.e);
            }
        }
        assert!(bessel_j01(24.9).is_none());
    }
}
