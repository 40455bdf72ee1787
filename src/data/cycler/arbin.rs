//! Arbin MITS Pro CSV exports, new style (`Data Point,Date Time,Test Time (s),Step Time
//! (s),Cycle Index,Step Index,…,Current (A),Voltage (V),…,Aux_Temperature_1 (C)`, as in
//! PyProBE's sample `ImperialCollegeLondon/PyProBE`,
//! `tests/sample_data/arbin/sample_data_arbin.csv`, read by `pyprobe/cyclers/arbin.py`) and
//! old style (`Data_Point,Test_Time(s),…,Step_Index,Current(A),Voltage(V),…`, as BEEP's
//! `TRI-AMDD/beep`, `beep/conversion_schemas/arbin_conversion.yaml`). Current is charge
//! positive (PyProBE keeps it as is in its charge-positive convention): the reader flips it.

use super::table::{Layout, TimeKind, current_factor, first_column, kelvin_offset, required, time_factor, voltage_factor};

/// The header line of an Arbin export among the first lines.
pub fn header(lines: &[&str]) -> Option<usize> {
    lines.iter().take(20).position(|l| (l.contains("Test Time (s)") || l.contains("Test_Time(s)")) && l.contains("Current"))
}

/// Column layout of an Arbin header.
pub fn layout(headers: &[String]) -> Result<Layout, String> {
    let (ct, ut) = required(headers, "time", &["Test Time", "Test_Time"])?;
    let (ci, ui) = required(headers, "current", &["Current"])?;
    let (cv, uv) = required(headers, "voltage", &["Voltage"])?;
    Ok(Layout {
        time: (ct, TimeKind::Seconds(time_factor(&ut, &headers[ct])?)),
        current: (ci, -current_factor(&ui, &headers[ci])?),
        state: None,
        voltage: (cv, voltage_factor(&uv, &headers[cv])?),
        temperature: first_column(headers, &["Aux_Temperature_1", "Temperature"]).map(|(k, u)| (k, kelvin_offset(&u))),
        step: first_column(headers, &["Step Index", "Step_Index"]).map(|c| c.0),
        drop_repeats: true,
    })
}
