//! Current protocols: constant current or C-rate steps, rests, and current-vs-time tables.
//! Current is in amperes, discharge positive.

use serde::{Deserialize, Serialize};

use crate::error::Error;
use crate::params::function::interpolate;

/// One step of a protocol.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "snake_case", deny_unknown_fields)]
pub enum Step {
    /// Constant current (A) for `duration` (s), ended early by a voltage cut-off.
    Current { current: f64, duration: f64 },
    /// Constant C-rate (multiples of the nominal capacity per hour) for `duration` (s),
    /// ended early by a voltage cut-off.
    CRate { rate: f64, duration: f64 },
    /// Constant power (W, discharge positive) for `duration` (s), ended early by a voltage
    /// cut-off; the current follows the state as `I = P / V`.
    Power { power: f64, duration: f64 },
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
            Step::Rest { .. } => Demand::Current(0.0),
            Step::Table { time, current } => {
                Demand::Current(interpolate(time, current, t.clamp(0.0, time[time.len() - 1])))
            }
        }
    }

    /// Whether voltage cut-offs end this step.
    pub fn has_cutoffs(&self) -> bool {
        !matches!(self, Step::Rest { .. })
    }
}

impl Protocol {
    /// Constant-current discharge at `rate` C until the lower cut-off (at most `1.5 / rate` h).
    pub fn discharge(rate: f64) -> Self {
        Self { steps: vec![Step::CRate { rate, duration: 1.5 * 3600.0 / rate.abs() }] }
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
            match step {
                Step::Current { current: v, .. } | Step::CRate { rate: v, .. } if !v.is_finite() => {
                    return Err(Error::invalid(field("current"), *v, "must be finite"));
                }
                Step::Power { power, .. } if !power.is_finite() => {
                    return Err(Error::invalid(field("power"), *power, "must be finite"));
                }
                Step::Table { time, current } => {
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
