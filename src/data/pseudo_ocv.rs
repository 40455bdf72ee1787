//! Pseudo open-circuit voltage from slow (C/20 to C/10) constant-current branches: each branch
//! is put on a state-of-charge axis by its own charge (0 at its empty end, 1 at its full end),
//! and the pseudo-OCV is the mean of the discharge and charge voltages at the same state of
//! charge; half their gap is the hysteresis band (with the overpotential of the slow rate).

use serde::Serialize;

use super::Recording;
use super::cycler::{Step, StepKind};
use crate::params::function::interpolate;

/// One constant-current branch of a pseudo-OCV test.
#[derive(Clone, Debug, Serialize)]
pub struct OcvBranch {
    /// Step number in its recording ([`super::cycler::steps`]).
    pub step: usize,
    /// Charge the branch moves (A h).
    pub capacity: f64,
    /// Mean current (A, discharge positive).
    pub mean_current: f64,
    /// State of charge (-) of every sample, ascending, and its voltage (V).
    #[serde(skip)]
    pub soc: Vec<f64>,
    #[serde(skip)]
    pub voltage: Vec<f64>,
}

impl OcvBranch {
    /// The longest-charge constant-current step of `rec` that discharges (`discharge`) or
    /// charges; `None` when it has none.
    pub fn find(rec: &Recording, steps: &[Step], discharge: bool) -> Option<Self> {
        steps
            .iter()
            .filter(|s| s.kind == StepKind::Cc && (s.mean_current > 0.0) == discharge && s.last > s.first)
            .map(|s| Self::from_step(rec, s))
            .max_by(|a, b| a.capacity.total_cmp(&b.capacity))
    }

    /// The branch of step `s`, its state of charge by coulomb counting over the step.
    fn from_step(rec: &Recording, s: &Step) -> Self {
        let (t, i) = (&rec.time, &rec.current);
        let mut moved = vec![0.0];
        for k in s.first..s.last {
            let q = moved[moved.len() - 1] + 0.5 * (i[k] + i[k + 1]).abs() * (t[k + 1] - t[k]) / 3600.0;
            moved.push(q);
        }
        let capacity = moved[moved.len() - 1];
        let discharge = s.mean_current > 0.0;
        let mut pairs: Vec<(f64, f64)> = moved
            .iter()
            .zip(&rec.voltage[s.first..=s.last])
            .map(|(q, v)| (if discharge { 1.0 - q / capacity } else { q / capacity }, *v))
            .collect();
        pairs.sort_by(|a, b| a.0.total_cmp(&b.0));
        pairs.dedup_by(|a, b| a.0 == b.0);
        Self { step: s.number, capacity, mean_current: s.mean_current, soc: pairs.iter().map(|p| p.0).collect(), voltage: pairs.iter().map(|p| p.1).collect() }
    }

    /// Voltage (V) at state of charge `soc` (-).
    pub fn at(&self, soc: f64) -> f64 {
        interpolate(&self.soc, &self.voltage, soc)
    }
}

/// A pseudo-OCV on a uniform state-of-charge grid.
#[derive(Clone, Debug, Serialize)]
pub struct PseudoOcv {
    pub discharge: Option<OcvBranch>,
    pub charge: Option<OcvBranch>,
    /// State of charge (-), 0 to 1.
    pub soc: Vec<f64>,
    /// Charge discharged from the full end (A h): `(1 - soc)` times the mean branch capacity.
    pub discharged: Vec<f64>,
    /// Mean of the branches' voltages (V).
    pub voltage: Vec<f64>,
    /// Half the charge-discharge gap (V); zero with one branch.
    pub half_gap: Vec<f64>,
}

impl PseudoOcv {
    /// The pseudo-OCV of the branches on `points` (>= 2) states of charge; `None` without a
    /// branch.
    pub fn new(discharge: Option<OcvBranch>, charge: Option<OcvBranch>, points: usize) -> Option<Self> {
        let branches: Vec<&OcvBranch> = discharge.iter().chain(charge.iter()).collect();
        if branches.is_empty() {
            return None;
        }
        let capacity = branches.iter().map(|b| b.capacity).sum::<f64>() / branches.len() as f64;
        let soc: Vec<f64> = (0..points).map(|k| k as f64 / (points - 1) as f64).collect();
        let (mut voltage, mut half_gap) = (Vec::new(), Vec::new());
        for &s in &soc {
            match (&discharge, &charge) {
                (Some(d), Some(c)) => {
                    let (vd, vc) = (d.at(s), c.at(s));
                    voltage.push(0.5 * (vd + vc));
                    half_gap.push(0.5 * (vc - vd));
                }
                _ => {
                    voltage.push(branches[0].at(s));
                    half_gap.push(0.0);
                }
            }
        }
        let discharged = soc.iter().map(|s| (1.0 - s) * capacity).collect();
        Some(Self { discharge, charge, soc, discharged, voltage, half_gap })
    }

    /// Mean capacity of the branches (A h).
    pub fn capacity(&self) -> f64 {
        self.discharged[0]
    }

    /// The table as CSV: `soc,discharged_Ah,ocv_V,half_gap_V,discharge_V,charge_V` (a missing
    /// branch's column empty).
    pub fn csv(&self) -> String {
        use std::fmt::Write;
        let mut s = String::from("soc,discharged_Ah,ocv_V,half_gap_V,discharge_V,charge_V\n");
        let at = |b: &Option<OcvBranch>, x: f64| b.as_ref().map_or(String::new(), |b| format!("{:.6}", b.at(x)));
        for k in 0..self.soc.len() {
            let x = self.soc[k];
            let _ = writeln!(s, "{x:.6},{:.6},{:.6},{:.6},{},{}", self.discharged[k], self.voltage[k], self.half_gap[k], at(&self.discharge, x), at(&self.charge, x));
        }
        s
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::data::cycler::steps;

    /// A linear OCV 3 + soc (V) at 1 A h, discharged then charged at 0.1 A with a 20 mV
    /// overpotential: the mean is the OCV and the half gap 20 mV, exactly.
    #[test]
    fn mean_and_half_gap_of_a_symmetric_overpotential() {
        let mut rec = Recording::default();
        let dt = 360.0;
        for k in 0..=100 {
            rec.time.push(k as f64 * dt);
            rec.current.push(0.1);
            rec.voltage.push(3.0 + (1.0 - 0.01 * k as f64) - 0.02);
        }
        for k in 0..=100 {
            rec.time.push((101 + k) as f64 * dt);
            rec.current.push(-0.1);
            rec.voltage.push(3.0 + 0.01 * k as f64 + 0.02);
        }
        let s = steps(&rec, None);
        let (d, c) = (OcvBranch::find(&rec, &s, true).unwrap(), OcvBranch::find(&rec, &s, false).unwrap());
        assert!((d.capacity - 1.0).abs() < 1e-12 && (c.capacity - 1.0).abs() < 1e-12, "{} {}", d.capacity, c.capacity);
        let ocv = PseudoOcv::new(Some(d), Some(c), 11).unwrap();
        for k in 0..11 {
            assert!((ocv.voltage[k] - (3.0 + ocv.soc[k])).abs() < 1e-9, "{k}: {}", ocv.voltage[k]);
            assert!((ocv.half_gap[k] - 0.02).abs() < 1e-9);
            assert!((ocv.discharged[k] - (1.0 - ocv.soc[k])).abs() < 1e-12);
        }
        assert!(PseudoOcv::new(None, None, 11).is_none());
    }
}
