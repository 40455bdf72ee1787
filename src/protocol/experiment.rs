//! PyBaMM-style experiment strings, one per step:
//!
//! - `Discharge at 1C until 2.5 V`, `Charge at C/2 for 30 minutes or until 4.2 V`,
//!   `Discharge at 2 A for 10 s`, `Discharge at 5 W until 3 V`;
//! - `Hold at 4.2 V until C/50` (or `until 50 mA`, `for 1 hour`, both);
//! - `Rest for 1 hour`.
//!
//! Rates are `xC` or `C/x`; currents `A` or `mA`; powers `W`; voltages `V` or `mV`; durations
//! `s`, `second(s)`, `min`, `minute(s)`, `h`, `hour(s)`. A step with only an `until` runs for
//! at most [`UNBOUNDED`].

use super::Step;
use crate::error::Error;

/// The longest a step with no `for` runs (s): a day, as PyBaMM's default.
pub const UNBOUNDED: f64 = 24.0 * 3600.0;

/// What a quantity in an experiment string is.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Quantity {
    /// Multiples of the nominal capacity per hour (1/h).
    CRate(f64),
    Current(f64),
    Power(f64),
    Voltage(f64),
    Seconds(f64),
}

/// Reads `1C`, `C/2`, `2 A`, `500 mA`, `5 W`, `4.2 V`, `30 minutes`, ... (`words` split on
/// spaces: a number and its unit may be one word or two).
fn quantity(words: &[&str]) -> Option<Quantity> {
    let text: String = words.concat();
    let lower = text.to_ascii_lowercase();
    if let Some(x) = lower.strip_prefix("c/") {
        return x.parse::<f64>().ok().filter(|x| *x > 0.0).map(|x| Quantity::CRate(1.0 / x));
    }
    let split = lower.find(|c: char| !(c.is_ascii_digit() || c == '.' || c == 'e' || c == '-' || c == '+')).unwrap_or(lower.len());
    let (number, unit) = lower.split_at(split);
    let value: f64 = number.parse().ok()?;
    Some(match unit {
        "c" => Quantity::CRate(value),
        "a" => Quantity::Current(value),
        "ma" => Quantity::Current(value * 1e-3),
        "w" => Quantity::Power(value),
        "kw" => Quantity::Power(value * 1e3),
        "v" => Quantity::Voltage(value),
        "mv" => Quantity::Voltage(value * 1e-3),
        "s" | "sec" | "second" | "seconds" => Quantity::Seconds(value),
        "min" | "mins" | "minute" | "minutes" => Quantity::Seconds(value * 60.0),
        "h" | "hr" | "hour" | "hours" => Quantity::Seconds(value * 3600.0),
        _ => return None,
    })
}

/// One experiment string as a step, for a cell of nominal `capacity` (A h) (a current limit
/// given as a C-rate needs it).
pub fn parse_step(text: &str, capacity: f64) -> Result<Step, Error> {
    let fail = |why: &str| Error::InvalidSetting { field: "experiment".into(), reason: format!("\"{text}\": {why}") };
    let words: Vec<&str> = text.split_whitespace().collect();
    let Some(verb) = words.first().map(|w| w.to_ascii_lowercase()) else {
        return Err(fail("is empty"));
    };
    // Clauses: "at X", "for D", "until L" ("or" joins them).
    let (mut at, mut duration, mut until) = (None, None, None);
    let mut k = 1;
    while k < words.len() {
        let key = words[k].to_ascii_lowercase();
        let end = (k + 1..words.len()).find(|&j| matches!(words[j].to_ascii_lowercase().as_str(), "at" | "for" | "until" | "or")).unwrap_or(words.len());
        let value = quantity(&words[k + 1..end]);
        let slot = match key.as_str() {
            "or" => {
                k += 1;
                continue;
            }
            "at" => &mut at,
            "for" => &mut duration,
            "until" => &mut until,
            _ => return Err(fail(&format!("unexpected word \"{}\" (expected at, for, until or or)", words[k]))),
        };
        *slot = Some(value.ok_or_else(|| fail(&format!("cannot read \"{}\" after \"{key}\"", words[k + 1..end].join(" "))))?);
        k = end;
    }
    let seconds = match duration {
        Some(Quantity::Seconds(s)) if s > 0.0 && s.is_finite() => Some(s),
        Some(_) => return Err(fail("\"for\" needs a positive duration (s, min, h)")),
        None => None,
    };
    let limit_voltage = match until {
        Some(Quantity::Voltage(v)) => Some(v),
        None => None,
        Some(_) if verb != "hold" => return Err(fail("\"until\" needs a voltage (V) for a discharge or charge")),
        Some(_) => None,
    };
    let bounded = |s: Option<f64>| -> Result<f64, Error> {
        match (s, until) {
            (Some(s), _) => Ok(s),
            (None, Some(_)) => Ok(UNBOUNDED),
            (None, None) => Err(fail("needs \"for\" a duration or \"until\" a limit")),
        }
    };
    let sign = match verb.as_str() {
        "discharge" => 1.0,
        "charge" => -1.0,
        "rest" => {
            return match (at, seconds) {
                (None, Some(duration)) => Ok(Step::Rest { duration }),
                _ => Err(fail("a rest takes only \"for\" a duration")),
            };
        }
        "hold" => {
            let Some(Quantity::Voltage(voltage)) = at else {
                return Err(fail("a hold needs \"at\" a voltage (V)"));
            };
            let until_current = match until {
                Some(Quantity::Current(i)) => Some(i.abs()),
                Some(Quantity::CRate(c)) => Some((c * capacity).abs()),
                None => None,
                Some(_) => return Err(fail("a hold ends \"until\" a current (A, mA or C-rate)")),
            };
            return Ok(Step::Hold { voltage, duration: bounded(seconds)?, until_current });
        }
        _ => return Err(fail(&format!("unknown step \"{}\" (expected Discharge, Charge, Rest or Hold)", words[0]))),
    };
    let duration = bounded(seconds)?;
    match at {
        Some(Quantity::CRate(rate)) => Ok(Step::CRate { rate: sign * rate, duration, until_voltage: limit_voltage }),
        Some(Quantity::Current(i)) => Ok(Step::Current { current: sign * i, duration, until_voltage: limit_voltage }),
        Some(Quantity::Power(p)) => Ok(Step::Power { power: sign * p, duration, until_voltage: limit_voltage }),
        _ => Err(fail("a discharge or charge needs \"at\" a C-rate, current (A) or power (W)")),
    }
}

/// A list of experiment strings as a protocol.
pub fn parse(steps: &[impl AsRef<str>], capacity: f64) -> Result<super::Protocol, Error> {
    let steps = steps.iter().map(|s| parse_step(s.as_ref(), capacity)).collect::<Result<Vec<_>, _>>()?;
    let protocol = super::Protocol { steps };
    protocol.validate()?;
    Ok(protocol)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reads_pybamm_style_steps() {
        let q = 5.0;
        assert_eq!(parse_step("Discharge at 1C until 2.5 V", q).unwrap(), Step::CRate { rate: 1.0, duration: UNBOUNDED, until_voltage: Some(2.5) });
        assert_eq!(parse_step("Charge at C/2 for 30 minutes or until 4.2 V", q).unwrap(), Step::CRate { rate: -0.5, duration: 1800.0, until_voltage: Some(4.2) });
        assert_eq!(parse_step("Discharge at 500 mA for 10 s", q).unwrap(), Step::Current { current: 0.5, duration: 10.0, until_voltage: None });
        assert_eq!(parse_step("Discharge at 5 W until 3000 mV", q).unwrap(), Step::Power { power: 5.0, duration: UNBOUNDED, until_voltage: Some(3.0) });
        assert_eq!(parse_step("Hold at 4.2 V until C/50", q).unwrap(), Step::Hold { voltage: 4.2, duration: UNBOUNDED, until_current: Some(0.1) });
        assert_eq!(parse_step("Hold at 4.1V for 1 hour", q).unwrap(), Step::Hold { voltage: 4.1, duration: 3600.0, until_current: None });
        assert_eq!(parse_step("Rest for 2 hours", q).unwrap(), Step::Rest { duration: 7200.0 });
    }

    #[test]
    fn errors_quote_the_step() {
        for (text, why) in [
            ("Discharge at 1C", "needs \"for\""),
            ("Charge at 1C until C/50", "needs a voltage"),
            ("Rest until 4 V", "only \"for\""),
            ("Hold at 1C until C/50", "\"at\" a voltage"),
            ("Sing at 1C for 1 h", "unknown step"),
            ("Discharge at 1X for 1 h", "cannot read \"1X\""),
            ("Discharge at 1C for -5 minutes", "positive duration"),
        ] {
            let e = parse_step(text, 5.0).unwrap_err().to_string();
            assert!(e.contains(text) && e.contains(why), "{text}: {e}");
        }
    }
}
