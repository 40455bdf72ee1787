//! Fitting model parameters to a measured impedance spectrum.
//!
//! The cost of a candidate is `sum_k |Z_model(f_k) - Z_data(f_k)|^2 / |Z_data(f_k)|^2`, so
//! every frequency weighs by its relative error. Models come from [`ModelBuilder`]s, so
//! geometric parameters (e.g. `negative.particle_radius`) can be identified; the builders
//! rebuild only when the geometry changes.

use super::spectrum::Spectrum;
use crate::error::Error;
use crate::geometry::MeshSizes;
use crate::models::{BuilderPool, ModelBuilder};
use crate::models::{ModelKind, Submodels};
use crate::optim::Objective;
use crate::params::{ParameterSet, set_initial_soc};

/// An impedance-fitting objective over named (dotted) parameters.
pub struct EisFit {
    /// Parameter set that candidates modify.
    pub base: ParameterSet,
    /// Dotted parameter paths, one per variable.
    pub variables: Vec<String>,
    /// The measured spectrum.
    pub data: Spectrum,
    pub kind: ModelKind,
    pub submodels: Submodels,
    pub mesh: MeshSizes,
    /// State of charge applied to each candidate after its parameters are set (so fitted
    /// capacities keep the cell at the measured SOC); `None` keeps the base concentrations.
    pub soc: Option<f64>,
    /// Builders re-used across evaluations (one per concurrent evaluation).
    pool: BuilderPool,
}

impl EisFit {
    /// Checks that every variable names a scalar parameter.
    pub fn new(base: ParameterSet, variables: Vec<String>, data: Spectrum, kind: ModelKind) -> Result<Self, Error> {
        for v in &variables {
            base.get(v)?;
        }
        data.validate()?;
        Ok(Self {
            base,
            variables,
            data,
            kind,
            submodels: Submodels::default(),
            mesh: MeshSizes::default(),
            soc: None,
            pool: BuilderPool::default(),
        })
    }

    /// Sets the submodels (e.g. contact resistance on).
    pub fn with_submodels(mut self, submodels: Submodels) -> Self {
        self.submodels = submodels;
        self
    }

    /// Sets the mesh sizes.
    pub fn with_mesh(mut self, mesh: MeshSizes) -> Result<Self, Error> {
        mesh.validate()?;
        self.mesh = mesh;
        Ok(self)
    }

    /// Puts every candidate at state of charge `soc` in [0, 1].
    pub fn with_soc(mut self, soc: f64) -> Result<Self, Error> {
        set_initial_soc(&mut self.base.clone(), soc)?;
        self.soc = Some(soc);
        Ok(self)
    }

    /// The parameter set of candidate `x`.
    pub fn parameters(&self, x: &[f64]) -> Result<ParameterSet, Error> {
        if x.len() != self.variables.len() {
            return Err(Error::InvalidSetting {
                field: "x".into(),
                reason: format!("{} values for {} variables", x.len(), self.variables.len()),
            });
        }
        let mut p = self.base.clone();
        for (path, &v) in self.variables.iter().zip(x) {
            p.set(path, v)?;
        }
        if let Some(soc) = self.soc {
            set_initial_soc(&mut p, soc)?;
        }
        p.validate()?;
        Ok(p)
    }

    /// Model spectrum of candidate `x` at the data's frequencies.
    pub fn model_spectrum(&self, x: &[f64]) -> Result<Spectrum, Error> {
        let p = self.parameters(x)?;
        self.pool.with(
            || ModelBuilder::new(self.kind, self.submodels, self.mesh),
            |builder| {
                builder.build(&p).and_then(|b| super::model_impedance(b.model.as_ref(), &mut b.workspace, &self.data.frequency))
            },
        )
    }

    /// Relative squared misfit of candidate `x`.
    pub fn cost(&self, x: &[f64]) -> Result<f64, Error> {
        Ok(relative_misfit(&self.model_spectrum(x)?, &self.data))
    }

    /// Model builds so far across all builders.
    pub fn rebuild_count(&self) -> usize {
        self.pool.rebuild_count()
    }
}

/// `sum_k |Z_model - Z_data|^2 / |Z_data|^2` over the common points (same frequencies).
pub fn relative_misfit(model: &Spectrum, data: &Spectrum) -> f64 {
    (0..data.len())
        .map(|k| {
            let (dr, di) = (model.z_re[k] - data.z_re[k], model.z_im[k] - data.z_im[k]);
            (dr * dr + di * di) / (data.z_re[k].powi(2) + data.z_im[k].powi(2))
        })
        .sum()
}

impl Objective for EisFit {
    fn dim(&self) -> usize {
        self.variables.len()
    }
    fn evaluate(&self, x: &[f64]) -> f64 {
        self.cost(x).unwrap_or(f64::INFINITY)
    }
}
