//! Gauss-Legendre nodes and weights as certified balls, cached per degree and precision.
//!
//! # Method
//!
//! The `n` nodes are the roots of the Legendre polynomial `P_n` (DLMF 18.3), found
//! and enclosed in three steps:
//!
//! 1. **Start.** Tricomi's approximation `x_k ~ cos(pi (4k - 1)/(4n + 2))`
//!    (DLMF 18.16.6 with the first correction term), refined by Newton's method in
//!    f64 and then in double-double (about 95 bits).
//! 2. **Refine.** Chebyshev's step in MPFR, `x <- x - t - (P_n''/(2 P_n')) t^2`, `t =
//!    P_n(x)/P_n'(x)`, with `P_n''/P_n' = (2x - n(n+1) t)/(1 - x^2)` from Legendre's
//!    equation (so it costs what Newton's step does and triples the bits, less about `4
//!    log2 n`), the precisions planned top-down by thirds up to about a third of the
//!    bits to certify ([`newton_bits`]). Where the precision fits 8 limbs, `P_n/P_n'`
//!    comes from the scaled monic recurrence `S_0 = 1`, `S_1 = 2x`, `S_{k+1} = 2x S_k -
//!    g_k S_{k-1}`, `g_k = 4k^2/(4k^2 - 1)` (DLMF 18.9.1 with `S_k = 2^k P_k / kappa_k`,
//!    `kappa_k` the leading coefficient of `P_k`) in the fixed-point format of
//!    `ball/fixed`, and `P_n/P_n' = (1 - x^2) S_n / (n (2n/(2n-1) S_{n-1} - x S_n))`
//!    (DLMF 18.9.18); above, from the series at 0 of `legendre_series.rs` (`O(n)` word
//!    operations and `O(n^(1/2))` full products, against the recurrence's `2n` full
//!    products). All of this is an estimate: the next step proves.
//! 3. **Certify.** One evaluation in ball arithmetic at the point `x` (an exact float,
//!    the refined iterate) gives balls containing `P_n(x)` and `P_n'(x)`; Legendre's
//!    equation `(1 - x^2) P_n'' = 2x P_n' - n(n+1) P_n` (DLMF 18.8.1) and its derivative
//!    `(1 - x^2) P_n''' = 4x P_n'' - (n(n+1) - 2) P_n'` give balls containing `P_n''(x)`
//!    and `P_n'''(x)`. `M_k = P_n^(k)(1) >= |P_n^(k)|` on `[-1, 1]` (`P_n^(k)` is
//!    `(2k-1)!!` times the Gegenbauer polynomial `C^(k+1/2)_(n-k)`, DLMF 18.9.19, and
//!    `|C^lambda_m(y)| <= C^lambda_m(1)` for `lambda > 0`, DLMF 18.14.4). A last step
//!    `x1 = x + delta` (a float; Chebyshev's step, of third order) is taken in this
//!    arithmetic: by Taylor's theorem to third order with the remainders bounded
//!    through `M_4`, balls `A`, `D` and `C` contain `P_n(x1)`, `P_n'(x1)` and
//!    `P_n''(x1)` (`certify_node`; where double-double leaves the iterate accurate
//!    enough, [`second_order_suffices`], Newton's step and Taylor's theorem to second
//!    order through `M_3`, with fewer ball operations). Take `eps >= |A|`, `d <= |D|`, `r >= 4 eps/d`, and
//!    `M = |C| + M_3 r >= |P_n''|` on `[x1 - r, x1 + r]`. Taylor's theorem gives `P_n(x1
//!    +- r) = P_n(x1) +- P_n'(x1) r + R`, `|R| <= M r^2/2`. When `M r^2 <= 4 eps`
//!    (checked with upper bounds), `|P_n(x1) + R| <= eps + 2 eps < 4 eps <= |P_n'(x1)|
//!    r`, so `P_n(x1 - r)` and `P_n(x1 + r)` have opposite signs: a root lies in `(x1 -
//!    r, x1 + r)`. The `ceil(n/2)` non-negative roots are all found this way in
//!    disjoint, ordered intervals (for odd `n` the root 0 is exact), and `P_n` has
//!    exactly `n` roots, symmetric about 0, so every node is enclosed. The weight `w = 2
//!    / ((1 - y^2) P_n'(y)^2)` (DLMF 3.5.19) at the root `y` is evaluated in ball
//!    arithmetic on the node's ball with `P_n'(y)` in `D +- M r` (the mean value
//!    theorem), so it encloses the true weight. Where the bound fails or leaves the
//!    node or the weight wider than planned (not seen; the tests ask that it never does
//!    for the integrator's degrees), the root is enclosed as before 2026-11-29 instead:
//!    by the signs of `P_n` at `x +- 2^-target`, both evaluated in ball arithmetic, and
//!    the weight from `P_n'` on that ball.
//!
//! The ball evaluations ([`Evaluation`]) use, where the certified precision fits the
//! 8 limbs of `ball/fixed` (up to about 510 bits), the Fourier form (DLMF 18.5.11,
//! `lambda = 1/2`): `P_n(cos theta) = sum_{k=0}^n c_k c_{n-k} cos((n - 2k) theta)`, `c_k
//! = (1/2)_k / k!`, and its derivative in `theta`, `P_n'(cos theta) = sum_k c_k c_{n-k}
//! (n - 2k) sin((n - 2k) theta) / sin theta`, with `e^{i theta} = x + i (1 -
//! x^2)^(1/2)` and the cosines and sines the real and imaginary parts of `w^n
//! conj(w)^(2k)`, formed in complex discs ([`Disc`]). The coefficients are positive and
//! sum to `P_n(1) = 1`, and a product of discs of modulus 1 adds their radii, so a
//! radius grows about linearly in `n`: `3 log2 n + 16` guard bits suffice
//! ([`precisions`]). The three-term recurrence in ball arithmetic grows radii by up to
//! `1 + sqrt 2` a step and would need `1.28 n + 40` guard bits. Above 8 limbs they use
//! the hypergeometric series at 0 with rectangular splitting (`legendre_series.rs`, as
//! Arb's `arb_hypgeom_legendre_p_ui_zero`), which loses about `n log2(|x| + (1 +
//! x^2)^(1/2))` bits to cancellation (carried as extra working bits) but costs `n`
//! word-size products and sums and `m - 1 + n/m` full products (`m ~ n^(1/2)`)
//! where the Fourier form costs `2n` full products.
//!
//! Cost: a node takes one ball evaluation at the certified precision and Chebyshev
//! steps at precisions that about triple up to a third of it (none at all for `prec`
//! up to about 100 bits, where double-double suffices). At 3353 bits, degree 430
//! (the rule of a 3333-bit integral), a rule took 0.41 s with the Fourier form and the
//! recurrence (2026-11-29 morning) and takes 0.066 s now (CPU time, `first_call rule
//! 430 3353`; docs/quadrature.md). Before 2026-11-29 it took four or five MPFR Newton
//! steps of five operations per degree up to the full precision and three Fourier
//! evaluations. Rules are cached for the life of the process ([`rule`]). C Arb
//! (`arb_hypgeom_legendre_p_ui_root`) also uses Newton steps with the precision
//! doubled and an interval Newton step at the end, with its own choice among the
//! recurrence, the series at 0 or 1 and the asymptotic expansion: see
//! docs/quadrature.md for the side-by-side first call.

use std::collections::HashMap;
use std::sync::{Arc, Mutex, OnceLock};

use rug::float::Round;
use rug::ops::AssignRound;
use rug::{Assign, Float};

use crate::ball::fixed::{self, limbs::Signed, limbs::MAX_LIMBS};
use crate::ball::{Ball, Dd, Mag};
use crate::error::{Error, Invariant, Result};

use super::legendre_series::{chebyshev_step, SeriesPlan};

/// A Gauss-Legendre rule on `[-1, 1]`: the non-negative nodes (in decreasing
/// order) and their weights; the negative nodes mirror them.
#[derive(Debug)]
pub(crate) struct Rule {
    /// `x_k >= 0`, `k = 0 .. ceil(n/2)`, largest first; for odd `n` the last is 0.
    pub nodes: Vec<Ball>,
    /// The matching weights.
    pub weights: Vec<Ball>,
}

type Cache = Mutex<HashMap<(usize, u32), Arc<Rule>>>;

fn cache() -> &'static Cache {
    static CACHE: OnceLock<Cache> = OnceLock::new();
    CACHE.get_or_init(|| Mutex::new(HashMap::new()))
}

/// The degree-`n` rule with node and weight balls at `prec` bits (cached).
pub(crate) fn rule(n: usize, prec: u32) -> Result<Arc<Rule>> {
    if let Ok(c) = cache().lock() {
        if let Some(r) = c.get(&(n, prec)) {
            return Ok(Arc::clone(r));
        }
    }
    let r = Arc::new(compute_rule(n, prec)?);
    if let Ok(mut c) = cache().lock() {
        c.insert((n, prec), Arc::clone(&r));
    }
    Ok(r)
}

/// `(P_n(X), P_{n-1}(X))` in ball arithmetic (encloses the values for every point of
/// `X`): the three-term recurrence, used before the Fourier form; the tests compare.
#[cfg(test)]
fn legendre_pair_ball(n: usize, x: &Ball) -> Result<(Ball, Ball)> {
    let p = x.prec();
    let mut prev = Ball::one(p);
    let mut cur = x.clone();
    for k in 1..n {
        let next = cur.mul(x).mul_i64((2 * k + 1) as i64).sub(&prev.mul_i64(k as i64)).div_i64((k + 1) as i64)?;
        prev = std::mem::replace(&mut cur, next);
    }
    Ok((cur, prev))
}

/// `c_j = (1/2)_j / j! = binom(2j, j) / 4^j`, `j = 0 ..= n`, as balls at `prec` bits
/// (`c_{j+1} = c_j (2j + 1)/(2j + 2)`; all positive, `sum_k c_k c_{n-k} = P_n(1) = 1`).
fn fourier_coefficients(n: usize, prec: u32) -> Result<Vec<Ball>> {
    let mut c = Vec::with_capacity(n + 1);
    c.push(Ball::one(prec));
    for j in 0..n {
        let next = c[j].mul_i64(2 * j as i64 + 1).div_i64(2 * j as i64 + 2)?;
        c.push(next);
    }
    Ok(c)
}

/// The weights of the Fourier form of degree `n` and of its derivative: `t_k = 2 c_k
/// c_{n-k}` and `u_k = (n - 2k) t_k` for `k < n/2`, and `t_{n/2} = c_{n/2}^2` (even `n`;
/// its `u` is 0), from `c` of [`fourier_coefficients`]; and, where the precision allows
/// the fixed-point loop ([`fourier_fixed`]), the same in its format.
struct FourierWeights {
    t: Vec<Ball>,
    u: Vec<Ball>,
    fixed: Option<FixedWeights>,
}

/// The weights `t_k` and `u_k 2^-s` (`n < 2^s`) as Q2 magnitudes of `l` limbs (all are
/// positive, at most 1), concatenated, and the sums the radii need (`u = 2^-F` the ulp):
/// `a = sum (rad + u) + 2u` per term (conversion and product) and `m = sum (|w| + u)`,
/// for `t` and for `u 2^-s`.
struct FixedWeights {
    l: usize,
    shift: i64,
    t: Vec<u64>,
    u: Vec<u64>,
    a_t: Mag,
    m_t: Mag,
    a_u: Mag,
    m_u: Mag,
}

impl FixedWeights {
    fn new(n: usize, t: &[Ball], u: &[Ball], prec: u32) -> Option<FixedWeights> {
        let l = fixed::limbs_for_bits(prec)?;
        let ulp = Mag::pow2(-(64 * l as i64 - 2));
        let shift = (usize::BITS - n.leading_zeros()) as i64; // n < 2^shift
        let convert = |w: &[Ball], e: i64| -> Option<(Vec<u64>, Mag, Mag)> {
            let mut limbs = Vec::with_capacity(w.len() * l);
            let (mut a, mut m) = (Mag::ZERO, Mag::ZERO);
            for b in w {
                limbs.extend(fixed::to_magnitude(b.mid(), e, l)?);
                a = a.add(b.rad_mag().mul_2exp(e).add(ulp.mul(Mag::from_f64(3.0))));
                m = m.add(b.abs_upper_mag().mul_2exp(e).add(ulp));
            }
            Some((limbs, a, m))
        };
        let (t, a_t, m_t) = convert(t, 0)?;
        let (u, a_u, m_u) = convert(u, -shift)?;
        Some(FixedWeights { l, shift, t, u, a_t, m_t, a_u, m_u })
    }
}

impl FourierWeights {
    fn new(n: usize, c: &[Ball]) -> FourierWeights {
        let mut t: Vec<Ball> = (0..n.div_ceil(2)).map(|k| c[k].mul(&c[n - k]).mul_pow2(1)).collect();
        let u: Vec<Ball> = t.iter().enumerate().map(|(k, tk)| tk.mul_i64((n - 2 * k) as i64)).collect();
        if n % 2 == 0 {
            t.push(c[n / 2].sqr());
        }
        let fixed = FixedWeights::new(n, &t, &u, c[0].prec());
        FourierWeights { t, u, fixed }
    }
}

/// How a rule evaluates `P_n` and `P_n'` in ball arithmetic: the Fourier form where its
/// loop runs in fixed point (up to 8 limbs), the series at 0 with rectangular splitting
/// above (`legendre_series.rs`; at 3353 bits and degree 430 about 30 times fewer limb
/// products a point).
enum Evaluation {
    Fourier(FourierWeights),
    Series(SeriesPlan),
}

impl Evaluation {
    /// The evaluation for degree `n` at `ext` bits.
    fn new(n: usize, ext: u32) -> Result<Evaluation> {
        if n >= 2 && fixed::limbs_for_bits(ext).is_none() {
            return Ok(Evaluation::Series(SeriesPlan::new(n, ext)?));
        }
        Ok(Evaluation::Fourier(FourierWeights::new(n, &fourier_coefficients(n, ext)?)))
    }

    /// `(P_n(x), P_n'(x))` for every point of the ball `x` in `(-1, 1)`, as balls at
    /// `x`'s precision.
    fn eval(&self, n: usize, x: &Ball) -> Result<(Ball, Ball)> {
        match self {
            Evaluation::Fourier(fw) => legendre_fourier(n, x, fw),
            Evaluation::Series(plan) => {
                let p = x.prec();
                let (v, d) = plan.eval(x, plan.working_prec(x.to_f64(), p))?;
                Ok((v.set_prec(p), d.set_prec(p)))
            }
        }
    }

    fn series(&self) -> Option<&SeriesPlan> {
        match self {
            Evaluation::Series(plan) => Some(plan),
            Evaluation::Fourier(_) => None,
        }
    }
}

/// `(P_n(x), P_n'(x))` for a ball `x` in `(-1, 1)` by the Fourier form (DLMF 18.5.11 with
/// `lambda = 1/2`): `P_n(cos theta) = sum_{k=0}^n c_k c_{n-k} cos((n - 2k) theta)` and
/// `P_n'(cos theta) = sum_k c_k c_{n-k} (n - 2k) sin((n - 2k) theta) / sin theta` (its
/// derivative in `theta` over `-sin theta`), with `e^{i theta} = w = x + i (1 -
/// x^2)^(1/2)` and `e^{i (n - 2k) theta} = w^n conj(w)^(2k)`. Every coefficient is
/// positive and every `|w^j| = 1`, so ball radii grow about linearly in `n`. The terms
/// `k` and `n - k` are equal and summed once, doubled in the weights.
fn legendre_fourier(n: usize, x: &Ball, fw: &FourierWeights) -> Result<(Ball, Ball)> {
    let p = x.prec();
    let s = Ball::one(p).sub(&x.sqr()).sqrt()?;
    let w = Disc::from_balls(x, &s);
    let step = w.conj().mul(&w.conj());
    let z = w.pow(n as u64);
    let (value, slope) = match fourier_fixed_dispatch(n, &z, &step, fw, p) {
        Some(vs) => vs,
        None => fourier_mpfr(n, z, &step, fw, p),
    };
    Ok((value, slope.div(&s)?))
}

/// The loop of [`legendre_fourier`] in MPFR: `(sum t_k Re z_k, sum u_k Im z_k)`, `z_k =
/// z step^k`.
fn fourier_mpfr(n: usize, mut z: Disc, step: &Disc, fw: &FourierWeights, p: u32) -> (Ball, Ball) {
    let mut value = FourierSum::new(p);
    let mut slope = FourierSum::new(p);
    let mut tmp = Disc::zero(p);
    let mut scratch = Float::new(p);
    for (t, u) in fw.t.iter().zip(&fw.u) {
        value.add(t, &z.re, z.rad);
        slope.add(u, &z.im, z.rad);
        tmp.assign_mul(&z, step, &mut scratch);
        std::mem::swap(&mut z, &mut tmp);
    }
    if n % 2 == 0 {
        value.add(&fw.t[n / 2], &z.re, z.rad);
    }
    (value.ball(), slope.ball())
}

/// The loop of [`legendre_fourier`] in the signed fixed-point format of
/// `crate::ball::fixed` (`L` limbs with `F = 64 L - 2 >= p` fractional bits, so no
/// coarser than the MPFR loop), where every value is below 4 in magnitude: the discs
/// `z_k` and the step enclose numbers of modulus 1, the weights `t_k` are at most 1 and
/// the slope's `u_k = (n - 2k) t_k` are scaled by `2^-s`, `n < 2^s` ([`FixedWeights`]).
/// `None` (then the MPFR loop runs) where the weights have no fixed-point form at `p`
/// bits or a radius could leave that range. With `u = 2^-F`:
///
/// - a disc's point converted from floats errs by less than `u` in each part: `2u`
///   more radius;
/// - a disc product `a b` of points `a_m, b_m` (`|a_m| <= 1 + r_a`, `|b_m| <= 1 + r_b`)
///   has each part from two truncated products (each below `1.01 u` off) and an exact
///   sum: the point errs by less than `sqrt 2 * 2.02 u < 3 u`, and the radius is `r_a
///   (|b_m| + r_b) + |a_m| r_b + 3 u`, as [`Disc::assign_mul`]. With the step's radius
///   `s`, `r_{k+1} <= q r_k + c`, `q = 1 + 3s`, `c = s + 3u`, so `r_k <= q^k (r_0 + k
///   c) <= (1 + 6 s k)(r_0 + k c) =: R` while `3 s k <= 1` (`e^x <= 1 + 2x` on `[0, 1]`):
///   one bound `R` of every radius, computed before the loop;
/// - a term `t v`, `t` in the ball `m +- rho` (times `2^e`), `v` the part of a number of
///   modulus 1 within `r <= R` of the disc's part `V` (exact in the format): with `T` the
///   truncated `m 2^e` (`|T - m 2^e| < u`) and the product truncated (`1.01 u`),
///   `|t 2^e v - T V| <= (rho 2^e + u) + (|m| 2^e + u) r + 2u`; summed over the terms,
///   at most `a + m R` ([`FixedWeights`]). The sums are exact, and `|T V| <= (|m| 2^e +
///   u)(1 + R)`: every partial sum is below `m (1 + R)`, asked to be below 2.
fn fourier_fixed_dispatch(n: usize, z: &Disc, step: &Disc, fw: &FourierWeights, p: u32) -> Option<(Ball, Ball)> {
    let fx = fw.fixed.as_ref()?;
    if fixed::limbs_for_bits(p)? != fx.l {
        return None;
    }
    match fx.l {
        1 => fourier_fixed::<1>(n, z, step, fx, p),
        2 => fourier_fixed::<2>(n, z, step, fx, p),
        3 => fourier_fixed::<3>(n, z, step, fx, p),
        4 => fourier_fixed::<4>(n, z, step, fx, p),
        5 => fourier_fixed::<5>(n, z, step, fx, p),
        6 => fourier_fixed::<6>(n, z, step, fx, p),
        7 => fourier_fixed::<7>(n, z, step, fx, p),
        _ => fourier_fixed::<8>(n, z, step, fx, p),
    }
}

/// The entry `k` of a concatenated table of `L`-limb magnitudes, as a positive value.
#[inline]
fn fixed_entry<const L: usize>(tab: &[u64], k: usize) -> Signed<L> {
    let mut mag = [0u64; L];
    mag.copy_from_slice(&tab[k * L..(k + 1) * L]);
    Signed { mag, neg: false }
}

/// The fixed-point sum times `2^e` as a ball at `p` bits with the radius `rad 2^e`.
fn fixed_ball<const L: usize>(sum: &Signed<L>, rad: Mag, e: i64, p: u32) -> Ball {
    let mut b = Ball::from_float(&(fixed::from_signed(sum) << e as i32), p);
    b.add_error_mag(rad.mul_2exp(e));
    b
}

fn fourier_fixed<const L: usize>(n: usize, z: &Disc, step: &Disc, fx: &FixedWeights, p: u32) -> Option<(Ball, Ball)> {
    let u = Mag::pow2(-(64 * L as i64 - 2));
    let one = Mag::from_f64(1.0);
    let (mut zr, mut zi) = (fixed::to_signed::<L>(&z.re, 0)?, fixed::to_signed::<L>(&z.im, 0)?);
    let (sr, si) = (fixed::to_signed::<L>(&step.re, 0)?, fixed::to_signed::<L>(&step.im, 0)?);
    let (r0, srad) = (z.rad.add(u.mul_2exp(1)), step.rad.add(u.mul_2exp(1)));
    // the bound R of every disc radius (see above)
    let k = Mag::from_f64(fx.t.len() as f64 / L as f64);
    let sk3 = srad.mul(k).mul(Mag::from_f64(3.0));
    if sk3.to_f64_up() > 1.0 {
        return None;
    }
    let c = srad.add(u.mul(Mag::from_f64(3.0)));
    let r_max = one.add(sk3.mul_2exp(1)).mul(r0.add(k.mul(c)));
    // |parts| <= 1 + R < 1.5: every product below 4; the partial sums below 2
    let one_r = one.add(r_max);
    if r_max.to_f64_up() >= 0.5 || fx.m_t.mul(one_r).to_f64_up() >= 2.0 || fx.m_u.mul(one_r).to_f64_up() >= 2.0 {
        return None;
    }
    let (mut value, mut slope) = (Signed::<L>::ZERO, Signed::<L>::ZERO);
    let half = fx.u.len() / L;
    for j in 0..half {
        value = value.add(&fixed_entry::<L>(&fx.t, j).mul(&zr));
        slope = slope.add(&fixed_entry::<L>(&fx.u, j).mul(&zi));
        let re = zr.mul(&sr).sub(&zi.mul(&si));
        let im = zr.mul(&si).add(&zi.mul(&sr));
        (zr, zi) = (re, im);
    }
    if n % 2 == 0 {
        value = value.add(&fixed_entry::<L>(&fx.t, half).mul(&zr));
    }
    let value_rad = fx.a_t.add(fx.m_t.mul(r_max));
    let slope_rad = fx.a_u.add(fx.m_u.mul(r_max));
    Some((fixed_ball(&value, value_rad, 0, p), fixed_ball(&slope, slope_rad, fx.shift, p)))
}

/// `sum_k t_k v_k` accumulated in a float with a radius, `v_k` the real or imaginary
/// part of a disc `z_k` that encloses a number of modulus 1, so `|v_k| <= 1` and `|mid
/// v_k| <= 1 + r_k`: a term adds `rad(t) (1 + r) + |mid(t)| r` (the ball and disc
/// radii), `2^-p |mid(t)| (1 + r)` (the product rounded to nearest, `u = 2^-p`) and
/// `2^-p` times a bound of the new sum (the addition rounded); the sum is at most
/// `bound`, the running `sum |t| (1 + r)`, up to the roundings, and `2 bound` covers
/// those.
struct FourierSum {
    mid: Float,
    prod: Float,
    rad: Mag,
    bound: Mag,
}

impl FourierSum {
    fn new(p: u32) -> FourierSum {
        FourierSum { mid: Float::new(p), prod: Float::new(p), rad: Mag::ZERO, bound: Mag::ZERO }
    }

    fn add(&mut self, t: &Ball, v: &Float, r: Mag) {
        let p = self.mid.prec() as i64;
        let one_r = Mag::from_f64(1.0).add(r);
        let t_mag = t.abs_upper_mag();
        self.prod.assign(t.mid() * v);
        self.mid += &self.prod;
        let term_up = t_mag.mul(one_r);
        self.bound = self.bound.add(term_up);
        let propagated = t.rad_mag().mul(one_r).add(t_mag.mul(r));
        let rounding = term_up.add(self.bound.mul_2exp(1)).mul_2exp(-p);
        self.rad = self.rad.add(propagated).add(rounding);
    }

    fn ball(&self) -> Ball {
        let mut b = Ball::from_float(&self.mid, self.mid.prec());
        b.add_error_mag(self.rad);
        b
    }
}

/// A complex disc: the point `re + i im` (floats) and the radius `rad`. Every disc here
/// encloses a number of modulus 1 (`w = e^{i theta}`, its conjugate, their powers and
/// products), so its point has modulus at most `1 + rad`. A product of such discs has a
/// radius about the sum of theirs (a rectangle's radii would grow by up to `sqrt 2` a
/// product). Products are formed in place.
struct Disc {
    re: Float,
    im: Float,
    rad: Mag,
}

impl Disc {
    fn zero(p: u32) -> Disc {
        Disc { re: Float::new(p), im: Float::new(p), rad: Mag::ZERO }
    }

    fn from_balls(re: &Ball, im: &Ball) -> Disc {
        Disc { re: re.mid().clone(), im: im.mid().clone(), rad: re.rad_mag().add(im.rad_mag()) }
    }

    fn conj(&self) -> Disc {
        Disc { re: self.re.clone(), im: Float::with_val(self.im.prec(), -&self.im), rad: self.rad }
    }

    fn mul(&self, o: &Disc) -> Disc {
        let mut d = Disc::zero(self.re.prec());
        let mut scratch = Float::new(self.re.prec());
        d.assign_mul(self, o, &mut scratch);
        d
    }

    /// `self = a b`: `|a b - a_m b_m| <= r_a (|b_m| + r_b) + |a_m| r_b`, and the point
    /// `a_m b_m` rounded to nearest, each part from two products and a sum, so that each
    /// part errs by at most `3 u |a_m| |b_m|` (`u = 2^-prec`): `2^(3 - prec) |a_m| |b_m|`
    /// covers both. `|a_m| <= 1 + r_a`, `|b_m| <= 1 + r_b` (the discs enclose numbers of
    /// modulus 1). `t` is scratch space.
    fn assign_mul(&mut self, a: &Disc, b: &Disc, t: &mut Float) {
        let p = self.re.prec();
        let (ma, mb) = (Mag::from_f64(1.0).add(a.rad), Mag::from_f64(1.0).add(b.rad));
        self.re.assign(&a.re * &b.re);
        t.assign(&a.im * &b.im);
        self.re -= &*t;
        self.im.assign(&a.re * &b.im);
        t.assign(&a.im * &b.re);
        self.im += &*t;
        let rounding = ma.mul(mb).mul_2exp(3 - p as i64);
        self.rad = a.rad.mul(mb.add(b.rad)).add(ma.mul(b.rad)).add(rounding);
    }

    fn pow(&self, mut e: u64) -> Disc {
        let p = self.re.prec();
        let mut result = Disc { re: Float::with_val(p, 1), im: Float::new(p), rad: Mag::ZERO };
        let mut base = Disc { re: self.re.clone(), im: self.im.clone(), rad: self.rad };
        while e > 0 {
            if e & 1 == 1 {
                result = result.mul(&base);
            }
            e >>= 1;
            if e > 0 {
                base = base.mul(&base);
            }
        }
        result
    }
}

/// The coefficients of the scaled monic recurrence `S_{k+1} = 2x S_k - g_k S_{k-1}`,
/// `g_k = 4k^2/(4k^2 - 1)` (`g[0]` unused), and `2n/(2n - 1)`, in double-double and
/// in MPFR at `prec` bits: estimates for Newton's method (the certificate does not
/// use them).
struct Recurrence {
    n: usize,
    g_dd: Vec<Dd>,
    g: Vec<Float>,
    c_dd: Dd,
    c: Float,
    /// `g_k` as Q2 magnitudes of `MAX_LIMBS` limbs, concatenated (a format of `L` limbs
    /// reads the top `L` of each), for [`Recurrence::step_fixed`].
    g_fixed: Vec<u64>,
    /// `S_k 2^-scale < 1/2` for `k <= n` (`|S_k| <= (pi k)^(1/2)` up to a few percent:
    /// `S_k = 4^k (k!)^2 / (2k)! P_k`, DLMF 5.11.7, `|P_k| <= 1`).
    scale: i64,
}

impl Recurrence {
    fn new(n: usize, prec: u32) -> Recurrence {
        let ratio = |k: usize| (4.0 * (k * k) as f64, 4.0 * (k * k) as f64 - 1.0);
        let g_dd = (0..n).map(|k| if k == 0 { Dd::from_f64(0.0) } else { Dd::from_f64(ratio(k).0) / Dd::from_f64(ratio(k).1) }).collect();
        let g: Vec<Float> = (0..n)
            .map(|k| if k == 0 { Float::new(prec) } else { Float::with_val(prec, ratio(k).0) / ratio(k).1 })
            .collect();
        let nf = n as f64;
        let g_fixed = g.iter().flat_map(|gk: &Float| fixed::to_magnitude(gk, 0, MAX_LIMBS).unwrap_or_else(|| vec![0; MAX_LIMBS])).collect();
        let scale = ((std::f64::consts::PI * nf).sqrt() * 1.1 + 1.0).log2().ceil() as i64 + 1;
        Recurrence {
            n,
            g_dd,
            g,
            c_dd: Dd::from_f64(2.0 * nf) / Dd::from_f64(2.0 * nf - 1.0),
            c: Float::with_val(prec, 2.0 * nf) / (2.0 * nf - 1.0),
            g_fixed,
            scale,
        }
    }

    /// [`Recurrence::step`] with the recurrence in the signed fixed-point format of
    /// `crate::ball::fixed` (`L` limbs, at least `scale + log2 n + 8` bits beyond `x`'s
    /// precision for the truncations and the scaling): `None` where that needs more
    /// than `MAX_LIMBS` limbs or `x` does not fit. An estimate, as the MPFR step.
    fn step_fixed(&self, x: &mut Float) -> Option<()> {
        let bits = x.prec() + self.scale as u32 + (usize::BITS - self.n.leading_zeros()) + 8;
        match fixed::limbs_for_bits(bits)? {
            1 => self.step_fixed_l::<1>(x),
            2 => self.step_fixed_l::<2>(x),
            3 => self.step_fixed_l::<3>(x),
            4 => self.step_fixed_l::<4>(x),
            5 => self.step_fixed_l::<5>(x),
            6 => self.step_fixed_l::<6>(x),
            7 => self.step_fixed_l::<7>(x),
            _ => self.step_fixed_l::<8>(x),
        }
    }

    fn step_fixed_l<const L: usize>(&self, x: &mut Float) -> Option<()> {
        let x2 = fixed::to_signed::<L>(x, 1)?;
        let mut prev = fixed::to_signed::<L>(&Float::with_val(64, 1), -self.scale)?;
        let mut cur = x2.mul(&prev);
        for k in 1..self.n {
            let mut g = Signed::<L> { mag: [0; L], neg: false };
            g.mag.copy_from_slice(&self.g_fixed[k * MAX_LIMBS + MAX_LIMBS - L..(k + 1) * MAX_LIMBS]);
            let next = x2.mul(&cur).sub(&g.mul(&prev));
            prev = cur;
            cur = next;
        }
        self.correct(x, &fixed::from_signed(&cur), &fixed::from_signed(&prev));
        Some(())
    }

    /// Chebyshev's step ([`chebyshev_step`]) from `S_n` and `S_{n-1}` (or the same times
    /// one power of two): `P_n(x)/P_n'(x) = (1 - x^2) S_n / (n (c S_{n-1} - x S_n))`.
    fn correct(&self, x: &mut Float, cur: &Float, prev: &Float) {
        let q = x.prec();
        let one_minus = Float::with_val(q, 1) - Float::with_val(q, x.square_ref());
        let den = Float::with_val(q, prev.mul_sub_mul_ref(&self.c, x, cur)) * self.n as u32;
        let num = Float::with_val(q, &one_minus * cur);
        chebyshev_step(x, &(num / den), &one_minus, self.n);
    }

    /// The Newton correction `P_n(x)/P_n'(x)` in f64 (the recurrence's coefficients
    /// rounded to f64: no division a degree).
    fn step_f64(&self, x: f64) -> f64 {
        let x2 = x + x;
        let (mut prev, mut cur) = (1.0, x2);
        for g in &self.g_dd[1..] {
            let next = x2 * cur - g.hi * prev;
            prev = cur;
            cur = next;
        }
        (1.0 - x * x) * cur / ((self.c_dd.hi * prev - x * cur) * self.n as f64)
    }

    /// The Newton correction `P_n(x)/P_n'(x)` in double-double.
    fn step_dd(&self, x: Dd) -> Dd {
        let x2 = x + x;
        let (mut prev, mut cur) = (Dd::from_f64(1.0), x2);
        for g in &self.g_dd[1..] {
            let next = x2 * cur - *g * prev;
            prev = cur;
            cur = next;
        }
        let one_minus = Dd::from_f64(1.0) - x * x;
        (one_minus * cur) / ((self.c_dd * prev - x * cur).mul_f64(self.n as f64))
    }

    /// One Newton step in MPFR at `x`'s precision: `x <- x - P_n(x)/P_n'(x)`.
    fn step(&self, x: &mut Float) {
        if self.step_fixed(x).is_some() {
            return;
        }
        let q = x.prec();
        let x2 = Float::with_val(q, &*x * 2u32);
        let mut prev = Float::with_val(q, 1);
        let mut cur = x2.clone();
        let mut t = Float::new(q);
        let mut u = Float::new(q);
        for g in &self.g[1..] {
            // two products and a difference: faster than one `mpfr_fmms` at these sizes
            t.assign(&cur * &x2);
            u.assign(g * &prev);
            t -= &u;
            std::mem::swap(&mut prev, &mut cur);
            std::mem::swap(&mut cur, &mut t);
        }
        self.correct(x, &cur, &prev);
    }
}

/// The root of `P_n` near `x0` (Tricomi's start), by Newton's method in f64, in
/// double-double and in MPFR with the precision about doubled a step, to about
/// `prec` bits (an estimate: [`certify_node`] proves).
fn newton_root(rec: &Recurrence, series: Option<&SeriesPlan>, x0: f64, prec: u32) -> Float {
    let n = rec.n;
    let mut x = x0;
    // f64 until a step is below 2^-33 relative (the error after it about 2^-50: the
    // two double-double steps then reach their precision)
    for _ in 0..8 {
        let step = rec.step_f64(x);
        x -= step;
        if step.abs() <= 1e-10 * x.abs().max(1e-300) {
            break;
        }
    }
    let mut xd = Dd::from_f64(x);
    for _ in 0..2 {
        xd = xd - rec.step_dd(xd);
    }
    // about 95 correct bits now; a step from `a` correct bits gives about `3a - 4 log2
    // n` (Chebyshev's step converges cubically, `(P_n''/P_n')^2` up to about `n^4`)
    let loss = 4 * (usize::BITS - n.leading_zeros()) + 8;
    let mut xf = Float::with_val(prec.max(106), xd.hi);
    xf += xd.lo;
    // The precisions top-down (as Arb's `legendre_p_ui_root`): a step at `q` bits from
    // `a` correct ones gives `min(q - 8, 3a - loss)`, so the level below `q` is `(q - 8 +
    // loss)/3 + 8`, down to what double-double gave.
    let mut levels = Vec::new();
    if prec > 90 {
        levels.push(prec + 8);
        loop {
            let need = (levels[levels.len() - 1] - 8 + loss).div_ceil(3);
            if need <= 90 {
                break;
            }
            levels.push(need + 8);
        }
    }
    for &q in levels.iter().rev() {
        xf.set_prec_round(q, Round::Nearest);
        // the recurrence in fixed point where it fits, else the series (when the rule
        // evaluates by it), else the recurrence in MPFR
        if rec.step_fixed(&mut xf).is_none() {
            match series {
                Some(plan) => plan.newton_step(&mut xf, q),
                None => rec.step(&mut xf),
            }
        }
    }
    // `prec` bits, so that the certificate's precision holds `x` exactly
    xf.set_prec_round(prec, Round::Nearest);
    xf
}

/// Sign of a ball that excludes zero: `Some(true)` positive, `Some(false)` negative.
fn strict_sign(b: &Ball) -> Option<bool> {
    if b.is_positive() {
        Some(true)
    } else if b.is_negative() {
        Some(false)
    } else {
        None
    }
}

/// Extra bits that cover the growth of ball radii through the three-term
/// recurrence: a radius grows at most by the larger root of `t^2 = 2|x| t + 1`,
/// `1 + sqrt(2) < 2^1.28`, a step for `|x| <= 1`. The recurrence itself is stable
/// (the radius growth is an overestimate), so these bits only keep the balls tight.
#[cfg(test)]
fn recurrence_guard(n: usize) -> u32 {
    (1.28 * n as f64).ceil() as u32 + 40
}

/// The precisions of a rule of degree `n` for `prec`-bit nodes and weights: Newton's
/// iterate to `target` bits, and the Fourier form evaluated at `ext` bits (`L = log2
/// n`). The node's radius is then about `4 (2^-target + rad P_n(x) / |P_n'(x)|)`, the
/// ball of `P_n(x)` about `n 2^-ext` wide; `P_n'(x)` is a sum of terms up to `n` over
/// `sin theta >= 1/n`, about `n^3 2^-ext` wide against `|P_n'(x)| >= 0.8 n^(1/2)` at a
/// root; and the weight's relative radius is that of `P_n'` plus about `|P_n''/P_n'|
/// r <= n^2 r`. Both are about `2^-(prec + 8)`: rounded to `prec` bits, the nodes and
/// weights lose nothing more (the test `every_node_is_certified_by_the_taylor_bound`
/// checks the radii).
fn precisions(n: usize, prec: u32) -> (u32, u32) {
    let l = usize::BITS - n.leading_zeros();
    (prec + 2 * l + 12, prec + 3 * l + 16)
}

/// The bits of Newton's iterate before the certificate's own step: where
/// [`second_order_suffices`], what Newton's step there asks; else that step is of
/// third order (method block, step 3), and its Taylor remainders, through `M_4 =
/// P_n''''(1) ~ 2^(8 L - 8.6)`, ask that `M_4 delta^3/6` stay below `2^-(prec + 6)`
/// times `|P_n'| >= 0.8 n^(1/2)` (`L = log2 n`, rounded up).
fn newton_bits(n: usize, prec: u32) -> u32 {
    let l = usize::BITS - n.leading_zeros();
    if second_order_suffices(n, prec) {
        return (prec + 6 * l + 17) / 2;
    }
    (prec + 8 * l + 20) / 3
}

/// Whether the certificate's Newton step (second order, remainders through `M_3`)
/// suffices for Newton's iterate as double-double leaves it (about 90 bits): the weight
/// asks that `M_3 delta^2/|P_n'| ~ 2^(5.5 L - 6) delta^2` stay below `2^-(prec + 6)`.
/// Then the third-order step, which needs fewer bits of the iterate but more ball
/// operations, would save no MPFR step: up to `164 - 6 L` bits (`L = log2 n` rounded
/// up), so 128 bits to degree 63, 110 to degree 511: the rules of 64-bit integrals.
fn second_order_suffices(n: usize, prec: u32) -> bool {
    let l = usize::BITS - n.leading_zeros();
    (prec + 6 * l + 17) / 2 <= 90
}

/// `P_n^(k)(1) = (n - k + 1) ... (n + k) / (2^k k!)`, rounded up: the largest `|P_n^(k)|`
/// on `[-1, 1]` (`P_n^(k)` is `(2k-1)!!` times the Gegenbauer polynomial
/// `C^(k+1/2)_(n-k)`, DLMF 18.9.19, and `|C^lambda_m| <= C^lambda_m(1)` there for
/// `lambda > 0`, DLMF 18.14.4).
fn derivative_bound_at_one(n: usize, k: usize) -> Mag {
    let mut m = Mag::from_f64(1.0);
    for j in 0..2 * k {
        // a factor n + k - j <= 0 (n < k) makes the derivative 0: the bound 0 holds
        m = m.mul(Mag::from_f64((n + k).saturating_sub(j) as f64));
    }
    for j in 1..=k {
        m = m.div(Mag::from_f64((2 * j) as f64));
    }
    m
}

fn compute_rule(n: usize, prec: u32) -> Result<Rule> {
    let mut fallbacks = 0;
    build_rule(n, prec, &mut fallbacks)
}

/// [`compute_rule`], counting the nodes certified by the fallback.
fn build_rule(n: usize, prec: u32, fallbacks: &mut usize) -> Result<Rule> {
    if n == 0 {
        return Err(Error::Internal { what: "Gauss-Legendre rule of degree 0".into() });
    }
    let half = n.div_ceil(2);
    let (target, ext) = precisions(n, prec);
    let ev = Evaluation::new(n, ext)?;
    let rec = Recurrence::new(n, target + 8);
    let mut nodes = Vec::with_capacity(half);
    let mut weights = Vec::with_capacity(half);
    let nf = n as f64;
    let mut prev_low: Option<Float> = None;
    for k in 1..=half {
        let exact_zero = n % 2 == 1 && k == half;
        let (node, w) = if exact_zero {
            let zero = Ball::zero(ext);
            let (_, d) = ev.eval(n, &zero)?;
            (zero, Ball::from_i64(2, ext).div(&d.sqr())?)
        } else {
            let theta = std::f64::consts::PI * (4.0 * k as f64 - 1.0) / (4.0 * nf + 2.0);
            let x0 = (1.0 - (nf - 1.0) / (8.0 * nf * nf * nf)) * theta.cos();
            let x = newton_root(&rec, ev.series(), x0, newton_bits(n, prec));
            match certify_node(n, &x, prec, &ev)? {
                Some(nw) => nw,
                None => {
                    *fallbacks += 1;
                    certify_node_by_signs(n, &newton_root(&rec, ev.series(), x0, target + 4), ext, target, &ev)?
                }
            }
        };
        // Disjoint and ordered (largest first), all inside (0, 1).
        let (lo, hi) = (node.lower(), node.upper());
        if hi >= 1 || (!exact_zero && lo <= 0) {
            return Err(Error::Invariant(Invariant::GaussLegendreNodeOutside { degree: n, node: k }));
        }
        if let Some(pl) = &prev_low {
            if hi >= *pl {
                return Err(Error::Invariant(Invariant::GaussLegendreNodesOverlap { degree: n, node: k }));
            }
        }
        prev_low = Some(lo);
        nodes.push(node.set_prec(prec));
        weights.push(w.set_prec(prec));
    }
    Ok(Rule { nodes, weights })
}

/// The weight `2 / ((1 - y^2) P_n'(y)^2)` for every `y` in `node`, `slope` a ball that
/// contains `P_n'(y)` for each of them.
fn weight(node: &Ball, slope: &Ball) -> Result<Ball> {
    let p = node.prec();
    let one_minus = Ball::one(p).sub(&node.sqr());
    Ball::from_i64(2, p).div(&one_minus.mul(&slope.sqr()))
}

/// The root of `P_n` next to `x` and its weight, from one evaluation of `P_n` and
/// `P_n'` at the point `x`, and a Newton step from there (method block, step 3);
/// `None` when the bound does not prove a root within `2^-(prec + 6)` of the new
/// point or leaves the weight wider than `2^-(prec + 4)` relative (then
/// [`certify_node_by_signs`]).
fn certify_node(n: usize, x: &Float, prec: u32, ev: &Evaluation) -> Result<Option<(Ball, Ball)>> {
    let ext = precisions(n, prec).1;
    let xb = Ball::from_float(x, ext);
    // x exact, and inside (-1, 1), where the bounds through M_3 hold
    if !xb.rad_mag().is_zero() || *x >= 1 || *x <= -1 {
        return Ok(None);
    }
    let (value, slope) = ev.eval(n, &xb)?;
    // P_n''(x) and P_n'''(x) from Legendre's equation (1 - x^2) P'' = 2x P' - n(n+1) P
    // (DLMF 18.8.1) and its derivative (1 - x^2) P''' = 4x P'' - (n(n+1) - 2) P', and
    // M_k >= |P_n^(k)| on [-1, 1]
    let m3 = derivative_bound_at_one(n, 3);
    let one_minus = Ball::one(ext).sub(&xb.sqr());
    let nn1 = (n * (n + 1)) as i64;
    let curvature = xb.mul(&slope).mul_pow2(1).sub(&value.mul_i64(nn1)).div(&one_minus)?;
    let (xb1, value, slope, curvature) = if second_order_suffices(n, prec) {
        // Newton's step x1 = x + delta, delta = -P/P', and Taylor's theorem to second
        // order with the remainders bounded by M_3: P(x1) in A + D delta +- (|P''(x)| +
        // M_3 |delta|) delta^2/2, P'(x1) in D + P'' delta +- M_3 delta^2/2, P''(x1) in
        // P'' +- M_3 |delta|
        let t = Float::with_val(ext, value.mid() / slope.mid());
        let xb1 = Ball::from_float(&Float::with_val(ext, x - &t), ext);
        let delta = xb1.sub(&xb);
        let dm = delta.abs_upper_mag();
        let half_dm2 = dm.mul(dm).mul_2exp(-1);
        let mut value = value.add(&slope.mul(&delta));
        value.add_error_mag(curvature.abs_upper_mag().add(m3.mul(dm)).mul(half_dm2));
        let mut slope = slope.add(&curvature.mul(&delta));
        slope.add_error_mag(m3.mul(half_dm2));
        let mut curvature = curvature;
        curvature.add_error_mag(m3.mul(dm));
        (xb1, value, slope, curvature)
    } else {
        // Chebyshev's step x1 = x + delta, delta = -t - P'' t^2/(2 P'), t = P/P' (the
        // root of the Taylor polynomial of degree 2, to third order), and Taylor's
        // theorem from x to x1 with the remainders bounded by M_4: P(x1) in A + D delta +
        // P'' delta^2/2 + P''' delta^3/6 +- M_4 delta^4/24, P'(x1) in D + P'' delta +
        // P''' delta^2/2 +- M_4 |delta|^3/6, P''(x1) in P'' + P''' delta +- M_4
        // delta^2/2
        let m4 = derivative_bound_at_one(n, 4);
        let third = xb.mul(&curvature).mul_pow2(2).sub(&slope.mul_i64(nn1 - 2)).div(&one_minus)?;
        let t = Float::with_val(ext, value.mid() / slope.mid());
        let mut t2 = Float::with_val(ext, t.square_ref());
        t2 *= curvature.mid();
        t2 /= slope.mid();
        t2 >>= 1;
        let x1 = Float::with_val(ext, x - &t) - t2;
        let xb1 = Ball::from_float(&x1, ext);
        let delta = xb1.sub(&xb);
        let dm = delta.abs_upper_mag();
        let dm2 = dm.mul(dm);
        let (half_delta2, sixth_delta3) = (delta.sqr().mul_pow2(-1), delta.sqr().mul(&delta).div_i64(6)?);
        let mut value = value.add(&slope.mul(&delta)).add(&curvature.mul(&half_delta2)).add(&third.mul(&sixth_delta3));
        value.add_error_mag(m4.mul(dm2.mul(dm2)).div(Mag::from_f64(24.0)));
        let mut slope = slope.add(&curvature.mul(&delta)).add(&third.mul(&half_delta2));
        slope.add_error_mag(m4.mul(dm2.mul(dm)).div(Mag::from_f64(6.0)));
        let mut curvature = curvature.add(&third.mul(&delta));
        curvature.add_error_mag(m4.mul(dm2).mul_2exp(-1));
        (xb1, value, slope, curvature)
    };
    let xb = xb1;
    // eps > 0 even when P_n(x1) is exactly 0, so that r > 0
    let eps = value.abs_upper_mag().add(Mag::pow2(-2 * ext as i64));
    let d = slope.abs_lower_mag();
    if d.is_zero() {
        return Ok(None);
    }
    let r = eps.mul_2exp(2).div(d);
    // |P_n''| <= |P_n''(x1)| + M_3 r on [x1 - r, x1 + r]
    let m = curvature.abs_upper_mag().add(m3.mul(r));
    if !m.mul(r.mul(r)).le(&eps.mul_2exp(2)) || !r.le(&Mag::pow2(-(prec as i64) - 6)) {
        return Ok(None);
    }
    let mut node = xb;
    node.add_error_mag(r);
    let mut slope_on_node = slope;
    slope_on_node.add_error_mag(m.mul(r));
    let w = weight(&node, &slope_on_node)?;
    if !w.rad_mag().le(&w.abs_lower_mag().mul_2exp(-(prec as i64) - 4)) {
        return Ok(None);
    }
    Ok(Some((node, w)))
}

/// Encloses the root of `P_n` next to `x` by a sign change (a ball of radius about
/// `2^-target`, `P_n` evaluated at `ext` bits at both ends) and its weight from `P_n'`
/// on that ball: the route before 2026-11-29, kept for a node where
/// [`certify_node`]'s bound fails.
fn certify_node_by_signs(n: usize, x: &Float, ext: u32, target: u32, ev: &Evaluation) -> Result<(Ball, Ball)> {
    // delta starts at the target and grows if the signs cannot be decided (the
    // Newton iterate is then less accurate than expected).
    let mut delta_exp = -(target as i64);
    for _ in 0..8 {
        let delta = Mag::pow2(delta_exp).to_float();
        let mut lo = Float::new(ext);
        lo.assign_round(x - &delta, Round::Down);
        let mut hi = Float::new(ext);
        hi.assign_round(x + &delta, Round::Up);
        let (plo, _) = ev.eval(n, &Ball::from_float(&lo, ext))?;
        let (phi, _) = ev.eval(n, &Ball::from_float(&hi, ext))?;
        if let (Some(a), Some(b)) = (strict_sign(&plo), strict_sign(&phi)) {
            if a != b {
                let node = Ball::hull(&lo, &hi, ext);
                let (_, slope) = ev.eval(n, &node)?;
                let w = weight(&node, &slope)?;
                return Ok((node, w));
            }
        }
        delta_exp += 8;
    }
    Err(Error::Invariant(Invariant::LegendreRootNotCertified { degree: n, target_bits: target }))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// sum w_k x_k^(2j) = 2/(2j+1) for 2j <= 2n - 1.
    #[test]
    fn rules_integrate_even_monomials_exactly() {
        for &n in &[1usize, 2, 3, 4, 7, 16, 33, 64, 101] {
            let r = rule(n, 128).unwrap();
            for j in 0..n {
                let mut s = Ball::zero(128);
                for (k, (x, w)) in r.nodes.iter().zip(&r.weights).enumerate() {
                    let mult = if n % 2 == 1 && k == r.nodes.len() - 1 { 1 } else { 2 };
                    s = s.add(&w.mul(&x.pow_u64(2 * j as u64)).mul_i64(mult));
                }
                let exact = Ball::from_ratio(2, 2 * j as i64 + 1, 256);
                assert!(s.overlaps(&exact), "n = {n}, j = {j}: {s:?}");
                assert!(s.rad_mag().le(&Mag::pow2(-110)), "n = {n}: radius {:?}", s.rad_mag());
            }
        }
    }

    #[test]
    fn nodes_are_tight_at_high_precision() {
        let r = rule(20, 1000).unwrap();
        for x in &r.nodes {
            assert!(x.rad_mag().le(&Mag::pow2(-995)), "{:?}", x.rad_mag());
        }
        // the cache hands back the same rule
        assert!(Arc::ptr_eq(&r, &rule(20, 1000).unwrap()));
    }

    /// The Fourier form and the three-term recurrence (with its guard bits) enclose the
    /// same values of `P_n` and `P_n' = n (P_{n-1} - x P_n)/(1 - x^2)`, and the Fourier
    /// form's balls are the narrower.
    #[test]
    fn fourier_form_agrees_with_the_recurrence() {
        for &n in &[1usize, 2, 5, 30, 101] {
            let fw = FourierWeights::new(n, &fourier_coefficients(n, 200).unwrap());
            for x in [0.0, 0.1, 0.5, 0.77, 0.999] {
                let xb = Ball::from_float(&Float::with_val(200, x), 200);
                let (f, fd) = legendre_fourier(n, &xb, &fw).unwrap();
                let p = 200 + recurrence_guard(n);
                let xr = Ball::from_float(&Float::with_val(p, x), p);
                let (r, rm) = legendre_pair_ball(n, &xr).unwrap();
                let rd = rm.sub(&xr.mul(&r)).mul_i64(n as i64).div(&Ball::one(p).sub(&xr.sqr())).unwrap();
                assert!(f.overlaps(&r), "n {n} x {x}: {f:?} vs {r:?}");
                assert!(fd.overlaps(&rd), "n {n} x {x}: P' {fd:?} vs {rd:?}");
                assert!(f.rad_mag().le(&Mag::pow2(-180)), "n {n} x {x}: {:?}", f.rad_mag());
                assert!(fd.rad_mag().le(&Mag::pow2(-170)), "n {n} x {x}: P' {:?}", fd.rad_mag());
            }
        }
    }

    /// Newton's step with the recurrence in fixed point lands where the MPFR step does,
    /// to within `2^-(q - 16)` at `q` bits, for degrees up to 2048 (where the scaling
    /// `2^-scale` of `S_k` must hold).
    #[test]
    fn fixed_point_newton_step_agrees_with_mpfr() {
        for &n in &[2usize, 7, 108, 512, 2048] {
            let rec = Recurrence::new(n, 600);
            let theta = std::f64::consts::PI * 3.0 / (4.0 * n as f64 + 2.0);
            for q in [120u32, 200, 300, 440] {
                let x0 = Float::with_val(q, theta.cos() * (1.0 - 1e-9));
                let (mut a, mut b) = (x0.clone(), x0.clone());
                assert!(rec.step_fixed(&mut a).is_some(), "n {n} q {q}: not served");
                // the MPFR step (step_fixed declines at no precision this test uses)
                let mut prev = Float::with_val(q, 1);
                let x2 = Float::with_val(q, &b * 2u32);
                let mut cur = x2.clone();
                for g in &rec.g[1..] {
                    let next = Float::with_val(q, &cur * &x2) - Float::with_val(q, g * &prev);
                    prev = cur;
                    cur = next;
                }
                rec.correct(&mut b, &cur, &prev);
                let d = Float::with_val(q, &a - &b).abs();
                assert!(d <= Float::with_val(q, 1) >> (q as i32 - 16), "n {n} q {q}: {d}");
                assert!(a != x0, "n {n} q {q}: no step taken");
            }
        }
    }

    /// The fixed-point loop of the Fourier form and the MPFR loop enclose the same values
    /// with radii of the same size, at every limb count (`p` from 60 to 500 bits), and the
    /// fixed-point one serves every case asked of it here.
    #[test]
    fn fixed_point_fourier_loop_agrees_with_mpfr() {
        for p in [60u32, 126, 190, 253, 333, 390, 446, 500] {
            for &n in &[1usize, 2, 5, 30, 108, 512] {
                let fw = FourierWeights::new(n, &fourier_coefficients(n, p).unwrap());
                for x in [0.0, 0.1, 0.5, 0.77, 0.999] {
                    let xb = Ball::from_float(&Float::with_val(p, x), p);
                    let s = Ball::one(p).sub(&xb.sqr()).sqrt().unwrap();
                    let w = Disc::from_balls(&xb, &s);
                    let step = w.conj().mul(&w.conj());
                    let z = w.pow(n as u64);
                    let (fv, fs) = fourier_fixed_dispatch(n, &z, &step, &fw, p).unwrap_or_else(|| panic!("fixed point refused p {p} n {n} x {x}"));
                    let (mv, ms) = fourier_mpfr(n, z, &step, &fw, p);
                    for (f, m, what) in [(&fv, &mv, "P"), (&fs, &ms, "P' sin")] {
                        assert!(f.overlaps(m), "p {p} n {n} x {x} {what}: {f:?} vs {m:?}");
                        let (rf, rm) = (f.rad_mag().to_f64_up(), m.rad_mag().to_f64_up());
                        assert!(rf <= 4.0 * rm + 1e-300 && rm <= 64.0 * rf, "p {p} n {n} x {x} {what}: radii {rf:e} fixed, {rm:e} MPFR");
                    }
                }
            }
        }
        // a ball too wide for the format's range goes to MPFR
        let p = 200;
        let fw = FourierWeights::new(4, &fourier_coefficients(4, p).unwrap());
        let wide = Disc { re: Float::with_val(p, 0.5), im: Float::with_val(p, 0.8), rad: Mag::from_f64(0.7) };
        assert!(fourier_fixed_dispatch(4, &wide, &wide, &fw, p).is_none());
    }

    /// Every node of the integrator's degrees (up to 512 below 1096 bits, where its cap
    /// `prec/2 + 60` is below 608) is certified by the one evaluation of step 3 at 64,
    /// 333 and 1000 bits (and six degrees up to the cap 608 at 3333, two at 3353, the
    /// rules of 3333-bit integrals), none by the fallback; the nodes and weights,
    /// rounded to the requested bits, keep them.
    #[test]
    fn every_node_is_certified_by_the_taylor_bound() {
        let all: Vec<usize> = crate::quad::certified::adaptive::DEGREES.iter().copied().filter(|&n| n <= 512).collect();
        for (prec, degrees) in [(64u32, all.clone()), (333, all.clone()), (1000, all), (3333, vec![7, 108, 304, 430, 512, 608]), (3353, vec![304, 430])] {
            for n in degrees {
                let mut fallbacks = 0;
                let r = build_rule(n, prec, &mut fallbacks).unwrap();
                assert_eq!(fallbacks, 0, "n {n} at {prec} bits");
                for (x, w) in r.nodes.iter().zip(&r.weights) {
                    assert!(x.rad_mag().le(&Mag::pow2(1 - prec as i64)), "n {n} at {prec}: node radius {:?}", x.rad_mag());
                    let rel = w.rad_mag().div(w.abs_lower_mag());
                    assert!(rel.le(&Mag::pow2(2 - prec as i64)), "n {n} at {prec}: weight radius {:?}", rel);
                }
            }
        }
    }

    /// Above 8 limbs the rules are evaluated by the series at 0 (`legendre_series.rs`);
    /// the Fourier form (in MPFR there), the evaluation before, proves the same nodes
    /// and weights: `P_n` takes opposite signs at the two ends of each node's ball, and
    /// the weight from `P_n'` on that ball overlaps the rule's. Nodes are checked at
    /// the two ends of the range and in between.
    #[test]
    fn series_rules_agree_with_the_fourier_form() {
        for (n, prec) in [(2usize, 600u32), (3, 600), (7, 1000), (30, 600), (108, 2000), (304, 3353), (430, 3353)] {
            let mut fallbacks = 0;
            let r = build_rule(n, prec, &mut fallbacks).unwrap();
            assert_eq!(fallbacks, 0, "n {n} at {prec}");
            let ext = precisions(n, prec).1;
            assert!(matches!(Evaluation::new(n, ext).unwrap(), Evaluation::Series(_)), "n {n} at {prec}: not by the series");
            let fourier = Evaluation::Fourier(FourierWeights::new(n, &fourier_coefficients(n, ext).unwrap()));
            let half = r.nodes.len();
            let mut ks: Vec<usize> = (0..half).step_by(half.div_ceil(6).max(1)).collect();
            ks.push(half - 1);
            for k in ks {
                let (x, w) = (&r.nodes[k], &r.weights[k]);
                if x.mid().is_zero() {
                    continue;
                }
                let (lo, hi) = (fourier.eval(n, &Ball::from_float(&x.lower(), ext)).unwrap().0, fourier.eval(n, &Ball::from_float(&x.upper(), ext)).unwrap().0);
                let (a, b) = (strict_sign(&lo), strict_sign(&hi));
                assert!(a.is_some() && b.is_some() && a != b, "n {n} at {prec}, node {k}: P_n at the ends {lo:?}, {hi:?}");
                let (_, slope) = fourier.eval(n, &x.set_prec(ext)).unwrap();
                let wf = weight(&x.set_prec(ext), &slope).unwrap();
                assert!(wf.overlaps(w), "n {n} at {prec}, node {k}: weight {w:?} vs the Fourier form's {wf:?}");
            }
        }
    }

    /// The fallback (signs at `x +- 2^-target`) encloses the same root as step 3, by
    /// either evaluation.
    #[test]
    fn the_fallback_encloses_the_same_nodes() {
        // the Fourier form at 200 bits, the series at 1000
        for (n, prec) in [(2usize, 200u32), (7, 200), (38, 200), (100, 200), (7, 1000), (100, 1000)] {
            let (target, ext) = precisions(n, prec);
            let ev = Evaluation::new(n, ext).unwrap();
            let rec = Recurrence::new(n, target + 8);
            let r = rule(n, prec).unwrap();
            for (k, (x, w)) in r.nodes.iter().zip(&r.weights).enumerate().filter(|(_, (x, _))| !x.mid().is_zero()) {
                let (node, weight) = certify_node_by_signs(n, &newton_root(&rec, ev.series(), x.mid().to_f64(), target + 4), ext, target, &ev).unwrap();
                assert!(node.overlaps(x) && weight.overlaps(w), "n {n} at {prec}, node {k}");
            }
        }
    }

    #[test]
    fn degree_zero_is_an_error() {
        assert!(rule(0, 64).is_err());
    }
}
