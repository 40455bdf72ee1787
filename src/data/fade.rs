//! A measured capacity-fade curve: discharge capacity (A h) per cycle number, as a cycler's
//! cycle statistics (or `cellstudio cycle`'s `cycles.csv`) give it.

use std::path::Path;

use crate::error::Error;

/// Discharge capacity per cycle.
#[derive(Clone, Debug, PartialEq)]
pub struct CapacityFade {
    /// Cycle numbers, from 1, strictly increasing (cycles may be skipped).
    pub cycles: Vec<usize>,
    /// Discharge capacity of each cycle (A h).
    pub capacity: Vec<f64>,
}

/// The header names read (any case): cycle number and discharge capacity in A h.
pub const CYCLE_COLUMN: &str = "cycle";
pub const CAPACITY_COLUMN: &str = "discharge_capacity_Ah";

impl CapacityFade {
    /// Reads a CSV with a header row holding [`CYCLE_COLUMN`] and [`CAPACITY_COLUMN`]. Errors
    /// name the file, line, column and value: a missing column, a cycle that is not a whole
    /// number from 1 or does not increase, a capacity that is not positive and finite, fewer
    /// than 3 rows.
    pub fn from_csv(path: &Path) -> Result<Self, Error> {
        let name = path.display().to_string();
        let fail = |message: String| Error::Parse { path: name.clone(), message };
        let mut reader = csv::Reader::from_reader(std::fs::File::open(path).map_err(Error::io(path))?);
        let headers = reader.headers().map_err(|e| fail(e.to_string()))?.clone();
        let column = |wanted: &str| {
            headers.iter().position(|h| h.trim().eq_ignore_ascii_case(wanted)).ok_or_else(|| {
                fail(format!("missing column `{wanted}` (found: {})", headers.iter().collect::<Vec<_>>().join(", ")))
            })
        };
        let (cc, cq) = (column(CYCLE_COLUMN)?, column(CAPACITY_COLUMN)?);
        let mut fade = CapacityFade { cycles: Vec::new(), capacity: Vec::new() };
        for (row, record) in reader.records().enumerate() {
            let record = record.map_err(|e| fail(e.to_string()))?;
            let line = row + 2;
            let value = |col: usize| -> Result<f64, Error> {
                let text = record.get(col).unwrap_or("").trim();
                text.parse::<f64>().map_err(|_| fail(format!("line {line}: `{}` = `{text}` is not a number", &headers[col])))
            };
            let cycle = value(cc)?;
            if !(cycle >= 1.0 && cycle.fract() == 0.0 && cycle < 1e9) {
                return Err(fail(format!("line {line}: `{}` = {cycle} is not a cycle number (a whole number from 1)", &headers[cc])));
            }
            let cycle = cycle as usize;
            if let Some(&previous) = fade.cycles.last().filter(|p| cycle <= **p) {
                return Err(fail(format!("line {line}: `{}` = {cycle} does not increase (previous {previous})", &headers[cc])));
            }
            let q = value(cq)?;
            if !(q > 0.0 && q.is_finite()) {
                return Err(fail(format!("line {line}: `{}` = {q} A h is not a discharge capacity (positive and finite)", &headers[cq])));
            }
            fade.cycles.push(cycle);
            fade.capacity.push(q);
        }
        if fade.cycles.len() < 3 {
            return Err(fail(format!("needs at least 3 cycles to show a fade, found {}", fade.cycles.len())));
        }
        Ok(fade)
    }

    /// The last cycle number.
    pub fn last_cycle(&self) -> usize {
        *self.cycles.last().expect("a fade curve holds at least 3 cycles")
    }
}
