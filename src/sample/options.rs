//! Settings of a sampling run ([`SampleOptions`]) and of the samplers ([`SamplerOptions`]).

use serde::{Deserialize, Serialize};

use crate::error::{Error, Result};

fn setting(field: &str, reason: String) -> Error {
    Error::InvalidSetting { field: field.to_string(), reason }
}

fn positive(field: &str, v: f64) -> Result<()> {
    if v > 0.0 && v.is_finite() { Ok(()) } else { Err(setting(field, format!("must be positive and finite, got {v}"))) }
}

fn at_least(field: &str, v: usize, min: usize) -> Result<()> {
    if v >= min { Ok(()) } else { Err(setting(field, format!("must be at least {min}, got {v}"))) }
}

/// Chains, iterations and seed of a [`sample`](super::sample) run.
///
/// Deserialises from a study file with defaults for missing keys; unknown keys are rejected.
///
/// ```
/// use cellstudio::sample::SampleOptions;
///
/// let options: SampleOptions = toml::from_str("chains = 6\nseed = 3").unwrap();
/// assert_eq!((options.chains, options.iterations), (6, 1000));
/// assert!(toml::from_str::<SampleOptions>("chain = 6").is_err());
/// let bad = SampleOptions { iterations: 2, ..Default::default() };
/// assert_eq!(bad.validate().unwrap_err().to_string(), "invalid setting `iterations`: must be at least 4, got 2");
/// ```
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct SampleOptions {
    /// Number of chains (the population size for DE-MC).
    pub chains: usize,
    /// Kept iterations per chain (at least 4, so split R-hat has two halves of two).
    pub iterations: usize,
    /// Warmup (adaptation) iterations per chain, discarded.
    pub warmup: usize,
    /// Master seed; chain `k` is seeded with [`chain_seed`](super::chain_seed)`(seed, k)`.
    pub seed: u64,
    /// Show a progress bar on the terminal.
    pub progress: bool,
}

impl Default for SampleOptions {
    fn default() -> Self {
        SampleOptions { chains: 4, iterations: 1000, warmup: 1000, seed: 0, progress: false }
    }
}

impl SampleOptions {
    /// Checks every field.
    pub fn validate(&self) -> Result<()> {
        at_least("chains", self.chains, 1)?;
        at_least("iterations", self.iterations, 4)
    }
}

/// Tuning of the samplers: one struct for all of them (each reads the fields it needs), so a
/// study file names the sampler and its settings in one table.
///
/// Deserialises with defaults for missing keys; unknown keys are rejected. `validate` checks
/// every field, whichever sampler uses it.
///
/// ```
/// use cellstudio::sample::SamplerOptions;
///
/// let options: SamplerOptions = toml::from_str("max_tree_depth = 8\nadapt_mass_matrix = false").unwrap();
/// options.validate().unwrap();
/// assert!(toml::from_str::<SamplerOptions>("tree_depth = 8").is_err());
/// let bad = SamplerOptions { target_acceptance: Some(1.5), ..Default::default() };
/// assert_eq!(
///     bad.validate().unwrap_err().to_string(),
///     "invalid setting `target_acceptance`: must be in (0, 1), got 1.5"
/// );
/// ```
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct SamplerOptions {
    /// Initial proposal standard deviation of random-walk and adaptive Metropolis
    /// (sampler-space units, per coordinate).
    pub proposal_scale: f64,
    /// Acceptance rate that warmup adaptation aims at; `None` uses each method's default:
    /// 0.234 (random walk, adaptive Metropolis; Roberts, Gelman & Gilks 1997), 0.574 (MALA;
    /// Roberts & Rosenthal 1998), 0.65 (HMC; Beskos et al. 2013), 0.8 (NUTS, as Stan).
    pub target_acceptance: Option<f64>,
    /// Adapt the tuning (proposal scale and covariance, slice width, step size, mass matrix)
    /// during warmup.
    pub adapt: bool,
    /// Initial slice width `w` per coordinate (sampler-space units).
    pub slice_width: f64,
    /// Maximum number of stepping-out steps per side and coordinate (Neal's `m`).
    pub max_stepping_out: usize,
    /// Initial leapfrog step size of MALA, HMC and NUTS; `None` finds one with the heuristic of
    /// Hoffman & Gelman (2014, Algorithm 4).
    pub step_size: Option<f64>,
    /// Leapfrog steps per HMC iteration.
    pub leapfrog_steps: usize,
    /// Maximum tree depth of NUTS (at most `2^depth - 1` leapfrog steps per iteration).
    pub max_tree_depth: usize,
    /// Adapt a diagonal mass matrix (inverse = posterior variances) in warmup windows, as
    /// Stan does (MALA, HMC, NUTS; needs `adapt`).
    pub adapt_mass_matrix: bool,
    /// DE-MC scale `γ` of the difference vector; `None` uses `2.38 / sqrt(2·dim)`.
    pub de_gamma: Option<f64>,
    /// Standard deviation of the DE-MC proposal noise `e` (sampler-space units).
    pub de_noise: f64,
    /// Every `de_jump_every`-th DE-MC generation uses `γ = 1` to jump between modes (0: never).
    pub de_jump_every: usize,
}

impl Default for SamplerOptions {
    fn default() -> Self {
        SamplerOptions {
            proposal_scale: 0.1,
            target_acceptance: None,
            adapt: true,
            slice_width: 1.0,
            max_stepping_out: 32,
            step_size: None,
            leapfrog_steps: 20,
            max_tree_depth: 10,
            adapt_mass_matrix: true,
            de_gamma: None,
            de_noise: 1e-4,
            de_jump_every: 10,
        }
    }
}

impl SamplerOptions {
    /// Checks every field.
    pub fn validate(&self) -> Result<()> {
        positive("proposal_scale", self.proposal_scale)?;
        if let Some(a) = self.target_acceptance
            && !(a > 0.0 && a < 1.0)
        {
            return Err(setting("target_acceptance", format!("must be in (0, 1), got {a}")));
        }
        positive("slice_width", self.slice_width)?;
        if let Some(h) = self.step_size {
            positive("step_size", h)?;
        }
        at_least("leapfrog_steps", self.leapfrog_steps, 1)?;
        at_least("max_tree_depth", self.max_tree_depth, 1)?;
        if self.max_tree_depth > 30 {
            return Err(setting("max_tree_depth", format!("must be at most 30, got {}", self.max_tree_depth)));
        }
        if let Some(g) = self.de_gamma {
            positive("de_gamma", g)?;
        }
        if !(self.de_noise >= 0.0 && self.de_noise.is_finite()) {
            return Err(setting("de_noise", format!("must be non-negative and finite, got {}", self.de_noise)));
        }
        Ok(())
    }

    /// The configured target acceptance rate, or the method's `default`.
    pub(crate) fn acceptance(&self, default: f64) -> f64 {
        self.target_acceptance.unwrap_or(default)
    }
}
