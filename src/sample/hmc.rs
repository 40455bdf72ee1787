//! Hamiltonian Monte Carlo with a fixed number of leapfrog steps (Duane et al. 1987; Neal 2011).

use rand::Rng;
use rand::rngs::StdRng;

use super::hamiltonian::{Dynamics, InvMass, MAX_ENERGY_ERROR, Point, Step, joint, leapfrog, momentum, run_dynamics};
use super::metropolis::metropolis;
use super::target::Counted;
use super::{Chain, LogDensity, Progress, ChainSampler, SamplerOptions, Schedule};
use crate::error::Result;

/// `steps` leapfrog steps of size `ε·(1 + jitter·U(-1, 1))`, then a Metropolis test on the
/// energy error. With one step and no jitter this is exactly MALA.
pub(super) struct StaticTrajectory {
    pub steps: usize,
    /// Relative step-size jitter (Neal 2011, section 5.4.2.2: avoids periodic trajectories).
    pub jitter: f64,
    pub acceptance: f64,
}

impl Dynamics for StaticTrajectory {
    fn default_acceptance(&self) -> f64 {
        self.acceptance
    }

    fn transition(&self, counted: &Counted, rng: &mut StdRng, current: &Point, eps: f64, inv_mass: &InvMass) -> Result<Step> {
        let p0 = momentum(rng, inv_mass);
        let h0 = joint(current, &p0, inv_mass);
        let eps = if self.jitter > 0.0 { eps * (1.0 + self.jitter * rng.random_range(-1.0..1.0)) } else { eps };
        let (mut q, mut p) = (current.clone(), p0);
        for _ in 0..self.steps {
            (q, p) = leapfrog(counted, &q, &p, eps, inv_mass)?;
            if q.log_p == f64::NEG_INFINITY {
                break;
            }
        }
        let log_ratio = joint(&q, &p, inv_mass) - h0;
        let divergent = !(log_ratio > -MAX_ENERGY_ERROR);
        let (accepted, alpha) = metropolis(rng, log_ratio);
        Ok(Step { point: if accepted { q } else { current.clone() }, accept_stat: alpha, divergent })
    }
}

/// Hamiltonian Monte Carlo: momentum `p ~ N(0, M)`, `leapfrog_steps` leapfrog steps with
/// a ±10% jittered step size, Metropolis test on `H = -log p(x) + ½pᵀM⁻¹p`. Step size and
/// diagonal mass matrix adapt during warmup (target acceptance 0.65 by default). The recorded
/// acceptance rate is the mean Metropolis acceptance probability.
#[derive(Clone, Debug)]
pub struct Hmc {
    options: SamplerOptions,
}

impl Hmc {
    pub fn new(options: SamplerOptions) -> Result<Self> {
        options.validate()?;
        Ok(Hmc { options })
    }
}

impl ChainSampler for Hmc {
    fn name(&self) -> &str {
        "hmc"
    }

    fn run_chain(&self, target: &dyn LogDensity, x0: &[f64], seed: u64, schedule: Schedule, progress: Progress) -> Result<Chain> {
        run_dynamics(&StaticTrajectory { steps: self.options.leapfrog_steps, jitter: 0.1, acceptance: 0.65 }, &self.options, target, x0, seed, schedule, progress)
    }
}
