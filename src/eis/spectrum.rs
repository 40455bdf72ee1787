//! An impedance spectrum: frequencies (Hz) and complex impedance (ohm), with CSV exchange.

use std::path::Path;

use serde::{Deserialize, Serialize};

use crate::error::Error;

/// Impedance `z_re + i z_im` (ohm) at each frequency (Hz). Current is discharge-positive and
/// `Z = -dV/dI`, so a cell has `Re Z > 0` and capacitive behaviour shows as `Im Z < 0`.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Spectrum {
    /// Frequency (Hz), positive.
    pub frequency: Vec<f64>,
    /// Real part of the impedance (ohm).
    pub z_re: Vec<f64>,
    /// Imaginary part of the impedance (ohm).
    pub z_im: Vec<f64>,
}

/// CSV column names.
const COLUMNS: [&str; 3] = ["frequency_Hz", "z_re_ohm", "z_im_ohm"];

/// Checks that there is at least one frequency and every one is positive and finite.
pub(crate) fn check_frequencies(frequencies: &[f64]) -> Result<(), Error> {
    if frequencies.is_empty() {
        return Err(Error::InvalidSetting { field: "frequency".into(), reason: "no frequencies".into() });
    }
    for (i, &f) in frequencies.iter().enumerate() {
        if !(f > 0.0 && f.is_finite()) {
            return Err(Error::invalid(format!("frequency[{i}]"), f, "must be positive and finite"));
        }
    }
    Ok(())
}

/// `n` frequencies (Hz) spaced evenly in log from `f_max` down to `f_min`, as analysers sweep.
///
/// ```
/// let f = cellstudio::eis::log_frequencies(1e-3, 1e3, 7).unwrap();
/// assert!((f[0] - 1e3).abs() < 1e-9 && (f[6] - 1e-3).abs() < 1e-15);
/// assert!(cellstudio::eis::log_frequencies(0.0, 1.0, 5).is_err());
/// ```
pub fn log_frequencies(f_min: f64, f_max: f64, n: usize) -> Result<Vec<f64>, Error> {
    check_frequencies(&[f_min, f_max])?;
    if !(f_max > f_min) || !(2..=1_000_000).contains(&n) {
        return Err(Error::invalid("frequency", f_max, format!("need f_max > f_min = {f_min} and 2 <= n <= 1000000 (n = {n})")));
    }
    let (a, b) = (f_max.log10(), f_min.log10());
    Ok((0..n).map(|k| 10f64.powf(a + (b - a) * k as f64 / (n - 1) as f64)).collect())
}

impl Spectrum {
    /// A validated spectrum.
    pub fn new(frequency: Vec<f64>, z_re: Vec<f64>, z_im: Vec<f64>) -> Result<Self, Error> {
        let s = Self { frequency, z_re, z_im };
        s.validate()?;
        Ok(s)
    }

    /// Equal lengths, at least one point, positive frequencies, finite impedances.
    pub fn validate(&self) -> Result<(), Error> {
        check_frequencies(&self.frequency)?;
        let n = self.frequency.len();
        if self.z_re.len() != n || self.z_im.len() != n {
            return Err(Error::InvalidSetting {
                field: "spectrum".into(),
                reason: format!("{n} frequencies, {} real parts, {} imaginary parts", self.z_re.len(), self.z_im.len()),
            });
        }
        for (name, v) in [("z_re", &self.z_re), ("z_im", &self.z_im)] {
            if let Some(i) = v.iter().position(|x| !x.is_finite()) {
                return Err(Error::invalid(format!("{name}[{i}]"), v[i], "must be finite"));
            }
        }
        Ok(())
    }

    /// Number of frequencies.
    pub fn len(&self) -> usize {
        self.frequency.len()
    }

    pub fn is_empty(&self) -> bool {
        self.frequency.is_empty()
    }

    /// `|Z|` (ohm) at point `i`.
    pub fn magnitude(&self, i: usize) -> f64 {
        self.z_re[i].hypot(self.z_im[i])
    }

    /// Phase of `Z` (rad) at point `i`, in (-pi, pi].
    pub fn phase(&self, i: usize) -> f64 {
        self.z_im[i].atan2(self.z_re[i])
    }

    /// Writes the columns `frequency_Hz,z_re_ohm,z_im_ohm`.
    pub fn write_csv(&self, path: &Path) -> Result<(), Error> {
        use std::fmt::Write;
        let mut s = COLUMNS.join(",");
        s.push('\n');
        for i in 0..self.len() {
            let _ = writeln!(s, "{},{},{}", self.frequency[i], self.z_re[i], self.z_im[i]);
        }
        crate::error::write_file(path, s)
    }

    /// Reads a CSV file with a header row naming the columns `frequency_Hz`, `z_re_ohm` and
    /// `z_im_ohm` (any order, other columns ignored). Errors name the line and value.
    pub fn from_csv(path: &Path) -> Result<Self, Error> {
        let name = path.display().to_string();
        let parse_err = |message: String| Error::Parse { path: name.clone(), message };
        let mut reader = csv::Reader::from_reader(std::fs::File::open(path).map_err(Error::io(path))?);
        let headers = reader.headers().map_err(|e| parse_err(e.to_string()))?.clone();
        let mut cols = [0usize; 3];
        for (slot, wanted) in cols.iter_mut().zip(COLUMNS) {
            *slot = headers.iter().position(|h| h.trim() == wanted).ok_or_else(|| {
                parse_err(format!("missing column `{wanted}` (found: {})", headers.iter().collect::<Vec<_>>().join(", ")))
            })?;
        }
        let mut values: [Vec<f64>; 3] = Default::default();
        for (row, record) in reader.records().enumerate() {
            let record = record.map_err(|e| parse_err(e.to_string()))?;
            let line = row + 2;
            for ((&col, wanted), out) in cols.iter().zip(COLUMNS).zip(values.iter_mut()) {
                let text = record.get(col).unwrap_or("").trim();
                let v: f64 =
                    text.parse().map_err(|_| parse_err(format!("line {line}: `{wanted}` = `{text}` is not a number")))?;
                if !v.is_finite() {
                    return Err(parse_err(format!("line {line}: `{wanted}` is {v}")));
                }
                if wanted == COLUMNS[0] && v <= 0.0 {
                    return Err(parse_err(format!("line {line}: `{wanted}` = {v} must be positive")));
                }
                out.push(v);
            }
        }
        if values[0].is_empty() {
            return Err(parse_err("no data rows".into()));
        }
        let [frequency, z_re, z_im] = values;
        Self::new(frequency, z_re, z_im)
    }
}
