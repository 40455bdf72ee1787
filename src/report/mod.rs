//! Reports: plots (SVG via plotters) and summaries.

pub mod plot;
pub mod diagnosis_plot;
