//! Locating a mismatch: where in time, after which current steps, in which capacity band,
//! at rest or under load, how it scales with current, and whether noise can explain it.

use serde::Serialize;

use super::features::Features;
use crate::stats::{TestResult, least_squares, ljung_box, noise_from_dense_differences, rms, runs_test};
use crate::data::Recording;

/// Straight-line fit `r ≈ a + b x`.
#[derive(Clone, Copy, Debug, Serialize)]
pub struct Regression {
    /// Slope `b` (V per unit of the regressor).
    pub slope: f64,
    /// Coefficient of determination (-).
    pub r2: f64,
}

fn regress(x: &[f64], y: &[f64]) -> Option<Regression> {
    least_squares(&[vec![1.0; x.len()], x.to_vec()], y).map(|(b, r2)| Regression { slope: b[1], r2 })
}

/// Share of the squared residual in a window of time after current steps, among the points
/// under load or among those at rest (so a residual present throughout every load does not
/// look concentrated just because rests are long).
#[derive(Clone, Debug, Serialize)]
pub struct Window {
    /// Whether the window covers points under load (else at rest).
    pub load: bool,
    /// Window start and end (s after the last current step).
    pub from: f64,
    pub to: f64,
    /// Fraction of the load (or rest) points in the window (-).
    pub point_share: f64,
    /// Fraction of the squared residual of the load (or rest) points in the window (-).
    pub error_share: f64,
    /// Fraction of the whole squared residual in the window (-).
    pub total_share: f64,
}

impl Window {
    /// How much denser the error is in this window than on average (-).
    pub fn concentration(&self) -> f64 {
        if self.point_share > 0.0 { self.error_share / self.point_share } else { 0.0 }
    }
}

/// Residual statistics over a band of a variable (current, discharged capacity).
#[derive(Clone, Debug, Serialize)]
pub struct Band {
    pub lower: f64,
    pub upper: f64,
    pub points: usize,
    /// Mean residual (V).
    pub mean: f64,
    /// RMS residual (V).
    pub rms: f64,
}

/// A stretch of the recording where the residual stands out.
#[derive(Clone, Debug, Serialize)]
pub struct Segment {
    /// Start and end time (s).
    pub start: f64,
    pub end: f64,
    /// Mean current (A) and mean residual (V) over the segment.
    pub mean_current: f64,
    pub mean_residual: f64,
    /// Share of the total squared residual (-).
    pub error_share: f64,
}

/// How the residual responds at current steps.
#[derive(Clone, Debug, Serialize)]
pub struct StepResponse {
    pub steps: usize,
    /// `-Δr / ΔI` across the steps (ohm): the series resistance the model lacks.
    pub instantaneous_resistance: f64,
    /// `R²` of `Δr` against `ΔI` (-).
    pub r2: f64,
    pub windows: Vec<Window>,
}

/// Everything the residual analysis found. Residuals are `r = V_model - V_data` (V), as in fitting.
#[derive(Clone, Debug, Serialize)]
pub struct ResidualAnalysis {
    /// Points analysed (repeated-time points excluded).
    pub points: usize,
    pub rmse: f64,
    pub mean: f64,
    pub max_abs: f64,
    /// Time of the largest |r| (s).
    pub time_of_max: f64,
    /// White-noise level estimated from first differences of the residual (V).
    pub noise: f64,
    /// `rmse / noise` (-): about 1 when the residual is noise.
    pub structure_ratio: f64,
    pub lag1_autocorrelation: f64,
    pub ljung_box: TestResult,
    pub runs: TestResult,
    /// Whether noise cannot explain the residual: a whiteness test rejects at p < 0.001, or
    /// the RMS is more than 1.5 times the point-to-point noise.
    pub structured: bool,
    /// `r` against current (slope in ohm).
    pub vs_current: Option<Regression>,
    /// `r` against discharged capacity (slope in V/(A h)).
    pub vs_capacity: Option<Regression>,
    /// `r` against temperature rise (V/K), when temperature is recorded.
    pub vs_temperature: Option<Regression>,
    /// `r` against temperature rise times current (V/(K A)), when temperature is recorded:
    /// faster kinetics in a warmer cell show under load only.
    pub vs_heating: Option<Regression>,
    pub step_response: StepResponse,
    /// RMS residual at rest and under load (V).
    pub rest_rms: f64,
    pub load_rms: f64,
    /// Mean residual (V) in rests that follow a discharge and in rests that follow a charge
    /// (NaN when there are none): a difference of sign marks OCV hysteresis.
    pub rest_after_discharge: f64,
    pub rest_after_charge: f64,
    /// Bands of |current| (A).
    pub current_bands: Vec<Band>,
    /// Bands of state of charge relative to the start, `-q / Q_nominal` (-).
    pub soc_bands: Vec<Band>,
    /// Stretches where the residual stands out, largest error first.
    pub segments: Vec<Segment>,
}

/// Least temperature rise (K) the residual is regressed on: ten steps of a 0.1 K thermocouple.
pub const MIN_TEMPERATURE_SPAN: f64 = 1.0;

fn bands(x: &[f64], r: &[f64], edges: &[f64]) -> Vec<Band> {
    edges
        .windows(2)
        .enumerate()
        .filter_map(|(b, e)| {
            let last = b + 2 == edges.len();
            let sel: Vec<f64> =
                x.iter().zip(r).filter(|(v, _)| **v >= e[0] && (**v < e[1] || (last && **v <= e[1]))).map(|(_, r)| *r).collect();
            (!sel.is_empty()).then(|| Band {
                lower: e[0],
                upper: e[1],
                points: sel.len(),
                mean: sel.iter().sum::<f64>() / sel.len() as f64,
                rms: rms(&sel),
            })
        })
        .collect()
}

/// Analyses the residual `r = V_model - V_data` at every recorded point.
pub fn analyse(rec: &Recording, features: &Features, residual: &[f64], nominal_capacity: f64) -> ResidualAnalysis {
    let idx: Vec<usize> = (0..residual.len()).filter(|&k| features.valid[k]).collect();
    let r: Vec<f64> = idx.iter().map(|&k| residual[k]).collect();
    let pick = |v: &[f64]| idx.iter().map(|&k| v[k]).collect::<Vec<f64>>();
    let (current, capacity, time) = (pick(&rec.current), pick(&features.capacity), pick(&rec.time));
    let n = r.len();
    let total_sq: f64 = r.iter().map(|v| v * v).sum::<f64>().max(f64::MIN_POSITIVE);
    let rmse = rms(&r);
    let (k_max, max_abs) = r.iter().enumerate().fold((0, 0.0f64), |m, (k, v)| if v.abs() > m.1 { (k, v.abs()) } else { m });
    let noise = noise_from_dense_differences(&r, &time).max(1e-9);
    let lags = (n / 5).clamp(1, 20);
    let lb = ljung_box(&r, lags);
    let runs = runs_test(&r);
    let structure_ratio = rmse / noise;
    let structured = lb.p_value < 1e-3 || runs.p_value < 1e-3 || structure_ratio > 1.5;

    // Steps: residual jump against current jump.
    let (mut di, mut dr) = (Vec::new(), Vec::new());
    for s in &features.steps {
        let before = (0..=s.before).rev().find(|&k| features.valid[k]);
        let after = (s.after..residual.len()).find(|&k| features.valid[k]);
        if let (Some(b), Some(a)) = (before, after) {
            di.push(s.delta);
            dr.push(residual[a] - residual[b]);
        }
    }
    let (instantaneous_resistance, step_r2) = if di.len() >= 2 {
        // Through the origin: Δr = R ΔI (a model without a series resistance R sits R I above
        // the data under a discharge current I).
        let num: f64 = di.iter().zip(&dr).map(|(a, b)| a * b).sum();
        let den: f64 = di.iter().map(|a| a * a).sum();
        let slope = num / den;
        let ss: f64 = dr.iter().map(|v| v * v).sum();
        let res: f64 = di.iter().zip(&dr).map(|(a, b)| (b - slope * a).powi(2)).sum();
        (slope, if ss > 0.0 { 1.0 - res / ss } else { 0.0 })
    } else {
        (0.0, 0.0)
    };
    // A temperature that moves by less than a few thermocouple steps (0.1 K) carries no
    // signal: regressing on it turns one step into millivolts per kelvin.
    let resolved_rise = features.temperature_rise.as_ref().filter(|t| t.iter().fold(0.0f64, |m, v| m.max(v.abs())) >= MIN_TEMPERATURE_SPAN);
    let since = pick(&features.since_step);
    let mut windows = Vec::new();
    for load in [true, false] {
        let group: Vec<usize> = (0..n).filter(|&k| (current[k] != 0.0) == load).collect();
        let group_sq: f64 = group.iter().map(|&k| r[k] * r[k]).sum::<f64>().max(f64::MIN_POSITIVE);
        for (from, to) in [(0.0, 2.5), (2.5, 30.0), (30.0, 300.0), (300.0, f64::INFINITY)] {
            let inside: Vec<usize> = group.iter().copied().filter(|&k| since[k] >= from && since[k] < to).collect();
            let sq: f64 = inside.iter().map(|&k| r[k] * r[k]).sum();
            windows.push(Window {
                load,
                from,
                to,
                point_share: inside.len() as f64 / group.len().max(1) as f64,
                error_share: sq / group_sq,
                total_share: sq / total_sq,
            });
        }
    }

    // Sign of the last non-zero current before each point.
    let last_sign: Vec<f64> = current
        .iter()
        .scan(0.0, |sign, &i| {
            if i != 0.0 {
                *sign = i.signum();
            }
            Some(*sign)
        })
        .collect();
    let rest_mean = |sign: f64| {
        let sel: Vec<f64> = (0..n).filter(|&k| current[k] == 0.0 && last_sign[k] == sign).map(|k| r[k]).collect();
        if sel.is_empty() { f64::NAN } else { sel.iter().sum::<f64>() / sel.len() as f64 }
    };
    let (rest_rms, load_rms) = super::at_rest::rest_and_load_rms(rec, residual);
    let abs_i: Vec<f64> = current.iter().map(|v| v.abs()).collect();
    let i_max = abs_i.iter().fold(0.0f64, |m, v| m.max(*v));
    let mut current_edges = vec![0.0, 1e-9 * i_max.max(1e-12)];
    current_edges.extend((1..=4).map(|k| f64::from(k) * 0.25 * i_max));
    let soc: Vec<f64> = capacity.iter().map(|q| -q / nominal_capacity).collect();
    let (s0, s1) = soc.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| (a.min(*v), b.max(*v)));
    let soc_edges: Vec<f64> = (0..=5).map(|k| s0 + (s1 - s0) * f64::from(k) / 5.0).collect();

    ResidualAnalysis {
        points: n,
        rmse,
        mean: r.iter().sum::<f64>() / n.max(1) as f64,
        max_abs,
        time_of_max: time.get(k_max).copied().unwrap_or(0.0),
        noise,
        structure_ratio,
        lag1_autocorrelation: crate::stats::autocorrelation(&r, 1)[0],
        ljung_box: lb,
        runs,
        structured,
        vs_current: regress(&current, &r),
        vs_capacity: regress(&capacity, &r),
        vs_temperature: resolved_rise.and_then(|t| regress(&pick(t), &r)),
        vs_heating: resolved_rise.and_then(|t| {
            let heating: Vec<f64> = pick(t).iter().zip(&current).map(|(t, i)| t * i).collect();
            regress(&heating, &r)
        }),
        step_response: StepResponse { steps: di.len(), instantaneous_resistance, r2: step_r2, windows },
        rest_rms,
        rest_after_discharge: rest_mean(1.0),
        rest_after_charge: rest_mean(-1.0),
        load_rms,
        current_bands: bands(&abs_i, &r, &current_edges),
        soc_bands: if s1 > s0 { bands(&soc, &r, &soc_edges) } else { Vec::new() },
        segments: segments(&time, &current, &r, noise.max(0.0) * 3.0),
    }
}

/// Stretches where a centred moving RMS of the residual exceeds both `floor` and the overall
/// RMS; stretches closer than ten points are merged; the eight largest are returned.
fn segments(time: &[f64], current: &[f64], r: &[f64], floor: f64) -> Vec<Segment> {
    let n = r.len();
    let total_sq: f64 = r.iter().map(|v| v * v).sum::<f64>().max(f64::MIN_POSITIVE);
    let threshold = floor.max(rms(r));
    let half = 5usize;
    let above: Vec<bool> = (0..n)
        .map(|k| {
            let (a, b) = (k.saturating_sub(half), (k + half + 1).min(n));
            rms(&r[a..b]) > threshold
        })
        .collect();
    let mut runs: Vec<(usize, usize)> = Vec::new();
    for k in (0..n).filter(|&k| above[k]) {
        match runs.last_mut() {
            Some((_, end)) if k <= *end + 10 => *end = k,
            _ => runs.push((k, k)),
        }
    }
    let mut out: Vec<Segment> = runs
        .into_iter()
        .filter(|(a, b)| b > a)
        .map(|(a, b)| {
            let len = (b - a + 1) as f64;
            Segment {
                start: time[a],
                end: time[b],
                mean_current: current[a..=b].iter().sum::<f64>() / len,
                mean_residual: r[a..=b].iter().sum::<f64>() / len,
                error_share: r[a..=b].iter().map(|v| v * v).sum::<f64>() / total_sq,
            }
        })
        .collect();
    out.sort_by(|a, b| b.error_share.total_cmp(&a.error_share));
    out.truncate(8);
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A residual `R I` (a missing series resistance) on a pulse recording: the step jumps
    /// and the current regression both give `R`, rests carry no error, and the load windows
    /// show no concentration after the steps.
    #[test]
    fn a_missing_resistance_is_located_at_load_and_scaled_with_current() {
        let (mut time, mut current) = (Vec::new(), Vec::new());
        let mut t = 0.0;
        // Pulses of equal magnitude, so every load point carries the same error.
        for (i, d) in [(5.0, 60), (0.0, 120), (-5.0, 60), (0.0, 120), (5.0, 60), (0.0, 120)] {
            for k in 0..=d {
                time.push(t + f64::from(k));
                current.push(i);
            }
            t += f64::from(d);
        }
        let voltage = vec![3.7; time.len()];
        let rec = Recording { time, current, voltage, temperature: None };
        let f = Features::of(&rec);
        let r: Vec<f64> = rec.current.iter().map(|i| 0.01 * i).collect();
        let a = analyse(&rec, &f, &r, 5.0);
        assert!((a.step_response.instantaneous_resistance - 0.01).abs() < 1e-12);
        assert!((a.vs_current.unwrap().slope - 0.01).abs() < 1e-12);
        assert!(a.rest_rms < 1e-15 && a.load_rms > 0.05);
        for w in a.step_response.windows.iter().filter(|w| w.load && w.point_share > 0.0) {
            assert!((w.concentration() - 1.0).abs() < 1e-9, "{w:?}");
        }
    }
}
