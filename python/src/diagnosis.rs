//! `diagnose`: model-discrepancy diagnosis of a recording file, as `cellstudio diagnose` runs
//! it (the same checks, rounds, report text and files), returned as JSON text.

use std::path::PathBuf;

use cellstudio::Error;
use cellstudio::diagnose::{DiagnoseOptions, default_fit_parameter, diagnose_rounds, report};
use cellstudio::models::{ModelKind, Submodels};
use cellstudio::output::OutputDir;
use cellstudio::problem::fitting::ModelSpec;
use pyo3::prelude::*;
use serde_json::json;

use crate::parameters::PyParameterSet;
use crate::{json, to_py};

/// Diagnoses the recording at `data` (this crate's CSV columns `time_s`, `current_A`
/// discharge positive, `voltage_V`, optional `temperature_K`, or a raw cycler export) with
/// `model` on `parameters`; writes `diagnosis.md`, `diagnosis.json` and plots into `out`.
/// `fit` names parameters (dotted paths) fitted in every model; `refits` caps the candidates
/// refitted; `max_rounds` the rounds. Errors carry the command line's text, with the
/// argument names of this function where the command line names its flags.
#[pyfunction]
#[pyo3(signature = (data, parameters, model="spme", out=PathBuf::from("out/diagnosis"), contact_resistance=false, thermal=false, fit=Vec::new(), refits=None, start_at_rest=false, max_rounds=3))]
#[allow(clippy::too_many_arguments)]
pub fn diagnose(
    py: Python<'_>,
    data: PathBuf,
    parameters: PyRef<'_, PyParameterSet>,
    model: &str,
    out: PathBuf,
    contact_resistance: bool,
    thermal: bool,
    fit: Vec<String>,
    refits: Option<usize>,
    start_at_rest: bool,
    max_rounds: usize,
) -> PyResult<String> {
    let kind: ModelKind = model.parse().map_err(to_py)?;
    let p = parameters.inner.clone();
    py.detach(|| {
        if refits == Some(0) {
            return Err(Error::invalid("refits", 0.0, "must be at least 1: with no candidate refitted nothing can be named or ruled out"));
        }
        if max_rounds == 0 {
            return Err(Error::invalid("max_rounds", 0.0, "must be at least 1"));
        }
        let staged = OutputDir::create(&out, &[data.as_path()])?;
        let rec = cellstudio::data::cycler::read_recording(&data, &Default::default())?;
        let submodels = Submodels { contact_resistance, thermal, ..Default::default() };
        let mut options = DiagnoseOptions::new(ModelSpec::new(kind, submodels));
        options.fitted = fit.iter().map(|path| default_fit_parameter(path, &p)).collect::<Result<_, _>>()?;
        if let Some(n) = refits {
            options.max_refits = n;
        }
        options.fit.start_at_rest = start_at_rest;
        let rounds = diagnose_rounds(&rec, &p, &options, max_rounds)?;
        let markdown: Vec<String> = rounds.iter().map(|d| report::markdown(d, &[])).collect();
        let conclusion = report::conclusion(&rounds);
        let written = cellstudio::report::diagnosis_files::write(&rounds, staged.path())?;
        let files = staged.commit(&written)?;
        Ok(json(&json!({
            "rounds": rounds,
            "markdown": markdown,
            "conclusion": conclusion,
            "files": files.iter().map(|f| f.display().to_string()).collect::<Vec<_>>(),
        })))
    })
    .map_err(to_py)
}
