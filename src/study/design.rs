//! Running a study's single-objective design search: projected, bounded optimisation of one
//! density metric, with a report (Markdown + JSON) and initial vs optimised voltage plots.

use super::write_output;
use std::fmt::Write as _;
use std::path::PathBuf;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::time::Instant;

use super::Study;
use crate::error::Error;
use crate::optim::{
    Bounds, Objective, OptimOptions, OptimResult, Problem, ProgressObserver, by_name,
};
use crate::problem::design::{DesignMetrics, DesignProblem, Metric};
use crate::report::plot::{Series, line_plot};
use crate::simulation::{SimOptions, simulate};

/// Minimises minus the chosen metric; a failed simulation or a discharge that stops early
/// (below `min_utilisation`) is penalised (+inf) and the search goes on; a design outside the
/// limits scores [`OUTSIDE_LIMITS`] plus its relative violation, worse than any inside.
struct MaximiseMetric<'a> {
    problem: &'a DesignProblem,
    metric: Metric,
    min_utilisation: f64,
    /// A design outside these is penalised like a failed one.
    limits: &'a [super::limits::Limit],
    /// Evaluations over every start, those whose simulation failed and those that stopped
    /// early (both penalised): the report says how much of the search found no design.
    evaluated: AtomicUsize,
    failed: AtomicUsize,
    stopped_early: AtomicUsize,
}

/// The score of a design outside the limits before its violation is added: above minus any
/// metric's value (densities are below 10^5).
const OUTSIDE_LIMITS: f64 = 1e9;

/// Starts that end further apart than this fraction of the best are reported as different
/// local optima.
const MULTI_START_SPREAD: f64 = 1e-3;

/// The most sweep points `design` evaluates to check its optimum against the study's grid
/// (the seed's 169 take 0.2 s; a larger grid is `sweep`'s job).
const SWEEP_CHECK_LIMIT: usize = 2000;

impl Objective for MaximiseMetric<'_> {
    fn dim(&self) -> usize {
        self.problem.variables.len()
    }
    fn evaluate(&self, x: &[f64]) -> f64 {
        self.evaluated.fetch_add(1, Ordering::Relaxed);
        match self.problem.evaluate(x) {
            Ok(m) if !m.stopped_early(self.min_utilisation) => match super::limits::violation(self.limits, &m) {
                0.0 => -m.get(self.metric),
                v => OUTSIDE_LIMITS + v,
            },
            Ok(_) => {
                self.stopped_early.fetch_add(1, Ordering::Relaxed);
                f64::INFINITY
            }
            Err(_) => {
                self.failed.fetch_add(1, Ordering::Relaxed);
                f64::INFINITY
            }
        }
    }
}

/// What a design search produced.
pub struct DesignOutcome {
    pub metric: Metric,
    pub initial_x: Vec<f64>,
    pub initial: DesignMetrics,
    pub result: OptimResult,
    pub optimised: DesignMetrics,
    pub rebuilds: usize,
    pub seconds: f64,
    pub files: Vec<PathBuf>,
    /// Warnings also written into the report (optimum on a bound).
    pub warnings: Vec<String>,
    /// The study's limits active at the optimum, in words.
    pub active_limits: Vec<String>,
    /// The metric each start of the search ended at (`[optimiser] starts`), the baseline's
    /// first.
    pub start_values: Vec<f64>,
    /// When the study has a `[sweep]` table: the best valid grid point and its metric, a
    /// check that the search did not stop short of what a grid finds.
    pub sweep_best: Option<(Vec<f64>, f64)>,
}

impl DesignOutcome {
    /// Relative improvement of the metric (%).
    pub fn improvement(&self) -> f64 {
        100.0 * (self.optimised.get(self.metric) / self.initial.get(self.metric) - 1.0)
    }
}

/// Runs the study's optimiser on its first objective from the baseline design.
pub fn run_design(study: &Study) -> Result<DesignOutcome, Error> {
    if study.objective.maximise.len() != 1 {
        let names: Vec<&str> = study.objective.maximise.iter().map(|m| m.label()).collect();
        return Err(Error::InvalidSetting {
            field: "objective.maximise".into(),
            reason: format!("`design` maximises one objective, the study names {} ({}); use `pareto` for several", names.len(), names.join(", ")),
        });
    }
    let metric = study.objective.maximise[0];
    let problem = study.problem()?;
    let mut table = study.optimiser.clone();
    let method = table
        .remove("method")
        .and_then(|v| v.as_str().map(str::to_string))
        .unwrap_or_else(|| "nelder-mead".into());
    let starts = match table.remove("starts") {
        None => 1,
        Some(v) => v.as_integer().filter(|n| *n >= 1).ok_or_else(|| Error::InvalidSetting {
            field: "optimiser.starts".into(),
            reason: format!("must be a whole number of at least 1, got {v}"),
        })? as usize,
    };
    let options: OptimOptions = table
        .try_into()
        .map_err(|e: toml::de::Error| Error::InvalidSetting { field: "optimiser".into(), reason: e.to_string() })?;
    let mut optimiser = by_name(&method, options.clone())?;
    let dir = study.output_dir()?;
    let objective = MaximiseMetric { problem: &problem, metric, min_utilisation: study.operating.min_utilisation(), limits: &study.limits, evaluated: AtomicUsize::new(0), failed: AtomicUsize::new(0), stopped_early: AtomicUsize::new(0) };
    let bounds = Bounds::new(
        study.variables.iter().map(|v| v.lower).collect(),
        study.variables.iter().map(|v| v.upper).collect(),
    )?;
    let transforms = study.variables.iter().map(|v| v.transform()).collect();
    let opt_problem = Problem::new(&objective, bounds)?.with_constraints(super::constraints::linear_constraints(study))?.with_transforms(transforms)?;
    let start = Instant::now();
    let initial_x = study.baseline()?;
    let initial = problem.evaluate(&initial_x)?;
    let x0 = opt_problem.project(&initial_x)?;
    let mut observer = ProgressObserver::new("design", options.max_iterations, |f| format!("best {:.3}", -f));
    let mut result = optimiser.minimise(&opt_problem, &x0, &mut observer)?;
    observer.finish();
    // More starts, when asked: seeded Latin-hypercube points over the bounds, each searched
    // the same way; the best end is kept and the spread of the ends reported.
    let mut start_values = vec![-result.f];
    if starts > 1 {
        let (lo, hi): (Vec<f64>, Vec<f64>) = study.variables.iter().map(|v| (v.lower, v.upper)).unzip();
        for x in crate::problem::sweep::latin_hypercube(&lo, &hi, starts - 1, options.seed) {
            let other = by_name(&method, options.clone())?.minimise(&opt_problem, &opt_problem.project(&x)?, &mut crate::optim::NoObserver)?;
            start_values.push(-other.f);
            if other.f < result.f {
                result = other;
            }
        }
    }
    let optimised = problem.evaluate(&result.x)
        .map_err(|e| Error::InvalidSetting { field: "design".into(), reason: format!("no valid design: the optimum at {:?} fails: {e}", result.x) })?;
    let value = optimised.get(metric);
    if !super::limits::all_hold(&study.limits, &optimised) {
        let limits: Vec<String> = study.limits.iter().filter(|l| !l.holds(&optimised)).map(super::limits::Limit::describe).collect();
        return Err(Error::InvalidSetting {
            field: "limits".into(),
            reason: format!("no valid design: no candidate the search evaluated keeps {} (the best, at {:?}, does not)", limits.join(", "), result.x),
        });
    }
    if !(value > 0.0 && value.is_finite()) || super::degenerate(&optimised, &initial) {
        return Err(Error::InvalidSetting {
            field: "design".into(),
            reason: format!(
                "no valid design: the optimum at {:?} stores {} W h against the baseline's {} W h ({} = {}, degenerate); check the variables' bounds",
                result.x, crate::error::number(optimised.energy), crate::error::number(initial.energy), metric.label(), crate::error::number(value)
            ),
        });
    }
    let min_u = study.operating.min_utilisation();
    if optimised.stopped_early(min_u) {
        // The search ranks such designs below every valid one: none it evaluated was valid.
        return Err(Error::InvalidSetting {
            field: "design".into(),
            reason: format!(
                "no valid design: the optimum at {:?} stops early, delivering {:.1} % of its theoretical capacity (threshold {:.0} %, operating.min_utilisation); lower operating.c_rate or widen the variables' bounds",
                result.x,
                100.0 * optimised.utilisation,
                100.0 * min_u
            ),
        });
    }
    let seconds = start.elapsed().as_secs_f64();
    let names: Vec<String> = study.variables.iter().map(|v| v.path.clone()).collect();
    let lower: Vec<f64> = study.variables.iter().map(|v| v.lower).collect();
    let upper: Vec<f64> = study.variables.iter().map(|v| v.upper).collect();
    let mut warnings = study.warnings();
    warnings.extend(super::at_bound_warnings("the optimum", &names, &result.x, &lower, &upper));
    warnings.extend(super::truncation_warning("the design search", &result.stop, result.iterations, result.evaluations));
    let evaluations = objective.evaluated.load(Ordering::Relaxed);
    for (count, what) in [(objective.failed.load(Ordering::Relaxed), "failed to simulate"), (objective.stopped_early.load(Ordering::Relaxed), "stopped early")] {
        if count > 0 {
            warnings.push(format!(
                "{count} of the {evaluations} designs the search evaluated {what} and were ranked below every valid design; the optimum may sit on the edge of the region where that happens"
            ));
        }
    }
    if initial.stopped_early(min_u) {
        warnings.push(format!("the baseline's discharge stops early: it delivers {:.1} % of its theoretical capacity (threshold {:.0} %)", 100.0 * initial.utilisation, 100.0 * min_u));
    }
    if !super::limits::all_hold(&study.limits, &initial) {
        let limits: Vec<String> = study.limits.iter().filter(|l| !l.holds(&initial)).map(super::limits::Limit::describe).collect();
        warnings.push(format!("the baseline lies outside the limits ({}): the improvement compares with a design that does not qualify", limits.join(", ")));
    }
    let (worst, best) = start_values.iter().filter(|v| v.is_finite()).fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| (a.min(*v), b.max(*v)));
    if starts > 1 && best - worst > MULTI_START_SPREAD * best.abs() {
        warnings.push(format!(
            "the {starts} starts ended between {} and {} ({}): the search finds different local optima; the best is kept",
            crate::error::number(worst),
            crate::error::number(best),
            metric.label()
        ));
    }
    // Counted before the points are made: a large grid is `sweep`'s job, not held here.
    let grid = match study.sweep.as_ref().and_then(super::Sweep::size) {
        Some(n) if n > SWEEP_CHECK_LIMIT => {
            warnings.push(format!("the study's sweep has {n} points, more than the {SWEEP_CHECK_LIMIT} `design` evaluates as a check: run `sweep` to compare"));
            Vec::new()
        }
        Some(_) => super::sweep::sweep_candidates(study)?,
        None => Vec::new(),
    };
    let sweep_best = match grid.len() {
        1..=SWEEP_CHECK_LIMIT => {
            let points = super::sweep::evaluate_points(study, &problem, &initial, grid)?;
            points
                .into_iter()
                .filter(|p| p.status == crate::problem::sweep::Status::Valid)
                .filter_map(|p| p.metrics.map(|m| (p.x, m.get(metric))))
                .max_by(|a, b| a.1.total_cmp(&b.1))
        }
        _ => None,
    };
    if let Some((x, v)) = &sweep_best {
        if *v > value * (1.0 + MULTI_START_SPREAD) {
            warnings.push(format!("the sweep's best grid point, {} at {x:?}, beats the search's optimum ({}): the search stopped short", crate::error::number(*v), crate::error::number(value)));
        }
    }
    let active_limits = super::limits::active(&study.limits, &optimised);
    let mut outcome = DesignOutcome {
        metric,
        initial_x,
        initial,
        result,
        optimised,
        rebuilds: problem.rebuild_count(),
        seconds,
        files: Vec::new(),
        warnings,
        active_limits,
        start_values,
        sweep_best,
    };
    write_outputs(study, &problem, &mut outcome, &method, dir.path())?;
    outcome.files = dir.commit(&outcome.files)?;
    Ok(outcome)
}

fn write_outputs(study: &Study, problem: &DesignProblem, out: &mut DesignOutcome, method: &str, dir: &std::path::Path) -> Result<(), Error> {
    let names: Vec<&str> = study.variables.iter().map(|v| v.path.as_str()).collect();
    let json = serde_json::json!({
        "study": study.name, "variables": names, "method": method,
        "initial": { "x": out.initial_x, "metrics": out.initial },
        "optimised": { "x": out.result.x, "metrics": out.optimised },
        "format": problem.format.label(),
        "mass_basis": { "initial": problem.mass_basis(&problem.parameters(&out.initial_x)?)?, "optimised": problem.mass_basis(&problem.parameters(&out.result.x)?)? },
        "result": out.result, "rebuilds": out.rebuilds, "seconds": out.seconds, "warnings": out.warnings,
        "limits": study.limits, "active_limits": out.active_limits, "start_values": out.start_values, "sweep_best": out.sweep_best,
    });
    write_output(dir, "design.json", serde_json::to_string_pretty(&json).unwrap_or_default(), &mut out.files)?;

    // Voltage profiles of the initial and optimised designs.
    let mut curves = Vec::new();
    for (label, x) in [("initial", &out.initial_x), ("optimised", &out.result.x)] {
        let p = problem.parameters(x)?;
        let mut builder = crate::models::ModelBuilder::new(problem.kind, problem.submodels, problem.mesh);
        let built = builder.build(&p)?;
        let sol = simulate(built.model.as_ref(), &mut built.workspace, &problem.protocol(&p), &SimOptions::for_cell(&p), None)?;
        curves.push((label.to_string(), sol.capacity, sol.voltage));
    }
    let plot = dir.join("design_voltage.svg");
    let series: Vec<Series> = curves.iter().map(|(l, q, v)| Series { label: l.clone(), x: q, y: v }).collect();
    line_plot(&plot, &format!("{}: discharge", study.name), "Discharged capacity (A h)", "Voltage (V)", &series)?;
    out.files.push(plot);

    let mut md = String::new();
    let _ = writeln!(md, "# {}\n", study.name);
    let _ = writeln!(md, "Maximised {} with {method} ({:?} after {} iterations, {} evaluations, {} model builds, {:.2} s).\n",
        out.metric.label(), out.result.stop, out.result.iterations, out.result.evaluations, out.rebuilds, out.seconds);
    let _ = writeln!(md, "| | {} | energy (W h) | capacity (A h) | area (m^2) | mass (g) | volume (cm^3) | W h/kg | W h/L | W/kg | W/L |", names.join(" | "));
    let _ = writeln!(md, "|---|{}{}", "---|".repeat(names.len()), "---|".repeat(9));
    for (label, x, m) in [("initial", &out.initial_x, &out.initial), ("optimised", &out.result.x, &out.optimised)] {
        let xs: Vec<String> = x.iter().map(|v| format!("{v:.4e}")).collect();
        let _ = writeln!(md, "| {label} | {} | {:.3} | {:.3} | {:.4} | {:.2} | {:.3} | {:.1} | {:.1} | {:.1} | {:.1} |", xs.join(" | "),
            m.energy, m.capacity, m.area, m.mass * 1e3, m.volume * 1e6, m.gravimetric_energy_density, m.volumetric_energy_density,
            m.gravimetric_power_density, m.volumetric_power_density);
    }
    let _ = writeln!(md, "\nImprovement: {:+.2} %.\n", out.improvement());
    if let Some((x, v)) = &out.sweep_best {
        let xs: Vec<String> = x.iter().map(|v| format!("{v:.4e}")).collect();
        let _ = writeln!(md, "Against the study's sweep: its best valid grid point is {v:.2} at [{}]; the search's optimum is {:.2}.\n", xs.join(", "), out.optimised.get(out.metric));
    }
    if out.start_values.len() > 1 {
        let ends: Vec<String> = out.start_values.iter().map(|v| format!("{v:.2}")).collect();
        let _ = writeln!(md, "Multi-start: {} starts (the baseline, then seeded Latin-hypercube points) ended at {}; the best is reported.\n", ends.len(), ends.join(", "));
    }
    if !study.limits.is_empty() {
        let all: Vec<String> = study
            .limits
            .iter()
            .map(|l| format!("{} (initial {:.4}, optimised {:.4})", l.describe(), out.initial.get(l.metric), out.optimised.get(l.metric)))
            .collect();
        let active = if out.active_limits.is_empty() { "none".to_string() } else { out.active_limits.join(", ") };
        let _ = writeln!(md, "Limits: {}; active at the optimum (within {:.0} % of the bound): {active}.\n", all.join(", "), 100.0 * super::limits::ACTIVE_WITHIN);
    }
    for w in &out.warnings {
        let _ = writeln!(md, "**Warning:** {w}\n");
    }
    let _ = writeln!(md, "{}\n", super::basis::power_definition(problem, study.operating.min_utilisation()));
    let _ = writeln!(md, "![voltage](design_voltage.svg)\n");
    md.push_str(&super::basis::mass_basis_section(problem, &[("initial", &out.initial_x), ("optimised", &out.result.x)])?);
    write_output(dir, "report.md", md, &mut out.files)?;
    Ok(())
}
