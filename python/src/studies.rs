//! Studies from their TOML files, run as `cellstudio design`, `sweep`, `pareto`, `fit`,
//! `sample`, `parameterise` and `cycle` run them (same library calls, same files written),
//! their outcomes returned as JSON text for the Python layer.

use std::path::{Path, PathBuf};

use cellstudio::Error;
use cellstudio::params::Override;
use cellstudio::problem::design::Metric;
use cellstudio::study::Study;
use cellstudio::study::fit::{FitStudy, parameter_table};
use serde_json::{Value, json};
use pyo3::prelude::*;

use crate::{json, to_py};


/// `--set PATH=VALUE` overrides from Python's `{path: value}` pairs.
fn overrides(set: Vec<(String, f64)>) -> Vec<Override> {
    set.into_iter().map(|(path, value)| Override { path, value }).collect()
}

/// The design study at `path` with `set` overrides and, when given, its output folder moved.
fn design_study(path: &Path, set: Vec<(String, f64)>, out: Option<PathBuf>) -> Result<Study, Error> {
    let mut study = Study::from_file(path)?.with_overrides(overrides(set))?;
    if let Some(dir) = out {
        study.output.dir = dir;
    }
    Ok(study)
}

/// The fitting study at `path`, likewise.
fn fit_study(path: &Path, set: Vec<(String, f64)>, out: Option<PathBuf>) -> Result<FitStudy, Error> {
    let mut study = FitStudy::from_file(path)?.with_overrides(overrides(set))?;
    if let Some(dir) = out {
        study.output.dir = dir;
    }
    Ok(study)
}

/// The decision variables' dotted paths.
fn variables(study: &Study) -> Vec<String> {
    study.variables.iter().map(|v| v.path.clone()).collect()
}

/// Runs `body` without the GIL: its JSON as text, its error as `CellstudioError`.
fn detached(py: Python<'_>, body: impl FnOnce() -> Result<Value, Error> + Send) -> PyResult<String> {
    py.detach(body).map(|v| json(&v)).map_err(to_py)
}

/// A run's own `fields` with what every run reports: the study's name, the warnings (also in
/// its report) and the files it wrote.
fn outcome(name: &str, warnings: &[String], files: &[PathBuf], mut fields: Value) -> Value {
    fields["study"] = json!(name);
    fields["warnings"] = json!(warnings);
    fields["files"] = json!(files.iter().map(|f| f.display().to_string()).collect::<Vec<_>>());
    fields
}

/// Runs the study's optimiser (`cellstudio design`).
#[pyfunction]
#[pyo3(signature = (path, set=Vec::new(), out=None))]
pub fn design(py: Python<'_>, path: PathBuf, set: Vec<(String, f64)>, out: Option<PathBuf>) -> PyResult<String> {
    detached(py, || {
        let study = design_study(&path, set, out)?;
        let o = cellstudio::study::design::run_design(&study)?;
        Ok(outcome(&study.name, &o.warnings, &o.files, json!({
            "variables": variables(&study),
            "metric": o.metric,
            "metric_label": o.metric.label(),
            "initial_x": o.initial_x,
            "initial": o.initial,
            "initial_value": o.initial.get(o.metric),
            "x": o.result.x,
            "optimised": o.optimised,
            "optimised_value": o.optimised.get(o.metric),
            "improvement_percent": o.improvement(),
            "search": o.result,
            "rebuilds": o.rebuilds,
            "seconds": o.seconds,
            "active_limits": o.active_limits,
            "start_values": o.start_values,
            "sweep_best": o.sweep_best,
        })))
    })
}

/// Evaluates the study's grid or Latin hypercube (`cellstudio sweep`).
#[pyfunction]
#[pyo3(signature = (path, set=Vec::new(), out=None))]
pub fn sweep(py: Python<'_>, path: PathBuf, set: Vec<(String, f64)>, out: Option<PathBuf>) -> PyResult<String> {
    detached(py, || {
        let study = design_study(&path, set, out)?;
        let o = cellstudio::study::sweep::run_sweep(&study)?;
        let best: Value = [Metric::GravimetricEnergyDensity, Metric::VolumetricEnergyDensity]
            .into_iter()
            .filter_map(|m| o.best(m).map(|(p, metrics)| (serde_json::to_value(m).unwrap_or_default().as_str().unwrap_or_default().to_string(), json!({"x": p.x, "metrics": metrics}))))
            .collect::<serde_json::Map<_, _>>()
            .into();
        Ok(outcome(&study.name, &o.warnings, &o.files, json!({
            "variables": variables(&study),
            "points": o.points,
            "baseline": o.baseline,
            "best": best,
            "rebuilds": o.rebuilds,
            "seconds": o.seconds,
        })))
    })
}

/// Runs NSGA-II on the study's objectives (`cellstudio pareto`).
#[pyfunction]
#[pyo3(signature = (path, set=Vec::new(), out=None))]
pub fn pareto(py: Python<'_>, path: PathBuf, set: Vec<(String, f64)>, out: Option<PathBuf>) -> PyResult<String> {
    detached(py, || {
        let study = design_study(&path, set, out)?;
        let o = cellstudio::study::pareto::run_pareto(&study)?;
        Ok(outcome(&study.name, &o.warnings, &o.files, json!({
            "variables": variables(&study),
            "objectives": study.objective.maximise,
            "front": o.front,
            "baseline": o.baseline,
            "evaluated": o.evaluated,
            "failed": o.failed,
            "stopped_early": o.stopped_early,
            "repaired": o.repaired,
            "rebuilds": o.rebuilds,
            "seconds": o.seconds,
        })))
    })
}

/// Fits the study's parameters to its recording or to `data` (`cellstudio fit`). A fit that
/// ends with a parameter on a bound raises, as the command line exits non-zero, after writing
/// its outputs to `NAME.rejected`.
#[pyfunction]
#[pyo3(signature = (path, data=None, set=Vec::new(), out=None))]
pub fn fit(py: Python<'_>, path: PathBuf, data: Option<PathBuf>, set: Vec<(String, f64)>, out: Option<PathBuf>) -> PyResult<String> {
    detached(py, || {
        let study = fit_study(&path, set, out)?;
        let o = cellstudio::study::fit_run::run_fit(&study, data.as_deref())?;
        if let Some(rejection) = o.rejection {
            return Err(rejection);
        }
        Ok(outcome(&study.name, &o.warnings, &o.files, json!({
            "result": o.result,
            "initial_rmse": o.initial_rmse,
            "experiments": o.experiments,
            "table": parameter_table(&o.result),
            "notes": o.notes,
        })))
    })
}

/// Samples the study's posterior (`cellstudio sample`); `sampler` entries (e.g. `chains`,
/// `iterations`, `warmup`, `seed`) replace those of the study's `[sampler]` table.
#[pyfunction]
#[pyo3(signature = (path, data=None, set=Vec::new(), out=None, sampler=Vec::new()))]
pub fn sample(py: Python<'_>, path: PathBuf, data: Option<PathBuf>, set: Vec<(String, f64)>, out: Option<PathBuf>, sampler: Vec<(String, i64)>) -> PyResult<String> {
    detached(py, || {
        let mut study = fit_study(&path, set, out)?;
        for (key, value) in sampler {
            study.sampler.insert(key, toml::Value::Integer(value));
        }
        let o = cellstudio::study::sample::run_sample(&study, data.as_deref())?;
        Ok(outcome(&study.name, &o.warnings, &o.files, json!({
            "names": o.names,
            "summary": o.summary,
            "table": o.summary.table(),
            "seconds": o.seconds,
            "notes": o.notes,
        })))
    })
}

/// Reads and checks the design study at `path` with `set` overrides (as every run does
/// first); returns it as JSON text.
#[pyfunction]
#[pyo3(signature = (path, set=Vec::new()))]
pub fn load_design(path: PathBuf, set: Vec<(String, f64)>) -> PyResult<String> {
    let study = design_study(&path, set, None).map_err(to_py)?;
    serde_json::to_string(&study).map_err(|e| to_py(Error::Parse { path: path.display().to_string(), message: e.to_string() }))
}

/// Runs the parameterisation study's stages (`cellstudio parameterise`): pseudo-OCV,
/// balancing, pulses, kinetics, GITT, each feeding the next.
#[pyfunction]
#[pyo3(signature = (path, set=Vec::new(), out=None))]
pub fn parameterise(py: Python<'_>, path: PathBuf, set: Vec<(String, f64)>, out: Option<PathBuf>) -> PyResult<String> {
    use cellstudio::study::parameterise::{ParameterisationStudy, run_parameterisation};
    detached(py, || {
        let mut study = ParameterisationStudy::from_file(&path)?.with_overrides(overrides(set))?;
        if let Some(dir) = out {
            study.output.dir = dir;
        }
        let o = run_parameterisation(&study)?;
        Ok(outcome(&study.name, &o.warnings, &o.files, json!({
            "stages": o.stages,
            "summary": o.summary,
            "notes": o.notes,
            "parameters": o.parameters,
        })))
    })
}

/// Cycles the cell as the study says (`cellstudio cycle`), with its fade fit when the study
/// has a `[fit]` table.
#[pyfunction]
#[pyo3(signature = (path, set=Vec::new(), out=None))]
pub fn cycle(py: Python<'_>, path: PathBuf, set: Vec<(String, f64)>, out: Option<PathBuf>) -> PyResult<String> {
    use cellstudio::study::cycle::CycleStudy;
    detached(py, || {
        let mut study = CycleStudy::from_file(&path)?.with_overrides(overrides(set))?;
        if let Some(dir) = out {
            study.output.dir = dir;
        }
        let o = study.run(&mut |_| {})?;
        let warnings = o.fade.as_ref().map(|f| f.warnings()).unwrap_or_default();
        Ok(outcome(&study.name, &warnings, &o.files, json!({
            "cycles": o.summaries,
            "seconds": o.seconds,
            "fade_fit": o.fade,
        })))
    })
}
