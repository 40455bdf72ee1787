//! The lumped thermal submodel against PyBaMM 26.10 (`scripts/make_thermal_reference.py`,
//! curves in `tests/data/thermal/`): Chen 2020 with a total heat-transfer coefficient of
//! 12 W/(m^2 K), the cell starting at the ambient temperature, from full, the same mesh,
//! PyBaMM's IDAKLU at rtol = atol = 1e-8 and ours at 1e-8:
//! - at 35 degC ambient, 2 cycles (the DFN 1) of a 2C discharge to 2.7 V, 15 min rest, 1C
//!   CC-CV to 4.2 V and C/10, 15 min rest: the SPM, SPMe and DFN thermal alone and with
//!   reaction-limited SEI growth at 100 times Chen 2020's exchange current; that SEI
//!   isothermal (SPM);
//! - at 5 degC ambient, 2 cycles of a 1C discharge to 3.0 V, 15 min rest, 2C CC-CV to 4.2 V
//!   and C/10, 15 min rest: the SPM with irreversible lithium plating (OKane2022's
//!   parameters, our defaults), which plates 1.3e-2 mol of lithium (7 % of the full
//!   negative electrode's).
//!
//! - the OCPs' entropic change of the same cell (O'Regan 2022, which Chen 2020 leaves at
//!   zero): the SPM, SPMe and DFN thermal at 35 degC as above, and the SPM and DFN
//!   isothermal at 0 degC through one 1C cycle.
//!
//! Compared: the voltage outside the holds, the current in the holds and the temperature,
//! each step from the last one's end state, and when each step ends. With side reactions
//! PyBaMM heats with the intercalation current only and not through the SEI film
//! ([`cellstudio::models::submodels::thermal::SideReactionSite::uncounted_heat`]); the DFN's
//! open-circuit power is `-sum a j U dx` over its volumes
//! ([`cellstudio::models::submodels::thermal::bernardi_heat_of_power`]).

use crate::common;

use cellstudio::geometry::MeshSizes;
use cellstudio::models::submodels::{PlatingModel, SeiModel};
use cellstudio::models::{ModelBuilder, ModelKind, Submodels};
use cellstudio::params::{Function1D, ParameterSet, chen2020};
use cellstudio::protocol::{Step, experiment};

const CYCLE: [&str; 5] = ["Discharge at 2C until 2.7 V", "Rest for 15 minutes", "Charge at 1C until 4.2 V", "Hold at 4.2 V until C/10", "Rest for 15 minutes"];
const PLATING_CYCLE: [&str; 5] = ["Discharge at 1C until 3.0 V", "Rest for 15 minutes", "Charge at 2C until 4.2 V", "Hold at 4.2 V until C/10", "Rest for 15 minutes"];
const ENTROPIC_CYCLE: [&str; 5] = ["Discharge at 1C until 2.7 V", "Rest for 15 minutes", "Charge at 1C until 4.2 V", "Hold at 4.2 V until C/10", "Rest for 15 minutes"];
const WARM: f64 = 308.15;
const COLD: f64 = 278.15;
const FREEZING: f64 = 273.15;

/// One reference run: its CSV name, model and submodels, cycle, cycles and ambient (K).
struct Case {
    name: &'static str,
    kind: ModelKind,
    submodels: Submodels,
    cycle: [&'static str; 5],
    cycles: usize,
    ambient: f64,
}

impl Case {
    fn at_35_degc(name: &'static str, kind: ModelKind, thermal: bool, sei: SeiModel, cycles: usize) -> Self {
        Case { name, kind, submodels: Submodels { thermal, sei, ..Default::default() }, cycle: CYCLE, cycles, ambient: WARM }
    }

    /// Chen 2020 at the case's ambient, the SEI's exchange current times 100 with SEI on,
    /// and O'Regan 2022's entropic change of the OCPs in the cases named `*entropic*`.
    fn params(&self) -> ParameterSet {
        let mut p = chen2020();
        if self.name.contains("entropic") {
            p.negative.ocp_entropic_change = Function1D::ORegan2022GraphiteEntropicChange;
            p.positive.ocp_entropic_change = Function1D::ORegan2022Nmc811EntropicChange;
        }
        p.thermal.ambient_temperature = self.ambient;
        p.thermal.initial_temperature = self.ambient;
        p.thermal.heat_transfer_coefficient = 12.0;
        if self.submodels.sei != SeiModel::None {
            p.sei.exchange_current *= 100.0;
        }
        cellstudio::params::set_initial_soc(&mut p, 1.0).unwrap();
        p
    }
}

/// The differences against PyBaMM's curve.
#[derive(Debug)]
struct Gaps {
    /// Voltage RMS and max outside the holds (mV).
    voltage: (f64, f64),
    /// Hold current RMS and max (mA).
    current: (f64, f64),
    /// Largest temperature difference (K).
    temperature: f64,
    /// Largest step-end difference (s).
    step_end: f64,
}

/// Limits on [`Gaps`], about five times the achieved.
struct Limits {
    voltage: (f64, f64),
    current: (f64, f64),
    temperature: f64,
    step_end: f64,
}

fn compare(case: &Case) -> Gaps {
    let rec = common::csv_rows("thermal", &format!("{}.csv", case.name));
    let p = case.params();
    let steps: Vec<Step> = (0..case.cycles).flat_map(|_| experiment::parse(&case.cycle, p.cell.nominal_capacity).unwrap().steps).collect();
    let mut b = ModelBuilder::new(case.kind, case.submodels, MeshSizes::default());
    let built = b.build(&p).unwrap();
    let model = built.model.as_ref();
    let mut dt = Vec::new();
    let run = common::step_by_step(model, &mut built.workspace, &steps, &rec, 4, |s| s % 5 == 3, &common::tight_options(&p), |sol, k, r| {
        dt.push(sol.temperature[k] - r[3]);
    });
    let (v, i) = (run.voltage, run.current);
    assert!(v.len() > 300 * case.cycles && i.len() > 10 * case.cycles, "{}: compared {} voltages and {} currents", case.name, v.len(), i.len());
    let (rms, max) = (common::rms, common::max_abs);
    let gaps = Gaps { voltage: (rms(&v), max(&v)), current: (rms(&i), max(&i)), temperature: max(&dt), step_end: run.step_end };
    println!("{}: {gaps:?}", case.name);
    gaps
}

fn check(case: Case, limits: Limits) {
    let g = compare(&case);
    let name = case.name;
    assert!(g.voltage.0 < limits.voltage.0 && g.voltage.1 < limits.voltage.1, "{name}: voltage {:?} mV", g.voltage);
    assert!(g.current.0 < limits.current.0 && g.current.1 < limits.current.1, "{name}: hold current {:?} mA", g.current);
    assert!(g.temperature < limits.temperature, "{name}: temperature {} K", g.temperature);
    assert!(g.step_end < limits.step_end, "{name}: step ends {} s apart", g.step_end);
}

/// Achieved: voltage RMS / max 6.1e-5 / 2.9e-4 mV, hold current 3.3e-4 / 9.5e-4 mA,
/// temperature 1.0e-4 K, step ends 3.8e-4 s.
#[test]
fn lumped_thermal_spm_matches_pybamm() {
    let case = Case::at_35_degc("spm_thermal", ModelKind::Spm, true, SeiModel::None, 2);
    check(case, Limits { voltage: (3e-4, 1.5e-3), current: (1.7e-3, 5e-3), temperature: 5e-4, step_end: 2e-3 });
}

/// Achieved: voltage RMS / max 1.5e-2 / 3.2e-2 mV, hold current 0.10 / 0.16 mA, temperature
/// 1.9e-2 K, step ends 8.1e-2 s: PyBaMM's ohmic heat is the solid's and electrolyte's
/// `-i grad phi` of its composite potentials, not quite the `I (U - V)` of its voltage.
#[test]
fn lumped_thermal_spme_matches_pybamm() {
    let case = Case::at_35_degc("spme_thermal", ModelKind::Spme, true, SeiModel::None, 2);
    check(case, Limits { voltage: (0.075, 0.16), current: (0.5, 0.8), temperature: 0.095, step_end: 0.4 });
}

/// Achieved: voltage RMS / max 1.5e-2 / 5.2e-2 mV, hold current 0.14 / 0.34 mA, temperature
/// 2.3e-2 K, step ends 5.5e-2 s (one cycle; with the plain mean of the surface OCPs in place
/// of the reaction-weighted `-sum a j U dx`, 0.67 / 2.0 mV and 1.3 K).
#[test]
fn lumped_thermal_dfn_matches_pybamm() {
    let case = Case::at_35_degc("dfn_thermal", ModelKind::Dfn, true, SeiModel::None, 1);
    check(case, Limits { voltage: (0.078, 0.26), current: (0.72, 1.7), temperature: 0.11, step_end: 0.28 });
}

/// Achieved: voltage RMS / max 3.7e-5 / 3.2e-4 mV, hold current 3.7e-4 / 1.0e-3 mA,
/// temperature 3.7e-5 K, step ends 7.1e-4 s (heating with the total current through the
/// film: 1.2 / 3.8 mV, 7.8 / 14 mA, 1.5 K, 7.8 s).
#[test]
fn sei_under_self_heating_spm_matches_pybamm() {
    let case = Case::at_35_degc("spm_thermal_sei", ModelKind::Spm, true, SeiModel::ReactionLimited, 2);
    check(case, Limits { voltage: (2e-4, 1.6e-3), current: (1.8e-3, 5e-3), temperature: 2e-4, step_end: 3.5e-3 });
}

/// Achieved: voltage RMS / max 1.5e-2 / 3.6e-2 mV, hold current 9.0e-2 / 0.14 mA,
/// temperature 1.9e-2 K, step ends 7.8e-2 s, as the SPMe without SEI (heating with the total
/// current through the film: 1.1 / 3.1 mV, 9.2 / 18 mA, 1.7 K, 11 s).
#[test]
fn sei_under_self_heating_spme_matches_pybamm() {
    let case = Case::at_35_degc("spme_thermal_sei", ModelKind::Spme, true, SeiModel::ReactionLimited, 2);
    check(case, Limits { voltage: (0.078, 0.18), current: (0.45, 0.7), temperature: 0.095, step_end: 0.4 });
}

/// Achieved: voltage RMS / max 1.5e-2 / 3.5e-2 mV, hold current 0.13 / 0.34 mA, temperature
/// 2.2e-2 K, step ends 0.40 s (the C/10 end of the hold), one cycle, as the DFN without SEI
/// (before: 0.53 / 1.4 mV, 4.9 / 7.7 mA, 0.88 K, 4.1 s).
#[test]
fn sei_under_self_heating_dfn_matches_pybamm() {
    let case = Case::at_35_degc("dfn_thermal_sei", ModelKind::Dfn, true, SeiModel::ReactionLimited, 1);
    check(case, Limits { voltage: (0.077, 0.17), current: (0.66, 1.7), temperature: 0.11, step_end: 2.0 });
}

/// Achieved: voltage RMS / max 3.0e-5 / 3.2e-4 mV, hold current 4.2e-4 / 1.2e-3 mA, step
/// ends 1.0e-3 s; the temperature is the ambient in both.
#[test]
fn isothermal_sei_at_35_degc_matches_pybamm() {
    let case = Case::at_35_degc("spm_sei", ModelKind::Spm, false, SeiModel::ReactionLimited, 2);
    check(case, Limits { voltage: (1.5e-4, 1.6e-3), current: (2e-3, 6e-3), temperature: 1e-9, step_end: 5e-3 });
}

/// Achieved: voltage RMS / max 5.6e-5 / 2.0e-4 mV, hold current 4.5e-4 / 4.9e-3 mA,
/// temperature 7.1e-5 K, step ends 7.4e-4 s (heating with the total current: 0.29 / 1.5 mV,
/// 11 / 31 mA, 0.35 K, 12 s).
#[test]
fn plating_under_self_heating_spm_matches_pybamm() {
    let submodels = Submodels { thermal: true, plating: PlatingModel::Irreversible, ..Default::default() };
    let case = Case { name: "spm_thermal_plating", kind: ModelKind::Spm, submodels, cycle: PLATING_CYCLE, cycles: 2, ambient: COLD };
    check(case, Limits { voltage: (3e-4, 1e-3), current: (2.3e-3, 2.5e-2), temperature: 3.5e-4, step_end: 4e-3 });
}

/// The OCPs' entropic change (O'Regan 2022's dU/dT of the LG M50) under self-heating at
/// 35 degC: the OCP `U(x) + (T - T_ref) dU/dT(x)` and the reversible heat `a j T dU/dT(x)` at
/// the particle surface. The term moves PyBaMM's first 2C discharge by 1.5 mV RMS (2.8 mV
/// at most) and the temperature by 5.7 K. Achieved: voltage RMS / max 4.0e-5 / 3.9e-4 mV,
/// hold current 4.0e-4 / 1.2e-3 mA, temperature 7.0e-5 K, step ends 5.9e-4 s.
#[test]
fn entropic_change_under_self_heating_spm_matches_pybamm() {
    let case = Case::at_35_degc("spm_thermal_entropic", ModelKind::Spm, true, SeiModel::None, 2);
    check(case, Limits { voltage: (2e-4, 2e-3), current: (2e-3, 6e-3), temperature: 3.5e-4, step_end: 3e-3 });
}

/// As [`entropic_change_under_self_heating_spm_matches_pybamm`], the SPMe (the term: 3.6 /
/// 12 mV, 5.6 K). Achieved: voltage 1.4e-2 / 2.3e-2 mV, hold current 9.9e-2 / 0.16 mA,
/// temperature 1.9e-2 K, step ends 7.7e-2 s, as the SPMe without it.
#[test]
fn entropic_change_under_self_heating_spme_matches_pybamm() {
    let case = Case::at_35_degc("spme_thermal_entropic", ModelKind::Spme, true, SeiModel::None, 2);
    check(case, Limits { voltage: (0.07, 0.12), current: (0.5, 0.8), temperature: 0.1, step_end: 0.4 });
}

/// As [`entropic_change_under_self_heating_spm_matches_pybamm`], the DFN, one cycle (the
/// term: 3.5 / 12 mV, 5.1 K). Achieved: voltage 1.4e-2 / 4.8e-2 mV, hold current 0.14 /
/// 0.34 mA, temperature 2.3e-2 K, step ends 9.1e-2 s, as the DFN without it.
#[test]
fn entropic_change_under_self_heating_dfn_matches_pybamm() {
    let case = Case::at_35_degc("dfn_thermal_entropic", ModelKind::Dfn, true, SeiModel::None, 1);
    check(case, Limits { voltage: (0.075, 0.25), current: (0.72, 1.7), temperature: 0.115, step_end: 0.45 });
}

/// The entropic change isothermal at 0 degC, 25 K below the OCPs' reference temperature: one
/// 1C cycle. Achieved: voltage RMS / max 3.3e-5 / 4.2e-4 mV, hold current 2.2e-4 / 5.8e-4 mA,
/// step ends 4.2e-4 s.
#[test]
fn entropic_change_at_0_degc_spm_matches_pybamm() {
    let case = Case { name: "spm_entropic_cold", kind: ModelKind::Spm, submodels: Submodels::default(), cycle: ENTROPIC_CYCLE, cycles: 1, ambient: FREEZING };
    check(case, Limits { voltage: (1.7e-4, 2e-3), current: (1.1e-3, 3e-3), temperature: 1e-9, step_end: 2.1e-3 });
}

/// As [`entropic_change_at_0_degc_spm_matches_pybamm`], the DFN. Achieved: voltage 1.3e-5 /
/// 6.8e-5 mV, hold current 3.8e-4 / 1.6e-3 mA, step ends 1.5e-3 s.
#[test]
fn entropic_change_at_0_degc_dfn_matches_pybamm() {
    let case = Case { name: "dfn_entropic_cold", kind: ModelKind::Dfn, submodels: Submodels::default(), cycle: ENTROPIC_CYCLE, cycles: 1, ambient: FREEZING };
    check(case, Limits { voltage: (7e-5, 3.4e-4), current: (1.9e-3, 8e-3), temperature: 1e-9, step_end: 7.5e-3 });
}
