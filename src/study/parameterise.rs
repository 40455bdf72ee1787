//! Parameterisation studies (`cellstudio parameterise`, `fits/param_*.toml`): the workflows
//! of a cell's parameterisation as stages, run in order, each feeding the next: `[ocv]` (the
//! pseudo-OCV of slow charge and discharge branches), `[balancing]` (stoichiometry windows and
//! electrode capacities from that pseudo-OCV and the set's half-cell OCPs), `[pulses]`
//! (resistance against state of charge), `[kinetics]` (rate constants or resistances fitted to
//! a pulse), `[gitt]` (particle diffusivity against stoichiometry), `[thermal]` (heat
//! transfer and capacity from a recorded temperature) and `[joint]` (several recordings
//! refitted together at the end). One report, one JSON and each stage's tables
//! and plots.

use std::path::{Path, PathBuf};

use serde::{Deserialize, Serialize};

use super::{CellChoice, Output, ReportSection, write_output};
use crate::data::cycler::{Step, read_checked, steps};
use crate::data::{CsvFormat, PseudoOcv, Recording};
use crate::error::Error;
use crate::params::ParameterSet;

/// A parameterisation study as written in `fits/param_*.toml`.
#[derive(Clone, Debug, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct ParameterisationStudy {
    /// Title used in reports.
    pub name: String,
    /// The file the study was read from (an input no output may overwrite).
    #[serde(skip)]
    pub source: Option<PathBuf>,
    #[serde(default)]
    pub cell: CellChoice,
    pub ocv: Option<super::ocv::OcvSection>,
    pub balancing: Option<super::balancing::BalancingSection>,
    pub pulses: Option<super::pulses::PulseSection>,
    pub kinetics: Option<super::kinetics::KineticsSection>,
    pub gitt: Option<super::gitt::GittSection>,
    pub thermal: Option<super::thermal_stage::ThermalSection>,
    pub joint: Option<super::joint_stage::JointSection>,
    #[serde(default)]
    pub output: Output,
}

/// What earlier stages hand to later ones.
pub struct Stages {
    /// The parameter set, updated by the stages that identify parameters.
    pub parameters: ParameterSet,
    /// The pseudo-OCV of `[ocv]`.
    pub ocv: Option<PseudoOcv>,
    /// The window capacity (A h) of `[balancing]`.
    pub window_capacity: Option<f64>,
}

impl Stages {
    /// Puts a stage's fitted values (`names`, `values`) into the parameter set, except those
    /// on a bound of their search range (`at_bound`: no estimate), which keep the value
    /// before the stage; returns the notes that say which went in and which did not.
    pub fn apply_fitted(&mut self, stage: &str, names: &[String], values: &[f64], at_bound: &[super::OnBound]) -> Result<Vec<String>, Error> {
        let (mut applied, mut kept) = (Vec::new(), Vec::new());
        for (name, v) in names.iter().zip(values) {
            if at_bound.iter().any(|b| &b.name == name) {
                kept.push(name.as_str());
            } else {
                self.parameters.set(name, *v)?;
                applied.push(name.as_str());
            }
        }
        let mut notes = Vec::new();
        if !applied.is_empty() {
            notes.push(format!("the fitted values of {} are used from here on ({stage}.apply = true)", applied.join(", ")));
        }
        if !kept.is_empty() {
            notes.push(format!("{} ended on a bound of the search range in [{stage}] and kept the value before it", kept.join(", ")));
        }
        Ok(notes)
    }
}

/// What a parameterisation run produced.
pub struct ParameterisationOutcome {
    pub files: Vec<PathBuf>,
    /// One line per stage for the console.
    pub summary: Vec<String>,
    pub notes: Vec<String>,
    pub warnings: Vec<String>,
    /// Each stage's results by its key (`ocv`, `balancing`, ...), as `parameterisation.json`.
    pub stages: serde_json::Value,
    /// The parameter set as the stages left it, as `parameters.json`.
    pub parameters: crate::params::ParameterSet,
}

/// One stage's report section, console line, notes and JSON.
pub struct StageOutput {
    pub report: ReportSection,
    pub summary: String,
    pub notes: Vec<String>,
    pub json: serde_json::Value,
}

impl ParameterisationStudy {
    /// Reads and checks a study file.
    pub fn from_file(path: &Path) -> Result<Self, Error> {
        let text = std::fs::read_to_string(path).map_err(Error::io(path))?;
        let mut study = Self::from_toml(&text, &path.display().to_string())?;
        study.source = Some(path.to_path_buf());
        Ok(study)
    }

    /// Parses and checks study text; `origin` names it in errors.
    pub fn from_toml(text: &str, origin: &str) -> Result<Self, Error> {
        let study: Self = toml::from_str(text).map_err(|e| Error::Parse { path: origin.into(), message: e.to_string() })?;
        study.validate()?;
        Ok(study)
    }

    /// The study with `--set` overrides of the cell's parameters, checked again.
    pub fn with_overrides(mut self, overrides: Vec<crate::params::Override>) -> Result<Self, Error> {
        if !overrides.is_empty() {
            self.cell.overrides = overrides;
            self.validate()?;
        }
        Ok(self)
    }

    /// Checks every section before any work.
    pub fn validate(&self) -> Result<(), Error> {
        let cell = self.cell.load()?;
        if self.ocv.is_none() && self.balancing.is_none() && self.pulses.is_none() && self.kinetics.is_none() && self.gitt.is_none() && self.thermal.is_none() && self.joint.is_none() {
            return Err(Error::InvalidSetting { field: "ocv".into(), reason: "the study has no stage: give at least one of [ocv], [balancing], [pulses], [kinetics], [gitt], [thermal], [joint]".into() });
        }
        if let Some(o) = &self.ocv {
            o.validate()?;
        }
        if let Some(b) = &self.balancing {
            b.validate(self.ocv.is_some())?;
        }
        if let Some(p) = &self.pulses {
            p.validate("pulses")?;
        }
        if let Some(k) = &self.kinetics {
            k.validate()?;
        }
        if let Some(g) = &self.gitt {
            g.validate()?;
        }
        if let Some(t) = &self.thermal {
            t.validate(&cell)?;
        }
        if let Some(j) = &self.joint {
            j.validate(&cell)?;
        }
        Ok(())
    }

    /// Files the run reads: the study, the parameter set, the recordings.
    pub fn inputs(&self) -> Vec<&Path> {
        let pulses = self.pulses.iter().map(|p| p.file.as_path()).chain(self.kinetics.iter().map(|k| k.file.as_path())).chain(self.gitt.iter().map(|g| g.file.as_path())).chain(self.thermal.iter().map(|t| t.file.as_path()));
        let recordings = self.ocv.iter().flat_map(|o| o.files()).chain(pulses).chain(self.joint.iter().flat_map(|j| j.files()));
        self.source.as_deref().into_iter().chain(self.cell.file()).chain(recordings).collect()
    }
}

/// A recording read and checked against the cell as a fit reads it, with its steps; notes of
/// the checks are appended to `notes`.
pub(crate) fn recording_and_steps(path: &Path, format: &CsvFormat, cell: &ParameterSet, notes: &mut Vec<String>) -> Result<(Recording, Vec<Step>), Error> {
    let (data, checks) = read_checked(path, format, cell)?;
    notes.extend(checks);
    let s = steps(&data.recording, data.step.as_deref());
    Ok((data.recording, s))
}

/// Runs the study's stages in order into a staged output folder, committed at the end: a
/// failing stage leaves nothing behind.
pub fn run_parameterisation(study: &ParameterisationStudy) -> Result<ParameterisationOutcome, Error> {
    let out = crate::output::OutputDir::create(&study.output.dir, &study.inputs())?;
    let dir = out.path().to_path_buf();
    let mut stages = Stages { parameters: study.cell.load()?, ocv: None, window_capacity: None };
    let mut outputs = Vec::new();
    if let Some(section) = &study.ocv {
        outputs.push(("ocv", super::ocv::run_ocv(section, &mut stages, &dir)?));
    }
    if let Some(section) = &study.balancing {
        outputs.push(("balancing", super::balancing::run_balancing(section, &mut stages, &dir)?));
    }
    if let Some(section) = &study.pulses {
        outputs.push(("pulses", super::pulses::run_pulses(section, &mut stages, &dir)?));
    }
    if let Some(section) = &study.kinetics {
        outputs.push(("kinetics", super::kinetics::run_kinetics(section, &mut stages, &dir)?));
    }
    if let Some(section) = &study.gitt {
        outputs.push(("gitt", super::gitt::run_gitt(section, &mut stages, &dir)?));
    }
    if let Some(section) = &study.thermal {
        outputs.push(("thermal", super::thermal_stage::run_thermal(section, &mut stages, &dir)?));
    }
    if let Some(section) = &study.joint {
        outputs.push(("joint", super::joint_stage::run_joint_stage(section, &mut stages, &dir)?));
    }
    let mut md = format!("# {}\n\nParameter set: {}.\n", study.name, stages.parameters.name);
    let (mut files, mut summary, mut notes, mut warnings) = (Vec::new(), Vec::new(), Vec::new(), Vec::new());
    let mut json = serde_json::Map::new();
    for (key, stage) in outputs {
        md.push_str(&stage.report.section);
        files.extend(stage.report.files);
        warnings.extend(stage.report.warnings);
        summary.push(stage.summary);
        notes.extend(stage.notes);
        json.insert(key.into(), stage.json);
    }
    // The set as the stages left it, readable as `[cell] parameter_set` by later studies.
    write_output(&dir, "parameters.json", serde_json::to_string_pretty(&stages.parameters).expect("serialisable"), &mut files)?;
    md.push_str("\nThe parameter set as the stages left it: `parameters.json` (use it as `[cell] parameter_set` of a later study).\n");
    let stages_json = serde_json::Value::Object(json);
    write_output(&dir, "parameterisation.json", serde_json::to_string_pretty(&stages_json).expect("serialisable"), &mut files)?;
    let md = super::fit::with_notes(md, &notes, &warnings);
    write_output(&dir, "report.md", md, &mut files)?;
    let files = out.commit(&files)?;
    Ok(ParameterisationOutcome { files, summary, notes, warnings, stages: stages_json, parameters: stages.parameters })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A fitted value on a bound of its range stays out of the set; the others go in.
    #[test]
    fn a_value_on_a_bound_keeps_the_one_before() {
        let mut stages = Stages { parameters: crate::params::chen2020(), ocv: None, window_capacity: None };
        let names = vec!["negative.diffusivity".to_string(), "positive.rate_constant".to_string()];
        let on_bound = vec![super::super::OnBound { name: names[1].clone(), value: 1e-4, side: "upper" }];
        let notes = stages.apply_fitted("kinetics", &names, &[2e-14, 1e-4], &on_bound).unwrap();
        assert_eq!(stages.parameters.get("negative.diffusivity").unwrap(), 2e-14);
        assert_eq!(stages.parameters.get("positive.rate_constant").unwrap(), crate::params::chen2020().get("positive.rate_constant").unwrap());
        assert!(notes[0].contains("negative.diffusivity") && notes[1].contains("positive.rate_constant") && notes[1].contains("kept"), "{notes:?}");
    }
}
