//! The command line's arguments (clap): one subcommand per run, with its flags and their
//! help text. `main.rs` dispatches them.

use std::path::PathBuf;

use clap::{Args, Parser, Subcommand};

use cellstudio::models::ModelKind;
use cellstudio::params::Override;

#[derive(Parser)]
#[command(name = "cellstudio", about = "Battery design optimisation and parameterisation studio")]
pub(crate) struct Cli {
    #[command(subcommand)]
    pub command: Command,
}

/// `--set PATH=VALUE` overrides of the parameter set (repeatable).
#[derive(Args, Clone, Debug, Default)]
pub(crate) struct Overrides {
    /// Override one parameter in SI units, e.g. `--set negative.diffusivity=3e-14` (repeatable).
    #[arg(long = "set", value_name = "PATH=VALUE")]
    pub set: Vec<Override>,
}

impl Overrides {
    /// Whether `path` is overridden (`--set cell.contact_resistance=...` switches the
    /// contact-resistance submodel on, as `--contact-resistance` does).
    pub fn sets(&self, path: &str) -> bool {
        self.set.iter().any(|o| o.path == path)
    }

    /// Whether the contact-resistance submodel is on: asked for by its flag (`asked`) or
    /// switched on by a `--set` of its resistance.
    pub fn contact_resistance(&self, asked: bool) -> bool {
        asked || self.sets("cell.contact_resistance")
    }
}

#[derive(Subcommand)]
pub(crate) enum Command {
    /// Simulate a discharge or a protocol and write CSV + voltage plot.
    Simulate {
        #[command(flatten)]
        overrides: Overrides,
        /// spm, spme or dfn.
        #[arg(long, default_value = "spme")]
        model: ModelKind,
        /// Constant-current discharge rate (C) to the lower cut-off.
        #[arg(long, default_value_t = 1.0, allow_negative_numbers = true)]
        c_rate: f64,
        /// Protocol TOML file (overrides --c-rate), e.g. protocols/pulse_1C.toml.
        #[arg(long, conflicts_with = "experiment")]
        protocol: Option<PathBuf>,
        /// One experiment step as PyBaMM writes it (repeatable, in order; overrides --c-rate),
        /// e.g. `--experiment "Charge at 1C until 4.2 V" --experiment "Hold at 4.2 V until C/50"`.
        #[arg(long)]
        experiment: Vec<String>,
        /// Parameter-set file: TOML, JSON or BPX JSON (default: embedded Chen 2020).
        #[arg(long)]
        params: Option<PathBuf>,
        /// Switch on the contact-resistance submodel with this resistance (ohm).
        #[arg(long, allow_negative_numbers = true)]
        contact_resistance: Option<f64>,
        /// Switch on the lumped thermal submodel.
        #[arg(long)]
        thermal: bool,
        /// Switch on the particle-size distribution (SPM only): lognormal radii of relative
        /// standard deviation negative.radius_relative_std and positive.radius_relative_std
        /// (0.3 unless set; a `--set` of either also switches it on), 30 sizes per electrode.
        #[arg(long)]
        size_distribution: bool,
        /// Volumes per domain and per particle (x_n = x_s = x_p = r_n = r_p).
        #[arg(long, default_value_t = 20)]
        mesh: usize,
        /// Output folder.
        #[arg(long, default_value = "out")]
        out: PathBuf,
        /// Solve this many times and report the median wall time.
        #[arg(long, default_value_t = 1)]
        repeat: usize,
        /// Print the summary as one JSON object.
        #[arg(long)]
        json: bool,
    },
    /// Run a design study end to end: optimise its objective and write the report.
    Design {
        #[command(flatten)]
        overrides: Overrides,
        /// Study file, e.g. designs/gravimetric_chen2020.toml.
        study: PathBuf,
    },
    /// Search the non-dominated front of a multi-objective study (NSGA-II) and plot it.
    Pareto {
        #[command(flatten)]
        overrides: Overrides,
        /// Study file with two or more objectives, e.g. designs/energy_vs_power_chen2020.toml.
        study: PathBuf,
    },
    /// Cycle a cell N times (e.g. CC-CV with SEI growth) and write per-cycle summaries:
    /// capacity, retention, lithium lost, SEI thickness.
    Cycle {
        #[command(flatten)]
        overrides: Overrides,
        /// Cycling study file, e.g. examples/cycle_sei_chen2020.toml.
        study: PathBuf,
    },
    /// Run a parameterisation study: pseudo-OCV, electrode balancing, pulse resistance,
    /// kinetics, GITT diffusivity, thermal and a joint refit as stages, each feeding the next,
    /// with one report.
    Parameterise {
        #[command(flatten)]
        overrides: Overrides,
        /// Parameterisation study file, e.g. fits/param_ocv_c20.toml.
        study: PathBuf,
    },
    /// Fit model parameters to a recording: optimise, report standard errors and plots.
    Fit {
        #[command(flatten)]
        overrides: Overrides,
        /// Fitting study file, e.g. fits/spm_contact_resistance.toml.
        study: PathBuf,
        /// Recording CSV or raw cycler export (overrides the study's `data.file`).
        #[arg(long)]
        data: Option<PathBuf>,
    },
    /// Sample the posterior of a fitting study's parameters (fit first, then MCMC).
    Sample {
        #[command(flatten)]
        overrides: Overrides,
        /// Fitting study file with a `[sampler]` table, e.g. fits/spm_contact_resistance.toml.
        study: PathBuf,
        /// Recording CSV (overrides the study's `data.file`).
        #[arg(long)]
        data: Option<PathBuf>,
    },
    /// Impedance spectrum of a model at a state of charge (CSV + Nyquist plot), optionally
    /// fitted to a measured spectrum.
    Eis {
        #[command(flatten)]
        overrides: Overrides,
        /// spm, spme or dfn.
        #[arg(long, default_value = "spm")]
        model: ModelKind,
        /// State of charge (0..1) of the rest state.
        #[arg(long, default_value_t = 0.5, allow_negative_numbers = true)]
        soc: f64,
        /// Parameter-set file: TOML, JSON or BPX JSON (default: embedded Chen 2020).
        #[arg(long)]
        params: Option<PathBuf>,
        /// Switch on the contact-resistance submodel with this resistance (ohm).
        #[arg(long, allow_negative_numbers = true)]
        contact_resistance: Option<f64>,
        /// Lowest and highest frequency (Hz) and number of frequencies of the model spectrum.
        #[arg(long, num_args = 3, allow_negative_numbers = true, default_values_t = [1e-4, 1e3, 60.0])]
        frequencies: Vec<f64>,
        /// Measured spectrum CSV (frequency_Hz, z_re_ohm, z_im_ohm) to fit.
        #[arg(long)]
        fit: Option<PathBuf>,
        /// Dotted parameters to fit, comma separated (with --fit).
        #[arg(long, value_delimiter = ',', default_value = "negative.diffusivity,cell.contact_resistance")]
        parameters: Vec<String>,
        /// Optimiser for the fit.
        #[arg(long, default_value = "nelder-mead")]
        optimiser: String,
        #[arg(long, default_value = "out/eis")]
        out: PathBuf,
    },
    /// Locate where a model and a recording disagree, name the missing physics, refit the
    /// candidates and write a report (Markdown, JSON, plots).
    Diagnose {
        #[command(flatten)]
        overrides: Overrides,
        /// The model to test: spm, spme or dfn.
        #[arg(long, default_value = "spm")]
        model: ModelKind,
        /// Recording CSV with time_s, current_A (discharge positive), voltage_V[, temperature_K],
        /// or a raw Basytec, BioLogic, Maccor, Neware or Arbin export, or PyProBE Parquet (detected).
        #[arg(long)]
        data: PathBuf,
        /// Parameter-set file (default: embedded Chen 2020).
        #[arg(long)]
        params: Option<PathBuf>,
        /// The model already has the contact-resistance submodel (cell.contact_resistance; a
        /// `--set` of it switches the submodel on too).
        #[arg(long)]
        contact_resistance: bool,
        /// The model already has the lumped thermal submodel.
        #[arg(long)]
        thermal: bool,
        /// Parameters fitted in the model and in every candidate (comma-separated paths).
        #[arg(long, value_delimiter = ',')]
        fit: Vec<String>,
        /// Refit at most this many candidates of the library (default: every identifiable one).
        #[arg(long)]
        refits: Option<usize>,
        /// Start the models from the rest state at the first recorded voltage.
        #[arg(long)]
        start_at_rest: bool,
        /// Diagnose again with each named effect added, up to this many rounds.
        #[arg(long, default_value_t = 3)]
        max_rounds: usize,
        /// Start no further round once this many seconds have passed (the round in progress
        /// finishes and the report says the diagnosis was cut short). Default: no limit.
        #[arg(long)]
        time_budget: Option<f64>,
        /// Output folder.
        #[arg(long, default_value = "out/diagnosis")]
        out: PathBuf,
    },
    /// Recordings and raw cycler exports.
    Data {
        #[command(subcommand)]
        action: DataCommand,
    },
    /// Evaluate a study's grid sweep (in parallel) and write CSV, JSON and density plots.
    Sweep {
        #[command(flatten)]
        overrides: Overrides,
        /// Study file, e.g. designs/gravimetric_chen2020.toml.
        study: PathBuf,
        /// Evaluate only part K of N of the candidates (e.g. `2/8`, one per cluster task) into
        /// `<output.dir>.shard-K-of-N/shard.json`; `--merge` combines them.
        #[arg(long, conflicts_with = "merge")]
        shard: Option<cellstudio::study::shard::Shard>,
        /// Merge these shard folders (every part once) into the ordinary sweep output.
        #[arg(long, num_args = 1..)]
        merge: Vec<PathBuf>,
    },
}

#[derive(Subcommand)]
pub(crate) enum DataCommand {
    /// Detect a file's format and print its rows, time span and steps; refused, as `fit` and
    /// `diagnose` refuse it, when it cannot be a recording of the cell (a unit or sign error).
    Inspect {
        #[command(flatten)]
        overrides: Overrides,
        /// A raw cycler export (Basytec, BioLogic, Maccor, Neware, Arbin), PyProBE Parquet or
        /// a recording CSV.
        file: PathBuf,
        /// The cell the recording is checked against: parameter-set file (default: embedded
        /// Chen 2020).
        #[arg(long)]
        params: Option<PathBuf>,
        /// Print the summary and steps as JSON.
        #[arg(long)]
        json: bool,
    },
}
