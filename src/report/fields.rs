//! Spatial fields of a simulation (concentration and potential profiles) at a few times: one
//! long-format CSV and one SVG per field.

use std::fmt::Write;
use std::path::{Path, PathBuf};

use super::plot::{Series, line_plot};
use crate::error::Error;
use crate::models::Model;
use crate::simulation::Solution;

/// Indices of the recorded outputs nearest to 0, 25, 50, 75 and 100 % of the simulated time.
pub fn snapshot_indices(time: &[f64]) -> Vec<usize> {
    let (Some(&t0), Some(&t1)) = (time.first(), time.last()) else { return Vec::new() };
    let mut idx: Vec<usize> = [0.0, 0.25, 0.5, 0.75, 1.0]
        .iter()
        .map(|f| {
            let target = t0 + f * (t1 - t0);
            let after = time.partition_point(|&t| t < target).min(time.len() - 1);
            if after > 0 && target - time[after - 1] < time[after] - target { after - 1 } else { after }
        })
        .collect();
    idx.dedup();
    idx
}

/// Writes `{stem}_fields.csv` (columns time_s, field, unit, axis, position_m, value) and
/// `{stem}_field_<name>.svg` for the fields of `model` at the snapshot times of `sol`, whose
/// states must have been kept. Returns the files written.
pub fn write_fields(model: &dyn Model, sol: &Solution, dir: &Path, stem: &str) -> Result<Vec<PathBuf>, Error> {
    if sol.states.len() != sol.time.len() {
        return Err(Error::invalid("states", 0.0, "spatial fields need the states kept at every output"));
    }
    let snapshots: Vec<(f64, Vec<crate::models::Field>)> =
        snapshot_indices(&sol.time).into_iter().map(|k| (sol.time[k], model.fields(&sol.states[k]))).collect();
    let Some((_, first)) = snapshots.first() else { return Ok(Vec::new()) };
    let mut csv = String::from("time_s,field,unit,axis,position_m,value\n");
    for (t, fields) in &snapshots {
        for f in fields {
            for (x, v) in f.position.iter().zip(&f.value) {
                let _ = writeln!(csv, "{t},{},{},{},{x},{v}", f.name, f.unit, f.axis);
            }
        }
    }
    let csv_path = dir.join(format!("{stem}_fields.csv"));
    crate::error::write_file(&csv_path, csv)?;
    let mut written = vec![csv_path];
    for (j, field) in first.iter().enumerate() {
        let microns: Vec<Vec<f64>> =
            snapshots.iter().map(|(_, fs)| fs[j].position.iter().map(|x| x * 1e6).collect()).collect();
        let series: Vec<Series> = snapshots
            .iter()
            .zip(&microns)
            .map(|((t, fs), x)| Series { label: format!("t = {t:.0} s"), x, y: &fs[j].value })
            .collect();
        let path = dir.join(format!("{stem}_field_{}.svg", field.name.replace(' ', "_")));
        let axis = format!("{} (um)", field.axis);
        line_plot(&path, field.name, &axis, &format!("{} ({})", field.name, field.unit), &series)?;
        written.push(path);
    }
    Ok(written)
}
