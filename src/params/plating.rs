//! Parameters of lithium plating on the negative electrode, as PyBaMM names them (its keys
//! in each field's doc), with the values of PyBaMM's "OKane2022" set (O'Kane 2022, the LG M50
//! cell of Chen 2020 with degradation parameters) as the default. They are read only when a
//! plating submodel is on (`submodels = { plating = "irreversible" }`).
//!
//! OKane2022's exchange-current functions are fixed here: plating `F k c_e`, stripping
//! `F k c_Li` (A/m^2, O'Kane 2020), and its dead-lithium decay rate `gamma_0 L_sei_0 / L_sei`
//! (1/s, O'Kane 2022), with `k` and `gamma_0` below.

use serde::{Deserialize, Serialize};

use super::check::{check, non_negative, positive};
use crate::error::Error;

/// Lithium plating parameters (SI units, `[plating]` of a parameter file).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct Plating {
    /// "Lithium plating kinetic rate constant [m.s-1]" `k_Li`: the exchange-current densities
    /// are `F k_Li c_e` (plating) and `F k_Li c_Li` (stripping).
    pub kinetic_rate_constant: f64,
    /// "Lithium plating transfer coefficient" `alpha_pl` (-); stripping's is `1 - alpha_pl`.
    pub transfer_coefficient: f64,
    /// "Initial plated lithium concentration [mol.m-3]" `c_Li_0` (per m^3 of electrode).
    pub initial_concentration: f64,
    /// "Typical plated lithium concentration [mol.m-3]" `c_Li_typ`: the states' scale.
    pub typical_concentration: f64,
    /// "Dead lithium decay constant [s-1]" `gamma_0` (partially reversible).
    pub dead_lithium_decay_constant: f64,
    /// "Lithium metal partial molar volume [m3.mol-1]" `V_bar_Li`: plated-layer thickness
    /// `c_Li V_bar_Li / a`.
    pub lithium_partial_molar_volume: f64,
}

impl Default for Plating {
    /// PyBaMM 26.10's OKane2022 values.
    fn default() -> Self {
        Self {
            kinetic_rate_constant: 1e-9,
            transfer_coefficient: 0.65,
            initial_concentration: 0.0,
            typical_concentration: 1000.0,
            dead_lithium_decay_constant: 1e-6,
            lithium_partial_molar_volume: 1.3e-5,
        }
    }
}

impl Plating {
    /// Checks every field; the error names it (`plating.NAME`) and its value.
    pub fn validate(&self) -> Result<(), Error> {
        non_negative("plating.kinetic_rate_constant", self.kinetic_rate_constant)?;
        let alpha = self.transfer_coefficient;
        check("plating.transfer_coefficient", alpha, (0.0..=1.0).contains(&alpha), "must lie in [0, 1]")?;
        non_negative("plating.initial_concentration", self.initial_concentration)?;
        positive("plating.typical_concentration", self.typical_concentration)?;
        non_negative("plating.dead_lithium_decay_constant", self.dead_lithium_decay_constant)?;
        positive("plating.lithium_partial_molar_volume", self.lithium_partial_molar_volume)
    }

    /// The field named `name` (after `plating.`), for `--set plating.NAME=VALUE`.
    pub(super) fn field_mut(&mut self, name: &str) -> Option<&mut f64> {
        Some(match name {
            "kinetic_rate_constant" => &mut self.kinetic_rate_constant,
            "transfer_coefficient" => &mut self.transfer_coefficient,
            "initial_concentration" => &mut self.initial_concentration,
            "typical_concentration" => &mut self.typical_concentration,
            "dead_lithium_decay_constant" => &mut self.dead_lithium_decay_constant,
            "lithium_partial_molar_volume" => &mut self.lithium_partial_molar_volume,
            _ => return None,
        })
    }
}

#[cfg(test)]
mod tests {
    #[test]
    fn bad_plating_values_name_the_field() {
        let mut p = crate::params::chen2020();
        p.set("plating.kinetic_rate_constant", -1e-9).unwrap();
        let e = p.validate().unwrap_err().to_string();
        assert!(e.contains("`plating.kinetic_rate_constant`") && e.contains("= -1e-9"), "{e}");
        p.set("plating.kinetic_rate_constant", 2e-9).unwrap();
        p.set("plating.transfer_coefficient", f64::NAN).unwrap();
        let e = p.validate().unwrap_err().to_string();
        assert!(e.contains("`plating.transfer_coefficient`") && e.contains("NaN"), "{e}");
        assert!(p.set("plating.rate_constant", 1.0).is_err());
        assert_eq!(p.get("plating.kinetic_rate_constant").unwrap(), 2e-9);
    }
}
