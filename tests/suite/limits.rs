//! Limits on simulated metrics (nonlinear constraints): a design search that starts outside a
//! plating-free charge limit is led inside it and names the limit active; a sweep marks the
//! points outside; a limit without bounds is an error naming it.

use cellstudio::problem::sweep::Status;
use cellstudio::study::Study;
use cellstudio::study::design::run_design;
use cellstudio::study::sweep::run_sweep;

fn study(limit: &str, out: &std::path::Path) -> Result<Study, cellstudio::error::Error> {
    Study::from_toml(
        &format!(
            r#"
name = "energy with a charge limit"
[model]
kind = "spme"
[operating]
c_rate = 1.0
[[variables]]
path = "negative.thickness"
lower = 50e-6
upper = 100e-6
[[variables]]
path = "positive.thickness"
lower = 45e-6
upper = 90e-6
{limit}
[objective]
maximise = ["gravimetric_energy_density"]
[optimiser]
method = "nelder_mead"
max_iterations = 60
seed = 1
[sweep]
points = [5, 5]
[output]
dir = "{}"
"#,
            out.display()
        ),
        "test",
    )
}

const LIMIT: &str = "[[limits]]\nmetric = \"fast_charge_rate\"\nlower = 0.65";

#[test]
fn design_and_sweep_keep_a_plating_free_charge_limit() {
    let tmp = tempfile::tempdir().unwrap();
    let dir = tmp.path();
    let s = study(LIMIT, &dir.join("design")).unwrap();
    let out = run_design(&s).unwrap();
    let rate = out.optimised.fast_charge.unwrap().rate;
    // The baseline (0.574C) lies outside; the optimum inside, on the limit.
    assert!(out.initial.fast_charge.unwrap().rate < 0.65 && rate >= 0.65, "{rate}");
    assert_eq!(out.active_limits.len(), 1, "{:?}", out.active_limits);
    assert!(out.warnings.iter().any(|w| w.contains("baseline lies outside the limits")));
    let s = study(LIMIT, &dir.join("sweep")).unwrap();
    let sweep = run_sweep(&s).unwrap();
    let outside = sweep.count(Status::OutsideLimits);
    assert!(outside > 0 && outside < sweep.points.len(), "{outside}");
    for p in &sweep.points {
        let r = p.metrics.unwrap().fast_charge.unwrap().rate;
        assert_eq!(p.status == Status::OutsideLimits, r < 0.65, "{:?}: {r}", p.x);
    }
    let (best, _) = sweep.best(cellstudio::problem::design::Metric::GravimetricEnergyDensity).unwrap();
    assert!(best.metrics.unwrap().fast_charge.unwrap().rate >= 0.65);
    // The search's optimum is at least the sweep's best inside the limit (to a grid step).
    assert!(out.optimised.gravimetric_energy_density >= best.metrics.unwrap().gravimetric_energy_density - 1e-9);
}

#[test]
fn a_limit_without_bounds_is_named() {
    let e = study("[[limits]]\nmetric = \"capacity\"", std::path::Path::new("/tmp/unused")).unwrap_err().to_string();
    assert!(e.contains("limits[0]") && e.contains("lower"), "{e}");
    let e = study("[[limits]]\nmetric = \"speed\"\nlower = 1.0", std::path::Path::new("/tmp/unused")).unwrap_err().to_string();
    assert!(e.contains("speed"), "{e}");
}
