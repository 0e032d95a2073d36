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
//! * f64: for `k <= 1000` native with a proven bound of at most `1e-14` relative
//!   (`native.rs`; next to the zero of `G(k, .)`, `k >= 2`, the Taylor route of
//!   `zero_taylor.rs`), else the certified 64-bit value rounded (within 1 ulp).
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

mod beta_series;
mod beta_series_dd;
mod constants;
pub(crate) mod dd;
mod direct;
mod elementary;
pub(crate) mod family;
pub(crate) mod native;
pub use native::{NEAR_ONE_F64_MAX_KW, NEAR_ONE_F64_MIN_Y, TABLE_K_MAX};
mod near_one;
mod near_one_fast;
mod slater;
mod zero_taylor;

pub use constants::MeijerConstants;
pub use direct::{direct_sums_sweep, meijer_g_k_direct, meijer_g_k_direct_ball, meijer_g_k_from_sum};
pub use family::meijer_g_k_family_f64;
pub use near_one::{meijer_g_k_at_one, meijer_g_k_at_one_with, meijer_g_k_near_one, meijer_g_k_near_one_ball, near_one_sums_sweep};
pub use slater::meijer_g33_slater_mp;

use crate::ball::{Ball, Bounded};
use crate::error::{Error, Interval, Result};
use crate::special::{check_finite, exact, f64_from_mp, ziv, DEFAULT_GUARD_BITS};

/// Largest `k` accepted.
pub const MAX_K: u32 = 1_000_000;

/// Largest `y < 1` of the native f64 series (about `ln(2^-60)/ln(y) = 1300` terms at 0.97);
/// above it the double-double near-one expansion runs (`native.rs`, `dd.rs`).
pub const Y_NATIVE_MAX: f64 = 0.97;

/// Upper limit of `k (1 - y)` for the near-one expansion: its two sums cancel
/// by about `(1-w)^{-k} ~ e^{k w}`, i.e. `1.44 k w` bits.
pub const NEAR_ONE_MAX_KW: f64 = 40.0;

/// The two algorithms.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[non_exhaustive]
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
    validate_k(k)?;
    if !(*y > 0 && *y <= 1) {
        return Err(y_out_of_range(y.to_f64()));
    }
    Ok(())
}

/// [`validate`] for an f64 `y` (no MPFR float: the native path's arguments are checked in f64).
fn validate_f64(k: u32, y: f64) -> Result<()> {
    crate::error::finite(y, "y")?;
    validate_k(k)?;
    if !(y > 0.0 && y <= 1.0) {
        return Err(y_out_of_range(y));
    }
    Ok(())
}

fn validate_k(k: u32) -> Result<()> {
    if k > MAX_K {
        return Err(Error::IntegerOutOfRange { arg: "k", value: k as i64, min: 0, max: MAX_K as i64 });
    }
    Ok(())
}

fn y_out_of_range(y: f64) -> Error {
    Error::OutOfRange { arg: "y (= (a/x)^2 with x >= a)", value: y, allowed: Interval::left_open(0.0, 1.0) }
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
        let yb = crate::special::input_ball(y, wp);
        if near_one {
            meijer_g_k_near_one_ball(&consts, &Ball::one(wp).sub(&yb), wp)
        } else {
            meijer_g_k_direct_ball(&consts, &yb, wp)
        }
    })
}

/// Largest relative bound the native f64 path may return (beyond it: MP).
pub const NATIVE_REL_TOL: f64 = 1e-14;


/// How many [`meijer_g_k`] / [`meijer_g_k_bounded`] calls fell back to MP since
/// the process started (see `native.rs` for where).
#[deprecated(note = "use `maugis::special::fallback_counts().meijer_g_k`: one snapshot of every counter")]
pub fn meijer_g_k_fallbacks() -> u64 {
    crate::special::fallback_counts().meijer_g_k
}

/// `G(k, y)` in f64: the native value where its proven bound is at most
/// [`NATIVE_REL_TOL`] relative, else the certified 64-bit value, rounded.
pub fn meijer_g_k(k: u32, y: f64) -> Result<f64> {
    validate_f64(k, y)?;
    if let Some(b) = native::meijer_g_k_native_bounded(k, y, NATIVE_REL_TOL) {
        return Ok(b.value);
    }
    let ye = exact(y);
    crate::special::fallback::count(crate::special::F64Route::MeijerGK);
    f64_from_mp("meijer_g_k", guard_bits(k, y), |wp| meijer_g_k_wp(k, &ye, wp))
}

/// The native f64 path of [`meijer_g_k_bounded`] alone: `Some` with a proven
/// bound where it certifies `err <= rel_tol |G|`, `None` where
/// [`meijer_g_k_bounded`] would fall back to MP (for solvers that count or avoid
/// the slow path). Errors: as [`meijer_g_k_bounded`] for `k` and `y`;
/// [`Error::OutOfRange`] for a `rel_tol` that is not positive and finite.
pub fn meijer_g_k_native_bounded(k: u32, y: f64, rel_tol: f64) -> Result<Option<Bounded>> {
    validate_f64(k, y)?;
    crate::special::check_rel_tol(rel_tol)?;
    Ok(native::meijer_g_k_native_bounded(k, y, rel_tol))
}

/// `G(k, y)` in f64 with a proven error bound for the f64 `y` as given: native
/// (`native.rs`: f64 sums, the Taylor series about the zero of `G(k, .)`, double-double
/// near it and for `y > 0.97`) for `k <= 1000`; else the certified MP
/// value (counted by [`crate::special::fallback_counts`]): `k > 1000`. The bound is
/// relative: natively `err <= 1e-14 |value|`, from MP about `2^-64 |value|` (the Ziv
/// loop raises the precision until the ball is relative; only an exact zero,
/// `G(1, 1) = 0`, returned as `0 +/- 0`, or an f64 `y` on a zero of `G`, which
/// none of the tested `k` has, would end in `Error::PrecisionExhausted`).
pub fn meijer_g_k_bounded(k: u32, y: f64) -> Result<Bounded> {
    // checked in f64: an MPFR float for y (about 350 instructions with its allocation, a
    // third of the Taylor route about the zero) only where MP answers
    validate_f64(k, y)?;
    if let Some(b) = native::meijer_g_k_native_bounded(k, y, NATIVE_REL_TOL) {
        return Ok(b);
    }
    let ye = exact(y);
    crate::special::fallback::count(crate::special::F64Route::MeijerGK);
    crate::special::bounded_from_mp("meijer_g_k", guard_bits(k, y), |wp| meijer_g_k_wp(k, &ye, wp))
}

#[cfg(test)]
mod tests {
    use super::*;
    use super::direct::direct_sum;

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

