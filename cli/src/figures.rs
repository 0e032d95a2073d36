//! `maugis figures`: the paper's Figs. 2 to 14 regenerated with the paper's
//! parameters, from the semi-analytical model (invalid stretches faded as
//! `maugis curve` draws them) and, where the paper overlays its GFMD results,
//! from the numerical solver (`maugis-solver`): its loading and unloading
//! states on the load-area panels, and its fields in the profiles where the
//! contact cavitates.
//!
//! Writes one SVG per panel (`fig02.svg`, `fig04a.svg`, ...) into `--out`
//! (atomically, [`crate::output`]) and, with `--write-doc FILE`, the page that
//! shows them (`docs/figures.md`: caption, what the paper shows, what ours
//! shows, the command, the differences), with the pictures linked as
//! `figures/<name>.svg`. The page does not depend on the solver or on
//! `--only`, so `--only fig02 --no-solver --write-doc` regenerates it whole
//! in a second (the test `figures_md_is_current`). Bad input exits with code 2
//! before any work, and nothing is written.

mod draw;
mod pages;
mod solver;

use std::collections::BTreeMap;
use std::fmt::Write as _;
use std::path::PathBuf;
use std::sync::atomic::{AtomicU64, Ordering};

use clap::Args;
use rayon::prelude::*;

use maugis::contact::curve::{CurveOptions, JumpDirection};
use maugis::contact::model::Params;
use maugis::contact::paper as paper_sets;
use maugis::contact::state_profile::sample_state;
use maugis_solver::run::SimulationSpec;

use crate::args::short;
use crate::curve::Run;
use crate::output::{check_file_target, check_out_dir, print_stdout, write_atomically, write_file_atomically, OutFile};
use crate::paper::{cavitating_stretch, jump_near};

use draw::{load_area_panel, profile_figure, Locus, PanelCurve, ProfileLine};
use solver::{profile_near, SolverRun};

/// Flags of `maugis figures`.
#[derive(Args, Debug)]
pub struct FiguresArgs {
    /// Output directory (written atomically).
    #[arg(long, value_name = "DIR", default_value = "maugis-figures")]
    pub out: PathBuf,
    /// Only these figures, comma-separated (`fig02,fig05`; default: all).
    #[arg(long, value_name = "LIST", value_delimiter = ',')]
    pub only: Vec<String>,
    /// Leave the solver out (model only; much faster).
    #[arg(long)]
    pub no_solver: bool,
    /// Solver grid cells, a power of two.
    #[arg(long, value_name = "N", default_value_t = DEFAULT_GRID)]
    pub grid: usize,
    /// Solver approach steps per leg.
    #[arg(long, value_name = "S", default_value_t = DEFAULT_STEPS)]
    pub steps: usize,
    /// Also write the page showing the figures (linked as figures/NAME.svg) to FILE.
    #[arg(long, value_name = "FILE")]
    pub write_doc: Option<PathBuf>,
}

/// Solver grid cells of the committed figures.
const DEFAULT_GRID: usize = 4096;
/// Solver approach steps per leg of the committed figures.
const DEFAULT_STEPS: usize = 200;

/// The roughness of Figs. 4a (and 4d's text): `{2 sqrt(2)/8, 2}`.
const R4A: (f64, f64) = (paper_sets::FIG_4A.alpha, paper_sets::FIG_4A.beta);
/// Figs. 2, 4b, 11-14: `{sqrt(2)/3, 2}`.
const R4B: (f64, f64) = (paper_sets::FIG_4B.alpha, paper_sets::FIG_4B.beta);
/// Figs. 4c, 5-10, 13-14: `{2 sqrt(2)/8, 9/8}`.
const R4C: (f64, f64) = (paper_sets::FIG_4C.alpha, paper_sets::FIG_4C.beta);
/// Fig. 3: the smooth cylinder (beta plays no role with alpha = 0).
const SMOOTH: (f64, f64) = (paper_sets::SMOOTH.alpha, paper_sets::SMOOTH.beta);

/// The roughness as the paper writes it.
fn roughness_name(r: (f64, f64)) -> &'static str {
    paper_sets::ROUGHNESSES.iter().find(|n| n.pair() == r).map_or("{α, β}", |n| n.label)
}

/// Marker shapes of the marked loci and the solver states.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Shape {
    Up,
    Down,
    Square,
    Diamond,
    Circle,
}

/// A limit line of a load-area panel.
#[derive(Clone, Copy, Debug)]
pub enum Limit {
    /// E.42a.
    Jkr,
    /// E.42b.
    JkrEnvelope,
    /// E.43a at lambda.
    Mdmt(f64),
    /// E.43d at lambda.
    MdmtEnvelope(f64),
    /// E.44 at lambda.
    SmoothMdmt(f64),
    /// Eq. 17 at lambda, for roughness `(alpha, beta)`.
    Local(f64, (f64, f64)),
}

/// Key of a parameter set.
type Key = (u64, u64, u64);

fn key(lambda: f64, r: (f64, f64)) -> Key {
    (lambda.to_bits(), r.0.to_bits(), r.1.to_bits())
}

/// Everything the figures draw from: model curves and solver runs.
pub struct Ctx {
    curves: BTreeMap<Key, Run>,
    sims: BTreeMap<Key, SolverRun>,
}

impl Ctx {
    fn curve(&self, lambda: f64, r: (f64, f64)) -> Result<&Run, String> {
        self.curves.get(&key(lambda, r)).ok_or_else(|| format!("internal error: no curve at lambda = {lambda}"))
    }

    fn sim(&self, lambda: f64, r: (f64, f64)) -> Option<&SolverRun> {
        self.sims.get(&key(lambda, r))
    }

    /// The model load at `abar` on the grid curve (nearest grid state).
    fn load_at(&self, lambda: f64, r: (f64, f64), abar: f64) -> Result<f64, String> {
        let c = &self.curve(lambda, r)?.curve;
        maugis::contact::curve::load_at(c.params, abar).map_err(|e| format!("lambda = {}, abar = {abar}: {e}", short(lambda)))
    }
}

/// A figure: its panels and the text of its section of the page.
pub struct Figure {
    /// `fig05`.
    pub id: &'static str,
    /// Section title.
    pub title: &'static str,
    /// The paper's caption, abridged.
    pub caption: &'static str,
    /// What the paper shows.
    pub paper: &'static str,
    /// What ours shows.
    pub ours: &'static str,
    /// Differences from the paper.
    pub differences: &'static str,
    /// The panels' file stems (`fig04a`, ...).
    pub files: &'static [&'static str],
    /// Model curves it needs: `(lambda, roughness)`.
    pub curves: Vec<(f64, (f64, f64))>,
    /// Solver runs it needs.
    pub sims: Vec<(f64, (f64, f64))>,
    /// Marked loci, also listed on the page.
    pub loci: fn(&Ctx) -> Result<Vec<Locus>, String>,
    /// Builds the panels (SVG text, in the order of `files`).
    pub build: fn(&Ctx) -> Result<Vec<String>, String>,
}

fn no_loci(_: &Ctx) -> Result<Vec<Locus>, String> {
    Ok(Vec::new())
}

/// A load-area panel of the curves `(lambda, roughness, colour, offset)`,
/// with the solver's states where `solver` and they were computed.
#[allow(clippy::too_many_arguments)]
fn la_panel(ctx: &Ctx, title: &str, r: (f64, f64), window: (f64, f64), curves: &[(f64, (f64, f64), usize, f64)], limits: &[Limit], loci: &[Locus], labels: bool, solver: bool) -> Result<String, String> {
    let mut pcs = Vec::new();
    for &(lambda, rr, colour, offset) in curves {
        let run = ctx.curve(lambda, rr)?;
        let label = labels.then(|| {
            let shift = if offset != 0.0 { format!(", L̄ shifted by C = {offset:+}") } else { String::new() };
            format!("λ = {}, {{α, β}} = {}{shift}", short(lambda), roughness_name(rr))
        });
        pcs.push(PanelCurve { run, colour, offset, label, solver: ctx.sim(lambda, rr).filter(|_| solver).map(|s| s.legs.as_slice()) });
    }
    load_area_panel(title, r.0, r.1, window, None, limits, &pcs, loci)
}

/// Model lines `(label, colour, profile)` of states `(lambda, abar)`.
fn model_line(lambda: f64, r: (f64, f64), abar: f64, colour: usize, what: &str, xmax: f64) -> Result<ProfileLine, String> {
    let p = Params::new(lambda, r.0, r.1).map_err(|e| e.to_string())?;
    let s = sample_state(p, abar, Some(xmax), 700).map_err(|e| format!("lambda = {}, abar = {abar}: {e}", short(lambda)))?;
    let valid = if s.validity.valid { "" } else { ", invalid" };
    Ok(ProfileLine {
        label: format!("model, λ = {}, ā = {:.2}{what}{valid}", short(lambda), abar),
        colour,
        solver: false,
        abar,
        c: Some(s.strip_end()),
        samples: s.samples.iter().map(|q| [q.xbar, q.pbar, q.ubar, q.gbar]).collect(),
    })
}

/// The solver's state nearest `abar` on a leg, as a profile line (none without the solver).
fn solver_line(ctx: &Ctx, lambda: f64, r: (f64, f64), unloading: bool, abar: f64, colour: usize) -> Result<Option<ProfileLine>, String> {
    let Some(run) = ctx.sim(lambda, r) else { return Ok(None) };
    let p = profile_near(run, unloading, abar)?;
    let cav = if p.intervals > 1 { format!(" ({} contact intervals, outer edge {:.2})", p.intervals, p.outer) } else { String::new() };
    let leg = if unloading { "unloading" } else { "loading" };
    Ok(Some(ProfileLine::of_solver(format!("solver, λ = {}, {leg}, ā = {:.2}{cav}", short(lambda), p.abar), colour, &p)))
}

/// The rigid profile over `[0, xmax]`.
fn rigid(r: (f64, f64), xmax: f64) -> Result<Vec<(f64, f64)>, String> {
    (0..=800)
        .map(|i| {
            let x = xmax * f64::from(i) / 800.0;
            maugis::contact::displacement::profile_depth(1.0, r.0, r.1, x).map(|h| (x, h)).map_err(|e| e.to_string())
        })
        .collect()
}

/// The loading and unloading jumps of `lambda` (Fig. 4c roughness) near the paper's loci.
fn jumps(ctx: &Ctx, lambda: f64, near: (f64, f64)) -> Result<[(f64, f64); 2], String> {
    let c = &ctx.curve(lambda, R4C)?.curve;
    let up = jump_near(c, JumpDirection::Loading, near.0)?;
    let down = jump_near(c, JumpDirection::Unloading, near.1)?;
    Ok([(up.from.abar, up.to.abar), (down.from.abar, down.to.abar)])
}

/// Every figure, in the paper's order.
pub fn figures() -> Vec<Figure> {
    pages::all()
}

/// Runs `maugis figures`.
pub fn run(a: FiguresArgs) -> Result<(), String> {
    let all = figures();
    for id in &a.only {
        if !all.iter().any(|f| f.id == id) {
            let ids: Vec<&str> = all.iter().map(|f| f.id).collect();
            return Err(format!("--only {id}: no such figure (one of {})", ids.join(", ")));
        }
    }
    if !a.grid.is_power_of_two() || !(256..=1 << 20).contains(&a.grid) {
        return Err(format!("--grid must be a power of two in [256, 1048576] (got {})", a.grid));
    }
    if !(10..=100_000).contains(&a.steps) {
        return Err(format!("--steps must lie in [10, 100000] (got {})", a.steps));
    }
    check_out_dir(&a.out)?;
    if let Some(path) = &a.write_doc {
        check_file_target("--write-doc", path)?;
    }
    let chosen: Vec<&Figure> = all.iter().filter(|f| a.only.is_empty() || a.only.iter().any(|o| o == f.id)).collect();

    // Model curves of every figure (the page lists their loci), solver runs of the chosen ones.
    let mut want: BTreeMap<Key, (f64, (f64, f64))> = BTreeMap::new();
    for f in &all {
        for &(l, r) in &f.curves {
            want.insert(key(l, r), (l, r));
        }
    }
    let opts = CurveOptions::default();
    let curves = want
        .into_par_iter()
        .map(|(k, (lambda, r))| {
            let params = Params::new(lambda, r.0, r.1).map_err(|e| e.to_string())?;
            let curve = maugis::contact::curve::load_area_curve(params, opts).map_err(|e| format!("lambda = {}: {e}", short(lambda)))?;
            Ok((k, Run { lambda, curve }))
        })
        .collect::<Result<BTreeMap<_, _>, String>>()?;
    let mut sims_wanted: BTreeMap<Key, (f64, (f64, f64))> = BTreeMap::new();
    if !a.no_solver {
        for f in &chosen {
            for &(l, r) in &f.sims {
                sims_wanted.insert(key(l, r), (l, r));
            }
        }
    }
    let pb = crate::curve::progress((sims_wanted.len() * 2 * a.steps) as u64, "solver cycles");
    let done = AtomicU64::new(0);
    let tick = || {
        pb.set_position(done.fetch_add(1, Ordering::Relaxed) + 1);
    };
    let sims = sims_wanted
        .into_par_iter()
        .map(|(k, (lambda, r))| {
            let spec = SimulationSpec { lambda, alpha: r.0, beta: r.1, amax: opts.amax, cells: a.grid, steps_per_leg: a.steps };
            Ok((k, solver::run(spec, &tick)?))
        })
        .collect::<Result<BTreeMap<_, _>, String>>()?;
    pb.finish_and_clear();
    let ctx = Ctx { curves, sims };

    let pb = crate::curve::progress(chosen.len() as u64, "drawing");
    let built = chosen
        .par_iter()
        .map(|f| {
            let svgs = (f.build)(&ctx).map_err(|e| format!("{}: {e}", f.id))?;
            pb.inc(1);
            Ok(f.files.iter().zip(svgs).map(|(n, s)| OutFile::text(format!("{n}.svg"), s)).collect::<Vec<_>>())
        })
        .collect::<Result<Vec<_>, String>>()?;
    pb.finish_and_clear();
    let files: Vec<OutFile> = built.into_iter().flatten().collect();
    let page = match &a.write_doc {
        Some(_) => Some(page(&all, &ctx)?),
        None => None,
    };
    let written = write_atomically(&a.out, &files)?;
    let mut text = format!("maugis figures: {} figure(s), {} file(s) in {}\n", chosen.len(), written.len(), a.out.display());
    if let (Some(path), Some(page)) = (&a.write_doc, page) {
        write_file_atomically("--write-doc", path, &page)?;
        let _ = writeln!(text, "wrote {}", path.display());
    }
    print_stdout(&text)
}

/// The page (docs/figures.md).
fn page(all: &[Figure], ctx: &Ctx) -> Result<String, String> {
    let mut s = String::new();
    let _ = writeln!(s, "# The paper's figures, regenerated\n");
    let _ = writeln!(s, "Generated by `maugis figures --out docs/figures --write-doc docs/figures.md`; do not edit");
    let _ = writeln!(s, "by hand (the test `figures_md_is_current` regenerates this page). One figure alone:");
    let _ = writeln!(s, "`maugis figures --only fig05 --out DIR` (add `--no-solver` for the model only).\n");
    let _ = writeln!(s, "{}\n", pages::INTRO);
    for f in all {
        let _ = writeln!(s, "## {}\n", f.title);
        for n in f.files {
            let _ = writeln!(s, "![{n}](figures/{n}.svg)\n");
        }
        let _ = writeln!(s, "**The paper's caption** (abridged). {}\n", f.caption);
        let _ = writeln!(s, "**What the paper shows.** {}\n", f.paper);
        let _ = writeln!(s, "**What ours shows.** {}\n", f.ours);
        let loci = (f.loci)(ctx)?;
        if !loci.is_empty() {
            let _ = writeln!(s, "Marked loci (model):\n");
            for l in &loci {
                let _ = writeln!(s, "- {}", l.label);
            }
            let _ = writeln!(s);
        }
        let solver = if f.sims.is_empty() { String::new() } else { format!(" (solver: {DEFAULT_GRID} cells, {DEFAULT_STEPS} approach steps per leg)") };
        let _ = writeln!(s, "**Command.** `maugis figures --only {} --out DIR`{solver}\n", f.id);
        let _ = writeln!(s, "**Differences.** {}\n", f.differences);
    }
    Ok(s)
}
