//! Global sensitivity of a fitting problem: Sobol' indices of the simulated voltage (at every
//! recorded point, weighted as the cost weighs it) to each fitted parameter over its whole
//! search box (log-uniform for parameters searched on a log scale). The Fisher statements of
//! [`super::verdict`] are local to the optimum; these say whether the recording responds to a
//! parameter anywhere in the box, and how much of that response it shares with the others.

use serde::Serialize;

use super::fitting::FittingProblem;
use crate::error::Error;
use crate::stats::sobol::{SobolIndices, SobolSettings, sobol_indices};

/// A total index below this share of the output variance (-) reads as "no influence in the
/// box": a conventional round number, stated, not tuned.
pub const NEGLIGIBLE_TOTAL: f64 = 0.01;

/// Sobol' indices of every fitted parameter, with a verdict each.
#[derive(Clone, Debug, Serialize)]
pub struct GlobalSensitivity {
    pub names: Vec<String>,
    pub indices: SobolIndices,
    pub verdicts: Vec<String>,
}

/// The parameter vector (parameter units) at the point `u` of the unit cube.
fn to_parameters(problem: &FittingProblem, u: &[f64]) -> Vec<f64> {
    problem
        .parameters
        .iter()
        .zip(u)
        .map(|(p, u)| if p.log { (p.lower.ln() + u * (p.upper.ln() - p.lower.ln())).exp() } else { p.lower + u * (p.upper - p.lower) })
        .collect()
}

/// Sobol' indices of `problem`'s weighted voltage; points where the model fails are left out.
pub fn global_sensitivity(problem: &FittingProblem, settings: &SobolSettings) -> Result<GlobalSensitivity, Error> {
    let output = |u: &[f64]| -> Option<Vec<f64>> {
        let v = problem.simulate(&to_parameters(problem, u)).ok()?;
        Some(v.iter().zip(&problem.weights).map(|(v, w)| v * w.sqrt()).collect())
    };
    let indices = sobol_indices(problem.dim(), &output, settings)?;
    let verdicts = (0..problem.dim())
        .map(|i| {
            let (s, st) = (indices.first[i], indices.total[i]);
            if st < NEGLIGIBLE_TOTAL {
                "no influence on the voltage anywhere in its range: not identifiable from this recording".to_string()
            } else if st > 2.0 * s.max(0.0) + 0.05 {
                format!("acts mostly through interactions (total {st:.2} against first-order {s:.2}): determined only together with others")
            } else {
                format!("influential on its own ({:.0} % of the voltage's variance)", 100.0 * s.max(0.0))
            }
        })
        .collect();
    Ok(GlobalSensitivity { names: problem.parameters.iter().map(|p| p.path.clone()).collect(), indices, verdicts })
}
