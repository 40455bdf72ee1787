//! The target as samplers see it: counted evaluations, `NaN`/`+inf` mapped to `-inf`, and
//! gradients from the target or from central finite differences.

use std::sync::atomic::{AtomicUsize, Ordering};

use rayon::prelude::*;

use super::LogDensity;
use crate::error::{Error, Result};

/// Log density as samplers use it: `NaN` and `+inf` (model failures) become `-inf`.
fn clean(v: f64) -> f64 {
    if v.is_nan() || v == f64::INFINITY { f64::NEG_INFINITY } else { v }
}

/// Central finite-difference gradient of `target` at `x`, steps `h_i = cbrt(eps)·max(|x_i|, 1)`.
///
/// Where one probe falls outside the support (log density `-inf`) the difference becomes
/// one-sided with the value at `x`; where both do, that component is 0. The `2·dim` probes are
/// evaluated in parallel, in a fixed order. Returns `(log p(x), gradient)`; the gradient is
/// all zeros when `x` itself is outside the support.
///
/// ```
/// use cellstudio::sample::{finite_difference_gradient, LogDensity};
/// struct Quad;
/// impl LogDensity for Quad {
///     fn dim(&self) -> usize { 2 }
///     fn log_density(&self, x: &[f64]) -> f64 { -x[0] * x[0] + 3.0 * x[1] }
/// }
/// let (f, g) = finite_difference_gradient(&Quad, &[1.0, 2.0]);
/// assert_eq!(f, 5.0);
/// assert!((g[0] + 2.0).abs() < 1e-8 && (g[1] - 3.0).abs() < 1e-8);
/// ```
pub fn finite_difference_gradient(target: &dyn LogDensity, x: &[f64]) -> (f64, Vec<f64>) {
    let f0 = clean(target.log_density(x));
    let n = x.len();
    if f0 == f64::NEG_INFINITY {
        return (f0, vec![0.0; n]);
    }
    let h: Vec<f64> = x.iter().map(|v| f64::EPSILON.cbrt() * v.abs().max(1.0)).collect();
    let values: Vec<f64> = (0..2 * n)
        .into_par_iter()
        .map(|k| {
            let (i, sign) = (k / 2, if k % 2 == 0 { 1.0 } else { -1.0 });
            let mut p = x.to_vec();
            p[i] += sign * h[i];
            clean(target.log_density(&p))
        })
        .collect();
    let grad = (0..n)
        .map(|i| {
            let (fp, fm) = (values[2 * i], values[2 * i + 1]);
            match (fp.is_finite(), fm.is_finite()) {
                (true, true) => (fp - fm) / (2.0 * h[i]),
                (true, false) => (fp - f0) / h[i],
                (false, true) => (f0 - fm) / h[i],
                (false, false) => 0.0,
            }
        })
        .collect();
    (f0, grad)
}

/// A target with evaluation counters (thread-safe: finite-difference probes run in parallel).
pub(crate) struct Counted<'a> {
    target: &'a dyn LogDensity,
    evaluations: AtomicUsize,
    gradients: AtomicUsize,
}

impl<'a> Counted<'a> {
    pub fn new(target: &'a dyn LogDensity) -> Self {
        Counted { target, evaluations: AtomicUsize::new(0), gradients: AtomicUsize::new(0) }
    }

    /// log p(x), `-inf` for failures.
    pub fn log_density(&self, x: &[f64]) -> f64 {
        self.evaluations.fetch_add(1, Ordering::Relaxed);
        clean(self.target.log_density(x))
    }

    /// log p(x) and its gradient: analytic if the target provides it, else central
    /// differences (`2·dim + 1` evaluations). A non-finite gradient component is an error of
    /// the target only if it is analytic; it is returned as is and the samplers reject it.
    pub fn value_and_gradient(&self, x: &[f64]) -> Result<(f64, Vec<f64>)> {
        if let Some((f, g)) = self.target.log_density_and_gradient(x) {
            self.gradients.fetch_add(1, Ordering::Relaxed);
            if g.len() != x.len() {
                return Err(Error::InvalidSetting {
                    field: "gradient".into(),
                    reason: format!("log-density gradient has {} entries for {} variables", g.len(), x.len()),
                });
            }
            return Ok((clean(f), g));
        }
        let (f, g) = finite_difference_gradient(self.target, x);
        let used = if f == f64::NEG_INFINITY { 1 } else { 1 + 2 * x.len() };
        self.evaluations.fetch_add(used, Ordering::Relaxed);
        Ok((f, g))
    }

    /// (log-density evaluations, analytic gradient evaluations) so far.
    pub fn counts(&self) -> (usize, usize) {
        (self.evaluations.load(Ordering::Relaxed), self.gradients.load(Ordering::Relaxed))
    }
}
