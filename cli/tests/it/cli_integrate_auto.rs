//! `maugis integrate` and `eval`'s `integrate` request without declarations (issue
//! 36): infinite ends, oscillatory tails and singular ends found from the expression.
//! References: `reference/data/integrals_infinite.csv`
//! (`reference/generate_infinite_integrals.py`).

use std::io::Write;
use std::process::{Command, Stdio};

use rug::Float;
use serde_json::Value;

fn reference(id: &str) -> Float {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/../reference/data/integrals_infinite.csv");
    let table = std::fs::read_to_string(path).expect("reference/data/integrals_infinite.csv");
    let line = table.lines().find(|l| l.starts_with(&format!("{id},"))).unwrap_or_else(|| panic!("no row {id}"));
    Float::with_val(1400, Float::parse(line.rsplit(',').next().unwrap()).unwrap())
}

fn contains(mid: &str, rad: &str, exact: &Float) -> bool {
    let p = exact.prec();
    let mid = Float::with_val(p, Float::parse(mid).unwrap());
    let rad = Float::with_val(p, Float::parse(rad).unwrap());
    Float::with_val(p, &mid - exact).abs() <= rad
}

fn field<'a>(stdout: &'a str, key: &str) -> &'a str {
    stdout.lines().find_map(|l| l.strip_prefix(key).and_then(|r| r.strip_prefix(": "))).unwrap_or_else(|| panic!("no {key} in {stdout}"))
}

#[test]
fn integrate_answers_infinite_ranges_as_typed() {
    for (args, id) in [
        (["exp(-x)/(1+x)", "0", "inf"], "exp_over_1px"),
        (["x^2*exp(-x^2)", "-inf", "inf"], "x2_gauss"),
        (["1/(1+x^2)", "0", "inf"], "lorentz_half"),
        (["sin(x)/x", "0", "inf"], "sinc"),
    ] {
        let out = Command::new(env!("CARGO_BIN_EXE_maugis")).arg("integrate").args(args).args(["--prec", "64"]).output().unwrap();
        let stdout = String::from_utf8(out.stdout).unwrap();
        assert_eq!(out.status.code(), Some(0), "{args:?}: {}", String::from_utf8_lossy(&out.stderr));
        assert!(out.stderr.is_empty(), "{args:?}: {}", String::from_utf8_lossy(&out.stderr));
        assert!(contains(field(&stdout, "mid"), field(&stdout, "rad"), &reference(id)), "{args:?}: {stdout}");
    }
}

#[test]
fn integrate_refuses_a_divergent_tail_with_exit_2() {
    let out = Command::new(env!("CARGO_BIN_EXE_maugis")).args(["integrate", "1/x", "1", "inf"]).output().unwrap();
    assert_eq!(out.status.code(), Some(2));
    assert!(out.stdout.is_empty());
    let err = String::from_utf8(out.stderr).unwrap();
    assert!(err.contains("not absolutely integrable"), "{err}");
}

#[test]
fn eval_requests_take_infinite_ends() {
    let mut child = Command::new(env!("CARGO_BIN_EXE_maugis")).arg("eval").stdin(Stdio::piped()).stdout(Stdio::piped()).spawn().unwrap();
    let input = concat!(
        r#"{"id":1,"fn":"integrate","f":"besselj(0, x)","a":0,"b":"inf","prec":64}"#,
        "\n",
        r#"{"id":2,"fn":"integrate","f":"x^2*exp(-x^2)","a":"-inf","b":"inf","prec":64}"#,
        "\n",
    );
    child.stdin.take().unwrap().write_all(input.as_bytes()).unwrap();
    let out = child.wait_with_output().unwrap();
    let lines: Vec<Value> = String::from_utf8(out.stdout).unwrap().lines().map(|l| serde_json::from_str(l).unwrap()).collect();
    for (r, id) in lines.iter().zip(["j0", "x2_gauss"]) {
        assert!(r.get("error").is_none(), "{r}");
        assert!(contains(r["mid"].as_str().unwrap(), r["rad"].as_str().unwrap(), &reference(id)), "{r}");
    }
    assert_eq!(lines.len(), 2);
}

/// A zero integral answers under the default absolute tolerance, which both front ends
/// print (`abs_tol`), and the ball contains 0 (issue 40, item 3).
#[test]
fn zero_integral_reports_its_absolute_tolerance() {
    let zero = Float::new(64);
    let out = Command::new(env!("CARGO_BIN_EXE_maugis")).args(["integrate", "sin(x)", "-1", "1", "--prec", "64"]).output().unwrap();
    let stdout = String::from_utf8(out.stdout).unwrap();
    assert_eq!(out.status.code(), Some(0), "{}", String::from_utf8_lossy(&out.stderr));
    assert!(out.stderr.is_empty(), "{}", String::from_utf8_lossy(&out.stderr));
    assert!(contains(field(&stdout, "mid"), field(&stdout, "rad"), &zero), "{stdout}");
    let tol: f64 = field(&stdout, "abs_tol").parse().unwrap();
    let rad: f64 = field(&stdout, "rad").parse().unwrap();
    assert!(rad <= tol && tol < 4.0 * 2f64.powi(-64), "{stdout}");

    let mut child = Command::new(env!("CARGO_BIN_EXE_maugis")).arg("eval").stdin(Stdio::piped()).stdout(Stdio::piped()).spawn().unwrap();
    let input = concat!(r#"{"id":1,"fn":"integrate","f":"atan(tanh(tanh(x)))","a":-3,"b":3,"prec":64}"#, "\n", r#"{"id":2,"fn":"integrate","f":"exp(x)","a":0,"b":1,"prec":64}"#, "\n");
    child.stdin.take().unwrap().write_all(input.as_bytes()).unwrap();
    let out = child.wait_with_output().unwrap();
    let lines: Vec<Value> = String::from_utf8(out.stdout).unwrap().lines().map(|l| serde_json::from_str(l).unwrap()).collect();
    assert_eq!(lines.len(), 2);
    assert!(lines[0].get("goal_met").is_none(), "{}", lines[0]);
    assert!(contains(lines[0]["mid"].as_str().unwrap(), lines[0]["rad"].as_str().unwrap(), &zero), "{}", lines[0]);
    assert!(lines[0]["abs_tol"].as_str().is_some_and(|t| t.parse::<f64>().unwrap() < 8.0 * 2f64.powi(-64)), "{}", lines[0]);
    // a nonzero integral meets the relative goal and has no abs_tol
    assert!(lines[1].get("abs_tol").is_none(), "{}", lines[1]);
}
