//! Distribution tails and quantiles (`statrs`): the standard normal and the chi-square.

use statrs::distribution::{ChiSquared, ContinuousCDF, Normal};

fn standard_normal() -> Normal {
    Normal::standard()
}

/// Upper tail `P(Z > z)` of the standard normal distribution.
pub fn normal_sf(z: f64) -> f64 {
    standard_normal().sf(z)
}

/// Inverse of the standard normal distribution function, `Φ⁻¹(p)` for `p` in (0, 1).
pub fn normal_quantile(p: f64) -> f64 {
    standard_normal().inverse_cdf(p)
}

/// Upper tail `P(X > x)` of the chi-square distribution with `dof > 0` degrees of freedom
/// (1 for `x <= 0`; NaN for a NaN `x` or a non-positive `dof`).
pub fn chi2_sf(x: f64, dof: f64) -> f64 {
    if x.is_nan() {
        return f64::NAN;
    }
    if x <= 0.0 {
        return 1.0;
    }
    ChiSquared::new(dof).map_or(f64::NAN, |d| d.sf(x))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Tail values and quantiles against printed tables (Abramowitz & Stegun 26.2, 26.4).
    #[test]
    fn tails_and_quantiles_match_tables() {
        assert!((normal_sf(1.959_964) - 0.025).abs() < 1e-7);
        assert!((normal_sf(-1.0) - 0.841_344_746).abs() < 1e-9);
        for (x, dof, p) in [(3.841_459, 1.0, 0.05), (18.307_04, 10.0, 0.05), (37.566_23, 20.0, 0.01), (0.114_832, 3.0, 0.99)] {
            assert!((chi2_sf(x, dof) - p).abs() < 1e-6, "chi2({x}, {dof}) = {} vs {p}", chi2_sf(x, dof));
        }
        for (p, z) in [(0.5, 0.0), (0.975, 1.959_963_984_540_054), (0.001, -3.090_232_306_167_813_5), (0.9999, 3.719_016_485_455_709)] {
            assert!((normal_quantile(p) - z).abs() < 1e-12 * (1.0 + z.abs()), "{p}: {}", normal_quantile(p));
        }
        assert_eq!(chi2_sf(0.0, 3.0), 1.0);
        assert!(chi2_sf(f64::NAN, 3.0).is_nan());
    }
}
