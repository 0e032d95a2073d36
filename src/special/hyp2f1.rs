//! Gauss hypergeometric function `2F1(a, b; c; z)`, real parameters, real `z <= 1`.
//!
//! # Method
//!
//! `2F1(a, b; c; z) = sum_n (a)_n (b)_n / ((c)_n n!) z^n` [DLMF 15.2.1] for
//! `|z| < 1`, continued to `z < -1` and to `z = 1` as below. Every formula is
//! evaluated in ball arithmetic (or in place with an a-priori rounding bound,
//! see *Error argument*), so the returned ball contains the exact value at the
//! given binary inputs. [`choose_algorithm`] picks one [`Algorithm`]; each is a
//! public function callable on its own at a working precision `wp`.
//!
//! ## Special cases first
//!
//! * **Terminating** ([`Algorithm::Polynomial`]): `a` or `b` a non-positive
//!   integer `-d`. `2F1` is a polynomial of degree `d`, summed for any `z <= 1`.
//!   For `d <= 300` it is summed *exactly* in rationals (`rug::Rational`) and
//!   rounded once, so exact zeros (e.g. Chu-Vandermonde zeros at `z = 1`) come
//!   back as `[0 +/- 0]`; longer polynomials use the series engine below.
//! * **`c` a non-positive integer** `-m`: a pole of every term with `n > m`;
//!   allowed only when the series terminates first (`d <= m`, the usual
//!   convention, as in mpmath), otherwise [`Error::Domain`].
//! * **`z = 1`** ([`Algorithm::Gauss`]): Gauss's sum
//!   `Gamma(c) Gamma(c-a-b) / (Gamma(c-a) Gamma(c-b))` when `c - a - b > 0`
//!   [DLMF 15.4.20]; a terminating series uses the polynomial (Chu-Vandermonde,
//!   DLMF 15.4.24, for any `c - a - b`); otherwise the series diverges and the
//!   result is [`Error::Domain`].
//! * `z = 0` gives exactly 1.
//!
//! ## Regions (non-terminating)
//!
//! | region | algorithm | series argument |
//! |---|---|---|
//! | `|z| <= 1/2` | [`Algorithm::Direct`]: DLMF 15.2.1 | `z`, `|z| <= 1/2` |
//! | `-1 <= z < -1/2` | [`Algorithm::Pfaff`]: `(1-z)^{-a} 2F1(a, c-b; c; z/(z-1))` [DLMF 15.8.1] | `w in (1/3, 1/2]` |
//! | `1/2 < z < 1` | [`Algorithm::Connection`] / [`Algorithm::ConnectionLog`] (1-z formula) | `1 - z in (0, 1/2)` |
//! | `z < -1` | [`Algorithm::PfaffConnection`] / [`Algorithm::PfaffConnectionLog`]: Pfaff to `w = z/(z-1) in (1/2, 1)`, then the 1-w formula with `1 - w = 1/(1-z)` | `1/(1-z) in (0, 1/2)` |
//!
//! Within `-1 <= z <= 1/2` the same function is also
//! `(1-z)^{c-a-b} 2F1(c-a, c-b; c; z)` ([`Algorithm::Euler`], DLMF 15.8.1) and
//! `(1-z)^{-b} 2F1(c-a, b; c; w)` ([`Algorithm::PfaffSwapped`]); for `z < 0`
//! also `(1-z)^{-a} 2F1(a, c-b; c; w)` with `|w| < |z|`. [`choose_algorithm`]
//! simulates the term magnitudes of these series in f64 and takes the cheapest
//! (terms times precision plus cancellation, the direct series on ties). This
//! matters for large negative parameters: `2F1(-N+1/2, 2; 3; 1/2)` loses about
//! `0.6 N` bits to cancellation in the direct series, while the Euler transform
//! has positive terms (`N = 10^6` takes 0.2 s instead of minutes).
//!
//! * **1-z formula** (`s = c - a - b` not an integer) [DLMF 15.8.4, 15.10.21]:
//!   `2F1 = G1 2F1(a, b; 1-s; 1-z) + (1-z)^s G2 2F1(c-a, c-b; 1+s; 1-z)`,
//!   `G1 = Gamma(c) Gamma(s) / (Gamma(c-a) Gamma(c-b))`,
//!   `G2 = Gamma(c) Gamma(-s) / (Gamma(a) Gamma(b))`. All parameter combinations
//!   (`c-a`, `c-a-b`, `1-s`, ...) are formed *exactly* (binary sums with enough
//!   bits), so the Gamma values are taken at exact points; `1/Gamma` at a pole
//!   is the exact zero, which switches the corresponding piece off. Gamma ratios
//!   whose arguments differ by a small integer are Pochhammer products
//!   (`Gamma(x+k)/Gamma(x) = (x)_k`), which is exact in the limit and cheap.
//!   A series `2F1(p, q; p; x)` is the power `(1-x)^{-q}` [DLMF 15.4.6]; this is
//!   what makes the paper's model case `2F1(1, k+1/2; k+2; y)` cheap near 1
//!   (the second piece is `y^{-k-1}`).
//! * **Degenerate 1-z formula** (`s = m` an integer): the Gamma poles of the two
//!   pieces cancel and the limit has logarithms [DLMF 15.8.10, A&S 15.3.10-11].
//!   For `m >= 0`, with `u = 1 - z`,
//!   `2F1(a, b; a+b+m; z) = Gamma(m) Gamma(c) / (Gamma(a+m) Gamma(b+m)) sum_{n<m} (a)_n (b)_n / (n! (1-m)_n) u^n`
//!   `  - (-u)^m Gamma(c) / (Gamma(a) Gamma(b)) sum_n (a+m)_n (b+m)_n / (n! (n+m)!) u^n`
//!   `    * [ln u - psi(n+1) - psi(n+m+1) + psi(a+m+n) + psi(b+m+n)]`
//!   (the first sum is absent for `m = 0`). For `m < 0` Euler's transformation
//!   `2F1(a, b; c; z) = u^{c-a-b} 2F1(c-a, c-b; c; z)` [DLMF 15.8.1] maps to
//!   `-m > 0` (this is A&S 15.3.12). The digamma values start from MPFR's
//!   correctly rounded `psi` at exact points and are advanced with
//!   `psi(x+1) = psi(x) + 1/x` in balls. If `c - a` or `c - b` is a non-positive
//!   integer, Euler's transformation makes the function `u^s` times a polynomial
//!   ([`Algorithm::Euler`]); together with the terminating case this
//!   removes every sub-case in which the digamma arguments could hit a pole.
//! * **`z < -1`**: Pfaff gives `(1-z)^{-a} 2F1(a, c-b; c; w)` with
//!   `w = z/(z-1) in (1/2, 1)`; that function is then evaluated by the 1-w
//!   formula above (parameters `a, c-b, c`; `s' = b - a`, degenerate when `b - a`
//!   is an integer), with the series argument `1 - w = 1/(1-z)`. If `c - b` (or
//!   `c - a`, then Pfaff on `b`) is a non-positive integer the transformed
//!   function is a polynomial in `w` (summed exactly in rationals).
//!
//! ## Large parameters: direct series near 1
//!
//! With large parameters the two pieces of the 1-z formula can both be far
//! larger than their sum: for `2F1(1, k+1/2; k+2; y)` they are about
//! `y^{-k}`, so at `k = 1000`, `y = 0.6` some 740 bits cancel. For
//! `1/2 < z < 1` (and for `w` after Pfaff) [`choose_algorithm`] therefore
//! compares estimated costs: an f64 simulation of the term magnitudes of the
//! direct series in `z` and of the 1-z series, the cancellation between the
//! pieces from f64 log-Gamma estimates, and a fixed price for the Gamma
//! values. It takes the direct series (`|z| < 1` converges; the ratio test is
//! rigorous) when that is cheaper. The estimate only chooses; the certified
//! error bound never depends on it.
//!
//! # Error argument
//!
//! * **Series engine** ([`series_2f1`]): terms and partial sums are computed in
//!   place at `p = max(wp, 64)` bits with round-to-nearest (`u = 2^-p`). Each
//!   step `t_{n+1} = t_n (a+n)(b+n) z / ((c+n)(n+1))` performs at most 8
//!   roundings (3 when `2^k a`, `2^k b`, `2^k c` are small integers: the ratio is
//!   then a quotient of two exact machine integers), so
//!   `|t~_n - t_n| <= gamma_{8n} |t_n| <= 10 n u |t~_n|`, and each addition errs
//!   by at most `2 u |s~_k|`. The radius is
//!   `10 N u sum|t~_n| + 2 N u max|s~_k|` (zero when MPFR reports every
//!   operation exact) plus the tail: for `n >= N0` past every negative parameter,
//!   `|t_{n+1}/t_n| <= rho = |z|^+ min over the two pairings of
//!   max(1, (a+N0)/(c+N0)) max(1, (b+N0)/(1+N0))` (each factor is monotone in `n`,
//!   so `rho` stays valid for every later stopping index `N`), and
//!   `sum_{n>=N} |t_n| <= |t_N| / (1 - rho)`. `rho` is rounded upward at `wp + 16`
//!   bits (not with the 53-bit radius arithmetic: `|z|` may be within `2^-40` of
//!   1, where the direct series can still be the cheap choice when `c - a - b` is
//!   large), and summation stops once `|t_N| / (1 - rho)` is below `2^-wp |s|`
//!   (the bound of `pfq`, with the better pairing). When `z` is a ball
//!   `[z~ +/- r]` (after Pfaff) the sum is taken at `z~` and
//!   `|t_n(z) - t_n(z~)| <= ((1 + r/|z~|)^n - 1) |t_n(z~)|` is added, with
//!   `(1+d)^N - 1 <= expm1(N d)`.
//! * **Logarithmic series**: summed in ball arithmetic. Tail: the coefficient
//!   ratio is bounded as above (pairs `(a+m, m+1)`, `(b+m, 1)` or swapped), and for
//!   `n >= N` the bracket is at most `|ln u| + |A-1| psi'(x1) + |B-m-1| psi'(x2)`
//!   by the mean value theorem, with `psi'(x) <= 1/x + 1/x^2` and `x1, x2` the
//!   smallest arguments at `n = N`.
//! * **Gamma, digamma, powers**: MPFR's correctly rounded `gamma`/`digamma` at
//!   exact points (one ulp), `exp`/`ln` with directed rounding ([`Ball`]).
//!   Small integers and half-integers use `(n-1)!` and `sqrt(pi) (1/2)_n`
//!   (MPFR's `gamma` is slowest there), other small arguments are shifted into
//!   `[1, 2)` by `Gamma(x) = Gamma(x+K)/(x)_K`; all in ball arithmetic.
//! * The Ziv loop ([`ziv`]) raises the working precision until
//!   `rad <= 2^-prec |mid|`; its first guard is the estimated cancellation.
//!
//! # Branch cut
//!
//! The principal branch of `2F1` has its cut on `[1, inf)` [DLMF 15.2(i)]; on
//! the cut the value depends on the side of approach and is complex. Only real
//! `z <= 1` is supported; `z > 1` is [`Error::Domain`].
//!
//! # Performance
//!
//! The paper's model case `2F1(1, k+1/2; k+2; y)`, `k <= 1000`, 128 bits
//! (release build, best of 5): 6-30 us for `y <= 1/2`, 20-100 us on
//! `(1/2, 1)` (direct series up to about `y = 0.9` at `k = 1000`, the 1-z
//! formula above; about 40 us at `y = 1 - 10^-12`), about 1 us at `y = 1`.
//! `model_case_timing` (ignored test) prints the table.
//!
//! # Accuracy
//!
//! * MP: certified, `rad <= 2^-prec |mid|`.
//! * f64: for `|z| <= 1/2` the f64 series (`pfq_f64`) when its error estimate is
//!   below [`F64_TRUST`] relative; otherwise the certified 64-bit value rounded
//!   (within one ulp). Tolerance `1e-14` relative (absolute near zeros).
//!
//! Domain: finite real `a, b, c`, real `z <= 1`; `|c - a - b| <= 10^5` when it is
//! an integer and `z > 1/2` or `z < -1`. Tested: `|a|, |b| <= 10`,
//! `0.25 <= c <= 15`, `-10^6 <= z <= 1`, and the model case up to `k = 1000`.
//! Larger parameters work but cost grows with them (`2F1(-10^6+1/2, 2; 3; 1/2)`
//! takes 0.2 s); a series that would need more than 5 * 10^6 terms is
//! [`Error::NoConvergence`]. When `c - a - b` is within `eps` of an integer
//! without being one, the 1-z formula cancels about `log2(1/eps)` bits, which
//! the Ziv loop supplies.

use std::cmp::Ordering;
use std::f64::consts::{LN_2, PI};

use rug::float::Round;
use rug::ops::{AddAssignRound, AssignRound, DivAssignRound, MulAssignRound, SubAssignRound};
use rug::{Float, Rational};

use crate::ball::{Ball, Bounded, MAG_PREC};
use crate::error::{check_prec, finite, Error, Result};
use crate::special::pfq::{pfq_f64, pfq_series, F64_TRUST, MAX_SERIES_TERMS};
use crate::special::{
    check_finite, exact, exact_add, exact_sub, f64_from_mp, is_nonpositive_integer, ziv, DEFAULT_GUARD_BITS,
    F64_FALLBACK_PREC,
};

/// Up to `|z| = 1/2` (and down to `z = -1`) only series in `z` or `w = z/(z-1)`
/// are used (direct, Euler, Pfaff); beyond, the 1-z formulas are candidates.
pub const DIRECT_RADIUS: f64 = 0.5;

/// Polynomials up to this degree are summed exactly in rationals.
pub const EXACT_POLY_MAX_DEGREE: u64 = 300;

/// Largest `|c - a - b|` for the logarithmic formula (its finite sum has that many terms).
pub const MAX_LOG_M: u64 = 100_000;

/// Gamma ratios whose arguments differ by an integer up to this are Pochhammer products.
const POCHHAMMER_PAIR_MAX: u64 = 64;

/// Minimum precision of the series engine (its error bound assumes `8 N 2^-p` tiny).
const MIN_SERIES_PREC: u32 = 64;

/// Cap on the f64 cost simulations (iterations).
const SIM_CAP: u64 = 200_000;

/// Price of the Gamma/digamma values of a connection formula, in series terms.
const GAMMA_COST_TERMS: f64 = 150.0;

/// Relative price of one logarithmic-series term (ball arithmetic, digammas).
const LOG_TERM_COST: f64 = 6.0;

/// The algorithms (see the module docs for the formulas).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Algorithm {
    /// `a` or `b` a non-positive integer: finite sum, any `z <= 1`.
    Polynomial,
    /// Power series in `z` (`|z| <= 1/2` unless a transformed series is cheaper;
    /// `1/2 < z < 1` when cheaper than the 1-z formula).
    Direct,
    /// Pfaff, then the power series in `w = z/(z-1)`: `(1-z)^{-a} 2F1(a, c-b; c; w)`
    /// (`-1 <= z < -1/2`; `-1/2 <= z < 0` when cheaper; `z < -1` when cheaper or when
    /// the transformed series terminates).
    Pfaff,
    /// Pfaff on `b`: `(1-z)^{-b} 2F1(c-a, b; c; w)`, same regions as [`Algorithm::Pfaff`].
    PfaffSwapped,
    /// Euler: `(1-z)^{c-a-b} 2F1(c-a, c-b; c; z)` [DLMF 15.8.1]: a polynomial times a
    /// power when `c - a` or `c - b` is a non-positive integer (any `z < 1`), else the
    /// series for `|z| <= 1/2` when cheaper than the direct one.
    Euler,
    /// 1-z connection formula, `c - a - b` not an integer, `1/2 < z < 1`.
    Connection,
    /// Logarithmic 1-z formula, `c - a - b` an integer, `1/2 < z < 1`.
    ConnectionLog,
    /// Pfaff then the 1-w formula, `b - a` not an integer, `z < -1`.
    PfaffConnection,
    /// Pfaff then the logarithmic 1-w formula, `b - a` an integer, `z < -1`.
    PfaffConnectionLog,
    /// Gauss's sum at `z = 1`, `c - a - b > 0`.
    Gauss,
}

// ----- small exact helpers ------------------------------------------------

/// An exact ball for an exact float (precision at least `wp`).
fn xball(x: &Float, wp: u32) -> Ball {
    Ball::from_float(x, wp.max(x.prec()))
}

/// `d` when `x = -d` is a non-positive integer.
fn nonpos_degree(x: &Float) -> Option<u64> {
    if is_nonpositive_integer(x) {
        Some((-x.to_f64()) as u64)
    } else {
        None
    }
}

/// Degree of the polynomial when `a` or `b` is a non-positive integer.
fn terminating_degree(a: &Float, b: &Float) -> Option<u64> {
    match (nonpos_degree(a), nonpos_degree(b)) {
        (Some(x), Some(y)) => Some(x.min(y)),
        (x, y) => x.or(y),
    }
}

fn one() -> Float {
    Float::with_val(2, 1)
}

fn int_float(n: u64) -> Float {
    Float::with_val(64, n)
}

fn pole_error(c: &Float) -> Error {
    Error::Domain {
        what: format!(
            "2F1: c = {} is a non-positive integer, a pole of the series; it is defined only when a or b \
             is a non-positive integer of no larger magnitude (terminating series)",
            c.to_f64()
        ),
    }
}

// ----- upward-rounded magnitudes -------------------------------------------

fn mag_zero() -> Float {
    Float::new(MAG_PREC)
}

fn mag_inf() -> Float {
    Float::with_val(MAG_PREC, rug::float::Special::Infinity)
}

fn mag_abs(x: &Float) -> Float {
    Float::with_val_round(MAG_PREC, x.abs_ref(), Round::Up).0
}

fn mag_abs_down(x: &Float) -> Float {
    Float::with_val_round(MAG_PREC, x.abs_ref(), Round::Down).0
}

fn mag_add(a: &Float, b: &Float) -> Float {
    Float::with_val_round(MAG_PREC, a + b, Round::Up).0
}

fn mag_mul(a: &Float, b: &Float) -> Float {
    Float::with_val_round(MAG_PREC, a * b, Round::Up).0
}

fn mag_div(a: &Float, b: &Float) -> Float {
    if b.is_zero() || b.is_sign_negative() {
        return mag_inf();
    }
    Float::with_val_round(MAG_PREC, a / b, Round::Up).0
}

fn mag_u64(n: u64) -> Float {
    Float::with_val_round(MAG_PREC, n, Round::Up).0
}

fn mag_pow2(e: i64) -> Float {
    let mut r = Float::with_val(MAG_PREC, 1);
    r <<= e.clamp(i32::MIN as i64 / 2, i32::MAX as i64 / 2) as i32;
    r
}

fn mag_min(a: Float, b: Float) -> Float {
    if a <= b {
        a
    } else {
        b
    }
}

/// Upper bound of `1 / (1 - rho)` for `rho < 1`.
fn mag_geometric(rho: &Float) -> Float {
    let den = Float::with_val_round(MAG_PREC, 1 - rho, Round::Down).0;
    mag_div(&Float::with_val(MAG_PREC, 1), &den)
}

// ----- series engine ---------------------------------------------------------

/// Smallest `N` with `p + N > 0` for every parameter `p`.
fn first_positive_index(params: &[&Float]) -> Result<u64> {
    let mut n = 0u64;
    for p in params {
        if **p <= 0 {
            let v = -p.to_f64();
            if v.is_nan() || v >= 1e15 {
                return Err(Error::Domain { what: "2F1: parameter too large in magnitude (|p| >= 1e15)".into() });
            }
            n = n.max(v.floor() as u64 + 1);
        }
    }
    Ok(n)
}

/// Upper bound of `max(1, (p+n)/(q+n))` at `prec` bits (infinite when `q + n <= 0`).
fn pair_factor(p: &Float, q: &Float, n: u64, prec: u32) -> Float {
    let num = Float::with_val_round(prec, p + n, Round::Up).0;
    let den = Float::with_val_round(prec, q + n, Round::Down).0;
    if den <= 0 || num < 0 {
        return mag_inf();
    }
    let f = Float::with_val_round(prec, &num / &den, Round::Up).0;
    if f < 1 {
        Float::with_val(prec, 1)
    } else {
        f
    }
}

/// Upper bound of `|x|` over a ball at `prec` bits (full accuracy, unlike the
/// 32-bit radius arithmetic: `|x|` may be within `2^-40` of 1).
fn abs_upper_precise(x: &Ball, prec: u32) -> Float {
    let hi = Float::with_val_round(prec, x.upper().abs_ref(), Round::Up).0;
    let lo = Float::with_val_round(prec, x.lower().abs_ref(), Round::Up).0;
    if hi >= lo {
        hi
    } else {
        lo
    }
}

/// `rho_N`: bound on `|t_{n+1}/t_n|` for all `n >= N` of a series with term
/// ratio `(p1+n)(p2+n) x / ((q1+n)(q2+n))`, the better of the two pairings, at
/// `prec` bits (rounded upward). Each factor is non-increasing in `N`, so
/// `rho_N` also bounds the ratios beyond any later `N`.
fn ratio_bound(p1: &Float, p2: &Float, q1: &Float, q2: &Float, x_abs_up: &Float, n: u64, prec: u32) -> Float {
    let mul = |a: &Float, b: &Float| Float::with_val_round(prec, a * b, Round::Up).0;
    let f1 = mul(&pair_factor(p1, q1, n, prec), &pair_factor(p2, q2, n, prec));
    let f2 = mul(&pair_factor(p2, q1, n, prec), &pair_factor(p1, q2, n, prec));
    mul(x_abs_up, &mag_min(f1, f2))
}

/// `1 / (1 - rho_N)` (upward) once `rho_N < 1`, tried at most every 8 terms.
struct TailFactor {
    factor: Option<Float>,
    next_try: u64,
}

impl TailFactor {
    fn new() -> TailFactor {
        TailFactor { factor: None, next_try: 0 }
    }

    fn get(&mut self, n: u64, rho: impl FnOnce() -> Float) -> Option<&Float> {
        if self.factor.is_none() && n >= self.next_try {
            let r = rho();
            if r < 1 {
                self.factor = Some(mag_geometric(&r));
            } else {
                self.next_try = n + 8;
            }
        }
        self.factor.as_ref()
    }
}

/// `|t| * f` (by exponents, `f >= 1`) is at most `2^-(wp+1) max(|s|, 2^-wp sum|t|)`.
fn negligible_scaled(t: &Float, f: &Float, s: &Float, abs_sum: &Float, wp: u32) -> bool {
    match (t.get_exp(), f.get_exp()) {
        (None, _) => true,
        (Some(et), Some(ef)) => {
            let e = (et as i64 + ef as i64).clamp(i32::MIN as i64 / 2, i32::MAX as i64 / 2) as i32;
            let shifted = Float::with_val(2, 1) << e;
            negligible(&shifted, s, abs_sum, wp)
        }
        (Some(_), None) => false,
    }
}

/// Whether `|t| <= 2^-(wp+1) max(|s|, 2^-wp sum|t|)` (by exponents).
fn negligible(t: &Float, s: &Float, abs_sum: &Float, wp: u32) -> bool {
    let Some(et) = t.get_exp() else { return true };
    let (et, wp) = (et as i64, wp as i64);
    match s.get_exp() {
        Some(es) => et + wp + 2 <= es as i64,
        None => match abs_sum.get_exp() {
            Some(ea) => et + 2 * wp + 2 <= ea as i64,
            None => false,
        },
    }
}

/// `(2^k a, 2^k b, 2^k c, k)` when these are integers below `2^31` in magnitude
/// for some `k <= 16`.
fn scaled_integers(a: &Float, b: &Float, c: &Float) -> Option<(i64, i64, i64, u32)> {
    let conv = |x: &Float, k: u32| -> Option<i64> {
        let y = Float::with_val(x.prec(), x << k);
        if !y.is_integer() || y.clone().abs() >= (1u64 << 31) {
            return None;
        }
        Some(y.to_f64() as i64)
    };
    (0..=16u32).find_map(|k| Some((conv(a, k)?, conv(b, k)?, conv(c, k)?, k)))
}

/// The series `2F1(a, b; c; z)` (exact parameters, `z` a ball with `|z| < 1`,
/// or any `z` when the series terminates) summed in place at `wp` bits, with the
/// a-priori rounding bound, the perturbation bound for the radius of `z` and the
/// rigorous tail bound of the module docs.
pub fn series_2f1(a: &Float, b: &Float, c: &Float, z: &Ball, wp: u32) -> Result<Ball> {
    let wp = wp.max(MIN_SERIES_PREC);
    let deg = terminating_degree(a, b);
    if let Some(m) = nonpos_degree(c) {
        if deg.map_or(true, |d| d > m) {
            return Err(pole_error(c));
        }
    }
    if deg.is_none() && !(z.upper() < 1 && z.lower() > -1) {
        return Err(Error::Domain { what: "2F1 series needs |z| < 1 (transform the argument first)".into() });
    }
    if let Some(d) = deg {
        if d > MAX_SERIES_TERMS {
            return Err(Error::NoConvergence { function: "hyp2f1", terms: d });
        }
    }
    let zm = z.mid();
    if zm.is_zero() {
        if z.is_exact() {
            return Ok(Ball::one(wp));
        }
        // A ball around zero: the ball-arithmetic core needs no division by |z~|.
        let sum = pfq_series(&[xball(a, wp), xball(b, wp)], &[xball(c, wp)], z, wp)?;
        return Ok(sum.sum);
    }
    let n_pos = if deg.is_some() { 0 } else { first_positive_index(&[a, b, c])? };
    let delta = if z.is_exact() { None } else { Some(mag_div(&z.rad(), &mag_abs_down(zm))) };
    let rho_prec = wp + 16;
    let z_abs_up = abs_upper_precise(z, rho_prec);
    let mut tail_factor = TailFactor::new();

    let scaled = scaled_integers(a, b, c);
    let mut t = Float::with_val(wp, 1);
    let mut s = Float::with_val(wp, 1);
    let mut an = Float::new(wp);
    let mut bn = Float::new(wp);
    let mut cn = Float::new(wp);
    let mut abs_sum = Float::with_val(MAG_PREC, 1);
    let mut max_exp_s: i64 = 1; // |s~_k| < 2^max_exp_s for all k
    let mut all_exact = true;
    let mut tail = mag_zero();
    let mut n: u64 = 0;
    loop {
        if deg == Some(n) {
            break;
        }
        // Small dyadic parameters: the ratio (a+n)(b+n) / ((c+n)(n+1)) as a quotient
        // of two machine integers (3 roundings per step instead of 8).
        let int_step = scaled.and_then(|(ai, bi, ci, k)| {
            let nk = (n as i128) << k;
            let num = (ai as i128 + nk) * (bi as i128 + nk);
            let den = ((ci as i128 + nk) * (n as i128 + 1)) << k;
            Some((i64::try_from(num).ok()?, i64::try_from(den).ok()?))
        });
        let inexact = match int_step {
            Some((_, 0)) => return Err(pole_error(c)),
            Some((num, den)) => {
                let mut inexact = t.mul_assign_round(num, Round::Nearest) != Ordering::Equal;
                inexact |= t.mul_assign_round(zm, Round::Nearest) != Ordering::Equal;
                inexact |= t.div_assign_round(den, Round::Nearest) != Ordering::Equal;
                inexact
            }
            None => {
                let mut inexact = an.assign_round(a + n, Round::Nearest) != Ordering::Equal;
                inexact |= bn.assign_round(b + n, Round::Nearest) != Ordering::Equal;
                inexact |= cn.assign_round(c + n, Round::Nearest) != Ordering::Equal;
                if cn.is_zero() {
                    return Err(pole_error(c));
                }
                inexact |= t.mul_assign_round(&an, Round::Nearest) != Ordering::Equal;
                inexact |= t.mul_assign_round(&bn, Round::Nearest) != Ordering::Equal;
                inexact |= t.mul_assign_round(zm, Round::Nearest) != Ordering::Equal;
                inexact |= t.div_assign_round(&cn, Round::Nearest) != Ordering::Equal;
                inexact |= t.div_assign_round(n + 1, Round::Nearest) != Ordering::Equal;
                inexact
            }
        };
        all_exact &= !inexact;
        n += 1;
        if !t.is_finite() {
            return Err(Error::Overflow { what: "hyp2f1 series term".into() });
        }
        if deg.is_none() && n >= n_pos && negligible(&t, &s, &abs_sum, wp) {
            let factor = tail_factor.get(n, || ratio_bound(a, b, c, &one(), &z_abs_up, n, rho_prec));
            if let Some(factor) = factor {
                if negligible_scaled(&t, factor, &s, &abs_sum, wp) {
                    // sum_{k>=N} |t_k(z)| <= |t_N(z)| / (1 - rho), with
                    // |t_N(z)| <= |t~_N| (1 + 10 N u) (1 + delta)^N.
                    let mut tn = mag_mul(
                        &mag_abs(&t),
                        &mag_add(&Float::with_val(MAG_PREC, 1), &mag_mul(&mag_u64(10 * n), &mag_pow2(-(wp as i64)))),
                    );
                    if let Some(d) = &delta {
                        let e = expm1_up(&mag_mul(d, &mag_u64(n)));
                        tn = mag_mul(&tn, &mag_add(&Float::with_val(MAG_PREC, 1), &e));
                    }
                    tail = mag_mul(&tn, factor);
                    break;
                }
            }
        }
        all_exact &= s.add_assign_round(&t, Round::Nearest) == Ordering::Equal;
        if t.is_sign_negative() {
            abs_sum.sub_assign_round(&t, Round::Up);
        } else {
            abs_sum.add_assign_round(&t, Round::Up);
        }
        if let Some(e) = s.get_exp() {
            max_exp_s = max_exp_s.max(e as i64);
        }
        if n > MAX_SERIES_TERMS {
            return Err(Error::NoConvergence { function: "hyp2f1", terms: n });
        }
    }
    let u = mag_pow2(-(wp as i64));
    let mut rad = tail;
    if !all_exact {
        let nn = mag_u64(n.max(1));
        let term_err = mag_mul(&mag_mul(&abs_sum, &mag_mul(&nn, &mag_u64(10))), &u);
        let sum_err = mag_mul(&mag_mul(&mag_pow2(max_exp_s + 1), &nn), &u);
        rad = mag_add(&rad, &mag_add(&term_err, &sum_err));
    }
    if let Some(d) = &delta {
        // sum_{n<N} |t_n(z) - t_n(z~)| <= expm1(N delta) (1 + 10 N u) sum |t~_n|
        let e = expm1_up(&mag_mul(d, &mag_u64(n.max(1))));
        let grow = mag_add(&Float::with_val(MAG_PREC, 1), &mag_mul(&mag_u64(10 * n.max(1)), &u));
        rad = mag_add(&rad, &mag_mul(&mag_mul(&e, &grow), &abs_sum));
    }
    Ok(Ball::with_radius(s, &rad))
}

/// Upper bound of `expm1(x)` for `x >= 0`.
fn expm1_up(x: &Float) -> Float {
    let mut e = x.clone();
    e.exp_m1_round(Round::Up);
    e
}

/// `2F1(p, q; r; x)`, using `2F1(p, q; p; x) = (1-x)^{-q}` [DLMF 15.4.6] when a
/// numerator equals the denominator; `one_minus_x` must enclose `1 - x`.
fn series_or_power(p: &Float, q: &Float, r: &Float, x: &Ball, one_minus_x: &Ball, wp: u32) -> Result<Ball> {
    if p == r {
        return pow_exact_exponent(one_minus_x, &Float::with_val(q.prec(), -q), wp);
    }
    if q == r {
        return pow_exact_exponent(one_minus_x, &Float::with_val(p.prec(), -p), wp);
    }
    series_2f1(p, q, r, x, wp)
}

/// `base^e` for `base > 0` and an exact exponent (binary powering for integers).
fn pow_exact_exponent(base: &Ball, e: &Float, wp: u32) -> Result<Ball> {
    if e.is_zero() {
        return Ok(Ball::one(wp));
    }
    if e.is_integer() && e.clone().abs() <= (1u64 << 20) {
        let n = e.to_f64().abs() as u64;
        let p = base.pow_u64(n);
        return if e.is_sign_negative() { p.recip() } else { Ok(p) };
    }
    base.pow(&xball(e, wp))
}

// ----- exact polynomials ------------------------------------------------------

fn to_rational(x: &Float) -> Result<Rational> {
    x.to_rational().ok_or(Error::NonFinite { what: "hyp2f1 argument" })
}

/// The terminating sum `sum_{n<=deg} (a)_n (b)_n / ((c)_n n!) z^n`, exactly.
fn poly_rational(a: &Float, b: &Float, c: &Float, z: &Rational, deg: u64) -> Result<Rational> {
    let (aq, bq, cq) = (to_rational(a)?, to_rational(b)?, to_rational(c)?);
    let mut t = Rational::from(1);
    let mut s = Rational::from(1);
    for n in 0..deg {
        let nq = Rational::from(n);
        let den = Rational::from(&cq + &nq) * Rational::from(n + 1);
        if den == 0 {
            return Err(pole_error(c));
        }
        t *= Rational::from(&aq + &nq);
        t *= Rational::from(&bq + &nq);
        t *= z;
        t /= den;
        s += &t;
    }
    Ok(s)
}

/// The ball around `q` rounded to `wp` bits (exact when representable).
fn ball_from_rational(q: &Rational, wp: u32) -> Ball {
    let (mid, ord) = Float::with_val_round(wp, q, Round::Nearest);
    let rad = match (ord, mid.get_exp()) {
        (Ordering::Equal, _) => mag_zero(),
        (_, Some(e)) => mag_pow2(e as i64 - wp as i64),
        (_, None) => mag_inf(),
    };
    Ball::with_radius(mid, &rad)
}

/// The terminating `2F1(a, b; c; z)` at an exact rational `z` (exact sum when the
/// degree is at most [`EXACT_POLY_MAX_DEGREE`], else the series engine at the ball `zb`).
fn polynomial_at(a: &Float, b: &Float, c: &Float, zq: &Rational, zb: &Ball, wp: u32) -> Result<Ball> {
    let Some(deg) = terminating_degree(a, b) else {
        return Err(Error::Internal { what: "hyp2f1 polynomial: no non-positive integer numerator".into() });
    };
    if let Some(m) = nonpos_degree(c) {
        if deg > m {
            return Err(pole_error(c));
        }
    }
    if deg <= EXACT_POLY_MAX_DEGREE {
        return Ok(ball_from_rational(&poly_rational(a, b, c, zq, deg)?, wp));
    }
    series_2f1(a, b, c, zb, wp)
}

// ----- Gamma ratios -------------------------------------------------------------

/// `(x)_k = x (x+1) ... (x+k-1)` in balls.
fn pochhammer(x: &Float, k: u64, wp: u32) -> Ball {
    let xb = xball(x, wp);
    let mut r = Ball::one(wp);
    for i in 0..k {
        r = r.mul(&xb.add_i64(i as i64));
    }
    r
}

/// `prod Gamma(num_i) / prod Gamma(den_j)` at exact points. `num` must avoid the
/// poles; a pole in `den` makes the product an exact zero. Arguments that differ
/// by an integer of at most 64 are paired into Pochhammer
/// products.
pub fn gamma_ratio(num: &[&Float], den: &[&Float], wp: u32) -> Result<Ball> {
    if den.iter().any(|y| is_nonpositive_integer(y)) {
        return Ok(Ball::zero(wp));
    }
    let mut used = vec![false; den.len()];
    let mut r = Ball::one(wp);
    for x in num {
        if is_nonpositive_integer(x) {
            return Err(Error::Domain { what: format!("2F1: Gamma at the pole {}", x.to_f64()) });
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
                    r = r.div(&pochhammer(x, k, wp))?;
                } else {
                    // Gamma(y + k) / Gamma(y) = (y)_k
                    r = r.mul(&pochhammer(den[j], k, wp));
                }
            }
            None => r = r.mul(&gamma_ball(x, wp)?),
        }
    }
    for (j, y) in den.iter().enumerate() {
        if !used[j] {
            r = r.div(&gamma_ball(y, wp)?)?;
        }
    }
    Ok(r)
}

/// `Gamma(x)` at an exact non-pole `x`: `(n-1)!` and `sqrt(pi) (1/2)_n` (or
/// `sqrt(pi) / (1/2 - n)_n`) at small integers and half-integers, a shift
/// `Gamma(x) = Gamma(x+K) / (x)_K` into `[1, 2)` for other small `x < 1` (MPFR is
/// slowest there), otherwise MPFR's correctly rounded value.
fn gamma_ball(x: &Float, wp: u32) -> Result<Ball> {
    const SMALL: f64 = 64.0;
    if is_nonpositive_integer(x) {
        return Err(Error::Domain { what: format!("2F1: Gamma at the pole {}", x.to_f64()) });
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
        let shifted = exact_add(x, &int_float(k));
        return xball(&shifted, wp).gamma()?.div(&pochhammer(x, k, wp));
    }
    xball(x, wp).gamma()
}

// ----- the algorithms ------------------------------------------------------------

/// [`Algorithm::Polynomial`]: `a` or `b` a non-positive integer, any `z`.
pub fn hyp2f1_polynomial(a: &Float, b: &Float, c: &Float, z: &Float, wp: u32) -> Result<Ball> {
    polynomial_at(a, b, c, &to_rational(z)?, &xball(z, wp), wp)
}

/// [`Algorithm::Direct`]: the power series, `|z| < 1`.
pub fn hyp2f1_direct(a: &Float, b: &Float, c: &Float, z: &Float, wp: u32) -> Result<Ball> {
    series_2f1(a, b, c, &xball(z, wp), wp)
}

/// [`Algorithm::Pfaff`]: `(1-z)^{-a} 2F1(a, c-b; c; z/(z-1))` (or the same with
/// `a`, `b` swapped when that makes the transformed series terminate); needs
/// `z < 1/2` unless the transformed series terminates (then any `z < 1`).
pub fn hyp2f1_pfaff(a: &Float, b: &Float, c: &Float, z: &Float, wp: u32) -> Result<Ball> {
    if *z >= 1 {
        return Err(Error::Domain { what: "Pfaff transformation needs z < 1".into() });
    }
    let ca = exact_sub(c, a);
    let cb = exact_sub(c, b);
    // (1-z)^{-p} 2F1(p, q; c; w)
    let (p, q) = if is_nonpositive_integer(&ca) && !is_nonpositive_integer(&cb) { (b, ca) } else { (a, cb) };
    let omz = exact_sub(&one(), z);
    let omz_b = xball(&omz, wp);
    let pre = pow_exact_exponent(&omz_b, &Float::with_val(p.prec(), -p), wp)?;
    let u = omz_b.recip()?;
    let w = xball(z, wp).mul(&u).neg();
    let inner = if terminating_degree(p, &q).is_some() {
        let zq = to_rational(z)?;
        let wq = &zq / Rational::from(&zq - 1u32);
        polynomial_at(p, &q, c, &wq, &w, wp)?
    } else {
        series_2f1(p, &q, c, &w, wp)?
    };
    Ok(pre.mul(&inner))
}

/// [`Algorithm::Euler`]: `(1-z)^{c-a-b} 2F1(c-a, c-b; c; z)` [DLMF 15.8.1]; any
/// `z < 1` when `c - a` or `c - b` is a non-positive integer (polynomial), else `|z| < 1`.
pub fn hyp2f1_euler(a: &Float, b: &Float, c: &Float, z: &Float, wp: u32) -> Result<Ball> {
    if *z >= 1 {
        return Err(Error::Domain { what: "Euler transformation needs z < 1".into() });
    }
    let ca = exact_sub(c, a);
    let cb = exact_sub(c, b);
    let s = exact_sub(&ca, b);
    let u = xball(&exact_sub(&one(), z), wp);
    let inner = if terminating_degree(&ca, &cb).is_some() {
        hyp2f1_polynomial(&ca, &cb, c, z, wp)?
    } else {
        series_2f1(&ca, &cb, c, &xball(z, wp), wp)?
    };
    Ok(pow_exact_exponent(&u, &s, wp)?.mul(&inner))
}

/// [`Algorithm::Connection`]: the 1-z formula for exact `0 < z < 1`, `c - a - b`
/// not an integer.
pub fn hyp2f1_connection(a: &Float, b: &Float, c: &Float, z: &Float, wp: u32) -> Result<Ball> {
    if !(*z > 0 && *z < 1) {
        return Err(Error::Domain { what: "1-z formula needs 0 < z < 1".into() });
    }
    let u = xball(&exact_sub(&one(), z), wp);
    connection_core(a, b, c, &xball(z, wp), &u, wp)
}

/// The 1-x formula at balls `x` and `u = 1 - x` (`0 < u < 1`), `c - a - b` not an integer.
fn connection_core(a: &Float, b: &Float, c: &Float, x: &Ball, u: &Ball, wp: u32) -> Result<Ball> {
    let ca = exact_sub(c, a);
    let cb = exact_sub(c, b);
    let s = exact_sub(&ca, b);
    if s.is_integer() {
        return Err(Error::Domain { what: "1-z formula: c - a - b is an integer (use the logarithmic formula)".into() });
    }
    let neg_s = Float::with_val(s.prec(), -&s);
    let one_minus_s = exact_sub(&one(), &s);
    let one_plus_s = exact_add(&one(), &s);
    let g1 = gamma_ratio(&[c, &s], &[&ca, &cb], wp)?;
    let t1 = if g1.is_exact() && g1.mid().is_zero() {
        g1
    } else {
        g1.mul(&series_or_power(a, b, &one_minus_s, u, x, wp)?)
    };
    let g2 = gamma_ratio(&[c, &neg_s], &[a, b], wp)?;
    let t2 = if g2.is_exact() && g2.mid().is_zero() {
        g2
    } else {
        let us = pow_exact_exponent(u, &s, wp)?;
        g2.mul(&us).mul(&series_or_power(&ca, &cb, &one_plus_s, u, x, wp)?)
    };
    Ok(t1.add(&t2))
}

/// [`Algorithm::ConnectionLog`]: the logarithmic 1-z formula for exact
/// `0 < z < 1`, `c - a - b` an integer (none of `a, b, c-a, c-b` a non-positive integer).
pub fn hyp2f1_connection_log(a: &Float, b: &Float, c: &Float, z: &Float, wp: u32) -> Result<Ball> {
    if !(*z > 0 && *z < 1) {
        return Err(Error::Domain { what: "1-z formula needs 0 < z < 1".into() });
    }
    let u = xball(&exact_sub(&one(), z), wp);
    log_core(a, b, c, &u, wp)
}

/// The logarithmic 1-x formula at the ball `u = 1 - x`, `0 < u < 1`.
fn log_core(a: &Float, b: &Float, c: &Float, u: &Ball, wp: u32) -> Result<Ball> {
    let ca = exact_sub(c, a);
    let cb = exact_sub(c, b);
    let s = exact_sub(&ca, b);
    if !s.is_integer() {
        return Err(Error::Domain { what: "logarithmic 1-z formula needs c - a - b an integer".into() });
    }
    if [a, b, &ca, &cb].iter().any(|x| is_nonpositive_integer(x)) {
        return Err(Error::Domain {
            what: "logarithmic 1-z formula: a, b, c-a, c-b must not be non-positive integers \
                   (the function is a polynomial times a power; use the polynomial algorithms)"
                .into(),
        });
    }
    let mf = s.to_f64();
    if mf.abs() > MAX_LOG_M as f64 {
        return Err(Error::Domain { what: format!("2F1: |c - a - b| = {} exceeds {MAX_LOG_M}", mf.abs()) });
    }
    let m = mf.abs() as u64;
    if mf >= 0.0 {
        log_formula(a, b, c, &ca, &cb, m, u, wp)
    } else {
        // Euler: 2F1(a,b;c;z) = u^{-m} 2F1(c-a, c-b; c; z), with c - (c-a) - (c-b) = m.
        let f = log_formula(&ca, &cb, c, a, b, m, u, wp)?;
        Ok(f.div(&u.pow_u64(m))?)
    }
}

/// `2F1(a, b; a+b+m; 1-u)` for an integer `m >= 0` [A&S 15.3.10-11]; `ca = c-a`, `cb = c-b`.
#[allow(clippy::too_many_arguments)]
fn log_formula(a: &Float, b: &Float, c: &Float, ca: &Float, cb: &Float, m: u64, u: &Ball, wp: u32) -> Result<Ball> {
    let mut result = Ball::zero(wp);
    if m >= 1 {
        let g = gamma_ratio(&[c], &[ca, cb], wp)?;
        if !(g.is_exact() && g.mid().is_zero()) {
            let gm = Ball::factorial((m - 1) as u32, wp); // Gamma(m)
            result = g.mul(&gm).mul(&finite_sum(a, b, m, u, wp)?);
        }
    }
    let g2 = gamma_ratio(&[c], &[a, b], wp)?;
    if !(g2.is_exact() && g2.mid().is_zero()) {
        let am = exact_add(a, &int_float(m));
        let bm = exact_add(b, &int_float(m));
        let mut part = g2.mul(&u.pow_u64(m)).mul(&log_series(&am, &bm, m, u, wp)?);
        // -(-u)^m = (-1)^{m+1} u^m
        if m % 2 == 0 {
            part = part.neg();
        }
        result = result.add(&part);
    }
    Ok(result)
}

/// `sum_{n<m} (a)_n (b)_n / (n! (1-m)_n) u^n`.
fn finite_sum(a: &Float, b: &Float, m: u64, u: &Ball, wp: u32) -> Result<Ball> {
    let (ab, bb) = (xball(a, wp), xball(b, wp));
    let mut t = Ball::one(wp);
    let mut s = Ball::one(wp);
    for n in 0..m.saturating_sub(1) {
        let ni = n as i64;
        let den = Ball::from_i64((ni + 1) * (ni + 1 - m as i64), wp);
        t = t.mul(&ab.add_i64(ni)).mul(&bb.add_i64(ni)).mul(u).div(&den)?;
        s = s.add(&t);
    }
    Ok(s)
}

/// Upper bound of `psi'(x) <= 1/x + 1/x^2` at a lower bound `x > 0`.
fn trigamma_up(x_lo: &Float) -> Float {
    if *x_lo <= 0 {
        return mag_inf();
    }
    let inv = mag_div(&Float::with_val(MAG_PREC, 1), x_lo);
    mag_add(&inv, &mag_mul(&inv, &inv))
}

/// For `n >= N`: bound on `|ln u - psi(n+1) - psi(n+m+1) + psi(A+n) + psi(B+n)|`.
fn log_bracket_bound(aa: &Float, bb: &Float, m: u64, n: u64, lnu_abs: &Float) -> Float {
    let lo = |p: &Float| Float::with_val_round(MAG_PREC, p + n, Round::Down).0;
    let n1 = Float::with_val_round(MAG_PREC, n + 1, Round::Down).0;
    let nm1 = Float::with_val_round(MAG_PREC, n + m + 1, Round::Down).0;
    let dist = |p: &Float, q: u64| mag_abs(&exact_sub(p, &int_float(q)));
    let term = |p: &Float, q: u64, qn: &Float| {
        let x = mag_min(lo(p), qn.clone());
        mag_mul(&dist(p, q), &trigamma_up(&x))
    };
    let opt1 = mag_add(&term(aa, 1, &n1), &term(bb, m + 1, &nm1));
    let opt2 = mag_add(&term(bb, 1, &n1), &term(aa, m + 1, &nm1));
    mag_add(lnu_abs, &mag_min(opt1, opt2))
}

/// `L = sum_n (A)_n (B)_n / (n! (n+m)!) u^n [ln u - psi(n+1) - psi(n+m+1) + psi(A+n) + psi(B+n)]`
/// in ball arithmetic with the tail bound of the module docs (`A`, `B` not
/// non-positive integers, `0 < u < 1`).
fn log_series(aa: &Float, bb: &Float, m: u64, u: &Ball, wp: u32) -> Result<Ball> {
    let wp = wp.max(MIN_SERIES_PREC);
    let lnu = u.ln()?;
    let m32 = u32::try_from(m).map_err(|_| Error::Domain { what: "2F1: c - a - b too large".into() })?;
    let mut tau = Ball::factorial(m32, wp).recip()?;
    let mut psi1 = Ball::from_i64(1, wp).digamma()?;
    let mut psim = Ball::from_i64(m as i64 + 1, wp).digamma()?;
    let (ab, bbb) = (xball(aa, wp), xball(bb, wp));
    let mut psia = ab.digamma()?;
    let mut psib = bbb.digamma()?;
    let mut sum = tau.mul(&lnu.sub(&psi1).sub(&psim).add(&psia).add(&psib));
    let mut abs_sum = sum.abs_upper();
    let n_pos = first_positive_index(&[aa, bb])?;
    let lnu_abs = lnu.abs_upper();
    let proxy = mag_add(&lnu_abs, &Float::with_val(MAG_PREC, 1));
    let rho_prec = wp + 16;
    let u_abs = abs_upper_precise(u, rho_prec);
    let q1 = int_float(m + 1);
    let mut tail_factor = TailFactor::new();
    let mut n: u64 = 0;
    loop {
        let ni = n as i64;
        let an = ab.add_i64(ni);
        let bn = bbb.add_i64(ni);
        let den = Ball::from_i64((ni + 1) * (ni + m as i64 + 1), wp);
        tau = tau.mul(&an).mul(&bn).mul(u).div(&den)?;
        psi1 = psi1.add(&Ball::from_ratio(1, ni + 1, wp));
        psim = psim.add(&Ball::from_ratio(1, ni + m as i64 + 1, wp));
        psia = psia.add(&an.recip()?);
        psib = psib.add(&bn.recip()?);
        n += 1;
        if n >= n_pos {
            let tau_up = tau.abs_upper();
            let proxy_term = mag_mul(&tau_up, &proxy);
            if negligible(&proxy_term, sum.mid(), &abs_sum, wp) {
                let factor = tail_factor.get(n, || ratio_bound(aa, bb, &q1, &one(), &u_abs, n, rho_prec));
                if let Some(factor) = factor {
                    if negligible_scaled(&proxy_term, factor, sum.mid(), &abs_sum, wp) {
                        let h = log_bracket_bound(aa, bb, m, n, &lnu_abs);
                        let tail = mag_mul(&mag_mul(&tau_up, &h), factor);
                        if tail.is_finite() {
                            sum.add_error(&tail);
                            return Ok(sum);
                        }
                    }
                }
            }
        }
        let term = tau.mul(&lnu.sub(&psi1).sub(&psim).add(&psia).add(&psib));
        abs_sum = mag_add(&abs_sum, &term.abs_upper());
        sum = sum.add(&term);
        if !sum.is_finite() {
            return Err(Error::Overflow { what: "hyp2f1 logarithmic series".into() });
        }
        if n > MAX_SERIES_TERMS {
            return Err(Error::NoConvergence { function: "hyp2f1 (logarithmic series)", terms: n });
        }
    }
}

/// [`Algorithm::PfaffConnection`] and [`Algorithm::PfaffConnectionLog`]: for
/// `z < 0`, `(1-z)^{-a} 2F1(a, c-b; c; w)`, `w = z/(z-1)`, with the inner function
/// by the 1-w formula (logarithmic when `b - a` is an integer) at `1 - w = 1/(1-z)`.
/// Falls back to [`hyp2f1_pfaff`] when the transformed function is a polynomial
/// (times a power).
pub fn hyp2f1_pfaff_connection(a: &Float, b: &Float, c: &Float, z: &Float, wp: u32) -> Result<Ball> {
    if *z >= 0 {
        return Err(Error::Domain { what: "Pfaff + 1-w formula needs z < 0".into() });
    }
    let ca = exact_sub(c, a);
    let cb = exact_sub(c, b);
    if [a, b, &ca, &cb].iter().any(|x| is_nonpositive_integer(x)) {
        return hyp2f1_pfaff(a, b, c, z, wp);
    }
    let omz_b = xball(&exact_sub(&one(), z), wp);
    let pre = pow_exact_exponent(&omz_b, &Float::with_val(a.prec(), -a), wp)?;
    let u = omz_b.recip()?;
    let w = xball(z, wp).mul(&u).neg();
    let s = exact_sub(b, a);
    let inner = if s.is_integer() { log_core(a, &cb, c, &u, wp)? } else { connection_core(a, &cb, c, &w, &u, wp)? };
    Ok(pre.mul(&inner))
}

/// [`Algorithm::Gauss`]: `2F1(a, b; c; 1) = Gamma(c) Gamma(c-a-b) / (Gamma(c-a) Gamma(c-b))`, `c - a - b > 0`.
pub fn hyp2f1_gauss(a: &Float, b: &Float, c: &Float, wp: u32) -> Result<Ball> {
    let ca = exact_sub(c, a);
    let cb = exact_sub(c, b);
    let s = exact_sub(&ca, b);
    if s <= 0 {
        return Err(Error::Domain { what: "Gauss's sum needs c - a - b > 0".into() });
    }
    gamma_ratio(&[c, &s], &[&ca, &cb], wp)
}

// ----- cost model ----------------------------------------------------------------

/// f64 estimate of `ln |Gamma(x)|` (`+inf` at the poles); only for choosing.
fn lgamma_est(x: f64) -> f64 {
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

/// Result of [`simulate`]: term count and log2 of `sum |t_n|` and of `|sum t_n|`.
#[derive(Debug, Clone, Copy)]
struct Sim {
    terms: f64,
    log2_abs: f64,
    log2_val: f64,
    /// False when the cap was reached (then the other fields describe the partial sum).
    converged: bool,
}

impl Sim {
    fn lost(&self) -> f64 {
        let l = self.log2_abs - self.log2_val;
        if l.is_nan() {
            0.0
        } else {
            l.clamp(0.0, 1e6)
        }
    }
}

fn f64_exponent(v: f64) -> i64 {
    ((v.abs().to_bits() >> 52) & 0x7ff) as i64 - 1023
}

/// f64 simulation of the series with term ratio `(p1+n)(p2+n) x / ((q1+n)(q2+n))`
/// until the terms fall `bits` below the sum; the partial sum (`converged =
/// false`) past `cap` terms; `None` at a pole or on overflow.
fn simulate(p: [f64; 2], q: [f64; 2], x: f64, bits: f64, cap: u64) -> Option<Sim> {
    let is_nonpos_int = |v: f64| v <= 0.0 && v == v.floor();
    let deg = p.iter().filter(|v| is_nonpos_int(**v)).map(|v| (-v) as u64).min();
    let mut n_pos = 0u64;
    for v in p.iter().chain(q.iter()) {
        if *v <= 0.0 && !is_nonpos_int(*v) {
            n_pos = n_pos.max((-v).floor() as u64 + 1);
        }
    }
    if n_pos > cap {
        // At least n_pos terms (the tail bound needs every parameter positive).
        return Some(Sim { terms: n_pos as f64, log2_abs: 0.0, log2_val: 0.0, converged: false });
    }
    let bits = bits.min(1e6) as i64;
    let (mut t, mut s, mut abs) = (1.0f64, 1.0f64, 1.0f64);
    let mut scale = 0.0f64; // true values are 2^scale times these
    let big = 2f64.powi(500);
    let mut n = 0u64;
    loop {
        if deg == Some(n) {
            break;
        }
        let nf = n as f64;
        let den = (q[0] + nf) * (q[1] + nf);
        if den == 0.0 {
            return None;
        }
        let r = (p[0] + nf) * (p[1] + nf) / den * x;
        t *= r;
        n += 1;
        if !t.is_finite() {
            return None;
        }
        if deg.is_none() && n >= n_pos && r.abs() < 1.0 {
            let ref_mag = if s != 0.0 { s.abs() } else { abs * 2f64.powi(-(bits.min(1000) as i32)) };
            if t == 0.0 || f64_exponent(t) + bits < f64_exponent(ref_mag) {
                // The engine's tail bound |t_N| / (1 - rho_N) (see `ratio_bound`).
                let nf = n as f64;
                let pf = |a: f64, b: f64| ((a + nf) / (b + nf)).max(1.0);
                let rho = x.abs() * (pf(p[0], q[0]) * pf(p[1], q[1])).min(pf(p[1], q[0]) * pf(p[0], q[1]));
                if rho < 1.0 && (t == 0.0 || f64_exponent(t) + bits + 1 + (-(1.0 - rho).log2()).ceil() as i64 <= f64_exponent(ref_mag)) {
                    break;
                }
            }
        }
        s += t;
        abs += t.abs();
        if abs > big {
            t /= big;
            s /= big;
            abs /= big;
            scale += 500.0;
        }
        if n > cap {
            break;
        }
    }
    let log2_val = if s == 0.0 { f64::NEG_INFINITY } else { s.abs().log2() + scale };
    Some(Sim { terms: n as f64, log2_abs: abs.log2() + scale, log2_val, converged: n <= cap })
}

/// [`simulate`], converged runs only.
fn simulate_converged(p: [f64; 2], q: [f64; 2], x: f64, bits: f64, cap: u64) -> Option<Sim> {
    simulate(p, q, x, bits, cap).filter(|s| s.converged)
}

/// Terms and log2 of the magnitude of `2F1(p1, p2; q; u)`, with the power shortcut.
fn series_estimate(p1: f64, p2: f64, q: f64, u: f64, bits: f64) -> (f64, f64) {
    if p1 == q {
        return (0.0, -p2 * (1.0 - u).log2());
    }
    if p2 == q {
        return (0.0, -p1 * (1.0 - u).log2());
    }
    match simulate_converged([p1, p2], [q, 1.0], u, bits, SIM_CAP) {
        Some(s) => (s.terms, s.log2_abs),
        None => (f64::INFINITY, 0.0),
    }
}

/// For `2F1(a, b; c; x)` with `1/2 < x < 1`, `u = 1 - x`, `s = c - a - b`
/// (exact): whether the direct series is cheaper than the 1-x formula, and the
/// estimated bits lost by the chosen one.
fn near_one_choice(a: &Float, b: &Float, c: &Float, s: &Float, x: f64, u: f64, bits: f64) -> (bool, f64) {
    let (af, bf, cf) = (a.to_f64(), b.to_f64(), c.to_f64());
    let lg2 = |v: f64| lgamma_est(v) / LN_2;
    let (n_conn, log2_big, fixed) = if s.is_integer() {
        let m = s.to_f64();
        let (pa, pb, mm, shift) = if m >= 0.0 { (af, bf, m, 0.0) } else { (cf - af, cf - bf, -m, m * u.log2()) };
        let (nl, sl) = match simulate_converged([pa + mm, pb + mm], [mm + 1.0, 1.0], u, bits, SIM_CAP) {
            Some(sim) => (sim.terms, sim.log2_abs),
            None => (f64::INFINITY, 0.0),
        };
        let t1 = if mm >= 1.0 { lg2(cf) + lg2(mm) - lg2(cf - pa) - lg2(cf - pb) } else { f64::NEG_INFINITY };
        let t2 = lg2(cf) - lg2(pa) - lg2(pb) + mm * u.log2() + (u.ln().abs() + 2.0).log2() + sl;
        (mm + LOG_TERM_COST * nl, t1.max(t2) + shift, 2.0 * GAMMA_COST_TERMS)
    } else {
        let sf = s.to_f64();
        let (n1, l1) = series_estimate(af, bf, 1.0 - sf, u, bits);
        let (n2, l2) = series_estimate(cf - af, cf - bf, 1.0 + sf, u, bits);
        let t1 = lg2(cf) + lg2(sf) - lg2(cf - af) - lg2(cf - bf) + l1;
        let t2 = lg2(cf) + lg2(-sf) - lg2(af) - lg2(bf) + sf * u.log2() + l2;
        (n1 + n2, t1.max(t2), GAMMA_COST_TERMS)
    };
    let conn_base = n_conn + fixed;
    let cap = if conn_base.is_finite() { (8.0 * conn_base + 100.0).min(SIM_CAP as f64) as u64 } else { SIM_CAP };
    match simulate([af, bf], [cf, 1.0], x, bits, cap) {
        None => (false, 0.0),
        Some(d) => {
            let lost_d = d.lost();
            if !conn_base.is_finite() && d.converged {
                return (true, lost_d);
            }
            // |f| from the (partial) direct sum: for 0 < x < 1 its terms end up of
            // one sign, so a partial sum errs on the side of more guard bits.
            let lost_c = if log2_big.is_finite() && d.log2_val.is_finite() {
                (log2_big - d.log2_val).clamp(0.0, 1e6)
            } else {
                0.0
            };
            if !d.converged {
                return (false, lost_c);
            }
            let cost_d = d.terms * (bits + lost_d);
            let cost_c = n_conn * (1.0 + lost_c / bits) * (bits + lost_c) + fixed * bits;
            if cost_d <= cost_c {
                (true, lost_d)
            } else {
                (false, lost_c)
            }
        }
    }
}

/// Price of a power prefactor (Euler, Pfaff), in series terms.
const PREFACTOR_COST_TERMS: f64 = 30.0;

/// For `-1 <= z <= 1/2` (non-terminating): the cheapest of the direct series, its
/// Euler transform (both in `z`, for `|z| <= 1/2`) and the two Pfaff transforms
/// (in `w = z/(z-1)`, `|w| < |z|`, for `z < 0`), by simulated terms times
/// (precision + cancellation). The direct series wins ties; `-1 <= z < -1/2` is
/// always Pfaff (`|w| <= 1/2`).
fn small_z_choice(af: f64, bf: f64, cf: f64, caf: f64, cbf: f64, zf: f64, bits: f64) -> (Algorithm, u32) {
    let w = zf / (zf - 1.0);
    // log2 of the prefactors (1-z)^e that turn each transformed sum into f.
    let l1z = (1.0 - zf).log2();
    let mut cands: Vec<(Algorithm, [f64; 2], f64, f64, f64)> = Vec::with_capacity(4);
    if zf >= -DIRECT_RADIUS {
        cands.push((Algorithm::Direct, [af, bf], zf, 0.0, 0.0));
        cands.push((Algorithm::Euler, [caf, cbf], zf, PREFACTOR_COST_TERMS, (cf - af - bf) * l1z));
    }
    if zf < 0.0 {
        cands.push((Algorithm::Pfaff, [af, cbf], w, PREFACTOR_COST_TERMS, -af * l1z));
        cands.push((Algorithm::PfaffSwapped, [caf, bf], w, PREFACTOR_COST_TERMS, -bf * l1z));
    }
    let sims: Vec<Option<Sim>> = cands.iter().map(|c| simulate(c.1, [cf, 1.0], c.2, bits, SIM_CAP)).collect();
    // All candidates sum the same f: take log2|f| from the run with the least
    // cancellation (an f64 sum says nothing once ~50 bits cancel), then charge every
    // candidate log2(sum |t| * prefactor / |f|).
    let mut log2_f = f64::NAN;
    let mut least = f64::INFINITY;
    for (c, sim) in cands.iter().zip(&sims) {
        if let Some(sim) = sim {
            if sim.log2_val.is_finite() && sim.lost() < least {
                least = sim.lost();
                log2_f = sim.log2_val + c.4;
            }
        }
    }
    let mut best = (cands[0].0, f64::INFINITY, 0u32);
    for (c, sim) in cands.iter().zip(&sims) {
        let Some(sim) = sim else { continue };
        let mut lost = sim.lost();
        if log2_f.is_finite() {
            lost = lost.max((sim.log2_abs + c.4 - log2_f).clamp(0.0, 1e6));
        }
        // A run cut at the cap is at least that expensive: count it double.
        let penalty = if sim.converged { 1.0 } else { 2.0 };
        let cost = (sim.terms * penalty + c.3) * (bits + lost);
        if cost < best.1 {
            best = (c.0, cost, (lost + sim.terms.max(1.0).log2()).clamp(0.0, 65536.0) as u32);
        }
    }
    (best.0, best.2)
}

/// The algorithm and an estimate of the bits it loses (first Ziv guard).
fn plan(a: &Float, b: &Float, c: &Float, z: &Float, wp: u32) -> (Algorithm, u32) {
    let bits = wp as f64;
    let guard = |lost: f64, terms: f64| -> u32 { (lost + terms.max(1.0).log2()).clamp(0.0, 65536.0) as u32 };
    let sim_guard = |p: [f64; 2], q: [f64; 2], x: f64| -> u32 {
        match simulate_converged(p, q, x, bits, SIM_CAP) {
            Some(s) => guard(s.lost(), s.terms),
            None => 0,
        }
    };
    let (af, bf, cf, zf) = (a.to_f64(), b.to_f64(), c.to_f64(), z.to_f64());
    if let Some(d) = terminating_degree(a, b) {
        let g = if d <= EXACT_POLY_MAX_DEGREE { 0 } else { sim_guard([af, bf], [cf, 1.0], zf) };
        return (Algorithm::Polynomial, g);
    }
    if *z == 1 {
        return (Algorithm::Gauss, 0);
    }
    let ca = exact_sub(c, a);
    let cb = exact_sub(c, b);
    if *z >= -1 && *z <= DIRECT_RADIUS {
        return small_z_choice(af, bf, cf, ca.to_f64(), cb.to_f64(), zf, bits);
    }
    if *z > 0 {
        if terminating_degree(&ca, &cb).is_some() {
            return (Algorithm::Euler, 0);
        }
        let s = exact_sub(&ca, b);
        let u = exact_sub(&one(), z).to_f64();
        let (direct, lost) = near_one_choice(a, b, c, &s, zf, u, bits);
        let g = guard(lost, bits);
        return match (direct, s.is_integer()) {
            (true, _) => (Algorithm::Direct, g),
            (false, true) => (Algorithm::ConnectionLog, g),
            (false, false) => (Algorithm::Connection, g),
        };
    }
    // z < -1
    if terminating_degree(&ca, &cb).is_some() {
        return (Algorithm::Pfaff, 0);
    }
    let s = exact_sub(b, a);
    let u = 1.0 / (1.0 - zf);
    let (direct, lost) = near_one_choice(a, &cb, c, &s, 1.0 - u, u, bits);
    let g = guard(lost, bits);
    match (direct, s.is_integer()) {
        (true, _) => (Algorithm::Pfaff, g),
        (false, true) => (Algorithm::PfaffConnectionLog, g),
        (false, false) => (Algorithm::PfaffConnection, g),
    }
}

/// Picks the algorithm for validated arguments (finite, `z <= 1`, see
/// [`hyp2f1_mp`]) at working precision `wp` (the module docs list the regions).
pub fn choose_algorithm(a: &Float, b: &Float, c: &Float, z: &Float, wp: u32) -> Algorithm {
    plan(a, b, c, z, wp).0
}

/// Runs one algorithm at working precision `wp`.
pub fn evaluate(alg: Algorithm, a: &Float, b: &Float, c: &Float, z: &Float, wp: u32) -> Result<Ball> {
    match alg {
        Algorithm::Polynomial => hyp2f1_polynomial(a, b, c, z, wp),
        Algorithm::Direct => hyp2f1_direct(a, b, c, z, wp),
        Algorithm::Pfaff => hyp2f1_pfaff(a, b, c, z, wp),
        Algorithm::PfaffSwapped => hyp2f1_pfaff(b, a, c, z, wp),
        Algorithm::Euler => hyp2f1_euler(a, b, c, z, wp),
        Algorithm::Connection => hyp2f1_connection(a, b, c, z, wp),
        Algorithm::ConnectionLog => hyp2f1_connection_log(a, b, c, z, wp),
        Algorithm::PfaffConnection | Algorithm::PfaffConnectionLog => hyp2f1_pfaff_connection(a, b, c, z, wp),
        Algorithm::Gauss => hyp2f1_gauss(a, b, c, wp),
    }
}

// ----- public entry points ---------------------------------------------------------

/// Checks the arguments: finite, `z <= 1`, `c` not a pole, `z = 1` convergent.
fn validate(a: &Float, b: &Float, c: &Float, z: &Float) -> Result<()> {
    check_finite(a, "a")?;
    check_finite(b, "b")?;
    check_finite(c, "c")?;
    check_finite(z, "z")?;
    if *z > 1 {
        return Err(Error::Domain {
            what: format!(
                "2F1: z = {} > 1 lies on the branch cut [1, inf) of the principal branch (complex values); \
                 only real z <= 1 is supported",
                z.to_f64()
            ),
        });
    }
    let deg = terminating_degree(a, b);
    if let Some(m) = nonpos_degree(c) {
        if deg.map_or(true, |d| d > m) {
            return Err(pole_error(c));
        }
    }
    if *z == 1 && deg.is_none() {
        let s = exact_sub(&exact_sub(c, a), b);
        if s <= 0 {
            return Err(Error::Domain {
                what: format!(
                    "2F1(a, b; c; 1) diverges when c - a - b <= 0 (here {}); Gauss's sum needs c - a - b > 0",
                    s.to_f64()
                ),
            });
        }
    }
    Ok(())
}

/// Certified `2F1(a, b; c; z)` for real `z <= 1`, with `rad <= 2^-prec |mid|`.
pub fn hyp2f1_mp(a: &Float, b: &Float, c: &Float, z: &Float, prec: u32) -> Result<Ball> {
    check_prec(prec)?;
    validate(a, b, c, z)?;
    if z.is_zero() {
        return Ok(Ball::one(prec));
    }
    let (alg, lost) = plan(a, b, c, z, prec + DEFAULT_GUARD_BITS);
    ziv("hyp2f1", prec, DEFAULT_GUARD_BITS + lost, |wp| evaluate(alg, a, b, c, z, wp))
}

/// `2F1(a, b; c; z)` in f64 with a proven error bound for the f64 inputs as given.
pub fn hyp2f1_bounded(a: f64, b: f64, c: f64, z: f64) -> Result<Bounded> {
    finite(a, "a")?;
    finite(b, "b")?;
    finite(c, "c")?;
    finite(z, "z")?;
    let ball = hyp2f1_mp(&exact(a), &exact(b), &exact(c), &exact(z), crate::special::F64_FALLBACK_PREC)?;
    crate::special::bounded_from_ball("hyp2f1", &ball)
}

/// `2F1(a, b; c; z)` in f64 for real `z <= 1`, within `1e-14` relative
/// (absolute near zeros); see the module docs.
pub fn hyp2f1(a: f64, b: f64, c: f64, z: f64) -> Result<f64> {
    finite(a, "a")?;
    finite(b, "b")?;
    finite(c, "c")?;
    finite(z, "z")?;
    let (ae, be, ce, ze) = (exact(a), exact(b), exact(c), exact(z));
    validate(&ae, &be, &ce, &ze)?;
    if z == 0.0 {
        return Ok(1.0);
    }
    if z.abs() <= DIRECT_RADIUS {
        // Pair the larger numerator with the larger denominator for the tail estimate.
        let (hi, lo) = if a >= b { (a, b) } else { (b, a) };
        let nums = if c >= 1.0 { [hi, lo] } else { [lo, hi] };
        if let Some((s, err, _)) = pfq_f64(&nums, &[c], z) {
            if s.is_finite() && err <= F64_TRUST * s.abs() {
                return Ok(s);
            }
        }
    }
    let (alg, lost) = plan(&ae, &be, &ce, &ze, F64_FALLBACK_PREC + DEFAULT_GUARD_BITS);
    f64_from_mp("hyp2f1", DEFAULT_GUARD_BITS + lost, |wp| evaluate(alg, &ae, &be, &ce, &ze, wp))
}

#[cfg(test)]
mod tests {
    use super::*;

    const P: u32 = 128;
    /// Precision of the independently computed reference balls.
    const REF: u32 = 320;

    fn f(x: f64) -> Float {
        exact(x)
    }

    fn mp(a: f64, b: f64, c: f64, z: f64) -> Ball {
        let r = hyp2f1_mp(&f(a), &f(b), &f(c), &f(z), P);
        match r {
            Ok(v) => {
                assert!(v.meets_rel(P), "2F1({a},{b};{c};{z}) not certified to {P} bits: {v:?}");
                v
            }
            Err(e) => panic!("2F1({a},{b};{c};{z}): {e}"),
        }
    }

    fn check(name: &str, got: &Ball, want: &Ball) {
        assert!(got.overlaps(want), "{name}: got {got:?}, closed form {want:?}");
    }

    fn zb(z: f64) -> Ball {
        Ball::from_f64(z, REF).unwrap()
    }

    /// `-ln(1 - z)` as a ball.
    fn ell(z: f64) -> Ball {
        xball(&exact_sub(&one(), &f(z)), REF).ln().unwrap().neg()
    }

    /// Monotone increasing MPFR function at a ball, through its endpoints.
    fn monotone(x: &Ball, g: impl Fn(&Float, Round) -> Float) -> Ball {
        Ball::hull(&g(&x.lower(), Round::Down), &g(&x.upper(), Round::Up), REF)
    }

    #[test]
    fn log_cases_match_elementary_closed_forms() {
        // c - a - b = 0, 1, 2, -1, -2 (DLMF 15.4.2 and partial fractions).
        let zs = [0.3, -0.3, 0.55, 0.6, 0.75, 0.9, 0.999, 1.0 - 2f64.powi(-40), -0.75, -1.0, -1.5, -3.0, -77.25, -1e6];
        for &z in &zs {
            let (zz, l) = (zb(z), ell(z));
            let one_b = Ball::one(REF);
            let l1 = l.div(&zz).unwrap();
            let l2 = l.sub(&zz).div(&zz.sqr()).unwrap();
            let l3 = l.sub(&zz).sub(&zz.sqr().mul_pow2(-1)).div(&zz.sqr().mul(&zz)).unwrap();
            let omz = one_b.sub(&zz);
            check(&format!("2F1(1,1;2;{z})"), &mp(1.0, 1.0, 2.0, z), &l1);
            // 2F1(1,1;3;z) = 2((1-z) ln(1-z) + z)/z^2
            let w = omz.mul(&l.neg()).add(&zz).mul_pow2(1).div(&zz.sqr()).unwrap();
            check(&format!("2F1(1,1;3;{z})"), &mp(1.0, 1.0, 3.0, z), &w);
            // 2F1(1,1;4;z) = 3 (L1 - 2 L2 + L3)
            let w = l1.sub(&l2.mul_pow2(1)).add(&l3).mul_i64(3);
            check(&format!("2F1(1,1;4;{z})"), &mp(1.0, 1.0, 4.0, z), &w);
            // 2F1(2,2;3;z) = 2/(1-z) - 2 L2
            let w = omz.recip().unwrap().sub(&l2).mul_pow2(1);
            check(&format!("2F1(2,2;3;{z})"), &mp(2.0, 2.0, 3.0, z), &w);
            // 2F1(3,3;4;z) = 3/2 (z/(1-z)^2 + 2 L3)
            let w = zz.div(&omz.sqr()).unwrap().add(&l3.mul_pow2(1)).mul_i64(3).mul_pow2(-1);
            check(&format!("2F1(3,3;4;{z})"), &mp(3.0, 3.0, 4.0, z), &w);
        }
    }

    #[test]
    fn complete_elliptic_integral_via_agm() {
        // 2F1(1/2, 1/2; 1; z) = 1 / AGM(1, sqrt(1 - z)): degenerate with m = 0.
        for &z in &[0.3, 0.7, 0.95, 1.0 - 1e-12, -0.4, -0.8, -5.0, -1e4] {
            let r = xball(&exact_sub(&one(), &f(z)), REF).sqrt().unwrap();
            let agm = monotone(&r, |x, rnd| Float::with_val_round(REF, Float::with_val(REF, 1).agm_ref(x), rnd).0);
            check(&format!("K at {z}"), &mp(0.5, 0.5, 1.0, z), &agm.recip().unwrap());
        }
    }

    #[test]
    fn arcsin_and_arsinh_closed_forms() {
        // 2F1(1/2, 1/2; 3/2; x^2) = asin(x)/x, 2F1(1/2, 1/2; 3/2; -x^2) = asinh(x)/x (c-a-b = 1/2).
        for &x in &[0.5, 0.75, 0.875, 0.96875, 1.0 - 2f64.powi(-20), 1.0] {
            let xb = zb(x);
            let w = monotone(&xb, |v, rnd| Float::with_val_round(REF, v.asin_ref(), rnd).0).div(&xb).unwrap();
            check(&format!("asin {x}"), &mp(0.5, 0.5, 1.5, x * x), &w);
        }
        for &x in &[0.5, 0.75, 1.5, 2.0, 100.0] {
            let xb = zb(x);
            let w = monotone(&xb, |v, rnd| Float::with_val_round(REF, v.asinh_ref(), rnd).0).div(&xb).unwrap();
            check(&format!("asinh {x}"), &mp(0.5, 0.5, 1.5, -x * x), &w);
        }
    }

    #[test]
    fn power_closed_form_b_equals_c() {
        // 2F1(a, b; b; z) = (1 - z)^{-a} [DLMF 15.4.6]
        for &(a, b) in &[(0.3, 2.7), (-1.75, 0.5), (4.5, 12.0)] {
            for &z in &[0.3, -0.7, 0.8, 0.999, -5.0, -1e5] {
                let w = xball(&exact_sub(&one(), &f(z)), REF).pow(&zb(-a)).unwrap();
                check(&format!("(1-z)^-a a={a} z={z}"), &mp(a, b, b, z), &w);
                check(&format!("(1-z)^-a a={a} z={z} swapped"), &mp(b, a, b, z), &w);
            }
        }
    }

    #[test]
    fn model_case_closed_forms_and_gauss() {
        // k = 0: 2F1(1, 1/2; 2; y) = 2 (1 - sqrt(1 - y)) / y.
        for &y in &[0.3, 0.7, 1.0 - 1e-12, 1.0] {
            let yy = zb(y);
            let sq = xball(&exact_sub(&one(), &f(y)), REF).sqrt().unwrap();
            let w = Ball::one(REF).sub(&sq).mul_pow2(1).div(&yy).unwrap();
            check(&format!("k=0 y={y}"), &mp(1.0, 0.5, 2.0, y), &w);
        }
        // Gauss: 2F1(1, k+1/2; k+2; 1) = Gamma(k+2) Gamma(1/2) / (Gamma(k+1) Gamma(3/2)) = 2 (k+1).
        for &k in &[0.0, 1.0, 10.0, 1000.0] {
            let g = mp(1.0, k + 0.5, k + 2.0, 1.0);
            assert!(g.contains(&Float::with_val(64, 2.0 * (k + 1.0))), "k={k}: {g:?}");
            assert_eq!(choose_algorithm(&f(1.0), &f(k + 0.5), &f(k + 2.0), &f(1.0), P), Algorithm::Gauss);
        }
        // Certified near 1 and across (0, 1].
        for &k in &[0.0, 3.0, 100.0, 1000.0] {
            for &y in &[0.1, 0.5, 0.6, 0.9, 0.99, 1.0 - 1e-6, 1.0 - 1e-12, 1.0] {
                let _ = mp(1.0, k + 0.5, k + 2.0, y);
            }
        }
    }

    /// DLMF 15.5.11: (c-a) F(a-1) + (2a - c + (b-a) z) F(a) + a (z-1) F(a+1) = 0
    /// (`a - 1`, `a + 1` formed exactly).
    fn contiguous_a(a: f64, b: f64, c: f64, z: f64) {
        let (af, bf, cf, zf) = (f(a), f(b), f(c), f(z));
        let run = |x: &Float| -> Ball {
            let v = hyp2f1_mp(x, &bf, &cf, &zf, P).unwrap_or_else(|e| panic!("2F1({x},{b};{c};{z}): {e}"));
            assert!(v.meets_rel(P), "2F1({x},{b};{c};{z}) not certified: {v:?}");
            v
        };
        let fm = run(&exact_sub(&af, &one()));
        let f0 = run(&af);
        let fp = run(&exact_add(&af, &one()));
        let (ab, bb, cb, zz) = (zb(a), zb(b), zb(c), zb(z));
        let coef0 = ab.mul_i64(2).sub(&cb).add(&bb.sub(&ab).mul(&zz));
        let sum = cb.sub(&ab).mul(&fm).add(&coef0.mul(&f0)).add(&ab.mul(&zz.sub(&Ball::one(REF))).mul(&fp));
        assert!(sum.contains(&Float::new(64)), "contiguous relation a={a} b={b} c={c} z={z}: {sum:?}");
        // the relation is not trivially satisfied by wide balls
        let scale = f0.abs_upper();
        assert!(sum.rad() < Float::with_val(64, &scale * 1e-30), "too wide: {sum:?}");
    }

    #[test]
    fn contiguous_relations_across_regions() {
        // c - a - b = 2, 1, 0 for a-1, a, a+1 (logarithmic cases), and generic parameters.
        for &z in &[0.3, -0.4, -0.9, 0.6, 0.7, 0.95, 1.0 - 1e-10, -3.0, -50.0, -1e6] {
            contiguous_a(0.375, 1.4375, 2.8125, z);
            contiguous_a(-2.3, 4.1, 1.7, z);
            contiguous_a(2.5, -7.25, 0.375, z);
            // b - a integer (logarithmic after Pfaff for z < -1)
            contiguous_a(0.75, 2.75, 1.125, z);
        }
        // Model-like large parameters, including c - a - b = 1/2 and -1/2.
        for &z in &[0.3, 0.6, 0.9, 0.999, 1.0 - 1e-12, -0.7, -20.0] {
            contiguous_a(1.0, 1000.5, 1002.0, z);
            contiguous_a(1.0, 10.5, 12.0, z);
        }
    }

    #[test]
    fn algorithms_agree_where_both_apply() {
        let wp = 200;
        let ok = |x: &Ball, y: &Ball, what: &str| {
            assert!(x.overlaps(y), "{what}: {x:?} vs {y:?}");
            assert!(x.meets_rel(wp - 40) && y.meets_rel(wp - 40), "{what}: not accurate {x:?} {y:?}");
        };
        for &(a, b, c) in &[(0.3, 1.7, 2.9), (-2.5, 3.25, 1.5), (1.0, 10.5, 12.0), (4.0, -3.5, 7.25)] {
            let (a, b, c) = (f(a), f(b), f(c));
            for &z in &[0.55, 0.6, 0.7] {
                let d = hyp2f1_direct(&a, &b, &c, &f(z), 2 * wp).unwrap();
                let k = hyp2f1_connection(&a, &b, &c, &f(z), wp).unwrap();
                ok(&d, &k, &format!("direct vs 1-z at {z}"));
            }
            for &z in &[-0.4, -0.6, -0.9] {
                let d = hyp2f1_direct(&a, &b, &c, &f(z), 2 * wp).unwrap();
                let p = hyp2f1_pfaff(&a, &b, &c, &f(z), wp).unwrap();
                ok(&d, &p, &format!("direct vs Pfaff at {z}"));
            }
            for &z in &[-1.25, -1.5, -3.0] {
                let p = hyp2f1_pfaff(&a, &b, &c, &f(z), 2 * wp).unwrap();
                let q = hyp2f1_pfaff_connection(&a, &b, &c, &f(z), wp).unwrap();
                ok(&p, &q, &format!("Pfaff vs Pfaff+1-w at {z}"));
            }
        }
        // Logarithmic cases: m = 2, -1, 0, 3 against the direct series; b - a integer after Pfaff.
        for &(a, b, c) in &[(0.375, 1.625, 4.0), (1.25, 0.5, 0.75), (0.5, 0.5, 1.0), (-0.75, 2.5, 4.75), (2.5, 4.5, 4.0)] {
            let (a, b, c) = (f(a), f(b), f(c));
            for &z in &[0.55, 0.7] {
                let d = hyp2f1_direct(&a, &b, &c, &f(z), 2 * wp).unwrap();
                let k = hyp2f1_connection_log(&a, &b, &c, &f(z), wp).unwrap();
                ok(&d, &k, &format!("direct vs log at {z}"));
            }
        }
        for &(a, b, c) in &[(0.375, 2.375, 1.875), (1.5, 1.5, 0.25), (-1.5, 1.5, 3.5)] {
            let (a, b, c) = (f(a), f(b), f(c));
            for &z in &[-1.5, -2.5] {
                let p = hyp2f1_pfaff(&a, &b, &c, &f(z), 2 * wp).unwrap();
                let q = hyp2f1_pfaff_connection(&a, &b, &c, &f(z), wp).unwrap();
                ok(&p, &q, &format!("Pfaff vs Pfaff+log at {z}"));
            }
        }
        // Gauss's sum vs the terminating series at z = 1 (Chu-Vandermonde).
        let (a, b, c) = (f(-3.0), f(2.25), f(7.5));
        let g = hyp2f1_gauss(&a, &b, &c, wp).unwrap();
        let p = hyp2f1_polynomial(&a, &b, &c, &f(1.0), wp).unwrap();
        ok(&g, &p, "Gauss vs polynomial");
        // Series engine vs the ball-arithmetic pFq core at a ball argument.
        let zball = Ball::from_ratio(-1, 3, wp);
        let e = series_2f1(&f(0.3), &f(-1.7), &f(2.9), &zball, wp).unwrap();
        let q = pfq_series(&[Ball::from_f64(0.3, wp).unwrap(), Ball::from_f64(-1.7, wp).unwrap()], &[Ball::from_f64(2.9, wp).unwrap()], &zball, wp)
            .unwrap()
            .sum;
        ok(&e, &q, "series engine vs pfq core");
    }

    #[test]
    fn terminating_and_euler_polynomials() {
        // Chu-Vandermonde zero: 2F1(-3, 2; 1; 1) = (c-b)_3/(c)_3 = (-1)_3 / 1 = 0, exactly.
        let zero = hyp2f1_mp(&f(-3.0), &f(2.0), &f(1.0), &f(1.0), P).unwrap();
        assert!(zero.is_exact() && zero.mid().is_zero(), "{zero:?}");
        let zero = hyp2f1_mp(&f(-2.0), &f(2.5), &f(1.5), &f(1.0), P).unwrap();
        assert!(zero.is_exact() && zero.mid().is_zero(), "{zero:?}");
        // 2F1(-2, b; c; z) = 1 - 2 b z / c + b (b+1) z^2 / (c (c+1)), also with c = -3 (allowed).
        for &(b, c) in &[(0.7, 2.5), (3.0, -3.0), (-1.5, 0.25)] {
            for &z in &[-1e6, -3.0, -0.75, 0.3, 0.9, 1.0] {
                let (bb, cb, zz) = (zb(b), zb(c), zb(z));
                let w = Ball::one(REF)
                    .sub(&bb.mul(&zz).mul_i64(2).div(&cb).unwrap())
                    .add(&bb.mul(&bb.add_i64(1)).mul(&zz.sqr()).div(&cb.mul(&cb.add_i64(1))).unwrap());
                check(&format!("poly b={b} c={c} z={z}"), &mp(-2.0, b, c, z), &w);
            }
        }
        // Long polynomial (series engine) vs the exact rational sum.
        let (a, b, c, z) = (f(-400.0), f(0.5), f(1.5), f(-0.25));
        let s = series_2f1(&a, &b, &c, &xball(&z, 300), 300).unwrap();
        let q = poly_rational(&a, &b, &c, &to_rational(&z).unwrap(), 400).unwrap();
        assert!(s.contains(&Float::with_val(600, &q)), "{s:?}");
        // Euler polynomial: c - a = -2, compared with the direct series at z = 0.8.
        let (a, b, c) = (f(2.5), f(0.7), f(0.5));
        assert_eq!(choose_algorithm(&a, &b, &c, &f(0.8), P), Algorithm::Euler);
        let e = hyp2f1_euler(&a, &b, &c, &f(0.8), 200).unwrap();
        let d = hyp2f1_direct(&a, &b, &c, &f(0.8), 400).unwrap();
        assert!(e.overlaps(&d), "{e:?} vs {d:?}");
        // ... and after Pfaff for z < -1 (c - b = -3 makes the transformed series terminate).
        let (a, b, c) = (f(0.3), f(4.25), f(1.25));
        let p = mp(0.3, 4.25, 1.25, -7.5);
        let q = hyp2f1_pfaff_connection(&a, &b, &c, &f(-7.5), 200).unwrap();
        assert!(p.overlaps(&q));
    }

    #[test]
    fn algorithm_choice_by_region() {
        let ch = |a: f64, b: f64, c: f64, z: f64| choose_algorithm(&f(a), &f(b), &f(c), &f(z), P);
        assert_eq!(ch(0.3, 1.7, 2.9, 0.5), Algorithm::Direct);
        assert_eq!(ch(0.3, 1.7, 2.9, -0.2), Algorithm::Direct);
        // |w| = 1/3 < 1/2: Pfaff is cheaper at z = -1/2.
        assert!(matches!(ch(0.3, 1.7, 2.9, -0.5), Algorithm::Pfaff | Algorithm::PfaffSwapped));
        // Large negative a: the direct series cancels, Euler's transform has positive terms.
        assert_eq!(ch(-2000.5, 2.0, 3.0, 0.5), Algorithm::Euler);
        assert_eq!(ch(0.3, 1.7, 2.9, -0.75), Algorithm::Pfaff);
        assert_eq!(ch(0.3, 1.7, 2.9, 0.9), Algorithm::Connection);
        assert_eq!(ch(1.0, 1.0, 2.0, 0.9), Algorithm::ConnectionLog);
        assert_eq!(ch(0.3, 1.7, 2.9, -5.0), Algorithm::PfaffConnection);
        assert_eq!(ch(1.0, 1.0, 2.0, -50.0), Algorithm::PfaffConnectionLog);
        assert_eq!(ch(0.3, 1.7, 2.9, 1.0), Algorithm::Gauss);
        assert_eq!(ch(-3.0, 1.7, 2.9, -1e6), Algorithm::Polynomial);
        // Model case: direct series where the 1-z pieces would cancel, 1-z formula near 1.
        assert_eq!(ch(1.0, 1000.5, 1002.0, 0.6), Algorithm::Direct);
        assert_eq!(ch(1.0, 1000.5, 1002.0, 1.0 - 1e-12), Algorithm::Connection);
    }

    #[test]
    fn f64_matches_mp_on_a_grid() {
        let zs = [-1e6, -30.0, -2.0, -1.0, -0.7, -0.3, 0.1, 0.45, 0.5, 0.6, 0.9, 1.0 - 1e-9, 1.0];
        let mut n = 0;
        for &a in &[-2.5, -2.0, 0.5, 1.0, 3.7] {
            for &b in &[-1.3, 0.25, 2.0] {
                for &c in &[0.25, 1.5, 5.0] {
                    for &z in &zs {
                        let m = hyp2f1_mp(&f(a), &f(b), &f(c), &f(z), 80);
                        let v = hyp2f1(a, b, c, z);
                        match (m, v) {
                            (Ok(m), Ok(v)) => {
                                let w = m.to_f64();
                                assert!((v - w).abs() <= 1e-14 * w.abs(), "2F1({a},{b};{c};{z}): {v} vs {w}");
                                n += 1;
                            }
                            (Err(_), Err(_)) => assert_eq!(z, 1.0, "({a},{b};{c};{z}) failed"),
                            (m, v) => panic!("2F1({a},{b};{c};{z}): mp {m:?} vs f64 {v:?}"),
                        }
                    }
                }
            }
        }
        assert!(n > 500);
    }

    #[test]
    fn high_precision() {
        let prec = 1000;
        let z = f(0.9);
        let v = hyp2f1_mp(&f(1.0), &f(1.0), &f(2.0), &z, prec).unwrap();
        assert!(v.meets_rel(prec));
        let l = xball(&exact_sub(&one(), &z), prec + 100).ln().unwrap().neg().div(&xball(&z, prec + 100)).unwrap();
        assert!(v.overlaps(&l), "{v:?} vs {l:?}");
        for &y in &[0.3, 0.9, 1.0 - 1e-12] {
            let m = hyp2f1_mp(&f(1.0), &f(1000.5), &f(1002.0), &f(y), prec).unwrap();
            let lo = hyp2f1_mp(&f(1.0), &f(1000.5), &f(1002.0), &f(y), 100).unwrap();
            assert!(m.meets_rel(prec) && m.overlaps(&lo), "{m:?} vs {lo:?}");
        }
    }

    #[test]
    fn bad_input_is_an_error() {
        let nan = f64::NAN;
        let inf = f64::INFINITY;
        for args in [[nan, 1.0, 1.0, 0.5], [1.0, inf, 1.0, 0.5], [1.0, 1.0, -inf, 0.5], [1.0, 1.0, 1.0, nan]] {
            assert!(matches!(hyp2f1(args[0], args[1], args[2], args[3]), Err(Error::NonFinite { .. })));
        }
        assert!(matches!(hyp2f1(1.0, 1.0, 2.0, 1.5), Err(Error::Domain { .. })));
        assert!(matches!(hyp2f1(1.0, 1.0, -2.0, 0.5), Err(Error::Domain { .. })));
        assert!(matches!(hyp2f1(-5.0, 1.0, -2.0, 0.5), Err(Error::Domain { .. })));
        assert!(matches!(hyp2f1(1.0, 1.0, 2.0, 1.0), Err(Error::Domain { .. })));
        assert!(matches!(hyp2f1(1.0, 2.0, 2.5, 1.0), Err(Error::Domain { .. })));
        assert!(hyp2f1(-2.0, 1.0, -2.0, 0.5).is_ok());
        assert!(hyp2f1_mp(&f(1.0), &f(1.0), &f(2.0), &f(0.5), 0).is_err());
        assert!(hyp2f1_mp(&f(1.0), &f(1.0), &f(2.0), &f(0.5), crate::MAX_PREC + 1).is_err());
        assert!(hyp2f1_mp(&f(1.0), &f(1.0), &Float::with_val(53, rug::float::Special::Nan), &f(0.5), 64).is_err());
        assert!(hyp2f1_direct(&f(1.0), &f(1.0), &f(2.0), &f(1.0), 64).is_err());
        assert!(hyp2f1_connection(&f(1.0), &f(1.0), &f(2.0), &f(0.7), 64).is_err());
        assert!(hyp2f1_connection_log(&f(1.0), &f(1.5), &f(2.0), &f(0.7), 64).is_err());
        assert_eq!(hyp2f1(0.3, 0.4, 0.5, 0.0).unwrap(), 1.0);
    }

}
