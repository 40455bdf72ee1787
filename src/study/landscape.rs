//! The `[landscape]` section of a fitting study: the cost on a grid over the first two fitted
//! parameters, drawn as a heat map with the optimiser's trace.

use std::path::Path;

use indicatif::ParallelProgressIterator;
use rayon::prelude::*;
use serde::{Deserialize, Serialize};

use crate::cost::CostKind;
use crate::error::Error;
use crate::problem::identification::{FitObjective, FitResult};
use crate::problem::fitting::FittingProblem;
use crate::report::plot::{Overlay, heat_map};

/// A grid of the cost over the first two parameters (log-spaced for log parameters).
#[derive(Clone, Debug, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct Landscape {
    /// Grid points per parameter.
    pub points: usize,
}

/// The cost on a grid over the first two parameters (other parameters at the optimum), drawn
/// as log10(cost - min + 1e-12 scale) with the optimiser's trace.
pub(crate) fn landscape(problem: &FittingProblem, cost: CostKind, result: &FitResult, points: usize, path: &Path) -> Result<(), Error> {
    let objective = FitObjective { problem, cost };
    let axis = |k: usize| -> Vec<f64> {
        let p = &problem.parameters[k];
        (0..points)
            .map(|i| {
                let u = i as f64 / (points - 1) as f64;
                if p.log { (p.lower.ln() + u * (p.upper / p.lower).ln()).exp() } else { p.lower + u * (p.upper - p.lower) }
            })
            .collect()
    };
    let (xs, ys) = (axis(0), axis(1));
    let cells: Vec<(usize, usize)> = (0..points).flat_map(|i| (0..points).map(move |j| (i, j))).collect();
    let bar = crate::progress::bar("landscape", cells.len() as u64, "landscape {bar:30} {pos}/{len} points [{elapsed}, eta {eta}]");
    let values: Vec<f64> = cells
        .par_iter()
        .progress_with(bar.clone())
        .map(|&(i, j)| {
            let mut x = result.x.clone();
            x[0] = xs[i];
            x[1] = ys[j];
            use crate::optim::Objective;
            objective.evaluate(&x)
        })
        .collect();
    bar.finish_and_clear();
    let shown = |k: usize, v: f64| if problem.parameters[k].log { v.log10() } else { v };
    let fmin = values.iter().copied().filter(|v| v.is_finite()).fold(f64::INFINITY, f64::min).min(result.cost);
    let spread = values.iter().copied().filter(|v| v.is_finite()).fold(0.0f64, |m, v| m.max(v - fmin));
    let mut z = vec![vec![f64::NAN; points]; points];
    for (&(i, j), v) in cells.iter().zip(&values) {
        z[i][j] = (v - fmin + 1e-9 * spread.max(1e-300)).log10();
    }
    let label = |k: usize| {
        let p = &problem.parameters[k];
        if p.log { format!("log10 {}", p.path) } else { p.path.clone() }
    };
    let start = problem.initial();
    let trace: Vec<(f64, f64)> = std::iter::once(&start[..])
        .chain(result.trace.iter().map(|e| &e.best_x[..]))
        .map(|x| (shown(0, x[0]), shown(1, x[1])))
        .collect();
    heat_map(
        path,
        &format!("cost landscape: log10({} - min)", cost.name()),
        (&label(0), &label(1)),
        &xs.iter().map(|&v| shown(0, v)).collect::<Vec<_>>(),
        &ys.iter().map(|&v| shown(1, v)).collect::<Vec<_>>(),
        &z,
        &Overlay { marks: &[("optimum".into(), (shown(0, result.x[0]), shown(1, result.x[1])))], trace: &trace, boundaries: &[] },
    )
}
