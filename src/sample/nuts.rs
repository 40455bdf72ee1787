//! The No-U-Turn Sampler (Hoffman & Gelman 2014, Algorithm 6: slice variable, recursive tree
//! doubling, dual-averaging step size), with a diagonal mass matrix.

use rand::Rng;
use rand::rngs::StdRng;

use super::hamiltonian::{Dynamics, InvMass, MAX_ENERGY_ERROR, Point, Step, joint, leapfrog, momentum, run_dynamics, velocity};
use super::target::Counted;
use super::{Chain, LogDensity, Progress, ChainSampler, SamplerOptions, Schedule};
use crate::error::Result;

/// A trajectory end: position and momentum.
type End = (Point, Vec<f64>);

/// A subtree of the trajectory.
struct Tree {
    minus: End,
    plus: End,
    /// Point sampled uniformly among the subtree's points inside the slice.
    proposal: Point,
    /// Number of points inside the slice `n`.
    n: usize,
    /// `s`: no U-turn and no divergence inside the subtree.
    keep_going: bool,
    /// Sum of the Metropolis acceptance probabilities of the leaves, and their number.
    alpha: f64,
    n_alpha: usize,
    divergent: bool,
}

/// True while the trajectory has not turned back: `(x⁺ - x⁻)·M⁻¹p⁻ >= 0` and
/// `(x⁺ - x⁻)·M⁻¹p⁺ >= 0`.
fn no_u_turn(minus: &End, plus: &End, inv_mass: &InvMass) -> bool {
    let dx: Vec<f64> = plus.0.x.iter().zip(&minus.0.x).map(|(a, b)| a - b).collect();
    let dot = |p: &[f64]| dx.iter().zip(velocity(p, inv_mass)).map(|(d, v)| d * v).sum::<f64>();
    dot(&minus.1) >= 0.0 && dot(&plus.1) >= 0.0
}

/// Settings of one NUTS transition.
struct Context<'c, 'a> {
    counted: &'c Counted<'a>,
    inv_mass: &'c InvMass,
    /// Signed step `v·ε`.
    step: f64,
    /// Log slice level `log u`.
    log_u: f64,
    /// Log joint density of the initial point.
    joint0: f64,
}

impl Context<'_, '_> {
    /// BuildTree of Algorithm 6 from `start` with `2^depth` leapfrog steps.
    fn build(&self, rng: &mut StdRng, start: &End, depth: usize) -> Result<Tree> {
        if depth == 0 {
            let (q, p) = leapfrog(self.counted, &start.0, &start.1, self.step, self.inv_mass)?;
            let h = joint(&q, &p, self.inv_mass);
            let keep_going = self.log_u < h + MAX_ENERGY_ERROR;
            let alpha = if h.is_finite() { (h - self.joint0).min(0.0).exp() } else { 0.0 };
            let end = (q.clone(), p);
            return Ok(Tree {
                minus: end.clone(),
                plus: end,
                proposal: q,
                n: usize::from(self.log_u <= h),
                keep_going,
                alpha,
                n_alpha: 1,
                divergent: !keep_going,
            });
        }
        let mut tree = self.build(rng, start, depth - 1)?;
        if !tree.keep_going {
            return Ok(tree);
        }
        let outer = if self.step < 0.0 { &tree.minus } else { &tree.plus };
        let next = self.build(rng, outer, depth - 1)?;
        if self.step < 0.0 {
            tree.minus = next.minus;
        } else {
            tree.plus = next.plus;
        }
        let total = tree.n + next.n;
        if total > 0 && rng.random::<f64>() < next.n as f64 / total as f64 {
            tree.proposal = next.proposal;
        }
        tree.alpha += next.alpha;
        tree.n_alpha += next.n_alpha;
        tree.divergent |= next.divergent;
        tree.keep_going = next.keep_going && no_u_turn(&tree.minus, &tree.plus, self.inv_mass);
        tree.n = total;
        Ok(tree)
    }
}

struct NoUTurn {
    max_depth: usize,
}

impl Dynamics for NoUTurn {
    fn default_acceptance(&self) -> f64 {
        0.8
    }

    fn transition(&self, counted: &Counted, rng: &mut StdRng, current: &Point, eps: f64, inv_mass: &InvMass) -> Result<Step> {
        let p0 = momentum(rng, inv_mass);
        let joint0 = joint(current, &p0, inv_mass);
        let log_u = joint0 + (1.0 - rng.random::<f64>()).ln();
        let mut minus: End = (current.clone(), p0);
        let mut plus = minus.clone();
        let mut proposal = current.clone();
        let (mut n, mut alpha, mut n_alpha, mut divergent) = (1usize, 0.0, 0usize, false);
        for depth in 0..self.max_depth {
            let forward = rng.random::<bool>();
            let context = Context { counted, inv_mass, step: if forward { eps } else { -eps }, log_u, joint0 };
            let tree = context.build(rng, if forward { &plus } else { &minus }, depth)?;
            if forward {
                plus = tree.plus;
            } else {
                minus = tree.minus;
            }
            alpha += tree.alpha;
            n_alpha += tree.n_alpha;
            divergent |= tree.divergent;
            if tree.keep_going && rng.random::<f64>() < tree.n as f64 / n as f64 {
                proposal = tree.proposal;
            }
            n += tree.n;
            if !(tree.keep_going && no_u_turn(&minus, &plus, inv_mass)) {
                break;
            }
        }
        Ok(Step { point: proposal, accept_stat: alpha / n_alpha.max(1) as f64, divergent })
    }
}

/// No-U-Turn Sampler: trajectories double (forwards or backwards at random) until they make
/// a U-turn, diverge, or reach `2^max_tree_depth - 1` leapfrog steps; the next state is drawn
/// from the points inside the slice (Hoffman & Gelman 2014, Algorithm 6). Step size (dual
/// averaging, target acceptance statistic 0.8) and diagonal mass matrix adapt during warmup.
/// The recorded acceptance rate is the mean acceptance statistic `α/n_α`.
#[derive(Clone, Debug)]
pub struct Nuts {
    options: SamplerOptions,
}

impl Nuts {
    pub fn new(options: SamplerOptions) -> Result<Self> {
        options.validate()?;
        Ok(Nuts { options })
    }
}

impl ChainSampler for Nuts {
    fn name(&self) -> &str {
        "nuts"
    }

    fn run_chain(&self, target: &dyn LogDensity, x0: &[f64], seed: u64, schedule: Schedule, progress: Progress) -> Result<Chain> {
        run_dynamics(&NoUTurn { max_depth: self.options.max_tree_depth }, &self.options, target, x0, seed, schedule, progress)
    }
}
