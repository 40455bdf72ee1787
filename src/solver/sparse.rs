//! Sparse Newton matrix `M - c J` with a fixed pattern.
//!
//! The matrix is factorised by [`StaticLu`] (minimum-degree ordering, no pivoting, symbolic
//! structure computed once per pattern, i.e. once per model build). Should a pivot come out
//! tiny, that factorisation is redone by faer's sparse LU with partial pivoting, whose
//! symbolic analysis is built on first need.

use faer::dyn_stack::{MemBuffer, MemStack};
use faer::sparse::linalg::lu::{LuRef, NumericLu, SymbolicLu, factorize_symbolic_lu};
use faer::sparse::{SparseColMatRef, SymbolicSparseColMat};
use faer::{Conj, Par};

use super::static_lu::StaticLu;
use crate::error::Error;

/// The compressed-column pattern of `entries` (row, col) plus the diagonal of an `n x n`
/// matrix, with the value slot of each entry and of each diagonal element.
pub(crate) fn pattern_with_diagonal(n: usize, entries: &[(usize, usize)]) -> (SymbolicSparseColMat<usize>, Vec<usize>, Vec<usize>) {
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
    let slots = entries.iter().map(|&(r, c)| slot_of(r, c)).collect();
    let diag = (0..n).map(|i| slot_of(i, i)).collect();
    (SymbolicSparseColMat::new_checked(n, n, col_ptr, None, row_idx), slots, diag)
}

/// A square sparse matrix with a fixed pattern (the Jacobian pattern plus the diagonal).
#[derive(Clone)]
pub struct SparseSystem {
    n: usize,
    entries: Vec<(usize, usize)>,
    lu: StaticLu,
    /// Slots in `lu`'s value array of the Jacobian entries and of the diagonal.
    jac_slots: Vec<usize>,
    diag_slots: Vec<usize>,
    /// The Jacobian loaded by [`SparseSystem::load_jacobian`], laid out as `lu`'s value
    /// array (zero in the slots no Jacobian entry writes: fill, and diagonals outside the
    /// pattern), so that each factorisation fills the matrix in one contiguous pass.
    jac_lu: Vec<f64>,
    /// Pivoting fallback, built on first need.
    fallback: Option<Box<PivotingLu>>,
    /// Which factorisation `solve` uses.
    state: Factorised,
}

#[derive(Clone, Copy, PartialEq)]
enum Factorised {
    No,
    Static,
    Pivoting,
}

impl SparseSystem {
    /// Number of states.
    pub fn len(&self) -> usize {
        self.n
    }

    /// Builds the pattern from distinct Jacobian entries `(row, col)`, the unknowns `last`
    /// eliminated last (see [`super::ordering::minimum_degree`]).
    pub fn new(n: usize, entries: &[(usize, usize)], last: &[usize]) -> Result<Self, Error> {
        if let Some(&(r, c)) = entries.iter().find(|&&(r, c)| r >= n || c >= n) {
            return Err(Error::Linear(format!("Jacobian entry ({r}, {c}) outside a {n} x {n} matrix")));
        }
        let mut all = entries.to_vec();
        all.extend((0..n).map(|i| (i, i)));
        let (lu, mut slots) = StaticLu::new(n, &all, last);
        let diag_slots = slots.split_off(entries.len());
        let jac_lu = vec![0.0; lu.nnz()];
        Ok(Self {
            n,
            entries: entries.to_vec(),
            lu,
            jac_slots: slots,
            diag_slots,
            jac_lu,
            fallback: None,
            state: Factorised::No,
        })
    }

    /// Sets the matrix to `diag(mass) - c * J`, where `jac[k]` is the value of entry `k` of the
    /// pattern given to [`SparseSystem::new`], and factorises it.
    pub fn factorise(&mut self, mass: &[f64], c: f64, jac: &[f64]) -> Result<(), Error> {
        self.load_jacobian(jac);
        self.factorise_loaded(mass, c)
    }

    /// Loads the Jacobian `J` (`jac[k]` the value of entry `k` of the pattern given to
    /// [`SparseSystem::new`]) for the factorisations that follow: a Jacobian serves several
    /// Newton matrices (one per step-size change), so it is laid out once.
    pub fn load_jacobian(&mut self, jac: &[f64]) {
        // Entries are distinct, so each Jacobian slot is written once.
        for (&slot, &j) in self.jac_slots.iter().zip(jac) {
            self.jac_lu[slot] = j;
        }
    }

    /// Sets the matrix to `diag(mass) - c * J` with the last loaded Jacobian and factorises it.
    pub fn factorise_loaded(&mut self, mass: &[f64], c: f64) -> Result<(), Error> {
        self.state = Factorised::No;
        let vals = self.lu.values_mut();
        for (v, &j) in vals.iter_mut().zip(&self.jac_lu) {
            *v = 0.0 - c * j;
        }
        for (&slot, &m) in self.diag_slots.iter().zip(mass) {
            vals[slot] += m;
        }
        if self.lu.factorise() {
            self.state = Factorised::Static;
            return Ok(());
        }
        if self.fallback.is_none() {
            self.fallback = Some(Box::new(PivotingLu::new(self.n, &self.entries)?));
        }
        let jac: Vec<f64> = self.jac_slots.iter().map(|&slot| self.jac_lu[slot]).collect();
        self.fallback.as_mut().expect("built above").factorise(mass, c, &jac)?;
        self.state = Factorised::Pivoting;
        Ok(())
    }

    /// Solves in place with the last factorisation.
    pub fn solve(&mut self, rhs: &mut [f64]) {
        debug_assert_eq!(rhs.len(), self.n);
        match self.state {
            Factorised::Static => self.lu.solve(rhs),
            Factorised::Pivoting => self.fallback.as_mut().expect("factorised").solve(rhs),
            Factorised::No => panic!("factorise before solve"),
        }
    }

    /// Whether the last factorisation fell back to partial pivoting (a tiny static pivot).
    pub fn pivoted(&self) -> bool {
        self.state == Factorised::Pivoting
    }

    /// Entries of the triangular factors of the unpivoted LU, fill included.
    pub fn factor_nnz(&self) -> usize {
        self.lu.nnz()
    }
}

/// faer's sparse LU with partial pivoting on the same pattern.
struct PivotingLu {
    n: usize,
    symbolic: SymbolicSparseColMat<usize>,
    /// Position of each diagonal entry in `values`.
    diag: Vec<usize>,
    /// For each pattern entry `(row, col)` of the Jacobian (in the caller's order), its slot.
    slots: Vec<usize>,
    values: Vec<f64>,
    symbolic_lu: SymbolicLu<usize>,
    numeric_lu: NumericLu<usize, f64>,
    factorised: bool,
    factor_scratch: MemBuffer,
    solve_scratch: MemBuffer,
}

impl Clone for PivotingLu {
    fn clone(&self) -> Self {
        Self::from_parts(self.n, self.symbolic.clone(), self.diag.clone(), self.slots.clone(), self.symbolic_lu.clone())
    }
}

impl PivotingLu {
    /// Builds the pattern from distinct Jacobian entries `(row, col)`.
    fn new(n: usize, entries: &[(usize, usize)]) -> Result<Self, Error> {
        let (symbolic, slots, diag) = pattern_with_diagonal(n, entries);
        let symbolic_lu = factorize_symbolic_lu(symbolic.as_ref(), Default::default())
            .map_err(|e| Error::Linear(format!("symbolic LU: {e:?}")))?;
        Ok(Self::from_parts(n, symbolic, diag, slots, symbolic_lu))
    }

    fn from_parts(
        n: usize,
        symbolic: SymbolicSparseColMat<usize>,
        diag: Vec<usize>,
        slots: Vec<usize>,
        symbolic_lu: SymbolicLu<usize>,
    ) -> Self {
        let factor_scratch =
            MemBuffer::new(symbolic_lu.factorize_numeric_lu_scratch::<f64>(Par::Seq, Default::default()));
        let solve_scratch = MemBuffer::new(symbolic_lu.solve_in_place_scratch::<f64>(1, Par::Seq));
        let nnz = symbolic.row_idx().len();
        Self {
            n,
            symbolic,
            diag,
            slots,
            values: vec![0.0; nnz],
            symbolic_lu,
            numeric_lu: NumericLu::new(),
            factorised: false,
            factor_scratch,
            solve_scratch,
        }
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
        self.factorised = false;
        self.symbolic_lu
            .factorize_numeric_lu(
                &mut self.numeric_lu,
                mat,
                Par::Seq,
                MemStack::new(&mut self.factor_scratch),
                Default::default(),
            )
            .map_err(|e| Error::Linear(format!("numeric LU: {e:?}")))?;
        self.factorised = true;
        Ok(())
    }

    /// Solves in place with the last factorisation.
    pub fn solve(&mut self, rhs: &mut [f64]) {
        debug_assert_eq!(rhs.len(), self.n);
        assert!(self.factorised, "factorise before solve");
        LuRef::new_unchecked(&self.symbolic_lu, &self.numeric_lu).solve_in_place_with_conj(
            Conj::No,
            faer::ColMut::from_slice_mut(rhs).as_mat_mut(),
            Par::Seq,
            MemStack::new(&mut self.solve_scratch),
        );
    }
}
