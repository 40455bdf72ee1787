//! The files of a model-discrepancy diagnosis: `diagnosis.md` (the conclusion over the rounds,
//! then each round's report with its plots), `diagnosis.json` and the plots.

use std::fmt::Write;
use std::path::{Path, PathBuf};

use crate::diagnose::Diagnosis;
use crate::diagnose::report::{conclusion, markdown};
use crate::error::Error;

/// Writes `diagnosis.md`, `diagnosis.json` and the plots of every round into `dir`; returns
/// the files.
pub fn write(rounds: &[Diagnosis], dir: &Path) -> Result<Vec<PathBuf>, Error> {
    std::fs::create_dir_all(dir).map_err(Error::io(dir))?;
    let mut md = String::new();
    let mut files = Vec::new();
    for (k, d) in rounds.iter().enumerate() {
        let stem = if k == 0 { "diagnosis".to_string() } else { format!("diagnosis_round{}", k + 1) };
        let plots = super::diagnosis_plot::write_plots(d, dir, &stem)?;
        let names: Vec<(String, String)> = plots
            .iter()
            .map(|(title, p)| (title.clone(), p.file_name().map(|n| n.to_string_lossy().into_owned()).unwrap_or_default()))
            .collect();
        if rounds.len() > 1 {
            let _ = writeln!(md, "{}# Round {} of {}\n", if k > 0 { "\n---\n\n" } else { "" }, k + 1, rounds.len());
        }
        md.push_str(&markdown(d, &names));
        files.extend(plots.into_iter().map(|(_, p)| p));
    }
    if rounds.len() > 1 {
        md.insert_str(0, &format!("{}\n\n", conclusion(rounds)));
    }
    let md_path = dir.join("diagnosis.md");
    crate::error::write_file(&md_path, md)?;
    let json = dir.join("diagnosis.json");
    let text = serde_json::to_string_pretty(rounds).map_err(|e| Error::Parse { path: json.display().to_string(), message: e.to_string() })?;
    crate::error::write_file(&json, text)?;
    files.splice(0..0, [md_path, json]);
    Ok(files)
}
