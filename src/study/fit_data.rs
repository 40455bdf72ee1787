//! The `[data]` / `[[data]]` entries of a fitting study: each experiment's recording and
//! format, synthetic noise, temperature, initial state, protocol and weight, with checks that
//! name the entry.

use std::path::PathBuf;

use serde::{Deserialize, Serialize};

use crate::data::CsvFormat;
use crate::error::Error;
use crate::problem::fitting::{FitParameter, INITIAL_SOC};

/// A recording to fit, with what belongs to its experiment.
#[derive(Clone, Debug, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct DataChoice {
    /// Label in reports (default `data1`, `data2`, ... in file order).
    #[serde(default)]
    pub name: Option<String>,
    /// CSV file or raw cycler export, relative to the working directory (the CLI's `--data`
    /// overrides it in a study with one entry).
    pub file: PathBuf,
    #[serde(default)]
    pub format: CsvFormat,
    /// For synthetic studies only: Gaussian noise (V) added to the voltage of the study's own
    /// `file` (a simulated curve), seeded by `noise_seed`. Never added to a recording given
    /// with `--data`; the report says when it was added.
    #[serde(default)]
    pub synthetic_noise: f64,
    #[serde(default)]
    pub noise_seed: u64,
    /// The recording begins at rest: start from the state whose open-circuit voltage is the
    /// first recorded voltage instead of the parameter set's initial concentrations.
    #[serde(default)]
    pub start_at_rest_voltage: bool,
    /// Weight (-) of this experiment's cost in the sum over experiments.
    #[serde(default = "one")]
    pub weight: f64,
    /// Ambient and initial temperature (K) of the experiment; the parameter set's when absent.
    #[serde(default)]
    pub temperature: Option<f64>,
    /// Initial state of charge (-): a number fixes it, a table `{ initial, lower, upper }`
    /// fits it as this experiment's own (nuisance) parameter.
    #[serde(default)]
    pub initial_soc: Option<InitialSoc>,
    /// Protocol file (TOML) driving the model instead of the recorded current; its duration
    /// must cover the recording.
    #[serde(default)]
    pub protocol: Option<PathBuf>,
}

fn one() -> f64 {
    1.0
}

/// The initial state of charge of one experiment.
#[derive(Clone, Copy, Debug, Deserialize, Serialize)]
#[serde(untagged)]
pub enum InitialSoc {
    Fixed(f64),
    Fitted { initial: f64, lower: f64, upper: f64 },
}

/// `[data]` (one table) or `[[data]]` (an array of tables), with errors that name the entry.
pub(crate) fn one_or_many<'de, D: serde::Deserializer<'de>>(d: D) -> Result<Vec<DataChoice>, D::Error> {
    use serde::de::Error as _;
    let value = toml::Value::deserialize(d)?;
    match value {
        toml::Value::Array(entries) if entries.is_empty() => Err(D::Error::custom("[[data]] needs at least one entry")),
        toml::Value::Array(entries) => entries
            .into_iter()
            .enumerate()
            .map(|(k, e)| e.try_into().map_err(|e| D::Error::custom(format!("[[data]] entry {}: {e}", k + 1))))
            .collect(),
        toml::Value::Table(_) => value.try_into().map(|d| vec![d]).map_err(|e| D::Error::custom(format!("[data]: {e}"))),
        _ => Err(D::Error::custom("`data` must be a table [data] or an array of tables [[data]]")),
    }
}

impl DataChoice {
    /// The experiment's label: `name`, or `data<k+1>`.
    pub fn label(&self, k: usize) -> String {
        self.name.clone().unwrap_or_else(|| format!("data{}", k + 1))
    }

    pub(crate) fn validate(&self, k: usize) -> Result<(), Error> {
        let field = |f: &str| format!("data.{}.{f}", self.label(k));
        if !(self.synthetic_noise >= 0.0 && self.synthetic_noise.is_finite()) {
            return Err(Error::invalid(field("synthetic_noise"), self.synthetic_noise, "must be non-negative"));
        }
        if !(self.weight >= 0.0 && self.weight.is_finite()) {
            return Err(Error::invalid(field("weight"), self.weight, "must be non-negative and finite"));
        }
        if let Some(t) = self.temperature {
            crate::params::check::temperature(&field("temperature"), t)?;
        }
        match self.initial_soc {
            Some(_) if self.start_at_rest_voltage => Err(Error::InvalidSetting {
                field: field("initial_soc"),
                reason: "give either initial_soc or start_at_rest_voltage = true, not both".into(),
            }),
            Some(InitialSoc::Fixed(v)) if !(0.0..=1.0).contains(&v) => Err(Error::invalid(field("initial_soc"), v, "must lie in [0, 1]")),
            Some(InitialSoc::Fitted { initial, lower, upper }) => {
                let p = FitParameter::linear(INITIAL_SOC, initial, lower, upper);
                if !(0.0 <= lower && upper <= 1.0) {
                    return Err(Error::invalid(field("initial_soc.upper"), upper, format!("bounds [{lower}, {upper}] must lie in [0, 1]")));
                }
                p.validate(&crate::params::chen2020()).map_err(|e| Error::InvalidSetting { field: field("initial_soc"), reason: e.to_string() })
            }
            _ => Ok(()),
        }
    }
}
