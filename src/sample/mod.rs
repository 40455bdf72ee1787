//! MCMC samplers behind one trait, with convergence diagnostics.
//!
//! Every sampler implements [`Sampler`] and draws from a [`LogDensity`] over `R^dim` (the
//! sampler's space; a fitting problem maps it to model parameters itself). [`sample`] runs
//! several chains in parallel with rayon and returns a [`SampleResult`]; its
//! [`SampleResult::summary`] gives the posterior mean, sd, quantiles, split R-hat and effective
//! sample size per parameter ([`PosteriorSummary`], serialisable, with a plain-text table).
//!
//! Samplers ([`SAMPLER_NAMES`], built by [`by_name`] from one [`SamplerOptions`]):
//! random-walk Metropolis, Haario-Bardenet adaptive covariance Metropolis, differential-evolution
//! MCMC (ter Braak 2006), coordinate-wise slice sampling with stepping out (Neal 2003), MALA,
//! HMC and NUTS (Hoffman & Gelman 2014). Tuning (proposal scale, covariance, slice width, step
//! size, diagonal mass matrix) adapts during warmup only, so the kept draws come from a fixed,
//! valid Markov kernel.
//!
//! Reproducibility. Chain `k` uses its own generator seeded from [`chain_seed`]`(seed, k)`, and
//! finite-difference probes are evaluated in a fixed order, so the same seed gives bit-identical
//! draws for any number of threads.
//!
//! ```
//! use cellstudio::sample::{by_name, sample, LogDensity, SampleOptions};
//!
//! /// Standard normal in 2-D.
//! struct Normal;
//! impl LogDensity for Normal {
//!     fn dim(&self) -> usize { 2 }
//!     fn log_density(&self, x: &[f64]) -> f64 { -0.5 * x.iter().map(|v| v * v).sum::<f64>() }
//! }
//!
//! let sampler = by_name("nuts", Default::default()).unwrap();
//! let options = SampleOptions { chains: 2, iterations: 500, warmup: 300, seed: 1, ..Default::default() };
//! let result = sample(&Normal, sampler.as_ref(), &options, &[vec![0.5, -0.5], vec![-0.5, 0.5]]).unwrap();
//! let summary = result.summary(&["a", "b"]);
//! assert!(summary.parameters[0].mean.abs() < 0.3 && (summary.parameters[1].sd - 1.0).abs() < 0.2);
//! ```

mod adaptive;
mod de_mc;
mod hamiltonian;
mod hmc;
mod mala;
mod metropolis;
mod nuts;
mod options;
mod run;
mod slice;
mod summary;
mod target;
mod warmup;

use rayon::prelude::*;
use serde::{Deserialize, Serialize};

use crate::error::{Error, Result};

pub use adaptive::AdaptiveMetropolis;
pub use de_mc::DifferentialEvolutionMc;
pub use hmc::Hmc;
pub use mala::Mala;
pub use metropolis::RandomWalkMetropolis;
pub use nuts::Nuts;
pub use options::{SampleOptions, SamplerOptions};
pub use run::{SampleResult, chain_seed, sample};
pub use slice::SliceSampler;
pub use summary::{ParameterSummary, PosteriorSummary};
pub use target::finite_difference_gradient;

/// An unnormalised log-density over R^dim (the sampler's space; a fitting problem maps it to model parameters itself).
pub trait LogDensity: Sync {
    fn dim(&self) -> usize;
    /// log p(x) up to a constant; f64::NEG_INFINITY outside the support or when the model fails.
    fn log_density(&self, x: &[f64]) -> f64;
    /// log p(x) and its gradient, if the target can compute them analytically; samplers that need gradients fall back to central finite differences when this returns None.
    fn log_density_and_gradient(&self, _x: &[f64]) -> Option<(f64, Vec<f64>)> {
        None
    }
}

/// Iterations of one run: `warmup` adaptation iterations (discarded), then `iterations` kept.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub struct Schedule {
    pub warmup: usize,
    pub iterations: usize,
}

impl Schedule {
    /// Total iterations, warmup included.
    pub fn total(&self) -> usize {
        self.warmup + self.iterations
    }
}

/// Called once per chain and iteration (warmup included); progress bars implement it.
pub type Progress<'a> = &'a (dyn Fn() + Sync);

/// The kept (post-warmup) draws of one chain and its statistics.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Chain {
    /// `draws[t]` is the state after kept iteration `t` (sampler space).
    pub draws: Vec<Vec<f64>>,
    /// `log_density[t]` = log p(`draws[t]`).
    pub log_density: Vec<f64>,
    /// Mean acceptance statistic over the kept iterations: the fraction of accepted proposals
    /// for random-walk, adaptive and DE-MC Metropolis; the mean Metropolis acceptance
    /// probability for MALA and HMC, and its mean over the trajectory for NUTS (the statistic
    /// their step-size adaptation targets); 1 for slice sampling (which always moves).
    pub acceptance_rate: f64,
    /// Log-density evaluations, warmup and finite-difference probes included.
    pub evaluations: usize,
    /// Analytic gradient evaluations (`log_density_and_gradient` returning `Some`).
    pub gradient_evaluations: usize,
    /// Final (adapted) step size of gradient samplers.
    pub step_size: Option<f64>,
    /// Kept iterations whose trajectory diverged (energy error above 1000), gradient samplers.
    pub divergences: usize,
}

/// An MCMC method.
pub trait Sampler: Sync {
    /// Canonical name, as accepted by [`by_name`].
    fn name(&self) -> &str;

    /// Runs one chain per start, chain `k` from `starts[k]` with seed `seeds[k]`; chains run in
    /// parallel (population samplers evolve them together). Starts must have a finite log
    /// density ([`sample`] checks this).
    fn run_chains(
        &self,
        target: &dyn LogDensity,
        starts: &[Vec<f64>],
        seeds: &[u64],
        schedule: Schedule,
        progress: Progress,
    ) -> Result<Vec<Chain>>;
}

/// A sampler whose chains are independent: implementing one chain makes it a [`Sampler`]
/// that runs the chains in parallel with rayon (results in start order).
pub trait ChainSampler: Sync {
    /// Canonical name, as accepted by [`by_name`].
    fn name(&self) -> &str;

    /// Runs one chain from `x0` (finite log density) with its own generator seeded by `seed`.
    fn run_chain(&self, target: &dyn LogDensity, x0: &[f64], seed: u64, schedule: Schedule, progress: Progress)
    -> Result<Chain>;
}

impl<T: ChainSampler> Sampler for T {
    fn name(&self) -> &str {
        ChainSampler::name(self)
    }

    fn run_chains(
        &self,
        target: &dyn LogDensity,
        starts: &[Vec<f64>],
        seeds: &[u64],
        schedule: Schedule,
        progress: Progress,
    ) -> Result<Vec<Chain>> {
        starts.par_iter().zip(seeds.par_iter()).map(|(x0, &seed)| self.run_chain(target, x0, seed, schedule, progress)).collect()
    }
}

/// Canonical sampler names accepted by [`by_name`].
pub const SAMPLER_NAMES: [&str; 7] = ["rwm", "adaptive-metropolis", "de-mc", "slice", "mala", "hmc", "nuts"];

/// Builds a sampler from its name (case-insensitive; `_` and `-` are interchangeable;
/// aliases: `random-walk-metropolis`, `metropolis`, `haario-bardenet`, `am`, `demc`,
/// `differential-evolution`, `slice-sampling`, `langevin`, `hamiltonian`, `no-u-turn`).
///
/// ```
/// let err = cellstudio::sample::by_name("gibbs", Default::default()).err().unwrap();
/// assert!(err.to_string().contains("rwm, adaptive-metropolis, de-mc"));
/// ```
pub fn by_name(name: &str, options: SamplerOptions) -> Result<Box<dyn Sampler>> {
    let key = name.trim().to_ascii_lowercase().replace('_', "-");
    Ok(match key.as_str() {
        "rwm" | "random-walk-metropolis" | "metropolis" => Box::new(RandomWalkMetropolis::new(options)?),
        "adaptive-metropolis" | "haario-bardenet" | "am" => Box::new(AdaptiveMetropolis::new(options)?),
        "de-mc" | "demc" | "differential-evolution" => Box::new(DifferentialEvolutionMc::new(options)?),
        "slice" | "slice-sampling" => Box::new(SliceSampler::new(options)?),
        "mala" | "langevin" => Box::new(Mala::new(options)?),
        "hmc" | "hamiltonian" => Box::new(Hmc::new(options)?),
        "nuts" | "no-u-turn" => Box::new(Nuts::new(options)?),
        _ => {
            return Err(Error::InvalidSetting {
                field: "sampler".into(),
                reason: format!("unknown sampler `{name}`; valid names: {}", SAMPLER_NAMES.join(", ")),
            });
        }
    })
}
