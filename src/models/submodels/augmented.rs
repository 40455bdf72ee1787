//! Submodels that wrap any physics model without touching it: a series RC element and a
//! one-state OCV hysteresis (each an appended state), a leak and a voltage offset.
//!
//! [`Augmented`] wraps a built `Box<dyn PhysicsModel>`; the wrapped model sees only its own
//! states, and the extra states follow them:
//!
//! - RC element (`cell.rc_resistance` `R` (ohm), `cell.rc_capacitance` `C` (F)): the voltage
//!   `v` (V) across the element obeys `dv/dt = I / C - v / (R C)` and the terminal voltage
//!   loses `v`. With `R = 0` the element is a short (`v` relaxes to zero).
//! - Hysteresis (`cell.hysteresis_voltage` `M` (V), `cell.hysteresis_rate` `k` (-),
//!   `cell.hysteresis_initial` `h(0)`): the state `h` in [-1, 1] obeys
//!   `dh/dt = k |I| / (3600 Q) (-sign(I) - h)` with `Q` the nominal capacity (A h), i.e.
//!   `k / (3600 Q) (-I - |I| h)`, and the terminal voltage gains `M h`: discharge
//!   (`I > 0`) drives `h` to -1 and lowers the voltage, charge raises it; at rest `h` holds.
//! - Leak (`cell.leakage_current` `I_L` (A), discharge positive): the cell carries
//!   `I + I_L` where the cycler drives and records `I`, e.g. self-discharge through a soft
//!   short or a current sensor's offset. Every other submodel sees `I + I_L`.
//! - Voltage offset (`cell.voltage_offset` `V_0` (V)): the terminal voltage gains `V_0`, e.g.
//!   the voltage channel's calibration or an OCP shifted against the set's.
//! - Voltage gain (`cell.voltage_gain` `g` (-)): the voltage channel reads `1 + g` times the
//!   cell's voltage (before the offset), a calibration error of the channel's scale.
//! - Current gain (`cell.current_gain` `g` (-)): the current channel reads `1 + g` times the
//!   cell's current, so the cell carries `I / (1 + g)` (before the leak) where the cycler
//!   records `I`: a shunt or Hall sensor out of calibration. In a model without an
//!   electrolyte it is the same as both electrodes' capacity and area scaled by `1 + g`.
//! - OCV correction (`cell.ocv_correction`, see [`crate::params::OcvCorrection`]): the state
//!   `q` (A h) counts the charge the cell carries, `dq/dt = I / 3600`, and the terminal
//!   voltage gains `ΔV(q)`: an open-circuit voltage whose shape differs from the set's.

use crate::models::{Electrochem, Model, PhysicsModel, Submodels};
use crate::params::ParameterSet;

/// Typical size of the RC voltage (V), for tolerances and difference steps.
const RC_SCALE: f64 = 0.01;

/// Seconds per hour: the charge state counts ampere-hours.
const SECONDS_PER_HOUR: f64 = 3600.0;

/// A physics model with RC and/or hysteresis states appended.
pub struct Augmented {
    base: Box<dyn PhysicsModel>,
    /// Index of the RC state, when on.
    rc: Option<usize>,
    /// Index of the hysteresis state, when on.
    hysteresis: Option<usize>,
    /// Index of the charge state (A h) of the OCV correction, when on.
    charge: Option<usize>,
    /// Whether the leak is on.
    leak: bool,
    /// Whether the voltage offset is on.
    offset: bool,
    /// Whether the voltage gain is on.
    gain: bool,
    /// Whether the current gain is on.
    current_gain: bool,
    /// Number of states of the wrapped model.
    n_base: usize,
    mass: Vec<f64>,
    scale: Vec<f64>,
}

impl Augmented {
    /// Wraps `base`, appending the states of the submodels switched on in `submodels`.
    pub fn new(base: Box<dyn PhysicsModel>, submodels: Submodels) -> Self {
        let n_base = base.len();
        let mut mass = base.mass().to_vec();
        let mut scale = base.scale().to_vec();
        let mut next = n_base;
        let mut push = |on: bool, s: f64| {
            on.then(|| {
                mass.push(1.0);
                scale.push(s);
                next += 1;
                next - 1
            })
        };
        let rc = push(submodels.rc, RC_SCALE);
        let hysteresis = push(submodels.hysteresis, 1.0);
        let charge = push(submodels.ocv_correction, base.electrochem().params.cell.nominal_capacity);
        Self { base, rc, hysteresis, charge, leak: submodels.leak, offset: submodels.voltage_offset, gain: submodels.voltage_gain, current_gain: submodels.current_gain, n_base, mass, scale }
    }

    /// The wrapped model.
    pub fn base(&self) -> &dyn PhysicsModel {
        self.base.as_ref()
    }

    fn cell(&self) -> &crate::params::Cell {
        &self.base.electrochem().params.cell
    }

    /// The current (A) the cell carries when the cycler drives (and records) `current`:
    /// over the current channel's gain, plus the leak.
    fn inside(&self, current: f64) -> f64 {
        let cell = self.cell();
        let carried = if self.current_gain { current / (1.0 + cell.current_gain) } else { current };
        if self.leak { carried + cell.leakage_current } else { carried }
    }

    /// Voltage across the RC element (V), zero when it is off.
    pub fn rc_voltage(&self, y: &[f64]) -> f64 {
        self.rc.map_or(0.0, |k| y[k])
    }

    /// Hysteresis state `h` (-), zero when it is off.
    pub fn hysteresis_state(&self, y: &[f64]) -> f64 {
        self.hysteresis.map_or(0.0, |k| y[k])
    }

    /// The OCV correction (V) at the charge passed, zero when it is off.
    pub fn ocv_correction(&self, y: &[f64]) -> f64 {
        self.charge.map_or(0.0, |k| self.cell().ocv_correction.at(y[k]))
    }
}

impl Model for Augmented {
    fn name(&self) -> String {
        let mut name = self.base.name();
        if self.rc.is_some() {
            name.push_str("+RC");
        }
        if self.hysteresis.is_some() {
            name.push_str("+hysteresis");
        }
        if self.leak {
            name.push_str("+leak");
        }
        if self.offset {
            name.push_str("+offset");
        }
        if self.gain {
            name.push_str("+gain");
        }
        if self.current_gain {
            name.push_str("+current gain");
        }
        if self.charge.is_some() {
            name.push_str("+OCV correction");
        }
        name
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

    fn accumulating_states(&self) -> Vec<usize> {
        self.base.accumulating_states()
    }

    fn rows_reading_current(&self) -> Vec<usize> {
        // The wrapped model's rows (the leak only shifts the current it reads) and every
        // appended state: the RC, hysteresis and charge states all integrate the current.
        let mut rows = self.base.rows_reading_current();
        rows.extend(self.n_base..self.len());
        rows
    }

    fn jacobian_pattern(&self) -> Vec<(usize, usize)> {
        let mut p = self.base.jacobian_pattern();
        p.extend(self.rc.iter().chain(&self.hysteresis).chain(&self.charge).map(|&k| (k, k)));
        p
    }

    fn initial_state(&self) -> Vec<f64> {
        let mut y = self.base.initial_state();
        if self.rc.is_some() {
            y.push(0.0);
        }
        if self.hysteresis.is_some() {
            y.push(self.cell().hysteresis_initial);
        }
        if self.charge.is_some() {
            y.push(0.0);
        }
        y
    }

    fn rhs(&self, y: &[f64], current: f64, out: &mut [f64]) {
        let current = self.inside(current);
        let nb = self.n_base;
        self.base.rhs(&y[..nb], current, &mut out[..nb]);
        let cell = self.cell();
        if let Some(k) = self.rc {
            let (r, c) = (cell.rc_resistance, cell.rc_capacitance);
            out[k] = if r > 0.0 { (current - y[k] / r) / c } else { -y[k] };
        }
        if let Some(k) = self.hysteresis {
            let rate = cell.hysteresis_rate / (SECONDS_PER_HOUR * cell.nominal_capacity);
            out[k] = rate * (-current - current.abs() * y[k]);
        }
        if let Some(k) = self.charge {
            out[k] = current / SECONDS_PER_HOUR;
        }
    }

    fn voltage(&self, y: &[f64], current: f64) -> f64 {
        let cell = self.base.voltage(&y[..self.n_base], self.inside(current)) - self.rc_voltage(y)
            + self.cell().hysteresis_voltage * self.hysteresis_state(y)
            + self.ocv_correction(y);
        let scale = if self.gain { 1.0 + self.cell().voltage_gain } else { 1.0 };
        scale * cell + if self.offset { self.cell().voltage_offset } else { 0.0 }
    }

    fn temperature(&self, y: &[f64]) -> f64 {
        self.base.temperature(&y[..self.n_base])
    }
    fn temperature_state(&self) -> Option<usize> {
        self.base.temperature_state()
    }

    fn solid_lithium(&self, y: &[f64]) -> f64 {
        self.base.solid_lithium(&y[..self.n_base])
    }

    fn open_circuit_voltage(&self, y: &[f64]) -> f64 {
        self.base.open_circuit_voltage(&y[..self.n_base])
    }

    fn sei_lithium(&self, y: &[f64]) -> f64 {
        self.base.sei_lithium(&y[..self.n_base])
    }

    fn sei_thickness(&self, y: &[f64]) -> Option<f64> {
        self.base.sei_thickness(&y[..self.n_base])
    }

    fn active_material(&self, y: &[f64]) -> Option<super::lam::ActiveMaterial> {
        self.base.active_material(&y[..self.n_base])
    }

    fn plated_lithium(&self, y: &[f64]) -> Option<super::plating::PlatedLithium> {
        self.base.plated_lithium(&y[..self.n_base])
    }

    fn plating_margin(&self, y: &[f64], current: f64) -> Option<f64> {
        self.base.plating_margin(&y[..self.n_base], self.inside(current))
    }

    fn fields(&self, y: &[f64]) -> Vec<crate::models::Field> {
        self.base.fields(&y[..self.n_base])
    }

    fn output_states(&self) -> Vec<usize> {
        let mut out = self.base.output_states();
        out.extend(self.n_base..self.len());
        out
    }
}

impl PhysicsModel for Augmented {
    fn electrochem(&self) -> &Electrochem {
        self.base.electrochem()
    }
    fn set_params(&mut self, params: ParameterSet) {
        self.base.set_params(params);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::MeshSizes;
    use crate::models::ModelBuilder;
    use crate::models::ModelKind;
    use crate::protocol::{Protocol, Step};
    use crate::simulation::{SimOptions, simulate};

    fn run(submodels: Submodels, p: &ParameterSet, protocol: &Protocol, t_eval: Vec<f64>) -> Vec<f64> {
        let mut builder = ModelBuilder::new(ModelKind::Spm, submodels, MeshSizes::default());
        let built = builder.build(p).unwrap();
        let mut opts = SimOptions::for_cell(p);
        opts.t_eval = Some(t_eval);
        opts.solver.set_tolerance(1e-9);
        simulate(built.model.as_ref(), &mut built.workspace, protocol, &opts, None).unwrap().voltage
    }

    /// The RC element adds `-I R (1 - exp(-t / (R C)))` during a current step and
    /// `-I R (1 - exp(-T/RC)) exp(-(t - T)/(R C))` in the rest after it (analytic solution
    /// of the linear ODE), on top of the unchanged SPM voltage.
    #[test]
    fn rc_element_matches_the_analytic_step_response() {
        let mut p = crate::params::chen2020();
        p.cell.rc_resistance = 0.012;
        p.cell.rc_capacitance = 800.0;
        let tau = 0.012 * 800.0;
        let protocol = Protocol { steps: vec![Step::Current { current: 5.0, duration: 30.0, until_voltage: None }, Step::Rest { duration: 60.0 }] };
        let t: Vec<f64> = (0..=90).map(f64::from).collect();
        let plain = run(Submodels::default(), &p, &protocol, t.clone());
        let rc = run(Submodels { rc: true, ..Default::default() }, &p, &protocol, t.clone());
        for (k, &tk) in t.iter().enumerate().skip(1) {
            let v = if tk <= 30.0 {
                5.0 * 0.012 * (1.0 - (-tk / tau).exp())
            } else {
                5.0 * 0.012 * (1.0 - (-30.0 / tau).exp()) * (-(tk - 30.0) / tau).exp()
            };
            let got = plain[k] - rc[k];
            assert!((got - v).abs() < 2e-6, "t = {tk}: RC drop {got} vs analytic {v}");
        }
    }

    /// Hysteresis: with `h(0) = 0`, a discharge at current `I` gives
    /// `h = -(1 - exp(-k I t / (3600 Q)))` and the voltage offset `M h` holds through a rest.
    #[test]
    fn hysteresis_state_matches_the_analytic_solution() {
        let mut p = crate::params::chen2020();
        p.cell.hysteresis_voltage = 0.02;
        p.cell.hysteresis_rate = 20.0;
        let protocol = Protocol { steps: vec![Step::Current { current: 5.0, duration: 600.0, until_voltage: None }, Step::Rest { duration: 300.0 }] };
        let t: Vec<f64> = (0..=18).map(|k| 50.0 * f64::from(k)).collect();
        let plain = run(Submodels::default(), &p, &protocol, t.clone());
        let hyst = run(Submodels { hysteresis: true, ..Default::default() }, &p, &protocol, t.clone());
        let rate = 20.0 * 5.0 / (3600.0 * p.cell.nominal_capacity);
        for (k, &tk) in t.iter().enumerate() {
            let h = -(1.0 - (-rate * tk.min(600.0)).exp());
            let got = hyst[k] - plain[k];
            assert!((got - 0.02 * h).abs() < 2e-6, "t = {tk}: offset {got} vs {}", 0.02 * h);
        }
    }

    /// A current channel reading 2.5 % high: the cell carries the recorded 1C over 1.025, and
    /// in the SPM that is the same as both electrodes 2.5 % thicker at the recorded current
    /// (capacity and surface scale together; no electrolyte to tell them apart).
    #[test]
    fn a_current_gain_carries_the_recorded_current_over_one_plus_the_gain() {
        let mut p = crate::params::chen2020();
        p.cell.current_gain = 0.025;
        let t: Vec<f64> = (0..=12).map(|k| 250.0 * f64::from(k)).collect();
        let step = |current: f64| Protocol { steps: vec![Step::Current { current, duration: 3000.0, until_voltage: None }, Step::Rest { duration: 600.0 }] };
        let read = run(Submodels { current_gain: true, ..Default::default() }, &p, &step(5.0), t.clone());
        let carried = run(Submodels::default(), &p, &step(5.0 / 1.025), t.clone());
        let mut thicker = p.clone();
        thicker.negative.thickness *= 1.025;
        thicker.positive.thickness *= 1.025;
        let scaled = run(Submodels::default(), &thicker, &step(5.0), t.clone());
        let plain = run(Submodels::default(), &p, &step(5.0), t.clone());
        for k in 0..t.len() {
            assert!((read[k] - carried[k]).abs() < 1e-9, "t = {}: {} vs {}", t[k], read[k], carried[k]);
            assert!((read[k] - scaled[k]).abs() < 2e-5, "t = {}: {} vs {} (thicker)", t[k], read[k], scaled[k]);
        }
        // The gain moved the curve: 2.5 % less charge passed by the end of the discharge.
        assert!(read[12] - plain[12] > 2e-3, "{} vs {}", read[12], plain[12]);
    }

    /// A rest with a leak `I_L` is the same cell discharged at `I_L` without one (the cycler
    /// records zero current), and the leak costs no extra state.
    #[test]
    fn a_rest_with_a_leak_is_a_discharge_at_the_leak_current() {
        let mut p = crate::params::chen2020();
        p.cell.leakage_current = 0.4;
        let t: Vec<f64> = (0..=12).map(|k| 300.0 * f64::from(k)).collect();
        let rest = Protocol { steps: vec![Step::Rest { duration: 3600.0 }] };
        let drawn = Protocol { steps: vec![Step::Current { current: 0.4, duration: 3600.0, until_voltage: None }] };
        let leaking = run(Submodels { leak: true, ..Default::default() }, &p, &rest, t.clone());
        let discharged = run(Submodels::default(), &p, &drawn, t.clone());
        let resting = run(Submodels::default(), &p, &rest, t.clone());
        for k in 0..t.len() {
            assert!((leaking[k] - discharged[k]).abs() < 1e-9, "t = {}: {} vs {}", t[k], leaking[k], discharged[k]);
        }
        // The leak discharged the cell: 0.4 A h at 4.5 % of the capacity lowers the voltage.
        assert!(resting[12] - leaking[12] > 0.01, "{} vs {}", resting[12], leaking[12]);
        let mut builder = ModelBuilder::new(ModelKind::Spm, Submodels { leak: true, ..Default::default() }, MeshSizes::default());
        let plain = ModelBuilder::new(ModelKind::Spm, Submodels::default(), MeshSizes::default()).build(&p).unwrap().model.len();
        let built = builder.build(&p).unwrap();
        assert_eq!((built.model.len(), built.model.name()), (plain, "SPM+leak".to_string()));
    }

    /// The voltage offset moves the whole curve by `V_0` and nothing else.
    #[test]
    fn a_voltage_offset_shifts_the_curve_by_its_value() {
        let mut p = crate::params::chen2020();
        p.cell.voltage_offset = -0.008;
        let t: Vec<f64> = (0..=12).map(|k| 150.0 * f64::from(k)).collect();
        let protocol = Protocol { steps: vec![Step::Current { current: 5.0, duration: 1200.0, until_voltage: None }, Step::Rest { duration: 600.0 }] };
        let shifted = run(Submodels { voltage_offset: true, ..Default::default() }, &p, &protocol, t.clone());
        let plain = run(Submodels::default(), &p, &protocol, t.clone());
        for k in 0..t.len() {
            assert!((shifted[k] - plain[k] + 0.008).abs() < 1e-12, "t = {}: {} vs {}", t[k], shifted[k], plain[k]);
        }
    }

    /// The voltage gain scales the cell's voltage by `1 + g` before the offset is added.
    #[test]
    fn a_voltage_gain_scales_the_curve_before_the_offset() {
        let mut p = crate::params::chen2020();
        (p.cell.voltage_gain, p.cell.voltage_offset) = (0.003, -0.002);
        let t: Vec<f64> = (0..=12).map(|k| 150.0 * f64::from(k)).collect();
        let protocol = Protocol { steps: vec![Step::Current { current: 5.0, duration: 1200.0, until_voltage: None }, Step::Rest { duration: 600.0 }] };
        let read = run(Submodels { voltage_gain: true, voltage_offset: true, ..Default::default() }, &p, &protocol, t.clone());
        let plain = run(Submodels::default(), &p, &protocol, t.clone());
        for k in 0..t.len() {
            assert!((read[k] - (1.003 * plain[k] - 0.002)).abs() < 1e-12, "t = {}: {} vs {}", t[k], read[k], plain[k]);
        }
    }

    /// The wrapper leaves the wrapped model's states, temperature and lithium alone, and the
    /// builder re-uses it when only non-geometric parameters change.
    #[test]
    fn wrapper_appends_states_and_survives_parameter_changes() {
        let p = crate::params::chen2020();
        let sub = Submodels { rc: true, hysteresis: true, thermal: true, ..Default::default() };
        let mut builder = ModelBuilder::new(ModelKind::Spm, sub, MeshSizes::default());
        let plain_len = ModelBuilder::new(ModelKind::Spm, Submodels { thermal: true, ..Default::default() }, MeshSizes::default())
            .build(&p)
            .unwrap()
            .model
            .len();
        let built = builder.build(&p).unwrap();
        assert_eq!(built.model.len(), plain_len + 2);
        assert_eq!(built.model.name(), "SPM+RC+hysteresis");
        let y = built.model.initial_state();
        assert_eq!(built.model.temperature(&y), p.thermal.initial_temperature);
        let mut q = p.clone();
        q.cell.hysteresis_initial = 0.5;
        q.cell.hysteresis_voltage = 0.01;
        let v0 = builder.build(&p).unwrap().model.voltage(&y, 0.0);
        let built = builder.build(&q).unwrap();
        let y = built.model.initial_state();
        assert_eq!(y[y.len() - 1], 0.5);
        assert!((built.model.voltage(&y, 0.0) - v0 - 0.005).abs() < 1e-12);
        assert_eq!(builder.rebuild_count(), 1);
    }

    /// The OCV correction adds `ΔV(q)` at the charge passed, `q = I t / 3600` under a
    /// constant current (held through the rest), and changes nothing else.
    #[test]
    fn an_ocv_correction_follows_the_charge_passed() {
        let mut p = crate::params::chen2020();
        p.cell.ocv_correction = crate::params::OcvCorrection { charge: vec![0.0, 1.0, 2.0], voltage: vec![0.0, 0.03, -0.01] };
        let t: Vec<f64> = (0..=12).map(|k| 150.0 * f64::from(k)).collect();
        let protocol = Protocol { steps: vec![Step::Current { current: 5.0, duration: 1200.0, until_voltage: None }, Step::Rest { duration: 600.0 }] };
        let corrected = run(Submodels { ocv_correction: true, ..Default::default() }, &p, &protocol, t.clone());
        let plain = run(Submodels::default(), &p, &protocol, t.clone());
        for k in 0..t.len() {
            let q = 5.0 * t[k].min(1200.0) / 3600.0;
            let dv = if q <= 1.0 { 0.03 * q } else { 0.03 - 0.04 * (q - 1.0) };
            assert!((corrected[k] - plain[k] - dv).abs() < 1e-9, "t = {}: {} vs {}", t[k], corrected[k] - plain[k], dv);
        }
    }
}
