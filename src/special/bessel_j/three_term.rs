//! `J_n(x)` for large `n` and `x` by the three-term recurrence: forward from
//! certified `J_0(x)`, `J_1(x)` below the turning point (`k < x`), and past it
//! (`k > x`) by a product of ratios `J_k / J_{k-1}` from the backward
//! (continued-fraction) recurrence. Midpoints run on bare MPFR numbers; the
//! error bound is proven once for the whole run (no ball per step).
//!
//! # Forward part, `1 <= k < x` (the oscillatory region)
//!
//! `y_{k+1} = c_k y_k - y_{k-1}`, `c_k = 2k/x` [DLMF 10.6.1], is solved by
//! `J_k(x)` and `Y_k(x)`. Computed in floating point, the midpoints satisfy it
//! up to a local error `delta_k`, and the errors `e_k = y~_k - J_k` obey the
//! same recurrence forced by `delta_k`. Bounding `|e_k|` by absolute values
//! would grow like a Fibonacci sequence (`~e^{0.47 x}` at `n = x`); instead the
//! pair `(e_{k+1}, e_k)` is measured in the energy norm
//! `||(a, b)||_c = (a^2 - c a b + b^2)^{1/2}` (`0 <= c < 2`), the same argument
//! as the double-double path (`native_recurrence.rs`):
//!
//! * the step matrix `[[c_k, -1], [1, 0]]` preserves `a^2 - c_k a b + b^2`
//!   (expand), so a step adds only `|delta_k|` to the norm;
//! * `|a b| <= Q_c / (2 - c)` (from `a^2 + b^2 >= 2|ab|`), so going from `c_k`
//!   to `c_{k+1} = c_k + 2/x` multiplies the norm by at most
//!   `(1 + 1/(x - k))^{1/2}`; over `k = 1..t-2` the product is at most
//!   `exp(1/2 sum 1/(x - k)) <= ((x - 1)/(x - t + 1))^{1/2}` (the sum is below
//!   `int_1^{t-1} ds/(x - s)`, the summand increasing);
//! * at the start `||(e_1, e_0)||_{c_1} <= |e_0| + |e_1|`, and at the end
//!   `Q_c(a, b) >= (1 - c^2/4) max(a^2, b^2)` with `c = c_{t-1}`, i.e. a factor
//!   `x / (x^2 - (t-1)^2)^{1/2}`.
//!
//! **Local errors.** The forward run is in fixed point: `Y_k = y~_k 2^F`
//! (`F = wp`) are integers, `C = round(2^(F+G+1)/x)` (`G = 64` extra bits, so
//! `|C 2^-(F+G) - 2/x| <= 2^-(F+G)`), `T_k = k C` exactly, and
//! `Y_{k+1} = floor(T_k Y_k / 2^(F+G)) - Y_{k-1}`. So
//! `y~_{k+1} = (2/x k + k gamma) y~_k - y~_{k-1} - phi 2^-F`, `|gamma| <= 2^-(F+G)`,
//! `|phi| < 1`, and `|delta_k| <= (k 2^E 2^-G + 1) 2^-F`, where `2^E` bounds
//! every `|y~_k|` (from the integers' bit lengths). The start values are the
//! midpoints of `J_0`, `J_1` rounded to `F` fraction bits (`2^-(F+1)` each).
//! Hence, for `2 <= t < x` and both `i = t - 1, t`,
//!
//! `|y~_i - J_i| <= (|e_0| + |e_1| + 2^-F + (t - 1)(t 2^(E-G) + 1) 2^-F) x (x - 1)^{1/2} / ((x - t + 1) (x + t - 1)^{1/2})`.
//!
//! (Integer arithmetic is about 1.7x faster than MPFR here: GMP's `mpz`
//! multiply and shift against `mpfr_fms`, both exact up to the one floor.)
//!
//! `J_0`, `J_1` come from the other methods of [`super`] (Hankel's expansion
//! for large `x`). Against `|J_t| ~ (x^2 - t^2)^{-1/4}` the bound costs about
//! `log2(t x / (x - t))` bits, paid as guard bits; near a zero of `J_n` the Ziv
//! loop of [`super`] adds more.
//!
//! # Past the turning point, `n >= x`
//!
//! Let `m` be the largest integer below `x`. The forward part certifies
//! `J_{m-1}`, `J_m`, and one ball step gives `J_{m+1}` (positive: `m+1 >= x`
//! lies below the first zero `j_{m+1,1} > m + 1` [DLMF 10.21.3]). Then
//! `J_n = J_{m+1} prod_{k=m+2}^{n} rho_k`, `rho_k = J_k / J_{k-1}`, where for
//! `k > x` [DLMF 10.6.1]
//!
//! `rho_k = x / (2k - x rho_{k+1})`, and `0 < rho_k <= 1`
//!
//! (`J_k > 0` for `k > x`; `rho_k -> 0` as `k -> inf`, and `rho_{k+1} <= 1`
//! gives `rho_k <= x/(2k - x) <= 1`: downward induction). Also
//! `rho_k >= x/(2k)`. For `a, b` in `[0, 1]` and `k >= x + 1`,
//! `f_k(a) = x/(2k - xa)` is increasing, `f_k(a) <= f_k(1) = R_k`,
//! `R_k = x/(2k - x) < 1` (decreasing in `k`), and
//! `|f_k(a) - f_k(b)| <= R_k^2 |a - b|`.
//!
//! The ratios are not divided out: the backward recurrence
//! `y~_{k-1} = fl(fl(k c~) y~_k - y~_{k+1})` runs on bare midpoints from
//! `y~_{N+1} = 0`, `y~_N = 1` (so `r~_{N+1} = 0` and
//! `eps_{N+1} = |r~_{N+1} - rho_{N+1}| <= 1`), and `r~_k = y~_k / y~_{k-1}`
//! (exact quotients of the computed numbers) telescope:
//! `prod_{k=m+2}^n r~_k = y~_n / y~_{m+1}`.
//! Dividing a step by `y~_k`: `1/r~_k = ((2k/x)(1 + phi) - r~_{k+1})(1 + theta)`,
//! `|phi| <= 2.01u`, `|theta| <= u`; as `2k/(2k - x r) <= 2` for `k >= x`,
//! `r~_k = f_k(r~_{k+1}) (1 + eta)` with `|eta| <= 7.1u`, and `r~_k` stays
//! in `(0, 1)` (`7.1u x < 2`, implied by the check `L <= 1/2` below). So
//! `eps_k <= R_k^2 eps_{k+1} + 7.1u R_k`, and unrolled (the `R_j` decrease)
//! `eps_k <= C_k + 7.1u R_k / (1 - R_k^2)`, `C_k = prod_{j=k}^N R_j^2 <= C_n`
//! for `k <= n`. A factor's relative error is `eta_k <= eps_k 2k/x`
//! (`rho_k >= x/(2k)`), and `(2k/x) R_k / (1 - R_k^2) = (2k - x)/(2(k - x))`.
//! With the one final division, `|ln(P~/P)| <= L = 2 sum eta_k + u` (all
//! terms `<= 1/2`), and `|P~ - P| <= 2 L P~` for `L <= 1/2`
//! (`e^L - 1 <= 2L` there). `N` is chosen (an f64 walk on `log2 R_k`, so that
//! `x` below f64's range works too) so that `C_n` is below `2^-wp` over the
//! number of factors; the sum `A = sum (2k - x)/(2(k - x))` is
//! about `(n - x) + (x/2) ln(n - x)`.
//!
//! # Sequences: `J_0(x), ..., J_nmax(x)` ([`bessel_j_sequence_three_term`])
//!
//! The same two runs, keeping every value (`x > 0`, `m` the largest integer
//! below `x`, or 0):
//!
//! * `J_0`, `J_1`: certified by [`super`] (relative `2^-wp`).
//! * `2 <= i <= min(m, nmax)`: the forward run to `t = min(m, nmax)`. The bound
//!   above holds for every `t' <= t` with the same `E` (a bound on every
//!   `|y~_k|` of the run), so `y~_i` gets the bound with `t = i`:
//!   `(|e_0| + |e_1| + 2^-F + (i - 1)(i 2^(E-G) + 1) 2^-F)` times the growth at
//!   `i`. It is largest next to the turning point, about `x^2 2^-wp`.
//! * `J_{m+1}`: one ball step from `J_{m-1}`, `J_m` (`m >= 1`; `J_1` itself
//!   when `x <= 1`).
//! * `m + 2 <= k <= nmax`: one ratio walk from `N` (chosen for `n = nmax`) down
//!   to `m + 1`, keeping `y~_k`. For each `k` the partial product
//!   `y~_k / y~_{m+1} = prod_{j=m+2}^k r~_j` has `|ln(y~_k/y~_{m+1}) - ln(J_k/J_{m+1})|
//!   <= L0 = 2 sum_{j=m+2}^{nmax} eta_j` (its `eta_j` are a subset of the
//!   whole walk's, with `C_j <= C_nmax`). So
//!   `J_k in (J_{m+1} / y~_{m+1}) y~_k [1 +- 2 L0]`: one ball division, then
//!   one ball product per `k`.
//!
//! No radius is carried from step to step, so nothing grows like the ball
//! recurrence's `~2^(0.67 x)` (the downward ball recurrence adds the radii of
//! `(2n/x) J_n` and `J_{n+1}`: the growth of `|y_{n-1}| = (2n/x)|y_n| + |y_{n+1}|`,
//! `exp(int_0^x asinh(n/x) dn) = e^(0.467 x)`, measured as `0.68 x` bits).
//! Radii: at most `2^-wp` times about `x^2` absolute below the turning point,
//! `x^{7/3}` relative at it, and `x^{7/3} + 28 A` relative past it (the
//! tolerance table of `tests/bessel_sequence_mp.rs`).
//!
//! Cost: `max(n, x)` steps of three MPFR operations at `wp` bits plus two
//! certified values at `x`: about 0.1 us per step at 200 bits.

use rug::float::Round;
use rug::{Assign, Float, Integer};

use crate::ball::{Ball, Mag};
use crate::error::{Error, Result};
use crate::special::check_finite;

/// Most steps the backward ratio recurrence may run past `n` before giving up.
const MAX_RATIO_STEPS: u64 = 50_000_000;

/// Upper bound of `x (x - 1)^{1/2} / ((x - t + 1) (x + t - 1)^{1/2})` for exact `x > t >= 2`:
/// the energy norm's growth and its conversion back to one component. In f64:
/// the numerator grows with `x` and the denominator too, so the numerator is
/// taken at `x` rounded up and the denominator at `x` rounded down; nine
/// roundings to nearest (each `2^-53` relative) are covered by the factor
/// `1 + 2^-40`. Infinite (no bound) when `x` is beyond `2^40` or `t` not below it.
fn forward_growth_up(x: &Float, t: u64) -> Mag {
    let (xu, xd) = (x.to_f64_round(Round::Up), x.to_f64_round(Round::Down));
    let tm1 = (t - 1) as f64; // exact: t < x <= 2^40
    let lo = xd - tm1;
    if !(xu <= GROWTH_MAX_X && lo > 0.0) {
        return Mag::inf();
    }
    let num = xu * (xu - 1.0).sqrt();
    let den = lo * (xd + tm1).sqrt();
    Mag::from_f64(num / den * (1.0 + GROWTH_SLACK))
}

/// Largest `x` of [`forward_growth_up`] (`x - t + 1 >= 1` then stays positive in f64).
const GROWTH_MAX_X: f64 = (1u64 << 40) as f64;
/// Relative slack of [`forward_growth_up`]'s f64 evaluation.
const GROWTH_SLACK: f64 = 1.0 / (1u64 << 40) as f64;

/// Extra fraction bits of the fixed-point `2/x` (so that `k |2/x - C 2^-(F+G)|`
/// stays far below one unit for every `k` up to `2^40`).
const COEFF_EXTRA_BITS: u32 = 64;

/// The forward run of the module docs in fixed point: its last two values and
/// what the error bound of every value needs.
struct ForwardRun {
    /// `Y_{t-1}`, `Y_t` (`y~_k = Y_k 2^-F`).
    last: (Integer, Integer),
    /// `|e_0| + |e_1| + 2^-F`: the start values' errors and their rounding.
    start: Mag,
    /// `E` with `2^E >= max |y~_k|` over the run (from the integers' bit lengths).
    e: i64,
    /// Fraction bits `F`.
    f: u32,
}

impl ForwardRun {
    /// The bound of the module docs on `|y~_i - J_i|` and `|y~_{i-1} - J_{i-1}|`, `2 <= i <= t`:
    /// `(start + (i - 1)(i 2^(E-G) + 1) 2^-F)` times the energy-norm growth.
    fn bound(&self, i: u64, x: &Float) -> Mag {
        let g = COEFF_EXTRA_BITS as i64;
        let per_step = Mag::from_f64(i as f64).mul(Mag::pow2(self.e - g)).add(Mag::from_f64(1.0)).mul(Mag::pow2(-(self.f as i64)));
        self.start.add(Mag::from_f64((i - 1) as f64).mul(per_step)).mul(forward_growth_up(x, i))
    }
}

/// `y~_k = Y_k 2^-F` as an exact float.
fn from_fixed(v: &Integer, f: u32) -> Float {
    Float::with_val(v.significant_bits().max(2), v) >> f
}

/// The forward recurrence in fixed point from certified `J_0`, `J_1` to `t`
/// (`2 <= t < x`), calling `visit(k, Y_k)` for `k = 2..=t` (module docs).
fn forward_run(t: u64, x: &Float, j0: &Ball, j1: &Ball, wp: u32, mut visit: impl FnMut(u64, &Integer)) -> Result<ForwardRun> {
    debug_assert!(t >= 2 && *x > t);
    let f = wp; // fraction bits F of Y_k = y~_k 2^F
    let g = COEFF_EXTRA_BITS;
    let to_fixed = |v: &Float, shift: u32| -> Result<Integer> {
        let scaled = Float::with_val(v.prec().max(2), v) << shift;
        scaled
            .to_integer() // round to nearest
            .ok_or_else(|| Error::Overflow { what: "Bessel recurrence start value".into() })
    };
    // C = round(2^(F+G+1) / x): |C 2^-(F+G) - 2/x| <= 2^-(F+G) (1/2 for the rounding
    // to an integer, far less for the (wp + 2G)-bit reciprocal).
    let c = to_fixed(&Float::with_val(wp + 2 * g, x.recip_ref()), f + g + 1)?;
    // Y_0, Y_1 = round(mid 2^F): the start errors grow by at most 2^-(F+1) each.
    let mut a = to_fixed(j0.mid(), f)?;
    let mut b = to_fixed(j1.mid(), f)?;
    let mut tk = Integer::new(); // T_k = k C, exact
    let mut s = Integer::new();
    let mut max_bits = a.significant_bits().max(b.significant_bits());
    for k in 1..t {
        tk += &c;
        s.assign(&tk * &b);
        s >>= f + g; // floor: an error below one unit 2^-F
        s -= &a;
        max_bits = max_bits.max(s.significant_bits());
        visit(k + 1, &s);
        std::mem::swap(&mut a, &mut b);
        std::mem::swap(&mut b, &mut s);
    }
    // a = Y_{t-1}, b = Y_t. Local error per step (module docs):
    // |delta_k| <= (k 2^E 2^-G + 1) 2^-F with 2^E = 2^(max_bits - F) >= max |y~_k|.
    let start = j0.rad_mag().add(j1.rad_mag()).add(Mag::pow2(-(f as i64)));
    Ok(ForwardRun { last: (a, b), start, e: max_bits as i64 - f as i64, f })
}

/// Certified `(J_{t-1}(x), J_t(x))` for `2 <= t < x` from certified `J_0`, `J_1`
/// (forward recurrence in fixed point with the energy-norm bound of the module docs).
fn forward_pair(t: u64, x: &Float, j0: &Ball, j1: &Ball, wp: u32) -> Result<(Ball, Ball)> {
    let run = forward_run(t, x, j0, j1, wp, |_, _| {})?;
    let bound = run.bound(t, x);
    let (a, b) = &run.last;
    Ok((Ball::with_mag(from_fixed(a, run.f), bound), Ball::with_mag(from_fixed(b, run.f), bound)))
}

/// Largest integer strictly below `x` (`x > 0` exact).
pub(crate) fn below_turning_point(x: &Float) -> u64 {
    let c = Float::with_val(x.prec(), x.ceil_ref());
    let ci = c.to_integer().map_or(0, |i| i.to_u64().unwrap_or(u64::MAX));
    ci.saturating_sub(1)
}

/// `J_n(x)` by the recurrence (`n >= 2`, `x > 1` exact), given certified
/// `J_0(x)`, `J_1(x)` at working precision `wp`: forward for `n < x`, forward
/// to the turning point then the ratio product for `n >= x`.
pub fn bessel_j_three_term(n: u64, x: &Float, j0: &Ball, j1: &Ball, wp: u32) -> Result<Ball> {
    crate::error::check_working_prec(wp)?;
    if n < 2 || *x <= 1 {
        return Err(Error::precondition("three-term recurrence needs n >= 2 and x > 1"));
    }
    let m = below_turning_point(x);
    if n <= m {
        return Ok(forward_pair(n, x, j0, j1, wp)?.1);
    }
    let (jm1, jm) = if m == 1 { (j0.clone(), j1.clone()) } else { forward_pair(m, x, j0, j1, wp)? };
    let j_next = past_turning_point(m, x, &jm1, &jm)?;
    if n == m + 1 {
        return Ok(j_next);
    }
    let (mut y_n, mut y_a) = (Float::new(wp), Float::new(wp));
    let l0 = ratio_walk(n, m, x, wp, |k, y| {
        if k == n {
            y_n.assign(y);
        } else if k == m + 1 {
            y_a.assign(y);
        }
    })?;
    // prod_{k=m+2}^n r~_k = y~_n / y~_{m+1}, plus the one rounding of this division.
    let prod = Float::with_val(wp, &y_n / &y_a);
    let l = l0.add(Mag::pow2(-(wp as i64)));
    if !l.le(&Mag::from_f64(0.5)) {
        return Err(Error::NoConvergence { function: "bessel_j (ratio recurrence bound)", terms: n - m });
    }
    let rad = Mag::from_float_up(&prod).mul(l).mul_2exp(1);
    Ok(j_next.mul(&Ball::with_mag(prod, rad)))
}

/// `J_{m+1} = (2m/x) J_m - J_{m-1}` [DLMF 10.6.1] in balls (`m >= 1`), with `x` exact.
fn past_turning_point(m: u64, x: &Float, jm1: &Ball, jm: &Ball) -> Result<Ball> {
    let xb = Ball::from_float(x, x.prec().max(jm.prec()));
    let m_i = i64::try_from(m).map_err(|_| Error::IntegerOutOfRange { arg: "recurrence start", value: i64::MAX, min: 0, max: i64::MAX })?;
    Ok(jm.mul_i64(2 * m_i).div(&xb)?.sub(jm1))
}

/// The backward recurrence of the ratio part (module docs), for `m` the largest
/// integer below `x` and `n >= m + 2`: `y_{k-1} = (2k/x) y_k - y_{k+1}` from
/// `y_{N+1} = 0`, `y_N = 1` on bare midpoints (no division), calling
/// `visit(k, y~_k)` for `m + 1 <= k <= n`. Returns `L0 = 2 sum_{k=m+2}^n eta_k`,
/// which bounds `|ln(y~_k / y~_{m+1}) - ln(J_k / J_{m+1})|` for every
/// `m + 2 <= k <= n` (`y~_k / y~_{m+1}` is exactly the product of the computed
/// ratios `r~_j = y~_j / y~_{j-1}`, `j = m+2..=k`, and every partial sum of the
/// `eta_j` is below the whole).
fn ratio_walk(n: u64, m: u64, x: &Float, wp: u32, mut visit: impl FnMut(u64, &Float)) -> Result<Mag> {
    debug_assert!(n >= m + 2);
    // x < n <= 2^24 here (the callers' caps), so x's f64 rounding moves every
    // f64 quantity below by far less than the slack used. R_k and C_n are kept
    // as base-2 logarithms (x may be far below f64's range: x = 2^-2000).
    let xf = x.to_f64();
    let lx = Float::with_val(64, x.log2_ref()).to_f64(); // log2 x, within 2^-60 relative
    // log2 R_k = log2 x - log2(2k - x), raised by a relative slack (an upper bound)
    let log_r = |k: u64| {
        let l = lx - (2.0 * k as f64 - xf).log2();
        l + 1e-9 * (1.0 + l.abs())
    };
    let factors = (n - m - 1) as f64;
    // Walk up from n until C_n = prod_{j=n}^N R_j^2 <= 2^-(wp + log2(factors n / x) + 8).
    let want = wp as f64 + ((factors * n as f64).log2() - lx).max(0.0) + 8.0;
    let mut log_c = 0.0f64; // log2 C_n (an upper bound)
    let mut top = n;
    while -log_c < want {
        log_c += 2.0 * log_r(top);
        top += 1;
        if top - n > MAX_RATIO_STEPS {
            return Err(Error::NoConvergence { function: "bessel_j (ratio recurrence)", terms: top - n });
        }
    }
    // top = N + 1: y~_{N+1} = 0, y~_N = 1, so r~_{N+1} = 0 and |r~_{N+1} - rho_{N+1}| <= 1.
    let mut c = Float::with_val(wp, x.recip_ref());
    c <<= 1u32; // fl(2/x)
    let mut a = Float::with_val(wp, 0); // y~_{k+1}
    let mut b = Float::with_val(wp, 1); // y~_k
    let mut s = Float::new(wp);
    let mut ck = Float::new(wp); // fl(k c~)
    // sum over the product's range of (2k/x) R_k / (1 - R_k^2) = (2k - x) / (2 (k - x))
    let mut amp_sum = 0.0f64;
    let mut k = top - 1;
    loop {
        if k <= n {
            visit(k, &b);
            if k >= m + 2 {
                let kf = k as f64;
                amp_sum += (2.0 * kf - xf) / (2.0 * (kf - xf));
            }
        }
        if k == m + 1 {
            break;
        }
        // y~_{k-1} = fl(fl(k c~) y~_k - y~_{k+1})
        ck.assign(&c * k);
        s.assign(b.mul_sub_ref(&ck, &a)); // one rounding (mpfr_fms)
        std::mem::swap(&mut a, &mut b);
        std::mem::swap(&mut b, &mut s);
        k -= 1;
    }
    // L0 = 2 [ C_n factors (2n/x) + 7.1 u A ] in Mag (u = 2^-wp), the f64 parts with slack
    // (A is a sum of positive f64 terms: relative error far below 1e-6).
    let slack = 1.0 + 1e-6;
    // C_n factors (2n/x) = 2^(log2(2 factors n) - log2 x + log2 C_n)
    let log_c_part = (2.0 * factors * n as f64 * slack).log2() - lx + log_c;
    let c_part = Mag::pow2((log_c_part + 1e-9 * (1.0 + log_c_part.abs())).ceil() as i64);
    let u_part = Mag::from_f64(7.1 * amp_sum * slack).mul(Mag::pow2(-(wp as i64)));
    Ok(c_part.add(u_part).mul_2exp(1))
}

// ---------------------------------------------------------------- sequences

/// Certified `J_0(x), ..., J_nmax(x)` by one forward run and one ratio walk
/// at working precision `wp` (`x > 0` exact): the **Sequences** section of the
/// module docs. The radii stay near `2^-wp` times a modest power of `x`
/// (about `x^{4/3}` relative at the turning point), whatever `x`: the
/// recurrence runs on midpoints and its error is bounded once, where the ball
/// recurrence of [`super::bessel_j_sequence_mp`] widens by about `0.67 x` bits.
///
/// Errors: `wp` outside `2 ..= MAX_WORKING_PREC` ([`Error::Precision`]), `x`
/// not finite or not positive, `nmax` above [`super::MAX_SEQUENCE_ORDER`] or
/// `x` above [`super::MAX_SEQUENCE_ARGUMENT`] (the run is `max(nmax, x)`
/// steps long), and [`Error::NoConvergence`] when `wp` is too small for the
/// bound to hold (`L0 > 1/2`).
pub fn bessel_j_sequence_three_term(nmax: u64, x: &Float, wp: u32) -> Result<Vec<Ball>> {
    crate::error::check_working_prec(wp)?;
    check_finite(x, "x")?;
    if *x <= 0 || *x > super::MAX_SEQUENCE_ARGUMENT {
        let allowed = crate::error::Interval::left_open(0.0, super::MAX_SEQUENCE_ARGUMENT);
        return Err(Error::OutOfRange { arg: "x", value: x.to_f64(), allowed });
    }
    if nmax > super::MAX_SEQUENCE_ORDER as u64 {
        let max = super::MAX_SEQUENCE_ORDER as i64;
        return Err(Error::IntegerOutOfRange { arg: "nmax", value: i64::try_from(nmax).unwrap_or(i64::MAX), min: 0, max });
    }
    let j0 = super::bessel_j_ball(0, x, wp)?;
    if nmax == 0 {
        return Ok(vec![j0]);
    }
    let j1 = super::bessel_j_ball(1, x, wp)?;
    let m = below_turning_point(x);
    let mut out = Vec::with_capacity(nmax as usize + 1);
    out.push(j0);
    out.push(j1);
    // Below the turning point: the forward run, each value with its own bound.
    let t = m.min(nmax);
    if t >= 2 {
        let mut mids = Vec::with_capacity(t as usize - 1);
        let run = forward_run(t, x, &out[0], &out[1], wp, |_, y| mids.push(from_fixed(y, wp)))?;
        for (i, mid) in (2..=t).zip(mids) {
            out.push(Ball::with_mag(mid, run.bound(i, x)));
        }
    }
    if nmax <= m {
        return Ok(out);
    }
    // Past it: J_{m+1} (J_1 itself when x <= 1), then J_k = J_{m+1} y~_k / y~_{m+1}.
    if m >= 1 {
        let next = past_turning_point(m, x, &out[m as usize - 1], &out[m as usize])?;
        out.push(next);
    }
    if nmax == m + 1 {
        return Ok(out);
    }
    let anchor = m as usize + 1;
    let mut ys = vec![Float::new(wp); (nmax - m) as usize]; // y~_k at k - (m + 1)
    let l0 = ratio_walk(nmax, m, x, wp, |k, y| ys[(k - m - 1) as usize].assign(y))?;
    if !l0.le(&Mag::from_f64(0.5)) {
        return Err(Error::NoConvergence { function: "bessel_j sequence (ratio recurrence bound)", terms: nmax - m });
    }
    // J_k in J_{m+1} (y~_k / y~_{m+1}) [e^-L0, e^L0], and e^L0 - 1 <= 2 L0 for L0 <= 1/2.
    let scale = out[anchor].div(&Ball::from_float(&ys[0], wp))?;
    for y in ys.into_iter().skip(1) {
        let rad = Mag::from_float_up(&y).mul(l0).mul_2exp(1);
        out.push(scale.mul(&Ball::with_mag(y, rad)));
    }
    Ok(out)
}

/// A fixed-point forward step against an MPFR backward step (1.5 in the plan's units):
/// measured 1.7x cheaper.
const FORWARD_STEP_WEIGHT: f64 = 0.9;

/// f64 estimates for the chooser: `(steps, guard bits)` of [`bessel_j_three_term`]
/// at `(n, x, wp)` (`n >= 2`, `x > 1`).
pub(crate) fn plan(n: u64, x: f64, wp: u32) -> (f64, f64) {
    let nf = n as f64;
    let m = (x.ceil() - 1.0).max(1.0);
    let top = nf.min(m);
    // the bound's growth t x / (x - t) against |J_t| ~ (x^2 - t^2)^{-1/4}, plus slack
    let gap = (x - top + 1.0).max(1.0);
    let mut guard = (9.0 * x * top / gap * ((x - top) * (x + top)).max(1.0).powf(0.25) * (x / (x + top)).sqrt()).log2().max(0.0) + 12.0;
    let mut steps = top * FORWARD_STEP_WEIGHT;
    if nf > m {
        // backward part: the walk past n until prod R_j^2 < 2^-wp, then down to m + 1
        let mut log_c = 0.0;
        let mut j = nf;
        while -log_c < wp as f64 + 16.0 && j - nf < 1e7 {
            log_c += 2.0 * (x / (2.0 * j - x)).log2();
            j += 1.0;
        }
        steps += (j - m) * 1.5;
        guard += ((nf - m) * nf / x).log2().max(0.0) + 4.0;
    }
    (steps, guard)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn growth_factor_is_an_upper_bound() {
        let x = Float::with_val(53, 20000.5);
        let g = forward_growth_up(&x, 10000).to_f64_up();
        let exact = 20000.5 * 19999.5f64.sqrt() / (10001.5 * 29999.5f64.sqrt());
        assert!(g >= exact && g <= exact * (1.0 + 1e-11), "{g} vs {exact}");
        assert!(!forward_growth_up(&Float::with_val(53, 100.0), 101).is_finite());
    }

    #[test]
    fn turning_point_index() {
        assert_eq!(below_turning_point(&Float::with_val(53, 5000.25)), 5000);
        assert_eq!(below_turning_point(&Float::with_val(53, 5000.0)), 4999);
        assert_eq!(below_turning_point(&Float::with_val(53, 1.5)), 1);
    }
}
