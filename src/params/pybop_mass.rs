//! PyBOP's mass convention, to compare absolute W h/kg one to one with PyBOP's design
//! examples (`examples/scripts/design_optimisation/*` in PyBOP 25.x): its `cell_mass` counts
//! `A (L_n rho_n + L_p rho_p + L_s rho_s + L_cu rho_cu + L_al rho_al)` over the plate area `A`,
//! with each electrode's mass density `eps_am rho_am + eps rho_e + (1 - eps_am - eps) rho_cb`,
//! and the examples set the active-material and carbon-binder densities to PyBaMM's
//! "electrode density" (the whole porous electrode's, a thermal parameter) and the electrolyte
//! density to the separator density. No packaging; the volume is `A` times the stack thickness.

use serde::{Deserialize, Serialize};

use super::mass::{MassBasis, Part, StackAreas, component};
use super::set::ParameterSet;
use crate::error::Error;

/// The densities PyBOP's design examples use (kg/m^3); defaults: PyBaMM's Chen 2020 values.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct PybopDensities {
    /// PyBaMM "Negative electrode density", used for active material and carbon-binder.
    pub negative_electrode: f64,
    /// PyBaMM "Positive electrode density", used for active material and carbon-binder.
    pub positive_electrode: f64,
    /// PyBaMM "Separator density", used for the separator and for the electrolyte.
    pub separator: f64,
}

impl Default for PybopDensities {
    fn default() -> Self {
        Self { negative_electrode: 1657.0, positive_electrode: 3262.0, separator: 397.0 }
    }
}

/// Which mass convention a design problem reports.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub enum MassConvention {
    /// The cell format's components (free area: the set's plate area and packaging fractions).
    #[default]
    Cellstudio,
    /// PyBOP's design-example convention with these densities.
    Pybop(PybopDensities),
}

impl PybopDensities {
    /// Every density positive; errors name `cell.pybop.<field>`.
    pub fn validate(&self) -> Result<(), Error> {
        super::check::positive("cell.pybop.negative_electrode", self.negative_electrode)?;
        super::check::positive("cell.pybop.positive_electrode", self.positive_electrode)?;
        super::check::positive("cell.pybop.separator", self.separator)
    }
}

impl ParameterSet {
    /// The mass basis in PyBOP's convention with densities `d`: this set's stack with PyBOP's
    /// densities substituted, the separator counted solid, and no packaging.
    pub fn pybop_mass_basis(&self, d: &PybopDensities) -> MassBasis {
        let mut p = self.clone();
        for (e, rho) in [(&mut p.negative, d.negative_electrode), (&mut p.positive, d.positive_electrode)] {
            e.active_density = rho;
            e.inactive_density = rho;
        }
        p.electrolyte.density = d.separator;
        let a = p.cell.area();
        let mut components = p.stack_components(StackAreas::uniform(a));
        components.retain(|c| c.part != Part::Separator);
        let source = "PyBOP: Separator density";
        components.insert(6, component("separator (solid, PyBOP)", Part::Separator, d.separator, p.separator.thickness * a, source));
        for c in components.iter_mut().filter(|c| c.part != Part::Collectors && c.part != Part::Separator) {
            c.source = if c.name.contains("electrolyte") { "PyBOP: Separator density".into() } else { "PyBOP: electrode density".into() };
        }
        MassBasis::new(
            format!("Mass basis: PyBOP's convention (its design examples): plate area {a:.4} m^2; electrode density for active material and binder, separator density for the separator (as solid) and the electrolyte; both collectors once; no packaging."),
            components,
            a * p.sandwich_thickness(),
            "stack volume, no packaging".into(),
        )
    }
}

#[cfg(test)]
mod tests {
    use crate::params::chen2020;

    /// PyBOP's `cell_mass` by hand for Chen 2020: sum of thickness x density per layer.
    #[test]
    fn matches_pybop_cell_mass_by_hand() {
        let p = chen2020();
        let areal = 85.2e-6 * (0.75 * 1657.0 + 0.25 * 397.0) + 75.6e-6 * (0.665 * 3262.0 + 0.335 * 397.0) + 12e-6 * 397.0 + 12e-6 * 8960.0 + 16e-6 * 2700.0;
        let m = p.pybop_mass_basis(&super::PybopDensities::default()).mass;
        assert!((m / (areal * 0.065 * 1.58) - 1.0).abs() < 1e-12, "{m}");
    }
}
