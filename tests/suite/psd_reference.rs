//! The particle-size distribution submodel against PyBaMM 26.10's many-particle model
//! (`scripts/make_psd_reference.py`, curves in `tests/data/psd/`): Chen 2020 with
//! `get_size_distribution_parameters`, isothermal, from the set's initial concentrations,
//! 20 shells per particle and 30 sizes per electrode in both, PyBaMM's IDAKLU at
//! rtol = atol = 1e-8 and ours at 1e-8. Each step runs from the last one's end state at
//! PyBaMM's output times; the voltage is compared 20 s and more from each step's ends.

use crate::common;

use cellstudio::geometry::MeshSizes;
use cellstudio::models::submodels::ParticleSize;
use cellstudio::models::{ModelBuilder, ModelKind, Submodels};
use cellstudio::params::chen2020;
use cellstudio::protocol::{Step, experiment};

/// Voltage RMS and max (mV), the largest step-end difference (s) and the largest
/// temperature difference (K, with `thermal`) of case `name`: relative standard deviations
/// `std` (negative, positive), ambient `ambient` (K), steps `steps` (PyBaMM's strings).
fn compare(name: &str, std: [f64; 2], ambient: f64, steps: &[&str], thermal: bool) -> [f64; 4] {
    let rec = common::csv_rows("psd", &format!("{name}.csv"));
    let mut p = chen2020();
    (p.negative.radius_relative_std, p.positive.radius_relative_std) = (std[0], std[1]);
    (p.thermal.ambient_temperature, p.thermal.initial_temperature) = (ambient, ambient);
    p.thermal.heat_transfer_coefficient = 12.0;
    let steps: Vec<Step> = experiment::parse(steps, p.cell.nominal_capacity).unwrap().steps;
    let submodels = Submodels { particle_size: ParticleSize::Distribution, thermal, ..Default::default() };
    let mut b = ModelBuilder::new(ModelKind::Spm, submodels, MeshSizes::default());
    let built = b.build(&p).unwrap();
    let mut dt: f64 = 0.0;
    let run = common::step_by_step(built.model.as_ref(), &mut built.workspace, &steps, &rec, 3, |_| false, &common::tight_options(&p), |sol, k, r| {
        if thermal {
            dt = dt.max((sol.temperature[k] - r[4]).abs());
        }
    });
    assert!(run.voltage.len() > 250, "{name}: compared {} voltages", run.voltage.len());
    let gaps = [common::rms(&run.voltage), common::max_abs(&run.voltage), run.step_end, dt];
    println!("{name}: voltage RMS / max {:.2e} / {:.2e} mV, step ends {:.2e} s apart, temperature {:.2e} K", gaps[0], gaps[1], gaps[2], gaps[3]);
    gaps
}

/// Asserts case `name`'s gaps are below `limits` (voltage RMS and max in mV, step ends in s,
/// temperature in K).
fn check(name: &str, std: [f64; 2], ambient: f64, steps: &[&str], thermal: bool, limits: [f64; 4]) {
    let g = compare(name, std, ambient, steps, thermal);
    assert!(g[0] < limits[0] && g[1] < limits[1], "{name}: voltage RMS / max {} / {} mV", g[0], g[1]);
    assert!(g[2] < limits[2], "{name}: step ends {} s apart", g[2]);
    assert!(g[3] <= limits[3], "{name}: temperature {} K", g[3]);
}

/// Relative std 0.3 in both electrodes, 1C to 2.5 V at 25 degC. Achieved: voltage RMS / max
/// 2.6e-5 / 2.0e-4 mV, cut-off 9e-7 s apart.
#[test]
fn mpm_1c_discharge_matches_pybamm() {
    check("mpm_1c", [0.3, 0.3], 298.15, &["Discharge at 1C until 2.5 V"], false, [1.2e-4, 1e-3, 1e-4, 0.0]);
}

/// 4 x (2C for 3 min, 20 min rest) at 25 degC: the sizes exchange lithium through the
/// shared potential during the rests. Achieved: 1.2e-5 / 9.4e-5 mV.
#[test]
fn mpm_pulse_relaxation_matches_pybamm() {
    let steps: Vec<&str> = (0..4).flat_map(|_| ["Discharge at 2C for 3 minutes", "Rest for 20 minutes"]).collect();
    check("mpm_pulse", [0.3, 0.3], 298.15, &steps, false, [6e-5, 5e-4, 1e-4, 0.0]);
}

/// 1C at 15 degC (isothermal; Arrhenius exchange currents). Achieved: 2.3e-5 / 1.3e-4 mV,
/// cut-off 2.3e-6 s apart.
#[test]
fn mpm_at_15_degc_matches_pybamm() {
    check("mpm_1c_15degc", [0.3, 0.3], 288.15, &["Discharge at 1C until 2.5 V"], false, [1.2e-4, 7e-4, 1e-4, 0.0]);
}

/// Relative std 0.15 (negative) and 0.45 (positive), 2C to 2.5 V then 30 min rest. Achieved:
/// 7.3e-5 / 6.4e-4 mV, cut-off 3.6e-5 s apart. The smallest positive particles fill at the
/// end of the discharge: without PyBaMM's OCP asymptotes
/// ([`cellstudio::models::Electrochem::bounded_ocp`]) the cut-off came 0.74 s apart and the
/// rest 0.98 / 1.6 mV off.
#[test]
fn mpm_with_different_spreads_matches_pybamm() {
    check("mpm_2c_mixed", [0.15, 0.45], 298.15, &["Discharge at 2C until 2.5 V", "Rest for 30 minutes"], false, [3.5e-4, 3e-3, 2e-4, 0.0]);
}

/// Lumped thermal (h = 12 W/(m^2 K), from 25 degC), 2C to 2.5 V then 30 min rest: PyBaMM heats
/// with the area-weighted mean overpotential, `I (U_bar - V)` with the area-weighted mean
/// surface OCPs. Achieved: voltage RMS / max 6.3e-5 / 4.3e-4 mV, cut-off 1.1e-6 s apart,
/// temperature 1.0e-6 K.
#[test]
fn mpm_with_lumped_thermal_matches_pybamm() {
    check("mpm_thermal", [0.3, 0.3], 298.15, &["Discharge at 2C until 2.5 V", "Rest for 30 minutes"], true, [3e-4, 2e-3, 1e-5, 5e-6]);
}
