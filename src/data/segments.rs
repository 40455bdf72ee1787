//! The protocol that reproduces a recording's current: constant stretches become current or
//! rest steps, varying stretches become piecewise-linear tables, and a repeated time marks a
//! jump between steps.

use super::Recording;
use crate::protocol::{Protocol, Step};

/// Relative spread (-, of the largest |current|) within which recorded currents count as one
/// constant step: 0.2 %, 10 mA at 5 A, above a cycler's noise of a few mA and below the
/// change between 1 s samples of a drive cycle.
pub const CONSTANT_CURRENT_TOLERANCE: f64 = 2e-3;

impl Recording {
    /// The recorded current (A, discharge positive) as a protocol, linear between samples.
    /// Samples whose currents agree within [`CONSTANT_CURRENT_TOLERANCE`] of the largest
    /// current are one constant step at their mean (a cycler's constant current carries a
    /// few mA of measurement noise); a rest is a stretch of zero current.
    pub fn protocol(&self) -> Protocol {
        let (t, i) = (&self.time, &self.current);
        let tol = CONSTANT_CURRENT_TOLERANCE * i.iter().fold(0.0f64, |m, v| m.max(v.abs())).max(1e-12);
        let mut steps = Vec::new();
        // The open stretch: start index and whether it is constant.
        let mut open: Option<(usize, bool)> = None;
        let close = |steps: &mut Vec<Step>, start: usize, end: usize, constant: bool| {
            if end <= start || t[end] <= t[start] {
                return;
            }
            let duration = t[end] - t[start];
            steps.push(if !constant {
                Step::Table { time: t[start..=end].iter().map(|v| v - t[start]).collect(), current: i[start..=end].to_vec() }
            } else if i[start..=end].iter().all(|v| *v == 0.0) {
                Step::Rest { duration }
            } else {
                // The charge-weighted mean over the stretch (trapezoids).
                let charge: f64 = (start..end).map(|k| 0.5 * (i[k] + i[k + 1]) * (t[k + 1] - t[k])).sum();
                Step::Current { current: charge / duration, duration, until_voltage: None }
            });
        };
        for k in 0..t.len() - 1 {
            if t[k + 1] == t[k] {
                // A jump: close the open stretch at k.
                if let Some((s, c)) = open.take() {
                    close(&mut steps, s, k, c);
                }
                continue;
            }
            let constant = (i[k + 1] - i[k]).abs() <= tol;
            match open {
                Some((s, c)) if c == constant && (!c || (i[k] - i[s]).abs() <= tol) => {}
                Some((s, c)) => {
                    close(&mut steps, s, k, c);
                    open = Some((k, constant));
                }
                None => open = Some((k, constant)),
            }
        }
        if let Some((s, c)) = open {
            close(&mut steps, s, t.len() - 1, c);
        }
        Protocol { steps }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn rec(time: &[f64], current: &[f64]) -> Recording {
        Recording { time: time.to_vec(), current: current.to_vec(), voltage: vec![3.7; time.len()], temperature: None }
    }

    #[test]
    fn steps_from_jumps_constants_and_ramps() {
        let r = rec(&[0.0, 10.0, 20.0, 20.0, 30.0, 40.0, 45.0, 50.0], &[5.0, 5.0, 5.0, 0.0, 0.0, 0.0, 1.0, 3.0]);
        let p = r.protocol();
        assert_eq!(
            p.steps,
            vec![
                Step::Current { current: 5.0, duration: 20.0, until_voltage: None },
                Step::Rest { duration: 20.0 },
                Step::Table { time: vec![0.0, 5.0, 10.0], current: vec![0.0, 1.0, 3.0] },
            ]
        );
        assert_eq!(p.duration(), 50.0);
    }

    #[test]
    fn a_change_of_constant_level_without_repeated_time_is_a_ramp() {
        let r = rec(&[0.0, 10.0, 20.0, 30.0], &[2.0, 2.0, 0.0, 0.0]);
        let p = r.protocol();
        assert_eq!(
            p.steps,
            vec![
                Step::Current { current: 2.0, duration: 10.0, until_voltage: None },
                Step::Table { time: vec![0.0, 10.0], current: vec![2.0, 0.0] },
                Step::Rest { duration: 10.0 },
            ]
        );
    }
}
