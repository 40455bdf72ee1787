//! Runs a model through a protocol: consistent initialisation of algebraic states at every
//! step start, stiff integration, cut-off events, and the recorded outputs. Voltage holds
//! append the current to the states ([`hold`]); [`cycling`] repeats a cycle with summaries.

pub mod cycling;
mod demand;
mod drive;
mod hold;
mod record;

use serde::Serialize;

use crate::error::Error;
use crate::models::Model;
use crate::protocol::{Protocol, Step};
pub(crate) use drive::UnderCurrent;
use demand::StepStart;
use drive::Driven;
use record::Recorder;
use crate::solver::{DenseOutput, SolverOptions, SolverStats, Workspace, integrate};

/// Options of a simulation.
#[derive(Clone, Debug)]
pub struct SimOptions {
    pub solver: SolverOptions,
    /// Output times (s), increasing. `None` records every solver step.
    pub t_eval: Option<Vec<f64>>,
    /// Which states are evaluated at each output, and whether they are stored.
    pub states: States,
    /// Lower and upper voltage cut-offs (V).
    pub cutoffs: (f64, f64),
    /// Nominal capacity (A h) that converts C-rates to amperes.
    pub capacity: f64,
    /// How the charge and energy are integrated and recorded.
    pub integrals: Integrals,
    /// A recorded cell temperature (times in s from the start, temperatures in K) that the
    /// model's temperature state follows (`dT/dt = (T_rec(t) - T) / TEMPERATURE_LAG`) in place
    /// of its heat balance; needs a thermal submodel.
    pub temperature_input: Option<std::sync::Arc<(Vec<f64>, Vec<f64>)>>,
}

impl SimOptions {
    /// Cut-offs and capacity of a parameter set, default solver, every step recorded.
    pub fn for_cell(p: &crate::params::ParameterSet) -> Self {
        Self {
            solver: SolverOptions::default(),
            t_eval: None,
            states: States::ForOutputs,
            cutoffs: (p.cell.lower_cutoff, p.cell.upper_cutoff),
            capacity: p.cell.nominal_capacity,
            integrals: Integrals::AtEveryOutput,
            temperature_input: None,
        }
    }
}

/// Which states a simulation evaluates at each output, and whether it stores them.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum States {
    /// Only those the voltage and temperature read ([`Model::output_states`]); none stored.
    ForOutputs,
    /// Every state, handed to the observer of [`simulate_observed`] but not stored: memory
    /// stays flat however many outputs there are.
    Observed,
    /// Every state, stored in [`Solution::states`] (spatial fields, conservation checks).
    Kept,
}

/// How a simulation integrates the charge (A h) and energy (W h) it records.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Integrals {
    /// Integrated up to every output time.
    AtEveryOutput,
    /// Integrated over every solver step; an output between steps records voltage, current
    /// and state at its time with the charge and energy of the last step's end (much cheaper
    /// when the outputs are dense, as for a recording sampled every second).
    AtStepEnds,
    /// The charge integrated as with [`Integrals::AtStepEnds`]; the energy recorded as NaN
    /// and the voltage not evaluated for it (cycling, whose summaries read only the charge).
    ChargeAtStepEnds,
    /// Not integrated: recorded as NaN, and their quadrature over every solver step skipped
    /// (a fifth to a quarter of an SPM's or SPMe's solve), for callers that read only the
    /// voltage, current and temperature, such as fits.
    Off,
}

/// Recorded outputs of a simulation.
#[derive(Clone, Debug, Default, Serialize)]
pub struct Solution {
    /// Time (s).
    pub time: Vec<f64>,
    /// Applied current (A, discharge positive).
    pub current: Vec<f64>,
    /// Terminal voltage (V).
    pub voltage: Vec<f64>,
    /// Charge discharged since the start (A h).
    pub capacity: Vec<f64>,
    /// Energy delivered since the start (W h).
    pub energy: Vec<f64>,
    /// Cell temperature (K).
    pub temperature: Vec<f64>,
    /// Full states at each output, when requested.
    #[serde(skip)]
    pub states: Vec<Vec<f64>>,
    /// Solver work counters.
    pub stats: SolverStats,
    /// Times (s) at which a voltage cut-off ended a step.
    pub cutoff_times: Vec<f64>,
    /// The full state at the end (where a following run starts).
    #[serde(skip)]
    pub final_state: Vec<f64>,
}

impl Solution {
    /// Discharged capacity at the end (A h).
    pub fn final_capacity(&self) -> f64 {
        self.capacity.last().copied().unwrap_or(0.0)
    }

    /// Delivered energy at the end (W h).
    pub fn final_energy(&self) -> f64 {
        self.energy.last().copied().unwrap_or(0.0)
    }

    /// Terminal voltage at the end (V).
    pub fn final_voltage(&self) -> f64 {
        self.voltage.last().copied().unwrap_or(f64::NAN)
    }

    /// Writes the outputs as CSV.
    pub fn write_csv(&self, path: &std::path::Path) -> Result<(), Error> {
        use std::fmt::Write;
        let mut s =
            String::from("time_s,current_A,voltage_V,discharge_capacity_Ah,energy_Wh,temperature_K\n");
        for i in 0..self.time.len() {
            let _ = writeln!(
                s,
                "{},{},{},{},{},{}",
                self.time[i],
                self.current[i],
                self.voltage[i],
                self.capacity[i],
                self.energy[i],
                self.temperature[i]
            );
        }
        crate::error::write_file(path, s)
    }
}

/// Solves the algebraic rows `f_alg(y) = 0` for the algebraic states by Newton's method,
/// holding the differential states fixed. Once an update is below `CHORD_FROM` (relative to
/// the state scales) and ten times smaller than the one before, the factorised Jacobian is kept
/// (chord iterations: one right-hand side and one solve each) while the updates keep shrinking
/// tenfold. Converged when an update is below `1e-12`, or below `NOISE_FLOOR` and no longer
/// halving with a fresh Jacobian: a right-hand side computed by differences (forward
/// sensitivities' directional derivatives `J s`) has a noise floor that Newton cannot go
/// below; far under the integrator's tolerances, whose corrector solves the algebraic rows
/// again at every step.
pub fn consistent_initialisation(
    model: &dyn Model,
    ws: &mut Workspace,
    current: f64,
    y: &mut [f64],
) -> Result<(), Error> {
    /// Largest update (relative to the state scales) after which the Jacobian is kept.
    const CHORD_FROM: f64 = 1e-3;
    /// Largest update (relative to the state scales) taken as the right-hand side's noise.
    const NOISE_FLOOR: f64 = 1e-6;
    let mass = model.mass();
    if mass.iter().all(|&m| m != 0.0) {
        return Ok(());
    }
    let n = y.len();
    let scale = model.scale();
    let mut f = vec![0.0; n];
    let mut dy = vec![0.0; n];
    let mut g = |yy: &[f64], out: &mut [f64]| model.rhs(yy, current, out);
    let mut refresh = true;
    let mut last = f64::INFINITY;
    for _ in 0..50 {
        g(y, &mut f);
        if refresh {
            ws.factorise_algebraic(&mut g, y, &f, model.difference_scale(), mass)?;
        }
        for ((d, v), &m) in dy.iter_mut().zip(&f).zip(mass) {
            *d = if m == 0.0 { -v } else { 0.0 };
        }
        ws.solve_algebraic(&mut dy);
        let mut step = 0.0f64;
        for i in 0..n {
            if mass[i] == 0.0 {
                y[i] += dy[i];
                // Not `f64::max`, which would drop a NaN.
                let r = (dy[i] / scale[i]).abs();
                step = if r > step || r.is_nan() { r } else { step };
            }
        }
        if !step.is_finite() {
            break;
        }
        if step < 1e-12 || (refresh && step < NOISE_FLOOR && step > 0.5 * last) {
            return Ok(());
        }
        refresh = !(step < CHORD_FROM && step < 0.1 * last);
        last = step;
    }
    Err(Error::Solver { t: 0.0, reason: "consistent initialisation of algebraic states did not converge".into() })
}

/// Simulates `model` through `protocol` from `y0` (or the model's initial state).
pub fn simulate(
    model: &dyn Model,
    ws: &mut Workspace,
    protocol: &Protocol,
    opts: &SimOptions,
    y0: Option<Vec<f64>>,
) -> Result<Solution, Error> {
    simulate_observed(model, ws, protocol, opts, y0, &mut |_, _| {})
}

/// [`simulate`], calling `on_output(y, current)` at every recorded output, in time order.
/// Unless `opts.states` is [`States::Observed`] or [`States::Kept`], only the model's [`Model::output_states`] of `y` are current
/// (the others hold stale values): derive from `y` only what the voltage reads. Keeps memory
/// flat for dense outputs (a 10^6-point recording) where kept states would not fit.
pub fn simulate_observed(
    model: &dyn Model,
    ws: &mut Workspace,
    protocol: &Protocol,
    opts: &SimOptions,
    y0: Option<Vec<f64>>,
    on_output: &mut dyn FnMut(&[f64], f64),
) -> Result<Solution, Error> {
    protocol.validate()?;
    let mut y = y0.unwrap_or_else(|| model.initial_state());
    let n = y.len();
    let (lower, upper) = opts.cutoffs;
    let t_eval = opts.t_eval.as_deref();
    if let Some(te) = t_eval {
        if let Some(w) = te.windows(2).find(|w| !(w[1] > w[0])) {
            return Err(Error::invalid("t_eval", w[1], "output times must increase strictly"));
        }
    }
    // Charge and energy start at zero, or are NaN throughout when not integrated.
    let integral = if opts.integrals == Integrals::Off { f64::NAN } else { 0.0 };
    let energy = matches!(opts.integrals, Integrals::AtEveryOutput | Integrals::AtStepEnds);
    let mut rec = Recorder {
        model,
        on_output,
        outputs: index_runs(model.output_states()),
        states: opts.states,
        rtol: opts.solver.rtol,
        energy,
        sol: Solution::default(),
        q: integral,
        e: if energy { 0.0 } else { f64::NAN },
        i: 0.0,
        p: 0.0,
        history: Vec::new(),
    };
    let mut next_eval = 0usize;
    let mut t0 = 0.0;
    let one_c = opts.capacity;
    for (k, step) in protocol.steps.iter().enumerate() {
        let drive = Driven { model, step, t0, capacity: opts.capacity };
        let (lower, upper) = step.voltage_window((lower, upper));
        let y_start = y.clone();
        let start = StepStart { model, step, index: k, t0, y: &y_start, window: (lower, upper), capacity: one_c };
        // A voltage hold solves for the current as one more (algebraic) state.
        let held = match *step {
            Step::Hold { voltage, .. } => {
                let i = hold::starting_current(model, ws, voltage, &mut y, rec.i, one_c).map_err(|err| at_time(err, t0))?;
                y.push(i);
                Some(hold::VoltageHold::new(model, voltage, one_c))
            }
            _ => {
                // A power step's current depends on the algebraic states and vice versa: alternate.
                let passes = if matches!(step, Step::Power { .. }) { 3 } else { 1 };
                for _ in 0..passes {
                    let i0 = drive.current(t0, &y);
                    if let Err(err) = consistent_initialisation(model, ws, i0, &mut y) {
                        let err = at_time(err, t0);
                        return Err(start.blame(ws, i0, &format!("the model fails ({err})"), err));
                    }
                }
                None
            }
        };
        if held.is_some() {
            rec.outputs.push(n..n + 1);
        }
        let mut buf = vec![0.0; y.len()];
        let i0 = drive.current(t0, &y);
        let v0 = model.voltage(&y[..n], i0);
        let crossed = if !step.has_cutoffs() {
            None
        } else if i0 > 0.0 && v0 <= lower {
            Some(("lower", lower, opts.cutoffs.0, "below"))
        } else if i0 < 0.0 && v0 >= upper {
            Some(("upper", upper, opts.cutoffs.1, "above"))
        } else {
            None
        };
        if let Some((side, limit, cell_limit, beyond)) = crossed {
            // Name the limit the user set: the step's own `until_voltage` or the cell's cut-off;
            // the step's demand instead when the cell carries 1C inside that limit ([`demand`]).
            let field = if limit != cell_limit { format!("protocol.steps[{k}].until_voltage") } else { format!("cell.{side}_cutoff") };
            let why = if !(0.0..10.0).contains(&v0) {
                ": the cell cannot carry this current (check the current or C-rate, the resistances and the electrode thicknesses)"
            } else {
                ""
            };
            let failure = Error::invalid(&field, limit, format!("voltage at the start of step {k} (t = {t0} s) is {v0:.4} V, already at or {beyond} the limit{why}"));
            let what = format!("the voltage is {v0:.4} V, already at or {beyond} `{field}` = {limit} V");
            return Err(start.blame(ws, i0, &what, failure));
        }
        rec.restart(t0, i0, i0 * v0);
        let (q0, e0) = (rec.q, rec.e);
        match t_eval {
            // Every step start is recorded, so a current jump shows as a vertical edge.
            None => rec.record(t0, &y, i0, v0, q0, e0),
            Some(te) => {
                while next_eval < te.len() && te[next_eval] <= t0 {
                    if k == 0 {
                        rec.record(t0, &y, i0, v0, q0, e0);
                    }
                    next_eval += 1;
                }
            }
        }
        // The event's last (t, I, V): at a step end the recorder needs the same values.
        let last_event = std::cell::Cell::new((f64::NAN, 0.0, 0.0));
        let event_fn = |t: f64, yy: &[f64]| {
            let i = drive.current(t, yy);
            let v = model.voltage(&yy[..n], i);
            last_event.set((t, i, v));
            match step {
                Step::Hold { until_current: Some(limit), .. } => i.abs() - limit,
                _ => (v - lower).min(upper - v),
            }
        };
        let ends_early = step.has_cutoffs() || matches!(step, Step::Hold { until_current: Some(_), .. });
        let event: Option<&dyn Fn(f64, &[f64]) -> f64> = if ends_early { Some(&event_fn) } else { None };
        let kinks = step.kinks().iter().map(|k| t0 + k).collect();
        let temperature = opts.temperature_input.as_deref().map(|(t, v)| (model.temperature_rows(), t.as_slice(), v.as_slice())).filter(|(rows, ..)| !rows.is_empty());
        let dae = UnderCurrent { model, current: |t: f64, y: &[f64]| drive.current(t, y), kinks, temperature };
        let mut observer = |t_old: f64, dense: &DenseOutput| {
            let t_new = dense.t_end();
            if let Some(te) = t_eval {
                while next_eval < te.len() && te[next_eval] <= t_new {
                    let t = te[next_eval];
                    if opts.integrals == Integrals::AtEveryOutput {
                        let end = rec.integrate_to(dense, &drive, (t_old, t), None, &dae.kinks, &mut buf);
                        let (q, e) = (rec.q + end.dq, rec.e + end.de);
                        rec.record(t, &buf, end.current, end.voltage, q, e);
                    } else {
                        rec.sample(dense, &drive, t, &mut buf);
                    }
                    next_eval += 1;
                }
            }
            let (t_event, i, v) = last_event.get();
            let at_end = (t_event == t_new).then_some((i, v));
            let end = match opts.integrals {
                Integrals::Off => rec.step_end(dense, &drive, t_new, at_end, &mut buf),
                _ => rec.integrate_to(dense, &drive, (t_old, t_new), at_end, &dae.kinks, &mut buf),
            };
            rec.advance(t_new, &end);
            if t_eval.is_none() {
                let (q, e) = (rec.q, rec.e);
                rec.record(t_new, &buf, end.current, end.voltage, q, e);
            }
        };
        let t_end = t0 + step.duration();
        let mut stats = SolverStats::default();
        let reason = match &held {
            Some(hold) => {
                let hold_ws = ws.extended(n + 1, || hold::VoltageHold::pattern(model))?;
                integrate(hold, hold_ws, &opts.solver, t0, &mut y, t_end, event, &mut observer, &mut stats)
            }
            None => integrate(&dae, ws, &opts.solver, t0, &mut y, t_end, event, &mut observer, &mut stats),
        };
        if held.is_some() {
            y.truncate(n);
            rec.outputs.pop();
        }
        rec.sol.stats.add(&stats);
        let reason = match reason {
            // Not one step taken: the step's current may be what the model cannot start under.
            Err(err @ Error::Solver { t, .. }) if t == t0 => return Err(start.blame(ws, i0, &format!("the model fails ({err})"), err)),
            other => other?,
        };
        match reason {
            crate::solver::StopReason::Event(t) => {
                rec.sol.cutoff_times.push(t);
                t0 = t;
            }
            crate::solver::StopReason::EndTime => t0 = t_end,
        }
    }
    rec.sol.final_state = y;
    Ok(rec.sol)
}

/// Sorted indices as runs of consecutive indices.
fn index_runs(mut idx: Vec<usize>) -> Vec<std::ops::Range<usize>> {
    idx.sort_unstable();
    idx.dedup();
    let mut runs: Vec<std::ops::Range<usize>> = Vec::new();
    for i in idx {
        match runs.last_mut() {
            Some(r) if r.end == i => r.end += 1,
            _ => runs.push(i..i + 1),
        }
    }
    runs
}

fn at_time(err: Error, t: f64) -> Error {
    match err {
        Error::Solver { reason, .. } => Error::Solver { t, reason },
        other => other,
    }
}
