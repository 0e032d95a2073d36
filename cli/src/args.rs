//! Value parsers shared by the `curve`, `profile` and `limits` subcommands.
//!
//! Every numeric flag is checked while the command line is parsed, so a bad value
//! is a clap usage error (exit code 2, one line on stderr) raised before anything
//! is computed or written. Numbers are arithmetic expressions, parsed by the
//! `exmex` crate (all arithmetic in f64, so `1/10` is 0.1): decimals (`0.125`,
//! `1e-1`, `2E6`), fractions (`1/10`, `9/8`), `pi` (or `PI`, `π`), `e`,
//! `sqrt(2)/3`, `2*sqrt(2)/8`, powers (`2^-3`) and the usual functions.
//!
//! The flag groups shared by several subcommands are flattened structs here:
//! [`Roughness`] (`--alpha`, `--beta`) and [`SiArgs`] (`--units si` and the
//! material flags).

use clap::{Args, ValueEnum};
use exmex::prelude::*;
use exmex::{literal_matcher_from_pattern, FloatOpsFactory, MakeOperators, MatchLiteral, Operator};
use maugis::contact::profile::WavyProfile;
use maugis::contact::units::{Cohesion, Material, Physical, Scales};

/// The paper's Fig. 4c amplitude `alpha = 2 sqrt(2)/8` ([`maugis::contact::paper::FIG_4C`]).
pub const FIG4C_ALPHA: f64 = maugis::contact::paper::FIG_4C.alpha;
/// The paper's Fig. 4c wavelength `beta = 9/8`.
pub const FIG4C_BETA: f64 = maugis::contact::paper::FIG_4C.beta;
/// Upper bound on `--points` (keeps a typo from running for hours).
pub const MAX_POINTS: usize = 1_000_000;

/// Largest contact half-width `abar` / `amax` accepted: the library's
/// [`maugis::contact::model::ABAR_MAX`] (the cost grows linearly with it; the
/// paper's range is `abar <= 6`).
pub const MAX_ABAR: f64 = maugis::contact::model::ABAR_MAX;
/// Largest wave argument `2 pi abar/beta` accepted when `alpha > 0`: the
/// library's [`maugis::contact::displacement::MAX_WAVE_D`] (the wave term's
/// Bessel series needs about that many terms per state).
pub const MAX_WAVE_ARG: f64 = maugis::contact::displacement::MAX_WAVE_D;

/// Checks the size of the problem before any work: `abar <= MAX_ABAR`
/// and, with waviness, `2 pi abar/beta <= MAX_WAVE_ARG`. `flag` names the option.
pub fn check_size(flag: &str, abar: f64, alpha: f64, beta: f64) -> Result<(), String> {
    if abar > MAX_ABAR {
        return Err(format!("{flag} must be <= {} (got {})", num(MAX_ABAR), num(abar)));
    }
    let d = 2.0 * std::f64::consts::PI * abar / beta;
    if alpha > 0.0 && d > MAX_WAVE_ARG {
        let name = flag.trim_start_matches('-');
        return Err(format!(
            "2 pi {name}/beta = {} exceeds {}: the wave series would take too long; reduce {flag} or increase --beta",
            num(d),
            num(MAX_WAVE_ARG)
        ));
    }
    Ok(())
}

/// Checks the model parameters with the library's own check
/// ([`maugis::contact::model::Params::new`]), naming the flag.
pub fn check_params(lambdas: &[f64], alpha: f64, beta: f64) -> Result<(), String> {
    use maugis::contact::model::Params;
    // alpha and beta are checked even when no lambda is given (at lambda = 1)
    let lambdas = if lambdas.is_empty() { &[1.0][..] } else { lambdas };
    for &l in lambdas {
        Params::new(l, alpha, beta).map_err(|e| match e {
            maugis::Error::OutOfRange { arg, value, allowed } => format!("--{arg} must lie in {allowed} (got {})", num(value)),
            other => other.to_string(),
        })?;
    }
    Ok(())
}

/// `x` for messages: plain for ordinary magnitudes, scientific otherwise.
pub fn num(x: f64) -> String {
    if x != 0.0 && x.is_finite() && (x.abs() >= 1e6 || x.abs() < 1e-4) {
        format!("{x:e}")
    } else {
        format!("{x}")
    }
}

/// A finite number given as an arithmetic expression (`sqrt(2)/3`, `9/8`, `pi/4`).
pub fn number(s: &str) -> Result<f64, String> {
    let t = s.trim();
    if t.is_empty() {
        return Err("empty value: give a number or an expression like sqrt(2)/3".into());
    }
    let v = Expression::parse(t)
        .and_then(|ex| ex.eval(&[]))
        .map_err(|e| format!("'{s}' is not a number or an arithmetic expression ({e})"))?;
    if !v.is_finite() {
        return Err(format!("'{s}' must be a finite number (not NaN or infinity)"));
    }
    Ok(v)
}

// Literals with an optional exponent (`2e6`, `1.5E-3`); exmex's default has none.
literal_matcher_from_pattern!(DecimalLiteral, r"^([0-9]+(\.[0-9]*)?|\.[0-9]+)([eE][+-]?[0-9]+)?");

/// exmex's float operators plus the constant `pi`.
#[derive(Clone, Debug)]
struct Operators;

impl MakeOperators<f64> for Operators {
    fn make<'a>() -> Vec<Operator<'a, f64>> {
        let mut ops = FloatOpsFactory::<f64>::make();
        ops.push(Operator::make_constant("pi", std::f64::consts::PI));
        ops
    }
}

/// A parsed expression without variables.
type Expression = FlatEx<f64, Operators, DecimalLiteral>;

/// Any finite number.
pub fn finite(s: &str) -> Result<f64, String> {
    number(s)
}

/// A finite number `> 0`.
pub fn positive(s: &str) -> Result<f64, String> {
    let v = number(s)?;
    if v > 0.0 {
        Ok(v)
    } else {
        Err(format!("must be > 0 (got {})", num(v)))
    }
}

/// A finite number `>= 0`.
pub fn non_negative(s: &str) -> Result<f64, String> {
    let v = number(s)?;
    if v >= 0.0 {
        Ok(v)
    } else {
        Err(format!("must be >= 0 (got {})", num(v)))
    }
}

/// A grid size in `2..=MAX_POINTS`.
pub fn grid_points(s: &str) -> Result<usize, String> {
    let n: usize = s.trim().parse().map_err(|_| format!("'{s}' is not a whole number"))?;
    if n < 2 {
        return Err(format!("must be >= 2 (got {n})"));
    }
    if n > MAX_POINTS {
        return Err(format!("must be <= {MAX_POINTS} (got {n})"));
    }
    Ok(n)
}

/// `x` with a few significant digits, trimmed (`0.353553`, `1.125`, `6`).
pub fn short(x: f64) -> String {
    let s = format!("{x:.6}");
    let s = s.trim_end_matches('0').trim_end_matches('.');
    if s == "-0" {
        "0".into()
    } else {
        s.to_string()
    }
}

/// `--alpha` and `--beta` (curve, profile, limits, sweep), and the profiles of many
/// waves: `--wave`, `--waves`, `--weierstrass` (curve, profile, limits, simulate, sweep).
#[derive(Args, Debug, Clone, Default)]
pub struct Roughness {
    /// Normalised wave amplitude alpha >= 0, e.g. 2*sqrt(2)/8 [default: 2 sqrt(2)/8];
    /// in `sweep` the fixed value when alpha is not the swept axis.
    #[arg(long, value_name = "A", value_parser = non_negative, allow_negative_numbers = true)]
    pub alpha: Option<f64>,
    /// Normalised wavelength beta > 0 [default: 9/8]; in `sweep` the fixed value
    /// when beta is not the swept axis.
    #[arg(long, value_name = "B", value_parser = positive, allow_negative_numbers = true)]
    pub beta: Option<f64>,
    /// One wave of the profile, `AMPLITUDE,WAVELENGTH` (normalised alpha_j, beta_j, or
    /// metres with --units si); repeat for a profile of many waves
    /// (`--wave 0.35,9/8 --wave 0.18,3/8`). Replaces --alpha/--beta.
    #[arg(long = "wave", value_name = "A,B", value_parser = wave_pair, allow_hyphen_values = true)]
    pub wave: Vec<(f64, f64)>,
    /// A table of harmonics: CSV lines `amplitude,wavelength` (normalised, or metres
    /// with --units si; `#` comments and a header line allowed). Replaces --alpha/--beta.
    #[arg(long = "waves", value_name = "FILE.csv")]
    pub waves: Option<std::path::PathBuf>,
    /// The Weierstrass profile of N scales below the first wave (--alpha/--beta or
    /// one --wave): wave j = 0..N-1 has wavelength beta gamma^-j and amplitude
    /// alpha gamma^(-H j); gamma > 1, 0 <= H <= 1.
    #[arg(long, value_name = "N,GAMMA,H", value_parser = weierstrass_triple)]
    pub weierstrass: Option<(usize, f64, f64)>,
}

impl Roughness {
    /// `(alpha, beta)` with the Fig. 4c defaults.
    pub fn values(&self) -> (f64, f64) {
        (self.alpha.unwrap_or(FIG4C_ALPHA), self.beta.unwrap_or(FIG4C_BETA))
    }

    /// Whether a flag of many waves (--wave, --waves, --weierstrass) was given.
    pub fn many_waves_given(&self) -> bool {
        !self.wave.is_empty() || self.waves.is_some() || self.weierstrass.is_some()
    }

    /// The flags given, for the conflict checks of `--units si`.
    pub fn given(&self) -> [(&'static str, bool); 5] {
        [
            ("--alpha", self.alpha.is_some()),
            ("--beta", self.beta.is_some()),
            ("--wave", !self.wave.is_empty()),
            ("--waves", self.waves.is_some()),
            ("--weierstrass", self.weierstrass.is_some()),
        ]
    }

    /// The waves as given, in the flags' units (normalised, or metres with --units si),
    /// `None` when only --alpha/--beta (or nothing) was given: read from --waves, or
    /// --wave, and expanded by --weierstrass. Errors name the flag (and the file's line).
    pub fn wave_pairs(&self) -> Result<Option<Vec<(f64, f64)>>, String> {
        if !self.many_waves_given() {
            return Ok(None);
        }
        if !self.wave.is_empty() || self.waves.is_some() {
            for (flag, given) in [("--alpha", self.alpha.is_some()), ("--beta", self.beta.is_some())] {
                if given {
                    return Err(format!("{flag} conflicts with --wave/--waves (give the first wave as --wave AMPLITUDE,WAVELENGTH)"));
                }
            }
        }
        if !self.wave.is_empty() && self.waves.is_some() {
            return Err("--wave conflicts with --waves: give the waves one way".into());
        }
        let mut pairs = if let Some(path) = &self.waves {
            let text = std::fs::read_to_string(path).map_err(|e| format!("--waves {}: {e}", path.display()))?;
            maugis::contact::profile::parse_harmonics(&text)
                .map_err(|e| format!("--waves {}: {e}", path.display()))?
                .into_iter()
                .map(|(_, a, b)| (a, b))
                .collect()
        } else if !self.wave.is_empty() {
            self.wave.clone()
        } else {
            vec![self.values()]
        };
        if let Some((n, gamma, hurst)) = self.weierstrass {
            let [(alpha, beta)] = pairs[..] else {
                return Err(format!("--weierstrass expands one first wave, got {} (give --alpha/--beta or one --wave)", pairs.len()));
            };
            let p = maugis::contact::profile::WavyProfile::weierstrass(alpha, beta, n, gamma, hurst)
                .map_err(|e| format!("--weierstrass: {e}"))?;
            pairs = p.waves().iter().map(|w| (w.alpha(), w.beta())).collect();
        }
        Ok(Some(pairs))
    }

    /// The profile in normalised units: the one wave of --alpha/--beta (Fig. 4c
    /// defaults), or the waves of --wave/--waves/--weierstrass, checked by the library
    /// (an error names the wave and the field).
    pub fn profile(&self) -> Result<WavyProfile, String> {
        match self.wave_pairs()? {
            None => {
                let (alpha, beta) = self.values();
                check_params(&[], alpha, beta)?;
                WavyProfile::one_wave(alpha, beta).map_err(|e| e.to_string())
            }
            Some(pairs) => WavyProfile::from_pairs(&pairs).map_err(|e| format!("{}: {e}", self.waves_flag())),
        }
    }

    /// The flag the waves came from, for messages.
    fn waves_flag(&self) -> String {
        match (&self.waves, self.weierstrass.is_some()) {
            (Some(p), _) => format!("--waves {}", p.display()),
            (None, true) => "--weierstrass".into(),
            (None, false) => "--wave".into(),
        }
    }
}

/// `AMPLITUDE,WAVELENGTH`: two numbers (expressions allowed), amplitude >= 0 and
/// wavelength > 0.
pub fn wave_pair(s: &str) -> Result<(f64, f64), String> {
    let parts: Vec<&str> = s.split(',').collect();
    let [a, b] = parts[..] else {
        return Err(format!("'{s}' is not AMPLITUDE,WAVELENGTH (two numbers separated by a comma)"));
    };
    let a = non_negative(a).map_err(|e| format!("amplitude: {e}"))?;
    let b = positive(b).map_err(|e| format!("wavelength: {e}"))?;
    Ok((a, b))
}

/// `N,GAMMA,H`: a whole number of scales and two numbers.
pub fn weierstrass_triple(s: &str) -> Result<(usize, f64, f64), String> {
    let parts: Vec<&str> = s.split(',').collect();
    let [n, g, h] = parts[..] else {
        return Err(format!("'{s}' is not N,GAMMA,H (three values separated by commas)"));
    };
    let n: usize = n.trim().parse().map_err(|_| format!("N: '{n}' is not a whole number"))?;
    let max = maugis::contact::profile::MAX_WAVES;
    if !(1..=max).contains(&n) {
        return Err(format!("N must lie in 1..={max} (got {n})"));
    }
    let g = number(g).map_err(|e| format!("GAMMA: {e}"))?;
    if !(g > 1.0) {
        return Err(format!("GAMMA must be > 1 (got {})", num(g)));
    }
    let h = number(h).map_err(|e| format!("H: {e}"))?;
    if !(0.0..=1.0).contains(&h) {
        return Err(format!("H must lie in [0, 1] (got {})", num(h)));
    }
    Ok((n, g, h))
}

/// Checks the size of a profile's problem before any work: `abar <= MAX_ABAR` and,
/// for every wave with an amplitude, `2 pi abar/beta_j <= MAX_WAVE_ARG`. One wave:
/// [`check_size`]'s messages.
pub fn check_profile_size(flag: &str, abar: f64, profile: &WavyProfile) -> Result<(), String> {
    if let [w] = profile.waves() {
        return check_size(flag, abar, w.alpha(), w.beta());
    }
    check_size(flag, abar, 0.0, 1.0)?;
    for (j, w) in profile.waves().iter().enumerate() {
        let d = 2.0 * std::f64::consts::PI * abar / w.beta();
        if w.alpha() > 0.0 && d > MAX_WAVE_ARG {
            let name = flag.trim_start_matches('-');
            return Err(format!(
                "wave {}: 2 pi {name}/beta = {} exceeds {}: the wave series would take too long; reduce {flag} or lengthen the wave",
                j + 1,
                num(d),
                num(MAX_WAVE_ARG)
            ));
        }
    }
    Ok(())
}

/// Checks every lambda with a profile (one wave: [`check_params`]'s messages).
pub fn check_profile_params(lambdas: &[f64], profile: &WavyProfile) -> Result<(), String> {
    if let [w] = profile.waves() {
        return check_params(lambdas, w.alpha(), w.beta());
    }
    use maugis::contact::model::Params;
    let lambdas = if lambdas.is_empty() { &[1.0][..] } else { lambdas };
    for &l in lambdas {
        Params::with_profile(l, *profile).map_err(|e| match e {
            maugis::Error::OutOfRange { arg, value, allowed } => format!("--{arg} must lie in {allowed} (got {})", num(value)),
            other => other.to_string(),
        })?;
    }
    Ok(())
}

/// The profile for titles and reports: `α = 0.353553, β = 1.125` for one wave,
/// `2 waves (α, β) = (0.3536, 1.125) + (0.1768, 0.375)` otherwise (four significant
/// digits, at most six waves listed, so that a title fits its picture).
pub fn profile_title(profile: &WavyProfile) -> String {
    match profile.waves() {
        [] => "smooth cylinder".into(),
        [w] => format!("α = {}, β = {}", short(w.alpha()), short(w.beta())),
        ws => {
            let shown: Vec<String> = ws.iter().take(6).map(|w| format!("({}, {})", sig4(w.alpha()), sig4(w.beta()))).collect();
            let more = if ws.len() > 6 { format!(" + {} more", ws.len() - 6) } else { String::new() };
            format!("{} waves (α, β) = {}{more}", ws.len(), shown.join(" + "))
        }
    }
}

/// `x` to four significant digits, trimmed (`0.3536`, `1.125`, `0.25`).
pub fn sig4(x: f64) -> String {
    if x == 0.0 || !x.is_finite() {
        return short(x);
    }
    let digits = (3 - x.abs().log10().floor() as i32).max(0) as usize;
    let s = format!("{x:.digits$}");
    if s.contains('.') { s.trim_end_matches('0').trim_end_matches('.').to_string() } else { s }
}

/// The profile in ASCII for the terminal report: `alpha = 0.353553, beta = 1.125` for
/// one wave (today's wording), `2 waves (alpha, beta) = (0.35, 1.125) + (0.18, 0.375)`.
pub fn profile_report(profile: &WavyProfile) -> String {
    match profile.waves() {
        [w] => format!("alpha = {}, beta = {}", short(w.alpha()), short(w.beta())),
        _ => profile_title(profile).replace('α', "alpha").replace('β', "beta"),
    }
}

/// The CSV columns naming a profile: `alpha,beta` for one wave, `alpha_1,beta_1,alpha_2,..`
/// for several; with their values (full precision, as the CSVs write numbers).
pub fn profile_columns(profile: &WavyProfile) -> (Vec<String>, Vec<String>) {
    match profile.waves() {
        [w] => (vec!["alpha".into(), "beta".into()], vec![w.alpha().to_string(), w.beta().to_string()]),
        ws => {
            let names = ws.iter().enumerate().flat_map(|(j, _)| [format!("alpha_{}", j + 1), format!("beta_{}", j + 1)]).collect();
            let values = ws.iter().flat_map(|w| [w.alpha().to_string(), w.beta().to_string()]).collect();
            (names, values)
        }
    }
}

/// The unit system of the inputs and outputs.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum UnitSystem {
    /// SI: the contact from --e-star, --radius, --dgamma, --sigma or --delta-c, --amplitude, --wavelength.
    Si,
}

/// `--units si` and the material flags (curve, profile, limits).
#[derive(Args, Debug, Clone, Default)]
pub struct SiArgs {
    /// Physical units: `si` takes the contact from the material flags below
    /// instead of --lambda, --alpha and --beta, and adds SI values to the output.
    #[arg(long, value_name = "SYSTEM")]
    pub units: Option<UnitSystem>,
    /// Plane-strain modulus E* = E/(1 - nu^2) in Pa (with --units si).
    #[arg(long = "e-star", value_name = "PA", value_parser = positive, allow_negative_numbers = true)]
    pub e_star: Option<f64>,
    /// Cylinder radius R in m (with --units si).
    #[arg(long, value_name = "M", value_parser = positive, allow_negative_numbers = true)]
    pub radius: Option<f64>,
    /// Work of adhesion dgamma in J/m^2 (with --units si).
    #[arg(long, value_name = "J_M2", value_parser = positive, allow_negative_numbers = true)]
    pub dgamma: Option<f64>,
    /// Dugdale adhesive stress sigma_0 in Pa (with --units si); repeat for several curves.
    #[arg(long, value_name = "PA", value_parser = positive, allow_negative_numbers = true)]
    pub sigma: Vec<f64>,
    /// Dugdale interaction range delta_c = dgamma/sigma_0 in m (with --units si), instead of --sigma.
    #[arg(long = "delta-c", value_name = "M", value_parser = positive, allow_negative_numbers = true)]
    pub delta_c: Vec<f64>,
    /// Wave amplitude A in m (with --units si) [default: 0, smooth].
    #[arg(long, value_name = "M", value_parser = non_negative, allow_negative_numbers = true)]
    pub amplitude: Option<f64>,
    /// Wavelength zeta in m (with --units si; needed when --amplitude > 0).
    #[arg(long, value_name = "M", value_parser = positive, allow_negative_numbers = true)]
    pub wavelength: Option<f64>,
}

/// A run in SI units: the material and one contact per Dugdale strength.
#[derive(Debug, Clone)]
pub struct SiRun {
    /// Material and geometry.
    pub material: Material,
    /// The scales.
    pub scales: Scales,
    /// `lambda` per `--sigma` / `--delta-c`, in the order given.
    pub lambdas: Vec<f64>,
    /// The profile in normalised units: the one wave of --amplitude/--wavelength, or
    /// the waves given in metres by --wave/--waves (with --weierstrass).
    pub profile: WavyProfile,
}

impl SiArgs {
    /// `None` without `--units`; with `--units si` the contact in model units.
    /// `normalised` lists the normalised flags the command was given (they
    /// conflict with `--units si`). Every message names its flag. The waves of
    /// --wave/--waves in metres (`waves_m`) replace --amplitude/--wavelength (which
    /// then conflict).
    pub fn resolve_with_waves(&self, normalised: &[(&str, bool)], waves_m: Option<&[(f64, f64)]>) -> Result<Option<SiRun>, String> {
        let given = [
            ("--e-star", self.e_star.is_some()),
            ("--radius", self.radius.is_some()),
            ("--dgamma", self.dgamma.is_some()),
            ("--sigma", !self.sigma.is_empty()),
            ("--delta-c", !self.delta_c.is_empty()),
            ("--amplitude", self.amplitude.is_some()),
            ("--wavelength", self.wavelength.is_some()),
        ];
        let Some(UnitSystem::Si) = self.units else {
            if let Some((flag, _)) = given.iter().find(|g| g.1) {
                return Err(format!("{flag} needs --units si"));
            }
            return Ok(None);
        };
        if let Some((flag, _)) = normalised.iter().find(|g| g.1) {
            return Err(format!("{flag} conflicts with --units si (give the material: --e-star, --radius, --dgamma, --sigma or --delta-c, --amplitude, --wavelength)"));
        }
        let need = |v: Option<f64>, flag: &str| v.ok_or_else(|| format!("--units si needs {flag}"));
        let material = Material { e_star: need(self.e_star, "--e-star")?, radius: need(self.radius, "--radius")?, dgamma: need(self.dgamma, "--dgamma")? };
        let cohesions: Vec<Cohesion> = match (self.sigma.is_empty(), self.delta_c.is_empty()) {
            (false, true) => self.sigma.iter().map(|&s| Cohesion::Stress(s)).collect(),
            (true, false) => self.delta_c.iter().map(|&d| Cohesion::Range(d)).collect(),
            (true, true) => return Err("--units si needs --sigma or --delta-c".into()),
            (false, false) => return Err("--sigma conflicts with --delta-c: give one of them".into()),
        };
        let amplitude = self.amplitude.unwrap_or(0.0);
        let scales = Scales::new(material).map_err(|e| format!("--e-star/--radius/--dgamma: {e}"))?;
        if let Some(waves_m) = waves_m {
            for (flag, given) in [("--amplitude", self.amplitude.is_some()), ("--wavelength", self.wavelength.is_some())] {
                if given {
                    return Err(format!("{flag} conflicts with --wave/--waves (with --units si they give the waves in metres)"));
                }
            }
            let profile = scales.profile_from_si(waves_m).map_err(|e| format!("--wave/--waves (in metres): {e}"))?;
            let mut lambdas = Vec::new();
            for c in cohesions {
                let flag = if matches!(c, Cohesion::Stress(_)) { "--sigma" } else { "--delta-c" };
                let lambda = scales.lambda(c).map_err(|e| format!("{flag}: {e}"))?;
                check_profile_params(&[lambda], &profile).map_err(|e| e.replace("--lambda", &format!("lambda = l_v/delta_c from {flag}")))?;
                lambdas.push(lambda);
            }
            return Ok(Some(SiRun { material, scales, lambdas, profile }));
        }
        // smooth: the wavelength does not enter; take l_h
        let wavelength = match self.wavelength {
            Some(z) => z,
            None if amplitude == 0.0 => scales.horizontal,
            None => return Err("--amplitude > 0 needs --wavelength".into()),
        };
        let mut lambdas = Vec::new();
        let (mut alpha, mut beta) = (0.0, 1.0);
        for c in cohesions {
            let flag = if matches!(c, Cohesion::Stress(_)) { "--sigma" } else { "--delta-c" };
            let p = Physical { material, cohesion: c, amplitude, wavelength };
            let lambda = scales.lambda(c).map_err(|e| format!("{flag}: {e}"))?;
            alpha = scales.alpha(amplitude).map_err(|e| format!("--amplitude: {e}"))?;
            beta = scales.beta(wavelength).map_err(|e| format!("--wavelength: {e}"))?;
            check_params(&[lambda], alpha, beta).map_err(|e| {
                let e = e.replace("--lambda", &format!("lambda = l_v/delta_c from {flag}"));
                let e = e.replace("--alpha", "alpha = A/l_v from --amplitude");
                e.replace("--beta", "beta = zeta/l_h from --wavelength")
            })?;
            p.params().map_err(|e| format!("{flag}: {e}"))?;
            lambdas.push(lambda);
        }
        let profile = WavyProfile::one_wave(alpha, beta).map_err(|e| e.to_string())?;
        Ok(Some(SiRun { material, scales, lambdas, profile }))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn parsers() {
        assert_eq!(positive("1/10"), Ok(0.1));
        assert_eq!(positive("9/8"), Ok(1.125));
        assert!(positive("0").is_err());
        assert!(positive("NaN").is_err());
        assert!(positive("inf").is_err());
        assert!(positive("1/0").is_err());
        assert!((positive("sqrt(2)/3").unwrap() - 2f64.sqrt() / 3.0).abs() < 1e-16);
        assert_eq!(positive("2*sqrt(2)/8"), Ok(FIG4C_ALPHA));
        assert_eq!(positive("pi/4"), Ok(std::f64::consts::FRAC_PI_4));
        assert_eq!(positive("1e-1"), Ok(0.1));
        assert_eq!(positive("2E6"), Ok(2e6));
        assert_eq!(positive("1.5e+3/3"), Ok(500.0));
        assert_eq!(positive("pi"), Ok(std::f64::consts::PI));
        assert_eq!(positive("2^-3"), Ok(0.125));
        assert_eq!(positive(".5"), Ok(0.5));
        assert!(positive("1e").is_err());
        assert!(positive("sqrt(-1)").is_err());
        assert!(positive("2 +").is_err());
        assert!(positive("").is_err());
        assert!(non_negative("-1").is_err());
        assert_eq!(non_negative("0"), Ok(0.0));
        assert!(grid_points("1").is_err());
        assert_eq!(grid_points("2"), Ok(2));
        assert_eq!(short(0.1), "0.1");
        assert_eq!(short(6.0), "6");
        assert_eq!(short(FIG4C_ALPHA), "0.353553");
        assert_eq!(num(1e300), "1e300");
        assert_eq!(num(0.25), "0.25");
        assert!(check_size("--amax", 6.0, FIG4C_ALPHA, FIG4C_BETA).is_ok());
        assert!(check_size("--amax", 1e5, 0.0, 1.0).is_err());
        assert!(check_size("--amax", 6.0, 0.3, 1e-5).is_err());
        assert!(check_size("--amax", 6.0, 0.0, 1e-5).is_ok());
    }
}
