//! Recording a simulation's outputs: the state, current and voltage at each output time,
//! and the charge and energy by adaptive Simpson quadrature on the integrator's interpolant.

use super::Solution;
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
    pub keep_states: bool,
    /// Relative tolerance of the energy quadrature: the solver's.
    pub rtol: f64,
    pub sol: Solution,
    /// Discharged charge (A h) and delivered energy (W h) at the end of the last step.
    pub q: f64,
    pub e: f64,
    /// Current (A) and power (W) at the end of the last step (right limits at a protocol
    /// step start).
    pub i: f64,
    pub p: f64,
}

/// Values at the end of a quadrature interval.
pub(super) struct IntervalEnd {
    /// Charge (A h) and energy (W h) over the interval.
    pub dq: f64,
    pub de: f64,
    pub current: f64,
    pub voltage: f64,
}

impl Recorder<'_> {
    pub fn record(&mut self, t: f64, y: &[f64], i: f64, v: f64, q: f64, e: f64) {
        let y = &y[..self.model.len()];
        let s = &mut self.sol;
        s.time.push(t);
        s.current.push(i);
        s.voltage.push(v);
        s.capacity.push(q);
        s.energy.push(e);
        s.temperature.push(self.model.temperature(y));
        if self.keep_states {
            s.states.push(y.to_vec());
        }
        (self.on_output)(y, i);
    }

    /// Charge and energy over `[a, b]` by adaptive Simpson quadrature on the interpolant, from
    /// the current and power (`self.i`, `self.p`) at `a`; leaves `y(b)` in `buf` (only the
    /// output states unless every state is kept). A step is
    /// halved until the two halves agree with the whole to `rtol` (the solver's: the integral
    /// need not be more accurate than the trajectory it integrates) of the charge and energy
    /// scales, so long solver steps on a curved voltage do not bias the energy.
    /// `at_b`, when known, is the current and voltage at `b` (the cut-off event evaluated them).
    /// Records the state, current and voltage at `t` inside the step of `dense`, with the
    /// charge and energy accumulated to the step's start.
    pub fn sample(&mut self, dense: &DenseOutput, drive: &Driven, t: f64, buf: &mut [f64]) {
        if self.keep_states {
            dense.eval(t, buf);
        } else {
            dense.eval_ranges(t, &self.outputs, buf);
        }
        let i = drive.current(t, buf);
        let v = self.model.voltage(&buf[..self.model.len()], i);
        let (q, e) = (self.q, self.e);
        self.record(t, buf, i, v, q, e);
    }

    pub fn integrate_to(
        &self,
        dense: &DenseOutput,
        drive: &Driven,
        (a, b): (f64, f64),
        at_b: Option<(f64, f64)>,
        buf: &mut [f64],
    ) -> IntervalEnd {
        let mut sample = |t: f64, buf: &mut [f64]| {
            dense.eval_ranges(t, &self.outputs, buf);
            let i = drive.current(t, buf);
            (i, i * self.model.voltage(&buf[..self.model.len()], i))
        };
        let mid = sample(0.5 * (a + b), buf);
        let end = match at_b {
            Some((i, v)) => (i, i * v),
            None => sample(b, buf),
        };
        let voltage = if end.0 != 0.0 { end.1 / end.0 } else { self.model.voltage(&buf[..self.model.len()], 0.0) };
        let (dq, de) = adaptive_simpson(&mut sample, buf, (a, b), [(self.i, self.p), mid, end], self.rtol, 12);
        // `buf` was overwritten by interior samples: restore y(b).
        if self.keep_states {
            dense.eval(b, buf);
        } else {
            dense.eval_ranges(b, &self.outputs, buf);
        }
        IntervalEnd { dq: dq / 3600.0, de: de / 3600.0, current: end.0, voltage }
    }
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
