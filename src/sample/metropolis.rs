//! Random-walk Metropolis with an isotropic Gaussian proposal whose scale adapts during warmup.

use rand::rngs::StdRng;
use rand::{Rng, SeedableRng};
use rand_distr::StandardNormal;

use super::run::Recorder;
use super::target::Counted;
use super::{Chain, LogDensity, Progress, ChainSampler, SamplerOptions, Schedule};
use crate::error::Result;

/// Metropolis test on `log_ratio = log p(y) - log p(x)` (symmetric proposal, or with the
/// proposal correction included): returns (accepted, acceptance probability `min(1, e^r)`).
/// Always draws one uniform, so the random stream does not depend on the outcome.
pub(super) fn metropolis(rng: &mut StdRng, log_ratio: f64) -> (bool, f64) {
    let u: f64 = rng.random();
    let alpha = if log_ratio.is_nan() { 0.0 } else { log_ratio.min(0.0).exp() };
    (u < alpha, alpha)
}

/// Robbins-Monro gain `(t + 1)^(-0.6)` of warmup iteration `t` (as Haario-Bardenet in PINTS).
pub(super) fn gain(t: usize) -> f64 {
    (t as f64 + 1.0).powf(-0.6)
}

/// A standard-normal vector of length `n`.
pub(super) fn normal_vector(rng: &mut StdRng, n: usize) -> Vec<f64> {
    (0..n).map(|_| rng.sample(StandardNormal)).collect()
}

/// Random-walk Metropolis: proposal `y = x + λ·ξ`, `ξ ~ N(0, I)`. During warmup (with
/// `adapt`) `log λ` follows a Robbins-Monro recursion towards the target acceptance rate
/// (default 0.234); `λ` starts at `proposal_scale` and is fixed after warmup.
#[derive(Clone, Debug)]
pub struct RandomWalkMetropolis {
    options: SamplerOptions,
}

impl RandomWalkMetropolis {
    pub fn new(options: SamplerOptions) -> Result<Self> {
        options.validate()?;
        Ok(RandomWalkMetropolis { options })
    }

}

impl ChainSampler for RandomWalkMetropolis {
    fn name(&self) -> &str {
        "rwm"
    }

    fn run_chain(&self, target: &dyn LogDensity, x0: &[f64], seed: u64, schedule: Schedule, progress: Progress) -> Result<Chain> {
        let counted = Counted::new(target);
        let mut rng = StdRng::seed_from_u64(seed);
        let mut rec = Recorder::new(schedule);
        let goal = self.options.acceptance(0.234);
        let mut log_scale = self.options.proposal_scale.ln();
        let mut x = x0.to_vec();
        let mut fx = counted.log_density(&x);
        for it in 0..schedule.total() {
            let scale = log_scale.exp();
            let y: Vec<f64> = normal_vector(&mut rng, x.len()).iter().zip(&x).map(|(z, xi)| xi + scale * z).collect();
            let fy = counted.log_density(&y);
            let (accepted, alpha) = metropolis(&mut rng, fy - fx);
            if accepted {
                x = y;
                fx = fy;
            }
            if self.options.adapt && it < schedule.warmup {
                log_scale += gain(it) * (alpha - goal);
            }
            rec.record(it, &x, fx, f64::from(u8::from(accepted)), false);
            progress();
        }
        Ok(rec.finish(&counted, None))
    }
}
