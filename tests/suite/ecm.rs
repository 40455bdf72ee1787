//! Thevenin equivalent-circuit model: closed-form step and relaxation responses through the
//! simulation runner, thermal and charge balances, the Chen 2020 default, and input errors.

use cellstudio::models::Model;
use cellstudio::models::ecm::{Ecm, EcmParameters, EcmThermal, RcPair};
use cellstudio::params::Function1D;
use cellstudio::protocol::{Protocol, Step};
use cellstudio::simulation::{Integrals, SimOptions, States, Solution, simulate};
use cellstudio::solver::Workspace;

const CAPACITY: f64 = 2.0; // A h
const SOC0: f64 = 0.9;
const R0: f64 = 0.015; // ohm
const R1: f64 = 0.025; // ohm
const C1: f64 = 800.0; // F, tau = 20 s

/// OCV linear in SOC: 3.0 V at SOC 0, 4.2 V at SOC 1.
fn linear_ocv(soc: f64) -> f64 {
    3.0 + 1.2 * soc
}

fn one_rc() -> EcmParameters {
    EcmParameters {
        capacity: CAPACITY,
        initial_soc: SOC0,
        r0: R0,
        rc_pairs: vec![RcPair { r: R1, c: C1 }],
        ocv: Function1D::Table { x: vec![0.0, 1.0], y: vec![linear_ocv(0.0), linear_ocv(1.0)] },
        ambient_temperature: 298.15,
        thermal: None,
    }
}

fn run(model: &Ecm, protocol: &Protocol, t_eval: Vec<f64>, keep_states: bool) -> Solution {
    let mut ws = Workspace::new(model.len(), model.jacobian_pattern()).unwrap();
    let opts = SimOptions {
        solver: Default::default(),
        t_eval: Some(t_eval),
        states: if keep_states { States::Kept } else { States::ForOutputs },
        cutoffs: (2.5, 4.3),
        capacity: model.params().capacity,
        integrals: Integrals::AtEveryOutput,
        temperature_input: None,
    };
    simulate(model, &mut ws, protocol, &opts, None).unwrap()
}

fn grid(end: f64, dt: f64) -> Vec<f64> {
    (0..=(end / dt).round() as usize).map(|i| i as f64 * dt).collect()
}

/// Constant-current step: V(t) = OCV(SOC(t)) - I R0 - I R1 (1 - exp(-t / (R1 C1))).
#[test]
fn constant_current_step_matches_closed_form() {
    let model = Ecm::new(one_rc()).unwrap();
    let tau = R1 * C1;
    for current in [CAPACITY, -0.5 * CAPACITY, 3.0 * CAPACITY] {
        let duration = 600.0;
        let protocol = Protocol { steps: vec![Step::Current { current, duration, until_voltage: None }] };
        let sol = run(&model, &protocol, grid(duration, 0.5), false);
        assert_eq!(sol.time.len(), 1201);
        let exact = |t: f64| {
            let soc = SOC0 - current * t / (3600.0 * CAPACITY);
            linear_ocv(soc) - current * R0 - current * R1 * (1.0 - (-t / tau).exp())
        };
        let worst = sol.time.iter().zip(&sol.voltage).map(|(&t, &v)| (v - exact(t)).abs()).fold(0.0, f64::max);
        let q_err = (sol.final_capacity() - current * duration / 3600.0).abs();
        println!(
            "I = {current} A: max |V - V_exact| = {worst:.3e} V over {} outputs, {} steps; capacity error {q_err:.2e} A h",
            sol.time.len(),
            sol.stats.steps
        );
        assert!(worst < 1e-5, "I = {current} A: voltage error {worst:e} V");
        assert!(q_err < 1e-9, "I = {current} A: capacity error {q_err:e} A h");
    }
}

/// Rest after a pulse: the RC voltage decays as exp(-(t - t_p) / (R1 C1)), so one time
/// constant after the pulse V is OCV - v1(t_p) / e, and the fitted decay rate is 1 / tau.
#[test]
fn rest_after_pulse_relaxes_with_rc_time_constant() {
    let model = Ecm::new(one_rc()).unwrap();
    let tau = R1 * C1;
    let (current, t_p, rest) = (2.0 * CAPACITY, 30.0, 200.0);
    let protocol = Protocol { steps: vec![Step::Current { current, duration: t_p, until_voltage: None }, Step::Rest { duration: rest }] };
    let mut t_eval = grid(t_p + rest, 1.0);
    t_eval.push(t_p + tau);
    t_eval.sort_by(f64::total_cmp);
    t_eval.dedup();
    let sol = run(&model, &protocol, t_eval, false);
    let soc_end = SOC0 - current * t_p / (3600.0 * CAPACITY);
    let v1_end = current * R1 * (1.0 - (-t_p / tau).exp());
    let exact = |t: f64| {
        if t <= t_p {
            linear_ocv(SOC0 - current * t / (3600.0 * CAPACITY))
                - current * R0
                - current * R1 * (1.0 - (-t / tau).exp())
        } else {
            linear_ocv(soc_end) - v1_end * (-(t - t_p) / tau).exp()
        }
    };
    let at = |t: f64| sol.voltage[sol.time.iter().position(|&x| x == t).unwrap()];
    let err_tau = (at(t_p + tau) - exact(t_p + tau)).abs();
    // The rest starts at the end of the pulse: the recorded value at t_p is the pulse's.
    let worst = sol
        .time
        .iter()
        .zip(&sol.voltage)
        .filter(|(t, _)| **t != t_p)
        .map(|(&t, &v)| (v - exact(t)).abs())
        .fold(0.0, f64::max);
    // Decay rate from two points in the rest: (OCV - V) ∝ exp(-t / tau).
    let (ta, tb) = (t_p + 10.0, t_p + 60.0);
    let ocv = linear_ocv(soc_end);
    let tau_fit = (tb - ta) / ((ocv - at(ta)) / (ocv - at(tb))).ln();
    println!(
        "|V - V_exact| at t_p + tau = {err_tau:.3e} V, max over pulse and rest = {worst:.3e} V; \
         fitted tau = {tau_fit:.6} s (exact {tau} s)"
    );
    assert!(err_tau < 1e-4, "error one time constant into the rest: {err_tau:e} V");
    assert!(worst < 1e-4, "error over pulse and rest: {worst:e} V");
    assert!((tau_fit - tau).abs() / tau < 1e-3, "fitted tau {tau_fit} s vs {tau} s");
}

/// Two RC pairs, thermal balance: the temperature tends to T_amb + I^2 (R0 + R1 + R2) / hA,
/// and the charge-equivalent lithium falls by the discharged capacity.
#[test]
fn thermal_steady_state_and_charge_balance() {
    let mut p = one_rc();
    p.rc_pairs.push(RcPair { r: 0.01, c: 500.0 }); // tau = 5 s
    let (c_th, ha) = (50.0, 0.5); // J/K, W/K: thermal time constant 100 s
    p.thermal = Some(EcmThermal { heat_capacity: c_th, cooling: ha });
    let model = Ecm::new(p.clone()).unwrap();
    assert_eq!(model.len(), 4);
    let current = CAPACITY;
    let duration = 2000.0;
    let protocol = Protocol { steps: vec![Step::Current { current, duration, until_voltage: None }] };
    let sol = run(&model, &protocol, grid(duration, 10.0), true);
    let r_total = R0 + R1 + 0.01;
    let t_ss = p.ambient_temperature + current * current * r_total / ha;
    let t_end = *sol.temperature.last().unwrap();
    println!("T(end) = {t_end:.6} K, steady state {t_ss:.6} K");
    assert!((t_end - t_ss).abs() < 1e-3, "T {t_end} K vs steady state {t_ss} K");
    let y0 = &sol.states[0];
    let y1 = sol.states.last().unwrap();
    let dq = (model.solid_lithium(y0) - model.solid_lithium(y1)) * cellstudio::params::FARADAY / 3600.0;
    assert!((dq - sol.final_capacity()).abs() < 1e-9, "lithium {dq} A h vs capacity {}", sol.final_capacity());
    assert!((model.open_circuit_voltage(y1) - linear_ocv(model.soc(y1))).abs() < 1e-12);
}

/// The Chen 2020 default: its OCV table spans the physics models' initial OCV down to the
/// lower cut-off, and a 1C discharge ends at the cut-off near the table's capacity.
#[test]
fn chen2020_default_is_consistent_with_the_physics_models() {
    use cellstudio::geometry::MeshSizes;
    use cellstudio::models::ModelBuilder;
    use cellstudio::models::{ModelKind, Submodels};
    let p = cellstudio::params::chen2020();
    let ecm_p = EcmParameters::from_chen2020();
    ecm_p.validate().unwrap();
    let model = Ecm::new(ecm_p.clone()).unwrap();
    let mut b = ModelBuilder::new(ModelKind::Spm, Submodels::default(), MeshSizes::default());
    let built = b.build(&p).unwrap();
    let ocv_spm = built.model.open_circuit_voltage(&built.model.initial_state());
    let ocv_ecm = model.open_circuit_voltage(&model.initial_state());
    println!(
        "capacity {:.4} A h, OCV(1) = {ocv_ecm:.6} V (SPM {ocv_spm:.6} V), OCV(0) = {:.6} V",
        ecm_p.capacity,
        ecm_p.ocv.eval(0.0)
    );
    assert!((ocv_spm - ocv_ecm).abs() < 1e-9);
    assert!((ecm_p.ocv.eval(0.0) - p.cell.lower_cutoff).abs() < 1e-9);
    assert!((ecm_p.capacity - p.cell.nominal_capacity).abs() / p.cell.nominal_capacity < 0.1);
    let mut ws = Workspace::new(model.len(), model.jacobian_pattern()).unwrap();
    let opts = SimOptions { capacity: ecm_p.capacity, ..SimOptions::for_cell(&p) };
    let sol = simulate(&model, &mut ws, &Protocol::discharge(1.0), &opts, None).unwrap();
    println!("1C: {:.4} A h to {:.4} V", sol.final_capacity(), sol.final_voltage());
    assert_eq!(sol.cutoff_times.len(), 1);
    assert!((sol.final_voltage() - p.cell.lower_cutoff).abs() < 1e-6);
    assert!(sol.final_capacity() > 0.8 * ecm_p.capacity && sol.final_capacity() < ecm_p.capacity);
}

fn error_of(edit: impl Fn(&mut EcmParameters)) -> String {
    let mut p = one_rc();
    edit(&mut p);
    match Ecm::new(p) {
        Ok(_) => panic!("accepted bad ECM parameters"),
        Err(e) => e.to_string(),
    }
}

/// An edit that makes the parameters invalid, the field and the value the error must name.
type BadCase<'a> = (&'a dyn Fn(&mut EcmParameters), &'a str, &'a str);

#[test]
fn bad_input_names_the_field_and_value() {
    let cases: [BadCase; 8] = [
        (&|p| p.r0 = -0.01, "`r0`", "-0.01"),
        (&|p| p.initial_soc = 1.5, "`initial_soc`", "1.5"),
        (&|p| p.initial_soc = -0.1, "`initial_soc`", "-0.1"),
        (&|p| p.capacity = 0.0, "`capacity`", "= 0"),
        (&|p| p.rc_pairs[0].r = -0.02, "`rc_pairs[0].r`", "-0.02"),
        (&|p| p.rc_pairs[0].c = 0.0, "`rc_pairs[0].c`", "= 0"),
        (&|p| p.ambient_temperature = f64::NAN, "`ambient_temperature`", "NaN"),
        (&|p| p.thermal = Some(EcmThermal { heat_capacity: 10.0, cooling: -1.0 }), "`thermal.cooling`", "-1"),
    ];
    for (edit, field, value) in cases {
        let e = error_of(edit);
        println!("{e}");
        assert!(e.contains(field) && e.contains(value), "{e}");
    }
    let e = error_of(|p| p.ocv = Function1D::Table { x: vec![0.0, 0.5, 0.5], y: vec![3.0, 3.5, 4.0] });
    assert!(e.contains("`ocv`") && e.contains("strictly increasing"), "{e}");
    let e = error_of(|p| p.ocv = Function1D::Table { x: vec![0.0, 1.0], y: vec![3.0] });
    assert!(e.contains("`ocv`") && e.contains("equal lengths"), "{e}");
}

#[test]
fn parameters_round_trip_through_toml_and_reject_unknown_fields() {
    let mut p = one_rc();
    p.thermal = Some(EcmThermal { heat_capacity: 50.0, cooling: 0.5 });
    let text = toml::to_string(&p).unwrap();
    let back: EcmParameters = toml::from_str(&text).unwrap();
    assert_eq!(back, p);
    let bad = format!("{text}\nr00 = 0.01\n");
    let e = toml::from_str::<EcmParameters>(&bad).unwrap_err().to_string();
    assert!(e.contains("r00"), "{e}");
    let bad = text.replace("c = 800.0", "c = 800.0\ntau = 20.0");
    let e = toml::from_str::<EcmParameters>(&bad).unwrap_err().to_string();
    assert!(e.contains("tau"), "{e}");
}

/// The DFN (default mesh, Chen 2020) through a 1C pulse of 600 s from SOC 0.5 and 1800 s
/// of rest, outputs every second: the solution and its overpotential `OCV - V` (V).
fn dfn_pulse_at_half_soc() -> (Solution, Vec<f64>) {
    use cellstudio::geometry::MeshSizes;
    use cellstudio::models::ModelBuilder;
    use cellstudio::models::ecm::equilibrium_ocv_table;
    use cellstudio::models::{ModelKind, Submodels};
    let mut p = cellstudio::params::chen2020();
    let (capacity, _) = equilibrium_ocv_table(&p, 2);
    let area = p.cell.area();
    let q = 0.5 * capacity * 3600.0; // C discharged to SOC 0.5
    p.negative.initial_concentration -= p.negative.max_concentration * q / (p.negative.areal_capacity() * area);
    p.positive.initial_concentration += p.positive.max_concentration * q / (p.positive.areal_capacity() * area);
    let mut b = ModelBuilder::new(ModelKind::Dfn, Submodels::default(), MeshSizes::default());
    let built = b.build(&p).unwrap();
    let opts = SimOptions { t_eval: Some(grid(PULSE + REST, 1.0)), states: States::Kept, ..SimOptions::for_cell(&p) };
    let sol = simulate(built.model.as_ref(), &mut built.workspace, &pulse_protocol(), &opts, None).unwrap();
    let eta = sol.states.iter().zip(&sol.voltage).map(|(y, v)| built.model.open_circuit_voltage(y) - v).collect();
    (sol, eta)
}

const PULSE: f64 = 600.0;
const REST: f64 = 1800.0;

fn pulse_protocol() -> Protocol {
    let current = cellstudio::params::chen2020().cell.nominal_capacity;
    Protocol { steps: vec![Step::Current { current, duration: PULSE, until_voltage: None }, Step::Rest { duration: REST }] }
}

/// The Chen 2020 default ECM, started at SOC 0.5, follows the DFN through the pulse it was
/// fitted to.
#[test]
fn chen2020_default_follows_the_dfn_pulse() {
    let (dfn, _) = dfn_pulse_at_half_soc();
    let mut p = EcmParameters::from_chen2020();
    p.initial_soc = 0.5;
    let ecm = run(&Ecm::new(p).unwrap(), &pulse_protocol(), grid(PULSE + REST, 1.0), false);
    assert_eq!(ecm.time, dfn.time);
    let diff: Vec<f64> = ecm.voltage.iter().zip(&dfn.voltage).map(|(a, b)| a - b).collect();
    let rms = (diff.iter().map(|d| d * d).sum::<f64>() / diff.len() as f64).sqrt();
    let worst = diff.iter().fold(0.0f64, |m, d| m.max(d.abs()));
    println!("ECM vs DFN, 1C pulse at SOC 0.5: RMS {:.3} mV, max {:.3} mV", rms * 1e3, worst * 1e3);
    assert!(rms < 2e-3 && worst < 10e-3, "RMS {rms} V, max {worst} V");
}

/// The constants of `EcmParameters::from_chen2020` are the fit of `R0` and two RC pairs to
/// the DFN's overpotential `OCV - V` over a 1C pulse of 600 s from SOC 0.5 and 1800 s of
/// rest (linear least squares in the resistances, grid search over the time constants).
/// If the DFN changes, this fails and prints the new constants.
#[test]
fn chen2020_constants_are_the_dfn_fit() {
    let (sol, eta) = dfn_pulse_at_half_soc();
    let (current, t_p) = (sol.current[0], PULSE);
    // Unit-resistance response of an RC pair of time constant tau.
    let rc = |t: f64, tau: f64| {
        if t <= t_p {
            current * (1.0 - (-t / tau).exp())
        } else {
            current * (1.0 - (-t_p / tau).exp()) * (-(t - t_p) / tau).exp()
        }
    };
    let fit = |tau1: f64, tau2: f64| -> ([f64; 3], f64) {
        let cols = |i: usize| [sol.current[i], rc(sol.time[i], tau1), rc(sol.time[i], tau2)];
        let mut a = [[0.0; 4]; 3];
        for (i, &e) in eta.iter().enumerate() {
            let c = cols(i);
            for (row, &cr) in a.iter_mut().zip(&c) {
                for (v, &ck) in row.iter_mut().zip(&c) {
                    *v += cr * ck;
                }
                row[3] += cr * e;
            }
        }
        for k in 0..3 {
            for r in k + 1..3 {
                let (pivot, f) = (a[k], a[r][k] / a[k][k]);
                for (v, p) in a[r].iter_mut().zip(pivot).skip(k) {
                    *v -= f * p;
                }
            }
        }
        let mut x = [0.0; 3];
        for k in (0..3).rev() {
            x[k] = (a[k][3] - (k + 1..3).map(|m| a[k][m] * x[m]).sum::<f64>()) / a[k][k];
        }
        let sse: f64 = (0..sol.time.len())
            .map(|i| {
                let c = cols(i);
                (c[0] * x[0] + c[1] * x[1] + c[2] * x[2] - eta[i]).powi(2)
            })
            .sum();
        (x, (sse / sol.time.len() as f64).sqrt())
    };
    let log_grid = |lo: f64, hi: f64, n: usize| -> Vec<f64> {
        (0..n).map(|i| lo * (hi / lo).powf(i as f64 / (n - 1) as f64)).collect()
    };
    let mut best = (f64::INFINITY, 0.0, 0.0, [0.0; 3]);
    for &tau1 in &log_grid(1.0, 200.0, 80) {
        for &tau2 in &log_grid(200.0, 20000.0, 80) {
            let (x, rms) = fit(tau1, tau2);
            if rms < best.0 && x.iter().all(|&r| r > 0.0) {
                best = (rms, tau1, tau2, x);
            }
        }
    }
    let (rms, tau1, tau2, x) = best;
    println!(
        "DFN at SOC 0.5, 1C pulse: eta(0+) = {:.6} V, eta(t_p) = {:.6} V; {} steps",
        eta[0], eta[t_p as usize], sol.stats.steps
    );
    println!(
        "fit: R0 = {:.6e} ohm, (R1, tau1) = ({:.6e} ohm, {tau1:.4} s), (R2, tau2) = ({:.6e} ohm, {tau2:.4} s), RMS {:.3} mV",
        x[0],
        x[1],
        x[2],
        rms * 1e3
    );
    let p = EcmParameters::from_chen2020();
    let close = |a: f64, b: f64| (a - b).abs() <= 1e-3 * b.abs();
    assert!(close(p.r0, x[0]), "R0 {} vs fit {}", p.r0, x[0]);
    assert_eq!(p.rc_pairs.len(), 2);
    for (pair, (r, tau)) in p.rc_pairs.iter().zip([(x[1], tau1), (x[2], tau2)]) {
        assert!(
            close(pair.r, r) && close(pair.tau(), tau),
            "RC pair {pair:?} (tau {}) vs fit ({r}, {tau})",
            pair.tau()
        );
    }
    assert!(rms < 2e-3, "fit RMS {rms} V");
}
