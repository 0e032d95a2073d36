//! `maugis eval`: a JSON Lines calculator.
//!
//! One request per input line, one response per output line, in order:
//!
//! ```text
//! {"id": 1, "fn": "bessel_j", "n": 5, "x": "2.5", "prec": 200}
//! {"id": 1, "mid": "1.95016...e-2", "rad": "3.1e-62", "prec": 200}
//! {"id": 2, "fn": "hyp2f1", "a": 1, "b": 0.5, "c": 2, "z": 0.25}
//! {"id": 2, "f64": 1.0718...}
//! ```
//!
//! # Input contract
//!
//! Arguments are JSON numbers or decimal strings; either way the decimal text
//! as typed is what counts (JSON numbers keep their text: serde_json runs with
//! `arbitrary_precision`).
//!
//! * Without `"prec"` the f64 path runs: each decimal is rounded to the nearest
//!   double and the answer is for those doubles.
//! * With `"prec"` the certified path runs. For the functions wired to ball
//!   inputs (`bessel_j`, `hyp1f2`, `hyp2f1`, `meijer_g_k`, `u_wave`, `du_wave`,
//!   and the model's `strip_ratio`, `load`, `strip_ratio_waves`, `load_waves`) each decimal becomes a ball that **contains the
//!   decimal** ([`maugis::ball::Decimal`], Arb's convention): exact when the
//!   decimal is a binary fraction (`2.5`, `0.375`), otherwise the decimal rounded
//!   to nearest with a one-ulp radius. The printed ball contains the function
//!   **at the decimal typed**. The decimals are rounded at `max(prec, 53) + 64`
//!   bits first and, where the input radius keeps the answer from `prec` bits
//!   (near a zero), at more bits ([`maugis::ball::eval_at_decimals`]).
//!   If an edge of the function (a pole, a divergence) lies inside the input
//!   ball, the answer is an error that names it, never a number.
//! * The other functions (`u_wave_series`, `u_wave_quad`, `u_hertz`,
//!   `u_adhesive`) round each decimal to nearest at `max(prec, 53) + 64` bits
//!   and certify (or, for the quadrature, estimate) the function at that binary
//!   number ([`maugis::registry::MpInputs::Rounded`]).
//!
//! * `integrate` takes the integrand as a string in x (`"f"`, the language of
//!   [`maugis::quad::expr`]), the ends `"a"` and `"b"` as decimals (`"b": "inf"`
//!   for a semi-infinite range, with a `"decay"`), and optionally
//!   `"weight": {"alpha": AL, "beta": BE, "log": K}` (the integrand is then
//!   `(x-a)^AL (b-x)^BE log^K(x-a)` times `f`) and
//!   `"decay": {"rate": C | "power": P, "bound": M}` (`|f(x)| <= M e^(-C x)` or
//!   `M x^(-P)` for `x >= a`). It is always certified (`"prec"` defaults to 53)
//!   and answers `mid` and `rad` of the real part (`im_mid`, `im_rad` too when the
//!   imaginary part may exceed `rad`), the evaluations spent,
//!   `"goal_met": false` with a `"warning"` when a limit stopped it early, and
//!   `"abs_tol"` when the ball contains 0 and met the goal by the default absolute
//!   tolerance (`2^-prec` times a bound of `int |f|`: a zero integral).
//!
//! * `strip_ratio_waves` and `load_waves` are `strip_ratio` and `load` for a profile of
//!   any number of waves: `"lambda"`, `"abar"` and `"waves": [[alpha_1, beta_1], ...]`
//!   (each value a number or a decimal string, up to 64 waves; a bad wave is an error
//!   naming the wave, from 1, and the field):
//!   `{"fn": "strip_ratio_waves", "lambda": 3, "abar": 2, "waves": [[0.35, 1.125], ["0.175", "0.375"]], "prec": 64}`.
//!
//! * `"budget_ms"` (optional, `1 ..= 86 400 000`) is the request's time
//!   budget in milliseconds; without it the library's default,
//!   [`maugis::Budget::DEFAULT`] (30 s). A request that its cost model puts past
//!   the budget is refused at once, and one whose loops reach it is stopped
//!   there; either way the line is `{"id": ..., "error": "...", "refused": "time"}`
//!   (the input is fine: a larger budget or a lower precision may answer it).
//!   The budget never changes an answer ([`maugis::budget`]).
//!
//! Integer arguments (`n`, `k`, `kmax`, `prec`, `budget_ms`) must be integers as typed.
//! A bad line gets `{"id": ..., "error": "..."}` and the stream goes on.
//!
//! Responses are flushed whenever no further input waits, so an interactive
//! client gets each answer before it sends its next line.
//!
//! An `integrate` request in its common form takes a fast path ([`fast`]: typed
//! fields borrowed from the line, cached integrand and ends, the response written
//! straight into the output buffer) that answers byte for byte as the general path
//! below; everything else goes through the general path. With
//! `MAUGIS_EVAL_PROFILE=1` the time per request by stage (JSON, arguments,
//! evaluation, response, output) is printed to stderr at the end
//! (`reference/bench_arb_bessel.py --eval` uses it).

use std::io::{BufRead, Write};

use maugis::ball::Decimal;
use maugis::registry::{self, Answer, Arg, ParamKind, Repeated};
use maugis::quad::certified::Options;
use maugis::quad::expr::{integrate_range, DecaySpec, WeightSpec};
use maugis::{Ball, Budget, Error, MAX_PREC};
use serde_json::{json, Map, Value};

use crate::integrate::digits_for;
use cache::{parsed_end, parsed_expr};
use response::integral_fields;

mod cache;
mod fast;
mod profile;
mod response;

/// A request-level failure, turned into an error line (with `"refused": "time"`
/// for a refusal of the time budget: the input is fine, a larger `"budget_ms"`
/// may answer it).
struct BadRequest {
    msg: String,
    time_limit: bool,
}

impl BadRequest {
    fn new(msg: impl Into<String>) -> Self {
        BadRequest { msg: msg.into(), time_limit: false }
    }
}

impl From<Error> for BadRequest {
    fn from(e: Error) -> Self {
        BadRequest { msg: e.to_string(), time_limit: e.is_time_limit() }
    }
}

type Req<T> = std::result::Result<T, BadRequest>;

/// The request `integrate` and its fields: the one request that is not a
/// function of the library's registry ([`maugis::registry`]).
const INTEGRATE: (&str, &[&str]) = ("integrate", &["f", "a", "b", "weight", "decay"]);

/// The argument as decimal text (JSON number text or string).
fn arg_text<'a>(obj: &'a Map<String, Value>, name: &str) -> Req<String> {
    match obj.get(name) {
        None => Err(BadRequest::new(format!("missing argument \"{name}\""))),
        Some(Value::Number(n)) => Ok(n.to_string()),
        Some(Value::String(s)) => Ok(s.trim().to_string()),
        Some(other) => Err(BadRequest::new(format!("argument \"{name}\" must be a number or a decimal string, got {other}"))),
    }
}

fn arg_f64(obj: &Map<String, Value>, name: &str) -> Req<f64> {
    profile::timed(profile::ARGS, || arg_f64_untimed(obj, name))
}

fn arg_f64_untimed(obj: &Map<String, Value>, name: &str) -> Req<f64> {
    parse_f64(&format!("argument \"{name}\""), &arg_text(obj, name)?)
}

/// Decimal text as a finite f64; `what` names it in the error.
fn parse_f64(what: &str, t: &str) -> Req<f64> {
    let v: f64 = t.parse().map_err(|_| BadRequest::new(format!("{what} = {t:?} is not a decimal number")))?;
    if !v.is_finite() {
        return Err(BadRequest::new(format!("{what} must be finite (got {t})")));
    }
    Ok(v)
}

/// The list of repeated groups of a function (`"waves": [[alpha, beta], ...]`), flat,
/// each value's text with its name (`waves[2].beta`). The count and the completeness of
/// the groups are the registry's to check: a group of the wrong length is passed on as
/// it is and refused there with a typed error ([`maugis::Error::IncompleteGroup`]).
fn group_texts(obj: &Map<String, Value>, r: Repeated) -> Req<Vec<(String, String)>> {
    let list = match obj.get(r.list) {
        Some(Value::Array(list)) => list,
        None => return Err(BadRequest::new(format!("missing argument \"{}\" (a list of [{}] for each {})", r.list, r.names.join(", "), r.group))),
        Some(other) => return Err(BadRequest::new(format!("\"{}\" must be a list of [{}] for each {}, got {other}", r.list, r.names.join(", "), r.group))),
    };
    let mut out = Vec::new();
    for (j, item) in list.iter().enumerate() {
        let Value::Array(group) = item else {
            return Err(BadRequest::new(format!("{}[{}] must be a list [{}], got {item}", r.list, j + 1, r.names.join(", "))));
        };
        for (k, v) in group.iter().enumerate() {
            let name = format!("{}[{}].{}", r.list, j + 1, r.names.get(k).copied().unwrap_or("?"));
            let text = match v {
                Value::Number(n) => n.to_string(),
                Value::String(s) => s.trim().to_string(),
                other => return Err(BadRequest::new(format!("{name} must be a number or a decimal string, got {other}"))),
            };
            out.push((name, text));
        }
    }
    Ok(out)
}

/// The argument as an exact [`Decimal`] (for functions wired to ball inputs).
fn arg_decimal(obj: &Map<String, Value>, name: &str) -> Req<Decimal> {
    profile::timed(profile::ARGS, || {
        let t = arg_text(obj, name)?;
        Decimal::parse(&t).map_err(|e| BadRequest::new(format!("argument \"{name}\": {e}")))
    })
}

fn arg_int(obj: &Map<String, Value>, name: &str) -> Req<i64> {
    profile::timed(profile::ARGS, || arg_int_untimed(obj, name))
}

fn arg_int_untimed(obj: &Map<String, Value>, name: &str) -> Req<i64> {
    // a JSON integer as typed (no text copy); "5.0", "1e3" and strings take the text path
    if let Some(Value::Number(n)) = obj.get(name) {
        if let Some(v) = n.as_i64() {
            return Ok(v);
        }
    }
    let t = arg_text(obj, name)?;
    if let Ok(v) = t.parse::<i64>() {
        return Ok(v);
    }
    let v: f64 = t.parse().map_err(|_| BadRequest::new(format!("argument \"{name}\" = {t:?} is not an integer")))?;
    if v.is_finite() && v == v.trunc() && v.abs() < 9.0e15 {
        Ok(v as i64)
    } else {
        Err(BadRequest::new(format!("argument \"{name}\" must be an integer (got {t})")))
    }
}

fn arg_u32(obj: &Map<String, Value>, name: &str) -> Req<u32> {
    let v = arg_int(obj, name)?;
    u32::try_from(v).map_err(|_| BadRequest::new(format!("argument \"{name}\" must be a non-negative integer (got {v})")))
}

/// Reads `"budget_ms"`: the request's time budget in milliseconds
/// (`1 ..= 86 400 000`), [`Budget::DEFAULT`] (30 s) without it.
fn read_budget(obj: &Map<String, Value>) -> Req<Budget> {
    match obj.get("budget_ms") {
        None | Some(Value::Null) => Ok(Budget::DEFAULT),
        Some(_) => {
            let ms = arg_int(obj, "budget_ms")?;
            let ms = u64::try_from(ms).unwrap_or(0);
            Ok(Budget::from_millis(ms)?)
        }
    }
}

/// Reads `"prec"` if present.
fn read_prec(obj: &Map<String, Value>) -> Req<Option<u32>> {
    match obj.get("prec") {
        None | Some(Value::Null) => Ok(None),
        Some(_) => {
            let p = arg_int(obj, "prec")?;
            if p < 2 || p > MAX_PREC as i64 {
                Err(BadRequest::new(format!("\"prec\" = {p} is out of range: use 2 ..= {MAX_PREC} bits")))
            } else {
                Ok(Some(p as u32))
            }
        }
    }
}

/// Rejects argument names the function does not take (typos would otherwise be silent).
fn check_names(obj: &Map<String, Value>, fname: &str, args: &[&str]) -> Req<()> {
    for key in obj.keys() {
        if key == "id" || key == "fn" || key == "prec" || key == "budget_ms" || args.contains(&key.as_str()) {
            continue;
        }
        return Err(BadRequest::new(format!(
            "unknown argument \"{key}\" for {fname} (it takes {})",
            args.join(", ")
        )));
    }
    Ok(())
}

fn mp_response(id: &Value, ball: &Ball, prec: u32) -> Value {
    profile::timed(profile::RESPONSE, || {
        let (mid, rad) = ball.to_decimal(digits_for(prec));
        json!({"id": id, "mid": mid, "rad": rad, "prec": prec})
    })
}

fn f64_response(id: &Value, v: f64) -> Value {
    json!({"id": id, "f64": v})
}

/// Evaluates one parsed request object.
fn evaluate(obj: &Map<String, Value>) -> Req<Value> {
    let id = obj.get("id").cloned().unwrap_or(Value::Null);
    let fname = match obj.get("fn") {
        Some(Value::String(s)) => s.as_str(),
        Some(_) => return Err(BadRequest::new("\"fn\" must be a string")),
        None => return Err(BadRequest::new("missing \"fn\" (the function name)")),
    };
    if fname == INTEGRATE.0 {
        check_names(obj, fname, INTEGRATE.1)?;
        let prec = read_prec(obj)?;
        let budget = read_budget(obj)?;
        return budget.run(|| evaluate_integral(obj, &id, prec.unwrap_or(DEFAULT_INTEGRAL_PREC)));
    }
    let function = registry::function(fname).map_err(|e| match e {
        Error::UnknownFunction { name, known } => {
            BadRequest::new(format!("unknown fn \"{name}\"; known: {}, {}", known.join(", "), INTEGRATE.0))
        }
        other => other.into(),
    })?;
    let mut names: Vec<&str> = function.param_names().collect();
    names.extend(function.repeated.map(|r| r.list));
    check_names(obj, fname, &names)?;
    let prec = read_prec(obj)?;
    let budget = read_budget(obj)?;
    let answer = match prec {
        None => {
            let mut args = function
                .params
                .iter()
                .map(|p| Ok(match p.kind { ParamKind::Integer => Arg::Int(arg_int(obj, p.name)?), ParamKind::Real => Arg::Real(arg_f64(obj, p.name)?) }))
                .collect::<Req<Vec<_>>>()?;
            if let Some(r) = function.repeated {
                args.extend(group_texts(obj, r)?.iter().map(|(name, t)| parse_f64(name, t).map(Arg::Real)).collect::<Req<Vec<_>>>()?);
            }
            budget.run(|| function.eval_f64(&args))?
        }
        Some(p) => {
            let mut args = function
                .params
                .iter()
                .map(|q| Ok(match q.kind { ParamKind::Integer => Arg::Int(arg_int(obj, q.name)?), ParamKind::Real => Arg::Real(arg_decimal(obj, q.name)?) }))
                .collect::<Req<Vec<_>>>()?;
            if let Some(r) = function.repeated {
                let texts = group_texts(obj, r)?;
                for (name, t) in &texts {
                    let d = profile::timed(profile::ARGS, || Decimal::parse(t)).map_err(|e| BadRequest::new(format!("{name}: {e}")))?;
                    args.push(Arg::Real(d));
                }
            }
            function.eval_mp_with_budget(&args, p, budget)?
        }
    };
    Ok(respond(&id, answer, prec))
}

/// The response object of an [`Answer`].
fn respond(id: &Value, answer: Answer, prec: Option<u32>) -> Value {
    let p = prec.unwrap_or(53);
    match answer {
        Answer::F64(v) => f64_response(id, v),
        Answer::Ball(b) => mp_response(id, &b, p),
        Answer::SeriesF64 { value, trunc } => json!({"id": id, "f64": value, "trunc": trunc}),
        Answer::SeriesBall { mut value, trunc } => {
            value.add_error(&trunc);
            let mut resp = mp_response(id, &value, p);
            resp["trunc"] = Value::String(maugis::ball::decimal_upper(&trunc));
            resp
        }
        Answer::EstimateF64 { value, error_estimate } => {
            json!({"id": id, "f64": value, "error_estimate": error_estimate, "certified": false})
        }
        Answer::EstimateMp { value, error_estimate } => json!({
            "id": id,
            "mid": value.to_string_radix(10, Some(digits_for(p))),
            "error_estimate": maugis::ball::decimal_upper(&error_estimate),
            "prec": p,
            "certified": false
        }),
        other => json!({"id": id, "error": format!("internal: no presentation for {other:?}")}),
    }
}

/// Precision of an `integrate` request without `"prec"` (bits).
const DEFAULT_INTEGRAL_PREC: u32 = 53;

/// The fields of a nested object argument (`"weight"`, `"decay"`), checked against `names`.
fn sub_object<'a>(obj: &'a Map<String, Value>, name: &str, names: &[&str]) -> Req<Option<&'a Map<String, Value>>> {
    match obj.get(name) {
        None | Some(Value::Null) => Ok(None),
        Some(Value::Object(sub)) => {
            if let Some(key) = sub.keys().find(|k| !names.contains(&k.as_str())) {
                return Err(BadRequest::new(format!("unknown field \"{key}\" in \"{name}\" (it takes {})", names.join(", "))));
            }
            Ok(Some(sub))
        }
        Some(other) => Err(BadRequest::new(format!("\"{name}\" must be an object, got {other}"))),
    }
}

/// An optional decimal field of a nested object.
fn opt_decimal(obj: &Map<String, Value>, name: &str) -> Req<Option<Decimal>> {
    obj.contains_key(name).then(|| arg_decimal(obj, name)).transpose()
}

/// `{"fn": "integrate", "f": EXPR, "a": A, "b": B | "inf", "prec": P,
/// "weight": {"alpha": AL, "beta": BE, "log": K}, "decay": {"rate": C | "power": P, "bound": M}}`.
fn evaluate_integral(obj: &Map<String, Value>, id: &Value, prec: u32) -> Req<Value> {
    let f = match obj.get("f") {
        Some(Value::String(s)) => profile::timed(profile::ARGS, || parsed_expr(s))?,
        Some(other) => return Err(BadRequest::new(format!("\"f\" must be the integrand as a string, got {other}"))),
        None => return Err(BadRequest::new("missing argument \"f\" (the integrand in x, e.g. \"exp(-x^2)\")")),
    };
    let a = profile::timed(profile::ARGS, || parsed_end(&arg_text(obj, "a")?).map_err(BadRequest::from))?;
    let b = profile::timed(profile::ARGS, || parsed_end(&arg_text(obj, "b")?).map_err(BadRequest::from))?;
    let weight = match sub_object(obj, "weight", &["alpha", "beta", "log"])? {
        None => None,
        Some(w) => Some(WeightSpec {
            alpha: opt_decimal(w, "alpha")?,
            beta: opt_decimal(w, "beta")?,
            log: if w.contains_key("log") { arg_u32(w, "log")? } else { 0 },
        }),
    };
    let decay = match sub_object(obj, "decay", &["rate", "power", "bound"])? {
        None => None,
        Some(d) => {
            let bound = arg_decimal(d, "bound")?;
            Some(match (opt_decimal(d, "rate")?, opt_decimal(d, "power")?) {
                (Some(rate), None) => DecaySpec::Exponential { rate, bound },
                (None, Some(power)) => DecaySpec::Algebraic { power, bound },
                _ => return Err(BadRequest::new("\"decay\" takes one of \"rate\" (exponential) and \"power\" (algebraic), with \"bound\"")),
            })
        }
    };
    let r = integrate_range(&f, &a, &b, weight.as_ref(), decay.as_ref(), prec, &Options::new())?;
    Ok(profile::timed(profile::RESPONSE, || {
        let mut resp = json!({"id": id});
        for (key, value) in integral_fields(&r, prec) {
            resp[key] = value.into_value();
        }
        resp
    }))
}

/// [`evaluate`], its time less the argument and response stages charged to
/// the evaluation stage of the profile.
fn evaluate_timed(obj: &Map<String, Value>) -> Req<Value> {
    if !profile::enabled() {
        return evaluate(obj);
    }
    let nested = || profile::get(profile::ARGS) as i64 + profile::get(profile::RESPONSE) as i64;
    let before = nested();
    let t = std::time::Instant::now();
    let out = evaluate(obj);
    let spent = t.elapsed().as_nanos() as i64;
    profile::add(profile::EVAL, spent - (nested() - before));
    out
}

/// Handles one input line; always returns exactly one response.
pub fn handle_line(line: &str) -> Value {
    let parsed: Value = match profile::timed(profile::JSON, || serde_json::from_str(line)) {
        Ok(v) => v,
        Err(e) => return json!({"id": Value::Null, "error": format!("invalid JSON: {e}")}),
    };
    let Value::Object(obj) = parsed else {
        return json!({"id": Value::Null, "error": "each line must be a JSON object"});
    };
    let id = obj.get("id").cloned().unwrap_or(Value::Null);
    // A panic in a numerical routine would be a bug; catch it so the stream goes on.
    let result = std::panic::catch_unwind(|| evaluate_timed(&obj));
    match result {
        Ok(Ok(v)) => v,
        Ok(Err(BadRequest { msg, time_limit: false })) => json!({"id": id, "error": msg}),
        Ok(Err(BadRequest { msg, time_limit: true })) => json!({"id": id, "error": msg, "refused": "time"}),
        Err(_) => json!({"id": id, "error": INTERNAL_ERROR}),
    }
}

/// The error line's message when a numerical routine panicked (a bug).
const INTERNAL_ERROR: &str = "internal error while evaluating (please report this input)";

/// Appends the response line to `line` (without its newline) to `out`: an
/// `integrate` request through the fast path ([`fast::integrate`]) when it takes it,
/// any other through [`handle_line`].
pub fn handle_line_into(line: &str, out: &mut Vec<u8>) {
    if fast::integrate(line, out) {
        return;
    }
    let resp = handle_line(line);
    profile::timed(profile::OUTPUT, || {
        // cannot fail: a Value always serialises, and a Vec takes every write
        let _ = serde_json::to_writer(&mut *out, &resp);
    });
}

/// Runs the calculator over stdin/stdout. Returns the process exit code.
///
/// Responses are flushed whenever no further input is waiting in the read
/// buffer (an interactive client gets each answer before it sends the next
/// line; a piped batch is written in large blocks, not one `write` per line).
pub fn run() -> i32 {
    let mut input = std::io::BufReader::with_capacity(1 << 16, std::io::stdin().lock());
    let stdout = std::io::stdout();
    let mut out = std::io::BufWriter::with_capacity(1 << 16, stdout.lock());
    let mut line = String::new();
    let mut resp = Vec::new();
    let mut requests = 0u64;
    loop {
        line.clear();
        match profile::timed(profile::READ, || input.read_line(&mut line)) {
            Ok(0) => break,
            Ok(_) => {}
            Err(e) => {
                eprintln!("maugis eval: cannot read stdin: {e}");
                return 2;
            }
        }
        if line.trim().is_empty() {
            continue;
        }
        requests += 1;
        resp.clear();
        handle_line_into(line.trim_end_matches(['\n', '\r']), &mut resp);
        resp.push(b'\n');
        let written = profile::timed(profile::OUTPUT, || {
            out.write_all(&resp)?;
            if input.buffer().is_empty() {
                out.flush()?;
            }
            Ok::<(), std::io::Error>(())
        });
        if written.is_err() {
            // Broken pipe: the reader went away.
            return 0;
        }
    }
    profile::report(requests);
    if out.flush().is_err() {
        return 0;
    }
    0
}

#[cfg(test)]
mod fuzz {
    //! The `eval` line parser on fuzzed input (issue 26, item 5): random JSON
    //! objects over the registry's names and argument names, with numbers, decimal
    //! strings, objects and junk as values, and raw bytes. `handle_line_into` catches a
    //! panic and answers "internal error"; the test fails on that answer, and on a line
    //! of the fast path ([`fast`]) that differs from the general path's.

    use super::*;
    // the same reproducible input sequence as the library's and the solver's targets
    use crate::fuzz_inputs::check;

    const NAMES: [&str; 6] = ["integrate", "nope", "", "bessel_j ", "BESSEL_J", "load"];
    const VALUES: [&str; 19] = [
        "1", "-1", "2.5", "\"2.5\"", "\"0.001\"", "1e400", "-0", "\"nan\"", "null", "{}", "[1]", "true", "\"x\"",
        "9223372036854775808", "\"sqrt(x)\"", "{\"alpha\": -0.5, \"log\": 9}",
        "[[0.35, 1.125], [\"0.175\", \"0.375\"]]", "[[0.35], [1, 2, 3]]", "[[-1, \"0\"], null]",
    ];
    const PRECS: [&str; 7] = ["0", "1", "53", "65537", "-5", "\"64\"", "4294967296"];

    /// The response line to `line`, checked against the general path's when the fast
    /// path answered it.
    fn answer(line: &str) -> (Value, String) {
        let mut out = Vec::new();
        handle_line_into(line, &mut out);
        let text = String::from_utf8(out).expect("UTF-8");
        if fast::integrate(line, &mut Vec::new()) {
            assert_eq!(text, handle_line(line).to_string(), "{line}: the fast path's line differs");
        }
        (serde_json::from_str(&text).expect("a JSON line"), text)
    }

    fn assert_answered(line: &str) {
        let (resp, text) = answer(line);
        assert!(!text.contains("internal error"), "{line} -> {text}");
        assert!(resp.get("error").is_some() || resp.get("f64").is_some() || resp.get("mid").is_some(), "{line} -> {text}");
    }

    #[test]
    fn structured_requests() {
        check().with_type::<(u8, Vec<(u8, u8)>, Option<u8>)>().for_each(|(f, args, prec)| {
            let all: Vec<&str> = registry::names().chain(NAMES).collect();
            let name = all[*f as usize % all.len()];
            let params: Vec<&str> = registry::function(name)
                .map(|g| g.param_names().chain(g.repeated.map(|r| r.list)).collect())
                .unwrap_or_else(|_| vec!["f", "a", "b", "x", "weight", "decay"]);
            let mut fields = vec![format!("\"fn\": \"{name}\"")];
            for (k, v) in args.iter().take(6) {
                let key = params.get(*k as usize % (params.len() + 1)).copied().unwrap_or("junk");
                fields.push(format!("\"{key}\": {}", VALUES[*v as usize % VALUES.len()]));
            }
            if let Some(p) = prec {
                fields.push(format!("\"prec\": {}", PRECS[*p as usize % PRECS.len()]));
            }
            assert_answered(&format!("{{{}}}", fields.join(", ")));
        });
    }

    const EXPRS: [&str; 6] = ["\"x\"", "\"1/(1+x^2)\"", "\"sin(x)\"", "\"exp(-x)\"", "\"x^2\"", "\"sin(\""];
    const ENDS: [&str; 10] = ["0", "1", "-1", "2.5", "1E0", "\"0.001\"", "\" 2.5 \"", "\"inf\"", "\"-inf\"", "true"];
    const IDS: [&str; 8] = ["1", "\"r\"", "1.50", "1e3", "null", "{\"b\": 1, \"a\": [2]}", "\"\\u0041\"", "-0"];
    const INTEGRAL_PRECS: [&str; 7] = ["53", "64", "128", "null", "\"64\"", "1", "64.0"];
    const EXTRAS: [&str; 6] = ["\"budget_ms\": 60000", "\"weight\": null", "\"decay\": null", "\"budget_ms\": 0", "\"junk\": 1", "\"f\": \"x\""];

    /// `integrate` requests in the forms the fast path takes and in the forms next to
    /// them it leaves to the general path (a string precision, a duplicate field, an
    /// escape, a bad end): every line is answered, and one of the fast path's is the
    /// general path's byte for byte ([`answer`]). Some inputs must take the fast path.
    #[test]
    fn integrate_requests() {
        use std::sync::atomic::{AtomicUsize, Ordering};
        let taken = AtomicUsize::new(0);
        check().with_type::<(u8, u8, u8, Option<u8>, Option<u8>, Option<u8>)>().for_each(|(f, a, b, id, prec, extra)| {
            let pick = |list: &[&'static str], i: u8| list[i as usize % list.len()];
            let mut fields = vec![
                "\"fn\": \"integrate\"".to_string(),
                format!("\"f\": {}", pick(&EXPRS, *f)),
                format!("\"a\": {}", pick(&ENDS, *a)),
                format!("\"b\": {}", pick(&ENDS, *b)),
            ];
            fields.extend(id.map(|i| format!("\"id\": {}", pick(&IDS, i))));
            fields.extend(prec.map(|p| format!("\"prec\": {}", pick(&INTEGRAL_PRECS, p))));
            fields.extend(extra.map(|e| pick(&EXTRAS, e).to_string()));
            let line = format!("{{{}}}", fields.join(", "));
            let (resp, text) = answer(&line);
            assert!(resp.get("error").is_some() || resp.get("mid").is_some(), "{line} -> {text}");
            if fast::integrate(&line, &mut Vec::new()) {
                taken.fetch_add(1, Ordering::Relaxed);
            }
        });
        assert!(taken.into_inner() > 0, "no input took the fast path");
    }

    #[test]
    fn raw_lines() {
        check().for_each(|bytes| {
            let line = String::from_utf8_lossy(bytes);
            let (_, text) = answer(&line);
            assert!(!text.contains("internal error"), "{line:?}");
        });
    }
}
