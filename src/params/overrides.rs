//! `--set path=value` overrides of single parameters (SI units, as the parameter set stores
//! them), with errors that name the key the user wrote.

use std::str::FromStr;

use super::ParameterSet;
use crate::error::Error;

/// One override `path=value`, e.g. `negative.diffusivity=3e-14` (m^2/s).
#[derive(Clone, Debug, PartialEq)]
pub struct Override {
    /// Dotted parameter path.
    pub path: String,
    /// New value in the parameter's SI unit.
    pub value: f64,
}

impl FromStr for Override {
    type Err = String;

    /// ```
    /// use cellstudio::params::Override;
    /// let o: Override = "cell.contact_resistance=0.01".parse().unwrap();
    /// assert_eq!((o.path.as_str(), o.value), ("cell.contact_resistance", 0.01));
    /// assert_eq!("x".parse::<Override>().unwrap_err(), "expected PATH=VALUE, e.g. negative.diffusivity=3e-14, got `x`");
    /// assert!("a.b=fast".parse::<Override>().unwrap_err().contains("`fast` is not a number"));
    /// ```
    fn from_str(s: &str) -> Result<Self, String> {
        let (path, value) = s
            .split_once('=')
            .ok_or_else(|| format!("expected PATH=VALUE, e.g. negative.diffusivity=3e-14, got `{s}`"))?;
        let (path, value) = (path.trim(), value.trim());
        let v: f64 = value.parse().map_err(|_| format!("`{path}`: `{value}` is not a number"))?;
        if !v.is_finite() {
            return Err(format!("`{path}`: `{value}` is not a finite number"));
        }
        Ok(Self { path: path.to_string(), value: v })
    }
}

/// Applies `overrides` in order and validates the result; errors name the overridden key.
///
/// ```
/// use cellstudio::params::{apply_overrides, chen2020};
/// let mut p = chen2020();
/// apply_overrides(&mut p, &["positive.thickness=7e-5".parse().unwrap()]).unwrap();
/// assert_eq!(p.positive.thickness, 7e-5);
/// let e = apply_overrides(&mut p, &["positive.thicknes=7e-5".parse().unwrap()]).unwrap_err().to_string();
/// assert!(e.contains("--set positive.thicknes"), "{e}");
/// let e = apply_overrides(&mut p, &["positive.thickness=-1".parse().unwrap()]).unwrap_err().to_string();
/// assert!(e.contains("positive.thickness (from --set)") && e.contains("-1"), "{e}");
/// ```
pub fn apply_overrides(p: &mut ParameterSet, overrides: &[Override]) -> Result<(), Error> {
    if overrides.is_empty() {
        return Ok(());
    }
    for o in overrides {
        p.set(&o.path, o.value).map_err(|_| Error::InvalidSetting {
            field: format!("--set {}", o.path),
            reason: format!("`{}` is not a scalar parameter of the set (e.g. negative.diffusivity)", o.path),
        })?;
    }
    p.validate().map_err(|e| match e {
        Error::InvalidParameter { field, value, reason } if overrides.iter().any(|o| o.path == field) => {
            Error::InvalidParameter { field: format!("{field} (from --set)"), value, reason }
        }
        other => other,
    })
}
