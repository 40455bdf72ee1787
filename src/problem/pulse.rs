//! HPPC-style pulse power: the largest constant discharge current a cell sustains for a
//! pulse of `seconds` from rest at a state of charge without its voltage falling below a
//! limit, and the power `P = I V_min` it delivers at the end of the pulse (USABC's
//! definition of available pulse power). Unlike the mean power of a full discharge, it does
//! not depend on how early a transport-limited discharge stops.

use serde::{Deserialize, Serialize};

use crate::error::Error;
use crate::models::ModelBuilder;
use crate::params::{ParameterSet, StoichiometryWindow};
use crate::protocol::{Protocol, Step};
use crate::simulation::{SimOptions, simulate};

/// Where and how long a pulse is.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PulseSpec {
    /// State of charge (-) the pulse starts from, at rest (0 and 1 at the cut-offs, or where an
    /// electrode fills or empties first: [`StoichiometryWindow::within_reach`]).
    #[serde(default = "PulseSpec::default_soc")]
    pub soc: f64,
    /// Pulse length (s).
    #[serde(default = "PulseSpec::default_seconds")]
    pub seconds: f64,
    /// Voltage (V) the pulse may fall to; the cell's lower cut-off when absent.
    #[serde(default)]
    pub voltage: Option<f64>,
}

impl Default for PulseSpec {
    /// 10 s from 50 % SOC to the lower cut-off, as an HPPC test.
    fn default() -> Self {
        Self { soc: Self::default_soc(), seconds: Self::default_seconds(), voltage: None }
    }
}

/// Relative width (-) of the bracket on the pulse current at which the search stops.
const CURRENT_TOLERANCE: f64 = 1e-4;

impl PulseSpec {
    fn default_soc() -> f64 {
        0.5
    }
    fn default_seconds() -> f64 {
        10.0
    }

    /// Checks the fields against the cell `p`; errors name the field and value.
    pub fn validate(&self, p: &ParameterSet) -> Result<(), Error> {
        if !(self.soc > 0.0 && self.soc <= 1.0) {
            return Err(Error::invalid("operating.pulse.soc", self.soc, "must lie in (0, 1]"));
        }
        if !(self.seconds > 0.0 && self.seconds.is_finite()) {
            return Err(Error::invalid("operating.pulse.seconds", self.seconds, "must be positive and finite"));
        }
        if let Some(v) = self.voltage {
            if !(v >= p.cell.lower_cutoff && v < p.cell.upper_cutoff) {
                return Err(Error::invalid(
                    "operating.pulse.voltage",
                    v,
                    format!("must lie in the cell's window [{}, {}) V", p.cell.lower_cutoff, p.cell.upper_cutoff),
                ));
            }
        }
        Ok(())
    }

    /// The pulse power (W) of the cell `p` built by `builder`, and the pulse current (A).
    /// Bisection on the current: a pulse whose voltage reaches the limit before its end asks
    /// too much, one that ends above it too little.
    pub fn power(&self, builder: &mut ModelBuilder, p: &ParameterSet) -> Result<(f64, f64), Error> {
        let mut p = p.clone();
        p.validate()?;
        StoichiometryWindow::within_reach(&p).place(&mut p, self.soc);
        let v_min = self.voltage.unwrap_or(p.cell.lower_cutoff);
        let mut opts = SimOptions::for_cell(&p);
        opts.cutoffs.0 = v_min;
        let built = builder.build(&p)?;
        // Voltage at the pulse's end over the limit (V): negative when the pulse reached the
        // limit early, or when the model failed under it (e.g. a particle surface emptied
        // before the voltage reached the limit: the cell cannot carry that current).
        let mut end_margin = |current: f64| -> Result<f64, Error> {
            let protocol = Protocol { steps: vec![Step::Current { current, duration: self.seconds, until_voltage: None }] };
            Ok(match simulate(built.model.as_ref(), &mut built.workspace, &protocol, &opts, None) {
                Ok(sol) if sol.cutoff_times.is_empty() => sol.final_voltage() - v_min,
                Ok(_) => -1.0,
                Err(_) if current > 0.0 => -1.0,
                Err(e) => return Err(e),
            })
        };
        // The cell must at least rest above the limit.
        if end_margin(0.0)? <= 0.0 {
            return Err(Error::invalid("operating.pulse.soc", self.soc, format!("the cell rests at or below the pulse's limit of {v_min} V there")));
        }
        let one_c = p.cell.nominal_capacity;
        let too_far = |hi: f64| Error::Solver { t: self.seconds, reason: format!("no pulse current up to {hi:.0} A reaches {v_min} V in {} s", self.seconds) };
        let (lo, hi) = super::bracket::edge(|i| Ok(end_margin(i)? > 0.0), 0.0, one_c, 1e3 * one_c, CURRENT_TOLERANCE, too_far)?;
        if lo == 0.0 && hi < 1e-3 * one_c {
            return Err(Error::Solver { t: 0.0, reason: format!("no pulse current above {hi:.2e} A holds {v_min} V for {} s", self.seconds) });
        }
        let current = 0.5 * (lo + hi);
        Ok((current * v_min, current))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::MeshSizes;
    use crate::models::{ModelKind, Submodels};

    #[test]
    fn pulse_ends_at_the_voltage_limit() {
        let p = crate::params::chen2020();
        let spec = PulseSpec::default();
        let mut builder = ModelBuilder::new(ModelKind::Spm, Submodels::default(), MeshSizes::default());
        let (power, current) = spec.power(&mut builder, &p).unwrap();
        println!("SPM pulse: {current:.4} A, {power:.3} W");
        assert!((power - current * p.cell.lower_cutoff).abs() < 1e-9 * power);
        // The current found ends the 10 s pulse at the limit: 0.1 % less stays above it,
        // 0.1 % more reaches it early.
        let mut q = p.clone();
        crate::params::set_initial_soc(&mut q, spec.soc).unwrap();
        let built = builder.build(&q).unwrap();
        let mut run = |i: f64| {
            let protocol = Protocol { steps: vec![Step::Current { current: i, duration: spec.seconds, until_voltage: None }] };
            simulate(built.model.as_ref(), &mut built.workspace, &protocol, &SimOptions::for_cell(&q), None).unwrap()
        };
        let below = run(0.999 * current);
        assert!(below.cutoff_times.is_empty() && below.final_voltage() > p.cell.lower_cutoff);
        assert!(!run(1.001 * current).cutoff_times.is_empty());
    }

    #[test]
    fn bad_pulse_fields_are_named() {
        let p = crate::params::chen2020();
        for (spec, field) in [
            (PulseSpec { soc: 1.5, ..PulseSpec::default() }, "soc"),
            (PulseSpec { seconds: 0.0, ..PulseSpec::default() }, "seconds"),
            (PulseSpec { voltage: Some(5.0), ..PulseSpec::default() }, "voltage"),
        ] {
            let e = spec.validate(&p).unwrap_err().to_string();
            assert!(e.contains(&format!("operating.pulse.{field}")), "{e}");
        }
    }
}
