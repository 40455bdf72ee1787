//! Optional physics added to a model: lumped thermal balance (contact resistance is a
//! single series term applied in each model's voltage), states appended by a wrapper
//! (series RC element, OCV hysteresis), and SEI growth inside the single-particle models.

pub mod augmented;
pub mod sei;
pub mod thermal;

pub use augmented::Augmented;
pub use sei::{SeiLayer, SeiModel};
pub use thermal::LumpedThermal;
