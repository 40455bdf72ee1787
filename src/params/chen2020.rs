//! The LG M50 (21700, 5 A h) parameter set of Chen et al. (2020), "Development of
//! Experimental Techniques for Parameterization of Multi-scale Lithium-ion Battery Models",
//! J. Electrochem. Soc. 167 080534, as distributed with PyBaMM ("Chen2020").
//!
//! Chen 2020 gives no material densities for a mass budget; those fields use handbook values
//! (graphite 2260 kg/m^3, NMC 811 4870 kg/m^3, PVDF/carbon 1800 kg/m^3, LiPF6 EC:EMC
//! electrolyte 1280 kg/m^3, polyethylene 946 kg/m^3) and a packaging allowance that brings
//! the cell to the LG M50's 68-70 g and 21700 can volume.

use super::function::Function1D;
use super::set::{Cell, Electrode, Electrolyte, ParameterSet, Separator, Thermal};

/// The Chen 2020 LG M50 parameter set.
pub fn chen2020() -> ParameterSet {
    ParameterSet {
        name: "Chen2020 (LG M50)".into(),
        cell: Cell {
            electrode_height: 0.065,
            electrode_width: 1.58,
            negative_collector_thickness: 12e-6,
            positive_collector_thickness: 16e-6,
            negative_collector_density: 8960.0,
            positive_collector_density: 2700.0,
            packaging_mass_fraction: 0.08,
            packaging_volume_fraction: 0.17,
            nominal_capacity: 5.0,
            lower_cutoff: 2.5,
            upper_cutoff: 4.2,
            contact_resistance: 0.0,
            rc_resistance: 0.0,
            rc_capacitance: super::set::DEFAULT_RC_CAPACITANCE,
            hysteresis_voltage: 0.0,
            hysteresis_rate: super::set::DEFAULT_HYSTERESIS_RATE,
            hysteresis_initial: 0.0,
            leakage_current: 0.0,
            voltage_offset: 0.0,
        },
        negative: Electrode {
            thickness: 85.2e-6,
            particle_radius: 5.86e-6,
            active_fraction: 0.75,
            porosity: 0.25,
            bruggeman_electrolyte: 1.5,
            bruggeman_solid: 0.0,
            conductivity: 215.0,
            max_concentration: 33133.0,
            initial_concentration: 29866.0,
            diffusivity: 3.3e-14,
            diffusivity_activation_energy: 0.0,
            ocp: Function1D::Chen2020GraphiteOcp,
            ocp_entropic_change: 0.0,
            rate_constant: 6.48e-7,
            rate_activation_energy: 35000.0,
            charge_transfer_coefficient: 0.5,
            active_density: 2260.0,
            inactive_density: 1800.0,
            volumetric_heat_capacity: 1657.0 * 700.0,
            double_layer_capacitance: 0.2,
        },
        separator: Separator {
            thickness: 12e-6,
            porosity: 0.47,
            bruggeman: 1.5,
            solid_density: 946.0,
            volumetric_heat_capacity: 397.0 * 700.0,
        },
        positive: Electrode {
            thickness: 75.6e-6,
            particle_radius: 5.22e-6,
            active_fraction: 0.665,
            porosity: 0.335,
            bruggeman_electrolyte: 1.5,
            bruggeman_solid: 0.0,
            conductivity: 0.18,
            max_concentration: 63104.0,
            initial_concentration: 17038.0,
            diffusivity: 4e-15,
            diffusivity_activation_energy: 0.0,
            ocp: Function1D::Chen2020Nmc811Ocp,
            ocp_entropic_change: 0.0,
            rate_constant: 3.42e-6,
            rate_activation_energy: 17800.0,
            charge_transfer_coefficient: 0.5,
            active_density: 4870.0,
            inactive_density: 1800.0,
            volumetric_heat_capacity: 3262.0 * 700.0,
            double_layer_capacitance: 0.2,
        },
        electrolyte: Electrolyte {
            initial_concentration: 1000.0,
            transference_number: 0.2594,
            thermodynamic_factor: 1.0,
            diffusivity: Function1D::Nyman2008Diffusivity,
            conductivity: Function1D::Nyman2008Conductivity,
            activation_energy: 0.0,
            diffusivity_factor: 1.0,
            conductivity_factor: 1.0,
            density: 1280.0,
        },
        thermal: Thermal {
            reference_temperature: 298.15,
            ambient_temperature: 298.15,
            initial_temperature: 298.15,
            heat_transfer_coefficient: 10.0,
            cooling_area: 0.00531,
            cell_volume: 2.42e-5,
            negative_collector_heat_capacity: 8960.0 * 385.0,
            positive_collector_heat_capacity: 2700.0 * 897.0,
        },
        sei: super::sei::Sei::default(),
        lam: super::lam::Lam::default(),
        plating: super::plating::Plating::default(),
    }
}
