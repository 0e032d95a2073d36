//! `G(k, y)` in f64 for large `k (1 - y)` by the expansion of `S(y)` as an
//! expectation over a Beta law (issue 23, item 4): a few dozen terms where the
//! direct series needs `~40/(1-y)` and the near-one expansion cancels by `e^{k w}`.
//!
//! # Method
//!
//! `S(y) = sum_{n>=1} (k+1/2)_n y^n/((k+2)_n n) = E[-ln(1 - y t)]`, `t ~ Beta(k+1/2, 3/2)`,
//! since `E[t^n] = (k+1/2)_n/(k+2)_n` [DLMF 5.12.1 with 5.12.3] and `-ln(1 - z) = sum z^n/n`
//! (monotone convergence, `0 <= y t < 1`). With `t = 1 - sigma`, `sigma ~ Beta(3/2, k+1/2)`,
//! `E[sigma^j] = (3/2)_j/(k+2)_j`, and `w = 1 - y`: `1 - y t = w (1 + x sigma)`,
//! `x = y/w`, so `S = -ln w - A`, `A = E[ln(1 + x sigma)]`, and
//!
//! `B = -ln(y)/2 - S/2 + P_k/2 = (ln(w/y) + A + P_k)/2`, `P_k = psi(k+2) - psi(k+1/2)`.
//!
//! For `X >= 0`, `ln(1 + X) = sum_{j=1}^J (-1)^{j+1} X^j/j + R_J(X)`,
//! `R_J(X) = (-1)^J int_0^X s^J/(1+s) ds`, `|R_J(X)| <= X^{J+1}/(J+1)` (for every `X >= 0`,
//! also `X > 1`) [DLMF 4.6.1 and its integral remainder]. Taking expectations:
//!
//! `A = sum_{j=1}^J (-1)^{j+1} b_j/j + R`, `b_j = x^j (3/2)_j/(k+2)_j`,
//! `|R| <= b_{J+1}/(J+1)`,
//!
//! a rigorous bound at every `J`. The series diverges (`b_{j+1}/b_j = x (j+3/2)/(k+2+j)`
//! exceeds 1 for `j > ~k w/(1 - 2w)`), and its smallest term is about `e^{-k w}`
//! times a modest factor; so this route serves where `k w >~ 30`.
//!
//! **In f64.** `x~ = fl(y/w)` (`w` exact for `y >= 1/2`), `b_j = b_{j-1} fl(fl(x~ (2j+1))/(2k+2+2j))`:
//! with `x~`'s own rounding compounding, `b~_j = b_j (1 + theta)`, `|theta| <= gamma_{4j}`;
//! the terms `fl(b~_j/j)` `gamma_{4j+1}` [Higham, *Accuracy and Stability*, 3.1]. The
//! alternating sum is plain: its roundings are at most `u sum_m |s~_m|` over the partial
//! sums, accumulated in the loop. The remainder is bounded by the next term, inflated by
//! its `gamma`. `ln(w/y)` from [`super::elementary::ln_w_over_y_bounded`] (relative where
//! it vanishes at `y = 1/2`, so the zero of `G(k, .)` near `y = 1/2 + 3/(4k)` keeps its
//! digits down to `|B| ~ 1e-13 (A + P_k)`), `P_k` and `C_k` from the certified table.
//! The bracket: two roundings; the product `C_k B` as in [`super::native`].
//!
//! The sum stops when the next term is below `2^-57 |ln(w/y) + A + P_k|` (its running
//! estimate), or as soon as the terms grow (the bound is valid at any `J`; the caller
//! accepts the value only if the bound is `1e-14` relative).

use super::elementary::{ln_w_over_y_bounded, Val};
use crate::ball::Bounded;

const U: f64 = f64::EPSILON / 2.0;

/// Cap on the terms (the smallest term sits near `j ~ k w/y`; the route is tried
/// only for `k w <= ~500` terms' worth).
const MAX_TERMS: u32 = 2000;

/// Smallest `k (1 - y)` at which [`meijer_g_k_beta_series`] is tried: below, its
/// smallest term (about `e^{-k w}`) cannot reach `1e-14` of `G`.
pub const BETA_SERIES_MIN_KW: f64 = 28.0;

/// `G(k, y) = C_k B` by the Beta-expectation expansion (module docs), `1/2 <= y < 1`,
/// with `C_k`, `P_k` and their errors given. `None` outside that range.
pub(crate) fn meijer_g_k_beta_series(k: u32, y: f64, c: Val, p: Val) -> Option<Bounded> {
    if !(0.5..1.0).contains(&y) {
        return None;
    }
    let w = 1.0 - y; // exact (Sterbenz)
    let x = y / w;
    let l = ln_w_over_y_bounded(y)?;
    let kf = k as f64;
    let lp = l.v + p.v; // estimate of the bracket without A (for the stopping rule)
    let mut b = 1.0f64;
    let mut s = 0.0f64; // A's partial sum
    let mut abs_partials = 0.0f64; // sum of |s~_m|
    let mut weighted = 0.0f64; // sum (4m+1) |a~_m|
    let mut prev = f64::INFINITY;
    let mut j = 1u32;
    let remainder = loop {
        let jf = j as f64;
        b *= x * (2.0 * jf + 1.0) / (2.0 * kf + 2.0 + 2.0 * jf);
        let a = b / jf;
        // b_j bounds |R_{j-1}|: stop before adding it if it is small enough or grows
        let bound_next = a * (1.0 + 1.0001 * (4.0 * jf + 1.0) * U);
        if bound_next <= 6.9e-18 * (lp + s).abs() || a >= prev || j >= MAX_TERMS {
            break bound_next;
        }
        s = if j % 2 == 1 { s + a } else { s - a };
        abs_partials += s.abs();
        weighted += (4.0 * jf + 1.0) * a;
        prev = a;
        j += 1;
    };
    let e_a = remainder + 1.0001 * U * weighted + U * abs_partials;
    let t1 = l.v + s;
    let t2 = t1 + p.v;
    let bv = 0.5 * t2;
    let be = 0.5 * (l.e + e_a + p.e + U * t1.abs() + U * t2.abs());
    let g = c.v * bv;
    let e = (c.v.abs() * be + bv.abs() * c.e + c.e * be + U * g.abs()) * (1.0 + 1.0 / (1u64 << 30) as f64);
    (g.is_finite() && e.is_finite()).then(|| Bounded { value: g, err: e.next_up() })
}
