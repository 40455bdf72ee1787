//! Plating within one charge. The plating candidates need several cycles in general (lithium
//! plated charge after charge shows as fade), but a single charge shows plating too when the
//! negative electrode falls below lithium's potential during it and a rest or a discharge
//! follows, in which the plated lithium strips back (a plateau the model misses). Whether that
//! happens is read from the user's fitted model, not from the recording's rate or temperature:
//! its plating margin `phi_s - phi_e` at the negative electrode's separator edge
//! ([`crate::models::Model::plating_margin`]), the one the fast-charge search holds.

use super::refit::{FitSettings, replay_problem};
use crate::data::Recording;
use crate::params::ParameterSet;
use crate::problem::fitting::{FitParameter, ModelSpec};

/// Where the fitted model's negative electrode falls below lithium's potential during a
/// charge that a rest or a discharge follows.
#[derive(Clone, Copy, Debug)]
pub(super) struct PlatingSeen {
    /// The least plating margin (V) during such charges, at most 0.
    pub margin: f64,
    /// When (s from the recording's start).
    pub at_s: f64,
}

impl PlatingSeen {
    /// Why the plating candidates are tried on a recording of few cycles.
    pub fn note(&self) -> String {
        format!(
            "The user's fitted model plates within a charge: its plating margin (phi_s - phi_e at the negative electrode's separator edge) falls to {:.1} mV at t = {:.0} s, and a rest or a discharge follows, in which plated lithium would strip back; so the plating candidates are tried although the recording spans few cycles.",
            self.margin * 1e3,
            self.at_s
        )
    }
}

/// The least plating margin, at most 0, of the model `spec` (on `base`, `fitted` at `values`)
/// replaying `data` during a charge (negative current) that a rest or a discharge follows;
/// `None` when it stays above 0 there, the model has no margin, or the replay fails.
pub(super) fn plating_in_a_charge(spec: ModelSpec, base: &ParameterSet, fitted: &[FitParameter], values: &[f64], data: &Recording, settings: &FitSettings) -> Option<PlatingSeen> {
    // The last charging point a rest or a discharge follows.
    let last_charge = data.current.iter().rposition(|i| *i >= 0.0).and_then(|after| data.current[..after].iter().rposition(|i| *i < 0.0))?;
    let problem = replay_problem(spec, base.clone(), fitted.to_vec(), data, settings).ok()?;
    let mut outputs: Vec<(f64, f64)> = Vec::with_capacity(data.time.len());
    let mut watch = |model: &dyn crate::models::Model, y: &[f64], i: f64| outputs.push((model.plating_margin(y, i).unwrap_or(f64::INFINITY), i));
    problem.replay_watching(values, &mut watch).ok()?;
    // Output k is the recording's k-th distinct time.
    let mut times: Vec<f64> = data.time.iter().map(|t| t - data.time[0]).collect();
    times.dedup();
    let until = data.time[last_charge] - data.time[0];
    outputs
        .iter()
        .zip(&times)
        .filter(|((margin, i), t)| *i < 0.0 && **t <= until && *margin <= 0.0)
        .map(|((margin, _), t)| PlatingSeen { margin: *margin, at_s: *t })
        .min_by(|a, b| a.margin.total_cmp(&b.margin))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::models::{ModelKind, Submodels};
    use crate::params::chen2020;

    /// A recording of `current` (A) held for `seconds` each, sampled every 10 s, its voltage
    /// unused by the replay.
    fn recording(steps: &[(f64, f64)]) -> Recording {
        let mut current = Vec::new();
        for &(i, seconds) in steps {
            current.extend(std::iter::repeat_n(i, (seconds / 10.0) as usize));
        }
        let time = (0..current.len()).map(|k| 10.0 * k as f64).collect();
        Recording { time, voltage: vec![3.7; current.len()], current, temperature: None }
    }

    /// The SPM of Chen 2020 from 30 % of its charge: a 3C charge at 0 degC takes the negative
    /// electrode below lithium's potential, a C/5 one at 25 degC does not, and a charge that
    /// nothing follows shows no stripping either way.
    #[test]
    fn a_fast_cold_charge_with_a_rest_after_it_plates_and_a_slow_one_does_not() {
        let spec = ModelSpec::new(ModelKind::Spm, Submodels::default());
        let soc = [FitParameter::linear(crate::problem::fitting::INITIAL_SOC, 0.3, 0.0, 1.0)];
        let settings = FitSettings::default();
        let mut cold = chen2020();
        cold.thermal.ambient_temperature = 273.15;
        cold.thermal.initial_temperature = 273.15;
        let q = cold.cell.nominal_capacity;
        let fast = recording(&[(0.0, 60.0), (-3.0 * q, 600.0), (0.0, 600.0)]);
        let seen = plating_in_a_charge(spec, &cold, &soc, &[0.3], &fast, &settings).expect("a 3C charge at 0 degC plates");
        assert!(seen.margin <= 0.0 && seen.at_s > 60.0 && seen.at_s <= 660.0, "{seen:?}");
        let unfollowed = recording(&[(0.0, 60.0), (-3.0 * q, 600.0)]);
        assert!(plating_in_a_charge(spec, &cold, &soc, &[0.3], &unfollowed, &settings).is_none());
        let slow = recording(&[(0.0, 60.0), (-0.2 * q, 600.0), (0.0, 600.0)]);
        assert!(plating_in_a_charge(spec, &chen2020(), &soc, &[0.3], &slow, &settings).is_none());
    }
}
