//! The `[fit]` table of a cycling study: ageing parameters (e.g. `sei.exchange_current`)
//! fitted to a measured capacity-fade curve by Levenberg-Marquardt
//! ([`crate::problem::fade::FadeProblem`]), with standard errors; the cycles then run at the
//! fitted values, and the report flags a value on its bound or a search stopped on its cap.
//!
//! ```toml
//! [fit]
//! data = "fade.csv"   # columns `cycle`, `discharge_capacity_Ah`
//! parameters = [{ path = "sei.exchange_current", initial = 1e-6, lower = 1e-8, upper = 1e-4, log = true }]
//! ```

use std::path::{Path, PathBuf};

use serde::{Deserialize, Serialize};

use crate::data::CapacityFade;
use crate::error::Error;
use crate::models::{ModelKind, Submodels};
use crate::params::ParameterSet;
use crate::problem::fade::FadeProblem;
use crate::problem::fitting::FitParameter;
use crate::problem::least_squares::{LeastSquares, LmSettings, levenberg_marquardt};
use crate::protocol::Protocol;
use crate::report::plot::{Series, line_plot};
use crate::simulation::SimOptions;

/// The `[fit]` table as written.
#[derive(Clone, Debug, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct FadeFitSpec {
    /// CSV of the measured curve (columns `cycle`, `discharge_capacity_Ah`).
    pub data: PathBuf,
    /// The ageing parameters fitted, with bounds and starts.
    pub parameters: Vec<FitParameter>,
}

/// What the fit found.
#[derive(Clone, Debug, Serialize)]
pub struct FadeFitOutcome {
    pub names: Vec<String>,
    /// Fitted values and standard errors (parameter units).
    pub values: Vec<f64>,
    pub std_errors: Vec<f64>,
    pub on_bound: Vec<bool>,
    pub converged: bool,
    pub iterations: usize,
    pub simulations: usize,
    /// Measured cycles and capacities (A h), and the model's at the start and fitted values.
    pub cycles: Vec<usize>,
    pub measured_ah: Vec<f64>,
    pub start_ah: Vec<f64>,
    pub fitted_ah: Vec<f64>,
    /// RMS capacity error (A h) at the start values and fitted.
    pub rmse_start_ah: f64,
    pub rmse_fitted_ah: f64,
}

impl FadeFitSpec {
    /// At least one parameter, each a scalar of `base` with finite bounds around its start.
    pub fn validate(&self, base: &ParameterSet) -> Result<(), Error> {
        if self.parameters.is_empty() {
            return Err(Error::InvalidSetting { field: "fit.parameters".into(), reason: "at least one parameter is needed".into() });
        }
        self.parameters.iter().try_for_each(|p| p.validate(base))
    }

    /// Fits the parameters to the curve for the cell `base` (at its starting state) cycled
    /// through `cycle`; returns the fitted set and the outcome.
    pub fn fit(&self, base: &ParameterSet, kind: ModelKind, submodels: Submodels, cycle: &Protocol, options: &SimOptions) -> Result<(ParameterSet, FadeFitOutcome), Error> {
        let data = CapacityFade::from_csv(&self.data).map_err(|e| e.input("fit.data"))?;
        let problem = FadeProblem { base: base.clone(), kind, submodels, cycle: cycle.clone(), options: options.clone(), parameters: self.parameters.clone(), data };
        let start = problem.initial();
        let start_ah = problem.run(&start)?;
        let fit = levenberg_marquardt(&problem, &start, LmSettings::default())?;
        let rms = |m: &[f64]| (m.iter().zip(&problem.data.capacity).map(|(a, b)| (a - b).powi(2)).sum::<f64>() / m.len() as f64).sqrt();
        let outcome = FadeFitOutcome {
            names: self.parameters.iter().map(|p| p.path.clone()).collect(),
            values: fit.x.clone(),
            std_errors: fit.std_errors.clone(),
            on_bound: fit.on_bound.clone(),
            converged: fit.converged,
            iterations: fit.iterations,
            simulations: fit.simulations,
            cycles: problem.data.cycles.clone(),
            measured_ah: problem.data.capacity.clone(),
            rmse_start_ah: rms(&start_ah),
            rmse_fitted_ah: rms(&fit.voltage),
            start_ah,
            fitted_ah: fit.voltage,
        };
        Ok((problem.parameter_set(&outcome.values)?, outcome))
    }
}

impl FadeFitOutcome {
    /// Warnings a reader must see: a value on its bound, a search stopped on its cap.
    pub fn warnings(&self) -> Vec<String> {
        let mut w: Vec<String> = self
            .names
            .iter()
            .zip(&self.values)
            .zip(&self.on_bound)
            .filter(|(_, b)| **b)
            .map(|((n, v), _)| format!("the fitted {n} = {v:.4e} lies on its bound: the best value may lie outside the searched range"))
            .collect();
        if !self.converged {
            w.push(format!("the fade fit stopped after {} iterations without converging: the values are the best found so far", self.iterations));
        }
        w
    }

    /// One line per parameter: `path = value ± error`.
    pub fn lines(&self) -> Vec<String> {
        self.names.iter().zip(&self.values).zip(&self.std_errors).map(|((n, v), e)| format!("{n} = {v:.4e} ± {e:.2e}")).collect()
    }

    /// Measured, start and fitted capacity against cycle.
    pub fn plot(&self, path: &Path, title: &str) -> Result<(), Error> {
        let x: Vec<f64> = self.cycles.iter().map(|c| *c as f64).collect();
        line_plot(path, title, "Cycle", "Discharge capacity (A h)", &[
            Series { label: "measured".into(), x: &x, y: &self.measured_ah },
            Series { label: "model at the start values".into(), x: &x, y: &self.start_ah },
            Series { label: "model fitted".into(), x: &x, y: &self.fitted_ah },
        ])
    }
}
