//! Multi-scale roughness: what bounds the load-area response of a profile of many
//! waves (issue 39, item 1; docs/multiscale.md).
//!
//! # The envelope of one wave, and of many
//!
//! Each wave adds `(pi^2 alpha_j a/beta_j) J1(D_j)`, `D_j = 2 pi a/beta_j`, to the
//! adhesionless load (Eq. 14, E.42a). For large `D_j`,
//! `J1(D) = sqrt(2/(pi D)) cos(D - 3 pi/4) + O(D^-3/2)`, so the waves add
//!
//! ```text
//! sqrt(a) g(a),   g(a) = sum_j c_j cos(2 pi a/beta_j - 3 pi/4),   c_j = pi alpha_j/sqrt(beta_j),
//! ```
//!
//! to the smooth response. One wave: `g` swings between `+/- c_1`, the paper's
//! envelope `pi sqrt(alpha^2/beta) sqrt(a)`, whose inverse scale is the (scaled)
//! Johnson parameter `chi = sqrt(beta/alpha^2) = pi/c_1`.
//!
//! Many waves: three candidate envelopes `sqrt(a) M`:
//!
//! * the **triangle** sum `M = T = sum_j c_j` (`1/chi_eff = sum_j 1/chi_j`,
//!   [`crate::contact::limits::envelope_halfwidth_profile`]): always an upper bound
//!   of `|g|`; sharp when the wavelengths are rationally independent (Kronecker:
//!   the phases then align somewhere), loose otherwise;
//! * the **phase-locked** constants `M+ = sup g`, `M- = -inf g`: when every
//!   `P/beta_j` is an integer for one period `P` (a Weierstrass profile with integer
//!   `gamma`), `g` is `P`-periodic, the phases never align, and `M+`, `M-` are the
//!   sharp asymptotic envelope. For odd integer ratios `g(a + P/2) = -g(a)` and
//!   `M+ = M-`; for even ones the envelope is lopsided;
//! * no single constant: the upper and lower envelopes need `M+` and `M-` apart.
//!
//! [`envelope_constants`] computes `T`, and `M+`, `M-` by sampling `g` over one
//! period with step `h = beta_min/256`: a maximum lies within `h/2` of a sample,
//! and `g(a*) - g(s) <= G2 (h/2)^2/2` with `G2 = sum_j c_j (2 pi/beta_j)^2 >= |g''|`
//! (`g'(a*) = 0`), so `sampled max <= M+ <= sampled max + G2 h^2/8` (likewise `M-`);
//! the returned `upper` and `lower` are the right ends, and `sampling_error` is
//! `G2 h^2/8`. The samples are f64 sums of a few cosines (relative rounding about
//! `N 2^-52`, far below the sampling error): an estimate in the project's sense,
//! not a certified bound.
//!
//! # The excursion of the model outside an envelope
//!
//! [`envelope_excursion`] measures, on a solved load-area curve at Maugis parameter
//! `lambda`, the normalised wave part of the response against two references:
//!
//! * **local** (Eq. 17): `w(a) = (L(a) - L_smooth(lambda, a))/sqrt(a)`, the curve
//!   against the smooth Maugis curve at the same `lambda`; the envelope claims
//!   `-M- <= w <= M+`;
//! * **global** (the paper's bound, E.42b below and E.43d at `lambda -> 0` above):
//!   `(L - pi a^2/4)/sqrt(a) <= M+` and `(L - pi a^2/4 + sqrt(2 pi a))/sqrt(a) >= -M-`.
//!
//! Each maximum is over the grid states with `a >= beta_1` (the coarsest wave's
//! `D_1 >= 2 pi`, where its asymptotic form is within a few per cent; the paper
//! ignores `D -> 0` too), over all of them and over the valid ones.

use std::f64::consts::PI;

use crate::contact::curve::{load_area_curve, Curve, CurveOptions};
use crate::contact::limits::jkr_load_profile;
use crate::contact::model::Params;
use crate::contact::curve_state::load_at;
use crate::contact::profile::WavyProfile;
use crate::error::{finite, Error, Interval, Result};

/// The envelope constants of a profile: the half-width of the asymptotic envelope of
/// the waves' load is `sqrt(abar)` times one of them.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct EnvelopeConstants {
    /// The triangle sum `T = sum_j pi alpha_j/sqrt(beta_j)`.
    pub triangle: f64,
    /// `M+ = sup g` (an upper end: the sampled maximum plus [`Self::sampling_error`]);
    /// `T` when the profile has no common period.
    pub upper: f64,
    /// `M- = -inf g`, likewise.
    pub lower: f64,
    /// The common period `P` of the waves (`P/beta_j` integers), when there is one
    /// within [`MAX_PERIOD_MULTIPLE`] coarsest wavelengths.
    pub period: Option<f64>,
    /// The width of the enclosure of `M+` and `M-` left by the sampling, `G2 h^2/8`
    /// (0 without a period).
    pub sampling_error: f64,
}

impl EnvelopeConstants {
    /// The Johnson parameter of one wave with the same envelope constant `m`:
    /// `pi/m` (one wave: `sqrt(beta/alpha^2)`).
    pub fn johnson(m: f64) -> f64 {
        PI / m
    }
}

/// The largest common period searched: `q beta_max` for `q = 1..=16`.
pub const MAX_PERIOD_MULTIPLE: usize = 16;

/// Samples per finest wavelength when `g` is maximised over a period.
const SAMPLES_PER_FINEST: f64 = 256.0;

/// More samples than this over one period and the period is not used (bounded time).
const MAX_SAMPLES: f64 = 4.0e6;

/// `P/beta` is taken as an integer when within this relative distance of one.
const PERIOD_TOLERANCE: f64 = 1e-9;

/// The waves with an amplitude, as `(c_j, beta_j)`.
fn weights(profile: &WavyProfile) -> Vec<(f64, f64)> {
    profile.active_waves().map(|w| (PI * w.alpha() / w.beta().sqrt(), w.beta())).collect()
}

/// The common period of the wavelengths, if one is at most 16 coarsest wavelengths.
fn common_period(waves: &[(f64, f64)]) -> Option<f64> {
    let coarsest = waves.iter().map(|w| w.1).fold(0.0, f64::max);
    (1..=MAX_PERIOD_MULTIPLE).map(|q| q as f64 * coarsest).find(|&p| {
        waves.iter().all(|&(_, beta)| {
            let r = p / beta;
            (r - r.round()).abs() <= PERIOD_TOLERANCE * r
        })
    })
}

/// `g(a) = sum_j c_j cos(2 pi a/beta_j - 3 pi/4)`.
fn g(waves: &[(f64, f64)], a: f64) -> f64 {
    waves.iter().fold(0.0, |s, &(c, beta)| s + c * (2.0 * PI * a / beta - 0.75 * PI).cos())
}

/// The envelope constants of `profile` (see the module docs). A smooth profile has
/// all constants 0.
pub fn envelope_constants(profile: &WavyProfile) -> EnvelopeConstants {
    let waves = weights(profile);
    let triangle: f64 = waves.iter().map(|w| w.0).sum();
    let unlocked = EnvelopeConstants { triangle, upper: triangle, lower: triangle, period: None, sampling_error: 0.0 };
    if waves.len() < 2 {
        return EnvelopeConstants { period: waves.first().map(|w| w.1), ..unlocked };
    }
    let Some(period) = common_period(&waves) else { return unlocked };
    let finest = waves.iter().map(|w| w.1).fold(f64::INFINITY, f64::min);
    let h = finest / SAMPLES_PER_FINEST;
    let n = (period / h).ceil();
    if n > MAX_SAMPLES {
        return unlocked;
    }
    let n = n as usize;
    let h = period / n as f64;
    let (mut hi, mut lo) = (f64::NEG_INFINITY, f64::INFINITY);
    for i in 0..n {
        let v = g(&waves, i as f64 * h);
        hi = hi.max(v);
        lo = lo.min(v);
    }
    let g2: f64 = waves.iter().map(|&(c, beta)| c * (2.0 * PI / beta).powi(2)).sum();
    let sampling_error = g2 * h * h / 8.0;
    EnvelopeConstants {
        triangle,
        upper: (hi + sampling_error).min(triangle),
        lower: (-lo + sampling_error).min(triangle),
        period: Some(period),
        sampling_error,
    }
}

/// The largest excursions of one curve's normalised wave part (module docs), over a
/// set of states.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Excursions {
    /// States measured.
    pub states: usize,
    /// `max (L - L_smooth(lambda))/sqrt(a)`: against `M+` (local, Eq. 17).
    pub local_up: f64,
    /// `max (L_smooth(lambda) - L)/sqrt(a)`: against `M-`.
    pub local_down: f64,
    /// `max (L - pi a^2/4)/sqrt(a)`: against `M+` (global, adhesionless above).
    pub global_up: f64,
    /// `max (pi a^2/4 - sqrt(2 pi a) - L)/sqrt(a)`: against `M-` (global, JKR below).
    pub global_down: f64,
}

impl Excursions {
    fn empty() -> Excursions {
        let n = f64::NEG_INFINITY;
        Excursions { states: 0, local_up: n, local_down: n, global_up: n, global_down: n }
    }

    fn add(&mut self, abar: f64, load: f64, smooth: f64) {
        let r = abar.sqrt();
        let hertz = PI * abar * abar / 4.0;
        self.states += 1;
        self.local_up = self.local_up.max((load - smooth) / r);
        self.local_down = self.local_down.max((smooth - load) / r);
        self.global_up = self.global_up.max((load - hertz) / r);
        self.global_down = self.global_down.max((hertz - (2.0 * PI * abar).sqrt() - load) / r);
    }
}

/// One curve's excursions: over the states with `a >= beta_1`, all and valid.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct EnvelopeExcursion {
    /// Maugis parameter.
    pub lambda: f64,
    /// The smallest contact measured (the coarsest wavelength).
    pub abar_min: f64,
    /// Every state with `abar >= abar_min`.
    pub all: Excursions,
    /// The valid ones among them (`states` 0 when none is valid; the maxima are then
    /// `-inf`, written as absent in JSON).
    pub valid: Excursions,
}

/// The excursions of `curve` (its profile's coarsest wavelength sets `abar_min`).
pub fn envelope_excursion(curve: &Curve) -> Result<EnvelopeExcursion> {
    let params = curve.params;
    let abar_min = params.profile.coarsest_wavelength().unwrap_or(0.0);
    let smooth = params.smooth();
    let (mut all, mut valid) = (Excursions::empty(), Excursions::empty());
    for p in curve.points.iter().filter(|p| p.abar >= abar_min) {
        let reference = load_at(smooth, p.abar)?;
        all.add(p.abar, p.load, reference);
        if p.validity.valid {
            valid.add(p.abar, p.load, reference);
        }
    }
    if all.states == 0 {
        let amax = curve.points.last().map_or(0.0, |p| p.abar);
        return Err(Error::OutOfRange { arg: "amax (the curve's largest contact)", value: amax, allowed: Interval::above(abar_min) });
    }
    Ok(EnvelopeExcursion { lambda: params.lambda, abar_min, all, valid })
}

/// Grid points per finest wavelength on the curves of [`envelope_row`]: the sampled
/// extremes of the finest wave fall short of the true ones by at most
/// `1 - cos(pi/32)`, 0.5 % of its amplitude.
pub const POINTS_PER_FINEST: f64 = 32.0;

/// One Weierstrass profile at one `lambda`: its constants and the model's excursions.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct EnvelopeRow {
    /// Number of scales `N`.
    pub scales: usize,
    /// Wavelength ratio `gamma`.
    pub gamma: f64,
    /// Hurst exponent `H`.
    pub hurst: f64,
    /// Maugis parameter.
    pub lambda: f64,
    /// Grid points of the curve (`abar_i = amax i/points`).
    pub points: usize,
    /// The profile's envelope constants.
    pub constants: EnvelopeConstants,
    /// The model curve's excursions.
    pub excursion: EnvelopeExcursion,
    /// The JKR limit's (E.42a) on the same grid: `max (L_JKR - L_JKR,smooth)/sqrt(a)`
    /// and `max (L_JKR,smooth - L_JKR)/sqrt(a)` over `a >= beta_1`, what the
    /// asymptotic envelope leaves out at finite `D` (lambda-independent).
    pub jkr: (f64, f64),
}

/// The JKR limit's excursions `(up, down)` on the grid of `options`, over `a >= beta_1`
/// (see [`EnvelopeRow::jkr`]).
pub fn jkr_excursion(profile: &WavyProfile, options: CurveOptions) -> Result<(f64, f64)> {
    let abar_min = profile.coarsest_wavelength().unwrap_or(0.0);
    let (mut up, mut down) = (f64::NEG_INFINITY, f64::NEG_INFINITY);
    for i in 1..=options.points {
        let abar = options.amax * i as f64 / options.points as f64;
        if abar < abar_min {
            continue;
        }
        let w = (jkr_load_profile(profile, abar)? - jkr_load_profile(&WavyProfile::smooth(), abar)?) / abar.sqrt();
        up = up.max(w);
        down = down.max(-w);
    }
    Ok((up, down))
}

/// The largest grid [`envelope_curve_options`] builds (a curve of this many states
/// takes minutes; beyond it the request is refused at once).
pub const MAX_ENVELOPE_POINTS: usize = 200_000;

/// The curve options of a profile's envelope check: `amax`, and at least
/// [`POINTS_PER_FINEST`] grid points per finest wavelength (600 at least). More than
/// [`MAX_ENVELOPE_POINTS`] is [`Error::IntegerOutOfRange`], before any work.
pub fn envelope_curve_options(profile: &WavyProfile, amax: f64) -> Result<CurveOptions> {
    finite(amax, "amax")?;
    Interval::above(0.0).check("amax", amax)?;
    let finest = profile.finest_wavelength().unwrap_or(amax);
    let wanted = (POINTS_PER_FINEST * amax / finest).ceil().max(600.0);
    if !(wanted <= MAX_ENVELOPE_POINTS as f64) {
        let value = if wanted < i64::MAX as f64 { wanted as i64 } else { i64::MAX };
        return Err(Error::IntegerOutOfRange { arg: "grid points of an envelope curve (32 per finest wavelength up to amax)", value, min: 2, max: MAX_ENVELOPE_POINTS as i64 });
    }
    Ok(CurveOptions { amax, points: wanted as usize, ..CurveOptions::default() })
}

/// [`EnvelopeRow`] of the Weierstrass profile `(alpha_1, beta_1, scales, gamma, hurst)`
/// ([`WavyProfile::weierstrass`]) at `lambda`, on contacts up to `amax`.
pub fn envelope_row(alpha_1: f64, beta_1: f64, scales: usize, gamma: f64, hurst: f64, lambda: f64, amax: f64) -> Result<EnvelopeRow> {
    let profile = WavyProfile::weierstrass(alpha_1, beta_1, scales, gamma, hurst)?;
    let params = Params::with_profile(lambda, profile)?;
    let options = envelope_curve_options(&profile, amax)?;
    let curve = load_area_curve(params, options)?;
    Ok(EnvelopeRow {
        scales,
        gamma,
        hurst,
        lambda,
        points: options.points,
        constants: envelope_constants(&profile),
        excursion: envelope_excursion(&curve)?,
        jkr: jkr_excursion(&profile, options)?,
    })
}

/// The grid of Weierstrass profiles and Maugis parameters of an envelope study.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct EnvelopeStudy {
    /// The first (coarsest) wave's amplitude.
    pub alpha_1: f64,
    /// Its wavelength.
    pub beta_1: f64,
    /// Numbers of scales `N`.
    pub scales: Vec<usize>,
    /// Wavelength ratios `gamma`.
    pub gammas: Vec<f64>,
    /// Hurst exponents `H`.
    pub hursts: Vec<f64>,
    /// Maugis parameters.
    pub lambdas: Vec<f64>,
    /// Largest contact of every curve.
    pub amax: f64,
}

impl EnvelopeStudy {
    /// Issue 39's grid below the Fig. 4c wave (`alpha_1 = 2 sqrt(2)/8`, `beta_1 = 9/8`):
    /// `N in {2, 3, 4}`, `H in {0.3, 0.5, 0.8}`, `gamma in {2, 3}`,
    /// `lambda in {1/10, 3/10, 1, 3, 10, 30, 100}`, `abar <= 6`.
    pub fn issue_grid() -> EnvelopeStudy {
        EnvelopeStudy {
            alpha_1: 2.0 * std::f64::consts::SQRT_2 / 8.0,
            beta_1: 9.0 / 8.0,
            scales: vec![2, 3, 4],
            gammas: vec![2.0, 3.0],
            hursts: vec![0.3, 0.5, 0.8],
            lambdas: vec![0.1, 0.3, 1.0, 3.0, 10.0, 30.0, 100.0],
            amax: 6.0,
        }
    }

    /// The cases `(N, gamma, H, lambda)` in the order of the rows: by `N`, `gamma`, `H`, then `lambda`.
    pub fn cases(&self) -> Vec<(usize, f64, f64, f64)> {
        let mut out = Vec::new();
        for &n in &self.scales {
            for &gamma in &self.gammas {
                for &hurst in &self.hursts {
                    out.extend(self.lambdas.iter().map(|&lambda| (n, gamma, hurst, lambda)));
                }
            }
        }
        out
    }

    /// [`envelope_row`] of one case.
    pub fn row(&self, (n, gamma, hurst, lambda): (usize, f64, f64, f64)) -> Result<EnvelopeRow> {
        envelope_row(self.alpha_1, self.beta_1, n, gamma, hurst, lambda, self.amax)
    }
}

/// The normalised wave part `w(a) = (L(a) - L_smooth(lambda, a))/sqrt(a)` of a curve
/// at every grid state, as `(abar, w, valid)`: what the local envelope bounds.
pub fn wave_part(curve: &Curve) -> Result<Vec<(f64, f64, bool)>> {
    let smooth = curve.params.smooth();
    curve.points.iter().map(|p| Ok((p.abar, (p.load - load_at(smooth, p.abar)?) / p.abar.sqrt(), p.validity.valid))).collect()
}
