//! The algebraic block of a semi-explicit DAE (algebraic rows and columns only), for
//! consistent initialisation: its own colouring (fewer colours than the whole pattern) and
//! its own, much smaller, sparse LU.

use super::jacobian::ColouredPattern;
use super::sparse::SparseSystem;
use crate::error::Error;

/// The Jacobian block `J_aa` of the algebraic rows with respect to the algebraic states.
pub(super) struct AlgebraicBlock {
    /// Indices of the algebraic states (rows with a zero mass).
    index: Vec<usize>,
    /// The block's entries in full numbering, coloured by their columns.
    pattern: ColouredPattern,
    /// `J_aa` in compact numbering (position in `index`), factorised by [`AlgebraicBlock::factorise`].
    system: SparseSystem,
    /// Values of the block's entries, in `pattern`'s order.
    jac: Vec<f64>,
    /// Zero mass of the compact system, and the compact right-hand side.
    zero_mass: Vec<f64>,
    rhs: Vec<f64>,
}

impl AlgebraicBlock {
    /// The block of the full pattern `entries` (full numbering) for the mass diagonal `mass`.
    pub(super) fn new(entries: &[(usize, usize)], mass: &[f64]) -> Result<Self, Error> {
        let n = mass.len();
        let index: Vec<usize> = (0..n).filter(|&i| mass[i] == 0.0).collect();
        let mut compact = vec![usize::MAX; n];
        for (k, &i) in index.iter().enumerate() {
            compact[i] = k;
        }
        let block: Vec<(usize, usize)> = entries.iter().copied().filter(|&(r, c)| mass[r] == 0.0 && mass[c] == 0.0).collect();
        let local: Vec<(usize, usize)> = block.iter().map(|&(r, c)| (compact[r], compact[c])).collect();
        let na = index.len();
        Ok(Self {
            system: SparseSystem::new(na, &local, &[])?,
            jac: vec![0.0; block.len()],
            pattern: ColouredPattern::new(n, block),
            index,
            zero_mass: vec![0.0; na],
            rhs: vec![0.0; na],
        })
    }

    /// Evaluates `J_aa` at `y` by coloured differences of `f` (with `f0 = f(y)`, `scale` the
    /// states' typical magnitudes) and factorises it.
    pub(super) fn factorise(
        &mut self,
        f: &mut dyn FnMut(&[f64], &mut [f64]),
        y: &[f64],
        f0: &[f64],
        scale: &[f64],
    ) -> Result<(), Error> {
        self.pattern.evaluate(f, y, f0, scale, &mut self.jac);
        // diag(0) - (-1) J_aa = J_aa
        self.system.factorise(&self.zero_mass, -1.0, &self.jac)
    }

    /// Replaces the algebraic entries of the full-length `rhs` by `J_aa^-1` applied to them
    /// (the differential entries are left alone).
    pub(super) fn solve(&mut self, rhs: &mut [f64]) {
        for (r, &i) in self.rhs.iter_mut().zip(&self.index) {
            *r = rhs[i];
        }
        self.system.solve(&mut self.rhs);
        for (r, &i) in self.rhs.iter().zip(&self.index) {
            rhs[i] = *r;
        }
    }
}
