//! `maugis curve`: load-area responses `Lbar(abar)` for several Maugis
//! parameters, with turning points, jumps under load control, pull-off and the
//! validity (cavitation / interpenetration) of every state.
//!
//! Without arguments it reproduces the setting of the paper's Fig. 4c:
//! `alpha = 2 sqrt(2)/8`, `beta = 9/8`, `lambda in {1/10, 1/4, 1/2, 1, 3/2, 3, 6}`,
//! `abar in (0, 6]` on 600 points, and writes into `maugis-out/`:
//!
//! * `curve_lambda_<L>.csv`: `abar,m,load,valid,min_strip_gap,max_traction`;
//! * `summary.json`: parameters and, per lambda, turning points, jumps,
//!   pull-off, the number of invalid states and the invalid `abar` stretches;
//! * `load-area.svg`: all curves with the Appendix E limits and envelopes
//!   (`--amin`, `--ymin`, `--ymax` set the window; the legend sits outside the data);
//! * `load-approach.svg`: `Lbar(Delta-bar)` of every curve, with pull-off.
//!
//! `--format json` writes no file and prints one JSON object instead (see
//! the library's [`RunSummary`]). The curves are computed in parallel (rayon); a progress bar is
//! shown on stderr when it is a terminal. Files are written atomically
//! ([`crate::output`]).

use std::io::IsTerminal;
use std::fmt::Write as _;
use std::path::PathBuf;
use std::time::{Duration, Instant};

use clap::{Args, ValueEnum};
use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};
use plotters::prelude::*;

use maugis::contact::curve::{Curve, CurveOptions, CurvePoint, JumpDirection, TurningKind};
use maugis::contact::located::At;
use maugis::contact::profile::WavyProfile;
use maugis::contact::summary::{load_area_curves_profile, RunSummary};
use maugis::contact::limits::{appendix_e_rows, AppendixE};
use maugis::contact::model::Params;

use maugis::contact::summary::SiSummary;
use maugis::contact::units::Scales;
use serde::Serialize;

use crate::args::{self, num, short, Roughness, SiArgs, SiRun};
use crate::output::{check_out_dir, print_stdout, write_atomically, OutFile};
use crate::plot::{arrow_head, clip_y, colour, finish_load_area_chart, plot_err, triangle_down, triangle_up, xy_chart, Legend, Mark, DARK_GREY, LEGEND_FONT, LIGHT_GREY};

/// The Maugis parameters of the paper's Figs. 4 and 13 (default run).
pub const DEFAULT_LAMBDAS: [f64; 7] = maugis::contact::paper::MAIN_LAMBDAS;

/// Output format.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum CurveFormat {
    /// CSV per lambda, summary.json and load-area.svg in --out.
    Files,
    /// One JSON object on stdout, no files.
    Json,
}

/// Flags of `maugis curve`.
#[derive(Args, Debug)]
pub struct CurveArgs {
    /// Maugis parameter lambda > 0; repeat for several curves
    /// [default: 1/10 1/4 1/2 1 3/2 3 6]. Expressions like 1/10 or sqrt(2)/3 are accepted.
    #[arg(long = "lambda", value_name = "L", value_parser = args::positive, allow_negative_numbers = true)]
    pub lambda: Vec<f64>,
    /// --alpha, --beta.
    #[command(flatten)]
    pub roughness: Roughness,
    /// --units si and the material.
    #[command(flatten)]
    pub si: SiArgs,
    /// Largest contact half-width abar.
    #[arg(long, value_name = "AMAX", default_value = "6", value_parser = args::positive, allow_negative_numbers = true)]
    pub amax: f64,
    /// Grid points per curve, abar_i = amax i/points.
    #[arg(long, value_name = "N", default_value = "600", value_parser = args::grid_points)]
    pub points: usize,
    /// Where a rigid machine grips the body under displacement control, in units
    /// of l_h (> 0): the controlled approach is Delta + (2 L/pi) ln(datum).
    #[arg(long, value_name = "XD", default_value = "100", value_parser = args::positive, allow_negative_numbers = true)]
    pub datum: f64,
    /// Output directory (written atomically).
    #[arg(long, value_name = "DIR", default_value = "maugis-out")]
    pub out: PathBuf,
    /// `files` (default) or `json` (print to stdout, write nothing).
    #[arg(long, value_name = "FORMAT", default_value = "files")]
    pub format: CurveFormat,
    /// Left end of the plots' abar axis (plot only; the grid starts at amax/points).
    #[arg(long, value_name = "AMIN", value_parser = args::non_negative, allow_negative_numbers = true)]
    pub amin: Option<f64>,
    /// Lower end of the plots' load axis [default: the data's range].
    #[arg(long, value_name = "Y", value_parser = args::finite, allow_negative_numbers = true)]
    pub ymin: Option<f64>,
    /// Upper end of the plots' load axis [default: the data's range].
    #[arg(long, value_name = "Y", value_parser = args::finite, allow_negative_numbers = true)]
    pub ymax: Option<f64>,
}

/// The plots' window: abar from `amin`, optional load bounds.
#[derive(Clone, Copy, Debug, Default)]
pub struct Window {
    /// Left end of the abar axis.
    pub amin: f64,
    /// Lower end of the load axis.
    pub ymin: Option<f64>,
    /// Upper end of the load axis.
    pub ymax: Option<f64>,
}

/// One computed curve.
pub struct Run {
    /// Its Maugis parameter.
    pub lambda: f64,
    /// The library's result.
    pub curve: Curve,
}

// ---------------------------------------------------------------- output

/// The run's summary: the library's schema ([`RunSummary::new`]), the same
/// object for `summary.json` and `--format json`; files name the curves' CSVs.
fn summary(runs: &[Run], profile: &WavyProfile, opts: CurveOptions, with_csv: bool) -> RunSummary {
    RunSummary::for_profile(profile, opts, runs.iter().map(|r| &r.curve), |c| with_csv.then(|| csv_name(c.params.lambda())))
}

/// The run as JSON; with `--units si` an `si` object ([`SiSummary`]) joins the
/// normalised schema's keys.
fn with_si(run: &RunSummary, si: Option<&SiRun>, pretty: bool) -> Result<String, String> {
    #[derive(Serialize)]
    struct WithSi<'a> {
        #[serde(flatten)]
        run: &'a RunSummary,
        si: SiSummary,
    }
    let text = match si {
        None if pretty => serde_json::to_string_pretty(run),
        None => serde_json::to_string(run),
        Some(r) => {
            let out = WithSi { run, si: SiSummary::new(run, r.material).map_err(|e| e.to_string())? };
            if pretty {
                serde_json::to_string_pretty(&out)
            } else {
                serde_json::to_string(&out)
            }
        }
    };
    text.map_err(|e| format!("could not format JSON: {e}"))
}

/// The CSV file name of a curve.
pub fn csv_name(lambda: f64) -> String {
    format!("curve_lambda_{lambda}.csv")
}

/// The grid states of a curve as CSV; every row carries the curve's parameters.
/// With `--units si` (`scales`) three SI columns follow: `a_m`, `load_n_per_m`, `approach_m`.
fn curve_csv(c: &Curve, scales: Option<&Scales>) -> Result<String, String> {
    let mut w = csv::Writer::from_writer(Vec::new());
    let err = |e: csv::Error| format!("could not format CSV: {e}");
    let (wave_names, wave_values) = args::profile_columns(c.params.profile());
    let mut header: Vec<&str> = vec!["lambda"];
    header.extend(wave_names.iter().map(String::as_str));
    header.extend(["abar", "m", "m_minus_1", "load", "approach", "valid", "min_strip_gap", "max_traction"]);
    if scales.is_some() {
        header.extend(["a_m", "load_n_per_m", "approach_m"]);
    }
    w.write_record(&header).map_err(err)?;
    let lambda = c.params.lambda();
    for p in &c.points {
        let si: Vec<String> = scales
            .map(|s| vec![s.to_horizontal(p.abar).to_string(), s.to_load(p.load).to_string(), s.to_vertical(p.approach).to_string()])
            .unwrap_or_default();
        w.write_record(
            std::iter::once(lambda.to_string())
                .chain(wave_values.iter().cloned())
                .chain([
            p.abar.to_string(),
            p.m.to_string(),
            p.m_minus_1.to_string(),
            p.load.to_string(),
            p.approach.to_string(),
            p.validity.valid.to_string(),
            p.validity.min_strip_gap.to_string(),
            p.validity.max_traction.to_string(),
        ])
                .chain(si),
        )
        .map_err(err)?;
    }
    let bytes = w.into_inner().map_err(|e| format!("could not format CSV: {e}"))?;
    String::from_utf8(bytes).map_err(|e| format!("could not format CSV: {e}"))
}

// ---------------------------------------------------------------- computing

/// A progress bar on stderr, hidden when stderr is not a terminal.
pub fn progress(len: u64, what: &str) -> ProgressBar {
    if !std::io::stderr().is_terminal() {
        return ProgressBar::hidden();
    }
    let pb = ProgressBar::with_draw_target(Some(len), ProgressDrawTarget::stderr());
    if let Ok(style) = ProgressStyle::with_template("{spinner} {msg} [{bar:30}] {pos}/{len} ({elapsed})") {
        pb.set_style(style.progress_chars("=> "));
    }
    pb.set_message(what.to_string());
    pb.enable_steady_tick(Duration::from_millis(120));
    pb
}

/// Computes the curves (the library's [`load_area_curves`], in parallel over lambda).
pub fn compute(lambdas: &[f64], profile: &WavyProfile, opts: CurveOptions) -> Result<Vec<Run>, String> {
    let pb = progress(lambdas.len() as u64, "load-area curves");
    let curves = load_area_curves_profile(lambdas, profile, opts, || pb.inc(1));
    pb.finish_and_clear();
    let curves = curves.map_err(|e| match e.at {
        At::Curve { lambda } => format!("lambda = {}: {}", num(lambda), e.error),
        _ => e.to_string(),
    })?;
    Ok(lambdas.iter().zip(curves).map(|(&lambda, curve)| Run { lambda, curve }).collect())
}

/// Runs `maugis curve`.
pub fn run(a: CurveArgs) -> Result<(), String> {
    let mut normalised = vec![("--lambda", !a.lambda.is_empty())];
    normalised.extend(a.roughness.given().into_iter().filter(|(f, _)| matches!(*f, "--alpha" | "--beta")));
    let si = a.si.resolve_with_waves(&normalised, a.roughness.wave_pairs()?.as_deref())?;
    let profile = match &si {
        Some(r) => r.profile,
        None => a.roughness.profile()?,
    };
    let mut lambdas = match &si {
        Some(r) => r.lambdas.clone(),
        None if a.lambda.is_empty() => DEFAULT_LAMBDAS.to_vec(),
        None => a.lambda.clone(),
    };
    lambdas.sort_by(f64::total_cmp);
    lambdas.dedup();
    // Everything is validated before any work: the parsers checked the ranges,
    // the library checks the combination, and the output directory is usable.
    args::check_profile_params(&lambdas, &profile)?;
    args::check_profile_size("--amax", a.amax, &profile)?;
    let window = Window { amin: a.amin.unwrap_or(0.0), ymin: a.ymin, ymax: a.ymax };
    if window.amin >= a.amax {
        return Err(format!("--amin ({}) must be below --amax ({})", num(window.amin), num(a.amax)));
    }
    if let (Some(lo), Some(hi)) = (a.ymin, a.ymax) {
        if lo >= hi {
            return Err(format!("--ymin ({}) must be below --ymax ({})", num(lo), num(hi)));
        }
    }
    if a.format == CurveFormat::Files {
        check_out_dir(&a.out)?;
    }
    let opts = CurveOptions { amax: a.amax, points: a.points, datum: a.datum };

    let t0 = Instant::now();
    let runs = compute(&lambdas, &profile, opts)?;
    let elapsed = t0.elapsed();
    let mdmt_lambda = lambdas.first().copied().unwrap_or(0.1);

    if a.format == CurveFormat::Json {
        let out = summary(&runs, &profile, opts, false);
        let text = with_si(&out, si.as_ref(), false)?;
        return print_stdout(&format!("{text}\n"));
    }

    // Every file is rendered in memory before anything touches the disk.
    let mut files = Vec::new();
    for r in &runs {
        files.push(OutFile::text(csv_name(r.lambda), curve_csv(&r.curve, si.as_ref().map(|s| &s.scales))?));
    }
    let summary = summary(&runs, &profile, opts, true);
    let mut text = with_si(&summary, si.as_ref(), true)?;
    text.push('\n');
    files.push(OutFile::text("summary.json", text));
    files.push(OutFile::text("load-area.svg", load_area_svg(&runs, &profile, a.amax, mdmt_lambda, window)?));
    files.push(OutFile::text("load-approach.svg", load_approach_svg(&runs, &profile, window)?));
    let written = write_atomically(&a.out, &files)?;

    let mut report = String::new();
    let _ = writeln!(
        report,
        "maugis curve: {}, abar in (0, {}], {} points per curve, {} curve(s) in {:.1} s",
        args::profile_report(&profile),
        short(a.amax),
        a.points,
        runs.len(),
        elapsed.as_secs_f64()
    );
    let _ = writeln!(
        report,
        "  {:>8}  {:>16}  {:>17}  {:>26}  {:>22}  {:>8}",
        "lambda", "turning max/min", "jumps load/unload", "pull-off (abar, Lbar)", "valid pull-off", "invalid"
    );
    let mut at_grid_start = false;
    for r in &runs {
        let c = &r.curve;
        let nmax = c.turning_points.iter().filter(|t| t.kind == TurningKind::Max).count();
        let nmin = c.turning_points.len() - nmax;
        let nload = c.jumps.iter().filter(|j| j.direction == JumpDirection::Loading).count();
        let nunload = c.jumps.len() - nload;
        let po = match c.pull_off {
            Some(p) => format!("({:.4}, {:.4}){}", p.abar, p.load, if p.validity.valid { "" } else { " invalid" }),
            None => "none".into(),
        };
        // the most tensile valid state unloading reaches, where the raw one is invalid
        let vpo = match (c.pull_off, c.valid_pull_off) {
            (Some(p), Some(v)) if p.validity.valid && v.abar == p.abar && v.load == p.load => "same".into(),
            (_, Some(v)) => {
                let first = c.points.first().is_some_and(|g| g.abar == v.abar);
                at_grid_start |= first;
                format!("({:.4}, {:.4}){}", v.abar, v.load, if first { "*" } else { "" })
            }
            (_, None) => "none".into(),
        };
        let inv = c.points.iter().filter(|p| !p.validity.valid).count();
        let _ = writeln!(
            report,
            "  {:>8}  {:>16}  {:>17}  {:>26}  {:>22}  {:>8}",
            short(r.lambda),
            format!("{nmax}/{nmin}"),
            format!("{nload}/{nunload}"),
            po,
            vpo,
            format!("{inv}/{}", c.points.len())
        );
    }
    if at_grid_start {
        let _ = writeln!(report, "  * at the smallest abar of the grid: the valid small-contact branch may reach lower loads below it");
    }
    if let Some(r) = &si {
        let s = SiSummary::new(&summary, r.material).map_err(|e| e.to_string())?;
        let _ = writeln!(report, "SI: l_h = {:.4e} m, l_v = {:.4e} m, load scale {:.4e} N/m, energy scale {:.4e} J/m", s.scales.horizontal, s.scales.vertical, s.scales.load, s.scales.energy);
        for c in &s.curves {
            let po = match (c.pull_off_load_n_per_m, c.pull_off_half_width_m) {
                (Some(l), Some(w)) => format!("pull-off {l:.4e} N/m at a = {w:.4e} m"),
                _ => "no pull-off".into(),
            };
            let _ = writeln!(
                report,
                "  lambda = {}: sigma_0 = {:.4e} Pa, delta_c = {:.4e} m, {po}, W = {:.4e} J/m (load control), {:.4e} J/m (displacement control)",
                short(c.lambda),
                c.sigma_pa,
                c.delta_c_m,
                c.dissipation_load_control_j_per_m,
                c.dissipation_displacement_control_j_per_m
            );
        }
    }
    let _ = writeln!(report, "wrote {} file(s) to {}:", written.len(), a.out.display());
    for p in &written {
        let _ = writeln!(report, "  {}", p.display());
    }
    print_stdout(&report)
}

// ---------------------------------------------------------------- plot

/// Splits a curve into runs of equal validity; neighbouring runs share their
/// boundary point so the drawn line is continuous.
pub(crate) fn validity_runs<'p>(points: impl IntoIterator<Item = &'p CurvePoint>, coords: impl Fn(&CurvePoint) -> (f64, f64)) -> Vec<(bool, Vec<(f64, f64)>)> {
    let mut out: Vec<(bool, Vec<(f64, f64)>)> = Vec::new();
    for p in points {
        let xy = coords(p);
        let v = p.validity.valid;
        match out.last_mut() {
            Some((lv, pts)) if *lv == v => pts.push(xy),
            Some((_, pts)) => {
                let last = pts.last().copied();
                let mut new = Vec::new();
                if let Some(l) = last {
                    // draw the connecting segment in the style of the invalid side
                    if v {
                        pts.push(xy);
                    } else {
                        new.push(l);
                    }
                }
                new.push(xy);
                out.push((v, new));
            }
            None => out.push((v, vec![xy])),
        }
    }
    out
}

/// Draws one curve's validity runs (from [`validity_runs`]): valid parts solid,
/// invalid parts thin, faded and dashed, clipped to `[ymin, ymax]`, and adds the
/// curve's legend entry (in the dashed style when every state is invalid).
pub(crate) fn draw_validity_runs(
    chart: &mut ChartContext<'_, SVGBackend<'_>, Cartesian2d<plotters::coord::types::RangedCoordf64, plotters::coord::types::RangedCoordf64>>,
    legend: &mut Legend,
    runs: Vec<(bool, Vec<(f64, f64)>)>,
    (ymin, ymax): (f64, f64),
    colour_index: usize,
    lambda: f64,
) -> Result<(), String> {
    let col = colour(colour_index);
    let solid = col.stroke_width(3);
    let faded = ShapeStyle { color: col.mix(0.6), filled: false, stroke_width: 2 };
    let any_valid = runs.iter().any(|(valid, _)| *valid);
    for (valid, pts) in runs {
        for piece in clip_y(&pts, ymin, ymax) {
            if valid {
                chart.draw_series(LineSeries::new(piece, solid)).map_err(plot_err)?;
            } else {
                chart.draw_series(DashedLineSeries::new(piece, 3, 5, faded)).map_err(plot_err)?;
            }
        }
    }
    if any_valid {
        legend.line(format!("λ = {}", short(lambda)), solid, 0, 0);
    } else {
        legend.line(format!("λ = {} (all states invalid)", short(lambda)), faded, 3, 5);
    }
    Ok(())
}

/// The legend entry for invalid stretches (thin, faded, dotted).
pub(crate) fn invalid_entry(legend: &mut Legend, label: &str) {
    legend.line(label, ShapeStyle { color: BLACK.mix(0.6), filled: false, stroke_width: 2 }, 3, 5);
}

/// A limit line: points, style, dash, gap, legend label.
type LimitLine<'a> = (&'a [(f64, f64)], ShapeStyle, u32, u32, Option<String>);

/// The load-area plot's title: the profile and its Johnson parameter(s)
/// `chi_j = sqrt(beta_j/alpha_j^2)` (the paper's `sqrt(2 beta/(pi alpha)^2)` up to
/// `sqrt(2)/pi`).
fn load_area_title(profile: &WavyProfile) -> String {
    let chi = |alpha: f64, beta: f64| if alpha > 0.0 { short((beta / (alpha * alpha)).sqrt()) } else { "∞".into() };
    match profile.waves() {
        [w] => format!(
            "Wavy Maugis line contact: load-area response, α = {}, β = {} (Johnson parameter √(β/α²) = {})",
            short(w.alpha()),
            short(w.beta()),
            chi(w.alpha(), w.beta())
        ),
        ws => {
            let chis: Vec<String> = ws.iter().take(6).map(|w| chi(w.alpha(), w.beta())).collect();
            let johnson = if chis.windows(2).all(|p| p[0] == p[1]) {
                format!("√(β/α²) = {} for each wave", chis[0])
            } else {
                format!("√(β_j/α_j²) = {}", chis.join(", "))
            };
            format!("Load-area response, {} ({johnson})", args::profile_title(profile))
        }
    }
}

/// The load-area plot (SVG text).
pub fn load_area_svg(runs: &[Run], profile: &WavyProfile, amax: f64, mdmt_lambda: f64, window: Window) -> Result<String, String> {
    // Limit curves on a fine grid.
    let n = 800usize;
    let mdmt_params = Params::with_profile(mdmt_lambda, *profile).map_err(|e| e.to_string())?;
    let limits = appendix_e_rows(mdmt_params, amax, n).map_err(|e| crate::limits::limits_error(&e))?;
    let line = |f: fn(&AppendixE) -> f64| limits.iter().map(|(x, l)| (*x, f(l))).collect::<Vec<_>>();
    let (jkr, jkr_lo, jkr_hi) = (line(|l| l.jkr), line(|l| l.jkr_envelope.0), line(|l| l.jkr_envelope.1));
    let (mdmt, mdmt_lo, mdmt_hi) = (line(|l| l.mdmt), line(|l| l.mdmt_envelope.0), line(|l| l.mdmt_envelope.1));

    // y window: the curves' range with a margin (the limits are clipped to it).
    let (mut ymin, mut ymax) = (f64::INFINITY, f64::NEG_INFINITY);
    for r in runs {
        for p in &r.curve.points {
            if p.load.is_finite() {
                ymin = ymin.min(p.load);
                ymax = ymax.max(p.load);
            }
        }
    }
    if !(ymin.is_finite() && ymax.is_finite()) {
        ymin = -5.0;
        ymax = 25.0;
    }
    let span = (ymax - ymin).max(1.0);
    let (ymin, ymax) = (window.ymin.unwrap_or(ymin - 0.06 * span), window.ymax.unwrap_or(ymax + 0.06 * span));

    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, (1400 + crate::plot::LEGEND_WIDTH, 950)).into_drawing_area();
        root.fill(&WHITE).map_err(plot_err)?;
        let title = load_area_title(profile);
        let mut chart = xy_chart(&root, title, (window.amin, amax), (ymin, ymax), ("contact half-width abar", "load Lbar"))?;
        let mut legend = Legend::new(LEGEND_FONT);

        // zero-load line
        chart.draw_series(LineSeries::new(vec![(0.0, 0.0), (amax, 0.0)], BLACK.mix(0.5).stroke_width(1))).map_err(plot_err)?;

        // Limits (medium dash) and envelopes (long dash), grey.
        let limit_style = |c: RGBColor, w: u32| ShapeStyle { color: c.to_rgba(), filled: false, stroke_width: w };
        // (line, style, dash, gap, legend label); the legend entries are added
        // after the curves so that the lambda entries come first.
        let ml = short(mdmt_lambda);
        let limit_lines: [LimitLine<'_>; 6] = [
            (&jkr, limit_style(DARK_GREY, 2), 9, 6, Some("JKR limit λ→∞ (E.42a)".into())),
            (&jkr_lo, limit_style(DARK_GREY, 1), 20, 8, Some("JKR envelope (E.42b)".into())),
            (&jkr_hi, limit_style(DARK_GREY, 1), 20, 8, None),
            (&mdmt, limit_style(LIGHT_GREY, 2), 9, 6, Some(format!("M-DMT limit at λ = {ml} (E.43a)"))),
            (&mdmt_lo, limit_style(LIGHT_GREY, 1), 20, 8, Some(format!("M-DMT envelope at λ = {ml} (E.43d)"))),
            (&mdmt_hi, limit_style(LIGHT_GREY, 1), 20, 8, None),
        ];
        for (pts, style, dash, gap, _) in &limit_lines {
            for piece in clip_y(pts, ymin, ymax) {
                chart.draw_series(DashedLineSeries::new(piece, *dash, *gap, *style)).map_err(plot_err)?;
            }
        }

        // Curves: valid parts solid, invalid parts thin, faded and dashed.
        for (i, r) in runs.iter().enumerate() {
            draw_validity_runs(&mut chart, &mut legend, validity_runs(&r.curve.points, |p| (p.abar, p.load)), (ymin, ymax), i, r.lambda)?;
        }

        // Jumps: horizontal arrows at constant load, in the curve's colour; thin
        // and faded when they start on an invalid state.
        let inside = |y: f64| y >= ymin && y <= ymax;
        for (i, r) in runs.iter().enumerate() {
            let col = colour(i);
            for j in &r.curve.jumps {
                let (from_abar, to_abar, load) = (j.from.abar, j.to.abar, j.from.load);
                if !inside(load) {
                    continue;
                }
                let ok = j.from.valid;
                let (line, head) = if ok {
                    (col.stroke_width(2), col.filled())
                } else {
                    (ShapeStyle { color: col.mix(0.5), filled: false, stroke_width: 1 }, col.mix(0.5).filled())
                };
                chart
                    .draw_series(LineSeries::new(vec![(from_abar, load), (to_abar, load)], line))
                    .map_err(plot_err)?;
                let right = to_abar > from_abar;
                let (len, half) = if ok { (12, 5) } else { (9, 4) };
                chart
                    .draw_series(std::iter::once(
                        EmptyElement::at((to_abar, load)) + Polygon::new(arrow_head(right, len, half), head),
                    ))
                    .map_err(plot_err)?;
            }
        }

        // Turning points (triangles) and pull-off (circle), outlined in black;
        // hollow when the state there is invalid.
        for (i, r) in runs.iter().enumerate() {
            let col = colour(i);
            for t in &r.curve.turning_points {
                if !inside(t.load) {
                    continue;
                }
                let shape = match t.kind {
                    TurningKind::Max => triangle_up(7),
                    TurningKind::Min => triangle_down(7),
                };
                let (fill, outline) = if valid_at(&r.curve, t.abar) {
                    (col.filled(), BLACK.stroke_width(1))
                } else {
                    (WHITE.filled(), col.stroke_width(2))
                };
                chart
                    .draw_series(std::iter::once(
                        EmptyElement::at((t.abar, t.load))
                            + Polygon::new(shape.clone(), fill)
                            + PathElement::new(closed(&shape), outline),
                    ))
                    .map_err(plot_err)?;
            }
            if let Some(po) = r.curve.pull_off {
                let (ab, l) = (po.abar, po.load);
                if inside(l) {
                    let (fill, outline) = if po.validity.valid {
                        (col.filled(), BLACK.stroke_width(2))
                    } else {
                        (WHITE.filled(), col.stroke_width(2))
                    };
                    chart
                        .draw_series(std::iter::once(
                            EmptyElement::at((ab, l)) + Circle::new((0, 0), 6, fill) + Circle::new((0, 0), 6, outline),
                        ))
                        .map_err(plot_err)?;
                }
            }
        }

        // Legend entries after the curves': the limits, then the symbols.
        for (_, style, dash, gap, label) in limit_lines {
            if let Some(l) = label {
                legend.line(l, style, dash, gap);
            }
        }
        let grey = RGBColor(120, 120, 120);
        let outlined = |shape: Vec<(i32, i32)>| Mark::polygon(shape, grey.filled(), Some(BLACK.stroke_width(1)));
        invalid_entry(&mut legend, "invalid state: cavitation (p̄ > 1) or interpenetration (ḡ < 0)");
        legend.entry("turning point: load maximum", vec![outlined(triangle_up(7))]);
        legend.entry("turning point: load minimum", vec![outlined(triangle_down(7))]);
        let half = Legend::SWATCH / 2;
        legend.entry(
            "jump at constant load (loading →, unloading ←)",
            vec![
                Mark::Line { points: vec![(-half, 0), (half, 0)], style: BLACK.stroke_width(2), dash: 0, gap: 0 },
                Mark::polygon(arrow_head(true, 12, 5).into_iter().map(|(a, b)| (a + half, b)).collect(), BLACK.filled(), None),
            ],
        );
        legend.entry("hollow marker or thin arrow: on an invalid state", vec![Mark::polygon(triangle_up(7), WHITE.filled(), Some(grey.stroke_width(2)))]);
        legend.entry("pull-off", vec![Mark::circle(6, grey.filled(), Some(BLACK.stroke_width(2)))]);

        finish_load_area_chart(&chart, &root, &legend)?;
    }
    Ok(svg)
}

/// The load-approach plot `Lbar(Delta-bar)` (datum at infinity): each curve,
/// valid stretches solid, invalid ones dashed, and its pull-off.
pub fn load_approach_svg(runs: &[Run], profile: &WavyProfile, window: Window) -> Result<String, String> {
    let (mut x0, mut x1, mut y0, mut y1) = (f64::INFINITY, f64::NEG_INFINITY, f64::INFINITY, f64::NEG_INFINITY);
    for r in runs {
        for p in r.curve.points.iter().filter(|p| p.abar >= window.amin) {
            x0 = x0.min(p.approach);
            x1 = x1.max(p.approach);
            y0 = y0.min(p.load);
            y1 = y1.max(p.load);
        }
    }
    if !(x0.is_finite() && x1 > x0 && y0.is_finite() && y1 > y0) {
        (x0, x1, y0, y1) = (-1.0, 1.0, -1.0, 1.0);
    }
    let (dx, dy) = (0.05 * (x1 - x0), 0.06 * (y1 - y0));
    let (ymin, ymax) = (window.ymin.unwrap_or(y0 - dy), window.ymax.unwrap_or(y1 + dy));
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, (1400 + crate::plot::LEGEND_WIDTH, 950)).into_drawing_area();
        root.fill(&WHITE).map_err(plot_err)?;
        let title = if profile.len() == 1 {
            format!("Load-approach response, {} (approach from a datum at infinity, log term removed)", args::profile_title(profile))
        } else {
            format!("Load-approach response, {} (datum at infinity)", args::profile_title(profile))
        };
        let mut chart = xy_chart(&root, title, (x0 - dx, x1 + dx), (ymin, ymax), ("approach Δ̄", "load Lbar"))?;
        let mut legend = Legend::new(LEGEND_FONT);
        for (i, r) in runs.iter().enumerate() {
            let col = colour(i);
            let pts = r.curve.points.iter().filter(|p| p.abar >= window.amin);
            draw_validity_runs(&mut chart, &mut legend, validity_runs(pts, |p| (p.approach, p.load)), (ymin, ymax), i, r.lambda)?;
            if let Some(po) = r.curve.pull_off {
                if po.load >= ymin && po.load <= ymax {
                    chart
                        .draw_series(std::iter::once(Circle::new((po.approach, po.load), 6, col.filled())))
                        .map_err(plot_err)?;
                }
            }
        }
        invalid_entry(&mut legend, "invalid state (cavitation or interpenetration)");
        legend.entry("pull-off", vec![Mark::circle(6, RGBColor(120, 120, 120).filled(), None)]);
        finish_load_area_chart(&chart, &root, &legend)?;
    }
    Ok(svg)
}

/// Validity of the grid state nearest to `abar`.
pub(crate) fn valid_at(c: &Curve, abar: f64) -> bool {
    c.points
        .iter()
        .min_by(|p, q| (p.abar - abar).abs().total_cmp(&(q.abar - abar).abs()))
        .map(|p| p.validity.valid)
        .unwrap_or(true)
}

/// A closed outline of a polygon.
pub(crate) fn closed(shape: &[(i32, i32)]) -> Vec<(i32, i32)> {
    let mut v = shape.to_vec();
    if let Some(&f) = shape.first() {
        v.push(f);
    }
    v
}
