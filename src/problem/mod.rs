//! Problems: what to simulate for a candidate parameter vector and what to measure.

pub mod balancing;
pub mod bracket;
pub mod design;
pub mod experiment_design;
pub mod fade;
pub mod fast_charge;
pub mod fit_parameter;
pub mod fitting;
pub mod gitt;
pub mod global_sensitivity;
pub mod delay;
pub mod history;
pub mod identification;
pub mod joint;
pub mod least_squares;
pub mod life;
pub mod lost_lithium;
pub mod model_spec;
pub mod posterior;
pub mod profile;
pub mod pulse;
pub mod sensitivity;
pub mod sweep;
pub mod timed_energy;
pub mod verdict;
