//! The split of a recording into steps: rest, constant current (CC), constant voltage (CV),
//! pulse, or varying current (a drive cycle or a ramp). Rows change step where the cycler's
//! step number changes and, within a cycler step, where the current stops being constant
//! (a CC-CV charge logged as one step is a CC step then a CV step).

use serde::Serialize;

use crate::data::Recording;
use crate::data::segments::CONSTANT_CURRENT_TOLERANCE;

/// Longest constant-current step (s) called a pulse: HPPC and resistance pulses last 1 to
/// 30 s; GITT pulses of minutes are CC steps.
pub const PULSE_MAX_DURATION: f64 = 60.0;

/// Voltage band (V) within which a step with a changing current is constant-voltage: a few
/// times a cycler's voltage noise, far below the voltage change of a CC step.
pub const CV_TOLERANCE: f64 = 0.005;

/// Least relative decay (-) of the current over a constant-voltage step: a CV phase takes
/// the current from its CC value down to a cut-off of a few percent of it, while the settling
/// of a cycler's current at the start of a CC step is about 1 %.
pub const CV_MIN_DECAY: f64 = 0.1;

/// What a step does.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
pub enum StepKind {
    Rest,
    /// Constant current.
    Cc,
    /// Constant voltage (the current decays by at least [`CV_MIN_DECAY`] while the voltage holds
    /// within [`CV_TOLERANCE`]).
    Cv,
    /// Constant current for at most [`PULSE_MAX_DURATION`].
    Pulse,
    /// Current that is neither constant nor held by a constant voltage.
    Varying,
}

impl std::fmt::Display for StepKind {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(match self {
            StepKind::Rest => "rest",
            StepKind::Cc => "CC",
            StepKind::Cv => "CV",
            StepKind::Pulse => "pulse",
            StepKind::Varying => "varying",
        })
    }
}

/// One step of a recording.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Step {
    /// Step number in the recording, from 1.
    pub number: usize,
    /// The cycler's own step number, when the file has one.
    pub cycler_step: Option<i64>,
    pub kind: StepKind,
    /// First and last row (0-based, inclusive).
    pub first: usize,
    pub last: usize,
    /// From the first row to the next step's first row (or to this step's last row) (s).
    pub duration: f64,
    /// Time-averaged current (A, discharge positive).
    pub mean_current: f64,
    /// Voltage at the first and last row (V).
    pub start_voltage: f64,
    pub end_voltage: f64,
}

/// Splits `rec` into steps; `cycler_step` is the cycler's step number of every row, if known.
///
/// ```
/// use cellstudio::data::Recording;
/// use cellstudio::data::cycler::{StepKind, steps};
/// let time = vec![0.0, 10.0, 10.0, 20.0, 30.0, 30.0, 40.0];
/// let current = vec![0.0, 0.0, 5.0, 5.0, 5.0, 0.0, 0.0];
/// let voltage = vec![4.0, 4.0, 3.9, 3.85, 3.8, 3.9, 3.92];
/// let rec = Recording { time, current, voltage, temperature: None };
/// let kinds: Vec<StepKind> = steps(&rec, None).iter().map(|s| s.kind).collect();
/// assert_eq!(kinds, [StepKind::Rest, StepKind::Pulse, StepKind::Rest]);
/// ```
pub fn steps(rec: &Recording, cycler_step: Option<&[i64]>) -> Vec<Step> {
    let (t, i, v) = (&rec.time, &rec.current, &rec.voltage);
    let n = t.len();
    let peak = i.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    let tol = (CONSTANT_CURRENT_TOLERANCE * peak).max(1e-12);
    let mut out: Vec<Step> = Vec::new();
    let mut block = 0;
    while block < n {
        let same = |k: usize| cycler_step.is_none_or(|s| s[k] == s[block]);
        let block_end = (block..n).take_while(|&k| same(k)).last().unwrap_or(block);
        let mut a = block;
        while a <= block_end {
            let (b, kind) = segment(t, i, v, a, block_end, tol);
            out.push(summary(rec, a, b, kind, cycler_step.map(|s| s[a])));
            a = b + 1;
        }
        block = block_end + 1;
    }
    for k in 0..out.len() {
        let end = out.get(k + 1).map_or(t[out[k].last], |s| t[s.first]);
        out[k].duration = end - t[out[k].first];
        out[k].number = k + 1;
        if out[k].kind == StepKind::Cc && out[k].duration <= PULSE_MAX_DURATION {
            out[k].kind = StepKind::Pulse;
        }
    }
    out
}

/// The segment that starts at row `a` (ending at most at `end`): its last row and kind.
fn segment(t: &[f64], i: &[f64], v: &[f64], a: usize, end: usize, tol: f64) -> (usize, StepKind) {
    let extend = |ok: &dyn Fn(usize) -> bool| (a + 1..=end).take_while(|&k| ok(k)).last().unwrap_or(a);
    if i[a].abs() <= tol {
        return (extend(&|k| i[k].abs() <= tol), StepKind::Rest);
    }
    let sign = i[a].signum();
    // Constant voltage: the current keeps its sign and does not grow (within the tolerance)
    // while the voltage holds, and it decays by at least CV_MIN_DECAY over the run.
    let cv_end = extend(&|k| (v[k] - v[a]).abs() <= CV_TOLERANCE && i[k] * sign > tol && i[k].abs() <= i[k - 1].abs() + tol);
    if cv_end > a && i[cv_end].abs() < (1.0 - CV_MIN_DECAY) * i[a].abs() {
        return (cv_end, StepKind::Cv);
    }
    // Constant current: every row within the tolerance of the running mean.
    let mut sum = i[a];
    let mut b = a;
    for k in a + 1..=end {
        if (i[k] - sum / (k - a) as f64).abs() > tol {
            break;
        }
        sum += i[k];
        b = k;
    }
    if b > a || t[a] == t.get(a + 1).copied().unwrap_or(f64::NAN) || a == end {
        return (b, StepKind::Cc);
    }
    // Varying: until the current settles (two rows agree) or rests.
    let b = extend(&|k| i[k].abs() > tol && (k == end || (i[k + 1] - i[k]).abs() > tol));
    (b, StepKind::Varying)
}

fn summary(rec: &Recording, a: usize, b: usize, kind: StepKind, cycler_step: Option<i64>) -> Step {
    let (t, i) = (&rec.time, &rec.current);
    let span = t[b] - t[a];
    let mean_current = if span > 0.0 {
        (a..b).map(|k| 0.5 * (i[k] + i[k + 1]) * (t[k + 1] - t[k])).sum::<f64>() / span
    } else {
        i[a..=b].iter().sum::<f64>() / (b - a + 1) as f64
    };
    Step {
        number: 0,
        cycler_step,
        kind,
        first: a,
        last: b,
        duration: span,
        mean_current,
        start_voltage: rec.voltage[a],
        end_voltage: rec.voltage[b],
    }
}

/// The steps as a Markdown table (number, cycler step, kind, duration, mean current, start
/// and end voltage).
pub fn step_table(steps: &[Step]) -> String {
    use std::fmt::Write;
    let mut s = String::from("| step | cycler step | kind | duration (s) | mean current (A) | start V | end V |\n|---|---|---|---|---|---|---|\n");
    for st in steps {
        let cs = st.cycler_step.map_or("-".to_string(), |c| c.to_string());
        let _ = writeln!(
            s,
            "| {} | {cs} | {} | {:.1} | {:.4} | {:.4} | {:.4} |",
            st.number, st.kind, st.duration, st.mean_current, st.start_voltage, st.end_voltage
        );
    }
    s
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn cccv_charge_in_one_cycler_step_is_cc_then_cv() {
        // 1 s samples: -2.5 A until 4.2 V, then the current decays at 4.2 V.
        let mut time = Vec::new();
        let (mut current, mut voltage) = (Vec::new(), Vec::new());
        for k in 0..600 {
            time.push(k as f64);
            if k < 300 {
                current.push(-2.5);
                voltage.push(3.9 + 0.3 * k as f64 / 300.0);
            } else {
                current.push(-2.5 * (-(k as f64 - 300.0) / 60.0).exp());
                voltage.push(4.2);
            }
        }
        let rec = Recording { time, current, voltage, temperature: None };
        let s = steps(&rec, Some(&[7; 600]));
        let kinds: Vec<StepKind> = s.iter().map(|s| s.kind).collect();
        assert_eq!(kinds, [StepKind::Cc, StepKind::Cv], "{}", step_table(&s));
        assert!(s.iter().all(|s| s.cycler_step == Some(7)));
        assert!((s[0].mean_current + 2.5).abs() < 0.01);
    }

    #[test]
    fn cycler_step_numbers_split_steps() {
        let rec = Recording { time: vec![0.0, 1.0, 2.0, 3.0], current: vec![1.0, 1.0, 1.0, 1.0], voltage: vec![3.7; 4], temperature: None };
        let s = steps(&rec, Some(&[1, 1, 2, 2]));
        assert_eq!(s.len(), 2);
        assert_eq!((s[0].first, s[0].last, s[1].first, s[1].last), (0, 1, 2, 3));
        assert_eq!(s[0].duration, 2.0);
    }
}
