//! Warnings every run gives the same way: a result on a bound of its search range, a search
//! stopped on its iteration or evaluation cap.

/// The values of `x` that lie on a bound (within 1e-6 of their range): index and side.
pub fn on_bounds(x: &[f64], lower: &[f64], upper: &[f64]) -> Vec<(usize, &'static str)> {
    let mut out = Vec::new();
    for (k, ((&v, &lo), &hi)) in x.iter().zip(lower).zip(upper).enumerate() {
        let tol = 1e-6 * (hi - lo).abs();
        for (side, b) in [("lower", lo), ("upper", hi)] {
            if (v - b).abs() <= tol {
                out.push((k, side));
            }
        }
    }
    out
}

/// A named value on a bound of its search range.
#[derive(Clone, Debug, PartialEq)]
pub struct OnBound {
    pub name: String,
    pub value: f64,
    /// `"lower"` or `"upper"`.
    pub side: &'static str,
}

impl std::fmt::Display for OnBound {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{} = {} at its {} bound", self.name, crate::error::number(self.value), self.side)
    }
}

/// The values of `x` on a bound ([`on_bounds`]) with their `names`.
pub fn named_on_bounds(names: &[String], x: &[f64], lower: &[f64], upper: &[f64]) -> Vec<OnBound> {
    on_bounds(x, lower, upper)
        .into_iter()
        .filter_map(|(k, side)| Some(OnBound { name: names.get(k)?.clone(), value: x[k], side }))
        .collect()
}

/// One warning per value of `x` on a bound ([`on_bounds`]), naming it.
pub fn at_bound_warnings(what: &str, names: &[String], x: &[f64], lower: &[f64], upper: &[f64]) -> Vec<String> {
    named_on_bounds(names, x, lower, upper).iter().map(|b| bound_warning(what, b)).collect()
}

/// The fitted `parameters`' values in `x` that ended on a bound of their search range, and one
/// warning per value ([`at_bound_warnings`]) saying so.
pub fn fitted_on_bounds(what: &str, parameters: &[crate::problem::fitting::FitParameter], x: &[f64]) -> (Vec<OnBound>, Vec<String>) {
    let names: Vec<String> = parameters.iter().map(|p| p.path.clone()).collect();
    let (lower, upper): (Vec<f64>, Vec<f64>) = parameters.iter().map(|p| (p.lower, p.upper)).unzip();
    let on_bound = named_on_bounds(&names, x, &lower, &upper);
    let warnings = on_bound.iter().map(|b| bound_warning(what, b)).collect();
    (on_bound, warnings)
}

/// The warning of `what` ending with `b` on a bound.
fn bound_warning(what: &str, b: &OnBound) -> String {
    format!("{what} has {b}; the best value may lie outside the searched range")
}

/// A warning when a Levenberg-Marquardt fit stopped on its iteration cap before converging.
pub fn unconverged_warning(what: &str, fit: &crate::problem::least_squares::LeastSquaresFit) -> Option<String> {
    (!fit.converged).then(|| format!("{what} stopped after {} iterations before converging: the values are the best found so far", fit.iterations))
}

/// A warning when an optimiser stopped on its iteration or evaluation cap rather than on
/// convergence: the result is the best found so far, not an optimum.
pub fn truncation_warning(what: &str, stop: &crate::optim::StopReason, iterations: usize, evaluations: usize) -> Option<String> {
    let cap = cap_name(stop)?;
    truncation_warning_with(what, stop, iterations, evaluations, &format!("raise [optimiser] max_{cap}s to go on"))
}

/// [`truncation_warning`] for a search whose cap the user cannot raise: `remedy` says what to
/// do instead.
pub fn truncation_warning_with(what: &str, stop: &crate::optim::StopReason, iterations: usize, evaluations: usize, remedy: &str) -> Option<String> {
    let cap = cap_name(stop)?;
    Some(format!(
        "{what} stopped on its {cap} cap ({iterations} iterations, {evaluations} evaluations) before converging: the result is the best found so far; {remedy}"
    ))
}

/// `iteration` or `evaluation` for a search stopped on that cap; `None` for any other end.
fn cap_name(stop: &crate::optim::StopReason) -> Option<&'static str> {
    use crate::optim::StopReason;
    match stop {
        StopReason::MaxIterations => Some("iteration"),
        StopReason::MaxEvaluations => Some("evaluation"),
        _ => None,
    }
}
