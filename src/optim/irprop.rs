//! iRprop⁻ (Igel and Hüsken, "Improving the Rprop learning algorithm", 2000).

use super::gradient_descent::require_finite_start;
use super::run::{Candidate, Run, projected_gradient};
use super::{Observer, OptimOptions, OptimResult, Optimiser, Problem};
use crate::error::Result;

/// Step growth factor η⁺.
const ETA_PLUS: f64 = 1.2;
/// Step shrink factor η⁻.
const ETA_MINUS: f64 = 0.5;

/// iRprop⁻: sign-based steps with one adaptive step size `Δ_i` per variable, driven by the
/// projected gradient (components blocked by active constraints removed, so a constrained
/// minimum is a fixed point). When the sign of `∂f/∂u_i` is unchanged, `Δ_i` grows by 1.2; when it flips, `Δ_i` shrinks by 0.5 and that
/// coordinate pauses for one iteration. Steps start at `sigma0` and stay within
/// `[x_tolerance / 10, 1]` (fractions of the bound range); each candidate is projected.
/// Stops with `Tolerance` once every `Δ_i <= x_tolerance` (except where the gradient is
/// exactly zero) and the last iteration improved the best value by at most `f_tolerance`
/// (the iteration is not monotone). Insensitive to the scale of the gradient. Deterministic.
#[derive(Clone, Debug)]
pub struct IRpropMinus {
    options: OptimOptions,
}

impl IRpropMinus {
    pub fn new(options: OptimOptions) -> Result<Self> {
        options.validate()?;
        Ok(IRpropMinus { options })
    }
}

impl Optimiser for IRpropMinus {
    fn name(&self) -> &str {
        "irprop-"
    }

    fn minimise(&mut self, problem: &Problem, x0: &[f64], observer: &mut dyn Observer) -> Result<OptimResult> {
        let (mut run, mut current) = Run::start(problem, &self.options, observer, x0)?;
        require_finite_start(&current, "iRprop-")?;
        let n = run.dim();
        let (delta_min, delta_max) = (0.1 * self.options.x_tolerance, 1.0);
        let mut delta = vec![self.options.sigma0.min(delta_max); n];
        let mut previous = vec![0.0; n];
        let sigma0 = self.options.sigma0;
        let gradient = |run: &mut Run, c: &Candidate| -> Result<Vec<f64>> {
            let g = run.gradient(c)?;
            projected_gradient(run, c, &g, sigma0)
        };
        let mut g = gradient(&mut run, &current)?;
        loop {
            let trial: Vec<f64> = (0..n)
                .map(|i| {
                    let product = g[i] * previous[i];
                    if product > 0.0 {
                        delta[i] = (delta[i] * ETA_PLUS).min(delta_max);
                    } else if product < 0.0 {
                        delta[i] = (delta[i] * ETA_MINUS).max(delta_min);
                        g[i] = 0.0;
                    }
                    previous[i] = g[i];
                    current.u[i] - g[i].signum() * if g[i] == 0.0 { 0.0 } else { delta[i] }
                })
                .collect();
            let best_before = run.best().f;
            current = run.evaluate(&trial)?;
            let improvement = best_before - run.best().f;
            g = gradient(&mut run, &current)?;
            // A coordinate whose gradient is exactly zero does not move and cannot shrink its
            // step: it does not block convergence.
            let converged = (0..n).all(|i| delta[i] <= self.options.x_tolerance || g[i] == 0.0)
                && improvement <= self.options.f_tolerance;
            if let Some(stop) = run.end_iteration(converged) {
                return Ok(run.finish(stop));
            }
        }
    }
}
