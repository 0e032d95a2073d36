//! `maugis profile`: the traction, displacement and gap profiles of one state
//! (one contact half-width `abar`), like the paper's Figs. 6, 8 and 9.
//!
//! The state is solved and sampled by the library ([`sample_state`]). Over the symmetric
//! half `xbar in [0, 1.5 m abar]` it writes `profile.csv` with the columns
//! `xbar,pbar,ubar,gbar,hbar` (traction, substrate displacement, gap, rigid
//! profile depth, all normalised) and `profile.svg` with three panels: traction;
//! displacement and rigid profile; gap with the interaction range
//! `deltabar = 1/lambda`. The contact edge `x = abar` and the strip end
//! `x = m abar` are marked with vertical lines, and the title states the
//! validity of the state. `--format json` prints the same data instead.

use std::fmt::Write as _;
use std::path::PathBuf;

use clap::{Args, ValueEnum};
use plotters::coord::Shift;
use plotters::prelude::*;
use serde::Serialize;

use maugis::contact::model::{Params, Validity};
use maugis::contact::located::{At, LocatedError};
use maugis::contact::state_profile::{sample_state, StateProfile};

use maugis::contact::units::{Material, Scales};

use crate::args::{self, num, short, Roughness, SiArgs};
use crate::integrate::digits_for;
use crate::output::{check_out_dir, print_stdout, write_atomically, OutFile};
use crate::plot::{clip_y, colour, plot_err, tick, Legend, DARK_GREY, LIGHT_GREY};

/// Output format.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum ProfileFormat {
    /// profile.csv and profile.svg in --out.
    Files,
    /// One JSON object on stdout, no files.
    Json,
}

/// Flags of `maugis profile`.
#[derive(Args, Debug)]
pub struct ProfileArgs {
    /// Contact half-width abar > 0 (required, or --half-width with --units si).
    #[arg(long, value_name = "A", value_parser = args::positive, allow_negative_numbers = true)]
    pub abar: Option<f64>,
    /// Contact half-width a in m (with --units si), instead of --abar.
    #[arg(long = "half-width", value_name = "M", value_parser = args::positive)]
    pub half_width: Option<f64>,
    /// Maugis parameter lambda > 0 [default: 1].
    #[arg(long, value_name = "L", value_parser = args::positive, allow_negative_numbers = true)]
    pub lambda: Option<f64>,
    /// --alpha, --beta.
    #[command(flatten)]
    pub roughness: Roughness,
    /// --units si and the material.
    #[command(flatten)]
    pub si: SiArgs,
    /// Sample points over xbar in [0, 1.5 m abar] (the edge and strip end are added).
    #[arg(long, value_name = "N", default_value = "600", value_parser = args::grid_points)]
    pub points: usize,
    /// Output directory (written atomically).
    #[arg(long, value_name = "DIR", default_value = "maugis-out")]
    pub out: PathBuf,
    /// `files` (default) or `json` (print to stdout, write nothing).
    #[arg(long, value_name = "FORMAT", default_value = "files")]
    pub format: ProfileFormat,
    /// Also the traction as certified balls at P bits (2..=1024): columns
    /// pbar_mid, pbar_rad (CSV) or fields (JSON samples), with m certified too.
    #[arg(long, value_name = "P", value_parser = clap::value_parser!(u32).range(2..=1024))]
    pub prec: Option<u32>,
}

/// One sample of the profile.
#[derive(Serialize, Clone)]
struct Sample {
    xbar: f64,
    pbar: f64,
    ubar: f64,
    gbar: f64,
    hbar: f64,
    /// The certified traction (with `--prec`): midpoint and radius, decimal.
    #[serde(skip_serializing_if = "Option::is_none")]
    pbar_mid: Option<String>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pbar_rad: Option<String>,
}

#[derive(Serialize)]
struct ProfileJson {
    lambda: f64,
    alpha: f64,
    beta: f64,
    /// Every wave, when the profile has other than exactly one.
    #[serde(skip_serializing_if = "Option::is_none")]
    waves: Option<maugis::contact::profile::WavyProfile>,
    abar: f64,
    m: f64,
    load: f64,
    valid: bool,
    min_strip_gap: f64,
    min_strip_gap_at: f64,
    max_traction: f64,
    max_traction_at: f64,
    samples: Vec<Sample>,
    #[serde(skip_serializing_if = "Option::is_none")]
    si: Option<ProfileSi>,
}

/// The state in SI units (with `--units si`); samples scale by `scales`
/// (`x` by `horizontal`, `u`, `g`, `h` by `vertical`, `p` by `sigma_pa`).
#[derive(Serialize)]
struct ProfileSi {
    material: Material,
    scales: Scales,
    sigma_pa: f64,
    delta_c_m: f64,
    half_width_m: f64,
    strip_end_m: f64,
    load_n_per_m: f64,
}

/// A one-line description of the validity of a state.
fn validity_text(v: &Validity) -> String {
    let (cav, pen) = (v.cavitation, v.interpenetration);
    match (cav, pen) {
        (false, false) => format!(
            "valid (max p̄ = {:.4} ≤ 1, min strip gap = {:.3e} ≥ 0)",
            v.max_traction, v.min_strip_gap
        ),
        (true, false) => format!("INVALID: cavitation, max p̄ = {:.4} > 1 at x̄ = {:.3}", v.max_traction, v.max_traction_at),
        (false, true) => format!(
            "INVALID: interpenetration, strip gap = {:.3e} < 0 at x̄ = {:.3}",
            v.min_strip_gap, v.min_strip_gap_at
        ),
        (true, true) => format!(
            "INVALID: cavitation (max p̄ = {:.4}) and interpenetration (min gap = {:.3e})",
            v.max_traction, v.min_strip_gap
        ),
    }
}

/// A sampling error in the command's words.
fn profile_error(e: LocatedError) -> String {
    let error = &e.error;
    match e.at {
        At::State { abar } => format!("abar = {}: {error}", num(abar)),
        At::CertifiedStripRatio { abar } => format!("abar = {}: certified m: {error}", num(abar)),
        At::Sample { xbar } => format!("at xbar = {}: {error}", num(xbar)),
        _ => e.to_string(),
    }
}

/// Runs `maugis profile`.
pub fn run(a: ProfileArgs) -> Result<(), String> {
    let si = a.si.resolve_with_waves(
        &[
            ("--lambda", a.lambda.is_some()),
            ("--alpha", a.roughness.alpha.is_some()),
            ("--beta", a.roughness.beta.is_some()),
            ("--abar", a.abar.is_some()),
        ],
        a.roughness.wave_pairs()?.as_deref(),
    )?;
    let (lambda, profile, abar) = match &si {
        Some(r) => {
            if r.lambdas.len() != 1 {
                return Err("profile takes one --sigma or --delta-c".into());
            }
            let hw = a.half_width.ok_or("--units si needs --half-width (the contact half-width in m)")?;
            (r.lambdas[0], r.profile, r.scales.from_horizontal(hw))
        }
        None => {
            if a.half_width.is_some() {
                return Err("--half-width needs --units si (or give --abar)".into());
            }
            (a.lambda.unwrap_or(1.0), a.roughness.profile()?, a.abar.ok_or("--abar is required (the contact half-width, normalised)")?)
        }
    };
    let flag = if si.is_some() { "--half-width" } else { "--abar" };
    let params = Params::with_profile(lambda, profile).map_err(|e| e.to_string())?;
    args::check_profile_size(flag, abar, &profile)?;
    let (alpha, beta) = (params.alpha(), params.beta());
    if a.format == ProfileFormat::Files {
        check_out_dir(&a.out)?;
    }
    let state = sample_state(params, abar, None, a.points).map_err(profile_error)?;
    let (m, load, validity) = (state.m, state.load, state.validity);
    let c = state.strip_end();
    // --prec: the traction at each sample as a certified ball, printed in decimal
    let certified: Vec<(String, String)> = match a.prec {
        Some(p) => state.certified_traction(p).map_err(profile_error)?.iter().map(|b| b.to_decimal(digits_for(p))).collect(),
        None => Vec::new(),
    };
    let mut certified = certified.into_iter();
    let samples: Vec<Sample> = state
        .samples
        .iter()
        .map(|s| {
            let (pbar_mid, pbar_rad) = certified.next().map_or((None, None), |(mid, rad)| (Some(mid), Some(rad)));
            Sample { xbar: s.xbar, pbar: s.pbar, ubar: s.ubar, gbar: s.gbar, hbar: s.hbar, pbar_mid, pbar_rad }
        })
        .collect();

    if a.format == ProfileFormat::Json {
        let out = ProfileJson {
            lambda: lambda,
            alpha,
            beta,
            waves: (profile.len() != 1).then_some(profile),
            abar: abar,
            m,
            load,
            valid: validity.valid,
            min_strip_gap: validity.min_strip_gap,
            min_strip_gap_at: validity.min_strip_gap_at,
            max_traction: validity.max_traction,
            max_traction_at: validity.max_traction_at,
            samples,
            si: si.as_ref().map(|r| ProfileSi {
                material: r.material,
                scales: r.scales,
                sigma_pa: r.scales.sigma(lambda),
                delta_c_m: r.scales.delta_c(lambda),
                half_width_m: r.scales.to_horizontal(abar),
                strip_end_m: r.scales.to_horizontal(c),
                load_n_per_m: r.scales.to_load(load),
            }),
        };
        let text = serde_json::to_string(&out).map_err(|e| format!("could not format JSON: {e}"))?;
        return print_stdout(&format!("{text}\n"));
    }

    let mut w = csv::Writer::from_writer(Vec::new());
    let err = |e: csv::Error| format!("could not format CSV: {e}");
    let mut header = vec!["xbar", "pbar", "ubar", "gbar", "hbar"];
    if si.is_some() {
        header.extend(["x_m", "p_pa", "u_m", "g_m", "h_m"]);
    }
    if a.prec.is_some() {
        header.extend(["pbar_mid", "pbar_rad"]);
    }
    w.write_record(&header).map_err(err)?;
    for s in &samples {
        let mut row = vec![s.xbar.to_string(), s.pbar.to_string(), s.ubar.to_string(), s.gbar.to_string(), s.hbar.to_string()];
        if let Some(r) = &si {
            let k = &r.scales;
            row.extend([k.to_horizontal(s.xbar), k.to_traction(s.pbar, lambda), k.to_vertical(s.ubar), k.to_vertical(s.gbar), k.to_vertical(s.hbar)].map(|v| v.to_string()));
        }
        if let (Some(mid), Some(rad)) = (&s.pbar_mid, &s.pbar_rad) {
            row.extend([mid.clone(), rad.clone()]);
        }
        w.write_record(&row).map_err(err)?;
    }
    let csv_bytes = w.into_inner().map_err(|e| format!("could not format CSV: {e}"))?;
    let svg = profile_svg(&samples, &state)?;
    let files = [OutFile { name: "profile.csv".into(), bytes: csv_bytes }, OutFile::text("profile.svg", svg)];
    let written = write_atomically(&a.out, &files)?;
    let mut report = String::new();
    let _ = writeln!(
        report,
        "maugis profile: lambda = {}, {}, abar = {}: m = {:.6}, strip end c = {:.6}, load = {:.6}",
        short(lambda),
        args::profile_report(&profile),
        short(abar),
        m,
        c,
        load
    );
    let _ = writeln!(report, "  {}", validity_text(&validity));
    if let Some(r) = &si {
        let k = &r.scales;
        let _ = writeln!(
            report,
            "  SI: a = {:.4e} m, c = {:.4e} m, load = {:.4e} N/m, sigma_0 = {:.4e} Pa, delta_c = {:.4e} m",
            k.to_horizontal(abar),
            k.to_horizontal(c),
            k.to_load(load),
            k.sigma(lambda),
            k.delta_c(lambda)
        );
    }
    let _ = writeln!(report, "wrote {} file(s) to {}:", written.len(), a.out.display());
    for p in &written {
        let _ = writeln!(report, "  {}", p.display());
    }
    print_stdout(&report)
}

/// Range of the given values with a margin.
fn range_of(vals: impl Iterator<Item = f64>) -> (f64, f64) {
    let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
    for v in vals.filter(|v| v.is_finite()) {
        lo = lo.min(v);
        hi = hi.max(v);
    }
    if !(lo.is_finite() && hi.is_finite()) {
        return (-1.0, 1.0);
    }
    let span = (hi - lo).max(1e-3);
    (lo - 0.08 * span, hi + 0.08 * span)
}

/// A line of a panel: legend label, colour, stroke width, points.
type Series = (String, RGBColor, u32, Vec<(f64, f64)>);

/// Draws one panel with series `(label, colour, points)`, vertical lines at the
/// contact edge and strip end, and optional horizontal reference lines; the
/// legend sits in the upper right corner of the data when `legend_right`, else
/// in the upper left.
#[allow(clippy::too_many_arguments)]
fn panel(
    area: &DrawingArea<SVGBackend<'_>, Shift>,
    caption: Option<&str>,
    ylabel: &str,
    xmax: f64,
    series: &[Series],
    hlines: &[(String, f64)],
    abar: f64,
    c: f64,
    show_x_label: bool,
    legend_right: bool,
) -> Result<(), String> {
    let (ylo, yhi) = range_of(series.iter().flat_map(|s| s.3.iter().map(|p| p.1)).chain(hlines.iter().map(|h| h.1)));
    let mut b = ChartBuilder::on(area);
    b.margin(12).margin_right(30).x_label_area_size(if show_x_label { 55 } else { 30 }).y_label_area_size(80);
    if let Some(cap) = caption {
        b.caption(cap, ("sans-serif", 22));
    }
    let mut chart = b.build_cartesian_2d(0.0..xmax, ylo..yhi).map_err(plot_err)?;
    let mut mesh = chart.configure_mesh();
    mesh.y_desc(ylabel)
        .axis_desc_style(("sans-serif", 20))
        .label_style(("sans-serif", 15))
        .x_label_formatter(&tick)
            .y_label_formatter(&tick)
            .light_line_style(RGBColor(238, 238, 238))
        .bold_line_style(RGBColor(210, 210, 210));
    if show_x_label {
        mesh.x_desc("position x̄ (normalised, symmetric half x̄ ≥ 0)");
    }
    mesh.draw().map_err(plot_err)?;

    let edge = ShapeStyle { color: DARK_GREY.to_rgba(), filled: false, stroke_width: 2 };
    let strip = ShapeStyle { color: LIGHT_GREY.to_rgba(), filled: false, stroke_width: 2 };
    let mut legend = Legend::new(15.0);
    chart.draw_series(DashedLineSeries::new(vec![(abar, ylo), (abar, yhi)], 8, 5, edge)).map_err(plot_err)?;
    legend.line(format!("contact edge x̄ = ā = {}", short(abar)), edge, 8, 5);
    chart.draw_series(DashedLineSeries::new(vec![(c, ylo), (c, yhi)], 3, 4, strip)).map_err(plot_err)?;
    legend.line(format!("strip end x̄ = m ā = {:.4}", c), strip, 3, 4);
    for (label, y) in hlines {
        let st = ShapeStyle { color: BLACK.mix(0.5), filled: false, stroke_width: 1 };
        chart.draw_series(DashedLineSeries::new(vec![(0.0, *y), (xmax, *y)], 12, 6, st)).map_err(plot_err)?;
        legend.line(label.as_str(), st, 12, 6);
    }
    for (label, col, width, pts) in series {
        let st = col.stroke_width(*width);
        for piece in clip_y(pts, ylo, yhi) {
            chart.draw_series(LineSeries::new(piece, st)).map_err(plot_err)?;
        }
        legend.line(label.as_str(), st, 0, 0);
    }
    // inside the plotting area, in the corner `legend_right` says
    let plot = chart.plotting_area().strip_coord_spec();
    let (w, _) = plot.dim_in_pixel();
    let (lw, _) = legend.size();
    let x = if legend_right { (w as i32 - lw - 8).max(8) } else { 8 };
    legend.draw(&plot, (x, 8), w as i32 - 16)?;
    Ok(())
}

/// The three-panel profile plot (SVG text) of the state.
fn profile_svg(s: &[Sample], state: &StateProfile) -> Result<String, String> {
    let lambda = state.params.lambda();
    let (abar, m, load, v) = (state.abar, state.m, state.load, &state.validity);
    let c = state.strip_end();
    let xmax = s.last().map(|p| p.xbar).unwrap_or(1.5 * c).max(1e-9);
    let pts = |f: fn(&Sample) -> f64| s.iter().map(|p| (p.xbar, f(p))).collect::<Vec<_>>();
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, (1200, 1250)).into_drawing_area();
        root.fill(&WHITE).map_err(plot_err)?;
        let title = format!(
            "State at ā = {}, λ = {}, {}: strip ratio m = {:.4}, load = {:.4}",
            short(abar),
            short(lambda),
            args::profile_title(state.params.profile()),
            m,
            load
        );
        let root = root.titled(&title, ("sans-serif", 26)).map_err(plot_err)?;
        let (head, body) = root.split_vertically(40);
        let vt = validity_text(v);
        let vcol = if v.valid { RGBColor(30, 120, 30) } else { RGBColor(200, 20, 20) };
        head.draw(&Text::new(vt, (80, 8), ("sans-serif", 21).into_font().color(&vcol))).map_err(plot_err)?;
        let panels = body.split_evenly((3, 1));
        let [top, mid, bottom] = match panels.as_slice() {
            [a, b, c] => [a, b, c],
            _ => return Err("internal error: could not split the plot".into()),
        };
        panel(
            top,
            Some("traction (tensile > 0; p̄ = 1 in the adhesive strip)"),
            "traction p̄",
            xmax,
            &[("traction p̄".into(), colour(3), 3, pts(|p| p.pbar))],
            &[("p̄ = 1 (cohesive stress)".into(), 1.0), ("p̄ = 0".into(), 0.0)],
            abar,
            c,
            false,
            true,
        )?;
        panel(
            mid,
            Some("substrate displacement and rigid profile (positive downward)"),
            "ū, h̄",
            xmax,
            &[
                ("rigid profile h̄".into(), RGBColor(90, 90, 90), 2, pts(|p| p.hbar)),
                ("substrate displacement ū".into(), colour(2), 3, pts(|p| p.ubar)),
            ],
            &[],
            abar,
            c,
            false,
            false,
        )?;
        panel(
            bottom,
            Some("gap ḡ = h̄ − ū (zero in the contact)"),
            "gap ḡ",
            xmax,
            &[("gap ḡ".into(), colour(0), 3, pts(|p| p.gbar))],
            &[(format!("interaction range δ̄ = 1/λ = {}", short(1.0 / lambda)), 1.0 / lambda)],
            abar,
            c,
            true,
            false,
        )?;
        root.present().map_err(plot_err)?;
    }
    Ok(svg)
}
