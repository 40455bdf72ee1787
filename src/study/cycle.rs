//! Cycling studies (`cellstudio cycle STUDY.toml`): a cell and model (typically with an SEI,
//! loss-of-active-material or lithium plating submodel) through `N` repetitions of one cycle's protocol, a progress-bar tick per cycle,
//! and per-cycle summaries written as `cycles.csv`, `cycles.json` and a retention plot
//! into a staged output folder (all or nothing).
//!
//! ```toml
//! name = "SEI growth over 20 CC-CV cycles"
//! [cell]
//! parameter_set = "chen2020"
//! [model]
//! kind = "spm"
//! submodels = { sei = "reaction limited" }
//! [cycling]
//! cycles = 20
//! initial_soc = 0.0
//! cycle = ["Charge at 1C until 4.1 V", "Hold at 4.1 V until C/20", "Rest for 10 minutes",
//!          "Discharge at 1C until 3.0 V", "Rest for 10 minutes"]
//! [output]
//! dir = "out/cycle_sei"
//! ```

use std::path::{Path, PathBuf};
use std::time::Instant;

use serde::{Deserialize, Serialize};

use super::{CellChoice, ModelChoice, Output};
use crate::error::Error;
use crate::geometry::MeshSizes;
use crate::models::ModelBuilder;
use crate::params::Override;
use crate::report::plot::{Series, line_plot};
use crate::simulation::SimOptions;
use crate::simulation::cycling::{CycleSummary, run_cycles};

/// Largest number of cycles a study may ask for (a typo guard: 10^6 cycles is years of
/// wall time).
pub const MAX_CYCLES: usize = 100_000;

/// A cycling study as written in its TOML file.
#[derive(Clone, Debug, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct CycleStudy {
    /// Title used in outputs.
    pub name: String,
    /// The file the study was read from (an input no output may overwrite).
    #[serde(skip)]
    pub source: Option<PathBuf>,
    #[serde(default)]
    pub cell: CellChoice,
    #[serde(default)]
    pub model: ModelChoice,
    pub cycling: Cycling,
    #[serde(default)]
    pub output: Output,
    /// Ageing parameters fitted to a measured capacity-fade curve before the cycles run.
    #[serde(default)]
    pub fit: Option<super::fade_fit::FadeFitSpec>,
}

/// The `[cycling]` table.
#[derive(Clone, Debug, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct Cycling {
    /// Number of cycles `N` (1 to [`MAX_CYCLES`]).
    pub cycles: usize,
    /// One cycle's steps as PyBaMM writes them ("Charge at 1C until 4.1 V", ...).
    pub cycle: Vec<String>,
    /// State of charge (0 to 1, within the cell's cut-off window) to start from; the
    /// parameter set's initial concentrations when absent. Starting empty and charging
    /// first makes every discharge start from the same charged state.
    #[serde(default)]
    pub initial_soc: Option<f64>,
    /// Relative and absolute tolerance of the integrator (default 1e-6).
    #[serde(default = "default_tolerance")]
    pub tolerance: f64,
}

fn default_tolerance() -> f64 {
    1e-6
}

/// What a cycling study produced.
pub struct CycleOutcome {
    pub summaries: Vec<CycleSummary>,
    /// Wall time of the cycles (s).
    pub seconds: f64,
    pub files: Vec<PathBuf>,
    /// The fade fit, when the study has a `[fit]` table.
    pub fade: Option<super::fade_fit::FadeFitOutcome>,
}

impl CycleStudy {
    /// Reads and checks a study file.
    pub fn from_file(path: &Path) -> Result<Self, Error> {
        let text = std::fs::read_to_string(path).map_err(Error::io(&path))?;
        let mut study: CycleStudy = toml::from_str(&text).map_err(|e| Error::Parse { path: path.display().to_string(), message: e.to_string() })?;
        study.source = Some(path.to_path_buf());
        study.validate()?;
        Ok(study)
    }

    /// The study with `--set` overrides of the cell's parameters, checked again.
    pub fn with_overrides(mut self, overrides: Vec<Override>) -> Result<Self, Error> {
        self.cell.overrides = overrides;
        self.validate()?;
        Ok(self)
    }

    /// Checks the cycle count, tolerance, steps and cell; errors name the key.
    pub fn validate(&self) -> Result<(), Error> {
        let c = &self.cycling;
        if !(1..=MAX_CYCLES).contains(&c.cycles) {
            return Err(Error::invalid("cycling.cycles", c.cycles as f64, format!("must be between 1 and {MAX_CYCLES}")));
        }
        if !(c.tolerance > 0.0 && c.tolerance < 1e-2) {
            return Err(Error::invalid("cycling.tolerance", c.tolerance, "must lie in (0, 0.01)"));
        }
        let p = self.parameters()?;
        let sub = &self.model.submodels;
        crate::models::submodels::refuse_unread_overrides(sub, &self.cell.overrides)?;
        if let Some(fit) = &self.fit {
            fit.validate(&p)?;
            crate::models::submodels::refuse_unread(sub, super::fit::fitted_paths("fit.parameters", &fit.parameters))?;
        }
        crate::protocol::experiment::parse(&c.cycle, p.cell.nominal_capacity)
            .map_err(|e| Error::InvalidSetting { field: "cycling.cycle".into(), reason: e.to_string() })?
            .validate()
    }

    /// The cell's parameters, placed at `initial_soc` when given.
    fn parameters(&self) -> Result<crate::params::ParameterSet, Error> {
        let mut p = self.cell.load()?;
        if let Some(soc) = self.cycling.initial_soc {
            crate::params::set_initial_soc_from(&mut p, soc, "cycling.initial_soc")?;
        }
        Ok(p)
    }

    /// Runs the cycles, observing each with `on_cycle` (after the progress bar's tick), and
    /// writes the outputs.
    pub fn run(&self, on_cycle: &mut dyn FnMut(&CycleSummary)) -> Result<CycleOutcome, Error> {
        let p = self.parameters()?;
        let protocol = crate::protocol::experiment::parse(&self.cycling.cycle, p.cell.nominal_capacity)?;
        let inputs: Vec<&Path> = self.source.as_deref().into_iter().chain(self.cell.file()).chain(self.fit.as_ref().map(|f| f.data.as_path())).collect();
        let staged = crate::output::OutputDir::create(&self.output.dir, &inputs)?;
        let mut opts = SimOptions::for_cell(&p);
        opts.solver.set_tolerance(self.cycling.tolerance);
        let (p, fade) = match &self.fit {
            Some(spec) => {
                let (fitted, outcome) = spec.fit(&p, self.model.kind, self.model.submodels, &protocol, &opts)?;
                (fitted, Some(outcome))
            }
            None => (p, None),
        };
        let mut builder = ModelBuilder::new(self.model.kind, self.model.submodels, MeshSizes::default());
        let built = builder.build(&p)?;
        let n = self.cycling.cycles;
        let bar = crate::progress::bar("cycle", n as u64, "cycle {bar:30} {pos}/{len} cycles [{elapsed}, eta {eta}] {msg}");
        let start = Instant::now();
        let summaries = run_cycles(built.model.as_ref(), &mut built.workspace, &protocol, n, &opts, &mut |s| {
            bar.set_message(format!("{:.4} A h", s.discharge_capacity_ah));
            bar.inc(1);
            on_cycle(s);
        });
        bar.finish_and_clear();
        let summaries = summaries?;
        let seconds = start.elapsed().as_secs_f64();
        let dir = staged.path();
        let (csv, json, svg) = (dir.join("cycles.csv"), dir.join("cycles.json"), dir.join("capacity_retention.svg"));
        crate::error::write_file(&csv, summary_csv(&summaries))?;
        let body = serde_json::json!({
            "name": self.name,
            "model": self.model.kind.to_string(),
            "submodels": self.model.submodels,
            "cycle": self.cycling.cycle,
            "initial_soc": self.cycling.initial_soc,
            "tolerance": self.cycling.tolerance,
            "wall_time_s": seconds,
            "cycles": summaries,
        });
        crate::error::write_file(&json, serde_json::to_string_pretty(&body).unwrap_or_default())?;
        let x: Vec<f64> = summaries.iter().map(|s| s.cycle as f64).collect();
        let y: Vec<f64> = summaries.iter().map(|s| 100.0 * s.capacity_retention).collect();
        line_plot(&svg, &self.name, "Cycle", "Capacity retention (%)", &[Series { label: format!("{} {}", self.model.kind, p.name), x: &x, y: &y }])?;
        let mut written = vec![csv, json, svg];
        if let Some(fade) = &fade {
            let (json, svg) = (dir.join("fade_fit.json"), dir.join("fade_fit.svg"));
            let body = serde_json::json!({ "fit": fade, "warnings": fade.warnings() });
            crate::error::write_file(&json, serde_json::to_string_pretty(&body).unwrap_or_default())?;
            fade.plot(&svg, &format!("{}: capacity fade", self.name))?;
            written.extend([json, svg]);
        }
        let files = staged.commit(&written)?;
        Ok(CycleOutcome { summaries, seconds, files, fade })
    }
}

/// The summaries as CSV, one row per cycle (SI units, thickness in m; the SEI's, LAM's and
/// plating's columns empty without them; plating's come last, after `steps`).
fn summary_csv(summaries: &[CycleSummary]) -> String {
    use std::fmt::Write;
    let mut s = String::from(
        "cycle,end_time_s,discharge_capacity_Ah,charge_capacity_Ah,capacity_retention,lithium_lost_to_sei_mol,lithium_inventory_lost,sei_thickness_m,\
         negative_active_material_lost,positive_active_material_lost,lithium_lost_to_negative_lam_mol,lithium_lost_to_positive_lam_mol,end_voltage_V,steps,\
         lithium_lost_to_plating_mol,dead_lithium_mol\n",
    );
    let one = |v: Option<f64>| v.map_or(String::new(), |x| format!("{x:.6e}"));
    let pair = |v: Option<[f64; 2]>| v.map_or([String::new(), String::new()], |v| v.map(|x| format!("{x:.6e}")));
    for c in summaries {
        let l = one(c.sei_thickness_m);
        let (plated, dead) = (one(c.lithium_lost_to_plating_mol), one(c.dead_lithium_mol));
        let [am_n, am_p] = pair(c.active_material_lost);
        let [li_n, li_p] = pair(c.lithium_lost_to_lam_mol);
        let _ = writeln!(
            s,
            "{},{},{:.9},{:.9},{:.9},{:.6e},{:.6e},{l},{am_n},{am_p},{li_n},{li_p},{:.6},{},{plated},{dead}",
            c.cycle, c.end_time_s, c.discharge_capacity_ah, c.charge_capacity_ah, c.capacity_retention, c.lithium_lost_to_sei_mol, c.lithium_inventory_lost, c.end_voltage_v, c.steps
        );
    }
    s
}
