//! `maugis multiscale envelope` (issue 39, item 1): a small study writes its CSV, JSON,
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
