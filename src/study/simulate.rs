//! The `simulate` run: one model through one protocol (a discharge at a C-rate, PyBaMM-style
//! experiment steps, or a protocol file), timed over repeats, written as CSV, a voltage plot
//! and concentration/potential profiles into a staged output folder.

use std::path::PathBuf;
use std::time::Instant;

use crate::error::Error;
use crate::geometry::MeshSizes;
use crate::models::{ModelBuilder, ModelKind, Submodels};
use crate::output::OutputDir;
use crate::params::ParameterSet;
use crate::protocol::Protocol;
use crate::report::plot::{Series, line_plot};
use crate::simulation::{SimOptions, Solution, States, simulate};

/// Where the protocol comes from; errors name it as the user wrote it.
pub enum ProtocolSource {
    /// A constant-current discharge at this C-rate (1/h) to the lower cut-off.
    Discharge { c_rate: f64 },
    /// Experiment steps as PyBaMM writes them, in order.
    Experiment(Vec<String>),
    /// A protocol TOML file.
    File(PathBuf),
}

/// What to simulate.
pub struct SimulateRun {
    pub model: ModelKind,
    pub submodels: Submodels,
    pub params: ParameterSet,
    pub protocol: ProtocolSource,
    /// Volumes per electrode/separator domain and per particle (-).
    pub mesh: usize,
    /// Timed solves; the median is reported.
    pub repeat: usize,
    pub out: PathBuf,
    /// Files the run reads (parameter set), which no output may overwrite.
    pub inputs: Vec<PathBuf>,
}

/// What a `simulate` run produced.
pub struct SimulateOutcome {
    pub solution: Solution,
    /// Model build time and median solve time (s).
    pub build_time: f64,
    pub solve_time_median: f64,
    pub repeats: usize,
    pub csv: PathBuf,
    pub svg: PathBuf,
    /// Field profiles: the CSV first, then its plots.
    pub fields: Vec<PathBuf>,
    pub warnings: Vec<String>,
}

impl SimulateOutcome {
    /// The one-line JSON summary of `simulate --json`.
    pub fn summary_json(&self, model: ModelKind) -> serde_json::Value {
        let sol = &self.solution;
        serde_json::json!({
            "model": model.to_string(),
            "capacity_Ah": sol.final_capacity(),
            "energy_Wh": sol.final_energy(),
            "final_voltage_V": sol.final_voltage(),
            "end_time_s": sol.time.last(),
            "build_time_s": self.build_time,
            "solve_time_s_median": self.solve_time_median,
            "repeats": self.repeats,
            "steps": sol.stats.steps,
            "csv": self.csv.display().to_string(),
            "fields": self.fields.iter().map(|f| f.display().to_string()).collect::<Vec<_>>(),
        })
    }
}

impl ProtocolSource {
    /// The protocol for the cell `p` (a bad rate, step string or file is an error naming it).
    pub fn protocol(&self, p: &ParameterSet) -> Result<Protocol, Error> {
        match self {
            ProtocolSource::Discharge { c_rate } => {
                if !(*c_rate > 0.0 && c_rate.is_finite()) {
                    return Err(Error::invalid("--c-rate", *c_rate, "must be positive"));
                }
                Ok(Protocol::discharge_within(*c_rate, p.discharge_time_limit(*c_rate)))
            }
            ProtocolSource::Experiment(steps) => crate::protocol::experiment::parse(steps, p.cell.nominal_capacity),
            ProtocolSource::File(path) => {
                let text = std::fs::read_to_string(path).map_err(|e| Error::io(path)(e).input("--protocol"))?;
                toml::from_str(&text).map_err(|e| Error::Parse { path: path.display().to_string(), message: e.to_string() })
            }
        }
    }

    /// A failed simulation named by what the user wrote: the rate, the experiment or the file.
    pub fn name_failure(&self, e: Error) -> Error {
        match self {
            ProtocolSource::Experiment(steps) => Error::InvalidSetting { field: "--experiment".into(), reason: format!("{steps:?} failed: {e}") },
            ProtocolSource::Discharge { c_rate } if matches!(e, Error::StepDemand { .. }) => e.demand_named("--c-rate", *c_rate),
            ProtocolSource::Discharge { c_rate } => Error::InvalidSetting { field: "--c-rate".into(), reason: format!("a {c_rate} C discharge failed: {e}") },
            ProtocolSource::File(path) => Error::InvalidSetting { field: "--protocol".into(), reason: format!("{} failed: {e}", path.display()) },
        }
    }
}

/// Builds the model, solves `run.repeat` times (timed), and writes the outputs (all or none).
pub fn run_simulate(run: &SimulateRun) -> Result<SimulateOutcome, Error> {
    if run.repeat == 0 {
        return Err(Error::invalid("--repeat", 0.0, "must be at least 1"));
    }
    if run.mesh < 2 {
        return Err(Error::invalid("--mesh", run.mesh as f64, "must be at least 2 volumes"));
    }
    let p = &run.params;
    let protocol = run.protocol.protocol(p)?;
    let mut inputs: Vec<&std::path::Path> = run.inputs.iter().map(PathBuf::as_path).collect();
    if let ProtocolSource::File(path) = &run.protocol {
        inputs.push(path);
    }
    let staged = OutputDir::create(&run.out, &inputs)?;
    let dir = staged.path();
    let m = run.mesh;
    let mut builder = ModelBuilder::new(run.model, run.submodels, MeshSizes { x_n: m, x_s: m, x_p: m, r_n: m, r_p: m, ..Default::default() });
    let t_build = Instant::now();
    let built = builder.build(p)?;
    let build_time = t_build.elapsed().as_secs_f64();
    let opts = SimOptions::for_cell(p);
    let mut times = Vec::new();
    let mut solution = None;
    for _ in 0..run.repeat {
        let t = Instant::now();
        solution = Some(simulate(built.model.as_ref(), &mut built.workspace, &protocol, &opts, None).map_err(|e| run.protocol.name_failure(e))?);
        times.push(t.elapsed().as_secs_f64());
    }
    let solution = solution.expect("at least one run");
    let mut warnings = Vec::new();
    if let ProtocolSource::Discharge { c_rate } = run.protocol
        && solution.cutoff_times.is_empty()
    {
        warnings.push(format!(
            "the {c_rate} C discharge ended at its time limit ({:.0} s), not at the lower cut-off ({} V): it is cut short",
            solution.time.last().copied().unwrap_or(0.0),
            p.cell.lower_cutoff
        ));
    }
    times.sort_by(f64::total_cmp);
    let stem = format!("{}_simulation", run.model.to_string().to_lowercase());
    let csv = dir.join(format!("{stem}.csv"));
    let svg = dir.join(format!("{stem}_voltage.svg"));
    solution.write_csv(&csv)?;
    let label = format!("{} {}", run.model, p.name);
    line_plot(&svg, "Terminal voltage", "Time (s)", "Voltage (V)", &[Series { label, x: &solution.time, y: &solution.voltage }])?;
    // Concentration and potential profiles, from one more run that keeps the states (the
    // timed runs do not pay for the copies).
    let kept = SimOptions { states: States::Kept, ..opts.clone() };
    let with_states = simulate(built.model.as_ref(), &mut built.workspace, &protocol, &kept, None)?;
    let fields = crate::report::fields::write_fields(built.model.as_ref(), &with_states, dir, &stem)?;
    let mut written = staged.commit(&[vec![csv, svg], fields].concat())?;
    let fields = written.split_off(2);
    Ok(SimulateOutcome {
        solution,
        build_time,
        solve_time_median: times[times.len() / 2],
        repeats: times.len(),
        csv: written[0].clone(),
        svg: written[1].clone(),
        fields,
        warnings,
    })
}
