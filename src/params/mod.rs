//! Parameter sets: typed structs in SI units, the embedded Chen 2020 default, BPX exchange,
//! the cell's mass and volume budget, and cell formats (can or pouch) that size the stack.

pub(crate) mod check;
mod capacity;
mod chen2020;
pub mod bpx;
pub mod format;
pub mod function;
pub mod mass;
pub mod pybop_mass;
mod initial_state;
pub mod lam;
mod load;
mod overrides;
pub mod ocv_correction;
pub mod second_phase;
pub mod plating;
pub mod sei;
mod set;
pub mod soc;

pub use chen2020::chen2020;
pub use function::Function1D;
pub use format::{CellFormat, Cylindrical, FormatName, Pouch, Sizing};
pub use pybop_mass::{MassConvention, PybopDensities};
pub use mass::{CellBudget, MassBasis, MassComponent, Part, StackAreas};
pub use overrides::{Override, apply_overrides, from_base_table};
pub use soc::{StoichiometryWindow, set_initial_soc, set_initial_soc_from, stoichiometry_window};
pub use lam::{Lam, LamElectrode};
pub use plating::Plating;
pub use ocv_correction::OcvCorrection;
pub use second_phase::BlendOcp;
pub use sei::Sei;
pub use set::{Cell, DEFAULT_RADIUS_RELATIVE_STD, Electrode, Electrolyte, FARADAY, GAS_CONSTANT, MAX_RADIUS_RELATIVE_STD, ParameterSet, Separator, Thermal};
