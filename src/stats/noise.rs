//! Robust white-noise level of a recorded series from its first differences.

use super::descriptive::median;

/// Robust white-noise level of a series sampled densely relative to its structure: the
/// median absolute first difference divided by `0.6745 √2` (exact for Gaussian noise on a
/// locally constant signal; jumps and slow trends barely move the median).
pub fn noise_from_differences(x: &[f64]) -> f64 {
    noise_of(x.windows(2).map(|w| (w[1] - w[0]).abs()).collect())
}

/// White-noise level from absolute first differences `d`: their median over `0.6745 √2`.
fn noise_of(d: Vec<f64>) -> f64 {
    median(&d) / (0.674_489_75 * std::f64::consts::SQRT_2)
}

/// [`noise_from_differences`] over the neighbours sampled at most 1.5 times the 10th-percentile
/// time step apart (`t` in s, one per value): on irregular sampling (a cycler logging every
/// second near steps and every minute on long stretches) the wide pairs carry the signal's
/// drift and read as noise. On uniform sampling every pair is kept (the same estimate); with
/// fewer than 30 dense pairs, all are used.
pub fn noise_from_dense_differences(x: &[f64], t: &[f64]) -> f64 {
    let mut steps: Vec<f64> = t.windows(2).map(|w| w[1] - w[0]).filter(|dt| *dt > 0.0).collect();
    if steps.is_empty() {
        return noise_from_differences(x);
    }
    steps.sort_by(f64::total_cmp);
    let dense = 1.5 * steps[steps.len() / 10];
    let d: Vec<f64> = x.windows(2).zip(t.windows(2)).filter(|(_, w)| w[1] - w[0] <= dense).map(|(v, _)| (v[1] - v[0]).abs()).collect();
    if d.len() < 30 {
        return noise_from_differences(x);
    }
    noise_of(d)
}

/// Resolution (K) of a recorded temperature: the least noise it is credited with.
const TEMPERATURE_RESOLUTION: f64 = 0.1;

/// Weight (V/K) of a recorded temperature's residuals beside the voltage's: the noise of the
/// voltage over that of the temperature (at least [`TEMPERATURE_RESOLUTION`]), both from
/// [`noise_from_dense_differences`] over the times `t` (s), so each counts as its likelihood
/// does. `None` when the voltage shows no noise.
pub fn temperature_weight(voltage: &[f64], temperature: &[f64], t: &[f64]) -> Option<f64> {
    let noise_v = noise_from_dense_differences(voltage, t);
    (noise_v > 0.0).then(|| noise_v / temperature_noise(temperature, t))
}

/// Noise (K) of a recorded temperature at times `t` (s): [`noise_from_dense_differences`],
/// at least [`TEMPERATURE_RESOLUTION`].
pub fn temperature_noise(temperature: &[f64], t: &[f64]) -> f64 {
    noise_from_dense_differences(temperature, t).max(TEMPERATURE_RESOLUTION)
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand::SeedableRng;
    use rand_distr::{Distribution, Normal};

    /// 2 mV noise on a signal that drifts 5 mV per minute, sampled every second for 10 s after
    /// each of 100 steps and every 60 s in between: the wide pairs carry 5 mV of drift each.
    #[test]
    fn dense_differences_ignore_the_drift_of_sparse_stretches() {
        let mut rng = rand::rngs::StdRng::seed_from_u64(5);
        let normal = Normal::new(0.0, 0.002).unwrap();
        let t: Vec<f64> = (0..100).flat_map(|k| (0..10).map(move |j| 600.0 * k as f64 + j as f64).chain((1..10).map(move |j| 600.0 * k as f64 + 60.0 * j as f64))).collect();
        let x: Vec<f64> = t.iter().map(|t| 0.005 * (t / 60.0) + normal.sample(&mut rng)).collect();
        let (all, dense) = (noise_from_differences(&x), noise_from_dense_differences(&x, &t));
        assert!((dense / 0.002 - 1.0).abs() < 0.1, "{dense}");
        assert!(all > 1.1 * dense, "{all} vs {dense}");
        // Uniform sampling: the same estimate as from all pairs.
        let u: Vec<f64> = (0..x.len()).map(|k| k as f64).collect();
        assert_eq!(noise_from_dense_differences(&x, &u), noise_from_differences(&x));
    }
}
