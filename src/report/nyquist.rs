//! Nyquist plot of impedance spectra: `-Im Z` against `Re Z` (milliohm) on equal axes, so
//! that a semicircle looks like one and a 45-degree Warburg line has slope one.

use std::path::Path;

use plotters::prelude::*;

use crate::eis::Spectrum;
use crate::error::Error;

/// Milliohm per ohm.
const MILLI: f64 = 1e3;

/// Line colours of the model spectra (matplotlib's tab10: blue, red, green, purple, brown).
const COLOURS: [RGBColor; 5] =
    [RGBColor(31, 119, 180), RGBColor(214, 39, 40), RGBColor(44, 160, 44), RGBColor(148, 103, 189), RGBColor(140, 86, 75)];

/// Ranges `(x0..x1, y0..y1)` that hold every point, padded, and stretched so one milliohm
/// has the same length on both axes of a `width x height` pixel plotting area.
fn equal_ranges(points: &[(f64, f64)], width: f64, height: f64) -> ((f64, f64), (f64, f64)) {
    let finite = points.iter().filter(|p| p.0.is_finite() && p.1.is_finite());
    let (mut x0, mut x1, mut y0, mut y1) = (f64::INFINITY, f64::NEG_INFINITY, f64::INFINITY, f64::NEG_INFINITY);
    for &(x, y) in finite {
        x0 = x0.min(x);
        x1 = x1.max(x);
        y0 = y0.min(y);
        y1 = y1.max(y);
    }
    if !(x0 <= x1 && y0 <= y1) {
        return ((0.0, 1.0), (0.0, 1.0));
    }
    // Include the origin of -Im Z so the real-axis intercept shows.
    y0 = y0.min(0.0);
    let per_pixel = ((x1 - x0) / width).max((y1 - y0) / height).max(1e-12) * 1.1;
    let (cx, cy) = (0.5 * (x0 + x1), 0.5 * (y0 + y1));
    let (hx, hy) = (0.5 * per_pixel * width, 0.5 * per_pixel * height);
    ((cx - hx, cx + hx), (cy - hy, cy + hy))
}

/// Draws `data` as points and each `(label, spectrum)` of `models` as a line, and writes an
/// SVG file.
pub fn nyquist_plot(path: &Path, title: &str, data: Option<(&str, &Spectrum)>, models: &[(&str, &Spectrum)]) -> Result<(), Error> {
    let err = |e: String| Error::Plot { path: path.display().to_string(), message: e };
    let to_points = |s: &Spectrum| -> Vec<(f64, f64)> {
        s.z_re.iter().zip(&s.z_im).map(|(&r, &i)| (r * MILLI, -i * MILLI)).collect()
    };
    let data_points = data.map(|(label, s)| (label, to_points(s)));
    let model_points: Vec<(&str, Vec<(f64, f64)>)> = models.iter().map(|(l, s)| (*l, to_points(s))).collect();
    let all: Vec<(f64, f64)> =
        data_points.iter().flat_map(|d| d.1.iter()).chain(model_points.iter().flat_map(|m| m.1.iter())).copied().collect();

    let root = SVGBackend::new(path, (900, 700)).into_drawing_area();
    root.fill(&WHITE).map_err(|e| err(e.to_string()))?;
    let builder = || {
        let mut b = ChartBuilder::on(&root);
        b.caption(title, ("sans-serif", 24)).margin(15).x_label_area_size(45).y_label_area_size(65);
        b
    };
    // A first (undrawn) chart measures the plotting area for the equal-axis ranges.
    let (w, h) = builder().build_cartesian_2d(0.0..1.0, 0.0..1.0).map_err(|e| err(e.to_string()))?.plotting_area().dim_in_pixel();
    let ((x0, x1), (y0, y1)) = equal_ranges(&all, w as f64, h as f64);
    let mut chart = builder().build_cartesian_2d(x0..x1, y0..y1).map_err(|e| err(e.to_string()))?;
    chart
        .configure_mesh()
        .x_desc("Re Z (milliohm)")
        .y_desc("-Im Z (milliohm)")
        .draw()
        .map_err(|e| err(e.to_string()))?;
    for (k, (label, pts)) in model_points.iter().enumerate() {
        let colour = COLOURS[k % COLOURS.len()];
        chart
            .draw_series(LineSeries::new(pts.iter().copied().filter(|p| p.0.is_finite() && p.1.is_finite()), colour.stroke_width(2)))
            .map_err(|e| err(e.to_string()))?
            .label(label.to_string())
            .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], colour.stroke_width(2)));
    }
    if let Some((label, pts)) = &data_points {
        chart
            .draw_series(pts.iter().filter(|p| p.0.is_finite() && p.1.is_finite()).map(|&p| Circle::new(p, 4, BLACK.stroke_width(1))))
            .map_err(|e| err(e.to_string()))?
            .label(label.to_string())
            .legend(|(x, y)| Circle::new((x, y), 4, BLACK.stroke_width(1)));
    }
    chart
        .configure_series_labels()
        .position(SeriesLabelPosition::UpperLeft)
        .background_style(WHITE.mix(0.8))
        .border_style(BLACK)
        .draw()
        .map_err(|e| err(e.to_string()))?;
    root.present().map_err(|e| err(e.to_string()))
}

#[cfg(test)]
mod tests {
    #[test]
    fn ranges_have_equal_scale_and_hold_the_points() {
        let pts = [(30.0, 0.0), (60.0, 40.0), (45.0, 5.0)];
        let ((x0, x1), (y0, y1)) = super::equal_ranges(&pts, 800.0, 400.0);
        assert!(((x1 - x0) / 800.0 - (y1 - y0) / 400.0).abs() < 1e-12);
        assert!(pts.iter().all(|p| p.0 > x0 && p.0 < x1 && p.1 > y0 && p.1 < y1));
    }
}
