//! Gamma, Pochhammer and upward-rounded magnitude helpers shared by the
//! hypergeometric functions.
//!
//! # Method
//!
//! * **Gamma at exact points** ([`gamma_ball`]): MPFR's correctly rounded `gamma`
//!   (one ulp) wrapped in a ball. Small integers and half-integers use `(n-1)!`
//!   and `sqrt(pi) (1/2)_n` (MPFR's `gamma` is slowest there), other small
//!   arguments are shifted into `[1, 2)` by `Gamma(x) = Gamma(x+K)/(x)_K`
//!   [DLMF 5.5.1]; all in ball arithmetic.
//! * **Long arguments** ([`gamma_of_ball`]): an exact argument with more bits than
//!   Gamma at `wp` needs (a sum of parameters of very different magnitudes) is
//!   rounded to about `wp + log2(x psi(x))` bits (next to a pole, its distance
//!   too), and the rounding is carried by `|Gamma(t) - Gamma(m)| <= |Gamma(m)|
//!   (e^{rM} - 1)`, `M = max |psi|` over the ball (psi is increasing between
//!   poles, DLMF 5.15.1). MPFR's Gamma at 35 000 bits takes about two minutes.
//! * **Gamma ratios** ([`gamma_ratio_scaled`]): `prod Gamma(num_i) / prod Gamma(den_j)`.
//!   Arguments that differ by an integer `k <= 64` are paired into Pochhammer
//!   products `Gamma(x+k)/Gamma(x) = (x)_k` [DLMF 5.2.5], which is exact in the
//!   limit and cheap; `1/Gamma` at a pole is the exact zero [DLMF 5.2.1].
//! * **Magnitudes** (`mag_*`): non-negative upper bounds as `Float`s at
//!   [`MAG_PREC`] bits, every operation rounded upward (or downward where a lower
//!   bound is needed, `mag_abs_down`), for the radius and tail bounds of the
//!   series engines. They complement [`Mag`](crate::ball::Mag), which has an f64
//!   mantissa; these keep MPFR's exponent range for tail bounds of huge terms.
//! * [`lgamma_est`]: an f64 *estimate* of `ln |Gamma(x)|` for cost models only
//!   (never inside a bound).

use std::f64::consts::PI;

use rug::float::Round;
use rug::Float;

use crate::ball::{Ball, Scaled, MAG_PREC};
use rug::ops::AssignRound;
use crate::error::{Error, Result};
use crate::special::{exact_add, exact_sub, is_nonpositive_integer};

/// Gamma ratios whose arguments differ by an integer up to this are Pochhammer products.
const POCHHAMMER_PAIR_MAX: u64 = 64;

/// An exact ball for an exact float (precision at least `wp`).
pub(crate) fn xball(x: &Float, wp: u32) -> Ball {
    Ball::from_float(x, wp.max(x.prec()))
}

/// The exact float `n`.
pub(crate) fn int_float(n: u64) -> Float {
    Float::with_val(64, n)
}

// ----- upward-rounded magnitudes -------------------------------------------

pub(crate) fn mag_zero() -> Float {
    Float::new(MAG_PREC)
}

pub(crate) fn mag_inf() -> Float {
    Float::with_val(MAG_PREC, rug::float::Special::Infinity)
}

pub(crate) fn mag_abs(x: &Float) -> Float {
    Float::with_val_round(MAG_PREC, x.abs_ref(), Round::Up).0
}

pub(crate) fn mag_abs_down(x: &Float) -> Float {
    Float::with_val_round(MAG_PREC, x.abs_ref(), Round::Down).0
}

pub(crate) fn mag_add(a: &Float, b: &Float) -> Float {
    Float::with_val_round(MAG_PREC, a + b, Round::Up).0
}

pub(crate) fn mag_mul(a: &Float, b: &Float) -> Float {
    Float::with_val_round(MAG_PREC, a * b, Round::Up).0
}

pub(crate) fn mag_div(a: &Float, b: &Float) -> Float {
    if b.is_zero() || b.is_sign_negative() {
        return mag_inf();
    }
    Float::with_val_round(MAG_PREC, a / b, Round::Up).0
}

pub(crate) fn mag_u64(n: u64) -> Float {
    Float::with_val_round(MAG_PREC, n, Round::Up).0
}

pub(crate) fn mag_pow2(e: i64) -> Float {
    let mut r = Float::with_val(MAG_PREC, 1);
    r <<= e.clamp(i32::MIN as i64 / 2, i32::MAX as i64 / 2) as i32;
    r
}

pub(crate) fn mag_min(a: Float, b: Float) -> Float {
    if a <= b {
        a
    } else {
        b
    }
}

/// Upper bound of `1 / (1 - rho)` for `rho < 1`.
pub(crate) fn mag_geometric(rho: &Float) -> Float {
    let den = Float::with_val_round(MAG_PREC, 1 - rho, Round::Down).0;
    mag_div(&Float::with_val(MAG_PREC, 1), &den)
}

/// Upper bound of `expm1(x)` for `x >= 0`.
pub(crate) fn expm1_up(x: &Float) -> Float {
    let mut e = x.clone();
    e.exp_m1_round(Round::Up);
    e
}

// ----- Gamma and Pochhammer --------------------------------------------------

/// `(x)_k = x (x+1) ... (x+k-1)` in balls.
pub(crate) fn pochhammer(x: &Float, k: u64, wp: u32) -> Ball {
    let xb = xball(x, wp);
    let mut r = Ball::one(wp);
    for i in 0..k {
        r = r.mul(&xb.add_i64(i as i64));
    }
    r
}

/// `prod Gamma(num_i) / prod Gamma(den_j)` at exact points as a [`Scaled`] (the
/// caller forms the value, or multiplies more factors first). `num` must avoid
/// the poles; a pole in `den` makes the product an exact zero. Arguments that
/// differ by an integer of at most 64 are paired into Pochhammer products; huge
/// close arguments by Stirling's pair formula ([`gamma_pair_scaled`]); other
/// Gammas past the exponent range are carried in logarithms ([`gamma_scaled`]).
pub(crate) fn gamma_ratio_scaled(num: &[&Float], den: &[&Float], wp: u32) -> Result<Scaled> {
    if den.iter().any(|y| is_nonpositive_integer(y)) {
        return Ok(Scaled::from_ball(Ball::zero(wp)));
    }
    let mut used = vec![false; den.len()];
    let mut r = Scaled::one(wp);
    for x in num {
        if is_nonpositive_integer(x) {
            return Err(Error::Pole { function: "Gamma", at: x.to_f64() });
        }
        let mut best: Option<(usize, Float)> = None;
        for (j, y) in den.iter().enumerate() {
            if used[j] {
                continue;
            }
            let d = exact_sub(x, y);
            if d.is_integer() && d.clone().abs() <= POCHHAMMER_PAIR_MAX {
                let better = match &best {
                    Some((_, bd)) => d.clone().abs() < bd.clone().abs(),
                    None => true,
                };
                if better {
                    best = Some((j, d));
                }
            }
        }
        match best {
            Some((j, d)) => {
                used[j] = true;
                let k = d.to_f64().abs() as u64;
                if d.is_sign_negative() {
                    // Gamma(x) / Gamma(x + k) = 1 / (x)_k
                    r = r.div_ball(&pochhammer(x, k, wp))?;
                } else {
                    // Gamma(y + k) / Gamma(y) = (y)_k
                    r = r.mul_ball(&pochhammer(den[j], k, wp));
                }
            }
            None => {
                // both arguments past 2^(wp+16) and close (|x - y| below |y|/2):
                // Stirling for the pair (`gamma_pair_scaled`), at the bits
                // `(x - y) ln y` needs instead of `y ln y`
                let huge = |t: &Float| *t > 0 && t.get_exp().is_some_and(|e| i64::from(e) > i64::from(wp) + 17);
                let close = (0..den.len()).find(|&j| {
                    let y = den[j];
                    !used[j] && huge(x) && huge(y) && exact_sub(x, y).get_exp().is_none_or(|e| e < y.get_exp().unwrap_or(0) - 1)
                });
                match close {
                    Some(j) => {
                        used[j] = true;
                        let (xb, yb) = (Ball::from_float(x, x.prec()), Ball::from_float(den[j], den[j].prec()));
                        let d = exact_sub(x, den[j]);
                        r = r.mul(&gamma_pair_scaled(&xb, &yb, &Ball::from_float(&d, d.prec()), wp)?);
                    }
                    None => r = r.mul(&gamma_scaled(x, wp)?),
                }
            }
        }
    }
    for (j, y) in den.iter().enumerate() {
        if !used[j] {
            r = r.div(&gamma_scaled(y, wp)?)?;
        }
    }
    Ok(r)
}

/// `Gamma(x)` at an exact non-pole `x` as a [`Scaled`]: [`gamma_ball`] where the
/// value is inside the exponent range, else in logarithms ([`ln_gamma_scaled`]).
pub(crate) fn gamma_scaled(x: &Float, wp: u32) -> Result<Scaled> {
    match gamma_ball(x, wp) {
        Err(Error::Overflow { .. }) => ln_gamma_scaled(&Ball::from_float(x, x.prec()), wp),
        r => r.map(Scaled::from_ball),
    }
}

/// [`gamma_of_ball`] as a [`Scaled`]: in logarithms where Gamma passes the
/// exponent range ([`ln_gamma_scaled`]).
pub(crate) fn gamma_of_ball_scaled(x: &Ball, wp: u32) -> Result<Scaled> {
    match gamma_of_ball(x, wp) {
        Err(Error::Overflow { .. }) => ln_gamma_scaled(x, wp),
        r => r.map(Scaled::from_ball),
    }
}

/// `Gamma(x) / Gamma(y)` over balls, where the ball `d` encloses `x - y` (given
/// by the caller from the inputs: `Gamma(c) / Gamma(c - a)` takes `d = a`, so
/// the radius of `c`, shared by both arguments, does not enter twice). When both
/// `x` and `y` are at least `2^(wp+16)`: Stirling's formula for both [DLMF
/// 5.6.1], whose difference is, exactly,
/// `S(y + d) - S(y) = (y - 1/2) ln(1 + d/y) + d ln(y + d) - d`
/// (`S(t) = (t - 1/2) ln t - t + ln(2 pi)/2`), evaluated in ball arithmetic at
/// `wp + 16 + log2 |d ln y|` bits (not `log2 |y ln y|`: `Gamma(10^30000 + 50) /
/// Gamma(10^30000)` costs a logarithm at about 200 bits, not at 100 000), and
/// the remainders `R(t) in (0, 1/(12 t))` as the radius `max(1/(12 x_lo), 1/(12
/// y_lo))`. Otherwise [`gamma_of_ball_scaled`] of each.
pub(crate) fn gamma_pair_scaled(x: &Ball, y: &Ball, d: &Ball, wp: u32) -> Result<Scaled> {
    if let Some(r) = gamma_pair_integer(x, y, d, wp) {
        return Ok(r);
    }
    let huge = |t: &Ball| t.lower() > 0 && t.lower().get_exp().is_some_and(|e| i64::from(e) > i64::from(wp) + 17);
    if !(huge(x) && huge(y)) {
        return gamma_of_ball_scaled(x, wp)?.div(&gamma_of_ball_scaled(y, wp)?);
    }
    if d.is_exact() && d.mid().is_zero() {
        return Ok(Scaled::one(wp));
    }
    let ey = y.mid().get_exp().map_or(1, i64::from).max(1);
    let ed = d.mid().get_exp().map_or(0, i64::from);
    let size = (ed + (64 - (ey as u64).leading_zeros()) as i64).max(0);
    let p = (i64::from(wp) + 16 + size).min(i64::from(crate::MAX_WORKING_PREC) * 4) as u32;
    // Two ball logarithms below, each an MPFR logarithm at both ends: four at `p`
    // bits, about 1.7 times one `ln_seconds` (measured at 96 000 bits: 14 ms each
    // warm, `log 2` at a new precision 14 ms more; one estimate, 42 ms, let the
    // seed-2 scan's `2F1(2.9e28811, 5.7e-73; 1.9e28873; -9)` run 0.21 s under a
    // 100 ms budget, docs/fuzzing.md): charged as two.
    crate::budget::check_estimate("Gamma(y + d) / Gamma(y) by Stirling (logarithms at the bits d ln y needs)", 2.0 * crate::ball::ln_seconds(p), f64::INFINITY)?;
    let (yb, db) = (y.set_prec(p), d.set_prec(p));
    let ratio = db.div(&yb)?;
    if ratio.lower() <= -1 {
        return gamma_of_ball_scaled(x, wp)?.div(&gamma_of_ball_scaled(y, wp)?);
    }
    let l = yb
        .sub(&Ball::from_ratio(1, 2, p))
        .mul(&ratio.ln_1p()?)
        .add(&db.mul(&yb.add(&db).ln()?))
        .sub(&db);
    let bound = |t: &Ball| {
        let mut twelve = Float::with_val(64, 0);
        twelve.assign_round(&t.lower() * 12u32, Round::Down);
        Float::with_val_round(64, twelve.recip_ref(), Round::Up).0
    };
    let mut l = l;
    l.add_error(&bound(x).max(&bound(y)));
    Ok(Scaled::with_log(Ball::one(wp), l))
}

/// Most factors of [`gamma_pair_integer`]'s product.
const PAIR_PRODUCT_MAX: u32 = 1024;

/// `Gamma(x) / Gamma(y)` for `d = x - y` an exact integer `n`, `0 < |n| <=`
/// [`PAIR_PRODUCT_MAX`], by `Gamma(t + 1) = t Gamma(t)` [DLMF 5.5.1]:
/// `prod_{j=1}^{n} (x - j)` for `n > 0`, `1 / prod_{j=1}^{|n|} (y - j)` for `n <
/// 0`, from `x` (or `y`) alone in ball arithmetic. Both Gammas may sit next to
/// their poles while the ratio is a polynomial: `Gamma(c) / Gamma(c - 19)` at `c
/// = 5e-21621` is `(c - 1) ... (c - 19)`, where `c - 19`, rounded to the working
/// precision, is a ball around the pole `-19` (issue 37's scan: `2F1(-206.375,
/// 19; 5e-21621; -5e10784)` refused `PrecisionExhausted`). The identity is one of
/// meromorphic functions, so the product is the ratio's value (its continuous
/// extension) at every point of the ball. `None` when `d` is not such an
/// integer, or a factor ball holds zero (`1/0`), or the product is not finite.
fn gamma_pair_integer(x: &Ball, y: &Ball, d: &Ball, wp: u32) -> Option<Scaled> {
    if !d.is_exact() || !d.mid().is_integer() || d.mid().is_zero() {
        return None;
    }
    let n = d.mid().to_f64();
    if n.abs() > f64::from(PAIR_PRODUCT_MAX) {
        return None;
    }
    let (base, count) = if n > 0.0 { (x, n as i64) } else { (y, -n as i64) };
    let p = wp + 16;
    let mut prod = Ball::one(p);
    for j in 1..=count {
        prod = prod.mul(&base.set_prec(p.max(base.prec())).add_i64(-j));
    }
    let prod = if n > 0.0 { prod } else { prod.recip().ok()? };
    prod.is_finite().then(|| Scaled::from_ball(prod))
}

/// `Gamma` over a pole-free ball `x` with `|x| >= 2` as `m e^l`:
/// `e^(ln Gamma(x))` for `x >= 2` ([`ln_gamma_positive`]); for `x <= -2` the
/// reflection `Gamma(x) = pi / ((-1)^n sin(pi d) Gamma(1 - x))` [DLMF 5.5.3],
/// `x = n + d` with `n` the integer nearest the midpoint (`sin(pi x) = (-1)^n
/// sin(pi d)`; every `t` of the ball has `t - n` in the ball `d`), so `m = pi /
/// ((-1)^n sin(pi d))` and `l = -ln Gamma(1 - x)`. Other balls (and a `sin(pi d)`
/// ball holding zero) are [`Error::Overflow`], as the plain Gamma reported.
fn ln_gamma_scaled(x: &Ball, wp: u32) -> Result<Scaled> {
    if x.lower() >= 2 {
        return Ok(Scaled::with_log(Ball::one(wp), ln_gamma_positive(x, wp)?));
    }
    let what = "gamma (in logarithms: a ball too wide or next to a pole)";
    if x.upper() <= -2 {
        let n = Float::with_val(x.prec(), x.mid().round_ref());
        let mut d = Ball::from_float(&exact_sub(x.mid(), &n), wp + 16);
        d.add_error_mag(x.rad_mag());
        let sin = d.mul(&Ball::pi(wp + 16)).sin();
        if sin.contains_zero() {
            return Err(Error::Overflow { what: what.into() });
        }
        let odd = !Float::with_val(n.prec() + 1, &n / 2u32).is_integer();
        let m = Ball::pi(wp + 16).div(&if odd { sin.neg() } else { sin })?;
        let mut one_minus_x = Ball::from_float(&exact_sub(&int_float(1), x.mid()), x.prec() + 1);
        one_minus_x.add_error_mag(x.rad_mag());
        return Ok(Scaled::with_log(m, ln_gamma_positive(&one_minus_x, wp)?.neg()));
    }
    Err(Error::Overflow { what: what.into() })
}

/// `ln Gamma` over a ball `x >= 2`, to an absolute error of about
/// `2^-(wp+16)`: the ball rounded to `p = wp + 16 + log2(x ln x)` bits (the
/// rounding stays in its radius), then
/// * for `x >= 2^(wp+16)`, Stirling's formula with its remainder [DLMF 5.6.1]:
///   `ln Gamma(t) - S(t)` lies in `(0, 1/(12 t))` for `t > 0`, `S(t) = (t - 1/2)
///   ln t - t + ln(2 pi)/2`; `S` in ball arithmetic over the ball and the
///   remainder as a radius `1/(12 x_lo)`;
/// * else MPFR's correctly rounded `ln |Gamma|` (one ulp) at the midpoint, and
///   the radius `r` carried by `0 < psi(t) < ln t` for `t >= 2` [DLMF 5.9.13's
///   consequence `psi(t) < ln t`, and `psi > 0` past 1.47]: `|ln Gamma(t) - ln
///   Gamma(m)| <= r ln(x_hi)`.
fn ln_gamma_positive(x: &Ball, wp: u32) -> Result<Ball> {
    let ex = x.mid().get_exp().map_or(1, i64::from).max(1);
    let size = ex + (64 - (ex as u64).leading_zeros()) as i64;
    let p = (i64::from(wp) + 16 + size).min(i64::from(crate::MAX_WORKING_PREC) * 4) as u32;
    // at exactly p bits: rounded when longer, extended (exactly) when shorter, so
    // that `ln` and the products below run at p bits
    let xb = x.set_prec(p);
    if ex > i64::from(wp) + 16 {
        // one `ln` at p bits: 45 ms at 100 000 bits (a parameter of 10^30000)
        crate::budget::check_estimate("ln Gamma(x) by Stirling (ln x at the bits its size needs)", crate::ball::ln_seconds(p), f64::INFINITY)?;
        let s = xb.sub(&Ball::from_ratio(1, 2, p)).mul(&xb.ln()?).sub(&xb);
        // ln(2 pi)/2 is of size 1: wp + 32 bits carry it to 2^-(wp+16)
        let mut s = s.add(&Ball::pi(wp + 32).mul_i64(2).ln()?.mul_pow2(-1));
        let lo = xb.lower();
        let mut twelve_lo = Float::with_val(64, 0);
        twelve_lo.assign_round(&lo * 12u32, Round::Down);
        let mut bound = Float::with_val(64, 0);
        bound.assign_round(twelve_lo.recip_ref(), Round::Up);
        s.add_error(&bound);
        return Ok(s);
    }
    crate::budget::check_estimate("ln Gamma(x) (MPFR)", gamma_seconds(p), f64::INFINITY)?;
    let mut lg = Float::new(p);
    let mut sign = std::cmp::Ordering::Equal;
    let ord = (&mut lg, &mut sign).assign_round(xb.mid().ln_abs_gamma_ref(), Round::Nearest);
    let mut out = crate::ball::rounded(lg, ord);
    if !xb.is_exact() {
        let ln_hi = Float::with_val_round(64, xb.upper().ln_ref(), Round::Up).0;
        out.add_error_mag(xb.rad_mag().mul(crate::ball::Mag::from_float_up(&ln_hi)));
    }
    Ok(out)
}

/// `Gamma(x)` at an exact non-pole `x`: `(n-1)!` and `sqrt(pi) (1/2)_n` (or
/// `sqrt(pi) / (1/2 - n)_n`) at small integers and half-integers, a shift
/// `Gamma(x) = Gamma(x+K) / (x)_K` into `[1, 2)` for other small `x < 1` (MPFR is
/// slowest there), otherwise MPFR's correctly rounded value. An `x` with more
/// bits than [`gamma_arg_bits`] can use (a sum of parameters of very different
/// magnitudes, exact at tens of thousands of bits, where MPFR's Gamma takes
/// minutes computing Bernoulli numbers) is rounded to that many bits and the
/// rounding carried by [`gamma_of_ball`].
pub(crate) fn gamma_ball(x: &Float, wp: u32) -> Result<Ball> {
    if is_nonpositive_integer(x) {
        return Err(Error::Pole { function: "Gamma", at: x.to_f64() });
    }
    let bits = gamma_arg_bits(x, wp);
    if x.prec() > bits {
        let rounded = Ball::from_float(x, bits);
        if crate::special::pfq::contains_pole(&rounded, None).is_none() {
            return gamma_of_ball(&rounded, wp);
        }
    }
    gamma_exact(x, wp)
}

/// How many bits of an exact `x` `Gamma(x)` at about `wp` bits needs: rounding
/// `x` to `p` bits moves it by `r <= 2^(e-p-1)` (`2^(e-1) <= |x| < 2^e`), which
/// moves `ln Gamma` by at most `r M`, `M = max |psi|` near `x`. `M` is about
/// `ln(2 + |x|)` plus `1/d` next to a pole at distance `d` (`psi(x) = psi(1-x) -
/// pi cot(pi x)` [DLMF 5.5.4]); `p` makes the estimate of `r M` about
/// `2^-(wp+8)`. An estimate (choosing only): [`gamma_of_ball`] bounds the
/// rounding rigorously whatever `p` is.
fn gamma_arg_bits(x: &Float, wp: u32) -> u32 {
    let Some(e) = x.get_exp() else { return wp };
    let e = e as i64;
    // log2 of ln(2 + |x|) + 2, from the exponent alone (|x| may overflow f64)
    let log_term = ((e.max(1) as f64) * std::f64::consts::LN_2 + 3.0).log2().ceil() as i64;
    let mut log2_m = log_term;
    if *x < 0.5 {
        // distance to the nearest non-positive integer (exact), by its exponent
        let n = Float::with_val(x.prec(), x.round_ref());
        let d = exact_sub(x, &n);
        if let Some(ed) = d.get_exp() {
            log2_m = log2_m.max(2 - ed as i64);
        }
    }
    let p = e + wp as i64 + 8 + log2_m.max(0);
    p.clamp(wp.max(64) as i64, (u32::MAX / 2) as i64) as u32
}

/// `Gamma` over a ball `[m +/- r]` without poles: `(ln |Gamma|)' = psi` is
/// increasing between poles [DLMF 5.15.1: `psi' > 0`], so on the ball `|psi| <=
/// M = max(|psi(lo)|, |psi(hi)|)` at any pole-free `[lo, hi]` that contains it,
/// and `Gamma(t) in Gamma(m) [e^{-rM}, e^{rM}]` (Gamma keeps its sign there):
/// `|Gamma(t) - Gamma(m)| <= |Gamma(m)| (e^{rM} - 1)`. `lo` and `hi` are the
/// ball's ends rounded outward to 64 bits (to the ball's precision when that
/// would reach a pole). `Gamma(m)` is [`gamma_ball`]'s enclosure. A ball that
/// contains a pole is [`Error::Pole`].
pub(crate) fn gamma_of_ball(x: &Ball, wp: u32) -> Result<Ball> {
    if x.is_exact() {
        // through gamma_ball, which rounds a midpoint longer than Gamma needs (a
        // decimal input tightened to 65 535 bits: MPFR's Gamma there took minutes)
        return gamma_ball(x.mid(), wp);
    }
    if let Some(at) = crate::special::pfq::contains_pole(x, None) {
        return Err(Error::Pole { function: "Gamma", at: at as f64 });
    }
    // Gamma(m) itself through gamma_ball: a long midpoint is rounded first
    let mut g = gamma_ball(x.mid(), wp)?;
    let (lo, hi) = (x.lower(), x.upper());
    let mut lo_psi = Float::with_val_round(64, &lo, Round::Down).0;
    let mut hi_psi = Float::with_val_round(64, &hi, Round::Up).0;
    let hull = Ball::hull(&lo_psi, &hi_psi, 64);
    if crate::special::pfq::contains_pole(&hull, None).is_some() {
        (lo_psi, hi_psi) = (lo, hi);
    }
    let m = psi_abs_upper(&lo_psi)?.max(psi_abs_upper(&hi_psi)?);
    let mut e = m.mul(x.rad_mag()).to_float();
    e.exp_m1_round(Round::Up);
    let grow = g.abs_upper_mag().mul(crate::ball::Mag::from_float_up(&e));
    g.add_error_mag(grow);
    Ok(g)
}

/// An upper bound of `|psi(t)|` at an exact `t` that is not a pole. Within
/// `d <= 2^-10` of a pole `-n` (`n >= 0`) it is `1/d + ln(n + 2) + 1`, from the
/// reflection `psi(t) = psi(1 - t) - pi cot(pi t)` [DLMF 5.5.4] with
/// `|pi cot(pi t)| = |pi cot(pi d)| <= 1/d` and `-gamma <= psi(1 - t) <= ln(n + 2)`
/// (`1 - t` lies within `2^-10` of `n + 1`; psi is increasing, `psi(1) =
/// -0.5772..`, `psi(y) < ln y`). MPFR's digamma works there at about `-log2 d`
/// extra bits with Bernoulli numbers: 0.7 s at `t = -10^4 + 4.3e-14` (through
/// 2F1's large-parameter route, issue 37's scan); elsewhere it is fast.
fn psi_abs_upper(t: &Float) -> Result<crate::ball::Mag> {
    use crate::ball::Mag;
    if *t < 0.5 {
        let n = Float::with_val(t.prec(), t.round_ref());
        let d = exact_sub(t, &n);
        if !d.is_zero() && d.get_exp().is_some_and(|e| e <= -10) {
            let abs = Float::with_val(d.prec(), d.abs_ref());
            let (inv, _) = Float::with_val_round(64, abs.recip_ref(), Round::Up);
            let log_term = ((-n.to_f64()).max(0.0) + 2.0).ln().next_up() + 1.0;
            return Ok(Mag::from_float_up(&inv).add(Mag::from_f64(log_term.next_up())));
        }
    }
    Ok(Ball::from_float(t, t.prec()).digamma()?.abs_upper_mag())
}

/// [`gamma_ball`] without the rounding of long arguments: `Gamma(x)` at
/// `max(wp, x.prec())` bits.
fn gamma_exact(x: &Float, wp: u32) -> Result<Ball> {
    const SMALL: f64 = 64.0;
    if is_nonpositive_integer(x) {
        return Err(Error::Pole { function: "Gamma", at: x.to_f64() });
    }
    let xf = x.to_f64();
    if x.is_integer() && xf <= SMALL {
        return Ok(Ball::factorial(xf as u32 - 1, wp));
    }
    let twice = Float::with_val(x.prec() + 1, x * 2u32);
    if twice.is_integer() && xf.abs() <= SMALL {
        let sqrt_pi = Ball::pi(wp).sqrt()?;
        let half = Float::with_val(2, 0.5);
        return if xf > 0.0 {
            Ok(sqrt_pi.mul(&pochhammer(&half, (xf - 0.5) as u64, wp)))
        } else {
            sqrt_pi.div(&pochhammer(x, (0.5 - xf) as u64, wp))
        };
    }
    if xf < 1.0 && xf > -SMALL {
        let k = (1.0 - xf).ceil() as u64;
        // x + K exact may be long (x = 10^-300 + 1): through gamma_ball, which rounds it
        let shifted = exact_add(x, &int_float(k));
        return gamma_ball(&shifted, wp)?.div(&pochhammer(x, k, wp));
    }
    // Gamma(x) at x >= 2^61 exceeds every exponent range (ln Gamma(x) > x (ln x - 1)
    // > 2^66, MPFR's largest exponent is below 2^63): the overflow MPFR reports
    // after working at about log2(x) bits (0.17 s at x = 2.1e31839), at once. At
    // x <= -2^61 (not an integer: a pole is caught above) the reflection
    // Gamma(x) = pi/(sin(pi x) Gamma(1 - x)) [DLMF 5.5.3] puts |Gamma(x)| below
    // 2^-2^66 / |sin(pi x)|, and |sin(pi x)| >= 2 dist(x, Z) >= 2^(62 - prec(x)):
    // below every exponent range too (MPFR worked 0.17 s to report it, issue 37's
    // scan, `hyp2f1(21.01e31838, -67, 3.66e-106, -65.5)` at 10 bits)
    if x.get_exp().is_some_and(|e| e > 61) {
        let what = if x.is_sign_positive() { "gamma" } else { "gamma (its magnitude below the exponent range)" };
        return Err(Error::Overflow { what: what.into() });
    }
    // Negative x (x <= -64 here: smaller ones were shifted above). MPFR's Gamma is
    // slow there: within d of a pole -n it works at about wp + log2(1/d) bits with
    // Bernoulli numbers (over a minute at d = 4.5e-22713, 2F1's c - a in issue 37's
    // scan, `hyp2f1(16777216, 24.06, 45e-22714, -74.875)` at 11 bits), and at
    // x = -99978.75 (2F1's large-parameter route, `hyp2f1(17, 100001, 22.25,
    // -123.25)` at 130 bits) it ran for seconds. The reflection
    // Gamma(x) = pi / (sin(pi x) Gamma(1 - x)) [DLMF 5.5.3] with
    // sin(pi x) = (-1)^n sin(pi d) (x = -n + d, d exact, |d| <= 1/2) needs Gamma only
    // at 1 - x = n + 1 - d > 64, far from every pole (a long argument is rounded and
    // the rounding carried by gamma_ball), and sin at d: ball arithmetic, so the
    // enclosure is as rigorous as the rest.
    if *x < 0.5 {
        let n = Float::with_val(x.prec(), x.round_ref());
        let d = exact_sub(x, &n);
        if !d.is_zero() {
            let g = gamma_ball(&exact_sub(&int_float(1), x), wp + 8)?;
            let sin = Ball::from_float(&d, wp + 8).mul(&Ball::pi(wp + 8)).sin();
            let odd = !Float::with_val(n.prec() + 1, &n / 2u32).is_integer();
            let den = g.mul(&sin);
            return Ball::pi(wp + 8).div(&if odd { den.neg() } else { den });
        }
    }
    // MPFR's Gamma at wp.max(prec(x)) bits: refused at once when its estimated time
    // (the first call's, Bernoulli numbers included) passes the installed budget
    let bits = wp.max(x.prec());
    crate::budget::check_estimate("Gamma(x) (MPFR)", gamma_seconds(bits), f64::INFINITY)?;
    xball(x, wp).gamma()
}

// ----- cost ---------------------------------------------------------------

/// Estimated seconds of the first MPFR Gamma at `wp` bits (for cost decisions
/// only). MPFR's Gamma computes and caches Bernoulli numbers up to about the
/// working precision, at a cost growing about as `wp^3`: the first Gamma at 4000 /
/// 8000 / 12000 / 16000 / 24000 bits took 0.08 / 0.70 / 2.7 / 8.1 / 39 s (test
/// profile, load 3; at 35 000 bits 116 s); later ones at the same precision reuse
/// the cache. The estimate is the 8000-bit time scaled as `wp^3`.
pub(crate) fn gamma_seconds(wp: u32) -> f64 {
    0.7 * (f64::from(wp) / 8000.0).powi(3)
}

// ----- estimates (choosing only) ---------------------------------------------

/// f64 estimate of `ln |Gamma(x)|` (`+inf` at the poles); only for choosing.
pub(crate) fn lgamma_est(x: f64) -> f64 {
    if !x.is_finite() || (x <= 0.0 && x == x.floor()) {
        return f64::INFINITY;
    }
    if x < 0.5 {
        let s = (PI * x).sin().abs();
        return PI.ln() - s.ln() - lgamma_est(1.0 - x);
    }
    let mut x = x;
    let mut acc = 0.0;
    while x < 10.0 {
        acc -= x.ln();
        x += 1.0;
    }
    acc + (x - 0.5) * x.ln() - x + 0.5 * (2.0 * PI).ln() + 1.0 / (12.0 * x) - 1.0 / (360.0 * x * x * x)
}


#[cfg(test)]
mod tests {
    use super::*;

    /// The reflection at negative `x` against MPFR's Gamma at the same exact `x`
    /// (where MPFR is still quick: `x = -n +- 2^e`, `d = 2^-70` and `2^-200` next to
    /// the poles `-64`, `-101`, `-1000`, and `d` from 1/8 to 1/2): the balls overlap
    /// and carry the precision asked for.
    #[test]
    fn gamma_next_to_a_pole_by_reflection_matches_mpfr() {
        for n in [64u32, 101, 1000] {
            for (e, sign) in [(-70i32, 1i32), (-70, -1), (-200, 1), (-1, 1), (-1, -1), (-3, 1), (-2, -1)] {
                let x = Float::with_val(400, -(n as i32)) + Float::with_val(400, sign) * Float::with_val(2, Float::i_exp(1, e));
                for wp in [53u32, 128] {
                    let reflected = gamma_exact(&x, wp).unwrap();
                    let direct = Ball::from_float(&x, x.prec()).gamma().unwrap();
                    assert!(reflected.overlaps(&direct), "x = -{n} + {sign} 2^{e} at {wp}: {reflected:?} vs {direct:?}");
                    assert!(reflected.rel_accuracy_bits() >= wp as f64 - 4.0, "x = -{n} + {sign} 2^{e} at {wp}: {reflected:?}");
                }
            }
        }
    }

    /// `ln Gamma` in logarithms against MPFR's correctly rounded `ln |Gamma|` at
    /// 1600 bits, on both branches (MPFR's below `2^(wp+16)`, Stirling's above), at
    /// exact points and over balls, and the reflection at negative `x`.
    #[test]
    fn ln_gamma_in_logarithms_encloses_mpfr() {
        let lgamma = |x: &Float| {
            let mut lg = Float::new(1600);
            let mut sign = std::cmp::Ordering::Equal;
            (&mut lg, &mut sign).assign_round(x.ln_abs_gamma_ref(), Round::Nearest);
            (lg, sign)
        };
        for wp in [20u32, 64, 200] {
            for x in ["3.5", "4.2e18", "1e40", "1.5e80", "7e300"] {
                let xf = Float::with_val(1200, Float::parse(x).unwrap());
                let l = ln_gamma_positive(&Ball::from_float(&xf, xf.prec()), wp).unwrap();
                assert!(l.contains(&lgamma(&xf).0), "{x} at {wp}: {l:?}");
                // absolute error about 2^-(wp+16)
                assert!(l.rad() < Float::with_val(64, Float::i_exp(1, -(wp as i32))), "{x} at {wp}: {l:?}");
                // over a ball: every point's value inside
                let ball = Ball::with_radius(xf.clone(), &Float::with_val(64, Float::i_exp(1, -10)));
                let lb = ln_gamma_positive(&ball, wp).unwrap();
                for end in [ball.lower(), ball.upper()] {
                    assert!(lb.contains(&lgamma(&Float::with_val(1200, &end)).0), "{x} ball at {wp}: {lb:?}");
                }
            }
        }
        // Gamma(-4.2e18 - 0.25) and Gamma(-1e40 + 1/3) by reflection, as m e^l
        for x in ["-4200000000000000000.25", "-1e40"] {
            let xf = Float::with_val(1200, Float::parse(x).unwrap()) + Float::with_val(1200, 1) / 3u32;
            let g = ln_gamma_scaled(&Ball::from_float(&xf, xf.prec()), 64).unwrap();
            let (lg, sign) = lgamma(&xf);
            // m e^l / (sign e^lg) = 1: ln|m| + l - lg = 0 and the signs agree
            let m = crate::ball::Scaled::with_log(Ball::one(64), Ball::from_float(&Float::with_val(1600, -&lg), 1600));
            let ratio = g.mul(&m).to_ball(64).unwrap();
            let one = if sign == std::cmp::Ordering::Less { -1 } else { 1 };
            assert!(ratio.contains(&Float::with_val(64, one)) && ratio.rel_accuracy_bits() > 50.0, "{x}: {ratio:?}");
        }
    }

    /// `Gamma(y + d) / Gamma(y)` by Stirling's pair formula against MPFR's
    /// `ln |Gamma|` difference at 1600 bits, `y` from `2^100` to `10^300`, `d` of
    /// either sign and size, over exact points and balls.
    #[test]
    fn gamma_pair_by_stirling_encloses_mpfr() {
        let lgamma = |x: &Float| {
            let mut lg = Float::new(1600);
            let mut sign = std::cmp::Ordering::Equal;
            (&mut lg, &mut sign).assign_round(x.ln_abs_gamma_ref(), Round::Nearest);
            lg
        };
        for y in ["1267650600228229401496703205376", "3.3e95", "1e300"] {
            for d in ["50.25", "-75.5", "1e20", "-3e-7"] {
                let yf = Float::with_val(1200, Float::parse(y).unwrap());
                let df = Float::with_val(1200, Float::parse(d).unwrap());
                let xf = Float::with_val(1200, &yf + &df);
                let want = Float::with_val(1600, lgamma(&xf) - lgamma(&yf));
                for wp in [24u32, 64] {
                    let (xb, yb, db) = (Ball::from_float(&xf, 1200), Ball::from_float(&yf, 1200), Ball::from_float(&df, 1200));
                    let g = gamma_pair_scaled(&xb, &yb, &db, wp).unwrap();
                    let back = g.mul(&Scaled::with_log(Ball::one(wp), Ball::from_float(&Float::with_val(1600, -&want), 1600))).to_ball(wp).unwrap();
                    assert!(back.contains(&Float::with_val(64, 1)) && back.rel_accuracy_bits() > wp as f64, "y {y}, d {d} at {wp}: {back:?}");
                }
            }
        }
    }
}
