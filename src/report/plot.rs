//! Line plots written as SVG.

use std::path::Path;

use plotters::prelude::*;

use super::decimate::for_plot;
use crate::error::Error;

/// One named series of a line plot.
pub struct Series<'a> {
    pub label: String,
    pub x: &'a [f64],
    pub y: &'a [f64],
}

fn bounds<'a>(values: impl Iterator<Item = &'a f64>) -> (f64, f64) {
    let (lo, hi) = values
        .filter(|v| v.is_finite())
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), &v| (lo.min(v), hi.max(v)));
    if !(lo <= hi) {
        return (0.0, 1.0);
    }
    let pad = ((hi - lo) * 0.05).max(1e-9);
    (lo - pad, hi + pad)
}

/// Draws `series` as lines on one set of axes and writes an SVG file.
pub fn line_plot(path: &Path, title: &str, x_label: &str, y_label: &str, series: &[Series]) -> Result<(), Error> {
    let err = |e: String| Error::Plot { path: path.display().to_string(), message: e };
    let root = SVGBackend::new(path, (900, 600)).into_drawing_area();
    root.fill(&WHITE).map_err(|e| err(e.to_string()))?;
    let (x0, x1) = bounds(series.iter().flat_map(|s| s.x.iter()));
    let (y0, y1) = bounds(series.iter().flat_map(|s| s.y.iter()));
    let mut chart = ChartBuilder::on(&root)
        .caption(title, ("sans-serif", 24))
        .margin(15)
        .x_label_area_size(45)
        .y_label_area_size(65)
        .build_cartesian_2d(x0..x1, y0..y1)
        .map_err(|e| err(e.to_string()))?;
    chart
        .configure_mesh()
        .x_desc(x_label)
        .y_desc(y_label)
        .draw()
        .map_err(|e| err(e.to_string()))?;
    for (k, s) in series.iter().enumerate() {
        let colour = Palette99::pick(k).to_rgba();
        chart
            .draw_series(LineSeries::new(for_plot(s.x.iter().copied().zip(s.y.iter().copied())), colour.stroke_width(2)))
            .map_err(|e| err(e.to_string()))?
            .label(s.label.clone())
            .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], colour.stroke_width(2)));
    }
    chart
        .configure_series_labels()
        .background_style(WHITE.mix(0.8))
        .border_style(BLACK)
        .draw()
        .map_err(|e| err(e.to_string()))?;
    root.present().map_err(|e| err(e.to_string()))
}

/// What a heat map draws over its cells: the points `marks` (the first, e.g. the baseline, as
/// a red cross; the others, e.g. the best design, as black rings), an optional `trace` (e.g. an
/// optimiser's path) as a white line with dots, and `boundaries` (e.g. linear constraints) as
/// black segments from one end to the other.
#[derive(Default)]
pub struct Overlay<'a> {
    pub marks: &'a [(String, (f64, f64))],
    pub trace: &'a [(f64, f64)],
    pub boundaries: &'a [((f64, f64), (f64, f64))],
}

/// A heat map of `z[i][j]` over the grid `x[i]`, `y[j]` (NaN cells are left blank) with a
/// colour bar and `overlay` drawn over it.
pub fn heat_map(path: &Path, title: &str, labels: (&str, &str), x: &[f64], y: &[f64], z: &[Vec<f64>], overlay: &Overlay) -> Result<(), Error> {
    let Overlay { marks, trace, boundaries } = *overlay;
    let err = |e: String| Error::Plot { path: path.display().to_string(), message: e };
    let root = SVGBackend::new(path, (1000, 700)).into_drawing_area();
    root.fill(&WHITE).map_err(|e| err(e.to_string()))?;
    let (root, bar) = root.split_horizontally(860);
    let half = |v: &[f64]| if v.len() > 1 { 0.5 * (v[1] - v[0]) } else { 0.5 };
    let (hx, hy) = (half(x), half(y));
    let (zmin, zmax) = bounds(z.iter().flatten());
    colour_bar(&bar, zmin, zmax, title).map_err(|e| err(e.to_string()))?;
    let mut chart = ChartBuilder::on(&root)
        .caption(title, ("sans-serif", 22))
        .margin(15)
        .x_label_area_size(45)
        .y_label_area_size(70)
        .build_cartesian_2d((x[0] - hx)..(x[x.len() - 1] + hx), (y[0] - hy)..(y[y.len() - 1] + hy))
        .map_err(|e| err(e.to_string()))?;
    chart.configure_mesh().x_desc(labels.0).y_desc(labels.1).draw().map_err(|e| err(e.to_string()))?;
    let cells = x.iter().enumerate().flat_map(|(i, &xi)| {
        y.iter().enumerate().filter_map(move |(j, &yj)| {
            let v = z[i][j];
            v.is_finite().then(|| {
                let t = (v - zmin) / (zmax - zmin);
                let colour = ViridisRGB::get_color(t);
                Rectangle::new([(xi - hx, yj - hy), (xi + hx, yj + hy)], colour.filled())
            })
        })
    });
    chart.draw_series(cells).map_err(|e| err(e.to_string()))?;
    if !trace.is_empty() {
        chart
            .draw_series(LineSeries::new(trace.iter().copied(), WHITE.stroke_width(2)))
            .map_err(|e| err(e.to_string()))?
            .label("optimiser trace")
            .legend(|(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], BLACK.stroke_width(2)));
        chart
            .draw_series(trace.iter().map(|&p| Circle::new(p, 3, WHITE.filled())))
            .map_err(|e| err(e.to_string()))?;
    }
    for (k, &(a, b)) in boundaries.iter().enumerate() {
        let drawn = chart.draw_series(LineSeries::new([a, b], BLACK.stroke_width(2))).map_err(|e| err(e.to_string()))?;
        if k == 0 {
            drawn.label("constraint boundary").legend(|(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], BLACK.stroke_width(2)));
        }
    }
    let legend = !marks.is_empty() || !trace.is_empty() || !boundaries.is_empty();
    let corner = legend_corner(&[], &marks.iter().map(|m| m.1).collect::<Vec<_>>(), (x[0] - hx, x[x.len() - 1] + hx), (y[0] - hy, y[y.len() - 1] + hy));
    for (k, (label, p)) in marks.iter().enumerate() {
        if k == 0 {
            chart
                .draw_series(std::iter::once(Cross::new(*p, 8, RED.stroke_width(3))))
                .map_err(|e| err(e.to_string()))?
                .label(label.clone())
                .legend(|(x, y)| Cross::new((x, y), 6, RED.stroke_width(2)));
        } else {
            chart
                .draw_series(std::iter::once(Circle::new(*p, 8, BLACK.stroke_width(3))))
                .map_err(|e| err(e.to_string()))?
                .label(label.clone())
                .legend(|(x, y)| Circle::new((x, y), 5, BLACK.stroke_width(2)));
        }
    }
    if legend {
        chart.configure_series_labels().position(corner).background_style(WHITE.mix(0.8)).border_style(BLACK).draw().map_err(|e| err(e.to_string()))?;
    }
    root.present().map_err(|e| err(e.to_string()))
}

/// A vertical viridis colour bar from `zmin` to `zmax` with ticks, labelled `label`.
fn colour_bar<DB: DrawingBackend>(area: &DrawingArea<DB, plotters::coord::Shift>, zmin: f64, zmax: f64, label: &str) -> Result<(), DrawingAreaErrorKind<DB::ErrorType>> {
    let mut bar = ChartBuilder::on(area).margin_top(45).margin_bottom(60).margin_right(10).y_label_area_size(90).build_cartesian_2d(0.0..1.0, zmin..zmax)?;
    bar.configure_mesh().disable_x_mesh().disable_y_mesh().disable_x_axis().y_desc(label).label_style(("sans-serif", 14)).axis_desc_style(("sans-serif", 16)).y_label_formatter(&|v| format!("{v:.1}")).draw()?;
    let n = 100;
    bar.draw_series((0..n).map(|k| {
        let (a, b) = (zmin + (zmax - zmin) * k as f64 / n as f64, zmin + (zmax - zmin) * (k + 1) as f64 / n as f64);
        Rectangle::new([(0.0, a), (1.0, b)], ViridisRGB::get_color((k as f64 + 0.5) / n as f64).filled())
    }))?;
    Ok(())
}

/// The corner for a legend: the one with the fewest points (and none of the marks) nearby.
fn legend_corner(points: &[(f64, f64)], marks: &[(f64, f64)], (x0, x1): (f64, f64), (y0, y1): (f64, f64)) -> SeriesLabelPosition {
    let corners = [
        (SeriesLabelPosition::UpperRight, 1.0, 1.0),
        (SeriesLabelPosition::UpperLeft, 0.0, 1.0),
        (SeriesLabelPosition::LowerRight, 1.0, 0.0),
        (SeriesLabelPosition::LowerLeft, 0.0, 0.0),
    ];
    let near = |(u, v): (f64, f64), (cx, cy): (f64, f64)| {
        let (u, v) = ((u - x0) / (x1 - x0), (v - y0) / (y1 - y0));
        (u - cx).abs() < 0.35 && (v - cy).abs() < 0.3
    };
    let cost = |c: (f64, f64)| points.iter().filter(|&&p| near(p, c)).count() + 1_000_000 * marks.iter().filter(|&&m| near(m, c)).count();
    corners.iter().min_by_key(|(_, cx, cy)| cost((*cx, *cy))).map_or(SeriesLabelPosition::UpperRight, |c| c.0.clone())
}

/// A scatter plot of named point sets, with an optional marked point (e.g. the baseline).
pub fn scatter_plot(
    path: &Path,
    title: &str,
    labels: (&str, &str),
    sets: &[(String, Vec<(f64, f64)>)],
    mark: Option<(String, (f64, f64))>,
) -> Result<(), Error> {
    let err = |e: String| Error::Plot { path: path.display().to_string(), message: e };
    let root = SVGBackend::new(path, (900, 650)).into_drawing_area();
    root.fill(&WHITE).map_err(|e| err(e.to_string()))?;
    let mark_point = mark.as_ref().map(|m| m.1);
    let all = || sets.iter().flat_map(|s| s.1.iter()).chain(mark.iter().map(|m| &m.1));
    let (x0, x1) = bounds(all().map(|p| &p.0));
    let (y0, y1) = bounds(all().map(|p| &p.1));
    let mut chart = ChartBuilder::on(&root)
        .caption(title, ("sans-serif", 22))
        .margin(15)
        .x_label_area_size(45)
        .y_label_area_size(70)
        .build_cartesian_2d(x0..x1, y0..y1)
        .map_err(|e| err(e.to_string()))?;
    chart.configure_mesh().x_desc(labels.0).y_desc(labels.1).draw().map_err(|e| err(e.to_string()))?;
    for (k, (label, pts)) in sets.iter().enumerate() {
        let colour = Palette99::pick(k).to_rgba();
        let size = if k == sets.len() - 1 { 5 } else { 3 };
        chart
            .draw_series(pts.iter().filter(|p| p.0.is_finite() && p.1.is_finite()).map(|&p| Circle::new(p, size, colour.filled())))
            .map_err(|e| err(e.to_string()))?
            .label(label.clone())
            .legend(move |(x, y)| Circle::new((x, y), 4, colour.filled()));
    }
    if let Some((label, p)) = mark {
        chart
            .draw_series(std::iter::once(Cross::new(p, 9, BLACK.stroke_width(3))))
            .map_err(|e| err(e.to_string()))?
            .label(label)
            .legend(|(x, y)| Cross::new((x, y), 6, BLACK.stroke_width(2)));
    }
    let finite: Vec<(f64, f64)> = sets.iter().flat_map(|s| s.1.iter().copied()).filter(|p| p.0.is_finite() && p.1.is_finite()).collect();
    let corner = legend_corner(&finite, mark_point.as_slice(), (x0, x1), (y0, y1));
    chart.configure_series_labels().position(corner).background_style(WHITE.mix(0.8)).border_style(BLACK).draw().map_err(|e| err(e.to_string()))?;
    root.present().map_err(|e| err(e.to_string()))
}
