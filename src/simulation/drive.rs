//! The electrical drive of a protocol step: the current a step applies to a model (given,
//! from a power demand, or the held state of a voltage hold), and the model as a DAE under it.

use crate::models::Model;
use crate::protocol::{Demand, Step};
use crate::solver::Dae;

/// A model driven by one protocol step's current.
pub(super) struct Driven<'a> {
    pub model: &'a dyn Model,
    pub step: &'a Step,
    pub t0: f64,
    pub capacity: f64,
}

impl Driven<'_> {
    /// Current (A) at time `t` in state `y`: the step's current, for a power step the
    /// smallest root of `I V(y, I) = P`, for a voltage hold the state after the model's.
    pub(super) fn current(&self, t: f64, y: &[f64]) -> f64 {
        match self.step.demand_at(t - self.t0, self.capacity) {
            Demand::Current(i) => i,
            Demand::Power(p) => self.current_for_power(p, y),
            Demand::Voltage(_) => y[self.model.len()],
        }
    }

    /// The current (A) at time `t` when the step gives it, independent of the state; `None`
    /// for a power demand or a voltage hold.
    pub(super) fn given_current(&self, t: f64) -> Option<f64> {
        match self.step.demand_at(t - self.t0, self.capacity) {
            Demand::Current(i) => Some(i),
            _ => None,
        }
    }

    /// Fixed-point iteration `I <- P / V(y, I)` (it contracts while `|I dV/dI| < V`), with a
    /// bracketing fallback near the maximum-power point. When the cell cannot deliver `P`,
    /// the current of maximum power is returned, as a power-limited cycler would do: the
    /// voltage then falls through the cut-off and the step ends there.
    fn current_for_power(&self, p: f64, y: &[f64]) -> f64 {
        let sign = p.signum();
        // Work with |P| on the discharge or charge branch: I = sign * x, x >= 0.
        let g = |x: f64| sign * x * self.model.voltage(y, sign * x) - p.abs();
        let v0 = self.model.voltage(y, 0.0);
        let mut x = p.abs() / v0;
        for _ in 0..30 {
            let next = p.abs() / (sign * self.model.voltage(y, sign * x));
            if !next.is_finite() || next < 0.0 {
                break;
            }
            let done = (next - x).abs() <= 1e-13 * (1.0 + x);
            x = next;
            if done {
                return sign * x;
            }
        }
        // Expand a bracket from zero while the delivered power still rises.
        let (mut lo, mut hi) = (0.0, p.abs() / v0);
        let (mut glo, mut ghi) = (g(lo), g(hi));
        while ghi < 0.0 && ghi > glo && hi < 1e6 {
            lo = hi;
            glo = ghi;
            hi *= 1.5;
            ghi = g(hi);
        }
        if ghi >= 0.0 {
            for _ in 0..200 {
                let mid = 0.5 * (lo + hi);
                if g(mid) >= 0.0 { hi = mid } else { lo = mid }
                if hi - lo <= 1e-13 * (1.0 + hi) {
                    break;
                }
            }
            return sign * 0.5 * (lo + hi);
        }
        // Not deliverable: golden-section search for the maximum-power current.
        let (mut a, mut b) = (0.0, hi);
        let r = 0.5 * (5f64.sqrt() - 1.0);
        for _ in 0..80 {
            let (c, d) = (b - r * (b - a), a + r * (b - a));
            if g(c) > g(d) { b = d } else { a = c }
        }
        sign * 0.5 * (a + b)
    }
}

/// A model as a DAE for the integrator, under the applied current `current(t, y)` (A) whose
/// kinks in time are at `kinks` (s, increasing).
pub(crate) struct UnderCurrent<'a, F> {
    pub model: &'a dyn Model,
    pub current: F,
    pub kinks: Vec<f64>,
    /// The rows that follow a recorded temperature ([`Model::temperature_rows`]) and the
    /// recording (times s, K).
    pub temperature: Option<(Vec<(usize, f64)>, &'a [f64], &'a [f64])>,
}

/// Time constant (s) with which a model's temperature follows a recorded one.
pub const TEMPERATURE_LAG: f64 = 1.0;

impl<F: Fn(f64, &[f64]) -> f64> Dae for UnderCurrent<'_, F> {
    fn len(&self) -> usize {
        self.model.len()
    }
    fn mass(&self) -> &[f64] {
        self.model.mass()
    }
    fn scale(&self) -> &[f64] {
        self.model.scale()
    }
    fn accumulating_states(&self) -> Vec<usize> {
        self.model.accumulating_states()
    }
    fn difference_scale(&self) -> &[f64] {
        self.model.difference_scale()
    }
    fn rhs(&self, t: f64, y: &[f64], out: &mut [f64]) {
        self.model.rhs(y, (self.current)(t, y), out);
        if let Some((rows, times, temps)) = &self.temperature {
            let recorded = crate::params::function::interpolate(times, temps, t);
            for &(k, w) in rows {
                out[k] = (w * recorded - y[k]) / TEMPERATURE_LAG;
            }
        }
    }
    fn breakpoints(&self) -> &[f64] {
        &self.kinks
    }
}
