//! Running a study's multi-objective search: NSGA-II over the decision variables, the
//! non-dominated front as CSV/JSON and a plot with the baseline marked.

use super::write_output;
use std::fmt::Write as _;
use std::path::PathBuf;
use std::time::Instant;

use super::Study;
use crate::error::Error;
use crate::pareto::{Individual, Nsga2Options, nsga2};
use crate::report::plot::scatter_plot;

/// What a Pareto search produced.
pub struct ParetoOutcome {
    pub front: Vec<Individual>,
    pub evaluated: usize,
    pub failed: usize,
    pub baseline: Vec<f64>,
    pub rebuilds: usize,
    pub seconds: f64,
    pub files: Vec<PathBuf>,
    /// Warnings also written into `pareto_front.json` (failed designs, baseline off bounds).
    pub warnings: Vec<String>,
}

/// Runs NSGA-II with the study's `[optimiser]` table as [`Nsga2Options`].
pub fn run_pareto(study: &Study) -> Result<ParetoOutcome, Error> {
    let metrics = &study.objective.maximise;
    if metrics.len() < 2 {
        return Err(Error::InvalidSetting {
            field: "objective.maximise".into(),
            reason: format!("pareto needs two or more objectives, got {}", metrics.len()),
        });
    }
    let mut table = study.optimiser.clone();
    table.remove("method");
    let opts: Nsga2Options = table
        .try_into()
        .map_err(|e: toml::de::Error| Error::InvalidSetting { field: "optimiser".into(), reason: e.to_string() })?;
    let problem = study.problem()?;
    let out = study.output_dir()?;
    let lower: Vec<f64> = study.variables.iter().map(|v| v.lower).collect();
    let upper: Vec<f64> = study.variables.iter().map(|v| v.upper).collect();
    let failed = std::sync::atomic::AtomicUsize::new(0);
    let evaluate = |x: &[f64]| match problem.evaluate(x) {
        Ok(m) => metrics.iter().map(|&k| m.get(k)).collect(),
        Err(_) => {
            failed.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
            vec![f64::NEG_INFINITY; metrics.len()]
        }
    };
    let start = Instant::now();
    let baseline_m = problem.evaluate(&study.baseline()?)?;
    let baseline: Vec<f64> = metrics.iter().map(|&k| baseline_m.get(k)).collect();
    let bar = indicatif::ProgressBar::new(opts.generations as u64);
    let (front, archive) = nsga2(&lower, &upper, &opts, &evaluate, &mut |g| bar.set_position(g as u64));
    bar.finish_and_clear();
    let seconds = start.elapsed().as_secs_f64();

    let failed = failed.into_inner();
    if front.is_empty() || failed >= archive.len() {
        return Err(Error::InvalidSetting {
            field: "pareto".into(),
            reason: format!("no valid design: {failed} of {} designs failed (nothing written)", archive.len()),
        });
    }
    let mut warnings = study.warnings();
    if failed > 0 {
        warnings.push(format!("{failed} of {} designs failed", archive.len()));
    }
    let dir = out.path();
    let names: Vec<String> = study.variables.iter().map(|v| v.path.clone()).collect();
    let objectives: Vec<String> = metrics.iter().map(|m| serde_json::to_value(m).unwrap_or_default().as_str().unwrap_or("").to_string()).collect();
    let mut csv = format!("{},{}\n", names.join(","), objectives.join(","));
    let mut sorted = front.clone();
    sorted.sort_by(|a, b| a.f[0].total_cmp(&b.f[0]));
    for ind in &sorted {
        let cols: Vec<String> = ind.x.iter().chain(&ind.f).map(|v| v.to_string()).collect();
        let _ = writeln!(csv, "{}", cols.join(","));
    }
    let mut files = Vec::new();
    write_output(dir, "pareto_front.csv", csv, &mut files)?;
    let json = serde_json::json!({ "study": study.name, "variables": names, "objectives": objectives,
        "baseline": baseline, "front": sorted, "evaluated": archive.len(), "failed": failed, "warnings": warnings, "seconds": seconds });
    write_output(dir, "pareto_front.json", serde_json::to_string_pretty(&json).unwrap_or_default(), &mut files)?;
    let plot = dir.join("pareto_front.svg");
    let pts = |set: &[Individual]| set.iter().map(|i| (i.f[0], i.f[1])).collect::<Vec<_>>();
    scatter_plot(
        &plot,
        &study.name,
        (metrics[0].label(), metrics[1].label()),
        &[("evaluated designs".into(), pts(&archive)), ("non-dominated front".into(), pts(&sorted))],
        Some(("baseline".into(), (baseline[0], baseline[1]))),
    )?;
    files.push(plot);
    let files = out.commit(&files)?;
    Ok(ParetoOutcome {
        front: sorted,
        evaluated: archive.len(),
        failed,
        baseline,
        rebuilds: problem.rebuild_count(),
        seconds,
        files,
        warnings,
    })
}
