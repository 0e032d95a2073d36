//! `P_n(x)` and `P_n'(x)` by the hypergeometric series at 0 with rectangular splitting,
//! in ball arithmetic: the evaluation of the Gauss-Legendre rules above 8 limbs
//! (`legendre.rs`), where it costs `O(sqrt n)` full products and `O(n)` products and
//! quotients by word-size integers a point instead of the Fourier form's `n/2` complex
//! products (issue 36, the 3333-bit first call).
//!
//! # Method
//!
//! With `n = 2d + s` (`s = n mod 2`), `y = -x^2` and DLMF 18.5.8 written from the lowest
//! power of `x` (as Arb's `arb_hypgeom_legendre_p_ui_zero`),
//!
//! `P_n(x) = (-1)^d C x^s F(y)`, `F(y) = sum_{j=0}^{d} T_j y^j`, `T_0 = 1`,
//! `T_j = T_{j-1} a_j / b_j`, `a_j = (d - j + 1)(n + 2j - 1 + s)`, `b_j = j (2j - 1 + 2s)`,
//!
//! with `C = c_d` for even `n` and `C = 2 (d + 1) c_{d+1}` for odd `n`, `c_k = (1/2)_k/k!
//! = binom(2k, k)/4^k` (the coefficient of `x^s` in `P_n`, DLMF 18.5.8 at `k = d`). The
//! ratio `T_j/T_{j-1}` is that of consecutive coefficients `(-1)^(d-j) binom(n, d-j)
//! binom(n + 2j + s, n) / 2^n` (the binomials' ratios, multiplied out). The derivative in
//! `y` is `F'(y) = T_1 G(y)`, `G(y) = sum_{i=0}^{d-1} U_i y^i`, `U_0 = 1`, `U_i = U_{i-1}
//! a_{i+1} / (i (2i + 1 + 2s))` (`U_i = (i + 1) T_{i+1} / T_1`), so that
//!
//! `P_n'(x) = (-1)^d C (-2x) T_1 G(y)` (even `n`), `(-1)^d C (F(y) - 2x^2 T_1 G(y))` (odd).
//!
//! **Rectangular splitting** (Smith; Arb's `legendre_p_ui_zero.c` does the same with
//! integer coefficients). For `S = sum_{j=0}^{K} T_j y^j` and `m` powers `y^1 .. y^m`,
//! Horner's scheme from the top keeps, after the index `j`, `s_j = sum_{i=j}^{K} (T_i /
//! T_j) y^(i - base(j))`, `base(j) = m floor(j/m)`: `s_K = y^(K mod m)` and `s_{j-1} =
//! y^((j-1) mod m) + (a_j/b_j) Z_j s_j`, `Z_j = y^m` when `m` divides `j` and 1 otherwise;
//! `s_0 = S`. Steps `t = h, h-1, .., l+1` with `m` dividing none of `l+1 .. h-1` (a
//! chunk) combine to `B s_l = A Z_h s_h + sum_{i=l}^{h-1} c_i y^(i mod m)`, `A = prod_t
//! a_t`, `B = prod_t b_t`, `c_i = prod_{t=l+1}^{i} a_t prod_{t=i+1}^{h} b_t` (unroll the
//! two-term step and multiply by `B`). A chunk takes at most as many steps as keep `A`,
//! `B` and every `c_i` below `2^63` (three at the integrator's degrees): a chunk costs
//! one product and one quotient by a word, a term one product by a word and one sum,
//! and every `m` terms one full product (by `y^m`). With `F` and `G` sharing the
//! powers, a point costs `m - 1 + 2 d/m` full products, `m ~ (2d)^(1/2)`.
//!
//! **Enclosure.** Every operation is one of ball arithmetic (midpoint rounded to
//! nearest, the radius widened by the input radii and by `2^(e - p)`, `e` the result's
//! exponent, for each rounding), so the results contain `P_n(x)` and `P_n'(x)` for every
//! `x` in the input ball. The working precision only decides how tight they are: the
//! Horner sums are at most `sum |T_j y^j| = F(x^2)`, and `C |x|^s F(x^2) = |P_n(i x)| <=
//! (|x| + (1 + x^2)^(1/2))^n` (Laplace's first integral, `P_n(z) = (1/pi) int_0^pi (z +
//! (z^2 - 1)^(1/2) cos phi)^n dphi`), so a rounding costs about `n log2(|x| + (1 +
//! x^2)^(1/2))` bits of the result (at most `1.27 n`): [`SeriesPlan::working_prec`] adds
//! them.
//!
//! The Newton (Chebyshev) steps before the certificate ([`SeriesPlan::newton_step`]) use
//! the same sums without radii: estimates, which the certificate proves.

use std::cmp::Ordering;

use rug::float::Round;
use rug::ops::{AddAssignRound, AssignRound, DivAssignRound, MulAssignRound};
use rug::{Assign, Float};

use crate::ball::{Ball, Mag};
use crate::error::Result;

/// The chunks of the rectangular-splitting Horner scheme of one series (module doc).
struct Chunk {
    /// `h` and `l`: the chunk takes `s_h` to `s_l`.
    high: usize,
    low: usize,
    /// `A = prod a_t` and `B = prod b_t`, `t = l+1 ..= h`.
    a: u64,
    b: u64,
    /// `c_i`, `i = l .. h`, in that order.
    c: Vec<u64>,
    /// `m` divides `h` (and `h > 0`): `s_h` is multiplied by `y^m` first.
    boundary: bool,
}

/// One series `sum_{j=0}^{K} T_j y^j` with `T_j/T_{j-1} = a_j/b_j`, as chunks.
struct Series {
    top: usize,
    chunks: Vec<Chunk>,
}

impl Series {
    /// The chunks for `K = top`, `m` powers and the ratios `ratio(j) = (a_j, b_j)`,
    /// `j = 1 ..= K` (positive words; a chunk of one step holds any).
    fn new(top: usize, m: usize, ratio: impl Fn(usize) -> (u64, u64)) -> Series {
        let mut chunks = Vec::new();
        let mut h = top;
        while h > 0 {
            // t = l+1 ..= h: m divides none of l+1 .. h-1
            let floor_mult = m * ((h - 1) / m);
            let mut l = h;
            let (mut a, mut b) = (1u64, 1u64);
            // extend while A, B and every c_i stay below 2^63: each is a product of h - l
            // factors, each at most the largest a_t, b_t of the chunk
            let mut largest = 1u64;
            while l > floor_mult {
                let (at, bt) = ratio(l);
                let big = largest.max(at).max(bt);
                let steps = (h - l + 1) as u32;
                // every product of `steps` factors of at most `big` fits
                if (big as f64).log2() * steps as f64 >= 63.0 && l < h {
                    break;
                }
                largest = big;
                a *= at;
                b *= bt;
                l -= 1;
            }
            // c_i = prod_{t=l+1}^{i} a_t prod_{t=i+1}^{h} b_t
            let c = (l..h)
                .map(|i| {
                    let mut p = 1u64;
                    for t in l + 1..=i {
                        p *= ratio(t).0;
                    }
                    for t in i + 1..=h {
                        p *= ratio(t).1;
                    }
                    p
                })
                .collect();
            chunks.push(Chunk { high: h, low: l, a, b, c, boundary: h % m == 0 });
            h = l;
        }
        Series { top, chunks }
    }

    /// `sum T_j y^j` from `pows[k] = y^k`, `k = 0 ..= m` (`pows[0]` unused), at `p` bits;
    /// without `track`, the midpoint alone (an estimate: the radius is left at 0).
    fn eval(&self, pows: &[Ball], p: u32, track: bool) -> Ball {
        let m = pows.len() - 1;
        let mut s = Acc::new(p, track);
        match self.top % m {
            0 => s.set_one(),
            e => s.set(&pows[e]),
        }
        for ch in &self.chunks {
            if ch.boundary {
                s.mul(&pows[m]);
            }
            s.mul_u64(ch.a);
            for (i, &c) in (ch.low..ch.high).zip(&ch.c).rev() {
                match i % m {
                    0 => s.add_u64(c),
                    e => s.add_mul_u64(&pows[e], c),
                }
            }
            s.div_u64(ch.b);
        }
        s.ball()
    }
}

/// The series of degree `n` (module doc), evaluated at any point.
pub(crate) struct SeriesPlan {
    n: usize,
    m: usize,
    /// `F` and `G`.
    f: Series,
    g: Series,
    /// `T_1 = a_1/b_1`, as its numerator and denominator.
    t1: (u64, u64),
    /// `(-1)^d C`.
    scale: Ball,
}

impl SeriesPlan {
    /// The plan for degree `n >= 2`, with `(-1)^d C` at `prec` bits (module doc).
    pub(crate) fn new(n: usize, prec: u32) -> Result<SeriesPlan> {
        let d = n / 2;
        let s = (n % 2) as u64;
        let (nn, dd) = (n as u64, d as u64);
        let a = move |j: usize| (dd - j as u64 + 1) * (nn + 2 * j as u64 - 1 + s);
        let m = ((2 * d) as f64).sqrt().ceil().max(1.0) as usize;
        let f = Series::new(d, m, |j| (a(j), j as u64 * (2 * j as u64 - 1 + 2 * s)));
        let g = Series::new(d.saturating_sub(1), m, |i| (a(i + 1), i as u64 * (2 * i as u64 + 1 + 2 * s)));
        // c_k = c_{k-1} (2k - 1)/(2k), k <= d + s
        let mut scale = Ball::one(prec);
        for k in 1..=d + s as usize {
            scale = scale.mul_i64(2 * k as i64 - 1).div_i64(2 * k as i64)?;
        }
        if s == 1 {
            scale = scale.mul_i64(2 * (d as i64 + 1));
        }
        if d % 2 == 1 {
            scale = scale.neg();
        }
        Ok(SeriesPlan { n, m, f, g, t1: (a(1), 1 + 2 * s), scale })
    }

    /// The bits to evaluate at `x` so that the roundings cost about `out` bits' worth of
    /// `P_n` and `P_n'` (module doc: the sums reach `(|x| + (1 + x^2)^(1/2))^n`, and
    /// `P_n'` about `n` times that).
    pub(crate) fn working_prec(&self, x: f64, out: u32) -> u32 {
        let x = x.abs().min(1.0);
        let lost = self.n as f64 * (x + (1.0 + x * x).sqrt()).log2();
        let l = usize::BITS - self.n.leading_zeros();
        out + lost.ceil() as u32 + 2 * l + 4
    }

    /// `y^k`, `k = 0 ..= m`, at `p` bits, `y = -x^2`.
    fn powers(&self, x: &Ball, p: u32) -> Vec<Ball> {
        let y = x.set_prec(p).sqr().neg();
        let mut pows = Vec::with_capacity(self.m + 1);
        pows.push(Ball::one(p));
        pows.push(y.clone());
        for k in 2..=self.m {
            let next = if k % 2 == 0 { pows[k / 2].sqr() } else { pows[k - 1].mul(&y) };
            pows.push(next);
        }
        pows
    }

    /// `F(y)` and `G(y)` at `p` bits, `y = -x^2`.
    fn sums(&self, x: &Ball, p: u32) -> (Ball, Ball) {
        let pows = self.powers(x, p);
        (self.f.eval(&pows, p, true), self.g.eval(&pows, p, true))
    }

    /// Balls containing `P_n(x)` and `P_n'(x)` for every `x` in the ball `x`, evaluated
    /// at `p` bits ([`SeriesPlan::working_prec`]).
    pub(crate) fn eval(&self, x: &Ball, p: u32) -> Result<(Ball, Ball)> {
        let (f, g) = self.sums(x, p);
        let t1g = g.mul_i64(self.t1.0 as i64).div_i64(self.t1.1 as i64)?;
        let (value, slope) = if self.n % 2 == 0 {
            (f, t1g.mul(x).mul_pow2(1).neg())
        } else {
            let slope = f.sub(&t1g.mul(&x.sqr()).mul_pow2(1));
            (f.mul(x), slope)
        };
        Ok((value.mul(&self.scale), slope.mul(&self.scale)))
    }

    /// Chebyshev's step ([`chebyshev_step`]) from `x` correct to about
    /// `q/3` bits, the result at `x`'s precision (an estimate; `(-1)^d C` cancels in
    /// `t = P_n/P_n'`, and no radius is kept). `F` is summed at
    /// [`SeriesPlan::working_prec`] for `q` bits, `G` for `2q/3 + 16`: a relative error `e`
    /// of `P_n'` adds about `e |t|` to the step's result.
    pub(crate) fn newton_step(&self, x: &mut Float, q: u32) {
        let xf = x.to_f64();
        let (pf, pg) = (self.working_prec(xf, q), self.working_prec(xf, 2 * q / 3 + 16));
        let pows = self.powers(&Ball::from_float(x, x.prec()), pf);
        let f = self.f.eval(&pows, pf, false);
        let pows_g: Vec<Ball> = pows.iter().map(|b| b.set_prec(pg)).collect();
        let g = self.g.eval(&pows_g, pg, false);
        let (f, g) = (f.mid(), g.mid());
        let p = x.prec();
        let mut t1g = Float::with_val(p, g * self.t1.0);
        t1g /= self.t1.1;
        let t = if self.n % 2 == 0 {
            // F / (-2 x T_1 G)
            let den = Float::with_val(p, &t1g * &*x) * 2u32;
            Float::with_val(p, -(f / den))
        } else {
            // x F / (F - 2 x^2 T_1 G)
            let x2 = Float::with_val(p, x.square_ref());
            let den = Float::with_val(p, f - Float::with_val(p, &t1g * &x2) * 2u32);
            Float::with_val(p, f * &*x) / den
        };
        let one_minus = Float::with_val(p, 1) - Float::with_val(p, x.square_ref());
        chebyshev_step(x, &t, &one_minus, self.n);
    }
}

/// Chebyshev's step `x <- x - t - (P_n''/(2 P_n')) t^2` from `t = P_n(x)/P_n'(x)` and
/// `1 - x^2`, with `P_n''/P_n' = (2x - n(n+1) t)/(1 - x^2)` (Legendre's equation, DLMF
/// 18.8.1): the root of the Taylor polynomial of degree 2, so the error is cubed (times
/// about `(P_n''/P_n')^2`) where Newton's step squares it. An estimate: the certificate
/// proves.
pub(crate) fn chebyshev_step(x: &mut Float, t: &Float, one_minus: &Float, n: usize) {
    let q = x.prec();
    let mut ratio = Float::with_val(q, t * (n * (n + 1)) as u64);
    ratio = Float::with_val(q, &*x * 2u32) - ratio;
    ratio /= one_minus;
    let mut second = Float::with_val(q, t.square_ref());
    second *= &ratio;
    second >>= 1;
    *x -= t;
    *x -= second;
}

/// A ball updated in place (no allocation a term): the midpoint rounded to nearest and
/// the radius widened by the inputs' radii and `2^(e - p)` a rounding.
struct Acc {
    mid: Float,
    rad: Mag,
    tmp: Float,
    /// Whether the radius is kept (else it stays 0: an estimate).
    track: bool,
}

fn rounding(m: &Float, ord: Ordering) -> Mag {
    if ord == Ordering::Equal {
        return Mag::ZERO;
    }
    match m.get_exp() {
        Some(e) => Mag::pow2(e as i64 - m.prec() as i64),
        None => Mag::inf(),
    }
}

/// `c` rounded up and down as a [`Mag`] (`c < 2^64`; the f64 conversion rounds to nearest).
fn word_up(c: u64) -> Mag {
    Mag::from_f64((c as f64).next_up())
}

fn word_down(c: u64) -> Mag {
    Mag::from_f64((c as f64).next_down())
}

impl Acc {
    fn new(p: u32, track: bool) -> Acc {
        Acc { mid: Float::new(p), rad: Mag::ZERO, tmp: Float::new(p), track }
    }

    fn set_one(&mut self) {
        self.mid.assign(1);
        self.rad = Mag::ZERO;
    }

    fn set(&mut self, b: &Ball) {
        let ord = self.mid.assign_round(b.mid(), Round::Nearest);
        if self.track {
            self.rad = b.rad_mag().add(rounding(&self.mid, ord));
        }
    }

    /// `self *= b` (a full product).
    fn mul(&mut self, b: &Ball) {
        let ord = self.tmp.assign_round(&self.mid * b.mid(), Round::Nearest);
        std::mem::swap(&mut self.mid, &mut self.tmp);
        if !self.track {
            return;
        }
        // |a b - a_m b_m| <= r_a |b_m| + (|a_m| + r_a) r_b, a = the old self
        let (factor, product) = (&self.tmp, &self.mid);
        let mut rad = rounding(product, ord).add(self.rad.mul(Mag::from_float_up(b.mid())));
        if !b.rad_mag().is_zero() {
            rad = rad.add(Mag::from_float_up(factor).add(self.rad).mul(b.rad_mag()));
        }
        self.rad = rad;
    }

    fn mul_u64(&mut self, c: u64) {
        let ord = self.mid.mul_assign_round(c, Round::Nearest);
        if self.track {
            self.rad = self.rad.mul(word_up(c)).add(rounding(&self.mid, ord));
        }
    }

    fn div_u64(&mut self, c: u64) {
        let ord = self.mid.div_assign_round(c, Round::Nearest);
        if self.track {
            self.rad = self.rad.div(word_down(c)).add(rounding(&self.mid, ord));
        }
    }

    fn add_u64(&mut self, c: u64) {
        let ord = self.mid.add_assign_round(c, Round::Nearest);
        if self.track {
            self.rad = self.rad.add(rounding(&self.mid, ord));
        }
    }

    /// `self += b c`.
    fn add_mul_u64(&mut self, b: &Ball, c: u64) {
        let o1 = self.tmp.assign_round(b.mid() * c, Round::Nearest);
        let r1 = if self.track { rounding(&self.tmp, o1) } else { Mag::ZERO };
        let o2 = self.mid.add_assign_round(&self.tmp, Round::Nearest);
        if self.track {
            self.rad = self.rad.add(b.rad_mag().mul(word_up(c))).add(r1).add(rounding(&self.mid, o2));
        }
    }

    fn ball(self) -> Ball {
        Ball::with_mag(self.mid, self.rad)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The series encloses `P_n` and `P_n'` of the three-term recurrence in exact
    /// rationals, at dyadic points inside and outside `[-1, 1]` and up to the largest
    /// degree an integration may ask (2048), and at the working
    /// precision for 300 bits its radii inside `[-1, 1]` stay below `2^-290`.
    #[test]
    fn series_encloses_exact_values() {
        use rug::Rational;
        for &n in &[2usize, 3, 4, 5, 10, 31, 64, 107, 300, 2048] {
            let plan = SeriesPlan::new(n, 400).unwrap();
            for (num, den) in [(0i64, 1i64), (1, 8), (-3, 16), (127, 128), (-1023, 1024), (1, 1), (5, 4)] {
                let xr = Rational::from((num, den));
                let (mut prev, mut cur) = (Rational::from(1), xr.clone());
                for k in 1..n {
                    let next = (Rational::from(2 * k + 1) * &xr * &cur - Rational::from(k) * &prev) / Rational::from(k + 1);
                    prev = std::mem::replace(&mut cur, next);
                }
                // P_n' = n (P_{n-1} - x P_n)/(1 - x^2), or P_n'(+-1) = (+-1)^(n-1) n(n+1)/2
                let xb = Ball::from_float(&Float::with_val(400, &xr), 400);
                let p = plan.working_prec(num as f64 / den as f64, 300);
                let (v, dv) = plan.eval(&xb, p).unwrap();
                let exact = Ball::from_float(&Float::with_val(800, &cur), 800);
                assert!(v.overlaps(&exact), "n {n} x {num}/{den}: {v:?} vs {cur}");
                if xr.clone().abs() != 1 {
                    let d = Rational::from(n) * (prev - xr.clone() * &cur) / (Rational::from(1) - xr.clone() * &xr);
                    assert!(dv.overlaps(&Ball::from_float(&Float::with_val(800, &d), 800)), "n {n} x {num}/{den}: P' {dv:?}");
                }
                // P_n'(0) = 0 for even n: no relative radius
                if num.abs() <= den && !(num == 0 && n % 2 == 0) {
                    assert!(v.rad_mag().le(&Mag::pow2(-290)), "n {n} x {num}/{den}: {:?}", v.rad_mag());
                    let rel = dv.rad_mag().div(dv.abs_lower_mag());
                    assert!(rel.le(&Mag::pow2(-280)), "n {n} x {num}/{den}: P' relative {rel:?}");
                }
            }
        }
    }
}
