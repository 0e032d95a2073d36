//! The response line of an `integrate` request: which fields it has, and their JSON
//! text written straight into the output buffer.
//!
//! The fields are those of a `serde_json` object built from them, in its order (keys
//! sorted, as `serde_json::Map` keeps them), so that a line written here is byte for
//! byte the line the general path serialises (the fast path's test compares the two).

use std::borrow::Cow;

use maugis::quad::certified::Integral;
use maugis::quad::expr::shortfall;
use serde_json::Value;

use crate::integrate::BallText;

/// A field's value.
pub enum Field<'a> {
    Text(Cow<'a, str>),
    Uint(u64),
    Bool(bool),
    /// JSON text, written as it is.
    Json(&'a str),
}

impl Field<'_> {
    /// The value as `serde_json` holds it (`Json` text parsed).
    pub fn into_value(self) -> Value {
        match self {
            Field::Text(t) => Value::String(t.into_owned()),
            Field::Uint(n) => Value::from(n),
            Field::Bool(b) => Value::Bool(b),
            Field::Json(t) => serde_json::from_str(t).unwrap_or(Value::Null),
        }
    }
}

/// The fields of an integral's response at `prec` bits besides `"id"`, in key order:
/// the ball ([`BallText`]), `"prec"`, `"evaluations"`, and `"goal_met": false` with a
/// `"warning"` when a limit stopped it before its goal.
pub fn integral_fields(r: &Integral, prec: u32) -> Vec<(&'static str, Field<'static>)> {
    let ball = BallText::of(r, prec);
    let mut fields = Vec::with_capacity(11);
    fields.extend(ball.abs_tol.map(|t| ("abs_tol", Field::Text(t.into()))));
    fields.push(("evaluations", Field::Uint(r.evaluations)));
    let note = shortfall(r);
    if note.is_some() {
        fields.push(("goal_met", Field::Bool(false)));
    }
    if let Some((im_mid, im_rad)) = ball.im {
        fields.extend([("im_mid", Field::Text(im_mid.into())), ("im_rad", Field::Text(im_rad.into()))]);
    }
    fields.extend([("mid", Field::Text(ball.mid.into())), ("prec", Field::Uint(prec.into())), ("rad", Field::Text(ball.rad.into()))]);
    fields.extend(note.map(|n| ("warning", Field::Text(n.into()))));
    fields
}

/// The fields of an error line besides `"id"`: the message, and `"refused": "time"`
/// when the time budget refused or stopped the request.
pub fn error_fields(msg: String, time_limit: bool) -> Vec<(&'static str, Field<'static>)> {
    let mut fields = vec![("error", Field::Text(msg.into()))];
    if time_limit {
        fields.push(("refused", Field::Text("time".into())));
    }
    fields
}

/// Appends the object `{"id": ID, fields..}` to `out`, keys sorted (the fields are
/// sorted first unless they come so); `id` is the id's JSON text (`null`, a number, a
/// string).
pub fn write_object<'a>(out: &mut Vec<u8>, id: &'a str, mut fields: Vec<(&'static str, Field<'a>)>) {
    if !fields.is_sorted_by_key(|(k, _)| *k) {
        fields.sort_unstable_by_key(|(k, _)| *k);
    }
    let at = fields.partition_point(|(k, _)| *k < "id");
    fields.insert(at, ("id", Field::Json(id)));
    out.push(b'{');
    for (i, (key, value)) in fields.iter().enumerate() {
        if i > 0 {
            out.push(b',');
        }
        write_str(out, key);
        out.push(b':');
        match value {
            Field::Text(t) => write_str(out, t),
            Field::Uint(n) => write_uint(out, *n),
            Field::Bool(b) => out.extend_from_slice(if *b { b"true" } else { b"false" }),
            Field::Json(t) => out.extend_from_slice(t.as_bytes()),
        }
    }
    out.push(b'}');
}

/// The decimal digits of `n`.
fn write_uint(out: &mut Vec<u8>, mut n: u64) {
    let mut digits = [0u8; 20];
    let mut i = digits.len();
    loop {
        i -= 1;
        digits[i] = b'0' + (n % 10) as u8;
        n /= 10;
        if n == 0 {
            break;
        }
    }
    out.extend_from_slice(&digits[i..]);
}

/// A JSON string: as it is between quotes when nothing in it needs an escape (the
/// decimals, the keys), otherwise through `serde_json`.
fn write_str(out: &mut Vec<u8>, s: &str) {
    if s.bytes().all(|b| b >= 0x20 && b != b'"' && b != b'\\') {
        out.push(b'"');
        out.extend_from_slice(s.as_bytes());
        out.push(b'"');
    } else {
        // cannot fail: a str always serialises, and a Vec takes every write
        let _ = serde_json::to_writer(&mut *out, s);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// An object written here is `serde_json`'s serialisation of the same object:
    /// keys sorted whatever their order, the id placed among them, integers at both
    /// ends of `u64`, and strings that need escapes.
    #[test]
    fn writes_what_serde_json_writes() {
        let fields = || {
            vec![
                ("zeta", Field::Uint(0)),
                ("mid", Field::Text("1.5e-1".into())),
                ("big", Field::Uint(u64::MAX)),
                ("warning", Field::Text("a \"quoted\"\\ line\n\u{1}é".into())),
                ("goal_met", Field::Bool(false)),
                ("abs_tol", Field::Json("[1,2]")),
            ]
        };
        for id in ["null", "7", "\"run\""] {
            let mut out = Vec::new();
            write_object(&mut out, id, fields());
            let mut map = serde_json::Map::new();
            map.insert("id".into(), serde_json::from_str(id).unwrap());
            map.extend(fields().into_iter().map(|(k, v)| (k.to_string(), v.into_value())));
            assert_eq!(String::from_utf8(out).unwrap(), Value::Object(map).to_string());
        }
    }
}
