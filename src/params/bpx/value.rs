//! One BPX value read: a number checked against the range its key allows, or an error that
//! names the BPX key path (`Parameterisation/Cell/Volume [m3]`), what was found there, and
//! which of our fields it fed.

use std::collections::BTreeMap;

use serde_json::Value;

use super::super::check::check;
use crate::error::Error;

/// How a BPX number must lie.
#[derive(Clone, Copy)]
pub(super) enum Check {
    Finite,
    Positive,
    NonNegative,
    /// (0, 1)
    OpenUnit,
    /// [0, 1]
    ClosedUnit,
    /// (0, 1]
    HalfOpenUnit,
}

impl Check {
    /// `v` if it lies as `self` requires, else an error naming `path`.
    pub(super) fn apply(self, path: &str, v: f64) -> Result<f64, Error> {
        let (ok, reason) = match self {
            Check::Finite => (true, "must be finite"),
            Check::Positive => (v > 0.0, "must be positive"),
            Check::NonNegative => (v >= 0.0, "must not be negative"),
            Check::OpenUnit => (v > 0.0 && v < 1.0, "must lie strictly between 0 and 1"),
            Check::ClosedUnit => ((0.0..=1.0).contains(&v), "must lie between 0 and 1"),
            Check::HalfOpenUnit => (v > 0.0 && v <= 1.0, "must lie in (0, 1]"),
        };
        check(path, v, ok, reason).map(|()| v)
    }
}

/// A JSON value as an error message names it.
pub(super) fn describe(v: &Value) -> String {
    match v {
        Value::Null => "null".into(),
        Value::Bool(b) => format!("the boolean {b}"),
        Value::Number(n) => format!("the number {n}"),
        Value::String(s) => format!("the string {s:?}"),
        Value::Array(_) => "an array".into(),
        Value::Object(_) => "an object".into(),
    }
}

/// The error for a value of the wrong JSON type.
pub(super) fn type_error(path: &str, expected: &str, v: &Value) -> Error {
    Error::InvalidSetting {
        field: path.into(),
        reason: format!("expected {expected}, found {}", describe(v)),
    }
}

/// The error for a required key that is absent.
pub(super) fn missing(path: &str) -> Error {
    Error::InvalidSetting { field: path.into(), reason: "required BPX key is missing".into() }
}

/// A JSON number checked against `check`; strings (expressions) are refused.
pub(super) fn number(path: &str, v: &Value, check: Check) -> Result<f64, Error> {
    match v.as_f64() {
        Some(x) if v.is_number() => check.apply(path, x),
        _ => Err(type_error(path, "a number", v)),
    }
}

/// Names the BPX key behind a failing field of ours: `origin` maps our field paths to the
/// BPX key(s) they came from, and the error's field becomes `` `key` -> `field` ``.
pub(super) fn relabel(e: Error, origin: &BTreeMap<String, String>) -> Error {
    let label = |field: String| match origin.get(&field) {
        Some(src) => format!("{src}` -> `{field}"),
        None => field,
    };
    match e {
        Error::InvalidParameter { field, value, reason } => {
            Error::InvalidParameter { field: label(field), value, reason }
        }
        Error::InvalidSetting { field, reason } => Error::InvalidSetting { field: label(field), reason },
        other => other,
    }
}
