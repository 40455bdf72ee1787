//! Whiteness tests of a residual: Ljung-Box (autocorrelation) and Wald-Wolfowitz runs.

use serde::Serialize;

use super::descriptive::{autocorrelation, median};
use super::distributions::{chi2_sf, normal_sf};

/// Result of a whiteness test.
#[derive(Clone, Copy, Debug, Serialize)]
pub struct TestResult {
    /// Test statistic (Q for Ljung-Box, z for the runs test).
    pub statistic: f64,
    /// Probability of a statistic at least this extreme for white noise.
    pub p_value: f64,
}

/// Ljung-Box portmanteau test over lags `1..=lags`: `Q = n (n + 2) Σ ρ_k² / (n - k)`,
/// chi-square with `lags` degrees of freedom for white noise.
pub fn ljung_box(x: &[f64], lags: usize) -> TestResult {
    let n = x.len() as f64;
    let rho = autocorrelation(x, lags);
    let q = n * (n + 2.0) * rho.iter().enumerate().map(|(k, r)| r * r / (n - (k + 1) as f64)).sum::<f64>();
    TestResult { statistic: q, p_value: chi2_sf(q, lags as f64) }
}

/// Wald-Wolfowitz runs test on the signs of `x - median(x)` (zeros dropped): z-score of the
/// number of runs (negative: too few runs, i.e. clustered residuals), two-sided p-value.
pub fn runs_test(x: &[f64]) -> TestResult {
    let med = median(x);
    let signs: Vec<bool> = x.iter().filter(|v| **v != med).map(|v| *v > med).collect();
    let n1 = signs.iter().filter(|s| **s).count() as f64;
    let n2 = signs.len() as f64 - n1;
    if n1 == 0.0 || n2 == 0.0 {
        return TestResult { statistic: f64::NAN, p_value: f64::NAN };
    }
    let runs = 1.0 + signs.windows(2).filter(|w| w[0] != w[1]).count() as f64;
    let n = n1 + n2;
    let expected = 2.0 * n1 * n2 / n + 1.0;
    let var = 2.0 * n1 * n2 * (2.0 * n1 * n2 - n) / (n * n * (n - 1.0));
    let z = (runs - expected) / var.sqrt();
    TestResult { statistic: z, p_value: 2.0 * normal_sf(z.abs()) }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::stats::noise::noise_from_differences;
    use rand::SeedableRng;
    use rand_distr::{Distribution, Normal};

    /// White noise passes both whiteness tests (at the 1% level) and its level is recovered
    /// from differences; a random walk fails both.
    #[test]
    fn whiteness_tests_separate_noise_from_structure() {
        let mut rng = rand::rngs::StdRng::seed_from_u64(11);
        let normal = Normal::new(0.0, 0.002).unwrap();
        let noise: Vec<f64> = (0..4000).map(|_| normal.sample(&mut rng)).collect();
        assert!(ljung_box(&noise, 20).p_value > 0.01);
        assert!(runs_test(&noise).p_value > 0.01);
        assert!((noise_from_differences(&noise) / 0.002 - 1.0).abs() < 0.05);
        let walk: Vec<f64> = noise.iter().scan(0.0, |s, v| { *s += v; Some(*s) }).collect();
        assert!(ljung_box(&walk, 20).p_value < 1e-6);
        assert!(runs_test(&walk).p_value < 1e-6);
    }
}
