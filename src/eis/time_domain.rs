//! Impedance measured in the time domain, as a potentiostat would: drive the full nonlinear
//! model from rest with a small sinusoidal current and fit the voltage's amplitude and phase.
//! Independent of the linearisation, so it validates it.

use serde::{Deserialize, Serialize};

use crate::error::Error;
use crate::models::Model;
use crate::simulation::UnderCurrent;
use crate::stats::least_squares;
use crate::solver::{DenseOutput, SolverOptions, SolverStats, Workspace, integrate};

/// Settings of a sinusoidal-current experiment.
#[derive(Clone, Debug, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct SineOptions {
    /// Current amplitude (A): small enough for a linear response.
    pub amplitude: f64,
    /// Time (s) to let transients decay before the fit window; the simulation runs at least
    /// `settle_periods` periods too.
    pub settle_time: f64,
    /// Least number of whole periods before the fit window.
    pub settle_periods: usize,
    /// Whole periods in the fit window.
    pub fit_periods: usize,
    /// Voltage samples per period in the fit window.
    pub samples_per_period: usize,
    /// Integrator settings (the step is capped at 1/40 of a period in addition).
    pub solver: SolverOptions,
}

impl Default for SineOptions {
    fn default() -> Self {
        Self {
            amplitude: 0.05,
            settle_time: 0.0,
            settle_periods: 3,
            fit_periods: 2,
            samples_per_period: 64,
            solver: SolverOptions { rtol: 1e-9, atol: 1e-10, ..SolverOptions::default() },
        }
    }
}

/// The fitted response at one frequency.
#[derive(Clone, Copy, Debug, Serialize)]
pub struct SineResponse {
    /// Frequency (Hz).
    pub frequency: f64,
    /// Impedance `-V_hat / I_hat` (ohm), real and imaginary parts.
    pub z_re: f64,
    pub z_im: f64,
    /// Root-mean-square residual of the fit (V): non-linearity plus left-over transients.
    pub residual: f64,
    /// Integrator work.
    pub stats: SolverStats,
}

/// Drives `model` from the rest state `y_rest` (consistent at zero current) with a sinusoidal
/// current of `frequency` (Hz) and fits `V(t) = p(t) + a sin(wt) + b cos(wt)` over the fit
/// window by least squares, where the quadratic `p` absorbs the slow drift of the state of
/// charge and of slowly decaying transients.
pub fn sine_response(
    model: &dyn Model,
    ws: &mut Workspace,
    y_rest: &[f64],
    frequency: f64,
    opts: &SineOptions,
) -> Result<SineResponse, Error> {
    if !(frequency > 0.0 && frequency.is_finite()) {
        return Err(Error::invalid("frequency", frequency, "must be positive and finite"));
    }
    if !(opts.amplitude > 0.0 && opts.amplitude.is_finite()) {
        return Err(Error::invalid("amplitude", opts.amplitude, "must be positive and finite"));
    }
    if opts.fit_periods == 0 || opts.samples_per_period < 4 {
        return Err(Error::InvalidSetting {
            field: "fit_periods".into(),
            reason: "need at least one fit period and 4 samples per period".into(),
        });
    }
    let period = 1.0 / frequency;
    let omega = 2.0 * std::f64::consts::PI * frequency;
    let settle = (opts.settle_time / period).ceil().max(opts.settle_periods as f64) * period;
    let t_end = settle + opts.fit_periods as f64 * period;
    let n_samples = opts.fit_periods * opts.samples_per_period;
    let times: Vec<f64> = (0..n_samples).map(|k| settle + (k as f64 + 0.5) * period / opts.samples_per_period as f64).collect();
    let current = |t: f64| opts.amplitude * (omega * t).sin();
    let mut y = y_rest.to_vec();
    let mut voltage = Vec::with_capacity(n_samples);
    let mut buf = vec![0.0; y.len()];
    let mut observer = |_t_old: f64, dense: &DenseOutput| {
        while voltage.len() < n_samples && times[voltage.len()] <= dense.t_end() {
            let t = times[voltage.len()];
            dense.eval(t, &mut buf);
            voltage.push(model.voltage(&buf, current(t)));
        }
    };
    let solver = SolverOptions { max_step: opts.solver.max_step.min(period / 40.0), ..opts.solver.clone() };
    let mut stats = SolverStats::default();
    let dae = UnderCurrent { model, current: |t: f64, _: &[f64]| current(t), kinks: Vec::new(), temperature: None };
    integrate(&dae, ws, &solver, 0.0, &mut y, t_end, None, &mut observer, &mut stats)?;
    if voltage.len() < n_samples {
        return Err(Error::Solver { t: t_end, reason: "the integration ended before the fit window".into() });
    }
    let (a, b, residual) = fit_sinusoid(&times, &voltage, omega)
        .ok_or_else(|| Error::Solver { t: t_end, reason: "the fit window cannot separate the sinusoid from the drift".into() })?;
    // V = a sin + b cos = Im((a + i b) e^{i w t}); I = Im(A e^{i w t}); Z = -V_hat / I_hat.
    Ok(SineResponse { frequency, z_re: -a / opts.amplitude, z_im: -b / opts.amplitude, residual, stats })
}

/// Least-squares fit of `v(t) = c0 + c1 s + c2 s^2 + a sin(wt) + b cos(wt)` (with `s` the
/// time scaled to [-1, 1] over the window); returns `(a, b, rms residual)`, or `None` when the
/// window cannot separate the terms.
fn fit_sinusoid(t: &[f64], v: &[f64], omega: f64) -> Option<(f64, f64, f64)> {
    let (t0, t1) = (t[0], t[t.len() - 1]);
    let s: Vec<f64> = t.iter().map(|t| (2.0 * t - t0 - t1) / (t1 - t0)).collect();
    let columns = [
        vec![1.0; t.len()],
        s.clone(),
        s.iter().map(|s| s * s).collect(),
        t.iter().map(|t| (omega * t).sin()).collect(),
        t.iter().map(|t| (omega * t).cos()).collect(),
    ];
    let (coef, _) = least_squares(&columns, v)?;
    let sq: f64 = (0..t.len()).map(|k| (v[k] - columns.iter().zip(&coef).map(|(c, b)| c[k] * b).sum::<f64>()).powi(2)).sum();
    Some((coef[3], coef[4], (sq / t.len() as f64).sqrt()))
}

#[cfg(test)]
mod tests {
    #[test]
    fn fit_recovers_a_sinusoid_on_a_drift() {
        let omega = 2.0 * std::f64::consts::PI * 0.3;
        let t: Vec<f64> = (0..300).map(|k| 10.0 + k as f64 * 0.02).collect();
        let v: Vec<f64> = t.iter().map(|&t| 3.7 - 1e-3 * t + 2e-5 * t * t + 0.3 * (omega * t).sin() - 0.1 * (omega * t).cos()).collect();
        let (a, b, r) = super::fit_sinusoid(&t, &v, omega).unwrap();
        assert!((a - 0.3).abs() < 1e-10 && (b + 0.1).abs() < 1e-10 && r < 1e-10, "{a} {b} {r}");
    }
}
