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
