//! A time series of current, voltage and (optionally) temperature from a cycler or from
//! another simulator.

use std::path::Path;

use super::CsvFormat;
use crate::error::{Error, number};
use crate::params::check::TEMPERATURE_RANGE;
use crate::params::function::interpolate;

/// A recording: time (s, non-decreasing; a repeated time marks a current step, as PyBaMM
/// writes them), current (A, discharge positive), voltage (V), and optionally temperature (K).
#[derive(Clone, Debug, Default)]
pub struct Recording {
    pub time: Vec<f64>,
    pub current: Vec<f64>,
    pub voltage: Vec<f64>,
    pub temperature: Option<Vec<f64>>,
}

/// Voltage difference between a simulation and a recording over their common time span.
#[derive(Clone, Copy, Debug, serde::Serialize)]
pub struct VoltageError {
    /// Root-mean-square difference (V).
    pub rms: f64,
    /// Largest absolute difference (V).
    pub max: f64,
    /// Number of recorded points compared.
    pub points: usize,
}

impl Recording {
    /// Reads a CSV file with a header row whose columns are `time_s`, `current_A`,
    /// `voltage_V` and optionally `temperature_K` (discharge positive).
    pub fn from_csv(path: &Path) -> Result<Self, Error> {
        Self::from_csv_with(path, &CsvFormat::default())
    }

    /// Reads a CSV file with a header row, mapping columns, units and the current sign by
    /// `format`. Errors name the file, line, column and value: a missing column, an empty
    /// file, a value that is not a finite number, time that goes backwards, and voltages
    /// outside (0, 10) V (usually a wrong `voltage_unit`).
    pub fn from_csv_with(path: &Path, format: &CsvFormat) -> Result<Self, Error> {
        let name = path.display().to_string();
        let parse_err = |message: String| Error::Parse { path: name.clone(), message };
        let (kt, ki, kv) = (format.time_factor()?, format.current_factor()?, format.voltage_factor()?);
        let mut reader = csv::Reader::from_reader(std::fs::File::open(path).map_err(Error::io(path))?);
        let headers = reader.headers().map_err(|e| parse_err(e.to_string()))?.clone();
        let column = |wanted: &str| headers.iter().position(|h| h.trim() == wanted);
        let required = |wanted: &str| {
            column(wanted).ok_or_else(|| parse_err(format!("missing column `{wanted}` (found: {})", headers.iter().collect::<Vec<_>>().join(", "))))
        };
        let (ct, ci, cv) = (required(&format.time)?, required(&format.current)?, required(&format.voltage)?);
        let ctemp = format.temperature.as_deref().and_then(column);
        let mut rec = Recording { temperature: ctemp.map(|_| Vec::new()), ..Default::default() };
        for (row, record) in reader.records().enumerate() {
            let record = record.map_err(|e| parse_err(e.to_string()))?;
            let line = row + 2;
            let value = |col: usize| -> Result<f64, Error> {
                let what = &headers[col];
                let text = record.get(col).unwrap_or("").trim();
                let v: f64 = text
                    .parse()
                    .map_err(|_| parse_err(format!("line {line}: `{what}` = `{text}` is not a number")))?;
                if v.is_finite() { Ok(v) } else { Err(parse_err(format!("line {line}: `{what}` is {v}"))) }
            };
            rec.time.push(kt * value(ct)?);
            rec.current.push(ki * value(ci)?);
            let v = kv * value(cv)?;
            if !(v > 0.0 && v < 10.0) {
                return Err(parse_err(format!(
                    "line {line}: `{}` = {} V is not a cell voltage (check voltage_unit = `{}`)",
                    format.voltage, number(v), format.voltage_unit
                )));
            }
            rec.voltage.push(v);
            if let (Some(c), Some(t)) = (ctemp, rec.temperature.as_mut()) {
                let kelvin = format.temperature_in_kelvin(value(c)?)?;
                if !TEMPERATURE_RANGE.contains(&kelvin) {
                    return Err(parse_err(format!(
                        "line {line}: `{}` = {} K is not a cell temperature (check temperature_unit = `{}`: degC reads as K)",
                        &headers[c], number(kelvin), format.temperature_unit
                    )));
                }
                t.push(kelvin);
            }
        }
        if rec.time.len() < 2 {
            return Err(parse_err(format!("needs at least 2 data rows, found {}", rec.time.len())));
        }
        if let Some(k) = rec.time.windows(2).position(|w| !(w[1] >= w[0])) {
            return Err(parse_err(format!(
                "line {}: `{}` = {} does not increase (previous {})",
                k + 3,
                format.time,
                rec.time[k + 1],
                rec.time[k]
            )));
        }
        if let Some((k, reason)) = rec.time_shape_error() {
            return Err(parse_err(format!("line {}: `{}` = {} {reason}", k + 2, format.time, number(rec.time[k] / kt))));
        }
        Ok(rec)
    }

    /// What is wrong with the shape of a non-decreasing time column, if anything: the index of
    /// the row that breaks it and why. A repeated time marks one current step (two rows at one
    /// time, as PyBaMM writes them); a third row at that time carries a current that lasts no
    /// time, which no replay can honour. A recording whose rows all share one time spans
    /// nothing to simulate.
    pub fn time_shape_error(&self) -> Option<(usize, String)> {
        let t = &self.time;
        if let Some(k) = (2..t.len()).find(|&k| t[k] == t[k - 1] && t[k] == t[k - 2]) {
            return Some((k, "is the third row at this time: a repeated time marks one current step (two rows), and a third row's current would last no time; remove or re-time it".into()));
        }
        match (t.first(), t.last()) {
            (Some(first), Some(last)) if !(last > first) => {
                Some((t.len() - 1, "is the time of every row: the recording spans no time".into()))
            }
            _ => None,
        }
    }

    /// Writes the recording as CSV in this crate's default format.
    pub fn write_csv(&self, path: &Path) -> Result<(), Error> {
        use std::fmt::Write;
        let mut s = String::from("time_s,current_A,voltage_V");
        s.push_str(if self.temperature.is_some() { ",temperature_K\n" } else { "\n" });
        for k in 0..self.time.len() {
            let _ = write!(s, "{},{},{}", self.time[k], self.current[k], self.voltage[k]);
            match &self.temperature {
                Some(t) => { let _ = writeln!(s, ",{}", t[k]); }
                None => s.push('\n'),
            }
        }
        crate::error::write_file(path, s)
    }

    /// Whether point `k` shares its time with a neighbour (either side of a current step as
    /// PyBaMM writes them): its voltage is ambiguous.
    pub fn is_repeated(&self, k: usize) -> bool {
        let t = self.time[k];
        (k > 0 && self.time[k - 1] == t) || (k + 1 < self.time.len() && self.time[k + 1] == t)
    }

    /// Distinct recorded times (s), strictly increasing: output times for a simulation.
    pub fn distinct_times(&self) -> Vec<f64> {
        let mut t = self.time.clone();
        t.dedup();
        t
    }

    /// Compares simulated voltage `(t, v)` with the recording over the common time span.
    /// Points at a repeated time (either side of a current step) are ambiguous and skipped.
    pub fn voltage_error(&self, t: &[f64], v: &[f64]) -> VoltageError {
        let (t0, t1) = (t[0].max(self.time[0]), t[t.len() - 1].min(self.time[self.time.len() - 1]));
        let mut sum = 0.0;
        let mut max = 0.0f64;
        let mut points = 0;
        for (k, (&tr, &vr)) in self.time.iter().zip(&self.voltage).enumerate() {
            if tr < t0 || tr > t1 || self.is_repeated(k) {
                continue;
            }
            let d = interpolate(t, v, tr) - vr;
            sum += d * d;
            max = max.max(d.abs());
            points += 1;
        }
        VoltageError { rms: (sum / points.max(1) as f64).sqrt(), max, points }
    }
}
