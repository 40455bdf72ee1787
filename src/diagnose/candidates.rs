//! The library of candidate explanations of a mismatch: each with the residual signature it
//! leaves, when a recording can identify it, how to add it to a model, and the range of
//! fitted values that is physically plausible.
//!
//! Two classes: **missing physics** (a submodel or a richer model the user's model lacks)
//! and **parameter mismatch** (a parameter the user's model already has, refitted).

use serde::Serialize;

use super::ageing::{self, Load};
use super::features::Features;
use crate::data::Recording;
use crate::models::ModelKind;
use crate::params::ParameterSet;
use crate::problem::fitting::{FitParameter, INITIAL_SOC, ModelSpec};
use crate::problem::history::{HISTORY_CURRENT, HISTORY_DURATION};

/// A candidate explanation.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Candidate {
    SeriesResistance,
    Electrolyte,
    ElectrolyteComposite,
    ElectrolyteTransport,
    Kinetics,
    SolidDiffusion,
    LithiumInventory,
    ActiveMaterial,
    Thermal,
    RcDynamics,
    Hysteresis,
    SeiGrowth,
    SeiGrowthSeries,
    LithiumPlating,
    LithiumPlatingPartial,
    ActiveMaterialGrowth,
    ActiveMaterialThroughput,
    Leak,
    VoltageOffset,
    VoltageGain,
    UnrelaxedStart,
}

/// Missing physics or a parameter the model has but with the wrong value.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Class {
    MissingPhysics,
    ParameterMismatch,
    /// How the recording was made, not the cell (it began part-way through a test).
    RecordingCondition,
}

/// A candidate added to a model: the model to build, its base parameters, the parameters to
/// fit in addition to (or instead of) the user's, and the honest parameter count.
#[derive(Clone, Debug)]
pub struct Augmentation {
    pub spec: ModelSpec,
    pub base: ParameterSet,
    pub extra: Vec<FitParameter>,
    /// Fitted paths of the user's model this candidate frees differently (and drops).
    pub replaces: Vec<String>,
    /// Fixed parameters a structural change brings in (e.g. the electrolyte's transport
    /// properties when an SPM becomes an SPMe): counted in the information criteria.
    pub structural_parameters: usize,
    /// What changed, in words (e.g. "SPM -> SPMe").
    pub change: String,
    /// Its parameters are rates known only to within decades (ageing rates): each is screened
    /// a decade apart across its range before the fit ([`super::refit::Starts::screen`]).
    pub screened: bool,
}

/// Multiplicative range (-) over which a parameter that the model already has is refitted.
const MISMATCH_RANGE: f64 = 30.0;

/// How far (K) the fitted ambient may lie from a recording's first temperature.
const AMBIENT_RANGE_K: f64 = 30.0;

/// Fixed parameters the DFN brings to an SPM: the electrolyte's diffusivity, conductivity,
/// transference number, thermodynamic factor, initial concentration, porosities and
/// tortuosity (7), and the two solid conductivities (2); to an SPMe, the latter two.
const SPM_TO_DFN_FIXED: usize = 9;
const SPME_TO_DFN_FIXED: usize = 2;

/// The leak candidate's search range and plausible size, as C-rates (1/h): a sensor offset
/// or a soft short beyond C/100 would be seen on any cycler.
const LEAK_SEARCH_C_RATE: f64 = 0.02;
const LEAK_PLAUSIBLE_C_RATE: f64 = 0.01;

/// The unrelaxed-start candidate's search: a load of up to 3C either way (1/h), held for 10 s
/// to 2 h (from 10 min) before the first recorded point.
const HISTORY_C_RATE: f64 = 3.0;
const HISTORY_START_S: f64 = 600.0;
const HISTORY_RANGE_S: (f64, f64) = (10.0, 7200.0);

/// The voltage-offset candidate's search range and plausible size (V).
const VOLTAGE_OFFSET_SEARCH: f64 = 0.05;
const VOLTAGE_OFFSET_PLAUSIBLE: f64 = 0.02;

/// The voltage-gain candidate's search range and plausible size (-): 0.5 % reads 21 mV off
/// at 4.2 V, as far as the offset's plausible 20 mV.
const VOLTAGE_GAIN_SEARCH: f64 = 0.02;
const VOLTAGE_GAIN_PLAUSIBLE: f64 = 0.005;

/// The hysteresis candidate's starting decay rate (-): the state moves `1 - e^-1` of the way
/// to a branch per tenth of the capacity passed.
const HYSTERESIS_START_RATE: f64 = 10.0;

/// How far into each branch (of ±1) a load must drive the unit hysteresis state for the
/// recording to show hysteresis without rests after both directions.
const HYSTERESIS_BRANCH: f64 = 0.5;

impl Candidate {
    pub const ALL: [Candidate; 21] = [
        Candidate::SeriesResistance,
        Candidate::Electrolyte,
        Candidate::ElectrolyteComposite,
        Candidate::ElectrolyteTransport,
        Candidate::Kinetics,
        Candidate::SolidDiffusion,
        Candidate::LithiumInventory,
        Candidate::ActiveMaterial,
        Candidate::Thermal,
        Candidate::RcDynamics,
        Candidate::Hysteresis,
        Candidate::SeiGrowth,
        Candidate::SeiGrowthSeries,
        Candidate::LithiumPlating,
        Candidate::LithiumPlatingPartial,
        Candidate::ActiveMaterialGrowth,
        Candidate::ActiveMaterialThroughput,
        Candidate::Leak,
        Candidate::VoltageOffset,
        Candidate::VoltageGain,
        Candidate::UnrelaxedStart,
    ];

    /// An ageing candidate: it changes the cell from cycle to cycle ([`ageing`]).
    pub fn is_ageing(self) -> bool {
        matches!(self, Candidate::SeiGrowth | Candidate::SeiGrowthSeries | Candidate::LithiumPlating | Candidate::LithiumPlatingPartial | Candidate::ActiveMaterialGrowth | Candidate::ActiveMaterialThroughput)
    }

    /// Short name, as the verdict uses it.
    pub fn name(self) -> &'static str {
        match self {
            Candidate::SeriesResistance => "series/contact resistance",
            Candidate::Electrolyte => "electrolyte transport",
            Candidate::ElectrolyteComposite => "electrolyte transport (composite SPMe)",
            Candidate::ElectrolyteTransport => "electrolyte transport properties (diffusivity, conductivity)",
            Candidate::Kinetics => "charge-transfer kinetics (exchange-current density)",
            Candidate::SolidDiffusion => "solid (particle) diffusivity",
            Candidate::LithiumInventory => "loss of lithium inventory (stoichiometry offset)",
            Candidate::ActiveMaterial => "loss of active material (electrode capacity)",
            Candidate::Thermal => "thermal (self-heating, temperature dependence)",
            Candidate::RcDynamics => "RC / double-layer dynamics",
            Candidate::Hysteresis => "OCV hysteresis",
            Candidate::SeiGrowth => "SEI growth (lithium lost as the film grows, in cycling and in storage)",
            Candidate::SeiGrowthSeries => "SEI growth, reaction and transport in series (lithium lost as the film grows, more slowly as it thickens)",
            Candidate::LithiumPlating => "lithium plating (lithium lost to irreversible plating during the charges)",
            Candidate::LithiumPlatingPartial => "lithium plating, partially reversible (plated lithium strips back after the charges and part of it turns dead)",
            Candidate::ActiveMaterialGrowth => "progressive loss of active material (stress-driven, over the cycles)",
            Candidate::ActiveMaterialThroughput => "progressive loss of active material (throughput-driven, over the cycles)",
            Candidate::Leak => "self-discharge or current offset (a leak current the cycler does not record: soft short or sensor bias)",
            Candidate::VoltageOffset => "voltage offset (the voltage channel's calibration, or an open-circuit potential shifted against the set's)",
            Candidate::VoltageGain => "voltage gain (the voltage channel's calibration reads a share of the voltage high or low)",
            Candidate::UnrelaxedStart => "an unrelaxed start (a load just before the first recorded point: the recording began part-way through a test)",
        }
    }

    pub fn class(self) -> Class {
        match self {
            Candidate::SeriesResistance
            | Candidate::Electrolyte
            | Candidate::ElectrolyteComposite
            | Candidate::Thermal
            | Candidate::RcDynamics
            | Candidate::Hysteresis
            | Candidate::SeiGrowth
            | Candidate::SeiGrowthSeries
            | Candidate::LithiumPlating
            | Candidate::LithiumPlatingPartial
            | Candidate::ActiveMaterialGrowth
            | Candidate::ActiveMaterialThroughput
            | Candidate::Leak
            | Candidate::VoltageOffset
            | Candidate::VoltageGain => {
                Class::MissingPhysics
            }
            Candidate::UnrelaxedStart => Class::RecordingCondition,
            _ => Class::ParameterMismatch,
        }
    }

    /// The residual signature this effect leaves when it is missing or mis-set.
    pub fn signature(self) -> &'static str {
        match self {
            Candidate::SeriesResistance => "an instantaneous voltage step at every current step, proportional to the current change and the same at every state of charge",
            Candidate::Electrolyte => "polarisation that grows with rate and relaxes over tens of seconds to minutes in rests (an SPM or SPMe used where the DFN's electrolyte is needed)",
            Candidate::ElectrolyteComposite => "as electrolyte transport, with the SPMe's composite (first-order) electrolyte instead of the DFN's",
            Candidate::ElectrolyteTransport => "rate-dependent polarisation that builds over the first minutes of a load and relaxes in rests, with the electrolyte model already present",
            Candidate::Kinetics => "an instantaneous overpotential at current steps that is not proportional to the current (asinh) and grows towards the ends of the stoichiometry range",
            Candidate::SolidDiffusion => "an extra drop late in a high-rate discharge and slow (many minutes) relaxation in rests",
            Candidate::LithiumInventory => "the end of discharge (the knee) arrives earlier or later and the OCV is shifted along the capacity axis; persists at rest",
            Candidate::ActiveMaterial => "one electrode's OCV features are compressed along the capacity axis (less capacity), with a shifted knee; persists at rest",
            Candidate::Thermal => "losses that fall as the cell warms under load (correlated with the recorded temperature rise or with the accumulated I²)",
            Candidate::RcDynamics => "transients of seconds after current steps that settle to an offset under load and decay in rests",
            Candidate::Hysteresis => "an offset at rest whose sign follows the direction of the last current (charge vs discharge), not its size",
            Candidate::SeiGrowthSeries => "as reaction-limited SEI growth, but the lithium lost per cycle (or per hour of storage) falls as the film thickens and transport through it takes over (towards growth with the square root of time, whatever the potential)",
            Candidate::SeiGrowth => "capacity and the end-of-discharge knee drift from cycle to cycle, or across a storage rest, as lithium is consumed (a fixed stoichiometry offset does not drift), with a slowly growing film resistance",
            Candidate::LithiumPlating => "capacity and the knee drift from cycle to cycle as lithium plates while the negative electrode's potential is low (late in fast charges), with no film resistance; grows steeply with the charge rate and at low temperature",
            Candidate::LithiumPlatingPartial => "as irreversible plating, but the plated lithium strips back in the rest or discharge after each charge (a voltage plateau there), and only the part that turned dead is lost from cycle to cycle",
            Candidate::ActiveMaterialGrowth => "one electrode's OCV features are compressed more from cycle to cycle (its capacity shrinks as it cycles), faster where the current stresses its particles most",
            Candidate::ActiveMaterialThroughput => "one electrode's OCV features are compressed more from cycle to cycle (its capacity shrinks as it cycles), in proportion to the charge passed in either direction",
            Candidate::VoltageOffset => "a constant difference, the same under load and at rest, at every state of charge and current",
            Candidate::VoltageGain => "a difference in proportion to the voltage itself: the same share under load and at rest, larger at the top of the voltage window than at the bottom",
            Candidate::UnrelaxedStart => "a transient at the start only, fading over minutes whatever the load, as the particles and electrolyte relax from a load the recording did not hold",
            Candidate::Leak => "the state of charge drifts at a constant rate whatever the load: the voltage keeps sliding in rests instead of settling, and the charge put back differs from the charge taken out by the leak times the time",
        }
    }

    /// The physically plausible range of the fitted values, in words (stated in the report).
    pub fn plausible_range(self) -> &'static str {
        match self {
            Candidate::SeriesResistance => "0.1 to 100 mOhm",
            Candidate::Electrolyte | Candidate::ElectrolyteComposite => "no fitted parameters",
            Candidate::ElectrolyteTransport | Candidate::Kinetics | Candidate::SolidDiffusion => "0.05 to 20 times the set's value, not on a search bound",
            Candidate::LithiumInventory => "up to 40 % of the cyclable lithium lost (or gained)",
            Candidate::ActiveMaterial => "up to 50 % of an electrode's active material lost",
            Candidate::Thermal => "heat-transfer coefficient 1 to 500 W/(m^2 K)",
            Candidate::RcDynamics => "time constant R C of 1 ms to 30 s (longer is transport, not an interface)",
            Candidate::Hysteresis => "half-width up to 50 mV",
            Candidate::SeiGrowth => "SEI exchange current 0.001 to 1000 times the set's",
            Candidate::SeiGrowthSeries => "SEI rate constant 0.001 to 1000 times the set's; EC diffusivity up to the one whose transport limit takes 50 % of the negative electrode's lithium over the recording",
            Candidate::LithiumPlating => "plating rate constant 0.001 to 1000 times the set's",
            Candidate::LithiumPlatingPartial => "plating rate constant 0.001 to 1000 times the set's, dead-lithium decay constant 1e-8 to 1e-2 1/s",
            Candidate::ActiveMaterialGrowth => "up to 50 % of an electrode's active material lost over the recording (steady-profile estimate)",
            Candidate::ActiveMaterialThroughput => "up to 50 % of an electrode's active material lost over the recording",
            Candidate::Leak => "up to C/100 either way (a leak or a sensor offset of 1 % of the 1C current)",
            Candidate::VoltageOffset => "up to 20 mV either way",
            Candidate::VoltageGain => "up to 0.5 % either way (21 mV at 4.2 V)",
            Candidate::UnrelaxedStart => "a load of up to 3C either way, held 10 s to 2 h before the first point",
        }
    }

    /// The experiment that separates this candidate from `other` when both fit equally on
    /// this recording, whose features `f` say what it already holds (an experiment it already
    /// contains did not separate them, so a stronger one is named).
    pub fn separating_experiment(self, other: Candidate, f: &Features) -> String {
        use Candidate::*;
        let has_rates = f.distinct_rates >= 2;
        match (self, other) {
            (SeriesResistance, Kinetics) | (Kinetics, SeriesResistance) if has_rates => format!(
                "pulses at rates well above this recording's (it has {} load levels, and their overpotentials still fit a straight line in the current) and near both ends of the state of charge, where kinetics grow and a resistance does not",
                f.distinct_rates
            ),
            (SeriesResistance, Kinetics) | (Kinetics, SeriesResistance) => {
                "current pulses at two or more rates (kinetics is non-linear in current, a resistance is not) across the state of charge".into()
            }
            (SeriesResistance, RcDynamics) | (RcDynamics, SeriesResistance) => "sampling faster than 0.1 s around current steps, or an impedance spectrum".into(),
            (LithiumInventory, ActiveMaterial) | (ActiveMaterial, LithiumInventory) => {
                "a slow (C/20) charge and discharge over the full window, read by differential voltage analysis".into()
            }
            (LithiumPlating, LithiumPlatingPartial) | (LithiumPlatingPartial, LithiumPlating) => {
                "a rest of an hour after a fast charge, sampled every few seconds (reversible plated lithium strips back there, a voltage plateau irreversible plating lacks)".into()
            }
            (LithiumPlating | LithiumPlatingPartial, SeiGrowth | SeiGrowthSeries) | (SeiGrowth | SeiGrowthSeries, LithiumPlating | LithiumPlatingPartial) => "cycles at a second charge rate, or a storage period at high state of charge (both are cathodic side reactions on the same potential difference: plating grows steeply with the charge rate and at low temperature, SEI growth with time at high state of charge)".into(),
            (SeiGrowth, SeiGrowthSeries) | (SeiGrowthSeries, SeiGrowth) => {
                "more cycles, or a storage period of days between two slow cycles (a film limited by transport grows more slowly as it thickens, a reaction-limited one does not)".into()
            }
            (ActiveMaterialGrowth, ActiveMaterialThroughput) | (ActiveMaterialThroughput, ActiveMaterialGrowth) => {
                "cycles at a second rate (stress-driven loss per charge passed grows with the current, throughput-driven loss does not), or a cycle whose charge and discharge differ in rate".into()
            }
            (ActiveMaterialGrowth | ActiveMaterialThroughput, LithiumInventory | SeiGrowth | SeiGrowthSeries | LithiumPlating | LithiumPlatingPartial | ActiveMaterial)
            | (LithiumInventory | SeiGrowth | SeiGrowthSeries | LithiumPlating | LithiumPlatingPartial | ActiveMaterial, ActiveMaterialGrowth | ActiveMaterialThroughput) => {
                "a slow (C/20) cycle at the start and the end, read by differential voltage analysis".into()
            }
            (VoltageOffset, VoltageGain) | (VoltageGain, VoltageOffset) => {
                "the voltage channel checked against a reference at the top and at the bottom of the voltage window (an offset reads the same at both, a gain in proportion to the voltage)".into()
            }
            (VoltageGain, _) | (_, VoltageGain) => "a slow (C/20) charge and discharge over the full window with the voltage channel checked against a reference at its top and bottom: a shifted stoichiometry moves the OCV's features along the capacity axis, a gain scales the whole curve".into(),
            (VoltageOffset, _) | (_, VoltageOffset) => "a slow (C/20) charge and discharge over the full window with the voltage channel checked against a reference: a shifted stoichiometry moves the OCV's features along the capacity axis, an offset moves the whole curve up or down".into(),
            (Leak, _) | (_, Leak) => "a rest of several hours at a middle state of charge, then a slow charge and discharge (a leak keeps discharging the cell at rest and the charge balance does not close; lost lithium or material does neither)".into(),
            (Thermal, _) | (_, Thermal) => "the same protocol at a second ambient temperature, with the cell temperature recorded".into(),
            _ if has_rates => format!(
                "the same cell at a rate well above this recording's highest (its {} load levels did not separate them), with a rest after charge and after discharge",
                f.distinct_rates
            ),
            _ => "the same cell at a second C-rate with a rest after charge and after discharge".into(),
        }
    }

    /// The candidate that makes this one's structural change with no fitted parameters, on
    /// a model of `kind`: this one at the set's values is that one.
    pub fn structural_alias(self, kind: ModelKind) -> Option<Candidate> {
        (self == Candidate::ElectrolyteTransport && kind == ModelKind::Spm).then_some(Candidate::Electrolyte)
    }

    /// Why the recording cannot identify this candidate, or `None` when it can; `q_nominal`
    /// is the cell's capacity (A h).
    pub fn not_identifiable(self, rec: &Recording, f: &Features, q_nominal: f64) -> Option<String> {
        match self {
            // Hysteresis is an offset whose sign follows the direction of the charge passed:
            // it is seen at rest after both directions, or, with one rest, when the load
            // itself drives the hysteresis state (at the candidate's starting rate) well into
            // both branches (a drive that charges and discharges).
            Candidate::Hysteresis if !(f.rests_after_charge > 0 && f.rests_after_discharge > 0) => {
                let h = Features::hysteresis_state(rec, HYSTERESIS_START_RATE, q_nominal);
                let (low, high) = h.iter().fold((0.0f64, 0.0f64), |(l, u), v| (l.min(*v), u.max(*v)));
                let both_branches = low <= -HYSTERESIS_BRANCH && high >= HYSTERESIS_BRANCH;
                (!(both_branches && f.rests_after_charge + f.rests_after_discharge > 0)).then(|| {
                    format!(
                        "needs rests after both charge and discharge, or a rest and a load that passes enough charge both ways to swing the hysteresis state past ±{HYSTERESIS_BRANCH} (this recording has {} and {} rests, the state spans {low:.2} to {high:.2})",
                        f.rests_after_charge, f.rests_after_discharge
                    )
                })
            }
            Candidate::Thermal if rec.temperature.is_none() && f.distinct_rates < 2 => {
                Some("needs a recorded temperature or loads at two or more rates".into())
            }
            // An overpotential is told from the open-circuit voltage by how the voltage moves
            // with the current at one state of charge: steps, or a load whose level changes
            // (e.g. the falling current of a constant-voltage hold).
            Candidate::SeriesResistance | Candidate::Kinetics | Candidate::RcDynamics if f.steps.is_empty() && f.distinct_rates < 2 => {
                Some("needs current steps or loads at two or more rates".into())
            }
            Candidate::SeiGrowth | Candidate::SeiGrowthSeries => ageing::too_short_for_sei(f),
            Candidate::LithiumPlating | Candidate::LithiumPlatingPartial | Candidate::ActiveMaterialGrowth | Candidate::ActiveMaterialThroughput => ageing::too_few_cycles(f),
            // In one uninterrupted run a leak only rescales the charge passed (a capacity or
            // stoichiometry change); a rest, or charge and discharge both, sets it apart.
            Candidate::Leak if f.rests_after_charge + f.rests_after_discharge == 0 && !(rec.current.iter().any(|i| *i > 0.0) && rec.current.iter().any(|i| *i < 0.0)) => {
                Some("needs a rest, or both charge and discharge (in one constant-direction run a leak is a change of capacity)".into())
            }
            _ => None,
        }
    }

    /// The model with this candidate added, or `None` when the model already has it or it
    /// cannot be added (e.g. electrolyte transport to a DFN). `fitted` lists the paths the
    /// user's model already fits; they stay fitted beside the candidate's. With a recorded
    /// first temperature in `load` the thermal candidate fits the ambient too (a cell need not
    /// start at the temperature of its room); the progressive LAM candidate's range follows
    /// its RMS current and duration.
    pub fn augment(self, spec: &ModelSpec, base: &ParameterSet, fitted: &[String], load: &Load) -> Option<Augmentation> {
        let mut spec = *spec;
        let mut p = base.clone();
        let mut aged = None;
        let around = |path: &str| {
            let v = p.get(path).ok().filter(|v| *v > 0.0)?;
            Some(FitParameter::log(path, v, v / MISMATCH_RANGE, v * MISMATCH_RANGE))
        };
        let mut replaces = Vec::new();
        let mut structural_parameters = 0;
        let (extra, change): (Vec<FitParameter>, String) = match self {
            Candidate::SeriesResistance => {
                let on = spec.submodels.contact_resistance;
                spec.submodels.contact_resistance = true;
                let r0 = if on { p.cell.contact_resistance.max(1e-4) } else { 2e-3 };
                (vec![FitParameter::linear("cell.contact_resistance", r0, 0.0, 0.2)], "contact-resistance submodel on".into())
            }
            Candidate::Electrolyte => {
                // The full electrolyte model: the SPMe is an approximation of the DFN that
                // loses accuracy exactly where electrolyte transport matters (high rates).
                let next = match spec.kind {
                    ModelKind::Spm | ModelKind::Spme => ModelKind::Dfn,
                    ModelKind::Dfn => return None,
                };
                structural_parameters = if spec.kind == ModelKind::Spm { SPM_TO_DFN_FIXED } else { SPME_TO_DFN_FIXED };
                let change = format!("{} -> {next}", spec.kind);
                spec.kind = next;
                (Vec::new(), change)
            }
            Candidate::ElectrolyteComposite => {
                if spec.kind != ModelKind::Spm {
                    return None;
                }
                spec.kind = ModelKind::Spme;
                structural_parameters = 7;
                (Vec::new(), "SPM -> SPMe".into())
            }
            Candidate::ElectrolyteTransport => {
                let factors = self.refitted_paths().iter().map(|p| around(p)).collect::<Option<_>>()?;
                // An SPM has no electrolyte whose properties could be off: the electrolyte
                // comes in (SPM -> DFN, its 9 fixed parameters counted) with its properties
                // refitted, one effect (an electrolyte that is not the set's, e.g. salt lost).
                if spec.kind == ModelKind::Spm {
                    structural_parameters = SPM_TO_DFN_FIXED;
                    spec.kind = ModelKind::Dfn;
                    (factors, "SPM -> DFN, electrolyte diffusivity and conductivity factors refitted".into())
                } else {
                    (factors, "electrolyte diffusivity and conductivity factors refitted".into())
                }
            }
            Candidate::SeiGrowth | Candidate::SeiGrowthSeries | Candidate::LithiumPlating | Candidate::LithiumPlatingPartial | Candidate::ActiveMaterialGrowth | Candidate::ActiveMaterialThroughput => {
                let (extra, fixed, change, changed_base) = ageing::augment(self, &mut spec, &p, load)?;
                (structural_parameters, aged) = (fixed, changed_base);
                (extra, change)
            }
            Candidate::Kinetics => (self.refitted_paths().iter().map(|p| around(p)).collect::<Option<_>>()?, "reaction rate constants of both electrodes refitted".into()),
            Candidate::SolidDiffusion => (self.refitted_paths().iter().map(|p| around(p)).collect::<Option<_>>()?, "particle diffusivities refitted".into()),
            Candidate::LithiumInventory => {
                let c = |path: &str, c0: f64, cmax: f64| FitParameter::linear(path, c0, 0.01 * cmax, 0.99 * cmax);
                replaces.push(INITIAL_SOC.to_string());
                (
                    vec![
                        c("negative.initial_concentration", p.negative.initial_concentration, p.negative.max_concentration),
                        c("positive.initial_concentration", p.positive.initial_concentration, p.positive.max_concentration),
                    ],
                    "initial electrode concentrations refitted independently (cyclable lithium free)".into(),
                )
            }
            Candidate::ActiveMaterial => {
                let a = |path: &str, eps: f64, porosity: f64| {
                    let hi = eps.min(1.0 - porosity - 1e-9);
                    FitParameter::log(path, 0.97 * hi, 0.4 * eps, hi)
                };
                (
                    vec![
                        a("negative.active_fraction", p.negative.active_fraction, p.negative.porosity),
                        a("positive.active_fraction", p.positive.active_fraction, p.positive.porosity),
                    ],
                    "active-material volume fractions of both electrodes refitted".into(),
                )
            }
            Candidate::Thermal => {
                if spec.submodels.thermal {
                    return None;
                }
                spec.submodels.thermal = true;
                // Heat capacity, cooling area and the activation energies enter as fixed values.
                structural_parameters = 3;
                let mut extra = vec![FitParameter::log("thermal.heat_transfer_coefficient", 10.0, 0.1, 1000.0)];
                let change = match load.start_temperature {
                    Some(t0) => {
                        extra.push(FitParameter::linear("thermal.ambient_temperature", t0, t0 - AMBIENT_RANGE_K, t0 + AMBIENT_RANGE_K));
                        "lumped thermal submodel on, ambient fitted to the recorded temperature"
                    }
                    None => "lumped thermal submodel on",
                };
                (extra, change.into())
            }
            Candidate::VoltageOffset => {
                if spec.submodels.voltage_offset {
                    return None;
                }
                spec.submodels.voltage_offset = true;
                (vec![FitParameter::linear("cell.voltage_offset", 0.0, -VOLTAGE_OFFSET_SEARCH, VOLTAGE_OFFSET_SEARCH)], "voltage-offset submodel on".into())
            }
            Candidate::VoltageGain => {
                if spec.submodels.voltage_gain {
                    return None;
                }
                spec.submodels.voltage_gain = true;
                (vec![FitParameter::linear("cell.voltage_gain", 0.0, -VOLTAGE_GAIN_SEARCH, VOLTAGE_GAIN_SEARCH)], "voltage-gain submodel on".into())
            }
            Candidate::UnrelaxedStart => {
                if fitted.iter().any(|f| f == HISTORY_CURRENT) {
                    return None;
                }
                let most = HISTORY_C_RATE * p.cell.nominal_capacity;
                (
                    vec![FitParameter::linear(HISTORY_CURRENT, 0.0, -most, most), FitParameter::log(HISTORY_DURATION, HISTORY_START_S, HISTORY_RANGE_S.0, HISTORY_RANGE_S.1)],
                    "a constant load before the first point fitted (its current and duration), from the rest state".into(),
                )
            }
            Candidate::Leak => {
                if spec.submodels.leak {
                    return None;
                }
                spec.submodels.leak = true;
                let most = LEAK_SEARCH_C_RATE * p.cell.nominal_capacity;
                (vec![FitParameter::linear("cell.leakage_current", 0.0, -most, most)], "leak submodel on (a constant current inside the cell)".into())
            }
            Candidate::RcDynamics => {
                if spec.submodels.rc {
                    return None;
                }
                spec.submodels.rc = true;
                (
                    vec![FitParameter::linear("cell.rc_resistance", 5e-3, 0.0, 0.1), FitParameter::log("cell.rc_capacitance", 1000.0, 1.0, 1e6)],
                    "series RC submodel on".into(),
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
                        FitParameter::log("cell.hysteresis_rate", HYSTERESIS_START_RATE, 0.5, 500.0),
                        FitParameter::linear("cell.hysteresis_initial", 0.0, -1.0, 1.0),
                    ],
                    "OCV hysteresis submodel on".into(),
                )
            }
        };
        let extra: Vec<FitParameter> = extra.into_iter().filter(|e| !fitted.contains(&e.path)).collect();
        if extra.is_empty() && structural_parameters == 0 && self != Candidate::SeriesResistance {
            return None;
        }
        if extra.is_empty() && self == Candidate::SeriesResistance && fitted.contains(&"cell.contact_resistance".to_string()) {
            return None;
        }
        if let Some(b) = aged {
            p = b;
        }
        let screened = self.is_ageing();
        Some(Augmentation { spec, base: p, extra, replaces, structural_parameters, change, screened })
    }

    /// The set's parameters a parameter-mismatch candidate refits (empty for the others).
    pub fn refitted_paths(self) -> &'static [&'static str] {
        match self {
            Candidate::ElectrolyteTransport => &["electrolyte.diffusivity_factor", "electrolyte.conductivity_factor"],
            Candidate::Kinetics => &["negative.rate_constant", "positive.rate_constant"],
            Candidate::SolidDiffusion => &["negative.diffusivity", "positive.diffusivity"],
            Candidate::ActiveMaterial => &["negative.active_fraction", "positive.active_fraction"],
            Candidate::LithiumInventory => &["negative.initial_concentration", "positive.initial_concentration"],
            _ => &[],
        }
    }

    /// The pairs of `names` and `values` that are this candidate's own (a pair of effects
    /// fits both effects' parameters: each is judged on its own).
    fn own<'a>(self, names: &'a [String], values: &'a [f64]) -> impl Iterator<Item = (&'a String, &'a f64)> {
        names.iter().zip(values).filter(move |(n, _)| self.refitted_paths().contains(&n.as_str()))
    }

    /// Why fitted `values` of `names` (parameter units) are implausible for this candidate,
    /// relative to the user's set `base`; `None` when they are plausible.
    pub fn implausible(self, names: &[String], values: &[f64], base: &ParameterSet, load: &Load) -> Option<String> {
        let get = |path: &str| names.iter().position(|n| n == path).map(|k| values[k]);
        match self {
            Candidate::SeriesResistance => {
                let r = get("cell.contact_resistance")?;
                (!(1e-4..=0.1).contains(&r)).then(|| format!("contact resistance {:.3} mOhm is outside 0.1 to 100 mOhm", r * 1e3))
            }
            Candidate::ElectrolyteTransport | Candidate::Kinetics | Candidate::SolidDiffusion => self.own(names, values).find_map(|(n, v)| {
                let v0 = base.get(n).ok()?;
                let ratio = v / v0;
                (!(0.05..=20.0).contains(&ratio)).then(|| format!("{n} at {ratio:.3} times the set's value is outside 0.05 to 20"))
            }),
            Candidate::LithiumInventory => {
                let (cn, cp) = (get("negative.initial_concentration")?, get("positive.initial_concentration")?);
                let lithium = |a: f64, b: f64| base.negative.active_fraction * base.negative.thickness * a + base.positive.active_fraction * base.positive.thickness * b;
                let change = lithium(cn, cp) / lithium(base.negative.initial_concentration, base.positive.initial_concentration) - 1.0;
                (change.abs() > 0.4).then(|| format!("a change of {:.0} % of the cyclable lithium exceeds 40 %", 100.0 * change))
            }
            Candidate::ActiveMaterial => self.own(names, values).find_map(|(n, v)| {
                let loss = 1.0 - v / base.get(n).ok()?;
                (loss > 0.5).then(|| format!("{n} lost {:.0} %, more than 50 %", 100.0 * loss))
            }),
            Candidate::Thermal => {
                let h = get("thermal.heat_transfer_coefficient")?;
                (!(1.0..=500.0).contains(&h)).then(|| format!("heat-transfer coefficient {h:.3} W/(m^2 K) is outside 1 to 500"))
            }
            Candidate::RcDynamics => {
                let tau = get("cell.rc_resistance")? * get("cell.rc_capacitance")?;
                (!(1e-3..=30.0).contains(&tau)).then(|| format!("time constant {tau:.3} s is outside 1 ms to 30 s"))
            }
            Candidate::Hysteresis => {
                let h = get("cell.hysteresis_voltage")?;
                (h > 0.05).then(|| format!("hysteresis half-width {:.1} mV exceeds 50 mV", h * 1e3))
            }
            Candidate::SeiGrowth | Candidate::SeiGrowthSeries | Candidate::LithiumPlating | Candidate::LithiumPlatingPartial | Candidate::ActiveMaterialGrowth | Candidate::ActiveMaterialThroughput => {
                ageing::implausible(self, get, base, load)
            }
            Candidate::VoltageOffset => {
                let v = get("cell.voltage_offset")?;
                (v.abs() > VOLTAGE_OFFSET_PLAUSIBLE).then(|| format!("an offset of {:.1} mV exceeds 20 mV", v * 1e3))
            }
            Candidate::VoltageGain => {
                let g = get("cell.voltage_gain")?;
                (g.abs() > VOLTAGE_GAIN_PLAUSIBLE).then(|| format!("a gain error of {:.2} % exceeds 0.5 %", g * 1e2))
            }
            Candidate::Leak => {
                let leak = get("cell.leakage_current")?;
                let most = LEAK_PLAUSIBLE_C_RATE * base.cell.nominal_capacity;
                (leak.abs() > most).then(|| format!("a leak of {:.1} mA exceeds C/100 ({:.1} mA)", leak * 1e3, most * 1e3))
            }
            Candidate::Electrolyte | Candidate::ElectrolyteComposite | Candidate::UnrelaxedStart => None,
        }
    }

    /// Why fitted values describe dynamics faster than the recording's sampling can resolve
    /// (an RC element whose time constant is shorter than the median time step cannot be
    /// told from a series resistance).
    pub fn unresolved(self, names: &[String], values: &[f64], rec: &Recording) -> Option<String> {
        if self != Candidate::RcDynamics {
            return None;
        }
        let get = |path: &str| names.iter().position(|n| n == path).map(|k| values[k]);
        let tau = get("cell.rc_resistance")? * get("cell.rc_capacitance")?;
        let step = rec.stats(1.0).median_step;
        (tau < step).then(|| format!("time constant {tau:.3} s is shorter than the {step:.2} s sampling step: unresolved, it acts as a series resistance"))
    }

    /// A more specific name from the fitted values where the candidate has one (which
    /// electrode lost active material, whether lithium was lost or gained).
    pub fn named_by_values(self, names: &[String], values: &[f64], base: &ParameterSet, load: &Load) -> String {
        let get = |path: &str| names.iter().position(|n| n == path).map(|k| values[k]);
        match self {
            Candidate::ActiveMaterial => {
                let loss = |path: &str| get(path).and_then(|v| base.get(path).ok().map(|v0| 1.0 - v / v0)).unwrap_or(0.0);
                let (n, p) = (loss("negative.active_fraction"), loss("positive.active_fraction"));
                if both_alike(n, p) {
                    return capacity_scale_name(0.5 * (n + p));
                }
                let (which, l) = if p >= n { ("positive", p) } else { ("negative", n) };
                format!("loss of active material, {which} electrode ({:.0} % of its capacity)", 100.0 * l)
            }
            Candidate::ActiveMaterialGrowth | Candidate::ActiveMaterialThroughput => {
                let (n, p) = ageing::lam_losses(get, base, load);
                let (which, l) = if p > n { ("positive", p) } else { ("negative", n) };
                format!("progressive loss of active material, {which} electrode (about {:.1} % of its capacity over the recording)", 100.0 * l)
            }
            Candidate::VoltageOffset => match get("cell.voltage_offset") {
                Some(v) => format!("{} of {:+.1} mV", self.name(), v * 1e3),
                None => self.name().to_string(),
            },
            Candidate::VoltageGain => match get("cell.voltage_gain") {
                Some(g) => format!("{} of {:+.2} % (the channel reads {:.3} times the cell's voltage)", self.name(), g * 1e2, 1.0 + g),
                None => self.name().to_string(),
            },
            Candidate::Leak => match get("cell.leakage_current") {
                Some(leak) => {
                    let way = if leak >= 0.0 { "discharging" } else { "charging" };
                    format!("{} of {:.1} mA {way} the cell (C/{:.0})", self.name(), leak.abs() * 1e3, base.cell.nominal_capacity / leak.abs().max(1e-12))
                }
                None => self.name().to_string(),
            },
            _ => self.name().to_string(),
        }
    }
}

/// Relative difference (-) within which two electrodes' fitted losses of active material
/// count as one loss of both: the fits of the two fractions trade a little against each
/// other through the OCP slopes, so alike losses come back a few per cent apart.
const ALIKE_LOSSES: f64 = 0.1;

/// Whether the negative and positive losses `n`, `p` (fractions, -) are one loss of both
/// electrodes: the same sign, at least half a per cent, within [`ALIKE_LOSSES`] of each other.
fn both_alike(n: f64, p: f64) -> bool {
    n * p > 0.0 && n.abs().min(p.abs()) >= 0.005 && (n - p).abs() <= ALIKE_LOSSES * n.abs().max(p.abs())
}

/// The name of a loss `l` (-) of both electrodes alike: from the voltage alone it is a scale
/// on every current density, the same as a smaller working electrode area or a current
/// channel that misreads the current by the same share (only the ohmic drop in the tabs and
/// contacts, which does not scale with the area, tells them apart).
fn capacity_scale_name(l: f64) -> String {
    let (share, reads) = (100.0 * l.abs(), if l > 0.0 { "low" } else { "high" });
    let what = if l > 0.0 { "loss" } else { "gain" };
    format!(
        "{what} of active material in both electrodes alike ({share:.1} % each): a capacity scale, the same as {share:.1} % of the electrode area {} or a current channel (sensor gain) reading {share:.1} % {reads}",
        if l > 0.0 { "inactive (unwetted or delaminated)" } else { "more than the set's" }
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_pair_judges_each_candidate_on_its_own_parameters() {
        // Diffusivity at 0.3 times the set's value beside an 8 % loss of negative active
        // material: the loss is plausible, and the diffusivity is not a "lost" material.
        let base = crate::params::chen2020();
        let names: Vec<String> = ["positive.diffusivity", "negative.active_fraction", "positive.active_fraction"].map(String::from).to_vec();
        let values = [0.3 * base.positive.diffusivity, 0.92 * base.negative.active_fraction, base.positive.active_fraction];
        assert_eq!(Candidate::ActiveMaterial.implausible(&names, &values, &base, &Load::default()), None);
        assert_eq!(Candidate::SolidDiffusion.implausible(&names, &values, &base, &Load::default()), None);
        // Each still refuses its own implausible values.
        let values = [0.01 * base.positive.diffusivity, 0.4 * base.negative.active_fraction, base.positive.active_fraction];
        assert!(Candidate::ActiveMaterial.implausible(&names, &values, &base, &Load::default()).is_some_and(|why| why.contains("negative.active_fraction")));
        assert!(Candidate::SolidDiffusion.implausible(&names, &values, &base, &Load::default()).is_some_and(|why| why.contains("positive.diffusivity")));
    }

    /// Equal losses of both electrodes are named as the capacity scale they are; unequal
    /// ones by the electrode that lost more.
    #[test]
    fn alike_losses_of_both_electrodes_are_a_capacity_scale() {
        let base = crate::params::chen2020();
        let names: Vec<String> = ["negative.active_fraction", "positive.active_fraction"].map(String::from).to_vec();
        let name = |n: f64, p: f64| {
            let values = [(1.0 - n) * base.negative.active_fraction, (1.0 - p) * base.positive.active_fraction];
            Candidate::ActiveMaterial.named_by_values(&names, &values, &base, &Load::default())
        };
        let scale = name(0.030, 0.0304);
        assert!(scale.contains("both electrodes") && scale.contains("current channel") && scale.contains("3.0 % low"), "{scale}");
        assert!(name(-0.05, -0.052).contains("reading 5.1 % high"));
        assert!(name(0.12, 0.02).contains("negative electrode (12 %"));
        assert!(name(0.001, 0.001).contains("positive electrode (0 %"));
    }

    /// SEI growth needs 3 cycles, or a storage rest of a day with a load after it (the
    /// capacity check after a calendar-ageing storage).
    #[test]
    fn sei_growth_needs_cycles_or_a_day_of_storage_before_a_load() {
        let q = crate::params::chen2020().cell.nominal_capacity;
        let checks_around = |rest_h: usize| {
            // A 1 h discharge, a rest of `rest_h` hours logged every 30 min, a 1 h discharge.
            let (mut time, mut current) = (Vec::new(), Vec::new());
            let mut t = 0.0;
            let mut push = |dt: f64, i: f64, n: usize| {
                for _ in 0..n {
                    time.push(t);
                    current.push(i);
                    t += dt;
                }
            };
            push(60.0, 0.5 * q, 60);
            push(1800.0, 0.0, 2 * rest_h);
            push(60.0, 0.5 * q, 60);
            let n = time.len();
            Recording { time, current, voltage: vec![3.7; n], temperature: None }
        };
        let reason = |r: &Recording| Candidate::SeiGrowth.not_identifiable(r, &Features::of(r), q);
        assert_eq!(reason(&checks_around(30)), None);
        assert!(reason(&checks_around(10)).is_some_and(|why| why.contains("storage rest of 24 h")), "{:?}", reason(&checks_around(10)));
        // Plating needs the cycles whatever the storage.
        let r = checks_around(30);
        assert!(Candidate::LithiumPlating.not_identifiable(&r, &Features::of(&r), q).is_some());
    }

    /// A leak only rescales the charge of a run in one direction; a rest or a return
    /// charge sets it apart. Beyond C/100 it is implausible.
    #[test]
    fn a_leak_needs_a_rest_or_both_directions() {
        let base = crate::params::chen2020();
        let q = base.cell.nominal_capacity;
        let rec = |current: Vec<f64>| {
            let n = current.len();
            Recording { time: (0..n).map(|k| 60.0 * k as f64).collect(), current, voltage: vec![3.7; n], temperature: None }
        };
        let discharge = rec(vec![q; 30]);
        let with_rest = rec([vec![q; 20], vec![0.0; 10]].concat());
        let both_ways = rec([vec![q; 15], vec![-q; 15]].concat());
        let reason = |r: &Recording| Candidate::Leak.not_identifiable(r, &Features::of(r), q);
        assert!(reason(&discharge).is_some_and(|why| why.contains("rest")));
        assert_eq!((reason(&with_rest), reason(&both_ways)), (None, None));
        let names = vec!["cell.leakage_current".to_string()];
        assert_eq!(Candidate::Leak.implausible(&names, &[0.009 * q], &base, &Load::default()), None);
        assert!(Candidate::Leak.implausible(&names, &[-0.011 * q], &base, &Load::default()).is_some_and(|why| why.contains("C/100")));
    }
}
