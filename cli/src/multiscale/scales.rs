//! `maugis multiscale scales`, `merge` and `transition`: W, cavitation and
//! lambda* against the number of scales (docs/multiscale.md, questions 2 and
//! 3). The computing is the solver's (`maugis_solver::scales`); this file
//! parses, runs with a progress bar and writes.
//!
//! Files in `--out`: `scales.json` (the spec and every cycle: what `merge`
//! reads), and for a whole study (not a shard) `scales.csv` (one row per
//! Hurst exponent, lambda and number of scales), `cycles.csv` (every cycle run),
//! `scales.md` (the tables of docs/multiscale.md) and `scales.svg` (W against N).
//! `transition` writes `transition.csv`, `transition.md` and `transition.json`:
//! lambda* per Hurst exponent and number of scales, with its uncertainty.

use std::fmt::Write as _;
use std::path::PathBuf;

use clap::Args;
use plotters::prelude::*;

use maugis_solver::scales::{lambda_star, merge, run_study_reusing, shard_cases, CycleRole, ScaleCycle, ScaleResolution, ScaleTransition, ScalesRow, ScalesSpec, ScalesStudy, StarScan};

use crate::args::{self, short};
use crate::curve::progress;
use crate::output::{check_out_dir, print_stdout, write_atomically, OutFile};
use crate::plot::{colour, plot_err, Legend, LEGEND_FONT, LEGEND_WIDTH};

/// The profiles and the resolution, shared by `scales` and `transition`.
#[derive(Args, Debug)]
pub struct StudyFlags {
    /// Amplitude alpha_1 of the first (coarsest) wave.
    #[arg(long, value_name = "A", default_value = "2*sqrt(2)/8", value_parser = args::positive, allow_negative_numbers = true)]
    pub alpha: f64,
    /// Wavelength beta_1 of the first wave.
    #[arg(long, value_name = "B", default_value = "9/8", value_parser = args::positive, allow_negative_numbers = true)]
    pub beta: f64,
    /// Wavelength ratio gamma > 1 of neighbouring scales.
    #[arg(long, value_name = "GAMMA", default_value = "2", value_parser = args::positive, allow_negative_numbers = true)]
    pub gamma: f64,
    /// Hurst exponents H in [0, 1].
    #[arg(long, value_name = "H", value_delimiter = ',', default_value = "0.5,0.8", value_parser = args::non_negative, allow_negative_numbers = true)]
    pub hurst: Vec<f64>,
    /// Profiles of 1 ..= N scales.
    #[arg(long, value_name = "N", default_value = "6", value_parser = clap::value_parser!(usize))]
    pub max_scales: usize,
    /// Largest contact half-width of every cycle.
    #[arg(long, value_name = "AMAX", default_value = "6", value_parser = args::positive, allow_negative_numbers = true)]
    pub amax: f64,
    /// Grid cells per finest wavelength.
    #[arg(long, value_name = "C", default_value = "16", value_parser = args::positive, allow_negative_numbers = true)]
    pub cells_per_wavelength: f64,
    /// Approach steps per leg per finest wavelength of contact half-width.
    #[arg(long, value_name = "S", default_value = "16", value_parser = args::positive, allow_negative_numbers = true)]
    pub steps_per_wavelength: f64,
    /// Multiply cells and steps by 2^R (the grid study).
    #[arg(long, value_name = "R", default_value = "0", value_parser = clap::value_parser!(u32))]
    pub refine: u32,
    /// Model curve points per cycle (at least 32 per finest wavelength).
    #[arg(long, value_name = "N", default_value = "600", value_parser = args::grid_points)]
    pub model_points: usize,
}

impl StudyFlags {
    /// The study's spec at `lambdas`.
    fn spec(&self, lambdas: Vec<f64>) -> ScalesSpec {
        ScalesSpec {
            alpha: self.alpha,
            beta: self.beta,
            gamma: self.gamma,
            hursts: self.hurst.clone(),
            lambdas,
            max_scales: self.max_scales,
            amax: self.amax,
            resolution: ScaleResolution { cells_per_wavelength: self.cells_per_wavelength, steps_per_wavelength: self.steps_per_wavelength, refinement: self.refine },
            model_points: self.model_points,
            law: Default::default(),
        }
    }
}

/// Flags of `maugis multiscale scales`.
#[derive(Args, Debug)]
pub struct ScalesArgs {
    /// The profiles and the resolution.
    #[command(flatten)]
    pub study: StudyFlags,
    /// Maugis parameters.
    #[arg(long, value_name = "L", value_delimiter = ',', default_value = "1/2,1,3,6,30", value_parser = args::positive, allow_negative_numbers = true)]
    pub lambda: Vec<f64>,
    /// Compute only shard s of n (1-based), e.g. --shard 3/8 in an array job.
    #[arg(long, value_name = "S/N", value_parser = crate::sweep::shard)]
    pub shard: Option<(usize, usize)>,
    /// Take the cycles an earlier study (its output directory, holding a
    /// scales.json) ran with the same amax, resolution and model points from it
    /// instead of running them again (repeatable): a study of more scales extends
    /// one of fewer.
    #[arg(long, value_name = "DIR")]
    pub reuse: Vec<PathBuf>,
    /// Output directory (written atomically).
    #[arg(long, value_name = "DIR", default_value = "maugis-scales")]
    pub out: PathBuf,
}

/// Flags of `maugis multiscale transition`.
#[derive(Args, Debug)]
pub struct TransitionArgs {
    /// The profiles and the resolution.
    #[command(flatten)]
    pub study: StudyFlags,
    /// The numbers of scales to search (default 1 ..= --max-scales).
    #[arg(long, value_name = "N", value_delimiter = ',', value_parser = clap::value_parser!(usize))]
    pub scales: Vec<usize>,
    /// Scan range of lambda.
    #[arg(long, value_name = "L", default_value = "0.1", value_parser = args::positive, allow_negative_numbers = true)]
    pub lambda_min: f64,
    /// Scan range of lambda.
    #[arg(long, value_name = "L", default_value = "10", value_parser = args::positive, allow_negative_numbers = true)]
    pub lambda_max: f64,
    /// Scan points (log-spaced).
    #[arg(long, value_name = "N", default_value = "7", value_parser = clap::value_parser!(usize))]
    pub scan: usize,
    /// The threshold: this fraction of the model's W in the JKR limit.
    #[arg(long, value_name = "F", default_value = "0.05", value_parser = args::positive, allow_negative_numbers = true)]
    pub fraction: f64,
    /// Bisect until the bracket's ratio is below 1 + this.
    #[arg(long, value_name = "T", default_value = "0.03", value_parser = args::positive, allow_negative_numbers = true)]
    pub rel_tol: f64,
    /// Skip the refined search (no grid uncertainty).
    #[arg(long)]
    pub no_refine: bool,
    /// Output directory (written atomically).
    #[arg(long, value_name = "DIR", default_value = "maugis-transition")]
    pub out: PathBuf,
}

/// Flags of `maugis multiscale merge`.
#[derive(Args, Debug)]
pub struct ScalesMergeArgs {
    /// The shards' output directories (each holds a scales.json); one whole
    /// study's directory redraws its tables and figure.
    #[arg(value_name = "SHARD_DIR", required = true)]
    pub shards: Vec<PathBuf>,
    /// Output directory of the merged study.
    #[arg(long, value_name = "DIR", default_value = "maugis-scales")]
    pub out: PathBuf,
}

/// Runs `maugis multiscale scales`.
pub fn run_scales(a: ScalesArgs) -> Result<(), String> {
    let spec = a.study.spec(a.lambda.clone());
    // every case checked before any work
    let cases = shard_cases(&spec, a.shard).map_err(|e| e.to_string())?;
    check_out_dir(&a.out)?;
    let earlier = a.reuse.iter().map(|d| read_study(d)).collect::<Result<Vec<_>, _>>()?;
    let pb = progress(cases.len() as u64, "scales: simulated cycles");
    let study = run_study_reusing(spec, a.shard, &earlier, |_| pb.inc(1)).map_err(|e| e.to_string())?;
    pb.finish_and_clear();
    write_study(&study, &a.out)
}

/// Runs `maugis multiscale merge`.
pub fn run_merge(a: ScalesMergeArgs) -> Result<(), String> {
    check_out_dir(&a.out)?;
    let parts = a.shards.iter().map(|d| read_study(d)).collect::<Result<Vec<_>, _>>()?;
    let study = merge(&parts).map_err(|e| e.to_string())?;
    write_study(&study, &a.out)
}

/// The study in `dir/scales.json`.
fn read_study(dir: &std::path::Path) -> Result<ScalesStudy, String> {
    let path = dir.join("scales.json");
    let text = std::fs::read_to_string(&path).map_err(|e| format!("cannot read {}: {e}", path.display()))?;
    serde_json::from_str::<ScalesStudy>(&text).map_err(|e| format!("{}: not a scales.json ({e})", path.display()))
}

/// Writes a study (a shard: its JSON only) and reports.
fn write_study(study: &ScalesStudy, out: &std::path::Path) -> Result<(), String> {
    let json = serde_json::to_string_pretty(study).map_err(|e| format!("could not format JSON: {e}"))?;
    let mut files = vec![OutFile::text("scales.json", json + "\n")];
    let rows = study.rows();
    if study.shard.is_none() {
        files.push(OutFile::text("scales.csv", rows_csv(&rows)));
        files.push(OutFile::text("cycles.csv", cycles_csv(&study.cycles)));
        files.push(OutFile::text("scales.md", tables_md(study, &rows)));
        files.push(OutFile::text("scales.svg", w_svg(study, &rows)?));
    }
    let written = write_atomically(out, &files)?;
    let mut report = String::new();
    let cpu: f64 = study.cycles.iter().map(|c| c.seconds).sum();
    let failed = study.cycles.iter().filter(|c| c.error.is_some() || c.model_error.is_some()).count();
    let _ = writeln!(
        report,
        "maugis multiscale scales: {} cycles{} ({failed} with an error), {:.0} s of cycle time",
        study.cycles.len(),
        study.shard.map_or(String::new(), |(s, n)| format!(" (shard {s}/{n})")),
        cpu
    );
    if study.shard.is_none() {
        let _ = write!(report, "{}", tables_md(study, &rows));
    }
    let _ = writeln!(report, "wrote {} file(s) to {}:", written.len(), out.display());
    for p in &written {
        let _ = writeln!(report, "  {}", p.display());
    }
    print_stdout(&report)
}

fn opt(x: Option<f64>) -> String {
    x.filter(|v| v.is_finite()).map_or(String::new(), |v| v.to_string())
}

/// The columns every cycle has, in both CSVs.
const MEASURED: &str = "cells,steps_per_leg,w,w_d,cavitated_fraction,max_intervals,pull_off,model_w,model_w_d,model_valid";

/// A cycle's [`MEASURED`] cells.
fn measured(c: &ScaleCycle) -> String {
    [
        c.cells.to_string(),
        c.steps_per_leg.to_string(),
        opt(c.w),
        opt(c.w_d),
        c.cavitated_fraction.to_string(),
        c.max_intervals.to_string(),
        opt(c.pull_off),
        opt(c.model.map(|m| m.w)),
        opt(c.model.map(|m| m.w_d)),
        c.model.map_or(String::new(), |m| m.valid.to_string()),
    ]
    .join(",")
}

/// A cycle's error as a quoted CSV cell.
fn error_cell(c: &ScaleCycle) -> String {
    let model = c.model_error.as_ref().map(|e| format!("model: {e}"));
    let parts: Vec<&str> = c.error.iter().chain(&model).map(String::as_str).collect();
    format!("\"{}\"", parts.join("; ").replace('"', "'"))
}

fn rows_csv(rows: &[ScalesRow]) -> String {
    let mut s = format!("hurst,lambda,scales,{MEASURED},w_smooth,w_sum_of_singles,w_d_sum_of_singles,model_valid_fraction,traction_estimate,seconds,error\n");
    for r in rows {
        let c = &r.profile;
        let _ = writeln!(
            s,
            "{},{},{},{},{},{},{},{},{},{},{}",
            r.hurst,
            r.lambda,
            r.scales,
            measured(c),
            opt(r.w_smooth),
            opt(r.w_sum_of_singles),
            opt(r.w_d_sum_of_singles),
            opt(c.model.map(|m| m.valid_fraction)),
            c.traction_estimate,
            c.seconds,
            error_cell(c)
        );
    }
    s
}

fn role_name(r: &CycleRole) -> String {
    match r {
        CycleRole::Profile { hurst, scales } => format!("profile H={} N={scales}", short(*hurst)),
        CycleRole::Single { hurst, wave } => format!("single H={} j={wave}", short(*hurst)),
        CycleRole::Smooth => "smooth".into(),
    }
}

fn cycles_csv(cycles: &[ScaleCycle]) -> String {
    let mut s = format!("index,lambda,waves,roles,half_width,{MEASURED},seconds,error\n");
    for c in cycles {
        let waves = c.waves.iter().map(|(a, b)| format!("{a}:{b}")).collect::<Vec<_>>().join(" ");
        let roles = c.roles.iter().map(role_name).collect::<Vec<_>>().join("; ");
        let _ = writeln!(s, "{},{},{waves},{roles},{},{},{},{}", c.index, c.lambda, c.half_width, measured(c), c.seconds, error_cell(c));
    }
    s
}

fn f2(x: Option<f64>) -> String {
    x.filter(|v| v.is_finite()).map_or("-".into(), |v| format!("{v:.2}"))
}

/// The tables of docs/multiscale.md: W against N (solver; sum of singles;
/// model where its cycle is valid), then cavitation.
fn tables_md(study: &ScalesStudy, rows: &[ScalesRow]) -> String {
    let spec = &study.spec;
    let mut s = String::new();
    for &hurst in &spec.hursts {
        let _ = writeln!(s, "\nW (load control) against N, H = {}: solver W / sum of the single scales' W / model W where its whole cycle is valid ('-': not valid)\n", short(hurst));
        let _ = write!(s, "| N |");
        for &l in &spec.lambdas {
            let _ = write!(s, " lambda = {} |", short(l));
        }
        let _ = writeln!(s);
        let _ = writeln!(s, "|---|{}", "---|".repeat(spec.lambdas.len()));
        for n in 1..=spec.max_scales {
            let _ = write!(s, "| {n} |");
            for &l in &spec.lambdas {
                let cell = match rows.iter().find(|r| r.hurst == hurst && r.lambda == l && r.scales == n) {
                    Some(r) => format!(
                        "{} / {} / {}",
                        f2(r.profile.w),
                        f2(r.w_sum_of_singles),
                        f2(r.profile.model.filter(|m| m.valid).map(|m| m.w))
                    ),
                    None => "not run".into(),
                };
                let _ = write!(s, " {cell} |");
            }
            let _ = writeln!(s);
        }
    }
    let _ = writeln!(s, "\nCavitation: the smallest N whose solver cycle holds a state of more than one contact interval (its cavitated fraction of states, its traction estimate alpha_N/(lambda beta_N)); the model's whole cycle valid up to N\n");
    let _ = writeln!(s, "| H | lambda | smallest N cavitating | cavitated fraction | alpha_N/(lambda beta_N) | largest N with a valid model cycle |");
    let _ = writeln!(s, "|---|---|---|---|---|---|");
    for &hurst in &spec.hursts {
        for &l in &spec.lambdas {
            let of: Vec<&ScalesRow> = rows.iter().filter(|r| r.hurst == hurst && r.lambda == l).collect();
            let first = of.iter().find(|r| r.profile.cavitated_fraction > 0.0);
            let valid = of.iter().filter(|r| r.profile.model.is_some_and(|m| m.valid)).map(|r| r.scales).max();
            let _ = writeln!(
                s,
                "| {} | {} | {} | {} | {} | {} |",
                short(hurst),
                short(l),
                first.map_or(format!("none up to {}", spec.max_scales), |r| r.scales.to_string()),
                first.map_or("-".into(), |r| format!("{:.3}", r.profile.cavitated_fraction)),
                first.map_or("-".into(), |r| format!("{:.3}", r.profile.traction_estimate)),
                valid.map_or("none".into(), |n| n.to_string())
            );
        }
    }
    s
}

/// W against N, one panel per lambda (each with its own W axis): the solver's
/// W for each Hurst exponent (solid, dashed), the sum of the single scales'
/// W (open circles) and the model's W where its whole cycle is valid
/// (triangles).
fn w_svg(study: &ScalesStudy, rows: &[ScalesRow]) -> Result<String, String> {
    let spec = &study.spec;
    let panels = spec.lambdas.len();
    let cols = panels.min(3);
    let grid_rows = panels.div_ceil(cols);
    let (pw, ph) = (560u32, 430u32);
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, (pw * cols as u32 + LEGEND_WIDTH, ph * grid_rows as u32 + 60)).into_drawing_area();
        root.fill(&WHITE).map_err(plot_err)?;
        let root = root.titled(&format!("W of the closed cycle against the number of scales N (gamma = {})", short(spec.gamma)), ("sans-serif", 24)).map_err(plot_err)?;
        let (left, _) = root.split_horizontally(pw * cols as u32);
        let areas = left.split_evenly((grid_rows, cols));
        let style = |k: usize, _i: usize| ShapeStyle { color: colour(k).to_rgba(), filled: false, stroke_width: 2 };
        for (i, (&l, area)) in spec.lambdas.iter().zip(&areas).enumerate() {
            let of: Vec<&ScalesRow> = rows.iter().filter(|r| r.lambda == l).collect();
            let ys = of.iter().flat_map(|r| [r.profile.w, r.w_sum_of_singles, r.profile.model.filter(|m| m.valid).map(|m| m.w)]).flatten().filter(|v| v.is_finite());
            let ymax = ys.fold(0.1f64, f64::max) * 1.1;
            let mut chart = ChartBuilder::on(area)
                .caption(format!("lambda = {}", short(l)), ("sans-serif", 20))
                .margin(12)
                .x_label_area_size(40)
                .y_label_area_size(55)
                .build_cartesian_2d(0.5..spec.max_scales as f64 + 0.5, 0.0..ymax)
                .map_err(plot_err)?;
            chart
                .configure_mesh()
                .x_labels(spec.max_scales.min(12))
                .x_label_formatter(&|v| format!("{v:.0}"))
                .y_label_formatter(&crate::plot::tick)
                .x_desc(if i / cols == grid_rows - 1 { "N" } else { "" })
                .y_desc("W")
                .label_style(("sans-serif", 15))
                .light_line_style(RGBColor(235, 235, 235))
                .draw()
                .map_err(plot_err)?;
            for (k, &hurst) in spec.hursts.iter().enumerate() {
                let mine: Vec<&&ScalesRow> = of.iter().filter(|r| r.hurst == hurst).collect();
                let pts: Vec<(f64, f64)> = mine.iter().filter_map(|r| r.profile.w.map(|w| (r.scales as f64, w))).collect();
                let sums: Vec<(f64, f64)> = mine.iter().filter_map(|r| r.w_sum_of_singles.map(|w| (r.scales as f64, w))).collect();
                let model: Vec<(f64, f64)> = mine.iter().filter_map(|r| r.profile.model.filter(|m| m.valid).map(|m| (r.scales as f64, m.w))).collect();
                let st = style(k, i);
                if k == 0 {
                    chart.draw_series(LineSeries::new(pts.clone(), st)).map_err(plot_err)?;
                } else {
                    chart.draw_series(DashedLineSeries::new(pts.clone(), 10, 6, st)).map_err(plot_err)?;
                }
                chart.draw_series(pts.iter().map(|&p| Circle::new(p, 4, st.filled()))).map_err(plot_err)?;
                chart.draw_series(sums.iter().map(|&p| Circle::new(p, 7, st))).map_err(plot_err)?;
                chart.draw_series(model.iter().map(|&p| TriangleMarker::new(p, 7, st))).map_err(plot_err)?;
            }
        }
        let mut legend = Legend::new(LEGEND_FONT);
        let grey = ShapeStyle { color: RGBColor(90, 90, 90).to_rgba(), filled: false, stroke_width: 2 };
        let white = ShapeStyle { color: WHITE.to_rgba(), filled: true, stroke_width: 0 };
        for (k, &hurst) in spec.hursts.iter().enumerate() {
            legend.line(format!("solver W, H = {}", short(hurst)), style(k, 0), if k == 0 { 0 } else { 10 }, 6);
        }
        legend.entry("sum of the single scales' W", vec![crate::plot::Mark::circle(7, white, Some(grey))]);
        legend.entry("model W (whole cycle valid)", vec![crate::plot::Mark::polygon(crate::plot::triangle_up(7), grey.filled(), None)]);
        let (w, _) = root.dim_in_pixel();
        let x = (pw * cols as u32) as i32 + 10;
        legend.draw(&root, (x, 40), w as i32 - x - 10)?;
        root.present().map_err(plot_err)?;
    }
    Ok(svg)
}

/// Runs `maugis multiscale transition`: lambda* against the number of scales,
/// the (H, N) searches in parallel.
pub fn run_transition(a: TransitionArgs) -> Result<(), String> {
    use rayon::prelude::*;
    let spec = a.study.spec(vec![a.lambda_min, a.lambda_max]);
    spec.check().map_err(|e| e.to_string())?;
    let scales: Vec<usize> = if a.scales.is_empty() { (1..=spec.max_scales).collect() } else { a.scales.clone() };
    if let Some(&n) = scales.iter().find(|&&n| n == 0 || n > spec.max_scales) {
        return Err(format!("--scales {n}: must lie in 1..={} (--max-scales)", spec.max_scales));
    }
    if a.scan < 2 {
        return Err(format!("--scan {}: need at least 2 points", a.scan));
    }
    if a.lambda_max <= a.lambda_min {
        return Err(format!("--lambda-max {} must exceed --lambda-min {}", short(a.lambda_max), short(a.lambda_min)));
    }
    check_out_dir(&a.out)?;
    let scan = StarScan { lambda_min: a.lambda_min, lambda_max: a.lambda_max, scan: a.scan, fraction: a.fraction, rel_tol: a.rel_tol, refine: !a.no_refine };
    let pairs: Vec<(f64, usize)> = spec.hursts.iter().flat_map(|&h| scales.iter().map(move |&n| (h, n))).collect();
    let pb = progress(pairs.len() as u64, "transition: lambda* searches");
    let results: Vec<(f64, usize, Result<ScaleTransition, String>)> = pairs
        .par_iter()
        .map(|&(h, n)| {
            let r = lambda_star(&spec, h, n, scan, &|_| {}).map_err(|e| e.to_string());
            pb.inc(1);
            (h, n, r)
        })
        .collect();
    pb.finish_and_clear();
    let mut csv = String::from("hurst,scales,fraction,w_jkr,threshold,lambda_star,lambda_star_coarse,rel_uncertainty,outside,non_monotone,evaluations,scan_excess,error\n");
    let mut md = String::from("| H | N | W_JKR | threshold | lambda* | uncertainty | coarse lambda* | excess on the scan |\n|---|---|---|---|---|---|---|---|\n");
    let mut found = Vec::new();
    for (h, n, r) in &results {
        match r {
            Ok(t) => {
                let outside = t.refined.as_ref().unwrap_or(&t.search).outside.map_or("", |o| o.name());
                let scan_excess: Vec<String> = t.search.evaluations.iter().take(a.scan).map(|e| format!("{:.3}:{:.3}", e.lambda, e.excess())).collect();
                let _ = writeln!(
                    csv,
                    "{h},{n},{},{},{},{},{},{},{outside},{},{},{},",
                    a.fraction,
                    t.w_jkr,
                    t.threshold,
                    opt(t.lambda_star()),
                    opt(t.search.lambda_star),
                    opt(t.relative_uncertainty()),
                    t.search.non_monotone || t.refined.as_ref().is_some_and(|r| r.non_monotone),
                    t.search.evaluations.len() + t.refined.as_ref().map_or(0, |r| r.evaluations.len()),
                    scan_excess.join(" ")
                );
                let _ = writeln!(
                    md,
                    "| {} | {n} | {:.2} | {:.3} | {} | {} | {} | {} |",
                    short(*h),
                    t.w_jkr,
                    t.threshold,
                    t.lambda_star().map_or(if outside.is_empty() { "-".to_string() } else { outside.to_string() }, |l| format!("{l:.3}")),
                    t.relative_uncertainty().map_or("-".into(), |u| format!("{:.0} %", 100.0 * u)),
                    t.search.lambda_star.map_or("-".into(), |l| format!("{l:.3}")),
                    scan_excess.join(", ")
                );
                found.push(t.clone());
            }
            Err(e) => {
                let _ = writeln!(csv, "{h},{n},{},,,,,,,,,,\"{}\"", a.fraction, e.replace('"', "'"));
                let _ = writeln!(md, "| {} | {n} | error: {e} | | | | | |", short(*h));
            }
        }
    }
    let json = serde_json::to_string_pretty(&serde_json::json!({ "spec": spec, "scan": scan, "transitions": found })).map_err(|e| format!("could not format JSON: {e}"))?;
    let written = write_atomically(&a.out, &[OutFile::text("transition.csv", csv), OutFile::text("transition.md", md.clone()), OutFile::text("transition.json", json + "\n")])?;
    let mut report = format!("maugis multiscale transition: {} searches\n{md}", results.len());
    let _ = writeln!(report, "wrote {} file(s) to {}:", written.len(), a.out.display());
    for p in &written {
        let _ = writeln!(report, "  {}", p.display());
    }
    print_stdout(&report)
}
