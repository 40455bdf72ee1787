//! Limits on simulated metrics (nonlinear constraints), e.g. a least plating-free charge
//! rate or capacity:
//!
//! ```toml
//! [[limits]]
//! metric = "fast_charge_rate"
//! lower = 0.6
//! ```
//!
//! `design` ranks every candidate outside a limit below every one inside, and among
//! themselves by how far outside they lie (Deb's feasibility rule, so a search that starts
//! outside is led inside), and names the limits active at its optimum; `sweep` marks such points
//! `outside_limits` and keeps them out of its best; `pareto` keeps them off the front. Each
//! run counts them.

use serde::{Deserialize, Serialize};

use crate::error::Error;
use crate::problem::design::{DesignMetrics, Metric};

/// A bound on one metric (its unit: W h/kg, C, A h, ...).
#[derive(Clone, Debug, PartialEq, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct Limit {
    pub metric: Metric,
    #[serde(default)]
    pub lower: Option<f64>,
    #[serde(default)]
    pub upper: Option<f64>,
}

/// A limit is active at a design when its metric lies within this fraction of the bound's
/// magnitude from it.
pub const ACTIVE_WITHIN: f64 = 0.01;

impl Limit {
    /// Checks the bounds of `limits[k]`; errors name the field.
    pub fn validate(&self, k: usize) -> Result<(), Error> {
        let field = |f: &str| format!("limits[{k}].{f}");
        if self.lower.is_none() && self.upper.is_none() {
            return Err(Error::InvalidSetting { field: format!("limits[{k}]"), reason: "needs `lower`, `upper` or both".into() });
        }
        for (name, v) in [("lower", self.lower), ("upper", self.upper)] {
            if let Some(v) = v.filter(|v| !v.is_finite()) {
                return Err(Error::invalid(field(name), v, "must be finite"));
            }
        }
        if let (Some(lo), Some(hi)) = (self.lower, self.upper) {
            if !(lo < hi) {
                return Err(Error::invalid(field("upper"), hi, format!("must exceed lower = {lo}")));
            }
        }
        Ok(())
    }

    /// How far design metrics `m` lie outside this limit, relative to the bound's magnitude
    /// (0 inside; infinite for a metric that could not be computed).
    pub fn violation(&self, m: &DesignMetrics) -> f64 {
        let v = m.get(self.metric);
        if !v.is_finite() {
            return f64::INFINITY;
        }
        let relative = |gap: f64, bound: f64| (gap / bound.abs().max(f64::MIN_POSITIVE)).max(0.0);
        self.lower.map_or(0.0, |lo| relative(lo - v, lo)) + self.upper.map_or(0.0, |hi| relative(v - hi, hi))
    }

    /// Whether design metrics `m` keep this limit.
    pub fn holds(&self, m: &DesignMetrics) -> bool {
        self.violation(m) == 0.0
    }

    /// The limit in words, e.g. "plating-free charge rate (C) >= 0.6".
    pub fn describe(&self) -> String {
        match (self.lower, self.upper) {
            (Some(lo), Some(hi)) => format!("{lo} <= {} <= {hi}", self.metric.label()),
            (Some(lo), None) => format!("{} >= {lo}", self.metric.label()),
            (None, Some(hi)) => format!("{} <= {hi}", self.metric.label()),
            (None, None) => self.metric.label().to_string(),
        }
    }

    /// Whether the limit is active at `m`: its metric within [`ACTIVE_WITHIN`] of a bound.
    pub fn active(&self, m: &DesignMetrics) -> bool {
        let v = m.get(self.metric);
        [self.lower, self.upper].into_iter().flatten().any(|b| (v - b).abs() <= ACTIVE_WITHIN * b.abs().max(f64::MIN_POSITIVE))
    }
}

/// Whether `m` keeps every limit.
pub fn all_hold(limits: &[Limit], m: &DesignMetrics) -> bool {
    limits.iter().all(|l| l.holds(m))
}

/// The summed relative violation of `limits` at `m` (0 when all hold).
pub fn violation(limits: &[Limit], m: &DesignMetrics) -> f64 {
    limits.iter().map(|l| l.violation(m)).sum()
}

/// The limits active at `m`, in words.
pub fn active(limits: &[Limit], m: &DesignMetrics) -> Vec<String> {
    limits.iter().filter(|l| l.active(m)).map(Limit::describe).collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::problem::design::FastCharge;

    #[test]
    fn limits_hold_fail_and_activate() {
        let m = DesignMetrics { capacity: 5.0, fast_charge: Some(FastCharge { rate: 0.6, current: 3.0, seconds: 4200.0 }), ..Default::default() };
        let rate = Limit { metric: Metric::FastChargeRate, lower: Some(0.6), upper: None };
        assert!(rate.holds(&m) && rate.active(&m));
        let more = Limit { lower: Some(0.7), ..rate.clone() };
        assert!(!more.holds(&m) && !more.active(&m));
        // A metric the run did not compute keeps no limit.
        assert!(!Limit { metric: Metric::GravimetricPulsePowerDensity, lower: Some(1.0), upper: None }.holds(&m));
        assert!(Limit { metric: Metric::Capacity, lower: None, upper: None }.validate(0).unwrap_err().to_string().contains("limits[0]"));
        let e = Limit { metric: Metric::Capacity, lower: Some(5.0), upper: Some(4.0) }.validate(2).unwrap_err().to_string();
        assert!(e.contains("limits[2].upper"), "{e}");
    }
}
