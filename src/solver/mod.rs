//! Stiff time integration: BDF/NDF with sparse LU, coloured finite-difference Jacobians,
//! dense output and event location.

pub mod bdf;
mod algebraic;
mod dense;
pub mod jacobian;
pub mod ordering;
pub mod sparse;
pub mod static_lu;
mod sweep;
mod workspace;

pub use bdf::{Bdf, Dae, DenseOutput, SolverOptions, SolverStats, StepInfo, StopReason, Workspace, integrate};
