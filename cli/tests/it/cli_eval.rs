//! `maugis eval` end to end: the protocol, certified output, and bad lines.

use std::io::Write;
use std::process::{Command, Stdio};

use rug::Float;
use serde_json::Value;

/// `maugis eval` with its three streams piped.
fn eval_command() -> Command {
    let mut cmd = Command::new(env!("CARGO_BIN_EXE_maugis"));
    cmd.arg("eval").stdin(Stdio::piped()).stdout(Stdio::piped()).stderr(Stdio::piped());
    cmd
}

fn eval_lines(input: &str) -> (Vec<Value>, i32) {
    let mut child = eval_command().spawn().expect("spawn maugis");
    child.stdin.take().unwrap().write_all(input.as_bytes()).unwrap();
    let out = child.wait_with_output().unwrap();
    let text = String::from_utf8(out.stdout).unwrap();
    let values = text.lines().map(|l| serde_json::from_str(l).expect("each output line is JSON")).collect();
    (values, out.status.code().unwrap_or(-1))
}

#[test]
fn issue_example_prints_a_certified_ball() {
    let (out, code) = eval_lines("{\"id\":1,\"fn\":\"bessel_j\",\"n\":5,\"x\":\"2.5\",\"prec\":200}\n");
    assert_eq!(code, 0);
    assert_eq!(out.len(), 1);
    let r = &out[0];
    assert_eq!(r["id"], 1);
    assert_eq!(r["prec"], 200);
    let mid = r["mid"].as_str().unwrap();
    let rad = Float::with_val(64, Float::parse(r["rad"].as_str().unwrap()).unwrap());
    // at least prec*log10(2)+3 = 64 significant digits
    let digits = mid.split('e').next().unwrap().chars().filter(|c| c.is_ascii_digit()).count();
    assert!(digits >= 64, "{mid}");
    // The printed ball is certified: it agrees with the library's ball.
    let lib = maugis::special::bessel_j::bessel_j_mp(5, &Float::with_val(53, 2.5), 200).unwrap();
    let m = Float::with_val(300, Float::parse(mid).unwrap());
    assert!(Float::with_val(300, &m - lib.mid()).abs() <= Float::with_val(300, &rad + lib.rad()));
    assert!(rad <= Float::with_val(64, 1e-59));
}

#[test]
fn f64_path_and_order() {
    let input = concat!(
        "{\"id\":\"a\",\"fn\":\"bessel_j\",\"n\":0,\"x\":1}\n",
        "{\"id\":\"b\",\"fn\":\"meijer_g_k\",\"k\":1,\"y\":1}\n",
        "{\"id\":\"c\",\"fn\":\"hyp1f2\",\"a\":0.5,\"b1\":1,\"b2\":1.5,\"z\":-300}\n",
        "{\"id\":\"d\",\"fn\":\"hyp2f1\",\"a\":1,\"b\":1,\"c\":2,\"z\":0.5}\n",
    );
    let (out, code) = eval_lines(input);
    assert_eq!(code, 0);
    let ids: Vec<&str> = out.iter().map(|v| v["id"].as_str().unwrap()).collect();
    assert_eq!(ids, ["a", "b", "c", "d"]);
    let j0 = out[0]["f64"].as_f64().unwrap();
    assert_eq!(j0, maugis::special::bessel_j::bessel_j(0, 1.0).unwrap());
    assert_eq!(out[1]["f64"].as_f64().unwrap(), 0.0);
    // 2F1(1,1;2;1/2) = 2 ln 2
    let v = out[3]["f64"].as_f64().unwrap();
    assert!(approx::relative_eq!(v, 2.0 * std::f64::consts::LN_2, max_relative = 1e-15));
}

#[test]
fn bad_lines_get_errors_and_the_stream_goes_on() {
    let bad = [
        "not json",
        "[1,2]",
        "{\"id\":2}",
        "{\"id\":3,\"fn\":\"nope\"}",
        "{\"id\":4,\"fn\":\"bessel_j\",\"n\":1}",
        "{\"id\":5,\"fn\":\"bessel_j\",\"n\":1,\"x\":\"NaN\"}",
        "{\"id\":6,\"fn\":\"bessel_j\",\"n\":1,\"x\":1,\"prec\":1}",
        "{\"id\":7,\"fn\":\"bessel_j\",\"n\":1,\"x\":1,\"prec\":100000000}",
        "{\"id\":8,\"fn\":\"bessel_j\",\"n\":1.5,\"x\":1}",
        "{\"id\":9,\"fn\":\"meijer_g_k\",\"k\":-1,\"y\":0.5}",
        "{\"id\":10,\"fn\":\"meijer_g_k\",\"k\":1,\"y\":2}",
        "{\"id\":11,\"fn\":\"hyp2f1\",\"a\":1,\"b\":1,\"c\":2,\"z\":1.5}",
        "{\"id\":12,\"fn\":\"hyp1f2\",\"a\":1,\"b1\":-2,\"b2\":1,\"z\":1}",
        "{\"id\":13,\"fn\":\"bessel_j\",\"n\":1,\"x\":1,\"typo\":3}",
        "{\"id\":14,\"fn\":\"bessel_j\",\"n\":1,\"x\":\"1e999999\"}",
        "{\"id\":15,\"fn\":\"hyp2f1\",\"a\":1,\"b\":1,\"c\":-3,\"z\":0.5}",
    ];
    let mut input = bad.join("\n");
    input.push_str("\n{\"id\":99,\"fn\":\"bessel_j\",\"n\":1,\"x\":1}\n");
    let (out, code) = eval_lines(&input);
    assert_eq!(code, 0);
    assert_eq!(out.len(), bad.len() + 1);
    for (line, resp) in bad.iter().zip(&out) {
        let msg = resp["error"].as_str().unwrap_or_else(|| panic!("no error for {line}: {resp}"));
        assert!(msg.len() > 10, "unhelpful message for {line}: {msg}");
    }
    assert_eq!(out[2]["id"], 2);
    assert_eq!(out.last().unwrap()["id"], 99);
    assert!(out.last().unwrap()["f64"].is_number());
}

#[test]
fn unknown_subcommand_exits_2() {
    let out = Command::new(env!("CARGO_BIN_EXE_maugis")).arg("frobnicate").output().unwrap();
    assert_eq!(out.status.code(), Some(2));
}

#[test]
fn decimal_input_is_a_ball_that_contains_the_decimal() {
    // J_n at a Bessel zero typed to 20+ digits: the printed ball contains J_n at
    // the decimal (reference: reference/data/bessel_j_decimal.csv, mpmath).
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/../reference/data/bessel_j_decimal.csv");
    let table = std::fs::read_to_string(path).expect("reference table");
    let mut checked = 0;
    for line in table.lines().filter(|l| !l.starts_with('#') && !l.starts_with("n,")).step_by(13) {
        let cols: Vec<&str> = line.split(',').collect();
        let (n, x, value) = (cols[0], cols[1], cols[2]);
        let req = format!("{{\"id\":1,\"fn\":\"bessel_j\",\"n\":{n},\"x\":\"{x}\",\"prec\":53}}\n");
        let (out, code) = eval_lines(&req);
        assert_eq!(code, 0);
        let mid = Float::with_val(400, Float::parse(out[0]["mid"].as_str().unwrap()).unwrap());
        let rad = Float::with_val(400, Float::parse(out[0]["rad"].as_str().unwrap()).unwrap());
        let exact = Float::with_val(400, Float::parse(value).unwrap());
        assert!(Float::with_val(400, &mid - &exact).abs() <= rad, "{req}: {:?}", out[0]);
        checked += 1;
    }
    assert!(checked >= 20);
}

#[test]
fn ball_contract_for_1f2_g_and_the_wave() {
    // Every function on the ball contract: the printed ball contains the value
    // at the decimals typed (reference: reference/data/ball_inputs_decimal.csv).
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/../reference/data/ball_inputs_decimal.csv");
    let table = std::fs::read_to_string(path).expect("reference table");
    let names = |f: &str| -> &'static [&'static str] {
        match f {
            "hyp1f2" => &["a", "b1", "b2", "z"],
            "meijer_g_k" => &["k", "y"],
            _ => &["a", "zeta", "amp", "x"],
        }
    };
    let mut input = String::new();
    let mut expected = Vec::new();
    for line in table.lines().filter(|l| !l.starts_with('#') && !l.starts_with("fn,")).step_by(3) {
        let cols: Vec<&str> = line.split(',').collect();
        let (f, args, value) = (cols[0], cols[1], cols[2]);
        let fields: Vec<String> =
            names(f).iter().zip(args.split_whitespace()).map(|(n, v)| format!("\"{n}\":\"{v}\"")).collect();
        input.push_str(&format!("{{\"fn\":\"{f}\",{},\"prec\":128}}\n", fields.join(",")));
        expected.push((f.to_string(), args.to_string(), value.to_string()));
    }
    let (out, code) = eval_lines(&input);
    assert_eq!(code, 0);
    assert_eq!(out.len(), expected.len());
    for (resp, (f, args, value)) in out.iter().zip(&expected) {
        let mid = Float::with_val(400, Float::parse(resp["mid"].as_str().unwrap_or_else(|| panic!("{f} {args}: {resp}"))).unwrap());
        let rad = Float::with_val(400, Float::parse(resp["rad"].as_str().unwrap()).unwrap());
        let exact = Float::with_val(400, Float::parse(value).unwrap());
        assert!(Float::with_val(400, &mid - &exact).abs() <= rad, "{f} {args}: {resp} vs {value}");
    }
    assert!(expected.len() >= 40, "{}", expected.len());
    // issue 13's row: u_w(50) at zeta = 0.1 is 1 - cos(1000 pi) = 0
    let (out, _) = eval_lines("{\"fn\":\"u_wave\",\"a\":\"50\",\"zeta\":\"0.1\",\"amp\":\"1\",\"x\":\"50\",\"prec\":128}\n");
    let mid = Float::with_val(400, Float::parse(out[0]["mid"].as_str().unwrap()).unwrap());
    let rad = Float::with_val(400, Float::parse(out[0]["rad"].as_str().unwrap()).unwrap());
    assert!(mid.abs() <= rad, "{}", out[0]);
    // an edge inside the balls is an error line that names it
    let (out, _) = eval_lines("{\"fn\":\"hyp1f2\",\"a\":\"0.5\",\"b1\":\"-2\",\"b2\":\"1.5\",\"z\":\"-3\",\"prec\":64}\n");
    assert!(out[0]["error"].as_str().unwrap().contains("pole"), "{}", out[0]);
}

#[test]
fn model_strip_ratio_and_load_at_typed_decimals() {
    // strip_ratio and load on the ball contract: the printed balls contain m
    // and the load at the decimals typed (reference/data/model_decimal.csv),
    // the f64 path agrees, and a parameter out of range is an error line.
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/../reference/data/model_decimal.csv");
    let table = std::fs::read_to_string(path).expect("reference table");
    let mut input = String::new();
    let mut expected = Vec::new();
    for line in table.lines().filter(|l| !l.starts_with('#') && !l.starts_with("lambda,")).step_by(4) {
        let c: Vec<&str> = line.split(',').collect();
        let fields = format!("\"lambda\":\"{}\",\"alpha\":\"{}\",\"beta\":\"{}\",\"abar\":\"{}\"", c[0], c[1], c[2], c[3]);
        for (f, value) in [("strip_ratio", c[4]), ("load", c[5])] {
            input.push_str(&format!("{{\"fn\":\"{f}\",{fields},\"prec\":128}}\n{{\"fn\":\"{f}\",{fields}}}\n"));
            expected.push((f, line.to_string(), value.to_string()));
        }
    }
    let (out, code) = eval_lines(&input);
    assert_eq!(code, 0);
    assert_eq!(out.len(), 2 * expected.len());
    for (pair, (f, line, value)) in out.chunks(2).zip(&expected) {
        let (ball, f64_resp) = (&pair[0], &pair[1]);
        let mid = Float::with_val(400, Float::parse(ball["mid"].as_str().unwrap_or_else(|| panic!("{f} {line}: {ball}"))).unwrap());
        let rad = Float::with_val(400, Float::parse(ball["rad"].as_str().unwrap()).unwrap());
        let exact = Float::with_val(400, Float::parse(value).unwrap());
        assert!(Float::with_val(400, &mid - &exact).abs() <= rad, "{f} {line}: {ball} vs {value}");
        let v = f64_resp["f64"].as_f64().unwrap_or_else(|| panic!("{f} {line}: {f64_resp}"));
        assert!((v - exact.to_f64()).abs() <= 1e-9 * exact.to_f64().abs().max(1.0), "{f} {line}: f64 {v} vs {value}");
    }
    assert!(expected.len() >= 8, "{}", expected.len());
    let (out, _) = eval_lines("{\"fn\":\"load\",\"lambda\":\"1\",\"alpha\":\"-0.1\",\"beta\":\"1.125\",\"abar\":\"2\",\"prec\":64}\n");
    assert!(out[0]["error"].as_str().unwrap().contains("alpha"), "{}", out[0]);
}

#[test]
fn model_of_many_waves_at_typed_decimals() {
    // strip_ratio_waves / load_waves: one wave prints what strip_ratio / load print,
    // byte for byte; two waves contain the mpmath values of
    // reference/data/model_waves_decimal.csv; a bad wave or an incomplete one is an
    // error line that names it, and the stream goes on.
    let one = "\"lambda\":\"3\",\"alpha\":\"0.35\",\"beta\":\"1.125\",\"abar\":\"2.2\"";
    let many = "\"lambda\":\"3\",\"abar\":\"2.2\",\"waves\":[[\"0.35\",\"1.125\"]]";
    let mut input = String::new();
    for (a, b) in [("strip_ratio", "strip_ratio_waves"), ("load", "load_waves")] {
        for prec in [",\"prec\":96", ""] {
            input.push_str(&format!("{{\"fn\":\"{a}\",{one}{prec}}}\n{{\"fn\":\"{b}\",{many}{prec}}}\n"));
        }
    }
    let (out, code) = eval_lines(&input);
    assert_eq!(code, 0);
    assert_eq!(out.len(), 8);
    for pair in out.chunks(2) {
        assert!(pair[0].get("error").is_none(), "{}", pair[0]);
        assert_eq!(pair[0], pair[1]);
    }
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/../reference/data/model_waves_decimal.csv");
    let table = std::fs::read_to_string(path).expect("reference table");
    let row = table.lines().find(|l| !l.starts_with('#') && !l.starts_with("lambda,")).expect("a row");
    let c: Vec<&str> = row.split(',').collect();
    let w: Vec<&str> = c[2].split_whitespace().collect();
    let list: Vec<String> = w.chunks(2).map(|p| format!("[\"{}\",\"{}\"]", p[0], p[1])).collect();
    let fields = format!("\"lambda\":\"{}\",\"abar\":\"{}\",\"waves\":[{}],\"prec\":128", c[0], c[1], list.join(","));
    let (out, _) = eval_lines(&format!("{{\"fn\":\"strip_ratio_waves\",{fields}}}\n{{\"fn\":\"load_waves\",{fields}}}\n"));
    for (resp, value) in out.iter().zip([c[3], c[4]]) {
        let mid = Float::with_val(400, Float::parse(resp["mid"].as_str().unwrap_or_else(|| panic!("{row}: {resp}"))).unwrap());
        let rad = Float::with_val(400, Float::parse(resp["rad"].as_str().unwrap()).unwrap());
        let exact = Float::with_val(400, Float::parse(value).unwrap());
        assert!(Float::with_val(400, &mid - &exact).abs() <= rad, "{row}: {resp} vs {value}");
    }
    let bad = [
        ("[[0.35,1.125],[-0.1,0.375]]", "wave 2: amplitude"),
        ("[[0.35,1.125],[0.1,0]]", "wave 2: wavelength"),
        ("[[0.35,1.125],[0.1]]", "wave 2 incomplete"),
        ("[[0.35,\"x\"]]", "waves[1].beta"),
        ("[0.35,1.125]", "waves[1] must be a list"),
        ("\"0.35,1.125\"", "must be a list"),
    ];
    let input: String = bad.iter().map(|(w, _)| format!("{{\"fn\":\"load_waves\",\"lambda\":3,\"abar\":2,\"waves\":{w},\"prec\":64}}\n")).collect();
    let (out, code) = eval_lines(&format!("{input}{{\"fn\":\"strip_ratio_waves\",\"lambda\":3,\"abar\":2}}\n"));
    assert_eq!(code, 0);
    assert_eq!(out.len(), bad.len() + 1);
    for (resp, (w, says)) in out.iter().zip(&bad) {
        let msg = resp["error"].as_str().unwrap_or_else(|| panic!("{w}: {resp}"));
        assert!(msg.contains(says), "{w}: {msg}");
    }
    assert!(out[bad.len()]["error"].as_str().unwrap().contains("missing argument \"waves\""), "{}", out[bad.len()]);
}

/// Responses are batched only while more input is waiting: a client that sends
/// one line and waits gets its answer before it sends the next (stdin open).
#[test]
fn interactive_client_gets_each_answer_before_the_next_line() {
    use std::io::{BufRead, BufReader};
    let mut child = eval_command().spawn().expect("spawn maugis");
    let mut stdin = child.stdin.take().unwrap();
    let (tx, rx) = std::sync::mpsc::channel();
    let stdout = child.stdout.take().unwrap();
    std::thread::spawn(move || {
        for line in BufReader::new(stdout).lines() {
            if tx.send(line.unwrap()).is_err() {
                break;
            }
        }
    });
    // J_0(2.5) from reference/data/bessel_j_grid.csv (2.5 is exact in binary), at 128 bits
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/../reference/data/bessel_j_grid.csv");
    let table = std::fs::read_to_string(path).expect("reference table");
    let j0 = table.lines().find(|l| l.starts_with("0,2.5,")).expect("J_0(2.5) in bessel_j_grid").rsplit(',').next().unwrap();
    let j0 = Float::with_val(600, Float::parse(j0).unwrap());
    for id in 1..=3 {
        writeln!(stdin, "{{\"id\":{id},\"fn\":\"bessel_j\",\"n\":0,\"x\":\"2.5\",\"prec\":128}}").unwrap();
        stdin.flush().unwrap();
        let got = rx.recv_timeout(std::time::Duration::from_secs(20)).expect("an answer while stdin stays open");
        let v: Value = serde_json::from_str(&got).unwrap();
        assert_eq!(v["id"], id);
        let mid = Float::with_val(600, Float::parse(v["mid"].as_str().unwrap()).unwrap());
        let rad = Float::with_val(600, Float::parse(v["rad"].as_str().unwrap()).unwrap());
        assert!(Float::with_val(600, &mid - &j0).abs() <= rad && rad <= 1e-37, "{got}");
    }
    drop(stdin);
    assert!(child.wait().unwrap().success());
}

/// `MAUGIS_EVAL_PROFILE=1` reports the time per stage on stderr; stdout is unchanged.
#[test]
fn profile_reports_the_stages_on_stderr() {
    let input = "{\"id\":1,\"fn\":\"bessel_j\",\"n\":0,\"x\":\"2.5\",\"prec\":128}\n{\"id\":2,\"fn\":\"nope\"}\n";
    let run = |profile: bool| {
        let mut cmd = eval_command();
        if profile {
            cmd.env("MAUGIS_EVAL_PROFILE", "1");
        } else {
            cmd.env_remove("MAUGIS_EVAL_PROFILE");
        }
        let mut child = cmd.spawn().expect("spawn maugis");
        child.stdin.take().unwrap().write_all(input.as_bytes()).unwrap();
        child.wait_with_output().unwrap()
    };
    let (plain, profiled) = (run(false), run(true));
    assert_eq!(plain.stdout, profiled.stdout);
    assert!(plain.stderr.is_empty());
    let err = String::from_utf8(profiled.stderr).unwrap();
    assert!(err.contains("2 requests"), "{err}");
    for stage in ["JSON parse", "arguments", "evaluation", "response", "output"] {
        assert!(err.contains(stage), "{stage} missing in {err}");
    }
}

#[test]
fn budget_ms_refuses_at_once_and_never_changes_an_answer() {
    let input = concat!(
        // 1F2(1e12; 1.5, 2.5; 100): about 4.6e4 series terms, estimated past 1 ms
        "{\"id\":1,\"fn\":\"hyp1f2\",\"a\":\"1e12\",\"b1\":1.5,\"b2\":2.5,\"z\":100,\"prec\":64,\"budget_ms\":1}\n",
        "{\"id\":2,\"fn\":\"hyp1f2\",\"a\":\"1e12\",\"b1\":1.5,\"b2\":2.5,\"z\":100,\"prec\":64}\n",
        "{\"id\":3,\"fn\":\"hyp1f2\",\"a\":\"1e12\",\"b1\":1.5,\"b2\":2.5,\"z\":100,\"prec\":64,\"budget_ms\":600000}\n",
        "{\"id\":4,\"fn\":\"bessel_j\",\"n\":1,\"x\":1,\"prec\":64,\"budget_ms\":0}\n",
        "{\"id\":5,\"fn\":\"bessel_j\",\"n\":1,\"x\":1,\"prec\":64,\"budget_ms\":\"1.5\"}\n",
    );
    let (out, code) = eval_lines(input);
    assert_eq!(code, 0);
    let msg = out[0]["error"].as_str().expect("refused");
    assert_eq!(out[0]["refused"], "time", "{}", out[0]);
    assert!(msg.contains("would take about") && msg.contains("budget"), "{msg}");
    // the default and a long budget give the same ball
    assert!(out[1]["mid"].is_string(), "{}", out[1]);
    assert_eq!((&out[1]["mid"], &out[1]["rad"]), (&out[2]["mid"], &out[2]["rad"]));
    // a budget out of range or not an integer is a bad request, not a time refusal
    for r in &out[3..] {
        assert!(r["error"].is_string() && r.get("refused").is_none(), "{r}");
    }
    assert!(out[3]["error"].as_str().unwrap().contains("budget_ms"), "{}", out[3]);
}
