//! Stiff time integration: BDF/NDF with sparse LU, coloured finite-difference Jacobians,
//! dense output and event location.

pub mod bdf;
pub mod jacobian;
pub mod ordering;
pub mod sparse;
pub mod static_lu;

pub use bdf::{Dae, DenseOutput, SolverOptions, SolverStats, StopReason, Workspace, integrate};
