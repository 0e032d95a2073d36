//! `maugis curve`, `maugis profile`, `maugis limits`, `maugis sweep` and `maugis merge` end to end: the JSON
//! schema, the files written, atomic output, and one-line usage errors (exit
//! code 2, nothing written). Small grids keep it fast. Every SVG written is
//! rendered and its legend checked (`render`).

use crate::render;

use std::path::{Path, PathBuf};
use std::process::{Command, Output};
use std::sync::atomic::{AtomicUsize, Ordering};

use serde_json::Value;

fn maugis(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_maugis")).args(args).output().expect("spawn maugis")
}

/// A fresh, not yet existing path under the temp directory; removed on drop
/// (with any `<name>.tmp-*` sibling).
struct TempPath(PathBuf);

impl TempPath {
    fn new(tag: &str) -> TempPath {
        static N: AtomicUsize = AtomicUsize::new(0);
        let nanos = std::time::SystemTime::now().duration_since(std::time::UNIX_EPOCH).map(|d| d.as_nanos()).unwrap_or(0);
        let name = format!("maugis-cli-{tag}-{}-{}-{nanos}", std::process::id(), N.fetch_add(1, Ordering::SeqCst));
        let p = std::env::temp_dir().join(name);
        assert!(!p.exists());
        TempPath(p)
    }
    fn path(&self) -> &Path {
        &self.0
    }
    fn str(&self) -> &str {
        self.0.to_str().expect("utf-8 temp path")
    }
    /// Leftover temporary siblings `<name>.tmp-*`.
    fn tmp_siblings(&self) -> Vec<PathBuf> {
        let name = self.0.file_name().unwrap().to_string_lossy().into_owned();
        let parent = self.0.parent().unwrap();
        std::fs::read_dir(parent)
            .unwrap()
            .filter_map(|e| e.ok())
            .map(|e| e.path())
            .filter(|p| p.file_name().map(|f| f.to_string_lossy().starts_with(&format!("{name}.tmp-"))).unwrap_or(false))
            .collect()
    }
}

impl Drop for TempPath {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.0);
        for p in self.tmp_siblings() {
            let _ = std::fs::remove_dir_all(p);
        }
    }
}

fn stdout(o: &Output) -> String {
    String::from_utf8(o.stdout.clone()).expect("utf-8 stdout")
}

fn stderr(o: &Output) -> String {
    String::from_utf8(o.stderr.clone()).expect("utf-8 stderr")
}

fn keys(v: &Value) -> Vec<String> {
    let mut k: Vec<String> = v.as_object().expect("object").keys().cloned().collect();
    k.sort();
    k
}

fn sorted(k: &[&str]) -> Vec<String> {
    let mut v: Vec<String> = k.iter().map(|s| s.to_string()).collect();
    v.sort();
    v
}

fn is_num(v: &Value) -> bool {
    v.is_number()
}

#[test]
fn curve_json_follows_the_schema() {
    let dir = TempPath::new("json");
    let o = maugis(&["curve", "--lambda", "1", "--lambda", "6", "--points", "60", "--format", "json", "--out", dir.str()]);
    assert_eq!(o.status.code(), Some(0), "stderr: {}", stderr(&o));
    assert!(!dir.path().exists(), "--format json must write no files");
    let text = stdout(&o);
    assert_eq!(text.trim().lines().count(), 1, "one JSON object on one line");
    let v: Value = serde_json::from_str(text.trim()).expect("valid JSON");
    assert_eq!(keys(&v), sorted(&["params", "mdmt_limit_lambda", "curves"]));
    let p = &v["params"];
    assert_eq!(keys(p), sorted(&["alpha", "beta", "amax", "points", "datum"]));
    assert!((p["alpha"].as_f64().unwrap() - 2f64.sqrt() / 4.0).abs() < 1e-15);
    assert_eq!(p["beta"].as_f64(), Some(1.125));
    assert_eq!(p["amax"].as_f64(), Some(6.0));
    assert_eq!(p["points"].as_u64(), Some(60));

    let curves = v["curves"].as_array().expect("curves array");
    assert_eq!(curves.len(), 2);
    let lambdas: Vec<f64> = curves.iter().map(|c| c["lambda"].as_f64().unwrap()).collect();
    assert_eq!(lambdas, [1.0, 6.0]);
    let mut n_turning = 0;
    let mut n_jumps = 0;
    for c in curves {
        assert_eq!(
            keys(c),
            sorted(&[
                "lambda", "alpha", "beta", "csv", "invalid_points", "invalid_stretches", "turning_points", "jumps", "loops",
                "pull_off", "valid_pull_off", "dissipation", "load_control", "displacement_control", "points",
            ])
        );
        assert!(c["csv"].is_null());
        let pts = c["points"].as_array().unwrap();
        assert_eq!(pts.len(), 60);
        let mut prev = 0.0;
        for q in pts {
            assert_eq!(keys(q), sorted(&["abar", "m", "m_minus_1", "load", "approach", "validity"]));
            for k in ["abar", "m", "m_minus_1", "load", "approach"] {
                assert!(is_num(&q[k]), "{k} = {}", q[k]);
            }
            assert!(q["validity"]["valid"].is_boolean());
            let a = q["abar"].as_f64().unwrap();
            assert!(a > prev && a <= 6.0 + 1e-12);
            prev = a;
            assert!(q["m_minus_1"].as_f64().unwrap() > 0.0);
        }
        for t in c["turning_points"].as_array().unwrap() {
            assert_eq!(keys(t), sorted(&["abar", "load", "kind"]));
            let k = t["kind"].as_str().unwrap();
            assert!(k == "max" || k == "min", "{k}");
            n_turning += 1;
        }
        for j in c["jumps"].as_array().unwrap() {
            assert_eq!(keys(j), sorted(&["direction", "from", "to", "from_turning_point"]));
            let d = j["direction"].as_str().unwrap();
            assert!(d == "loading" || d == "unloading", "{d}");
            let (from, to) = (j["from"]["abar"].as_f64().unwrap(), j["to"]["abar"].as_f64().unwrap());
            if d == "loading" {
                assert!(to > from);
            } else {
                assert!(to < from);
            }
            assert_eq!(j["from"]["load"].as_f64(), j["to"]["load"].as_f64(), "a load-control jump keeps the load");
            n_jumps += 1;
        }
        let d = &c["dissipation"];
        assert!(is_num(&d["load_control"]) && is_num(&d["displacement_control"]));
        let po = &c["pull_off"];
        assert!(is_num(&po["abar"]) && is_num(&po["load"]) && po["validity"]["valid"].is_boolean());
    }
    assert!(n_turning > 0 && n_jumps > 0);
}

/// The numbers of a Markdown page, in order.
fn numbers(text: &str) -> Vec<f64> {
    text.split(|c: char| !(c.is_ascii_digit() || c == '.' || c == '-' || c == '+'))
        .filter_map(|t| t.trim_matches(|c| c == '.' || c == '+').parse::<f64>().ok())
        .collect()
}

/// docs/paper.md is what `maugis paper` generates now (every number, to the
/// printed digits).
#[test]
fn paper_md_is_current() {
    let dir = TempPath::new("paper");
    std::fs::create_dir(dir.path()).unwrap();
    let file = dir.path().join("paper.md");
    let o = maugis(&["paper", "--write", file.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(0), "stderr: {}", stderr(&o));
    let fresh = std::fs::read_to_string(&file).unwrap();
    let committed = std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("../docs/paper.md")).expect("docs/paper.md");
    let (a, b) = (numbers(&fresh), numbers(&committed));
    assert_eq!(a.len(), b.len(), "docs/paper.md is stale: regenerate with `maugis paper --write docs/paper.md`");
    for (x, y) in a.iter().zip(&b) {
        assert!((x - y).abs() <= 1e-4 + 1e-9 * x.abs(), "docs/paper.md is stale ({x} vs {y}): regenerate with `maugis paper --write docs/paper.md`");
    }
    // stdout without --write; a missing folder is refused
    let o = maugis(&["paper"]);
    assert_eq!(o.status.code(), Some(0));
    assert_eq!(numbers(&stdout(&o)), a);
    let o = maugis(&["paper", "--write", dir.path().join("no/such/paper.md").to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("--write"));
}

/// PDMS-like material used by the SI tests.
const SI: [&str; 12] = ["--units", "si", "--e-star", "2e6", "--radius", "1e-3", "--dgamma", "0.05", "--amplitude", "2.5e-7", "--wavelength", "3.3e-5"];

fn json_of(args: &[&str]) -> Value {
    let o = maugis(args);
    assert_eq!(o.status.code(), Some(0), "{args:?}: stderr: {}", stderr(&o));
    serde_json::from_str(stdout(&o).trim()).expect("valid JSON")
}

/// `--units si`: the same curve as the normalised run at the derived lambda,
/// alpha, beta; SI values are the normalised ones times the scales; `--sigma`
/// and `--delta-c = dgamma/sigma` agree; CSV and profile carry SI columns.
#[test]
fn units_si_converts_inputs_and_outputs() {
    let mut args = vec!["curve", "--points", "120", "--format", "json", "--sigma", "1.5e5"];
    args.extend(SI);
    let si = json_of(&args);
    let c = &si["curves"][0];
    let (lambda, alpha, beta) = (c["lambda"].as_f64().unwrap(), c["alpha"].as_f64().unwrap(), c["beta"].as_f64().unwrap());
    // by hand: l_h = (dgamma R^2/E*)^(1/3), l_v = l_h^2/R, sigma scale (E*^2 dgamma/R)^(1/3)
    let (e, r, g) = (2e6f64, 1e-3f64, 0.05f64);
    let lh = (g * r * r / e).cbrt();
    let lv = lh * lh / r;
    assert!((lambda / (1.5e5 / (e * e * g / r).cbrt()) - 1.0).abs() < 1e-12, "{lambda}");
    assert!((alpha / (2.5e-7 / lv) - 1.0).abs() < 1e-12 && (beta / (3.3e-5 / lh) - 1.0).abs() < 1e-12);
    // the normalised run at those parameters is the same object plus nothing
    let norm = json_of(&["curve", "--points", "120", "--format", "json", "--lambda", &lambda.to_string(), "--alpha", &alpha.to_string(), "--beta", &beta.to_string()]);
    assert_eq!(norm["curves"], si["curves"]);
    assert!(norm.get("si").is_none());
    let s = &si["si"];
    let load_scale = (e * g * g * r).cbrt();
    let po = c["pull_off"]["load"].as_f64().unwrap();
    let sc = &s["curves"][0];
    assert!((sc["pull_off_load_n_per_m"].as_f64().unwrap() / (po * load_scale) - 1.0).abs() < 1e-12);
    assert!((sc["pull_off_half_width_m"].as_f64().unwrap() / (c["pull_off"]["abar"].as_f64().unwrap() * lh) - 1.0).abs() < 1e-12);
    let w = c["dissipation"]["load_control"].as_f64().unwrap();
    assert!((sc["dissipation_load_control_j_per_m"].as_f64().unwrap() - w * g * lh).abs() <= 1e-12 * (w * g * lh).abs().max(1e-300));
    assert!((sc["delta_c_m"].as_f64().unwrap() / (g / 1.5e5) - 1.0).abs() < 1e-12);
    assert!((s["scales"]["vertical"].as_f64().unwrap() / lv - 1.0).abs() < 1e-12);
    // --delta-c = dgamma/sigma_0 gives the same lambda
    let mut args = vec!["curve", "--points", "120", "--format", "json", "--delta-c"];
    let dc = (g / 1.5e5).to_string();
    args.push(&dc);
    args.extend(SI);
    let by_range = json_of(&args);
    assert!((by_range["curves"][0]["lambda"].as_f64().unwrap() / lambda - 1.0).abs() < 1e-12);
    // files: CSV with SI columns, summary.json with the si object
    let dir = TempPath::new("si");
    let mut args = vec!["curve", "--points", "40", "--sigma", "1.5e5", "--out", dir.str()];
    args.extend(SI);
    let o = maugis(&args);
    assert_eq!(o.status.code(), Some(0), "stderr: {}", stderr(&o));
    assert!(stdout(&o).contains("J/m"));
    let summary: Value = serde_json::from_str(&std::fs::read_to_string(dir.path().join("summary.json")).unwrap()).unwrap();
    assert!(summary["si"]["scales"]["horizontal"].is_number());
    let csv_name = summary["curves"][0]["csv"].as_str().unwrap().to_string();
    let text = std::fs::read_to_string(dir.path().join(csv_name)).unwrap();
    let mut lines = text.lines();
    assert!(lines.next().unwrap().ends_with(",a_m,load_n_per_m,approach_m"));
    let row: Vec<f64> = lines.next().unwrap().split(',').filter_map(|v| v.parse().ok()).collect();
    let (abar, load, a_m, l_si) = (row[3], row[6], row[row.len() - 3], row[row.len() - 2]);
    assert!((a_m / (abar * lh) - 1.0).abs() < 1e-12 && (l_si / (load * load_scale) - 1.0).abs() < 1e-12);
    // profile: --half-width in m
    let mut args = vec!["profile", "--format", "json", "--sigma", "1.5e5", "--half-width", "6e-5", "--points", "20"];
    args.extend(SI);
    let p = json_of(&args);
    assert!((p["abar"].as_f64().unwrap() / (6e-5 / lh) - 1.0).abs() < 1e-12);
    assert!((p["si"]["load_n_per_m"].as_f64().unwrap() / (p["load"].as_f64().unwrap() * load_scale) - 1.0).abs() < 1e-12);
    assert!((p["si"]["half_width_m"].as_f64().unwrap() / 6e-5 - 1.0).abs() < 1e-12);
}

/// Bad SI input exits 2, names the flag, writes nothing.
#[test]
fn units_si_bad_input_names_the_flag() {
    let base = |extra: &[&'static str]| -> Vec<&'static str> {
        let mut v = vec!["curve", "--units", "si", "--e-star", "2e6", "--radius", "1e-3", "--dgamma", "0.05"];
        v.extend(extra);
        v
    };
    let cases: Vec<(Vec<&str>, &str)> = vec![
        (vec!["curve", "--sigma", "1e5"], "--sigma"),
        (vec!["curve", "--units", "cgs"], "--units"),
        (vec!["curve", "--units", "si", "--sigma", "1e5"], "--e-star"),
        (base(&[]), "--sigma"),
        (base(&["--sigma", "1e5", "--lambda", "3"]), "--lambda"),
        (base(&["--sigma", "1e5", "--alpha", "0.3"]), "--alpha"),
        (base(&["--sigma", "1e5", "--delta-c", "1e-6"]), "--delta-c"),
        (base(&["--sigma", "-1e5"]), "--sigma"),
        (base(&["--sigma", "0"]), "--sigma"),
        (base(&["--delta-c", "NaN"]), "--delta-c"),
        (base(&["--sigma", "1e25"]), "--sigma"),
        (base(&["--sigma", "1e5", "--amplitude", "1e-6"]), "--wavelength"),
        (base(&["--sigma", "1e5", "--amplitude=-1e-6", "--wavelength", "1e-5"]), "--amplitude"),
        (base(&["--sigma", "1e5", "--amplitude", "1e-6", "--wavelength", "0"]), "--wavelength"),
        (vec!["curve", "--units", "si", "--e-star", "-2e6", "--radius", "1e-3", "--dgamma", "0.05", "--sigma", "1e5"], "--e-star"),
        (vec!["curve", "--units", "si", "--e-star", "2e6", "--radius", "1e-3", "--dgamma", "0", "--sigma", "1e5"], "--dgamma"),
        (vec!["profile", "--units", "si", "--e-star", "2e6", "--radius", "1e-3", "--dgamma", "0.05", "--sigma", "1e5"], "--half-width"),
        (vec!["profile", "--units", "si", "--e-star", "2e6", "--radius", "1e-3", "--dgamma", "0.05", "--sigma", "1e5", "--abar", "2"], "--abar"),
        (vec!["profile", "--abar", "2", "--half-width", "1e-5"], "--half-width"),
        (vec!["profile", "--lambda", "1"], "--abar"),
    ];
    for (args, flag) in cases {
        let dir = TempPath::new("si-bad");
        let mut full = args.clone();
        full.insert(1, "--out");
        full.insert(2, dir.str());
        let o = maugis(&full);
        let err = stderr(&o);
        assert_eq!(o.status.code(), Some(2), "{args:?}: stderr {err}");
        assert_eq!(err.lines().count(), 1, "{args:?}: {err:?}");
        assert!(err.contains(flag), "{args:?}: does not name {flag}: {err}");
        assert!(stdout(&o).is_empty() && !dir.path().exists(), "{args:?}: wrote output");
    }
}

/// `--datum` moves the machine's grip: it reaches the schema and the
/// displacement-controlled paths, and leaves load control alone.
#[test]
fn datum_sets_the_displacement_control_grip() {
    let run = |datum: &str| -> Value {
        let o = maugis(&["curve", "--lambda", "3", "--points", "200", "--datum", datum, "--format", "json"]);
        assert_eq!(o.status.code(), Some(0), "stderr: {}", stderr(&o));
        serde_json::from_str(stdout(&o).trim()).expect("valid JSON")
    };
    let (near, far) = (run("100"), run("1e4"));
    assert_eq!(far["params"]["datum"].as_f64(), Some(1e4));
    let (c1, c2) = (&near["curves"][0], &far["curves"][0]);
    assert!((c2["displacement_control"]["datum"].as_f64().unwrap() / 1e4 - 1.0).abs() < 1e-12);
    assert_eq!(c1["dissipation"]["load_control"], c2["dissipation"]["load_control"]);
    let (w, wd1, wd2) = (
        c1["dissipation"]["load_control"].as_f64().unwrap(),
        c1["dissipation"]["displacement_control"].as_f64().unwrap(),
        c2["dissipation"]["displacement_control"].as_f64().unwrap(),
    );
    assert!(wd1 < wd2 && wd2 < w, "W = {w}, W_d(100) = {wd1}, W_d(1e4) = {wd2}");
}

/// The plot window flags and a palette that does not repeat for many curves.
#[test]
fn plot_window_and_many_curves() {
    let dir = TempPath::new("window");
    let mut args: Vec<String> = ["curve", "--points", "12", "--amin", "1", "--ymin", "-3", "--ymax", "20", "--out", dir.str()]
        .iter()
        .map(|s| s.to_string())
        .collect();
    for k in 1..=12 {
        args.push("--lambda".into());
        args.push(format!("{k}/4"));
    }
    let refs: Vec<&str> = args.iter().map(String::as_str).collect();
    let o = maugis(&refs);
    assert_eq!(o.status.code(), Some(0), "stderr: {}", stderr(&o));
    let svg = std::fs::read_to_string(dir.path().join("load-area.svg")).unwrap();
    // twelve legend entries with twelve distinct stroke colours
    let mut colours: Vec<&str> = svg
        .split("stroke=\"")
        .skip(1)
        .filter_map(|t| t.split('"').next())
        .filter(|c| c.starts_with('#'))
        .collect();
    colours.sort();
    colours.dedup();
    assert!(colours.len() >= 12 + 2, "{} colours", colours.len());
    assert!(svg.contains(">\n3</text>") || svg.contains("λ = 3"), "legend");
    let report = render::check_svg(&dir.path().join("load-area.svg"));
    assert_lambda_entries(&report, 12);
}

/// The legend of a curve plot has `n` entries `λ = ...`, each in a colour of
/// its own that is not a grey.
fn assert_lambda_entries(report: &render::Report, n: usize) {
    let mut colours = Vec::new();
    for e in report.entries().filter(|e| e.label.starts_with("λ = ")) {
        let c = e.colours.iter().find(|c| c.chromatic()).unwrap_or_else(|| panic!("{:?} has no colour: {:?}", e.label, e.colours));
        assert!(!colours.contains(&c.rgb), "{:?} repeats the colour {:?}", e.label, c.rgb);
        colours.push(c.rgb);
    }
    assert_eq!(colours.len(), n, "{report:?}");
}

/// Parameters are arithmetic expressions.
#[test]
fn parameters_accept_expressions() {
    let o = maugis(&["curve", "--lambda", "sqrt(9)", "--alpha", "2*sqrt(2)/8", "--beta", "9/8", "--points", "10", "--format", "json"]);
    assert_eq!(o.status.code(), Some(0), "stderr: {}", stderr(&o));
    let v: Value = serde_json::from_str(stdout(&o).trim()).unwrap();
    assert_eq!(v["params"]["alpha"].as_f64(), Some(2f64.sqrt() / 4.0));
    assert_eq!(v["curves"][0]["lambda"].as_f64(), Some(3.0));
    let o = maugis(&["curve", "--alpha", "sqrt(", "--format", "json"]);
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("--alpha"), "{}", stderr(&o));
}

/// summary.json and --format json are the same object (up to the CSV names).
#[test]
fn summary_json_equals_format_json() {
    let dir = TempPath::new("same");
    let args = ["curve", "--lambda", "3", "--points", "30"];
    let o = maugis(&[&args[..], &["--format", "json"]].concat());
    assert_eq!(o.status.code(), Some(0), "stderr: {}", stderr(&o));
    let mut from_stdout: Value = serde_json::from_str(stdout(&o).trim()).unwrap();
    let o = maugis(&[&args[..], &["--out", dir.str()]].concat());
    assert_eq!(o.status.code(), Some(0), "stderr: {}", stderr(&o));
    let mut from_file: Value = serde_json::from_str(&std::fs::read_to_string(dir.path().join("summary.json")).unwrap()).unwrap();
    assert_eq!(from_file["curves"][0]["csv"].as_str(), Some("curve_lambda_3.csv"));
    from_file["curves"][0]["csv"] = Value::Null;
    from_stdout["curves"][0]["csv"] = Value::Null;
    assert_eq!(from_file, from_stdout);
}

#[test]
fn curve_writes_csv_summary_and_svg() {
    let dir = TempPath::new("files");
    let o = maugis(&["curve", "--lambda", "1/2", "--lambda", "3", "--points", "40", "--out", dir.str()]);
    assert_eq!(o.status.code(), Some(0), "stderr: {}", stderr(&o));
    let out = stdout(&o);
    assert!(out.contains("summary.json") && out.contains("load-area.svg"), "{out}");
    assert!(dir.tmp_siblings().is_empty(), "temporary directory left behind");

    for (lambda, name) in [(0.5, "curve_lambda_0.5.csv"), (3.0, "curve_lambda_3.csv")] {
        let mut r = csv::Reader::from_path(dir.path().join(name)).expect(name);
        let header: Vec<String> = r.headers().unwrap().iter().map(String::from).collect();
        assert_eq!(
            header,
            ["lambda", "alpha", "beta", "abar", "m", "m_minus_1", "load", "approach", "valid", "min_strip_gap", "max_traction"]
        );
        let rows: Vec<csv::StringRecord> = r.records().map(|x| x.unwrap()).collect();
        assert_eq!(rows.len(), 40, "lambda {lambda}");
        for row in &rows {
            for (i, field) in row.iter().enumerate() {
                if i == 8 {
                    assert!(field == "true" || field == "false");
                } else {
                    field.parse::<f64>().unwrap_or_else(|_| panic!("{field}"));
                }
            }
        }
        // agrees with the library
        let params = maugis::contact::model::Params::new(lambda, 2f64.sqrt() / 4.0, 1.125).unwrap();
        assert_eq!(rows[10][0].parse::<f64>().unwrap(), lambda, "every row carries lambda");
        let a: f64 = rows[10][3].parse().unwrap();
        let s = maugis::contact::curve::state(params, a).unwrap();
        let load: f64 = rows[10][6].parse().unwrap();
        assert!((load - s.load).abs() <= 1e-12 * (1.0 + s.load.abs()), "{load} vs {}", s.load);
    }

    let summary: Value = serde_json::from_str(&std::fs::read_to_string(dir.path().join("summary.json")).unwrap()).unwrap();
    assert_eq!(summary["params"]["points"].as_u64(), Some(40));
    let curves = summary["curves"].as_array().unwrap();
    assert_eq!(curves.len(), 2);
    for c in curves {
        for k in ["lambda", "turning_points", "jumps", "pull_off", "invalid_points", "invalid_stretches"] {
            assert!(c.get(k).is_some(), "summary curve lacks {k}");
        }
        let invalid = c["invalid_points"].as_u64().unwrap();
        let in_stretches: u64 = c["invalid_stretches"].as_array().unwrap().iter().map(|s| s["points"].as_u64().unwrap()).sum();
        assert_eq!(invalid, in_stretches);
    }

    let svg = std::fs::read_to_string(dir.path().join("load-approach.svg")).unwrap();
    assert!(svg.contains("<svg") && svg.contains("approach"));
    let report = render::check_svg(&dir.path().join("load-approach.svg"));
    assert_lambda_entries(&report, 2);
    report.entry("pull-off");
    let svg = std::fs::read_to_string(dir.path().join("load-area.svg")).unwrap();
    assert!(svg.len() > 1000 && svg.contains("<svg"));
    assert!(svg.contains("contact half-width abar") && svg.contains("load Lbar"));
    let report = render::check_svg(&dir.path().join("load-area.svg"));
    assert_lambda_entries(&report, 2);
    for label in ["turning point: load maximum", "turning point: load minimum", "pull-off", "JKR limit λ→∞ (E.42a)"] {
        report.entry(label);
    }

    // A second run into the existing directory replaces the folder: no stale files.
    let o = maugis(&["curve", "--lambda", "3", "--points", "20", "--out", dir.str()]);
    assert_eq!(o.status.code(), Some(0), "stderr: {}", stderr(&o));
    let r = csv::Reader::from_path(dir.path().join("curve_lambda_3.csv")).unwrap();
    assert_eq!(r.into_records().count(), 20);
    assert!(!dir.path().join("curve_lambda_0.5.csv").exists(), "stale CSV of the first run");
    assert!(dir.tmp_siblings().is_empty());
    // a non-empty folder maugis did not write is refused, untouched
    let foreign = TempPath::new("foreign");
    std::fs::create_dir(foreign.path()).unwrap();
    std::fs::write(foreign.path().join("notes.txt"), "mine").unwrap();
    let o = maugis(&["curve", "--lambda", "3", "--points", "20", "--out", foreign.str()]);
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("--out"), "{}", stderr(&o));
    assert_eq!(std::fs::read_dir(foreign.path()).unwrap().count(), 1);
}

#[test]
fn bad_parameters_exit_2_with_one_line_and_no_files() {
    let cases: &[&[&str]] = &[
        &["curve", "--lambda", "0"],
        &["curve", "--alpha", "-1"],
        &["curve", "--beta", "0"],
        &["curve", "--amax", "0"],
        &["curve", "--points", "1"],
        &["curve", "--lambda", "NaN"],
        &["curve", "--lambda", "inf"],
        &["curve", "--bogus"],
        &["curve", "--lambda"],
        &["curve", "--format", "xml"],
        &["curve", "--amax", "1e300"],
        &["curve", "--beta", "1e-9"],
        &["profile", "--lambda", "1"],
        &["profile", "--abar", "0"],
        &["profile", "--abar", "2", "--beta", "-3"],
        &["limits", "--amax", "-1"],
        &["limits", "--points", "1"],
        &["curve", "--alpha", "sqrt("],
        &["curve", "--beta", "sqrt(-1)"],
        &["curve", "--lambda", "2 +"],
        &["curve", "--amin", "7"],
        &["curve", "--ymin", "3", "--ymax", "1"],
        &["curve", "--ymax", "NaN"],
        &["curve", "--amin", "-1"],
        &["curve", "--datum", "0"],
        &["curve", "--datum", "-3"],
        &["sweep", "--lambda-min", "0"],
        &["sweep", "--lambda-min", "2", "--lambda-max", "1"],
        &["sweep", "--lambda-n", "0"],
        &["sweep", "--n", "20000"],
        &["sweep", "--axis", "gamma"],
        &["sweep", "--min", "-1"],
        &["sweep", "--min", "0.5", "--max", "0.1"],
        &["sweep", "--axis", "beta", "--min", "0"],
        &["sweep", "--shard", "0/2"],
        &["sweep", "--shard", "3/2"],
        &["sweep", "--shard", "x"],
        &["sweep", "--points", "1"],
        &["merge"],
        &["frobnicate"],
    ];
    for args in cases {
        let dir = TempPath::new("bad");
        let mut full: Vec<&str> = args.to_vec();
        // put --out first so a missing value at the end stays missing
        full.insert(1, "--out");
        full.insert(2, dir.str());
        if args[0] == "frobnicate" {
            full.truncate(1);
        }
        let o = maugis(&full);
        let err = stderr(&o);
        assert_eq!(o.status.code(), Some(2), "{args:?}: stderr {err}");
        assert_eq!(err.lines().count(), 1, "{args:?}: not one line: {err:?}");
        assert!(err.starts_with("maugis: "), "{args:?}: {err}");
        assert!(stdout(&o).is_empty(), "{args:?}: stdout {}", stdout(&o));
        assert!(!dir.path().exists(), "{args:?}: created the output directory");
        assert!(dir.tmp_siblings().is_empty(), "{args:?}: left a temporary directory");
        if args[0] == "sweep" || args.iter().any(|a| ["--amin", "--ymin", "--ymax", "--alpha", "--beta", "--datum"].contains(a)) {
            let flag = args.iter().rev().find(|a| a.starts_with("--")).unwrap();
            assert!(err.contains(flag), "{args:?}: the message does not name {flag}: {err}");
        }
    }
}

/// A small regime map; two shards merged equal the unsharded run.
#[test]
fn sweep_writes_a_map_and_shards_merge_to_the_whole() {
    let grid = ["--lambda-min", "0.5", "--lambda-max", "6", "--lambda-n", "3", "--n", "3", "--points", "60"];
    let whole = TempPath::new("sweep");
    let o = maugis(&[&["sweep"][..], &grid, &["--out", whole.str()]].concat());
    assert_eq!(o.status.code(), Some(0), "stderr: {}", stderr(&o));
    let mut r = csv::Reader::from_path(whole.path().join("sweep.csv")).unwrap();
    let header: Vec<String> = r.headers().unwrap().iter().map(String::from).collect();
    assert_eq!(header[..3], ["index", "lambda", "value"]);
    let rows: Vec<csv::StringRecord> = r.records().map(|x| x.unwrap()).collect();
    assert_eq!(rows.len(), 9);
    let col = |name: &str| header.iter().position(|h| h == name).unwrap_or_else(|| panic!("no column {name}"));
    for row in &rows {
        let regime = &row[col("regime")];
        assert!(["dissipative", "cavitating", "smooth_like"].contains(&regime), "{regime}");
        // A valid pull-off state is (up to the grid) the most tensile valid state.
        if &row[col("pull_off_valid")] == "true" {
            let p: f64 = row[col("pull_off")].parse().unwrap();
            let v: f64 = row[col("valid_pull_off")].parse().expect("a valid pull-off has a valid_pull_off");
            assert!((v - p).abs() <= 0.05, "valid_pull_off {v} vs valid pull_off {p}");
        }
    }
    let svg = std::fs::read_to_string(whole.path().join("sweep.svg")).unwrap();
    assert!(svg.contains("<svg") && svg.contains("dissipative"));
    // the regimes' swatches in distinct colours
    let report = render::check_svg(&whole.path().join("sweep.svg"));
    let fill = |label: &str| report.entry(label).colours[0].rgb;
    let regimes = ["dissipative: valid loops", "cavitating: loops through invalid states", "smooth-like: no roughness-induced loop"].map(fill);
    assert!(regimes[0] != regimes[1] && regimes[1] != regimes[2] && regimes[0] != regimes[2], "{regimes:?}");

    let (s1, s2, merged) = (TempPath::new("shard1"), TempPath::new("shard2"), TempPath::new("merged"));
    for (sh, dir) in [("1/2", &s1), ("2/2", &s2)] {
        let o = maugis(&[&["sweep"][..], &grid, &["--shard", sh, "--out", dir.str()]].concat());
        assert_eq!(o.status.code(), Some(0), "stderr: {}", stderr(&o));
        assert!(!dir.path().join("sweep.svg").exists(), "a shard draws no map");
    }
    // one shard alone does not merge
    let o = maugis(&["merge", s1.str(), "--out", merged.str()]);
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("missing") && !merged.path().exists());
    let o = maugis(&["merge", s2.str(), s1.str(), "--out", merged.str()]);
    assert_eq!(o.status.code(), Some(0), "stderr: {}", stderr(&o));
    let read = |d: &TempPath| -> Value { serde_json::from_str(&std::fs::read_to_string(d.path().join("sweep.json")).unwrap()).unwrap() };
    assert_eq!(read(&merged), read(&whole));
    assert_eq!(
        std::fs::read_to_string(merged.path().join("sweep.csv")).unwrap(),
        std::fs::read_to_string(whole.path().join("sweep.csv")).unwrap()
    );
}

/// `maugis sweep --solver` on a small grid (1024 cells, 100 steps: about a
/// second): the CSV columns, the side-by-side SVG (rendered, legend checked),
/// two shards merged equal the whole; bad flags exit 2 with no files.
#[test]
fn solver_sweep_writes_both_maps_and_shards_merge_to_the_whole() {
    let grid = [
        "--solver", "--lambda-min", "1", "--lambda-max", "6", "--lambda-n", "2", "--n", "2", "--max", "0.35", "--points", "60", "--cells",
        "1024", "--steps", "100",
    ];
    let whole = TempPath::new("solver-map");
    let o = maugis(&[&["sweep"][..], &grid, &["--out", whole.str()]].concat());
    assert_eq!(o.status.code(), Some(0), "stderr: {}", stderr(&o));
    assert!(stdout(&o).contains("the model's label agrees at"), "{}", stdout(&o));
    let mut r = csv::Reader::from_path(whole.path().join("sweep.csv")).unwrap();
    let header: Vec<String> = r.headers().unwrap().iter().map(String::from).collect();
    let col = |name: &str| header.iter().position(|h| h == name).unwrap_or_else(|| panic!("no column {name}"));
    let rows: Vec<csv::StringRecord> = r.records().map(|x| x.unwrap()).collect();
    assert_eq!(rows.len(), 4);
    for row in &rows {
        for c in ["lambda", "alpha", "beta", "w_solver", "w_model"] {
            row[col(c)].parse::<f64>().unwrap_or_else(|_| panic!("{c}: {:?}", &row[col(c)]));
        }
        assert!(["dissipative", "both", "cavitating", "smooth_like"].contains(&&row[col("regime_solver")]), "{row:?}");
        assert!(["dissipative", "cavitating", "smooth_like"].contains(&&row[col("regime_model")]), "{row:?}");
        assert_eq!(&row[col("cells")], "1024");
    }
    let report = render::check_svg(&whole.path().join("sweep.svg"));
    let fill = |label: &str| report.entry(label).colours[0].rgb;
    let labels = [
        "dissipative: W above the smooth cylinder's by > 0.02 (model: a valid loop)",
        "both: dissipative and cavitated states (solver only)",
        "cavitating: cavitated states, no dissipation (model: loops, all invalid)",
    ];
    let colours = labels.map(fill);
    assert!(colours[0] != colours[1] && colours[1] != colours[2] && colours[0] != colours[2], "{colours:?}");
    let disagreeing = rows.iter().filter(|r| &r[col("agree")] == "false").count();
    report.entry(&format!("labels disagree ({disagreeing} of 4 points)"));

    let (s1, s2, merged) = (TempPath::new("smap1"), TempPath::new("smap2"), TempPath::new("smerged"));
    for (sh, dir) in [("1/2", &s1), ("2/2", &s2)] {
        let o = maugis(&[&["sweep"][..], &grid, &["--shard", sh, "--out", dir.str()]].concat());
        assert_eq!(o.status.code(), Some(0), "stderr: {}", stderr(&o));
        assert!(!dir.path().join("sweep.svg").exists(), "a shard draws no map");
    }
    let o = maugis(&["merge", s2.str(), s1.str(), "--out", merged.str()]);
    assert_eq!(o.status.code(), Some(0), "stderr: {}", stderr(&o));
    for f in ["sweep.json", "sweep.csv", "sweep.svg"] {
        let read = |d: &TempPath| std::fs::read_to_string(d.path().join(f)).unwrap();
        assert_eq!(read(&merged), read(&whole), "{f}");
    }
    // a model sweep does not merge with a solver map
    let model = TempPath::new("smodel");
    let o = maugis(&["sweep", "--lambda-n", "1", "--n", "1", "--points", "30", "--shard", "1/2", "--out", model.str()]);
    assert_eq!(o.status.code(), Some(0), "stderr: {}", stderr(&o));
    let mixed = TempPath::new("smixed");
    let o = maugis(&["merge", s1.str(), model.str(), "--out", mixed.str()]);
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("solver maps") && !mixed.path().exists(), "{}", stderr(&o));

    let bad: &[&[&str]] = &[
        &["--solver", "--margin", "-1"],
        &["--margin", "0.1"],
        &["--solver", "--cells", "1024"],
        &["--solver", "--cells", "1000", "--steps", "100"],
        &["--solver", "--cells", "1024", "--steps", "1"],
        &["--solver", "--shard", "3/2"],
    ];
    for args in bad {
        let dir = TempPath::new("sbad");
        let o = maugis(&[&["sweep", "--lambda-n", "1", "--n", "1", "--out", dir.str()][..], args].concat());
        assert_eq!(o.status.code(), Some(2), "{args:?}: {}", stderr(&o));
        assert_eq!(stderr(&o).lines().count(), 1, "{args:?}: {}", stderr(&o));
        assert!(!dir.path().exists() && dir.tmp_siblings().is_empty(), "{args:?}: wrote files");
    }
}

#[test]
fn out_that_is_a_file_is_refused_before_computing() {
    let file = TempPath::new("file");
    std::fs::write(file.path(), "not a directory").unwrap();
    let o = maugis(&["curve", "--lambda", "1", "--points", "10", "--out", file.str()]);
    assert_eq!(o.status.code(), Some(2));
    assert_eq!(stderr(&o).lines().count(), 1);
    assert_eq!(std::fs::read_to_string(file.path()).unwrap(), "not a directory");
    let _ = std::fs::remove_file(file.path());
}

#[test]
fn profile_writes_csv_and_svg() {
    let dir = TempPath::new("profile");
    let o = maugis(&["profile", "--abar", "2.71", "--lambda", "6", "--points", "50", "--out", dir.str()]);
    assert_eq!(o.status.code(), Some(0), "stderr: {}", stderr(&o));
    let mut r = csv::Reader::from_path(dir.path().join("profile.csv")).unwrap();
    let header: Vec<String> = r.headers().unwrap().iter().map(String::from).collect();
    assert_eq!(header, ["xbar", "pbar", "ubar", "gbar", "hbar"]);
    let rows: Vec<Vec<f64>> = r.records().map(|x| x.unwrap().iter().map(|f| f.parse::<f64>().unwrap()).collect()).collect();
    assert!(rows.len() >= 50);
    assert_eq!(rows[0][0], 0.0);
    // edge x = abar is sampled; the gap vanishes inside the contact, pbar = 1 in the strip
    assert!(rows.iter().any(|r| r[0] == 2.71));
    for r in &rows {
        if r[0] <= 2.71 {
            assert_eq!(r[3], 0.0);
        }
    }
    assert!(rows.iter().any(|r| r[0] > 2.71 && r[1] == 1.0));
    let svg = std::fs::read_to_string(dir.path().join("profile.svg")).unwrap();
    assert!(svg.contains("<svg") && svg.contains("valid"));
    // three panels, each with its own legend
    let report = render::check_svg(&dir.path().join("profile.svg"));
    assert_eq!(report.legends.len(), 3, "{report:?}");
    assert!(report.entry("traction p̄").colours.iter().any(|c| c.chromatic()));
    assert!(dir.tmp_siblings().is_empty());

    let o = maugis(&["profile", "--abar", "3", "--points", "20", "--format", "json"]);
    assert_eq!(o.status.code(), Some(0));
    let v: Value = serde_json::from_str(stdout(&o).trim()).unwrap();
    assert!(v["m"].as_f64().unwrap() > 1.0 && v["valid"].is_boolean());
    assert!(v["samples"].as_array().unwrap().len() >= 20);
}

#[test]
fn limits_write_csv_and_svg_or_print() {
    let dir = TempPath::new("limits");
    let o = maugis(&["limits", "--points", "30", "--out", dir.str()]);
    assert_eq!(o.status.code(), Some(0), "stderr: {}", stderr(&o));
    let mut r = csv::Reader::from_path(dir.path().join("limits.csv")).unwrap();
    let header: Vec<String> = r.headers().unwrap().iter().map(String::from).collect();
    assert_eq!(
        header,
        [
            "abar",
            "jkr",
            "jkr_env_lower",
            "jkr_env_upper",
            "mdmt",
            "mdmt_env_lower",
            "mdmt_env_upper",
            "smooth_mdmt",
            "local_env_lower",
            "local_env_upper"
        ]
    );
    let rows: Vec<Vec<f64>> = r.records().map(|x| x.unwrap().iter().map(|f| f.parse::<f64>().unwrap()).collect()).collect();
    assert_eq!(rows.len(), 30);
    for row in &rows {
        assert!(row[2] <= row[3] && row[5] <= row[6] && row[8] <= row[9]);
        // E.44 at abar: pi a^2/4 - 2 sqrt(2 lambda), lambda = 1/10 by default
        let a = row[0];
        assert!((row[7] - (std::f64::consts::PI * a * a / 4.0 - 2.0 * 0.2f64.sqrt())).abs() < 1e-12);
    }
    assert!(std::fs::read_to_string(dir.path().join("limits.svg")).unwrap().contains("<svg"));
    let report = render::check_svg(&dir.path().join("limits.svg"));
    assert!(report.entry("local envelope, λ = 0.1 (Eq. 17)").colours.iter().any(|c| c.chromatic()));

    let o = maugis(&["limits", "--points", "5", "--format", "json"]);
    assert_eq!(o.status.code(), Some(0));
    let v: Value = serde_json::from_str(stdout(&o).trim()).unwrap();
    assert_eq!(v["rows"].as_array().unwrap().len(), 5);
    let o = maugis(&["limits", "--points", "5", "--format", "csv"]);
    assert_eq!(o.status.code(), Some(0));
    assert_eq!(stdout(&o).lines().count(), 6);
}
