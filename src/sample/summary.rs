//! Posterior summary per parameter (serialisable, with a plain-text table).

use std::fmt;

use serde::{Deserialize, Serialize};

use super::SampleResult;
use crate::stats::convergence::{effective_sample_size, rank_normalised_rhat, split_rhat};
use crate::stats::quantile;

/// Summary of the kept draws of one parameter, pooled over chains.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct ParameterSummary {
    pub name: String,
    pub mean: f64,
    /// Standard deviation (unbiased variance).
    pub sd: f64,
    /// Monte-Carlo standard error of the mean, `sd / sqrt(ess)`.
    pub mcse_mean: f64,
    /// 2.5% quantile.
    pub q2_5: f64,
    pub median: f64,
    /// 97.5% quantile.
    pub q97_5: f64,
    /// Split R-hat (Gelman et al.; below 1.05 when the chains agree).
    pub rhat: f64,
    /// Rank-normalised split R-hat, bulk and tail (Vehtari et al. 2021; below 1.01).
    pub rank_rhat: f64,
    /// Effective sample size (Geyer initial monotone sequence, over chains).
    pub ess: f64,
}

impl ParameterSummary {
    /// Summary of `chains` (the draws of one parameter, one vector per chain).
    pub fn from_chains(name: &str, chains: &[Vec<f64>]) -> Self {
        let mut pooled: Vec<f64> = chains.iter().flatten().copied().collect();
        let count = pooled.len() as f64;
        let mean = pooled.iter().sum::<f64>() / count;
        let sd = (pooled.iter().map(|v| (v - mean) * (v - mean)).sum::<f64>() / (count - 1.0)).sqrt();
        pooled.sort_by(f64::total_cmp);
        let ess = effective_sample_size(chains);
        ParameterSummary {
            name: name.to_string(),
            mean,
            sd,
            mcse_mean: sd / ess.sqrt(),
            q2_5: quantile(&pooled, 0.025),
            median: quantile(&pooled, 0.5),
            q97_5: quantile(&pooled, 0.975),
            rhat: split_rhat(chains),
            rank_rhat: rank_normalised_rhat(chains),
            ess,
        }
    }
}

/// Posterior summary of a [`SampleResult`].
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct PosteriorSummary {
    pub sampler: String,
    pub chains: usize,
    /// Kept draws per chain.
    pub draws_per_chain: usize,
    /// Acceptance rate of each chain (see [`Chain::acceptance_rate`](super::Chain)).
    pub acceptance_rate: Vec<f64>,
    /// Divergent transitions over all chains (gradient samplers).
    pub divergences: usize,
    /// Log-density evaluations over all chains (warmup and finite differences included).
    pub evaluations: usize,
    pub parameters: Vec<ParameterSummary>,
}

impl PosteriorSummary {
    pub(crate) fn new<S: AsRef<str>>(result: &SampleResult, names: &[S]) -> Self {
        let parameters = (0..result.dim())
            .map(|i| {
                let name = names.get(i).map_or_else(|| format!("x{i}"), |s| s.as_ref().to_string());
                ParameterSummary::from_chains(&name, &result.parameter(i))
            })
            .collect();
        PosteriorSummary {
            sampler: result.sampler.clone(),
            chains: result.chains.len(),
            draws_per_chain: result.chains.first().map_or(0, |c| c.draws.len()),
            acceptance_rate: result.acceptance_rates(),
            divergences: result.chains.iter().map(|c| c.divergences).sum(),
            evaluations: result.chains.iter().map(|c| c.evaluations).sum(),
            parameters,
        }
    }

    /// Largest R-hat over parameters (`NaN` if any is `NaN`).
    pub fn max_rhat(&self) -> f64 {
        self.parameters.iter().map(|p| p.rhat).fold(1.0, |a, b| if a.is_nan() || b.is_nan() { f64::NAN } else { a.max(b) })
    }

    /// Smallest ESS over parameters.
    pub fn min_ess(&self) -> f64 {
        self.parameters.iter().map(|p| p.ess).fold(f64::INFINITY, f64::min)
    }

    /// Plain-text table: one row per parameter, then the chain statistics.
    pub fn table(&self) -> String {
        let width = self.parameters.iter().map(|p| p.name.len()).max().unwrap_or(4).max(9);
        let mut out = format!(
            "{:<width$} {:>12} {:>12} {:>12} {:>12} {:>12} {:>12} {:>7} {:>7} {:>8}\n",
            "parameter", "mean", "sd", "mcse", "2.5%", "50%", "97.5%", "R-hat", "rank-R", "ESS"
        );
        for p in &self.parameters {
            out += &format!(
                "{:<width$} {:>12.5e} {:>12.5e} {:>12.3e} {:>12.5e} {:>12.5e} {:>12.5e} {:>7.3} {:>7.3} {:>8.0}\n",
                p.name, p.mean, p.sd, p.mcse_mean, p.q2_5, p.median, p.q97_5, p.rhat, p.rank_rhat, p.ess
            );
        }
        let rates: Vec<String> = self.acceptance_rate.iter().map(|a| format!("{a:.3}")).collect();
        out += &format!(
            "{}: {} chains x {} draws, acceptance [{}], {} divergences, {} log-density evaluations\n",
            self.sampler,
            self.chains,
            self.draws_per_chain,
            rates.join(", "),
            self.divergences,
            self.evaluations
        );
        out
    }
}

impl fmt::Display for PosteriorSummary {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.table())
    }
}
