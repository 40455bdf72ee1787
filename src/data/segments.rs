//! The protocol that reproduces a recording's current: constant stretches become current or
//! rest steps, varying stretches become piecewise-linear tables, and a repeated time marks a
//! jump between steps. A change a cycler logged early (before its logging period, so it was
//! triggered by the change) is read as a jump at the end of the gap, not as a ramp across it.

use super::Recording;
use crate::protocol::{Protocol, Step};

/// Relative spread (-, of the largest |current|) within which recorded currents count as one
/// constant step: 0.2 %, 10 mA at 5 A, above a cycler's noise of a few mA and below the
/// change between 1 s samples of a drive cycle.
pub const CONSTANT_CURRENT_TOLERANCE: f64 = 2e-3;

/// Spread within which recorded currents count as one constant step on a noisy channel, in
/// standard deviations of its noise ([`Recording::current_noise`]): two samples of one step
/// differ by more than this with odds of 1 in 2000.
pub const CONSTANT_CURRENT_IN_NOISE: f64 = 5.0;

/// Standard errors within which the mean current of a constant stretch on a noisy channel
/// counts as zero (a rest).
const REST_IN_STANDARD_ERRORS: f64 = 3.0;

impl Recording {
    /// The recorded current (A, discharge positive) as a protocol, linear between samples.
    /// Samples whose currents agree within [`CONSTANT_CURRENT_TOLERANCE`] of the largest
    /// current, or within [`CONSTANT_CURRENT_IN_NOISE`] standard deviations of the channel's
    /// noise where that is larger, are one constant step at their mean (a cycler's constant
    /// current carries measurement noise); a rest is a stretch of zero current, or on a noisy
    /// channel one whose mean is zero within its standard error.
    pub fn protocol(&self) -> Protocol {
        let noise = self.current_noise();
        let largest = self.current.iter().fold(0.0f64, |m, v| m.max(v.abs()));
        let tol = (CONSTANT_CURRENT_TOLERANCE * largest).max(CONSTANT_CURRENT_IN_NOISE * noise).max(1e-12);
        let (t, i) = &self.with_triggered_jumps(tol);
        let mut steps = Vec::new();
        // The open stretch: start index and whether it is constant.
        let mut open: Option<(usize, bool)> = None;
        let close = |steps: &mut Vec<Step>, start: usize, end: usize, constant: bool| {
            if end <= start || t[end] <= t[start] {
                return;
            }
            let duration = t[end] - t[start];
            // The charge-weighted mean over the stretch (trapezoids).
            let mean = (start..end).map(|k| 0.5 * (i[k] + i[k + 1]) * (t[k + 1] - t[k])).sum::<f64>() / duration;
            let zero_in_noise = mean.abs() <= REST_IN_STANDARD_ERRORS * noise / ((end + 1 - start) as f64).sqrt();
            steps.push(if !constant {
                Step::Table { time: t[start..=end].iter().map(|v| v - t[start]).collect(), current: i[start..=end].to_vec() }
            } else if i[start..=end].iter().all(|v| *v == 0.0) || zero_in_noise {
                Step::Rest { duration }
            } else {
                Step::Current { current: mean, duration, until_voltage: None }
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

    /// Time (s) and current (A) with a sample added where a logged change was triggered.
    /// A cycler that logs a steady current on a period, and at once when the current moves by
    /// more than its threshold, leaves a gap shorter than its period before a jump: the current
    /// held until the last fine interval of that gap, not rising across it as linear
    /// interpolation would have it. Such a gap gets a sample at the held current one fine
    /// interval before its end. Left linear: a change logged on the period (the jump may lie
    /// anywhere in the gap; the ramp carries the charge of a jump at its middle), and a run of
    /// early-logged changes of one sign after the first (a smooth decay, as in a CV hold, logged
    /// each time it crosses the threshold). The fine interval is the recording's most common
    /// gap, the period its most common gap of at least [`PERIOD_IN_FINE`] fine intervals; a
    /// recording without such gaps is left as it is.
    fn with_triggered_jumps(&self, tol: f64) -> (Vec<f64>, Vec<f64>) {
        let (t, i) = (&self.time, &self.current);
        let gaps: Vec<f64> = t.windows(2).map(|w| w[1] - w[0]).collect();
        let Some(fine) = most_common(gaps.iter().copied().filter(|g| *g > 0.0)) else { return (t.clone(), i.clone()) };
        let Some(period) = most_common(gaps.iter().copied().filter(|g| *g >= PERIOD_IN_FINE * fine)) else { return (t.clone(), i.clone()) };
        let (mut time, mut current) = (Vec::with_capacity(t.len()), Vec::with_capacity(t.len()));
        // The sign of the previous interval's change when it was logged early (0: it was not).
        let mut run = 0.0;
        for k in 0..t.len() {
            if k > 0 {
                let (gap, change) = (gaps[k - 1], i[k] - i[k - 1]);
                let early = change.abs() > tol && gap > 1.5 * fine && gap < 0.9 * period;
                if early && change.signum() != run {
                    time.push(t[k] - fine);
                    current.push(i[k - 1]);
                }
                run = if early { change.signum() } else { 0.0 };
            }
            time.push(t[k]);
            current.push(i[k]);
        }
        (time, current)
    }
}

/// Shortest gap (in fine sampling intervals) that counts as a cycler's logging period.
const PERIOD_IN_FINE: f64 = 5.0;

/// The most common of `values` (s), to the millisecond; the shorter of equally common ones.
fn most_common(values: impl Iterator<Item = f64>) -> Option<f64> {
    let mut ms: Vec<i64> = values.map(|v| (v * 1e3).round() as i64).collect();
    ms.sort_unstable();
    ms.chunk_by(|a, b| a == b).max_by_key(|run| (run.len(), std::cmp::Reverse(run[0]))).map(|run| run[0] as f64 * 1e-3)
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
    fn steps_on_a_noisy_current_channel_are_read_at_their_means() {
        use rand::SeedableRng;
        use rand_distr::{Distribution, Normal};
        // 10 s rest, then 40 steps of 5 A or -3 A, 12 s each, 1 s samples, 25 mA sensor noise.
        let levels: Vec<f64> = (0..40).map(|k| if (k * 7) % 3 == 0 { -3.0 } else { 5.0 }).collect();
        let set: Vec<f64> = std::iter::repeat_n(0.0, 11).chain(levels.iter().flat_map(|l| std::iter::repeat_n(*l, 12))).collect();
        let mut rng = rand::rngs::StdRng::seed_from_u64(3);
        let noise = Normal::new(0.0, 0.025).unwrap();
        let time: Vec<f64> = (0..set.len()).map(|k| k as f64).collect();
        let current: Vec<f64> = set.iter().map(|i| i + noise.sample(&mut rng)).collect();
        let steps = rec(&time, &current).protocol().steps;
        // One rest, then per change of level a one-second ramp between two constant steps.
        let constant: Vec<&Step> = steps.iter().filter(|s| !matches!(s, Step::Table { .. })).collect();
        let changes = 1 + levels.windows(2).filter(|w| w[0] != w[1]).count();
        assert_eq!(constant.len(), changes + 1, "{steps:?}");
        assert!(matches!(constant[0], Step::Rest { .. }), "{:?}", constant[0]);
        for step in &constant[1..] {
            let Step::Current { current, .. } = step else { panic!("{step:?}") };
            // A mean of about 11 samples: within 3 standard errors (23 mA) of its level.
            let off = (current - 5.0).abs().min((current + 3.0).abs());
            assert!(off < 0.023, "{step:?}");
        }
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

    #[test]
    fn a_change_logged_before_the_period_is_a_jump_at_the_end_of_its_gap() {
        // 1 s samples, then 0.1 A logged every 30 s; the jump to 2 A is logged 15 s after the
        // last 0.1 A sample (triggered by the change), then the new level on the period.
        let r = rec(&[0.0, 1.0, 2.0, 3.0, 4.0, 34.0, 64.0, 79.0, 109.0], &[0.1, 0.1, 0.1, 0.1, 0.1, 0.1, 0.1, 2.0, 2.0]);
        assert_eq!(
            r.protocol().steps,
            vec![
                Step::Current { current: 0.1, duration: 78.0, until_voltage: None },
                Step::Table { time: vec![0.0, 1.0], current: vec![0.1, 2.0] },
                Step::Current { current: 2.0, duration: 30.0, until_voltage: None },
            ]
        );
        // Logged on the period (30 s after the last sample): a ramp across the gap.
        let r = rec(&[0.0, 1.0, 2.0, 3.0, 4.0, 34.0, 64.0, 94.0], &[0.1, 0.1, 0.1, 0.1, 0.1, 0.1, 0.1, 2.0]);
        assert_eq!(r.protocol().steps.last(), Some(&Step::Table { time: vec![0.0, 30.0], current: vec![0.1, 2.0] }));
    }

    #[test]
    fn a_decay_logged_at_each_threshold_crossing_stays_linear_after_its_first_change() {
        // A CV-like decay logged every time it falls by 0.5 A, 10-20 s apart, after a 30 s period.
        let time = [0.0, 1.0, 2.0, 3.0, 4.0, 34.0, 64.0, 74.0, 86.0, 101.0];
        let r = rec(&time, &[5.0, 5.0, 5.0, 5.0, 5.0, 5.0, 5.0, 4.5, 4.0, 3.5]);
        let (t, _) = r.with_triggered_jumps(0.01);
        assert_eq!(t, vec![0.0, 1.0, 2.0, 3.0, 4.0, 34.0, 64.0, 73.0, 74.0, 86.0, 101.0]);
    }
}
