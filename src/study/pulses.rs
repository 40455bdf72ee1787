//! The `[pulses]` stage of a parameterisation study: the resistance of every pulse (a
//! constant-current step after a rest) after given times, against the state of charge by
//! coulomb counting; `pulses.csv` and `pulse_resistance.svg`.

use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use serde::{Deserialize, Serialize};

use super::ReportSection;
use super::parameterise::{StageOutput, Stages, recording_and_steps};
use crate::data::{CsvFormat, Pulse, Recording, pulses};
use crate::error::Error;
use crate::report::plot::{Series, line_plot};

/// `[pulses]`: the recording, its starting state of charge and the times of the resistances.
#[derive(Clone, Debug, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct PulseSection {
    /// Recording (this crate's CSV or a cycler export) with rests before its pulses.
    pub file: PathBuf,
    #[serde(default)]
    pub format: CsvFormat,
    /// State of charge (-) at the recording's start (default 1: it starts full).
    #[serde(default = "full")]
    pub initial_soc: f64,
    /// Capacity (A h) that maps charge to state of charge; default: the window capacity of
    /// `[balancing]`, else the pseudo-OCV's of `[ocv]`, else the set's nominal capacity.
    pub capacity: Option<f64>,
    /// Times into each pulse (s) at which its resistance is taken (default 1 s and 10 s).
    #[serde(default = "default_times")]
    pub times: Vec<f64>,
}

fn full() -> f64 {
    1.0
}
fn default_times() -> Vec<f64> {
    vec![1.0, 10.0]
}

impl PulseSection {
    pub(crate) fn validate(&self, field: &str) -> Result<(), Error> {
        if !(0.0..=1.0).contains(&self.initial_soc) {
            return Err(Error::invalid(format!("{field}.initial_soc"), self.initial_soc, "must lie in [0, 1]"));
        }
        if let Some(c) = self.capacity.filter(|c| !(*c > 0.0 && c.is_finite())) {
            return Err(Error::invalid(format!("{field}.capacity"), c, "must be a positive capacity (A h)"));
        }
        if self.times.is_empty() {
            return Err(Error::InvalidSetting { field: format!("{field}.times"), reason: "give at least one time (s)".into() });
        }
        if let Some(t) = self.times.iter().find(|t| !(**t > 0.0 && t.is_finite())) {
            return Err(Error::invalid(format!("{field}.times"), *t, "must be positive times (s)"));
        }
        Ok(())
    }

    /// The capacity (A h) of the state-of-charge axis and where it comes from.
    pub(crate) fn capacity(&self, stages: &Stages) -> (f64, &'static str) {
        match (self.capacity, stages.window_capacity, &stages.ocv) {
            (Some(c), _, _) => (c, "given"),
            (None, Some(c), _) => (c, "the window capacity of [balancing]"),
            (None, None, Some(o)) => (o.capacity(), "the pseudo-OCV of [ocv]"),
            (None, None, None) => (stages.parameters.cell.nominal_capacity, "the nominal capacity"),
        }
    }

}

/// The recording `file` and its pulses; an error naming `field` when it has none.
pub(crate) fn read_pulses(field: &str, file: &Path, format: &CsvFormat, stages: &Stages, notes: &mut Vec<String>) -> Result<(Recording, Vec<Pulse>), Error> {
    let (rec, s) = recording_and_steps(file, format, &stages.parameters, notes)?;
    let found = pulses(&rec, &s);
    if found.is_empty() {
        return Err(Error::InvalidSetting {
            field: format!("{field}.file"),
            reason: format!("`{}` has no constant-current step after a rest (its steps:\n{})", file.display(), crate::data::cycler::step_table(&s)),
        });
    }
    Ok((rec, found))
}

/// Runs `[pulses]`.
pub fn run_pulses(section: &PulseSection, stages: &mut Stages, dir: &Path) -> Result<StageOutput, Error> {
    let mut notes = Vec::new();
    let (rec, found) = read_pulses("pulses", &section.file, &section.format, stages, &mut notes)?;
    let (capacity, source) = section.capacity(stages);
    let soc = |p: &Pulse| section.initial_soc - p.discharged_before / capacity;
    let mut csv = String::from("step,start_s,current_A,duration_s,discharged_Ah,soc");
    for t in &section.times {
        let _ = write!(csv, ",resistance_{t}s_ohm");
    }
    csv.push('\n');
    let mut md = String::from("\n## Pulse resistance (`[pulses]`)\n\n");
    let _ = writeln!(
        md,
        "`{}`: {} pulse(s) (constant-current steps after a rest). Resistance after `t` s: (rested voltage before the pulse - voltage at `t`) / current. State of charge = {} - discharged charge / {:.4} A h ({source}).\n",
        section.file.display(),
        found.len(),
        section.initial_soc,
        capacity
    );
    md.push_str("| step | current (A) | duration (s) | SOC (-) |");
    for t in &section.times {
        let _ = write!(md, " R({t} s) (mOhm) |");
    }
    md.push_str("\n|---|---|---|---|");
    md.push_str(&"---|".repeat(section.times.len()));
    md.push('\n');
    let mut curves: Vec<(Vec<f64>, Vec<f64>)> = vec![(Vec::new(), Vec::new()); section.times.len()];
    let mut json = Vec::new();
    for p in &found {
        let r: Vec<Option<f64>> = section.times.iter().map(|&t| p.resistance(&rec, t)).collect();
        let _ = write!(csv, "{},{},{:.6},{},{:.6},{:.6}", p.step, p.start, p.current, p.duration, p.discharged_before, soc(p));
        let _ = write!(md, "| {} | {:.4} | {:.1} | {:.4} |", p.step, p.current, p.duration, soc(p));
        for (k, v) in r.iter().enumerate() {
            let _ = write!(csv, ",{}", v.map_or(String::new(), |v| format!("{v:.6e}")));
            let _ = write!(md, " {} |", v.map_or("-".into(), |v| format!("{:.3}", 1e3 * v)));
            if let Some(v) = v {
                curves[k].0.push(soc(p));
                curves[k].1.push(1e3 * v);
            }
        }
        csv.push('\n');
        md.push('\n');
        json.push(serde_json::json!({ "pulse": p, "soc": soc(p), "resistance_ohm": section.times.iter().zip(&r).map(|(t, v)| serde_json::json!({ "time_s": t, "ohm": v })).collect::<Vec<_>>() }));
    }
    let mut files: Vec<PathBuf> = Vec::new();
    super::write_output(dir, "pulses.csv", csv, &mut files)?;
    let series: Vec<Series> = section.times.iter().zip(&curves).map(|(t, c)| Series { label: format!("after {t} s"), x: &c.0, y: &c.1 }).collect();
    let plot = dir.join("pulse_resistance.svg");
    line_plot(&plot, "pulse resistance against state of charge", "state of charge (-)", "resistance (mOhm)", &series)?;
    files.push(plot);
    let _ = writeln!(md, "\nTable: `pulses.csv`; plot: `pulse_resistance.svg`.");
    let first = &curves[0];
    let summary = format!(
        "pulses: {} pulse(s); R({} s) {:.2}-{:.2} mOhm over SOC {:.3}-{:.3}",
        found.len(),
        section.times[0],
        first.1.iter().copied().fold(f64::INFINITY, f64::min),
        first.1.iter().copied().fold(f64::NEG_INFINITY, f64::max),
        first.0.iter().copied().fold(f64::INFINITY, f64::min),
        first.0.iter().copied().fold(f64::NEG_INFINITY, f64::max)
    );
    Ok(StageOutput { report: ReportSection { files, section: md, warnings: Vec::new() }, summary, notes, json: serde_json::json!({ "capacity_Ah": capacity, "capacity_from": source, "pulses": json }) })
}
