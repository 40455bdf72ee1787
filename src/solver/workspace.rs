//! The integrator's reusable work space for one model build: Jacobian pattern and colouring,
//! the sparse LU of the Newton matrix, and the algebraic block for consistent initialisation.

use super::jacobian::ColouredPattern;
use super::sparse::SparseSystem;
use crate::error::Error;

/// Reusable work space for one model build: Jacobian pattern, colouring and sparse LU.
pub struct Workspace {
    pub(super) pattern: ColouredPattern,
    pub(super) system: SparseSystem,
    pub(super) jac: Vec<f64>,
    /// The algebraic block (algebraic rows and columns) with its own, smaller colouring, and
    /// each of its entries' place in `pattern`; built at the first consistent initialisation.
    algebraic: Option<(ColouredPattern, Vec<usize>)>,
    algebraic_jac: Vec<f64>,
}

impl Workspace {
    /// Builds the work space for `n` states and Jacobian entries `(row, col)` (duplicates
    /// are merged).
    pub fn new(n: usize, mut entries: Vec<(usize, usize)>) -> Result<Self, Error> {
        entries.sort_unstable();
        entries.dedup();
        let system = SparseSystem::new(n, &entries)?;
        let jac = vec![0.0; entries.len()];
        Ok(Self { pattern: ColouredPattern::new(n, entries), system, jac, algebraic: None, algebraic_jac: Vec::new() })
    }

    /// Residual evaluations per Jacobian.
    pub fn n_colours(&self) -> usize {
        self.pattern.n_colours()
    }

    /// Entries of the LU factors of the Newton matrix, fill included (zero fill means the
    /// factors have as many entries as the pattern plus the diagonal).
    pub fn factor_nnz(&self) -> usize {
        self.system.factor_nnz()
    }

    /// Factorises the Newton matrix of the algebraic rows alone, `diag(mass) + J_aa`
    /// (identity on differential rows), for consistent initialisation; `f0 = f(y)`. Only the
    /// algebraic columns are perturbed, so a Jacobian costs the colours of the algebraic block
    /// (the DFN's potentials) instead of those of the whole pattern.
    pub fn factorise_algebraic(
        &mut self,
        f: &mut dyn FnMut(&[f64], &mut [f64]),
        y: &[f64],
        f0: &[f64],
        scale: &[f64],
        mass: &[f64],
    ) -> Result<(), Error> {
        let full = &self.pattern.entries;
        let (block, place) = self.algebraic.get_or_insert_with(|| {
            let (place, entries): (Vec<usize>, Vec<(usize, usize)>) =
                full.iter().enumerate().filter(|&(_, &(r, c))| mass[r] == 0.0 && mass[c] == 0.0).unzip();
            (ColouredPattern::new(y.len(), entries), place)
        });
        self.algebraic_jac.resize(place.len(), 0.0);
        block.evaluate(f, y, f0, scale, &mut self.algebraic_jac);
        self.jac.iter_mut().for_each(|v| *v = 0.0);
        for (&k, &v) in place.iter().zip(&self.algebraic_jac) {
            self.jac[k] = v;
        }
        self.system.factorise(mass, -1.0, &self.jac)
    }

    /// Solves with the last factorisation.
    pub fn solve(&mut self, rhs: &mut [f64]) {
        self.system.solve(rhs)
    }
}
