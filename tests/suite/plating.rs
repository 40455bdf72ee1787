//! Lithium plating against PyBaMM 26.10 (`scripts/make_plating_submodel_reference.py`, curves
//! in `tests/data/plating-submodel/`): the SPM, SPMe and DFN on Chen 2020 with OKane2022's plating
//! parameters (our defaults) and PyBaMM's "lithium plating" options "irreversible",
//! "reversible", "partially reversible", and "partially reversible" with the SEI "reaction
//! limited", through 3 cycles with a 2C CC-CV charge, the same mesh, PyBaMM's IDAKLU at
//! rtol = atol = 1e-8 and ours at 1e-8. Compared: the voltage outside the holds, the current
//! in the holds, the plated and dead lithium against time, and the per-cycle summaries.
//! Lithium (particles + plated + dead + SEI) is conserved to round-off; a zero rate constant
//! reproduces the model without plating.

use cellstudio::geometry::MeshSizes;
use cellstudio::models::submodels::{PlatingModel, SeiModel};
use cellstudio::models::{ModelBuilder, ModelKind, Submodels};
use cellstudio::params::chen2020;
use cellstudio::protocol::{Protocol, Step, experiment};
use cellstudio::simulation::{SimOptions, States, simulate};

const CYCLE: [&str; 5] = ["Discharge at 1C until 3.0 V", "Rest for 10 minutes", "Charge at 2C until 4.1 V", "Hold at 4.1 V until C/20", "Rest for 10 minutes"];
const CYCLES: usize = 3;
const OPTIONS: [(PlatingModel, SeiModel, &str); 4] = [
    (PlatingModel::Irreversible, SeiModel::None, "irreversible"),
    (PlatingModel::Reversible, SeiModel::None, "reversible"),
    (PlatingModel::PartiallyReversible, SeiModel::None, "partially_reversible"),
    (PlatingModel::PartiallyReversible, SeiModel::ReactionLimited, "partially_reversible_sei"),
];

use crate::common;
use common::AgeingLimits;

fn rows(file: &str) -> Vec<Vec<f64>> {
    common::csv_rows("plating-submodel", file)
}

fn builder(kind: ModelKind, plating: PlatingModel, sei: SeiModel) -> ModelBuilder {
    ModelBuilder::new(kind, Submodels { plating, sei, ..Default::default() }, MeshSizes::default())
}

fn cycle() -> Protocol {
    experiment::parse(&CYCLE, chen2020().cell.nominal_capacity).unwrap()
}

/// The differences over the cycles against PyBaMM's curve.
#[derive(Debug)]
struct Gaps {
    /// Voltage RMS and max outside the holds (mV).
    voltage: (f64, f64),
    /// Hold current RMS and max (mA).
    current: (f64, f64),
    /// Largest plated (reversible) and dead lithium differences relative to the largest
    /// plated lithium (reversible plus dead) of the run (-).
    lithium: [f64; 2],
    /// Largest relative change of particles + plated + dead + SEI lithium (-).
    conservation: f64,
}

fn compare(kind: ModelKind, plating: PlatingModel, sei: SeiModel, name: &str) -> Gaps {
    let rec = rows(&format!("{}_{name}.csv", kind.to_string().to_lowercase()));
    let steps: Vec<Step> = (0..CYCLES).flat_map(|_| cycle().steps).collect();
    let p = chen2020();
    let mut b = builder(kind, plating, sei);
    let built = b.build(&p).unwrap();
    let model = built.model.as_ref();
    let largest = rec.iter().map(|r| r[3] + r[4]).fold(0.0f64, f64::max);
    let total = |y: &[f64]| model.solid_lithium(y) + model.sei_lithium(y) + model.plated_lithium(y).unwrap().total_mol();
    let total0 = total(&model.initial_state());
    let (mut lithium, mut conservation) = ([0.0f64; 2], 0.0f64);
    let hold = |s: usize| s % CYCLE.len() == 3;
    let run = common::step_by_step(model, &mut built.workspace, &steps, &rec, 6, hold, &common::tight_options(&p), |sol, k, r| {
        let y = &sol.states[k];
        let li = model.plated_lithium(y).unwrap();
        lithium[0] = lithium[0].max((li.plated_mol - r[3]).abs() / largest);
        lithium[1] = lithium[1].max((li.dead_mol - r[4]).abs() / largest);
        conservation = conservation.max((total(y) - total0).abs() / total0);
    });
    let (v, i) = (run.voltage, run.current);
    assert!(v.len() > 200 && i.len() > 150, "{name}: compared {} voltages and {} currents", v.len(), i.len());
    let (rms, max) = (common::rms, common::max_abs);
    let gaps = Gaps { voltage: (rms(&v), max(&v)), current: (rms(&i), max(&i)), lithium, conservation };
    println!("{kind} {name}: {gaps:?}");
    gaps
}

/// SPM and SPMe: limits three to five times the largest achieved: voltage RMS / max
/// 1.3e-5-5.5e-5 / 8.5e-5-3.7e-4 mV (the largest for the SPM with the SEI), hold current RMS
/// / max 2.0e-4-4.5e-4 / 7.4e-4-2.7e-3 mA, plated and dead lithium within 1.4e-5 of the run's
/// largest plated lithium (2.5e-6 without the SEI).
const SPM_LIMITS: AgeingLimits = AgeingLimits { voltage: (2.5e-4, 1.5e-3), current: (2e-3, 1e-2), ageing: 6e-5 };

/// DFN: limits about four times the largest achieved: voltage RMS / max 9.1e-6-1.9e-5 /
/// 5.4e-5-1.0e-4 mV, hold current RMS / max 6.6e-5-3.4e-4 / 4.6e-4-1.5e-3 mA, plated and
/// dead lithium within 3.3e-7 of the run's largest plated lithium.
const DFN_LIMITS: AgeingLimits = AgeingLimits { voltage: (8e-5, 4e-4), current: (1.4e-3, 6e-3), ageing: 1.3e-6 };

/// Every option on `kind` within `limits`; lithium conserved to round-off (achieved
/// 5.9e-16-1.2e-15, DFN 5.9e-16-7.8e-16).
fn check(kind: ModelKind, limits: AgeingLimits) {
    for (plating, sei, name) in OPTIONS {
        let g = compare(kind, plating, sei, name);
        limits.assert(&format!("{kind} {name}"), g.voltage, g.current, "plated and dead lithium", &g.lithium, g.conservation);
    }
}

#[test]
fn plating_spm_matches_pybamm() {
    check(ModelKind::Spm, SPM_LIMITS);
}

#[test]
fn plating_spme_matches_pybamm() {
    check(ModelKind::Spme, SPM_LIMITS);
}

#[test]
fn plating_dfn_matches_pybamm() {
    check(ModelKind::Dfn, DFN_LIMITS);
}

/// The per-cycle summaries of `run_cycles` (discharge capacity, lithium lost to plating,
/// dead lithium) against PyBaMM's over the same experiment.
#[test]
fn plating_cycle_summaries_match_pybamm() {
    let p = chen2020();
    for kind in [ModelKind::Spm, ModelKind::Spme, ModelKind::Dfn] {
        for (plating, sei, name) in OPTIONS {
            let reference = rows(&format!("{}_{name}_cycles.csv", kind.to_string().to_lowercase()));
            let summaries = common::cycle_summaries(kind, Submodels { plating, sei, ..Default::default() }, &p, &cycle(), CYCLES);
            let final_lost = reference[CYCLES - 1][2];
            let (mut dq, mut dli, mut ddead) = (0.0f64, 0.0f64, 0.0f64);
            for (s, r) in summaries.iter().zip(&reference) {
                dq = dq.max((s.discharge_capacity_ah - r[1]).abs());
                dli = dli.max((s.lithium_lost_to_plating_mol.unwrap() - r[2]).abs() / final_lost);
                ddead = ddead.max((s.dead_lithium_mol.unwrap() - r[3]).abs() / final_lost);
            }
            println!("{kind} {name}: discharge capacity within {dq:.2e} A h, lithium lost to plating within {dli:.2e} and dead lithium within {ddead:.2e} of the final loss");
            // Limits about four times the largest achieved (the ageing states held to a third
            // of the tolerance over the three cycles): capacity 1.5e-8-4.7e-7 A h, lithium lost
            // to plating 7.8e-8-6.2e-7 and dead lithium up to 3.5e-7 of the final loss (DFN:
            // 6.6e-9-1.4e-7 A h, 5.5e-8-3.9e-7, 5.5e-8).
            assert!(dq < 1.5e-6, "{kind} {name}: discharge capacity {dq:e} A h");
            assert!(dli < 2.5e-6 && ddead < 1.5e-6, "{kind} {name}: lithium lost {dli:e}, dead {ddead:e}");
        }
    }
}

/// With the rate constant 0 each plating option reproduces the model without plating: the
/// same voltage and charge to the integrator's tolerance (achieved: 2e-10 V, 6e-8 A h, the
/// end of the cycle 2e-4 s apart: the extra states change the step sizes) and no plated
/// lithium.
#[test]
fn zero_rate_constant_is_the_model_without_plating() {
    let mut p = chen2020();
    p.plating.kinetic_rate_constant = 0.0;
    let protocol = cycle();
    for kind in [ModelKind::Spm, ModelKind::Spme, ModelKind::Dfn] {
        let run = |plating| {
            let mut b = builder(kind, plating, SeiModel::None);
            let built = b.build(&p).unwrap();
            let opts = SimOptions { states: States::Kept, ..common::tight_options(&p) };
            let sol = simulate(built.model.as_ref(), &mut built.workspace, &protocol, &opts, None).unwrap();
            let plated = sol.states.iter().map(|y| built.model.plated_lithium(y).map_or(0.0, |l| l.total_mol())).fold(0.0f64, |m, x| m.max(x.abs()));
            (sol, plated)
        };
        let (base, _) = run(PlatingModel::None);
        for plating in [PlatingModel::Irreversible, PlatingModel::Reversible, PlatingModel::PartiallyReversible] {
            let (sol, plated) = run(plating);
            assert_eq!(plated, 0.0, "{kind} {plating:?}");
            let dt = (sol.time.last().unwrap() - base.time.last().unwrap()).abs();
            let dv = (sol.final_voltage() - base.final_voltage()).abs();
            let dq = (sol.capacity.last().unwrap() - base.capacity.last().unwrap()).abs();
            println!("{kind} {plating:?}: end time {dt:.2e} s, end voltage {dv:.2e} V, charge {dq:.2e} A h apart");
            assert!(dt < 1e-3 && dv < 1e-9 && dq < 3e-7, "{kind} {plating:?}: {dt:e} s, {dv:e} V, {dq:e} A h");
        }
    }
}

/// A bad plating parameter names its field and value, on every model.
#[test]
fn plating_rejects_bad_parameters() {
    for (field, value, reason) in [
        ("plating.kinetic_rate_constant", -1e-9, "must not be negative"),
        ("plating.transfer_coefficient", 1.5, "must lie in [0, 1]"),
        ("plating.dead_lithium_decay_constant", f64::NAN, "must not be negative"),
        ("plating.typical_concentration", 0.0, "must be positive"),
        ("plating.lithium_partial_molar_volume", f64::INFINITY, "must be positive"),
    ] {
        let mut p = chen2020();
        p.set(field, value).unwrap();
        for kind in [ModelKind::Spm, ModelKind::Spme, ModelKind::Dfn] {
            let e = builder(kind, PlatingModel::Reversible, SeiModel::None).build(&p).err().unwrap().to_string();
            assert!(e.contains(&format!("`{field}`")) && e.contains(reason), "{kind} {field} = {value}: {e}");
        }
    }
}

/// Reversible plating through the end of a 1C discharge from full, where the stripping rate
/// grows as `exp((1 - alpha) F eta / RT)`: every model reaches the 2.5 V cut-off and the
/// plated lithium stays at zero to within the absolute tolerance (atol 1e-6 times the typical
/// concentration, 1000 mol/m^3). With stripping clipped at zero plated lithium (PyBaMM's
/// `max(c_Li, 0)`) the SPMe's partially reversible plating failed at 3,543 s (steps
/// collapsing at the kink) and its reversible plating sank to -0.011 mol/m^3; achieved now:
/// SPM -2.5e-4, SPMe -7.7e-5, DFN -5.7e-4 mol/m^3.
#[test]
fn reversible_plating_discharges_to_the_cut_off_without_negative_lithium() {
    let p = chen2020();
    let opts = SimOptions { states: States::Kept, ..SimOptions::for_cell(&p) };
    for kind in [ModelKind::Spm, ModelKind::Spme, ModelKind::Dfn] {
        for plating in [PlatingModel::Reversible, PlatingModel::PartiallyReversible] {
            let mut b = builder(kind, plating, SeiModel::None);
            let built = b.build(&p).unwrap();
            let sol = simulate(built.model.as_ref(), &mut built.workspace, &Protocol::discharge(1.0), &opts, None)
                .unwrap_or_else(|e| panic!("{kind} {plating:?}: {e}"));
            let v_end = *sol.voltage.last().unwrap();
            assert!((v_end - p.cell.lower_cutoff).abs() < 1e-6, "{kind} {plating:?}: ended at {v_end} V");
            let plated = built.model.accumulating_states();
            let least = sol.states.iter().flat_map(|y| plated.iter().map(|&i| y[i])).fold(f64::INFINITY, f64::min);
            println!("{kind} {plating:?}: least plated or dead lithium {least:.3e} mol/m^3");
            assert!(least > -opts.solver.atol * p.plating.typical_concentration, "{kind} {plating:?}: plated lithium fell to {least:.3e} mol/m^3");
        }
    }
}
