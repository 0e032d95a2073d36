//! The certified per-contact data of the bounded wave path ([`CertifiedBessel`]):
//! the sequence `J_n(D)` natively in double-double (top series and downward
//! recurrence, every step bounded) or in MP at [`super::CERT_PREC`] bits, the
//! Horner coefficients of both sums with their error bounds, and the per-`x`
//! evaluation with its proven bound (module docs of [`super`]).

use rug::float::Round;

use crate::ball::{Ball, Bounded, BoundedDd, Dd, Dekker, ExactProduct, U};
use crate::error::Result;
use crate::special::bessel_j::{
    bessel_j01, bessel_j_sequence_three_term, forward_sequence, inv_factorials, HANKEL_MAX_X, HANKEL_MIN_X, MAX_TABLE_FACTORIAL, TABLE_ETA,
};

use super::kernels::*;
use super::*;

/// The certified per-contact data of the Bessel form.
#[derive(Debug, Clone)]
pub(crate) struct CertifiedBessel {
    /// `1 - J_0(D)`.
    one_minus_j0: BoundedDd,
    /// `D J_1(D)`.
    d_j1: BoundedDd,
    /// `1/a` (one double-double quotient, with its bound).
    inv_a: BoundedDd,
    /// The Horner coefficients of both sums, interleaved (one load stream):
    /// `[u.hi, T.hi, u.lo, T.lo, e_u, e_T]` for `i = 0..N`, where
    /// `u_{i+1} = (-1)^i J_{2i+2}(D)` (the `u` sum is `X sum_i u_{i+1} X^i`, `X = q^2`),
    /// `T_i = sum_{n=i+1}^{N} (-1)^{n+1} n J_{2n}(D)` (the gradient sum
    /// `sum_n (-1)^{n+1} n J_{2n} geo_n = (1 + q) sum_i T_i q^{2i}`, collecting the
    /// powers `q^{2i}` and `q^{2i+1}` of `geo_n = sum_{j<2n} q^j`), and `e_*` the
    /// coefficient's error bound plus `gamma_4 (|lo| + 1.0001 u |hi|)` (the Horner step's share).
    coef: Vec<[f64; 6]>,
    /// `lambda_i <= ln(horner_tol / (suffix_{i+1} (1 + 2^-40)))`, `i = 0..N`, where
    /// `suffix_i` bounds (rounded up) `sum_{i' >= i} (|c_i'| + err_i')` over both
    /// sums (`+inf` for `i = N - 1`, where nothing is left): the Horner sums may stop
    /// after power `i` once `(i + 1) ln|X| <= lambda_i` ([`CertifiedBessel::horner_top`]).
    lambda: Vec<f64>,
    /// Tolerance of the Horner truncation, `2^-62 min(1, D)`.
    horner_tol: f64,
    n_terms: usize,
    /// `sum_{n>N} (D/2)^{2n}/(2n)!`, rounded up.
    tail0: f64,
    /// `sum_{n>N} n^2 (D/2)^{2n}/(2n)!`, rounded up.
    tail2: f64,
}

/// `N` and the tails `sum_{n>N} (D/2)^{2n}/(2n)!`, `sum_{n>N} n^2 (D/2)^{2n}/(2n)!`
/// in f64, rounded up: the terms `t_m = (D/2)^{2m}/(2m)!` by their ratio
/// `h^2/((2m-1) 2m)` (three roundings per step, covered by `1 + 4u`), and once the
/// ratio of the weighted terms `rho = h^2 ((m+1)/m)^2/((2m+1)(2m+2))` is below
/// 1/2, the tails from `m` are at most `t_m m^p/(1 - rho)` (decreasing ratios).
/// `half_d_up >= D/2`. `None` if `N` passes `max_n`.
pub(super) fn bessel_tails(half_d_up: f64, max_n: usize) -> Option<(usize, f64, f64)> {
    let h2 = half_d_up * half_d_up * (1.0 + 2.0 * U);
    let mut t = 1.0f64; // t_0
    for m in 1..=max_n + 1 {
        let mf = m as f64;
        t = t * h2 / ((2.0 * mf - 1.0) * (2.0 * mf)) * (1.0 + 4.0 * U);
        let rho = h2 / ((2.0 * mf + 1.0) * (2.0 * mf + 2.0)) * ((mf + 1.0) / mf).powi(2) * (1.0 + 8.0 * U);
        if rho < 0.5 {
            let tail0 = t / (1.0 - rho) * (1.0 + 4.0 * U);
            let tail2 = t * mf * mf / (1.0 - rho) * (1.0 + 8.0 * U);
            if tail0 <= BESSEL_TAIL_TARGET && tail2 <= BESSEL_TAIL_TARGET {
                return Some((m - 1, tail0, tail2));
            }
        }
    }
    None
}

/// `J_n(D) = (D/2)^n/n! sum_k t_k`, `t_{k+1} = t_k z/((k+1)(n+k+1))`, `z = -(D/2)^2`
/// [DLMF 10.2.2] in [`BoundedDd`]: `pre` is `(D/2)^n/n!`. The sum stops at the
/// first `K` with ratio bound `|z|/((K+1)(n+K+1)) <= 1/2` and
/// `|t_K| <= 2^-108 |S|`; the tail is then at most `2 |t_K|` (the downward
/// recurrence amplifies the top errors by up to `~2^100` at `D = 33.5`, but in
/// absolute terms to `~1e-20`).
#[inline(always)]
pub(super) fn j_series<P: ExactProduct>(pre: BoundedDd, z: BoundedDd, n: usize) -> Option<BoundedDd> {
    let z_up = z.mag() + z.e;
    let mut t = BoundedDd::ONE;
    let mut s = BoundedDd::ONE;
    let mut k = 0usize;
    let tail = loop {
        let div = ((k + 1) * (n + k + 1)) as f64; // exact
        t = t.mul_p::<P>(z.div_f64_p::<P>(div));
        k += 1;
        let t_up = t.mag() + t.e;
        if z_up <= 0.5 * ((k + 1) * (n + k + 1)) as f64 && t_up <= TAIL_REL_SERIES * s.mag() {
            break 2.0 * t_up;
        }
        s = s.add(t);
        if k > 10_000 || !t_up.is_finite() {
            return None;
        }
    };
    s.e += tail;
    Some(pre.mul_p::<P>(s))
}

/// `J_0(D), ..., J_top(D)` with proven bounds, natively: `J_{top-1}`, `J_top` by
/// the power series, the rest by the recurrence `J_{k-1} = (2k/D) J_k - J_{k+1}`
/// [DLMF 10.6.1] run downward, everything in [`BoundedDd`] (module docs).
#[inline(always)]
pub(super) fn native_sequence<P: ExactProduct>(d: BoundedDd, top: usize) -> Option<Vec<BoundedDd>> {
    if top < 2 || top as u64 > MAX_TABLE_FACTORIAL {
        return None;
    }
    let h = d.mul_f64_p::<P>(0.5);
    let z = h.mul_p::<P>(h).neg();
    // (D/2)^m by binary powering, then 1/m! from the table (relative error <= TABLE_ETA).
    let m = top - 1;
    let (mut acc, mut base, mut e) = (BoundedDd::ONE, h, m);
    while e > 0 {
        if e & 1 == 1 {
            acc = acc.mul_p::<P>(base);
        }
        e >>= 1;
        if e > 0 {
            base = base.mul_p::<P>(base);
        }
    }
    let f = inv_factorials()[m];
    let inv_fact = BoundedDd { v: f, e: TABLE_ETA * crate::ball::mag(f) };
    let pre_m = acc.mul_p::<P>(inv_fact);
    let pre_top = pre_m.mul_p::<P>(h).div_f64_p::<P>(top as f64);
    let mut y = vec![BoundedDd::ZERO; top + 1];
    y[m] = j_series::<P>(pre_m, z, m)?;
    y[top] = j_series::<P>(pre_top, z, top)?;
    // Below the turning point (`k < D`) the downward recurrence's running bound
    // grows like `e^{0.47 D}` on top of the `e^{0.55 D}` above it; from
    // `D = 25` on, the orders below `nf = floor(x) - 1` come instead from the
    // forward recurrence of `native_recurrence.rs` at `x = D.hi` (Hankel's
    // `J_0`, `J_1`; energy-norm bound, no such growth), moved to `D = x + delta`
    // by Taylor: `J_k(D) = J_k(x) + delta (J_{k-1}(x) - J_{k+1}(x))/2 + R`,
    // `|R| <= delta^2/2` (`|J_k''| <= 1`, DLMF 10.6.1, 10.14.1).
    let x = d.v.hi;
    let nf = if (HANKEL_MIN_X..=HANKEL_MAX_X).contains(&x) { x.floor() as usize - 1 } else { 0 };
    if nf >= m {
        return None;
    }
    let inv = BoundedDd::ONE.div(d)?;
    for k in (nf + 1..=m).rev() {
        // the factor 2k/D off the recurrence's dependency chain
        let c = inv.mul_f64_p::<P>((2 * k) as f64);
        y[k - 1] = y[k].mul_sub_p::<P>(c, y[k + 1]);
    }
    if nf > 0 {
        let (j0, j1) = bessel_j01::<P>(x)?;
        let mut fw = vec![BoundedDd::ZERO; nf + 1];
        forward_sequence::<P>(nf as u64, x, j0, j1, &mut fw)?;
        // D = x + delta + eps, delta = d.lo (an f64), |eps| <= e_D. The Taylor
        // term is tiny (|delta| <= ulp(x)/2), so it is formed in f64:
        // g = fl(fl(b.hi - c.hi) 0.5) with b = J_{k-1}(x) (J_{-1} = -J_1), c = J_{k+1}(x)
        // errs from J_k'(x) = (b - c)/2 by E_g = (e_b + e_c + |b.lo| + |c.lo| + u |b.hi - c.hi|)/2,
        // and corr = fl(delta g) from (delta + eps) J_k' by |delta| E_g + e_D + u |corr|
        // (|J_k'| <= 1); the remainder adds (|delta| + e_D)^2/2.
        let delta = d.v.lo;
        let delta_up = delta.abs() + d.e;
        let rem = 0.5 * delta_up * delta_up * (1.0 + 4.0 * U) + d.e;
        for k in 0..nf {
            let below = if k == 0 { fw[1].neg() } else { fw[k - 1] };
            let (b, c) = (below, fw[k + 1]);
            let diff = b.v.hi - c.v.hi;
            let g = diff * 0.5;
            let e_g = (b.e + c.e + b.v.lo.abs() + c.v.lo.abs() + U * diff.abs()) * 0.5;
            let corr = delta * g;
            let e_corr = (delta.abs() * e_g + U * corr.abs() + rem) * (1.0 + 4.0 * U);
            y[k] = fw[k].add(BoundedDd { v: Dd::from_f64(corr), e: e_corr });
        }
    }
    Some(y)
}

impl CertifiedBessel {
    /// Certified `D` and `J_n(D)` for `a > 0`, `zeta > 0` (validated by the
    /// caller): natively in double-double where that certifies (`D` up to about
    /// 60), else at [`CERT_PREC`] bits in MP.
    pub(crate) fn new(a: f64, zeta: f64) -> Result<CertifiedBessel> {
        match Self::native_only(a, zeta) {
            Some(c) => Ok(c),
            None => Self::new_mp_counted(a, zeta),
        }
    }

    /// [`CertifiedBessel::new_mp`], counted by [`wave_bounded_mp_contacts`].
    pub(crate) fn new_mp_counted(a: f64, zeta: f64) -> Result<CertifiedBessel> {
        crate::special::fallback::count(crate::special::F64Route::WaveBoundedMpContact);
        Self::new_mp(a, zeta)
    }

    /// The native per-contact data only (`None` where it does not certify;
    /// the estimate paths then use the double-double Miller data instead).
    pub(crate) fn native_only(a: f64, zeta: f64) -> Option<CertifiedBessel> {
        #[cfg(target_arch = "x86_64")]
        if has_fma() {
            // SAFETY: the CPU supports FMA (checked just above).
            return unsafe { native_fused(a, zeta) };
        }
        Self::native::<Dekker>(a, zeta)
    }

    /// The native per-contact data (`None` where it does not certify).
    #[inline(always)]
    pub(super) fn native<P: ExactProduct>(a: f64, zeta: f64) -> Option<CertifiedBessel> {
        let two_pi = BoundedDd { v: Dd::TWO_PI, e: TWO_PI_ERR };
        let d = two_pi.mul_f64_p::<P>(a).div_f64_p::<P>(zeta);
        let half_up = (d.mag() + d.e) * 0.5 * (1.0 + 2.0 * U);
        let (n_terms, tail0, tail2) = bessel_tails(half_up, (MAX_TABLE_FACTORIAL as usize - 2) / 2)?;
        let n_terms = n_terms.max(1);
        let j = native_sequence::<P>(d, 2 * n_terms + 1)?;
        if !j.iter().all(|v| v.e <= NATIVE_J_ERR_MAX) {
            return None;
        }
        Some(Self::from_sequence::<P>(a, d, &j, n_terms, tail0, tail2))
    }

    /// The MP route: `J_n(D)` as balls at [`CERT_PREC`] bits
    /// ([`bessel_j_sequence_three_term`] at the midpoint of the ball `D`: its
    /// radii stay near `2^-wp` times a power of `D`, where the ball recurrence
    /// of `bessel_j_sequence_mp` widens by about `0.68 D` bits, 5.7e136 of
    /// bound at `D = 628`; widened by `rad(D)` since `|J_n'| <= 1` [DLMF 10.14.1]).
    pub(crate) fn new_mp(a: f64, zeta: f64) -> Result<CertifiedBessel> {
        let wp = CERT_PREC;
        let d = Ball::pi(wp).mul_pow2(1).mul(&Ball::from_f64(a, wp)?).div(&Ball::from_f64(zeta, wp)?)?;
        // N with both tails below 2^-110 (the double-double level).
        let (n_terms, tail0, tail2) = crate::contact::displacement::bessel_mp::bessel_terms(&d.upper(), 110)?;
        let nmax = 2 * n_terms + 1;
        let mid = d.mid().clone();
        let mut j = bessel_j_sequence_three_term(nmax, &mid, wp)?;
        for v in j.iter_mut() {
            v.add_error_mag(d.rad_mag());
        }
        let jt: Vec<BoundedDd> = j.iter().map(tr_from_ball).collect();
        Ok(Self::from_sequence::<Dekker>(
            a,
            tr_from_ball(&d),
            &jt,
            n_terms as usize,
            tail0.to_f64_round(Round::Up),
            tail2.to_f64_round(Round::Up),
        ))
    }

    /// The Horner coefficients and their bounds from `J_0, ..., J_{2N+1}`, in
    /// one pass from the top: `u_{i+1} = (-1)^i J_{2i+2}` (a sign flip, exact),
    /// `T_i = T_{i+1} + (i + 1) u_{i+1}`, the suffix sums of `|c| + e` over both
    /// sums, and from them the truncation table `lambda`.
    #[inline(always)]
    pub(super) fn from_sequence<P: ExactProduct>(
        a: f64,
        d: BoundedDd,
        jt: &[BoundedDd],
        n_terms: usize,
        tail0: f64,
        tail2: f64,
    ) -> CertifiedBessel {
        let err = |c: BoundedDd| (c.e + GAMMA4 * (c.v.lo.abs() + 1.0001 * U * c.v.hi.abs())) * (1.0 + 4.0 * U);
        let d_lo = d.v.hi.abs() - d.v.lo.abs() - d.e;
        let horner_tol = HORNER_TAIL_REL * d_lo.clamp(0.0, 1.0);
        let ln_tol = ln_lower(horner_tol);
        let mut coef = vec![[0.0f64; 6]; n_terms];
        let mut lambda = vec![f64::INFINITY; n_terms];
        let mut t_acc = BoundedDd::ZERO;
        // suffix_{i+1} = max over both sums of sum_{i' > i} (|c_i'| + e_i'), rounded up
        let (mut su, mut sd) = (0.0f64, 0.0f64);
        for i in (0..n_terms).rev() {
            let suffix = su.max(sd) * (1.0 + 1.0 / (1u64 << 40) as f64);
            if suffix > 0.0 {
                lambda[i] = ln_tol - ln_upper(suffix);
            }
            let c = if i % 2 == 0 { jt[2 * i + 2] } else { jt[2 * i + 2].neg() };
            t_acc = t_acc.add(c.mul_f64_p::<P>((i + 1) as f64));
            let (eu, et) = (err(c), err(t_acc));
            coef[i] = [c.v.hi, t_acc.v.hi, c.v.lo, t_acc.v.lo, eu, et];
            su = (su + c.mag() + eu) * (1.0 + 4.0 * U);
            sd = (sd + t_acc.mag() + et) * (1.0 + 4.0 * U);
        }
        CertifiedBessel {
            one_minus_j0: BoundedDd::ONE.sub(jt[0]),
            d_j1: d.mul_p::<P>(jt[1]),
            inv_a: BoundedDd::ONE.div_f64_p::<P>(a),
            coef,
            lambda,
            horner_tol,
            n_terms,
            tail0,
            tail2,
        }
    }

    /// `(u_w(x), du_w/dx)` with proven bounds, or `None` where the native path
    /// does not certify (`x/a > 25/7`). `a <= x` and finiteness are the caller's.
    pub(crate) fn eval_bounded(&self, a: f64, amp: f64, x: f64) -> Option<(Bounded, Bounded)> {
        #[cfg(target_arch = "x86_64")]
        if has_fma() {
            // SAFETY: the CPU supports FMA (checked just above).
            return unsafe { eval_fused(self, a, amp, x) };
        }
        self.eval_with::<Dekker>(a, amp, x)
    }

    /// [`CertifiedBessel::eval_bounded`] at every `x` of `xs` (each `>= a`, finite:
    /// the caller's) into `out[i]`, in one loop compiled for the CPU's fused
    /// multiply-add (no per-point dispatch). The indices where the native path
    /// does not certify (`x/a > 25/7`) are pushed to `refused` (their `out`
    /// entries are left as they were). `out.len() == xs.len()`.
    pub(crate) fn eval_bounded_batch(&self, a: f64, amp: f64, xs: &[f64], out: &mut [(Bounded, Bounded)], refused: &mut Vec<usize>) {
        #[cfg(target_arch = "x86_64")]
        if has_fma() {
            // SAFETY: the CPU supports FMA (checked just above).
            return unsafe { eval_batch_fused(self, a, amp, xs, out, refused) };
        }
        self.eval_batch_with::<Dekker>(a, amp, xs, out, refused)
    }

    #[inline(always)]
    pub(super) fn eval_batch_with<P: WaveKernel>(&self, a: f64, amp: f64, xs: &[f64], out: &mut [(Bounded, Bounded)], refused: &mut Vec<usize>) {
        for (i, (&x, o)) in xs.iter().zip(out.iter_mut()).enumerate() {
            match self.eval_with::<P>(a, amp, x) {
                Some(r) => *o = r,
                None => refused.push(i),
            }
        }
    }

    #[inline(always)]
    pub(super) fn eval_with<P: WaveKernel>(&self, a: f64, amp: f64, x: f64) -> Option<(Bounded, Bounded)> {
        let rm1 = BoundedDd { v: Dd::diff(x, a), e: 0.0 }; // x - a, exact
        let rp1 = BoundedDd { v: Dd::diff(x, -a), e: 0.0 }; // x + a, exact
        // off the critical path: (x + a)/(2a) and the gradient's factor 8A/a
        let half_ratio = rp1.mul_p::<P>(self.inv_a).mul_f64_p::<P>(0.5);
        let du_scale = self.inv_a.mul_f64_p::<P>(8.0 * amp);
        let t = div_p::<P>(rm1, rp1)?.sqrt_p::<P>()?;
        if !(t.mag() + t.e <= T_MAX) {
            return None;
        }
        let one_minus_t = BoundedDd::ONE.sub(t);
        // q = (1 - t)/(1 + t) = (1 - t)^2/(1 - t^2) = (1 - t)^2 (x + a)/(2a)
        let q = one_minus_t.mul_p::<P>(one_minus_t).mul_p::<P>(half_ratio);
        let q2 = q.mul_p::<P>(q);
        let arg = CompArg::new(q2);
        let acosh_r = neg_ln::<P>(q)?; // acosh(x/a) = -ln q
        let (top, rem) = self.horner_top(arg.xa);
        let (mut su, mut sdu) = P::horner2(arg, &self.coef[..=top]);
        su.e += rem + self.tail0;
        sdu.e += rem + 2.0 * self.tail2;
        let inner = self.one_minus_j0.add(self.d_j1.mul_p::<P>(acosh_r)).add(su.mul_p::<P>(q2).mul_f64_p::<P>(2.0));
        let u = inner.mul_f64_p::<P>(amp);
        // (1 - t)(1 + q) = 2q: du/dx = (4A/a)(1 - t)(1 + q) S = (8A/a) q S
        let du = sdu.mul_p::<P>(q).mul_p::<P>(du_scale);
        Some((u.finish()?, du.finish()?))
    }

    /// Where the Horner sums in `X = q^2` stop for `|X| <= xa`: the first power `i`
    /// with `(i + 1) ln_upper(xa) <= lambda_i`, which implies
    /// `xa^{i+1} suffix_{i+1} <= horner_tol` (the remainder bound, returned with `i`;
    /// the product `(i + 1) L`, `L < 0`, is shrunk by `2^-50` against its rounding),
    /// else all `N` terms (remainder 0).
    #[inline(always)]
    pub(super) fn horner_top(&self, xa: f64) -> (usize, f64) {
        let n = self.n_terms;
        if !(xa < 1.0 && xa > f64::MIN_POSITIVE) {
            return if xa == 0.0 { (0, 0.0) } else { (n - 1, 0.0) };
        }
        let l = ln_upper(xa) * (1.0 - 1.0 / (1u64 << 50) as f64);
        for (i, &lam) in self.lambda.iter().enumerate() {
            if (i + 1) as f64 * l <= lam {
                return (i, if i + 1 < n { self.horner_tol } else { 0.0 });
            }
        }
        (n - 1, 0.0)
    }
}

/// [`CertifiedBessel::native`] compiled with the `fma` target feature.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "fma")]
pub(super) unsafe fn native_fused(a: f64, zeta: f64) -> Option<CertifiedBessel> {
    CertifiedBessel::native::<crate::ball::Fused>(a, zeta)
}

/// [`CertifiedBessel::eval_bounded_batch`] compiled with the `fma` target feature.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "fma")]
pub(super) unsafe fn eval_batch_fused(c: &CertifiedBessel, a: f64, amp: f64, xs: &[f64], out: &mut [(Bounded, Bounded)], refused: &mut Vec<usize>) {
    c.eval_batch_with::<crate::ball::Fused>(a, amp, xs, out, refused)
}

/// [`CertifiedBessel::eval_with`] compiled with the `fma` target feature.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "fma")]
pub(super) unsafe fn eval_fused(c: &CertifiedBessel, a: f64, amp: f64, x: f64) -> Option<(Bounded, Bounded)> {
    c.eval_with::<crate::ball::Fused>(a, amp, x)
}

