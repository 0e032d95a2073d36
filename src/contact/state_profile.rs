//! The profiles of one state sampled over the symmetric half `xbar >= 0`:
//! traction, substrate displacement, gap and rigid profile depth, as the
//! paper's Figs. 6, 8, 9, 10, 12 and 14 draw them, and `maugis profile` and
//! the Python `profile` print them.
//!
//! [`sample_state`] solves the state at contact half-width `abar`
//! ([`ContactSize::solve_strip`]) and samples it on a uniform grid over
//! `[0, xmax]`, with the contact edge `abar` and the strip end `m abar` added
//! when they lie in the range, so that the kinks of the profiles are drawn
//! where they are. [`sample_state_at`] samples at given positions instead, in
//! their order (in parallel for long inputs with the `parallel` feature).
//! [`StateProfile::certified_traction`] adds the traction at the samples as
//! certified balls.
//!
//! Errors are a [`LocatedError`]: the library's error and where it arose
//! (the arguments, the state, the certified strip ratio or one sample), so
//! that a front end words the context its own way.

use crate::ball::Ball;
use crate::contact::model::{ContactSize, Params, StripEnd, Validity};
use crate::contact::model_mp::solve_m_mp;
use crate::contact::traction_mp::traction_mp;
use crate::contact::located::{At, LocatedError};
use crate::error::{Error, Interval};

#[cfg(feature = "parallel")]
use rayon::prelude::*;

/// Inputs shorter than this are sampled on the calling thread (with the
/// `parallel` feature; without it, always).
pub const PARALLEL_MIN_SAMPLES: usize = 2048;

/// Largest number of grid points [`sample_state`] takes.
pub const MAX_SAMPLES: usize = 10_000_000;

/// One sample of a state's profiles (normalised: `x` by `l_h`; `u`, `g`, `h`
/// by `l_v`; the traction by the cohesive stress, tensile positive).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ProfileSample {
    /// Position `xbar >= 0`.
    pub xbar: f64,
    /// Traction `pbar` (Eq. 16 inside the contact, 1 in the strip, 0 beyond).
    pub pbar: f64,
    /// Substrate displacement `ubar` (positive downward, like the profile).
    pub ubar: f64,
    /// Gap `gbar = hbar - ubar` (0 in the contact).
    pub gbar: f64,
    /// Rigid profile depth `hbar` (Eq. 1).
    pub hbar: f64,
}

/// A state and its sampled profiles.
#[derive(Debug, Clone, PartialEq)]
pub struct StateProfile {
    /// The parameters.
    pub params: Params,
    /// Contact half-width.
    pub abar: f64,
    /// Strip ratio `m = c/a`.
    pub m: f64,
    /// Load `Lbar` (Eq. 14).
    pub load: f64,
    /// Validity of the state.
    pub validity: Validity,
    /// The samples: ascending in `xbar` from [`sample_state`], in the given
    /// order from [`sample_state_at`].
    pub samples: Vec<ProfileSample>,
}

impl StateProfile {
    /// The strip end `c = m abar`.
    pub fn strip_end(&self) -> f64 {
        self.m * self.abar
    }

    /// The traction at every sample as a certified ball at `prec` bits
    /// ([`traction_mp`], with the strip ratio certified by [`solve_m_mp`]), in
    /// the order of the samples.
    pub fn certified_traction(&self, prec: u32) -> Result<Vec<Ball>, LocatedError> {
        let (params, abar) = (self.params, self.abar);
        let m = solve_m_mp(params, abar, prec).map_err(|e| At::CertifiedStripRatio { abar }.wrap(e))?;
        self.samples
            .iter()
            .map(|s| traction_mp(params, abar, &m, s.xbar, prec).map_err(|e| At::Sample { xbar: s.xbar }.wrap(e)))
            .collect()
    }
}

/// The uniform grid of [`sample_state`]: `points` values `xmax i/(points-1)`,
/// plus `extra` positions inside `[0, xmax]`, sorted, without repeats.
fn grid(xmax: f64, points: usize, extra: [f64; 2]) -> Vec<f64> {
    let mut xs: Vec<f64> = (0..points).map(|i| xmax * i as f64 / (points - 1) as f64).collect();
    xs.extend(extra.into_iter().filter(|&x| x <= xmax));
    xs.sort_by(f64::total_cmp);
    xs.dedup();
    xs
}

/// A solved state: its contact size, strip solution, load and validity.
struct Solved {
    cs: ContactSize,
    strip: StripEnd,
    load: f64,
    validity: Validity,
}

fn solve(params: Params, abar: f64) -> Result<Solved, LocatedError> {
    let cs = ContactSize::new(params, abar).map_err(|e| At::Input.wrap(e))?;
    let state = |e| At::State { abar }.wrap(e);
    let strip = cs.solve_strip().map_err(state)?;
    let validity = cs.validity_at(strip).map_err(state)?;
    let load = cs.load_at(strip);
    Ok(Solved { cs, strip, load, validity })
}

impl Solved {
    fn sample(&self, x: f64) -> Result<ProfileSample, LocatedError> {
        let (cs, strip) = (&self.cs, self.strip);
        let at = |e| At::Sample { xbar: x }.wrap(e);
        let p = cs.params();
        Ok(ProfileSample {
            xbar: x,
            pbar: cs.traction_at(strip, x),
            ubar: cs.displacement_at(strip, x).map_err(at)?,
            gbar: cs.gap_at(strip, x).map_err(at)?,
            hbar: p.profile().depth(crate::error::finite(x, "x").map_err(at)?),
        })
    }

    fn sample_all(&self, xs: &[f64]) -> Result<Vec<ProfileSample>, LocatedError> {
        #[cfg(feature = "parallel")]
        if xs.len() >= PARALLEL_MIN_SAMPLES {
            return xs.par_iter().with_min_len(256).map(|&x| self.sample(x)).collect();
        }
        xs.iter().map(|&x| self.sample(x)).collect()
    }

    fn profile(self, samples: Vec<ProfileSample>) -> StateProfile {
        let m = self.strip.m();
        StateProfile { params: self.cs.params(), abar: self.cs.abar(), m, load: self.load, validity: self.validity, samples }
    }
}

/// Solves the state at `abar` and samples its profiles on `points` uniform
/// positions over `[0, xmax]` (`2 <= points <= MAX_SAMPLES`, `xmax > 0`;
/// `None`: `1.5 m abar`), plus the contact edge and the strip end where they
/// lie inside. Errors on bad input and where the model has no state.
pub fn sample_state(params: Params, abar: f64, xmax: Option<f64>, points: usize) -> Result<StateProfile, LocatedError> {
    if !(2..=MAX_SAMPLES).contains(&points) {
        let value = i64::try_from(points).unwrap_or(i64::MAX);
        return Err(At::Input.wrap(Error::IntegerOutOfRange { arg: "points", value, min: 2, max: MAX_SAMPLES as i64 }));
    }
    let s = solve(params, abar)?;
    let c = s.strip.m() * abar;
    let xmax = xmax.unwrap_or(1.5 * c);
    if let Err(e) = Interval::above(0.0).check("xmax", xmax).and_then(|x| crate::error::finite(x, "xmax")) {
        return Err(At::Input.wrap(e));
    }
    let samples = s.sample_all(&grid(xmax, points, [abar, c]))?;
    Ok(s.profile(samples))
}

/// Solves the state at `abar` and samples its profiles at the positions `xs`,
/// in their order (repeats and any order allowed; each must be finite).
pub fn sample_state_at(params: Params, abar: f64, xs: &[f64]) -> Result<StateProfile, LocatedError> {
    let s = solve(params, abar)?;
    let samples = s.sample_all(xs)?;
    Ok(s.profile(samples))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn fig4c() -> Params {
        Params::new(1.0, std::f64::consts::SQRT_2 / 4.0, 1.125).unwrap()
    }

    #[test]
    fn samples_meet_the_profile_in_the_contact_and_hold_the_edges() {
        let params = fig4c();
        let s = sample_state(params, 2.0, None, 50).unwrap();
        assert!(s.samples.iter().any(|p| p.xbar == 2.0));
        assert!(s.samples.iter().any(|p| p.xbar == s.strip_end()));
        assert!(s.samples.windows(2).all(|w| w[0].xbar < w[1].xbar));
        for p in s.samples.iter().filter(|p| p.xbar < 2.0) {
            assert!(p.gbar.abs() < 1e-9 * (1.0 + p.hbar.abs()), "{p:?}");
        }
        for p in s.samples.iter().filter(|p| p.xbar > 2.0 && p.xbar < s.strip_end()) {
            assert_eq!(p.pbar, 1.0);
        }
        assert!(matches!(sample_state(params, 2.0, None, 1), Err(LocatedError { at: At::Input, .. })));
        assert!(matches!(sample_state(params, 2.0, Some(f64::NAN), 10), Err(LocatedError { at: At::Input, .. })));
        assert!(matches!(sample_state(params, -1.0, None, 10), Err(LocatedError { at: At::Input, .. })));
    }

    #[test]
    fn given_positions_keep_their_order_and_match_the_grid() {
        let params = fig4c();
        let g = sample_state(params, 2.0, None, 40).unwrap();
        let xs: Vec<f64> = g.samples.iter().rev().map(|p| p.xbar).chain([0.5, 0.5]).collect();
        let s = sample_state_at(params, 2.0, &xs).unwrap();
        assert_eq!((s.m, s.load, s.validity), (g.m, g.load, g.validity));
        assert_eq!(s.samples.iter().map(|p| p.xbar).collect::<Vec<_>>(), xs);
        for (a, b) in s.samples.iter().rev().skip(2).zip(&g.samples) {
            assert_eq!(a, b);
        }
        // long inputs (parallel with the feature) give the same samples
        let long: Vec<f64> = (0..3000).map(|i| 3.0 * i as f64 / 2999.0).collect();
        let par = sample_state_at(params, 2.0, &long).unwrap();
        for (p, &x) in par.samples.iter().zip(&long) {
            assert_eq!(*p, sample_state_at(params, 2.0, &[x]).unwrap().samples[0]);
        }
        assert!(sample_state_at(params, 2.0, &[]).unwrap().samples.is_empty());
        match sample_state_at(params, 2.0, &[0.5, f64::NAN]) {
            Err(LocatedError { at: At::Sample { xbar }, .. }) => assert!(xbar.is_nan()),
            other => panic!("{other:?}"),
        }
    }

    #[test]
    fn certified_traction_encloses_the_f64_traction() {
        let s = sample_state(fig4c(), 2.0, None, 12).unwrap();
        let balls = s.certified_traction(80).unwrap();
        assert_eq!(balls.len(), s.samples.len());
        for (b, p) in balls.iter().zip(&s.samples) {
            let (mid, rad) = (b.mid().to_f64(), b.rad().to_f64());
            assert!((mid - p.pbar).abs() <= rad + 1e-9 * (1.0 + p.pbar.abs()), "{p:?}: {mid} +/- {rad}");
        }
        assert!(s.certified_traction(0).is_err());
    }
}
