//! `simulate`: a model through a PyBaMM-style experiment (or a constant-current discharge to
//! the lower cut-off), as `cellstudio simulate` runs it, returned as NumPy arrays.

use std::time::Instant;

use cellstudio::geometry::MeshSizes;
use cellstudio::models::{ModelBuilder, ModelKind, Submodels};
use cellstudio::simulation::{SimOptions, Solution};
use cellstudio::study::simulate::ProtocolSource;
use cellstudio::Error;
use numpy::IntoPyArray;
use pyo3::prelude::*;
use pyo3::types::PyDict;

use crate::parameters::PyParameterSet;
use crate::to_py;

/// Simulates `model` ("spm", "spme" or "dfn") with `parameters` through `experiment` (PyBaMM
/// step strings, e.g. "Discharge at 1C until 2.5 V"), or, without one, a `c_rate` discharge
/// to the lower cut-off. `contact_resistance` switches the submodel on (it is also on when the
/// set's `cell.contact_resistance` is above 0); `thermal` the lumped thermal model; `mesh` is
/// the number of volumes per domain and particle. Returns a dict of arrays in SI units (time
/// s, current A with discharge positive, voltage V, capacity A h, energy W h, temperature K)
/// and the run's summary.
#[pyfunction]
#[pyo3(signature = (model, parameters, experiment=None, c_rate=1.0, contact_resistance=false, thermal=false, mesh=20))]
#[allow(clippy::too_many_arguments)]
pub fn simulate<'py>(
    py: Python<'py>,
    model: &str,
    parameters: PyRef<'py, PyParameterSet>,
    experiment: Option<Vec<String>>,
    c_rate: f64,
    contact_resistance: bool,
    thermal: bool,
    mesh: usize,
) -> PyResult<Bound<'py, PyDict>> {
    let kind: ModelKind = model.parse().map_err(to_py)?;
    let p = parameters.inner.clone();
    let experiment = experiment.unwrap_or_default();
    let (sol, build_time, solve_time) = py.detach(|| run(kind, &p, &experiment, c_rate, contact_resistance, thermal, mesh)).map_err(to_py)?;
    let out = PyDict::new(py);
    out.set_item("model", kind.to_string())?;
    out.set_item("parameters", p.name.clone())?;
    out.set_item("capacity_Ah", sol.final_capacity())?;
    out.set_item("energy_Wh", sol.final_energy())?;
    out.set_item("final_voltage_V", sol.final_voltage())?;
    out.set_item("build_time_s", build_time)?;
    out.set_item("solve_time_s", solve_time)?;
    out.set_item("steps", sol.stats.steps)?;
    out.set_item("cutoff_times", sol.cutoff_times.clone())?;
    out.set_item("time", sol.time.into_pyarray(py))?;
    out.set_item("current", sol.current.into_pyarray(py))?;
    out.set_item("voltage", sol.voltage.into_pyarray(py))?;
    out.set_item("capacity", sol.capacity.into_pyarray(py))?;
    out.set_item("energy", sol.energy.into_pyarray(py))?;
    out.set_item("temperature", sol.temperature.into_pyarray(py))?;
    Ok(out)
}

/// The run, without the GIL: the protocol, the model built once, one solve; the build and
/// solve wall times (s). Errors name the argument as the command line names its flag.
fn run(kind: ModelKind, p: &cellstudio::params::ParameterSet, experiment: &[String], c_rate: f64, contact_resistance: bool, thermal: bool, mesh: usize) -> Result<(Solution, f64, f64), Error> {
    if !(c_rate > 0.0 && c_rate.is_finite()) {
        return Err(Error::invalid("c_rate", c_rate, "must be positive"));
    }
    if mesh < 2 {
        return Err(Error::invalid("mesh", mesh as f64, "must be at least 2 volumes"));
    }
    // The command line's protocol choice and error naming (`study::simulate`).
    let source = if experiment.is_empty() { ProtocolSource::Discharge { c_rate } } else { ProtocolSource::Experiment(experiment.to_vec()) };
    let protocol = source.protocol(p)?;
    let submodels = Submodels { contact_resistance: contact_resistance || p.cell.contact_resistance > 0.0, thermal, ..Default::default() };
    let sizes = MeshSizes { x_n: mesh, x_s: mesh, x_p: mesh, r_n: mesh, r_p: mesh, ..Default::default() };
    let t = Instant::now();
    let mut builder = ModelBuilder::new(kind, submodels, sizes);
    let built = builder.build(p)?;
    let build_time = t.elapsed().as_secs_f64();
    let t = Instant::now();
    let sol = cellstudio::simulation::simulate(built.model.as_ref(), &mut built.workspace, &protocol, &SimOptions::for_cell(p), None).map_err(|e| source.name_failure(e))?;
    Ok((sol, build_time, t.elapsed().as_secs_f64()))
}
