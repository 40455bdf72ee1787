//! PyProBE's processed format (`ImperialCollegeLondon/PyProBE`, `pyprobe/cyclers/basecycler.py`
//! and the sample `tests/sample_data/LGM50/*.parquet`): columns `Time [s]`, `Step`, `Event`,
//! `Current [A]`, `Voltage [V]`, `Capacity [Ah]`, `Temperature [C]`, as Parquet
//! ([`super::parquet_table`]) or the same columns as CSV. Current is charge positive (the sample's
//! C/10 discharge, step 5, carries -0.5 A while the voltage falls): the reader flips it.

use super::table::{Layout, TimeKind, current_factor, first_column, kelvin_offset, required, time_factor, voltage_factor};

/// The header line of a PyProBE table among the first lines.
pub fn header(lines: &[&str]) -> Option<usize> {
    lines.iter().take(20).position(|l| l.contains("Time [s]") && l.contains("Current [A]") && l.contains("Voltage [V]"))
}

/// Column layout of a PyProBE header.
pub fn layout(headers: &[String]) -> Result<Layout, String> {
    let (ct, ut) = required(headers, "time", &["Time"])?;
    let (ci, ui) = required(headers, "current", &["Current"])?;
    let (cv, uv) = required(headers, "voltage", &["Voltage"])?;
    Ok(Layout {
        time: (ct, TimeKind::Seconds(time_factor(&ut, &headers[ct])?)),
        current: (ci, -current_factor(&ui, &headers[ci])?),
        state: None,
        voltage: (cv, voltage_factor(&uv, &headers[cv])?),
        temperature: first_column(headers, &["Temperature"]).map(|(k, u)| (k, kelvin_offset(&u))),
        step: first_column(headers, &["Step"]).map(|c| c.0),
        drop_repeats: true,
    })
}
