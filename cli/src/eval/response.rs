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

use crate::integrate::ball_fields;

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

/// The fields of an integral's response at `prec` bits, besides `"id"`: the ball
/// ([`ball_fields`]), `"prec"`, `"evaluations"`, and `"goal_met": false` with a
/// `"warning"` when a limit stopped it before its goal.
pub fn integral_fields(r: &Integral, prec: u32) -> Vec<(&'static str, Field<'static>)> {
    let mut fields: Vec<(&'static str, Field<'static>)> = ball_fields(r, prec).into_iter().map(|(k, v)| (k, Field::Text(v.into()))).collect();
    fields.push(("prec", Field::Uint(prec.into())));
    fields.push(("evaluations", Field::Uint(r.evaluations)));
    if let Some(note) = shortfall(r) {
        fields.push(("goal_met", Field::Bool(false)));
        fields.push(("warning", Field::Text(note.into())));
    }
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

/// Appends the object `{"id": ID, fields..}` to `out`, keys sorted; `id` is the id's
/// JSON text (`null`, a number, a string).
pub fn write_object<'a>(out: &mut Vec<u8>, id: &'a str, mut fields: Vec<(&'static str, Field<'a>)>) {
    fields.push(("id", Field::Json(id)));
    fields.sort_unstable_by_key(|(k, _)| *k);
    out.push(b'{');
    for (i, (key, value)) in fields.iter().enumerate() {
        if i > 0 {
            out.push(b',');
        }
        write_str(out, key);
        out.push(b':');
        match value {
            Field::Json(t) => out.extend_from_slice(t.as_bytes()),
            Field::Text(t) => write_str(out, t),
            Field::Uint(n) => out.extend_from_slice(n.to_string().as_bytes()),
            Field::Bool(b) => out.extend_from_slice(if *b { b"true" } else { b"false" }),
        }
    }
    out.push(b'}');
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
