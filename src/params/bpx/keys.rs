//! The mapping's two vocabularies: the BPX section and key names, and the fields of ours that
//! BPX lacks (exported under `User-defined`), that every import must account for, or that
//! make up the lumped heat capacity.

use super::super::ParameterSet;
use crate::error::Error;

/// Version written in the `Header` of exported documents.
pub const BPX_VERSION: f64 = 0.5;
/// Prefix of our own keys in the `User-defined` section.
pub const USER_PREFIX: &str = "cellstudio.";
/// User-defined key of the initial state of charge (BPX v0.x has none).
pub(super) const SOC_KEY: &str = "cellstudio.initial_state_of_charge";

// Sections.
pub(super) const HEADER: &str = "Header";
pub(super) const PARAMETERISATION: &str = "Parameterisation";
pub(super) const CELL: &str = "Cell";
pub(super) const ELECTROLYTE: &str = "Electrolyte";
pub(super) const NEGATIVE: &str = "Negative electrode";
pub(super) const POSITIVE: &str = "Positive electrode";
pub(super) const SEPARATOR: &str = "Separator";
pub(super) const USER_DEFINED: &str = "User-defined";
pub(super) const STATE: &str = "State";
pub(super) const INITIAL_CONDITIONS: &str = "Initial conditions";
pub(super) const THERMAL_ENVIRONMENT: &str = "Thermal environment";
pub(super) const VALIDATION: &str = "Validation";

// Cell keys.
pub(super) const AREA: &str = "Electrode area [m2]";
pub(super) const PAIRS: &str = "Number of electrode pairs connected in parallel to make a cell";
pub(super) const EXTERNAL_AREA: &str = "External surface area [m2]";
pub(super) const VOLUME: &str = "Volume [m3]";
pub(super) const LOWER_CUTOFF: &str = "Lower voltage cut-off [V]";
pub(super) const UPPER_CUTOFF: &str = "Upper voltage cut-off [V]";
pub(super) const CAPACITY: &str = "Nominal cell capacity [A.h]";
pub(super) const AMBIENT_T: &str = "Ambient temperature [K]";
pub(super) const INITIAL_T: &str = "Initial temperature [K]";
pub(super) const REFERENCE_T: &str = "Reference temperature [K]";
pub(super) const DENSITY: &str = "Density [kg.m-3]";
pub(super) const HEAT_CAPACITY: &str = "Specific heat capacity [J.K-1.kg-1]";
pub(super) const HEAT_TRANSFER: &str = "Heat transfer coefficient [W.m-2.K-1]";
pub(super) const SOC: &str = "Initial state-of-charge";

// Electrolyte keys (diffusivity and conductivity also name electrode keys).
pub(super) const ELECTROLYTE_C0: &str = "Initial concentration [mol.m-3]";
pub(super) const ELECTROLYTE_C0_V1: &str = "Initial electrolyte concentration [mol.m-3]";
pub(super) const TRANSFERENCE: &str = "Cation transference number";
pub(super) const DIFFUSIVITY: &str = "Diffusivity [m2.s-1]";
pub(super) const DIFFUSIVITY_EA: &str = "Diffusivity activation energy [J.mol-1]";
pub(super) const CONDUCTIVITY: &str = "Conductivity [S.m-1]";
pub(super) const CONDUCTIVITY_EA: &str = "Conductivity activation energy [J.mol-1]";

// Electrode and separator keys.
pub(super) const THICKNESS: &str = "Thickness [m]";
pub(super) const POROSITY: &str = "Porosity";
pub(super) const TRANSPORT_EFFICIENCY: &str = "Transport efficiency";
pub(super) const RADIUS: &str = "Particle radius [m]";
pub(super) const SURFACE_AREA: &str = "Surface area per unit volume [m-1]";
pub(super) const MAX_CONCENTRATION: &str = "Maximum concentration [mol.m-3]";
pub(super) const MIN_STO: &str = "Minimum stoichiometry";
pub(super) const MAX_STO: &str = "Maximum stoichiometry";
pub(super) const OCP: &str = "OCP [V]";
pub(super) const ENTROPIC: &str = "Entropic change coefficient [V.K-1]";
pub(super) const RATE: &str = "Reaction rate constant [mol.m-2.s-1]";
pub(super) const RATE_EA: &str = "Reaction rate constant activation energy [J.mol-1]";
pub(super) const PARTICLE: &str = "Particle";

/// Our scalar fields with no BPX equivalent, exported as `cellstudio.<path>` user-defined keys.
pub(super) const USER_DEFINED_FIELDS: &[&str] = &[
    "negative.bruggeman_solid",
    "negative.charge_transfer_coefficient",
    "negative.active_density",
    "negative.inactive_density",
    "negative.volumetric_heat_capacity",
    "negative.double_layer_capacitance",
    "negative.radius_relative_std",
    "negative.second_phase_share",
    "negative.second_phase_potential",
    "negative.second_phase_width",
    "positive.bruggeman_solid",
    "positive.charge_transfer_coefficient",
    "positive.active_density",
    "positive.inactive_density",
    "positive.volumetric_heat_capacity",
    "positive.double_layer_capacitance",
    "positive.radius_relative_std",
    "positive.second_phase_share",
    "positive.second_phase_potential",
    "positive.second_phase_width",
    "separator.solid_density",
    "separator.volumetric_heat_capacity",
    "electrolyte.thermodynamic_factor",
    "electrolyte.density",
    "cell.electrode_height",
    "cell.negative_collector_thickness",
    "cell.positive_collector_thickness",
    "cell.negative_collector_density",
    "cell.positive_collector_density",
    "cell.packaging_mass_fraction",
    "cell.packaging_volume_fraction",
    "cell.contact_resistance",
    "cell.rc_resistance",
    "cell.rc_capacitance",
    "cell.hysteresis_voltage",
    "cell.hysteresis_rate",
    "cell.hysteresis_initial",
    "cell.leakage_current",
    "cell.voltage_offset",
    "cell.voltage_gain",
    "cell.current_gain",
    "thermal.heat_transfer_coefficient",
    "thermal.negative_collector_heat_capacity",
    "thermal.positive_collector_heat_capacity",
];

/// Scalar fields of each electrode.
const ELECTRODE_FIELDS: &[&str] = &[
    "thickness",
    "particle_radius",
    "active_fraction",
    "porosity",
    "bruggeman_electrolyte",
    "bruggeman_solid",
    "conductivity",
    "max_concentration",
    "initial_concentration",
    "diffusivity",
    "diffusivity_activation_energy",
    "ocp_entropic_change",
    "rate_constant",
    "rate_activation_energy",
    "charge_transfer_coefficient",
    "active_density",
    "inactive_density",
    "volumetric_heat_capacity",
    "double_layer_capacitance",
    "radius_relative_std",
    "second_phase_share",
    "second_phase_potential",
    "second_phase_width",
];

/// Scalar fields outside the electrodes, as dotted paths.
const OTHER_FIELDS: &[&str] = &[
    "separator.thickness",
    "separator.porosity",
    "separator.bruggeman",
    "separator.solid_density",
    "separator.volumetric_heat_capacity",
    "electrolyte.initial_concentration",
    "electrolyte.transference_number",
    "electrolyte.thermodynamic_factor",
    "electrolyte.activation_energy",
    "electrolyte.density",
    "cell.electrode_height",
    "cell.electrode_width",
    "cell.negative_collector_thickness",
    "cell.positive_collector_thickness",
    "cell.negative_collector_density",
    "cell.positive_collector_density",
    "cell.packaging_mass_fraction",
    "cell.packaging_volume_fraction",
    "cell.nominal_capacity",
    "cell.lower_cutoff",
    "cell.upper_cutoff",
    "cell.contact_resistance",
    "cell.rc_resistance",
    "cell.rc_capacitance",
    "cell.hysteresis_voltage",
    "cell.hysteresis_rate",
    "cell.hysteresis_initial",
    "cell.leakage_current",
    "cell.voltage_offset",
    "cell.voltage_gain",
    "cell.current_gain",
    "thermal.reference_temperature",
    "thermal.ambient_temperature",
    "thermal.initial_temperature",
    "thermal.heat_transfer_coefficient",
    "thermal.cooling_area",
    "thermal.cell_volume",
    "thermal.negative_collector_heat_capacity",
    "thermal.positive_collector_heat_capacity",
];

/// Every scalar field of a [`ParameterSet`] as a dotted path.
pub(super) fn scalar_paths() -> Vec<String> {
    ["negative", "positive"]
        .iter()
        .flat_map(|side| ELECTRODE_FIELDS.iter().map(move |f| format!("{side}.{f}")))
        .chain(OTHER_FIELDS.iter().map(|f| f.to_string()))
        .collect()
}

/// The five layers of the lumped heat capacity: (thickness path, heat-capacity path).
pub(super) const HEAT_LAYERS: [(&str, &str); 5] = [
    ("negative.thickness", "negative.volumetric_heat_capacity"),
    ("separator.thickness", "separator.volumetric_heat_capacity"),
    ("positive.thickness", "positive.volumetric_heat_capacity"),
    ("cell.negative_collector_thickness", "thermal.negative_collector_heat_capacity"),
    ("cell.positive_collector_thickness", "thermal.positive_collector_heat_capacity"),
];

/// Thickness-weighted mean volumetric heat capacity (J/(m^3 K)) of the stack, as the lumped
/// thermal model uses it.
pub(super) fn mean_heat_capacity(p: &ParameterSet) -> Result<f64, Error> {
    let mut total = 0.0;
    let mut weighted = 0.0;
    for (t, c) in HEAT_LAYERS {
        let t = p.get(t)?;
        total += t;
        weighted += t * p.get(c)?;
    }
    Ok(weighted / total)
}
