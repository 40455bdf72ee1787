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

/// Plausible cell temperatures (K): -73 to 127 degC. A value below reads as degrees Celsius.
pub(crate) const TEMPERATURE_RANGE: std::ops::RangeInclusive<f64> = 200.0..=400.0;

/// A temperature (K) within [`TEMPERATURE_RANGE`].
pub(crate) fn temperature(field: &str, value: f64) -> Result<(), Error> {
    let reason = format!(
        "must be a temperature in kelvin between {} and {} K (25 degC is 298.15 K)",
        TEMPERATURE_RANGE.start(),
        TEMPERATURE_RANGE.end()
    );
    check(field, value, TEMPERATURE_RANGE.contains(&value), &reason)
}

/// `0 < value < 1`.
pub(crate) fn open_unit(field: &str, value: f64) -> Result<(), Error> {
    check(field, value, value > 0.0 && value < 1.0, "must lie strictly between 0 and 1")
}
