//! Cycle life of a design: the capacity it keeps after `N` cycles of one cycle's protocol
//! (e.g. CC-CV charge and CC discharge), with the model's ageing submodel (SEI growth) on.
//! A design study bounds it (`[[limits]] metric = "capacity_retention", lower = 0.8`) or
//! trades it against density (two objectives), so a denser cell that fades faster is not
//! taken for a better one.
//!
//! ```toml
//! [operating]
//! c_rate = 1.0
//! life = { cycles = 500, initial_soc = 0.0, cycle = ["Charge at 1C until 4.1 V",
//!          "Hold at 4.1 V until C/20", "Discharge at 1C until 3.0 V"] }
//! ```

use serde::{Deserialize, Serialize};

use crate::error::Error;
use crate::models::ModelBuilder;
use crate::params::ParameterSet;
use crate::protocol::Protocol;
use crate::simulation::SimOptions;
use crate::simulation::cycling::run_cycles;

/// Largest number of cycles a life metric may ask for (each candidate runs them all).
pub const MAX_LIFE_CYCLES: usize = 10_000;

/// The cycles whose capacity retention is measured.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct LifeSpec {
    /// Number of cycles `N` (2 to [`MAX_LIFE_CYCLES`]).
    pub cycles: usize,
    /// One cycle's steps as PyBaMM writes them; "1C" is the design's own 1C (the discharge's).
    pub cycle: Vec<String>,
    /// State of charge (0 to 1, within the cut-off window) each candidate starts from; its
    /// set's initial concentrations when absent. Starting empty and charging first makes
    /// every discharge start from the same charged state.
    #[serde(default)]
    pub initial_soc: Option<f64>,
}

impl LifeSpec {
    /// Checks the cycle count, start and steps (with a 1C of `one_c` A h); errors name the
    /// key under `operating.life`.
    pub fn validate(&self, one_c: f64) -> Result<(), Error> {
        if !(2..=MAX_LIFE_CYCLES).contains(&self.cycles) {
            return Err(Error::invalid("operating.life.cycles", self.cycles as f64, format!("must be between 2 and {MAX_LIFE_CYCLES}")));
        }
        if let Some(soc) = self.initial_soc.filter(|s| !(0.0..=1.0).contains(s)) {
            return Err(Error::invalid("operating.life.initial_soc", soc, "state of charge must lie in [0, 1]"));
        }
        self.protocol(one_c).map(|_| ())
    }

    /// One cycle's protocol with 1C = `one_c` (A h).
    fn protocol(&self, one_c: f64) -> Result<Protocol, Error> {
        crate::protocol::experiment::parse(&self.cycle, one_c)
            .map_err(|e| Error::InvalidSetting { field: "operating.life.cycle".into(), reason: e.to_string() })
    }

    /// Discharge capacity of the last cycle over the first's (-) for the cell `p` built by
    /// `builder`, 1C being `one_c` (A h).
    pub fn retention(&self, builder: &mut ModelBuilder, p: &ParameterSet, one_c: f64) -> Result<f64, Error> {
        let mut p = p.clone();
        if let Some(soc) = self.initial_soc {
            crate::params::set_initial_soc_from(&mut p, soc, "operating.life.initial_soc")?;
        }
        let protocol = self.protocol(one_c)?;
        let built = builder.build(&p)?;
        let summaries = run_cycles(built.model.as_ref(), &mut built.workspace, &protocol, self.cycles, &SimOptions::for_cell(&p), &mut |_| {})?;
        let last = summaries.last().expect("run_cycles returns one summary per cycle, at least one");
        if !last.capacity_retention.is_finite() {
            return Err(Error::Solver { t: last.end_time_s, reason: "the first cycle discharged nothing: no capacity to retain".into() });
        }
        Ok(last.capacity_retention)
    }
}
