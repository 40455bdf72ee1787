//! Statistics for residual analysis: distribution tails, whiteness tests (Ljung-Box,
//! Wald-Wolfowitz runs), least-squares regression and a robust noise estimate.

use serde::Serialize;

/// Upper tail `P(Z > z)` of the standard normal distribution.
pub fn normal_sf(z: f64) -> f64 {
    0.5 * erfc(z / std::f64::consts::SQRT_2)
}

/// Complementary error function (relative error below 1.2e-7; Numerical Recipes `erfcc`).
pub fn erfc(x: f64) -> f64 {
    let z = x.abs();
    let t = 1.0 / (1.0 + 0.5 * z);
    let poly = -z * z - 1.26551223
        + t * (1.00002368
            + t * (0.37409196
                + t * (0.09678418
                    + t * (-0.18628806 + t * (0.27886807 + t * (-1.13520398 + t * (1.48851587 + t * (-0.82215223 + t * 0.17087277))))))));
    let r = t * poly.exp();
    if x >= 0.0 { r } else { 2.0 - r }
}

/// `ln Γ(x)` for `x > 0` (Lanczos, g = 7, 9 terms; about 1e-15 relative).
pub fn ln_gamma(x: f64) -> f64 {
    const G: [f64; 9] = [
        0.999_999_999_999_809_9,
        676.520_368_121_885_1,
        -1_259.139_216_722_402_8,
        771.323_428_777_653_1,
        -176.615_029_162_140_6,
        12.507_343_278_686_905,
        -0.138_571_095_265_720_12,
        9.984_369_578_019_572e-6,
        1.505_632_735_149_311_6e-7,
    ];
    if x < 0.5 {
        let pi = std::f64::consts::PI;
        return (pi / (pi * x).sin()).ln() - ln_gamma(1.0 - x);
    }
    let x = x - 1.0;
    let t = x + 7.5;
    let sum = G[1..].iter().enumerate().fold(G[0], |s, (k, g)| s + g / (x + k as f64 + 1.0));
    0.5 * (2.0 * std::f64::consts::PI).ln() + (x + 0.5) * t.ln() - t + sum.ln()
}

/// Regularised upper incomplete gamma `Q(a, x)` (series below `a + 1`, continued fraction
/// above).
pub fn gamma_q(a: f64, x: f64) -> f64 {
    if x <= 0.0 {
        return 1.0;
    }
    let ln_front = a * x.ln() - x - ln_gamma(a);
    if x < a + 1.0 {
        let (mut term, mut sum, mut n) = (1.0 / a, 1.0 / a, a);
        for _ in 0..1000 {
            n += 1.0;
            term *= x / n;
            sum += term;
            if term.abs() < sum.abs() * 1e-16 {
                break;
            }
        }
        1.0 - sum * ln_front.exp()
    } else {
        // Lentz's method for the continued fraction.
        let tiny = 1e-300;
        let mut b = x + 1.0 - a;
        let mut c = 1.0 / tiny;
        let mut d = 1.0 / b;
        let mut h = d;
        for i in 1..1000 {
            let an = -(i as f64) * (i as f64 - a);
            b += 2.0;
            d = an * d + b;
            if d.abs() < tiny {
                d = tiny;
            }
            c = b + an / c;
            if c.abs() < tiny {
                c = tiny;
            }
            d = 1.0 / d;
            let delta = d * c;
            h *= delta;
            if (delta - 1.0).abs() < 1e-16 {
                break;
            }
        }
        ln_front.exp() * h
    }
}

/// Upper tail `P(X > x)` of the chi-square distribution with `dof` degrees of freedom.
pub fn chi2_sf(x: f64, dof: f64) -> f64 {
    gamma_q(0.5 * dof, 0.5 * x)
}

use crate::stats::autocorrelation;
use crate::stats::mean;

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

/// Median (NaN for an empty slice).
pub fn median(x: &[f64]) -> f64 {
    if x.is_empty() {
        return f64::NAN;
    }
    let mut s = x.to_vec();
    s.sort_by(f64::total_cmp);
    let n = s.len();
    if n % 2 == 1 { s[n / 2] } else { 0.5 * (s[n / 2 - 1] + s[n / 2]) }
}

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

/// Ordinary least squares `y ≈ X b` (columns of `X` given; add a column of ones for an
/// intercept). Returns the coefficients and `R²` about the mean of `y`, or `None` when the
/// normal equations are singular.
pub fn least_squares(columns: &[Vec<f64>], y: &[f64]) -> Option<(Vec<f64>, f64)> {
    let p = columns.len();
    let n = y.len();
    if p == 0 || columns.iter().any(|c| c.len() != n) || n <= p {
        return None;
    }
    // Scale columns to unit RMS so the normal equations are well conditioned.
    let norms: Vec<f64> = columns.iter().map(|c| (c.iter().map(|v| v * v).sum::<f64>() / n as f64).sqrt()).collect();
    if norms.iter().any(|s| !(*s > 0.0) || !s.is_finite()) {
        return None;
    }
    let mut a = vec![0.0; p * p];
    let mut b = vec![0.0; p];
    for i in 0..p {
        for j in 0..p {
            a[i * p + j] = columns[i].iter().zip(&columns[j]).map(|(u, v)| u * v).sum::<f64>() / (norms[i] * norms[j]);
        }
        b[i] = columns[i].iter().zip(y).map(|(u, v)| u * v).sum::<f64>() / norms[i];
    }
    let coef = solve_spd(&mut a, &mut b, p)?;
    let coef: Vec<f64> = coef.iter().zip(&norms).map(|(c, s)| c / s).collect();
    let m = mean(y);
    let ss_tot: f64 = y.iter().map(|v| (v - m) * (v - m)).sum();
    let ss_res: f64 = (0..n)
        .map(|k| {
            let fit: f64 = columns.iter().zip(&coef).map(|(c, b)| c[k] * b).sum();
            (y[k] - fit) * (y[k] - fit)
        })
        .sum();
    let r2 = if ss_tot > 0.0 { 1.0 - ss_res / ss_tot } else { 0.0 };
    Some((coef, r2))
}

/// Solves `A x = b` for a symmetric positive (semi-)definite `A` by Cholesky with a tiny
/// relative ridge; `None` when `A` is numerically singular.
fn solve_spd(a: &mut [f64], b: &mut [f64], p: usize) -> Option<Vec<f64>> {
    let ridge = 1e-12 * (0..p).map(|i| a[i * p + i]).fold(0.0, f64::max);
    for i in 0..p {
        a[i * p + i] += ridge;
    }
    for j in 0..p {
        let mut d = a[j * p + j];
        for k in 0..j {
            d -= a[j * p + k] * a[j * p + k];
        }
        // Columns are scaled to unit RMS, so the diagonal is about 1: a tiny pivot means
        // a column is (nearly) a combination of the others.
        if !(d > 1e-10) {
            return None;
        }
        let d = d.sqrt();
        a[j * p + j] = d;
        for i in j + 1..p {
            let mut s = a[i * p + j];
            for k in 0..j {
                s -= a[i * p + k] * a[j * p + k];
            }
            a[i * p + j] = s / d;
        }
    }
    let mut x = b.to_vec();
    for i in 0..p {
        for k in 0..i {
            x[i] -= a[i * p + k] * x[k];
        }
        x[i] /= a[i * p + i];
    }
    for i in (0..p).rev() {
        for k in i + 1..p {
            x[i] -= a[k * p + i] * x[k];
        }
        x[i] /= a[i * p + i];
    }
    Some(x)
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand::SeedableRng;
    use rand_distr::{Distribution, Normal};

    /// Tail values against printed tables (Abramowitz & Stegun 26.2, 26.4).
    #[test]
    fn tails_match_tables() {
        assert!((normal_sf(1.959_964) - 0.025).abs() < 1e-7);
        assert!((normal_sf(-1.0) - 0.841_344_746).abs() < 1e-7);
        for (x, dof, p) in [(3.841_459, 1.0, 0.05), (18.307_04, 10.0, 0.05), (37.566_23, 20.0, 0.01), (0.114_832, 3.0, 0.99)] {
            assert!((chi2_sf(x, dof) - p).abs() < 1e-6, "chi2({x}, {dof}) = {} vs {p}", chi2_sf(x, dof));
        }
        assert!((ln_gamma(10.0) - 362_880f64.ln()).abs() < 1e-12);
    }

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

    #[test]
    fn least_squares_recovers_a_line() {
        let x: Vec<f64> = (0..50).map(f64::from).collect();
        let y: Vec<f64> = x.iter().map(|v| 3.0 - 0.5 * v).collect();
        let (b, r2) = least_squares(&[vec![1.0; 50], x], &y).unwrap();
        assert!((b[0] - 3.0).abs() < 1e-9 && (b[1] + 0.5).abs() < 1e-9 && (r2 - 1.0).abs() < 1e-12);
        assert!(least_squares(&[vec![1.0; 5], vec![2.0; 5]], &[1.0; 5]).is_none());
    }
}
