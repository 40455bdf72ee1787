//! Profile likelihoods on PyBaMM's curve (`tests/data/spm_contact_resistance_seed.csv`: a
//! PyBaMM SPM with D_n = 3.3e-14 m^2/s and 10 mOhm, 1C discharge then rest, 2 mV synthetic
//! noise). For the seed pair the model is nearly linear in its parameters near the optimum, so
//! the profile intervals agree with the Fisher ones and hold PyBaMM's values; the statistic
//! grows as the square of the distance in standard errors. With both rate constants freed
//! beside the resistance, the profile finds what the Fisher interval hides: nothing in a
//! constant-current discharge bounds the resistance from below (kinetics take its place).

use std::process::Command;

const REPO: &str = env!("CARGO_MANIFEST_DIR");

/// Runs a fit with `[profile]` over `parameters` (TOML `[[parameters]]` tables) and returns
/// `profiles.json`.
fn profiles(name: &str, parameters: &str) -> serde_json::Value {
    let tmp = tempfile::tempdir().unwrap();
    let dir = tmp.path();
    let study = format!(
        "name = \"{name}\"\n[model]\nkind = \"spm\"\nsubmodels = {{ contact_resistance = true }}\n[data]\nfile = \"{REPO}/tests/data/spm_contact_resistance_seed.csv\"\nsynthetic_noise = 0.002\nnoise_seed = 7\n{parameters}\n[cost]\nkind = \"sse\"\n[optimiser]\nmethod = \"lbfgsb\"\nseed = 1\n[profile]\npoints = 6\n[output]\ndir = \"out\"\n"
    );
    std::fs::write(dir.join("fit.toml"), study).unwrap();
    let out = Command::new(env!("CARGO_BIN_EXE_cellstudio")).args(["fit", "fit.toml"]).current_dir(&dir).output().unwrap();
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let report = std::fs::read_to_string(dir.join("out/report.md")).unwrap();
    assert!(report.contains("## Profile likelihoods") && dir.join("out/profile_0.svg").exists());
    let json = serde_json::from_str(&std::fs::read_to_string(dir.join("out/profiles.json")).unwrap()).unwrap();
    json
}

fn parameter(path: &str, initial: f64, lower: f64, upper: f64) -> String {
    format!("[[parameters]]\npath = \"{path}\"\ninitial = {initial:e}\nlower = {lower:e}\nupper = {upper:e}\nlog = true\n")
}

#[test]
fn seed_pair_profiles_agree_with_fisher_and_hold_pybamm_values() {
    let p = profiles("seed", &(parameter("negative.diffusivity", 6.6e-14, 1e-15, 1e-12) + &parameter("cell.contact_resistance", 0.005, 1e-4, 0.1)));
    for (k, truth) in [(0, 3.3e-14), (1, 0.010)] {
        let (best, lower, upper) = (p[k]["best"].as_f64().unwrap(), p[k]["lower"].as_f64().unwrap(), p[k]["upper"].as_f64().unwrap());
        assert!(lower < truth && truth < upper, "{}: {truth} outside [{lower}, {upper}]", p[k]["name"]);
        // Achieved: symmetric about the optimum to 1.4 % (a near-linear model).
        let (below, above) = (best - lower, upper - best);
        assert!((below / above - 1.0).abs() < 0.03, "{}: {below} below, {above} above", p[k]["name"]);
        // The statistic at the outermost held values (4 standard errors): 16 for a quadratic
        // profile; achieved 15.2-15.6.
        let s: Vec<f64> = p[k]["statistic"].as_array().unwrap().iter().map(|v| v.as_f64().unwrap()).collect();
        for end in [s[0], s[s.len() - 1]] {
            assert!((end - 16.0).abs() < 1.5, "{}: {s:?}", p[k]["name"]);
        }
        assert!(s.iter().all(|v| *v >= 0.0) && s.contains(&0.0));
    }
}

#[test]
fn resistance_beside_both_rate_constants_is_not_bounded_below() {
    let free = parameter("positive.rate_constant", 5e-6, 1e-7, 1e-4)
        + &parameter("negative.rate_constant", 5e-6, 1e-8, 1e-3)
        + &parameter("cell.contact_resistance", 0.005, 1e-4, 0.1);
    let p = profiles("kinetics", &free);
    let r = &p[2];
    assert_eq!(r["name"], "cell.contact_resistance");
    // Fisher: 7.5 ± 5.3 mOhm (95 %), an interval that looks bounded; the profile stays below
    // the threshold down to the lowest value it holds, and its upper end holds PyBaMM's 10 mOhm.
    assert!(r["lower"].is_null(), "{r}");
    assert!(r["upper"].as_f64().unwrap() > 0.010, "{r}");
}
