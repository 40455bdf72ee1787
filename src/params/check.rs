//! Range checks shared by every parameter struct: each error names the field and value.

use crate::error::Error;

/// `ok` and finite, else an error with `reason`.
pub(crate) fn check(field: &str, value: f64, ok: bool, reason: &str) -> Result<(), Error> {
    if ok && value.is_finite() { Ok(()) } else { Err(Error::invalid(field, value, reason)) }
}

/// `value > 0` and finite.
pub(crate) fn positive(field: &str, value: f64) -> Result<(), Error> {
    check(field, value, value > 0.0, "must be positive")
}

/// `value >= 0` and finite.
pub(crate) fn non_negative(field: &str, value: f64) -> Result<(), Error> {
    check(field, value, value >= 0.0, "must not be negative")
}

/// `0 < value < 1`.
pub(crate) fn open_unit(field: &str, value: f64) -> Result<(), Error> {
    check(field, value, value > 0.0 && value < 1.0, "must lie strictly between 0 and 1")
}
