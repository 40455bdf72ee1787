//! Pulses of a resistance test or a GITT: constant-current steps that follow a rest, with the
//! rested voltage before them, the relaxed voltage after them, their resistance after a given
//! time and the classic Weppner-Huggins diffusivity estimate.

use serde::Serialize;

use super::Recording;
use super::cycler::{Step, StepKind};
use crate::params::function::interpolate;

/// A constant-current step that follows a rest.
#[derive(Clone, Debug, Serialize)]
pub struct Pulse {
    /// Step number in the recording ([`super::cycler::steps`]).
    pub step: usize,
    /// First and last row of the pulse, and the last row of the rest after it (if any).
    pub first: usize,
    pub last: usize,
    pub relaxed_row: Option<usize>,
    /// Time of the pulse's first row (s) and its duration (s).
    pub start: f64,
    pub duration: f64,
    /// Mean current (A, discharge positive).
    pub current: f64,
    /// Voltage (V) at the end of the rest before, at the pulse's first and last rows, and at
    /// the end of the rest after (if any).
    pub rest_voltage: f64,
    pub start_voltage: f64,
    pub end_voltage: f64,
    pub relaxed_voltage: Option<f64>,
    /// Charge discharged from the recording's start to the pulse's start (A h).
    pub discharged_before: f64,
}

/// The pulses of `rec`: every constant-current step (CC or pulse) directly after a rest.
pub fn pulses(rec: &Recording, steps: &[Step]) -> Vec<Pulse> {
    let (t, i) = (&rec.time, &rec.current);
    let mut discharged = vec![0.0; t.len()];
    for k in 1..t.len() {
        discharged[k] = discharged[k - 1] + 0.5 * (i[k - 1] + i[k]) * (t[k] - t[k - 1]) / 3600.0;
    }
    steps
        .windows(2)
        .enumerate()
        .filter(|(_, w)| w[0].kind == StepKind::Rest && matches!(w[1].kind, StepKind::Cc | StepKind::Pulse) && w[1].last > w[1].first)
        .map(|(k, w)| {
            let (rest, s) = (&w[0], &w[1]);
            let after = steps.get(k + 2).filter(|a| a.kind == StepKind::Rest);
            Pulse {
                step: s.number,
                first: s.first,
                last: s.last,
                relaxed_row: after.map(|a| a.last),
                start: t[s.first],
                duration: t[s.last] - t[s.first],
                current: s.mean_current,
                rest_voltage: rec.voltage[rest.last],
                start_voltage: rec.voltage[s.first],
                end_voltage: rec.voltage[s.last],
                relaxed_voltage: after.map(|a| rec.voltage[a.last]),
                discharged_before: discharged[s.first],
            }
        })
        .collect()
}

impl Pulse {
    /// The rows of the pulse and the rest after it as a recording of their own, from the
    /// rested row before the pulse (time from 0).
    pub fn window(&self, rec: &Recording) -> Recording {
        let (a, b) = (self.first - 1, self.relaxed_row.unwrap_or(self.last));
        let t0 = rec.time[a];
        Recording {
            time: rec.time[a..=b].iter().map(|t| t - t0).collect(),
            current: rec.current[a..=b].to_vec(),
            voltage: rec.voltage[a..=b].to_vec(),
            temperature: rec.temperature.as_ref().map(|t| t[a..=b].to_vec()),
        }
    }

    /// Resistance (ohm) `dt` seconds into the pulse: `(V_rest - V(t0 + dt)) / I`, the voltage
    /// interpolated between the pulse's rows; `None` when the pulse is shorter than `dt`.
    pub fn resistance(&self, rec: &Recording, dt: f64) -> Option<f64> {
        if dt > self.duration || self.current == 0.0 {
            return None;
        }
        let v = interpolate(&rec.time[self.first..=self.last], &rec.voltage[self.first..=self.last], self.start + dt);
        Some((self.rest_voltage - v) / self.current)
    }

    /// The Weppner-Huggins estimate of the solid diffusivity (m^2/s) of spherical particles of
    /// radius `radius` (m): `D = 4 / (pi tau) (R / 3)^2 (dE_s / dE_t)^2`, with `tau` the pulse
    /// duration, `dE_s` the change of the rested voltage over the pulse and `dE_t` the change
    /// during the pulse after the instantaneous jump. It assumes the voltage follows `sqrt(t)`
    /// throughout (`tau` much shorter than `R^2 / D`) and one electrode; in a full cell both
    /// electrodes respond, so it is a first estimate. `None` without a rest after the pulse.
    pub fn weppner_huggins(&self, radius: f64) -> Option<f64> {
        let d_es = self.relaxed_voltage? - self.rest_voltage;
        let d_et = self.end_voltage - self.start_voltage;
        (d_et != 0.0).then(|| 4.0 / (std::f64::consts::PI * self.duration) * (radius / 3.0).powi(2) * (d_es / d_et).powi(2))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::data::cycler::steps;

    /// A cell that is a 20 mOhm resistor in series with a `sqrt(t)` transient: the resistance
    /// at 1 s is 20 mOhm plus the transient's share, and Weppner-Huggins inverts the transient
    /// it was built from.
    #[test]
    fn resistance_and_weppner_huggins_of_a_known_response() {
        let (r0, current, tau, radius, d) = (0.02, 1.0, 100.0, 5e-6, 1e-14);
        let (d_es, e0) = (-0.01, 3.8);
        // dE_t from the formula: dE_t = dE_s (R/3) sqrt(4 / (pi tau D)).
        let d_et = d_es * (radius / 3.0) * (4.0 / (std::f64::consts::PI * tau * d)).sqrt();
        let mut rec = Recording::default();
        let mut push = |t: f64, i: f64, v: f64| {
            rec.time.push(t);
            rec.current.push(i);
            rec.voltage.push(v);
        };
        for k in 0..=10 {
            push(k as f64, 0.0, e0);
        }
        for k in 0..=100 {
            push(10.0 + k as f64, current, e0 - r0 * current + d_et * (k as f64 / tau).sqrt());
        }
        for k in 0..=50 {
            push(110.0 + k as f64, 0.0, e0 + d_es);
        }
        let s = steps(&rec, None);
        let p = pulses(&rec, &s);
        assert_eq!(p.len(), 1, "{}", crate::data::cycler::step_table(&s));
        let p = &p[0];
        assert_eq!((p.duration, p.current, p.rest_voltage), (tau, current, e0));
        let want = r0 - d_et * (1.0 / tau).sqrt();
        assert!((p.resistance(&rec, 1.0).unwrap() - want).abs() < 1e-12, "{:?}", p.resistance(&rec, 1.0));
        assert!(p.resistance(&rec, 101.0).is_none());
        let got = p.weppner_huggins(radius).unwrap();
        assert!((got / d - 1.0).abs() < 1e-9, "{got}");
        assert!((p.discharged_before).abs() < 1e-15);
    }
}
