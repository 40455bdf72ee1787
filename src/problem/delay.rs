//! A voltage channel out of step with the current channel: a logger that stamps each voltage
//! `tau` seconds after it was measured (unsynchronised messages, a filter's group delay), so
//! the voltage recorded at `t` is the cell's at `t - tau` (negative `tau`: stamped early). A fit
//! path of the recording, not of the cell: the model is read at the shifted times, and its
//! sensitivity to `tau` is minus the voltage's slope there.

use super::fitting::FitParameter;

/// Fit path of the voltage channel's delay (s) behind the current channel.
pub const VOLTAGE_DELAY: &str = "data.voltage_delay";

/// Half-width (s) of the central difference that gives the voltage's slope.
const SLOPE_HALF_WIDTH: f64 = 0.5;

/// Whether `path` is the delay's fit path.
pub fn is_delay(path: &str) -> bool {
    path == VOLTAGE_DELAY
}

/// The delay (s) at the fitted `values` of `parameters` (or held in `pinned`), `None` when it
/// is not fitted.
pub fn delay_at(parameters: &[FitParameter], values: &[f64], pinned: &[(FitParameter, f64)]) -> Option<f64> {
    parameters.iter().zip(values).map(|(p, v)| (p, *v)).chain(pinned.iter().map(|(p, v)| (p, *v))).find(|(p, _)| is_delay(&p.path)).map(|(_, v)| v)
}

/// The output times of a replay read with a delay: each distinct recorded time `t` (s from the
/// start), the time `t - tau` its voltage comes from (held at the first and last time), and,
/// for the sensitivity, the times either side of that one.
#[derive(Clone, Debug)]
pub struct DelayedTimes {
    /// Sorted distinct output times (s) to simulate.
    pub times: Vec<f64>,
    /// Per recorded time: the output index of `t - tau`, and of `t` itself (for channels that
    /// are not delayed, e.g. the temperature).
    pub voltage_at: Vec<usize>,
    pub plain_at: Vec<usize>,
    /// Per recorded time: the output indices just after and just before `t - tau`.
    slope_at: Vec<(usize, usize)>,
}

impl DelayedTimes {
    /// The output times for recorded times `t_eval` (sorted, distinct, from 0) and delay `tau` (s).
    pub fn new(t_eval: &[f64], tau: f64) -> Self {
        let end = t_eval.last().copied().unwrap_or(0.0);
        let clamp = |t: f64| t.clamp(0.0, end);
        let shifted: Vec<f64> = t_eval.iter().map(|t| clamp(t - tau)).collect();
        let mut times: Vec<f64> = t_eval.iter().copied().chain(shifted.iter().flat_map(|s| [*s, clamp(s + SLOPE_HALF_WIDTH), clamp(s - SLOPE_HALF_WIDTH)])).collect();
        times.sort_by(f64::total_cmp);
        times.dedup();
        let index = |t: f64| times.binary_search_by(|x| x.total_cmp(&t)).expect("an output time");
        let voltage_at = shifted.iter().map(|s| index(*s)).collect();
        let plain_at = t_eval.iter().map(|t| index(*t)).collect();
        let slope_at = shifted.iter().map(|s| (index(clamp(s + SLOPE_HALF_WIDTH)), index(clamp(s - SLOPE_HALF_WIDTH)))).collect();
        Self { times, voltage_at, plain_at, slope_at }
    }

    /// Per recorded time, `dV_recorded / dtau = -dV/dt` at `t - tau` (V/s) from the outputs `v`
    /// at [`Self::times`] (one-sided where the shifted time is held at an end).
    pub fn delay_sensitivity(&self, v: &[f64]) -> Vec<f64> {
        self.slope_at
            .iter()
            .map(|&(after, before)| {
                let dt = self.times[after] - self.times[before];
                if dt > 0.0 { -(v[after] - v[before]) / dt } else { 0.0 }
            })
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_delayed_channel_reads_the_voltage_earlier_and_its_slope() {
        let t_eval: Vec<f64> = (0..=10).map(f64::from).collect();
        let d = DelayedTimes::new(&t_eval, 2.0);
        // A voltage that rises 0.01 V/s: read 2 s late it is 0.02 V low, and holds the first
        // value over the first 2 s.
        let v: Vec<f64> = d.times.iter().map(|t| 3.7 + 0.01 * t).collect();
        for (k, t) in t_eval.iter().enumerate() {
            assert!((v[d.voltage_at[k]] - (3.7 + 0.01 * (t - 2.0).max(0.0))).abs() < 1e-12);
            assert!((v[d.plain_at[k]] - (3.7 + 0.01 * t)).abs() < 1e-12);
        }
        let s = d.delay_sensitivity(&v);
        assert!(s.iter().all(|x| (x + 0.01).abs() < 1e-12), "{s:?}");
        let pinned = [(FitParameter::linear(VOLTAGE_DELAY, 0.0, -5.0, 5.0), 1.5)];
        assert_eq!(delay_at(&[], &[], &pinned), Some(1.5));
        assert_eq!(delay_at(&[FitParameter::linear("cell.contact_resistance", 0.0, 0.0, 1.0)], &[0.1], &[]), None);
    }
}
