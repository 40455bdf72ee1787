//! Which parameters of the switchable submodels a model reads. A `--set` (or a fitted
//! parameter) that the chosen submodels never read changes nothing, silently: setting
//! `sei.kinetic_rate_constant` under the "reaction limited" SEI law, say, whose rate is
//! `sei.exchange_current`. The studies refuse such a parameter and say what would read it.
//!
//! Only what is certain is claimed: a parameter of a submodel that is off, or one that only
//! some laws of a submodel read. Everything else (including what a submodel reads under
//! every law) counts as read. `tests/suite/unread_parameters.rs` checks every claim: the
//! parameter changed leaves the model's equations bit for bit the same.

use serde::Serialize;

use super::{LamModel, ParticleSize, PlatingModel, SeiModel};
use crate::models::Submodels;

/// SEI parameters that only some growth laws read (every other `sei.*` is read by all).
const SEI_LAW_FIELDS: [(&str, &[SeiModel]); 10] = {
    use SeiModel::*;
    [
        ("exchange_current", &[ReactionLimited]),
        ("open_circuit_potential", &[ReactionLimited, ElectronMigrationLimited, EcReactionLimited]),
        ("solvent_diffusivity", &[SolventDiffusionLimited]),
        ("solvent_concentration", &[SolventDiffusionLimited]),
        ("electron_conductivity", &[ElectronMigrationLimited]),
        ("interstitial_diffusivity", &[InterstitialDiffusionLimited]),
        ("interstitial_concentration", &[InterstitialDiffusionLimited]),
        ("ec_concentration", &[EcReactionLimited]),
        ("ec_diffusivity", &[EcReactionLimited]),
        ("kinetic_rate_constant", &[EcReactionLimited]),
    ]
};

/// LAM parameters of the particle mechanics, read only by the stress-driven laws.
const LAM_STRESS_FIELDS: [&str; 7] =
    ["proportional_term", "exponential_term", "critical_stress", "partial_molar_volume", "youngs_modulus", "poisson_ratio", "reference_concentration"];

/// Why a model with `submodels` never reads the parameter at dotted `path`, or `None` when it
/// may (or `path` belongs to no switchable submodel).
pub fn unread_reason(submodels: &Submodels, path: &str) -> Option<String> {
    let s = submodels;
    let (group, name) = path.split_once('.')?;
    let off = |what: &str, key: &str| Some(format!("the {what} submodel is off (`{key}` in the model's submodels turns it on)"));
    match (group, name) {
        ("cell", "contact_resistance") if !s.contact_resistance => off("contact-resistance", "contact_resistance = true"),
        ("cell", "rc_resistance" | "rc_capacitance") if !s.rc => off("RC", "rc = true"),
        ("cell", "hysteresis_voltage" | "hysteresis_rate" | "hysteresis_initial") if !s.hysteresis => off("hysteresis", "hysteresis = true"),
        ("cell", "leakage_current") if !s.leak => off("leak", "leak = true"),
        ("cell", "voltage_offset") if !s.voltage_offset => off("voltage-offset", "voltage_offset = true"),
        ("cell", "voltage_gain") if !s.voltage_gain => off("voltage-gain", "voltage_gain = true"),
        ("cell", "current_gain") if !s.current_gain => off("current-gain", "current_gain = true"),
        // The lumped thermal model's heat balance (the isothermal model reads the ambient and
        // reference temperatures, and the entropic change away from the reference).
        ("thermal", "heat_transfer_coefficient" | "cooling_area" | "cell_volume" | "negative_collector_heat_capacity" | "positive_collector_heat_capacity")
        | ("negative" | "separator" | "positive", "volumetric_heat_capacity")
            if !s.thermal =>
        {
            off("thermal", "thermal = true")
        }
        ("negative" | "positive", "radius_relative_std") if s.particle_size == ParticleSize::Single => {
            off("particle-size distribution", "particle_size = \"distribution\"")
        }
        // Partially reversible plating reads the SEI's initial thickness with the SEI off
        // (PyBaMM's "constant" SEI).
        ("sei", "initial_thickness") if s.plating == PlatingModel::PartiallyReversible => None,
        ("sei", _) if s.sei == SeiModel::None => off("SEI", "sei = \"reaction limited\" or another law"),
        ("sei", field) => {
            let (_, laws) = SEI_LAW_FIELDS.iter().find(|(f, _)| *f == field)?;
            (!laws.contains(&s.sei)).then(|| law_reason("SEI", s.sei, laws))
        }
        ("lam", _) if s.lam == LamModel::None => off("loss-of-active-material", "lam = \"stress-driven\" or another law"),
        ("lam", rest) => {
            let (side, field) = rest.split_once('.')?;
            match field {
                f if LAM_STRESS_FIELDS.contains(&f) && !s.lam.stress() => {
                    Some(law_reason("LAM", s.lam, &[LamModel::StressDriven, LamModel::StressAndReactionDriven]))
                }
                "reaction_factor" if !s.lam.reaction() => Some(law_reason("LAM", s.lam, &[LamModel::ReactionDriven, LamModel::StressAndReactionDriven])),
                "reaction_factor" if side == "positive" => Some("reaction-driven LAM follows the SEI, which grows on the negative electrode only".into()),
                "current_rate" if !s.lam.current() => Some(law_reason("LAM", s.lam, &[LamModel::CurrentDriven])),
                _ => None,
            }
        }
        ("plating", _) if s.plating == PlatingModel::None => off("lithium-plating", "plating = \"irreversible\" or another law"),
        ("plating", "dead_lithium_decay_constant") if s.plating != PlatingModel::PartiallyReversible => {
            Some(law_reason("plating", s.plating, &[PlatingModel::PartiallyReversible]))
        }
        _ => None,
    }
}

/// Refuses the first of `settings` (each a field name for the error, e.g. `--set sei.x` or
/// `parameters[2]`, and the parameter's dotted path) that a model with `submodels` never
/// reads: setting or fitting it would change nothing.
pub fn refuse_unread<'a>(submodels: &Submodels, settings: impl IntoIterator<Item = (String, &'a str)>) -> Result<(), crate::error::Error> {
    for (field, path) in settings {
        if let Some(why) = unread_reason(submodels, path) {
            return Err(crate::error::Error::InvalidSetting { field, reason: format!("the model does not read {path}, so it would change nothing: {why}") });
        }
    }
    Ok(())
}

/// [`refuse_unread`] for `--set` overrides.
pub fn refuse_unread_overrides(submodels: &Submodels, overrides: &[crate::params::Override]) -> Result<(), crate::error::Error> {
    refuse_unread(submodels, overrides.iter().map(|o| (format!("--set {}", o.path), o.path.as_str())))
}

/// "the SEI law is \"reaction limited\"; only \"ec reaction limited\" reads it".
fn law_reason<T: Serialize>(what: &str, law: T, readers: &[T]) -> String {
    let name = |l: &T| serde_json::to_string(l).unwrap_or_default();
    let readers: Vec<String> = readers.iter().map(name).collect();
    format!("the {what} law is {}; only {} read{} it", name(&law), readers.join(" or "), if readers.len() == 1 { "s" } else { "" })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_the_law_that_would_read_it() {
        let sub = Submodels { sei: SeiModel::ReactionLimited, ..Default::default() };
        let why = unread_reason(&sub, "sei.kinetic_rate_constant").unwrap();
        assert_eq!(why, "the SEI law is \"reaction limited\"; only \"ec reaction limited\" reads it");
        assert_eq!(unread_reason(&sub, "sei.exchange_current"), None);
        assert_eq!(unread_reason(&sub, "sei.partial_molar_volume"), None);
        assert!(unread_reason(&Submodels::default(), "sei.exchange_current").unwrap().contains("SEI submodel is off"));
        assert!(unread_reason(&Submodels::default(), "cell.rc_resistance").unwrap().contains("rc = true"));
        assert_eq!(unread_reason(&Submodels::default(), "positive.thickness"), None);
    }
}
