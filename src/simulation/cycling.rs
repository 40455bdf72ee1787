//! Cycling: one cycle's protocol (e.g. CC-CV charge and CC discharge) run `N` times, each
//! cycle from the state the last one ended in, keeping one [`CycleSummary`] per cycle and no
//! states: memory does not grow with `N`. The caller observes each summary as it is made
//! (a progress bar, a log), so the loop does no I/O.

use serde::Serialize;

use super::{Integrals, SimOptions, States, simulate};
use crate::error::Error;
use crate::models::Model;
use crate::protocol::Protocol;
use crate::solver::Workspace;

/// What one cycle did to the cell.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct CycleSummary {
    /// Cycle number, from 1.
    pub cycle: usize,
    /// Time at the cycle's end since the first cycle's start (s).
    pub end_time_s: f64,
    /// Charge delivered while the current was positive (discharge) (A h).
    pub discharge_capacity_ah: f64,
    /// Charge taken while the current was negative (charge) (A h).
    pub charge_capacity_ah: f64,
    /// `discharge_capacity_ah` over the first cycle's (-).
    pub capacity_retention: f64,
    /// Lithium bound in the SEI since the start, at the cycle's end (mol).
    pub lithium_lost_to_sei_mol: f64,
    /// Loss of lithium inventory: the particles' lithium lost since the start over the
    /// particles' lithium at the start, at the cycle's end (-).
    pub lithium_inventory_lost: f64,
    /// SEI thickness at the cycle's end (m); `None` without an SEI submodel.
    pub sei_thickness_m: Option<f64>,
    /// Active material lost per electrode (negative, positive) since the start, at the
    /// cycle's end: the lost share of the initial active material volume fraction (-),
    /// `1 - eps_s / eps_s0`; `None` without a loss-of-active-material submodel.
    pub active_material_lost: Option<[f64; 2]>,
    /// Lithium lost with each electrode's active material (negative, positive) since the
    /// start, at the cycle's end (mol); `None` without a loss-of-active-material submodel.
    pub lithium_lost_to_lam_mol: Option<[f64; 2]>,
    /// Lithium lost to plating since the start, reversible and dead, at the cycle's end
    /// (mol), PyBaMM's "Loss of lithium to negative lithium plating [mol]"; `None` without a
    /// plating submodel.
    pub lithium_lost_to_plating_mol: Option<f64>,
    /// Dead lithium since the start at the cycle's end (mol), the irreversible part of
    /// `lithium_lost_to_plating_mol`; `None` without a plating submodel.
    pub dead_lithium_mol: Option<f64>,
    /// Terminal voltage at the cycle's end (V).
    pub end_voltage_v: f64,
    /// Integrator steps of the cycle.
    pub steps: usize,
}

/// Runs `cycle` `n` times from the model's initial state under `opts` (its `t_eval`,
/// `states` and `integrals` are ignored: every solver step is recorded for the cycle's
/// charge throughput, then dropped; the energy is not integrated), calling `on_cycle` after
/// each cycle. The ageing states are held to `1 / n` of the tolerance
/// (`SolverOptions::accumulator_tolerance`): their errors add up from cycle to cycle where
/// the others' decay.
pub fn run_cycles(
    model: &dyn Model,
    ws: &mut Workspace,
    cycle: &Protocol,
    n: usize,
    opts: &SimOptions,
    on_cycle: &mut dyn FnMut(&CycleSummary),
) -> Result<Vec<CycleSummary>, Error> {
    if n == 0 {
        return Err(Error::invalid("cycling.cycles", 0.0, "must be at least 1"));
    }
    let mut opts = SimOptions { t_eval: None, states: States::ForOutputs, integrals: Integrals::ChargeAtStepEnds, ..opts.clone() };
    opts.solver.accumulator_tolerance /= n as f64;
    let mut y = model.initial_state();
    let (li0, sei0) = (model.solid_lithium(&y), model.sei_lithium(&y));
    let am0 = model.active_material(&y);
    let plated0 = model.plated_lithium(&y);
    let mut summaries: Vec<CycleSummary> = Vec::with_capacity(n);
    let mut t = 0.0;
    for k in 1..=n {
        let sol = simulate(model, ws, cycle, &opts, Some(y)).map_err(|e| match e {
            Error::Solver { t: ts, reason } => Error::Solver { t: t + ts, reason: format!("cycle {k}: {reason}") },
            other => other,
        })?;
        y = sol.final_state.clone();
        let (mut discharged, mut charged) = (0.0, 0.0);
        for w in sol.capacity.windows(2) {
            let dq = w[1] - w[0];
            if dq > 0.0 { discharged += dq } else { charged -= dq }
        }
        t += sol.time.last().copied().unwrap_or(0.0);
        let first = summaries.first().map_or(discharged, |s| s.discharge_capacity_ah);
        let summary = CycleSummary {
            cycle: k,
            end_time_s: t,
            discharge_capacity_ah: discharged,
            charge_capacity_ah: charged,
            capacity_retention: if first > 0.0 { discharged / first } else { f64::NAN },
            lithium_lost_to_sei_mol: model.sei_lithium(&y) - sei0,
            lithium_inventory_lost: (li0 - model.solid_lithium(&y)) / li0,
            sei_thickness_m: model.sei_thickness(&y),
            active_material_lost: am0.zip(model.active_material(&y)).map(|(a0, a)| [0, 1].map(|k| 1.0 - a.fraction[k] / a0.fraction[k])),
            lithium_lost_to_lam_mol: model.active_material(&y).map(|a| a.lithium_lost_mol),
            lithium_lost_to_plating_mol: plated0.zip(model.plated_lithium(&y)).map(|(p0, p)| p.total_mol() - p0.total_mol()),
            dead_lithium_mol: plated0.zip(model.plated_lithium(&y)).map(|(p0, p)| p.dead_mol - p0.dead_mol),
            end_voltage_v: sol.final_voltage(),
            steps: sol.stats.steps,
        };
        on_cycle(&summary);
        summaries.push(summary);
    }
    Ok(summaries)
}
