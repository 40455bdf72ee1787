//! The `[joint]` stage of a parameterisation study: several recordings fitted together at the
//! end, sharing the parameters, on the set as the stages before left it (a fit study's
//! `[[data]]` entries, `parameters`, `cost` and `[optimiser]`; gradients from forward
//! sensitivities through every experiment); `fit_voltage_joint_<name>.svg`,
//! `fit_residual_joint_<name>.svg`.

use std::fmt::Write as _;
use std::path::Path;

use serde::{Deserialize, Serialize};

use super::fit::{DataChoice, FitStudy};
use super::joint_fit::{JointRun, joint_problem_on, run_joint};
use super::parameterise::{StageOutput, Stages};
use super::{CellChoice, Output, ReportSection};
use crate::cost::CostKind;
use crate::error::Error;
use crate::params::ParameterSet;
use crate::problem::fitting::{FitParameter, ModelSpec};

/// `[joint]`: the model, the recordings (`[[joint.data]]`, as a fit study's `[[data]]`), the
/// shared parameters, the cost and the optimiser.
#[derive(Clone, Debug, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct JointSection {
    pub model: ModelSpec,
    #[serde(deserialize_with = "super::fit_data::one_or_many")]
    pub data: Vec<DataChoice>,
    /// The shared parameters (`path`, `lower`, `upper`, `log`, optional `initial`).
    pub parameters: Vec<RefitParameter>,
    #[serde(default)]
    pub cost: CostKind,
    /// `method` (default `lbfgsb`) plus the optimiser's options.
    #[serde(default)]
    pub optimiser: toml::Table,
    /// Put the fitted shared values into the parameter set (default true); a value on a bound
    /// of its search range is never put in.
    #[serde(default = "yes")]
    pub apply: bool,
}

fn yes() -> bool {
    true
}

/// A shared parameter of the joint refit: a fit study's parameter whose search starts, unless
/// `initial` is given, at the value the stages before left in the set.
#[derive(Clone, Debug, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct RefitParameter {
    pub path: String,
    #[serde(default)]
    pub initial: Option<f64>,
    pub lower: f64,
    pub upper: f64,
    #[serde(default)]
    pub log: bool,
}

impl RefitParameter {
    /// The fit parameter starting at `initial`, else at `left` (the set's value).
    fn starting_at(&self, left: f64) -> FitParameter {
        let start = self.initial.unwrap_or(left);
        FitParameter { log: self.log, ..FitParameter::linear(&self.path, start, self.lower, self.upper) }
    }
}

impl JointSection {
    /// The section as a fit study (its checks and its experiments' problems are a fit study's)
    /// with its parameters' starts in `set` (where `initial` is not given).
    fn fit_study(&self, set: &ParameterSet) -> Result<FitStudy, Error> {
        let parameters = self.parameters.iter().map(|p| Ok(p.starting_at(set.get(&p.path)?))).collect::<Result<Vec<_>, Error>>().map_err(|e| e.within("joint"))?;
        Ok(FitStudy {
            name: "joint".into(),
            source: None,
            cell: CellChoice::default(),
            model: self.model,
            data: self.data.clone(),
            parameters,
            cost: self.cost,
            optimiser: self.optimiser.clone(),
            sampler: toml::Table::new(),
            landscape: None,
            profile: None,
            sobol: None,
            experiment_design: None,
            output: Output::default(),
        })
    }

    /// Checks the section as a fit study on `set` (the study's cell; the starts the stages
    /// will leave are checked again when the stage runs).
    pub(crate) fn validate(&self, set: &ParameterSet) -> Result<(), Error> {
        let mut study = self.fit_study(set)?;
        // Before the stages run, an absent `initial` is checked at the middle of the range.
        for (p, q) in study.parameters.iter_mut().zip(&self.parameters) {
            if q.initial.is_none() && q.lower < q.upper {
                p.initial = if q.log && q.lower > 0.0 { (q.lower * q.upper).sqrt() } else { 0.5 * (q.lower + q.upper) };
            }
        }
        for p in &study.parameters {
            p.validate(set).map_err(|e| e.within("joint"))?;
        }
        study.validate().map_err(|e| e.within("joint"))
    }

    /// The recordings and protocols the stage reads.
    pub fn files(&self) -> impl Iterator<Item = &Path> {
        self.data.iter().flat_map(|d| std::iter::once(d.file.as_path()).chain(d.protocol.as_deref()))
    }
}

/// Runs `[joint]` with the parameter set as the stages before left it.
pub fn run_joint_stage(section: &JointSection, stages: &mut Stages, dir: &Path) -> Result<StageOutput, Error> {
    let study = section.fit_study(&stages.parameters)?;
    let (problem, checks) = joint_problem_on(&study, &stages.parameters, None).map_err(|e| match e {
        // A start outside its range is one the stages before left there.
        Error::InvalidParameter { field, value, reason } if field.ends_with(".initial") => {
            Error::InvalidParameter { field: format!("joint.{field}"), value, reason: format!("{reason} (the value the stages before left; give initial or widen the range)") }
        }
        other => other.within("joint"),
    })?;
    let JointRun { fit, files, body, warnings, at_bound } = run_joint(&study, &problem, None, dir, "_joint")?;
    let r = &fit.result;
    let mut md = String::from("\n## Joint refit (`[joint]`)\n\n");
    md.push_str("On the parameter set as the stages before left it. ");
    md.push_str(&body);
    md.push_str("\n| shared parameter | before | fitted |\n|---|---|---|\n");
    let mut fitted = Vec::new();
    for (k, p) in section.parameters.iter().enumerate() {
        let before = stages.parameters.get(&p.path)?;
        let _ = writeln!(md, "| {} | {before:.5e} | {:.5e} |", p.path, r.x[k]);
        fitted.push(format!("{} = {:.4e} ± {:.1e}", p.path, r.x[k], r.std_errors.get(k).copied().unwrap_or(f64::NAN)));
    }
    let rmse: Vec<String> = fit.experiments.iter().map(|e| format!("{} {:.3} -> {:.3}", e.name, 1e3 * e.initial_rmse, 1e3 * e.rmse)).collect();
    let summary = format!("joint: {}; RMSE (mV) {}", fitted.join(", "), rmse.join(", "));
    let mut notes: Vec<String> = checks;
    if section.apply {
        let names: Vec<String> = section.parameters.iter().map(|p| p.path.clone()).collect();
        notes.extend(stages.apply_fitted("joint", &names, &r.x[..names.len()], &at_bound)?);
    }
    let json = serde_json::to_value(&fit).expect("serialisable");
    Ok(StageOutput { report: ReportSection { files, section: md, warnings }, summary, notes, json })
}
