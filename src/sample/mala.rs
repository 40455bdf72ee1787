//! Metropolis-adjusted Langevin algorithm (Roberts & Tweedie 1996).

use super::hamiltonian::run_chain;
use super::hmc::StaticTrajectory;
use super::{Chain, LogDensity, Progress, Sampler, SamplerOptions, Schedule, independent_chains};
use crate::error::Result;

/// MALA: proposal `y = x + ½ε²·M⁻¹∇log p(x) + ε·M^(-1/2)·ξ` with the Metropolis-Hastings
/// correction, implemented as one leapfrog step of HMC (the two are the same Markov kernel).
/// Step size `ε` and a diagonal preconditioner `M⁻¹` adapt during warmup (target acceptance
/// 0.574 by default).
#[derive(Clone, Debug)]
pub struct Mala {
    options: SamplerOptions,
}

impl Mala {
    pub fn new(options: SamplerOptions) -> Result<Self> {
        options.validate()?;
        Ok(Mala { options })
    }
}

impl Sampler for Mala {
    fn name(&self) -> &str {
        "mala"
    }

    fn run_chains(
        &self,
        target: &dyn LogDensity,
        starts: &[Vec<f64>],
        seeds: &[u64],
        schedule: Schedule,
        progress: Progress,
    ) -> Result<Vec<Chain>> {
        let dynamics = StaticTrajectory { steps: 1, jitter: 0.0, acceptance: 0.574 };
        independent_chains(starts, seeds, |x0, seed| run_chain(&dynamics, &self.options, target, x0, seed, schedule, progress))
    }
}
