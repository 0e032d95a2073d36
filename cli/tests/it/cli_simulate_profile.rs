//! `maugis simulate --profile FILE.csv`: a table sampled from the Fig. 4c
//! profile gives the built-in run's loads (within 1e-3 of the load scale);
//! a malformed table exits 2, names the file and the line, and writes nothing.

use std::path::{Path, PathBuf};
use std::process::Command;

const ALPHA: f64 = std::f64::consts::SQRT_2 / 4.0;
const BETA: f64 = 1.125;

fn maugis() -> Command {
    Command::new(env!("CARGO_BIN_EXE_maugis"))
}

fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("maugis-sim-profile-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

const RUN: [&str; 10] = ["--lambda", "1", "--amax", "2.5", "--grid", "1024", "--steps", "20", "--format", "json"];

fn run_json(extra: &[&str]) -> serde_json::Value {
    let (a, b) = (ALPHA.to_string(), BETA.to_string());
    let out = maugis().arg("simulate").args(RUN).args(["--alpha", &a, "--beta", &b]).args(extra).output().unwrap();
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    serde_json::from_slice(&out.stdout).unwrap()
}

fn write_table(path: &Path, half_width: f64) {
    let mut text = String::from("x,h\n");
    let n = ((2.0 * half_width + 1.0) / 0.01).ceil() as usize;
    for k in 0..=n {
        let x = -half_width - 0.5 + k as f64 * 0.01;
        let h = 0.5 * x * x + ALPHA * (1.0 - (2.0 * std::f64::consts::PI * x / BETA).cos());
        text.push_str(&format!("{x},{h}\n"));
    }
    std::fs::write(path, text).unwrap();
}

#[test]
fn a_fig4c_table_gives_the_built_in_loads() {
    let dir = scratch("ok");
    let built_in = run_json(&[]);
    let x = built_in["half_width"].as_f64().unwrap();
    let csv = dir.join("fig4c.csv");
    write_table(&csv, x);
    let from_table = run_json(&["--profile", csv.to_str().unwrap()]);
    assert_eq!(built_in["profile"], "wavy_cylinder");
    assert_eq!(from_table["profile"], "table");
    let loads = |v: &serde_json::Value| v["states"].as_array().unwrap().iter().map(|s| s["load"].as_f64().unwrap()).collect::<Vec<f64>>();
    let (a, b) = (loads(&built_in), loads(&from_table));
    assert_eq!(a.len(), b.len());
    let worst = a.iter().zip(&b).map(|(p, q)| (p - q).abs()).fold(0.0, f64::max);
    assert!(worst <= 1e-3, "{worst}");
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn a_malformed_table_exits_2_naming_the_line() {
    let dir = scratch("bad");
    let cases: [(&str, String, &str); 5] = [
        ("header.csv", "x,depth\n-9,1\n0,0\n9,1\n10,2\n".into(), "line 1"),
        ("row.csv", "x,h\n-30,450\n-1,0.5\n1,0.5\n2,two\n30,450\n".into(), "line 5"),
        ("fields.csv", "x,h\n-30,450\n-1,0.5,7\n1,0.5\n30,450\n".into(), "line 3"),
        ("unsorted.csv", "x,h\n-30,450\n1,0.5\n-1,0.5\n30,450\n".into(), "line 4"),
        ("short.csv", "x,h\n-1,0.5\n0,0\n1,0.5\n2,2\n".into(), "covers x in [-1, 2]"),
    ];
    for (name, text, expected) in cases {
        let csv = dir.join(name);
        std::fs::write(&csv, text).unwrap();
        let out_dir = dir.join("out");
        let out = maugis()
            .args(["simulate", "--lambda", "1", "--alpha", "0", "--beta", "1", "--amax", "2", "--grid", "512", "--steps", "10"])
            .arg("--profile")
            .arg(&csv)
            .arg("--out")
            .arg(&out_dir)
            .output()
            .unwrap();
        assert_eq!(out.status.code(), Some(2), "{name}");
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(err.lines().count(), 1, "{name}: {err}");
        assert!(err.contains(expected) && err.contains(name), "{name}: {err}");
        assert!(!out_dir.exists(), "{name}");
    }
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn bad_domain_options_exit_2() {
    let dir = scratch("opts");
    let out_dir = dir.join("out");
    for extra in [
        vec!["--alpha", "0", "--beta", "4", "--periodic"],
        vec!["--alpha", "0", "--beta", "1", "--half-width", "-1"],
        vec!["--alpha", "0", "--beta", "1", "--half-width", "nan"],
        vec!["--alpha", "0", "--beta", "1", "--half-width", "1"],
        vec!["--alpha", "0", "--beta", "1", "--profile", "/nonexistent/table.csv"],
    ] {
        let out = maugis()
            .args(["simulate", "--lambda", "1", "--amax", "2", "--grid", "512", "--steps", "10"])
            .args(&extra)
            .arg("--out")
            .arg(&out_dir)
            .output()
            .unwrap();
        assert_eq!(out.status.code(), Some(2), "{extra:?}");
        assert_eq!(String::from_utf8_lossy(&out.stderr).lines().count(), 1, "{extra:?}");
        assert!(!out_dir.exists(), "{extra:?}");
    }
    let _ = std::fs::remove_dir_all(&dir);
}
