//! Plots of a model-discrepancy diagnosis: voltage before/after, residual before/after with
//! the mismatching segments and the held-out blocks shaded.

use std::path::{Path, PathBuf};

use plotters::prelude::*;

use crate::diagnose::Diagnosis;
use crate::error::Error;

/// Time ranges `[start, end]` (s) of consecutive `true` entries of `mask`.
fn spans(time: &[f64], mask: &[bool]) -> Vec<(f64, f64)> {
    let mut out: Vec<(f64, f64)> = Vec::new();
    let mut open: Option<f64> = None;
    for (k, &m) in mask.iter().enumerate() {
        match (m, open) {
            (true, None) => open = Some(time[k]),
            (false, Some(s)) => {
                out.push((s, time[k - 1]));
                open = None;
            }
            _ => {}
        }
    }
    if let Some(s) = open {
        out.push((s, time[time.len() - 1]));
    }
    out
}

/// Shaded time spans drawn under a chart's lines.
struct Shading {
    label: String,
    spans: Vec<(f64, f64)>,
    colour: RGBColor,
    alpha: f64,
}

/// Lines over time on one set of axes with shaded spans underneath.
fn shaded_plot(path: &Path, title: &str, y_label: &str, series: &[(String, Vec<(f64, f64)>)], shading: &[Shading]) -> Result<(), Error> {
    let err = |e: String| Error::Plot { path: path.display().to_string(), message: e };
    let root = SVGBackend::new(path, (1100, 600)).into_drawing_area();
    root.fill(&WHITE).map_err(|e| err(e.to_string()))?;
    let pts = || series.iter().flat_map(|s| s.1.iter()).filter(|p| p.0.is_finite() && p.1.is_finite());
    let (x0, x1) = pts().fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), p| (a.min(p.0), b.max(p.0)));
    let (y0, y1) = pts().fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), p| (a.min(p.1), b.max(p.1)));
    if !(x0 < x1) || !(y0 <= y1) {
        return Err(err("nothing to plot".into()));
    }
    let pad = ((y1 - y0) * 0.05).max(1e-6);
    let (y0, y1) = (y0 - pad, y1 + pad);
    let mut chart = ChartBuilder::on(&root)
        .caption(title, ("sans-serif", 22))
        .margin(15)
        .x_label_area_size(45)
        .y_label_area_size(70)
        .build_cartesian_2d(x0..x1, y0..y1)
        .map_err(|e| err(e.to_string()))?;
    chart.configure_mesh().x_desc("Time (s)").y_desc(y_label).draw().map_err(|e| err(e.to_string()))?;
    for sh in shading {
        let style = sh.colour.mix(sh.alpha).filled();
        let legend_style = style;
        chart
            .draw_series(sh.spans.iter().map(|&(a, b)| Rectangle::new([(a, y0), (b.max(a + (x1 - x0) * 1e-3), y1)], style)))
            .map_err(|e| err(e.to_string()))?
            .label(sh.label.clone())
            .legend(move |(x, y)| Rectangle::new([(x, y - 5), (x + 20, y + 5)], legend_style));
    }
    for (k, (label, p)) in series.iter().enumerate() {
        let colour = Palette99::pick(k).to_rgba();
        chart
            .draw_series(LineSeries::new(super::decimate::for_plot(p.iter().copied()), colour.stroke_width(2)))
            .map_err(|e| err(e.to_string()))?
            .label(label.clone())
            .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], colour.stroke_width(2)));
    }
    chart.configure_series_labels().background_style(WHITE.mix(0.8)).border_style(BLACK).draw().map_err(|e| err(e.to_string()))?;
    root.present().map_err(|e| err(e.to_string()))
}

/// Writes `{stem}_voltage.svg` and `{stem}_residual.svg` into `dir`; returns (title, path)
/// pairs.
pub fn write_plots(d: &Diagnosis, dir: &Path, stem: &str) -> Result<Vec<(String, PathBuf)>, Error> {
    let rec = &d.data;
    let valid: Vec<usize> = (0..rec.time.len()).filter(|&k| !rec.is_repeated(k)).collect();
    let curve = |v: &[f64]| valid.iter().map(|&k| (rec.time[k], v[k])).collect::<Vec<_>>();
    let residual = |v: &[f64]| valid.iter().map(|&k| (rec.time[k], 1e3 * (v[k] - rec.voltage[k]))).collect::<Vec<_>>();
    let best = d.best().and_then(|c| c.fit.as_ref().map(|f| (c.name.clone(), f)));
    let holdout = Shading { label: "held out".into(), spans: spans(&rec.time, &d.split.holdout), colour: RGBColor(120, 120, 120), alpha: 0.12 };
    let mismatch = Shading {
        label: "mismatching segments".into(),
        spans: d.residual.segments.iter().map(|s| (s.start, s.end)).collect(),
        colour: RGBColor(220, 40, 40),
        alpha: 0.22,
    };
    let mut out = Vec::new();
    let mut volts = vec![("recorded".to_string(), curve(&rec.voltage)), (format!("{} as given", d.model), curve(&d.baseline.voltage))];
    if let Some((name, f)) = &best {
        volts.push((format!("with {name}"), curve(&f.voltage)));
    }
    let path = dir.join(format!("{stem}_voltage.svg"));
    shaded_plot(&path, "Terminal voltage: recording and models", "Voltage (V)", &volts, &[holdout])?;
    out.push(("Voltage before and after".to_string(), path));
    let holdout = Shading { label: "held out".into(), spans: spans(&rec.time, &d.split.holdout), colour: RGBColor(120, 120, 120), alpha: 0.12 };
    let mut res = vec![(format!("{} as given", d.model), residual(&d.baseline.voltage))];
    if let Some((name, f)) = &best {
        res.push((format!("with {name}"), residual(&f.voltage)));
    }
    let path = dir.join(format!("{stem}_residual.svg"));
    shaded_plot(&path, "Residual V_model - V_data (mismatching segments shaded)", "Residual (mV)", &res, &[holdout, mismatch])?;
    out.push(("Residual before and after, mismatching segments".to_string(), path));
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::spans;

    #[test]
    fn spans_of_a_mask() {
        let t = [0.0, 1.0, 2.0, 3.0, 4.0];
        assert_eq!(spans(&t, &[false, true, true, false, true]), vec![(1.0, 2.0), (4.0, 4.0)]);
    }
}
