//! Recorded cycler data: CSV import with column checks, raw cycler exports ([`cycler`]), and
//! comparison of simulated voltage against a recording.

pub mod cycler;
mod current_noise;
mod fade;
mod format;
mod pseudo_ocv;
mod pulses;
mod recording;
mod sanity;
mod segments;

pub use fade::CapacityFade;
pub use format::CsvFormat;
pub use pseudo_ocv::{OcvBranch, PseudoOcv};
pub use pulses::{Pulse, pulses};
pub use recording::{Recording, VoltageError};
pub use sanity::{Finding, RecordingStats};
