//! The `[profile]` section of a fitting study: a profile likelihood of every fitted parameter
//! ([`crate::problem::profile`]), one plot each, a table beside the Fisher (Wald) intervals
//! and `profiles.json`.

use std::fmt::Write as _;
use std::path::Path;

use rayon::prelude::*;
use serde::{Deserialize, Serialize};

use crate::error::Error;
use crate::problem::identification::FitResult;
use crate::problem::fitting::FittingProblem;
use crate::problem::profile::{CHI2_95_ONE_DOF, Profile, profile};
use crate::report::plot::{Series, line_plot};

/// Held values on each side of the optimum, per parameter.
#[derive(Clone, Debug, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct ProfileSettings {
    pub points: usize,
}

impl ProfileSettings {
    pub fn validate(&self) -> Result<(), Error> {
        if !(2..=50).contains(&self.points) {
            return Err(Error::invalid("profile.points", self.points as f64, "must lie in 2..=50"));
        }
        Ok(())
    }
}

/// Profiles every fitted parameter of `problem` around `result` (in parallel) and writes
/// `profile_<k>.svg` per parameter and `profiles.json` into `dir`.
pub fn write_profiles(dir: &Path, title: &str, problem: &FittingProblem, result: &FitResult, settings: &ProfileSettings) -> Result<super::ReportSection, Error> {
    let best = &result.x[..problem.dim()];
    let profiles: Vec<Profile> =
        (0..problem.dim()).into_par_iter().map(|k| profile(problem, best, &result.std_errors, k, settings.points)).collect::<Result<_, _>>()?;
    let mut files = Vec::new();
    let mut warnings = Vec::new();
    let n = |v: f64| if (1e-3..1e4).contains(&v.abs()) { format!("{v:.5}") } else { format!("{v:.4e}") };
    let mut section = format!(
        "## Profile likelihoods\n\nEach parameter held at {} values on either side of the optimum while the others are refitted; the 95 % interval is where the likelihood ratio stays below {CHI2_95_ONE_DOF:.2} (chi-squared, one degree of freedom), beside the Fisher interval (±1.96 standard errors).\n\n| parameter | fitted | profile 95 % interval | Fisher 95 % interval |\n|---|---|---|---|\n",
        settings.points
    );
    for (k, p) in profiles.iter().enumerate() {
        let se = result.std_errors[k];
        let _ = writeln!(section, "| {} | {} | {} | [{}, {}] |", p.name, n(p.best), p.describe(&n), n(p.best - 1.96 * se), n(p.best + 1.96 * se));
        if let Some(sse) = p.better_fit {
            warnings.push(format!(
                "the profile of {} met a better fit (SSE {} V^2) than the optimum: the search stopped in a local minimum",
                p.name,
                n(sse)
            ));
        }
        let path = dir.join(format!("profile_{k}.svg"));
        let threshold = vec![CHI2_95_ONE_DOF; p.values.len()];
        let kept: Vec<(f64, f64)> = p.values.iter().zip(&p.statistic).filter(|(_, s)| s.is_finite()).map(|(v, s)| (*v, *s)).collect();
        let (x, y): (Vec<f64>, Vec<f64>) = kept.into_iter().unzip();
        line_plot(
            &path,
            &format!("{title}: profile of {}", p.name),
            &p.name,
            "likelihood ratio (-)",
            &[Series { label: "profile".into(), x: &x, y: &y }, Series { label: "95 % threshold".into(), x: &p.values, y: &threshold }],
        )?;
        files.push(path);
    }
    let json = dir.join("profiles.json");
    crate::error::write_file(&json, serde_json::to_string_pretty(&profiles).expect("serialisable"))?;
    files.push(json);
    Ok(super::ReportSection { files, section, warnings })
}
