//! The Bayesian posterior of a fitting problem as a log-density for the samplers: Gaussian
//! likelihood of the residuals, the parameters' priors, and their bounds.

use super::identification::{FitObjective, SIGMA_BOUNDS};
use super::fitting::FittingProblem;
use crate::cost::CostKind;
use crate::sample::LogDensity;

/// Posterior over the sampling coordinates `z`: `z_k = ln θ_k` for log-scaled parameters,
/// `θ_k` otherwise, then `ln σ` when the noise level is unknown (log-uniform prior on
/// [`SIGMA_BOUNDS`]). The density includes the Jacobian of the log maps, so draws mapped back
/// by [`to_model`](Self::to_model) follow the priors stated in parameter units.
pub struct Posterior<'a> {
    objective: FitObjective<'a>,
}

impl<'a> Posterior<'a> {
    /// `sigma` is the known noise level (V), or `None` to sample it.
    pub fn new(problem: &'a FittingProblem, sigma: Option<f64>) -> Self {
        Self { objective: FitObjective { problem, cost: CostKind::Map { sigma } } }
    }

    fn problem(&self) -> &FittingProblem {
        self.objective.problem
    }

    fn samples_sigma(&self) -> bool {
        self.objective.cost.fits_sigma()
    }

    /// Parameter names in sampling order (`sigma` last when sampled).
    pub fn names(&self) -> Vec<String> {
        let mut n: Vec<String> = self.problem().parameters.iter().map(|p| p.path.clone()).collect();
        if self.samples_sigma() {
            n.push("sigma".into());
        }
        n
    }

    /// Sampling coordinates of model values `x` (sigma last when sampled).
    pub fn to_sampling(&self, x: &[f64]) -> Vec<f64> {
        x.iter().enumerate().map(|(k, &v)| if self.is_log(k) { v.ln() } else { v }).collect()
    }

    /// Model values of sampling coordinates `z`.
    pub fn to_model(&self, z: &[f64]) -> Vec<f64> {
        z.iter().enumerate().map(|(k, &v)| if self.is_log(k) { v.exp() } else { v }).collect()
    }

    fn is_log(&self, k: usize) -> bool {
        self.problem().parameters.get(k).is_none_or(|p| p.log)
    }

    fn inside(&self, x: &[f64]) -> bool {
        let params = &self.problem().parameters;
        let in_params = params.iter().zip(x).all(|(p, &v)| v >= p.lower && v <= p.upper);
        let in_sigma = !self.samples_sigma() || (x[params.len()] >= SIGMA_BOUNDS.0 && x[params.len()] <= SIGMA_BOUNDS.1);
        in_params && in_sigma
    }

    /// `ln |dθ/dz|` of the parameters' log maps (sigma's log-uniform prior is flat in `ln σ`).
    fn log_jacobian(&self, x: &[f64]) -> f64 {
        self.problem().parameters.iter().zip(x).filter(|(p, _)| p.log).map(|(_, v)| v.ln()).sum()
    }
}

impl LogDensity for Posterior<'_> {
    fn dim(&self) -> usize {
        use crate::optim::Objective;
        self.objective.dim()
    }

    fn log_density(&self, z: &[f64]) -> f64 {
        use crate::optim::Objective;
        let x = self.to_model(z);
        if !self.inside(&x) {
            return f64::NEG_INFINITY;
        }
        let neg = self.objective.evaluate(&x);
        if neg.is_finite() { -neg + self.log_jacobian(&x) } else { f64::NEG_INFINITY }
    }

    fn log_density_and_gradient(&self, z: &[f64]) -> Option<(f64, Vec<f64>)> {
        let x = self.to_model(z);
        if !self.inside(&x) {
            return Some((f64::NEG_INFINITY, vec![0.0; z.len()]));
        }
        let (neg, g) = self.objective.value_and_gradient(&x).ok()?;
        let n = self.problem().dim();
        let grad = (0..z.len())
            .map(|k| match (self.is_log(k), k < n) {
                (true, true) => -g[k] * x[k] + 1.0,
                (true, false) => -g[k] * x[k],
                (false, _) => -g[k],
            })
            .collect();
        Some((-neg + self.log_jacobian(&x), grad))
    }
}
