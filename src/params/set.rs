//! The typed parameter set of a lithium-ion cell (SI units throughout).

use serde::{Deserialize, Serialize};

use super::function::Function1D;
use super::ocv_correction::OcvCorrection;
use super::check::{check, non_negative, open_unit, positive, temperature};
use crate::error::Error;

/// Gas constant (J/(mol K)).
pub const GAS_CONSTANT: f64 = 8.314462618;
/// Faraday constant (C/mol).
pub const FARADAY: f64 = 96485.33212;

/// One porous electrode.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Electrode {
    /// Coating thickness (m). Geometric.
    pub thickness: f64,
    /// Particle radius (m). Geometric.
    pub particle_radius: f64,
    /// Active-material volume fraction (-).
    pub active_fraction: f64,
    /// Electrolyte volume fraction (porosity) (-). Binder and carbon fill the rest.
    pub porosity: f64,
    /// Bruggeman exponent of the electrolyte transport (-).
    pub bruggeman_electrolyte: f64,
    /// Bruggeman exponent of the solid conductivity (-).
    pub bruggeman_solid: f64,
    /// Solid-phase electronic conductivity (S/m).
    pub conductivity: f64,
    /// Maximum lithium concentration in the active material (mol/m^3).
    pub max_concentration: f64,
    /// Initial (uniform) lithium concentration in the particles (mol/m^3).
    pub initial_concentration: f64,
    /// Particle diffusivity at the reference temperature (m^2/s).
    pub diffusivity: f64,
    /// Activation energy of the particle diffusivity (J/mol).
    pub diffusivity_activation_energy: f64,
    /// Open-circuit potential vs stoichiometry (V).
    pub ocp: Function1D,
    /// Entropic change of the OCP, dU/dT (V/K) against stoichiometry: the OCP at temperature
    /// `T` is `U(x) + (T - T_ref) dU/dT(x)` (PyBaMM's form), and `T dU/dT` the reversible heat.
    /// A number in a file is a constant.
    #[serde(deserialize_with = "super::function::number_or_function", serialize_with = "super::function::serialize_number_or_function")]
    pub ocp_entropic_change: Function1D,
    /// Factor (-) on `ocp_entropic_change`: its size, with its shape kept (what a fit of the
    /// entropic term frees). 1 by default.
    #[serde(default = "one")]
    pub ocp_entropic_change_factor: f64,
    /// Reaction rate constant m_ref in j0 = m_ref c_e^a c_s^a (c_max - c_s)^(1-a)
    /// (A/m^2 (m^3/mol)^1.5).
    pub rate_constant: f64,
    /// Activation energy of the reaction rate constant (J/mol).
    pub rate_activation_energy: f64,
    /// Anodic charge-transfer coefficient `alpha` of the Butler-Volmer kinetics (-), PyBaMM's
    /// "Butler-Volmer transfer coefficient": 0.5 is the symmetric form, any other value
    /// PyBaMM's asymmetric one, `j0 (exp(alpha F eta / RT) - exp(-(1 - alpha) F eta / RT))`.
    pub charge_transfer_coefficient: f64,
    /// Density of the active material (kg/m^3), for the cell mass.
    pub active_density: f64,
    /// Density of the binder and conductive additive (kg/m^3), for the cell mass.
    pub inactive_density: f64,
    /// Volumetric heat capacity of the coating (J/(m^3 K)).
    pub volumetric_heat_capacity: f64,
    /// Double-layer capacitance (F/m^2).
    pub double_layer_capacitance: f64,
    /// Relative standard deviation `sd / R` (-) of the area-weighted lognormal distribution
    /// of particle radii about `particle_radius`, used when the particle-size distribution
    /// submodel is on (PyBaMM's `get_size_distribution_parameters`, default 0.3); 0 keeps
    /// this electrode's single particle size.
    #[serde(default = "default_radius_relative_std")]
    pub radius_relative_std: f64,
    /// Share (-) of the electrode's sites held by a second active material (e.g. silicon beside
    /// graphite) that shares the particles' potential; 0 (the default) for none. See
    /// [`super::second_phase`].
    #[serde(default)]
    pub second_phase_share: f64,
    /// Standard potential (V vs Li) around which the second material fills.
    #[serde(default = "default_second_phase_potential")]
    pub second_phase_potential: f64,
    /// Width (V) of the second material's filling (the logistic's `w`; RT/F = 25.7 mV is
    /// one ideal site).
    #[serde(default = "default_second_phase_width")]
    pub second_phase_width: f64,
}

fn default_second_phase_potential() -> f64 {
    0.3
}

fn default_second_phase_width() -> f64 {
    0.05
}

/// PyBaMM's default relative standard deviation of the particle radii (-).
pub const DEFAULT_RADIUS_RELATIVE_STD: f64 = 0.3;

/// Largest relative standard deviation of the particle radii accepted (-): the radii then
/// span 0 to 6 times the mean.
pub const MAX_RADIUS_RELATIVE_STD: f64 = 1.0;

fn default_radius_relative_std() -> f64 {
    DEFAULT_RADIUS_RELATIVE_STD
}

impl Electrode {
    /// Binder + conductive-additive volume fraction, `1 - active - porosity` (-).
    pub fn inactive_fraction(&self) -> f64 {
        1.0 - self.active_fraction - self.porosity
    }

    /// Specific interfacial area `3 eps_s / R` (1/m).
    pub fn surface_area_density(&self) -> f64 {
        3.0 * self.active_fraction / self.particle_radius
    }

    /// Theoretical capacity between stoichiometries 0 and 1 per unit electrode area (C/m^2).
    pub fn areal_capacity(&self) -> f64 {
        self.active_fraction * self.max_concentration * self.thickness * FARADAY
    }

    fn validate(&self, name: &str) -> Result<(), Error> {
        let f = |field: &str| format!("{name}.{field}");
        positive(&f("thickness"), self.thickness)?;
        positive(&f("particle_radius"), self.particle_radius)?;
        open_unit(&f("porosity"), self.porosity)?;
        open_unit(&f("active_fraction"), self.active_fraction)?;
        if self.inactive_fraction() < -1e-12 {
            return Err(Error::invalid(
                f("active_fraction"),
                self.active_fraction,
                format!(
                    "active fraction + porosity = {} exceeds 1",
                    self.active_fraction + self.porosity
                ),
            ));
        }
        non_negative(&f("bruggeman_electrolyte"), self.bruggeman_electrolyte)?;
        non_negative(&f("bruggeman_solid"), self.bruggeman_solid)?;
        positive(&f("conductivity"), self.conductivity)?;
        positive(&f("max_concentration"), self.max_concentration)?;
        positive(&f("diffusivity"), self.diffusivity)?;
        non_negative(&f("diffusivity_activation_energy"), self.diffusivity_activation_energy)?;
        positive(&f("rate_constant"), self.rate_constant)?;
        non_negative(&f("rate_activation_energy"), self.rate_activation_energy)?;
        open_unit(&f("charge_transfer_coefficient"), self.charge_transfer_coefficient)?;
        positive(&f("active_density"), self.active_density)?;
        positive(&f("inactive_density"), self.inactive_density)?;
        positive(&f("volumetric_heat_capacity"), self.volumetric_heat_capacity)?;
        non_negative(&f("double_layer_capacitance"), self.double_layer_capacitance)?;
        let std = self.radius_relative_std;
        check(&f("radius_relative_std"), std, (0.0..=MAX_RADIUS_RELATIVE_STD).contains(&std), &format!("must lie between 0 (one particle size) and {MAX_RADIUS_RELATIVE_STD} (relative standard deviation of the particle radii)"))?;
        let sto = self.initial_concentration / self.max_concentration;
        if !(sto > 0.0 && sto < 1.0) {
            return Err(Error::invalid(
                f("initial_concentration"),
                self.initial_concentration,
                format!("must lie strictly between 0 and max_concentration = {}", self.max_concentration),
            ));
        }
        check(&f("second_phase_share"), self.second_phase_share, (0.0..1.0).contains(&self.second_phase_share), "must lie in [0, 1)")?;
        positive(&f("second_phase_width"), self.second_phase_width)?;
        check(&f("second_phase_potential"), self.second_phase_potential, true, "must be finite")?;
        self.ocp.validate(&f("ocp"))?;
        self.ocp_entropic_change.validate(&f("ocp_entropic_change"))?;
        check(&f("ocp_entropic_change_factor"), self.ocp_entropic_change_factor, self.ocp_entropic_change_factor.is_finite(), "must be finite")
    }

    /// The entropic change dU/dT (V/K) at stoichiometry `sto`, factor included.
    pub fn entropic_change(&self, sto: f64) -> f64 {
        if self.ocp_entropic_change.is_zero() {
            return 0.0;
        }
        self.ocp_entropic_change_factor * self.ocp_entropic_change.eval(sto)
    }
}

/// The separator.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Separator {
    /// Thickness (m). Geometric.
    pub thickness: f64,
    /// Porosity (-).
    pub porosity: f64,
    /// Bruggeman exponent (-).
    pub bruggeman: f64,
    /// Density of the separator's solid material (kg/m^3).
    pub solid_density: f64,
    /// Volumetric heat capacity (J/(m^3 K)).
    pub volumetric_heat_capacity: f64,
}

/// The electrolyte.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Electrolyte {
    /// Initial (uniform) salt concentration (mol/m^3).
    pub initial_concentration: f64,
    /// Cation transference number (-).
    pub transference_number: f64,
    /// Thermodynamic factor (1 + d ln f / d ln c) (-).
    pub thermodynamic_factor: f64,
    /// Salt diffusivity vs concentration at the reference temperature (m^2/s).
    pub diffusivity: Function1D,
    /// Ionic conductivity vs concentration at the reference temperature (S/m).
    pub conductivity: Function1D,
    /// Activation energy of diffusivity and conductivity (J/mol).
    pub activation_energy: f64,
    /// Factor on the diffusivity function (-), 1 for the function as given: what a fit of
    /// the electrolyte's transport adjusts.
    #[serde(default = "one")]
    pub diffusivity_factor: f64,
    /// Factor on the conductivity function (-), 1 for the function as given.
    #[serde(default = "one")]
    pub conductivity_factor: f64,
    /// Density (kg/m^3), for the cell mass.
    pub density: f64,
}

/// Cell-level geometry, current collectors, packaging and operating limits.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Cell {
    /// Electrode height (m). Geometric.
    pub electrode_height: f64,
    /// Electrode width (m), unrolled. Geometric.
    pub electrode_width: f64,
    /// Negative (copper) current-collector thickness (m).
    pub negative_collector_thickness: f64,
    /// Positive (aluminium) current-collector thickness (m).
    pub positive_collector_thickness: f64,
    /// Negative current-collector density (kg/m^3).
    pub negative_collector_density: f64,
    /// Positive current-collector density (kg/m^3).
    pub positive_collector_density: f64,
    /// Mass of tabs, can and packaging as a fraction of the electrode-stack mass (-).
    pub packaging_mass_fraction: f64,
    /// Volume of tabs, can and free space as a fraction of the electrode-stack volume (-).
    pub packaging_volume_fraction: f64,
    /// Nominal capacity (A h): the current of 1C in amperes.
    pub nominal_capacity: f64,
    /// Lower voltage cut-off (V).
    pub lower_cutoff: f64,
    /// Upper voltage cut-off (V).
    pub upper_cutoff: f64,
    /// Contact (series) resistance (ohm), used when the contact-resistance submodel is on.
    pub contact_resistance: f64,
    /// Resistance of the series RC element (ohm), used when the RC submodel is on.
    #[serde(default)]
    pub rc_resistance: f64,
    /// Capacitance of the series RC element (F), used when the RC submodel is on.
    #[serde(default = "default_rc_capacitance")]
    pub rc_capacitance: f64,
    /// Largest OCV hysteresis offset `M` (V), used when the hysteresis submodel is on.
    #[serde(default)]
    pub hysteresis_voltage: f64,
    /// Rate `k` (-) of the hysteresis state: it relaxes over `1/k` of the nominal capacity.
    #[serde(default = "default_hysteresis_rate")]
    pub hysteresis_rate: f64,
    /// Initial hysteresis state `h(0)` in [-1, 1] (-): -1 after a discharge, +1 after a charge.
    #[serde(default)]
    pub hysteresis_initial: f64,
    /// Current (A, discharge positive) that flows inside the cell but not through the
    /// cycler: self-discharge through a soft short, or the offset of the current sensor.
    /// Used when the leak submodel is on.
    #[serde(default)]
    pub leakage_current: f64,
    /// Constant added to the terminal voltage (V): the voltage channel's calibration offset,
    /// or an open-circuit potential shifted against the set's. Used when the voltage-offset
    /// submodel is on.
    #[serde(default)]
    pub voltage_offset: f64,
    /// Relative error of the voltage channel's scale (-): the channel reads `1 + g` times the
    /// cell's voltage (0.003 reads 0.3 % high). Used when the voltage-gain submodel is on.
    #[serde(default)]
    pub voltage_gain: f64,
    /// Relative error of the current channel's scale (-): the channel reads `1 + g` times the
    /// cell's current (0.025 reads 2.5 % high, on charge and discharge alike). Used when the
    /// current-gain submodel is on.
    #[serde(default)]
    pub current_gain: f64,
    /// Correction to the open-circuit voltage against the charge passed, used when the
    /// OCV-correction submodel is on (no points by default).
    #[serde(default, skip_serializing_if = "OcvCorrection::is_empty")]
    pub ocv_correction: OcvCorrection,
}

/// Default RC capacitance (F): a 10 s time constant at 10 mOhm.
pub const DEFAULT_RC_CAPACITANCE: f64 = 1000.0;
/// Default hysteresis rate (-): the state settles within about a tenth of the capacity.
pub const DEFAULT_HYSTERESIS_RATE: f64 = 10.0;

fn one() -> f64 {
    1.0
}

fn default_rc_capacitance() -> f64 {
    DEFAULT_RC_CAPACITANCE
}

fn default_hysteresis_rate() -> f64 {
    DEFAULT_HYSTERESIS_RATE
}

impl Cell {
    /// Electrode (plate) area (m^2).
    pub fn area(&self) -> f64 {
        self.electrode_height * self.electrode_width
    }
}

/// Thermal environment and lumped heat capacity.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Thermal {
    /// Reference temperature of the Arrhenius laws (K).
    pub reference_temperature: f64,
    /// Ambient temperature (K).
    pub ambient_temperature: f64,
    /// Initial cell temperature (K).
    pub initial_temperature: f64,
    /// Heat-transfer coefficient to the ambient (W/(m^2 K)).
    pub heat_transfer_coefficient: f64,
    /// Cooling surface area (m^2).
    pub cooling_area: f64,
    /// Cell volume used by the lumped thermal model (m^3).
    pub cell_volume: f64,
    /// Volumetric heat capacity of the negative current collector (J/(m^3 K)).
    pub negative_collector_heat_capacity: f64,
    /// Volumetric heat capacity of the positive current collector (J/(m^3 K)).
    pub positive_collector_heat_capacity: f64,
}

/// A complete parameter set.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ParameterSet {
    /// Human-readable name.
    pub name: String,
    pub cell: Cell,
    pub negative: Electrode,
    pub separator: Separator,
    pub positive: Electrode,
    pub electrolyte: Electrolyte,
    pub thermal: Thermal,
    /// SEI growth (read only when an SEI submodel is on); PyBaMM's Chen2020 values when absent.
    #[serde(default)]
    pub sei: super::sei::Sei,
    /// Loss of active material and particle mechanics (read only when a LAM submodel is on);
    /// PyBaMM's OKane2022 constants when absent.
    #[serde(default)]
    pub lam: super::lam::Lam,
    /// Lithium plating (read only when a plating submodel is on); PyBaMM's OKane2022 values
    /// when absent.
    #[serde(default)]
    pub plating: super::plating::Plating,
}

impl ParameterSet {
    /// Checks every field is physical; the error names the first offending field and value.
    pub fn validate(&self) -> Result<(), Error> {
        self.negative.validate("negative")?;
        self.positive.validate("positive")?;
        let s = &self.separator;
        positive("separator.thickness", s.thickness)?;
        open_unit("separator.porosity", s.porosity)?;
        non_negative("separator.bruggeman", s.bruggeman)?;
        positive("separator.solid_density", s.solid_density)?;
        positive("separator.volumetric_heat_capacity", s.volumetric_heat_capacity)?;
        let e = &self.electrolyte;
        positive("electrolyte.initial_concentration", e.initial_concentration)?;
        open_unit("electrolyte.transference_number", e.transference_number)?;
        positive("electrolyte.thermodynamic_factor", e.thermodynamic_factor)?;
        non_negative("electrolyte.activation_energy", e.activation_energy)?;
        positive("electrolyte.density", e.density)?;
        positive("electrolyte.diffusivity_factor", e.diffusivity_factor)?;
        positive("electrolyte.conductivity_factor", e.conductivity_factor)?;
        e.diffusivity.validate("electrolyte.diffusivity")?;
        e.conductivity.validate("electrolyte.conductivity")?;
        let c = &self.cell;
        positive("cell.electrode_height", c.electrode_height)?;
        positive("cell.electrode_width", c.electrode_width)?;
        non_negative("cell.negative_collector_thickness", c.negative_collector_thickness)?;
        non_negative("cell.positive_collector_thickness", c.positive_collector_thickness)?;
        positive("cell.negative_collector_density", c.negative_collector_density)?;
        positive("cell.positive_collector_density", c.positive_collector_density)?;
        non_negative("cell.packaging_mass_fraction", c.packaging_mass_fraction)?;
        non_negative("cell.packaging_volume_fraction", c.packaging_volume_fraction)?;
        positive("cell.nominal_capacity", c.nominal_capacity)?;
        positive("cell.lower_cutoff", c.lower_cutoff)?;
        if !(c.upper_cutoff > c.lower_cutoff) {
            return Err(Error::invalid(
                "cell.upper_cutoff",
                c.upper_cutoff,
                format!("must exceed cell.lower_cutoff = {}", c.lower_cutoff),
            ));
        }
        non_negative("cell.contact_resistance", c.contact_resistance)?;
        non_negative("cell.rc_resistance", c.rc_resistance)?;
        positive("cell.rc_capacitance", c.rc_capacitance)?;
        non_negative("cell.hysteresis_voltage", c.hysteresis_voltage)?;
        positive("cell.hysteresis_rate", c.hysteresis_rate)?;
        check("cell.hysteresis_initial", c.hysteresis_initial, c.hysteresis_initial.abs() <= 1.0, "must lie in [-1, 1]")?;
        check("cell.leakage_current", c.leakage_current, c.leakage_current.is_finite(), "must be a finite current (A)")?;
        check("cell.voltage_offset", c.voltage_offset, c.voltage_offset.is_finite(), "must be a finite voltage (V)")?;
        check("cell.voltage_gain", c.voltage_gain, c.voltage_gain.is_finite() && c.voltage_gain.abs() < 0.5, "must be a finite relative scale error (-) between -0.5 and 0.5")?;
        check("cell.current_gain", c.current_gain, c.current_gain.is_finite() && c.current_gain.abs() < 0.5, "must be a finite relative scale error (-) between -0.5 and 0.5")?;
        c.ocv_correction.validate()?;
        let t = &self.thermal;
        temperature("thermal.reference_temperature", t.reference_temperature)?;
        temperature("thermal.ambient_temperature", t.ambient_temperature)?;
        temperature("thermal.initial_temperature", t.initial_temperature)?;
        non_negative("thermal.heat_transfer_coefficient", t.heat_transfer_coefficient)?;
        non_negative("thermal.cooling_area", t.cooling_area)?;
        positive("thermal.cell_volume", t.cell_volume)?;
        positive("thermal.negative_collector_heat_capacity", t.negative_collector_heat_capacity)?;
        positive("thermal.positive_collector_heat_capacity", t.positive_collector_heat_capacity)?;
        self.sei.validate()?;
        self.lam.validate()?;
        self.plating.validate()
    }

    /// Reads a parameter set from a TOML file and validates it: a whole set, or a base set
    /// with a few overrides (`base = "chen2020"`, see [`super::from_base_table`]).
    pub fn from_toml_file(path: &std::path::Path) -> Result<Self, Error> {
        let text = std::fs::read_to_string(path)
            .map_err(Error::io(&path))?;
        let parse = |e: toml::de::Error| Error::Parse { path: path.display().to_string(), message: e.to_string() };
        let table: toml::Table = toml::from_str(&text).map_err(parse)?;
        if table.contains_key("base") {
            return super::from_base_table(&table, &path.display().to_string());
        }
        let set: ParameterSet = toml::from_str(&text).map_err(parse)?;
        set.validate()?;
        Ok(set)
    }

    /// Sets a scalar parameter by its dotted path (e.g. `positive.thickness`).
    pub fn set(&mut self, path: &str, value: f64) -> Result<(), Error> {
        // A scalar entropic change replaces a function of stoichiometry.
        match path {
            "negative.ocp_entropic_change" => self.negative.ocp_entropic_change = Function1D::Constant { value },
            "positive.ocp_entropic_change" => self.positive.ocp_entropic_change = Function1D::Constant { value },
            _ => *self.field_mut(path)? = value,
        }
        Ok(())
    }

    /// The dotted path of every number the set holds, as serialised (e.g. `sei.exchange_current`,
    /// `lam.negative.current_rate`); function-valued parameters' inner numbers included.
    pub fn numeric_paths(&self) -> Vec<String> {
        fn leaves(prefix: &str, v: &serde_json::Value, out: &mut Vec<String>) {
            let path = |k: &str| if prefix.is_empty() { k.to_string() } else { format!("{prefix}.{k}") };
            match v {
                serde_json::Value::Object(m) => m.iter().for_each(|(k, v)| leaves(&path(k), v, out)),
                serde_json::Value::Number(_) => out.push(prefix.to_string()),
                _ => {}
            }
        }
        let mut out = Vec::new();
        leaves("", &serde_json::to_value(self).expect("a parameter set serialises"), &mut out);
        out
    }

    /// Reads a scalar parameter by its dotted path.
    pub fn get(&self, path: &str) -> Result<f64, Error> {
        let mut copy = self.clone();
        Ok(*copy.field_mut(path)?)
    }

    fn field_mut(&mut self, path: &str) -> Result<&mut f64, Error> {
        let unknown = || Error::InvalidSetting {
            field: path.into(),
            reason: "not a scalar parameter of the set".into(),
        };
        let (group, name) = path.split_once('.').ok_or_else(unknown)?;
        let slot = match group {
            "negative" | "positive" => {
                let e = if group == "negative" { &mut self.negative } else { &mut self.positive };
                match name {
                    "thickness" => &mut e.thickness,
                    "particle_radius" => &mut e.particle_radius,
                    "active_fraction" => &mut e.active_fraction,
                    "porosity" => &mut e.porosity,
                    "bruggeman_electrolyte" => &mut e.bruggeman_electrolyte,
                    "bruggeman_solid" => &mut e.bruggeman_solid,
                    "conductivity" => &mut e.conductivity,
                    "max_concentration" => &mut e.max_concentration,
                    "initial_concentration" => &mut e.initial_concentration,
                    "diffusivity" => &mut e.diffusivity,
                    "diffusivity_activation_energy" => &mut e.diffusivity_activation_energy,
                    "ocp_entropic_change" => match &mut e.ocp_entropic_change {
                        Function1D::Constant { value } => value,
                        _ => return Err(Error::InvalidSetting { field: path.into(), reason: "a function of stoichiometry here, not a scalar: set its size with ocp_entropic_change_factor".into() }),
                    },
                    "ocp_entropic_change_factor" => &mut e.ocp_entropic_change_factor,
                    "rate_constant" => &mut e.rate_constant,
                    "rate_activation_energy" => &mut e.rate_activation_energy,
                    "charge_transfer_coefficient" => &mut e.charge_transfer_coefficient,
                    "active_density" => &mut e.active_density,
                    "inactive_density" => &mut e.inactive_density,
                    "volumetric_heat_capacity" => &mut e.volumetric_heat_capacity,
                    "double_layer_capacitance" => &mut e.double_layer_capacitance,
                    "radius_relative_std" => &mut e.radius_relative_std,
                    "second_phase_share" => &mut e.second_phase_share,
                    "second_phase_potential" => &mut e.second_phase_potential,
                    "second_phase_width" => &mut e.second_phase_width,
                    _ => return Err(unknown()),
                }
            }
            "separator" => match name {
                "thickness" => &mut self.separator.thickness,
                "porosity" => &mut self.separator.porosity,
                "bruggeman" => &mut self.separator.bruggeman,
                "solid_density" => &mut self.separator.solid_density,
                "volumetric_heat_capacity" => &mut self.separator.volumetric_heat_capacity,
                _ => return Err(unknown()),
            },
            "electrolyte" => match name {
                "initial_concentration" => &mut self.electrolyte.initial_concentration,
                "transference_number" => &mut self.electrolyte.transference_number,
                "thermodynamic_factor" => &mut self.electrolyte.thermodynamic_factor,
                "activation_energy" => &mut self.electrolyte.activation_energy,
                "diffusivity_factor" => &mut self.electrolyte.diffusivity_factor,
                "conductivity_factor" => &mut self.electrolyte.conductivity_factor,
                "density" => &mut self.electrolyte.density,
                _ => return Err(unknown()),
            },
            "cell" => match name {
                "electrode_height" => &mut self.cell.electrode_height,
                "electrode_width" => &mut self.cell.electrode_width,
                "negative_collector_thickness" => &mut self.cell.negative_collector_thickness,
                "positive_collector_thickness" => &mut self.cell.positive_collector_thickness,
                "negative_collector_density" => &mut self.cell.negative_collector_density,
                "positive_collector_density" => &mut self.cell.positive_collector_density,
                "packaging_mass_fraction" => &mut self.cell.packaging_mass_fraction,
                "packaging_volume_fraction" => &mut self.cell.packaging_volume_fraction,
                "nominal_capacity" => &mut self.cell.nominal_capacity,
                "lower_cutoff" => &mut self.cell.lower_cutoff,
                "upper_cutoff" => &mut self.cell.upper_cutoff,
                "contact_resistance" => &mut self.cell.contact_resistance,
                "rc_resistance" => &mut self.cell.rc_resistance,
                "rc_capacitance" => &mut self.cell.rc_capacitance,
                "hysteresis_voltage" => &mut self.cell.hysteresis_voltage,
                "hysteresis_rate" => &mut self.cell.hysteresis_rate,
                "hysteresis_initial" => &mut self.cell.hysteresis_initial,
                "leakage_current" => &mut self.cell.leakage_current,
                "voltage_offset" => &mut self.cell.voltage_offset,
                "voltage_gain" => &mut self.cell.voltage_gain,
                "current_gain" => &mut self.cell.current_gain,
                _ => match name.strip_prefix("ocv_correction.") {
                    Some(k) => self.cell.ocv_correction.voltage_mut(k).ok_or_else(unknown)?,
                    None => return Err(unknown()),
                },
            },
            "thermal" => match name {
                "reference_temperature" => &mut self.thermal.reference_temperature,
                "ambient_temperature" => &mut self.thermal.ambient_temperature,
                "initial_temperature" => &mut self.thermal.initial_temperature,
                "heat_transfer_coefficient" => &mut self.thermal.heat_transfer_coefficient,
                "cooling_area" => &mut self.thermal.cooling_area,
                "cell_volume" => &mut self.thermal.cell_volume,
                "negative_collector_heat_capacity" => {
                    &mut self.thermal.negative_collector_heat_capacity
                }
                "positive_collector_heat_capacity" => {
                    &mut self.thermal.positive_collector_heat_capacity
                }
                _ => return Err(unknown()),
            },
            "sei" => self.sei.field_mut(name).ok_or_else(unknown)?,
            "lam" => self.lam.field_mut(name).ok_or_else(unknown)?,
            "plating" => self.plating.field_mut(name).ok_or_else(unknown)?,
            _ => return Err(unknown()),
        };
        Ok(slot)
    }
}
