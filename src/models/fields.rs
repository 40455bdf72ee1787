//! Named spatial fields of a model state (concentrations and potentials against position),
//! for reports and plots.

use serde::Serialize;

use super::electrochem::{Electrochem, Side};

/// One field of a state: values at positions along an axis.
#[derive(Clone, Debug, Serialize)]
pub struct Field {
    /// What it is, e.g. "electrolyte concentration".
    pub name: &'static str,
    /// Unit of the values, e.g. "mol/m^3".
    pub unit: &'static str,
    /// What the positions measure: "x" (through the cell from the negative current collector),
    /// "r" (from a particle's centre) or "R" (the particle radius, across a size distribution).
    pub axis: &'static str,
    /// Positions (m): volume centres.
    pub position: Vec<f64>,
    pub value: Vec<f64>,
}

impl Field {
    fn new(name: &'static str, unit: &'static str, axis: &'static str, position: Vec<f64>, value: Vec<f64>) -> Self {
        debug_assert_eq!(position.len(), value.len());
        Self { name, unit, axis, position, value }
    }

    /// A concentration (mol/m^3) against x.
    pub fn concentration_x(name: &'static str, position: Vec<f64>, value: Vec<f64>) -> Self {
        Self::new(name, "mol/m^3", "x", position, value)
    }

    /// A concentration (mol/m^3) against the particle radius R of a size distribution.
    pub fn concentration_radius(name: &'static str, radius: Vec<f64>, value: Vec<f64>) -> Self {
        Self::new(name, "mol/m^3", "R", radius, value)
    }

    /// A potential (V) against x.
    pub fn potential_x(name: &'static str, position: Vec<f64>, value: Vec<f64>) -> Self {
        Self::new(name, "V", "x", position, value)
    }
}

impl Electrochem {
    /// Centres (m) of the x volumes of the negative electrode, separator and positive electrode.
    pub fn x_centres(&self) -> Vec<f64> {
        let d = &self.disc;
        [&d.x_n, &d.x_s, &d.x_p].iter().flat_map(|m| m.centres.iter().copied()).collect()
    }

    /// Centres (m) of the x volumes of one electrode.
    pub fn electrode_x_centres(&self, side: Side) -> Vec<f64> {
        match side {
            Side::Negative => self.disc.x_n.centres.clone(),
            Side::Positive => self.disc.x_p.centres.clone(),
        }
    }

    /// The concentration profiles of the two representative particles of a single particle
    /// model, with shell concentrations `cn` and `cp`.
    pub fn single_particle_fields(&self, cn: &[f64], cp: &[f64]) -> Vec<Field> {
        let particle = |name, side, c: &[f64]| Field::new(name, "mol/m^3", "r", self.sphere(side).centres.clone(), c.to_vec());
        vec![
            particle("negative particle concentration", Side::Negative, cn),
            particle("positive particle concentration", Side::Positive, cp),
        ]
    }
}
