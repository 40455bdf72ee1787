//! Cell mass (kg) and volume (m^3) from the geometry and material densities.
//!
//! Convention (as in PyBaMM/PyBOP): the electrode area is the unrolled plate area and each
//! layer (coatings, separator, both current collectors) is counted once over that area.
//! Tabs, can and free volume are the set's packaging allowances on top of the stack.

use super::set::{Electrode, ParameterSet};

/// Mass per unit plate area of a porous electrode coating, electrolyte included (kg/m^2).
fn coating_areal_mass(e: &Electrode, electrolyte_density: f64) -> f64 {
    e.thickness
        * (e.active_fraction * e.active_density
            + e.inactive_fraction().max(0.0) * e.inactive_density
            + e.porosity * electrolyte_density)
}

/// Mass and volume budget of a cell.
#[derive(Clone, Copy, Debug, serde::Serialize)]
pub struct CellBudget {
    /// Negative coating mass (kg).
    pub negative_coating: f64,
    /// Positive coating mass (kg).
    pub positive_coating: f64,
    /// Separator with its electrolyte (kg).
    pub separator: f64,
    /// Both current collectors (kg).
    pub collectors: f64,
    /// Tabs, can and packaging (kg).
    pub packaging: f64,
    /// Total cell mass (kg).
    pub mass: f64,
    /// Total cell volume (m^3).
    pub volume: f64,
}

impl ParameterSet {
    /// Mass and volume of the cell.
    pub fn budget(&self) -> CellBudget {
        let a = self.cell.area();
        let rho_e = self.electrolyte.density;
        let s = &self.separator;
        let c = &self.cell;
        let negative_coating = a * coating_areal_mass(&self.negative, rho_e);
        let positive_coating = a * coating_areal_mass(&self.positive, rho_e);
        let separator = a * s.thickness * ((1.0 - s.porosity) * s.solid_density + s.porosity * rho_e);
        let collectors = a
            * (c.negative_collector_thickness * c.negative_collector_density
                + c.positive_collector_thickness * c.positive_collector_density);
        let stack = negative_coating + positive_coating + separator + collectors;
        let packaging = stack * c.packaging_mass_fraction;
        let stack_volume = a
            * (self.negative.thickness
                + s.thickness
                + self.positive.thickness
                + c.negative_collector_thickness
                + c.positive_collector_thickness);
        CellBudget {
            negative_coating,
            positive_coating,
            separator,
            collectors,
            packaging,
            mass: stack + packaging,
            volume: stack_volume * (1.0 + c.packaging_volume_fraction),
        }
    }
}
