//! `maugis multiscale`: the multi-scale roughness studies of docs/multiscale.md
//! (issue 39). The computing is the library's (`maugis::contact::multiscale`); this
//! file parses, runs with a progress bar and writes.
//!
//! `maugis multiscale envelope`: for Weierstrass profiles below one wave, the
//! envelope constants (the triangle sum `T` and the phase-locked `M+`, `M-`) and the
//! largest excursion of the model's load-area curve outside them, over a grid of
//! `(N, gamma, H, lambda)`. Files in `--out`: `envelope.csv` (one row per case),
//! `envelope.json`, `envelope.md` (the table of docs/multiscale.md: per profile, the
//! worst ratio over lambda), `envelope.svg` (the ratios against lambda) and
//! `envelope-wave.svg` (the wave part `w(a)` of one profile against its envelopes).
//!
//! `maugis multiscale scales` / `merge` (`multiscale/scales.rs`): W and cavitation
//! against the number of scales, with the numerical solver, sharded.

use std::fmt::Write as _;
use std::path::PathBuf;

use clap::{Args, Subcommand, ValueEnum};
use plotters::prelude::*;
use serde::Serialize;

use maugis::contact::curve::load_area_curve;
use maugis::contact::model::Params;
use maugis::contact::multiscale::{envelope_constants, envelope_curve_options, wave_part, EnvelopeRow, EnvelopeStudy};
use maugis::contact::profile::WavyProfile;

mod scales;

use crate::args::{self, short};
use crate::curve::progress;
use crate::output::{check_out_dir, print_stdout, write_atomically, OutFile};
use crate::plot::{clip_y, colour, finish_load_area_chart, plot_err, xy_chart, Legend, DARK_GREY, LEGEND_FONT, LEGEND_WIDTH, LIGHT_GREY};

/// Flags of `maugis multiscale`.
#[derive(Args, Debug)]
pub struct MultiscaleArgs {
    /// The study.
    #[command(subcommand)]
    pub study: Study,
}

/// The studies.
#[derive(Subcommand, Debug)]
pub enum Study {
    /// Envelope constants of Weierstrass profiles and the model's largest excursion outside them.
    Envelope(EnvelopeArgs),
    /// W and cavitation against the number of scales: solver cycles of Weierstrass
    /// profiles of 1..N scales, the single scales and the model beside them (sharded).
    Scales(scales::ScalesArgs),
    /// Merge the output directories of `maugis multiscale scales --shard s/n` runs (or
    /// redraw one whole study's tables and figure from its scales.json).
    Merge(scales::ScalesMergeArgs),
    /// The transitional lambda* against the number of scales: the lambda below which the
    /// solver's roughness-induced W falls under a fraction of the JKR limit's.
    Transition(scales::TransitionArgs),
}

/// Output format.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum StudyFormat {
    /// CSV, JSON, Markdown table and SVGs in --out.
    Files,
    /// The CSV table on stdout, no files.
    Csv,
    /// One JSON object on stdout, no files.
    Json,
}

/// Flags of `maugis multiscale envelope`.
#[derive(Args, Debug)]
pub struct EnvelopeArgs {
    /// Amplitude alpha_1 of the first (coarsest) wave.
    #[arg(long, value_name = "A", default_value = "2*sqrt(2)/8", value_parser = args::non_negative, allow_negative_numbers = true)]
    pub alpha: f64,
    /// Wavelength beta_1 of the first wave.
    #[arg(long, value_name = "B", default_value = "9/8", value_parser = args::positive, allow_negative_numbers = true)]
    pub beta: f64,
    /// Numbers of scales N (comma-separated or repeated).
    #[arg(long, value_name = "N", value_delimiter = ',', default_values_t = vec![2usize, 3, 4], value_parser = clap::value_parser!(usize))]
    pub scales: Vec<usize>,
    /// Wavelength ratios gamma > 1.
    #[arg(long, value_name = "GAMMA", value_delimiter = ',', default_value = "2,3", value_parser = args::positive, allow_negative_numbers = true)]
    pub gamma: Vec<f64>,
    /// Hurst exponents H in [0, 1].
    #[arg(long, value_name = "H", value_delimiter = ',', default_value = "0.3,0.5,0.8", value_parser = args::non_negative, allow_negative_numbers = true)]
    pub hurst: Vec<f64>,
    /// Maugis parameters.
    #[arg(long, value_name = "L", value_delimiter = ',', default_value = "1/10,3/10,1,3,10,30,100", value_parser = args::positive, allow_negative_numbers = true)]
    pub lambda: Vec<f64>,
    /// Largest contact half-width of every curve.
    #[arg(long, value_name = "AMAX", default_value = "6", value_parser = args::positive, allow_negative_numbers = true)]
    pub amax: f64,
    /// The profile of envelope-wave.svg, N,GAMMA,H.
    #[arg(long, value_name = "N,GAMMA,H", default_value = "4,2,0.5", value_parser = args::weierstrass_triple)]
    pub figure: (usize, f64, f64),
    /// Output directory (written atomically).
    #[arg(long, value_name = "DIR", default_value = "maugis-out")]
    pub out: PathBuf,
    /// `files` (default), `csv` or `json` (print to stdout, write nothing).
    #[arg(long, value_name = "FORMAT", default_value = "files")]
    pub format: StudyFormat,
}

/// Runs `maugis multiscale`.
pub fn run(a: MultiscaleArgs) -> Result<(), String> {
    match a.study {
        Study::Envelope(e) => run_envelope(e),
        Study::Scales(s) => scales::run_scales(s),
        Study::Merge(m) => scales::run_merge(m),
        Study::Transition(t) => scales::run_transition(t),
    }
}

#[derive(Serialize)]
struct EnvelopeJson<'a> {
    study: &'a EnvelopeStudy,
    rows: &'a [EnvelopeRow],
}

/// `x`, or an empty cell when it is not finite (no valid state).
fn cell(x: f64) -> String {
    if x.is_finite() {
        x.to_string()
    } else {
        String::new()
    }
}

/// The columns of envelope.csv.
const COLUMNS: [&str; 23] = [
    "scales",
    "gamma",
    "hurst",
    "lambda",
    "points",
    "triangle",
    "upper",
    "lower",
    "sampling_error",
    "states",
    "local_up",
    "local_down",
    "global_up",
    "global_down",
    "valid_states",
    "valid_local_up",
    "valid_local_down",
    "valid_global_up",
    "valid_global_down",
    "local_up_ratio",
    "local_down_ratio",
    "jkr_up",
    "jkr_down",
];

fn envelope_csv(rows: &[EnvelopeRow]) -> Result<String, String> {
    let mut w = csv::Writer::from_writer(Vec::new());
    let err = |e: csv::Error| format!("could not format CSV: {e}");
    w.write_record(COLUMNS).map_err(err)?;
    for r in rows {
        let (c, all, valid) = (r.constants, r.excursion.all, r.excursion.valid);
        let record = [
            r.scales.to_string(),
            cell(r.gamma),
            cell(r.hurst),
            cell(r.lambda),
            r.points.to_string(),
            cell(c.triangle),
            cell(c.upper),
            cell(c.lower),
            cell(c.sampling_error),
            all.states.to_string(),
            cell(all.local_up),
            cell(all.local_down),
            cell(all.global_up),
            cell(all.global_down),
            valid.states.to_string(),
            cell(valid.local_up),
            cell(valid.local_down),
            cell(valid.global_up),
            cell(valid.global_down),
            cell(all.local_up / c.upper),
            cell(all.local_down / c.lower),
            cell(r.jkr.0),
            cell(r.jkr.1),
        ];
        w.write_record(record).map_err(err)?;
    }
    let bytes = w.into_inner().map_err(|e| format!("could not format CSV: {e}"))?;
    String::from_utf8(bytes).map_err(|e| format!("could not format CSV: {e}"))
}

/// The worst of `f` over the rows of one profile (`-inf` when none is finite).
fn worst(rows: &[&EnvelopeRow], f: impl Fn(&EnvelopeRow) -> f64) -> (f64, f64) {
    rows.iter().map(|r| (f(r), r.lambda)).filter(|v| v.0.is_finite()).fold((f64::NEG_INFINITY, f64::NAN), |a, b| if b.0 > a.0 { b } else { a })
}

/// A ratio and the lambda where it is reached, for the Markdown table.
fn ratio_cell((ratio, lambda): (f64, f64)) -> String {
    if ratio.is_finite() {
        format!("{ratio:.3} ({})", short(lambda))
    } else {
        "-".into()
    }
}

/// The table of docs/multiscale.md: one line per profile, the worst ratio over lambda.
fn envelope_md(study: &EnvelopeStudy, rows: &[EnvelopeRow]) -> String {
    let mut md = String::new();
    let _ = writeln!(
        md,
        "| N | gamma | H | T | M+ | M- | JKR up / M+ | JKR down / M- | local up / M+ | local down / M- | global up / M+ | global down / M- | valid: local up / M+ | valid: local down / M- |"
    );
    let _ = writeln!(md, "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|");
    for &n in &study.scales {
        for &gamma in &study.gammas {
            for &hurst in &study.hursts {
                let group: Vec<&EnvelopeRow> = rows.iter().filter(|r| r.scales == n && r.gamma == gamma && r.hurst == hurst).collect();
                let Some(first) = group.first() else { continue };
                let c = first.constants;
                let _ = writeln!(
                    md,
                    "| {n} | {} | {} | {:.3} | {:.3} | {:.3} | {:.3} | {:.3} | {} | {} | {} | {} | {} | {} |",
                    short(gamma),
                    short(hurst),
                    c.triangle,
                    c.upper,
                    c.lower,
                    first.jkr.0 / c.upper,
                    first.jkr.1 / c.lower,
                    ratio_cell(worst(&group, |r| r.excursion.all.local_up / r.constants.upper)),
                    ratio_cell(worst(&group, |r| r.excursion.all.local_down / r.constants.lower)),
                    ratio_cell(worst(&group, |r| r.excursion.all.global_up / r.constants.upper)),
                    ratio_cell(worst(&group, |r| r.excursion.all.global_down / r.constants.lower)),
                    ratio_cell(worst(&group, |r| r.excursion.valid.local_up / r.constants.upper)),
                    ratio_cell(worst(&group, |r| r.excursion.valid.local_down / r.constants.lower)),
                );
            }
        }
    }
    md
}

fn run_envelope(a: EnvelopeArgs) -> Result<(), String> {
    let study = EnvelopeStudy {
        alpha_1: a.alpha,
        beta_1: a.beta,
        scales: a.scales.clone(),
        gammas: a.gamma.clone(),
        hursts: a.hurst.clone(),
        lambdas: a.lambda.clone(),
        amax: a.amax,
    };
    // every profile checked before any work (a bad value is named at once)
    for &(n, gamma, hurst, lambda) in &study.cases() {
        let profile = WavyProfile::weierstrass(a.alpha, a.beta, n, gamma, hurst).map_err(|e| e.to_string())?;
        Params::with_profile(lambda, profile).map_err(|e| e.to_string())?;
        envelope_curve_options(&profile, a.amax).map_err(|e| format!("N = {n}, gamma = {}: {e}", short(gamma)))?;
    }
    if study.cases().is_empty() {
        return Err("nothing to compute: give at least one value of --scales, --gamma, --hurst and --lambda".into());
    }
    let (fn_, fg, fh) = a.figure;
    let figure_profile = WavyProfile::weierstrass(a.alpha, a.beta, fn_, fg, fh).map_err(|e| format!("--figure: {e}"))?;
    if figure_profile.coarsest_wavelength().is_some_and(|b| a.amax <= b) || a.amax <= a.beta {
        return Err(format!("--amax {} must exceed the first wavelength {} (the excursions are measured where abar >= beta_1)", short(a.amax), short(a.beta)));
    }
    if a.format == StudyFormat::Files {
        check_out_dir(&a.out)?;
    }
    let cases = study.cases();
    let pb = progress(cases.len() as u64, "envelope: load-area curves");
    let mut rows = Vec::with_capacity(cases.len());
    for &case in &cases {
        let (n, gamma, hurst, lambda) = case;
        let row = study.row(case).map_err(|e| format!("N = {n}, gamma = {}, H = {}, lambda = {}: {e}", short(gamma), short(hurst), short(lambda)))?;
        rows.push(row);
        pb.inc(1);
    }
    pb.finish_and_clear();
    match a.format {
        StudyFormat::Csv => print_stdout(&envelope_csv(&rows)?),
        StudyFormat::Json => {
            let text = serde_json::to_string(&EnvelopeJson { study: &study, rows: &rows }).map_err(|e| format!("could not format JSON: {e}"))?;
            print_stdout(&format!("{text}\n"))
        }
        StudyFormat::Files => {
            let json = serde_json::to_string_pretty(&EnvelopeJson { study: &study, rows: &rows }).map_err(|e| format!("could not format JSON: {e}"))?;
            let files = [
                OutFile::text("envelope.csv", envelope_csv(&rows)?),
                OutFile::text("envelope.json", json + "\n"),
                OutFile::text("envelope.md", envelope_md(&study, &rows)),
                OutFile::text("envelope.svg", ratios_svg(&study, &rows)?),
                OutFile::text("envelope-wave.svg", wave_svg(&figure_profile, &study)?),
            ];
            let written = write_atomically(&a.out, &files)?;
            let mut report = String::new();
            let _ = writeln!(report, "maugis multiscale envelope: {} cases ({} profiles x {} lambda)", rows.len(), rows.len() / study.lambdas.len().max(1), study.lambdas.len());
            let _ = write!(report, "{}", envelope_md(&study, &rows));
            let _ = writeln!(report, "wrote {} file(s) to {}:", written.len(), a.out.display());
            for p in &written {
                let _ = writeln!(report, "  {}", p.display());
            }
            print_stdout(&report)
        }
    }
}

/// A line style.
fn line(c: RGBColor, w: u32) -> ShapeStyle {
    ShapeStyle { color: c.to_rgba(), filled: false, stroke_width: w }
}

/// The ratios `local_up/M+` and `local_down/M-` against lambda (log axis), one line
/// per profile, colour by `N`, dash by `gamma`, width by `H`.
fn ratios_svg(study: &EnvelopeStudy, rows: &[EnvelopeRow]) -> Result<String, String> {
    let lmin = study.lambdas.iter().copied().fold(f64::INFINITY, f64::min);
    let lmax = study.lambdas.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    let (x0, x1) = (lmin.log10() - 0.1, lmax.log10() + 0.1);
    let ratios = rows.iter().flat_map(|r| [r.excursion.all.local_up / r.constants.upper, r.excursion.all.local_down / r.constants.lower]).filter(|v| v.is_finite());
    let (lo, hi) = ratios.fold((1.0f64, 1.0f64), |(lo, hi), v| (lo.min(v), hi.max(v)));
    let (y0, y1) = ((lo - 0.05).max(0.0), hi + 0.05);
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, (1300 + LEGEND_WIDTH, 900)).into_drawing_area();
        root.fill(&WHITE).map_err(plot_err)?;
        let title = "Largest excursion of the wave part over the phase-locked envelope".to_string();
        let mut chart = xy_chart(&root, title, (x0, x1), (y0, y1), ("log10 lambda", "max w/M+ (solid), max -w/M- (dashed)"))?;
        let mut legend = Legend::new(LEGEND_FONT);
        chart.draw_series(LineSeries::new(vec![(x0, 1.0), (x1, 1.0)], line(DARK_GREY, 2))).map_err(plot_err)?;
        legend.line("the envelope (ratio 1)", line(DARK_GREY, 2), 0, 0);
        for (i, &n) in study.scales.iter().enumerate() {
            for &gamma in &study.gammas {
                for (k, &hurst) in study.hursts.iter().enumerate() {
                    let group: Vec<&EnvelopeRow> = rows.iter().filter(|r| r.scales == n && r.gamma == gamma && r.hurst == hurst).collect();
                    let up: Vec<(f64, f64)> = group.iter().map(|r| (r.lambda.log10(), r.excursion.all.local_up / r.constants.upper)).collect();
                    let down: Vec<(f64, f64)> = group.iter().map(|r| (r.lambda.log10(), r.excursion.all.local_down / r.constants.lower)).collect();
                    let st = line(colour(i + if gamma > 2.5 { 3 } else { 0 }), 1 + k as u32);
                    chart.draw_series(LineSeries::new(up, st)).map_err(plot_err)?;
                    for piece in clip_y(&down, y0, y1) {
                        chart.draw_series(DashedLineSeries::new(piece, 10, 6, st)).map_err(plot_err)?;
                    }
                    if k == study.hursts.len() - 1 {
                        legend.line(format!("N = {n}, gamma = {} (H = {}: thin to thick)", short(gamma), study.hursts.iter().map(|h| short(*h)).collect::<Vec<_>>().join(", ")), st, 0, 0);
                    }
                }
            }
        }
        finish_load_area_chart(&chart, &root, &legend)?;
    }
    Ok(svg)
}

/// The wave part `w(a)` of one profile at the study's smallest, middle and largest
/// lambda, with `+M+`, `-M-` and `+/-T`.
fn wave_svg(profile: &WavyProfile, study: &EnvelopeStudy) -> Result<String, String> {
    let mut lambdas = study.lambdas.clone();
    lambdas.sort_by(f64::total_cmp);
    lambdas.dedup();
    let picks: Vec<f64> = match lambdas.len() {
        0 => vec![],
        1 | 2 => lambdas.clone(),
        n => vec![lambdas[0], lambdas[n / 2], lambdas[n - 1]],
    };
    let c = envelope_constants(profile);
    let options = envelope_curve_options(profile, study.amax).map_err(|e| e.to_string())?;
    let mut series = Vec::new();
    for &lambda in &picks {
        let params = Params::with_profile(lambda, *profile).map_err(|e| e.to_string())?;
        let curve = load_area_curve(params, options).map_err(|e| format!("lambda = {}: {e}", short(lambda)))?;
        series.push((lambda, wave_part(&curve).map_err(|e| e.to_string())?));
    }
    let ylim = 1.15 * c.triangle;
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, (1300 + LEGEND_WIDTH, 900)).into_drawing_area();
        root.fill(&WHITE).map_err(plot_err)?;
        let title = format!("Wave part of the load, {}", args::profile_title(profile));
        let mut chart = xy_chart(&root, title, (0.0, study.amax), (-ylim, ylim), ("contact half-width abar", "w = (L - L_smooth(λ))/sqrt(abar)"))?;
        let mut legend = Legend::new(LEGEND_FONT);
        let flat = |y: f64| vec![(0.0, y), (study.amax, y)];
        chart.draw_series(DashedLineSeries::new(flat(c.triangle), 18, 7, line(LIGHT_GREY, 2))).map_err(plot_err)?;
        chart.draw_series(DashedLineSeries::new(flat(-c.triangle), 18, 7, line(LIGHT_GREY, 2))).map_err(plot_err)?;
        legend.line(format!("± T = ± {:.3} (sum of the waves' envelopes)", c.triangle), line(LIGHT_GREY, 2), 18, 7);
        chart.draw_series(LineSeries::new(flat(c.upper), line(DARK_GREY, 2))).map_err(plot_err)?;
        chart.draw_series(LineSeries::new(flat(-c.lower), line(DARK_GREY, 2))).map_err(plot_err)?;
        legend.line(format!("+M+ = {:.3}, -M- = -{:.3} (phase-locked)", c.upper, c.lower), line(DARK_GREY, 2), 0, 0);
        let beta_1 = profile.coarsest_wavelength().unwrap_or(0.0);
        chart.draw_series(DashedLineSeries::new(vec![(beta_1, -ylim), (beta_1, ylim)], 4, 6, line(DARK_GREY, 1))).map_err(plot_err)?;
        legend.line(format!("abar = beta_1 = {} (measured to its right)", short(beta_1)), line(DARK_GREY, 1), 4, 6);
        for (i, (lambda, pts)) in series.iter().enumerate() {
            let st = line(colour(i), 2);
            let xy: Vec<(f64, f64)> = pts.iter().map(|p| (p.0, p.1)).collect();
            for piece in clip_y(&xy, -ylim, ylim) {
                chart.draw_series(LineSeries::new(piece, st)).map_err(plot_err)?;
            }
            legend.line(format!("λ = {}", short(*lambda)), st, 0, 0);
        }
        finish_load_area_chart(&chart, &root, &legend)?;
    }
    Ok(svg)
}
