//! Analytic limits and invariants: lithium conservation, the open-circuit limit, and the
//! ordering of SPM / SPMe / DFN with rate.

use crate::common;

use cellstudio::geometry::MeshSizes;
use cellstudio::models::ModelBuilder;
use cellstudio::models::{ModelKind, Submodels};
use cellstudio::params::chen2020;
use cellstudio::protocol::{Protocol, Step};
use cellstudio::simulation::{SimOptions, States, simulate};
use common::{pulse, run};

const KINDS: [ModelKind; 3] = [ModelKind::Spm, ModelKind::Spme, ModelKind::Dfn];

/// Solid-phase lithium is conserved to round-off under any current: discharge, rest,
/// charge, and a drive-cycle-like table, with and without the thermal submodel.
#[test]
fn solid_lithium_is_conserved() {
    let p = chen2020();
    let protocol = Protocol {
        steps: vec![
            Step::CRate { rate: 2.0, duration: 600.0, until_voltage: None },
            Step::Rest { duration: 300.0 },
            Step::Current { current: -3.0, duration: 300.0, until_voltage: None },
            Step::Table { time: vec![0.0, 30.0, 60.0, 90.0, 120.0], current: vec![5.0, -5.0, 8.0, 0.0, 2.0] },
        ],
    };
    for kind in KINDS {
        for thermal in [false, true] {
            let sub = Submodels { thermal, ..Default::default() };
            let mut b = ModelBuilder::new(kind, sub, MeshSizes::default());
            let built = b.build(&p).unwrap();
            let opts = SimOptions { states: States::Kept, ..SimOptions::for_cell(&p) };
            let sol = simulate(built.model.as_ref(), &mut built.workspace, &protocol, &opts, None).unwrap();
            let li0 = built.model.solid_lithium(&sol.states[0]);
            let worst = sol
                .states
                .iter()
                .map(|y| (built.model.solid_lithium(y) - li0).abs() / li0)
                .fold(0.0, f64::max);
            println!("{kind} thermal={thermal}: Li {li0:.6} mol, worst relative drift {worst:.2e}");
            assert!(sol.final_capacity().abs() > 0.1, "{kind}: protocol moved no charge");
            assert!(worst < 1e-10, "{kind} thermal={thermal}: lithium drift {worst:e}");
        }
    }
}

/// At vanishing current the terminal voltage tends to the OCV of the particle
/// stoichiometries, linearly in current (overpotentials are linear at small current).
#[test]
fn low_current_voltage_tends_to_ocv() {
    let p = chen2020();
    for kind in KINDS {
        let gaps: Vec<f64> = [0.01, 0.001]
            .iter()
            .map(|&rate| {
                let protocol = Protocol { steps: vec![Step::CRate { rate, duration: 600.0, until_voltage: None }] };
                let mut b = ModelBuilder::new(kind, Submodels::default(), MeshSizes::default());
                let built = b.build(&p).unwrap();
                let opts = SimOptions { states: States::Kept, ..SimOptions::for_cell(&p) };
                let sol = simulate(built.model.as_ref(), &mut built.workspace, &protocol, &opts, None).unwrap();
                let y = sol.states.last().unwrap();
                (sol.final_voltage() - built.model.open_circuit_voltage(y)).abs()
            })
            .collect();
        println!("{kind}: |V - OCV| = {:.4} mV at C/100, {:.4} mV at C/1000", gaps[0] * 1e3, gaps[1] * 1e3);
        assert!(gaps[1] < 0.5e-3, "{kind}: {} V from OCV at C/1000", gaps[1]);
        let ratio = gaps[0] / gaps[1];
        assert!((7.0..13.0).contains(&ratio), "{kind}: gap should scale with current, ratio {ratio}");
    }
}

/// SPM, SPMe and DFN agree at C/20 and diverge as the rate grows, SPM first.
#[test]
fn models_agree_at_low_rate_and_diverge_in_order() {
    let p = chen2020();
    let mut spm_gap = Vec::new();
    let mut spme_gap = Vec::new();
    for rate in [0.05, 1.0, 2.0] {
        let protocol = Protocol::discharge(rate);
        let t: Vec<f64> = (0..200).map(|k| k as f64 * 0.9 / rate * 3600.0 / 200.0 * 0.95).collect();
        let v = |kind| run(kind, Submodels::default(), MeshSizes::default(), &p, &protocol, Some(t.clone()), false).voltage;
        let (spm, spme, dfn) = (v(ModelKind::Spm), v(ModelKind::Spme), v(ModelKind::Dfn));
        let rms = |a: &[f64]| (a.iter().zip(&dfn).map(|(x, y)| (x - y) * (x - y)).sum::<f64>() / a.len() as f64).sqrt();
        spm_gap.push(rms(&spm));
        spme_gap.push(rms(&spme));
        println!("{rate}C: SPM-DFN {:.2} mV, SPMe-DFN {:.2} mV", spm_gap.last().unwrap() * 1e3, spme_gap.last().unwrap() * 1e3);
    }
    // Overpotentials are nearly linear in current, so the C/20 gaps should be about 1/20 of
    // the 1C gaps; allow 1/10, and a few mV in absolute terms.
    assert!(spm_gap[0] < 5e-3 && spme_gap[0] < 1e-3, "models disagree at C/20");
    assert!(spm_gap[0] < spm_gap[1] / 10.0 && spme_gap[0] < spme_gap[1] / 10.0, "C/20 gap not small vs 1C");
    for k in 0..3 {
        assert!(spme_gap[k] < spm_gap[k], "SPMe should be closer to DFN than SPM");
    }
    for g in [&spm_gap, &spme_gap] {
        assert!(g[0] < g[1] && g[1] < g[2], "gap should grow with rate: {g:?}");
    }
}

/// The pulse protocol relaxes back towards the OCV during each rest.
#[test]
fn pulse_relaxes_to_ocv() {
    let p = chen2020();
    for kind in KINDS {
        let sol = run(kind, Submodels::default(), MeshSizes::default(), &p, &pulse(), None, true);
        let mut b = ModelBuilder::new(kind, Submodels::default(), MeshSizes::default());
        let model = &b.build(&p).unwrap().model;
        let y = sol.states.last().unwrap();
        let gap = (sol.final_voltage() - model.open_circuit_voltage(y)).abs();
        assert!(gap < 1e-3, "{kind}: {gap} V from OCV after 10 min rest");
    }
}

/// A second active material in the negative electrode (15 % of its sites filling around
/// 0.3 V vs Li, silicon-like): at C/1000 the SPM's voltage is the blend's OCV at the particles'
/// average stoichiometries, computed independently of the model's table (by bisection on the
/// host stoichiometry, `Electrode::open_circuit_potential`), and lithium stays conserved.
#[test]
fn a_second_material_sets_the_open_circuit_limit() {
    let mut p = chen2020();
    (p.negative.second_phase_share, p.negative.second_phase_potential, p.negative.second_phase_width) = (0.15, 0.3, 0.08);
    cellstudio::params::set_initial_soc(&mut p, 0.3).unwrap();
    let protocol = Protocol { steps: vec![Step::CRate { rate: 0.001, duration: 600.0, until_voltage: None }] };
    let mut b = ModelBuilder::new(ModelKind::Spm, Submodels::default(), MeshSizes::default());
    let built = b.build(&p).unwrap();
    let opts = SimOptions { states: States::Kept, ..SimOptions::for_cell(&p) };
    let sol = simulate(built.model.as_ref(), &mut built.workspace, &protocol, &opts, None).unwrap();
    let y = sol.states.last().unwrap();
    let (nn, np) = (built.model.electrochem().disc.sphere_n.len(), built.model.electrochem().disc.sphere_p.len());
    let ec = built.model.electrochem();
    let (xn, yp) = (ec.disc.sphere_n.average(&y[..nn]) / p.negative.max_concentration, ec.disc.sphere_p.average(&y[nn..nn + np]) / p.positive.max_concentration);
    let ocv = p.positive.open_circuit_potential(yp) - p.negative.open_circuit_potential(xn);
    let gap = (sol.final_voltage() - ocv).abs();
    let plain = p.positive.ocp.eval(yp) - p.negative.ocp.eval(xn);
    println!("second material: |V - blend OCV| = {:.4} mV at C/1000 (the host's OCV alone is {:.1} mV away)", gap * 1e3, (sol.final_voltage() - plain).abs() * 1e3);
    assert!(gap < 0.5e-3, "{gap} V from the blend's OCV");
    assert!((sol.final_voltage() - plain).abs() > 10e-3, "the second material should move the OCV here");
    let li = |y: &[f64]| built.model.solid_lithium(y);
    assert!((li(y) / li(&sol.states[0]) - 1.0).abs() < 1e-10);
    // The ECM's equilibrium OCV from the same set reads the blend too (SOC 1 is the set's
    // initial state, so the discharged charge gives the SOC).
    let (capacity, ocv_table) = cellstudio::models::ecm::equilibrium_ocv_table(&p, 4001);
    let soc = 1.0 - sol.capacity.last().unwrap() / capacity;
    let ecm_gap = (ocv_table.eval(soc) - sol.final_voltage()).abs();
    println!("second material: the ECM's equilibrium OCV is {:.4} mV from the SPM at C/1000", ecm_gap * 1e3);
    assert!(ecm_gap < 0.5e-3, "the ECM's OCV table is {ecm_gap} V from the SPM at C/1000");
}

/// A particle radius sets the particles' diffusion time as R^2/D and the surface per volume as
/// 3 eps/R: scaling the radius by `f` gives the voltage of the set with D / f^2 and the rate
/// constant / f to round-off (the scaled particle mesh is the same discretisation), in every
/// model: a recording cannot tell a radius from the pair (the reason a coarser powder is named
/// as kinetics and diffusivity together).
#[test]
fn a_particle_radius_is_a_diffusivity_and_a_rate_constant_together() {
    let p = chen2020();
    let protocol = pulse();
    for kind in KINDS {
        for (side, f) in [("negative", 2.0), ("positive", 0.6)] {
            let mut radius = p.clone();
            radius.set(&format!("{side}.particle_radius"), f * p.get(&format!("{side}.particle_radius")).unwrap()).unwrap();
            let mut both = p.clone();
            both.set(&format!("{side}.diffusivity"), p.get(&format!("{side}.diffusivity")).unwrap() / (f * f)).unwrap();
            both.set(&format!("{side}.rate_constant"), p.get(&format!("{side}.rate_constant")).unwrap() / f).unwrap();
            let t: Vec<f64> = (0..=360).map(|k| 10.0 * k as f64).collect();
            let v = |q: &cellstudio::params::ParameterSet| run(kind, Submodels::default(), MeshSizes::default(), q, &protocol, Some(t.clone()), false).voltage;
            let (a, b, set) = (v(&radius), v(&both), v(&p));
            let rms = |x: &[f64], y: &[f64]| (x.iter().zip(y).map(|(u, w)| (u - w).powi(2)).sum::<f64>() / x.len() as f64).sqrt();
            let (gap, effect) = (rms(&a, &b), rms(&a, &set));
            println!("{kind} {side} radius x{f}: {:.2e} mV from D/f^2 and k/f (round-off: the same discretisation), the radius itself moves it {:.2} mV", gap * 1e3, effect * 1e3);
            assert!(effect > 1e-3, "{kind} {side}: the radius moved the voltage only {effect:e} V");
            assert!(gap < 1e-13, "{kind} {side}: {gap:e} V apart");
        }
    }
}
