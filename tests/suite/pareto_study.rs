//! `pareto` on the energy-vs-power study: designs whose discharge stops early are counted and
//! kept out of the front, linear constraints hold on every design, `[optimiser] method` is
//! honoured.

use cellstudio::study::Study;
use cellstudio::study::pareto::run_pareto;

fn text() -> String {
    std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/designs/energy_vs_power_chen2020.toml")).unwrap()
}

/// The study with its output in a fresh temporary folder, kept while the guard lives.
fn study(text: &str) -> (Study, tempfile::TempDir) {
    let mut s = Study::from_toml(text, "pareto.toml").unwrap();
    let tmp = tempfile::tempdir().unwrap();
    s.output.dir = tmp.path().join("out");
    (s, tmp)
}

#[test]
fn designs_that_stop_early_are_counted_and_kept_off_the_front() {
    // Before the flag, 19 of the 32 front points delivered 12-49 W h/kg (discharges cut off
    // after about a minute); the baseline delivers 230 W h/kg.
    let (s, _tmp) = study(&text().replace("generations = 20", "generations = 8"));
    let out = run_pareto(&s).unwrap();
    println!("{} evaluated, {} stopped early, {} failed, front {}", out.evaluated, out.stopped_early, out.failed, out.front.len());
    assert!(out.stopped_early > 0, "the study has transport-limited designs");
    let problem = s.problem().unwrap();
    for ind in &out.front {
        let m = problem.evaluate(&ind.x).unwrap();
        assert!(!m.stopped_early(0.5), "front point at {:?} delivers {:.1} %", ind.x, 100.0 * m.utilisation);
        assert!(ind.f[0] > 150.0, "front point at {:?}: {} W h/kg", ind.x, ind.f[0]);
    }
    let report = std::fs::read_to_string(s.output.dir.join("report.md")).unwrap();
    assert!(report.contains(&format!("{} stopped early", out.stopped_early)) && report.contains("Power is the mean power"));
}

#[test]
fn pareto_respects_linear_constraints_by_projection() {
    let t = text().replace("generations = 20", "generations = 4").replace(
        "[objective]",
        "[[constraints]]\nterms = { \"positive.active_fraction\" = 1.0 }\nupper = 0.6\n\n[objective]",
    );
    let (s, _tmp) = study(&t);
    let out = run_pareto(&s).unwrap();
    assert!(out.repaired > 0, "some NSGA-II candidates start above 0.6");
    for ind in &out.front {
        assert!(ind.x[1] <= 0.6 + 1e-9, "front point with active fraction {}", ind.x[1]);
    }
}

#[test]
fn pareto_refuses_a_single_objective_method() {
    let (s, _tmp) = study(&text().replace("method = \"nsga2\"", "method = \"cmaes\""));
    let e = run_pareto(&s).err().expect("cmaes is not multi-objective").to_string();
    assert!(e.contains("optimiser.method") && e.contains("cmaes") && e.contains("NSGA-II"), "{e}");
}
