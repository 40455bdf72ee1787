//! Whether a candidate's fitted values are physically plausible, resolved by the recording's
//! sampling, and the name they give it (which electrode, how much, which way).

use super::*;
use crate::params::soc::LithiumLine;

impl Candidate {
    /// The pairs of `names` and `values` that are this candidate's own (a pair of effects
    /// fits both effects' parameters: each is judged on its own).
    fn own<'a>(self, names: &'a [String], values: &'a [f64]) -> impl Iterator<Item = (&'a String, &'a f64)> {
        names.iter().zip(values).filter(move |(n, _)| self.refitted_paths().contains(&n.as_str()))
    }

    /// This candidate's own fitted values as factors of the set's values, by path.
    fn own_factors<'a>(self, names: &'a [String], values: &'a [f64], base: &'a ParameterSet) -> impl Iterator<Item = (&'a String, f64)> {
        self.own(names, values).filter_map(|(n, v)| Some((n, v / base.get(n).ok()?)))
    }

    /// Which of this candidate's own fitted values lies outside `range` times the set's value.
    fn factor_outside(self, names: &[String], values: &[f64], base: &ParameterSet, range: (f64, f64)) -> Option<String> {
        self.own_factors(names, values, base).find_map(|(n, ratio)| {
            (!(range.0..=range.1).contains(&ratio)).then(|| format!("{n} at {ratio:.3} times the set's value is outside {} to {}", range.0, range.1))
        })
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
            Candidate::ElectrolyteTransport | Candidate::Kinetics | Candidate::SolidDiffusion => self.factor_outside(names, values, base, MISMATCH_PLAUSIBLE),
            Candidate::ElectrolyteConcentration => self.factor_outside(names, values, base, SALT_PLAUSIBLE),
            // The set's own thickness is the search's lower bound (no gain): only the upper one
            // marks a stand-in.
            Candidate::ElectrodeLoading => self.factor_outside(names, values, base, (0.0, 0.99 * LOADING_GAIN)),
            Candidate::RadiusNegative | Candidate::RadiusPositive => self.factor_outside(names, values, base, RADIUS_PLAUSIBLE),
            Candidate::LithiumInventory => {
                let (cn, cp) = (get("negative.initial_concentration")?, get("positive.initial_concentration")?);
                let change = lithium_change(cn, cp, base);
                // A start at the end of an electrode's stoichiometry range is where the search
                // stopped, not an estimate: the fit ran out of that electrode's OCP curve (more
                // likely the curve itself, or the balance, differs from the set's).
                let edge = [("negative", cn / base.negative.max_concentration), ("positive", cp / base.positive.max_concentration)]
                    .into_iter()
                    .find(|(_, x)| crate::problem::least_squares::near_bound(*x, INVENTORY_EDGE, 1.0 - INVENTORY_EDGE));
                if let Some((side, x)) = edge {
                    return Some(format!("the {side} electrode would start at stoichiometry {x:.3}, the end of its search range: the fit ran out of its OCP curve (the curve or the balance may differ from the set's)"));
                }
                (change.abs() > 0.4).then(|| format!("a change of {:.0} % of the cyclable lithium exceeds 40 %", 100.0 * change))
            }
            Candidate::ActiveMaterial => self.own(names, values).find_map(|(n, v)| {
                let loss = 1.0 - v / base.get(n).ok()?;
                (loss > 0.5).then(|| format!("{n} lost {:.0} %, more than 50 %", 100.0 * loss))
            }),
            Candidate::Thermal | Candidate::HeatBalance => {
                let h = get("thermal.heat_transfer_coefficient")?;
                (!(1.0..=500.0).contains(&h)).then(|| format!("heat-transfer coefficient {h:.3} W/(m^2 K) is outside 1 to 500"))
            }
            Candidate::RcDynamics => {
                let tau = get("cell.rc_resistance")? * get("cell.rc_capacitance")?;
                (!(1e-3..=30.0).contains(&tau)).then(|| format!("time constant {tau:.3} s is outside 1 ms to 30 s"))
            }
            Candidate::SizeDistribution => ["negative", "positive"].iter().find_map(|side| {
                let s = get(&format!("{side}.radius_relative_std"))?;
                (s > SIZE_SPREAD_PLAUSIBLE).then(|| format!("a {side} radius spread of {s:.2} exceeds {SIZE_SPREAD_PLAUSIBLE}"))
            }),
            Candidate::Hysteresis => {
                let h = get("cell.hysteresis_voltage")?;
                (h > 0.05).then(|| format!("hysteresis half-width {:.1} mV exceeds 50 mV", h * 1e3))
            }
            Candidate::SeiGrowth | Candidate::SeiGrowthSeries | Candidate::LithiumPlating | Candidate::LithiumPlatingPartial | Candidate::ActiveMaterialGrowth | Candidate::ActiveMaterialThroughput => {
                ageing::implausible(self, get, base, load)
            }
            Candidate::SecondMaterialNegative | Candidate::SecondMaterialPositive => {
                let (side, potential) = self.second_material()?;
                let (share, u0, width) = self.second_material_values(get)?;
                let near = crate::problem::least_squares::near_bound;
                if !(SECOND_SHARE_PLAUSIBLE.0..=SECOND_SHARE_PLAUSIBLE.1).contains(&share) {
                    return Some(format!("a second material holding {:.1} % of the {side} electrode's sites is outside {:.1} to {:.0} %", 100.0 * share, 100.0 * SECOND_SHARE_PLAUSIBLE.0, 100.0 * SECOND_SHARE_PLAUSIBLE.1));
                }
                if near(u0, potential.1, potential.2) || near(width, SECOND_WIDTH.1, SECOND_WIDTH.2) {
                    return Some(format!("the second material's potential {u0:.3} V or width {:.0} mV is on its search bound", 1e3 * width));
                }
                None
            }
            Candidate::EntropicChange => ["negative", "positive"].iter().find_map(|side| {
                let f = get(&format!("{side}.ocp_entropic_change_factor"))?;
                (!(ENTROPIC_PLAUSIBLE.0..=ENTROPIC_PLAUSIBLE.1).contains(&f) || crate::problem::least_squares::near_bound(f, ENTROPIC_SEARCH.0, ENTROPIC_SEARCH.1))
                    .then(|| format!("the {side} electrode's dU/dT at {f:.2} times its chemistry's is outside {} to {}", ENTROPIC_PLAUSIBLE.0, ENTROPIC_PLAUSIBLE.1))
            }),
            Candidate::VoltageOffset => {
                let v = get("cell.voltage_offset")?;
                (v.abs() > VOLTAGE_OFFSET_PLAUSIBLE).then(|| format!("an offset of {:.1} mV exceeds {:.0} mV", v * 1e3, VOLTAGE_OFFSET_PLAUSIBLE * 1e3))
            }
            Candidate::VoltageGain => {
                let g = get("cell.voltage_gain")?;
                (g.abs() > VOLTAGE_GAIN_PLAUSIBLE).then(|| format!("a gain error of {:.2} % exceeds {} %", g * 1e2, VOLTAGE_GAIN_PLAUSIBLE * 1e2))
            }
            Candidate::CurrentGain => {
                let g = get("cell.current_gain")?;
                (g.abs() > CURRENT_GAIN_PLAUSIBLE).then(|| format!("a current gain error of {:.2} % exceeds {} %", g * 1e2, CURRENT_GAIN_PLAUSIBLE * 1e2))
            }
            Candidate::Leak => {
                let leak = get("cell.leakage_current")?;
                // Discharging, a soft short: plausible over its whole search.
                let most = OFFSET_PLAUSIBLE_C_RATE * base.cell.nominal_capacity;
                (-leak > most).then(|| format!("{:.1} mA charging the cell can only be a current channel's offset, and one beyond C/{:.0} ({:.1} mA) would be seen", -leak * 1e3, 1.0 / OFFSET_PLAUSIBLE_C_RATE, most * 1e3))
            }
            Candidate::VoltageDelay => {
                let tau = get(VOLTAGE_DELAY)?;
                (tau.abs() > VOLTAGE_DELAY_PLAUSIBLE_S).then(|| format!("a delay of {tau:.2} s exceeds {VOLTAGE_DELAY_PLAUSIBLE_S} s"))
            }
            Candidate::Electrolyte | Candidate::ElectrolyteComposite | Candidate::UnrelaxedStart | Candidate::RecordedTemperature => None,
        }
    }

    /// Why fitted values describe dynamics faster than the recording's sampling can resolve:
    /// an RC element whose time constant is shorter than the median time step cannot be told
    /// from a series resistance, and a voltage channel's delay shorter than it only reshapes
    /// the first sample after each current step (standing in for whatever happens there).
    pub fn unresolved(self, names: &[String], values: &[f64], rec: &Recording) -> Option<String> {
        let get = |path: &str| names.iter().position(|n| n == path).map(|k| values[k]);
        let step = rec.stats(1.0).median_step;
        match self {
            Candidate::RcDynamics => {
                let tau = get("cell.rc_resistance")? * get("cell.rc_capacitance")?;
                (tau < step).then(|| format!("time constant {tau:.3} s is shorter than the {step:.2} s sampling step: unresolved, it acts as a series resistance"))
            }
            Candidate::VoltageDelay => {
                let tau = get(VOLTAGE_DELAY)?;
                let step = step_sampling(rec).unwrap_or(step);
                (tau.abs() < step).then(|| format!("a delay of {tau:.3} s is shorter than the {step:.2} s sampling step after current steps: unresolved, it only reshapes the first sample after each step"))
            }
            _ => None,
        }
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
                // Where the loss state was fitted, the lithium the lost material held: its
                // stoichiometry (0: delithiated, its lithium stayed cyclable).
                let held = get(LOSS_SOC).map_or(String::new(), |s| {
                    let (x, y) = lost_stoichiometries(base, s);
                    format!(", lost at stoichiometry {:.2}", if p >= n { y } else { x })
                });
                format!("loss of active material, {which} electrode ({:.0} % of its capacity{held})", 100.0 * l)
            }
            Candidate::ElectrodeLoading => {
                let gain = |side: &str| {
                    let path = format!("{side}.thickness");
                    get(&path).and_then(|l| base.get(&path).ok().map(|l0| l / l0 - 1.0)).unwrap_or(0.0)
                };
                let (n, p) = (gain("negative"), gain("positive"));
                if both_alike(n, p) {
                    return capacity_scale_name(-0.5 * (n + p));
                }
                let (side, g) = if p >= n { ("positive", p) } else { ("negative", n) };
                format!("a heavier {side} electrode coating ({:.0} % more active material per area than the set's: capacity and lithium)", 100.0 * g)
            }
            Candidate::RadiusNegative | Candidate::RadiusPositive => match self.own_factors(names, values, base).next() {
                Some((_, ratio)) => format!("{}, {ratio:.2} times the set's", self.name()),
                None => self.name().to_string(),
            },
            Candidate::ActiveMaterialGrowth | Candidate::ActiveMaterialThroughput => {
                let (n, p) = ageing::lam_losses(get, base, load);
                let (which, l) = if p > n { ("positive", p) } else { ("negative", n) };
                format!("progressive loss of active material, {which} electrode (about {:.1} % of its capacity over the recording)", 100.0 * l)
            }
            Candidate::SecondMaterialNegative | Candidate::SecondMaterialPositive => {
                let Some((share, u0, width)) = self.second_material_values(get) else { return self.name().to_string() };
                // The fit balances the electrodes' lithium afresh with the material: a change
                // of the cyclable lithium it found is part of what it says about the cell.
                let change = get("negative.initial_concentration").zip(get("positive.initial_concentration")).map(|(cn, cp)| lithium_change(cn, cp, base));
                let lithium = change.filter(|c| c.abs() >= LITHIUM_CHANGE_REPORTED).map_or(String::new(), |c| {
                    format!(", with {:.1} % of the cyclable lithium {}", 100.0 * c.abs(), if c < 0.0 { "lost" } else { "gained" })
                });
                format!("{}: {:.1} % of its sites filling around {u0:.3} V vs Li over about {:.0} mV{lithium}", self.name(), 100.0 * share, 1e3 * width)
            }
            Candidate::EntropicChange => {
                let factor = |side: &str| get(&format!("{side}.ocp_entropic_change_factor")).map(|f| format!("{side} electrode {f:.2}"));
                let sizes: Vec<String> = ["negative", "positive"].iter().filter_map(|s| factor(s)).collect();
                let offset = base.thermal.ambient_temperature - base.thermal.reference_temperature;
                format!("{}, the cell {:.0} K {} their {:.2} K reference ({} times its chemistry's published dU/dT)", self.name(), offset.abs(), if offset < 0.0 { "below" } else { "above" }, base.thermal.reference_temperature, sizes.join(", "))
            }
            Candidate::VoltageOffset => match get("cell.voltage_offset") {
                Some(v) => format!("{} of {:+.1} mV", self.name(), v * 1e3),
                None => self.name().to_string(),
            },
            Candidate::VoltageGain => match get("cell.voltage_gain") {
                Some(g) => format!("{} of {:+.2} % (the channel reads {:.3} times the cell's voltage)", self.name(), g * 1e2, 1.0 + g),
                None => self.name().to_string(),
            },
            Candidate::CurrentGain => match get("cell.current_gain") {
                Some(g) => format!("{} of {:+.2} % (the channel reads {:.3} times the cell's current)", self.name(), g * 1e2, 1.0 + g),
                None => self.name().to_string(),
            },
            Candidate::VoltageDelay => match get(VOLTAGE_DELAY) {
                Some(tau) => format!("{} of {:.2} s (the voltage is logged {:.2} s {} the current)", self.name(), tau.abs(), tau.abs(), if tau >= 0.0 { "after" } else { "before" }),
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

/// The change (-) of the cell's cyclable lithium ([`LithiumLine::lithium`]) when its electrodes
/// start at concentrations `cn` and `cp` (mol/m^3) against the set's (the same at any state
/// of charge: a charge moves lithium between them).
fn lithium_change(cn: f64, cp: f64, base: &ParameterSet) -> f64 {
    let mut fitted = base.clone();
    (fitted.negative.initial_concentration, fitted.positive.initial_concentration) = (cn, cp);
    LithiumLine::of(&fitted).lithium() / LithiumLine::of(base).lithium() - 1.0
}

/// Samples after a current step over which [`step_sampling`] takes its median time step.
const AFTER_A_STEP: usize = 5;

/// The median time step (s) of the first [`AFTER_A_STEP`] samples after each current step (the
/// current moving by a fifth of its peak, [`Recording::large_current_steps`]): how finely
/// the recording resolves a step's response (a cycler logs densely there); `None` without steps.
fn step_sampling(rec: &Recording) -> Option<f64> {
    let t = &rec.time;
    let mut steps: Vec<f64> = Vec::new();
    for k in rec.large_current_steps() {
        steps.extend((k..(k + AFTER_A_STEP).min(t.len() - 1)).map(|m| t[m + 1] - t[m]).filter(|dt| *dt > 0.0));
    }
    (!steps.is_empty()).then(|| crate::stats::median(&steps))
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
        // With the loss state fitted, the lost material's stoichiometry: none at the
        // negative's empty end (delithiated), the set's at its initial state.
        let with_state: Vec<String> = names.iter().cloned().chain([LOSS_SOC.to_string()]).collect();
        let (start, empty, _) = loss_soc_range(&base);
        let at = |s: f64| Candidate::ActiveMaterial.named_by_values(&with_state, &[0.93 * base.negative.active_fraction, base.positive.active_fraction, s], &base, &Load::default());
        assert!(at(empty).contains("negative electrode (7 % of its capacity, lost at stoichiometry 0.00)"), "{}", at(empty));
        let x0 = base.negative.initial_concentration / base.negative.max_concentration;
        assert!(at(start).contains(&format!("lost at stoichiometry {x0:.2}")), "{}", at(start));
    }

    /// A second material a few mV wide (a flat plateau, blind ar8: 2.4 mV) is plausible; a
    /// width on either end of its search is not estimated. The cyclable lithium its
    /// rebalanced electrodes hold is reported from 1 % of change, with its sign.
    #[test]
    fn a_second_material_may_be_a_plateau_and_says_what_lithium_it_found() {
        let base = crate::params::chen2020();
        let c = Candidate::SecondMaterialNegative;
        let names: Vec<String> = ["negative.second_phase_share", "negative.second_phase_potential", "negative.second_phase_width", "negative.initial_concentration", "positive.initial_concentration"].map(String::from).to_vec();
        let (cn, cp) = (base.negative.initial_concentration, base.positive.initial_concentration);
        let values = |width: f64, lithium: f64| [0.1, 0.23, width, lithium * cn, lithium * cp];
        let load = Load::default();
        assert_eq!(c.implausible(&names, &values(0.0024, 1.0), &base, &load), None);
        assert!(c.implausible(&names, &values(SECOND_WIDTH.1, 1.0), &base, &load).is_some_and(|why| why.contains("width 1 mV")));
        assert!(c.implausible(&names, &values(SECOND_WIDTH.2, 1.0), &base, &load).is_some_and(|why| why.contains("500 mV")));
        // Both electrodes' concentrations 5 % lower: 5 % of the cyclable lithium lost.
        let named = c.named_by_values(&names, &values(0.02, 0.95), &base, &load);
        assert!(named.contains("over about 20 mV, with 5.0 % of the cyclable lithium lost"), "{named}");
        assert!(c.named_by_values(&names, &values(0.02, 1.02), &base, &load).contains("2.0 % of the cyclable lithium gained"));
        assert!(!c.named_by_values(&names, &values(0.02, 0.995), &base, &load).contains("cyclable lithium"));
    }

    /// A delay shorter than the sampling after current steps is unresolved; one longer is not.
    #[test]
    fn a_delay_shorter_than_the_sampling_after_steps_is_unresolved() {
        // Pulses logged every 1 s for their first 5 s, then every 30 s.
        let (mut time, mut current) = (Vec::new(), Vec::new());
        let mut t = 0.0;
        for k in 0..6 {
            for dt in [1.0, 1.0, 1.0, 1.0, 1.0, 30.0, 30.0, 30.0, 30.0, 30.0, 30.0] {
                time.push(t);
                current.push(if k % 2 == 0 { 5.0 } else { 0.0 });
                t += dt;
            }
        }
        let n = time.len();
        let rec = Recording { time, current, voltage: vec![3.7; n], temperature: None };
        let names = vec![VOLTAGE_DELAY.to_string()];
        assert!(Candidate::VoltageDelay.unresolved(&names, &[0.006], &rec).is_some_and(|why| why.contains("1.00 s")));
        assert_eq!(Candidate::VoltageDelay.unresolved(&names, &[2.0], &rec), None);
    }

    /// The size distribution is offered on the SPM only (PyBaMM's MPM), fits both spreads,
    /// and refuses a spread above 0.8.
    #[test]
    fn a_size_distribution_is_offered_on_the_spm_and_refuses_wide_spreads() {
        let base = crate::params::chen2020();
        let spec = |kind| ModelSpec::new(kind, crate::models::Submodels::default());
        let aug = Candidate::SizeDistribution.augment(&spec(ModelKind::Spm), &base, &[], &Load::default()).expect("offered on the SPM");
        assert_eq!(aug.spec.submodels.particle_size, ParticleSize::Distribution);
        assert_eq!(aug.extra.iter().map(|e| e.path.as_str()).collect::<Vec<_>>(), ["negative.radius_relative_std", "positive.radius_relative_std"]);
        assert!(Candidate::SizeDistribution.augment(&spec(ModelKind::Spme), &base, &[], &Load::default()).is_none());
        let names: Vec<String> = ["negative.radius_relative_std", "positive.radius_relative_std"].map(String::from).to_vec();
        assert_eq!(Candidate::SizeDistribution.implausible(&names, &[0.4, 0.8], &base, &Load::default()), None);
        assert!(Candidate::SizeDistribution.implausible(&names, &[0.4, 0.85], &base, &Load::default()).is_some_and(|why| why.contains("positive radius spread of 0.85")));
    }

    /// The OCPs' entropic change is offered away from their reference temperature (or on a
    /// model that heats itself), with the chemistry's published dU/dT where the set has none
    /// and the set's own where it has one; a negative factor, one beyond 3 or one on its search
    /// bound is implausible.
    #[test]
    fn the_entropic_change_is_offered_away_from_the_reference_temperature() {
        let spec = |thermal| ModelSpec::new(ModelKind::Spm, crate::models::Submodels { thermal, ..Default::default() });
        let at = |kelvin: f64| {
            let mut p = crate::params::chen2020();
            p.thermal.ambient_temperature = kelvin;
            p
        };
        let offer = |p: &ParameterSet, thermal| Candidate::EntropicChange.augment(&spec(thermal), p, &[], &Load::default());
        assert!(offer(&at(298.15), false).is_none() && offer(&at(301.0), false).is_none());
        assert!(offer(&at(298.15), true).is_some());
        let cold = at(273.15);
        let aug = offer(&cold, false).expect("offered 25 K below the reference");
        assert_eq!(aug.extra.iter().map(|e| e.path.as_str()).collect::<Vec<_>>(), ["negative.ocp_entropic_change_factor", "positive.ocp_entropic_change_factor"]);
        assert_eq!(aug.base.negative.ocp_entropic_change, crate::params::Function1D::ORegan2022GraphiteEntropicChange);
        // An OCP without a published dU/dT keeps none, and that electrode is not fitted.
        let mut other = cold.clone();
        other.positive.ocp = crate::params::Function1D::Table { x: vec![0.0, 1.0], y: vec![4.3, 3.5] };
        let aug = offer(&other, false).expect("the negative's still");
        assert_eq!(aug.extra.len(), 1);
        assert!(aug.base.positive.ocp_entropic_change.is_zero());
        let names: Vec<String> = aug.extra.iter().map(|e| e.path.clone()).collect();
        let two: Vec<String> = ["negative.ocp_entropic_change_factor", "positive.ocp_entropic_change_factor"].map(String::from).to_vec();
        let load = Load::default();
        assert_eq!(Candidate::EntropicChange.implausible(&two, &[1.02, 0.7], &cold, &load), None);
        assert!(Candidate::EntropicChange.implausible(&two, &[1.0, -0.3], &cold, &load).is_some_and(|why| why.contains("positive electrode's dU/dT at -0.30")));
        assert!(Candidate::EntropicChange.implausible(&names, &[3.5], &cold, &load).is_some());
        let named = Candidate::EntropicChange.named_by_values(&two, &[1.02, 0.7], &cold, &load);
        assert!(named.contains("entropic change") && named.contains("25 K below") && named.contains("negative electrode 1.02"), "{named}");
    }

    /// A second material is offered once per electrode, with the electrodes' initial
    /// concentrations refitted in place of the state of charge; a share below 0.5 % or above
    /// 40 %, or a potential or width on its search bound, is implausible.
    #[test]
    fn a_second_material_refits_the_balance_and_refuses_extreme_shares() {
        let base = crate::params::chen2020();
        let spec = ModelSpec::new(ModelKind::Spme, crate::models::Submodels::default());
        let aug = Candidate::SecondMaterialNegative.augment(&spec, &base, &[], &Load::default()).expect("offered");
        let paths: Vec<&str> = aug.extra.iter().map(|e| e.path.as_str()).collect();
        assert_eq!(paths, ["negative.second_phase_share", "negative.second_phase_potential", "negative.second_phase_width", "negative.initial_concentration", "positive.initial_concentration"]);
        assert_eq!(aug.replaces, [INITIAL_SOC, LOSS_SOC]);
        let mut blended = base.clone();
        blended.positive.second_phase_share = 0.1;
        assert!(Candidate::SecondMaterialPositive.augment(&spec, &blended, &[], &Load::default()).is_none(), "already has one");
        let names: Vec<String> = paths[..3].iter().map(|s| s.to_string()).collect();
        let load = Load::default();
        assert_eq!(Candidate::SecondMaterialNegative.implausible(&names, &[0.12, 0.31, 0.12], &base, &load), None);
        assert!(Candidate::SecondMaterialNegative.implausible(&names, &[0.45, 0.31, 0.12], &base, &load).is_some_and(|why| why.contains("45.0 %")));
        assert!(Candidate::SecondMaterialNegative.implausible(&names, &[0.002, 0.31, 0.12], &base, &load).is_some());
        assert!(Candidate::SecondMaterialNegative.implausible(&names, &[0.12, SECOND_POTENTIAL_NEGATIVE.2, 0.12], &base, &load).is_some_and(|why| why.contains("search bound")));
        let named = Candidate::SecondMaterialNegative.named_by_values(&names, &[0.121, 0.311, 0.119], &base, &load);
        assert!(named.contains("negative electrode") && named.contains("12.1 % of its sites") && named.contains("0.311 V"), "{named}");
    }

    /// Lithium inventory fitted to the end of an electrode's stoichiometry range has run out
    /// of its OCP curve: implausible, whatever the change of lithium.
    #[test]
    fn an_inventory_at_the_end_of_the_stoichiometry_range_is_implausible() {
        let base = crate::params::chen2020();
        let names: Vec<String> = ["negative.initial_concentration", "positive.initial_concentration"].map(String::from).to_vec();
        let (cn, cp) = (base.negative.initial_concentration, base.positive.initial_concentration);
        assert_eq!(Candidate::LithiumInventory.implausible(&names, &[0.97 * cn, cp], &base, &Load::default()), None);
        let edge = (1.0 - INVENTORY_EDGE) * base.negative.max_concentration;
        let why = Candidate::LithiumInventory.implausible(&names, &[edge, cp], &base, &Load::default());
        assert!(why.as_ref().is_some_and(|w| w.contains("negative electrode would start at stoichiometry 0.990")), "{why:?}");
    }
}
