//! Posterior sampling of a fitting study: fit first, then run the study's sampler from
//! over-dispersed starts around the optimum, and report the posterior (summary table with
//! R-hat and ESS, credible intervals, samples, trace and marginal plots). A fit that ends with
//! a parameter on a bound is rejected as `fit` rejects it (its outputs in `NAME.rejected`, a
//! non-zero exit naming the parameter and the bound), and nothing is sampled.

use super::write_output;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use rand::SeedableRng;
use rand_distr::{Distribution, Normal};

use super::fit::FitStudy;
use super::fit_run::fit_into;
use crate::cost::CostKind;
use crate::error::Error;
use crate::problem::posterior::Posterior;
use crate::report::mcmc_plot::{marginal_histograms, trace_plot};
use crate::sample::{PosteriorSummary, SampleOptions, SampleResult, SamplerOptions, by_name, sample};

/// Keys of the `[sampler]` table that belong to the run rather than the sampler.
const RUN_KEYS: [&str; 5] = ["chains", "iterations", "warmup", "seed", "progress"];

/// What a sampling run produced.
pub struct SampleOutcome {
    pub names: Vec<String>,
    pub result: SampleResult,
    /// Summary in model units (log-sampled parameters mapped back).
    pub summary: PosteriorSummary,
    pub seconds: f64,
    pub files: Vec<PathBuf>,
    /// The fit's notes (synthetic noise) and warnings (parameters at a bound).
    pub notes: Vec<String>,
    pub warnings: Vec<String>,
}

impl FitStudy {
    /// The sampler's name, its options and the run options from `[sampler]`.
    pub fn sampler(&self) -> Result<(String, SamplerOptions, SampleOptions), Error> {
        let mut table = self.sampler.clone();
        let method = table.remove("method").and_then(|v| v.as_str().map(str::to_string)).unwrap_or_else(|| "haario-bardenet".into());
        let mut run = toml::Table::new();
        for key in RUN_KEYS {
            if let Some(v) = table.remove(key) {
                run.insert(key.into(), v);
            }
        }
        // The run's own keys are taken out first, so name them beside the sampler's.
        let bad = |e: toml::de::Error| {
            let mut reason = e.to_string().trim_end().to_string();
            if reason.contains("unknown field") {
                reason.push_str(&format!(", or a run key: `{}`", RUN_KEYS.join("`, `")));
            }
            Error::InvalidSetting { field: "sampler".into(), reason }
        };
        let sampler: SamplerOptions = table.try_into().map_err(bad)?;
        let run: SampleOptions = run.try_into().map_err(bad)?;
        sampler.validate()?;
        run.validate()?;
        Ok((method, sampler, run))
    }
}

/// Largest split R-hat (-) and least effective sample size of converged chains.
const MAX_RHAT: f64 = 1.01;
const MIN_ESS: f64 = 100.0;

/// Fits the study (writing its fit report), then samples the posterior and writes
/// `posterior.md`, `posterior.json`, `samples.csv`, `trace.svg` and `marginals.svg`.
pub fn run_sample(study: &FitStudy, data: Option<&Path>) -> Result<SampleOutcome, Error> {
    let (method, mut sampler_options, mut run) = study.sampler()?;
    run.progress = true;
    // Sampling takes one experiment: fail before any work on a joint study.
    study.problem(data)?;
    let out = crate::output::OutputDir::create(&study.output.dir, &study.inputs(data))?;
    let fitted = fit_into(study, data, out.path())?;
    // A fit on a bound is no estimate to sample around: rejected as `fit` rejects it.
    if let Some(rejection) = super::fit::on_bound_rejection(&fitted.at_bound, "; nothing was sampled", &out) {
        out.reject(&fitted.files)?;
        return Err(rejection);
    }
    let problem = study.problem(data)?;
    let sigma = match study.cost {
        CostKind::GaussianLogLikelihood { sigma } | CostKind::Map { sigma } => sigma,
        _ => None,
    };
    let posterior = Posterior::new(&problem, sigma);
    let names = posterior.names();
    // Centre: the fitted parameters (and the RMS residual as sigma when it is sampled).
    let mut centre = fitted.result.x[..problem.dim()].to_vec();
    let mut spread: Vec<f64> = centre.iter().zip(&fitted.result.std_errors).map(|(x, e)| e.min(0.1 * x.abs())).collect();
    if names.len() > problem.dim() {
        // The noise level is sampled within its prior's range; a fit whose residual lies
        // outside it (a model-made, noise-free recording) leaves no start with a density.
        let (lo, hi) = crate::problem::identification::SIGMA_BOUNDS;
        if !(lo..=hi).contains(&fitted.result.rmse) {
            return Err(Error::InvalidSetting {
                field: "cost".into(),
                reason: format!(
                    "the fit's RMS residual, {} V, lies outside the range [{}, {}] V in which `sample` searches the noise level sigma (the recording is {} for a sampled noise level); give it instead: [cost] kind = \"gaussian_log_likelihood\", sigma = ... (V)",
                    crate::error::number(fitted.result.rmse),
                    crate::error::number(lo),
                    crate::error::number(hi),
                    if fitted.result.rmse < lo { "too clean, probably model-made," } else { "too far from the model" }
                ),
            });
        }
        let n = problem.weights.iter().filter(|w| **w > 0.0).count() as f64;
        centre.push(fitted.result.rmse);
        spread.push(fitted.result.rmse / (2.0 * n).sqrt());
    }
    let z0 = posterior.to_sampling(&centre);
    // Standard deviations in the sampling space (log coordinates: relative errors).
    let sd_z: Vec<f64> = posterior.to_sampling(&centre.iter().zip(&spread).map(|(c, s)| c + s).collect::<Vec<_>>())
        .iter()
        .zip(&z0)
        .map(|(a, b)| (a - b).abs().max(1e-12))
        .collect();
    let smallest = sd_z.iter().copied().fold(f64::INFINITY, f64::min);
    if sampler_options.proposal_scale == SamplerOptions::default().proposal_scale {
        sampler_options.proposal_scale = smallest;
    }
    if sampler_options.slice_width == SamplerOptions::default().slice_width {
        sampler_options.slice_width = 2.0 * smallest;
    }
    let mut rng = rand::rngs::StdRng::seed_from_u64(run.seed);
    let unit = Normal::new(0.0, 1.0).expect("unit normal");
    let starts: Vec<Vec<f64>> = (0..run.chains)
        .map(|_| z0.iter().zip(&sd_z).map(|(z, s)| z + 2.0 * s * unit.sample(&mut rng)).collect())
        .map(|z: Vec<f64>| if crate::sample::LogDensity::log_density(&posterior, &z).is_finite() { z } else { z0.clone() })
        .collect();
    let sampler = by_name(&method, sampler_options)?;
    let start = std::time::Instant::now();
    let result = sample(&posterior, sampler.as_ref(), &run, &starts)?;
    let seconds = start.elapsed().as_secs_f64();
    let mut in_model = result.clone();
    for chain in &mut in_model.chains {
        for d in &mut chain.draws {
            *d = posterior.to_model(d);
        }
    }
    let summary = in_model.summary(&names);
    let dir = out.path();
    let mut files = fitted.files;
    let mut csv = format!("chain,{}\n", names.join(","));
    for (k, chain) in in_model.chains.iter().enumerate() {
        for d in &chain.draws {
            let _ = writeln!(csv, "{k},{}", d.iter().map(|v| format!("{v:e}")).collect::<Vec<_>>().join(","));
        }
    }
    write_output(dir, "samples.csv", csv, &mut files)?;
    for (name, path) in [("trace", dir.join("trace.svg")), ("marginals", dir.join("marginals.svg"))] {
        let title = format!("{}: {name}", study.name);
        if name == "trace" {
            trace_plot(&path, &title, &names, &in_model.chains)?;
        } else {
            marginal_histograms(&path, &title, &names, &in_model.chains, None, 40)?;
        }
        files.push(path);
    }
    write_output(dir, "posterior.json", serde_json::to_string_pretty(&summary).expect("serialisable"), &mut files)?;
    let mut md = format!("# {}: posterior\n\n", study.name);
    let _ = writeln!(
        md,
        "{} sampler, {} chains x {} kept iterations after {} warmup, {:.1} s; acceptance {:?}.\n",
        result.sampler,
        run.chains,
        run.iterations,
        run.warmup,
        seconds,
        result.acceptance_rates().iter().map(|a| (a * 1000.0).round() / 1000.0).collect::<Vec<_>>()
    );
    let _ = writeln!(md, "```\n{}\n```", summary.table());
    let mut warnings = fitted.warnings;
    // Vehtari et al. (2021): R-hat below 1.01 and at least 100 effective draws.
    let (rhat, ess) = (summary.max_rhat(), summary.min_ess());
    if !(rhat < MAX_RHAT && ess >= MIN_ESS) {
        let warning = format!(
            "the chains have not converged: R-hat up to {rhat:.3} (needs < {MAX_RHAT}), effective sample size down to {ess:.0} (needs >= {MIN_ESS}); the posterior summary is not reliable: raise [sampler] iterations and warmup"
        );
        let _ = writeln!(md, "\n**Warning:** {warning}.");
        warnings.push(warning);
    }
    write_output(dir, "posterior.md", md, &mut files)?;
    let files = out.commit(&files)?;
    Ok(SampleOutcome { names, result: in_model, summary, seconds, files, notes: fitted.notes, warnings })
}
