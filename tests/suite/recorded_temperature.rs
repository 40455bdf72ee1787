//! A model whose temperature follows a recorded one (`ModelSpec::recorded_temperature`),
//! proven on a PyBaMM-made recording (blind batch aj5): a wheelchair's cell taken from 21 degC
//! indoors to -4 degC outside and back, its temperature recorded. The isothermal DFN at 21 degC
//! misses it by about 14 mV; following the recorded temperature, the DFN at the case's true
//! initial state (90 %) replays it to the 1 mV noise (0.975 mV measured).

use std::path::Path;

use cellstudio::data::Recording;
use cellstudio::models::{ModelKind, Submodels};
use cellstudio::params::chen2020;
use cellstudio::problem::fitting::{FitParameter, FittingProblem, INITIAL_SOC, ModelSpec};

const CASE: &str = "tests/data/diagnosis-extra/aj5_ambient_change_wheelchair_outing_in_frost_21C_to_minus4C_recorded_10s_dfn/recording.csv";

/// The aj5 recording, and a fit of its initial state of charge with `kind` (thermal or not),
/// at the case's ambient and recorded first temperature, following the recorded temperature
/// when `follow`.
fn problem(kind: ModelKind, thermal: bool, follow: bool) -> (Recording, FittingProblem) {
    let rec = Recording::from_csv(Path::new(CASE)).unwrap();
    let mut base = chen2020();
    base.thermal.ambient_temperature = 294.15;
    base.thermal.initial_temperature = rec.temperature.as_ref().unwrap()[0];
    let spec = ModelSpec { kind, submodels: Submodels { thermal, ..Submodels::default() }, mesh: Default::default(), recorded_temperature: follow };
    let problem = FittingProblem::new(spec, base, vec![FitParameter::linear(INITIAL_SOC, 0.9, 0.3, 1.0)], rec.clone()).unwrap();
    (rec, problem)
}

/// Points not at a repeated time (either side of a current step), as fits count them.
fn counted(rec: &Recording) -> Vec<usize> {
    (0..rec.time.len()).filter(|&k| !rec.is_repeated(k)).collect()
}

/// RMSE (V) of the DFN's replay at initial state of charge 0.9.
fn replay_rmse(thermal: bool, follow: bool) -> f64 {
    let (rec, problem) = problem(ModelKind::Dfn, thermal, follow);
    let v = problem.simulate(&[0.9]).unwrap();
    let points = counted(&rec);
    (points.iter().map(|&k| (rec.voltage[k] - v[k]).powi(2)).sum::<f64>() / points.len() as f64).sqrt()
}

#[test]
fn a_dfn_following_the_recorded_temperature_replays_a_cell_taken_into_the_cold() {
    let followed = replay_rmse(true, true);
    let isothermal = replay_rmse(false, false);
    println!("RMSE at 90 % SOC: following the recorded temperature {:.3} mV, isothermal {:.3} mV", followed * 1e3, isothermal * 1e3);
    assert!(followed < 1.05e-3, "following the recorded temperature: {:.3} mV (noise 1 mV)", followed * 1e3);
    assert!(isothermal > 10e-3, "the isothermal replay should miss the cold: {:.3} mV", isothermal * 1e3);
}

#[test]
fn following_a_temperature_needs_one_recorded_and_a_thermal_model() {
    let rec = Recording::from_csv(Path::new(CASE)).unwrap();
    let follow = |thermal: bool, rec: Recording| {
        let spec = ModelSpec { kind: ModelKind::Spm, submodels: Submodels { thermal, ..Submodels::default() }, mesh: Default::default(), recorded_temperature: true };
        FittingProblem::new(spec, chen2020(), vec![FitParameter::linear(INITIAL_SOC, 0.9, 0.3, 1.0)], rec).err().expect("refused").to_string()
    };
    let why = follow(false, rec.clone());
    assert!(why.contains("model.submodels.thermal"), "{why}");
    let mut without = rec;
    without.temperature = None;
    let why = follow(true, without);
    assert!(why.contains("data.temperature"), "{why}");
}

/// Forward sensitivities follow the recorded temperature too (their temperature rows decay to
/// zero, as the recording does not depend on the parameters): dV/dSOC from them matches a
/// central difference of two plain replays (step 1e-3) to 2.4e-4 of its RMS (the difference's
/// own noise: the replays step differently through the recorded temperature's kinks). Copies
/// that ran their own heat balance were 1.4e-3 off.
#[test]
fn sensitivities_follow_the_recorded_temperature() {
    let (followed, own) = (sensitivity_error(true), sensitivity_error(false));
    println!("relative RMS error of dV/dSOC: following {followed:.2e}, own heat balance {own:.2e}");
    assert!(followed < 6e-4, "{followed:.3e}");
    assert!(own < 2e-4, "{own:.3e}");
}

/// RMS difference of dV/dSOC from forward sensitivities and from a central difference of two
/// replays, relative to the latter's RMS (thermal SPMe).
fn sensitivity_error(follow: bool) -> f64 {
    let (rec, problem) = problem(ModelKind::Spme, true, follow);
    let with = problem.simulate_with_sensitivities(&[0.9]).unwrap();
    let h = 1e-3;
    let (up, down) = (problem.simulate(&[0.9 + h]).unwrap(), problem.simulate(&[0.9 - h]).unwrap());
    let rows: Vec<f64> = with.sensitivity_rows().map(|r| r[0]).collect();
    let points = counted(&rec);
    let difference: Vec<f64> = points.iter().map(|&k| (up[k] - down[k]) / (2.0 * h)).collect();
    let scale = (difference.iter().map(|d| d * d).sum::<f64>() / difference.len() as f64).sqrt();
    let error = (points.iter().zip(&difference).map(|(&k, d)| (rows[k] - d).powi(2)).sum::<f64>() / difference.len() as f64).sqrt();
    error / scale
}
