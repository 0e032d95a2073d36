//! `2F1(a, b; c; z)` with one large parameter (`|a|` or `|b|` from about `10^3`
//! up, the other two moderate), for `z < 0` and `0 < z < 1`, over balls of
//! parameters.
//!
//! # Why
//!
//! With `b = 10^6` and `z = -1/2` every series in `z` or `w = z/(z-1)` runs to
//! about `b |z| / (1 - |z|) = 10^6` terms before it decays, the direct one with
//! about `b log2(1 + |z|)` bits of cancellation; and the majorant that bounds the
//! effect of the input radii (`ball_input.rs`) is `2F1(A, B; C; |z|)`, about
//! `2^(10^6)` times the value. Arb returns NaN and mpmath raises NoConvergence at
//! `2F1(1.5, 1000001; 24.74; -0.5)`.
//!
//! # Method
//!
//! The connection formulas whose series arguments do not depend on `b`:
//!
//! * `z < 0` [DLMF 15.8.2 with 15.8.1, A&S 15.3.8], `u = 1/(1-z) in (0, 1)`:
//!   `2F1 = G1 (1-z)^{-a} 2F1(a, c-b; a-b+1; u) + G2 (1-z)^{-b} 2F1(b, c-a; b-a+1; u)`,
//!   `G1 = Gamma(c) Gamma(b-a) / (Gamma(b) Gamma(c-a))`,
//!   `G2 = Gamma(c) Gamma(a-b) / (Gamma(a) Gamma(c-b))`; `b - a` not an integer.
//! * `0 < z < 1` [DLMF 15.8.4, A&S 15.3.6], `u = 1 - z`, `s = c - a - b` not an integer:
//!   `2F1 = G3 2F1(a, b; 1-s; u) + u^s G4 2F1(c-a, c-b; 1+s; u)`,
//!   `G3 = Gamma(c) Gamma(s) / (Gamma(c-a) Gamma(c-b))`, `G4 = Gamma(c) Gamma(-s) / (Gamma(a) Gamma(b))`.
//!
//! In each series the large parameter sits in a numerator and a denominator
//! whose difference `delta` is moderate (`c - b` over `a - b + 1`: `delta = a - c + 1`),
//! so its term ratio is `u (1 + O(delta / b))` times a moderate factor: about
//! `(wp + 64) / log2(1/u)` terms, independent of `b`. Everything is ball
//! arithmetic on the input balls (Gamma over a ball: `gamma_of_ball`, its psi
//! bound), so the result encloses the function over the balls without a
//! majorant.
//!
//! # Tail bound (the series with a large negative pair)
//!
//! Terms `t_{n+1} = t_n (p+n)(r+n) u / ((q+n)(n+1))`, with `p` paired with the
//! denominator `q` (`delta = max |p - q|`) and `r` with `n + 1` (`delta' = max |r - 1|`).
//! The engine of `series.rs` bounds the tail only past every negative
//! parameter (here `10^6` terms). Instead, after `N` terms:
//!
//! * `|p+k| / |q+k| <= 1 + delta / |q+k|` and `|r+k| / (k+1) <= 1 + delta' / (k+1)`.
//! * **Zone 1**, `N <= k < K`: if `q + N > 0` on the ball, `K = inf` and
//!   `|q+k| >= D = q_lo + N`; if `q + N < 0`, with `E = -q_hi - N`, `K = N + floor(E/2)`
//!   and `|q+k| >= D = E/2` there. The ratio is at most
//!   `rho = u_hi (1 + delta/D)(1 + delta'/(N+1))`, and if `rho < 1`,
//!   `sum_{N <= n < K} |t_n| <= |t_N| / (1 - rho)`, `|t_K| <= |t_N| rho^(K-N)`.
//! * **Zone 2**, `k >= K` (`q + k` crosses zero once): at most two `k` have
//!   `|q+k| < 1`, each `>= d0` (the ball's distance to the integers); the other
//!   `|q+k|` are distinct and spaced by 1 on each side of the crossing, so
//!   `sum 1/|q+k| <= 2 (1 + ln n)` over `K <= k < n`. Hence
//!   `prod_{k=K}^{n-1} |p+k|/|q+k| <= C n^m`, `C = (1 + delta/d0)^2 e^(2 delta)`,
//!   `m = 2 delta`; with `y = u_hi (1 + delta'/(K+1))` and `n^m <= K^m e^(m (n-K)/K)`,
//!   `sum_{n >= K} |t_n| <= |t_K| C K^m / (1 - y e^(m/K))` when `y e^(m/K) < 1`.
//!
//! Both pairings (`p` or `r` with `q`) are tried; every bound is computed with
//! upward rounding (MPFR), and the sum stops once the tail is below `2^-wp` of
//! the sum. The tail is added to the radius of the ball-arithmetic partial sum.
//!
//! # Choice
//!
//! [`large_param_terms`] estimates the terms of this route and is used by the
//! chooser (`choose.rs`) when the largest parameter is at least
//! [`LARGE_PARAM`] and [`RATIO_OTHERS`] times the others, and the estimate is
//! below both [`MAX_TERMS`] and the `b |z|` terms of the series in `z`.

use rug::float::Round;
use rug::ops::{AddAssignRound, AssignRound, DivAssignRound, MulAssignRound, Pow, SubAssignRound};
use rug::Float;

use crate::ball::{Ball, Scaled};
use crate::error::{Error, Result};
use crate::special::gamma::{gamma_of_ball_scaled, gamma_pair_scaled};
use crate::special::input_ball;
use crate::special::pfq::contains_pole;

/// Smallest `max(|a|, |b|)` for which the chooser considers this route.
pub(crate) const LARGE_PARAM: f64 = 1000.0;

/// Largest `max(|a|, |b|)` for this route (tested to `10^6`; at `4.3e18` the
/// ball path's Ziv loop ran for minutes: the other methods refuse those at once).
pub(crate) const LARGE_PARAM_MAX: f64 = 1.0e7;

/// The large parameter must be at least this many times `max(other, |c|) + 1`.
pub(crate) const RATIO_OTHERS: f64 = 16.0;

/// Most terms of one series of this route (beyond: [`Error::NoConvergence`]).
pub(crate) const MAX_TERMS: u64 = 100_000;

/// Precision of the tail-bound arithmetic (all rounded upward or downward as bounds).
const BOUND_PREC: u32 = 64;

/// Estimated terms of one series of this route at `bits` bits, when it applies
/// (the chooser's cost estimate; the certified bound never depends on it).
pub(crate) fn large_param_terms(a: f64, b: f64, c: f64, z: f64, bits: f64) -> Option<f64> {
    let (big, small) = if a.abs() >= b.abs() { (a.abs(), b.abs()) } else { (b.abs(), a.abs()) };
    let others = small.max(c.abs());
    if !(big >= LARGE_PARAM && big <= LARGE_PARAM_MAX && big >= RATIO_OTHERS * (others + 1.0)) || !(z < 1.0) || z == 0.0 {
        return None;
    }
    let u = if z < 0.0 { 1.0 / (1.0 - z) } else { 1.0 - z };
    let n = (bits + 64.0) / -u.log2() + 2.0 * (others + 1.0) / (1.0 - u);
    (n.is_finite() && n <= MAX_TERMS as f64).then_some(n)
}

/// Estimated bits the route's series lose to cancellation (the first Ziv
/// guard; an estimate only): a series `2F1(alpha, big; gamma; u)` whose moderate
/// parameter is negative cancels about `|alpha| log2((1+u)/(1-u))` bits
/// (`series_pair` takes the better of `alpha` and its Euler partner; in both
/// formulas the pairs are `(a, a-c+1)` and `(c-a, 1-a)`), plus `log2` of the
/// large parameter for the Gamma values and powers at it. The formulas are
/// symmetric in `a` and `b`; the estimate takes `b` as the large one (with `a =
/// 7.4e17` it read `c - a` as a moderate parameter of `-7.4e17` and planned
/// 65 536 guard bits, issue 37's scan).
pub(crate) fn large_param_loss(a: f64, b: f64, c: f64, z: f64) -> u32 {
    let (a, b) = if a.abs() > b.abs() { (b, a) } else { (a, b) };
    let u = if z < 0.0 { 1.0 / (1.0 - z) } else { 1.0 - z };
    let per = ((1.0 + u) / (1.0 - u)).log2();
    let eff = |alpha: f64, alt: f64| if alpha < 0.0 { alpha.max(alt) } else { alpha };
    let worst = eff(a, a - c + 1.0).min(eff(c - a, 1.0 - a)).min(0.0);
    let big = a.abs().max(b.abs()).max(2.0);
    (-worst * per + big.log2() + 8.0).clamp(0.0, 65536.0) as u32
}

/// Whether the route is estimated cheaper than the series in `z` or `w`, which
/// run to at least `big |z|` terms (about `big |z| / (1 - |z|)`), for `z < 0`
/// with up to `big log2(1 + |z|)` bits of cancellation: `terms` (from
/// [`large_param_terms`]) below twice that.
pub(crate) fn large_param_cheaper(a: f64, b: f64, z: f64, terms: f64) -> bool {
    terms < 2.0 * a.abs().max(b.abs()) * z.abs()
}

fn up(x: Float) -> Float {
    Float::with_val_round(BOUND_PREC, &x, Round::Up).0
}

fn add_up(a: &Float, b: &Float) -> Float {
    Float::with_val_round(BOUND_PREC, a + b, Round::Up).0
}

fn mul_up(a: &Float, b: &Float) -> Float {
    Float::with_val_round(BOUND_PREC, a * b, Round::Up).0
}

/// `a / b` rounded up (`a >= 0`, `b > 0` a lower bound).
fn div_up(a: &Float, b: &Float) -> Float {
    Float::with_val_round(BOUND_PREC, a / b, Round::Up).0
}

fn exp_up(x: &Float) -> Float {
    Float::with_val_round(BOUND_PREC, x.exp_ref(), Round::Up).0
}

/// `1 / (1 - x)` rounded up, for `0 <= x < 1` (`None` otherwise).
fn geometric_up(x: &Float) -> Option<Float> {
    let d = Float::with_val_round(BOUND_PREC, 1 - x, Round::Down).0;
    (d > 0).then(|| div_up(&Float::with_val(BOUND_PREC, 1), &d))
}

/// Lower bound of the distance of the ball to the nearest integer (0 if it holds one).
fn integer_distance(x: &Ball) -> Float {
    let (lo, hi) = (x.lower(), x.upper());
    let fl = Float::with_val(lo.prec(), lo.floor_ref());
    let ce = Float::with_val(hi.prec(), hi.ceil_ref());
    if fl != Float::with_val(hi.prec(), hi.floor_ref()) || lo.is_integer() || hi.is_integer() {
        return Float::new(BOUND_PREC);
    }
    let d1 = Float::with_val_round(BOUND_PREC, &lo - &fl, Round::Down).0;
    let d2 = Float::with_val_round(BOUND_PREC, &ce - &hi, Round::Down).0;
    if d1 < d2 {
        d1
    } else {
        d2
    }
}

/// Upper bound of `sum_{n >= N} |t_n|` given `|t_N| <= t_abs`, for the pairing
/// `p` with `q` and `r` with `n + 1` (module docs), or `None` when it does not
/// yet bound the tail.
fn tail_bound(p: &Ball, r: &Ball, q: &Ball, u_hi: &Float, n: u64, t_abs: &Float) -> Option<Float> {
    let one = Float::with_val(BOUND_PREC, 1);
    let delta = up(p.sub(q).abs_upper());
    let delta_r = up(r.add_i64(-1).abs_upper());
    let nf = Float::with_val(BOUND_PREC, n);
    let r_factor = |k: &Float| add_up(&one, &div_up(&delta_r, &Float::with_val_round(BOUND_PREC, k + 1u32, Round::Down).0));
    let q_lo_n = Float::with_val_round(BOUND_PREC, q.lower() + n, Round::Down).0;
    let q_hi_n = Float::with_val_round(BOUND_PREC, q.upper() + n, Round::Up).0;
    // zone 1
    let (d1, k_end) = if q_lo_n > 0 {
        (q_lo_n, None)
    } else if q_hi_n < 0 {
        let e = Float::with_val_round(BOUND_PREC, -&q_hi_n, Round::Down).0;
        let half = Float::with_val_round(BOUND_PREC, &e / 2u32, Round::Down).0;
        // K - N as a float: at a parameter of 7.4e17 it is about 3.7e17 (an
        // integer past f64's exact range, and past u64 at 10^20), where
        // rho^(K-N) makes zone 2 vanish; only its bound's inputs need it
        let steps = Float::with_val(BOUND_PREC, half.floor_ref());
        if !(steps >= 1) {
            return None;
        }
        (half, Some(steps))
    } else {
        return None;
    };
    let rho = mul_up(&mul_up(u_hi, &add_up(&one, &div_up(&delta, &d1))), &r_factor(&nf));
    let zone1 = geometric_up(&rho)?;
    let Some(steps) = k_end else { return Some(mul_up(t_abs, &zone1)) };
    // zone 2
    let d0 = integer_distance(q);
    if !(d0 > 0) {
        return None;
    }
    let kf = Float::with_val_round(BOUND_PREC, &nf + &steps, Round::Down).0;
    let m = mul_up(&delta, &Float::with_val(BOUND_PREC, 2));
    let near = add_up(&one, &div_up(&delta, &d0));
    let c = mul_up(&mul_up(&near, &near), &exp_up(&m));
    let y = mul_up(u_hi, &r_factor(&kf));
    let grow = exp_up(&div_up(&m, &kf));
    let zone2_geom = geometric_up(&mul_up(&y, &grow))?;
    let k_up = Float::with_val_round(BOUND_PREC, &nf + &steps, Round::Up).0;
    let k_pow = Float::with_val_round(BOUND_PREC, (&k_up).pow(&m), Round::Up).0;
    // K = N + steps, an integer with K - N <= E/2 (what zone 1 needs); where K
    // itself is rounded, it is rounded the way that enlarges each bound (down in
    // `r_factor` and `e^(m/K)`, up in `K^m`)
    let rho_pow = Float::with_val_round(BOUND_PREC, (&rho).pow(&steps), Round::Up).0;
    let zone2 = mul_up(&mul_up(&mul_up(&rho_pow, &c), &k_pow), &zone2_geom);
    let total = mul_up(t_abs, &add_up(&zone1, &zone2));
    total.is_finite().then_some(total)
}

/// Lower bound of `min_k |p~ + k|` over `k >= 0` for the midpoint `p~` of a
/// parameter ball (its own value when positive, else its distance to the
/// integers; 0 at a non-positive integer).
fn min_shifted(p: &Ball) -> Float {
    let m = p.mid();
    if *m > 0 {
        return Float::with_val_round(BOUND_PREC, m, Round::Down).0;
    }
    integer_distance(&Ball::from_float(m, m.prec()))
}

/// `2F1(p1, p2; q; x)` over balls, `0 < x < 1` on its ball: the terms at the
/// midpoints summed in place at `wp` bits, with the rounding and input-radius
/// bounds below and the zoned tail bound of the module docs.
///
/// Rounding (as `series.rs`): at most 8 roundings a step, so
/// `|t~_n - t_n(mid)| <= 10 n u |t~_n|` (`u = 2^-wp`), and each addition errs by
/// at most `2 u |s~_k|`. Input radii: each factor `p + k` is `(p~ + k)(1 + e)`
/// with `|e| <= r_p / m_p`, `m_p <= min_k |p~ + k|` ([`min_shifted`]); a
/// denominator factor moves by at most twice that while `r_q / m_q <= 1/2`; `x`
/// by `r_x / x~`. So `|t_n(p) - t_n(mid)| <= expm1(n eta) |t_n(mid)|`,
/// `eta = r_1/m_1 + r_2/m_2 + 2 r_q/m_q + r_x/x~`, summed over `n < N` against
/// `sum |t~_n|`, and `|t_N| <= |t~_N| (1 + 10 N u)(1 + expm1(N eta))` enters the tail.
pub(crate) fn series_zoned(p1: &Ball, p2: &Ball, q: &Ball, x: &Ball, wp: u32) -> Result<Ball> {
    if !(x.lower() > 0 && x.upper() < 1) {
        return Err(Error::precondition("zoned 2F1 series needs 0 < x < 1"));
    }
    if let Some(pole) = contains_pole(q, None) {
        return Err(Error::Pole { function: "2F1 series denominator", at: pole as f64 });
    }
    let wp = wp.max(64);
    let one = Float::with_val(BOUND_PREC, 1);
    // eta of the docs (infinite when a midpoint sits on a non-positive integer
    // with a radius around it, or a denominator radius is too wide)
    let eta = {
        let part = |b: &Ball, twice: bool| -> Float {
            if b.is_exact() {
                return Float::new(BOUND_PREC);
            }
            let m = min_shifted(b);
            let e = div_up(&up(b.rad()), &m);
            if twice {
                if e > 0.5 || !(m > 0) {
                    return Float::with_val(BOUND_PREC, f64::INFINITY);
                }
                mul_up(&e, &Float::with_val(BOUND_PREC, 2))
            } else if m > 0 {
                e
            } else {
                Float::with_val(BOUND_PREC, f64::INFINITY)
            }
        };
        let ex = if x.is_exact() {
            Float::new(BOUND_PREC)
        } else {
            div_up(&up(x.rad()), &Float::with_val_round(BOUND_PREC, x.mid(), Round::Down).0)
        };
        add_up(&add_up(&part(p1, false), &part(p2, false)), &add_up(&part(q, true), &ex))
    };
    if !eta.is_finite() {
        return Err(Error::precondition("zoned 2F1 series: a parameter ball too wide for its midpoint bound"));
    }
    let (m1, m2, mq, mx) = (p1.mid(), p2.mid(), q.mid(), x.mid());
    let u_hi = up(x.upper());
    let mut t = Float::with_val(wp, 1);
    let mut s = Float::with_val(wp, 1);
    let (mut an, mut bn, mut cn) = (Float::new(wp), Float::new(wp), Float::new(wp));
    let mut abs_sum = Float::with_val(BOUND_PREC, 1);
    let mut max_s = Float::with_val(BOUND_PREC, 1);
    let mut next_try = 0u64;
    let mut n = 0u64;
    let unit = Float::with_val(BOUND_PREC, 1) >> wp;
    // 1 + 10 n u and 1 + expm1(n eta), upward
    let rounding = |n: u64| add_up(&one, &mul_up(&Float::with_val(BOUND_PREC, 10 * n.max(1)), &unit));
    let perturb = |n: u64| {
        let mut e = mul_up(&eta, &Float::with_val(BOUND_PREC, n.max(1)));
        e.exp_m1_round(Round::Up);
        e
    };
    loop {
        an.assign_round(m1 + n, Round::Nearest);
        bn.assign_round(m2 + n, Round::Nearest);
        cn.assign_round(mq + n, Round::Nearest);
        if cn.is_zero() {
            return Err(Error::Pole { function: "2F1 series denominator", at: mq.to_f64() });
        }
        t.mul_assign_round(&an, Round::Nearest);
        t.mul_assign_round(&bn, Round::Nearest);
        t.mul_assign_round(mx, Round::Nearest);
        t.div_assign_round(&cn, Round::Nearest);
        t.div_assign_round(n + 1, Round::Nearest);
        n += 1;
        if !t.is_finite() {
            return Err(Error::Overflow { what: "2F1 series term (large-parameter route)".into() });
        }
        // cheap test first: |t~_N| below 2^-wp of the sum (or 2^-2wp of sum |t|)
        let small = |v: &Float, shift: u32| match (t.get_exp(), v.get_exp()) {
            (None, _) => true,
            (Some(et), Some(ev)) => (et as i64) + (shift as i64) + 2 <= ev as i64,
            _ => false,
        };
        // t~ = 0: a numerator is an exact non-positive integer (a ball around
        // one has an infinite eta, refused above): every later term is 0 too
        let terminated = t.is_zero();
        if terminated || (n >= next_try && (small(&s, wp) || small(&abs_sum, 2 * wp))) {
            let t_abs = mul_up(&mul_up(&up(t.clone().abs()), &rounding(n)), &add_up(&one, &perturb(n)));
            let tail = if terminated {
                Some(Float::new(BOUND_PREC))
            } else {
                [(p1, p2), (p2, p1)]
                    .iter()
                    .filter_map(|(p, r)| tail_bound(p, r, q, &u_hi, n, &t_abs))
                    .min_by(|a, b| a.partial_cmp(b).unwrap_or(std::cmp::Ordering::Equal))
            };
            if let Some(tail) = tail {
                let s_abs = Float::with_val_round(BOUND_PREC, s.abs_ref(), Round::Down).0;
                if terminated || tail <= Float::with_val(BOUND_PREC, &s_abs >> wp) || tail <= Float::with_val(BOUND_PREC, &abs_sum >> (2 * wp)) {
                    // rounding: 10 N u sum|t~| + 2 N u max|s~|; radii: expm1(N eta)(1 + 10 N u) sum|t~|
                    let nn = Float::with_val(BOUND_PREC, n);
                    let term_err = mul_up(&mul_up(&abs_sum, &mul_up(&nn, &Float::with_val(BOUND_PREC, 10))), &unit);
                    let sum_err = mul_up(&mul_up(&max_s, &mul_up(&nn, &Float::with_val(BOUND_PREC, 2))), &unit);
                    let radius_err = mul_up(&mul_up(&perturb(n), &rounding(n)), &abs_sum);
                    let rad = add_up(&add_up(&tail, &term_err), &add_up(&sum_err, &radius_err));
                    return Ok(Ball::with_radius(s, &rad));
                }
            }
            next_try = n + 8;
        }
        s.add_assign_round(&t, Round::Nearest);
        if t.is_sign_negative() {
            abs_sum.sub_assign_round(&t, Round::Up);
        } else {
            abs_sum.add_assign_round(&t, Round::Up);
        }
        if s.cmp_abs(&max_s) == Some(std::cmp::Ordering::Greater) {
            max_s = up(s.clone().abs());
        }
        if n > MAX_TERMS {
            return Err(Error::NoConvergence { function: "hyp2f1 (large-parameter route)", terms: n });
        }
        if n % crate::budget::TERMS_BETWEEN_CHECKS == 0 {
            crate::budget::check_elapsed("2F1 connection series (large-parameter route)", 0.0, crate::error::Reached::Terms { count: n })?;
        }
    }
}

/// `2F1(alpha, big; gamma; u)` with `big` and `gamma` the large pair and
/// `one_minus_u` enclosing `1 - u`: when `alpha < 0` its first terms alternate and
/// cancel (about `|alpha| log2((1+u)/(1-u))` bits: the sum is near
/// `(1-u)^-alpha`), so Euler's transformation [DLMF 15.8.1]
/// `(1-u)^(gamma-alpha-big) 2F1(gamma-alpha, gamma-big; gamma; u)` is summed
/// instead when `gamma - big` is the larger (the pair stays large, the moderate
/// parameter becomes `gamma - big`). In all four series of the route
/// `gamma - alpha - big = 1 - c`; the caller passes `euler = (gamma - alpha,
/// gamma - big)` formed from the inputs directly (`1 - b`, not `(c-a-b+1) - (c-a)`,
/// whose ball would hold the integer `1 - b` with a radius around it).
struct SeriesPair<'a> {
    alpha: &'a Ball,
    big: &'a Ball,
    gamma: &'a Ball,
    euler: (Ball, Ball),
}

impl SeriesPair<'_> {
    /// Whether Euler's form is summed (its moderate parameter is the larger).
    fn takes_euler(&self) -> bool {
        self.alpha.mid().is_sign_negative() && self.euler.1.mid() > self.alpha.mid()
    }

    /// Estimated bits the summed form cancels at `u` (an estimate only: it sets
    /// the precision of the sum, never its bound): `|m| log2((1+u)/(1-u))` for
    /// a negative moderate parameter `m`, else 0.
    fn cancellation(&self, u: f64) -> u32 {
        let m = if self.takes_euler() { self.euler.1.mid().to_f64() } else { self.alpha.mid().to_f64() };
        let per = ((1.0 + u) / (1.0 - u)).log2();
        if m < 0.0 && per.is_finite() {
            (-m * per).clamp(0.0, 65536.0) as u32
        } else {
            0
        }
    }

    fn sum(&self, one_minus_c: &Ball, u: &Ball, one_minus_u: &Ball, wp: u32) -> Result<Ball> {
        if self.takes_euler() {
            // a base longer than the working precision (`1 - u` at `u = 1/(1 - z)`,
            // `z = -1.7e30833`: about 10^5 bits) is rounded into its ball first: `ln` at
            // its own length took 0.4 s (issue 37's scan), for the same enclosure at `wp`
            let pre = Scaled::pow(one_minus_u, one_minus_c, wp)?;
            return pre.mul_ball(&series_zoned(&self.euler.0, &self.euler.1, self.gamma, u, wp)?).to_ball(wp);
        }
        series_zoned(self.alpha, self.big, self.gamma, u, wp)
    }
}

/// The two series of a formula at their own precisions: `wp` (which the
/// chooser's planned loss raised for the series that cancels most) less the
/// bits by which each cancels less than the other. A series of positive terms
/// next to one that cancels 250 bits (`2F1(-47.3, 1e6; 12.9; -0.05)`: 11 859
/// terms at 561 bits) is summed at the precision its own terms need; a sum's
/// bound holds at any precision, and the Ziv loop raises `wp` for both if the
/// estimate was short.
fn sum_both(s1: &SeriesPair, s2: &SeriesPair, one_minus_c: &Ball, u: &Ball, one_minus_u: &Ball, wp: u32) -> Result<(Ball, Ball)> {
    let uf = u.mid().to_f64();
    let (c1, c2) = (s1.cancellation(uf), s2.cancellation(uf));
    let worst = c1.max(c2);
    let at = |c: u32| wp.saturating_sub(worst - c).max(64);
    Ok((s1.sum(one_minus_c, u, one_minus_u, at(c1))?, s2.sum(one_minus_c, u, one_minus_u, at(c2))?))
}

/// `Gamma(x1) Gamma(x2) / (Gamma(y1) Gamma(y2))` over balls without poles, in
/// logarithms where a Gamma passes the exponent range (`Scaled`).
fn gamma_quotient(num: [&Ball; 2], den: [&Ball; 2], wp: u32) -> Result<Scaled> {
    let n = gamma_of_ball_scaled(num[0], wp)?.mul(&gamma_of_ball_scaled(num[1], wp)?);
    let d = gamma_of_ball_scaled(den[0], wp)?.mul(&gamma_of_ball_scaled(den[1], wp)?);
    n.div(&d)
}

/// Most bits of [`difference`]'s exact midpoint.
const DIFFERENCE_MAX_BITS: u32 = 1 << 17;

/// `x - y` over balls with the midpoints' difference exact (up to
/// [`DIFFERENCE_MAX_BITS`], else rounded as `Ball::sub`): `c - 19` at `c =
/// 5e-21621` keeps its distance to the pole `-19`, which a rounding to the
/// working precision would swallow (the formula's Gammas and the series' lower
/// parameter `a - b + 1` need it; issue 37's scan). The radius is the sum of
/// the radii; the series engine rounds each `p + n` from the midpoint, so a long
/// midpoint costs one long addition a term.
pub(super) fn difference(x: &Ball, y: &Ball) -> Ball {
    let m = crate::special::exact_sub(x.mid(), y.mid());
    if m.prec() > DIFFERENCE_MAX_BITS {
        return x.sub(y);
    }
    Ball::with_mag(m, x.rad_mag().add(y.rad_mag()))
}

/// The route of the module docs at working precision `wp`, over balls of
/// parameters and `z` (`z < 0` or `0 < z < 1` on its ball). Errors when a
/// needed difference (`b - a`, or `c - a - b`) holds an integer or a Gamma
/// argument holds a pole: the caller then takes another method.
pub(crate) fn hyp2f1_large_param(a: &Ball, b: &Ball, c: &Ball, z: &Ball, wp: u32) -> Result<Ball> {
    let [a, b, c, z] = [a, b, c, z].map(|x| input_ball(x, wp));
    let one = Ball::one(wp);
    let (ca, cb) = (difference(&c, &a), difference(&c, &b));
    let omc = c.neg().add_i64(1);
    if z.upper() < 0 {
        let omz = one.sub(&z);
        let u = omz.recip()?;
        let (ba, ab) = (difference(&b, &a), difference(&a, &b));
        // `c - a` (or `c - b`) an exact non-positive integer: `1/Gamma(c - a) = 0`
        // and that term vanishes (its other factors are finite: `b - a` is not an
        // integer, else the route fails above). `2F1(2, 29.65; 1; -5.4e7163)` was
        // refused PrecisionExhausted (the Gamma pole sent it to Pfaff, `w` within
        // `1e-7164` of 1: issue 37's scan)
        let vanishes = |x: &Ball| x.is_exact() && crate::special::is_nonpositive_integer(x.mid());
        // G1 = [Gamma(c) / Gamma(c - a)] [Gamma(b - a) / Gamma(b)], G2 likewise
        // with a and b exchanged: each pair by its difference (`gamma_pair_scaled`)
        let g1 = if vanishes(&ca) {
            None
        } else {
            Some(gamma_pair_scaled(&c, &ca, &a, wp)?.mul(&gamma_pair_scaled(&ba, &b, &a.neg(), wp)?))
        };
        let g2 = if vanishes(&cb) {
            None
        } else {
            Some(gamma_pair_scaled(&c, &cb, &b, wp)?.mul(&gamma_pair_scaled(&ab, &a, &b.neg(), wp)?))
        };
        let omu = z.neg().mul(&u);
        let e1 = (b.neg().add_i64(1), a.sub(&c).add_i64(1));
        let e2 = (b.sub(&c).add_i64(1), a.neg().add_i64(1));
        // the powers: `Scaled::pow` rounds `1 - z` (a decimal tightened to 54 000
        // bits: `ln` and `exp` at that length, issue 37's scan) to `wp` bits, or
        // to the bits a large `|a ln(1 - z)|` needs
        let (q1, q2) = (ab.add_i64(1), ba.add_i64(1));
        let s1 = SeriesPair { alpha: &a, big: &cb, gamma: &q1, euler: e1 };
        let s2 = SeriesPair { alpha: &ca, big: &b, gamma: &q2, euler: e2 };
        // each term's Gamma quotient and power in logarithms, formed once
        // (a term below the exponent range, `2^(-5.5e18)` at `a = 7.4e17`, `z =
        // -177.9`, goes into the radius)
        let term = |g: Scaled, e: &Ball, f: &Ball| -> Result<Scaled> { Ok(g.mul(&Scaled::pow(&omz, &e.neg(), wp)?).mul_ball(f)) };
        let terms = match (g1, g2) {
            (Some(g1), Some(g2)) => {
                let (f1, f2) = sum_both(&s1, &s2, &omc, &u, &omu, wp)?;
                vec![term(g1, &a, &f1)?, term(g2, &b, &f2)?]
            }
            (Some(g1), None) => vec![term(g1, &a, &s1.sum(&omc, &u, &omu, wp)?)?],
            (None, Some(g2)) => vec![term(g2, &b, &s2.sum(&omc, &u, &omu, wp)?)?],
            // both vanish only with `b - a` an integer too (the logarithmic case)
            (None, None) => return Err(Error::precondition("large-parameter 2F1 route: c - a and c - b both non-positive integers")),
        };
        return Scaled::sum_to_value(&terms, wp);
    }
    if z.lower() > 0 && z.upper() < 1 {
        let u = one.sub(&z);
        let s = ca.sub(&b);
        let neg_s = s.neg();
        let g3 = gamma_pair_scaled(&c, &ca, &a, wp)?.mul(&gamma_pair_scaled(&s, &cb, &a.neg(), wp)?);
        let g4 = gamma_quotient([&c, &neg_s], [&a, &b], wp)?;
        let e3 = (b.sub(&c).add_i64(1), a.sub(&c).add_i64(1));
        let e4 = (b.neg().add_i64(1), a.neg().add_i64(1));
        let (q3, q4) = (neg_s.add_i64(1), s.add_i64(1));
        let s3 = SeriesPair { alpha: &a, big: &b, gamma: &q3, euler: e3 };
        let s4 = SeriesPair { alpha: &ca, big: &cb, gamma: &q4, euler: e4 };
        let (f3, f4) = sum_both(&s3, &s4, &omc, &u, &z, wp)?;
        let t1 = g3.mul_ball(&f3);
        let t2 = g4.mul(&Scaled::pow(&u, &s, wp)?).mul_ball(&f4);
        return Scaled::sum_to_value(&[t1, t2], wp);
    }
    Err(Error::precondition("large-parameter 2F1 route needs z < 0 or 0 < z < 1"))
}
