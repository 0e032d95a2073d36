//! `maugis simulate`: the numerical Dugdale-Maugis solver (`maugis-solver`) on
//! one loading-unloading cycle under displacement control, next to the
//! semi-analytical load-area curve.
//!
//! Writes into `--out` (atomically, [`crate::output`]):
//!
//! * `simulate.csv`: `leg,approach,abar,load,contact_intervals,zone_cells,model_load,model_valid,load_controlled,zone_ends_placed`
//!   (`load_controlled`: the state is on the load-controlled path of its leg,
//!   `maugis_solver::path::load_controlled`; `zone_ends_placed`: `false` where the
//!   Dugdale zone ends on cell edges, with the grid-pinning error);
//! * `simulate.svg`: the simulated states over the semi-analytical curve (valid
//!   stretches solid, invalid ones faded), and the load-controlled path of each
//!   leg as a line (its jumps dashed).
//!
//! `--profile FILE.csv` replaces the built-in profile by a table (`x,h`,
//! `maugis_solver::profile_file`); `--periodic` makes the domain one period of
//! a periodic half-plane; `--half-width` sets the domain; `--law exp` the smooth
//! exponential adhesion law in place of Dugdale's. A table with a bad
//! line exits 2 naming the file and the line, before any work.
//!
//! `--format json` writes no file and prints one JSON object, with
//! `"dissipation": {"load_control": W, "displacement_control": W_d, "datum": ..}`,
//! W of the closed in-contact cycle as the model's curve defines it
//! (`maugis_solver::dissipation`), and `stiff_cycle_work`, the work
//! `oint L dDelta` of the simulated stiff-machine cycle (not W). Bad input exits
//! with code 2 before any work.

use std::fmt::Write as _;
use std::path::PathBuf;

use clap::{Args, ValueEnum};
use plotters::prelude::*;

use maugis::contact::curve::{load_area_curve, CurveOptions};
use maugis::contact::model::Params;
use maugis_solver::profile::AdhesionLaw;
use maugis_solver::profile_file::ProfileTable;
use maugis_solver::run::{simulate_with, Domain, SimulationOptions, SimulationSpec, StateRecord};

use crate::args::{self, short, Roughness};
use maugis::contact::profile::WavyProfile;
use crate::output::{check_out_dir, print_stdout, write_atomically, OutFile};
use crate::plot::{colour, finish_load_area_chart, load_area_chart, plot_err, Legend, Mark, LEGEND_FONT, LIGHT_GREY};

/// Output format.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum SimFormat {
    /// simulate.csv and simulate.svg in --out.
    Files,
    /// One JSON object on stdout, no files.
    Json,
}

/// The interface law (`--law`), shared with `maugis sweep --solver`.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, ValueEnum)]
pub enum LawArg {
    /// Dugdale-Maugis: constant stress lambda over the range 1/lambda (the paper's law).
    #[default]
    Dugdale,
    /// Smooth: hard wall and stress lambda exp(-lambda g), the same peak stress and work.
    Exp,
}

impl From<LawArg> for AdhesionLaw {
    fn from(l: LawArg) -> AdhesionLaw {
        match l {
            LawArg::Dugdale => AdhesionLaw::Dugdale,
            LawArg::Exp => AdhesionLaw::Exponential,
        }
    }
}

/// Flags of `maugis simulate`.
#[derive(Args, Debug)]
pub struct SimulateArgs {
    /// Maugis parameter lambda > 0.
    #[arg(long, value_name = "L", value_parser = args::positive, allow_negative_numbers = true)]
    pub lambda: f64,
    /// The profile: --alpha/--beta (one wave), or --wave/--waves/--weierstrass (many
    /// waves, the cylinder carrying them is simulated and compared with the model of
    /// the same profile).
    #[command(flatten)]
    pub roughness: Roughness,
    /// Loading stops at this contact half-width.
    #[arg(long, value_name = "X", default_value = "4", value_parser = args::positive, allow_negative_numbers = true)]
    pub amax: f64,
    /// Grid cells, a power of two.
    #[arg(long, value_name = "N", default_value = "4096")]
    pub grid: usize,
    /// Approach steps per leg.
    #[arg(long, value_name = "S", default_value = "100")]
    pub steps: usize,
    /// Output directory (written atomically).
    #[arg(long, value_name = "DIR", default_value = "maugis-simulate")]
    pub out: PathBuf,
    /// `files` (default) or `json`.
    #[arg(long, value_name = "FORMAT", default_value = "files")]
    pub format: SimFormat,
    /// A profile table in place of the built-in profile: CSV with the header
    /// `x,h`, in the normalised units of the built-in profile, x strictly
    /// increasing, covering the domain. --alpha/--beta (or --wave ...) then name the
    /// model the states are compared with (and that sizes the domain); without them
    /// no model is drawn or compared.
    #[arg(long, value_name = "FILE.csv")]
    pub profile: Option<PathBuf>,
    /// The domain half-width X (default: sized by the model for the free
    /// domain; beta/2, or the table's extent, for the periodic one).
    #[arg(long, value_name = "X", value_parser = args::positive, allow_negative_numbers = true)]
    pub half_width: Option<f64>,
    /// A periodic half-plane of period 2X: the built-in profile is then the
    /// wave alone, alpha (1 - cos(2 pi x/beta)) on [-beta/2, beta/2].
    #[arg(long)]
    pub periodic: bool,
    /// The adhesion law: `dugdale` (default) or `exp` (smooth, matched in
    /// peak stress and work of adhesion; docs/solver.md).
    #[arg(long, value_name = "LAW", default_value = "dugdale")]
    pub law: LawArg,
}

/// The solver's options from the flags: the profile table read and checked
/// (a bad line is an error naming the file and the line).
fn options(a: &SimulateArgs, waves: Option<WavyProfile>, without_model: bool) -> Result<SimulationOptions, String> {
    let profile = match &a.profile {
        None => None,
        Some(path) => {
            let text = std::fs::read_to_string(path).map_err(|e| format!("--profile {}: {e}", path.display()))?;
            Some(ProfileTable::parse(&text).map_err(|e| format!("--profile {}: {e}", path.display()))?)
        }
    };
    let domain = if a.periodic { Domain::Periodic } else { Domain::Free };
    Ok(SimulationOptions { profile, half_width: a.half_width, domain, law: a.law.into(), waves, without_model })
}

/// Runs the subcommand.
pub fn run(a: SimulateArgs) -> Result<(), String> {
    if a.format == SimFormat::Files {
        check_out_dir(&a.out)?;
    }
    if !(2..=100_000).contains(&a.steps) {
        return Err(format!("--steps must lie in [2, 100000] (got {})", a.steps));
    }
    // A profile table without --alpha/--beta/--wave names no model: none is
    // compared or drawn, and the smooth cylinder sizes the domain.
    let model_given = a.roughness.alpha.is_some() || a.roughness.beta.is_some() || a.roughness.many_waves_given();
    let without_model = a.profile.is_some() && !model_given;
    let profile = if without_model { WavyProfile::one_wave(0.0, 1.0).map_err(|e| e.to_string())? } else { a.roughness.profile()? };
    args::check_profile_params(&[a.lambda], &profile)?;
    let params = Params::with_profile(a.lambda, profile).map_err(|e| e.to_string())?;
    let (alpha, beta, waves) = match profile.waves() {
        [w] => (w.alpha(), w.beta(), None),
        ws => (ws.first().map_or(0.0, |w| w.alpha()), ws.first().map_or(1.0, |w| w.beta()), Some(profile)),
    };
    let opts = options(&a, waves, without_model)?;
    let profile_path = a.profile.clone();
    let spec = SimulationSpec { lambda: a.lambda, alpha, beta, amax: a.amax, cells: a.grid, steps_per_leg: a.steps };
    let pb = crate::curve::progress(2 * a.steps as u64, "simulating");
    let sim = simulate_with(spec, opts, &mut |k, total| {
        pb.set_length(total as u64);
        pb.set_position(k as u64);
    })
    .map_err(|e| match (&profile_path, &e) {
        (Some(path), maugis_solver::SolverError::ProfileCoverage { .. }) => format!("--profile {}: {e}", path.display()),
        _ => e.to_string(),
    })?;
    pb.finish_and_clear();
    let (x, c) = (sim.half_width, &sim.cycle);
    let report = sim.report();
    let all = &report.states;
    if a.format == SimFormat::Json {
        let text = serde_json::to_string(&report).map_err(|e| e.to_string())?;
        return print_stdout(&(text + "\n"));
    }
    let mut csv = String::from("leg,approach,abar,load,contact_intervals,zone_cells,model_load,model_valid,load_controlled,zone_ends_placed\n");
    for r in all {
        let _ = writeln!(
            csv,
            "{},{},{},{},{},{},{},{},{},{}",
            r.leg,
            r.approach,
            r.abar,
            r.load,
            r.contact_intervals,
            r.zone_cells,
            r.model_load.map(|v| v.to_string()).unwrap_or_default(),
            r.model_valid.map(|v| v.to_string()).unwrap_or_default(),
            r.load_controlled,
            r.zone_ends_placed
        );
    }
    let svg = overlay_svg(params, a.amax, all, a.periodic, without_model)?;
    let files = [OutFile::text("simulate.csv", csv), OutFile::text("simulate.svg", svg)];
    let written = write_atomically(&a.out, &files)?;
    let mut text = format!(
        "maugis simulate: lambda {}, {}, {} cells on [-{}, {}], {} states, dissipation W {} (load control), \
         W_d {} (displacement control, datum {}), stiff-cycle work {}, load-controlled pull-off {}\n",
        short(a.lambda),
        sim_profile_report(&profile, without_model),
        a.grid,
        short(x),
        short(x),
        all.len(),
        report.dissipation.as_ref().map(|d| short(d.load_control)).unwrap_or_else(|| "none".into()),
        report.dissipation.as_ref().map(|d| short(d.displacement_control)).unwrap_or_else(|| "none".into()),
        report.dissipation.as_ref().map(|d| short(d.datum)).unwrap_or_else(|| "none".into()),
        short(c.stiff_work),
        report.pull_off.map(short).unwrap_or_else(|| "none".into())
    );
    if without_model {
        let _ = writeln!(text, "  no model curve: the profile table is none of the model's profiles (give --alpha/--beta or --wave to compare with one)");
    }
    for p in written {
        let _ = writeln!(text, "  {}", p.display());
    }
    print_stdout(&text)
}

/// The profile in the report line: `alpha A, beta B` for one wave (the old wording),
/// the waves otherwise, `profile table` without a model.
fn sim_profile_report(profile: &WavyProfile, without_model: bool) -> String {
    match profile.waves() {
        _ if without_model => "profile table".into(),
        [w] => format!("alpha {}, beta {}", short(w.alpha()), short(w.beta())),
        _ => args::profile_report(profile),
    }
}

/// Simulated states (loading and unloading markers) over the model curve.
/// On the periodic domain the model (a cylinder) is not drawn, nor for a profile
/// table that names no model (`no_model`).
fn overlay_svg(params: Params, amax: f64, rows: &[StateRecord], periodic: bool, no_model: bool) -> Result<String, String> {
    let mut curve = load_area_curve(params, CurveOptions { amax, points: 400, ..CurveOptions::default() }).map_err(|e| e.to_string())?;
    if periodic || no_model {
        curve.points.clear();
    }
    let loads = curve.points.iter().map(|p| p.load).chain(rows.iter().map(|r| r.load));
    let (lo, hi) = loads.fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), v| (l.min(v), h.max(v)));
    let pad = 0.05 * (hi - lo).max(1.0);
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, (1000 + crate::plot::LEGEND_WIDTH, 850)).into_drawing_area();
        root.fill(&WHITE).map_err(plot_err)?;
        let title = if no_model && !periodic {
            format!("simulation: λ = {}, profile table (no model profile given)", short(params.lambda()))
        } else {
            format!("simulation vs model: λ = {}, {}", short(params.lambda()), args::profile_title(params.profile()))
        };
        let mut chart = load_area_chart(&root, title, amax, lo - pad, hi + pad)?;
        let mut legend = Legend::new(LEGEND_FONT);
        let mut first = [true, true];
        for w in curve.points.windows(2) {
            let valid = w[0].validity.valid && w[1].validity.valid;
            let style = if valid { colour(0).stroke_width(2) } else { LIGHT_GREY.mix(0.5).stroke_width(1) };
            chart.draw_series(LineSeries::new([(w[0].abar, w[0].load), (w[1].abar, w[1].load)], style)).map_err(plot_err)?;
            let k = usize::from(!valid);
            if first[k] {
                first[k] = false;
                legend.line(if valid { "model, valid" } else { "model, invalid (faded)" }, style, 0, 0);
            }
        }
        for (leg, col, name) in [
            ("loading", colour(3), "simulation, loading"),
            ("unloading", colour(2), "simulation, unloading"),
            ("reloading", colour(4), "simulation, reloading"),
        ] {
            // The load-controlled path: consecutive path states joined, solid
            // where the leg visits them in turn, dashed across a jump.
            let leg_rows: Vec<&StateRecord> = rows.iter().filter(|r| r.leg == leg).collect();
            let mut last: Option<(usize, (f64, f64))> = None;
            let mut labelled = false;
            for (i, r) in leg_rows.iter().enumerate().filter(|(_, r)| r.load_controlled && r.abar > 0.0) {
                let p = (r.abar, r.load);
                if let Some((j, q)) = last {
                    if i == j + 1 {
                        chart.draw_series(LineSeries::new([q, p], col.stroke_width(1))).map_err(plot_err)?;
                    } else {
                        chart.draw_series(DashedLineSeries::new([q, p], 4, 4, col.stroke_width(1))).map_err(plot_err)?;
                    }
                    if !labelled {
                        labelled = true;
                        legend.line(format!("{name}, load-controlled path (jumps dashed)"), col.stroke_width(1), 0, 0);
                    }
                }
                last = Some((i, p));
            }
            let pts: Vec<(f64, f64)> = rows.iter().filter(|r| r.leg == leg && r.abar > 0.0).map(|r| (r.abar, r.load)).collect();
            if pts.is_empty() {
                continue;
            }
            chart.draw_series(pts.iter().map(|&p| Circle::new(p, 3, col.filled()))).map_err(plot_err)?;
            legend.entry(name, vec![Mark::circle(4, col.filled(), None)]);
        }
        finish_load_area_chart(&chart, &root, &legend)?;
    }
    Ok(svg)
}
