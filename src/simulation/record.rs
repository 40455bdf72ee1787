//! Recording a simulation's outputs: the state, current and voltage at each output time,
//! and the charge and energy over each solver step: by the polynomial through the last step
//! ends when it predicts the step's midpoint, else by adaptive Simpson quadrature on the
//! integrator's interpolant.

use super::{Solution, States};
use super::drive::Driven;
use crate::models::Model;
use crate::solver::DenseOutput;

/// Running totals and recording of outputs.
pub(super) struct Recorder<'a> {
    pub model: &'a dyn Model,
    /// Called at every output with the state and the current (see [`simulate_observed`]).
    pub on_output: &'a mut dyn FnMut(&[f64], f64),
    /// The states that voltage and temperature read ([`Model::output_states`]), as runs of
    /// consecutive indices.
    pub outputs: Vec<std::ops::Range<usize>>,
    pub states: States,
    /// Relative tolerance of the quadrature: the solver's.
    pub rtol: f64,
    /// The energy is integrated beside the charge (else it stays NaN, and the voltage is not
    /// evaluated for it).
    pub energy: bool,
    pub sol: Solution,
    /// Discharged charge (A h) and delivered energy (W h) at the end of the last step.
    pub q: f64,
    pub e: f64,
    /// Current (A) and power (W) at the end of the last step (right limits at a protocol
    /// step start).
    pub i: f64,
    pub p: f64,
    /// (time s, current A, power W) at the last solver step ends since the drive was last
    /// restarted or kinked, oldest first, at most [`HISTORY`]; the last is at `self.i`, `self.p`.
    pub history: Vec<(f64, f64, f64)>,
}

/// Step ends kept for [`history_rule`]: with the interval's midpoint and end, six nodes of a
/// quintic (its Gauss-Legendre rule is exact to degree 7).
const HISTORY: usize = 4;
const _: () = assert!(HISTORY + 2 <= 8);

/// Values at the end of a quadrature interval.
pub(super) struct IntervalEnd {
    /// Charge (A h) and energy (W h) over the interval.
    pub dq: f64,
    pub de: f64,
    pub current: f64,
    pub voltage: f64,
}

impl Recorder<'_> {
    /// Starts a stretch of smooth drive at `t` (s) with current `i` (A) and power `p` (W)
    /// (right limits): forgets the step ends before it.
    pub fn restart(&mut self, t: f64, i: f64, p: f64) {
        let p = if self.energy { p } else { 0.0 };
        self.i = i;
        self.p = p;
        self.history.clear();
        self.history.push((t, i, p));
    }

    /// Adds a solver step that ended at `t` (s) to the totals.
    pub fn advance(&mut self, t: f64, end: &IntervalEnd) {
        self.q += end.dq;
        self.e += end.de;
        self.i = end.current;
        self.p = if self.energy { end.current * end.voltage } else { 0.0 };
        if self.history.len() == HISTORY {
            self.history.remove(0);
        }
        self.history.push((t, self.i, self.p));
    }

    pub fn record(&mut self, t: f64, y: &[f64], i: f64, v: f64, q: f64, e: f64) {
        let y = &y[..self.model.len()];
        let s = &mut self.sol;
        s.time.push(t);
        s.current.push(i);
        s.voltage.push(v);
        s.capacity.push(q);
        s.energy.push(e);
        s.temperature.push(self.model.temperature(y));
        if self.states == States::Kept {
            s.states.push(y.to_vec());
        }
        (self.on_output)(y, i);
    }

    /// Records the state, current and voltage at `t` inside the step of `dense`, with the
    /// charge and energy accumulated to the step's start.
    pub fn sample(&mut self, dense: &DenseOutput, drive: &Driven, t: f64, buf: &mut [f64]) {
        self.state_at(dense, t, buf);
        let i = drive.current(t, buf);
        let v = self.model.voltage(&buf[..self.model.len()], i);
        let (q, e) = (self.q, self.e);
        self.record(t, buf, i, v, q, e);
    }

    /// The current and voltage at a step's end `b` without the charge and energy over the
    /// step (NaN); leaves `y(b)` in `buf` as [`Recorder::integrate_to`] does. `at_b`, when
    /// known, is the current and voltage at `b`.
    pub fn step_end(&self, dense: &DenseOutput, drive: &Driven, b: f64, at_b: Option<(f64, f64)>, buf: &mut [f64]) -> IntervalEnd {
        self.state_at(dense, b, buf);
        let (current, voltage) = at_b.unwrap_or_else(|| {
            let i = drive.current(b, buf);
            (i, self.model.voltage(&buf[..self.model.len()], i))
        });
        IntervalEnd { dq: f64::NAN, de: f64::NAN, current, voltage }
    }

    /// `y(t)` in `buf`: every state when all are observed or kept, else the output states.
    fn state_at(&self, dense: &DenseOutput, t: f64, buf: &mut [f64]) {
        if self.states != States::ForOutputs {
            dense.eval(t, buf);
        } else {
            dense.eval_ranges(t, &self.outputs, buf);
        }
    }

    /// Charge and energy over `[a, b]`, `a` the last step end (current and power `self.i`,
    /// `self.p`); leaves `y(b)` in `buf` (only the output states unless every state is observed or kept).
    /// `at_b`, when known, is the current and voltage at `b` (the cut-off event evaluated them).
    /// Both integrals are held to `rtol` (the solver's: the integral need not be more accurate
    /// than the trajectory it integrates) of their scale over the interval, so long solver
    /// steps on a curved voltage do not bias the energy: first by the polynomial through the
    /// last step ends, the midpoint and `b` ([`history_rule`]: one voltage evaluation inside
    /// the step), else by adaptive Simpson quadrature on the integrator's interpolant (three
    /// or more). `kinks` (s, increasing) are the drive's kinks: the polynomial never spans one.
    pub fn integrate_to(
        &self,
        dense: &DenseOutput,
        drive: &Driven,
        (a, b): (f64, f64),
        at_b: Option<(f64, f64)>,
        kinks: &[f64],
        buf: &mut [f64],
    ) -> IntervalEnd {
        // (current, power); at rest, or without the energy, the power is 0 without evaluating
        // the voltage, and without the energy a current the step gives reads no state.
        let energy = self.energy;
        let mut sample = |t: f64, buf: &mut [f64]| {
            if let Some(i) = drive.given_current(t).filter(|_| !energy) {
                return (i, 0.0);
            }
            dense.eval_ranges(t, &self.outputs, buf);
            let i = drive.current(t, buf);
            (i, if i == 0.0 || !energy { 0.0 } else { i * self.model.voltage(&buf[..self.model.len()], i) })
        };
        let mid = sample(0.5 * (a + b), buf);
        let end = match at_b {
            Some((i, v)) => (i, if energy { i * v } else { 0.0 }),
            None => sample(b, buf),
        };
        // The voltage at `b` from its power, or the event's; else read from y(b) below.
        let voltage = (energy && end.0 != 0.0).then(|| end.1 / end.0).or(at_b.map(|(_, v)| v));
        let smooth = |from: f64| kinks.get(kinks.partition_point(|&k| k <= from)).is_none_or(|&k| k >= b);
        let from_history = match self.history[..] {
            [oldest, _, .., last] if last.0 == a && smooth(oldest.0) => history_rule(&self.history, (0.5 * (a + b), mid.0, mid.1), (b, end.0, end.1), self.rtol, energy),
            _ => None,
        };
        let (dq, de) = match from_history {
            Some(integrals) => integrals,
            None => adaptive_simpson(&mut sample, buf, (a, b), [(self.i, self.p), mid, end], self.rtol, 12),
        };
        // Unless only `b` was sampled (and its state read), restore y(b) in `buf`.
        if from_history.is_none() || at_b.is_some() || self.states != States::ForOutputs || !energy {
            self.state_at(dense, b, buf);
        }
        let voltage = voltage.unwrap_or_else(|| self.model.voltage(&buf[..self.model.len()], end.0));
        let de = if energy { de / 3600.0 } else { f64::NAN };
        IntervalEnd { dq: dq / 3600.0, de, current: end.0, voltage }
    }
}

/// Integrals of current and power (A s, J) over `[a, b]` from the last step ends (time s,
/// current A, power W; oldest first, the last at `a`, at most [`HISTORY`]) and the values at
/// the midpoint and `b`: the polynomial through all of them, when the one through all but the
/// midpoint predicts the midpoint to `tol` of the integrand's scale over the interval (as the
/// step ends carry no sign of a feature between them, the midpoint is looked at); `None`
/// otherwise. Exact for a constant current. Without `energy` the power is not integrated (0).
fn history_rule(nodes: &[(f64, f64, f64)], (m, im, pm): (f64, f64, f64), (b, ib, pb): (f64, f64, f64), tol: f64, energy: bool) -> Option<(f64, f64)> {
    const MAX: usize = HISTORY + 2;
    let n = nodes.len() + 2;
    // Nodes: b, then back in time from a, then the midpoint (last, so that its Newton term is
    // the midpoint's surprise).
    let mut x = [b; MAX];
    let (mut fi, mut fp) = ([ib; MAX], [pb; MAX]);
    for (k, &(t, i, p)) in nodes.iter().rev().enumerate() {
        (x[k + 1], fi[k + 1], fp[k + 1]) = (t, i, p);
    }
    (x[n - 1], fi[n - 1], fp[n - 1]) = (m, im, pm);
    let a = x[1];
    let h = b - a;
    // Integrals over [a, b] of the Newton basis (x - x0)...(x - x_{k-1}), by 4-point
    // Gauss-Legendre (exact to degree 7), and the last basis function at the midpoint.
    let (r1, r2) = ((3.0 / 7.0 - 2.0 / 7.0 * 1.2f64.sqrt()).sqrt(), (3.0 / 7.0 + 2.0 / 7.0 * 1.2f64.sqrt()).sqrt());
    let (w1, w2) = ((18.0 + 30f64.sqrt()) / 72.0, (18.0 - 30f64.sqrt()) / 72.0);
    let gauss = [(-r2, w2), (-r1, w1), (r1, w1), (r2, w2)];
    let mut basis = [0.0; MAX];
    for (s, w) in gauss {
        let t = a + 0.5 * (1.0 + s) * h;
        let mut product = h * w;
        for k in 0..n {
            basis[k] += product;
            product *= t - x[k];
        }
    }
    let at_mid: f64 = x[..n - 1].iter().map(|xk| m - xk).product();
    let integral = |mut c: [f64; MAX]| {
        // The integrand's size at b and a (c[0], c[1] before the differences).
        let scale = h * (c[0].abs() + c[1].abs() + 1e-12);
        for j in 1..n {
            for k in (j..n).rev() {
                c[k] = (c[k] - c[k - 1]) / (x[k] - x[k - j]);
            }
        }
        let surprise = c[n - 1] * at_mid;
        (surprise.abs() * h <= tol * scale).then(|| c[..n].iter().zip(&basis).map(|(c, w)| c * w).sum())
    };
    Some((integral(fi)?, if energy { integral(fp)? } else { 0.0 }))
}

/// Adaptive Simpson quadrature of (current, power) over `[a, b]` given the samples at `a`,
/// the midpoint and `b`, to relative tolerance `tol`; returns (A s, J).
fn adaptive_simpson(
    sample: &mut dyn FnMut(f64, &mut [f64]) -> (f64, f64),
    buf: &mut [f64],
    (a, b): (f64, f64),
    [fa, fm, fb]: [(f64, f64); 3],
    tol: f64,
    depth: usize,
) -> (f64, f64) {
    let h = b - a;
    let whole = (h / 6.0 * (fa.0 + 4.0 * fm.0 + fb.0), h / 6.0 * (fa.1 + 4.0 * fm.1 + fb.1));
    let m = 0.5 * (a + b);
    let fl = sample(0.5 * (a + m), buf);
    let fr = sample(0.5 * (m + b), buf);
    let left = (h / 12.0 * (fa.0 + 4.0 * fl.0 + fm.0), h / 12.0 * (fa.1 + 4.0 * fl.1 + fm.1));
    let right = (h / 12.0 * (fm.0 + 4.0 * fr.0 + fb.0), h / 12.0 * (fm.1 + 4.0 * fr.1 + fb.1));
    let halves = (left.0 + right.0, left.1 + right.1);
    // Tolerances relative to the size of the integrand over the interval.
    let scale_q = h * (fa.0.abs() + fb.0.abs() + 1e-12);
    let scale_e = h * (fa.1.abs() + fb.1.abs() + 1e-12);
    let converged = (halves.0 - whole.0).abs() <= tol * scale_q && (halves.1 - whole.1).abs() <= tol * scale_e;
    if converged || depth == 0 {
        // Richardson extrapolation of the two Simpson estimates.
        return (halves.0 + (halves.0 - whole.0) / 15.0, halves.1 + (halves.1 - whole.1) / 15.0);
    }
    let l = adaptive_simpson(sample, buf, (a, m), [fa, fl, fm], tol, depth - 1);
    let r = adaptive_simpson(sample, buf, (m, b), [fm, fr, fb], tol, depth - 1);
    (l.0 + r.0, l.1 + r.1)
}

