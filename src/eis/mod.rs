//! Electrochemical impedance: linearised frequency response of the discretised models.
//!
//! A built model is linearised about its rest state (algebraic states consistent at zero
//! current) by central differences, `M dy' = J dy + B dI`, `dV = C dy + D dI`, and its
//! impedance is `Z(w) = -(C (i w M - J)^{-1} B + D)` (ohm; current discharge-positive, so
//! `Re Z > 0`). [`sine_response`] measures the same quantity in the time domain for
//! validation, and [`EisFit`] fits parameters to a measured [`Spectrum`].
//!
//! ```
//! use cellstudio::eis::{log_frequencies, model_impedance};
//! use cellstudio::geometry::MeshSizes;
//! use cellstudio::models::{ModelBuilder, ModelKind, Submodels};
//!
//! let mut p = cellstudio::params::chen2020();
//! cellstudio::params::set_initial_soc(&mut p, 0.5).unwrap();
//! let mut builder = ModelBuilder::new(ModelKind::Spm, Submodels::default(), MeshSizes::default());
//! let built = builder.build(&p).unwrap();
//! let f = log_frequencies(1e-3, 1e3, 20).unwrap();
//! let z = model_impedance(built.model.as_ref(), &mut built.workspace, &f).unwrap();
//! assert!(z.z_re.iter().all(|&r| r > 0.0));
//! assert!(z.z_im.iter().all(|&i| i < 0.0));
//! ```

pub mod impedance;
pub mod linearise;
pub mod spectrum;
pub mod spectrum_fit;
pub mod time_domain;

pub use impedance::{ImpedanceSolver, impedance};
pub use linearise::{Linearisation, linearise, rest_state};
pub use spectrum::{Spectrum, log_frequencies};
pub use spectrum_fit::EisFit;
pub use time_domain::{SineOptions, SineResponse, sine_response};

use crate::error::Error;
use crate::models::Model;
use crate::solver::Workspace;

/// Impedance spectrum (ohm) of `model` about its rest state at `frequencies` (Hz).
pub fn model_impedance(model: &dyn Model, ws: &mut Workspace, frequencies: &[f64]) -> Result<Spectrum, Error> {
    let y0 = rest_state(model, ws)?;
    impedance(&linearise(model, &y0)?, frequencies)
}
