//! Limited-memory BFGS with constraints handled by projection (a projected L-BFGS in the
//! spirit of L-BFGS-B; not the Byrd–Lu–Nocedal–Zhu Cauchy-point algorithm).

use std::collections::VecDeque;

use super::gradient_descent::{LineSearch, projected_line_search, require_finite_start};
use super::run::{Run, max_abs_diff, projected_gradient};
use super::{Observer, OptimOptions, OptimResult, Optimiser, Problem, StopReason};
use crate::linalg::dot;
use crate::error::{Error, Result};

/// Projected L-BFGS.
///
/// Each iteration computes the projected gradient `r` (the gradient with the components
/// blocked by active bounds removed; with linear constraints `r = (u - P(u - κ·g)) / κ`,
/// `κ = sigma0 / ||g||∞`), the
/// quasi-Newton direction `d = -H·r` by the two-loop recursion over the last `memory` pairs
/// (`s = Δu`, `y = Δg`, kept only when `sᵀy > 0`), drops components of `d` that push into an
/// active bound, and backtracks along `P(u + α·d)` from `α = 1` until the Armijo condition
/// holds. If that fails the memory is cleared and a projected steepest-descent step is
/// tried. The first step moves the largest coordinate by `sigma0`. Stops with `Tolerance`
/// when a step changes `u` by at most `x_tolerance` and `f` by at most `f_tolerance`, or
/// when the projected gradient vanishes. Deterministic.
#[derive(Clone, Debug)]
pub struct ProjectedLbfgs {
    options: OptimOptions,
    memory: usize,
}

impl ProjectedLbfgs {
    pub fn new(options: OptimOptions) -> Result<Self> {
        options.validate()?;
        Ok(ProjectedLbfgs { options, memory: 10 })
    }

    /// Number of correction pairs kept (>= 1, default 10).
    ///
    /// ```
    /// use cellstudio::optim::{ProjectedLbfgs, OptimOptions};
    /// let err = ProjectedLbfgs::new(OptimOptions::default()).unwrap().with_memory(0).unwrap_err();
    /// assert_eq!(err.to_string(), "invalid setting `memory`: must be at least 1");
    /// ```
    pub fn with_memory(mut self, m: usize) -> Result<Self> {
        if m == 0 {
            return Err(Error::InvalidSetting { field: "memory".into(), reason: "must be at least 1".into() });
        }
        self.memory = m;
        Ok(self)
    }
}

/// `H·q` by the L-BFGS two-loop recursion, `H₀ = γ·I` with `γ = sᵀy / yᵀy` of the newest pair.
fn two_loop(memory: &VecDeque<(Vec<f64>, Vec<f64>)>, q: &[f64]) -> Vec<f64> {
    let mut q = q.to_vec();
    let mut alphas = Vec::with_capacity(memory.len());
    for (s, y) in memory.iter().rev() {
        let rho = 1.0 / dot(y, s);
        let a = rho * dot(s, &q);
        for (qi, yi) in q.iter_mut().zip(y) {
            *qi -= a * yi;
        }
        alphas.push((a, rho));
    }
    if let Some((s, y)) = memory.back() {
        let gamma = dot(s, y) / dot(y, y);
        for qi in q.iter_mut() {
            *qi *= gamma;
        }
    }
    for ((s, y), (a, rho)) in memory.iter().zip(alphas.into_iter().rev()) {
        let b = rho * dot(y, &q);
        for (qi, si) in q.iter_mut().zip(s) {
            *qi += (a - b) * si;
        }
    }
    q
}

impl Optimiser for ProjectedLbfgs {
    fn name(&self) -> &str {
        "lbfgsb"
    }

    fn minimise(&mut self, problem: &Problem, x0: &[f64], observer: &mut dyn Observer) -> Result<OptimResult> {
        let (mut run, mut current) = Run::start(problem, &self.options, observer, x0)?;
        require_finite_start(&current, "L-BFGS-B")?;
        let sigma0 = self.options.sigma0;
        let mut g = run.gradient(&current)?;
        let mut memory: VecDeque<(Vec<f64>, Vec<f64>)> = VecDeque::with_capacity(self.memory);
        loop {
            let r = projected_gradient(&run, &current, &g, sigma0)?;
            if r.iter().all(|v| *v == 0.0) {
                run.end_iteration(true);
                return Ok(run.finish(StopReason::Tolerance));
            }
            let steepest = |r: &[f64]| -> Vec<f64> {
                let r_max = r.iter().fold(0.0f64, |m, v| m.max(v.abs()));
                r.iter().map(|v| -v * sigma0 / r_max).collect()
            };
            let mut direction: Vec<f64> =
                if memory.is_empty() { steepest(&r) } else { two_loop(&memory, &r).into_iter().map(|v| -v).collect() };
            for (i, d) in direction.iter_mut().enumerate() {
                let u = current.u[i];
                if (u <= run.space.lower[i] && *d < 0.0) || (u >= run.space.upper[i] && *d > 0.0) {
                    *d = 0.0;
                }
            }
            if dot(&g, &direction) >= 0.0 {
                memory.clear();
                direction = steepest(&r);
            }
            let mut outcome = projected_line_search(&mut run, &current, &g, &direction, 1.0)?;
            if matches!(outcome, LineSearch::Failed) && !memory.is_empty() {
                memory.clear();
                direction = steepest(&r);
                outcome = projected_line_search(&mut run, &current, &g, &direction, 1.0)?;
            }
            let next = match outcome {
                LineSearch::Accepted(c, _) => c,
                LineSearch::Stationary => {
                    run.end_iteration(true);
                    return Ok(run.finish(StopReason::Tolerance));
                }
                LineSearch::Failed => {
                    run.end_iteration(false);
                    return Ok(run.finish(StopReason::LineSearchFailed));
                }
            };
            let g_next = run.gradient(&next)?;
            let s: Vec<f64> = next.u.iter().zip(&current.u).map(|(a, b)| a - b).collect();
            let y: Vec<f64> = g_next.iter().zip(&g).map(|(a, b)| a - b).collect();
            let sy = dot(&s, &y);
            if sy > 1e-12 * dot(&s, &s).sqrt() * dot(&y, &y).sqrt() && sy > 0.0 {
                if memory.len() == self.memory {
                    memory.pop_front();
                }
                memory.push_back((s, y));
            }
            let converged = max_abs_diff(&next.u, &current.u) <= self.options.x_tolerance
                && (current.f - next.f).abs() <= self.options.f_tolerance;
            current = next;
            g = g_next;
            if let Some(stop) = run.end_iteration(converged) {
                return Ok(run.finish(stop));
            }
        }
    }
}
