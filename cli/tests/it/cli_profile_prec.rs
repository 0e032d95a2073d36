//! `maugis profile --prec P`: the traction at the profile's points as certified
//! balls (`pbar_mid`, `pbar_rad`), checked against the f64 traction column.

use std::process::Command;

fn profile(args: &[&str]) -> (String, String, i32) {
    let out = Command::new(env!("CARGO_BIN_EXE_maugis")).arg("profile").args(args).output().expect("run maugis");
    (String::from_utf8_lossy(&out.stdout).into_owned(), String::from_utf8_lossy(&out.stderr).into_owned(), out.status.code().unwrap_or(-1))
}

const STATE: [&str; 8] = ["--abar", "1.3", "--lambda", "0.5", "--alpha", "0.1", "--beta", "1.125"];

#[test]
fn json_samples_carry_certified_traction() {
    let mut args = STATE.to_vec();
    args.extend(["--points", "40", "--prec", "80", "--format", "json"]);
    let (out, err, code) = profile(&args);
    assert_eq!(code, 0, "{err}");
    let v: serde_json::Value = serde_json::from_str(&out).expect("JSON");
    let samples = v["samples"].as_array().expect("samples");
    assert!(samples.len() >= 40);
    let mut inside = 0;
    for s in samples {
        let f = s["pbar"].as_f64().unwrap();
        let mid: f64 = s["pbar_mid"].as_str().expect("pbar_mid").parse().unwrap();
        let rad: f64 = s["pbar_rad"].as_str().expect("pbar_rad").parse().unwrap();
        // the f64 traction within 1e-9 of the ball (the f64 route is an estimate)
        assert!((mid - f).abs() <= rad + 1e-9, "x = {}: ball {mid} +/- {rad} vs f64 {f}", s["xbar"]);
        assert!(rad < 1e-20, "x = {}: rad {rad}", s["xbar"]);
        if s["xbar"].as_f64().unwrap() < 1.3 {
            inside += 1;
            assert!(mid != 0.0 && mid != 1.0);
        }
    }
    assert!(inside >= 10, "{inside} points inside the contact");
}

#[test]
fn without_prec_no_ball_fields() {
    let mut args = STATE.to_vec();
    args.extend(["--points", "5", "--format", "json"]);
    let (out, err, code) = profile(&args);
    assert_eq!(code, 0, "{err}");
    assert!(!out.contains("pbar_mid") && out.contains("\"pbar\""));
}

#[test]
fn csv_has_ball_columns() {
    let dir = std::env::temp_dir().join(format!("maugis-profile-prec-{}", std::process::id()));
    let mut args = STATE.to_vec();
    let d = dir.to_string_lossy().into_owned();
    args.extend(["--points", "6", "--prec", "64", "--out", &d]);
    let (_, err, code) = profile(&args);
    assert_eq!(code, 0, "{err}");
    let csv = std::fs::read_to_string(dir.join("profile.csv")).unwrap();
    let mut lines = csv.lines();
    assert_eq!(lines.next().unwrap(), "xbar,pbar,ubar,gbar,hbar,pbar_mid,pbar_rad");
    for line in lines {
        let cols: Vec<&str> = line.split(',').collect();
        assert_eq!(cols.len(), 7, "{line}");
        let (f, mid): (f64, f64) = (cols[1].parse().unwrap(), cols[5].parse().unwrap());
        assert!((f - mid).abs() < 1e-9, "{line}");
    }
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn bad_prec_is_rejected() {
    for p in ["0", "1", "5000", "x"] {
        let mut args = STATE.to_vec();
        args.extend(["--prec", p, "--format", "json"]);
        let (out, _, code) = profile(&args);
        assert_eq!(code, 2, "--prec {p}");
        assert!(out.is_empty());
    }
}
