//! `u_wave` / `du_wave` and `u_wave_bounded` / `du_wave_bounded` **from
//! scratch**: one compensated Miller recurrence with the sums of the Bessel
//! form accumulated in the same loop, compiled twice from one generic loop:
//! as a value ([`wave_value`], an **estimate**, enforced by `tests/wave_value.rs`:
//! at most `1e-15` of `max(|u_w|, |A|)`, and of `max(|du_w/dx|, 2 pi |A|/zeta)`)
//! and with a **proven bound** ([`wave_scratch_bounded`]: the running error
//! bound below runs alongside; tests/wave_bounded.rs and the unit test here
//! check it against the certified MP values). The bounded pass forms one result
//! per call: for `u_w` it skips the gradient's `V_i`, `S` and the chain's
//! `sum n^2 e_{2n}`, for `du_w/dx` the Horner sum `U` and the `u_w` assembly
//! (each result's bound below uses only its own inputs); that saves about a
//! fifth of the instructions of the pass that formed both.
//!
//! # Method
//!
//! Notation of [`super`]: `D = 2 pi a/zeta`, `t = sqrt((x-a)/(x+a))`,
//! `q = (1-t)^2 (x+a)/(2a)`, `X = q^2`, `Y = -X`, `acosh(x/a) = -ln q`
//! (the geometry as bounded double-doubles, as on the per-contact path).
//!
//! * **Miller's recurrence** [DLMF 10.6.1, 10.74(iv)]: `p_{M+1} = 0`, `p_M = 1`,
//!   `p_{k-1} = (2k/D) p_k - p_{k+1}` down to `k = 1`, `M = 2 top`, `top = N + 1`,
//!   `N` the truncation of the certified path (both Bessel tails below `2^-64`)
//!   from a table over `D` in steps of 1/4 (computed at each bucket's upper end:
//!   the tails grow with `D`). Then `p_k = Lambda P_k` with
//!   `Lambda = p_0 + 2 sum_{m=1}^{top} p_{2m}`, and `P_k` is `J_k(D)` up to
//!   Miller's start error (below) [DLMF 10.12.4: `J_0 + 2 sum J_{2n} = 1`].
//! * **Compensation.** Each `p_k` is carried as `h_k + l_k`: `h_{k-1} = fl(c h_k - h_{k+1})`
//!   (one fused multiply-add, the only operation on the dependency chain),
//!   `c + cl = 2k (1/D)` (`1/D` in double-double), the step's rounding error
//!   `c h_k - h_{k+1} - h_{k-1} = (c h_k - s) - rho` with `s + rho = h_{k+1} + h_{k-1}`
//!   (two_sum), `r = fl(c h_k - s)` (fused), and
//!   `l_{k-1} = fl(c l_k + fl(fl(cl h_k + fl(r - rho)) - l_{k+1}))`: the low parts run
//!   through the same linear recurrence driven by the local rounding errors.
//! * **The sums in the same loop**, at each even order `2m` as it appears
//!   (no coefficient table, no second pass): `Lambda` (two_sum, low parts in
//!   f64), `V_{m-1} = m p_{2m} - V_m` (compensated; `V_i = (-1)^i T_i`,
//!   `T_i = sum_{n>i} (-1)^{n+1} n p_{2n}`), and by compensated Horner in
//!   `Y = -X` (Graillat-Langlois-Louvet, with the double-double `Y`)
//!   `U = sum_{m>=1} p_{2m} Y^{m-1}` and `S = sum_{i>=0} V_i Y^i`. The Horner
//!   sums start at the order `n_x` with `|X|^{n_x} (top+1)^2 <= 2^-64` (from
//!   `-ln |X| >= 2 (acosh - 10^-15)`, the margin covering the rounding of
//!   `X` and of `acosh`; for the gradient alone, which needs no `acosh`, from
//!   an upper bound of `|X|` through the tangent bound `ln_upper` of `ln`;
//!   `n_x = top` near `x = a`).
//! * **Assembly** (bounded double-doubles, `crate::ball::dd_bounded`):
//!   `u_w = A [1 + (-p_0 + D p_1 acosh + 2 X U)/Lambda]`,
//!   `du_w/dx = (8A/a) q S/Lambda` ([`super`]: `(1 - t)(1 + q) = 2q`).
//!
//! # Error bound (the bounded path)
//!
//! `u = 2^-53`; `a_j = |h_j|`, `b_j = |l_j|`; `p~_j = h_j + l_j` the computed
//! value (exact sum of its two parts); `p_j` the exact Miller solution from the
//! same start with the exact multipliers `c_k = 2k/D` (`D` the exact `2 pi a/zeta`
//! of the f64 inputs).
//!
//! 1. **Multipliers.** `D~` (bounded double-double, error `e_D`); `1/D~` by
//!    `recip`: `r0 = fl(1/b.hi)`, `1 - b.hi r0` exact by one fused multiply-add,
//!    then two roundings of size `u^2` and `r0 e` rounded: relative error
//!    `<= (3.1 + 2.1 + 4.1) u^2 <= 9.4 u^2` (the last from `1/(1-eps) - 1 - eps`,
//!    `|eps| <= 2.02 u`). `c = fl(kk i_h)` (`kk = 2k`, an exact integer),
//!    `cl = fl(fl(kk i_h - c) + fl(kk i_l))` (the first term exact): `|cl| <= 2.0001 u c`
//!    and `|c + cl - kk (i_h + i_l)| <= 3.0003 u^2 c`. Together
//!    `|c + cl - c_k| <= rho_c c_k`, `rho_c = e_D/(|D~| - e_D) + 13 u^2`.
//! 2. **Local error of a step.** Let `delta_k = p~_{k-1} - (c_k p~_k - p~_{k+1})`.
//!    With `eps_h = c h_k - h_{k+1} - h_{k-1}` (`|eps_h| <= u a_{k-1}`) and
//!    `s + rho = h_{k+1} + h_{k-1}` (`|rho| <= u |s|`), `c h_k - s = eps_h + rho`,
//!    so `|c h_k - s| <= u (2.0001 a_{k-1} + 1.0001 a_{k+1})`. The ideal low part
//!    is `(c h_k - s) - rho + c l_k + cl h_k + cl l_k - l_{k+1}`; the computed one
//!    differs by the rounding of `r`, of `d1 = fl(r - rho)`, `d3 = fl(cl h_k + d1)`,
//!    `d2 = fl(d3 - l_{k+1})`, `l_{k-1} = fl(c l_k + d2)` (each `<= u` times
//!    its result), and the dropped `cl l_k`. Summing,
//!    `|rounding| <= u^2 (11.004 a_{k-1} + 7.003 a_{k+1} + 4.001 c a_k) + u (1.0001 b_{k+1} + b_{k-1}) + 2.0001 u c b_k`,
//!    and the multiplier adds `1.001 c rho_c (a_k + b_k)`. The step's own
//!    identities remove the `k+1` terms: `h_{k+1} = c h_k - h_{k-1} - eps_h`
//!    gives `a_{k+1} <= c a_k + 1.0001 a_{k-1}`, and `l_{k+1} = d3 - d2 (1+theta)^-1`,
//!    `d2 = l_{k-1} (1+theta')^-1 - c l_k` give
//!    `b_{k+1} <= 1.0003 b_{k-1} + 1.0001 c b_k + u (4.002 c a_k + 5.004 a_{k-1})`. Hence
//!    `|delta_k| <= u^2 (23.013 a_{k-1} + 15.007 c a_k) + u (2.0004 b_{k-1} + 3.0003 c b_k) + 1.001 c rho_c (a_k + b_k)
//!    <= mu (z_{k-1} + c z_k)`, with `mu = 23.07 u^2 + 1.001 rho_c`,
//!    `z_j = a_j + kappa b_j`, `kappa = (3.11 u + 1.001 rho_c)/mu`.
//! 3. **Propagation.** `E_k = |p~_k - p_k|` obeys
//!    `E_{k-1} <= c_k E_k + E_{k+1} + mu (z_{k-1} + c z_k)`, `E_M = E_{M+1} = 0`
//!    (the start is exact). The loop runs this triangle-inequality chain in
//!    units of `mu`, `e_{k-1} = fl(c e_k + fl(e_{k+1} + fl(c z_k + z_{k-1})))`
//!    (one fused multiply-add on its latency path), from the computed `z`.
//!    Its growth, like `e^{0.47 D}` below the turning point and like the
//!    dominant solution above it, is harmless while `u^2 e^{0.47 D}` stays far
//!    below `u` (the measured bounds below). Each step
//!    rounds at most 7 times relative to `c_k` (`c` itself within `1.01 u`), and
//!    the sums below add `3 top` more, so the computed chain times
//!    `1 + 2^-40` bounds the exact one (`M <= 160`).
//!    The sums of the loop weight it: `E_0`, `E_1`, `sum_{m>=1} E_{2m}`
//!    (for `Lambda`, and for `U` with `|Y|^{m-1} <= 1.01`) and
//!    `sum_n n^2 E_{2n} = sum_i sum_{n>i} n E_{2n}` (for `S`).
//! 4. **Miller's start** (Nicholson). `p_k = K (J_k - nu Y_k)`, `nu = J_{M+1}/Y_{M+1}`,
//!    so `P_k - J_k = (-nu Y_k + J_k (tau' + nu L_Y))/(1 - tau' - nu L_Y)` with
//!    `tau' = 2 sum_{m>top} J_{2m}`, `L_Y = Y_0 + 2 sum_{m=1}^{top} Y_{2m}`.
//!    `J_nu^2 + Y_nu^2 = (8/pi^2) int_0^inf K_0(2D sinh t) cosh(2 nu t) dt`
//!    [DLMF 10.9.30] grows with the order, so `|Y_k| <= M_k <= M_{M+1}` for
//!    `k <= M + 1`; the Wronskian [DLMF 10.5.2] gives
//!    `M_{M+1} >= 2/(pi D (|J_M| + |J_{M+1}|))`, and with `|J_n| <= j_n = (D/2)^n/n!`
//!    [DLMF 10.14.4], `j_M <= 2^-64`, `|J_{M+1}|/M_{M+1} < 2^-120`, so
//!    `|Y_{M+1}| >= M_{M+1} (1 - 2^-240)`. Hence `|nu Y_k| <= j_{M+1} (1 + 2^-239)`,
//!    `|nu L_Y| <= (M + 1) j_{M+1} (1 + 2^-239)`, `tau' <= 4 j_{M+2}` (consecutive
//!    even terms shrink by at least 1/2, checked), and with `|J_k| <= 1`
//!    [DLMF 10.14.1], `|P_k - J_k| <= eps_M = ((M + 2) j_{M+1} + 4 j_{M+2}) (1 + 2^-40)`,
//!    tabulated per bucket at its upper end (`j_n` grows with `D`). In `u_w`
//!    it weighs `1 + D acosh + 2 top` (the `X^n <= 1`), in `q S` at most
//!    `sum_{n<=top} n^2 <= top^3`; the orders beyond `2 top` add `2 tail0 <= 2^-63`
//!    and `tail2 <= 2^-64` (`0 <= q, geo_n/2n <= 1`).
//! 5. **The sums' own rounding**, with `SA = sum_{m>=1} a_{2m} <= Z` and
//!    `SB = sum_{m>=1} b_{2m} <= Z/kappa`, `Z = sum_{m>=1} z_{2m}` (summed in
//!    the loop, times `1 + 2^-40`):
//!    * `Lambda`: `lam_h + lam_l` after exact two_sums, two roundings a step on
//!      the low part, `|lam_h| <= 1.01 SA`: `<= u top (5 u top SA + 3 SB)`;
//!    * `V_i`: three roundings a step on `vl` (`|pm_e| <= u m a`, `|e| <= u |s|`,
//!      `|vh| <= 1.01 top (SA + SB)`, `|vl| <= 1.02 (top SB + 3.1 u top^2 SA)`):
//!      `<= u top (2.1 SB + 9.4 u top SA)` per coefficient, in `S` (`|Y|^i <= 1.01`)
//!      `<= u top^3 (2.1 SB + 9.4 u top SA)`;
//!    * compensated Horner (Higham Lemma 3.1): a step errs by
//!      `<= gamma_4 (|pi| + |sigma| + |h yl| + |l yh| + |cl|) + |l yl|`, `|yh| <= 1`,
//!      `|yl| <= u`, `|h| <= 1.01 sum |c_h|`, and `|l| <= 3.1 top u sum |c_h| + 1.01 sum |c_l| + err`
//!      (the `h` chain is plain Horner in `yh`): `err <= u top (28.5 u top sum |c_h| + 9.3 sum |c_l|)`.
//!      For `U` (`sum |c_h| <= SA`, `sum |c_l| <= SB`) that is charged
//!      `u top (29 u top SA + 10 SB)`; for `S` (`sum |vh| <= 1.01 top^2 (SA + SB)`,
//!      `sum |vl| <= top max |vl|`) together with the `V_i` part,
//!      `u top^3 (70 u top SA + 13 SB)`;
//!    * the Horner terms beyond `n_x`: `|X|^{n_x} <= 2^-64/(top+1)^2`, so
//!      `<= 2^-64 1.01 (SA + SB)/(top+1)^2` in `U` and `<= 2^-64 1.01 (SA + SB)` in `S`;
//!    * the argument `Y~ = -X~` instead of `-X` (`|X~ - X| <= e_X`):
//!      `<= e_X top 1.02 (SA + SB)` in `U`, `e_X top^3 1.02 (SA + SB)` in `S`.
//! 6. **Assembly.** `p~_0`, `p~_1`, `Lambda~`, `U`, `S` enter as bounded
//!    double-doubles with the errors of 3 and 5; the operations follow the
//!    error model of `crate::ball::dd_bounded` (quotients by `div_p` of
//!    [`super::kernels`]); `Lambda` cancels between numerator and
//!    denominator, so the quotients bound `|B(p~)/Lambda(p~) - B(P)|` for the
//!    exact Miller `P`, and 4 moves `P` to `J`. `finish` adds the final
//!    rounding and inflates the bound for its own f64 evaluation.
//!
//! Measured (tests/wave_scratch.rs, 1125 points of the model domain with its
//! edges; the unit test below): the bound is at most `1.18e-16` of the scales
//! (the error itself at most `1.05e-16`). It grows like the chain's `e^{0.47 D}`
//! beyond: `3.8e-16` at `D = 37.7`, `1.3e-14` at `D = 41.9`, `5e-12` at `D = 54`,
//! `8e-9` at `D = 63`; the caller (`wave_f64.rs`) takes the per-contact certified
//! path wherever the bound exceeds `2^-50` of the scales (`D` beyond about 40).
//! The compensation of the recurrence is what keeps the bound this small: an
//! uncompensated f64 recurrence could not be proven better than `2.7e-14` (u)
//! and `2.3e-14` (du) of the scales on the model domain even with its exact
//! Green's functions (`reference/wave_plain_miller_bound.py`; the orders above
//! `1.5 D` contribute below `1e-17`; docs/performance.md, "the floor of a proven bound").
//!
//! Where it does not apply (no fused multiply-add, `x/a > 25/7`, `D` beyond
//! the table) both paths return `None` and the callers use the previous routes.
//! References: DLMF 10.5.2, 10.6.1, 10.9.30, 10.12.4, 10.14.1, 10.14.4, 10.74(iv);
//! Higham, *Accuracy and Stability of Numerical Algorithms* (2002), Lemma 3.1;
//! Graillat, Langlois, Louvet (2009); Joldes, Muller, Popescu (2017).

use super::certified::bessel_tails;
use super::kernels::{div_p, has_fma, ln_upper, neg_ln, pow_int};
use super::{T_MAX, TWO_PI_ERR};
use crate::ball::{two_sum, Bounded, BoundedDd, Dd, Fused, U};

/// The table of `N(D)` covers `D <= D_MAX_TABLE` in steps of `1/D_STEPS`.
const D_STEPS: f64 = 4.0;
const D_MAX_TABLE: f64 = 64.0;

/// The largest `top = N + 1` of the table (`N = 63` at `D = 64`), with room.
const MAX_TOP: usize = 80;

/// `2^-64`: both Bessel tails of the table's `N` are below it ([`bessel_tails`]).
const TAIL: f64 = 5.421_010_862_427_522e-20;

/// `64 ln 2`, rounded up.
const LN2_64_UP: f64 = 44.361_419_555_836_51;

/// Covers the roundings of the f64 bound chains (at most `6 M <= 1600` of
/// them, each `<= u`, in a product: `(1 - u)^1600 >= 1 - 2^-42`).
const CHAIN_INFLATION: f64 = 1.0 + 1.0 / (1u64 << 40) as f64;

/// One bucket `D in ((i-1)/4, i/4]` of the table: the truncation `N` of the
/// certified path at `D = i/4` (the tails grow with `D`, so it serves the
/// whole interval) and the bound `eps_M` of Miller's start error at the same
/// `D` (method block, "Miller's start").
#[derive(Clone, Copy)]
struct Bucket {
    n: u16,
    /// The bucket's upper end `D_hi` (slightly above `i/4`).
    d_hi: f64,
    /// `eps_M`, `tail0`, `tail2` at `D_hi`.
    miller: f64,
    tail0: f64,
    tail2: f64,
}

fn table() -> &'static [Bucket] {
    static TABLE: std::sync::OnceLock<Vec<Bucket>> = std::sync::OnceLock::new();
    TABLE.get_or_init(|| {
        let len = (D_MAX_TABLE * D_STEPS) as usize + 1;
        (0..len)
            .map(|i| {
                let half_d = i as f64 / D_STEPS * 0.5 * (1.0 + 1e-12);
                let inf = f64::INFINITY;
                let Some((n, tail0, tail2)) = bessel_tails(half_d, 400) else {
                    return Bucket { n: u16::MAX, d_hi: 2.0 * half_d, miller: inf, tail0: inf, tail2: inf };
                };
                // N = 0 (D <= 1/4) runs with N = 1: its tails are the smaller ones of N = 0
                let n = n.max(1);
                Bucket { n: n as u16, d_hi: 2.0 * half_d, miller: miller_start_bound(half_d, 2 * (n + 1)), tail0, tail2 }
            })
            .collect()
    })
}

/// `eps_M >= |J_k(D) - P_k|` for every `k <= M`, `P` Miller's normalised
/// sequence started at `p_{M+1} = 0`, `p_M = 1` in exact arithmetic, for every
/// `D <= 2 half_d` (method block): `((M + 2) j + tau) (1 + 2^-40)` with
/// `j = h^{M+1}/(M+1)! >= |J_{M+1}|` and `tau = 4 h^{M+2}/(M+2)! >= 2 sum_{2n > M} |J_{2n}|`
/// (`h = D/2`; the ratio of consecutive even terms is checked below 1/2).
/// Infinite where the premises fail.
fn miller_start_bound(half_d: f64, m: usize) -> f64 {
    let mut t = 1.0f64; // h^k/k!, rounded up
    let mut terms = [0.0f64; 2];
    for k in 1..=m + 2 {
        t = t * half_d / k as f64 * (1.0 + 4.0 * U);
        if k > m {
            terms[k - m - 1] = t;
        }
    }
    let ratio = half_d * half_d / ((m + 3) * (m + 4)) as f64;
    if !(ratio <= 0.5 && t <= TAIL) {
        return f64::INFINITY;
    }
    let (j, tau) = (terms[0], 4.0 * terms[1]);
    (((m + 2) as f64 * j + tau) * CHAIN_INFLATION).next_up()
}

/// `(u_w(x), du_w/dx)` by the fast value path (module docs), or `None` where
/// it does not apply. The inputs are validated by the caller (finite,
/// `a, zeta > 0`, `x >= a`).
pub(crate) fn wave_value(a: f64, zeta: f64, amp: f64, x: f64) -> Option<(f64, f64)> {
    #[cfg(target_arch = "x86_64")]
    if has_fma() {
        // SAFETY: the CPU supports FMA (checked just above).
        return unsafe { wave_value_fma(a, zeta, amp, x) };
    }
    let _ = (a, zeta, amp, x);
    None
}

/// `u_w(x)` (`DU = false`) or `du_w/dx` (`DU = true`) with a proven bound by
/// the same single pass (module docs, "Error bound"), which forms only the sums
/// that result needs; `None` where it does not apply (no FMA, `x/a > 25/7`,
/// `D` beyond the table, a non-finite intermediate).
pub(crate) fn wave_scratch_bounded<const DU: bool>(a: f64, zeta: f64, amp: f64, x: f64) -> Option<Bounded> {
    #[cfg(target_arch = "x86_64")]
    if has_fma() {
        // SAFETY: the CPU supports FMA (checked just above).
        return unsafe { wave_bounded_fma::<DU>(a, zeta, amp, x) };
    }
    let _ = (a, zeta, amp, x);
    None
}

#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "fma")]
unsafe fn wave_value_fma(a: f64, zeta: f64, amp: f64, x: f64) -> Option<(f64, f64)> {
    wave_value_with(a, zeta, amp, x)
}

#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "fma")]
unsafe fn wave_bounded_fma<const DU: bool>(a: f64, zeta: f64, amp: f64, x: f64) -> Option<Bounded> {
    wave_bounded_with::<DU>(a, zeta, amp, x)
}

/// One compensated Horner step `acc <- acc Y + c` (`acc = h + l`, `Y = yh + yl`,
/// `c = ch + cl`): `p + pi = h yh` exactly, `h' + sigma = p + ch` exactly,
/// `l' = l yh + (pi + sigma + h yl + cl)`.
#[inline(always)]
fn horner_step(h: f64, l: f64, yh: f64, yl: f64, ch: f64, cl: f64) -> (f64, f64) {
    let p = h * yh;
    let pi = h.mul_add(yh, -p);
    let (s, sigma) = two_sum(p, ch);
    (s, l.mul_add(yh, h.mul_add(yl, cl) + (pi + sigma)))
}

/// One compensated step of the recurrence, `p_{k-1} = c p_k - p_{k+1}` with
/// `c + cl = 2k/D` (module docs, "Compensation"):
/// `l' = fl(c l0 + fl(fl(cl h0 + fl(r - rho)) - l1))`.
#[inline(always)]
fn rec_step(c: f64, cl: f64, h0: f64, l0: f64, h1: f64, l1: f64) -> (f64, f64) {
    let hn = c.mul_add(h0, -h1);
    let (s, rho) = two_sum(h1, hn);
    let r = c.mul_add(h0, -s);
    (hn, c.mul_add(l0, cl.mul_add(h0, r - rho) - l1))
}

#[inline(always)]
fn dd(h: f64, l: f64) -> Dd {
    let (hi, lo) = two_sum(h, l);
    Dd { hi, lo }
}

/// `1/b` in double-double: `r0 = fl(1/b.hi)`, `e = 1 - b r0` (the first part by
/// one fused multiply-add, exact), `1/b = r0 + r0 e + O(e^2)` (relative error
/// `<= 9.4 u^2`, method block).
#[inline(always)]
fn recip(b: Dd) -> Dd {
    let r0 = 1.0 / b.hi;
    let e = (-b.hi).mul_add(r0, 1.0) - b.lo * r0;
    dd(r0, r0 * e)
}

/// The geometry of one `x`: `q`, `X = q^2`, `acosh(x/a) = -ln q` (each with its
/// bound; `acosh` only with `ACOSH`, else zero: the gradient does not use it),
/// and `1/a`.
struct Geometry {
    q: BoundedDd,
    big_x: BoundedDd,
    acosh: BoundedDd,
    inv_a: BoundedDd,
}

#[inline(always)]
fn geometry<const ACOSH: bool>(a: f64, x: f64) -> Option<Geometry> {
    let rm1 = BoundedDd { v: Dd::diff(x, a), e: 0.0 }; // x - a, exact
    let rp1 = BoundedDd { v: Dd::diff(x, -a), e: 0.0 }; // x + a, exact
    let t = div_p::<Fused>(rm1, rp1)?.sqrt_p::<Fused>()?;
    if !(t.mag() + t.e <= T_MAX) {
        return None;
    }
    let one_minus_t = BoundedDd::ONE.sub(t);
    let inv_a = BoundedDd::ONE.div_f64_p::<Fused>(a);
    // q = (1 - t)/(1 + t) = (1 - t)^2 (x + a)/(2a)
    let q = one_minus_t.mul_p::<Fused>(one_minus_t).mul_p::<Fused>(rp1.mul_p::<Fused>(inv_a).mul_f64_p::<Fused>(0.5));
    let big_x = q.mul_p::<Fused>(q);
    let acosh = if ACOSH { neg_ln::<Fused>(q)? } else { BoundedDd { v: Dd::ZERO, e: 0.0 } };
    Some(Geometry { q, big_x, acosh, inv_a })
}

/// Where the Horner sums in `Y = -X` start: the order `n_x` with
/// `|X|^{n_x} (top + 1)^2 <= 2^-64`, from a lower bound of `-ln |X|`: with
/// `acosh` ([`neg_ln_x_from_acosh`]) where the geometry has it, else from `X`
/// alone ([`neg_ln_x_from_x`]); `top` near `x = a`, where the bound is not positive.
#[inline(always)]
fn horner_start(neg_ln_x_lower: f64, top: usize) -> usize {
    let lo = neg_ln_x_lower;
    if !(lo > 0.0) {
        return top;
    }
    let need = (LN2_64_UP + 2.0 * ln_upper((top + 1) as f64)) / lo * CHAIN_INFLATION;
    if need < top as f64 { need.ceil() as usize } else { top }
}

/// `-ln |X| >= 2 (acosh - 10^-15)` (the margin covers the rounding of `X` and of
/// `acosh`, whose low part and bound are checked below `4e-16`; 0 where not).
#[inline(always)]
fn neg_ln_x_from_acosh(acosh: BoundedDd) -> f64 {
    let lo = acosh.v.hi - 1e-15;
    if lo > 0.0 && acosh.v.lo.abs() + acosh.e <= 4e-16 { 2.0 * lo } else { 0.0 }
}

/// `-ln |X| >= -ln_upper(x_up)`, `x_up` the bound `|X~.hi| + |X~.lo| + e_X` of
/// `|X|` times `1 + 4u` (its two sums and the product rounded), `ln_upper` the
/// tangent bound of `kernels.rs` (within 0.072 of `ln`).
#[inline(always)]
fn neg_ln_x_from_x(big_x: BoundedDd) -> f64 {
    -ln_upper((big_x.v.hi.abs() + big_x.v.lo.abs() + big_x.e) * (1.0 + 4.0 * U))
}

/// What one pass leaves: `p_0`, `p_1` (as `h + l`), `Lambda = sum_{m>=1} p_{2m}`,
/// the Horner sums `U`, `S`, and (when bounded) the propagated bounds in units
/// of `mu`: `e_0`, `e_1`, `sum_{m>=1} e_{2m}`, `sum_n n^2 e_{2n}`, and
/// `sum_{m>=1} z_{2m}` (method block, "Error bound").
#[derive(Default)]
struct Pass {
    p0: (f64, f64),
    p1: (f64, f64),
    lam: (f64, f64),
    u: (f64, f64),
    s: (f64, f64),
    e0: f64,
    e1: f64,
    e_lam: f64,
    e_s: f64,
    sum_z: f64,
}

/// Miller's recurrence from `p_{2 top + 1} = 0`, `p_{2 top} = 1` with the three
/// sums in the same loop (module docs). With `BOUND`, the running error bound
/// of the recurrence in units of `mu` (`e_{k-1} = c (e_k + z_k) + e_{k+1} + z_{k-1}`,
/// `z_j = |h_j| + kappa |l_j|`) and its sums run alongside. Without `WITH_U`
/// the Horner sum `U` is not formed, without `WITH_S` neither the `V_i` nor `S`
/// nor the chain's `sum_n n^2 e_{2n}` (the result that needs them is not asked for).
#[inline(always)]
fn miller_pass<const BOUND: bool, const WITH_U: bool, const WITH_S: bool>(
    inv_d: Dd,
    top: usize,
    n_x: usize,
    yh: f64,
    yl: f64,
    kappa: f64,
) -> Pass {
    let (mut h1, mut l1) = (0.0f64, 0.0f64); // p_{k+1}
    let (mut h0, mut l0) = (1.0f64, 0.0f64); // p_k, k = 2n
    let (mut lam_h, mut lam_l) = (1.0f64, 0.0f64); // sum_{n>=1} p_{2n}
    let (mut vh, mut vl) = (top as f64, 0.0f64); // V_{top-1} = top p_{2 top}
    let (mut uh, mut ul, mut sh, mut sl) = (0.0f64, 0.0f64, 0.0f64, 0.0f64);
    if top <= n_x {
        uh = 1.0;
        sh = vh;
    }
    // the bound's state: z_k, e_{k+1}, e_k, and the sums
    let mut z0 = 1.0f64;
    let (mut e1, mut e0) = (0.0f64, 0.0f64);
    let (mut e_lam, mut ev, mut e_s, mut sum_z) = (0.0f64, 0.0f64, 0.0f64, 1.0f64);
    // c + cl = kk/D, kk = 2k (the counters in f64: no integer conversions in the loop)
    let mult = |kk: f64| (kk * inv_d.hi, kk.mul_add(inv_d.hi, -(kk * inv_d.hi)) + kk * inv_d.lo);
    let n_x = n_x as f64;
    let mut kk = 4.0 * top as f64; // 2k at k = 2n
    let mut mf = top as f64 - 1.0; // m = n - 1
    for _ in 0..top {
        // p_{2n} -> p_{2n-1} -> p_{2n-2}
        let (c, cl) = mult(kk);
        let (ho, lo) = rec_step(c, cl, h0, l0, h1, l1);
        if BOUND {
            let zn = kappa.mul_add(lo.abs(), ho.abs());
            (e1, e0) = (e0, c.mul_add(e0, e1 + c.mul_add(z0, zn)));
            z0 = zn;
        }
        let (c, cl) = mult(kk - 2.0);
        let (he, le) = rec_step(c, cl, ho, lo, h0, l0);
        if BOUND {
            let zn = kappa.mul_add(le.abs(), he.abs());
            (e1, e0) = (e0, c.mul_add(e0, e1 + c.mul_add(z0, zn)));
            z0 = zn;
        }
        h1 = ho;
        l1 = lo;
        h0 = he;
        l0 = le;
        if mf == 0.0 {
            break;
        }
        // the even order 2m just formed
        let (s, e) = two_sum(lam_h, he);
        lam_h = s;
        lam_l += e + le;
        // V_{m-1} = m p_{2m} - V_m
        if WITH_S {
            let pm = mf * he;
            let pm_e = mf.mul_add(he, -pm);
            let (s, e) = two_sum(pm, -vh);
            vh = s;
            vl = mf.mul_add(le, pm_e + e) - vl;
        }
        if mf <= n_x {
            if WITH_U {
                (uh, ul) = horner_step(uh, ul, yh, yl, he, le);
            }
            if WITH_S {
                (sh, sl) = horner_step(sh, sl, yh, yl, vh, vl);
            }
        }
        if BOUND {
            sum_z += z0;
            e_lam += e0;
            if WITH_S {
                ev = mf.mul_add(e0, ev);
                e_s += ev;
            }
        }
        kk -= 4.0;
        mf -= 1.0;
    }
    Pass { p0: (h0, l0), p1: (h1, l1), lam: (lam_h, lam_l), u: (uh, ul), s: (sh, sl), e0, e1, e_lam, e_s, sum_z }
}

/// `D` (bounded), `1/D` in double-double and the bucket of the table.
#[inline(always)]
fn contact(a: f64, zeta: f64) -> Option<(BoundedDd, Dd, usize, Bucket)> {
    let two_pi = BoundedDd { v: Dd::TWO_PI, e: TWO_PI_ERR };
    let d = two_pi.mul_f64_p::<Fused>(a).div_f64_p::<Fused>(zeta);
    if !(d.v.hi > 1e-100 && d.v.hi <= D_MAX_TABLE) {
        return None;
    }
    let bucket = *table().get((d.v.hi * D_STEPS).ceil() as usize)?;
    if bucket.n as usize + 1 >= MAX_TOP {
        return None;
    }
    Some((d, recip(d.v), bucket.n as usize + 1, bucket))
}

#[inline(always)]
fn wave_value_with(a: f64, zeta: f64, amp: f64, x: f64) -> Option<(f64, f64)> {
    let (d, inv_d, top, _) = contact(a, zeta)?;
    let g = geometry::<true>(a, x)?;
    let n_x = horner_start(neg_ln_x_from_acosh(g.acosh), top);
    let (yh, yl) = (-g.big_x.v.hi, -g.big_x.v.lo);
    let p = miller_pass::<false, true, true>(inv_d, top, n_x, yh, yl, 0.0);
    let (p0, p1) = (dd(p.p0.0, p.p0.1), dd(p.p1.0, p.p1.1));
    let lambda = p0 + dd(p.lam.0, p.lam.1).mul_f64_p::<Fused>(2.0);
    let inv_lambda = recip(lambda);
    let u_sum = dd(p.u.0, p.u.1).mul_p::<Fused>(g.big_x.v).mul_f64_p::<Fused>(2.0);
    let bracket = d.v.mul_p::<Fused>(p1).mul_p::<Fused>(g.acosh.v) + u_sum - p0;
    let u = (Dd::ONE + bracket.mul_p::<Fused>(inv_lambda)).mul_f64_p::<Fused>(amp).to_f64();
    let du = dd(p.s.0, p.s.1)
        .mul_p::<Fused>(g.q.v)
        .mul_p::<Fused>(inv_lambda)
        .mul_p::<Fused>(g.inv_a.v)
        .mul_f64_p::<Fused>(8.0 * amp)
        .to_f64();
    if !(u.is_finite() && du.is_finite()) {
        return None;
    }
    Some((u, du))
}

/// The bounded pass and the assembly of one result (`DU` selects `du_w/dx`):
/// the common part (`D`, the geometry, the pass with `p_0`, `p_1`, `Lambda` and
/// the chain), then only the sum and the assembly that result needs (method
/// block, 5 and 6; each result's bound uses only its own inputs).
#[inline(always)]
fn wave_bounded_with<const DU: bool>(a: f64, zeta: f64, amp: f64, x: f64) -> Option<Bounded> {
    let (d, inv_d, top, bucket) = contact(a, zeta)?;
    let d_low = d.v.hi - d.v.lo.abs() - d.e;
    if !(d_low > 0.0) {
        return None;
    }
    let g = if DU { geometry::<false>(a, x)? } else { geometry::<true>(a, x)? };
    let n_x = horner_start(if DU { neg_ln_x_from_x(g.big_x) } else { neg_ln_x_from_acosh(g.acosh) }, top);
    let (yh, yl) = (-g.big_x.v.hi, -g.big_x.v.lo);
    // the recurrence's local error (method block): rho_c bounds the relative
    // error of the multipliers c + cl against 2k/D; |delta_k| <= mu (z_{k-1} + c z_k)
    let u2 = U * U;
    let rho_c = d.e / d_low + 13.0 * u2;
    let mu = 23.07 * u2 + 1.001 * rho_c;
    let kappa = (3.11 * U + 1.001 * rho_c) / mu * (1.0 + 4.0 * U);
    let p = if DU {
        miller_pass::<true, false, true>(inv_d, top, n_x, yh, yl, kappa)
    } else {
        miller_pass::<true, true, false>(inv_d, top, n_x, yh, yl, kappa)
    };
    let scale = mu * CHAIN_INFLATION;
    let (e0, e1, e_lam, e_s) = (p.e0 * scale, p.e1 * scale, p.e_lam * scale, p.e_s * scale);
    let tf = top as f64;
    let sa = p.sum_z * CHAIN_INFLATION;
    let sb = sa / kappa;
    let drop = TAIL * 1.01 * (sa + sb);
    let sec_lam = U * tf * (5.0 * U * tf * sa + 3.0 * sb);
    let b = |v: (f64, f64), e: f64| BoundedDd { v: dd(v.0, v.1), e };
    let p0 = b(p.p0, e0);
    let lambda = p0.add(b(p.lam, e_lam + sec_lam).mul_f64_p::<Fused>(2.0));
    // Miller's start (P_k against J_k) and the orders beyond 2 top, scaled from
    // the bucket's D_hi to D by (D/D_hi)^{2 top}: every term there has order > 2 top
    let shrink = (pow_int(((d.mag() + d.e) / bucket.d_hi).min(1.0), 2 * top as u32) * CHAIN_INFLATION).min(1.0);
    let (miller, tail0, tail2) = (bucket.miller * shrink, bucket.tail0 * shrink, bucket.tail2 * shrink);
    if DU {
        let t3 = tf * tf * tf;
        let sec_s = U * t3 * (70.0 * U * tf * sa + 13.0 * sb) + drop + g.big_x.e * t3 * 1.02 * (sa + sb);
        let ss = b(p.s, 1.01 * e_s + sec_s);
        let mut gs = div_p::<Fused>(ss.mul_p::<Fused>(g.q), lambda)?;
        gs.e += miller * t3 + tail2;
        gs.mul_p::<Fused>(g.inv_a.mul_f64_p::<Fused>(8.0 * amp)).finish()
    } else {
        let sec_u = U * tf * (29.0 * U * tf * sa + 10.0 * sb) + drop / ((tf + 1.0) * (tf + 1.0)) + g.big_x.e * tf * 1.02 * (sa + sb);
        let p1 = b(p.p1, e1);
        let su = b(p.u, 1.01 * e_lam + sec_u);
        let u_sum = su.mul_p::<Fused>(g.big_x).mul_f64_p::<Fused>(2.0);
        let bracket = d.mul_p::<Fused>(p1).mul_p::<Fused>(g.acosh).add(u_sum).sub(p0);
        let mut r = div_p::<Fused>(bracket, lambda)?;
        let weight = 1.0 + (d.mag() + d.e) * (g.acosh.mag() + g.acosh.e) + 2.0 * tf;
        r.e += miller * weight + 2.0 * tail0;
        BoundedDd::ONE.add(r).mul_f64_p::<Fused>(amp).finish()
    }
}

/// Where the time of one from-scratch bounded call goes (issue 23, item 5): thread
/// CPU time per call (the fastest of 15 batches), min / median / max over the
/// model-domain grid (`a` from 0.5 to 6 in steps of 1/4, `x/a` in {1, 1.001, 1.1,
/// 1.5, 2, 2.5, 3}, `zeta = 9/8`), of: the whole `u_w` bounded route; its fixed
/// part alone (`D`, the bucket, the geometry with `-ln q`); the compensated
/// recurrence alone (with `Lambda`, no other sum, no bound); a plain f64 Miller
/// recurrence of the same length (one fused multiply-add a step); the fixed part
/// with the pass with `U`, with the bound, and with both (the assembly is the rest);
/// and, to read the others in cycles, one fused multiply-add of a dependent chain.
/// A measurement that asserts nothing; needs FMA. Run by hand:
/// `cargo test --release --features maugis/gmp-no-check --lib cost_split -- --ignored --nocapture`.
#[cfg(all(test, target_arch = "x86_64"))]
mod cost_split {
    use super::*;
    use std::hint::black_box;

    /// Fastest of 15 batches of `reps` calls, ns per call.
    fn per_call(reps: usize, mut f: impl FnMut() -> f64) -> f64 {
        let mut best = f64::INFINITY;
        let mut acc = 0.0;
        for _ in 0..15 {
            let t0 = crate::budget::thread_cpu_seconds() * 1e9;
            for _ in 0..reps {
                acc += f();
            }
            best = best.min(((crate::budget::thread_cpu_seconds() * 1e9) - t0) / reps as f64);
        }
        black_box(acc);
        best
    }

    #[target_feature(enable = "fma")]
    unsafe fn fixed_part(a: f64, zeta: f64, x: f64) -> f64 {
        let (d, inv_d, top, _) = contact(a, zeta).unwrap();
        let g = geometry::<true>(a, x).unwrap();
        d.v.hi + inv_d.lo + top as f64 + g.acosh.v.hi + g.big_x.e
    }

    #[target_feature(enable = "fma")]
    unsafe fn compensated(a: f64, zeta: f64) -> f64 {
        let (_, inv_d, top, _) = contact(a, zeta).unwrap();
        let p = miller_pass::<false, false, false>(inv_d, top, 0, 0.0, 0.0, 0.0);
        p.lam.0 + p.lam.1 + p.p0.0 + p.p0.1 + p.p1.0 + p.p1.1
    }

    #[target_feature(enable = "fma")]
    unsafe fn pass<const BOUND: bool, const WITH_U: bool>(a: f64, zeta: f64, x: f64) -> f64 {
        let (_, inv_d, top, _) = contact(a, zeta).unwrap();
        let g = geometry::<true>(a, x).unwrap();
        let n_x = horner_start(neg_ln_x_from_acosh(g.acosh), top);
        let p = miller_pass::<BOUND, WITH_U, false>(inv_d, top, n_x, -g.big_x.v.hi, -g.big_x.v.lo, 1e15);
        // every field, so that none of the pass is optimised away
        p.lam.0 + p.lam.1 + p.p0.0 + p.p0.1 + p.p1.0 + p.p1.1 + p.u.0 + p.u.1 + p.e0 + p.e1 + p.e_lam + p.sum_z
    }

    #[target_feature(enable = "fma")]
    unsafe fn fma_chain() -> f64 {
        let (mut v, a, b) = (black_box(1.0f64), black_box(0.999_999_9f64), black_box(1e-9f64));
        for _ in 0..1000 {
            v = v.mul_add(a, b);
        }
        v
    }

    #[target_feature(enable = "fma")]
    unsafe fn plain(a: f64, zeta: f64) -> f64 {
        let (_, inv_d, top, _) = contact(a, zeta).unwrap();
        let (mut p1, mut p0, mut lam) = (0.0f64, 1.0f64, 0.0f64);
        let mut kk = 4.0 * top as f64;
        for _ in 0..top {
            let po = (kk * inv_d.hi).mul_add(p0, -p1);
            let pe = ((kk - 2.0) * inv_d.hi).mul_add(po, -p0);
            (p1, p0) = (po, pe);
            lam += pe;
            kk -= 4.0;
        }
        lam + p0
    }

    #[test]
    #[ignore = "measurement, asserts nothing: run by hand (see the doc comment)"]
    fn cost_split() {
        assert!(has_fma());
        let zeta = 1.125;
        let mut rows: [Vec<f64>; 7] = Default::default();
        for i in 0..=22 {
            let a = 0.5 + 0.25 * i as f64;
            for r in [1.0, 1.001, 1.1, 1.5, 2.0, 2.5, 3.0] {
                let x = a * r;
                let reps = 2000;
                // SAFETY: FMA asserted above.
                unsafe {
                    rows[0].push(per_call(reps, || wave_scratch_bounded::<false>(black_box(a), zeta, 1.0, black_box(x)).unwrap().value));
                    rows[1].push(per_call(reps, || fixed_part(black_box(a), zeta, black_box(x))));
                    rows[2].push(per_call(reps, || compensated(black_box(a), zeta)));
                    rows[3].push(per_call(reps, || plain(black_box(a), zeta)));
                    rows[4].push(per_call(reps, || pass::<false, true>(black_box(a), zeta, black_box(x))));
                    rows[5].push(per_call(reps, || pass::<true, false>(black_box(a), zeta, black_box(x))));
                    rows[6].push(per_call(reps, || pass::<true, true>(black_box(a), zeta, black_box(x))));
                }
            }
        }
        // SAFETY: FMA asserted above.
        let chain = per_call(1, || unsafe { fma_chain() }) / 1000.0;
        eprintln!("{:44} {chain:6.3} ns", "one fused multiply-add of a dependent chain");
        let names = ["u_w bounded, whole route", "fixed part (D, bucket, geometry, -ln q)", "compensated recurrence alone", "plain f64 recurrence alone", "fixed + pass with U, no bound", "fixed + pass with bound, no U", "fixed + pass with U and bound"];
        for (name, mut v) in names.into_iter().zip(rows) {
            v.sort_by(f64::total_cmp);
            eprintln!("{name:44} min {:6.1} / median {:6.1} / max {:6.1} ns per call", v[0], v[v.len() / 2], v[v.len() - 1]);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::contact::displacement::{du_wave_mp, u_wave_mp};
    use crate::special::exact;
    use rug::Float;

    /// The one-pass bound encloses the 200-bit certified values at every point
    /// (the edge, one ulp, `1 + 1e-15`, the far field, `D` from 0.13 to 63), and
    /// at `zeta = 9/8` it is within `2e-16` of the scales (printed: the worst
    /// bound and error over all points, as fractions of the scales).
    #[test]
    fn scratch_bound_encloses_and_is_tight() {
        if !has_fma() {
            return;
        }
        let mut worst = [0.0f64; 4];
        for &(a, zeta) in &[(0.5, 1.125), (1.0, 1.125), (3.0, 1.125), (6.0, 1.125), (6.0, 1.0), (6.0, 0.95), (6.0, 0.9), (6.0, 0.7), (6.0, 0.6), (2.0, 0.25), (0.1, 5.0)] {
            for &r in &[1.0, 1.0 + f64::EPSILON, 1.0 + 1e-15, 1.0 + 1e-9, 1.01, 1.5, 2.0, 3.0, 3.5] {
                let x = a * r;
                let u = wave_scratch_bounded::<false>(a, zeta, 1.0, x).unwrap();
                let du = wave_scratch_bounded::<true>(a, zeta, 1.0, x).unwrap();
                let (ae, ze, me, xe) = (exact(a), exact(zeta), exact(1.0), exact(x));
                let u_ref = u_wave_mp(&ae, &ze, &me, &xe, 200).unwrap();
                let du_ref = du_wave_mp(&ae, &ze, &me, &xe, 200).unwrap();
                let us = u_ref.to_f64().abs().max(1.0);
                let dus = du_ref.to_f64().abs().max(2.0 * std::f64::consts::PI / zeta);
                let eu = Float::with_val(264, u_ref.mid() - u.value).abs().to_f64();
                let edu = Float::with_val(264, du_ref.mid() - du.value).abs().to_f64();
                assert!(eu <= u.err, "a={a} zeta={zeta} x={x}: u {u} misses {u_ref:?}");
                assert!(edu <= du.err, "a={a} zeta={zeta} x={x}: du {du} misses {du_ref:?}");
                if zeta == 1.125 {
                    // the model's wavelength: the bound is tight
                    assert!(u.err <= 2e-16 * us && du.err <= 2e-16 * dus, "a={a} x={x}: bounds {u} {du}");
                }
                worst = [worst[0].max(eu / us), worst[1].max(u.err / us), worst[2].max(edu / dus), worst[3].max(du.err / dus)];
            }
        }
        eprintln!("worst: {:.2e} {:.2e} {:.2e} {:.2e}", worst[0], worst[1], worst[2], worst[3]);
    }
}
