//! The backward-difference array of the BDF/NDF method: `d[0]` the state, `d[k]` its k-th
//! backward difference scaled to the current step size. The predictor, the update after an
//! accepted step and the rescaling for a step-size change all work on it.

use super::control::{Coefficients, MAX_ORDER};

/// The backward differences `d[0..MAX_ORDER + 3]` (each of length n) and their work space.
pub(super) struct Differences {
    pub(super) d: Vec<Vec<f64>>,
    scratch: Vec<Vec<f64>>,
}

/// The predicted state of a step and the history term `psi` of its corrector equation.
pub(super) struct Prediction {
    pub(super) y: Vec<f64>,
    pub(super) psi: Vec<f64>,
}

impl Prediction {
    pub(super) fn new(n: usize) -> Self {
        Self { y: vec![0.0; n], psi: vec![0.0; n] }
    }
}

impl Differences {
    /// The array of a first-order start at state `y0` with first difference `dy` (`h y'`).
    pub(super) fn new(y0: &[f64], dy: impl Iterator<Item = f64>) -> Self {
        let n = y0.len();
        let mut d: Vec<Vec<f64>> = vec![vec![0.0; n]; MAX_ORDER + 3];
        d[0].copy_from_slice(y0);
        for (di, v) in d[1].iter_mut().zip(dy) {
            *di = v;
        }
        Self { d, scratch: vec![vec![0.0; n]; MAX_ORDER + 1] }
    }

    /// Predictor of a step of `order`: `y = sum d[0..=order]`, and
    /// `psi = sum_k gamma_k / alpha_order d[k]`.
    pub(super) fn predict(&self, order: usize, coeffs: &Coefficients, out: &mut Prediction) {
        out.y.copy_from_slice(&self.d[0]);
        out.psi.iter_mut().for_each(|v| *v = 0.0);
        for k in 1..=order {
            let w = coeffs.gamma[k] / coeffs.alpha[order];
            for ((yp, ps), dk) in out.y.iter_mut().zip(out.psi.iter_mut()).zip(&self.d[k]) {
                *yp += dk;
                *ps += w * dk;
            }
        }
    }

    /// Updates the array after an accepted step of `order` whose corrector moved the
    /// prediction by `dvec`.
    pub(super) fn accept(&mut self, order: usize, dvec: &[f64]) {
        let d = &mut self.d;
        {
            let (lo, hi) = d.split_at_mut(order + 2);
            for ((next, last), dv) in hi[0].iter_mut().zip(lo[order + 1].iter_mut()).zip(dvec) {
                *next = dv - *last;
                *last = *dv;
            }
        }
        for k in (0..=order).rev() {
            let (lo, hi) = d.split_at_mut(k + 1);
            for (a, b) in lo[k].iter_mut().zip(&hi[0]) {
                *a += b;
            }
        }
    }

    /// Rescales the differences up to `order` for a step-size change by `factor`.
    pub(super) fn rescale(&mut self, order: usize, factor: f64) {
        let (d, scratch) = (&mut self.d, &mut self.scratch);
        let r = compute_r(order, factor);
        let u = compute_r(order, 1.0);
        // RU = R * U; D[:order+1] = RU^T D[:order+1]
        let k = order + 1;
        let mut ru = [0.0; (MAX_ORDER + 1) * (MAX_ORDER + 1)];
        for i in 0..k {
            for j in 0..k {
                ru[i * k + j] = (0..k).map(|m| r[i * k + m] * u[m * k + j]).sum();
            }
        }
        for (j, row) in scratch.iter_mut().enumerate().take(k) {
            row.iter_mut().for_each(|v| *v = 0.0);
            for i in 0..k {
                let w = ru[i * k + j];
                if w != 0.0 {
                    for (a, b) in row.iter_mut().zip(&d[i]) {
                        *a += w * b;
                    }
                }
            }
        }
        for j in 0..k {
            std::mem::swap(&mut d[j], &mut scratch[j]);
        }
    }
}

/// The (order + 1)^2 matrix R of Shampine & Reichelt for a step-size ratio `factor`, row-major.
fn compute_r(order: usize, factor: f64) -> Vec<f64> {
    let k = order + 1;
    let mut m = vec![0.0; k * k];
    for j in 0..k {
        m[j] = 1.0;
    }
    for i in 1..k {
        for j in 1..k {
            m[i * k + j] = (i as f64 - 1.0 - factor * j as f64) / i as f64;
        }
    }
    // cumulative product down the columns
    for i in 1..k {
        for j in 0..k {
            m[i * k + j] *= m[(i - 1) * k + j];
        }
    }
    m
}
