//! AdamW (Loshchilov and Hutter, "Decoupled weight decay regularization", ICLR 2019) with
//! projection and a reduce-on-plateau learning rate.

use super::gradient_descent::require_finite_start;
use super::run::{Candidate, Run, max_abs_diff, projected_gradient};
use super::{Observer, OptimOptions, OptimResult, Optimiser, Problem};
use crate::error::{Error, Result};

/// Iterations without a new best value before the learning rate is halved.
const PLATEAU: usize = 25;

/// Adam with decoupled weight decay: `u ← P(u - lr·(m̂ / (√v̂ + ε) + λ·u))` with the usual
/// bias-corrected moment estimates of the projected gradient (components blocked by active
/// constraints removed, so a constrained minimum is a fixed point) (`β₁ = 0.9`, `β₂ = 0.999`, `ε = 1e-8`). The learning rate
/// starts at `sigma0` (Adam's first step moves every coordinate by about `lr`); after
/// 25 iterations without a new best value it is halved and the iteration restarts (fresh
/// moments) from the best point, which makes the deterministic iteration converge instead of
/// circling the minimum. Stops with `Tolerance` once `lr <= x_tolerance`, or when a step
/// moves by at most `x_tolerance` and changes `f` by at most `f_tolerance`. The result is the
/// best point by `f`.
///
/// Weight decay `λ` (default 0) pulls the normalised search coordinates towards zero, i.e.
/// it moves the minimiser: leave it at 0 unless that regularisation is wanted.
#[derive(Clone, Debug)]
pub struct AdamW {
    options: OptimOptions,
    weight_decay: f64,
}

impl AdamW {
    pub fn new(options: OptimOptions) -> Result<Self> {
        options.validate()?;
        Ok(AdamW { options, weight_decay: 0.0 })
    }

    /// Decoupled weight decay `λ >= 0` (default 0).
    ///
    /// ```
    /// use cellstudio::optim::{AdamW, OptimOptions};
    /// let err = AdamW::new(OptimOptions::default()).unwrap().with_weight_decay(-0.1).unwrap_err();
    /// assert_eq!(err.to_string(), "invalid setting `weight_decay`: must be non-negative and finite, got -0.1");
    /// ```
    pub fn with_weight_decay(mut self, lambda: f64) -> Result<Self> {
        if !(lambda >= 0.0 && lambda.is_finite()) {
            return Err(Error::InvalidSetting {
                field: "weight_decay".into(),
                reason: format!("must be non-negative and finite, got {lambda}"),
            });
        }
        self.weight_decay = lambda;
        Ok(self)
    }
}

impl Optimiser for AdamW {
    fn name(&self) -> &str {
        "adamw"
    }

    fn minimise(&mut self, problem: &Problem, x0: &[f64], observer: &mut dyn Observer) -> Result<OptimResult> {
        let (beta1, beta2, eps) = (0.9f64, 0.999f64, 1e-8);
        let (mut run, mut current) = Run::start(problem, &self.options, observer, x0)?;
        require_finite_start(&current, "AdamW")?;
        let n = run.dim();
        let sigma0 = self.options.sigma0;
        let gradient = |run: &mut Run, c: &Candidate| -> Result<Vec<f64>> {
            let g = run.gradient(c)?;
            projected_gradient(run, c, &g, sigma0)
        };
        let mut g = gradient(&mut run, &current)?;
        let mut lr = self.options.sigma0;
        let (mut m, mut v) = (vec![0.0; n], vec![0.0; n]);
        let mut stall = 0;
        let mut t = 0;
        loop {
            t += 1;
            let (c1, c2) = (1.0 - beta1.powi(t), 1.0 - beta2.powi(t));
            let trial: Vec<f64> = (0..n)
                .map(|i| {
                    m[i] = beta1 * m[i] + (1.0 - beta1) * g[i];
                    v[i] = beta2 * v[i] + (1.0 - beta2) * g[i] * g[i];
                    let step = (m[i] / c1) / ((v[i] / c2).sqrt() + eps) + self.weight_decay * current.u[i];
                    current.u[i] - lr * step
                })
                .collect();
            let best_before = run.best().f;
            let next = run.evaluate(&trial)?;
            let moved = max_abs_diff(&next.u, &current.u);
            let change = (next.f - current.f).abs();
            current = next;
            if run.best().f < best_before {
                stall = 0;
                g = gradient(&mut run, &current)?;
            } else {
                stall += 1;
                if stall >= PLATEAU {
                    // Plateau: halve the rate and restart the moments from the best point.
                    lr *= 0.5;
                    stall = 0;
                    current = run.best().clone();
                    m.fill(0.0);
                    v.fill(0.0);
                    t = 0;
                }
                g = gradient(&mut run, &current)?;
            }
            let converged = lr <= self.options.x_tolerance
                || (moved <= self.options.x_tolerance && change <= self.options.f_tolerance);
            if let Some(stop) = run.end_iteration(converged) {
                return Ok(run.finish(stop));
            }
        }
    }
}
