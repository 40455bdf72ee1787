//! MCMC plots written as SVG: trace plots and marginal histograms.

use std::path::Path;

use plotters::prelude::*;

use crate::error::Error;
use crate::sample::Chain;

/// Finite range of `values`, padded by 5% (`(0, 1)` when there is none).
fn padded_range(values: impl Iterator<Item = f64>) -> (f64, f64) {
    let (lo, hi) = values.filter(|v| v.is_finite()).fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), v| (lo.min(v), hi.max(v)));
    if !(lo <= hi) {
        return (0.0, 1.0);
    }
    let pad = ((hi - lo) * 0.05).max(1e-9 * (1.0 + lo.abs()));
    (lo - pad, hi + pad)
}

fn name_of<S: AsRef<str>>(names: &[S], i: usize) -> String {
    names.get(i).map_or_else(|| format!("x{i}"), |s| s.as_ref().to_string())
}

/// Trace plot: one panel per parameter (stacked), the kept draws of each chain against the
/// iteration, one colour per chain.
pub fn trace_plot<S: AsRef<str>>(path: &Path, title: &str, names: &[S], chains: &[Chain]) -> Result<(), Error> {
    let err = |e: String| Error::Plot { path: path.display().to_string(), message: e };
    let dim = chains.first().and_then(|c| c.draws.first()).map_or(0, Vec::len);
    if dim == 0 {
        return Err(err("no draws to plot".into()));
    }
    let root = SVGBackend::new(path, (1000, (220 * dim + 60) as u32)).into_drawing_area();
    root.fill(&WHITE).map_err(|e| err(e.to_string()))?;
    let root = root.titled(title, ("sans-serif", 24)).map_err(|e| err(e.to_string()))?;
    let length = chains.iter().map(|c| c.draws.len()).max().unwrap_or(1);
    for (i, panel) in root.split_evenly((dim, 1)).iter().enumerate() {
        let (y0, y1) = padded_range(chains.iter().flat_map(|c| c.draws.iter().map(move |d| d[i])));
        let mut chart = ChartBuilder::on(panel)
            .margin(10)
            .x_label_area_size(35)
            .y_label_area_size(75)
            .build_cartesian_2d(0.0..length as f64, y0..y1)
            .map_err(|e| err(e.to_string()))?;
        chart
            .configure_mesh()
            .x_desc("iteration")
            .y_desc(name_of(names, i))
            .x_label_formatter(&|v| format!("{v:.0}"))
            .draw()
            .map_err(|e| err(e.to_string()))?;
        for (k, chain) in chains.iter().enumerate() {
            let colour = Palette99::pick(k).to_rgba();
            chart
                .draw_series(LineSeries::new(
                    super::decimate::for_plot(chain.draws.iter().enumerate().map(|(t, d)| (t as f64, d[i]))),
                    colour.mix(0.7).stroke_width(1),
                ))
                .map_err(|e| err(e.to_string()))?
                .label(format!("chain {k}"))
                .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], colour.stroke_width(2)));
        }
        if i == 0 {
            chart
                .configure_series_labels()
                .background_style(WHITE.mix(0.8))
                .border_style(BLACK)
                .draw()
                .map_err(|e| err(e.to_string()))?;
        }
    }
    root.present().map_err(|e| err(e.to_string()))
}

/// Marginal histograms of the draws pooled over chains, one panel per parameter (up to three
/// per row), normalised to a probability density, with `truth[i]` (e.g. the parameter used
/// to synthesise the data) drawn as a vertical red line.
pub fn marginal_histograms<S: AsRef<str>>(
    path: &Path,
    title: &str,
    names: &[S],
    chains: &[Chain],
    truth: Option<&[f64]>,
    bins: usize,
) -> Result<(), Error> {
    let err = |e: String| Error::Plot { path: path.display().to_string(), message: e };
    let dim = chains.first().and_then(|c| c.draws.first()).map_or(0, Vec::len);
    if dim == 0 {
        return Err(err("no draws to plot".into()));
    }
    let bins = bins.max(1);
    let cols = dim.min(3);
    let rows = dim.div_ceil(cols);
    let root = SVGBackend::new(path, ((360 * cols) as u32, (300 * rows + 50) as u32)).into_drawing_area();
    root.fill(&WHITE).map_err(|e| err(e.to_string()))?;
    let root = root.titled(title, ("sans-serif", 24)).map_err(|e| err(e.to_string()))?;
    for (i, panel) in root.split_evenly((rows, cols)).iter().enumerate().take(dim) {
        let values: Vec<f64> = chains.iter().flat_map(|c| c.draws.iter().map(|d| d[i])).filter(|v| v.is_finite()).collect();
        let mark = truth.and_then(|t| t.get(i).copied()).filter(|v| v.is_finite());
        let (x0, x1) = padded_range(values.iter().copied().chain(mark));
        let width = (x1 - x0) / bins as f64;
        let mut counts = vec![0usize; bins];
        for v in &values {
            counts[(((v - x0) / width) as usize).min(bins - 1)] += 1;
        }
        let scale = 1.0 / (values.len().max(1) as f64 * width);
        let top = counts.iter().copied().max().unwrap_or(0) as f64 * scale * 1.05;
        let mut chart = ChartBuilder::on(panel)
            .margin(10)
            .x_label_area_size(35)
            .y_label_area_size(60)
            .build_cartesian_2d(x0..x1, 0.0..top.max(f64::MIN_POSITIVE))
            .map_err(|e| err(e.to_string()))?;
        chart
            .configure_mesh()
            .x_desc(name_of(names, i))
            .y_desc("density")
            .x_labels(5)
            .draw()
            .map_err(|e| err(e.to_string()))?;
        let colour = Palette99::pick(3).to_rgba();
        chart
            .draw_series(counts.iter().enumerate().map(|(b, &c)| {
                let left = x0 + b as f64 * width;
                Rectangle::new([(left, 0.0), (left + width, c as f64 * scale)], colour.mix(0.6).filled())
            }))
            .map_err(|e| err(e.to_string()))?;
        if let Some(m) = mark {
            chart
                .draw_series(std::iter::once(PathElement::new(vec![(m, 0.0), (m, top)], RED.stroke_width(3))))
                .map_err(|e| err(e.to_string()))?;
        }
    }
    root.present().map_err(|e| err(e.to_string()))
}
