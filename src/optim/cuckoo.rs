//! Cuckoo search via Lévy flights (Yang and Deb, 2009), following the authors' reference
//! implementation.

use rand::Rng;
use rand::seq::SliceRandom;

use super::run::{Run, normal, population_converged};
use super::{Observer, OptimOptions, OptimResult, Optimiser, Problem};
use crate::error::{Error, Result};

/// Lévy exponent β of the flights.
const LEVY_BETA: f64 = 1.5;
/// Mantegna's σ_u for β = 1.5:
/// `[Γ(1+β)·sin(πβ/2) / (Γ((1+β)/2)·β·2^((β-1)/2))]^(1/β)`.
const MANTEGNA_SIGMA: f64 = 0.696_574_502_557_696_7;
/// Scale of the Lévy steps relative to the distance to the best nest.
const STEP_SCALE: f64 = 0.01;

/// Cuckoo search. Each generation has two evaluated phases:
/// 1. Lévy flights: nest `x` proposes `x + 0.01·L ⊙ (x - best) ⊙ N(0, 1)` (`L` Lévy-stable,
///    β = 1.5, Mantegna's algorithm) and takes it if better;
/// 2. discovery: with `K_ij = [r_ij > pa]`, nest `x_i` proposes `x_i + r·K_i ⊙ (x_p - x_q)`
///    (random permutations `p`, `q`, `r ~ U(0, 1)`) and takes it if better — so each
///    coordinate moves with probability `1 - pa`, exactly as in the reference code.
///
/// 25 nests by default, `pa = 0.25`.
#[derive(Clone, Debug)]
pub struct CuckooSearch {
    options: OptimOptions,
    discovery: f64,
}

impl CuckooSearch {
    pub fn new(options: OptimOptions) -> Result<Self> {
        options.validate()?;
        Ok(CuckooSearch { options, discovery: 0.25 })
    }

    /// Discovery rate `pa` in `[0, 1)` (default 0.25).
    ///
    /// ```
    /// use cellstudio::optim::{CuckooSearch, OptimOptions};
    /// assert!(CuckooSearch::new(OptimOptions::default()).unwrap().with_discovery_rate(1.0).is_err());
    /// ```
    pub fn with_discovery_rate(mut self, pa: f64) -> Result<Self> {
        if !(0.0..1.0).contains(&pa) {
            return Err(Error::InvalidSetting {
                field: "discovery_rate".into(),
                reason: format!("must be in [0, 1), got {pa}"),
            });
        }
        self.discovery = pa;
        Ok(self)
    }
}

impl Optimiser for CuckooSearch {
    fn name(&self) -> &str {
        "cuckoo"
    }

    fn minimise(&mut self, problem: &Problem, x0: &[f64], observer: &mut dyn Observer) -> Result<OptimResult> {
        let (mut run, c0) = Run::start(problem, &self.options, observer, x0)?;
        let mut rng = run.rng();
        let n = run.dim();
        let size = self.options.population(25, 3, "cuckoo search")?;
        let mut nests = vec![c0.clone()];
        let initial = run.initial_population(&mut rng, &c0.u, size);
        nests.extend(run.evaluate_batch(&initial[1..])?);
        loop {
            // Lévy flights.
            let best = run.best().u.clone();
            let flights: Vec<Vec<f64>> = nests
                .iter()
                .map(|nest| {
                    (0..n)
                        .map(|i| {
                            let levy = MANTEGNA_SIGMA * normal(&mut rng) / normal(&mut rng).abs().powf(1.0 / LEVY_BETA);
                            nest.u[i] + STEP_SCALE * levy * (nest.u[i] - best[i]) * normal(&mut rng)
                        })
                        .collect()
                })
                .collect();
            for (slot, c) in nests.iter_mut().zip(run.evaluate_batch(&flights)?) {
                if c.f < slot.f {
                    *slot = c;
                }
            }
            // Discovery of nests by the hosts: biased random walks.
            let mut p: Vec<usize> = (0..size).collect();
            let mut q: Vec<usize> = (0..size).collect();
            p.shuffle(&mut rng);
            q.shuffle(&mut rng);
            let r: f64 = rng.random();
            let mut moved = Vec::new();
            let mut proposals = Vec::new();
            for k in 0..size {
                let mut changed = false;
                let proposal: Vec<f64> = (0..n)
                    .map(|i| {
                        if rng.random::<f64>() > self.discovery {
                            changed = true;
                            nests[k].u[i] + r * (nests[p[k]].u[i] - nests[q[k]].u[i])
                        } else {
                            nests[k].u[i]
                        }
                    })
                    .collect();
                if changed && p[k] != q[k] {
                    moved.push(k);
                    proposals.push(proposal);
                }
            }
            for (k, c) in moved.into_iter().zip(run.evaluate_batch(&proposals)?) {
                if c.f < nests[k].f {
                    nests[k] = c;
                }
            }
            let best = run.best().u.clone();
            let us: Vec<&[f64]> = nests.iter().map(|c| c.u.as_slice()).collect();
            let fs: Vec<f64> = nests.iter().map(|c| c.f).collect();
            let converged = population_converged(&us, &fs, &best, &self.options);
            if let Some(stop) = run.end_iteration(converged) {
                return Ok(run.finish(stop));
            }
        }
    }
}
