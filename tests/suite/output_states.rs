//! `Model::output_states` lists every state the voltage and temperature read: the energy
//! quadrature interpolates only those, so a missing index would silently bias the energy.

use cellstudio::geometry::MeshSizes;
use cellstudio::models::ModelBuilder;
use cellstudio::models::submodels::{LamModel, ParticleSize, SeiModel};
use cellstudio::models::{ModelKind, Submodels};
use cellstudio::params::chen2020;
use cellstudio::protocol::Protocol;
use cellstudio::simulation::{SimOptions, simulate};

#[test]
fn voltage_and_temperature_read_only_the_output_states() {
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
            let opts = SimOptions { keep_states: true, ..SimOptions::for_cell(&p) };
            let sol = simulate(model, &mut built.workspace, &Protocol::discharge(1.0), &opts, None).unwrap();
            let y = &sol.states[sol.states.len() / 2];
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
        }
    }
}
