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
    apply(p, overrides, "--set")
}

/// [`apply_overrides`] with errors naming `source` (`--set` or a file).
fn apply(p: &mut ParameterSet, overrides: &[Override], source: &str) -> Result<(), Error> {
    if overrides.is_empty() {
        return Ok(());
    }
    for o in overrides {
        p.set(&o.path, o.value).map_err(|_| Error::InvalidSetting {
            field: format!("{source} {}", o.path),
            reason: format!("`{}` is not a scalar parameter of the set (e.g. negative.diffusivity)", o.path),
        })?;
    }
    p.validate().map_err(|e| match e {
        Error::InvalidParameter { field, value, reason } if overrides.iter().any(|o| o.path == field) => {
            Error::InvalidParameter { field: format!("{field} (from {source})"), value, reason }
        }
        other => other,
    })
}

/// A parameter file that names a base set and overrides a few scalars (SI units):
///
/// ```toml
/// base = "chen2020"
/// name = "Chen 2020, thinner positive"   # optional
/// [positive]
/// thickness = 6.5e-5
/// ```
///
/// `origin` names the file in errors, each with the key as the file writes it.
///
/// ```
/// let table: toml::Table = toml::from_str("base = \"chen2020\"\n[positive]\nthickness = 6.5e-5\n").unwrap();
/// let p = cellstudio::params::from_base_table(&table, "mine.toml").unwrap();
/// assert_eq!(p.positive.thickness, 6.5e-5);
/// let table: toml::Table = toml::from_str("base = \"chen2020\"\n[positive]\nthicknes = 6.5e-5\n").unwrap();
/// let e = cellstudio::params::from_base_table(&table, "mine.toml").unwrap_err().to_string();
/// assert!(e.contains("mine.toml positive.thicknes"), "{e}");
/// ```
pub fn from_base_table(table: &toml::Table, origin: &str) -> Result<ParameterSet, Error> {
    let setting = |key: &str, reason: String| Error::InvalidSetting { field: format!("{origin} {key}"), reason };
    let mut p = match table.get("base").and_then(|v| v.as_str()) {
        Some("chen2020") => super::chen2020(),
        Some(other) => return Err(setting("base", format!("unknown base set `{other}` (known: chen2020)"))),
        None => return Err(setting("base", "must name a base set, e.g. base = \"chen2020\"".into())),
    };
    let mut overrides = Vec::new();
    let mut stack: Vec<(String, &toml::Table)> = vec![(String::new(), table)];
    while let Some((prefix, t)) = stack.pop() {
        for (key, value) in t {
            let path = if prefix.is_empty() { key.clone() } else { format!("{prefix}.{key}") };
            match value {
                toml::Value::Table(inner) => stack.push((path, inner)),
                toml::Value::Float(v) => overrides.push(Override { path, value: *v }),
                toml::Value::Integer(v) => overrides.push(Override { path, value: *v as f64 }),
                toml::Value::String(name) if path == "name" => p.name = name.clone(),
                _ if path == "base" => {}
                _ => return Err(setting(&path, "expected a number (SI units)".into())),
            }
        }
    }
    overrides.sort_by(|a, b| a.path.cmp(&b.path));
    apply(&mut p, &overrides, origin)?;
    Ok(p)
}
