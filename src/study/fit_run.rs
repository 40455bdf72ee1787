//! Running a fit study: one recording or several (a joint fit), into a staged output folder
//! that is committed, or set aside when a parameter ended on a bound.

use std::path::Path;

use super::fit::{FitOutcome, FitStudy, on_bound_rejection, single_fit_into};
use super::joint_fit::joint_fit_into;
use crate::error::Error;

/// Fits the study's problem, then writes `report.md`, `fit.json`, `fit_voltage.svg`,
/// `fit_residual.svg` and (with `[landscape]`) `landscape.svg`. A fit with a parameter on a
/// bound is no estimate: its files go to `NAME.rejected` beside the output folder, whose
/// previous results stay, and [`FitOutcome::rejection`] says so.
pub fn run_fit(study: &FitStudy, data: Option<&Path>) -> Result<FitOutcome, Error> {
    let out = crate::output::OutputDir::create(&study.output.dir, &study.inputs(data))?;
    let mut outcome = fit_into(study, data, out.path())?;
    match on_bound_rejection(&outcome.at_bound, "", &out) {
        None => outcome.files = out.commit(&outcome.files)?,
        Some(rejection) => {
            outcome.rejection = Some(rejection);
            outcome.files = out.reject(&outcome.files)?;
        }
    }
    Ok(outcome)
}

/// [`run_fit`] writing into `dir` (a staged output folder).
pub(crate) fn fit_into(study: &FitStudy, data: Option<&Path>, dir: &Path) -> Result<FitOutcome, Error> {
    if study.is_joint() { joint_fit_into(study, data, dir) } else { single_fit_into(study, data, dir) }
}
