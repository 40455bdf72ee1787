//! Particle swarm optimisation with the SPSO 2011 coefficients (Clerc, "Standard Particle
//! Swarm Optimisation", 2012) and a global-best topology.

use rand::Rng;

use super::run::{Run, population_converged};
use super::{Observer, OptimOptions, OptimResult, Optimiser, Problem};
use crate::error::Result;

/// Inertia weight `w = 1 / (2 ln 2)`.
const INERTIA: f64 = 0.721_347_520_444_481_7;
/// Cognitive and social acceleration `c = 0.5 + ln 2`.
const ACCELERATION: f64 = 1.193_147_180_559_945_3;

/// Particle swarm: `v ← w·v + c·r₁·(p - x) + c·r₂·(g - x)`, `x ← P(x + v)`, where `p` is the
/// particle's best, `g` the swarm's best and `P` the projection (the velocity is kept as
/// computed, so a particle pressed against a bound keeps exploring along it). Swarm size `10 + ⌊2√n⌋` by
/// default; initial velocities uniform in `±sigma0`.
#[derive(Clone, Debug)]
pub struct ParticleSwarm {
    options: OptimOptions,
}

impl ParticleSwarm {
    pub fn new(options: OptimOptions) -> Result<Self> {
        options.validate()?;
        Ok(ParticleSwarm { options })
    }
}

impl Optimiser for ParticleSwarm {
    fn name(&self) -> &str {
        "pso"
    }

    fn minimise(&mut self, problem: &Problem, x0: &[f64], observer: &mut dyn Observer) -> Result<OptimResult> {
        let (mut run, c0) = Run::start(problem, &self.options, observer, x0)?;
        let mut rng = run.rng();
        let n = run.dim();
        let size = self.options.population(10 + (2.0 * (n as f64).sqrt()) as usize, 2, "particle swarm")?;
        let initial = run.initial_population(&mut rng, &c0.u, size);
        let sigma0 = self.options.sigma0;
        let mut velocity: Vec<Vec<f64>> =
            (0..size).map(|_| (0..n).map(|_| rng.random_range(-sigma0..=sigma0)).collect()).collect();
        let mut position = vec![c0.clone()];
        position.extend(run.evaluate_batch(&initial[1..])?);
        let mut personal = position.clone();
        loop {
            let global = run.best().u.clone();
            let proposals: Vec<Vec<f64>> = (0..size)
                .map(|k| {
                    (0..n)
                        .map(|i| {
                            let (r1, r2): (f64, f64) = (rng.random(), rng.random());
                            let x = position[k].u[i];
                            velocity[k][i] = INERTIA * velocity[k][i]
                                + ACCELERATION * r1 * (personal[k].u[i] - x)
                                + ACCELERATION * r2 * (global[i] - x);
                            x + velocity[k][i]
                        })
                        .collect()
                })
                .collect();
            let evaluated = run.evaluate_batch(&proposals)?;
            for (k, c) in evaluated.into_iter().enumerate() {
                if c.f < personal[k].f {
                    personal[k] = c.clone();
                }
                position[k] = c;
            }
            let best = run.best().u.clone();
            let us: Vec<&[f64]> = personal.iter().map(|c| c.u.as_slice()).collect();
            let fs: Vec<f64> = personal.iter().map(|c| c.f).collect();
            let converged = population_converged(&us, &fs, &best, &self.options);
            if let Some(stop) = run.end_iteration(converged) {
                return Ok(run.finish(stop));
            }
        }
    }
}
