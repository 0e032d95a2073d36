//! `exp` of a midpoint at working precisions from [`WIDE_MIN_PREC`] (487, where
//! [`super`]'s Horner kernels stop at 8 limbs) to [`WIDE_MAX_PREC`] bits (9 to 73
//! limbs), in fixed-point arithmetic on GMP's `mpn` layer with a rigorous error bound.
//! MPFR's `exp` costs about 2.5 times Arb's there (715 000 instructions a call at 3400
//! bits, most of a warm `e^(-x^2)` integral at 3333 bits); this one about 40% of
//! MPFR's from 490 to 4600 bits (through `CBall::exp`: 22 800 against 41 400
//! instructions at 490 bits, 249 000 against 578 000 at 3000).
//!
//! # Method
//!
//! Arb's `arb_exp` in its two-table range (F. Johansson, "Efficient implementation of
//! elementary functions in the medium-precision range", ARITH 22, 2015): table levels
//! as in [`super`], and the Taylor series by Smith's rectangular splitting, so that
//! about `2 sqrt N` of its `N` terms cost a full product and the rest a division by a
//! one-limb integer and an addition.
//!
//! A value is `X 2^-F`, `F = 64 L` fractional bits, `X` an unsigned integer of
//! `W = L + 1` limbs (values below `2^64`; all here are below 3). `L` is the least with
//! `F >= wp + 32`. A product is a short product (the partial products below the
//! result's last limb but two omitted, then the low `L` limbs dropped: the floor of
//! the exact product or one below it), a division by an integer is the floor, sums and
//! products by one-limb integers are exact. Every operation errs downward, a product by
//! less than two *ulps* `2^-F`, a division by less than one.
//!
//! 1. **Reduction.** `n = floor(m / ln 2)` (an f64 guess, corrected) and
//!    `t = m - n ln 2` in `[0, 1)`, in MPFR at `F + 96` bits (`ln 2` correctly rounded
//!    there, `|n| < 2^21`: `t` errs by less than `2^(22 - F - 96)`), then
//!    `T = floor(t 2^F)`: `|t - T 2^-F| < 1.01` ulps.
//! 2. **Tables.** `T 2^-F = k_1 2^-8 + k_2 2^-16 + ... + k_5 2^-40 + s`, `s < 2^-40`;
//!    `e^(k 2^(-8 j))` for `k < 256` and `j = 1, ..., 5` are tabulated per `L` at the first
//!    call (powers of the step in MPFR at `F + 40` bits, then the floor: off by at most
//!    one unit, as in [`super`]; counted as 2 ulps).
//! 3. **Taylor series** `e^s = sum_(k<=N) s^k / k!` with the least `N` whose tail
//!    `2 s^(N+1)/(N+1)!` is below one ulp. With `m = ceil(sqrt(N + 1))`, the powers
//!    `P_j = P_(j-1) S` (`P_1 = S` exact) and the blocks of `m` terms summed by
//!    Horner's rule over the powers (as in `special::bessel_j::series`):
//!    `R_i = P_0 + (P_1 + ... (P_(m-1) + P_m R_(i+1) / (im + m)) ... / (im + 2)) / (im + 1)`.
//!    The steps `acc <- acc / d + P` are taken in groups whose divisors' product `C`
//!    fits a limb: `acc <- floor((acc + P_a d_a + P_(a-1) d_a d_(a-1) + ...) / C)`, one
//!    division a group, the rest exact products by one limb and sums.
//!    Every operand is non-negative and every operation is monotone and rounds down,
//!    so each computed value lies below the exact one (the same recurrences in real
//!    arithmetic), and its deficit grows as follows: a power's by less than
//!    `2 / (1 - s) <= 2.0001` ulps in all; a group of `g` steps divides the deficit by
//!    `C >= 1` and adds less than `1 + 2.0001 g` (each `P`'s deficit enters times
//!    `C_j / C <= 1`, and the floor); the product by `P_m` multiplies the deficit by
//!    `s^m < 2^-40` and adds `R 2.0001 + 2 < 4.01` (`R_i <= e^s`). A block thus adds at
//!    most `4.01 + 3.0001 m` ulps, the earlier blocks' deficits shrunk by `2^-40`:
//!    with the tail, `e^s` errs by less than `a_0 = 3.01 m + 6` ulps.
//! 4. **Recombination.** `e^t = e^s prod_j e^(k_j 2^(-8 j))`, deepest level first: a
//!    product `V E` with `|V| <= v`, `|E| <= e` errs by at most `e a + 2 v + 2` ulps
//!    from `V`'s error `a` and the entry's 2. The bound is run in f64 with the bounds
//!    `e^(255 2^(-8 j))` (computed in f64 and raised by a factor `1 + 10^-9`), plus
//!    `e^t 1.01 < 2.75` ulps for the reduction, and rounded up with a 1% margin.
//! 5. **Result.** `e^m = 2^n e^t`, rounded to `wp` bits by MPFR from the integer (its
//!    ternary value gives the rounding error), the bound that error plus the ulps
//!    above, scaled by `2^(n - F)`.
//!
//! # Regions
//!
//! `None` (the caller uses MPFR) outside `WIDE_MIN_PREC <= wp <= WIDE_MAX_PREC`, for
//! `|m| >= 2^20` or a non-finite `m`, and on targets whose GMP limb is not 64 bits.

use std::sync::OnceLock;

use rug::Float;

use super::limbs::Divisor;
use super::raw_parts;
use super::Mag;

/// Least working precision served here.
pub(crate) const WIDE_MIN_PREC: u32 = super::MAX_FIXED_PREC + 1;
/// Largest working precision served here (Arb's two-table limit is 4600 bits).
pub(crate) const WIDE_MAX_PREC: u32 = 4600;
/// Guard bits of the format over the working precision.
const WIDE_GUARD: u32 = 32;
/// The most limbs `L` (`F = 64 L`).
const WIDE_MAX_LIMBS: usize = (WIDE_MAX_PREC + WIDE_GUARD).div_ceil(64) as usize;
/// Table levels and index bits per level (256 entries a level).
const LEVELS: usize = 5;
const TAB_BITS: u32 = 8;

/// The tables of one `L`.
struct WideTables {
    /// Level `j` (from 1): `floor(e^(k 2^(-8 j)) 2^F)` (or one unit off), `W` limbs per entry.
    exp: Vec<Vec<u64>>,
    /// `ln 2` at `F + 96` bits.
    ln2: Float,
    /// The Taylor order `N`.
    order: u64,
}

static TABLES: [OnceLock<WideTables>; WIDE_MAX_LIMBS + 1] = [const { OnceLock::new() }; WIDE_MAX_LIMBS + 1];

/// `floor(D 2^sh)` as exactly `n` little-endian limbs for the integer `D` of limbs `d`,
/// or `None` when it does not fit.
fn shifted(d: &[u64], sh: i64, n: usize) -> Option<Vec<u64>> {
    let top_pos = (d.len() as i64 - 1) * 64 + (64 - d[d.len() - 1].leading_zeros() as i64) + sh;
    if top_pos > 64 * n as i64 {
        return None;
    }
    let q = sh.div_euclid(64);
    let r = sh.rem_euclid(64) as u32;
    let limb = |k: i64| -> u64 { if k < 0 || k as usize >= d.len() { 0 } else { d[k as usize] } };
    Some(
        (0..n)
            .map(|i| {
                let k = i as i64 - q;
                if r == 0 { limb(k) } else { (limb(k) << r) | (limb(k - 1) >> (64 - r)) }
            })
            .collect(),
    )
}

/// `floor(v 2^f)` in `n` limbs for a finite `v >= 0` that fits (any `n`; also the
/// table entries of [`super`]).
pub(super) fn to_fixed(v: &Float, f: i64, n: usize) -> Option<Vec<u64>> {
    if v.is_zero() {
        return Some(vec![0; n]);
    }
    if !v.is_finite() || v.is_sign_negative() {
        return None;
    }
    // v = D 2^(e - 64 |d|), D the significand's limbs as an integer
    let (d, e) = raw_parts(v);
    shifted(d, e - 64 * d.len() as i64 + f, n)
}

fn tables(l: usize) -> &'static WideTables {
    TABLES[l].get_or_init(|| {
        let f = 64 * l as u32;
        let w = l + 1;
        // e^(k t) = e^((k-1) t) e^t in MPFR at f + 40 bits, then the floor (super's
        // levels at W >= 9 limbs)
        let exp = (1..=LEVELS as u32).map(|level| super::exp_level(f, level, w)).collect();
        let order = super::exp_order(f, TAB_BITS * LEVELS as u32);
        WideTables { exp, ln2: Float::with_val(f + 96, rug::float::Constant::Log2), order }
    })
}

/// The number of limbs `L` for a working precision, `None` outside the region.
fn limbs_for(wp: u32) -> Option<usize> {
    ((WIDE_MIN_PREC..=WIDE_MAX_PREC).contains(&wp) && cfg!(target_pointer_width = "64")).then(|| (wp + WIDE_GUARD).div_ceil(64) as usize)
}

/// `A B 2^-F` of two `W`-limb values (`W = L + 1`; the product below `2^64`) by a
/// short product: the partial products `a_i b_j` with `i + j <= W - 4` are omitted
/// (each below `2^(64 (W - 2))`, fewer than `W^2` of them: together below `2^-50`
/// units of the result, `2^(64 L)`), then the low `L` limbs are dropped. The result is
/// the floor of the exact product or one below it (never above). `acc` holds `2 W`
/// limbs of scratch.
fn mul_into(out: &mut [u64], a: &[u64], b: &[u64], acc: &mut [u64]) {
    let w = a.len();
    assert!(w >= 3 && b.len() == w && out.len() == w && acc.len() == 2 * w);
    // b's top zero limbs (the powers of s < 2^-40 have many) take no part
    let bl = b.iter().rposition(|&x| x != 0).map_or(0, |p| p + 1);
    acc.fill(0);
    for (i, &ai) in a.iter().enumerate() {
        let j0 = (w - 3).saturating_sub(i);
        if ai == 0 || j0 >= bl {
            continue;
        }
        // SAFETY: row i adds b[j0..bl] ai into acc[i + j0 .. i + bl] (within 2 W limbs;
        // acc and b are distinct borrows) and its carry limb goes to acc[i + bl], which
        // no earlier row has written.
        unsafe {
            let carry = gmp_mpfr_sys::gmp::mpn_addmul_1(acc.as_mut_ptr().add(i + j0), b.as_ptr().add(j0), (bl - j0) as _, ai);
            acc[i + bl] = carry;
        }
    }
    debug_assert_eq!(acc[2 * w - 1], 0);
    out.copy_from_slice(&acc[w - 1..2 * w - 1]);
}

/// `X <- X + Y c` for a one-limb `c`, `X` one limb longer than `Y` (the sum fits).
fn add_mul_small(x: &mut [u64], y: &[u64], c: u64) {
    let n = y.len();
    assert_eq!(x.len(), n + 1);
    // SAFETY: GMP adds y c into the first n limbs of x (distinct borrows) and returns
    // the carry limb
    let carry = unsafe { gmp_mpfr_sys::gmp::mpn_addmul_1(x.as_mut_ptr(), y.as_ptr(), n as _, c) };
    let (top, overflow) = x[n].overflowing_add(carry);
    x[n] = top;
    debug_assert!(!overflow);
}

/// `e^m` rounded to `wp` bits and a bound on its error; `None` outside the region
/// served (module docs).
pub(crate) fn exp(m: &Float, wp: u32) -> Option<(Float, Mag)> {
    let l = limbs_for(wp)?;
    if !m.is_finite() || m.get_exp().is_none_or(|e| e > 20) {
        return None;
    }
    if m.is_zero() {
        return Some((Float::with_val(wp, 1), Mag::ZERO));
    }
    let tab = tables(l);
    let f = 64 * l as u32;
    let w = l + 1;
    // 1. reduction: t = m - n ln 2 in [0, 1)
    let pr = tab.ln2.prec();
    let mut n = (m.to_f64() / std::f64::consts::LN_2).floor() as i64;
    let mut t = None;
    for _ in 0..4 {
        let nl = Float::with_val(pr, &tab.ln2 * n);
        let tv = Float::with_val(pr, m - &nl);
        if tv.is_sign_negative() && !tv.is_zero() {
            n -= 1;
        } else if tv >= 1 {
            n += 1;
        } else {
            t = Some(tv);
            break;
        }
    }
    let mut s = to_fixed(&t?, f as i64, w)?;
    // 2. the table indices: the top 24 fractional bits (limb L - 1; limb L is 0)
    let top = s[l - 1];
    let k: [usize; LEVELS] = std::array::from_fn(|j| ((top >> (56 - 8 * j)) & 0xff) as usize);
    s[l - 1] &= (1u64 << (64 - 8 * LEVELS)) - 1;
    // 3. e^s by rectangular splitting
    let terms = tab.order + 1;
    let mb = ((terms as f64).sqrt().ceil() as u64).max(1);
    let mut scratch = vec![0u64; 2 * w];
    let mut powers: Vec<Vec<u64>> = Vec::with_capacity(mb as usize + 1);
    let mut one = vec![0u64; w];
    one[l] = 1;
    powers.push(one);
    powers.push(s.clone());
    for j in 2..=mb as usize {
        let mut p = vec![0u64; w];
        mul_into(&mut p, &powers[j - 1], &s, &mut scratch);
        powers.push(p);
    }
    let blocks = terms.div_ceil(mb);
    let mut acc = vec![0u64; w];
    let mut tmp = vec![0u64; w];
    let mut wide = vec![0u64; w + 1];
    for i in (0..blocks).rev() {
        let lo = i * mb;
        let len = mb.min(terms - lo);
        if i + 1 < blocks {
            mul_into(&mut tmp, &acc, &powers[mb as usize], &mut scratch);
            std::mem::swap(&mut acc, &mut tmp);
        }
        // the steps j = len, ..., 1 (acc <- floor(acc / (lo + j)) + P_(j-1)) in groups
        // whose divisors' product C fits a limb: acc <- floor((acc + sum P_(j-1) C_j) / C),
        // C_j the product of the group's divisors down to j
        let mut j = len;
        while j >= 1 {
            wide[..w].copy_from_slice(&acc);
            wide[w] = 0;
            let mut c: u64 = 1;
            while j >= 1 {
                let Some(next) = c.checked_mul(lo + j) else { break };
                c = next;
                add_mul_small(&mut wide, &powers[j as usize - 1], c);
                j -= 1;
            }
            if c > 1 {
                let d = Divisor::new(c);
                d.div_slice_in_place(&mut wide);
            }
            debug_assert_eq!(wide[w], 0);
            acc.copy_from_slice(&wide[..w]);
        }
    }
    // 4. recombination, deepest level first, with the error bound in ulps
    let mut ulps = 3.01 * mb as f64 + 6.0;
    let mut v_bound = 1.0001;
    for j in (0..LEVELS).rev() {
        if k[j] != 0 {
            let e = &tab.exp[j][k[j] * w..(k[j] + 1) * w];
            mul_into(&mut tmp, &acc, e, &mut scratch);
            std::mem::swap(&mut acc, &mut tmp);
            // e^(255 2^(-8 (j + 1))), above by far more than the f64 rounding
            let e_bound = (255.0 * (2f64).powi(-8 * (j as i32 + 1))).exp() * (1.0 + 1e-9);
            ulps = e_bound * ulps + 2.0 * v_bound + 2.0;
            v_bound *= e_bound;
        }
    }
    let ulps = ((ulps + 2.75) * 1.01).ceil();
    // 5. e^m = 2^n e^t
    let scale = n - f as i64;
    let (y, ord) = super::to_float(&acc, scale, wp, false);
    if !y.is_finite() || y.is_zero() {
        return None;
    }
    let err = super::bound(&y, ord, ulps, scale);
    Some((y, err))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// At 487 to 4600 bits, over arguments from tiny to 2^19 of both signs and at the
    /// table boundaries, the ball `y +- err` contains `e^m` (MPFR's at 128 more bits,
    /// whose error is far below), and the error bound is at most `2^-(wp - 2)` relative.
    #[test]
    fn wide_exp_encloses_and_is_tight() {
        let pts: Vec<f64> = vec![1e-30, 1e-9, 0.25, 0.5, 0.693, 0.6931471805599453, 1.0, 1.5, 2.0, 3.999, 4.0, 10.5, 100.25, 524287.0, 255.0 / 256.0];
        for wp in [487u32, 488, 600, 1000, 1001, 1500, 2048, 3353, 3400, 4600] {
            for &x in &pts {
                for sign in [1.0, -1.0] {
                    // a midpoint with wp bits: x plus a tail of bits
                    let mut m = Float::with_val(wp, x * sign);
                    m += Float::with_val(wp, 1) / 3u32 * Float::with_val(wp, x * 1e-12);
                    let (y, err) = exp(&m, wp).expect("served");
                    let exact = Float::with_val(wp + 128, m.exp_ref());
                    let diff = Float::with_val(wp + 128, &exact - &y).abs();
                    assert!(diff <= err.to_float(), "wp={wp} m={x}: |diff| {diff:.3e} > {:.3e}", err.to_float());
                    let rel = Float::with_val(64, err.to_float() / &y);
                    assert!(rel <= Float::with_val(64, 1) >> (wp - 2), "wp={wp} m={x}: relative bound {rel:.3e}");
                }
            }
        }
        assert!(exp(&Float::with_val(486, 1.5), 486).is_none());
        assert!(exp(&Float::with_val(4601, 1.5), 4601).is_none());
        assert!(exp(&Float::with_val(2000, 2f64.powi(21)), 2000).is_none());
    }
}
