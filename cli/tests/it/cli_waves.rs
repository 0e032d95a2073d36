//! Profiles of many waves through the command line (issue 35): `--wave A,B`
//! (repeatable), `--waves FILE.csv`, `--weierstrass N,GAMMA,H` for curve, profile,
//! limits, simulate and sweep (its regime maps: cli_sweep_waves.rs). One wave given as `--wave A,B` writes byte for byte what
//! `--alpha A --beta B` writes; every output names all the waves; bad input exits
//! with 2, one line on stderr, and writes nothing.

use std::path::PathBuf;
use std::process::{Command, Output};

use serde_json::Value;

use crate::render;

pub(crate) fn maugis(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_maugis")).args(args).output().expect("spawn maugis")
}

/// A fresh directory path under the temp directory (not created), removed on drop.
pub(crate) struct Scratch(pub(crate) PathBuf);

impl Scratch {
    pub(crate) fn new(tag: &str) -> Scratch {
        let nanos = std::time::SystemTime::now().duration_since(std::time::UNIX_EPOCH).map_or(0, |d| d.as_nanos());
        Scratch(std::env::temp_dir().join(format!("maugis-waves-{tag}-{}-{nanos}", std::process::id())))
    }
    fn join(&self, name: &str) -> String {
        self.0.join(name).to_str().unwrap().to_string()
    }
    pub(crate) fn s(&self) -> &str {
        self.0.to_str().unwrap()
    }
    /// The text of file `name` in this directory.
    pub(crate) fn read(&self, name: &str) -> String {
        std::fs::read_to_string(self.0.join(name)).unwrap_or_else(|e| panic!("{}/{name}: {e}", self.s()))
    }
}

impl Drop for Scratch {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.0);
        let _ = std::fs::remove_file(&self.0);
    }
}

fn json(args: &[&str]) -> Value {
    let o = maugis(args);
    assert!(o.status.success(), "{args:?}: {}", String::from_utf8_lossy(&o.stderr));
    serde_json::from_slice(&o.stdout).unwrap()
}

const SMALL: [&str; 4] = ["--amax", "3", "--points", "60"];

#[test]
fn one_wave_flag_writes_what_alpha_beta_write_byte_for_byte() {
    let (a, b) = (Scratch::new("ab"), Scratch::new("wave"));
    let common = ["curve", "--lambda", "1", "--lambda", "3"];
    let oa = maugis(&[&common[..], &SMALL, &["--alpha", "2*sqrt(2)/8", "--beta", "9/8", "--out", a.s()]].concat());
    let ob = maugis(&[&common[..], &SMALL, &["--wave", "2*sqrt(2)/8,9/8", "--out", b.s()]].concat());
    assert!(oa.status.success() && ob.status.success(), "{}", String::from_utf8_lossy(&ob.stderr));
    let mut names: Vec<String> = std::fs::read_dir(&a.0).unwrap().map(|e| e.unwrap().file_name().to_string_lossy().into_owned()).collect();
    names.sort();
    assert!(names.len() >= 5, "{names:?}");
    for n in &names {
        let (x, y) = (std::fs::read(a.0.join(n)).unwrap(), std::fs::read(b.0.join(n)).unwrap());
        assert!(x == y, "{n} differs between --alpha/--beta and --wave");
    }
    // the report too, but for the run time and the directory
    let strip = |o: &Output, dir: &str| {
        let t = String::from_utf8_lossy(&o.stdout).replace(dir, "OUT");
        t.lines().map(|l| l.split(" curve(s) in ").next().unwrap_or(l).to_string()).collect::<Vec<_>>()
    };
    assert_eq!(strip(&oa, a.s()), strip(&ob, b.s()));
    // and the JSON of every command that takes the waves
    for cmd in [&["curve", "--lambda", "2", "--format", "json", "--amax", "2", "--points", "30"][..], &["profile", "--lambda", "2", "--abar", "1.5", "--format", "json"], &["limits", "--lambda", "2", "--format", "json", "--points", "20"]] {
        let x = maugis(&[cmd, &["--alpha", "0.3", "--beta", "0.9"]].concat());
        let y = maugis(&[cmd, &["--wave", "0.3,0.9"]].concat());
        assert!(x.status.success() && x.stdout == y.stdout, "{cmd:?}");
    }
}

#[test]
fn many_waves_are_named_in_every_output() {
    let w = ["--wave", "0.35,1.125", "--wave", "0.18,0.375"];
    let v = json(&[&["curve", "--lambda", "3", "--format", "json", "--amax", "2", "--points", "40"][..], &w].concat());
    let waves = v["params"]["waves"].as_array().expect("params.waves");
    assert_eq!(waves.len(), 2);
    assert_eq!((waves[1]["alpha"].as_f64(), waves[1]["beta"].as_f64()), (Some(0.18), Some(0.375)));
    assert_eq!(v["curves"][0]["waves"].as_array().map(Vec::len), Some(2));
    for cmd in [&["profile", "--lambda", "3", "--abar", "1.2", "--format", "json"][..], &["limits", "--lambda", "3", "--format", "json", "--points", "10"]] {
        let v = json(&[cmd, &w].concat());
        let waves = if cmd[0] == "limits" { &v["params"]["waves"] } else { &v["waves"] };
        assert_eq!(waves.as_array().map(Vec::len), Some(2), "{cmd:?}: {v}");
    }
    // files: CSV columns per wave, the report line
    let out = Scratch::new("many");
    let o = maugis(&[&["curve", "--lambda", "3", "--amax", "2", "--points", "40", "--out", out.s()][..], &w].concat());
    assert!(o.status.success());
    let csv = std::fs::read_to_string(out.join("curve_lambda_3.csv")).unwrap();
    assert!(csv.starts_with("lambda,alpha_1,beta_1,alpha_2,beta_2,abar,"), "{}", csv.lines().next().unwrap());
    let report = String::from_utf8_lossy(&o.stdout);
    assert!(report.contains("2 waves (alpha, beta) = (0.35, 1.125) + (0.18, 0.375)"), "{report}");
    let svg = std::fs::read_to_string(out.join("load-area.svg")).unwrap();
    assert!(svg.contains("2 waves (α, β) = (0.35, 1.125) + (0.18, 0.375)"));
}

#[test]
fn a_harmonics_file_and_weierstrass_give_the_same_waves() {
    let dir = Scratch::new("file");
    std::fs::create_dir_all(&dir.0).unwrap();
    let file = dir.join("waves.csv");
    std::fs::write(&file, "# two waves\namplitude,wavelength\n0.35,1.125\n0.175,0.5625\n").unwrap();
    let base = ["curve", "--lambda", "2", "--format", "json", "--amax", "2", "--points", "30"];
    let from_file = json(&[&base[..], &["--waves", &file]].concat());
    let from_flags = json(&[&base[..], &["--wave", "0.35,1.125", "--wave", "0.175,0.5625"]].concat());
    assert_eq!(from_file, from_flags);
    // Weierstrass: gamma = 2, H = 1 halves both, from --alpha/--beta
    let w = json(&[&base[..], &["--alpha", "0.35", "--beta", "1.125", "--weierstrass", "2,2,1"]].concat());
    assert_eq!(w, from_flags);
    let w3 = json(&[&base[..], &["--wave", "0.4,2", "--weierstrass", "3,4,0.5"]].concat());
    let betas: Vec<f64> = w3["params"]["waves"].as_array().unwrap().iter().map(|x| x["beta"].as_f64().unwrap()).collect();
    assert_eq!(betas, vec![2.0, 0.5, 0.125]);
}

#[test]
fn bad_waves_exit_2_with_one_line_and_no_files() {
    let dir = Scratch::new("bad");
    std::fs::create_dir_all(&dir.0).unwrap();
    let empty = dir.join("empty.csv");
    std::fs::write(&empty, "# nothing\namplitude,wavelength\n").unwrap();
    let malformed = dir.join("malformed.csv");
    std::fs::write(&malformed, "0.3,1.125\n0.1;0.375\n").unwrap();
    let negative = dir.join("negative.csv");
    std::fs::write(&negative, "0.3,1.125\n-0.1,0.375\n").unwrap();
    let many = dir.join("many.csv");
    std::fs::write(&many, "0.01,1\n".repeat(65)).unwrap();
    let cases: Vec<(Vec<&str>, &str)> = vec![
        (vec!["--wave", "-0.1,1"], "amplitude"),
        (vec!["--wave", "nan,1"], "amplitude"),
        (vec!["--wave", "0.1,0"], "wavelength"),
        (vec!["--wave", "0.1"], "AMPLITUDE,WAVELENGTH"),
        (vec!["--wave", "0.1,1", "--alpha", "0.2"], "--alpha conflicts"),
        (vec!["--wave", "0.1,1", "--waves", &empty], "conflicts"),
        (vec!["--waves", &empty], "no wave"),
        (vec!["--waves", &malformed], "line 2"),
        (vec!["--waves", &negative], "wave 2: amplitude"),
        (vec!["--waves", &many], "65 waves"),
        (vec!["--waves", "/nonexistent/waves.csv"], "--waves"),
        (vec!["--weierstrass", "65,2,0.5"], "N must"),
        (vec!["--weierstrass", "3,1,0.5"], "GAMMA"),
        (vec!["--weierstrass", "3,2,1.5"], "H must"),
        (vec!["--wave", "0.1,1", "--wave", "0.1,0.5", "--weierstrass", "3,2,0.5"], "expands one first wave"),
    ];
    for (extra, needle) in cases {
        for cmd in [
            &["curve", "--lambda", "1", "--amax", "2", "--points", "20"][..],
            &["limits", "--lambda", "1", "--points", "10"],
            &["simulate", "--lambda", "1", "--grid", "512", "--steps", "4"],
            &["sweep", "--lambda-n", "2", "--n", "2", "--amax", "2", "--points", "20"],
        ] {
            let out = dir.join("out");
            let o = maugis(&[cmd, &extra, &["--out", &out]].concat());
            let err = String::from_utf8_lossy(&o.stderr);
            assert_eq!(o.status.code(), Some(2), "{cmd:?} {extra:?}: {err}");
            assert!(err.contains(needle), "{cmd:?} {extra:?}: {err}");
            assert!(!std::path::Path::new(&out).exists(), "{cmd:?} {extra:?} wrote files");
        }
    }
    // sweep: a profile is swept on the amplitude axis only, the solver map runs one
    // wave, and a scale that takes a wave out of range is refused before any work
    let two = ["--wave", "0.1,1", "--wave", "0.1,0.5", "--lambda-n", "2", "--n", "2", "--points", "20"];
    for (extra, needle) in [
        (&["--axis", "beta"][..], "--axis amplitude"),
        (&["--solver"], "--solver maps one wave"),
        (&["--max", "1e8"], "wave 1: amplitude"),
        (&["--max", "inf"], "--max"),
    ] {
        let out = dir.join("sweep");
        let o = maugis(&[&["sweep"][..], &two, extra, &["--out", &out]].concat());
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(2), "{extra:?}: {err}");
        assert!(err.contains(needle), "{extra:?}: {err}");
        assert!(!std::path::Path::new(&out).exists(), "{extra:?} wrote files");
    }
}

#[test]
fn simulate_runs_the_profile_of_many_waves_and_a_table_without_a_model() {
    let sim = ["simulate", "--lambda", "3", "--amax", "1.5", "--grid", "1024", "--steps", "10", "--format", "json"];
    let v = json(&[&sim[..], &["--wave", "0.35,1.125", "--wave", "0.18,0.375"]].concat());
    assert_eq!(v["profile"], "rough_cylinder");
    assert_eq!(v["waves"].as_array().map(Vec::len), Some(2));
    let states = v["states"].as_array().unwrap();
    assert!(states.iter().any(|s| s["model_load"].is_number()), "no state compared with the model");
    // a profile table without --alpha/--beta: no model compared, and the report says so
    let dir = Scratch::new("table");
    std::fs::create_dir_all(&dir.0).unwrap();
    let table = dir.join("h.csv");
    let rows: String = (0..=400).map(|i| -20.0 + 0.1 * i as f64).map(|x| format!("{x},{}\n", 0.5 * x * x)).collect();
    std::fs::write(&table, format!("x,h\n{rows}")).unwrap();
    let v = json(&[&sim[..], &["--profile", &table]].concat());
    assert_eq!(v["profile"], "table");
    assert!(v["states"].as_array().unwrap().iter().all(|s| s["model_load"].is_null()));
    let out = dir.join("out");
    let o = maugis(&["simulate", "--lambda", "3", "--amax", "1.5", "--grid", "1024", "--steps", "10", "--profile", &table, "--out", &out]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    assert!(String::from_utf8_lossy(&o.stdout).contains("no model curve"));
    // the periodic domain takes one sinusoid
    let o = maugis(&[&sim[..], &["--wave", "0.35,1.125", "--wave", "0.18,0.375", "--periodic"]].concat());
    assert_eq!(o.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&o.stderr).contains("periodic domain takes one sinusoid"));
}

/// The load-area plots of a two-wave and a 4-scale Weierstrass profile (the figures
/// of docs/model.md at 150 points): rendered, every legend readable and every
/// coloured line explained, the title naming the waves.
#[test]
fn the_plots_of_many_waves_read() {
    for (tag, waves) in [
        ("two", &["--wave", "2*sqrt(2)/8,9/8", "--wave", "sqrt(2)/8,3/8"][..]),
        ("weierstrass", &["--alpha", "2*sqrt(2)/8", "--beta", "9/8", "--weierstrass", "4,2,0.5"]),
    ] {
        let out = Scratch::new(&format!("plot-{tag}"));
        let o = maugis(&[&["curve", "--lambda", "1/2", "--lambda", "3", "--lambda", "6", "--points", "150", "--out", out.s()][..], waves].concat());
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        let report = render::check_svg(&out.0.join("load-area.svg"));
        for label in ["λ = 0.5", "λ = 3", "λ = 6"] {
            assert!(report.entries().any(|e| e.label.starts_with(label)), "{tag}: no legend entry {label}");
        }
        let svg = std::fs::read_to_string(out.0.join("load-area.svg")).unwrap();
        assert!(svg.contains(if tag == "two" { "2 waves (α, β)" } else { "4 waves (α, β)" }), "{tag}: title");
        render::check_svg(&out.0.join("load-approach.svg"));
    }
}
