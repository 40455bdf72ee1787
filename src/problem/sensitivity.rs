//! Forward sensitivities of a discretised model: the state is augmented with
//! `s_k = p̄_k dy/dθ_k` for each fitted parameter `θ_k` (scale `p̄_k = |θ_k|`, or 1 at zero),
//! which obey `M s_k' = J s_k + p̄_k df/dθ_k` and are integrated with the states under the same
//! error control. As in CVODES's difference-quotient option, `J s_k` is a directional
//! difference of the right-hand side and `df/dθ_k` a difference between the model and a copy
//! built at `θ_k + δ_k`, so every model (and submodel) gets sensitivities without hand-written
//! derivatives, and gradients are smooth in the parameters (unlike differences of two
//! adaptively stepped simulations).

use std::sync::Mutex;

use crate::models::Model;

/// Relative parameter step of the perturbed copies.
pub const PARAMETER_STEP: f64 = 1e-7;

/// Difference step of a Jacobian column of a sensitivity block, relative to the state scale.
/// The sensitivity equations are linear in `s`, so a step this large costs no truncation
/// error, while `J s`, itself a directional difference, carries rounding noise (about
/// `eps^(2/3)` of its size, `sqrt(eps)` when it was one-sided): a column step of `sqrt(eps)`
/// of the scale, as for the states, left those columns order-one noise (a DFN fit of the
/// initial state of charge had Newton diverge at a current step).
const SENSITIVITY_COLUMN_STEP: f64 = 1e-2;

/// A model with its forward sensitivities appended to the state.
pub struct Sensitivities<'a> {
    base: &'a dyn Model,
    /// The model built at `θ_k + δ_k`, one per parameter.
    perturbed: Vec<&'a dyn Model>,
    /// Parameter scales `p̄_k` and steps `δ_k` (parameter units; negative at an upper bound).
    scales: Vec<f64>,
    steps: Vec<f64>,
    mass: Vec<f64>,
    scale: Vec<f64>,
    /// Floors of the Jacobian's difference steps: the base model's widened to a step of
    /// `eps^(1/3)`, then the sensitivity blocks' at [`SENSITIVITY_COLUMN_STEP`].
    difference_scale: Vec<f64>,
    /// `eps^(1/3)`: the relative step of the central `J s` and of the states' Jacobian columns.
    central_step: f64,
    /// The base model's output states (what its voltage reads).
    outputs: Vec<usize>,
    scratch: Mutex<(Vec<f64>, Vec<f64>, Vec<f64>)>,
}

impl<'a> Sensitivities<'a> {
    /// `perturbed[k]` must be `base` rebuilt with parameter `k` moved by `steps[k]` (either
    /// sign).
    pub fn new(base: &'a dyn Model, perturbed: Vec<&'a dyn Model>, scales: Vec<f64>, steps: Vec<f64>) -> Self {
        let n = base.len();
        let blocks = 1 + perturbed.len();
        let mass = base.mass().repeat(blocks);
        let scale = base.scale().repeat(blocks);
        let widen = SENSITIVITY_COLUMN_STEP / f64::EPSILON.sqrt();
        // The states' columns also carry the sensitivity rows' dependence on `y` (through
        // `J(y) s`), a difference of the central `J s`, whose noise is about eps^(2/3): a step
        // of eps^(1/3) of the scale balances that noise against the truncation error of the
        // base rows (a modified Newton's matrix need not be more exact).
        let central_step = f64::EPSILON.cbrt();
        let state_step = central_step / f64::EPSILON.sqrt();
        let difference_scale = base.difference_scale().iter().map(|s| state_step * s).chain(scale[n..].iter().map(|s| widen * s)).collect();
        let outputs = base.output_states();
        Self { base, perturbed, scales, steps, mass, scale, difference_scale, central_step, outputs, scratch: Mutex::new((vec![0.0; n], vec![0.0; n], vec![0.0; n])) }
    }

    fn n(&self) -> usize {
        self.base.len()
    }

    /// Directional-difference step for `J s` so that `ε s` is `relative` of the state scale
    /// (`sqrt(eps)` for a one-sided difference, `eps^(1/3)` for a central one), measured over
    /// the states `rows` (all of them for the right-hand side, the output states for the
    /// voltage).
    fn direction_step(&self, s: &[f64], rows: impl ExactSizeIterator<Item = usize>, relative: f64) -> Option<f64> {
        let n = rows.len().max(1) as f64;
        let scale = self.base.scale();
        let wrms = (rows.map(|j| (s[j] / scale[j]).powi(2)).sum::<f64>() / n).sqrt();
        (wrms > 0.0).then(|| relative / wrms)
    }

    /// Initial augmented state: the base model's, with `s_k(0) = p̄_k dy0/dθ_k`.
    pub fn initial_state(&self) -> Vec<f64> {
        let perturbed: Vec<Vec<f64>> = self.perturbed.iter().map(|m| m.initial_state()).collect();
        self.augmented(self.base.initial_state(), &perturbed)
    }

    /// The augmented state of base state `y` and the perturbed copies' states `perturbed`
    /// (one per parameter, each reached as `y` was, at its own parameter values).
    pub fn augmented(&self, y: Vec<f64>, perturbed: &[Vec<f64>]) -> Vec<f64> {
        let mut z = y.clone();
        for (k, yk) in perturbed.iter().enumerate() {
            let f = self.scales[k] / self.steps[k];
            z.extend(yk.iter().zip(&y).map(|(a, b)| f * (a - b)));
        }
        z
    }

    /// `p̄_k dV/dθ_k` at augmented state `z` and current `i` (A), for every parameter. Reads
    /// only the output states of each block ([`Model::output_states`]), as the voltage does.
    pub fn voltage_sensitivities(&self, z: &[f64], i: f64) -> Vec<f64> {
        let n = self.n();
        let y = &z[..n];
        let v = self.base.voltage(y, i);
        let mut buf = y.to_vec();
        (0..self.perturbed.len())
            .map(|k| {
                let s = &z[(k + 1) * n..(k + 2) * n];
                // Directional difference along s, over the states the voltage reads.
                let direct = if let Some(eps) = self.direction_step(s, self.outputs.iter().copied(), f64::EPSILON.sqrt()) {
                    for &j in &self.outputs {
                        buf[j] = y[j] + eps * s[j];
                    }
                    (self.base.voltage(&buf, i) - v) / eps
                } else {
                    0.0
                };
                for &j in &self.outputs {
                    buf[j] = y[j];
                }
                direct + self.scales[k] * (self.perturbed[k].voltage(y, i) - v) / self.steps[k]
            })
            .collect()
    }
}

impl Model for Sensitivities<'_> {
    fn name(&self) -> String {
        format!("{} with {} sensitivities", self.base.name(), self.perturbed.len())
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
    fn difference_scale(&self) -> &[f64] {
        &self.difference_scale
    }
    /// Block lower triangular: each sensitivity block has the model's pattern on its own
    /// states and on the states `y` (through `J(y) s`).
    fn jacobian_pattern(&self) -> Vec<(usize, usize)> {
        let n = self.n();
        let base = self.base.jacobian_pattern();
        let mut pattern = base.clone();
        for b in 1..=self.perturbed.len() {
            for &(r, c) in &base {
                pattern.push((b * n + r, b * n + c));
                pattern.push((b * n + r, c));
            }
        }
        pattern
    }
    fn initial_state(&self) -> Vec<f64> {
        Sensitivities::initial_state(self)
    }
    /// The base model's output states in every block: all that
    /// [`Sensitivities::voltage_sensitivities`] reads.
    fn output_states(&self) -> Vec<usize> {
        let n = self.n();
        (0..=self.perturbed.len()).flat_map(|b| self.outputs.iter().map(move |&j| b * n + j)).collect()
    }
    fn rhs(&self, z: &[f64], current: f64, out: &mut [f64]) {
        let n = self.n();
        let y = &z[..n];
        let (f0, rest) = out.split_at_mut(n);
        self.base.rhs(y, current, f0);
        let mut guard = self.scratch.lock().expect("sensitivity scratch");
        let (shifted, fa, fb) = &mut *guard;
        for (k, m) in self.perturbed.iter().enumerate() {
            let s = &z[(k + 1) * n..(k + 2) * n];
            let o = &mut rest[k * n..(k + 1) * n];
            m.rhs(y, current, fb);
            let f = self.scales[k] / self.steps[k];
            for j in 0..n {
                o[j] = f * (fb[j] - f0[j]);
            }
            // Central: J s to about eps^(2/3) instead of sqrt(eps), below the corrector's
            // tolerance on the algebraic rows (a DFN's potentials).
            if let Some(eps) = self.direction_step(s, 0..s.len(), self.central_step) {
                for j in 0..n {
                    shifted[j] = y[j] + eps * s[j];
                }
                self.base.rhs(shifted, current, fa);
                for j in 0..n {
                    shifted[j] = y[j] - eps * s[j];
                }
                self.base.rhs(shifted, current, fb);
                for j in 0..n {
                    o[j] += (fa[j] - fb[j]) / (2.0 * eps);
                }
            }
        }
    }
    fn voltage(&self, z: &[f64], current: f64) -> f64 {
        self.base.voltage(&z[..self.n()], current)
    }
    fn temperature(&self, z: &[f64]) -> f64 {
        self.base.temperature(&z[..self.n()])
    }
    /// The base model's temperature follows the recording; its sensitivities decay to zero.
    fn temperature_rows(&self) -> Vec<(usize, f64)> {
        let n = self.n();
        self.base.temperature_state().map_or_else(Vec::new, |k| (0..=self.perturbed.len()).map(|b| (b * n + k, if b == 0 { 1.0 } else { 0.0 })).collect())
    }
    fn solid_lithium(&self, z: &[f64]) -> f64 {
        self.base.solid_lithium(&z[..self.n()])
    }
    fn open_circuit_voltage(&self, z: &[f64]) -> f64 {
        self.base.open_circuit_voltage(&z[..self.n()])
    }
}
