//! Helpers shared by the integration tests.
#![allow(dead_code)]

use cellstudio::data::Recording;
use cellstudio::geometry::MeshSizes;
use cellstudio::models::ModelBuilder;
use cellstudio::models::{ModelKind, Submodels};
use cellstudio::params::ParameterSet;
use cellstudio::protocol::Protocol;
use cellstudio::simulation::{SimOptions, States, Solution, simulate};

/// Reference curve shipped in tests/data (copied from ../shared/reference, PyBaMM 26.10).
pub fn reference(name: &str) -> Recording {
    let path = format!("{}/tests/data/{name}.csv", env!("CARGO_MANIFEST_DIR"));
    Recording::from_csv(path.as_ref()).expect("reference curve")
}

pub fn pulse() -> Protocol {
    let path = format!("{}/protocols/pulse_1C.toml", env!("CARGO_MANIFEST_DIR"));
    toml::from_str(&std::fs::read_to_string(path).unwrap()).unwrap()
}

/// Runs `kind` on `p` through `protocol`, with outputs at `t_eval` when given.
pub fn run(
    kind: ModelKind,
    submodels: Submodels,
    mesh: MeshSizes,
    p: &ParameterSet,
    protocol: &Protocol,
    t_eval: Option<Vec<f64>>,
    keep_states: bool,
) -> Solution {
    let mut b = ModelBuilder::new(kind, submodels, mesh);
    let built = b.build(p).expect("build");
    let opts = SimOptions { t_eval, states: if keep_states { States::Kept } else { States::ForOutputs }, ..SimOptions::for_cell(p) };
    simulate(built.model.as_ref(), &mut built.workspace, protocol, &opts, None).expect("simulate")
}

pub fn uniform_mesh(n: usize) -> MeshSizes {
    MeshSizes { x_n: n, x_s: n, x_p: n, r_n: n, r_p: n, ..Default::default() }
}

/// Rows of a PyBaMM reference CSV in `tests/data/{folder}/{file}` (header skipped).
pub fn csv_rows(folder: &str, file: &str) -> Vec<Vec<f64>> {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data").join(folder).join(file);
    let text = std::fs::read_to_string(&path).unwrap();
    text.lines().skip(1).map(|l| l.split(',').map(|x| x.parse().unwrap()).collect()).collect()
}

/// Options for `p` at rtol = atol = 1e-8, the tolerance of the ageing reference curves.
pub fn tight_options(p: &ParameterSet) -> SimOptions {
    let mut opts = SimOptions::for_cell(p);
    opts.solver.set_tolerance(1e-8);
    opts
}

/// The per-cycle summaries of `n` repetitions of `cycle` on `kind` with `submodels` on `p`
/// (default mesh, [`tight_options`]), as the ageing tests compare them with PyBaMM's.
pub fn cycle_summaries(kind: ModelKind, submodels: Submodels, p: &ParameterSet, cycle: &Protocol, n: usize) -> Vec<cellstudio::simulation::cycling::CycleSummary> {
    let mut b = ModelBuilder::new(kind, submodels, MeshSizes::default());
    let built = b.build(p).expect("build");
    cellstudio::simulation::cycling::run_cycles(built.model.as_ref(), &mut built.workspace, cycle, n, &tight_options(p), &mut |_| {}).expect("cycles")
}

/// Differences from a reference over a run of steps.
pub struct StepGaps {
    /// Voltage differences outside the holds, 20 s and more from each step's ends (mV).
    pub voltage: Vec<f64>,
    /// Current differences in the holds, as far from their ends (mA).
    pub current: Vec<f64>,
    /// Largest difference between the step ends (s).
    pub step_end: f64,
}

/// Runs `steps` one at a time on `model`, each from the last one's end state, with outputs at
/// a reference's times since each step's start (`rows`: time (s), current (A) and voltage (V)
/// in columns 0 to 2, the 0-based step in column `step_col`), so that a step ending a
/// millisecond apart (the C/20 end of a hold is that sensitive to either solver's
/// tolerance) does not shift the later steps against each other. Compares the current in
/// the steps `hold` names and the voltage in the others, away from the steps' ends (the
/// first output holds the last step's current), and calls `visit(solution, k, row)` for
/// each reference row with an output `k`.
pub fn step_by_step(
    model: &dyn cellstudio::models::Model,
    ws: &mut cellstudio::solver::Workspace,
    steps: &[cellstudio::protocol::Step],
    rows: &[Vec<f64>],
    step_col: usize,
    hold: impl Fn(usize) -> bool,
    opts: &SimOptions,
    mut visit: impl FnMut(&Solution, usize, &[f64]),
) -> StepGaps {
    let mut y = model.initial_state();
    let mut gaps = StepGaps { voltage: Vec::new(), current: Vec::new(), step_end: 0.0 };
    for (s, step) in steps.iter().enumerate() {
        let ref_rows: Vec<&Vec<f64>> = rows.iter().filter(|r| r[step_col] as usize == s).collect();
        let t0 = ref_rows[0][0];
        let mut times: Vec<f64> = ref_rows.iter().map(|r| r[0] - t0).collect();
        times.dedup();
        let opts = SimOptions { t_eval: Some(times), states: States::Kept, ..opts.clone() };
        let sol = simulate(model, ws, &Protocol { steps: vec![step.clone()] }, &opts, Some(y)).unwrap();
        y = sol.final_state.clone();
        let ours_end = sol.cutoff_times.first().copied().unwrap_or(step.duration());
        let ref_end = ref_rows[ref_rows.len() - 1][0] - t0;
        gaps.step_end = gaps.step_end.max((ours_end - ref_end).abs());
        for r in ref_rows {
            let Some(k) = sol.time.iter().position(|t| *t == r[0] - t0) else { continue };
            visit(&sol, k, r);
            if sol.time[k] < 20.0 || sol.time[k] > ours_end.min(ref_end) - 20.0 {
                continue;
            }
            if hold(s) {
                gaps.current.push((sol.current[k] - r[1]) * 1e3);
            } else {
                gaps.voltage.push((sol.voltage[k] - r[2]) * 1e3);
            }
        }
    }
    gaps
}

/// Root mean square of `x`.
pub fn rms(x: &[f64]) -> f64 {
    (x.iter().map(|e| e * e).sum::<f64>() / x.len() as f64).sqrt()
}

/// Largest magnitude in `x`.
pub fn max_abs(x: &[f64]) -> f64 {
    x.iter().fold(0.0f64, |m, e| m.max(e.abs()))
}

/// Limits on an ageing run's gaps to PyBaMM: voltage RMS and max outside the holds (mV),
/// hold current RMS and max (mA), and the ageing quantities' relative differences (-).
pub struct AgeingLimits {
    pub voltage: (f64, f64),
    pub current: (f64, f64),
    pub ageing: f64,
}

impl AgeingLimits {
    /// Asserts that case `label`'s voltage and hold-current gaps (RMS, max), its ageing
    /// quantities' differences `ageing` (`what` names them) are within the limits, and that
    /// its lithium changed by less than 1e-14 of the total (`conservation`: round-off).
    pub fn assert(&self, label: &str, voltage: (f64, f64), current: (f64, f64), what: &str, ageing: &[f64], conservation: f64) {
        assert!(voltage.0 < self.voltage.0 && voltage.1 < self.voltage.1, "{label}: voltage {voltage:?} mV");
        assert!(current.0 < self.current.0 && current.1 < self.current.1, "{label}: hold current {current:?} mA");
        assert!(ageing.iter().all(|d| *d < self.ageing), "{label}: {what} {ageing:?}");
        assert!(conservation < 1e-14, "{label}: lithium changed by {conservation:e}");
    }
}
