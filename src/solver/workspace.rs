//! The integrator's reusable work space for one model build: Jacobian pattern and colouring,
//! the sparse LU of the Newton matrix, and the algebraic block for consistent initialisation.

use super::algebraic::AlgebraicBlock;
use super::jacobian::ColouredPattern;
use super::sparse::SparseSystem;
use crate::error::Error;

/// Reusable work space for one model build: Jacobian pattern, colouring and sparse LU.
pub struct Workspace {
    pub(super) pattern: ColouredPattern,
    pub(super) system: SparseSystem,
    pub(super) jac: Vec<f64>,
    /// The algebraic block (algebraic rows and columns) with its own, smaller colouring and
    /// LU; built at the first consistent initialisation.
    algebraic: Option<AlgebraicBlock>,
    /// A work space for the same DAE with more states (a voltage hold's: the model's states
    /// and the current), built at its first use and kept with this one.
    extended: Option<Box<Workspace>>,
}

impl Workspace {
    /// Builds the work space for `n` states and Jacobian entries `(row, col)` (duplicates
    /// are merged).
    pub fn new(n: usize, entries: Vec<(usize, usize)>) -> Result<Self, Error> {
        Self::eliminating_last(n, entries, &[])
    }

    /// [`Workspace::new`] with the unknowns `last` eliminated last by the LU.
    fn eliminating_last(n: usize, mut entries: Vec<(usize, usize)>, last: &[usize]) -> Result<Self, Error> {
        entries.sort_unstable();
        entries.dedup();
        let system = SparseSystem::new(n, &entries, last)?;
        let jac = vec![0.0; entries.len()];
        Ok(Self { pattern: ColouredPattern::new(n, entries), system, jac, algebraic: None, extended: None })
    }

    /// The work space for this DAE extended to `n` states with Jacobian entries `entries()`,
    /// built at the first call (or when `n` changes) and kept, so that a cycle's voltage
    /// holds do not each rebuild its colouring and symbolic LU. The extension's last state (a
    /// hold's current, whose own pivot is zero without a contact resistance) is eliminated
    /// last.
    pub fn extended(&mut self, n: usize, entries: impl FnOnce() -> Vec<(usize, usize)>) -> Result<&mut Workspace, Error> {
        match &mut self.extended {
            Some(ws) if ws.system.len() == n => {}
            slot => *slot = Some(Box::new(Workspace::eliminating_last(n, entries(), &[n - 1])?)),
        }
        Ok(self.extended.as_deref_mut().expect("built above"))
    }

    /// Residual evaluations per Jacobian.
    pub fn n_colours(&self) -> usize {
        self.pattern.n_colours()
    }

    /// Whether the last factorisation of the Newton matrix fell back to partial pivoting (a
    /// tiny static pivot).
    pub fn pivoted(&self) -> bool {
        self.system.pivoted()
    }

    /// Entries of the LU factors of the Newton matrix, fill included (zero fill means the
    /// factors have as many entries as the pattern plus the diagonal).
    pub fn factor_nnz(&self) -> usize {
        self.system.factor_nnz()
    }

    /// Evaluates and factorises the Jacobian block `J_aa` of the algebraic rows with respect
    /// to the algebraic states at `y` (with `f0 = f(y)`), for consistent initialisation. Only
    /// the algebraic columns are perturbed and only the block is factorised, so this costs the
    /// colours and the LU of the algebraic block (the DFN's potentials), not of the whole
    /// pattern; the Newton matrix and Jacobian of the integrator are left untouched.
    pub fn factorise_algebraic(
        &mut self,
        f: &mut dyn FnMut(&[f64], &mut [f64]),
        y: &[f64],
        f0: &[f64],
        scale: &[f64],
        mass: &[f64],
    ) -> Result<(), Error> {
        let block = match &mut self.algebraic {
            Some(block) => block,
            None => self.algebraic.insert(AlgebraicBlock::new(&self.pattern.entries, mass)?),
        };
        block.factorise(f, y, f0, scale)
    }

    /// Applies `J_aa^-1` of the last [`Workspace::factorise_algebraic`] to the algebraic
    /// entries of `rhs` in place (the differential entries are left alone).
    pub fn solve_algebraic(&mut self, rhs: &mut [f64]) {
        self.algebraic.as_mut().expect("factorise_algebraic before solve_algebraic").solve(rhs)
    }
}
