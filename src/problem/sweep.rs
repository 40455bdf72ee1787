//! Parameter sweeps: evaluate a design problem over a grid in parallel.

use indicatif::{ParallelProgressIterator, ProgressBar, ProgressStyle};
use rayon::prelude::*;
use serde::Serialize;

use super::design::{DesignMetrics, DesignProblem};

/// One evaluated candidate; `metrics` is `None` when its simulation failed (with the reason).
#[derive(Clone, Debug, Serialize)]
pub struct SweepPoint {
    pub x: Vec<f64>,
    pub metrics: Option<DesignMetrics>,
    pub error: Option<String>,
}

/// A full tensor grid with `points[k]` evenly spaced values in `[lower[k], upper[k]]`,
/// first variable varying slowest.
pub fn grid(lower: &[f64], upper: &[f64], points: &[usize]) -> Vec<Vec<f64>> {
    let mut out = vec![Vec::new()];
    for k in 0..lower.len() {
        let n = points[k];
        let values: Vec<f64> =
            (0..n).map(|i| lower[k] + (upper[k] - lower[k]) * i as f64 / (n - 1) as f64).collect();
        out = out
            .into_iter()
            .flat_map(|prefix| {
                values.iter().map(move |&v| {
                    let mut p = prefix.clone();
                    p.push(v);
                    p
                })
            })
            .collect();
    }
    out
}

/// Evaluates every candidate in parallel, with a progress bar on a terminal. The order of
/// the results is the order of `candidates`, whatever the thread count.
pub fn evaluate_all(problem: &DesignProblem, candidates: &[Vec<f64>]) -> Vec<SweepPoint> {
    let bar = ProgressBar::new(candidates.len() as u64);
    bar.set_style(
        ProgressStyle::with_template("{bar:40} {pos}/{len} designs, {elapsed} elapsed, eta {eta}")
            .unwrap_or_else(|_| ProgressStyle::default_bar()),
    );
    let points = candidates
        .par_iter()
        .progress_with(bar.clone())
        .map(|x| match problem.evaluate(x) {
            Ok(m) => SweepPoint { x: x.clone(), metrics: Some(m), error: None },
            Err(e) => SweepPoint { x: x.clone(), metrics: None, error: Some(e.to_string()) },
        })
        .collect();
    bar.finish_and_clear();
    points
}
