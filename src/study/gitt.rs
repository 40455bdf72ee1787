//! The `[gitt]` stage of a parameterisation study: one electrode's particle diffusivity
//! fitted to each pulse of a GITT recording and its relaxation
//! ([`crate::problem::gitt`]), against that electrode's stoichiometry, beside the
//! Weppner-Huggins first estimate; `gitt.csv` and `gitt_diffusivity.svg`.

use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use serde::{Deserialize, Serialize};

use super::ReportSection;
use super::parameterise::{StageOutput, Stages};
use super::pulses::read_pulses;
use crate::data::CsvFormat;
use crate::error::Error;
use crate::problem::fitting::{FitParameter, ModelSpec};
use crate::problem::gitt::fit_pulses;
use crate::report::plot::{Series, line_plot};

/// `[gitt]`: the recording, the model and the diffusivity to fit.
#[derive(Clone, Debug, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct GittSection {
    /// GITT recording: constant-current pulses, each after a rest and followed by one.
    pub file: PathBuf,
    #[serde(default)]
    pub format: CsvFormat,
    /// The model fitted to each pulse (`{ kind = "dfn" }`; submodels and mesh as in a fit).
    pub model: ModelSpec,
    /// The diffusivity fitted: `path` (`negative.diffusivity` or `positive.diffusivity`),
    /// `initial`, `lower`, `upper`, `log`.
    pub parameter: FitParameter,
    /// Put the median of the fitted diffusivities into the parameter set (default false).
    #[serde(default)]
    pub apply: bool,
}

impl GittSection {
    pub(crate) fn validate(&self) -> Result<(), Error> {
        if !matches!(self.parameter.path.as_str(), "negative.diffusivity" | "positive.diffusivity") {
            return Err(Error::InvalidSetting { field: "gitt.parameter.path".into(), reason: format!("`{}`: give negative.diffusivity or positive.diffusivity", self.parameter.path) });
        }
        self.parameter.validate(&crate::params::chen2020()).map_err(|e| Error::InvalidSetting { field: "gitt.parameter".into(), reason: e.to_string() })
    }
}

/// Runs `[gitt]` with the parameter set as the stages before left it.
pub fn run_gitt(section: &GittSection, stages: &mut Stages, dir: &Path) -> Result<StageOutput, Error> {
    let mut notes = Vec::new();
    let (rec, found) = read_pulses("gitt", &section.file, &section.format, stages, &mut notes)?;
    let fits = fit_pulses(section.model, &stages.parameters, &rec, &found, &section.parameter)?;
    let negative = section.parameter.path.starts_with("negative");
    let (symbol, electrode) = if negative { ("x", "negative") } else { ("y", "positive") };
    let stoichiometry = |f: &crate::problem::gitt::PulseDiffusivity| if negative { f.negative_stoichiometry } else { f.positive_stoichiometry };
    let (lo, hi) = (section.parameter.lower, section.parameter.upper);
    let mut warnings = Vec::new();
    let mut csv = String::from("step,discharged_Ah,current_A,duration_s,negative_stoichiometry,positive_stoichiometry,ocp_slope_V,fitted_m2_s,std_error_m2_s,rmse_V,weppner_huggins_m2_s\n");
    let mut md = String::from("\n## GITT diffusivity (`[gitt]`)\n\n");
    let _ = writeln!(
        md,
        "`{}`: {} pulse(s). Each pulse and the rest after it is fitted on its own: the {} model from the rest state at the voltage recorded before the pulse (on the set's lithium line), `{}` by bounded Levenberg-Marquardt on plain simulations from the best of a scan over its range, the other parameters as the stages before left them. The stoichiometries are the model's at the pulse's midpoint; where the electrode's OCP is flat there (small |dU/dx|) the voltage hardly depends on its diffusivity, and the fitted value carries whatever the model misses. Weppner-Huggins `4/(pi tau) (R/3)^2 (dE_s/dE_t)^2` is the classic first estimate: it assumes one electrode and a `sqrt(t)` response over the whole pulse.\n",
        section.file.display(),
        fits.len(),
        section.model.kind,
        section.parameter.path
    );
    let _ = writeln!(md, "| step | {symbol} (-) | dU/d{symbol} (V) | fitted D (m^2/s) | std. error | RMSE (mV) | Weppner-Huggins (m^2/s) |\n|---|---|---|---|---|---|---|");
    let (mut xs, mut fitted, mut xs_wh, mut wh) = (Vec::new(), Vec::new(), Vec::new(), Vec::new());
    for f in &fits {
        let on_bound = super::on_bounds(&[f.fitted], &[lo], &[hi]);
        if let Some(why) = &f.failure {
            warnings.push(format!("the fit of pulse step {} failed: {why}", f.step));
        } else if let Some((_, side)) = on_bound.first() {
            warnings.push(format!("the fit of pulse step {} ended at the {side} bound of {} ({}): no estimate there", f.step, section.parameter.path, crate::error::number(f.fitted)));
        } else {
            xs.push(stoichiometry(f));
            fitted.push(f.fitted.log10());
        }
        if f.converged == Some(false) {
            warnings.push(format!("the fit of pulse step {} stopped on its iteration cap or with a parameter held before converging: the value is the best found so far", f.step));
        }
        if let Some(d) = f.weppner_huggins.filter(|d| *d > 0.0) {
            xs_wh.push(stoichiometry(f));
            wh.push(d.log10());
        }
        let wh_text = f.weppner_huggins.map_or(String::new(), |d| format!("{d:.4e}"));
        let _ = writeln!(csv, "{},{:.6},{:.6},{},{:.6},{:.6},{:.4},{:.6e},{:.3e},{:.6e},{wh_text}", f.step, f.discharged_before, f.current, f.duration, f.negative_stoichiometry, f.positive_stoichiometry, f.ocp_slope, f.fitted, f.std_error, f.rmse);
        let mark = if f.failure.is_some() { " (failed)" } else if on_bound.is_empty() { "" } else { " (on bound)" };
        let _ = writeln!(md, "| {} | {:.4} | {:.3} | {:.4e}{mark} | {:.2e} | {:.3} | {} |", f.step, stoichiometry(f), f.ocp_slope, f.fitted, f.std_error, 1e3 * f.rmse, if wh_text.is_empty() { "-".into() } else { wh_text });
    }
    let mut files: Vec<PathBuf> = Vec::new();
    super::write_output(dir, "gitt.csv", csv, &mut files)?;
    let plot = dir.join("gitt_diffusivity.svg");
    line_plot(&plot, &format!("{electrode} particle diffusivity from GITT"), &format!("{electrode} stoichiometry {symbol} (-)"), "log10 D (m^2/s)", &[
        Series { label: format!("fitted ({})", section.model.kind), x: &xs, y: &fitted },
        Series { label: "Weppner-Huggins (first estimate)".into(), x: &xs_wh, y: &wh },
    ])?;
    files.push(plot);
    let median = (!fitted.is_empty()).then(|| 10f64.powf(crate::stats::median(&fitted)));
    let _ = writeln!(md, "\nMedian of the fitted values: {}. Table: `gitt.csv`; plot: `gitt_diffusivity.svg`.", median.map_or("-".into(), |m| format!("{m:.4e} m^2/s")));
    if let (true, Some(m)) = (section.apply, median) {
        stages.parameters.set(&section.parameter.path, m)?;
        notes.push(format!("{} = {m:.4e} m^2/s (the median of the GITT fits) is used from here on (gitt.apply = true)", section.parameter.path));
    }
    let summary = format!(
        "gitt: {} pulse(s), {} = {} (median of the fits), {symbol} {:.3}-{:.3}",
        fits.len(),
        section.parameter.path,
        median.map_or("-".into(), |m| format!("{m:.4e} m^2/s")),
        xs.iter().copied().fold(f64::INFINITY, f64::min),
        xs.iter().copied().fold(f64::NEG_INFINITY, f64::max)
    );
    Ok(StageOutput { report: ReportSection { files, section: md, warnings }, summary, notes, json: serde_json::json!({ "pulses": fits, "median_m2_s": median }) })
}
