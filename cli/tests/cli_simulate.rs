//! `maugis simulate`: a small run writes CSV and SVG; bad input exits 2 and writes nothing.

use std::process::Command;

fn maugis() -> Command {
    Command::new(env!("CARGO_BIN_EXE_maugis"))
}

#[test]
fn small_run_writes_csv_and_svg() {
    let dir = std::env::temp_dir().join(format!("maugis-sim-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    let out = maugis()
        .args(["simulate", "--lambda", "1", "--alpha", "0", "--beta", "1", "--amax", "1.5", "--grid", "512", "--steps", "6", "--out"])
        .arg(&dir)
        .output()
        .unwrap();
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let csv = std::fs::read_to_string(dir.join("simulate.csv")).unwrap();
    assert!(csv.starts_with("leg,approach,abar,load,contact_intervals"));
    assert!(csv.lines().any(|l| l.starts_with("unloading,")));
    assert!(std::fs::read_to_string(dir.join("simulate.svg")).unwrap().contains("<svg"));
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn bad_input_exits_2_without_files() {
    let dir = std::env::temp_dir().join(format!("maugis-sim-bad-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    for args in [
        vec!["--lambda", "-1", "--alpha", "0", "--beta", "1"],
        vec!["--lambda", "1", "--alpha", "0", "--beta", "1", "--grid", "1000"],
        vec!["--lambda", "1", "--alpha", "0", "--beta", "1", "--steps", "1"],
    ] {
        let out = maugis().arg("simulate").args(&args).arg("--out").arg(&dir).output().unwrap();
        assert_eq!(out.status.code(), Some(2), "{args:?}");
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(err.lines().count(), 1, "{err}");
        assert!(!dir.exists());
    }
}
