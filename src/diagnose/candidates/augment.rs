//! How each candidate is added to the user's model: the submodel or model it switches on, the
//! parameters it fits and their search ranges.

use super::*;

impl Candidate {
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
        // A parameter of the set refitted within `range` times its value either way (log).
        let around = |path: &str, range: f64| {
            let v = p.get(path).ok().filter(|v| *v > 0.0)?;
            Some(FitParameter::log(path, v, v / range, v * range))
        };
        let refitted = |range: f64| self.refitted_paths().iter().map(|path| around(path, range)).collect::<Option<Vec<_>>>();
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
            // The electrolyte's transport properties, or its salt (one parameter for its
            // transport and both electrodes' exchange currents). An SPM has no electrolyte
            // whose properties could be off: the electrolyte comes in (SPM -> DFN, its 9 fixed
            // parameters counted) with them refitted, one effect (an electrolyte that is not
            // the set's, e.g. salt lost).
            Candidate::ElectrolyteTransport | Candidate::ElectrolyteConcentration => {
                let (range, what) = match self {
                    Candidate::ElectrolyteTransport => (MISMATCH_RANGE, "electrolyte diffusivity and conductivity factors"),
                    _ => (SALT_SEARCH, "electrolyte salt concentration"),
                };
                let fitted = refitted(range)?;
                if spec.kind == ModelKind::Spm {
                    structural_parameters = SPM_TO_DFN_FIXED;
                    spec.kind = ModelKind::Dfn;
                    (fitted, format!("SPM -> DFN, {what} refitted"))
                } else {
                    (fitted, format!("{what} refitted"))
                }
            }
            Candidate::SeiGrowth | Candidate::SeiGrowthSeries | Candidate::LithiumPlating | Candidate::LithiumPlatingPartial | Candidate::ActiveMaterialGrowth | Candidate::ActiveMaterialThroughput => {
                let (extra, fixed, change, changed_base) = ageing::augment(self, &mut spec, &p, load)?;
                (structural_parameters, aged) = (fixed, changed_base);
                (extra, change)
            }
            Candidate::Kinetics => (refitted(MISMATCH_RANGE)?, "reaction rate constants of both electrodes refitted".into()),
            Candidate::SolidDiffusion => (refitted(MISMATCH_RANGE)?, "particle diffusivities refitted".into()),
            // One parameter for two effects of an electrode (the diffusion time R^2/D and the
            // surface per volume 3 eps/R); geometric, so every evaluation rebuilds the mesh.
            Candidate::RadiusNegative | Candidate::RadiusPositive => (refitted(RADIUS_SEARCH)?, "particle radius refitted".into()),
            Candidate::SizeDistribution => {
                // Built on the SPM only (PyBaMM's MPM), without the ageing submodels: what
                // `check_for` refuses is not offered.
                let mut sized = spec.submodels;
                sized.particle_size = ParticleSize::Distribution;
                if spec.submodels.particle_size == ParticleSize::Distribution || sized.check_for(spec.kind).is_err() {
                    return None;
                }
                spec.submodels = sized;
                (spec.mesh.size_n, spec.mesh.size_p) = (SIZE_CLASSES, SIZE_CLASSES);
                let spread = |path: &str| FitParameter::linear(path, SIZE_SPREAD_START, 0.0, 1.0);
                (vec![spread("negative.radius_relative_std"), spread("positive.radius_relative_std")], "particle-size distribution submodel on (lognormal radii about the set's mean)".into())
            }
            Candidate::LithiumInventory => {
                let c = |path: &str, c0: f64, cmax: f64| FitParameter::linear(path, c0, INVENTORY_EDGE * cmax, (1.0 - INVENTORY_EDGE) * cmax);
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
                let mut fractions = vec![
                    a("negative.active_fraction", p.negative.active_fraction, p.negative.porosity),
                    a("positive.active_fraction", p.positive.active_fraction, p.positive.porosity),
                ];
                // The state at which the material was lost sets the lithium it took along,
                // from the set's initial state (how PyBaMM ages a set) over the whole range;
                // not where the initial concentrations are fitted (they set the lithium).
                if !fitted.iter().any(|f| f.ends_with("initial_concentration")) {
                    let (start, lower, upper) = loss_soc_range(&p);
                    fractions.push(FitParameter::linear(LOSS_SOC, start, lower, upper));
                }
                (fractions, "active-material volume fractions of both electrodes and the state of charge at which they were lost (the lithium it took) refitted".into())
            }
            // A heavier coating: each electrode's thickness from the set's up (its porosity and
            // particles the set's), the lithium it holds at the set's stoichiometry; geometric,
            // so every evaluation rebuilds the mesh. Less material is the loss candidate's.
            Candidate::ElectrodeLoading => {
                let thicker = |path: &str| {
                    let l = p.get(path).ok().filter(|l| *l > 0.0)?;
                    Some(FitParameter::log(path, 1.02 * l, l, LOADING_GAIN * l))
                };
                (self.refitted_paths().iter().map(|path| thicker(path)).collect::<Option<_>>()?, "electrode thicknesses refitted from the set's upwards (more capacity and lithium per area)".into())
            }
            Candidate::Thermal => {
                if spec.submodels.thermal {
                    return None;
                }
                spec.submodels.thermal = true;
                // Heat capacity, cooling area and the activation energies enter as fixed values.
                structural_parameters = 3;
                let (extra, ambient) = heat_balance(10.0, load);
                (extra, format!("lumped thermal submodel on{ambient}"))
            }
            Candidate::HeatBalance => {
                if !spec.submodels.thermal || spec.recorded_temperature {
                    return None;
                }
                let (extra, ambient) = heat_balance(p.thermal.heat_transfer_coefficient.clamp(0.1, 1000.0), load);
                (extra, format!("the thermal model's heat-transfer coefficient refitted{ambient}"))
            }
            Candidate::RecordedTemperature => {
                if spec.recorded_temperature {
                    return None;
                }
                spec.submodels.thermal = true;
                spec.recorded_temperature = true;
                // The set's temperature dependences enter as fixed values; a heat balance the
                // user's model fitted is read from the recording instead.
                structural_parameters = temperature_dependences(&p);
                if structural_parameters == 0 {
                    return None;
                }
                replaces.extend(fitted.iter().filter(|f| f.starts_with("thermal.")).cloned());
                (Vec::new(), "lumped thermal submodel on, its temperature read from the recording in place of its heat balance".into())
            }
            Candidate::EntropicChange => {
                // Offered where the OCPs' temperature term is seen: the model away from their
                // reference temperature, or heating itself. Each electrode keeps the set's
                // dU/dT, or takes its chemistry's published one, and its size is fitted.
                let away = (p.thermal.ambient_temperature - p.thermal.reference_temperature).abs() >= ENTROPIC_MIN_OFFSET_K;
                if !(away || spec.submodels.thermal) {
                    return None;
                }
                let mut extra = Vec::new();
                for (side, e) in [("negative", &mut p.negative), ("positive", &mut p.positive)] {
                    if e.ocp_entropic_change.is_zero() {
                        match e.ocp.published_entropic_change() {
                            Some(f) => (e.ocp_entropic_change, e.ocp_entropic_change_factor) = (f, 1.0),
                            None => continue,
                        }
                    }
                    let path = format!("{side}.ocp_entropic_change_factor");
                    extra.push(FitParameter::linear(&path, 1.0, ENTROPIC_SEARCH.0, ENTROPIC_SEARCH.1));
                }
                (extra, "the OCPs' entropic change dU/dT switched on (the chemistry's published curves where the set has none), its size fitted per electrode".into())
            }
            Candidate::SecondMaterialNegative | Candidate::SecondMaterialPositive => {
                let (side, potential) = self.second_material()?;
                let e = if side == "negative" { &p.negative } else { &p.positive };
                if e.has_second_phase() {
                    return None;
                }
                let path = |name: &str| format!("{side}.second_phase_{name}");
                // The set's balance of the electrodes was made without the material: the
                // initial concentrations are refitted with it, as for lithium inventory.
                let c = |path: &str, c0: f64, cmax: f64| FitParameter::linear(path, c0, INVENTORY_EDGE * cmax, (1.0 - INVENTORY_EDGE) * cmax);
                replaces.push(INITIAL_SOC.to_string());
                (
                    vec![
                        FitParameter::linear(&path("share"), SECOND_SHARE.0, SECOND_SHARE.1, SECOND_SHARE.2),
                        FitParameter::linear(&path("potential"), potential.0, potential.1, potential.2),
                        FitParameter::log(&path("width"), SECOND_WIDTH.0, SECOND_WIDTH.1, SECOND_WIDTH.2),
                        c("negative.initial_concentration", p.negative.initial_concentration, p.negative.max_concentration),
                        c("positive.initial_concentration", p.positive.initial_concentration, p.positive.max_concentration),
                    ],
                    format!("a second material in the {side} electrode: its share of the sites, where and how broadly it fills, and the electrodes' initial concentrations fitted"),
                )
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
            Candidate::CurrentGain => {
                if spec.submodels.current_gain {
                    return None;
                }
                spec.submodels.current_gain = true;
                (vec![FitParameter::linear("cell.current_gain", 0.0, -CURRENT_GAIN_SEARCH, CURRENT_GAIN_SEARCH)], "current-gain submodel on".into())
            }
            Candidate::VoltageDelay => (
                vec![FitParameter::linear(VOLTAGE_DELAY, 0.0, -VOLTAGE_DELAY_SEARCH_S, VOLTAGE_DELAY_SEARCH_S)],
                "voltage read at a fitted delay".into(),
            ),
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
                let (charging, discharging) = LEAK_SEARCH_C_RATE;
                let q = p.cell.nominal_capacity;
                (vec![FitParameter::linear("cell.leakage_current", 0.0, -charging * q, discharging * q)], "leak submodel on (a constant current inside the cell)".into())
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
        // Fitted initial concentrations fix the lithium that a lost material's state would set.
        if replaces.iter().any(|r| r == INITIAL_SOC) {
            replaces.push(LOSS_SOC.to_string());
        }
        let screened = self.is_ageing();
        Some(Augmentation { spec, base: p, extra, replaces, structural_parameters, change, screened })
    }
}

/// The temperature dependences of set `p`: its non-zero activation energies (particle
/// diffusivities, reaction rates, electrolyte, SEI) and entropic changes of the OCPs.
fn temperature_dependences(p: &ParameterSet) -> usize {
    let electrodes = [&p.negative, &p.positive];
    let energies = electrodes.iter().flat_map(|e| [e.diffusivity_activation_energy, e.rate_activation_energy]).chain([p.electrolyte.activation_energy, p.sei.activation_energy]);
    energies.filter(|e| *e != 0.0).count() + electrodes.iter().filter(|e| !e.ocp_entropic_change.is_zero()).count()
}

/// The heat balance's fitted parameters: the heat-transfer coefficient (from `h0`, W/(m^2 K))
/// and, with a recorded first temperature in `load`, the ambient (a cell need not start at the
/// temperature of its room); with the words for the latter.
fn heat_balance(h0: f64, load: &Load) -> (Vec<FitParameter>, &'static str) {
    let h = FitParameter::log("thermal.heat_transfer_coefficient", h0, 0.1, 1000.0);
    match load.start_temperature {
        Some(t0) => (vec![h, FitParameter::linear("thermal.ambient_temperature", t0, t0 - AMBIENT_RANGE_K, t0 + AMBIENT_RANGE_K)], ", ambient fitted to the recorded temperature"),
        None => (vec![h], ""),
    }
}
