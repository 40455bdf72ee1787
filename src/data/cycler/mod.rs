//! Raw cycler exports: detection of the vendor from the header, one reader per vendor
//! (Basytec, BioLogic, Maccor, Neware, Arbin, PyProBE's processed tables as Parquet or CSV;
//! this crate's own CSV as `Native`), conversion to a [`Recording`] (s, A discharge positive,
//! V, K) with the cycler's step numbers, and the split into steps ([`steps`]).

mod arbin;
mod basytec;
mod biologic;
mod inspect;
mod maccor;
mod neware;
mod parquet_table;
mod pyprobe;
mod steps;
mod table;

use std::path::Path;

use serde::Serialize;

pub use inspect::{inspect_json, inspect_text};
pub use steps::{CV_TOLERANCE, PULSE_MAX_DURATION, Step, StepKind, step_table, steps};
use table::{Layout, TimeKind};

use super::{CsvFormat, Recording};
use crate::error::Error;

/// The vendor layout of a file.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
pub enum CyclerFormat {
    /// This crate's CSV: `time_s,current_A,voltage_V[,temperature_K]`, discharge positive.
    Native,
    Basytec,
    BioLogic,
    Maccor,
    Neware,
    Arbin,
    /// PyProBE's processed table (`Time [s]`, `Current [A]`, ...), as Parquet or CSV.
    PyProbe,
}

impl std::fmt::Display for CyclerFormat {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        std::fmt::Debug::fmt(self, f)
    }
}

/// Lines read when looking for a header (BioLogic headers run to about 100 lines).
const HEADER_SEARCH_LINES: usize = 400;

type HeaderFn = fn(&[&str]) -> Option<usize>;
type LayoutFn = fn(&[String]) -> Result<Layout, String>;

/// Vendors in the order they are tried (the most specific first).
const VENDORS: [(CyclerFormat, HeaderFn, LayoutFn); 7] = [
    (CyclerFormat::Native, native_header, native_layout),
    (CyclerFormat::PyProbe, pyprobe::header, pyprobe::layout),
    (CyclerFormat::Basytec, basytec::header, basytec::layout),
    (CyclerFormat::BioLogic, biologic::header, biologic::layout),
    (CyclerFormat::Arbin, arbin::header, arbin::layout),
    (CyclerFormat::Maccor, maccor::header, maccor::layout),
    (CyclerFormat::Neware, neware::header, neware::layout),
];

fn native_header(lines: &[&str]) -> Option<usize> {
    let first = lines.first()?;
    // Names as the CSV reader sees them: trimmed, quotes removed.
    let names: Vec<&str> = first.split(',').map(|n| n.trim().trim_matches('"')).collect();
    ["time_s", "current_A", "voltage_V"].iter().all(|n| names.contains(n)).then_some(0)
}

fn native_layout(headers: &[String]) -> Result<Layout, String> {
    let find = |name: &str| {
        headers.iter().position(|h| h == name).ok_or_else(|| format!("missing column `{name}`"))
    };
    Ok(Layout {
        time: (find("time_s")?, TimeKind::Seconds(1.0)),
        current: (find("current_A")?, 1.0),
        state: None,
        voltage: (find("voltage_V")?, 1.0),
        temperature: find("temperature_K").ok().map(|k| (k, 0.0)),
        step: None,
        drop_repeats: false,
    })
}

/// A cycler file read into SI units.
#[derive(Clone, Debug)]
pub struct CyclerData {
    pub format: CyclerFormat,
    /// Time (s) from the first row (this crate's CSV as [`read_with`] reads it: as
    /// recorded), current (A, discharge positive), voltage (V), temperature (K).
    pub recording: Recording,
    /// The cycler's step number of every row, when the file has one.
    pub step: Option<Vec<i64>>,
    /// Time of the recording's zero in the file's own clock (s; seconds since 1970 for
    /// calendar times).
    pub time_offset: f64,
    /// Rows dropped for repeating the previous row's time and current.
    pub dropped_repeats: usize,
}

/// The vendor of `text` by its header, if known.
///
/// ```
/// use cellstudio::data::cycler::{CyclerFormat, detect};
/// assert_eq!(detect("Rec,Cycle C,Step,Test Time (sec),Current,Voltage\n"), Some(CyclerFormat::Maccor));
/// assert_eq!(detect("hello\n"), None);
/// ```
pub fn detect(text: &str) -> Option<CyclerFormat> {
    let lines: Vec<&str> = text.lines().take(HEADER_SEARCH_LINES).collect();
    VENDORS.iter().find(|(_, header, _)| header(&lines).is_some()).map(|v| v.0)
}

/// Reads a cycler export given as text; `name` labels errors (the file name). Errors name
/// the vendor, line, column and value; no input panics.
pub fn read_str(name: &str, text: &str) -> Result<CyclerData, Error> {
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    let parse_err = |message: String| Error::Parse { path: name.to_string(), message };
    let lines: Vec<&str> = text.lines().collect();
    let head = &lines[..lines.len().min(HEADER_SEARCH_LINES)];
    let (format, header, layout) = VENDORS
        .iter()
        .find_map(|(f, header, layout)| header(head).map(|k| (*f, k, layout)))
        .ok_or_else(|| {
            if lines.iter().all(|l| l.trim().is_empty()) {
                return parse_err("the file is empty".into());
            }
            let first = lines.first().copied().unwrap_or_default();
            // Our columns separated by something else (a spreadsheet's `;` or a tab).
            let separator = [';', '\t'].into_iter().find(|&c| ["time_s", "current_A", "voltage_V"].iter().all(|n| first.split(c).any(|f| f.trim().trim_matches('"') == *n)));
            let hint = separator.map_or(String::new(), |c| format!("; its columns are separated by {c:?}: save it with commas (and `.` decimals)"));
            parse_err(format!(
                "not a known cycler export: no Basytec, BioLogic, Maccor, Neware, Arbin, PyProBE or time_s,current_A,voltage_V header in the first {HEADER_SEARCH_LINES} lines (first line: `{}`){hint}",
                first.chars().take(80).collect::<String>()
            ))
        })?;
    let table = table::table(&lines, header, 0);
    let layout = layout(&table.headers).map_err(|m| parse_err(format!("{format} export: {m}")))?;
    let rows = table::read_rows(&table, &layout).map_err(|m| parse_err(format!("{format} export: {m}")))?;
    Ok(CyclerData { format, recording: rows.recording, step: rows.step, time_offset: rows.time_offset, dropped_repeats: rows.dropped_repeats })
}

/// Reads a cycler export (any encoding; bytes that are not UTF-8, as Latin-1 degree signs,
/// are replaced), or a Parquet file.
pub fn read(path: &Path) -> Result<CyclerData, Error> {
    let bytes = std::fs::read(path).map_err(Error::io(path))?;
    read_bytes(path, &bytes)
}

/// [`read`] of the file's bytes: a Parquet file's rows as text, else the bytes as text.
fn read_bytes(path: &Path, bytes: &[u8]) -> Result<CyclerData, Error> {
    let name = path.display().to_string();
    if parquet_table::is_parquet(bytes) {
        let text = parquet_table::to_text(path).map_err(|message| Error::Parse { path: name.clone(), message })?;
        return read_str(&name, &text);
    }
    read_str(&name, &String::from_utf8_lossy(bytes))
}

/// The file `path` as a fit, a diagnosis and `data inspect` read it: with `format` when it is
/// not the default (the user said how to read the file) or when the file is this crate's CSV
/// ([`Recording::from_csv_with`], times as recorded); otherwise by the reader of the cycler
/// whose header it has; a file of neither kind is refused.
pub fn read_with(path: &Path, format: &CsvFormat) -> Result<CyclerData, Error> {
    let plain = |recording| CyclerData { format: CyclerFormat::Native, recording, step: None, time_offset: 0.0, dropped_repeats: 0 };
    if *format != CsvFormat::default() {
        return Ok(plain(Recording::from_csv_with(path, format)?));
    }
    let bytes = std::fs::read(path).map_err(Error::io(path))?;
    let text = String::from_utf8_lossy(&bytes);
    match detect(text.strip_prefix('\u{feff}').unwrap_or(&text)) {
        Some(CyclerFormat::Native) => Ok(plain(Recording::from_csv_with(path, format)?)),
        // A vendor's reader (or Parquet), or the error naming the vendors and the first line.
        _ => read_bytes(path, &bytes),
    }
}

/// The recording in `path` for a fit or a diagnosis ([`read_with`]).
pub fn read_recording(path: &Path, format: &CsvFormat) -> Result<Recording, Error> {
    Ok(read_with(path, format)?.recording)
}

/// [`read_with`], then checked against the cell `cell` as a fit and a diagnosis check it
/// ([`Recording::refuse_unit_errors`]: a likely unit or sign error is an error naming the
/// file); the other findings come back as notes.
pub fn read_checked(path: &Path, format: &CsvFormat, cell: &crate::params::ParameterSet) -> Result<(CyclerData, Vec<String>), Error> {
    let data = read_with(path, format)?;
    let notes = data.recording.refuse_unit_errors(&path.display().to_string(), cell)?;
    Ok((data, notes))
}
