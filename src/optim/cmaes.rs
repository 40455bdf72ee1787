//! CMA-ES (Hansen, "The CMA Evolution Strategy: A Tutorial", 2016), (μ/μ_w, λ) with
//! cumulative step-size adaptation and rank-one + rank-μ covariance updates.

use crate::linalg::{mat_t_vec, mat_vec, sym_eigen};
use super::run::{Run, history_flat, normal, penalised_ranking};
use super::{Observer, OptimOptions, OptimResult, Optimiser, Problem, StopReason};
use crate::error::Result;

/// Covariance matrix adaptation evolution strategy.
///
/// Population `λ = 4 + ⌊3 ln n⌋` unless `population_size` is set; initial step `sigma0`.
/// Samples are projected before evaluation; the distribution is updated with the raw samples
/// ranked by the projected value plus a distance penalty (see `penalised_ranking`), so the
/// mean is drawn back into the feasible set rather than stuck outside it.
#[derive(Clone, Debug)]
pub struct CmaEs {
    options: OptimOptions,
}

impl CmaEs {
    pub fn new(options: OptimOptions) -> Result<Self> {
        options.validate()?;
        Ok(CmaEs { options })
    }
}

impl Optimiser for CmaEs {
    fn name(&self) -> &str {
        "cmaes"
    }

    fn minimise(&mut self, problem: &Problem, x0: &[f64], observer: &mut dyn Observer) -> Result<OptimResult> {
        let (mut run, c0) = Run::start(problem, &self.options, observer, x0)?;
        let mut rng = run.rng();
        let n = run.dim();
        let nf = n as f64;
        let lambda = self.options.population(4 + (3.0 * nf.ln()).floor() as usize, 2, "CMA-ES")?;
        let mu = lambda / 2;
        let raw_w: Vec<f64> = (0..mu).map(|i| (mu as f64 + 0.5).ln() - ((i + 1) as f64).ln()).collect();
        let sum_w: f64 = raw_w.iter().sum();
        let weights: Vec<f64> = raw_w.iter().map(|w| w / sum_w).collect();
        let mu_eff = 1.0 / weights.iter().map(|w| w * w).sum::<f64>();
        // Learning rates of the evolution paths (c_c, c_σ), rank-one (c_1) and rank-μ (c_μ)
        // updates, and the step-size damping d_σ.
        let cc = (4.0 + mu_eff / nf) / (nf + 4.0 + 2.0 * mu_eff / nf);
        let cs = (mu_eff + 2.0) / (nf + mu_eff + 5.0);
        let c1 = 2.0 / ((nf + 1.3).powi(2) + mu_eff);
        let cmu = (1.0 - c1).min(2.0 * (mu_eff - 2.0 + 1.0 / mu_eff) / ((nf + 2.0).powi(2) + mu_eff));
        let damps = 1.0 + 2.0 * (((mu_eff - 1.0) / (nf + 1.0)).sqrt() - 1.0).max(0.0) + cs;
        // E||N(0, I)||.
        let chi_n = nf.sqrt() * (1.0 - 1.0 / (4.0 * nf) + 1.0 / (21.0 * nf * nf));
        let window = 10 + (30.0 * nf / lambda as f64).ceil() as usize;

        let mut mean = c0.u.clone();
        // Step size σ in normalised units.
        let mut sigma = self.options.sigma0;
        let mut cov = crate::linalg::identity(n);
        let mut pc = vec![0.0; n];
        let mut ps = vec![0.0; n];
        let mut history = Vec::new();
        let mut generation = 0usize;
        loop {
            generation += 1;
            let (values, vectors) = sym_eigen(&cov, n)?;
            let d: Vec<f64> = values.iter().map(|v| v.max(1e-300).sqrt()).collect();
            // Samples y_k = B·D·s_k, candidates z_k = m + σ·y_k; random numbers drawn in order.
            let ys: Vec<Vec<f64>> = (0..lambda)
                .map(|_| {
                    let s: Vec<f64> = (0..n).map(|i| d[i] * normal(&mut rng)).collect();
                    mat_vec(&vectors, n, &s)
                })
                .collect();
            let zs: Vec<Vec<f64>> =
                ys.iter().map(|y| mean.iter().zip(y).map(|(m, y)| m + sigma * y).collect()).collect();
            let evaluated = run.evaluate_batch(&zs)?;
            let mean_var = (0..n).map(|i| cov[i * n + i]).sum::<f64>() / nf;
            let order = penalised_ranking(&zs, &evaluated, sigma * sigma * mean_var);

            let old_mean = mean.clone();
            let mut y_w = vec![0.0; n];
            for (w, &k) in weights.iter().zip(&order) {
                for i in 0..n {
                    y_w[i] += w * ys[k][i];
                }
            }
            for i in 0..n {
                mean[i] = old_mean[i] + sigma * y_w[i];
            }
            // C^{-1/2}·y_w = B·D^{-1}·Bᵀ·y_w.
            let by = mat_t_vec(&vectors, n, &y_w);
            let scaled: Vec<f64> = by.iter().zip(&d).map(|(v, d)| v / d).collect();
            let c_inv_sqrt_y = mat_vec(&vectors, n, &scaled);
            let a_s = (cs * (2.0 - cs) * mu_eff).sqrt();
            for i in 0..n {
                ps[i] = (1.0 - cs) * ps[i] + a_s * c_inv_sqrt_y[i];
            }
            let ps_norm = ps.iter().map(|v| v * v).sum::<f64>().sqrt();
            let h_sigma =
                ps_norm / (1.0 - (1.0 - cs).powi(2 * generation as i32)).sqrt() / chi_n < 1.4 + 2.0 / (nf + 1.0);
            let a_c = if h_sigma { (cc * (2.0 - cc) * mu_eff).sqrt() } else { 0.0 };
            for i in 0..n {
                pc[i] = (1.0 - cc) * pc[i] + a_c * y_w[i];
            }
            let decay = 1.0 - c1 - cmu + if h_sigma { 0.0 } else { c1 * cc * (2.0 - cc) };
            for i in 0..n {
                for j in 0..=i {
                    let rank_mu: f64 = weights.iter().zip(&order).map(|(w, &k)| w * ys[k][i] * ys[k][j]).sum();
                    let v = decay * cov[i * n + j] + c1 * pc[i] * pc[j] + cmu * rank_mu;
                    cov[i * n + j] = v;
                    cov[j * n + i] = v;
                }
            }
            sigma *= ((cs / damps) * (ps_norm / chi_n - 1.0)).min(1.0).exp();

            let fs: Vec<f64> = evaluated.iter().map(|c| c.f).collect();
            history.push(evaluated[order[0]].f);
            let max_sd = (0..n).map(|i| cov[i * n + i].sqrt()).fold(0.0, f64::max);
            let max_pc = pc.iter().fold(0.0f64, |m, v| m.max(v.abs()));
            let converged = sigma * max_sd.max(max_pc) <= self.options.x_tolerance
                && history_flat(&history, window, &fs, &self.options);
            let (dmin, dmax) = d.iter().fold((f64::INFINITY, 0.0f64), |(lo, hi), v| (lo.min(*v), hi.max(*v)));
            let degenerate = !sigma.is_finite() || sigma * dmax == 0.0 || dmax > 1e7 * dmin;
            if let Some(stop) = run.end_iteration(converged) {
                return Ok(run.finish(stop));
            }
            if degenerate {
                return Ok(run.finish(StopReason::Degenerate));
            }
        }
    }
}
