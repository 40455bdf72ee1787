//! `sweep` honours linear constraints: infeasible grid points are skipped and counted, the
//! best design is chosen among feasible ones, and `design` agrees with it.

use cellstudio::problem::design::Metric;
use cellstudio::problem::sweep::Status;
use cellstudio::study::Study;
use cellstudio::study::sweep::run_sweep;

#[test]
fn sweep_skips_points_outside_the_constraints() {
    let text = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/designs/gravimetric_chen2020.toml")).unwrap().replace(
        "[objective]",
        "[[constraints]]\nterms = { \"positive.active_fraction\" = 1.0 }\nupper = 0.6\n\n[objective]",
    );
    let mut study = Study::from_toml(&text, "constrained.toml").unwrap();
    let tmp = tempfile::tempdir().unwrap();
    study.output.dir = tmp.path().join("out");
    let out = run_sweep(&study).unwrap();
    // 13 x 13 grid, active fraction 0.500, 0.525, ..., 0.800: 5 of 13 columns are feasible.
    assert_eq!(out.count(Status::Infeasible), 8 * 13);
    assert!(out.points.iter().filter(|p| p.status == Status::Infeasible).all(|p| p.metrics.is_none() && p.x[1] > 0.6));
    let (best, _) = out.best(Metric::GravimetricEnergyDensity).unwrap();
    assert!(best.x[1] <= 0.6 + 1e-12, "best at active fraction {}", best.x[1]);
    assert!(out.warnings.iter().any(|w| w.contains("104 of 169 designs violate")));
    let csv = std::fs::read_to_string(study.output.dir.join("sweep.csv")).unwrap();
    assert_eq!(csv.lines().filter(|l| l.contains(",infeasible,")).count(), 104);
    // The heat maps draw the boundary active fraction = 60 % (shown in %) across the whole
    // thickness axis: one horizontal black segment.
    let svg = std::fs::read_to_string(study.output.dir.join("sweep_gravimetric_energy_density.svg")).unwrap();
    assert!(svg.contains("constraint boundary"), "no boundary in the legend");
    let segment = svg
        .split("<polyline")
        .filter(|l| l.contains("stroke=\"#000000\" stroke-width=\"2\""))
        .find_map(|l| l.split("points=\"").nth(1)?.split('"').next().map(str::to_string))
        .expect("a boundary segment");
    let ends: Vec<(f64, f64)> = segment.split_whitespace().map(|p| p.split_once(',').map(|(x, y)| (x.parse().unwrap(), y.parse().unwrap())).unwrap()).collect();
    assert!(ends.len() == 2 && (ends[0].1 - ends[1].1).abs() <= 1.0 && ends[1].0 - ends[0].0 > 500.0, "{ends:?}");
}
