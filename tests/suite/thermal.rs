//! Lumped thermal submodel: energy balance and Arrhenius coupling.

use crate::common;

use cellstudio::geometry::{Discretisation, Geometry, MeshSizes};
use cellstudio::models::electrochem::Side;
use cellstudio::models::spm::Spm;
use cellstudio::models::{Electrochem, Model};
use cellstudio::simulation::{SimOptions, States, simulate};
use cellstudio::solver::Workspace;
use cellstudio::models::{ModelKind, Submodels};
use cellstudio::models::submodels::LumpedThermal;
use cellstudio::params::chen2020;
use cellstudio::protocol::Protocol;
use common::run;

const THERMAL: Submodels = Submodels { contact_resistance: false, thermal: true, rc: false, hysteresis: false, leak: false, voltage_offset: false, voltage_gain: false, current_gain: false, ocv_correction: false, sei: cellstudio::models::submodels::SeiModel::None, lam: cellstudio::models::submodels::LamModel::None, plating: cellstudio::models::submodels::PlatingModel::None, stress_induced_diffusion: None, particle_size: cellstudio::models::submodels::ParticleSize::Single };

/// With no cooling, the temperature state must integrate the heat source: C dT equals
/// the integral of the irreversible + ohmic heat I (U_surf - V) (PyBaMM's lumped source,
/// entropic terms being zero in Chen 2020), computed here independently by quadrature on the
/// stored states; and it is bounded by the electrical work lost against the bulk OCV.
#[test]
fn adiabatic_temperature_rise_matches_integrated_heat() {
    let mut p = chen2020();
    p.thermal.heat_transfer_coefficient = 0.0;
    let ec = Electrochem::new(p.clone(), Discretisation::new(Geometry::of(&p, MeshSizes::default())), THERMAL);
    let model = Spm::new(ec);
    let mut ws = Workspace::new(model.len(), model.jacobian_pattern()).unwrap();
    let t_eval: Vec<f64> = (0..=3400).map(|k| k as f64 * 0.5).collect();
    let opts = SimOptions { states: States::Kept, t_eval: Some(t_eval), ..SimOptions::for_cell(&p) };
    let sol = simulate(&model, &mut ws, &Protocol::discharge(2.0), &opts, None).unwrap();
    let (mut heat, mut lost) = (0.0, 0.0);
    let rate = |k: usize| {
        let y = &sol.states[k];
        let (sn, sp) = model.surface_concentrations(y);
        let t = sol.temperature[k];
        let ocv_surface = model.ec.ocp(Side::Positive, sp, t) - model.ec.ocp(Side::Negative, sn, t);
        let i = sol.current[k];
        (i * (ocv_surface - sol.voltage[k]), i * (model.open_circuit_voltage(y) - sol.voltage[k]))
    };
    for k in 1..sol.time.len() {
        let dt = sol.time[k] - sol.time[k - 1];
        let (a, b) = (rate(k - 1), rate(k));
        heat += 0.5 * dt * (a.0 + b.0);
        lost += 0.5 * dt * (a.1 + b.1);
    }
    let t_rise = sol.temperature.last().unwrap() - sol.temperature[0];
    let stored = LumpedThermal::new(&p).heat_capacity * t_rise;
    println!("dT = {t_rise:.3} K, C dT = {stored:.1} J, integrated heat = {heat:.1} J, lost work vs bulk OCV = {lost:.1} J");
    assert!(t_rise > 1.0, "a 2C adiabatic discharge should heat the cell");
    assert!((stored - heat).abs() < 0.005 * heat, "{stored} J stored vs {heat} J generated");
    assert!(heat < lost, "heat {heat} J exceeds the work lost {lost} J");
}

/// A warmer cell has faster kinetics and diffusion: higher voltage under the same load.
#[test]
fn warmer_cell_has_lower_overpotential() {
    let mut cold = chen2020();
    cold.negative.diffusivity_activation_energy = 30e3;
    cold.positive.diffusivity_activation_energy = 30e3;
    let mut warm = cold.clone();
    warm.thermal.ambient_temperature = 318.15;
    warm.thermal.initial_temperature = 318.15;
    let t: Vec<f64> = vec![600.0];
    for kind in [ModelKind::Spm, ModelKind::Dfn] {
        let v = |p: &cellstudio::params::ParameterSet| {
            run(kind, THERMAL, MeshSizes::default(), p, &Protocol::discharge(1.0), Some(t.clone()), false).voltage[0]
        };
        let (vc, vw) = (v(&cold), v(&warm));
        println!("{kind}: V(600 s) = {vc:.4} V at 298 K, {vw:.4} V at 318 K");
        assert!(vw > vc + 5e-3, "{kind}: warm {vw} V vs cold {vc} V");
    }
}
