//! Metropolis-adjusted Langevin algorithm (Roberts & Tweedie 1996).

use super::hamiltonian::run_dynamics;
use super::hmc::StaticTrajectory;
use super::{Chain, LogDensity, Progress, ChainSampler, SamplerOptions, Schedule};
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

impl ChainSampler for Mala {
    fn name(&self) -> &str {
        "mala"
    }

    fn run_chain(&self, target: &dyn LogDensity, x0: &[f64], seed: u64, schedule: Schedule, progress: Progress) -> Result<Chain> {
        run_dynamics(&StaticTrajectory { steps: 1, jitter: 0.0, acceptance: 0.574 }, &self.options, target, x0, seed, schedule, progress)
    }
}
