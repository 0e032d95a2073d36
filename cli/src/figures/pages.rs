//! The figures of `maugis figures`, one [`Figure`] each: parameters read off the
//! paper's captions and text, the panels they draw, and their section of
//! docs/figures.md.

use super::draw::{Locus, Quantity};
use super::*;

/// The page's opening paragraph.
pub const INTRO: &str = "Each load-area panel draws the semi-analytical curves of the model (solid where the \
state is valid; thin, faded and dotted where it is not: a traction above the cohesive stress inside the contact, \
so a valley would cavitate, or a negative gap in the adhesive strip), the limit lines of Appendix E in grey, and, \
where the paper overlays its GFMD results, the states of our FFT boundary-element solver (`maugis-solver`, \
docs/solver.md) on one displacement-controlled cycle: loading as diamonds on a dotted line, unloading as squares on \
a dashed line, hollow where the simulated contact has cavitated (more than one contact interval). A simulated \
state is drawn at its total intimate contact half-width, half the summed length of its contact intervals, as the \
paper draws its numerical results (\"the total intimate contact area\"): once the contact cavitates, the outermost \
contact edge jumps from crest to crest while the total contact changes continuously. The solver runs \
a stiff machine (displacement control), the GFMD of the paper too, so both show the stretches that load control \
would jump over. Profiles draw the model as solid lines and the solver as dashed lines, over the symmetric half \
x̄ ≥ 0, with the model's contact edge ā and strip end m ā as thin dashed verticals. All quantities are normalised \
as in docs/model.md; the traction is tensile positive, in units of the cohesive stress.";

const LAMBDAS4: [f64; 5] = [0.1, 0.25, 0.5, 1.0, 3.0];
const LAMBDAS3: [f64; 6] = [0.1, 0.25, 0.5, 1.0, 3.0, 6.0];

fn each(lambdas: &[f64], r: (f64, f64)) -> Vec<(f64, (f64, f64))> {
    lambdas.iter().map(|&l| (l, r)).collect()
}

fn curves_of(lambdas: &[f64], r: (f64, f64)) -> Vec<(f64, (f64, f64), usize, f64)> {
    lambdas.iter().enumerate().map(|(i, &l)| (l, r, i, 0.0)).collect()
}

/// The standard limits of a wavy load-area panel.
fn wavy_limits(mdmt: f64) -> Vec<Limit> {
    vec![Limit::Jkr, Limit::JkrEnvelope, Limit::Mdmt(mdmt), Limit::MdmtEnvelope(mdmt)]
}

fn locus(ctx: &Ctx, lambda: f64, r: (f64, f64), colour: usize, abar: f64, shape: Shape, what: &str) -> Result<Locus, String> {
    let load = ctx.load_at(lambda, r, abar)?;
    Ok(Locus { colour, abar, load, shape, label: format!("λ = {}: ā = {abar:.3}, L̄ = {load:.3} ({what})", short(lambda)) })
}

// ---------------------------------------------------------------- Fig. 2

fn fig02(ctx: &Ctx) -> Result<Vec<String>, String> {
    let t = "Fig. 2: limits of the load-area response, {α, β} = {√2/3, 2}, with the model at λ = 1/10 and 6";
    Ok(vec![la_panel(ctx, t, R4B, (0.0, 6.0), &[(0.1, R4B, 0, 0.0), (6.0, R4B, 5, 0.0)], &wavy_limits(0.1), &[], false, false)?])
}

// ---------------------------------------------------------------- Fig. 3

fn fig03(ctx: &Ctx) -> Result<Vec<String>, String> {
    let lim = [Limit::Jkr, Limit::SmoothMdmt(0.1)];
    let a = la_panel(ctx, "Fig. 3a: smooth cylinder {α, β} = {0, −}, model and solver", SMOOTH, (0.0, 6.0), &curves_of(&LAMBDAS3, SMOOTH), &lim, &[], false, true)?;
    let sub: Vec<_> = curves_of(&LAMBDAS3, SMOOTH).into_iter().filter(|c| c.0 != 1.0 && c.0 != 3.0).collect();
    let b = la_panel(ctx, "Fig. 3b: smooth cylinder near jump-out, 0 < ā ≤ 2", SMOOTH, (0.0, 2.0), &sub, &lim, &[], false, true)?;
    Ok(vec![a, b])
}

// ---------------------------------------------------------------- Fig. 4

fn fig04(ctx: &Ctx) -> Result<Vec<String>, String> {
    let mut out = Vec::new();
    for (p, r) in [("a", R4A), ("b", R4B), ("c", R4C)] {
        let t = format!("Fig. 4{p}: {{α, β}} = {}, model and solver", roughness_name(r));
        out.push(la_panel(ctx, &t, r, (0.0, 6.0), &curves_of(&LAMBDAS4, r), &wavy_limits(0.1), &[], false, true)?);
    }
    let d = [(3.0, R4C, 4, 0.0), (6.0, R4C, 5, 0.0)];
    out.push(la_panel(ctx, "Fig. 4d: {α, β} = {2√2/8, 9/8}, λ = 3 and 6", R4C, (0.0, 6.0), &d, &wavy_limits(0.1), &[], false, true)?);
    Ok(out)
}

// ---------------------------------------------------------------- Fig. 5

fn fig05_loci(ctx: &Ctx) -> Result<Vec<Locus>, String> {
    let [(l0, l1), (u0, u1)] = jumps(ctx, 6.0, (2.71, 3.16))?;
    let (c0, c1) = cavitating_stretch(&ctx.curve(0.25, R4C)?.curve, 3.0)?;
    Ok(vec![
        locus(ctx, 6.0, R4C, 1, l0, Shape::Up, "loading instability starts")?,
        locus(ctx, 6.0, R4C, 1, l1, Shape::Down, "loading jump lands")?,
        locus(ctx, 6.0, R4C, 1, u0, Shape::Down, "unloading instability starts")?,
        locus(ctx, 6.0, R4C, 1, u1, Shape::Up, "unloading jump lands")?,
        locus(ctx, 0.25, R4C, 0, c0, Shape::Circle, "first state with p̄ > 1: cavitation starts")?,
        locus(ctx, 0.25, R4C, 0, c1, Shape::Circle, "last state with p̄ > 1: cavitation ends")?,
    ])
}

fn fig05(ctx: &Ctx) -> Result<Vec<String>, String> {
    let t = "Fig. 5: {α, β} = {2√2/8, 9/8}, λ = 1/4 and 6, 2 ≤ ā ≤ 4";
    let cs = [(0.25, R4C, 0, 0.0), (6.0, R4C, 1, 0.0)];
    Ok(vec![la_panel(ctx, t, R4C, (2.0, 4.0), &cs, &wavy_limits(0.25), &fig05_loci(ctx)?, false, true)?])
}

// ---------------------------------------------------------------- Fig. 6

fn fig06(ctx: &Ctx) -> Result<Vec<String>, String> {
    let [(l0, l1), (u0, u1)] = jumps(ctx, 6.0, (2.71, 3.16))?;
    let q = [(Quantity::Displacement, "substrate displacement and rigid profile".to_string()), (Quantity::Traction, "traction".to_string())];
    let xmax = 5.0;
    let mut out = Vec::new();
    for (p, leg, (b, a)) in [("a", "loading", (l0, l1)), ("b", "unloading", (u0, u1))] {
        let lines = [model_line(6.0, R4C, b, 0, ", before the jump", xmax)?, model_line(6.0, R4C, a, 1, ", after the jump", xmax)?];
        let t = format!("Fig. 6{p}: λ = 6, {{2√2/8, 9/8}}, {leg}: just before and after the instability");
        out.push(profile_figure(&t, xmax, &q, &lines, &rigid(R4C, xmax)?, &[])?);
    }
    Ok(out)
}

// ---------------------------------------------------------------- Fig. 7

fn fig07_loci(ctx: &Ctx) -> Result<Vec<Locus>, String> {
    let [(a0, _), (b0, _)] = jumps(ctx, 1.5, (2.60, 2.77))?;
    let [(c0, _), (d0, _)] = jumps(ctx, 6.0, (2.71, 3.16))?;
    let mut v = vec![
        locus(ctx, 1.5, R4C, 3, a0, Shape::Square, "loading instability starts")?,
        locus(ctx, 1.5, R4C, 3, b0, Shape::Square, "unloading instability starts")?,
        locus(ctx, 6.0, R4C, 1, c0, Shape::Square, "loading instability starts")?,
        locus(ctx, 6.0, R4C, 1, d0, Shape::Square, "unloading instability starts")?,
    ];
    for (l, c) in [(1.5, 3), (6.0, 1)] {
        v.push(locus(ctx, l, R4C, c, 2.4, Shape::Circle, "Fig. 8a, ā = 12/5")?);
        v.push(locus(ctx, l, R4C, c, 3.16, Shape::Up, "Fig. 8a, ā = 79/25")?);
    }
    Ok(v)
}

fn fig07(ctx: &Ctx) -> Result<Vec<String>, String> {
    let t = "Fig. 7: {α, β} = {2√2/8, 9/8}, λ = 3/2 and 6";
    let cs = [(1.5, R4C, 3, 0.0), (6.0, R4C, 1, 0.0)];
    let lim = [Limit::Jkr, Limit::JkrEnvelope, Limit::MdmtEnvelope(1.5)];
    Ok(vec![la_panel(ctx, t, R4C, (1.5, 4.5), &cs, &lim, &fig07_loci(ctx)?, false, false)?])
}

// ---------------------------------------------------------------- Fig. 8

fn fig08(ctx: &Ctx) -> Result<Vec<String>, String> {
    let xmax = 4.5;
    let tq = [(Quantity::Traction, "traction".to_string())];
    let mut a = Vec::new();
    for (l, c, d) in [(1.5, 3, 4), (6.0, 1, 0)] {
        a.push(model_line(l, R4C, 2.4, c, "", xmax)?);
        a.push(model_line(l, R4C, 3.16, d, "", xmax)?);
    }
    let fa = profile_figure("Fig. 8a: traction at ā = 12/5 and 79/25, λ = 3/2 and 6", xmax, &tq, &a, &[], &[])?;
    let [(a0, _), (b0, _)] = jumps(ctx, 1.5, (2.60, 2.77))?;
    let [(c0, _), (d0, _)] = jumps(ctx, 6.0, (2.71, 3.16))?;
    let q = [(Quantity::Traction, "traction".to_string()), (Quantity::GapOverA, "gap against x̄/ā".to_string())];
    let delta = [("δ̄ = 1/λ at λ = 3/2".to_string(), 1.0 / 1.5), ("δ̄ = 1/λ at λ = 6".to_string(), 1.0 / 6.0)];
    let mut out = vec![fa];
    for (p, leg, unloading, (x32, x6)) in [("b", "loading", false, (a0, c0)), ("c", "unloading", true, (b0, d0))] {
        let mut lines = Vec::new();
        for (l, abar, c, cs) in [(1.5, x32, 3, 6), (6.0, x6, 1, 5)] {
            lines.push(model_line(l, R4C, abar, c, &format!(", {leg} turning point"), xmax)?);
            lines.extend(solver_line(ctx, l, R4C, unloading, abar, cs)?);
        }
        let t = format!("Fig. 8{p}: traction and gap just before the {leg} instabilities, λ = 3/2 and 6");
        out.push(profile_figure(&t, xmax, &q, &lines, &[], &delta)?);
    }
    Ok(out)
}

// ---------------------------------------------------------------- Figs. 9, 10

fn uq() -> [(Quantity, String); 2] {
    [(Quantity::Displacement, "substrate displacement and rigid profile".to_string()), (Quantity::Traction, "traction".to_string())]
}

fn fig09(ctx: &Ctx) -> Result<Vec<String>, String> {
    let (c0, c1) = cavitating_stretch(&ctx.curve(0.25, R4C)?.curve, 3.0)?;
    let xmax = 5.0;
    let mut out = Vec::new();
    for (p, leg, abar, unloading) in [("a", "loading", c0, false), ("b", "unloading", c1, true)] {
        let mut lines = vec![model_line(0.25, R4C, abar, 0, "", xmax)?];
        lines.extend(solver_line(ctx, 0.25, R4C, false, abar, 1)?);
        lines.extend(solver_line(ctx, 0.25, R4C, true, abar, 2)?);
        let t = format!("Fig. 9{p}: λ = 1/4, {{2√2/8, 9/8}}, at the {} end of the cavitating stretch ({leg})", if unloading { "upper" } else { "lower" });
        out.push(profile_figure(&t, xmax, &uq(), &lines, &rigid(R4C, xmax)?, &[])?);
    }
    Ok(out)
}

fn fig10(ctx: &Ctx) -> Result<Vec<String>, String> {
    let xmax = 5.0;
    let mut lines = vec![model_line(0.25, R4C, 3.0, 0, "", xmax)?];
    lines.extend(solver_line(ctx, 0.25, R4C, false, 3.0, 1)?);
    lines.extend(solver_line(ctx, 0.25, R4C, true, 3.0, 2)?);
    let mut q = uq().to_vec();
    q.push((Quantity::Gap, "gap (the paper's inset)".to_string()));
    let delta = [("interaction range δ̄ = 1/λ = 4".to_string(), 4.0)];
    Ok(vec![profile_figure("Fig. 10: λ = 1/4, {2√2/8, 9/8}, ā ≈ 3, loading and unloading", xmax, &q, &lines, &rigid(R4C, xmax)?, &delta)?])
}

// ---------------------------------------------------------------- Fig. 11

const FIG11_ABARS: [(f64, Shape, &str); 3] = [(2.96, Shape::Square, "Fig. 12a"), (3.25, Shape::Up, "Fig. 12b"), (3.63, Shape::Circle, "Fig. 12c")];

fn fig11_loci(ctx: &Ctx) -> Result<Vec<Locus>, String> {
    let mut v = Vec::new();
    for (l, c) in [(0.1, 0), (0.5, 2)] {
        for (abar, shape, what) in FIG11_ABARS {
            v.push(locus(ctx, l, R4B, c, abar, shape, what)?);
        }
    }
    Ok(v)
}

fn fig11(ctx: &Ctx) -> Result<Vec<String>, String> {
    let t = "Fig. 11: {α, β} = {√2/3, 2}, λ = 1/10 and 1/2, 2.5 ≤ ā ≤ 4.5";
    let cs = [(0.1, R4B, 0, 0.0), (0.5, R4B, 2, 0.0)];
    let lim = [Limit::Mdmt(0.1), Limit::MdmtEnvelope(0.1), Limit::JkrEnvelope];
    Ok(vec![la_panel(ctx, t, R4B, (2.5, 4.5), &cs, &lim, &fig11_loci(ctx)?, false, true)?])
}

// ---------------------------------------------------------------- Fig. 12

fn fig12(ctx: &Ctx) -> Result<Vec<String>, String> {
    let xmax = 8.0;
    let q = [(Quantity::ShiftedDisplacement, "displacement shifted to 0 at the contact edge".to_string()), (Quantity::Traction, "traction".to_string())];
    let mut out = Vec::new();
    for (p, (abar, _, _)) in ["a", "b", "c"].into_iter().zip(FIG11_ABARS) {
        let mut lines = vec![model_line(0.1, R4B, abar, 0, "", xmax)?, model_line(0.5, R4B, abar, 2, "", xmax)?];
        lines.extend(solver_line(ctx, 0.1, R4B, false, abar, 1)?);
        let t = format!("Fig. 12{p}: {{√2/3, 2}}, λ = 1/10 and 1/2 at ā = {abar}");
        out.push(profile_figure(&t, xmax, &q, &lines, &[], &[])?);
    }
    Ok(out)
}

// ---------------------------------------------------------------- Fig. 13

fn fig13(ctx: &Ctx) -> Result<Vec<String>, String> {
    let mut out = Vec::new();
    for (p, l) in [("a", 0.5), ("b", 1.0), ("c", 1.5)] {
        let cs = [(l, R4B, 0, 0.0), (l, R4C, 1, 0.0)];
        // one local envelope: it depends on the roughness through alpha^2/beta = 1/9 only, the same for both
        let lim = [Limit::Local(l, R4B), Limit::JkrEnvelope, Limit::MdmtEnvelope(l)];
        let t = format!("Fig. 13{p}: λ = {}, {{√2/3, 2}} and {{2√2/8, 9/8}}, with the local envelope (17)", short(l));
        out.push(la_panel(ctx, &t, R4B, (0.0, 6.0), &cs, &lim, &[], true, false)?);
    }
    Ok(out)
}

// ---------------------------------------------------------------- Fig. 14

const FIG14: [(f64, usize, f64); 3] = [(0.5, 0, 2.3), (1.0, 1, 1.0), (1.5, 3, -1.0)];

fn fig14_loci(ctx: &Ctx) -> Result<Vec<Locus>, String> {
    let mut v = Vec::new();
    for r in [R4B, R4C] {
        for (l, c, off) in FIG14 {
            let mut x = locus(ctx, l, r, c, 3.0, Shape::Up, &format!("{}, drawn at L̄ + C = {:.3}, Fig. 14c/d", roughness_name(r), ctx.load_at(l, r, 3.0)? + off))?;
            x.load += off;
            v.push(x);
        }
    }
    Ok(v)
}

fn fig14(ctx: &Ctx) -> Result<Vec<String>, String> {
    let loci = fig14_loci(ctx)?;
    let mut out = Vec::new();
    for (p, r, part) in [("a", R4B, &loci[..3]), ("b", R4C, &loci[3..])] {
        let cs: Vec<_> = FIG14.iter().map(|&(l, c, off)| (l, r, c, off)).collect();
        let t = format!("Fig. 14{p}: {{α, β}} = {}, λ = 1/2, 1, 3/2, 2.4 ≤ ā ≤ 3.6, loads shifted by C", roughness_name(r));
        out.push(la_panel(ctx, &t, r, (2.4, 3.6), &cs, &[], part, true, true)?);
    }
    let xmax = 5.0;
    for (p, r) in [("c", R4B), ("d", R4C)] {
        let mut lines = Vec::new();
        for (l, c, _) in &FIG14[..2] {
            lines.push(model_line(*l, r, 3.0, *c, "", xmax)?);
            lines.extend(solver_line(ctx, *l, r, false, 3.0, c + 6)?);
        }
        let t = format!("Fig. 14{p}: {{α, β}} = {}, λ = 1/2 and 1 at ā ≈ 3 (loading)", roughness_name(r));
        out.push(profile_figure(&t, xmax, &uq(), &lines, &rigid(r, xmax)?, &[])?);
    }
    Ok(out)
}

// ---------------------------------------------------------------- the list

/// Every figure.
pub fn all() -> Vec<Figure> {
    let fig4c_runs = |ls: &[f64]| each(ls, R4C);
    vec![
        Figure {
            id: "fig02",
            title: "Fig. 2: the limits, {α, β} = {√2/3, 2}",
            caption: "Normalised load against the intimate contact area for λ ~ 0 and ∞, {α, β} = {√2/3, 2}; the medium-dashed grey lines are the M-DMT (E.43a) and JKR (E.42a) responses, the long-dashed lines their envelopes (E.43d, E.42b).",
            paper: "The closed-form limits only: the JKR and M-DMT responses oscillating inside their envelopes.",
            ours: "The same limits and envelopes (M-DMT at λ = 1/10), and, for reference, the model at λ = 1/10 and 6.",
            differences: "The paper's λ ~ 0 limit needs a λ for E.43a; we take λ = 1/10, the smallest the paper uses. The model curves are an addition.",
            files: &["fig02"],
            curves: each(&[0.1, 6.0], R4B),
            sims: vec![],
            loci: no_loci,
            build: fig02,
        },
        Figure {
            id: "fig03",
            title: "Fig. 3: smooth cylinder, model and solver",
            caption: "Load against contact area for λ = 1/10, 1/4, 1/2, 1, 3 and 6 in smooth contact; the JKR (E.42) and DMT (E.44) limits at λ ~ ∞ and 1/10 in grey; semi-analytical solid, numerical (GFMD) dashed with square markers; (b) 0 < ā ≤ 2, without λ = 1 and 3.",
            paper: "The numerical and semi-analytical curves coincide except at jump-out of contact, visible for λ = 3 and 6 as a horizontal dashed line in (b).",
            ours: "The solver's loading and unloading states lie on the model curves. While loading, the contact snaps in at a finite ā; while unloading, the stiff machine follows the model past the load minimum and the contact jumps out at a finite ā (about 0.6 at λ = 6, panel b): the model's states below are unstable under displacement control and carry no simulated state.",
            differences: "Our solver runs displacement control both ways, so the jump-out shows as a gap between states rather than a horizontal line. The paper's abscissa range of (a) is not stated; we draw 0 < ā ≤ 6.",
            files: &["fig03a", "fig03b"],
            curves: each(&LAMBDAS3, SMOOTH),
            sims: each(&LAMBDAS3, SMOOTH),
            loci: no_loci,
            build: fig03,
        },
        Figure {
            id: "fig04",
            title: "Fig. 4: three roughnesses, model and solver",
            caption: "Load against contact area for λ = 1/10, 1/4, 1/2 (1) and 3 with (a) {2√2/8, 2}, (b) {√2/3, 2}, (c) {2√2/8, 9/8}; numerical loading dotted with diamonds, unloading dashed with squares; limits (E.42a, E.43a) and envelopes (E.42b, E.43d) in grey; λ = 6 added in (d).",
            paper: "Agreement that grows with λ, the Johnson parameter and β; instabilities (horizontal jumps) only at λ = 3 and 6 in (b)-(d); in (c) at λ = 1/4 to 1 a monotonic numerical response where the contact cavitates.",
            ours: "The same curves with the solver's states. Where the model is faded (invalid) the solver leaves it: its contact cavitates (hollow squares) and its load changes monotonically with the total contact. At λ = 3 and 6 the solver jumps between the model's turning points (the near-horizontal dotted and dashed lines), as the GFMD does.",
            differences: "Panel (d) is read as the (c) roughness with λ = 3 and 6, as the text says (\"λ = 6 in Fig. 4d\"); the caption's \"(a,d)\" is ambiguous.",
            files: &["fig04a", "fig04b", "fig04c", "fig04d"],
            curves: [each(&LAMBDAS4, R4A), each(&LAMBDAS4, R4B), fig4c_runs(&LAMBDAS4), fig4c_runs(&[6.0])].concat(),
            sims: [each(&LAMBDAS4, R4A), each(&LAMBDAS4, R4B), fig4c_runs(&LAMBDAS4), fig4c_runs(&[6.0])].concat(),
            loci: no_loci,
            build: fig04,
        },
        Figure {
            id: "fig05",
            title: "Fig. 5: instability and cavitation, {2√2/8, 9/8}",
            caption: "Load against contact area for λ = 1/4 and 6, 2 ≤ ā ≤ 4; the continuous contact areas that border the instability and the cavitation marked by Δ and ∇ symbols.",
            paper: "λ = 6 jumps at ā = 2.71 (loading) and 3.16 (unloading); λ = 1/4 cavitates between 2.59 and 3.47, where the numerical response is monotonic.",
            ours: "The model's jumps and cavitating stretch (marked), with the solver's states. At λ = 6 the solver jumps where the model turns (the near-horizontal dotted and dashed lines). At λ = 1/4 the simulated contact cavitates (hollow squares) across the stretch the model flags invalid, and its load rises monotonically with the total contact there, loading and unloading on one curve, as the paper's GFMD.",
            differences: "The loci are ours (listed above), within 0.02 of the paper's (docs/paper.md). The paper's stars for λ = 1/4 are circles here.",
            files: &["fig05"],
            curves: fig4c_runs(&[0.25, 6.0]),
            sims: fig4c_runs(&[0.25, 6.0]),
            loci: fig05_loci,
            build: fig05,
        },
        Figure {
            id: "fig06",
            title: "Fig. 6: profiles across the λ = 6 instabilities",
            caption: "Semi-analytical displacement and traction against |x̄|, {2√2/8, 9/8}, λ = 6, (a) loading at ā ≈ 2.71 and 3.40, (b) unloading at 3.16 and 2.47; the rigid punch in grey.",
            paper: "Just before a loading jump the traction inside the contact edge is at a minimum, before an unloading jump at a maximum.",
            ours: "The model's displacement (with the rigid profile) and traction at our computed jump ends.",
            differences: "The states are at our loci (2.726 → 3.388 loading, 3.146 → 2.463 unloading), not the paper's rounded ones. Model only, as in the paper.",
            files: &["fig06a", "fig06b"],
            curves: fig4c_runs(&[6.0]),
            sims: vec![],
            loci: no_loci,
            build: fig06,
        },
        Figure {
            id: "fig07",
            title: "Fig. 7: λ = 3/2 against λ = 6",
            caption: "Load against contact area, {2√2/8, 9/8}, λ = 3/2 and 6; JKR limit and envelopes in grey; the contact areas that border the instabilities as open squares.",
            paper: "λ = 6 follows JKR; λ = 3/2 departs from it, with a larger jump while loading (from 2.60) than while unloading (from 2.77).",
            ours: "The same two curves with the jump starts (squares) and the states of Fig. 8a (circle at 12/5, triangle at 79/25).",
            differences: "Window 1.5 ≤ ā ≤ 4.5 (the paper's is not stated). Model only, as in the paper.",
            files: &["fig07"],
            curves: fig4c_runs(&[1.5, 6.0]),
            sims: vec![],
            loci: fig07_loci,
            build: fig07,
        },
        Figure {
            id: "fig08",
            title: "Fig. 8: traction and gap, λ = 3/2 and 6",
            caption: "(a) Traction at ā = 12/5 and 79/25 for λ = 3/2 and 6; (b) traction and (c) gap against |x̄|/ā just before the instabilities (ā ≈ 2.60, 2.71, 2.77, 3.16).",
            paper: "Semi-analytical and numerical profiles; the adhesive strip widens as λ falls, and the gap gradient in the strip is larger while loading than while unloading.",
            ours: "(a) The model's traction at ā = 12/5 and 79/25. (b, c) The model's traction and gap at our turning points, with the solver's state of the same leg whose total contact half-width is nearest (dashed).",
            differences: "Our (b) and (c) are arranged by leg (b loading, c unloading), each with traction and gap; the paper's by quantity (b traction, c gap), each with loading on top and unloading below. The solver's state is the nearest of its leg, not refined to the turning point (labels give its ā).",
            files: &["fig08a", "fig08b", "fig08c"],
            curves: fig4c_runs(&[1.5, 6.0]),
            sims: fig4c_runs(&[1.5, 6.0]),
            loci: no_loci,
            build: fig08,
        },
        Figure {
            id: "fig09",
            title: "Fig. 9: λ = 1/4 at the ends of cavitation",
            caption: "Displacement and traction, {2√2/8, 9/8}, λ = 1/4, (a) loading at ā ≈ 2.59, (b) unloading at 3.47; numerical loading dotted with diamonds, unloading dashed with squares; semi-analytical solid.",
            paper: "Model and solver, loading and unloading, coincide at both states.",
            ours: "The model at our cavitating stretch's ends and the solver's loading and unloading states nearest to them.",
            differences: "The solver's states are the cycle's states whose total contact half-width is nearest the model's ā (labels give theirs). Our stretch ends are its outermost grid states with p̄ > 1 (2.60, 3.47; paper 2.59, 3.47), so the model states drawn are flagged invalid, barely.",
            files: &["fig09a", "fig09b"],
            curves: fig4c_runs(&[0.25]),
            sims: fig4c_runs(&[0.25]),
            loci: no_loci,
            build: fig09,
        },
        Figure {
            id: "fig10",
            title: "Fig. 10: λ = 1/4 inside the cavitating stretch",
            caption: "Displacement and traction, {2√2/8, 9/8}, λ = 1/4, at ā ≈ 3, loading and unloading; inset: the gap.",
            paper: "The semi-analytical traction exceeds the cohesive stress in the valleys and its gap is negative on the crests; the numerical contact is fragmented instead (cavitation).",
            ours: "The model (invalid) and the solver's loading and unloading states at ā ≈ 3, with the gap as a third panel.",
            differences: "The solver's state is the one whose total contact half-width is nearest 3; its outermost contact edge lies further out (label). The paper's inset is our third panel.",
            files: &["fig10"],
            curves: fig4c_runs(&[0.25]),
            sims: fig4c_runs(&[0.25]),
            loci: no_loci,
            build: fig10,
        },
        Figure {
            id: "fig11",
            title: "Fig. 11: cavitation without instability, {√2/3, 2}",
            caption: "Load against contact area, {√2/3, 2}, λ = 1/10 and 1/2; M-DMT limit (E.43a) at λ = 1/10 and the envelopes in grey.",
            paper: "λ = 1/2 stays continuous between ā = 2.96 and 3.63; λ = 1/10 cavitates there (negative model slope in places).",
            ours: "The model and the solver's states, with the states of Fig. 12 marked on both curves: λ = 1/2 stays continuous and on the model; λ = 1/10's simulated contact cavitates (hollow squares) between the marked states, where the model is invalid.",
            differences: "The solver (ours) stands in for GFMD. Its few states across the flat cavitating stretch of λ = 1/10 are the approach steps (200 per leg up to ā = 6): the load hardly changes there, and the total contact moves far in one step.",
            files: &["fig11"],
            curves: each(&[0.1, 0.5], R4B),
            sims: each(&[0.1, 0.5], R4B),
            loci: fig11_loci,
            build: fig11,
        },
        Figure {
            id: "fig12",
            title: "Fig. 12: profiles, λ = 1/10 and 1/2, {√2/3, 2}",
            caption: "Shifted displacement ū − C and traction against |x̄|, λ = 1/10 (dashed) and 1/2 (solid), at (a) ā ≈ 2.96, (b) 3.25, (c) 3.63; contact sizes and gap sizes in grey.",
            paper: "The strip of λ = 1/10 spans several valleys and crests and its contact cavitates at 3.25; λ = 1/2 stays continuous.",
            ours: "Both λ from the model (solid) and the solver's loading state of λ = 1/10 (dashed), which has cavitated at ā ≈ 3.25: the crest beyond the contact edge is in contact, the valley before it is not.",
            differences: "Line styles differ (the paper dashes λ = 1/10; we dash the solver). The paper's profiles are semi-analytical only. Each line is shifted by its own displacement at its (outermost) contact edge.",
            files: &["fig12a", "fig12b", "fig12c"],
            curves: each(&[0.1, 0.5], R4B),
            sims: each(&[0.1], R4B),
            loci: no_loci,
            build: fig12,
        },
        Figure {
            id: "fig13",
            title: "Fig. 13: the local envelope (17)",
            caption: "Load against contact area, {√2/3, 2} and {2√2/8, 9/8}, (a) λ = 1/2, (b) 1, (c) 3/2; the local envelope (17) medium-dashed, the JKR and M-DMT envelopes long-dashed.",
            paper: "The response stays within the local envelope and touches it near its turning points for λ ≥ 1; for λ ≤ 1 the envelope overestimates.",
            ours: "The model for both roughnesses and the local envelope (17), one line: it depends on the roughness through α²/β only, 1/9 for both (scaled Johnson parameter 3).",
            differences: "Model only, as the caption. The JKR envelope depends on α²/β only and is the same for both roughnesses; the M-DMT envelope drawn is that of {√2/3, 2}.",
            files: &["fig13a", "fig13b", "fig13c"],
            curves: [each(&[0.5, 1.0, 1.5], R4B), fig4c_runs(&[0.5, 1.0, 1.5])].concat(),
            sims: vec![],
            loci: no_loci,
            build: fig13,
        },
        Figure {
            id: "fig14",
            title: "Fig. 14: continuous, unstable and cavitating contact",
            caption: "(a, b) Load against contact area for λ = 1/2, 1, 3/2, (a) {√2/3, 2}, (b) {2√2/8, 9/8}, loads shifted by C = 2.3, 1, −1; (c, d) the numerical displacement and traction at ā ≈ 3 (Δ markers).",
            paper: "{√2/3, 2} stays continuous for λ = 1/2 and 1; {2√2/8, 9/8} cavitates at λ ≤ 1 in the valleys next to the outermost crests in contact; λ = 3/2 jumps both ways.",
            ours: "The model and the solver's states (shifted as in the paper) and, in (c, d), the model and the solver's loading state at ā ≈ 3 for λ = 1/2 and 1.",
            differences: "The caption of (c, d) says λ = 1/10 and 1/2 and (c) {2/√3, 2}; the text says λ = 1/2 and 1 and {√2/3, 2}, which we follow. We add the model's profiles to the solver's.",
            files: &["fig14a", "fig14b", "fig14c", "fig14d"],
            curves: [each(&[0.5, 1.0, 1.5], R4B), fig4c_runs(&[0.5, 1.0, 1.5])].concat(),
            sims: [each(&[0.5, 1.0, 1.5], R4B), fig4c_runs(&[0.5, 1.0, 1.5])].concat(),
            loci: fig14_loci,
            build: fig14,
        },
    ]
}
