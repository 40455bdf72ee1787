//! Error type of the crate: every failure names what went wrong and where.

use thiserror::Error;

#[derive(Debug, Error)]
pub enum Error {
    /// A parameter is outside its physical range.
    #[error("invalid parameter `{field}` = {value}: {reason}")]
    InvalidParameter { field: String, value: f64, reason: String },
    /// A configuration value (not a number) is not acceptable.
    #[error("invalid setting `{field}`: {reason}")]
    InvalidSetting { field: String, reason: String },
    /// The time integrator could not continue.
    #[error("solver failed at t = {t:.6} s: {reason}")]
    Solver { t: f64, reason: String },
    /// A sparse factorisation failed (singular or out of memory).
    #[error("linear solver: {0}")]
    Linear(String),
    /// A file could not be read or written.
    #[error("{path}: {source}")]
    Io { path: String, source: std::io::Error },
    /// A file's contents could not be parsed.
    #[error("{path}: {message}")]
    Parse { path: String, message: String },
    /// A plot could not be drawn.
    #[error("plot {path}: {message}")]
    Plot { path: String, message: String },
}

impl Error {
    pub fn invalid(field: impl Into<String>, value: f64, reason: impl Into<String>) -> Self {
        Error::InvalidParameter { field: field.into(), value, reason: reason.into() }
    }
}

pub type Result<T> = std::result::Result<T, Error>;
