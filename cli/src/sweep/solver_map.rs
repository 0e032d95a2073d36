//! `maugis sweep --solver`: the regime map drawn by the numerical solver
//! (library: `maugis_solver::map`), presented as CSV, JSON and SVG.
//!
//! Files in `--out`:
//!
//! * `sweep.csv`: one row per grid point, the columns of [`COLUMNS`]
//!   (`lambda`, `alpha`, `beta`, `w_solver`, `regime_solver`, `w_model`,
//!   `regime_model` among them; `docs/solver-map.md` defines each);
//! * `sweep.json`: the library's `SolverMap` with `"kind": "solver_map"`, which
//!   `maugis merge` reads back;
//! * `sweep.svg` (whole maps only): the solver's and the model's labels side by
//!   side, the points where they disagree ringed on both.

use std::fmt::Write as _;
use std::path::{Path, PathBuf};
use std::time::Instant;

use plotters::prelude::*;

use maugis::contact::sweep::{Regime, SweepGrid};
use maugis_solver::map::{map_cycles, merge_maps, model_regime_name, run_map, MapOptions, Resolution, ResolutionRule, SolverMap, SolverRegime};

use super::{axis_name, fixed_label, regime_panel, SweepArgs};
use crate::args::short;
use crate::curve::progress;
use crate::output::{print_stdout, write_atomically, OutFile};
use crate::plot::{plot_err, Legend, Mark};

/// The CSV columns.
pub const COLUMNS: [&str; 25] = [
    "index",
    "lambda",
    "value",
    "alpha",
    "beta",
    "cells",
    "steps_per_leg",
    "w_solver",
    "w_solver_cavitated",
    "w_solver_d",
    "w_smooth",
    "w_excess",
    "loops_solver",
    "instabilities_solver",
    "cavitated_fraction",
    "pull_off_solver",
    "regime_solver",
    "w_model",
    "w_model_invalid",
    "instabilities_model",
    "valid_fraction_model",
    "pull_off_model",
    "regime_model",
    "agree",
    "solver_error",
];

/// The `"kind"` of a solver map's `sweep.json`.
const KIND: &str = "solver_map";

/// Whether a parsed `sweep.json` is a solver map's.
pub fn is_solver_map(v: &serde_json::Value) -> bool {
    v.get("kind").and_then(|k| k.as_str()) == Some(KIND)
}

fn opt(v: Option<f64>) -> String {
    v.map_or(String::new(), |x| x.to_string())
}

fn map_csv(m: &SolverMap) -> Result<String, String> {
    let err = |e: csv::Error| format!("could not format CSV: {e}");
    let mut w = csv::Writer::from_writer(Vec::new());
    w.write_record(COLUMNS).map_err(err)?;
    for p in &m.points {
        let c = p.solver.as_ref();
        let cf = |f: fn(&maugis_solver::map::CycleMeasure) -> f64| opt(c.map(f));
        let row: [String; 25] = [
            p.index.to_string(),
            p.lambda.to_string(),
            p.value.to_string(),
            p.alpha.to_string(),
            p.beta.to_string(),
            c.map_or(String::new(), |c| c.resolution.cells.to_string()),
            c.map_or(String::new(), |c| c.resolution.steps_per_leg.to_string()),
            cf(|c| c.w),
            cf(|c| c.w_cavitated),
            cf(|c| c.w_d),
            opt(p.w_smooth),
            opt(c.zip(p.w_smooth).map(|(c, s)| c.w - s)),
            c.map_or(String::new(), |c| c.loops.to_string()),
            c.map_or(String::new(), |c| c.instabilities.to_string()),
            cf(|c| c.cavitated_fraction),
            opt(c.and_then(|c| c.pull_off)),
            p.regime_solver.name().to_string(),
            p.model.dissipation.to_string(),
            p.model.dissipation_invalid.to_string(),
            p.model.instabilities.to_string(),
            p.model.valid_fraction.to_string(),
            opt(p.model.pull_off),
            model_regime_name(p.model.regime).to_string(),
            p.agree.to_string(),
            p.solver_error.clone().unwrap_or_default(),
        ];
        w.write_record(row).map_err(err)?;
    }
    let bytes = w.into_inner().map_err(|e| format!("could not format CSV: {e}"))?;
    String::from_utf8(bytes).map_err(|e| format!("could not format CSV: {e}"))
}

const BLUE: RGBColor = RGBColor(31, 91, 180);
const ORANGE: RGBColor = RGBColor(214, 96, 24);
const PURPLE: RGBColor = RGBColor(128, 60, 160);
const LIGHT: RGBColor = RGBColor(225, 225, 225);
const FAILED: RGBColor = RGBColor(90, 90, 90);

fn solver_colour(r: SolverRegime) -> RGBColor {
    match r {
        SolverRegime::Dissipative => BLUE,
        SolverRegime::Both => PURPLE,
        SolverRegime::Cavitating => ORANGE,
        SolverRegime::SmoothLike => LIGHT,
        SolverRegime::Failed => FAILED,
    }
}

fn model_colour(r: Regime) -> RGBColor {
    match r {
        Regime::Dissipative => BLUE,
        Regime::Cavitating => ORANGE,
        Regime::SmoothLike => LIGHT,
    }
}

/// Both maps side by side, disagreeing points ringed on both, one legend below.
fn map_svg(m: &SolverMap) -> Result<String, String> {
    let g = &m.grid;
    let cell = |c: RGBColor| vec![Mark::Rect { from: (-12, -9), to: (12, 9), style: c.filled() }, Mark::Rect { from: (-12, -9), to: (12, 9), style: BLACK.stroke_width(1) }];
    let disagree: Vec<(f64, f64)> = m.points.iter().filter(|p| !p.agree).map(|p| (p.lambda, p.value)).collect();
    let mut legend = Legend::new(16.0);
    legend
        .entry(format!("dissipative: W above the smooth cylinder's by > {} (model: a valid loop)", short(m.options.margin)), cell(BLUE))
        .entry("both: dissipative and cavitated states (solver only)", cell(PURPLE))
        .entry("cavitating: cavitated states, no dissipation (model: loops, all invalid)", cell(ORANGE))
        .entry("smooth-like: neither (model: no roughness-induced loop)", cell(LIGHT))
        .entry(format!("labels disagree ({} of {} points)", disagree.len(), m.points.len()), vec![Mark::circle(7, WHITE.filled(), Some(BLACK.stroke_width(2)))]);
    if m.points.iter().any(|p| p.regime_solver == SolverRegime::Failed) {
        legend.entry("solver failed (see solver_error in the CSV)", cell(FAILED));
    }
    let (panel_w, panel_h) = (620u32, 640u32);
    let (lw, lh) = legend.size();
    let height = panel_h + lh as u32 + 40;
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, (2 * panel_w, height)).into_drawing_area();
        root.fill(&WHITE).map_err(plot_err)?;
        let (top, bottom) = root.split_vertically(panel_h);
        let (left, right) = top.split_horizontally(panel_w);
        let rule = match m.options.resolution {
            ResolutionRule::Auto => "per-λ resolution".to_string(),
            ResolutionRule::Fixed(r) => format!("{} cells, {} steps", r.cells, r.steps_per_leg),
        };
        let solver_title = format!("Solver: {} over log10 λ, {} ({rule})", axis_name(g.axis), fixed_label(g));
        let model_title = format!("Model: {} over log10 λ, {} ({} points per curve)", axis_name(g.axis), fixed_label(g), g.points);
        let solver_cells = m.points.iter().map(|p| (p.lambda, p.value, solver_colour(p.regime_solver)));
        regime_panel(&left, g, &solver_title, 16, solver_cells, &disagree)?;
        let model_cells = m.points.iter().map(|p| (p.lambda, p.value, model_colour(p.model.regime)));
        regime_panel(&right, g, &model_title, 16, model_cells, &disagree)?;
        let x = ((2 * panel_w) as i32 - lw).max(20) / 2;
        legend.draw(&bottom, (x, 10), (2 * panel_w) as i32 - 40)?;
        root.present().map_err(plot_err)?;
    }
    Ok(svg)
}

fn files_of(m: &SolverMap) -> Result<Vec<OutFile>, String> {
    let mut files = vec![OutFile::text("sweep.csv", map_csv(m)?)];
    let mut v = serde_json::to_value(m).map_err(|e| format!("could not format JSON: {e}"))?;
    if let Some(o) = v.as_object_mut() {
        o.insert("kind".into(), KIND.into());
    }
    let mut json = serde_json::to_string_pretty(&v).map_err(|e| format!("could not format JSON: {e}"))?;
    json.push('\n');
    files.push(OutFile::text("sweep.json", json));
    if m.shard.is_none() {
        files.push(OutFile::text("sweep.svg", map_svg(m)?));
    }
    Ok(files)
}

fn report(m: &SolverMap, written: &[PathBuf], out: &Path, secs: Option<f64>) -> String {
    let mut r = String::new();
    let count = |reg: SolverRegime| m.points.iter().filter(|p| p.regime_solver == reg).count();
    let _ = writeln!(
        r,
        "maugis sweep --solver: {} point(s){}{}: solver {} dissipative, {} both, {} cavitating, {} smooth-like, {} failed; \
         the model's label agrees at {}",
        m.points.len(),
        m.shard.map_or(String::new(), |(a, b)| format!(" (shard {a}/{b})")),
        secs.map_or(String::new(), |t| format!(" in {t:.1} s")),
        count(SolverRegime::Dissipative),
        count(SolverRegime::Both),
        count(SolverRegime::Cavitating),
        count(SolverRegime::SmoothLike),
        count(SolverRegime::Failed),
        m.points.iter().filter(|p| p.agree).count()
    );
    let _ = writeln!(r, "wrote {} file(s) to {}:", written.len(), out.display());
    for p in written {
        let _ = writeln!(r, "  {}", p.display());
    }
    r
}

/// Runs `maugis sweep --solver` on a checked grid (the output folder checked too).
pub fn run(a: &SweepArgs, grid: SweepGrid) -> Result<(), String> {
    let resolution = match (a.cells, a.steps) {
        (Some(cells), Some(steps_per_leg)) => ResolutionRule::Fixed(Resolution { cells, steps_per_leg }),
        _ => ResolutionRule::Auto,
    };
    let options = MapOptions { resolution, margin: a.margin, law: a.law.into() };
    let flag = |e: maugis_solver::SolverError| match resolution {
        ResolutionRule::Fixed(_) => format!("--cells/--steps: {e}"),
        ResolutionRule::Auto => format!("--margin: {e}"),
    };
    options.check().map_err(flag)?;
    let total = map_cycles(&grid, a.shard).map_err(|e| e.to_string())?.len();
    let pb = progress(total as u64, "solver cycles");
    let t0 = Instant::now();
    let map = run_map(grid, options, a.shard, || pb.inc(1)).map_err(|e| e.to_string())?;
    pb.finish_and_clear();
    let secs = t0.elapsed().as_secs_f64();
    let written = write_atomically(&a.out, &files_of(&map)?)?;
    print_stdout(&report(&map, &written, &a.out, Some(secs)))
}

/// `maugis merge` of solver-map shards.
pub fn merge(parts: &[SolverMap], out: &Path) -> Result<(), String> {
    let map = merge_maps(parts).map_err(|e| e.to_string())?;
    let written = write_atomically(out, &files_of(&map)?)?;
    print_stdout(&report(&map, &written, out, None))
}
