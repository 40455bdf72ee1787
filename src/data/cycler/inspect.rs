//! What `cellstudio data inspect FILE` prints: the detected format, rows, time span and the
//! steps table, as text or JSON.

use std::fmt::Write as _;
use std::path::Path;

use super::{CyclerData, step_table, steps};

/// The summary of a read cycler file as aligned text lines and a Markdown steps table.
pub fn inspect_text(file: &Path, data: &CyclerData) -> String {
    let rec = &data.recording;
    let st = steps(rec, data.step.as_deref());
    let mut s = String::new();
    let _ = writeln!(s, "file             {}", file.display());
    let _ = writeln!(s, "format           {}", data.format);
    let _ = writeln!(s, "rows             {} ({} repeated rows dropped)", rec.time.len(), data.dropped_repeats);
    let (first, last) = (rec.time.first().copied().unwrap_or(0.0), rec.time.last().copied().unwrap_or(0.0));
    let _ = writeln!(s, "duration         {:.1} s (first row at {} s of the file's clock)", last - first, data.time_offset + first);
    let _ = writeln!(s, "temperature      {}", if rec.temperature.is_some() { "yes" } else { "no" });
    let _ = write!(s, "steps            {}\n\n{}", st.len(), step_table(&st));
    s
}

/// The same summary as JSON (steps with their first and last rows).
pub fn inspect_json(file: &Path, data: &CyclerData) -> serde_json::Value {
    let rec = &data.recording;
    serde_json::json!({
        "file": file.display().to_string(),
        "format": data.format,
        "rows": rec.time.len(),
        "dropped_repeats": data.dropped_repeats,
        "duration_s": rec.time.last().zip(rec.time.first()).map(|(last, first)| last - first),
        "time_offset_s": data.time_offset + rec.time.first().copied().unwrap_or(0.0),
        "temperature": rec.temperature.is_some(),
        "steps": steps(rec, data.step.as_deref()),
    })
}
