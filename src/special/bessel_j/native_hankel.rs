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
//! exact in binary for small `k` (`nu = 0`: 1, -1, 9/2, -75/2;
//! `nu = 1`: 1, 3, -15/2, 105/2).
//!
//! * **Head** `k <= 3` in double-double: `v` by one division, its powers by
//!   products, each `e_k v^k` by an exact-f64 scaling.
//! * **Tail** `k >= 4` in f64: `s_k = s_{k-1} (4nu^2 - (2k-1)^2) fl(v) fl(1/k)` from
//!   `fl(s_3)`, five roundings a step (`fl(v)` and the table `fl(1/k)` included), so
//!   `|fl(s_k) - s_k| <= (1 + 5.01 (k-3)) u |s_k|` (`k <= 200`), summed
//!   as they come (both `nu` in one loop) with `u |partial sum|` per addition. At `x >= 25`, `|s_4| <= 3.7e-7`,
//!   so the tail's f64 error is below `3e-22`.
//! * **Truncation** [DLMF 10.17.14 with 10.17.15, on the real axis, as in
//!   `hankel.rs`]: after `l` terms the remainder of the complex sum is at most
//!   `2 |a_l x^-l| exp(|nu^2 - 1/4|/x) <= 2.07 |s_l|` for `x >= 25`
//!   (`exp(0.75/25) < 1.031`), whatever the phase; `l` is the first index with
//!   `2.07 |s_l| (1 + 5.01 (l-3) u) <= 2^-80`, or where the terms start to grow
//!   (the least term is `2.2e-23` at `x = 25`, `9e-28` at `x = 30`).
//! * **Phase**: `w = r + q pi/2` with `q = round((x - pi/4)/(pi/2))` and
//!   `r = x - (2q+1) pi/4`, computed as `x - m * PI_4` in double-double from the
//!   double-double `PI_4` (`|PI_4 - pi/4| <= 7.5e-34`, checked against MPFR in the
//!   tests) with its error carried (`m <= 2^40`). `sin r`, `cos r` at the
//!   double-double value `r~` (`|r~| <= 0.8`): `r~ = j/128 + d` with
//!   `j = round(128 r~)`, `|d| <= 1/256` (`r~.hi - j/128` is exact by Sterbenz,
//!   then one exact two_sum), `sin(j/128)`, `cos(j/128)` from a table rounded
//!   from 256-bit MPFR values (`2 u^2` relative), and
//!   `sin d = d (1 + T_s(D))`, `cos d = 1 - D/2 + T_c(D)`, `D = d^2 <= 1.53e-5`,
//!   with the short alternating series `T_s = sum_{i=1..3} (-1)^i D^i/(2i+1)!`,
//!   `T_c = sum_{i=2..4} (-1)^i D^i/(2i)!` by Horner in f64 (`|d T_s| <= 1e-8`,
//!   `|T_c| <= 1e-11`, so their f64 errors, `16 u sum |c_i| D^i` from Higham's
//!   `gamma_{2m}` plus the roundings of the coefficients and of `D`, are below
//!   `2e-23`; the first neglected term bounds the truncation). Then
//!   `sin r = S_j cos d + C_j sin d`, `cos r = C_j cos d - S_j sin d`. The error
//!   of `r~` adds `|r - r~|` to both (`|sin'|, |cos'| <= 1`).
//! * `A = sqrt(2/(pi x))` from the double-double `2/pi` (`|error| <= 2.2e-33`).
//!
//! Every double-double step carries its bound by the model of
//! `crate::ball::dd_bounded`. The heads are as short as keeps the errors of
//! `J_0`, `J_1` near `1e-22` (the least term `2.2e-23` at `x = 25`, the f64 tails
//! above): against `|J_n| ~ 0.1` that is `2^-60` relative, far below the
//! `2^-53` the callers need.

use crate::ball::{two_sum, BoundedDd, Dd, ExactProduct, U, U2};

/// Smallest `x` of this path: below it the least term of the expansion (about
/// `e^{-2x}`) stops being small enough, and the power series is used instead.
pub(crate) const HANKEL_MIN_X: f64 = 25.0;
/// Largest `x` (the phase multiple `m` stays exact and the reduction error small).
pub(crate) const HANKEL_MAX_X: f64 = (1u64 << 40) as f64;
/// `2 exp(0.75/x)` for `x >= HANKEL_MIN_X`, rounded up.
const REMAINDER_FACTOR: f64 = 2.07;
/// Truncation target of the expansion, `2^-80`.
const HANKEL_TARGET: f64 = 8.271806125530277e-25;
/// Most terms before giving up (not reached for `x >= 25`).
const MAX_TERMS: usize = 200;

/// `pi/4` as a double-double with its error bound (MPFR: `7.49e-34`).
const PI_4: BoundedDd = BoundedDd { v: Dd { hi: std::f64::consts::FRAC_PI_4, lo: 3.061616997868383e-17 }, e: 7.5e-34 };
/// `2/pi` as a double-double with its error bound (MPFR: `2.14e-33`).
const TWO_OVER_PI: BoundedDd = BoundedDd { v: Dd { hi: std::f64::consts::FRAC_2_PI, lo: -3.935735335036497e-17 }, e: 2.2e-33 };

/// Highest `k` of the double-double head.
const HEAD: usize = 3;
/// `e_k(nu) = 8^k a_k(nu)`, `k = 0..=HEAD`, exact.
const E0: [f64; HEAD + 1] = [1.0, -1.0, 4.5, -37.5];
const E1: [f64; HEAD + 1] = [1.0, 3.0, -7.5, 52.5];

/// Tables built once from 256-bit MPFR values.
struct Tables {
    /// `(sin(j/128), cos(j/128))` for `j = -SINCOS_J..=SINCOS_J`, relative error `<= 2 u^2`.
    sincos: Vec<(BoundedDd, BoundedDd)>,
    /// `fl(1/k)`, `k < MAX_TERMS` (index 0 unused).
    inv: Vec<f64>,
}

/// Spacing of the sine/cosine table, `1/SINCOS_SCALE`.
const SINCOS_SCALE: f64 = 128.0;
/// The sine/cosine table covers `|r| <= (SINCOS_J + 1/2)/128`.
const SINCOS_J: i64 = 103;

fn tables() -> &'static Tables {
    static TABLES: std::sync::OnceLock<Tables> = std::sync::OnceLock::new();
    TABLES.get_or_init(|| {
        let dd = |f: &rug::Float| {
            let hi = f.to_f64();
            let lo = rug::Float::with_val(256, f - hi).to_f64();
            BoundedDd { v: Dd { hi, lo }, e: 2.0 * U2 * (hi.abs() + lo.abs()) }
        };
        let sincos = (-SINCOS_J..=SINCOS_J)
            .map(|j| {
                let r = rug::Float::with_val(256, j) / SINCOS_SCALE as u32;
                (dd(&rug::Float::with_val(256, r.sin_ref())), dd(&rug::Float::with_val(256, r.cos_ref())))
            })
            .collect();
        let inv = (0..MAX_TERMS).map(|k| if k == 0 { 0.0 } else { 1.0 / k as f64 }).collect();
        Tables { sincos, inv }
    })
}

/// `(J_0(x), J_1(x))` with proven bounds, `HANKEL_MIN_X <= x <= HANKEL_MAX_X`.
#[inline(always)]
pub(crate) fn bessel_j01<P: ExactProduct>(x: f64) -> Option<(BoundedDd, BoundedDd)> {
    if !(HANKEL_MIN_X..=HANKEL_MAX_X).contains(&x) {
        return None;
    }
    let t = tables();
    let v = BoundedDd::ONE.div_f64_p::<P>(8.0 * x);
    let v2 = v.mul_p::<P>(v);
    let v3 = v2.mul_p::<P>(v);
    let [(p0, q0), (p1, q1)] = hankel_pq01::<P>(t, [v, v2, v3])?;
    let (sin_w, cos_w) = sin_cos_phase::<P>(t, x)?;
    let amp = TWO_OVER_PI.div_f64_p::<P>(x).sqrt_p::<P>()?;
    let j0 = amp.mul_p::<P>(p0.mul_p::<P>(cos_w).sub(q0.mul_p::<P>(sin_w)));
    let j1 = amp.mul_p::<P>(p1.mul_p::<P>(sin_w).add(q1.mul_p::<P>(cos_w)));
    Some((j0, j1))
}

/// `P_nu`, `Q_nu` for `nu = 0, 1` with their bounds from `v = 1/(8x)` and its
/// powers; the truncation remainder is added to both (it bounds the complex
/// remainder). The two f64 tails run in one loop (independent chains), each
/// stopping on its own, and are summed as they come with `u |partial sum|`
/// per addition (recursive summation, valid in any order).
#[inline(always)]
fn hankel_pq01<P: ExactProduct>(t: &Tables, [v, v2, v3]: [BoundedDd; 3]) -> Option<[(BoundedDd, BoundedDd); 2]> {
    const FOUR_NU2: [f64; 2] = [0.0, 4.0];
    let heads = [&E0, &E1].map(|e| {
        let p = BoundedDd::ONE.add(v2.mul_f64_p::<P>(-e[2]));
        let s_head = v3.mul_f64_p::<P>(-e[3]);
        (p, v.mul_f64_p::<P>(e[1]).add(s_head), s_head.v.hi)
    });
    let vf = v.v.hi;
    // s_3 = e_3 v^3 (the head's last term, sign restored), then the f64 tail from k = HEAD + 1.
    let mut s = [-heads[0].2, -heads[1].2];
    let (mut tail_p, mut tail_q, mut err) = ([0.0f64; 2], [0.0f64; 2], [0.0f64; 2]);
    let mut remainder: [Option<f64>; 2] = [None, None];
    let mut k = HEAD + 1;
    while remainder[0].is_none() || remainder[1].is_none() {
        let odd = (2 * k - 1) as f64;
        let rel = U + 5.01 * (k - HEAD) as f64 * U;
        for nu in 0..2 {
            if remainder[nu].is_some() {
                continue;
            }
            let s_prev = s[nu];
            s[nu] = s[nu] * (FOUR_NU2[nu] - odd * odd) * vf * t.inv[k];
            let bound = REMAINDER_FACTOR * s[nu].abs() * (1.0 + rel);
            // The bound holds for every l: stop at the target or where the terms
            // turn to grow (the least term, about 2e-23 at x = 25).
            if bound <= HANKEL_TARGET || s[nu].abs() >= s_prev.abs() {
                remainder[nu] = Some(bound);
                continue;
            }
            if k >= MAX_TERMS - 1 || !s[nu].is_finite() {
                return None;
            }
            err[nu] += rel * s[nu].abs();
            let term = if (k / 2) % 2 == 1 { -s[nu] } else { s[nu] };
            if k % 2 == 0 {
                tail_p[nu] += term;
                err[nu] += U * tail_p[nu].abs();
            } else {
                tail_q[nu] += term;
                err[nu] += U * tail_q[nu].abs();
            }
        }
        k += 1;
    }
    let out = |nu: usize| {
        let e = err[nu] + remainder[nu].unwrap_or(f64::INFINITY);
        let (p, q, _) = heads[nu];
        (p.add(BoundedDd { v: Dd::from_f64(tail_p[nu]), e }), q.add(BoundedDd { v: Dd::from_f64(tail_q[nu]), e }))
    };
    Some([out(0), out(1)])
}

/// `(sin w, cos w)`, `w = x - pi/4`, with proven bounds (module docs).
#[inline(always)]
fn sin_cos_phase<P: ExactProduct>(t: &Tables, x: f64) -> Option<(BoundedDd, BoundedDd)> {
    let quarter_turns = ((x - PI_4.v.hi) / (2.0 * PI_4.v.hi)).round();
    let m = 2.0 * quarter_turns + 1.0; // exact: x <= 2^40
    let r = BoundedDd::exact(x).sub(PI_4.mul_f64_p::<P>(m));
    let (s, c) = sin_cos_reduced::<P>(t, r.v)?;
    let (s, c) = (BoundedDd { v: s.v, e: s.e + r.e }, BoundedDd { v: c.v, e: c.e + r.e });
    Some(match (quarter_turns as i64).rem_euclid(4) {
        0 => (s, c),
        1 => (c, s.neg()),
        2 => (s.neg(), c.neg()),
        _ => (c.neg(), s),
    })
}

/// `(sin r, cos r)` at an exact double-double `r`, `|r| <= 0.8`: the table
/// at `j/128` nearest to `r` and `sin d`, `cos d` for `d = r - j/128`,
/// `|d| <= 1/256` (module docs).
#[inline(always)]
fn sin_cos_reduced<P: ExactProduct>(t: &Tables, r: Dd) -> Option<(BoundedDd, BoundedDd)> {
    if !(r.hi.abs() <= 0.8) {
        return None;
    }
    let j = (r.hi * SINCOS_SCALE).round();
    let r0 = j / SINCOS_SCALE;
    // r.hi - r0 is exact (Sterbenz: r.hi and r0 within a factor 3/2, or r0 = 0).
    let (dh, dl) = two_sum(r.hi - r0, r.lo);
    let d = BoundedDd { v: Dd { hi: dh, lo: dl }, e: 0.0 };
    let dsq = d.mul_p::<P>(d);
    let big_d = dsq.v.hi; // |big_d - d^2| <= (u + 9 u^2) d^2
    if !(big_d <= SINCOS_D2_MAX) {
        return None;
    }
    // sin d = d (1 + T_s), T_s = sum_{i=1}^{3} (-1)^i D^i/(2i+1)!;
    // cos d = 1 - D/2 + T_c, T_c = sum_{i=2}^{4} (-1)^i D^i/(2i)!.
    let t_s = small_poly(big_d, &SIN_COEF);
    let t_c = small_poly(big_d, &COS_COEF);
    let sin_d = d.add(d.mul_p::<P>(t_s));
    let cos_d = BoundedDd::ONE.sub(dsq.mul_f64_p::<P>(0.5)).add(t_c);
    let (s0, c0) = t.sincos[(j as i64 + SINCOS_J) as usize];
    Some((s0.mul_p::<P>(cos_d).add(c0.mul_p::<P>(sin_d)), c0.mul_p::<P>(cos_d).sub(s0.mul_p::<P>(sin_d))))
}

/// Largest `d^2` the short polynomials cover: `(1/256 + 2^-40)^2`, rounded up.
const SINCOS_D2_MAX: f64 = 1.5259e-5;
/// Coefficients of `T_s` in `D` (`D^1..D^3`) and `T_c` (`D^2..D^4`), as f64
/// (each within `u` relative of `(-1)^i/(2i+1)!`, `(-1)^i/(2i)!`).
const SIN_COEF: [f64; 4] = [0.0, -1.0 / 6.0, 1.0 / 120.0, -1.0 / 5040.0];
const COS_COEF: [f64; 5] = [0.0, 0.0, 1.0 / 24.0, -1.0 / 720.0, 1.0 / 40320.0];

/// `sum_i c_i D^i` (`0 <= D <= SINCOS_D2_MAX`) by Horner in f64 with its bound:
/// Horner's `gamma_{2m} sum |c_i| D^i` [Higham, Accuracy and Stability, (5.3)],
/// `u` for the rounded coefficients, `m u` for the rounding of `D` (derivative
/// bound), so `16 u sum |c_i| D^i` for `m <= 5`; plus the truncation: the
/// series alternate with terms falling by `D/((2m+2)(2m+3)) < 1e-5`, so the
/// first neglected term, `|c_m| D^m D / 30`, bounds it.
fn small_poly(big_d: f64, c: &[f64]) -> BoundedDd {
    let (mut p, mut a) = (0.0f64, 0.0f64);
    for &ci in c.iter().rev() {
        p = p * big_d + ci;
        a = a * big_d + ci.abs();
    }
    let m = c.len() - 1;
    let last = c[m].abs() * big_d.powi(m as i32);
    let e = 16.0 * U * a * 1.001 + last * big_d / 30.0;
    BoundedDd { v: Dd::from_f64(p), e }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ball::Dekker;
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
        for &r in &[0.0, 1e-20, -0.3, std::f64::consts::FRAC_PI_4, -0.8, 0.5] {
            let (s, c) = sin_cos_reduced::<Dekker>(tables(), Dd { hi: r, lo: r * 1e-17 }).unwrap();
            let rf = to_float(Dd { hi: r, lo: r * 1e-17 });
            assert!(encloses(s, &Float::with_val(300, rf.sin_ref())), "sin {r}");
            assert!(encloses(c, &Float::with_val(300, rf.cos_ref())), "cos {r}");
            assert!(s.e < 5e-23 && c.e < 5e-23, "{r}: {} {}", s.e, c.e);
        }
    }

    #[test]
    fn j01_enclose_the_mp_values() {
        for &x in &[25.0, 25.5, 30.0, 47.123, 100.0, 150.0, 1e4 + 0.25, 7e8] {
            let (j0, j1) = bessel_j01::<Dekker>(x).unwrap();
            for (n, b) in [(0i64, j0), (1, j1)] {
                let e = super::super::bessel_j_mp(n, &Float::with_val(53, x), 300).unwrap();
                assert!(encloses(b, e.mid()), "J_{n}({x}): {:?} vs {}", b, e.mid());
                assert!(b.e < if x < 30.0 { 1e-21 } else { 3e-22 }, "J_{n}({x}): bound {:e}", b.e);
            }
        }
        assert!(bessel_j01::<Dekker>(24.9).is_none());
    }
}
