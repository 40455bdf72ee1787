//! The `[ocv]` stage of a parameterisation study: the pseudo-OCV of a slow discharge and
//! charge (one recording holding both, or one recording per branch), its hysteresis band and
//! the capacity of each branch; `ocv.csv`, `ocv.svg` and `ocv_hysteresis.svg`.

use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use serde::{Deserialize, Serialize};

use super::ReportSection;
use super::parameterise::{StageOutput, Stages, recording_and_steps};
use crate::data::cycler::Step;
use crate::data::{CsvFormat, OcvBranch, PseudoOcv, Recording};
use crate::error::Error;
use crate::report::plot::{Series, line_plot};

/// Default number of states of charge of the pseudo-OCV table.
pub const DEFAULT_POINTS: usize = 201;

/// `[ocv]`: where the branches are.
#[derive(Clone, Debug, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct OcvSection {
    /// One recording with a constant-current discharge and a constant-current charge (the
    /// longest of each is taken).
    pub file: Option<PathBuf>,
    /// Or: a recording whose longest constant-current discharge is the discharge branch.
    pub discharge: Option<PathBuf>,
    /// And/or: a recording whose longest constant-current charge is the charge branch.
    pub charge: Option<PathBuf>,
    /// Column format of the recordings (default: this crate's CSV or a detected cycler export).
    #[serde(default)]
    pub format: CsvFormat,
    /// States of charge in the table (default 201).
    #[serde(default = "default_points")]
    pub points: usize,
}

fn default_points() -> usize {
    DEFAULT_POINTS
}

impl OcvSection {
    pub(crate) fn validate(&self) -> Result<(), Error> {
        match (&self.file, &self.discharge, &self.charge) {
            (Some(_), None, None) | (None, Some(_), _) | (None, None, Some(_)) => {}
            (None, None, None) => {
                return Err(Error::InvalidSetting { field: "ocv".into(), reason: "give `file` (discharge and charge in one recording) or `discharge` and/or `charge`".into() });
            }
            _ => return Err(Error::InvalidSetting { field: "ocv.file".into(), reason: "give either `file` or `discharge`/`charge`, not both".into() }),
        }
        if !(3..=100_000).contains(&self.points) {
            return Err(Error::invalid("ocv.points", self.points as f64, "must lie in 3..=100000"));
        }
        Ok(())
    }

    /// The recordings the stage reads.
    pub fn files(&self) -> impl Iterator<Item = &Path> {
        [&self.file, &self.discharge, &self.charge].into_iter().flatten().map(PathBuf::as_path)
    }
}

/// The branch of a recording (`discharge` or charge); an error naming `field` and the file
/// when it has none and it was given for that branch.
fn branch(field: &str, path: &Path, (rec, s): &(Recording, Vec<Step>), discharge: bool) -> Result<Option<OcvBranch>, Error> {
    let found = OcvBranch::find(rec, s, discharge);
    if found.is_none() && field != "ocv.file" {
        return Err(Error::InvalidSetting {
            field: field.into(),
            reason: format!(
                "`{}` has no constant-current {} step (its steps:\n{})",
                path.display(),
                if discharge { "discharge" } else { "charge" },
                crate::data::cycler::step_table(s)
            ),
        });
    }
    Ok(found)
}

/// Runs `[ocv]`: the pseudo-OCV goes to `stages.ocv` for the stages after it.
pub fn run_ocv(section: &OcvSection, stages: &mut Stages, dir: &Path) -> Result<StageOutput, Error> {
    let mut notes = Vec::new();
    let mut read = |f: &Path| recording_and_steps(f, &section.format, &stages.parameters, &mut notes);
    let (discharge, charge) = match &section.file {
        Some(f) => {
            let data = read(f)?;
            (branch("ocv.file", f, &data, true)?, branch("ocv.file", f, &data, false)?)
        }
        None => {
            let mut one = |field: &str, f: &Option<PathBuf>, discharge: bool| -> Result<Option<OcvBranch>, Error> {
                f.as_deref().map(|f| branch(field, f, &read(f)?, discharge)).transpose().map(Option::flatten)
            };
            (one("ocv.discharge", &section.discharge, true)?, one("ocv.charge", &section.charge, false)?)
        }
    };
    if let (Some(f), true) = (&section.file, discharge.is_none() || charge.is_none()) {
        if discharge.is_none() && charge.is_none() {
            return Err(Error::InvalidSetting { field: "ocv.file".into(), reason: format!("`{}` has no constant-current discharge or charge step", f.display()) });
        }
        notes.push(format!(
            "`{}` has no constant-current {} step: the pseudo-OCV is the other branch alone, with its overpotential and no hysteresis band",
            f.display(),
            if discharge.is_none() { "discharge" } else { "charge" }
        ));
    } else if section.file.is_none() && (discharge.is_none() || charge.is_none()) {
        notes.push("one branch only: the pseudo-OCV carries that branch's overpotential and has no hysteresis band".into());
    }
    let ocv = PseudoOcv::new(discharge, charge, section.points).expect("a branch was found");
    let nominal = stages.parameters.cell.nominal_capacity;
    let mut files = Vec::new();
    super::write_output(dir, "ocv.csv", ocv.csv(), &mut files)?;
    let mut series = vec![Series { label: "pseudo-OCV".into(), x: &ocv.soc, y: &ocv.voltage }];
    let branch_curves: Vec<(String, Vec<f64>)> = [("discharge", &ocv.discharge), ("charge", &ocv.charge)]
        .into_iter()
        .filter_map(|(name, b)| b.as_ref().map(|b| (format!("{name} at C/{:.0}", nominal / b.mean_current.abs()), ocv.soc.iter().map(|&s| b.at(s)).collect())))
        .collect();
    series.extend(branch_curves.iter().map(|(label, y)| Series { label: label.clone(), x: &ocv.soc, y }));
    let plot = dir.join("ocv.svg");
    line_plot(&plot, "pseudo-OCV", "state of charge (-)", "voltage (V)", &series)?;
    files.push(plot);
    let gap_mv: Vec<f64> = ocv.half_gap.iter().map(|g| 1e3 * g).collect();
    let plot = dir.join("ocv_hysteresis.svg");
    line_plot(&plot, "hysteresis band: half the charge-discharge gap", "state of charge (-)", "half gap (mV)", &[Series { label: "half gap".into(), x: &ocv.soc, y: &gap_mv }])?;
    files.push(plot);
    let mut md = String::from("\n## Pseudo-OCV (`[ocv]`)\n\n");
    md.push_str("Each branch is put on a state-of-charge axis by its own charge (coulomb counting over the step, 0 at its empty end, 1 at its full end); the pseudo-OCV is the mean of the branches at the same state of charge, the hysteresis band half their gap (it holds the slow rate's overpotential as well as true hysteresis).\n\n");
    md.push_str("| branch | step | mean current (A) | rate | capacity (A h) |\n|---|---|---|---|---|\n");
    for (name, b) in [("discharge", &ocv.discharge), ("charge", &ocv.charge)] {
        if let Some(b) = b {
            let _ = writeln!(md, "| {name} | {} | {:.4} | C/{:.1} | {:.4} |", b.step, b.mean_current, nominal / b.mean_current.abs(), b.capacity);
        }
    }
    let gap = ocv.half_gap.iter().map(|g| g.abs());
    let (max_gap, mean_gap) = (gap.clone().fold(0.0, f64::max), gap.sum::<f64>() / ocv.half_gap.len() as f64);
    let _ = writeln!(
        md,
        "\nPseudo-OCV from {:.4} V (SOC 0) to {:.4} V (SOC 1) over {:.4} A h (mean of the branches); half gap {:.2} mV on average, {:.2} mV at most. Table: `ocv.csv`; plots: `ocv.svg`, `ocv_hysteresis.svg`.",
        ocv.voltage[0],
        ocv.voltage[ocv.voltage.len() - 1],
        ocv.capacity(),
        1e3 * mean_gap,
        1e3 * max_gap
    );
    let summary = format!(
        "ocv: {:.4} A h (discharge {}, charge {}), mean half gap {:.2} mV",
        ocv.capacity(),
        ocv.discharge.as_ref().map_or("-".into(), |b| format!("{:.4} A h", b.capacity)),
        ocv.charge.as_ref().map_or("-".into(), |b| format!("{:.4} A h", b.capacity)),
        1e3 * mean_gap
    );
    let json = serde_json::json!({
        "discharge": ocv.discharge, "charge": ocv.charge, "capacity_Ah": ocv.capacity(),
        "mean_half_gap_V": mean_gap, "max_half_gap_V": max_gap,
    });
    stages.ocv = Some(ocv);
    Ok(StageOutput { report: ReportSection { files, section: md, warnings: Vec::new() }, summary, notes, json })
}
