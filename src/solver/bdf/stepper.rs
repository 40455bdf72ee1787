//! [`Bdf`]: the BDF/NDF stepper. It holds the DAE, the work space, the settings, the
//! backward-difference array, the step size and order, and the work counters; [`Bdf::step`]
//! takes one accepted step and [`Bdf::dense`] interpolates it.

use super::control::{self, Coefficients, set_weights, weighted_rms};
use super::differences::{Differences, Prediction};
use super::newton::{NEWTON_MAXITER, Newton};
use super::{Dae, DenseOutput, SolverOptions, SolverStats, Workspace};
use crate::error::Error;

/// What one call of [`Bdf::step`] did.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct StepInfo {
    /// Start of the step (s).
    pub t_old: f64,
    /// End of the step (s).
    pub t: f64,
    /// Step size (s).
    pub h: f64,
    /// Order of the method on this step (1-5).
    pub order: usize,
}

/// Variable-order, variable-step BDF/NDF stepper for `M y' = f(t, y)` from `t0` to a stop time.
pub struct Bdf<'a> {
    pub(super) opts: &'a SolverOptions,
    /// Absolute tolerance of each state (its scale times `opts.atol`).
    atol: Vec<f64>,
    coeffs: Coefficients,
    d: Differences,
    pred: Prediction,
    newton: Newton<'a>,
    /// Error weights 1 / (atol + rtol |y|) of the current step.
    weight: Vec<f64>,
    /// The DAE's accumulating states when `opts.accumulator_tolerance` tightens them (their
    /// weights are divided by it), else empty.
    accumulating: Vec<usize>,
    /// Time (s) of the state `d[0]`.
    t: f64,
    /// The stop time (s): steps end on it rather than pass it.
    t_stop: f64,
    /// The DAE's breakpoints (s, increasing) from the first after the current time on:
    /// steps end on them rather than pass them.
    breaks: &'a [f64],
    /// Accepted steps since one ended on a breakpoint (`usize::MAX` before any did).
    since_break: usize,
    /// Size (s) of the last accepted step.
    h: f64,
    /// Size (s) of the next step to try.
    h_abs: f64,
    order: usize,
    /// Steps taken since the last change of step size or order.
    n_equal_steps: usize,
    /// Weighted error estimate and step-change safety factor of the last accepted step.
    error_norm: f64,
    safety: f64,
    /// The step size and order are yet to be adapted to the last accepted step.
    adapt_pending: bool,
    stats: SolverStats,
}

impl<'a> Bdf<'a> {
    /// A stepper at `(t0, y0)` bound for `t_stop` (s), its first step chosen from the
    /// derivative there. `y0` must be consistent (algebraic rows satisfied).
    pub fn new(
        dae: &'a dyn Dae,
        ws: &'a mut Workspace,
        opts: &'a SolverOptions,
        t0: f64,
        y0: &[f64],
        t_stop: f64,
    ) -> Result<Self, Error> {
        let n = dae.len();
        let span = t_stop - t0;
        if span <= 0.0 {
            return Err(Error::Solver { t: t0, reason: "the stop time is not after the start".into() });
        }
        let mut stats = SolverStats::default();
        let atol: Vec<f64> = dae.scale().iter().map(|s| opts.atol * s).collect();
        let mut f0 = vec![0.0; n];
        dae.rhs(t0, y0, &mut f0);
        stats.rhs_evals += 1;
        if f0.iter().any(|v| !v.is_finite()) {
            return Err(Error::Solver { t: t0, reason: "non-finite right-hand side at start".into() });
        }
        let fdiff: Vec<f64> = f0.iter().zip(dae.mass()).map(|(f, m)| f * m).collect();
        let breaks = dae.breakpoints();
        let breaks = &breaks[breaks.partition_point(|&b| b <= t0)..];
        let h_abs = control::initial_step(dae, t0, y0, &fdiff, &atol, opts, next_end(breaks, t_stop) - t0, &mut stats);
        Ok(Self {
            opts,
            atol,
            coeffs: Coefficients::new(),
            d: Differences::new(y0, fdiff.iter().map(|f| f * h_abs)),
            pred: Prediction::new(n),
            newton: Newton::new(dae, ws, opts.rtol),
            weight: vec![0.0; n],
            accumulating: if opts.accumulator_tolerance < 1.0 { dae.accumulating_states() } else { Vec::new() },
            t: t0,
            t_stop,
            breaks,
            since_break: usize::MAX,
            h: 0.0,
            h_abs,
            order: 1,
            n_equal_steps: 0,
            error_norm: 0.0,
            safety: 0.9,
            adapt_pending: false,
            stats,
        })
    }

    /// Time (s) of the current state.
    pub fn t(&self) -> f64 {
        self.t
    }

    /// The current state.
    pub fn state(&self) -> &[f64] {
        &self.d.d[0]
    }

    /// The stop time (s).
    pub fn t_stop(&self) -> f64 {
        self.t_stop
    }

    /// Order of the last accepted step (1 before the first).
    pub fn order(&self) -> usize {
        self.order
    }

    /// Work done since the stepper was built.
    pub fn stats(&self) -> &SolverStats {
        &self.stats
    }

    /// The interpolant of the last accepted step, valid on `[t - h, t]`; meaningless before
    /// the first step.
    pub fn dense(&self) -> DenseOutput<'_> {
        DenseOutput { t: self.t, h: self.h, order: self.order, d: &self.d.d, end: self.t }
    }

    /// Takes one step, retrying with smaller steps until one passes the error test; the step
    /// ends on the stop time rather than pass it. Fails when the step size falls below round-off
    /// in `t`, a Newton matrix cannot be factorised, or the stop time is already reached.
    pub fn step(&mut self) -> Result<StepInfo, Error> {
        let t = self.t;
        if t >= self.t_stop {
            return Err(Error::Solver { t, reason: "the stop time is already reached".into() });
        }
        if self.adapt_pending {
            self.adapt_pending = false;
            self.adapt();
        }
        let (order, max_step) = (self.order, self.opts.max_step);
        let min_step = 10.0 * (t.abs() * f64::EPSILON).max(f64::MIN_POSITIVE);
        if self.h_abs > max_step {
            self.d.rescale(order, max_step / self.h_abs);
            self.h_abs = max_step;
            self.n_equal_steps = 0;
        }
        loop {
            if self.h_abs < min_step {
                return Err(Error::Solver { t, reason: "step size fell below its minimum".into() });
            }
            let mut t_new = t + self.h_abs;
            // Snap to the next breakpoint or the end rather than pass it or leave a sliver of a
            // step. A step that already ends there (a breakpoint every step) keeps its size.
            let limit = next_end(self.breaks, self.t_stop);
            if t_new >= limit - 1e-3 * self.h_abs {
                t_new = limit;
                let factor = (t_new - t) / self.h_abs;
                if factor != 1.0 {
                    self.d.rescale(order, factor);
                }
                if (factor - 1.0).abs() > 1e-9 {
                    self.n_equal_steps = 0;
                }
            }
            let h = t_new - t;
            self.h_abs = h;
            self.d.predict(order, &self.coeffs, &mut self.pred);
            set_weights(&mut self.weight, &self.atol, self.opts.rtol, &self.pred.y, &self.accumulating, 1.0 / self.opts.accumulator_tolerance);
            let c = h / self.coeffs.alpha[order];
            let solved = self.newton.solve(t_new, c, &self.pred, &self.weight, &mut self.stats)?;
            let Some(n_iter) = solved else {
                self.h_abs *= 0.5;
                self.d.rescale(order, 0.5);
                self.n_equal_steps = 0;
                self.newton.invalidate_matrix();
                self.stats.rejected_steps += 1;
                continue;
            };
            self.safety = control::safety(n_iter, NEWTON_MAXITER);
            set_weights(&mut self.weight, &self.atol, self.opts.rtol, &self.newton.y_new, &self.accumulating, 1.0 / self.opts.accumulator_tolerance);
            // An algebraic state's slope jumps at a breakpoint, so while the predictor still
            // extrapolates from points before it, the corrector's distance from the prediction
            // is no error estimate for those rows; the corrector has solved them exactly given
            // the differential states, whose error the test still bounds.
            if self.since_break < order {
                for (w, &m) in self.weight.iter_mut().zip(self.newton.mass) {
                    if m == 0.0 {
                        *w = 0.0;
                    }
                }
            }
            self.error_norm = weighted_rms(self.coeffs.error_const[order], &self.newton.dvec, &self.weight);
            if self.error_norm > 1.0 {
                let factor = control::rejection_factor(self.safety, self.error_norm, order);
                self.h_abs *= factor;
                self.d.rescale(order, factor);
                self.n_equal_steps = 0;
                self.stats.rejected_steps += 1;
                self.stats.error_test_failures += 1;
                continue;
            }
            self.t = t_new;
            self.h = h;
            let passed = self.breaks.partition_point(|&b| b <= t_new);
            self.since_break = if passed > 0 { 0 } else { self.since_break.saturating_add(1) };
            self.breaks = &self.breaks[passed..];
            self.stats.steps += 1;
            self.newton.age_jacobian();
            self.n_equal_steps += 1;
            self.d.accept(order, &self.newton.dvec);
            self.adapt_pending = true;
            return Ok(StepInfo { t_old: t, t: t_new, h, order });
        }
    }

    /// After `order + 1` equal steps, moves to the order (one down, same, one up) that allows
    /// the largest next step, and scales the step size accordingly. Deferred from the end of
    /// a step to the start of the next so that [`Bdf::dense`] still sees the step taken.
    fn adapt(&mut self) {
        let order = self.order;
        if self.n_equal_steps < order + 1 {
            return;
        }
        let (d, e, w) = (&self.d.d, &self.coeffs.error_const, &self.weight);
        let error_m_norm = if order > 1 { weighted_rms(e[order - 1], &d[order], w) } else { f64::INFINITY };
        let error_p_norm =
            if order < control::MAX_ORDER { weighted_rms(e[order + 1], &d[order + 2], w) } else { f64::INFINITY };
        let (new_order, factor) = control::choose_order(order, [error_m_norm, self.error_norm, error_p_norm], self.safety);
        self.order = new_order;
        self.h_abs *= factor;
        self.d.rescale(new_order, factor);
        self.n_equal_steps = 0;
    }
}

/// Where the next step must end at the latest (s): the first of `breaks` (the breakpoints
/// still ahead) or the stop time `t_stop`, whichever comes first.
fn next_end(breaks: &[f64], t_stop: f64) -> f64 {
    breaks.first().map_or(t_stop, |&b| b.min(t_stop))
}
