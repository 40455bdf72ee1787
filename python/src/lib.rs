//! `cellstudio._native`: the Rust side of the Python package. Each function here calls the
//! same library entry point as the command line (`src/main.rs` of the root crate) and hands
//! its result back as NumPy arrays or JSON text; the pure-Python layer in `cellstudio/` turns
//! the JSON into dicts and DataFrames. Long runs release the GIL (`Python::detach`).

use pyo3::create_exception;
use pyo3::exceptions::PyException;
use pyo3::prelude::*;

mod diagnosis;
mod parameters;
mod simulation;
mod studies;

create_exception!(cellstudio, CellstudioError, PyException, "An error of cellstudio, with the message the command line prints.");

/// A library error as `CellstudioError`, with the text the command line prints after `error: `.
pub(crate) fn to_py(e: cellstudio::Error) -> PyErr {
    CellstudioError::new_err(e.to_string())
}

/// A result's JSON text (the crate's result types are serde types).
pub(crate) fn json(value: &serde_json::Value) -> String {
    value.to_string()
}

/// Label, position and length of the library's current progress bar while a run goes on
/// (`None` otherwise): polled by the Python layer to draw it with tqdm.
#[pyfunction]
fn progress() -> Option<(String, u64, u64)> {
    cellstudio::progress::snapshot()
}

#[pymodule]
fn _native(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add("CellstudioError", m.py().get_type::<CellstudioError>())?;
    m.add_class::<parameters::PyParameterSet>()?;
    m.add_function(wrap_pyfunction!(simulation::simulate, m)?)?;
    m.add_function(wrap_pyfunction!(studies::load_design, m)?)?;
    m.add_function(wrap_pyfunction!(studies::design, m)?)?;
    m.add_function(wrap_pyfunction!(studies::sweep, m)?)?;
    m.add_function(wrap_pyfunction!(studies::pareto, m)?)?;
    m.add_function(wrap_pyfunction!(studies::fit, m)?)?;
    m.add_function(wrap_pyfunction!(studies::sample, m)?)?;
    m.add_function(wrap_pyfunction!(studies::parameterise, m)?)?;
    m.add_function(wrap_pyfunction!(studies::cycle, m)?)?;
    m.add_function(wrap_pyfunction!(diagnosis::diagnose, m)?)?;
    m.add_function(wrap_pyfunction!(progress, m)?)?;
    Ok(())
}
