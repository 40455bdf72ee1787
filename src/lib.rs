//! cellstudio: battery design optimisation and parameterisation.
//!
//! The pipeline is model -> problem -> cost -> optimiser/sampler, fed by parameter sets and
//! protocols, reported by plots.

pub mod cost;
pub mod data;
pub mod diagnose;
pub mod eis;
pub mod error;
pub mod geometry;
pub mod linalg;
pub mod models;
pub mod optim;
pub mod output;
pub mod params;
pub mod problem;
pub mod progress;
pub mod protocol;
pub mod report;
pub mod sample;
pub mod simulation;
pub mod solver;
pub mod stats;
pub mod study;

pub use error::{Error, Result};
