//! Electrode balancing: the stoichiometry windows and electrode capacities that make the
//! half-cell OCPs reproduce a full-cell pseudo-OCV. With `q` the charge discharged from the
//! top of the pseudo-OCV (A h), the negative and positive stoichiometries are
//! `x(q) = x_top - q / Q_n` and `y(q) = y_top + q / Q_p`, and the model OCV is
//! `U_p(y(q)) - U_n(x(q))`. The four parameters `x_top`, `y_top`, `Q_n`, `Q_p` (electrode
//! capacities per unit stoichiometry, A h) are fitted by least squares with analytic
//! gradients (projected L-BFGS), standard errors from the Gauss-Newton information.

use serde::Serialize;

use crate::error::Error;
use crate::optim::{Bounds, NoObserver, Objective, OptimOptions, Problem, StopReason, by_name};
use crate::params::function::Function1D;
use crate::params::{FARADAY, ParameterSet, StoichiometryWindow, stoichiometry_window};

/// Names of the fitted quantities, in order.
pub const NAMES: [&str; 4] = ["x_top", "y_top", "negative_capacity_Ah", "positive_capacity_Ah"];

/// A balance of the electrodes against a pseudo-OCV.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Balance {
    /// Negative and positive stoichiometry (-) at the top of the pseudo-OCV (`q = 0`).
    pub x_top: f64,
    pub y_top: f64,
    /// Negative and positive electrode capacity per unit stoichiometry (A h).
    pub q_n: f64,
    pub q_p: f64,
}

impl Balance {
    fn from_slice(v: &[f64]) -> Self {
        Self { x_top: v[0], y_top: v[1], q_n: v[2], q_p: v[3] }
    }
    fn to_vec(self) -> Vec<f64> {
        vec![self.x_top, self.y_top, self.q_n, self.q_p]
    }

    /// Stoichiometries (-) after discharging `q` (A h) from the top.
    pub fn at(&self, q: f64) -> (f64, f64) {
        (self.x_top - q / self.q_n, self.y_top + q / self.q_p)
    }

    /// Cyclable lithium (A h): `Q_n x + Q_p y`, the same at every `q`.
    pub fn lithium(&self) -> f64 {
        self.q_n * self.x_top + self.q_p * self.y_top
    }

    /// The balance of parameter set `p`: its electrode capacities and its stoichiometries at
    /// the open-circuit voltage `v_top` (V) with its cyclable lithium.
    pub fn of(p: &ParameterSet, v_top: f64) -> Self {
        let line = crate::params::soc::LithiumLine::of(p);
        let x_top = line.negative_at_ocv(p, v_top);
        let (q_n, q_p) = electrode_capacities(p);
        Self { x_top, y_top: line.positive(x_top), q_n, q_p }
    }

    /// Puts the balance into `p`: each electrode's maximum concentration (its capacity per
    /// volume of active material) scaled so that `eps L A c_max F = Q`, geometry untouched,
    /// and the initial concentrations at the top of the pseudo-OCV. Returns the window
    /// between the set's cut-offs ([`stoichiometry_window`]).
    pub fn apply(&self, p: &mut ParameterSet) -> Result<StoichiometryWindow, Error> {
        let (q_n, q_p) = electrode_capacities(p);
        p.negative.max_concentration *= self.q_n / q_n;
        p.positive.max_concentration *= self.q_p / q_p;
        p.negative.initial_concentration = self.x_top * p.negative.max_concentration;
        p.positive.initial_concentration = self.y_top * p.positive.max_concentration;
        stoichiometry_window(p)
    }
}

/// Negative and positive electrode capacities per unit stoichiometry (A h) of `p`.
pub fn electrode_capacities(p: &ParameterSet) -> (f64, f64) {
    let q = |e: &crate::params::Electrode| e.active_fraction * e.thickness * p.cell.area() * e.max_concentration * FARADAY / 3600.0;
    (q(&p.negative), q(&p.positive))
}

/// A pseudo-OCV to balance against.
pub struct BalancingProblem {
    /// Charge discharged from the top (A h) and the pseudo-OCV there (V).
    pub discharged: Vec<f64>,
    pub voltage: Vec<f64>,
    pub negative_ocp: Function1D,
    pub positive_ocp: Function1D,
}

/// Step (-) of the central differences of the OCPs.
const OCP_STEP: f64 = 1e-6;

/// Slope `dU/dx` (V per unit stoichiometry) of the OCP `f` at `x`, by central differences.
pub fn ocp_slope(f: &Function1D, x: f64) -> f64 {
    (f.eval(x + OCP_STEP) - f.eval(x - OCP_STEP)) / (2.0 * OCP_STEP)
}

impl BalancingProblem {
    /// Model OCV minus pseudo-OCV (V) at every point, and (when asked) the rows
    /// `d residual / d (x_top, y_top, Q_n, Q_p)`.
    pub fn residuals(&self, b: &Balance, rows: Option<&mut Vec<[f64; 4]>>) -> Vec<f64> {
        let mut out = Vec::with_capacity(self.voltage.len());
        let mut jac = Vec::new();
        for (&q, &v) in self.discharged.iter().zip(&self.voltage) {
            let (x, y) = b.at(q);
            out.push(self.positive_ocp.eval(y) - self.negative_ocp.eval(x) - v);
            if rows.is_some() {
                let (dn, dp) = (ocp_slope(&self.negative_ocp, x), ocp_slope(&self.positive_ocp, y));
                jac.push([-dn, dp, -dn * q / (b.q_n * b.q_n), -dp * q / (b.q_p * b.q_p)]);
            }
        }
        if let Some(r) = rows {
            *r = jac;
        }
        out
    }
}

impl Objective for BalancingProblem {
    fn dim(&self) -> usize {
        4
    }
    fn evaluate(&self, x: &[f64]) -> f64 {
        self.residuals(&Balance::from_slice(x), None).iter().map(|r| r * r).sum()
    }
    fn gradient(&self, x: &[f64]) -> Option<Vec<f64>> {
        let mut rows = Vec::new();
        let r = self.residuals(&Balance::from_slice(x), Some(&mut rows));
        let mut g = vec![0.0; 4];
        for (ri, row) in r.iter().zip(&rows) {
            for k in 0..4 {
                g[k] += 2.0 * ri * row[k];
            }
        }
        Some(g)
    }
}

/// A fitted balance.
#[derive(Clone, Debug, Serialize)]
pub struct BalanceFit {
    pub balance: Balance,
    /// Standard errors of `x_top`, `y_top`, `Q_n`, `Q_p` (their units) and their correlation.
    pub std_errors: Vec<f64>,
    pub correlation: Vec<Vec<f64>>,
    /// Standard errors of the cyclable lithium (A h) and the N/P ratio (-).
    pub lithium_error: f64,
    pub np_ratio_error: f64,
    /// RMS of model minus pseudo-OCV (V).
    pub rmse: f64,
    /// Lag-1 autocorrelation of the residuals (-): near 1, the errors are systematic and the
    /// standard errors lower bounds.
    pub residual_lag1: f64,
    pub evaluations: usize,
    pub stop: StopReason,
    pub lower: Vec<f64>,
    pub upper: Vec<f64>,
}

/// Fits the balance from `start` within `lower`/`upper` (in [`NAMES`] order).
pub fn fit_balance(problem: &BalancingProblem, start: Balance, lower: [f64; 4], upper: [f64; 4]) -> Result<BalanceFit, Error> {
    let search = Problem::new(problem, Bounds::new(lower.to_vec(), upper.to_vec())?)?;
    let options = OptimOptions { max_iterations: 2000, max_evaluations: 20_000, f_tolerance: 1e-14, ..Default::default() };
    let result = by_name("lbfgsb", options)?.minimise(&search, &start.to_vec(), &mut NoObserver)?;
    let balance = Balance::from_slice(&result.x);
    let mut rows = Vec::new();
    let r = problem.residuals(&balance, Some(&mut rows));
    let w = vec![1.0; r.len()];
    let id = super::identification::covariance(&r, &w, rows.iter().map(|row| row.as_slice()), &result.x)?;
    let cov = |a: usize, b: usize| id.correlation[a][b] * id.std_errors[a] * id.std_errors[b];
    let spread = |g: [f64; 4]| (0..4).flat_map(|a| (0..4).map(move |b| (a, b))).map(|(a, b)| g[a] * g[b] * cov(a, b)).sum::<f64>().max(0.0).sqrt();
    let b = balance;
    Ok(BalanceFit {
        lithium_error: spread([b.q_n, b.q_p, b.x_top, b.y_top]),
        np_ratio_error: spread([0.0, 0.0, 1.0 / b.q_p, -b.q_n / (b.q_p * b.q_p)]),
        residual_lag1: crate::stats::lag1(&r, &w),
        std_errors: id.std_errors,
        correlation: id.correlation,
        rmse: id.rmse,
        evaluations: result.evaluations,
        stop: result.stop,
        balance,
        lower: lower.to_vec(),
        upper: upper.to_vec(),
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::params::chen2020;

    /// The OCV of Chen 2020's own balance is recovered from a start 15-20 % off, to the
    /// optimiser's precision.
    #[test]
    fn recovers_a_noise_free_balance() {
        let p = chen2020();
        let truth = Balance::of(&p, 4.2);
        let discharged: Vec<f64> = (0..=200).map(|k| 5.0 * k as f64 / 200.0).collect();
        let problem = BalancingProblem {
            voltage: discharged.iter().map(|&q| {
                let (x, y) = truth.at(q);
                p.positive.ocp.eval(y) - p.negative.ocp.eval(x)
            }).collect(),
            discharged,
            negative_ocp: p.negative.ocp.clone(),
            positive_ocp: p.positive.ocp.clone(),
        };
        let start = Balance { x_top: 0.8, y_top: 0.3, q_n: 1.2 * truth.q_n, q_p: 0.85 * truth.q_p };
        let fit = fit_balance(&problem, start, [0.05, 0.0, 2.5, 2.5], [1.0, 0.95, 25.0, 25.0]).unwrap();
        let b = fit.balance;
        assert!(fit.rmse < 1e-6, "{fit:?}");
        for (got, want) in [(b.x_top, truth.x_top), (b.y_top, truth.y_top), (b.q_n, truth.q_n), (b.q_p, truth.q_p)] {
            assert!((got / want - 1.0).abs() < 1e-4, "{got} vs {want}: {fit:?}");
        }
        let mut applied = p.clone();
        let w = b.apply(&mut applied).unwrap();
        let w0 = stoichiometry_window(&p).unwrap();
        assert!((w.x100 - w0.x100).abs() < 1e-4 && (w.y0 - w0.y0).abs() < 1e-4, "{w:?} vs {w0:?}");
    }
}
