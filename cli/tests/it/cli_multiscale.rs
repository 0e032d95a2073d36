//! `maugis multiscale envelope` (issue 39, item 1), `scales`, `merge` and `transition`
//! (items 2 and 3): a small study writes its CSV, JSON,
//! Markdown table and two plots that render with their legends; bad input exits with
//! 2 and writes nothing.

use std::path::PathBuf;
use std::process::{Command, Output};

use crate::render;

fn maugis(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_maugis")).args(args).output().expect("spawn maugis")
}

fn scratch(tag: &str) -> PathBuf {
    let nanos = std::time::SystemTime::now().duration_since(std::time::UNIX_EPOCH).map_or(0, |d| d.as_nanos());
    std::env::temp_dir().join(format!("maugis-multiscale-{tag}-{}-{nanos}", std::process::id()))
}

const SMALL: [&str; 10] = ["--scales", "2", "--gamma", "2,3", "--hurst", "0.5", "--lambda", "3,100", "--amax", "3"];

#[test]
fn a_small_envelope_study_writes_its_tables_and_plots() {
    let out = scratch("files");
    let o = maugis(&[&["multiscale", "envelope"][..], &SMALL, &["--figure", "2,2,0.5", "--out", out.to_str().unwrap()]].concat());
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let csv = std::fs::read_to_string(out.join("envelope.csv")).unwrap();
    let mut lines = csv.lines();
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    assert_eq!(&header[..4], ["scales", "gamma", "hurst", "lambda"]);
    let rows: Vec<Vec<&str>> = lines.map(|l| l.split(',').collect()).collect();
    assert_eq!(rows.len(), 4, "2 profiles x 2 lambda");
    let col = |name: &str| header.iter().position(|h| *h == name).unwrap();
    for r in &rows {
        let (t, up, lo) = (r[col("triangle")].parse::<f64>().unwrap(), r[col("upper")].parse::<f64>().unwrap(), r[col("lower")].parse::<f64>().unwrap());
        assert!(up <= t && lo <= t && up > 0.5 * t, "{r:?}");
        let ratio: f64 = r[col("local_up_ratio")].parse().unwrap();
        assert!(ratio > 0.5 && ratio < 1.03, "{r:?}");
    }
    let json: serde_json::Value = serde_json::from_str(&std::fs::read_to_string(out.join("envelope.json")).unwrap()).unwrap();
    assert_eq!(json["rows"].as_array().unwrap().len(), 4);
    let md = std::fs::read_to_string(out.join("envelope.md")).unwrap();
    assert_eq!(md.lines().filter(|l| l.starts_with("| 2 |")).count(), 2, "{md}");
    let ratios = render::check_svg(&out.join("envelope.svg"));
    assert!(ratios.entries().any(|e| e.label.starts_with("N = 2, gamma = 3")), "ratios plot legend");
    let wave = render::check_svg(&out.join("envelope-wave.svg"));
    for label in ["± T", "+M+", "λ = 3", "λ = 100"] {
        assert!(wave.entries().any(|e| e.label.starts_with(label)), "wave plot: no legend entry {label}");
    }
    let _ = std::fs::remove_dir_all(&out);
}

#[test]
fn bad_input_exits_2_and_writes_nothing() {
    for (tag, extra) in [
        ("hurst", &["--hurst", "1.5"][..]),
        ("gamma", &["--gamma", "1"]),
        ("amax", &["--amax", "1"]),
        ("lambda", &["--lambda", "nan"]),
        ("scales", &["--scales", "0"]),
        ("figure", &["--figure", "2,0.5,0.5"]),
        ("grid", &["--amax", "1e6"]),
    ] {
        let out = scratch(tag);
        let o = maugis(&[&["multiscale", "envelope", "--scales", "2", "--gamma", "2", "--hurst", "0.5", "--lambda", "3", "--out", out.to_str().unwrap()][..], extra].concat());
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(2), "{tag}: {err}");
        assert!(!out.exists(), "{tag}: wrote {}", out.display());
        assert!(!err.trim().is_empty(), "{tag}: no message");
    }
}

/// `maugis multiscale scales` (items 2 and 3): one scale at lambda = 1 (two
/// cycles, the smooth cylinder and the wave), as two shards merged; the
/// merged files, the tables and the plot with its legend; a study reusing it
/// runs nothing and writes the same rows.
#[test]
fn a_sharded_scales_study_merges_into_its_tables_and_plot() {
    let base = ["multiscale", "scales", "--max-scales", "1", "--hurst", "0.5", "--lambda", "1"];
    let (s1, s2, whole, again) = (scratch("s1"), scratch("s2"), scratch("whole"), scratch("again"));
    for (shard, dir) in [("1/2", &s1), ("2/2", &s2)] {
        let o = maugis(&[&base[..], &["--shard", shard, "--out", dir.to_str().unwrap()]].concat());
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        assert!(dir.join("scales.json").exists() && !dir.join("scales.csv").exists(), "a shard writes its JSON only");
    }
    let o = maugis(&["multiscale", "merge", s1.to_str().unwrap(), s2.to_str().unwrap(), "--out", whole.to_str().unwrap()]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let csv = std::fs::read_to_string(whole.join("scales.csv")).unwrap();
    let mut lines = csv.lines();
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    let rows: Vec<Vec<&str>> = lines.map(|l| l.split(',').collect()).collect();
    assert_eq!(rows.len(), 1, "{csv}");
    let col = |name: &str| header.iter().position(|h| *h == name).unwrap();
    let w: f64 = rows[0][col("w")].parse().unwrap();
    let sum: f64 = rows[0][col("w_sum_of_singles")].parse().unwrap();
    assert!(w > 0.2 && w == sum, "one scale: W {w}, the sum of singles {sum}");
    assert_eq!(std::fs::read_to_string(whole.join("cycles.csv")).unwrap().lines().count(), 3);
    let md = std::fs::read_to_string(whole.join("scales.md")).unwrap();
    assert!(md.contains("| 1 |") && md.contains("smallest N cavitating"), "{md}");
    let plot = render::check_svg(&whole.join("scales.svg"));
    for label in ["solver W, H = 0.5", "sum of the single scales", "model W"] {
        assert!(plot.entries().any(|e| e.label.starts_with(label)), "plot legend: no entry {label}");
    }
    // Reusing the merged study runs no cycle and gives the same rows.
    let o = maugis(&[&base[..], &["--reuse", whole.to_str().unwrap(), "--out", again.to_str().unwrap()]].concat());
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let rows_again = std::fs::read_to_string(again.join("scales.csv")).unwrap();
    assert_eq!(rows_again, csv);
    for d in [s1, s2, whole, again] {
        let _ = std::fs::remove_dir_all(d);
    }
}

#[test]
fn bad_scales_input_exits_2_and_writes_nothing() {
    let s1 = scratch("lonely");
    let o = maugis(&["multiscale", "scales", "--max-scales", "1", "--hurst", "0.5", "--lambda", "1", "--shard", "1/2", "--out", s1.to_str().unwrap()]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    for (tag, args) in [
        ("gamma", vec!["multiscale", "scales", "--gamma", "1"]),
        ("hurst", vec!["multiscale", "scales", "--hurst", "2"]),
        ("scales", vec!["multiscale", "scales", "--max-scales", "0"]),
        ("shard", vec!["multiscale", "scales", "--shard", "3/2"]),
        ("lambda", vec!["multiscale", "scales", "--lambda", "-1"]),
        ("merge-missing", vec!["multiscale", "merge", s1.to_str().unwrap()]),
        ("merge-none", vec!["multiscale", "merge", "/nonexistent-maugis-dir"]),
        ("transition-scales", vec!["multiscale", "transition", "--max-scales", "2", "--scales", "3"]),
        ("transition-range", vec!["multiscale", "transition", "--lambda-min", "3", "--lambda-max", "1"]),
    ] {
        let out = scratch(tag);
        let o = maugis(&[&args[..], &["--out", out.to_str().unwrap()]].concat());
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(2), "{tag}: {err}");
        assert!(!out.exists(), "{tag}: wrote {}", out.display());
        assert!(!err.trim().is_empty(), "{tag}: no message");
    }
    let _ = std::fs::remove_dir_all(s1);
}

fn docs() -> PathBuf {
    std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../docs")
}

/// The committed studies behind docs/multiscale.md (items 2 and 4): in every
/// `docs/multiscale/*` folder holding a `scales.json`, `maugis multiscale merge`
/// rewrites the CSVs, the tables and the plot byte for byte (the figures are
/// drawn from the committed data, not edited by hand), and every W row of the
/// page's answer tables is a row of one of those tables.
#[test]
fn the_committed_scales_studies_are_what_merge_writes() {
    let dirs: Vec<PathBuf> = {
        let mut v: Vec<PathBuf> = std::fs::read_dir(docs().join("multiscale"))
            .expect("docs/multiscale")
            .filter_map(|e| e.ok().map(|e| e.path()))
            .filter(|p| p.join("scales.json").exists())
            .collect();
        v.sort();
        v
    };
    assert!(dirs.len() >= 2, "no committed scales studies: {dirs:?}");
    let mut tables = String::new();
    for dir in &dirs {
        let out = scratch("committed");
        let o = maugis(&["multiscale", "merge", dir.to_str().unwrap(), "--out", out.to_str().unwrap()]);
        assert!(o.status.success(), "{}: {}", dir.display(), String::from_utf8_lossy(&o.stderr));
        for name in ["scales.csv", "cycles.csv", "scales.md", "scales.svg"] {
            let fresh = std::fs::read(out.join(name)).unwrap();
            let committed = std::fs::read(dir.join(name)).unwrap_or_default();
            assert!(fresh == committed, "{}/{name} is stale: redraw with `maugis multiscale merge {0} --out <tmp>` and copy it back", dir.display());
        }
        tables.push_str(&std::fs::read_to_string(dir.join("scales.md")).unwrap());
        let _ = std::fs::remove_dir_all(out);
    }
    let page = std::fs::read_to_string(docs().join("multiscale.md")).unwrap();
    let answer = page.split("### The answer").nth(1).and_then(|s| s.split("## 3.").next()).expect("section 2's answer");
    let w_rows: Vec<&str> = answer.lines().filter(|l| l.starts_with("| ") && l.contains(" / ")).collect();
    assert!(w_rows.len() >= 10, "the answer's W tables: {w_rows:?}");
    for row in w_rows {
        assert!(tables.lines().any(|l| l == row), "docs/multiscale.md row not in any committed scales.md: {row}");
    }
}
