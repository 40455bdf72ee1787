//! Energy at a fixed discharge time (a point of the cell's Ragone curve): the largest
//! constant power a cell sustains from full charge for `seconds` before its voltage reaches
//! the lower cut-off, and the energy `P t` it then delivers. Unlike the mean power of a
//! discharge at one C-rate, it compares designs at the same duty (e.g. a 10-minute discharge)
//! whatever their capacity.

use serde::{Deserialize, Serialize};

use crate::error::Error;
use crate::models::ModelBuilder;
use crate::params::ParameterSet;
use crate::protocol::{Protocol, Step};
use crate::simulation::{SimOptions, simulate};

/// How long the constant-power discharge lasts.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct TimedEnergySpec {
    /// Discharge time (s) from full charge to the lower cut-off.
    #[serde(default = "TimedEnergySpec::default_seconds")]
    pub seconds: f64,
}

impl Default for TimedEnergySpec {
    /// A 10-minute discharge (about 6C).
    fn default() -> Self {
        Self { seconds: Self::default_seconds() }
    }
}

/// Relative width (-) of the bracket on the power at which the search stops.
const POWER_TOLERANCE: f64 = 1e-4;

impl TimedEnergySpec {
    fn default_seconds() -> f64 {
        600.0
    }

    /// The time must be positive and finite; the error names the field.
    pub fn validate(&self) -> Result<(), Error> {
        if !(self.seconds > 0.0 && self.seconds.is_finite()) {
            return Err(Error::invalid("operating.timed_energy.seconds", self.seconds, "must be positive and finite"));
        }
        Ok(())
    }

    /// The power (W) of the cell `p` (from its initial state) built by `builder` that lasts
    /// exactly `seconds` to the lower cut-off, and the energy (W h) it delivers. Bisection on
    /// the power: a discharge that reaches the cut-off early asks too much (as does one the
    /// model cannot carry), one still above it at the end too little.
    pub fn energy(&self, builder: &mut ModelBuilder, p: &ParameterSet) -> Result<(f64, f64), Error> {
        let built = builder.build(p)?;
        let opts = SimOptions::for_cell(p);
        let mut lasts = |power: f64| -> Result<bool, Error> {
            let protocol = Protocol { steps: vec![Step::Power { power, duration: self.seconds, until_voltage: None }] };
            Ok(match simulate(built.model.as_ref(), &mut built.workspace, &protocol, &opts, None) {
                Ok(sol) => sol.cutoff_times.is_empty(),
                Err(_) => false,
            })
        };
        // The theoretical energy at the upper cut-off spread over the time cannot be sustained.
        let ceiling = p.theoretical_capacity() * p.cell.upper_cutoff * 3600.0 / self.seconds;
        let too_far = |hi: f64| Error::Solver { t: self.seconds, reason: format!("a constant {hi:.1} W still lasts {} s", self.seconds) };
        let (lo, hi) = super::bracket::edge(&mut lasts, 0.0, 0.05 * ceiling, 2.0 * ceiling, POWER_TOLERANCE, too_far)?;
        if lo == 0.0 {
            return Err(Error::Solver { t: 0.0, reason: format!("no constant power above {hi:.3e} W lasts {} s", self.seconds) });
        }
        let power = 0.5 * (lo + hi);
        Ok((power, power * self.seconds / 3600.0))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::MeshSizes;
    use crate::models::{ModelKind, Submodels};

    /// The power found lasts the time: 0.1 % less power is still above the cut-off at its end,
    /// 0.1 % more does not last (it reaches the cut-off early, or a particle surface empties
    /// first and the model cannot carry it).
    #[test]
    fn power_found_lasts_the_time() {
        let p = crate::params::chen2020();
        let spec = TimedEnergySpec::default();
        let mut builder = ModelBuilder::new(ModelKind::Spm, Submodels::default(), MeshSizes::default());
        let (power, energy) = spec.energy(&mut builder, &p).unwrap();
        println!("SPM, 10 min: {power:.3} W, {energy:.4} W h");
        let built = builder.build(&p).unwrap();
        let mut run = |w: f64| {
            let protocol = Protocol { steps: vec![Step::Power { power: w, duration: spec.seconds, until_voltage: None }] };
            simulate(built.model.as_ref(), &mut built.workspace, &protocol, &SimOptions::for_cell(&p), None).map(|sol| sol.cutoff_times.is_empty())
        };
        assert!(run(0.999 * power).unwrap());
        assert!(!run(1.001 * power).unwrap_or(false));
        assert!((energy - power * spec.seconds / 3600.0).abs() < 1e-12 * energy);
        assert!(TimedEnergySpec { seconds: -1.0 }.validate().unwrap_err().to_string().contains("operating.timed_energy.seconds"));
    }
}
