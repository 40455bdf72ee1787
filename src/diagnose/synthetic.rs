//! Synthetic recordings: a (richer) model run through a current protocol, sampled on a
//! regular grid with both sides of every current jump at a repeated time (as PyBaMM and
//! the fitting stack write them), plus seeded Gaussian noise.

use rand::SeedableRng;
use rand_distr::{Distribution, Normal};

use crate::data::Recording;
use crate::error::Error;
use crate::geometry::MeshSizes;
use crate::models::ModelBuilder;
use crate::models::{ModelKind, Submodels};
use crate::params::ParameterSet;
use crate::protocol::{Demand, Protocol, Step};
use crate::simulation::{SimOptions, States, simulate};

/// How to generate a recording.
#[derive(Clone, Debug)]
pub struct SyntheticSpec {
    pub kind: ModelKind,
    pub submodels: Submodels,
    pub mesh: MeshSizes,
    pub params: ParameterSet,
    /// Current (A) and rest steps; C-rate steps use `params.cell.nominal_capacity`.
    pub protocol: Protocol,
    /// Sampling period (s); step boundaries should fall on multiples of it.
    pub period: f64,
    /// Standard deviation of the voltage noise (V).
    pub noise: f64,
    /// Write the model temperature (K, with noise of `noise_temperature`) as well.
    pub temperature: bool,
    /// Standard deviation of the temperature noise (K).
    pub noise_temperature: f64,
    pub seed: u64,
}

impl SyntheticSpec {
    /// Defaults: 1 s sampling, 1 mV noise, no temperature column, seed 0.
    pub fn new(kind: ModelKind, submodels: Submodels, params: ParameterSet, protocol: Protocol) -> Self {
        Self {
            kind,
            submodels,
            mesh: MeshSizes::default(),
            params,
            protocol,
            period: 1.0,
            noise: 0.001,
            temperature: false,
            noise_temperature: 0.05,
            seed: 0,
        }
    }
}

/// Sample times and currents of `protocol`: a regular grid per step, with the step start
/// repeated (new current) after the previous step's end (old current).
fn skeleton(protocol: &Protocol, period: f64, capacity: f64) -> Result<(Vec<f64>, Vec<f64>), Error> {
    if !(period > 0.0 && period.is_finite()) {
        return Err(Error::invalid("period", period, "must be positive and finite"));
    }
    let (mut time, mut current) = (Vec::new(), Vec::new());
    let mut t0 = 0.0;
    for step in &protocol.steps {
        let n = (step.duration() / period).round().max(1.0) as usize;
        for k in 0..=n {
            let dt = (k as f64 * period).min(step.duration());
            let i = match step.demand_at(dt, capacity) {
                Demand::Current(i) => i,
                Demand::Power(_) | Demand::Voltage(_) => {
                    return Err(Error::InvalidSetting { field: "protocol".into(), reason: "power and voltage-hold steps are not supported here".into() });
                }
            };
            time.push(t0 + dt);
            current.push(i);
        }
        t0 += step.duration();
    }
    Ok((time, current))
}

/// Runs the spec's model through its protocol and writes what a cycler would record.
pub fn synthetic_recording(spec: &SyntheticSpec) -> Result<Recording, Error> {
    if let Some(k) = spec.protocol.steps.iter().position(|s| matches!(s, Step::Power { .. })) {
        return Err(Error::InvalidSetting { field: format!("protocol.steps[{k}]"), reason: "power steps are not supported here".into() });
    }
    let p = &spec.params;
    let (time, current) = skeleton(&spec.protocol, spec.period, p.cell.nominal_capacity)?;
    let mut builder = ModelBuilder::new(spec.kind, spec.submodels, spec.mesh);
    let built = builder.build(p)?;
    let mut distinct = time.clone();
    distinct.dedup();
    let opts = SimOptions { t_eval: Some(distinct.clone()), states: States::Kept, cutoffs: (0.0, 100.0), ..SimOptions::for_cell(p) };
    let sol = simulate(built.model.as_ref(), &mut built.workspace, &spec.protocol, &opts, None)?;
    if sol.time.len() != distinct.len() {
        return Err(Error::Solver { t: sol.time.last().copied().unwrap_or(0.0), reason: "simulation stopped early".into() });
    }
    let mut rng = rand::rngs::StdRng::seed_from_u64(spec.seed);
    let noise = Normal::new(0.0, spec.noise.max(0.0)).map_err(|e| Error::invalid("noise", spec.noise, e.to_string()))?;
    let noise_t = Normal::new(0.0, spec.noise_temperature.max(0.0))
        .map_err(|e| Error::invalid("noise_temperature", spec.noise_temperature, e.to_string()))?;
    let mut rec = Recording { temperature: spec.temperature.then(Vec::new), ..Default::default() };
    let mut out = 0usize;
    for (k, (&t, &i)) in time.iter().zip(&current).enumerate() {
        if k > 0 && time[k - 1] != t {
            out += 1;
        }
        let y = &sol.states[out];
        // The point after a jump: the same state at the new current.
        let v = built.model.voltage(y, i);
        rec.time.push(t);
        rec.current.push(i);
        rec.voltage.push(v + noise.sample(&mut rng));
        if let Some(temps) = rec.temperature.as_mut() {
            temps.push(built.model.temperature(y) + noise_t.sample(&mut rng));
        }
    }
    Ok(rec)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn skeleton_repeats_step_boundaries() {
        let protocol = Protocol { steps: vec![Step::Current { current: 2.0, duration: 3.0, until_voltage: None }, Step::Rest { duration: 2.0 }] };
        let (t, i) = skeleton(&protocol, 1.0, 5.0).unwrap();
        assert_eq!(t, vec![0.0, 1.0, 2.0, 3.0, 3.0, 4.0, 5.0]);
        assert_eq!(i, vec![2.0, 2.0, 2.0, 2.0, 0.0, 0.0, 0.0]);
        let rec = Recording { time: t, current: i, voltage: vec![0.0; 7], temperature: None };
        assert_eq!(rec.protocol(), protocol);
    }
}
