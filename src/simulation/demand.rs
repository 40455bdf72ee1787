//! Whose fault a step's failure at its start is. When the cell, from the state the step starts
//! in, carries its nominal 1C in the step's direction (the model healthy, the voltage inside
//! the step's window) but not the step's own demand (its current, C-rate or power), the demand
//! is what put the voltage beyond a cut-off or broke the model: the error then names it by the
//! step's key (e.g. `protocol.steps[1].rate` = 50), not the cut-off the voltage crossed.
//! Otherwise the failure stays as found: a cut-off or step limit that even 1C crosses from
//! there (an empty cell, a window too narrow), a state the model cannot start from.

use super::consistent_initialisation;
use crate::error::Error;
use crate::models::Model;
use crate::protocol::Step;
use crate::solver::Workspace;

/// The start of protocol step `index` (its `t0`, s), for blaming a failure there.
pub(super) struct StepStart<'a> {
    pub model: &'a dyn Model,
    pub step: &'a Step,
    pub index: usize,
    /// Start time of the step (s).
    pub t0: f64,
    /// The state the step starts from, before its algebraic states were fitted to its current.
    pub y: &'a [f64],
    /// The step's voltage window `(lower, upper)` (V).
    pub window: (f64, f64),
    /// Nominal capacity (A h): the current of 1C in amperes.
    pub capacity: f64,
}

impl StepStart<'_> {
    /// `failure`, what happened (`what`) under the step's current `current` (A), as an
    /// [`Error::StepDemand`] when the cell carries 1C in the same direction; else as it is.
    /// Voltage holds keep theirs: the current is their unknown, not their demand.
    pub(super) fn blame(&self, ws: &mut Workspace, current: f64, what: &str, failure: Error) -> Error {
        let Some((key, value)) = self.step.demand() else { return failure };
        if matches!(self.step, Step::Hold { .. }) {
            return failure;
        }
        let one_c = self.capacity.copysign(current);
        let Some(v_one_c) = self.voltage_under(ws, one_c) else { return failure };
        let amperes = |i: f64| crate::error::number((i * 1e4).round() / 1e4);
        Error::StepDemand {
            step: self.index,
            key,
            value,
            reason: format!(
                "at the start of step {} (t = {} s), under {} A, {what}, though the cell carries 1C ({} A) from there at {v_one_c:.4} V: the demand is more than this cell carries (or check its resistances and electrode thicknesses)",
                self.index,
                self.t0,
                amperes(current),
                amperes(one_c)
            ),
        }
    }

    /// The terminal voltage (V) under `current` (A) from the step's starting state, when the
    /// model is consistent and finite there and the voltage lies strictly inside the window.
    fn voltage_under(&self, ws: &mut Workspace, current: f64) -> Option<f64> {
        let mut y = self.y.to_vec();
        consistent_initialisation(self.model, ws, current, &mut y).ok()?;
        let mut f = vec![0.0; y.len()];
        self.model.rhs(&y, current, &mut f);
        let v = self.model.voltage(&y, current);
        let (lower, upper) = self.window;
        (f.iter().all(|x| x.is_finite()) && v > lower && v < upper).then_some(v)
    }
}
