//! The `[kinetics]` stage of a parameterisation study: parameters such as rate constants or
//! a contact resistance fitted to one pulse of a recording and the rest after it, from the
//! rest state at the voltage before the pulse, with the parameter set as the stages before
//! left it (bounded Levenberg-Marquardt on plain simulations,
//! [`crate::problem::least_squares`]); `fit_voltage_kinetics.svg`, `fit_residual_kinetics.svg`.

use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use serde::{Deserialize, Serialize};

use super::ReportSection;
use super::parameterise::{StageOutput, Stages};
use super::pulses::read_pulses;
use crate::data::CsvFormat;
use crate::error::Error;
use crate::problem::fitting::{FitParameter, FittingProblem, ModelSpec};
use crate::problem::least_squares::{LmSettings, levenberg_marquardt};

/// `[kinetics]`: the recording, the pulse, the model and the parameters to fit.
#[derive(Clone, Debug, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct KineticsSection {
    /// Recording with constant-current pulses after rests (a pulse test or a GITT).
    pub file: PathBuf,
    #[serde(default)]
    pub format: CsvFormat,
    /// Which pulse, counting constant-current steps after a rest from 1 (default 1).
    #[serde(default = "first")]
    pub pulse: usize,
    pub model: ModelSpec,
    /// The parameters fitted (`path`, `initial`, `lower`, `upper`, `log`), as in a fit study.
    pub parameters: Vec<FitParameter>,
    /// Put the fitted values into the parameter set for the later stages (default true).
    #[serde(default = "yes")]
    pub apply: bool,
}

fn first() -> usize {
    1
}
fn yes() -> bool {
    true
}

impl KineticsSection {
    pub(crate) fn validate(&self) -> Result<(), Error> {
        if self.parameters.is_empty() {
            return Err(Error::InvalidSetting { field: "kinetics.parameters".into(), reason: "at least one is needed".into() });
        }
        if self.pulse == 0 {
            return Err(Error::invalid("kinetics.pulse", 0.0, "pulses count from 1"));
        }
        for p in &self.parameters {
            p.validate(&crate::params::chen2020()).map_err(|e| Error::InvalidSetting { field: "kinetics.parameters".into(), reason: e.to_string() })?;
        }
        Ok(())
    }
}

/// Runs `[kinetics]` with the parameter set as the stages before left it.
pub fn run_kinetics(section: &KineticsSection, stages: &mut Stages, dir: &Path) -> Result<StageOutput, Error> {
    let mut notes = Vec::new();
    let (rec, found) = read_pulses("kinetics", &section.file, &section.format, stages, &mut notes)?;
    let pulse = found.get(section.pulse - 1).ok_or_else(|| {
        Error::invalid("kinetics.pulse", section.pulse as f64, format!("`{}` has {} pulse(s)", section.file.display(), found.len()))
    })?;
    let problem = FittingProblem::new(section.model, stages.parameters.clone(), section.parameters.clone(), pulse.window(&rec))?.starting_at_rest()?;
    let initial = problem.simulate(&problem.initial())?;
    let fit = levenberg_marquardt(&problem, &problem.initial(), LmSettings::default())?;
    let names: Vec<String> = section.parameters.iter().map(|p| p.path.clone()).collect();
    let (at_bound, mut warnings) = super::fitted_on_bounds("the kinetics fit", &section.parameters, &fit.x);
    warnings.extend(super::unconverged_warning("the kinetics fit", &fit));
    let files: Vec<PathBuf> = super::fit::fit_plots(dir, "kinetics", "_kinetics", &problem, &initial, &fit.voltage)?;
    let rmse = |v: &[f64]| crate::stats::weighted_rms(&problem.residuals(v), &problem.weights);
    let mut md = String::from("\n## Kinetics (`[kinetics]`)\n\n");
    let _ = writeln!(
        md,
        "`{}`, pulse {} (step {}, {:.4} A for {:.1} s) and the rest after it: the {} model from the rest state at the voltage before the pulse, fitted by bounded Levenberg-Marquardt on plain simulations with the parameter set as the stages before left it: RMSE {:.3} mV (initial {:.3} mV), {} simulations, {}converged.\n",
        section.file.display(),
        section.pulse,
        pulse.step,
        pulse.current,
        pulse.duration,
        section.model.kind,
        1e3 * rmse(&fit.voltage),
        1e3 * rmse(&initial),
        fit.simulations,
        if fit.converged { "" } else { "not " }
    );
    md.push_str("| parameter | fitted | std. error | before |\n|---|---|---|---|\n");
    let mut summary = String::from("kinetics:");
    for (k, name) in names.iter().enumerate() {
        let before = stages.parameters.get(name)?;
        let _ = writeln!(md, "| {name} | {:.5e} | {:.2e} | {before:.5e} |", fit.x[k], fit.std_errors[k]);
        let _ = write!(summary, " {name} = {:.4e} ± {:.1e}", fit.x[k], fit.std_errors[k]);
    }
    let _ = write!(summary, ", RMSE {:.3} mV", 1e3 * rmse(&fit.voltage));
    if section.apply {
        notes.extend(stages.apply_fitted("kinetics", &names, &fit.x, &at_bound)?);
    }
    Ok(StageOutput { report: ReportSection { files, section: md, warnings }, summary, notes, json: serde_json::to_value(&fit).expect("serialisable") })
}
