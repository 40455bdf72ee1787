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
///
/// With side reactions in the negative electrode this counts more than PyBaMM's heat source
/// does; the models subtract [`SideReactionSite::uncounted_heat`] of each negative site.
pub fn bernardi_heat(current: f64, ocv: f64, voltage: f64, temp: f64, docv_dt: f64) -> f64 {
    current * (ocv - voltage) - current * temp * docv_dt
}

/// [`bernardi_heat`] (W) with the open-circuit power `ocv_power` (W) in place of `I U`: for
/// reactions whose current and OCP vary through the electrodes, `-A sum a j_tot U dx` over
/// the electrode volumes (nonzero at rest while currents redistribute), which makes the heat
/// PyBaMM's ohmic plus reaction heat `Q_ohm + sum a j_tot eta` by charge conservation; and
/// the reversible heat `reversible` (W), `A T sum a j_tot dU/dT dx` (PyBaMM's `Q_rev`).
pub fn bernardi_heat_of_power(ocv_power: f64, current: f64, voltage: f64, reversible: f64) -> f64 {
    ocv_power - current * voltage + reversible
}

/// The reactions at one negative-electrode site (the whole electrode in the single-particle
/// models, one x volume in the DFN) with side reactions (SEI growth, lithium plating) on.
#[derive(Clone, Copy, Debug)]
pub struct SideReactionSite {
    /// Surface area density `a` (1/m).
    pub a: f64,
    /// Total interfacial current density `j_tot` (A/m^2): intercalation plus side reactions.
    pub total_current: f64,
    /// Side-reaction current density `j_sei + j_Li` (A/m^2), negative while they consume
    /// lithium.
    pub side_current: f64,
    /// `phi_s - phi_e` (V), with the film's drop.
    pub delta_phi: f64,
    /// Open-circuit potential at the particle surface `U_n` (V).
    pub ocp: f64,
    /// SEI film drop `j_tot L_sei R_sei` (V); zero without SEI.
    pub film: f64,
}

impl SideReactionSite {
    /// Heat (W/m^3 of electrode) that [`bernardi_heat`] counts at this site and PyBaMM's
    /// thermal submodel does not: `a (j_tot film + j_side (eta_r + T dU_n/dT))` with the
    /// intercalation overpotential `eta_r = phi_s - phi_e - U_n - film`.
    ///
    /// `I (U - V)` is the ohmic heat plus `sum a j_tot (eta_r + film)` over the electrodes;
    /// PyBaMM's `Q_rxn + Q_rev` is `a j (eta_r + T dU/dT)` with `j = j_tot - j_side`, its
    /// "volumetric interfacial current density" of intercalation alone, and its ohmic heat is
    /// the solid's and the electrolyte's only, so neither the film's ohmic heat nor the side
    /// reactions' current at the intercalation overpotential and entropy heats the cell.
    /// `temp` (K), `entropic_change` `dU_n/dT` (V/K).
    pub fn uncounted_heat(&self, temp: f64, entropic_change: f64) -> f64 {
        let eta_r = self.delta_phi - self.ocp - self.film;
        self.a * (self.total_current * self.film + self.side_current * (eta_r + temp * entropic_change))
    }
}
