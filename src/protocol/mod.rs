//! Protocols: constant current, C-rate or power steps (each ended by the cell's cut-offs or
//! its own voltage limit), voltage holds ended by a current limit, rests, and current-vs-time
//! tables. Current is in amperes, discharge positive. [`experiment`] reads PyBaMM-style
//! experiment strings ("Charge at 1C until 4.2 V", "Hold at 4.2 V until C/50").

pub mod experiment;

use serde::{Deserialize, Serialize};

use crate::error::Error;
use crate::params::function::interpolate;

/// One step of a protocol.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "snake_case", deny_unknown_fields)]
pub enum Step {
    /// Constant current (A) for `duration` (s), ended early by a voltage cut-off or
    /// `until_voltage` (V: reached falling on discharge, rising on charge).
    Current {
        current: f64,
        duration: f64,
        #[serde(default, skip_serializing_if = "Option::is_none")]
        until_voltage: Option<f64>,
    },
    /// Constant C-rate (multiples of the nominal capacity per hour) for `duration` (s),
    /// ended early as [`Step::Current`].
    CRate {
        rate: f64,
        duration: f64,
        #[serde(default, skip_serializing_if = "Option::is_none")]
        until_voltage: Option<f64>,
    },
    /// Constant power (W, discharge positive) for `duration` (s), ended early as
    /// [`Step::Current`]; the current follows the state as `I = P / V`.
    Power {
        power: f64,
        duration: f64,
        #[serde(default, skip_serializing_if = "Option::is_none")]
        until_voltage: Option<f64>,
    },
    /// Constant terminal voltage `voltage` (V) for `duration` (s), ended early when the
    /// current's magnitude falls to `until_current` (A); the current is whatever holds the
    /// voltage.
    Hold {
        voltage: f64,
        duration: f64,
        #[serde(default, skip_serializing_if = "Option::is_none")]
        until_current: Option<f64>,
    },
    /// Zero current for `duration` (s).
    Rest { duration: f64 },
    /// Piecewise-linear current (A) through the points `(time, current)`; times (s) start at
    /// zero, relative to the step start, and increase strictly.
    Table { time: Vec<f64>, current: Vec<f64> },
}

/// The electrical demand of a step at one instant.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Demand {
    /// Current (A, discharge positive).
    Current(f64),
    /// Power (W, discharge positive).
    Power(f64),
    /// Terminal voltage (V): the current is an unknown of the step.
    Voltage(f64),
}

/// A sequence of steps.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Protocol {
    pub steps: Vec<Step>,
}

impl Step {
    /// Duration of the step (s).
    pub fn duration(&self) -> f64 {
        match self {
            Step::Current { duration, .. }
            | Step::CRate { duration, .. }
            | Step::Power { duration, .. }
            | Step::Hold { duration, .. }
            | Step::Rest { duration } => *duration,
            Step::Table { time, .. } => time.last().copied().unwrap_or(0.0),
        }
    }

    /// What the step demands at `t` seconds into it, for a cell of `capacity` (A h).
    pub fn demand_at(&self, t: f64, capacity: f64) -> Demand {
        match self {
            Step::Current { current, .. } => Demand::Current(*current),
            Step::CRate { rate, .. } => Demand::Current(rate * capacity),
            Step::Power { power, .. } => Demand::Power(*power),
            Step::Hold { voltage, .. } => Demand::Voltage(*voltage),
            Step::Rest { .. } => Demand::Current(0.0),
            Step::Table { time, current } => {
                Demand::Current(interpolate(time, current, t.clamp(0.0, time[time.len() - 1])))
            }
        }
    }

    /// The key of what the step demands and its value, as a protocol file writes them:
    /// `("current", A)`, `("rate", C)`, `("power", W)`, `("voltage", V)` for a hold,
    /// `("current", A)` at the start of a table; `None` for a rest.
    pub fn demand(&self) -> Option<(&'static str, f64)> {
        match self {
            Step::Current { current, .. } => Some(("current", *current)),
            Step::CRate { rate, .. } => Some(("rate", *rate)),
            Step::Power { power, .. } => Some(("power", *power)),
            Step::Hold { voltage, .. } => Some(("voltage", *voltage)),
            Step::Rest { .. } => None,
            Step::Table { current, .. } => current.first().map(|&i| ("current", i)),
        }
    }

    /// Times (s, from the step start) inside the step where its current has a kink: the
    /// interior points of a table; none for the other steps.
    pub fn kinks(&self) -> &[f64] {
        match self {
            Step::Table { time, .. } if time.len() > 2 => &time[1..time.len() - 1],
            _ => &[],
        }
    }

    /// Whether voltage cut-offs end this step.
    pub fn has_cutoffs(&self) -> bool {
        !matches!(self, Step::Rest { .. } | Step::Hold { .. })
    }

    /// The voltage window (V) that ends this step, from the cell's cut-offs `(lower, upper)`
    /// narrowed by the step's own `until_voltage` on the side its current flows to.
    pub fn voltage_window(&self, (lower, upper): (f64, f64)) -> (f64, f64) {
        let (sign, until) = match self {
            Step::Current { current: v, until_voltage, .. } | Step::CRate { rate: v, until_voltage, .. } | Step::Power { power: v, until_voltage, .. } => {
                (v.signum(), *until_voltage)
            }
            _ => (0.0, None),
        };
        match until {
            Some(u) if sign > 0.0 => (lower.max(u), upper),
            Some(u) if sign < 0.0 => (lower, upper.min(u)),
            _ => (lower, upper),
        }
    }
}

impl Protocol {
    /// Constant-current discharge at `rate` C until the lower cut-off (at most `1.5 / rate` h).
    pub fn discharge(rate: f64) -> Self {
        Self::discharge_within(rate, 1.5 * 3600.0 / rate.abs())
    }

    /// Constant-current discharge at `rate` C until the lower cut-off or `duration` (s), e.g.
    /// [`crate::params::ParameterSet::discharge_time_limit`], which only a cut-short run reaches.
    pub fn discharge_within(rate: f64, duration: f64) -> Self {
        Self { steps: vec![Step::CRate { rate, duration, until_voltage: None }] }
    }

    /// Total duration (s).
    pub fn duration(&self) -> f64 {
        self.steps.iter().map(Step::duration).sum()
    }

    /// Checks durations, finiteness and table shapes; errors name the step.
    pub fn validate(&self) -> Result<(), Error> {
        if self.steps.is_empty() {
            return Err(Error::InvalidSetting { field: "protocol.steps".into(), reason: "is empty".into() });
        }
        for (i, step) in self.steps.iter().enumerate() {
            let field = |name: &str| format!("protocol.steps[{i}].{name}");
            let d = step.duration();
            if !(d > 0.0 && d.is_finite()) {
                return Err(Error::invalid(field("duration"), d, "must be positive and finite"));
            }
            if let Step::Current { until_voltage: Some(u), .. } | Step::CRate { until_voltage: Some(u), .. } | Step::Power { until_voltage: Some(u), .. } = step {
                if !(u.is_finite() && *u > 0.0) {
                    return Err(Error::invalid(field("until_voltage"), *u, "must be positive and finite"));
                }
            }
            match (step, step.demand()) {
                (Step::Current { .. } | Step::CRate { .. } | Step::Power { .. }, Some((key, v))) if !v.is_finite() => {
                    return Err(Error::invalid(field(key), v, "must be finite"));
                }
                (Step::Hold { voltage, .. }, _) if !(voltage.is_finite() && *voltage > 0.0) => {
                    return Err(Error::invalid(field("voltage"), *voltage, "must be positive and finite"));
                }
                (Step::Hold { until_current: Some(i), .. }, _) if !(i.is_finite() && *i > 0.0) => {
                    return Err(Error::invalid(field("until_current"), *i, "must be positive and finite (A, a magnitude)"));
                }
                (Step::Table { time, current }, _) => {
                    if time.len() < 2 || time.len() != current.len() {
                        return Err(Error::InvalidSetting {
                            field: field("time"),
                            reason: format!(
                                "needs at least 2 points and as many currents ({} times, {} currents)",
                                time.len(),
                                current.len()
                            ),
                        });
                    }
                    if time[0] != 0.0 {
                        return Err(Error::invalid(field("time"), time[0], "must start at 0"));
                    }
                    if let Some(w) = time.windows(2).find(|w| !(w[1] > w[0])) {
                        return Err(Error::invalid(field("time"), w[1], "must increase strictly"));
                    }
                    if let Some(v) = current.iter().find(|v| !v.is_finite()) {
                        return Err(Error::invalid(field("current"), *v, "must be finite"));
                    }
                }
                _ => {}
            }
        }
        Ok(())
    }
}
