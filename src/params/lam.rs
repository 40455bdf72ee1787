//! Parameters of loss of active material (LAM) and of the particle mechanics that drives it,
//! per electrode, as PyBaMM names them (its keys, after "Negative electrode " or "Positive
//! electrode ", in each field's doc). They are read only when a LAM submodel is on
//! (`submodels = { lam = "stress-driven" }`). Defaults: the constants of PyBaMM's
//! "OKane2022" set (the LG M50 cell of Chen 2020 with degradation parameters), and the
//! negative "reaction-driven LAM factor" 1e-4 m^3/mol of PyBaMM's LAM notebook (0 in
//! OKane2022 and Chen2020, which would make reaction-driven LAM do nothing).

use serde::{Deserialize, Serialize};

use super::check::{check, non_negative, positive};
use crate::error::Error;

/// LAM parameters of both electrodes (`[lam.negative]`, `[lam.positive]`).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct Lam {
    pub negative: LamElectrode,
    pub positive: LamElectrode,
}

/// One electrode's LAM and mechanical parameters (SI units). A `[lam.negative]` or
/// `[lam.positive]` table in a parameter file gives all of them (an absent table takes the
/// defaults; `--set lam.negative.NAME=VALUE` changes one).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct LamElectrode {
    /// "LAM constant proportional term [s-1]" `beta_LAM` (stress-driven).
    pub proportional_term: f64,
    /// "LAM constant exponential term" `m_LAM` (-) (stress-driven).
    pub exponential_term: f64,
    /// "critical stress [Pa]" `sigma_c` (stress-driven).
    pub critical_stress: f64,
    /// "partial molar volume [m3.mol-1]" `Omega` of lithium in the particle (a constant here;
    /// PyBaMM allows a function of stoichiometry and temperature).
    pub partial_molar_volume: f64,
    /// "Young's modulus [Pa]" `E` (a constant here, as `Omega`).
    pub youngs_modulus: f64,
    /// "Poisson's ratio" `nu` (-).
    pub poisson_ratio: f64,
    /// "reference concentration for free of deformation [mol.m-3]" `c_0`.
    pub reference_concentration: f64,
    /// "reaction-driven LAM factor [m3.mol-1]" `beta_LAM_sei` (reaction-driven).
    pub reaction_factor: f64,
    /// Current-driven LAM coefficient `k_I` (m^2/(A s)): `d eps / dt = -k_I |I / A|`, PyBaMM's
    /// "current-driven LAM rate" function `-k_I |i|` (PyBaMM's sets define no such function;
    /// 0 here, so that turning the law on changes nothing until it is given).
    #[serde(default)]
    pub current_rate: f64,
}

impl Default for Lam {
    fn default() -> Self {
        let negative = LamElectrode {
            proportional_term: 2.7778e-7,
            exponential_term: 2.0,
            critical_stress: 6e7,
            partial_molar_volume: 3.1e-6,
            youngs_modulus: 1.5e10,
            poisson_ratio: 0.3,
            reference_concentration: 0.0,
            reaction_factor: 1e-4,
            current_rate: 0.0,
        };
        let positive = LamElectrode {
            critical_stress: 3.75e8,
            partial_molar_volume: 1.25e-5,
            youngs_modulus: 3.75e11,
            poisson_ratio: 0.2,
            reaction_factor: 0.0,
            ..negative.clone()
        };
        Self { negative, positive }
    }
}

impl LamElectrode {
    /// Checks every field; the error names it (`lam.SIDE.NAME`) and its value.
    fn validate(&self, side: &str) -> Result<(), Error> {
        let f = |name: &str| format!("lam.{side}.{name}");
        non_negative(&f("proportional_term"), self.proportional_term)?;
        positive(&f("exponential_term"), self.exponential_term)?;
        positive(&f("critical_stress"), self.critical_stress)?;
        check(&f("partial_molar_volume"), self.partial_molar_volume, true, "must be finite")?;
        non_negative(&f("youngs_modulus"), self.youngs_modulus)?;
        check(&f("poisson_ratio"), self.poisson_ratio, self.poisson_ratio > -1.0 && self.poisson_ratio < 0.5, "must lie in (-1, 0.5)")?;
        non_negative(&f("reference_concentration"), self.reference_concentration)?;
        non_negative(&f("reaction_factor"), self.reaction_factor)?;
        non_negative(&f("current_rate"), self.current_rate)
    }

    /// The coefficient `theta_M = Omega / (R T) * 2 Omega E / (9 (1 - nu))` (m^3/mol) of
    /// stress-induced diffusion at temperature `temp` (K): the particle diffusivity is
    /// `D (1 + theta_M (c - c_0))` (PyBaMM, Ai 2020 eq. 12).
    pub fn stress_diffusion_coefficient(&self, temp: f64) -> f64 {
        let omega = self.partial_molar_volume;
        omega / (super::GAS_CONSTANT * temp) * 2.0 * omega * self.youngs_modulus / (9.0 * (1.0 - self.poisson_ratio))
    }

    /// Tangential stress (Pa) at the particle surface, `Omega E (c_av - c_surf) / (3 (1 - nu))`
    /// for r-averaged and surface concentrations `c_av`, `c_surf` (mol/m^3) (the radial
    /// stress there is zero) (PyBaMM, Ai 2020 eq. 8 at r = R).
    pub fn surface_tangential_stress(&self, c_av: f64, c_surf: f64) -> f64 {
        self.partial_molar_volume * self.youngs_modulus * (c_av - c_surf) / (3.0 * (1.0 - self.poisson_ratio))
    }

    fn field_mut(&mut self, name: &str) -> Option<&mut f64> {
        Some(match name {
            "proportional_term" => &mut self.proportional_term,
            "exponential_term" => &mut self.exponential_term,
            "critical_stress" => &mut self.critical_stress,
            "partial_molar_volume" => &mut self.partial_molar_volume,
            "youngs_modulus" => &mut self.youngs_modulus,
            "poisson_ratio" => &mut self.poisson_ratio,
            "reference_concentration" => &mut self.reference_concentration,
            "reaction_factor" => &mut self.reaction_factor,
            "current_rate" => &mut self.current_rate,
            _ => return None,
        })
    }
}

impl Lam {
    /// Checks every field; the error names it (`lam.SIDE.NAME`) and its value.
    pub fn validate(&self) -> Result<(), Error> {
        self.negative.validate("negative")?;
        self.positive.validate("positive")
    }

    /// The field named `name` (after `lam.`, e.g. `negative.critical_stress`), for
    /// `--set lam.negative.critical_stress=VALUE`.
    pub(super) fn field_mut(&mut self, name: &str) -> Option<&mut f64> {
        let (side, field) = name.split_once('.')?;
        match side {
            "negative" => self.negative.field_mut(field),
            "positive" => self.positive.field_mut(field),
            _ => None,
        }
    }
}

#[cfg(test)]
mod tests {
    #[test]
    fn bad_lam_values_name_the_field() {
        let mut p = crate::params::chen2020();
        p.set("lam.positive.poisson_ratio", 0.7).unwrap();
        let e = p.validate().unwrap_err().to_string();
        assert!(e.contains("`lam.positive.poisson_ratio`") && e.contains("0.7"), "{e}");
        assert!(p.set("lam.negative.critical_stres", 1.0).is_err());
        assert!(p.set("lam.middle.critical_stress", 1.0).is_err());
        p.set("lam.negative.critical_stress", 5e7).unwrap();
        assert_eq!(p.get("lam.negative.critical_stress").unwrap(), 5e7);
    }
}
