//! How a cycler's CSV maps onto a [`Recording`](super::Recording): column names, units and the
//! sign convention of the current.

use serde::{Deserialize, Serialize};

use crate::error::Error;

/// Column names, units and current sign of a recording CSV. Defaults read the files this
/// crate writes (`time_s`, `current_A`, `voltage_V`, optional `temperature_K`, discharge
/// positive).
///
/// ```
/// use cellstudio::data::CsvFormat;
/// let f: CsvFormat = toml::from_str("time = \"Test_Time(s)\"\ncurrent_unit = \"mA\"\ndischarge_positive = false").unwrap();
/// assert_eq!(f.current_factor().unwrap(), -1e-3);
/// assert!(toml::from_str::<CsvFormat>("voltage_units = \"V\"").is_err());
/// ```
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct CsvFormat {
    /// Column holding time.
    pub time: String,
    /// Column holding current.
    pub current: String,
    /// Column holding terminal voltage.
    pub voltage: String,
    /// Column holding temperature, if any; a missing optional column is not an error.
    pub temperature: Option<String>,
    /// Unit of the time column: `s`, `min` or `h`.
    pub time_unit: String,
    /// Unit of the current column: `A` or `mA`.
    pub current_unit: String,
    /// Unit of the voltage column: `V` or `mV`.
    pub voltage_unit: String,
    /// Unit of the temperature column: `K` or `degC`.
    pub temperature_unit: String,
    /// Whether the file's discharge current is positive (this crate's convention). Set to
    /// `false` for cyclers that log discharge as negative current.
    pub discharge_positive: bool,
}

impl Default for CsvFormat {
    fn default() -> Self {
        Self {
            time: "time_s".into(),
            current: "current_A".into(),
            voltage: "voltage_V".into(),
            temperature: Some("temperature_K".into()),
            time_unit: "s".into(),
            current_unit: "A".into(),
            voltage_unit: "V".into(),
            temperature_unit: "K".into(),
            discharge_positive: true,
        }
    }
}

fn unknown_unit(field: &str, unit: &str, allowed: &str) -> Error {
    Error::InvalidSetting { field: field.into(), reason: format!("unknown unit `{unit}` (expected {allowed})") }
}

impl CsvFormat {
    /// Seconds per unit of the time column.
    pub fn time_factor(&self) -> Result<f64, Error> {
        match self.time_unit.as_str() {
            "s" => Ok(1.0),
            "min" => Ok(60.0),
            "h" => Ok(3600.0),
            u => Err(unknown_unit("time_unit", u, "s, min or h")),
        }
    }

    /// Amperes (discharge positive) per unit of the current column.
    pub fn current_factor(&self) -> Result<f64, Error> {
        let magnitude = match self.current_unit.as_str() {
            "A" => 1.0,
            "mA" => 1e-3,
            u => return Err(unknown_unit("current_unit", u, "A or mA")),
        };
        Ok(if self.discharge_positive { magnitude } else { -magnitude })
    }

    /// Volts per unit of the voltage column.
    pub fn voltage_factor(&self) -> Result<f64, Error> {
        match self.voltage_unit.as_str() {
            "V" => Ok(1.0),
            "mV" => Ok(1e-3),
            u => Err(unknown_unit("voltage_unit", u, "V or mV")),
        }
    }

    /// Kelvin of a temperature reading.
    pub fn temperature_in_kelvin(&self, value: f64) -> Result<f64, Error> {
        match self.temperature_unit.as_str() {
            "K" => Ok(value),
            "degC" | "C" => Ok(value + 273.15),
            u => Err(unknown_unit("temperature_unit", u, "K or degC")),
        }
    }
}
