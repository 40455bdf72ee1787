//! Thevenin equivalent-circuit model: a series resistance `R0`, `n` parallel RC pairs and an
//! open-circuit voltage tabulated against state of charge, with an optional lumped thermal
//! balance.
//!
//! States: `[SOC, v_1, ..., v_n, (T)]` with
//!
//! ```text
//! dSOC/dt = -I / (3600 Q)
//! dv_k/dt = I / C_k - v_k / (R_k C_k)
//! C_th dT/dt = I^2 R0 + I sum_k v_k - hA (T - T_amb)        (thermal only)
//! V       = OCV(SOC) - I R0 - sum_k v_k
//! ```
//!
//! where `I` is the applied current (A, discharge positive), `Q` the capacity (A h) and
//! `v_k` the voltage (V) across RC pair `k`. The heat source is the irreversible heat
//! `I (OCV - V)` of the circuit; the ECM has no entropic term. Parameters do not depend on
//! temperature.

use serde::{Deserialize, Serialize};

use super::Model;
use crate::error::Error;
use crate::params::check::{check, non_negative, positive};
use crate::params::{FARADAY, Function1D, ParameterSet};

/// One parallel resistor-capacitor pair.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RcPair {
    /// Resistance (ohm), strictly positive.
    pub r: f64,
    /// Capacitance (F), strictly positive. The pair's time constant is `r c` (s).
    pub c: f64,
}

impl RcPair {
    /// Time constant `r c` (s).
    pub fn tau(&self) -> f64 {
        self.r * self.c
    }
}

/// Lumped (0-D) thermal balance of the ECM: `C dT/dt = Q_irr - hA (T - T_amb)`.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct EcmThermal {
    /// Heat capacity of the whole cell (J/K), strictly positive.
    pub heat_capacity: f64,
    /// Cooling conductance `h A` to the ambient (W/K), not negative.
    pub cooling: f64,
}

/// Parameters of a Thevenin equivalent-circuit model.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct EcmParameters {
    /// Capacity (A h) between SOC 0 and SOC 1, strictly positive.
    pub capacity: f64,
    /// Initial state of charge (-), in [0, 1].
    pub initial_soc: f64,
    /// Series (ohmic) resistance R0 (ohm), not negative.
    pub r0: f64,
    /// Parallel RC pairs, in series with R0 (may be empty).
    #[serde(default)]
    pub rc_pairs: Vec<RcPair>,
    /// Open-circuit voltage (V) as a function of SOC (-).
    pub ocv: Function1D,
    /// Ambient temperature (K), also the initial cell temperature, strictly positive.
    pub ambient_temperature: f64,
    /// Lumped thermal balance; `None` holds the cell at the ambient temperature.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub thermal: Option<EcmThermal>,
}

impl EcmParameters {
    /// Checks every field; the error names the first offending field and its value.
    pub fn validate(&self) -> Result<(), Error> {
        positive("capacity", self.capacity)?;
        check("initial_soc", self.initial_soc, (0.0..=1.0).contains(&self.initial_soc), "must lie in [0, 1]")?;
        non_negative("r0", self.r0)?;
        for (k, pair) in self.rc_pairs.iter().enumerate() {
            positive(&format!("rc_pairs[{k}].r"), pair.r)?;
            positive(&format!("rc_pairs[{k}].c"), pair.c)?;
        }
        self.ocv.validate("ocv")?;
        for soc in [0.0, 0.5, 1.0] {
            let v = self.ocv.eval(soc);
            if !v.is_finite() {
                return Err(Error::invalid("ocv", v, format!("is not finite at SOC = {soc}")));
            }
        }
        positive("ambient_temperature", self.ambient_temperature)?;
        if let Some(th) = &self.thermal {
            positive("thermal.heat_capacity", th.heat_capacity)?;
            non_negative("thermal.cooling", th.cooling)?;
        }
        Ok(())
    }

    /// Reads ECM parameters from a TOML file and validates them.
    pub fn from_toml_file(path: &std::path::Path) -> Result<Self, Error> {
        let text =
            std::fs::read_to_string(path).map_err(Error::io(&path))?;
        let p: EcmParameters = toml::from_str(&text)
            .map_err(|e| Error::Parse { path: path.display().to_string(), message: e.to_string() })?;
        p.validate()?;
        Ok(p)
    }

    /// An ECM of the Chen 2020 LG M50 cell (see [`equilibrium_ocv_table`] for the OCV and the
    /// capacity), at SOC 1 and 298.15 K, without the thermal balance.
    ///
    /// `R0` and the two RC pairs were fitted by linear least squares (with a grid search
    /// over the two time constants) to the overpotential `OCV - V` of the crate's DFN
    /// (default mesh, Chen 2020 parameters, no contact resistance) during a 1C discharge
    /// pulse of 600 s from SOC 0.5 followed by 1800 s of rest; the fit is reproduced by
    /// the test `chen2020_constants_are_the_dfn_fit` in `tests/suite/ecm.rs` (RMS residual 1.05 mV).
    /// They are constants, not functions of SOC or temperature, so the ECM is a coarse
    /// surrogate away from mid SOC and 1C.
    pub fn from_chen2020() -> EcmParameters {
        let p = crate::params::chen2020();
        let (capacity, ocv) = equilibrium_ocv_table(&p, 201);
        EcmParameters {
            capacity,
            initial_soc: 1.0,
            r0: CHEN2020_R0,
            rc_pairs: CHEN2020_RC.iter().map(|&(r, tau)| RcPair { r, c: tau / r }).collect(),
            ocv,
            ambient_temperature: p.thermal.ambient_temperature,
            thermal: None,
        }
    }
}

/// Fitted series resistance of the Chen 2020 ECM (ohm); see [`EcmParameters::from_chen2020`].
const CHEN2020_R0: f64 = 2.403e-2;
/// Fitted RC pairs of the Chen 2020 ECM as `(R (ohm), tau (s))`.
const CHEN2020_RC: [(f64, f64); 2] = [(1.225e-2, 30.58), (8.026e-3, 338.0)];

/// Equilibrium OCV against SOC of a physics parameter set, from its OCP functions and
/// stoichiometry windows (the C/0 limit of any of the physics models).
///
/// SOC 1 is the set's initial state (the particles' initial concentrations). Discharging
/// a charge `q` (C) moves the negative stoichiometry down by `q / Q_n` and the positive
/// one up by `q / Q_p`, with `Q = eps_s c_max L F A` the theoretical capacity of each
/// electrode; SOC 0 is where the OCV reaches `cell.lower_cutoff` (or where an electrode
/// runs out of lithium or vacancies, whichever comes first). Returns the capacity (A h)
/// between SOC 0 and 1 and a table of `n >= 2` OCVs (V) at uniformly spaced SOCs.
pub fn equilibrium_ocv_table(p: &ParameterSet, n: usize) -> (f64, Function1D) {
    let n = n.max(2);
    let area = p.cell.area();
    let (neg, pos) = (&p.negative, &p.positive);
    let q_n = neg.areal_capacity() * area;
    let q_p = pos.areal_capacity() * area;
    let x0 = neg.initial_concentration / neg.max_concentration;
    let y0 = pos.initial_concentration / pos.max_concentration;
    let ocv = |q: f64| pos.open_circuit_potential(y0 + q / q_p) - neg.open_circuit_potential(x0 - q / q_n);
    // Bisection for the charge at the lower cut-off within the stoichiometry window.
    let (mut lo, mut hi) = (0.0, (x0 * q_n).min((1.0 - y0) * q_p));
    if ocv(hi) < p.cell.lower_cutoff {
        for _ in 0..200 {
            let mid = 0.5 * (lo + hi);
            if ocv(mid) > p.cell.lower_cutoff {
                lo = mid;
            } else {
                hi = mid;
            }
        }
    }
    let q_max = hi;
    let soc: Vec<f64> = (0..n).map(|i| i as f64 / (n - 1) as f64).collect();
    let volts = soc.iter().map(|&s| ocv((1.0 - s) * q_max)).collect();
    (q_max / 3600.0, Function1D::Table { x: soc, y: volts })
}

/// Thevenin equivalent-circuit model.
#[derive(Clone, Debug)]
pub struct Ecm {
    params: EcmParameters,
    mass: Vec<f64>,
    scale: Vec<f64>,
}

impl Ecm {
    /// Validates `params` and builds the model.
    pub fn new(params: EcmParameters) -> Result<Self, Error> {
        params.validate()?;
        let n = 1 + params.rc_pairs.len() + usize::from(params.thermal.is_some());
        let one_c = params.capacity; // current (A) of 1C
        let mut scale = vec![1.0];
        scale.extend(params.rc_pairs.iter().map(|pair| (pair.r * one_c).max(1e-3)));
        if params.thermal.is_some() {
            scale.push(params.ambient_temperature);
        }
        Ok(Self { params, mass: vec![1.0; n], scale })
    }

    /// The (validated) parameters.
    pub fn params(&self) -> &EcmParameters {
        &self.params
    }

    /// Number of RC pairs.
    pub fn n_rc(&self) -> usize {
        self.params.rc_pairs.len()
    }

    /// State of charge (-) of a state vector.
    pub fn soc(&self, y: &[f64]) -> f64 {
        y[0]
    }

    /// Voltages (V) across the RC pairs.
    pub fn rc_voltages<'a>(&self, y: &'a [f64]) -> &'a [f64] {
        &y[1..1 + self.n_rc()]
    }

    /// A state at state of charge `soc` with relaxed RC pairs and the cell at ambient.
    pub fn state_at_soc(&self, soc: f64) -> Vec<f64> {
        let mut y = vec![0.0; self.len()];
        y[0] = soc;
        if self.params.thermal.is_some() {
            y[self.len() - 1] = self.params.ambient_temperature;
        }
        y
    }

    /// Irreversible heat generation `I (OCV - V) = I^2 R0 + I sum v_k` (W).
    pub fn heat(&self, y: &[f64], current: f64) -> f64 {
        current * (current * self.params.r0 + self.rc_voltages(y).iter().sum::<f64>())
    }
}

impl Model for Ecm {
    fn name(&self) -> String {
        format!("ECM ({} RC)", self.n_rc())
    }

    fn len(&self) -> usize {
        self.mass.len()
    }

    fn mass(&self) -> &[f64] {
        &self.mass
    }

    fn scale(&self) -> &[f64] {
        &self.scale
    }

    fn jacobian_pattern(&self) -> Vec<(usize, usize)> {
        let n = self.len();
        let mut p: Vec<(usize, usize)> = (0..n).map(|i| (i, i)).collect();
        if self.params.thermal.is_some() {
            let t = n - 1;
            p.extend((1..1 + self.n_rc()).map(|k| (t, k)));
        }
        p
    }

    fn initial_state(&self) -> Vec<f64> {
        self.state_at_soc(self.params.initial_soc)
    }

    fn rhs(&self, y: &[f64], current: f64, out: &mut [f64]) {
        let p = &self.params;
        out[0] = -current / (3600.0 * p.capacity);
        for (k, pair) in p.rc_pairs.iter().enumerate() {
            out[1 + k] = current / pair.c - y[1 + k] / pair.tau();
        }
        if let Some(th) = &p.thermal {
            let t = y.len() - 1;
            out[t] = (self.heat(y, current) - th.cooling * (y[t] - p.ambient_temperature)) / th.heat_capacity;
        }
    }

    fn voltage(&self, y: &[f64], current: f64) -> f64 {
        self.open_circuit_voltage(y) - current * self.params.r0 - self.rc_voltages(y).iter().sum::<f64>()
    }

    fn temperature_state(&self) -> Option<usize> {
        self.params.thermal.is_some().then(|| self.len() - 1)
    }

    fn temperature(&self, y: &[f64]) -> f64 {
        self.temperature_state().map_or(self.params.ambient_temperature, |k| y[k])
    }

    /// Charge-equivalent lithium `SOC Q 3600 / F` (mol): the cyclable lithium still to move
    /// between the electrodes before SOC 0. Unlike the physics models' total solid lithium,
    /// which is conserved, it changes at `-I / F`, so the conservation check of an ECM is
    /// `F (n(0) - n(t)) / 3600 = ` the discharged capacity (A h).
    fn solid_lithium(&self, y: &[f64]) -> f64 {
        self.soc(y) * self.params.capacity * 3600.0 / FARADAY
    }

    fn open_circuit_voltage(&self, y: &[f64]) -> f64 {
        self.params.ocv.eval(self.soc(y))
    }
}

