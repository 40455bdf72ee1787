//! Recorded cycler data: CSV import with column checks, and comparison of simulated voltage
//! against a recording.

mod format;
mod recording;
mod sanity;
mod segments;

pub use format::CsvFormat;
pub use recording::{Recording, VoltageError};
pub use sanity::{Finding, RecordingStats};
