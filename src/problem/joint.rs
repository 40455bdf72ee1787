//! Several experiments fitted together: each is a [`FittingProblem`] with its own recording,
//! protocol, temperature and initial state, sharing the cell parameters; per-experiment
//! nuisance parameters (the initial state of charge) sit after the shared ones in the joint
//! vector. The cost is the weighted sum of the experiments' costs, its gradient the weighted
//! sum of theirs (forward sensitivities of every experiment), and the standard errors come
//! from the summed Fisher information.

use rayon::prelude::*;
use serde::Serialize;

use super::fit::{FitObjective, FitResult, covariance, minimise, weighted_rms};
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
/// from every experiment's sensitivities (rows weighted by the experiment's weight).
pub fn fit_joint(problem: &JointProblem, cost: CostKind, optimiser: &str, options: OptimOptions) -> Result<JointFit, Error> {
    let objective = JointObjective { problem, cost };
    let initial = problem.initial();
    let search = minimise(&objective, &problem.parameters, cost, optimiser, options)?;
    let theta = search.result.x[..problem.dim()].to_vec();
    let sims: Vec<_> = problem
        .experiments
        .par_iter()
        .map(|e| Ok((e.problem.simulate_with_sensitivities(&problem.local(e, &theta))?, e.problem.simulate(&problem.local(e, &initial))?)))
        .collect::<Result<_, Error>>()?;
    let (mut r, mut w, mut rows, mut voltage) = (Vec::new(), Vec::new(), Vec::new(), Vec::new());
    let mut experiments = Vec::new();
    for (e, (sim, v0)) in problem.experiments.iter().zip(sims) {
        let re = e.problem.residuals(&sim.voltage);
        let we = &e.problem.weights;
        for (k, row) in sim.sensitivity.iter().enumerate() {
            let mut joint = vec![0.0; problem.dim()];
            for (&j, s) in e.index.iter().zip(row) {
                joint[j] = *s;
            }
            rows.push(joint);
            r.push(re[k]);
            w.push(e.weight * we[k]);
        }
        experiments.push(ExperimentFit {
            name: e.name.clone(),
            weight: e.weight,
            points: we.iter().filter(|w| **w > 0.0).count(),
            initial_rmse: weighted_rms(&e.problem.residuals(&v0), we),
            rmse: weighted_rms(&re, we),
            voltage: sim.voltage.clone(),
            initial_voltage: v0,
        });
        voltage.extend(sim.voltage);
    }
    let scale: Vec<f64> = problem.parameters.iter().map(|p| p.initial.abs().max(f64::MIN_POSITIVE)).collect();
    let id = covariance(&r, &w, &rows, &scale)?;
    Ok(JointFit { result: search.into_result(id, voltage), experiments })
}
