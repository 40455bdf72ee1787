//! A correction to the open-circuit voltage as a function of the charge passed: what a cell
//! whose electrode OCP curves differ from the set's needs on top of the set's OCV.
//!
//! The correction `ΔV(q)` (V) is piecewise linear in the charge `q` (A h, discharge
//! positive) passed since the start of the simulation, through `voltage[k]` at `charge[k]`,
//! and flat beyond the first and last points. It is used when the OCV-correction submodel is
//! on; its values are addressed as `cell.ocv_correction.K` (the `K`-th voltage, from 0).

use serde::{Deserialize, Serialize};

use crate::error::Error;

/// Piecewise-linear OCV correction `ΔV(q)`.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct OcvCorrection {
    /// Charge passed since the start (A h, discharge positive), strictly increasing.
    pub charge: Vec<f64>,
    /// Correction (V) at each point of `charge`.
    pub voltage: Vec<f64>,
}

impl OcvCorrection {
    /// `n` points evenly spread over `[low, high]` (A h), every correction zero.
    pub fn zero_over(low: f64, high: f64, n: usize) -> Self {
        let n = n.max(2);
        let charge = (0..n).map(|k| low + (high - low) * k as f64 / (n - 1) as f64).collect();
        Self { charge, voltage: vec![0.0; n] }
    }

    pub fn is_empty(&self) -> bool {
        self.charge.is_empty()
    }

    /// The correction (V) after `q` (A h) passed; zero when there are no points.
    pub fn at(&self, q: f64) -> f64 {
        match self.charge.as_slice() {
            [] => 0.0,
            [_] => self.voltage[0],
            xs if q <= xs[0] => self.voltage[0],
            xs if q >= xs[xs.len() - 1] => self.voltage[xs.len() - 1],
            xs => super::function::interpolate(xs, &self.voltage, q),
        }
    }

    /// The `k`-th correction voltage, for a parameter path `cell.ocv_correction.K`.
    pub fn voltage_mut(&mut self, k: &str) -> Option<&mut f64> {
        self.voltage.get_mut(k.parse::<usize>().ok()?)
    }

    /// Checks the points; errors name `cell.ocv_correction`.
    pub fn validate(&self) -> Result<(), Error> {
        let field = "cell.ocv_correction";
        if self.charge.len() != self.voltage.len() || self.charge.len() == 1 {
            return Err(Error::InvalidSetting {
                field: field.into(),
                reason: format!("needs no points or at least 2, as many charges as voltages (charge: {}, voltage: {})", self.charge.len(), self.voltage.len()),
            });
        }
        if let Some(v) = self.charge.iter().chain(&self.voltage).find(|v| !v.is_finite()) {
            return Err(Error::invalid(&format!("{field}.charge/voltage"), *v, "must be finite"));
        }
        if let Some(w) = self.charge.windows(2).find(|w| w[1] <= w[0]) {
            return Err(Error::invalid(&format!("{field}.charge"), w[1], "must be strictly increasing (A h)"));
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::OcvCorrection;

    #[test]
    fn the_correction_interpolates_and_is_flat_outside_its_points() {
        let mut c = OcvCorrection::zero_over(0.0, 2.0, 3);
        assert_eq!(c.charge, vec![0.0, 1.0, 2.0]);
        *c.voltage_mut("1").unwrap() = 0.01;
        *c.voltage_mut("2").unwrap() = -0.02;
        assert!((c.at(0.5) - 0.005).abs() < 1e-15);
        assert!((c.at(1.5) + 0.005).abs() < 1e-15);
        assert_eq!((c.at(-1.0), c.at(5.0)), (0.0, -0.02));
        assert!(c.voltage_mut("3").is_none() && c.voltage_mut("x").is_none());
        assert_eq!(OcvCorrection::default().at(1.0), 0.0);
    }

    #[test]
    fn bad_points_are_refused_with_the_field() {
        let c = OcvCorrection { charge: vec![0.0, 0.0], voltage: vec![0.0, 0.0] };
        assert!(c.validate().unwrap_err().to_string().contains("cell.ocv_correction.charge"));
        let c = OcvCorrection { charge: vec![0.0, 1.0], voltage: vec![0.0] };
        assert!(c.validate().unwrap_err().to_string().contains("cell.ocv_correction"));
        assert!(OcvCorrection::default().validate().is_ok());
    }
}
