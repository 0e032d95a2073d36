//! The common `integrate` request without a `serde_json::Value` in between.
//!
//! A small integral at 64 bits takes 12-17 us in the library, and `eval`'s own work
//! per request through the general path (the line parsed into a `Value` map, the
//! decimals and the integrand parsed, a `Value` response serialised, the map dropped)
//! was about 33 000 instructions, 6-9 us (docs/quadrature.md, "`eval`'s own cost per request").
//! Here the line is read into a typed request whose fields borrow from the line, the
//! integrand and the ends come from the parse caches ([`super::cache`]), and the
//! response is written straight into the output buffer ([`super::response`]).
//!
//! Only what this path answers exactly as the general path would is taken: `"fn":
//! "integrate"`; no field besides `id`, `fn`, `f`, `a`, `b`, `prec`, `budget_ms`,
//! `weight`, `decay`, each once; `f` a string, `a` and `b` decimal strings or numbers,
//! `prec` and `budget_ms` integers (or `null`), all in range; strings without escapes.
//! Anything else, and any error before the integration (a bad integrand, an end that
//! does not parse, a precision out of range), goes to the general path, which says
//! what is wrong in its own words. The integration runs once either way: its errors
//! are answered here. The module's test compares the two paths' lines.

use std::borrow::Cow;
use std::panic::{catch_unwind, AssertUnwindSafe};

use maugis::quad::certified::Options;
use maugis::quad::expr::integrate_range;
use maugis::{Budget, MAX_PREC};
use serde::Deserialize;
use serde_json::value::RawValue;
use serde_json::Value;

use super::cache::{parsed_end, parsed_expr};
use super::profile;
use super::response::{error_fields, integral_fields, write_object};

/// An `integrate` request as typed, borrowed from its line.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct Request<'a> {
    #[serde(borrow, default)]
    id: Option<&'a RawValue>,
    #[serde(rename = "fn")]
    function: &'a str,
    f: &'a str,
    #[serde(borrow)]
    a: &'a RawValue,
    #[serde(borrow)]
    b: &'a RawValue,
    #[serde(default)]
    prec: Option<u64>,
    #[serde(default)]
    budget_ms: Option<u64>,
    #[serde(borrow, default)]
    weight: Option<&'a RawValue>,
    #[serde(borrow, default)]
    decay: Option<&'a RawValue>,
}

/// Answers `line` into `out` if it is an `integrate` request this path takes (see the
/// module docs); otherwise writes nothing and returns false.
pub fn integrate(line: &str, out: &mut Vec<u8>) -> bool {
    let Some(req) = profile::timed(profile::JSON, || serde_json::from_str::<Request>(line).ok()) else {
        return false;
    };
    if req.function != "integrate" || req.weight.is_some() || req.decay.is_some() {
        return false;
    }
    let Some(prec) = (match req.prec {
        None => Some(super::DEFAULT_INTEGRAL_PREC),
        Some(p) => u32::try_from(p).ok().filter(|p| (2..=MAX_PREC).contains(p)),
    }) else {
        return false;
    };
    let Some(budget) = (match req.budget_ms {
        None => Some(Budget::DEFAULT),
        Some(ms) => Budget::from_millis(ms).ok(),
    }) else {
        return false;
    };
    let id = id_text(req.id);
    let answer = catch_unwind(AssertUnwindSafe(|| {
        let args = profile::timed(profile::ARGS, || {
            let f = parsed_expr(req.f).ok()?;
            let a = parsed_end(decimal_text(req.a)?).ok()?;
            let b = parsed_end(decimal_text(req.b)?).ok()?;
            Some((f, a, b))
        });
        let (f, a, b) = args?;
        let r = profile::timed(profile::EVAL, || budget.run(|| integrate_range(&f, &a, &b, None, None, prec, &Options::new())));
        Some(profile::timed(profile::RESPONSE, || match r {
            Ok(r) => integral_fields(&r, prec),
            Err(e) => error_fields(e.to_string(), e.is_time_limit()),
        }))
    }));
    let fields = match answer {
        Ok(None) => return false,
        Ok(Some(fields)) => fields,
        Err(_) => error_fields(super::INTERNAL_ERROR.to_string(), false),
    };
    profile::timed(profile::RESPONSE, || write_object(out, &id, fields));
    true
}

/// The id's JSON text as the general path writes it back: as typed when that is the
/// same (`null` for none, a string without escapes, `true`, `false`, a number without
/// an exponent), otherwise as `serde_json` writes the parsed value (an exponent as
/// `e+3`, escapes resolved, an object's keys sorted).
fn id_text(id: Option<&RawValue>) -> Cow<'_, str> {
    let Some(raw) = id.map(RawValue::get) else {
        return Cow::Borrowed("null");
    };
    let plain = match raw.as_bytes()[0] {
        b'"' => !raw.contains('\\'),
        b't' | b'f' | b'n' => true,
        b'-' | b'0'..=b'9' => !raw.contains(['e', 'E']),
        _ => false,
    };
    if plain {
        return Cow::Borrowed(raw);
    }
    let value: Value = serde_json::from_str(raw).unwrap_or(Value::Null);
    Cow::Owned(value.to_string())
}

/// The decimal text of an end: a string's content (trimmed) or a number's text;
/// `None` for anything else (the general path says what is wrong).
fn decimal_text(raw: &RawValue) -> Option<&str> {
    let t = raw.get();
    match t.as_bytes()[0] {
        b'"' if !t.contains('\\') => Some(t[1..t.len() - 1].trim()),
        b'-' | b'0'..=b'9' => Some(t),
        _ => None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The general path's line for `line`.
    fn general(line: &str) -> String {
        super::super::handle_line(line).to_string()
    }

    /// The fast path's line for `line`, `None` when it leaves the line to the general path
    /// (then it wrote nothing).
    fn fast(line: &str) -> Option<String> {
        let mut out = Vec::new();
        let taken = integrate(line, &mut out);
        assert!(taken || out.is_empty(), "{line}: left to the general path after writing");
        taken.then(|| String::from_utf8(out).expect("UTF-8"))
    }

    /// Each line the fast path takes gets, byte for byte, the general path's line: the
    /// ball, the absolute tolerance, the imaginary part, the warning of a shortfall, the
    /// library's errors, and the id in each of its JSON forms.
    #[test]
    fn takes_common_requests_and_answers_them_as_the_general_path() {
        let taken = [
            r#"{"id":1,"fn":"integrate","f":"1/(1+x^2)","a":"0","b":"1","prec":64}"#,
            r#"{"fn":"integrate","f":"1/(1+x^2)","a":0,"b":1.0}"#,
            r#"{"id":"run 7","fn":"integrate","f":"sin(x)","a":"-1","b":"1","prec":64}"#,
            r#"{"id":"é","fn":"integrate","f":"exp(-x)","a":" 0 ","b":"inf","prec":333,"budget_ms":60000}"#,
            r#"{"id":1.50,"fn":"integrate","f":"x","a":-0,"b":1E0,"prec":null,"budget_ms":null,"weight":null,"decay":null}"#,
            r#"{"id":1E+3,"fn":"integrate","f":"x","a":"0","b":"1"}"#,
            r#"{"id":"a\u0041","fn":"integrate","f":"x","a":"0","b":"1"}"#,
            r#"{"id":{"z":[1, 2],"a":null},"fn":"integrate","f":"x","a":"0","b":"1"}"#,
            r#"{"id":true,"fn":"integrate","f":"x","a":"0","b":"1"}"#,
            r#"{"id":null,"fn":"integrate","f":"x","a":"0","b":"1"}"#,
            r#" { "id" : 2 , "fn" : "integrate" , "f" : "x" , "a" : "0" , "b" : "1" } "#,
            // the imaginary part, and a shortfall with its warning
            r#"{"id":3,"fn":"integrate","f":"sqrt(x)","a":"-1","b":"1","prec":64}"#,
            // the library's errors
            r#"{"id":4,"fn":"integrate","f":"1/x","a":"-1","b":"1"}"#,
            r#"{"id":5,"fn":"integrate","f":"x^2","a":"0","b":"inf"}"#,
            r#"{"id":6,"fn":"integrate","f":"x","a":"1","b":"1"}"#,
        ];
        for line in taken {
            assert_eq!(fast(line).unwrap_or_else(|| panic!("{line}: not taken")), general(line), "{line}");
        }
    }

    /// A request stopped by its time budget answers `"refused": "time"` after the error
    /// and the id (the message holds the time spent, which differs between two runs).
    #[test]
    fn time_refusal_has_the_general_paths_fields() {
        let line = r#"{"id":5,"fn":"integrate","f":"sin(x)^2","a":"0","b":"1000","prec":333,"budget_ms":1}"#;
        let out = fast(line).expect("taken");
        let keys = |t: &str| serde_json::from_str::<serde_json::Map<String, Value>>(t).unwrap().keys().cloned().collect::<Vec<_>>();
        assert_eq!(keys(&out), keys(&general(line)));
        assert!(out.starts_with(r#"{"error":""#) && out.ends_with(r#"","id":5,"refused":"time"}"#), "{out}");
    }

    /// Lines the fast path leaves to the general path, which words their errors or reads
    /// the fields the fast path does not.
    #[test]
    fn leaves_the_rest_to_the_general_path() {
        let left = [
            r#"{"id":1,"fn":"bessel_j","n":0,"x":"1","prec":64}"#,
            r#"{"fn":"integrate","f":"x","a":"0","b":"1","weight":{"alpha":"-0.5"}}"#,
            r#"{"fn":"integrate","f":"exp(-x)","a":"0","b":"inf","decay":{"rate":1,"bound":1}}"#,
            r#"{"fn":"integrate","f":"x","a":"0","b":"1","prec":"64"}"#,
            r#"{"fn":"integrate","f":"x","a":"0","b":"1","prec":64.0}"#,
            r#"{"fn":"integrate","f":"x","a":"0","b":"1","prec":1}"#,
            r#"{"fn":"integrate","f":"x","a":"0","b":"1","prec":-5}"#,
            r#"{"fn":"integrate","f":"x","a":"0","b":"1","prec":4294967298}"#,
            r#"{"fn":"integrate","f":"x","a":"0","b":"1","budget_ms":0}"#,
            r#"{"fn":"integrate","f":"x","a":"0","b":"1","junk":1}"#,
            r#"{"fn":"integrate","f":"x","f":"x","a":"0","b":"1"}"#,
            r#"{"fn":"integrate","f":"x\u0020","a":"0","b":"1"}"#,
            r#"{"fn":"integrate","f":"sin(","a":"0","b":"1"}"#,
            r#"{"fn":"integrate","f":"x","a":"0..1","b":"1"}"#,
            r#"{"fn":"integrate","f":"x","a":true,"b":"1"}"#,
            r#"{"fn":"integrate","f":"x","a":"\u0030","b":"1"}"#,
            r#"{"fn":"integrate","f":"x","a":"0"}"#,
            r#"{"fn":"integrate","f":1,"a":"0","b":"1"}"#,
            r#"{"fn":"integrate","f":"x","a":"0","b":"1""#,
            r#"[1]"#,
        ];
        for line in left {
            assert_eq!(fast(line), None, "{line}");
        }
    }
}
