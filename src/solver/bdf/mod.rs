//! Variable-order (1-5), variable-step BDF/NDF integrator for semi-explicit index-1 DAEs
//! `M y' = f(t, y)` with a diagonal 0/1 mass matrix `M`.
//!
//! The step, order and error-control logic follows Shampine & Reichelt's NDF
//! (the scheme of MATLAB `ode15s` and SciPy `BDF`), written on a backward-difference array so
//! that step-size changes are O(order^2) and dense output is free. Newton matrices are
//! sparse (see [`SparseSystem`](super::sparse::SparseSystem)) and the Jacobian is a coloured finite difference (see
//! [`ColouredPattern`](super::jacobian::ColouredPattern)); both are reused across steps until Newton convergence slows.
//!
//! [`Bdf`] (`stepper.rs`) takes one step at a time; `solve.rs` drives it to a stop time and
//! locates events; `newton.rs` solves each step's corrector; `control.rs` chooses step size and
//! order; `differences.rs` keeps the backward-difference array. [`integrate`] wraps them.

mod control;
mod differences;
mod newton;
mod solve;
mod stepper;

pub use super::dense::DenseOutput;
pub use super::workspace::Workspace;
use crate::error::Error;
pub use stepper::{Bdf, StepInfo};

/// A semi-explicit DAE `M y' = f(t, y)`.
pub trait Dae {
    /// Number of states.
    fn len(&self) -> usize;
    /// Diagonal of the mass matrix: 1 for differential rows, 0 for algebraic rows.
    fn mass(&self) -> &[f64];
    /// Typical magnitude of each state (absolute tolerance and difference steps scale by it).
    fn scale(&self) -> &[f64];
    /// Floor of each state's finite-difference step, before the `sqrt(eps)` factor (see
    /// [`crate::models::Model::difference_scale`]).
    fn difference_scale(&self) -> &[f64] {
        self.scale()
    }
    /// Evaluates `f(t, y)` into `out`.
    fn rhs(&self, t: f64, y: &[f64], out: &mut [f64]);
    /// Times (s), increasing, where `f` has a kink in `t` (the points of a piecewise-linear
    /// input): steps end on them rather than straddle them, as CVODE's stop times.
    fn breakpoints(&self) -> &[f64] {
        &[]
    }
    /// States that only integrate a rate and never relax (an SEI layer, plated lithium, lost
    /// active material): their local errors add up over a run instead of decaying, so
    /// [`SolverOptions::accumulator_tolerance`] may hold them tighter than the rest.
    fn accumulating_states(&self) -> Vec<usize> {
        Vec::new()
    }
}

/// Tolerances and limits of the integrator.
#[derive(Clone, Debug, serde::Serialize, serde::Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct SolverOptions {
    /// Relative tolerance.
    pub rtol: f64,
    /// Absolute tolerance, relative to each state's typical magnitude.
    pub atol: f64,
    /// Largest step (s).
    pub max_step: f64,
    /// Largest number of accepted steps per call.
    pub max_steps: usize,
    /// Factor (0, 1] on both tolerances of the [`Dae::accumulating_states`]; 1 holds them
    /// like every other state. A cycling run of `N` cycles holds them to `1 / N` of it, so
    /// that what they accumulate over the run is about one cycle's error at the tolerance.
    pub accumulator_tolerance: f64,
}

impl Default for SolverOptions {
    fn default() -> Self {
        Self { rtol: 1e-6, atol: 1e-6, max_step: f64::INFINITY, max_steps: 100_000, accumulator_tolerance: 1.0 }
    }
}

impl SolverOptions {
    /// Sets both tolerances to `tol` (rtol = atol, the way studies and the diagnosis give one).
    pub fn set_tolerance(&mut self, tol: f64) {
        (self.rtol, self.atol) = (tol, tol);
    }
}

/// Counters of the work done, for benchmarks and performance-regression tests.
#[derive(Clone, Copy, Debug, Default, serde::Serialize)]
pub struct SolverStats {
    /// Accepted steps.
    pub steps: usize,
    /// Rejected step attempts (Newton failures with a fresh Jacobian plus error-test failures).
    pub rejected_steps: usize,
    /// Right-hand side evaluations, including those of finite-difference Jacobians.
    pub rhs_evals: usize,
    pub jacobian_evals: usize,
    pub factorisations: usize,
    /// Newton iterations (one linear solve each).
    pub newton_iters: usize,
    /// Newton iterations that failed to converge (with a stale or a fresh Jacobian).
    pub newton_failures: usize,
    /// Steps rejected by the local error test.
    pub error_test_failures: usize,
}

impl SolverStats {
    pub fn add(&mut self, other: &SolverStats) {
        self.steps += other.steps;
        self.rejected_steps += other.rejected_steps;
        self.rhs_evals += other.rhs_evals;
        self.jacobian_evals += other.jacobian_evals;
        self.factorisations += other.factorisations;
        self.newton_iters += other.newton_iters;
        self.newton_failures += other.newton_failures;
        self.error_test_failures += other.error_test_failures;
    }
}

/// Why an integration call returned.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum StopReason {
    /// The end time was reached.
    EndTime,
    /// The event function crossed zero at this time (s).
    Event(f64),
}

/// Integrates `dae` from `(t0, y0)` to `t_end`, or until `event(t, y)` changes sign.
///
/// `y0` must be consistent (algebraic rows satisfied). After every accepted step,
/// `observer(t_old, dense)` is called with the step's interpolant; on return `y0` holds the
/// final state (at the event time if one fired).
pub fn integrate(
    dae: &dyn Dae,
    ws: &mut Workspace,
    opts: &SolverOptions,
    t0: f64,
    y0: &mut [f64],
    t_end: f64,
    event: Option<&dyn Fn(f64, &[f64]) -> f64>,
    observer: &mut dyn FnMut(f64, &DenseOutput),
    stats: &mut SolverStats,
) -> Result<StopReason, Error> {
    if t_end - t0 <= 0.0 {
        return Ok(StopReason::EndTime);
    }
    // A failed start has cost its one evaluation of the right-hand side.
    let mut bdf = Bdf::new(dae, ws, opts, t0, y0, t_end).inspect_err(|_| stats.rhs_evals += 1)?;
    let stop = bdf.solve(event, observer);
    stats.add(bdf.stats());
    let stop = stop?;
    match stop {
        StopReason::EndTime => y0.copy_from_slice(bdf.state()),
        StopReason::Event(t_event) => bdf.dense().eval(t_event, y0),
    }
    Ok(stop)
}
