//! Reports: plots (SVG via plotters) and summaries.

pub mod decimate;
pub mod fields;
pub mod nyquist;
pub mod plot;
pub mod diagnosis_files;
pub mod diagnosis_plot;
pub mod mcmc_plot;
