//! Descriptive statistics of a series (residuals, chains): mean, variance, median, quantiles
//! and autocorrelation.

/// Arithmetic mean (0 for an empty slice).
pub fn mean(x: &[f64]) -> f64 {
    x.iter().sum::<f64>() / x.len().max(1) as f64
}

/// Root-mean-square (0 for an empty slice).
pub fn rms(x: &[f64]) -> f64 {
    if x.is_empty() { 0.0 } else { (x.iter().map(|v| v * v).sum::<f64>() / x.len() as f64).sqrt() }
}

/// Root-mean-square of `r` with point weights `w` (units of `r`); points of zero weight are
/// left out (even a NaN there), NaN when no weight is positive.
pub fn weighted_rms(r: &[f64], w: &[f64]) -> f64 {
    let weight: f64 = w.iter().sum();
    (r.iter().zip(w).filter(|(_, w)| **w != 0.0).map(|(r, w)| w * r * r).sum::<f64>() / weight).sqrt()
}

/// Unbiased sample variance (0 for fewer than two values).
pub fn variance(x: &[f64]) -> f64 {
    if x.len() < 2 {
        return 0.0;
    }
    let m = mean(x);
    x.iter().map(|v| (v - m) * (v - m)).sum::<f64>() / (x.len() - 1) as f64
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

/// Quantile `q` in [0, 1] of `sorted` (ascending) by linear interpolation between order
/// statistics (Hyndman & Fan type 7, the default of R and NumPy); `NaN` when empty.
pub fn quantile(sorted: &[f64], q: f64) -> f64 {
    if sorted.is_empty() {
        return f64::NAN;
    }
    let h = (sorted.len() - 1) as f64 * q.clamp(0.0, 1.0);
    let lo = h.floor() as usize;
    let hi = (lo + 1).min(sorted.len() - 1);
    sorted[lo] + (h - lo as f64) * (sorted[hi] - sorted[lo])
}

/// Sample autocorrelation of `x` at lags `1..=max_lag` (0 where it is undefined: a lag as long
/// as the series, or a constant series).
pub fn autocorrelation(x: &[f64], max_lag: usize) -> Vec<f64> {
    let m = mean(x);
    let var: f64 = x.iter().map(|v| (v - m) * (v - m)).sum();
    (1..=max_lag)
        .map(|lag| {
            if lag >= x.len() || var == 0.0 {
                return 0.0;
            }
            x.iter().zip(&x[lag..]).map(|(a, b)| (a - m) * (b - m)).sum::<f64>() / var
        })
        .collect()
}

/// Lag-1 autocorrelation of the points of `r` with positive weight, taken in order (0 for
/// fewer than three of them).
pub fn lag1(r: &[f64], weights: &[f64]) -> f64 {
    let kept: Vec<f64> = r.iter().zip(weights).filter(|(_, w)| **w > 0.0).map(|(r, _)| *r).collect();
    if kept.len() < 3 {
        return 0.0;
    }
    autocorrelation(&kept, 1)[0]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn quantiles_type_7() {
        let x = [1.0, 2.0, 3.0, 4.0];
        assert_eq!(quantile(&x, 0.5), 2.5);
        assert_eq!(quantile(&x, 0.0), 1.0);
        assert_eq!(quantile(&x, 1.0), 4.0);
        assert!((quantile(&x, 0.025) - 1.075).abs() < 1e-12);
    }

    #[test]
    fn autocorrelation_of_an_alternating_and_a_constant_series() {
        let x = [1.0, -1.0, 1.0, -1.0, 1.0, -1.0];
        let rho = autocorrelation(&x, 2);
        // sum of (x_k x_k+1) over 5 pairs / sum of x_k^2 over 6 points.
        assert!((rho[0] + 5.0 / 6.0).abs() < 1e-15 && (rho[1] - 4.0 / 6.0).abs() < 1e-15, "{rho:?}");
        assert_eq!(autocorrelation(&[2.0; 5], 1), vec![0.0]);
        // Zero-weight points are left out before the lag is taken.
        // [1, -1, 1, -1]: three products of -1 over a sum of squares of 4.
        assert!((lag1(&[1.0, 9.0, -1.0, 1.0, -1.0], &[1.0, 0.0, 1.0, 1.0, 1.0]) + 0.75).abs() < 1e-15);
    }
}
