//! The indenter's profile: a cylinder carrying any number of cosine waves
//! (normalised units, docs/model.md "Many waves").
//!
//! ```text
//! hbar(x) = x^2/2 + sum_j alpha_j (1 - cos(2 pi x/beta_j))
//!         = x^2/2 + sum_j 2 alpha_j sin^2(pi x/beta_j)
//! ```
//!
//! with amplitudes `alpha_j = A_j/l_v >= 0` and wavelengths `beta_j = zeta_j/l_h > 0`
//! (the two length scales of `docs/model.md`). The seed paper's profile (Eq. 1) is the
//! one-wave case; a profile with no wave is the smooth cylinder.
//!
//! * [`CosineWave`]: one wave `(alpha, beta)`, checked once.
//! * [`WavyProfile`]: the cylinder plus at most [`MAX_WAVES`] waves, in the order given
//!   (the model's sums run in that order; reordering changes results only by rounding).
//!   It is `Copy`: the waves live inline, so [`crate::contact::model::Params`] stays `Copy`.
//! * [`WavyProfile::weierstrass`]: the standard multi-scale family, `N` scales with
//!   wavelength ratio `gamma > 1` and amplitude ratio `gamma^(-H)`:
//!   `beta_j = beta_1 gamma^(-j)`, `alpha_j = alpha_1 gamma^(-H j)`, `j = 0..N-1`.
//! * [`WavyProfile::from_harmonics_table`]: a table of harmonics, one
//!   `amplitude,wavelength` pair a line (`#` comments, an optional header line).
//!
//! Every bad value is a typed [`ProfileError`] naming the wave (1-based) and the field,
//! or the line of the table.
//!
//! Nothing here computes a model quantity: the sums over waves are in
//! [`crate::contact::model`].

use crate::error::{Error, Interval, ProfileError, Result, WaveField};

/// Most waves a profile carries. The cost of a state grows with the sum of the waves'
/// Bessel lengths `D_j = 2 pi abar/beta_j` (docs/model.md), so this is a bound on the
/// work of one call, not on what the mathematics allows.
pub const MAX_WAVES: usize = 64;

/// Allowed amplitudes `alpha_j` (0 is a wave that is not there).
pub const AMPLITUDE_RANGE: Interval = Interval::closed(0.0, 1e6);
/// Allowed wavelengths `beta_j`.
pub const WAVELENGTH_RANGE: Interval = Interval::closed(1e-6, 1e6);
/// Allowed Weierstrass wavelength ratios `gamma`.
pub const GAMMA_RANGE: Interval = Interval { lo: 1.0, hi: 1e3, lo_closed: false, hi_closed: true };
/// Allowed Weierstrass Hurst exponents `H`.
pub const HURST_RANGE: Interval = Interval::closed(0.0, 1.0);

/// One cosine wave of the profile, `alpha (1 - cos(2 pi x/beta))` (normalised).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CosineWave {
    alpha: f64,
    beta: f64,
}

impl CosineWave {
    const ZERO: CosineWave = CosineWave { alpha: 0.0, beta: 1.0 };

    /// The wave of amplitude `alpha` in [`AMPLITUDE_RANGE`] and wavelength `beta` in
    /// [`WAVELENGTH_RANGE`]; a bad value is [`ProfileError::Wave`] for wave 1.
    pub fn new(alpha: f64, beta: f64) -> Result<CosineWave> {
        CosineWave::checked(1, alpha, beta)
    }

    /// The same checks, naming wave `index` (1-based) in the error.
    fn checked(index: usize, alpha: f64, beta: f64) -> Result<CosineWave> {
        for (field, value, allowed) in
            [(WaveField::Amplitude, alpha, AMPLITUDE_RANGE), (WaveField::Wavelength, beta, WAVELENGTH_RANGE)]
        {
            if !allowed.contains(value) {
                return Err(Error::Profile(ProfileError::Wave { wave: index, field, value, allowed }));
            }
        }
        Ok(CosineWave { alpha, beta })
    }

    /// The amplitude `alpha` (in `l_v`).
    pub fn alpha(&self) -> f64 {
        self.alpha
    }

    /// The wavelength `beta` (in `l_h`).
    pub fn beta(&self) -> f64 {
        self.beta
    }

    /// The Bessel length `D = 2 pi abar/beta` of this wave at contact size `abar`.
    pub fn bessel_length(&self, abar: f64) -> f64 {
        2.0 * std::f64::consts::PI * abar / self.beta
    }

    /// The depth this wave adds at `x`: `2 alpha sin^2(pi x/beta)`.
    pub fn depth(&self, x: f64) -> f64 {
        let sn = (std::f64::consts::PI * x / self.beta).sin();
        2.0 * self.alpha * sn * sn
    }
}

/// The cylinder plus `0..=`[`MAX_WAVES`] cosine waves, in the order given.
#[derive(Clone, Copy)]
pub struct WavyProfile {
    count: usize,
    waves: [CosineWave; MAX_WAVES],
}

impl PartialEq for WavyProfile {
    fn eq(&self, other: &WavyProfile) -> bool {
        self.waves() == other.waves()
    }
}

impl std::fmt::Debug for WavyProfile {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_list().entries(self.waves()).finish()
    }
}

impl WavyProfile {
    /// The smooth cylinder (no wave).
    pub const fn smooth() -> WavyProfile {
        WavyProfile { count: 0, waves: [CosineWave::ZERO; MAX_WAVES] }
    }

    /// The cylinder with one wave (the seed paper's profile).
    pub fn one_wave(alpha: f64, beta: f64) -> Result<WavyProfile> {
        WavyProfile::from_pairs(&[(alpha, beta)])
    }

    /// The cylinder with the waves `(alpha_j, beta_j)` in this order. Errors:
    /// [`ProfileError::TooManyWaves`] beyond [`MAX_WAVES`], [`ProfileError::Wave`]
    /// naming the first bad wave (1-based) and field.
    pub fn from_pairs(pairs: &[(f64, f64)]) -> Result<WavyProfile> {
        if pairs.len() > MAX_WAVES {
            return Err(Error::Profile(ProfileError::TooManyWaves { count: pairs.len(), max: MAX_WAVES }));
        }
        let mut p = WavyProfile::smooth();
        for (i, &(alpha, beta)) in pairs.iter().enumerate() {
            p.waves[i] = CosineWave::checked(i + 1, alpha, beta)?;
        }
        p.count = pairs.len();
        Ok(p)
    }

    /// The cylinder with these waves (each already checked).
    pub fn from_waves(waves: &[CosineWave]) -> Result<WavyProfile> {
        let pairs: Vec<(f64, f64)> = waves.iter().map(|w| (w.alpha, w.beta)).collect();
        WavyProfile::from_pairs(&pairs)
    }

    /// The Weierstrass profile: `n` scales below the first wave `(alpha_1, beta_1)`,
    /// wave `j = 0..n-1` with `beta_j = beta_1 gamma^(-j)` and
    /// `alpha_j = alpha_1 gamma^(-H j)` (`gamma^(-j)` and `gamma^(-H j)` by `powi`/`powf`
    /// of the exact `gamma`). `n` in `1..=`[`MAX_WAVES`], `gamma` in [`GAMMA_RANGE`],
    /// `hurst` in [`HURST_RANGE`]; every wave must then lie in the wave ranges (the
    /// error names the wave that leaves them).
    pub fn weierstrass(alpha_1: f64, beta_1: f64, n: usize, gamma: f64, hurst: f64) -> Result<WavyProfile> {
        if n == 0 || n > MAX_WAVES {
            return Err(Error::Profile(ProfileError::TooManyWaves { count: n, max: MAX_WAVES }));
        }
        for (arg, v, range) in [("gamma", gamma, GAMMA_RANGE), ("H", hurst, HURST_RANGE)] {
            if !range.contains(v) {
                return Err(Error::Profile(ProfileError::Weierstrass { arg, value: v, allowed: range }));
            }
        }
        let pairs: Vec<(f64, f64)> = (0..n)
            .map(|j| {
                let j = j as i32;
                (alpha_1 * gamma.powf(-hurst * f64::from(j)), beta_1 * gamma.powi(-j))
            })
            .collect();
        WavyProfile::from_pairs(&pairs)
    }

    /// A table of harmonics: one `amplitude,wavelength` pair a line (normalised units;
    /// see [`crate::contact::units::Scales::profile_from_si`] for metres), blank lines and
    /// lines starting with `#` skipped, and a first line that is not two numbers read as a
    /// header. Errors name the line (1-based): [`ProfileError::HarmonicsLine`], and
    /// [`ProfileError::NoHarmonics`] for a table without a wave.
    pub fn from_harmonics_table(text: &str) -> Result<WavyProfile> {
        let pairs = parse_harmonics(text)?;
        let pairs: Vec<(f64, f64)> = pairs.into_iter().map(|(_, a, b)| (a, b)).collect();
        WavyProfile::from_pairs(&pairs)
    }

    /// The same wavelengths with every amplitude 0 (the smooth cylinder, sampled as
    /// finely as this profile by the model's root scans).
    pub fn without_amplitudes(&self) -> WavyProfile {
        let mut p = *self;
        for w in &mut p.waves[..p.count] {
            w.alpha = 0.0;
        }
        p
    }

    /// The waves, in the order given.
    pub fn waves(&self) -> &[CosineWave] {
        &self.waves[..self.count]
    }

    /// How many waves.
    pub fn len(&self) -> usize {
        self.count
    }

    /// No wave: the smooth cylinder.
    pub fn is_empty(&self) -> bool {
        self.count == 0
    }

    /// Every amplitude is 0: the smooth cylinder, whatever the wavelengths.
    pub fn is_smooth(&self) -> bool {
        self.waves().iter().all(|w| w.alpha == 0.0)
    }

    /// The waves with a nonzero amplitude.
    pub fn active_waves(&self) -> impl Iterator<Item = &CosineWave> {
        self.waves().iter().filter(|w| w.alpha > 0.0)
    }

    /// The shortest wavelength of a wave with a nonzero amplitude (`None` when smooth).
    pub fn finest_wavelength(&self) -> Option<f64> {
        self.active_waves().map(|w| w.beta).reduce(f64::min)
    }

    /// The wavelength the model's scans resolve: the finest of the waves with an
    /// amplitude, or without one the finest of all the waves (infinite without a wave).
    pub fn scan_wavelength(&self) -> f64 {
        self.finest_wavelength().unwrap_or_else(|| self.waves().iter().map(|w| w.beta).fold(f64::INFINITY, f64::min))
    }

    /// The longest wavelength of a wave with a nonzero amplitude (`None` when smooth).
    pub fn coarsest_wavelength(&self) -> Option<f64> {
        self.active_waves().map(|w| w.beta).reduce(f64::max)
    }

    /// `sum_j alpha_j`: the profile's largest possible rise above the cylinder is twice it.
    pub fn total_amplitude(&self) -> f64 {
        self.waves().iter().map(|w| w.alpha).sum()
    }

    /// `hbar(x) = x^2/2 + sum_j 2 alpha_j sin^2(pi x/beta_j)`.
    pub fn depth(&self, x: f64) -> f64 {
        x * x / 2.0 + self.wave_depth(x)
    }

    /// The waves' part of the depth, `sum_j 2 alpha_j sin^2(pi x/beta_j)`.
    pub fn wave_depth(&self, x: f64) -> f64 {
        self.waves().iter().map(|w| w.depth(x)).fold(0.0, |s, d| s + d)
    }

    /// A one-line name of the profile for titles and reports:
    /// `alpha = 0.35, beta = 1.125` for one wave, `2 waves (alpha, beta) = (0.35, 1.125) + (0.18, 0.375)`.
    pub fn describe(&self) -> String {
        match self.waves() {
            [] => "smooth cylinder".to_string(),
            [w] => format!("alpha = {}, beta = {}", w.alpha, w.beta),
            ws => {
                let parts: Vec<String> = ws.iter().map(|w| format!("({}, {})", w.alpha, w.beta)).collect();
                format!("{} waves (alpha, beta) = {}", ws.len(), parts.join(" + "))
            }
        }
    }
}

/// The rows of a harmonics table: `(line, first column, second column)`, 1-based lines.
pub fn parse_harmonics(text: &str) -> Result<Vec<(usize, f64, f64)>> {
    let mut rows = Vec::new();
    let mut seen_content = false;
    for (i, raw) in text.lines().enumerate() {
        let line_no = i + 1;
        let line = raw.trim();
        if line.is_empty() || line.starts_with('#') {
            continue;
        }
        let first_content = !seen_content;
        seen_content = true;
        let cols: Vec<&str> = line.split(',').map(str::trim).collect();
        let numbers: Vec<Option<f64>> = cols.iter().map(|c| c.parse::<f64>().ok()).collect();
        if first_content && cols.len() == 2 && numbers.iter().all(Option::is_none) {
            continue; // a header such as `amplitude,wavelength`
        }
        if cols.len() != 2 {
            return Err(Error::Profile(ProfileError::HarmonicsLine { line: line_no, columns: cols.len(), bad_column: None }));
        }
        match (numbers[0], numbers[1]) {
            (Some(a), Some(b)) => rows.push((line_no, a, b)),
            (None, _) => {
                return Err(Error::Profile(ProfileError::HarmonicsLine { line: line_no, columns: 2, bad_column: Some(1) }))
            }
            (_, None) => {
                return Err(Error::Profile(ProfileError::HarmonicsLine { line: line_no, columns: 2, bad_column: Some(2) }))
            }
        }
    }
    if rows.is_empty() {
        return Err(Error::Profile(ProfileError::NoHarmonics));
    }
    Ok(rows)
}

#[cfg(feature = "serde")]
mod serde_impl {
    use super::{CosineWave, WavyProfile};

    /// One wave in JSON: `{"alpha": .., "beta": ..}`.
    #[derive(serde::Serialize, serde::Deserialize)]
    pub(crate) struct WaveFields {
        pub(crate) alpha: f64,
        pub(crate) beta: f64,
    }

    impl serde::Serialize for CosineWave {
        fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
            WaveFields { alpha: self.alpha, beta: self.beta }.serialize(s)
        }
    }

    impl<'de> serde::Deserialize<'de> for CosineWave {
        fn deserialize<D: serde::Deserializer<'de>>(d: D) -> Result<CosineWave, D::Error> {
            let f = WaveFields::deserialize(d)?;
            CosineWave::new(f.alpha, f.beta).map_err(serde::de::Error::custom)
        }
    }

    /// A profile in JSON: the list of its waves, checked by [`WavyProfile::from_pairs`].
    impl serde::Serialize for WavyProfile {
        fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
            s.collect_seq(self.waves())
        }
    }

    impl<'de> serde::Deserialize<'de> for WavyProfile {
        fn deserialize<D: serde::Deserializer<'de>>(d: D) -> Result<WavyProfile, D::Error> {
            let fields = Vec::<WaveFields>::deserialize(d)?;
            let pairs: Vec<(f64, f64)> = fields.iter().map(|f| (f.alpha, f.beta)).collect();
            WavyProfile::from_pairs(&pairs).map_err(serde::de::Error::custom)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bad_waves_name_the_wave_and_the_field() {
        let e = WavyProfile::from_pairs(&[(0.1, 1.0), (f64::NAN, 0.5)]).unwrap_err();
        assert!(matches!(e, Error::Profile(ProfileError::Wave { wave: 2, field: WaveField::Amplitude, .. })), "{e:?}");
        let e = WavyProfile::from_pairs(&[(0.1, 1.0), (0.2, 0.5), (0.1, 0.0)]).unwrap_err();
        assert!(matches!(e, Error::Profile(ProfileError::Wave { wave: 3, field: WaveField::Wavelength, .. })), "{e:?}");
        let e = WavyProfile::from_pairs(&[(-0.1, 1.0)]).unwrap_err();
        assert!(e.to_string().contains("wave 1") && e.to_string().contains("amplitude"), "{e}");
        let many = vec![(0.1, 1.0); MAX_WAVES + 1];
        assert!(matches!(
            WavyProfile::from_pairs(&many),
            Err(Error::Profile(ProfileError::TooManyWaves { count, max: MAX_WAVES })) if count == MAX_WAVES + 1
        ));
        assert_eq!(WavyProfile::from_pairs(&many[..MAX_WAVES]).unwrap().len(), MAX_WAVES);
    }

    #[test]
    fn weierstrass_scales() {
        let p = WavyProfile::weierstrass(0.4, 2.0, 3, 2.0, 0.5).unwrap();
        let w = p.waves();
        assert_eq!(w.len(), 3);
        assert_eq!((w[0].alpha(), w[0].beta()), (0.4, 2.0));
        assert_eq!(w[2].beta(), 0.5);
        assert!((w[2].alpha() - 0.2).abs() < 1e-15);
        assert!(WavyProfile::weierstrass(0.4, 2.0, 3, 1.0, 0.5).is_err());
        assert!(WavyProfile::weierstrass(0.4, 2.0, 0, 2.0, 0.5).is_err());
        assert!(WavyProfile::weierstrass(0.4, 2.0, 3, 2.0, f64::NAN).is_err());
        // the finest wave leaves the wavelength range: named
        let e = WavyProfile::weierstrass(0.4, 1e-5, 5, 100.0, 0.5).unwrap_err();
        assert!(matches!(e, Error::Profile(ProfileError::Wave { wave: 2, field: WaveField::Wavelength, .. })), "{e:?}");
    }

    #[test]
    fn harmonics_tables() {
        let p = WavyProfile::from_harmonics_table("# a comment\namplitude,wavelength\n0.3, 1.125\n\n0.1,0.375\n").unwrap();
        assert_eq!(p, WavyProfile::from_pairs(&[(0.3, 1.125), (0.1, 0.375)]).unwrap());
        for (text, line) in [("0.3,1\n0.1\n", 2), ("0.3,1\nx,1\n", 2), ("a,b\n0.3,1,2\n", 2), ("0.3;1\n", 1)] {
            match WavyProfile::from_harmonics_table(text) {
                Err(Error::Profile(ProfileError::HarmonicsLine { line: l, .. })) => assert_eq!(l, line, "{text:?}"),
                other => panic!("{text:?}: {other:?}"),
            }
        }
        assert!(matches!(WavyProfile::from_harmonics_table("# nothing\n"), Err(Error::Profile(ProfileError::NoHarmonics))));
        assert!(matches!(WavyProfile::from_harmonics_table("amplitude,wavelength\n"), Err(Error::Profile(ProfileError::NoHarmonics))));
        // a bad value is named by its wave
        assert!(matches!(
            WavyProfile::from_harmonics_table("0.3,1\n0.2,-1\n"),
            Err(Error::Profile(ProfileError::Wave { wave: 2, field: WaveField::Wavelength, .. }))
        ));
    }

    #[test]
    fn depth_and_description() {
        let p = WavyProfile::from_pairs(&[(0.3, 1.125), (0.1, 0.375)]).unwrap();
        let x = 0.7;
        let direct = x * x / 2.0 + p.waves().iter().map(|w| w.alpha() * (1.0 - (2.0 * std::f64::consts::PI * x / w.beta()).cos())).sum::<f64>();
        assert!((p.depth(x) - direct).abs() < 1e-15);
        assert_eq!(p.finest_wavelength(), Some(0.375));
        assert!(p.describe().contains("2 waves"));
        assert_eq!(WavyProfile::one_wave(0.3, 1.125).unwrap().describe(), "alpha = 0.3, beta = 1.125");
        assert!(WavyProfile::smooth().is_smooth() && WavyProfile::smooth().finest_wavelength().is_none());
    }
}
