//! Gauss-Legendre nodes and weights as certified balls, cached per degree and precision.
//!
//! # Method
//!
//! The `n` nodes are the roots of the Legendre polynomial `P_n` (DLMF 18.3), found
//! and enclosed in three steps:
//!
//! 1. **Start.** Tricomi's approximation `x_k ~ cos(pi (4k - 1)/(4n + 2))`
//!    (DLMF 18.16.6 with the first correction term), refined by Newton's method in
//!    f64.
//! 2. **Refine.** Newton's method in MPFR, `x <- x - P_n(x)/P_n'(x)`, with the
//!    precision doubled each step (quadratic convergence) up to the bits to certify
//!    plus 8, and one more step there. `P_n` and `P_n'` come from the three-term
//!    recurrence `(k+1) P_{k+1} = (2k+1) x P_k - k P_{k-1}` (DLMF 18.9.1) and
//!    `(1 - x^2) P_n' = n (P_{n-1} - x P_n)` (DLMF 18.9.18), in floats (an estimate:
//!    the next step proves).
//! 3. **Certify.** `P_n` is evaluated in ball arithmetic at the two exact points
//!    `x - delta` and `x + delta`. Opposite signs (balls that exclude zero) prove
//!    a root in `[x - delta, x + delta]`. The `ceil(n/2)` non-negative roots are
//!    all found this way in disjoint, ordered intervals (for odd `n` the root 0 is
//!    exact), and `P_n` has exactly `n` roots, symmetric about 0, so every node
//!    is enclosed. The weight `w = 2 (1 - x^2) / (n P_{n-1}(x))^2` (DLMF 3.5.19
//!    with the identity above at a root) is evaluated in ball arithmetic on the
//!    node's ball, so it encloses the true weight.
//!
//! The ball evaluations of `P_n` and `P_{n-1}` use the Fourier form (DLMF 18.5.11,
//! `lambda = 1/2`): `P_m(cos theta) = sum_{k=0}^m c_k c_{m-k} cos((m - 2k) theta)`, `c_k
//! = (1/2)_k / k!`, with `e^{i theta} = x + i (1 - x^2)^(1/2)` and the cosines the real
//! parts of `w^m conj(w)^(2k)`, formed in complex discs ([`Disc`]). The coefficients are
//! positive and sum to `P_m(1) = 1`, and a product of discs of modulus 1 adds their
//! radii, so a radius grows about linearly in `m` (and as `m^2` times the node's
//! radius, the Markov bound of `P_m'`): `2 log2 n + 24` guard bits suffice. The
//! three-term recurrence in ball arithmetic, used before, grows radii by up to `1 +
//! sqrt 2` a step and needed `2.56 n + 80` guard bits (1200 bits for a rule of degree
//! 300 at 333 bits); the Fourier form made the first call of `int_0^1 1/(1+x^2)` about
//! 1.5x faster at 333 and 3333 bits (`examples/first_call.rs`).
//!
//! Cost: `O(n)` operations a polynomial evaluation, a few evaluations a node, so
//! `O(n^2)` a rule, once per `(n, prec)`: rules are cached for the life of the
//! process ([`rule`]). C Arb builds its nodes faster at 64 to 333 bits (asymptotic
//! starts and evaluations, `arb_hypgeom_legendre_p_ui_root`): see docs/quadrature.md.

use std::collections::HashMap;
use std::sync::{Arc, Mutex, OnceLock};

use rug::float::Round;
use rug::ops::AssignRound;
use rug::{Assign, Float};

use crate::ball::{Ball, Mag};
use crate::error::{Error, Invariant, Result};

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

/// `(P_n(x), P_{n-1}(x))` by the three-term recurrence, in MPFR at `x`'s precision.
fn legendre_pair(n: usize, x: &Float) -> (Float, Float) {
    let p = x.prec();
    let mut prev = Float::with_val(p, 1);
    let mut cur = x.clone();
    let mut t = Float::new(p);
    for k in 1..n {
        // P_{k+1} = ((2k+1) x P_k - k P_{k-1}) / (k+1)
        t.assign(&cur * x);
        t *= (2 * k + 1) as u64;
        prev *= k as u64;
        t -= &prev;
        t /= (k + 1) as u64;
        std::mem::swap(&mut prev, &mut cur);
        std::mem::swap(&mut cur, &mut t);
    }
    (cur, prev)
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

/// `P_m(x)` for a ball `x` in `[-1, 1]` by the Fourier form (DLMF 18.5.11 with `lambda =
/// 1/2`): `P_m(cos theta) = sum_{k=0}^m c_k c_{m-k} cos((m - 2k) theta)`, with `e^{i
/// theta} = w = x + i (1 - x^2)^(1/2)`, `cos((m - 2k) theta) = Re(w^m conj(w)^(2k))`.
/// Every coefficient is positive and every `|w^j| = 1`, so ball radii grow about
/// linearly in `m` (the three-term recurrence in ball arithmetic grows them by up to
/// `1 + sqrt 2` a step). `c` from [`fourier_coefficients`] (at least `m + 1` of them).
fn legendre_fourier(m: usize, x: &Ball, cc: &[Ball]) -> Result<Ball> {
    let p = x.prec();
    let s = Ball::one(p).sub(&x.sqr()).sqrt()?;
    let w = Disc::from_balls(x, &s);
    let step = w.conj().mul(&w.conj());
    let mut z = w.pow(m as u64);
    // k and m - k give the same cosine: the terms k < m/2 twice (cc holds 2 c_k c_{m-k}),
    // k = m/2 (m even) once
    let mut sum = FourierSum::new(p);
    let mut tmp = Disc::zero(p);
    for term in cc.iter().take(m.div_ceil(2)) {
        sum.add(term, &z);
        tmp.assign_mul(&z, &step);
        std::mem::swap(&mut z, &mut tmp);
    }
    if m % 2 == 0 {
        sum.add(&cc[m / 2], &z);
    }
    Ok(sum.ball())
}

/// `sum_k t_k Re(z_k)` accumulated in a float with a radius. Every `z_k` is a disc that
/// encloses a number of modulus 1, so `|Re z_k| <= 1` and `|Re mid(z_k)| <= 1 + r_k`:
/// a term adds `rad(t) (1 + r) + |mid(t)| r` (the ball and disc radii), `2^-p |mid(t)| (1
/// + r)` (the product rounded to nearest, `u = 2^-p`) and `2^-p` times a bound of the
/// new sum (the addition rounded); the sum is at most `bound`, the running `sum |t| (1 +
/// r)`, up to the roundings, and `2 bound` covers those.
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

    fn add(&mut self, t: &Ball, z: &Disc) {
        let p = self.mid.prec() as i64;
        let one_r = Mag::from_f64(1.0).add(z.rad);
        let t_mag = t.abs_upper_mag();
        self.prod.assign(t.mid() * &z.re);
        self.mid += &self.prod;
        let term_up = t_mag.mul(one_r);
        self.bound = self.bound.add(term_up);
        let propagated = t.rad_mag().mul(one_r).add(t_mag.mul(z.rad));
        let rounding = term_up.add(self.bound.mul_2exp(1)).mul_2exp(-p);
        self.rad = self.rad.add(propagated).add(rounding);
    }

    fn ball(&self) -> Ball {
        let mut b = Ball::from_float(&self.mid, self.mid.prec());
        b.add_error_mag(self.rad);
        b
    }
}

/// `2 c_k c_{m-k}` for `k < m/2` and `c_{m/2}^2` (even `m`): the weights of
/// [`legendre_fourier`], from `c` of [`fourier_coefficients`].
fn fourier_weights(m: usize, c: &[Ball]) -> Vec<Ball> {
    let mut out: Vec<Ball> = (0..m.div_ceil(2)).map(|k| c[k].mul(&c[m - k]).mul_pow2(1)).collect();
    if m % 2 == 0 {
        out.push(c[m / 2].sqr());
    }
    out
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
        d.assign_mul(self, o);
        d
    }

    /// `self = a b`: `|a b - a_m b_m| <= r_a (|b_m| + r_b) + |a_m| r_b`, and the point
    /// `a_m b_m` rounded to nearest, each part from two products and a sum, so that each
    /// part errs by at most `3 u |a_m| |b_m|` (`u = 2^-prec`): `2^(3 - prec) |a_m| |b_m|`
    /// covers both. `|a_m| <= 1 + r_a`, `|b_m| <= 1 + r_b` (the discs enclose numbers of
    /// modulus 1).
    fn assign_mul(&mut self, a: &Disc, b: &Disc) {
        let p = self.re.prec();
        let (ma, mb) = (Mag::from_f64(1.0).add(a.rad), Mag::from_f64(1.0).add(b.rad));
        self.re.assign(&a.re * &b.re);
        let t = Float::with_val(p, &a.im * &b.im);
        self.re -= &t;
        self.im.assign(&a.re * &b.im);
        let t = Float::with_val(p, &a.im * &b.re);
        self.im += &t;
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

/// Newton's method for the root near `x0` (f64 start), refined to `prec` bits.
fn newton_root(n: usize, x0: f64, prec: u32) -> Float {
    // f64 Newton first.
    let mut x = x0;
    for _ in 0..8 {
        let (pn, pm) = legendre_pair_f64(n, x);
        let d = n as f64 * (pm - x * pn) / (1.0 - x * x);
        let step = pn / d;
        x -= step;
        if step.abs() <= 1e-17 * x.abs().max(1e-300) {
            break;
        }
    }
    let mut q = 53u32;
    let mut xf = Float::with_val(prec, x);
    loop {
        q = (2 * q).min(prec);
        xf.set_prec_round(q, Round::Nearest);
        let (pn, pm) = legendre_pair(n, &xf);
        // d = n (P_{n-1} - x P_n) / (1 - x^2)
        let mut num = Float::with_val(q, &xf * &pn);
        num = Float::with_val(q, &pm - &num) * n as u64;
        let one_minus = Float::with_val(q, 1) - Float::with_val(q, xf.square_ref());
        let d = num / one_minus;
        let step = pn / d;
        xf -= step;
        if q == prec {
            break;
        }
    }
    // One more step at full precision: the doubling ends one step short of it (the f64
    // start next to 1 is good to fewer than 53 bits: P_76 at 768 bits kept 725 of 844
    // without this step, too few to certify)
    let (pn, pm) = legendre_pair(n, &xf);
    let num = Float::with_val(prec, &pm - Float::with_val(prec, &xf * &pn)) * n as u64;
    let one_minus = Float::with_val(prec, 1) - Float::with_val(prec, xf.square_ref());
    let d = num / one_minus;
    xf -= pn / d;
    xf
}

fn legendre_pair_f64(n: usize, x: f64) -> (f64, f64) {
    let (mut prev, mut cur) = (1.0, x);
    for k in 1..n {
        let next = ((2 * k + 1) as f64 * x * cur - k as f64 * prev) / (k + 1) as f64;
        prev = cur;
        cur = next;
    }
    (cur, prev)
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

/// Extra bits for the Fourier form ([`legendre_fourier`]): its radii grow about as
/// `m^2` on a node's ball (the Markov bound `|P_m'| <= m (m + 1)/2` times the ball's
/// radius) and as `m` from rounding.
fn fourier_guard(n: usize) -> u32 {
    2 * (usize::BITS - n.leading_zeros()) + 24
}

fn compute_rule(n: usize, prec: u32) -> Result<Rule> {
    if n == 0 {
        return Err(Error::Internal { what: "Gauss-Legendre rule of degree 0".into() });
    }
    let half = n.div_ceil(2);
    let wp = prec + 2 * (usize::BITS - n.leading_zeros()) + 16;
    // Roots to `target` bits (Newton in MPFR), enclosed in balls of radius
    // `2^-target`, `P_n` and `P_{n-1}` evaluated by the Fourier form at `ext` bits: the
    // weight then still has about `wp` bits.
    let guard = fourier_guard(n);
    let target = wp + guard;
    let ext = target + guard;
    let c = fourier_coefficients(n, ext)?;
    let (cc_n, cc_m) = (fourier_weights(n, &c), fourier_weights(n - 1, &c));
    let mut nodes = Vec::with_capacity(half);
    let mut weights = Vec::with_capacity(half);
    let nf = n as f64;
    let mut prev_low: Option<Float> = None;
    for k in 1..=half {
        let exact_zero = n % 2 == 1 && k == half;
        let node = if exact_zero {
            Ball::zero(ext)
        } else {
            let theta = std::f64::consts::PI * (4.0 * k as f64 - 1.0) / (4.0 * nf + 2.0);
            let x0 = (1.0 - (nf - 1.0) / (8.0 * nf * nf * nf)) * theta.cos();
            let x = newton_root(n, x0, target + 8);
            certify_root(n, &x, ext, target, &cc_n)?
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
        let pm = if n == 1 { Ball::one(ext) } else { legendre_fourier(n - 1, &node, &cc_m)? };
        let one_minus = Ball::one(ext).sub(&node.sqr());
        let den = pm.mul_i64(n as i64).sqr();
        let w = one_minus.mul_pow2(1).div(&den)?;
        nodes.push(node.set_prec(prec));
        weights.push(w.set_prec(prec));
    }
    Ok(Rule { nodes, weights })
}

/// Encloses the root of `P_n` next to `x` by a sign change: a ball of radius about
/// `2^-target`, `P_n` evaluated at `ext` bits.
fn certify_root(n: usize, x: &Float, ext: u32, target: u32, cc: &[Ball]) -> Result<Ball> {
    // delta starts at the target and grows if the signs cannot be decided (the
    // Newton iterate is then less accurate than expected).
    let mut delta_exp = -(target as i64);
    for _ in 0..8 {
        let delta = Mag::pow2(delta_exp).to_float();
        let mut lo = Float::new(ext);
        lo.assign_round(x - &delta, Round::Down);
        let mut hi = Float::new(ext);
        hi.assign_round(x + &delta, Round::Up);
        let plo = legendre_fourier(n, &Ball::from_float(&lo, ext), cc)?;
        let phi = legendre_fourier(n, &Ball::from_float(&hi, ext), cc)?;
        if let (Some(a), Some(b)) = (strict_sign(&plo), strict_sign(&phi)) {
            if a != b {
                return Ok(Ball::hull(&lo, &hi, ext));
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
        for &n in &[1usize, 2, 3, 4, 7, 16, 33] {
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
    /// same values, and the Fourier form's balls are the narrower.
    #[test]
    fn fourier_form_agrees_with_the_recurrence() {
        for &n in &[1usize, 2, 5, 30, 101] {
            let c = fourier_weights(n, &fourier_coefficients(n, 200).unwrap());
            for x in [0.0, 0.1, 0.5, 0.77, 0.999, 1.0] {
                let xb = Ball::from_float(&Float::with_val(200, x), 200);
                let f = legendre_fourier(n, &xb, &c).unwrap();
                let xr = Ball::from_float(&Float::with_val(200 + recurrence_guard(n), x), 200 + recurrence_guard(n));
                let (r, _) = legendre_pair_ball(n, &xr).unwrap();
                assert!(f.overlaps(&r), "n {n} x {x}: {f:?} vs {r:?}");
                assert!(f.rad_mag().le(&Mag::pow2(-180)), "n {n} x {x}: {:?}", f.rad_mag());
            }
        }
    }

    #[test]
    fn degree_zero_is_an_error() {
        assert!(rule(0, 64).is_err());
    }
}
