//! Finite-difference Jacobian of a sparse system, compressed by column colouring
//! (Curtis-Powell-Reid): columns that share no row are perturbed together, so a Jacobian
//! costs one residual evaluation per colour instead of one per state.

/// Colour groups of the columns of a sparsity pattern.
pub struct ColouredPattern {
    /// Pattern entries `(row, col)`, in the order Jacobian values are returned.
    pub entries: Vec<(usize, usize)>,
    /// Columns of each colour.
    groups: Vec<Vec<usize>>,
    /// For each column, the indices into `entries` of its non-zeros.
    col_entries: Vec<Vec<usize>>,
}

impl ColouredPattern {
    /// Greedy colouring of the columns of an `n x n` pattern.
    pub fn new(n: usize, entries: Vec<(usize, usize)>) -> Self {
        let mut rows_of_col: Vec<Vec<usize>> = vec![Vec::new(); n];
        let mut cols_of_row: Vec<Vec<usize>> = vec![Vec::new(); n];
        let mut col_entries: Vec<Vec<usize>> = vec![Vec::new(); n];
        for (k, &(r, c)) in entries.iter().enumerate() {
            rows_of_col[c].push(r);
            cols_of_row[r].push(c);
            col_entries[c].push(k);
        }
        let mut colour = vec![usize::MAX; n];
        let mut groups: Vec<Vec<usize>> = Vec::new();
        let mut forbidden: Vec<usize> = Vec::new(); // forbidden[g] == c marks g used near column c
        // A column without entries is never perturbed: it would only disturb the rows the
        // pattern leaves out (e.g. differential rows when colouring an algebraic block).
        for c in (0..n).filter(|&c| !rows_of_col[c].is_empty()) {
            for &r in &rows_of_col[c] {
                for &other in &cols_of_row[r] {
                    let g = colour[other];
                    if g != usize::MAX {
                        forbidden[g] = c;
                    }
                }
            }
            let g = (0..groups.len()).find(|&g| forbidden[g] != c).unwrap_or_else(|| {
                groups.push(Vec::new());
                forbidden.push(usize::MAX);
                groups.len() - 1
            });
            colour[c] = g;
            groups[g].push(c);
        }
        Self { entries, groups, col_entries }
    }

    /// Number of colours (residual evaluations per Jacobian).
    pub fn n_colours(&self) -> usize {
        self.groups.len()
    }

    /// Fills `jac` (one value per pattern entry) by forward differences of `f` about `y`,
    /// where `f0 = f(y)` and `scale[i]` is the typical magnitude of state `i`.
    pub fn evaluate(
        &self,
        f: &mut dyn FnMut(&[f64], &mut [f64]),
        y: &[f64],
        f0: &[f64],
        scale: &[f64],
        jac: &mut [f64],
    ) {
        let n = y.len();
        let mut yp = y.to_vec();
        let mut fp = vec![0.0; n];
        let mut step = vec![0.0; n];
        let sqrt_eps = f64::EPSILON.sqrt();
        for group in &self.groups {
            for &c in group {
                let h = sqrt_eps * y[c].abs().max(scale[c]);
                // Make the step exactly representable.
                let yc = y[c] + h;
                step[c] = yc - y[c];
                yp[c] = yc;
            }
            f(&yp, &mut fp);
            for &c in group {
                for &k in &self.col_entries[c] {
                    let r = self.entries[k].0;
                    jac[k] = (fp[r] - f0[r]) / step[c];
                }
                yp[c] = y[c];
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A block pattern (here the entry (0, 0) of f = (y0 + 5 y1, y1)) must not perturb the
    /// columns it leaves out, or their couplings leak into the block's entries.
    #[test]
    fn columns_outside_the_pattern_are_not_perturbed() {
        let pattern = ColouredPattern::new(2, vec![(0, 0)]);
        let mut f = |y: &[f64], out: &mut [f64]| {
            out[0] = y[0] + 5.0 * y[1];
            out[1] = y[1];
        };
        let y = [0.3, 0.7];
        let mut f0 = [0.0; 2];
        f(&y, &mut f0);
        let mut jac = [0.0];
        pattern.evaluate(&mut f, &y, &f0, &[1.0, 1.0], &mut jac);
        assert!((jac[0] - 1.0).abs() < 1e-7, "{}", jac[0]);
    }

    #[test]
    fn tridiagonal_needs_three_colours_and_exact_linear_jacobian() {
        let n: usize = 10;
        let mut entries = Vec::new();
        for i in 0..n {
            for j in i.saturating_sub(1)..(i + 2).min(n) {
                entries.push((i, j));
            }
        }
        let pattern = ColouredPattern::new(n, entries);
        assert_eq!(pattern.n_colours(), 3);
        // f_i = -2 y_i + y_{i-1} + y_{i+1}: linear, so forward differences are exact up to
        // round-off.
        let mut f = |y: &[f64], out: &mut [f64]| {
            for i in 0..n {
                let l = if i > 0 { y[i - 1] } else { 0.0 };
                let r = if i + 1 < n { y[i + 1] } else { 0.0 };
                out[i] = -2.0 * y[i] + l + r;
            }
        };
        let y: Vec<f64> = (0..n).map(|i| i as f64 * 0.3).collect();
        let mut f0 = vec![0.0; n];
        f(&y, &mut f0);
        let mut jac = vec![0.0; pattern.entries.len()];
        pattern.evaluate(&mut f, &y, &f0, &vec![1.0; n], &mut jac);
        for (k, &(r, c)) in pattern.entries.iter().enumerate() {
            let exact = if r == c { -2.0 } else { 1.0 };
            assert!((jac[k] - exact).abs() < 1e-6, "({r},{c}) = {}", jac[k]);
        }
    }
}
