//! Sparse Newton matrix `M - c J` with a fixed pattern, factorised by faer's sparse LU.
//!
//! The symbolic factorisation is done once per pattern (once per mesh); every Newton-matrix
//! update is a numeric refactorisation only.

use faer::Par;
use faer::linalg::solvers::Solve;
use faer::sparse::linalg::solvers::{Lu, SymbolicLu};
use faer::sparse::{SparseColMatRef, SymbolicSparseColMat};

use crate::error::Error;

/// A square sparse matrix with a fixed pattern (the Jacobian pattern plus the diagonal).
pub struct SparseSystem {
    n: usize,
    symbolic: SymbolicSparseColMat<usize>,
    /// Position of each diagonal entry in `values`.
    diag: Vec<usize>,
    /// For each pattern entry `(row, col)` of the Jacobian (in the caller's order), its slot.
    slots: Vec<usize>,
    values: Vec<f64>,
    symbolic_lu: SymbolicLu<usize>,
    lu: Option<Lu<usize, f64>>,
}

impl SparseSystem {
    /// Builds the pattern from distinct Jacobian entries `(row, col)`.
    pub fn new(n: usize, entries: &[(usize, usize)]) -> Result<Self, Error> {
        let mut cols: Vec<Vec<usize>> = vec![Vec::new(); n];
        for &(r, c) in entries {
            cols[c].push(r);
        }
        for (c, rows) in cols.iter_mut().enumerate() {
            rows.push(c);
            rows.sort_unstable();
            rows.dedup();
        }
        let mut col_ptr = Vec::with_capacity(n + 1);
        let mut row_idx = Vec::new();
        col_ptr.push(0);
        for rows in &cols {
            row_idx.extend_from_slice(rows);
            col_ptr.push(row_idx.len());
        }
        let slot_of = |r: usize, c: usize| -> usize {
            let start = col_ptr[c];
            start + row_idx[start..col_ptr[c + 1]].binary_search(&r).expect("entry in pattern")
        };
        let diag = (0..n).map(|i| slot_of(i, i)).collect();
        let slots = entries.iter().map(|&(r, c)| slot_of(r, c)).collect();
        let nnz = row_idx.len();
        let symbolic = SymbolicSparseColMat::new_checked(n, n, col_ptr, None, row_idx);
        let symbolic_lu = SymbolicLu::try_new(symbolic.as_ref())
            .map_err(|e| Error::Linear(format!("symbolic LU: {e:?}")))?;
        Ok(Self { n, symbolic, diag, slots, values: vec![0.0; nnz], symbolic_lu, lu: None })
    }

    /// Number of stored non-zeros.
    pub fn nnz(&self) -> usize {
        self.values.len()
    }

    /// Sets the matrix to `diag(mass) - c * J`, where `jac[k]` is the value of entry `k` of the
    /// pattern given to [`SparseSystem::new`], and factorises it.
    pub fn factorise(&mut self, mass: &[f64], c: f64, jac: &[f64]) -> Result<(), Error> {
        self.values.iter_mut().for_each(|v| *v = 0.0);
        for (&slot, &j) in self.slots.iter().zip(jac) {
            self.values[slot] -= c * j;
        }
        for (i, &slot) in self.diag.iter().enumerate() {
            self.values[slot] += mass[i];
        }
        let mat = SparseColMatRef::new(self.symbolic.as_ref(), &self.values);
        faer::set_global_parallelism(Par::Seq);
        let lu = Lu::try_new_with_symbolic(self.symbolic_lu.clone(), mat)
            .map_err(|e| Error::Linear(format!("numeric LU: {e:?}")))?;
        self.lu = Some(lu);
        Ok(())
    }

    /// Solves in place with the last factorisation.
    pub fn solve(&self, rhs: &mut [f64]) {
        debug_assert_eq!(rhs.len(), self.n);
        let lu = self.lu.as_ref().expect("factorise before solve");
        lu.solve_in_place(faer::ColMut::from_slice_mut(rhs).as_mat_mut());
    }
}
