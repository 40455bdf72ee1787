//! The experiment that would separate two candidates that fit a recording equally well.

use super::Candidate;
use crate::diagnose::features::Features;

impl Candidate {
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
            (VoltageDelay, _) | (_, VoltageDelay) => "current steps logged at 10 Hz or faster with the voltage and current on one clock (a delay shifts the whole response in time, a cell's response starts at the step)".into(),
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
            (CurrentGain, _) | (_, CurrentGain) => "the current channel checked against a reference shunt at two currents, or a full charge and discharge at C/20 whose counted capacity is compared with the cell's rating (a gain scales every current counted; a cell's capacity is its own)".into(),
            (VoltageOffset, _) | (_, VoltageOffset) => "a slow (C/20) charge and discharge over the full window with the voltage channel checked against a reference: a shifted stoichiometry moves the OCV's features along the capacity axis, an offset moves the whole curve up or down".into(),
            (Leak, _) | (_, Leak) => "a rest of several hours at a middle state of charge, then a slow charge and discharge (a leak keeps discharging the cell at rest and the charge balance does not close; lost lithium or material does neither)".into(),
            (SecondMaterialNegative | SecondMaterialPositive, _) | (_, SecondMaterialNegative | SecondMaterialPositive) => "a slow (C/20) charge and discharge over the full window read by differential voltage analysis (dV/dQ): a second material adds a peak of its own, a shifted or stretched stoichiometry moves the existing ones; or half-cells of each electrode".into(),
            (EntropicChange, _) | (_, EntropicChange) => "the open-circuit voltage at rest at three temperatures (say 15, 25 and 35 degC, an hour at each) at several states of charge: the entropic change is the slope of the OCV against temperature, and vanishes at the OCPs' 25 degC reference".into(),
            (RecordedTemperature, _) | (_, RecordedTemperature) => "the same protocol in a climate chamber held at one temperature, with the cell temperature recorded (a cell heated by its own losses departs from the chamber's temperature only under load, and returns to it at rest)".into(),
            (Thermal | HeatBalance, _) | (_, Thermal | HeatBalance) => "the same protocol at a second ambient temperature, with the cell temperature recorded".into(),
            _ if has_rates => format!(
                "the same cell at a rate well above this recording's highest (its {} load levels did not separate them), with a rest after charge and after discharge",
                f.distinct_rates
            ),
            _ => "the same cell at a second C-rate with a rest after charge and after discharge".into(),
        }
    }
}
