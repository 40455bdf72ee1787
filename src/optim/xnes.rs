//! Exponential natural evolution strategy (Glasmachers, Schaul, Sun, Wierstra and
//! Schmidhuber, "Exponential natural evolution strategies", GECCO 2010).

use crate::linalg::{expm_sym, identity, mat_mul, mat_vec, sym_eigen};
use super::run::{Run, history_flat, nes_utilities, normal, penalised_ranking};
use super::{Observer, OptimOptions, OptimResult, Optimiser, Problem, StopReason};
use crate::error::Result;

/// xNES: Gaussian search distribution `N(μ, σ²·B·Bᵀ)` with `det B = 1`, updated along the
/// natural gradient of rank-based utilities. Population `4 + ⌊3 ln n⌋` by default.
/// Constraint handling as in [`super::CmaEs`].
#[derive(Clone, Debug)]
pub struct Xnes {
    options: OptimOptions,
}

impl Xnes {
    pub fn new(options: OptimOptions) -> Result<Self> {
        options.validate()?;
        Ok(Xnes { options })
    }
}

impl Optimiser for Xnes {
    fn name(&self) -> &str {
        "xnes"
    }

    fn minimise(&mut self, problem: &Problem, x0: &[f64], observer: &mut dyn Observer) -> Result<OptimResult> {
        let (mut run, c0) = Run::start(problem, &self.options, observer, x0)?;
        let mut rng = run.rng();
        let n = run.dim();
        let nf = n as f64;
        let lambda = self.options.population(4 + (3.0 * nf.ln()).floor() as usize, 2, "xNES")?;
        let utilities = nes_utilities(lambda);
        // Learning rates of the mean (η_μ) and of the scale and shape (η_σ = η_B).
        let eta_mu = 1.0;
        let eta_sigma = (9.0 + 3.0 * nf.ln()) / (5.0 * nf * nf.sqrt());
        let window = 10 + (30.0 * nf / lambda as f64).ceil() as usize;

        let mut mean = c0.u.clone();
        let mut sigma = self.options.sigma0;
        let mut b = identity(n);
        let mut history = Vec::new();
        loop {
            let ss: Vec<Vec<f64>> = (0..lambda).map(|_| (0..n).map(|_| normal(&mut rng)).collect()).collect();
            let zs: Vec<Vec<f64>> = ss
                .iter()
                .map(|s| {
                    let bs = mat_vec(&b, n, s);
                    mean.iter().zip(&bs).map(|(m, v)| m + sigma * v).collect()
                })
                .collect();
            let evaluated = run.evaluate_batch(&zs)?;
            let bbt_diag =
                |b: &[f64]| -> Vec<f64> { (0..n).map(|i| (0..n).map(|k| b[i * n + k].powi(2)).sum()).collect() };
            let mean_var = bbt_diag(&b).iter().sum::<f64>() / nf;
            let order = penalised_ranking(&zs, &evaluated, sigma * sigma * mean_var);

            let mut g_delta = vec![0.0; n];
            let mut g_m = vec![0.0; n * n];
            for (u, &k) in utilities.iter().zip(&order) {
                let s = &ss[k];
                for i in 0..n {
                    g_delta[i] += u * s[i];
                    for j in 0..n {
                        g_m[i * n + j] += u * (s[i] * s[j] - if i == j { 1.0 } else { 0.0 });
                    }
                }
            }
            let g_sigma = (0..n).map(|i| g_m[i * n + i]).sum::<f64>() / nf;
            for i in 0..n {
                g_m[i * n + i] -= g_sigma;
            }
            let step = mat_vec(&b, n, &g_delta);
            for i in 0..n {
                mean[i] += eta_mu * sigma * step[i];
            }
            sigma *= (0.5 * eta_sigma * g_sigma).exp();
            let half: Vec<f64> = g_m.iter().map(|v| 0.5 * eta_sigma * v).collect();
            b = mat_mul(&b, &expm_sym(&half, n)?, n);

            let fs: Vec<f64> = evaluated.iter().map(|c| c.f).collect();
            history.push(evaluated[order[0]].f);
            let max_sd = bbt_diag(&b).into_iter().fold(0.0, f64::max).sqrt();
            let converged =
                sigma * max_sd <= self.options.x_tolerance && history_flat(&history, window, &fs, &self.options);
            let degenerate = !sigma.is_finite() || sigma == 0.0 || b.iter().any(|v| !v.is_finite()) || {
                let bt: Vec<f64> = (0..n * n).map(|k| b[(k % n) * n + k / n]).collect();
                let (values, _) = sym_eigen(&mat_mul(&b, &bt, n), n)?;
                values[n - 1] > 1e14 * values[0].max(0.0)
            };
            if let Some(stop) = run.end_iteration(converged) {
                return Ok(run.finish(stop));
            }
            if degenerate {
                return Ok(run.finish(StopReason::Degenerate));
            }
        }
    }
}
