//! The generalized hypergeometric series pFq with a rigorous tail bound.
//!
//! # Method
//!
//! `pFq(a; b; z) = sum_n t_n`, `t_0 = 1`,
//! `t_{n+1} = t_n * z * prod_i (a_i + n) / (prod_j (b_j + n) * (n + 1))` [DLMF 16.2.1].
//!
//! The terms are computed in ball arithmetic, so every rounding is inside the
//! result. Summation stops at the first `N` past every negative parameter
//! (`a_i + N >= 0`, `b_j + N > 0`) where the tail bound below is smaller than
//! `2^-wp` times the partial sum.
//!
//! # Tail bound
//!
//! For `n >= N` with all shifted parameters positive, pair each numerator
//! `a_i + n` with a denominator `d_i + n` from `(b_1, ..., b_q, 1)` (both sorted
//! by size, which keeps the bound tight; any pairing is valid):
//! `(a_i + n)/(d_i + n) <= max(1, (a_i^+ + N)/(d_i^- + N))` because the ratio is
//! monotone in `n` (`a^+` is the ball's upper end, `d^-` the lower end).
//! Each unpaired denominator contributes `1/(d^- + N)`. Hence
//! `|t_{n+1}/t_n| <= rho_N := |z|^+ * prod_pairs max(1, ...) * prod_unpaired 1/(d^- + N)`
//! for all `n >= N`, and if `rho_N < 1`,
//! `sum_{n>=N} |t_n| <= |t_N| / (1 - rho_N)`.
//!
//! **Two zones.** A paired factor with `a^+ <= d^-` is at most 1, and bounding it
//! by 1 over all later `n` can keep `rho_N >= 1` for thousands of terms where
//! the factor itself is tiny (`1F2(-1e-24686; 20.12, 1e31099; 16777217)`: the
//! factor `(a+n)/(b2+n)` is about `10^-31099`). It increases with `n`, so over
//! `N <= n < M` (`TAIL_ZONE_END`, `2^32`) it is at most its value at `M`; with
//! `rho_1` the ratio bound over that zone and `rho_2 = rho_M`, when both are
//! below 1: `sum_{n>=N} |t_n| <= |t_N| (1/(1 - rho_1) + rho_1^(M-N)/(1 - rho_2))`.
//! `rho_1` is non-increasing in `N` and `rho_1 <= rho_N`, so whether a bound
//! exists is monotone in `N` (the cost model below relies on it).
//!
//! All of `rho_N` is computed with upward (numerators) and downward
//! (denominators) rounding. This is the bound of Arb's `hypgeom` module in its
//! simplest form (cf. F. Johansson, "Computing hypergeometric functions
//! rigorously", ACM TOMS 45 (2019), Sec. 4).
//!
//! # Domain
//!
//! * `p <= q`: every `z`;
//! * `p = q + 1`: `|z| < 1` (callers transform other arguments first);
//! * `p > q + 1`, or any `p` with a numerator an exact non-positive integer: the
//!   series terminates, every `z`.
//!
//! A denominator equal to a non-positive integer is a pole and an error unless
//! the series terminates before reaching it.
//!
//! # Cost
//!
//! Before summing, `check_series_cost` proves a lower bound of the terms the
//! loop must run (it stops only where the ratio bound is below 1, and that bound
//! is non-increasing in `n`) and refuses with [`Error::TooExpensive`] when the
//! estimated time passes [`MAX_SERIES_SECONDS`] (for example
//! `1F2(3.7e18; 20.03, -179.875; 23.7)`, whose terms grow for 4.4 million steps).
//!
//! # f64 path
//!
//! `pfq_f64` sums the same recurrence in f64 and returns an error *estimate*:
//! each term carries at most `c n` roundings (`c = 2 (p + q + 2)`), so with
//! `u = 2^-53`, `|error| <~ ((c + 1) N u) * sum |t_n| + tail`. It is an estimate,
//! not a proof (the bound itself is evaluated in f64); [`hyp_pfq`] uses it only
//! to decide whether to trust the fast result or to fall back to the MP path.

use rug::float::Round;
use rug::ops::AssignRound;
use rug::Float;

use crate::ball::{Ball, Mag, MAG_PREC};
use crate::error::{Error, Result};

/// Names of the lower parameters in errors.
const LOWER_PARAMETER_NAMES: [&str; 8] = ["b1", "b2", "b3", "b4", "b5", "b6", "b7", "b8"];
use crate::special::{check_finite, exact, f64_from_mp, ziv, DEFAULT_GUARD_BITS};

/// Hard cap on the number of series terms.
pub(crate) const MAX_SERIES_TERMS: u64 = 5_000_000;

/// Relative error-estimate threshold under which the f64 fast path is trusted:
/// the f64 functions built on this core promise `1e-14` relative.
pub const F64_TRUST: f64 = 4e-15;

/// A summed series: the enclosure of the full sum and a cancellation measure.
/// (`abs_sum`, `terms` and `cancellation_bits` are diagnostics for callers'
/// guard estimates; no caller reads them at present.)
#[derive(Debug, Clone)]
#[allow(dead_code)]
pub(crate) struct SeriesSum {
    /// Ball containing the whole infinite sum (tail included).
    pub sum: Ball,
    /// Upper bound on `sum |t_n|` over the summed terms.
    pub abs_sum: Float,
    /// Number of terms summed.
    pub terms: u64,
}

#[allow(dead_code)]
impl SeriesSum {
    /// Bits lost to cancellation, `log2(sum |t_n| / |sum|)`, as an estimate for
    /// the guard bits of the next Ziv round.
    pub fn cancellation_bits(&self) -> u32 {
        let s = self.sum.mid().to_f64().abs();
        let a = self.abs_sum.to_f64();
        if s == 0.0 || !s.is_finite() || !a.is_finite() {
            // Values outside the f64 range: compare exponents.
            let es = self.sum.mid().get_exp().unwrap_or(i32::MIN / 2) as i64;
            let ea = self.abs_sum.get_exp().unwrap_or(0) as i64;
            return (ea - es).clamp(0, 1 << 20) as u32;
        }
        (a / s).log2().max(0.0).ceil() as u32
    }
}

/// The refusal of a series whose tail bound starts only past a parameter of
/// `-terms` (at least `terms` terms, `terms >= 10^15`): a cost, not the input's
/// fault (it was `OutOfRange`, which read as a domain error: issue 37's scan met
/// it at `c - a = -2.7e29278` once the Gammas there were answered in logarithms).
pub(crate) fn series_past_negative_parameter(function: &'static str, terms: f64) -> Error {
    let per_term = seconds_per_term(64);
    let limit = crate::budget::limit_seconds(MAX_SERIES_TERMS as f64 * per_term);
    Error::TooExpensive { function, seconds: (terms * per_term).max(limit.next_up()), limit_seconds: limit }
}

/// Smallest `N >= 0` with `x + N > 0` for every ball `x` (its lower end).
fn first_positive_index(params: &[Ball]) -> Result<u64> {
    let mut n = 0u64;
    for p in params {
        let lo = p.lower();
        if lo <= 0 {
            let m = Float::with_val(64, -&lo).ceil();
            let m = m.to_f64();
            if !(m.is_finite() && m < 1e15) {
                return Err(series_past_negative_parameter("hypergeometric series (a parameter below -1e15)", m));
            }
            n = n.max(m as u64 + 1);
        }
    }
    Ok(n)
}

/// The ratio bound `rho_N` of the module docs (rounded upward).
///
/// Any pairing of numerators with denominators gives a valid bound; pairing the
/// largest numerator with the largest denominator (both sorted) gives a tight one.
fn ratio_bound(a: &[Ball], b: &[Ball], z: &Ball, n: u64) -> Float {
    ratio_bound_to(a, b, z, n, None)
}

/// End `M` of the first zone of the two-zone tail bound (module docs).
const TAIL_ZONE_END: u64 = 1 << 32;

/// [`ratio_bound`] over `N <= n < m` when `m` is given: a paired factor
/// `(a + n)/(d + n)` that is at most 1 at `N` (`a^+ <= d^-`) increases with `n`,
/// so over the zone it is below its value at `m` (instead of 1).
fn ratio_bound_to(a: &[Ball], b: &[Ball], z: &Ball, n: u64, zone_end: Option<u64>) -> Float {
    let nn = Float::with_val(64, n);
    let mut rho = z.abs_upper();
    let one = Float::with_val(MAG_PREC, 1);
    let infinity = || Float::with_val(MAG_PREC, rug::float::Special::Infinity);
    let mut numerators: Vec<Float> = a.iter().map(|x| x.upper()).collect();
    let mut denominators: Vec<Float> = b.iter().map(|d| d.lower()).chain(std::iter::once(one.clone())).collect();
    let by_value_desc = |x: &Float, y: &Float| y.partial_cmp(x).unwrap_or(std::cmp::Ordering::Equal);
    numerators.sort_by(by_value_desc);
    denominators.sort_by(by_value_desc);
    if numerators.len() > denominators.len() {
        // More numerators than denominators: no geometric bound.
        return infinity();
    }
    for (i, d) in denominators.iter().enumerate() {
        let mut den = Float::new(MAG_PREC);
        den.assign_round(d + &nn, Round::Down);
        if den <= 0 {
            return infinity();
        }
        let mut f = Float::new(MAG_PREC);
        match numerators.get(i) {
            Some(ai) => {
                let mut num = Float::new(MAG_PREC);
                num.assign_round(ai + &nn, Round::Up);
                f.assign_round(&num / &den, Round::Up);
                if f <= one {
                    let Some(m) = zone_end else { continue };
                    let mm = Float::with_val(64, m);
                    let mut num_m = Float::new(MAG_PREC);
                    num_m.assign_round(ai + &mm, Round::Up);
                    let mut den_m = Float::new(MAG_PREC);
                    den_m.assign_round(d + &mm, Round::Down);
                    f.assign_round(&num_m / &den_m, Round::Up);
                    if f >= one {
                        continue;
                    }
                }
            }
            None => {
                f.assign_round(&one / &den, Round::Up);
            }
        }
        let mut r = Float::new(MAG_PREC);
        r.assign_round(&rho * &f, Round::Up);
        rho = r;
    }
    rho
}

/// `K` with `sum_{n >= N} |t_n| <= K |t_N|` (rounded upward), or `None` where no
/// bound holds yet: `1 / (1 - rho_N)` when [`ratio_bound`] is below 1, else the
/// two-zone bound of the module docs.
fn tail_multiplier(a: &[Ball], b: &[Ball], z: &Ball, n: u64) -> Option<Float> {
    let one = Float::with_val(MAG_PREC, 1);
    let geometric = |rho: &Float| -> Option<Float> {
        let d = Float::with_val_round(MAG_PREC, &one - rho, Round::Down).0;
        (d > 0).then(|| Float::with_val_round(MAG_PREC, &one / &d, Round::Up).0)
    };
    let rho = ratio_bound(a, b, z, n);
    if rho < 1 {
        return geometric(&rho);
    }
    if n >= TAIL_ZONE_END {
        return None;
    }
    let rho1 = ratio_bound_to(a, b, z, n, Some(TAIL_ZONE_END));
    let first = geometric(&rho1)?;
    let second = geometric(&ratio_bound(a, b, z, TAIL_ZONE_END))?;
    let steps = Float::with_val(64, TAIL_ZONE_END - n);
    let decay = Float::with_val_round(MAG_PREC, rug::ops::Pow::pow(&rho1, &steps), Round::Up).0;
    let rest = Float::with_val_round(MAG_PREC, &decay * &second, Round::Up).0;
    let k = Float::with_val_round(MAG_PREC, &first + &rest, Round::Up).0;
    k.is_finite().then_some(k)
}

/// Sums `pFq(a; b; z)` in ball arithmetic at working precision `wp`, tail included.
pub(crate) fn pfq_series(a: &[Ball], b: &[Ball], z: &Ball, wp: u32) -> Result<SeriesSum> {
    let p = a.len();
    let q = b.len();
    let terminates = a.iter().any(|x| x.is_exact_nonpositive_integer());
    if !terminates {
        if p > q + 1 {
            return Err(Error::Divergent {
                function: "pFq with p > q + 1",
                needs: "z = 0 or a terminating series (a numerator parameter a non-positive integer)",
                value: z.to_f64(),
            });
        }
        if p == q + 1 && z.abs_upper() >= 1 {
            return Err(Error::Divergent { function: "pFq series with p = q + 1", needs: "|z| < 1", value: z.to_f64() });
        }
    }
    let mut t = Ball::one(wp);
    let mut s = Ball::one(wp);
    let mut abs_sum = Mag::from_f64(1.0);
    let finish = |sum: Ball, abs_sum: Mag, terms: u64| SeriesSum { sum, abs_sum: abs_sum.to_float(), terms };
    if z.is_exact() && z.mid().is_zero() {
        return Ok(finish(s, abs_sum, 1));
    }
    let n_pos = first_positive_index(a)?.max(first_positive_index(b)?);
    let mut n: u64 = 0;
    loop {
        // t_{n+1} = t_n z prod(a+n) / (prod(b+n) (n+1))
        let mut num = z.clone();
        for ai in a {
            num = num.mul(&ai.add_i64(n as i64));
        }
        let mut den = Ball::from_i64(n as i64 + 1, wp);
        for bj in b {
            let d = bj.add_i64(n as i64);
            if d.contains_zero() {
                if d.is_exact() {
                    let pole = -(n as f64);
                    return Err(Error::ParameterPole { function: "pFq", arg: "b", pole, lower: pole, upper: pole });
                }
                return Err(Error::DivisionByZero);
            }
            den = den.mul(&d);
        }
        t = t.mul(&num).div(&den)?;
        n += 1;
        if t.is_exact() && t.mid().is_zero() {
            // Terminating series: every later term is exactly zero.
            return Ok(finish(s, abs_sum, n));
        }
        let t_up = t.abs_upper_mag();
        if !t_up.is_finite() {
            return Err(Error::Overflow { what: "hypergeometric series term".into() });
        }
        if n >= n_pos {
            // target = 2^-wp max(|s|, 2^-wp sum|t|)
            let target = s.abs_lower_mag().max(abs_sum.mul_2exp(-(wp as i64))).mul_2exp(-(wp as i64));
            if t_up.le(&target) {
                if let Some(k) = tail_multiplier(a, b, z, n) {
                    s.add_error_mag(t_up.mul(Mag::from_float_up(&k)));
                    return Ok(finish(s, abs_sum, n));
                }
            }
        }
        s = s.add(&t);
        abs_sum = abs_sum.add(t_up);
        if n > MAX_SERIES_TERMS {
            return Err(Error::NoConvergence { function: "pFq", terms: n });
        }
        if n % crate::budget::TERMS_BETWEEN_CHECKS == 0 {
            // the installed time budget (crate::budget): the cost model counts terms
            // at the working precision, but a parameter held exactly at 10^5 bits
            // (1e31099 typed) makes every term cost that precision, and a slowly
            // decaying series runs long before its tail bound holds
            crate::budget::check_elapsed("the pFq series, term by term", 0.0, crate::error::Reached::Terms { count: n })?;
        }
    }
}

/// f64 sum of pFq with an error estimate; `None` where the series cannot be used.
///
/// Returns `(value, error_estimate, sum |t_n|)`. The sum is compensated
/// (Neumaier's TwoSum), so summation contributes about `u |s| + N u^2 sum |t_n|`;
/// term `n` carries a relative error of at most about `c n u` from its `c n`
/// roundings, which contributes `c u sum n |t_n|`.
pub(crate) fn pfq_f64(a: &[f64], b: &[f64], z: f64) -> Option<(f64, f64, f64)> {
    let p = a.len();
    let q = b.len();
    let terminates = a.iter().any(|&x| x <= 0.0 && x == x.floor());
    if !terminates && (p > q + 1 || (p == q + 1 && z.abs() >= 1.0)) {
        return None;
    }
    if b.iter().any(|&x| x <= 0.0 && x == x.floor()) {
        return None;
    }
    let neg_params = a.iter().chain(b.iter()).fold(0.0f64, |m, &x| m.max(-x));
    let n_pos = if neg_params > 0.0 { (neg_params.ceil() as u64).saturating_add(1) } else { 0 };
    let mut t = 1.0f64;
    let mut s = 1.0f64;
    let mut comp = 0.0f64;
    let mut abs_sum = 1.0f64;
    let mut weighted = 0.0f64; // sum n |t_n|
    let c = 2.0 * (p + q + 2) as f64;
    let u = f64::EPSILON / 2.0;
    let estimate = |s: f64, n: u64, abs_sum: f64, weighted: f64, tail: f64| {
        (u * s.abs() + c * u * weighted + n as f64 * u * u * abs_sum) * 1.01 + tail
    };
    let mut n: u64 = 0;
    loop {
        let nf = n as f64;
        let mut num = z;
        for &ai in a {
            num *= ai + nf;
        }
        let mut den = nf + 1.0;
        for &bj in b {
            den *= bj + nf;
        }
        t *= num / den;
        n += 1;
        if t == 0.0 {
            let v = s + comp;
            return Some((v, estimate(v, n, abs_sum, weighted, 0.0), abs_sum));
        }
        if !t.is_finite() || n > 100_000 {
            return None;
        }
        if n >= n_pos && t.abs() <= 1e-17 * (s + comp).abs().max(abs_sum * 1e-17) {
            let nf = n as f64;
            let mut rho = z.abs();
            let dens: Vec<f64> = b.iter().copied().chain(std::iter::once(1.0)).collect();
            let mut ok = true;
            for (i, &ai) in a.iter().enumerate() {
                match dens.get(i) {
                    Some(&d) => rho *= ((ai + nf) / (d + nf)).max(1.0),
                    None => ok = false,
                }
            }
            for &d in dens.iter().skip(p) {
                rho /= d + nf;
            }
            if ok && rho < 1.0 {
                let tail = t.abs() / (1.0 - rho);
                let v = s + comp;
                return Some((v, estimate(v, n, abs_sum, weighted, tail), abs_sum));
            }
        }
        // Neumaier's compensated addition.
        let new = s + t;
        comp += if s.abs() >= t.abs() { (s - new) + t } else { (t - new) + s };
        s = new;
        abs_sum += t.abs();
        weighted += n as f64 * t.abs();
    }
}

/// Largest working precision of [`pfq_series_exact`]: its f64 bound needs
/// `u = 2^-wp` a normal f64 (at 1100 bits `u` was 0, the stopping test never
/// passed and the loop ran to its 5M-term cap). (`u^2` in the stopping target may
/// underflow to 0 from 538 bits: that only makes the series stop later.)
const MAX_EXACT_SERIES_PREC: u32 = 1000;

/// `pFq(a; b; z)` for exact (binary-float) parameters and `z`, summed in plain MPFR
/// floats with a running error bound instead of ball arithmetic: `Ok(None)` where it
/// does not apply (`p > q`, a pole among the `b`, magnitudes outside the f64
/// exponent range of the bound, `wp` above [`MAX_EXACT_SERIES_PREC`]), and the caller
/// uses [`pfq_series`].
///
/// **Method.** `P_n = z prod_i (a_i + n)` and `Q_n = (n + 1) prod_j (b_j + n)` are
/// formed exactly (sums and products of binary floats at the precision that holds
/// them), so the term update `t~_{n+1} = fl(fl(t~_n P_n)/Q_n)` has two roundings.
///
/// **Error bound.** With `u = 2^-wp` (round to nearest, `|fl(x) - x| <= u |fl(x)|`),
/// `|t~_{n+1} - t~_n P_n/Q_n| <= u |t~_{n+1}| + u |fl(t~_n P_n)|/|Q_n|
/// <= u (1 + 1/(1-u)) |t~_{n+1}|`, and by induction the relative error of the
/// computed term is `eps_n <= eps_{n-1} (1 + 3u) + 2.001 u`, so
/// `|t~_n - t_n| <= 2.01 n u |t~_n|` for `n u < 2^-20`. Each addition
/// `s~ <- fl(s~ + t~)` errs by at most `u |s~_new|`. So the computed partial sum
/// through `N - 1` differs from the exact one by at most
/// `2.01 u sum_n n |t~_n| + u sum_k |s~_k|`. **Tail**: as in [`pfq_series`], once
/// `n >= N` passes every negative parameter and `rho_N < 1`,
/// `sum_{n>=N} |t_n| <= |t_N|/(1 - rho_N)` with `|t_N| <= (1 + 2.01 N u) |t~_N|`.
/// The magnitudes are bounded by `|x| <= 2^exp(x)` (exact f64 powers of two,
/// subnormal ones included, at most a factor 2 high, cheaper than a conversion) and the bound is summed in f64
/// (fewer than `2^22` operations of relative error `2^-53` each) and inflated by
/// `1 + 2^-28`, plus `4 (N+1) 2^-1074` for f64 roundings in the subnormal range;
/// a sum below `1e-280` goes to the ball series instead.
///
/// Compared with the ball series this does three MPFR operations per term and no
/// radius arithmetic: `1F2(1/2; 1, 3/2; -300)` at 128 bits in 34 us (was 97 us through
/// the ball series), against Arb's 67 us (81 bits) in the same session
/// (`reference/bench_arb_hyp1f2.py`, load 6.5 on 2 cores).
fn pfq_series_exact(a: &[Float], b: &[Float], z: &Float, wp: u32) -> Result<Option<Ball>> {
    use crate::special::{exact_add, is_nonpositive_integer};
    let (p, q) = (a.len(), b.len());
    if p > q || b.iter().any(is_nonpositive_integer) || !(24..=MAX_EXACT_SERIES_PREC).contains(&wp) {
        return Ok(None);
    }
    let u = (-(wp as f64)).exp2();
    // |x| <= 2^exp(x): an f64 upper bound without a conversion (at most 2x high)
    let up = |x: &Float| match x.get_exp() {
        None => if x.is_zero() { 0.0 } else { f64::INFINITY },
        Some(e) if e > 1023 => f64::INFINITY,
        Some(e) if e < -1073 => f64::from_bits(1),
        // 2^e as a subnormal (exact): bit e + 1074 of the significand
        Some(e) if e < -1021 => f64::from_bits(1u64 << (e + 1074)),
        Some(e) => f64::from_bits(((e + 1023) as u64) << 52),
    };
    let exact_balls = |xs: &[Float]| xs.iter().map(|x| Ball::from_float(x, x.prec())).collect::<Vec<Ball>>();
    let (a_balls, b_balls, z_ball) = (exact_balls(a), exact_balls(b), Ball::from_float(z, z.prec()));
    let n_pos = first_positive_index(&a_balls)?.max(first_positive_index(&b_balls)?);
    let mut t = Float::with_val(wp, 1);
    let mut s = Float::with_val(wp, 1);
    let mut weighted = 0.0f64; // sum_n n |t~_n|
    let mut sums = 1.0f64; // sum_k |s~_k|
    let mut abs_sum = 1.0f64; // sum_n |t~_n|
    let inflate = 1.0 + (-28.0f64).exp2();
    // Dyadic form `x = X 2^-e` of every parameter (`X` an i128, `e >= 0`), for integer
    // term ratios: `P_n = Z 2^ez prod(A_i + n 2^e_i) 2^-e_i`, likewise `Q_n`.
    let dyadic = |x: &Float| -> Option<(i128, u32)> {
        let (m, e) = x.to_integer_exp()?;
        if m == 0 {
            return Some((0, 0));
        }
        let tz = m.find_one(0)?;
        let (m, e) = (m >> tz, e + tz as i32);
        let mi = m.to_i128().filter(|v| v.unsigned_abs() < 1 << 100)?;
        if e >= 0 {
            mi.checked_mul(1i128.checked_shl(e as u32)?).filter(|v| v.unsigned_abs() < 1 << 100).map(|v| (v, 0))
        } else {
            (-e <= 60).then_some((mi, (-e) as u32))
        }
    };
    let z_dy = z.to_integer_exp().and_then(|(m, e)| {
        if m == 0 {
            return None;
        }
        let tz = m.find_one(0)?;
        Some(((m >> tz).to_i128()?, e + tz as i32))
    });
    let a_dy: Option<Vec<(i128, u32)>> = a.iter().map(dyadic).collect();
    let b_dy: Option<Vec<(i128, u32)>> = b.iter().map(dyadic).collect();
    let int_parts = match (z_dy, a_dy, b_dy) {
        (Some((zm, ze)), Some(ad), Some(bd)) => {
            let shift = ze as i64 - ad.iter().map(|x| x.1 as i64).sum::<i64>() + bd.iter().map(|x| x.1 as i64).sum::<i64>();
            Some((zm, shift, ad, bd))
        }
        _ => None,
    };
    // P_n and Q_n as i128 with the power of two, when they fit
    let int_ratio = |n: u64| -> Option<(i128, i128, i64)> {
        let (zm, shift, ad, bd) = int_parts.as_ref()?;
        let n = i128::from(n);
        let mut p = *zm;
        for &(x, e) in ad {
            p = p.checked_mul(x.checked_add(n.checked_mul(1i128 << e)?)?)?;
        }
        let mut q = n + 1;
        for &(x, e) in bd {
            q = q.checked_mul(x.checked_add(n.checked_mul(1i128 << e)?)?)?;
        }
        Some((p, q, *shift))
    };
    let mut n: u64 = 0;
    loop {
        if let Some((p, q, shift)) = int_ratio(n) {
            t *= p;
            t /= q;
            t <<= shift as i32;
        } else {
            let nf = Float::with_val(64, n);
            let mut num = z.clone();
            for ai in a {
                let f = exact_add(ai, &nf);
                num = Float::with_val(num.prec() + f.prec(), &num * &f);
            }
            let mut den = Float::with_val(64, n + 1);
            for bj in b {
                let f = exact_add(bj, &nf);
                den = Float::with_val(den.prec() + f.prec(), &den * &f);
            }
            t *= &num;
            t /= &den;
        }
        n += 1;
        let t_up = up(&t);
        if t.is_zero() {
            // terminating series (an a_i = -n): every later term is exactly zero
            let err = (2.01 * u * weighted + u * sums) * inflate + subnormal_slack(n);
            return Ok(finite_ball(s, err));
        }
        if !t_up.is_finite() || n > MAX_SERIES_TERMS || (n as f64) * u > (-20.0f64).exp2() {
            return Ok(None);
        }
        if n >= n_pos {
            let s_abs = up(&s);
            let target = u * s_abs.max(u * abs_sum);
            if t_up <= target {
                if let Some(k) = tail_multiplier(&a_balls, &b_balls, &z_ball, n) {
                    let tail = t_up * (1.0 + 2.01 * n as f64 * u) * k.to_f64_round(Round::Up) / (1.0 - 1e-15);
                    let err = (2.01 * u * weighted + u * sums + tail) * inflate + subnormal_slack(n);
                    return Ok(finite_ball(s, err));
                }
            }
        }
        s += &t;
        weighted += n as f64 * t_up;
        abs_sum += t_up;
        sums += up(&s);
    }
}

/// The absolute error of `4 n` f64 operations in the subnormal range (where the
/// relative inflation of the bound does not cover them).
fn subnormal_slack(n: u64) -> f64 {
    4.0 * (n as f64 + 1.0) * f64::from_bits(1)
}

/// The ball `[mid +/- err]` if `err` is finite and `|mid|` is far above the f64
/// subnormal range of the bound (else `None`: the caller uses balls).
fn finite_ball(mid: Float, err: f64) -> Option<Ball> {
    let big_enough = mid.as_abs().to_f64() > 1e-280;
    (err.is_finite() && big_enough).then(|| Ball::with_mag(mid, Mag::from_f64(err.next_up())))
}

/// Estimated CPU time of one series term at working precision `wp`, in seconds:
/// 1.2 us at about 130 bits measured for `1F2(3.7e18; 20.03, -179.875; 23.7)` at
/// 98 bits (4.46M terms in 5.4 s, load 6.6 on 2 cores), scaled linearly above 128 bits.
pub(crate) fn seconds_per_term(wp: u32) -> f64 {
    1.2e-6 * (f64::from(wp) / 128.0).max(1.0)
}

/// Estimated CPU time past which a series evaluation is refused with
/// [`Error::TooExpensive`] instead of run (seconds).
pub const MAX_SERIES_SECONDS: f64 = 1.0;

/// Refuses, in bounded time, a series that must run more than
/// [`MAX_SERIES_SECONDS`] at working precision `wp`.
///
/// **Why this is a lower bound on the work.** Unless the series terminates (a
/// numerator an exact non-positive integer), both summation loops
/// ([`pfq_series`], `pfq_series_exact`) stop only at some `n >= n_pos`
/// (every shifted parameter positive) where a tail bound exists
/// ([`tail_multiplier`]: `rho_n < 1`, or the two zones of the module docs). For
/// `n >= n_pos` the sorted pairing does not depend on `n`, each paired factor
/// `max(1, (a + n)/(d + n))` and each unpaired `1/(d + n)` is non-increasing in
/// `n`, and so is the first zone's `rho_1`: no bound at some `B >= n_pos` means
/// no stop before `B`: at least `B` terms (up to the upward rounding of `rho`, which only matters when
/// `rho_B` is within a few ulps of 1). The time per term is an estimate
/// ([`seconds_per_term`]), so the refusal is a cost decision, never a claim
/// about the value. The reported time comes from a doubling search for the
/// first `n` with `rho_n < 1` (a lower bound of the terms, within a factor 2).
fn check_series_cost(a: &[Ball], b: &[Ball], z: &Ball, wp: u32) -> Result<()> {
    if a.iter().any(|x| x.is_exact_nonpositive_integer()) || (z.is_exact() && z.mid().is_zero()) {
        return Ok(());
    }
    let per_term = seconds_per_term(wp);
    // the method's cap, shortened by what is left of the call's time budget
    let limit = crate::budget::limit_seconds(MAX_SERIES_SECONDS);
    let budget = (limit / per_term) as u64;
    let n_pos = first_positive_index(a)?.max(first_positive_index(b)?);
    if n_pos <= budget && tail_multiplier(a, b, z, budget).is_some() {
        return Ok(());
    }
    // At least `budget` terms: estimate how many (capped at 2^62).
    let mut n = budget.max(n_pos).max(1);
    while n < 1 << 62 && tail_multiplier(a, b, z, n).is_none() {
        n *= 2;
    }
    Err(Error::TooExpensive {
        function: "pFq(a; b; z) by its series",
        seconds: ((n / 2).max(budget) as f64 * per_term).max(limit.next_up()),
        limit_seconds: limit,
    })
}

/// Checks and converts pFq arguments.
fn to_balls(xs: &[Float], wp: u32) -> Vec<Ball> {
    xs.iter().map(|x| Ball::from_float(x, wp)).collect()
}

/// Certified `pFq(a; b; z)` where its series converges (see the module docs).
pub fn hyp_pfq_mp(a: &[Float], b: &[Float], z: &Float, prec: u32) -> Result<Ball> {
    crate::error::check_prec(prec)?;
    for x in a.iter().chain(b.iter()).chain(std::iter::once(z)) {
        check_finite(x, "hypergeometric argument")?;
    }
    let mut guard = DEFAULT_GUARD_BITS;
    // A cheap f64 pass estimates the cancellation.
    let af: Vec<f64> = a.iter().map(|x| x.to_f64()).collect();
    let bf: Vec<f64> = b.iter().map(|x| x.to_f64()).collect();
    if let Some((s, _, abs)) = pfq_f64(&af, &bf, z.to_f64()) {
        if s != 0.0 && s.is_finite() && abs.is_finite() {
            guard += (abs / s.abs()).log2().max(0.0) as u32;
        }
    }
    let exact_balls = |xs: &[Float]| xs.iter().map(|x| Ball::from_float(x, x.prec())).collect::<Vec<Ball>>();
    check_series_cost(&exact_balls(a), &exact_balls(b), &Ball::from_float(z, z.prec()), prec + guard)?;
    ziv("hyp_pfq", prec, guard, |wp| {
        if let Some(sum) = pfq_series_exact(a, b, z, wp)? {
            return Ok(sum);
        }
        let sum = pfq_series(&to_balls(a, wp), &to_balls(b, wp), &Ball::from_float(z, wp), wp)?;
        Ok(sum.sum)
    })
}

/// Whether the ball contains the integer `-j` for some `0 <= j < limit`
/// (`limit = None`: any non-positive integer).
pub(crate) fn contains_pole(x: &Ball, limit: Option<u64>) -> Option<i64> {
    let lo = x.lower();
    if lo > 0 {
        return None;
    }
    // the smallest integer >= lo; a pole -j needs -j <= upper and j < limit
    let k = Float::with_val(lo.prec().max(64), lo.ceil_ref());
    if k > 0 || k > x.upper() {
        return None;
    }
    let j = (-k.to_f64()) as u64;
    if limit.is_some_and(|d| j >= d) {
        return None;
    }
    // saturating: a pole beyond -i64::MAX is reported at -i64::MAX (found by tests/fuzz.rs)
    Some(-(j.min(i64::MAX as u64) as i64))
}

/// Certified `pFq(a; b; z)` over balls of inputs (Arb's convention): the result
/// contains the function at every point of the balls.
///
/// **Argument.** `pfq_series` runs in ball arithmetic and its tail bound uses
/// the balls' upper ends of `|z|` and the numerators and the lower ends of the
/// denominators, so it bounds the tail at every point of the balls; every term
/// therefore encloses the term at every point, and so does the sum. Exact
/// inputs go to [`hyp_pfq_mp`]. The inputs are rounded to the working precision
/// first ([`Ball::set_prec`] adds the rounding to the radius). The working
/// precision is raised while that still halves the radius
/// (`crate::special::ziv_ball_inputs`); past that the input radius dominates
/// and the (enclosing) ball is returned.
///
/// **Edges.** A denominator ball that contains a non-positive integer the
/// series reaches (a pole) is a typed error that names it.
pub fn hyp_pfq_ball_mp(a: &[Ball], b: &[Ball], z: &Ball, prec: u32) -> Result<Ball> {
    crate::error::check_prec(prec)?;
    if a.iter().chain(b.iter()).chain(std::iter::once(z)).any(|x| !x.is_finite()) {
        return Err(Error::NonFinite { what: "hypergeometric argument" });
    }
    if a.iter().chain(b.iter()).chain(std::iter::once(z)).all(Ball::is_exact) {
        let mids = |xs: &[Ball]| xs.iter().map(|x| x.mid().clone()).collect::<Vec<Float>>();
        return hyp_pfq_mp(&mids(a), &mids(b), z.mid(), prec);
    }
    // The series terminates after `d` terms when a numerator is exactly -d.
    let degree = a
        .iter()
        .filter(|x| x.is_exact_nonpositive_integer())
        .map(|x| ((-x.mid().to_f64()) as u64).saturating_add(1))
        .min();
    for (j, bj) in b.iter().enumerate() {
        if let Some(pole) = contains_pole(bj, degree) {
            return Err(Error::ParameterPole {
                function: "pFq",
                arg: LOWER_PARAMETER_NAMES.get(j).copied().unwrap_or("b"),
                pole: pole as f64,
                lower: bj.lower().to_f64(),
                upper: bj.upper().to_f64(),
            });
        }
    }
    let mut guard = DEFAULT_GUARD_BITS;
    let af: Vec<f64> = a.iter().map(Ball::to_f64).collect();
    let bf: Vec<f64> = b.iter().map(Ball::to_f64).collect();
    if let Some((s, _, abs)) = pfq_f64(&af, &bf, z.to_f64()) {
        if s != 0.0 && s.is_finite() && abs.is_finite() {
            guard += (abs / s.abs()).log2().max(0.0) as u32;
        }
    }
    check_series_cost(a, b, z, prec + guard)?;
    crate::special::ziv_ball_inputs(prec, guard, None, |wp| {
        let at = |xs: &[Ball]| xs.iter().map(|x| crate::special::input_ball(x, wp)).collect::<Vec<Ball>>();
        Ok(pfq_series(&at(a), &at(b), &crate::special::input_ball(z, wp), wp)?.sum)
    })
}

/// f64 `pFq(a; b; z)`: fast series when its error estimate is below
/// [`F64_TRUST`], otherwise the rounded MP value.
pub fn hyp_pfq(a: &[f64], b: &[f64], z: f64) -> Result<f64> {
    for &x in a.iter().chain(b.iter()).chain(std::iter::once(&z)) {
        crate::error::finite(x, "hypergeometric argument")?;
    }
    if let Some((s, err, _)) = pfq_f64(a, b, z) {
        if err <= F64_TRUST * s.abs() && s.is_finite() {
            return Ok(s);
        }
    }
    let ae: Vec<Float> = a.iter().map(|&x| exact(x)).collect();
    let be: Vec<Float> = b.iter().map(|&x| exact(x)).collect();
    let ze = exact(z);
    f64_from_mp("hyp_pfq", DEFAULT_GUARD_BITS, |wp| {
        Ok(pfq_series(&to_balls(&ae, wp), &to_balls(&be, wp), &Ball::from_float(&ze, wp), wp)?.sum)
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn exp_series_encloses_e() {
        // 0F0(;;1) = e
        let b = hyp_pfq_mp(&[], &[], &exact(1.0), 200).unwrap();
        let e = Float::with_val(400, 1).exp();
        assert!(b.contains(&e));
        assert!(b.meets_rel(200));
    }

    /// The two-zone tail bound: `1F1(1; 10^20; 10^4) = sum_n 10^(4n) / (10^20)_n`
    /// has `rho_N = 10^4/(N+1)` with the paired factor bounded by 1 (about 10^4
    /// terms), while the factor itself is `10^-20`: a few terms, and the ball holds
    /// the sum (terms summed exactly in rationals, tail below `10^-16k`); a huge
    /// lower parameter of 10^31099 (issue 37's scan) likewise.
    #[test]
    fn a_tiny_paired_factor_ends_the_series_early() {
        use rug::ops::Pow;
        use rug::Rational;
        let (z, b) = (Rational::from(10000), Rational::from(rug::Integer::from(10u32).pow(20u32)));
        let (mut term, mut sum) = (Rational::from(1), Rational::from(1));
        for n in 0..30u32 {
            term = term * &z / (Rational::from(&b + n));
            sum += &term;
        }
        let want = Float::with_val(1200, &sum);
        for wp in [64, 300, 1000] {
            let r = pfq_series(&[Ball::one(wp)], &[Ball::from_float(&Float::with_val(wp, &b), wp)], &Ball::from_i64(10000, wp), wp).unwrap();
            assert!(r.sum.contains(&want), "{wp}: {:?}", r.sum);
            assert!(r.sum.meets_rel(wp - 8), "{wp}: {:?}", r.sum);
            assert!(r.terms <= 2 * u64::from(wp) / 50 + 4, "{wp}: {} terms", r.terms);
            // the multiplier is a bound of the tail only where it exists; plain rho is not below 1
            assert!(ratio_bound(&[Ball::one(wp)], &[Ball::from_float(&Float::with_val(wp, &b), wp)], &Ball::from_i64(10000, wp), r.terms) >= 1);
        }
        let big = Ball::from_float(&Float::with_val(128, Float::parse("1e31099").unwrap()), 128);
        let a = Ball::from_float(&Float::with_val(128, Float::parse("-1.0375e-24686").unwrap()), 128);
        let r = pfq_series(&[a], &[Ball::from_f64(20.12, 128).unwrap(), big], &Ball::from_i64(16777217, 128), 128).unwrap();
        assert!(r.terms <= 8 && r.sum.contains(&Float::with_val(64, 1)), "{} terms: {:?}", r.terms, r.sum);
    }

    #[test]
    fn geometric_series() {
        // 1F0(1;;z) = 1/(1-z), |z|<1
        let b = hyp_pfq_mp(&[exact(1.0)], &[], &exact(0.5), 100).unwrap();
        assert!(b.contains(&Float::with_val(200, 2)));
        assert!(hyp_pfq_mp(&[exact(1.0)], &[], &exact(1.5), 100).is_err());
    }

    #[test]
    fn terminating_series_is_exact() {
        // 2F1(-2, 1; 1; z) = (1 - z)^2
        let b = hyp_pfq_mp(&[exact(-2.0), exact(1.0)], &[exact(1.0)], &exact(3.0), 64).unwrap();
        assert!(b.contains(&Float::with_val(64, 4)));
        assert!(b.is_exact());
    }

    #[test]
    fn pole_is_an_error() {
        assert!(hyp_pfq_mp(&[exact(1.0)], &[exact(-1.0)], &exact(0.5), 64).is_err());
        assert!(hyp_pfq(&[1.0], &[-1.0], 0.5).is_err());
    }

    #[test]
    fn exact_parameter_series_encloses_the_ball_series() {
        // (a, b, z): cancelling, growing, negative parameters, terminating, tiny z
        let cases: &[(&[f64], &[f64], f64)] = &[
            (&[0.5], &[1.0, 1.5], -300.0),
            (&[0.5], &[101.0, 101.5], -1225.0),
            (&[1.25], &[2.5, 3.75], 40.0),
            (&[-3.0], &[2.5, 0.75], 7.5),
            (&[-2.5], &[-1.25, 0.75], -60.0),
            (&[0.1], &[0.3, 0.7], -1e-9),
            (&[], &[], -20.0),
            (&[], &[0.5], -1000.0),
            (&[2.0, 3.0], &[0.25, 0.125], -0.5),
            // terms below 2^-1022 (f64 subnormal bounds; once summed as negative numbers)
            (&[-337.8177490234375], &[427.4927978515625, 294.2845458984375], -63.8824462890625),
        ];
        for &(a, b, z) in cases {
            let (ae, be, ze): (Vec<Float>, Vec<Float>, Float) = (a.iter().map(|&x| exact(x)).collect(), b.iter().map(|&x| exact(x)).collect(), exact(z));
            let reference = pfq_series(&to_balls(&ae, 1200), &to_balls(&be, 1200), &Ball::from_float(&ze, 1200), 1200).unwrap().sum;
            for wp in [64u32, 128, 300, 1000] {
                let fast = pfq_series_exact(&ae, &be, &ze, wp).unwrap().unwrap_or_else(|| panic!("{a:?} {b:?} {z}: no fast path"));
                assert!(fast.overlaps(&reference) && fast.rad() >= Float::with_val(600, fast.mid() - reference.mid()).abs() - reference.rad(), "{a:?} {b:?} {z} wp={wp}: {fast:?} vs {reference:?}");
                let ball = pfq_series(&to_balls(&ae, wp), &to_balls(&be, wp), &Ball::from_float(&ze, wp), wp).unwrap().sum;
                // the running bound is no looser than ball arithmetic by more than 4 bits
                assert!(fast.rad() <= ball.rad() * 16u32 + Float::with_val(64, 1e-300), "{a:?} {b:?} {z} wp={wp}: {fast:?} vs {ball:?}");
            }
        }
        // a pole or p > q: not this path
        assert!(pfq_series_exact(&[exact(1.0)], &[exact(-1.0)], &exact(0.5), 64).unwrap().is_none());
        assert!(pfq_series_exact(&[exact(1.0), exact(2.0)], &[exact(3.0)], &exact(0.5), 64).unwrap().is_none());
    }

    #[test]
    fn f64_matches_mp() {
        let v = hyp_pfq(&[0.5], &[1.0, 1.5], -300.0).unwrap();
        let m = hyp_pfq_mp(&[exact(0.5)], &[exact(1.0), exact(1.5)], &exact(-300.0), 80).unwrap();
        assert!((v - m.to_f64()).abs() <= 1e-14 * m.to_f64().abs());
    }
}
