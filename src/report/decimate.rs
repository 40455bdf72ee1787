//! Thinning long series for plots: a 10^6-point recording drawn point by point makes a 24 MB
//! SVG that no browser opens, yet 900 pixels show at most a few thousand distinct points.

/// Most points a plotted series keeps (a few per pixel column of a 900-pixel plot).
pub const MAX_PLOT_POINTS: usize = 4000;

/// The finite points of a series, thinned to [`MAX_PLOT_POINTS`] by largest-triangle-three-
/// buckets (the `lttb` crate: keeps the first and last point and, per bucket, the point that
/// spans the largest triangle with its neighbours, so peaks and steps survive).
pub fn for_plot(points: impl Iterator<Item = (f64, f64)>) -> Vec<(f64, f64)> {
    let finite: Vec<lttb::DataPoint> =
        points.filter(|(x, y)| x.is_finite() && y.is_finite()).map(|(x, y)| lttb::DataPoint::new(x, y)).collect();
    if finite.len() <= MAX_PLOT_POINTS {
        return finite.into_iter().map(|p| (p.x, p.y)).collect();
    }
    lttb::lttb(finite, MAX_PLOT_POINTS).into_iter().map(|p| (p.x, p.y)).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn short_series_are_kept_and_long_ones_keep_their_extremes() {
        let short: Vec<(f64, f64)> = (0..10).map(|k| (k as f64, (k * k) as f64)).collect();
        assert_eq!(for_plot(short.iter().copied().chain([(f64::NAN, 1.0)])), short);
        // A million points of a slow ramp with one spike: the spike and both ends survive.
        let n = 1_000_000;
        let long = (0..n).map(|k| (k as f64, if k == 654_321 { 5.0 } else { k as f64 * 1e-6 }));
        let thin = for_plot(long);
        assert!(thin.len() <= MAX_PLOT_POINTS, "{}", thin.len());
        assert_eq!(thin.first(), Some(&(0.0, 0.0)));
        assert_eq!(thin.last().map(|p| p.0), Some((n - 1) as f64));
        assert!(thin.contains(&(654_321.0, 5.0)));
    }
}
