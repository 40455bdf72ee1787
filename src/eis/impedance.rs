//! Frequency response of a linearised model: `Z(w) = -(C (i w M - J)^{-1} B + D)` (ohm),
//! with current discharge-positive, so `Re Z > 0` for a passive cell.
//!
//! The complex matrix `i w M - J` has the same pattern at every frequency: its symbolic LU
//! (ordering, elimination tree) is computed once, and each frequency costs one numeric
//! complex sparse LU and one solve. Frequencies are spread over rayon workers.

use faer::c64;
use faer::dyn_stack::{MemBuffer, MemStack};
use faer::sparse::linalg::lu::{LuRef, NumericLu, SymbolicLu, factorize_symbolic_lu};
use faer::sparse::{SparseColMatRef, SymbolicSparseColMat};
use faer::{Conj, Par};
use rayon::prelude::*;

use super::linearise::Linearisation;
use super::spectrum::Spectrum;
use crate::error::Error;
use crate::solver::sparse::pattern_with_diagonal;

/// Reusable complex solver for the impedance of one linearisation at many frequencies.
pub struct ImpedanceSolver<'a> {
    lin: &'a Linearisation,
    symbolic: SymbolicSparseColMat<usize>,
    /// For each Jacobian entry, its slot in the CSC values.
    slots: Vec<usize>,
    /// Slot of each diagonal entry.
    diag: Vec<usize>,
    symbolic_lu: SymbolicLu<usize>,
}

/// Per-worker scratch: values, numeric LU and work buffers.
struct Scratch {
    values: Vec<c64>,
    numeric: NumericLu<usize, c64>,
    factor: MemBuffer,
    solve: MemBuffer,
    rhs: Vec<c64>,
}

impl<'a> ImpedanceSolver<'a> {
    /// Builds the pattern of `i w M - J` (Jacobian entries plus the diagonal) and its
    /// symbolic LU.
    pub fn new(lin: &'a Linearisation) -> Result<Self, Error> {
        let entries: Vec<(usize, usize)> = lin.jacobian.iter().map(|&(r, c, _)| (r, c)).collect();
        let (symbolic, slots, diag) = pattern_with_diagonal(lin.n, &entries);
        let symbolic_lu = factorize_symbolic_lu(symbolic.as_ref(), Default::default())
            .map_err(|e| Error::Linear(format!("symbolic LU: {e:?}")))?;
        Ok(Self { lin, symbolic, slots, diag, symbolic_lu })
    }

    fn scratch(&self) -> Scratch {
        Scratch {
            values: vec![c64::new(0.0, 0.0); self.symbolic.row_idx().len()],
            numeric: NumericLu::new(),
            factor: MemBuffer::new(self.symbolic_lu.factorize_numeric_lu_scratch::<c64>(Par::Seq, Default::default())),
            solve: MemBuffer::new(self.symbolic_lu.solve_in_place_scratch::<c64>(1, Par::Seq)),
            rhs: vec![c64::new(0.0, 0.0); self.lin.n],
        }
    }

    /// Impedance (ohm) at angular frequency `omega` (rad/s).
    fn at(&self, s: &mut Scratch, omega: f64) -> Result<c64, Error> {
        let lin = self.lin;
        s.values.iter_mut().for_each(|v| *v = c64::new(0.0, 0.0));
        for (&slot, &(_, _, j)) in self.slots.iter().zip(&lin.jacobian) {
            s.values[slot].re -= j;
        }
        for (&slot, &m) in self.diag.iter().zip(&lin.mass) {
            s.values[slot].im += omega * m;
        }
        let mat = SparseColMatRef::new(self.symbolic.as_ref(), &s.values);
        self.symbolic_lu
            .factorize_numeric_lu(&mut s.numeric, mat, Par::Seq, MemStack::new(&mut s.factor), Default::default())
            .map_err(|e| Error::Linear(format!("numeric LU at omega = {omega} rad/s: {e:?}")))?;
        for (r, &b) in s.rhs.iter_mut().zip(&lin.b) {
            *r = c64::new(b, 0.0);
        }
        LuRef::new_unchecked(&self.symbolic_lu, &s.numeric).solve_in_place_with_conj(
            Conj::No,
            faer::ColMut::from_slice_mut(&mut s.rhs).as_mat_mut(),
            Par::Seq,
            MemStack::new(&mut s.solve),
        );
        let mut z = c64::new(lin.d, 0.0);
        for (x, &c) in s.rhs.iter().zip(&lin.c) {
            z += x * c;
        }
        let z = -z;
        if z.re.is_finite() && z.im.is_finite() {
            Ok(z)
        } else {
            Err(Error::Linear(format!("non-finite impedance at omega = {omega} rad/s (singular system)")))
        }
    }

    /// Impedance spectrum at `frequencies` (Hz, positive).
    pub fn spectrum(&self, frequencies: &[f64]) -> Result<Spectrum, Error> {
        super::spectrum::check_frequencies(frequencies)?;
        let z: Vec<c64> = frequencies
            .par_iter()
            .map_init(|| self.scratch(), |s, &f| self.at(s, 2.0 * std::f64::consts::PI * f))
            .collect::<Result<_, _>>()?;
        Spectrum::new(frequencies.to_vec(), z.iter().map(|v| v.re).collect(), z.iter().map(|v| v.im).collect())
    }
}

/// Impedance spectrum of a linearisation at `frequencies` (Hz).
pub fn impedance(lin: &Linearisation, frequencies: &[f64]) -> Result<Spectrum, Error> {
    ImpedanceSolver::new(lin)?.spectrum(frequencies)
}
