//! A parameter to identify (its path, start, bounds, scale and prior) and how fitted values
//! are set on a parameter set.

use serde::{Deserialize, Serialize};

use super::delay::is_delay;
use super::history::is_history;
use super::lost_lithium::{is_loss_soc, take_lost_lithium};
use crate::cost::Prior;
use crate::error::Error;
use crate::params::ParameterSet;

/// The path of the initial state of charge (-, 0 at the lower cut-off, 1 at the upper), a
/// fit parameter that is not a field of the set: it places the initial particle
/// concentrations on the set's lithium line ([`crate::params::set_initial_soc`]) after the
/// other fitted values are set.
pub const INITIAL_SOC: &str = "initial_soc";

/// Sets `values` of `parameters` in `p`, the initial state of charge last (a load before the
/// recording, [`super::history`], and a delay of its voltage channel, [`super::delay`], are
/// not parameters of the set); the state at which active material was lost,
/// [`super::lost_lithium`], sets the cyclable lithium from `p` as it was before.
pub(super) fn apply(p: &mut ParameterSet, parameters: &[FitParameter], values: &[f64]) -> Result<(), Error> {
    let (mut soc, mut loss_soc) = (None, None);
    let unaged = parameters.iter().any(|fp| is_loss_soc(&fp.path)).then(|| p.clone());
    for (fp, &v) in parameters.iter().zip(values) {
        if fp.path == INITIAL_SOC {
            soc = Some(v)
        } else if is_loss_soc(&fp.path) {
            loss_soc = Some(v)
        } else if !is_history(&fp.path) && !is_delay(&fp.path) {
            p.set(&fp.path, v)?
        }
    }
    if let (Some(unaged), Some(v)) = (unaged, loss_soc) {
        take_lost_lithium(&unaged, p, v)?;
    }
    if let Some(v) = soc {
        crate::params::set_initial_soc(p, v)?;
    }
    Ok(())
}

/// One parameter to identify, by dotted path (e.g. `negative.diffusivity`).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct FitParameter {
    pub path: String,
    /// Start of the search (parameter units).
    pub initial: f64,
    pub lower: f64,
    pub upper: f64,
    /// Search (and sample) the natural logarithm; needs a positive lower bound.
    #[serde(default)]
    pub log: bool,
    /// Prior for MAP costs and sampling (uniform within the bounds by default).
    #[serde(default)]
    pub prior: Prior,
}

impl FitParameter {
    /// A parameter searched on a log scale between `lower` and `upper`.
    pub fn log(path: &str, initial: f64, lower: f64, upper: f64) -> Self {
        Self { path: path.into(), initial, lower, upper, log: true, prior: Prior::Uniform }
    }

    /// A parameter searched linearly between `lower` and `upper`.
    pub fn linear(path: &str, initial: f64, lower: f64, upper: f64) -> Self {
        Self { path: path.into(), initial, lower, upper, log: false, prior: Prior::Uniform }
    }

    pub(crate) fn validate(&self, base: &ParameterSet) -> Result<(), Error> {
        if self.path != INITIAL_SOC && !is_history(&self.path) && !is_delay(&self.path) && !is_loss_soc(&self.path) {
            base.get(&self.path)?;
        }
        let field = |name: &str| format!("parameters.{}.{name}", self.path);
        for (name, v) in [("initial", self.initial), ("lower", self.lower), ("upper", self.upper)] {
            if !v.is_finite() {
                return Err(Error::invalid(field(name), v, "must be finite"));
            }
        }
        if !(self.lower < self.upper) {
            return Err(Error::invalid(field("upper"), self.upper, format!("must exceed lower = {}", self.lower)));
        }
        if !(self.initial >= self.lower && self.initial <= self.upper) {
            return Err(Error::invalid(
                field("initial"),
                self.initial,
                format!("must lie within [{}, {}]", self.lower, self.upper),
            ));
        }
        if self.log && self.lower <= 0.0 {
            return Err(Error::invalid(field("lower"), self.lower, "must be positive for a log-scaled parameter"));
        }
        self.prior.validate(&field("prior"))
    }
}
