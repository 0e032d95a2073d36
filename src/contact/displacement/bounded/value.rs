//! The fast **value** path of `u_wave` / `du_wave` from scratch: one
//! compensated Miller recurrence with both sums of the Bessel form
//! accumulated in the same loop. Its error is an **estimate** (no proven
//! bound: the bounded path is [`super::CertifiedBessel`]); the accuracy is
//! measured and enforced by `tests/wave_value.rs` (at most `1e-15` of
//! `max(|u_w|, |A|)`, and of `max(|du_w/dx|, 2 pi |A|/zeta)` for the gradient,
//! on a dense grid of the model domain and its edges, against the 200-bit
//! Bessel form).
//!
//! # Method
//!
//! Notation of [`super`]: `D = 2 pi a/zeta`, `t = sqrt((x-a)/(x+a))`,
//! `q = (1-t)^2 (x+a)/(2a)`, `X = q^2`, `Y = -X`, `acosh(x/a) = -ln q`.
//!
//! * **Miller's recurrence** [DLMF 10.6.1, 10.74(iv)]: `p_{M+1} = 0`, `p_M = 1`,
//!   `p_{k-1} = (2k/D) p_k - p_{k+1}` down to `k = 1`, so that `p_k = lambda J_k(D)`
//!   up to a relative error `~ J_{M+1}/Y_{M+1}` (negligible), with
//!   `lambda = p_0 + 2 sum_{n>=1} p_{2n}` from `J_0 + 2 sum J_{2n} = 1`
//!   [DLMF 10.12.4]. `M = 2N + 2`, `N` the truncation of the certified path
//!   (both Bessel tails below `2^-64`), from a table over `D` in steps of 1/4.
//! * **Compensation.** Each `p_k` is carried as `h_k + l_k`: `h_{k-1} = fl(c h_k - h_{k+1})`
//!   (one fused multiply-add, the only operation on the dependency chain),
//!   `c + c_l = 2k (1/D)` (`1/D` in double-double), the step's rounding error
//!   `c h_k - h_{k+1} - h_{k-1} = fma(c, h_k, -s) - rho` with `s + rho = h_{k+1} + h_{k-1}`
//!   (two_sum), and `l_{k-1} = c l_k + c_l h_k - l_{k+1} + (that error)`: the
//!   low parts run through the same linear recurrence driven by the local
//!   rounding errors, so `h + l` is accurate to a few `u^2` relative, as in
//!   double-double, at a fraction of its cost.
//! * **The sums in the same loop**, at each even order `2n` as it appears
//!   (no coefficient table, no second pass): `Lambda = sum p_{2n}` (two_sum),
//!   `V_{n-1} = n p_{2n} - V_n` (so `V_i = (-1)^i T_i`,
//!   `T_i = sum_{n>i} (-1)^{n+1} n p_{2n}`), and by compensated Horner in
//!   `Y = -X` (Graillat-Langlois-Louvet, with the double-double `Y`)
//!   `U = sum_{n>=1} p_{2n} Y^{n-1}` and `S = sum_{i>=0} V_i Y^i`. The Horner
//!   sums start at the order `n_x` where `X^{n_x} (N+1)^2 <= 2^-64` (the
//!   higher terms are below the rounding; `n_x = N + 1` near `x = a`).
//! * **Assembly** in double-double: with `P = p/lambda`,
//!   `u_w = A [1 + (-p_0 + D p_1 acosh(r) + 2 X U)/lambda]`,
//!   `du_w/dx = (8A/a) q S/lambda` ([`super`]: `(1 - t)(1 + q) = 2q`).
//!
//! Where it does not apply (no fused multiply-add, `x/a > 25/7`, `D` beyond
//! the table) it returns `None` and the caller uses the previous route.

use super::certified::bessel_tails;
use super::kernels::{div_p, has_fma, ln_upper, neg_ln};
use super::{T_MAX, TWO_PI_ERR};
use crate::ball::{two_sum, BoundedDd, Dd, Fused};

/// The table of `N(D)` covers `D <= D_MAX_TABLE` in steps of `1/D_STEPS`.
const D_STEPS: f64 = 4.0;
const D_MAX_TABLE: f64 = 64.0;

/// `N` for `D in ((i-1)/4, i/4]`: the certified path's truncation at `D = i/4`
/// (the tails grow with `D`, so it serves the whole interval).
fn n_table() -> &'static [u16] {
    static TABLE: std::sync::OnceLock<Vec<u16>> = std::sync::OnceLock::new();
    TABLE.get_or_init(|| {
        let len = (D_MAX_TABLE * D_STEPS) as usize + 1;
        (0..len)
            .map(|i| {
                let half_d = i as f64 / D_STEPS * 0.5 * (1.0 + 1e-12);
                bessel_tails(half_d, 400).map_or(u16::MAX, |(n, _, _)| n.max(1) as u16)
            })
            .collect()
    })
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

#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "fma")]
unsafe fn wave_value_fma(a: f64, zeta: f64, amp: f64, x: f64) -> Option<(f64, f64)> {
    wave_value_with(a, zeta, amp, x)
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
/// `c + cl = 2k/D` (module docs, "Compensation").
#[inline(always)]
fn rec_step(c: f64, cl: f64, h0: f64, l0: f64, h1: f64, l1: f64) -> (f64, f64) {
    let hn = c.mul_add(h0, -h1);
    let (s, rho) = two_sum(h1, hn);
    let r = c.mul_add(h0, -s);
    (hn, c.mul_add(l0, cl.mul_add(h0, (r - rho) - l1)))
}

#[inline(always)]
fn dd(h: f64, l: f64) -> Dd {
    let (hi, lo) = two_sum(h, l);
    Dd { hi, lo }
}

/// `1/b` in double-double: `r0 = fl(1/b.hi)`, `e = 1 - b r0` (the first part by
/// one fused multiply-add, exact), `1/b = r0 + r0 e + O(e^2)`.
#[inline(always)]
fn recip(b: Dd) -> Dd {
    let r0 = 1.0 / b.hi;
    let e = (-b.hi).mul_add(r0, 1.0) - b.lo * r0;
    dd(r0, r0 * e)
}

#[inline(always)]
fn wave_value_with(a: f64, zeta: f64, amp: f64, x: f64) -> Option<(f64, f64)> {
    // D and 1/D in double-double
    let two_pi = BoundedDd { v: Dd::TWO_PI, e: TWO_PI_ERR };
    let d = two_pi.mul_f64_p::<Fused>(a).div_f64_p::<Fused>(zeta).v;
    if !(d.hi > 1e-100 && d.hi <= D_MAX_TABLE) {
        return None;
    }
    let inv_d = recip(d);
    let n_terms = *n_table().get((d.hi * D_STEPS).ceil() as usize)? as usize;
    if n_terms == u16::MAX as usize {
        return None;
    }
    // geometry (as on the bounded path)
    let rm1 = BoundedDd { v: Dd::diff(x, a), e: 0.0 };
    let rp1 = BoundedDd { v: Dd::diff(x, -a), e: 0.0 };
    let t = div_p::<Fused>(rm1, rp1)?.sqrt_p::<Fused>()?;
    if !(t.v.hi <= T_MAX) {
        return None;
    }
    let one_minus_t = Dd::ONE - t.v;
    let half_ratio = rp1.v.mul_p::<Fused>(recip(Dd::from_f64(a))).mul_f64_p::<Fused>(0.5);
    let q = one_minus_t.mul_p::<Fused>(one_minus_t).mul_p::<Fused>(half_ratio);
    let big_x = q.mul_p::<Fused>(q);
    let acosh_r = neg_ln::<Fused>(BoundedDd { v: q, e: 0.0 })?.v;
    let (yh, yl) = (-big_x.hi, -big_x.lo);
    // Horner start: X^{n_x} (N+1)^2 <= 2^-64, -ln X = 2 acosh(r)
    let top = n_terms + 1;
    let n_x = if acosh_r.hi > 0.0 {
        let need = (64.0 * std::f64::consts::LN_2 + 2.0 * ln_upper((top + 1) as f64)) / (2.0 * acosh_r.hi);
        if need < top as f64 { need.ceil() as usize } else { top }
    } else {
        top
    };
    // Miller: p_{2 top + 1} = 0, p_{2 top} = 1
    let (mut h1, mut l1) = (0.0f64, 0.0f64); // p_{k+1}
    let (mut h0, mut l0) = (1.0f64, 0.0f64); // p_k, k = 2n
    let (mut lam_h, mut lam_l) = (1.0f64, 0.0f64); // sum_{n>=1} p_{2n}
    let (mut vh, mut vl) = (top as f64, 0.0f64); // V_{top-1} = top p_{2 top}
    let (mut uh, mut ul, mut sh, mut sl) = (0.0f64, 0.0f64, 0.0f64, 0.0f64);
    if top <= n_x {
        uh = 1.0;
        sh = vh;
    }
    // c + cl = kk/D, kk = 2k (the counters in f64: no integer conversions in the loop)
    let step = |kk: f64, h0: f64, l0: f64, h1: f64, l1: f64| {
        let c = kk * inv_d.hi;
        let cl = kk.mul_add(inv_d.hi, -c) + kk * inv_d.lo;
        rec_step(c, cl, h0, l0, h1, l1)
    };
    let n_x = n_x as f64;
    let mut kk = 4.0 * top as f64; // 2k at k = 2n
    let mut mf = top as f64 - 1.0; // m = n - 1
    for _ in 0..top {
        // p_{2n} -> p_{2n-1} -> p_{2n-2}
        let (ho, lo) = step(kk, h0, l0, h1, l1);
        let (he, le) = step(kk - 2.0, ho, lo, h0, l0);
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
        let pm = mf * he;
        let pm_e = mf.mul_add(he, -pm);
        let (s, e) = two_sum(pm, -vh);
        vh = s;
        vl = mf.mul_add(le, pm_e + e) - vl;
        if mf <= n_x {
            let (a1, b1) = horner_step(uh, ul, yh, yl, he, le);
            uh = a1;
            ul = b1;
            let (a2, b2) = horner_step(sh, sl, yh, yl, vh, vl);
            sh = a2;
            sl = b2;
        }
        kk -= 4.0;
        mf -= 1.0;
    }
    let (p0, p1) = (dd(h0, l0), dd(h1, l1));
    let lambda = p0 + dd(lam_h, lam_l).mul_f64_p::<Fused>(2.0);
    let inv_lambda = recip(lambda);
    let u_sum = dd(uh, ul).mul_p::<Fused>(big_x).mul_f64_p::<Fused>(2.0);
    let bracket = d.mul_p::<Fused>(p1).mul_p::<Fused>(acosh_r) + u_sum - p0;
    let u = (Dd::ONE + bracket.mul_p::<Fused>(inv_lambda)).mul_f64_p::<Fused>(amp).to_f64();
    let du = dd(sh, sl)
        .mul_p::<Fused>(q)
        .mul_p::<Fused>(inv_lambda)
        .mul_p::<Fused>(recip(Dd::from_f64(a)))
        .mul_f64_p::<Fused>(8.0 * amp)
        .to_f64();
    if !(u.is_finite() && du.is_finite()) {
        return None;
    }
    Some((u, du))
}
