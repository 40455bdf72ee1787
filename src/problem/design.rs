//! Design problems: a candidate design (values of chosen parameters) is turned into a
//! parameter set, discharged in simulation, and measured as energy and power per cell mass
//! and volume.

use serde::{Deserialize, Serialize};

use crate::error::Error;
use crate::geometry::MeshSizes;
use crate::models::{BuilderPool, ModelBuilder};
use crate::models::{ModelKind, Submodels};
use crate::params::{CellFormat, MassBasis, MassConvention, ParameterSet};
use crate::protocol::{Protocol, Step};
pub use super::fast_charge::{FastCharge, FastChargeSpec};
pub use super::life::LifeSpec;
pub use super::pulse::PulseSpec;
pub use super::timed_energy::TimedEnergySpec;
use crate::simulation::{SimOptions, simulate};

/// A figure of merit of a discharged design.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Metric {
    /// Energy per cell mass (W h/kg).
    GravimetricEnergyDensity,
    /// Energy per cell volume (W h/L).
    VolumetricEnergyDensity,
    /// Mean discharge power per cell mass (W/kg).
    GravimetricPowerDensity,
    /// Mean discharge power per cell volume (W/L).
    VolumetricPowerDensity,
    /// Pulse power ([`PulseSpec`]) per cell mass (W/kg).
    GravimetricPulsePowerDensity,
    /// Pulse power ([`PulseSpec`]) per cell volume (W/L).
    VolumetricPulsePowerDensity,
    /// The plating-free charge rate ([`FastChargeSpec`], 1/h).
    FastChargeRate,
    /// Discharged capacity (A h).
    Capacity,
    /// Delivered energy (W h).
    Energy,
    /// N/P ratio (-): the negative electrode's capacity (stoichiometry 0 to 1) over the
    /// capacity the cell cycles between its cut-offs, `1 / (x100 - x0)`; near 1 the negative
    /// electrode fills at full charge (plating risk).
    NpRatio,
    /// Largest rise of the cell temperature over its start during the discharge (K); needs
    /// the lumped thermal submodel.
    TemperatureRise,
    /// Energy of a constant-power discharge lasting a fixed time ([`TimedEnergySpec`]) per
    /// cell mass (W h/kg).
    GravimetricTimedEnergyDensity,
    /// The same per cell volume (W h/L).
    VolumetricTimedEnergyDensity,
    /// Discharge capacity after the life cycles over the first cycle's (-, [`LifeSpec`]);
    /// needs an ageing submodel.
    CapacityRetention,
}

/// How a dependent parameter follows the decision variables: `target = constant - sum(of)`.
/// E.g. porosity tied to the active fraction with the binder fraction held fixed:
/// `positive.porosity = (1 - inactive) - positive.active_fraction`.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Tie {
    /// Dotted parameter path that is set.
    pub target: String,
    /// Constant term.
    pub constant: f64,
    /// Dotted parameter paths subtracted from the constant.
    pub minus: Vec<String>,
}

impl Tie {
    /// `target = 1 - inactive - active` with the base set's inactive fraction held fixed.
    pub fn porosity_from_active(electrode: &str, base: &ParameterSet) -> Result<Self, Error> {
        let active = base.get(&format!("{electrode}.active_fraction"))?;
        let porosity = base.get(&format!("{electrode}.porosity"))?;
        Ok(Self {
            target: format!("{electrode}.porosity"),
            constant: active + porosity,
            minus: vec![format!("{electrode}.active_fraction")],
        })
    }
}

/// Everything measured on one design's discharge.
#[derive(Clone, Copy, Debug, Default, Serialize, Deserialize)]
pub struct DesignMetrics {
    /// Delivered energy (W h).
    pub energy: f64,
    /// Discharged capacity (A h).
    pub capacity: f64,
    /// Discharge duration (s).
    pub duration: f64,
    /// Cell mass (kg).
    pub mass: f64,
    /// Cell volume (m^3).
    pub volume: f64,
    /// Mean discharge current (A).
    pub current: f64,
    /// Theoretical capacity of the design (A h), see [`ParameterSet::theoretical_capacity`].
    pub theoretical_capacity: f64,
    /// Delivered over theoretical capacity (-): far below the baseline's when the discharge
    /// stops early (a design limited by transport at this rate).
    pub utilisation: f64,
    /// Sandwich area (m^2): fixed for a free-area cell, from the format otherwise.
    pub area: f64,
    pub gravimetric_energy_density: f64,
    pub volumetric_energy_density: f64,
    pub gravimetric_power_density: f64,
    pub volumetric_power_density: f64,
    /// Pulse power (W) and its densities (W/kg, W/L) when the problem asks for them
    /// ([`PulseSpec`]).
    pub pulse_power: Option<f64>,
    pub gravimetric_pulse_power_density: Option<f64>,
    pub volumetric_pulse_power_density: Option<f64>,
    /// The plating-free charge when the problem asks for it ([`FastChargeSpec`]).
    pub fast_charge: Option<FastCharge>,
    /// N/P ratio (-), see [`Metric::NpRatio`].
    pub np_ratio: f64,
    /// Largest temperature rise over the start during the discharge (K; 0 when isothermal).
    pub temperature_rise: f64,
    /// Energy (W h) of the timed discharge and its densities (W h/kg, W h/L), when the
    /// problem asks for them ([`TimedEnergySpec`]).
    pub timed_energy: Option<f64>,
    pub gravimetric_timed_energy_density: Option<f64>,
    pub volumetric_timed_energy_density: Option<f64>,
    /// Capacity retention after the life cycles (-), when the problem asks for it
    /// ([`LifeSpec`]).
    pub capacity_retention: Option<f64>,
}

impl Metric {
    /// Axis label with unit.
    pub fn label(&self) -> &'static str {
        match self {
            Metric::GravimetricEnergyDensity => "gravimetric energy density (W h/kg)",
            Metric::VolumetricEnergyDensity => "volumetric energy density (W h/L)",
            Metric::GravimetricPowerDensity => "gravimetric power density (W/kg)",
            Metric::VolumetricPowerDensity => "volumetric power density (W/L)",
            Metric::GravimetricPulsePowerDensity => "gravimetric pulse power density (W/kg)",
            Metric::VolumetricPulsePowerDensity => "volumetric pulse power density (W/L)",
            Metric::FastChargeRate => "plating-free charge rate (C)",
            Metric::Capacity => "discharge capacity (A h)",
            Metric::Energy => "discharge energy (W h)",
            Metric::NpRatio => "N/P capacity ratio (-)",
            Metric::TemperatureRise => "temperature rise (K)",
            Metric::GravimetricTimedEnergyDensity => "gravimetric energy density at a fixed discharge time (W h/kg)",
            Metric::VolumetricTimedEnergyDensity => "volumetric energy density at a fixed discharge time (W h/L)",
            Metric::CapacityRetention => "capacity retention after the life cycles (-)",
        }
    }

    /// `v` with the decimals the metric's unit needs (0.1 W h/kg; 1e-4 for a ratio or a rate).
    pub fn show(&self, v: f64) -> String {
        let decimals = match self {
            Metric::FastChargeRate | Metric::NpRatio | Metric::CapacityRetention => 4,
            Metric::Capacity | Metric::Energy | Metric::TemperatureRise => 3,
            _ => 1,
        };
        format!("{v:.decimals$}")
    }

    /// The metric's name in study files (`gravimetric_energy_density`, ...).
    pub fn key(&self) -> String {
        serde_json::to_value(self).ok().and_then(|v| v.as_str().map(str::to_string)).unwrap_or_default()
    }

    /// Whether the metric needs a timed discharge ([`TimedEnergySpec`]) besides the discharge.
    pub fn needs_timed_energy(&self) -> bool {
        matches!(self, Metric::GravimetricTimedEnergyDensity | Metric::VolumetricTimedEnergyDensity)
    }

    /// Whether the metric needs a pulse ([`PulseSpec`]) besides the discharge.
    pub fn needs_pulse(&self) -> bool {
        matches!(self, Metric::GravimetricPulsePowerDensity | Metric::VolumetricPulsePowerDensity)
    }

    /// Whether the metric needs a plating-free charge search ([`FastChargeSpec`]).
    pub fn needs_fast_charge(&self) -> bool {
        matches!(self, Metric::FastChargeRate)
    }

    /// Whether the metric needs the life cycles ([`LifeSpec`]).
    pub fn needs_life(&self) -> bool {
        matches!(self, Metric::CapacityRetention)
    }
}

impl DesignMetrics {
    /// Whether the discharge stopped early: it delivered less than `min_utilisation` of the
    /// design's theoretical capacity.
    pub fn stopped_early(&self, min_utilisation: f64) -> bool {
        !(self.utilisation >= min_utilisation)
    }

    pub fn get(&self, m: Metric) -> f64 {
        match m {
            Metric::GravimetricEnergyDensity => self.gravimetric_energy_density,
            Metric::VolumetricEnergyDensity => self.volumetric_energy_density,
            Metric::GravimetricPowerDensity => self.gravimetric_power_density,
            Metric::VolumetricPowerDensity => self.volumetric_power_density,
            Metric::GravimetricPulsePowerDensity => self.gravimetric_pulse_power_density.unwrap_or(f64::NAN),
            Metric::VolumetricPulsePowerDensity => self.volumetric_pulse_power_density.unwrap_or(f64::NAN),
            Metric::FastChargeRate => self.fast_charge.map_or(f64::NAN, |f| f.rate),
            Metric::Capacity => self.capacity,
            Metric::Energy => self.energy,
            Metric::NpRatio => self.np_ratio,
            Metric::TemperatureRise => self.temperature_rise,
            Metric::GravimetricTimedEnergyDensity => self.gravimetric_timed_energy_density.unwrap_or(f64::NAN),
            Metric::VolumetricTimedEnergyDensity => self.volumetric_timed_energy_density.unwrap_or(f64::NAN),
            Metric::CapacityRetention => self.capacity_retention.unwrap_or(f64::NAN),
        }
    }
}

/// A design problem: decision variables (dotted parameter paths), ties, and the discharge.
pub struct DesignProblem {
    pub base: ParameterSet,
    pub variables: Vec<String>,
    pub ties: Vec<Tie>,
    pub kind: ModelKind,
    pub submodels: Submodels,
    pub mesh: MeshSizes,
    /// Discharge rate (C).
    pub c_rate: f64,
    /// Re-derive 1C from each candidate's theoretical capacity instead of the nominal one.
    pub rate_from_theoretical_capacity: bool,
    /// Constant discharge power (W) instead of the C-rate, when set.
    pub power: Option<f64>,
    /// Cell format: sizes the electrode area from the stack thickness (free area keeps it).
    pub format: CellFormat,
    /// Which components count in the mass and volume.
    pub mass_convention: MassConvention,
    /// The pulse whose power is measured besides the discharge, when asked for.
    pub pulse: Option<PulseSpec>,
    /// The charge whose plating-free rate is measured, when asked for.
    pub fast_charge: Option<FastChargeSpec>,
    /// The timed constant-power discharge whose energy is measured, when asked for.
    pub timed_energy: Option<TimedEnergySpec>,
    /// The cycles whose capacity retention is measured, when asked for.
    pub life: Option<LifeSpec>,
    /// Builders re-used across evaluations (one per concurrent evaluation).
    pool: BuilderPool,
}

impl DesignProblem {
    pub fn new(
        base: ParameterSet,
        variables: Vec<String>,
        ties: Vec<Tie>,
        kind: ModelKind,
        c_rate: f64,
        rate_from_theoretical_capacity: bool,
    ) -> Result<Self, Error> {
        for v in variables.iter().chain(ties.iter().map(|t| &t.target)) {
            base.get(v)?;
        }
        if !(c_rate > 0.0 && c_rate.is_finite()) {
            return Err(Error::invalid("c_rate", c_rate, "must be positive"));
        }
        Ok(Self {
            base,
            variables,
            ties,
            kind,
            submodels: Submodels::default(),
            mesh: MeshSizes::default(),
            c_rate,
            rate_from_theoretical_capacity,
            power: None,
            format: CellFormat::FreeArea,
            mass_convention: MassConvention::Cellstudio,
            pulse: None,
            fast_charge: None,
            timed_energy: None,
            life: None,
            pool: BuilderPool::default(),
        })
    }

    /// Discharges at constant power `power` (W) instead of the C-rate.
    pub fn with_power(mut self, power: f64) -> Result<Self, Error> {
        if !(power > 0.0 && power.is_finite()) {
            return Err(Error::invalid("operating.power", power, "must be positive"));
        }
        self.power = Some(power);
        Ok(self)
    }

    /// Measures the pulse power of every candidate too ([`PulseSpec`]).
    pub fn with_pulse(mut self, pulse: PulseSpec) -> Result<Self, Error> {
        pulse.validate(&self.base)?;
        self.pulse = Some(pulse);
        Ok(self)
    }

    /// Measures the energy of every candidate's timed discharge too ([`TimedEnergySpec`]).
    pub fn with_timed_energy(mut self, spec: TimedEnergySpec) -> Result<Self, Error> {
        spec.validate()?;
        self.timed_energy = Some(spec);
        Ok(self)
    }

    /// Measures the plating-free charge of every candidate too ([`FastChargeSpec`]).
    pub fn with_fast_charge(mut self, spec: FastChargeSpec) -> Result<Self, Error> {
        spec.validate()?;
        self.fast_charge = Some(spec);
        Ok(self)
    }

    /// Measures every candidate's capacity retention after the life cycles too ([`LifeSpec`]).
    pub fn with_life(mut self, spec: LifeSpec) -> Result<Self, Error> {
        spec.validate(self.one_c(&self.base))?;
        self.life = Some(spec);
        Ok(self)
    }

    /// Puts the stack into a cell format; the base set must fit it.
    pub fn with_format(mut self, format: CellFormat) -> Result<Self, Error> {
        format.apply(&mut self.base.clone())?;
        self.format = format;
        Ok(self)
    }

    /// Counts mass and volume in `convention` (PyBOP's needs the free-area format).
    pub fn with_mass_convention(mut self, convention: MassConvention) -> Result<Self, Error> {
        if convention != MassConvention::Cellstudio && self.format != CellFormat::FreeArea {
            return Err(Error::InvalidSetting { field: "cell.mass_basis".into(), reason: "PyBOP's convention needs the free-area format".into() });
        }
        self.mass_convention = convention;
        Ok(self)
    }

    /// Mass basis of a candidate's (sized) parameter set in the problem's format and
    /// convention.
    pub fn mass_basis(&self, p: &ParameterSet) -> Result<MassBasis, Error> {
        match self.mass_convention {
            MassConvention::Pybop(d) => Ok(p.pybop_mass_basis(&d)),
            MassConvention::Cellstudio => self.format.mass_basis(p),
        }
    }

    /// The discharge protocol of a candidate's parameter set: constant current at the C-rate
    /// (of the nominal or theoretical capacity) or constant power, to the lower cut-off.
    pub fn protocol(&self, p: &ParameterSet) -> Protocol {
        let step = match self.power {
            Some(power) => {
                // Long enough for any design: the theoretical energy at the upper cut-off.
                let energy = p.theoretical_capacity() * p.cell.upper_cutoff * 3600.0;
                Step::Power { power, duration: 1.5 * energy / power, until_voltage: None }
            }
            None => {
                let one_c = self.one_c(p);
                let current = self.c_rate * one_c;
                // Long enough for any design: 1.5 times its theoretical capacity at this current.
                let duration = 1.5 * 3600.0 * p.theoretical_capacity().max(one_c) / current;
                Step::Current { current, duration, until_voltage: None }
            }
        };
        Protocol { steps: vec![step] }
    }

    /// The capacity (A h) that 1C of a candidate's parameter set discharges in an hour: the
    /// nominal or the theoretical one.
    pub fn one_c(&self, p: &ParameterSet) -> f64 {
        if self.rate_from_theoretical_capacity { p.theoretical_capacity() } else { p.cell.nominal_capacity }
    }

    /// The parameter set of a candidate `x` (one value per variable, ties applied).
    pub fn parameters(&self, x: &[f64]) -> Result<ParameterSet, Error> {
        let mut p = self.base.clone();
        for (path, &v) in self.variables.iter().zip(x) {
            p.set(path, v)?;
        }
        for tie in &self.ties {
            let mut value = tie.constant;
            for m in &tie.minus {
                value -= p.get(m)?;
            }
            p.set(&tie.target, value)?;
        }
        p.validate()?;
        self.format.apply(&mut p)?;
        Ok(p)
    }

    /// Simulates the discharge of candidate `x` and measures it.
    pub fn evaluate(&self, x: &[f64]) -> Result<DesignMetrics, Error> {
        self.with_builder(|builder| self.evaluate_with(builder, x))
    }

    /// Runs `f` with a builder from this problem's pool (its builds are counted).
    pub fn with_builder<R>(&self, f: impl FnOnce(&mut ModelBuilder) -> R) -> R {
        self.pool.with(|| ModelBuilder::new(self.kind, self.submodels, self.mesh), f)
    }

    /// [`evaluate`](Self::evaluate) with the given builder: candidates of one geometry in a
    /// row share its build.
    pub fn evaluate_with(&self, builder: &mut ModelBuilder, x: &[f64]) -> Result<DesignMetrics, Error> {
        let p = self.parameters(x)?;
        self.discharge(builder, &p)
    }

    /// The geometry candidate `x` builds (what decides whether a builder rebuilds), or `None`
    /// when its parameters are invalid.
    pub fn geometry(&self, x: &[f64]) -> Option<crate::geometry::Geometry> {
        self.parameters(x).ok().map(|p| crate::geometry::Geometry::of(&p, self.mesh))
    }

    fn discharge(&self, builder: &mut ModelBuilder, p: &ParameterSet) -> Result<DesignMetrics, Error> {
        let pulse_power = match &self.pulse {
            Some(spec) => Some(spec.power(builder, p)?.0),
            None => None,
        };
        let timed_energy = match &self.timed_energy {
            Some(spec) => Some(spec.energy(builder, p)?.1),
            None => None,
        };
        let fast_charge = match &self.fast_charge {
            Some(spec) => Some(spec.search(builder, p)?),
            None => None,
        };
        let capacity_retention = match &self.life {
            Some(spec) => Some(spec.retention(builder, p, self.one_c(p))?),
            None => None,
        };
        let built = builder.build(p)?;
        // The discharge's one step is made from `operating.c_rate` or `operating.power`: a
        // demand the cell cannot carry is named by that setting.
        let (setting, value) = match self.power {
            Some(power) => ("operating.power", power),
            None => ("operating.c_rate", self.c_rate),
        };
        let sol = simulate(built.model.as_ref(), &mut built.workspace, &self.protocol(p), &SimOptions::for_cell(p), None)
            .map_err(|e| e.demand_named(setting, value))?;
        if sol.cutoff_times.is_empty() {
            // Only a cut-off ends a design's discharge; a time limit would report a part of it.
            let t = sol.time.last().copied().unwrap_or(0.0);
            return Err(Error::Solver { t, reason: format!("the discharge reached its time limit at {t:.0} s before the lower cut-off ({} V)", p.cell.lower_cutoff) });
        }
        let budget = self.mass_basis(p)?;
        let energy = sol.final_energy();
        let duration = sol.time.last().copied().unwrap_or(0.0);
        let power = if duration > 0.0 { energy * 3600.0 / duration } else { 0.0 };
        let current = if duration > 0.0 { sol.final_capacity() * 3600.0 / duration } else { 0.0 };
        Ok(DesignMetrics {
            energy,
            capacity: sol.final_capacity(),
            duration,
            mass: budget.mass,
            volume: budget.volume,
            current,
            theoretical_capacity: p.theoretical_capacity(),
            utilisation: sol.final_capacity() / p.theoretical_capacity(),
            area: p.cell.area(),
            gravimetric_energy_density: energy / budget.mass,
            volumetric_energy_density: energy / (budget.volume * 1e3),
            gravimetric_power_density: power / budget.mass,
            volumetric_power_density: power / (budget.volume * 1e3),
            pulse_power,
            gravimetric_pulse_power_density: pulse_power.map(|w| w / budget.mass),
            volumetric_pulse_power_density: pulse_power.map(|w| w / (budget.volume * 1e3)),
            fast_charge,
            np_ratio: {
                let w = crate::params::soc::StoichiometryWindow::within_reach(p);
                1.0 / (w.x100 - w.x0)
            },
            timed_energy,
            gravimetric_timed_energy_density: timed_energy.map(|e| e / budget.mass),
            volumetric_timed_energy_density: timed_energy.map(|e| e / (budget.volume * 1e3)),
            capacity_retention,
            temperature_rise: sol.temperature.iter().fold(0.0f64, |m, t| m.max(t - sol.temperature[0])),
        })
    }

    /// Model builds so far across all builders.
    pub fn rebuild_count(&self) -> usize {
        self.pool.rebuild_count()
    }
}
