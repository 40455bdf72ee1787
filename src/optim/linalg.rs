//! Small dense helpers for the distribution-based optimisers. Matrices are `n × n`, row-major
//! `Vec<f64>`; `n` is the number of optimisation variables (tens at most).

use faer::{Mat, Side};

use crate::error::{Error, Result};

/// Eigen-decomposition of the symmetric matrix `a`: eigenvalues (ascending) and eigenvectors
/// (column `k` of the row-major result is the eigenvector of value `k`).
pub(crate) fn sym_eigen(a: &[f64], n: usize) -> Result<(Vec<f64>, Vec<f64>)> {
    let m = Mat::<f64>::from_fn(n, n, |i, j| 0.5 * (a[i * n + j] + a[j * n + i]));
    let evd = m
        .self_adjoint_eigen(Side::Lower)
        .map_err(|e| Error::Linear(format!("eigen-decomposition of the search covariance: {e:?}")))?;
    let values: Vec<f64> = (0..n).map(|k| evd.S().column_vector()[k]).collect();
    let u = evd.U();
    let mut vectors = vec![0.0; n * n];
    for i in 0..n {
        for k in 0..n {
            vectors[i * n + k] = u[(i, k)];
        }
    }
    Ok((values, vectors))
}

/// `a · x`.
pub(crate) fn mat_vec(a: &[f64], n: usize, x: &[f64]) -> Vec<f64> {
    (0..n).map(|i| (0..n).map(|j| a[i * n + j] * x[j]).sum()).collect()
}

/// `aᵀ · x`.
pub(crate) fn mat_t_vec(a: &[f64], n: usize, x: &[f64]) -> Vec<f64> {
    (0..n).map(|j| (0..n).map(|i| a[i * n + j] * x[i]).sum()).collect()
}

/// `a · b`.
pub(crate) fn mat_mul(a: &[f64], b: &[f64], n: usize) -> Vec<f64> {
    let mut c = vec![0.0; n * n];
    for i in 0..n {
        for k in 0..n {
            let aik = a[i * n + k];
            if aik != 0.0 {
                for j in 0..n {
                    c[i * n + j] += aik * b[k * n + j];
                }
            }
        }
    }
    c
}

/// Matrix exponential of a symmetric matrix, `V · diag(exp λ) · Vᵀ`.
pub(crate) fn expm_sym(a: &[f64], n: usize) -> Result<Vec<f64>> {
    let (values, v) = sym_eigen(a, n)?;
    let mut out = vec![0.0; n * n];
    for i in 0..n {
        for j in 0..n {
            out[i * n + j] = (0..n).map(|k| v[i * n + k] * values[k].exp() * v[j * n + k]).sum();
        }
    }
    Ok(out)
}

pub(crate) fn identity(n: usize) -> Vec<f64> {
    let mut a = vec![0.0; n * n];
    for i in 0..n {
        a[i * n + i] = 1.0;
    }
    a
}
