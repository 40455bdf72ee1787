//! Optimisers for design and parameterisation problems.
//!
//! Every optimiser implements [`Optimiser`] and minimises an [`Objective`] over a [`Problem`]:
//! box [`Bounds`], optional [`LinearConstraints`] (equalities and `a·x <= b` inequalities) and
//! per-variable [`Transform`]s. Every candidate is projected onto the feasible set before the
//! objective sees it, so the objective is only ever evaluated at feasible points.
//!
//! Search space. Optimisers work on `u = T(x) / scale`, where `T` is the per-variable transform
//! (identity or natural log) and `scale` is the width of the transformed bound range (or
//! `max(1, |T(x0)|)` for an unbounded variable). `sigma0` and `x_tolerance` in
//! [`OptimOptions`] are therefore fractions of the bound range, in the transformed space.
//!
//! Reproducibility. All random numbers are drawn sequentially from one seeded generator; only
//! the objective evaluations of a population (and of finite-difference probes) run in
//! parallel with rayon, so the same seed gives the same result for any number of threads.
//!
//! ```
//! use cellstudio::optim::{by_name, Bounds, NoObserver, Objective, OptimOptions, Problem};
//!
//! struct Sphere;
//! impl Objective for Sphere {
//!     fn dim(&self) -> usize { 2 }
//!     fn evaluate(&self, x: &[f64]) -> f64 { x.iter().map(|v| v * v).sum() }
//! }
//!
//! let bounds = Bounds::new(vec![-1.0; 2], vec![1.0; 2]).unwrap();
//! let problem = Problem::new(&Sphere, bounds).unwrap();
//! let options = OptimOptions::default().with_seed(3).with_max_evaluations(5_000).unwrap();
//! let mut optimiser = by_name("cmaes", options).unwrap();
//! let result = optimiser.minimise(&problem, &[0.5, -0.7], &mut NoObserver).unwrap();
//! assert!(result.f < 1e-12);
//! ```

mod adamw;
mod cmaes;
mod cuckoo;
mod differential_evolution;
mod gradient_descent;
mod irprop;
mod projected_lbfgs;
mod nelder_mead;
pub mod nsga2;
pub mod problem;
pub mod progress;
pub mod projection;
mod pso;
mod run;
mod snes;
mod xnes;

use rayon::prelude::*;
use serde::{Deserialize, Serialize};

use crate::error::{Error, Result};

pub use adamw::AdamW;
pub use cmaes::CmaEs;
pub use cuckoo::CuckooSearch;
pub use differential_evolution::DifferentialEvolution;
pub use gradient_descent::GradientDescent;
pub use irprop::IRpropMinus;
pub use projected_lbfgs::ProjectedLbfgs;
pub use nelder_mead::NelderMead;
pub use problem::{Bounds, Problem, Transform};
pub use progress::ProgressObserver;
pub use projection::LinearConstraints;
pub use pso::ParticleSwarm;
pub use snes::Snes;
pub use xnes::Xnes;

/// A scalar function to minimise.
///
/// A failed evaluation (solver failure, unphysical state) returns `f64::INFINITY` or a large
/// penalty; `NaN` is treated as `INFINITY`. `Sync` because populations are evaluated in
/// parallel.
pub trait Objective: Sync {
    /// Number of variables.
    fn dim(&self) -> usize;
    /// Objective value at `x` (model space, always feasible when called by an optimiser).
    fn evaluate(&self, x: &[f64]) -> f64;
    /// Analytic gradient at `x`, if available; gradient-based optimisers otherwise use
    /// central finite differences.
    fn gradient(&self, _x: &[f64]) -> Option<Vec<f64>> {
        None
    }
}

/// Why an optimiser stopped. These are outcomes, not errors.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum StopReason {
    /// `max_iterations` reached.
    MaxIterations,
    /// `max_evaluations` reached (checked after each iteration, so a population optimiser
    /// may exceed it by less than one population).
    MaxEvaluations,
    /// Converged: the spread (or change) of `x` is below `x_tolerance` and that of `f`
    /// below `f_tolerance`.
    Tolerance,
    /// The best value did not improve by more than `f_tolerance` for `patience` iterations.
    NoImprovement,
    /// A gradient method found no step that decreases the objective (typically at the
    /// limit of floating-point resolution near a minimum).
    LineSearchFailed,
    /// The search distribution became numerically degenerate (ill-conditioned covariance).
    Degenerate,
}

/// Result of a minimisation: the best feasible point seen (model space) and statistics.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct OptimResult {
    /// Best point (model space, feasible).
    pub x: Vec<f64>,
    /// Objective at `x`.
    pub f: f64,
    /// Objective evaluations, including finite-difference probes.
    pub evaluations: usize,
    /// Analytic gradient evaluations.
    pub gradient_evaluations: usize,
    /// Completed iterations (generations for population methods).
    pub iterations: usize,
    /// Why the optimiser stopped.
    pub stop: StopReason,
}

/// Watches an optimiser: called once at the end of every iteration. Plots, progress bars and
/// logs implement this; optimisers never depend on them.
pub trait Observer {
    /// `iter` counts from 1; `best_x` is in model space.
    fn iteration(&mut self, iter: usize, best_f: f64, best_x: &[f64], evaluations: usize);
}

/// Observer that does nothing.
#[derive(Clone, Copy, Debug, Default)]
pub struct NoObserver;

impl Observer for NoObserver {
    fn iteration(&mut self, _iter: usize, _best_f: f64, _best_x: &[f64], _evaluations: usize) {}
}

/// One row of a [`TraceObserver`].
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct TraceEntry {
    pub iteration: usize,
    pub best_f: f64,
    pub best_x: Vec<f64>,
    pub evaluations: usize,
}

/// Observer that records the best point after every iteration.
#[derive(Clone, Debug, Default)]
pub struct TraceObserver {
    pub entries: Vec<TraceEntry>,
}

impl Observer for TraceObserver {
    fn iteration(&mut self, iter: usize, best_f: f64, best_x: &[f64], evaluations: usize) {
        self.entries.push(TraceEntry { iteration: iter, best_f, best_x: best_x.to_vec(), evaluations });
    }
}

/// A minimisation method.
pub trait Optimiser {
    /// Canonical name, as accepted by [`by_name`].
    fn name(&self) -> &str;
    /// Minimise `problem` from `x0` (model space; projected onto the feasible set first).
    fn minimise(&mut self, problem: &Problem, x0: &[f64], observer: &mut dyn Observer) -> Result<OptimResult>;
}

/// Stopping and start-up settings shared by all optimisers.
///
/// Deserialises from a study file with defaults for missing keys; unknown keys are rejected.
/// Setters validate and return `Result`.
///
/// ```
/// use cellstudio::optim::OptimOptions;
///
/// let options: OptimOptions = toml::from_str("seed = 7\nsigma0 = 0.1\npatience = 50").unwrap();
/// options.validate().unwrap();
/// assert_eq!(options.seed, 7);
/// assert_eq!(options.max_iterations, OptimOptions::default().max_iterations);
/// assert!(toml::from_str::<OptimOptions>("sigma = 0.1").is_err());
///
/// let err = OptimOptions::default().with_sigma0(-1.0).unwrap_err();
/// assert_eq!(err.to_string(), "invalid setting `sigma0`: must be positive and finite, got -1");
/// ```
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct OptimOptions {
    /// Maximum number of iterations (generations for population methods).
    pub max_iterations: usize,
    /// Maximum number of objective evaluations (checked after each iteration).
    pub max_evaluations: usize,
    /// Absolute tolerance on `f`: convergence needs the spread/change of `f` below it, and an
    /// improvement must exceed it to reset `patience`.
    pub f_tolerance: f64,
    /// Tolerance on `x` as a fraction of the bound range (transformed space).
    pub x_tolerance: f64,
    /// Stop after this many consecutive iterations without improvement of the best value.
    pub patience: usize,
    /// Seed of the random number generator.
    pub seed: u64,
    /// Population size; `None` picks each method's default.
    pub population_size: Option<usize>,
    /// Initial step (or spread of the initial population) as a fraction of the bound range.
    pub sigma0: f64,
}

impl Default for OptimOptions {
    fn default() -> Self {
        OptimOptions {
            max_iterations: 1000,
            max_evaluations: 100_000,
            f_tolerance: 1e-10,
            x_tolerance: 1e-8,
            patience: 200,
            seed: 0,
            population_size: None,
            sigma0: 0.2,
        }
    }
}

fn setting(field: &str, reason: String) -> Error {
    Error::InvalidSetting { field: field.to_string(), reason }
}

impl OptimOptions {
    /// Checks every field; called by each optimiser's constructor.
    pub fn validate(&self) -> Result<()> {
        if self.max_iterations == 0 {
            return Err(setting("max_iterations", "must be at least 1".into()));
        }
        if self.max_evaluations == 0 {
            return Err(setting("max_evaluations", "must be at least 1".into()));
        }
        if !(self.f_tolerance >= 0.0 && self.f_tolerance.is_finite()) {
            return Err(setting("f_tolerance", format!("must be non-negative and finite, got {}", self.f_tolerance)));
        }
        if !(self.x_tolerance >= 0.0 && self.x_tolerance.is_finite()) {
            return Err(setting("x_tolerance", format!("must be non-negative and finite, got {}", self.x_tolerance)));
        }
        if self.patience == 0 {
            return Err(setting("patience", "must be at least 1".into()));
        }
        if let Some(n) = self.population_size
            && n < 2
        {
            return Err(setting("population_size", format!("must be at least 2, got {n}")));
        }
        if !(self.sigma0 > 0.0 && self.sigma0.is_finite()) {
            return Err(setting("sigma0", format!("must be positive and finite, got {}", self.sigma0)));
        }
        Ok(())
    }

    /// Sets `max_iterations` (>= 1).
    pub fn with_max_iterations(mut self, n: usize) -> Result<Self> {
        self.max_iterations = n;
        self.validate().map(|_| self)
    }
    /// Sets `max_evaluations` (>= 1).
    pub fn with_max_evaluations(mut self, n: usize) -> Result<Self> {
        self.max_evaluations = n;
        self.validate().map(|_| self)
    }
    /// Sets `f_tolerance` (>= 0).
    pub fn with_f_tolerance(mut self, tol: f64) -> Result<Self> {
        self.f_tolerance = tol;
        self.validate().map(|_| self)
    }
    /// Sets `x_tolerance` (>= 0, fraction of the bound range).
    pub fn with_x_tolerance(mut self, tol: f64) -> Result<Self> {
        self.x_tolerance = tol;
        self.validate().map(|_| self)
    }
    /// Sets `patience` (>= 1 iterations).
    pub fn with_patience(mut self, n: usize) -> Result<Self> {
        self.patience = n;
        self.validate().map(|_| self)
    }
    /// Sets the seed (any value).
    pub fn with_seed(mut self, seed: u64) -> Self {
        self.seed = seed;
        self
    }
    /// Sets the population size (>= 2; some methods need more and say so).
    pub fn with_population_size(mut self, n: usize) -> Result<Self> {
        self.population_size = Some(n);
        self.validate().map(|_| self)
    }
    /// Sets `sigma0` (> 0, fraction of the bound range).
    pub fn with_sigma0(mut self, sigma0: f64) -> Result<Self> {
        self.sigma0 = sigma0;
        self.validate().map(|_| self)
    }

    /// Population size: the configured one, or `default`, checked against `minimum`.
    pub(crate) fn population(&self, default: usize, minimum: usize, method: &str) -> Result<usize> {
        let n = self.population_size.unwrap_or(default);
        if n < minimum {
            return Err(setting("population_size", format!("{method} needs at least {minimum}, got {n}")));
        }
        Ok(n)
    }
}

/// Canonical optimiser names accepted by [`by_name`].
pub const OPTIMISER_NAMES: [&str; 11] = [
    "nelder-mead",
    "cmaes",
    "xnes",
    "snes",
    "differential-evolution",
    "pso",
    "cuckoo",
    "gradient-descent",
    "adamw",
    "irprop-",
    "lbfgsb",
];

/// Builds an optimiser from its name (case-insensitive; `_` and `-` are interchangeable;
/// aliases: `nm`, `cma-es`, `de`, `particle-swarm`, `cuckoo-search`, `gd`, `adam`,
/// `irprop`, `l-bfgs-b`, `lbfgs`).
///
/// ```
/// let err = cellstudio::optim::by_name("simplex", Default::default()).err().unwrap();
/// assert!(err.to_string().contains("nelder-mead, cmaes, xnes"));
/// ```
pub fn by_name(name: &str, options: OptimOptions) -> Result<Box<dyn Optimiser>> {
    let key = name.trim().to_ascii_lowercase().replace('_', "-");
    Ok(match key.as_str() {
        "nelder-mead" | "neldermead" | "nm" => Box::new(NelderMead::new(options)?),
        "cmaes" | "cma-es" | "cma" => Box::new(CmaEs::new(options)?),
        "xnes" => Box::new(Xnes::new(options)?),
        "snes" => Box::new(Snes::new(options)?),
        "differential-evolution" | "de" => Box::new(DifferentialEvolution::new(options)?),
        "pso" | "particle-swarm" => Box::new(ParticleSwarm::new(options)?),
        "cuckoo" | "cuckoo-search" => Box::new(CuckooSearch::new(options)?),
        "gradient-descent" | "gd" => Box::new(GradientDescent::new(options)?),
        "adamw" | "adam" => Box::new(AdamW::new(options)?),
        "irprop-" | "irprop" | "irprop-minus" => Box::new(IRpropMinus::new(options)?),
        "lbfgsb" | "l-bfgs-b" | "lbfgs" | "l-bfgs" => Box::new(ProjectedLbfgs::new(options)?),
        _ => {
            return Err(setting(
                "optimiser",
                format!("unknown optimiser `{name}`; valid names: {}", OPTIMISER_NAMES.join(", ")),
            ));
        }
    })
}

/// Central finite-difference gradient of `f` at `x` with per-coordinate steps `h`.
///
/// With `bounds`, probes never leave the box: near a bound the step is shortened, and at a
/// bound the difference becomes one-sided. The `2·dim` (+1 when one-sided) evaluations run in
/// parallel.
///
/// ```
/// use cellstudio::optim::central_difference;
/// let g = central_difference(&|x: &[f64]| x[0] * x[0] + 3.0 * x[1], &[1.0, 2.0], &[1e-5, 1e-5], None);
/// assert!((g[0] - 2.0).abs() < 1e-8 && (g[1] - 3.0).abs() < 1e-8);
/// ```
pub fn central_difference(
    f: &(dyn Fn(&[f64]) -> f64 + Sync),
    x: &[f64],
    h: &[f64],
    bounds: Option<&Bounds>,
) -> Vec<f64> {
    match bounds {
        Some(b) => difference_probes(f, x, h, b.lower(), b.upper()).0,
        None => {
            let inf = vec![f64::INFINITY; x.len()];
            let ninf = vec![f64::NEG_INFINITY; x.len()];
            difference_probes(f, x, h, &ninf, &inf).0
        }
    }
}

/// Gradient of `objective` at `x`: the analytic one if provided, else central differences with
/// steps `cbrt(eps)·max(|x_i|, 1)`.
pub fn finite_difference_gradient(objective: &dyn Objective, x: &[f64]) -> Vec<f64> {
    if let Some(g) = objective.gradient(x) {
        return g;
    }
    let h: Vec<f64> = x.iter().map(|v| f64::EPSILON.cbrt() * v.abs().max(1.0)).collect();
    central_difference(&|p: &[f64]| objective.evaluate(p), x, &h, None)
}

/// Central differences within `[lower, upper]`; returns the gradient and the number of
/// evaluations used.
pub(crate) fn difference_probes(
    f: &(dyn Fn(&[f64]) -> f64 + Sync),
    x: &[f64],
    h: &[f64],
    lower: &[f64],
    upper: &[f64],
) -> (Vec<f64>, usize) {
    let n = x.len();
    let mut plus = Vec::with_capacity(n);
    let mut minus = Vec::with_capacity(n);
    for i in 0..n {
        plus.push((x[i] + h[i]).min(upper[i]).max(x[i]));
        minus.push((x[i] - h[i]).max(lower[i]).min(x[i]));
    }
    let need_centre = (0..n).any(|i| plus[i] == x[i] || minus[i] == x[i]);
    // Probe list: (coordinate, value); the centre (if needed) is evaluated once.
    let mut probes: Vec<(usize, f64)> = Vec::with_capacity(2 * n);
    for i in 0..n {
        if plus[i] != x[i] {
            probes.push((i, plus[i]));
        }
        if minus[i] != x[i] {
            probes.push((i, minus[i]));
        }
    }
    let values: Vec<f64> = probes
        .par_iter()
        .map(|&(i, v)| {
            let mut p = x.to_vec();
            p[i] = v;
            sanitise(f(&p))
        })
        .collect();
    let centre = if need_centre { sanitise(f(x)) } else { f64::NAN };
    let mut f_plus = vec![centre; n];
    let mut f_minus = vec![centre; n];
    for (&(i, v), &fv) in probes.iter().zip(&values) {
        if v > x[i] {
            f_plus[i] = fv;
        } else {
            f_minus[i] = fv;
        }
    }
    let grad = (0..n)
        .map(|i| {
            let width = plus[i] - minus[i];
            if width > 0.0 { (f_plus[i] - f_minus[i]) / width } else { 0.0 }
        })
        .collect();
    (grad, probes.len() + usize::from(need_centre))
}

/// Objective values as optimisers see them: `NaN` becomes `+inf`.
pub(crate) fn sanitise(f: f64) -> f64 {
    if f.is_nan() { f64::INFINITY } else { f }
}
