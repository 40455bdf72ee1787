//! Profile likelihoods (Raue et al., Bioinformatics 25 (2009) 1923): each fitted parameter
//! held at a grid of values on either side of the optimum while the others are refitted by
//! Levenberg-Marquardt, warm-started from the neighbouring grid point. The likelihood-ratio
//! statistic against the best fit, with the noise level profiled out, is
//! `n_eff ln(SSE(θ) / SSE_min)`; the 95 % interval is where it stays below the chi-squared
//! quantile with one degree of freedom. Unlike the Fisher (Wald) interval it follows the cost
//! as it is, so a side that never rises above the threshold before the search bound is found
//! out: the data do not bound the parameter there.

use serde::Serialize;

use super::fitting::FittingProblem;
use super::least_squares::{LmSettings, levenberg_marquardt};
use crate::error::Error;

/// 95 % quantile of the chi-squared distribution with one degree of freedom.
pub const CHI2_95_ONE_DOF: f64 = 3.841_458_820_694_124;

/// Standard errors on either side of the optimum a profile spans (clipped to the bounds).
const SPAN_STANDARD_ERRORS: f64 = 4.0;

/// The profile of one fitted parameter.
#[derive(Clone, Debug, Serialize)]
pub struct Profile {
    pub name: String,
    /// The optimum (parameter units).
    pub best: f64,
    /// Held values (parameter units), ascending, the optimum among them.
    pub values: Vec<f64>,
    /// Likelihood-ratio statistic at each held value (-); NaN where the refit failed.
    pub statistic: Vec<f64>,
    /// Ends of the 95 % interval, where the statistic crosses [`CHI2_95_ONE_DOF`]; `None` on a
    /// side where it stays below up to the end of the profile (not bounded by the data there).
    pub lower: Option<f64>,
    pub upper: Option<f64>,
    /// Lowest SSE the profile met below the optimum's, when it found a better fit (V²).
    pub better_fit: Option<f64>,
}

impl Profile {
    /// In words, numbers written by `n`: an interval, or which side the data leave open.
    pub fn describe(&self, n: &dyn Fn(f64) -> String) -> String {
        let (first, last) = (self.values[0], self.values[self.values.len() - 1]);
        match (self.lower, self.upper) {
            (Some(l), Some(u)) => format!("[{}, {}]", n(l), n(u)),
            (None, Some(u)) => format!("not bounded below down to {} (the lowest value held), up to {}", n(first), n(u)),
            (Some(l), None) => format!("from {}, not bounded above up to {} (the highest value held)", n(l), n(last)),
            (None, None) => format!("not bounded from {} to {} (all values held): not identifiable", n(first), n(last)),
        }
    }
}

/// The profile of fitted parameter `k` of `problem` around the optimum `best` (parameter
/// units) with standard errors `std_errors`, `points` held values on each side.
pub fn profile(problem: &FittingProblem, best: &[f64], std_errors: &[f64], k: usize, points: usize) -> Result<Profile, Error> {
    let p = &problem.parameters[k];
    let settings = LmSettings::default();
    let optimum = levenberg_marquardt(problem, best, settings)?;
    let residual: Vec<f64> = problem.residuals(&optimum.voltage);
    let rho = crate::stats::lag1(&residual, &problem.weights).max(0.0);
    let n_eff = optimum.points as f64 * (1.0 - rho) / (1.0 + rho);
    // Grid in the parameter's search coordinate (log or linear), out from the optimum.
    let (to_z, to_x): (fn(f64) -> f64, fn(f64) -> f64) = if p.log { (f64::ln, f64::exp) } else { (|v| v, |v| v) };
    let centre = optimum.x[k];
    let se_z = if p.log { std_errors[k] / centre } else { std_errors[k] };
    let reach = |edge: f64| {
        let z = to_z(centre) + (to_z(edge) - to_z(centre)).signum() * SPAN_STANDARD_ERRORS * se_z;
        if se_z.is_finite() && se_z > 0.0 && (z - to_z(edge)) * (to_z(centre) - to_z(edge)) > 0.0 { z } else { to_z(edge) }
    };
    let mut sides: Vec<Vec<(f64, f64)>> = Vec::new();
    let mut better = f64::INFINITY;
    for edge in [p.lower, p.upper] {
        let far = reach(edge);
        let mut others: Vec<f64> = optimum.x.iter().enumerate().filter(|(j, _)| *j != k).map(|(_, v)| *v).collect();
        let mut side = Vec::new();
        for j in 1..=points.max(1) {
            let value = to_x(to_z(centre) + (far - to_z(centre)) * j as f64 / points.max(1) as f64).clamp(p.lower, p.upper);
            let held = problem.pinned(k, value)?;
            let sse = match levenberg_marquardt(&held, &others, settings) {
                Ok(fit) => {
                    others = fit.x;
                    fit.sse
                }
                Err(_) => f64::NAN,
            };
            better = better.min(sse);
            side.push((value, sse));
        }
        sides.push(side);
    }
    let sse_min = optimum.sse.min(better);
    let statistic = |sse: f64| if sse.is_finite() { n_eff * (sse / sse_min).ln() } else { f64::NAN };
    let crossing = |side: &[(f64, f64)]| {
        let mut previous = (centre, statistic(optimum.sse));
        for &(v, sse) in side {
            let s = statistic(sse);
            if s >= CHI2_95_ONE_DOF {
                let f = (CHI2_95_ONE_DOF - previous.1) / (s - previous.1);
                return Some(to_x(to_z(previous.0) + f * (to_z(v) - to_z(previous.0))));
            }
            if s.is_finite() {
                previous = (v, s);
            }
        }
        None
    };
    let (lower, upper) = (crossing(&sides[0]), crossing(&sides[1]));
    let mut grid: Vec<(f64, f64)> = sides.concat();
    grid.push((centre, optimum.sse));
    grid.sort_by(|a, b| a.0.total_cmp(&b.0));
    Ok(Profile {
        name: p.path.clone(),
        best: centre,
        values: grid.iter().map(|g| g.0).collect(),
        statistic: grid.iter().map(|g| statistic(g.1)).collect(),
        lower,
        upper,
        better_fit: (better < optimum.sse * (1.0 - 1e-6)).then_some(better),
    })
}
