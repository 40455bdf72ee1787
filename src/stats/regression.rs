//! Ordinary least-squares regression of a series on given columns.

use super::descriptive::mean;
use crate::linalg::cholesky_solve;

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
    // A tiny relative ridge; a squared pivot at most 1e-10 of the diagonal's order marks a
    // column that is (nearly) a combination of the others.
    let ridge = 1e-12 * (0..p).map(|i| a[i * p + i]).fold(0.0, f64::max);
    for i in 0..p {
        a[i * p + i] += ridge;
    }
    let coef = cholesky_solve(&a, p, &b, 1e-10)?;
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn least_squares_recovers_a_line() {
        let x: Vec<f64> = (0..50).map(f64::from).collect();
        let y: Vec<f64> = x.iter().map(|v| 3.0 - 0.5 * v).collect();
        let (b, r2) = least_squares(&[vec![1.0; 50], x], &y).unwrap();
        assert!((b[0] - 3.0).abs() < 1e-9 && (b[1] + 0.5).abs() < 1e-9 && (r2 - 1.0).abs() < 1e-12);
        assert!(least_squares(&[vec![1.0; 5], vec![2.0; 5]], &[1.0; 5]).is_none());
    }
}
