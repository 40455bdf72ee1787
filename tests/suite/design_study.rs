//! The seed design study end to end: the optimiser improves the gravimetric energy density
//! of the Chen 2020 baseline while the volume fractions still sum to one.

use cellstudio::study::Study;
use cellstudio::study::design::run_design;

#[test]
fn seed_study_improves_gravimetric_energy_density() {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/designs/gravimetric_chen2020.toml");
    let mut study = Study::from_file(path.as_ref()).unwrap();
    let tmp = tempfile::tempdir().unwrap();
    study.output.dir = tmp.path().join("out");
    let out = run_design(&study).unwrap();
    println!(
        "{:.2} -> {:.2} W h/kg ({:+.2} %), {} evaluations, {} builds, {:.2} s",
        out.initial.gravimetric_energy_density,
        out.optimised.gravimetric_energy_density,
        out.improvement(),
        out.result.evaluations,
        out.rebuilds,
        out.seconds
    );
    assert!(out.improvement() > 1.0, "no improvement: {:+.3} %", out.improvement());
    // The study's 13 x 13 sweep is the check: its best grid point (269.29) does not beat the
    // search's optimum (269.47).
    let (_, grid_best) = out.sweep_best.clone().expect("the seed study has a [sweep] table");
    assert!(out.optimised.gravimetric_energy_density >= grid_best, "{} < {grid_best}", out.optimised.gravimetric_energy_density);
    let p = study.problem().unwrap().parameters(&out.result.x).unwrap();
    let e = &p.positive;
    assert!((e.active_fraction + e.porosity + e.inactive_fraction() - 1.0).abs() < 1e-12);
    assert!(e.inactive_fraction().abs() < 1e-12, "binder fraction should stay at the baseline's 0");
    for (v, x) in study.variables.iter().zip(&out.result.x) {
        assert!(*x >= v.lower && *x <= v.upper, "{} = {x} outside bounds", v.path);
    }
    assert!(out.files.iter().all(|f| f.exists()));
}

#[test]
fn more_starts_keep_the_best_end_and_report_every_one() {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/designs/gravimetric_chen2020.toml");
    let mut study = Study::from_file(path.as_ref()).unwrap();
    let tmp = tempfile::tempdir().unwrap();
    study.output.dir = tmp.path().join("out");
    study.optimiser.insert("starts".into(), toml::Value::Integer(3));
    let out = run_design(&study).unwrap();
    assert_eq!(out.start_values.len(), 3);
    let best = out.start_values.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    assert_eq!(out.optimised.gravimetric_energy_density, best, "{:?}", out.start_values);
    assert!(std::fs::read_to_string(out.files.iter().find(|f| f.ends_with("report.md")).unwrap()).unwrap().contains("Multi-start: 3 starts"));
    std::fs::remove_dir_all(&study.output.dir).unwrap();
    study.optimiser.insert("starts".into(), toml::Value::Integer(0));
    let e = run_design(&study).err().unwrap().to_string();
    assert!(e.contains("optimiser.starts"), "{e}");
}
