//! The `[balancing]` stage of a parameterisation study: the electrode balance fitted to the
//! pseudo-OCV of `[ocv]` with the parameter set's half-cell OCPs ([`crate::problem::balancing`]);
//! the stoichiometry windows, electrode capacities, N/P ratio and lithium inventory with
//! standard errors, `balancing.csv`, `balancing.svg`, `balancing_residual.svg`; optionally
//! the balance put into the parameter set for the stages after it.

use std::fmt::Write as _;
use std::path::Path;

use serde::{Deserialize, Serialize};

use super::ReportSection;
use super::parameterise::{StageOutput, Stages};
use crate::error::Error;
use crate::problem::balancing::{Balance, BalancingProblem, NAMES, electrode_capacities, fit_balance};
use crate::report::plot::{Series, line_plot};

/// `[balancing]`: the part of the pseudo-OCV fitted and whether later stages use the result.
#[derive(Clone, Debug, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct BalancingSection {
    /// States of charge (-) of the pseudo-OCV fitted: from `soc_min` to `soc_max` (default
    /// 0 to 1; narrow it to leave out the ends, where a slow rate's overpotential is largest).
    #[serde(default)]
    pub soc_min: f64,
    #[serde(default = "one")]
    pub soc_max: f64,
    /// Put the fitted balance into the parameter set for the later stages (default true).
    #[serde(default = "yes")]
    pub apply: bool,
}

fn one() -> f64 {
    1.0
}
fn yes() -> bool {
    true
}

impl BalancingSection {
    pub(crate) fn validate(&self, has_ocv: bool) -> Result<(), Error> {
        if !has_ocv {
            return Err(Error::InvalidSetting { field: "balancing".into(), reason: "needs the pseudo-OCV of an [ocv] section (a slow discharge alone will do: [ocv] discharge = \"FILE\")".into() });
        }
        if !(0.0 <= self.soc_min && self.soc_min < self.soc_max && self.soc_max <= 1.0) {
            return Err(Error::invalid("balancing.soc_max", self.soc_max, format!("needs 0 <= soc_min ({}) < soc_max <= 1", self.soc_min)));
        }
        Ok(())
    }
}

/// Runs `[balancing]` on `stages.ocv`.
pub fn run_balancing(section: &BalancingSection, stages: &mut Stages, dir: &Path) -> Result<StageOutput, Error> {
    let ocv = stages.ocv.as_ref().ok_or_else(|| Error::InvalidSetting { field: "balancing".into(), reason: "needs the pseudo-OCV of an [ocv] section".into() })?;
    let p = &stages.parameters;
    let kept: Vec<usize> = (0..ocv.soc.len()).filter(|&k| (section.soc_min..=section.soc_max).contains(&ocv.soc[k])).collect();
    if kept.len() < 10 {
        return Err(Error::invalid("balancing.soc_min", section.soc_min, format!("leaves {} points of the pseudo-OCV to fit; 10 or more are needed", kept.len())));
    }
    let problem = BalancingProblem {
        discharged: kept.iter().map(|&k| ocv.discharged[k]).collect(),
        voltage: kept.iter().map(|&k| ocv.voltage[k]).collect(),
        negative_ocp: p.negative.ocp.clone(),
        positive_ocp: p.positive.ocp.clone(),
    };
    let capacity = ocv.capacity();
    let start = Balance::of(p, ocv.voltage[ocv.voltage.len() - 1]);
    let fit = fit_balance(&problem, start, [0.05, 0.0, capacity, capacity], [1.0, 0.95, 10.0 * capacity, 10.0 * capacity])?;
    let b = fit.balance;
    let names: Vec<String> = NAMES.iter().map(|n| n.to_string()).collect();
    let x = [b.x_top, b.y_top, b.q_n, b.q_p];
    let mut warnings = super::at_bound_warnings("the electrode balance", &names, &x, &fit.lower, &fit.upper);
    let remedy = "its caps are not a setting of the study: check the pseudo-OCV and the electrodes' OCPs";
    warnings.extend(super::truncation_warning_with("the electrode balance", &fit.stop, 0, fit.evaluations, remedy));
    let mut applied = p.clone();
    let window = b.apply(&mut applied)?;
    let before = crate::params::stoichiometry_window(p).ok();
    let (q_n0, q_p0) = electrode_capacities(p);
    let (x_end, y_end) = b.at(problem.discharged[0].max(problem.discharged[problem.discharged.len() - 1]));
    for (name, v) in [("negative", b.x_top), ("negative", x_end), ("positive", b.y_top), ("positive", y_end)] {
        if !(0.0..=1.0).contains(&v) {
            warnings.push(format!("the fitted {name} stoichiometry reaches {v:.4} over the pseudo-OCV, outside [0, 1]: the OCPs are extrapolated there"));
        }
    }
    let mut files = Vec::new();
    let (model, residual): (Vec<f64>, Vec<f64>) = {
        let r = problem.residuals(&b, None);
        (r.iter().zip(&problem.voltage).map(|(r, v)| r + v).collect(), r.iter().map(|r| 1e3 * r).collect())
    };
    let mut csv = String::from("discharged_Ah,pseudo_ocv_V,model_ocv_V,negative_stoichiometry,positive_stoichiometry\n");
    for (k, &q) in problem.discharged.iter().enumerate() {
        let (xs, ys) = b.at(q);
        let _ = writeln!(csv, "{q:.6},{:.6},{:.6},{xs:.6},{ys:.6}", problem.voltage[k], model[k]);
    }
    super::write_output(dir, "balancing.csv", csv, &mut files)?;
    let plot = dir.join("balancing.svg");
    line_plot(&plot, "electrode balance: pseudo-OCV and U_p(y) - U_n(x)", "discharged (A h)", "voltage (V)", &[
        Series { label: "pseudo-OCV".into(), x: &problem.discharged, y: &problem.voltage },
        Series { label: "fitted balance".into(), x: &problem.discharged, y: &model },
    ])?;
    files.push(plot);
    let plot = dir.join("balancing_residual.svg");
    line_plot(&plot, "electrode balance: residual (model - pseudo-OCV)", "discharged (A h)", "residual (mV)", &[Series { label: "residual".into(), x: &problem.discharged, y: &residual }])?;
    files.push(plot);

    let lithium0 = q_n0 * p.negative.initial_concentration / p.negative.max_concentration + q_p0 * p.positive.initial_concentration / p.positive.max_concentration;
    let mut md = String::from("\n## Electrode balance (`[balancing]`)\n\n");
    let _ = writeln!(
        md,
        "Fitted `U_p(y_top + q/Q_p) - U_n(x_top - q/Q_n)` to the pseudo-OCV from SOC {} to {} ({} points, {:.4} A h) with the set's OCPs: RMSE {:.2} mV, {} evaluations, stop: {:?}. Standard errors from the Gauss-Newton information; the residual's lag-1 autocorrelation is {:.2}, so where it is near 1 the misfit is systematic and the errors are lower bounds. Windows at the cut-offs ({} V, {} V) on the fitted lithium line.\n",
        section.soc_min, section.soc_max, problem.voltage.len(), capacity, 1e3 * fit.rmse, fit.evaluations, fit.stop, fit.residual_lag1, p.cell.upper_cutoff, p.cell.lower_cutoff
    );
    md.push_str("| quantity | fitted | std. error | parameter set |\n|---|---|---|---|\n");
    let set = |v: Option<f64>| v.map_or("-".into(), |v| format!("{v:.4}"));
    let rows = [
        ("negative capacity Q_n (A h)", b.q_n, fit.std_errors[2], Some(q_n0)),
        ("positive capacity Q_p (A h)", b.q_p, fit.std_errors[3], Some(q_p0)),
        ("N/P ratio Q_n/Q_p (-)", b.q_n / b.q_p, fit.np_ratio_error, Some(q_n0 / q_p0)),
        ("cyclable lithium (A h)", b.lithium(), fit.lithium_error, Some(lithium0)),
        ("x at the pseudo-OCV's top (-)", b.x_top, fit.std_errors[0], None),
        ("y at the pseudo-OCV's top (-)", b.y_top, fit.std_errors[1], None),
    ];
    for (name, v, e, s) in rows {
        let _ = writeln!(md, "| {name} | {v:.4} | {e:.4} | {} |", set(s));
    }
    let wins = [("x_0", window.x0, before.map(|w| w.x0)), ("x_100", window.x100, before.map(|w| w.x100)), ("y_0", window.y0, before.map(|w| w.y0)), ("y_100", window.y100, before.map(|w| w.y100))];
    for (name, v, s) in wins {
        let _ = writeln!(md, "| {name} (-) | {v:.4} | - | {} |", set(s));
    }
    let _ = writeln!(md, "| window capacity (A h) | {:.4} | - | {} |", window.capacity(&applied), set(before.map(|w| w.capacity(p))));
    let mut notes = Vec::new();
    stages.window_capacity = Some(window.capacity(&applied));
    if section.apply {
        let _ = writeln!(md, "\nThe balance is put into the parameter set for the later stages: each electrode's maximum concentration scaled to its fitted capacity (negative {:.1}, positive {:.1} mol/m^3; geometry unchanged), initial concentrations at the pseudo-OCV's top.", applied.negative.max_concentration, applied.positive.max_concentration);
        notes.push("the fitted electrode balance is used by the stages after [balancing] (balancing.apply = true)".into());
        stages.parameters = applied.clone();
    }
    let summary = format!(
        "balancing: Q_n {:.4} ± {:.4} A h, Q_p {:.4} ± {:.4} A h, N/P {:.4}, lithium {:.4} A h, x {:.4}-{:.4}, y {:.4}-{:.4}, RMSE {:.2} mV",
        b.q_n, fit.std_errors[2], b.q_p, fit.std_errors[3], b.q_n / b.q_p, b.lithium(), window.x0, window.x100, window.y100, window.y0, 1e3 * fit.rmse
    );
    let json = serde_json::json!({ "fit": fit, "window": window, "window_capacity_Ah": window.capacity(&applied), "np_ratio": b.q_n / b.q_p, "cyclable_lithium_Ah": b.lithium() });
    Ok(StageOutput { report: ReportSection { files, section: md, warnings }, summary, notes, json })
}
