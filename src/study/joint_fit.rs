//! The fit of a study with several `[[data]]` entries: the experiments' problems joined
//! ([`crate::problem::joint`]), fitted together, and reported with each experiment's RMSE,
//! its fit and residual plots, and the shared and per-experiment parameters with standard
//! errors.

use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use super::fit::{FitOutcome, FitStudy, fit_plots, parameter_table, with_notes};
use super::write_output;
use crate::error::Error;
use crate::params::ParameterSet;
use crate::problem::joint::{JointFit, JointProblem, fit_joint};

/// The study's experiments joined into one problem, with the notes of each recording's
/// checks against the cell (a likely unit error is an error before any fit).
pub fn joint_problem(study: &FitStudy, data: Option<&Path>) -> Result<(JointProblem, Vec<String>), Error> {
    joint_problem_on(study, &study.cell.load()?, data)
}

/// [`joint_problem`] on the parameter set `base` instead of the study's cell.
pub fn joint_problem_on(study: &FitStudy, base: &ParameterSet, data: Option<&Path>) -> Result<(JointProblem, Vec<String>), Error> {
    let mut experiments = Vec::new();
    let mut notes = Vec::new();
    for (k, d) in study.data.iter().enumerate() {
        let (problem, own, checks) = study.experiment_problem_on(base.clone(), k, data)?;
        notes.extend(checks.into_iter().map(|n| format!("{}: {n}", d.label(k))));
        experiments.push((d.label(k), problem, d.weight, own));
    }
    Ok((JointProblem::new(study.parameters.clone(), experiments)?, notes))
}

/// A joint fit done and drawn: the fit, its plots, the report's body (without heading),
/// warnings and the parameters that ended on a bound.
pub(crate) struct JointRun {
    pub fit: JointFit,
    pub files: Vec<PathBuf>,
    pub body: String,
    pub warnings: Vec<String>,
    pub at_bound: Vec<super::OnBound>,
}

/// Fits `problem` (the study's experiments) jointly and writes, per experiment,
/// `fit_voltage<suffix>_<name>.svg` and `fit_residual<suffix>_<name>.svg` into `dir`.
pub(crate) fn run_joint(study: &FitStudy, problem: &JointProblem, data: Option<&Path>, dir: &Path, suffix: &str) -> Result<JointRun, Error> {
    let (method, options) = study.optimiser()?;
    let fit = fit_joint(problem, study.cost, &method, options)?;
    let r = &fit.result;
    let (at_bound, mut warnings) = super::fitted_on_bounds("the joint fit", &problem.parameters, &r.x);
    warnings.extend(super::truncation_warning("the joint fit", &r.stop, r.iterations, r.evaluations));
    let mut files = Vec::new();
    for (e, ef) in problem.experiments.iter().zip(&fit.experiments) {
        let title = format!("{}: {}", study.name, ef.name);
        files.extend(fit_plots(dir, &title, &format!("{suffix}_{}", ef.name), &e.problem, &ef.initial_voltage, &ef.voltage)?);
    }
    let body = report(study, data, problem, &fit, &method);
    Ok(JointRun { fit, files, body, warnings, at_bound })
}

/// Fits the experiments jointly and writes `report.md`, `fit.json` and, per experiment,
/// `fit_voltage_<name>.svg` and `fit_residual_<name>.svg` into `dir`.
pub(crate) fn joint_fit_into(study: &FitStudy, data: Option<&Path>, dir: &Path) -> Result<FitOutcome, Error> {
    let (problem, checks) = joint_problem(study, data)?;
    let JointRun { fit, mut files, body, warnings, at_bound } = run_joint(study, &problem, data, dir, "")?;
    let notes: Vec<String> = study.noise_note(data).into_iter().chain(checks).collect();
    write_output(dir, "fit.json", serde_json::to_string_pretty(&fit).expect("serialisable"), &mut files)?;
    let md = format!("# {}\n\n{body}", study.name);
    write_output(dir, "report.md", with_notes(md, &notes, &warnings), &mut files)?;
    let initial_rmse = combined_initial_rmse(&fit);
    Ok(FitOutcome { result: fit.result, initial_rmse, files, notes, warnings, at_bound, experiments: fit.experiments, rejection: None })
}

/// The RMS residual (V) at the initial parameters over every experiment's points, each
/// weighted by its experiment's weight.
fn combined_initial_rmse(fit: &JointFit) -> f64 {
    let (sum, weight) = fit.experiments.iter().fold((0.0, 0.0), |(s, w), e| {
        let n = e.weight * e.points as f64;
        (s + n * e.initial_rmse * e.initial_rmse, w + n)
    });
    (sum / weight).sqrt()
}

fn report(study: &FitStudy, data: Option<&Path>, problem: &JointProblem, fit: &JointFit, method: &str) -> String {
    let r = &fit.result;
    let mut s = String::new();
    let _ = writeln!(
        s,
        "Fitted {} parameter(s) of the {} model jointly to {} experiments by {} with the {} optimiser: \
         weighted RMSE {:.3} mV (initial {:.3} mV), {} evaluations and {} gradients in {:.2} s, stop: {:?}.\n",
        problem.dim(),
        study.model.kind,
        problem.experiments.len(),
        study.cost.name(),
        method,
        r.rmse * 1e3,
        combined_initial_rmse(fit) * 1e3,
        r.evaluations,
        r.gradient_evaluations,
        r.seconds,
        r.stop
    );
    s.push_str("| experiment | file | weight | points | initial RMSE (mV) | fitted RMSE (mV) |\n|---|---|---|---|---|---|\n");
    for (k, e) in fit.experiments.iter().enumerate() {
        let _ = writeln!(
            s,
            "| {} | `{}` | {} | {} | {:.3} | {:.3} |",
            e.name,
            data.filter(|_| k == 0).unwrap_or(&study.data[k].file).display(),
            e.weight,
            e.points,
            e.initial_rmse * 1e3,
            e.rmse * 1e3
        );
    }
    s.push('\n');
    s.push_str(&parameter_table(r));
    s
}
