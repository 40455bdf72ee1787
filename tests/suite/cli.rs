//! End-to-end tests of the command line: the built binary run in temporary folders on small
//! problems. Each test pins one defect of issue 12 (user data altered, inputs overwritten,
//! half-written folders, exit 0 on nonsense, panics, messages naming fields the user never
//! wrote, no parameter overrides).

use std::path::Path;

use crate::cli_support;

use cli_support::*;

fn fitted_rmse(s: &Scratch) -> f64 {
    let json: serde_json::Value = serde_json::from_str(&std::fs::read_to_string(s.path("out/fit.json")).unwrap()).unwrap();
    json["rmse"].as_f64().unwrap()
}

#[test]
fn fit_never_adds_synthetic_noise_to_a_user_recording() {
    let s = Scratch::new("noise");
    let study = fit_study(&s, "[cost]\nkind = \"sse\"\n");
    // The user's recording: a noise-free copy of the seed curve.
    let recording = s.path("my_recording.csv");
    std::fs::copy(Path::new(REPO).join("tests/data/spm_contact_resistance_seed.csv"), &recording).unwrap();
    let before = std::fs::read(&recording).unwrap();
    let o = run(&s.0, &["fit", study.to_str().unwrap(), "--data", recording.to_str().unwrap()]);
    succeeds(&o);
    assert!(stderr(&o).contains("was not applied"), "{}", stderr(&o));
    let report = std::fs::read_to_string(s.path("out/report.md")).unwrap();
    assert!(report.contains("`data.synthetic_noise` (2 mV) was not applied"), "{report}");
    // PyBaMM's noise-free curve fits to well under the 2 mV noise level.
    let clean = fitted_rmse(&s);
    assert!(clean < 0.5e-3, "RMSE {clean} V: noise was added to the user's recording");
    assert_eq!(std::fs::read(&recording).unwrap(), before);

    // The study's own synthetic file does get its noise, and says so.
    let o = run(&s.0, &["fit", study.to_str().unwrap()]);
    succeeds(&o);
    assert!(stderr(&o).contains("synthetic Gaussian noise of 2 mV (seed 7) was added"), "{}", stderr(&o));
    let noisy = fitted_rmse(&s);
    assert!((noisy - 2e-3).abs() < 0.2e-3, "RMSE {noisy} V, expected the 2 mV noise");
    let report = std::fs::read_to_string(s.path("out/report.md")).unwrap();
    assert!(report.contains("synthetic Gaussian noise of 2 mV"), "{report}");
}

/// A cell that cannot replay the recording at the start values (half the positive electrode:
/// it empties before the discharge ends) is named as such, with those values and the fix,
/// before any search, not as a bare solver failure; nothing is written.
#[test]
fn a_fit_whose_start_cannot_replay_the_recording_says_why() {
    let s = Scratch::new("start");
    let study = fit_study(&s, "[cost]\nkind = \"sse\"\n");
    let o = run(&s.0, &["fit", study.to_str().unwrap(), "--set", "positive.thickness=3e-5"]);
    fails_with(&o, &["`data at the start values`", "cell.contact_resistance = ", "the model's voltage left", "raise the initial value of initial_soc"]);
    assert!(!s.path("out").exists(), "a failed fit wrote its output folder");
}

#[test]
fn eis_never_writes_over_the_spectrum_it_fits() {
    let s = Scratch::new("eis");
    let o = run(&s.0, &["eis", "--model", "spm", "--contact-resistance", "0.01", "--frequencies", "1e-2", "1e3", "12", "--out", "out/eis"]);
    succeeds(&o);
    let spectrum = s.path("out/eis/spectrum.csv");
    let measured = std::fs::read(&spectrum).unwrap();
    // The README's fit command with the default --out out/eis.
    let o = run(&s.0, &["eis", "--model", "spm", "--contact-resistance", "0.005", "--fit", "out/eis/spectrum.csv", "--parameters", "cell.contact_resistance"]);
    fails_with(&o, &["out/eis/spectrum.csv", "lies inside the output folder"]);
    assert_eq!(std::fs::read(&spectrum).unwrap(), measured, "the measured spectrum was overwritten");
    // Written elsewhere it runs and fits the resistance back.
    let o = run(
        &s.0,
        &["eis", "--model", "spm", "--contact-resistance", "0.005", "--fit", "out/eis/spectrum.csv", "--parameters", "cell.contact_resistance", "--out", "out/eis_fit"],
    );
    succeeds(&o);
    let stdout = String::from_utf8_lossy(&o.stdout);
    let r: f64 = stdout.lines().find_map(|l| l.trim().strip_prefix("cell.contact_resistance = ")).unwrap().parse().unwrap();
    assert!((r - 0.01).abs() < 1e-4, "{stdout}");
    assert_eq!(std::fs::read(&spectrum).unwrap(), measured);
}

#[test]
fn simulate_refuses_an_output_folder_holding_its_protocol() {
    let s = Scratch::new("sim-input");
    std::fs::create_dir_all(s.path("out")).unwrap();
    let protocol = "[[steps]]\nkind = \"c_rate\"\nrate = 1.0\nduration = 10.0\n";
    let path = s.write("out/simulate_protocol.toml", protocol);
    let o = run(&s.0, &["simulate", "--model", "spm", "--mesh", "5", "--protocol", "out/simulate_protocol.toml", "--out", "out"]);
    fails_with(&o, &["out/simulate_protocol.toml", "lies inside the output folder"]);
    assert_eq!(std::fs::read_to_string(&path).unwrap(), protocol);
    // A user's file that shares a name with an output is never replaced either.
    let mine = s.write("out/spm_simulation.csv", "my own notes");
    let o = run(&s.0, &["simulate", "--model", "spm", "--mesh", "5", "--protocol", path.to_str().unwrap(), "--out", "out2"]);
    succeeds(&o);
    std::fs::rename(s.path("out/simulate_protocol.toml"), s.path("protocol.toml")).unwrap();
    let o = run(&s.0, &["simulate", "--model", "spm", "--mesh", "5", "--protocol", "protocol.toml", "--out", "out"]);
    fails_with(&o, &["spm_simulation.csv", "no earlier cellstudio run wrote it"]);
    assert_eq!(std::fs::read_to_string(&mine).unwrap(), "my own notes");
    assert_eq!(s.entries(), vec!["out", "out2", "protocol.toml"], "a partial folder was left behind");
}

const DESIGN: &str = r#"name = "cli design"
[model]
kind = "spm"
[operating]
c_rate = 1.0
[[variables]]
path = "positive.thickness"
lower = LOWER
upper = UPPER
[objective]
maximise = [OBJECTIVES]
[optimiser]
method = "nelder_mead"
max_iterations = 8
seed = 1
[sweep]
points = [3]
[output]
dir = "out"
"#;

fn design_study(s: &Scratch, lower: &str, upper: &str, objectives: &str) -> String {
    let text = DESIGN.replace("LOWER", lower).replace("UPPER", upper).replace("OBJECTIVES", objectives);
    s.write("design.toml", &text).to_string_lossy().into_owned()
}

#[test]
fn a_failed_design_leaves_the_previous_results_and_no_partial_folder() {
    let s = Scratch::new("design");
    let study = design_study(&s, "60e-6", "90e-6", r#""gravimetric_energy_density""#);
    succeeds(&run(&s.0, &["design", &study]));
    let report = std::fs::read_to_string(s.path("out/report.md")).unwrap();
    let listing = std::fs::read_to_string(s.path("out/.cellstudio-outputs")).unwrap();
    assert!(listing.contains("report.md") && listing.contains("design.json"), "{listing}");
    // Bounds of 1-2 nm: the optimum stores no energy. Non-zero exit, nothing replaced.
    let study = design_study(&s, "1e-9", "2e-9", r#""gravimetric_energy_density""#);
    fails_with(&run(&s.0, &["design", &study]), &["no valid design"]);
    assert_eq!(std::fs::read_to_string(s.path("out/report.md")).unwrap(), report);
    assert_eq!(s.entries(), vec!["design.toml", "out"], "a partial folder was left behind");
}

#[test]
fn design_rejects_two_objectives_before_any_work() {
    let s = Scratch::new("objectives");
    let study = design_study(&s, "60e-6", "90e-6", r#""gravimetric_energy_density", "volumetric_energy_density""#);
    fails_with(&run(&s.0, &["design", &study]), &["objective.maximise", "use `pareto`"]);
    assert!(!s.path("out").exists());
}

#[test]
fn design_warns_when_the_optimum_sits_on_a_bound() {
    let s = Scratch::new("bound");
    // Thicker is better over this narrow range: the optimum is the upper bound.
    let study = design_study(&s, "60e-6", "61e-6", r#""gravimetric_energy_density""#);
    let o = run(&s.0, &["design", &study]);
    succeeds(&o);
    assert!(stderr(&o).contains("warning: the optimum has positive.thickness"), "{}", stderr(&o));
    let report = std::fs::read_to_string(s.path("out/report.md")).unwrap();
    assert!(report.contains("positive.thickness = 6.1e-5 at its upper bound"), "{report}");
    // The Chen 2020 baseline (75.6 um) lies outside these bounds: a warning, not a silent start elsewhere.
    assert!(stderr(&o).contains("the baseline's positive.thickness = 7.56e-5 lies outside its bounds"), "{}", stderr(&o));
}

#[test]
fn bounds_outside_the_physical_range_are_refused() {
    let s = Scratch::new("physical");
    let text = DESIGN
        .replace("positive.thickness", "positive.active_fraction")
        .replace("LOWER", "0.5")
        .replace("UPPER", "1.5")
        .replace("OBJECTIVES", r#""gravimetric_energy_density""#);
    let study = s.write("design.toml", &text);
    fails_with(&run(&s.0, &["design", study.to_str().unwrap()]), &["variables[0].upper", "1.5"]);
}

#[test]
fn unknown_cost_keys_and_sampler_typos_fail_before_any_work() {
    let s = Scratch::new("keys");
    let study = fit_study(&s, "[cost]\nkind = \"sse\"\nsigma = 0.002\n");
    fails_with(&run(&s.0, &["fit", study.to_str().unwrap()]), &["cost.sigma"]);
    let study = fit_study(&s, "[sampler]\nmethod = \"haario-bardenett\"\n");
    fails_with(&run(&s.0, &["fit", study.to_str().unwrap()]), &["haario-bardenett"]);
    assert!(!s.path("out").exists(), "the fit ran before the sampler name was checked");
}

#[test]
fn eis_frequency_counts_are_checked_not_truncated_or_overflowed() {
    let s = Scratch::new("freq");
    fails_with(&run(&s.0, &["eis", "--frequencies", "1e-4", "1e3", "1e30"]), &["--frequencies N", "at most"]);
    fails_with(&run(&s.0, &["eis", "--frequencies", "1e-4", "1e3", "2.7"]), &["--frequencies N", "2.7", "whole number"]);
    fails_with(&run(&s.0, &["eis", "--frequencies", "1e3", "1e-4", "10"]), &["--frequencies F_MAX"]);
    assert!(!s.path("out").exists());
}

#[test]
fn messages_name_the_flag_the_user_wrote() {
    let s = Scratch::new("flags");
    fails_with(&run(&s.0, &["simulate", "--c-rate", "0"]), &["--c-rate", "must be positive"]);
    fails_with(&run(&s.0, &["eis", "--soc", "1.5"]), &["--soc", "1.5"]);
    // 50C takes the SPMe below its cut-off at once: the message names the rate, not the cut-off
    // (more in `a_rate_the_cell_cannot_carry_is_named_where_the_user_set_it`).
    let e = fails_with(&run(&s.0, &["simulate", "--c-rate", "50", "--mesh", "5"]), &["invalid parameter `--c-rate` = 50", "below `cell.lower_cutoff` = 2.5 V"]);
    assert!(!e.contains("invalid parameter `cell.lower_cutoff`"), "{e}");
    assert!(!s.path("out").exists(), "a failed simulation left an output folder");
    fails_with(&run(&s.0, &["simulate", "--contact-resistance=-1"]), &["--contact-resistance"]);
}

#[test]
fn a_rate_the_cell_cannot_carry_is_named_where_the_user_set_it() {
    let s = Scratch::new("rate");
    // The cell carries 1C but not 50C (SPMe: 2.35 V at once, below the 2.5 V cut-off; DFN at
    // 20C: a non-finite right-hand side at the start). The error names the key that set the
    // rate, with its value; before, it named `cell.lower_cutoff` = 2.5, which nobody set.
    let blames_the_cut_off = |e: &str| e.contains("invalid parameter `cell.lower_cutoff`");
    s.write("fast.toml", "[[steps]]\nkind = \"rest\"\nduration = 10.0\n[[steps]]\nkind = \"c_rate\"\nrate = 50.0\nduration = 100.0\n");
    let e = fails_with(&run(&s.0, &["simulate", "--model", "spme", "--mesh", "5", "--protocol", "fast.toml"]), &["fast.toml", "`protocol.steps[1].rate` = 50", "step 1 (t = 10 s)"]);
    assert!(!blames_the_cut_off(&e), "{e}");
    let e = fails_with(&run(&s.0, &["simulate", "--model", "dfn", "--mesh", "5", "--c-rate", "20"]), &["invalid parameter `--c-rate` = 20", "the model fails"]);
    assert!(!blames_the_cut_off(&e), "{e}");
    let text = DESIGN.replace("LOWER", "60e-6").replace("UPPER", "90e-6").replace("OBJECTIVES", r#""gravimetric_energy_density""#);
    let study = s.write("design.toml", &text.replace("kind = \"spm\"", "kind = \"spme\"").replace("c_rate = 1.0", "c_rate = 50.0"));
    let e = fails_with(&run(&s.0, &["design", study.to_str().unwrap()]), &["invalid parameter `operating.c_rate` = 50"]);
    assert!(!blames_the_cut_off(&e), "{e}");
    // A cut-off that even 1C crosses at once (just below the full cell's 4.18 V) is still named.
    fails_with(&run(&s.0, &["simulate", "--model", "spm", "--mesh", "5", "--set", "cell.lower_cutoff=4.15"]), &["invalid parameter `cell.lower_cutoff` = 4.15"]);
    assert_eq!(s.entries(), vec!["design.toml", "fast.toml"], "a failed run left an output");
}

#[test]
fn set_overrides_one_parameter_and_errors_name_the_key() {
    let s = Scratch::new("set");
    let o = run(&s.0, &["simulate", "--model", "spm", "--mesh", "6", "--set", "cell.lower_cutoff=3.4", "--json"]);
    succeeds(&o);
    let summary: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    let v = summary["final_voltage_V"].as_f64().unwrap();
    assert!((v - 3.4).abs() < 1e-3, "final voltage {v} V, the override was not used");
    // A parameter file may name a base set and override a few values.
    s.write("mine.toml", "base = \"chen2020\"\n[cell]\nlower_cutoff = 3.3\n");
    let o = run(&s.0, &["simulate", "--model", "spm", "--mesh", "6", "--params", "mine.toml", "--json"]);
    succeeds(&o);
    let v = serde_json::from_slice::<serde_json::Value>(&o.stdout).unwrap()["final_voltage_V"].as_f64().unwrap();
    assert!((v - 3.3).abs() < 1e-3, "final voltage {v} V, the file's override was not used");
    s.write("typo.toml", "base = \"chen2020\"\n[cell]\nlower_cutof = 3.3\n");
    fails_with(&run(&s.0, &["simulate", "--params", "typo.toml"]), &["typo.toml cell.lower_cutof"]);
    // Overriding the contact resistance switches its submodel on, as --contact-resistance does.
    let energy = |args: &[&str]| -> f64 {
        let o = run(&s.0, &[&["simulate", "--model", "spm", "--mesh", "6", "--json"], args].concat());
        succeeds(&o);
        serde_json::from_slice::<serde_json::Value>(&o.stdout).unwrap()["energy_Wh"].as_f64().unwrap()
    };
    let (plain, flag, set) = (energy(&[]), energy(&["--contact-resistance", "0.05"]), energy(&["--set", "cell.contact_resistance=0.05"]));
    assert!(flag < 0.95 * plain && (set - flag).abs() < 1e-9 * flag, "{plain} {flag} {set}");
    fails_with(&run(&s.0, &["simulate", "--set", "positive.thicknes=7e-5"]), &["--set positive.thicknes"]);
    fails_with(&run(&s.0, &["simulate", "--set", "positive.thickness=-1"]), &["positive.thickness (from --set)", "-1"]);
    let bad = run(&s.0, &["simulate", "--set", "positive.thickness"]);
    assert_eq!(bad.status.code(), Some(2), "clap's usage error: {}", stderr(&bad));
    assert!(stderr(&bad).contains("PATH=VALUE"), "{}", stderr(&bad));
    // Studies take the same flag.
    let study = design_study(&s, "60e-6", "90e-6", r#""gravimetric_energy_density""#);
    fails_with(&run(&s.0, &["sweep", &study, "--set", "negative.porosityy=0.3"]), &["--set negative.porosityy"]);
    let study = fit_study(&s, "");
    fails_with(&run(&s.0, &["fit", study.to_str().unwrap(), "--set", "cell.nominal_capacityy=5"]), &["--set cell.nominal_capacityy"]);
}

#[test]
fn a_sweep_with_no_valid_design_fails_and_writes_nothing() {
    let s = Scratch::new("sweep");
    // Negative electrodes of 1-2 nm store no energy.
    let text = DESIGN.replace("positive.thickness", "negative.thickness").replace("LOWER", "1e-9").replace("UPPER", "2e-9");
    let study = s.write("design.toml", &text.replace("OBJECTIVES", r#""gravimetric_energy_density""#));
    fails_with(&run(&s.0, &["sweep", study.to_str().unwrap()]), &["no valid design", "3 store less than 0.001 of the baseline's energy"]);
    assert_eq!(s.entries(), vec!["design.toml"]);
}

#[test]
fn data_inspect_names_the_format_and_the_steps() {
    let repo = Path::new(REPO);
    let o = run(repo, &["data", "inspect", "tests/data/cycler/neware_documented_layout.csv"]);
    let out = String::from_utf8_lossy(&o.stdout);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(out.contains("format           Neware") && out.contains("rows             9"), "{out}");
    assert!(out.contains("| 2 | 2 | CC | 90.1 | 2.5000 | 4.1021 | 4.0530 |"), "{out}");
    let o = run(repo, &["data", "inspect", "Cargo.toml"]);
    fails_with(&o, &["Cargo.toml", "not a known cycler export", "`[package]`"]);
}

#[test]
fn data_inspect_refuses_what_fit_refuses_with_the_same_reason() {
    let s = Scratch::new("inspect-refuses");
    let study = fit_study(&s, "[cost]\nkind = \"sse\"\n");
    let scaled = |column: usize, factor: f64| move |_: usize, cells: &mut Vec<String>| cells[column] = (cells[column].parse::<f64>().unwrap() * factor).to_string();
    let neware = std::fs::read_to_string(Path::new(REPO).join("tests/data/cycler/neware_documented_layout.csv")).unwrap();
    let bad = [
        ("minutes.csv", seed_edited(scaled(0, 1.0 / 60.0)), "time_unit = \"min\""),
        ("charge_positive.csv", seed_edited(scaled(1, -1.0)), "discharge_positive = false"),
        ("celsius_as_kelvin.csv", seed_edited(|_, cells| cells[4] = "25".into()), "25 K is not a cell temperature"),
        ("nan.csv", seed_edited(|row, cells| if row == 5 { cells[2] = "nan".into() }), "line 7: `voltage_V` is NaN"),
        ("backwards.csv", seed_edited(|row, cells| if row == 5 { cells[0] = "0.5".into() }), "line 7: `time_s` = 0.5 does not increase"),
        // A raw export's temperature column is range-checked too (2510 degC: a lost decimal point).
        ("neware_hot.csv", neware.replacen(",25.1\n", ",2510\n", 1), "(2783.15 K) is not a cell temperature"),
    ];
    for (name, text, why) in bad {
        let file = s.write(name, &text);
        let file = file.to_str().unwrap();
        let fit = fails_with(&run(&s.0, &["fit", study.to_str().unwrap(), "--data", file]), &[name, why]);
        let inspect = fails_with(&run(&s.0, &["data", "inspect", file]), &[name, why]);
        let reason = |e: &str| e.lines().find(|l| l.starts_with("error:")).unwrap().to_string();
        assert_eq!(reason(&inspect), reason(&fit), "data inspect and fit disagree on {name}");
    }
    assert!(!s.path("out").exists());
    // The unchanged seed recording passes both checks.
    succeeds(&run(&s.0, &["data", "inspect", &format!("{REPO}/tests/data/spm_contact_resistance_seed.csv")]));
}

#[test]
fn a_fit_pinned_on_a_bound_fails_and_a_truncated_fit_says_so() {
    let s = Scratch::new("pinned");
    // The seed recording has R = 10 mOhm; a search range that ends at 2 mOhm pins the fit there.
    let study = fit_study(&s, "[cost]\nkind = \"sse\"\n");
    let text = std::fs::read_to_string(&study).unwrap().replace("initial = 0.005\n", "initial = 0.001\n").replace("upper = 0.1\n", "upper = 0.002\n");
    std::fs::write(&study, text).unwrap();
    let o = run(&s.0, &["fit", study.to_str().unwrap()]);
    fails_with(&o, &["parameters.cell.contact_resistance", "ended on a bound", "no estimate"]);
    // Written for inspection beside the output folder, with the bound named in the report.
    let report = std::fs::read_to_string(s.path("out.rejected/report.md")).unwrap();
    assert!(report.contains("cell.contact_resistance = 0.002 at its upper bound"), "{report}");

    // One iteration from a start 2x away: a result, but the report says the search was cut short.
    let study = fit_study(&s, "[cost]\nkind = \"sse\"\n");
    let text = std::fs::read_to_string(&study).unwrap().replace("seed = 1\n", "seed = 1\nmax_iterations = 1\n");
    std::fs::write(&study, text).unwrap();
    let o = run(&s.0, &["fit", study.to_str().unwrap()]);
    succeeds(&o);
    assert!(stderr(&o).contains("warning: the fit stopped on its iteration cap (1 iterations"), "{}", stderr(&o));
    let report = std::fs::read_to_string(s.path("out/report.md")).unwrap();
    assert!(report.contains("raise [optimiser] max_iterations"), "{report}");
}

#[test]
fn a_sample_whose_fit_ends_on_a_bound_fails_as_fit_does() {
    let s = Scratch::new("sample-bound");
    let sampler = "[sampler]\nchains = 2\niterations = 100\nwarmup = 50\n";
    let study = fit_study(&s, sampler);
    succeeds(&run(&s.0, &["sample", study.to_str().unwrap()]));
    let previous = std::fs::read(s.path("out/posterior.md")).unwrap();
    // The seed recording has R = 10 mOhm: a range from 20 mOhm up pins the fit on its lower
    // bound (before, the chains were sampled around it and the run exited 0).
    let text = std::fs::read_to_string(&study).unwrap().replace("initial = 0.005\n", "initial = 0.03\n").replace("lower = 1e-4\n", "lower = 0.02\n");
    std::fs::write(&study, text).unwrap();
    let o = run(&s.0, &["sample", study.to_str().unwrap()]);
    fails_with(&o, &["parameters.cell.contact_resistance", "cell.contact_resistance = 0.02 at its lower bound", "nothing was sampled", "`out.rejected`"]);
    // The fit's outputs for inspection, no posterior; the previous results as they were.
    let report = std::fs::read_to_string(s.path("out.rejected/report.md")).unwrap();
    assert!(report.contains("cell.contact_resistance = 0.02 at its lower bound"), "{report}");
    assert!(!s.path("out.rejected/posterior.md").exists() && !s.path("out.rejected/samples.csv").exists());
    assert_eq!(std::fs::read(s.path("out/posterior.md")).unwrap(), previous);
    assert_eq!(s.entries(), vec!["fit.toml", "out", "out.rejected"]);
}

#[test]
fn fit_names_a_recording_in_minutes_or_milliamps_before_any_work() {
    let s = Scratch::new("units");
    let study = fit_study(&s, "[cost]\nkind = \"sse\"\n");
    let rescaled = |column: usize, factor: f64| seed_edited(|_, cells| cells[column] = (cells[column].parse::<f64>().unwrap() * factor).to_string());
    let minutes = s.write("minutes.csv", &rescaled(0, 1.0 / 60.0));
    let o = run(&s.0, &["fit", study.to_str().unwrap(), "--data", minutes.to_str().unwrap()]);
    fails_with(&o, &["minutes.csv", "likely unit error", "time_unit = \"min\""]);
    let milliamps = s.write("milliamps.csv", &rescaled(1, 1e3));
    let o = run(&s.0, &["fit", study.to_str().unwrap(), "--data", milliamps.to_str().unwrap()]);
    fails_with(&o, &["milliamps.csv", "likely unit error", "current_unit = \"mA\""]);
    assert!(!s.path("out").exists());
}
