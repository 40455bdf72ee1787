//! Differential evolution, DE/rand/1/bin (Storn and Price, 1997) with dithered weight.

use rand::Rng;

use super::run::{Run, population_converged};
use super::{Observer, OptimOptions, OptimResult, Optimiser, Problem};
use crate::error::{Error, Result};

/// Differential evolution. Each generation every member `i` proposes
/// `a + F·(b - c)` (three other distinct members), crossed over coordinate-wise with
/// probability `CR`, projected, and replaces `i` if not worse. `F` is drawn uniformly from
/// `[0.5, 1)` each generation ("dither"), `CR = 0.9`. Population `clamp(10·n, 20, 100)` by
/// default; the initial population is `x0` plus uniform draws within `x0 ± 2·sigma0`.
#[derive(Clone, Debug)]
pub struct DifferentialEvolution {
    options: OptimOptions,
    crossover: f64,
}

impl DifferentialEvolution {
    pub fn new(options: OptimOptions) -> Result<Self> {
        options.validate()?;
        Ok(DifferentialEvolution { options, crossover: 0.9 })
    }

    /// Crossover probability `CR` in `[0, 1]` (default 0.9).
    ///
    /// ```
    /// use cellstudio::optim::{DifferentialEvolution, OptimOptions};
    /// let de = DifferentialEvolution::new(OptimOptions::default()).unwrap();
    /// let err = de.with_crossover(1.5).unwrap_err();
    /// assert_eq!(err.to_string(), "invalid setting `crossover`: must be in [0, 1], got 1.5");
    /// ```
    pub fn with_crossover(mut self, cr: f64) -> Result<Self> {
        if !(0.0..=1.0).contains(&cr) {
            return Err(Error::InvalidSetting {
                field: "crossover".into(),
                reason: format!("must be in [0, 1], got {cr}"),
            });
        }
        self.crossover = cr;
        Ok(self)
    }
}

impl Optimiser for DifferentialEvolution {
    fn name(&self) -> &str {
        "differential-evolution"
    }

    fn minimise(&mut self, problem: &Problem, x0: &[f64], observer: &mut dyn Observer) -> Result<OptimResult> {
        let (mut run, c0) = Run::start(problem, &self.options, observer, x0)?;
        let mut rng = run.rng();
        let n = run.dim();
        let size = self.options.population((10 * n).clamp(20, 100), 4, "differential evolution")?;
        let mut pop = vec![c0.clone()];
        let initial = run.initial_population(&mut rng, &c0.u, size);
        pop.extend(run.evaluate_batch(&initial[1..])?);
        loop {
            // Differential weight F, dithered per generation.
            let weight: f64 = rng.random_range(0.5..1.0);
            let trials: Vec<Vec<f64>> = (0..size)
                .map(|i| {
                    let mut pick = |exclude: &[usize]| loop {
                        let k = rng.random_range(0..size);
                        if !exclude.contains(&k) {
                            return k;
                        }
                    };
                    let a = pick(&[i]);
                    let b = pick(&[i, a]);
                    let c = pick(&[i, a, b]);
                    let forced = rng.random_range(0..n);
                    (0..n)
                        .map(|j| {
                            if j == forced || rng.random::<f64>() < self.crossover {
                                pop[a].u[j] + weight * (pop[b].u[j] - pop[c].u[j])
                            } else {
                                pop[i].u[j]
                            }
                        })
                        .collect()
                })
                .collect();
            let evaluated = run.evaluate_batch(&trials)?;
            for (slot, trial) in pop.iter_mut().zip(evaluated) {
                if trial.f <= slot.f {
                    *slot = trial;
                }
            }
            let best = run.best().u.clone();
            let us: Vec<&[f64]> = pop.iter().map(|c| c.u.as_slice()).collect();
            let fs: Vec<f64> = pop.iter().map(|c| c.f).collect();
            let converged = population_converged(&us, &fs, &best, &self.options);
            if let Some(stop) = run.end_iteration(converged) {
                return Ok(run.finish(stop));
            }
        }
    }
}
