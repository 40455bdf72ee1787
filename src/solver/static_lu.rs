//! Sparse LU with a fixed (fill-reducing, minimum-degree) symmetric ordering and no
//! pivoting: the symbolic structure, including every fill entry, is computed once, so a
//! numeric factorisation is row-wise Gaussian elimination in place, on positions looked up
//! once (an elimination program), and a solve is two sparse triangular sweeps. The elimination order
//! is sorted by level in the elimination tree (same fill), so neighbouring rows of a sweep
//! are independent and the processor overlaps them.
//!
//! Without pivoting a factorisation can meet a pivot that is tiny relative to its row; it
//! then reports failure and the caller falls back to a pivoting LU.

use super::ordering::minimum_degree;
use super::sweep::Sweep;

/// Factors `P A P^T = L U` of a square matrix with a fixed pattern.
#[derive(Clone)]
pub struct StaticLu {
    n: usize,
    /// `perm[i]`: original index of permuted row/column `i`.
    perm: Vec<usize>,
    /// Filled rows in permuted numbering: columns `cols[row_ptr[i]..row_ptr[i + 1]]`,
    /// increasing; `diag_pos[i]` is the position of column `i`.
    row_ptr: Vec<usize>,
    cols: Vec<usize>,
    diag_pos: Vec<usize>,
    /// Factor values (unit-lower `L` left of the diagonal, `U` from it).
    vals: Vec<f64>,
    /// `1 / U_ii`.
    inv_diag: Vec<f64>,
    /// Off-diagonal parts of `L` and of `D^-1 U`, row by row, for the solve.
    lower: Sweep,
    upper: Sweep,
    /// The elimination program: eliminating with the `L` entry at position `p` subtracts
    /// `L_p vals[q]` from `vals[t]` for each `(t, q)` in `updates[update_ptr[p]..update_ptr[p + 1]]`
    /// (`q` in the `U` row of the entry's column, `t` the same column in the entry's row).
    update_ptr: Vec<u32>,
    updates: Vec<(u32, u32)>,
    /// Permuted solve vector.
    z: Vec<f64>,
}

/// Smallest accepted |pivot| relative to the largest |entry| of its original row.
const PIVOT_TOL: f64 = 1e-10;

impl StaticLu {
    /// Symbolic analysis of the pattern `entries` (`(row, col)`, original numbering; the
    /// diagonal is added). Returns the factoriser and, for each entry, its position in the
    /// value array that [`StaticLu::factorise`] takes.
    pub fn new(n: usize, entries: &[(usize, usize)], last: &[usize]) -> (Self, Vec<usize>) {
        let elim = minimum_degree(n, entries, last).by_level();
        let perm = elim.order;
        let mut iperm = vec![0; n];
        for (i, &p) in perm.iter().enumerate() {
            iperm[p] = i;
        }
        // Row i of the filled matrix: {i} ∪ later(i) ∪ {k : i ∈ later(k)}, all permuted.
        let mut rows: Vec<Vec<usize>> = vec![Vec::new(); n];
        for (k, &pk) in perm.iter().enumerate() {
            rows[k].push(k);
            for &w in &elim.later[pk] {
                let j = iperm[w];
                rows[k].push(j);
                rows[j].push(k);
            }
        }
        let mut row_ptr = Vec::with_capacity(n + 1);
        let mut cols = Vec::new();
        let mut diag_pos = Vec::with_capacity(n);
        row_ptr.push(0);
        for (i, r) in rows.iter_mut().enumerate() {
            r.sort_unstable();
            r.dedup();
            diag_pos.push(cols.len() + r.binary_search(&i).expect("diagonal present"));
            cols.extend_from_slice(r);
            row_ptr.push(cols.len());
        }
        let pos = |r: usize, c: usize| -> usize {
            let (i, j) = (iperm[r], iperm[c]);
            let s = row_ptr[i];
            s + cols[s..row_ptr[i + 1]].binary_search(&j).expect("entry in filled pattern")
        };
        let slots = entries.iter().map(|&(r, c)| pos(r, c)).collect();
        let nnz = cols.len();
        // Row i is eliminated with each earlier row k of its L part, in increasing k; row k's
        // U entries (columns after k) are all in row i's filled pattern.
        let mut update_ptr = vec![0u32; nnz + 1];
        let mut updates = Vec::new();
        for i in 0..n {
            let row = &cols[row_ptr[i]..row_ptr[i + 1]];
            for p in row_ptr[i]..diag_pos[i] {
                let k = cols[p];
                for q in diag_pos[k] + 1..row_ptr[k + 1] {
                    let t = row_ptr[i] + row.binary_search(&cols[q]).expect("fill entry in pattern");
                    updates.push((t as u32, q as u32));
                }
                update_ptr[p + 1] = updates.len() as u32;
            }
            for p in diag_pos[i]..row_ptr[i + 1] {
                update_ptr[p + 1] = updates.len() as u32;
            }
        }
        let lower = Sweep::new(n, &cols, |i| row_ptr[i]..diag_pos[i]);
        let upper = Sweep::new(n, &cols, |i| diag_pos[i] + 1..row_ptr[i + 1]);
        let lu = Self {
            n,
            perm,
            row_ptr,
            cols,
            diag_pos,
            vals: vec![0.0; nnz],
            inv_diag: vec![0.0; n],
            lower,
            upper,
            update_ptr,
            updates,
            z: vec![0.0; n],
        };
        (lu, slots)
    }

    /// Entries of the factors, fill included.
    pub fn nnz(&self) -> usize {
        self.cols.len()
    }

    /// Value array to fill (with the matrix entries at the slots returned by
    /// [`StaticLu::new`]) before [`StaticLu::factorise`]; zero it first.
    pub fn values_mut(&mut self) -> &mut [f64] {
        &mut self.vals
    }

    /// Factorises in place the matrix loaded into [`StaticLu::values_mut`]. Returns `false`
    /// when a pivot is tiny relative to its row or not finite (the factors are then invalid).
    pub fn factorise(&mut self) -> bool {
        let (cols, vals, updates, update_ptr) = (&self.cols[..], &mut self.vals[..], &self.updates[..], &self.update_ptr[..]);
        let (row_ptr, diag_pos, inv_diag) = (&self.row_ptr[..], &self.diag_pos[..], &mut self.inv_diag[..]);
        // SAFETY: `new` builds `row_ptr` (length n + 1, non-decreasing, ending at
        // `cols.len() == vals.len()`), `diag_pos[i]` within row i, every column index below n
        // (the length of `inv_diag`), `update_ptr` (length nnz + 1, non-decreasing, ending at
        // `updates.len()`) and every update position below nnz; the eliminated rows k < i are
        // earlier rows of the same structure.
        unsafe {
            for i in 0..self.n {
                let (start, end, d) = (*row_ptr.get_unchecked(i), *row_ptr.get_unchecked(i + 1), *diag_pos.get_unchecked(i));
                // `a > row_max` skips a NaN as `f64::max` does, in one instruction instead of
                // `max`'s NaN-handling sequence.
                let mut row_max = 0.0f64;
                for &v in vals.get_unchecked(start..end) {
                    let a = v.abs();
                    if a > row_max {
                        row_max = a;
                    }
                }
                for p in start..d {
                    let k = *cols.get_unchecked(p);
                    let l = *vals.get_unchecked(p) * *inv_diag.get_unchecked(k);
                    *vals.get_unchecked_mut(p) = l;
                    if l != 0.0 {
                        let (a, b) = (*update_ptr.get_unchecked(p) as usize, *update_ptr.get_unchecked(p + 1) as usize);
                        for &(t, q) in updates.get_unchecked(a..b) {
                            let v = l * *vals.get_unchecked(q as usize);
                            *vals.get_unchecked_mut(t as usize) -= v;
                        }
                    }
                }
                let pivot = *vals.get_unchecked(d);
                if !(pivot.abs() > PIVOT_TOL * row_max) || !pivot.is_finite() {
                    return false;
                }
                *inv_diag.get_unchecked_mut(i) = 1.0 / pivot;
            }
        }
        for (v, &p) in self.lower.vals.iter_mut().zip(&self.lower.pos) {
            *v = self.vals[p as usize];
        }
        let u = &mut self.upper;
        for (i, &d) in self.inv_diag.iter().enumerate() {
            let row = u.row_start(i)..u.row_start(i + 1);
            for (v, &p) in u.vals[row.clone()].iter_mut().zip(&u.pos[row]) {
                *v = self.vals[p as usize] * d;
            }
        }
        true
    }

    /// Solves `A x = b` in place with the last successful factorisation.
    pub fn solve(&mut self, b: &mut [f64]) {
        assert_eq!(b.len(), self.n);
        let z = &mut self.z[..];
        // SAFETY: `perm` is a permutation of 0..n, `b.len() == n`, and the sweeps were built by
        // `new` with n rows and columns below n. This is the innermost loop of every Newton
        // iteration, where bounds checks would cost as much as the arithmetic.
        unsafe {
            for (zi, &p) in z.iter_mut().zip(&self.perm) {
                *zi = *b.get_unchecked(p);
            }
            // L z = P b, row by row: each row's columns are earlier rows, already final.
            self.lower.forward(z);
            // (D^-1 U) x = D^-1 z, from the last row up.
            for (zi, d) in z.iter_mut().zip(&self.inv_diag) {
                *zi *= d;
            }
            self.upper.backward(z);
            for (zi, &p) in z.iter().zip(&self.perm) {
                *b.get_unchecked_mut(p) = *zi;
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A 2-D five-point Laplacian plus identity (fill is unavoidable) against a dense solve.
    #[test]
    fn solves_a_grid_laplacian_like_dense_elimination() {
        let m = 5;
        let n = m * m;
        let mut entries = Vec::new();
        let mut a = vec![0.0; n * n];
        for i in 0..m {
            for j in 0..m {
                let r = i * m + j;
                entries.push((r, r));
                a[r * n + r] = 5.0;
                for (di, dj) in [(0i64, 1i64), (1, 0), (0, -1), (-1, 0)] {
                    let (ii, jj) = (i as i64 + di, j as i64 + dj);
                    if ii >= 0 && jj >= 0 && ii < m as i64 && jj < m as i64 {
                        let c = ii as usize * m + jj as usize;
                        entries.push((r, c));
                        // unsymmetric values on a symmetric pattern
                        a[r * n + c] = -1.0 - 0.1 * (r as f64 - c as f64).signum();
                    }
                }
            }
        }
        let (mut lu, slots) = StaticLu::new(n, &entries, &[]);
        for (&(r, c), &s) in entries.iter().zip(&slots) {
            lu.values_mut()[s] = a[r * n + c];
        }
        assert!(lu.factorise());
        let x_true: Vec<f64> = (0..n).map(|i| (i as f64 * 0.37).sin()).collect();
        let mut b: Vec<f64> = (0..n).map(|r| (0..n).map(|c| a[r * n + c] * x_true[c]).sum()).collect();
        lu.solve(&mut b);
        for (x, t) in b.iter().zip(&x_true) {
            assert!((x - t).abs() < 1e-12, "{x} vs {t}");
        }
    }

    #[test]
    fn zero_pivot_is_reported() {
        let entries = [(0, 0), (0, 1), (1, 0), (1, 1)];
        let (mut lu, slots) = StaticLu::new(2, &entries, &[]);
        // [[0, 1], [1, 0]] needs pivoting.
        for (&(r, c), &s) in entries.iter().zip(&slots) {
            lu.values_mut()[s] = if r == c { 0.0 } else { 1.0 };
        }
        assert!(!lu.factorise());
    }
}
