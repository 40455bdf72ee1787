//! A time series of current, voltage and (optionally) temperature from a cycler or from
//! another simulator.

use std::path::Path;

use crate::error::Error;
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
    /// Reads a CSV file with a header row. Columns are found by name: `time_s`,
    /// `current_A`, `voltage_V` and optionally `temperature_K`.
    pub fn from_csv(path: &Path) -> Result<Self, Error> {
        let name = path.display().to_string();
        let parse_err = |message: String| Error::Parse { path: name.clone(), message };
        let mut reader = csv::Reader::from_path(path).map_err(|e| parse_err(e.to_string()))?;
        let headers = reader.headers().map_err(|e| parse_err(e.to_string()))?.clone();
        let column = |wanted: &str| headers.iter().position(|h| h.trim() == wanted);
        let required = |wanted: &str| {
            column(wanted).ok_or_else(|| parse_err(format!("missing column `{wanted}` (found: {})", headers.iter().collect::<Vec<_>>().join(", "))))
        };
        let (ct, ci, cv) = (required("time_s")?, required("current_A")?, required("voltage_V")?);
        let ctemp = column("temperature_K");
        let mut rec = Recording { temperature: ctemp.map(|_| Vec::new()), ..Default::default() };
        for (row, record) in reader.records().enumerate() {
            let record = record.map_err(|e| parse_err(e.to_string()))?;
            let line = row + 2;
            let value = |col: usize, what: &str| -> Result<f64, Error> {
                let text = record.get(col).unwrap_or("").trim();
                let v: f64 = text
                    .parse()
                    .map_err(|_| parse_err(format!("line {line}: `{what}` = `{text}` is not a number")))?;
                if v.is_finite() { Ok(v) } else { Err(parse_err(format!("line {line}: `{what}` is {v}"))) }
            };
            rec.time.push(value(ct, "time_s")?);
            rec.current.push(value(ci, "current_A")?);
            rec.voltage.push(value(cv, "voltage_V")?);
            if let (Some(c), Some(t)) = (ctemp, rec.temperature.as_mut()) {
                t.push(value(c, "temperature_K")?);
            }
        }
        if rec.time.len() < 2 {
            return Err(parse_err(format!("needs at least 2 data rows, found {}", rec.time.len())));
        }
        if let Some(k) = rec.time.windows(2).position(|w| !(w[1] >= w[0])) {
            return Err(parse_err(format!(
                "line {}: `time_s` = {} does not increase (previous {})",
                k + 3,
                rec.time[k + 1],
                rec.time[k]
            )));
        }
        Ok(rec)
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
        let n = self.time.len();
        for (k, (&tr, &vr)) in self.time.iter().zip(&self.voltage).enumerate() {
            let repeated = (k > 0 && self.time[k - 1] == tr) || (k + 1 < n && self.time[k + 1] == tr);
            if tr < t0 || tr > t1 || repeated {
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
