//! The measurement noise of a recording's current channel. A cycler's current sensor adds
//! white noise to the current it holds (a few mA on a good channel, tens of mA on a noisy
//! one); read sample by sample, that noise turns every constant step into a jagged table the
//! solver must follow second by second, and puts the noise into the model's voltage. Knowing
//! its level lets [`Recording::protocol`](super::Recording::protocol) read a stretch that is
//! constant within the noise as one step at its mean.

use super::Recording;

/// Samples per window over which the spread about the window's mean is taken.
const WINDOW: usize = 6;

/// The 25 % quantile of the sample standard deviation of `WINDOW` Gaussian samples, in units
/// of their standard deviation: sqrt(chi2(0.25; 5 dof) / 5) = sqrt(2.6746 / 5).
const QUARTILE_OF_SPREAD: f64 = 0.731_4;

/// Largest correlation (in magnitude) between the changes of voltage and of current from
/// sample to sample, in the quiet windows, for the current's fluctuations to count as the
/// sensor's noise: fluctuations the cell carried move its voltage with them (by its
/// resistance), a sensor's noise does not.
const RESPONSE_CORRELATION: f64 = 0.2;

/// Fewest quiet windows on which the whiteness of the noise is judged.
const MIN_QUIET_WINDOWS: usize = 20;

/// Largest lag-1 autocorrelation of the differences between neighbouring samples that counts
/// as white noise (-): differences of white noise correlate at -0.5, those of a smooth signal
/// (a drive cycle's ramps) at zero or above.
const WHITE_CORRELATION: f64 = -0.3;

impl Recording {
    /// Standard deviation (A) of the white noise on the current channel, or 0 when the current
    /// shows none. The spread is taken in windows of six samples at distinct times; windows
    /// that straddle a change of current spread wide, windows within a constant step spread
    /// by the noise alone, so the quietest quarter of the windows measures it (scaled by the
    /// quartile of a Gaussian sample's spread). It counts as noise only when the differences
    /// between neighbours in the quiet windows correlate as white noise does, so a smoothly
    /// varying current (a drive cycle sampled every second) is never taken for noise, and
    /// when the voltage does not move with them: fluctuations the cell itself carried (a drive
    /// that jitters about its level) are its current, not noise.
    pub fn current_noise(&self) -> f64 {
        let windows: Vec<(usize, f64)> = (0..self.time.len() / WINDOW)
            .map(|w| w * WINDOW)
            .filter(|&a| self.time[a..a + WINDOW].windows(2).all(|p| p[1] > p[0]))
            .map(|a| (a, spread(&self.current[a..a + WINDOW])))
            .collect();
        if windows.len() < MIN_QUIET_WINDOWS {
            return 0.0;
        }
        let mut spreads: Vec<f64> = windows.iter().map(|w| w.1).collect();
        spreads.sort_by(f64::total_cmp);
        let sigma = spreads[spreads.len() / 4] / QUARTILE_OF_SPREAD;
        if sigma == 0.0 {
            return 0.0;
        }
        // Pairs of neighbouring current differences inside the quiet windows, and the voltage
        // differences beside them.
        let (mut sxy, mut sxx, mut n) = (0.0, 0.0, 0);
        let (mut siv, mut svv, mut sii) = (0.0, 0.0, 0.0);
        for &(a, s) in windows.iter().filter(|w| w.1 <= 2.0 * sigma) {
            let d: Vec<f64> = self.current[a..a + WINDOW].windows(2).map(|p| p[1] - p[0]).collect();
            let dv: Vec<f64> = self.voltage[a..a + WINDOW].windows(2).map(|p| p[1] - p[0]).collect();
            sxy += d.windows(2).map(|p| p[0] * p[1]).sum::<f64>();
            sxx += d.iter().map(|v| v * v).sum::<f64>() * (d.len() - 1) as f64 / d.len() as f64;
            siv += d.iter().zip(&dv).map(|(i, v)| i * v).sum::<f64>();
            sii += d.iter().map(|i| i * i).sum::<f64>();
            svv += dv.iter().map(|v| v * v).sum::<f64>();
            n += usize::from(s > 0.0);
        }
        let white = n >= MIN_QUIET_WINDOWS && sxx > 0.0 && sxy / sxx < WHITE_CORRELATION;
        let followed = svv > 0.0 && (siv / (sii * svv).sqrt()).abs() > RESPONSE_CORRELATION;
        if white && !followed { sigma } else { 0.0 }
    }
}

/// Sample standard deviation (A) of `values` about their mean.
fn spread(values: &[f64]) -> f64 {
    let mean = values.iter().sum::<f64>() / values.len() as f64;
    (values.iter().map(|v| (v - mean).powi(2)).sum::<f64>() / (values.len() - 1) as f64).sqrt()
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand::{Rng, SeedableRng};
    use rand_distr::{Distribution, Normal};

    /// A recording of `current` whose voltage is 1 mV of noise about 3.7 V less `ohm` times
    /// the current (`ohm` 0: the voltage does not see it, as a sensor's noise).
    fn rec_with(current: Vec<f64>, ohm: f64) -> Recording {
        let mut rng = rand::rngs::StdRng::seed_from_u64(11);
        let noise = Normal::new(0.0, 1e-3).unwrap();
        let time = (0..current.len()).map(|k| k as f64).collect();
        let voltage = current.iter().map(|i| 3.7 - ohm * i + noise.sample(&mut rng)).collect();
        Recording { time, voltage, current, temperature: None }
    }

    fn rec(current: Vec<f64>) -> Recording {
        rec_with(current, 0.0)
    }

    /// Steps of 5 A, -3 A and rest, 8-40 s long, as a pulse test or a binary sequence holds.
    fn steps(n: usize, seed: u64) -> Vec<f64> {
        let mut rng = rand::rngs::StdRng::seed_from_u64(seed);
        let mut i = Vec::with_capacity(n);
        while i.len() < n {
            let level = [5.0, -3.0, 0.0][rng.random_range(0..3)];
            let len = rng.random_range(8..40);
            i.extend(std::iter::repeat_n(level, len));
        }
        i.truncate(n);
        i
    }

    #[test]
    fn the_noise_on_constant_steps_is_measured() {
        let mut rng = rand::rngs::StdRng::seed_from_u64(7);
        let noise = Normal::new(0.0, 0.025).unwrap();
        let current: Vec<f64> = steps(4000, 1).into_iter().map(|i| i + noise.sample(&mut rng)).collect();
        let sigma = rec(current).current_noise();
        // The quartile estimate from ~600 windows scatters by a few per cent.
        assert!((sigma / 0.025 - 1.0).abs() < 0.08, "sigma {sigma}");
    }

    #[test]
    fn fluctuations_the_voltage_follows_are_the_cells_current() {
        // The same 25 mA jitter, carried by a cell of 30 mOhm: 0.75 mV steps under 1 mV noise.
        let mut rng = rand::rngs::StdRng::seed_from_u64(7);
        let jitter = Normal::new(0.0, 0.025).unwrap();
        let current: Vec<f64> = steps(4000, 1).into_iter().map(|i| i + jitter.sample(&mut rng)).collect();
        assert!(rec(current.clone()).current_noise() > 0.0);
        assert_eq!(rec_with(current, 0.03).current_noise(), 0.0);
    }

    #[test]
    fn clean_steps_and_smooth_drives_have_no_noise() {
        assert_eq!(rec(steps(4000, 2)).current_noise(), 0.0);
        // A drive cycle: a current that moves every second, smoothly, with no rests.
        let drive: Vec<f64> = (0..4000).map(|k| 6.0 * (k as f64 / 37.0).sin() + 2.0 * (k as f64 / 5.3).sin()).collect();
        assert_eq!(rec(drive).current_noise(), 0.0);
    }
}
