//! Step-size and order control of the BDF/NDF method (Shampine & Reichelt's NDF, as in MATLAB
//! `ode15s` and SciPy `BDF`): the method's coefficients, the error weights and norms, the
//! initial step, the factor after a rejected step and the order choice after an accepted one.

use super::{Dae, SolverOptions, SolverStats};

pub(super) const MAX_ORDER: usize = 5;
const MIN_FACTOR: f64 = 0.2;
const MAX_FACTOR: f64 = 10.0;
/// NDF coefficients kappa_k of Shampine & Reichelt (1997).
const KAPPA: [f64; 6] = [0.0, -0.1850, -1.0 / 9.0, -0.0823, -0.0415, 0.0];

/// The method's coefficients for orders 0 to [`MAX_ORDER`].
pub(super) struct Coefficients {
    /// `gamma_k = sum_{j <= k} 1 / j`.
    pub(super) gamma: [f64; MAX_ORDER + 1],
    /// `alpha_k = (1 - kappa_k) gamma_k`: a step of size h solves with `c = h / alpha_k`.
    pub(super) alpha: [f64; MAX_ORDER + 1],
    /// Local error constant of each order.
    pub(super) error_const: [f64; MAX_ORDER + 1],
}

impl Coefficients {
    pub(super) fn new() -> Self {
        let mut gamma = [0.0; MAX_ORDER + 1];
        for k in 1..=MAX_ORDER {
            gamma[k] = gamma[k - 1] + 1.0 / k as f64;
        }
        let alpha = std::array::from_fn(|k| (1.0 - KAPPA[k]) * gamma[k]);
        let error_const = std::array::from_fn(|k| KAPPA[k] * gamma[k] + 1.0 / (k + 1) as f64);
        Self { gamma, alpha, error_const }
    }
}

fn rms(x: &[f64], scale: &[f64]) -> f64 {
    let s: f64 = x.iter().zip(scale).map(|(a, b)| (a / b) * (a / b)).sum();
    (s / x.len() as f64).sqrt()
}

/// Root mean square of `c x` weighted by `w = 1 / scale`.
pub(super) fn weighted_rms(c: f64, x: &[f64], w: &[f64]) -> f64 {
    c.abs() * (weighted_sum_squares(x, w) / x.len() as f64).sqrt()
}

/// `sum_i (x_i w_i)^2`, accumulated in [`LANES`] interleaved partial sums: a single running
/// sum is a chain of dependent additions that the compiler may not reorder, so the loop
/// would run one element at a time; with independent partial sums it vectorises. (The
/// rounding differs from the sequential sum by a few ulps of the norm.)
pub(super) fn weighted_sum_squares(x: &[f64], w: &[f64]) -> f64 {
    let n = x.len().min(w.len());
    let (x, w) = (&x[..n], &w[..n]);
    let mut acc = [0.0; LANES];
    let (xc, wc) = (x.chunks_exact(LANES), w.chunks_exact(LANES));
    let (xr, wr) = (xc.remainder(), wc.remainder());
    for (xs, ws) in xc.zip(wc) {
        for k in 0..LANES {
            let v = xs[k] * ws[k];
            acc[k] += v * v;
        }
    }
    let tail: f64 = xr.iter().zip(wr).map(|(a, b)| (a * b) * (a * b)).sum();
    (acc[0] + acc[1]) + (acc[2] + acc[3]) + tail
}

/// Partial sums of [`weighted_sum_squares`].
const LANES: usize = 4;

/// Error weights `1 / (atol + rtol |y|)`, times `gain` on the `tightened` states.
pub(super) fn set_weights(w: &mut [f64], atol: &[f64], rtol: f64, y: &[f64], tightened: &[usize], gain: f64) {
    for ((w, a), y) in w.iter_mut().zip(atol).zip(y) {
        *w = 1.0 / (a + rtol * y.abs());
    }
    for &k in tightened {
        w[k] *= gain;
    }
}

/// First step size (s) from `(t, y0)` with masked derivative `fdiff = M f(t, y0)` (Hairer,
/// Norsett & Wanner, with algebraic rows masked) and absolute tolerances `atol`, at most
/// `opts.max_step` and `span` (s); costs one right-hand side evaluation.
#[allow(clippy::too_many_arguments)]
pub(super) fn initial_step(
    dae: &dyn Dae,
    t: f64,
    y0: &[f64],
    fdiff: &[f64],
    atol: &[f64],
    opts: &SolverOptions,
    span: f64,
    stats: &mut SolverStats,
) -> f64 {
    let (mass, rtol) = (dae.mass(), opts.rtol);
    let scale0: Vec<f64> = y0.iter().zip(atol).map(|(y, a)| a + rtol * y.abs()).collect();
    let d0 = rms(y0, &scale0);
    let d1 = rms(fdiff, &scale0);
    let h0 = if d0 < 1e-5 || d1 < 1e-5 { 1e-6 } else { 0.01 * d0 / d1 };
    let h0 = h0.min(span);
    let y1: Vec<f64> = y0.iter().zip(fdiff).map(|(y, f)| y + h0 * f).collect();
    let mut f1 = vec![0.0; y0.len()];
    dae.rhs(t + h0, &y1, &mut f1);
    stats.rhs_evals += 1;
    let df: Vec<f64> = f1.iter().zip(fdiff).zip(mass).map(|((a, b), m)| (a * m - b) / h0).collect();
    let d2 = rms(&df, &scale0);
    let h1 = if d1 <= 1e-15 && d2 <= 1e-15 { (h0 * 1e-3).max(1e-6) } else { (0.01 / d1.max(d2)).powf(0.5) };
    (100.0 * h0).min(h1).min(opts.max_step).min(span)
}

/// Safety factor of step-size changes after a step whose Newton solve took `n_iter`
/// iterations out of at most `max_iter`.
pub(super) fn safety(n_iter: usize, max_iter: usize) -> f64 {
    0.9 * (2 * max_iter + 1) as f64 / (2 * max_iter + n_iter) as f64
}

/// Step-size factor after a step of `order` rejected with `error_norm > 1`.
pub(super) fn rejection_factor(safety: f64, error_norm: f64, order: usize) -> f64 {
    MIN_FACTOR.max(safety * error_norm.powf(-1.0 / (order as f64 + 1.0)))
}

/// The next order and step-size factor after `order + 1` equal steps: the order among
/// `order - 1, order, order + 1` whose error norm (`norms`, in that order) allows the largest
/// step.
pub(super) fn choose_order(order: usize, norms: [f64; 3], safety: f64) -> (usize, f64) {
    let mut best = 0;
    let mut best_factor = f64::NEG_INFINITY;
    for (k, e) in norms.iter().enumerate() {
        let fac = e.powf(-1.0 / (order + k) as f64);
        let fac = if fac.is_nan() { 0.0 } else { fac };
        if fac > best_factor {
            best_factor = fac;
            best = k;
        }
    }
    ((order as isize + best as isize - 1) as usize, MAX_FACTOR.min(safety * best_factor))
}
