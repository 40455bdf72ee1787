//! Impedance measured in the time domain, as a potentiostat would: drive the full nonlinear
//! model from rest with a small sinusoidal current and fit the voltage's amplitude and phase.
//! Independent of the linearisation, so it validates it.

use serde::{Deserialize, Serialize};

use crate::error::Error;
use crate::models::Model;
use crate::simulation::UnderCurrent;
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
    let dae = UnderCurrent { model, current: |t: f64, _: &[f64]| current(t) };
    integrate(&dae, ws, &solver, 0.0, &mut y, t_end, None, &mut observer, &mut stats)?;
    if voltage.len() < n_samples {
        return Err(Error::Solver { t: t_end, reason: "the integration ended before the fit window".into() });
    }
    let (a, b, residual) = fit_sinusoid(&times, &voltage, omega);
    // V = a sin + b cos = Im((a + i b) e^{i w t}); I = Im(A e^{i w t}); Z = -V_hat / I_hat.
    Ok(SineResponse { frequency, z_re: -a / opts.amplitude, z_im: -b / opts.amplitude, residual, stats })
}

/// Least-squares fit of `v(t) = c0 + c1 s + c2 s^2 + a sin(wt) + b cos(wt)` (with `s` the
/// time scaled to [-1, 1] over the window); returns `(a, b, rms residual)`.
fn fit_sinusoid(t: &[f64], v: &[f64], omega: f64) -> (f64, f64, f64) {
    let (t0, t1) = (t[0], t[t.len() - 1]);
    let basis = |t: f64| {
        let s = (2.0 * t - t0 - t1) / (t1 - t0);
        [1.0, s, s * s, (omega * t).sin(), (omega * t).cos()]
    };
    let v_mean = v.iter().sum::<f64>() / v.len() as f64;
    let mut ata = [[0.0; 5]; 5];
    let mut atb = [0.0; 5];
    for (&ti, &vi) in t.iter().zip(v) {
        let phi = basis(ti);
        for r in 0..5 {
            atb[r] += phi[r] * (vi - v_mean);
            for c in 0..5 {
                ata[r][c] += phi[r] * phi[c];
            }
        }
    }
    let coef = solve5(ata, atb);
    let sq: f64 = t
        .iter()
        .zip(v)
        .map(|(&ti, &vi)| {
            let phi = basis(ti);
            let fit: f64 = phi.iter().zip(&coef).map(|(p, c)| p * c).sum();
            (vi - v_mean - fit).powi(2)
        })
        .sum();
    (coef[3], coef[4], (sq / t.len() as f64).sqrt())
}

/// Gaussian elimination with partial pivoting on a 5 x 5 system.
fn solve5(mut a: [[f64; 5]; 5], mut b: [f64; 5]) -> [f64; 5] {
    for k in 0..5 {
        let p = (k..5).max_by(|&i, &j| a[i][k].abs().total_cmp(&a[j][k].abs())).unwrap_or(k);
        a.swap(k, p);
        b.swap(k, p);
        for i in k + 1..5 {
            let f = a[i][k] / a[k][k];
            for j in k..5 {
                a[i][j] -= f * a[k][j];
            }
            b[i] -= f * b[k];
        }
    }
    let mut x = [0.0; 5];
    for k in (0..5).rev() {
        let s: f64 = (k + 1..5).map(|j| a[k][j] * x[j]).sum();
        x[k] = (b[k] - s) / a[k][k];
    }
    x
}

#[cfg(test)]
mod tests {
    #[test]
    fn fit_recovers_a_sinusoid_on_a_drift() {
        let omega = 2.0 * std::f64::consts::PI * 0.3;
        let t: Vec<f64> = (0..300).map(|k| 10.0 + k as f64 * 0.02).collect();
        let v: Vec<f64> = t.iter().map(|&t| 3.7 - 1e-3 * t + 2e-5 * t * t + 0.3 * (omega * t).sin() - 0.1 * (omega * t).cos()).collect();
        let (a, b, r) = super::fit_sinusoid(&t, &v, omega);
        assert!((a - 0.3).abs() < 1e-10 && (b + 0.1).abs() < 1e-10 && r < 1e-10, "{a} {b} {r}");
    }
}
