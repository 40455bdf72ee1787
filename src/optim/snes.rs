//! Separable natural evolution strategy (Schaul, Glasmachers and Schmidhuber, "High
//! dimensions and heavy tails for natural evolution strategies", GECCO 2011).

use super::run::{Run, history_flat, nes_utilities, normal, penalised_ranking};
use super::{Observer, OptimOptions, OptimResult, Optimiser, Problem, StopReason};
use crate::error::Result;

/// sNES: Gaussian search distribution with a diagonal covariance (one step size per
/// variable), `O(n)` per sample. Population `4 + ⌊3 ln n⌋` by default. Constraint handling as
/// in [`super::CmaEs`].
#[derive(Clone, Debug)]
pub struct Snes {
    options: OptimOptions,
}

impl Snes {
    pub fn new(options: OptimOptions) -> Result<Self> {
        options.validate()?;
        Ok(Snes { options })
    }
}

impl Optimiser for Snes {
    fn name(&self) -> &str {
        "snes"
    }

    fn minimise(&mut self, problem: &Problem, x0: &[f64], observer: &mut dyn Observer) -> Result<OptimResult> {
        let (mut run, c0) = Run::start(problem, &self.options, observer, x0)?;
        let mut rng = run.rng();
        let n = run.dim();
        let nf = n as f64;
        let lambda = self.options.population(4 + (3.0 * nf.ln()).floor() as usize, 2, "sNES")?;
        let utilities = nes_utilities(lambda);
        // Learning rates of the mean (η_μ) and of the step sizes (η_σ).
        let eta_mu = 1.0;
        let eta_sigma = (3.0 + nf.ln()) / (5.0 * nf.sqrt());
        let window = 10 + (30.0 * nf / lambda as f64).ceil() as usize;

        let mut mean = c0.u.clone();
        // Per-variable step sizes σ_i in normalised units.
        let mut sigma = vec![self.options.sigma0; n];
        let mut history = Vec::new();
        loop {
            let ss: Vec<Vec<f64>> = (0..lambda).map(|_| (0..n).map(|_| normal(&mut rng)).collect()).collect();
            let zs: Vec<Vec<f64>> = ss.iter().map(|s| (0..n).map(|i| mean[i] + sigma[i] * s[i]).collect()).collect();
            let evaluated = run.evaluate_batch(&zs)?;
            let mean_var = sigma.iter().map(|s| s * s).sum::<f64>() / nf;
            let order = penalised_ranking(&zs, &evaluated, mean_var);

            let mut g_mu = vec![0.0; n];
            let mut g_sigma = vec![0.0; n];
            for (u, &k) in utilities.iter().zip(&order) {
                for i in 0..n {
                    let s = ss[k][i];
                    g_mu[i] += u * s;
                    g_sigma[i] += u * (s * s - 1.0);
                }
            }
            for i in 0..n {
                mean[i] += eta_mu * sigma[i] * g_mu[i];
                sigma[i] *= (0.5 * eta_sigma * g_sigma[i]).exp();
            }

            let fs: Vec<f64> = evaluated.iter().map(|c| c.f).collect();
            history.push(evaluated[order[0]].f);
            let max_sigma = sigma.iter().copied().fold(0.0, f64::max);
            let converged = max_sigma <= self.options.x_tolerance && history_flat(&history, window, &fs, &self.options);
            let degenerate = sigma.iter().any(|s| !s.is_finite() || *s == 0.0);
            if let Some(stop) = run.end_iteration(converged) {
                return Ok(run.finish(stop));
            }
            if degenerate {
                return Ok(run.finish(StopReason::Degenerate));
            }
        }
    }
}
