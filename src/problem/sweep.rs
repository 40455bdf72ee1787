//! Parameter sweeps: evaluate a design problem over a grid in parallel.

use rayon::prelude::*;
use serde::{Deserialize, Serialize};

use super::design::{DesignMetrics, DesignProblem};
use crate::geometry::Geometry;

/// One candidate; `metrics` is `None` when its simulation failed (with the reason) or it
/// was not evaluated (infeasible).
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct SweepPoint {
    pub x: Vec<f64>,
    pub metrics: Option<DesignMetrics>,
    pub error: Option<String>,
    pub status: Status,
}

/// What became of a sweep point.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Status {
    /// Evaluated, a result.
    #[default]
    Valid,
    /// The simulation failed.
    Failed,
    /// Stores practically nothing (see `study::degenerate`).
    Degenerate,
    /// The discharge delivered less than the study's `min_utilisation` of the theoretical
    /// capacity.
    StoppedEarly,
    /// Outside the linear constraints: skipped, not evaluated.
    Infeasible,
    /// Evaluated, but a simulated metric lies outside the study's limits.
    OutsideLimits,
}

impl Status {
    /// Name in CSV files.
    pub fn name(self) -> &'static str {
        match self {
            Status::Valid => "valid",
            Status::Failed => "failed",
            Status::Degenerate => "degenerate",
            Status::StoppedEarly => "stopped_early",
            Status::Infeasible => "infeasible",
            Status::OutsideLimits => "outside_limits",
        }
    }
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

/// A Latin hypercube of `n` samples in the box: each variable's range is cut into `n`
/// equal strata and each stratum is used once, in a seeded random pairing.
pub fn latin_hypercube(lower: &[f64], upper: &[f64], n: usize, seed: u64) -> Vec<Vec<f64>> {
    use rand::seq::SliceRandom;
    use rand::{Rng, SeedableRng};
    let mut rng = rand::rngs::StdRng::seed_from_u64(seed);
    let mut columns: Vec<Vec<f64>> = Vec::with_capacity(lower.len());
    for k in 0..lower.len() {
        let mut strata: Vec<usize> = (0..n).collect();
        strata.shuffle(&mut rng);
        columns.push(
            strata
                .into_iter()
                .map(|s| lower[k] + (upper[k] - lower[k]) * (s as f64 + rng.random::<f64>()) / n as f64)
                .collect(),
        );
    }
    (0..n).map(|i| columns.iter().map(|c| c[i]).collect()).collect()
}

/// Evaluates every candidate in parallel, with a progress bar on a terminal. The order of
/// the results is the order of `candidates`, whatever the thread count.
///
/// Work is split by geometry: candidates are ordered by the geometry they build and cut into
/// runs of one geometry (split further only to keep every thread busy), and each run is
/// evaluated in turn by one builder. So the number of model builds is about the number of
/// distinct geometries plus a few per thread, not a number that grows with interleaving.
pub fn evaluate_all(problem: &DesignProblem, candidates: &[Vec<f64>]) -> Vec<SweepPoint> {
    let bar = crate::progress::bar("sweep", candidates.len() as u64, "{bar:40} {pos}/{len} designs, {elapsed} elapsed, eta {eta}");
    let tasks = geometry_runs(problem, candidates, 4 * rayon::current_num_threads());
    let mut results: Vec<(usize, SweepPoint)> = tasks
        .par_iter()
        .flat_map_iter(|run| {
            let evaluated: Vec<(usize, SweepPoint)> = problem.with_builder(|builder| {
                run.iter()
                    .map(|&k| {
                        let x = &candidates[k];
                        let point = match problem.evaluate_with(builder, x) {
                            Ok(m) => SweepPoint { x: x.clone(), metrics: Some(m), error: None, status: Status::Valid },
                            Err(e) => SweepPoint { x: x.clone(), metrics: None, error: Some(e.to_string()), status: Status::Failed },
                        };
                        bar.inc(1);
                        (k, point)
                    })
                    .collect()
            });
            evaluated
        })
        .collect();
    bar.finish_and_clear();
    results.sort_unstable_by_key(|(k, _)| *k);
    results.into_iter().map(|(_, p)| p).collect()
}

/// Candidate indices grouped into runs that build one geometry, ordered by geometry; runs are
/// cut to at most `ceil(n / min_tasks)` candidates so that there are at least about
/// `min_tasks` of them.
fn geometry_runs(problem: &DesignProblem, candidates: &[Vec<f64>], min_tasks: usize) -> Vec<Vec<usize>> {
    let keys: Vec<Option<Geometry>> = candidates.par_iter().map(|x| problem.geometry(x)).collect();
    let mut order: Vec<usize> = (0..candidates.len()).collect();
    order.sort_by(|&a, &b| keys[a].partial_cmp(&keys[b]).unwrap_or(std::cmp::Ordering::Equal));
    let longest = candidates.len().div_ceil(min_tasks.max(1)).max(1);
    let mut runs: Vec<Vec<usize>> = Vec::new();
    for k in order {
        match runs.last_mut() {
            Some(run) if run.len() < longest && keys[k].is_some() && keys[run[0]] == keys[k] => run.push(k),
            _ => runs.push(vec![k]),
        }
    }
    runs
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn latin_hypercube_fills_every_stratum_once() {
        let n = 17;
        let pts = latin_hypercube(&[0.0, 10.0], &[1.0, 20.0], n, 3);
        for (k, (lo, hi)) in [(0.0, 1.0), (10.0, 20.0)].iter().enumerate() {
            let mut strata: Vec<usize> = pts.iter().map(|p| ((p[k] - lo) / (hi - lo) * n as f64) as usize).collect();
            strata.sort_unstable();
            assert_eq!(strata, (0..n).collect::<Vec<_>>());
        }
        assert_eq!(pts, latin_hypercube(&[0.0, 10.0], &[1.0, 20.0], n, 3));
    }
}
