//! Costs and likelihoods of fitting problems, and priors of fitted parameters.

mod kind;
mod prior;

pub use kind::{CostKind, CostValue};
pub use prior::Prior;
