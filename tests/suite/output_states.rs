//! The index lists a model declares about itself: `Model::output_states` lists every state the
//! voltage and temperature read (the energy quadrature interpolates only those, so a missing
//! index would silently bias the energy); `Model::rows_reading_current` lists every row of the
//! right-hand side that reads the applied current (a voltage hold puts the current's Jacobian
//! column on those rows only, so a missing row would leave its Newton matrix wrong).

use cellstudio::geometry::MeshSizes;
use cellstudio::models::ModelBuilder;
use cellstudio::models::submodels::{LamModel, ParticleSize, SeiModel};
use cellstudio::models::{Model, ModelKind, Submodels};
use cellstudio::params::chen2020;
use cellstudio::protocol::Protocol;
use cellstudio::simulation::{SimOptions, States, simulate};

/// Calls `check(kind, submodels, model, y)` for each model with each submodel variant it
/// builds, at the state half-way through a 1C discharge.
fn for_each_variant(mut check: impl FnMut(ModelKind, Submodels, &dyn Model, &[f64])) {
    let mut p = chen2020();
    p.cell.contact_resistance = 0.01;
    p.cell.rc_resistance = 0.005;
    p.cell.rc_capacitance = 1000.0;
    p.cell.hysteresis_voltage = 0.01;
    let variants = [
        Submodels::default(),
        Submodels { contact_resistance: true, thermal: true, ..Default::default() },
        Submodels { rc: true, hysteresis: true, thermal: true, ..Default::default() },
        Submodels { sei: SeiModel::ReactionLimited, thermal: true, ..Default::default() },
        Submodels { sei: SeiModel::ReactionLimited, lam: LamModel::StressAndReactionDriven, thermal: true, ..Default::default() },
        Submodels { particle_size: ParticleSize::Distribution, contact_resistance: true, thermal: true, ..Default::default() },
    ];
    for kind in [ModelKind::Spm, ModelKind::Spme, ModelKind::Dfn] {
        for sub in variants {
            if kind == ModelKind::Dfn && sub.lam != LamModel::None || kind != ModelKind::Spm && sub.particle_size != ParticleSize::Single {
                continue; // not built on the DFN, or on the SPM only
            }
            let mut b = ModelBuilder::new(kind, sub, MeshSizes::default());
            let built = b.build(&p).unwrap();
            let model = built.model.as_ref();
            let opts = SimOptions { states: States::Kept, ..SimOptions::for_cell(&p) };
            let sol = simulate(model, &mut built.workspace, &Protocol::discharge(1.0), &opts, None).unwrap();
            check(kind, sub, model, &sol.states[sol.states.len() / 2]);
        }
    }
}

#[test]
fn voltage_and_temperature_read_only_the_output_states() {
    for_each_variant(|kind, sub, model, y| {
        let outputs = model.output_states();
        assert!(outputs.len() < model.len(), "{kind} {sub:?}: the model should need fewer states than it has");
        // Every other state replaced: by a far-off value, then by NaN.
        for junk in [|v: f64| 1.7 * v + 0.3, |_| f64::NAN] {
            let mut masked: Vec<f64> = y.iter().map(|&v| junk(v)).collect();
            for &i in &outputs {
                masked[i] = y[i];
            }
            for current in [0.0, 5.0, -2.5] {
                let (v, v_masked) = (model.voltage(y, current), model.voltage(&masked, current));
                assert_eq!(v.to_bits(), v_masked.to_bits(), "{kind} {sub:?}: voltage at {current} A reads an unlisted state");
            }
            assert_eq!(model.temperature(y).to_bits(), model.temperature(&masked).to_bits(), "{kind} {sub:?}: temperature");
        }
    });
}

#[test]
fn only_the_listed_rows_read_the_current() {
    let mut sparse = 0;
    for_each_variant(|kind, sub, model, y| {
        let rows = model.rows_reading_current();
        let n = model.len();
        let (mut f0, mut f1) = (vec![0.0; n], vec![0.0; n]);
        for current in [0.0, 5.0, -2.5] {
            model.rhs(y, current, &mut f0);
            model.rhs(y, current + 0.37, &mut f1);
            for i in (0..n).filter(|&i| f0[i].to_bits() != f1[i].to_bits()) {
                assert!(rows.contains(&i), "{kind} {sub:?}: row {i} of {n} reads the current at {current} A but is not listed");
            }
        }
        // The DFN without loss of active material lists only the collector and heat rows,
        // the appended RC and hysteresis states too.
        if kind == ModelKind::Dfn && sub.lam == LamModel::None {
            assert!(rows.len() < 8, "{kind} {sub:?}: {} of {n} rows listed", rows.len());
            sparse += 1;
        }
    });
    assert_eq!(sparse, 4, "DFN variants without loss of active material");
}

/// `States::Observed` hands the observer every state, identical to those `States::Kept`
/// stores, and stores none itself (memory flat on long recordings).
#[test]
fn observed_states_are_the_kept_ones_but_not_stored() {
    let p = chen2020();
    for kind in [ModelKind::Spm, ModelKind::Dfn] {
        let mut b = ModelBuilder::new(kind, Submodels::default(), MeshSizes::default());
        let built = b.build(&p).unwrap();
        let model = built.model.as_ref();
        let run = |states: States, ws: &mut _| {
            let mut seen = Vec::new();
            let opts = SimOptions { states, t_eval: Some((0..=30).map(|k| 100.0 * k as f64).collect()), ..SimOptions::for_cell(&p) };
            let sol = cellstudio::simulation::simulate_observed(model, ws, &Protocol::discharge(1.0), &opts, None, &mut |y, _| seen.push(y.to_vec())).unwrap();
            (sol, seen)
        };
        let (kept, seen_kept) = run(States::Kept, &mut built.workspace);
        let (observed, seen) = run(States::Observed, &mut built.workspace);
        assert_eq!(kept.states.len(), 31, "{kind}");
        assert!(observed.states.is_empty(), "{kind}: observed states were stored");
        assert_eq!(seen, kept.states, "{kind}: the observer saw other states than those kept");
        assert_eq!(seen_kept, kept.states, "{kind}");
        // Only the output states are current otherwise: some other state differs.
        let (_, partial) = run(States::ForOutputs, &mut built.workspace);
        assert_ne!(partial, kept.states, "{kind}: ForOutputs evaluated every state");
    }
}
