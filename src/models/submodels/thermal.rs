//! Lumped (0-D) thermal balance `C dT/dt = Q - hA (T - T_amb)`.

use crate::params::ParameterSet;

/// Heat capacity and cooling of the whole cell.
#[derive(Clone, Copy, Debug)]
pub struct LumpedThermal {
    /// Heat capacity of the cell (J/K): the layer-thickness-weighted volumetric heat
    /// capacity of the stack times the cell volume.
    pub heat_capacity: f64,
    /// Cooling conductance `h A` (W/K).
    pub cooling: f64,
    /// Ambient temperature (K).
    pub ambient: f64,
}

impl LumpedThermal {
    pub fn new(p: &ParameterSet) -> Self {
        let t = &p.thermal;
        let c = &p.cell;
        let layers = [
            (p.negative.thickness, p.negative.volumetric_heat_capacity),
            (p.separator.thickness, p.separator.volumetric_heat_capacity),
            (p.positive.thickness, p.positive.volumetric_heat_capacity),
            (c.negative_collector_thickness, t.negative_collector_heat_capacity),
            (c.positive_collector_thickness, t.positive_collector_heat_capacity),
        ];
        let total: f64 = layers.iter().map(|l| l.0).sum();
        let mean: f64 = layers.iter().map(|l| l.0 * l.1).sum::<f64>() / total;
        Self {
            heat_capacity: mean * t.cell_volume,
            cooling: t.heat_transfer_coefficient * t.cooling_area,
            ambient: t.ambient_temperature,
        }
    }

    /// `dT/dt` (K/s) for total heat generation `heat` (W) at temperature `temp` (K).
    pub fn rate(&self, heat: f64, temp: f64) -> f64 {
        (heat - self.cooling * (temp - self.ambient)) / self.heat_capacity
    }
}

/// Bernardi heat generation (W) of a cell at current `current` (A, discharge positive):
/// irreversible + ohmic `I (U - V)` plus reversible `-I T dU/dT`.
pub fn bernardi_heat(current: f64, ocv: f64, voltage: f64, temp: f64, docv_dt: f64) -> f64 {
    current * (ocv - voltage) - current * temp * docv_dt
}
