//! Optional physics added to a model: lumped thermal balance (contact resistance is a
//! single series term applied in each model's voltage).

pub mod thermal;

pub use thermal::LumpedThermal;
