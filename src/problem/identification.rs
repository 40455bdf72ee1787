//! Identification: a cost of a fitting problem as an optimiser objective (with gradients from
//! forward sensitivities), the fit itself, and standard errors from the Fisher information.

use std::time::Instant;

use serde::Serialize;

use super::fitting::{FitParameter, FittingProblem, Simulated};
use crate::cost::CostKind;
use crate::error::Error;
use crate::stats::weighted_rms;
use crate::optim::{Bounds, Objective, OptimOptions, Problem, ProgressObserver, StopReason, TraceEntry, Transform, by_name};

/// Bounds and start of the noise level when it is fitted (V).
pub const SIGMA_BOUNDS: (f64, f64) = (1e-5, 0.5);
pub const SIGMA_START: f64 = 0.005;

/// A cost of a fitting problem over the model parameters (and the noise level last, when the
/// cost fits it). Failed simulations cost `+inf`.
pub struct FitObjective<'a> {
    pub problem: &'a FittingProblem,
    pub cost: CostKind,
}

impl FitObjective<'_> {
    fn split<'x>(&self, x: &'x [f64]) -> (&'x [f64], Option<f64>) {
        let n = self.problem.dim();
        (&x[..n], self.cost.fits_sigma().then(|| x[n]))
    }

    /// Value and gradient (model space) from one simulation with sensitivities.
    pub fn value_and_gradient(&self, x: &[f64]) -> Result<(f64, Vec<f64>), Error> {
        let (theta, sigma) = self.split(x);
        let (mut value, mut g) = self.data_term_and_gradient(theta, sigma)?;
        if self.cost.uses_priors() {
            for (k, (p, &v)) in self.problem.parameters.iter().zip(theta).enumerate() {
                value -= p.prior.log_pdf(v);
                g[k] -= p.prior.d_log_pdf(v);
            }
        }
        Ok((value, g))
    }

    /// The cost of the residuals alone (no priors) at model parameters `theta` and noise
    /// level `sigma`, with its gradient over `theta` then `sigma` (when given): the part
    /// that adds up over experiments ([`super::joint`]).
    pub fn data_term_and_gradient(&self, theta: &[f64], sigma: Option<f64>) -> Result<(f64, Vec<f64>), Error> {
        let sim = self.problem.simulate_with_sensitivities(theta)?;
        let r = self.problem.residuals(&sim.voltage);
        let c = self.cost.evaluate(&r, &self.problem.weights, sigma);
        let mut g = vec![0.0; theta.len() + usize::from(sigma.is_some())];
        for (row, d) in sim.sensitivity_rows().zip(&c.d_residual) {
            for (gk, s) in g.iter_mut().zip(row) {
                *gk += d * s;
            }
        }
        if sigma.is_some() {
            g[theta.len()] = c.d_sigma;
        }
        Ok((c.value, g))
    }

    /// The cost of the residuals alone (no priors); `None` when the simulation fails.
    pub fn data_term(&self, theta: &[f64], sigma: Option<f64>) -> Option<f64> {
        let v = self.problem.simulate(theta).ok()?;
        Some(self.cost.evaluate(&self.problem.residuals(&v), &self.problem.weights, sigma).value)
    }
}

impl Objective for FitObjective<'_> {
    fn dim(&self) -> usize {
        self.problem.dim() + usize::from(self.cost.fits_sigma())
    }
    fn evaluate(&self, x: &[f64]) -> f64 {
        let (theta, sigma) = self.split(x);
        let Some(mut value) = self.data_term(theta, sigma) else { return f64::INFINITY };
        if self.cost.uses_priors() {
            for (p, &v) in self.problem.parameters.iter().zip(theta) {
                value -= p.prior.log_pdf(v);
            }
        }
        value
    }
    fn gradient(&self, x: &[f64]) -> Option<Vec<f64>> {
        self.value_and_gradient(x).ok().map(|(_, g)| g)
    }
}

/// Result of a fit.
#[derive(Clone, Debug, Serialize)]
pub struct FitResult {
    /// Fitted parameter paths, then `sigma` when fitted.
    pub names: Vec<String>,
    /// Best point (parameter units; sigma in V last when fitted).
    pub x: Vec<f64>,
    pub cost: f64,
    /// Root-mean-square residual over the weighted points (V).
    pub rmse: f64,
    /// Standard errors of the model parameters (Gauss-Newton / Fisher information with the
    /// noise level estimated from the residuals), in parameter units.
    pub std_errors: Vec<f64>,
    /// Correlation matrix of the model parameters.
    pub correlation: Vec<Vec<f64>>,
    /// What the data determine of each model parameter ([`super::verdict`]).
    pub standings: Vec<super::verdict::Standing>,
    pub evaluations: usize,
    pub gradient_evaluations: usize,
    pub iterations: usize,
    pub stop: StopReason,
    /// Model voltage (V) at every recorded point at the optimum.
    pub voltage: Vec<f64>,
    /// Best point after every iteration.
    pub trace: Vec<TraceEntry>,
    /// Wall time of the search (s).
    pub seconds: f64,
}

/// Minimises `cost` over the problem's parameters with the named optimiser, from the
/// parameters' initial values, then evaluates standard errors at the optimum.
pub fn fit(problem: &FittingProblem, cost: CostKind, optimiser: &str, options: OptimOptions) -> Result<FitResult, Error> {
    let objective = FitObjective { problem, cost };
    let search = minimise(&objective, &problem.parameters, cost, optimiser, options)
        .map_err(|err| explain_start(err, || problem.unreplayable(&problem.initial(), "data")))?;
    let theta = &search.result.x[..problem.dim()];
    let sim = problem.simulate_with_sensitivities(theta)?;
    let id = identifiability(problem, &sim)?;
    Ok(search.into_result(id, sim.voltage))
}

/// An optimiser's refusal of a start where the objective is not finite (field `x0`), or a
/// solver failure that ended the search, replaced by `why` the model cannot replay the data
/// at the start values (a discharge that reaches its cut-off before the recording ends, a
/// state outside its window, a model cell that empties under load), when that is the reason:
/// `why` returns `None` where the start replays, and the error stands.
pub(crate) fn explain_start(err: Error, why: impl FnOnce() -> Option<Error>) -> Error {
    match &err {
        Error::InvalidSetting { field, .. } if field == "x0" => why().unwrap_or(err),
        Error::Solver { .. } => why().unwrap_or(err),
        _ => err,
    }
}

/// A finished search: the optimiser's result, the names of its coordinates, its trace and
/// wall time.
pub(crate) struct Search {
    pub names: Vec<String>,
    pub result: crate::optim::OptimResult,
    pub trace: Vec<TraceEntry>,
    pub seconds: f64,
}

impl Search {
    pub(crate) fn into_result(self, id: Identifiability, voltage: Vec<f64>) -> FitResult {
        let r = self.result;
        let standings = super::verdict::standings(&self.names, &r.x, &id.std_errors, &id.correlation);
        FitResult {
            standings,
            names: self.names,
            x: r.x,
            cost: r.f,
            rmse: id.rmse,
            std_errors: id.std_errors,
            correlation: id.correlation,
            evaluations: r.evaluations,
            gradient_evaluations: r.gradient_evaluations,
            iterations: r.iterations,
            stop: r.stop,
            voltage,
            trace: self.trace,
            seconds: self.seconds,
        }
    }
}

/// Minimises `objective` over `parameters` (and the noise level last, when `cost` fits it)
/// within their bounds, log-scaled where asked, from their initial values.
pub(crate) fn minimise(
    objective: &dyn Objective,
    parameters: &[FitParameter],
    cost: CostKind,
    optimiser: &str,
    options: OptimOptions,
) -> Result<Search, Error> {
    cost.validate()?;
    let mut lower: Vec<f64> = parameters.iter().map(|p| p.lower).collect();
    let mut upper: Vec<f64> = parameters.iter().map(|p| p.upper).collect();
    let mut transforms: Vec<Transform> = parameters.iter().map(|p| if p.log { Transform::Log } else { Transform::Identity }).collect();
    let mut x0: Vec<f64> = parameters.iter().map(|p| p.initial).collect();
    let mut names: Vec<String> = parameters.iter().map(|p| p.path.clone()).collect();
    if cost.fits_sigma() {
        lower.push(SIGMA_BOUNDS.0);
        upper.push(SIGMA_BOUNDS.1);
        transforms.push(Transform::Log);
        x0.push(SIGMA_START);
        names.push("sigma".into());
    }
    let search = Problem::new(objective, Bounds::new(lower, upper)?)?.with_transforms(transforms)?;
    let mut progress = ProgressObserver::new("fit", options.max_iterations, |f| format!("cost {f:.4e}"));
    let start = Instant::now();
    let result = by_name(optimiser, options)?.minimise(&search, &x0, &mut progress)?;
    let trace = progress.finish();
    let seconds = start.elapsed().as_secs_f64();
    if !result.f.is_finite() {
        return Err(Error::Solver { t: 0.0, reason: "every simulation of the fit failed".into() });
    }
    Ok(Search { names, result, trace: trace.entries, seconds })
}

/// Local identifiability at a fitted point.
pub struct Identifiability {
    /// Weighted RMS residual (V).
    pub rmse: f64,
    pub std_errors: Vec<f64>,
    pub correlation: Vec<Vec<f64>>,
}

/// Covariance `s² (Sᵀ W S)⁻¹` of least squares, with `s²` the weighted residual variance over
/// `N - P` degrees of freedom; a direction the data do not inform has an infinite error.
pub fn identifiability(problem: &FittingProblem, sim: &Simulated) -> Result<Identifiability, Error> {
    let scale: Vec<f64> = problem.parameters.iter().map(|p| p.initial.abs().max(f64::MIN_POSITIVE)).collect();
    covariance(&problem.residuals(&sim.voltage), &problem.weights, sim.sensitivity_rows(), &scale)
}

/// `Σ_t w_t (θ_a ∂V_t/∂θ_a)(θ_b ∂V_t/∂θ_b)` (row-major `p × p`, V²) from point weights `w`
/// and sensitivity rows (V per parameter unit), `θ = scale`: the Fisher information in
/// relative units (times the noise variance), which keeps the eigenproblem well scaled.
pub fn relative_information<'a>(w: &[f64], sensitivity: impl IntoIterator<Item = &'a [f64]>, scale: &[f64]) -> Vec<f64> {
    let p = scale.len();
    let mut fisher = vec![0.0; p * p];
    for (row, &wi) in sensitivity.into_iter().zip(w) {
        for a in 0..p {
            for b in 0..p {
                fisher[a * p + b] += wi * row[a] * scale[a] * row[b] * scale[b];
            }
        }
    }
    fisher
}

/// [`identifiability`] from residuals `r` (V), point weights `w` and sensitivity rows
/// (V per parameter unit, one per residual), with `scale` the typical size of each parameter.
pub fn covariance<'a>(r: &[f64], w: &[f64], sensitivity: impl IntoIterator<Item = &'a [f64]>, scale: &[f64]) -> Result<Identifiability, Error> {
    let p = scale.len();
    let weight: f64 = w.iter().sum();
    let sse: f64 = r.iter().zip(w).map(|(r, w)| w * r * r).sum();
    let rmse = weighted_rms(r, w);
    if p == 0 {
        return Ok(Identifiability { rmse, std_errors: Vec::new(), correlation: Vec::new() });
    }
    let s2 = sse / (weight - p as f64).max(1.0);
    let fisher = relative_information(w, sensitivity, scale);
    let mut cov = crate::linalg::sym_inverse(&fisher, p)?;
    for a in 0..p {
        for b in 0..p {
            cov[a * p + b] *= s2 * scale[a] * scale[b];
        }
    }
    let std_errors: Vec<f64> = (0..p).map(|a| cov[a * p + a].sqrt()).collect();
    let correlation =
        (0..p).map(|a| (0..p).map(|b| cov[a * p + b] / (std_errors[a] * std_errors[b])).collect()).collect();
    Ok(Identifiability { rmse, std_errors, correlation })
}
