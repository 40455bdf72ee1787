//! Variable-order (1-5), variable-step BDF/NDF integrator for semi-explicit index-1 DAEs
//! `M y' = f(t, y)` with a diagonal 0/1 mass matrix `M`.
//!
//! The step, order and error-control logic follows Shampine & Reichelt's NDF
//! (the scheme of MATLAB `ode15s` and SciPy `BDF`), written on a backward-difference array so
//! that step-size changes are O(order^2) and dense output is free. Newton matrices are
//! sparse (see [`SparseSystem`](super::sparse::SparseSystem)) and the Jacobian is a coloured finite difference (see
//! [`ColouredPattern`](super::jacobian::ColouredPattern)); both are reused across steps until Newton convergence slows.

pub use super::dense::DenseOutput;
pub use super::workspace::Workspace;
use crate::error::Error;

const MAX_ORDER: usize = 5;
const NEWTON_MAXITER: usize = 4;
/// Newton convergence threshold on the weighted correction norm.
const NEWTON_TOL: f64 = 0.03;
const MIN_FACTOR: f64 = 0.2;
const MAX_FACTOR: f64 = 10.0;
/// Largest relative change of `c = h / alpha` before the Newton matrix is refactorised.
const MAX_GAMMA_DRIFT: f64 = 0.3;
/// NDF coefficients kappa_k of Shampine & Reichelt (1997).
const KAPPA: [f64; 6] = [0.0, -0.1850, -1.0 / 9.0, -0.0823, -0.0415, 0.0];

/// A semi-explicit DAE `M y' = f(t, y)`.
pub trait Dae {
    /// Number of states.
    fn len(&self) -> usize;
    /// Diagonal of the mass matrix: 1 for differential rows, 0 for algebraic rows.
    fn mass(&self) -> &[f64];
    /// Typical magnitude of each state (absolute tolerance and difference steps scale by it).
    fn scale(&self) -> &[f64];
    /// Evaluates `f(t, y)` into `out`.
    fn rhs(&self, t: f64, y: &[f64], out: &mut [f64]);
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
}

impl Default for SolverOptions {
    fn default() -> Self {
        Self { rtol: 1e-6, atol: 1e-6, max_step: f64::INFINITY, max_steps: 100_000 }
    }
}

/// Counters of the work done, for benchmarks and performance-regression tests.
#[derive(Clone, Copy, Debug, Default, serde::Serialize)]
pub struct SolverStats {
    pub steps: usize,
    pub rejected_steps: usize,
    pub rhs_evals: usize,
    pub jacobian_evals: usize,
    pub factorisations: usize,
}

impl SolverStats {
    pub fn add(&mut self, other: &SolverStats) {
        self.steps += other.steps;
        self.rejected_steps += other.rejected_steps;
        self.rhs_evals += other.rhs_evals;
        self.jacobian_evals += other.jacobian_evals;
        self.factorisations += other.factorisations;
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

fn rms(x: &[f64], scale: &[f64]) -> f64 {
    let s: f64 = x.iter().zip(scale).map(|(a, b)| (a / b) * (a / b)).sum();
    (s / x.len() as f64).sqrt()
}

/// Root mean square of `c x` weighted by `w = 1 / scale`.
fn weighted_rms(c: f64, x: &[f64], w: &[f64]) -> f64 {
    let s: f64 = x.iter().zip(w).map(|(a, b)| (a * b) * (a * b)).sum();
    c.abs() * (s / x.len() as f64).sqrt()
}

/// Error weights `1 / (atol + rtol |y|)`.
fn set_weights(w: &mut [f64], atol: &[f64], rtol: f64, y: &[f64]) {
    for ((w, a), y) in w.iter_mut().zip(atol).zip(y) {
        *w = 1.0 / (a + rtol * y.abs());
    }
}

/// Rescales the difference array `d` for a step-size change by `factor`, using `scratch`
/// (at least `order + 1` rows of length n) as work space.
fn change_d(d: &mut [Vec<f64>], scratch: &mut [Vec<f64>], order: usize, factor: f64) {
    let r = compute_r(order, factor);
    let u = compute_r(order, 1.0);
    // RU = R * U; D[:order+1] = RU^T D[:order+1]
    let k = order + 1;
    let mut ru = [0.0; (MAX_ORDER + 1) * (MAX_ORDER + 1)];
    for i in 0..k {
        for j in 0..k {
            ru[i * k + j] = (0..k).map(|m| r[i * k + m] * u[m * k + j]).sum();
        }
    }
    for (j, row) in scratch.iter_mut().enumerate().take(k) {
        row.iter_mut().for_each(|v| *v = 0.0);
        for i in 0..k {
            let w = ru[i * k + j];
            if w != 0.0 {
                for (a, b) in row.iter_mut().zip(&d[i]) {
                    *a += w * b;
                }
            }
        }
    }
    for j in 0..k {
        std::mem::swap(&mut d[j], &mut scratch[j]);
    }
}

fn compute_r(order: usize, factor: f64) -> Vec<f64> {
    let k = order + 1;
    let mut m = vec![0.0; k * k];
    for j in 0..k {
        m[j] = 1.0;
    }
    for i in 1..k {
        for j in 1..k {
            m[i * k + j] = (i as f64 - 1.0 - factor * j as f64) / i as f64;
        }
    }
    // cumulative product down the columns
    for i in 1..k {
        for j in 0..k {
            m[i * k + j] *= m[(i - 1) * k + j];
        }
    }
    m
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
    let n = dae.len();
    let mass = dae.mass();
    let state_scale = dae.scale();
    let atol: Vec<f64> = state_scale.iter().map(|s| opts.atol * s).collect();
    let rtol = opts.rtol;
    // Newton stops when the estimated remaining correction is below this fraction of the
    // error weights (SciPy's value at loose rtol; CVODE allows ~0.1). Tighter values only add
    // iterations and, through slower convergence tests, Jacobian evaluations.
    let newton_tol = (10.0 * f64::EPSILON / rtol).max(NEWTON_TOL);

    let mut gamma = [0.0; MAX_ORDER + 1];
    for k in 1..=MAX_ORDER {
        gamma[k] = gamma[k - 1] + 1.0 / k as f64;
    }
    let alpha: Vec<f64> = (0..=MAX_ORDER).map(|k| (1.0 - KAPPA[k]) * gamma[k]).collect();
    let error_const: Vec<f64> =
        (0..=MAX_ORDER).map(|k| KAPPA[k] * gamma[k] + 1.0 / (k + 1) as f64).collect();

    let mut t = t0;
    let span = t_end - t0;
    if span <= 0.0 {
        return Ok(StopReason::EndTime);
    }
    let mut f0 = vec![0.0; n];
    dae.rhs(t, y0, &mut f0);
    stats.rhs_evals += 1;
    if f0.iter().any(|v| !v.is_finite()) {
        return Err(Error::Solver { t, reason: "non-finite right-hand side at start".into() });
    }
    let fdiff: Vec<f64> = f0.iter().zip(mass).map(|(f, m)| f * m).collect();

    // Initial step (Hairer, Norsett & Wanner, with algebraic rows masked).
    let scale0: Vec<f64> = y0.iter().zip(&atol).map(|(y, a)| a + rtol * y.abs()).collect();
    let d0 = rms(y0, &scale0);
    let d1 = rms(&fdiff, &scale0);
    let h0 = if d0 < 1e-5 || d1 < 1e-5 { 1e-6 } else { 0.01 * d0 / d1 };
    let h0 = h0.min(span);
    let y1: Vec<f64> = y0.iter().zip(&fdiff).map(|(y, f)| y + h0 * f).collect();
    let mut f1 = vec![0.0; n];
    dae.rhs(t + h0, &y1, &mut f1);
    stats.rhs_evals += 1;
    let df: Vec<f64> =
        f1.iter().zip(&fdiff).zip(mass).map(|((a, b), m)| (a * m - b) / h0).collect();
    let d2 = rms(&df, &scale0);
    let h1 = if d1 <= 1e-15 && d2 <= 1e-15 {
        (h0 * 1e-3).max(1e-6)
    } else {
        (0.01 / d1.max(d2)).powf(0.5)
    };
    let mut h_abs = (100.0 * h0).min(h1).min(opts.max_step).min(span);

    let mut d: Vec<Vec<f64>> = vec![vec![0.0; n]; MAX_ORDER + 3];
    let mut d_scratch: Vec<Vec<f64>> = vec![vec![0.0; n]; MAX_ORDER + 1];
    d[0].copy_from_slice(y0);
    for i in 0..n {
        d[1][i] = fdiff[i] * h_abs;
    }
    let mut order = 1usize;
    let mut n_equal_steps = 0usize;
    let mut lu_valid = false;
    let mut lu_c = 0.0;
    let mut jac_current = false;
    let mut have_jac = false;
    // Convergence rate of the last Newton iteration on the current Newton matrix (CVODE's
    // `crate`): it lets a step whose first correction is already small stop after one
    // iteration. Forgotten whenever the matrix changes.
    let mut rate_memory: Option<f64> = None;

    let mut f = vec![0.0; n];
    let mut rhs = vec![0.0; n];
    let mut y_pred = vec![0.0; n];
    let mut psi = vec![0.0; n];
    let mut y_new = vec![0.0; n];
    let mut dvec = vec![0.0; n];
    // Error weights 1 / (atol + rtol |y|) of the current step.
    let mut weight = vec![0.0; n];
    let mut g_old = event.map(|g| g(t, y0));
    let mut steps = 0usize;

    loop {
        let min_step = 10.0 * (t.abs() * f64::EPSILON).max(f64::MIN_POSITIVE);
        if h_abs > opts.max_step {
            change_d(&mut d, &mut d_scratch, order, opts.max_step / h_abs);
            h_abs = opts.max_step;
            n_equal_steps = 0;
        }
        let mut accepted = false;
        let mut h = h_abs;
        let mut t_new = t;
        let mut n_iter;
        let mut error_norm = 0.0;
        let mut safety = 0.9;
        while !accepted {
            if h_abs < min_step {
                return Err(Error::Solver { t, reason: "step size fell below its minimum".into() });
            }
            t_new = t + h_abs;
            // Snap to the end rather than leave a sliver of a step.
            if t_new >= t_end - 1e-3 * h_abs {
                t_new = t_end;
                change_d(&mut d, &mut d_scratch, order, (t_new - t) / h_abs);
                n_equal_steps = 0;
            }
            h = t_new - t;
            h_abs = h;
            y_pred.copy_from_slice(&d[0]);
            psi.iter_mut().for_each(|v| *v = 0.0);
            for k in 1..=order {
                let w = gamma[k] / alpha[order];
                for ((yp, ps), dk) in y_pred.iter_mut().zip(psi.iter_mut()).zip(&d[k]) {
                    *yp += dk;
                    *ps += w * dk;
                }
            }
            set_weights(&mut weight, &atol, rtol, &y_pred);
            let c = h / alpha[order];
            let mut converged;
            loop {
                if !have_jac {
                    let mut g = |yy: &[f64], out: &mut [f64]| dae.rhs(t_new, yy, out);
                    dae.rhs(t_new, &y_pred, &mut f);
                    ws.pattern.evaluate(&mut g, &y_pred, &f, state_scale, &mut ws.jac);
                    stats.rhs_evals += 1 + ws.pattern.n_colours();
                    stats.jacobian_evals += 1;
                    have_jac = true;
                    jac_current = true;
                    lu_valid = false;
                }
                // The Newton matrix M - c J is kept while c drifts by less than 30 %
                // (as CVODE does); a stale c only slows the modified Newton iteration.
                if !lu_valid || (c / lu_c - 1.0).abs() > MAX_GAMMA_DRIFT {
                    ws.system.factorise(mass, c, &ws.jac)?;
                    stats.factorisations += 1;
                    lu_valid = true;
                    lu_c = c;
                    rate_memory = None;
                }
                // Newton iteration on M (psi + d) - c f(y_pred + d) = 0.
                y_new.copy_from_slice(&y_pred);
                dvec.iter_mut().for_each(|v| *v = 0.0);
                let mut dy_norm_old: Option<f64> = None;
                converged = false;
                n_iter = 0;
                for k in 0..NEWTON_MAXITER {
                    n_iter = k + 1;
                    dae.rhs(t_new, &y_new, &mut f);
                    stats.rhs_evals += 1;
                    let mut finite = true;
                    for ((((r, fi), m), ps), dv) in rhs.iter_mut().zip(&f).zip(mass).zip(&psi).zip(&dvec) {
                        finite &= fi.is_finite();
                        *r = c * fi - m * (ps + dv);
                    }
                    if !finite {
                        break;
                    }
                    ws.system.solve(&mut rhs);
                    let dy_norm = weighted_rms(1.0, &rhs, &weight);
                    let rate = dy_norm_old.map(|old| dy_norm / old);
                    if let Some(r) = rate {
                        if r >= 1.0
                            || r.powi((NEWTON_MAXITER - k) as i32) / (1.0 - r) * dy_norm > newton_tol
                        {
                            break;
                        }
                    }
                    for ((yn, dv), r) in y_new.iter_mut().zip(dvec.iter_mut()).zip(&rhs) {
                        *yn += r;
                        *dv += r;
                    }
                    if let Some(r) = rate {
                        rate_memory = Some(r);
                    }
                    // The first iteration may stop on the remembered rate, but only if its
                    // correction is within the error weights: a large first correction with a
                    // stale rate can leave the algebraic states loosely solved, and the next
                    // steps then shrink without end trying to absorb that inconsistency. Without
                    // a remembered rate (a new matrix) the correction itself must be below the
                    // tolerance, as CVODE does with its rate reset to 1.
                    let rate_est = match k {
                        0 if dy_norm <= 1.0 => rate_memory,
                        0 => None,
                        _ => rate,
                    };
                    if dy_norm == 0.0
                        || rate_est.is_some_and(|r| r < 1.0 && r / (1.0 - r) * dy_norm < newton_tol)
                        || (k == 0 && rate_memory.is_none() && dy_norm < newton_tol)
                    {
                        converged = true;
                        break;
                    }
                    dy_norm_old = Some(dy_norm);
                }
                if converged || jac_current {
                    break;
                }
                // First refactorise a Newton matrix built for an older step size; only if
                // that fails too is the Jacobian itself re-evaluated.
                if lu_c != c {
                    lu_valid = false;
                    continue;
                }
                have_jac = false;
            }
            if !converged {
                h_abs *= 0.5;
                change_d(&mut d, &mut d_scratch, order, 0.5);
                n_equal_steps = 0;
                lu_valid = false;
                stats.rejected_steps += 1;
                continue;
            }
            safety = 0.9 * (2 * NEWTON_MAXITER + 1) as f64 / (2 * NEWTON_MAXITER + n_iter) as f64;
            set_weights(&mut weight, &atol, rtol, &y_new);
            error_norm = weighted_rms(error_const[order], &dvec, &weight);
            if error_norm > 1.0 {
                let factor = MIN_FACTOR.max(safety * error_norm.powf(-1.0 / (order as f64 + 1.0)));
                h_abs *= factor;
                change_d(&mut d, &mut d_scratch, order, factor);
                n_equal_steps = 0;
                stats.rejected_steps += 1;
            } else {
                accepted = true;
            }
        }
        let t_old = t;
        t = t_new;
        steps += 1;
        stats.steps += 1;
        jac_current = false;
        n_equal_steps += 1;
        // Update the difference array.
        {
            let (lo, hi) = d.split_at_mut(order + 2);
            for ((next, last), dv) in hi[0].iter_mut().zip(lo[order + 1].iter_mut()).zip(&dvec) {
                *next = dv - *last;
                *last = *dv;
            }
        }
        for k in (0..=order).rev() {
            let (lo, hi) = d.split_at_mut(k + 1);
            for (a, b) in lo[k].iter_mut().zip(&hi[0]) {
                *a += b;
            }
        }
        let dense = DenseOutput { t, h, order, d: &d, end: t };
        // Event location on the interpolant (Illinois false position).
        if let (Some(g), Some(go)) = (event, g_old) {
            let g_new = g(t, &d[0]);
            if go.signum() != g_new.signum() && g_new != go {
                let mut buf = vec![0.0; n];
                let (mut ta, mut ga, mut tb, mut gb) = (t_old, go, t, g_new);
                let mut side = 0i32;
                for _ in 0..100 {
                    // False position, falling back to bisection where g is not finite
                    // (e.g. the voltage of a depleted particle).
                    let tc = match (ta * gb - tb * ga) / (gb - ga) {
                        x if x.is_finite() && x > ta.min(tb) && x < ta.max(tb) => x,
                        _ => 0.5 * (ta + tb),
                    };
                    dense.eval(tc, &mut buf);
                    let gc = g(tc, &buf);
                    if gc.signum() == gb.signum() {
                        tb = tc;
                        gb = gc;
                        if side == -1 {
                            ga *= 0.5;
                        }
                        side = -1;
                    } else {
                        ta = tc;
                        ga = gc;
                        if side == 1 {
                            gb *= 0.5;
                        }
                        side = 1;
                    }
                    if (tb - ta).abs() <= 1e-12 * t.abs().max(1.0) || gc == 0.0 {
                        break;
                    }
                }
                let t_event = if ga.abs() < gb.abs() { ta } else { tb };
                observer(t_old, &DenseOutput { t, h, order, d: &d, end: t_event });
                dense.eval(t_event, y0);
                return Ok(StopReason::Event(t_event));
            }
            g_old = Some(g_new);
        }
        observer(t_old, &dense);
        if t >= t_end {
            y0.copy_from_slice(&d[0]);
            return Ok(StopReason::EndTime);
        }
        if steps >= opts.max_steps {
            return Err(Error::Solver { t, reason: format!("exceeded {} steps", opts.max_steps) });
        }
        if n_equal_steps < order + 1 {
            continue;
        }
        let error_m_norm =
            if order > 1 { weighted_rms(error_const[order - 1], &d[order], &weight) } else { f64::INFINITY };
        let error_p_norm =
            if order < MAX_ORDER { weighted_rms(error_const[order + 1], &d[order + 2], &weight) } else { f64::INFINITY };
        let norms = [error_m_norm, error_norm, error_p_norm];
        let mut best = 0;
        let mut best_factor = f64::NEG_INFINITY;
        for (k, e) in norms.iter().enumerate() {
            let fac = e.powf(-1.0 / (order + k) as f64);
            let fac = if fac.is_nan() { 0.0 } else { fac };
            if fac > best_factor {
                best_factor = fac;
                best = k;
            }
        }
        order = (order as isize + best as isize - 1) as usize;
        let factor = MAX_FACTOR.min(safety * best_factor);
        h_abs *= factor;
        change_d(&mut d, &mut d_scratch, order, factor);
        n_equal_steps = 0;
    }
}
