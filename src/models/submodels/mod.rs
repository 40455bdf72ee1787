//! Optional physics added to a model: lumped thermal balance (contact resistance is a
//! single series term applied in each model's voltage), and states appended by a wrapper
//! (series RC element, OCV hysteresis).

pub mod augmented;
pub mod thermal;

pub use augmented::Augmented;
pub use thermal::LumpedThermal;
