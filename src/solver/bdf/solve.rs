//! Driving a [`Bdf`] stepper to its stop time, handing each step to an observer and locating
//! a sign change of an event function on the steps' interpolants.

use super::stepper::Bdf;
use super::{DenseOutput, StopReason};
use crate::error::Error;

impl Bdf<'_> {
    /// Steps to the stop time, or until `event(t, y)` changes sign. After every accepted step,
    /// `observer(t_old, dense)` is called with the step's interpolant (cut at the event time if
    /// one fired). The state at the returned time is [`Bdf::state`] at the stop time, else
    /// `self.dense().eval(t_event, ..)`. Fails after `opts.max_steps` steps.
    pub fn solve(
        &mut self,
        event: Option<&dyn Fn(f64, &[f64]) -> f64>,
        observer: &mut dyn FnMut(f64, &DenseOutput),
    ) -> Result<StopReason, Error> {
        let mut g_old = event.map(|g| g(self.t(), self.state()));
        loop {
            let step = self.step()?;
            let (t_old, t) = (step.t_old, step.t);
            let dense = self.dense();
            if let (Some(g), Some(go)) = (event, g_old) {
                let g_new = g(t, self.state());
                if go.signum() != g_new.signum() && g_new != go {
                    let t_event = locate_event(g, &dense, (t_old, go), (t, g_new));
                    observer(t_old, &DenseOutput { end: t_event, ..dense });
                    return Ok(StopReason::Event(t_event));
                }
                g_old = Some(g_new);
            }
            observer(t_old, &dense);
            if t >= self.t_stop() {
                return Ok(StopReason::EndTime);
            }
            if self.stats().steps >= self.opts.max_steps {
                return Err(Error::Solver { t, reason: format!("exceeded {} steps", self.opts.max_steps) });
            }
        }
    }
}

/// The zero of `g` on the interpolant `dense` between `(ta, ga)` (the step start) and
/// `(tb, gb)` (its end), where `g` changes sign, by Illinois false position: the end whose
/// `|g|` is smaller after the bracket shrinks below round-off in `t` or `g` hits zero.
fn locate_event(g: &dyn Fn(f64, &[f64]) -> f64, dense: &DenseOutput, (mut ta, mut ga): (f64, f64), (mut tb, mut gb): (f64, f64)) -> f64 {
    let t = tb;
    let mut buf = vec![0.0; dense.d[0].len()];
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
    if ga.abs() < gb.abs() { ta } else { tb }
}
