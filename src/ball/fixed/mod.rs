//! `exp`, `sin` and `cos` of a midpoint at working precisions up to 486 bits, in
//! fixed-point arithmetic on 64-bit limbs, with a rigorous error bound: the kernels
//! under [`super::Ball`]'s elementary functions, where MPFR's correctly rounded
//! `exp` and `sin` cost 2.5 to 6 times Arb's (0.70-2.4 us against 0.13-0.80 us per call
//! at 64-400 bits, `reference/elementary_mpfr_arb.c` on this project's machine).
//!
//! # Method
//!
//! This is Arb's method for `arb_exp` and `arb_sin_cos` at low precision (F. Johansson,
//! "Efficient implementation of elementary functions in the medium-precision range",
//! ARITH 22, 2015), with up to three table levels and Horner's rule in place of
//! rectangular splitting.
//!
//! The working format (see [`limbs`]) has `F = 64 L - 2` fractional bits, `L` the least
//! number of limbs with `F >= wp + 24`; every operation truncates and errs by less
//! than one *ulp* `2^-F` (a product by less than `1 + 2^-57`, which the margins of
//! step 4 absorb).
//!
//! 1. **Reduction.** `|m| < 2^20`. For `exp`, `n = floor(m / ln 2)` and
//!    `t = m - n ln 2` in `[0, 1)`; for `sin` and `cos`, `n = round(|m| / (pi/2))` and
//!    `u = | |m| - n pi/2 |` (below 1, with its sign kept). `n` is guessed in f64 and
//!    corrected until `t` (or `u`) lies in `[0, 1)`: only the bound on `t` matters, not
//!    the optimality of `n`. The constant is stored with `F + 64` bits, `|m|` is
//!    truncated to `F` bits: `t` errs by less than `1 + 1 + |n| 2^-64 < 3` ulps.
//! 2. **Tables.** `t = k_1 2^-8 + ... + k_v 2^(-8 v) + s` with `k_j` the next eight
//!    bits of `t` and `s < 2^(-8 v)`, `v <= 3` levels chosen per `L` by the cost in
//!    multiplications. `e^(k 2^(-8 j))`, `sin(k 2^(-8 j))`, `cos(k 2^(-8 j))` are
//!    tabulated for `k < 256`, computed once per `L` (the exponential's apart from the
//!    sine's and cosine's, filled lazily: the first [`LAZY_CALLS`] calls of each `L` go
//!    to MPFR, the next builds the tables) as powers of the step in
//!    MPFR at `F + 40` bits and truncated (error below 1.01 ulp; counted as 2;
//!    [`exp_level`]).
//! 3. **Taylor series** in `s`, by Horner's rule, to the least order whose tail is
//!    below one ulp (`e^s`: tail `<= 2 s^(N+1)/(N+1)!`; `sin s / s` and `cos s`:
//!    alternating, the tail below the first omitted term). Each Horner step
//!    `R <- 1 +- floor(floor(s R) / j)` adds less than 2 ulps and contracts the
//!    earlier error by `s/j < 2^-8`, so `R` errs by at most `2.02 + 1` ulps
//!    (`sin s = s R` by 1.02, `cos s` by 3.03). The divisions are multiplications by a
//!    precomputed reciprocal ([`limbs::Divisor`]).
//! 4. **Recombination.** `e^t = e^s prod_j e^(k_j 2^(-8 j))`; `(sin, cos)` of `u` by
//!    rotating `(sin s, cos s)` by each level's angle, deepest first. A product `A B`
//!    errs by `|A| b + |B| a + 1` ulps from the factors' errors `a`, `b`; a rotation by
//!    `(S, C)` turns the errors `(a_s, a_c)` of its input `(S_in, C_in)` into
//!    `(|S| a_c + a_s, a_c + |S| a_s)` plus `2 (|S_in| + |C_in|) + 2`. With `e^t < 2`,
//!    `|S| <= 2^-16, 2^-8, 0.85` at levels 3, 2, 1, and `|S_in| + |C_in| <= 1.01` before
//!    the last rotation: `e^t` errs by at most `19.2` ulps before the reduction and
//!    `(sin u, cos u)` by at most `(22.5, 22.8)`; the reduction error `delta < 3` ulps
//!    carried through the derivative (`e^t < 2.01`; sin, cos 1-Lipschitz) adds 6.03 and
//!    3. The bounds returned are 32 ulps for each.
//! 5. **Result.** `e^m = 2^n e^t`; the quadrant `n mod 4` permutes and negates `sin u`,
//!    `cos u`. The fixed-point value is rounded to `wp` bits by MPFR (`mpfr_set_z_2exp`,
//!    its ternary value gives the rounding error), and the bound is that error plus the
//!    ulps above, scaled.
//!
//! # Regions
//!
//! `exp` from 487 to 4600 bits goes to [`wide`] (the same method on GMP's `mpn` layer
//! with Taylor series by rectangular splitting; its own module docs).
//!
//! `None` (the caller uses MPFR) for `wp > 486` (`exp`: outside [`wide`]'s range), `|m| >= 2^20`, a non-finite `m`, for
//! `sin`/`cos` when `|m| < 2^-16` or when either result is below `2^-16` in magnitude
//! (an absolute error bound would cost relative bits there; MPFR's are correctly
//! rounded), and on targets whose GMP limb is not 64 bits.

pub(crate) mod limbs;
mod wide;

use std::cmp::Ordering;
use std::sync::atomic::{AtomicU32, Ordering as AtomicOrdering};
use std::sync::OnceLock;

use rug::Float;

use super::mag::raw_parts;
use super::Mag;
use limbs::MAX_LIMBS;

/// Guard bits of the fixed-point format over the working precision.
const GUARD: u32 = 24;

/// Largest working precision served here.
#[allow(dead_code)]
pub(crate) const MAX_FIXED_PREC: u32 = 64 * MAX_LIMBS as u32 - 2 - GUARD;

/// Guard bits of the MPFR arithmetic that builds the tables ([`exp_level`]); the
/// constants `ln 2` and `pi/2`, stored with `F + 64` bits, are computed at `F + 128`.
const TABLE_GUARD: u32 = 40;

/// Table index bits per level (256 entries), and the most levels.
const TAB_BITS: u32 = 8;
const TAB_LEN: usize = 1 << TAB_BITS;
const MAX_LEVELS: usize = 3;

/// The tables and Horner divisors of `exp` for one number of limbs `L`.
struct ExpTables {
    /// Level `j` (from 1): `floor(e^(k 2^(-8 j)) 2^F)`, `L` limbs per entry, `k < 256`.
    exp: Vec<Vec<u64>>,
    /// `floor(ln2 2^(F+64))`: `L + 1` limbs.
    ln2: Vec<u64>,
    /// Levels used by `exp` (chosen by cost).
    exp_levels: usize,
    /// The Horner divisors of `e^s` to `s^N`, outermost first: `N, ..., 1`.
    exp_div: Vec<limbs::Divisor>,
}

/// The same for `sin` and `cos`, built apart: an integrand with `exp` only never pays
/// for them (the tables are most of a first call at 333 bits).
struct TrigTables {
    /// Level `j` (from 1): `floor(sin(k 2^(-8 j)) 2^F)`, `floor(cos(..) 2^F)`.
    sin: Vec<Vec<u64>>,
    cos: Vec<Vec<u64>>,
    /// `floor(pi/2 2^(F+64))`: `L + 1` limbs.
    half_pi: Vec<u64>,
    /// Levels used by `sin`/`cos` (chosen by cost).
    trig_levels: usize,
    /// The terms `y^j`, `j = 1, 2, ...`, of `sin s / s` and `cos s` in `y = s^2`.
    trig_terms: Vec<TrigTerm>,
    /// The error bound of `sin_cos_fixed` in ulps (module docs, step 4), from the orders.
    trig_ulps: f64,
}

/// How the term `y^j` enters the series: `C_j = y^j / (2j)!` by the chunks of `(2j)!`
/// (products of consecutive integers below `2^64`) when `cos` needs it, and
/// `S_j = C_j / (2j + 1)` when `sin s / s` needs it.
struct TrigTerm {
    factorial: Vec<limbs::Divisor>,
    in_cos: bool,
    sin_extra: Option<limbs::Divisor>,
}

/// The chunks of `(2j)!`: products of `1..=2j` grouped greedily below `2^64`.
fn factorial_chunks(n: u64) -> Vec<u64> {
    let mut chunks = Vec::new();
    let mut c: u64 = 1;
    for k in 2..=n {
        match c.checked_mul(k) {
            Some(v) => c = v,
            None => {
                chunks.push(c);
                c = k;
            }
        }
    }
    if c > 1 {
        chunks.push(c);
    }
    chunks
}

/// The terms of the sine and cosine series to orders `n_sin`, `n_cos` (in `y`), and
/// the error bound in ulps that they and `levels` rotations give (module docs, step 4).
fn trig_terms(n_sin: u64, n_cos: u64, levels: usize) -> (Vec<TrigTerm>, f64) {
    let n = n_sin.max(n_cos);
    let mut terms = Vec::new();
    // y^j errs by less than 1.02 ulps (y < 2^-16 contracts every earlier error)
    let (mut err_cos, mut err_sin) = (1.0, 1.0); // the truncation of each series
    for j in 1..=n {
        let chunks = factorial_chunks(2 * j);
        let err_c = 1.02 + chunks.len() as f64; // C_j = floor chain of y^j / (2j)!
        if j <= n_cos {
            err_cos += err_c;
        }
        if j <= n_sin {
            err_sin += err_c / (2 * j + 1) as f64 + 1.0;
        }
        terms.push(TrigTerm {
            factorial: chunks.into_iter().map(limbs::Divisor::new).collect(),
            in_cos: j <= n_cos,
            sin_extra: (j <= n_sin).then(|| limbs::Divisor::new(2 * j + 1)),
        });
    }
    // sin s = s (sin s / s): s < 2^-8 scales the error, plus the product's floor
    let (mut a_s, mut a_c) = (err_sin / 256.0 + 1.02, err_cos);
    // rotations, deepest level first: |S| <= 2^-16, 2^-8, 0.85 at levels 3, 2, 1; the
    // table errors (2 ulps each) times |S_in| + |C_in| <= 1.42, plus two floors
    for level in (1..=levels).rev() {
        let s_max = if level == 1 { 0.85 } else { (2f64).powi(-8 * (level as i32 - 1)) };
        let (ns, nc) = (s_max * a_c + a_s + 2.0 * 1.42 + 2.02, a_c + s_max * a_s + 2.0 * 1.42 + 2.02);
        (a_s, a_c) = (ns, nc);
    }
    // the reduction error (3 ulps; sin and cos are 1-Lipschitz), and a margin
    ((terms), (a_s.max(a_c) + 3.0).ceil() + 1.0)
}

static EXP_TABLES: [OnceLock<ExpTables>; MAX_LIMBS + 1] = [const { OnceLock::new() }; MAX_LIMBS + 1];
static TRIG_TABLES: [OnceLock<TrigTables>; MAX_LIMBS + 1] = [const { OnceLock::new() }; MAX_LIMBS + 1];

/// Calls answered by MPFR before the tables of a limb count are built (the tables are
/// filled lazily, like a ski rental): building the sine and cosine tables costs about
/// 850 000 instructions at one limb and 3.4 million at six (2026-11-29, callgrind of
/// `maugis eval` on one `integrate` request of `sin x` at 64 bits: half of the request),
/// that is the saving of the fixed-point kernel over MPFR's `sin` (about 0.5 us a call
/// at 64 bits, 1.6 us at 333; the module docs) on 500 to 600 calls. With 256 calls
/// first in MPFR, a process that makes few calls (a one-shot `maugis integrate` of a
/// small integral: `sin x` on `[-1, 1]` stays below 256 at 64 and 333 bits, its first
/// call 1.69M -> 1.07M and 8.2M -> 5.2M instructions, docs/quadrature.md) never pays for the tables,
/// and one that makes many pays at most the tables' cost once more. The answers are
/// certified either way (MPFR's are correctly rounded).
const LAZY_CALLS: u32 = 256;

static EXP_CALLS: [AtomicU32; MAX_LIMBS + 1] = [const { AtomicU32::new(0) }; MAX_LIMBS + 1];
static TRIG_CALLS: [AtomicU32; MAX_LIMBS + 1] = [const { AtomicU32::new(0) }; MAX_LIMBS + 1];

/// Whether the fixed-point kernel of one limb count serves this call: its tables exist,
/// or [`LAZY_CALLS`] calls have gone to MPFR before it (they are built now).
fn tables_ready<T>(tables: &OnceLock<T>, calls: &AtomicU32) -> bool {
    tables.get().is_some() || calls.fetch_add(1, AtomicOrdering::Relaxed) >= LAZY_CALLS
}

/// `floor(v 2^shift)` as exactly `len` little-endian limbs (`v >= 0` finite, the result
/// fits), read off `v`'s significand without an integer conversion.
fn fixed_limbs(v: &Float, shift: i32, len: usize) -> Vec<u64> {
    wide::to_fixed(v, shift as i64, len).expect("table entry does not fit")
}

/// `log2(n!)`, rounded down (f64 sums, then a margin).
fn log2_factorial_lower(n: u64) -> f64 {
    (2..=n).map(|k| (k as f64).log2()).sum::<f64>() * (1.0 - 1e-12)
}

/// The least `n` with `b (n + 1) + log2((n + 1)!) >= f + 1`: the tail
/// `2 s^(n+1)/(n+1)!` of `e^s` below one ulp for `s < 2^-b`.
fn exp_order(f: u32, b: u32) -> u64 {
    (1..).find(|&n: &u64| b as f64 * (n + 1) as f64 + log2_factorial_lower(n + 1) >= f as f64 + 1.0).unwrap_or(1)
}

/// The least `n` with `b e + log2(d!) >= f`, `e = 2 n + 2`, `d = e + extra`: the first
/// omitted term of `sin s / s` (`extra = 1`) or `cos s` (`extra = 0`) below one ulp.
fn trig_order(f: u32, b: u32, extra: u64) -> u64 {
    (1..)
        .find(|&n: &u64| {
            let e = 2 * n + 2;
            b as f64 * e as f64 + log2_factorial_lower(e + extra) >= f as f64
        })
        .unwrap_or(1)
}

/// The entries `k = 0..255` of table level `level` of the working format with `f`
/// fractional bits. They are powers of the level's step `t = 2^-(8 level)`:
/// `e^{kt} = e^{(k-1)t} e^t`, and `(cos kt, sin kt)` the previous pair rotated by
/// `(cos t, sin t)`, in MPFR at `p = f + 40` bits ([`TABLE_GUARD`]) rounded to nearest: each of the at
/// most 255 steps adds a relative error of a few `2^-p` (a rotation keeps the norm, so
/// errors add), in all below `2^(12 - p) = 2^-(f + 28)`, far below the table's unit
/// `2^-f`: the floor is off by at most one unit, as with one MPFR call per entry (the 2
/// ulps of `trig_terms`), at a fraction of the cost. The products go into temporaries
/// allocated once.
///
/// Below `MAX_LIMBS` limbs the powers are formed in the fixed-point format of
/// `L + 1` limbs instead ([`level_fixed`]) and each entry is its top `L` limbs.
fn exp_level(f: u32, level: u32, l: usize) -> Vec<u64> {
    if l < MAX_LIMBS {
        return level_fixed(level, l, false).0;
    }
    let p = f + TABLE_GUARD;
    let step = Float::with_val(p, 1) >> (TAB_BITS * level);
    let e_step = Float::with_val(p, step.exp_ref());
    let mut ev = Float::with_val(p, 1);
    let mut out = Vec::with_capacity(TAB_LEN * l);
    for k in 0..TAB_LEN {
        if k > 0 {
            ev *= &e_step;
        }
        out.extend(fixed_limbs(&ev, f as i32, l));
    }
    out
}

/// The sine and cosine entries of one level (see [`exp_level`]).
fn trig_level(f: u32, level: u32, l: usize) -> (Vec<u64>, Vec<u64>) {
    use rug::Assign;
    if l < MAX_LIMBS {
        let (_, sn, cs) = level_fixed(level, l, true);
        return (sn, cs);
    }
    let p = f + TABLE_GUARD;
    let step = Float::with_val(p, 1) >> (TAB_BITS * level);
    let (s_step, c_step) = step.sin_cos(Float::new(p));
    let (mut sv, mut cv) = (Float::new(p), Float::with_val(p, 1));
    let (mut t1, mut t2) = (Float::new(p), Float::new(p));
    let (mut sn, mut cs) = (Vec::with_capacity(TAB_LEN * l), Vec::with_capacity(TAB_LEN * l));
    for k in 0..TAB_LEN {
        if k > 0 {
            // (s, c) <- (s C + c S, c C - s S), each product rounded, then the sum
            t1.assign(&sv * &c_step);
            t2.assign(&cv * &s_step);
            let new_s = Float::with_val(p, &t1 + &t2);
            t1.assign(&cv * &c_step);
            t2.assign(&sv * &s_step);
            cv.assign(&t1 - &t2);
            sv = new_s;
        }
        sn.extend(fixed_limbs(&sv, f as i32, l));
        cs.extend(fixed_limbs(&cv, f as i32, l));
    }
    (sn, cs)
}

/// The entries of one level for `L < MAX_LIMBS` limbs: `e^{kt}`, `sin kt`, `cos kt`,
/// `t = 2^-(8 level)`, as powers of the step (from MPFR at `64 W + 40` bits, `W = L +
/// 1`, truncated) formed in the signed format of `W` limbs (`u = 2^-(64 W -
/// 2)`), then cut to their top `L` limbs, which is the floor at `L` limbs of the
/// `W`-limb value (`F_W - F_L = 64 (W - L)`). Errors: the step is off by less than `u`
/// per part; a product truncates by less than `1.01 u`; a rotation `(c + i s)(C + i
/// S)` takes Gauss's three products `cC`, `sS`, `(c + s)(C + S)` (all below 2.3), so
/// its parts err by less than `2.02 u` and `3.03 u`; `e^{kt} < e` and the rotations
/// keep the norm near 1, so after `k <= 255` steps the error is at most `255 (e u +
/// 4.3 u + e u) e < 2^13 u`, and with `W - L >= 1` that is
/// below `2^-51` units of the `L`-limb format: the cut entry is the floor of the true
/// value or one unit off, as the MPFR build's. `trig` asks for the sines and cosines
/// (the last two vectors), otherwise the exponentials (the first).
fn level_fixed(level: u32, l: usize, trig: bool) -> (Vec<u64>, Vec<u64>, Vec<u64>) {
    match l {
        1 => level_fixed_w::<2>(level, l, trig),
        2 => level_fixed_w::<3>(level, l, trig),
        3 => level_fixed_w::<4>(level, l, trig),
        4 => level_fixed_w::<5>(level, l, trig),
        5 => level_fixed_w::<6>(level, l, trig),
        6 => level_fixed_w::<7>(level, l, trig),
        _ => level_fixed_w::<8>(level, l, trig),
    }
}

/// [`level_fixed`] in the format of `W > L` limbs.
fn level_fixed_w<const W: usize>(level: u32, l: usize, trig: bool) -> (Vec<u64>, Vec<u64>, Vec<u64>) {
    debug_assert!(W > l);
    let p = 64 * W as u32 + TABLE_GUARD;
    let step = Float::with_val(p, 1) >> (TAB_BITS * level);
    let e_step = to_signed::<W>(&Float::with_val(p, step.exp_ref()), 0).expect("e^t < 4");
    let (s_step, c_step) = step.sin_cos(Float::new(p));
    let (ss, cs) = (to_signed::<W>(&s_step, 0).expect("sin t < 4"), to_signed::<W>(&c_step, 0).expect("cos t < 4"));
    let cs_ss = cs.add(&ss);
    let one = limbs::Signed::<W> { mag: limbs::one::<W>(), neg: false };
    let (mut ev, mut sv, mut cv) = (one, limbs::Signed::<W>::ZERO, one);
    let (mut e_out, mut s_out, mut c_out) = (Vec::with_capacity(TAB_LEN * l), Vec::with_capacity(TAB_LEN * l), Vec::with_capacity(TAB_LEN * l));
    for k in 0..TAB_LEN {
        if trig {
            if k > 0 {
                // (c + i s)(C + i S) by Gauss's three products
                let (p1, p2) = (cv.mul(&cs), sv.mul(&ss));
                let p3 = cv.add(&sv).mul(&cs_ss);
                cv = p1.sub(&p2);
                sv = p3.sub(&p1).sub(&p2);
            }
            s_out.extend_from_slice(&sv.mag[W - l..]);
            c_out.extend_from_slice(&cv.mag[W - l..]);
        } else {
            if k > 0 {
                ev = ev.mul(&e_step);
            }
            e_out.extend_from_slice(&ev.mag[W - l..]);
        }
    }
    (e_out, s_out, c_out)
}

fn exp_tables(l: usize) -> &'static ExpTables {
    EXP_TABLES[l].get_or_init(|| {
        let f = 64 * l as u32 - 2;
        let p = f + 128;
        // levels by cost in full multiplications (a division counts half of one):
        // one per level and per order
        let exp_levels = (1..=MAX_LEVELS).min_by_key(|&v| 2 * v as u64 + 3 * exp_order(f, TAB_BITS * v as u32)).unwrap_or(1);
        let exp = (1..=exp_levels as u32).map(|level| exp_level(f, level, l)).collect();
        let ln2 = fixed_limbs(&Float::with_val(p, rug::float::Constant::Log2), f as i32 + 64, l + 1);
        let be = TAB_BITS * exp_levels as u32;
        ExpTables { exp, ln2, exp_levels, exp_div: (1..=exp_order(f, be)).rev().map(limbs::Divisor::new).collect() }
    })
}

fn trig_tables(l: usize) -> &'static TrigTables {
    TRIG_TABLES[l].get_or_init(|| {
        let f = 64 * l as u32 - 2;
        let p = f + 128;
        // levels by cost in full multiplications: four per extra level, two per order
        let trig_levels = (1..=MAX_LEVELS)
            .min_by_key(|&v| {
                let b = TAB_BITS * v as u32;
                8 * v as u64 + 4 * trig_order(f, b, 1).max(trig_order(f, b, 0))
            })
            .unwrap_or(1);
        let (sin, cos) = (1..=trig_levels as u32).map(|level| trig_level(f, level, l)).unzip();
        let half_pi = fixed_limbs(&(Float::with_val(p, rug::float::Constant::Pi) >> 1), f as i32 + 64, l + 1);
        let bt = TAB_BITS * trig_levels as u32;
        let (trig_terms, trig_ulps) = trig_terms(trig_order(f, bt, 1), trig_order(f, bt, 0), trig_levels);
        TrigTables { sin, cos, half_pi, trig_levels, trig_terms, trig_ulps }
    })
}

/// The number of limbs for a working precision, `None` above [`MAX_FIXED_PREC`].
fn limbs_for(wp: u32) -> Option<usize> {
    let l = (wp + GUARD + 2).div_ceil(64) as usize;
    (l <= MAX_LIMBS && cfg!(target_pointer_width = "64")).then_some(l.max(1))
}

/// `|m|` as an f64 from the top limb of its significand (a guess for the reduction,
/// accurate to about 2^-52, and 0 below 2^-1000), without MPFR's conversion.
fn approx_abs(m: &Float) -> f64 {
    let (d, e) = raw_parts(m);
    let top = d[d.len() - 1] as f64; // in [2^63, 2^64)
    let shift = e - 64;
    if shift < -1000 {
        return 0.0;
    }
    // 2^shift for |shift| < 1023, from its bits
    top * f64::from_bits(((1023 + shift) as u64) << 52)
}

/// The number of limbs `L` whose Q2 format has at least `bits` fractional bits,
/// `None` above [`limbs::MAX_LIMBS`] (or where a GMP limb is not 64 bits).
pub(crate) fn limbs_for_bits(bits: u32) -> Option<usize> {
    let l = (bits + 2).div_ceil(64) as usize;
    (l <= MAX_LIMBS && cfg!(target_pointer_width = "64")).then_some(l.max(1))
}

/// `v 2^e` in the signed Q2 format of `L` limbs, the magnitude truncated (an error below
/// one ulp `2^-(64 L - 2)`); `None` when `|v| 2^e >= 4` or `v` is not finite.
pub(crate) fn to_signed<const L: usize>(v: &Float, e: i64) -> Option<limbs::Signed<L>> {
    if v.is_zero() {
        return Some(limbs::Signed::ZERO);
    }
    if !v.is_finite() {
        return None;
    }
    let (d, ve) = raw_parts(v);
    let w = limbs::shifted(d, ve - 64 * d.len() as i64 + 64 * L as i64 - 2 + e, L)?;
    // below 4: `shifted` refuses a value that does not fit in `L` limbs
    let mut mag = [0u64; L];
    mag.copy_from_slice(&w[..L]);
    Some(limbs::Signed { mag, neg: v.is_sign_negative() })
}

/// `floor(|v| 2^(F + e))` as the `l` limbs of a Q2 magnitude (`F = 64 l - 2`), an error
/// below one ulp; `None` when `|v| 2^e >= 4` or `v` is not finite.
pub(crate) fn to_magnitude(v: &Float, e: i64, l: usize) -> Option<Vec<u64>> {
    if v.is_zero() {
        return Some(vec![0; l]);
    }
    if !v.is_finite() || l > MAX_LIMBS {
        return None;
    }
    let (d, ve) = raw_parts(v);
    let w = limbs::shifted(d, ve - 64 * d.len() as i64 + 64 * l as i64 - 2 + e, l)?;
    Some(w[..l].to_vec())
}

/// A signed Q2 value as an exact float (precision `64 L`).
pub(crate) fn from_signed<const L: usize>(x: &limbs::Signed<L>) -> Float {
    let (y, ord) = to_float(&x.mag, -(64 * L as i64 - 2), 64 * L as u32, x.neg);
    debug_assert_eq!(ord, Ordering::Equal);
    y
}

/// `X 2^e` rounded to nearest at `prec` bits, with MPFR's ternary value.
fn to_float(x: &[u64], e: i64, prec: u32, negative: bool) -> (Float, Ordering) {
    let mut y = Float::new(prec);
    // SAFETY: `mpz_roinit_n` makes a read-only mpz over `x`'s limbs (normalised, no
    // allocation); it is only read by `mpfr_set_z_2exp` while `x` is borrowed.
    let ord = unsafe {
        let mut z = std::mem::MaybeUninit::<gmp_mpfr_sys::gmp::mpz_t>::uninit();
        let zp = gmp_mpfr_sys::gmp::mpz_roinit_n(z.as_mut_ptr(), x.as_ptr() as *const gmp_mpfr_sys::gmp::limb_t, x.len() as _);
        gmp_mpfr_sys::mpfr::set_z_2exp(y.as_raw_mut(), zp, e as _, gmp_mpfr_sys::mpfr::rnd_t::RNDN)
    };
    let mut ord = ord.cmp(&0);
    if negative {
        y = -y;
        ord = ord.reverse();
    }
    (y, ord)
}

/// The rounding error of [`to_float`] plus `ulps 2^scale_exp`.
fn bound(y: &Float, ord: Ordering, ulps: f64, scale_exp: i64) -> Mag {
    super::rounding_error(y, ord).add(Mag::from_f64(ulps).mul(Mag::pow2(scale_exp)))
}

/// `e^m` rounded to `wp` bits and a bound on its error; `None` outside the region
/// served (see the module docs).
pub(crate) fn exp(m: &Float, wp: u32) -> Option<(Float, Mag)> {
    let Some(l) = limbs_for(wp) else {
        return wide::exp(m, wp);
    };
    if !tables_ready(&EXP_TABLES[l], &EXP_CALLS[l]) {
        return None;
    }
    match l {
        1 => exp_kernel::<1>(m, wp),
        2 => exp_kernel::<2>(m, wp),
        3 => exp_kernel::<3>(m, wp),
        4 => exp_kernel::<4>(m, wp),
        5 => exp_kernel::<5>(m, wp),
        6 => exp_kernel::<6>(m, wp),
        7 => exp_kernel::<7>(m, wp),
        _ => exp_kernel::<8>(m, wp),
    }
}

/// `(sin m, cos m)` rounded to `wp` bits, each with a bound on its error; `None`
/// outside the region served (see the module docs).
pub(crate) fn sin_cos(m: &Float, wp: u32) -> Option<((Float, Mag), (Float, Mag))> {
    let (s, c) = sin_cos_dispatch(m, wp, Want::Both)?;
    Some((s, c?))
}

/// `sin m` rounded to `wp` bits with a bound on its error (as [`sin_cos`], without
/// rounding the cosine).
pub(crate) fn sin(m: &Float, wp: u32) -> Option<(Float, Mag)> {
    sin_cos_dispatch(m, wp, Want::Sin).map(|(s, _)| s)
}

fn sin_cos_dispatch(m: &Float, wp: u32, want: Want) -> Option<((Float, Mag), Option<(Float, Mag)>)> {
    let l = limbs_for(wp)?;
    if !tables_ready(&TRIG_TABLES[l], &TRIG_CALLS[l]) {
        return None;
    }
    match l {
        1 => sin_cos_kernel::<1>(m, wp, want),
        2 => sin_cos_kernel::<2>(m, wp, want),
        3 => sin_cos_kernel::<3>(m, wp, want),
        4 => sin_cos_kernel::<4>(m, wp, want),
        5 => sin_cos_kernel::<5>(m, wp, want),
        6 => sin_cos_kernel::<6>(m, wp, want),
        7 => sin_cos_kernel::<7>(m, wp, want),
        _ => sin_cos_kernel::<8>(m, wp, want),
    }
}

/// `floor(|m| 2^F)` in `L + 1` limbs, for `|m| < 2^20`.
fn argument<const L: usize>(m: &Float) -> Option<limbs::Wide> {
    let (d, e) = raw_parts(m);
    let f = 64 * L as i64 - 2;
    limbs::shifted(d, e - 64 * d.len() as i64 + f, L + 1)
}

/// `floor(n c 2^F)` for a constant `c` stored as `floor(c 2^(F+64))` in `L + 1` limbs.
fn multiple<const L: usize>(c: &[u64], n: u64) -> limbs::Wide {
    let p = limbs::mul_small(c, n);
    let mut out: limbs::Wide = [0; MAX_LIMBS + 1];
    out[..L + 1].copy_from_slice(&p[1..L + 2]);
    out
}

/// `|a - b|` of two wide values (`L + 1` limbs) and whether `a < b`.
fn abs_diff<const L: usize>(a: &limbs::Wide, b: &limbs::Wide) -> (limbs::Wide, bool) {
    let (hi, lo, neg) = if limbs::ge(&a[..L + 1], &b[..L + 1]) { (a, b, false) } else { (b, a, true) };
    let mut z: limbs::Wide = [0; MAX_LIMBS + 1];
    let mut borrow = false;
    for i in 0..L + 1 {
        let (d1, b1) = hi[i].overflowing_sub(lo[i]);
        let (d2, b2) = d1.overflowing_sub(borrow as u64);
        z[i] = d2;
        borrow = b1 || b2;
    }
    (z, neg)
}

/// The Q2 form of a wide value below 1, or `None` when it is not below 1.
fn below_one<const L: usize>(w: &limbs::Wide) -> Option<[u64; L]> {
    if w[L] != 0 || w[L - 1] >> 62 != 0 {
        return None;
    }
    let mut x = [0u64; L];
    x.copy_from_slice(&w[..L]);
    Some(x)
}

/// Splits `t < 1` into the table indices `k_1..k_levels` (its top `8 levels` bits, eight
/// per level) and the rest `s < 2^(-8 levels)`.
fn split<const L: usize>(mut t: [u64; L], levels: usize) -> ([usize; MAX_LEVELS], [u64; L]) {
    let mut k = [0usize; MAX_LEVELS];
    for (j, kj) in k.iter_mut().enumerate().take(levels) {
        *kj = ((t[L - 1] >> (62 - TAB_BITS * (j as u32 + 1))) & (TAB_LEN as u64 - 1)) as usize;
    }
    t[L - 1] &= (1u64 << (62 - TAB_BITS * levels as u32)) - 1;
    (k, t)
}

fn entry<const L: usize>(tab: &[u64], k: usize) -> [u64; L] {
    let mut x = [0u64; L];
    x.copy_from_slice(&tab[k * L..(k + 1) * L]);
    x
}

fn exp_kernel<const L: usize>(m: &Float, wp: u32) -> Option<(Float, Mag)> {
    if m.is_zero() {
        return Some((Float::with_val(wp, 1), Mag::ZERO));
    }
    let (v, n) = exp_fixed::<L>(m)?;
    let f = 64 * L as i64 - 2;
    let (y, ord) = to_float(&v, n - f, wp, false);
    if !y.is_finite() || y.is_zero() {
        return None;
    }
    let err = bound(&y, ord, EXP_ULPS, n - f);
    Some((y, err))
}

/// Error bound of [`exp_fixed`] in ulps of `2^(n - F)` (module docs, step 4).
const EXP_ULPS: f64 = 32.0;

/// `(V, n)` with `|V 2^(n - F) - e^m| <= 32 2^(n - F)` (finite nonzero `m`).
fn exp_fixed<const L: usize>(m: &Float) -> Option<([u64; L], i64)> {
    if !m.is_finite() || m.is_zero() || m.get_exp().is_none_or(|e| e > 21) {
        return None;
    }
    let mf = if m.is_sign_negative() { -approx_abs(m) } else { approx_abs(m) };
    if mf.abs() >= (1u64 << 20) as f64 {
        return None;
    }
    let tab = exp_tables(L);
    let ym = argument::<L>(m)?;
    let negative = m.is_sign_negative();
    let mut n = (mf / std::f64::consts::LN_2).floor() as i64;
    // t = m - n ln2 in [0, 1): correct the f64 guess of n (a few steps at most)
    let mut t = None;
    for _ in 0..4 {
        let a = multiple::<L>(&tab.ln2, n.unsigned_abs());
        let (d, neg) = abs_diff::<L>(&ym, &a);
        // m >= 0: t = |m| - n ln2 (n >= 0); m < 0: t = |n| ln2 - |m|
        let t_negative = (if negative { !neg } else { neg }) && d.iter().any(|&x| x != 0);
        if t_negative {
            n -= 1;
            continue;
        }
        match below_one::<L>(&d) {
            Some(x) => {
                t = Some(x);
                break;
            }
            None => n += 1,
        }
    }
    let t = t?;
    let (k, s) = split(t, tab.exp_levels);
    let one = limbs::one::<L>();
    let mut r = one;
    for d in &tab.exp_div {
        r = limbs::add(&one, &limbs::div_small(&limbs::mul(&s, &r), d));
    }
    for (j, &kj) in k.iter().enumerate().take(tab.exp_levels) {
        if kj != 0 {
            r = limbs::mul(&entry::<L>(&tab.exp[j], kj), &r);
        }
    }
    Some((r, n))
}

/// Which of `sin m`, `cos m` to round to a float.
#[derive(Clone, Copy, PartialEq)]
enum Want {
    Sin,
    Both,
}

fn sin_cos_kernel<const L: usize>(m: &Float, wp: u32, want: Want) -> Option<((Float, Mag), Option<(Float, Mag)>)> {
    let (sin_mag, sin_neg, cos_mag, cos_neg) = sin_cos_fixed::<L>(m)?;
    // below 2^-16 an absolute bound would cost relative bits: MPFR instead
    let small = |x: &[u64; L]| x[L - 1] >> (62 - 16) == 0;
    if small(&sin_mag) || (want == Want::Both && small(&cos_mag)) {
        return None;
    }
    let f = 64 * L as i64 - 2;
    let rounded = |x: &[u64; L], neg: bool| {
        let (y, ord) = to_float(x, -f, wp, neg);
        let e = bound(&y, ord, trig_tables(L).trig_ulps, -f);
        (y, e)
    };
    let cos = (want == Want::Both).then(|| rounded(&cos_mag, cos_neg));
    Some((rounded(&sin_mag, sin_neg), cos))
}

/// `(|sin m| 2^F, sin m < 0, |cos m| 2^F, cos m < 0)`, each magnitude within
/// `trig_ulps` ulps of its table.
fn sin_cos_fixed<const L: usize>(m: &Float) -> Option<([u64; L], bool, [u64; L], bool)> {
    if !m.is_finite() || m.is_zero() || m.get_exp().is_none_or(|e| e > 21) {
        return None;
    }
    let mf = approx_abs(m);
    if mf >= (1u64 << 20) as f64 || mf < 1.0 / 65536.0 {
        return None;
    }
    let tab = trig_tables(L);
    let ym = argument::<L>(m)?;
    let mut n = (mf.abs() / std::f64::consts::FRAC_PI_2).round() as u64;
    let mut reduced = None;
    for _ in 0..4 {
        let a = multiple::<L>(&tab.half_pi, n);
        let (d, u_negative) = abs_diff::<L>(&ym, &a);
        match below_one::<L>(&d) {
            Some(x) => {
                reduced = Some((x, u_negative));
                break;
            }
            None if u_negative => n -= 1,
            None => n += 1,
        }
    }
    let (u, u_negative) = reduced?;
    let (k, s) = split(u, tab.trig_levels);
    let one = limbs::one::<L>();
    // sin s / s and cos s from the powers y^j, y = s^2, shared by both series:
    // C_j = y^j / (2j)!, S_j = C_j / (2j + 1); the signs alternate
    let y = limbs::mul(&s, &s);
    let mut pow = y;
    let zero = [0u64; L];
    let (mut sin_plus, mut sin_minus, mut cos_plus, mut cos_minus) = (one, zero, one, zero);
    for (j, term) in tab.trig_terms.iter().enumerate() {
        if j > 0 {
            pow = limbs::mul(&pow, &y);
        }
        let mut c = pow;
        for d in &term.factorial {
            c = limbs::div_small(&c, d);
        }
        let odd = j % 2 == 0; // the term of y^(j+1)
        if term.in_cos {
            if odd {
                cos_minus = limbs::add(&cos_minus, &c);
            } else {
                cos_plus = limbs::add(&cos_plus, &c);
            }
        }
        if let Some(d) = &term.sin_extra {
            let t = limbs::div_small(&c, d);
            if odd {
                sin_minus = limbs::add(&sin_minus, &t);
            } else {
                sin_plus = limbs::add(&sin_plus, &t);
            }
        }
    }
    let sin_s = limbs::mul(&s, &limbs::sub(&sin_plus, &sin_minus));
    let cos_s = limbs::sub(&cos_plus, &cos_minus);
    // rotate (sin s, cos s) by each level's angle, innermost (smallest) first
    let (mut sin_u, mut cos_u) = (sin_s, cos_s);
    for j in (0..tab.trig_levels).rev() {
        if k[j] == 0 {
            continue;
        }
        let (sk, ck) = (entry::<L>(&tab.sin[j], k[j]), entry::<L>(&tab.cos[j], k[j]));
        (sin_u, cos_u) = (
            limbs::add(&limbs::mul(&sk, &cos_u), &limbs::mul(&ck, &sin_u)),
            limbs::sub(&limbs::mul(&ck, &cos_u), &limbs::mul(&sk, &sin_u)),
        );
    }
    // t = +-u: sin t = -+ sin u, cos t = cos u; then the quadrant n mod 4, then m's sign
    let (mut sin_mag, mut sin_neg, mut cos_mag, mut cos_neg) = (sin_u, u_negative, cos_u, false);
    match n % 4 {
        0 => {}
        1 => {
            (sin_mag, sin_neg, cos_mag, cos_neg) = (cos_mag, cos_neg, sin_mag, !sin_neg);
        }
        2 => {
            (sin_neg, cos_neg) = (!sin_neg, !cos_neg);
        }
        _ => {
            (sin_mag, sin_neg, cos_mag, cos_neg) = (cos_mag, !cos_neg, sin_mag, sin_neg);
        }
    }
    if m.is_sign_negative() {
        sin_neg = !sin_neg;
    }
    Some((sin_mag, sin_neg, cos_mag, cos_neg))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Whether `[y +- e]` contains `v`, `v` computed by MPFR at 1200 bits.
    fn encloses(y: &Float, e: Mag, v: &Float) -> bool {
        let d = Float::with_val(1200, v - y).abs();
        d <= e.to_float()
    }

    fn points() -> Vec<Float> {
        let mut s: u64 = 0x2545F4914F6CDD1D;
        let mut pts = Vec::new();
        for i in 0..400 {
            s ^= s << 13;
            s ^= s >> 7;
            s ^= s << 17;
            let u = (s >> 11) as f64 / (1u64 << 53) as f64;
            // magnitudes from 2^-20 to 2^19.5, both signs
            let mag = (2f64).powf(-20.0 + 39.5 * u);
            let x = if i % 2 == 0 { mag } else { -mag };
            let mut f = Float::with_val(600, x);
            // extra low bits so that the midpoint fills its precision
            f += Float::with_val(600, x * 1e-17 * u);
            pts.push(f);
        }
        // the hard places: multiples of ln2 and pi/2 (t, u near 0 and near 1), 0.5
        for n in [1i32, 2, 3, 7, 100, 10_000, 200_000] {
            let ln2 = Float::with_val(600, rug::float::Constant::Log2) * n;
            let hp: Float = Float::with_val(600, rug::float::Constant::Pi) * n / 2;
            pts.extend([ln2.clone(), -ln2, hp.clone(), -hp]);
        }
        pts.push(Float::with_val(600, 0.5));
        pts
    }

    /// Builds every limb count's tables, so that the kernels serve from the first call
    /// (the lazy fill's first [`LAZY_CALLS`] calls would otherwise go to MPFR).
    fn all_tables() {
        for l in 1..=MAX_LIMBS {
            exp_tables(l);
            trig_tables(l);
        }
    }

    #[test]
    fn the_tables_are_built_after_the_lazy_calls() {
        let (tables, calls) = (OnceLock::<u8>::new(), AtomicU32::new(0));
        let answered: Vec<bool> = (0..LAZY_CALLS + 2).map(|_| tables_ready(&tables, &calls)).collect();
        assert!(answered[..LAZY_CALLS as usize].iter().all(|&r| !r), "the first LAZY_CALLS go to MPFR");
        assert!(answered[LAZY_CALLS as usize..].iter().all(|&r| r), "then the kernel serves");
        // tables that exist serve at once, without counting
        let (built, fresh) = (OnceLock::from(1u8), AtomicU32::new(0));
        assert!(tables_ready(&built, &fresh));
        assert_eq!(fresh.load(AtomicOrdering::Relaxed), 0);
    }

    #[test]
    fn exp_and_sin_cos_enclose_at_every_limb_count() {
        all_tables();
        let mut served = 0;
        for wp in [24u32, 53, 64, 84, 100, 128, 200, 333, 353, 400, 486] {
            for x in points() {
                let m = Float::with_val(wp, &x);
                if let Some((y, e)) = exp(&m, wp) {
                    served += 1;
                    let v = Float::with_val(1200, m.exp_ref());
                    assert!(encloses(&y, e, &v), "exp {m} at {wp}: {y} +- {e:?}");
                    // the bound is within a few ulps of wp
                    assert!(e.le(&Mag::from_float_up(&y).mul(Mag::pow2(2 - wp as i64))), "exp {m} at {wp}: radius {e:?} too wide");
                }
                if let Some(((ys, es), (yc, ec))) = sin_cos(&m, wp) {
                    served += 1;
                    let (vs, vc) = Float::with_val(1200, &m).sin_cos(Float::new(1200));
                    assert!(encloses(&ys, es, &vs), "sin {m} at {wp}: {ys} +- {es:?}");
                    assert_eq!(sin(&m, wp), Some((ys.clone(), es)), "sin alone at {m}");
                    assert!(encloses(&yc, ec, &vc), "cos {m} at {wp}: {yc} +- {ec:?}");
                    assert!(es.le(&Mag::from_float_up(&ys).mul(Mag::pow2(2 - wp as i64))), "sin {m} at {wp}: radius too wide");
                    assert!(ec.le(&Mag::from_float_up(&yc).mul(Mag::pow2(2 - wp as i64))), "cos {m} at {wp}: radius too wide");
                }
            }
        }
        // most points are served by the kernels (not all left to MPFR)
        assert!(served > 8000, "served {served}");
    }

    /// `X 2^e` (negated when `neg`) as an exact float.
    fn exact<const L: usize>(x: &[u64; L], e: i64, neg: bool) -> Float {
        let i = rug::Integer::from_digits(x, rug::integer::Order::Lsf);
        let v = Float::with_val(64 * L as u32 + 8, i) << e as i32;
        if neg {
            -v
        } else {
            v
        }
    }

    /// The fixed-point results before rounding to `wp`, against the ulp bounds of the
    /// module docs; and the largest error seen, in ulps, so that a bound that could
    /// not fail is noticed (it must stay within a factor 8 of the bound).
    fn raw_errors<const L: usize>() -> (f64, f64) {
        let f = 64 * L as i64 - 2;
        let (mut worst_exp, mut worst_trig) = (0f64, 0f64);
        for x in points() {
            let m = Float::with_val(64 * L as u32, &x);
            let ulps = |d: Float, e: i64| (d.abs() >> e as i32).to_f64();
            if let Some((v, n)) = exp_fixed::<L>(&m) {
                let d = Float::with_val(1500, m.exp_ref()) - exact(&v, n - f, false);
                let u = ulps(d, n - f);
                assert!(u <= EXP_ULPS, "exp {m}, L = {L}: {u} ulps");
                worst_exp = worst_exp.max(u);
            }
            if let Some((sm, sn, cm, cn)) = sin_cos_fixed::<L>(&m) {
                let (vs, vc) = Float::with_val(1500, &m).sin_cos(Float::new(1500));
                let us = ulps(vs - exact(&sm, -f, sn), -f);
                let uc = ulps(vc - exact(&cm, -f, cn), -f);
                let b = trig_tables(L).trig_ulps;
                assert!(us <= b && uc <= b, "sin/cos {m}, L = {L}: {us}, {uc} ulps of {b}");
                worst_trig = worst_trig.max(us).max(uc);
            }
        }
        (worst_exp, worst_trig)
    }

    #[test]
    fn fixed_point_results_are_within_their_ulp_bounds() {
        for l in 1..=MAX_LIMBS {
            let b = trig_tables(l).trig_ulps;
            eprintln!("L = {l}: trig levels {}, terms {}, bound {b} ulps", trig_tables(l).trig_levels, trig_tables(l).trig_terms.len());
            assert!(b <= 64.0, "the sine/cosine bound {b} ulps at L = {l} exceeds the 64 the guard bits allow for");
        }
        for (we, wt) in [raw_errors::<1>(), raw_errors::<2>(), raw_errors::<3>(), raw_errors::<6>(), raw_errors::<8>()] {
            eprintln!("worst: exp {we:.2} ulps, sin/cos {wt:.2} ulps");
            assert!(we > EXP_ULPS / 16.0 && wt > 1.0, "worst errors {we}, {wt} ulps: the bounds are far too loose");
        }
    }

    /// Every table entry is the floor of its value times `2^F` or one unit below or
    /// above (the 2 ulps the bounds count), against one MPFR call per entry at 1500 bits;
    /// the constants are exact floors.
    #[test]
    fn table_entries_are_within_one_unit_of_their_floors() {
        let floor_of = |v: Float, shift: i64, len: usize| -> rug::Integer {
            let i = (v << shift as i32).floor().to_integer().unwrap();
            assert!(i.significant_bits() as usize <= 64 * len);
            i
        };
        for l in 1..=MAX_LIMBS {
            let f = 64 * l as i64 - 2;
            let (et, tt) = (exp_tables(l), trig_tables(l));
            let digits = |x: &[u64]| rug::Integer::from_digits(x, rug::integer::Order::Lsf);
            for (j, level) in et.exp.iter().enumerate() {
                for k in 0..TAB_LEN {
                    let a = Float::with_val(1500, k) >> (TAB_BITS * (j as u32 + 1));
                    let want = floor_of(Float::with_val(1500, a.exp_ref()), f, l);
                    let diff = (digits(&level[k * l..(k + 1) * l]) - want).abs();
                    assert!(diff <= 1, "exp L = {l} level {} k = {k}: {diff}", j + 1);
                }
            }
            for (j, (sl, cl)) in tt.sin.iter().zip(&tt.cos).enumerate() {
                for k in 0..TAB_LEN {
                    let a = Float::with_val(1500, k) >> (TAB_BITS * (j as u32 + 1));
                    let (sv, cv) = a.sin_cos(Float::new(1500));
                    for (tab, v, what) in [(sl, sv, "sin"), (cl, cv, "cos")] {
                        let diff = (digits(&tab[k * l..(k + 1) * l]) - floor_of(v, f, l)).abs();
                        assert!(diff <= 1, "{what} L = {l} level {} k = {k}: {diff}", j + 1);
                    }
                }
            }
            assert_eq!(digits(&et.ln2), floor_of(Float::with_val(1500, rug::float::Constant::Log2), f + 64, l + 1));
            assert_eq!(digits(&tt.half_pi), floor_of(Float::with_val(1500, rug::float::Constant::Pi) >> 1, f + 64, l + 1));
        }
    }

    #[test]
    fn outside_the_region_the_caller_is_told_to_use_mpfr() {
        all_tables();
        assert!(exp(&Float::with_val(64, 1e7), 64).is_none());
        // exp past the Horner kernels goes to wide.rs up to its limit, sin_cos to MPFR
        assert!(exp(&Float::with_val(4601, 1), 4601).is_none());
        assert!(exp(&Float::with_val(600, 1), 600).is_some());
        assert!(sin_cos(&Float::with_val(600, 1), 600).is_none());
        assert!(sin_cos(&Float::with_val(64, 1e-9), 64).is_none());
        assert!(sin_cos(&Float::with_val(64, rug::float::Special::Nan), 64).is_none());
        // sin of pi to 64 bits is about 5e-20: too small for an absolute bound
        assert!(sin_cos(&Float::with_val(64, rug::float::Constant::Pi), 64).is_none());
        assert_eq!(exp(&Float::with_val(64, 0), 64).map(|(y, _)| y), Some(Float::with_val(64, 1)));
    }
}
