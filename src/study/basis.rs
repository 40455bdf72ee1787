//! Report text shared by `design`, `sweep` and `pareto`: the mass and volume basis of chosen
//! designs (component, density, volume, mass) and the definition of power and of a discharge
//! that stops early.

use std::fmt::Write as _;

use crate::error::Error;
use crate::problem::design::DesignProblem;

/// A "Mass and volume basis" Markdown section with one table per labelled design `x`.
pub fn mass_basis_section(problem: &DesignProblem, designs: &[(&str, &[f64])]) -> Result<String, Error> {
    let mut md = format!("## Mass and volume basis\n\nCell format: {}. Only the components listed count in the mass; \
        densities are those of the parameter set and the format, so absolute W h/kg compare with another tool only on the same basis.\n\n",
        problem.format.label());
    for (label, x) in designs {
        let p = problem.parameters(x)?;
        let _ = writeln!(md, "### {label}\n\n{}", problem.mass_basis(&p)?.markdown());
    }
    Ok(md)
}

/// How power and an early stop are defined, for the report.
pub fn power_definition(problem: &DesignProblem, min_utilisation: f64) -> String {
    let drive = match problem.power {
        Some(w) => format!("a constant-power discharge at {w} W"),
        None if problem.rate_from_theoretical_capacity => format!("a constant-current discharge at {} C of each design's theoretical capacity", problem.c_rate),
        None => format!("a constant-current discharge at {} C of the nominal capacity", problem.c_rate),
    };
    format!(
        "Power is the mean power of {drive} from full charge to the lower cut-off: delivered energy / discharge time. \
         A discharge that delivers less than {:.0} % of the design's theoretical capacity (lithium the negative electrode can \
         release or the positive accept) stops early (transport-limited at this rate): its mean power describes a truncated run, \
         so it is flagged and kept out of fronts and of the best design, as is a design whose simulation fails.",
        100.0 * min_utilisation
    ) + &pulse_definition(problem)
        + &fast_charge_definition(problem)
        + &life_definition(problem)
}

/// How capacity retention is defined, when the problem measures it.
fn life_definition(problem: &DesignProblem) -> String {
    let Some(spec) = &problem.life else { return String::new() };
    let start = spec.initial_soc.map_or_else(|| "its set's initial state".to_string(), |s| format!("{:.0} % state of charge", 100.0 * s));
    format!(
        " Capacity retention is the discharge capacity of the last of {} cycles of [{}] over the first's, each design from {start}, \
         with its ageing submodel on and 1C of its own {} capacity.",
        spec.cycles,
        spec.cycle.join("; "),
        if problem.rate_from_theoretical_capacity { "theoretical" } else { "nominal" }
    )
}

/// How the plating-free charge rate is defined, when the problem measures it.
fn fast_charge_definition(problem: &DesignProblem) -> String {
    let Some(spec) = problem.fast_charge else { return String::new() };
    format!(
        " The plating-free charge rate is the largest constant charge rate (multiples of the design's 0-100 % window capacity \
         per hour) that takes it from {:.0} % to {:.0} % state of charge without reaching the upper cut-off and with the \
         negative electrode's phi_s - phi_e (the lithium-plating overpotential against Li/Li+; x-averaged in the SPM and SPMe, \
         the least over the electrode in the DFN) never below {} V, found by bisection to 1e-4 of it.",
        100.0 * spec.from_soc,
        100.0 * spec.to_soc,
        spec.margin
    )
}

/// How pulse power is defined, when the problem measures it.
fn pulse_definition(problem: &DesignProblem) -> String {
    let Some(spec) = problem.pulse else { return String::new() };
    let limit = spec.voltage.map_or_else(|| "the lower cut-off".to_string(), |v| format!("{v} V"));
    format!(
        " Pulse power (HPPC-style) is the largest constant discharge current a design sustains for {} s from rest at {:.0} % \
         state of charge before its voltage reaches {limit}, times that voltage (USABC's available pulse power), found by \
         bisection on the current to {:.0e} of it; it does not depend on where a full discharge stops.",
        spec.seconds,
        100.0 * spec.soc,
        1e-4
    )
}
