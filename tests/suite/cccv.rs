//! CC-CV against PyBaMM 26.10 (`scripts/make_cccv_reference.py`, curves in
//! `tests/data/cccv/`): "Discharge at 1C until 3.0 V", "Rest for 10 minutes", "Charge at 1C
//! until 4.1 V", "Hold at 4.1 V until C/20", "Rest for 10 minutes", Chen 2020, the same mesh
//! (20 volumes per domain and per particle), PyBaMM's IDAKLU at rtol = atol = 1e-8 and ours
//! at 1e-8. The experiment is given as PyBaMM's strings, so the parser is on the path too.
//! Compared: the voltage outside the hold, the current during the hold, and when each step
//! ends (the cut-off events and the hold's current limit).

use cellstudio::geometry::MeshSizes;
use cellstudio::models::ModelBuilder;
use cellstudio::models::{ModelKind, Submodels};
use cellstudio::params::chen2020;
use cellstudio::protocol::experiment;
use cellstudio::simulation::{SimOptions, simulate};

const EXPERIMENT: [&str; 5] = ["Discharge at 1C until 3.0 V", "Rest for 10 minutes", "Charge at 1C until 4.1 V", "Hold at 4.1 V until C/20", "Rest for 10 minutes"];

struct Reference {
    time: Vec<f64>,
    current: Vec<f64>,
    voltage: Vec<f64>,
    step: Vec<usize>,
}

fn reference(name: &str) -> Reference {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/cccv").join(format!("{name}.csv"));
    let text = std::fs::read_to_string(&path).unwrap();
    let mut r = Reference { time: vec![], current: vec![], voltage: vec![], step: vec![] };
    for line in text.lines().skip(1) {
        let v: Vec<f64> = line.split(',').map(|x| x.parse().unwrap()).collect();
        r.time.push(v[0]);
        r.current.push(v[1]);
        r.voltage.push(v[2]);
        r.step.push(v[3] as usize);
    }
    r
}

/// The value of `y` recorded at time `x` (an output time of both sides).
fn at(t: &[f64], y: &[f64], x: f64) -> f64 {
    y[t.iter().position(|v| *v == x).expect("an output time")]
}

/// (voltage RMS outside the hold (mV), current RMS in the hold (mA), largest step-end
/// difference (s)).
fn compare(kind: ModelKind) -> (f64, f64, f64) {
    let p = chen2020();
    let name = kind.to_string().to_lowercase();
    let rec = reference(&name);
    let protocol = experiment::parse(&EXPERIMENT, p.cell.nominal_capacity).unwrap();
    let mut b = ModelBuilder::new(kind, Submodels::default(), MeshSizes::default());
    let built = b.build(&p).unwrap();
    // Outputs at the reference's times (a repeated time, a step boundary, once).
    let mut times = rec.time.clone();
    times.dedup();
    let mut opts = SimOptions { t_eval: Some(times), ..SimOptions::for_cell(&p) };
    opts.solver.set_tolerance(1e-8);
    let sol = simulate(built.model.as_ref(), &mut built.workspace, &protocol, &opts, None).unwrap();
    // Step ends: ours are the recorded step boundaries (cut-off events and the hold's
    // limit, then the durations of the rests).
    let ref_ends: Vec<f64> = (0..EXPERIMENT.len()).map(|s| rec.time[rec.step.iter().rposition(|k| *k == s).unwrap()]).collect();
    let mut ours_ends = Vec::new();
    let mut t0 = 0.0;
    let mut cutoff = sol.cutoff_times.iter();
    for step in &protocol.steps {
        t0 = match step {
            cellstudio::protocol::Step::Rest { duration } => t0 + duration,
            _ => *cutoff.next().expect("every CC and CV step ends on its event"),
        };
        ours_ends.push(t0);
    }
    let end_gap = ref_ends.iter().zip(&ours_ends).map(|(a, b)| (a - b).abs()).fold(0.0, f64::max);
    // Points at least 20 s from any step boundary, either side's.
    let boundary = |t: f64| ref_ends.iter().chain(&ours_ends).any(|e| (t - e).abs() < 20.0);
    let (mut sv, mut nv, mut si, mut ni) = (0.0, 0, 0.0, 0);
    for k in 0..rec.time.len() {
        let t = rec.time[k];
        if boundary(t) || t > sol.time[sol.time.len() - 1] {
            continue;
        }
        if rec.step[k] == 3 {
            si += (at(&sol.time, &sol.current, t) - rec.current[k]).powi(2);
            ni += 1;
        } else {
            sv += (at(&sol.time, &sol.voltage, t) - rec.voltage[k]).powi(2);
            nv += 1;
        }
    }
    assert!(nv > 500 && ni > 200, "{name}: compared {nv} voltages and {ni} currents");
    let (v_rms, i_rms) = ((sv / nv as f64).sqrt() * 1e3, (si / ni as f64).sqrt() * 1e3);
    println!("{name}: voltage RMS {v_rms:.2e} mV (CC and rests), hold current RMS {i_rms:.2e} mA, step ends within {end_gap:.3} s; ours {ours_ends:?}, PyBaMM {ref_ends:?}");
    (v_rms, i_rms, end_gap)
}

/// About five times the achieved (2.1e-5 / 1.8e-5 / 1.1e-5 mV, 2.2e-4 / 3.1e-4 / 2.7e-4 mA,
/// 0.0003 / 0.001 / 0.002 s for the SPM / SPMe / DFN).
fn check(kind: ModelKind) {
    let (v, i, end) = compare(kind);
    assert!(v < 1e-4 && i < 1.5e-3 && end < 0.01, "{kind:?}: {v:.2e} mV, {i:.2e} mA, {end:.4} s");
}

#[test]
fn cccv_matches_pybamm_spm() {
    check(ModelKind::Spm);
}

#[test]
fn cccv_matches_pybamm_spme() {
    check(ModelKind::Spme);
}

#[test]
fn cccv_matches_pybamm_dfn() {
    check(ModelKind::Dfn);
}
