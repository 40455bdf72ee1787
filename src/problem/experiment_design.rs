//! Optimal experiment design: which next experiment, from a family of pulse trains and
//! constant-current discharges within the cell's voltage limits, would best determine the
//! parameters a fit left undetermined.
//!
//! Each candidate is simulated at the fitted parameters with forward sensitivities; its Fisher
//! information (relative units, `θ_a θ_b Σ_t s_a(t) s_b(t) / σ²` over points sampled every
//! `sampling` seconds, `σ` the fit's noise level) is added to the fitted recording's. The
//! criterion is D_s-optimality on the targets: the log-determinant of the targets' block of
//! the covariance `F⁻¹` (the volume of their confidence ellipsoid; lower is better). The
//! targets are the parameters the fit did not identify (relative standard error above
//! [`MAX_RELATIVE_ERROR`](super::verdict::MAX_RELATIVE_ERROR) or correlated beyond [`MAX_CORRELATION`](super::verdict::MAX_CORRELATION)); all of them when it
//! identified every one. These are predictions at the fitted point: local, as the Fisher
//! standard errors are.

use rayon::prelude::*;
use serde::{Deserialize, Serialize};

use super::fitting::FittingProblem;
use super::identification::relative_information;
use super::verdict::{Standing, standings};
use crate::data::Recording;
use crate::error::Error;
use crate::linalg::{sym_eigen, sym_inverse};
use crate::models::ModelBuilder;
use crate::protocol::experiment;
use crate::simulation::{SimOptions, simulate};

/// The family of candidate experiments, each started from the fitted cell's initial state.
#[derive(Clone, Debug, Deserialize, Serialize)]
#[serde(default, deny_unknown_fields)]
pub struct DesignSettings {
    /// Discharge rates of the pulses and of the constant-current candidates (C).
    pub rates: Vec<f64>,
    /// Pulse lengths (s).
    pub pulse_seconds: Vec<f64>,
    /// Rests after each pulse (s).
    pub rest_seconds: Vec<f64>,
    /// Pulses per train.
    pub pulses: usize,
    /// Sampling interval of the predicted recording (s).
    pub sampling: f64,
}

impl Default for DesignSettings {
    fn default() -> Self {
        Self { rates: vec![0.5, 1.0, 2.0], pulse_seconds: vec![10.0, 60.0], rest_seconds: vec![60.0, 600.0], pulses: 10, sampling: 1.0 }
    }
}

impl DesignSettings {
    pub fn validate(&self) -> Result<(), Error> {
        let positive = |field: &str, v: &[f64]| match v.iter().find(|x| !(**x > 0.0 && x.is_finite())) {
            Some(x) => Err(Error::invalid(field, *x, "must be positive and finite")),
            None if v.is_empty() => Err(Error::InvalidSetting { field: field.into(), reason: "needs at least one value".into() }),
            None => Ok(()),
        };
        positive("experiment_design.rates", &self.rates)?;
        positive("experiment_design.pulse_seconds", &self.pulse_seconds)?;
        positive("experiment_design.rest_seconds", &self.rest_seconds)?;
        if !(1..=200).contains(&self.pulses) {
            return Err(Error::invalid("experiment_design.pulses", self.pulses as f64, "must lie in 1..=200"));
        }
        if !(self.sampling > 0.0 && self.sampling <= 60.0) {
            return Err(Error::invalid("experiment_design.sampling", self.sampling, "must lie in (0, 60] s"));
        }
        Ok(())
    }

    /// The candidates as experiment strings: every pulse train, then a discharge at each rate.
    pub fn candidates(&self, lower_cutoff: f64) -> Vec<Vec<String>> {
        let mut out = Vec::new();
        for &rate in &self.rates {
            for &pulse in &self.pulse_seconds {
                for &rest in &self.rest_seconds {
                    let one = [format!("Discharge at {rate}C for {pulse} seconds or until {lower_cutoff} V"), format!("Rest for {rest} seconds")];
                    out.push(one.iter().cycle().take(2 * self.pulses).cloned().collect());
                }
            }
        }
        out.extend(self.rates.iter().map(|rate| vec![format!("Discharge at {rate}C until {lower_cutoff} V"), "Rest for 30 minutes".to_string()]));
        out
    }
}

/// One candidate experiment and what it would leave.
#[derive(Clone, Debug, Serialize)]
pub struct CandidateExperiment {
    pub steps: Vec<String>,
    /// Duration (s) of the experiment as simulated (steps end early at a cut-off).
    pub duration: f64,
    /// Predicted relative standard error (-) of every fitted parameter after fitting the
    /// recording and this experiment together.
    pub relative_std_errors: Vec<f64>,
    /// D_s criterion: ln det of the targets' relative covariance (lower is better).
    pub criterion: f64,
}

/// The design: the fit's standing, and the candidates best first.
#[derive(Clone, Debug, Serialize)]
pub struct ExperimentDesign {
    pub names: Vec<String>,
    pub targets: Vec<String>,
    /// Noise level (V) the predictions assume.
    pub noise: f64,
    /// Relative standard errors (-) from the fitted recording alone, and its criterion.
    pub before: Vec<f64>,
    pub criterion_before: f64,
    pub candidates: Vec<CandidateExperiment>,
}

/// Fisher information of `problem` at `x` in relative units, noise `sigma` (V).
pub fn relative_fisher(problem: &FittingProblem, x: &[f64], sigma: f64) -> Result<Vec<f64>, Error> {
    let sim = problem.simulate_with_sensitivities(x)?;
    Ok(relative_information(&problem.weights, sim.sensitivity_rows(), x).into_iter().map(|v| v / (sigma * sigma)).collect())
}

/// Relative standard errors and the D_s criterion of `f` on `targets`.
fn standing(f: &[f64], p: usize, targets: &[usize]) -> Result<(Vec<f64>, f64), Error> {
    let cov = sym_inverse(f, p)?;
    let se = (0..p).map(|a| cov[a * p + a].max(0.0).sqrt()).collect();
    let t = targets.len();
    let block: Vec<f64> = (0..t * t).map(|k| cov[targets[k / t] * p + targets[k % t]]).collect();
    let criterion = if block.iter().all(|v| v.is_finite()) {
        let (values, _) = sym_eigen(&block, t)?;
        values.iter().map(|v| v.max(f64::MIN_POSITIVE).ln()).sum()
    } else {
        f64::INFINITY
    };
    Ok((se, criterion))
}

/// Parameters the fitted recording leaves undetermined (all of them when none is).
fn undetermined(f: &[f64], p: usize) -> Result<Vec<usize>, Error> {
    let cov = sym_inverse(f, p)?;
    let se: Vec<f64> = (0..p).map(|a| cov[a * p + a].max(0.0).sqrt()).collect();
    let rho: Vec<Vec<f64>> = (0..p).map(|a| (0..p).map(|b| cov[a * p + b] / (se[a] * se[b])).collect()).collect();
    // Relative units: every parameter at 1.
    let names: Vec<String> = (0..p).map(|a| a.to_string()).collect();
    let loose: Vec<usize> =
        standings(&names, &vec![1.0; p], &se, &rho).iter().enumerate().filter(|(_, s)| !matches!(s, Standing::Identified { .. })).map(|(a, _)| a).collect();
    Ok(if loose.is_empty() { (0..p).collect() } else { loose })
}

/// The recording `steps` would produce from the cell at `x`, sampled every `sampling`
/// seconds (its voltage and current as simulated).
fn predicted_recording(problem: &FittingProblem, x: &[f64], steps: &[String], sampling: f64) -> Result<(crate::protocol::Protocol, Recording), Error> {
    let p = problem.parameters_at(x)?;
    let protocol = experiment::parse(steps, p.cell.nominal_capacity)?;
    let mut builder = ModelBuilder::new(problem.spec.kind, problem.spec.submodels, problem.spec.mesh);
    let built = builder.build(&p)?;
    let opts = SimOptions::for_cell(&p);
    let probe = simulate(built.model.as_ref(), &mut built.workspace, &protocol, &opts, None)?;
    let end = probe.time.last().copied().unwrap_or(0.0);
    let grid: Vec<f64> = (0..).map(|k| k as f64 * sampling).take_while(|t| *t <= end).collect();
    let sampled = simulate(built.model.as_ref(), &mut built.workspace, &protocol, &SimOptions { t_eval: Some(grid.clone()), ..opts }, None)?;
    let n = sampled.time.len().min(grid.len());
    let rec = Recording { time: sampled.time[..n].to_vec(), current: sampled.current[..n].to_vec(), voltage: sampled.voltage[..n].to_vec(), temperature: None };
    Ok((protocol, rec))
}

/// Ranks the candidates of `settings` as additions to `problem`'s recording, at the fitted
/// point `x` with noise `sigma` (V).
pub fn design_experiment(problem: &FittingProblem, x: &[f64], sigma: f64, settings: &DesignSettings) -> Result<ExperimentDesign, Error> {
    settings.validate()?;
    if !(sigma > 0.0 && sigma.is_finite()) {
        return Err(Error::invalid("noise", sigma, "must be a positive voltage (V)"));
    }
    let p = problem.dim();
    let f0 = relative_fisher(problem, x, sigma)?;
    let targets = undetermined(&f0, p)?;
    let (before, criterion_before) = standing(&f0, p, &targets)?;
    let lower = problem.parameters_at(x)?.cell.lower_cutoff;
    let scored: Vec<Result<CandidateExperiment, Error>> = settings
        .candidates(lower)
        .into_par_iter()
        .map(|steps| {
            let (protocol, rec) = predicted_recording(problem, x, &steps, settings.sampling)?;
            let duration = rec.time.last().copied().unwrap_or(0.0);
            // From the same initial state as the fitted recording (its rest voltage, if it
            // started from one).
            let mut base = problem.base.clone();
            if let Some(v) = problem.initial_ocv {
                base.set_initial_ocv(v)?;
            }
            let next = FittingProblem::new(problem.spec, base, problem.parameters.clone(), rec)?.with_protocol(protocol)?;
            let f1 = relative_fisher(&next, x, sigma)?;
            let total: Vec<f64> = f0.iter().zip(&f1).map(|(a, b)| a + b).collect();
            let (relative_std_errors, criterion) = standing(&total, p, &targets)?;
            Ok(CandidateExperiment { steps, duration, relative_std_errors, criterion })
        })
        .collect();
    let mut candidates: Vec<CandidateExperiment> = scored.into_iter().collect::<Result<_, _>>()?;
    candidates.sort_by(|a, b| a.criterion.total_cmp(&b.criterion));
    let names: Vec<String> = problem.parameters.iter().map(|q| q.path.clone()).collect();
    Ok(ExperimentDesign { targets: targets.iter().map(|&k| names[k].clone()).collect(), names, noise: sigma, before, criterion_before, candidates })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The same information twice (an experiment repeated) divides every standard error by
    /// √2 and lowers the criterion by `t ln 2` for `t` targets; a block the recording does not
    /// inform has infinite errors and criterion.
    #[test]
    fn repeating_an_experiment_divides_the_errors_by_root_two() {
        let f = [4.0, 3.9, 3.9, 4.0];
        let (se, c) = standing(&f, 2, &[0, 1]).unwrap();
        let twice: Vec<f64> = f.iter().map(|v| 2.0 * v).collect();
        let (se2, c2) = standing(&twice, 2, &[0, 1]).unwrap();
        for k in 0..2 {
            assert!((se[k] / se2[k] - 2f64.sqrt()).abs() < 1e-12, "{se:?} {se2:?}");
        }
        assert!((c - c2 - 2.0 * 2f64.ln()).abs() < 1e-12);
        // Correlated (rho = 0.975): both are targets.
        assert_eq!(undetermined(&f, 2).unwrap(), vec![0, 1]);
        let (se0, c0) = standing(&[1.0, 0.0, 0.0, 0.0], 2, &[1]).unwrap();
        assert!(se0[1].is_infinite() && c0.is_infinite() && (se0[0] - 1.0).abs() < 1e-15);
    }
}
