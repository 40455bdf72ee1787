//! Differential-evolution Markov chain Monte Carlo (ter Braak 2006): a population of chains
//! whose proposals are scaled differences of other chains.

use rand::rngs::StdRng;
use rand::{Rng, SeedableRng};

use super::metropolis::{metropolis, normal_vector};
use super::run::Recorder;
use super::target::Counted;
use super::{Chain, LogDensity, Progress, Sampler, SamplerOptions, Schedule};
use crate::error::{Error, Result};

/// DE-MC: in every generation each chain `i` in turn proposes
/// `y = x_i + γ·(x_a - x_b) + e`, with `a ≠ b` drawn uniformly from the other chains' current
/// states and `e ~ N(0, de_noise²·I)`, and accepts it with the Metropolis probability. The
/// update is a Metropolis-within-Gibbs step on the product of the chains' targets, so every
/// chain is exactly stationary (ter Braak 2006). `γ = de_gamma` (default `2.38/sqrt(2·dim)`),
/// or 1 every `de_jump_every`-th generation to jump between modes.
///
/// The population is the set of chains: at least 3 are needed, and ter Braak recommends
/// `2·dim` or more (with fewer than `dim + 1` the differences span a subspace and only the
/// noise explores the rest). Chains are updated in turn, so the target is evaluated
/// sequentially. Chain `i` draws its random numbers from its own seeded generator. The
/// proposal does not adapt, so warmup only discards draws.
#[derive(Clone, Debug)]
pub struct DifferentialEvolutionMc {
    options: SamplerOptions,
}

impl DifferentialEvolutionMc {
    pub fn new(options: SamplerOptions) -> Result<Self> {
        options.validate()?;
        Ok(DifferentialEvolutionMc { options })
    }
}

/// Two distinct indices in `0..m`, both different from `i` (`m >= 3`).
fn two_others(rng: &mut StdRng, m: usize, i: usize) -> (usize, usize) {
    let mut a = rng.random_range(0..m - 1);
    if a >= i {
        a += 1;
    }
    let mut b = rng.random_range(0..m - 2);
    for skip in [i.min(a), i.max(a)] {
        if b >= skip {
            b += 1;
        }
    }
    (a, b)
}

impl Sampler for DifferentialEvolutionMc {
    fn name(&self) -> &str {
        "de-mc"
    }

    fn run_chains(
        &self,
        target: &dyn LogDensity,
        starts: &[Vec<f64>],
        seeds: &[u64],
        schedule: Schedule,
        progress: Progress,
    ) -> Result<Vec<Chain>> {
        let m = starts.len();
        if m < 3 {
            return Err(Error::InvalidSetting {
                field: "chains".into(),
                reason: format!("de-mc evolves a population of chains and needs at least 3, got {m}"),
            });
        }
        let n = starts[0].len();
        let gamma = self.options.de_gamma.unwrap_or(2.38 / (2.0 * n as f64).sqrt());
        let counted: Vec<Counted> = (0..m).map(|_| Counted::new(target)).collect();
        let mut rngs: Vec<StdRng> = seeds.iter().map(|&s| StdRng::seed_from_u64(s)).collect();
        let mut recs: Vec<Recorder> = (0..m).map(|_| Recorder::new(schedule)).collect();
        let mut x: Vec<Vec<f64>> = starts.to_vec();
        let mut fx: Vec<f64> = (0..m).map(|i| counted[i].log_density(&x[i])).collect();
        for it in 0..schedule.total() {
            let jump = self.options.de_jump_every > 0 && (it + 1) % self.options.de_jump_every == 0;
            let g = if jump { 1.0 } else { gamma };
            for i in 0..m {
                let rng = &mut rngs[i];
                let (a, b) = two_others(rng, m, i);
                let e = normal_vector(rng, n);
                let y: Vec<f64> =
                    (0..n).map(|k| x[i][k] + g * (x[a][k] - x[b][k]) + self.options.de_noise * e[k]).collect();
                let fy = counted[i].log_density(&y);
                let (accepted, _) = metropolis(rng, fy - fx[i]);
                if accepted {
                    x[i] = y;
                    fx[i] = fy;
                }
                recs[i].record(it, &x[i], fx[i], f64::from(u8::from(accepted)), false);
                progress();
            }
        }
        Ok(recs.into_iter().zip(&counted).map(|(r, c)| r.finish(c, None)).collect())
    }
}
