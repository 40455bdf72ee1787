//! Design study files (TOML): cell, model, operating point, decision variables, ties,
//! objectives, optimiser and outputs; the other studies (fit, sample, eis, cycle, ...) in
//! their modules. Unknown keys are errors naming the key and line.

pub mod balancing;
pub mod basis;
pub mod cell;
pub mod constraints;
pub mod cycle;
pub mod design;
pub mod eis;
pub mod experiment_design;
pub mod fade_fit;
pub mod fit;
mod fit_data;
pub mod fit_run;
pub mod gitt;
pub mod joint_fit;
pub mod joint_stage;
pub mod kinetics;
pub mod landscape;
pub mod limits;
pub mod ocv;
pub mod parameterise;
pub mod profiles;
pub mod pulses;
pub mod sample;
pub mod shard;
pub mod simulate;
pub mod sobol;
pub mod pareto;
pub mod sweep;
pub mod thermal_stage;
mod validate;
mod warnings;
pub use warnings::{OnBound, at_bound_warnings, fitted_on_bounds, named_on_bounds, on_bounds, truncation_warning, truncation_warning_with, unconverged_warning};


/// What an optional section of a fit report (profiles, experiment design, Sobol' indices)
/// adds to the fit's outputs.
pub struct ReportSection {
    pub files: Vec<std::path::PathBuf>,
    /// The report's section (Markdown).
    pub section: String,
    pub warnings: Vec<String>,
}

use std::path::{Path, PathBuf};

use serde::{Deserialize, Serialize};

use crate::error::Error;
use crate::models::ModelKind;
pub use cell::CellChoice;
use crate::params::{Override, ParameterSet};
use crate::problem::design::{DesignProblem, Metric, Tie};

/// A design study as written in `designs/*.toml`.
#[derive(Clone, Debug, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct Study {
    /// Title used in reports.
    pub name: String,
    /// The file the study was read from (an input no output may overwrite).
    #[serde(skip)]
    pub source: Option<PathBuf>,
    #[serde(default)]
    pub cell: CellChoice,
    #[serde(default)]
    pub model: ModelChoice,
    pub operating: Operating,
    pub variables: Vec<Variable>,
    #[serde(default)]
    pub ties: Vec<Tie>,
    /// Linear constraints on the decision variables.
    #[serde(default)]
    pub constraints: Vec<Constraint>,
    /// Bounds on simulated metrics ([`limits`]).
    #[serde(default)]
    pub limits: Vec<limits::Limit>,
    pub objective: Objectives,
    #[serde(default)]
    pub optimiser: toml::Table,
    #[serde(default)]
    pub sweep: Option<Sweep>,
    #[serde(default)]
    pub output: Output,
}

#[derive(Clone, Debug, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct ModelChoice {
    /// spm, spme or dfn.
    pub kind: ModelKind,
    /// Optional submodels, e.g. `{ thermal = true }` for a temperature-rise limit.
    #[serde(default)]
    pub submodels: crate::models::Submodels,
}

impl Default for ModelChoice {
    fn default() -> Self {
        Self { kind: ModelKind::Spme, submodels: Default::default() }
    }
}

/// The operating condition of the discharge.
#[derive(Clone, Debug, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct Operating {
    /// Discharge rate (C); give this or `power`.
    pub c_rate: Option<f64>,
    /// Constant discharge power (W); give this or `c_rate`.
    pub power: Option<f64>,
    /// Derive 1C from each candidate's theoretical capacity rather than the nominal one.
    #[serde(default)]
    pub rate_from_theoretical_capacity: bool,
    /// Ambient and initial temperature (K); the parameter set's when absent.
    pub temperature: Option<f64>,
    /// Lower voltage cut-off (V); the parameter set's when absent.
    pub lower_cutoff: Option<f64>,
    /// Upper voltage cut-off (V); the parameter set's when absent.
    pub upper_cutoff: Option<f64>,
    /// Smallest delivered / theoretical capacity (-) of a discharge that does not stop early
    /// (default 0.5); designs below it are flagged and kept out of fronts and bests.
    pub min_utilisation: Option<f64>,
    /// The pulse of the pulse-power metrics (10 s from 50 % SOC to the lower cut-off when a
    /// pulse metric is asked for without it).
    pub pulse: Option<crate::problem::pulse::PulseSpec>,
    /// The charge of the plating-free charge rate (10 % to 80 %, margin 0 V when the metric is
    /// asked for without it).
    pub fast_charge: Option<crate::problem::fast_charge::FastChargeSpec>,
    /// The constant-power discharge of the energy at a fixed discharge time (10 minutes when
    /// its metric is asked for without it).
    pub timed_energy: Option<crate::problem::timed_energy::TimedEnergySpec>,
    /// The cycles of the capacity-retention metric (no default: a cycle life is asked for
    /// with its own protocol).
    pub life: Option<crate::problem::life::LifeSpec>,
}

/// Default of [`Operating::min_utilisation`].
pub const DEFAULT_MIN_UTILISATION: f64 = 0.5;

impl Operating {
    /// The early-stop threshold (-).
    pub fn min_utilisation(&self) -> f64 {
        self.min_utilisation.unwrap_or(DEFAULT_MIN_UTILISATION)
    }
}

/// A decision variable.
#[derive(Clone, Debug, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct Variable {
    /// Dotted parameter path, e.g. `positive.thickness`.
    pub path: String,
    pub lower: f64,
    pub upper: f64,
    /// Search in log space.
    #[serde(default)]
    pub log: bool,
    /// Search `(x - offset) / scale` instead of `x` (affine transform; `scale` > 0).
    pub scale: Option<f64>,
    /// Offset of the affine transform (default 0).
    pub offset: Option<f64>,
}

impl Variable {
    /// The optimiser's transform for this variable.
    pub fn transform(&self) -> crate::optim::Transform {
        use crate::optim::Transform;
        match (self.log, self.scale) {
            (true, _) => Transform::Log,
            (false, Some(scale)) => Transform::Affine { scale, offset: self.offset.unwrap_or(0.0) },
            (false, None) => Transform::Identity,
        }
    }
}

/// A linear constraint `sum(terms) <= upper`, `>= lower` or `== equals` on decision variables.
#[derive(Clone, Debug, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct Constraint {
    /// Coefficient of each decision variable (by parameter path).
    pub terms: std::collections::BTreeMap<String, f64>,
    pub upper: Option<f64>,
    pub lower: Option<f64>,
    pub equals: Option<f64>,
}

/// Objectives: one to maximise for `design`, two or more for `pareto`.
#[derive(Clone, Debug, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct Objectives {
    pub maximise: Vec<Metric>,
}

/// Grid sweep settings.
#[derive(Clone, Debug, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct Sweep {
    /// Grid: points per variable.
    #[serde(default)]
    pub points: Vec<usize>,
    /// `grid` (default) or `latin_hypercube`.
    #[serde(default)]
    pub design: SweepDesign,
    /// Number of samples of a Latin hypercube.
    #[serde(default)]
    pub samples: Option<usize>,
    /// Seed of a Latin hypercube.
    #[serde(default)]
    pub seed: u64,
}

impl Sweep {
    /// The number of designs the sweep evaluates (grid: the product of `points`; Latin
    /// hypercube: `samples`); `None` when it overflows.
    pub fn size(&self) -> Option<usize> {
        match self.design {
            SweepDesign::Grid => self.points.iter().try_fold(1usize, |n, &k| n.checked_mul(k)),
            SweepDesign::LatinHypercube => self.samples,
        }
    }
}

/// The most designs one study may ask for (a sweep's points, or a `pareto` run's population
/// times its generations): each is held in memory until the results are written (10^5 sweep
/// designs took 92 MB and 80 s on 2 cores), so more than this is a typo, not a plan, and is
/// refused before it exhausts the machine's memory.
pub const MAX_DESIGNS: usize = 10_000_000;

/// The error for `field` = `given` asking for `designs` designs, if more than [`MAX_DESIGNS`].
pub(crate) fn check_design_count(field: &str, given: &str, designs: f64) -> Result<(), Error> {
    if designs <= MAX_DESIGNS as f64 {
        return Ok(());
    }
    Err(Error::InvalidSetting {
        field: field.into(),
        reason: format!(
            "{given} makes {} designs, more than the {MAX_DESIGNS} one study may evaluate (each is held in memory until the results are written)",
            crate::error::number(designs)
        ),
    })
}

/// How sweep points are placed.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Deserialize, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum SweepDesign {
    #[default]
    Grid,
    LatinHypercube,
}

#[derive(Clone, Debug, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct Output {
    /// Folder for CSV, JSON, plots and the report.
    pub dir: PathBuf,
}

impl Default for Output {
    fn default() -> Self {
        Self { dir: PathBuf::from("out") }
    }
}

impl Study {
    /// Reads and checks a study file.
    pub fn from_file(path: &Path) -> Result<Self, Error> {
        let text = std::fs::read_to_string(path).map_err(Error::io(&path))?;
        let mut study = Self::from_toml(&text, &path.display().to_string())?;
        study.source = Some(path.to_path_buf());
        Ok(study)
    }

    /// The study with `--set` overrides of the cell's parameters, checked again.
    pub fn with_overrides(mut self, overrides: Vec<Override>) -> Result<Self, Error> {
        if !overrides.is_empty() {
            self.cell.overrides = overrides;
            self.validate()?;
        }
        Ok(self)
    }

    /// Files the study reads: the study file and the parameter-set file.
    pub fn inputs(&self) -> Vec<&Path> {
        self.source.as_deref().into_iter().chain(self.cell.file()).collect()
    }

    /// Creates the staged output folder, checked against the study's inputs.
    pub fn output_dir(&self) -> Result<crate::output::OutputDir, Error> {
        crate::output::OutputDir::create(&self.output.dir, &self.inputs())
    }

    /// Parses and checks study text; `origin` names it in errors.
    pub fn from_toml(text: &str, origin: &str) -> Result<Self, Error> {
        let study: Study = toml::from_str(text).map_err(|e| Error::Parse { path: origin.into(), message: e.to_string() })?;
        study.validate()?;
        Ok(study)
    }

    /// The metrics the study evaluates: its objectives and those its limits bound.
    pub fn metrics(&self) -> impl Iterator<Item = Metric> + '_ {
        self.objective.maximise.iter().copied().chain(self.limits.iter().map(|l| l.metric))
    }

    /// The base parameter set, with the operating temperature and cut-offs applied.
    pub fn base_parameters(&self) -> Result<ParameterSet, Error> {
        let mut p = self.cell.load()?;
        let op = &self.operating;
        if let Some(t) = op.temperature {
            crate::params::check::temperature("operating.temperature", t)?;
            p.thermal.ambient_temperature = t;
            p.thermal.initial_temperature = t;
        }
        if let Some(v) = op.lower_cutoff {
            p.cell.lower_cutoff = v;
        }
        if let Some(v) = op.upper_cutoff {
            p.cell.upper_cutoff = v;
        }
        p.validate().map_err(|e| match e {
            Error::InvalidParameter { field, value, reason } => {
                Error::InvalidParameter { field: format!("{field} (after [operating])"), value, reason }
            }
            other => other,
        })?;
        Ok(p)
    }

    /// Decision-variable values of the base parameter set.
    pub fn baseline(&self) -> Result<Vec<f64>, Error> {
        let base = self.base_parameters()?;
        self.variables.iter().map(|v| base.get(&v.path)).collect()
    }

    /// Warnings about a valid study: baseline values outside their variable's bounds (the
    /// search starts from the projection; the baseline is still reported as it is).
    pub fn warnings(&self) -> Vec<String> {
        let Ok(baseline) = self.baseline() else { return Vec::new() };
        self.variables
            .iter()
            .zip(baseline)
            .filter(|(v, b)| !(v.lower..=v.upper).contains(b))
            .map(|(v, b)| {
                format!(
                    "the baseline's {} = {} lies outside its bounds [{}, {}]",
                    v.path,
                    crate::error::number(b),
                    crate::error::number(v.lower),
                    crate::error::number(v.upper)
                )
            })
            .collect()
    }

    /// The design problem the study describes.
    pub fn problem(&self) -> Result<DesignProblem, Error> {
        let problem = DesignProblem::new(
            self.base_parameters()?,
            self.variables.iter().map(|v| v.path.clone()).collect(),
            self.ties.clone(),
            self.model.kind,
            self.operating.c_rate.unwrap_or(1.0),
            self.operating.rate_from_theoretical_capacity,
        )?
        .with_format(self.cell.cell_format()?)?
        .with_mass_convention(self.cell.mass_convention()?)?;
        let mut problem = problem;
        problem.submodels = self.model.submodels;
        let problem = match self.operating.pulse {
            Some(spec) => problem.with_pulse(spec)?,
            None if self.metrics().any(|m| m.needs_pulse()) => problem.with_pulse(Default::default())?,
            None => problem,
        };
        let problem = match self.operating.timed_energy {
            Some(spec) => problem.with_timed_energy(spec)?,
            None if self.metrics().any(|m| m.needs_timed_energy()) => problem.with_timed_energy(Default::default())?,
            None => problem,
        };
        let problem = match self.operating.fast_charge {
            Some(spec) => problem.with_fast_charge(spec)?,
            None if self.metrics().any(|m| m.needs_fast_charge()) => problem.with_fast_charge(Default::default())?,
            None => problem,
        };
        let problem = match &self.operating.life {
            Some(spec) => problem.with_life(spec.clone())?,
            None => problem,
        };
        match self.operating.power {
            Some(power) => problem.with_power(power),
            None => Ok(problem),
        }
    }
}

/// Fraction of the baseline's energy below which a design counts as degenerate (it stores
/// practically nothing, e.g. a 1 nm electrode).
pub const DEGENERATE_ENERGY_FRACTION: f64 = 1e-3;

/// Whether design metrics `m` are no result: non-finite, or an energy (W h) below
/// [`DEGENERATE_ENERGY_FRACTION`] of the baseline's.
pub fn degenerate(m: &crate::problem::design::DesignMetrics, baseline: &crate::problem::design::DesignMetrics) -> bool {
    !(m.energy.is_finite() && m.energy > DEGENERATE_ENERGY_FRACTION * baseline.energy)
}

/// Writes `text` to `dir/name` and appends the path to `files`.
pub(crate) fn write_output(dir: &Path, name: &str, text: String, files: &mut Vec<PathBuf>) -> Result<(), Error> {
    let path = dir.join(name);
    crate::error::write_file(&path, text)?;
    files.push(path);
    Ok(())
}
