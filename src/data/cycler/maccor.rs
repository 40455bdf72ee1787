//! Maccor text/CSV exports, in two layouts:
//!
//! - signed current, charge positive: PyProBE's sample (`ImperialCollegeLondon/PyProBE`,
//!   `tests/sample_data/maccor/sample_data_maccor.csv`, read by `pyprobe/cyclers/maccor.py`):
//!   two metadata lines (`Today's Date`, `Date of Test:`), then `Rec,Cycle C,Step,Test Time
//!   (sec),Step Time (sec),Capacity,Energy,Current,Voltage,DPT Time,Temp 1`;
//! - unsigned current with a state column: the tab-separated `Rec# Cyc# Step Test (Sec)
//!   Step (Sec) Amp-hr Watt-hr Amps Volts State ES DPt Time` export that BEEP reads
//!   (`TRI-AMDD/beep`, `beep/conversion_schemas/maccor_conversion.yaml`: `charge_state_code:
//!   'C'`, `discharge_state_code: 'D'`), `R` for rest; some exports name the state `MD`.
//!
//! Current in A, voltage in V, time in s, `Temp 1` in °C.

use super::table::{Layout, TimeKind, column, current_factor, first_column, kelvin_offset, required, time_factor, voltage_factor};

/// The header line of a Maccor export among the first lines.
pub fn header(lines: &[&str]) -> Option<usize> {
    lines.iter().take(20).position(|l| {
        let l = l.to_ascii_lowercase();
        l.starts_with("rec") && (l.contains("test time (sec)") || l.contains("test (sec)"))
    })
}

/// Column layout of a Maccor header.
pub fn layout(headers: &[String]) -> Result<Layout, String> {
    let (ct, ut) = required(headers, "time", &["Test Time", "Test"])?;
    let (ci, ui) = required(headers, "current", &["Current", "Amps"])?;
    let (cv, uv) = required(headers, "voltage", &["Voltage", "Volts"])?;
    let state = first_column(headers, &["MD", "State"]).map(|c| c.0);
    // With a state column the current is a magnitude (signed by the state); without, it is
    // signed charge positive.
    let sign = if state.is_some() { 1.0 } else { -1.0 };
    Ok(Layout {
        time: (ct, TimeKind::Seconds(time_factor(&ut.to_ascii_lowercase(), &headers[ct])?)),
        current: (ci, sign * current_factor(&ui, &headers[ci])?),
        state,
        voltage: (cv, voltage_factor(&uv, &headers[cv])?),
        temperature: first_column(headers, &["Temp 1"]).map(|(k, u)| (k, kelvin_offset(&u))),
        step: column(headers, "Step").map(|c| c.0),
        drop_repeats: true,
    })
}
