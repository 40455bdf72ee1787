//! Prior distributions of fitted parameters (model space).

use serde::{Deserialize, Serialize};

use crate::error::Error;

/// A prior density of one parameter. `Uniform` is flat inside the parameter's bounds.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "snake_case", deny_unknown_fields)]
pub enum Prior {
    /// Flat between the parameter's bounds (log-density 0 inside).
    #[default]
    Uniform,
    /// Normal with `mean` and standard deviation `sd` (parameter units).
    Gaussian { mean: f64, sd: f64 },
    /// Log-normal: `ln x` is normal with mean `mu` and standard deviation `sigma`.
    LogNormal { mu: f64, sigma: f64 },
}

const LN_SQRT_2PI: f64 = 0.918_938_533_204_672_7;

impl Prior {
    /// Checks the prior's own parameters; `field` names it in errors.
    pub fn validate(&self, field: &str) -> Result<(), Error> {
        match *self {
            Prior::Uniform => Ok(()),
            Prior::Gaussian { mean, sd } => {
                if !mean.is_finite() {
                    return Err(Error::invalid(format!("{field}.mean"), mean, "must be finite"));
                }
                if !(sd > 0.0 && sd.is_finite()) {
                    return Err(Error::invalid(format!("{field}.sd"), sd, "must be positive"));
                }
                Ok(())
            }
            Prior::LogNormal { mu, sigma } => {
                if !mu.is_finite() {
                    return Err(Error::invalid(format!("{field}.mu"), mu, "must be finite"));
                }
                if !(sigma > 0.0 && sigma.is_finite()) {
                    return Err(Error::invalid(format!("{field}.sigma"), sigma, "must be positive"));
                }
                Ok(())
            }
        }
    }

    /// Normalised log-density at `x` (the uniform prior's bounds are applied by the problem).
    pub fn log_pdf(&self, x: f64) -> f64 {
        match *self {
            Prior::Uniform => 0.0,
            Prior::Gaussian { mean, sd } => -0.5 * ((x - mean) / sd).powi(2) - sd.ln() - LN_SQRT_2PI,
            Prior::LogNormal { mu, sigma } => {
                if x <= 0.0 {
                    return f64::NEG_INFINITY;
                }
                let z = (x.ln() - mu) / sigma;
                -0.5 * z * z - sigma.ln() - LN_SQRT_2PI - x.ln()
            }
        }
    }

    /// Derivative of [`log_pdf`](Self::log_pdf) with respect to `x`.
    pub fn d_log_pdf(&self, x: f64) -> f64 {
        match *self {
            Prior::Uniform => 0.0,
            Prior::Gaussian { mean, sd } => -(x - mean) / (sd * sd),
            Prior::LogNormal { mu, sigma } => -((x.ln() - mu) / (sigma * sigma) + 1.0) / x,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Trapezoidal integral of the density over a wide grid is 1, and the derivative matches
    /// a central difference.
    #[test]
    fn densities_normalise_and_derivatives_match() {
        for (prior, a, b) in [
            (Prior::Gaussian { mean: 2.0, sd: 0.5 }, -3.0, 7.0),
            (Prior::LogNormal { mu: -1.0, sigma: 0.4 }, 1e-9, 5.0),
        ] {
            let n = 200_000;
            let h = (b - a) / n as f64;
            let mass: f64 = (0..=n)
                .map(|k| {
                    let w = if k == 0 || k == n { 0.5 } else { 1.0 };
                    w * prior.log_pdf(a + k as f64 * h).exp()
                })
                .sum::<f64>()
                * h;
            assert!((mass - 1.0).abs() < 1e-6, "{prior:?}: {mass}");
            for x in [0.3, 1.1, 2.5] {
                let fd = (prior.log_pdf(x + 1e-6) - prior.log_pdf(x - 1e-6)) / 2e-6;
                assert!((fd - prior.d_log_pdf(x)).abs() < 1e-6 * (1.0 + fd.abs()), "{prior:?} at {x}");
            }
        }
    }
}
