//! `maugis simulate`: a small run writes CSV and SVG (rendered and its legend
//! checked, `render`); bad input exits 2 and writes nothing.

use crate::render;

use std::process::Command;

fn maugis() -> Command {
    Command::new(env!("CARGO_BIN_EXE_maugis"))
}

#[test]
fn small_run_writes_csv_and_svg() {
    let dir = std::env::temp_dir().join(format!("maugis-sim-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    let out = maugis()
        .args(["simulate", "--lambda", "1", "--alpha", "0", "--beta", "1", "--amax", "2.5", "--grid", "512", "--steps", "10", "--out"])
        .arg(&dir)
        .output()
        .unwrap();
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let csv = std::fs::read_to_string(dir.join("simulate.csv")).unwrap();
    let header = csv.lines().next().unwrap();
    assert!(header.starts_with("leg,approach,abar,load,contact_intervals"));
    assert!(header.ends_with(",load_controlled,zone_ends_placed"));
    // zone_ends_placed: a bool on every row, and the ends are placed on most states
    let placed: Vec<bool> = csv.lines().skip(1).map(|l| l.rsplit(',').next().unwrap().parse().unwrap()).collect();
    assert!(placed.iter().filter(|&&p| p).count() * 2 > placed.len(), "{placed:?}");
    assert!(csv.lines().any(|l| l.starts_with("unloading,")));
    // The load-controlled path: on loading its loads rise; some unloading
    // states are on it, and the unloading path's loads fall.
    for leg in ["loading,", "unloading,"] {
        let loads: Vec<f64> = csv
            .lines()
            .filter(|l| l.starts_with(leg) && l.split(',').nth(8) == Some("true"))
            .map(|l| l.split(',').nth(3).unwrap().parse().unwrap())
            .collect();
        assert!(loads.len() >= 2, "{leg} {loads:?}");
        let rising = leg == "loading,";
        assert!(loads.windows(2).all(|w| if rising { w[1] > w[0] } else { w[1] < w[0] }), "{leg} {loads:?}");
    }
    assert!(std::fs::read_to_string(dir.join("simulate.svg")).unwrap().contains("<svg"));
    let report = render::check_svg(&dir.join("simulate.svg"));
    let colour = |label: &str| report.entry(label).colours.iter().find(|c| c.chromatic()).map(|c| c.rgb);
    let (loading, unloading) = (colour("simulation, loading"), colour("simulation, unloading"));
    assert!(loading.is_some() && unloading.is_some() && loading != unloading, "{report:?}");
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn json_carries_the_load_controlled_path_and_pull_off() {
    let out = maugis()
        .args(["simulate", "--lambda", "1", "--alpha", "0", "--beta", "1", "--amax", "2.5", "--grid", "512", "--steps", "10", "--format", "json"])
        .output()
        .unwrap();
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let pull_off = v["pull_off"].as_f64().expect("pull_off");
    let states = v["states"].as_array().unwrap();
    let on_path: Vec<&serde_json::Value> = states.iter().filter(|s| s["load_controlled"] == true).collect();
    assert!(states.iter().all(|s| s["zone_ends_placed"].is_boolean()));
    assert!(on_path.len() >= 4 && on_path.len() < states.len());
    // Pull-off is the most tensile load of the unloading leg, and on the path.
    let min_unloading = states.iter().filter(|s| s["leg"] == "unloading").map(|s| s["load"].as_f64().unwrap()).fold(f64::INFINITY, f64::min);
    assert!(pull_off < 0.0 && pull_off == min_unloading, "{pull_off} {min_unloading}");
    assert!(on_path.iter().any(|s| s["load"].as_f64() == Some(pull_off)));
    // W of the closed in-contact cycle with the curve's keys (0 for the smooth
    // cylinder), next to the stiff-machine work, which is not W.
    let d = &v["dissipation"];
    let (w, wd) = (d["load_control"].as_f64().expect("W"), d["displacement_control"].as_f64().expect("W_d"));
    assert!(w.abs() <= 0.02 && wd.abs() <= 0.02, "W {w}, W_d {wd}");
    assert_eq!(d["datum"].as_f64(), Some(100.0));
    assert!(v["stiff_cycle_work"].as_f64().expect("stiff_cycle_work") > 0.1);
    assert!(v.get("dissipated").is_none());
}

#[test]
fn bad_input_exits_2_without_files() {
    let dir = std::env::temp_dir().join(format!("maugis-sim-bad-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    for args in [
        vec!["--lambda", "-1", "--alpha", "0", "--beta", "1"],
        vec!["--lambda", "1", "--alpha", "0", "--beta", "1", "--grid", "1000"],
        vec!["--lambda", "1", "--alpha", "0", "--beta", "1", "--steps", "1"],
        vec!["--lambda", "nan", "--alpha", "0", "--beta", "1"],
        vec!["--lambda", "1e5", "--alpha", "0", "--beta", "1"],
        vec!["--lambda", "1", "--alpha", "-0.1", "--beta", "1"],
        vec!["--lambda", "1", "--alpha", "0", "--beta", "0"],
        vec!["--lambda", "1", "--alpha", "0", "--beta", "1", "--amax", "-1"],
        vec!["--lambda", "1", "--alpha", "0", "--beta", "1", "--amax", "inf"],
        vec!["--lambda", "1", "--alpha", "0", "--beta", "1", "--grid", "32"],
        vec!["--lambda", "1", "--alpha", "0", "--beta", "1", "--grid", "0"],
        vec!["--lambda", "1", "--alpha", "0", "--beta", "1", "--format", "xml"],
        vec!["--lambda", "1", "--alpha", "0", "--beta", "1", "--law", "lj93"],
    ] {
        let out = maugis().arg("simulate").args(&args).arg("--out").arg(&dir).output().unwrap();
        assert_eq!(out.status.code(), Some(2), "{args:?}");
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(err.lines().count(), 1, "{err}");
        assert!(!dir.exists());
    }
}

/// `--law exp`: the smooth law runs, is named in the JSON, and pulls off at
/// another load than Dugdale's at lambda = 1 (the laws differ in shape).
#[test]
fn law_exp_runs_and_is_named() {
    let run = |law: &str| {
        let out = maugis()
            .args(["simulate", "--lambda", "1", "--alpha", "0", "--beta", "1", "--amax", "2.5", "--grid", "512", "--steps", "20", "--format", "json", "--law", law])
            .output()
            .unwrap();
        assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
        serde_json::from_slice::<serde_json::Value>(&out.stdout).unwrap()
    };
    let (e, d) = (run("exp"), run("dugdale"));
    assert_eq!(e["law"], "exp");
    assert_eq!(d["law"], "dugdale");
    let (pe, pd) = (e["pull_off"].as_f64().unwrap(), d["pull_off"].as_f64().unwrap());
    assert!(pe < 0.0 && (pe - pd).abs() > 0.01, "exp {pe}, dugdale {pd}");
    // The smooth cylinder dissipates nothing under either law.
    assert!(e["dissipation"]["load_control"].as_f64().unwrap().abs() <= 0.02);
}
