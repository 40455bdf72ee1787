//! Fitting problems: a model, the parameters to identify and a recording whose current drives
//! the model; the simulated voltage at the recorded times, with forward sensitivities.

use std::sync::Mutex;

use super::delay::{DelayedTimes, delay_at, is_delay};
use super::fit_parameter::apply;
pub use super::fit_parameter::{FitParameter, INITIAL_SOC};
use super::history::{history_step, state_after};
pub use super::model_spec::ModelSpec;
use super::sensitivity::{PARAMETER_STEP, Sensitivities};
use crate::data::Recording;
use crate::error::Error;
use crate::models::{Model, ModelBuilder};
use crate::params::ParameterSet;
use crate::protocol::Protocol;
use crate::simulation::{Integrals, SimOptions, Solution, States, simulate, simulate_observed};
use crate::solver::{SolverOptions, Workspace};

/// Voltage window (V) of a replayed recording: no cell cut-off ends a replay, but a model
/// whose voltage leaves this window has broken down.
pub const REPLAY_WINDOW: (f64, f64) = (0.0, 100.0);

/// Simulated voltage at the recorded points and, optionally, its sensitivities.
#[derive(Clone, Debug, Default)]
pub struct Simulated {
    /// Model voltage (V) at every recorded point.
    pub voltage: Vec<f64>,
    /// `dV_i/dθ_k` (V per parameter unit) when requested: row-major, one row of
    /// [`FittingProblem::dim`] values per recorded point (see [`Simulated::sensitivity_rows`]).
    pub sensitivity: Vec<f64>,
    /// Columns of [`Simulated::sensitivity`]: the number of fitted parameters (0 without).
    pub columns: usize,
    /// Model temperature (K) at every recorded point when the temperature is fitted
    /// ([`FittingProblem::fitting_temperature`]); empty otherwise.
    pub temperature: Vec<f64>,
}

impl Simulated {
    /// The rows `dV_i/dθ` of [`Simulated::sensitivity`], one per recorded point.
    pub fn sensitivity_rows(&self) -> std::slice::ChunksExact<'_, f64> {
        self.sensitivity.chunks_exact(self.columns.max(1))
    }
}

/// Builders re-used across evaluations: the model at θ and one copy per parameter at θ + δ.
struct Worker {
    builders: Vec<ModelBuilder>,
    sensitivity_workspace: Option<Workspace>,
}

/// A model, the parameters to identify, and a recording.
pub struct FittingProblem {
    pub spec: ModelSpec,
    pub base: ParameterSet,
    pub parameters: Vec<FitParameter>,
    pub data: Recording,
    /// Non-negative weight of each recorded point in costs (0 leaves it out).
    pub weights: Vec<f64>,
    pub solver: SolverOptions,
    /// Open-circuit voltage (V) of the initial state, set before the fitted parameters (which
    /// may still override the initial concentrations); `None` keeps the set's initial state.
    pub initial_ocv: Option<f64>,
    protocol: Protocol,
    /// Parameters held at a value (a profile's fixed one), applied with the fitted ones.
    pinned: Vec<(FitParameter, f64)>,
    /// Weight (V/K) of the recorded temperature's residuals beside the voltage's in costs,
    /// when the temperature is fitted too.
    temperature_weight: Option<f64>,
    /// The recorded temperature the model's temperature follows (times from the start, K).
    temperature_input: Option<std::sync::Arc<(Vec<f64>, Vec<f64>)>>,
    /// Whether the voltage's residuals enter the costs (false: the temperature alone is fitted).
    voltage_fitted: bool,
    /// Distinct output times (s, from the recording's start) and each point's output index.
    t_eval: Vec<f64>,
    output_of_point: Vec<usize>,
    pool: Mutex<Vec<Worker>>,
}

impl FittingProblem {
    /// Validates the parameters against `base` and derives the protocol from the recorded
    /// current. Points at a repeated time (either side of a current jump) get weight 0.
    pub fn new(spec: ModelSpec, base: ParameterSet, parameters: Vec<FitParameter>, data: Recording) -> Result<Self, Error> {
        base.validate()?;
        for p in &parameters {
            p.validate(&base)?;
        }
        if let Some((k, _)) = parameters.iter().enumerate().find(|(k, p)| parameters[..*k].iter().any(|q| q.path == p.path)) {
            return Err(Error::InvalidSetting { field: format!("parameters.{}", parameters[k].path), reason: "listed twice".into() });
        }
        let n = data.time.len();
        if n < 2 || data.current.len() != n || data.voltage.len() != n {
            return Err(Error::InvalidSetting {
                field: "data".into(),
                reason: format!("needs at least 2 points with time, current and voltage each ({n} times)"),
            });
        }
        if let Some(k) = (0..n).find(|&k| !(data.time[k].is_finite() && data.current[k].is_finite() && data.voltage[k].is_finite())) {
            return Err(Error::invalid("data", data.time[k], format!("point {k} has a non-finite time, current or voltage")));
        }
        if let Some(k) = data.time.windows(2).position(|w| !(w[1] >= w[0])) {
            return Err(Error::invalid("data.time", data.time[k + 1], format!("decreases at point {}", k + 1)));
        }
        let t0 = data.time[0];
        let mut t_eval: Vec<f64> = Vec::with_capacity(n);
        let mut output_of_point = Vec::with_capacity(n);
        for &t in &data.time {
            if t_eval.last() != Some(&(t - t0)) {
                t_eval.push(t - t0);
            }
            output_of_point.push(t_eval.len() - 1);
        }
        let weights = (0..n).map(|k| if data.is_repeated(k) { 0.0 } else { 1.0 }).collect();
        let protocol = data.protocol();
        protocol.validate()?;
        let problem = Self {
            spec,
            base,
            parameters,
            data,
            weights,
            solver: SolverOptions::default(),
            initial_ocv: None,
            protocol,
            pinned: Vec::new(),
            temperature_weight: None,
            temperature_input: None,
            voltage_fitted: true,
            t_eval,
            output_of_point,
            pool: Mutex::new(Vec::new()),
        };
        match spec.recorded_temperature {
            true => problem.following_recorded_temperature(),
            false => Ok(problem),
        }
    }

    /// The same problem with fitted parameter `k` held at `value` (parameter units) and the
    /// others still fitted, e.g. for a profile likelihood.
    pub fn pinned(&self, k: usize, value: f64) -> Result<Self, Error> {
        let mut parameters = self.parameters.clone();
        let fixed = parameters.remove(k);
        if !(value >= fixed.lower && value <= fixed.upper) {
            return Err(Error::invalid(fixed.path.clone(), value, format!("must lie within [{}, {}] to be held", fixed.lower, fixed.upper)));
        }
        let mut pinned = self.pinned.clone();
        pinned.push((fixed, value));
        Ok(Self {
            spec: self.spec,
            base: self.base.clone(),
            parameters,
            data: self.data.clone(),
            weights: self.weights.clone(),
            solver: self.solver.clone(),
            initial_ocv: self.initial_ocv,
            protocol: self.protocol.clone(),
            pinned,
            temperature_weight: self.temperature_weight,
            temperature_input: self.temperature_input.clone(),
            voltage_fitted: self.voltage_fitted,
            t_eval: self.t_eval.clone(),
            output_of_point: self.output_of_point.clone(),
            pool: Mutex::new(Vec::new()),
        })
    }

    /// Applies the fitted values `x` and the pinned ones to `p` (the initial state of charge
    /// last, as it depends on the others).
    fn apply_all(&self, p: &mut ParameterSet, x: &[f64]) -> Result<(), Error> {
        let (fixed, values): (Vec<FitParameter>, Vec<f64>) = self.pinned.iter().cloned().unzip();
        apply(p, &[self.parameters.as_slice(), &fixed].concat(), &[x, &values].concat())
    }

    /// Starts from the rest state whose open-circuit voltage is the first recorded voltage
    /// (a recording that begins after a long rest). Errors if the first current is not zero.
    pub fn starting_at_rest(mut self) -> Result<Self, Error> {
        if self.data.current[0] != 0.0 {
            return Err(Error::invalid("data.current", self.data.current[0], "must be 0 at the first point to start at rest"));
        }
        let v = self.data.voltage[0];
        self.base.clone().set_initial_ocv(v)?;
        self.initial_ocv = Some(v);
        Ok(self)
    }

    /// Drives the model by `protocol` instead of the recorded current (e.g. the set points of
    /// the cycler's schedule). Its duration must reach the last recorded time.
    pub fn with_protocol(mut self, protocol: Protocol) -> Result<Self, Error> {
        protocol.validate()?;
        let span = self.t_eval.last().copied().unwrap_or(0.0);
        if !(protocol.duration() >= span) {
            return Err(Error::invalid("protocol", protocol.duration(), format!("lasts less than the recording ({span} s)")));
        }
        self.protocol = protocol;
        Ok(self)
    }

    /// Restricts costs to points with positive weight (e.g. a training window); the model
    /// still runs through the whole recording. Points at a repeated time stay out.
    pub fn with_weights(mut self, weights: Vec<f64>) -> Result<Self, Error> {
        if weights.len() != self.data.time.len() {
            return Err(Error::InvalidSetting {
                field: "weights".into(),
                reason: format!("{} weights for {} recorded points", weights.len(), self.data.time.len()),
            });
        }
        if let Some(w) = weights.iter().find(|w| !(**w >= 0.0 && w.is_finite())) {
            return Err(Error::invalid("weights", *w, "must be non-negative and finite"));
        }
        for (k, w) in weights.into_iter().enumerate() {
            self.weights[k] = if self.data.is_repeated(k) { 0.0 } else { w };
        }
        if self.weights.iter().all(|&w| w == 0.0) {
            return Err(Error::InvalidSetting { field: "weights".into(), reason: "leave no point in the cost".into() });
        }
        Ok(self)
    }

    /// Fits the recorded temperature beside the voltage, each temperature residual (K)
    /// counted as `weight` (V/K) times it (the voltage noise over the temperature noise
    /// weighs both as their likelihoods do). Needs a recorded temperature and a thermal model.
    pub fn fitting_temperature(mut self, weight: f64) -> Result<Self, Error> {
        if self.data.temperature.is_none() {
            return Err(Error::InvalidSetting { field: "data.temperature".into(), reason: "no temperature recorded to fit".into() });
        }
        if !self.spec.submodels.thermal {
            return Err(Error::InvalidSetting { field: "model.submodels.thermal".into(), reason: "only a thermal model predicts the temperature".into() });
        }
        if self.temperature_input.is_some() {
            return Err(Error::InvalidSetting { field: "model.recorded_temperature".into(), reason: "the model's temperature follows the recording: there is no temperature to fit".into() });
        }
        if !(weight > 0.0 && weight.is_finite()) {
            return Err(Error::invalid("temperature_weight", weight, "must be positive and finite"));
        }
        self.temperature_weight = Some(weight);
        Ok(self)
    }

    /// Runs the model at the recorded temperature: its temperature state follows the
    /// recording's (`simulation::TEMPERATURE_LAG`) in place of its heat balance, so every
    /// temperature dependence of the set sees the cell's measured temperature. Needs a recorded
    /// temperature and a thermal model (which supplies the temperature state).
    fn following_recorded_temperature(mut self) -> Result<Self, Error> {
        let Some(temps) = self.data.temperature.clone() else {
            return Err(Error::InvalidSetting { field: "data.temperature".into(), reason: "no temperature recorded to follow".into() });
        };
        if !self.spec.submodels.thermal {
            return Err(Error::InvalidSetting { field: "model.submodels.thermal".into(), reason: "the temperature is a state of the thermal submodel only".into() });
        }
        let t0 = self.data.time[0];
        let times = self.data.time.iter().map(|t| t - t0).collect();
        self.temperature_input = Some(std::sync::Arc::new((times, temps)));
        Ok(self)
    }

    /// Fits the recorded temperature alone (K residuals): the voltage drives the heat but its
    /// residuals leave the costs (a thermal parameter fitted on an electrochemistry fitted
    /// before). Needs a recorded temperature and a thermal model.
    pub fn fitting_temperature_only(self) -> Result<Self, Error> {
        let mut problem = self.fitting_temperature(1.0)?;
        problem.voltage_fitted = false;
        Ok(problem)
    }

    /// Residuals per recorded point in the costs: the voltage's, the temperature's, or both.
    pub fn residuals_per_point(&self) -> usize {
        usize::from(self.voltage_fitted) + usize::from(self.temperature_weight.is_some())
    }

    /// Residuals (in recording order) whose serial correlation the fit reports: the
    /// voltage's `V_model - V_data` (V), or the temperature's (K) when it is fitted alone.
    pub fn fitted_residuals(&self, outputs: &Simulated) -> Vec<f64> {
        match (&self.data.temperature, self.voltage_fitted) {
            (Some(recorded), false) => outputs.temperature.iter().zip(recorded).map(|(m, d)| m - d).collect(),
            _ => self.residuals(&outputs.voltage),
        }
    }

    /// Number of fitted model parameters.
    pub fn dim(&self) -> usize {
        self.parameters.len()
    }

    /// Initial values of the fitted parameters.
    pub fn initial(&self) -> Vec<f64> {
        self.parameters.iter().map(|p| p.initial).collect()
    }

    /// The parameter set at `x` (one value per fitted parameter), validated.
    pub fn parameters_at(&self, x: &[f64]) -> Result<ParameterSet, Error> {
        if x.len() != self.dim() {
            return Err(Error::InvalidSetting {
                field: "x".into(),
                reason: format!("{} values for {} fitted parameters", x.len(), self.dim()),
            });
        }
        let mut p = self.base.clone();
        if let Some(v) = self.initial_ocv {
            p.set_initial_ocv(v)?;
        }
        self.apply_all(&mut p, x)?;
        p.validate()?;
        Ok(p)
    }

    /// Why the model cannot replay `what` (the recording, named for the user) at parameters
    /// `x`, as an error that names the values; `None` when it can.
    pub fn unreplayable(&self, x: &[f64], what: &str) -> Option<Error> {
        Some(self.start_failure(x, what, self.simulate(x).err()?))
    }

    /// The error `why` of a replay of `what` at the start values `x`, with those values and
    /// the likely fix (see [`FittingProblem::unreplayable`]).
    pub fn start_failure(&self, x: &[f64], what: &str, why: Error) -> Error {
        let values: Vec<String> = self.parameters.iter().zip(x).map(|(p, v)| format!("{} = {v:.6e}", p.path)).collect();
        Error::InvalidSetting {
            field: format!("{what} at the start values"),
            reason: format!(
                "the model cannot replay it from {}: {why} (a model cell that empties before the recording ends needs a higher starting state of charge: raise the initial value of initial_soc)",
                values.join(", ")
            ),
        }
    }

    /// Model voltage (V) at every recorded point.
    pub fn simulate(&self, x: &[f64]) -> Result<Vec<f64>, Error> {
        Ok(self.run(x, false)?.voltage)
    }

    /// Model voltage (V) and, when it is fitted, temperature (K) at every recorded point.
    pub fn simulate_outputs(&self, x: &[f64]) -> Result<Simulated, Error> {
        self.run(x, false)
    }

    /// Model voltage and its forward sensitivities to the fitted parameters.
    pub fn simulate_with_sensitivities(&self, x: &[f64]) -> Result<Simulated, Error> {
        self.run(x, true)
    }

    fn options(&self, p: &ParameterSet) -> SimOptions {
        SimOptions {
            solver: self.solver.clone(),
            t_eval: Some(self.t_eval.clone()),
            states: States::ForOutputs,
            // Recordings are replayed whole: cut-offs do not end them.
            cutoffs: REPLAY_WINDOW,
            capacity: p.cell.nominal_capacity,
            // Only the voltage (and temperature) at the recorded times is compared.
            integrals: Integrals::Off,
            temperature_input: self.temperature_input.clone(),
        }
    }

    /// The replay's options, its output times those of `delayed` when the voltage channel's
    /// delay is fitted.
    fn options_with(&self, p: &ParameterSet, delayed: Option<&DelayedTimes>) -> SimOptions {
        let opts = self.options(p);
        match delayed {
            Some(d) => SimOptions { t_eval: Some(d.times.clone()), ..opts },
            None => opts,
        }
    }

    /// The output times with the voltage channel's delay at `x`, when one is fitted.
    fn delayed(&self, x: &[f64]) -> Option<DelayedTimes> {
        delay_at(&self.parameters, x, &self.pinned).map(|tau| DelayedTimes::new(&self.t_eval, tau))
    }

    /// The load before the recording at `x`, when one is fitted.
    fn history(&self, x: &[f64]) -> Result<Option<crate::protocol::Step>, Error> {
        history_step(&self.parameters, x, &self.pinned)
    }

    fn run(&self, x: &[f64], sensitivities: bool) -> Result<Simulated, Error> {
        let p = self.parameters_at(x)?;
        let mut worker = self.pool.lock().expect("builder pool").pop().unwrap_or_else(|| Worker {
            builders: (0..=self.dim()).map(|_| self.spec.builder()).collect(),
            sensitivity_workspace: None,
        });
        let result = if sensitivities { self.run_sensitivities(&mut worker, x, &p) } else { self.run_plain(&mut worker, x, &p, None) };
        self.pool.lock().expect("builder pool").push(worker);
        result
    }

    /// The replay at `x`, handing `watch` the model, its whole state and the current (A) at
    /// every output time: what the model does beyond its voltage (e.g. its plating margin).
    pub fn replay_watching(&self, x: &[f64], watch: &mut dyn FnMut(&dyn Model, &[f64], f64)) -> Result<Simulated, Error> {
        let p = self.parameters_at(x)?;
        let mut worker = Worker { builders: vec![self.spec.builder()], sensitivity_workspace: None };
        self.run_plain(&mut worker, x, &p, Some(watch))
    }

    /// The replay at `x`; with `watch`, every state is handed to it (not stored).
    fn run_plain(&self, worker: &mut Worker, x: &[f64], p: &ParameterSet, watch: Option<&mut dyn FnMut(&dyn Model, &[f64], f64)>) -> Result<Simulated, Error> {
        let built = worker.builders[0].build(p)?;
        let delayed = self.delayed(x);
        let opts = SimOptions { states: if watch.is_some() { States::Observed } else { States::ForOutputs }, ..self.options_with(p, delayed.as_ref()) };
        let y0 = match self.history(x)? {
            Some(step) => Some(state_after(built.model.as_ref(), &mut built.workspace, &step, &opts)?),
            None => None,
        };
        let model = built.model.as_ref();
        let sol = match watch {
            Some(watch) => simulate_observed(model, &mut built.workspace, &self.protocol, &opts, y0, &mut |y, i| watch(model, y, i))?,
            None => simulate(model, &mut built.workspace, &self.protocol, &opts, y0)?,
        };
        let voltage = self.at_points(&sol, delayed.as_ref())?;
        let temperature = match self.temperature_weight {
            Some(_) => self.output_of_point.iter().map(|&k| sol.temperature[delayed.as_ref().map_or(k, |d| d.plain_at[k])]).collect(),
            None => Vec::new(),
        };
        Ok(Simulated { voltage, sensitivity: Vec::new(), columns: 0, temperature })
    }

    fn run_sensitivities(&self, worker: &mut Worker, x: &[f64], p: &ParameterSet) -> Result<Simulated, Error> {
        let scales: Vec<f64> = x.iter().map(|v| if *v != 0.0 { v.abs() } else { 1.0 }).collect();
        // A step beyond the upper bound may leave the parameter's domain (an initial state of
        // charge of 1 + 1e-7): step inwards there.
        let steps: Vec<f64> = scales
            .iter()
            .zip(x)
            .zip(&self.parameters)
            .map(|((s, v), p)| if v + PARAMETER_STEP * s > p.upper { -PARAMETER_STEP * s } else { PARAMETER_STEP * s })
            .collect();
        let (first, rest) = worker.builders.split_at_mut(1);
        let delayed = self.delayed(x);
        let opts = self.options_with(p, delayed.as_ref());
        let history = self.history(x)?;
        let base = first[0].build(p)?;
        // With a load before the recording, every copy starts where its own history ends.
        let base_start = match &history {
            Some(step) => Some(state_after(base.model.as_ref(), &mut base.workspace, step, &opts)?),
            None => None,
        };
        let mut perturbed: Vec<&dyn Model> = Vec::with_capacity(rest.len());
        let mut starts: Vec<Vec<f64>> = Vec::new();
        for (k, b) in rest.iter_mut().enumerate() {
            let mut q = self.base.clone();
            if let Some(v) = self.initial_ocv {
                q.set_initial_ocv(v)?;
            }
            let mut xk = x.to_vec();
            xk[k] += steps[k];
            self.apply_all(&mut q, &xk)?;
            let built = b.build(&q)?;
            if base_start.is_some() {
                let step = self.history(&xk)?.expect("the history is fitted");
                starts.push(state_after(built.model.as_ref(), &mut built.workspace, &step, &opts)?);
            }
            perturbed.push(built.model.as_ref());
        }
        let model = Sensitivities::new(base.model.as_ref(), perturbed, scales.clone(), steps);
        let z0 = match base_start {
            Some(y) => model.augmented(y, &starts),
            None => model.initial_state(),
        };
        let ws = match &mut worker.sensitivity_workspace {
            Some(ws) => ws,
            slot => slot.insert(Workspace::new(model.len(), model.jacobian_pattern())?),
        };
        // Only dV/dθ at each output is kept, never the augmented state: memory stays flat for
        // a 10^6-point recording.
        let mut rows: Vec<f64> = Vec::with_capacity(self.t_eval.len() * scales.len());
        let mut derive = |z: &[f64], i: f64| rows.extend(model.voltage_sensitivities(z, i).iter().zip(&scales).map(|(d, s)| d / s));
        let sol = simulate_observed(&model, ws, &self.protocol, &opts, Some(z0), &mut derive)?;
        let voltage = self.at_points(&sol, delayed.as_ref())?;
        let dim = scales.len();
        // Read with a delay, each point's row is the one at its shifted time, and the delay's
        // column (which no model copy changes) is minus the voltage's slope there.
        let (row_of, delay_column): (Vec<usize>, Option<(usize, Vec<f64>)>) = match &delayed {
            Some(d) => (d.voltage_at.clone(), self.parameters.iter().position(|q| is_delay(&q.path)).map(|k| (k, d.delay_sensitivity(&sol.voltage)))),
            None => ((0..self.t_eval.len()).collect(), None),
        };
        let sensitivity = self
            .output_of_point
            .iter()
            .flat_map(|&k| {
                let mut row = rows[row_of[k] * dim..(row_of[k] + 1) * dim].to_vec();
                if let Some((column, slope)) = &delay_column {
                    row[*column] = slope[k];
                }
                row
            })
            .collect();
        Ok(Simulated { voltage, sensitivity, columns: dim, temperature: Vec::new() })
    }

    /// Maps outputs at the distinct times (shifted by the voltage channel's delay when one is
    /// fitted) onto the recorded points; errors if the replay ended early, saying why.
    fn at_points(&self, sol: &Solution, delayed: Option<&DelayedTimes>) -> Result<Vec<f64>, Error> {
        let expected = delayed.map_or(self.t_eval.len(), |d| d.times.len());
        if sol.time.len() != expected {
            // Where the model broke down (its voltage left the window), else where it stopped:
            // a caller that cuts the recording there must cut before the breakdown, not after.
            let t = sol.cutoff_times.first().or(sol.time.last()).copied().unwrap_or(0.0);
            let why = match sol.cutoff_times.first() {
                Some(tc) => format!(
                    "the model's voltage left ({}, {}) V at t = {tc:.1} s (a concentration at its limit: the model breaks down there)",
                    REPLAY_WINDOW.0, REPLAY_WINDOW.1
                ),
                None => "the simulation ended early".into(),
            };
            return Err(Error::Solver { t, reason: format!("{why}; {} of {expected} output times simulated", sol.time.len()) });
        }
        Ok(self.output_of_point.iter().map(|&k| sol.voltage[delayed.map_or(k, |d| d.voltage_at[k])]).collect())
    }

    /// Residuals `V_model - V_data` (V) at every recorded point.
    pub fn residuals(&self, voltage: &[f64]) -> Vec<f64> {
        voltage.iter().zip(&self.data.voltage).map(|(m, d)| m - d).collect()
    }

    /// Weighted cost residuals of `outputs`: `sqrt(w) (V_model - V_data)` at every recorded
    /// point (unless the temperature is fitted alone), then `sqrt(w) c (T_model - T_data)` when
    /// the temperature is fitted with weight `c` (V/K).
    pub fn weighted_residuals(&self, outputs: &Simulated) -> Vec<f64> {
        let voltage = self.residuals(&outputs.voltage).into_iter().zip(&self.weights).map(|(r, w)| r * w.sqrt()).filter(|_| self.voltage_fitted);
        let temperature = match (self.temperature_weight, &self.data.temperature) {
            (Some(c), Some(recorded)) => outputs.temperature.iter().zip(recorded).zip(&self.weights).map(|((m, d), w)| c * (m - d) * w.sqrt()).collect(),
            _ => Vec::new(),
        };
        voltage.chain(temperature).collect()
    }

    /// Model builds so far, over all pooled builders (the perturbed copies included).
    pub fn rebuild_count(&self) -> usize {
        self.pool.lock().expect("builder pool").iter().flat_map(|w| &w.builders).map(|b| b.rebuild_count()).sum()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::models::{ModelKind, Submodels};

    fn recording(temperature: Option<Vec<f64>>) -> Recording {
        let time: Vec<f64> = (0..20).map(f64::from).collect();
        let current = vec![5.0; 20];
        let voltage = vec![3.9; 20];
        Recording { time, current, voltage, temperature }
    }

    #[test]
    fn a_temperature_is_fitted_only_when_recorded_and_predicted() {
        let p = crate::params::chen2020();
        let thermal = ModelSpec::new(ModelKind::Spm, Submodels { thermal: true, ..Submodels::default() });
        let isothermal = ModelSpec::new(ModelKind::Spm, Submodels::default());
        let fit = |spec, t| FittingProblem::new(spec, p.clone(), Vec::new(), recording(t)).expect("problem");
        let err = fit(thermal, None).fitting_temperature(0.01).err().expect("no temperature").to_string();
        assert!(err.contains("data.temperature"), "{err}");
        let err = fit(isothermal, Some(vec![298.15; 20])).fitting_temperature(0.01).err().expect("isothermal").to_string();
        assert!(err.contains("model.submodels.thermal"), "{err}");
        let err = fit(thermal, Some(vec![298.15; 20])).fitting_temperature(f64::NAN).err().expect("NaN weight").to_string();
        assert!(err.contains("temperature_weight"), "{err}");
        // Fitted: the weighted temperature residuals follow the voltage's, c (T_model - T_data).
        let recorded: Vec<f64> = (0..20).map(|k| 298.15 + 0.1 * k as f64).collect();
        let problem = fit(thermal, Some(recorded.clone())).fitting_temperature(0.01).expect("fitted temperature");
        let outputs = problem.simulate_outputs(&[]).expect("simulates");
        assert_eq!(outputs.temperature.len(), 20);
        let r = problem.weighted_residuals(&outputs);
        assert_eq!(r.len(), 40);
        let k = 7;
        let expected = 0.01 * (outputs.temperature[k] - recorded[k]) * problem.weights[k].sqrt();
        assert!((r[20 + k] - expected).abs() < 1e-15, "{} vs {expected}", r[20 + k]);
        assert_eq!(problem.residuals_per_point(), 2);
        // Fitted alone: only the temperature's residuals (K), and they are the ones reported.
        let alone = fit(thermal, Some(recorded.clone())).fitting_temperature_only().expect("temperature alone");
        let r = alone.weighted_residuals(&outputs);
        assert_eq!((r.len(), alone.residuals_per_point()), (20, 1));
        assert!((r[k] - (outputs.temperature[k] - recorded[k]) * alone.weights[k].sqrt()).abs() < 1e-15);
        assert_eq!(alone.fitted_residuals(&outputs)[k], outputs.temperature[k] - recorded[k]);
    }
}
