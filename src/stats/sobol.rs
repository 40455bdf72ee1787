//! Variance-based global sensitivity: Sobol' first-order and total indices of a function of
//! `k` independent inputs uniform on `[0, 1]`, by the Saltelli sampling scheme (Saltelli et
//! al. 2010, "Variance based sensitivity analysis of model output", estimators (b) and (f):
//! Saltelli's first order, Jansen's total), with bootstrap intervals. The base samples `A` and
//! `B` are the first `k` and the next `k` dimensions of an Owen-scrambled Sobol' sequence
//! (`sobol_burley`, seeded), as SALib draws them: faster convergence than independent draws.
//!
//! A vector output (a voltage at every recorded time) gets the aggregated indices of Gamboa
//! et al. (2014): every output's numerator and variance summed before dividing, so each
//! output weighs by its variance.
//!
//! ```
//! use cellstudio::stats::sobol::{SobolSettings, sobol_indices};
//! // f = x0 + 2 x1: first-order = total = 1/5 and 4/5, the third input does nothing.
//! let f = |u: &[f64]| Some(vec![u[0] + 2.0 * u[1]]);
//! let s = sobol_indices(3, &f, &SobolSettings { samples: 4096, seed: 1, bootstrap: 50 }).unwrap();
//! assert!((s.total[0] - 0.2).abs() < 0.02 && (s.total[1] - 0.8).abs() < 0.03);
//! assert!(s.total[2].abs() < 1e-12 && s.first[2].abs() < 1e-12);
//! ```

use rand::rngs::StdRng;
use rand::{Rng, SeedableRng};
use rayon::prelude::*;
use serde::{Deserialize, Serialize};

use super::descriptive::quantile;
use crate::error::Error;

/// Sample sizes and seed.
#[derive(Clone, Debug, Deserialize, Serialize)]
#[serde(default, deny_unknown_fields)]
pub struct SobolSettings {
    /// Base samples `N`: the function is evaluated `N (k + 2)` times.
    pub samples: usize,
    pub seed: u64,
    /// Bootstrap resamples for the 95 % intervals (0: none).
    pub bootstrap: usize,
}

impl Default for SobolSettings {
    fn default() -> Self {
        Self { samples: 64, seed: 1, bootstrap: 200 }
    }
}

impl SobolSettings {
    pub fn validate(&self) -> Result<(), Error> {
        if !(8..=100_000).contains(&self.samples) {
            return Err(Error::invalid("sobol.samples", self.samples as f64, "must lie in 8..=100000"));
        }
        if self.bootstrap > 10_000 {
            return Err(Error::invalid("sobol.bootstrap", self.bootstrap as f64, "must be at most 10000"));
        }
        Ok(())
    }
}

/// First-order and total indices per input, with 95 % bootstrap intervals.
#[derive(Clone, Debug, Serialize)]
pub struct SobolIndices {
    /// Share of the output variance due to each input alone (-).
    pub first: Vec<f64>,
    /// Share due to each input including all its interactions (-): near 0 means the output
    /// does not depend on the input anywhere in the box.
    pub total: Vec<f64>,
    /// 95 % bootstrap intervals `(low, high)` of `first` and `total` (empty without bootstrap).
    pub first_interval: Vec<(f64, f64)>,
    pub total_interval: Vec<(f64, f64)>,
    /// Base samples whose every evaluation succeeded (the others are left out).
    pub samples_used: usize,
    pub evaluations: usize,
}

/// The evaluations of one base sample: `f(A)`, `f(B)` and `f(A with input i from B)`.
struct Row {
    a: Vec<f64>,
    b: Vec<f64>,
    ab: Vec<Vec<f64>>,
}

/// Sobol' indices of `f` over `[0, 1]^k` (`f` returns `None` where it cannot be evaluated;
/// those base samples are left out). Evaluations run in parallel; the result depends only on
/// the seed.
pub fn sobol_indices(k: usize, f: &(dyn Fn(&[f64]) -> Option<Vec<f64>> + Sync), settings: &SobolSettings) -> Result<SobolIndices, Error> {
    settings.validate()?;
    if 2 * k > sobol_burley::NUM_DIMENSIONS as usize {
        return Err(Error::invalid("parameters", k as f64, format!("Sobol' indices take at most {} inputs", sobol_burley::NUM_DIMENSIONS / 2)));
    }
    // The seed is hashed to the scrambling seed (32 bits).
    let scramble = (settings.seed ^ (settings.seed >> 32)) as u32;
    let point = |j: usize, first: usize| -> Vec<f64> { (first..first + k).map(|d| f64::from(sobol_burley::sample(j as u32, d as u32, scramble))).collect() };
    let points: Vec<(Vec<f64>, Vec<f64>)> = (0..settings.samples).map(|j| (point(j, 0), point(j, k))).collect();
    let rows: Vec<Option<Row>> = points
        .par_iter()
        .map(|(a, b)| {
            let ab = (0..k)
                .map(|i| {
                    let mut x = a.clone();
                    x[i] = b[i];
                    f(&x)
                })
                .collect::<Option<Vec<_>>>()?;
            Some(Row { a: f(a)?, b: f(b)?, ab })
        })
        .collect();
    let rows: Vec<Row> = rows.into_iter().flatten().filter(|r| same_length(r)).collect();
    if rows.len() < 4 {
        return Err(Error::InvalidSetting {
            field: "sobol.samples".into(),
            reason: format!("only {} of {} base samples could be evaluated", rows.len(), settings.samples),
        });
    }
    let all: Vec<usize> = (0..rows.len()).collect();
    let (first, total) = estimate(&rows, &all, k);
    let (mut first_interval, mut total_interval) = (Vec::new(), Vec::new());
    if settings.bootstrap > 0 {
        let mut boot_rng = StdRng::seed_from_u64(settings.seed.wrapping_add(1));
        let resamples: Vec<Vec<usize>> = (0..settings.bootstrap).map(|_| (0..rows.len()).map(|_| boot_rng.random_range(0..rows.len())).collect()).collect();
        let estimates: Vec<(Vec<f64>, Vec<f64>)> = resamples.par_iter().map(|idx| estimate(&rows, idx, k)).collect();
        let interval = |pick: &dyn Fn(&(Vec<f64>, Vec<f64>)) -> f64| {
            let mut v: Vec<f64> = estimates.iter().map(pick).filter(|v| v.is_finite()).collect();
            v.sort_by(f64::total_cmp);
            (quantile(&v, 0.025), quantile(&v, 0.975))
        };
        first_interval = (0..k).map(|i| interval(&|e| e.0[i])).collect();
        total_interval = (0..k).map(|i| interval(&|e| e.1[i])).collect();
    }
    Ok(SobolIndices { first, total, first_interval, total_interval, samples_used: rows.len(), evaluations: settings.samples * (k + 2) })
}

fn same_length(r: &Row) -> bool {
    let m = r.a.len();
    r.b.len() == m && r.ab.iter().all(|v| v.len() == m)
}

/// Aggregated first-order (Saltelli 2010) and total (Jansen 1999) indices over the rows `idx`.
fn estimate(rows: &[Row], idx: &[usize], k: usize) -> (Vec<f64>, Vec<f64>) {
    let n = idx.len() as f64;
    let m = rows[0].a.len();
    // Output mean and variance from f(A) and f(B) together; the variance summed over the
    // outputs. The first-order numerator multiplies f(B) by a difference of zero mean, so f(B)
    // is centred first: the same expectation, far less noise when the mean is large against
    // the spread (a voltage of 3.7 V that varies by millivolts).
    let means: Vec<f64> = (0..m).map(|t| idx.iter().map(|&r| rows[r].a[t] + rows[r].b[t]).sum::<f64>() / (2.0 * n)).collect();
    let mut variance = 0.0;
    for (t, mean) in means.iter().enumerate() {
        variance += idx.iter().map(|&r| (rows[r].a[t] - mean).powi(2) + (rows[r].b[t] - mean).powi(2)).sum::<f64>() / (2.0 * n - 1.0);
    }
    let mut first = vec![0.0; k];
    let mut total = vec![0.0; k];
    if !(variance > 0.0) {
        // A constant output depends on no input.
        return (first, total);
    }
    for i in 0..k {
        let (mut v_i, mut e_i) = (0.0, 0.0);
        for &r in idx {
            let row = &rows[r];
            for t in 0..m {
                let d = row.ab[i][t] - row.a[t];
                v_i += (row.b[t] - means[t]) * d;
                e_i += d * d;
            }
        }
        first[i] = v_i / n / variance;
        total[i] = e_i / (2.0 * n) / variance;
    }
    (first, total)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The Ishigami function (a = 7, b = 0.1) on [-pi, pi]^3, whose indices are known in
    /// closed form (Saltelli et al. 2008, "Global Sensitivity Analysis: The Primer", 4.6).
    fn ishigami(u: &[f64]) -> Option<Vec<f64>> {
        let x: Vec<f64> = u.iter().map(|u| std::f64::consts::PI * (2.0 * u - 1.0)).collect();
        Some(vec![x[0].sin() + 7.0 * x[1].sin().powi(2) + 0.1 * x[2].powi(4) * x[0].sin()])
    }

    fn exact() -> ([f64; 3], [f64; 3]) {
        let (a, b, pi4) = (7.0f64, 0.1f64, std::f64::consts::PI.powi(4));
        let v1 = 0.5 * (1.0 + b * pi4 / 5.0).powi(2);
        let v2 = a * a / 8.0;
        let v13 = b * b * pi4 * pi4 * 8.0 / 225.0;
        let v = v1 + v2 + v13;
        ([v1 / v, v2 / v, 0.0], [(v1 + v13) / v, v2 / v, v13 / v])
    }

    #[test]
    fn ishigami_indices_match_the_closed_form() {
        let s = sobol_indices(3, &ishigami, &SobolSettings { samples: 8192, seed: 3, bootstrap: 100 }).unwrap();
        let (first, total) = exact();
        for i in 0..3 {
            println!("x{i}: first {:.4} (exact {:.4}) {:?}, total {:.4} (exact {:.4}) {:?}", s.first[i], first[i], s.first_interval[i], s.total[i], total[i], s.total_interval[i]);
            assert!((s.first[i] - first[i]).abs() < 0.01, "first x{i}");
            assert!((s.total[i] - total[i]).abs() < 0.01, "total x{i}");
            // The intervals hold the exact value.
            assert!(s.total_interval[i].0 <= total[i] && total[i] <= s.total_interval[i].1, "total x{i}");
        }
        assert_eq!(s.evaluations, 8192 * 5);
    }

    #[test]
    fn a_vector_output_weighs_each_output_by_its_variance() {
        // Output 0 depends on u0 only, output 1 (ten times the spread) on u1 only.
        let f = |u: &[f64]| Some(vec![u[0], 10.0 * u[1]]);
        let s = sobol_indices(2, &f, &SobolSettings { samples: 4096, seed: 5, bootstrap: 0 }).unwrap();
        let share = 1.0 / 101.0;
        println!("{:?} {:?}", s.first, s.total);
        assert!((s.total[0] - share).abs() < 0.003 && (s.total[1] - (1.0 - share)).abs() < 0.03, "{:?}", s.total);
    }

    #[test]
    fn failed_evaluations_are_left_out() {
        let f = |u: &[f64]| (u[0] > 0.1).then(|| vec![u[0]]);
        let s = sobol_indices(1, &f, &SobolSettings { samples: 100, seed: 2, bootstrap: 0 }).unwrap();
        assert!(s.samples_used < 100 && s.samples_used > 60, "{}", s.samples_used);
        assert!((s.total[0] - 1.0).abs() < 0.05 && (s.first[0] - 1.0).abs() < 0.2, "{:?} {:?}", s.first, s.total);
    }
}
