//! Running several chains: start checks, per-chain seeds, the progress bar, and recording of
//! the kept draws.

use indicatif::ProgressBar;
use serde::{Deserialize, Serialize};

use super::summary::PosteriorSummary;
use super::target::Counted;
use super::{Chain, LogDensity, SampleOptions, Sampler, Schedule};
use crate::error::{Error, Result};

/// SplitMix64 finaliser (Steele, Lea & Flood 2014): a bijective mix of 64 bits.
fn splitmix64(mut z: u64) -> u64 {
    z = z.wrapping_add(0x9E37_79B9_7F4A_7C15);
    z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
    z ^ (z >> 31)
}

/// Seed of chain `chain` derived from the master `seed` (distinct chains get unrelated
/// streams; independent of the number of threads).
pub fn chain_seed(seed: u64, chain: usize) -> u64 {
    splitmix64(seed ^ splitmix64(chain as u64))
}

/// Draws of all chains of one [`sample`] run.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct SampleResult {
    /// Canonical sampler name.
    pub sampler: String,
    pub options: SampleOptions,
    pub chains: Vec<Chain>,
}

impl SampleResult {
    /// Number of parameters.
    pub fn dim(&self) -> usize {
        self.chains.first().and_then(|c| c.draws.first()).map_or(0, Vec::len)
    }

    /// Kept draws of parameter `i`, one vector per chain.
    pub fn parameter(&self, i: usize) -> Vec<Vec<f64>> {
        self.chains.iter().map(|c| c.draws.iter().map(|d| d[i]).collect()).collect()
    }

    /// Acceptance rate of each chain (see [`Chain::acceptance_rate`]).
    pub fn acceptance_rates(&self) -> Vec<f64> {
        self.chains.iter().map(|c| c.acceptance_rate).collect()
    }

    /// Posterior summary per parameter; `names[i]` names parameter `i` (missing names become
    /// `x{i}`).
    pub fn summary<S: AsRef<str>>(&self, names: &[S]) -> PosteriorSummary {
        PosteriorSummary::new(self, names)
    }
}

fn bad_start(reason: String) -> Error {
    Error::InvalidSetting { field: "starts".into(), reason }
}

/// Runs `options.chains` chains of `sampler` on `target` in parallel (rayon) and returns their
/// kept draws.
///
/// `starts` holds one start point per chain, or a single point shared by all chains
/// (over-dispersed starts make R-hat meaningful). Every start must have `target.dim()` finite
/// entries and a finite log density. Chain `k` is seeded with
/// [`chain_seed`]`(options.seed, k)`, so the draws do not depend on the number of threads.
pub fn sample(
    target: &dyn LogDensity,
    sampler: &dyn Sampler,
    options: &SampleOptions,
    starts: &[Vec<f64>],
) -> Result<SampleResult> {
    options.validate()?;
    let n = target.dim();
    if n == 0 {
        return Err(bad_start("the target has no variables".into()));
    }
    let starts: Vec<Vec<f64>> = match starts.len() {
        1 => vec![starts[0].clone(); options.chains],
        k if k == options.chains => starts.to_vec(),
        k => return Err(bad_start(format!("{k} start points for {} chains (give 1 or one per chain)", options.chains))),
    };
    for (k, x0) in starts.iter().enumerate() {
        if x0.len() != n {
            return Err(bad_start(format!("start {k} has {} entries for {n} variables", x0.len())));
        }
        if x0.iter().any(|v| !v.is_finite()) {
            return Err(bad_start(format!("start {k} = {x0:?} is not finite")));
        }
        let f = target.log_density(x0);
        if !(f.is_finite()) {
            return Err(bad_start(format!("start {k} = {x0:?} has log density {f}")));
        }
    }
    let seeds: Vec<u64> = (0..options.chains).map(|k| chain_seed(options.seed, k)).collect();
    let schedule = Schedule { warmup: options.warmup, iterations: options.iterations };
    let bar = if options.progress {
        let bar = crate::progress::bar(sampler.name(), (options.chains * schedule.total()) as u64, "{msg} [{elapsed_precise}] {wide_bar} {pos}/{len} ({eta})");
        bar.set_message(sampler.name().to_string());
        bar
    } else {
        ProgressBar::hidden()
    };
    let tick = || bar.inc(1);
    let chains = sampler.run_chains(target, &starts, &seeds, schedule, &tick)?;
    bar.finish_and_clear();
    Ok(SampleResult { sampler: sampler.name().to_string(), options: options.clone(), chains })
}

/// Collects the kept iterations of one chain.
pub(crate) struct Recorder {
    warmup: usize,
    draws: Vec<Vec<f64>>,
    log_density: Vec<f64>,
    accept: f64,
    divergences: usize,
}

impl Recorder {
    pub fn new(schedule: Schedule) -> Self {
        Recorder {
            warmup: schedule.warmup,
            draws: Vec::with_capacity(schedule.iterations),
            log_density: Vec::with_capacity(schedule.iterations),
            accept: 0.0,
            divergences: 0,
        }
    }

    /// Records iteration `iteration` (counting from 0, warmup included) if it is kept.
    pub fn record(&mut self, iteration: usize, x: &[f64], log_density: f64, accept_stat: f64, divergent: bool) {
        if iteration < self.warmup {
            return;
        }
        self.draws.push(x.to_vec());
        self.log_density.push(log_density);
        self.accept += accept_stat;
        self.divergences += usize::from(divergent);
    }

    pub fn finish(self, counted: &Counted, step_size: Option<f64>) -> Chain {
        let (evaluations, gradient_evaluations) = counted.counts();
        let kept = self.draws.len().max(1) as f64;
        Chain {
            acceptance_rate: self.accept / kept,
            draws: self.draws,
            log_density: self.log_density,
            evaluations,
            gradient_evaluations,
            step_size,
            divergences: self.divergences,
        }
    }
}
