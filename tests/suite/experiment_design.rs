//! Experiment design after a fit (`[experiment_design]` in a fitting study) on PyBaMM's seed
//! curve (`tests/data/spm_contact_resistance_seed.csv`: an SPM with 10 mOhm, 1C discharge then
//! 30 min rest, sampled every 10 s, 2 mV noise), fitting the positive rate constant with the
//! contact resistance, which one constant-current discharge cannot tell apart
//! (`tests/identifiability.rs`).
//!
//! Two independent checks: the candidate that repeats the recorded experiment on the same
//! 10 s grid doubles the Fisher information, so it must divide both standard errors by √2
//! (linear algebra, not a tolerance we chose); and the best candidate must be a discharge at a
//! second rate, since a charge-transfer overpotential (sinh⁻¹ in the current) and an ohmic one
//! (linear) differ only in how they scale with the current.

use std::process::Command;

const REPO: &str = env!("CARGO_MANIFEST_DIR");

#[test]
fn a_second_rate_separates_kinetics_from_resistance() {
    let tmp = tempfile::tempdir().unwrap();
    let dir = tmp.path();
    let study = format!(
        "name = \"oed\"\n[model]\nkind = \"spm\"\nsubmodels = {{ contact_resistance = true }}\n[data]\nfile = \"{REPO}/tests/data/spm_contact_resistance_seed.csv\"\nsynthetic_noise = 0.002\nnoise_seed = 7\n\
         [[parameters]]\npath = \"positive.rate_constant\"\ninitial = 5e-6\nlower = 1e-7\nupper = 1e-4\nlog = true\n\
         [[parameters]]\npath = \"cell.contact_resistance\"\ninitial = 0.005\nlower = 1e-4\nupper = 0.1\nlog = true\n\
         [cost]\nkind = \"sse\"\n[optimiser]\nmethod = \"lbfgsb\"\nseed = 1\n\
         [experiment_design]\nrates = [0.5, 1.0, 2.0]\npulse_seconds = [10.0, 60.0]\nrest_seconds = [60.0, 600.0]\npulses = 5\nsampling = 10.0\n[output]\ndir = \"{}\"\n",
        dir.join("out").display()
    );
    std::fs::write(dir.join("fit.toml"), study).unwrap();
    let out = Command::new(env!("CARGO_BIN_EXE_cellstudio")).args(["fit", "fit.toml"]).current_dir(&dir).output().unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr).to_string();
    let text = std::fs::read_to_string(dir.join("out/experiment_design.json")).unwrap_or_else(|_| panic!("{stderr}"));
    let report = std::fs::read_to_string(dir.join("out/report.md")).unwrap();
    let d: serde_json::Value = serde_json::from_str(&text).unwrap();
    let numbers = |v: &serde_json::Value| -> Vec<f64> { v.as_array().unwrap().iter().map(|x| x.as_f64().unwrap_or(f64::INFINITY)).collect() };
    let before = numbers(&d["before"]);
    let candidates = d["candidates"].as_array().unwrap();
    println!("{}", report.split("## Next experiment").nth(1).unwrap_or(""));
    // Both are targets: the recording determines them only together.
    assert_eq!(d["targets"].as_array().unwrap().len(), 2);
    assert_eq!(candidates.len(), 3 * 2 * 2 + 3);
    let steps = |c: &serde_json::Value| c["steps"].as_array().unwrap().iter().map(|s| s.as_str().unwrap().to_string()).collect::<Vec<_>>();
    let repeat = candidates.iter().find(|c| steps(c) == ["Discharge at 1C until 2.5 V", "Rest for 30 minutes"]).unwrap();
    for (k, after) in numbers(&repeat["relative_std_errors"]).iter().enumerate() {
        let ratio = before[k] / after;
        println!("parameter {k}: {:.3} % -> {:.3} % (ratio {ratio:.4})", 100.0 * before[k], 100.0 * after);
        assert!((ratio - 2f64.sqrt()).abs() < 0.002, "parameter {k}: ratio {ratio}");
    }
    let best = steps(&candidates[0]);
    assert!(best.len() == 2 && best[0].contains("until") && !best[0].contains(" 1C "), "best: {best:?}");
    // Adding information never raises an error.
    for c in candidates {
        assert!(numbers(&c["relative_std_errors"]).iter().zip(&before).all(|(a, b)| a <= b), "{c}");
    }
}
