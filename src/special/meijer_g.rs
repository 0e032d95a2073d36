//! The Eq. 12 Meijer-G family
//! `G(k, y) = Re G^{2,2}_{3,3}(-y | 0, 1/2-k, 1; 0, 0, -k-1)`, integer `k >= 0`,
//! `y in (0, 1]`, and a general `G^{2,2}_{3,3}` by Slater's theorem.
//!
//! # The closed form
//!
//! `z = -y` lies on the branch cut of `G` and `z = -1` (the contact edge
//! `x = a` in the seed's Eq. 12) is its singular point; the real part is still
//! finite there. With `C_k = 2 Gamma(k+1/2)/Gamma(k+2)` (docs/displacement.md, Route 1,
//! verified against mpmath's `meijerg`):
//!
//! ```text
//! G(k, y) = C_k B(y),
//! B(y)    = -ln(y)/2 - S(y)/2 + (psi(k+2) - psi(k+1/2))/2,
//! S(y)    = sum_{n>=1} (k+1/2)_n y^n / ((k+2)_n n)
//!         = ((k+1/2) y/(k+2)) 3F2(1, 1, k+3/2; 2, k+3; y).
//! ```
//!
//! `B` is the antiderivative the seed's D.41a states:
//! `dB/dy = -2F1(1, k+1/2; k+2; y) / (2y)` (a test checks this against
//! [`hyp2f1`](crate::special::hyp2f1)).
//!
//! # Value at the singular point
//!
//! `S(1) = psi(k+2) - psi(3/2)` by the Euler integral
//! `(b)_n/(c)_n = B(b+n, c-b)/B(b, c-b)` and `sum t^n/n = -ln(1-t)`
//! (this is Gauss-type summation of the 3F2), hence
//! `B(1) = (psi(3/2) - psi(k+1/2))/2`: `1` for `k = 0`, exactly `0` for `k = 1`,
//! and `-sum_{j=2}^{k} 1/(2j-1)` for `k >= 2`.
//!
//! # Regions (see [`choose_algorithm`])
//!
//! * **Direct** (`y <= 1/2`, or `k (1-y) > NEAR_ONE_MAX_KW`): the series `S(y)`
//!   through the pFq core; its term ratio is at most `y`, so the rigorous tail is
//!   geometric. Cost about `wp ln2 / (1-y)` terms.
//! * **NearOne** (`y > 1/2` and `k (1-y) <= NEAR_ONE_MAX_KW`): expansion in
//!   `w = 1 - y`. Integrating `dB/dy` from `y` to `1` and applying the `1-z`
//!   connection formula [DLMF 15.8.4] to `2F1(1, k+1/2; k+2; t)` (here
//!   `c-a-b = 1/2`, and one of the two pieces collapses to `t^{-k-1}`):
//!
//!   ```text
//!   2F1(1,k+1/2;k+2;t) = 2(k+1) 2F1(1,k+1/2;1/2;1-t) - K (1-t)^{1/2} t^{-k-1},
//!   K = 2 sqrt(pi) Gamma(k+2)/Gamma(k+1/2) = 4 sqrt(pi)/C_k,
//!   B(y) = B(1) + (k+1) I1(w) - (K/2) I2(w),
//!   I1(w) = sum_j h_j w^{j+1}/(j+1),        h_j = sum_{i<=j} r_i,  r_i = (k+1/2)_i/(1/2)_i,
//!   I2(w) = w^{3/2} sum_j c_j w^j/(j+3/2),   c_j = (k+2)_j / j!.
//!   ```
//!
//!   So `G(k,y) = C_k B(1) + C_k (k+1) I1(w) - 2 sqrt(pi) I2(w)`.
//!   **Tail bounds.** `r_i` increases, so `h_j <= (j+1) r_j` and the `I1` terms are
//!   at most `r_j w^{j+1}`, whose ratio `w (k+1/2+j)/(1/2+j)` decreases in `j`:
//!   from index `J` on, the tail is at most `r_J w^{J+1}/(1-rho)`,
//!   `rho = w (k+1/2+J)/(1/2+J)`. The `I2` term ratio is at most
//!   `w (k+2+j)/(j+1)`, also decreasing, giving `V_J/(1-rho')`.
//!   The two sums grow to about `(1-w)^{-k}` before they cancel, so this region
//!   is limited to `k w <= NEAR_ONE_MAX_KW` (at most ~58 bits of cancellation,
//!   which the Ziv loop adds as guard bits).
//!
//! # Accuracy
//!
//! * MP: certified, `rad <= 2^-prec |mid|` (`G(1, 1) = 0` is returned exactly).
//! * f64: the certified 64-bit value rounded (within 1 ulp; tolerance `1e-14`
//!   relative, absolute near the zero of `G(k, .)` for `k >= 2`).
//!
//! # Slater's theorem
//!
//! [`meijer_g33_slater_mp`] evaluates `G^{2,2}_{3,3}(z)` for `-1 < z < 0` in
//! non-degenerate position (`b1 - b2` not an integer) as the sum of two 3F2
//! series [DLMF 16.17.2]. The family above is degenerate (`b1 = b2 = 0`); tests
//! compare it with Slater's sum at slightly perturbed parameters.
//!
//! References: seed paper Eq. 12 and D.41a; DLMF 15.8.4, 16.17.2, 5.5.2 (psi
//! recurrence); docs/displacement.md, Route 1.

use rug::Float;

pub use crate::special::meijer_g_family::meijer_g_k_family_f64;

use crate::ball::{Ball, Bounded, Mag, MAG_PREC};
use crate::error::{Error, Result};
use crate::special::pfq::pfq_series;
use crate::special::{check_finite, exact, exact_add, exact_sub, f64_from_mp, ziv, DEFAULT_GUARD_BITS};

/// Largest `k` accepted.
pub const MAX_K: u32 = 1_000_000;

/// Largest `k` of [`MeijerConstants::cached`]'s table.
const CACHED_K_MAX: u32 = 1000;

/// Working precision of [`MeijerConstants::cached`]'s table (`wp <= CACHED_PREC - 32` uses it).
const CACHED_PREC: u32 = 192;

/// Upper limit of `k (1 - y)` for the near-one expansion: its two sums cancel
/// by about `(1-w)^{-k} ~ e^{k w}`, i.e. `1.44 k w` bits.
pub const NEAR_ONE_MAX_KW: f64 = 40.0;

/// The two algorithms.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Algorithm {
    /// `S(y)` summed directly.
    Direct,
    /// Expansion in `1 - y` around the singular point.
    NearOne,
    /// `y = 1`: the exact value `C_k B(1)`.
    AtOne,
}

/// Picks the algorithm for `G(k, y)`: near one where allowed (`y > 1/2`,
/// `k (1-y) <= NEAR_ONE_MAX_KW`) and cheaper by the term counts at about 100 bits:
/// direct `~ 70/(-ln y)` terms; near one `~ k w/(1-w) + 70/(-ln w)` terms at
/// `1.45 k w` extra bits. (Before the cost test, `k = 47`, `y = 0.52` went near one
/// with 33 extra bits and ~150 terms against ~110 direct terms: 0.9 ms at 64 bits.)
pub fn choose_algorithm(k: u32, y: f64) -> Algorithm {
    if y == 1.0 {
        return Algorithm::AtOne;
    }
    let w = 1.0 - y;
    let kw = (k as f64) * w;
    if !(y > 0.5 && kw <= NEAR_ONE_MAX_KW) {
        return Algorithm::Direct;
    }
    let bits = 70.0;
    let direct = bits / -y.ln();
    let near = (kw / y + bits / -w.ln()) * (1.0 + 1.45 * kw / 100.0);
    if near <= direct {
        Algorithm::NearOne
    } else {
        Algorithm::Direct
    }
}

fn validate(k: u32, y: &Float) -> Result<()> {
    check_finite(y, "y")?;
    if k > MAX_K {
        return Err(Error::IntegerOutOfRange { arg: "k", value: k as i64, min: 0, max: MAX_K as i64 });
    }
    if !(*y > 0 && *y <= 1) {
        return Err(Error::Domain { what: "meijer_g_k needs 0 < y <= 1 (y = (a/x)^2 with x >= a)".into() });
    }
    Ok(())
}

/// The `k`-dependent constants of `G(k, .)`: `C_k = 2 Gamma(k+1/2)/Gamma(k+2)`,
/// `psi(k+2) - psi(k+1/2)` and `B_k(1) = (psi(3/2) - psi(k+1/2))/2`.
///
/// [`MeijerConstants::new`] evaluates them with MPFR's correctly rounded gamma
/// and digamma; [`MeijerConstants::next`] steps `k -> k+1` with the exact
/// recurrences `C_{k+1} = C_k (k+1/2)/(k+2)` [DLMF 5.5.1],
/// `psi(x+1) = psi(x) + 1/x` [DLMF 5.5.2], so
/// `psi-diff_{k+1} = psi-diff_k + 1/(k+2) - 1/(k+1/2)` and
/// `B_{k+1}(1) = B_k(1) - 1/(2k+1)`: a sum over `k` pays for gamma/digamma once.
#[derive(Debug, Clone)]
pub struct MeijerConstants {
    k: u32,
    c_k: Ball,
    psi_diff: Ball,
    bracket_at_one: Ball,
}

impl MeijerConstants {
    /// The constants for `k` at working precision `wp`.
    pub fn new(k: u32, wp: u32) -> Result<Self> {
        crate::error::check_working_prec(wp)?;
        let kf = Float::with_val(64, k);
        let half = Ball::from_float(&Float::with_val(64, &kf + 0.5), wp);
        let two = Ball::from_float(&Float::with_val(64, &kf + 2u32), wp);
        let c_k = half.gamma()?.div(&two.gamma()?)?.mul_pow2(1);
        let psi_half = half.digamma()?;
        let psi_diff = two.digamma()?.sub(&psi_half);
        let bracket_at_one = match k {
            0 => Ball::one(wp),
            1 => Ball::zero(wp),
            _ => Ball::from_ratio(3, 2, wp).digamma()?.sub(&psi_half).mul_pow2(-1),
        };
        Ok(MeijerConstants { k, c_k, psi_diff, bracket_at_one })
    }

    /// The constants for `k` at working precision `wp`, from a process-wide table
    /// for `k <= CACHED_K_MAX` and `wp <= CACHED_PREC - 32` (built once, on first
    /// use, by the recurrences from `k = 0` at `CACHED_PREC` bits, about 2 ms), else
    /// [`MeijerConstants::new`]. MPFR's gamma and digamma cost 80-210 us at 100 bits,
    /// which dominated the f64 fallback of `meijer_g_k_bounded`. The table's balls
    /// enclose the constants; rounding to `wp` adds its error to the radius.
    pub fn cached(k: u32, wp: u32) -> Result<Self> {
        use std::sync::OnceLock;
        static TABLE: OnceLock<Option<Vec<MeijerConstants>>> = OnceLock::new();
        if k > CACHED_K_MAX || wp + 32 > CACHED_PREC {
            return MeijerConstants::new(k, wp);
        }
        let table = TABLE.get_or_init(|| {
            let mut c = MeijerConstants::new(0, CACHED_PREC).ok()?;
            let mut out = Vec::with_capacity(CACHED_K_MAX as usize + 1);
            for _ in 0..CACHED_K_MAX {
                let next = c.next().ok()?;
                out.push(c);
                c = next;
            }
            out.push(c);
            Some(out)
        });
        match table {
            Some(t) => {
                let c = &t[k as usize];
                Ok(MeijerConstants { k, c_k: c.c_k.set_prec(wp), psi_diff: c.psi_diff.set_prec(wp), bracket_at_one: c.bracket_at_one.set_prec(wp) })
            }
            None => MeijerConstants::new(k, wp),
        }
    }

    /// The constants for `k + 1`, by recurrence.
    pub fn next(&self) -> Result<Self> {
        let k = self.k as i64;
        let wp = self.c_k.prec();
        // (k + 1/2)/(k + 2) = (2k + 1)/(2k + 4)
        let c_k = self.c_k.mul_i64(2 * k + 1).div_i64(2 * k + 4)?;
        // 1/(k+2) - 1/(k+1/2) = 1/(k+2) - 2/(2k+1)
        let step = Ball::one(wp).div_i64(k + 2)?.sub(&Ball::from_i64(2, wp).div_i64(2 * k + 1)?);
        let psi_diff = self.psi_diff.add(&step);
        let bracket_at_one = self.bracket_at_one.sub(&Ball::one(wp).div_i64(2 * k + 1)?);
        Ok(MeijerConstants { k: self.k + 1, c_k, psi_diff, bracket_at_one })
    }

    /// `k`.
    pub fn k(&self) -> u32 {
        self.k
    }

    /// `(C_k, psi(k+2) - psi(k+1/2), B_k(1))`.
    pub(crate) fn parts(&self) -> (&Ball, &Ball, &Ball) {
        (&self.c_k, &self.psi_diff, &self.bracket_at_one)
    }
}

/// `G(k, y)` by the direct series at working precision `wp`.
pub fn meijer_g_k_direct(k: u32, y: &Float, wp: u32) -> Result<Ball> {
    crate::error::check_working_prec(wp)?;
    meijer_g_k_direct_ball(&MeijerConstants::cached(k, wp)?, &Ball::from_float(y, wp), wp)
}

/// `S(y) = sum_{n>=1} (b)_n y^n / ((c)_n n)`, `b = k+1/2`, `c = k+2`, with the tail
/// bound `sum_{n>=N} v_n <= (r_N/N) / (1 - y)`: `r_n = (b)_n y^n/(c)_n` has ratio
/// `y (b+n)/(c+n) <= y`.
fn direct_sum(k: u32, yb: &Ball, wp: u32) -> Result<Ball> {
    let y_up = yb.upper();
    if y_up >= 1 {
        return Err(Error::Domain { what: "the direct series needs y < 1".into() });
    }
    let b2 = 2 * k as i64 + 1; // 2b
    let c2 = 2 * k as i64 + 4; // 2c
    let mut r = Ball::one(wp);
    let mut sum = Ball::zero(wp);
    let one_minus_y = Mag::from_float_down(&Float::with_val(MAG_PREC, 1 - &y_up));
    let mut n: i64 = 0;
    loop {
        // r_{n+1} = r_n y (2b + 2n)/(2c + 2n)
        r = r.mul(yb).mul_i64(b2 + 2 * n).div_i64(c2 + 2 * n)?;
        n += 1;
        let v = r.div_i64(n)?;
        // tail from n on: (r_n/n)/(1-y)
        let tail = v.abs_upper_mag().div(one_minus_y);
        if tail.le(&sum.abs_lower_mag().mul_2exp(-(wp as i64) - 4)) {
            sum.add_error_mag(tail);
            return Ok(sum);
        }
        sum = sum.add(&v);
        if n > 100_000_000 {
            return Err(Error::NoConvergence { function: "meijer_g_k (direct)", terms: n as u64 });
        }
    }
}

/// `S_k(y)` for every `k = 0..=kmax` at once (`0 < y < 1`), for sums over `k`
/// such as Eq. 12.
///
/// With `b = k+1/2`, `c = k+2`, the Pochhammer ratios of consecutive `k` differ by
/// `u_n^(k) - u_n^(k+1) = -(3/2) n u_n^(k) / (b (c+n))`, which sums to
/// `S_{k+1} = S_k + (3/((2k+1)(k+2))) (H_k - 1)`, `H_k = 2F1(1, k+1/2; k+3; y)`, and
/// `H_k = 1 + ((2k+1)/(2k+6)) y H_{k+1}` [DLMF 15.5.11-type contiguity for `a = 1`].
/// `H` is run downward from its series at `kmax` (the recurrence contracts by `y`),
/// `S` upward from the direct `S_0` (positive increments): two series instead of
/// `kmax + 1`. All in balls; the tails are those of `direct_sum` and of the `H`
/// series (ratio `<= y`).
pub fn direct_sums_sweep(kmax: u32, yb: &Ball, wp: u32) -> Result<Vec<Ball>> {
    crate::error::check_working_prec(wp)?;
    let y_up = yb.upper();
    if y_up >= 1 {
        return Err(Error::Domain { what: "the direct series needs y < 1".into() });
    }
    let top = kmax as i64;
    // H_top = sum_n (b)_n/(c')_n y^n, b = top + 1/2, c' = top + 3: ratio y (2b + 2n)/(2c' + 2n)
    let one_minus_y = Mag::from_float_down(&Float::with_val(MAG_PREC, 1 - &y_up));
    let mut t = Ball::one(wp);
    let mut h_top = Ball::one(wp);
    let mut n: i64 = 0;
    loop {
        t = t.mul(yb).mul_i64(2 * top + 1 + 2 * n).div_i64(2 * top + 6 + 2 * n)?;
        n += 1;
        let tail = t.abs_upper_mag().div(one_minus_y);
        if tail.le(&h_top.abs_lower_mag().mul_2exp(-(wp as i64) - 4)) {
            h_top.add_error_mag(tail);
            break;
        }
        h_top = h_top.add(&t);
        if n > 100_000_000 {
            return Err(Error::NoConvergence { function: "meijer_g_k (sweep)", terms: n as u64 });
        }
    }
    sums_by_recurrence(direct_sum(0, yb, wp)?, h_top, kmax, yb)
}

/// The two recurrences of [`direct_sums_sweep`] from `S_0` and `H_kmax`.
fn sums_by_recurrence(s0: Ball, h_top: Ball, kmax: u32, yb: &Ball) -> Result<Vec<Ball>> {
    let top = kmax as i64;
    let wp = s0.prec();
    let mut h = vec![Ball::zero(wp); kmax as usize + 1];
    h[kmax as usize] = h_top;
    for k in (0..top).rev() {
        let next = h[k as usize + 1].mul(yb).mul_i64(2 * k + 1).div_i64(2 * k + 6)?;
        h[k as usize] = next.add_i64(1);
    }
    let mut out = Vec::with_capacity(kmax as usize + 1);
    out.push(s0);
    for k in 0..top {
        let inc = h[k as usize].add_i64(-1).mul_i64(3).div_i64((2 * k + 1) * (k + 2))?;
        let next = out[k as usize].add(&inc);
        out.push(next);
    }
    Ok(out)
}

/// [`direct_sums_sweep`] near `y = 1` (`w = 1 - y` small, `kmax w` moderate):
/// `S_0 = -ln y + psi(2) - psi(1/2) - 2 B_0(y)` from the near-one expansion of
/// `G(0, y)`, and `H_kmax` from the 1-z connection formula [DLMF 15.8.4]
/// (`c - a - b = 3/2`; the second piece collapses to a power):
/// `2F1(1, b; k+3; y) = (2(k+2)/3) 2F1(1, b; -1/2; w) + (8 sqrt(pi)/3) ((k+2)/C_k) w^{3/2} y^{-k-2}`,
/// `b = k+1/2`, with `Gamma(k+3)/Gamma(k+1/2) = 2(k+2)/C_k`. The series
/// `2F1(1, b; -1/2; w)` has term ratio `w (b+n)/(n-1/2)`, decreasing for `n >= 1`,
/// so its tail is geometric once that ratio is below 1.
pub fn near_one_sums_sweep(kmax: u32, w: &Ball, wp: u32) -> Result<Vec<Ball>> {
    crate::error::check_working_prec(wp)?;
    let w = if w.lower() < 0 { Ball::hull(&Float::new(wp), &w.upper(), wp) } else { w.clone() };
    if w.upper() > 0.5 {
        return Err(Error::Domain { what: "the near-one sweep needs 1 - y <= 1/2".into() });
    }
    let yb = Ball::one(wp).sub(&w);
    let c0 = MeijerConstants::new(0, wp)?;
    // S_0 from B_0 = G_0 / C_0
    let b0 = meijer_g_k_near_one_ball(&c0, &w, wp)?.div(&c0.c_k)?;
    let s0 = yb.ln()?.neg().add(&c0.psi_diff).sub(&b0.mul_pow2(1));
    // H_top by the connection formula
    let top = kmax as i64;
    let ct = MeijerConstants::new(kmax, wp)?;
    let w_up = w.abs_upper_mag();
    let one = Mag::from_f64(1.0);
    let mut t = Ball::one(wp);
    let mut f = Ball::one(wp);
    let mut n: i64 = 0;
    loop {
        // t_{n+1} = t_n w (b+n)/(n-1/2) = t_n w (2k+1+2n)/(2n-1)
        t = t.mul(&w).mul_i64(2 * top + 1 + 2 * n).div_i64(2 * n - 1)?;
        n += 1;
        let rho = w_up
            .mul(Mag::from_f64(((2 * top + 1 + 2 * n) as f64).next_up()))
            .div(Mag::from_f64(((2 * n - 1) as f64).next_down()));
        let one_minus = one.sub_lower(rho);
        if !one_minus.is_zero() {
            let tail = t.abs_upper_mag().div(one_minus);
            if tail.le(&f.abs_lower_mag().mul_2exp(-(wp as i64) - 4)) {
                f.add_error_mag(tail);
                break;
            }
        }
        f = f.add(&t);
        if n > 100_000_000 {
            return Err(Error::NoConvergence { function: "meijer_g_k (near-one sweep)", terms: n as u64 });
        }
    }
    let first = f.mul_i64(2 * (top + 2)).div_i64(3)?;
    let power = w.sqrt()?.mul(&w).div(&yb.pow_u64(kmax as u64 + 2))?;
    let second = Ball::pi(wp).sqrt()?.mul_i64(8 * (top + 2)).div_i64(3)?.div(&ct.c_k)?.mul(&power);
    let h_top = first.add(&second);
    sums_by_recurrence(s0, h_top, kmax, &yb)
}

/// `G(k, y)` from `S_k(y)` (e.g. from [`direct_sums_sweep`]) and the constants.
pub fn meijer_g_k_from_sum(consts: &MeijerConstants, ln_y: &Ball, s: &Ball) -> Ball {
    let bracket = ln_y.neg().sub(s).add(&consts.psi_diff).mul_pow2(-1);
    consts.c_k.mul(&bracket)
}

/// [`meijer_g_k_direct`] for an argument known only as a ball (`0 < y < 1`
/// over the whole ball): every operation is a ball operation, so the result
/// encloses `G(k, y)` for every `y` in the ball.
pub fn meijer_g_k_direct_ball(consts: &MeijerConstants, yb: &Ball, wp: u32) -> Result<Ball> {
    let s = direct_sum(consts.k, yb, wp)?;
    let bracket = yb.ln()?.neg().sub(&s).add(&consts.psi_diff).mul_pow2(-1);
    Ok(consts.c_k.mul(&bracket))
}

/// `G(k, y)` by the expansion in `w = 1 - y` at working precision `wp` (`y >= 1/2`).
pub fn meijer_g_k_near_one(k: u32, y: &Float, wp: u32) -> Result<Ball> {
    crate::error::check_working_prec(wp)?;
    if *y < 0.5 {
        return Err(Error::Domain { what: "the near-one expansion needs y >= 1/2".into() });
    }
    // w = 1 - y exactly.
    let w_exact = exact_sub(&Float::with_val(2, 1), y);
    meijer_g_k_near_one_ball(&MeijerConstants::cached(k, wp)?, &Ball::from_float(&w_exact, wp), wp)
}

/// [`meijer_g_k_near_one`] for `w = 1 - y` known only as a ball with
/// `0 <= w <= 1/2` (a lower end below zero is clipped: the true `w` is `>= 0`).
pub fn meijer_g_k_near_one_ball(consts: &MeijerConstants, w: &Ball, wp: u32) -> Result<Ball> {
    let k = consts.k;
    let w = if w.lower() < 0 { Ball::hull(&Float::new(wp), &w.upper(), wp) } else { w.clone() };
    if w.upper() > 0.5 {
        return Err(Error::Domain { what: "the near-one expansion needs 1 - y <= 1/2".into() });
    }
    let kw = (k as f64) * w.upper().to_f64();
    let kk = k as i64;
    let w_up = w.abs_upper_mag();
    let one = Mag::from_f64(1.0);
    // Integer ratios as Mag bounds (the integers are exact doubles).
    let ratio = |num: i64, den: i64| Mag::from_f64(num as f64).div(Mag::from_f64(den as f64));
    // I1 = sum_j h_j w^{j+1}/(j+1), r_{j+1} = r_j (2k+1+2j)/(1+2j)
    let mut r = Ball::one(wp); // r_j
    let mut h = Ball::one(wp); // h_j
    let mut wpow = w.clone(); // w^{j+1}
    let mut i1 = Ball::zero(wp);
    let mut j: i64 = 0;
    loop {
        i1 = i1.add(&h.mul(&wpow).div_i64(j + 1)?);
        r = r.mul_i64(2 * kk + 1 + 2 * j).div_i64(1 + 2 * j)?;
        h = h.add(&r);
        wpow = wpow.mul(&w);
        j += 1;
        // tail from index j <= r_j w^{j+1} / (1 - rho), rho = w (2k+1+2j)/(1+2j)
        if (j as f64) > kw {
            let rho = w_up.mul(ratio(2 * kk + 1 + 2 * j, 1 + 2 * j));
            let one_minus = one.sub_lower(rho);
            if !one_minus.is_zero() {
                let tail = r.abs_upper_mag().mul(wpow.abs_upper_mag()).div(one_minus);
                if tail.le(&i1.abs_upper_mag().mul_2exp(-(wp as i64) - 4)) {
                    i1.add_error_mag(tail);
                    break;
                }
            }
        }
        if j > 50_000_000 {
            return Err(Error::NoConvergence { function: "meijer_g_k (near one, I1)", terms: j as u64 });
        }
    }
    // I2 = w^{3/2} sum_j c_j w^j / (j + 3/2), c_{j+1} = c_j (k+2+j)/(j+1)
    let mut cj = Ball::one(wp);
    let mut wj = Ball::one(wp);
    let mut sum2 = Ball::zero(wp);
    let mut j: i64 = 0;
    loop {
        sum2 = sum2.add(&cj.mul(&wj).mul_pow2(1).div_i64(2 * j + 3)?);
        cj = cj.mul_i64(kk + 2 + j).div_i64(j + 1)?;
        wj = wj.mul(&w);
        j += 1;
        if (j as f64) > kw {
            // term ratio <= w (k+2+j)/(j+1), decreasing in j
            let rho = w_up.mul(ratio(kk + 2 + j, j + 1));
            let one_minus = one.sub_lower(rho);
            if !one_minus.is_zero() {
                let next = cj.abs_upper_mag().mul(wj.abs_upper_mag()).mul(ratio(2, 2 * j + 3));
                let tail = next.div(one_minus);
                if tail.le(&sum2.abs_upper_mag().mul_2exp(-(wp as i64) - 4)) {
                    sum2.add_error_mag(tail);
                    break;
                }
            }
        }
        if j > 50_000_000 {
            return Err(Error::NoConvergence { function: "meijer_g_k (near one, I2)", terms: j as u64 });
        }
    }
    let i2 = w.sqrt()?.mul(&w).mul(&sum2);
    let ck = &consts.c_k;
    let two_sqrt_pi = Ball::pi(wp).sqrt()?.mul_pow2(1);
    let at_one = ck.mul(&consts.bracket_at_one);
    Ok(at_one.add(&ck.mul_i64(kk + 1).mul(&i1)).sub(&two_sqrt_pi.mul(&i2)))
}

/// `G(k, 1) = C_k B(1)`.
pub fn meijer_g_k_at_one(k: u32, wp: u32) -> Result<Ball> {
    crate::error::check_working_prec(wp)?;
    Ok(meijer_g_k_at_one_with(&MeijerConstants::cached(k, wp)?))
}

/// `G(k, 1) = C_k B(1)` from precomputed constants.
pub fn meijer_g_k_at_one_with(consts: &MeijerConstants) -> Ball {
    consts.c_k.mul(&consts.bracket_at_one)
}

fn meijer_g_k_wp(k: u32, y: &Float, wp: u32) -> Result<Ball> {
    match choose_algorithm(k, y.to_f64()) {
        Algorithm::AtOne if *y == 1 => meijer_g_k_at_one(k, wp),
        Algorithm::AtOne | Algorithm::NearOne => meijer_g_k_near_one(k, y, wp),
        Algorithm::Direct => meijer_g_k_direct(k, y, wp),
    }
}

fn guard_bits(k: u32, y: f64) -> u32 {
    let w = 1.0 - y;
    let cancel = match choose_algorithm(k, y) {
        Algorithm::NearOne => 1.45 * (k as f64) * w,
        // psi(k+2) - psi(k+1/2) ~ 3/(2k) against psi ~ ln k.
        Algorithm::Direct => (1.0 + k as f64).log2() + 4.0,
        Algorithm::AtOne => 0.0,
    };
    DEFAULT_GUARD_BITS + cancel as u32
}

/// Certified `G(k, y)` with `rad <= 2^-prec |mid|`.
pub fn meijer_g_k_mp(k: u32, y: &Float, prec: u32) -> Result<Ball> {
    crate::error::check_prec(prec)?;
    validate(k, y)?;
    ziv("meijer_g_k", prec, guard_bits(k, y.to_f64()), |wp| meijer_g_k_wp(k, y, wp))
}

/// Certified `G(k, y)` over a ball of `y` (Arb's convention): the result
/// contains `G(k, t)` for every `t` in the ball.
///
/// **Argument.** The two sums ([`meijer_g_k_direct_ball`],
/// [`meijer_g_k_near_one_ball`]) run in ball
/// arithmetic on the ball `y` (or `w = 1 - y`), and their tail bounds use the
/// ball's upper end of `y` (resp. `|w|`), so they enclose the function over the
/// ball. `ln y` is a ball function. The edges are `y = 0` (the logarithmic
/// singularity) and `y > 1` (outside the domain, `x < a`): a ball that reaches
/// either is a typed error. A ball that reaches `y = 1` from below is summed by
/// the near-one expansion, which is valid on `0 <= w < 1`. An exact `y` gives
/// [`meijer_g_k_mp`]'s answer.
pub fn meijer_g_k_ball_mp(k: u32, y: &Ball, prec: u32) -> Result<Ball> {
    crate::error::check_prec(prec)?;
    if !y.is_finite() {
        return Err(Error::NonFinite { what: "y" });
    }
    if y.is_exact() {
        return meijer_g_k_mp(k, y.mid(), prec);
    }
    validate(k, y.mid())?;
    // y = 0 is G's logarithmic singularity; y > 1 is x < a
    y.check_within("y (= (a/x)^2)", crate::error::Interval::left_open(0.0, 1.0))?;
    let yf = y.to_f64();
    let near_one = matches!(choose_algorithm(k, yf), Algorithm::NearOne | Algorithm::AtOne);
    crate::special::ziv_ball_inputs(prec, guard_bits(k, yf.min(1.0 - f64::EPSILON)), None, |wp| {
        let consts = MeijerConstants::new(k, wp)?;
        let yb = y.set_prec(wp);
        if near_one {
            meijer_g_k_near_one_ball(&consts, &Ball::one(wp).sub(&yb), wp)
        } else {
            meijer_g_k_direct_ball(&consts, &yb, wp)
        }
    })
}

/// Largest relative bound the native f64 path may return (beyond it: MP).
pub const NATIVE_REL_TOL: f64 = 1e-14;

static NATIVE_FALLBACKS: std::sync::atomic::AtomicU64 = std::sync::atomic::AtomicU64::new(0);

/// How many [`meijer_g_k`] / [`meijer_g_k_bounded`] calls fell back to MP since
/// the process started (see [`crate::special::meijer_g_native`] for where).
pub fn meijer_g_k_fallbacks() -> u64 {
    NATIVE_FALLBACKS.load(std::sync::atomic::Ordering::Relaxed)
}

/// `G(k, y)` in f64: the native value where its proven bound is at most
/// [`NATIVE_REL_TOL`] relative, else the certified 64-bit value, rounded.
pub fn meijer_g_k(k: u32, y: f64) -> Result<f64> {
    crate::error::finite(y, "y")?;
    let ye = exact(y);
    validate(k, &ye)?;
    if let Some(b) = crate::special::meijer_g_native::meijer_g_k_native_bounded(k, y, NATIVE_REL_TOL) {
        return Ok(b.value);
    }
    NATIVE_FALLBACKS.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
    f64_from_mp("meijer_g_k", guard_bits(k, y), |wp| meijer_g_k_wp(k, &ye, wp))
}

/// `G(k, y)` in f64 with a proven error bound for the f64 `y` as given: native
/// ([`crate::special::meijer_g_native`]: f64 sums, double-double next to the
/// zero of `G(k, .)` and for `y > 0.97`) for `k <= 1000`; else the certified MP
/// value (counted by [`meijer_g_k_fallbacks`]): `k > 1000`, and the f64 `y`
/// closest to a zero of `G(k, .)` (`|G| <~ 1e-16`). The bound is relative there
/// too: natively `err <= 1e-14 |value|`, from MP about `2^-64 |value|` (the Ziv
/// loop raises the precision until the ball is relative; only an exact zero,
/// `G(1, 1) = 0`, returned as `0 +/- 0`, or an f64 `y` on a zero of `G`, which
/// none of the tested `k` has, would end in `Error::PrecisionExhausted`).
pub fn meijer_g_k_bounded(k: u32, y: f64) -> Result<Bounded> {
    crate::error::finite(y, "y")?;
    let ye = exact(y);
    validate(k, &ye)?;
    if let Some(b) = crate::special::meijer_g_native::meijer_g_k_native_bounded(k, y, NATIVE_REL_TOL) {
        return Ok(b);
    }
    NATIVE_FALLBACKS.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
    crate::special::bounded_from_mp("meijer_g_k", guard_bits(k, y), |wp| meijer_g_k_wp(k, &ye, wp))
}

/// Real and imaginary parts of `G^{2,2}_{3,3}(z | a1, a2, a3; b1, b2, b3)` for
/// `-1 < z < 0` by Slater's theorem [DLMF 16.17.2], at working precision `wp`.
///
/// Requires non-degenerate position: `b1 - b2` not an integer, and no Gamma
/// pole among `Gamma(1 + b_h - a_1), Gamma(1 + b_h - a_2)`. `z^{b_h}` is taken on
/// the principal branch, `(-y)^b = y^b e^{i pi b}` (mpmath's convention).
/// The parameters must be exactly representable (they are combined exactly).
pub fn meijer_g33_slater_mp(a: [f64; 3], b: [f64; 3], z: f64, wp: u32) -> Result<(Ball, Ball)> {
    for &v in a.iter().chain(b.iter()).chain(std::iter::once(&z)) {
        crate::error::finite(v, "Meijer G argument")?;
    }
    if !(z > -1.0 && z < 0.0) {
        return Err(Error::Domain { what: "Slater's sum is implemented for -1 < z < 0".into() });
    }
    let ae: Vec<Float> = a.iter().map(|&v| exact(v)).collect();
    let be: Vec<Float> = b.iter().map(|&v| exact(v)).collect();
    if exact_sub(&be[0], &be[1]).is_integer() {
        return Err(Error::Domain { what: "Slater's sum needs b1 - b2 not an integer (degenerate position)".into() });
    }
    let y = Ball::from_f64(-z, wp)?;
    let ln_y = y.ln()?;
    let one = Float::with_val(2, 1);
    let mut re = Ball::zero(wp);
    let mut im = Ball::zero(wp);
    for h in 0..2 {
        let other = 1 - h;
        let bh = &be[h];
        let g = |x: Float| Ball::from_float(&x, wp.max(x.prec())).gamma();
        let rg = |x: Float| Ball::from_float(&x, wp.max(x.prec())).rgamma();
        let one_plus_bh = exact_add(&one, bh);
        let coef = g(exact_sub(&be[other], bh))?
            .mul(&g(exact_sub(&one_plus_bh, &ae[0]))?)
            .mul(&g(exact_sub(&one_plus_bh, &ae[1]))?)
            .mul(&rg(exact_sub(&one_plus_bh, &be[2]))?)
            .mul(&rg(exact_sub(&ae[2], bh))?)
            .set_prec(wp);
        let num: Vec<Ball> = (0..3).map(|i| Ball::from_float(&exact_sub(&one_plus_bh, &ae[i]), wp)).collect();
        let den: Vec<Ball> = vec![
            Ball::from_float(&exact_sub(&one_plus_bh, &be[other]), wp),
            Ball::from_float(&exact_sub(&one_plus_bh, &be[2]), wp),
        ];
        // argument (-1)^{p-m-n} z = -z = y
        let f = pfq_series(&num, &den, &y, wp)?.sum;
        let bh_ball = Ball::from_float(bh, wp);
        let ypow = ln_y.mul(&bh_ball).exp()?;
        let (s, c) = Ball::pi(wp).mul(&bh_ball).sin_cos();
        let common = coef.mul(&ypow).mul(&f);
        re = re.add(&common.mul(&c));
        im = im.add(&common.mul(&s));
    }
    Ok((re, im))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn value_at_one_is_closed_form() {
        // G(0,1) = 2 sqrt(pi), G(1,1) = 0 exactly.
        let g0 = meijer_g_k_mp(0, &exact(1.0), 128).unwrap();
        let two_sqrt_pi = Float::with_val(300, rug::float::Constant::Pi).sqrt() * 2u32;
        assert!(g0.contains(&two_sqrt_pi));
        let g1 = meijer_g_k_mp(1, &exact(1.0), 128).unwrap();
        assert!(g1.mid().is_zero() && g1.is_exact());
    }

    #[test]
    fn cached_constants_enclose_the_direct_ones() {
        for k in [0u32, 1, 2, 47, 999, 1000, 1001] {
            for wp in [64u32, 128, 160, 200] {
                let (c, d) = (MeijerConstants::cached(k, wp).unwrap(), MeijerConstants::new(k, 300).unwrap());
                for (x, y) in [(c.parts().0, d.parts().0), (c.parts().1, d.parts().1), (c.parts().2, d.parts().2)] {
                    assert!(x.overlaps(y) && x.meets_rel(wp - 20).then_some(()).or(x.mid().is_zero().then_some(())).is_some(), "k={k} wp={wp}: {x:?} vs {y:?}");
                }
            }
        }
    }

    #[test]
    fn regions_overlap() {
        for &(k, y) in &[(0u32, 0.75), (3, 0.6), (20, 0.9), (200, 0.95)] {
            let ye = exact(y);
            let d = meijer_g_k_direct(k, &ye, 200).unwrap();
            let n = meijer_g_k_near_one(k, &ye, 200).unwrap();
            assert!(d.overlaps(&n), "k={k} y={y}: {d:?} vs {n:?}");
            assert!(d.meets_rel(100) && n.meets_rel(100));
        }
    }

    #[test]
    fn near_one_approaches_value_at_one() {
        let y = exact(1.0 - 1e-12);
        for k in [0u32, 1, 2, 7, 1000] {
            let g = meijer_g_k_mp(k, &y, 128).unwrap();
            let g1 = meijer_g_k_mp(k, &exact(1.0), 128).unwrap();
            // |G(k,y) - G(k,1)| = O(sqrt(1-y)) (the I2 term), tiny here.
            let d = g.sub(&g1).abs_upper().to_f64();
            assert!(d < 1e-4, "k={k}: {d}");
        }
    }

    #[test]
    fn near_one_sweep_matches_the_per_k_expansion() {
        let wp = 160;
        for &w in &[0.001, 1e-6, 0.0625] {
            let wb = Ball::from_f64(w, wp).unwrap();
            let y = Ball::one(wp).sub(&wb);
            let ln_y = y.ln().unwrap();
            let sums = near_one_sums_sweep(60, &wb, wp).unwrap();
            let mut c = MeijerConstants::new(0, wp).unwrap();
            for k in 0..=60u32 {
                let per_k = meijer_g_k_near_one_ball(&c, &wb, wp).unwrap();
                let swept = meijer_g_k_from_sum(&c, &ln_y, &sums[k as usize]);
                assert!(swept.overlaps(&per_k), "w={w} k={k}: {swept:?} vs {per_k:?}");
                // absolute accuracy (G(1, y) is O(sqrt(w)) while S_1 is O(1))
                assert!(swept.rad().to_f64() < 1e-35, "w={w} k={k}: {swept:?}");
                c = c.next().unwrap();
            }
        }
    }

    #[test]
    fn sweep_matches_direct_sums() {
        let wp = 160;
        for &y in &[0.01, 0.25, 0.5, 0.875] {
            let yb = Ball::from_f64(y, wp).unwrap();
            let sweep = direct_sums_sweep(120, &yb, wp).unwrap();
            for k in [0u32, 1, 5, 37, 120] {
                let d = direct_sum(k, &yb, wp).unwrap();
                assert!(sweep[k as usize].overlaps(&d), "y={y} k={k}");
                assert!(sweep[k as usize].meets_rel(wp - 20), "y={y} k={k}: {:?}", sweep[k as usize]);
            }
        }
    }

    #[test]
    fn bad_input() {
        assert!(meijer_g_k(1, 0.0).is_err());
        assert!(meijer_g_k(1, 1.5).is_err());
        assert!(meijer_g_k(1, f64::NAN).is_err());
        assert!(meijer_g_k_mp(1, &exact(0.5), 0).is_err());
    }
}
