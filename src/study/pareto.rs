//! Running a study's multi-objective search: NSGA-II over the decision variables, the
//! non-dominated front as CSV/JSON and a plot with the baseline marked.

use super::write_output;
use std::fmt::Write as _;
use std::path::PathBuf;
use std::time::Instant;

use super::Study;
use crate::error::Error;
use std::sync::atomic::{AtomicUsize, Ordering};

use crate::optim::Bounds;
use crate::optim::nsga2::{Individual, Nsga2Options, nsga2};
use crate::report::plot::scatter_plot;

/// What a Pareto search produced.
pub struct ParetoOutcome {
    pub front: Vec<Individual>,
    pub evaluated: usize,
    /// Designs whose simulation failed.
    pub failed: usize,
    /// Designs whose discharge stopped early (below `operating.min_utilisation`).
    pub stopped_early: usize,
    /// Candidates outside the linear constraints, projected onto them before evaluation.
    pub repaired: usize,
    pub baseline: Vec<f64>,
    pub rebuilds: usize,
    pub seconds: f64,
    pub files: Vec<PathBuf>,
    /// Warnings also written into `pareto_front.json` and `report.md`.
    pub warnings: Vec<String>,
}

/// The names `[optimiser] method` may give for NSGA-II, the only multi-objective optimiser.
const NSGA2_NAMES: [&str; 4] = ["nsga2", "nsga-ii", "nsga_ii", "nsga-2"];

/// The study's `[optimiser]` table as [`Nsga2Options`]; a method other than NSGA-II is an
/// error naming it.
fn nsga2_options(study: &Study) -> Result<Nsga2Options, Error> {
    let mut table = study.optimiser.clone();
    if let Some(method) = table.remove("method") {
        let name = method.as_str().unwrap_or_default().to_ascii_lowercase();
        if !NSGA2_NAMES.contains(&name.as_str()) {
            return Err(Error::InvalidSetting {
                field: "optimiser.method".into(),
                reason: format!("`pareto` runs NSGA-II (method = \"nsga2\"); {method} is a single-objective optimiser: use it with `design`"),
            });
        }
    }
    let opts: Nsga2Options = table.try_into().map_err(|e: toml::de::Error| Error::InvalidSetting { field: "optimiser".into(), reason: e.to_string() })?;
    opts.validate()?;
    // Every design of every generation is kept (the archive behind the plots and counts).
    let designs = opts.population as f64 * (opts.generations as f64 + 1.0);
    let given = format!("population = {} with {} generations", opts.population, opts.generations);
    super::check_design_count("optimiser.population", &given, designs)?;
    Ok(opts)
}

/// Runs NSGA-II with the study's `[optimiser]` table as [`Nsga2Options`]: candidates outside
/// the linear constraints are projected onto them, designs that fail or whose discharge
/// stops early are kept out of the front and counted.
pub fn run_pareto(study: &Study) -> Result<ParetoOutcome, Error> {
    let metrics = &study.objective.maximise;
    if metrics.len() < 2 {
        return Err(Error::InvalidSetting {
            field: "objective.maximise".into(),
            reason: format!("pareto needs two or more objectives, got {}", metrics.len()),
        });
    }
    if let Some((k, m)) = metrics.iter().enumerate().find(|(k, m)| metrics[..*k].contains(m)) {
        return Err(Error::InvalidSetting { field: format!("objective.maximise[{k}]"), reason: format!("{} is listed twice", m.label()) });
    }
    let opts = nsga2_options(study)?;
    let problem = study.problem()?;
    let feasibility = super::constraints::Feasibility::of(study)?;
    let out = study.output_dir()?;
    let bounds = Bounds::new(study.variables.iter().map(|v| v.lower).collect(), study.variables.iter().map(|v| v.upper).collect())?;
    let min_u = study.operating.min_utilisation();
    let (failed, early, repaired, outside) = (AtomicUsize::new(0), AtomicUsize::new(0), AtomicUsize::new(0), AtomicUsize::new(0));
    // Objectives of the designs that stopped early, for the plot only.
    let truncated = std::sync::Mutex::new(Vec::new());
    let excluded = vec![f64::NEG_INFINITY; metrics.len()];
    let evaluate = |x: &[f64]| match problem.evaluate(x) {
        Ok(m) if m.stopped_early(min_u) => {
            early.fetch_add(1, Ordering::Relaxed);
            if let Ok(mut t) = truncated.lock() {
                t.push((m.get(metrics[0]), m.get(metrics[1])));
            }
            excluded.clone()
        }
        Ok(m) if !super::limits::all_hold(&study.limits, &m) => {
            outside.fetch_add(1, Ordering::Relaxed);
            excluded.clone()
        }
        Ok(m) if feasibility.is_feasible(x) => metrics.iter().map(|&k| m.get(k)).collect(),
        _ => {
            failed.fetch_add(1, Ordering::Relaxed);
            excluded.clone()
        }
    };
    let repair = |x: &[f64]| {
        if feasibility.is_feasible(x) {
            return x.to_vec();
        }
        repaired.fetch_add(1, Ordering::Relaxed);
        feasibility.repair(x).unwrap_or_else(|_| x.to_vec())
    };
    let start = Instant::now();
    let baseline_m = problem.evaluate(&study.baseline()?)?;
    let baseline: Vec<f64> = metrics.iter().map(|&k| baseline_m.get(k)).collect();
    let bar = crate::progress::bar("pareto", opts.generations as u64, "pareto {bar:30} {pos}/{len} generations [{elapsed}]");
    let (front, archive) = nsga2(&bounds, &opts, &evaluate, &repair, &mut |g| bar.set_position(g as u64));
    bar.finish_and_clear();
    let seconds = start.elapsed().as_secs_f64();

    let (failed, stopped_early, repaired, outside) = (failed.into_inner(), early.into_inner(), repaired.into_inner(), outside.into_inner());
    let front: Vec<Individual> = front.into_iter().filter(|i| i.f.iter().all(|v| v.is_finite())).collect();
    if front.is_empty() {
        return Err(Error::InvalidSetting {
            field: "pareto".into(),
            reason: format!("no valid design (nothing written): of {} designs {failed} failed, {stopped_early} stopped early and {outside} lie outside the limits", archive.len()),
        });
    }
    let mut warnings = study.warnings();
    if failed > 0 {
        warnings.push(format!("{failed} of {} designs failed (kept out of the front)", archive.len()));
    }
    if outside > 0 {
        let limits: Vec<String> = study.limits.iter().map(super::limits::Limit::describe).collect();
        warnings.push(format!("{outside} of {} designs lie outside the limits ({}; kept out of the front)", archive.len(), limits.join(", ")));
    }
    if stopped_early > 0 {
        warnings.push(format!(
            "{stopped_early} of {} designs stopped early: they delivered less than {:.0} % of their theoretical capacity (kept out of the front)",
            archive.len(),
            100.0 * min_u
        ));
    }
    let dir = out.path();
    let names: Vec<String> = study.variables.iter().map(|v| v.path.clone()).collect();
    let objectives: Vec<String> = metrics.iter().map(|m| serde_json::to_value(m).unwrap_or_default().as_str().unwrap_or("").to_string()).collect();
    let mut csv = format!("{},{}\n", names.join(","), objectives.join(","));
    let mut sorted = front.clone();
    sorted.sort_by(|a, b| a.f[0].total_cmp(&b.f[0]));
    sorted.dedup_by(|a, b| a.x == b.x);
    for ind in &sorted {
        let cols: Vec<String> = ind.x.iter().chain(&ind.f).map(|v| v.to_string()).collect();
        let _ = writeln!(csv, "{}", cols.join(","));
    }
    let mut files = Vec::new();
    write_output(dir, "pareto_front.csv", csv, &mut files)?;
    let json = serde_json::json!({ "study": study.name, "variables": names, "objectives": objectives,
        "baseline": baseline, "front": sorted, "evaluated": archive.len(), "failed": failed, "stopped_early": stopped_early, "repaired": repaired,
        "power_definition": super::basis::power_definition(&problem, min_u), "warnings": warnings, "seconds": seconds });
    write_output(dir, "pareto_front.json", serde_json::to_string_pretty(&json).unwrap_or_default(), &mut files)?;
    let counts = Counts { evaluated: archive.len(), failed, stopped_early, repaired };
    write_output(dir, "report.md", report(study, &problem, &counts, &sorted, &baseline, &warnings)?, &mut files)?;
    let plot = dir.join("pareto_front.svg");
    let pts = |set: &[Individual]| set.iter().map(|i| (i.f[0], i.f[1])).collect::<Vec<_>>();
    scatter_plot(
        &plot,
        &study.name,
        (metrics[0].label(), metrics[1].label()),
        &[
            ("stopped early (excluded)".into(), truncated.into_inner().unwrap_or_default()),
            ("evaluated designs".into(), pts(&archive)),
            ("non-dominated front".into(), pts(&sorted)),
        ],
        Some(("baseline".into(), (baseline[0], baseline[1]))),
    )?;
    files.push(plot);
    let files = out.commit(&files)?;
    Ok(ParetoOutcome {
        front: sorted,
        evaluated: archive.len(),
        failed,
        stopped_early,
        repaired,
        baseline,
        rebuilds: problem.rebuild_count(),
        seconds,
        files,
        warnings,
    })
}

/// How many designs were evaluated, and how many of them were kept out of the front.
struct Counts {
    evaluated: usize,
    failed: usize,
    stopped_early: usize,
    repaired: usize,
}

/// `report.md`: counts, the power definition, the front as a table, the baseline's mass basis.
fn report(study: &Study, problem: &crate::problem::design::DesignProblem, c: &Counts, front: &[Individual], baseline: &[f64], warnings: &[String]) -> Result<String, Error> {
    let metrics = &study.objective.maximise;
    let mut md = format!("# {}\n\nNSGA-II over {} designs: {} on the front; {} failed and {} stopped early (both kept out of the front); {} candidates outside the linear constraints were projected onto them.\n\n",
        study.name, c.evaluated, front.len(), c.failed, c.stopped_early, c.repaired);
    let _ = writeln!(md, "{}\n", super::basis::power_definition(problem, study.operating.min_utilisation()));
    for w in warnings {
        let _ = writeln!(md, "**Warning:** {w}\n");
    }
    let names: Vec<&str> = study.variables.iter().map(|v| v.path.as_str()).collect();
    let labels: Vec<&str> = metrics.iter().map(|m| m.label()).collect();
    let _ = writeln!(md, "| | {} | {} |\n|---|{}{}", names.join(" | "), labels.join(" | "), "---|".repeat(names.len()), "---|".repeat(labels.len()));
    let _ = writeln!(md, "| baseline | {} | {} |", study.baseline()?.iter().map(|v| format!("{v:.4e}")).collect::<Vec<_>>().join(" | "),
        metrics.iter().zip(baseline).map(|(m, v)| m.show(*v)).collect::<Vec<_>>().join(" | "));
    for (k, ind) in front.iter().enumerate() {
        let xs: Vec<String> = ind.x.iter().map(|v| format!("{v:.4e}")).collect();
        let fs: Vec<String> = metrics.iter().zip(&ind.f).map(|(m, v)| m.show(*v)).collect();
        let _ = writeln!(md, "| front {} | {} | {} |", k + 1, xs.join(" | "), fs.join(" | "));
    }
    md.push_str("\n![front](pareto_front.svg)\n\n");
    md.push_str(&super::basis::mass_basis_section(problem, &[("baseline", &study.baseline()?)])?);
    Ok(md)
}
