//! Signals derived from a recording alone (no model): discharged capacity, current steps,
//! time since the last step, low-pass filtered current and a hysteresis-like state. They are
//! the regressors of the residual signatures.

use crate::data::Recording;

/// A current step in the recording.
#[derive(Clone, Copy, Debug, serde::Serialize)]
pub struct CurrentStep {
    /// Time of the step (s, recording clock).
    pub time: f64,
    /// Index of the last point before the step.
    pub before: usize,
    /// Index of the first point after the step.
    pub after: usize,
    /// Current change (A).
    pub delta: f64,
}

/// Derived signals, one value per recorded point.
#[derive(Clone, Debug)]
pub struct Features {
    /// Points that enter statistics: not on either side of a repeated time.
    pub valid: Vec<bool>,
    /// Charge discharged since the start (A h), trapezoidal.
    pub capacity: Vec<f64>,
    /// Steps larger than 5 % of the largest |current|.
    pub steps: Vec<CurrentStep>,
    /// Time since the last step (s); infinite before the first.
    pub since_step: Vec<f64>,
    /// Temperature rise over the first recorded temperature (K), when recorded.
    pub temperature_rise: Option<Vec<f64>>,
    /// Rests of at least 60 s that follow a charge and that follow a discharge.
    pub rests_after_charge: usize,
    pub rests_after_discharge: usize,
    /// Distinct load levels: |current| clusters more than 30 % apart, each held for 60 s.
    pub distinct_rates: usize,
    /// The longest rest (s) that a load follows (|current| at most 1 % of the largest).
    pub longest_rest_before_load: f64,
}

/// Rests of at least `min_rest` seconds after charge and after discharge, the number of
/// distinct |current| levels (more than 30 % apart) held for at least `min_rest` seconds, and
/// the longest rest (s) that a load follows.
fn rests_and_rates(rec: &Recording, min_rest: f64) -> (usize, usize, usize, f64) {
    let (t, i) = (&rec.time, &rec.current);
    let largest = i.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    let floor = 0.01 * largest.max(1e-12);
    let (mut after_charge, mut after_discharge) = (0, 0);
    let mut last_sign = 0.0;
    let mut longest_rest = 0.0f64;
    let mut k = 0;
    // Time held at each |current| level (A, s).
    let mut levels: Vec<(f64, f64)> = Vec::new();
    while k < t.len() {
        let start = k;
        let resting = i[k].abs() <= floor;
        while k + 1 < t.len() && (i[k + 1].abs() <= floor) == resting && (resting || i[k + 1].signum() == i[start].signum()) {
            k += 1;
        }
        let span = t[k] - t[start];
        if resting {
            if k + 1 < t.len() {
                longest_rest = longest_rest.max(t[k + 1] - t[start]);
            }
            if span >= min_rest {
                if last_sign > 0.0 { after_discharge += 1 } else if last_sign < 0.0 { after_charge += 1 }
            }
        } else {
            last_sign = i[start].signum();
            for j in start..k {
                let a = i[j].abs();
                let dt = t[j + 1] - t[j];
                match levels.iter_mut().find(|(l, _)| (a - *l).abs() <= 0.3 * l.max(a)) {
                    Some(level) => level.1 += dt,
                    None => levels.push((a, dt)),
                }
            }
        }
        k += 1;
    }
    (after_charge, after_discharge, levels.iter().filter(|(_, held)| *held >= min_rest).count(), longest_rest)
}

impl Features {
    /// The window of charge (A h) the recording moves: the widest span of its discharged
    /// charge.
    pub fn charge_window(&self) -> f64 {
        charge_window(&self.capacity)
    }

    pub fn of(rec: &Recording) -> Self {
        let n = rec.time.len();
        let (t, i) = (&rec.time, &rec.current);
        let valid: Vec<bool> = (0..n).map(|k| !rec.is_repeated(k)).collect();
        let mut capacity = vec![0.0; n];
        for k in 1..n {
            capacity[k] = capacity[k - 1] + 0.5 * (i[k] + i[k - 1]) * (t[k] - t[k - 1]) / 3600.0;
        }
        let largest = i.iter().fold(0.0f64, |m, v| m.max(v.abs()));
        let threshold = 0.05 * largest.max(1e-12);
        let mut steps = Vec::new();
        for k in 0..n.saturating_sub(1) {
            let delta = i[k + 1] - i[k];
            if delta.abs() > threshold {
                // A jump at a repeated time, or a change between two samples.
                steps.push(CurrentStep { time: t[k + 1], before: k, after: k + 1, delta });
            }
        }
        let mut since_step = vec![f64::INFINITY; n];
        let mut last: Option<f64> = None;
        let mut next = 0;
        for k in 0..n {
            while next < steps.len() && steps[next].after <= k {
                last = Some(steps[next].time);
                next += 1;
            }
            if let Some(ts) = last {
                since_step[k] = t[k] - ts;
            }
        }
        let temperature_rise = rec.temperature.as_ref().map(|temp| temp.iter().map(|v| v - temp[0]).collect());
        let (rests_after_charge, rests_after_discharge, distinct_rates, longest_rest_before_load) = rests_and_rates(rec, 60.0);
        Self { valid, capacity, steps, since_step, temperature_rise, rests_after_charge, rests_after_discharge, distinct_rates, longest_rest_before_load }
    }

    /// First-order low-pass filter of `signal` with time constant `tau` (s), exact for a
    /// signal linear between samples; a repeated time holds the state.
    pub fn low_pass(rec: &Recording, signal: &[f64], tau: f64) -> Vec<f64> {
        let t = &rec.time;
        let mut out = vec![0.0; signal.len()];
        for k in 1..signal.len() {
            let h = t[k] - t[k - 1];
            if h <= 0.0 {
                out[k] = out[k - 1];
                continue;
            }
            let a = (-h / tau).exp();
            // x' = (u - x)/tau with u linear from u0 to u1 over h.
            let (u0, u1) = (signal[k - 1], signal[k]);
            let slope = (u1 - u0) / h;
            out[k] = a * out[k - 1] + (1.0 - a) * u0 + slope * (h - tau * (1.0 - a));
        }
        out
    }

    /// The values of `x` (one per recorded point) at the usable points, in order.
    pub fn usable(&self, x: &[f64]) -> Vec<f64> {
        x.iter().zip(&self.valid).filter(|(_, ok)| **ok).map(|(v, _)| *v).collect()
    }

    /// Unit-amplitude hysteresis state `dh/dt = k |I| / (3600 Q) (-sign(I) - h)` from zero,
    /// for rate `k` (-) and capacity `q_nominal` (A h), by exact steps at constant current.
    pub fn hysteresis_state(rec: &Recording, rate: f64, q_nominal: f64) -> Vec<f64> {
        let (t, i) = (&rec.time, &rec.current);
        let mut h = vec![0.0; t.len()];
        for k in 1..t.len() {
            let dt = t[k] - t[k - 1];
            let current = 0.5 * (i[k] + i[k - 1]);
            let a = (-rate * current.abs() * dt / (3600.0 * q_nominal)).exp();
            let target = -current.signum();
            h[k] = if current == 0.0 { h[k - 1] } else { target + (h[k - 1] - target) * a };
        }
        h
    }
}

/// The largest fall and the largest rise of a sequence (each a later value against an earlier
/// one), both non-negative: how far a state went down, and how far up, at its widest.
pub fn largest_swings(x: &[f64]) -> (f64, f64) {
    let (mut low, mut high, mut fall, mut rise) = (f64::INFINITY, f64::NEG_INFINITY, 0.0f64, 0.0f64);
    for &v in x {
        (high, low) = (high.max(v), low.min(v));
        (fall, rise) = (fall.max(high - v), rise.max(v - low));
    }
    (fall, rise)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn rec(time: Vec<f64>, current: Vec<f64>) -> Recording {
        let n = time.len();
        Recording { time, current, voltage: vec![3.7; n], temperature: None }
    }

    /// The filter of a unit step equals `1 - exp(-t / tau)` at every sample.
    #[test]
    fn low_pass_of_a_step_is_the_analytic_response() {
        let mut time = vec![0.0, 10.0, 10.0];
        let mut current = vec![0.0, 0.0, 1.0];
        for k in 11..=60 {
            time.push(f64::from(k));
            current.push(1.0);
        }
        let r = rec(time, current);
        let y = Features::low_pass(&r, &r.current, 7.0);
        for (k, &t) in r.time.iter().enumerate().skip(3) {
            assert!((y[k] - (1.0 - (-(t - 10.0) / 7.0f64).exp())).abs() < 1e-12);
        }
        let f = Features::of(&r);
        assert_eq!(f.steps.len(), 1);
        assert_eq!(f.steps[0].time, 10.0);
        assert!(!f.valid[1] && !f.valid[2] && f.valid[3]);
        assert_eq!(f.since_step[12], 10.0);
        assert!((f.capacity[r.time.len() - 1] - 50.0 / 3600.0).abs() < 1e-12);
    }

    /// A state that falls to -0.55 and comes back to 0.17 swings 0.55 down and 0.72 up; one
    /// that only falls has no rise.
    #[test]
    fn largest_swings_count_each_direction() {
        let (fall, rise) = largest_swings(&[0.0, -0.3, -0.55, -0.2, 0.17, 0.1]);
        assert!((fall - 0.55).abs() < 1e-15 && (rise - 0.72).abs() < 1e-15, "{fall} {rise}");
        assert_eq!(largest_swings(&[0.0, -0.5, -0.9]), (0.9, 0.0));
        assert_eq!(largest_swings(&[]), (0.0, 0.0));
    }
}

/// The widest span (A h) of a cumulative discharged charge `capacity` (0 when empty).
pub fn charge_window(capacity: &[f64]) -> f64 {
    let (lo, hi) = capacity.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), q| (a.min(*q), b.max(*q)));
    (hi - lo).max(0.0)
}
