//! Voltage curves against an independent simulator (PyBaMM 26.10, IDAKLU, rtol = atol =
//! 1e-8, Chen 2020, default mesh): DFN within 5 mV RMS, SPM and SPMe within 3 mV RMS, over
//! the whole discharge; the pulse protocol likewise.

mod common;

use cellstudio::geometry::MeshSizes;
use cellstudio::models::{ModelKind, Submodels};
use cellstudio::params::chen2020;
use cellstudio::protocol::Protocol;
use common::{pulse, reference, run, uniform_mesh};

fn check(kind: ModelKind, case: &str, protocol: Protocol, tol_mv: f64) {
    let p = chen2020();
    let name = format!("{}_{case}", kind.to_string().to_lowercase());
    let rec = reference(&name);
    let sol = run(kind, Submodels::default(), MeshSizes::default(), &p, &protocol, Some(rec.distinct_times()), false);
    let err = rec.voltage_error(&sol.time, &sol.voltage);
    let t_end_ref = rec.time[rec.time.len() - 1];
    let t_end = sol.time[sol.time.len() - 1];
    println!("{name}: rms {:.3} mV, max {:.3} mV over {} points", err.rms * 1e3, err.max * 1e3, err.points);
    // The whole discharge is compared: both curves end at (nearly) the same time.
    assert!((t_end - t_end_ref).abs() < 0.01 * t_end_ref, "{name}: ends at {t_end} s, reference {t_end_ref} s");
    assert!(err.points as f64 > 0.99 * rec.distinct_times().len() as f64, "{name}: compared only {} points", err.points);
    assert!(err.rms * 1e3 < tol_mv, "{name}: RMS {:.3} mV exceeds {tol_mv} mV", err.rms * 1e3);
}

#[test]
fn spm_matches_pybamm() {
    for (rate, case) in [(0.5, "0.5C"), (1.0, "1C"), (2.0, "2C")] {
        check(ModelKind::Spm, case, Protocol::discharge(rate), 3.0);
    }
    check(ModelKind::Spm, "pulse", pulse(), 3.0);
}

#[test]
fn spme_matches_pybamm() {
    for (rate, case) in [(0.5, "0.5C"), (1.0, "1C"), (2.0, "2C")] {
        check(ModelKind::Spme, case, Protocol::discharge(rate), 3.0);
    }
    check(ModelKind::Spme, "pulse", pulse(), 3.0);
}

#[test]
fn dfn_matches_pybamm() {
    for (rate, case) in [(0.5, "0.5C"), (1.0, "1C"), (2.0, "2C")] {
        check(ModelKind::Dfn, case, Protocol::discharge(rate), 5.0);
    }
    check(ModelKind::Dfn, "pulse", pulse(), 5.0);
}

/// Mesh refinement converges toward PyBaMM's fine-mesh (40 per domain, 60 per particle)
/// solution, not away from it.
#[test]
fn dfn_mesh_refinement_converges_to_fine_reference() {
    let p = chen2020();
    let rec = reference("dfn_1C_fine");
    let errors: Vec<f64> = [5usize, 10, 20, 40]
        .iter()
        .map(|&n| {
            let mesh = MeshSizes { r_n: (3 * n) / 2, r_p: (3 * n) / 2, ..uniform_mesh(n) };
            let sol = run(ModelKind::Dfn, Submodels::default(), mesh, &p, &Protocol::discharge(1.0), Some(rec.distinct_times()), false);
            let e = rec.voltage_error(&sol.time, &sol.voltage).rms;
            println!("mesh {n}: rms {:.3} mV", e * 1e3);
            e
        })
        .collect();
    for w in errors.windows(2) {
        assert!(w[1] < w[0], "error did not decrease with refinement: {errors:?}");
    }
    assert!(errors[3] < 1e-3, "finest mesh still {:.3} mV from the fine reference", errors[3] * 1e3);
}

/// SPM with a 10 mOhm contact resistance and D_n = 3.3e-14 m^2/s: 1C to 2.5 V then 30 min
/// rest (the fitting seed's synthetic case), against PyBaMM.
#[test]
fn spm_contact_resistance_matches_pybamm() {
    let mut p = chen2020();
    p.cell.contact_resistance = 0.01;
    p.negative.diffusivity = 3.3e-14;
    let protocol = Protocol {
        steps: vec![
            cellstudio::protocol::Step::CRate { rate: 1.0, duration: 7200.0 },
            cellstudio::protocol::Step::Rest { duration: 1800.0 },
        ],
    };
    let rec = reference("spm_contact_resistance_seed");
    let sub = Submodels { contact_resistance: true, ..Default::default() };
    let sol = run(ModelKind::Spm, sub, MeshSizes::default(), &p, &protocol, Some(rec.distinct_times()), false);
    let err = rec.voltage_error(&sol.time, &sol.voltage);
    println!("spm_contact_resistance_seed: rms {:.3} mV, max {:.3} mV over {} points", err.rms * 1e3, err.max * 1e3, err.points);
    assert!(err.points as f64 > 0.98 * rec.time.len() as f64, "compared only {} points", err.points);
    assert!(err.rms < 3e-3, "RMS {:.3} mV", err.rms * 1e3);
}
