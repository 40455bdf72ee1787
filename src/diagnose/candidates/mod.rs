//! The library of candidate explanations of a mismatch: each with the residual signature it
//! leaves, when a recording can identify it, how to add it to a model, and the range of
//! fitted values that is physically plausible.
//!
//! Two classes: **missing physics** (a submodel or a richer model the user's model lacks)
//! and **parameter mismatch** (a parameter the user's model already has, refitted).

mod augment;
mod experiments;
mod plausibility;
mod ranges;

use serde::Serialize;

use super::ageing::{self, Load};
use super::features::{Features, largest_swings};
use crate::data::Recording;
use crate::models::ModelKind;
use crate::models::submodels::ParticleSize;
use crate::params::ParameterSet;
use crate::problem::fitting::{FitParameter, INITIAL_SOC, ModelSpec};
use crate::problem::delay::VOLTAGE_DELAY;
use crate::problem::history::{HISTORY_CURRENT, HISTORY_DURATION};
use crate::problem::lost_lithium::{LOSS_SOC, loss_soc_range, lost_stoichiometries};
use ranges::*;

/// Whether a candidate may read the parameter set's value at dotted `path` where the user's
/// model does not: the ageing candidates start from the set's SEI, plating and LAM
/// parameters, and the thermal candidate takes the set's heat capacities and cooling
/// geometry. The other switchable submodels' candidates (contact, RC, hysteresis, leak,
/// offset and gains, size distribution) fit every parameter they add from their own starts.
pub fn read_by_a_candidate(path: &str) -> bool {
    let group = path.split_once('.').map_or(path, |(group, _)| group);
    matches!(group, "sei" | "lam" | "plating" | "thermal") || path.ends_with(".volumetric_heat_capacity")
}

/// A candidate explanation.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Candidate {
    SeriesResistance,
    Electrolyte,
    ElectrolyteComposite,
    ElectrolyteTransport,
    ElectrolyteConcentration,
    Kinetics,
    SolidDiffusion,
    RadiusNegative,
    RadiusPositive,
    SizeDistribution,
    LithiumInventory,
    ActiveMaterial,
    ElectrodeLoading,
    Thermal,
    HeatBalance,
    RecordedTemperature,
    RcDynamics,
    Hysteresis,
    EntropicChange,
    SecondMaterialNegative,
    SecondMaterialPositive,
    SeiGrowth,
    SeiGrowthSeries,
    LithiumPlating,
    LithiumPlatingPartial,
    ActiveMaterialGrowth,
    ActiveMaterialThroughput,
    Leak,
    VoltageOffset,
    VoltageGain,
    CurrentGain,
    UnrelaxedStart,
    VoltageDelay,
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

/// The least window of charge (a share of the nominal capacity) over which an electrode's
/// capacity is read from the open-circuit voltage's shape: a second active material is told
/// from a shifted or stretched stoichiometry by a step or tail across a window, and a
/// progressive loss of active material compresses the features along the capacity axis;
/// within a few per cent of one state of charge either is a local slope.
const SHAPE_WINDOW: f64 = 0.2;

/// Why the recording's window of charge is too narrow to read the OCV's shape, or `None`.
fn too_narrow(f: &Features, q_nominal: f64) -> Option<String> {
    let window = f.charge_window() / q_nominal;
    (window < SHAPE_WINDOW).then(|| format!("needs a recording that moves at least {:.0} % of the nominal capacity (this one spans {:.1} %)", 100.0 * SHAPE_WINDOW, 100.0 * window))
}

impl Candidate {
    pub const ALL: [Candidate; 33] = [
        Candidate::SeriesResistance,
        Candidate::Electrolyte,
        Candidate::ElectrolyteComposite,
        Candidate::ElectrolyteTransport,
        Candidate::ElectrolyteConcentration,
        Candidate::Kinetics,
        Candidate::SolidDiffusion,
        Candidate::RadiusNegative,
        Candidate::RadiusPositive,
        Candidate::SizeDistribution,
        Candidate::LithiumInventory,
        Candidate::ActiveMaterial,
        Candidate::ElectrodeLoading,
        Candidate::Thermal,
        Candidate::HeatBalance,
        Candidate::RecordedTemperature,
        Candidate::RcDynamics,
        Candidate::Hysteresis,
        Candidate::EntropicChange,
        Candidate::SecondMaterialNegative,
        Candidate::SecondMaterialPositive,
        Candidate::SeiGrowth,
        Candidate::SeiGrowthSeries,
        Candidate::LithiumPlating,
        Candidate::LithiumPlatingPartial,
        Candidate::ActiveMaterialGrowth,
        Candidate::ActiveMaterialThroughput,
        Candidate::Leak,
        Candidate::VoltageOffset,
        Candidate::VoltageGain,
        Candidate::CurrentGain,
        Candidate::UnrelaxedStart,
        Candidate::VoltageDelay,
    ];

    /// A second-material candidate's electrode and the search of its potential (start,
    /// lower, upper; V vs Li); `None` for the other candidates.
    fn second_material(self) -> Option<(&'static str, (f64, f64, f64))> {
        match self {
            Candidate::SecondMaterialNegative => Some(("negative", SECOND_POTENTIAL_NEGATIVE)),
            Candidate::SecondMaterialPositive => Some(("positive", SECOND_POTENTIAL_POSITIVE)),
            _ => None,
        }
    }

    /// The fitted share, potential (V) and width (V) of a second-material candidate, read by
    /// `get` from its electrode's paths.
    fn second_material_values(self, get: impl Fn(&str) -> Option<f64>) -> Option<(f64, f64, f64)> {
        let (side, _) = self.second_material()?;
        let value = |name: &str| get(&format!("{side}.second_phase_{name}"));
        Some((value("share")?, value("potential")?, value("width")?))
    }

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
            Candidate::ElectrolyteConcentration => "electrolyte salt concentration (salt consumed or a different fill: the conductivity, the diffusion and the exchange currents together)",
            Candidate::Kinetics => "charge-transfer kinetics (exchange-current density)",
            Candidate::SolidDiffusion => "solid (particle) diffusivity",
            Candidate::RadiusNegative => "particle radius of the negative electrode (its solid diffusion length and surface area per volume together)",
            Candidate::RadiusPositive => "particle radius of the positive electrode (its solid diffusion length and surface area per volume together)",
            Candidate::SizeDistribution => "particle-size distribution (a spread of particle radii in each electrode)",
            Candidate::LithiumInventory => "loss of lithium inventory (stoichiometry offset)",
            Candidate::ActiveMaterial => "loss of active material (electrode capacity)",
            Candidate::ElectrodeLoading => "a heavier electrode coating (more active material per area than the set's: a thicker electrode with its capacity and lithium)",
            Candidate::Thermal => "thermal (self-heating, temperature dependence)",
            Candidate::HeatBalance => "the thermal model's heat balance (self-heating with another heat-transfer coefficient or ambient)",
            Candidate::RecordedTemperature => "temperature dependence at the recorded temperature (the cell's temperature set from outside, e.g. by an ambient that changed, not by its own heat alone)",
            Candidate::RcDynamics => "RC / double-layer dynamics",
            Candidate::Hysteresis => "OCV hysteresis",
            Candidate::EntropicChange => "temperature dependence of the open-circuit potentials (their entropic change dU/dT)",
            Candidate::SecondMaterialNegative => "a second active material in the negative electrode (a composite or blend, such as silicon beside graphite: part of its capacity at another open-circuit potential)",
            Candidate::SecondMaterialPositive => "a second active material in the positive electrode (a blended cathode: part of its capacity at another open-circuit potential)",
            Candidate::SeiGrowth => "SEI growth (lithium lost as the film grows, in cycling and in storage)",
            Candidate::SeiGrowthSeries => "SEI growth, reaction and transport in series (lithium lost as the film grows, more slowly as it thickens)",
            Candidate::LithiumPlating => "lithium plating (lithium lost to irreversible plating during the charges)",
            Candidate::LithiumPlatingPartial => "lithium plating, partially reversible (plated lithium strips back after the charges and part of it turns dead)",
            Candidate::ActiveMaterialGrowth => "progressive loss of active material (stress-driven, over the cycles)",
            Candidate::ActiveMaterialThroughput => "progressive loss of active material (throughput-driven, over the cycles)",
            Candidate::Leak => "self-discharge or current offset (a leak current the cycler does not record: soft short or sensor bias)",
            Candidate::VoltageOffset => "voltage offset (the voltage channel's calibration, or an open-circuit potential shifted against the set's)",
            Candidate::VoltageGain => "voltage gain (the voltage channel's calibration reads a share of the voltage high or low)",
            Candidate::CurrentGain => "current gain (the current channel's calibration reads a share of the current high or low; without an electrolyte model the same as both electrodes' capacity and area scaled alike)",
            Candidate::UnrelaxedStart => "an unrelaxed start (a load just before the first recorded point: the recording began part-way through a test)",
            Candidate::VoltageDelay => "voltage channel delay (its time stamps misaligned with the current's)",
        }
    }

    pub fn class(self) -> Class {
        match self {
            Candidate::SeriesResistance
            | Candidate::Electrolyte
            | Candidate::ElectrolyteComposite
            | Candidate::Thermal
            | Candidate::RecordedTemperature
            | Candidate::RcDynamics
            | Candidate::Hysteresis
            | Candidate::EntropicChange
            | Candidate::SecondMaterialNegative
            | Candidate::SecondMaterialPositive
            | Candidate::SeiGrowth
            | Candidate::SeiGrowthSeries
            | Candidate::LithiumPlating
            | Candidate::LithiumPlatingPartial
            | Candidate::ActiveMaterialGrowth
            | Candidate::ActiveMaterialThroughput
            | Candidate::Leak
            | Candidate::VoltageOffset
            | Candidate::VoltageGain
            | Candidate::CurrentGain
            | Candidate::SizeDistribution => {
                Class::MissingPhysics
            }
            Candidate::UnrelaxedStart | Candidate::VoltageDelay => Class::RecordingCondition,
            _ => Class::ParameterMismatch,
        }
    }

    /// Whether this effect relaxes when the current stops (it shapes the voltage under load
    /// and the relaxation after it, never the relaxed voltage): it cannot explain a model
    /// that is off at rest as much as under load ([`super::at_rest`]).
    pub fn relaxes_at_rest(self) -> bool {
        use Candidate::*;
        matches!(
            self,
            SeriesResistance
                | Electrolyte
                | ElectrolyteComposite
                | ElectrolyteTransport
                | ElectrolyteConcentration
                | Kinetics
                | SolidDiffusion
                | RadiusNegative
                | RadiusPositive
                | SizeDistribution
                | Thermal
                | RcDynamics
                | VoltageDelay
        )
    }

    /// Whether this effect is told from others by the rests (a leak keeps the voltage sliding
    /// through them): a fit of it that leaves the model off at rest as much as under load has
    /// not shown it, but stands in for the open-circuit voltage ([`super::at_rest`]).
    pub fn told_by_rests(self) -> bool {
        matches!(self, Candidate::Leak)
    }

    /// The residual signature this effect leaves when it is missing or mis-set.
    pub fn signature(self) -> &'static str {
        match self {
            Candidate::SeriesResistance => "an instantaneous voltage step at every current step, proportional to the current change and the same at every state of charge",
            Candidate::Electrolyte => "polarisation that grows with rate and relaxes over tens of seconds to minutes in rests (an SPM or SPMe used where the DFN's electrolyte is needed)",
            Candidate::ElectrolyteComposite => "as electrolyte transport, with the SPMe's composite (first-order) electrolyte instead of the DFN's",
            Candidate::ElectrolyteTransport => "rate-dependent polarisation that builds over the first minutes of a load and relaxes in rests, with the electrolyte model already present",
            Candidate::ElectrolyteConcentration => "as the electrolyte's transport properties (rate-dependent polarisation that builds over minutes and relaxes in rests) together with a reaction overpotential at current steps in both electrodes: the salt sets the conductivity and diffusivity through their concentration dependence and the exchange currents as its square root",
            Candidate::Kinetics => "an instantaneous overpotential at current steps that is not proportional to the current (asinh) and grows towards the ends of the stoichiometry range",
            Candidate::SolidDiffusion => "an extra drop late in a high-rate discharge and slow (many minutes) relaxation in rests",
            Candidate::RadiusNegative | Candidate::RadiusPositive => "as one electrode's solid diffusivity (an extra drop late in a load, slow relaxation in rests) together with its reaction overpotential at current steps: a radius R sets both, the diffusion time as R^2/D and the surface per volume as 3 eps/R",
            Candidate::SizeDistribution => "relaxation in rests stretched over a range of times that no single diffusion time fits (small particles settle in minutes, large ones over hours), with an extra drop late in a load as the small particles run out first",
            Candidate::LithiumInventory => "the end of discharge (the knee) arrives earlier or later and the OCV is shifted along the capacity axis; persists at rest",
            Candidate::ActiveMaterial => "one electrode's OCV features are compressed along the capacity axis (less capacity), with a shifted knee; persists at rest",
            Candidate::ElectrodeLoading => "one electrode's OCV features stretched along the capacity axis (more capacity than the set's), with a knee moved later and, in a model with an electrolyte, slightly more polarisation across the thicker electrode; persists at rest",
            Candidate::Thermal => "losses that fall as the cell warms under load (correlated with the recorded temperature rise or with the accumulated I²)",
            Candidate::HeatBalance => "as self-heating, with the thermal model already there: the cell warms faster or slower under load than the model does (the recorded temperature rises above or below the model's), and its losses follow",
            Candidate::RecordedTemperature => "losses that follow the recorded temperature rather than the load: larger wherever the cell was colder, whatever the current did before",
            Candidate::RcDynamics => "transients of seconds after current steps that settle to an offset under load and decay in rests",
            Candidate::Hysteresis => "an offset at rest whose sign follows the direction of the last current (charge vs discharge), not its size",
            Candidate::SecondMaterialNegative | Candidate::SecondMaterialPositive => "capacity on a slope or step of the open-circuit voltage where the set's electrode has none (a tail at one end, or a step inside the window), the same at rest and under load, which no shift or stretch of the stoichiometry axis reproduces",
            Candidate::EntropicChange => "an open-circuit voltage off by a few mV with a shape along the state of charge (the electrodes' dU/dT), the same at rest and under load, in proportion to the cell's distance from the OCPs' reference temperature (25 degC)",
            Candidate::SeiGrowthSeries => "as reaction-limited SEI growth, but the lithium lost per cycle (or per hour of storage) falls as the film thickens and transport through it takes over (towards growth with the square root of time, whatever the potential)",
            Candidate::SeiGrowth => "capacity and the end-of-discharge knee drift from cycle to cycle, or across a storage rest, as lithium is consumed (a fixed stoichiometry offset does not drift), with a slowly growing film resistance",
            Candidate::LithiumPlating => "capacity and the knee drift from cycle to cycle as lithium plates while the negative electrode's potential is low (late in fast charges), with no film resistance; grows steeply with the charge rate and at low temperature",
            Candidate::LithiumPlatingPartial => "as irreversible plating, but the plated lithium strips back in the rest or discharge after each charge (a voltage plateau there), and only the part that turned dead is lost from cycle to cycle",
            Candidate::ActiveMaterialGrowth => "one electrode's OCV features are compressed more from cycle to cycle (its capacity shrinks as it cycles), faster where the current stresses its particles most",
            Candidate::ActiveMaterialThroughput => "one electrode's OCV features are compressed more from cycle to cycle (its capacity shrinks as it cycles), in proportion to the charge passed in either direction",
            Candidate::VoltageOffset => "a constant difference, the same under load and at rest, at every state of charge and current",
            Candidate::VoltageGain => "a difference in proportion to the voltage itself: the same share under load and at rest, larger at the top of the voltage window than at the bottom",
            Candidate::CurrentGain => "the charge passed, and every overpotential, off by one share on charge and discharge alike: the OCV's features reached early or late in proportion to the charge counted, with no drift at rest",
            Candidate::UnrelaxedStart => "a transient at the start only, fading over minutes whatever the load, as the particles and electrolyte relax from a load the recording did not hold",
            Candidate::VoltageDelay => "a residual shaped like the voltage's own slope: at every change of current the voltage answers a fixed time late (or early), whatever the size of the change, and nothing is left in slow stretches",
            Candidate::Leak => "the state of charge drifts at a constant rate whatever the load: the voltage keeps sliding in rests instead of settling, and the charge put back differs from the charge taken out by the leak times the time",
        }
    }

    /// The physically plausible range of the fitted values, in words (stated in the report).
    pub fn plausible_range(self) -> &'static str {
        match self {
            Candidate::SeriesResistance => "0.1 to 100 mOhm",
            Candidate::Electrolyte | Candidate::ElectrolyteComposite | Candidate::RecordedTemperature => "no fitted parameters",
            Candidate::ElectrolyteTransport | Candidate::Kinetics | Candidate::SolidDiffusion => "0.05 to 20 times the set's value, not on a search bound",
            Candidate::ElectrolyteConcentration => "0.3 to 2 times the set's salt concentration, not on a search bound",
            Candidate::RadiusNegative | Candidate::RadiusPositive => "0.2 to 5 times the set's radius, not on a search bound",
            Candidate::SizeDistribution => "relative standard deviation of the radii up to 0.8 in each electrode (the mean radius the set's)",
            Candidate::LithiumInventory => "up to 40 % of the cyclable lithium lost (or gained)",
            Candidate::ActiveMaterial => "up to 50 % of an electrode's active material lost",
            Candidate::ElectrodeLoading => "up to 50 % more active material per area in an electrode (the search's bound)",
            Candidate::Thermal | Candidate::HeatBalance => "heat-transfer coefficient 1 to 500 W/(m^2 K)",
            Candidate::RcDynamics => "time constant R C of 1 ms to 30 s (longer is transport, not an interface)",
            Candidate::Hysteresis => "half-width up to 50 mV",
            Candidate::SecondMaterialNegative | Candidate::SecondMaterialPositive => "0.5 to 40 % of the electrode's sites, filling over 5 to 500 mV, no value on a search bound",
            Candidate::EntropicChange => "0 to 3 times the published dU/dT of the electrode's chemistry (the set's own where it has one), not on a search bound",
            Candidate::SeiGrowth => "SEI exchange current 0.001 to 1000 times the set's",
            Candidate::SeiGrowthSeries => "SEI rate constant 0.001 to 1000 times the set's; EC diffusivity up to the one whose transport limit takes 50 % of the negative electrode's lithium over the recording",
            Candidate::LithiumPlating => "plating rate constant 0.001 to 1000 times the set's",
            Candidate::LithiumPlatingPartial => "plating rate constant 0.001 to 1000 times the set's, dead-lithium decay constant 1e-8 to 1e-2 1/s",
            Candidate::ActiveMaterialGrowth => "up to 50 % of an electrode's active material lost over the recording (steady-profile estimate)",
            Candidate::ActiveMaterialThroughput => "up to 50 % of an electrode's active material lost over the recording",
            Candidate::Leak => "discharging up to C/20 (a soft short of 15 ohm or more in a 5 A h cell, or self-discharge); charging up to C/100 (only a current channel's offset can charge the cell: 1 % of the 1C current)",
            Candidate::VoltageOffset => "up to 20 mV either way",
            Candidate::VoltageGain => "up to 0.5 % either way (21 mV at 4.2 V)",
            Candidate::CurrentGain => "up to 5 % either way (a shunt or Hall sensor out of calibration; further off, a capacity check against the rating shows it)",
            Candidate::UnrelaxedStart => "a load of up to 3C either way, held 10 s to 2 h before the first point",
            Candidate::VoltageDelay => "up to 5 s either way (a logger's messages or a filter; longer would be seen by eye)",
        }
    }

    /// The candidate that makes this one's structural change with no fitted parameters, on
    /// a model of `kind`: this one at the set's values is that one.
    pub fn structural_alias(self, kind: ModelKind) -> Option<Candidate> {
        (matches!(self, Candidate::ElectrolyteTransport | Candidate::ElectrolyteConcentration) && kind == ModelKind::Spm).then_some(Candidate::Electrolyte)
    }

    /// Whether this candidate is lithium plating (either law).
    pub fn plates(self) -> bool {
        matches!(self, Candidate::LithiumPlating | Candidate::LithiumPlatingPartial)
    }

    /// Why the recording cannot identify this candidate, or `None` when it can; `q_nominal`
    /// is the cell's capacity (A h).
    pub fn not_identifiable(self, rec: &Recording, f: &Features, q_nominal: f64) -> Option<String> {
        match self {
            // Hysteresis is an offset whose sign follows the direction of the charge passed:
            // it is seen at rest after both directions, or, with a rest, when the load itself
            // drives the hysteresis state (at the candidate's starting rate) a long way down and
            // a long way up (a drive that charges and discharges; partial charges between rests).
            Candidate::Hysteresis if !(f.rests_after_charge > 0 && f.rests_after_discharge > 0) => {
                let h = Features::hysteresis_state(rec, HYSTERESIS_START_RATE, q_nominal);
                let (fall, rise) = largest_swings(&h);
                let both_ways = fall >= HYSTERESIS_SWING && rise >= HYSTERESIS_SWING;
                (!(both_ways && f.rests_after_charge + f.rests_after_discharge > 0)).then(|| {
                    format!(
                        "needs rests after both charge and discharge, or a rest and a load that passes enough charge both ways to swing the hysteresis state by {HYSTERESIS_SWING} down and up (this recording has {} and {} rests, the state falls by at most {fall:.2} and rises by at most {rise:.2})",
                        f.rests_after_charge, f.rests_after_discharge
                    )
                })
            }
            Candidate::Thermal | Candidate::HeatBalance if rec.temperature.is_none() && f.distinct_rates < 2 => {
                Some("needs a recorded temperature or loads at two or more rates".into())
            }
            // Read at its first value, the recorded temperature is where the model already runs.
            Candidate::RecordedTemperature => match &rec.temperature {
                None => Some("needs a recorded temperature".into()),
                Some(t) => {
                    let noise = crate::stats::noise::temperature_noise(t, &rec.time);
                    let span = t.iter().map(|v| (v - t[0]).abs()).fold(0.0, f64::max);
                    (span <= super::heat_balance::PREDICTED_WITHIN_NOISE * noise).then(|| format!("the recorded temperature stays within {span:.2} K of its first value (noise {noise:.2} K), where the model already runs"))
                }
            },
            // An overpotential is told from the open-circuit voltage by how the voltage moves
            // with the current at one state of charge: steps, or a load whose level changes
            // (e.g. the falling current of a constant-voltage hold).
            Candidate::SeriesResistance | Candidate::Kinetics | Candidate::RcDynamics | Candidate::VoltageDelay if f.steps.is_empty() && f.distinct_rates < 2 => {
                Some("needs current steps or loads at two or more rates".into())
            }
            Candidate::SeiGrowth | Candidate::SeiGrowthSeries => ageing::too_short_for_sei(f),
            Candidate::LithiumPlating | Candidate::LithiumPlatingPartial => ageing::too_few_cycles_to_plate(f),
            Candidate::ActiveMaterialGrowth | Candidate::ActiveMaterialThroughput => ageing::too_few_cycles(f).or_else(|| too_narrow(f, q_nominal)),
            // In one uninterrupted run a leak only rescales the charge passed (a capacity or
            // stoichiometry change); a rest, or charge and discharge both, sets it apart.
            Candidate::Leak if f.rests_after_charge + f.rests_after_discharge == 0 && !(rec.current.iter().any(|i| *i > 0.0) && rec.current.iter().any(|i| *i < 0.0)) => {
                Some("needs a rest, or both charge and discharge (in one constant-direction run a leak is a change of capacity)".into())
            }
            Candidate::SecondMaterialNegative | Candidate::SecondMaterialPositive => too_narrow(f, q_nominal),
            _ => None,
        }
    }

    /// The set's parameters a parameter-mismatch candidate refits (empty for the others).
    pub fn refitted_paths(self) -> &'static [&'static str] {
        match self {
            Candidate::ElectrolyteTransport => &["electrolyte.diffusivity_factor", "electrolyte.conductivity_factor"],
            Candidate::ElectrolyteConcentration => &["electrolyte.initial_concentration"],
            Candidate::Kinetics => &["negative.rate_constant", "positive.rate_constant"],
            Candidate::SolidDiffusion => &["negative.diffusivity", "positive.diffusivity"],
            Candidate::RadiusNegative => &["negative.particle_radius"],
            Candidate::RadiusPositive => &["positive.particle_radius"],
            Candidate::ActiveMaterial => &["negative.active_fraction", "positive.active_fraction"],
            Candidate::ElectrodeLoading => &["negative.thickness", "positive.thickness"],
            Candidate::HeatBalance => &["thermal.heat_transfer_coefficient", "thermal.ambient_temperature"],
            Candidate::LithiumInventory => &["negative.initial_concentration", "positive.initial_concentration"],
            _ => &[],
        }
    }

    /// Secondary properties of the effect (path, lower and upper bound of a linear search)
    /// refitted beside the candidate's own parameters once it is named and its fit still leaves
    /// structure ([`crate::diagnose::refine`]): the electrolyte's transference number, the third
    /// of its transport properties, which a diffusivity factor stands in for only in part; the
    /// electrodes' charge-transfer coefficients, whose asymmetry no rate constant can give.
    pub fn refinements(self) -> &'static [(&'static str, f64, f64)] {
        match self {
            Candidate::ElectrolyteTransport => &[("electrolyte.transference_number", 0.02, 0.9)],
            // The Tafel slopes: an asymmetric charge transfer moves the voltage by different
            // amounts on discharge and charge (PyBaMM's asymmetric Butler-Volmer).
            Candidate::Kinetics => &[("negative.charge_transfer_coefficient", 0.2, 0.8), ("positive.charge_transfer_coefficient", 0.2, 0.8)],
            _ => &[],
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A second material and a progressive loss of active material need a window of a fifth
    /// of the capacity: pulses about one state of charge do not offer them (however many
    /// swings they make), a discharge offers the second material and full cycles the loss.
    #[test]
    fn the_ocv_shape_needs_a_window_of_charge() {
        let q = crate::params::chen2020().cell.nominal_capacity;
        let record = |steps: &[(f64, f64)]| {
            let (mut time, mut current, mut t) = (vec![0.0], vec![0.0], 0.0);
            for &(duration, i) in steps {
                for _ in 0..(duration / 10.0) as usize {
                    t += 10.0;
                    time.push(t);
                    current.push(i);
                }
            }
            let voltage = vec![3.7; time.len()];
            Recording { time, current, voltage, temperature: None }
        };
        let pulses = record(&[(30.0, 2.0 * q), (600.0, 0.0), (30.0, -2.0 * q), (600.0, 0.0)]);
        let discharge = record(&[(1800.0, 0.5 * q)]);
        for c in [Candidate::SecondMaterialNegative, Candidate::SecondMaterialPositive] {
            let why = c.not_identifiable(&pulses, &Features::of(&pulses), q).expect("pulses do not identify a second material");
            assert!(why.contains("at least 20 %") && why.contains("spans 1.7 %"), "{why}");
            assert_eq!(c.not_identifiable(&discharge, &Features::of(&discharge), q), None);
        }
        let swings = record(&[(30.0, 2.0 * q), (30.0, -2.0 * q)].repeat(20));
        let cycles = record(&[(3600.0, q), (3600.0, -q)].repeat(4));
        for c in [Candidate::ActiveMaterialGrowth, Candidate::ActiveMaterialThroughput] {
            let why = c.not_identifiable(&swings, &Features::of(&swings), q).expect("swings about one state of charge do not identify a progressive loss");
            assert!(why.contains("at least 20 %"), "{why}");
            assert_eq!(c.not_identifiable(&cycles, &Features::of(&cycles), q), None);
        }
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
    /// charge sets it apart. Discharging the cell (a soft short) it is plausible over its
    /// search; charging it, only a current channel's offset, to C/100.
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
        assert_eq!(Candidate::Leak.implausible(&names, &[0.049 * q], &base, &Load::default()), None);
        assert_eq!(Candidate::Leak.implausible(&names, &[-0.009 * q], &base, &Load::default()), None);
        assert!(Candidate::Leak.implausible(&names, &[-0.011 * q], &base, &Load::default()).is_some_and(|why| why.contains("offset") && why.contains("C/100")));
    }

    /// A refinement frees a parameter of the set that the candidate does not already refit,
    /// over a range that holds the set's value (where the refit starts).
    #[test]
    fn refinements_are_other_parameters_of_the_set_within_their_range() {
        let base = crate::params::chen2020();
        for c in Candidate::ALL {
            for &(path, lower, upper) in c.refinements() {
                let v = base.get(path).unwrap_or_else(|e| panic!("{c:?}: {path}: {e}"));
                assert!(lower < v && v < upper, "{c:?}: {path} = {v} outside {lower}..{upper}");
                assert!(!c.refitted_paths().contains(&path), "{c:?} already refits {path}");
            }
        }
    }

    /// What [`read_by_a_candidate`] leaves out is never read from the set: a candidate that
    /// switches on a submodel the user's model lacks fits each of its parameters.
    #[test]
    fn a_candidate_fits_every_parameter_of_the_submodel_it_adds() {
        use crate::models::submodels::unread_reason;
        let base = crate::params::chen2020();
        // Every number of the set that the plain model does not read and no candidate reads
        // from the set.
        let plain = crate::models::Submodels::default();
        let unread: Vec<String> = base.numeric_paths().into_iter().filter(|p| unread_reason(&plain, p).is_some() && !read_by_a_candidate(p)).collect();
        let mut added = 0;
        for kind in [ModelKind::Spm, ModelKind::Spme, ModelKind::Dfn] {
            let spec = ModelSpec::new(kind, Default::default());
            for c in Candidate::ALL {
                let Some(aug) = c.augment(&spec, &base, &[], &Load::default()) else { continue };
                for path in &unread {
                    if unread_reason(&aug.spec.submodels, path).is_none() {
                        added += 1;
                        assert!(aug.extra.iter().any(|p| p.path == *path), "{c:?} on the {kind}: reads the set's {path}");
                    }
                }
            }
        }
        // Contact, RC (2), hysteresis (3), leak, offset, two gains on each model, and the
        // size distribution's two spreads on the SPM.
        assert_eq!(unread.len(), 12, "{unread:?}");
        assert_eq!(added, 3 * 10 + 2);
        assert!(read_by_a_candidate("sei.exchange_current") && read_by_a_candidate("positive.volumetric_heat_capacity"));
    }
}
