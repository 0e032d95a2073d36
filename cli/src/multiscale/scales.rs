//! `maugis multiscale scales` and `maugis multiscale merge`: W and cavitation
//! against the number of scales (docs/multiscale.md, questions 2 and 3). The
//! computing is the solver's (`maugis_solver::scales`); this file parses, runs
//! with a progress bar and writes.
//!
//! Files in `--out`: `scales.json` (the spec and every cycle: what `merge`
//! reads), and for a whole study (not a shard) `scales.csv` (one row per
//! Hurst exponent, lambda and number of scales), `cycles.csv` (every cycle run),
//! `scales.md` (the tables of docs/multiscale.md) and `scales.svg` (W against N).

use std::fmt::Write as _;
use std::path::PathBuf;

use clap::Args;
use plotters::prelude::*;

use maugis_solver::scales::{merge, run_study_reusing, shard_cases, CycleRole, ScaleCycle, ScaleResolution, ScalesRow, ScalesSpec, ScalesStudy};

use crate::args::{self, short};
use crate::curve::progress;
use crate::output::{check_out_dir, print_stdout, write_atomically, OutFile};
use crate::plot::{colour, finish_load_area_chart, plot_err, xy_chart, Legend, LEGEND_FONT, LEGEND_WIDTH};

/// Flags of `maugis multiscale scales`.
#[derive(Args, Debug)]
pub struct ScalesArgs {
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
    /// Maugis parameters.
    #[arg(long, value_name = "L", value_delimiter = ',', default_value = "1/2,1,3,6,30", value_parser = args::positive, allow_negative_numbers = true)]
    pub lambda: Vec<f64>,
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
    /// Model curve points per cycle.
    #[arg(long, value_name = "N", default_value = "600", value_parser = args::grid_points)]
    pub model_points: usize,
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
    let spec = ScalesSpec {
        alpha: a.alpha,
        beta: a.beta,
        gamma: a.gamma,
        hursts: a.hurst.clone(),
        lambdas: a.lambda.clone(),
        max_scales: a.max_scales,
        amax: a.amax,
        resolution: ScaleResolution { cells_per_wavelength: a.cells_per_wavelength, steps_per_wavelength: a.steps_per_wavelength, refinement: a.refine },
        model_points: a.model_points,
        law: Default::default(),
    };
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
    let failed = study.cycles.iter().filter(|c| c.error.is_some()).count();
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

fn rows_csv(rows: &[ScalesRow]) -> String {
    let mut s = String::from(
        "hurst,lambda,scales,cells,steps_per_leg,w,w_d,w_smooth,w_sum_of_singles,w_d_sum_of_singles,cavitated_fraction,max_intervals,pull_off,model_w,model_w_d,model_valid,model_valid_fraction,traction_estimate,seconds,error\n",
    );
    for r in rows {
        let c = &r.profile;
        let _ = writeln!(
            s,
            "{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},\"{}\"",
            r.hurst,
            r.lambda,
            r.scales,
            c.cells,
            c.steps_per_leg,
            opt(c.w),
            opt(c.w_d),
            opt(r.w_smooth),
            opt(r.w_sum_of_singles),
            opt(r.w_d_sum_of_singles),
            c.cavitated_fraction,
            c.max_intervals,
            opt(c.pull_off),
            opt(c.model.map(|m| m.w)),
            opt(c.model.map(|m| m.w_d)),
            c.model.map_or(String::new(), |m| m.valid.to_string()),
            opt(c.model.map(|m| m.valid_fraction)),
            c.traction_estimate,
            c.seconds,
            c.error.as_deref().unwrap_or("").replace('"', "'")
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
    let mut s = String::from("index,lambda,waves,roles,cells,steps_per_leg,half_width,w,w_d,cavitated_fraction,max_intervals,pull_off,model_w,model_w_d,model_valid,seconds,error\n");
    for c in cycles {
        let waves = c.waves.iter().map(|(a, b)| format!("{a}:{b}")).collect::<Vec<_>>().join(" ");
        let roles = c.roles.iter().map(role_name).collect::<Vec<_>>().join("; ");
        let _ = writeln!(
            s,
            "{},{},{waves},{roles},{},{},{},{},{},{},{},{},{},{},{},{},\"{}\"",
            c.index,
            c.lambda,
            c.cells,
            c.steps_per_leg,
            c.half_width,
            opt(c.w),
            opt(c.w_d),
            c.cavitated_fraction,
            c.max_intervals,
            opt(c.pull_off),
            opt(c.model.map(|m| m.w)),
            opt(c.model.map(|m| m.w_d)),
            c.model.map_or(String::new(), |m| m.valid.to_string()),
            c.seconds,
            c.error.as_deref().unwrap_or("").replace('"', "'")
        );
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

/// W against N: one line per lambda (colour) and Hurst exponent
/// (solid and dashed), the sum of the single scales as open circles.
fn w_svg(study: &ScalesStudy, rows: &[ScalesRow]) -> Result<String, String> {
    let spec = &study.spec;
    let ys = rows.iter().flat_map(|r| [r.profile.w, r.w_sum_of_singles]).flatten().filter(|v| v.is_finite());
    let ymax = ys.fold(1.0f64, f64::max) * 1.08;
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, (1300 + LEGEND_WIDTH, 900)).into_drawing_area();
        root.fill(&WHITE).map_err(plot_err)?;
        let title = format!("W of the closed cycle against the number of scales (gamma = {})", short(spec.gamma));
        let mut chart = xy_chart(&root, title, (0.5, spec.max_scales as f64 + 0.5), (0.0, ymax), ("number of scales N", "W (load control), units of dgamma l_h"))?;
        let mut legend = Legend::new(LEGEND_FONT);
        for (i, &l) in spec.lambdas.iter().enumerate() {
            for (k, &hurst) in spec.hursts.iter().enumerate() {
                let of: Vec<&ScalesRow> = rows.iter().filter(|r| r.hurst == hurst && r.lambda == l).collect();
                let pts: Vec<(f64, f64)> = of.iter().filter_map(|r| r.profile.w.map(|w| (r.scales as f64, w))).collect();
                let sums: Vec<(f64, f64)> = of.iter().filter_map(|r| r.w_sum_of_singles.map(|w| (r.scales as f64, w))).collect();
                let st = ShapeStyle { color: colour(i).to_rgba(), filled: false, stroke_width: 2 };
                if k == 0 {
                    chart.draw_series(LineSeries::new(pts.clone(), st)).map_err(plot_err)?;
                } else {
                    chart.draw_series(DashedLineSeries::new(pts.clone(), 10, 6, st)).map_err(plot_err)?;
                }
                chart.draw_series(pts.iter().map(|&p| Circle::new(p, 4, st.filled()))).map_err(plot_err)?;
                chart.draw_series(sums.iter().map(|&p| Circle::new(p, 6, st))).map_err(plot_err)?;
                legend.line(format!("lambda = {}, H = {}", short(l), short(hurst)), st, if k == 0 { 0 } else { 10 }, 6);
            }
        }
        let grey = ShapeStyle { color: RGBColor(90, 90, 90).to_rgba(), filled: false, stroke_width: 2 };
        let white = ShapeStyle { color: WHITE.to_rgba(), filled: true, stroke_width: 0 };
        legend.entry("sum of the single scales' W (open circles)", vec![crate::plot::Mark::circle(6, white, Some(grey))]);
        finish_load_area_chart(&chart, &root, &legend)?;
    }
    Ok(svg)
}
