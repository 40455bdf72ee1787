//! Error type of the crate: every failure names what went wrong and where.

use thiserror::Error;

#[derive(Debug, Error)]
pub enum Error {
    /// A parameter is outside its physical range.
    #[error("invalid parameter `{field}` = {}: {reason}", number(*value))]
    InvalidParameter { field: String, value: f64, reason: String },
    /// A protocol step demands more than the cell can carry from the state it starts in (its
    /// current, C-rate or power, by the step's key); [`Error::demand_named`] names the setting
    /// the step was made from instead.
    #[error("invalid parameter `protocol.steps[{step}].{key}` = {}: {reason}", number(*value))]
    StepDemand { step: usize, key: &'static str, value: f64, reason: String },
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

/// A number as people write it: plain between 1e-3 and 1e6, scientific otherwise.
pub fn number(v: f64) -> String {
    if v == 0.0 || !v.is_finite() || (1e-3..1e6).contains(&v.abs()) { format!("{v}") } else { format!("{v:e}") }
}

impl Error {
    pub fn invalid(field: impl Into<String>, value: f64, reason: impl Into<String>) -> Self {
        Error::InvalidParameter { field: field.into(), value, reason: reason.into() }
    }

    /// A [`StepDemand`](Error::StepDemand) named by the setting `field` = `value` the step was
    /// made from (e.g. a study's `operating.c_rate`, the command line's `--c-rate`); any other
    /// error as it is.
    pub fn demand_named(self, field: &str, value: f64) -> Self {
        match self {
            Error::StepDemand { reason, .. } => Error::invalid(field, value, reason),
            other => other,
        }
    }

    /// For `map_err`: an I/O error on `path`, named.
    pub fn io(path: &std::path::Path) -> impl FnOnce(std::io::Error) -> Error + '_ {
        move |source| Error::Io { path: path.display().to_string(), source }
    }

    /// The error of a section checked as a whole study (a parameterisation stage that is a
    /// fit study's sections): the field it names, prefixed with `section.`.
    pub fn within(self, section: &str) -> Self {
        match self {
            Error::InvalidParameter { field, value, reason } => Error::InvalidParameter { field: format!("{section}.{field}"), value, reason },
            Error::InvalidSetting { field, reason } => Error::InvalidSetting { field: format!("{section}.{field}"), reason },
            other => other,
        }
    }

    /// For `map_err` on reading an input the user named with `field` (a study key such as
    /// `data.data1.file`, or a flag such as `--params`): a file that cannot be read becomes an
    /// error naming the field and the path, and for a relative path the working directory it
    /// was looked up in; any other error as it is.
    pub fn input(self, field: &str) -> Self {
        match self {
            Error::Io { path, source } => {
                let cwd = std::env::current_dir().map(|d| d.display().to_string()).unwrap_or_default();
                let relative = match std::path::Path::new(&path).is_relative() {
                    true => format!(" (a relative path is read from the working directory, `{cwd}`)"),
                    false => String::new(),
                };
                Error::InvalidSetting { field: field.into(), reason: format!("cannot read `{path}`: {source}{relative}") }
            }
            other => other,
        }
    }
}

/// Writes `contents` to `path`; a failure names the path.
pub fn write_file(path: &std::path::Path, contents: impl AsRef<[u8]>) -> Result<()> {
    std::fs::write(path, contents).map_err(Error::io(path))
}

pub type Result<T> = std::result::Result<T, Error>;
