//! `models::submodels::unread_reason` claims a submodel parameter is not read by a model only
//! when it is not: with the parameter changed, the model's initial state, right-hand side and
//! voltage stay the same bit for bit (at the start and half-way through a 1C discharge, at
//! rest, discharging and charging). And the check can see a read: each law's own parameter,
//! changed, changes the model.

use cellstudio::geometry::MeshSizes;
use cellstudio::models::submodels::{LamModel, ParticleSize, PlatingModel, SeiModel, unread_reason};
use cellstudio::models::{ModelBuilder, ModelKind, Submodels};
use cellstudio::params::{ParameterSet, chen2020};
use cellstudio::protocol::Protocol;
use cellstudio::simulation::{SimOptions, States, simulate};

/// The cell with every submodel parameter away from zero, so that a read shows.
fn cell() -> ParameterSet {
    let mut p = chen2020();
    for (path, value) in [
        ("cell.contact_resistance", 0.01),
        ("cell.rc_resistance", 0.005),
        ("cell.rc_capacitance", 1000.0),
        ("cell.hysteresis_voltage", 0.01),
        ("cell.leakage_current", 0.05),
        ("cell.voltage_offset", 0.002),
        ("cell.voltage_gain", 0.003),
        ("cell.current_gain", 0.02),
        ("negative.radius_relative_std", 0.3),
        ("positive.radius_relative_std", 0.3),
        ("lam.negative.current_rate", 1e-6),
        ("lam.positive.current_rate", 1e-6),
    ] {
        p.set(path, value).unwrap();
    }
    p
}

/// Every scalar parameter of the switchable submodels: the `sei`, `lam` and `plating` tables,
/// the cell's and electrodes' submodel parameters and the lumped thermal model's heat balance.
fn submodel_paths(p: &ParameterSet) -> Vec<String> {
    let mut out: Vec<String> = p.numeric_paths().into_iter().filter(|path| ["sei.", "lam.", "plating."].iter().any(|g| path.starts_with(g))).collect();
    let cell = ["contact_resistance", "rc_resistance", "rc_capacitance", "hysteresis_voltage", "hysteresis_rate", "hysteresis_initial", "leakage_current", "voltage_offset", "voltage_gain", "current_gain"];
    out.extend(cell.iter().map(|n| format!("cell.{n}")));
    out.extend(["negative.radius_relative_std", "positive.radius_relative_std"].map(String::from));
    let thermal = ["heat_transfer_coefficient", "cooling_area", "cell_volume", "negative_collector_heat_capacity", "positive_collector_heat_capacity"];
    out.extend(thermal.iter().map(|n| format!("thermal.{n}")));
    out.extend(["negative", "separator", "positive"].map(|d| format!("{d}.volumetric_heat_capacity")));
    out
}

/// What the model built with `p` computes: its initial state, then its right-hand side and
/// voltage at `states` and three currents, as bits.
fn fingerprint(kind: ModelKind, sub: Submodels, p: &ParameterSet, states: &[Vec<f64>]) -> Vec<u64> {
    let mut b = ModelBuilder::new(kind, sub, MeshSizes::default());
    let model = b.build(p).unwrap().model.as_ref();
    let mut bits: Vec<u64> = model.initial_state().iter().map(|v| v.to_bits()).collect();
    let mut out = vec![0.0; model.len()];
    for y in states {
        for current in [0.0, 5.0, -2.5] {
            model.rhs(y, current, &mut out);
            bits.extend(out.iter().map(|v| v.to_bits()));
            bits.push(model.voltage(y, current).to_bits());
        }
    }
    bits
}

/// `p` with the parameter at `path` moved (by 10 %, or from zero).
fn moved(p: &ParameterSet, path: &str) -> ParameterSet {
    let mut q = p.clone();
    let v = q.get(path).unwrap();
    q.set(path, if v == 0.0 { 1e-3 } else { 0.9 * v }).unwrap();
    q
}

#[test]
fn a_parameter_called_unread_changes_nothing_and_a_laws_own_parameter_changes_the_model() {
    let p = cell();
    let paths = submodel_paths(&p);
    assert!(paths.len() > 40, "{paths:?}");
    let reaction = SeiModel::ReactionLimited;
    let variants: [(Submodels, &str); 15] = [
        (Submodels::default(), "positive.thickness"),
        (Submodels { contact_resistance: true, rc: true, hysteresis: true, leak: true, voltage_offset: true, voltage_gain: true, current_gain: true, ..Default::default() }, "cell.rc_resistance"),
        (Submodels { thermal: true, ..Default::default() }, "thermal.heat_transfer_coefficient"),
        (Submodels { particle_size: ParticleSize::Distribution, ..Default::default() }, "positive.radius_relative_std"),
        (Submodels { sei: SeiModel::ReactionLimited, ..Default::default() }, "sei.exchange_current"),
        (Submodels { sei: SeiModel::SolventDiffusionLimited, ..Default::default() }, "sei.solvent_diffusivity"),
        (Submodels { sei: SeiModel::ElectronMigrationLimited, ..Default::default() }, "sei.electron_conductivity"),
        (Submodels { sei: SeiModel::InterstitialDiffusionLimited, ..Default::default() }, "sei.interstitial_diffusivity"),
        (Submodels { sei: SeiModel::EcReactionLimited, ..Default::default() }, "sei.kinetic_rate_constant"),
        (Submodels { lam: LamModel::StressDriven, ..Default::default() }, "lam.negative.proportional_term"),
        (Submodels { sei: reaction, lam: LamModel::ReactionDriven, ..Default::default() }, "lam.negative.reaction_factor"),
        (Submodels { lam: LamModel::CurrentDriven, ..Default::default() }, "lam.positive.current_rate"),
        (Submodels { plating: PlatingModel::Irreversible, ..Default::default() }, "plating.kinetic_rate_constant"),
        (Submodels { plating: PlatingModel::Reversible, ..Default::default() }, "plating.kinetic_rate_constant"),
        (Submodels { plating: PlatingModel::PartiallyReversible, ..Default::default() }, "plating.dead_lithium_decay_constant"),
    ];
    let mut checked = 0;
    for kind in [ModelKind::Spm, ModelKind::Spme, ModelKind::Dfn] {
        for &(sub, own) in &variants {
            let mut b = ModelBuilder::new(kind, sub, MeshSizes::default());
            let Ok(built) = b.build(&p) else {
                assert!(kind != ModelKind::Spm, "the SPM builds every variant: {sub:?}");
                continue; // e.g. the size distribution, built on the SPM only
            };
            let opts = SimOptions { states: States::Kept, ..SimOptions::for_cell(&p) };
            let sol = simulate(built.model.as_ref(), &mut built.workspace, &Protocol::discharge(1.0), &opts, None)
                .unwrap_or_else(|e| panic!("{kind} {sub:?}: {e}"));
            let states = vec![sol.states[0].clone(), sol.states[sol.states.len() / 2].clone()];
            let base = fingerprint(kind, sub, &p, &states);
            assert_ne!(base, fingerprint(kind, sub, &moved(&p, own), &states), "{kind} {sub:?}: changing its own {own} changed nothing");
            for path in &paths {
                if let Some(why) = unread_reason(&sub, path) {
                    assert_eq!(base, fingerprint(kind, sub, &moved(&p, path), &states), "{kind} {sub:?}: {path} is called unread ({why}) but changes the model");
                    checked += 1;
                }
            }
        }
    }
    println!("{checked} claims checked");
    assert!(checked > 500, "{checked} claims checked");
}
