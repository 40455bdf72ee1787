//! The `[thermal]` stage of a parameterisation study: thermal parameters (the heat transfer
//! coefficient, a heat capacity) fitted to a recording's temperature alone, with the lumped
//! thermal model on the set as the stages before left it (bounded Levenberg-Marquardt on plain
//! simulations: the voltage drives the heat, its misfit is the electrochemistry's and is
//! reported beside, not fitted);
//! `fit_temperature_thermal.svg`, `fit_voltage_thermal.svg`, `fit_residual_thermal.svg`.

use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use serde::{Deserialize, Serialize};

use super::ReportSection;
use super::parameterise::{StageOutput, Stages};
use crate::data::CsvFormat;
use crate::data::cycler::read_checked;
use crate::error::Error;
use crate::problem::fitting::{FitParameter, FittingProblem, ModelSpec};
use crate::problem::least_squares::{LmSettings, levenberg_marquardt};
use crate::report::plot::{Series, line_plot};

/// `[thermal]`: the recording (with its temperature), the thermal model and the parameters.
#[derive(Clone, Debug, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct ThermalSection {
    /// Recording with a temperature column (a discharge that heats the cell, and the rest after).
    pub file: PathBuf,
    #[serde(default)]
    pub format: CsvFormat,
    /// The model, with `submodels = { thermal = true }`.
    pub model: ModelSpec,
    /// The parameters fitted (`path`, `initial`, `lower`, `upper`, `log`), as in a fit study.
    pub parameters: Vec<FitParameter>,
    /// Initial state of charge (-); when absent the model starts at rest at the first recorded
    /// voltage (the recording must then begin at rest).
    #[serde(default)]
    pub initial_soc: Option<f64>,
    /// Ambient and initial temperature (K); the first recorded temperature when absent.
    #[serde(default)]
    pub temperature: Option<f64>,
    /// Put the fitted values into the parameter set for the later stages (default true); a
    /// value on a bound of its search range is never put in.
    #[serde(default = "yes")]
    pub apply: bool,
}

fn yes() -> bool {
    true
}

impl ThermalSection {
    pub(crate) fn validate(&self, set: &crate::params::ParameterSet) -> Result<(), Error> {
        if !self.model.submodels.thermal {
            return Err(Error::InvalidSetting { field: "thermal.model.submodels.thermal".into(), reason: "the thermal stage fits the temperature: set submodels = { thermal = true }".into() });
        }
        if self.parameters.is_empty() {
            return Err(Error::InvalidSetting { field: "thermal.parameters".into(), reason: "at least one is needed".into() });
        }
        for p in &self.parameters {
            p.validate(set).map_err(|e| e.within("thermal"))?;
        }
        if let Some(soc) = self.initial_soc.filter(|s| !(0.0..=1.0).contains(s)) {
            return Err(Error::invalid("thermal.initial_soc", soc, "must lie in [0, 1]"));
        }
        if let Some(t) = self.temperature {
            crate::params::check::temperature("thermal.temperature", t)?;
        }
        Ok(())
    }
}

/// Runs `[thermal]` with the parameter set as the stages before left it.
pub fn run_thermal(section: &ThermalSection, stages: &mut Stages, dir: &Path) -> Result<StageOutput, Error> {
    let (data, mut notes) = read_checked(&section.file, &section.format, &stages.parameters).map_err(|e| e.input("thermal.file"))?;
    let rec = data.recording;
    let recorded = rec.temperature.clone().ok_or_else(|| Error::InvalidSetting {
        field: "thermal.file".into(),
        reason: format!("`{}` has no temperature column to fit", section.file.display()),
    })?;
    let mut base = stages.parameters.clone();
    let ambient = section.temperature.unwrap_or(recorded[0]);
    base.set("thermal.ambient_temperature", ambient)?;
    base.set("thermal.initial_temperature", ambient)?;
    if let Some(soc) = section.initial_soc {
        crate::params::set_initial_soc_from(&mut base, soc, "thermal.initial_soc")?;
    }
    let mut problem = FittingProblem::new(section.model, base, section.parameters.clone(), rec)?;
    if section.initial_soc.is_none() {
        problem = problem.starting_at_rest().map_err(|e| e.within("thermal"))?;
    }
    let problem = problem.fitting_temperature_only()?;
    let x0 = problem.initial();
    let initial = problem.simulate_outputs(&x0).map_err(|why| problem.start_failure(&x0, "thermal.file", why))?;
    let fit = levenberg_marquardt(&problem, &x0, LmSettings::default())?;
    let fitted = problem.simulate_outputs(&fit.x)?;
    let names: Vec<String> = section.parameters.iter().map(|p| p.path.clone()).collect();
    let (at_bound, mut warnings) = super::fitted_on_bounds("the thermal fit", &section.parameters, &fit.x);
    warnings.extend(super::unconverged_warning("the thermal fit", &fit));
    let mut files: Vec<PathBuf> = super::fit::fit_plots(dir, "thermal", "_thermal", &problem, &initial.voltage, &fitted.voltage)?;
    let temperature_plot = dir.join("fit_temperature_thermal.svg");
    let t = &problem.data.time;
    line_plot(
        &temperature_plot,
        "thermal: temperature",
        "time (s)",
        "temperature (K)",
        &[
            Series { label: "data".into(), x: t, y: &recorded },
            Series { label: "initial".into(), x: t, y: &initial.temperature },
            Series { label: "fitted".into(), x: t, y: &fitted.temperature },
        ],
    )?;
    files.push(temperature_plot);
    // RMSE of the voltage (V) and of the fitted temperature (K), initial and fitted.
    let rms = |r: Vec<f64>| crate::stats::weighted_rms(&r, &problem.weights);
    let (v0, v1) = (rms(problem.residuals(&initial.voltage)), rms(problem.residuals(&fitted.voltage)));
    let (t0, t1) = (rms(problem.fitted_residuals(&initial)), rms(problem.fitted_residuals(&fitted)));
    let rise = recorded.iter().fold(f64::NEG_INFINITY, |a, b| a.max(*b)) - recorded[0];
    let mut md = String::from("\n## Thermal (`[thermal]`)\n\n");
    let _ = writeln!(
        md,
        "`{}` (temperature rise {rise:.2} K over the first recorded {:.2} K): the {} model with the lumped thermal balance at ambient {ambient:.2} K, {}, the temperature fitted alone (the voltage drives the heat) by bounded Levenberg-Marquardt on plain simulations with the parameter set as the stages before left it: temperature RMSE {:.3} K (initial {:.3} K), voltage RMSE {:.3} mV (initial {:.3} mV), {} simulations, {}converged.\n",
        section.file.display(),
        recorded[0],
        section.model.kind,
        match section.initial_soc {
            Some(s) => format!("from state of charge {s}"),
            None => "from rest at the first recorded voltage".into(),
        },
        t1,
        t0,
        1e3 * v1,
        1e3 * v0,
        fit.simulations,
        if fit.converged { "" } else { "not " }
    );
    md.push_str("| parameter | fitted | std. error | before |\n|---|---|---|---|\n");
    let mut fitted_text = Vec::new();
    for (k, name) in names.iter().enumerate() {
        let before = stages.parameters.get(name)?;
        let _ = writeln!(md, "| {name} | {:.5e} | {:.2e} | {before:.5e} |", fit.x[k], fit.std_errors[k]);
        fitted_text.push(format!("{name} = {:.4e} ± {:.1e}", fit.x[k], fit.std_errors[k]));
    }
    let summary = format!("thermal: {}; temperature RMSE {t1:.3} K, voltage RMSE {:.3} mV", fitted_text.join(", "), 1e3 * v1);
    if section.apply {
        notes.extend(stages.apply_fitted("thermal", &names, &fit.x, &at_bound)?);
    }
    let json = serde_json::json!({ "fit": fit, "temperature_rmse_k": t1, "initial_temperature_rmse_k": t0, "ambient_k": ambient });
    Ok(StageOutput { report: ReportSection { files, section: md, warnings }, summary, notes, json })
}
