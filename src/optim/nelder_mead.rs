//! Nelder–Mead simplex search with the dimension-adaptive coefficients of Gao and Han (2012),
//! projected vertices, and restarts after convergence.

use super::run::{Candidate, Run, max_abs_diff};
use super::{Observer, OptimOptions, OptimResult, Optimiser, Problem};
use crate::error::Result;

/// Nelder–Mead simplex. Every trial point is projected onto the feasible set and the simplex
/// keeps the projected points, so it lives in the feasible set. Projection can flatten the
/// simplex onto a face; after convergence the simplex is rebuilt around the best point
/// (`sigma0` steps) and the search continues, until a restart no longer improves the best
/// value by more than `f_tolerance` or `max_restarts` is used up.
///
/// Deterministic: `seed` is not used.
#[derive(Clone, Debug)]
pub struct NelderMead {
    options: OptimOptions,
    max_restarts: usize,
}

impl NelderMead {
    pub fn new(options: OptimOptions) -> Result<Self> {
        options.validate()?;
        Ok(NelderMead { options, max_restarts: 3 })
    }

    /// Maximum number of restarts after convergence (default 3; 0 disables them).
    ///
    /// ```
    /// use cellstudio::optim::{NelderMead, OptimOptions};
    /// let nm = NelderMead::new(OptimOptions::default()).unwrap().with_max_restarts(0);
    /// ```
    pub fn with_max_restarts(mut self, n: usize) -> Self {
        self.max_restarts = n;
        self
    }
}

/// Simplex around `centre`: one vertex per coordinate, `step` away (or `-step` if that leaves
/// the bounds).
fn simplex_around(run: &mut Run, centre: &Candidate, step: f64) -> Result<Vec<Candidate>> {
    let n = run.dim();
    let points: Vec<Vec<f64>> = (0..n)
        .map(|i| {
            let mut p = centre.u.clone();
            p[i] = if p[i] + step <= run.space.upper[i] { p[i] + step } else { p[i] - step };
            p
        })
        .collect();
    let mut simplex = vec![centre.clone()];
    simplex.extend(run.evaluate_batch(&points)?);
    Ok(simplex)
}

fn sort(simplex: &mut [Candidate]) {
    simplex.sort_by(|a, b| a.f.total_cmp(&b.f));
}

impl Optimiser for NelderMead {
    fn name(&self) -> &str {
        "nelder-mead"
    }

    fn minimise(&mut self, problem: &Problem, x0: &[f64], observer: &mut dyn Observer) -> Result<OptimResult> {
        let (mut run, c0) = Run::start(problem, &self.options, observer, x0)?;
        let n = run.dim();
        let nf = n as f64;
        // Gao–Han coefficients: reflection, expansion, contraction, shrink.
        let (alpha, beta, gamma, delta) = (1.0, 1.0 + 2.0 / nf, 0.75 - 0.5 / nf, 1.0 - 1.0 / nf);
        let step = self.options.sigma0;
        let mut simplex = simplex_around(&mut run, &c0, step)?;
        let mut restarts = 0;
        let mut restart_f = f64::INFINITY;
        loop {
            sort(&mut simplex);
            let worst = simplex[n].clone();
            let centroid: Vec<f64> = (0..n).map(|i| simplex[..n].iter().map(|c| c.u[i]).sum::<f64>() / nf).collect();
            let along = |t: f64, from: &[f64]| -> Vec<f64> {
                // centroid + t·(centroid - from)
                centroid.iter().zip(from).map(|(c, w)| c + t * (c - w)).collect()
            };
            let reflected = run.evaluate(&along(alpha, &worst.u))?;
            if reflected.f < simplex[0].f {
                let expanded = run.evaluate(&along(-beta, &reflected.u))?;
                simplex[n] = if expanded.f < reflected.f { expanded } else { reflected };
            } else if reflected.f < simplex[n - 1].f {
                simplex[n] = reflected;
            } else {
                let contracted = if reflected.f < worst.f {
                    run.evaluate(&along(-gamma, &reflected.u))?
                } else {
                    run.evaluate(&along(-gamma, &worst.u))?
                };
                if contracted.f < reflected.f.min(worst.f) {
                    simplex[n] = contracted;
                } else {
                    let best = simplex[0].u.clone();
                    let shrunk: Vec<Vec<f64>> = simplex[1..]
                        .iter()
                        .map(|c| best.iter().zip(&c.u).map(|(b, v)| b + delta * (v - b)).collect())
                        .collect();
                    let evaluated = run.evaluate_batch(&shrunk)?;
                    for (slot, c) in simplex[1..].iter_mut().zip(evaluated) {
                        *slot = c;
                    }
                }
            }
            sort(&mut simplex);
            let size = simplex[1..].iter().map(|c| max_abs_diff(&c.u, &simplex[0].u)).fold(0.0, f64::max);
            let mut converged =
                size <= self.options.x_tolerance && simplex[n].f - simplex[0].f <= self.options.f_tolerance;
            if converged && restarts < self.max_restarts && restart_f - simplex[0].f > self.options.f_tolerance {
                restarts += 1;
                restart_f = simplex[0].f;
                let centre = simplex[0].clone();
                simplex = simplex_around(&mut run, &centre, step)?;
                converged = false;
            }
            if let Some(stop) = run.end_iteration(converged) {
                return Ok(run.finish(stop));
            }
        }
    }
}
