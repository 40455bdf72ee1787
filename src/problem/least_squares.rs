//! Bounded Levenberg-Marquardt on a fitting problem's weighted sum of squared residuals, with
//! a forward-difference Jacobian from plain simulations run in parallel.
//!
//! Why not the L-BFGS-B of [`super::fit`]: the diagnosis fits a handful of parameters of
//! many models, on long recordings, where each simulation is the cost. Gauss-Newton steps
//! use the residual's structure and converge in about ten Jacobians where a quasi-Newton
//! search on the scalar cost takes tens to hundreds of evaluations; the Jacobian columns are
//! independent simulations (parallel), and plain simulations are as robust as the model,
//! where the sensitivity system of a DFN may fail to integrate. (The `levenberg-marquardt`
//! crate has no bounds and brings nalgebra beside faer.)
//!
//! The search runs in scaled coordinates `z`: `ln v` for log-scaled parameters, `v / (upper -
//! lower)` for linear ones; bounds are kept by projecting each step onto the box.

use rayon::prelude::*;
use serde::Serialize;

use super::fitting::{FitParameter, FittingProblem};
use crate::error::Error;
use crate::linalg::sym_eigen;
use crate::stats::lag1;

/// Settings of a least-squares fit.
#[derive(Clone, Copy, Debug)]
pub struct LmSettings {
    /// Jacobians at most (each costs one simulation per parameter).
    pub max_iterations: usize,
    /// Converged when an accepted step lowers the SSE by less than this fraction (1e-4 of
    /// the SSE changes a log-likelihood over `n` points by `n 1e-4 / 2`, far below the
    /// margins it is used with).
    pub sse_tolerance: f64,
}

impl Default for LmSettings {
    fn default() -> Self {
        Self { max_iterations: 20, sse_tolerance: 1e-4 }
    }
}

/// Whether `value` lies within 1e-3 of the range of either end of `[lower, upper]`: where a
/// fit counts a parameter as ended on its search bound.
pub fn near_bound(value: f64, lower: f64, upper: f64) -> bool {
    (value - lower).abs() <= 1e-3 * (upper - lower) || (upper - value).abs() <= 1e-3 * (upper - lower)
}

/// The result of a least-squares fit.
#[derive(Clone, Debug, Serialize)]
pub struct LeastSquaresFit {
    /// Fitted values (parameter units).
    pub x: Vec<f64>,
    /// Standard errors (parameter units) from `σ² (JᵀJ)⁻¹`, `σ²` the residual variance on
    /// the weighted points, inflated by `(1 + ρ)/(1 - ρ)` for a lag-1 residual
    /// autocorrelation `ρ > 0`; infinite along directions the data do not determine.
    pub std_errors: Vec<f64>,
    /// Whether each parameter moves the residuals at all at `x` (false: its Jacobian column
    /// is negligible, e.g. a rate on its no-effect bound). Uninformed parameters are left out
    /// of the information matrix, so they neither make it singular nor count in its
    /// determinant.
    pub informed: Vec<bool>,
    /// Weighted sum of squared residuals (V²) and the number of weighted points.
    pub sse: f64,
    pub points: usize,
    /// `ln det(JᵀJ / σ²)` over the directions the data determine (the `information_rank`
    /// non-null eigenvalues among the informed parameters) in scaled coordinates, for a
    /// Laplace evidence.
    pub ln_det_information: f64,
    pub information_rank: usize,
    /// Which fitted values lie on a bound (within 0.1 % of the scaled range).
    pub on_bound: Vec<bool>,
    /// Whether the search stopped on its tolerance (false: on its iteration cap).
    pub converged: bool,
    pub iterations: usize,
    pub simulations: usize,
    /// The modelled curve at `x` ([`LeastSquares::curve`]): for a recording, the voltage (V)
    /// at every recorded point.
    #[serde(skip)]
    pub voltage: Vec<f64>,
}

/// What Levenberg-Marquardt fits: bounded parameters and the weighted residuals of a model
/// run at them (a recording's voltage, a capacity-fade curve, ...).
pub trait LeastSquares: Sync {
    /// What one model run produced.
    type Run: Send;
    /// The parameters, in the order of `x`.
    fn parameters(&self) -> &[FitParameter];
    /// Runs the model at `x` (parameter units); errors when it fails.
    fn run(&self, x: &[f64]) -> Result<Self::Run, Error>;
    /// Weighted residuals of a run.
    fn weighted_residuals(&self, run: &Self::Run) -> Vec<f64>;
    /// Points with a positive weight, and the residuals they give (more when a point holds
    /// several measured quantities), for the residual variance.
    fn counts(&self, run: &Self::Run) -> (usize, usize);
    /// Lag-1 autocorrelation of a run's residuals in recording order (0 when independent).
    fn lag1(&self, run: &Self::Run) -> f64;
    /// The modelled curve kept with the fit, one value per recorded point.
    fn curve(run: Self::Run) -> Vec<f64>;
}

impl LeastSquares for FittingProblem {
    type Run = super::fitting::Simulated;
    fn parameters(&self) -> &[FitParameter] {
        &self.parameters
    }
    fn run(&self, x: &[f64]) -> Result<Self::Run, Error> {
        self.simulate_outputs(x)
    }
    fn weighted_residuals(&self, run: &Self::Run) -> Vec<f64> {
        FittingProblem::weighted_residuals(self, run)
    }
    fn counts(&self, run: &Self::Run) -> (usize, usize) {
        let points = self.weights.iter().filter(|w| **w > 0.0).count();
        // A temperature fitted beside the voltage doubles the residuals.
        (points, if run.temperature.is_empty() { points } else { self.residuals_per_point() * points })
    }
    fn lag1(&self, run: &Self::Run) -> f64 {
        lag1(&self.fitted_residuals(run), &self.weights)
    }
    fn curve(run: Self::Run) -> Vec<f64> {
        run.voltage
    }
}

struct Scale<'a>(&'a [FitParameter]);

impl Scale<'_> {
    fn width(p: &FitParameter) -> f64 {
        p.upper - p.lower
    }
    fn to_z(&self, x: &[f64]) -> Vec<f64> {
        self.0.iter().zip(x).map(|(p, v)| if p.log { v.ln() } else { v / Self::width(p) }).collect()
    }
    fn to_x(&self, z: &[f64]) -> Vec<f64> {
        self.0.iter().zip(z).map(|(p, v)| if p.log { v.exp() } else { v * Self::width(p) }).collect()
    }
    fn bounds(&self) -> Vec<(f64, f64)> {
        self.0.iter().map(|p| if p.log { (p.lower.ln(), p.upper.ln()) } else { (p.lower / Self::width(p), p.upper / Self::width(p)) }).collect()
    }
    /// `dv/dz` at `x`.
    fn dx_dz(&self, x: &[f64]) -> Vec<f64> {
        self.0.iter().zip(x).map(|(p, v)| if p.log { *v } else { Self::width(p) }).collect()
    }
}

/// Sum of squares of `r`.
pub(crate) fn sse(r: &[f64]) -> f64 {
    r.iter().map(|v| v * v).sum()
}

/// Fits the problem's parameters from `start` (parameter units) by Levenberg-Marquardt.
/// Errors when the model fails at `start`; a failed trial step only raises the damping.
pub fn levenberg_marquardt<P: LeastSquares>(problem: &P, start: &[f64], settings: LmSettings) -> Result<LeastSquaresFit, Error> {
    let scale = Scale(problem.parameters());
    let bounds = scale.bounds();
    let k = start.len();
    let project = |z: &mut [f64]| z.iter_mut().zip(&bounds).for_each(|(v, (lo, hi))| *v = v.clamp(*lo, *hi));
    let mut z = scale.to_z(start);
    project(&mut z);
    let mut outputs = problem.run(&scale.to_x(&z))?;
    let mut r = problem.weighted_residuals(&outputs);
    let mut cost = sse(&r);
    let mut simulations = 1;
    let mut lambda = 1e-3;
    let mut converged = k == 0;
    let mut iterations = 0;
    let mut jac: Vec<Vec<f64>> = Vec::new();
    let mut holding = false;
    while !converged && iterations < settings.max_iterations {
        iterations += 1;
        // A model that fails on both sides of the point in every parameter stops the search
        // there (not converged) once a Jacobian exists; the last one stands for the
        // standard errors. A parameter whose steps break the model both ways is held for
        // the iteration, and a fit that ends holding one has not converged.
        let held = match jacobian(problem, &scale, &z, &bounds, &r) {
            Ok((mut j, mut held)) => {
                // A held column keeps the last one computed, when there is one.
                for (i, h) in held.iter_mut().enumerate().filter(|(_, h)| **h) {
                    if let Some(previous) = jac.get(i) {
                        j[i] = previous.clone();
                        *h = false;
                    }
                }
                jac = j;
                held
            }
            Err(_) if !jac.is_empty() => break,
            Err(e) => return Err(e),
        };
        holding = held.iter().any(|h| *h);
        simulations += k;
        let (jtj, jtr) = normal_equations(&jac, &r);
        let mut accepted = false;
        // Held components, and those on a bound whose descent direction points outside,
        // stay fixed.
        let fixed: Vec<bool> = (0..k)
            .map(|i| {
                let (lo, hi) = bounds[i];
                let span = hi - lo;
                held[i] || (z[i] - lo <= 1e-9 * span && jtr[i] > 0.0) || (hi - z[i] <= 1e-9 * span && jtr[i] < 0.0)
            })
            .collect();
        for _ in 0..8 {
            let mut a = jtj.clone();
            let mut b = jtr.clone();
            for i in 0..k {
                a[i * k + i] += lambda * (jtj[i * k + i] + 1e-12);
                if fixed[i] {
                    for j in 0..k {
                        a[i * k + j] = 0.0;
                        a[j * k + i] = 0.0;
                    }
                    a[i * k + i] = 1.0;
                    b[i] = 0.0;
                }
            }
            let step = solve_symmetric(&a, &b, k)?;
            let mut trial: Vec<f64> = z.iter().zip(&step).map(|(z, s)| z - s).collect();
            project(&mut trial);
            let moved = trial.iter().zip(&z).map(|(a, b)| (a - b).abs()).fold(0.0, f64::max);
            if moved < 1e-10 {
                converged = true;
                break;
            }
            simulations += 1;
            let Ok(v) = problem.run(&scale.to_x(&trial)) else {
                lambda *= 10.0;
                continue;
            };
            let rt = problem.weighted_residuals(&v);
            let ct = sse(&rt);
            if ct < cost {
                let gain = (cost - ct) / cost.max(f64::MIN_POSITIVE);
                (z, outputs, r, cost) = (trial, v, rt, ct);
                lambda = (lambda / 3.0).max(1e-9);
                accepted = true;
                converged = gain < settings.sse_tolerance || moved < 1e-6;
                break;
            }
            lambda *= 4.0;
        }
        if !accepted && !converged {
            // No step lowers the cost even with heavy damping: a (local) minimum.
            converged = lambda > 1e3;
            if converged {
                break;
            }
        }
    }
    if jac.is_empty() && k > 0 {
        let held;
        (jac, held) = jacobian(problem, &scale, &z, &bounds, &r)?;
        holding = held.iter().any(|h| *h);
        simulations += k;
    }
    converged &= !holding;
    let x = scale.to_x(&z);
    let (points, residuals) = problem.counts(&outputs);
    let dof = (residuals.saturating_sub(k)).max(1) as f64;
    let sigma2 = (cost / dof).max(f64::MIN_POSITIVE);
    let rho = problem.lag1(&outputs).max(0.0).min(0.99);
    let inflation = (1.0 + rho) / (1.0 - rho);
    let (jtj, _) = normal_equations(&jac, &r);
    let informed = informed_parameters(&jtj, k);
    let (cov, ln_det, rank) = informed_inverse_and_log_det(&jtj, k, &informed)?;
    let dxdz = scale.dx_dz(&x);
    let std_errors = (0..k).map(|i| (sigma2 * inflation * cov[i * k + i]).sqrt() * dxdz[i]).collect();
    let on_bound = z.iter().zip(&bounds).map(|(v, (lo, hi))| near_bound(*v, *lo, *hi)).collect();
    Ok(LeastSquaresFit {
        x,
        std_errors,
        sse: cost,
        points,
        ln_det_information: ln_det - rank as f64 * sigma2.ln(),
        information_rank: rank,
        informed,
        on_bound,
        converged,
        iterations,
        simulations,
        voltage: P::curve(outputs),
    })
}

/// Forward-difference Jacobian of the weighted residuals in scaled coordinates, one column
/// per parameter (stepping inwards at an upper bound), and which columns are held: zero
/// because the model breaks on both sides of the point in that parameter. Errors when every
/// column is held.
fn jacobian<P: LeastSquares>(problem: &P, scale: &Scale, z: &[f64], bounds: &[(f64, f64)], r: &[f64]) -> Result<(Vec<Vec<f64>>, Vec<bool>), Error> {
    let columns: Vec<Result<Vec<f64>, Error>> = (0..z.len())
        .into_par_iter()
        .map(|i| {
            let (lo, hi) = bounds[i];
            let h = if problem.parameters()[i].log { 1e-2 } else { 2e-3 };
            let h = if z[i] + h > hi { -h.min(z[i] - lo).max(h * 1e-3) } else { h };
            // Forward, or backward when the model fails on the forward side (a step that the
            // bounds shrink to nothing is no step).
            let column = |h: f64| -> Result<Vec<f64>, Error> {
                let mut zi = z.to_vec();
                zi[i] = (z[i] + h).clamp(lo, hi);
                let h = zi[i] - z[i];
                if h == 0.0 {
                    return Err(Error::invalid(problem.parameters()[i].path.clone(), scale.to_x(z)[i], "no room for a difference step inside the bounds"));
                }
                let v = problem.run(&scale.to_x(&zi))?;
                Ok(problem.weighted_residuals(&v).iter().zip(r).map(|(a, b)| (a - b) / h).collect())
            };
            column(h).or_else(|_| column(-h))
        })
        .collect();
    let held: Vec<bool> = columns.iter().map(|c| c.is_err()).collect();
    if held.iter().all(|h| *h) {
        return Err(columns.into_iter().find_map(Result::err).expect("a failed column"));
    }
    Ok((columns.into_iter().map(|c| c.unwrap_or_else(|_| vec![0.0; r.len()])).collect(), held))
}

/// `JᵀJ` (row-major `k × k`) and `Jᵀr` from Jacobian columns.
fn normal_equations(jac: &[Vec<f64>], r: &[f64]) -> (Vec<f64>, Vec<f64>) {
    let k = jac.len();
    let mut jtj = vec![0.0; k * k];
    for i in 0..k {
        for j in 0..=i {
            let v: f64 = jac[i].iter().zip(&jac[j]).map(|(a, b)| a * b).sum();
            jtj[i * k + j] = v;
            jtj[j * k + i] = v;
        }
    }
    let jtr = jac.iter().map(|c| c.iter().zip(r).map(|(a, b)| a * b).sum()).collect();
    (jtj, jtr)
}

/// Solves `a x = b` for symmetric positive semi-definite `a` through its eigen-decomposition
/// (directions with eigenvalues below `1e-12` of the largest are left out).
fn solve_symmetric(a: &[f64], b: &[f64], k: usize) -> Result<Vec<f64>, Error> {
    let (values, vectors) = sym_eigen(a, k)?;
    let top = values.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    let mut x = vec![0.0; k];
    for m in 0..k {
        if values[m] > 1e-12 * top {
            let c: f64 = (0..k).map(|i| vectors[i * k + m] * b[i]).sum::<f64>() / values[m];
            for i in 0..k {
                x[i] += c * vectors[i * k + m];
            }
        }
    }
    Ok(x)
}

/// Inverse (infinite diagonal along null directions) and `ln det` of a symmetric `k × k`.
/// Which of the `k` parameters the residuals depend on: a diagonal of `JᵀJ` above `1e-10`
/// of the largest (the threshold below which [`inverse_and_log_det`] calls a direction null).
fn informed_parameters(jtj: &[f64], k: usize) -> Vec<bool> {
    let top = (0..k).map(|i| jtj[i * k + i]).fold(0.0f64, f64::max);
    (0..k).map(|i| jtj[i * k + i] > 1e-10 * top).collect()
}

/// [`inverse_and_log_det`] of the block of `a` the `informed` parameters span, scattered back
/// into `k x k` with an infinite variance for each uninformed parameter.
fn informed_inverse_and_log_det(a: &[f64], k: usize, informed: &[bool]) -> Result<(Vec<f64>, f64, usize), Error> {
    let keep: Vec<usize> = (0..k).filter(|i| informed[*i]).collect();
    let m = keep.len();
    let block: Vec<f64> = keep.iter().flat_map(|i| keep.iter().map(move |j| a[i * k + j])).collect();
    let (inv, ln_det, rank) = if m == 0 { (Vec::new(), 0.0, 0) } else { inverse_and_log_det(&block, m)? };
    let mut full = vec![0.0; k * k];
    for i in (0..k).filter(|i| !informed[*i]) {
        full[i * k + i] = f64::INFINITY;
    }
    for (p, i) in keep.iter().enumerate() {
        for (q, j) in keep.iter().enumerate() {
            full[i * k + j] = inv[p * m + q];
        }
    }
    Ok((full, ln_det, rank))
}
/// Share of a unit eigenvector (-) below which a parameter does not lie along it: round-off
/// in the eigenvectors of a null direction is not a free parameter.
const NULL_COMPONENT: f64 = 1e-6;

/// The pseudo-inverse of the symmetric positive semi-definite `k x k` matrix `a` (infinite
/// variance for a parameter with a component above [`NULL_COMPONENT`] along a direction with
/// an eigenvalue below `1e-10` of the largest), the `ln det` over the other directions, and
/// how many they are.
fn inverse_and_log_det(a: &[f64], k: usize) -> Result<(Vec<f64>, f64, usize), Error> {
    let (values, vectors) = sym_eigen(a, k)?;
    let top = values.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    let mut inv = vec![0.0; k * k];
    let mut ln_det = 0.0;
    let mut rank = 0;
    for m in 0..k {
        let null = !(values[m] > 1e-10 * top);
        if !null {
            ln_det += values[m].ln();
            rank += 1;
        }
        for i in 0..k {
            for j in 0..k {
                inv[i * k + j] += if null { if vectors[i * k + m].abs() > NULL_COMPONENT && i == j { f64::INFINITY } else { 0.0 } } else { vectors[i * k + m] * vectors[j * k + m] / values[m] };
            }
        }
    }
    Ok((inv, ln_det, rank))
}


#[cfg(test)]
pub(crate) mod tests {
    use super::*;

    /// `v = slope(x) t` against a line of slope 2 with ±0.01 alternating noise.
    pub(crate) struct Line {
        parameters: Vec<FitParameter>,
        slope: fn(&[f64]) -> f64,
        data: Vec<f64>,
    }

    impl Line {
        pub(crate) fn new(parameters: Vec<FitParameter>, slope: fn(&[f64]) -> f64) -> Self {
            let data = (0..50).map(|t| 2.0 * t as f64 + if t % 2 == 0 { 0.01 } else { -0.01 }).collect();
            Self { parameters, slope, data }
        }
    }

    impl LeastSquares for Line {
        type Run = Vec<f64>;
        fn parameters(&self) -> &[FitParameter] {
            &self.parameters
        }
        fn run(&self, x: &[f64]) -> Result<Vec<f64>, Error> {
            Ok((0..self.data.len()).map(|t| (self.slope)(x) * t as f64).collect())
        }
        fn weighted_residuals(&self, run: &Vec<f64>) -> Vec<f64> {
            run.iter().zip(&self.data).map(|(m, d)| m - d).collect()
        }
        fn counts(&self, run: &Vec<f64>) -> (usize, usize) {
            (run.len(), run.len())
        }
        fn lag1(&self, _: &Vec<f64>) -> f64 {
            0.0
        }
        fn curve(run: Vec<f64>) -> Vec<f64> {
            run
        }
    }

    #[test]
    fn a_parameter_without_effect_is_left_out_of_the_information() {
        // `b` does not enter the model.
        let parameters = vec![FitParameter::log("a", 1.0, 0.1, 10.0), FitParameter::log("b", 1e-3, 1e-6, 1.0)];
        let fit = levenberg_marquardt(&Line::new(parameters, |x| x[0]), &[1.0, 1e-3], LmSettings::default()).unwrap();
        assert_eq!(fit.informed, vec![true, false]);
        assert_eq!(fit.information_rank, 1);
        assert!((fit.x[0] - 2.0).abs() < 1e-4, "{:?}", fit.x);
        assert!(fit.std_errors[0].is_finite() && fit.std_errors[0] > 0.0, "{:?}", fit.std_errors);
        assert!(fit.std_errors[1].is_infinite());
        // The determinant is a's alone, Σ t² a² / σ² in the log coordinate, to the 1 % of its
        // forward-difference column (step 1e-2 in ln a).
        let sigma2 = fit.sse / 48.0;
        let expected = ((0..50).map(|t| (t as f64).powi(2)).sum::<f64>() * fit.x[0].powi(2) / sigma2).ln();
        assert!((fit.ln_det_information - expected).abs() < 2e-2, "{} vs {expected}", fit.ln_det_information);
    }

    #[test]
    fn a_direction_the_data_leave_free_does_not_count_in_the_determinant() {
        // Only the product `a b` is determined.
        let parameters = vec![FitParameter::log("a", 1.0, 0.1, 10.0), FitParameter::log("b", 1.0, 0.1, 10.0)];
        let fit = levenberg_marquardt(&Line::new(parameters, |x| x[0] * x[1]), &[1.0, 1.0], LmSettings::default()).unwrap();
        assert_eq!(fit.informed, vec![true, true]);
        assert_eq!(fit.information_rank, 1);
        assert!(fit.ln_det_information.is_finite(), "{}", fit.ln_det_information);
        assert!(fit.std_errors.iter().all(|e| e.is_infinite()), "{:?}", fit.std_errors);
        assert!((fit.x[0] * fit.x[1] - 2.0).abs() < 1e-4, "{:?}", fit.x);
    }

    #[test]
    fn round_off_along_a_null_direction_leaves_a_parameter_determined() {
        // Information 4 along `u` (mostly `x0`) and 2 along `x1 + x2`; the null direction
        // `x1 - x2` leans 1e-9 towards `x0`, as round-off does: `x0` keeps a finite variance.
        let (t, s) = (1e-9f64, (1.0 - 1e-18f64).sqrt());
        let r = 1.0 / 2f64.sqrt();
        let u = [s, -t * r, t * r];
        let d = [0.0, r, r];
        let a: Vec<f64> = (0..9).map(|ij| (ij / 3, ij % 3)).map(|(i, j)| 4.0 * u[i] * u[j] + 2.0 * d[i] * d[j]).collect();
        let (inv, ln_det, rank) = inverse_and_log_det(&a, 3).unwrap();
        assert_eq!(rank, 2);
        assert!((ln_det - 8f64.ln()).abs() < 1e-12, "{ln_det}");
        assert!((inv[0] - 0.25).abs() < 1e-12, "{}", inv[0]);
        assert!(inv[4].is_infinite() && inv[8].is_infinite(), "{inv:?}");
    }
}
