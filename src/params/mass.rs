//! Cell mass (kg) and volume (m^3) from the geometry and material densities, component by
//! component, so a report can state its mass basis.
//!
//! Free-area convention (as in PyBaMM/PyBOP): the electrode area is the unrolled plate area and
//! each layer (coatings, separator, both current collectors) is counted once over that area.
//! Tabs, can and free volume are the set's packaging allowances on top of the stack. A cell
//! format ([`super::format`]) counts the same stack layers over the areas they really cover
//! (a double-sided collector once per two sandwiches) and its can or pouch from its size.

use serde::Serialize;

use super::set::{Electrode, ParameterSet};

/// Which part of the cell a mass component belongs to.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Part {
    NegativeCoating,
    PositiveCoating,
    Separator,
    Collectors,
    Packaging,
}

/// One line of a mass budget: a material, its density, volume and mass.
#[derive(Clone, Debug, Serialize)]
pub struct MassComponent {
    /// What it is, e.g. "negative active material".
    pub name: String,
    pub part: Part,
    /// Density (kg/m^3); `None` for an allowance given as a mass or a fraction.
    pub density: Option<f64>,
    /// Material volume (m^3); `None` for an allowance.
    pub volume: Option<f64>,
    /// Mass (kg).
    pub mass: f64,
    /// Where the density or allowance comes from.
    pub source: String,
}

/// A cell's mass and volume with the components that count in them.
#[derive(Clone, Debug, Serialize)]
pub struct MassBasis {
    /// The convention in one sentence (which areas, which packaging).
    pub convention: String,
    pub components: Vec<MassComponent>,
    /// Total mass (kg): the sum of the components.
    pub mass: f64,
    /// Cell volume (m^3).
    pub volume: f64,
    /// What the volume is (stack plus allowance, or the outer envelope).
    pub volume_basis: String,
}

impl MassBasis {
    /// A basis from its components; the mass is their sum.
    pub fn new(convention: String, components: Vec<MassComponent>, volume: f64, volume_basis: String) -> Self {
        let mass = components.iter().map(|c| c.mass).sum();
        Self { convention, components, mass, volume, volume_basis }
    }

    /// Mass of one part (kg).
    pub fn part(&self, part: Part) -> f64 {
        self.components.iter().filter(|c| c.part == part).map(|c| c.mass).sum()
    }

    /// The budget as a Markdown table (g, cm^3, kg/m^3, share of the mass), with the
    /// convention and volume basis above it.
    pub fn markdown(&self) -> String {
        use std::fmt::Write as _;
        let mut md = format!("{}\n\nVolume: {:.3} cm^3 ({}).\n\n", self.convention, self.volume * 1e6, self.volume_basis);
        md.push_str("| component | density (kg/m^3) | volume (cm^3) | mass (g) | share of mass | source |\n");
        md.push_str("|---|---|---|---|---|---|\n");
        for c in &self.components {
            let density = c.density.map_or("-".to_string(), |d| format!("{d:.0}"));
            let volume = c.volume.map_or("-".to_string(), |v| format!("{:.3}", v * 1e6));
            let _ = writeln!(md, "| {} | {density} | {volume} | {:.2} | {:.1} % | {} |", c.name, c.mass * 1e3, 100.0 * c.mass / self.mass, c.source);
        }
        let _ = writeln!(md, "| **total** | | | **{:.2}** | 100.0 % | |", self.mass * 1e3);
        md
    }
}

/// Areas over which the stack's layers are counted (m^2).
#[derive(Clone, Copy, Debug)]
pub struct StackAreas {
    /// Coated area of each electrode: the sandwich area the model sees.
    pub coating: f64,
    /// Separator area (all layers).
    pub separator: f64,
    /// Negative (copper) collector area.
    pub negative_collector: f64,
    /// Positive (aluminium) collector area.
    pub positive_collector: f64,
}

impl StackAreas {
    /// Every layer once over the plate area (the free-area convention).
    pub fn uniform(area: f64) -> Self {
        Self { coating: area, separator: area, negative_collector: area, positive_collector: area }
    }
}

/// A material of `density` (kg/m^3) and `volume` (m^3).
pub(crate) fn component(name: &str, part: Part, density: f64, volume: f64, source: &str) -> MassComponent {
    MassComponent { name: name.into(), part, density: Some(density), volume: Some(volume), mass: density * volume, source: source.into() }
}

const SET: &str = "parameter set";

fn coating(e: &Electrode, side: &str, part: Part, area: f64, rho_e: f64) -> [MassComponent; 3] {
    let v = e.thickness * area;
    [
        component(&format!("{side} active material"), part, e.active_density, v * e.active_fraction, SET),
        component(&format!("{side} binder and carbon"), part, e.inactive_density, v * e.inactive_fraction().max(0.0), SET),
        component(&format!("{side} pore electrolyte"), part, rho_e, v * e.porosity, SET),
    ]
}

impl ParameterSet {
    /// The electrode stack's components (coatings with their pore electrolyte, separator,
    /// collectors) over the given areas.
    pub fn stack_components(&self, areas: StackAreas) -> Vec<MassComponent> {
        let rho_e = self.electrolyte.density;
        let (s, c) = (&self.separator, &self.cell);
        let mut out = Vec::with_capacity(9);
        out.extend(coating(&self.negative, "negative", Part::NegativeCoating, areas.coating, rho_e));
        out.extend(coating(&self.positive, "positive", Part::PositiveCoating, areas.coating, rho_e));
        let vs = s.thickness * areas.separator;
        out.push(component("separator solid", Part::Separator, s.solid_density, vs * (1.0 - s.porosity), SET));
        out.push(component("separator pore electrolyte", Part::Separator, rho_e, vs * s.porosity, SET));
        out.push(component("negative collector (Cu)", Part::Collectors, c.negative_collector_density, c.negative_collector_thickness * areas.negative_collector, SET));
        out.push(component("positive collector (Al)", Part::Collectors, c.positive_collector_density, c.positive_collector_thickness * areas.positive_collector, SET));
        out
    }

    /// Thickness of one sandwich: negative coating, separator, positive coating and both
    /// collectors (m).
    pub fn sandwich_thickness(&self) -> f64 {
        let c = &self.cell;
        self.negative.thickness + self.separator.thickness + self.positive.thickness + c.negative_collector_thickness + c.positive_collector_thickness
    }

    /// The free-area mass basis: every stack layer once over the plate area, packaging as the
    /// set's mass and volume fractions of the stack.
    pub fn mass_basis(&self) -> MassBasis {
        let c = &self.cell;
        let a = c.area();
        let mut components = self.stack_components(StackAreas::uniform(a));
        let stack: f64 = components.iter().map(|x| x.mass).sum();
        components.push(MassComponent {
            name: "tabs, can and packaging".into(),
            part: Part::Packaging,
            density: None,
            volume: None,
            mass: stack * c.packaging_mass_fraction,
            source: format!("allowance: {} x stack mass (cell.packaging_mass_fraction)", c.packaging_mass_fraction),
        });
        MassBasis::new(
            format!(
                "Mass basis: free area (PyBaMM/PyBOP convention): electrode area {:.4} m^2 fixed; each layer (both coatings, separator, both collectors) counted once over it; packaging a fraction of the stack mass.",
                a
            ),
            components,
            a * self.sandwich_thickness() * (1.0 + c.packaging_volume_fraction),
            format!("stack volume x (1 + {}) (cell.packaging_volume_fraction)", c.packaging_volume_fraction),
        )
    }
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

impl From<&MassBasis> for CellBudget {
    fn from(b: &MassBasis) -> Self {
        Self {
            negative_coating: b.part(Part::NegativeCoating),
            positive_coating: b.part(Part::PositiveCoating),
            separator: b.part(Part::Separator),
            collectors: b.part(Part::Collectors),
            packaging: b.part(Part::Packaging),
            mass: b.mass,
            volume: b.volume,
        }
    }
}

impl ParameterSet {
    /// Mass and volume of the cell (free-area convention).
    pub fn budget(&self) -> CellBudget {
        CellBudget::from(&self.mass_basis())
    }
}
