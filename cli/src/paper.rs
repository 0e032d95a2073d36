//! `maugis paper`: every number the seed paper quotes, recomputed, next to the
//! paper's value with the difference; `--write docs/paper.md` regenerates the
//! committed page (test `paper_md_is_current` in `cli/tests/cli_curve.rs`).
//!
//! The paper's values are quoted from its text (a text extraction of the seed
//! paper, which is not in this repository) with the section or figure they come from. Ours come
//! from the library at the default grid (600 states on `abar in (0, 6]`),
//! turning points and jump targets refined, under load control.

use std::fmt::Write as _;
use std::path::PathBuf;

use clap::Args;

use maugis::contact::curve::{load_area_curve, state, Curve, CurveOptions, JumpDirection};
use maugis::contact::model::Params;
use maugis::contact::paths::Jump;
use maugis::contact::summary::invalid_stretches;

use crate::args::{FIG4C_ALPHA, FIG4C_BETA};
use crate::output::print_stdout;

/// Flags of `maugis paper`.
#[derive(Args, Debug)]
pub struct PaperArgs {
    /// Write the Markdown page to this file (atomically) instead of stdout.
    #[arg(long, value_name = "FILE")]
    pub write: Option<PathBuf>,
}

/// The paper's full reference (authors from the seed's CRediT statement, title
/// and year from the institutional record).
pub const CITATION: &str = "J. S. Van Dokkum, F. Pérez-Ràfols and L. Nicola, \
\"Instabilities and cavitation in cylindrical wavy line contact: A Maugis analysis\", 2024. \
Institutional record: <https://research.unipd.it/handle/11577/3549746>.";

/// Fig. 11-14 roughness `{alpha, beta} = {sqrt(2)/3, 2}`.
pub(crate) const FIG11_ALPHA: f64 = maugis::contact::paper::FIG_4B.alpha;
pub(crate) const FIG11_BETA: f64 = maugis::contact::paper::FIG_4B.beta;

/// One compared number.
struct Row {
    quantity: String,
    source: &'static str,
    paper: &'static str,
    ours: f64,
}

fn curve(lambda: f64, alpha: f64, beta: f64) -> Result<Curve, String> {
    let p = Params::new(lambda, alpha, beta).map_err(|e| e.to_string())?;
    load_area_curve(p, CurveOptions::default()).map_err(|e| format!("lambda = {lambda}: {e}"))
}

/// The jump of `direction` whose start is nearest to `near`.
pub(crate) fn jump_near(c: &Curve, direction: JumpDirection, near: f64) -> Result<Jump, String> {
    c.jumps
        .iter()
        .filter(|j| j.direction == direction)
        .min_by(|a, b| (a.from.abar - near).abs().total_cmp(&(b.from.abar - near).abs()))
        .copied()
        .ok_or_else(|| format!("lambda = {}: no {direction:?} jump", c.params.lambda()))
}

/// The invalid stretch (with cavitation) that contains `abar`: `(from, to)`.
pub(crate) fn cavitating_stretch(c: &Curve, abar: f64) -> Result<(f64, f64), String> {
    invalid_stretches(&c.points)
        .iter()
        .find(|s| s.cavitation && s.from_abar <= abar && abar <= s.to_abar)
        .map(|s| (s.from_abar, s.to_abar))
        .ok_or_else(|| format!("lambda = {}: no cavitating stretch at abar = {abar}", c.params.lambda()))
}

/// Every compared number.
fn rows() -> Result<(Vec<Row>, Vec<Curve>), String> {
    let mut rows = Vec::new();
    let mut push = |quantity: &str, source: &'static str, paper: &'static str, ours: f64| rows.push(Row { quantity: quantity.into(), source, paper, ours });

    let l6 = curve(6.0, FIG4C_ALPHA, FIG4C_BETA)?;
    let load6 = jump_near(&l6, JumpDirection::Loading, 2.71)?;
    let unload6 = jump_near(&l6, JumpDirection::Unloading, 3.16)?;
    push("lambda = 6: loading instability, abar", "Sec. 5.1, Figs. 5, 6a", "2.71", load6.from.abar);
    push("lambda = 6: loading jump target, abar", "Fig. 6 caption", "3.40", load6.to.abar);
    push("lambda = 6: loading jump size, Delta abar", "Sec. 5.1 (Fig. 4d)", "0.69", load6.to.abar - load6.from.abar);
    push("lambda = 6: unloading instability, abar", "Sec. 5.1, Figs. 5, 6b", "3.16", unload6.from.abar);
    push("lambda = 6: unloading jump target, abar", "Fig. 6 caption", "2.47", unload6.to.abar);
    push("lambda = 6: unloading jump target, abar", "Sec. 5.2 (text)", "2.45", unload6.to.abar);

    let l32 = curve(1.5, FIG4C_ALPHA, FIG4C_BETA)?;
    let load32 = jump_near(&l32, JumpDirection::Loading, 2.60)?;
    let unload32 = jump_near(&l32, JumpDirection::Unloading, 2.77)?;
    push("lambda = 3/2: loading instability, abar", "Sec. 5.2, Figs. 7, 8", "2.60", load32.from.abar);
    push("lambda = 3/2: unloading instability, abar", "Sec. 5.2, Figs. 7, 8", "2.77", unload32.from.abar);
    push("lambda = 3/2: unloading jump target, abar", "Sec. 5.2 (text)", "2.42", unload32.to.abar);

    let l14 = curve(0.25, FIG4C_ALPHA, FIG4C_BETA)?;
    let (c0, c1) = cavitating_stretch(&l14, 3.0)?;
    push("lambda = 1/4: cavitation starts, abar", "Sec. 5.2, Figs. 5, 9a", "2.59", c0);
    push("lambda = 1/4: cavitation ends, abar", "Sec. 5.2, Figs. 5, 9b", "3.47", c1);

    let l10 = curve(0.1, FIG11_ALPHA, FIG11_BETA)?;
    let (d0, d1) = cavitating_stretch(&l10, 3.3)?;
    push("{sqrt(2)/3, 2}, lambda = 1/10: cavitation starts, abar", "Sec. 5.3, Figs. 11, 12a", "2.96", d0);
    push("{sqrt(2)/3, 2}, lambda = 1/10: cavitation ends, abar", "Sec. 5.3, Figs. 11, 12c", "3.63", d1);
    let l12 = curve(0.5, FIG11_ALPHA, FIG11_BETA)?;
    let invalid = l12.points.iter().filter(|p| (2.9..=3.9).contains(&p.abar) && !p.validity.valid).count();
    push("{sqrt(2)/3, 2}, lambda = 1/2: invalid states in 29/10 <= abar <= 39/10", "Sec. 5.3, Fig. 11 (\"continuous\")", "0", invalid as f64);
    for (lambda, paper) in [(0.1, "6.30"), (0.5, "4.35")] {
        let p = Params::new(lambda, FIG11_ALPHA, FIG11_BETA).map_err(|e| e.to_string())?;
        let s = state(p, 3.63).map_err(|e| e.to_string())?;
        let q = if lambda == 0.1 { "{sqrt(2)/3, 2}, lambda = 1/10: contact size m abar at abar = 3.63" } else { "{sqrt(2)/3, 2}, lambda = 1/2: contact size m abar at abar = 3.63" };
        push(q, "Fig. 12c (vertical lines)", paper, s.m * s.abar);
    }
    for (lambda, paper) in [(0.1, "10"), (0.5, "2")] {
        let q = if lambda == 0.1 { "lambda = 1/10: interaction range deltabar = 1/lambda" } else { "lambda = 1/2: interaction range deltabar = 1/lambda" };
        push(q, "Fig. 12 (horizontal lines)", paper, 1.0 / lambda);
    }
    Ok((rows, vec![l14, l32, l6]))
}

/// The page.
fn page() -> Result<String, String> {
    let (rows, curves) = rows()?;
    let mut s = String::new();
    let _ = writeln!(s, "# The paper's numbers, recomputed\n");
    let _ = writeln!(s, "Generated by `maugis paper --write docs/paper.md`; do not edit by hand. The test");
    let _ = writeln!(s, "`paper_md_is_current` regenerates it and compares every number.\n");
    let _ = writeln!(s, "## The paper\n");
    let _ = writeln!(s, "{CITATION}\n");
    let _ = writeln!(s, "Journal, volume, article number and DOI: not found in any source searched (the");
    let _ = writeln!(s, "institutional record above, web pages and documentation indexes), so none is given here.\n");
    let _ = writeln!(s, "## Side by side\n");
    let _ = writeln!(s, "Roughness `{{alpha, beta}} = {{2 sqrt(2)/8, 9/8}}` (Fig. 4c) unless the row says");
    let _ = writeln!(s, "`{{sqrt(2)/3, 2}}` (Figs. 11-14). Ours: 600 grid states on `abar in (0, 6]`, turning");
    let _ = writeln!(s, "points and jump targets refined, load control; a cavitating stretch is the run of grid");
    let _ = writeln!(s, "states flagged invalid with `pbar > 1` (so its ends are grid points, 0.01 apart).\n");
    let _ = writeln!(s, "| quantity | where in the paper | paper | maugis | maugis - paper |");
    let _ = writeln!(s, "|---|---|---|---|---|");
    for r in &rows {
        let paper: f64 = r.paper.parse().map_err(|_| format!("bad paper value {}", r.paper))?;
        let _ = writeln!(s, "| {} | {} | {} | {:.4} | {:+.4} |", r.quantity, r.source, r.paper, r.ours, r.ours - paper);
    }
    let worst = rows.iter().filter_map(|r| r.paper.parse::<f64>().ok().map(|p| (r.ours - p).abs())).fold(0.0, f64::max);
    let _ = writeln!(s, "\nLargest difference: {worst:.4}. The paper reads its loci off figures to two decimals.\n");
    let _ = writeln!(s, "## Not quoted by the paper: pull-off and dissipation (Fig. 4c roughness)\n");
    let _ = writeln!(s, "Pull-off is the end of load-controlled unloading (refined); the valid pull-off is the most");
    let _ = writeln!(s, "tensile valid state unloading visits. W is the energy of the closed cycle (docs/model.md).\n");
    let _ = writeln!(s, "| lambda | pull-off abar | pull-off Lbar | valid | valid pull-off Lbar | W (load control) | W_d (x_d = 100) |");
    let _ = writeln!(s, "|---|---|---|---|---|---|---|");
    for c in &curves {
        let (pa, pl, pv) = c.pull_off.map(|p| (format!("{:.4}", p.abar), format!("{:.4}", p.load), p.validity.valid.to_string())).unwrap_or(("-".into(), "-".into(), "-".into()));
        let vp = c.valid_pull_off.map(|p| format!("{:.4}", p.load)).unwrap_or_else(|| "-".into());
        let _ = writeln!(
            s,
            "| {} | {pa} | {pl} | {pv} | {vp} | {:.4} | {:.4} |",
            c.params.lambda(),
            c.load_control.dissipation.total,
            c.displacement_control.dissipation.total
        );
    }
    Ok(s)
}

/// Runs `maugis paper`.
pub fn run(a: PaperArgs) -> Result<(), String> {
    if let Some(path) = &a.write {
        crate::output::check_file_target("--write", path)?;
    }
    let text = page()?;
    match &a.write {
        None => print_stdout(&text),
        Some(path) => {
            crate::output::write_file_atomically("--write", path, &text)?;
            print_stdout(&format!("wrote {}\n", path.display()))
        }
    }
}
