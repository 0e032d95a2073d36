//! Drawing the figures of `maugis figures`: load-area panels (model curves with
//! their invalid stretches faded, limit lines, the solver's states overlaid,
//! marked loci) and profile panels (traction, displacement, gap of a few
//! states, from the model and from the solver).

use plotters::coord::Shift;
use plotters::prelude::*;

use maugis::contact::limits::{jkr_envelope, jkr_load, local_envelope, mdmt_envelope, mdmt_load, smooth_mdmt_load};
use maugis::contact::model::Params;

use crate::args::{num, short};
use crate::curve::{closed, draw_validity_runs, invalid_entry, validity_runs, Run};
use crate::plot::{clip_y, colour, plot_err, triangle_down, triangle_up, xy_chart, Legend, Mark, DARK_GREY, LEGEND_FONT, LEGEND_WIDTH, LIGHT_GREY};

use super::solver::{SolverLeg, SolverProfile};
use super::{Limit, Shape};

/// Chart type of every panel.
type Chart<'a, 'b> = ChartContext<'a, SVGBackend<'b>, Cartesian2d<plotters::coord::types::RangedCoordf64, plotters::coord::types::RangedCoordf64>>;

/// Pixel outline of a marker shape, half-size `s`.
pub fn outline(shape: Shape, s: i32) -> Vec<(i32, i32)> {
    match shape {
        Shape::Up => triangle_up(s),
        Shape::Down => triangle_down(s),
        Shape::Square => vec![(-s * 4 / 5, -s * 4 / 5), (s * 4 / 5, -s * 4 / 5), (s * 4 / 5, s * 4 / 5), (-s * 4 / 5, s * 4 / 5)],
        Shape::Diamond => vec![(0, -s), (s, 0), (0, s), (-s, 0)],
        Shape::Circle => (0..16)
            .map(|k| {
                let t = std::f64::consts::PI * k as f64 / 8.0;
                ((f64::from(s) * t.cos()).round() as i32, (f64::from(s) * t.sin()).round() as i32)
            })
            .collect(),
    }
}

/// A marker of `shape` at `p`, filled with `fill` and outlined with `edge`.
fn marker(chart: &mut Chart<'_, '_>, p: (f64, f64), shape: Shape, s: i32, fill: ShapeStyle, edge: ShapeStyle) -> Result<(), String> {
    let pts = outline(shape, s);
    chart
        .draw_series(std::iter::once(EmptyElement::at(p) + Polygon::new(pts.clone(), fill) + PathElement::new(closed(&pts), edge)))
        .map_err(plot_err)?;
    Ok(())
}

/// A limit line's points on `abar_i = amax i/n` and its style, dash, gap and label.
fn limit_line(limit: Limit, alpha: f64, beta: f64, amin: f64, amax: f64) -> Result<Vec<(Vec<(f64, f64)>, ShapeStyle, u32, u32, Option<String>)>, String> {
    let n = 800usize;
    let xs: Vec<f64> = (0..=n).map(|i| amin + (amax - amin) * i as f64 / n as f64).filter(|&x| x > 0.0).collect();
    let style = |c: RGBColor, w: u32| ShapeStyle { color: c.to_rgba(), filled: false, stroke_width: w };
    let e = |x: f64| move |e: maugis::Error| format!("limits at abar = {}: {e}", num(x));
    let params = |lambda: f64| Params::new(lambda, alpha, beta).map_err(|e| e.to_string());
    let pair = |f: &dyn Fn(f64) -> Result<(f64, f64), String>| -> Result<(Vec<(f64, f64)>, Vec<(f64, f64)>), String> {
        let (mut lo, mut hi) = (Vec::new(), Vec::new());
        for &x in &xs {
            let (l, h) = f(x)?;
            lo.push((x, l));
            hi.push((x, h));
        }
        Ok((lo, hi))
    };
    Ok(match limit {
        Limit::Jkr => {
            let pts = xs.iter().map(|&x| jkr_load(alpha, beta, x).map(|l| (x, l)).map_err(e(x))).collect::<Result<Vec<_>, _>>()?;
            vec![(pts, style(DARK_GREY, 2), 9, 6, Some("JKR limit λ→∞ (E.42a)".into()))]
        }
        Limit::JkrEnvelope => {
            let (lo, hi) = pair(&|x| jkr_envelope(alpha, beta, x).map_err(e(x)))?;
            vec![(lo, style(DARK_GREY, 1), 20, 8, Some("JKR envelope (E.42b)".into())), (hi, style(DARK_GREY, 1), 20, 8, None)]
        }
        Limit::Mdmt(lambda) => {
            let p = params(lambda)?;
            let pts = xs.iter().map(|&x| mdmt_load(p, x).map(|l| (x, l)).map_err(e(x))).collect::<Result<Vec<_>, _>>()?;
            vec![(pts, style(LIGHT_GREY, 2), 9, 6, Some(format!("M-DMT limit at λ = {} (E.43a)", short(lambda))))]
        }
        Limit::MdmtEnvelope(lambda) => {
            let p = params(lambda)?;
            let (lo, hi) = pair(&|x| mdmt_envelope(p, x).map_err(e(x)))?;
            vec![
                (lo, style(LIGHT_GREY, 1), 20, 8, Some(format!("M-DMT envelope at λ = {} (E.43d)", short(lambda)))),
                (hi, style(LIGHT_GREY, 1), 20, 8, None),
            ]
        }
        Limit::SmoothMdmt(lambda) => {
            let pts = xs.iter().map(|&x| smooth_mdmt_load(lambda, x).map(|l| (x, l)).map_err(e(x))).collect::<Result<Vec<_>, _>>()?;
            vec![(pts, style(LIGHT_GREY, 2), 9, 6, Some(format!("smooth M-DMT limit at λ = {} (E.44)", short(lambda))))]
        }
        Limit::Local(lambda, (a, b)) => {
            let p = Params::new(lambda, a, b).map_err(|e| e.to_string())?;
            let (lo, hi) = pair(&|x| local_envelope(p, x).map_err(e(x)))?;
            vec![(lo, style(DARK_GREY, 2), 6, 4, Some(format!("local envelope (Eq. 17) at λ = {}", short(lambda)))), (hi, style(DARK_GREY, 2), 6, 4, None)]
        }
    })
}

/// One model curve of a load-area panel: its run, colour index, load offset.
pub struct PanelCurve<'r> {
    pub run: &'r Run,
    pub colour: usize,
    pub offset: f64,
    /// Legend label instead of `λ = ...` (when a panel holds several roughnesses).
    pub label: Option<String>,
    /// The solver's cycle at the same parameters, if overlaid.
    pub solver: Option<&'r [SolverLeg]>,
}

/// A marked locus: on the curve of colour `colour` (with its offset), at `(abar, load)`.
pub struct Locus {
    pub colour: usize,
    pub abar: f64,
    pub load: f64,
    pub shape: Shape,
    pub label: String,
}

/// A load-area panel (SVG text).
#[allow(clippy::too_many_arguments)]
pub fn load_area_panel(
    title: &str,
    alpha: f64,
    beta: f64,
    (amin, amax): (f64, f64),
    y: Option<(f64, f64)>,
    limits: &[Limit],
    curves: &[PanelCurve<'_>],
    loci: &[Locus],
) -> Result<String, String> {
    // y window: the model and the solver inside [amin, amax], with a margin
    let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
    for c in curves {
        let solver = c.solver.unwrap_or(&[]).iter().flat_map(|l| l.states.iter().map(|s| (s.abar, s.load + c.offset)));
        for (a, l) in c.run.curve.points.iter().map(|p| (p.abar, p.load + c.offset)).chain(solver) {
            if a >= amin && a <= amax && l.is_finite() {
                lo = lo.min(l);
                hi = hi.max(l);
            }
        }
    }
    if !(lo.is_finite() && hi.is_finite()) {
        (lo, hi) = (-5.0, 25.0);
    }
    let span = (hi - lo).max(0.5);
    let (ymin, ymax) = y.unwrap_or((lo - 0.06 * span, hi + 0.06 * span));
    let mut lines = Vec::new();
    for &l in limits {
        lines.extend(limit_line(l, alpha, beta, amin, amax)?);
    }
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, (1200 + LEGEND_WIDTH, 850)).into_drawing_area();
        root.fill(&WHITE).map_err(plot_err)?;
        let mut chart = xy_chart(&root, title.to_string(), (amin, amax), (ymin, ymax), ("contact half-width ā", "load L̄"))?;
        let mut legend = Legend::new(LEGEND_FONT);
        if ymin < 0.0 && ymax > 0.0 {
            chart.draw_series(LineSeries::new(vec![(amin, 0.0), (amax, 0.0)], BLACK.mix(0.5).stroke_width(1))).map_err(plot_err)?;
        }
        for (pts, style, dash, gap, _) in &lines {
            for piece in clip_y(pts, ymin, ymax) {
                chart.draw_series(DashedLineSeries::new(piece, *dash, *gap, *style)).map_err(plot_err)?;
            }
        }
        let mut solver_drawn = false;
        for c in curves {
            let pts = c.run.curve.points.iter().filter(|p| p.abar >= amin && p.abar <= amax);
            let runs = validity_runs(pts, |p| (p.abar, p.load + c.offset));
            match &c.label {
                None => draw_validity_runs(&mut chart, &mut legend, runs, (ymin, ymax), c.colour, c.run.lambda)?,
                Some(label) => {
                    let mut scratch = Legend::new(LEGEND_FONT);
                    draw_validity_runs(&mut chart, &mut scratch, runs, (ymin, ymax), c.colour, c.run.lambda)?;
                    legend.line(label.as_str(), colour(c.colour).stroke_width(3), 0, 0);
                }
            }
            for leg in c.solver.unwrap_or(&[]) {
                solver_drawn = true;
                draw_solver_leg(&mut chart, leg, colour(c.colour), (amin, amax), (ymin, ymax), c.offset)?;
            }
        }
        for l in loci {
            if l.abar >= amin && l.abar <= amax && l.load >= ymin && l.load <= ymax {
                marker(&mut chart, (l.abar, l.load), l.shape, 8, WHITE.filled(), colour(l.colour).stroke_width(3))?;
            }
        }
        for (_, style, dash, gap, label) in lines {
            if let Some(l) = label {
                legend.line(l, style, dash, gap);
            }
        }
        let invalid_shown = curves.iter().any(|c| c.run.curve.points.iter().any(|p| !p.validity.valid && p.abar >= amin && p.abar <= amax));
        if invalid_shown {
            invalid_entry(&mut legend, "model, invalid state: cavitation (p̄ > 1) or interpenetration (ḡ < 0)");
        }
        if solver_drawn {
            let grey = RGBColor(120, 120, 120);
            let h = Legend::SWATCH / 2;
            let line = |dash| Mark::Line { points: vec![(-h, 0), (h, 0)], style: grey.stroke_width(1), dash, gap: 4 };
            legend.entry("solver (maugis-solver), loading; ā: total contact half-width", vec![line(2), Mark::polygon(outline(Shape::Diamond, 5), grey.filled(), None)]);
            legend.entry("solver, unloading", vec![line(7), Mark::polygon(outline(Shape::Square, 5), grey.filled(), None)]);
            let cavitated = curves
                .iter()
                .flat_map(|c| c.solver.unwrap_or(&[]).iter().flat_map(|l| l.states.iter()))
                .any(|s| s.intervals > 1 && s.abar >= amin && s.abar <= amax);
            if cavitated {
                legend.entry(
                    "solver state with cavitation (several contact intervals)",
                    vec![Mark::polygon(outline(Shape::Square, 5), WHITE.filled(), Some(grey.stroke_width(2)))],
                );
            }
        }
        for l in loci {
            legend.entry(l.label.clone(), vec![Mark::polygon(outline(l.shape, 8), WHITE.filled(), Some(colour(l.colour).stroke_width(3)))]);
        }
        crate::plot::finish_load_area_chart(&chart, &root, &legend)?;
    }
    Ok(svg)
}

/// The states of one solver leg, joined in order (dotted while loading,
/// dashed while unloading) with a marker each; hollow where the contact has
/// cavitated.
fn draw_solver_leg(chart: &mut Chart<'_, '_>, leg: &SolverLeg, col: RGBColor, (amin, amax): (f64, f64), (ymin, ymax): (f64, f64), offset: f64) -> Result<(), String> {
    let pts: Vec<(f64, f64)> = leg.states.iter().filter(|s| s.abar > 0.0).map(|s| (s.abar, s.load + offset)).collect();
    let (dash, gap, shape) = if leg.unloading { (7, 4, Shape::Square) } else { (2, 4, Shape::Diamond) };
    let line = col.mix(0.9).stroke_width(1);
    for piece in clip_y(&pts, ymin, ymax) {
        let piece: Vec<(f64, f64)> = piece.into_iter().filter(|p| p.0 >= amin && p.0 <= amax).collect();
        if piece.len() > 1 {
            chart.draw_series(DashedLineSeries::new(piece, dash, gap, line)).map_err(plot_err)?;
        }
    }
    // Markers are guides to the eye: one where the leg has moved by at least
    // 1.5 % of the window since the last one drawn (the line joins them all).
    let mut last: Option<(f64, f64)> = None;
    for s in leg.states.iter().filter(|s| s.abar >= amin && s.abar <= amax && s.abar > 0.0) {
        let p = (s.abar, s.load + offset);
        if p.1 < ymin || p.1 > ymax {
            continue;
        }
        if let Some(q) = last {
            if ((p.0 - q.0) / (amax - amin)).hypot((p.1 - q.1) / (ymax - ymin)) < 0.015 {
                continue;
            }
        }
        last = Some(p);
        if s.intervals > 1 {
            marker(chart, p, shape, 4, WHITE.filled(), col.stroke_width(2))?;
        } else {
            marker(chart, p, shape, 4, col.filled(), col.stroke_width(1))?;
        }
    }
    Ok(())
}

/// What a profile panel shows.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Quantity {
    /// Traction `pbar` against `xbar`.
    Traction,
    /// Displacement `ubar` (and the rigid profile) against `xbar`.
    Displacement,
    /// `ubar - C`, `C` its value at the contact edge.
    ShiftedDisplacement,
    /// Gap against `xbar`.
    Gap,
    /// Gap against `xbar/abar`.
    GapOverA,
}

/// One profile line: label, colour index, dashed (solver) or solid (model), points
/// `(x, pbar, ubar, gbar)`, its contact edge.
pub struct ProfileLine {
    pub label: String,
    pub colour: usize,
    pub solver: bool,
    pub abar: f64,
    pub c: Option<f64>,
    pub samples: Vec<[f64; 4]>,
}

impl ProfileLine {
    /// The line of a solver state (its contact edge: the outermost one).
    pub fn of_solver(label: String, colour: usize, p: &SolverProfile) -> ProfileLine {
        ProfileLine { label, colour, solver: true, abar: p.outer, c: None, samples: p.samples.clone() }
    }
}

/// Panels stacked vertically, one per `quantity`, over `0 <= xbar <= xmax`
/// (`x/abar` for the gap); the rigid profile is drawn in the displacement
/// panels from `rigid` (`(x, hbar)`).
pub fn profile_figure(title: &str, xmax: f64, quantities: &[(Quantity, String)], lines: &[ProfileLine], rigid: &[(f64, f64)], delta: &[(String, f64)]) -> Result<String, String> {
    let h = 120 + 430 * quantities.len() as u32;
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, (1200 + LEGEND_WIDTH, h)).into_drawing_area();
        root.fill(&WHITE).map_err(plot_err)?;
        let root = root.titled(title, ("sans-serif", 24)).map_err(plot_err)?;
        let panels = root.split_evenly((quantities.len(), 1));
        for ((q, caption), area) in quantities.iter().zip(&panels) {
            profile_panel(area, *q, caption, xmax, lines, rigid, delta)?;
        }
        root.present().map_err(plot_err)?;
    }
    Ok(svg)
}

fn profile_panel(area: &DrawingArea<SVGBackend<'_>, Shift>, q: Quantity, caption: &str, xmax: f64, lines: &[ProfileLine], rigid: &[(f64, f64)], delta: &[(String, f64)]) -> Result<(), String> {
    let shift = |l: &ProfileLine| -> f64 {
        if q != Quantity::ShiftedDisplacement {
            return 0.0;
        }
        // C: the displacement at the contact edge (the sample nearest to it)
        l.samples.iter().min_by(|a, b| (a[0] - l.abar).abs().total_cmp(&(b[0] - l.abar).abs())).map(|s| s[2]).unwrap_or(0.0)
    };
    let series: Vec<(usize, Vec<(f64, f64)>)> = lines
        .iter()
        .enumerate()
        .map(|(i, l)| {
            let c = shift(l);
            let pts = l
                .samples
                .iter()
                .map(|s| match q {
                    Quantity::Traction => (s[0], s[1]),
                    Quantity::Displacement | Quantity::ShiftedDisplacement => (s[0], s[2] - c),
                    Quantity::Gap => (s[0], s[3]),
                    Quantity::GapOverA => (s[0] / l.abar, s[3]),
                })
                .filter(|p| p.0 <= xmax)
                .collect();
            (i, pts)
        })
        .collect();
    // the gap against x/a: as far as the widest model state reaches
    let xmax = if q == Quantity::GapOverA { xmax / lines.iter().map(|l| l.abar).fold(f64::MIN_POSITIVE, f64::max) } else { xmax };
    let series: Vec<(usize, Vec<(f64, f64)>)> = series.into_iter().map(|(i, pts)| (i, pts.into_iter().filter(|p| p.0 <= xmax).collect())).collect();
    let show_rigid = q == Quantity::Displacement;
    let rigid: Vec<(f64, f64)> = if show_rigid { rigid.iter().copied().filter(|p| p.0 <= xmax).collect() } else { Vec::new() };
    let ys = series.iter().flat_map(|s| s.1.iter().map(|p| p.1)).chain(rigid.iter().map(|p| p.1));
    let (mut lo, mut hi) = ys.filter(|v| v.is_finite()).fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), v| (l.min(v), h.max(v)));
    if q == Quantity::Traction {
        (lo, hi) = (lo.min(-0.1), hi.max(1.1));
    }
    if matches!(q, Quantity::Gap | Quantity::GapOverA) {
        hi = hi.min(2.5 * delta.iter().map(|d| d.1).fold(0.0, f64::max)).max(0.1);
        lo = lo.min(0.0);
    }
    if !(lo.is_finite() && hi.is_finite()) {
        (lo, hi) = (-1.0, 1.0);
    }
    let span = (hi - lo).max(1e-3);
    let (ylo, yhi) = (lo - 0.06 * span, hi + 0.06 * span);
    let xdesc = if q == Quantity::GapOverA { "scaled position x̄/ā" } else { "position x̄ (symmetric half)" };
    let ydesc = match q {
        Quantity::Traction => "traction p̄ (tensile > 0)",
        Quantity::Displacement => "displacement ū",
        Quantity::ShiftedDisplacement => "ū − C",
        Quantity::Gap | Quantity::GapOverA => "gap ḡ",
    };
    let mut chart = xy_chart(area, caption.to_string(), (0.0, xmax), (ylo, yhi), (xdesc, ydesc))?;
    let mut legend = Legend::new(LEGEND_FONT);
    let grey = BLACK.mix(0.5).stroke_width(1);
    if q == Quantity::Traction {
        chart.draw_series(DashedLineSeries::new(vec![(0.0, 1.0), (xmax, 1.0)], 12, 6, grey)).map_err(plot_err)?;
        legend.line("p̄ = 1 (cohesive stress)", grey, 12, 6);
    }
    if matches!(q, Quantity::Gap | Quantity::GapOverA) {
        for (label, d) in delta {
            chart.draw_series(DashedLineSeries::new(vec![(0.0, *d), (xmax, *d)], 12, 6, grey)).map_err(plot_err)?;
            legend.line(label.as_str(), grey, 12, 6);
        }
    }
    if show_rigid && !rigid.is_empty() {
        let st = RGBColor(90, 90, 90).stroke_width(2);
        for piece in clip_y(&rigid, ylo, yhi) {
            chart.draw_series(LineSeries::new(piece, st)).map_err(plot_err)?;
        }
        legend.line("rigid profile h̄", st, 0, 0);
    }
    for (i, pts) in &series {
        let l = &lines[*i];
        let col = colour(l.colour);
        let (st, dash) = if l.solver { (col.stroke_width(2), 6) } else { (col.stroke_width(3), 0) };
        for piece in clip_y(pts, ylo, yhi) {
            if dash == 0 {
                chart.draw_series(LineSeries::new(piece, st)).map_err(plot_err)?;
            } else {
                chart.draw_series(DashedLineSeries::new(piece, dash, 4, st)).map_err(plot_err)?;
            }
        }
        // the contact edge (and strip end), thin, in the line's colour
        if !l.solver && q != Quantity::GapOverA {
            let thin = ShapeStyle { color: col.mix(0.6), filled: false, stroke_width: 1 };
            for x in std::iter::once(l.abar).chain(l.c) {
                if x <= xmax {
                    chart.draw_series(DashedLineSeries::new(vec![(x, ylo), (x, yhi)], 3, 5, thin)).map_err(plot_err)?;
                }
            }
        }
        legend.line(l.label.as_str(), st, dash, 4);
    }
    if lines.iter().any(|l| !l.solver) && q != Quantity::GapOverA {
        legend.line("contact edge ā and strip end m ā (model)", ShapeStyle { color: BLACK.mix(0.6), filled: false, stroke_width: 1 }, 3, 5);
    }
    let (xs, ys) = chart.plotting_area().get_pixel_range();
    let (w, _) = area.dim_in_pixel();
    let (x0, _) = area.get_base_pixel();
    let x = xs.end + 20 - x0;
    legend.draw(area, (x, ys.start - area.get_base_pixel().1), w as i32 - x - 10)?;
    Ok(())
}
