//! `maugis figures`: docs/figures.md and the model-only pictures in
//! docs/figures/ are what the command writes now (a cheap subset is
//! regenerated: the page and the figures without solver runs); every committed
//! picture (the solver overlays too) passes the rendered-legend checks of
//! `render`; bad input exits 2 and writes nothing.
//!
//! The solver figures are not regenerated here (about a minute of solver
//! runs); their pictures are checked as committed.

use crate::render;

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

fn maugis(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_maugis")).args(args).output().expect("spawn maugis")
}

fn docs() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../docs")
}

/// A fresh directory under the temp directory, removed on drop.
struct TempDir(PathBuf);

impl TempDir {
    fn new(tag: &str) -> TempDir {
        let nanos = std::time::SystemTime::now().duration_since(std::time::UNIX_EPOCH).map(|d| d.as_nanos()).unwrap_or(0);
        let p = std::env::temp_dir().join(format!("maugis-figures-{tag}-{}-{nanos}", std::process::id()));
        std::fs::create_dir(&p).unwrap();
        TempDir(p)
    }
}

impl Drop for TempDir {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.0);
    }
}

fn svgs(dir: &Path) -> Vec<String> {
    let mut v: Vec<String> = std::fs::read_dir(dir)
        .unwrap()
        .filter_map(|e| e.ok())
        .map(|e| e.file_name().to_string_lossy().into_owned())
        .filter(|n| n.ends_with(".svg"))
        .collect();
    v.sort();
    v
}

/// The figures without solver runs (their pictures do not depend on `--no-solver`).
const MODEL_ONLY: &str = "fig02,fig06,fig07,fig13";

#[test]
fn figures_md_is_current() {
    let tmp = TempDir::new("md");
    let out = tmp.0.join("figures");
    let page = tmp.0.join("figures.md");
    let o = maugis(&["figures", "--only", MODEL_ONLY, "--no-solver", "--out", out.to_str().unwrap(), "--write-doc", page.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(0), "stderr: {}", String::from_utf8_lossy(&o.stderr));
    let fresh = std::fs::read_to_string(&page).unwrap();
    let committed = std::fs::read_to_string(docs().join("figures.md")).expect("docs/figures.md");
    assert!(fresh == committed, "docs/figures.md is stale: regenerate with `maugis figures --out docs/figures --write-doc docs/figures.md`");
    // the model-only pictures, byte for byte
    let names = svgs(&out);
    for id in MODEL_ONLY.split(',') {
        assert!(names.iter().any(|n| n.starts_with(id)), "{id} wrote nothing: {names:?}");
    }
    for n in &names {
        let a = std::fs::read(out.join(n)).unwrap();
        let b = std::fs::read(docs().join("figures").join(n)).unwrap_or_default();
        assert!(a == b, "docs/figures/{n} is stale: regenerate with `maugis figures --out docs/figures --write-doc docs/figures.md`");
    }
    // every picture the page links is committed, and nothing else is
    let linked: Vec<String> = {
        let mut v: Vec<String> = committed
            .lines()
            .filter_map(|l| l.strip_prefix("![").and_then(|r| r.split("](figures/").nth(1)).and_then(|r| r.strip_suffix(')')))
            .map(str::to_string)
            .collect();
        v.sort();
        v
    };
    assert_eq!(linked, svgs(&docs().join("figures")));
    // a fresh model-only run of every figure writes exactly those files
    let all = tmp.0.join("all");
    let o = maugis(&["figures", "--no-solver", "--out", all.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(0), "stderr: {}", String::from_utf8_lossy(&o.stderr));
    assert_eq!(svgs(&all), linked);
}

/// Every committed picture passes the legend checks (rendered from a copy, so
/// that the PNGs land in the temp directory). `MAUGIS_FIGURES_DIR` names
/// another folder to check instead (a fresh `maugis figures` run, to look at
/// with `MAUGIS_RENDER_DIR`).
#[test]
fn committed_figures_render() {
    let tmp = TempDir::new("render");
    let dir = std::env::var_os("MAUGIS_FIGURES_DIR").map(PathBuf::from).unwrap_or_else(|| docs().join("figures"));
    let names = svgs(&dir);
    assert!(!names.is_empty() && (names.len() >= 20 || std::env::var_os("MAUGIS_FIGURES_DIR").is_some()), "{names:?}");
    let mut problems = Vec::new();
    for n in &names {
        let copy = tmp.0.join(n);
        std::fs::copy(dir.join(n), &copy).unwrap();
        match std::panic::catch_unwind(|| render::check_svg(&copy)) {
            Ok(report) if report.entries().count() >= 2 => {
                // a curve's entry shows its colour
                for e in report.entries().filter(|e| e.label.starts_with("λ = ") || e.label.starts_with("model, λ") || e.label.starts_with("solver, λ")) {
                    if !e.colours.iter().any(|c| c.chromatic()) {
                        problems.push(format!("{n}: entry {:?} has no colour: {:?}", e.label, e.colours));
                    }
                }
            }
            Ok(report) => problems.push(format!("{n}: too few legend entries: {report:?}")),
            Err(e) => problems.push(format!("{n}: {}", e.downcast_ref::<String>().cloned().unwrap_or_default())),
        }
    }
    assert!(problems.is_empty(), "{}", problems.join("\n"));
}

#[test]
fn bad_input_exits_2_and_writes_nothing() {
    let tmp = TempDir::new("bad");
    let out = tmp.0.join("out");
    for args in [
        vec!["--only", "fig99"],
        vec!["--grid", "1000"],
        vec!["--steps", "1"],
        vec!["--write-doc", "/no/such/folder/figures.md"],
    ] {
        let mut all = vec!["figures", "--no-solver", "--out", out.to_str().unwrap()];
        all.extend(args.iter().copied());
        let o = maugis(&all);
        assert_eq!(o.status.code(), Some(2), "{args:?}");
        let err = String::from_utf8_lossy(&o.stderr);
        assert!(err.starts_with("maugis: ") && err.lines().count() == 1, "{args:?}: {err}");
        assert!(!out.exists(), "{args:?} wrote {}", out.display());
    }
    // a foreign non-empty folder is refused
    std::fs::create_dir(&out).unwrap();
    std::fs::write(out.join("mine.txt"), "x").unwrap();
    let o = maugis(&["figures", "--no-solver", "--only", "fig02", "--out", out.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(2));
    assert_eq!(svgs(&out).len(), 0);
}
