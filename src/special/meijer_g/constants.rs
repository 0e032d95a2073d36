//! The `k`-dependent constants of `G(k, .)` ([`MeijerConstants`]): `C_k`,
//! `psi(k+2) - psi(k+1/2)` and `B_k(1)`, by MPFR's gamma and digamma or by the
//! exact recurrences in `k` [DLMF 5.5.1, 5.5.2], with a process-wide table.
//!
//! Accuracy: every constant is a ball that encloses the true value (MPFR's
//! correctly rounded gamma/digamma widened by the ball operations; the table's
//! balls rounded to `wp` add the rounding to the radius).

use rug::Float;

use crate::ball::Ball;
use crate::error::Result;

/// Largest `k` of [`MeijerConstants::cached`]'s table.
const CACHED_K_MAX: u32 = 1000;

/// Largest `k` that [`MeijerConstants::new`] reaches by the recurrences from
/// `k = 0` (each step a few ball operations at the working precision; MPFR's
/// first gamma at 3 200 bits alone costs as much as a few thousand steps).
pub const RECURRENCE_K_MAX: u32 = 1024;

/// MPFR's gamma and digamma calls of [`MeijerConstants::new`] beyond
/// [`RECURRENCE_K_MAX`] (two gammas, three digammas), in units of one first
/// gamma's estimated time (`gamma_seconds`): the estimate that refuses them.
const MPFR_CONSTANTS_GAMMAS: f64 = 3.0;

/// Working precision of [`MeijerConstants::cached`]'s table (`wp <= CACHED_PREC - 32` uses it).
const CACHED_PREC: u32 = 192;

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
    pub(super) k: u32,
    pub(super) c_k: Ball,
    pub(super) psi_diff: Ball,
    pub(super) bracket_at_one: Ball,
}

impl MeijerConstants {
    /// The constants for `k` at working precision `wp`.
    ///
    /// Up to `RECURRENCE_K_MAX` (1024) from their closed forms at `k = 0`
    /// (`C_0 = 2 sqrt(pi)`, `psi(2) - psi(1/2) = 1 + 2 ln 2` [DLMF 5.4.13, 5.4.14],
    /// `B_0(1) = 1`) and [`MeijerConstants::next`]: no Gamma or digamma at all.
    /// MPFR's gamma and digamma at the working precision of the wave series'
    /// cancellation guard (3 200 bits at `D = 2 pi 10^4 / 29.4`) ran before any
    /// budget check and took 0.15 s of a 0.1 s budget (issue 37's scan). Beyond,
    /// MPFR's gamma and digamma, refused at once with [`crate::Error::TooExpensive`]
    /// when their estimated time passes the call's budget.
    pub fn new(k: u32, wp: u32) -> Result<Self> {
        crate::error::check_working_prec(wp)?;
        if k <= RECURRENCE_K_MAX {
            let ln2 = Ball::ln2(wp);
            let mut c = MeijerConstants {
                k: 0,
                c_k: Ball::pi(wp).sqrt()?.mul_pow2(1),
                psi_diff: ln2.mul_pow2(1).add_i64(1),
                bracket_at_one: Ball::one(wp),
            };
            for _ in 0..k {
                c = c.next()?;
            }
            return Ok(c);
        }
        crate::budget::check_estimate(
            "the Meijer-G constants (MPFR's Gamma and digamma at the working precision)",
            MPFR_CONSTANTS_GAMMAS * crate::special::gamma::gamma_seconds(wp),
            f64::INFINITY,
        )?;
        let kf = Float::with_val(64, k);
        let half = Ball::from_float(&Float::with_val(64, &kf + 0.5), wp);
        let two = Ball::from_float(&Float::with_val(64, &kf + 2u32), wp);
        let c_k = half.gamma()?.div(&two.gamma()?)?.mul_pow2(1);
        let psi_half = half.digamma()?;
        let psi_diff = two.digamma()?.sub(&psi_half);
        let bracket_at_one = Ball::from_ratio(3, 2, wp).digamma()?.sub(&psi_half).mul_pow2(-1);
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
        crate::error::check_working_prec(wp)?;
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


#[cfg(test)]
mod tests {
    use super::*;
    use crate::error::Error;

    /// The closed forms at `k = 0` and the recurrences (`new` up to
    /// `RECURRENCE_K_MAX`) against MPFR's gamma and digamma at the same `k`.
    #[test]
    fn the_recurrence_from_the_closed_forms_matches_mpfr() {
        for wp in [64, 200, 1000] {
            for k in [0u32, 1, 2, 7, 100, RECURRENCE_K_MAX] {
                let c = MeijerConstants::new(k, wp).unwrap();
                let kf = Float::with_val(64, k);
                let half = Float::with_val(wp + 64, &kf + 0.5);
                let two = Float::with_val(wp + 64, &kf + 2u32);
                let c_k = Float::with_val(wp + 64, half.gamma_ref()) / Float::with_val(wp + 64, two.gamma_ref()) * 2u32;
                let psi_half = Float::with_val(wp + 64, half.digamma_ref());
                let psi_diff = Float::with_val(wp + 64, two.digamma_ref()) - &psi_half;
                let bracket = (Float::with_val(wp + 64, Float::with_val(wp + 64, 1.5).digamma_ref()) - &psi_half) / 2u32;
                for (ball, want, what) in [(&c.c_k, c_k, "C_k"), (&c.psi_diff, psi_diff, "psi diff"), (&c.bracket_at_one, bracket, "B_k(1)")] {
                    // MPFR's value at wp + 64 bits is within 2^-(wp+60) of the truth
                    let mut near = Ball::from_float(&want, wp + 64);
                    near.add_error(&(Float::with_val(64, want.abs_ref()) >> (wp + 60)));
                    assert!(ball.overlaps(&near), "{what} at k = {k}, {wp} bits: {ball:?} against {want}");
                    if k >= 2 || what != "B_k(1)" {
                        assert!(ball.meets_rel(wp - 16), "{what} at k = {k}, {wp} bits: {ball:?}");
                    }
                }
            }
        }
    }

    /// Beyond the recurrence, MPFR's gamma and digamma at 10^5 bits (about 20
    /// minutes for the first gamma) are refused by their estimate under a budget.
    #[test]
    fn mpfr_constants_past_the_budget_are_refused_at_once() {
        let r = crate::budget::Budget::from_millis(100).unwrap().run(|| MeijerConstants::new(RECURRENCE_K_MAX + 1, 100_000));
        assert!(matches!(r, Err(Error::TooExpensive { seconds, .. }) if seconds > 60.0), "{r:?}");
        // at 200 bits they answer, and agree with the recurrence one step further
        let mpfr = MeijerConstants::new(RECURRENCE_K_MAX + 1, 200).unwrap();
        let rec = MeijerConstants::new(RECURRENCE_K_MAX, 200).unwrap().next().unwrap();
        assert!(mpfr.c_k.overlaps(&rec.c_k) && mpfr.psi_diff.overlaps(&rec.psi_diff) && mpfr.bracket_at_one.overlaps(&rec.bracket_at_one));
    }
}
