//! `maugis integrate` and the `integrate` request of `maugis eval`, end to end.

use std::io::Write;
use std::process::{Command, Stdio};

use rug::Float;
use serde_json::Value;

/// Runs `maugis integrate ARGS`: (stdout, stderr, exit code).
fn integrate(args: &[&str]) -> (String, String, i32) {
    let out = Command::new(env!("CARGO_BIN_EXE_maugis")).arg("integrate").args(args).output().expect("run maugis");
    (String::from_utf8(out.stdout).unwrap(), String::from_utf8(out.stderr).unwrap(), out.status.code().unwrap_or(-1))
}

/// The value of `key: value` in the printed output.
fn field<'a>(stdout: &'a str, key: &str) -> Option<&'a str> {
    stdout.lines().find_map(|l| l.strip_prefix(key).and_then(|r| r.strip_prefix(": ")))
}

/// Whether the printed ball `mid +/- rad` contains `exact`.
fn contains(mid: &str, rad: &str, exact: &Float) -> bool {
    let p = exact.prec();
    let mid = Float::with_val(p, Float::parse(mid).unwrap());
    let rad = Float::with_val(p, Float::parse(rad).unwrap());
    Float::with_val(p, &mid - exact).abs() <= rad
}

/// An exact value from decimal text, at 512 bits.
fn exact(text: &str) -> Float {
    Float::with_val(512, Float::parse(text).unwrap())
}

/// The value of row `id` of `reference/data/integrals.csv` (`reference/generate_integrals.py`:
/// the closed form by mpmath at 3500 digits), at 512 bits.
fn golden(id: &str) -> Float {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/../reference/data/integrals.csv");
    let table = std::fs::read_to_string(path).expect("reference/data/integrals.csv");
    let line = table.lines().find(|l| l.starts_with(&format!("{id},"))).unwrap_or_else(|| panic!("no row {id}"));
    exact(line.rsplit(',').next().unwrap())
}

/// `int_0^inf exp(-x^2) dx = sqrt(pi)/2`, at 512 bits.
fn half_sqrt_pi() -> Float {
    Float::with_val(512, rug::float::Constant::Pi).sqrt() / 2u32
}

#[test]
fn sqrt_over_one_to_four_contains_fourteen_thirds() {
    let (out, err, code) = integrate(&["sqrt(x)", "1", "4", "--prec", "128"]);
    assert_eq!(code, 0, "{err}");
    assert!(err.is_empty(), "{err}");
    let (mid, rad) = (field(&out, "mid").unwrap(), field(&out, "rad").unwrap());
    let third = Float::with_val(512, 14) / 3u32;
    assert!(contains(mid, rad, &third), "{out}");
    assert!(Float::with_val(64, Float::parse(rad).unwrap()) <= Float::with_val(64, 1e-38), "{out}");
    // a real integrand: no imaginary part printed
    assert!(field(&out, "im_mid").is_none(), "{out}");
}

#[test]
fn endpoint_weight_and_infinite_range() {
    // x^(-1/2) cos(x) over [0, 1] = sqrt(2 pi) C(sqrt(2/pi)), written as cos(x) with alpha = -0.5
    let (out, err, code) = integrate(&["cos(x)", "0", "1", "--alpha", "-0.5", "--prec", "64"]);
    assert_eq!(code, 0, "{err}");
    let want = golden("Xcos_rsqrt");
    assert!(contains(field(&out, "mid").unwrap(), field(&out, "rad").unwrap(), &want), "{out}");
    // exp(-x^2) over [0, inf) = sqrt(pi)/2, declared |f| <= e^(1/4) e^(-x)
    let args = ["exp(-x^2)", "0", "inf", "--decay-rate", "1", "--decay-bound", "1.2841", "--prec", "128"];
    let (out, err, code) = integrate(&args);
    assert_eq!(code, 0, "{err}");
    let want = half_sqrt_pi();
    assert!(contains(field(&out, "mid").unwrap(), field(&out, "rad").unwrap(), &want), "{out}");
    // a leading minus in the expression and a negative end
    let (out, err, code) = integrate(&["-x^2", "-1", "1"]);
    assert_eq!(code, 0, "{err}");
    assert!(contains(field(&out, "mid").unwrap(), field(&out, "rad").unwrap(), &(Float::with_val(512, -2) / 3u32)), "{out}");
}

#[test]
fn bad_input_exits_2_with_one_line_and_prints_nothing() {
    let cases: [(&[&str], &str); 11] = [
        (&["foo(x)", "0", "1"], "unknown function 'foo'"),
        (&["x^", "0", "1"], "syntax error at character 3"),
        (&["", "0", "1"], "empty"),
        (&["besselj(1.5, x)", "0", "1"], "order of besselj"),
        (&["besselj(x)", "0", "1"], "takes 2 arguments"),
        (&["y + 1", "0", "1"], "unknown name 'y'"),
        (&["x", "0", "1x"], "not a decimal"),
        (&["x", "0", "inf"], "decay"),
        (&["x", "0", "1", "--prec", "1"], "--prec"),
        (&["1/x", "-1", "1"], "not bounded"),
        (&["1", "0", "1", "--alpha", "-1"], "alpha"),
    ];
    for (args, needle) in cases {
        let (out, err, code) = integrate(args);
        assert_eq!(code, 2, "{args:?}: {out} {err}");
        assert!(out.is_empty(), "{args:?} printed {out}");
        assert_eq!(err.lines().count(), 1, "{args:?}: {err}");
        assert!(err.starts_with("maugis: ") && err.contains(needle), "{args:?}: {err}");
    }
}

fn eval_lines(input: &str) -> Vec<Value> {
    let mut child = Command::new(env!("CARGO_BIN_EXE_maugis"))
        .arg("eval")
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .spawn()
        .expect("spawn maugis");
    child.stdin.take().unwrap().write_all(input.as_bytes()).unwrap();
    let out = child.wait_with_output().unwrap();
    String::from_utf8(out.stdout).unwrap().lines().map(|l| serde_json::from_str(l).unwrap()).collect()
}

#[test]
fn eval_requests_answer_mid_and_rad() {
    let input = concat!(
        r#"{"id":1,"fn":"integrate","f":"sqrt(x)","a":"1","b":"4","prec":128}"#,
        "\n",
        r#"{"id":2,"fn":"integrate","f":"cos(x)","a":0,"b":1,"prec":64,"weight":{"alpha":-0.5}}"#,
        "\n",
        r#"{"id":3,"fn":"integrate","f":"exp(-x^2)","a":0,"b":"inf","decay":{"rate":1,"bound":1.2841},"prec":200}"#,
        "\n",
        r#"{"id":4,"fn":"integrate","f":"1","a":0,"b":1,"weight":{"log":2}}"#,
        "\n",
        r#"{"id":5,"fn":"integrate","f":"foo(x)","a":0,"b":1}"#,
        "\n",
        r#"{"id":6,"fn":"integrate","f":"x","a":0,"b":"inf"}"#,
        "\n",
        r#"{"id":7,"fn":"integrate","f":"x","a":0,"b":1,"weight":{"gamma":1}}"#,
        "\n",
        r#"{"id":8,"fn":"integrate","f":"x","a":0,"b":1,"decay":{"rate":1,"power":2,"bound":1}}"#,
        "\n",
    );
    let out = eval_lines(input);
    assert_eq!(out.len(), 8);
    let ball = |r: &Value, want: &Float| {
        assert!(r.get("error").is_none(), "{r}");
        assert!(contains(r["mid"].as_str().unwrap(), r["rad"].as_str().unwrap(), want), "{r}");
    };
    ball(&out[0], &(Float::with_val(512, 14) / 3u32));
    assert_eq!(out[0]["prec"], 128);
    assert!(out[0]["evaluations"].as_u64().unwrap() > 0);
    ball(&out[1], &golden("Xcos_rsqrt"));
    ball(&out[2], &half_sqrt_pi());
    ball(&out[3], &exact("2"));
    assert_eq!(out[3]["prec"], 53);
    for (r, needle) in out[4..].iter().zip(["unknown function 'foo'", "decay", "\"gamma\"", "one of \"rate\""]) {
        let e = r["error"].as_str().unwrap_or_else(|| panic!("{r}"));
        assert!(e.contains(needle), "{e}");
    }
}

/// `--budget-ms`: `int_0^300 sin(x^2)` at 1000 bits takes seconds; under 20 ms it stops
/// with code 2, one line naming the evaluations reached and nothing on stdout; a bad
/// budget is refused while the command line is parsed; a generous one changes no digit.
#[test]
fn budget_ms_refuses_with_code_two_and_never_changes_an_answer() {
    let (out, err, code) = integrate(&["sin(x^2)", "0", "300", "--prec", "1000", "--budget-ms", "20"]);
    assert_eq!(code, 2, "{out}{err}");
    assert!(out.is_empty(), "{out}");
    assert!(err.contains("evaluations"), "{err}");
    for bad in ["0", "-5", "1.5", "x"] {
        let (out, err, code) = integrate(&["x", "0", "1", "--budget-ms", bad]);
        assert_eq!(code, 2, "--budget-ms {bad}: {out}{err}");
        assert!(out.is_empty() && err.contains("budget"), "--budget-ms {bad}: {err}");
    }
    let plain = integrate(&["exp(-x^2)", "0", "2", "--prec", "200"]);
    let generous = integrate(&["exp(-x^2)", "0", "2", "--prec", "200", "--budget-ms", "600000"]);
    assert_eq!(plain.2, 0, "{}", plain.1);
    assert_eq!(plain, generous);
}
