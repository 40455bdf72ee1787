//! Nonsense inputs found by a trust audit as a new user, each refused with exit 1, nothing
//! written and an error naming the key or flag the user wrote and its value: studies too large
//! to hold in memory, recordings whose time column cannot be replayed, input files that do not
//! exist, temperatures in degrees Celsius where kelvin are read, a noise level to sample from
//! a recording too clean to have one, negative numbers given to flags.

use std::path::Path;

use crate::cli_support;

use cli_support::*;

/// The seed design study with its sweep grid replaced by `points` and its output in `out`.
fn design_with_points(s: &Scratch, points: &str) -> String {
    let seed = std::fs::read_to_string(Path::new(REPO).join("designs/gravimetric_chen2020.toml")).unwrap();
    let text = seed.replace("points = [13, 13]", &format!("points = {points}")).replace("out/gravimetric_chen2020", "out");
    s.write("design.toml", &text).to_string_lossy().into_owned()
}

#[test]
fn studies_too_large_to_hold_in_memory_are_refused_before_any_work() {
    let s = Scratch::new("huge");
    // 10^10 grid points: before, `sweep` (and `design`, which makes the grid to count it)
    // allocated until the machine ran out of memory.
    let study = design_with_points(&s, "[100000, 100000]");
    for command in ["sweep", "design"] {
        fails_with(&run(&s.0, &[command, &study]), &["sweep.points", "[100000, 100000]", "1e10 designs"]);
    }
    // A population of 10^11: before, an abort on a failed allocation (exit 134).
    let seed = std::fs::read_to_string(Path::new(REPO).join("designs/energy_vs_power_chen2020.toml")).unwrap();
    let text = seed.replace("population = 32", "population = 100000000000").replace("out/energy_vs_power_chen2020", "out");
    let pareto = s.write("pareto.toml", &text);
    fails_with(&run(&s.0, &["pareto", pareto.to_str().unwrap()]), &["optimiser.population", "population = 100000000000 with 20 generations", "2.1e12 designs"]);
    assert!(!s.path("out").exists(), "a refused study wrote something");
    // A grid too large for `design` to check still runs the search, with a warning.
    let study = design_with_points(&s, "[50, 50]");
    let text = std::fs::read_to_string(&study).unwrap().replace("max_iterations = 60", "max_iterations = 3");
    std::fs::write(&study, text).unwrap();
    let o = run(&s.0, &["design", &study]);
    succeeds(&o);
    assert!(stderr(&o).contains("the study's sweep has 2500 points, more than the 2000"), "{}", stderr(&o));
}

#[test]
fn a_time_column_that_cannot_be_replayed_is_refused_naming_the_line() {
    let s = Scratch::new("times");
    // Rows 100 and 101 (file lines 102, 103) moved back to the time of row 99: a current step
    // is two rows at one time, a third row's current would last no time. Before, it became a
    // step of zero duration and was silently ignored by the fit.
    let triple = s.write("triple.csv", &seed_edited(|row, cells| {
        if row == 100 || row == 101 {
            cells[0] = "990".into();
        }
        if row == 100 {
            cells[1] = "2".into();
        }
    }));
    let triple = triple.to_str().unwrap();
    for args in [vec!["data", "inspect", triple], vec!["fit", &fit_study(&s, "").to_string_lossy(), "--data", triple]] {
        fails_with(&run(&s.0, &args.iter().map(|a| &**a).collect::<Vec<_>>()), &["triple.csv", "line 103", "`time_s` = 990", "third row"]);
    }
    // Two rows at one time are a current step, as before.
    let step = s.write("step.csv", &seed_edited(|row, cells| {
        if row == 100 {
            cells[0] = "990".into();
        }
    }));
    succeeds(&run(&s.0, &["data", "inspect", step.to_str().unwrap()]));
    // Every row at one time: nothing to simulate.
    let still = s.write("still.csv", "time_s,current_A,voltage_V\n5,1,3.9\n5,0,3.95\n");
    fails_with(&run(&s.0, &["data", "inspect", still.to_str().unwrap()]), &["line 3", "`time_s` = 5", "spans no time"]);
    // Our columns from a spreadsheet that separates by `;` with comma decimals, and an empty
    // file: before, both only "not a known cycler export (first line: ...)".
    let semicolons = seed_edited(|_, _| {}).replace(',', ";").replace('.', ",");
    let semicolons = s.write("semicolons.csv", &semicolons);
    fails_with(&run(&s.0, &["data", "inspect", semicolons.to_str().unwrap()]), &["separated by ';'", "save it with commas"]);
    let empty = s.write("empty.csv", "");
    fails_with(&run(&s.0, &["data", "inspect", empty.to_str().unwrap()]), &["empty.csv", "the file is empty"]);
    assert!(!s.path("out").exists());
}

#[test]
fn an_input_file_that_does_not_exist_is_named_by_its_key_or_flag() {
    let s = Scratch::new("missing");
    let dir = s.0.display().to_string();
    let study = fit_study(&s, "");
    let text = std::fs::read_to_string(&study).unwrap();
    let start = text.find("file = \"").unwrap();
    let end = start + text[start..].find('\n').unwrap();
    std::fs::write(&study, format!("{}file = \"nope.csv\"\nprotocol = \"nope.toml\"{}", &text[..start], &text[end..])).unwrap();
    let study = study.to_str().unwrap();
    fails_with(&run(&s.0, &["fit", study]), &["`data.data1.file`", "`nope.csv`", &format!("working directory, `{dir}`")]);
    fails_with(&run(&s.0, &["fit", study, "--data", "gone.csv"]), &["`--data`", "`gone.csv`"]);
    // The recording exists, the protocol does not.
    let seed = Path::new(REPO).join("tests/data/spm_contact_resistance_seed.csv");
    fails_with(&run(&s.0, &["fit", study, "--data", seed.to_str().unwrap()]), &["`data.data1.protocol`", "`nope.toml`"]);
    fails_with(&run(&s.0, &["simulate", "--params", "nope.toml"]), &["`--params`", "`nope.toml`"]);
    fails_with(&run(&s.0, &["simulate", "--protocol", "nope.toml"]), &["`--protocol`", "`nope.toml`"]);
    fails_with(&run(&s.0, &["eis", "--fit", "nope.csv"]), &["`--fit`", "`nope.csv`"]);
    fails_with(&run(&s.0, &["diagnose", "--data", "nope.csv"]), &["`--data`", "`nope.csv`"]);
    fails_with(&run(&s.0, &["diagnose", "--data", seed.to_str().unwrap(), "--time-budget", "0"]), &["`--time-budget`", "positive"]);
    fails_with(&run(&s.0, &["data", "inspect", "nope.csv"]), &["`FILE`", "`nope.csv`"]);
    // An output folder that cannot be made is named as the user wrote it, not by the
    // temporary folder beside it.
    let e = fails_with(&run(&s.0, &["simulate", "--model", "spm", "--out", "/proc/cellstudio-out"]), &["output folder", "`/proc/cellstudio-out`"]);
    assert!(!e.contains("partial"), "{e}");
    assert_eq!(s.entries(), vec!["fit.toml"], "a refused run wrote something");
}

#[test]
fn temperatures_in_celsius_are_named_where_the_study_sets_them() {
    let s = Scratch::new("celsius");
    // Before, `[data] temperature = 25` passed its check (0-1000 K) and failed later as
    // `thermal.ambient_temperature`, a key the study never wrote.
    let study = fit_study(&s, "");
    let text = std::fs::read_to_string(&study).unwrap().replace("noise_seed = 7\n", "noise_seed = 7\ntemperature = 25\n");
    std::fs::write(&study, text).unwrap();
    fails_with(&run(&s.0, &["fit", study.to_str().unwrap()]), &["`data.data1.temperature` = 25", "kelvin"]);
    let seed = std::fs::read_to_string(Path::new(REPO).join("designs/gravimetric_chen2020.toml")).unwrap();
    let design = s.write("design.toml", &seed.replace("c_rate = 1.0", "c_rate = 1.0\ntemperature = 25"));
    fails_with(&run(&s.0, &["design", design.to_str().unwrap()]), &["`operating.temperature` = 25", "kelvin"]);
}

#[test]
fn sampling_the_noise_of_a_noise_free_recording_is_refused_naming_the_cost() {
    let s = Scratch::new("clean");
    // PyBaMM's curve without noise fits to a few microvolts, below the 10 uV where `sample`
    // starts its search for sigma. Before, it failed as "invalid setting `starts`: start 0 =
    // [...] has log density -inf", a setting no study has.
    let study = fit_study(&s, "[cost]\nkind = \"sse\"\n[sampler]\nchains = 2\niterations = 30\nwarmup = 10\n");
    let seed = Path::new(REPO).join("tests/data/spm_contact_resistance_seed.csv");
    let e = fails_with(&run(&s.0, &["sample", study.to_str().unwrap(), "--data", seed.to_str().unwrap()]), &["`cost`", "RMS residual", "[1e-5, 0.5] V", "kind = \"gaussian_log_likelihood\", sigma"]);
    assert!(!e.contains("starts"), "{e}");
    assert_eq!(s.entries(), vec!["fit.toml"], "a refused sample wrote something");
}

#[test]
fn a_negative_number_after_a_flag_is_its_value_and_is_checked() {
    let s = Scratch::new("negative");
    // Before, `--c-rate -1` was "unexpected argument '-1' found" (exit 2), and `--repeat 0`
    // ran once and reported "median of 1".
    fails_with(&run(&s.0, &["simulate", "--c-rate", "-1"]), &["`--c-rate` = -1", "must be positive"]);
    fails_with(&run(&s.0, &["simulate", "--contact-resistance", "-0.01"]), &["`--contact-resistance` = -0.01"]);
    fails_with(&run(&s.0, &["eis", "--soc", "-0.5"]), &["`--soc` = -0.5"]);
    fails_with(&run(&s.0, &["eis", "--frequencies", "-1", "10", "5"]), &["`--frequencies F_MIN` = -1"]);
    fails_with(&run(&s.0, &["simulate", "--repeat", "0"]), &["`--repeat` = 0", "at least 1"]);
    assert!(s.entries().is_empty(), "a refused run wrote something");
}

#[test]
fn a_parameter_the_model_does_not_read_is_refused_naming_what_would_read_it() {
    let s = Scratch::new("unread");
    // Before, each ran and changed nothing: the first under the SEI law that reads
    // `sei.exchange_current`, the others with their submodel off.
    let cycle = std::fs::read_to_string(Path::new(REPO).join("examples/cycle_sei_chen2020.toml")).unwrap();
    let cycle = s.write("cycle.toml", &cycle.replace("out/cycle_sei", "out")).to_string_lossy().into_owned();
    let o = run(&s.0, &["cycle", &cycle, "--set", "sei.kinetic_rate_constant=1e-9"]);
    fails_with(&o, &["--set sei.kinetic_rate_constant", "\"reaction limited\"", "only \"ec reaction limited\" reads it"]);
    let o = run(&s.0, &["simulate", "--set", "sei.exchange_current=1e-6"]);
    fails_with(&o, &["--set sei.exchange_current", "the SEI submodel is off"]);
    let design = design_with_points(&s, "[3, 3]");
    let o = run(&s.0, &["design", &design, "--set", "plating.kinetic_rate_constant=1e-10"]);
    fails_with(&o, &["--set plating.kinetic_rate_constant", "lithium-plating submodel is off"]);
    let fit = fit_study(&s, "");
    let o = run(&s.0, &["fit", &fit.to_string_lossy(), "--set", "cell.rc_resistance=0.01"]);
    fails_with(&o, &["--set cell.rc_resistance", "the RC submodel is off", "rc = true"]);
    // A diagnosis's candidates fit these from their own starts, never from the set.
    let seed = Path::new(REPO).join("tests/data/spm_contact_resistance_seed.csv");
    let seed = seed.to_str().unwrap();
    let o = run(&s.0, &["diagnose", "--data", seed, "--out", "out", "--set", "cell.leakage_current=0.1"]);
    fails_with(&o, &["--set cell.leakage_current", "the leak submodel is off", "fits it from its own start"]);
    let o = run(&s.0, &["diagnose", "--data", seed, "--out", "out", "--fit", "cell.hysteresis_voltage"]);
    fails_with(&o, &["--fit cell.hysteresis_voltage", "the hysteresis submodel is off"]);
    assert!(!s.path("out").exists(), "a refused run wrote its output folder");
}
