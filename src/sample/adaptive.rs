//! Haario-Bardenet adaptive covariance Metropolis (Haario, Saksman & Tamminen 2001; the
//! global-scale variant of Andrieu & Thoms 2008, as `HaarioBardenetACMC` in PINTS).

use rand::SeedableRng;
use rand::rngs::StdRng;

use super::metropolis::{gain, metropolis, normal_vector};
use super::run::Recorder;
use super::target::Counted;
use super::{Chain, LogDensity, Progress, ChainSampler, SamplerOptions, Schedule};
use crate::error::Result;

/// Lower Cholesky factor (row-major) of the symmetric `n×n` matrix `a`, with a diagonal
/// jitter grown from `1e-12·max diag` until the factorisation succeeds.
fn cholesky(a: &[f64], n: usize) -> Vec<f64> {
    let max_diag = (0..n).map(|i| a[i * n + i].abs()).fold(f64::MIN_POSITIVE, f64::max);
    let mut jitter = 0.0;
    loop {
        let shifted: Vec<f64> = (0..n * n).map(|k| a[k] + if k % (n + 1) == 0 { jitter } else { 0.0 }).collect();
        if let Some(l) = crate::linalg::cholesky(&shifted, n) {
            return l;
        }
        jitter = if jitter == 0.0 { 1e-12 * max_diag } else { jitter * 10.0 };
        if !(jitter <= 1e3 * max_diag) {
            // Not a covariance (NaN entries): fall back to an isotropic matrix.
            let d = if max_diag.is_finite() { max_diag.sqrt() } else { 1.0 };
            return (0..n * n).map(|k| if k % (n + 1) == 0 { d } else { 0.0 }).collect();
        }
    }
}

/// Adaptive covariance Metropolis: proposal `y = x + N(0, λ·Σ)`.
///
/// Warmup (with `adapt`): for the first fifth only `log λ` adapts (Robbins-Monro towards the
/// target acceptance, default 0.234), with `Σ = proposal_scale²·I`; then `Σ ← λ·Σ`, `λ ← 1`
/// and mean `μ`, covariance `Σ` and `log λ` all adapt with gain `γ_s = (s + 10)^(-0.6)`:
/// `Σ ← (1 - γ)·Σ + γ·(x - μ)(x - μ)ᵀ`, `μ ← μ + γ·(x - μ)`, `log λ ← log λ + γ·(α - α*)`.
/// After warmup the proposal is fixed.
#[derive(Clone, Debug)]
pub struct AdaptiveMetropolis {
    options: SamplerOptions,
}

impl AdaptiveMetropolis {
    pub fn new(options: SamplerOptions) -> Result<Self> {
        options.validate()?;
        Ok(AdaptiveMetropolis { options })
    }

}

impl ChainSampler for AdaptiveMetropolis {
    fn name(&self) -> &str {
        "adaptive-metropolis"
    }

    fn run_chain(&self, target: &dyn LogDensity, x0: &[f64], seed: u64, schedule: Schedule, progress: Progress) -> Result<Chain> {
        let counted = Counted::new(target);
        let mut rng = StdRng::seed_from_u64(seed);
        let mut rec = Recorder::new(schedule);
        let n = x0.len();
        let goal = self.options.acceptance(0.234);
        let s0 = self.options.proposal_scale;
        let mut sigma: Vec<f64> = (0..n * n).map(|k| if k % (n + 1) == 0 { s0 * s0 } else { 0.0 }).collect();
        let mut mu = x0.to_vec();
        let mut log_lambda: f64 = 0.0;
        let scale_only = schedule.warmup / 5;
        let mut chol = cholesky(&sigma, n);
        let mut x = x0.to_vec();
        let mut fx = counted.log_density(&x);
        for it in 0..schedule.total() {
            let adapting = self.options.adapt && it < schedule.warmup;
            let lambda_sqrt = (0.5 * log_lambda).exp();
            let z = normal_vector(&mut rng, n);
            let y: Vec<f64> =
                (0..n).map(|i| x[i] + lambda_sqrt * (0..=i).map(|k| chol[i * n + k] * z[k]).sum::<f64>()).collect();
            let fy = counted.log_density(&y);
            let (accepted, alpha) = metropolis(&mut rng, fy - fx);
            if accepted {
                x = y;
                fx = fy;
            }
            if adapting {
                if it < scale_only {
                    log_lambda += gain(it) * (alpha - goal);
                } else {
                    if it == scale_only {
                        let lambda = log_lambda.exp();
                        sigma.iter_mut().for_each(|v| *v *= lambda);
                        log_lambda = 0.0;
                        mu.clone_from(&x);
                    }
                    let g = gain(it - scale_only + 9);
                    let d: Vec<f64> = x.iter().zip(&mu).map(|(a, b)| a - b).collect();
                    for i in 0..n {
                        for j in 0..n {
                            sigma[i * n + j] = (1.0 - g) * sigma[i * n + j] + g * d[i] * d[j];
                        }
                        mu[i] += g * d[i];
                    }
                    log_lambda += g * (alpha - goal);
                    chol = cholesky(&sigma, n);
                }
            }
            rec.record(it, &x, fx, f64::from(u8::from(accepted)), false);
            progress();
        }
        Ok(rec.finish(&counted, None))
    }
}
