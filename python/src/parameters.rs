//! `ParameterSet`: the crate's typed parameter set (SI units) behind dotted paths such as
//! `positive.thickness` (m), with the constructors the command line offers (Chen 2020, a file,
//! a BPX document) and JSON for pickling and `to_dict`.

use std::path::PathBuf;

use cellstudio::params::bpx::{from_bpx_json, to_bpx_json};
use cellstudio::params::{Override, ParameterSet, apply_overrides, chen2020};
use pyo3::prelude::*;

use crate::to_py;

/// A parameter set in SI units (m, mol/m^3, S/m, K, A h, V, ohm, ...).
#[pyclass(name = "ParameterSet", module = "cellstudio")]
#[derive(Clone)]
pub struct PyParameterSet {
    pub(crate) inner: ParameterSet,
}

#[pymethods]
impl PyParameterSet {
    /// The LG M50 set of Chen et al. (2020), as PyBaMM's "Chen2020".
    #[staticmethod]
    fn chen2020() -> Self {
        Self { inner: chen2020() }
    }

    /// Reads a parameter file as `--params` does: TOML, this crate's JSON or a BPX document.
    #[staticmethod]
    fn from_file(path: PathBuf) -> PyResult<Self> {
        ParameterSet::from_file(&path).map(|inner| Self { inner }).map_err(to_py)
    }

    /// Imports BPX JSON text; returns the set and the BPX keys that map to nothing here.
    #[staticmethod]
    fn from_bpx_json(text: &str) -> PyResult<(Self, Vec<String>)> {
        let import = from_bpx_json(text).map_err(to_py)?;
        Ok((Self { inner: import.params }, import.unknown_fields))
    }

    /// This set as a BPX v0.5 document (JSON text).
    fn to_bpx_json(&self) -> PyResult<String> {
        to_bpx_json(&self.inner).map_err(to_py)
    }

    /// A set from this crate's JSON layout (what [`to_json`](Self::to_json) writes), validated.
    #[staticmethod]
    fn from_json(text: &str) -> PyResult<Self> {
        let inner: ParameterSet = serde_json::from_str(text)
            .map_err(|e| to_py(cellstudio::Error::Parse { path: "parameter set JSON".into(), message: e.to_string() }))?;
        inner.validate().map_err(to_py)?;
        Ok(Self { inner })
    }

    /// The whole set (functions included) as JSON text.
    fn to_json(&self) -> String {
        serde_json::to_string(&self.inner).expect("a parameter set serialises")
    }

    /// Sets one scalar by dotted path (SI units) and validates the set, as `--set PATH=VALUE`
    /// does; on an error the set is left as it was.
    fn set(&mut self, path: &str, value: f64) -> PyResult<()> {
        let mut p = self.inner.clone();
        apply_overrides(&mut p, &[Override { path: path.into(), value }]).map_err(to_py)?;
        self.inner = p;
        Ok(())
    }

    /// One scalar by dotted path (SI units).
    fn get(&self, path: &str) -> PyResult<f64> {
        self.inner.get(path).map_err(to_py)
    }

    /// The set's name.
    #[getter]
    fn name(&self) -> String {
        self.inner.name.clone()
    }

    #[setter]
    fn set_name(&mut self, name: String) {
        self.inner.name = name;
    }

    fn __eq__(&self, other: &Self) -> bool {
        self.inner == other.inner
    }

    fn __repr__(&self) -> String {
        format!("ParameterSet({:?})", self.inner.name)
    }

    /// Pickles as its JSON text.
    fn __reduce__(slf: &Bound<'_, Self>) -> PyResult<(Py<PyAny>, (String,))> {
        let from_json = slf.get_type().getattr("from_json")?.unbind();
        Ok((from_json, (slf.borrow().to_json(),)))
    }
}
