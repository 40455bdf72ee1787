//! Parameters of SEI growth on the negative electrode, as PyBaMM names them (its keys in
//! each field's doc), with the values of PyBaMM's "Chen2020" set as the default. They are
//! read only when an SEI submodel is on (`submodels = { sei = "reaction limited" }`).

use serde::{Deserialize, Serialize};

use super::check::{non_negative, positive};
use crate::error::Error;

/// SEI layer and side-reaction parameters (SI units).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct Sei {
    /// "Ratio of lithium moles to SEI moles" `z_sei` (-).
    pub lithium_per_sei: f64,
    /// "SEI partial molar volume [m3.mol-1]" `V_bar_sei`.
    pub partial_molar_volume: f64,
    /// "SEI reaction exchange current density [A.m-2]" `j0_sei` (reaction limited).
    pub exchange_current: f64,
    /// "SEI resistivity [Ohm.m]" `R_sei`: the film's resistance per thickness and area.
    pub resistivity: f64,
    /// "SEI solvent diffusivity [m2.s-1]" `D_sol` (solvent-diffusion limited).
    pub solvent_diffusivity: f64,
    /// "Bulk solvent concentration [mol.m-3]" `c_sol` (solvent-diffusion limited).
    pub solvent_concentration: f64,
    /// "SEI open-circuit potential [V]" `U_sei`.
    pub open_circuit_potential: f64,
    /// "Initial SEI thickness [m]" `L_sei_0`.
    pub initial_thickness: f64,
    /// "SEI growth activation energy [J.mol-1]" `E_sei`.
    pub activation_energy: f64,
    /// "SEI electron conductivity [S.m-1]" `kappa_inner` (electron-migration limited).
    pub electron_conductivity: f64,
    /// "SEI lithium interstitial diffusivity [m2.s-1]" `D_li` (interstitial-diffusion limited).
    pub interstitial_diffusivity: f64,
    /// "Lithium interstitial reference concentration [mol.m-3]" `c_li_0`
    /// (interstitial-diffusion limited).
    pub interstitial_concentration: f64,
    /// "EC initial concentration in electrolyte [mol.m-3]" `c_ec_0` (EC reaction limited).
    pub ec_concentration: f64,
    /// "EC diffusivity [m2.s-1]" `D_ec` (EC reaction limited).
    pub ec_diffusivity: f64,
    /// "SEI kinetic rate constant [m.s-1]" `k_sei` (EC reaction limited).
    pub kinetic_rate_constant: f64,
}

impl Default for Sei {
    /// PyBaMM 26.10's Chen2020 values.
    fn default() -> Self {
        Self {
            lithium_per_sei: 2.0,
            partial_molar_volume: 9.585e-5,
            exchange_current: 1.5e-7,
            resistivity: 2e5,
            solvent_diffusivity: 2.5e-22,
            solvent_concentration: 2636.0,
            open_circuit_potential: 0.4,
            initial_thickness: 5e-9,
            activation_energy: 0.0,
            electron_conductivity: 8.95e-14,
            interstitial_diffusivity: 1e-20,
            interstitial_concentration: 15.0,
            ec_concentration: 4541.0,
            ec_diffusivity: 2e-18,
            kinetic_rate_constant: 1e-12,
        }
    }
}

impl Sei {
    /// Checks every field; the error names it (`sei.NAME`) and its value.
    pub fn validate(&self) -> Result<(), Error> {
        positive("sei.lithium_per_sei", self.lithium_per_sei)?;
        positive("sei.partial_molar_volume", self.partial_molar_volume)?;
        non_negative("sei.exchange_current", self.exchange_current)?;
        non_negative("sei.resistivity", self.resistivity)?;
        non_negative("sei.solvent_diffusivity", self.solvent_diffusivity)?;
        non_negative("sei.solvent_concentration", self.solvent_concentration)?;
        super::check::check("sei.open_circuit_potential", self.open_circuit_potential, true, "must be finite")?;
        positive("sei.initial_thickness", self.initial_thickness)?;
        non_negative("sei.activation_energy", self.activation_energy)?;
        non_negative("sei.electron_conductivity", self.electron_conductivity)?;
        non_negative("sei.interstitial_diffusivity", self.interstitial_diffusivity)?;
        non_negative("sei.interstitial_concentration", self.interstitial_concentration)?;
        non_negative("sei.ec_concentration", self.ec_concentration)?;
        positive("sei.ec_diffusivity", self.ec_diffusivity)?;
        non_negative("sei.kinetic_rate_constant", self.kinetic_rate_constant)
    }

    /// The field named `name` (after `sei.`), for `--set sei.NAME=VALUE`.
    pub(super) fn field_mut(&mut self, name: &str) -> Option<&mut f64> {
        Some(match name {
            "lithium_per_sei" => &mut self.lithium_per_sei,
            "partial_molar_volume" => &mut self.partial_molar_volume,
            "exchange_current" => &mut self.exchange_current,
            "resistivity" => &mut self.resistivity,
            "solvent_diffusivity" => &mut self.solvent_diffusivity,
            "solvent_concentration" => &mut self.solvent_concentration,
            "open_circuit_potential" => &mut self.open_circuit_potential,
            "initial_thickness" => &mut self.initial_thickness,
            "activation_energy" => &mut self.activation_energy,
            "electron_conductivity" => &mut self.electron_conductivity,
            "interstitial_diffusivity" => &mut self.interstitial_diffusivity,
            "interstitial_concentration" => &mut self.interstitial_concentration,
            "ec_concentration" => &mut self.ec_concentration,
            "ec_diffusivity" => &mut self.ec_diffusivity,
            "kinetic_rate_constant" => &mut self.kinetic_rate_constant,
            _ => return None,
        })
    }
}

#[cfg(test)]
mod tests {
    #[test]
    fn bad_sei_values_name_the_field() {
        let mut p = crate::params::chen2020();
        p.set("sei.initial_thickness", -1e-9).unwrap();
        let e = p.validate().unwrap_err().to_string();
        assert!(e.contains("`sei.initial_thickness`") && e.contains("must be positive"), "{e}");
        assert!(p.set("sei.thicknes", 1.0).is_err());
        p.set("sei.initial_thickness", 7e-9).unwrap();
        assert_eq!(p.get("sei.initial_thickness").unwrap(), 7e-9);
    }
}
