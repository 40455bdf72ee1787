//! The statistics layer, shared by fitting, sampling and diagnosis: descriptive statistics,
//! distribution tails (`statrs`), whiteness tests and noise levels of residuals, least-squares
//! regression, Sobol' global sensitivity indices, and convergence diagnostics of Markov chains.

pub mod convergence;
pub mod descriptive;
pub mod distributions;
pub mod noise;
pub mod regression;
pub mod sobol;
pub mod whiteness;

pub use descriptive::{autocorrelation, lag1, mean, median, quantile, rms, variance, weighted_rms};
pub use distributions::{chi2_sf, normal_quantile, normal_sf};
pub use noise::{noise_from_dense_differences, noise_from_differences};
pub use regression::least_squares;
pub use whiteness::{TestResult, ljung_box, runs_test};
