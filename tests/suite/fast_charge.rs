//! The lithium-plating margin and the plating-free charge rate against PyBaMM 26.10
//! (`scripts/make_plating_reference.py`, `tests/data/plating/`), Chen 2020 on the same mesh:
//! the margin (`phi_s - phi_e` in the negative electrode: x-averaged in the SPM and SPMe, the
//! least over x in the DFN) through a 2C charge from 10 % SOC, and the largest constant
//! charge rate from 10 % to 80 % that keeps it at or above 0 V.

use cellstudio::geometry::MeshSizes;
use cellstudio::models::ModelBuilder;
use cellstudio::models::{ModelKind, Submodels};
use cellstudio::params::{StoichiometryWindow, chen2020};
use cellstudio::problem::fast_charge::FastChargeSpec;
use cellstudio::protocol::{Protocol, Step};
use cellstudio::simulation::{SimOptions, States, simulate_observed};

fn data(file: &str) -> String {
    std::fs::read_to_string(std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/plating").join(file)).unwrap()
}

/// RMS and largest |margin - PyBaMM's| (mV) over a 1C charge from 10 % SOC.
fn margin_gap(kind: ModelKind) -> (f64, f64) {
    let name = kind.to_string().to_lowercase();
    let rows: Vec<(f64, f64)> = data(&format!("{name}_1C_margin.csv"))
        .lines()
        .skip(1)
        .map(|l| {
            let v: Vec<f64> = l.split(',').map(|x| x.parse().unwrap()).collect();
            (v[0], v[1])
        })
        .collect();
    let mut p = chen2020();
    let window = StoichiometryWindow::within_reach(&p);
    window.place(&mut p, 0.1);
    let current = window.capacity(&p);
    let protocol = Protocol { steps: vec![Step::Current { current: -current, duration: 0.7 * 3600.0, until_voltage: None }] };
    let mut b = ModelBuilder::new(kind, Submodels::default(), MeshSizes::default());
    let built = b.build(&p).unwrap();
    let mut opts = SimOptions { t_eval: Some(rows.iter().map(|r| r.0).collect()), states: States::Kept, ..SimOptions::for_cell(&p) };
    opts.solver.set_tolerance(1e-8);
    // PyBaMM's timed experiment step would run past the 4.2 V cut-off: so does this comparison.
    opts.cutoffs.1 = 6.0;
    let mut margins = Vec::new();
    let sol = simulate_observed(built.model.as_ref(), &mut built.workspace, &protocol, &opts, None, &mut |y, i| margins.push(built.model.plating_margin(y, i).unwrap())).unwrap();
    assert_eq!(sol.time.len(), margins.len());
    println!("{name}: ends at {} s, {} V, cut-offs {:?}", sol.time[sol.time.len() - 1], sol.voltage[sol.voltage.len() - 1], sol.cutoff_times);
    let gaps: Vec<f64> = sol.time.iter().zip(&margins).map(|(t, m)| (m - rows.iter().find(|r| r.0 == *t).expect("a reference time").1).abs() * 1e3).collect();
    assert!(gaps.len() > 100, "{name}: {} points", gaps.len());
    let rms = (gaps.iter().map(|g| g * g).sum::<f64>() / gaps.len() as f64).sqrt();
    let max = gaps.iter().copied().fold(0.0, f64::max);
    println!("{name}: margin {rms:.2e} mV RMS, {max:.2e} mV max over {} points, from {:.4} to {:.4} V", gaps.len(), margins[0], margins[margins.len() - 1]);
    (rms, max)
}

#[test]
fn plating_margin_matches_pybamm() {
    // Achieved (RMS, max, mV): SPM 1.9e-5, 2.1e-4; SPMe 3.8e-3, 3.8e-3 (a constant 3.8 uV: the
    // SPMe's j0 regularisation, see `Spme::surface_potential_difference`); DFN 9.2e-6, 4.0e-5.
    for (kind, rms_limit, max_limit) in [(ModelKind::Spm, 1e-4, 1e-3), (ModelKind::Spme, 2e-2, 2e-2), (ModelKind::Dfn, 5e-5, 2e-4)] {
        let (rms, max) = margin_gap(kind);
        assert!(rms < rms_limit && max < max_limit, "{kind:?}: {rms:.2e} / {max:.2e} mV");
    }
}

#[test]
fn plating_free_rate_matches_pybamm() {
    let reference: serde_json::Value = serde_json::from_str(&data("plating_free_rate.json")).unwrap();
    let p = chen2020();
    let q = StoichiometryWindow::within_reach(&p).capacity(&p);
    let q_ref = reference["window_capacity_Ah"].as_f64().unwrap();
    assert!((q - q_ref).abs() < 1e-6 * q_ref, "window capacity {q} vs PyBaMM {q_ref} A h");
    // With a 0 V margin the 4.2 V cut-off binds for this cell; with 20 mV the margin does.
    for (kind, margin, suffix) in [(ModelKind::Spme, 0.0, ""), (ModelKind::Dfn, 0.0, ""), (ModelKind::Spme, 0.02, "_20mV"), (ModelKind::Dfn, 0.02, "_20mV")] {
        let name = format!("{}{suffix}", kind.to_string().to_lowercase());
        let mut b = ModelBuilder::new(kind, Submodels::default(), MeshSizes::default());
        let found = FastChargeSpec { margin, ..FastChargeSpec::default() }.search(&mut b, &p).unwrap();
        let rate = reference["rate"][&name].as_f64().unwrap();
        let gap = (found.rate - rate).abs() / rate;
        println!("{name}: plating-free {:.4} C ({:.2} A, 10-80 % in {:.0} s) against PyBaMM's {rate:.4} C: {gap:.1e}", found.rate, found.current, found.seconds);
        // achieved 5e-6 to 5e-5; the bisections stop at 1e-4 (ours) and 1e-5 (PyBaMM) of the rate.
        assert!(gap < 2e-4, "{name}: {} vs {rate}", found.rate);
    }
}
