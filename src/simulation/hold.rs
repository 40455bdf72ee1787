//! Voltage holds (constant-voltage steps): the applied current becomes one more algebraic
//! unknown, appended to the model's states, with the equation `V(y, I) - V_hold = 0`. This
//! serves every model alike, including the DFN, whose terminal voltage is read off its
//! potentials and does not depend on the current directly.

use super::consistent_initialisation;
use crate::error::Error;
use crate::models::Model;
use crate::solver::{Dae, Workspace};

/// A model under a voltage hold: states `[y, I]` (I in A, discharge positive).
pub(super) struct VoltageHold<'a> {
    pub model: &'a dyn Model,
    /// Held terminal voltage (V).
    pub voltage: f64,
    mass: Vec<f64>,
    scale: Vec<f64>,
    difference_scale: Vec<f64>,
}

impl<'a> VoltageHold<'a> {
    /// `current_scale` (A): the typical current, e.g. the 1C current.
    pub fn new(model: &'a dyn Model, voltage: f64, current_scale: f64) -> Self {
        let mass = model.mass().iter().copied().chain([0.0]).collect();
        let current_scale = current_scale.abs().max(1e-6);
        let scale = model.scale().iter().copied().chain([current_scale]).collect();
        let difference_scale = model.difference_scale().iter().copied().chain([current_scale]).collect();
        Self { model, voltage, mass, scale, difference_scale }
    }

    /// The Jacobian pattern of the held system: the model's, the current's column in the rows
    /// that read it and in the voltage row, and the voltage row over the states the voltage
    /// reads.
    pub fn pattern(model: &dyn Model) -> Vec<(usize, usize)> {
        let n = model.len();
        let mut pattern = model.jacobian_pattern();
        pattern.extend(model.rows_reading_current().into_iter().chain([n]).map(|r| (r, n)));
        pattern.extend(model.output_states().into_iter().map(|c| (n, c)));
        pattern
    }
}

impl Dae for VoltageHold<'_> {
    fn len(&self) -> usize {
        self.model.len() + 1
    }
    fn mass(&self) -> &[f64] {
        &self.mass
    }
    fn scale(&self) -> &[f64] {
        &self.scale
    }
    fn accumulating_states(&self) -> Vec<usize> {
        self.model.accumulating_states()
    }
    fn difference_scale(&self) -> &[f64] {
        &self.difference_scale
    }
    fn rhs(&self, _t: f64, y: &[f64], out: &mut [f64]) {
        let n = self.model.len();
        let (states, current) = (&y[..n], y[n]);
        self.model.rhs(states, current, &mut out[..n]);
        out[n] = self.model.voltage(states, current) - self.voltage;
    }
}

/// The current (A) that holds `voltage` (V) at the start of a hold from the state `y`, whose
/// algebraic states are made consistent with it: a secant iteration on the current from
/// `guess` (A), each trial with its own consistent initialisation.
pub(super) fn starting_current(model: &dyn Model, ws: &mut Workspace, voltage: f64, y: &mut [f64], guess: f64, current_scale: f64) -> Result<f64, Error> {
    let mut residual = |i: f64, y: &mut [f64]| -> Result<f64, Error> {
        consistent_initialisation(model, ws, i, y)?;
        Ok(model.voltage(y, i) - voltage)
    };
    let step = 1e-3 * current_scale.abs().max(1e-6);
    let (mut a, mut b) = (guess, guess - step);
    let (mut fa, mut fb) = (residual(a, y)?, residual(b, y)?);
    for _ in 0..50 {
        if fb == fa {
            break;
        }
        let c = b - fb * (b - a) / (fb - fa);
        (a, fa) = (b, fb);
        b = c;
        fb = residual(b, y)?;
        if fb.abs() <= 1e-10 * voltage.abs().max(1.0) {
            return Ok(b);
        }
    }
    Err(Error::Solver { t: 0.0, reason: format!("no current holds {voltage} V at the start of the hold (last residual {fb:.3e} V)") })
}
