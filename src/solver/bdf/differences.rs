//! The backward-difference array of the BDF/NDF method: `d[0]` the state, `d[k]` its k-th
//! backward difference scaled to the current step size. The predictor, the update after an
//! accepted step and the rescaling for a step-size change all work on it.

use super::control::{Coefficients, MAX_ORDER};

/// The backward differences `d[0..MAX_ORDER + 3]`, each of length n.
pub(super) struct Differences {
    pub(super) d: Vec<Vec<f64>>,
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
        Self { d }
    }

    /// Predictor of a step of `order`: `y = sum d[0..=order]`, and
    /// `psi = sum_k gamma_k / alpha_order d[k]`.
    ///
    /// This and [`Differences::accept`] and [`Differences::rescale`] run once per step over
    /// all `(order + 1) n` differences; each is one pass over the states with the orders
    /// unrolled (a const parameter), so every difference is loaded and stored once per call
    /// and the states' loop vectorises. The sums keep the order of a loop over `k`.
    pub(super) fn predict(&self, order: usize, coeffs: &Coefficients, out: &mut Prediction) {
        match order {
            1 => self.predict_k::<1>(coeffs, out),
            2 => self.predict_k::<2>(coeffs, out),
            3 => self.predict_k::<3>(coeffs, out),
            4 => self.predict_k::<4>(coeffs, out),
            5 => self.predict_k::<5>(coeffs, out),
            _ => unreachable!("order {order} outside 1..={MAX_ORDER}"),
        }
    }

    fn predict_k<const K: usize>(&self, coeffs: &Coefficients, out: &mut Prediction) {
        let n = out.y.len();
        let w: [f64; K] = std::array::from_fn(|k| coeffs.gamma[k + 1] / coeffs.alpha[K]);
        let d0 = &self.d[0][..n];
        let d: [&[f64]; K] = std::array::from_fn(|k| &self.d[k + 1][..n]);
        let (y, psi) = (&mut out.y[..n], &mut out.psi[..n]);
        for i in 0..n {
            let (mut yi, mut pi) = (d0[i], 0.0);
            for k in 0..K {
                yi += d[k][i];
                pi += w[k] * d[k][i];
            }
            y[i] = yi;
            psi[i] = pi;
        }
    }

    /// Updates the array after an accepted step of `order` whose corrector moved the
    /// prediction by `dvec`: `d[order + 2] = dvec - d[order + 1]`, `d[order + 1] = dvec`, then
    /// `d[k] += d[k + 1]` for `k = order` down to 0.
    pub(super) fn accept(&mut self, order: usize, dvec: &[f64]) {
        match order + 1 {
            2 => self.accept_k::<2>(dvec),
            3 => self.accept_k::<3>(dvec),
            4 => self.accept_k::<4>(dvec),
            5 => self.accept_k::<5>(dvec),
            6 => self.accept_k::<6>(dvec),
            _ => unreachable!("order {order} outside 1..={MAX_ORDER}"),
        }
    }

    /// [`Differences::accept`] with `K = order + 1` rows below `d[order + 1]`.
    fn accept_k<const K: usize>(&mut self, dvec: &[f64]) {
        let n = dvec.len();
        let (lo, hi) = self.d.split_at_mut(K);
        let (last, next) = hi.split_at_mut(1);
        let (last, next) = (&mut last[0][..n], &mut next[0][..n]);
        let d: [&mut [f64]; K] = {
            let mut it = lo.iter_mut().map(|v| &mut v[..n]);
            std::array::from_fn(|_| it.next().expect("K rows"))
        };
        for i in 0..n {
            let dv = dvec[i];
            next[i] = dv - last[i];
            last[i] = dv;
            let mut above = dv;
            for k in (0..K).rev() {
                d[k][i] += above;
                above = d[k][i];
            }
        }
    }

    /// Rescales the differences up to `order` for a step-size change by `factor`:
    /// `D[..=order] = (R U)^T D[..=order]`.
    pub(super) fn rescale(&mut self, order: usize, factor: f64) {
        match order + 1 {
            2 => self.rescale_k::<2>(factor),
            3 => self.rescale_k::<3>(factor),
            4 => self.rescale_k::<4>(factor),
            5 => self.rescale_k::<5>(factor),
            6 => self.rescale_k::<6>(factor),
            _ => unreachable!("order {order} outside 1..={MAX_ORDER}"),
        }
    }

    /// [`Differences::rescale`] of the first `K` rows.
    fn rescale_k<const K: usize>(&mut self, factor: f64) {
        let r = compute_r::<K>(factor);
        let u = compute_r::<K>(1.0);
        // RU = R * U
        let ru: [[f64; K]; K] = std::array::from_fn(|i| std::array::from_fn(|j| (0..K).map(|m| r[i][m] * u[m][j]).sum()));
        let n = self.d[0].len();
        let d: [&mut [f64]; K] = {
            let mut it = self.d.iter_mut().map(|v| &mut v[..n]);
            std::array::from_fn(|_| it.next().expect("K rows"))
        };
        // Column 0 of `R U` is the first unit vector (`R` and `U` are 1 in row 0 and 0 below
        // it in column 0): the state `d[0]` does not change. The other columns are applied
        // without testing for zero entries, so the loop over the states vectorises.
        debug_assert!((1..K).all(|i| ru[i][0] == 0.0) && ru[0][0] == 1.0);
        for e in 0..n {
            let old: [f64; K] = std::array::from_fn(|i| d[i][e]);
            for j in 1..K {
                let mut s = 0.0;
                for i in 0..K {
                    s += ru[i][j] * old[i];
                }
                d[j][e] = s;
            }
        }
    }
}

/// The K x K matrix R of Shampine & Reichelt (K = order + 1) for a step-size ratio `factor`.
fn compute_r<const K: usize>(factor: f64) -> [[f64; K]; K] {
    let mut m = [[0.0; K]; K];
    m[0] = [1.0; K];
    for i in 1..K {
        for j in 1..K {
            m[i][j] = (i as f64 - 1.0 - factor * j as f64) / i as f64;
        }
    }
    // cumulative product down the columns
    for i in 1..K {
        for j in 0..K {
            m[i][j] *= m[i - 1][j];
        }
    }
    m
}

#[cfg(test)]
mod tests {
    use super::*;

    fn array(n: usize) -> Differences {
        let y0: Vec<f64> = (0..n).map(|i| 1.0 + i as f64).collect();
        let mut d = Differences::new(&y0, (0..n).map(|i| 0.1 * i as f64));
        for (k, row) in d.d.iter_mut().enumerate().skip(2) {
            row.iter_mut().enumerate().for_each(|(i, v)| *v = 0.01 * (k * i) as f64 - 0.02);
        }
        d
    }

    /// The fused passes give the loop-over-k formulas of their doc comments, exactly.
    #[test]
    fn fused_passes_match_the_formulas() {
        let n = 7;
        let coeffs = Coefficients::new();
        for order in 1..=MAX_ORDER {
            let d = array(n);
            let mut pred = Prediction::new(n);
            d.predict(order, &coeffs, &mut pred);
            for i in 0..n {
                let (mut y, mut psi) = (d.d[0][i], 0.0);
                for k in 1..=order {
                    y += d.d[k][i];
                    psi += coeffs.gamma[k] / coeffs.alpha[order] * d.d[k][i];
                }
                assert_eq!((pred.y[i], pred.psi[i]), (y, psi));
            }
            let mut acc = array(n);
            let dvec: Vec<f64> = (0..n).map(|i| 0.3 - 0.05 * i as f64).collect();
            acc.accept(order, &dvec);
            let mut expect = array(n).d;
            for i in 0..n {
                expect[order + 2][i] = dvec[i] - expect[order + 1][i];
                expect[order + 1][i] = dvec[i];
                for k in (0..=order).rev() {
                    expect[k][i] += expect[k + 1][i];
                }
            }
            assert_eq!(acc.d, expect);
        }
    }

    /// Rescaling by `f` and then by `1 / f` restores the differences (up to round-off).
    #[test]
    fn rescale_round_trip() {
        for order in 1..=MAX_ORDER {
            let mut d = array(5);
            d.rescale(order, 0.37);
            d.rescale(order, 1.0 / 0.37);
            let orig = array(5);
            for k in 0..=order {
                for i in 0..5 {
                    assert!((d.d[k][i] - orig.d[k][i]).abs() < 1e-12, "order {order} d[{k}][{i}]");
                }
            }
        }
    }
}
