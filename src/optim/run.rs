//! Machinery shared by the optimisers: the normalised search space, counted (parallel)
//! evaluation of projected candidates, best-point bookkeeping, stopping rules, and helpers
//! for populations.

use rand::rngs::StdRng;
use rand::{Rng, SeedableRng};
use rayon::prelude::*;

use super::{Observer, OptimOptions, OptimResult, Problem, StopReason, difference_probes, sanitise};
use crate::error::{Error, Result};

/// Normalised search space `u = T(x) / scale` of a problem.
pub(crate) struct Space<'r, 'a> {
    pub problem: &'r Problem<'a>,
    /// Search-space width of one normalised unit per variable.
    pub scale: Vec<f64>,
    /// Normalised bounds.
    pub lower: Vec<f64>,
    pub upper: Vec<f64>,
}

/// A feasible, evaluated point: normalised search coordinates, model coordinates, value.
#[derive(Clone, Debug)]
pub(crate) struct Candidate {
    pub u: Vec<f64>,
    pub x: Vec<f64>,
    pub f: f64,
}

impl Space<'_, '_> {
    pub fn dim(&self) -> usize {
        self.scale.len()
    }

    pub fn to_model(&self, u: &[f64]) -> Vec<f64> {
        let t = self.problem.transforms();
        u.iter().enumerate().map(|(i, &v)| t[i].to_model(v * self.scale[i])).collect()
    }

    pub fn normalise(&self, x: &[f64]) -> Vec<f64> {
        let t = self.problem.transforms();
        x.iter().enumerate().map(|(i, &v)| t[i].to_search(v) / self.scale[i]).collect()
    }

    /// Projects `u` onto the feasible set (in model space), without evaluating.
    pub fn project(&self, u: &[f64]) -> Result<Vec<f64>> {
        Ok(self.normalise(&self.problem.project(&self.to_model(u))?))
    }

    /// Projects `u` onto the feasible set (in model space) and evaluates the objective there.
    pub fn evaluate(&self, u: &[f64]) -> Result<Candidate> {
        let x = self.problem.project(&self.to_model(u))?;
        let f = sanitise(self.problem.objective().evaluate(&x));
        Ok(Candidate { u: self.normalise(&x), x, f })
    }
}

/// One minimisation in progress.
pub(crate) struct Run<'r, 'a> {
    pub space: Space<'r, 'a>,
    pub options: &'r OptimOptions,
    observer: &'r mut dyn Observer,
    pub evaluations: usize,
    pub gradient_evaluations: usize,
    pub iterations: usize,
    best: Option<Candidate>,
    /// Best value when `patience` was last reset.
    mark: f64,
    stale: usize,
}

impl<'r, 'a> Run<'r, 'a> {
    /// Validates `x0`, builds the normalised space and evaluates the projected start point.
    pub fn start(
        problem: &'r Problem<'a>,
        options: &'r OptimOptions,
        observer: &'r mut dyn Observer,
        x0: &[f64],
    ) -> Result<(Self, Candidate)> {
        options.validate()?;
        let n = problem.dim();
        if n == 0 {
            return Err(Error::InvalidSetting { field: "x0".into(), reason: "the problem has no variables".into() });
        }
        if x0.len() != n {
            return Err(Error::InvalidSetting {
                field: "x0".into(),
                reason: format!("start point has {} entries for {n} variables", x0.len()),
            });
        }
        if x0.iter().any(|v| !v.is_finite()) {
            return Err(Error::InvalidSetting {
                field: "x0".into(),
                reason: format!("start point {x0:?} is not finite"),
            });
        }
        let x0 = problem.project(x0)?;
        let sb = problem.search_bounds();
        let t = problem.transforms();
        let scale: Vec<f64> = (0..n)
            .map(|i| {
                let r = sb.range(i);
                if r.is_finite() && r > 0.0 { r } else { t[i].to_search(x0[i]).abs().max(1.0) }
            })
            .collect();
        let lower = (0..n).map(|i| sb.lower()[i] / scale[i]).collect();
        let upper = (0..n).map(|i| sb.upper()[i] / scale[i]).collect();
        let space = Space { problem, scale, lower, upper };
        let mut run = Run {
            space,
            options,
            observer,
            evaluations: 0,
            gradient_evaluations: 0,
            iterations: 0,
            best: None,
            mark: f64::INFINITY,
            stale: 0,
        };
        let u0 = run.space.normalise(&x0);
        let c0 = run.evaluate(&u0)?;
        Ok((run, c0))
    }

    pub fn rng(&self) -> StdRng {
        StdRng::seed_from_u64(self.options.seed)
    }

    pub fn dim(&self) -> usize {
        self.space.dim()
    }

    fn consider(&mut self, c: &Candidate) {
        if self.best.as_ref().is_none_or(|b| c.f < b.f) {
            self.best = Some(c.clone());
        }
    }

    pub fn best(&self) -> &Candidate {
        self.best.as_ref().expect("the start point is evaluated first")
    }

    /// Projects and evaluates one point.
    pub fn evaluate(&mut self, u: &[f64]) -> Result<Candidate> {
        let c = self.space.evaluate(u)?;
        self.evaluations += 1;
        self.consider(&c);
        Ok(c)
    }

    /// Projects and evaluates a batch in parallel; results in input order, so the outcome
    /// does not depend on the number of threads.
    pub fn evaluate_batch(&mut self, us: &[Vec<f64>]) -> Result<Vec<Candidate>> {
        let space = &self.space;
        let out: Vec<Candidate> = us.par_iter().map(|u| space.evaluate(u)).collect::<Result<_>>()?;
        self.evaluations += out.len();
        for c in &out {
            self.consider(c);
        }
        Ok(out)
    }

    /// Gradient with respect to the normalised search coordinates at the feasible point `c`:
    /// the analytic model-space gradient through the chain rule, else central differences in
    /// the normalised space (probes stay inside the bounds but may leave the linear
    /// constraints' set by one step).
    pub fn gradient(&mut self, c: &Candidate) -> Result<Vec<f64>> {
        let n = self.dim();
        let problem = self.space.problem;
        if let Some(gx) = problem.objective().gradient(&c.x) {
            if gx.len() != n {
                return Err(Error::InvalidSetting {
                    field: "gradient".into(),
                    reason: format!("objective gradient has {} entries for {n} variables", gx.len()),
                });
            }
            self.gradient_evaluations += 1;
            let t = problem.transforms();
            return Ok((0..n).map(|i| sanitise_grad(gx[i] * t[i].derivative(c.x[i]) * self.space.scale[i])).collect());
        }
        let h: Vec<f64> = c.u.iter().map(|v| f64::EPSILON.cbrt() * v.abs().max(1.0)).collect();
        let space = &self.space;
        let f = |u: &[f64]| problem.objective().evaluate(&problem.bounds().clamp(&space.to_model(u)));
        let (g, used) = difference_probes(&f, &c.u, &h, &space.lower, &space.upper);
        self.evaluations += used;
        Ok(g.into_iter().map(sanitise_grad).collect())
    }

    /// Ends an iteration: notifies the observer and applies the stopping rules. `converged` is
    /// the optimiser's own tolerance test.
    pub fn end_iteration(&mut self, converged: bool) -> Option<StopReason> {
        self.iterations += 1;
        let best = self.best.as_ref().expect("the start point is evaluated first");
        let (f, evaluations) = (best.f, self.evaluations);
        self.observer.iteration(self.iterations, f, &best.x, evaluations);
        if f < self.mark - self.options.f_tolerance || (self.mark.is_infinite() && f < self.mark) {
            self.mark = f;
            self.stale = 0;
        } else {
            self.stale += 1;
        }
        if converged {
            Some(StopReason::Tolerance)
        } else if self.evaluations >= self.options.max_evaluations {
            Some(StopReason::MaxEvaluations)
        } else if self.iterations >= self.options.max_iterations {
            Some(StopReason::MaxIterations)
        } else if self.stale >= self.options.patience {
            Some(StopReason::NoImprovement)
        } else {
            None
        }
    }

    pub fn finish(self, stop: StopReason) -> OptimResult {
        let best = self.best.expect("the start point is evaluated first");
        OptimResult {
            x: best.x,
            f: best.f,
            evaluations: self.evaluations,
            gradient_evaluations: self.gradient_evaluations,
            iterations: self.iterations,
            stop,
        }
    }

    /// Initial population: `u0` itself, then points drawn uniformly from the box
    /// `u0 ± 2·sigma0` intersected with the bounds (random numbers drawn in order).
    pub fn initial_population(&self, rng: &mut StdRng, u0: &[f64], size: usize) -> Vec<Vec<f64>> {
        let s = 2.0 * self.options.sigma0;
        let mut pop = vec![u0.to_vec()];
        while pop.len() < size {
            let p = (0..self.dim())
                .map(|i| {
                    let lo = (u0[i] - s).max(self.space.lower[i]);
                    let hi = (u0[i] + s).min(self.space.upper[i]);
                    if hi > lo { rng.random_range(lo..=hi) } else { lo }
                })
                .collect();
            pop.push(p);
        }
        pop
    }
}

fn sanitise_grad(g: f64) -> f64 {
    if g.is_finite() { g } else { 0.0 }
}

/// Standard normal sample.
pub(crate) fn normal(rng: &mut StdRng) -> f64 {
    rng.sample(rand_distr::StandardNormal)
}

/// Largest `|a_i - b_i|`.
pub(crate) fn max_abs_diff(a: &[f64], b: &[f64]) -> f64 {
    a.iter().zip(b).map(|(a, b)| (a - b).abs()).fold(0.0, f64::max)
}

pub(crate) fn squared_distance(a: &[f64], b: &[f64]) -> f64 {
    a.iter().zip(b).map(|(a, b)| (a - b) * (a - b)).sum()
}

/// Population convergence: every member within `x_tolerance` of the best (max-norm in
/// normalised units) and the values within `f_tolerance` of each other.
pub(crate) fn population_converged(us: &[&[f64]], fs: &[f64], best: &[f64], options: &OptimOptions) -> bool {
    let spread_x = us.iter().map(|u| max_abs_diff(u, best)).fold(0.0, f64::max);
    let lo = fs.iter().copied().fold(f64::INFINITY, f64::min);
    let hi = fs.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    spread_x <= options.x_tolerance && hi - lo <= options.f_tolerance
}

/// Ranking of raw samples `z_k` of a search distribution whose projections `P(z_k)` were
/// evaluated: by `f(P(z_k)) + w·||z_k - P(z_k)||²`, with `w` scaled so that a typical
/// infeasible distance (`step²` per coordinate) costs about the interquartile range of the
/// values. This pulls the distribution back into the feasible set (Hansen's boundary
/// penalty, adapted per generation); without constraints it is the plain ranking.
/// Returns the indices best first (stable, so ties keep sample order).
pub(crate) fn penalised_ranking(raw: &[Vec<f64>], evaluated: &[Candidate], step2: f64) -> Vec<usize> {
    let n = raw.first().map_or(1, Vec::len).max(1);
    let d2: Vec<f64> = raw.iter().zip(evaluated).map(|(z, c)| squared_distance(z, &c.u)).collect();
    let mut finite: Vec<f64> = evaluated.iter().map(|c| c.f).filter(|f| f.is_finite()).collect();
    finite.sort_by(f64::total_cmp);
    let iqr = if finite.len() >= 2 {
        let q = |p: f64| finite[((finite.len() - 1) as f64 * p).round() as usize];
        q(0.75) - q(0.25)
    } else {
        0.0
    };
    let w = if d2.iter().any(|&d| d > 0.0) { iqr.max(1e-300) / (step2 * n as f64).max(1e-300) } else { 0.0 };
    let key: Vec<f64> = evaluated.iter().zip(&d2).map(|(c, d)| c.f + w * d).collect();
    let mut order: Vec<usize> = (0..raw.len()).collect();
    order.sort_by(|&a, &b| key[a].total_cmp(&key[b]));
    order
}

/// Whether the best values of the last `window` generations (and the current spread) are
/// within `f_tolerance`: the "TolFun" test of the distribution methods.
pub(crate) fn history_flat(history: &[f64], window: usize, current: &[f64], options: &OptimOptions) -> bool {
    if history.len() < window {
        return false;
    }
    let recent = &history[history.len() - window..];
    let all = recent.iter().chain(current.iter()).copied().filter(|f| f.is_finite());
    let (lo, hi) = all.fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), f| (lo.min(f), hi.max(f)));
    hi - lo <= options.f_tolerance
}

/// Rank-based utilities of the natural evolution strategies (sum zero), best first.
pub(crate) fn nes_utilities(lambda: usize) -> Vec<f64> {
    let raw: Vec<f64> = (1..=lambda).map(|k| ((lambda as f64 / 2.0 + 1.0).ln() - (k as f64).ln()).max(0.0)).collect();
    let total: f64 = raw.iter().sum();
    raw.iter().map(|r| r / total - 1.0 / lambda as f64).collect()
}

/// Projected gradient `r = (u - P(u - κ·g)) / κ` with `κ = step / ||g||∞`: equal to `g` in
/// directions free of active constraints, with the components blocked by active bounds or
/// removed by equality constraints taken out; zero exactly at a constrained stationary point.
/// `step` (normalised units) keeps the probe displacement well above rounding; components
/// below `1e-8·||g||∞` (the projection's accuracy) are set to zero.
pub(crate) fn projected_gradient(run: &Run, c: &Candidate, g: &[f64], step: f64) -> Result<Vec<f64>> {
    let g_max = g.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    if g_max == 0.0 {
        return Ok(vec![0.0; g.len()]);
    }
    if run.space.problem.constraints().is_none() {
        // Box only: the exact per-coordinate rule, free of rounding.
        return Ok((0..g.len())
            .map(|i| {
                let blocked =
                    (c.u[i] <= run.space.lower[i] && g[i] > 0.0) || (c.u[i] >= run.space.upper[i] && g[i] < 0.0);
                if blocked { 0.0 } else { g[i] }
            })
            .collect());
    }
    let kappa = step / g_max;
    let stepped: Vec<f64> = c.u.iter().zip(g).map(|(u, g)| u - kappa * g).collect();
    let projected = run.space.project(&stepped)?;
    // Components at the level of the QP's accuracy are noise: zero them, so that sign-based
    // and normalised methods (iRprop⁻, Adam) rest at a constrained minimum.
    let noise = 1e-8 * g_max;
    Ok(c.u
        .iter()
        .zip(&projected)
        .map(|(u, p)| (u - p) / kappa)
        .map(|r| if r.abs() <= noise { 0.0 } else { r })
        .collect())
}
