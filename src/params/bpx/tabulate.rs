//! Tabulation: functions of one variable sampled into `{x, y}` tables, finely enough that
//! linear interpolation stays within a tolerance. Import uses it for expressions, export for
//! our built-in functions.

/// Concentration range (mol/m^3) over which electrolyte functions are tabulated.
pub(super) const ELECTROLYTE_RANGE: (f64, f64) = (0.0, 4000.0);
/// Absolute tolerance (V) of a tabulated OCP.
pub(super) const OCP_TOLERANCE: f64 = 1e-5;
/// Absolute tolerance (V/K) of a tabulated entropic change: the OCP it shifts 100 K from its
/// reference temperature stays within [`OCP_TOLERANCE`].
pub(super) const ENTROPIC_TOLERANCE: f64 = OCP_TOLERANCE / 100.0;
/// Tolerance of a tabulated electrolyte property, relative to its largest value.
pub(super) const ELECTROLYTE_TOLERANCE: f64 = 1e-4;

/// How closely a table must follow its function.
#[derive(Clone, Copy)]
pub(super) enum Tolerance {
    /// Absolute interpolation error.
    Absolute(f64),
    /// Interpolation error relative to the value, floored at 1e-3 of the largest |value|.
    Relative(f64),
}

/// Samples `f` over `range`: 101 uniform points, each interval bisected (up to 12 times)
/// until linear interpolation is within the tolerance at its quarter and mid points.
/// Non-finite values are left out.
pub(super) fn sample(f: &dyn Fn(f64) -> f64, range: (f64, f64), tolerance: Tolerance) -> (Vec<f64>, Vec<f64>) {
    let n = 101;
    let (a, b) = range;
    let coarse: Vec<(f64, f64)> = (0..n)
        .map(|i| if i == n - 1 { b } else { a + (b - a) * i as f64 / (n - 1) as f64 })
        .map(|x| (x, f(x)))
        .filter(|(_, y)| y.is_finite())
        .collect();
    // Allowed error: abs + rel |value|.
    let tol = match tolerance {
        Tolerance::Absolute(t) => (t, 0.0),
        Tolerance::Relative(r) => (r * 1e-3 * coarse.iter().map(|p| p.1.abs()).fold(0.0, f64::max), r),
    };
    let mut out: Vec<(f64, f64)> = Vec::new();
    if let Some(first) = coarse.first() {
        out.push(*first);
    }
    for w in coarse.windows(2) {
        refine(f, w[0], w[1], 12, tol, &mut out);
        out.push(w[1]);
    }
    out.into_iter().unzip()
}

fn refine(
    f: &dyn Fn(f64) -> f64,
    p0: (f64, f64),
    p1: (f64, f64),
    depth: u32,
    tol: (f64, f64),
    out: &mut Vec<(f64, f64)>,
) {
    if depth == 0 {
        return;
    }
    let at = |w: f64| {
        let x = p0.0 + w * (p1.0 - p0.0);
        (x, f(x), p0.1 + w * (p1.1 - p0.1))
    };
    let probes = [at(0.25), at(0.5), at(0.75)];
    if probes.iter().any(|p| !p.1.is_finite()) {
        return;
    }
    if probes.iter().all(|p| (p.1 - p.2).abs() <= tol.0 + tol.1 * p.1.abs()) {
        return;
    }
    let mid = (probes[1].0, probes[1].1);
    refine(f, p0, mid, depth - 1, tol, out);
    out.push(mid);
    refine(f, mid, p1, depth - 1, tol, out);
}
