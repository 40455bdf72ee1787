//! The `[experiment_design]` section of a fitting study: after the fit, the candidate
//! experiments ranked by how well they would determine what the fit left undetermined
//! ([`crate::problem::experiment_design`]), a table in the report and
//! `experiment_design.json`.

use std::fmt::Write as _;
use std::path::Path;

use crate::error::Error;
use crate::problem::experiment_design::{DesignSettings, design_experiment};
use crate::problem::fitting::FittingProblem;
use crate::problem::identification::FitResult;

/// Candidates listed in the report (all are in the JSON).
const LISTED: usize = 8;

/// Ranks the candidates at the fitted point, with the fit's RMSE as the noise level.
pub fn write_design(dir: &Path, problem: &FittingProblem, result: &FitResult, settings: &DesignSettings) -> Result<super::ReportSection, Error> {
    let x = &result.x[..problem.dim()];
    let d = design_experiment(problem, x, result.rmse, settings)?;
    let pct = |v: f64| if v.is_finite() { format!("{:.2} %", 100.0 * v) } else { "inf".into() };
    let mut section = format!(
        "## Next experiment (D-optimal design)\n\nEach candidate is simulated at the fitted parameters from the fitted recording's initial state, sampled every {} s, and its Fisher information (noise {:.2} mV, the fit's RMSE) added to the recording's. Ranked by the log-determinant of the covariance of {} (lower is better); predicted relative standard errors after fitting both together.\n\n| experiment | duration (s) | criterion | {} |\n|---|---|---|{}\n| this recording alone | - | {:.2} | {} |\n",
        settings.sampling,
        d.noise * 1e3,
        d.targets.join(", "),
        d.names.join(" | "),
        "---|".repeat(d.names.len()),
        d.criterion_before,
        d.before.iter().map(|v| pct(*v)).collect::<Vec<_>>().join(" | ")
    );
    for c in d.candidates.iter().take(LISTED) {
        let steps = if c.steps.len() > 2 { format!("{} x ({}; {})", c.steps.len() / 2, c.steps[0], c.steps[1]) } else { c.steps.join("; ") };
        let _ = writeln!(section, "| {steps} | {:.0} | {:.2} | {} |", c.duration, c.criterion, c.relative_std_errors.iter().map(|v| pct(*v)).collect::<Vec<_>>().join(" | "));
    }
    let json = dir.join("experiment_design.json");
    crate::error::write_file(&json, serde_json::to_string_pretty(&d).expect("serialisable"))?;
    Ok(super::ReportSection { files: vec![json], section, warnings: Vec::new() })
}
