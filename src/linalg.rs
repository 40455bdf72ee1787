//! The one dense linear-algebra path: small dense matrices (parameters, optimiser variables:
//! tens at most) as row-major `Vec<f64>`, factorised by `faer`. Used by the optimisers, the
//! samplers, the fits' covariances and the statistics layer; the sparse Newton systems of the
//! integrator live in `solver`.

use faer::linalg::solvers::Solve;
use faer::{Mat, Side};

use crate::error::{Error, Result};

/// Eigen-decomposition of the symmetric matrix `a`: eigenvalues (ascending) and eigenvectors
/// (column `k` of the row-major result is the eigenvector of value `k`).
pub fn sym_eigen(a: &[f64], n: usize) -> Result<(Vec<f64>, Vec<f64>)> {
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

/// Lower Cholesky factor `L` (row-major, zeros above the diagonal) of the symmetric `n × n`
/// matrix `a` (its lower triangle is read); `None` when `a` is not positive definite.
pub fn cholesky(a: &[f64], n: usize) -> Option<Vec<f64>> {
    let llt = Mat::<f64>::from_fn(n, n, |i, j| a[i * n + j]).llt(Side::Lower).ok()?;
    let l = llt.L();
    Some((0..n * n).map(|k| if k % n <= k / n { l[(k / n, k % n)] } else { 0.0 }).collect())
}

/// Solves `a x = b` for a symmetric positive-definite `n × n` matrix `a` by Cholesky; `None`
/// when a squared pivot `L_jj²` is at most `min_pivot` (a numerically singular `a`).
pub fn cholesky_solve(a: &[f64], n: usize, b: &[f64], min_pivot: f64) -> Option<Vec<f64>> {
    let llt = Mat::<f64>::from_fn(n, n, |i, j| a[i * n + j]).llt(Side::Lower).ok()?;
    if (0..n).any(|j| !(llt.L()[(j, j)].powi(2) > min_pivot)) {
        return None;
    }
    let x = llt.solve(Mat::<f64>::from_fn(n, 1, |i, _| b[i]));
    Some((0..n).map(|i| x[(i, 0)]).collect())
}

/// Inverse of the symmetric positive semi-definite `n × n` matrix `a` through its
/// eigen-decomposition: directions with eigenvalues below `1e-12` of the largest are not
/// informed, and every entry they reach is infinite (a covariance from a Fisher information).
pub fn sym_inverse(a: &[f64], n: usize) -> Result<Vec<f64>> {
    let (values, vectors) = sym_eigen(a, n)?;
    let largest = values.iter().fold(0.0f64, |m, v| m.max(*v));
    let mut inv = vec![0.0; n * n];
    for i in 0..n {
        for j in 0..n {
            inv[i * n + j] = (0..n)
                .map(|k| {
                    let w = vectors[i * n + k] * vectors[j * n + k];
                    match (w == 0.0, values[k] > 1e-12 * largest) {
                        (true, _) => 0.0,
                        (false, true) => w / values[k],
                        (false, false) => f64::INFINITY,
                    }
                })
                .sum();
        }
    }
    Ok(inv)
}

/// `aᵀ b` of two vectors.
pub fn dot(a: &[f64], b: &[f64]) -> f64 {
    a.iter().zip(b).map(|(a, b)| a * b).sum()
}

/// `a · x`.
pub fn mat_vec(a: &[f64], n: usize, x: &[f64]) -> Vec<f64> {
    (0..n).map(|i| (0..n).map(|j| a[i * n + j] * x[j]).sum()).collect()
}

/// `aᵀ · x`.
pub fn mat_t_vec(a: &[f64], n: usize, x: &[f64]) -> Vec<f64> {
    (0..n).map(|j| (0..n).map(|i| a[i * n + j] * x[i]).sum()).collect()
}

/// `a · b`.
pub fn mat_mul(a: &[f64], b: &[f64], n: usize) -> Vec<f64> {
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
pub fn expm_sym(a: &[f64], n: usize) -> Result<Vec<f64>> {
    let (values, v) = sym_eigen(a, n)?;
    let mut out = vec![0.0; n * n];
    for i in 0..n {
        for j in 0..n {
            out[i * n + j] = (0..n).map(|k| v[i * n + k] * values[k].exp() * v[j * n + k]).sum();
        }
    }
    Ok(out)
}

/// The `n × n` identity.
pub fn identity(n: usize) -> Vec<f64> {
    let mut a = vec![0.0; n * n];
    for i in 0..n {
        a[i * n + i] = 1.0;
    }
    a
}
