//! Ageing parameters fitted to a capacity-fade curve (issue 15 item 5): the cell is cycled
//! through the study's cycle up to the curve's last cycle, and the residuals are the
//! modelled discharge capacities (A h) at the measured cycles minus the measured ones; a
//! [`LeastSquares`] problem, so Levenberg-Marquardt fits it and gives standard errors.

use super::fitting::FitParameter;
use super::least_squares::LeastSquares;
use crate::data::CapacityFade;
use crate::error::Error;
use crate::geometry::MeshSizes;
use crate::models::{ModelBuilder, ModelKind, Submodels};
use crate::params::ParameterSet;
use crate::protocol::Protocol;
use crate::simulation::SimOptions;
use crate::simulation::cycling::run_cycles;
use crate::stats::lag1;

/// Discharge capacity per cycle of a cell whose ageing parameters are fitted.
pub struct FadeProblem {
    /// The cell at its starting state.
    pub base: ParameterSet,
    pub kind: ModelKind,
    /// Submodels, with the ageing one whose parameters are fitted.
    pub submodels: Submodels,
    /// One cycle's protocol.
    pub cycle: Protocol,
    pub options: SimOptions,
    pub parameters: Vec<FitParameter>,
    pub data: CapacityFade,
}

impl FadeProblem {
    /// The cell's parameters at `x` (one value per fitted parameter), checked.
    pub fn parameter_set(&self, x: &[f64]) -> Result<ParameterSet, Error> {
        let mut p = self.base.clone();
        for (fp, v) in self.parameters.iter().zip(x) {
            p.set(&fp.path, *v)?;
        }
        p.validate()?;
        Ok(p)
    }

    /// Modelled discharge capacity (A h) of every cycle up to the curve's last, at `x`.
    pub fn capacities(&self, x: &[f64]) -> Result<Vec<f64>, Error> {
        let p = self.parameter_set(x)?;
        let mut builder = ModelBuilder::new(self.kind, self.submodels, MeshSizes::default());
        let built = builder.build(&p)?;
        let summaries = run_cycles(built.model.as_ref(), &mut built.workspace, &self.cycle, self.data.last_cycle(), &self.options, &mut |_| {})?;
        Ok(summaries.iter().map(|s| s.discharge_capacity_ah).collect())
    }

    /// The fitted parameters' starting values.
    pub fn initial(&self) -> Vec<f64> {
        self.parameters.iter().map(|p| p.initial).collect()
    }
}

impl LeastSquares for FadeProblem {
    /// Modelled capacity (A h) at the measured cycles.
    type Run = Vec<f64>;
    fn parameters(&self) -> &[FitParameter] {
        &self.parameters
    }
    fn run(&self, x: &[f64]) -> Result<Vec<f64>, Error> {
        let all = self.capacities(x)?;
        Ok(self.data.cycles.iter().map(|c| all[c - 1]).collect())
    }
    fn weighted_residuals(&self, run: &Vec<f64>) -> Vec<f64> {
        run.iter().zip(&self.data.capacity).map(|(m, d)| m - d).collect()
    }
    fn counts(&self, run: &Vec<f64>) -> (usize, usize) {
        (run.len(), run.len())
    }
    fn lag1(&self, run: &Vec<f64>) -> f64 {
        lag1(&self.weighted_residuals(run), &vec![1.0; run.len()])
    }
    fn curve(run: Vec<f64>) -> Vec<f64> {
        run
    }
}
