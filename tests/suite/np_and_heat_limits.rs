//! Limits on the N/P ratio and on the temperature rise (issue 13): a design search that would
//! thin the negative electrode keeps the N/P ratio at its limit; a thermal design study keeps
//! the temperature rise of a 2C discharge under its limit; a temperature-rise metric without
//! the thermal submodel is an error naming it.

use cellstudio::params::chen2020;
use cellstudio::params::soc::StoichiometryWindow;
use cellstudio::study::Study;
use cellstudio::study::design::run_design;

fn study(model: &str, operating: &str, limit: &str, out: &std::path::Path) -> Result<Study, cellstudio::error::Error> {
    let text = format!(
        "name = \"limits\"\n[model]\n{model}\n[operating]\n{operating}\n[[variables]]\npath = \"negative.thickness\"\nlower = 50e-6\nupper = 100e-6\n[[variables]]\npath = \"positive.thickness\"\nlower = 45e-6\nupper = 90e-6\n{limit}\n[objective]\nmaximise = [\"gravimetric_energy_density\"]\n[optimiser]\nmethod = \"nelder_mead\"\nmax_iterations = 80\nseed = 1\n[output]\ndir = \"{}\"\n",
        out.display()
    );
    Study::from_toml(&text, "test")
}

#[test]
fn np_ratio_is_one_over_the_negative_window_and_its_limit_holds() {
    let dir = tempfile::tempdir().unwrap();
    let s = study("kind = \"spm\"", "c_rate = 1.0", "[[limits]]\nmetric = \"np_ratio\"\nlower = 1.2", &dir.path().join("out")).unwrap();
    let out = run_design(&s).unwrap();
    // Chen 2020: the negative electrode cycles between x0 and x100 of its capacity.
    let w = StoichiometryWindow::within_reach(&chen2020());
    assert!((out.initial.np_ratio - 1.0 / (w.x100 - w.x0)).abs() < 1e-9, "{} vs {}", out.initial.np_ratio, 1.0 / (w.x100 - w.x0));
    println!("N/P: baseline {:.4}, optimum {:.4} at {:?}", out.initial.np_ratio, out.optimised.np_ratio, out.result.x);
    assert!(out.initial.np_ratio < 1.2, "the baseline lies outside: {}", out.initial.np_ratio);
    assert!(out.optimised.np_ratio >= 1.2 && out.optimised.np_ratio < 1.25, "{}", out.optimised.np_ratio);
    assert!(!out.active_limits.is_empty(), "{:?}", out.active_limits);
}

#[test]
fn temperature_rise_limit_needs_the_thermal_submodel_and_holds() {
    let tmp = tempfile::tempdir().unwrap();
    let dir = tmp.path().join("out");
    // 2C of each design's own capacity: thinner electrodes carry less current and heat less.
    let operating = "c_rate = 2.0\nrate_from_theoretical_capacity = true";
    let limit = "[[limits]]\nmetric = \"temperature_rise\"\nupper = 15.0";
    let e = study("kind = \"spm\"", operating, limit, &dir).unwrap_err().to_string();
    assert!(e.contains("model.submodels") && e.contains("thermal"), "{e}");
    let s = study("kind = \"spm\"\nsubmodels = { thermal = true }", operating, limit, &dir).unwrap();
    let out = run_design(&s).unwrap();
    println!("rise: baseline {:.2} K, optimum {:.2} K, {:.1} -> {:.1} W h/kg", out.initial.temperature_rise, out.optimised.temperature_rise, out.initial.gravimetric_energy_density, out.optimised.gravimetric_energy_density);
    assert!(out.initial.temperature_rise > 15.0, "the baseline heats by {} K", out.initial.temperature_rise);
    assert!(out.optimised.temperature_rise <= 15.0 && out.optimised.temperature_rise > 14.0, "{}", out.optimised.temperature_rise);
    assert!(!out.active_limits.is_empty(), "{:?}", out.active_limits);
}
