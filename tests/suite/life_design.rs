//! Cycle life in design studies (issue 15 item 6): the capacity-retention metric against
//! PyBaMM's SEI cycling, its no-ageing limit, a retention limit that changes the optimum,
//! and the errors a study without cycles or without an ageing submodel gets.

use cellstudio::geometry::MeshSizes;
use cellstudio::models::submodels::SeiModel;
use cellstudio::models::{ModelBuilder, ModelKind, Submodels};
use cellstudio::params::chen2020;
use cellstudio::problem::life::LifeSpec;
use cellstudio::study::Study;
use cellstudio::study::design::run_design;

/// PyBaMM's experiment of `tests/data/sei/*_cycles.csv` (scripts/make_sei_reference.py).
const CYCLE: [&str; 5] = ["Discharge at 1C until 3.0 V", "Rest for 10 minutes", "Charge at 1C until 4.1 V", "Hold at 4.1 V until C/20", "Rest for 10 minutes"];

fn spec(cycles: usize) -> LifeSpec {
    LifeSpec { cycles, cycle: CYCLE.iter().map(|s| s.to_string()).collect(), initial_soc: None }
}

fn retention(sei: SeiModel, cycles: usize) -> f64 {
    let p = chen2020();
    let mut builder = ModelBuilder::new(ModelKind::Spm, Submodels { sei, ..Default::default() }, MeshSizes::default());
    spec(cycles).retention(&mut builder, &p, p.cell.nominal_capacity).unwrap()
}

/// Cycle 10's discharge capacity over cycle 1's, from PyBaMM's reference.
fn pybamm_retention(name: &str) -> f64 {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join(format!("tests/data/sei/spm_{name}_cycles.csv"));
    let text = std::fs::read_to_string(&path).unwrap();
    let q: Vec<f64> = text.lines().skip(1).map(|l| l.split(',').nth(1).unwrap().parse().unwrap()).collect();
    q[9] / q[0]
}

#[test]
fn retention_matches_pybamm_and_is_one_without_ageing() {
    for (sei, name) in [(SeiModel::ReactionLimited, "reaction_limited"), (SeiModel::SolventDiffusionLimited, "solvent_diffusion_limited")] {
        let (ours, theirs) = (retention(sei, 10), pybamm_retention(name));
        println!("{name}: retention after 10 cycles {ours:.8}, PyBaMM {theirs:.8} ({:.1e})", ours - theirs);
        assert!((ours - theirs).abs() < 5e-7, "{name}: {ours} vs PyBaMM {theirs}");
    }
    // Without ageing, cycles 2-10 repeat cycle 2 (the first starts from the set's state, not
    // the CC-CV charge): retention over cycle 2 is 1 to the solver's tolerance.
    let (ten, two) = (retention(SeiModel::None, 10), retention(SeiModel::None, 2));
    println!("no ageing: cycle 10 / cycle 2 = {:.3e} - 1", ten / two - 1.0);
    assert!((ten / two - 1.0).abs() < 5e-11, "{ten} vs {two}");
}

/// The study with its output in a fresh temporary folder, kept while the guard lives.
fn life_study(limit: Option<f64>) -> (Study, tempfile::TempDir) {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/designs/life_limited_chen2020.toml");
    let text = std::fs::read_to_string(path).unwrap().replace("cycles = 500", "cycles = 60");
    let text = match limit {
        Some(r) => text.replace("lower = 0.91", &format!("lower = {r}")),
        None => text.replace("[[limits]]\nmetric = \"capacity_retention\"\nlower = 0.91\n", ""),
    };
    let mut study = Study::from_toml(&text, "life.toml").unwrap();
    let tmp = tempfile::tempdir().unwrap();
    study.output.dir = tmp.path().join("out");
    (study, tmp)
}

#[test]
fn a_retention_limit_moves_the_optimum_inside_it() {
    let (free_study, _free_tmp) = life_study(None);
    let free = run_design(&free_study).unwrap();
    let r = |m: &cellstudio::problem::design::DesignMetrics| m.capacity_retention.unwrap();
    let (r0, r_free) = (r(&free.initial), r(&free.optimised));
    println!("unconstrained: {:.2} W h/kg, retention {r_free:.5} (baseline {r0:.5})", free.optimised.gravimetric_energy_density);
    // The densest design has the smallest particles, whose surface grows the most SEI.
    assert!(r_free < r0, "the unconstrained optimum should fade faster than the baseline: {r_free} vs {r0}");
    let limit = 0.5 * (r0 + r_free);
    let (bound_study, _bound_tmp) = life_study(Some(limit));
    let bound = run_design(&bound_study).unwrap();
    let r_bound = r(&bound.optimised);
    println!("limit {limit:.5}: {:.2} W h/kg, retention {r_bound:.5}, active {:?}", bound.optimised.gravimetric_energy_density, bound.active_limits);
    assert!(r_bound >= limit, "{r_bound} < {limit}");
    assert!(bound.optimised.gravimetric_energy_density < free.optimised.gravimetric_energy_density);
    assert!(bound.optimised.gravimetric_energy_density > bound.initial.gravimetric_energy_density);
    assert!(!bound.active_limits.is_empty(), "the limit should be active at the optimum");
    let report = std::fs::read_to_string(bound.files.iter().find(|f| f.ends_with("report.md")).unwrap()).unwrap();
    assert!(report.contains("Capacity retention is the discharge capacity of the last of 60 cycles"), "{report}");
}

#[test]
fn a_life_metric_needs_its_cycles_and_an_ageing_submodel() {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/designs/energy_vs_life_chen2020.toml");
    let text = std::fs::read_to_string(path).unwrap();
    let err = |t: &str| Study::from_toml(t, "bad.toml").err().expect("should be refused").to_string();
    let e = err(&text.replace("submodels = { sei = \"reaction limited\" }", ""));
    assert!(e.contains("model.submodels") && e.contains("ageing"), "{e}");
    let start = text.find("life = {").unwrap();
    let end = start + text[start..].find("] }").unwrap() + 3;
    let e = err(&format!("{}{}", &text[..start], &text[end..]));
    assert!(e.contains("operating.life"), "{e}");
    let e = err(&text.replace("cycles = 500", "cycles = 1"));
    assert!(e.contains("operating.life.cycles") && e.contains('1'), "{e}");
    let e = err(&text.replace("\"Rest for 10 minutes\",\n] }", "\"Rest for ten minutes\",\n] }"));
    assert!(e.contains("operating.life.cycle"), "{e}");
    let e = err(&text.replace("initial_soc = 0.0", "initial_soc = 1.5"));
    assert!(e.contains("operating.life.initial_soc") && e.contains("1.5"), "{e}");
}
