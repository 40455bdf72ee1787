//! The modified Newton solve of one BDF/NDF step, `M (psi + d) - c f(t, y_pred + d) = 0`, and
//! the reuse of its Jacobian and factorised Newton matrix `M - c J` across steps.

use super::control::weighted_sum_squares;
use super::differences::Prediction;
use super::{Dae, SolverStats, Workspace};
use crate::error::Error;

pub(super) const NEWTON_MAXITER: usize = 4;
/// Newton convergence threshold on the weighted correction norm at rtol [`NEWTON_TOL_RTOL`]
/// and below.
const NEWTON_TOL: f64 = 0.03;
const NEWTON_TOL_RTOL: f64 = 1e-6;
/// Largest Newton convergence threshold (IDA's default `epcon`, which PyBaMM's IDAKLU uses at
/// every tolerance).
const NEWTON_TOL_MAX: f64 = 0.1;

/// Newton convergence threshold for relative tolerance `rtol`: [`NEWTON_TOL`] up to rtol
/// 1e-6, then growing as `sqrt(rtol)` (SciPy's `BDF` law, with a 30 times larger constant) up to
/// [`NEWTON_TOL_MAX`] from rtol 1.2e-4. At loose tolerances the steps are long, Newton converges
/// more slowly, and a strict test fails steps that the error test would pass: the DFN at rtol
/// 1e-3 had 39 Newton failures in 58 steps (17 Jacobians, half its right-hand sides) where
/// IDAKLU had 1.
fn newton_tol(rtol: f64) -> f64 {
    (NEWTON_TOL * (rtol / NEWTON_TOL_RTOL).sqrt()).clamp(NEWTON_TOL, NEWTON_TOL_MAX).max(10.0 * f64::EPSILON / rtol)
}
/// Largest relative change of `c = h / alpha` before the Newton matrix is refactorised.
const MAX_GAMMA_DRIFT: f64 = 0.3;

/// Newton iteration state: the DAE and work space, which Jacobian and matrix are held, and
/// the solution of the last solve.
pub(super) struct Newton<'a> {
    dae: &'a dyn Dae,
    ws: &'a mut Workspace,
    /// The DAE's mass-matrix diagonal and its floors of the Jacobian's difference steps.
    pub(super) mass: &'a [f64],
    difference_scale: &'a [f64],
    /// Stopping threshold on the estimated remaining correction, in error weights.
    tol: f64,
    /// A Jacobian has been evaluated (in the work space).
    have_jac: bool,
    /// The Jacobian was evaluated during the current step (re-evaluating it cannot help).
    jac_current: bool,
    /// The factorised Newton matrix matches the Jacobian.
    lu_valid: bool,
    /// The `c` the Newton matrix was factorised with.
    lu_c: f64,
    /// Convergence rate of the last Newton iteration on the current Newton matrix (CVODE's
    /// `crate`): it lets a step whose first correction is already small stop after one
    /// iteration. Forgotten whenever the matrix changes.
    rate_memory: Option<f64>,
    f: Vec<f64>,
    rhs: Vec<f64>,
    /// The corrected state of the last solve.
    pub(super) y_new: Vec<f64>,
    /// The correction `y_new - y_pred` of the last solve.
    pub(super) dvec: Vec<f64>,
}

impl<'a> Newton<'a> {
    /// The state for `dae` at relative tolerance `rtol`, with no Jacobian yet.
    pub(super) fn new(dae: &'a dyn Dae, ws: &'a mut Workspace, rtol: f64) -> Self {
        let n = dae.len();
        Self {
            dae,
            ws,
            mass: dae.mass(),
            difference_scale: dae.difference_scale(),
            // Newton stops when the estimated remaining correction is below this fraction of the
            // error weights. Tighter values only add iterations and, through slower convergence
            // tests, Jacobian evaluations.
            tol: newton_tol(rtol),
            have_jac: false,
            jac_current: false,
            lu_valid: false,
            lu_c: 0.0,
            rate_memory: None,
            f: vec![0.0; n],
            rhs: vec![0.0; n],
            y_new: vec![0.0; n],
            dvec: vec![0.0; n],
        }
    }

    /// Forces a refactorisation at the next solve (after a step-size cut).
    pub(super) fn invalidate_matrix(&mut self) {
        self.lu_valid = false;
    }

    /// Marks the Jacobian as older than the next step (after an accepted step).
    pub(super) fn age_jacobian(&mut self) {
        self.jac_current = false;
    }

    /// Solves the corrector equation at `t_new` (s) with `c = h / alpha` from the prediction
    /// `pred`, measuring corrections in the error weights `weight`. Returns the number of
    /// iterations if it converged (solution in `y_new`, `dvec`), `None` if not even a fresh
    /// Jacobian made it converge.
    pub(super) fn solve(
        &mut self,
        t_new: f64,
        c: f64,
        pred: &Prediction,
        weight: &[f64],
        stats: &mut SolverStats,
    ) -> Result<Option<usize>, Error> {
        let (dae, ws, mass, difference_scale) = (self.dae, &mut *self.ws, self.mass, self.difference_scale);
        let (y_pred, psi) = (&pred.y[..], &pred.psi[..]);
        let (f, rhs, y_new, dvec) = (&mut self.f[..], &mut self.rhs[..], &mut self.y_new[..], &mut self.dvec[..]);
        let mut n_iter = 0;
        // `f` holds `f(t_new, y_pred)`, evaluated for a finite-difference Jacobian: the first
        // Newton iteration, which reads the same point, reuses it.
        let mut f_at_pred = false;
        loop {
            if !self.have_jac {
                let mut g = |yy: &[f64], out: &mut [f64]| dae.rhs(t_new, yy, out);
                dae.rhs(t_new, y_pred, f);
                ws.pattern.evaluate(&mut g, y_pred, f, difference_scale, &mut ws.jac);
                stats.rhs_evals += 1 + ws.pattern.n_colours();
                stats.jacobian_evals += 1;
                ws.system.load_jacobian(&ws.jac);
                f_at_pred = true;
                self.have_jac = true;
                self.jac_current = true;
                self.lu_valid = false;
            }
            // The Newton matrix M - c J is kept while c drifts by less than 30 %
            // (as CVODE does); a stale c only slows the modified Newton iteration.
            if !self.lu_valid || (c / self.lu_c - 1.0).abs() > MAX_GAMMA_DRIFT {
                ws.system.factorise_loaded(mass, c)?;
                stats.factorisations += 1;
                self.lu_valid = true;
                self.lu_c = c;
                self.rate_memory = None;
            }
            // Newton iteration on M (psi + d) - c f(y_pred + d) = 0, from d = 0 (the first
            // iteration reads y_pred and writes y_new and dvec instead of adding to them).
            let mut dy_norm_old: Option<f64> = None;
            let mut converged = false;
            for k in 0..NEWTON_MAXITER {
                n_iter = k + 1;
                if !(k == 0 && f_at_pred) {
                    dae.rhs(t_new, if k == 0 { y_pred } else { y_new }, f);
                    stats.rhs_evals += 1;
                    f_at_pred = k == 0;
                }
                stats.newton_iters += 1;
                // A non-finite right-hand side is caught by the norm of the correction below
                // (it spreads through the solve), so this loop has no test and vectorises.
                if k == 0 {
                    for (((r, fi), m), ps) in rhs.iter_mut().zip(f.iter()).zip(mass).zip(psi) {
                        *r = c * fi - m * (ps + 0.0);
                    }
                } else {
                    for ((((r, fi), m), ps), dv) in rhs.iter_mut().zip(f.iter()).zip(mass).zip(psi).zip(dvec.iter()) {
                        *r = c * fi - m * (ps + dv);
                    }
                }
                ws.system.solve(rhs);
                // The corrected state (left unused if the rate test below stops the
                // iteration), and the norm of the correction.
                if k == 0 {
                    for (((yn, dv), r), yp) in y_new.iter_mut().zip(dvec.iter_mut()).zip(rhs.iter()).zip(y_pred) {
                        *yn = yp + r;
                        *dv = 0.0 + r;
                    }
                } else {
                    for ((yn, dv), r) in y_new.iter_mut().zip(dvec.iter_mut()).zip(rhs.iter()) {
                        *yn += r;
                        *dv += r;
                    }
                }
                let dy_norm = (weighted_sum_squares(rhs, weight) / rhs.len() as f64).sqrt();
                if !dy_norm.is_finite() {
                    break;
                }
                let rate = dy_norm_old.map(|old| dy_norm / old);
                if let Some(r) = rate {
                    if r >= 1.0 || r.powi((NEWTON_MAXITER - k) as i32) / (1.0 - r) * dy_norm > self.tol {
                        break;
                    }
                }
                if let Some(r) = rate {
                    self.rate_memory = Some(r);
                }
                // The first iteration may stop on the remembered rate, but only if its
                // correction is within the error weights: a large first correction with a
                // stale rate can leave the algebraic states loosely solved, and the next
                // steps then shrink without end trying to absorb that inconsistency. Without
                // a remembered rate (a new matrix) the correction itself must be below the
                // tolerance, as CVODE does with its rate reset to 1.
                let rate_est = match k {
                    0 if dy_norm <= 1.0 => self.rate_memory,
                    0 => None,
                    _ => rate,
                };
                if dy_norm == 0.0
                    || rate_est.is_some_and(|r| r < 1.0 && r / (1.0 - r) * dy_norm < self.tol)
                    || (k == 0 && self.rate_memory.is_none() && dy_norm < self.tol)
                {
                    converged = true;
                    break;
                }
                dy_norm_old = Some(dy_norm);
            }
            if converged {
                return Ok(Some(n_iter));
            }
            stats.newton_failures += 1;
            if self.jac_current {
                return Ok(None);
            }
            // First refactorise a Newton matrix built for an older step size; only if
            // that fails too is the Jacobian itself re-evaluated.
            if self.lu_c != c {
                self.lu_valid = false;
                continue;
            }
            self.have_jac = false;
        }
    }
}

