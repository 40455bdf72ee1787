//! BioLogic EC-Lab / BT-Lab text exports (`.mpt`, or `.txt`/`.csv` from "Export as text"):
//! an optional header block (`EC-Lab ASCII FILE`, then `Nb header lines : N`, the column
//! row being line N), tab- (or `;`/`,`-) separated columns `mode ox/red … Ns … time/s …
//! Ecell/V I/mA …`, Latin-1 text (`Temperature/°C`). Following PyProBE
//! (`ImperialCollegeLondon/PyProBE`, `pyprobe/cyclers/biologic.py`): time `time/s`, step
//! `Ns`, current `I/mA` or `<I>/mA`, voltage `Ecell/V` or `Ewe/V`, temperature
//! `Temperature/°C`. The current is positive when the working electrode (the positive
//! electrode of a full cell) is oxidised, i.e. on charge (PyProBE keeps it as is in its
//! charge-positive convention): the reader flips it. Exports whose `time/s` holds a calendar
//! time (PyProBE handles those) are not read: the error names the line and value.

use super::table::{Layout, TimeKind, column, current_factor, first_column, kelvin_offset, required, time_factor, voltage_factor};

/// The header line of a BioLogic export among the first lines.
pub fn header(lines: &[&str]) -> Option<usize> {
    let banner = lines.first().is_some_and(|l| l.contains("ASCII FILE"));
    if banner {
        let n: usize = lines.get(1)?.strip_prefix("Nb header lines")?.split(':').nth(1)?.trim().parse().ok()?;
        return (n >= 1 && n <= lines.len()).then(|| n - 1);
    }
    lines.iter().take(3).position(|l| l.contains("time/") && (l.contains("Ecell/") || l.contains("Ewe/")))
}

/// Column layout of a BioLogic header.
pub fn layout(headers: &[String]) -> Result<Layout, String> {
    let (ct, ut) = required(headers, "time", &["time"])?;
    let (ci, ui) = required(headers, "current", &["I", "<I>"])?;
    let (cv, uv) = required(headers, "voltage", &["Ecell", "Ewe"])?;
    Ok(Layout {
        time: (ct, TimeKind::Seconds(time_factor(&ut, &headers[ct])?)),
        current: (ci, -current_factor(&ui, &headers[ci])?),
        state: None,
        voltage: (cv, voltage_factor(&uv, &headers[cv])?),
        temperature: first_column(headers, &["Temperature"]).map(|(k, u)| (k, kelvin_offset(&u))),
        step: column(headers, "Ns").map(|c| c.0),
        drop_repeats: true,
    })
}
