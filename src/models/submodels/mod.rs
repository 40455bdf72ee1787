//! Optional physics added to a model: lumped thermal balance (contact resistance is a
//! single series term applied in each model's voltage), states appended by a wrapper
//! (series RC element, OCV hysteresis), and SEI growth, loss of active material and lithium
//! plating inside the single-particle models, and a particle-size distribution in the SPM.

pub mod augmented;
pub mod lam;
pub mod plating;
pub mod reads;
pub mod sei;
pub mod size_distribution;
pub mod thermal;

pub use augmented::Augmented;
pub use lam::{LamDrivers, LamLayer, LamModel};
pub use plating::{PlatingLayer, PlatingModel};
pub use reads::{refuse_unread, refuse_unread_overrides, unread_reason};
pub use sei::{SeiLayer, SeiModel};
pub use size_distribution::{ParticleSize, SizeClasses};
pub use thermal::LumpedThermal;

/// The states of an electrochemical model's ageing layers that only integrate a rate (the
/// SEI, the lost active material, the plated lithium): its
/// [`crate::models::Model::accumulating_states`].
pub fn accumulating_states(sei: &SeiLayer, lam: &LamLayer, plating: &PlatingLayer) -> Vec<usize> {
    sei.indices().chain(lam.indices()).chain(plating.indices()).collect()
}
