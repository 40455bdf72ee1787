//! Basytec CTS exports, in the two layouts seen in the wild:
//!
//! - the result-file text export (`~Resultfile from Basytec Battery Test System`, metadata
//!   lines starting with `~`, the last of them the tab-separated header `~Time[s] DataSet …
//!   Line Command U[V] I[A] … T1[°C] …`), as PyProBE reads it
//!   (`ImperialCollegeLondon/PyProBE`, `pyprobe/cyclers/basytec.py`: time `~Time[*]`, step
//!   `Line`, current `I[*]`, voltage `U[*]`, temperature `T1[*]`);
//! - the CSV export of the WMG LG M50 campaign (`brosaplanella/TEC-reduced-model`,
//!   `data/*/Cell*_*.csv`): metadata (`Measurement ID`, `Program`, …), the header
//!   `Step,Status,Step Time,Prog Time,…,Voltage,Current,…,LogTempMid,…` and a units row
//!   `[],[],[ss.xxx],[ss.xxx],…,[V],[A],…,[T1],…`; time is `Prog Time` in seconds,
//!   temperatures are thermocouples in °C (`LogTempMid` the cell's middle, else the first
//!   `LogTemp…`).
//!
//! Both log discharge as negative current (the M50 recordings' README: "discharge logged
//! negative by the Basytec cycler"); the reader flips it.

use super::table::{Layout, TimeKind, column, current_factor, first_column, kelvin_offset, required, time_factor, voltage_factor};

/// The header line of a Basytec export among the first lines.
pub fn header(lines: &[&str]) -> Option<usize> {
    let result_file = lines.first().is_some_and(|l| l.starts_with("~Resultfile from Basytec"));
    let tilde = lines.iter().position(|l| l.starts_with("~Time["));
    if let (true, Some(k)) = (result_file, tilde) {
        return Some(k);
    }
    tilde.or_else(|| lines.iter().position(|l| l.starts_with("Step,Status,Step Time,Prog Time")))
}

/// Column layout of a Basytec header.
pub fn layout(headers: &[String]) -> Result<Layout, String> {
    let (ct, ut) = required(headers, "time", &["~Time", "Prog Time"])?;
    let (ci, ui) = required(headers, "current", &["I", "Current"])?;
    let (cv, uv) = required(headers, "voltage", &["U", "Voltage"])?;
    let temperature = first_column(headers, &["T1", "LogTempMid"])
        .or_else(|| headers.iter().position(|h| h.starts_with("LogTemp")).map(|k| (k, String::new())))
        .map(|(k, u)| (k, kelvin_offset(&u)));
    Ok(Layout {
        time: (ct, TimeKind::Seconds(time_factor(&ut, &headers[ct])?)),
        current: (ci, -current_factor(&ui, &headers[ci])?),
        state: None,
        voltage: (cv, voltage_factor(&uv, &headers[cv])?),
        temperature,
        step: column(headers, "Line").or_else(|| column(headers, "Step")).map(|c| c.0),
        drop_repeats: true,
    })
}
