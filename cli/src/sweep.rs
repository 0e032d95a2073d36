//! `maugis sweep` and `maugis merge`: regime maps over a grid of lambda (log)
//! and alpha, beta or the Johnson parameter of one wave, or the amplitude scale
//! `s` of a profile of many waves (`--wave`, `--waves`, `--weierstrass`: every
//! `alpha_j` times `s`, the wavelengths fixed) (library: `maugis::contact::sweep`).
//!
//! `maugis sweep` writes into `--out`:
//!
//! * `sweep.csv`: one row per grid point (`index, lambda, value, alpha, beta,
//!   instabilities, unloading_jumps, dissipation, dissipation_valid,
//!   dissipation_invalid, pull_off, pull_off_valid, valid_pull_off, valid_fraction,
//!   regime`); on the amplitude axis `alpha, beta` are the point's scaled profile,
//!   `alpha_1, beta_1, alpha_2, ..` for many waves;
//! * `sweep.json`: the grid (with its base profile on the amplitude axis), the
//!   shard and the points (the library's `Sweep`);
//! * `sweep.svg`: the regime map (colour: regime; shade: dissipation) — only
//!   for a whole sweep, not for a shard.
//!
//! With `--shard s/n` it computes every n-th grid point (`k % n == s - 1`);
//! `maugis merge DIR... --out DIR` reads the shards' `sweep.json`, checks that
//! they cover the grid exactly once, and writes the whole sweep's files. The
//! grid points run in parallel (rayon) with a progress bar on a terminal.
//!
//! `maugis sweep --solver` draws the map with the numerical solver instead
//! (library: `maugis_solver::map`; this file and `sweep/solver_map.rs` only
//! parse and present): the same grid, shards and files, with the solver's and
//! the model's labels side by side (`docs/solver-map.md`); `maugis merge`
//! recognises its `sweep.json` (`"kind": "solver_map"`).

use std::fmt::Write as _;
use std::path::PathBuf;
use std::time::Instant;

use clap::{Args, ValueEnum};
use plotters::prelude::*;

use maugis::contact::sweep::{merge, run_sweep, Regime, Sweep, SweepAxis, SweepGrid, SweepPoint};
use maugis_solver::map::model_regime_name;

use crate::args::{self, num, profile_columns, profile_report, profile_title, short, Roughness};
use crate::curve::progress;
use crate::output::{check_out_dir, print_stdout, write_atomically, OutFile};
use crate::plot::{plot_err, tick, Legend, Mark};

mod solver_map;

/// The second axis on the command line.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum Axis {
    /// Wave amplitude alpha (beta fixed by --beta).
    Alpha,
    /// Wavelength beta (alpha fixed by --alpha).
    Beta,
    /// Johnson parameter sqrt(beta/alpha^2) (beta fixed by --beta).
    Johnson,
    /// The scale s of every amplitude of the profile (--wave/--waves/--weierstrass,
    /// or --alpha/--beta): wave j is (s alpha_j, beta_j).
    Amplitude,
}

/// Flags of `maugis sweep`.
#[derive(Args, Debug)]
pub struct SweepArgs {
    /// Smallest lambda.
    #[arg(long, value_name = "L", default_value = "0.1", value_parser = args::positive, allow_negative_numbers = true)]
    pub lambda_min: f64,
    /// Largest lambda.
    #[arg(long, value_name = "L", default_value = "10", value_parser = args::positive, allow_negative_numbers = true)]
    pub lambda_max: f64,
    /// Number of lambda values (log-spaced).
    #[arg(long, value_name = "N", default_value = "40", value_parser = axis_points)]
    pub lambda_n: usize,
    /// The second axis: alpha, beta or johnson (one wave), or amplitude (the scale of
    /// every amplitude of the profile) [default: alpha; amplitude with --wave, --waves
    /// or --weierstrass, which take no other axis].
    #[arg(long, value_name = "AXIS")]
    pub axis: Option<Axis>,
    /// Smallest value of the second axis [default: 0].
    #[arg(long, value_name = "V", value_parser = args::non_negative, allow_negative_numbers = true)]
    pub min: Option<f64>,
    /// Largest value of the second axis [default: 0.7; 1 on the amplitude axis, the
    /// profile as given].
    #[arg(long, value_name = "V", value_parser = args::positive, allow_negative_numbers = true)]
    pub max: Option<f64>,
    /// Number of values of the second axis (linear).
    #[arg(long, value_name = "N", default_value = "40", value_parser = axis_points)]
    pub n: usize,
    /// --alpha (fixed for --axis beta), --beta (fixed for --axis alpha or johnson);
    /// the profile --wave/--waves/--weierstrass (scaled by --axis amplitude).
    #[command(flatten)]
    pub roughness: Roughness,
    /// Largest contact half-width of every curve.
    #[arg(long, value_name = "AMAX", default_value = "6", value_parser = args::positive, allow_negative_numbers = true)]
    pub amax: f64,
    /// Grid points per curve.
    #[arg(long, value_name = "N", default_value = "150", value_parser = args::grid_points)]
    pub points: usize,
    /// Compute only shard s of n (1-based), e.g. --shard 3/8 in an array job.
    #[arg(long, value_name = "S/N", value_parser = shard)]
    pub shard: Option<(usize, usize)>,
    /// Draw the map with the numerical solver: one simulated cycle per point,
    /// labelled next to the model (`docs/solver-map.md`).
    #[arg(long)]
    pub solver: bool,
    /// With --solver: the label margin of W over the smooth cylinder's W.
    #[arg(long, value_name = "M", default_value = "0.02", value_parser = args::non_negative, allow_negative_numbers = true, requires = "solver")]
    pub margin: f64,
    /// With --solver: grid cells of every cycle (a power of two) instead of the
    /// per-lambda rule; give --steps with it.
    #[arg(long, value_name = "N", requires_all = ["solver", "steps"])]
    pub cells: Option<usize>,
    /// With --solver: approach steps per leg of every cycle instead of the rule; give --cells with it.
    #[arg(long, value_name = "S", requires_all = ["solver", "cells"])]
    pub steps: Option<usize>,
    /// With --solver: the adhesion law of every cycle, `dugdale` (default) or
    /// `exp` (smooth, matched in peak stress and work; docs/solver.md).
    #[arg(long, value_name = "LAW", default_value = "dugdale", requires = "solver")]
    pub law: crate::simulate::LawArg,
    /// Output directory (written atomically).
    #[arg(long, value_name = "DIR", default_value = "maugis-sweep")]
    pub out: PathBuf,
}

/// Flags of `maugis merge`.
#[derive(Args, Debug)]
pub struct MergeArgs {
    /// The shards' output directories (each holds a sweep.json).
    #[arg(value_name = "SHARD_DIR", required = true)]
    pub shards: Vec<PathBuf>,
    /// Output directory of the merged sweep.
    #[arg(long, value_name = "DIR", default_value = "maugis-sweep")]
    pub out: PathBuf,
}

/// Points per axis: 1 ..= 10000.
fn axis_points(s: &str) -> Result<usize, String> {
    let n: usize = s.trim().parse().map_err(|_| format!("'{s}' is not a whole number"))?;
    if !(1..=10_000).contains(&n) {
        return Err(format!("must lie in 1..=10000 (got {n})"));
    }
    Ok(n)
}

/// `s/n` with `1 <= s <= n`.
pub(crate) fn shard(s: &str) -> Result<(usize, usize), String> {
    let (a, b) = s.split_once('/').ok_or_else(|| format!("'{s}' is not of the form s/n (e.g. 2/8)"))?;
    let parse = |t: &str| t.trim().parse::<usize>().map_err(|_| format!("'{s}' is not of the form s/n (e.g. 2/8)"));
    let (a, b) = (parse(a)?, parse(b)?);
    if b == 0 || a == 0 || a > b {
        return Err(format!("'{s}': need 1 <= s <= n"));
    }
    Ok((a, b))
}

pub(crate) fn axis_name(a: SweepAxis) -> &'static str {
    a.name()
}

/// The CSV columns naming a point's profile, and their values: `alpha, beta` of the
/// point on the one-wave axes; on the amplitude axis the scaled profile's
/// ([`profile_columns`]: `alpha, beta` for one wave, `alpha_1, beta_1, ..` for many).
fn profile_cells(s: &Sweep, p: &SweepPoint) -> Result<(Vec<String>, Vec<String>), String> {
    match s.grid.axis {
        SweepAxis::Amplitude => {
            let scaled = s.grid.profile_at(p.index % s.grid.n).map_err(|e| e.to_string())?;
            Ok(profile_columns(&scaled))
        }
        _ => Ok((vec!["alpha".into(), "beta".into()], vec![p.alpha.to_string(), p.beta.to_string()])),
    }
}

fn sweep_csv(s: &Sweep) -> Result<String, String> {
    let mut w = csv::Writer::from_writer(Vec::new());
    let err = |e: csv::Error| format!("could not format CSV: {e}");
    let names = match s.points.first() {
        Some(p) => profile_cells(s, p)?.0,
        None => vec!["alpha".into(), "beta".into()],
    };
    let mut header: Vec<String> = vec!["index".into(), "lambda".into(), "value".into()];
    header.extend(names);
    header.extend(
        [
            "instabilities", "unloading_jumps", "dissipation", "dissipation_valid", "dissipation_invalid", "pull_off", "pull_off_valid",
            "valid_pull_off", "valid_fraction", "regime",
        ]
        .map(String::from),
    );
    w.write_record(&header).map_err(err)?;
    for p in &s.points {
        let mut row = vec![p.index.to_string(), p.lambda.to_string(), p.value.to_string()];
        row.extend(profile_cells(s, p)?.1);
        row.extend([
            p.instabilities.to_string(),
            p.unloading_jumps.to_string(),
            p.dissipation.to_string(),
            p.dissipation_valid.to_string(),
            p.dissipation_invalid.to_string(),
            p.pull_off.map_or(String::new(), |v| v.to_string()),
            p.pull_off_valid.to_string(),
            p.valid_pull_off.map_or(String::new(), |v| v.to_string()),
            p.valid_fraction.to_string(),
            model_regime_name(p.regime).to_string(),
        ]);
        w.write_record(&row).map_err(err)?;
    }
    let bytes = w.into_inner().map_err(|e| format!("could not format CSV: {e}"))?;
    String::from_utf8(bytes).map_err(|e| format!("could not format CSV: {e}"))
}

/// The regime map: one cell per grid point, hue by regime, shade by dissipation.
fn sweep_svg(s: &Sweep) -> Result<String, String> {
    let g = &s.grid;
    let wmax = s.points.iter().map(|p| p.dissipation.abs()).filter(|w| w.is_finite()).fold(0.0, f64::max).max(1e-300);
    // legend beside the map: regime colours at full shade, then the shade ramp
    const BLUE: (f64, f64, f64) = (31.0, 91.0, 180.0);
    const ORANGE: (f64, f64, f64) = (214.0, 96.0, 24.0);
    let shade = |c: (f64, f64, f64), t: f64| {
        let mix = |v: f64| (255.0 - (255.0 - v) * (0.25 + 0.75 * t)).round() as u8;
        RGBColor(mix(c.0), mix(c.1), mix(c.2))
    };
    let cell = |c: RGBColor| vec![Mark::Rect { from: (-12, -9), to: (12, 9), style: c.filled() }, Mark::Rect { from: (-12, -9), to: (12, 9), style: BLACK.stroke_width(1) }];
    let ramp = |c| {
        let mut marks: Vec<Mark> = (0..5).map(|k| Mark::Rect { from: (-20 + 8 * k, -9), to: (-12 + 8 * k, 9), style: shade(c, f64::from(k) / 4.0).filled() }).collect();
        marks.push(Mark::Rect { from: (-20, -9), to: (20, 9), style: BLACK.stroke_width(1) });
        marks
    };
    let mut legend = Legend::new(16.0);
    legend
        .entry("dissipative: valid loops", cell(shade(BLUE, 1.0)))
        .entry("cavitating: loops through invalid states", cell(shade(ORANGE, 1.0)))
        .entry("smooth-like: no roughness-induced loop", cell(RGBColor(225, 225, 225)))
        .entry(format!("shade: dissipation |W| from 0 to {}", short(wmax)), ramp(BLUE))
        .entry("(same shading for cavitating cells)", ramp(ORANGE));

    let (plot_w, legend_w) = (860u32, legend.size().0 as u32 + 30);
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, (plot_w + legend_w, 800)).into_drawing_area();
        root.fill(&WHITE).map_err(plot_err)?;
        let (plot, beside) = root.split_horizontally(plot_w);
        let title = match g.axis {
            // the profile, which may not fit a title, is listed in the legend
            SweepAxis::Amplitude => format!("Regime map: amplitude scale s over log10 λ (amax = {}, {} points per curve)", short(g.amax), g.points),
            _ => format!("Regime map: {} over log10 λ, {} (amax = {}, {} points per curve)", axis_name(g.axis), fixed_label(g), short(g.amax), g.points),
        };
        let cells = s.points.iter().map(|p| {
            let t = (p.dissipation.abs() / wmax).clamp(0.0, 1.0);
            let col = match p.regime {
                Regime::Dissipative => shade(BLUE, t),
                Regime::Cavitating => shade(ORANGE, t),
                Regime::SmoothLike => RGBColor(225, 225, 225),
            };
            (p.lambda, p.value, col)
        });
        regime_panel(&plot, g, &title, 18, cells, &[])?;
        legend.draw(&beside, (10, 80), legend_w as i32 - 20)?;
        if let (SweepAxis::Amplitude, Some(p)) = (g.axis, &g.profile) {
            // the profile, a wave a line, below the legend
            let style = TextStyle::from(("sans-serif", 16).into_font());
            for (k, line) in profile_legend(p).iter().enumerate() {
                let y = 80 + legend.size().1 + 30 + 22 * k as i32;
                beside.draw(&Text::new(line.as_str(), (20, y), style.clone())).map_err(plot_err)?;
            }
        }
        root.present().map_err(plot_err)?;
    }
    Ok(svg)
}

/// `β = ...` or `α = ...`: the parameter a map holds fixed; on the amplitude axis
/// the profile it scales.
pub(crate) fn fixed_label(g: &SweepGrid) -> String {
    match (g.axis, &g.profile) {
        (SweepAxis::Amplitude, Some(p)) => format!("s × [{}]", profile_title(p)),
        (SweepAxis::Beta, _) => format!("α = {}", short(g.fixed)),
        _ => format!("β = {}", short(g.fixed)),
    }
}

/// The lines naming the profile of an amplitude map below its legend: the profile as
/// [`profile_title`] names it, a wave a line (at most eight listed).
fn profile_legend(p: &maugis::contact::profile::WavyProfile) -> Vec<String> {
    let mut lines = vec!["profile, every α_j times s:".to_string()];
    match p.waves() {
        [_] => lines.push(profile_title(p)),
        ws => {
            lines.push(format!("{} waves (α, β) =", ws.len()));
            for (j, w) in ws.iter().enumerate().take(8) {
                lines.push(format!("{}({}, {})", if j == 0 { "" } else { "+ " }, args::sig4(w.alpha()), args::sig4(w.beta())));
            }
            if ws.len() > 8 {
                lines.push(format!("+ {} more (sweep.json)", ws.len() - 8));
            }
        }
    }
    lines
}

/// The second axis' label on a map.
fn axis_label(g: &SweepGrid) -> &'static str {
    match g.axis {
        SweepAxis::Amplitude => "amplitude scale s",
        a => a.name(),
    }
}

/// One regime panel on `area`: a cell per grid point `(lambda, value, colour)`
/// over log10 lambda and the second axis, and a black ring (radius 7 px) on
/// each point of `rings`.
pub(crate) fn regime_panel<DB: DrawingBackend>(
    area: &DrawingArea<DB, plotters::coord::Shift>,
    g: &SweepGrid,
    title: &str,
    title_size: u32,
    cells: impl Iterator<Item = (f64, f64, RGBColor)>,
    rings: &[(f64, f64)],
) -> Result<(), String> {
    let (l0, l1) = (g.lambda_min.log10(), g.lambda_max.log10());
    let dl = if g.lambda_n > 1 { (l1 - l0) / (g.lambda_n - 1) as f64 } else { 1.0 };
    let dv = if g.n > 1 { (g.max - g.min) / (g.n - 1) as f64 } else { 1.0 };
    let mut chart = ChartBuilder::on(area)
        .caption(title, ("sans-serif", title_size))
        .margin(12)
        .x_label_area_size(55)
        .y_label_area_size(75)
        .build_cartesian_2d((l0 - dl / 2.0)..(l1 + dl / 2.0), (g.min - dv / 2.0)..(g.max + dv / 2.0))
        .map_err(plot_err)?;
    chart
        .configure_mesh()
        .x_desc("log10 λ (Maugis parameter)")
        .y_desc(axis_label(g))
        .axis_desc_style(("sans-serif", 18))
        .label_style(("sans-serif", 15))
        .x_label_formatter(&tick)
        .y_label_formatter(&tick)
        .disable_mesh()
        .draw()
        .map_err(plot_err)?;
    chart
        .draw_series(cells.map(|(lambda, v, col)| {
            let x = lambda.log10();
            Rectangle::new([(x - dl / 2.0, v - dv / 2.0), (x + dl / 2.0, v + dv / 2.0)], col.filled())
        }))
        .map_err(plot_err)?;
    chart.draw_series(rings.iter().map(|&(lambda, v)| Circle::new((lambda.log10(), v), 7, BLACK.stroke_width(2)))).map_err(plot_err)?;
    Ok(())
}

fn files_of(s: &Sweep) -> Result<Vec<OutFile>, String> {
    let mut files = vec![OutFile::text("sweep.csv", sweep_csv(s)?)];
    let mut json = serde_json::to_string_pretty(s).map_err(|e| format!("could not format JSON: {e}"))?;
    json.push('\n');
    files.push(OutFile::text("sweep.json", json));
    if s.shard.is_none() {
        files.push(OutFile::text("sweep.svg", sweep_svg(s)?));
    }
    Ok(files)
}

fn report(s: &Sweep, written: &[PathBuf], out: &std::path::Path, secs: Option<f64>) -> String {
    let mut r = String::new();
    let count = |reg: Regime| s.points.iter().filter(|p| p.regime == reg).count();
    let _ = writeln!(
        r,
        "maugis sweep: {} point(s){}{}: {} dissipative, {} cavitating, {} smooth-like",
        s.points.len(),
        s.shard.map_or(String::new(), |(a, b)| format!(" (shard {a}/{b})")),
        secs.map_or(String::new(), |t| format!(" in {t:.1} s")),
        count(Regime::Dissipative),
        count(Regime::Cavitating),
        count(Regime::SmoothLike)
    );
    if let (SweepAxis::Amplitude, Some(p)) = (s.grid.axis, &s.grid.profile) {
        let _ = writeln!(r, "profile: {}, every amplitude times s in [{}, {}]", profile_report(p), short(s.grid.min), short(s.grid.max));
    }
    let _ = writeln!(r, "wrote {} file(s) to {}:", written.len(), out.display());
    for p in written {
        let _ = writeln!(r, "  {}", p.display());
    }
    r
}

/// Runs `maugis sweep`.
pub fn run(a: SweepArgs) -> Result<(), String> {
    let many = a.roughness.many_waves_given();
    let axis = match (a.axis, many) {
        (None, true) | (Some(Axis::Amplitude), _) => SweepAxis::Amplitude,
        (Some(other), true) => {
            return Err(format!(
                "--axis {} sweeps one wave's parameter: a profile of --wave/--waves/--weierstrass is swept on --axis amplitude (every amplitude times s)",
                other.to_possible_value().map_or_else(String::new, |v| v.get_name().to_string())
            ))
        }
        (None, false) | (Some(Axis::Alpha), false) => SweepAxis::Alpha,
        (Some(Axis::Beta), false) => SweepAxis::Beta,
        (Some(Axis::Johnson), false) => SweepAxis::Johnson,
    };
    let (min, max) = (a.min.unwrap_or(0.0), a.max.unwrap_or(if axis == SweepAxis::Amplitude { 1.0 } else { 0.7 }));
    let (fixed, profile) = match axis {
        SweepAxis::Alpha | SweepAxis::Johnson => (a.roughness.values().1, None),
        SweepAxis::Beta => (a.roughness.values().0, None),
        SweepAxis::Amplitude => (0.0, Some(a.roughness.profile()?)),
    };
    if a.lambda_max < a.lambda_min {
        return Err(format!("--lambda-max ({}) must be >= --lambda-min ({})", num(a.lambda_max), num(a.lambda_min)));
    }
    if max < min {
        return Err(format!("--max ({}) must be >= --min ({})", num(max), num(min)));
    }
    if matches!(axis, SweepAxis::Beta | SweepAxis::Johnson) && min <= 0.0 {
        return Err(format!("--min must be > 0 for --axis {} (got {})", axis_name(axis), num(min)));
    }
    if a.solver {
        if let Some(p) = profile.filter(|p| p.len() > 1) {
            return Err(format!(
                "--solver maps one wave's cycles, but the profile has {} waves: map it with the model (without --solver)",
                p.len()
            ));
        }
    }
    let grid = SweepGrid { lambda_min: a.lambda_min, lambda_max: a.lambda_max, lambda_n: a.lambda_n, axis, min, max, n: a.n, fixed, profile, amax: a.amax, points: a.points };
    grid.check().map_err(|e| e.to_string())?;
    match (&profile, axis) {
        (Some(p), _) => args::check_profile_size("--amax", a.amax, p)?,
        (None, SweepAxis::Beta) => args::check_size("--amax", a.amax, 1.0, min)?,
        (None, _) => args::check_size("--amax", a.amax, 1.0, fixed)?,
    }
    check_out_dir(&a.out)?;
    if a.solver {
        return solver_map::run(&a, grid);
    }
    let total = a.shard.map_or(grid.len(), |(s, n)| (0..grid.len()).filter(|k| k % n == s - 1).count());
    let pb = progress(total as u64, "sweep");
    let t0 = Instant::now();
    let sweep = run_sweep(grid, a.shard, || pb.inc(1)).map_err(|e| e.to_string())?;
    pb.finish_and_clear();
    let secs = t0.elapsed().as_secs_f64();
    let written = write_atomically(&a.out, &files_of(&sweep)?)?;
    print_stdout(&report(&sweep, &written, &a.out, Some(secs)))
}

/// Runs `maugis merge`.
pub fn run_merge(a: MergeArgs) -> Result<(), String> {
    check_out_dir(&a.out)?;
    let mut parts = Vec::new();
    let mut maps = Vec::new();
    for d in &a.shards {
        let path = d.join("sweep.json");
        let text = std::fs::read_to_string(&path).map_err(|e| format!("cannot read {}: {e}", path.display()))?;
        let bad = |e: serde_json::Error| format!("{}: not a sweep.json ({e})", path.display());
        let v: serde_json::Value = serde_json::from_str(&text).map_err(bad)?;
        if solver_map::is_solver_map(&v) {
            maps.push(serde_json::from_value(v).map_err(bad)?);
        } else {
            parts.push(serde_json::from_value(v).map_err(bad)?);
        }
    }
    if !maps.is_empty() {
        if !parts.is_empty() {
            return Err("cannot merge model sweeps with solver maps (maugis sweep --solver)".into());
        }
        return solver_map::merge(&maps, &a.out);
    }
    let sweep = merge(&parts).map_err(|e| e.to_string())?;
    let written = write_atomically(&a.out, &files_of(&sweep)?)?;
    print_stdout(&report(&sweep, &written, &a.out, None))
}
