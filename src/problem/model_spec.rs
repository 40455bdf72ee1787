//! Which model a fitting problem builds: its kind, submodels, mesh, and whether its temperature
//! follows the recording's.

use serde::{Deserialize, Serialize};

use crate::geometry::MeshSizes;
use crate::models::{ModelBuilder, ModelKind, Submodels};

/// Which model to build.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ModelSpec {
    pub kind: ModelKind,
    #[serde(default)]
    pub submodels: Submodels,
    #[serde(default)]
    pub mesh: MeshSizes,
    /// The thermal submodel's temperature follows the recording's instead of its heat
    /// balance (`dT/dt = (T_rec(t) - T) / simulation::TEMPERATURE_LAG`): needs
    /// `submodels.thermal` and a recorded temperature ([`super::fitting::FittingProblem::new`] refuses it
    /// without them).
    #[serde(default)]
    pub recorded_temperature: bool,
}

impl ModelSpec {
    pub fn new(kind: ModelKind, submodels: Submodels) -> Self {
        Self { kind, submodels, mesh: MeshSizes::default(), recorded_temperature: false }
    }

    pub(super) fn builder(&self) -> ModelBuilder {
        ModelBuilder::new(self.kind, self.submodels, self.mesh)
    }
}

/// The model in words, e.g. "DFN + thermal (temperature as recorded)".
impl std::fmt::Display for ModelSpec {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let s = self.submodels;
        write!(f, "{}", self.kind)?;
        for (on, name) in [(s.contact_resistance, "contact resistance"), (s.thermal, "thermal"), (s.rc, "RC"), (s.hysteresis, "hysteresis"), (s.ocv_correction, "OCV correction")] {
            if on {
                write!(f, " + {name}")?;
            }
        }
        if self.recorded_temperature {
            f.write_str(" (temperature as recorded)")?;
        }
        Ok(())
    }
}
