//! Checks of a recording against the cell it is said to come from, before any model runs:
//! the charge it moves against the cell's capacity, its voltage swing against that charge,
//! its peak current as a C-rate, and its sampling. Likely unit errors are named as such,
//! with the `[data.format]` setting that fixes them.

use serde::Serialize;

use super::Recording;

/// One finding of the checks.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Finding {
    /// A likely unit error (the recording cannot be from this cell as read): fatal.
    pub unit_error: bool,
    pub message: String,
}

/// Summary numbers behind the findings.
#[derive(Clone, Copy, Debug, Serialize)]
pub struct RecordingStats {
    /// Range of the charge moved since the start (A h).
    pub charge_range: f64,
    /// Largest |current| (A) and as a C-rate of the nominal capacity (-).
    pub peak_current: f64,
    pub peak_c_rate: f64,
    /// Voltage range (V).
    pub voltage_span: f64,
    /// Change of the voltage between the first and the last point when the recording ends at
    /// rest (|current| below C/1000): about the open-circuit change the moved charge caused,
    /// less the first point's overpotential if it starts under load (V).
    pub rested_swing: Option<f64>,
    /// Median and largest time step (s).
    pub median_step: f64,
    pub largest_step: f64,
}

/// Samples either way over which [`Recording::sign_finding`] looks for the voltage's response
/// to a current step (a voltage channel logged out of step with the current).
const SIGN_LAGS: isize = 5;

impl Recording {
    /// The points `k` where the current moves by more than a fifth of its peak from point
    /// `k - 1`: the current steps whose responses the sign check and a delay's resolution read.
    pub fn large_current_steps(&self) -> Vec<usize> {
        let i = &self.current;
        let peak = i.iter().fold(0.0f64, |m, x| m.max(x.abs()));
        (1..i.len()).filter(|&k| (i[k] - i[k - 1]).abs() > 0.2 * peak).collect()
    }

    /// Summary numbers of the recording against nominal capacity `capacity` (A h).
    pub fn stats(&self, capacity: f64) -> RecordingStats {
        let (t, i, v) = (&self.time, &self.current, &self.voltage);
        let (mut q, mut q_min, mut q_max) = (0.0f64, 0.0f64, 0.0f64);
        let mut steps: Vec<f64> = Vec::with_capacity(t.len());
        for k in 1..t.len() {
            let dt = t[k] - t[k - 1];
            q += 0.5 * (i[k] + i[k - 1]) * dt / 3600.0;
            (q_min, q_max) = (q_min.min(q), q_max.max(q));
            if dt > 0.0 {
                steps.push(dt);
            }
        }
        steps.sort_by(f64::total_cmp);
        let peak = i.iter().fold(0.0f64, |m, x| m.max(x.abs()));
        let (v_min, v_max) = v.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), x| (a.min(*x), b.max(*x)));
        RecordingStats {
            charge_range: q_max - q_min,
            peak_current: peak,
            peak_c_rate: peak / capacity,
            voltage_span: v_max - v_min,
            rested_swing: {
                let rested = |k: usize| i[k].abs() < 1e-3 * capacity;
                let last = v.len() - 1;
                (v.len() > 1 && rested(last)).then(|| (v[last] - v[0]).abs())
            },
            median_step: steps.get(steps.len() / 2).copied().unwrap_or(0.0),
            largest_step: steps.last().copied().unwrap_or(0.0),
        }
    }

    /// Checks the recording against a cell of nominal capacity `capacity` (A h) whose
    /// open-circuit window spans `ocv_window` (V, upper minus lower cut-off).
    ///
    /// ```
    /// use cellstudio::data::Recording;
    /// // A 1C discharge of a 5 A h cell with time written in minutes: 60 "s" long.
    /// let time: Vec<f64> = (0..=60).map(f64::from).collect();
    /// let voltage = time.iter().map(|t| 4.1 - 1.3 * t / 60.0).collect();
    /// let rec = Recording { current: vec![5.0; 61], time, voltage, temperature: None };
    /// let f = rec.check_against_cell(5.0, 1.7);
    /// assert!(f[0].unit_error && f[0].message.contains("time_unit = \"min\""));
    ///
    /// // A strongly polarised cell: 3 minutes at 1.5C swing 1.4 V, then it rests back to
    /// // within 0.1 V of its start. Not a unit error (a note), since it ends at rest.
    /// let time = vec![0.0, 180.0, 181.0, 2000.0];
    /// let current = vec![7.5, 7.5, 0.0, 0.0];
    /// let voltage = vec![4.0, 2.7, 3.6, 4.1];
    /// let f = Recording { time, current, voltage, temperature: None }.check_against_cell(5.0, 1.7);
    /// assert!(!f[0].unit_error && f[0].message.contains("strongly polarised"), "{:?}", f);
    /// ```
    pub fn check_against_cell(&self, capacity: f64, ocv_window: f64) -> Vec<Finding> {
        let s = self.stats(capacity);
        let mut out = Vec::new();
        let fatal = |message: String| Finding { unit_error: true, message };
        if s.charge_range > 1.5 * capacity {
            out.push(fatal(format!(
                "the recording moves {:.3} A h, {:.1} times the cell's nominal {:.3} A h: is the current in mA (`[data.format] current_unit = \"mA\"`) or the time in ms?",
                s.charge_range,
                s.charge_range / capacity,
                capacity
            )));
        } else if s.peak_c_rate > 50.0 {
            out.push(fatal(format!(
                "the peak current {:.4} A is {:.0}C for the cell's nominal {:.3} A h: is the current in mA (`[data.format] current_unit = \"mA\"`)?",
                s.peak_current, s.peak_c_rate, capacity
            )));
        }
        if s.voltage_span > 0.6 * ocv_window && s.charge_range < 0.1 * capacity && s.peak_c_rate < 20.0 {
            let factor = 0.6 * capacity / s.charge_range.max(1e-12);
            let hint = if (30.0..=120.0).contains(&factor) {
                "is the time in minutes (`[data.format] time_unit = \"min\"`)?"
            } else if factor > 1000.0 {
                "is the time in hours (`[data.format] time_unit = \"h\"`) or the current in kA?"
            } else {
                "is the time or the current in another unit?"
            };
            let message = format!(
                "the voltage swings {:.3} V, {:.0} % of the cell's open-circuit window, while only {:.4} A h ({:.2} % of the nominal {:.3} A h) moves",
                s.voltage_span,
                100.0 * s.voltage_span / ocv_window,
                s.charge_range,
                100.0 * s.charge_range / capacity,
                capacity
            );
            // A cell that polarises strongly can swing that far under load and relax back: when
            // it ends at rest, only an end voltage far from the start is a unit error.
            match s.rested_swing {
                Some(rested) if rested <= 0.4 * ocv_window => out.push(Finding {
                    unit_error: false,
                    message: format!("{message} under load, but relaxes to within {rested:.3} V of its start: a strongly polarised cell ({hint})"),
                }),
                _ => out.push(fatal(format!("{message}: {hint}"))),
            }
        }
        if let Some(f) = self.sign_finding() {
            out.push(f);
        }
        if s.peak_c_rate > 20.0 && !out.iter().any(|f| f.unit_error) {
            out.push(Finding { unit_error: false, message: format!("the peak current is {:.0}C: an unusually high rate", s.peak_c_rate) });
        }
        if s.largest_step > 600.0 {
            out.push(Finding {
                unit_error: false,
                message: format!("the sampling has a gap of {:.0} s (median step {:.3} s): the model is driven by a linear current in between", s.largest_step, s.median_step),
            });
        }
        out
    }

    /// The current's sign against the voltage's response at current steps: a cell's voltage
    /// drops when its discharge current rises. When it rises at the steps that carry most of the
    /// response (at least two steps; over 80 % of the summed `|di dv|`, so that short steps
    /// whose response a lagged channel blurs count for little: blind aq5, a channel 3 s late
    /// under 1 s bursts, rose at only 77 % of its flipped steps but with 99.8 % of the
    /// response), or, with fewer steps, moves with the current over the longest load, the current
    /// is charge-positive as read: a unit error. The response is read at the lag (up to
    /// [`SIGN_LAGS`] samples either way) where it is strongest, so a voltage channel logged a
    /// few samples late or early is not taken for a sign error: the sign of the strongest
    /// response decides.
    ///
    /// ```
    /// use cellstudio::data::Recording;
    /// // A discharge pulse logged charge-positive: -5 A while the voltage drops.
    /// let time = vec![0.0, 0.0, 10.0, 10.0, 20.0];
    /// let current = vec![0.0, -5.0, -5.0, 0.0, 0.0];
    /// let voltage = vec![3.70, 3.65, 3.64, 3.69, 3.695];
    /// let f = Recording { time, current, voltage, temperature: None }.sign_finding().unwrap();
    /// assert!(f.unit_error && f.message.contains("discharge_positive"), "{f:?}");
    /// ```
    pub fn sign_finding(&self) -> Option<Finding> {
        let (i, v) = (&self.current, &self.voltage);
        // A step's response is the voltage's change `lag` samples later. At each lag: the
        // steps counted, those whose voltage rose with the discharge current, the summed
        // `di dv` (A V), its absolute values and their rising part.
        let large = self.large_current_steps();
        let response = |lag: isize| {
            let (mut steps, mut rising, mut sum, mut total, mut risen) = (0usize, 0usize, 0.0f64, 0.0f64, 0.0f64);
            for &k in &large {
                let m = k as isize + lag;
                if m < 1 || m as usize >= v.len() {
                    continue;
                }
                let (di, dv) = (i[k] - i[k - 1], v[m as usize] - v[m as usize - 1]);
                if dv != 0.0 {
                    steps += 1;
                    rising += usize::from(di * dv > 0.0);
                    sum += di * dv;
                    total += (di * dv).abs();
                    risen += (di * dv).max(0.0);
                }
            }
            (steps, rising, sum, total, risen)
        };
        let (steps, rising, _, total, risen) = (-SIGN_LAGS..=SIGN_LAGS).map(response).max_by(|a, b| a.2.abs().total_cmp(&b.2.abs())).unwrap_or_default();
        let fix = "is the current charge-positive (flip the sign of the current column, or `[data.format] discharge_positive = false`)?";
        if steps >= 2 {
            return (risen > 0.8 * total).then(|| Finding {
                unit_error: true,
                message: format!(
                    "the voltage rises when the discharge current rises at {rising} of {steps} current steps, which carry {:.0} % of the response: {fix}",
                    100.0 * risen / total
                ),
            });
        }
        // Too few steps: the longest load of one sign (by charge) must move the voltage against
        // its current (down on discharge, up on charge); 20 mV the other way is a sign error.
        let (mut best, mut start, mut charge) = ((0.0f64, 0.0f64), 0usize, 0.0f64);
        for k in 1..=i.len() {
            let same = k < i.len() && i[k] != 0.0 && i[k].signum() == i[start].signum();
            if same {
                charge += 0.5 * (i[k] + i[k - 1]).abs() * (self.time[k] - self.time[k - 1]);
                continue;
            }
            if i[start] != 0.0 && charge > best.0 {
                best = (charge, i[start].signum() * (v[k - 1] - v[start]));
            }
            (start, charge) = (k.min(i.len() - 1), 0.0);
        }
        (best.1 > 0.02).then(|| Finding {
            unit_error: true,
            message: format!("over its longest load the voltage moves {:.3} V with the current instead of against it: {fix}", best.1),
        })
    }

    /// [`check_against_cell`](Self::check_against_cell) for the cell `cell` (its nominal
    /// capacity, A h, and its window between the cut-offs, V): a likely unit error is an error
    /// naming `data` (`file`); the other findings come back as notes. The one check of a
    /// recording against its cell: `fit`, `diagnose` and `data inspect` all refuse through it.
    pub fn refuse_unit_errors(&self, file: &str, cell: &crate::params::ParameterSet) -> Result<Vec<String>, crate::Error> {
        let findings = self.check_against_cell(cell.cell.nominal_capacity, cell.cell.upper_cutoff - cell.cell.lower_cutoff);
        if let Some(f) = findings.iter().find(|f| f.unit_error) {
            return Err(crate::Error::InvalidSetting { field: format!("data ({file})"), reason: format!("likely unit error: {}", f.message) });
        }
        Ok(findings.into_iter().map(|f| format!("Recording check: {}.", f.message)).collect())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A drive of 1-3 s pulses through a 20 mOhm cell logged every second: read 2 s late the
    /// voltage moves with the current at most steps (its own lag), yet drops with the
    /// discharge current at the lag of the strongest response; a flipped current is refused.
    #[test]
    fn a_late_voltage_channel_is_not_a_sign_error() {
        let lengths = [1, 3, 2, 1, 3, 1, 2, 3, 3, 1, 2, 2, 1, 3];
        let current: Vec<f64> = lengths.iter().cycle().take(60).enumerate().flat_map(|(k, n)| vec![if k % 2 == 1 { 5.0 } else { 0.0 }; *n]).take(120).collect();
        let cell: Vec<f64> = current.iter().map(|i| 3.7 - 0.02 * i).collect();
        let late: Vec<f64> = (0..120).map(|k| cell[k.max(2) - 2]).collect();
        let time: Vec<f64> = (0..120).map(f64::from).collect();
        let rec = |current: Vec<f64>, voltage: Vec<f64>| Recording { time: time.clone(), current, voltage, temperature: None };
        assert!(rec(current.clone(), cell.clone()).sign_finding().is_none());
        assert!(rec(current.clone(), late.clone()).sign_finding().is_none());
        let flipped: Vec<f64> = current.iter().map(|i| -i).collect();
        assert!(rec(flipped.clone(), late).sign_finding().is_some_and(|f| f.unit_error));
        assert!(rec(flipped, cell).sign_finding().is_some_and(|f| f.unit_error));
    }
}
