//! The library of candidate missing physics: each with the residual signature it leaves,
//! the regressors that screen for that signature, and how to add it to a model.

use serde::Serialize;

use super::features::Features;
use super::stats::least_squares;
use crate::data::Recording;
use crate::models::ModelKind;
use crate::params::ParameterSet;
use crate::problem::fitting::{FitParameter, ModelSpec};

/// A candidate missing effect.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Candidate {
    SeriesResistance,
    Electrolyte,
    Thermal,
    SolidDiffusion,
    Stoichiometry,
    RcDynamics,
    Hysteresis,
}

/// A candidate added to a model: the model to build, its base parameters and the extra
/// parameters to fit.
#[derive(Clone, Debug)]
pub struct Augmentation {
    pub spec: ModelSpec,
    pub base: ParameterSet,
    pub extra: Vec<FitParameter>,
    /// What changed, in words (e.g. "SPM -> SPMe").
    pub change: String,
}

impl Candidate {
    pub const ALL: [Candidate; 7] = [
        Candidate::SeriesResistance,
        Candidate::Electrolyte,
        Candidate::Thermal,
        Candidate::SolidDiffusion,
        Candidate::Stoichiometry,
        Candidate::RcDynamics,
        Candidate::Hysteresis,
    ];

    /// Short name.
    pub fn name(self) -> &'static str {
        match self {
            Candidate::SeriesResistance => "series/contact resistance",
            Candidate::Electrolyte => "electrolyte transport",
            Candidate::Thermal => "thermal (self-heating)",
            Candidate::SolidDiffusion => "solid-diffusion limitation",
            Candidate::Stoichiometry => "capacity/stoichiometry offset",
            Candidate::RcDynamics => "RC / double-layer dynamics",
            Candidate::Hysteresis => "OCV hysteresis",
        }
    }

    /// The residual signature this effect leaves when it is missing from the model.
    pub fn signature(self) -> &'static str {
        match self {
            Candidate::SeriesResistance => {
                "an instantaneous voltage step at every current step, proportional to the current change, constant while the current is"
            }
            Candidate::Electrolyte => {
                "polarisation that grows with rate and relaxes over tens of seconds to minutes in rests (an SPM used where SPMe/DFN is needed)"
            }
            Candidate::Thermal => {
                "a residual that drifts as the cell self-heats at high rate: correlated with the temperature rise (or the accumulated I²), faster kinetics and diffusion late in a discharge"
            }
            Candidate::SolidDiffusion => {
                "an extra drop towards the end of a high-rate discharge and slow (hours) relaxation: refit particle diffusivities"
            }
            Candidate::Stoichiometry => {
                "a residual that grows with discharged capacity and persists at rest (loss of lithium inventory or active material): refit initial concentrations"
            }
            Candidate::RcDynamics => {
                "sub-second-to-seconds transients after current steps that settle to a constant offset under load and decay in rests: a series RC element"
            }
            Candidate::Hysteresis => {
                "an offset at rest whose sign follows the direction of the last current (charge vs discharge), not its size: one-state OCV hysteresis"
            }
        }
    }

    /// Regressors whose fit to the residual screens for this signature.
    pub fn regressors(self, rec: &Recording, f: &Features, q_nominal: f64) -> Vec<Vec<f64>> {
        let i = &rec.current;
        let lp = |tau: f64| Features::low_pass(rec, i, tau);
        match self {
            Candidate::SeriesResistance => vec![i.clone()],
            Candidate::Electrolyte => vec![i.clone(), lp(60.0)],
            Candidate::RcDynamics => vec![lp(2.0), lp(10.0)],
            Candidate::Thermal => {
                let rise = match &f.temperature_rise {
                    Some(t) => t.clone(),
                    None => Features::low_pass(rec, &i.iter().map(|v| v * v).collect::<Vec<_>>(), 1000.0),
                };
                let with_current = rise.iter().zip(i).map(|(t, i)| t * i).collect();
                vec![rise, with_current]
            }
            Candidate::SolidDiffusion => vec![lp(1000.0), i.iter().zip(&f.capacity).map(|(i, q)| i * q).collect()],
            Candidate::Stoichiometry => vec![f.capacity.clone(), f.capacity.iter().map(|q| q * q).collect()],
            Candidate::Hysteresis => vec![Features::hysteresis_state(rec, 10.0, q_nominal)],
        }
    }

    /// Screening score: `R²` of the residual on this candidate's regressors (with an
    /// intercept) over the points in `use_point`.
    pub fn screen(self, rec: &Recording, f: &Features, residual: &[f64], use_point: &[bool], q_nominal: f64) -> f64 {
        let idx: Vec<usize> = (0..residual.len()).filter(|&k| use_point[k]).collect();
        let mut cols = vec![vec![1.0; idx.len()]];
        cols.extend(self.regressors(rec, f, q_nominal).iter().map(|c| idx.iter().map(|&k| c[k]).collect::<Vec<f64>>()));
        let y: Vec<f64> = idx.iter().map(|&k| residual[k]).collect();
        // Drop regressors that are constant or collinear (e.g. no rests) one by one.
        while cols.len() > 1 {
            if let Some((_, r2)) = least_squares(&cols, &y) {
                return r2.max(0.0);
            }
            cols.pop();
        }
        0.0
    }

    /// The model with this effect added, or `None` when the model already has it or it
    /// cannot be added (e.g. electrolyte transport to a DFN). `fitted` lists the paths the
    /// baseline already fits; a candidate whose parameters are all among them is skipped.
    pub fn augment(self, spec: &ModelSpec, base: &ParameterSet, rec: &Recording, fitted: &[String]) -> Option<Augmentation> {
        let mut spec = *spec;
        let mut p = base.clone();
        // Whether the model itself changes (a submodel or the model kind), not only values.
        let structural = match self {
            Candidate::SeriesResistance => !spec.submodels.contact_resistance,
            Candidate::SolidDiffusion | Candidate::Stoichiometry => false,
            _ => true,
        };
        let (extra, change) = match self {
            Candidate::SeriesResistance => {
                let on = spec.submodels.contact_resistance;
                spec.submodels.contact_resistance = true;
                let r0 = if on { p.cell.contact_resistance.max(1e-4) } else { 1e-3 };
                (vec![FitParameter::linear("cell.contact_resistance", r0, 0.0, 0.2)], "contact-resistance submodel on".to_string())
            }
            Candidate::Electrolyte => {
                let next = match spec.kind {
                    ModelKind::Spm => ModelKind::Spme,
                    ModelKind::Spme => ModelKind::Dfn,
                    ModelKind::Dfn => return None,
                };
                let change = format!("{} -> {next}", spec.kind);
                spec.kind = next;
                (Vec::new(), change)
            }
            Candidate::Thermal => {
                if spec.submodels.thermal {
                    return None;
                }
                spec.submodels.thermal = true;
                if let Some(t) = rec.temperature.as_ref() {
                    p.thermal.initial_temperature = t[0];
                }
                let h = p.thermal.heat_transfer_coefficient.clamp(0.1, 1000.0);
                (vec![FitParameter::log("thermal.heat_transfer_coefficient", h, 0.1, 1000.0)], "lumped thermal submodel on".to_string())
            }
            Candidate::SolidDiffusion => {
                let d = |path: &str, v: f64| FitParameter::log(path, v, v / 100.0, v * 100.0);
                (
                    vec![d("negative.diffusivity", p.negative.diffusivity), d("positive.diffusivity", p.positive.diffusivity)],
                    "particle diffusivities refitted".to_string(),
                )
            }
            Candidate::Stoichiometry => {
                let c = |path: &str, c0: f64, cmax: f64| {
                    FitParameter::linear(path, c0, (0.8 * c0).max(0.02 * cmax), (1.2 * c0).min(0.98 * cmax))
                };
                (
                    vec![
                        c("negative.initial_concentration", p.negative.initial_concentration, p.negative.max_concentration),
                        c("positive.initial_concentration", p.positive.initial_concentration, p.positive.max_concentration),
                    ],
                    "initial electrode concentrations refitted".to_string(),
                )
            }
            Candidate::RcDynamics => {
                if spec.submodels.rc {
                    return None;
                }
                spec.submodels.rc = true;
                (
                    vec![
                        FitParameter::linear("cell.rc_resistance", 2e-3, 0.0, 0.1),
                        FitParameter::log("cell.rc_capacitance", 1000.0, 1.0, 1e6),
                    ],
                    "series RC submodel on".to_string(),
                )
            }
            Candidate::Hysteresis => {
                if spec.submodels.hysteresis {
                    return None;
                }
                spec.submodels.hysteresis = true;
                (
                    vec![
                        FitParameter::linear("cell.hysteresis_voltage", 5e-3, 0.0, 0.1),
                        FitParameter::log("cell.hysteresis_rate", 10.0, 0.5, 500.0),
                        FitParameter::linear("cell.hysteresis_initial", 0.0, -1.0, 1.0),
                    ],
                    "OCV hysteresis submodel on".to_string(),
                )
            }
        };
        let extra: Vec<FitParameter> = extra.into_iter().filter(|e| !fitted.contains(&e.path)).collect();
        if extra.is_empty() && !structural {
            return None;
        }
        Some(Augmentation { spec, base: p, extra, change })
    }
}
