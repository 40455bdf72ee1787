//! Plating-free fast charge: the largest constant charge rate that takes a cell from one
//! state of charge to another without reaching the upper cut-off and without its
//! lithium-plating margin ([`crate::models::Model::plating_margin`], `phi_s - phi_e` in the
//! negative electrode) falling below a limit, and the charge time at that rate. A design
//! that charges faster only by plating lithium does not count as faster.

use serde::{Deserialize, Serialize};

use crate::error::Error;
use crate::models::ModelBuilder;
use crate::params::{ParameterSet, StoichiometryWindow};
use crate::protocol::{Protocol, Step};
use crate::simulation::{SimOptions, States, simulate_observed};

/// The charge whose plating-free rate is measured.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct FastChargeSpec {
    /// State of charge (-) the charge starts from, at rest.
    #[serde(default = "FastChargeSpec::default_from")]
    pub from_soc: f64,
    /// State of charge (-) it ends at.
    #[serde(default = "FastChargeSpec::default_to")]
    pub to_soc: f64,
    /// The least plating margin (V) allowed anywhere during the charge.
    #[serde(default)]
    pub margin: f64,
}

impl Default for FastChargeSpec {
    /// 10 % to 80 %, no plating (margin 0 V).
    fn default() -> Self {
        Self { from_soc: Self::default_from(), to_soc: Self::default_to(), margin: 0.0 }
    }
}

/// The result of a plating-free charge search.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct FastCharge {
    /// Rate (1/h: multiples of the window's capacity per hour) and current (A, a magnitude).
    pub rate: f64,
    pub current: f64,
    /// Time (s) from `from_soc` to `to_soc` at that rate.
    pub seconds: f64,
}

/// Relative width of the bracket on the rate at which the search stops.
const RATE_TOLERANCE: f64 = 1e-4;

impl FastChargeSpec {
    fn default_from() -> f64 {
        0.1
    }
    fn default_to() -> f64 {
        0.8
    }

    /// Checks the fields; errors name the field and value.
    pub fn validate(&self) -> Result<(), Error> {
        if !(0.0..1.0).contains(&self.from_soc) {
            return Err(Error::invalid("operating.fast_charge.from_soc", self.from_soc, "must lie in [0, 1)"));
        }
        if !(self.to_soc > self.from_soc && self.to_soc <= 1.0) {
            return Err(Error::invalid("operating.fast_charge.to_soc", self.to_soc, format!("must lie in ({}, 1]", self.from_soc)));
        }
        if !self.margin.is_finite() {
            return Err(Error::invalid("operating.fast_charge.margin", self.margin, "must be finite (V)"));
        }
        Ok(())
    }

    /// The plating-free charge of the cell `p` built by `builder` (the SOC window of
    /// [`StoichiometryWindow::within_reach`]): bisection on the rate, a charge that reaches
    /// the cut-off or the margin asking too much.
    pub fn search(&self, builder: &mut ModelBuilder, p: &ParameterSet) -> Result<FastCharge, Error> {
        self.validate()?;
        let mut p = p.clone();
        p.validate()?;
        let window = StoichiometryWindow::within_reach(&p);
        window.place(&mut p, self.from_soc);
        let capacity = window.capacity(&p);
        let span = self.to_soc - self.from_soc;
        // Every state at every output (not stored): the margin reads potentials the voltage does not.
        let opts = SimOptions { states: States::Observed, ..SimOptions::for_cell(&p) };
        let built = builder.build(&p)?;
        let mut feasible = |rate: f64| -> Result<bool, Error> {
            let protocol = Protocol { steps: vec![Step::Current { current: -rate * capacity, duration: span / rate * 3600.0, until_voltage: None }] };
            let mut least = f64::INFINITY;
            let mut watch = |y: &[f64], i: f64| {
                if let Some(m) = built.model.plating_margin(y, i) {
                    least = least.min(m);
                }
            };
            Ok(match simulate_observed(built.model.as_ref(), &mut built.workspace, &protocol, &opts, None, &mut watch) {
                Ok(sol) => sol.cutoff_times.is_empty() && least >= self.margin,
                // A charge the model cannot follow asks too much; a failure at a crawl is an error.
                Err(_) if rate > 1e-3 => false,
                Err(e) => return Err(e),
            })
        };
        if built.model.plating_margin(&built.model.initial_state(), 0.0).is_none() {
            return Err(Error::InvalidSetting { field: "model".into(), reason: "the plating margin needs the SPM, SPMe or DFN".into() });
        }
        if !feasible(1e-2)? {
            return Err(Error::invalid("operating.fast_charge.margin", self.margin, "not held even at C/100"));
        }
        let too_far = |_| Error::Solver { t: 0.0, reason: "a plating-free charge faster than 1000C: check the cell".into() };
        let (lo, _) = super::bracket::edge(&mut feasible, 1e-2, 1.0, 1e3, RATE_TOLERANCE, too_far)?;
        // The fastest rate known to hold.
        Ok(FastCharge { rate: lo, current: lo * capacity, seconds: span / lo * 3600.0 })
    }
}
