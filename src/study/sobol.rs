//! The `[sobol]` section of a fitting study: Sobol' indices of every fitted parameter over
//! its search box ([`crate::problem::global_sensitivity`]), a table in the report and
//! `sobol.json`.

use std::fmt::Write as _;
use std::path::Path;

use crate::error::Error;
use crate::problem::fitting::FittingProblem;
use crate::problem::global_sensitivity::{NEGLIGIBLE_TOTAL, global_sensitivity};
use crate::stats::sobol::SobolSettings;

/// Computes the indices (in parallel, with a progress line on stderr) and writes `sobol.json`.
pub fn write_sobol(dir: &Path, problem: &FittingProblem, settings: &SobolSettings) -> Result<super::ReportSection, Error> {
    let runs = settings.samples * (problem.dim() + 2);
    eprintln!("sobol: {runs} simulations over the parameters' search boxes");
    let g = global_sensitivity(problem, settings)?;
    let s = &g.indices;
    let mut section = format!(
        "## Global sensitivity (Sobol' indices)\n\nShare of the variance of the weighted voltage over the parameters' whole search boxes (log-uniform where searched on a log scale): first-order (the parameter alone) and total (with its interactions); {} base samples, {} simulations, seed {}, 95 % bootstrap intervals from {} resamples. A total index below {NEGLIGIBLE_TOTAL} reads as no influence.\n\n| parameter | first-order | total | verdict |\n|---|---|---|---|\n",
        s.samples_used, s.evaluations, settings.seed, settings.bootstrap
    );
    let with = |v: f64, i: Option<&(f64, f64)>| match i {
        Some((lo, hi)) => format!("{v:.3} [{lo:.3}, {hi:.3}]"),
        None => format!("{v:.3}"),
    };
    for (k, name) in g.names.iter().enumerate() {
        let _ = writeln!(section, "| {name} | {} | {} | {} |", with(s.first[k], s.first_interval.get(k)), with(s.total[k], s.total_interval.get(k)), g.verdicts[k]);
    }
    let mut warnings = Vec::new();
    if s.samples_used < settings.samples {
        warnings.push(format!("the Sobol' indices left out {} of {} base samples where the model failed", settings.samples - s.samples_used, settings.samples));
    }
    let json = dir.join("sobol.json");
    crate::error::write_file(&json, serde_json::to_string_pretty(&g).expect("serialisable"))?;
    Ok(super::ReportSection { files: vec![json], section, warnings })
}
