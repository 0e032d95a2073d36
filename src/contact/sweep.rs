//! Regime maps: the load-area analysis over a grid of parameters (issue 9, item 4).
//!
//! A [`SweepGrid`] spans `lambda` on a logarithmic grid and a second parameter
//! on a linear grid: the amplitude `alpha`, the wavelength `beta`, or the
//! Johnson parameter `chi = sqrt(beta/alpha^2)` at fixed `beta`
//! (`alpha = sqrt(beta)/chi`), or the `amplitude` scale `s` of a profile of any
//! number of waves (docs/model.md "Many waves"): every amplitude `alpha_j` of the
//! grid's base profile times `s`, the wavelengths fixed, so that the profile keeps
//! its shape (for one wave `(alpha_1, beta)` this is the `alpha` axis at
//! `alpha = s alpha_1`). Each grid point is one [`load_area_curve`] run,
//! summarised by [`SweepPoint`]: the instabilities the loading path meets, the
//! dissipation under load control (split valid/invalid), pull-off, the valid
//! fraction of the states, and a [`Regime`]:
//!
//! * `dissipative`: some loop is valid (the waviness dissipates energy);
//! * `cavitating`: loops exist but every one passes through invalid states
//!   (the paper: cavitation removes the hysteresis);
//! * `smooth_like`: no loop beyond the pull-off cycle of a smooth cylinder,
//!   i.e. no loading jump from a turning point.
//!
//! Grid points are numbered `k = i_lambda * n_second + i_second`; shard `s` of
//! `n` (1-based) takes the points with `k % n == s - 1`, so shards are balanced
//! along both axes and [`merge`] reassembles them exactly.

#[cfg(feature = "parallel")]
use rayon::prelude::*;

use crate::contact::curve::{load_area_curve, CurveOptions};
use crate::contact::model::Params;
use crate::contact::paths::JumpDirection;
use crate::contact::profile::WavyProfile;
use crate::error::{finite, Error, Result, SweepError};

/// The second axis of a sweep.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
pub enum SweepAxis {
    /// Wave amplitude `alpha` (at fixed `beta`).
    Alpha,
    /// Wavelength `beta` (at fixed `alpha`).
    Beta,
    /// Johnson parameter `sqrt(beta/alpha^2)` (at fixed `beta`).
    Johnson,
    /// The scale `s` of every amplitude of the grid's base profile
    /// ([`SweepGrid::profile`]): wave `j` is `(s alpha_j, beta_j)`.
    Amplitude,
}

impl SweepAxis {
    /// The axis' name as the CLI and the JSON spell it: `"alpha"`, `"beta"` or `"johnson"`.
    pub fn name(self) -> &'static str {
        match self {
            SweepAxis::Alpha => "alpha",
            SweepAxis::Beta => "beta",
            SweepAxis::Johnson => "johnson",
            SweepAxis::Amplitude => "amplitude",
        }
    }
}

/// The regime of one grid point.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
pub enum Regime {
    /// Valid hysteresis loops.
    Dissipative,
    /// Loops, all through invalid states.
    Cavitating,
    /// No roughness-induced loop.
    SmoothLike,
}

/// A sweep's grid. The one-wave axes (`alpha`, `beta`, `johnson`) build their wave
/// from `fixed` and the axis' value and carry no `profile`; the `amplitude` axis scales
/// the base `profile` (which it must carry) and ignores `fixed`. In JSON the
/// `profile` (a list of `{"alpha", "beta"}` waves) is written only when present,
/// so sweeps written before it existed read back unchanged.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct SweepGrid {
    /// Smallest `lambda`.
    pub lambda_min: f64,
    /// Largest `lambda`.
    pub lambda_max: f64,
    /// Number of `lambda` values (log-spaced).
    pub lambda_n: usize,
    /// The second axis.
    pub axis: SweepAxis,
    /// Its smallest value.
    pub min: f64,
    /// Its largest value.
    pub max: f64,
    /// Number of values (linearly spaced).
    pub n: usize,
    /// The parameter held fixed: `beta` for the `alpha` and Johnson axes, `alpha` for
    /// the `beta` axis (unused by the `amplitude` axis).
    pub fixed: f64,
    /// The base profile the `amplitude` axis scales (`None` for the one-wave axes).
    #[cfg_attr(feature = "serde", serde(default, skip_serializing_if = "Option::is_none"))]
    pub profile: Option<WavyProfile>,
    /// The curve grid of every point.
    pub amax: f64,
    /// Grid points per curve.
    pub points: usize,
}

/// One grid point's result.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct SweepPoint {
    /// Index `k` in the grid.
    pub index: usize,
    /// Maugis parameter.
    pub lambda: f64,
    /// The second axis' value.
    pub value: f64,
    /// Amplitude (on the `amplitude` axis: the first wave's, `s alpha_1`; the whole
    /// profile is [`SweepGrid::profile_at`]).
    pub alpha: f64,
    /// Wavelength (on the `amplitude` axis: the first wave's, `beta_1`).
    pub beta: f64,
    /// Loading jumps from turning points (the instabilities the loading path meets).
    pub instabilities: usize,
    /// Unloading jumps.
    pub unloading_jumps: usize,
    /// Dissipation under load control (units of `dgamma l_h`).
    pub dissipation: f64,
    /// Of valid loops.
    pub dissipation_valid: f64,
    /// Of loops through invalid states.
    pub dissipation_invalid: f64,
    /// Pull-off load (none when the unloading path never leaves contact).
    pub pull_off: Option<f64>,
    /// The pull-off state is valid.
    pub pull_off_valid: bool,
    /// The most tensile valid load under load control (`Curve::valid_pull_off`):
    /// the pull-off a valid Maugis state supports, when `pull_off` is not valid.
    pub valid_pull_off: Option<f64>,
    /// Fraction of valid grid states.
    pub valid_fraction: f64,
    /// The regime.
    pub regime: Regime,
}

/// A sweep (or one shard of it).
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Sweep {
    /// The grid.
    pub grid: SweepGrid,
    /// `(s, n)` when this is shard `s` of `n`.
    pub shard: Option<(usize, usize)>,
    /// The computed points, by index.
    pub points: Vec<SweepPoint>,
}

impl SweepGrid {
    /// Checks the grid.
    pub fn check(&self) -> Result<()> {
        for (v, w) in [(self.lambda_min, "lambda_min"), (self.lambda_max, "lambda_max"), (self.min, "min"), (self.max, "max"), (self.fixed, "fixed"), (self.amax, "amax")] {
            finite(v, w)?;
        }
        if !(self.lambda_min > 0.0 && self.lambda_max >= self.lambda_min) {
            return Err(Error::Sweep(SweepError::LambdaRange { min: self.lambda_min, max: self.lambda_max }));
        }
        if self.lambda_n == 0 || self.n == 0 {
            return Err(Error::Sweep(SweepError::EmptyAxis));
        }
        if self.max < self.min {
            return Err(Error::Sweep(SweepError::AxisOrder { min: self.min, max: self.max }));
        }
        let zero_allowed = matches!(self.axis, SweepAxis::Alpha | SweepAxis::Amplitude);
        let lo_ok = if zero_allowed { self.min >= 0.0 } else { self.min > 0.0 };
        if !lo_ok {
            return Err(Error::Sweep(SweepError::AxisStart { axis: self.axis.name(), min: self.min, zero_allowed }));
        }
        match (self.axis, &self.profile) {
            (SweepAxis::Amplitude, None) => return Err(Error::Sweep(SweepError::NoBaseProfile)),
            (SweepAxis::Amplitude, Some(p)) if p.is_empty() => return Err(Error::Sweep(SweepError::NoBaseProfile)),
            (SweepAxis::Amplitude, Some(_)) => {}
            (axis, Some(p)) => return Err(Error::Sweep(SweepError::ProfileOnOneWaveAxis { axis: axis.name(), waves: p.len() })),
            (_, None) => {}
        }
        // every combination must be a valid parameter set
        for i in [0, self.lambda_n - 1] {
            for j in [0, self.n - 1] {
                self.params(i, j)?;
            }
        }
        Ok(())
    }

    /// `lambda_i`, log-spaced.
    pub fn lambda(&self, i: usize) -> f64 {
        if self.lambda_n == 1 {
            return self.lambda_min;
        }
        let t = i as f64 / (self.lambda_n - 1) as f64;
        (self.lambda_min.ln() + t * (self.lambda_max.ln() - self.lambda_min.ln())).exp()
    }

    /// The second axis' `j`-th value, linearly spaced.
    pub fn value(&self, j: usize) -> f64 {
        if self.n == 1 {
            return self.min;
        }
        self.min + (self.max - self.min) * j as f64 / (self.n - 1) as f64
    }

    /// The profile at the second axis' `j`-th value: the one wave of the one-wave axes,
    /// or on the `amplitude` axis the base profile with every `alpha_j` times the value.
    pub fn profile_at(&self, j: usize) -> Result<WavyProfile> {
        let v = self.value(j);
        let (alpha, beta) = match self.axis {
            SweepAxis::Alpha => (v, self.fixed),
            SweepAxis::Beta => (self.fixed, v),
            SweepAxis::Johnson => (self.fixed.sqrt() / v, self.fixed),
            SweepAxis::Amplitude => {
                let base = self.profile.ok_or(Error::Sweep(SweepError::NoBaseProfile))?;
                let pairs: Vec<(f64, f64)> = base.waves().iter().map(|w| (v * w.alpha(), w.beta())).collect();
                return WavyProfile::from_pairs(&pairs);
            }
        };
        WavyProfile::one_wave(alpha, beta)
    }

    /// The parameters of grid point `(i, j)`.
    pub fn params(&self, i: usize, j: usize) -> Result<Params> {
        let v = self.value(j);
        match self.axis {
            SweepAxis::Alpha => Params::new(self.lambda(i), v, self.fixed),
            SweepAxis::Beta => Params::new(self.lambda(i), self.fixed, v),
            SweepAxis::Johnson => Params::new(self.lambda(i), self.fixed.sqrt() / v, self.fixed),
            SweepAxis::Amplitude => Params::with_profile(self.lambda(i), self.profile_at(j)?),
        }
    }

    /// Number of grid points.
    pub fn len(&self) -> usize {
        self.lambda_n * self.n
    }

    /// Always false for a checked grid.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }
}

/// One grid point.
pub fn sweep_point(grid: &SweepGrid, index: usize) -> Result<SweepPoint> {
    let (i, j) = (index / grid.n, index % grid.n);
    let params = grid.params(i, j)?;
    let c = load_area_curve(params, CurveOptions { amax: grid.amax, points: grid.points, ..CurveOptions::default() })?;
    let lc = &c.load_control;
    let instabilities = lc.jumps.iter().filter(|j| j.direction == JumpDirection::Loading && j.from_turning_point).count();
    let unloading_jumps = lc.jumps.iter().filter(|j| j.direction == JumpDirection::Unloading).count();
    let d = lc.dissipation;
    let regime = if instabilities == 0 || lc.loops.is_empty() {
        Regime::SmoothLike
    } else if lc.loops.iter().any(|l| l.valid) {
        Regime::Dissipative
    } else {
        Regime::Cavitating
    };
    let n_valid = c.points.iter().filter(|p| p.validity.valid).count();
    Ok(SweepPoint {
        index,
        lambda: params.lambda,
        value: grid.value(j),
        alpha: params.alpha(),
        beta: params.beta(),
        instabilities,
        unloading_jumps,
        dissipation: d.total,
        dissipation_valid: d.valid,
        dissipation_invalid: d.invalid,
        pull_off: c.pull_off.map(|p| p.load),
        pull_off_valid: c.pull_off.map_or(false, |p| p.validity.valid),
        valid_pull_off: c.valid_pull_off.map(|p| p.load),
        valid_fraction: n_valid as f64 / c.points.len() as f64,
        regime,
    })
}

/// Runs shard `shard = (s, n)` (1-based; `None`: everything) of a grid;
/// `progress` is called once per finished point.
pub fn run_sweep<P: Fn() + Sync>(grid: SweepGrid, shard: Option<(usize, usize)>, progress: P) -> Result<Sweep> {
    grid.check()?;
    if let Some((s, n)) = shard {
        if n == 0 || s == 0 || s > n {
            return Err(Error::Sweep(SweepError::Shard { s, n }));
        }
    }
    let indices: Vec<usize> = (0..grid.len()).filter(|k| shard.map_or(true, |(s, n)| k % n == s - 1)).collect();
    #[cfg(feature = "parallel")]
    let it = indices.par_iter();
    #[cfg(not(feature = "parallel"))]
    let it = indices.iter();
    let points = it
        .map(|&k| {
            let r = sweep_point(&grid, k);
            progress();
            r
        })
        .collect::<Result<Vec<_>>>()?;
    Ok(Sweep { grid, shard, points })
}

/// Reassembles shards of one grid into the whole sweep (the shards may come in
/// any order; together they must cover every point exactly once).
pub fn merge(parts: &[Sweep]) -> Result<Sweep> {
    let first = parts.first().ok_or_else(|| Error::Sweep(SweepError::NothingToMerge))?;
    let grid = first.grid;
    let mut slots: Vec<Option<SweepPoint>> = vec![None; grid.len()];
    for p in parts {
        if p.grid.profile != grid.profile {
            return Err(Error::Sweep(SweepError::DifferentProfiles {
                first: grid.profile.map_or_else(|| "one wave".to_string(), |w| w.describe()),
                other: p.grid.profile.map_or_else(|| "one wave".to_string(), |w| w.describe()),
            }));
        }
        if p.grid != grid {
            return Err(Error::Sweep(SweepError::DifferentGrids));
        }
        for q in &p.points {
            match slots.get_mut(q.index) {
                Some(slot @ None) => *slot = Some(*q),
                Some(Some(_)) => return Err(Error::Sweep(SweepError::DuplicatePoint { index: q.index })),
                None => return Err(Error::Sweep(SweepError::PointOutsideGrid { index: q.index })),
            }
        }
    }
    let missing = slots.iter().filter(|s| s.is_none()).count();
    if missing > 0 {
        return Err(Error::Sweep(SweepError::MissingPoints { missing, total: grid.len() }));
    }
    Ok(Sweep { grid, shard: None, points: slots.into_iter().flatten().collect() })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn grid() -> SweepGrid {
        SweepGrid { lambda_min: 1.0, lambda_max: 6.0, lambda_n: 2, axis: SweepAxis::Alpha, min: 0.0, max: 0.35, n: 2, fixed: 1.125, profile: None, amax: 6.0, points: 40 }
    }

    #[test]
    fn shards_merge_and_bad_merges_are_refused() {
        let g = grid();
        let whole = run_sweep(g, None, || ()).unwrap();
        let a = run_sweep(g, Some((1, 3)), || ()).unwrap();
        let b = run_sweep(g, Some((2, 3)), || ()).unwrap();
        let c = run_sweep(g, Some((3, 3)), || ()).unwrap();
        assert_eq!(merge(&[c.clone(), a.clone(), b.clone()]).unwrap(), whole);
        assert!(merge(&[a.clone(), b.clone()]).is_err(), "missing shard");
        assert!(merge(&[a.clone(), a.clone(), b, c]).is_err(), "duplicate shard");
        assert!(merge(&[]).is_err());
        // smooth column: no instability; lambda = 6 with roughness: dissipative
        assert!(whole.points.iter().filter(|p| p.alpha == 0.0).all(|p| p.regime == Regime::SmoothLike));
        assert_eq!(whole.points[3].regime, Regime::Dissipative, "{:?}", whole.points[3]);
    }

    #[test]
    fn bad_grids_are_refused() {
        let g = grid();
        assert!(SweepGrid { lambda_min: 0.0, ..g }.check().is_err());
        assert!(SweepGrid { lambda_max: 0.5, ..g }.check().is_err());
        assert!(SweepGrid { n: 0, ..g }.check().is_err());
        assert!(SweepGrid { min: f64::NAN, ..g }.check().is_err());
        assert!(SweepGrid { axis: SweepAxis::Johnson, min: 0.0, ..g }.check().is_err());
        assert!(run_sweep(g, Some((0, 2)), || ()).is_err());
        assert!(run_sweep(g, Some((3, 2)), || ()).is_err());
    }
}
