//! The `maugis` command line.
//!
//! * `maugis eval`: JSON Lines calculator over the special functions (see `eval.rs`).
//! * `maugis integrate`: a certified integral of an expression in x (`integrate.rs`).
//! * `maugis demo`: evaluates a few representative requests through `eval` and
//!   prints them.
//! * `maugis curve`: the main job, load-area responses for several Maugis
//!   parameters with turning points, jumps, pull-off, validity, CSV/JSON/SVG
//!   output (see `curve.rs`).
//! * `maugis profile`: traction, displacement and gap of one state (`profile.rs`).
//! * `maugis limits`: the Appendix E limits and the Eq. 17 envelope (`limits.rs`).
//! * `maugis sweep` / `maugis merge`: regime maps, sharded for array jobs (`sweep.rs`).
//! * `maugis paper`: the paper's quoted numbers next to ours, docs/paper.md (`paper.rs`).
//! * `maugis figures`: the paper's Figs. 2-14 regenerated, docs/figures.md (`figures.rs`).
//! * `maugis multiscale`: the multi-scale roughness studies, docs/multiscale.md (`multiscale.rs`).
//!
//! Usage errors and runtime errors exit with code 2 and a one-line message on
//! stderr (`maugis: ...`); no output file is written then.

mod args;
mod curve;
mod eval;
mod figures;
mod integrate;
mod limits;
mod multiscale;
mod output;
mod paper;
mod plot;
mod profile;
mod simulate;
mod sweep;

/// The fuzz targets' reproducible inputs (`eval::fuzz`), shared with the library's
/// and the solver's targets.
#[cfg(test)]
#[path = "../../tests/it/common/fuzz_inputs.rs"]
mod fuzz_inputs;

use clap::{Parser, Subcommand};

#[derive(Parser)]
#[command(name = "maugis", version, about = "Certified special functions for the wavy Maugis line contact")]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// JSON Lines calculator: one request per stdin line, one response per stdout line.
    Eval,
    /// Certified integral of an expression in x over [A, B] (B may be inf with a declared
    /// decay), with optional endpoint weights; prints the ball as mid and rad.
    Integrate(integrate::IntegrateArgs),
    /// Show a few certified evaluations (the Eq. 12 building blocks at the model's arguments).
    Demo,
    /// Load-area curves Lbar(abar) for several lambda (default: the paper's Fig. 4c) with
    /// turning points, jumps, pull-off and validity; writes CSV, summary.json and load-area.svg.
    Curve(curve::CurveArgs),
    /// Traction, displacement and gap profiles of one state at contact half-width abar.
    Profile(profile::ProfileArgs),
    /// The Appendix E limits (JKR, M-DMT, smooth M-DMT) and the Eq. 17 local envelope.
    Limits(limits::LimitsArgs),
    /// Regime map over lambda (log) and alpha, beta or the Johnson parameter: instabilities,
    /// dissipation, pull-off, valid fraction, regime; CSV, JSON, SVG. Shardable (--shard s/n).
    Sweep(sweep::SweepArgs),
    /// Numerical Dugdale-Maugis simulation (maugis-solver): one loading-unloading cycle under
    /// displacement control over the semi-analytical curve; CSV and SVG, or JSON.
    Simulate(simulate::SimulateArgs),
    /// Merge the output directories of `maugis sweep --shard s/n` runs into the whole sweep.
    Merge(sweep::MergeArgs),
    /// The paper's Figs. 2-14 regenerated (model, solver overlays, profiles) as SVGs; --write-doc for docs/figures.md.
    Figures(figures::FiguresArgs),
    /// Every number the seed paper quotes, recomputed, next to the paper's value (docs/paper.md).
    Paper(paper::PaperArgs),
    /// Multi-scale roughness studies (docs/multiscale.md): `envelope`, the envelope of the
    /// load-area response of Weierstrass profiles against the model.
    Multiscale(multiscale::MultiscaleArgs),
}

/// Requests of the demo: the Eq. 12 factors at abar = 6, beta = 9/8, and the edge x = a.
const DEMO_REQUESTS: &[&str] = &[
    r#"{"id":"J_5(2.5), 200 bits","fn":"bessel_j","n":5,"x":"2.5","prec":200}"#,
    r#"{"id":"1F2(1/2; 1, 3/2; -300), 128 bits","fn":"hyp1f2","a":0.5,"b1":1,"b2":1.5,"z":-300,"prec":128}"#,
    r#"{"id":"1F2(1/2; 1001, 1001.5; -300), 128 bits","fn":"hyp1f2","a":0.5,"b1":1001,"b2":1001.5,"z":-300,"prec":128}"#,
    r#"{"id":"2F1(1, 1000.5; 1002; 1), 128 bits","fn":"hyp2f1","a":1,"b":1000.5,"c":1002,"z":1,"prec":128}"#,
    r#"{"id":"G(1000, 1 - 1e-12), 128 bits","fn":"meijer_g_k","k":1000,"y":"0.999999999999","prec":128}"#,
    r#"{"id":"G(3, 1) (singular point), f64","fn":"meijer_g_k","k":3,"y":1}"#,
    r#"{"id":"bad request","fn":"meijer_g_k","k":3,"y":1.5}"#,
];

fn main() {
    // `maugis eval` takes no flags: it starts without building the parser of every
    // subcommand's flags (clap's `Cli::command`, about 380 000 instructions and a few
    // dozen page faults, more than a small integral's request; docs/quadrature.md,
    // "`eval`'s own cost per request"). Anything else after `eval` goes through clap as before.
    let mut args = std::env::args_os().skip(1);
    if args.next().is_some_and(|a| a == "eval") && args.next().is_none() {
        std::process::exit(eval::run());
    }
    let cli = match Cli::try_parse() {
        Ok(c) => c,
        Err(e) => {
            if !e.use_stderr() {
                // --help / --version: clap's own output on stdout
                let _ = e.print();
                std::process::exit(0);
            }
            eprintln!("maugis: {}", one_line(&e));
            std::process::exit(2);
        }
    };
    let code = match cli.command {
        Command::Eval => eval::run(),
        Command::Demo => {
            // Write through a handle so a closed pipe (`maugis demo | head`) ends quietly.
            use std::io::Write;
            let mut out = std::io::stdout().lock();
            let mut text = String::from("maugis demo: certified evaluations through the `maugis eval` protocol\n\n");
            for req in DEMO_REQUESTS {
                text.push_str(&format!("> {req}\n< {}\n\n", eval::handle_line(req)));
            }
            text.push_str("Try: echo '{\"id\":1,\"fn\":\"bessel_j\",\"n\":5,\"x\":\"2.5\",\"prec\":200}' | maugis eval\n");
            let _ = out.write_all(text.as_bytes());
            0
        }
        Command::Integrate(a) => report(guarded(move || integrate::run(a))),
        Command::Curve(a) => report(guarded(move || curve::run(a))),
        Command::Profile(a) => report(guarded(move || profile::run(a))),
        Command::Limits(a) => report(guarded(move || limits::run(a))),
        Command::Sweep(a) => report(guarded(move || sweep::run(a))),
        Command::Simulate(a) => report(guarded(move || simulate::run(a))),
        Command::Merge(a) => report(guarded(move || sweep::run_merge(a))),
        Command::Paper(a) => report(guarded(move || paper::run(a))),
        Command::Multiscale(a) => report(guarded(move || multiscale::run(a))),
        Command::Figures(a) => report(guarded(move || figures::run(a))),
    };
    std::process::exit(code);
}

/// Runs `f`, turning a panic (a bug, in the library or here) into an error
/// reported on one line instead of a backtrace. Only the first panic of the run
/// is reported (rayon may panic on several threads).
fn guarded<F: FnOnce() -> Result<(), String> + std::panic::UnwindSafe>(f: F) -> Result<(), String> {
    use std::sync::atomic::{AtomicBool, Ordering};
    use std::sync::Mutex;
    static FIRST: Mutex<Option<String>> = Mutex::new(None);
    static SEEN: AtomicBool = AtomicBool::new(false);
    std::panic::set_hook(Box::new(|info| {
        if SEEN.swap(true, Ordering::SeqCst) {
            return;
        }
        let payload = info.payload();
        let msg = payload
            .downcast_ref::<&str>()
            .map(|s| s.to_string())
            .or_else(|| payload.downcast_ref::<String>().cloned())
            .unwrap_or_else(|| "unknown panic".into());
        let at = info.location().map(|l| format!(" at {}:{}", l.file(), l.line())).unwrap_or_default();
        if let Ok(mut first) = FIRST.lock() {
            *first = Some(format!("internal error (please report): {}{at}", msg.replace('\n', " ")));
        }
    }));
    let result = std::panic::catch_unwind(f);
    let _ = std::panic::take_hook();
    match result {
        Ok(r) => r,
        Err(_) => Err(FIRST
            .lock()
            .ok()
            .and_then(|mut m| m.take())
            .unwrap_or_else(|| "internal error (please report): panic".into())),
    }
}

/// Exit code of a subcommand: 0, or 2 after a one-line message on stderr.
fn report(r: Result<(), String>) -> i32 {
    match r {
        Ok(()) => 0,
        Err(msg) => {
            eprintln!("maugis: {}", msg.lines().next().unwrap_or("error"));
            2
        }
    }
}

/// A clap error as one line: clap's message up to its usage block, joined,
/// without the `error: ` prefix and tips, plus a pointer to `--help`.
fn one_line(e: &clap::Error) -> String {
    use clap::error::ErrorKind;
    if e.kind() == ErrorKind::DisplayHelpOnMissingArgumentOrSubcommand || e.kind() == ErrorKind::MissingSubcommand {
        return "a subcommand is required (eval, integrate, demo, curve, profile, limits, sweep, merge, simulate, paper, figures); try 'maugis --help'".into();
    }
    let text = e.render().to_string();
    let parts: Vec<&str> = text
        .lines()
        .map(str::trim)
        .take_while(|l| !l.starts_with("Usage:") && !l.starts_with("For more information"))
        .filter(|l| !l.is_empty() && !l.starts_with("tip:"))
        .collect();
    let joined = parts.join(" ");
    let msg = joined.strip_prefix("error: ").unwrap_or(&joined);
    let msg = if msg.is_empty() { "invalid command line" } else { msg };
    format!("{msg} (try --help)")
}
