//! Distances and likelihoods between a simulated and a recorded voltage, as values to
//! minimise, with their derivatives with respect to the residuals.

use serde::{Deserialize, Serialize};

use crate::error::Error;

/// A cost of the residuals `r_i = V_model(t_i) - V_data(t_i)` (V) with weights `w_i >= 0`
/// (0 leaves a point out, e.g. a hold-out window).
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "snake_case", deny_unknown_fields)]
pub enum CostKind {
    /// Sum of squared errors `sum w r^2` (V^2).
    Sse,
    /// Root-mean-square error `sqrt(sum w r^2 / sum w)` (V).
    Rmse,
    /// Minkowski distance `(sum w |r|^p)^(1/p)` (V), `p >= 1`.
    Minkowski { p: f64 },
    /// Sum of powers `sum w |r|^p` (V^p), `p >= 1`.
    SumOfPower { p: f64 },
    /// Negative Gaussian log-likelihood with noise standard deviation `sigma` (V); when
    /// `sigma` is absent it is fitted as an extra, last parameter.
    GaussianLogLikelihood { sigma: Option<f64> },
    /// Maximum a posteriori: the negative Gaussian log-likelihood minus the log-priors of
    /// the fitted parameters.
    Map { sigma: Option<f64> },
}

impl Default for CostKind {
    fn default() -> Self {
        CostKind::Sse
    }
}

/// A cost value with its derivatives.
#[derive(Clone, Debug, PartialEq)]
pub struct CostValue {
    pub value: f64,
    /// `d cost / d r_i`.
    pub d_residual: Vec<f64>,
    /// `d cost / d sigma` when sigma is fitted, else 0.
    pub d_sigma: f64,
}

const LN_2PI: f64 = 1.837_877_066_409_345_5;

impl CostKind {
    /// The keys a `[cost]` table of this kind may hold.
    pub fn keys(&self) -> &'static [&'static str] {
        match self {
            CostKind::Sse | CostKind::Rmse => &["kind"],
            CostKind::Minkowski { .. } | CostKind::SumOfPower { .. } => &["kind", "p"],
            CostKind::GaussianLogLikelihood { .. } | CostKind::Map { .. } => &["kind", "sigma"],
        }
    }

    /// Checks the cost's settings; errors name the field.
    pub fn validate(&self) -> Result<(), Error> {
        match *self {
            CostKind::Minkowski { p } | CostKind::SumOfPower { p } if !(p >= 1.0 && p.is_finite()) => {
                Err(Error::invalid("cost.p", p, "must be at least 1"))
            }
            CostKind::GaussianLogLikelihood { sigma: Some(s) } | CostKind::Map { sigma: Some(s) }
                if !(s > 0.0 && s.is_finite()) =>
            {
                Err(Error::invalid("cost.sigma", s, "must be positive"))
            }
            _ => Ok(()),
        }
    }

    /// Whether the noise level is fitted as an extra parameter.
    pub fn fits_sigma(&self) -> bool {
        matches!(self, CostKind::GaussianLogLikelihood { sigma: None } | CostKind::Map { sigma: None })
    }

    /// Whether the log-priors of the parameters enter the cost.
    pub fn uses_priors(&self) -> bool {
        matches!(self, CostKind::Map { .. })
    }

    /// Short name for reports.
    pub fn name(&self) -> String {
        match self {
            CostKind::Sse => "sum of squared errors".into(),
            CostKind::Rmse => "RMSE".into(),
            CostKind::Minkowski { p } => format!("Minkowski (p = {p})"),
            CostKind::SumOfPower { p } => format!("sum of power (p = {p})"),
            CostKind::GaussianLogLikelihood { sigma: Some(s) } => format!("Gaussian NLL (sigma = {s} V)"),
            CostKind::GaussianLogLikelihood { sigma: None } => "Gaussian NLL (sigma fitted)".into(),
            CostKind::Map { .. } => "MAP (Gaussian NLL - log prior)".into(),
        }
    }

    /// The cost of residuals `r` with weights `w`; `sigma` is the fitted noise level when
    /// [`fits_sigma`](Self::fits_sigma), ignored otherwise. Priors are added by the problem.
    pub fn evaluate(&self, r: &[f64], w: &[f64], sigma: Option<f64>) -> CostValue {
        let weight: f64 = w.iter().sum();
        let sse: f64 = r.iter().zip(w).map(|(r, w)| w * r * r).sum();
        let powers = |p: f64| -> (f64, Vec<f64>) {
            let sum = r.iter().zip(w).map(|(r, w)| w * r.abs().powf(p)).sum();
            let d = r.iter().zip(w).map(|(r, w)| w * p * r.abs().powf(p - 1.0) * r.signum()).collect();
            (sum, d)
        };
        let scaled = |factor: f64| r.iter().zip(w).map(|(r, w)| factor * w * r).collect::<Vec<_>>();
        match *self {
            CostKind::Sse => CostValue { value: sse, d_residual: scaled(2.0), d_sigma: 0.0 },
            CostKind::Rmse => {
                let rmse = (sse / weight).sqrt();
                let f = if rmse > 0.0 { 1.0 / (weight * rmse) } else { 0.0 };
                CostValue { value: rmse, d_residual: scaled(f), d_sigma: 0.0 }
            }
            CostKind::SumOfPower { p } => {
                let (value, d_residual) = powers(p);
                CostValue { value, d_residual, d_sigma: 0.0 }
            }
            CostKind::Minkowski { p } => {
                let (sum, d) = powers(p);
                let value = sum.powf(1.0 / p);
                let f = if sum > 0.0 { value / (p * sum) } else { 0.0 };
                CostValue { value, d_residual: d.iter().map(|v| f * v).collect(), d_sigma: 0.0 }
            }
            CostKind::GaussianLogLikelihood { sigma: fixed } | CostKind::Map { sigma: fixed } => {
                let s = fixed.or(sigma).unwrap_or(f64::NAN);
                let value = 0.5 * weight * (LN_2PI + 2.0 * s.ln()) + sse / (2.0 * s * s);
                let d_sigma = if fixed.is_none() { weight / s - sse / (s * s * s) } else { 0.0 };
                CostValue { value, d_residual: scaled(1.0 / (s * s)), d_sigma }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every cost's residual and sigma derivatives match central differences.
    #[test]
    fn derivatives_match_finite_differences() {
        let r = [0.003, -0.001, 0.0025, -0.004];
        let w = [1.0, 0.5, 1.0, 2.0];
        let sigma = Some(0.002);
        for cost in [
            CostKind::Sse,
            CostKind::Rmse,
            CostKind::Minkowski { p: 3.0 },
            CostKind::SumOfPower { p: 1.5 },
            CostKind::GaussianLogLikelihood { sigma: None },
            CostKind::Map { sigma: Some(0.001) },
        ] {
            let c = cost.evaluate(&r, &w, sigma);
            for i in 0..r.len() {
                let h = 1e-7;
                let (mut rp, mut rm) = (r, r);
                rp[i] += h;
                rm[i] -= h;
                let fd = (cost.evaluate(&rp, &w, sigma).value - cost.evaluate(&rm, &w, sigma).value) / (2.0 * h);
                assert!((fd - c.d_residual[i]).abs() < 1e-5 * (1.0 + fd.abs()), "{cost:?} r[{i}]: {fd} vs {}", c.d_residual[i]);
            }
            if cost.fits_sigma() {
                let h = 1e-9;
                let fd = (cost.evaluate(&r, &w, Some(0.002 + h)).value - cost.evaluate(&r, &w, Some(0.002 - h)).value) / (2.0 * h);
                assert!((fd - c.d_sigma).abs() < 1e-5 * fd.abs(), "{cost:?} sigma: {fd} vs {}", c.d_sigma);
            }
        }
    }

    /// The Gaussian likelihood is minimised over sigma at the RMS residual.
    #[test]
    fn fitted_sigma_optimum_is_the_rms_residual() {
        let r = [0.003, -0.001, 0.0025, -0.004];
        let w = [1.0; 4];
        let rms = (r.iter().map(|v| v * v).sum::<f64>() / 4.0).sqrt();
        let cost = CostKind::GaussianLogLikelihood { sigma: None };
        assert!(cost.evaluate(&r, &w, Some(rms)).d_sigma.abs() < 1e-9);
        assert!(CostKind::Minkowski { p: 0.5 }.validate().unwrap_err().to_string().contains("cost.p"));
    }
}
