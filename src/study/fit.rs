//! Fitting study files (TOML): cell, model, recording (with its CSV format), parameters to
//! identify, cost, optimiser, optional sampler and cost landscape; and the fit run with its
//! report (Markdown + JSON), fit/residual plots and the cost landscape with the optimiser trace.

use super::write_output;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use rand::SeedableRng;
use rand_distr::{Distribution, Normal};
use serde::{Deserialize, Serialize};

use super::{CellChoice, Output};
use crate::cost::CostKind;
use crate::data::Recording;
use crate::error::Error;
use crate::optim::OptimOptions;
use crate::problem::identification::{FitResult, fit};
use crate::problem::fitting::{FitParameter, FittingProblem, INITIAL_SOC, ModelSpec};
use crate::report::plot::{Series, line_plot};

pub use super::fit_data::{DataChoice, InitialSoc};

/// A fitting study as written in `fits/*.toml`.
#[derive(Clone, Debug, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct FitStudy {
    /// Title used in reports.
    pub name: String,
    /// The file the study was read from (an input no output may overwrite).
    #[serde(skip)]
    pub source: Option<PathBuf>,
    #[serde(default)]
    pub cell: CellChoice,
    pub model: ModelSpec,
    /// The recordings: one `[data]` table, or several `[[data]]` entries fitted jointly
    /// (sharing `parameters`, each with its own file, protocol, temperature, initial state
    /// and weight).
    #[serde(deserialize_with = "super::fit_data::one_or_many")]
    pub data: Vec<DataChoice>,
    pub parameters: Vec<FitParameter>,
    #[serde(default)]
    pub cost: CostKind,
    /// `method` (default `lbfgsb`) plus [`OptimOptions`] keys.
    #[serde(default)]
    pub optimiser: toml::Table,
    /// `method` plus the sampler's options; used by `sample`.
    #[serde(default)]
    pub sampler: toml::Table,
    /// Cost landscape over the first two parameters.
    #[serde(default)]
    pub landscape: Option<super::landscape::Landscape>,
    /// Profile likelihood of every fitted parameter.
    #[serde(default)]
    pub profile: Option<super::profiles::ProfileSettings>,
    /// Sobol' (global) sensitivity indices of every fitted parameter over its search box.
    #[serde(default)]
    pub sobol: Option<crate::stats::sobol::SobolSettings>,
    /// Candidate next experiments ranked by what they would determine.
    #[serde(default)]
    pub experiment_design: Option<crate::problem::experiment_design::DesignSettings>,
    #[serde(default)]
    pub output: Output,
}

impl FitStudy {
    /// Reads and checks a study file: every section, the cost's keys, the optimiser's and the
    /// sampler's names and options, before any work.
    pub fn from_file(path: &Path) -> Result<Self, Error> {
        let text = std::fs::read_to_string(path).map_err(Error::io(&path))?;
        let parse = |e: toml::de::Error| Error::Parse { path: path.display().to_string(), message: e.to_string() };
        let mut study: FitStudy = toml::from_str(&text).map_err(parse)?;
        let raw: toml::Table = toml::from_str(&text).map_err(parse)?;
        if let Some(cost) = raw.get("cost").and_then(|c| c.as_table()) {
            let allowed = study.cost.keys();
            if let Some(key) = cost.keys().find(|k| !allowed.contains(&k.as_str())) {
                return Err(Error::InvalidSetting {
                    field: format!("cost.{key}"),
                    reason: format!("unknown key for kind = \"{}\" (allowed: {})", study.cost.name(), allowed.join(", ")),
                });
            }
        }
        study.source = Some(path.to_path_buf());
        study.validate()?;
        Ok(study)
    }

    /// Checks the settings (the parameter set with its overrides included).
    pub fn validate(&self) -> Result<(), Error> {
        self.cost.validate()?;
        if self.parameters.is_empty() {
            return Err(Error::InvalidSetting { field: "parameters".into(), reason: "at least one is needed".into() });
        }
        if let Some(l) = &self.landscape {
            if l.points < 2 || l.points > 200 {
                return Err(Error::invalid("landscape.points", l.points as f64, "must lie in 2..=200"));
            }
        }
        // Sections that analyse one recording's fit.
        let single = |field: &str, what: &str| match self.data.len() > 1 {
            true => Err(Error::InvalidSetting { field: field.into(), reason: format!("{what} one [data] entry, not a joint fit") }),
            false => Ok(()),
        };
        if let Some(p) = &self.profile {
            p.validate()?;
            single("profile", "profile likelihoods take")?;
        }
        if let Some(d) = &self.experiment_design {
            d.validate()?;
            single("experiment_design", "experiment design takes")?;
        }
        if let Some(s) = &self.sobol {
            s.validate()?;
            single("sobol", "Sobol' indices take")?;
        }
        for (k, d) in self.data.iter().enumerate() {
            d.validate(k)?;
            if self.data[..k].iter().enumerate().any(|(j, o)| o.label(j) == d.label(k)) {
                return Err(Error::InvalidSetting { field: format!("data.{}.name", d.label(k)), reason: "two entries have this name".into() });
            }
        }
        let (method, options) = self.optimiser()?;
        crate::optim::by_name(&method, options)?;
        let (method, sampler, _) = self.sampler()?;
        crate::sample::by_name(&method, sampler)?;
        self.cell.load()?;
        let sub = &self.model.submodels;
        crate::models::submodels::refuse_unread(sub, fitted_paths("parameters", &self.parameters))?;
        crate::models::submodels::refuse_unread_overrides(sub, &self.cell.overrides)
    }

    /// The study with `--set` overrides of the cell's parameters, checked again.
    pub fn with_overrides(mut self, overrides: Vec<crate::params::Override>) -> Result<Self, Error> {
        // A fitted parameter takes its value from the fit, so a `--set` of it would be ignored.
        if let Some((o, k)) = overrides.iter().find_map(|o| self.parameters.iter().position(|p| p.path == o.path).map(|k| (o, k))) {
            return Err(Error::InvalidSetting {
                field: format!("--set {}", o.path),
                reason: format!("this study fits it (parameters[{k}]): set its starting value with parameters[{k}].initial instead"),
            });
        }
        if !overrides.is_empty() {
            self.cell.overrides = overrides;
            self.validate()?;
        }
        Ok(self)
    }

    /// Files the run reads: the study, the parameter set, the recordings and protocols.
    pub fn inputs<'a>(&'a self, data: Option<&'a Path>) -> Vec<&'a Path> {
        let files = self.data.iter().enumerate().flat_map(|(k, d)| {
            let file = if k == 0 { data.unwrap_or(&d.file) } else { &d.file };
            std::iter::once(file).chain(d.protocol.as_deref())
        });
        self.source.as_deref().into_iter().chain(self.cell.file()).chain(files).collect()
    }

    /// Whether the study fits several experiments (or one with its own fitted parameters)
    /// jointly ([`crate::problem::joint`]).
    pub fn is_joint(&self) -> bool {
        self.data.len() > 1 || self.data.iter().any(|d| matches!(d.initial_soc, Some(InitialSoc::Fitted { .. })))
    }

    /// Checks that `--data` replaces the file of a study with one `[data]`.
    pub fn check_data_override(&self, data: Option<&Path>) -> Result<(), Error> {
        match data {
            Some(d) if self.data.len() > 1 => Err(Error::InvalidSetting {
                field: "--data".into(),
                reason: format!("`{}`: the study has {} [[data]] entries; --data replaces the file of a study with one", d.display(), self.data.len()),
            }),
            _ => Ok(()),
        }
    }

    /// What the run does with `data.synthetic_noise`, when it is set: added to the study's own
    /// (synthetic) file, never to a recording given with `--data`.
    pub fn noise_note(&self, data: Option<&Path>) -> Vec<String> {
        self.data
            .iter()
            .filter(|d| d.synthetic_noise > 0.0)
            .map(|d| {
                // In mV, rounded to the microvolt.
                let mv = (d.synthetic_noise * 1e6).round() / 1e3;
                match data {
                    None => format!(
                        "synthetic Gaussian noise of {mv} mV (seed {}) was added to the voltage of `{}` (`data.synthetic_noise`)",
                        d.noise_seed,
                        d.file.display()
                    ),
                    Some(f) => format!(
                        "the study's `data.synthetic_noise` ({mv} mV) was not applied: `{}` (--data) is fitted as recorded",
                        f.display()
                    ),
                }
            })
            .collect()
    }

    /// The optimiser's name and options.
    pub fn optimiser(&self) -> Result<(String, OptimOptions), Error> {
        let mut table = self.optimiser.clone();
        let method = table.remove("method").and_then(|v| v.as_str().map(str::to_string)).unwrap_or_else(|| "lbfgsb".into());
        let options: OptimOptions = table
            .try_into()
            .map_err(|e: toml::de::Error| Error::InvalidSetting { field: "optimiser".into(), reason: e.to_string() })?;
        options.validate()?;
        Ok((method, options))
    }

    /// Reads recording `k`: `data` as recorded (for the first entry), or the study's own file
    /// with its synthetic noise added (when `synthetic_noise` is set). A raw cycler export
    /// (Basytec, BioLogic, Maccor, Neware, Arbin) is detected and read when `[data.format]`
    /// is the default.
    pub fn recording(&self, k: usize, data: Option<&Path>) -> Result<Recording, Error> {
        let d = &self.data[k];
        let data = data.filter(|_| k == 0);
        let field = if data.is_some() { "--data".to_string() } else { format!("data.{}.file", d.label(k)) };
        let mut rec = crate::data::cycler::read_recording(data.unwrap_or(&d.file), &d.format).map_err(|e| e.input(&field))?;
        if data.is_none() && d.synthetic_noise > 0.0 {
            let mut rng = rand::rngs::StdRng::seed_from_u64(d.noise_seed);
            let noise = Normal::new(0.0, d.synthetic_noise).expect("checked non-negative");
            for v in &mut rec.voltage {
                *v += noise.sample(&mut rng);
            }
        }
        Ok(rec)
    }

    /// The fitting problem of experiment `k` (its temperature, initial state and protocol),
    /// the number of its own parameters after the shared ones (1 with a fitted `initial_soc`,
    /// else 0) and the notes of the recording's checks against the cell (a likely unit error
    /// is an error before any fit).
    pub fn experiment_problem(&self, k: usize, data: Option<&Path>) -> Result<(FittingProblem, usize, Vec<String>), Error> {
        self.experiment_problem_on(self.cell.load()?, k, data)
    }

    /// [`experiment_problem`](Self::experiment_problem) on the parameter set `base` instead of
    /// the study's cell (a parameterisation stage fits on the set the stages before left).
    pub fn experiment_problem_on(&self, mut base: crate::params::ParameterSet, k: usize, data: Option<&Path>) -> Result<(FittingProblem, usize, Vec<String>), Error> {
        self.check_data_override(data)?;
        let d = &self.data[k];
        if let Some(t) = d.temperature {
            base.set("thermal.ambient_temperature", t)?;
            base.set("thermal.initial_temperature", t)?;
        }
        let mut parameters = self.parameters.clone();
        match d.initial_soc {
            Some(InitialSoc::Fixed(v)) => {
                crate::params::set_initial_soc(&mut base, v)?;
            }
            Some(InitialSoc::Fitted { initial, lower, upper }) => parameters.push(FitParameter::linear(INITIAL_SOC, initial, lower, upper)),
            None => {}
        }
        let own = parameters.len() - self.parameters.len();
        let recording = self.recording(k, data)?;
        let file = data.filter(|_| k == 0).unwrap_or(&d.file).display().to_string();
        let notes = recording.refuse_unit_errors(&file, &base)?;
        let mut problem = FittingProblem::new(self.model, base, parameters, recording)?;
        if d.start_at_rest_voltage {
            problem = problem.starting_at_rest()?;
        }
        if let Some(path) = &d.protocol {
            let text = std::fs::read_to_string(path).map_err(|e| Error::io(path)(e).input(&format!("data.{}.protocol", d.label(k))))?;
            let protocol = toml::from_str(&text).map_err(|e| Error::Parse { path: path.display().to_string(), message: e.to_string() })?;
            problem = problem.with_protocol(protocol)?;
        }
        Ok((problem, own, notes))
    }

    /// The fitting problem of a study with one experiment and no parameters of its own.
    pub fn problem(&self, data: Option<&Path>) -> Result<FittingProblem, Error> {
        self.problem_and_notes(data).map(|(problem, _)| problem)
    }

    /// [`problem`](Self::problem), and the recording checks' notes; a likely unit error in the
    /// recording (minutes read as seconds, mA as A) is an error before any fit.
    pub fn problem_and_notes(&self, data: Option<&Path>) -> Result<(FittingProblem, Vec<String>), Error> {
        self.check_data_override(data)?;
        if self.is_joint() {
            return Err(Error::InvalidSetting {
                field: "data".into(),
                reason: format!("the study fits {} experiments jointly (or fits an initial_soc): this run takes one [data] without fitted initial_soc", self.data.len()),
            });
        }
        let (problem, _, notes) = self.experiment_problem(0, data)?;
        Ok((problem, notes))
    }
}

/// What a fit produced.
pub struct FitOutcome {
    pub result: FitResult,
    /// RMS residual at the initial parameters (V).
    pub initial_rmse: f64,
    pub files: Vec<PathBuf>,
    /// Notes (synthetic noise) and warnings (parameters at a bound, a truncated search), also
    /// in the report.
    pub notes: Vec<String>,
    pub warnings: Vec<String>,
    /// Fitted parameters that ended on a bound of their search range: no estimate of them.
    pub at_bound: Vec<super::OnBound>,
    /// Each experiment's share of a joint fit (empty for one experiment).
    pub experiments: Vec<crate::problem::joint::ExperimentFit>,
    /// Why the run gives no estimate and must exit with an error (a parameter on a bound);
    /// its outputs then went to the output folder's `NAME.rejected` sibling, which it names.
    pub rejection: Option<Error>,
}

/// The error a run exits with when its fit ended with parameters on a bound of their search
/// range (`None` when none did): it names each parameter and its bound, and the `NAME.rejected`
/// folder of `out` its outputs go to (the caller moves them there with
/// [`OutputDir::reject`](crate::output::OutputDir::reject)). `then` says what the run did not
/// go on to do (e.g. `"; nothing was sampled"`).
pub(crate) fn on_bound_rejection(at_bound: &[super::OnBound], then: &str, out: &crate::output::OutputDir) -> Option<Error> {
    let first = at_bound.first()?;
    let listed = at_bound.iter().map(ToString::to_string).collect::<Vec<_>>().join(", ");
    Some(Error::InvalidSetting {
        field: format!("parameters.{}", first.name),
        reason: format!(
            "the fit ended on a bound of the search range, so it gives no estimate ({listed}){then}; \
             its outputs are written for inspection to `{}` and the results in `{}` are left as they were; \
             widen lower/upper or check the recording's units",
            out.rejected().display(),
            out.target().display()
        ),
    })
}

/// Fewest residual degrees of freedom (points less fitted parameters) without a warning.
const MIN_DEGREES_OF_FREEDOM: usize = 10;

/// The fit of a study with one recording, writing into `dir` (a staged output folder).
pub(crate) fn single_fit_into(study: &FitStudy, data: Option<&Path>, dir: &Path) -> Result<FitOutcome, Error> {
    let (problem, checks) = study.problem_and_notes(data)?;
    let (method, options) = study.optimiser()?;
    let x0 = problem.initial();
    let initial_voltage = problem.simulate(&x0).map_err(|why| problem.start_failure(&x0, "data", why))?;
    let initial_rmse = crate::stats::weighted_rms(&problem.residuals(&initial_voltage), &problem.weights);
    let result = fit(&problem, study.cost, &method, options)?;
    let notes: Vec<String> = study.noise_note(data).into_iter().chain(checks).collect();
    let (at_bound, mut warnings) = super::fitted_on_bounds("the fit", &problem.parameters, &result.x);
    warnings.extend(super::truncation_warning("the fit", &result.stop, result.iterations, result.evaluations));
    let points = problem.weights.iter().filter(|w| **w > 0.0).count();
    if points < problem.dim() + MIN_DEGREES_OF_FREEDOM {
        warnings.push(format!(
            "{points} points for {} fitted parameters leave {} degrees of freedom: the fit can follow the noise, and its standard errors are not reliable",
            problem.dim(),
            points.saturating_sub(problem.dim())
        ));
    }
    let mut files = fit_plots(dir, &study.name, "", &problem, &initial_voltage, &result.voltage)?;
    if let (Some(l), true) = (&study.landscape, problem.dim() >= 2) {
        let path = dir.join("landscape.svg");
        super::landscape::landscape(&problem, study.cost, &result, l.points, &path)?;
        files.push(path);
    }
    write_output(dir, "fit.json", serde_json::to_string_pretty(&result).expect("serialisable"), &mut files)?;
    let mut md = report(study, &problem, &result, initial_rmse);
    let sections = [
        study.profile.as_ref().map(|s| super::profiles::write_profiles(dir, &study.name, &problem, &result, s)).transpose()?,
        study.experiment_design.as_ref().map(|s| super::experiment_design::write_design(dir, &problem, &result, s)).transpose()?,
        study.sobol.as_ref().map(|s| super::sobol::write_sobol(dir, &problem, s)).transpose()?,
    ];
    for section in sections.into_iter().flatten() {
        md.push_str(&section.section);
        files.extend(section.files);
        warnings.extend(section.warnings);
    }
    write_output(dir, "report.md", with_notes(md, &notes, &warnings), &mut files)?;
    Ok(FitOutcome { result, initial_rmse, files, notes, warnings, at_bound, experiments: Vec::new(), rejection: None })
}

/// `fit_voltage<suffix>.svg` (data, initial and fitted voltage) and `fit_residual<suffix>.svg`
/// (initial and fitted residual in mV) of one experiment, written into `dir`.
pub(crate) fn fit_plots(dir: &Path, title: &str, suffix: &str, problem: &FittingProblem, initial: &[f64], fitted: &[f64]) -> Result<Vec<PathBuf>, Error> {
    let t = &problem.data.time;
    let voltage = dir.join(format!("fit_voltage{suffix}.svg"));
    line_plot(
        &voltage,
        &format!("{title}: voltage"),
        "time (s)",
        "voltage (V)",
        &[
            Series { label: "data".into(), x: t, y: &problem.data.voltage },
            Series { label: "initial".into(), x: t, y: initial },
            Series { label: "fitted".into(), x: t, y: fitted },
        ],
    )?;
    let mv = |v: &[f64]| problem.residuals(v).iter().map(|r| 1e3 * r).collect::<Vec<_>>();
    let residual = dir.join(format!("fit_residual{suffix}.svg"));
    line_plot(
        &residual,
        &format!("{title}: residual (model - data)"),
        "time (s)",
        "residual (mV)",
        &[Series { label: "initial".into(), x: t, y: &mv(initial) }, Series { label: "fitted".into(), x: t, y: &mv(fitted) }],
    )?;
    Ok(vec![voltage, residual])
}

/// A report with its notes and warnings appended.
pub(crate) fn with_notes(mut md: String, notes: &[String], warnings: &[String]) -> String {
    for n in notes {
        let _ = writeln!(md, "\nNote: {n}.");
    }
    for w in warnings {
        let _ = writeln!(md, "\n**Warning:** {w}.");
    }
    md
}

fn report(study: &FitStudy, problem: &FittingProblem, r: &FitResult, initial_rmse: f64) -> String {
    let mut s = String::new();
    let _ = writeln!(s, "# {}\n", study.name);
    let _ = writeln!(
        s,
        "Fitted {} parameter(s) of the {} model to {} recorded points by {} with the {} optimiser: \
         RMSE {:.3} mV (initial {:.3} mV), {} evaluations and {} gradients in {:.2} s, stop: {:?}.\n",
        problem.dim(),
        problem.spec,
        problem.weights.iter().filter(|w| **w > 0.0).count(),
        study.cost.name(),
        study.optimiser().map(|o| o.0).unwrap_or_default(),
        r.rmse * 1e3,
        initial_rmse * 1e3,
        r.evaluations,
        r.gradient_evaluations,
        r.seconds,
        r.stop
    );
    s.push_str(&parameter_table(r));
    s
}

/// Markdown table of fitted values, standard errors, what the data determine
/// ([`crate::problem::verdict`]) and correlations.
pub fn parameter_table(r: &FitResult) -> String {
    let mut s = String::from("| parameter | value | std. error | rel. error | verdict |\n|---|---|---|---|---|\n");
    for (k, name) in r.names.iter().enumerate() {
        let (v, e) = (r.x[k], r.std_errors.get(k).copied().unwrap_or(f64::NAN));
        let verdict = r.standings.get(k).map(|s| s.describe()).unwrap_or_default();
        let _ = writeln!(s, "| {name} | {v:.5e} | {e:.3e} | {:.2}% | {verdict} |", 100.0 * e / v.abs());
    }
    if let Some((parts, rel)) = crate::problem::verdict::sloppiest(&r.names, &r.x, &r.std_errors, &r.correlation) {
        let combination: Vec<String> = parts.iter().map(|(n, c)| format!("{c:+.2} ln {n}")).collect();
        let _ = writeln!(s, "\nLeast determined combination: {} (relative standard error {:.1} %).", combination.join(" "), 100.0 * rel);
    }
    if r.correlation.len() > 1 {
        s.push_str("\nCorrelation matrix:\n\n|   |");
        let p = r.correlation.len();
        for name in &r.names[..p] {
            let _ = write!(s, " {name} |");
        }
        s.push_str("\n|---|");
        s.push_str(&"---|".repeat(p));
        s.push('\n');
        for (a, row) in r.correlation.iter().enumerate() {
            let _ = write!(s, "| {} |", r.names[a]);
            for c in row {
                let _ = write!(s, " {c:+.3} |");
            }
            s.push('\n');
        }
    }
    s
}

/// Each fitted parameter's path with its field in the study (`{list}[k].path`), for errors
/// that name the field.
pub(crate) fn fitted_paths<'a>(list: &'a str, parameters: &'a [FitParameter]) -> impl Iterator<Item = (String, &'a str)> + 'a {
    parameters.iter().enumerate().map(move |(k, p)| (format!("{list}[{k}].path"), p.path.as_str()))
}
