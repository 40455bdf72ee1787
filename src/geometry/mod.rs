//! Meshes and discretised operators built from the cell geometry (the model builder that
//! rebuilds only when the geometry changes is `models::builder`).

pub mod mesh;

pub use mesh::{Mesh1D, SphereMesh};

use serde::{Deserialize, Serialize};

use crate::error::Error;
use crate::params::ParameterSet;

/// Number of finite volumes in each domain.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct MeshSizes {
    /// Negative electrode, through-thickness.
    pub x_n: usize,
    /// Separator.
    pub x_s: usize,
    /// Positive electrode.
    pub x_p: usize,
    /// Negative particle, radial.
    pub r_n: usize,
    /// Positive particle, radial.
    pub r_p: usize,
    /// Negative particle sizes (radius classes) of the particle-size distribution submodel
    /// (PyBaMM's `R_n` points); unused without it.
    pub size_n: usize,
    /// Positive particle sizes, as `size_n` (PyBaMM's `R_p`).
    pub size_p: usize,
}

impl Default for MeshSizes {
    /// PyBaMM's default mesh: 20 volumes per domain and per particle, 30 particle sizes.
    fn default() -> Self {
        Self { x_n: 20, x_s: 20, x_p: 20, r_n: 20, r_p: 20, size_n: 30, size_p: 30 }
    }
}

impl MeshSizes {
    pub fn validate(&self) -> Result<(), Error> {
        for (name, n) in [
            ("mesh.x_n", self.x_n),
            ("mesh.x_s", self.x_s),
            ("mesh.x_p", self.x_p),
            ("mesh.r_n", self.r_n),
            ("mesh.r_p", self.r_p),
        ] {
            if n < 2 {
                return Err(Error::invalid(name, n as f64, "needs at least 2 volumes"));
            }
        }
        for (name, n) in [("mesh.size_n", self.size_n), ("mesh.size_p", self.size_p)] {
            if n < 1 {
                return Err(Error::invalid(name, n as f64, "needs at least 1 particle size"));
            }
        }
        Ok(())
    }
}

/// The geometric parameters a discretisation depends on (m, m^2), plus the mesh sizes;
/// ordered field by field (sweeps group candidates by geometry).
#[derive(Clone, Copy, Debug, PartialEq, PartialOrd)]
pub struct Geometry {
    pub negative_thickness: f64,
    pub separator_thickness: f64,
    pub positive_thickness: f64,
    pub negative_radius: f64,
    pub positive_radius: f64,
    pub area: f64,
    pub sizes: MeshSizes,
}

impl Geometry {
    pub fn of(p: &ParameterSet, sizes: MeshSizes) -> Self {
        Self {
            negative_thickness: p.negative.thickness,
            separator_thickness: p.separator.thickness,
            positive_thickness: p.positive.thickness,
            negative_radius: p.negative.particle_radius,
            positive_radius: p.positive.particle_radius,
            area: p.cell.area(),
            sizes,
        }
    }
}

/// Meshes of every domain for one geometry.
#[derive(Clone, Debug)]
pub struct Discretisation {
    pub geometry: Geometry,
    /// Negative electrode, x from 0 to L_n.
    pub x_n: Mesh1D,
    /// Separator.
    pub x_s: Mesh1D,
    /// Positive electrode.
    pub x_p: Mesh1D,
    pub sphere_n: SphereMesh,
    pub sphere_p: SphereMesh,
}

impl Discretisation {
    pub fn new(g: Geometry) -> Self {
        let s = g.sizes;
        let (ln, ls, lp) = (g.negative_thickness, g.separator_thickness, g.positive_thickness);
        Self {
            geometry: g,
            x_n: Mesh1D::uniform(0.0, ln, s.x_n),
            x_s: Mesh1D::uniform(ln, ls, s.x_s),
            x_p: Mesh1D::uniform(ln + ls, lp, s.x_p),
            sphere_n: SphereMesh::new(g.negative_radius, s.r_n),
            sphere_p: SphereMesh::new(g.positive_radius, s.r_p),
        }
    }

    /// Number of x volumes across the whole cell.
    pub fn n_x(&self) -> usize {
        self.x_n.len() + self.x_s.len() + self.x_p.len()
    }

    /// Width of each x volume across the cell (m).
    pub fn x_widths(&self) -> Vec<f64> {
        let mut w = vec![self.x_n.dx; self.x_n.len()];
        w.extend(std::iter::repeat_n(self.x_s.dx, self.x_s.len()));
        w.extend(std::iter::repeat_n(self.x_p.dx, self.x_p.len()));
        w
    }

    /// Centres of every x volume across the cell (m).
    pub fn x_centres(&self) -> Vec<f64> {
        let mut c = self.x_n.centres.clone();
        c.extend_from_slice(&self.x_s.centres);
        c.extend_from_slice(&self.x_p.centres);
        c
    }
}
