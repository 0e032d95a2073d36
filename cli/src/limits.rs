//! `maugis limits`: the closed-form limits and envelopes of Appendix E and the
//! Eq. 17 local envelope over `abar in (0, amax]`.
//!
//! Columns (all loads `Lbar`): `abar`, `jkr` (E.42a), `jkr_env_lower`,
//! `jkr_env_upper` (E.42b), `mdmt` (E.43a at the given lambda),
//! `mdmt_env_lower`, `mdmt_env_upper` (E.43d), `smooth_mdmt` (E.44),
//! `local_env_lower`, `local_env_upper` (Eq. 17: the smooth Maugis load at the
//! same lambda +/- the envelope half-width; this one solves the smooth model at
//! every point).
//!
//! Default: `limits.csv` and `limits.svg` in `--out`; `--format csv` or
//! `--format json` print the table on stdout and write nothing.

use std::fmt::Write as _;
use std::path::PathBuf;

use clap::{Args, ValueEnum};
use plotters::prelude::*;
use serde::Serialize;

use maugis::contact::limits::{limit_rows, mdmt_pull_off, LimitRow};
use maugis::contact::located::{At, LocatedError};
use maugis::contact::model::Params;

use crate::args::{self, num, short, Roughness};
use crate::output::{check_out_dir, print_stdout, write_atomically, OutFile};
use crate::plot::{clip_y, colour, finish_load_area_chart, load_area_chart, plot_err, Legend, DARK_GREY, LEGEND_FONT, LIGHT_GREY};

/// Output format.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum LimitsFormat {
    /// limits.csv and limits.svg in --out.
    Files,
    /// The CSV table on stdout, no files.
    Csv,
    /// One JSON object on stdout, no files.
    Json,
}

/// Flags of `maugis limits`.
#[derive(Args, Debug)]
pub struct LimitsArgs {
    /// --alpha, --beta.
    #[command(flatten)]
    pub roughness: Roughness,
    /// Maugis parameter of the M-DMT (E.43), smooth M-DMT (E.44) and local (Eq. 17) curves.
    #[arg(long, value_name = "L", default_value = "1/10", value_parser = args::positive, allow_negative_numbers = true)]
    pub lambda: f64,
    /// Largest contact half-width abar.
    #[arg(long, value_name = "AMAX", default_value = "6", value_parser = args::positive, allow_negative_numbers = true)]
    pub amax: f64,
    /// Grid points, abar_i = amax i/points.
    #[arg(long, value_name = "N", default_value = "300", value_parser = args::grid_points)]
    pub points: usize,
    /// Output directory (written atomically).
    #[arg(long, value_name = "DIR", default_value = "maugis-out")]
    pub out: PathBuf,
    /// `files` (default), `csv` or `json` (print to stdout, write nothing).
    #[arg(long, value_name = "FORMAT", default_value = "files")]
    pub format: LimitsFormat,
}

#[derive(Serialize)]
struct LimitsJson {
    params: LimitsParams,
    rows: Vec<LimitRow>,
}

#[derive(Serialize)]
struct LimitsParams {
    alpha: f64,
    beta: f64,
    /// Every wave, when the profile has other than exactly one.
    #[serde(skip_serializing_if = "Option::is_none")]
    waves: Option<maugis::contact::profile::WavyProfile>,
    lambda: f64,
    amax: f64,
    points: usize,
    /// E.43c rigid pull-off `L'_p = 2 lambda cbar`.
    mdmt_pull_off: f64,
}

fn table_csv(rows: &[LimitRow]) -> Result<String, String> {
    let mut w = csv::Writer::from_writer(Vec::new());
    let err = |e: csv::Error| format!("could not format CSV: {e}");
    w.write_record(LimitRow::COLUMNS).map_err(err)?;
    for r in rows {
        w.write_record(r.values().map(|v| v.to_string())).map_err(err)?;
    }
    let bytes = w.into_inner().map_err(|e| format!("could not format CSV: {e}"))?;
    String::from_utf8(bytes).map_err(|e| format!("could not format CSV: {e}"))
}

/// A limits error in the command's words.
pub(crate) fn limits_error(e: &LocatedError) -> String {
    match e.at {
        At::Limits { abar } => format!("limits at abar = {}: {}", num(abar), e.error),
        _ => e.to_string(),
    }
}

/// Runs `maugis limits`.
pub fn run(a: LimitsArgs) -> Result<(), String> {
    let profile = a.roughness.profile()?;
    args::check_profile_params(&[a.lambda], &profile)?;
    let params = Params::with_profile(a.lambda, profile).map_err(|e| e.to_string())?;
    args::check_profile_size("--amax", a.amax, &profile)?;
    let (alpha, beta) = (params.alpha(), params.beta());
    if a.format == LimitsFormat::Files {
        check_out_dir(&a.out)?;
    }
    let n = a.points;
    let rows = limit_rows(params, a.amax, n).map_err(|e| limits_error(&e))?;
    let pull_off = mdmt_pull_off(params).map_err(|e| e.to_string())?;
    match a.format {
        LimitsFormat::Csv => {
            print_stdout(&table_csv(&rows)?)
        }
        LimitsFormat::Json => {
            let out = LimitsJson {
                params: LimitsParams { alpha, beta, waves: (profile.len() != 1).then_some(profile), lambda: a.lambda, amax: a.amax, points: n, mdmt_pull_off: pull_off },
                rows,
            };
            let text = serde_json::to_string(&out).map_err(|e| format!("could not format JSON: {e}"))?;
            print_stdout(&format!("{text}\n"))
        }
        LimitsFormat::Files => {
            let files = [
                OutFile::text("limits.csv", table_csv(&rows)?),
                OutFile::text("limits.svg", limits_svg(&rows, &profile, a.lambda, a.amax)?),
            ];
            let written = write_atomically(&a.out, &files)?;
            let mut report = String::new();
            let _ = writeln!(
                report,
                "maugis limits: {}, lambda = {}, abar in (0, {}], {} points; M-DMT pull-off L'_p = {:.6}",
                args::profile_report(&profile),
                short(a.lambda),
                short(a.amax),
                n,
                pull_off
            );
            let _ = writeln!(report, "wrote {} file(s) to {}:", written.len(), a.out.display());
            for p in &written {
                let _ = writeln!(report, "  {}", p.display());
            }
            print_stdout(&report)
        }
    }
}

/// A line of the plot: legend label, points, style, dash, gap (dash 0: solid).
type Series = (Option<String>, Vec<(f64, f64)>, ShapeStyle, u32, u32);

/// The limits plot (SVG text).
fn limits_svg(rows: &[LimitRow], profile: &maugis::contact::profile::WavyProfile, lambda: f64, amax: f64) -> Result<String, String> {
    let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
    for r in rows {
        for v in [r.jkr, r.mdmt, r.smooth_mdmt, r.local_env_lower, r.local_env_upper] {
            if v.is_finite() {
                lo = lo.min(v);
                hi = hi.max(v);
            }
        }
    }
    if !(lo.is_finite() && hi.is_finite()) {
        (lo, hi) = (-5.0, 25.0);
    }
    let span = (hi - lo).max(1.0);
    let (ymin, ymax) = (lo - 0.06 * span, hi + 0.06 * span);
    let col = |f: fn(&LimitRow) -> f64| rows.iter().map(|r| (r.abar, f(r))).collect::<Vec<_>>();
    let l = short(lambda);
    let style = |c: RGBColor, w: u32| ShapeStyle { color: c.to_rgba(), filled: false, stroke_width: w };
    // (label, points, style, dash, gap); dash 0 = solid
    let series: Vec<Series> = vec![
        (Some("JKR limit (E.42a)".into()), col(|r| r.jkr), style(DARK_GREY, 3), 0, 0),
        (Some("JKR envelope (E.42b)".into()), col(|r| r.jkr_env_lower), style(DARK_GREY, 1), 18, 7),
        (None, col(|r| r.jkr_env_upper), style(DARK_GREY, 1), 18, 7),
        (Some(format!("M-DMT limit, λ = {l} (E.43a)")), col(|r| r.mdmt), style(LIGHT_GREY, 3), 0, 0),
        (Some(format!("M-DMT envelope, λ = {l} (E.43d)")), col(|r| r.mdmt_env_lower), style(LIGHT_GREY, 1), 18, 7),
        (None, col(|r| r.mdmt_env_upper), style(LIGHT_GREY, 1), 18, 7),
        (Some(format!("smooth M-DMT, λ = {l} (E.44)")), col(|r| r.smooth_mdmt), style(colour(0), 2), 9, 6),
        (Some(format!("local envelope, λ = {l} (Eq. 17)")), col(|r| r.local_env_lower), style(colour(3), 2), 0, 0),
        (None, col(|r| r.local_env_upper), style(colour(3), 2), 0, 0),
    ];
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, (1300 + crate::plot::LEGEND_WIDTH, 900)).into_drawing_area();
        root.fill(&WHITE).map_err(plot_err)?;
        let title = format!("Appendix E limits and Eq. 17 envelope, {}, λ = {l}", args::profile_title(profile));
        let mut chart = load_area_chart(&root, title, amax, ymin, ymax)?;
        let mut legend = Legend::new(LEGEND_FONT);
        for (label, pts, st, dash, gap) in series {
            for piece in clip_y(&pts, ymin, ymax) {
                if dash == 0 {
                    chart.draw_series(LineSeries::new(piece, st)).map_err(plot_err)?;
                } else {
                    chart.draw_series(DashedLineSeries::new(piece, dash, gap, st)).map_err(plot_err)?;
                }
            }
            if let Some(lab) = label {
                legend.line(lab, st, dash, gap);
            }
        }
        finish_load_area_chart(&chart, &root, &legend)?;
    }
    Ok(svg)
}
