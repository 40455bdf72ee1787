//! Parameter sets: typed structs in SI units, the embedded Chen 2020 default, BPX exchange,
//! and the cell's mass and volume budget.

pub(crate) mod check;
mod chen2020;
pub mod bpx;
pub mod function;
pub mod mass;
mod initial_state;
mod load;
mod overrides;
mod set;
pub mod soc;

pub use chen2020::chen2020;
pub use function::Function1D;
pub use mass::CellBudget;
pub use overrides::{Override, apply_overrides, from_base_table};
pub use soc::{StoichiometryWindow, set_initial_soc, stoichiometry_window};
pub use set::{Cell, Electrode, Electrolyte, FARADAY, GAS_CONSTANT, ParameterSet, Separator, Thermal};
