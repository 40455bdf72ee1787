//! Machinery shared by the gradient samplers (MALA, HMC, NUTS): phase-space points, the
//! leapfrog integrator with a diagonal mass matrix, the initial step-size heuristic, and the
//! warmup driver (dual-averaging step size, windowed mass matrix).

use rand::rngs::StdRng;
use rand::{Rng, SeedableRng};
use rand_distr::StandardNormal;

use super::run::Recorder;
use super::target::Counted;
use super::warmup::{DualAveraging, Welford, metric_windows};
use super::{Chain, LogDensity, Progress, SamplerOptions, Schedule};
use crate::error::Result;

/// Energy error above which a trajectory counts as divergent (as Stan).
pub(super) const MAX_ENERGY_ERROR: f64 = 1000.0;

/// A position with its log density and gradient.
#[derive(Clone, Debug)]
pub(super) struct Point {
    pub x: Vec<f64>,
    pub log_p: f64,
    pub grad: Vec<f64>,
}

impl Point {
    pub fn at(counted: &Counted, x: Vec<f64>) -> Result<Self> {
        let (log_p, grad) = counted.value_and_gradient(&x)?;
        let log_p = if grad.iter().all(|g| g.is_finite()) { log_p } else { f64::NEG_INFINITY };
        Ok(Point { x, log_p, grad })
    }
}

/// Diagonal inverse mass matrix `M⁻¹` (the posterior variances once adapted).
pub(super) type InvMass = [f64];

/// Kinetic energy `½·pᵀM⁻¹p`.
pub(super) fn kinetic(p: &[f64], inv_mass: &InvMass) -> f64 {
    0.5 * p.iter().zip(inv_mass).map(|(pi, m)| pi * pi * m).sum::<f64>()
}

/// Momentum `p ~ N(0, M)`.
pub(super) fn momentum(rng: &mut StdRng, inv_mass: &InvMass) -> Vec<f64> {
    inv_mass.iter().map(|m| rng.sample::<f64, _>(StandardNormal) / m.sqrt()).collect()
}

/// Velocity `M⁻¹p`.
pub(super) fn velocity(p: &[f64], inv_mass: &InvMass) -> Vec<f64> {
    p.iter().zip(inv_mass).map(|(pi, m)| pi * m).collect()
}

/// One leapfrog step of size `eps` (negative to integrate backwards) from `(q, p)`.
pub(super) fn leapfrog(counted: &Counted, q: &Point, p: &[f64], eps: f64, inv_mass: &InvMass) -> Result<(Point, Vec<f64>)> {
    let half: Vec<f64> = p.iter().zip(&q.grad).map(|(pi, g)| pi + 0.5 * eps * g).collect();
    let x: Vec<f64> = q.x.iter().zip(&half).zip(inv_mass).map(|((xi, pi), m)| xi + eps * m * pi).collect();
    let next = Point::at(counted, x)?;
    let p_new = half.iter().zip(&next.grad).map(|(pi, g)| pi + 0.5 * eps * g).collect();
    Ok((next, p_new))
}

/// Log joint density `log p(q) - K(p)` (minus the Hamiltonian); `-inf` for NaN.
pub(super) fn joint(q: &Point, p: &[f64], inv_mass: &InvMass) -> f64 {
    let h = q.log_p - kinetic(p, inv_mass);
    if h.is_nan() { f64::NEG_INFINITY } else { h }
}

/// Initial step size by Hoffman & Gelman (2014, Algorithm 4): from `eps`, double or halve
/// until the one-step acceptance ratio crosses 1/2.
fn reasonable_step(counted: &Counted, rng: &mut StdRng, q: &Point, inv_mass: &InvMass, mut eps: f64) -> Result<f64> {
    let p = momentum(rng, inv_mass);
    let h0 = joint(q, &p, inv_mass);
    let log_ratio = |eps: f64| -> Result<f64> {
        let (q1, p1) = leapfrog(counted, q, &p, eps, inv_mass)?;
        Ok(joint(&q1, &p1, inv_mass) - h0)
    };
    let mut r = log_ratio(eps)?;
    let direction = if r > 0.5f64.ln() { 1.0 } else { -1.0 };
    for _ in 0..60 {
        if direction * r <= -direction * 2f64.ln() {
            break;
        }
        eps *= 2f64.powf(direction);
        r = log_ratio(eps)?;
    }
    Ok(eps)
}

/// Outcome of one transition of a gradient sampler.
pub(super) struct Step {
    pub point: Point,
    /// Acceptance statistic fed to dual averaging and recorded as the acceptance rate.
    pub accept_stat: f64,
    pub divergent: bool,
}

/// A gradient-based Markov transition with a step size and a diagonal mass matrix.
pub(super) trait Dynamics: Sync {
    /// Acceptance statistic that step-size adaptation aims at by default.
    fn default_acceptance(&self) -> f64;
    fn transition(&self, counted: &Counted, rng: &mut StdRng, current: &Point, eps: f64, inv_mass: &InvMass) -> Result<Step>;
}

/// Runs one chain of `dynamics`. With `options.adapt`, warmup adapts the step size by dual
/// averaging (restarted after each mass-matrix update) and, with `adapt_mass_matrix`, a
/// diagonal inverse mass matrix from the variances in Stan's windows; after warmup the step
/// size is the dual-averaging average `ε̄` and both stay fixed.
pub(super) fn run_dynamics(
    dynamics: &dyn Dynamics,
    options: &SamplerOptions,
    target: &dyn LogDensity,
    x0: &[f64],
    seed: u64,
    schedule: Schedule,
    progress: Progress,
) -> Result<Chain> {
    let counted = Counted::new(target);
    let mut rng = StdRng::seed_from_u64(seed);
    let mut rec = Recorder::new(schedule);
    let n = x0.len();
    let goal = options.acceptance(dynamics.default_acceptance());
    let mut current = Point::at(&counted, x0.to_vec())?;
    let mut inv_mass = vec![1.0; n];
    let mut eps = match options.step_size {
        Some(h) => h,
        None => reasonable_step(&counted, &mut rng, &current, &inv_mass, 1.0)?,
    };
    let mut averaging = DualAveraging::new(eps, goal);
    let windows = if options.adapt && options.adapt_mass_matrix { metric_windows(schedule.warmup) } else { Vec::new() };
    let mut variance = Welford::new(n);
    for it in 0..schedule.total() {
        let step = dynamics.transition(&counted, &mut rng, &current, eps, &inv_mass)?;
        current = step.point;
        if options.adapt && it < schedule.warmup {
            eps = averaging.update(step.accept_stat);
            if windows.iter().any(|&(start, end)| (start..end).contains(&it)) {
                variance.add(&current.x);
            }
            if windows.iter().any(|&(_, end)| end == it + 1) {
                if let Some(v) = variance.regularised_variance() {
                    inv_mass = v;
                    eps = reasonable_step(&counted, &mut rng, &current, &inv_mass, eps)?;
                }
                variance = Welford::new(n);
                averaging = DualAveraging::new(eps, goal);
            }
            if it + 1 == schedule.warmup {
                eps = averaging.final_step();
            }
        }
        rec.record(it, &current.x, current.log_p, step.accept_stat, step.divergent);
        progress();
    }
    Ok(rec.finish(&counted, Some(eps)))
}
