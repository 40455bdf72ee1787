//! Several experiments fitted together: each is a [`FittingProblem`] with its own recording,
//! protocol, temperature and initial state, sharing the cell parameters; per-experiment
//! nuisance parameters (the initial state of charge) sit after the shared ones in the joint
//! vector. The cost is the weighted sum of the experiments' costs, its gradient the weighted
//! sum of theirs (forward sensitivities of every experiment), and the standard errors come
//! from the summed Fisher information.

use rayon::prelude::*;
use serde::Serialize;

use super::identification::{FitObjective, FitResult, Identifiability, explain_start, minimise};
use crate::stats::weighted_rms;
use super::fitting::{FitParameter, FittingProblem};
use crate::cost::CostKind;
use crate::error::Error;
use crate::optim::{Objective, OptimOptions};

/// One experiment of a joint fit.
pub struct Experiment {
    /// Label in reports.
    pub name: String,
    /// The experiment's problem; its parameters are the joint vector's entries listed in
    /// `index`, in the same order.
    pub problem: FittingProblem,
    /// Non-negative weight of the experiment's cost in the sum.
    pub weight: f64,
    /// Position in the joint vector of each of `problem.parameters`.
    pub index: Vec<usize>,
}

/// Experiments sharing parameters.
pub struct JointProblem {
    /// The joint vector: shared parameters, then each experiment's own (named
    /// `<experiment>.<path>`).
    pub parameters: Vec<FitParameter>,
    pub experiments: Vec<Experiment>,
}

impl JointProblem {
    /// Joins experiments: each `(name, problem, weight, own)` has a problem whose parameters
    /// are `shared` followed by `own` of them (the experiment's nuisance parameters).
    pub fn new(shared: Vec<FitParameter>, experiments: Vec<(String, FittingProblem, f64, usize)>) -> Result<Self, Error> {
        if experiments.is_empty() {
            return Err(Error::InvalidSetting { field: "data".into(), reason: "no experiment to fit".into() });
        }
        let mut parameters = shared.clone();
        let mut out = Vec::with_capacity(experiments.len());
        for (name, problem, weight, own) in experiments {
            if !(weight >= 0.0 && weight.is_finite()) {
                return Err(Error::invalid(format!("data.{name}.weight"), weight, "must be non-negative and finite"));
            }
            let p = &problem.parameters;
            if p.len() != shared.len() + own || p[..shared.len()] != shared[..] {
                return Err(Error::InvalidSetting {
                    field: format!("data.{name}"),
                    reason: "the experiment's parameters must be the shared ones followed by its own".into(),
                });
            }
            let mut index: Vec<usize> = (0..shared.len()).collect();
            for q in &p[shared.len()..] {
                index.push(parameters.len());
                parameters.push(FitParameter { path: format!("{name}.{}", q.path), ..q.clone() });
            }
            out.push(Experiment { name, problem, weight, index });
        }
        if out.iter().all(|e| e.weight == 0.0) {
            return Err(Error::InvalidSetting { field: "data".into(), reason: "every experiment has weight 0".into() });
        }
        Ok(Self { parameters, experiments: out })
    }

    /// Number of joint parameters.
    pub fn dim(&self) -> usize {
        self.parameters.len()
    }

    /// Initial values of the joint parameters.
    pub fn initial(&self) -> Vec<f64> {
        self.parameters.iter().map(|p| p.initial).collect()
    }

    /// The experiment's own parameter values out of the joint vector `x`.
    pub fn local(&self, e: &Experiment, x: &[f64]) -> Vec<f64> {
        e.index.iter().map(|&k| x[k]).collect()
    }
}

/// The weighted sum of the experiments' costs over the joint parameters (the noise level
/// last and shared, when the cost fits it); priors once per joint parameter.
pub struct JointObjective<'a> {
    pub problem: &'a JointProblem,
    pub cost: CostKind,
}

impl JointObjective<'_> {
    fn split<'x>(&self, x: &'x [f64]) -> (&'x [f64], Option<f64>) {
        let n = self.problem.dim();
        (&x[..n], self.cost.fits_sigma().then(|| x[n]))
    }

    fn prior_term(&self, theta: &[f64], gradient: Option<&mut [f64]>) -> f64 {
        if !self.cost.uses_priors() {
            return 0.0;
        }
        let params = &self.problem.parameters;
        if let Some(g) = gradient {
            for (k, (p, &v)) in params.iter().zip(theta).enumerate() {
                g[k] -= p.prior.d_log_pdf(v);
            }
        }
        -params.iter().zip(theta).map(|(p, &v)| p.prior.log_pdf(v)).sum::<f64>()
    }

    /// Value and gradient (model space) from one simulation with sensitivities per experiment.
    pub fn value_and_gradient(&self, x: &[f64]) -> Result<(f64, Vec<f64>), Error> {
        let (theta, sigma) = self.split(x);
        let parts: Vec<(f64, Vec<f64>)> = self
            .problem
            .experiments
            .par_iter()
            .map(|e| FitObjective { problem: &e.problem, cost: self.cost }.data_term_and_gradient(&self.problem.local(e, theta), sigma))
            .collect::<Result<_, _>>()?;
        let mut g = vec![0.0; x.len()];
        let mut value = 0.0;
        for (e, (v, ge)) in self.problem.experiments.iter().zip(parts) {
            value += e.weight * v;
            for (&k, d) in e.index.iter().zip(&ge) {
                g[k] += e.weight * d;
            }
            if sigma.is_some() {
                g[theta.len()] += e.weight * ge[e.index.len()];
            }
        }
        value += self.prior_term(theta, Some(&mut g));
        Ok((value, g))
    }
}

impl Objective for JointObjective<'_> {
    fn dim(&self) -> usize {
        self.problem.dim() + usize::from(self.cost.fits_sigma())
    }
    fn evaluate(&self, x: &[f64]) -> f64 {
        let (theta, sigma) = self.split(x);
        let parts: Option<Vec<f64>> = self
            .problem
            .experiments
            .par_iter()
            .map(|e| FitObjective { problem: &e.problem, cost: self.cost }.data_term(&self.problem.local(e, theta), sigma))
            .collect();
        match parts {
            Some(p) => p.iter().zip(&self.problem.experiments).map(|(v, e)| e.weight * v).sum::<f64>() + self.prior_term(theta, None),
            None => f64::INFINITY,
        }
    }
    fn gradient(&self, x: &[f64]) -> Option<Vec<f64>> {
        self.value_and_gradient(x).ok().map(|(_, g)| g)
    }
}

/// One experiment's share of a joint fit.
#[derive(Clone, Debug, Serialize)]
pub struct ExperimentFit {
    pub name: String,
    pub weight: f64,
    /// Points in the cost.
    pub points: usize,
    /// RMS residual (V) at the initial and at the fitted parameters.
    pub initial_rmse: f64,
    pub rmse: f64,
    /// Model voltage (V) at every recorded point at the optimum.
    #[serde(skip)]
    pub voltage: Vec<f64>,
    /// Model voltage (V) at every recorded point at the initial parameters.
    #[serde(skip)]
    pub initial_voltage: Vec<f64>,
}

/// A joint fit: the result over the joint parameters (its `rmse` over all points with the
/// experiments' weights, its `voltage` the experiments' voltages one after another) and each
/// experiment's share.
#[derive(Clone, Debug, Serialize)]
pub struct JointFit {
    pub result: FitResult,
    pub experiments: Vec<ExperimentFit>,
}

/// Minimises the weighted sum of the experiments' costs, then evaluates the standard errors
/// from every experiment's sensitivities and residual variance ([`sandwich_covariance`]).
pub fn fit_joint(problem: &JointProblem, cost: CostKind, optimiser: &str, options: OptimOptions) -> Result<JointFit, Error> {
    let objective = JointObjective { problem, cost };
    let initial = problem.initial();
    let search = minimise(&objective, &problem.parameters, cost, optimiser, options).map_err(|err| {
        explain_start(err, || problem.experiments.iter().find_map(|e| e.problem.unreplayable(&problem.local(e, &initial), &format!("data \"{}\"", e.name))))
    })?;
    let theta = search.result.x[..problem.dim()].to_vec();
    let sims: Vec<_> = problem
        .experiments
        .par_iter()
        .map(|e| Ok((e.problem.simulate_with_sensitivities(&problem.local(e, &theta))?, e.problem.simulate(&problem.local(e, &initial))?)))
        .collect::<Result<_, Error>>()?;
    let mut blocks = Vec::new();
    let mut voltage = Vec::new();
    let mut experiments = Vec::new();
    for (e, (sim, v0)) in problem.experiments.iter().zip(sims) {
        let re = e.problem.residuals(&sim.voltage);
        let we = &e.problem.weights;
        let rows: Vec<Vec<f64>> = sim
            .sensitivity_rows()
            .map(|row| {
                let mut joint = vec![0.0; problem.dim()];
                for (&j, s) in e.index.iter().zip(row) {
                    joint[j] = *s;
                }
                joint
            })
            .collect();
        experiments.push(ExperimentFit {
            name: e.name.clone(),
            weight: e.weight,
            points: we.iter().filter(|w| **w > 0.0).count(),
            initial_rmse: weighted_rms(&e.problem.residuals(&v0), we),
            rmse: weighted_rms(&re, we),
            voltage: sim.voltage.clone(),
            initial_voltage: v0,
        });
        blocks.push(Block { weight: e.weight, residuals: re, point_weights: we.clone(), rows });
        voltage.extend(sim.voltage);
    }
    let scale: Vec<f64> = problem.parameters.iter().map(|p| p.initial.abs().max(f64::MIN_POSITIVE)).collect();
    let id = sandwich_covariance(&blocks, &scale)?;
    Ok(JointFit { result: search.into_result(id, voltage), experiments })
}

/// One experiment's residuals (V), point weights, sensitivity rows over the joint
/// parameters (V per unit) and weight in the cost.
struct Block {
    weight: f64,
    residuals: Vec<f64>,
    point_weights: Vec<f64>,
    rows: Vec<Vec<f64>>,
}

/// Covariance of a weighted least-squares fit whose experiment weights `w_e` are not their
/// inverse noise variances: `A⁻¹ B A⁻¹` with `A = Σ w_e J_eᵀJ_e` and
/// `B = Σ w_e² s_e² J_eᵀJ_e`, `s_e²` each experiment's residual variance (over `N - P`
/// degrees of freedom in all). With one weight for all it is `s² A⁻¹`, the single-experiment
/// [`super::identification::identifiability`]. Parameters along a direction the data do not inform
/// (eigenvalue of `A` below 1e-12 of the largest) get an infinite error.
fn sandwich_covariance(blocks: &[Block], scale: &[f64]) -> Result<Identifiability, Error> {
    let p = scale.len();
    let n: f64 = blocks.iter().map(|b| b.point_weights.iter().sum::<f64>()).sum();
    let (mut a, mut b) = (vec![0.0; p * p], vec![0.0; p * p]);
    let (mut sse, mut weight) = (0.0, 0.0);
    for blk in blocks {
        let ne: f64 = blk.point_weights.iter().sum();
        let sse_e: f64 = blk.residuals.iter().zip(&blk.point_weights).map(|(r, w)| w * r * r).sum();
        sse += blk.weight * sse_e;
        weight += blk.weight * ne;
        let s2 = sse_e / ne.max(1.0) * n / (n - p as f64).max(1.0);
        for (row, &wi) in blk.rows.iter().zip(&blk.point_weights) {
            for i in 0..p {
                for j in 0..p {
                    let f = wi * row[i] * scale[i] * row[j] * scale[j];
                    a[i * p + j] += blk.weight * f;
                    b[i * p + j] += blk.weight * blk.weight * s2 * f;
                }
            }
        }
    }
    let rmse = (sse / weight).sqrt();
    let (values, vectors) = crate::linalg::sym_eigen(&a, p)?;
    let largest = values.iter().fold(0.0f64, |m, v| m.max(*v));
    let informed: Vec<bool> = values.iter().map(|v| *v > 1e-12 * largest).collect();
    let mut pinv = vec![0.0; p * p];
    for i in 0..p {
        for j in 0..p {
            pinv[i * p + j] = (0..p).filter(|&k| informed[k]).map(|k| vectors[i * p + k] * vectors[j * p + k] / values[k]).sum();
        }
    }
    let product = |x: &[f64], y: &[f64]| -> Vec<f64> {
        (0..p * p).map(|ij| (0..p).map(|k| x[(ij / p) * p + k] * y[k * p + ij % p]).sum()).collect()
    };
    let scaled = product(&product(&pinv, &b), &pinv);
    let cov: Vec<f64> = (0..p * p).map(|ij| scaled[ij] * scale[ij / p] * scale[ij % p]).collect();
    let uninformed = |i: usize| (0..p).any(|k| !informed[k] && vectors[i * p + k].abs() > 1e-8);
    let std_errors: Vec<f64> = (0..p).map(|i| if uninformed(i) { f64::INFINITY } else { cov[i * p + i].sqrt() }).collect();
    let correlation = (0..p).map(|i| (0..p).map(|j| cov[i * p + j] / (std_errors[i] * std_errors[j])).collect()).collect();
    Ok(Identifiability { rmse, std_errors, correlation })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// With one experiment of weight 1 the sandwich is the plain least-squares covariance.
    #[test]
    fn sandwich_of_one_unit_weight_experiment_is_the_plain_covariance() {
        let rows: Vec<Vec<f64>> = (0..50).map(|k| vec![1.0, (k as f64 * 0.37).sin(), 0.1 * k as f64]).collect();
        let r: Vec<f64> = (0..50).map(|k| 1e-3 * ((k as f64 * 1.7).cos())).collect();
        let w = vec![1.0; 50];
        let scale = [2.0, 0.5, 1e-3];
        let plain = super::super::identification::covariance(&r, &w, rows.iter().map(Vec::as_slice), &scale).unwrap();
        let blocks = [Block { weight: 1.0, residuals: r.clone(), point_weights: w.clone(), rows: rows.clone() }];
        let s = sandwich_covariance(&blocks, &scale).unwrap();
        for k in 0..3 {
            assert!((s.std_errors[k] / plain.std_errors[k] - 1.0).abs() < 1e-9, "{:?} vs {:?}", s.std_errors, plain.std_errors);
        }
        assert!((s.rmse - plain.rmse).abs() < 1e-15);
        // Weight 4 on the same data: the estimate's covariance does not change (A and B
        // scale by 4 and 16).
        let blocks = [Block { weight: 4.0, residuals: r, point_weights: w, rows }];
        let s4 = sandwich_covariance(&blocks, &scale).unwrap();
        assert!((s4.std_errors[1] / plain.std_errors[1] - 1.0).abs() < 1e-9);
    }
}
