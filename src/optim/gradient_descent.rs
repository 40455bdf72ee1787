//! Projected gradient descent with an Armijo backtracking line search.

use super::run::{Candidate, Run, max_abs_diff};
use super::{Observer, OptimOptions, OptimResult, Optimiser, Problem, StopReason};
use crate::error::{Error, Result};

/// Armijo sufficient-decrease constant.
pub(crate) const ARMIJO: f64 = 1e-4;
/// Maximum number of step halvings in one line search.
pub(crate) const MAX_BACKTRACKS: usize = 50;

/// Steepest descent on the projected path `u(α) = P(u - α·g)`, where `α` is halved until the
/// Armijo condition `f(u(α)) <= f(u) + 1e-4·gᵀ(u(α) - u)` holds, and doubled for the next
/// iteration after a step accepted at the first trial. The first step moves the largest
/// coordinate by `sigma0`. Converges linearly: give it many iterations on ill-conditioned
/// problems. Deterministic.
#[derive(Clone, Debug)]
pub struct GradientDescent {
    options: OptimOptions,
}

impl GradientDescent {
    pub fn new(options: OptimOptions) -> Result<Self> {
        options.validate()?;
        Ok(GradientDescent { options })
    }
}

/// Gradient methods cannot start where the objective is not finite.
pub(crate) fn require_finite_start(c: &Candidate, method: &str) -> Result<()> {
    if c.f.is_finite() {
        Ok(())
    } else {
        Err(Error::InvalidSetting {
            field: "x0".into(),
            reason: format!("{method} needs a finite objective at the (projected) start point {:?}", c.x),
        })
    }
}

/// Outcome of a projected line search.
pub(crate) enum LineSearch {
    /// Sufficient decrease at step `alpha`.
    Accepted(Candidate, f64),
    /// The projected path does not move even at the first step: `u` is stationary for the
    /// constrained problem along this direction.
    Stationary,
    /// No decrease found.
    Failed,
}

/// Backtracking search along `u(α) = P(u + α·d)`, halving `α` until the Armijo condition
/// holds.
pub(crate) fn projected_line_search(
    run: &mut Run,
    current: &Candidate,
    gradient: &[f64],
    direction: &[f64],
    mut alpha: f64,
) -> Result<LineSearch> {
    for trial_index in 0..MAX_BACKTRACKS {
        let trial: Vec<f64> = current.u.iter().zip(direction).map(|(u, d)| u + alpha * d).collect();
        let c = run.evaluate(&trial)?;
        let decrease: f64 = gradient.iter().zip(c.u.iter().zip(&current.u)).map(|(g, (a, b))| g * (a - b)).sum();
        if decrease < 0.0 && c.f <= current.f + ARMIJO * decrease {
            return Ok(LineSearch::Accepted(c, alpha));
        }
        if max_abs_diff(&c.u, &current.u) == 0.0 {
            return Ok(if trial_index == 0 { LineSearch::Stationary } else { LineSearch::Failed });
        }
        alpha *= 0.5;
    }
    Ok(LineSearch::Failed)
}

impl Optimiser for GradientDescent {
    fn name(&self) -> &str {
        "gradient-descent"
    }

    fn minimise(&mut self, problem: &Problem, x0: &[f64], observer: &mut dyn Observer) -> Result<OptimResult> {
        let (mut run, mut current) = Run::start(problem, &self.options, observer, x0)?;
        require_finite_start(&current, "gradient descent")?;
        let mut g = run.gradient(&current)?;
        let g_max = g.iter().fold(0.0f64, |m, v| m.max(v.abs()));
        let mut alpha = if g_max > 0.0 { self.options.sigma0 / g_max } else { 1.0 };
        loop {
            let direction: Vec<f64> = g.iter().map(|v| -v).collect();
            let (next, used) = match projected_line_search(&mut run, &current, &g, &direction, alpha)? {
                LineSearch::Accepted(c, used) => (c, used),
                LineSearch::Stationary => {
                    run.end_iteration(true);
                    return Ok(run.finish(StopReason::Tolerance));
                }
                LineSearch::Failed => {
                    run.end_iteration(false);
                    return Ok(run.finish(StopReason::LineSearchFailed));
                }
            };
            alpha = if used == alpha { 2.0 * used } else { used };
            let converged = max_abs_diff(&next.u, &current.u) <= self.options.x_tolerance
                && (current.f - next.f).abs() <= self.options.f_tolerance;
            current = next;
            g = run.gradient(&current)?;
            if let Some(stop) = run.end_iteration(converged) {
                return Ok(run.finish(stop));
            }
        }
    }
}
