//! The double-word kernels of the bounded wave path (module docs of
//! [`super`]): a certified `-ln q` by table and series, the compensated
//! two-sum Horner scheme over the interleaved coefficients (scalar with
//! Dekker's or fused products, and a two-lane SSE kernel with FMA), and cheap
//! f64 bounds of `ln`. Every routine returns its value with a proven bound
//! (error model in `crate::ball::dd_bounded`; Graillat, Langlois, Louvet 2009).

use rug::float::Round;
use rug::Float;

use crate::ball::{two_sum, Ball, BoundedDd, Dd, Dekker, ExactProduct, U};
use crate::special::exact_sub;

use super::GAMMA4;

/// Whether the CPU has a fused multiply-add (checked once; `std` caches it).
#[inline]
pub(super) fn has_fma() -> bool {
    #[cfg(target_arch = "x86_64")]
    {
        std::arch::is_x86_feature_detected!("fma")
    }
    #[cfg(not(target_arch = "x86_64"))]
    {
        false
    }
}

/// A certified ball as a double-double with its conversion error.
pub(super) fn tr_from_ball(b: &Ball) -> BoundedDd {
    let mid = b.mid();
    let hi = mid.to_f64();
    let rest = exact_sub(mid, &Float::with_val(53, hi));
    let lo = rest.to_f64();
    let rem = exact_sub(&rest, &Float::with_val(53, lo)).abs().to_f64_round(Round::Up);
    let e = (rem + b.rad_mag().to_f64_up()).next_up();
    BoundedDd { v: Dd { hi, lo }, e }
}

/// `num / den` in [`BoundedDd`] without the long division: with `den = H + L`
/// (a normalised double-double, `|L| <= u |H|`) and `eps = fl(L/H)`,
/// `num/den = (num/H) (1 - eps) + r`, `|r| <= (u^2 + eps^2/(1 + eps)) |num/H| <= 2.01 u^2 |num/H|`
/// (`|L/H - eps| <= u |eps| <= u^2`), so `num/H` ([`BoundedDd::div_f64_p`]) times
/// the double-double `1 - eps` carrying `3 u^2` gives `num/den~`; the error
/// `e_den` of the denominator adds `|num/den~| e_den/(|den~| - e_den)`.
/// Falls back to [`BoundedDd::div`] if `den` is not normalised.
#[inline(always)]
pub(super) fn div_p<P: ExactProduct>(num: BoundedDd, den: BoundedDd) -> Option<BoundedDd> {
    let (h, l) = (den.v.hi, den.v.lo);
    let eps = l / h;
    if !(eps.abs() <= U) || h == 0.0 {
        return num.div(den);
    }
    let low = den.mag() - den.e;
    if !(low > 0.0) {
        return None;
    }
    let corr = BoundedDd { v: Dd { hi: 1.0, lo: -eps }, e: 3.0 * U * U };
    let mut r = num.div_f64_p::<P>(h).mul_p::<P>(corr);
    if den.e > 0.0 {
        r.e += (r.mag() + r.e) * den.e / low;
    }
    Some(r)
}

/// The reduction table of [`neg_ln`] has the points `c_j = 1 + j/LN_TABLE_STEPS`, `j = 0..=64`.
pub(super) const LN_TABLE_STEPS: usize = 64;

/// Binades of `q` that [`neg_ln`] takes: `q in [2^-3, 2)` (`q >= 1/7` for `t <= T_MAX`).
pub(super) const LN_BINADES: usize = 4;

/// Largest `|f| = |m r_j - 1|` [`neg_ln`] takes: `|m - c_j| <= 1/128`, `c_j >= 1`
/// give `|m/c_j - 1| <= 1/128 = 0.0078125`, and `r_j = fl(1/c_j)` adds `< 2u`.
pub(super) const LN_F_MAX: f64 = 0.0079;

/// `ln(1 + f) = f + f^2 P(f)`, `P(f) = sum_{k=2}^{10} (-1)^{k+1} f^{k-2}/k`: the
/// coefficients `-1/2, 1/3, ..., -1/10`, each correctly rounded (relative error `<= u`).
pub(super) const LN_COEF: [f64; 9] =
    [-1.0 / 2.0, 1.0 / 3.0, -1.0 / 4.0, 1.0 / 5.0, -1.0 / 6.0, 1.0 / 7.0, -1.0 / 8.0, 1.0 / 9.0, -1.0 / 10.0];

/// Truncation of [`LN_COEF`] at `|f| <= LN_F_MAX`: `|f|^11/(11 (1 - |f|)) < 6.9e-25`
/// (a unit test recomputes it).
pub(super) const LN_TRUNC: f64 = 7.0e-25;

/// The reduction table of [`neg_ln`]: `r_j = fl(1/c_j)` and, for each binade
/// `q in [2^-b, 2^{1-b})`, `L_{b,j} = ln(2^-b / r_j)` as a double-double with
/// its error (MPFR at 192 bits, every operation correctly rounded, so the
/// 192-bit value is within `2^-185` of the exact one; then split: error
/// `<= |rest| + 2^-180`).
pub(super) struct LnTable {
    r: [f64; LN_TABLE_STEPS + 1],
    l: [[BoundedDd; LN_TABLE_STEPS + 1]; LN_BINADES],
}

pub(super) fn ln_table() -> &'static LnTable {
    static TABLE: std::sync::OnceLock<LnTable> = std::sync::OnceLock::new();
    TABLE.get_or_init(|| {
        let r: [f64; LN_TABLE_STEPS + 1] =
            std::array::from_fn(|j| 1.0 / (1.0 + j as f64 / LN_TABLE_STEPS as f64)); // c_j exact
        let ln2 = Float::with_val(192, rug::float::Constant::Log2);
        let l = std::array::from_fn(|b| {
            std::array::from_fn(|j| {
                let mut v = Float::with_val(192, r[j]).ln(); // ln r_j
                v += Float::with_val(192, &ln2 * b as u32); // + b ln 2
                let v = -v; // ln(2^-b / r_j)
                let hi = v.to_f64();
                let rest = Float::with_val(192, &v - hi);
                let lo = rest.to_f64();
                let rem = Float::with_val(192, &rest - lo).abs().to_f64_round(Round::Up);
                BoundedDd { v: Dd { hi, lo }, e: (rem + 6.5e-55).next_up() } // 2^-180 < 6.5e-55
            })
        });
        LnTable { r, l }
    })
}

/// `-ln(q) = acosh(x/a)` for `q in [1/8, 2)` with a proven bound (module docs,
/// "acosh"): `q = 2^-b m`, `m in [1, 2)`, `c_j` the table point nearest to `m`,
/// `f = m r_j - 1` as a double-double from one exact product (no division:
/// `p + pe = m.hi r_j`, `p - 1` exact by Sterbenz, `fl(m.lo r_j + pe)` off by
/// `<= 2.01 u (2u + 1.01u) < 6.1 u^2`), and
/// `ln q = L_{b,j} + f + f^2 P(f)`, the last term in f64 at `y = f.hi`: Horner
/// over 9 coefficients, two roundings a step (`gamma_16`, on `sum |c_k| |y|^k <= 0.5027`),
/// the coefficients' rounding (`u 0.5027`), `fl(fl(y^2) P~)` (`2.0001 u`):
/// together `<= 10 u y^2`; plus [`LN_TRUNC`]; plus the move from `y` to the exact
/// `f` (`|d/df (ln(1+f) - f)| = |f/(1+f)| <= 0.008`). `None` outside the table.
#[inline(always)]
pub(super) fn neg_ln<P: ExactProduct>(q: BoundedDd) -> Option<BoundedDd> {
    let (qh, ql) = (q.v.hi, q.v.lo);
    let bits = qh.to_bits();
    let b = 1023 - ((bits >> 52) & 0x7ff) as i64; // q.hi in [2^-b, 2^{1-b})
    if !(0..LN_BINADES as i64).contains(&b) || qh <= 0.0 {
        return None;
    }
    let scale = f64::from_bits(((1023 + b) as u64) << 52); // 2^b, exact scaling
    let (mh, ml) = (qh * scale, ql * scale);
    let j = ((mh - 1.0) * LN_TABLE_STEPS as f64).round() as usize; // 0..=64
    let table = ln_table();
    let r = table.r[j];
    let (p, pe) = P::two_prod(mh, r);
    let (fh, fl) = two_sum(p - 1.0, ml * r + pe);
    if !(fh.abs() <= LN_F_MAX) {
        return None;
    }
    let e_f = r * scale * q.e + 6.1 * U * U;
    let mut pv = LN_COEF[8];
    for &c in LN_COEF[..8].iter().rev() {
        pv = pv * fh + c;
    }
    let y2 = fh * fh;
    let g = y2 * pv;
    let e_g = 10.0 * U * y2 + LN_TRUNC + 0.008 * (fl.abs() + e_f);
    let f = BoundedDd { v: Dd { hi: fh, lo: fl }, e: e_f };
    let ln_q = table.l[b as usize][j].add(f.add(BoundedDd { v: Dd::from_f64(g), e: e_g }));
    Some(ln_q.neg())
}

/// The per-`x` constants of a compensated Horner step: the argument
/// `X = xh + xl` (a double-double) with its error `ex`, and the multipliers of
/// the rounding bound.
#[derive(Clone, Copy)]
pub(crate) struct CompArg {
    pub(super) xh: f64,
    pub(super) xl: f64,
    /// `|xh| + |xl| + ex`, which bounds `|X~|` and `|X|`.
    pub(super) xa: f64,
    /// `ex + gamma_4 (|xl| + 2.0001 u |xh|)`: multiplies `|h|` (the last term is
    /// the `u |p| + u |h'|` of the step, with `|p| + |h'| <= 2.0001 |h xh| + 1.0001 |c.hi|`;
    /// the `|c.hi|` part is folded into the stored coefficient error).
    pub(super) kh: f64,
    /// `ex + gamma_4 |xh| + |xl|`: multiplies `|l|`.
    pub(super) kl: f64,
}

impl CompArg {
    #[inline(always)]
    pub(super) fn new(x: BoundedDd) -> CompArg {
        let (xh, xl, ex) = (x.v.hi, x.v.lo, x.e);
        let kh = ex + GAMMA4 * (xl.abs() + 2.0001 * U * xh.abs());
        CompArg { xh, xl, xa: xh.abs() + xl.abs() + ex, kh, kl: ex + GAMMA4 * xh.abs() + xl.abs() }
    }
}

/// Both compensated Horner sums over `coef` (rows `[u.hi, T.hi, u.lo, T.lo, e_u, e_T]`,
/// highest power last) at the argument `x`, in one loop (module docs,
/// "Compensated Horner"). One step of an accumulator `h + l` forms
/// `p + pi = h xh` (exact product), `h' + sigma = p + c.hi` (exact sum) and
/// `l' = fl((pi + sigma) + (h xl + (l xh + c.lo)))`. Its error obeys
/// `eps' <= eps xa + |h| kh + |l| kl + e_c`; unrolled over the `top` steps,
/// `eps <= E + (H kh + L kl) G`, where `E` is the Horner sum of the `e_c` at `xa`
/// (run alongside, one multiply-add per step), `H`, `L` the largest `|h|`, `|l|`
/// over both sums and all steps (running maxima), and `G = sum_{k<top} xa^k
/// <= top max(1, xa)^top`. (`kh ~ u^2`, `kl ~ u`, `L ~ u H`: that second part is
/// `~ top u^2 H`, far below `E`.)
#[inline(always)]
pub(super) fn comp_horner2<P: ExactProduct>(x: CompArg, coef: &[[f64; 6]]) -> (BoundedDd, BoundedDd) {
    let Some((last, rest)) = coef.split_last() else {
        return (BoundedDd::exact(0.0), BoundedDd::exact(0.0)); // the empty sums
    };
    let (mut uh, mut ul, mut ue) = (last[0], last[2], last[4]);
    let (mut dh, mut dl, mut de) = (last[1], last[3], last[5]);
    let (mut hmax, mut lmax) = (0.0f64, 0.0f64);
    let big = |a: f64, b: f64| if a > b { a } else { b };
    for c in rest.iter().rev() {
        hmax = big(big(hmax, uh.abs()), dh.abs());
        lmax = big(big(lmax, ul.abs()), dl.abs());
        let (p, pi) = P::two_prod(uh, x.xh);
        let (h, sigma) = two_sum(p, c[0]);
        ul = ul * x.xh + ((pi + sigma) + (uh * x.xl + c[2]));
        uh = h;
        ue = ue * x.xa + c[4];
        let (p, pi) = P::two_prod(dh, x.xh);
        let (h, sigma) = two_sum(p, c[1]);
        dl = dl * x.xh + ((pi + sigma) + (dh * x.xl + c[3]));
        dh = h;
        de = de * x.xa + c[5];
    }
    horner2_finish(x, rest.len() as u32, hmax, lmax, [uh, ul, ue], [dh, dl, de])
}

/// The end of [`comp_horner2`]: both accumulators as bounded double-doubles,
/// with the `(H kh + L kl) G` part of the bound.
#[inline(always)]
pub(super) fn horner2_finish(x: CompArg, steps: u32, hmax: f64, lmax: f64, u: [f64; 3], du: [f64; 3]) -> (BoundedDd, BoundedDd) {
    let g = steps as f64 * if x.xa <= 1.0 { 1.0 } else { pow_int(x.xa, steps) * (1.0 + 1.0 / (1u64 << 40) as f64) };
    let extra = (hmax * x.kh + lmax * x.kl) * g;
    let fin = |[h, l, e]: [f64; 3]| {
        let (hi, lo) = two_sum(h, l);
        BoundedDd { v: Dd { hi, lo }, e: e + extra }
    };
    (fin(u), fin(du))
}

/// [`comp_horner2`] with both sums in the two lanes of one SSE register
/// (`[u, T]`), fused multiply-adds for the exact products and the low parts
/// (`l' = fl(l xh + fl(fl(pi + sigma) + fl(h xl + c.lo)))`: every term passes at
/// most three roundings, within the `gamma_4` of the bound). Same bound.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "fma")]
#[inline]
pub(super) fn comp_horner2_fma(x: CompArg, coef: &[[f64; 6]]) -> (BoundedDd, BoundedDd) {
    use std::arch::x86_64::*;
    let Some((last, rest)) = coef.split_last() else {
        return (BoundedDd::exact(0.0), BoundedDd::exact(0.0)); // the empty sums
    };
    // SAFETY: each row has 6 f64; the unaligned loads read rows [0..2], [2..4], [4..6].
    let load = |row: &[f64; 6], k: usize| unsafe { _mm_loadu_pd(row.as_ptr().add(k)) };
    let (mut h, mut l, mut e) = (load(last, 0), load(last, 2), load(last, 4));
    let (xh, xl, xa) = (_mm_set1_pd(x.xh), _mm_set1_pd(x.xl), _mm_set1_pd(x.xa));
    let sign = _mm_set1_pd(-0.0);
    let (mut hmax, mut lmax) = (_mm_setzero_pd(), _mm_setzero_pd());
    for c in rest.iter().rev() {
        hmax = _mm_max_pd(hmax, _mm_andnot_pd(sign, h));
        lmax = _mm_max_pd(lmax, _mm_andnot_pd(sign, l));
        let (ch, cl, ce) = (load(c, 0), load(c, 2), load(c, 4));
        let p = _mm_mul_pd(h, xh);
        let pi = _mm_fmsub_pd(h, xh, p);
        let s = _mm_add_pd(p, ch);
        let bb = _mm_sub_pd(s, p);
        let sigma = _mm_add_pd(_mm_sub_pd(p, _mm_sub_pd(s, bb)), _mm_sub_pd(ch, bb));
        l = _mm_fmadd_pd(l, xh, _mm_add_pd(_mm_add_pd(pi, sigma), _mm_fmadd_pd(h, xl, cl)));
        h = s;
        e = _mm_fmadd_pd(e, xa, ce);
    }
    let mut out = [[0.0f64; 2]; 5];
    // SAFETY: five 2-lane stores into arrays of two f64.
    unsafe {
        _mm_storeu_pd(out[0].as_mut_ptr(), h);
        _mm_storeu_pd(out[1].as_mut_ptr(), l);
        _mm_storeu_pd(out[2].as_mut_ptr(), e);
        _mm_storeu_pd(out[3].as_mut_ptr(), hmax);
        _mm_storeu_pd(out[4].as_mut_ptr(), lmax);
    }
    let hm = out[3][0].max(out[3][1]);
    let lm = out[4][0].max(out[4][1]);
    horner2_finish(x, rest.len() as u32, hm, lm, [out[0][0], out[1][0], out[2][0]], [out[0][1], out[1][1], out[2][1]])
}

/// The product strategy of the per-`x` path and its Horner kernel: scalar
/// for Dekker's products, the two-lane SSE kernel with fused multiply-adds.
pub(crate) trait WaveKernel: ExactProduct + Sized {
    fn horner2(x: CompArg, coef: &[[f64; 6]]) -> (BoundedDd, BoundedDd) {
        comp_horner2::<Self>(x, coef)
    }
}

impl WaveKernel for Dekker {}

impl WaveKernel for crate::ball::Fused {
    #[inline(always)]
    fn horner2(x: CompArg, coef: &[[f64; 6]]) -> (BoundedDd, BoundedDd) {
        #[cfg(target_arch = "x86_64")]
        if has_fma() {
            // SAFETY: the CPU supports FMA (checked just above).
            return unsafe { comp_horner2_fma(x, coef) };
        }
        comp_horner2::<Self>(x, coef)
    }
}

/// `v = 2^e m`, `m in [1, 2)`, for a positive normal `v`.
#[inline(always)]
pub(super) fn exponent_mantissa(v: f64) -> (f64, f64) {
    let bits = v.to_bits();
    let exp = ((bits >> 52) & 0x7ff) as f64 - 1023.0;
    (exp, f64::from_bits((bits & ((1u64 << 52) - 1)) | (1023u64 << 52)))
}

/// Slack on the cheap logarithm bounds below: covers their own f64 roundings
/// (`|e| <= 1100` times `ln 2`'s rounding, a few `u` on values below 800).
pub(super) const LN_BOUND_SLACK: f64 = 1e-9;

/// A lower bound of `ln(v)` for a positive normal `v` (`log2(m) >= m - 1` on
/// `[1, 2)`, concavity; within 0.06 of the true value).
#[inline(always)]
pub(super) fn ln_lower(v: f64) -> f64 {
    let (exp, m) = exponent_mantissa(v);
    (exp + m - 1.0) * std::f64::consts::LN_2 - LN_BOUND_SLACK
}

/// An upper bound of `ln(v)` for a positive normal `v`: `ln m` lies below its
/// tangent at `3/2`, `ln(3/2) + (m - 3/2)/(3/2)` (within 0.072 on `[1, 2)`).
#[inline(always)]
pub(super) fn ln_upper(v: f64) -> f64 {
    let (exp, m) = exponent_mantissa(v);
    exp * std::f64::consts::LN_2 + 0.405_465_108_108_164_4 + (m - 1.5) * (2.0 / 3.0) + LN_BOUND_SLACK
}

/// `x^n` by binary powering (`n <= 127`: at most 14 roundings).
#[inline(always)]
pub(super) fn pow_int(x: f64, mut n: u32) -> f64 {
    let (mut acc, mut base) = (1.0f64, x);
    while n > 0 {
        if n & 1 == 1 {
            acc *= base;
        }
        n >>= 1;
        base *= base;
    }
    acc
}
