//! The part every cycler export shares: metadata lines, a header row (and sometimes a units
//! row), then delimited data rows. A vendor module says which columns hold what
//! ([`Layout`]); this module reads the rows into a [`Recording`] with the cycler's step
//! numbers, naming the line, column and value of anything it cannot read.

use chrono::NaiveDateTime;

use crate::data::Recording;
use crate::params::check::TEMPERATURE_RANGE;

/// How a time column is written.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum TimeKind {
    /// A number in a unit of this many seconds (1 for s, 3600 for h).
    Seconds(f64),
    /// An elapsed time `h:mm:ss(.fff)` or a calendar time `YYYY-MM-DD hh:mm:ss(.fff)` /
    /// `MM/DD/YYYY hh:mm:ss(.fff)`; read as seconds since the first row.
    Clock,
}

/// Where the columns a recording needs sit, and how to convert them to SI with discharge
/// positive.
#[derive(Clone, Debug)]
pub struct Layout {
    /// Column of time and how it is written.
    pub time: (usize, TimeKind),
    /// Column of current and the factor to amperes, discharge positive (negative for a
    /// cycler that logs discharge negative; the magnitude converts mA to A).
    pub current: (usize, f64),
    /// A column whose text gives the sign of an unsigned current (Maccor `MD`/`State`:
    /// `D` discharge, `C` charge, `R` rest); with it, `current`'s factor is applied to |I|.
    pub state: Option<usize>,
    /// Column of voltage and the factor to volts.
    pub voltage: (usize, f64),
    /// Column of temperature and the offset to kelvin (273.15 for °C), if any.
    pub temperature: Option<(usize, f64)>,
    /// Column of the cycler's step number, if any.
    pub step: Option<usize>,
    /// Drop a row that repeats the previous row's time and current (a cycler logging a step
    /// change twice); `false` keeps every row (this crate's own CSV).
    pub drop_repeats: bool,
}

/// A delimited table: header names and the data rows with their 1-based line numbers.
pub struct Table<'a> {
    pub headers: Vec<String>,
    pub rows: Vec<(usize, Vec<&'a str>)>,
    /// Numbers may be written with a decimal comma (`3,7012`, as exports in European locales
    /// write them): only when the delimiter is a tab or a semicolon.
    pub decimal_comma: bool,
}

/// The delimiter of a header line: tab, semicolon or comma, whichever splits it most.
pub fn delimiter(header: &str) -> char {
    ['\t', ';', ',']
        .into_iter()
        .max_by_key(|d| header.matches(*d).count())
        .filter(|d| header.contains(*d))
        .unwrap_or(',')
}

/// Splits the lines after `header` (index into `lines`) into fields; skips `skip` lines after
/// the header (a units row) and blank lines. Trailing empty fields (a trailing delimiter)
/// are kept as empty strings and never read.
///
/// A units row (every non-empty field in brackets, as Basytec's `[V]`, `[A]`) right after the
/// header is merged into the names (`Voltage[V]`) and skipped.
pub fn table<'a>(lines: &[&'a str], header: usize, skip: usize) -> Table<'a> {
    let d = delimiter(lines[header]);
    let split = |l: &'a str| l.split(d).map(|f| f.trim().trim_matches('"')).collect::<Vec<_>>();
    let mut headers: Vec<String> = split(lines[header]).into_iter().map(str::to_string).collect();
    let mut skip = skip;
    if let Some(units) = lines.get(header + 1 + skip).map(|l| split(l)) {
        let bracketed = |f: &&str| f.starts_with('[') && f.ends_with(']');
        if units.iter().any(|f| !f.is_empty()) && units.iter().filter(|f| !f.is_empty()).all(bracketed) {
            for (h, u) in headers.iter_mut().zip(&units) {
                h.push_str(u);
            }
            skip += 1;
        }
    }
    let rows = lines
        .iter()
        .enumerate()
        .skip(header + 1 + skip)
        .filter(|(_, l)| !l.trim().is_empty())
        .map(|(k, l)| (k + 1, split(l)))
        .collect();
    Table { headers, rows, decimal_comma: d != ',' }
}

/// The column whose name is `name` followed by nothing or by a unit, written `name (u)`,
/// `name(u)`, `name [u]`, `name[u]` or `name/u`; returns its index and the unit (empty when
/// none). ASCII case is ignored (Maccor writes `Amps` in one export, `amps` in another).
pub fn column(headers: &[String], name: &str) -> Option<(usize, String)> {
    headers.iter().enumerate().find_map(|(k, h)| {
        let head = h.get(..name.len()).filter(|p| p.eq_ignore_ascii_case(name))?;
        let rest = h[head.len()..].trim();
        let unit = if rest.is_empty() {
            ""
        } else if let Some(u) = rest.strip_prefix('(').and_then(|r| r.strip_suffix(')')) {
            u
        } else if let Some(u) = rest.strip_prefix('[').and_then(|r| r.strip_suffix(']')) {
            u
        } else {
            rest.strip_prefix('/')?
        };
        Some((k, unit.trim().to_string()))
    })
}

/// The first of `names` present as a column (see [`column`]).
pub fn first_column(headers: &[String], names: &[&str]) -> Option<(usize, String)> {
    names.iter().find_map(|n| column(headers, n))
}

/// The first of `names`, or an error naming them and the columns found.
pub fn required(headers: &[String], what: &str, names: &[&str]) -> Result<(usize, String), String> {
    first_column(headers, names).ok_or_else(|| {
        format!("no {what} column (looked for {}; found: {})", names.join(", "), headers.join(", "))
    })
}

/// Seconds per unit of a time column.
pub fn time_factor(unit: &str, column: &str) -> Result<f64, String> {
    match unit {
        "s" | "sec" | "Sec" | "ss.xxx" | "" => Ok(1.0),
        "ms" => Ok(1e-3),
        "min" => Ok(60.0),
        "h" => Ok(3600.0),
        u => Err(format!("column `{column}`: unknown time unit `{u}` (expected s, ms, min or h)")),
    }
}

/// Amperes per unit of a current column.
pub fn current_factor(unit: &str, column: &str) -> Result<f64, String> {
    match unit {
        "A" | "" => Ok(1.0),
        "mA" => Ok(1e-3),
        "uA" | "µA" | "\u{3bc}A" => Ok(1e-6),
        u => Err(format!("column `{column}`: unknown current unit `{u}` (expected A, mA or uA)")),
    }
}

/// Volts per unit of a voltage column.
pub fn voltage_factor(unit: &str, column: &str) -> Result<f64, String> {
    match unit {
        "V" | "" => Ok(1.0),
        "mV" => Ok(1e-3),
        u => Err(format!("column `{column}`: unknown voltage unit `{u}` (expected V or mV)")),
    }
}

/// Offset to kelvin of a temperature column: 0 for `K`, 273.15 for Celsius in any spelling
/// (`°C`, `℃`, `C`, `degC`; an unreadable degree sign, as Latin-1 files give, counts as °C).
pub fn kelvin_offset(unit: &str) -> f64 {
    if unit == "K" { 0.0 } else { 273.15 }
}

/// Seconds of an elapsed time `[d-]h:mm:ss(.fff)`.
fn clock_duration(text: &str) -> Option<f64> {
    let (days, clock) = match text.split_once('-') {
        Some((d, c)) if !c.contains('-') => (d.trim().parse::<f64>().ok()?, c),
        _ => (0.0, text),
    };
    let parts: Vec<&str> = clock.split(':').collect();
    if parts.len() < 2 || parts.len() > 3 {
        return None;
    }
    let mut s = 0.0;
    for p in &parts {
        let v: f64 = p.trim().parse().ok()?;
        if !(v >= 0.0 && v.is_finite()) {
            return None;
        }
        s = 60.0 * s + v;
    }
    Some(86400.0 * days + s)
}

/// Seconds since 1970 of a calendar time (collapsing repeated spaces, as Neware writes two).
fn calendar(text: &str) -> Option<f64> {
    let text = text.split_whitespace().collect::<Vec<_>>().join(" ");
    ["%Y-%m-%d %H:%M:%S%.f", "%m/%d/%Y %H:%M:%S%.f", "%d.%m.%Y %H:%M:%S%.f"]
        .iter()
        .find_map(|f| NaiveDateTime::parse_from_str(&text, f).ok())
        .map(|t| t.and_utc().timestamp_micros() as f64 * 1e-6)
}

/// What [`read_rows`] produced: the recording (time from 0 at the first row), the cycler's
/// step number per row, the time of the first row in the file's own clock (s), and how
/// many rows repeated the previous row's time and current (dropped).
pub struct Rows {
    pub recording: Recording,
    pub step: Option<Vec<i64>>,
    pub time_offset: f64,
    pub dropped_repeats: usize,
}

/// Reads the data rows by `layout`: time must not decrease, voltages must lie in (0, 10) V,
/// temperatures in the cell range of [`TEMPERATURE_RANGE`], repeated rows are dropped when the
/// layout says so.
pub fn read_rows(table: &Table, layout: &Layout) -> Result<Rows, String> {
    let h = &table.headers;
    let mut rec = Recording { temperature: layout.temperature.map(|_| Vec::new()), ..Default::default() };
    let mut step: Option<Vec<i64>> = layout.step.map(|_| Vec::new());
    let mut dropped = 0;
    let mut t0 = None;
    // The table row of every kept row, for the time checks after the loop.
    let mut kept = Vec::new();
    for (row, (line, fields)) in table.rows.iter().enumerate() {
        let text = |col: usize| fields.get(col).copied().unwrap_or("");
        let number = |col: usize| -> Result<f64, String> {
            let s = text(col);
            let parsed = s.parse::<f64>().or_else(|e| if table.decimal_comma { s.replace(',', ".").parse() } else { Err(e) });
            match parsed {
                Ok(v) if v.is_finite() => Ok(v),
                _ => Err(format!("line {line}: `{}` = `{s}` is not a finite number", h[col])),
            }
        };
        let (ct, kind) = layout.time;
        let t_abs = match kind {
            TimeKind::Seconds(f) => f * number(ct)?,
            TimeKind::Clock => {
                let s = text(ct);
                clock_duration(s).or_else(|| calendar(s)).ok_or_else(|| {
                    format!("line {line}: `{}` = `{s}` is neither h:mm:ss nor a date and time", h[ct])
                })?
            }
        };
        if !t_abs.is_finite() {
            return Err(format!("line {line}: `{}` = `{}` is not a finite time", h[ct], text(ct)));
        }
        let t = t_abs - *t0.get_or_insert(t_abs);
        let (ci, ki) = layout.current;
        // `+ 0.0` turns the -0.0 of a flipped zero into 0.0.
        let mut i = ki * number(ci)? + 0.0;
        if let Some(cs) = layout.state {
            let s = text(cs);
            i = match s.chars().next() {
                Some('D' | 'd') => i.abs(),
                Some('C' | 'c') => -i.abs(),
                Some('R' | 'r' | 'O' | 'S') => 0.0,
                _ => return Err(format!("line {line}: `{}` = `{s}` is not C, D or R", h[cs])),
            };
        }
        let (cv, kv) = layout.voltage;
        let v = kv * number(cv)?;
        if !(v > 0.0 && v < 10.0) {
            return Err(format!("line {line}: `{}` = {v} V is not a cell voltage", h[cv]));
        }
        if let Some(&tp) = rec.time.last() {
            if t < tp {
                return Err(format!("line {line}: `{}` = `{}` goes back in time ({t} s after the first row, previous {tp} s)", h[ct], text(ct)));
            }
            if layout.drop_repeats && t == tp && rec.current.last() == Some(&i) {
                dropped += 1;
                continue;
            }
        }
        kept.push(row);
        rec.time.push(t);
        rec.current.push(i);
        rec.voltage.push(v);
        if let (Some((c, off)), Some(temps)) = (layout.temperature, rec.temperature.as_mut()) {
            let kelvin = number(c)? + off;
            if !TEMPERATURE_RANGE.contains(&kelvin) {
                let unit = if off == 0.0 { "K" } else { "degC" };
                return Err(format!("line {line}: `{}` = `{}` ({kelvin} K) is not a cell temperature (the column is read in {unit})", h[c], text(c)));
            }
            temps.push(kelvin);
        }
        if let (Some(c), Some(steps)) = (layout.step, step.as_mut()) {
            let s = text(c);
            let n = s.parse::<i64>().or_else(|_| s.parse::<f64>().map(|v| v as i64)).map_err(|_| {
                format!("line {line}: `{}` = `{s}` is not a step number", h[c])
            })?;
            steps.push(n);
        }
    }
    if rec.time.len() < 2 {
        return Err(format!("needs at least 2 data rows, found {}", rec.time.len()));
    }
    if let Some((k, reason)) = rec.time_shape_error() {
        let ((ct, _), (line, fields)) = (layout.time, &table.rows[kept[k]]);
        return Err(format!("line {line}: `{}` = `{}` {reason}", h[ct], fields.get(ct).copied().unwrap_or("")));
    }
    Ok(Rows { recording: rec, step, time_offset: t0.unwrap_or(0.0), dropped_repeats: dropped })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn columns_with_units_in_every_spelling() {
        let h: Vec<String> = ["I/mA", "Current (A)", "U[V]", "Voltage(V)", "Current Range"].map(String::from).into();
        assert_eq!(column(&h, "I"), Some((0, "mA".into())));
        assert_eq!(column(&h, "Current"), Some((1, "A".into())));
        assert_eq!(column(&h, "U"), Some((2, "V".into())));
        assert_eq!(column(&h, "Voltage"), Some((3, "V".into())));
        assert_eq!(column(&h, "Volt"), None);
        assert_eq!(column(&h, "voltage"), Some((3, "V".into())));
    }

    #[test]
    fn clock_and_calendar_times() {
        assert_eq!(clock_duration("1:00:01.5"), Some(3601.5));
        assert_eq!(clock_duration("2-00:00:00"), Some(172800.0));
        assert_eq!(clock_duration("abc"), None);
        let a = calendar("2022-02-02  02:02:00.00").unwrap();
        let b = calendar("2022-02-02 02:02:05.10").unwrap();
        // Seconds since 1970 in f64 resolve 0.24 us.
        assert!((b - a - 5.1).abs() < 1e-6);
    }
}
