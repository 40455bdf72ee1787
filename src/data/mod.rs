//! Recorded cycler data: CSV import with column checks, and comparison of simulated voltage
//! against a recording.

mod recording;

pub use recording::{Recording, VoltageError};
