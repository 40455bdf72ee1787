//! Neware BTS CSV exports (the "record" sheet saved as CSV): columns such as `Record ID`,
//! `Step ID` / `Step Index`, `Step Type`, `Total Time` (elapsed `h:mm:ss.fff`) or `Realtime`
//! / `Date` (calendar time), `Current(mA)` or `Current(A)`, `Voltage(V)`, `T1(℃)` or
//! `Temperature(C)`. Column names follow BEEP (`TRI-AMDD/beep`,
//! `beep/conversion_schemas/neware_conversion.yaml`) and PyProBE
//! (`ImperialCollegeLondon/PyProBE`, `pyprobe/cyclers/neware.py` and
//! `tests/cyclers/test_neware.py`, where discharge rows carry negative `Current(mA)` while
//! `DChg. Cap.(mAh)` grows): discharge is negative, so the reader flips it.

use super::table::{Layout, TimeKind, current_factor, first_column, kelvin_offset, required, voltage_factor};

/// The header line of a Neware export among the first lines.
pub fn header(lines: &[&str]) -> Option<usize> {
    lines.iter().take(20).position(|l| {
        l.contains("Voltage(V)") && l.contains("Current(") && (l.contains("Step ID") || l.contains("Step Index"))
    })
}

/// Column layout of a Neware header.
pub fn layout(headers: &[String]) -> Result<Layout, String> {
    let (ct, _) = required(headers, "time", &["Total Time", "Realtime", "Date"])?;
    let (ci, ui) = required(headers, "current", &["Current"])?;
    let (cv, uv) = required(headers, "voltage", &["Voltage"])?;
    Ok(Layout {
        time: (ct, TimeKind::Clock),
        current: (ci, -current_factor(&ui, &headers[ci])?),
        state: None,
        voltage: (cv, voltage_factor(&uv, &headers[cv])?),
        temperature: first_column(headers, &["T1", "Temperature"]).map(|(k, u)| (k, kelvin_offset(&u))),
        step: first_column(headers, &["Step ID", "Step Index"]).map(|c| c.0),
        drop_repeats: true,
    })
}
