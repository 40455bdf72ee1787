//! The geometry-aware model builder: keeps the last build (mesh, operators, Jacobian
//! colouring, symbolic LU) and rebuilds only when a geometric parameter changes.

use crate::geometry::{Discretisation, Geometry, MeshSizes};
use crate::error::Error;
use super::dfn::Dfn;
use super::mpm::Mpm;
use super::spm::Spm;
use super::spme::Spme;
use super::submodels::{Augmented, ParticleSize};
use super::{Electrochem, ModelKind, PhysicsModel, Submodels};
use crate::params::ParameterSet;
use crate::solver::Workspace;

/// A built model and its solver work space.
pub struct Built {
    pub model: Box<dyn PhysicsModel>,
    pub workspace: Workspace,
    pub geometry: Geometry,
}

/// Builds physics models from parameter sets, re-using the last build while the geometry
/// (thicknesses, particle radii, plate area, mesh sizes) is unchanged.
pub struct ModelBuilder {
    pub kind: ModelKind,
    pub submodels: Submodels,
    pub mesh: MeshSizes,
    last: Option<Built>,
    builds: usize,
}

impl ModelBuilder {
    pub fn new(kind: ModelKind, submodels: Submodels, mesh: MeshSizes) -> Self {
        Self { kind, submodels, mesh, last: None, builds: 0 }
    }

    /// Number of (re)builds so far.
    pub fn rebuild_count(&self) -> usize {
        self.builds
    }

    /// Returns the model for `params`: the last build with its parameters replaced when the
    /// geometry is unchanged, otherwise a new build. Parameters are validated first.
    pub fn build(&mut self, params: &ParameterSet) -> Result<&mut Built, Error> {
        params.validate()?;
        self.mesh.validate()?;
        let geometry = Geometry::of(params, self.mesh);
        let reuse = self.last.as_ref().is_some_and(|b| b.geometry == geometry);
        if reuse {
            let built = self.last.as_mut().expect("checked above");
            built.model.set_params(params.clone());
        } else {
            self.submodels.check_for(self.kind)?;
            let distribution = self.submodels.particle_size == ParticleSize::Distribution;
            let ec = Electrochem::new(params.clone(), Discretisation::new(geometry), self.submodels);
            let mut model: Box<dyn PhysicsModel> = match self.kind {
                ModelKind::Spm if distribution => Box::new(Mpm::new(ec)),
                ModelKind::Spm => Box::new(Spm::new(ec)),
                ModelKind::Spme => Box::new(Spme::new(ec)),
                ModelKind::Dfn => Box::new(Dfn::new(ec)),
            };
            if self.submodels.augments() {
                model = Box::new(Augmented::new(model, self.submodels));
            }
            let workspace = Workspace::new(model.len(), model.jacobian_pattern())?;
            self.builds += 1;
            self.last = Some(Built { model, workspace, geometry });
        }
        Ok(self.last.as_mut().expect("just built"))
    }
}
