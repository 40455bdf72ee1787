//! A result says how its search went, on the terminal and in what it writes (found by a trust
//! audit as a new user): the designs a design search could not rank (failed or stopped
//! early), and an impedance fit's values with its stop reason and a cut-short search, with a
//! remedy the user can act on.

use std::path::Path;

use crate::cli_support;

use cli_support::*;

#[test]
fn a_design_search_counts_the_designs_it_could_not_rank() {
    let s = Scratch::new("ranked");
    // At 2C, positive electrodes up to 200 um: the thickest stop early (transport-limited).
    // Before, the search ranked them last without a word.
    let seed = std::fs::read_to_string(Path::new(REPO).join("designs/gravimetric_chen2020.toml")).unwrap();
    let text = seed
        .replace("c_rate = 1.0", "c_rate = 2.0")
        .replace("upper = 110e-6", "upper = 200e-6")
        .replace("max_iterations = 60", "max_iterations = 5")
        .replace("[sweep]\npoints = [13, 13]\n", "")
        .replace("out/gravimetric_chen2020", "out");
    let study = s.write("design.toml", &text);
    let o = run(&s.0, &["design", study.to_str().unwrap()]);
    succeeds(&o);
    let needle = "designs the search evaluated stopped early and were ranked below every valid design";
    assert!(stderr(&o).contains(needle), "{}", stderr(&o));
    let json: serde_json::Value = serde_json::from_str(&std::fs::read_to_string(s.path("out/design.json")).unwrap()).unwrap();
    assert!(json["warnings"].as_array().unwrap().iter().any(|w| w.as_str().unwrap().contains(needle)), "{json}");
    assert!(std::fs::read_to_string(s.path("out/report.md")).unwrap().contains(needle));
}

#[test]
fn an_impedance_fit_writes_its_values_and_how_its_search_ended() {
    let s = Scratch::new("eis-fit");
    succeeds(&run(&s.0, &["eis", "--model", "spm", "--contact-resistance", "0.01", "--frequencies", "1e-2", "1e3", "12", "--out", "measured"]));
    let fit = |optimiser: &str, parameters: &str, out: &str| {
        run(&s.0, &["eis", "--model", "spm", "--contact-resistance", "0.005", "--fit", "measured/spectrum.csv", "--parameters", parameters, "--optimiser", optimiser, "--out", out])
    };
    // A converged fit: before, its values were only printed.
    succeeds(&fit("nelder-mead", "cell.contact_resistance", "converged"));
    let json: serde_json::Value = serde_json::from_str(&std::fs::read_to_string(s.path("converged/fit.json")).unwrap()).unwrap();
    let r = json["parameters"]["cell.contact_resistance"].as_f64().unwrap();
    assert!((r - 0.01).abs() < 1e-6, "{json}");
    assert_eq!(json["stop"], "Tolerance", "{json}");
    assert!(json["warnings"].as_array().unwrap().is_empty(), "{json}");
    // Particle swarm on two parameters runs into the fixed cap of 2000 evaluations: the warning
    // is on the terminal and in fit.json, and no longer tells the user to raise an
    // `[optimiser]` setting `eis` does not have.
    let o = fit("pso", "cell.contact_resistance,negative.diffusivity", "capped");
    succeeds(&o);
    let e = stderr(&o);
    assert!(e.contains("warning: the impedance fit stopped on its evaluation cap") && e.contains("cap of 2000 evaluations is fixed"), "{e}");
    assert!(!e.contains("[optimiser]"), "{e}");
    let json: serde_json::Value = serde_json::from_str(&std::fs::read_to_string(s.path("capped/fit.json")).unwrap()).unwrap();
    assert_eq!(json["stop"], "MaxEvaluations", "{json}");
    assert!(json["warnings"][0].as_str().unwrap().contains("evaluation cap"), "{json}");
}
